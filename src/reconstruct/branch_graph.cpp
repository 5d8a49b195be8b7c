// Implementation of skelconv/reconstruct/branch_graph.hpp.
#include "skelconv/reconstruct/branch_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <queue>
#include <set>

#include <Eigen/Dense>

#include "skelconv/errors.hpp"
#include "union_find.hpp"

namespace skelconv::reconstruct {
namespace {

using Adjacency = std::vector<std::vector<std::pair<std::int32_t, double>>>;

Adjacency medial_adjacency(const MedialGraph& graph) {
  Adjacency adjacency(graph.vertices.size());
  for (const MedialEdge& e : graph.edges) {
    const double length = (graph.vertices[e.a].centre - graph.vertices[e.b].centre).norm();
    adjacency[e.a].push_back({e.b, length});
    adjacency[e.b].push_back({e.a, length});
  }
  return adjacency;
}

/// Graph distances from `source` (infinity where unreachable).
std::vector<double> dijkstra(const Adjacency& adjacency, std::int32_t source) {
  std::vector<double> distance(adjacency.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  distance[source] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    for (const auto& [w, length] : adjacency[v]) {
      if (d + length < distance[w]) distance[w] = d + length, queue.push({d + length, w});
    }
  }
  return distance;
}

/// Distances from an extremity of every connected piece: for each piece not
/// reached yet, Dijkstra from its first vertex, then again from the vertex of
/// the piece farthest from it among those whose ball is at least the median
/// (`minimum_radius`): an extremity of the axis, not the tip of a thin sheet
/// of small balls beside it, whose level sets would cut the tube obliquely.
std::vector<double> distances_from_extremities(const Adjacency& adjacency, const MedialGraph& graph,
                                               double minimum_radius) {
  std::vector<double> result(adjacency.size(), std::numeric_limits<double>::infinity());
  for (std::size_t start = 0; start < adjacency.size(); ++start) {
    if (std::isfinite(result[start])) continue;
    const std::vector<double> first = dijkstra(adjacency, std::int32_t(start));
    std::int32_t root = std::int32_t(start);
    for (std::size_t v = 0; v < first.size(); ++v) {
      if (std::isfinite(first[v]) && first[v] > first[root] && graph.vertices[v].radius >= minimum_radius)
        root = std::int32_t(v);
    }
    const std::vector<double> second = dijkstra(adjacency, root);
    for (std::size_t v = 0; v < second.size(); ++v) {
      if (std::isfinite(second[v])) result[v] = second[v];
    }
  }
  return result;
}

using detail::find_root;

/// Node (x, y, z, r) of a bin piece: mean centre and radius of its core balls.
Vec4 piece_node(const MedialGraph& graph, const std::vector<std::int32_t>& members, double core_fraction) {
  double largest = 0.0;
  for (std::int32_t v : members) largest = std::max(largest, graph.vertices[v].radius);
  Vec4 sum = Vec4::Zero();
  int count = 0;
  for (std::int32_t v : members) {
    const MedialVertex& m = graph.vertices[v];
    if (m.radius < core_fraction * largest) continue;
    sum += Vec4(m.centre.x(), m.centre.y(), m.centre.z(), m.radius);
    ++count;
  }
  return sum / count;
}

/// Node degrees and, per node, its incident neighbours in edge order.
std::vector<std::vector<std::int32_t>> neighbours(const CurveSkeleton& skeleton) {
  std::vector<std::vector<std::int32_t>> result(skeleton.nodes.size());
  for (const auto& [a, b] : skeleton.edges) result[a].push_back(b), result[b].push_back(a);
  return result;
}

/// The union-find pieces as lists of vertices, numbered by their first
/// vertex (deterministic).
std::vector<std::vector<std::int32_t>> bin_pieces(const MedialGraph& graph, std::vector<std::int32_t>& parent) {
  std::map<std::int32_t, std::int32_t> piece_of_root;
  std::vector<std::vector<std::int32_t>> members;
  for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
    const auto [it, added] = piece_of_root.emplace(find_root(parent, std::int32_t(v)), std::int32_t(members.size()));
    if (added) members.emplace_back();
    members[it->second].push_back(std::int32_t(v));
  }
  return members;
}

/// True when the node balls of two pieces overlap (centre distance < sum of
/// radii).
bool balls_overlap(const Vec4& a, const Vec4& b) { return (a.head<3>() - b.head<3>()).norm() < a.w() + b.w(); }

/// Merges, within one bin, the pieces listed in `bin_pieces` (indices into
/// `members`, in order) until no two node balls overlap; merged-away pieces
/// are marked in `gone`. The pair merged is always the first overlapping
/// one in (i, j) order, j into i. After a merge only piece i's node has
/// changed and every pair before (i, j) was apart, so the next first pair is
/// (a, i) for the first a < i that now overlaps i (i then merges into a and
/// the same holds for a), else the next j after i: each merge costs O(k),
/// not a rescan of all k² pairs (a noisy tree has bins of hundreds of
/// pieces; the rescan took minutes).
void merge_within_bin(const MedialGraph& graph, double core_fraction, std::vector<std::size_t> bin_pieces,
                      std::vector<std::vector<std::int32_t>>& members, std::vector<bool>& gone) {
  std::vector<Vec4> node;
  for (std::size_t k : bin_pieces) node.push_back(piece_node(graph, members[k], core_fraction));
  const auto merge = [&](std::size_t into, std::size_t from) {
    auto& target = members[bin_pieces[into]];
    const auto& source = members[bin_pieces[from]];
    target.insert(target.end(), source.begin(), source.end());
    gone[bin_pieces[from]] = true;
    bin_pieces.erase(bin_pieces.begin() + std::ptrdiff_t(from));
    node.erase(node.begin() + std::ptrdiff_t(from));
    node[into] = piece_node(graph, target, core_fraction);
  };
  for (std::size_t i = 0; i < bin_pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < bin_pieces.size();) {
      if (!balls_overlap(node[i], node[j])) {
        ++j;
        continue;
      }
      merge(i, j);
      // Piece i changed: the first earlier piece it now overlaps takes it.
      for (std::size_t a = 0; a < i;) {
        if (!balls_overlap(node[a], node[i])) {
          ++a;
          continue;
        }
        merge(a, i);
        i = a, a = 0;
      }
      j = i + 1;
    }
  }
}

