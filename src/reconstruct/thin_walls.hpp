// src/reconstruct/thin_walls.hpp — where a shape is a thin wall, found on its
// pruned medial graph, so that the medial path samples only there finer
// (docs/reconstruction_medial.md, "Thin walls"). Internal: the medial stage
// (medial_stage.cpp) is its one user.
//
// A wall about as thick as the samples' spacing h has Delaunay cells joining
// samples on both of its faces, whose circumcentres fall outside it: its
// medial sheet comes out as a net of holes. A tube (a limb) as thin keeps
// its medial axis, a curve, and is left as it is.
//
// Thin: a vertex of radius below `thin_radius` × h. A wall: thin vertices
// whose thin neighbours within R = 4 × thin_radius × h spread at least R / 4
// in a second direction (the square root of the middle eigenvalue of their
// covariance). A tube of radius r < R / 4 holds its medial vertices within r
// of its axis, so a straight one never passes; a sheet does wherever it is
// wider than about R: the vertices of a disc of radius R spread R / 2 in
// both directions, of a half disc (a wall's rim) 0.27 R across it, of a
// strip w wide w / √12 (w > 0.87 R). The thin vertices are decided by cubes
// of side R / 4, each from the cubes whose centroids lie within R of its
// own: a vertex's own neighbourhood would cost its thin neighbours each
// (thousands along a thin limb). And the input's two faces, along the
// sheet's normal (the direction of least spread) through the cube's
// centroid, must be less than 2 × (2 thin_radius h) apart: the small-scale medial
// structure under a noisy surface also spreads as a sheet, but has the
// shape's thick inside on one side.
//
// One wall: the wall cubes linked within R (across the holes of its
// sheet), kept if it is at least as wide as the disc that tells a sheet (its
// vertices spread R / 2 in a second direction: a smaller patch is a local
// arrangement, where thin limbs meet or a blob is flattened, not a wall
// whose sheet the coarse samples break) and if it is thinner than the
// spacing (median half-thickness t along those normals below h / 2: only
// then are samples on its two faces closer than neighbours on one face, the
// Delaunay cells that break its sheet; a ball's radius overstates the
// thickness where the samples are as far apart as the wall is thick),
// sampled at h / min(h / t, max_refinement): two samples across it.
//
// What is sampled finer: each triangle of the input with a sample (of the
// first sampling) within a wall vertex's radius + h of its centre: the
// samples the wall's balls touch and, one spacing further, those round the
// holes in its sheet.
#pragma once

#include <cstddef>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"

namespace skelconv::detail {

struct ThinWalls {
  /// One factor per triangle (SamplingOptions::triangle_refinement), or
  /// empty where no wall was found.
  std::vector<double> triangle_refinement;
  std::size_t thin_vertices = 0;  ///< vertices of radius below thin_radius × h
  std::size_t wall_vertices = 0;  ///< of those, the ones on a wall kept
  std::size_t walls = 0;          ///< walls kept (components of wall cubes)
  std::size_t triangles = 0;      ///< triangles sampled finer
  double finest = 1.0;            ///< the largest refinement
};

/// The thin walls of `surface` on `graph`, its medial graph built from
/// surface_samples(surface, sampling) with spacing h = `spacing` (pruned).
ThinWalls find_thin_walls(const TriangleMesh& surface, const reconstruct::MedialGraph& graph,
                          const reconstruct::SamplingOptions& sampling, double spacing, double thin_radius,
                          double max_refinement);

}  // namespace skelconv::detail
