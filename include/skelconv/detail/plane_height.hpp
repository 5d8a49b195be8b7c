// skelconv/detail/plane_height.hpp — the height z of a point P above a polygon's
// plane, from the exact inputs where P is near the plane (the exact
// preamble for polygons).
//
// The polygon driver (polygon_field.hpp) takes z = (P − V₀)·n with n the
// polygon's unit normal, rounded to doubles. Near the plane that product
// cancels: each component of n carries ε/2 of rounding, so z is off by
// ~ε|P − V₀| absolute, i.e. ε|P − V₀|/z relative, and the inverse kernels'
// field inside the polygon, f ≈ 2π z^(2−i)/(i − 2), carries it (i − 2)
// times (the certified spot checks measured 5.9e-12 at z = 1e-6 diam;
// docs/verify.md).
//
// For vertices that are exactly coplanar as doubles the plane is exact:
// with d_j = V_j − V₀,
//     N = Σ_(j=1)^(n−2) d_j × d_(j+1)     (twice the area vector, normal to it)
//     z = N·(P − V₀) / |N|.
// Every difference is split exactly (TwoSum), the cross products and the
// dot product are formed in double-word arithmetic (double_word.hpp), so
// N·(P − V₀) errs by a few ε² Σ_j |d_j × d_(j+1)| |P − V₀| before its one
// rounding, and |N| is the norm of N rounded (relative ε): z to a few ε of
// itself wherever z ≫ ε |P − V₀|. Vertices that are not exactly coplanar
// (rounded from a tilted plane) have no exact plane; this one is the plane
// through V₀ of their exact area vector, as close to them as n's.
//
// The fan of n − 2 double-word cross products costs ~100 flops per vertex,
// so the driver takes it only where the plain z loses digits:
// needs_exact_plane_height (8|z| < |P − V₀|∞, where the plain z is within
// ~8√3·2ε ≈ 6e-15 of itself otherwise), and only for the inverse kernels,
// the one family singular on the plane (the Cauchy and compact fields are
// smooth there and meet their targets with the plain z). Measured: a tilted
// pentagon's f and ∇f (Polygon::value_and_gradient, inverse i = 3 and 8)
// take ~1.42 and 1.64 µs with the exact height (z = 0.02 diam) against
// 1.32 and 1.53 µs without it (z = 0.2 diam): ~100 ns, 7%.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "skelconv/detail/double_word.hpp"

namespace skelconv {

/// z = (P − V₀)·n in plain arithmetic: the driver's height, in the order
/// every caller computes it.
template <class T>
T plain_plane_height(const std::array<T, 3>& p, const std::array<T, 3>& first_vertex, const std::array<T, 3>& n) {
  return (p[0] - first_vertex[0]) * n[0] + (p[1] - first_vertex[1]) * n[1] + (p[2] - first_vertex[2]) * n[2];
}

/// Whether the plain height z of P loses digits (header comment): 8|z| < |P − V₀|∞.
template <class T>
bool needs_exact_plane_height(const T& plain_z, const std::array<T, 3>& p, const std::array<T, 3>& first_vertex) {
  using std::abs;
  const T reach = std::max({abs(p[0] - first_vertex[0]), abs(p[1] - first_vertex[1]), abs(p[2] - first_vertex[2])});
  return T(8) * abs(plain_z) < reach;
}

/// z = N·(P − V₀)/|N| for the polygon `vertices` (boundary order; N points
/// the way they run counter-clockwise about), with the vertices and P taken
/// as exact: the exact height rounded to within a few ε of itself (header
/// comment).
template <class T>
T exact_plane_height(std::span<const std::array<T, 3>> vertices, const std::array<T, 3>& p) {
  using detail::DoubleWord;
  using std::sqrt;
  const std::array<T, 3>& origin = vertices[0];
  const auto difference = [&](const std::array<T, 3>& x, std::array<DoubleWord<T>, 3>& out) {
    for (int k = 0; k < 3; ++k) out[k] = detail::exact_word_difference(x[k], origin[k]);
  };
  std::array<DoubleWord<T>, 3> area{}, previous{}, next{};  // area = Σ d_j × d_(j+1)
  difference(vertices[1], previous);
  for (std::size_t j = 2; j < vertices.size(); ++j, previous = next) {
    difference(vertices[j], next);
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      const DoubleWord<T> component = detail::word_add(detail::word_multiply(previous[a], next[b]),
                                                       detail::word_negate(detail::word_multiply(previous[b], next[a])));
      area[i] = detail::word_add(area[i], component);
    }
  }
  std::array<DoubleWord<T>, 3> offset{};
  difference(p, offset);
  DoubleWord<T> numerator = detail::word_multiply(area[0], offset[0]);
  numerator = detail::word_add(numerator, detail::word_multiply(area[1], offset[1]));
  numerator = detail::word_add(numerator, detail::word_multiply(area[2], offset[2]));
  T norm2(0);
  for (int i = 0; i < 3; ++i) {
    const T rounded = area[i].hi + area[i].lo;
    norm2 += rounded * rounded;
  }
  return (numerator.hi + numerator.lo) / sqrt(norm2);
}

/// The foot P̄ = P − z n as a double-word vector: `foot` rounded and
/// `foot_lo` = P̄ − foot (the product z n by fma, the difference by TwoSum).
///
/// Why: rounded, P̄ is off by up to ε|P|/2 per coordinate, the same for
/// every edge: the field is then the field at a point displaced by that
/// much, a relative error ~ε|P|/d at a distance d from an edge or a vertex
/// (3e-13 measured by the certified spot checks, inverse kernels, P̄ 3e-4
/// diam from an edge). The edge kernels form P̄ − Q_m as (foot − Q_m) +
/// foot_lo (PolygonEdgeInput::p_lo), so what is left is the error of z and
/// n, ~ε|z|, relative to a distance ≥ |z|.
template <class T>
void plane_foot(const std::array<T, 3>& p, const T& z, const std::array<T, 3>& n, std::array<T, 3>& foot,
                std::array<T, 3>& foot_lo) {
  using std::fma;
  for (int k = 0; k < 3; ++k) {
    const T product = z * n[k];
    const T product_error = fma(z, n[k], -product);  // z n_k = product + product_error exactly
    T difference, difference_error;
    exact_difference(p[k], product, difference, difference_error);
    exact_difference(difference, product_error - difference_error, foot[k], foot_lo[k]);
  }
}

}  // namespace skelconv
