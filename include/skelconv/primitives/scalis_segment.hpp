// skelconv/primitives/scalis_segment.hpp — the SCALIS segment primitive: a
// scale-invariant integral surface along a segment whose radius varies
// linearly (docs/mathematics.md §4, Zanni et al. 2013 §3–4).
//
// With Γ(t) = A + t (B − A), the radius τ(t) = τ0 + (τ1 − τ0) t and the SCALIS
// kernel K of scale σ (docs/mathematics.md §1)
//
//     inverse  K(d) = (d/σ)^(−i)
//     cauchy   K(d) = (1 + (d/σ)²)^(−i/2)
//     compact  K(d) = (1 − (d/σ)²)^(i/2) for d < σ, else 0   (σ > 1)
//
// the field is
//
//     F(P) = ∫_0^1 K(|P − Γ(t)| / τ(t)) |AB| dt / τ(t),    f(P) = c F(P) / h
//
// with h = ∫ K(√(1 + u²)) du over ℝ, so that f = c (the iso value) at
// distance τ from an infinite line of constant radius τ:
//
//     inverse  h = σ^i W_i                    W_2 = π, W_3 = 2,
//     cauchy   h = σ^i (1 + σ²)^((1−i)/2) W_i  W_i = (i−3)/(i−2) W_{i−2}
//     compact  h = σ (1 − 1/σ²)^((i+1)/2) V_i  V_0 = 2, V_1 = π/2, V_i = i/(i+1) V_{i−2}
//
// F and ∇F come from the generated kernels (generated/scalis_segment_*.hpp)
// for the inverse and Cauchy families and from scalis_compact_F
// (skelconv/primitives/scalis_compact.hpp) for the compact family.
//
// Points where the integral diverges, reported as +inf (gradient (+inf,
// +inf, +inf)) as for Segment, decided exactly on the doubles given:
//   - inverse: P on the closed segment [A, B];
//   - cauchy: P at an end of radius 0 (the tip of a cone): there
//     τ^(i−1) q^(−i/2) ~ 1/t.
// Everything else is evaluated in the segment's own frame (coordinates and
// radii scaled by the power of two that brings |AB| into [1, 2),
// skelconv/detail/scaled_frame.hpp):
// F is scale invariant, so segments at any position and scale give the same
// relative accuracy. Any other non-finite result, or one outside the double
// range, throws EvaluationError; a σ whose normalisation h is outside the
// double range is refused (InputError at "kernel.sigma"), except for the
// inverse family, where σ^i cancels between F and h and any σ > 0 works.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/far_segment_rule.hpp"
#include "skelconv/primitives/scalis_segment_input.hpp"
#include "skelconv/primitives/segment_input.hpp"  // KernelFamily

namespace skelconv {

namespace generated {
template <class T>
struct ScalisSegmentKernel;  // generated/scalis_segment_table.hpp
}  // namespace generated
namespace detail {
template <class T>
struct CompactSegment;  // skelconv/detail/scalis_compact_support.hpp
}  // namespace detail

/// A SCALIS kernel: family, degree i and scale σ (docs/mathematics.md §1).
struct ScalisKernel {
  KernelFamily family = KernelFamily::cauchy;
  int degree = 4;
  double sigma = 1.0;  ///< > 0; > 1 for the compact family

  static ScalisKernel inverse(int degree, double sigma) { return {KernelFamily::inverse, degree, sigma}; }
  static ScalisKernel cauchy(int degree, double sigma) { return {KernelFamily::cauchy, degree, sigma}; }
  static ScalisKernel compact(int degree, double sigma) { return {KernelFamily::compact, degree, sigma}; }
};

class ScalisSegment {
 public:
  /// Degrees of the compact family (skelconv/primitives/scalis_compact.hpp); the
  /// inverse and Cauchy degrees are those of the generated table.
  static constexpr int min_compact_degree = 2, max_compact_degree = 10;

  /// Validates everything; throws InputError naming the field ("a", "b",
  /// "radius", "radius[k]", "kernel.degree", "kernel.sigma", "iso").
  ScalisSegment(const Vec3& a, const Vec3& b, double tau0, double tau1, const ScalisKernel& kernel,
                double iso = 1.0);

  const Vec3& a() const { return a_; }
  const Vec3& b() const { return b_; }
  double tau0() const { return tau0_; }
  double tau1() const { return tau1_; }
  const ScalisKernel& kernel() const { return kernel_; }
  double iso() const { return iso_; }
  /// h, the normalisation of this kernel: f = iso · F / h.
  double normalisation() const { return normalisation_; }
  /// "scalis_segment_cauchy_i4", or "scalis_compact_F" for the compact family.
  std::string evaluator_name() const;

  /// h = ∫ K(√(1 + u²)) du over ℝ for a SCALIS kernel (file comment).
  static double normalisation(KernelFamily family, int degree, double sigma);
  /// The degrees i available for `family`, ascending.
  static std::vector<int> supported_degrees(KernelFamily family);

  /// f(P) = iso · F(P) / h. Throws InputError if P is not finite,
  /// EvaluationError if the closed form fails in double precision.
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  FieldSample value_and_gradient(const Vec3& p) const;

  /// The short Gauss–Legendre rule of a Cauchy segment whose radii are both
  /// positive (far_segment_rule.hpp), which Skeleton's tolerance mode uses
  /// far from it; nullptr for every other SCALIS segment.
  const FarSegmentRule* far_rule() const { return far_rule_ ? &*far_rule_ : nullptr; }

 private:
  /// f = iso·F/h and/or ∇f (normalised, back in the world); +inf at the
  /// divergent points.
  double evaluate(const Vec3& p, bool want_value, std::array<double, 3>* grad) const;
  bool is_divergent_point(const Vec3& p, const Vec3& frame_p) const;

  Vec3 a_, b_;
  double tau0_ = 1.0, tau1_ = 1.0;
  ScalisKernel kernel_;
  double iso_ = 1.0;
  double normalisation_ = 1.0;
  /// The h the evaluation divides by: normalisation_, or for the inverse
  /// family W_i with σ = 1 in input_ (σ^i cancels; see the constructor).
  double evaluation_normalisation_ = 1.0;
  /// iso / evaluation_normalisation_, the factor of every F and ∇F.
  double field_scale_ = 1.0;
  /// The segment's frame (skelconv/detail/scaled_frame.hpp): |AB| scaled into
  /// [1, 2); F is scale invariant.
  ScaledFrame frame_;
  FrameFactors factors_;  ///< of F (value power 0)
  ScalisSegmentInput<double> input_;  ///< everything but P, in the frame
  const generated::ScalisSegmentKernel<double>* generated_ = nullptr;  ///< null for compact
  /// The generated kernel's per-segment quantities (its `prepare`, once, at
  /// construction, from input_): every evaluation reads them and does the
  /// per-point work only.
  std::vector<double> prepared_;
  /// The compact family's per-segment quantities (prepare_segment, once, at
  /// construction; null for the generated families).
  std::shared_ptr<const detail::CompactSegment<double>> compact_;
  /// Resolved once here, not per point: evaluator_name() (a C string, so
  /// that an evaluation allocates nothing) and where F diverges
  /// (is_divergent_point: on the segment itself, or at an end of radius 0).
  const char* name_ = "scalis_compact_F";
  bool diverges_on_segment_ = false;
  bool diverges_at_zero_radius_ = false;
  bool may_vanish_ = false;  ///< F may be 0 in double: the kernel has a finite support
  std::optional<FarSegmentRule> far_rule_;
};

}  // namespace skelconv
