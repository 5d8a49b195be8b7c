// skelconv/reconstruct/medial_mesh.hpp — a medial mesh: spheres joined by
// edges (tubes) and triangles (sheets), the skeleton that `skeletonize
// --method medial` turns into SCALIS triangles, segments and points
// (docs/reconstruction_medial.md). medial_quadric.hpp builds it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"  // Vec4

namespace skelconv::reconstruct {

struct MedialMesh {
  std::vector<Vec4> spheres;                           ///< (x, y, z, radius)
  std::vector<std::array<std::int32_t, 2>> edges;      ///< tubes: edges in no triangle
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< sheets
  std::vector<std::int32_t> isolated;                  ///< spheres in no edge or triangle
  /// Per sphere, the closed part of the input its centre lies deepest in,
  /// or, where the budget was shared out per part, whose medial graph it
  /// was simplified from (medial_parts.hpp); empty when the input is one
  /// part.
  std::vector<std::int32_t> parts;
};

/// How a medial triangle's one radius τ is taken from its spheres' radii
/// (triangle_radius). τ = (1 − s) A + s G, A the arithmetic mean, G the
/// geometric, and the geometric share s rises smoothly with q = A / G ≥ 1,
/// how unequal the radii are: 0 for q up to `fan_from`, 1 from `fan_to`,
/// the smoothstep 3t² − 2t³ of t = (q − fan_from) / (fan_to − fan_from)
/// between (so that the fit's Jacobian has no jump). fan_from = fan_to =
/// ∞ is the arithmetic mean everywhere, fan_from = fan_to = 1 the geometric
/// everywhere.
///
/// The default, 2 → 2.5, gives the geometric mean to the steepest fans
/// alone (q = 2 is radii about 1 : 1 : 12, or 1 : 13 : 13; CGAL's cow has
/// one such triangle of 358, where its rump's sheet runs into the tail,
/// 0.178, 0.017 and 0.0078, q 2.35). Wider blends took every triangle of
/// a cartoon's or a devil's sheets that fans into a thin part, and the fit
/// went elsewhere: 1.3 → 1.6 put the mannequin-devil's Hausdorff distance
/// from 1.35% to 1.59% of the diagonal, 1.5 → 1.8 to 1.94% with the
/// topology changed, the geometric mean everywhere to 1.85%
/// (docs/reconstruction_medial.md, "The primitives").
struct TriangleRadiusRule {
  double fan_from = 2.0;
  double fan_to = 2.5;
  static TriangleRadiusRule arithmetic() {
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  static TriangleRadiusRule geometric() { return {1.0, 1.0}; }
};

/// The one radius τ of the SCALIS triangle a medial triangle becomes, from
/// its spheres' radii a, b and c (one radius, because a radius varying over
/// the triangle costs the certified quadrature, far too slow to mesh), by
/// `rule`. Where a sheet fans out from a thick part's deep spheres to a
/// thin part's (CGAL's cow: its rump's sheet to the tail lying against it,
/// radii 0.066, 0.0077 and 0.0077), the arithmetic mean is set by the thick
/// corner and puts the thin corners' surface several times their radius
/// out (0.027, 3.5 times), which fills the concave crease where the thin
/// part meets the thick; the geometric mean weighs ratios alike (0.0157,
/// twice). Where the radii are close the two agree to second order
/// (A − G ≈ variance / (2 A)).
struct TriangleRadius {
  double tau;  ///< the triangle's radius
  /// 3 ∂τ/∂a, 3 ∂τ/∂b, 3 ∂τ/∂c: each sphere's share of a change in τ
  /// against the arithmetic mean's third (1 for the arithmetic mean, G / r
  /// for the geometric), so that the fit's Jacobian takes ∂F/∂τ / 3 × it.
  std::array<double, 3> thirds;
};

inline TriangleRadius triangle_radius(double a, double b, double c, const TriangleRadiusRule& rule) {
  const std::array<double, 3> r{a, b, c};
  const double am = (a + b + c) / 3;
  const double gm = std::cbrt(a * b * c);
  // The geometric share s(q) and its derivative ds/dq; a zero radius (no
  // ratio to weigh) keeps the arithmetic mean. fan_to ≤ 1 is the geometric
  // mean everywhere, even where rounding puts q a hair below 1 (equal radii).
  double s = 0.0, ds = 0.0;
  if (gm > 0) {
    const double q = am / gm;
    if (q >= rule.fan_to || rule.fan_to <= 1.0) {
      s = 1.0;
    } else if (q > rule.fan_from) {
      const double width = rule.fan_to - rule.fan_from;
      const double t = (q - rule.fan_from) / width;
      s = t * t * (3 - 2 * t);
      ds = 6 * t * (1 - t) / width;
    }
  }
  if (s == 0.0) return {am, {1.0, 1.0, 1.0}};
  TriangleRadius out{(1 - s) * am + s * gm, {}};
  for (std::size_t v = 0; v < 3; ++v) {
    // 3 ∂A/∂r = 1, 3 ∂G/∂r = G / r, 3 ∂q/∂r = (1 − A / r) / G.
    const double dgm = gm / r[v], dq = (1 - am / r[v]) / gm;
    out.thirds[v] = (1 - s) + s * dgm + ds * dq * (gm - am);
  }
  return out;
}

}  // namespace skelconv::reconstruct
