// Implementation of skelconv/reconstruct/medial_mesh.hpp.
#include "skelconv/reconstruct/medial_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <queue>
#include <set>
#include <utility>

#include "union_find.hpp"

namespace skelconv::reconstruct {
namespace {

using Index = std::int32_t;
using SphereEdge = std::array<Index, 2>;
using SphereTriangle = std::array<Index, 3>;

struct Neighbour {
  Index vertex;
  double length;  ///< in units of the local radius
};

std::vector<std::vector<Neighbour>> adjacency(const MedialGraph& graph, double radius_floor) {
  std::vector<std::vector<Neighbour>> next(graph.vertices.size());
  for (const MedialEdge& e : graph.edges) {
    const MedialVertex& a = graph.vertices[std::size_t(e.a)];
    const MedialVertex& b = graph.vertices[std::size_t(e.b)];
    const double unit = std::max(0.5 * (a.radius + b.radius), radius_floor);
    const double length = unit > 0.0 ? (a.centre - b.centre).norm() / unit : 0.0;
    next[std::size_t(e.a)].push_back({e.b, length});
    next[std::size_t(e.b)].push_back({e.a, length});
  }
  return next;
}

/// Geodesic Voronoi regions of the graph: the distance to the nearest seed
/// and its label, grown one seed at a time (Dijkstra from the new seed,
/// relaxing only where it is nearer than the seeds before it).
class Regions {
 public:
  explicit Regions(const std::vector<std::vector<Neighbour>>& next)
      : next_(next), distance_(next.size(), std::numeric_limits<double>::infinity()), label_(next.size(), -1) {}

  void add_seed(Index v) {
    const Index label = Index(seeds_.size());
    seeds_.push_back(v);
    using Item = std::pair<double, Index>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    distance_[std::size_t(v)] = 0.0;
    label_[std::size_t(v)] = label;
    queue.push({0.0, v});
    while (!queue.empty()) {
      const auto [d, u] = queue.top();
      queue.pop();
      if (d > distance_[std::size_t(u)]) continue;
      for (const Neighbour& n : next_[std::size_t(u)]) {
        const double through = d + n.length;
        if (through < distance_[std::size_t(n.vertex)]) {
          distance_[std::size_t(n.vertex)] = through;
          label_[std::size_t(n.vertex)] = label;
          queue.push({through, n.vertex});
        }
      }
    }
  }

  /// The vertex farthest from every seed (the lowest index among equals).
  Index farthest() const {
    return Index(std::max_element(distance_.begin(), distance_.end()) - distance_.begin());
  }
  double distance(Index v) const { return distance_[std::size_t(v)]; }
  Index label(Index v) const { return label_[std::size_t(v)]; }
  const std::vector<Index>& seeds() const { return seeds_; }

