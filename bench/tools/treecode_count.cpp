// bench/tools/treecode_count.cpp — counts what a Cartesian Taylor treecode
// would cost on the 1,000-segment Cauchy 4 random walk of
// bench/mesh_bench.cpp, at the vertices of its mesh, to a proven error bound
// (docs/field.md, "Infinite-support primitives": the numbers there are this
// program's output).
//
// Not built by CMake (a derivation, ~2 minutes):
//   build/release/src/skelconv mesh walk.json -o /tmp/walk.ply --ascii --method grid --size 0.5 --iso 0.37924406053543108
//   g++ -O2 -std=c++20 bench/tools/treecode_count.cpp -o /tmp/treecode_count && /tmp/treecode_count /tmp/walk.ply
// where walk.json is `/tmp/treecode_count --walk` (the skeleton of
// skelconv_bench_mesh's "segment cauchy" row, 1,000 segments) and the iso
// is f at 0.3 from the middle of one such segment, as that bench takes it.
//
// Prints:
//  1. the bound against the true truncation error of one cluster, and what a
//     Taylor coefficient costs here;
//  2. the share of f carried by segments beyond a distance R;
//  3. for every (vertex, cluster) pair with ρ/D ≤ 0.5, the degree that meets
//     the budget ε f at 1e-12 and the cluster's cost over its direct sum;
//  4. the cost per point of the best tree traversal for ε = 1e-12 … 1e-4;
//  5. the Gauss–Legendre nodes per segment that meet an equal share ε f/N,
//     and what a node (f and ∇f of the kernel) costs here.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Vec = std::array<double, 3>;
Vec operator-(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
struct Segment {
  Vec a, b;
};

// The kernel: Cauchy of degree i = 4, s = 4, K = (1 + s r²)^−2 =
// s^−α (r² + c²)^−α with α = i/2 = 2, c² = 1/s.
constexpr double s = 4, alpha = 2, c2 = 1 / s;
constexpr int two_alpha = 4;
double kernel(double r2) { return 1 / ((1 + s * r2) * (1 + s * r2)); }

// The cost model: a Cauchy 4 segment summed directly inside the mesher
// (docs/mesh.md, "Performance": 84–94 µs for 1,000), and one Taylor
// coefficient with its share of the moments' dot products (section 1
// measures ~20 ns in a plain implementation; 2 ns is about its
// floating-point work alone, so the counts favour the tree).
constexpr double direct_ns = 84, coefficient_ns = 2;

/// The walk of bench/mesh_bench.cpp (walk_skeleton): unit steps from the
/// centre of a cube of side 2 count^(1/3) + 2, reflected at its faces.
std::vector<Segment> walk(int count) {
  std::mt19937_64 random(20131);
  const auto uniform = [&random] { return double(random() >> 11) * 0x1.0p-53; };
  const double side = 2 * std::cbrt(double(count)) + 2;
  Vec p{side / 2, side / 2, side / 2};
  std::vector<Segment> segments;
  for (int k = 0; k < count; ++k) {
    const double z = 2 * uniform() - 1, phi = 2 * std::numbers::pi * uniform();
    Vec d{std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
    for (int i = 0; i < 3; ++i) {
      if (p[i] + d[i] < 0 || p[i] + d[i] > side) d[i] = -d[i];
    }
    const Vec b{p[0] + d[0], p[1] + d[1], p[2] + d[2]};
    segments.push_back({p, b});
    p = b;
  }
  return segments;
}

/// The vertices of an ASCII PLY written by `skelconv mesh --ascii`.
std::vector<Vec> read_vertices(const char* path) {
  std::ifstream in(path);
  std::string line;
  std::size_t count = 0;
  while (std::getline(in, line)) {
    if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    if (line == "end_header") break;
  }
  std::vector<Vec> vertices(count);
  for (Vec& v : vertices) {
    std::getline(in, line);
    std::istringstream(line) >> v[0] >> v[1] >> v[2];
  }
  return vertices;
}

/// f of one segment by the 64-point midpoint rule: ~1e-6 relative at the
/// mesh's vertices, enough for the budget ε f it scales.
double segment_field(const Segment& seg, const Vec& p) {
  const double length = norm(seg.b - seg.a);
  double f = 0;
  for (int q = 0; q < 64; ++q) {
    const double t = (q + 0.5) / 64;
    const Vec x{seg.a[0] + t * (seg.b[0] - seg.a[0]), seg.a[1] + t * (seg.b[1] - seg.a[1]),
                seg.a[2] + t * (seg.b[2] - seg.a[2])};
    const Vec d = p - x;
    f += kernel(dot(d, d));
  }
  return f * length / 64;
}

/// Σ_{n>p} binom(n + 2α − 1, n) t^n: with W D^−2α s^−α in front, the bound
/// on what the expansion of degree p leaves out (docs/field.md).
double tail(double t, int p) {
  double term = 1;  // binom(n + 2α − 1, n) t^n at n = 0
  for (int n = 1; n <= p; ++n) term *= t * (n + two_alpha - 1) / n;
  double sum = 0;
  for (int n = p + 1; n < p + 4000; ++n) {
    term *= t * (n + two_alpha - 1) / n;
    sum += term;
    if (term < 1e-30 * sum) break;
  }
  return sum;
}

/// Coefficients of the number of a degree-p expansion with ∇f: those of degree p + 1.
double coefficients(int p) { return (p + 2.0) * (p + 3.0) * (p + 4.0) / 6.0; }

/// Taylor coefficients b_k of G(x + h) = Σ b_k h^k, G = (|x|² + c²)^−α, for
/// |k| ≤ p, in a (p + 1)³ array, by the recurrence of docs/field.md.
void taylor_coefficients(const Vec& x, int p, std::vector<double>& b) {
  const int n = p + 1;
  b.assign(std::size_t(n * n * n), 0.0);
  const auto at = [n](int i, int j, int k) { return std::size_t((i * n + j) * n + k); };
  const double q = dot(x, x) + c2;
  b[0] = std::pow(q, -alpha);
  for (int m = 1; m <= p; ++m) {
    for (int i = m; i >= 0; --i) {
      for (int j = m - i; j >= 0; --j) {
        const int k[3] = {i, j, m - i - j};
        double first = 0, second = 0;
        for (int axis = 0; axis < 3; ++axis) {
          int l[3] = {k[0], k[1], k[2]};
          if (k[axis] >= 1) {
            --l[axis];
            first += x[axis] * b[at(l[0], l[1], l[2])];
          }
          if (k[axis] >= 2) {
            --l[axis];
            second += b[at(l[0], l[1], l[2])];
          }
        }
        b[at(k[0], k[1], k[2])] = -((2 * m - 2 + 2 * alpha) * first + (m - 2 + 2 * alpha) * second) / (m * q);
      }
    }
  }
}

/// Section 1: 8 unit segments of a random walk, 64 points each, expanded
/// around their box's centre at distances 2–5 ρ in 200 directions.
void bound_against_truncation() {
  std::mt19937 random(3);
  std::normal_distribution<> normal;
  std::vector<Vec> sources;
  Vec p{0, 0, 0};
  for (int k = 0; k < 8; ++k) {
    Vec d{normal(random), normal(random), normal(random)};
    const double l = norm(d);
    for (int q = 0; q < 64; ++q) {
      const double t = (q + 0.5) / 64;
      sources.push_back({p[0] + t * d[0] / l, p[1] + t * d[1] / l, p[2] + t * d[2] / l});
    }
    for (int i = 0; i < 3; ++i) p[i] += d[i] / l;
  }
  Vec lo = sources[0], hi = sources[0];
  for (const Vec& y : sources) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], y[i]), hi[i] = std::max(hi[i], y[i]);
  }
  const Vec centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  double rho = 0;
  for (const Vec& y : sources) rho = std::max(rho, norm(y - centre));
  const double weight = 1.0 / 64, total = weight * double(sources.size());
  std::printf("1. one cluster: 8 unit segments, rho %.3f\n", rho);
  std::vector<double> b;
  for (double distance : {2.0, 3.0, 5.0}) {
    for (int p : {4, 8, 12, 16, 24}) {
      const int n = p + 1;
      double worst_error = 0, worst_bound = 0;
      for (int direction = 0; direction < 200; ++direction) {
        Vec u{normal(random), normal(random), normal(random)};
        const double l = norm(u);
        const Vec x{distance * rho * u[0] / l, distance * rho * u[1] / l, distance * rho * u[2] / l};
        taylor_coefficients(x, p, b);
        long double exact = 0;
        double expanded = 0;
        for (const Vec& y : sources) {
          long double r2 = 0;
          for (int i = 0; i < 3; ++i) r2 += std::pow((long double)(x[i] + centre[i] - y[i]), 2);
          exact += weight * std::pow(r2 + c2, -(long double)alpha);
          const Vec h = centre - y;  // G(x − (y − centre))
          for (int i = 0; i <= p; ++i)
            for (int j = 0; i + j <= p; ++j)
              for (int k = 0; i + j + k <= p; ++k)
                expanded += weight * b[std::size_t((i * n + j) * n + k)] * std::pow(h[0], i) * std::pow(h[1], j) *
                            std::pow(h[2], k);
        }
        const double d = std::sqrt(dot(x, x) + c2);
        worst_error = std::max(worst_error, std::fabs(expanded - double(exact)) / double(exact));
        worst_bound = std::max(worst_bound, total * std::pow(d, -2 * alpha) * tail(rho / d, p) / double(exact));
      }
      std::printf("   |x| = %.0f rho, p = %2d: worst error %.2e, bound %.2e (x%.0f)\n", distance, p, worst_error,
                  worst_bound, worst_bound / worst_error);
    }
  }
  for (int p : {8, 16, 24}) {
    Vec x{3, 1, 2};
    const int repeats = 2000;
    const auto start = std::chrono::steady_clock::now();
    double sink = 0;
    for (int r = 0; r < repeats; ++r) {
      x[0] += 1e-9;
      taylor_coefficients(x, p, b);
      sink += b[1];
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    std::printf("   degree %d: %.1f ns per coefficient (%g)\n", p, ns / repeats / ((p + 1.0) * (p + 2) * (p + 3) / 6),
                sink);
  }
}

