// src/mesh/cgal_surface_mesher.hpp — the one place that calls CGAL Mesh_3
// (internal to src/mesh; compiled in its own OBJECT library because CGAL adds
// -frounding-math, which must stay out of the generated-kernel code).
//
// Delaunay refinement of the surface {level = 0} of an implicit domain
// (Labeled_mesh_domain_3::create_implicit_mesh_domain), started from the
// given seeds (inserted as surface vertices, then refine_mesh_3), with
// manifold facet criteria. Only the surface is wanted, so the volume is not
// refined beyond what the surface needs (no cell criteria), and neither
// perturbation nor exudation runs. CGAL's random generators are seeded with
// `random_seed`, so the same request gives the same mesh.
#pragma once

#include <functional>
#include <vector>

#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

struct CgalSurfaceRequest {
  /// Negative inside, positive outside (iso − f).
  std::function<double(const Vec3&)> level;
  Box3 box;                 ///< contains the whole surface; level > 0 on its faces
  std::vector<Vec3> seeds;  ///< points on the surface, at least one per component
  double facet_size = 0;      ///< CGAL facet_size: upper bound on facet circumradii
  double facet_distance = 0;  ///< CGAL facet_distance: facet centre to surface
  double facet_angle = 30;    ///< CGAL facet_angle: lower bound, degrees (≤ 30 terminates)
  /// Bisection accuracy of CGAL's surface intersections, relative to the box
  /// diagonal.
  double relative_error_bound = 1e-6;
  unsigned random_seed = 0;
};

/// The restricted Delaunay surface mesh: vertices and triangles oriented
/// with normals pointing out of {level < 0}; no normals. Empty if CGAL
/// produced no facets.
TriangleMesh cgal_surface_mesh(const CgalSurfaceRequest& request);

}  // namespace skelconv::detail
