// Implementation of fill_cavities.hpp.
#include "fill_cavities.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

#include "union_find.hpp"

namespace skelconv::detail {

namespace {

/// A component of a closed mesh: its signed volume (negative for a wall
/// that faces into the volume it bounds), its vertices and their box, its
/// χ.
struct Component {
  Vec3 origin = Vec3::Zero();
  double volume = 0.0;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  std::vector<std::int32_t> vertices;
  std::size_t triangles = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  long long euler_characteristic() {
    std::sort(edges.begin(), edges.end());
    const auto distinct = std::unique(edges.begin(), edges.end()) - edges.begin();
    return (long long)vertices.size() - (long long)distinct + (long long)triangles;
  }
};

/// The components of `meshed` (triangles joined through their vertices),
/// in the order of their roots (the same mesh, the same components). The
/// signed volume by the divergence theorem, Σ (a − o) · ((b − o) × (c − o))
/// / 6 over the triangles, o a vertex of the component, so that a small
/// cavity far from the coordinates' origin does not sum large terms to a
/// small volume of the wrong sign.
std::vector<Component> components_of(const TriangleMesh& meshed) {
  std::vector<std::int32_t> parent(meshed.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&parent](std::int32_t v) { return find_root(parent, v); };
  for (const auto& t : meshed.triangles)
    for (int k = 1; k < 3; ++k)
      if (const std::int32_t a = find(t[0]), b = find(t[std::size_t(k)]); a != b)
        parent[std::size_t(std::max(a, b))] = std::min(a, b);
  std::vector<Component> components;
  std::vector<std::int32_t> index(meshed.vertices.size(), -1);
  for (const auto& t : meshed.triangles) {
    const std::size_t root = std::size_t(find(t[0]));
    if (index[root] < 0) {
      index[root] = std::int32_t(components.size());
      components.emplace_back().origin = meshed.vertices[std::size_t(t[0])];
    }
    Component& c = components[std::size_t(index[root])];
    const Vec3 a = meshed.vertices[std::size_t(t[0])] - c.origin;
    const Vec3 b = meshed.vertices[std::size_t(t[1])] - c.origin;
    const Vec3 d = meshed.vertices[std::size_t(t[2])] - c.origin;
    c.volume += a.dot(b.cross(d)) / 6.0;
    ++c.triangles;
    for (std::size_t k = 0; k < 3; ++k) c.edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  std::vector<bool> seen(meshed.vertices.size(), false);
  for (const auto& t : meshed.triangles)
    for (const std::int32_t v : t) {
      if (seen[std::size_t(v)]) continue;
      seen[std::size_t(v)] = true;
      Component& c = components[std::size_t(index[std::size_t(find(v))])];
      c.lo = c.lo.cwiseMin(meshed.vertices[std::size_t(v)]);
      c.hi = c.hi.cwiseMax(meshed.vertices[std::size_t(v)]);
      c.vertices.push_back(v);
    }
  return components;
}

}  // namespace

MeshTopology topology_after_fill(const TriangleMesh& meshed, const std::vector<Cavity>& cavities,
                                 reconstruct::GuardFilledCavities counted) {
  MeshTopology t = mesh_topology(meshed);
  if (counted == reconstruct::GuardFilledCavities::none) return t;
  for (const Cavity& c : cavities) {
    if (counted == reconstruct::GuardFilledCavities::air && !c.air) continue;
    --t.components;
    t.euler_characteristic -= c.euler_characteristic;
  }
  return t;
}

bool encloses_empty_space(const TriangleMesh& surface) {
  const std::vector<Component> components = components_of(surface);
  return components.size() > 1 &&
         std::any_of(components.begin(), components.end(), [](const Component& c) { return c.volume < 0.0; });
}

std::vector<Cavity> spurious_cavities(const TriangleMesh& meshed, const std::function<double(const Vec3&)>& depth,
                                      bool input_hollow, double margin, double sigma) {
  std::vector<Component> components = components_of(meshed);
  std::vector<Cavity> cavities;
  if (components.size() < 2) return cavities;  // a lone surface bounds no cavity
  // The distance from `centre` to the nearest vertex of the outer surface
  // (the components bounding a positive volume).
  const auto to_outer_surface = [&](const Vec3& centre) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Component& c : components)
      if (c.volume > 0.0)
        for (const std::int32_t v : c.vertices)
          nearest = std::min(nearest, (meshed.vertices[std::size_t(v)] - centre).norm());
    return nearest;
  };
  for (Component& c : components) {
    if (!(c.volume < 0.0)) continue;
    const Vec3 centre = 0.5 * (c.lo + c.hi);
    double radius = 0.0;
    for (const std::int32_t v : c.vertices)
      radius = std::max(radius, (meshed.vertices[std::size_t(v)] - centre).norm());
    // Inside the input the sphere's support stays within its depth, so the
    // surface near the input's does not move. Outside it, the surface about
    // a bubble is the seal the reconstruction put over a crease's mouth,
    // not the input's: the sphere's own surface (f = iso) stays within the
    // outer wall, and only its tail reaches beyond.
    const double inside = depth(centre);
    double largest = 0.0;
    if (inside > 0.0)
      largest = inside / sigma;
    else if (!input_hollow)
      largest = to_outer_surface(centre);
    if (!(largest > 0.0)) continue;
    cavities.push_back({{centre.x(), centre.y(), centre.z(), std::min(radius + margin, largest)},
                        c.euler_characteristic(), !(inside > 0.0)});
  }
  return cavities;
}

