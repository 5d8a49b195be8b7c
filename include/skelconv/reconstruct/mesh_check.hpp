// skelconv/reconstruct/mesh_check.hpp — what reconstruction asks of its input
// mesh, checked before any sampling so that a bad mesh gets one message in
// the user's terms (docs/reconstruction.md, "Input"): not empty, closed,
// edge-manifold, consistently and outwardly oriented, without cavities,
// without self-intersections.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

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

/// Removes the vertices of `mesh` that no triangle uses (triangles
/// renumbered, the order of the others kept) and returns how many were
/// removed. Such a vertex is no point of the surface, yet every vertex is a
/// sample of the medial graph and widens the bounding box that the
/// tolerances, the sampling and the report's distances are relative to: one
/// stray vertex 1,000 away from a unit shape made its skeleton a single
/// ball and the measuring fail. Call it once the mesh is checked, so that
/// the checks' messages name the file's vertex indices.
std::size_t remove_unused_vertices(TriangleMesh& mesh);

/// Throws InputError naming the first problem of `mesh` (for edges, one
/// example edge by its two vertex indices):
/// - empty: no triangle (or a triangle with a repeated vertex only);
/// - open: an edge used by one triangle (a boundary);
/// - non-manifold: an edge used by more than two triangles;
/// - inconsistently oriented: an edge used twice in the same direction;
/// - inside out: a negative enclosed volume;
/// - a part wound the other way: a closed part with negative volume that
///   lies inside no other part;
/// - a cavity: a closed part with negative volume inside another;
/// - too far from the origin for its size: a diagonal below 1e5 ×
///   Segment::degenerate_length_ratio × its largest coordinate magnitude
///   (the skeleton's shortest pieces, down to ~5e-5 of the diagonal, could
///   not be written at that position);
/// - self-intersecting: two triangles cross (check_no_self_intersection),
///   tested only when `test_crossings` (the last test, the only one that
///   needs CGAL).
/// Degenerate triangles (a repeated index) are ignored, as the samplers do.
void check_closed_mesh(const TriangleMesh& mesh, bool test_crossings = true);

/// Throws InputError when a closed part of `mesh` (triangles joined by
/// edges) lies inside another: two spheres one in the other, both facing
/// outwards, enclose the inner one's inside twice, which is not a solid (its
/// surface is not the boundary of the enclosed volume). Tested by the
/// winding number of the other parts at a point of each part (its largest
/// triangle's centroid), so meaningful only for a mesh whose triangles do
/// not cross (a part that overlaps another has points inside it). Expects a
/// mesh check_closed_mesh accepts. Called by check_closed_mesh when it tests
/// crossings.
void check_no_nested_parts(const TriangleMesh& mesh);

/// Pairs of crossing triangles found by find_self_intersections.
struct SelfIntersections {
  std::size_t pairs = 0;  ///< crossing pairs in all; 0: none
  std::size_t first = 0, second = 0;  ///< the first pair found, indices in mesh.triangles, first < second
  /// Triangles of zero area (collinear corners, exactly), which CGAL reports
  /// as crossing themselves: not counted in `pairs`.
  std::size_t degenerate = 0;
  std::size_t first_degenerate = 0;  ///< index in mesh.triangles
  bool none() const { return pairs == 0 && degenerate == 0; }
};

/// The pairs of triangles of `mesh` that cross (CGAL
/// Polygon_mesh_processing::self_intersections, exact predicates). Triangles
/// that only share an edge or a vertex do not cross. Expects the edges
/// checked by check_closed_mesh.
SelfIntersections find_self_intersections(const TriangleMesh& mesh);

/// "the mesh intersects itself: triangles I and J cross (N crossing pair(s)
/// in all)": the problem, without what to do about it.
std::string self_intersection_problem(const SelfIntersections& found);

/// "the mesh has N triangle(s) of zero area (e.g. triangle I, ...)": the
/// problem when found.degenerate > 0, without what to do about it.
std::string degenerate_triangle_problem(const SelfIntersections& found);

/// Throws InputError naming the first pair of crossing triangles (indices
/// in `mesh.triangles`) and how many pairs cross (find_self_intersections):
/// two overlapping spheres stored as one mesh, a fold.
void check_no_self_intersection(const TriangleMesh& mesh);

/// What check_closed_mesh_joining_overlaps did to a mesh.
struct OverlapRepair {
  std::size_t crossing_pairs = 0;     ///< in the input; 0: none, the mesh was left as it was
  std::size_t triangles_removed = 0;  ///< input triangles not in the result (cut, or inside the union)
  std::size_t triangles_added = 0;    ///< result triangles not in the input (the pieces of cut ones)
  std::size_t cavities_filled = 0;    ///< voids the crossing parts closed off, filled
};

/// Whether `mesh`'s first problem for check_closed_mesh is one that
/// check_closed_mesh_repairing repairs: an edge of more than two triangles,
/// or a boundary edge, and no edge used twice in one direction (the
/// messages of `skeletonize` name --repair for those).
bool has_holes_or_non_manifold_edges(const TriangleMesh& mesh);

/// check_closed_mesh for a caller that offers check_closed_mesh_repairing as
/// an option: where the problem is one the repair fixes (holes, edges of more
/// than two triangles, an inside-out surface or part, crossing triangles), the message ends "(or pass
/// OPTION to let skeletonize ...)", OPTION in the caller's spelling
/// ("--repair" for the command, "repair=True" for Python).
void check_closed_mesh_offering_repair(const TriangleMesh& mesh, std::string_view repair_option);

