// Implementation of skelconv/reconstruct/pruning.hpp.
#include "skelconv/reconstruct/pruning.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <utility>

#include "union_find.hpp"

namespace skelconv::reconstruct {
namespace {

using detail::find_root;

/// Union-find roots of the vertices kept (-1 for removed ones), joined by the
/// edges between two kept vertices; `keep` selects.
std::vector<std::int32_t> pieces(const MedialGraph& graph, const std::vector<bool>& keep) {
  std::vector<std::int32_t> parent(graph.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const MedialEdge& e : graph.edges) {
    if (keep[e.a] && keep[e.b]) parent[find_root(parent, e.a)] = find_root(parent, e.b);
  }
  std::vector<std::int32_t> root(graph.vertices.size(), -1);
  for (std::size_t v = 0; v < root.size(); ++v) {
    if (keep[v]) root[v] = find_root(parent, std::int32_t(v));
  }
  return root;
}

std::size_t count_pieces(const std::vector<std::int32_t>& root) {
  std::size_t count = 0;
  for (std::size_t v = 0; v < root.size(); ++v) count += root[v] == std::int32_t(v);
  return count;
}

/// The surface part (MedialGraph::sample_parts) vertex `v`'s ball lies in:
/// the part most of its four samples are on (the first such, in sample
/// order, on a tie); 0 when the surface is one part.
std::int32_t vertex_part(const MedialGraph& graph, std::size_t v) {
  if (graph.sample_parts.empty()) return 0;
  std::array<std::int32_t, 4> parts;
  for (std::size_t k = 0; k < 4; ++k) parts[k] = graph.sample_parts[std::size_t(graph.vertices[v].samples[k])];
  std::int32_t best = parts[0];
  long most = 0;
  for (std::int32_t p : parts)
    if (const long c = std::count(parts.begin(), parts.end(), p); c > most) best = p, most = c;
  return best;
}

/// For each piece (union-find `root`) of the vertices `from` accepts, the
/// pair (u, v), v of the piece and u a vertex `to` accepts for v in v's
/// surface part, with the smallest `score(u, v)` (the first in vertex order
/// on a tie); a score that is not finite is no pair. Keyed by the piece's
/// root.
template <class From, class To, class Score>
std::map<std::int32_t, std::pair<std::int32_t, std::int32_t>> closest_pairs(const MedialGraph& graph,
                                                                            const std::vector<std::int32_t>& root,
                                                                            From from, To to, Score score) {
  std::map<std::int32_t, std::pair<std::int32_t, std::int32_t>> pair;
  std::map<std::int32_t, double> best;
  const std::size_t n = graph.vertices.size();
  for (std::size_t v = 0; v < n; ++v) {
    if (!from(v)) continue;
    const std::int32_t part = vertex_part(graph, v);
    for (std::size_t u = 0; u < n; ++u) {
      if (!to(u, v) || vertex_part(graph, u) != part) continue;
      const double value = score(graph.vertices[u], graph.vertices[v]);
      if (!std::isfinite(value)) continue;
      if (const auto at = best.find(root[v]); at == best.end() || value < at->second) {
        best[root[v]] = value;
        pair[root[v]] = {std::int32_t(u), std::int32_t(v)};
      }
    }
  }
  return pair;
}

/// Keeps the vertices with keep[v], renumbered in their order, and the edges
/// and faces whose vertices are all kept.
void compact(MedialGraph& graph, const std::vector<bool>& keep) {
  std::vector<std::int32_t> new_index(graph.vertices.size(), -1);
  std::vector<MedialVertex> vertices;
  for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
    if (!keep[v]) continue;
    new_index[v] = std::int32_t(vertices.size());
    vertices.push_back(graph.vertices[v]);
  }
  std::vector<MedialEdge> edges;
  for (MedialEdge e : graph.edges) {
    if (new_index[e.a] < 0 || new_index[e.b] < 0) continue;
    e.a = new_index[e.a], e.b = new_index[e.b];
    edges.push_back(e);
  }
  std::vector<std::vector<std::int32_t>> faces;
  for (std::vector<std::int32_t> f : graph.faces) {
    bool kept = true;
    for (std::int32_t& v : f) kept = kept && (v = new_index[std::size_t(v)]) >= 0;
    if (kept) faces.push_back(std::move(f));
  }
  graph.vertices = std::move(vertices);
  graph.edges = std::move(edges);
  graph.faces = std::move(faces);
}

/// θ = 2 asin(|p⁻p⁺| / 2ρ) from the span |p⁻p⁺|, the ratio clamped to 1.
double span_angle(double span, double rho) { return 2.0 * std::asin(std::min(1.0, span / (2.0 * rho))); }

/// Whether ball `v` reaches at least `reach` beyond every ball of `large`
/// (vertex indices, largest radius first): r − max (ρ − |centre distance|)
/// ≥ reach, its radius less the most any of them holds its centre in.
bool reaches_beyond(const MedialGraph& graph, const std::vector<std::size_t>& large, std::size_t v, double reach) {
  const MedialVertex& ball = graph.vertices[v];
  for (const std::size_t k : large) {
    const MedialVertex& other = graph.vertices[k];
    // No ball after this one holds the centre deeper than its radius.
    if (other.radius <= ball.radius - reach) return true;
    if (other.radius - (other.centre - ball.centre).norm() > ball.radius - reach) return false;
  }
  return true;
}

/// TipOptions::connect: marks kept the vertices on the shortest way
/// (Dijkstra over the Voronoi edges, each its centres' distance) from the
/// `anchored` vertices (those of the large pieces and the lobes) to each
/// tip piece (the `tipped` vertices, grouped by their union-find `root`),
/// through vertices that are not anchored; the tip piece's vertex nearest
/// that way ends it. Where the graph does not reach a tip piece (a tube
/// thinner than the samples' spacing along it: the Delaunay cells between
/// two rings of samples have their circumcentres outside, and the graph
/// stops there), the piece is bridged by a new edge, without a dual facet
/// ({-1, -1, -1}), between its ball and an anchored ball that overlap, the
/// pair whose centres are closest: two overlapping inscribed balls hold the
/// segment between their centres, so the edge stays inside the shape; both
/// balls in the same closed part of the surface (a Voronoi ball may reach a
/// little past a curved surface, into a close part beside it). A piece
/// whose balls overlap none of the anchored ones is bridged by the pair
/// with the smallest gap where the tube between them is clear of the
/// samples (no sample within half the radius of a ball along it), and
/// otherwise stays apart.
void connect_tips(MedialGraph& graph, const std::vector<std::int32_t>& root, const std::vector<bool>& anchored,
                  const std::vector<bool>& tipped, std::vector<bool>& keep, PruningReport& report) {
  const std::size_t n = graph.vertices.size();
  std::vector<std::vector<std::int32_t>> neighbours(n);
  for (const MedialEdge& e : graph.edges) {
    neighbours[std::size_t(e.a)].push_back(e.b);
    neighbours[std::size_t(e.b)].push_back(e.a);
  }
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> distance(n, infinity);
  std::vector<std::int32_t> previous(n, -1);
  using Item = std::pair<double, std::int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (std::size_t v = 0; v < n; ++v)
    if (anchored[v]) distance[v] = 0.0, queue.push({0.0, std::int32_t(v)});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[std::size_t(v)]) continue;
    for (const std::int32_t w : neighbours[std::size_t(v)]) {
      const double length = d + (graph.vertices[std::size_t(w)].centre - graph.vertices[std::size_t(v)].centre).norm();
      if (length < distance[std::size_t(w)]) {
        distance[std::size_t(w)] = length, previous[std::size_t(w)] = v;
        queue.push({length, w});
      }
    }
  }
  // Each tip piece's vertex nearest the anchored pieces (the first in
  // vertex order on a tie), then the way back from it.
  std::map<std::int32_t, std::int32_t> nearest;
  for (std::size_t v = 0; v < n; ++v) {
    if (!tipped[v] || distance[v] == infinity) continue;
    if (const auto [at, fresh] = nearest.emplace(root[v], std::int32_t(v));
        !fresh && distance[v] < distance[std::size_t(at->second)])
      at->second = std::int32_t(v);
  }
  for (const auto& [r, end] : nearest) {
    ++report.tips_connected;
    for (std::int32_t v = previous[std::size_t(end)]; v >= 0 && !anchored[std::size_t(v)];
         v = previous[std::size_t(v)]) {
      if (!keep[std::size_t(v)]) ++report.connecting_vertices;
      keep[std::size_t(v)] = true;
    }
  }
  // The pieces the graph does not reach: the closest overlapping pair of
  // balls (the first in vertex order on a tie), bridged.
  const auto bridge = closest_pairs(
      graph, root, [&](std::size_t v) { return tipped[v] && nearest.count(root[v]) == 0; },
      [&](std::size_t u, std::size_t) { return bool(anchored[u]); },
      [](const MedialVertex& other, const MedialVertex& ball) {
        const double d = (other.centre - ball.centre).norm();
        return d < ball.radius + other.radius ? d : std::numeric_limits<double>::infinity();
      });
  for (const auto& [r, pair] : bridge) {
    ++report.tips_bridged;
    graph.edges.push_back({pair.first, pair.second, {-1, -1, -1}});
  }
  // The pieces apart still (a sharp horn whose tip pieces and the body's
  // balls neither meet in the graph nor overlap: the horn narrows between
  // them below the samples' spacing): for each, the pair of balls with the
  // smallest gap between their spheres (the first in vertex order on a
  // tie), bridged where the tube between them stays clear of the samples,
  // each ball along it (centre and radius linear between the pair's)
  // holding no sample within half its radius: a bridge across air crosses
  // the surface, whose samples lie on the segment there. A piece bridged
  // anchors the next round, so a horn's pieces join in a chain from its
  // base (a straight bridge from the body to a curved horn's end leaves the
  // horn).
  std::vector<bool> held = anchored;
  std::set<std::int32_t> joined;
  for (const auto& [r, end] : nearest) joined.insert(r);
  for (const auto& [r, pair] : bridge) joined.insert(r);
  for (std::size_t v = 0; v < n; ++v)
    if (tipped[v] && joined.count(root[v]) > 0) held[v] = true;
  constexpr int steps = 16;
  const auto clear_between = [&graph](const MedialVertex& a, const MedialVertex& b) {
    for (int k = 0; k <= steps; ++k) {
      const double t = double(k) / steps;
      const Vec3 centre = (1.0 - t) * a.centre + t * b.centre;
      const double within = 0.5 * ((1.0 - t) * a.radius + t * b.radius);
      for (const Vec3& sample : graph.samples)
        if ((sample - centre).squaredNorm() < within * within) return false;
    }
    return true;
  };
  for (bool more = true; more;) {
    more = false;
    const auto gap_pair = closest_pairs(
        graph, root, [&](std::size_t v) { return tipped[v] && joined.count(root[v]) == 0; },
        [&](std::size_t u, std::size_t v) { return held[u] && root[u] != root[v]; },
        [](const MedialVertex& other, const MedialVertex& ball) {
          return (other.centre - ball.centre).norm() - ball.radius - other.radius;
        });
    for (const auto& [r, pair] : gap_pair) {
      if (!clear_between(graph.vertices[std::size_t(pair.first)], graph.vertices[std::size_t(pair.second)])) continue;
      ++report.tips_bridged;
      graph.edges.push_back({pair.first, pair.second, {-1, -1, -1}});
      joined.insert(r);
      for (std::size_t v = 0; v < n; ++v)
        if (root[v] == r) held[v] = true;
      more = true;
    }
  }
}

}  // namespace

