// parallel_for.hpp — run fn(k) for k in [0, count) on every core, with the
// same results as the plain loop when each fn(k) writes only its own slot.
//
// Threads take blocks of `block` consecutive indices from a shared counter
// (the cost of an index may vary a lot: a ray that marches far, a point deep
// in a crowd of primitives). Errors: the exception rethrown is the one of the
// LOWEST failing index, the one the plain loop would have thrown first; a
// thread stops a block at its first failure and skips indices beyond the
// lowest failure found so far, so no earlier failure is missed. What fn(k)
// computed for indices after it is thrown away with the exception, as the
// plain loop would never have computed it.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace skelconv::detail {

/// The threads parallel_for starts by default: every core, at least 1.
inline unsigned parallel_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

template <class Fn>
void parallel_for(std::size_t count, Fn&& fn, std::size_t block = 16, unsigned threads = parallel_threads()) {
  block = std::max<std::size_t>(1, block);
  const std::size_t blocks = (count + block - 1) / block;
  threads = unsigned(std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(1, blocks)));
  if (threads <= 1) {
    for (std::size_t k = 0; k < count; ++k) fn(k);
    return;
  }
  std::atomic<std::size_t> next_block{0};
  std::atomic<std::size_t> lowest_failure{count};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t b = next_block++; b < blocks; b = next_block++) {
      const std::size_t end = std::min(count, (b + 1) * block);
      for (std::size_t k = b * block; k < end && k < lowest_failure.load(std::memory_order_relaxed); ++k) {
        try {
          fn(k);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(failure_mutex);
          if (k < lowest_failure.load()) lowest_failure = k, failure = std::current_exception();
          break;
        }
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  try {
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {
    // No more threads to be had: those started and this one do the work.
  }
  work();
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace skelconv::detail