/// check_closed_mesh, except that a mesh whose triangles cross is replaced
/// by the boundary of the solid it encloses: the points where its
/// generalized winding number is at least 1/2, i.e. the union of its
/// overlapping parts, folds included. The surface is cut along its crossing
/// curves (CGAL Polygon_mesh_processing::experimental::autorefine) and each
/// piece kept when the winding number is 0 just in front of it and 1 just
/// behind (src/reconstruct/join_overlaps.cpp); voids that the crossing
/// parts close off (winding number 0, surrounded by the solid) are filled,
/// since a skeleton's solid has no cavity. The result is then checked
/// again, crossings included, and must keep the input's bounding box (a
/// union does, to rounding). Scanned and modelled meshes often overlap
/// slightly where parts meet (a horn, a leg) or fold over themselves; the
/// union is what the refusal asks the user to compute. Only crossings are
/// repaired: an open, non-manifold, inside-out or hollow mesh is refused as
/// by check_closed_mesh, before any repair. Throws InputError when the
/// union cannot be computed or is not a valid input (its new vertices are
/// rounded to double; a piece on which another sheet lies has no whole
/// winding number).
OverlapRepair check_closed_mesh_joining_overlaps(TriangleMesh& mesh);

/// What check_closed_mesh_repairing did to an open, non-manifold or
/// inside-out surface (all 0: it was closed, edge-manifold and facing
/// outwards, and left as it was).
struct SurfaceRepair {
  std::size_t non_manifold_edges = 0;  ///< in the input: edges of more than two triangles
  std::size_t boundary_edges = 0;      ///< in the input, after splitting the non-manifold ones
  /// Vertices left as two or more vertices at one position, one per fan of
  /// triangles, where merging them back would leave an edge of more than
  /// two triangles (the surface touches itself along an edge there).
  std::size_t vertices_split = 0;
  std::size_t isolated_vertices_removed = 0;  ///< vertices of no triangle: samples off the surface
  std::size_t holes_filled = 0;
  std::size_t holes_not_faired = 0;  ///< of those, filled without fairing (its linear system failed)
  std::size_t triangles_added = 0;
  std::size_t vertices_added = 0;  ///< inside the patches
  double largest_hole_area = 0.0;  ///< the largest patch's area / the closed surface's area
  /// Triangles turned round, of parts of the closed surface that faced
  /// inwards though no other part enclosed them (an inside-out export, or a
  /// patch wound the other way); 0 otherwise.
  std::size_t triangles_flipped = 0;
  std::size_t parts_flipped = 0;  ///< the parts those triangles made
  /// Triangles turned round first, to agree with their neighbours'
  /// orientation (each part oriented from its first triangle).
  std::size_t triangles_reoriented = 0;
  bool repaired() const {
    return non_manifold_edges + boundary_edges + isolated_vertices_removed + triangles_flipped +
               triangles_reoriented >
           0;
  }
};

/// What check_closed_mesh_repairing did: the surface closed, then overlaps joined.
struct InputRepair {
  SurfaceRepair surface;
  OverlapRepair overlaps;
};

/// The largest hole check_closed_mesh_repairing fills, as a fraction of the
/// closed surface's area. Between the box with one face missing (1/6: a
/// piece left out, filled) and the half-open shell (a hemisphere's opening
/// is 1/3 of the closed surface, a sheet's 1/2: an open shape, not a
/// missing piece, refused).
inline constexpr double max_hole_area_fraction = 0.25;

/// check_closed_mesh_joining_overlaps, after closing an open or
/// edge-non-manifold surface (`skelconv skeletonize --repair`;
/// docs/reconstruction_input.md, "Open and non-manifold meshes"):
/// 0. where no edge has more than two triangles, the triangles that run an
///    edge the same way as their neighbour are turned round, each part
///    oriented from its first triangle (a part with no consistent
///    orientation, a Möbius band, is refused);
/// 1. an edge of 2m triangles becomes m edges of two, each pair bounding
///    one wedge of the solid around it, and each vertex whose triangles
///    form several fans gets one copy per fan;
/// 2. each hole (boundary cycle, cut where it passes twice through one
///    vertex: holes that touch there) is triangulated, refined to the
///    density around it and faired (the steps of CGAL's
///    triangulate_refine_and_fair_hole; close_holes.hpp in src/);
/// 3. copies where the closed surface only touches itself at a vertex are
///    that vertex again; copies at a split edge stay (vertices_split), and
///    if the split sheets cross, the mesh is refused (CGAL's union crashed
///    on distinct vertices at one position);
/// 4. every part that faces inwards (negative enclosed volume) and lies
///    inside no other part is turned round (an export with the other
///    winding convention, a patch wound the other way, a part oriented
///    from an inward first triangle in step 0);
/// 5. then crossings as check_closed_mesh_joining_overlaps (a patch, or
///    the input, can cross the surface), and every check again.
/// Throws InputError for an inconsistent orientation at a non-manifold
/// edge (not repaired), when
/// the split or the hole filling fails, and for a hole whose patch is more
/// than `max_hole_area` of the closed surface's area, naming its size: an
/// opening that large is a shape left open, and a patch would invent a
/// large part of the shape. Vertices of no triangle are dropped when the
/// surface is repaired (each would be a sample of the medial graph).
InputRepair check_closed_mesh_repairing(TriangleMesh& mesh, double max_hole_area = max_hole_area_fraction);

}  // namespace skelconv::reconstruct
