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
//
// Where the mesh is far denser than the medial graph can use (a scan of a
// million triangles, a subdivided mesh), its vertices are thinned to one
// per cell of a grid set by the diagonal (SamplingOptions::vertex_cell_divisions),
// so that the samples, and the Delaunay triangulation, the inside tests
// and the simplification built on them, grow with the shape's area in
// units of the diagonal, not with the file's vertex count.
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
  /// fits, so that the 3-D Delaunay triangulation stays tractable (the
  /// vertices taken, sample_vertices, count in it; where they alone exceed
  /// it, no point is added).
  std::size_t max_samples = 200000;
  /// A mesh of more than `thin_vertices_above` vertices has them thinned
  /// to one per cell of a grid of spacing diagonal / vertex_cell_divisions
  /// where they outnumber the cells that hold any by more than
  /// `vertex_crowding` (sample_vertices). 200: a cell is 2.5 times finer
  /// than the medial path's finest spacing (a thin wall sampled at
  /// diagonal / 40 / 2.5), so that the thinned samples still resolve what
  /// the path looks at. A crowding of 2: thinning only where it removes
  /// more than half the vertices (a mesh subdivided once or twice, each
  /// vertex then with 4 or 16 in its place: 2.4 to 3.7). 50,000 vertices:
  /// below it the triangulation is cheap whatever the crowding, and small
  /// meshes crowded about their details (CGAL's boeing, 2,741 vertices,
  /// 2.58; the blade 3.97; the man once repaired, about 2.0) keep them;
  /// every mesh of docs/reconstruction_medial.md's tables is under it
  /// (bunny00 37,706, crowding 1.49). 0 divisions: every vertex is a
  /// sample.
  std::size_t thin_vertices_above = 50000;
  double vertex_cell_divisions = 200.0;
  double vertex_crowding = 2.0;
  /// Empty, or one factor (≥ 1) per triangle of the mesh: that triangle is
  /// sampled at h / its factor, and an edge at h / the larger factor of its
  /// two triangles (so that both agree on its points). The medial path
  /// samples a thin wall finer this way and leaves the rest as it was
  /// (thin_walls.hpp).
  std::vector<double> triangle_refinement;
};

/// The vertices of `mesh` taken as samples, in increasing order: every
/// vertex, unless they are more than `thin_vertices_above` and outnumber
/// the cells of spacing diagonal / `vertex_cell_divisions` that hold a
/// vertex by more than `vertex_crowding` times; then one per such cell, the vertex nearest the
/// centroid of the cell's vertices (the first of equals; merged_in_cells of
/// ball_fit.hpp with on_surface).
std::vector<std::int32_t> sample_vertices(const TriangleMesh& mesh, const SamplingOptions& options = {});

/// The vertices of `mesh` taken as samples (sample_vertices: first, in
/// order; all of them, vertex i sample i, unless the mesh is crowded)
/// followed by the added surface points. Triangles with a repeated index
/// are skipped.
std::vector<Vec3> surface_samples(const TriangleMesh& mesh, const SamplingOptions& options = {});

/// For each sample of surface_samples(mesh, options), in the same order,
/// one triangle it lies on: for a vertex, the first triangle round it (−1
/// for a vertex of none); for a point on an edge, the first of its two
/// triangles; for a point inside a triangle, that triangle.
std::vector<std::int32_t> sample_triangles(const TriangleMesh& mesh, const SamplingOptions& options = {});

}  // namespace skelconv::reconstruct
