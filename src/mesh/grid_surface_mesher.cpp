// The grid method's OpenVDB part (OpenVDB 10), built as the module
// libskelconv_grid_mesher.so, which grid_mesher_loader.cpp opens on first
// use: linked into the command, OpenVDB's relocations cost every process
// ~46 ms at start-up (`skelconv eval` took 60 ms, 9 without it), whether
// it meshes or not. Its one exported symbol is skelconv_grid_surface_mesh.
#include "grid_surface_mesher.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <stdexcept>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "../detail/parallel_for.hpp"

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

/// The world box of the cells around the nodes [first, last]: one voxel
/// beyond them on every side (a node is a corner of the cells on both sides).
Eigen::AlignedBox3d cells_around(const GridSurfaceRequest& request, const openvdb::Coord& first,
                                 const openvdb::Coord& last) {
  const auto node = [&request](const openvdb::Coord& c, int shift) {
    return Vec3(request.box.lo + request.voxel * Vec3(c.x() + shift, c.y() + shift, c.z() + shift));
  };
  return {node(first, -1), node(last, 1)};
}

/// Fills the level values of the nodes [first, last]: `constant` if given,
/// else level() at each.
template <class Accessor>
void fill_nodes(const GridSurfaceRequest& request, Accessor& accessor, const openvdb::Coord& first,
                const openvdb::Coord& last, const std::optional<float>& constant) {
  const float limit = std::numeric_limits<float>::max();
  const auto stored = [limit](double level) { return float(std::clamp(level, -double(limit), double(limit))); };
  for (int i = first.x(); i <= last.x(); ++i) {
    for (int j = first.y(); j <= last.y(); ++j) {
      for (int k = first.z(); k <= last.z(); ++k) {
        const Vec3 p = request.box.lo + request.voxel * Vec3(i, j, k);
        accessor.setValue(openvdb::Coord(i, j, k), constant ? *constant : stored(request.level(p)));
      }
    }
  }
}

/// The constant a block of nodes can hold instead of its samples: the
/// empty level outside every support, ±float max where sign_over proves
/// the sign on all the cells around it; none otherwise.
std::optional<float> block_constant(const GridSurfaceRequest& request, const openvdb::Coord& first,
                                    const openvdb::Coord& last) {
  if (outside_supports(request, first, last)) return float(request.empty_level);
  if (!request.sign_over) return std::nullopt;
  const int sign = request.sign_over(cells_around(request, first, last));
  if (sign == 0) return std::nullopt;
  return sign > 0 ? std::numeric_limits<float>::max() : -std::numeric_limits<float>::max();
}

/// Fills the nodes [first, last], a cube of `side` nodes (a power of two
/// times `block`) clipped to the grid: one constant for all of them if
/// block_constant allows it, else its eight octants, down to single blocks,
/// which are sampled. Large regions far from the surface are thus settled by
/// one test instead of one per block.
template <class Accessor>
void fill_region(const GridSurfaceRequest& request, Accessor& accessor, const openvdb::Coord& first,
                 const openvdb::Coord& count, int side) {
  const openvdb::Coord last(std::min(first.x() + side, count.x()) - 1, std::min(first.y() + side, count.y()) - 1,
                            std::min(first.z() + side, count.z()) - 1);
  const std::optional<float> constant = block_constant(request, first, last);
  if (constant || side == block) {
    fill_nodes(request, accessor, first, last, constant);
    return;
  }
  const int half = side / 2;
  for (int i = first.x(); i <= last.x(); i += half)
    for (int j = first.y(); j <= last.y(); j += half)
      for (int k = first.z(); k <= last.z(); k += half) fill_region(request, accessor, {i, j, k}, count, half);
}

/// An empty OpenVDB float grid, background +float max (outside). Its index
/// (i, j, k) stands for the world point box.lo + voxel (i, j, k), but its
/// transform is OpenVDB's identity: volumeToMesh then returns index-space
/// points, which openvdb_surface_mesh moves to the world in double. A world
/// transform made OpenVDB return world points in float (a surface 1e7 from
/// the origin came back on float's grid of 1, every vertex at the ball's
/// centre), and OpenVDB refused small voxels as a zero scale (8.2e-8, the
/// default spacing of a segment 1e-6 long).
openvdb::FloatGrid::Ptr empty_grid() {
  return openvdb::FloatGrid::create(/*background: outside*/ std::numeric_limits<float>::max());
}

