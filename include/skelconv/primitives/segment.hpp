// skelconv/primitives/segment.hpp — the segment primitive: a convolution surface field
// of a weighted line segment (docs/mathematics.md §2, Hubert 2012 §3).
//
//     f(P) = |AB| ∫_0^1 w(t) K(|P − Γ(t)|) dt,   Γ(t) = A + t (B − A)
//
// with the kernel K of a KernelSpec and the weight polynomial
// w(t) = Σ_k w_k t^k (k ≤ 3). The closed forms live in the generated table
// (docs/generated_api.md); this class validates its inputs once, picks the
// generated function, and handles the two cases the generated code must not
// see:
//   - finite-support kernels (compact, soft, wyvill: the trait's
//     support_radius R): P farther than R from the whole segment. The clip of
//     [A,B] to the ball of radius R around P (skelconv/detail/clip.hpp) is empty,
//     and f = 0, ∇f = 0 exactly. Otherwise, when P's foot on the line lies
//     on B's half of the segment, the generated code is given the segment
//     read from B (ends swapped, weight w(1 − t), prepared once beside the
//     direct one): the closed forms measure from their first end and lose
//     ~ε (|AB|/R)² far from it (src/primitives/reversed_segment.hpp).
//   - kernels singular at 0 (inverse): P on the segment itself. The integrand r^(-i) is not
//     integrable there (i ≥ 1), f = +∞. By convention value() returns +inf
//     and gradient() returns (+inf, +inf, +inf): there is no meaningful
//     direction, and +inf (never NaN) keeps sums of fields well defined.
//     "On the segment" is decided exactly on the doubles given:
//     AB × AP == 0 (all three components) and 0 ≤ AB·AP ≤ |AB|², i.e. the
//     projection parameter t = AB·AP / |AB|² lies in [0, 1].
//     For a weight that is positive there, +inf is the limit of f as P
//     approaches the segment; for other weights it is just the marker.
// Everything else goes to the generated code, evaluated in the segment's
// own frame (skelconv/detail/scaled_frame.hpp): coordinates scaled by a power of
// two that brings |AB| into [1, 2), s and R scaled with it, so that segments at any
// position and of any normal length give the same relative accuracy; f and
// ∇f are scaled back exactly by the kernel's homogeneity. Its result is
// checked: the field is finite there, so a NaN or ±inf result (a closed
// form failing, e.g. for a point within ~1e-100 |AB| of the segment) or a
// value outside the double range (f underflowing far from the segment, or
// overflowing near a tiny one) throws EvaluationError instead of being
// returned.
#pragma once

#include <array>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/far_segment_rule.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv {

namespace generated {
template <class T>
struct SegmentKernel;  // generated/segment_table.hpp, only used by pointer here
}  // namespace generated

class Segment {
 public:
  /// Most weight coefficients w_0 … w_3 (weight degree ≤ max_weight_degree).
  static constexpr std::size_t max_weight_coefficients = max_weight_degree + 1;
  /// Weight coefficients from this magnitude on leave the closed forms
  /// little headroom in double: their terms reach about 1e5 times the
  /// weight (a Cauchy i = 16 segment with weights [1e303, 1e303] returned a
  /// NaN gradient at 0.5 lengths, [1e300, 1e300] did not). A NaN or an
  /// infinity there is reported as the weight's, at `weight`.
  static constexpr double weight_overflow_start = 1e280;

  /// A segment is degenerate, and rejected, when |B − A| is below this
  /// fraction of its largest coordinate magnitude max(|A|∞, |B|∞): the end
  /// points are then known to fewer than ~8 significant digits relative to
  /// the segment's own length (a double coordinate carries a relative error
  /// of 1.1e-16 of its magnitude), and the closed forms, which divide by |AB|²
  /// and by AB-relative quantities, would lose the rest. |B − A| = 0, and
  /// lengths whose square is not a normal double, are rejected as well.
  static constexpr double degenerate_length_ratio = 1e-8;

  /// Validates everything and looks up the generated kernel (or the derived
  /// one of a family without a degree, derived_segment_kernels.hpp); throws
  /// InputError naming the offending field ("a", "b", "weight",
  /// "kernel.degree", "kernel.s", "kernel.R") and the problem.
  /// `weight` lists w_0 … w_d (1 to 4 coefficients, finite, not all zero);
  /// trailing zeros are dropped, so {1, 0.5, 0} uses the cheaper linear-weight
  /// closed form. Default: w(t) = 1.
  Segment(const Vec3& a, const Vec3& b, const KernelSpec& kernel,
          std::span<const double> weight);
  Segment(const Vec3& a, const Vec3& b, const KernelSpec& kernel,
          std::initializer_list<double> weight = {1.0})
      : Segment(a, b, kernel, std::span<const double>(weight.begin(), weight.size())) {}

