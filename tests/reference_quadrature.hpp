// tests/reference_quadrature.hpp — reference values for the tests, computed
// from the DEFINITION integral (docs/mathematics.md §2) by composite Gauss–Legendre
// quadrature in long double. It shares no code with the generated closed
// forms or the runtime: closed forms are checked against
// quadrature of the definition, never against another closed form.
//
//     f(P)  = |AB| ∫ w(t) K(q(t)) dt,           q(t) = |P − Γ(t)|²
//     ∇f(P) = |AB| ∫ w(t) K'(q(t)) 2 (P − Γ(t)) dt   (K as a function of q)
//
// over t ∈ [0, 1], or for the compact kernel over the part where q < R²
// (computed here independently of skelconv::clip_to_ball).
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace skelconv::test {

using Real = long double;
using Point = std::array<Real, 3>;

enum class ReferenceFamily { inverse, cauchy, compact };

struct ReferenceSegment {
  Point a, b;
  std::vector<Real> weight{1};  // w_0, w_1, ...
  ReferenceFamily family = ReferenceFamily::inverse;
  int degree = 3;
  Real s = 1;  // cauchy
  Real R = 1;  // compact
};

/// A point of the runtime (an Eigen vector, or anything with x(), y(), z())
/// as a reference point, exactly (double to long double).
template <class Vector>
Point to_reference(const Vector& v) {
  return {Real(v.x()), Real(v.y()), Real(v.z())};
}

struct ReferenceSample {
  Real value = 0;
  Point gradient{0, 0, 0};
};

/// Nodes and weights of the n-point Gauss–Legendre rule on [-1, 1], by
/// Newton's method on the Legendre polynomial P_n (three-term recurrence).
struct GaussLegendreRule {
  std::vector<Real> nodes, weights;
  explicit GaussLegendreRule(int n) {
    const Real pi = std::acos(Real(-1));
    for (int k = 0; k < n; ++k) {
      Real x = std::cos(pi * (k + Real(0.75)) / (n + Real(0.5)));  // initial guess
      Real derivative = 0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        Real p0 = 1, p1 = x;  // P_0, P_1
        for (int j = 2; j <= n; ++j) {
          const Real p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (x * p1 - p0) / (x * x - 1);  // P_n'(x)
        const Real step = p1 / derivative;
        x -= step;
        if (std::fabs(step) < Real(1e-30)) break;
      }
      nodes.push_back(x);
      weights.push_back(2 / ((1 - x * x) * derivative * derivative));
    }
  }
};

/// The definition integral of f and ∇f at p, with `panels` panels of a
/// 16-point rule. Compact: the interval where q < R² is mapped through the
/// smoothstep t = t0 + (t1 − t0)(3u² − 2u³), which turns the (t1 − t)^(i/2)
/// behaviour at the sphere into a smooth function of u for odd i too.
inline ReferenceSample integrate_definition(const ReferenceSegment& segment, const Point& p, int panels = 128) {
  static const GaussLegendreRule rule(16);
  Point ab, ap;
  for (int c = 0; c < 3; ++c) {
    ab[c] = segment.b[c] - segment.a[c];
    ap[c] = p[c] - segment.a[c];
  }
  const Real aa = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const Real length = std::sqrt(aa);
  const Real half_i = Real(segment.degree) / 2;

  // Integration interval in t and the map u ∈ [0,1] → t.
  Real t0 = 0, t1 = 1;
  bool smoothstep = false;
  if (segment.family == ReferenceFamily::compact) {
    // q(t) = aa t² − 2 bb t + cc < R²: between the roots of the quadratic.
    const Real bb = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
    const Real cc = ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2];
    const Real discriminant = bb * bb - aa * (cc - segment.R * segment.R);
    if (discriminant <= 0) return {};
    t0 = std::max(Real(0), (bb - std::sqrt(discriminant)) / aa);
    t1 = std::min(Real(1), (bb + std::sqrt(discriminant)) / aa);
    if (t0 >= t1) return {};
    smoothstep = true;
  }

  ReferenceSample sum;
  for (int panel = 0; panel < panels; ++panel) {
    const Real lo = Real(panel) / panels, hi = Real(panel + 1) / panels;
    for (std::size_t node = 0; node < rule.nodes.size(); ++node) {
      const Real u = (lo + hi) / 2 + (hi - lo) / 2 * rule.nodes[node];
      Real du = (hi - lo) / 2 * rule.weights[node];
      Real t;
      if (smoothstep) {
        t = t0 + (t1 - t0) * (3 * u * u - 2 * u * u * u);
        du *= (t1 - t0) * 6 * u * (1 - u);
      } else {
        t = t0 + (t1 - t0) * u;
        du *= (t1 - t0);
      }
      Real w = 0;
      for (std::size_t k = segment.weight.size(); k-- > 0;) w = w * t + segment.weight[k];
      Point d;  // P − Γ(t)
      for (int c = 0; c < 3; ++c) d[c] = p[c] - (segment.a[c] + t * ab[c]);
      const Real q = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];

      Real kernel = 0, kernel_dq = 0;  // K(q) and dK/dq
      switch (segment.family) {
        case ReferenceFamily::inverse:
          kernel = std::pow(q, -half_i);
          kernel_dq = -half_i * kernel / q;
          break;
        case ReferenceFamily::cauchy: {
          const Real base = 1 + segment.s * q;
          kernel = std::pow(base, -half_i);
          kernel_dq = -half_i * segment.s * kernel / base;
          break;
        }
        case ReferenceFamily::compact: {
          const Real base = 1 - q / (segment.R * segment.R);
          if (base <= 0) break;
          kernel = std::pow(base, half_i);
          kernel_dq = -half_i / (segment.R * segment.R) * std::pow(base, half_i - 1);
          break;
        }
      }
      sum.value += du * w * kernel;
      for (int c = 0; c < 3; ++c) sum.gradient[c] += du * w * kernel_dq * 2 * d[c];
    }
  }
  sum.value *= length;
  for (Real& g : sum.gradient) g *= length;
  return sum;
}

}  // namespace skelconv::test
