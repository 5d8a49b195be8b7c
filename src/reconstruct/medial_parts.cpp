// Implementation of skelconv/reconstruct/medial_parts.hpp.
#include "skelconv/reconstruct/medial_parts.hpp"

#include <algorithm>
#include <map>

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

}  // namespace skelconv::reconstruct
