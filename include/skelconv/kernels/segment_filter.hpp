// skelconv/kernels/segment_filter.hpp — generated segment kernels behind a
// floating-point filter: fast and exact at once.
//
// Every generated segment kernel has a stable form (generated/segment_*.hpp,
// <name>_{f,grad,f_and_grad}: run-time choices of stable rewrites near the
// line, beyond an end, in the far field) and, where its generic path calls no
// helper, a fast form (<name>_fast_*: the generic formula alone). The filter
// (CGAL's filtered kernels, Shewchuk's adaptive predicates) evaluates the
// fast form on RelativeError<double> (skelconv/kernels/relative_error.hpp),
// whose bound on the rounding error the compiler folds to constants except
// at the sums that can cancel, and accepts it when
//
//     bound ≤ tolerance · (|value| − bound)
//
// (so the relative error against the exact value is ≤ tolerance; for ∇f,
// Euclidean norms: the error vector's is at most that of the components'
// bounds). Elsewhere it returns the stable form. verify/filter_check.cpp
// checks the bound against binary128 references.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "skelconv/kernels/op_count.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv {

namespace generated {
template <class T>
struct SegmentKernel;
}  // namespace generated
struct FastFormWrappers;  // src/kernels/segment_filter.cpp

/// The default relative tolerance of the filter: the verifier's accuracy
/// goal for every generated kernel and region (docs/verify.md), so that an
/// accepted fast value is as good as the stable forms are required to be.
inline constexpr double kDefaultFilterTolerance = 1e-13;

/// What the fast form gave, with its error bounds (absolute, per component
/// for ∇f).
struct FastEvaluation {
  double f = 0, f_bound = 0;
  std::array<double, 3> grad{}, grad_bounds{};
  /// A bound on the Euclidean norm of ∇f's error vector.
  double grad_bound() const { return std::hypot(grad_bounds[0], grad_bounds[1], grad_bounds[2]); }
};

/// Whether a fast value of size `magnitude` with error bound `bound` passes
/// at `tolerance` (never an infinite or NaN one).
inline bool filter_accepts(double magnitude, double bound, double tolerance) {
  return magnitude < std::numeric_limits<double>::infinity() && bound <= tolerance * (magnitude - bound);
}

/// The same for a gradient `g` with component bounds `b`, in Euclidean
/// norms: bound ≤ tolerance (|g| − bound) ⟺ |b|² (1 + tolerance)² ≤
/// tolerance² |g|², compared without square roots where the squares can
/// neither overflow nor underflow to the scale of the comparison (|g| in
/// [1e−100, 1e100]: an underflowing b_i² is then below 1e−226, far under
/// tolerance² |g|²); elsewhere with hypot. The rounding of the sums of
/// squares (relative ≤ 3u) is inside the bounds' own safety margin
/// (relative_error.hpp).
inline bool filter_accepts_gradient(const std::array<double, 3>& g, const std::array<double, 3>& b,
                                    double tolerance) {
  const double largest = std::max({std::abs(g[0]), std::abs(g[1]), std::abs(g[2])});
  if (!(largest >= 1e-100 && largest <= 1e100))
    return filter_accepts(std::hypot(g[0], g[1], g[2]), std::hypot(b[0], b[1], b[2]), tolerance);
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const double scale = 1 + tolerance;
  return b2 * (scale * scale) <= tolerance * tolerance * g2;
}

/// One generated segment kernel with its filter.
class FilteredSegmentKernel {
 public:
  /// nullptr where (family, degree, weight degree) was not generated.
  static const FilteredSegmentKernel* find(KernelFamily family, int degree, int weight_degree);

  /// Whether the kernel has a fast form (else the filter always falls back).
  bool has_fast_form() const { return fast_ != nullptr; }
  const generated::SegmentKernel<double>& stable() const { return *stable_; }

  /// The fast forms alone, with their bounds (no fallback); false without a
  /// fast form. `which`: 0 f, 1 ∇f, 2 both (the fields it does not compute
  /// stay 0).
  bool evaluate_fast(const SegmentInput<double>& in, int which, FastEvaluation& out) const;

  /// f, ∇f, both: the fast form where the filter accepts it, else the stable
  /// one; `accepted` (if given) says which.
  double f(const SegmentInput<double>& in, double tolerance = kDefaultFilterTolerance,
           bool* accepted = nullptr) const;
  std::array<double, 3> grad(const SegmentInput<double>& in, double tolerance = kDefaultFilterTolerance,
                             bool* accepted = nullptr) const;
  double f_and_grad(const SegmentInput<double>& in, std::array<double, 3>& grad,
                    double tolerance = kDefaultFilterTolerance, bool* accepted = nullptr) const;

  /// The fast form's operation count (generic path, the generator's
  /// counting rules; the bound's operations are not counted): `which` 0 f,
  /// 1 ∇f, 2 both; empty without a fast form.
  OpCount fast_operation_count(int which) const;

  /// The stable function alone (the fallback), for comparisons.
  double stable_f(const SegmentInput<double>& in) const;
  double stable_f_and_grad(const SegmentInput<double>& in, std::array<double, 3>& grad) const;

  FilteredSegmentKernel(const generated::SegmentKernel<double>* stable, const FastFormWrappers* fast)
      : stable_(stable), fast_(fast) {}

 private:
  const generated::SegmentKernel<double>* stable_;
  const FastFormWrappers* fast_;
};

}  // namespace skelconv
