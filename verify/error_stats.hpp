// verify/error_stats.hpp — relative errors of one evaluation against the
// reference, and their maxima over a sweep cell.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "extended_precision.hpp"
#include "sampling.hpp"

namespace skelconv::verify {

/// Accuracy the generated code must reach in double in the generic region
/// (the only region asserted for now; the others are reported). A double
/// closed form with a few dozen operations and no cancellation keeps ~1e-15;
/// the targets leave room for the moderate cancellations a generic point
/// still has, and the gradient one more digit since it differentiates.
struct AccuracyTargets {
  double generic_f = 1e-13;
  double generic_grad = 1e-12;
};

/// How many references a (family, degree, region) cell — all weight degrees
/// together — may lose, before its verdict fails. Excluded samples are the
/// ones whose reference stays flagged after the retry with the stronger
/// reference; if they clustered where the generated code is wrong, the sweep
/// would pass on what is left, so their share is bounded:
///  * max_excluded_share = 1%: an error confined to more than 1% of a
///    region's samples cannot hide behind exclusions. After the retry the
///    default sweeps exclude 0 (segments) and at most 1 of 200 (0.5%,
///    polygons) per cell (measured, docs/verify_reference.md); without it,
///    up to 6.5% and 15%. So 1% fails on a storm, not on the reference's usual doubts;
///  * min_compared_share = 1/2: at least half of a cell's evaluations must be
///    compared (the rest: excluded, or outside the compact support, where
///    f = 0 by design; support_boundary puts 1/3 of its samples there).
struct ExclusionLimits {
  double max_excluded_share = 0.01;
  double min_compared_share = 0.5;

  /// Whether a cell with these counts passes (`evaluations` counts every
  /// evaluation of the cell: compared, excluded, and outside the support).
  bool allow(std::uint64_t compared, std::uint64_t excluded, std::uint64_t evaluations) const {
    if (evaluations == 0) return true;
    return double(excluded) <= max_excluded_share * double(evaluations) &&
           double(compared) >= min_compared_share * double(evaluations) && compared > 0;
  }
};

/// Relative errors of one evaluation.
///  f:              |f − f_ref| / |f_ref|
///  grad:           |g − g_ref| / |g_ref|                 (norm-wise)
///  grad_component: max_c |g_c − g_ref,c| / |g_ref|       (component-wise,
///                  normalised by the norm: a component that is small because
///                  of symmetry cannot have a meaningful relative error of its
///                  own, but an error large compared to |∇f| is visible here)
/// A non-finite result counts as an infinite error.
struct RelativeErrors {
  double f = 0;
  double grad = 0;
  double grad_component = 0;
  bool nonfinite = false;
};

template <class T>
RelativeErrors relative_errors(const T& f, const Vec3<T>& grad, const extended& f_ref, const Vec3<extended>& g_ref) {
  using std::isfinite;
  RelativeErrors out;
  const extended fe(f);
  const Vec3<extended> ge{extended(grad[0]), extended(grad[1]), extended(grad[2])};
  if (!isfinite(fe) || !isfinite(ge[0]) || !isfinite(ge[1]) || !isfinite(ge[2])) {
    out.nonfinite = true;
    out.f = out.grad = out.grad_component = std::numeric_limits<double>::infinity();
    return out;
  }
  out.f = static_cast<double>(abs(fe - f_ref) / abs(f_ref));
  const extended g_norm = norm(g_ref);
  const Vec3<extended> diff = sub(ge, g_ref);
  out.grad = static_cast<double>(norm(diff) / g_norm);
  for (int c = 0; c < 3; ++c) out.grad_component = std::max(out.grad_component, static_cast<double>(abs(diff[c]) / g_norm));
  return out;
}

inline RelativeErrors worst_of(const RelativeErrors& x, const RelativeErrors& y) {
  return {std::max(x.f, y.f), std::max(x.grad, y.grad), std::max(x.grad_component, y.grad_component),
          x.nonfinite || y.nonfinite};
}

/// Maxima of one precision (double or extended) over a cell, with the sample
/// that produced each maximum (for reproduction).
struct PrecisionStats {
  double max_f = 0;
  double max_grad = 0;
  double max_grad_component = 0;
  std::uint64_t nonfinite = 0;
  std::uint64_t f_above_target = 0;     ///< points with f error above the generic f target
  std::uint64_t grad_above_target = 0;  ///< points with |∇f| error above the generic ∇f target
  std::optional<SweepProblem> worst_f, worst_grad;

  /// Whether an error `value` of sample `index` becomes the new maximum over
  /// (`current`, `worst`). On a tie the smaller sample index wins, so the
  /// worst sample does not depend on the order in which threads or shards
  /// merge (a sample index is unique within a cell): a merged sharded sweep
  /// reports the same samples as the unsharded one.
  static bool replaces(double value, std::uint64_t index, double current, const std::optional<SweepProblem>& worst) {
    return !worst || value > current || (value == current && index < worst->index);
  }

  void add(const RelativeErrors& e, const SweepProblem& problem, const AccuracyTargets& targets) {
    if (e.nonfinite) ++nonfinite;
    if (!(e.f <= targets.generic_f)) ++f_above_target;
    if (!(e.grad <= targets.generic_grad)) ++grad_above_target;
    if (replaces(e.f, problem.index, max_f, worst_f)) max_f = e.f, worst_f = problem;
    if (replaces(e.grad, problem.index, max_grad, worst_grad)) max_grad = e.grad, worst_grad = problem;
    max_grad_component = std::max(max_grad_component, e.grad_component);
  }
  void merge(const PrecisionStats& o) {
    if (o.worst_f && replaces(o.max_f, o.worst_f->index, max_f, worst_f)) max_f = o.max_f, worst_f = o.worst_f;
    if (o.worst_grad && replaces(o.max_grad, o.worst_grad->index, max_grad, worst_grad))
      max_grad = o.max_grad, worst_grad = o.worst_grad;
    max_grad_component = std::max(max_grad_component, o.max_grad_component);
    nonfinite += o.nonfinite;
    f_above_target += o.f_above_target;
    grad_above_target += o.grad_above_target;
  }
};

/// One cell of the report: (family, degree, weight degree, region).
struct CellStats {
  std::uint64_t points = 0;            ///< compared points
  std::uint64_t excluded = 0;          ///< reference flagged even after the retry: not compared
  std::uint64_t retried = 0;           ///< reference flagged at first, recomputed with ReferenceTolerances::retry
  std::uint64_t outside_support = 0;   ///< compact, P outside the support: f = 0 and the double clip agrees
  std::uint64_t support_mismatch = 0;  ///< compact: binary128 and double clips disagree on emptiness
  PrecisionStats in_double;
  PrecisionStats in_extended;
  double max_reference_error = 0;      ///< largest error estimate among the compared references

  void merge(const CellStats& o) {
    points += o.points;
    excluded += o.excluded;
    retried += o.retried;
    outside_support += o.outside_support;
    support_mismatch += o.support_mismatch;
    in_double.merge(o.in_double);
    in_extended.merge(o.in_extended);
    max_reference_error = std::max(max_reference_error, o.max_reference_error);
  }
};

}  // namespace skelconv::verify
