// tests/scalis_reference_quadrature.hpp — reference values of the SCALIS
// segment field from its DEFINITION (SPEC §4, Zanni 2013 eq. 13), by
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
#include <functional>

#include "reference_quadrature.hpp"

namespace skelconv::test {

enum class ScalisReferenceFamily { inverse, cauchy, compact };

struct ScalisReferenceSegment {
  Point a, b;
  Real tau0 = 1, tau1 = 1, sigma = 1;
  ScalisReferenceFamily family = ScalisReferenceFamily::cauchy;
  int degree = 4;
};

/// K(x) and K'(x) of the SCALIS kernel (SPEC §1), x = d/τ ≥ 0.
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
/// 16-point rule until the halves and the whole agree to `tolerance` of the
/// largest component. The halves are then far more accurate than that
/// difference (the rule's error falls as (width)^32 on smooth parts), so
/// 1e-16 yields references good to ~1e-19 without chasing long double's
/// own rounding.
template <std::size_t N>
std::array<Real, N> integrate_adaptive(const std::function<std::array<Real, N>(Real)>& g, Real lo, Real hi,
                                       Real tolerance = 1e-16L, int depth = 0) {
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
  if (difference <= tolerance * size || depth >= 40) {
    std::array<Real, N> sum{};
    for (std::size_t c = 0; c < N; ++c) sum[c] = left[c] + right[c];
    return sum;
  }
  std::array<Real, N> l = integrate_adaptive<N>(g, lo, mid, tolerance, depth + 1);
  const std::array<Real, N> r = integrate_adaptive<N>(g, mid, hi, tolerance, depth + 1);
  for (std::size_t c = 0; c < N; ++c) l[c] += r[c];
  return l;
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
  const std::array<Real, 4> v = integrate_adaptive<4>(integrand, 0, 1);
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
