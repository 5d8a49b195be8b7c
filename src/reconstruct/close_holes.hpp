// src/reconstruct/close_holes.hpp — an open or edge-non-manifold mesh made
// closed for `skeletonize --repair`: the surface split where more than two
// triangles meet at an edge, each hole filled by a patch (CGAL's hole
// filling, close_holes.cpp, compiled on its own: its headers are heavy).
// Internal: check_closed_mesh_repairing (skelconv/reconstruct/mesh_check.hpp)
// is the public entry, which also decides whether a patch is too large.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

/// One hole as found and filled by close_holes.
struct FilledHole {
  std::size_t edges = 0;      ///< boundary edges of the cycle
  double length = 0.0;        ///< the cycle's length
  double patch_area = 0.0;    ///< the area of the triangles that fill it
  std::size_t triangles = 0;  ///< the patch's triangles
  std::size_t vertices = 0;   ///< vertices the patch added inside the hole (refinement)
  bool faired = false;        ///< false: fairing failed, the patch is left as refined (flat-ish)
};

/// The outcome of close_holes: the closed mesh, or why there is none.
struct ClosedMesh {
  std::optional<TriangleMesh> mesh;
  std::string failure;  ///< when !mesh: what went wrong, in the user's terms
  /// Vertex copies left where the surface touches itself (an edge of more
  /// than two triangles), each at its original's position.
  std::size_t vertices_split = 0;
  std::size_t isolated_vertices_removed = 0;  ///< vertices of no triangle (never written back)
  std::vector<FilledHole> holes;
};

/// `mesh`'s triangles with three distinct indices, whose orientation is
/// consistent (no edge used twice in one direction; checked by the caller),
/// as a closed surface:
/// 1. an edge of 2m triangles becomes m edges of two, each pair bounding one
///    wedge of the solid around it (by angle); then every vertex around
///    which the triangles do not form one disk or one half-disk is split,
///    one copy per fan (the copies at the original's position);
/// 2. each boundary cycle of that split surface, cut where it passes twice
///    through one input vertex (two holes touching there: the split
///    surface runs from one's border into the other's), is filled by the
///    steps of Polygon_mesh_processing::triangulate_refine_and_fair_hole:
///    triangulate_hole_polyline (minimal area and dihedral angles, given
///    the vertices across the cycle's edges), then, on the closed surface
///    (split again only at edges of more than two triangles), refine (to
///    the density of the edges around) and fair (the new vertices moved to
///    minimise the discrete bending energy, tangent to the surface at the
///    cycle). When the fairing's linear system cannot be solved the refined
///    patch is kept as it is (triangulate_and_refine_hole's result) and
///    the hole says so (faired = false);
/// 3. copies made where the closed surface only touches itself at a vertex
///    are that vertex again; vertices_split counts the copies left, at the
///    ends of split edges.
/// Fails on an edge with more triangles running one way than the other,
/// on an edge whose wedges nest so that no split of its ends separates
/// them (sheets crossing there), and when no triangulation of a hole is
/// found. The result's vertices are the used ones, in order, then the
/// copies left and the patches' new vertices.
ClosedMesh close_holes(const TriangleMesh& mesh);

}  // namespace skelconv::detail
