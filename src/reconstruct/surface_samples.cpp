// Implementation of skelconv/reconstruct/surface_samples.hpp.
#include "skelconv/reconstruct/surface_samples.hpp"

#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/reconstruct/ball_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>

namespace skelconv::reconstruct {
namespace {

using Edge = std::pair<std::int32_t, std::int32_t>;

bool proper(const std::array<std::int32_t, 3>& t) { return t[0] != t[1] && t[1] != t[2] && t[2] != t[0]; }

/// How much finer than h triangle t is sampled (SamplingOptions::triangle_refinement).
double refinement(const SamplingOptions& o, std::size_t t) {
  return o.triangle_refinement.empty() ? 1.0 : std::max(1.0, o.triangle_refinement[t]);
}

/// An undirected edge of the proper triangles, the first triangle on it
/// and the larger refinement of its triangles.
struct EdgeUse {
  Edge edge;
  std::int32_t triangle = 0;
  double refinement = 1.0;
};

/// Each undirected edge of the proper triangles once, in sorted order.
std::vector<EdgeUse> unique_edges(const TriangleMesh& mesh, const SamplingOptions& o) {
  std::map<Edge, EdgeUse> edges;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (!proper(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const Edge e = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [at, added] = edges.try_emplace(e, EdgeUse{e, std::int32_t(i), refinement(o, i)});
      if (!added) at->second.refinement = std::max(at->second.refinement, refinement(o, i));
    }
  }
  std::vector<EdgeUse> list;
  list.reserve(edges.size());
  for (const auto& entry : edges) list.push_back(entry.second);
  return list;
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
std::size_t added_count(const TriangleMesh& mesh, const std::vector<EdgeUse>& edges, double h,
                        const SamplingOptions& o) {
  std::size_t count = 0;
  for (const EdgeUse& e : edges) count += steps(length(mesh, e.edge), h / e.refinement) - 1;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (!proper(t)) continue;
    const std::size_t n = steps(longest_edge(mesh, t), h / refinement(o, i));
    count += (n - 1) * (n - 2) / 2;  // 0 for n = 1 and 2
  }
  return count;
}

/// The spacing h (SamplingOptions): diagonal / divisions, doubled until
/// the samples (`vertices` of the mesh's and the added points) fit the
/// budget, or until no point is added.
double spacing(const TriangleMesh& mesh, std::size_t vertices, const std::vector<EdgeUse>& edges,
               const SamplingOptions& o) {
  double h = bounding_box(mesh.vertices).diagonal() / o.diagonal_divisions;
  if (!(h > 0.0)) return INFINITY;  // every point in one place: nothing to spread
  for (std::size_t added = added_count(mesh, edges, h, o); vertices + added > o.max_samples && added > 0;
       added = added_count(mesh, edges, h, o))
    h *= 2.0;
  return h;
}

/// Calls add(point, triangle) for each added sample, in the order of
/// surface_samples.
template <class Add>
void for_each_added_sample(const TriangleMesh& mesh, std::size_t vertices, const SamplingOptions& options, Add&& add) {
  if (!options.triangle_refinement.empty() && options.triangle_refinement.size() != mesh.triangles.size())
    throw std::invalid_argument("surface_samples: triangle_refinement needs one factor per triangle");
  const std::vector<EdgeUse> edges = unique_edges(mesh, options);
  if (edges.empty()) return;
  const double h = spacing(mesh, vertices, edges, options);
  for (const EdgeUse& e : edges) {
    const std::size_t n = steps(length(mesh, e.edge), h / e.refinement);
    const Vec3& a = mesh.vertices[std::size_t(e.edge.first)];
    const Vec3& b = mesh.vertices[std::size_t(e.edge.second)];
    for (std::size_t k = 1; k < n; ++k) add(a + (b - a) * (double(k) / double(n)), e.triangle);
  }
  for (std::size_t ti = 0; ti < mesh.triangles.size(); ++ti) {
    const auto& t = mesh.triangles[ti];
    if (!proper(t)) continue;
    const std::size_t n = steps(longest_edge(mesh, t), h / refinement(options, ti));
    const Vec3& a = mesh.vertices[std::size_t(t[0])];
    const Vec3& b = mesh.vertices[std::size_t(t[1])];
    const Vec3& c = mesh.vertices[std::size_t(t[2])];
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t j = 1; i + j < n; ++j)
        add((a * double(n - i - j) + b * double(i) + c * double(j)) / double(n), std::int32_t(ti));
  }
}

}  // namespace

std::vector<std::int32_t> sample_vertices(const TriangleMesh& mesh, const SamplingOptions& options) {
  std::vector<std::int32_t> all(mesh.vertices.size());
  for (std::size_t v = 0; v < all.size(); ++v) all[v] = std::int32_t(v);
  if (mesh.vertices.empty() || mesh.vertices.size() <= options.thin_vertices_above ||
      !(options.vertex_cell_divisions > 0.0))
    return all;
  const double cell = bounding_box(mesh.vertices).diagonal() / options.vertex_cell_divisions;
  if (!(cell > 0.0)) return all;
  std::vector<WeightedPoint> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.push_back({v, 1.0});
  const std::vector<std::size_t> kept = nearest_in_cells(points, cell);
  if (double(mesh.vertices.size()) <= options.vertex_crowding * double(kept.size())) return all;
  return {kept.begin(), kept.end()};
}

std::vector<Vec3> surface_samples(const TriangleMesh& mesh, const SamplingOptions& options) {
  std::vector<Vec3> samples;
  for (const std::int32_t v : sample_vertices(mesh, options)) samples.push_back(mesh.vertices[std::size_t(v)]);
  for_each_added_sample(mesh, samples.size(), options, [&samples](const Vec3& p, std::int32_t) { samples.push_back(p); });
  return samples;
}

std::vector<std::int32_t> sample_triangles(const TriangleMesh& mesh, const SamplingOptions& options) {
  std::vector<std::int32_t> first(mesh.vertices.size(), -1);
  for (std::size_t i = mesh.triangles.size(); i-- > 0;)
    for (const std::int32_t v : mesh.triangles[i]) first[std::size_t(v)] = std::int32_t(i);
  std::vector<std::int32_t> triangles;
  for (const std::int32_t v : sample_vertices(mesh, options)) triangles.push_back(first[std::size_t(v)]);
  for_each_added_sample(mesh, triangles.size(), options,
                        [&triangles](const Vec3&, std::int32_t t) { triangles.push_back(t); });
  return triangles;
}

}  // namespace skelconv::reconstruct
