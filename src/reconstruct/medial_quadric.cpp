// Implementation of skelconv/reconstruct/medial_quadric.hpp.
#include "skelconv/reconstruct/medial_quadric.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <tuple>

#include <Eigen/Dense>

namespace skelconv::reconstruct {
namespace {

using Index = std::int32_t;
using Triangle = std::array<Index, 3>;

/// The spherical quadric sᵀ A s − 2 bᵀ s + c of the header.
struct Quadric {
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  Eigen::Vector4d b = Eigen::Vector4d::Zero();
  double c = 0.0;

  /// `weight` × the squared distance to the plane through q with outward unit normal n.
  void add_plane(const Vec3& q, const Vec3& n, double weight = 1.0) {
    const Eigen::Vector4d m(n.x(), n.y(), n.z(), 1.0);
    const double k = n.dot(q);
    A += weight * m * m.transpose();
    b += weight * k * m;
    c += weight * k * k;
  }
  Quadric& operator+=(const Quadric& o) {
    A += o.A, b += o.b, c += o.c;
    return *this;
  }
  double error(const Vec4& s) const { return std::max(0.0, s.dot(A * s) - 2.0 * b.dot(s) + c); }
};

/// The plane through q with outward unit normal n as (n, n·q): a sphere
/// (c, r) is n·c + r − n·q from it along n (Quadric::add_plane).
Vec4 plane(const Vec3& q, const Vec3& n) { return Vec4(n.x(), n.y(), n.z(), n.dot(q)); }

/// The farthest the sphere s is from any of `planes` (0 for none).
double worst_distance(const Vec4& s, const std::vector<Vec4>& planes) {
  double worst = 0.0;
  for (const Vec4& p : planes) worst = std::max(worst, std::abs(p.head<3>().dot(s.head<3>()) + s.w() - p.w()));
  return worst;
}

Triangle sorted(Index a, Index b, Index c) {
  Triangle t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

/// (|c_u − c_v| − |r_u − r_v|) / |c_u − c_v|, clamped to [0, 1]; 0 for
/// coincident centres.
double stability_ratio(const Vec4& u, const Vec4& v) {
  const double d = (u.head<3>() - v.head<3>()).norm();
  if (!(d > 0.0)) return 0.0;
  return std::clamp((d - std::abs(u.w() - v.w())) / d, 0.0, 1.0);
}

/// The 2-complex being simplified: spheres with their quadrics, the
/// neighbours of each (edges) and the triangles through each.
class Complex {
 public:
  std::vector<Vec4> sphere;
  std::vector<Quadric> quadric;
  // The tangent planes each sphere stands for, (n, n·q) of the planes its
  // quadric sums, kept only with an error target (QuadricOptions::error_target).
  std::vector<std::vector<Vec4>> planes;
  std::vector<std::vector<Index>> neighbours;  // sorted
  std::vector<std::vector<Triangle>> triangles_at;
  std::set<Triangle> triangles;
  std::vector<bool> alive;
  std::vector<bool> held;  // a sphere that keeps its place (QuadricOptions::reach_points)
  std::vector<unsigned> stamp;  // bumped whenever a vertex changes

  bool has_edge(Index u, Index v) const {
    const auto& n = neighbours[std::size_t(u)];
    return std::binary_search(n.begin(), n.end(), v);
  }
  void add_edge(Index u, Index v) {
    if (u == v) return;
    for (const auto& [p, q] : {std::pair{u, v}, std::pair{v, u}}) {
      auto& n = neighbours[std::size_t(p)];
      const auto at = std::lower_bound(n.begin(), n.end(), q);
      if (at == n.end() || *at != q) n.insert(at, q);
    }
  }
  void remove_edge(Index u, Index v) {
    for (const auto& [p, q] : {std::pair{u, v}, std::pair{v, u}}) {
      auto& n = neighbours[std::size_t(p)];
      const auto at = std::lower_bound(n.begin(), n.end(), q);
      if (at != n.end() && *at == q) n.erase(at);
    }
  }
  void add_triangle(const Triangle& t) {
    if (t[0] == t[1] || t[1] == t[2] || !triangles.insert(t).second) return;
    for (const Index i : t) triangles_at[std::size_t(i)].push_back(t);
    add_edge(t[0], t[1]), add_edge(t[1], t[2]), add_edge(t[0], t[2]);
  }
  void remove_triangle(const Triangle& t) {
    if (triangles.erase(t) == 0) return;
    for (const Index i : t) std::erase(triangles_at[std::size_t(i)], t);
  }

  /// Whether the balls of a triangle's corners cover it, tested at its
  /// centroid and the midpoints of its sides (each inside one of the three
  /// balls). The balls are inside the shape: a triangle across a tunnel of
  /// the shape crosses the tunnel, outside them.
  bool covered(const std::array<Index, 3>& t) const {
    const Vec4 &a = sphere[std::size_t(t[0])], &b = sphere[std::size_t(t[1])], &c = sphere[std::size_t(t[2])];
    const auto inside = [&](const Vec3& p) {
      for (const Vec4* s : {&a, &b, &c})
        if ((p - s->head<3>()).norm() <= s->w()) return true;
      return false;
    };
    const Vec3 pa = a.head<3>(), pb = b.head<3>(), pc = c.head<3>();
    return inside((pa + pb + pc) / 3) && inside((pa + pb) / 2) && inside((pb + pc) / 2) && inside((pa + pc) / 2);
  }

  /// The link condition for collapsing (u, v) (the header), except where
  /// the topology it would keep is not the shape's: a loop u–v–w without
  /// its triangle, inside the balls of its corners (a hole in a sheet where
  /// the Voronoi faces had a sliver, not a tunnel of the shape), and a
  /// closed tetrahedron inside them (a cavity, which a solid has none of).
  /// Such loops are returned in `fill`: the collapse closes them.
  /// `held(t)`: whether a loop not covered by its balls is closed all the
  /// same (QuadricOptions::inside_samples); `inside` counts those in `fill`.
  bool link_condition(Index u, Index v, std::vector<Index>& fill, std::size_t& inside,
                      const std::function<bool(const std::array<Index, 3>&)>& held) const {
    fill.clear();
    inside = 0;
    std::vector<Index> apexes;
    for (const Triangle& t : triangles_at[std::size_t(u)])
      if (std::find(t.begin(), t.end(), v) != t.end())
        for (const Index w : t)
          if (w != u && w != v) apexes.push_back(w);
    std::sort(apexes.begin(), apexes.end());
    const auto& nu = neighbours[std::size_t(u)];
    const auto& nv = neighbours[std::size_t(v)];
    std::vector<Index> common;
    std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(common));
    for (const Index w : common) {
      if (std::binary_search(apexes.begin(), apexes.end(), w)) continue;
      if (!covered({u, v, w})) {
        if (!held || !held({u, v, w})) return false;
        ++inside;
      }
      fill.push_back(w);
    }
    // A triangle (u, w, x) whose opposite edge also spans (v, w, x): the
    // four bound a tetrahedron, which the collapse flattens.
    for (const Triangle& t : triangles_at[std::size_t(u)]) {
      if (std::find(t.begin(), t.end(), v) != t.end()) continue;
      Index w = -1, x = -1;
      for (const Index i : t)
        if (i != u) (w < 0 ? w : x) = i;
      if (triangles.count(sorted(v, w, x)) && !(covered({u, v, w}) && covered({u, w, x}) && covered({v, w, x})))
        return false;
    }
    return true;
  }

  long long euler_characteristic() const {
    long long v = 0, e = 0;
    for (std::size_t i = 0; i < sphere.size(); ++i) {
      if (!alive[i]) continue;
      ++v;
      for (const Index j : neighbours[i]) e += Index(i) < j;
    }
    return v - e + (long long)triangles.size();
  }

  /// Triangles + edges in no triangle + spheres in no edge.
  std::size_t primitives() const {
    std::size_t count = triangles.size();
    for (std::size_t i = 0; i < sphere.size(); ++i) {
      if (!alive[i]) continue;
      if (neighbours[i].empty()) ++count;
      for (const Index j : neighbours[i]) {
        if (j < Index(i)) continue;
        bool in_triangle = false;
        for (const Triangle& t : triangles_at[i]) in_triangle = in_triangle || std::find(t.begin(), t.end(), j) != t.end();
        count += !in_triangle;
      }
    }
    return count;
  }
};

Complex initial_complex(const MedialGraph& graph, const QuadricOptions& o) {
  Complex k;
  const std::size_t n = graph.vertices.size();
  k.sphere.resize(n);
  k.quadric.resize(n);
  const bool targeted = o.error_target > 0.0;
  if (targeted) k.planes.resize(n);
  k.neighbours.resize(n);
  k.triangles_at.resize(n);
  k.alive.assign(n, true);
  k.held.assign(n, false);
  k.stamp.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const MedialVertex& m = graph.vertices[i];
    k.sphere[i] = Vec4(m.centre.x(), m.centre.y(), m.centre.z(), m.radius);
    // Contact planes only where the samples are known (a graph built by
    // hand has none: the vertex then starts with a zero quadric).
    if (graph.samples.empty()) continue;
    for (const std::int32_t s : m.samples) {
      const Vec3& q = graph.samples[std::size_t(s)];
      const Vec3 out = q - m.centre;
      if (!(out.norm() > 0.0)) continue;
      k.quadric[i].add_plane(q, out.normalized());
      if (targeted) k.planes[i].push_back(plane(q, out.normalized()));
    }
  }
  for (const ReachPoint& p : o.reach_points) {
    const Vec3 out = p.point - k.sphere[std::size_t(p.vertex)].head<3>();
    if (out.norm() > 0.0) {
      k.quadric[std::size_t(p.vertex)].add_plane(p.point, out.normalized(), o.reach_weight);
      if (targeted) k.planes[std::size_t(p.vertex)].push_back(plane(p.point, out.normalized()));
    }
    k.held[std::size_t(p.vertex)] = true;
  }
  for (const MedialEdge& e : graph.edges) k.add_edge(e.a, e.b);
  for (const auto& face : graph.faces)
    for (std::size_t j = 1; j + 1 < face.size(); ++j) k.add_triangle(sorted(face[0], face[j], face[j + 1]));
  return k;
}

/// Whether the input holds the triangle t of `k`: `depth` above
/// −`inside_tolerance` (half a facet of the measuring mesh: a thin wall's
/// bridge may graze its surface) at the points of a grid of
/// `inside_samples` steps a side (its corners are centres of balls of the
/// input already). A point inside one of the corners' balls needs no query.
bool held_by_input(const Complex& k, const QuadricOptions& o, const std::array<Index, 3>& t) {
  const int n = o.inside_samples;
  const Vec4 &a = k.sphere[std::size_t(t[0])], &b = k.sphere[std::size_t(t[1])], &c = k.sphere[std::size_t(t[2])];
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const int l = n - i - j;
      if (i == n || j == n || l == n) continue;  // a corner
      const Vec3 p = (double(i) * a.head<3>() + double(j) * b.head<3>() + double(l) * c.head<3>()) / double(n);
      bool in_ball = false;
      for (const Vec4* s : {&a, &b, &c}) in_ball = in_ball || (p - s->head<3>()).norm() < s->w();
      if (!in_ball && !(o.depth(p) > -o.inside_tolerance)) return false;
    }
  return true;
}

