// skelconv/polygon_near_plane.hpp — the edge integrals H_n of a polygon
// kernel near the polygon's plane, where the recurrence in n cancels.
//
// For an edge E = Q_{m+1} − Q_m seen from P̄ (the projection of P on the
// plane, at in-plane distance d from the edge's line) the generated polygon
// kernels need (codegen/polygon_families.hpp, SPEC §3)
//
//     H_n = α h ∫_0^1 dt / (α ρ(t)² q(t)^(n/2)),   q = α ρ² + ζ²,
//
// with ρ the in-plane distance from P̄ to Γ(t), h = ±|E| d and ζ² = α z² + β.
// The recurrence H_n = (H_{n−2} − α h J_n)/ζ² divides by ζ² → 0 near the
// plane (and at z = 0 for the inverse kernels, Hubert 2012 §6.3 gives
// separate formulas). Here H_n is instead written in the angle φ the edge
// point makes at P̄ with the foot of the perpendicular, ρ = d / cos φ:
//
//     H_n = sgn(h) ∫_{φ0}^{φ1} q(φ)^(−n/2) dφ,   q(φ) = α d² / cos²φ + ζ²,
//     tan φ_k = (a t_k − b) / (α |h|)  at the ends t_0 = 0, t_1 = 1,
//
// which holds at z = 0 as well. The integrand cos^n φ (α d² + ζ² cos²φ)^(−n/2)
// is analytic; the generated code calls this only where ζ² ≤ q_min/4, so
// that α d² ≥ 3 ζ² and its singularities (cos²φ = −α d²/ζ²) lie at
// |Im φ| ≥ asinh √3 ≈ 1.32 from an interval of length < π: a Bernstein
// ellipse of parameter ≥ 2.6, and a 20-point Gauss–Legendre rule is exact
// to ~2.6^(−40) ≈ 1e-17 relative (Trefethen, ATAP ch. 19). All nodes carry
// positive terms: nothing cancels. The verifier checks the claim against
// quadrature of the definition.
#pragma once

#include <boost/math/quadrature/gauss.hpp>

#include <cmath>

namespace skelconv {

/// Writes H_n for n = n_lo, n_lo + 2, …, n_hi to out[(n − n_lo)/2], from
/// alpha_h = α h, a = α|E|², zeta2 = ζ² and the slopes a t − b at t = 0, 1.
/// With h = 0 (P̄ on the edge's line) every H_n is 0.
template <class T>
void polygon_edge_H_near_plane(int n_lo, int n_hi, const T& alpha_h, const T& a, const T& zeta2, const T& slope0,
                               const T& slope1, T* out) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sqrt;
  using Rule = boost::math::quadrature::gauss<T, 20>;
  const int levels = (n_hi - n_lo) / 2 + 1;
  for (int l = 0; l < levels; ++l) out[l] = T(0);
  if (alpha_h == T(0)) return;
  const T abs_alpha_h = abs(alpha_h);
  const T phi0 = atan2(slope0, abs_alpha_h);
  const T phi1 = atan2(slope1, abs_alpha_h);
  const T alpha_d2 = alpha_h * alpha_h / a;  // α d² = (α h)² / (α |E|²)
  const T half_width = (phi1 - phi0) / 2, middle = (phi0 + phi1) / 2;
  const bool odd = n_lo % 2 != 0;
  auto add_node = [&](const T& x, const T& g) {
    const T c = cos(middle + half_width * x);
    const T c2 = c * c;
    const T inverse_q = c2 / (alpha_d2 + zeta2 * c2);  // 1/q(φ)
    // q^(−n_lo/2), then × 1/q per level.
    const T root = odd ? sqrt(inverse_q) : inverse_q;
    T level_value = T(1);
    for (int j = 0; j < (odd ? n_lo : n_lo / 2); ++j) level_value *= root;
    for (int l = 0; l < levels; ++l) {
      out[l] += g * level_value;
      level_value *= inverse_q;
    }
  };
  const auto& x = Rule::abscissa();
  const auto& g = Rule::weights();
  for (unsigned j = 0; j < x.size(); ++j) {
    add_node(x[j], g[j]);
    add_node(-x[j], g[j]);
  }
  const T scale = alpha_h > T(0) ? half_width : -half_width;
  for (int l = 0; l < levels; ++l) out[l] *= scale;
}

}  // namespace skelconv
