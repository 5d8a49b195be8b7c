// skelconv/reconstruct/surface_distance.hpp — how far apart two closed
// surfaces are: two-sided Hausdorff and RMS distances (CGAL
// Polygon_mesh_processing, in its own translation unit).
#pragma once

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

struct SurfaceDistance {
  double hausdorff = 0.0;  ///< the largest distance found from either surface to the other
  double rms = 0.0;        ///< root mean square over samples of both surfaces
  double diagonal = 0.0;   ///< bounding-box diagonal of the first surface
};

/// Edge length, as a fraction of the first surface's diagonal, of the
/// uniform split whose vertices the Hausdorff distance also measures (and
/// the report image colours): random samples alone leave gaps of a few
/// mean spacings on a large flat face, where a CAD part's largest distance
/// often lies, and missed it by up to ~6%.
inline constexpr double dense_sample_spacing = 1.0 / 150.0;

/// Hausdorff: the larger of PMP::approximate_Hausdorff_distance both ways,
/// with `samples_per_area` random points (fixed seed, same result for the
/// same meshes) per unit of area divided by the squared diagonal, and the
/// exact distance to the other surface of every vertex of `b` and of `a`
/// split to edges of at most dense_sample_spacing × diagonal. The RMS uses
/// the random samples. Throws InputError if either mesh has no triangle.
SurfaceDistance surface_distance(const TriangleMesh& a, const TriangleMesh& b, double samples_per_area = 2e4);

/// `mesh` with every triangle split uniformly (n × n pieces, n ≤ 64) until
/// its edges are at most `edge` long. Vertices are not shared between
/// triangles: for sampling and drawing, not for topology.
TriangleMesh split_to_edge_length(const TriangleMesh& mesh, double edge);

}  // namespace skelconv::reconstruct