/// The triangles of `k` on the edge (u, v).
std::size_t triangles_on(const Complex& k, Index u, Index v) {
  std::size_t count = 0;
  for (const Triangle& t : k.triangles_at[std::size_t(u)]) count += std::find(t.begin(), t.end(), v) != t.end();
  return count;
}

/// The shortest way from u to v (Euclidean lengths between centres) along
/// edges of `k` on at most one triangle, the edge (u, v) itself left out;
/// u first, v last. Empty where there is none.
std::vector<Index> rim_path(const Complex& k, Index u, Index v) {
  std::map<Index, double> distance{{u, 0.0}};
  std::map<Index, Index> previous;
  std::priority_queue<std::pair<double, Index>, std::vector<std::pair<double, Index>>, std::greater<>> queue;
  queue.push({0.0, u});
  while (!queue.empty()) {
    const auto [d, x] = queue.top();
    queue.pop();
    if (d > distance[x]) continue;
    if (x == v) break;
    for (const Index y : k.neighbours[std::size_t(x)]) {
      if ((x == u && y == v) || triangles_on(k, x, y) > 1) continue;
      const double through = d + (k.sphere[std::size_t(x)].head<3>() - k.sphere[std::size_t(y)].head<3>()).norm();
      if (const auto at = distance.find(y); at != distance.end() && at->second <= through) continue;
      distance[y] = through, previous[y] = x;
      queue.push({through, y});
    }
  }
  if (!previous.count(v)) return {};
  std::vector<Index> path{v};
  while (path.back() != u) path.push_back(previous[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

/// The loop `polygon` (closed from its last vertex to its first) cut into
/// triangles whose least round one is as round as can be (roundness: the
/// area over the sum of the squared sides; dynamic programming over the
/// polygon's diagonals, cubic in its length). A fan from one vertex, or
/// greedy ears, along a straight stretch of rim give triangles of no area,
/// which the skeleton file turns into edges, and the hole opens again.
std::vector<Triangle> round_triangles(const Complex& k, const std::vector<Index>& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return {};
  const auto roundness = [&](std::size_t i, std::size_t j, std::size_t l) {
    const Vec3 a = k.sphere[std::size_t(polygon[i])].head<3>(), b = k.sphere[std::size_t(polygon[j])].head<3>(),
               c = k.sphere[std::size_t(polygon[l])].head<3>();
    const double sides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return sides > 0.0 ? (b - a).cross(c - a).norm() / sides : 0.0;
  };
  // best[i][j]: the best least roundness of the polygon i, i + 1, …, j.
  std::vector<std::vector<double>> best(n, std::vector<double>(n, std::numeric_limits<double>::infinity()));
  std::vector<std::vector<std::size_t>> apex(n, std::vector<std::size_t>(n, 0));
  for (std::size_t length = 2; length < n; ++length)
    for (std::size_t i = 0; i + length < n; ++i) {
      const std::size_t j = i + length;
      best[i][j] = -1.0;
      for (std::size_t l = i + 1; l < j; ++l) {
        const double q = std::min({length == 2 || l == i + 1 ? std::numeric_limits<double>::infinity() : best[i][l],
                                   l + 1 == j ? std::numeric_limits<double>::infinity() : best[l][j],
                                   roundness(i, l, j)});
        if (q > best[i][j]) best[i][j] = q, apex[i][j] = l;
      }
    }
  std::vector<Triangle> triangles;
  std::vector<std::pair<std::size_t, std::size_t>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, j] = pending.back();
    pending.pop_back();
    if (j < i + 2) continue;
    const std::size_t l = apex[i][j];
    triangles.push_back(sorted(polygon[i], polygon[l], polygon[j]));
    pending.push_back({i, l}), pending.push_back({l, j});
  }
  return triangles;
}

/// Closes the sheet a tube edge bridges (QuadricOptions::inside_samples):
/// an edge on no triangle between two spheres of sheets, which with the
/// sheets' rim between its ends bounds a disc the input holds, is what is
/// left of a sheet whose Voronoi faces were dropped (a wall thinner than
/// the samples' spacing has Delaunay cells across it, whose circumcentres
/// fall outside it), not a tube: each side of it, the loop of the edge and
/// the shortest way back along the rim, is cut into triangles
/// (round_triangles), added where the input holds every one of them. A loop through
/// a tunnel of the input is never held. Returns the loops closed.
std::size_t close_bridged_sheets(Complex& k, const QuadricOptions& o) {
  std::vector<std::array<Index, 2>> bridges;
  for (Index u = 0; u < Index(k.sphere.size()); ++u) {
    if (!k.alive[std::size_t(u)] || k.triangles_at[std::size_t(u)].empty()) continue;
    for (const Index v : k.neighbours[std::size_t(u)])
      if (u < v && !k.triangles_at[std::size_t(v)].empty() && triangles_on(k, u, v) == 0) bridges.push_back({u, v});
  }
  std::size_t closed = 0;
  for (const auto& [u, v] : bridges) {
    for (int side = 0; side < 2 && triangles_on(k, u, v) < 2; ++side) {
      const std::vector<Index> path = rim_path(k, u, v);
      if (path.size() < 3) break;
      const std::vector<Triangle> fan = round_triangles(k, path);
      bool held = true;
      for (const Triangle& t : fan)
        held = held && t[0] != t[1] && t[1] != t[2] && !k.triangles.count(t) && held_by_input(k, o, t);
      if (!held) break;
      for (const Triangle& t : fan) k.add_triangle(t);
      ++closed;
    }
  }
  return closed;
}

/// Loops of the sheets' rims: the edges on exactly one triangle, walked
/// into simple cycles (a walk that comes back to one of its vertices cuts
/// that cycle off; one that ends where no rim edge is left is dropped), in
/// a fixed order.
std::vector<std::vector<Index>> rim_loops(const Complex& k) {
  std::map<Index, std::vector<Index>> rim;  // sorted neighbours along the rim
  for (Index u = 0; u < Index(k.sphere.size()); ++u) {
    if (!k.alive[std::size_t(u)]) continue;
    for (const Index v : k.neighbours[std::size_t(u)])
      if (u < v && triangles_on(k, u, v) == 1) rim[u].push_back(v), rim[v].push_back(u);
  }
  for (auto& [u, next] : rim) std::sort(next.begin(), next.end());
  const auto key = [](Index a, Index b) { return std::array<Index, 2>{std::min(a, b), std::max(a, b)}; };
  std::set<std::array<Index, 2>> used;
  std::vector<std::vector<Index>> loops;
  for (const auto& [start, first_next] : rim)
    for (const Index first : first_next) {
      if (used.count(key(start, first))) continue;
      std::vector<Index> path{start};
      std::map<Index, std::size_t> at{{start, 0}};
      Index x = start, y = first;
      while (true) {
        used.insert(key(x, y));
        if (const auto seen = at.find(y); seen != at.end()) {
          const std::size_t from = seen->second;
          loops.emplace_back(path.begin() + std::ptrdiff_t(from), path.end());
          for (std::size_t i = from + 1; i < path.size(); ++i) at.erase(path[i]);
          path.resize(from + 1);
        } else {
          at[y] = path.size();
          path.push_back(y);
        }
        x = y;
        y = -1;
        for (const Index w : rim[x])
          if (!used.count(key(x, w))) {
            y = w;
            break;
          }
        if (y < 0) break;
      }
    }
  return loops;
}

/// Chains of edges over GF(2), each a set of edges as bits, reduced
/// against the boundaries of the complex's triangles: a loop is the rim of
/// a piece of sheet (it bounds triangles already) where it reduces to
/// nothing.
class Boundaries {
 public:
  explicit Boundaries(const Complex& k) {
    for (const Triangle& t : k.triangles) add(t);
  }
  void add(const Triangle& t) { insert(chain({{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}})); }
  /// Whether the closed loop `polygon` bounds triangles of the complex.
  bool bounds(const std::vector<Index>& polygon) {
    std::vector<std::array<Index, 2>> edges;
    for (std::size_t i = 0; i < polygon.size(); ++i) edges.push_back({polygon[i], polygon[(i + 1) % polygon.size()]});
    return reduced(chain(edges)).empty();
  }

 private:
  using Bits = std::vector<std::uint64_t>;
  Bits chain(const std::vector<std::array<Index, 2>>& edges) {
    Bits bits;
    for (const auto& [a, b] : edges) {
      const auto [at, added] = number_.try_emplace({std::min(a, b), std::max(a, b)}, number_.size());
      const std::size_t n = at->second;
      if (bits.size() <= n / 64) bits.resize(n / 64 + 1, 0);
      bits[n / 64] ^= std::uint64_t(1) << (n % 64);
    }
    trim(bits);
    return bits;
  }
  static void trim(Bits& bits) {
    while (!bits.empty() && bits.back() == 0) bits.pop_back();
  }
  static std::size_t highest(const Bits& bits) {
    return 64 * (bits.size() - 1) + std::size_t(63 - std::countl_zero(bits.back()));
  }
  Bits reduced(Bits bits) const {
    while (!bits.empty()) {
      const auto row = rows_.find(highest(bits));
      if (row == rows_.end()) break;
      for (std::size_t i = 0; i < row->second.size(); ++i) bits[i] ^= row->second[i];
      trim(bits);
    }
    return bits;
  }
  void insert(const Bits& bits) {
    Bits r = reduced(bits);
    if (!r.empty()) rows_.emplace(highest(r), std::move(r));
  }
  std::map<std::array<Index, 2>, std::size_t> number_;
  std::map<std::size_t, Bits> rows_;  // by the highest edge each holds
};

/// Closes the holes of the sheets (QuadricOptions::inside_samples): a loop
/// of the sheets' rims (rim_loops) that bounds no triangles of the complex
/// is a hole through a sheet, a tunnel of the complex; where the input
/// holds the triangles that close it (round_triangles, held_by_input) it
/// is no tunnel of the shape but what is left of a sheet whose Voronoi
/// faces were dropped (a wall thinner than the samples' spacing), which
/// link_condition would have closed had a collapse on its rim met it as a
/// loop of three edges before the budget stopped them; it is closed.
/// Shortest loops first: the rim round a sheet with holes bounds no
/// triangles until its holes are closed, and then it does, so it is never
/// closed over the sheet. Returns the loops closed.
std::size_t close_sheet_holes(Complex& k, const QuadricOptions& o) {
  std::vector<std::vector<Index>> loops = rim_loops(k);
  const auto length = [&k](const std::vector<Index>& loop) {
    double sum = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i)
      sum += (k.sphere[std::size_t(loop[i])].head<3>() - k.sphere[std::size_t(loop[(i + 1) % loop.size()])].head<3>())
                 .norm();
    return sum;
  };
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < loops.size(); ++i) order.push_back({length(loops[i]), i});
  std::sort(order.begin(), order.end());
  Boundaries boundaries(k);
  std::size_t closed = 0;
  for (const auto& [ignored, i] : order) {
    const std::vector<Index>& loop = loops[i];
    if (boundaries.bounds(loop)) continue;
    const std::vector<Triangle> disc = round_triangles(k, loop);
    bool held = !disc.empty();
    for (const Triangle& t : disc)
      held = held && t[0] != t[1] && t[1] != t[2] && !k.triangles.count(t) && held_by_input(k, o, t);
    if (!held) continue;
    for (const Triangle& t : disc) k.add_triangle(t), boundaries.add(t);
    ++closed;
  }
  return closed;
}

