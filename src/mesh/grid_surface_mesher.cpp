// The grid method's OpenVDB part (OpenVDB 10), built as the module
// libskelconv_grid_mesher.so, which grid_mesher_loader.cpp opens on first
// use: linked into the command, OpenVDB's relocations cost every process
// ~46 ms at start-up (`skelconv eval` took 60 ms, 9 without it), whether
// it meshes or not. Its one exported symbol is skelconv_grid_surface_mesh.
#include "grid_surface_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <stdexcept>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

namespace skelconv::detail {
namespace {

/// Nodes per block side (OpenVDB's leaf size): the unit the support test skips.
constexpr int block = 8;

/// Whether no support box meets the world box of the nodes [first, last]
/// (node positions are monotone in the index, so they all lie in it).
bool outside_supports(const GridSurfaceRequest& request, const openvdb::Coord& first, const openvdb::Coord& last) {
  if (request.support_boxes == nullptr) return false;
  const auto node = [&request](const openvdb::Coord& c) {
    return Vec3(request.box.lo + request.voxel * Vec3(c.x(), c.y(), c.z()));
  };
  const Eigen::AlignedBox3d nodes(node(first), node(last));
  for (const Eigen::AlignedBox3d& support : *request.support_boxes)
    if (support.intersects(nodes)) return false;
  return true;
}

/// The level sampled on the grid nodes, as an OpenVDB float grid whose
/// index (i, j, k) is the world point box.lo + voxel (i, j, k), block by
/// block. Values are clamped to ±float max (an inverse kernel's skeleton
/// gives −inf).
openvdb::FloatGrid::Ptr sample(const GridSurfaceRequest& request, const openvdb::Coord& count) {
  const float limit = std::numeric_limits<float>::max();
  const auto stored = [limit](double level) { return float(std::clamp(level, -double(limit), double(limit))); };
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(/*background: outside*/ limit);
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(request.voxel);
  transform->postTranslate(openvdb::Vec3d(request.box.lo.x(), request.box.lo.y(), request.box.lo.z()));
  grid->setTransform(transform);
  auto accessor = grid->getAccessor();
  for (int bi = 0; bi < count.x(); bi += block) {
    for (int bj = 0; bj < count.y(); bj += block) {
      for (int bk = 0; bk < count.z(); bk += block) {
        const openvdb::Coord first(bi, bj, bk);
        const openvdb::Coord last(std::min(bi + block, count.x()) - 1, std::min(bj + block, count.y()) - 1,
                                  std::min(bk + block, count.z()) - 1);
        const bool empty = outside_supports(request, first, last);
        for (int i = first.x(); i <= last.x(); ++i) {
          for (int j = first.y(); j <= last.y(); ++j) {
            for (int k = first.z(); k <= last.z(); ++k) {
              const Vec3 p = request.box.lo + request.voxel * Vec3(i, j, k);
              accessor.setValue(openvdb::Coord(i, j, k), stored(empty ? request.empty_level : request.level(p)));
            }
          }
        }
      }
    }
  }
  return grid;
}

/// grid_surface_mesh (grid_surface_mesher.hpp), here under its own name: the
/// loader in the static library defines grid_surface_mesh itself.
TriangleMesh openvdb_surface_mesh(const GridSurfaceRequest& request) {
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

}  // namespace
}  // namespace skelconv::detail

/// The module's entry point, looked up by name (grid_mesher_loader.cpp).
extern "C" __attribute__((visibility("default"))) void skelconv_grid_surface_mesh(
    const skelconv::detail::GridSurfaceRequest* request, skelconv::TriangleMesh* mesh) {
  // OpenVDB's own exceptions (a grid transform it cannot build) leave the
  // module as std::runtime_error (the module does not link the runtime's
  // error types); grid_surface_mesh (grid_mesher_loader.cpp) words them for
  // the user.
  try {
    *mesh = skelconv::detail::openvdb_surface_mesh(*request);
  } catch (const openvdb::Exception& error) {
    throw std::runtime_error(error.what());
  }
}
