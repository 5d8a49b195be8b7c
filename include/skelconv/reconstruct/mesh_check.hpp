// skelconv/reconstruct/mesh_check.hpp — what reconstruction asks of its input
// mesh, checked before any sampling so that a bad mesh gets one message in
// the user's terms (docs/reconstruction.md, "Input"): not empty, closed,
// edge-manifold, consistently and outwardly oriented, without cavities,
// without self-intersections.
#pragma once

#include <cstddef>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

/// Throws InputError unless `mesh` has at most `max_triangles` triangles and
/// as many vertices: the work of a reconstruction grows with the number of
/// samples, and every vertex is one (the messages name the option
/// --max-triangles of `skelconv skeletonize`, which passes the limit).
void check_mesh_size(const TriangleMesh& mesh, std::size_t max_triangles);

/// Merges the vertices of `mesh` that sit at exactly the same position into
/// one (the first; triangles renumbered, the others removed) and returns how
/// many were removed. Triangle soups (STL-style exports, some PLY writers)
/// store every corner anew, and their surface would otherwise look open at
/// every edge. Positions a rounding apart stay distinct.
std::size_t merge_coincident_vertices(TriangleMesh& mesh);

/// Throws InputError naming the first problem of `mesh` (for edges, one
/// example edge by its two vertex indices):
/// - empty: no triangle (or a triangle with a repeated vertex only);
/// - open: an edge used by one triangle (a boundary);
/// - non-manifold: an edge used by more than two triangles;
/// - inconsistently oriented: an edge used twice in the same direction;
/// - inside out: a negative enclosed volume;
/// - a cavity: a connected component with negative volume inside the others;
/// - too far from the origin for its size: a diagonal below 1e5 ×
///   Segment::degenerate_length_ratio × its largest coordinate magnitude
///   (the skeleton's shortest pieces, down to ~5e-5 of the diagonal, could
///   not be written at that position);
/// - self-intersecting: two triangles cross (check_no_self_intersection).
/// Degenerate triangles (a repeated index) are ignored, as the samplers do.
void check_closed_mesh(const TriangleMesh& mesh);

/// Throws InputError naming the first pair of crossing triangles (indices
/// in `mesh.triangles`) and how many pairs cross: two overlapping spheres
/// stored as one mesh, a fold. Triangles that only share an edge or a
/// vertex do not cross (CGAL Polygon_mesh_processing::self_intersections,
/// exact predicates). Expects the edges checked by check_closed_mesh.
void check_no_self_intersection(const TriangleMesh& mesh);

}  // namespace skelconv::reconstruct
