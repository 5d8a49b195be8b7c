// skelconv/kernels/scalis_description.hpp — what the SCALIS primitives
// (docs/mathematics.md §4, Zanni et al. 2013) need of a kernel family, for the traits that have
// a SCALIS field (inverse, cauchy, compact: `primitives` has on_scalis).
//
// A SCALIS kernel of scale σ is K(d/σ), with the family's K at s = 1 or
// R = 1. Each of those traits declares, next to its K:
//
//   static double scalis_line_normalisation(int i, double σ);   // h of a segment:
//       F at distance 1 from an infinite segment of constant radius 1
//   static double scalis_plane_normalisation(int i, double σ);  // h of a triangle:
//       F at distance 1 from an infinite plane of constant radius 1
//       (InputError at "kernel.degree" where it diverges)
//   static ScalisPolygonKernel scalis_polygon_kernel(int i, double σ, double τ);
//       the classical kernel whose polygon closed form, times `factor`, is F
//       of a triangle of constant radius τ
//   static constexpr ScalisSingularity scalis_singularity;  // where F = +inf
//   static constexpr bool scalis_segment_generated;  // the segment's F is in the
//       generated table (false: the hand-written scalis_compact_F)
//   static constexpr bool scalis_sigma_above_one;    // σ > 1 is required (the
//       kernel vanishes at d = στ, so σ ≤ 1 never reaches the thickness τ)
//   static constexpr double scalis_radius_term;      // c in the triangle
//       quadrature's D = d² + c σ²τ² (families of infinite support; the
//       finite-support one integrates q = σ²τ² − d² > 0 instead)
//
// and the primitives reach them through with_scalis_trait() (kernel_list.hpp).
#pragma once

#include <numbers>

#include "skelconv/kernels/kernel_spec.hpp"

namespace skelconv::kernels {

/// Where a SCALIS segment's field is infinite, decided exactly by the caller.
enum class ScalisSingularity {
  none,            ///< nowhere (compact: left to scalis_compact_F)
  on_segment,      ///< on the closed segment (K(0) = +inf: inverse)
  at_zero_radius,  ///< at an end of radius 0 (K(0) finite, the 1/τ weight diverges: cauchy)
};

/// A classical kernel and the factor that turn the polygon closed form into
/// the SCALIS triangle's F at constant radius.
struct ScalisPolygonKernel {
  KernelSpec kernel;
  double factor = 1.0;
};

/// W_i = ∫ (1 + u²)^(−i/2) du over ℝ (i ≥ 2): W_2 = π, W_3 = 2,
/// W_i = (i − 3)/(i − 2) W_{i−2} (docs/mathematics.md §4, Zanni Table 5).
inline double inverse_line_integral(int i) {
  double w = i % 2 == 0 ? std::numbers::pi : 2.0;
  for (int m = i % 2 == 0 ? 4 : 5; m <= i; m += 2) w *= double(m - 3) / double(m - 2);
  return w;
}

/// V_i = ∫_{−1}^{1} (1 − v²)^(i/2) dv: V_0 = 2, V_1 = π/2, V_i = i/(i + 1) V_{i−2}.
inline double compact_line_integral(int i) {
  double v = i % 2 == 0 ? 2.0 : std::numbers::pi / 2;
  for (int m = i % 2 == 0 ? 2 : 3; m <= i; m += 2) v *= double(m) / double(m + 1);
  return v;
}

}  // namespace skelconv::kernels
