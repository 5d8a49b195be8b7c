// parallel_for.hpp — run fn(k) for k in [0, count) on several threads, with
// the same results as the plain loop when each fn(k) writes only its own
// slot. The one thread pool of skelconv: the batches (field/batch.cpp), the
// mesher's seeds, continuation and projection, the reconstruction's fits.
//
// Threads take blocks of `block` consecutive indices from a shared counter
// (the cost of an index may vary a lot: a ray that marches far, a point deep
// in a crowd of primitives). Errors: the failure kept is the one of the
// LOWEST failing index, the one the plain loop would have met first; a
// thread stops a block at its first failure and skips indices beyond the
// lowest failure found so far, so no earlier failure is missed. What fn(k)
// computed for indices after it is thrown away with the failure, as the
// plain loop would never have computed it.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

namespace skelconv::detail {

/// The threads parallel_for starts by default: every core, at least 1.
inline unsigned parallel_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

/// The lowest failing index and what it threw.
struct IndexedFailure {
  std::size_t index;
  std::exception_ptr error;
};

/// fn(k) for every k in [0, count) on at most `threads` threads (this one
/// among them), in blocks of `block`; block_done(n) after each block of n
/// indices, on the thread that ran it (a progress count: it must be safe to
/// call from several threads). Returns the failure of the lowest index, if
/// any, instead of throwing it.
template <class Fn, class BlockDone>
std::optional<IndexedFailure> parallel_blocks(std::size_t count, Fn&& fn, std::size_t block, unsigned threads,
                                              BlockDone&& block_done) {
  block = std::max<std::size_t>(1, block);
  const std::size_t blocks = (count + block - 1) / block;
  threads = unsigned(std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(1, blocks)));
  // What the helper threads share with this one, kept alive by each of
  // them: a helper that starts after the last block was taken (on a
  // loaded machine, a new thread may wait long for a core) finds no block
  // left and ends without touching anything else, so this thread waits
  // only for the blocks taken, never for a helper to be scheduled.
  struct Shared {
    std::atomic<std::size_t> next_block{0};
    std::size_t done_blocks = 0;  ///< under `mutex`
    std::mutex mutex;
    std::condition_variable all_done;
  };
  const auto shared = std::make_shared<Shared>();
  std::atomic<std::size_t> lowest_failure{count};
  std::optional<IndexedFailure> failure;
  std::mutex failure_mutex;
  // Runs block b; everything it refers to lives until every block is done.
  const auto run_block = [&](std::size_t b) {
    const std::size_t end = std::min(count, (b + 1) * block);
    for (std::size_t k = b * block; k < end && k < lowest_failure.load(std::memory_order_relaxed); ++k) {
      try {
        fn(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (k < lowest_failure.load()) lowest_failure = k, failure = IndexedFailure{k, std::current_exception()};
        break;
      }
    }
    block_done(end - b * block);
  };
  const auto work = [shared, blocks, run_ptr = &run_block] {
    for (std::size_t b = shared->next_block++; b < blocks; b = shared->next_block++) {
      (*run_ptr)(b);
      const std::lock_guard<std::mutex> lock(shared->mutex);
      if (++shared->done_blocks == blocks) shared->all_done.notify_all();
    }
  };
  try {
    for (unsigned t = 1; t < threads; ++t) std::thread(work).detach();
  } catch (const std::system_error&) {
    // No more threads to be had (a count far above the cores, or a memory
    // limit on the stacks): those started and this one do the work, with
    // the same results.
  }
  work();
  std::unique_lock<std::mutex> lock(shared->mutex);
  shared->all_done.wait(lock, [&] { return shared->done_blocks == blocks; });
  return failure;
}

/// parallel_blocks without a progress count, rethrowing the failure of the
/// lowest index.
template <class Fn>
void parallel_for(std::size_t count, Fn&& fn, std::size_t block = 16, unsigned threads = parallel_threads()) {
  if (const auto failure = parallel_blocks(count, fn, block, threads, [](std::size_t) {}))
    std::rethrow_exception(failure->error);
}

}  // namespace skelconv::detail
