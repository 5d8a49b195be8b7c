// skelconv/reconstruct/surface_samples.hpp — the points the medial graph is
// built from: the mesh's vertices, plus points spread over the triangles
// where the mesh is coarse, so that any closed mesh (a cube of 8 vertices,
// a CAD part with large flat faces) is sampled densely enough for its
// Voronoi vertices to approximate the medial axis (docs/reconstruction.md,
// "Samples").
//
// Deterministic, no random numbers: every edge longer than the spacing h
// (SamplingOptions)
// gets ⌈length / h⌉ − 1 evenly spaced points (once per edge, so that the two
// triangles sharing it agree), and every triangle whose longest edge exceeds
// h gets the interior points of the barycentric grid of n = ⌈longest / h⌉
// steps (points (i, j, k)/n with i, j, k ≥ 1). The grid's points are spread
// evenly over the triangle, so their number follows its area: the samples
// are area-weighted where the mesh is coarse.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

struct SamplingOptions {
  /// The spacing h is the bounding-box diagonal / this: a mesh of a few
  /// large triangles gets about this many samples along its diagonal, and
  /// a mesh whose edges are all shorter gets none. Not a multiple of the
  /// mesh's own edge lengths: the meshes CGAL's mesher writes mix edges of
  /// 1e-3 and 0.2 (the test tree: median 0.0017, longest 0.1998, diagonal
  /// 9.6), which would ask for millions of points. 12 keeps the test shapes
  /// of docs/reconstruction_results.md as they are, noisy ones included
  /// (longest edge ≤ diagonal / 16.2, plus up to 2√3 × 0.005 × the diagonal
  /// of noise: below diagonal / 12.6).
  double diagonal_divisions = 12.0;
  /// At most this many samples in all: h grows (doubling) until the count
  /// fits, so that the 3-D Delaunay triangulation stays tractable.
  std::size_t max_samples = 200000;
  /// Empty, or one factor (≥ 1) per triangle of the mesh: that triangle is
  /// sampled at h / its factor, and an edge at h / the larger factor of its
  /// two triangles (so that both agree on its points). The medial path
  /// samples a thin wall finer this way and leaves the rest as it was
  /// (thin_walls.hpp).
  std::vector<double> triangle_refinement;
};

/// The vertices of `mesh` (first, in order, so that vertex i is sample i)
/// followed by the added surface points. Triangles with a repeated index
/// are skipped.
std::vector<Vec3> surface_samples(const TriangleMesh& mesh, const SamplingOptions& options = {});

/// For each sample of surface_samples(mesh, options), in the same order,
/// one triangle it lies on: for a vertex, the first triangle round it (−1
/// for a vertex of none); for a point on an edge, the first of its two
/// triangles; for a point inside a triangle, that triangle.
std::vector<std::int32_t> sample_triangles(const TriangleMesh& mesh, const SamplingOptions& options = {});

}  // namespace skelconv::reconstruct
