// src/reconstruct/level_test.hpp — whether a skeleton's field is at or above
// its iso value at a point, decided as the exact evaluation decides it, bit
// for bit, but at the cost of the tolerance mode almost everywhere.
//
// The curve path's fit (surface_fit.cpp) bisects every ray to the surface
// f = iso, asking only f(P) ≥ iso; on a skeleton of thousands of Cauchy
// segments each exact f sums them all (CGAL's turbine: 2,357 segments, 93%
// of the run). The tolerance mode (docs/field.md, "Tolerance") gives f̃ with
// |f̃ − f| ≤ ε f at a third of the cost; where f̃ is farther from iso than
// `margin` f̃, a bound on |f̃ − f| plus |f − f_exact| (the exact evaluation's
// own error, its kernels' and its summation's), the exact evaluation is on
// the same side, and is not asked. Only the last few bisection steps of a
// ray, within ~1e-11 of the surface, ask it.
#pragma once

#include <atomic>
#include <cstddef>
#include <optional>

#include "skelconv/geometry.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::reconstruct {

class LevelTest {
 public:
  /// The tolerance mode's ε here (the mesher's).
  static constexpr double tolerance = Skeleton::default_tolerance;
  /// The relative error allowed each exact kernel evaluation (the kernels'
  /// asserted target is 1e-13: docs/verify_accuracy.md), ten times over.
  static constexpr double kernel_error = 1e-12;

  /// `skeleton` must outlive the test. The filter is used when the tolerance
  /// mode covers the skeleton's primitives (a sum, unweighted, of at least
  /// Skeleton::min_far_rule_segments segments that all have a far rule, at
  /// any nesting); otherwise every question is the exact evaluation's.
  explicit LevelTest(const Skeleton& skeleton);

  /// skeleton.value(p) ≥ skeleton.iso(), as the exact evaluation computes it.
  bool at_or_above(const Vec3& p) const;

  /// Whether the tolerance mode is asked first (for tests).
  bool filtered() const { return list_.has_value(); }
  /// The decisions the exact evaluation made (for tests: where the filter
  /// could not decide).
  std::size_t exact_questions() const { return exact_questions_.load(std::memory_order_relaxed); }

 private:
  const Skeleton& skeleton_;
  /// The same primitives as one list, in the same order: the tolerance mode
  /// covers lists only.
  std::optional<Skeleton> list_;
  double margin_ = 0.0;
  mutable std::atomic<std::size_t> exact_questions_{0};
};

}  // namespace skelconv::reconstruct
