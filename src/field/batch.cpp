// Implementation of skelconv/field/batch.hpp.
#include "skelconv/field/batch.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <utility>

#include "skelconv/errors.hpp"

namespace skelconv {

unsigned default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

BatchResult evaluate_batch(const Skeleton& skeleton, std::span<const Vec3> points, const BatchOptions& options) {
  skeleton.prepare();  // validates and builds the index before the threads share it
  BatchResult result;
  result.samples.resize(points.size());
  const std::size_t block = std::max<std::size_t>(1, options.block_size);
  const std::size_t blocks = (points.size() + block - 1) / block;
  const unsigned threads =
      unsigned(std::min<std::size_t>(options.threads == 0 ? default_thread_count() : options.threads,
                                     std::max<std::size_t>(1, blocks)));

  std::atomic<std::size_t> next_block{0};
  std::atomic<std::size_t> lowest_failure{points.size()};
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t b = next_block++; b < blocks; b = next_block++) {
      const std::size_t end = std::min(points.size(), (b + 1) * block);
      for (std::size_t k = b * block; k < end && k < lowest_failure.load(); ++k) {
        try {
          result.samples[k] = skeleton.value_and_gradient(points[k], options.acceleration);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(failure_mutex);
          if (k < lowest_failure.load()) {
            lowest_failure = k;
            result.failure = BatchFailure{k, std::current_exception()};
          }
          break;
        }
      }
    }
  };
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    for (std::thread& thread : pool) thread.join();
  }
  return result;
}

void rethrow_located(const std::exception_ptr& error, std::string where) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError& located) {
    throw InputError(located.what(), std::move(where));
  } catch (const EvaluationError& located) {
    throw EvaluationError(located.what(), std::move(where));
  }
}

}  // namespace skelconv