/// Merges pieces of the same bin whose node balls overlap: a tube sampled
/// coarsely can split a level set into pieces side by side, which would make
/// small cycles ("bubbles") in the curve skeleton; pieces of different
/// branches are farther apart. Bins are independent (a node depends only
/// on its piece), so each is merged on its own; the order of `members` is
/// kept.
template <class Bin>
void merge_overlapping_pieces(const MedialGraph& graph, double core_fraction, const Bin& bin,
                              std::vector<std::vector<std::int32_t>>& members) {
  std::map<std::int64_t, std::vector<std::size_t>> by_bin;
  for (std::size_t k = 0; k < members.size(); ++k) by_bin[bin(members[k][0])].push_back(k);
  std::vector<bool> gone(members.size(), false);
  for (const auto& [b, pieces] : by_bin) merge_within_bin(graph, core_fraction, pieces, members, gone);
  std::vector<std::vector<std::int32_t>> kept;
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (!gone[k]) kept.push_back(std::move(members[k]));
  }
  members = std::move(kept);
}

}  // namespace

double polyline_length(const std::vector<Vec4>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) length += (points[k].head<3>() - points[k - 1].head<3>()).norm();
  return length;
}

CurveSkeleton level_set_skeleton(const MedialGraph& graph, const LevelSetOptions& options) {
  if (!(options.bin_width > 0.0)) throw InputError("must be > 0", "bin_width");
  if (!(options.core_fraction > 0.0 && options.core_fraction <= 1.0)) throw InputError("must be in (0, 1]", "core_fraction");
  const Adjacency adjacency = medial_adjacency(graph);
  std::vector<double> radii;
  for (const MedialVertex& v : graph.vertices) radii.push_back(v.radius);
  std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
  const std::vector<double> distance = distances_from_extremities(adjacency, graph, radii[radii.size() / 2]);
  const auto bin = [&](std::int32_t v) { return std::int64_t(std::floor(distance[v] / options.bin_width)); };

  std::vector<std::int32_t> parent(graph.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const MedialEdge& e : graph.edges) {
    if (bin(e.a) == bin(e.b)) parent[find_root(parent, e.a)] = find_root(parent, e.b);
  }
  std::vector<std::vector<std::int32_t>> members = bin_pieces(graph, parent);
  merge_overlapping_pieces(graph, options.core_fraction, bin, members);
  std::vector<std::int32_t> piece(graph.vertices.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    for (std::int32_t v : members[k]) piece[v] = std::int32_t(k);
  }
  CurveSkeleton skeleton;
  for (const auto& m : members) skeleton.nodes.push_back(piece_node(graph, m, options.core_fraction));
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (const MedialEdge& e : graph.edges) {
    const std::int32_t a = piece[e.a], b = piece[e.b];
    if (a != b) edges.insert({std::min(a, b), std::max(a, b)});
  }
  skeleton.edges.assign(edges.begin(), edges.end());
  return skeleton;
}

