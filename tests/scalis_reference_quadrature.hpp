// tests/scalis_reference_quadrature.hpp — reference values of the SCALIS
// segment field from its DEFINITION (docs/mathematics.md §4, Zanni 2013 eq. 13), by
// adaptive Gauss–Legendre quadrature in long double. It shares no code with
// the generated closed forms or the runtime (only the rule's nodes, from
// reference_quadrature.hpp):
//
//     F(P)  = ∫_0^1 K(x) |AB| dt / τ(t),            x = |P − Γ(t)| / τ(t)
//     ∇F(P) = ∫_0^1 K'(x) (P − Γ(t)) / (τ |P − Γ|) |AB| dt / τ(t)
//     h     = ∫_ℝ K(√(1 + u²)) du
#pragma once

#include <array>
#include <cmath>
#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "reference_quadrature.hpp"

namespace skelconv::test {

enum class ScalisReferenceFamily { inverse, cauchy, compact };

struct ScalisReferenceSegment {
  Point a, b;
  Real tau0 = 1, tau1 = 1, sigma = 1;
  ScalisReferenceFamily family = ScalisReferenceFamily::cauchy;
  int degree = 4;
};

/// K(x) and K'(x) of the SCALIS kernel (docs/mathematics.md §1), x = d/τ ≥ 0.
inline std::array<Real, 2> scalis_kernel(ScalisReferenceFamily family, int degree, Real sigma, Real x) {
  const Real y = x / sigma, half_i = Real(degree) / 2;
  switch (family) {
    case ScalisReferenceFamily::inverse: {
      const Real k = std::pow(y, -Real(degree));
      return {k, -Real(degree) * k / x};
    }
    case ScalisReferenceFamily::cauchy: {
      const Real base = 1 + y * y;
      const Real k = std::pow(base, -half_i);
      return {k, -half_i * k / base * 2 * y / sigma};
    }
    case ScalisReferenceFamily::compact: {
      const Real base = 1 - y * y;
      if (base <= 0) return {0, 0};
      return {std::pow(base, half_i), -half_i * std::pow(base, half_i - 1) * 2 * y / sigma};
    }
  }
  return {0, 0};
}

/// ∫_lo^hi of a vector function (N components), adaptive bisection with a
/// 16-point rule until, on every panel, the two halves and the whole agree
/// to `absolute_tolerance` + `panel_relative_tolerance` × (the panel's
/// largest component) in every component. The halves are then far more
/// accurate than that difference (the rule's error falls as (width)^32 on
/// smooth parts).
template <std::size_t N>
std::array<Real, N> integrate_panels(const std::function<std::array<Real, N>(Real)>& g, Real lo, Real hi,
                                     Real absolute_tolerance, Real panel_relative_tolerance, int depth = 0) {
  static const GaussLegendreRule rule(16);
  auto panel = [&](Real l, Real h) {
    std::array<Real, N> sum{};
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      const Real x = (l + h) / 2 + (h - l) / 2 * rule.nodes[j];
      const std::array<Real, N> v = g(x);
      for (std::size_t c = 0; c < N; ++c) sum[c] += (h - l) / 2 * rule.weights[j] * v[c];
    }
    return sum;
  };
  const Real mid = (lo + hi) / 2;
  const std::array<Real, N> whole = panel(lo, hi), left = panel(lo, mid), right = panel(mid, hi);
  Real difference = 0, size = 0;
  for (std::size_t c = 0; c < N; ++c) {
    difference = std::max(difference, std::fabs(left[c] + right[c] - whole[c]));
    size = std::max(size, std::fabs(left[c] + right[c]));
  }
  if (difference <= absolute_tolerance + panel_relative_tolerance * size || depth >= 40) {
    std::array<Real, N> sum{};
    for (std::size_t c = 0; c < N; ++c) sum[c] = left[c] + right[c];
    return sum;
  }
  std::array<Real, N> l = integrate_panels<N>(g, lo, mid, absolute_tolerance, panel_relative_tolerance, depth + 1);
  const std::array<Real, N> r =
      integrate_panels<N>(g, mid, hi, absolute_tolerance, panel_relative_tolerance, depth + 1);
  for (std::size_t c = 0; c < N; ++c) l[c] += r[c];
  return l;
}

/// ∫ g over [breaks.front(), breaks.back()] to ~`relative_tolerance` of its
/// largest component: one 16-point panel per break interval gives the size,
/// then every interval is refined to that absolute tolerance (a relative
/// one per panel would chase rounding in panels where g is tiny). `breaks`
/// (ascending) should bracket every narrow peak, which a rule whose nodes
/// all miss it would never see.
template <std::size_t N>
std::array<Real, N> integrate_adaptive(const std::function<std::array<Real, N>(Real)>& g,
                                       const std::vector<Real>& breaks, Real relative_tolerance = 1e-16L) {
  auto over_breaks = [&](Real absolute_tolerance, Real panel_relative_tolerance) {
    std::array<Real, N> sum{};
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      if (!(breaks[k] < breaks[k + 1])) continue;
      const std::array<Real, N> part =
          integrate_panels<N>(g, breaks[k], breaks[k + 1], absolute_tolerance, panel_relative_tolerance);
      for (std::size_t c = 0; c < N; ++c) sum[c] += part[c];
    }
    return sum;
  };
  const std::array<Real, N> rough = over_breaks(std::numeric_limits<Real>::infinity(), Real(0));
  Real size = 0;
  for (Real v : rough) size = std::max(size, std::fabs(v));
  return over_breaks(relative_tolerance * size, Real(0));
}