struct Candidate {
  double cost = 0.0;
  Index u = 0, v = 0;
  unsigned stamp_u = 0, stamp_v = 0;
  Vec4 merged;
  bool operator>(const Candidate& o) const { return std::tie(cost, u, v) > std::tie(o.cost, o.u, o.v); }
};

class Simplifier {
 public:
  Simplifier(Complex& k, const QuadricOptions& o) : k_(k), o_(o) {
    for (Index u = 0; u < Index(k.sphere.size()); ++u)
      for (const Index v : k.neighbours[std::size_t(u)])
        if (u < v) push(u, v);
  }

  /// Collapses until the primitives fit the budget, then, with an error
  /// target, while collapses within it are left; or until no collapse is
  /// left.
  void run(QuadricReport& report) {
    std::size_t live = std::size_t(std::count(k_.alive.begin(), k_.alive.end(), true));
    std::size_t uncounted = 0;  // collapses before the primitives are counted again
    std::vector<Index> fill;
    std::size_t inside = 0;
    std::function<bool(const std::array<Index, 3>&)> held;
    if (o_.depth && o_.inside_samples > 0) held = [this](const std::array<Index, 3>& t) { return held_by_input(k_, o_, t); };
    const bool targeted = o_.error_target > 0.0;
    bool within_budget = false;
    while (!queue_.empty()) {
      // Counting the primitives is linear in the complex: only near the
      // end, and no more often than needed (a collapse removes at most a
      // few: the triangles and the edge on it). A collapse never adds
      // primitives, so once within the budget they stay within it.
      if (!within_budget) {
        if (live <= 4 * o_.budget && uncounted == 0) {
          const std::size_t p = k_.primitives();
          if (p <= o_.budget) {
            if (!targeted) {
              ++report.stopped_at_budget;
              return;
            }
            within_budget = true;
          } else {
            uncounted = (p - o_.budget) / 4;
          }
        } else if (uncounted > 0) {
          --uncounted;
        }
      }
      const Candidate c = queue_.top();
      queue_.pop();
      if (!k_.alive[std::size_t(c.u)] || !k_.alive[std::size_t(c.v)] || k_.stamp[std::size_t(c.u)] != c.stamp_u ||
          k_.stamp[std::size_t(c.v)] != c.stamp_v || !k_.has_edge(c.u, c.v))
        continue;
      // Measured only here, past the stamps' check: only once within the
      // budget, and only for the collapses that could be made.
      if (within_budget && std::max(worst_distance(c.merged, k_.planes[std::size_t(c.u)]),
                                    worst_distance(c.merged, k_.planes[std::size_t(c.v)])) > o_.error_target) {
        ++report.over_error_target;
        continue;
      }
      if (!k_.link_condition(c.u, c.v, fill, inside, held)) {
        ++report.refused_by_link;
        blocked_[c.u].push_back(c.v);
        blocked_[c.v].push_back(c.u);
        continue;
      }
      // A covered loop is closed by its triangle, which the collapse removes
      // with the edge: u–w and v–w become one edge.
      for (const Index w : fill) k_.add_triangle(sorted(c.u, c.v, w));
      report.loops_closed += fill.size();
      report.loops_closed_inside += inside;
      collapse(c);
      ++report.collapses;
      report.collapses_under_budget += within_budget;
      --live;
    }
    ++(within_budget ? report.stopped_at_error : report.stopped_without_collapse);
  }