BranchGraph extract_branches(const CurveSkeleton& skeleton) {
  const auto next = neighbours(skeleton);
  BranchGraph result;
  std::set<std::pair<std::int32_t, std::int32_t>> used;  // edges walked, both directions
  const auto mark = [&](std::int32_t a, std::int32_t b) { used.insert({a, b}), used.insert({b, a}); };
  const auto to_point = [&](std::int32_t n) { return skeleton.nodes[n]; };
  const auto walk = [&](std::int32_t start, std::int32_t first_step) {
    Branch branch;
    branch.first_node = start;
    branch.points.push_back(to_point(start));
    std::int32_t previous = start, current = first_step;
    mark(start, first_step);
    while (true) {
      branch.points.push_back(to_point(current));
      if (next[current].size() != 2 || current == start) break;
      const std::int32_t following = next[current][0] == previous ? next[current][1] : next[current][0];
      mark(current, following);
      branch.interior_nodes.push_back(current);
      previous = current, current = following;
    }
    branch.last_node = current;
    result.branches.push_back(std::move(branch));
  };
  for (std::size_t n = 0; n < skeleton.nodes.size(); ++n) {
    result.ends += next[n].size() == 1;
    result.junctions += next[n].size() >= 3;
    if (next[n].size() == 2) continue;
    for (std::int32_t m : next[n]) {
      if (!used.count({std::int32_t(n), m})) walk(std::int32_t(n), m);
    }
  }
  for (std::size_t n = 0; n < skeleton.nodes.size(); ++n) {  // cycles of regular nodes
    if (next[n].size() == 2 && !used.count({std::int32_t(n), next[n][0]})) walk(std::int32_t(n), next[n][0]);
  }
  return result;
}

namespace {

/// Rebuilds `skeleton` without the dropped nodes, with node `from` merged
/// into `into` (pass -1 for no merge), without self-edges or repeated edges.
void rebuild(CurveSkeleton& skeleton, const std::vector<bool>& drop, std::int32_t from, std::int32_t into) {
  std::vector<std::int32_t> index(skeleton.nodes.size(), -1);
  CurveSkeleton kept;
  for (std::size_t n = 0; n < skeleton.nodes.size(); ++n) {
    if (!drop[n] && std::int32_t(n) != from) index[n] = std::int32_t(kept.nodes.size()), kept.nodes.push_back(skeleton.nodes[n]);
  }
  if (from >= 0) index[from] = index[into];
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (const auto& [a, b] : skeleton.edges) {
    if (index[a] >= 0 && index[b] >= 0 && index[a] != index[b])
      edges.insert({std::min(index[a], index[b]), std::max(index[a], index[b])});
  }
  kept.edges.assign(edges.begin(), edges.end());
  skeleton = std::move(kept);
}

/// Marks the interior nodes of `branch` (all but its two end nodes).
void mark_interior(const Branch& branch, const CurveSkeleton&, std::vector<bool>& drop) {
  for (std::int32_t node : branch.interior_nodes) drop[node] = true;
}

/// One contraction of the shortest branch joining two junctions (or a loop
/// at one junction) shorter than `factor` × the larger end radius. Returns
/// false when there is none.
bool contract_one_bubble(CurveSkeleton& skeleton, double factor) {
  const auto next = neighbours(skeleton);
  const BranchGraph branches = extract_branches(skeleton);
  const Branch* shortest = nullptr;
  for (const Branch& b : branches.branches) {
    if (next[b.first_node].size() < 3 || next[b.last_node].size() < 3) continue;
    const double limit = factor * std::max(skeleton.nodes[b.first_node].w(), skeleton.nodes[b.last_node].w());
    if (polyline_length(b.points) >= limit) continue;
    if (shortest == nullptr || polyline_length(b.points) < polyline_length(shortest->points)) shortest = &b;
  }
  if (shortest == nullptr) return false;
  std::vector<bool> drop(skeleton.nodes.size(), false);
  mark_interior(*shortest, skeleton, drop);
  if (shortest->first_node == shortest->last_node) {
    rebuild(skeleton, drop, -1, -1);
    return true;
  }
  Vec4& into = skeleton.nodes[shortest->first_node];
  const Vec4& from = skeleton.nodes[shortest->last_node];
  into = Vec4((into.x() + from.x()) / 2, (into.y() + from.y()) / 2, (into.z() + from.z()) / 2, std::max(into.w(), from.w()));
  rebuild(skeleton, drop, shortest->last_node, shortest->first_node);
  return true;
}

/// True when the cycle made of branches `a` and `b` (same two end nodes)
/// encloses no hole: its centroid lies inside the ball of one of its points
/// (a handle, like a torus ring, leaves its centre uncovered).
bool encloses_no_hole(const Branch& a, const Branch& b) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec4& p : a.points) centroid += p.head<3>();
  for (const Vec4& p : b.points) centroid += p.head<3>();
  centroid /= double(a.points.size() + b.points.size());
  const auto covers = [&](const Vec4& p) { return (p.head<3>() - centroid).norm() < p.w(); };
  return std::any_of(a.points.begin(), a.points.end(), covers) || std::any_of(b.points.begin(), b.points.end(), covers);
}

