// src/mesh/grid_surface_mesher.hpp — the fast, non-adaptive alternative to
// cgal_surface_mesher.hpp (`skelconv mesh --method grid`; internal to
// src/mesh, compiled in its own OBJECT library because OpenVDB's headers
// are large).
//
// The level function is sampled at every node of a uniform grid of spacing
// `voxel` over the box (except in blocks outside a compact field's support,
// which hold a known constant), stored in an OpenVDB FloatGrid, and its zero set is
// extracted with openvdb::tools::volumeToMesh (no adaptivity: quads of about
// one voxel, each split into two triangles). No guarantee of topology
// beyond the grid's resolution: features thinner than a voxel may be lost
// or merged (docs/mesh.md compares both methods).
#pragma once

#include <functional>
#include <vector>

#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

struct GridSurfaceRequest {
  /// Negative inside, positive outside (iso − f).
  std::function<double(const Vec3&)> level;
  Box3 box;  ///< contains the whole surface; level > 0 on its faces
  double voxel = 0;
  /// Optional: level = empty_level exactly at every point outside these
  /// boxes (ImplicitField::support_boxes). A block of 8³ nodes that no box
  /// meets is then filled with empty_level without calling `level`: the
  /// same values, hence the same mesh, as the dense sampling.
  const std::vector<Eigen::AlignedBox3d>* support_boxes = nullptr;
  double empty_level = 0;
};

/// Vertices and triangles (normals pointing out of {level < 0}); vertices
/// carry float precision until projected. Empty if no zero crossing.
TriangleMesh grid_surface_mesh(const GridSurfaceRequest& request);

}  // namespace skelconv::detail
