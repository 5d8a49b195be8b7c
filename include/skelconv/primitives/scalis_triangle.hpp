// skelconv/primitives/scalis_triangle.hpp — the SCALIS triangle primitive: a
// scale-invariant integral surface over a triangle whose radius is given at
// the vertices and interpolated linearly (docs/mathematics.md §4, Zanni et al. 2013 §5.2,
// eq. 15).
//
// With τ(Q) the barycentric interpolation of the vertex radii τ0, τ1, τ2 and
// the SCALIS kernel K of scale σ (docs/mathematics.md §1)
//
//     inverse  K(d) = (d/σ)^(−i)
//     cauchy   K(d) = (1 + (d/σ)²)^(−i/2)
//     compact  K(d) = (1 − (d/σ)²)^(i/2) for d < σ, else 0   (σ > 1)
//
// the field is
//
//     F(P) = ∬_T K(|P − Q| / τ(Q)) dQ / τ(Q)²,      f(P) = c F(P) / h
//
// (1/τ² rather than the segment's 1/τ: a homothety multiplies areas by the
// square of its ratio, Zanni §5.2), with h = ∬ K(√(1 + |u|²)) du over the
// plane, so that f = c (the iso value) at distance τ from an infinite plane
// of constant radius τ. With t = 1 + |u|²,  h = π ∫_1^∞ K(√t) dt:
//
//     inverse  h = 2π σ^i / (i − 2)
//     cauchy   h = 2π σ² (1 + 1/σ²)^(1 − i/2) / (i − 2)
//     compact  h = 2π σ² (1 − 1/σ²)^((i + 2)/2) / (i + 2)
//
// (checked by quadrature in tests/scalis_triangle_test.cpp). For i = 2 the
// inverse and Cauchy h diverge (K ~ d^−2 over a plane), so those kernels
// start at i = 3.
//
// TWO PATHS, chosen once by the constructor (uses_closed_form()):
//  * CLOSED FORM — all three radii equal (τ > 0), and the kernel one the
//    polygon closed forms offer (inverse and Cauchy 3…10; compact 4, 6, 8,
//    10). With constant τ, K(r/τ) is a classical kernel of r = |P − Q|
//    (Zanni eq. 15 reduced to Hubert 2012): Cauchy c_s^i with s = 1/(σ²τ²),
//    inverse (στ)^i p^i, compact k_R^i with R = στ; F = C/τ², ∇F = ∇C/τ²,
//    C the polygon field of skelconv/primitives/polygon.hpp (exact to rounding, its
//    own accuracy notes apply).
//  * NUMERICAL — varying radius (no closed form is published), and the
//    compact degrees 2, 3, 5, 7, 9 even at constant radius: nested adaptive
//    Gauss–Kronrod quadrature of the definition (method in
//    src/primitives/scalis_triangle_quadrature.hpp), requesting a relative
//    error of requested_tolerance, with an error estimate (which includes
//    the rounding noise of the compact kernel's support test). The result
//    is returned only if the estimate is within certified_tolerance of |F|,
//    and for ∇F within certified_tolerance of max(|∇F|, 1e-3 M), M the sum
//    of the magnitudes of the parts ∇F is assembled from (where they cancel,
//    e.g. just above the centre of a symmetric triangle, |∇F| alone is not
//    a scale any floating-point sum can be relative to) — or, where F is
//    tiny (F < absolute_floor · h, 1e-6 of its value on a plane's surface),
//    within an absolute floor (absolute_floor below: f's error then stays
//    below 1e-16 · iso); otherwise EvaluationError ("numerical integration
//    could not reach 1e-10 …").
//    Measured (tests/scalis_triangle_test.cpp and 3,200 random points):
//    every evaluation certified; agreement with the closed form, with an
//    independent long-double quadrature and with additivity to 1e-15–3e-13;
//    estimates ≤ 1e-13 (inverse, Cauchy) and ≤ 7e-12 (compact). Cost per
//    value_and_gradient: 1,000–50,000 integrand evaluations, median
//    25–130 µs, up to ~1 ms, ~2–4 ms for P within 1e-7 of a large triangle.
//    KNOWN LIMIT: near a vertex of radius 0 (a second singular point of
//    K/τ², F ~ log) the cost grows: ~35,000–60,000 evaluations at 1e-2…1e-4
//    (relative to the edges) from the tip, ~10⁶ (~1 s) at 1e-6, and in the
//    triangle's plane at 1e-8 the gradient's estimate stalls at ~1e-9 and
//    gradient() / value_and_gradient() throw EvaluationError (value() still
//    certifies). At the tip itself the field is +inf (below).
//
// Both paths run in the triangle's own frame (coordinates and radii scaled
// by the power of two that brings the diameter into [1, 2),
// skelconv/detail/scaled_frame.hpp;
// F is scale invariant), so triangles at any position and scale give the
// same relative accuracy; a result outside the double range, and a σ whose
// normalisation h is, are errors.
//
// Points where the integral diverges give +inf (gradient (+inf, +inf,
// +inf)), as for the other primitives: the inverse kernel with P in the
// closed triangle; the Cauchy kernel with P at a point of radius 0 of the
// closed triangle (a vertex of radius 0, or an edge whose two radii are 0);
// the compact kernel there too when σ |∇τ · e| > 1 for some direction e
// into the triangle (the support then holds a wedge at P, where
// K/τ² ~ 1/ρ²). Any other non-finite result throws EvaluationError.
//
// Validation (constructor, InputError naming the field): the vertices as a
// polygon (skelconv/primitives/polygon.hpp: finite, no repeated vertex, no degenerate
// edge, non-zero area); "radius[k]" finite and ≥ 0, "radius" not all zero;
// "kernel.sigma" finite, > 0 (> 1 compact); "iso" finite and > 0;
// "kernel.degree" in supported_degrees().
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/primitives/polygon.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/scalis_segment.hpp"  // ScalisKernel

