// Implementation of thin_walls.hpp.
#include "thin_walls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>

#include <Eigen/Eigenvalues>

#include "skelconv/reconstruct/surface_query.hpp"
#include "skelconv/reconstruct/surface_samples.hpp"
#include "union_find.hpp"

namespace skelconv::detail {
namespace {

using reconstruct::MedialGraph;
using Cell = std::array<std::int64_t, 3>;

/// Points (given by index) hashed into cubes of side `size`: the ones
/// within `size` of a point are in the 27 cubes round its own.
class Grid {
 public:
  Grid(const std::vector<Vec3>& points, const std::vector<std::int32_t>& which, double size)
      : points_(points), size_(size) {
    for (const std::int32_t i : which) cells_[cell(points[std::size_t(i)])].push_back(i);
  }

  /// Calls f(i) for each hashed point i within `radius` (≤ the cube's
  /// side) of p, cube by cube in a fixed order, until f returns true.
  template <class F>
  void within(const Vec3& p, double radius, F&& f) const {
    const Cell c = cell(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto at = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (at == cells_.end()) continue;
          for (const std::int32_t i : at->second)
            if ((points_[std::size_t(i)] - p).norm() <= radius && f(i)) return;
        }
  }

  Cell cell(const Vec3& p) const {
    return {std::int64_t(std::floor(p.x() / size_)), std::int64_t(std::floor(p.y() / size_)),
            std::int64_t(std::floor(p.z() / size_))};
  }

