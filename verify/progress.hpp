// verify/progress.hpp — progress of a long run on stderr: done / total, rate
// and ETA, as one updating line on a terminal or a line every few seconds
// otherwise (logs of ctest and CI).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace skelconv::verify {

class ProgressReporter {
 public:
  /// `total_weight` is the total amount of work (e.g. samples), `items` the
  /// count of work items, both only for display.
  ProgressReporter(bool enabled, std::uint64_t total_weight, std::size_t items)
      : enabled_(enabled), total_(total_weight), items_(items), tty_(isatty(fileno(stderr)) != 0),
        start_(std::chrono::steady_clock::now()) {
    if (enabled_) printer_ = std::thread([this] { loop(); });
  }
  ~ProgressReporter() { finish(); }
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  void item_done(std::uint64_t weight) {
    done_ += weight;
    ++items_done_;
  }

  void finish() {
    if (!printer_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    printer_.join();
    print();
    if (tty_) std::fputc('\n', stderr);
  }

 private:
  void loop() {
    const auto period = tty_ ? std::chrono::milliseconds(500) : std::chrono::seconds(10);
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, period, [this] { return stop_; })) print();
  }

  void print() {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::uint64_t done = done_.load();
    const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
    const double eta = rate > 0 ? static_cast<double>(total_ - done) / rate : 0;
    std::fprintf(stderr, "%sverify: items %zu/%zu, samples %llu/%llu, %.0f samples/s, elapsed %.0f s, ETA %.0f s%s",
                 tty_ ? "\r" : "", items_done_.load(), items_, static_cast<unsigned long long>(done),
                 static_cast<unsigned long long>(total_), rate, elapsed, eta, tty_ ? "   " : "\n");
    std::fflush(stderr);
  }

  bool enabled_;
  std::uint64_t total_;
  std::size_t items_;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::uint64_t> done_{0};
  std::atomic<std::size_t> items_done_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread printer_;
};

}  // namespace skelconv::verify
