// Implementation of grid_surface_mesher.hpp (OpenVDB 10).
#include "grid_surface_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

namespace skelconv::detail {
namespace {

/// The level sampled on the grid nodes, as an OpenVDB float grid whose
/// index (i, j, k) is the world point box.lo + voxel (i, j, k). Values are
/// clamped to ±float max (an inverse kernel's skeleton gives −inf).
openvdb::FloatGrid::Ptr sample(const GridSurfaceRequest& request, const openvdb::Coord& count) {
  const float limit = std::numeric_limits<float>::max();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(/*background: outside*/ limit);
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(request.voxel);
  transform->postTranslate(openvdb::Vec3d(request.box.lo.x(), request.box.lo.y(), request.box.lo.z()));
  grid->setTransform(transform);
  auto accessor = grid->getAccessor();
  for (int i = 0; i < count.x(); ++i) {
    for (int j = 0; j < count.y(); ++j) {
      for (int k = 0; k < count.z(); ++k) {
        const Vec3 p = request.box.lo + request.voxel * Vec3(i, j, k);
        const double value = std::clamp(request.level(p), -double(limit), double(limit));
        accessor.setValue(openvdb::Coord(i, j, k), float(value));
      }
    }
  }
  return grid;
}

}  // namespace

TriangleMesh grid_surface_mesh(const GridSurfaceRequest& request) {
  openvdb::initialize();
  const Vec3 extent = request.box.hi - request.box.lo;
  const openvdb::Coord count(int(std::ceil(extent.x() / request.voxel)) + 1,
                             int(std::ceil(extent.y() / request.voxel)) + 1,
                             int(std::ceil(extent.z() / request.voxel)) + 1);
  const openvdb::FloatGrid::Ptr grid = sample(request, count);

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, /*isovalue*/ 0.0, /*adaptivity*/ 0.0);

  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const auto& p : points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  // OpenVDB's polygons turn counter-clockwise seen from the positive side
  // (outside), as TriangleMesh's do (checked by tests/mesh_test.cpp).
  const auto add = [&mesh](unsigned a, unsigned b, unsigned c) {
    mesh.triangles.push_back({std::int32_t(a), std::int32_t(b), std::int32_t(c)});
  };
  for (const auto& t : triangles) add(t[0], t[1], t[2]);
  for (const auto& q : quads) {
    add(q[0], q[1], q[2]);
    add(q[0], q[2], q[3]);
  }
  return mesh;
}

}  // namespace skelconv::detail
