// src/cli/count_option.hpp — the check of the options that count something
// (--threads, --max-points, --max-triangles): a whole number written with
// digits only. CLI11 reads "-1" into an unsigned option as the largest
// value (a limit of -1 was no limit at all), and its NonNegativeNumber
// names the range 0 to 1.8e308 in full. A limit of triangles must be at
// least 1: a limit of 0 triangles would refuse every mesh.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

/// `smallest`: 0 or 1 (a count of at least one).
inline CLI::Validator count_option(int smallest = 0) {
  return CLI::Validator(
      [smallest](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (digits && !(smallest > 0 && text.find_first_not_of('0') == std::string::npos)) return {};
        return "must be a whole number >= " + std::to_string(smallest) + " written with digits, got " + text;
      },
      "COUNT");
}

}  // namespace skelconv::cli