 private:
  /// The merged sphere of (u, v) and its cost.
  void push(Index u, Index v) {
    const Vec4 &su = k_.sphere[std::size_t(u)], &sv = k_.sphere[std::size_t(v)];
    Quadric q = k_.quadric[std::size_t(u)];
    q += k_.quadric[std::size_t(v)];
    const Vec4 mid = 0.5 * (su + sv);
    const double lambda = o_.regularisation * std::max(q.A.trace(), 1e-300);
    const Eigen::Matrix4d A = q.A + lambda * Eigen::Matrix4d::Identity();
    const Vec4 solved = A.ldlt().solve(q.b + lambda * mid);
    Vec4 best = mid;
    double best_error = std::numeric_limits<double>::infinity();
    const bool held_u = k_.held[std::size_t(u)], held_v = k_.held[std::size_t(v)];
    // Two held balls merge as any two (the budget must be reachable: a
    // small part's every ball may be held), and the merged ball is held.
    if (held_u != held_v) {
      // A tip's ball keeps its place: the other merges into it.
      best = held_u ? su : sv;
      best_error = q.error(best);
    } else {
      const double smallest = 0.5 * std::min(su.w(), sv.w());
      if (solved.allFinite() && solved.w() > smallest && inside_shape(solved, su, sv))
        best = solved, best_error = q.error(solved);
      // The ends are balls already; the midpoint is tested as the solution is.
      const bool mid_allowed = inside_shape(mid, su, sv);
      for (const Vec4& s : {su, sv, mid}) {
        const double e = q.error(s);
        if (e < best_error && (s != mid || mid_allowed)) best = s, best_error = e;
      }
    }
    Candidate c;
    const double length = o_.length_weight * 0.5 * q.A.trace() * (su.head<3>() - sv.head<3>()).squaredNorm();
    const double spread = o_.radius_weight * 0.5 * q.A.trace() * (su.w() - sv.w()) * (su.w() - sv.w());
    c.cost = (best_error + length + spread) * std::pow(stability_ratio(su, sv), 2);
    c.u = u, c.v = v;
    c.stamp_u = k_.stamp[std::size_t(u)], c.stamp_v = k_.stamp[std::size_t(v)];
    c.merged = best;
    queue_.push(c);
  }

