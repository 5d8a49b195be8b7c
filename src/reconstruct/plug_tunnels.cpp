// Implementation of plug_tunnels.hpp.
#include "plug_tunnels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Simple_cartesian.h>
#include <Eigen/Dense>

#include "union_find.hpp"

namespace skelconv::detail {

namespace {

using EdgeKey = std::uint64_t;

EdgeKey edge_key(std::int32_t a, std::int32_t b) {
  if (a > b) std::swap(a, b);
  return (EdgeKey(std::uint32_t(a)) << 32) | EdgeKey(std::uint32_t(b));
}

/// Components of the triangles of `mesh` that `kept` keeps (all where it is
/// empty), joined through shared vertices as mesh_topology counts them.
std::size_t component_count(const TriangleMesh& mesh, const std::vector<bool>& kept) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!kept.empty() && !kept[t]) continue;
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) used[std::size_t(tri[std::size_t(k)])] = true;
    for (int k = 1; k < 3; ++k)
      if (const std::int32_t a = find_root(parent, tri[0]), b = find_root(parent, tri[std::size_t(k)]); a != b)
        parent[std::size_t(std::max(a, b))] = std::min(a, b);
  }
  std::size_t count = 0;
  for (std::size_t v = 0; v < parent.size(); ++v) count += used[v] && find_root(parent, std::int32_t(v)) == std::int32_t(v);
  return count;
}

/// What the genus test needs of a closed mesh, computed once for the many
/// boxes it tries: each vertex's triangle count, each edge's, the
/// components.
class Indexed {
 public:
  explicit Indexed(const TriangleMesh& mesh) : mesh_(mesh), degree_(mesh.vertices.size(), 0) {
    for (const auto& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        ++degree_[std::size_t(t[std::size_t(k)])];
        edges_.push_back(edge_key(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]));
      }
    std::sort(edges_.begin(), edges_.end());
    components_ = component_count(mesh, {});
  }

  /// genus_drop_doubled of `removed`.
  long long drop_doubled(const std::vector<std::int32_t>& removed) const {
    // Taken out with the triangles: the vertices and edges none of whose
    // triangles stays. Left on the boundary: the edges some of whose do.
    std::map<std::int32_t, int> vertex_uses;
    std::map<EdgeKey, int> edge_uses;
    for (const std::int32_t t : removed) {
      const auto& tri = mesh_.triangles[std::size_t(t)];
      for (int k = 0; k < 3; ++k) {
        ++vertex_uses[tri[std::size_t(k)]];
        ++edge_uses[edge_key(tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)])];
      }
    }
    long long vertices_gone = 0, edges_gone = 0;
    for (const auto& [v, uses] : vertex_uses) vertices_gone += uses == degree_[std::size_t(v)];
    // The boundary loops: the components of the graph of boundary edges.
    std::map<std::int32_t, std::int32_t> parent;
    const auto find = [&parent](std::int32_t v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (const auto& [key, uses] : edge_uses) {
      const auto range = std::equal_range(edges_.begin(), edges_.end(), key);
      if (uses == range.second - range.first) {
        ++edges_gone;
        continue;
      }
      const auto a = std::int32_t(key >> 32), b = std::int32_t(key & 0xffffffffu);
      parent.emplace(a, a);
      parent.emplace(b, b);
      if (const std::int32_t ra = find(a), rb = find(b); ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
    long long loops = 0;
    for (const auto& [v, p] : parent) loops += find(v) == v;
    // χ' = χ − V_gone + E_gone − F_gone; each component of what is left
    // 2 − χ_i − b_i = 2 g_i, so 2 Σ g' = 2 c' − χ' − b and 2 Σ g = 2 c − χ.
    const long long local = edges_gone - vertices_gone - (long long)removed.size() + loops;
    if (local <= 0) return local;  // c' ≥ c: no drop
    std::vector<bool> kept(mesh_.triangles.size(), true);
    for (const std::int32_t t : removed) kept[std::size_t(t)] = false;
    const long long more = (long long)component_count(mesh_, kept) - (long long)components_;
    return local - 2 * more;
  }

 private:
  const TriangleMesh& mesh_;
  std::vector<int> degree_;
  std::vector<EdgeKey> edges_;
  std::size_t components_ = 0;
};

using Cell = std::array<std::int64_t, 3>;

}  // namespace

reconstruct::Vec4 smallest_ball(const std::vector<Vec3>& points) {
  if (points.empty()) return reconstruct::Vec4::Zero();
  // CGAL's solver in double precision with square roots: the ball is a
  // plug's size and place, not a predicate, so rounding is harmless. Its
  // random pivoting starts from a fixed seed, so the same points give the
  // same ball.
  using Kernel = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Min_sphere_of_points_d_traits_3<Kernel, double, CGAL::Tag_true>;
  std::vector<Kernel::Point_3> at;
  at.reserve(points.size());
  for (const Vec3& p : points) at.emplace_back(p.x(), p.y(), p.z());
  CGAL::Min_sphere_of_spheres_d<Traits> ball(at.begin(), at.end());  // its accessors are not const
  auto centre = ball.center_cartesian_begin();
  const double x = *centre++, y = *centre++, z = *centre;
  return {x, y, z, ball.radius()};
}

long long genus_drop_doubled(const TriangleMesh& mesh, const std::vector<std::int32_t>& removed) {
  return Indexed(mesh).drop_doubled(removed);
}

