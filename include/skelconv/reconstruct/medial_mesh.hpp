// skelconv/reconstruct/medial_mesh.hpp — the inner Voronoi graph simplified
// to a medial mesh: a budget of spheres joined by edges (tubes) and
// triangles (sheets), the skeleton that `skeletonize --method medial` turns
// into SCALIS triangles, segments and points (docs/reconstruction_medial.md).
//
// The medial axis of a body, a head, a hand or a plate is made of sheets; a
// curve skeleton cannot describe it. Q-MAT (Li et al., SIGGRAPH 2015)
// simplifies a dense medial mesh by edge collapses under a spherical quadric
// error. We reach the same kind of output by a cheaper route on the graph we
// already have (medial_graph.hpp): a partition of it into geodesic Voronoi
// regions (seeds placed by farthest-point sampling, each vertex to its
// nearest seed along the graph), whose dual is the medial mesh:
//
//   0. a Voronoi vertex whose ball lies inside a neighbour's is merged into
//      it (a spike toward a sharp vertex collapses into the ball it grows
//      from);
//   1. distances along the graph's edges are measured in units of the local
//      radius, |c_u − c_v| / max((ρ_u + ρ_v)/2, floor): the spheres are then
//      about `spacing` radii apart wherever the axis runs, densely along a
//      thin limb and sparsely in a fat body, as Q-MAT's quadric error places
//      them;
//   2. seeds by farthest-point sampling in that distance (one per connected
//      piece first, at its largest ball) until every vertex is within
//      `spacing` of a seed or the budget is spent; each vertex belongs to
//      its nearest seed (multi-source Dijkstra), and each region becomes the
//      seed's ball;
//   3. two regions joined by a Voronoi edge give an edge; three regions that
//      meet around one Voronoi vertex (it and its neighbours carry the three
//      labels) and are pairwise joined give a triangle — the dual of the
//      partition, so a sheet becomes triangles and a tube, whose Voronoi
//      vertices are a thin tangle along the axis, a chain of edges;
//   4. a triangle is refused when it is a sliver (smallest angle below
//      `min_triangle_angle_degrees`), when one of its edges already bounds
//      `max_triangles_per_edge` triangles, or when it would close a
//      tetrahedron with three accepted ones (four regions around one vertex
//      give all four triangles of a tetrahedron; two of them cover the
//      sheet, the other two would count it twice in a sum blend);
//   5. edges in no triangle are tubes, unless both ends are sheet vertices
//      (a diagonal of a refused triangle: the sheet already joins them);
//      spheres in no edge are isolated balls;
//   6. tube spurs are removed: chains from a tip to a sheet or junction
//      whose balls barely reach beyond the junction's ball (the spikes the
//      medial axis sends to every sharp vertex of a coarse mesh);
//   7. pieces whose balls overlap are joined by an edge (pruning can cut a
//      thin neck out of the graph; the foot must not come back detached).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"  // Vec4
#include "skelconv/reconstruct/medial_graph.hpp"

namespace skelconv::reconstruct {

struct MedialMeshOptions {
  /// At most this many spheres.
  std::size_t max_spheres = 200;
  /// Seeds are added until every Voronoi vertex is within this many local
  /// radii (along the graph) of one.
  double spacing = 1.0;
  /// The radius unit of the distance never falls below this (absolute,
  /// length units): a sheet's balls shrink to 0 at a convex edge, and
  /// distances in units of a vanishing radius would spend the budget there.
  double radius_floor = 0.0;
  double min_triangle_angle_degrees = 10.0;
  std::size_t max_triangles_per_edge = 3;
  /// Step 6: a tube chain from a tip to a sheet or junction whose balls
  /// reach at most this × the junction's radius beyond its ball is a spur,
  /// removed. 0 keeps every chain.
  double spur_protrusion = 0.5;
  /// Step 0: a Voronoi vertex whose ball lies within (1 + this) × a
  /// neighbour's radius of the neighbour's centre is merged into it.
  /// Negative keeps them all.
  double contained_slack = 0.05;
};

struct MedialMesh {
  std::vector<Vec4> spheres;                           ///< (x, y, z, radius)
  std::vector<std::array<std::int32_t, 2>> edges;      ///< tubes: edges in no triangle
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< sheets
  std::vector<std::int32_t> isolated;                  ///< spheres in no edge or triangle
};

/// The medial mesh of `graph` (usually pruned: prune_medial_graph), as
/// described above. Same graph, same mesh (no random choice: ties go to the
/// lower vertex index). Empty for an empty graph.
MedialMesh simplify_medial_graph(const MedialGraph& graph, const MedialMeshOptions& options);

}  // namespace skelconv::reconstruct
