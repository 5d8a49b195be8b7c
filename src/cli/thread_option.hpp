// src/cli/thread_option.hpp — the check of --threads (eval, mesh): a count
// (count_option) of at most max_batch_threads, refused while the command
// line is parsed with the limit and the cores in the message.
#pragma once

#include <algorithm>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "count_option.hpp"
#include "skelconv/field/batch.hpp"

namespace skelconv::cli {

/// Adds `--threads` to `command`, into `threads`, described by `what`.
inline CLI::Option* add_thread_option(CLI::App* command, unsigned& threads, const std::string& what) {
  return command->add_option("--threads", threads, what)
      ->check(count_option())
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            // count_option has passed: digits only. A count too long for
            // unsigned is over the limit too, and is refused with the limit.
            const std::size_t digits = text.size() - std::min(text.size(), text.find_first_not_of('0'));
            if (digits <= 4 && std::stoul(text) <= max_batch_threads) return {};
            return fmt::format("{}, got {}", thread_limit_text(), text);
          },
          "COUNT"));
}

}  // namespace skelconv::cli