  /// Whether `s`, merged from the balls `a` and `b`, is a ball of the shape
  /// (QuadricOptions::depth). A ball inside one of the two is (they are
  /// the shape's, or merged under this test), without a query.
  bool inside_shape(const Vec4& s, const Vec4& a, const Vec4& b) const {
    if (!o_.depth) return true;
    for (const Vec4* ball : {&a, &b})
      if ((s.head<3>() - ball->head<3>()).norm() + s.w() <= ball->w()) return true;
    // The signed distance is 1-Lipschitz: the depth at either end, less or
    // plus the way to it, decides most candidates without a query (homer:
    // all but about 900 of 248k a run). The margin, far above the
    // queries' rounding, keeps every decision the query's own.
    const Vec3 c = s.head<3>();
    const double margin = 1e-9 * (c.cwiseAbs().maxCoeff() + s.w());
    for (const Vec4* ball : {&a, &b}) {
      const double at = o_.depth(ball->head<3>()), far = (c - ball->head<3>()).norm();
      const double lower = at - far - margin, upper = at + far + margin;
      if (lower > 0.0 && s.w() <= lower + o_.overhang) return true;
      if (upper <= 0.0 || s.w() > upper + o_.overhang) return false;
    }
    const double depth = o_.depth(c);
    return depth > 0.0 && s.w() <= depth + o_.overhang;
  }

