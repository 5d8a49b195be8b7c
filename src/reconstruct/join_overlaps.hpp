// src/reconstruct/join_overlaps.hpp — the boundary of the union of a
// self-intersecting closed mesh's parts, through CGAL's corefinement
// (join_overlaps.cpp, in the CGAL object library, compiled on its own: its
// headers are heavy). Internal: check_closed_mesh_joining_overlaps
// (skelconv/reconstruct/mesh_check.hpp) is the public entry.
#pragma once

#include <optional>
#include <string>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

/// The outcome of join_overlapping_parts: the mesh, or why there is none.
struct JoinedMesh {
  std::optional<TriangleMesh> mesh;
  std::string failure;  ///< when !mesh: what went wrong, in the user's terms
};

/// `mesh` (closed, manifold, consistently oriented: check_closed_mesh
/// without its crossing test) cut along the curves where its triangles
/// cross, the pieces inside the enclosed solid removed and the rest stitched
/// (CGAL::Polygon_mesh_processing::experimental::
/// autorefine_and_remove_self_intersections). Vertices the cut adds are
/// rounded to double: the caller checks the result again.
JoinedMesh join_overlapping_parts(const TriangleMesh& mesh);

}  // namespace skelconv::detail