/// A binary tree of segments split at the median midpoint along the
/// longest axis of the box, leaves of at most `leaf` segments.
struct Node {
  Vec centre;
  double rho = 0, weight = 0;  // radius about centre, Σ |AB|
  int first = 0, end = 0, left = -1, right = -1;
};
int build(std::vector<Segment>& segments, std::vector<Node>& nodes, int first, int end, int leaf) {
  Vec lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int k = first; k < end; ++k) {
    for (const Vec& q : {segments[k].a, segments[k].b}) {
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], q[i]), hi[i] = std::max(hi[i], q[i]);
    }
  }
  Node node;
  node.centre = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  for (int k = first; k < end; ++k) {
    node.rho = std::max({node.rho, norm(segments[k].a - node.centre), norm(segments[k].b - node.centre)});
    node.weight += norm(segments[k].b - segments[k].a);
  }
  node.first = first;
  node.end = end;
  const int id = int(nodes.size());
  nodes.push_back(node);
  if (end - first <= leaf) return id;
  const Vec extent = hi - lo;
  const int axis = int(std::max_element(extent.begin(), extent.end()) - extent.begin());
  const int middle = (first + end) / 2;
  std::nth_element(segments.begin() + first, segments.begin() + middle, segments.begin() + end,
                   [axis](const Segment& u, const Segment& v) { return u.a[axis] + u.b[axis] < v.a[axis] + v.b[axis]; });
  const int left = build(segments, nodes, first, middle, leaf);
  const int right = build(segments, nodes, middle, end, leaf);
  nodes[id].left = left;
  nodes[id].right = right;
  return id;
}

