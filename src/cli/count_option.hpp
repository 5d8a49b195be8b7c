// src/cli/count_option.hpp — the check of the options that count something
// (--threads, --max-points, --max-triangles): a whole number written with
// digits only. CLI11 reads "-1" into an unsigned option as the largest
// value (a limit of -1 was no limit at all), and its NonNegativeNumber
// names the range 0 to 1.8e308 in full.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

inline CLI::Validator count_option() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return {};
        return "must be a whole number >= 0 written with digits, got " + text;
      },
      "COUNT");
}

}  // namespace skelconv::cli