 private:
  const std::vector<Vec3>& points_;
  double size_;
  std::map<Cell, std::vector<std::int32_t>> cells_;
};

/// The moments of a set of points: count, sum, sum of outer products.
struct Moments {
  double count = 0.0;
  Vec3 sum = Vec3::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  void add(const Vec3& p) { count += 1.0, sum += p, outer += p * p.transpose(); }
  void add(const Moments& m) { count += m.count, sum += m.sum, outer += m.outer; }
  Vec3 mean() const { return sum / count; }
};

/// How points spread: the middle eigenvalue of their covariance (how far
/// they spread in a second direction, squared) and the direction they
/// spread least in (a sheet's normal).
struct Spread {
  double middle = 0.0;
  Vec3 normal = Vec3::UnitZ();
};

Spread spread(const Moments& m) {
  const Vec3 mean = m.mean();
  const Eigen::Matrix3d covariance = m.outer / m.count - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  return {eigen.eigenvalues()[1], eigen.eigenvectors().col(0)};
}

double median(std::vector<double> values) {
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

ThinWalls find_thin_walls(const TriangleMesh& surface, const MedialGraph& graph,
                          const reconstruct::SamplingOptions& sampling, double spacing, double thin_radius,
                          double max_refinement) {
  ThinWalls walls;
  const double h = spacing, reach = 4.0 * thin_radius * h;
  std::vector<Vec3> centres;
  std::vector<std::int32_t> thin;
  for (std::size_t i = 0; i < graph.vertices.size(); ++i) {
    centres.push_back(graph.vertices[i].centre);
    if (graph.vertices[i].radius < thin_radius * h) thin.push_back(std::int32_t(i));
  }
  walls.thin_vertices = thin.size();
  if (thin.empty()) return walls;
  // The thin vertices gathered in cubes of side R / 4, each cube decided as
  // a whole from the cubes round it: a vertex's own neighbourhood would
  // cost its thin neighbours each (thousands along a thin limb).
  const double side = reach / 4.0;
  const Grid cubes_of(centres, thin, side);
  std::map<Cell, std::vector<std::int32_t>> members;
  for (const std::int32_t i : thin) members[cubes_of.cell(centres[std::size_t(i)])].push_back(i);
  std::vector<Moments> moments;
  std::vector<Vec3> middles;
  std::vector<std::int32_t> cubes;
  for (const auto& [key, list] : members) {
    Moments m;
    for (const std::int32_t i : list) m.add(centres[std::size_t(i)]);
    cubes.push_back(std::int32_t(moments.size()));
    moments.push_back(m);
    middles.push_back(m.mean());
  }
  const Grid cube_grid(middles, cubes, reach);
  std::optional<reconstruct::SurfaceQuery> faces;
  std::vector<std::int32_t> wall_cubes;
  std::vector<double> half_thickness(cubes.size(), 0.0);
  for (const std::int32_t k : cubes) {
    const Vec3& c = middles[std::size_t(k)];
    Moments near;
    cube_grid.within(c, reach, [&](std::int32_t j) {
      near.add(moments[std::size_t(j)]);
      return false;
    });
    const Spread s = spread(near);
    if (s.middle < (reach / 4.0) * (reach / 4.0)) continue;
    // Both faces of the wall across its sheet, within twice the thickness
    // a thin wall may have: small-scale medial structure under a noisy
    // surface also spreads as a sheet, but has the shape's thick inside on
    // one side.
    if (!faces) faces.emplace(surface);
    const std::optional<double> up = faces->ray_distance(c, s.normal), down = faces->ray_distance(c, -s.normal);
    if (!up || !down || *up + *down >= 2.0 * (2.0 * thin_radius * h)) continue;
    wall_cubes.push_back(k);
    half_thickness[std::size_t(k)] = (*up + *down) / 2.0;
  }
  if (wall_cubes.empty()) return walls;
  // One wall: the wall cubes linked within R (across the holes of its
  // sheet), sampled at its median half-thickness across the sheet (a
  // ball's radius overstates it where the samples are as far apart as the
  // wall is thick).
  std::vector<std::int32_t> parent(cubes.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
  const Grid wall_cube_grid(middles, wall_cubes, reach);
  for (const std::int32_t k : wall_cubes)
    wall_cube_grid.within(middles[std::size_t(k)], reach, [&](std::int32_t j) {
      parent[std::size_t(find_root(parent, k))] = find_root(parent, j);
      return false;
    });
  std::map<std::int32_t, std::vector<double>> thickness;
  std::map<std::int32_t, Moments> extent;
  for (const std::int32_t k : wall_cubes) {
    const std::int32_t root = find_root(parent, k);
    thickness[root].push_back(half_thickness[std::size_t(k)]);
    extent[root].add(moments[std::size_t(k)]);
  }
  // A wall at least as wide as the disc that tells a sheet (its vertices
  // spread R / 2 both ways): a smaller patch of sheet-like cubes is a
  // local arrangement (where thin limbs meet, a flattened blob), not a
  // wall whose sheet the coarse samples break.
  std::map<std::int32_t, double> refinement;
  // And thinner than the spacing (half-thickness below h / 2): only then
  // are samples on its two faces closer than neighbours on one face, the
  // Delaunay cells that break its sheet. A thicker one (a ball's radius
  // under 0.75 h, as the coarse samples overstate it, but both faces more
  // than a spacing apart) keeps its sheet and is left as it is.
  for (const auto& [root, t] : thickness) {
    const double half = median(t);
    if (half >= h / 2.0 || spread(extent[root]).middle < (reach / 2.0) * (reach / 2.0)) continue;
    refinement[root] = std::min(h / half, max_refinement);
    ++walls.walls;
  }
  if (refinement.empty()) return walls;
  // The wall vertices, each with its wall's refinement.
  std::vector<std::int32_t> on_wall;
  std::vector<double> wall_refinement(graph.vertices.size(), 1.0);
  {
    std::size_t k = 0;
    for (const auto& [key, list] : members) {
      const auto wall = refinement.find(find_root(parent, std::int32_t(k)));
      if (half_thickness[k] > 0.0 && wall != refinement.end())
        for (const std::int32_t i : list) {
          on_wall.push_back(i);
          wall_refinement[std::size_t(i)] = wall->second;
        }
      ++k;
    }
  }
  std::sort(on_wall.begin(), on_wall.end());
  walls.wall_vertices = on_wall.size();
  const Grid wall_grid(centres, on_wall, reach);
  // Each sample near a wall's ball raises its triangles to that wall's
  // refinement: a vertex's, all the triangles round it.
  std::vector<std::vector<std::int32_t>> round_vertex(surface.vertices.size());
  for (std::size_t t = 0; t < surface.triangles.size(); ++t)
    for (const std::int32_t v : surface.triangles[t]) round_vertex[std::size_t(v)].push_back(std::int32_t(t));
  const std::vector<std::int32_t> on_triangle = reconstruct::sample_triangles(surface, sampling);
  std::vector<double> factor(surface.triangles.size(), 1.0);
  for (std::size_t s = 0; s < graph.samples.size() && s < on_triangle.size(); ++s) {
    double most = 1.0;
    wall_grid.within(graph.samples[s], reach, [&](std::int32_t j) {
      const auto& v = graph.vertices[std::size_t(j)];
      if ((graph.samples[s] - v.centre).norm() > v.radius + h) return false;
      most = wall_refinement[std::size_t(j)];
      return true;  // the first wall found
    });
    if (most <= 1.0) continue;
    if (s < surface.vertices.size())
      for (const std::int32_t t : round_vertex[s]) factor[std::size_t(t)] = std::max(factor[std::size_t(t)], most);
    else if (on_triangle[s] >= 0)
      factor[std::size_t(on_triangle[s])] = std::max(factor[std::size_t(on_triangle[s])], most);
  }
  for (const double f : factor)
    if (f > 1.0) ++walls.triangles, walls.finest = std::max(walls.finest, f);
  if (walls.triangles > 0) walls.triangle_refinement = std::move(factor);
  return walls;
}

}  // namespace skelconv::detail