std::vector<reconstruct::Vec4> piece_bridges(const TriangleMesh& meshed, std::size_t components) {
  std::vector<Component> all = components_of(meshed);
  std::vector<std::size_t> outer;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].volume > 0.0) outer.push_back(i);
  std::vector<reconstruct::Vec4> bridges;
  if (outer.size() <= components) return bridges;
  // The smallest volume first; the largest, the body, is bridged to.
  std::stable_sort(outer.begin(), outer.end(),
                   [&all](std::size_t a, std::size_t b) { return all[a].volume < all[b].volume; });
  for (std::size_t k = 0; k + 1 < outer.size(); ++k) {
    const Component& piece = all[outer[k]];
    double nearest = std::numeric_limits<double>::infinity();
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    for (std::size_t j = 0; j < outer.size(); ++j) {
      if (j == k) continue;
      for (const std::int32_t u : piece.vertices)
        for (const std::int32_t v : all[outer[j]].vertices) {
          const double d = (meshed.vertices[std::size_t(u)] - meshed.vertices[std::size_t(v)]).norm();
          if (d < nearest) nearest = d, from = meshed.vertices[std::size_t(u)], to = meshed.vertices[std::size_t(v)];
        }
    }
    const Vec3 centre = 0.5 * (from + to);
    bridges.emplace_back(centre.x(), centre.y(), centre.z(), 0.5 * nearest);
  }
  return bridges;
}

std::size_t drop_smallest_primitives(reconstruct::MedialMesh& mesh, std::size_t count, double sigma) {
  std::size_t dropped = 0;
  for (; dropped < count; ++dropped) {
    std::vector<int> uses(mesh.spheres.size(), 0);
    for (const auto& e : mesh.edges)
      for (const std::int32_t v : e) ++uses[std::size_t(v)];
    for (const auto& t : mesh.triangles)
      for (const std::int32_t v : t) ++uses[std::size_t(v)];
    const auto centre = [&mesh](std::int32_t v) -> Vec3 { return mesh.spheres[std::size_t(v)].head<3>(); };
    const auto radius = [&mesh](std::int32_t v) { return mesh.spheres[std::size_t(v)].w(); };
    constexpr double pi = std::numbers::pi;
    // `which`: an edge's index, or edges.size() + a triangle's.
    double smallest = std::numeric_limits<double>::infinity();
    std::size_t which = mesh.edges.size() + mesh.triangles.size();
    for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
      const auto& e = mesh.edges[i];
      if (uses[std::size_t(e[0])] < 2 || uses[std::size_t(e[1])] < 2) continue;
      const double r = sigma * 0.5 * (radius(e[0]) + radius(e[1]));
      const double volume = pi * r * r * (centre(e[0]) - centre(e[1])).norm() + 4.0 / 3.0 * pi * r * r * r;
      if (volume < smallest) smallest = volume, which = i;
    }
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const auto& t = mesh.triangles[i];
      if (uses[std::size_t(t[0])] < 2 || uses[std::size_t(t[1])] < 2 || uses[std::size_t(t[2])] < 2) continue;
      const double r = sigma * (radius(t[0]) + radius(t[1]) + radius(t[2])) / 3.0;
      const Vec3 a = centre(t[0]), b = centre(t[1]), c = centre(t[2]);
      const double area = 0.5 * (b - a).cross(c - a).norm();
      const double perimeter = (b - a).norm() + (c - b).norm() + (a - c).norm();
      const double volume = 2.0 * r * area + 0.5 * pi * r * r * perimeter + 4.0 / 3.0 * pi * r * r * r;
      if (volume < smallest) smallest = volume, which = mesh.edges.size() + i;
    }
    if (which < mesh.edges.size()) {
      mesh.edges.erase(mesh.edges.begin() + std::ptrdiff_t(which));
    } else if (which < mesh.edges.size() + mesh.triangles.size()) {
      mesh.triangles.erase(mesh.triangles.begin() + std::ptrdiff_t(which - mesh.edges.size()));
    } else {
      break;
    }
  }
  return dropped;
}

}  // namespace skelconv::detail