std::vector<reconstruct::Vec4> air_tunnel_plugs(const TriangleMesh& meshed, const TriangleMesh& input, double cell) {
  std::vector<reconstruct::Vec4> plugs;
  if (meshed.triangles.empty() || !(cell > 0.0)) return plugs;
  Vec3 lo = meshed.vertices[std::size_t(meshed.triangles[0][0])];
  for (const auto& t : meshed.triangles)
    for (int k = 0; k < 3; ++k) lo = lo.cwiseMin(meshed.vertices[std::size_t(t[std::size_t(k)])]);
  const auto cell_of = [&](const Vec3& p) {
    const Vec3 q = (p - lo) / cell;
    return Cell{std::int64_t(std::floor(q.x())), std::int64_t(std::floor(q.y())), std::int64_t(std::floor(q.z()))};
  };
  std::vector<std::pair<Cell, std::int32_t>> by_cell;
  by_cell.reserve(meshed.triangles.size());
  for (std::size_t t = 0; t < meshed.triangles.size(); ++t) {
    const auto& tri = meshed.triangles[t];
    const Vec3 centroid = (meshed.vertices[std::size_t(tri[0])] + meshed.vertices[std::size_t(tri[1])] +
                           meshed.vertices[std::size_t(tri[2])]) /
                          3.0;
    by_cell.emplace_back(cell_of(centroid), std::int32_t(t));
  }
  std::sort(by_cell.begin(), by_cell.end());
  std::set<Cell> blocks;
  for (std::size_t i = 0; i < by_cell.size(); ++i) {
    if (i > 0 && by_cell[i].first == by_cell[i - 1].first) continue;
    const Cell& c = by_cell[i].first;
    for (int d = 0; d < 8; ++d) blocks.insert(Cell{c[0] - (d & 1), c[1] - ((d >> 1) & 1), c[2] - ((d >> 2) & 1)});
  }
  const Indexed surface(meshed);
  std::optional<Indexed> solid;  // the input's, built at the first cut
  std::vector<std::pair<double, reconstruct::Vec4>> found;
  for (const Cell& block : blocks) {
    std::vector<std::int32_t> inside;
    for (int d = 0; d < 8; ++d) {
      const Cell c{block[0] + (d & 1), block[1] + ((d >> 1) & 1), block[2] + ((d >> 2) & 1)};
      const auto first = std::lower_bound(by_cell.begin(), by_cell.end(), std::make_pair(c, std::int32_t(0)));
      for (auto it = first; it != by_cell.end() && it->first == c; ++it) inside.push_back(it->second);
    }
    if (inside.size() < 3) continue;
    std::sort(inside.begin(), inside.end());
    // The pieces of the box's triangles, joined through shared edges.
    std::map<EdgeKey, std::int32_t> first_on_edge;
    std::vector<std::int32_t> parent(inside.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 0; i < inside.size(); ++i) {
      const auto& tri = meshed.triangles[std::size_t(inside[i])];
      for (int k = 0; k < 3; ++k) {
        const auto [at, fresh] =
            first_on_edge.emplace(edge_key(tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)]), std::int32_t(i));
        if (!fresh)
          if (const std::int32_t a = find_root(parent, at->second), b = find_root(parent, std::int32_t(i)); a != b)
            parent[std::size_t(std::max(a, b))] = std::min(a, b);
      }
    }
    std::map<std::int32_t, std::vector<std::int32_t>> pieces;
    for (std::size_t i = 0; i < inside.size(); ++i) pieces[find_root(parent, std::int32_t(i))].push_back(inside[i]);
    for (const auto& [root, piece] : pieces) {
      if (piece.size() < 3 || surface.drop_doubled(piece) <= 0) continue;
      std::vector<std::int32_t> corners;
      for (const std::int32_t t : piece)
        for (int k = 0; k < 3; ++k) corners.push_back(meshed.triangles[std::size_t(t)][std::size_t(k)]);
      std::sort(corners.begin(), corners.end());
      corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
      std::vector<Vec3> at;
      at.reserve(corners.size());
      for (const std::int32_t v : corners) at.push_back(meshed.vertices[std::size_t(v)]);
      const reconstruct::Vec4 plug = smallest_ball(at);
      const double radius = plug.w();
      // The input's own tunnel here: its triangles meeting the box grown by
      // a cell cut a handle of the input too.
      const Vec3 box_lo = lo + cell * Vec3(double(block[0]) - 1.0, double(block[1]) - 1.0, double(block[2]) - 1.0);
      const Vec3 box_hi = box_lo + Vec3::Constant(4.0 * cell);
      std::vector<std::int32_t> near;
      for (std::size_t t = 0; t < input.triangles.size(); ++t) {
        const auto& tri = input.triangles[t];
        Vec3 t_lo = input.vertices[std::size_t(tri[0])], t_hi = t_lo;
        for (int k = 1; k < 3; ++k) {
          t_lo = t_lo.cwiseMin(input.vertices[std::size_t(tri[std::size_t(k)])]);
          t_hi = t_hi.cwiseMax(input.vertices[std::size_t(tri[std::size_t(k)])]);
        }
        if ((t_lo.array() <= box_hi.array()).all() && (t_hi.array() >= box_lo.array()).all())
          near.push_back(std::int32_t(t));
      }
      if (!solid) solid.emplace(input);
      if (!near.empty() && solid->drop_doubled(near) > 0) continue;
      found.emplace_back(radius, plug);
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    return std::lexicographical_compare(a.second.data(), a.second.data() + 4, b.second.data(), b.second.data() + 4);
  });
  for (const auto& [radius, ball] : found) plugs.push_back(ball);
  return plugs;
}

}  // namespace skelconv::detail