/// Distance from `p` to the polyline `points` minus the radius there
/// (interpolated along the nearest segment): ≤ 0 when p is inside its tube.
double outside_tube(const Vec3& p, const std::vector<Vec4>& points) {
  double best = INFINITY;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const Vec3 a = points[k - 1].head<3>(), d = points[k].head<3>() - a;
    const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (p - a - t * d).norm() - (points[k - 1].w() + t * (points[k].w() - points[k - 1].w())));
  }
  return best;
}

/// True when each of the two paths runs inside the other's tube (every
/// point within the radius of the other path): one tube, split by a tunnel
/// that noise bored through it, not a handle around a hole.
bool share_one_tube(const Branch& a, const Branch& b) {
  const auto inside = [](const Branch& from, const Branch& to) {
    return std::all_of(from.points.begin(), from.points.end(),
                       [&](const Vec4& p) { return outside_tube(p.head<3>(), to.points) <= 0.0; });
  };
  return inside(a, b) && inside(b, a);
}

/// One removal of a parallel path: two branches joining the same two
/// junctions whose cycle encloses no hole (the level sets of a branching
/// often leave a direct edge beside a path through one or two nodes). The
/// path with more interior nodes goes (the other is kept; paths without
/// interior nodes are single edges, never repeated). Returns false when
/// there is none.
bool remove_one_parallel_path(CurveSkeleton& skeleton) {
  const BranchGraph branches = extract_branches(skeleton);
  std::map<std::pair<std::int32_t, std::int32_t>, const Branch*> seen;
  for (const Branch& b : branches.branches) {
    if (b.first_node == b.last_node) continue;
    const auto key = std::minmax(b.first_node, b.last_node);
    const auto [it, added] = seen.emplace(key, &b);
    if (added || !(encloses_no_hole(*it->second, b) || share_one_tube(*it->second, b))) continue;
    const Branch& longer = it->second->interior_nodes.size() >= b.interior_nodes.size() ? *it->second : b;
    std::vector<bool> drop(skeleton.nodes.size(), false);
    mark_interior(longer, skeleton, drop);
    rebuild(skeleton, drop, -1, -1);
    return true;
  }
  return false;
}

