// src/primitives/scalis_triangle_quadrature.hpp — the NUMERICAL path of the
// SCALIS triangle (skelconv/primitives/scalis_triangle.hpp): F and ∇F of a triangle
// whose radius varies linearly, by nested adaptive Gauss–Kronrod quadrature
// of the definition, with an error estimate. Internal to skelconv_runtime.
//
//     F(P)  = ∬_T K(d) dQ / τ(Q)²,                d = |P − Q| / τ(Q)
//     ∇F(P) = ∬_T (K'(d)/d) (P − Q) dQ / τ(Q)⁴
//
// No closed form is known for a varying radius (Zanni 2013 §5.2 integrates
// numerically too). How the integrand is made smooth for the rules:
//  * The apex O is the point of T nearest to P̄, the foot of P in the plane.
//    T is split into the triangles (O, V_k, V_{k+1}) (those with O on their
//    edge are empty and left out) and each is integrated in polar
//    coordinates about O. Because O is the nearest point, (O − P̄)·e ≥ 0 for
//    every direction e into T, so along every ray |P − Q| grows from
//    w = |P − O|: the kernel's peak (width ~w for the inverse and Cauchy
//    kernels) is at ρ = 0 on every ray.
//  * Radial variable (inverse, Cauchy): ρ = c sinh u, c the modulus of the
//    complex zeros of the kernel's denominator D(ρ) (w for the inverse
//    kernel): the peak at ρ ≲ c and the algebraic tail ρ ≫ c both become
//    smooth in u, whatever c / ρ_max is (P very close to the plane).
//  * Radial variable (compact): the support on a ray is where
//    q(ρ) = σ²τ² − |P − Q|² > 0, a quadratic in ρ, and on T (τ ≥ 0) it is
//    one interval (στ − |PQ| is concave). The ray is cut to it, and an end
//    that is a root of q is approached as ρ = root ± Δ t² (both ends roots:
//    the smoothstep Δ (3t² − 2t³)), so that q^(i/2) (odd i: a square root)
//    is analytic in t.
//  * Angular variable: the point E(s) of the far edge at arc length s from
//    the foot of the perpendicular from O (height h), with s = h sinh v: then
//    dφ = dv / cosh v and ρ_max = h cosh v, smooth even for a thin
//    triangle (P̄ close to an edge) where φ alone would need many panels.
//  * Compact, angular variable: the radial integral is not smooth in v where
//    the support's boundary (the conic σ²τ(Q)² = |P − Q|²) crosses the far
//    edge, or where a ray is tangent to it (both found as roots of
//    quadratics); it behaves like |v − v_c|^(n + 1/2) there. The v range is
//    cut at those points and each piece mapped by the smoothstep
//    v = c0 + (c1 − c0)(3w² − 2w³), which makes such ends smooth in w. (Without
//    this the error estimate missed 4e-12 errors and odd degrees needed
//    ~10⁶ evaluations; with it, ~10⁴ and ~1e-15.)
//  * τ along a ray is interpolated between τ(O) and τ(E) (both from the
//    vertex radii along edges), so a vertex of radius 0 gives τ = 0 exactly
//    there; where τ ≤ 0 the integrand is 0 (its limit: K(d)/τ² → 0 as τ → 0
//    for i ≥ 3, and the compact support excludes it).
//
// Both levels are adaptive Gauss–Kronrod 15/31 (boost's nodes) with global
// bisection of the panel of largest error. A panel's error is |K31 − G15|
// (the error of the embedded Gauss rule, a large over-estimate of the
// Kronrod result's own) plus, at the outer level, the rays' error estimates
// integrated with the Kronrod weights. F's integrand is positive, ∂F/∂z's
// and the radial moments' are of one sign, so a ray stops at a relative
// error `tolerance` of its own values, or (compact) at twice the rounding
// noise of its values: q = σ²τ² − |PQ|² is a difference known to
// ~4ε(στ + r)², so a ray that only grazes the support cannot do better, and
// that noise is added to its error estimate. The outer level stops when the
// estimate of F is within tolerance·|F| and that of ∇F within
// tolerance·max(|∇F|, gradient_floor · M), M = |P − O| |∫∫G0| + ∫ |G1| dφ
// the sum of the magnitudes of the parts of ∇F (a floor for a point where
// ∇F cancels to ~0, e.g. by symmetry, where a relative error has no
// meaning) — or when its own
// discretisation error is below the rays' summed errors, which bisection
// cannot reduce. The reported errors are the sums of both, so what the
// caller certifies includes the rounding noise. Measured (tests, random
// points): estimates ≤ 1e-13 for inverse/Cauchy and ≤ 7e-12 for compact
// (the noise bound), actual errors ~1e-15; 1,000–50,000 integrand
// evaluations, median 60–130 µs, at most ~1 ms per F and ∇F.
//
// Points where the integral diverges (P in the closed triangle for the
// inverse kernel; P at a point of radius 0 of the closed triangle for the
// Cauchy kernel, and for the compact kernel when σ|∇τ·e| > 1 for some
// direction e into T there) give +inf, gradient (+inf, +inf, +inf).
#pragma once

#include <array>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/segment_input.hpp"  // KernelFamily

namespace skelconv::detail {

/// The outcome of one numerical evaluation.
struct ScalisTriangleIntegral {
  double F = 0.0;                ///< unnormalised F(P)
  Vec3 gradient = Vec3::Zero();  ///< ∇F(P) (when asked for)
  double F_error = 0.0;          ///< estimated absolute error of F
  double gradient_error = 0.0;   ///< estimated absolute error of ∇F (Euclidean norm bound)
  double gradient_scale = 0.0;   ///< max(|∇F|, gradient_floor · M), what gradient_error is relative to
  bool converged = false;        ///< both estimates within tolerance (see the file comment)
  bool divergent = false;        ///< F = +inf (see the file comment)
  long evaluations = 0;          ///< integrand evaluations
};

/// Relative floor of the gradient's error scale (see the file comment).
inline constexpr double scalis_triangle_gradient_floor = 1e-3;

/// F(P) and, if with_gradient, ∇F(P) of the triangle `vertices` with radii
/// `radii` (≥ 0, not all 0) and the SCALIS kernel (family, degree i ≥ 2
/// (≥ 3 for inverse and Cauchy), σ > 0 (> 1 compact)), requesting a relative
/// error `tolerance`. The caller validates the inputs; this only integrates.
ScalisTriangleIntegral integrate_scalis_triangle(const std::array<Vec3, 3>& vertices, const std::array<double, 3>& radii,
                                                 KernelFamily family, int degree, double sigma, const Vec3& p,
                                                 bool with_gradient, double tolerance);

}  // namespace skelconv::detail
