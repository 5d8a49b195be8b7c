// src/cli/exit_status.hpp — exit codes and the one way the CLI reports errors.
#pragma once

#include <cstdio>
#include <string_view>

namespace skelconv::cli {

/// Process exit codes (documented in docs/cli.md).
enum ExitStatus : int {
  exit_success = 0,
  /// Valid input, but a field value could not be computed in double precision
  /// (skelconv::EvaluationError), or an unexpected internal failure.
  exit_evaluation_failed = 1,
  /// Bad command line, unreadable or invalid skeleton file, bad point line.
  exit_bad_input = 2,
};

/// Writes "skelconv: error: <message>" as one line on stderr.
inline void report_error(std::string_view message) {
  std::fprintf(stderr, "skelconv: error: %.*s\n", int(message.size()), message.data());
}

}  // namespace skelconv::cli
