// src/reconstruct/join_overlaps.hpp — the boundary of the union of a
// self-intersecting closed mesh's parts, through CGAL's autorefinement and
// the winding number
// (join_overlaps.cpp, in the CGAL object library, compiled on its own: its
// headers are heavy). Internal: check_closed_mesh_joining_overlaps
// (skelconv/reconstruct/mesh_check.hpp) is the public entry.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

/// The outcome of join_overlapping_parts: the mesh, or why there is none.
struct JoinedMesh {
  std::optional<TriangleMesh> mesh;
  std::string failure;  ///< when !mesh: what went wrong, in the user's terms
  /// The failure is a precondition of CGAL's autorefinement that the mesh
  /// does not meet, found before running it.
  bool refused = false;
  /// Voids the overlapping parts close off, filled (their boundary removed).
  std::size_t cavities_filled = 0;
};

/// `mesh` (closed, manifold, consistently oriented: check_closed_mesh
/// without its crossing test) cut along the curves where its triangles
/// cross (CGAL::Polygon_mesh_processing::experimental::autorefine), and of
/// the pieces those that bound the solid where its winding number is at
/// least 1/2 (winding_number.hpp), inward-facing parts (voids the crossing
/// parts close off) removed. Vertices the cut adds are rounded to double
/// and each sheet keeps its own copy of them: the caller joins vertices at
/// one position and checks the result again.
/// Refused before the cut (`refused`): a position held by several vertices
/// of the halfedge mesh (where closed parts touch at a single vertex, split
/// for CGAL) that lies on a triangle with no corner there. The crossing
/// curve then passes through two vertices at one point, and CGAL's
/// corefinement crashed (a segmentation fault: two cubes touching at a
/// corner and a box touching both along that corner's edges), returned a
/// non-manifold union or left crossings.
JoinedMesh join_overlapping_parts(const TriangleMesh& mesh);

}  // namespace skelconv::detail