 private:
  const std::vector<std::vector<Neighbour>>& next_;
  std::vector<double> distance_;
  std::vector<Index> label_;
  std::vector<Index> seeds_;
};

/// Seeds by farthest-point sampling: first the largest ball of every
/// connected piece (a piece no seed reaches stays at infinite distance),
/// then the farthest vertex until all are within `spacing` or the budget
/// is spent.
Regions grow_regions(const MedialGraph& graph, const std::vector<std::vector<Neighbour>>& next,
                     const MedialMeshOptions& o) {
  Regions regions(next);
  while (regions.seeds().size() < o.max_spheres) {
    const Index far = regions.farthest();
    if (std::isinf(regions.distance(far))) {
      // An unreached piece: seed it at its largest ball (found by a walk).
      std::vector<Index> piece{far};
      std::vector<bool> seen(next.size(), false);
      seen[std::size_t(far)] = true;
      Index largest = far;
      for (std::size_t k = 0; k < piece.size(); ++k) {
        const Index u = piece[k];
        if (graph.vertices[std::size_t(u)].radius > graph.vertices[std::size_t(largest)].radius) largest = u;
        for (const Neighbour& n : next[std::size_t(u)])
          if (!seen[std::size_t(n.vertex)]) seen[std::size_t(n.vertex)] = true, piece.push_back(n.vertex);
      }
      regions.add_seed(largest);
    } else if (regions.distance(far) > o.spacing) {
      regions.add_seed(far);
    } else {
      break;
    }
  }
  return regions;
}

SphereEdge ordered(Index a, Index b) { return a < b ? SphereEdge{a, b} : SphereEdge{b, a}; }

/// Step 0: `graph` with every Voronoi vertex whose ball lies inside a
/// neighbour's, |c_v − c_u| + ρ_v ≤ (1 + slack) ρ_u, merged into that
/// neighbour (smallest balls first; the merged vertex's other neighbours
/// become the container's). Such a ball adds nothing to the shape, and a
/// chain of them is a spike the medial axis raises toward a sharp vertex
/// of a coarse mesh: where the spike leaves a sheet, its spheres would be
/// on triangles standing out of it (a tent), which the tube-spur rule does
/// not see. Merging collapses the spike into the sheet's ball it grows from.
MedialGraph without_contained_balls(const MedialGraph& graph, double slack) {
  const std::size_t n = graph.vertices.size();
  std::vector<std::set<Index>> next(n);
  for (const MedialEdge& e : graph.edges) {
    if (e.a == e.b) continue;
    next[std::size_t(e.a)].insert(e.b), next[std::size_t(e.b)].insert(e.a);
  }
  std::vector<Index> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = Index(i);
  std::stable_sort(order.begin(), order.end(), [&graph](Index a, Index b) {
    return graph.vertices[std::size_t(a)].radius < graph.vertices[std::size_t(b)].radius;
  });
  std::vector<bool> merged(n, false);
  for (const Index v : order) {
    const MedialVertex& ball = graph.vertices[std::size_t(v)];
    Index container = -1;
    for (const Index u : next[std::size_t(v)]) {
      const MedialVertex& other = graph.vertices[std::size_t(u)];
      if ((ball.centre - other.centre).norm() + ball.radius <= (1 + slack) * other.radius) {
        container = u;
        break;
      }
    }
    if (container < 0) continue;
    merged[std::size_t(v)] = true;
    for (const Index k : next[std::size_t(v)]) {
      next[std::size_t(k)].erase(v);
      if (k == container) continue;
      next[std::size_t(k)].insert(container), next[std::size_t(container)].insert(k);
    }
    next[std::size_t(v)].clear();
  }
  MedialGraph kept;
  kept.samples = graph.samples;
  std::vector<Index> number(n, -1);
  for (std::size_t v = 0; v < n; ++v)
    if (!merged[v]) number[v] = Index(kept.vertices.size()), kept.vertices.push_back(graph.vertices[v]);
  for (std::size_t v = 0; v < n; ++v)
    for (const Index u : next[v])
      if (Index(v) < u) kept.edges.push_back(MedialEdge{number[v], number[std::size_t(u)], {0, 0, 0}});
  return kept;
}

SphereTriangle ordered(Index a, Index b, Index c) {
  SphereTriangle t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

/// The smallest angle of the triangle of sphere centres, radians.
double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto angle = [](const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 u = q - p, v = r - p;
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

/// Step 3's candidate triangles with the number of Voronoi vertices that
/// witness each: three labels among a vertex and its neighbours, pairwise
/// joined by region edges.
std::map<SphereTriangle, int> candidate_triangles(const MedialGraph& graph, const std::vector<std::vector<Neighbour>>& next,
                                            const Regions& regions, const std::set<SphereEdge>& edges) {
  std::map<SphereTriangle, int> witnesses;
  std::vector<Index> labels;
  for (Index v = 0; v < Index(graph.vertices.size()); ++v) {
    labels.assign(1, regions.label(v));
    for (const Neighbour& n : next[std::size_t(v)]) labels.push_back(regions.label(n.vertex));
    std::erase(labels, Index(-1));  // a piece the budget left without a seed
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t j = i + 1; j < labels.size(); ++j)
        for (std::size_t k = j + 1; k < labels.size(); ++k) {
          const Index a = labels[i], b = labels[j], c = labels[k];
          if (edges.count({a, b}) && edges.count({b, c}) && edges.count({a, c})) ++witnesses[{a, b, c}];
        }
  }
  return witnesses;
}

/// Step 4: the candidates, most witnessed first, each accepted unless it is
/// a sliver, overloads an edge or closes a tetrahedron.
std::vector<SphereTriangle> accepted_triangles(const std::map<SphereTriangle, int>& witnesses, const std::vector<Vec4>& spheres,
                                         const MedialMeshOptions& o) {
  std::vector<std::pair<int, SphereTriangle>> order;
  for (const auto& [t, count] : witnesses) order.push_back({-count, t});
  std::sort(order.begin(), order.end());
  std::set<SphereTriangle> accepted;
  std::map<SphereEdge, std::size_t> per_edge;
  std::map<SphereEdge, std::vector<Index>> apex;  // the third vertices of an edge's accepted triangles
  const double min_angle = o.min_triangle_angle_degrees * std::numbers::pi / 180.0;
  std::vector<SphereTriangle> result;
  for (const auto& [count, t] : order) {
    const auto centre = [&spheres](Index i) -> Vec3 { return spheres[std::size_t(i)].head<3>(); };
    if (smallest_angle(centre(t[0]), centre(t[1]), centre(t[2])) < min_angle) continue;
    const std::array<SphereEdge, 3> sides{SphereEdge{t[0], t[1]}, SphereEdge{t[1], t[2]}, SphereEdge{t[0], t[2]}};
    bool refused = false;
    for (const SphereEdge& e : sides) refused = refused || per_edge[e] >= o.max_triangles_per_edge;
    // A tetrahedron t ∪ {d}: the three other faces through d all accepted.
    for (const Index d : apex[sides[0]]) {
      refused = refused || (accepted.count(ordered(t[1], t[2], d)) && accepted.count(ordered(t[0], t[2], d)));
    }
    if (refused) continue;
    accepted.insert(t);
    result.push_back(t);
    for (int k = 0; k < 3; ++k) {
      ++per_edge[sides[std::size_t(k)]];
      apex[sides[std::size_t(k)]].push_back(t[std::size_t((k + 2) % 3)]);
    }
  }
  std::sort(result.begin(), result.end());
  return result;
}

/// Step 6: removes tube spurs. A chain of tube edges from a tip (a sphere
/// on one edge, on no triangle) to where it attaches (a sphere on a sheet
/// or on three or more edges) is a spur when none of its balls reaches more
/// than `protrusion` × the attachment's radius beyond the attachment's
/// ball: the medial axis sends such a spike to every sharp vertex of a
/// coarse mesh, and a spike's primitives make a bump. A limb reaches far
/// beyond. Repeated until none is left (removing a spur can make a tip).
/// Returns the number of chains removed.
std::size_t remove_spurs(MedialMesh& mesh, double protrusion) {
  std::size_t removed = 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::vector<std::size_t>> at(mesh.spheres.size());  // edge indices per sphere
    std::vector<bool> on_sheet(mesh.spheres.size(), false);
    for (std::size_t k = 0; k < mesh.edges.size(); ++k)
      for (const Index i : mesh.edges[k]) at[std::size_t(i)].push_back(k);
    for (const SphereTriangle& t : mesh.triangles)
      for (const Index i : t) on_sheet[std::size_t(i)] = true;
    const auto attaches = [&](Index i) { return on_sheet[std::size_t(i)] || at[std::size_t(i)].size() >= 3; };
    std::vector<bool> drop(mesh.edges.size(), false);
    for (Index tip = 0; tip < Index(mesh.spheres.size()); ++tip) {
      if (at[std::size_t(tip)].size() != 1 || on_sheet[std::size_t(tip)]) continue;
      std::vector<std::size_t> chain;
      std::vector<Index> balls{tip};
      Index here = tip;
      std::size_t via = at[std::size_t(tip)][0];
      while (true) {
        chain.push_back(via);
        const Index next = mesh.edges[via][0] == here ? mesh.edges[via][1] : mesh.edges[via][0];
        here = next;
        if (attaches(here) || at[std::size_t(here)].size() != 2) break;
        balls.push_back(here);
        via = at[std::size_t(here)][0] == via ? at[std::size_t(here)][1] : at[std::size_t(here)][0];
      }
      if (!attaches(here)) continue;  // a free tube (two tips): not a spur
      const Vec4& base = mesh.spheres[std::size_t(here)];
      double reach = 0.0;
      for (const Index b : balls) {
        const Vec4& ball = mesh.spheres[std::size_t(b)];
        reach = std::max(reach, (ball.head<3>() - base.head<3>()).norm() + ball.w() - base.w());
      }
      if (reach > protrusion * base.w()) continue;
      for (const std::size_t k : chain) drop[k] = true;
      ++removed, changed = true;
    }
    std::vector<SphereEdge> kept;
    for (std::size_t k = 0; k < mesh.edges.size(); ++k)
      if (!drop[k]) kept.push_back(mesh.edges[k]);
    mesh.edges = std::move(kept);
  }
  return removed;
}

/// Step 7: joins the pieces of the medial mesh whose balls overlap. Pruning
/// can cut a thin neck (an ankle, a wrist) out of the graph, leaving a foot
/// whose balls overlap the leg's but no edge between them: the foot would
/// come back as a separate blob. Like Kruskal's algorithm: over the pairs
/// of spheres in different pieces, most overlapping first (|c_i − c_j| −
/// r_i − r_j most negative), an edge joins the two pieces. Pieces whose
/// balls do not overlap (two bodies) stay apart. Returns the edges added.
std::size_t join_overlapping_pieces(MedialMesh& mesh) {
  const Index n = Index(mesh.spheres.size());
  std::vector<Index> parent(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) parent[std::size_t(i)] = i;
  const auto unite = [&parent](Index a, Index b) { parent[std::size_t(detail::find_root(parent, a))] = detail::find_root(parent, b); };
  for (const SphereEdge& e : mesh.edges) unite(e[0], e[1]);
  for (const SphereTriangle& t : mesh.triangles) unite(t[0], t[1]), unite(t[1], t[2]);
  std::vector<std::pair<double, SphereEdge>> overlaps;
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j) {
      const Vec4 &a = mesh.spheres[std::size_t(i)], &b = mesh.spheres[std::size_t(j)];
      const double gap = (a.head<3>() - b.head<3>()).norm() - a.w() - b.w();
      if (gap < 0.0 && detail::find_root(parent, i) != detail::find_root(parent, j)) overlaps.push_back({gap, {i, j}});
    }
  std::sort(overlaps.begin(), overlaps.end());
  std::size_t added = 0;
  for (const auto& [gap, e] : overlaps) {
    if (detail::find_root(parent, e[0]) == detail::find_root(parent, e[1])) continue;
    unite(e[0], e[1]);
    mesh.edges.push_back(e);
    ++added;
  }
  if (added > 0) {
    std::vector<bool> joined(std::size_t(n), false);
    for (const SphereEdge& e : mesh.edges) joined[std::size_t(e[0])] = joined[std::size_t(e[1])] = true;
    std::erase_if(mesh.isolated, [&joined](Index i) { return joined[std::size_t(i)]; });
  }
  return added;
}

/// Drops the spheres no edge, triangle or isolated entry uses, renumbering
/// the rest in order.
void drop_unused_spheres(MedialMesh& mesh) {
  std::vector<Index> number(mesh.spheres.size(), -1);
  for (const SphereEdge& e : mesh.edges) number[std::size_t(e[0])] = number[std::size_t(e[1])] = 0;
  for (const SphereTriangle& t : mesh.triangles)
    for (const Index i : t) number[std::size_t(i)] = 0;
  for (const Index i : mesh.isolated) number[std::size_t(i)] = 0;
  std::vector<Vec4> spheres;
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i)
    if (number[i] == 0) number[i] = Index(spheres.size()), spheres.push_back(mesh.spheres[i]);
  mesh.spheres = std::move(spheres);
  for (SphereEdge& e : mesh.edges)
    for (Index& i : e) i = number[std::size_t(i)];
  for (SphereTriangle& t : mesh.triangles)
    for (Index& i : t) i = number[std::size_t(i)];
  for (Index& i : mesh.isolated) i = number[std::size_t(i)];
}

}  // namespace

