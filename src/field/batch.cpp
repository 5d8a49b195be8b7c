// Implementation of skelconv/field/batch.hpp.
#include "skelconv/field/batch.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv {

unsigned default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

namespace {

/// Runs evaluate_point(k) for k in [0, count) on the threads of `options`,
/// in blocks (batch.hpp, "Determinism" and "Errors"); returns the failure at
/// the lowest index.
template <class EvaluatePoint>
std::optional<BatchFailure> run_blocks(std::size_t count, const BatchOptions& options, EvaluatePoint evaluate_point) {
  const std::size_t block = std::max<std::size_t>(1, options.block_size);
  const std::size_t blocks = (count + block - 1) / block;
  const unsigned threads = unsigned(std::min<std::size_t>(
      options.threads == 0 ? default_thread_count() : options.threads, std::max<std::size_t>(1, blocks)));

  std::atomic<std::size_t> next_block{0};
  std::atomic<std::size_t> lowest_failure{count};
  std::optional<BatchFailure> failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t b = next_block++; b < blocks; b = next_block++) {
      const std::size_t end = std::min(count, (b + 1) * block);
      for (std::size_t k = b * block; k < end && k < lowest_failure.load(std::memory_order_relaxed); ++k) {
        try {
          evaluate_point(k);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(failure_mutex);
          if (k < lowest_failure.load()) {
            lowest_failure = k;
            failure = BatchFailure{k, std::current_exception()};
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
  return failure;
}

}  // namespace

BatchResult evaluate_batch(const Skeleton& skeleton, std::span<const Vec3> points, const BatchOptions& options) {
  Skeleton::checked_tolerance(options.tolerance);  // a bad option is no point's failure
  skeleton.prepare();  // validates and builds the index before the threads share it
  BatchResult result;
  result.samples.resize(points.size());
  result.failure = run_blocks(points.size(), options, [&](std::size_t k) {
    result.samples[k] = skeleton.value_and_gradient(points[k], options.acceleration, options.tolerance);
  });
  return result;
}

std::optional<BatchFailure> evaluate_batch_into(const Skeleton& skeleton, std::span<const double> xyz,
                                                std::span<double> values, std::span<double> gradients,
                                                const BatchOptions& options) {
  if (xyz.size() % 3 != 0 || values.size() != xyz.size() / 3 || gradients.size() != xyz.size()) {
    throw InputError(fmt::format("evaluate_batch_into needs 3N coordinates, N values and 3N gradient slots, got "
                                 "{}, {} and {}",
                                 xyz.size(), values.size(), gradients.size()));
  }
  Skeleton::checked_tolerance(options.tolerance);
  skeleton.prepare();
  return run_blocks(values.size(), options, [&](std::size_t k) {
    const FieldSample s =
        skeleton.value_and_gradient(Vec3(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]), options.acceleration,
                                    options.tolerance);
    values[k] = s.value;
    for (int c = 0; c < 3; ++c) gradients[3 * k + std::size_t(c)] = s.gradient[c];
  });
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