/// One contraction of a junction triangle: three junctions joined
/// pairwise by branches whose cycle encloses no hole (its centroid lies in
/// the ball of one of its points, as in remove_one_parallel_path). The
/// level sets of a branching sampled with noise can split its junction into
/// three nodes a radius or two apart, each taking one of the branches
/// leaving it: longer sides than contract_one_bubble takes, but no hole. The
/// three become one, at their mean, with the largest radius; the branches
/// between them go. Returns false when there is none.
bool contract_one_triangle(CurveSkeleton& skeleton) {
  const auto next = neighbours(skeleton);
  const BranchGraph branches = extract_branches(skeleton);
  std::map<std::pair<std::int32_t, std::int32_t>, const Branch*> between;  // junction pair → a branch
  for (const Branch& b : branches.branches) {
    if (b.first_node == b.last_node || next[b.first_node].size() < 3 || next[b.last_node].size() < 3) continue;
    between.emplace(std::minmax(b.first_node, b.last_node), &b);
  }
  for (const auto& [ab, side_ab] : between) {
    for (auto ac = between.lower_bound({ab.first, ab.second + 1}); ac != between.end() && ac->first.first == ab.first; ++ac) {
      const std::int32_t a = ab.first, b = ab.second, c = ac->first.second;
      const auto bc = between.find({b, c});
      if (bc == between.end()) continue;
      Branch rest;  // the other two sides, as one list of points for the hole test
      rest.points = ac->second->points;
      rest.points.insert(rest.points.end(), bc->second->points.begin(), bc->second->points.end());
      if (!encloses_no_hole(*side_ab, rest)) continue;
      std::vector<bool> drop(skeleton.nodes.size(), false);
      for (const Branch* side : {side_ab, ac->second, bc->second}) mark_interior(*side, skeleton, drop);
      const Vec4 &pa = skeleton.nodes[a], &pb = skeleton.nodes[b], &pc = skeleton.nodes[c];
      Vec4 merged = (pa + pb + pc) / 3;
      merged.w() = std::max({pa.w(), pb.w(), pc.w()});
      skeleton.nodes[a] = merged;
      for (auto& [u, v] : skeleton.edges) {
        if (u == b || u == c) u = a;
        if (v == b || v == c) v = a;
      }
      drop[b] = drop[c] = true;
      rebuild(skeleton, drop, -1, -1);
      return true;
    }
  }
  return false;
}

/// One removal of a split branch: a loop from a junction back to itself whose
/// two halves, cut at its node farthest from the junction, run in one tube
/// (or enclose no hole, as in remove_one_parallel_path). The level sets of a
/// branch can split it into two paths that meet only at its tip; a change of
/// the mesh in the last bits of its coordinates is enough to make the
/// tree's two outermost branches on one side come out so. The half with more
/// interior nodes goes, the tip stays and becomes the branch's end. A handle
/// at a junction (a ring on a stick) leaves its centre uncovered and its
/// halves apart: it stays. Returns false when there is none.
bool remove_one_split_loop(CurveSkeleton& skeleton) {
  const auto next = neighbours(skeleton);
  const BranchGraph branches = extract_branches(skeleton);
  for (const Branch& b : branches.branches) {
    // points = junction, interior_nodes..., junction.
    if (b.first_node != b.last_node || next[b.first_node].size() < 3 || b.interior_nodes.size() < 2) continue;
    const Vec3 junction = b.points.front().head<3>();
    std::size_t tip = 1;  // index into points
    for (std::size_t k = 2; k + 1 < b.points.size(); ++k) {
      if ((b.points[k].head<3>() - junction).norm() > (b.points[tip].head<3>() - junction).norm()) tip = k;
    }
    Branch out, back;
    out.points.assign(b.points.begin(), b.points.begin() + std::ptrdiff_t(tip) + 1);
    back.points.assign(b.points.begin() + std::ptrdiff_t(tip), b.points.end());
    out.interior_nodes.assign(b.interior_nodes.begin(), b.interior_nodes.begin() + std::ptrdiff_t(tip) - 1);
    back.interior_nodes.assign(b.interior_nodes.begin() + std::ptrdiff_t(tip), b.interior_nodes.end());
    if (!(encloses_no_hole(out, back) || share_one_tube(out, back))) continue;
    std::vector<bool> drop(skeleton.nodes.size(), false);
    mark_interior(out.interior_nodes.size() > back.interior_nodes.size() ? out : back, skeleton, drop);
    rebuild(skeleton, drop, -1, -1);
    return true;
  }
  return false;
}

/// A polyline segment of the skeleton with linearly varying radius, and the
/// branch it belongs to.
struct TubeSegment {
  Vec4 a, b;
  std::size_t branch = 0;
};

