// skelconv/reconstruct/medial_graph.hpp — the inner Voronoi graph of surface
// samples (Ferley 1996 §1.2.2), the raw material of the skeleton.
//
// The samples are the vertices of a closed triangle mesh plus points spread
// over its coarse triangles (surface_samples.hpp). Their 3-D Delaunay
// triangulation (CGAL Delaunay_triangulation_3, exact predicates) is dual to
// their Voronoi diagram: each Delaunay tetrahedron ↔ a Voronoi vertex, its
// circumcentre c, the centre of an empty ball of radius ρ touching four
// samples; each Delaunay facet shared by two tetrahedra ↔ a Voronoi edge.
//
// Which Voronoi vertices: those of the tetrahedra whose circumcentre is
// inside the closed mesh (CGAL Side_of_triangle_mesh, an AABB-tree ray test
// on the input surface). Boissonnat's "interior tetrahedra" would be the
// ones inside the polyhedron; the circumcentre test is the one that matches
// the *skeleton*: the ball centred at c is then a ball inside the shape (up
// to the sampling density) touching it at four samples, i.e. an
// approximately maximal inscribed ball. The poles (Amenta et al.: the
// farthest Voronoi vertex of each sample's cell) are a subset of these; we
// keep them all because only the full set is connected along the medial
// axis (the poles alone are scattered points). The graph's edges are the
// Voronoi edges between two kept vertices; its faces the Voronoi faces
// (each dual to a Delaunay edge, a polygon of the cells around it) whose
// vertices are all kept. A face whose polygon leaves the shape lies across
// the surface (its Delaunay edge joins two neighbouring samples); the faces
// left are the inner ones, the medial axis as a 2-complex of the shape's
// homotopy type when the samples are dense (Amenta, Choi & Kolluri's inner
// Voronoi diagram).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/surface_samples.hpp"

namespace skelconv::reconstruct {

/// A Voronoi vertex inside the shape: the centre of an inscribed ball.
struct MedialVertex {
  Vec3 centre;
  double radius = 0.0;                  ///< ρ, the distance to its 4 samples
  std::array<std::int32_t, 4> samples;  ///< the Delaunay tetrahedron's vertices
};

/// A Voronoi edge between two inner Voronoi vertices, dual to the Delaunay
/// facet `facet` (three sample indices) the two tetrahedra share; {-1, -1,
/// -1} for an edge pruning added between two overlapping balls
/// (pruning.hpp, TipOptions::connect), dual to no facet.
struct MedialEdge {
  std::int32_t a = 0, b = 0;
  std::array<std::int32_t, 3> facet;
};

struct MedialGraph {
  std::vector<Vec3> samples;  ///< the input points, indexed by the fields above
  std::vector<MedialVertex> vertices;
  std::vector<MedialEdge> edges;
  /// Voronoi faces: polygons of vertex indices in cyclic order (each
  /// consecutive pair, and the last with the first, joined by an edge).
  std::vector<std::vector<std::int32_t>> faces;
  /// For each sample, the closed part of the surface it lies on (triangles
  /// joined through shared vertices), numbered from 0 in the order of the
  /// parts' first triangles; empty: the surface is one part.
  std::vector<std::int32_t> sample_parts;
};

/// The inner Voronoi graph of the surface samples of `surface`
/// (surface_samples.hpp: the vertices it takes first, then the added points),
/// which must be a closed triangle mesh (the inside test needs one). Throws
/// InputError if it has fewer than `minimum_samples` distinct samples, no
/// triangles, or is not closed (an edge not shared by exactly two triangles).
/// `sampling` sets how densely (surface_samples.hpp).
MedialGraph medial_graph(const TriangleMesh& surface, std::size_t minimum_samples = 20,
                         const SamplingOptions& sampling = {});

}  // namespace skelconv::reconstruct
