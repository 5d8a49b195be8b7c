// Implementation of skelconv/reconstruct/ball_fit.hpp.
#include "skelconv/reconstruct/ball_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>

#include <Eigen/Dense>

#include "union_find.hpp"

namespace skelconv::reconstruct {
namespace {

/// R minimising the error for centre c: the weighted mean distance.
double best_radius(const std::vector<WeightedPoint>& points, const Vec3& c) {
  double sum = 0.0, weight = 0.0;
  for (const WeightedPoint& p : points) sum += p.weight * (p.point - c).norm(), weight += p.weight;
  return weight > 0.0 ? sum / weight : 0.0;
}

double error(const std::vector<WeightedPoint>& points, const Vec4& s) {
  double sum = 0.0;
  for (const WeightedPoint& p : points) {
    const double r = (p.point - s.head<3>()).norm() - s.w();
    sum += p.weight * r * r;
  }
  return sum;
}

/// The Gauss–Newton step of the residuals |p − c| − R in (c, R).
Vec4 gauss_newton_step(const std::vector<WeightedPoint>& points, const Vec4& s) {
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Vec4 rhs = Vec4::Zero();
  for (const WeightedPoint& p : points) {
    const Vec3 d = p.point - s.head<3>();
    const double distance = d.norm();
    if (!(distance > 0.0)) continue;  // a point at the centre has no direction
    Vec4 jacobian;
    jacobian << -d / distance, -1.0;
    normal += p.weight * jacobian * jacobian.transpose();
    rhs -= p.weight * (distance - s.w()) * jacobian;
  }
  return normal.ldlt().solve(rhs);
}

}  // namespace

namespace {

/// Appends the centroids of the n² sub-triangles of triangle t of `mesh`.
void append_points(const TriangleMesh& mesh, const std::array<std::int32_t, 3>& t, double h,
                   std::vector<WeightedPoint>& out) {
  const Vec3& a = mesh.vertices[std::size_t(t[0])];
  const Vec3& b = mesh.vertices[std::size_t(t[1])];
  const Vec3& c = mesh.vertices[std::size_t(t[2])];
  const double area = (b - a).cross(c - a).norm() / 2;
  if (!(area > 0.0)) return;
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  // At most 64² sub-triangles: the points only need to follow the area.
  const int n = h > 0.0 ? int(std::clamp(std::ceil(longest / h), 1.0, 64.0)) : 1;
  const double weight = area / double(n * n);
  // Barycentric grid of step 1/n: the upward sub-triangle at (i, j) has
  // its centroid at (i + 1/3, j + 1/3), the downward one at (i + 2/3, j + 2/3).
  const auto at = [&](double i, double j) { return (a * (n - i - j) + b * i + c * j) / double(n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      out.push_back({at(i + 1.0 / 3, j + 1.0 / 3), weight});
      if (i + j + 2 <= n) out.push_back({at(i + 2.0 / 3, j + 2.0 / 3), weight});
    }
}

/// The weighted centroid of `points`.
Vec3 centroid(const std::vector<WeightedPoint>& points) {
  Vec3 sum = Vec3::Zero();
  double weight = 0.0;
  for (const WeightedPoint& p : points) sum += p.weight * p.point, weight += p.weight;
  return weight > 0.0 ? Vec3(sum / weight) : sum;
}

}  // namespace

std::vector<WeightedPoint> area_weighted_points(const TriangleMesh& mesh, double h) {
  std::vector<WeightedPoint> out;
  for (const auto& t : mesh.triangles) append_points(mesh, t, h, out);
  return out;
}

namespace {

/// A cell of the merging grid and a group within it.
using CellKey = std::array<std::int64_t, 4>;

/// The cell of spacing h that holds p, group 0.
CellKey cell_of(const Vec3& p, double h) {
  return {std::int64_t(std::floor(p.x() / h)), std::int64_t(std::floor(p.y() / h)),
          std::int64_t(std::floor(p.z() / h)), 0};
}

/// `points` summed per key (`keys[k]` the key of `points[k]`): one entry
/// per key, in the order of each key's first point, at the weighted
/// centroid of its points with their total weight; `index[k]` the entry of
/// points[k].
std::vector<WeightedPoint> centroids_by_key(const std::vector<WeightedPoint>& points, const std::vector<CellKey>& keys,
                                            std::vector<std::size_t>& index) {
  std::map<CellKey, std::size_t> cell_index;
  std::vector<WeightedPoint> sums;  // weighted sums of the points, then centroids
  index.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const WeightedPoint& p = points[k];
    const auto [it, added] = cell_index.emplace(keys[k], sums.size());
    if (added) sums.push_back({Vec3::Zero(), 0.0});
    sums[it->second].point += p.weight * p.point;
    sums[it->second].weight += p.weight;
    index[k] = it->second;
  }
  for (WeightedPoint& s : sums)
    if (s.weight > 0.0) s.point /= s.weight;
  return sums;
}

/// For each entry of `centroids` (centroids_by_key), the point of its key
/// nearest to it (the first of equals).
std::vector<std::size_t> nearest_to_centroids(const std::vector<WeightedPoint>& points,
                                              const std::vector<WeightedPoint>& centroids,
                                              const std::vector<std::size_t>& index) {
  std::vector<double> nearest(centroids.size(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> chosen(centroids.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = index[k];
    const double d = (points[k].point - centroids[i].point).squaredNorm();
    if (d < nearest[i]) nearest[i] = d, chosen[i] = k;
  }
  return chosen;
}

/// `points` merged per key (`keys[k]` the key of `points[k]`), as
/// merged_in_cells describes: one point per key, in the order of each key's
/// first point.
std::vector<WeightedPoint> merged_by_key(const std::vector<WeightedPoint>& points, const std::vector<CellKey>& keys,
                                         bool on_surface) {
  std::vector<std::size_t> index;
  std::vector<WeightedPoint> sums = centroids_by_key(points, keys, index);
  if (on_surface) {
    const std::vector<std::size_t> chosen = nearest_to_centroids(points, sums, index);
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i].point = points[chosen[i]].point;
  }
  std::vector<WeightedPoint> merged;
  for (const WeightedPoint& s : sums)
    if (s.weight > 0.0) merged.push_back(s);
  return merged;
}

}  // namespace

std::vector<WeightedPoint> merged_in_cells(const std::vector<WeightedPoint>& points, double h, bool on_surface) {
  std::vector<CellKey> keys;
  keys.reserve(points.size());
  for (const WeightedPoint& p : points) keys.push_back(cell_of(p.point, h));
  return merged_by_key(points, keys, on_surface);
}

std::vector<std::size_t> nearest_in_cells(const std::vector<WeightedPoint>& points, double h) {
  std::vector<CellKey> keys;
  keys.reserve(points.size());
  for (const WeightedPoint& p : points) keys.push_back(cell_of(p.point, h));
  std::vector<std::size_t> index;
  const std::vector<WeightedPoint> centroids = centroids_by_key(points, keys, index);
  std::vector<std::size_t> chosen = nearest_to_centroids(points, centroids, index);
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

std::vector<WeightedPoint> surface_points_in_cells(const TriangleMesh& mesh, double h, double facing_angle,
                                                   double least_area) {
  // At π or more every point joins the cell's first group (a rounded cosine
  // of two opposite normals may fall just below −1).
  const double least_cosine =
      facing_angle >= std::numbers::pi ? -std::numeric_limits<double>::infinity() : std::cos(facing_angle);
  std::vector<WeightedPoint> points;
  std::vector<CellKey> keys;
  // Per cell, the unit normal of each group's first triangle.
  std::map<CellKey, std::vector<Vec3>> groups;
  for (const auto& t : mesh.triangles) {
    const std::size_t first = points.size();
    append_points(mesh, t, h, points);
    if (points.size() == first) continue;  // a triangle of no area
    const Vec3& a = mesh.vertices[std::size_t(t[0])];
    const Vec3 normal = (mesh.vertices[std::size_t(t[1])] - a).cross(mesh.vertices[std::size_t(t[2])] - a).normalized();
    for (std::size_t k = first; k < points.size(); ++k) {
      CellKey key = cell_of(points[k].point, h);
      std::vector<Vec3>& normals = groups[key];
      std::size_t group = 0;
      while (group < normals.size() && normals[group].dot(normal) < least_cosine) ++group;
      if (group == normals.size()) normals.push_back(normal);
      key[3] = std::int64_t(group);
      keys.push_back(key);
    }
  }
  // A group of less than least_area × h² (a face that only clips the cell,
  // or the side of a part thinner than the cell) joins its cell's largest
  // group; where every group is that small, the cell gives one point.
  if (least_area > 0.0) {
    std::map<CellKey, double> area;
    for (std::size_t k = 0; k < points.size(); ++k) area[keys[k]] += points[k].weight;
    // Per cell (its key with group 0), the key of its largest group: the
    // first of the largest, in the order of the keys.
    std::map<CellKey, CellKey> largest;
    for (const auto& [key, a] : area) {
      CellKey cell = key;
      cell[3] = 0;
      const auto [it, added] = largest.emplace(cell, key);
      if (!added && area.at(it->second) < a) it->second = key;
    }
    for (std::size_t k = 0; k < points.size(); ++k)
      if (area.at(keys[k]) < least_area * h * h) {
        CellKey cell = keys[k];
        cell[3] = 0;
        keys[k] = largest.at(cell);
      }
  }
  return merged_by_key(points, keys, true);
}

std::vector<Vec4> fit_component_spheres(const TriangleMesh& mesh, double h, double max_radius, std::size_t* flat) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[std::size_t(detail::find_root(parent, t[k]))] = detail::find_root(parent, t[0]);
  std::map<std::int32_t, std::size_t> component;  // root → index, in order of first triangle
  std::vector<std::vector<WeightedPoint>> points;
  for (const auto& t : mesh.triangles) {
    const auto [it, added] = component.emplace(detail::find_root(parent, t[0]), points.size());
    if (added) points.emplace_back();
    append_points(mesh, t, h, points[it->second]);
  }
  std::vector<Vec4> spheres;
  if (flat) *flat = 0;
  for (const auto& p : points) {
    if (p.empty()) continue;
    const Vec3 start = centroid(p);
    spheres.push_back(fit_sphere(p, start));
    if (!(spheres.back().w() <= max_radius)) {
      spheres.back() << start, best_radius(p, start);
      if (flat) ++*flat;
    }
  }
  return spheres;
}

Vec4 fit_sphere(const std::vector<WeightedPoint>& points, const Vec3& start, int iterations) {
  Vec4 sphere;
  sphere << start, best_radius(points, start);
  double current = error(points, sphere);
  for (int k = 0; k < iterations; ++k) {
    Vec4 step = gauss_newton_step(points, sphere);
    if (!step.allFinite()) break;
    double moved = -1.0;  // the accepted step's centre move; < 0: none accepted
    for (int halving = 0; halving < 30 && moved < 0.0; ++halving, step /= 2) {
      Vec4 next = sphere + step;
      next.w() = best_radius(points, next.head<3>());
      const double e = error(points, next);
      if (e < current) sphere = next, current = e, moved = step.head<3>().norm();
    }
    if (moved < 1e-12 * sphere.w()) break;
  }
  return sphere;
}

double first_order_rms(const Skeleton& skeleton, const std::vector<WeightedPoint>& points, double cap,
                       std::size_t max_points) {
  const std::size_t stride = std::max<std::size_t>(1, (points.size() + max_points - 1) / std::max<std::size_t>(1, max_points));
  double sum = 0.0, weight = 0.0;
  for (std::size_t k = 0; k < points.size(); k += stride) {
    const FieldSample s = skeleton.value_and_gradient(points[k].point);
    const double slope = s.gradient.norm();
    double d = slope > 0.0 ? std::abs(s.value - skeleton.iso()) / slope : cap;
    if (!(d < cap)) d = cap;  // also a NaN value or gradient
    sum += points[k].weight * d * d, weight += points[k].weight;
  }
  return weight > 0.0 ? std::sqrt(sum / weight) : cap;
}

}  // namespace skelconv::reconstruct
