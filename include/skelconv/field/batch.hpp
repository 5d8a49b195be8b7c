// skelconv/field/batch.hpp — f and ∇f of a skeleton at many points, on all
// cores, with the same bytes whatever the number of threads.
//
// Determinism: each point is evaluated by Skeleton::value_and_gradient alone
// (no sum across points, no shared accumulator), so its result does not
// depend on which thread computed it or when. Threads take blocks of
// `block_size` consecutive points from a shared counter (balancing skeletons
// whose cost varies in space) and write each result to its own slot.
//
// Errors: the reported failure is the one at the LOWEST point index, again
// whatever the thread count: a thread stops a block at its first failure and
// skips points beyond the lowest failure found so far; every point before
// the final lowest failure has been evaluated, so no earlier failure can be
// missed. samples[k] is valid for every k < failure->index.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// The most threads a batch takes (BatchOptions::threads): above it the
/// count is a typo, not a machine (each thread reserves a stack, 8 MB of
/// address space on Linux, and the system may refuse thousands).
inline constexpr unsigned max_batch_threads = 1024;

struct BatchOptions {
  /// Number of threads; 0 = every core (std::thread::hardware_concurrency).
  /// At most max_batch_threads (InputError at "threads" otherwise).
  unsigned threads = 0;
  /// Points per work item: large enough that taking one costs nothing next
  /// to evaluating it, small enough to balance 2–64 threads on 10⁴ points.
  std::size_t block_size = 256;
  Skeleton::Acceleration acceleration = Skeleton::Acceleration::indexed;
  /// The tolerance mode's relative tolerance (Skeleton::value_and_gradient;
  /// docs/field.md, "Tolerance"); 0: exact.
  double tolerance = 0.0;
  /// If set, called with the number of points evaluated so far (whole
  /// blocks) at most once per `progress_interval` seconds, between blocks,
  /// by one thread at a time; never for the last block (the caller knows
  /// when the batch ends). `skelconv eval`'s progress line. The results do
  /// not depend on it.
  std::function<void(std::size_t evaluated)> progress;
  double progress_interval = 1.0;
};

struct BatchFailure {
  std::size_t index;         ///< the lowest failing point
  std::exception_ptr error;  ///< its InputError or EvaluationError
};

struct BatchResult {
  std::vector<FieldSample> samples;     ///< one per point
  std::optional<BatchFailure> failure;  ///< the first failure by index, if any
};

/// The number of threads `threads` = 0 stands for: every core, at least 1.
unsigned default_thread_count();

/// "at most 1024 threads (0: every core, N here)": the limit, as the
/// refusals of a larger count say it.
std::string thread_limit_text();

/// Throws InputError located at "threads", "<thread_limit_text()>, got N",
/// unless threads <= max_batch_threads.
void check_thread_count(unsigned threads);

/// f and ∇f at every point. Never throws for a point (see BatchResult);
/// throws what Skeleton::prepare() throws for an invalid skeleton.
BatchResult evaluate_batch(const Skeleton& skeleton, std::span<const Vec3> points, const BatchOptions& options = {});

/// The same, written into arrays the caller owns (nothing allocated, no
/// copy): point k is (xyz[3k], xyz[3k+1], xyz[3k+2]); f goes to values[k],
/// ∇f to gradients[3k … 3k+2]. values.size() = xyz.size() / 3 and
/// gradients.size() = xyz.size() (InputError otherwise). Returns the
/// failure at the lowest index, if any (slots before it are written).
std::optional<BatchFailure> evaluate_batch_into(const Skeleton& skeleton, std::span<const double> xyz,
                                                std::span<double> values, std::span<double> gradients,
                                                const BatchOptions& options = {});

/// Rethrows `error` (an InputError or EvaluationError; anything else as it
/// is) as the same kind, its whole message as the problem, located at
/// `where`: a failing point of a batch becomes "line 3: primitives[0]: ..."
/// in the CLI and "points[2]: primitives[0]: ..." in the Python module.
[[noreturn]] void rethrow_located(const std::exception_ptr& error, std::string where);

}  // namespace skelconv