/// The lowest degree ≤ max_degree whose bound is ≤ budget, or −1.
int degree_for(const Node& node, const Vec& p, double budget, int max_degree = 60) {
  const Vec x = p - node.centre;
  const double d = std::sqrt(dot(x, x) + c2), t = node.rho / d;
  if (!(t < 1) || norm(x) <= node.rho) return -1;
  const double scale = node.weight * std::pow(s, -alpha) * std::pow(d, -2 * alpha);
  for (int degree = 0; degree <= max_degree; ++degree) {
    if (scale * tail(t, degree) <= budget) return degree;
  }
  return -1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--walk") == 0) {
    std::printf("{\"primitives\": [");
    const std::vector<Segment> segments = walk(1000);
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const Segment& g = segments[k];
      std::printf("%s{\"type\": \"segment\", \"a\": [%.17g, %.17g, %.17g], \"b\": [%.17g, %.17g, %.17g], "
                  "\"kernel\": {\"family\": \"cauchy\", \"degree\": 4, \"s\": 4}}",
                  k ? ",\n" : "\n", g.a[0], g.a[1], g.a[2], g.b[0], g.b[1], g.b[2]);
    }
    std::printf("]}\n");
    return 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: treecode_count MESH.ply | treecode_count --walk\n");
    return 2;
  }
  bound_against_truncation();

  std::vector<Segment> segments = walk(1000);
  const std::vector<Vec> all_vertices = read_vertices(argv[1]);
  std::vector<Vec> vertices;  // 400 of them, evenly through the file
  for (int k = 0; k < 400; ++k) vertices.push_back(all_vertices[all_vertices.size() * k / 400]);
  std::vector<double> field;
  for (const Vec& p : vertices) {
    double f = 0;
    for (const Segment& g : segments) f += segment_field(g, p);
    field.push_back(f);
  }

  // 2. The share of f beyond R (distance from a segment's midpoint).
  std::printf("2. share of f carried by the segments beyond R (mean, max over the vertices)\n");
  for (double radius : {2.0, 3.0, 5.0, 10.0, 15.0}) {
    double mean = 0, most = 0;
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      double far = 0;
      for (const Segment& g : segments) {
        const Vec middle{(g.a[0] + g.b[0]) / 2, (g.a[1] + g.b[1]) / 2, (g.a[2] + g.b[2]) / 2};
        if (norm(vertices[v] - middle) > radius) far += segment_field(g, vertices[v]);
      }
      mean += far / field[v] / double(vertices.size());
      most = std::max(most, far / field[v]);
    }
    std::printf("   R = %4.0f: %.3g, %.3g\n", radius, mean, most);
  }

  std::vector<Node> nodes;
  build(segments, nodes, 0, int(segments.size()), 8);

  // 3. Degree and cost of every cluster with ρ/D ≤ 0.5, at ε = 1e-12.
  std::printf("3. (vertex, cluster) pairs with rho/D <= 0.5 at 1e-12: degree quartiles, cost over the direct sum\n");
  const char* class_names[3] = {"<= 8 segments", "9-64 segments", "> 64 segments"};
  std::vector<double> degrees[3], ratios[3];
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    for (const Node& node : nodes) {
      const Vec x = vertices[v] - node.centre;
      if (node.rho > 0.5 * std::sqrt(dot(x, x) + c2)) continue;
      const int size = node.end - node.first;
      const int c = size <= 8 ? 0 : size <= 64 ? 1 : 2;
      int degree = degree_for(node, vertices[v], 1e-12 * field[v], 200);
      if (degree < 0) degree = 201;
      degrees[c].push_back(degree);
      ratios[c].push_back(coefficient_ns * coefficients(degree) / (direct_ns * size));
    }
  }
  for (int c = 0; c < 3; ++c) {
    auto& d = degrees[c];
    auto& r = ratios[c];
    if (d.empty()) continue;
    std::sort(d.begin(), d.end());
    std::sort(r.begin(), r.end());
    const std::size_t m = d.size(), cheaper = std::size_t(std::lower_bound(r.begin(), r.end(), 1.0) - r.begin());
    std::printf("   %s: %zu pairs, degree %.0f %.0f %.0f, cost ratio %.2f %.2f %.2f, cheaper in %zu\n", class_names[c],
                m, d[m / 4], d[m / 2], d[3 * m / 4], r[m / 4], r[m / 2], r[3 * m / 4], cheaper);
  }

  // 4. The best traversal: at every node the cheaper of accepting it (at the
  // lowest degree that meets the whole budget ε f, more than any real
  // allocation can grant) and opening it (a leaf: its direct sum).
  std::printf("4. cost per point, leaves of 8 (and of 4, 16, 32 at 1e-12)\n");
  const auto count = [&](const std::vector<Node>& tree, double epsilon) {
    double cost = 0, direct = 0, accepted = 0;
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      const Vec& p = vertices[v];
      const double budget = epsilon * field[v];
      std::function<double(int, double&, double&)> best = [&](int id, double& n_direct, double& n_accepted) {
        const Node& node = tree[id];
        const int degree = degree_for(node, p, budget);
        const double accept = degree >= 0 ? coefficient_ns * coefficients(degree) : INFINITY;
        double opened_direct = 0, opened_accepted = 0, open;
        if (node.left < 0) {
          open = direct_ns * (node.end - node.first);
          opened_direct = node.end - node.first;
        } else {
          open = best(node.left, opened_direct, opened_accepted) + best(node.right, opened_direct, opened_accepted);
        }
        if (accept < open) {
          n_accepted += 1;
          return accept;
        }
        n_direct += opened_direct;
        n_accepted += opened_accepted;
        return open;
      };
      cost += best(0, direct, accepted);
    }
    const double n = double(vertices.size());
    std::printf("   eps %.0e: %.1f segments direct, %.1f clusters, %.2f us against %.2f us: %.2fx\n", epsilon,
                direct / n, accepted / n, cost / n / 1000, direct_ns * double(segments.size()) / 1000,
                direct_ns * double(segments.size()) * n / cost);
  };
  for (double epsilon : {1e-12, 1e-10, 1e-8, 1e-6, 1e-4}) count(nodes, epsilon);
  for (int leaf : {4, 16, 32}) {
    std::vector<Node> other;
    build(segments, other, 0, int(segments.size()), leaf);
    std::printf("   leaves of %d:", leaf);
    count(other, 1e-12);
  }

  // 5. Gauss–Legendre per segment at ε f / N (ATAP Thm 19.3): on [−1, 1],
  // q(t) = h² ((t − a)² + b²) has its zeros at a ± ib; on the ellipse E_r
  // inside the one through them, |integrand| ≤ M, sampled at 256 points.
  std::printf("5. Gauss-Legendre nodes per segment for an equal share 1e-12 f / N (200 vertices)\n");
  std::vector<double> histogram(41, 0);
  double pairs = 0, nodes_total = 0;
  for (std::size_t v = 0; v < vertices.size(); v += 2) {
    const Vec& p = vertices[v];
    const double share = 1e-12 * field[v] / double(segments.size());
    for (const Segment& g : segments) {
      Vec e = g.b - g.a;
      const double h = norm(e) / 2;
      for (double& c : e) c /= 2 * h;
      const Vec x = p - Vec{(g.a[0] + g.b[0]) / 2, (g.a[1] + g.b[1]) / 2, (g.a[2] + g.b[2]) / 2};
      const double a = dot(x, e) / h, b = std::sqrt(std::max(0.0, dot(x, x) - dot(x, e) * dot(x, e)) + c2) / h;
      const std::complex<double> z(a, b);
      double r_zero = std::abs(z + std::sqrt(z - 1.0) * std::sqrt(z + 1.0));
      if (r_zero < 1) r_zero = 1 / r_zero;
      int best = 40;  // 40: more than any far rule (the exact function)
      for (int j = 1; j <= 24; ++j) {
        const double r = std::pow(r_zero, j / 25.0);
        double smallest = INFINITY;
        for (int k = 0; k < 256; ++k) {
          const double theta = 2 * std::numbers::pi * k / 256;
          const std::complex<double> t(0.5 * (r + 1 / r) * std::cos(theta), 0.5 * (r - 1 / r) * std::sin(theta));
          smallest = std::min(smallest, std::abs((t - a) * (t - a) + b * b));
        }
        const double m = h * std::pow(s, -alpha) * std::pow(h * h * 0.98 * smallest, -alpha);
        for (int n = 1; n < best; ++n) {
          // n points: ATAP Thm 19.3 with its I_(n−1) (its I_m has m + 1 points): ρ^(2 − 2n).
          if (64.0 / 15 * m * std::pow(r, 2.0 - 2.0 * n) / (r * r - 1) <= share) {
            best = n;
            break;
          }
        }
      }
      histogram[best] += 1;
      pairs += 1;
      nodes_total += best;
    }
  }
  for (int n = 0; n <= 40; ++n) {
    if (histogram[n] > 0) std::printf("   %d nodes: %.2f%%\n", n, 100 * histogram[n] / pairs);
  }
  std::printf("   mean %.2f nodes\n", nodes_total / pairs);

  // One node: K and ∇K at P − y, weighted, over 3,830 nodes in the cube.
  std::mt19937 random(1);
  std::uniform_real_distribution<> in_cube(0, 22);
  std::vector<Vec> where(3830);
  for (Vec& y : where) y = {in_cube(random), in_cube(random), in_cube(random)};
  const int repeats = 20000;
  double sink = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    const Vec p{11 + 1e-9 * r, 11, 11};
    double f = 0, g[3] = {0, 0, 0};
    for (const Vec& y : where) {
      const Vec d = p - y;
      const double inverse = 1 / (1 + s * dot(d, d)), k = 0.1 * inverse * inverse, slope = -2 * two_alpha * k * inverse;
      f += k;
      for (int i = 0; i < 3; ++i) g[i] += slope * d[i];
    }
    sink += f + g[0] + g[1] + g[2];
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  std::printf("   %.2f ns per node (%g)\n", ns / repeats / double(where.size()), sink);
}
