// src/cli/exit_status.hpp — exit codes and the one way the CLI reports errors.
#pragma once

#include <cstdio>
#include <new>
#include <string>
#include <string_view>

#include "skelconv/errors.hpp"

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

/// `text` with its control characters (but tab) written as \xNN: a message
/// quotes the user's bytes (a point line, a JSON key, a file name), and a
/// newline or escape sequence among them must not break its one line.
inline std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      out += "\\x";
      out += hex[byte >> 4];
      out += hex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

/// Writes "skelconv: error: <message>" as one line on stderr.
inline void report_error(std::string_view message) {
  const std::string line = printable(message);
  std::fprintf(stderr, "skelconv: error: %.*s\n", int(line.size()), line.data());
}

/// The one way a subcommand ends: runs `produce` (which returns the whole
/// standard output), reports an InputError (exit 2) or EvaluationError
/// (exit 1) as one line, and only when everything succeeded writes the
/// output, so that stdout never holds half a result.
template <class Produce>
int print_all_or_nothing(Produce produce) {
  std::string output;
  try {
    output = produce();
  } catch (const InputError& error) {
    report_error(error.what());
    return exit_bad_input;
  } catch (const EvaluationError& error) {
    report_error(error.what());
    return exit_evaluation_failed;
  } catch (const std::bad_alloc&) {
    report_error("out of memory: the work asked for is larger than this machine's memory (choose a coarser size "
                 "or fewer points)");
    return exit_evaluation_failed;
  }
  if (std::fwrite(output.data(), 1, output.size(), stdout) != output.size() || std::fflush(stdout) != 0) {
    report_error("cannot write to standard output");
    return exit_evaluation_failed;
  }
  return exit_success;
}

}  // namespace skelconv::cli