double pruning_angle(const Vec3& p_minus, const Vec3& p_plus, double rho) {
  return span_angle((p_plus - p_minus).norm(), rho);
}

double contact_span(const MedialGraph& graph, std::size_t v) {
  const MedialVertex& m = graph.vertices[v];
  double longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      longest = std::max(longest, (graph.samples[m.samples[i]] - graph.samples[m.samples[j]]).norm());
    }
  }
  return longest;
}

double vertex_angle(const MedialGraph& graph, std::size_t v) {
  return span_angle(contact_span(graph, v), graph.vertices[v].radius);
}

PruningReport prune_medial_graph(MedialGraph& graph, double threshold, double minimum_piece, double minimum_span,
                                 const LobeOptions& lobes, const TipOptions& tips) {
  const std::size_t n = graph.vertices.size();
  PruningReport report;
  std::vector<bool> keep(n);
  for (std::size_t v = 0; v < n; ++v) {
    keep[v] = vertex_angle(graph, v) >= threshold && contact_span(graph, v) >= minimum_span;
  }
  report.vertices_removed = n - std::size_t(std::count(keep.begin(), keep.end(), true));
  // What went, as connected pieces of the removed vertices.
  std::vector<bool> removed(n);
  for (std::size_t v = 0; v < n; ++v) removed[v] = !keep[v];
  report.branches_removed = count_pieces(pieces(graph, removed));
  // Islands: pieces of the kept graph much smaller than the largest in the
  // same part of the surface. A separate part (one bone of a foot, a ball
  // beside a body) has its own largest piece, however small the part is.
  const std::vector<std::int32_t> root = pieces(graph, keep);
  std::map<std::int32_t, std::size_t> size;
  std::map<std::int32_t, std::int32_t> part;  // piece -> the surface part of its first vertex
  for (std::size_t v = 0; v < n; ++v) {
    if (root[v] < 0) continue;
    ++size[root[v]];
    part.emplace(root[v], vertex_part(graph, v));
  }
  std::map<std::int32_t, std::size_t> largest;  // surface part -> its largest piece
  for (const auto& [r, s] : size) largest[part[r]] = std::max(largest[part[r]], s);
  const auto small = [&](std::int32_t r) { return double(size[r]) < minimum_piece * double(largest[part[r]]); };
  // Each small piece's deepest vertex, and the largest radius of the large pieces.
  std::map<std::int32_t, std::size_t> deepest;
  double large_radius = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    if (root[v] < 0) continue;
    const double radius = graph.vertices[v].radius;
    if (!small(root[v])) {
      large_radius = std::max(large_radius, radius);
    } else if (const auto [at, fresh] = deepest.emplace(root[v], v); !fresh && radius > graph.vertices[at->second].radius) {
      at->second = v;
    }
  }
  std::map<std::int32_t, bool> lobe;
  for (const auto& [r, d] : deepest) {
    const MedialVertex& ball = graph.vertices[d];
    if (lobes.radius <= 0.0 || ball.radius < lobes.radius * large_radius) continue;
    // How deep the large pieces' balls reach at the centre.
    double covered = 0.0;
    for (std::size_t v = 0; v < n; ++v) {
      if (root[v] >= 0 && !small(root[v]))
        covered = std::max(covered, graph.vertices[v].radius - (graph.vertices[v].centre - ball.centre).norm());
    }
    lobe[r] = ball.radius - covered >= lobes.outside * ball.radius;
  }
  // The tips (TipOptions): a small piece one of whose balls reaches far
  // enough beyond every ball of the large pieces and of the lobes.
  std::map<std::int32_t, bool> tip;
  if (tips.reach > 0.0) {
    std::vector<std::size_t> large;
    for (std::size_t v = 0; v < n; ++v)
      if (root[v] >= 0 && (!small(root[v]) || lobe[root[v]])) large.push_back(v);
    std::stable_sort(large.begin(), large.end(), [&graph](std::size_t a, std::size_t b) {
      return graph.vertices[a].radius > graph.vertices[b].radius;
    });
    for (std::size_t v = 0; v < n; ++v)
      if (root[v] >= 0 && small(root[v]) && !lobe[root[v]] && !tip[root[v]] &&
          reaches_beyond(graph, large, v, std::max(tips.reach, tips.thinness * graph.vertices[v].radius)))
        tip[root[v]] = true;
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (keep[v] && small(root[v]) && !lobe[root[v]] && !tip[root[v]]) keep[v] = false;
  }
  for (const auto& [r, s] : size) {
    if (small(r)) ++(lobe[r] ? report.lobes_kept : tip[r] ? report.tips_kept : report.small_pieces_removed);
  }
  if (tips.connect && report.tips_kept > 0) {
    std::vector<bool> anchored(n), tipped(n);
    for (std::size_t v = 0; v < n; ++v) {
      anchored[v] = root[v] >= 0 && (!small(root[v]) || lobe[root[v]]);
      tipped[v] = root[v] >= 0 && small(root[v]) && tip[root[v]];
    }
    connect_tips(graph, root, anchored, tipped, keep, report);
  }
  compact(graph, keep);
  return report;
}

}  // namespace skelconv::reconstruct
