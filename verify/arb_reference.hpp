// verify/arb_reference.hpp — certified references: the
// definition integrals of docs/mathematics.md §2 (segments) and §3 (planar polygons)
// enclosed in Arb's ball arithmetic (acb_calc_integrate: Gauss–Legendre with
// rigorous error bounds from the integrand's analytic extension). The result
// is a ball [mid ± rad] that provably contains the exact field of the exact
// double inputs; mid is returned in binary128 with the certified relative
// radius. Arb stays inside arb_reference.cpp: this header needs none of it.
//
// Segments (docs/mathematics.md §2, w(t) = Σ_k w_k t^k):
//     f  = |AB| ∫_{t0}^{t1} w(t) K(|P − Γ(t)|) dt
//     ∇f = |AB| ∫_{t0}^{t1} w(t) K'(r)/r (P − Γ(t)) dt
// with the kernels of docs/mathematics.md §1 written out (not the runtime's traits).
// Polygons (docs/mathematics.md §3): ∬_Ω K(|P − Q|) dQ reduced to 1-D edge integrals by an
// exact derivation (arb_reference.cpp, "Polygons"), each integrated with
// acb_calc_integrate. See docs/verify_certified.md, "Certified references (Arb)".
#pragma once

#include <span>
#include <string>

#include "extended_precision.hpp"
#include "sampling.hpp"  // SweepProblem, KernelFamily

namespace skelconv::verify {

/// A certified field: f and ∇f with bounds on their errors.
struct CertifiedField {
  bool certified = false;  ///< false: no enclosure could be made (`why` says why); do not use
  bool zero = false;       ///< the field is exactly 0 (compact: the support misses the primitive)
  extended f = 0;          ///< midpoint of the ball of f
  Vec3<extended> grad{};   ///< midpoints of the balls of ∇f
  /// Certified relative radius of the ball of f: the exact f is within
  /// f_bound·|f| of the ball's midpoint (upper bound). Handing the midpoint
  /// over in binary128 adds at most 2^-113 ≈ 1e-34 to it.
  double f_bound = 0;
  double grad_bound = 0;  ///< the same for ∇f, norm-wise: |radius vector| / lower bound of |∇f|
  std::string why;
};

/// Working precision and the accuracy asked of each integral. 256 bits
/// (77 digits) leaves room for the cancellations the enclosures carry
/// (polygon fans far away cancel by ~(distance/diameter)², 1e8 at 1e4
/// diameters; a near-line segment's P − Γ by 1e-6) while the goal, 2^-128
/// ≈ 3e-39 per integral, keeps the certified radius far below 1e-25.
struct ArbSettings {
  long precision_bits = 256;
  long goal_bits = 128;
};

/// The certified field of sweep sample `pb` (verify/sampling.hpp) with
/// weight w_0..w_{weight_degree}. Families: inverse and Cauchy (any degree
/// ≥ 1), compact (degree ≥ 2).
CertifiedField certified_segment_field(const SweepProblem& pb, int weight_degree, const ArbSettings& settings = {});

/// A polygon whose vertices are EXACTLY coplanar (as doubles), in boundary
/// order counter-clockwise about `normal_direction` (exact, any length):
/// the plane and the polygon are then defined by the inputs without any
/// rounding (verify/polygon_sampling.hpp's exact frame makes such polygons).
struct ExactPolygon {
  std::span<const Vec3<double>> vertices;
  Vec3<double> normal_direction{};
};

/// The certified polygon field at p. Families: inverse and Cauchy (degree
/// ≥ 3), compact (even degree ≥ 2).
CertifiedField certified_polygon_field(const ExactPolygon& polygon, const Vec3<double>& p, KernelFamily family,
                                       int degree, double s, double R, const ArbSettings& settings = {});

}  // namespace skelconv::verify
