// tick_clock.hpp — a cheap monotonic tick counter for timing many short
// intervals (the mesher's meter times each of ~250,000 field evaluations),
// and its conversion to seconds.
//
// On x86-64 the ticks are the time-stamp counter (rdtsc, ~20 ns a read on
// the project's virtual machine against ~55 ns for steady_clock::now(),
// which there goes through the paravirtual clock); elsewhere steady_clock's
// own ticks. The seconds per tick are measured, not assumed: between the
// clock's construction and the conversion, against steady_clock, so they
// are as good as the processor's counter is steady (Linux reports that as
// the constant_tsc flag, true of every x86-64 processor of the last
// fifteen years).
#pragma once

#include <chrono>
#include <cstdint>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

namespace skelconv::detail {

class TickClock {
 public:
  using Ticks = std::int64_t;

  static Ticks now() {
#if defined(__x86_64__)
    return Ticks(__rdtsc());
#else
    return Ticks(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
  }

  /// `ticks` (a sum of differences of now()) in seconds, at the rate
  /// measured since construction; 0 before any tick has passed.
  double seconds(Ticks ticks) const {
    const Ticks elapsed_ticks = now() - start_ticks_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return elapsed_ticks > 0 ? double(ticks) * (elapsed / double(elapsed_ticks)) : 0.0;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  Ticks start_ticks_ = now();
};

}  // namespace skelconv::detail
