// Implementation of skelconv/field/batch.hpp.
#include "skelconv/field/batch.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <fmt/format.h>

#include "skelconv/errors.hpp"

#include "../detail/parallel_for.hpp"

namespace skelconv {

unsigned default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

std::string thread_limit_text() {
  return fmt::format("at most {} threads (0: every core, {} here)", max_batch_threads, default_thread_count());
}

void check_thread_count(unsigned threads) {
  if (threads <= max_batch_threads) return;
  throw InputError(fmt::format("{}, got {}", thread_limit_text(), threads), "threads");
}

namespace {

/// The threads run_blocks runs `count` points on: never more than blocks.
unsigned thread_count(std::size_t count, const BatchOptions& options) {
  const std::size_t block = std::max<std::size_t>(1, options.block_size);
  const std::size_t blocks = (count + block - 1) / block;
  return unsigned(std::min<std::size_t>(options.threads == 0 ? default_thread_count() : options.threads,
                                        std::max<std::size_t>(1, blocks)));
}

/// Runs evaluate_point(k) for k in [0, count) on the threads of `options`
/// (thread_count), in blocks (batch.hpp, "Determinism" and "Errors");
/// returns the failure at the lowest index.
template <class EvaluatePoint>
std::optional<BatchFailure> run_blocks(std::size_t count, const BatchOptions& options, EvaluatePoint evaluate_point) {
  // BatchOptions::progress: whole blocks counted, one thread reporting at a
  // time (a thread that finds another reporting goes on), the clock read
  // once per block.
  std::atomic<std::size_t> evaluated{0};
  std::mutex progress_mutex;
  auto last_report = std::chrono::steady_clock::now();
  const auto block_done = [&](std::size_t points) {
    if (!options.progress) return;
    evaluated += points;
    const std::unique_lock<std::mutex> lock(progress_mutex, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const std::size_t done = evaluated.load();  // read under the lock: the reported counts grow
    if (done == count) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_report).count() < options.progress_interval) return;
    last_report = now;
    options.progress(done);
  };
  const auto failure =
      detail::parallel_blocks(count, evaluate_point, options.block_size, thread_count(count, options), block_done);
  if (!failure) return std::nullopt;
  return BatchFailure{failure->index, failure->error};
}

/// Results at least this large are new pages from the kernel on every call
/// (glibc maps anything above 32 MB afresh and unmaps it on free): worth
/// asking for transparent huge pages.
constexpr std::size_t huge_page_result_bytes = std::size_t(4) << 20;

/// Asks the kernel to back the untouched buffer [data, data + bytes) with
/// transparent huge pages where it can: one fault per 2 MB instead of one
/// per 4 kB. A fresh 64 MB result otherwise takes 16,384 faults, which on a
/// virtual machine cost more than writing the samples (docs/field.md, "Cost
/// of the public path"). A hint only: ignored where THP is off or not Linux.
void advise_huge_pages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < huge_page_result_bytes) return;
  constexpr std::uintptr_t page = 4096;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(data) + bytes;
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace

BatchResult evaluate_batch(const Skeleton& skeleton, std::span<const Vec3> points, const BatchOptions& options) {
  Skeleton::checked_tolerance(options.tolerance);  // a bad option is no point's failure
  check_thread_count(options.threads);
  skeleton.prepare();  // validates and builds the index before the threads share it
  BatchResult result;
  result.samples.reserve(points.size());
  advise_huge_pages(result.samples.data(), points.size() * sizeof(FieldSample));
  if (thread_count(points.size(), options) <= 1) {
    // One thread takes the points in order: each sample is constructed in
    // place once, not zeroed by resize first and then overwritten (a 64 MB
    // result is a second pass over memory that no cache holds).
    result.failure = run_blocks(points.size(), options, [&](std::size_t k) {
      result.samples.push_back(skeleton.value_and_gradient(points[k], options.acceleration, options.tolerance));
    });
    result.samples.resize(points.size());  // zeros after a failure (batch.hpp: samples[k] valid for k < index)
    return result;
  }
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
  check_thread_count(options.threads);
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