  const Vec3& a() const { return a_; }
  const Vec3& b() const { return b_; }
  const KernelSpec& kernel() const { return kernel_; }
  /// w_0 … w_d with trailing zeros dropped (d = weight_degree()).
  std::span<const double> weight() const { return {input_.w.data(), std::size_t(weight_degree_ + 1)}; }
  int weight_degree() const { return weight_degree_; }
  /// Name of the generated function in use, e.g. "segment_cauchy_i4_w1".
  std::string generated_name() const;

  /// The kernel degrees i the generated table offers for `family` with a
  /// weight of degree `weight_degree`, ascending (docs/generated_api.md).
  static std::vector<int> supported_degrees(KernelFamily family, int weight_degree = 0);

  /// f(P). Throws InputError if P is not finite, EvaluationError if the
  /// closed form fails in double precision (see the file comment).
  double value(const Vec3& p) const;
  /// ∇f(P), same rules as value().
  Vec3 gradient(const Vec3& p) const;
  /// f(P) and ∇f(P) together; cheaper than both calls (shared terms).
  FieldSample value_and_gradient(const Vec3& p) const;

  /// The short Gauss–Legendre rule of a Cauchy segment whose weight has no
  /// negative coefficient (far_segment_rule.hpp), which Skeleton's tolerance
  /// mode uses far from it; nullptr for every other segment.
  const FarSegmentRule* far_rule() const { return far_rule_ ? &*far_rule_ : nullptr; }

 private:
  /// What an evaluation at P has to do (see the file comment).
  enum class Case {
    call_generated,          ///< the closed form applies; point is filled in
    outside_compact_support, ///< compact kernel, P farther than R: f = 0
    on_inverse_singularity,  ///< inverse kernel, P on the segment: f = +inf
  };
  /// P in the frame, and for a finite-support kernel the clip [t0, t1] of
  /// its support on the segment read from the nearer end; `prepared` is that
  /// reading's preparation (prepared_ or prepared_from_b_; null for the Gaussian).
  Case locate(const Vec3& p, SegmentPoint<double>& point, const double*& prepared) const;
  /// The generated f, ∇f or both at `point`: from `prepared` where the kernel
  /// is split (every generated one, and the compact combinations of soft and
  /// Wyvill), else from input_ (the Gaussian).
  double call_f(const SegmentPoint<double>& point, const double* prepared) const;
  std::array<double, 3> call_grad(const SegmentPoint<double>& point, const double* prepared) const;
  double call_f_and_grad(const SegmentPoint<double>& point, const double* prepared, std::array<double, 3>& g) const;

  /// f' of the frame → f (and ∇f, with value_power_ − 1), see scaled_frame.hpp.
  double restore_value(double f, const Vec3& p) const;
  Vec3 restore_gradient(const std::array<double, 3>& g, const Vec3& p) const;

  Vec3 a_, b_;
  KernelSpec kernel_;
  int weight_degree_ = 0;
  /// The segment's frame: |AB| scaled into [1, 2), and its factors for f.
  ScaledFrame frame_;
  FrameFactors factors_;
  /// f has units length^value_power_: 1 − i (inverse) or 1.
  int value_power_ = 1;
  /// f can be 0 or tiny (compact kernel, a negative weight coefficient);
  /// otherwise f > 0 and a 0 or subnormal result is an underflow (an error).
  bool may_vanish_ = false;
  bool kernel_vanishes_far_ = false;  ///< ∇f may be 0 or subnormal: the kernel vanishes or underflows far away
  /// The largest |w_k|: above weight_overflow_start, a NaN or infinity out of
  /// the closed form is blamed on the weight (require_weight_headroom).
  double largest_weight_ = 0.0;
  /// Throws EvaluationError at "weight" when f or ∇f came out of the closed
  /// form non-finite (`what`: that result) and the weight is that large.
  void require_weight_headroom(const std::string& what, const Vec3& p) const;
  /// Everything but P (and the compact clip interval), filled once, in the frame.
  SegmentInput<double> input_;
  const generated::SegmentKernel<double>* generated_ = nullptr;
  /// The generated kernel's per-segment quantities (its `prepare`, once, at
  /// construction): every evaluation reads them and does the per-point work only.
  std::vector<double> prepared_;
  /// Finite-support kernels only: the same segment read from B (ends swapped,
  /// weight w(1 − t)) and its preparation, for P on B's half.
  SegmentInput<double> input_from_b_;
  std::vector<double> prepared_from_b_;
  /// From the kernel's trait: K = 0 beyond this (+inf: no clip), and K(0) = +inf.
  double support_radius_ = 0.0;
  bool singular_at_zero_ = false;
  std::optional<FarSegmentRule> far_rule_;
};

}  // namespace skelconv
