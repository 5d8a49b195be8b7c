// src/reconstruct/join_overlaps.hpp — the two repairs of a closed mesh
// whose triangles cross: the boundary of the union of its parts (CGAL's
// corefinement, join_overlaps.cpp) and, where that fails, a local remeshing
// of the crossings (CGAL's repair_self_intersections, remesh_crossings.cpp).
// Each in the CGAL object library, compiled on its own: their headers are
// heavy. Internal: check_closed_mesh_joining_overlaps
// (skelconv/reconstruct/mesh_check.hpp) is the public entry.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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

/// `mesh` (as above) with the triangles around its crossings removed and
/// the holes refilled, or smoothed, until no crossing is left
/// (CGAL::Polygon_mesh_processing::experimental::remove_self_intersections,
/// genus kept). For crossings the union cannot sort out: a fold, where the
/// curve of a crossing ends inside the surface and separates no part.
JoinedMesh remesh_crossings(const TriangleMesh& mesh);

/// The halfedge mesh `surface`'s triangles as a TriangleMesh (removed
/// elements skipped, the others renumbered in order), or why not.
template <class SurfaceMesh>
JoinedMesh to_triangle_mesh(const SurfaceMesh& surface, const char* step) {
  TriangleMesh out;
  std::vector<std::int32_t> index(surface.num_vertices() + surface.number_of_removed_vertices(), -1);
  for (const auto v : surface.vertices()) {
    index[std::size_t(v)] = std::int32_t(out.vertices.size());
    const auto& p = surface.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : surface.faces()) {
    std::array<std::int32_t, 3> t{};
    std::size_t n = 0;
    for (const auto v : vertices_around_face(surface.halfedge(f), surface)) {
      if (n == 3) break;
      t[n++] = index[std::size_t(v)];
    }
    if (n != 3 || surface.degree(f) != 3)
      return {std::nullopt, std::string(step) + " returned a face that is not a triangle"};
    out.triangles.push_back(t);
  }
  if (out.triangles.empty()) return {std::nullopt, std::string(step) + " removed every triangle"};
  return {std::move(out), {}};
}

}  // namespace skelconv::detail