  /// v merged into u at the candidate's sphere.
  void collapse(const Candidate& c) {
    const Index u = c.u, v = c.v;
    const std::vector<Triangle> through_v = k_.triangles_at[std::size_t(v)];
    for (const Triangle& t : through_v) k_.remove_triangle(t);
    const std::vector<Index> next_v = k_.neighbours[std::size_t(v)];
    for (const Index w : next_v) k_.remove_edge(v, w);
    for (const Index w : next_v) k_.add_edge(u, w);
    for (const Triangle& t : through_v) {
      if (std::find(t.begin(), t.end(), u) != t.end()) continue;  // on the edge: gone
      Triangle moved = t;
      for (Index& i : moved)
        if (i == v) i = u;
      k_.add_triangle(sorted(moved[0], moved[1], moved[2]));
    }
    k_.alive[std::size_t(v)] = false;
    k_.held[std::size_t(u)] = k_.held[std::size_t(u)] || k_.held[std::size_t(v)];
    k_.quadric[std::size_t(u)] += k_.quadric[std::size_t(v)];
    if (!k_.planes.empty()) {
      // The shorter list appended to the longer: each plane is copied at
      // most log₂ n times over all the collapses.
      std::vector<Vec4> &pu = k_.planes[std::size_t(u)], &pv = k_.planes[std::size_t(v)];
      if (pu.size() < pv.size()) std::swap(pu, pv);
      pu.insert(pu.end(), pv.begin(), pv.end());
      std::vector<Vec4>().swap(pv);
    }
    k_.sphere[std::size_t(u)] = c.merged;
    ++k_.stamp[std::size_t(u)];
    for (const Index w : k_.neighbours[std::size_t(u)]) push(u, w);
    // Collapses the link condition refused near u may be allowed now.
    std::vector<Index> around = k_.neighbours[std::size_t(u)];
    around.push_back(u);
    for (const Index w : around) {
      auto found = blocked_.find(w);
      if (found == blocked_.end()) continue;
      const std::vector<Index> others = std::move(found->second);
      blocked_.erase(found);
      for (const Index x : others)
        if (x != u && w != u && k_.alive[std::size_t(x)] && k_.has_edge(w, x)) push(std::min(w, x), std::max(w, x));
    }
  }

