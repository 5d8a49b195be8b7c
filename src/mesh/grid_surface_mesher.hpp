// src/mesh/grid_surface_mesher.hpp — the fast, non-adaptive alternative to
// cgal_surface_mesher.hpp (`skelconv mesh --method grid`; internal to
// src/mesh, compiled in its own OBJECT library because OpenVDB's headers
// are large).
//
// The level function is sampled at the nodes of a uniform grid of spacing
// `voxel` over the box (only the cells the surface crosses, found from
// seeds on it; or the whole box except blocks outside a compact field's
// support, which hold a known constant, and blocks where `sign_over` proves
// the surface absent: a narrow band around the surface), stored in an OpenVDB FloatGrid, and its zero set is
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
  /// Optional: `level` for points within `radius` of `centre` (a cell's
  /// corners), with what they share done once (ImplicitField::value_near):
  /// as accurate, not necessarily the same bits.
  std::function<std::function<double(const Vec3&)>(const Vec3& centre, double radius)> level_near;
  Box3 box;  ///< contains the whole surface; level > 0 on its faces
  double voxel = 0;
  /// Optional: level = empty_level exactly at every point outside these
  /// boxes (ImplicitField::support_boxes). A block of 8³ nodes that no box
  /// meets is then filled with empty_level without calling `level`: the
  /// same values, hence the same mesh, as the dense sampling.
  const std::vector<Eigen::AlignedBox3d>* support_boxes = nullptr;
  double empty_level = 0;
  /// Optional: +1 if level > 0 at every point of the box, −1 if level < 0
  /// there, 0 if unknown; "> 0" and "< 0" must hold for the values `level`
  /// returns, rounded to float. Blocks of block³ nodes whose nodes'
  /// cells all lie in such a box are filled with ±float max instead of
  /// being sampled: only cells whose corners change sign shape
  /// volumeToMesh's output (adaptivity 0), and no such cell touches them,
  /// so the mesh is the dense sampling's.
  std::function<int(const Eigen::AlignedBox3d&)> sign_over;
  /// Optional: points on the surface, at least one on every component to
  /// mesh. When given, the grid is not swept: only the cells whose corners
  /// change sign are sampled, found by continuation from the cells holding
  /// the seeds (each such cell's neighbours across a face whose corners
  /// change sign change sign too). Every other node takes the sign of its
  /// neighbour below it, from the box's bottom face (outside) up: a node
  /// differs in sign from that neighbour only across an edge whose cells all
  /// change sign, whose corners are all sampled. The mesh is then the dense
  /// sampling's on every component a seed reaches; a component no seed
  /// reaches is left out (support_boxes and sign_over are not used).
  std::vector<Vec3> seeds;
  /// Threads sampling the cells of the continuation (at least 1); the mesh
  /// is the same bytes for any count.
  unsigned threads = 1;
};

/// Vertices and triangles (normals pointing out of {level < 0}); vertices
/// carry float precision until projected. Empty if no zero crossing.
TriangleMesh grid_surface_mesh(const GridSurfaceRequest& request);

}  // namespace skelconv::detail
