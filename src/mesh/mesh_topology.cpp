// Implementation of skelconv/mesh/mesh_topology.hpp.
#include "skelconv/mesh/mesh_topology.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <utility>
#include <vector>

namespace skelconv {
namespace {

/// Union–find over 0..n−1 (path halving).
struct DisjointSets {
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
  std::vector<std::size_t> parent;
};

using Edge = std::pair<std::int32_t, std::int32_t>;  // (smaller, larger) vertex index

/// (edge, triangle) for every side of every triangle, sorted by edge, then
/// triangle. Placed by the edge's smaller vertex first (a counting sort: the
/// triangles come in order, so each vertex's uses do too), then each
/// vertex's few uses sorted by the larger: about linear in the triangles,
/// where one sort of all the uses is n log n (mesh summaries of 10⁵ and more
/// triangles run this on every `skelconv mesh`).
std::vector<std::pair<Edge, std::size_t>> sorted_edge_uses(const TriangleMesh& mesh) {
  const auto edge_of = [&mesh](std::size_t t, int k) {
    const std::int32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
    return Edge{std::min(a, b), std::max(a, b)};
  };
  std::int32_t largest = -1;
  for (const auto& t : mesh.triangles) largest = std::max({largest, t[0], t[1], t[2]});
  std::vector<std::size_t> start(std::size_t(largest) + 2, 0);  // uses of smaller vertex v: [start[v], start[v + 1])
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) ++start[std::size_t(edge_of(t, k).first) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<Edge, std::size_t>> uses(3 * mesh.triangles.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Edge edge = edge_of(t, k);
      uses[next[std::size_t(edge.first)]++] = {edge, t};
    }
  }
  for (std::size_t v = 0; v + 1 < start.size(); ++v) std::sort(uses.begin() + start[v], uses.begin() + start[v + 1]);
  return uses;
}

/// Over the vertices, the fans of triangles about each beyond its first (0
/// when the triangles around every vertex form one fan): the triangles at a
/// vertex joined through the edges at that vertex they share.
std::size_t extra_fans(const TriangleMesh& mesh, const std::vector<std::pair<Edge, std::size_t>>& uses) {
  if (mesh.triangles.empty()) return 0;
  DisjointSets corners(3 * mesh.triangles.size());  // corner (t, k) = 3t + k
  const auto corner_of = [&](std::size_t t, std::int32_t v) {
    const auto& tri = mesh.triangles[t];
    return 3 * t + std::size_t(std::find(tri.begin(), tri.end(), v) - tri.begin());
  };
  for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
    if (uses[i].first != uses[i + 1].first) continue;
    const auto [a, b] = uses[i].first;
    const std::size_t t = uses[i].second, u = uses[i + 1].second;
    corners.join(corner_of(t, a), corner_of(u, a));
    corners.join(corner_of(t, b), corner_of(u, b));
  }
  std::vector<std::size_t> fans_at(mesh.vertices.size(), 0);
  std::size_t extra = 0;
  for (std::size_t c = 0; c < 3 * mesh.triangles.size(); ++c) {
    if (corners.find(c) == c && ++fans_at[std::size_t(mesh.triangles[c / 3][c % 3])] > 1) ++extra;
  }
  return extra;
}

}  // namespace

MeshTopology mesh_topology(const TriangleMesh& mesh) {
  MeshTopology topology;
  topology.triangles = mesh.triangles.size();
  DisjointSets vertex_sets(mesh.vertices.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  bool repeated_vertex = false;
  for (const auto& t : mesh.triangles) {
    repeated_vertex |= t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
    for (int k = 0; k < 3; ++k) {
      used[std::size_t(t[k])] = true;
      vertex_sets.join(std::size_t(t[k]), std::size_t(t[(k + 1) % 3]));
    }
  }
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    ++topology.vertices;
    if (vertex_sets.find(v) == v) ++topology.components;
  }

  const auto uses = sorted_edge_uses(mesh);
  bool closed = true, at_most_two = true;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) ++j;
    ++topology.edges;
    closed &= j - i == 2;
    at_most_two &= j - i <= 2;
    i = j;
  }
  topology.euler_characteristic =
      (long long)topology.vertices - (long long)topology.edges + (long long)topology.triangles;
  topology.closed = closed && !mesh.triangles.empty();
  topology.pinches = extra_fans(mesh, uses);
  topology.manifold = at_most_two && !repeated_vertex && topology.pinches == 0;
  return topology;
}

long long topology_defects(const MeshTopology& reference, const MeshTopology& result) {
  const auto doubled_handles = [](const MeshTopology& t) {
    return 2 * (long long)t.components - t.euler_characteristic;
  };
  // The reference's readings: every pinch a neck (2·handles + pinches) down
  // to every pinch split (2·handles − pinches), in steps of 2.
  const long long pinches = (long long)reference.pinches, middle = doubled_handles(reference);
  const long long wanted = doubled_handles(result);
  long long nearest = std::clamp(wanted, middle - pinches, middle + pinches);
  if ((nearest - middle - pinches) % 2 != 0) nearest += nearest < wanted ? 1 : -1;
  return std::llabs((long long)result.components - (long long)reference.components) +
         std::llabs(wanted - nearest) / 2;
}

bool same_topology(const MeshTopology& reference, const MeshTopology& result) {
  // Exactly one of the readings (an odd χ off by one is not one of them).
  const long long pinches = (long long)reference.pinches;
  const long long off = result.euler_characteristic - reference.euler_characteristic;
  return result.components == reference.components && std::llabs(off) <= pinches && (off - pinches) % 2 == 0;
}

}  // namespace skelconv
