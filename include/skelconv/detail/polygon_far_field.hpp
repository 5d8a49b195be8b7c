// skelconv/detail/polygon_far_field.hpp — the field of a polygon seen from far away,
// where the contour sum cancels.
//
// The contour formula (polygon_field.hpp) adds fan triangles with apex P̄.
// Seen from a distance L much larger than the polygon's diameter d, those
// fans are of size ~L·d while the polygon is d²: the sum cancels ~L/d of its
// digits (measured: 1e-9 relative at L = 1e4 d). There the kernel is smooth
// over the polygon instead, and the definition integral is done directly:
// over the signed fan of triangles (Q_0, Q_m, Q_{m+1}) — whose signed sum is
// the polygon for any simple polygon, convex or not — each by an N × N
// Gauss–Legendre rule in collapsed (Duffy) coordinates. K(|P − Q|) is
// analytic in Q wherever |P − Q|² ∉ (−∞, 0] (inverse; (−∞, −1/s] for
// Cauchy), i.e. within a complex distance ≥ L of the polygon; with L ≥ 2 d
// (polygon_far_field_ratio below: P at ≥ 5 radii from the vertex centroid,
// the polygon within 1 radius of it, so L ≥ 4 radii ≥ 2 d) each 1-D rule
// converges like a Bernstein ellipse of parameter ≥ 2 + √5 ≈ 4.2, and N = 16 gives 4.2^(−32) ≈ 1e-20
// (Trefethen, ATAP ch. 19; the verifier checks it against quadrature).
// Compact kernels never need this: far from the polygon they vanish.
#pragma once

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <span>

#include "skelconv/primitives/segment_input.hpp"  // KernelFamily

namespace skelconv {

/// P counts as far when its distance from the polygon's vertex centroid —
/// with β/α added to its square, the kernel's own width — is at least this
/// many times the polygon's radius about that centroid (so that the
/// integrand's complex singularities are ≥ 2 diameters from the polygon).
inline constexpr double polygon_far_field_ratio = 5.0;

/// f and/or ∇f (grad != nullptr) of the polygon `vertices` (CCW about the
/// unit `normal`) at p, for the inverse (alpha = 1, beta = 0) or Cauchy
/// (alpha = s, beta = 1) kernel (α r² + β)^(−i/2), by the rule above.
template <class T>
T polygon_far_field(std::span<const std::array<T, 3>> vertices, const std::array<T, 3>& normal, int degree,
                    const T& alpha, const T& beta, const std::array<T, 3>& p, std::array<T, 3>* grad) {
  using std::sqrt;
  using Rule = boost::math::quadrature::gauss<T, 16>;
  const auto& x = Rule::abscissa();
  const auto& w = Rule::weights();
  const bool odd = degree % 2 != 0;
  T f = 0;
  std::array<T, 3> g = {T(0), T(0), T(0)};
  const auto& A = vertices[0];
  for (std::size_t m = 1; m + 1 < vertices.size(); ++m) {
    const auto& B = vertices[m];
    const auto& C = vertices[m + 1];
    const T e1[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const T e2[3] = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
    // Twice the signed area: (e1 × e2)·n.
    const T area2 = (e1[1] * e2[2] - e1[2] * e2[1]) * normal[0] + (e1[2] * e2[0] - e1[0] * e2[2]) * normal[1] +
                    (e1[0] * e2[1] - e1[1] * e2[0]) * normal[2];
    T tri_f = 0;
    T tri_g[3] = {T(0), T(0), T(0)};
    // Q = A + u (1 − v) e1 + u v e2, dQ = u |e1 × e2| du dv on [0, 1]².
    for (unsigned a = 0; a < x.size(); ++a)
      for (int sa : {-1, 1}) {
        const T u = (1 + sa * x[a]) / 2;
        for (unsigned b = 0; b < x.size(); ++b)
          for (int sb : {-1, 1}) {
            const T v = (1 + sb * x[b]) / 2;
            const T c1 = u * (1 - v), c2 = u * v;
            const T d[3] = {p[0] - A[0] - c1 * e1[0] - c2 * e2[0], p[1] - A[1] - c1 * e1[1] - c2 * e2[1],
                            p[2] - A[2] - c1 * e1[2] - c2 * e2[2]};
            const T q = alpha * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + beta;
            const T root = odd ? sqrt(q) : q;  // q^(−i/2) from powers of √q or q
            const T inverse_root = T(1) / root;
            T K = 1;
            for (int k = 0; k < (odd ? degree : degree / 2); ++k) K *= inverse_root;
            const T weight = w[a] * w[b] * u;
            tri_f += weight * K;
            // ∇_P K = −i α (P − Q) q^(−(i+2)/2)
            const T dK = -T(degree) * alpha * K / q * weight;
            for (int k = 0; k < 3; ++k) tri_g[k] += dK * d[k];
          }
      }
    const T scale = area2 / 4;  // ¼ from the two maps [−1, 1] → [0, 1]
    f += scale * tri_f;
    for (int k = 0; k < 3; ++k) g[k] += scale * tri_g[k];
  }
  if (grad) *grad = g;
  return f;
}

}  // namespace skelconv
