// skelconv/reconstruct/medial_mesh.hpp — a medial mesh: spheres joined by
// edges (tubes) and triangles (sheets), the skeleton that `skeletonize
// --method medial` turns into SCALIS triangles, segments and points
// (docs/reconstruction_medial.md). medial_quadric.hpp builds it.
#pragma once

#include <array>
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

}  // namespace skelconv::reconstruct
