// skelconv/reconstruct/medial_mesh.hpp — a medial mesh: spheres joined by
// edges (tubes) and triangles (sheets), the skeleton that `skeletonize
// --method medial` turns into SCALIS triangles, segments and points
// (docs/reconstruction_medial.md). medial_quadric.hpp builds it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
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

/// The one radius τ of the SCALIS triangle a medial triangle becomes, from
/// its spheres' radii a, b and c (one radius, because a radius varying over
/// the triangle costs the certified quadrature, far too slow to mesh): their
/// arithmetic mean (∂τ/∂a = 1/3), or with `geometric` their geometric mean
/// (∂τ/∂a = τ / (3 a); MedialOptions::geometric_triangle_radius). Where a
/// sheet fans out from a thick part's deep spheres to a thin part's (CGAL's
/// cow: its rump's sheet to the tail lying against it, radii 0.066, 0.0077
/// and 0.0077), the arithmetic mean is set by the thick corner and puts the
/// thin corners' surface several times their radius out (0.027, 3.5 times),
/// which fills the concave crease where the thin part meets the thick; the
/// geometric mean weighs ratios alike (0.0157, twice). Where the radii are
/// close the two agree to second order.
inline double triangle_radius(double a, double b, double c, bool geometric) {
  return geometric ? std::cbrt(a * b * c) : (a + b + c) / 3;
}

}  // namespace skelconv::reconstruct