template <std::size_t N>
std::array<Real, N> integrate_adaptive(const std::function<std::array<Real, N>(Real)>& g, Real lo, Real hi) {
  return integrate_adaptive<N>(g, std::vector<Real>{lo, hi});
}

/// Break points in [0, 1] that grade geometrically towards t_peak with the
/// peak's width `width` (width·4^k on both sides).
inline std::vector<Real> graded_breaks(Real t_peak, Real width) {
  std::vector<Real> breaks{0, 1};
  if (t_peak > 0 && t_peak < 1) breaks.push_back(t_peak);
  // Not finer than 1e-12: long double resolves t near 1 only to ~1e-19.
  for (Real step = std::max(width, Real(1e-12)); step < 1; step *= 4) {
    for (Real t : {t_peak - step, t_peak + step})
      if (t > 0 && t < 1) breaks.push_back(t);
  }
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

/// F(P) and ∇F(P) (unnormalised) from the definition.
inline ReferenceSample integrate_scalis_definition(const ScalisReferenceSegment& s, const Point& p) {
  Point ab;
  for (int c = 0; c < 3; ++c) ab[c] = s.b[c] - s.a[c];
  const Real length = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
  const std::function<std::array<Real, 4>(Real)> integrand = [&](Real t) -> std::array<Real, 4> {
    const Real tau = s.tau0 + (s.tau1 - s.tau0) * t;
    Point d;
    for (int c = 0; c < 3; ++c) d[c] = p[c] - (s.a[c] + t * ab[c]);
    const Real dist = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (tau <= 0 || dist <= 0) return {0, 0, 0, 0};  // a node exactly at a cone tip: measure zero
    const std::array<Real, 2> k = scalis_kernel(s.family, s.degree, s.sigma, dist / tau);
    const Real factor = length / tau;
    const Real g = k[1] / (tau * dist) * factor;
    return {k[0] * factor, g * d[0], g * d[1], g * d[2]};
  };
  // The integrand peaks where Γ(t) is nearest P (width ~ distance/|AB|) and,
  // for a cone, at the tip: grade the panels towards both.
  Real ab_ap = 0, ap_ap = 0;
  for (int c = 0; c < 3; ++c) {
    ab_ap += ab[c] * (p[c] - s.a[c]);
    ap_ap += (p[c] - s.a[c]) * (p[c] - s.a[c]);
  }
  const Real t_near = std::clamp(ab_ap / (length * length), Real(0), Real(1));
  const Real distance_to_line = std::sqrt(std::max(Real(0), ap_ap - ab_ap * ab_ap / (length * length)));
  std::vector<Real> breaks = graded_breaks(t_near, distance_to_line / length);
  const Real min_tau = std::min(s.tau0, s.tau1);
  if (min_tau < Real(1e-2) * std::max(s.tau0, s.tau1)) {
    const std::vector<Real> tip = graded_breaks(s.tau0 <= s.tau1 ? 0 : 1, Real(1e-9));
    breaks.insert(breaks.end(), tip.begin(), tip.end());
    std::sort(breaks.begin(), breaks.end());
  }
  const std::array<Real, 4> v = integrate_adaptive<4>(integrand, breaks);
  return {v[0], {v[1], v[2], v[3]}};
}

/// h = ∫_ℝ K(√(1 + u²)) du, through u = tan θ (inverse, Cauchy) or
/// u = U sin θ, U = √(σ² − 1) (compact), which make the integrand smooth.
inline Real integrate_scalis_normalisation(ScalisReferenceFamily family, int degree, Real sigma) {
  const Real half_pi = std::acos(Real(-1)) / 2;
  std::function<std::array<Real, 1>(Real)> integrand;
  if (family == ScalisReferenceFamily::compact) {
    const Real U = std::sqrt(sigma * sigma - 1);
    integrand = [=](Real theta) -> std::array<Real, 1> {
      const Real u = U * std::sin(theta);
      return {scalis_kernel(family, degree, sigma, std::sqrt(1 + u * u))[0] * U * std::cos(theta)};
    };
  } else {
    integrand = [=](Real theta) -> std::array<Real, 1> {
      const Real c = std::cos(theta);
      // K(sec θ) sec²θ, written without the infinite sec at ±π/2.
      return {scalis_kernel(family, degree, sigma, 1 / c)[0] / (c * c)};
    };
  }
  return integrate_adaptive<1>(integrand, -half_pi, half_pi)[0];
}

}  // namespace skelconv::test
