// src/cli/progress_lines.hpp — the progress lines of a long run on stderr,
// "skelconv COMMAND: what, T s": at most one a second, none in a run shorter
// than that, none with --quiet. Seconds count from the object's creation.
#pragma once

#include <chrono>
#include <cstdio>
#include <string_view>

namespace skelconv::cli {

class ProgressLines {
 public:
  /// `command`: the subcommand's name, e.g. "eval"; a literal (kept as is).
  ProgressLines(const char* command, bool quiet) : command_(command), quiet_(quiet) {}
  bool quiet() const { return quiet_; }
  /// Whether a second has passed since the last line (or the start); then
  /// the next line is due now.
  bool due() {
    if (quiet_) return false;
    const Clock::time_point now = Clock::now();
    if (now - last_ < std::chrono::seconds(1)) return false;
    last_ = now;
    return true;
  }
  void print(std::string_view what) const {
    std::fprintf(stderr, "skelconv %s: %.*s, %.1f s\n", command_, int(what.size()), what.data(),
                 std::chrono::duration<double>(Clock::now() - start_).count());
  }

 private:
  using Clock = std::chrono::steady_clock;
  const char* command_;
  bool quiet_;
  Clock::time_point start_ = Clock::now(), last_ = start_;
};

}  // namespace skelconv::cli