  Complex& k_;
  const QuadricOptions& o_;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> queue_;
  std::map<Index, std::vector<Index>> blocked_;  // lookup only: never iterated
};

/// Whether the segment p q is too short for the skeleton file (its length
/// below 1e-8 × the largest coordinate magnitude, docs/cli_skeleton.md),
/// with margin.
bool too_short(const Vec3& p, const Vec3& q) {
  return (p - q).norm() <= 1e-6 * std::max(p.cwiseAbs().maxCoeff(), q.cwiseAbs().maxCoeff());
}

/// A triangle better given as its longest side: too thin for the skeleton
/// file's polygon rule (area ≥ 1e-8 × diameter², docs/cli_skeleton.md), or
/// narrower than `thin` × its smallest radius and × its longest side. Along a tube the Voronoi
/// faces are a narrow tangle about the axis, and their simplified triangles
/// strips far narrower than the tube: a SCALIS triangle's field is
/// normalised for a wide sheet, and a strip of them falls short of a tube
/// that a segment of the same radius makes.
bool degenerate(const Vec4& a, const Vec4& b, const Vec4& c, double thin) {
  const Vec3 p = a.head<3>(), q = b.head<3>(), r = c.head<3>();
  if (too_short(p, q) || too_short(q, r) || too_short(p, r)) return true;
  const double diameter = std::max({(q - p).norm(), (r - q).norm(), (p - r).norm()});
  const double area = (q - p).cross(r - p).norm() / 2;
  // The smallest altitude is 2 × area / the longest side; a strip is also
  // narrow for its length (a sheet's triangles, small beside its radius
  // where it is thick, are not).
  const double altitude = 2 * area / diameter;
  return area < 1e-6 * diameter * diameter ||
         (altitude < thin * std::min({a.w(), b.w(), c.w()}) && altitude < thin * diameter);
}