namespace skelconv {

class ScalisTriangle {
 public:
  /// Degrees: inverse and Cauchy min_degree…max_degree, compact
  /// min_compact_degree…max_degree.
  static constexpr int min_degree = 3, min_compact_degree = 2, max_degree = 10;
  /// The relative error the numerical path asks its quadrature for, and the
  /// one it guarantees (by its error estimate) or throws.
  static constexpr double requested_tolerance = 1e-13;
  static constexpr double certified_tolerance = 1e-10;
  /// Where F is tiny the numerical path's promise is absolute instead:
  /// |error of F| ≤ certified_tolerance · max(|F|, absolute_floor · h) and
  /// |error of ∇F| ≤ certified_tolerance · max(scale of ∇F, absolute_floor · h / τ_max)
  /// (h the normalisation, F's value at distance τ from a plane of radius τ,
  /// and h/τ_max the size of ∇F there for the largest radius τ_max). In f
  /// this is 1e-10 · 1e-6 · iso = 1e-16 · iso: below half an ulp of the
  /// primitive's own iso value (ε/2 ≈ 1.1e-16), so it changes no comparison
  /// with that level, and no sum that reaches it, by more than its rounding.
  /// It is needed because a relative 1e-10 is out of reach where F ≪ h: at
  /// the rim of a compact support F → 0 as a power of q = σ²τ² − |P − Q|²,
  /// a difference whose rounding (of the inputs themselves) is a fixed
  /// absolute amount, so F's relative condition number grows without bound
  /// (e.g. F = 1.3e-15 with h = 17 and an error estimate of 1.9e-25 =
  /// 1.4e-10 F, at a point near the rim met when meshing
  /// tests/data/good/scalis_triangles.json).
  static constexpr double absolute_floor = 1e-6;

  /// Validates everything (see the file comment); throws InputError naming
  /// the field ("vertices", "vertices[k]", "radius", "radius[k]",
  /// "kernel.degree", "kernel.sigma", "iso").
  ScalisTriangle(const std::array<Vec3, 3>& vertices, const std::array<double, 3>& radii, const ScalisKernel& kernel,
                 double iso = 1.0);

  const std::array<Vec3, 3>& vertices() const { return vertices_; }
  const std::array<double, 3>& radii() const { return radii_; }
  const ScalisKernel& kernel() const { return kernel_; }
  double iso() const { return iso_; }
  /// h, the normalisation of this kernel: f = iso · F / h.
  double normalisation() const { return normalisation_; }
  /// True when value() etc. use the constant-radius closed form.
  bool uses_closed_form() const { return closed_form_.has_value(); }

  /// h = ∬ K(√(1 + |u|²)) du over ℝ² (file comment). Throws InputError for
  /// degree ≤ 2 of the inverse and Cauchy families (h is infinite).
  static double normalisation(KernelFamily family, int degree, double sigma);
  /// The degrees i available for `family`, ascending.
  static std::vector<int> supported_degrees(KernelFamily family);

  /// f(P) = iso · F(P) / h. Throws InputError if P is not finite,
  /// EvaluationError if the closed form fails in double precision or the
  /// numerical path cannot certify its result.
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  FieldSample value_and_gradient(const Vec3& p) const;
  /// f and ∇f by the numerical path whatever the radii (an independent
  /// check of the closed form), same rules as value_and_gradient().
  FieldSample numerical_value_and_gradient(const Vec3& p) const;

 private:
  /// The numerical path: F and, when grad != nullptr, ∇F (unnormalised,
  /// in the frame; P is named in messages, frame_p evaluated).
  double numerical(const Vec3& p, const Vec3& frame_p, Vec3* grad) const;
  /// The closed form: F and, when grad != nullptr, ∇F (unnormalised, in the frame).
  double closed(const Vec3& p, const Vec3& frame_p, Vec3* grad) const;
  /// P checked finite and put in the frame.
  Vec3 frame_point(const Vec3& p) const;
  /// f = iso·F/h and ∇f from the frame's F and ∇F (skelconv/detail/scaled_frame.hpp).
  FieldSample restore(double F, const Vec3* grad, const Vec3& p) const;

  std::array<Vec3, 3> vertices_;
  std::array<double, 3> radii_;
  ScalisKernel kernel_;
  double iso_ = 1.0;
  double normalisation_ = 1.0;
  /// Whether f may be 0 (a finite support), read from the family's facts
  /// once: restore() runs at every evaluation.
  bool may_vanish_ = false;
  /// The triangle's frame (skelconv/detail/scaled_frame.hpp: the diameter scaled
  /// into [1, 2)), and the vertices and radii in it.
  ScaledFrame frame_;
  /// frame_'s powers of two (F is scale invariant: power 0), computed once:
  /// frame_point and restore run at every evaluation.
  FrameFactors factors_;
  std::array<Vec3, 3> local_vertices_;
  std::array<double, 3> local_radii_{};
  /// Constant radius: the triangle as a polygon with the classical kernel
  /// K(r/τ) (file comment), in coordinates scaled by closed_form_scale_
  /// (a power of 2, so that τ·scale ∈ [1/2, 1) and s = 1/(σ²τ²) cannot
  /// overflow); F = closed_form_factor_ · C.
  std::optional<Polygon> closed_form_;
  double closed_form_scale_ = 1.0;
  double closed_form_factor_ = 1.0;
};

}  // namespace skelconv
