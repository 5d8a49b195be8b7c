// Implementation of skelconv/reconstruct/surface_samples.hpp.
#include "skelconv/reconstruct/surface_samples.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

namespace skelconv::reconstruct {
namespace {

using Edge = std::pair<std::int32_t, std::int32_t>;

bool proper(const std::array<std::int32_t, 3>& t) { return t[0] != t[1] && t[1] != t[2] && t[2] != t[0]; }

/// Undirected edges of the proper triangles, each once, in sorted order.
std::vector<Edge> unique_edges(const TriangleMesh& mesh) {
  std::set<Edge> edges;
  for (const auto& t : mesh.triangles) {
    if (!proper(t)) continue;
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  }
  return {edges.begin(), edges.end()};
}

double length(const TriangleMesh& mesh, const Edge& e) {
  return (mesh.vertices[std::size_t(e.first)] - mesh.vertices[std::size_t(e.second)]).norm();
}

double longest_edge(const TriangleMesh& mesh, const std::array<std::int32_t, 3>& t) {
  double longest = 0.0;
  for (int k = 0; k < 3; ++k) longest = std::max(longest, length(mesh, {t[k], t[(k + 1) % 3]}));
  return longest;
}

/// Steps of an edge or triangle of size `size` at spacing h (1: no point added).
std::size_t steps(double size, double h) { return std::size_t(std::max(1.0, std::ceil(size / h))); }

/// How many points spacing h adds (edge points, then interior grid points:
/// (n − 1)(n − 2)/2 for n steps).
std::size_t added_count(const TriangleMesh& mesh, const std::vector<Edge>& edges, double h) {
  std::size_t count = 0;
  for (const Edge& e : edges) count += steps(length(mesh, e), h) - 1;
  for (const auto& t : mesh.triangles) {
    if (!proper(t)) continue;
    const std::size_t n = steps(longest_edge(mesh, t), h);
    count += (n - 1) * (n - 2) / 2;  // 0 for n = 1 and 2
  }
  return count;
}

/// The spacing h (SamplingOptions): diagonal / divisions, doubled until
/// the samples fit the budget.
double spacing(const TriangleMesh& mesh, const std::vector<Edge>& edges, const SamplingOptions& o) {
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  double h = (hi - lo).norm() / o.diagonal_divisions;
  if (!(h > 0.0)) return INFINITY;  // every point in one place: nothing to spread
  while (mesh.vertices.size() + added_count(mesh, edges, h) > o.max_samples) h *= 2.0;
  return h;
}

}  // namespace

std::vector<Vec3> surface_samples(const TriangleMesh& mesh, const SamplingOptions& options) {
  std::vector<Vec3> samples = mesh.vertices;
  const std::vector<Edge> edges = unique_edges(mesh);
  if (edges.empty()) return samples;
  const double h = spacing(mesh, edges, options);
  for (const Edge& e : edges) {
    const std::size_t n = steps(length(mesh, e), h);
    const Vec3& a = mesh.vertices[std::size_t(e.first)];
    const Vec3& b = mesh.vertices[std::size_t(e.second)];
    for (std::size_t k = 1; k < n; ++k) samples.push_back(a + (b - a) * (double(k) / double(n)));
  }
  for (const auto& t : mesh.triangles) {
    if (!proper(t)) continue;
    const std::size_t n = steps(longest_edge(mesh, t), h);
    const Vec3& a = mesh.vertices[std::size_t(t[0])];
    const Vec3& b = mesh.vertices[std::size_t(t[1])];
    const Vec3& c = mesh.vertices[std::size_t(t[2])];
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t j = 1; i + j < n; ++j)
        samples.push_back((a * double(n - i - j) + b * double(i) + c * double(j)) / double(n));
  }
  return samples;
}

}  // namespace skelconv::reconstruct