/// How far the balls of branch `which` reach beyond the balls of the rest
/// of the skeleton: the largest, over its points p, of the smallest, over
/// the other branches' segments, of |p − q| + r_p − r_q, q the point of the
/// segment nearest p and r_q its interpolated radius (≤ 0: every ball of
/// the branch lies about inside the rest). Stops early once it reaches
/// `enough` (the caller only compares with it).
double protrusion(const std::vector<TubeSegment>& segments, const std::vector<Branch>& branches, std::size_t which,
                  double enough) {
  double reach = -INFINITY;
  for (const Vec4& p : branches[which].points) {
    double nearest = INFINITY;
    for (const TubeSegment& s : segments) {
      if (s.branch == which) continue;
      const Vec3 a = s.a.head<3>(), d = s.b.head<3>() - a;
      const double t = d.squaredNorm() > 0.0 ? std::clamp((p.head<3>() - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      nearest = std::min(nearest, (p.head<3>() - a - t * d).norm() + p.w() - (s.a.w() + t * (s.b.w() - s.a.w())));
      if (nearest <= reach) break;  // this point cannot raise the maximum
    }
    reach = std::max(reach, nearest);
    if (reach >= enough) return reach;
  }
  return reach;
}

/// The signed distance from `p` to the balls of segment s, about: |p − q|
/// − r_q, q the point of the segment nearest p; `radius` receives r_q.
double tube_distance(const Vec3& p, const TubeSegment& s, double* radius) {
  const Vec3 a = s.a.head<3>(), d = s.b.head<3>() - a;
  const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  *radius = s.a.w() + t * (s.b.w() - s.a.w());
  return (p - a - t * d).norm() - *radius;
}

std::vector<TubeSegment> tube_segments(const std::vector<Branch>& branches) {
  std::vector<TubeSegment> segments;
  for (std::size_t k = 0; k < branches.size(); ++k) {
    const auto& p = branches[k].points;
    for (std::size_t i = 1; i < p.size(); ++i) segments.push_back({p[i - 1], p[i], k});
  }
  return segments;
}

/// Per surface point, its nearest branch and how much better that branch
/// explains it than the rest (see explained_area): the two smallest
/// per-branch tube distances d₁ (branch k₁) and d₂ (radius r₂ there);
/// the point counts for k₁ when d₂ − |d₁| > tolerance × r₂.
struct NearestTubes {
  std::vector<std::size_t> branch;  ///< k₁ per point, or npos when it counts for none
};

NearestTubes nearest_tubes(const std::vector<TubeSegment>& segments, std::size_t branch_count,
                           const std::vector<WeightedPoint>& surface, double tolerance) {
  constexpr std::size_t none = std::size_t(-1);
  NearestTubes result;
  std::vector<double> best(branch_count), radius_at(branch_count);
  for (const WeightedPoint& w : surface) {
    std::fill(best.begin(), best.end(), INFINITY);
    for (const TubeSegment& s : segments) {
      double r = 0.0;
      const double d = tube_distance(w.point, s, &r);
      if (d < best[s.branch]) best[s.branch] = d, radius_at[s.branch] = r;
    }
    std::size_t first = none, second = none;
    for (std::size_t k = 0; k < branch_count; ++k) {
      if (!std::isfinite(best[k])) continue;
      if (first == none || best[k] < best[first]) second = first, first = k;
      else if (second == none || best[k] < best[second]) second = k;
    }
    const bool counts = first != none && (second == none || best[second] - std::abs(best[first]) >
                                                                tolerance * radius_at[second]);
    result.branch.push_back(counts ? first : none);
  }
  return result;
}

/// True when terminal branch `which` (from junction node `junction`) is a
/// spur by `rule` (SpurRule); `explained` holds each branch's explained area
/// when the rule has a surface.
bool is_spur(const CurveSkeleton& skeleton, const std::vector<TubeSegment>& segments, const std::vector<Branch>& branches,
             std::size_t which, std::int32_t junction, const SpurRule& rule, const std::vector<double>& explained) {
  const double radius = skeleton.nodes[junction].w();
  if (rule.surface != nullptr) return explained[which] < rule.explained_factor * std::numbers::pi * radius * radius;
  if (polyline_length(branches[which].points) < rule.length_factor * radius) return true;
  return rule.protrusion_factor > 0.0 &&
         protrusion(segments, branches, which, rule.protrusion_factor * radius) < rule.protrusion_factor * radius;
}

/// Each branch's explained area (explained_area), all at once.
std::vector<double> explained_areas(const std::vector<TubeSegment>& segments, std::size_t branch_count,
                                    const std::vector<WeightedPoint>& surface, double tolerance) {
  std::vector<double> area(branch_count, 0.0);
  const NearestTubes nearest = nearest_tubes(segments, branch_count, surface, tolerance);
  for (std::size_t i = 0; i < surface.size(); ++i)
    if (nearest.branch[i] < branch_count) area[nearest.branch[i]] += surface[i].weight;
  return area;
}

/// One pass of spur removal (see remove_spurs); returns the number removed.
std::size_t remove_spurs_once(CurveSkeleton& skeleton, const SpurRule& rule) {
  const auto next = neighbours(skeleton);
  const BranchGraph branches = extract_branches(skeleton);
  const std::vector<TubeSegment> segments = tube_segments(branches.branches);
  const std::vector<double> explained =
      rule.surface != nullptr
          ? explained_areas(segments, branches.branches.size(), *rule.surface, rule.explained_tolerance)
          : std::vector<double>{};
  // The shortest spur at each junction (one per junction per pass, so a
  // junction never loses all its branches at once).
  std::map<std::int32_t, const Branch*> shortest;
  for (std::size_t k = 0; k < branches.branches.size(); ++k) {
    const Branch& b = branches.branches[k];
    const bool first_end = next[b.first_node].size() == 1, last_end = next[b.last_node].size() == 1;
    if (first_end == last_end) continue;
    const std::int32_t junction = first_end ? b.last_node : b.first_node;
    if (!is_spur(skeleton, segments, branches.branches, k, junction, rule, explained)) continue;
    auto [it, added] = shortest.emplace(junction, &b);
    if (!added && polyline_length(b.points) < polyline_length(it->second->points)) it->second = &b;
  }
  std::vector<bool> drop(skeleton.nodes.size(), false);
  for (const auto& [junction, b] : shortest) {
    mark_interior(*b, skeleton, drop);
    drop[b->first_node == junction ? b->last_node : b->first_node] = true;
  }
  if (!shortest.empty()) rebuild(skeleton, drop, -1, -1);
  return shortest.size();
}

}  // namespace

double explained_area(const std::vector<Branch>& branches, std::size_t which, const std::vector<WeightedPoint>& surface,
                      double tolerance) {
  return explained_areas(tube_segments(branches), branches.size(), surface, tolerance).at(which);
}

std::size_t remove_spurs(CurveSkeleton& skeleton, double spur_factor, double protrusion_factor) {
  return remove_spurs(skeleton, SpurRule{spur_factor, protrusion_factor});
}

std::size_t remove_spurs(CurveSkeleton& skeleton, const SpurRule& rule) {
  std::size_t removed = 0;
  while (true) {
    bool changed = false;
    while (remove_one_parallel_path(skeleton)) changed = true, ++removed;
    while (remove_one_split_loop(skeleton)) changed = true, ++removed;
    // Short branches first: a bridge between two branches just past a
    // junction makes a triangle with it too, and contracting the bridge
    // keeps the junction where it is (the triangle's mean lies out in the
    // crotch).
    while (contract_one_bubble(skeleton, rule.length_factor)) changed = true, ++removed;
    while (contract_one_triangle(skeleton)) changed = true, ++removed;
    const std::size_t spurs = remove_spurs_once(skeleton, rule);
    removed += spurs;
    if (!changed && spurs == 0) return removed;
  }
}

namespace {

/// The axis line of a branch leaving a junction of radius `radius`: through
/// its first point at least `radius` (arc length) from the junction, along
/// the chord to its last point within `reach` × radius. Nothing when the
/// branch is too short to give one. `points` start at the junction.
std::optional<std::pair<Vec3, Vec3>> leaving_line(const std::vector<Vec4>& points, double radius, double reach) {
  double arc = 0.0;
  std::optional<std::size_t> near, far;
  for (std::size_t k = 1; k < points.size(); ++k) {
    arc += (points[k].head<3>() - points[k - 1].head<3>()).norm();
    if (arc < radius) continue;
    if (!near) near = k;
    if (arc <= reach * radius || !far) far = k;
    if (arc > reach * radius) break;
  }
  if (!near || *far == *near) {
    if (!near || *near + 1 >= points.size()) return std::nullopt;
    far = *near + 1;
  }
  const Vec3 a = points[*near].head<3>(), d = points[*far].head<3>() - a;
  if (d.norm() == 0.0) return std::nullopt;
  return std::pair{a, Vec3(d.normalized())};
}

/// The point nearest, in least squares, to the lines (a_i, d_i): the
/// solution of Σ (I − d_i d_iᵀ) x = Σ (I − d_i d_iᵀ) a_i. Nothing when the
/// lines are about parallel (the smallest eigenvalue of the sum below
/// `min_spread` × the number of lines).
std::optional<Vec3> nearest_to_lines(const std::vector<std::pair<Vec3, Vec3>>& lines, double min_spread) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Vec3 b = Vec3::Zero();
  for (const auto& [point, d] : lines) {
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - d * d.transpose();
    a += projector, b += projector * point;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(a);
  if (lines.size() < 2 || eigen.eigenvalues().minCoeff() < min_spread * double(lines.size())) return std::nullopt;
  return Vec3(a.ldlt().solve(b));
}

/// Moves junction node `j` (see relocate_junctions); true if it moved.
bool relocate_junction(CurveSkeleton& skeleton, std::int32_t j, const JunctionOptions& o) {
  const BranchGraph graph = extract_branches(skeleton);
  const double radius = skeleton.nodes[j].w();
  std::vector<std::pair<Vec3, Vec3>> lines;
  std::vector<std::pair<const Branch*, std::vector<Vec4>>> leaving;  // branch, points from j
  for (const Branch& b : graph.branches) {
    if (b.first_node == b.last_node || (b.first_node != j && b.last_node != j)) continue;
    std::vector<Vec4> points = b.points;
    if (b.first_node != j) std::reverse(points.begin(), points.end());
    if (const auto line = leaving_line(points, radius, o.reach)) lines.push_back(*line);
    leaving.emplace_back(&b, std::move(points));
  }
  const std::optional<Vec3> x = nearest_to_lines(lines, o.min_spread);
  if (!x || (*x - skeleton.nodes[j].head<3>()).norm() > o.largest_move * radius) return false;
  // Interior nodes now behind the junction along their branch, or within
  // half its radius ahead of it, go; the junction joins the next one.
  std::vector<bool> drop(skeleton.nodes.size(), false);
  for (const auto& [branch, points] : leaving) {
    const Vec3 direction = points.back().head<3>() - *x;
    if (direction.norm() == 0.0) continue;
    std::vector<std::int32_t> chain = branch->interior_nodes;
    if (branch->first_node != j) std::reverse(chain.begin(), chain.end());
    const std::int32_t far_end = branch->first_node == j ? branch->last_node : branch->first_node;
    std::int32_t previous = j;
    for (std::int32_t node : chain) {
      if ((skeleton.nodes[node].head<3>() - *x).dot(direction.normalized()) < 0.5 * radius) {
        drop[node] = true;
        continue;
      }
      if (previous == j) skeleton.edges.push_back({j, node});
      previous = node;
    }
    if (previous == j) skeleton.edges.push_back({j, far_end});
  }
  skeleton.nodes[j].head<3>() = *x;
  rebuild(skeleton, drop, -1, -1);
  return true;
}

}  // namespace

std::size_t relocate_junctions(CurveSkeleton& skeleton, const JunctionOptions& options) {
  std::size_t moved = 0;
  // A rebuild renumbers nodes, so the junctions are found again by their
  // (unchanged) positions, in their first order.
  std::vector<Vec4> junctions;
  const auto next = neighbours(skeleton);
  for (std::size_t n = 0; n < skeleton.nodes.size(); ++n) {
    if (next[n].size() >= 3) junctions.push_back(skeleton.nodes[n]);
  }
  for (const Vec4& junction : junctions) {
    const auto at = std::find(skeleton.nodes.begin(), skeleton.nodes.end(), junction);
    if (at == skeleton.nodes.end()) continue;
    moved += relocate_junction(skeleton, std::int32_t(at - skeleton.nodes.begin()), options);
  }
  return moved;
}


}  // namespace skelconv::reconstruct
