// skelconv/detail/polygon_angle_integrals.hpp — edge integrals of the polygon
// kernels in the angle an edge point makes at P̄, where the closed forms
// cancel: near the plane (inverse, Cauchy) and near the rim of the support
// disc (compact).
//
// For an edge E = Q_{m+1} − Q_m seen from P̄ (the projection of P on the
// plane, at in-plane distance d from the edge's line) the generated polygon
// kernels need (codegen/polygon_families.hpp, docs/mathematics.md §3)
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
// is analytic; the generated code calls this only where ζ² ≤ q_min/2
// (q_min the smaller end value of q; kNearPlaneRatio = 2 in
// codegen/polygon_families.cpp) and either α d² ≥ ζ² or the foot of P̄ lies
// on the edge. With α d² ≥ ζ² its singularities (cos²φ = −α d²/ζ², at
// φ = ±π/2 ± i asinh(√(α d²)/ζ)) lie at |Im φ| ≥ asinh 1 ≈ 0.88 from an
// interval of length < π: a Bernstein ellipse of parameter ≥ 2.18, and a
// 20-point Gauss–Legendre rule errs by ~2.18^(−40) ≈ 3e-14 relative at
// worst (Trefethen, ATAP ch. 19), far less for most edges. All nodes carry
// positive terms: nothing cancels. The verifier measures the result against
// quadrature of the definition (regions near_plane_inside and near_edges of
// skelconv-verify-polygons).
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

/// Compact kernels (codegen/polygon_families.cpp): writes, for p = p_lo … p_hi,
///
///     G^(p) = h ∫_{t0}^{t1} q^p / ρ² dt = sgn(h) ∫_{u0}^{u1} q(u)^p du / (1 + u²),
///     q(u) = w − D (1 + u²) = D (U − |u|)(U + |u|),
///     u = tan φ = slope / |h|,   D = d²/R² = h² / (|E|² R²),   U² = w/D − 1,
///
/// to out[p − p_lo], from h, |E|², w = 1 − z²/R², 1/R², the in-plane slopes
/// |E|² t − E·(P̄ − A) at the clip's ends t0, t1, and the exact support gaps
/// R² − |P − A|², R² − |P − B|² at the edge's ends (support_gap.hpp), which
/// count where the clip keeps an end (t0 = 0, t1 = 1). The generated code
/// calls this for a chord that stays beyond half the support disc's radius
/// from P̄, where the closed form w^p θ − (h/R²) Σ … cancels (q ≪ w).
///
/// q is formed as a product of distances, never as the difference w − D(1 +
/// u²): near the rim q ≪ w, and that difference would carry each rounding
/// of w, D and the slopes amplified w/q times, p times over in q^p (114 and
/// 2.3e-13 on the sample in docs/verify.md). Each side of u = 0 is
/// integrated over |u| ∈ [a, b], b the end nearer the rim; U − b is 0 where
/// the clip put that end on the rim, q(end)/(D (U + b)) at a polygon vertex
/// (q from its exact gap), and the nodes sit at σ = b − |u| ≥ 0 from it, so
/// U − |u| = (U − b) + σ is a sum of nonnegative terms. The length b − a
/// comes from the ends' distances to the rim when the far end is deeper by
/// more than the near end's depth (a vertex inside, the other end on the
/// rim: no clip end enters), else from |E|²(t1 − t0)/|h|.
///
/// The integrand, a polynomial over 1 + u², has its only poles at u = ±i.
/// The range is cut into panels [lo, hi] with hi − lo ≤ 1.5 √(1 + lo²)
/// (0 ≤ lo): each sees the poles through a Bernstein ellipse of parameter
/// ≥ 3.4, and 20 Gauss–Legendre points are exact to 3.4^(−40) ≈ 5e-22.
template <class T>
void polygon_edge_G_compact_chord(int p_lo, int p_hi, const T& h, const T& edge_length2, const T& w,
                                  const T& inv_R2, const T& slope0, const T& slope1, const T& t0, const T& t1,
                                  const T& gap0, const T& gap1, T* out) {
  using std::abs;
  using std::max;
  using std::min;
  using std::sqrt;
  using Rule = boost::math::quadrature::gauss<T, 20>;
  const int count = p_hi - p_lo + 1;
  for (int k = 0; k < count; ++k) out[k] = T(0);
  if (h == T(0)) return;
  const T abs_h = abs(h);
  const T u0 = slope0 / abs_h, u1 = slope1 / abs_h;
  const T D = h * h / edge_length2 * inv_R2;
  const T U = sqrt(max(T(0), (w - D) / D));  // the rim, |u| = U
  // U − |u_end|: 0 on the rim (a clip end), from the exact gap at a vertex.
  auto rim_distance = [&](bool vertex, const T& gap, const T& u_end) {
    return vertex ? max(T(0), gap) * inv_R2 / (D * (U + abs(u_end))) : T(0);
  };
  const T depth0 = rim_distance(t0 == T(0), gap0, u0), depth1 = rim_distance(t1 == T(1), gap1, u1);
  const T length = edge_length2 * (t1 - t0) / abs_h;  // u1 − u0
  const auto& x = Rule::abscissa();
  const auto& g = Rule::weights();
  // |u| from b − L (depth_a below the rim) up to b (depth_b below it).
  auto side = [&](const T& b, const T& depth_b, const T& depth_a, const T& direct_length) {
    const T L = depth_a - depth_b >= depth_b ? depth_a - depth_b : direct_length;
    T sigma_hi = L;  // σ = b − |u| runs from L down to 0
    while (sigma_hi > T(0)) {
      const T lo = max(T(0), b - sigma_hi);
      const T width = min(sigma_hi, T(1.5) * sqrt(1 + lo * lo));
      const T sigma_lo = sigma_hi - width;  // 0 on the last panel
      const T half = width / 2, mid = sigma_lo + half;
      auto add_node = [&](const T& sigma, const T& weight) {
        const T u = b - sigma;
        const T one_plus_u2 = 1 + u * u;
        const T q = D * (depth_b + sigma) * (U + u);
        T q_power = T(1);
        for (int p = 0; p < p_lo; ++p) q_power *= q;
        const T base = weight * half / one_plus_u2;
        for (int k = 0; k < count; ++k) {
          out[k] += base * q_power;
          q_power *= q;
        }
      };
      for (unsigned j = 0; j < x.size(); ++j) {
        add_node(mid - half * x[j], g[j]);
        add_node(mid + half * x[j], g[j]);
      }
      sigma_hi = sigma_lo;
    }
  };
  if (u1 > T(0)) {
    // |u| ∈ [max(u0, 0), u1]: b = u1; a = u0, or 0 where the chord crosses u = 0.
    const bool split = u0 < T(0);
    side(u1, depth1, split ? U : depth0, split ? u1 : length);
  }
  if (u0 < T(0)) {
    const bool split = u1 > T(0);
    side(-u0, depth0, split ? U : depth1, split ? -u0 : length);
  }
  if (h < T(0))
    for (int k = 0; k < count; ++k) out[k] = -out[k];
}

}  // namespace skelconv