MedialMesh simplify_medial_graph(const MedialGraph& input, const MedialMeshOptions& o) {
  MedialMesh mesh;
  if (input.vertices.empty() || o.max_spheres == 0) return mesh;
  const MedialGraph graph = o.contained_slack >= 0.0 ? without_contained_balls(input, o.contained_slack) : input;
  const std::vector<std::vector<Neighbour>> next = adjacency(graph, o.radius_floor);
  const Regions regions = grow_regions(graph, next, o);
  for (const Index seed : regions.seeds()) {
    const MedialVertex& v = graph.vertices[std::size_t(seed)];
    mesh.spheres.push_back(Vec4(v.centre.x(), v.centre.y(), v.centre.z(), v.radius));
  }
  std::set<SphereEdge> edges;
  for (const MedialEdge& e : graph.edges) {
    const Index a = regions.label(e.a), b = regions.label(e.b);
    if (a != b && a >= 0 && b >= 0) edges.insert(ordered(a, b));
  }
  const std::vector<SphereTriangle> triangles =
      accepted_triangles(candidate_triangles(graph, next, regions, edges), mesh.spheres, o);
  mesh.triangles = triangles;
  std::vector<bool> on_sheet(mesh.spheres.size(), false), joined(mesh.spheres.size(), false);
  std::set<SphereEdge> sheet_edges;
  for (const SphereTriangle& t : triangles) {
    for (const Index i : t) on_sheet[std::size_t(i)] = joined[std::size_t(i)] = true;
    sheet_edges.insert({t[0], t[1]}), sheet_edges.insert({t[1], t[2]}), sheet_edges.insert({t[0], t[2]});
  }
  for (const SphereEdge& e : edges) {
    if (sheet_edges.count(e) || (on_sheet[std::size_t(e[0])] && on_sheet[std::size_t(e[1])])) continue;
    mesh.edges.push_back(e);
    joined[std::size_t(e[0])] = joined[std::size_t(e[1])] = true;
  }
  for (Index i = 0; i < Index(mesh.spheres.size()); ++i)
    if (!joined[std::size_t(i)]) mesh.isolated.push_back(i);
  if (o.spur_protrusion > 0.0) remove_spurs(mesh, o.spur_protrusion);
  drop_unused_spheres(mesh);
  join_overlapping_pieces(mesh);
  return mesh;
}

}  // namespace skelconv::reconstruct