/// The live complex as a MedialMesh, renumbered in order. A degenerate
/// triangle gives its longest side as a tube edge (if no other triangle
/// holds it); an edge too short for the skeleton file is dropped.
MedialMesh to_mesh(const Complex& k, double thin_fraction) {
  MedialMesh mesh;
  std::vector<Index> number(k.sphere.size(), -1);
  for (std::size_t i = 0; i < k.sphere.size(); ++i)
    if (k.alive[i]) number[i] = Index(mesh.spheres.size()), mesh.spheres.push_back(k.sphere[i]);
  std::set<std::array<Index, 2>> sheet_edges, tube_edges;
  std::vector<Triangle> thin;
  for (const Triangle& t : k.triangles) {
    const Triangle r{number[std::size_t(t[0])], number[std::size_t(t[1])], number[std::size_t(t[2])]};
    const auto& s = mesh.spheres;
    if (degenerate(s[std::size_t(r[0])], s[std::size_t(r[1])], s[std::size_t(r[2])], thin_fraction)) {
      thin.push_back(r);
      continue;
    }
    mesh.triangles.push_back(r);
    sheet_edges.insert({r[0], r[1]}), sheet_edges.insert({r[1], r[2]}), sheet_edges.insert({r[0], r[2]});
  }
  for (std::size_t i = 0; i < k.sphere.size(); ++i)
    for (const Index j : k.neighbours[i])
      if (Index(i) < j) tube_edges.insert({number[i], number[std::size_t(j)]});
  for (const Triangle& t : thin) {
    // Its longest side, the other two dropped (they run along it).
    std::array<Index, 2> longest{t[0], t[1]};
    double length = -1.0;
    for (const auto& e : {std::array<Index, 2>{t[0], t[1]}, std::array<Index, 2>{t[1], t[2]}, std::array<Index, 2>{t[0], t[2]}}) {
      const double l = (mesh.spheres[std::size_t(e[0])].head<3>() - mesh.spheres[std::size_t(e[1])].head<3>()).norm();
      if (l > length) length = l, longest = e;
      tube_edges.erase(e);
    }
    tube_edges.insert(longest);
  }
  std::vector<bool> used(mesh.spheres.size(), false);
  for (const Triangle& t : mesh.triangles)
    for (const Index i : t) used[std::size_t(i)] = true;
  for (const auto& e : tube_edges) {
    if (sheet_edges.count(e)) continue;
    if (too_short(mesh.spheres[std::size_t(e[0])].head<3>(), mesh.spheres[std::size_t(e[1])].head<3>())) continue;
    mesh.edges.push_back(e);
    used[std::size_t(e[0])] = used[std::size_t(e[1])] = true;
  }
  for (Index i = 0; i < Index(mesh.spheres.size()); ++i)
    if (!used[std::size_t(i)]) mesh.isolated.push_back(i);
  return mesh;
}

}  // namespace

MedialMesh quadric_medial_mesh(const MedialGraph& graph, const QuadricOptions& o, QuadricReport* report) {
  QuadricReport r;
  Complex k = initial_complex(graph, o);
  r.tips_held = std::size_t(std::count(k.held.begin(), k.held.end(), true));
  r.vertices_before = k.sphere.size();
  r.triangles_before = k.triangles.size();
  r.euler_before = k.euler_characteristic();
  if (!k.sphere.empty()) {
    Simplifier simplifier(k, o);
    simplifier.run(r);
    if (o.depth && o.inside_samples > 0) {
      r.bridges_closed = close_bridged_sheets(k, o);
      r.holes_closed = close_sheet_holes(k, o);
    }
  }
  r.euler_after = k.euler_characteristic();
  if (report != nullptr) *report = r;
  return to_mesh(k, o.thin_triangle);
}

}  // namespace skelconv::reconstruct
