// Implementation of skelconv/reconstruct/medial_parts.hpp.
#include "skelconv/reconstruct/medial_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "union_find.hpp"

namespace skelconv::reconstruct {

std::vector<std::int32_t> triangle_parts(const TriangleMesh& surface) {
  std::vector<std::int32_t> parent(surface.vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
  for (const auto& t : surface.triangles)
    for (int k = 1; k < 3; ++k) parent[std::size_t(detail::find_root(parent, t[k]))] = detail::find_root(parent, t[0]);
  std::map<std::int32_t, std::int32_t> number;  // root -> part, in the order of first triangles
  std::vector<std::int32_t> parts(surface.triangles.size());
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const std::int32_t root = detail::find_root(parent, surface.triangles[t][0]);
    parts[t] = number.emplace(root, std::int32_t(number.size())).first->second;
  }
  return parts;
}

TriangleMesh surface_part(const TriangleMesh& surface, const std::vector<std::int32_t>& parts, std::int32_t part) {
  TriangleMesh out;
  std::vector<std::int32_t> renumbered(surface.vertices.size(), -1);
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    if (parts[t] != part) continue;
    std::array<std::int32_t, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = surface.triangles[t][std::size_t(k)];
      if (renumbered[std::size_t(v)] < 0) {
        renumbered[std::size_t(v)] = std::int32_t(out.vertices.size());
        out.vertices.push_back(surface.vertices[std::size_t(v)]);
        if (!surface.normals.empty()) out.normals.push_back(surface.normals[std::size_t(v)]);
      }
      triangle[std::size_t(k)] = renumbered[std::size_t(v)];
    }
    out.triangles.push_back(triangle);
  }
  return out;
}

std::size_t part_count(const MedialMesh& mesh) {
  if (mesh.parts.empty()) return 1;
  return std::size_t(*std::max_element(mesh.parts.begin(), mesh.parts.end())) + 1;
}

std::int32_t element_part(const MedialMesh& mesh, std::span<const std::int32_t> spheres) {
  if (mesh.parts.empty()) return 0;
  std::int32_t best = mesh.parts[std::size_t(spheres.front())];
  std::size_t most = 0;
  for (const std::int32_t s : spheres) {
    const std::int32_t p = mesh.parts[std::size_t(s)];
    const auto count = std::size_t(std::count_if(spheres.begin(), spheres.end(), [&](std::int32_t other) {
      return mesh.parts[std::size_t(other)] == p;
    }));
    if (count > most) best = p, most = count;
  }
  return best;
}

MedialMesh medial_mesh_part(const MedialMesh& mesh, std::int32_t part) {
  MedialMesh out;
  out.spheres = mesh.spheres;
  for (const auto& edge : mesh.edges)
    if (element_part(mesh, edge) == part) out.edges.push_back(edge);
  for (const auto& triangle : mesh.triangles)
    if (element_part(mesh, triangle) == part) out.triangles.push_back(triangle);
  for (const std::int32_t sphere : mesh.isolated)
    if (element_part(mesh, std::span<const std::int32_t>(&sphere, 1)) == part) out.isolated.push_back(sphere);
  return out;
}

std::vector<std::size_t> part_budgets(std::span<const double> weights, std::size_t budget, std::size_t minimum) {
  const std::size_t n = weights.size();
  if (n == 0) return {};
  const std::size_t floor_share = std::min(minimum, budget / n);
  std::vector<std::size_t> share(n, floor_share);
  const std::size_t rest = budget - floor_share * n;
  double total = 0.0;
  for (const double w : weights) total += std::max(w, 0.0);
  if (rest == 0 || !(total > 0.0)) return share;
  // What each part would get in proportion to its weight, less what the
  // minimum gave it already: the large parts share the rest.
  std::vector<double> want(n);
  double wanted = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    want[i] = std::max(0.0, double(budget) * std::max(weights[i], 0.0) / total - double(floor_share));
    wanted += want[i];
  }
  if (!(wanted > 0.0)) return share;
  std::vector<double> remainder(n);
  std::size_t given = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double exact = double(rest) * want[i] / wanted;
    const auto whole = std::size_t(std::floor(exact));
    share[i] += whole, given += whole;
    remainder[i] = exact - double(whole);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; k < n && given < rest; ++k) ++share[order[k]], ++given;
  return share;
}

std::vector<std::int32_t> vertex_parts(const MedialGraph& graph) {
  std::vector<std::int32_t> parts(graph.vertices.size(), 0);
  if (graph.sample_parts.empty()) return parts;
  for (std::size_t v = 0; v < parts.size(); ++v) {
    std::array<std::int32_t, 4> of;
    for (std::size_t k = 0; k < 4; ++k) of[k] = graph.sample_parts[std::size_t(graph.vertices[v].samples[k])];
    std::size_t most = 0;
    for (const std::int32_t p : of)
      if (const auto count = std::size_t(std::count(of.begin(), of.end(), p)); count > most) parts[v] = p, most = count;
  }
  return parts;
}

MedialGraph medial_graph_part(const MedialGraph& graph, const std::vector<std::int32_t>& parts, std::int32_t part) {
  MedialGraph out;
  out.samples = graph.samples;
  out.sample_parts = graph.sample_parts;
  std::vector<std::int32_t> number(graph.vertices.size(), -1);
  for (std::size_t v = 0; v < graph.vertices.size(); ++v)
    if (parts[v] == part) number[v] = std::int32_t(out.vertices.size()), out.vertices.push_back(graph.vertices[v]);
  for (const MedialEdge& e : graph.edges) {
    if (number[std::size_t(e.a)] < 0 || number[std::size_t(e.b)] < 0) continue;
    MedialEdge kept = e;
    kept.a = number[std::size_t(e.a)], kept.b = number[std::size_t(e.b)];
    out.edges.push_back(kept);
  }
  for (const auto& face : graph.faces) {
    std::vector<std::int32_t> kept;
    for (const std::int32_t v : face) {
      if (number[std::size_t(v)] < 0) break;
      kept.push_back(number[std::size_t(v)]);
    }
    if (kept.size() == face.size()) out.faces.push_back(std::move(kept));
  }
  return out;
}

MedialMesh joined_part_meshes(const std::vector<MedialMesh>& meshes) {
  MedialMesh out;
  for (std::size_t p = 0; p < meshes.size(); ++p) {
    const MedialMesh& m = meshes[p];
    const auto offset = std::int32_t(out.spheres.size());
    out.spheres.insert(out.spheres.end(), m.spheres.begin(), m.spheres.end());
    out.parts.insert(out.parts.end(), m.spheres.size(), std::int32_t(p));
    for (auto e : m.edges) {
      for (std::int32_t& i : e) i += offset;
      out.edges.push_back(e);
    }
    for (auto t : m.triangles) {
      for (std::int32_t& i : t) i += offset;
      out.triangles.push_back(t);
    }
    for (const std::int32_t i : m.isolated) out.isolated.push_back(i + offset);
  }
  return out;
}

}  // namespace skelconv::reconstruct
