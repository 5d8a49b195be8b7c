// skelconv/reconstruct/surface_distance.hpp — how far apart two closed
// surfaces are: two-sided Hausdorff and RMS distances (CGAL
// Polygon_mesh_processing, in its own translation unit).
#pragma once

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

struct SurfaceDistance {
  double hausdorff = 0.0;  ///< max of the two approximate one-sided distances
  double rms = 0.0;        ///< root mean square over samples of both surfaces
  double diagonal = 0.0;   ///< bounding-box diagonal of the first surface
};

/// PMP::approximate_Hausdorff_distance both ways, with `samples_per_area`
/// random points (fixed seed, same result for the same meshes) per unit of
/// area divided by the squared diagonal; the RMS uses the same kind of
/// samples. Throws InputError if either mesh has no triangle.
SurfaceDistance surface_distance(const TriangleMesh& a, const TriangleMesh& b, double samples_per_area = 2e4);

}  // namespace skelconv::reconstruct