/// The level sampled on the grid nodes, as an OpenVDB float grid (as
/// empty_grid). Values are clamped to ±float max (an inverse kernel's
/// skeleton gives −inf).
openvdb::FloatGrid::Ptr sample(const GridSurfaceRequest& request, const openvdb::Coord& count) {
  openvdb::FloatGrid::Ptr grid = empty_grid();
  auto accessor = grid->getAccessor();
  int side = block;
  while (side < std::max({count.x(), count.y(), count.z()})) side *= 2;
  fill_region(request, accessor, openvdb::Coord(0, 0, 0), count, side);
  return grid;
}

/// The sampling from seeds (GridSurfaceRequest::seeds): the crossing cells,
/// those whose corners change sign, found by continuation, with every
/// corner of each sampled; then the sign of every other node.
class SurfaceCells {
 public:
  SurfaceCells(const GridSurfaceRequest& request, openvdb::FloatGrid& grid, const openvdb::Coord& count)
      : request_(request), accessor_(grid.getAccessor()), count_(count) {}

  /// Samples the crossing cells reached from the cells around each seed.
  /// Seeds lie a fraction of a voxel apart on the same surface: a seed
  /// whose own cell the continuation from an earlier seed has already
  /// reached (sampled, crossing) adds nothing and is skipped, which spares
  /// sampling the 27 cells around each of thousands of seeds.
  ///
  /// The continuation goes in waves: the cells met for the first time from
  /// the previous wave's crossing cells, all sampled together (on several
  /// threads, sample_corners), then spread from in their order. The cells
  /// reached are the same as one cell at a time would reach, and every
  /// value is decided by the waves alone, never by the threads.
  void sample_from_seeds() {
    for (const Vec3& seed : request_.seeds) {
      const Vec3 at = (seed - request_.box.lo) / request_.voxel;
      const openvdb::Coord cell(int(std::floor(at.x())), int(std::floor(at.y())), int(std::floor(at.z())));
      if (reached(cell)) continue;
      // The seed's own cell may have corners of one sign (the surface dips
      // into it between them); then a neighbour's corners change sign.
      std::vector<openvdb::Coord> wave;
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k) meet(cell.offsetBy(i, j, k), wave);
      while (!wave.empty()) {
        const auto start = std::chrono::steady_clock::now();
        sample_corners(wave);
        // Helpers only where a wave's samples cost more than starting them:
        // on Zanni's ant (~1 µs an evaluation) the threads' starts cost more
        // CPU time than they saved. The values do not depend on it.
        parallel_ = std::chrono::steady_clock::now() - start >= parallel_wave_time;
        std::vector<openvdb::Coord> next;
        for (const openvdb::Coord& met : wave) spread_from(met, next);
        wave = std::move(next);
      }
    }
  }

  /// Gives every node not sampled the sign of the node below it (−z), the
  /// nodes on the box's bottom face outside (+float max, the background).
  /// Column by column, a block of nodes at a time: a block (an OpenVDB
  /// leaf's 8³ nodes) inside the grid that holds no sampled node, and that
  /// all its 8 × 8 columns enter inside, becomes one inactive tile of −float
  /// max instead of 512 stored nodes. volumeToMesh reads the same value at
  /// every node (a leaf of −float max or a tile of it: no sign change inside
  /// either, and the sampled leaves' neighbours are read by value), so the
  /// mesh is the same; a solid shape's interior then costs a tile per block
  /// instead of a leaf of 512 values (~2 KB, written page by page).
  void fill_signs() {
    const float limit = std::numeric_limits<float>::max();
    for (int bi = 0; bi < count_.x(); bi += block) {
      for (int bj = 0; bj < count_.y(); bj += block) {
        // inside[a][b]: the sign carried up column (bi + a, bj + b).
        std::array<std::array<bool, block>, block> inside{};
        const int ni = std::min(block, count_.x() - bi), nj = std::min(block, count_.y() - bj);
        for (int bk = 0; bk < count_.z(); bk += block) {
          const openvdb::Coord origin(bi, bj, bk);
          const bool whole = ni == block && nj == block && bk + block <= count_.z();
          const bool unsampled = accessor_.probeConstLeaf(origin) == nullptr;
          if (whole && unsampled && all_inside(inside)) {
            accessor_.addTile(/*level of a leaf-sized tile*/ 1, origin, -limit, /*active*/ false);
            continue;
          }
          // No sampled node and every column entering outside: every node
          // keeps the background (+float max), and the columns leave as
          // they came. Most of the box is such blocks.
          if (unsampled && none_inside(inside)) continue;
          const int nk = std::min(block, count_.z() - bk);
          for (int a = 0; a < ni; ++a) {
            for (int b = 0; b < nj; ++b) {
              bool& in = inside[a][b];
              for (int c = 0; c < nk; ++c) {
                const openvdb::Coord node(bi + a, bj + b, bk + c);
                float value;
                if (accessor_.probeValue(node, value)) {
                  in = value < 0;
                } else if (in) {
                  accessor_.setValue(node, -limit);
                }
              }
            }
          }
        }
      }
    }
  }

 private:
  /// The node of a cell's corner c (offsets (c & 1, c >> 1 & 1, c >> 2 & 1)).
  static openvdb::Coord corner(const openvdb::Coord& cell, int c) {
    return cell.offsetBy(c & 1, c >> 1 & 1, c >> 2 & 1);
  }

  /// The corner values of a cell met and sampled (sample_corners).
  std::array<float, 8> corners(const openvdb::Coord& cell) {
    std::array<float, 8> values;
    for (int c = 0; c < 8; ++c) accessor_.probeValue(corner(cell, c), values[c]);
    return values;
  }

  /// Samples the corners of a wave's cells that are not sampled yet. Each
  /// such node belongs to the first cell of the wave that has it as a
  /// corner, and is sampled with that cell's others: two or more through
  /// request.level_near around the cell's centre (what the corners share
  /// done once), one alone through request.level. The cells' samples are
  /// taken on request.threads threads, each into its own slot, and stored
  /// in the wave's order: the values, and the failure thrown (the first
  /// cell's), are one thread's.
  void sample_corners(const std::vector<openvdb::Coord>& wave) {
    struct Cell {
      openvdb::Coord cell;
      std::array<openvdb::Coord, 8> nodes{};
      std::array<float, 8> values{};
      int count = 0;
    };
    std::vector<Cell> cells;
    for (const openvdb::Coord& cell : wave) {
      Cell owned{.cell = cell, .nodes = {}, .values = {}, .count = 0};
      for (int c = 0; c < 8; ++c) {
        const openvdb::Coord node = corner(cell, c);
        if (accessor_.isValueOn(node)) continue;
        accessor_.setValueOn(node);  // claimed: a later cell of the wave leaves it to this one
        owned.nodes[owned.count++] = node;
      }
      if (owned.count > 0) cells.push_back(owned);
    }
    parallel_for(
        cells.size(),
        [&](std::size_t n) {
          Cell& owned = cells[n];
          std::function<double(const Vec3&)> near;
          if (owned.count >= 2 && request_.level_near) near = request_.level_near(centre(owned.cell), corner_reach * request_.voxel);
          const std::function<double(const Vec3&)>& level = near ? near : request_.level;
          for (int k = 0; k < owned.count; ++k) owned.values[k] = stored(level(node_point(owned.nodes[k])));
        },
        cells_per_block, parallel_ ? request_.threads : 1u);
    for (const Cell& owned : cells)
      for (int k = 0; k < owned.count; ++k) accessor_.setValue(owned.nodes[k], owned.values[k]);
  }

  Vec3 node_point(const openvdb::Coord& node) const {
    return request_.box.lo + request_.voxel * Vec3(node.x(), node.y(), node.z());
  }

  Vec3 centre(const openvdb::Coord& cell) const {
    return request_.box.lo + request_.voxel * (Vec3(cell.x(), cell.y(), cell.z()) + Vec3::Constant(0.5));
  }

  /// A level as the grid stores it: a float, ±float max at most (an
  /// inverse kernel's skeleton gives −inf).
  static float stored(double level) {
    const double limit = std::numeric_limits<float>::max();
    return float(std::clamp(level, -limit, limit));
  }

  /// Cells a thread takes at a time: a few hundred µs of evaluations on a
  /// crowded skeleton, and a wave of fewer cells stays on one thread.
  static constexpr std::size_t cells_per_block = 8;
  /// A wave that took this long on its threads has the next one sampled on
  /// request.threads threads, else on one (the first wave on all of them).
  static constexpr std::chrono::microseconds parallel_wave_time{1000};
  bool parallel_ = true;

  /// A cell's corners lie √3/2 voxel from its centre; a little more covers
  /// the rounding of their coordinates (a corner found outside would only
  /// be evaluated as usual).
  static constexpr double corner_reach = 0.8661;

  static bool all_inside(const std::array<std::array<bool, block>, block>& inside) {
    for (const auto& row : inside)
      for (bool in : row)
        if (!in) return false;
    return true;
  }

  static bool none_inside(const std::array<std::array<bool, block>, block>& inside) {
    for (const auto& row : inside)
      for (bool in : row)
        if (in) return false;
    return true;
  }

  static bool changes_sign(std::span<const float> values) {
    const bool first = values[0] < 0;
    return std::any_of(values.begin() + 1, values.end(), [first](float v) { return (v < 0) != first; });
  }

  /// Whether a cell was sampled and crosses the surface (then the
  /// continuation has spread from it).
  bool reached(const openvdb::Coord& cell) {
    return visited_.isValueOn(cell) && changes_sign(corners(cell));
  }

  /// Adds a cell to `wave` the first time it is met (inside the grid).
  void meet(const openvdb::Coord& cell, std::vector<openvdb::Coord>& wave) {
    if (cell.x() < 0 || cell.y() < 0 || cell.z() < 0 || cell.x() >= count_.x() - 1 || cell.y() >= count_.y() - 1 ||
        cell.z() >= count_.z() - 1)
      return;
    if (visited_.isValueOn(cell)) return;
    visited_.setValueOn(cell);
    wave.push_back(cell);
  }

  /// If a sampled cell crosses the surface, meets its neighbours across the
  /// faces whose four corners change sign, into `next`.
  void spread_from(const openvdb::Coord& cell, std::vector<openvdb::Coord>& next) {
    const std::array<float, 8> values = corners(cell);
    if (!changes_sign(values)) return;
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side <= 1; ++side) {
        std::array<float, 4> face;
        int n = 0;
        for (int c = 0; c < 8; ++c)
          if ((c >> axis & 1) == side) face[n++] = values[c];
        if (!changes_sign(face)) continue;
        openvdb::Coord neighbour = cell;
        neighbour[axis] += side == 1 ? 1 : -1;
        meet(neighbour, next);
      }
    }
  }

  const GridSurfaceRequest& request_;
  openvdb::FloatGrid::Accessor accessor_;
  openvdb::Coord count_;
  /// The cells met so far, one bit each in OpenVDB's blocks of 8³: no
  /// allocation per cell (a hash set's node), and each lookup near the last.
  openvdb::MaskTree visited_tree_;
  openvdb::tree::ValueAccessor<openvdb::MaskTree> visited_{visited_tree_};
};

/// The level on the crossing cells reached from the seeds, every other node
/// ±float max by its sign (SurfaceCells).
openvdb::FloatGrid::Ptr sample_surface_cells(const GridSurfaceRequest& request, const openvdb::Coord& count) {
  openvdb::FloatGrid::Ptr grid = empty_grid();
  SurfaceCells cells(request, *grid, count);
  cells.sample_from_seeds();
  cells.fill_signs();
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
  const openvdb::FloatGrid::Ptr grid = request.seeds.empty() ? sample(request, count) : sample_surface_cells(request, count);

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, /*isovalue*/ 0.0, /*adaptivity*/ 0.0);

  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const auto& p : points) mesh.vertices.push_back(request.box.lo + request.voxel * Vec3(p.x(), p.y(), p.z()));
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
