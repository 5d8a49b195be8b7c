// src/cli/tolerance_option.hpp — the check of --tolerance (eval, mesh): the
// library's rule (Skeleton::checked_tolerance), applied while the command
// line is parsed, so that the message names the option and comes before
// any input is read.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "skelconv/errors.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::cli {

inline CLI::Validator tolerance_range() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        // A non-number is left to CLI11's own conversion, which names it.
        if (!CLI::detail::lexical_cast(text, value)) return {};
        try {
          Skeleton::checked_tolerance(value);
        } catch (const InputError& error) {
          return error.problem();
        }
        return {};
      },
      "0 <= TOLERANCE < 1");
}

}  // namespace skelconv::cli
