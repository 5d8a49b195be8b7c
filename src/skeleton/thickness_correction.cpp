// Implementation of thickness_correction.hpp (the file comment there gives
// the method; docs/thickness_correction.md its use).
#include "skelconv/skeleton/thickness_correction.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv {
namespace {

/// Points farther than this fraction of the skeleton's size from the plane
/// through the first non-collinear nodes make the graph non-planar.
constexpr double planarity_ratio = 1e-9;
/// The power p of the fit's objective Σ|e_j|^p (departure_cost). Least
/// squares (2): higher powers approach the maximum the tolerance bounds,
/// but on the test graphs they converge slower and end farther from τ.
constexpr double fit_power = 2;
/// Levenberg–Marquardt damping: start, growth on a rejected step, floor.
constexpr double damping_start = 1e-4, damping_growth = 10.0, damping_floor = 1e-12;

const char* primitive_type_name(const Primitive& p) {
  static constexpr const char* names[] = {"segment", "polygon", "scalis_segment", "scalis_triangle", "point"};
  return names[p.index()];
}

void check_segment(const Segment& s, const Segment* first, const std::string& where) {
  const KernelSpec& k = s.kernel();
  if (k.family != KernelFamily::compact) {
    throw InputError(fmt::format("the thickness correction needs the \"compact\" kernel (its finite support keeps the "
                                 "correction local), got \"{}\"",
                                 family_name(k.family)),
                     where + ".kernel.family");
  }
  const std::vector<int> degrees = Segment::supported_degrees(KernelFamily::compact, 1);
  if (std::find(degrees.begin(), degrees.end(), k.degree) == degrees.end()) {
    throw InputError(fmt::format("degree {} has no linear-weight closed form (the corrected weights are linear)",
                                 k.degree),
                     where + ".kernel.degree");
  }
  if (first != nullptr && (first->kernel().degree != k.degree || first->kernel().R != k.R)) {
    throw InputError("differs from primitives[0].kernel: the correction needs one kernel for the whole graph",
                     where + ".kernel");
  }
}

std::size_t node_of(std::vector<Vec3>& nodes, const Vec3& p, double merge) {
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if ((nodes[k] - p).norm() <= merge) return k;
  }
  nodes.push_back(p);
  return nodes.size() - 1;
}

/// The unit normal of the plane holding every node (any unit vector normal
/// to the line for a collinear graph). InputError if there is none.
Vec3 plane_normal(const SegmentGraph& g, double size) {
  const Vec3 o = g.nodes[0];
  const Vec3 d = (g.nodes[g.edges[0].b] - g.nodes[g.edges[0].a]).normalized();
  Vec3 normal = Vec3::Zero();
  for (const Vec3& p : g.nodes) {
    const Vec3 c = d.cross(p - o);
    if (c.norm() > planarity_ratio * size) {
      normal = c.normalized();
      break;
    }
  }
  if (normal.isZero()) {  // collinear: the axis least aligned with the line gives a normal
    Eigen::Index axis = 0;
    d.cwiseAbs().minCoeff(&axis);
    normal = d.cross(Vec3::Unit(axis)).normalized();
  }
  for (const SegmentGraph::Edge& e : g.edges) {
    for (std::size_t n : {e.a, e.b}) {
      if (std::abs(normal.dot(g.nodes[n] - o)) > planarity_ratio * size) {
        throw InputError("the segments are not in one plane: the correction measures the thickness along the "
                         "plane's normal",
                         e.location);
      }
    }
  }
  return normal;
}

}  // namespace

SegmentGraph segment_graph_of(const Skeleton& skeleton) {
  SegmentGraph graph;
  graph.iso = skeleton.iso();
  std::vector<const Segment*> segments;
  for (std::size_t k = 0; k < skeleton.child_count(Skeleton::root); ++k) {
    const std::string where = fmt::format("primitives[{}]", k);
    const auto [is_blend, index] = skeleton.child(Skeleton::root, k);
    if (is_blend) {
      throw InputError("a blend node: the thickness correction works on the sum of top-level segments", where);
    }
    const Primitive& p = skeleton.primitives()[index];
    const Segment* s = std::get_if<Segment>(&p);
    if (s == nullptr) {
      throw InputError(fmt::format("the thickness correction supports \"segment\" primitives only, got \"{}\"",
                                   primitive_type_name(p)),
                       where + ".type");
    }
    check_segment(*s, segments.empty() ? nullptr : segments[0], where);
    segments.push_back(s);
  }
  if (segments.empty()) throw InputError("no segment: there is no graph to correct", "primitives");
  Eigen::AlignedBox3d box;
  for (const Segment* s : segments) box.extend(s->a()).extend(s->b());
  const double size = box.diagonal().norm();
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const std::size_t a = node_of(graph.nodes, segments[k]->a(), node_merge_ratio * size);
    const std::size_t b = node_of(graph.nodes, segments[k]->b(), node_merge_ratio * size);
    graph.edges.push_back({a, b, fmt::format("primitives[{}]", k)});
  }
  graph.kernel = segments[0]->kernel();
  graph.normal = plane_normal(graph, size);
  return graph;
}

Skeleton weighted_skeleton(const SegmentGraph& graph, const std::vector<double>& weights,
                           const std::vector<double>& point_weights) {
  Skeleton skeleton({}, graph.iso);
  for (const SegmentGraph::Edge& e : graph.edges) {
    const double wa = weights[e.a], wb = weights[e.b];
    skeleton.add(Segment(graph.nodes[e.a], graph.nodes[e.b], graph.kernel, {wa, wb - wa}));
  }
  for (std::size_t k = 0; k < point_weights.size(); ++k) {
    if (point_weights[k] > 0) skeleton.add(PointPrimitive(graph.nodes[k], graph.kernel, point_weights[k]));
  }
  return skeleton;
}

std::string weighted_skeleton_json(const SegmentGraph& graph, const std::vector<double>& weights,
                                   const std::vector<double>& point_weights) {
  const auto point = [](const Vec3& p) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", p.x(), p.y(), p.z()); };
  std::string out = "{\"primitives\": [\n";
  for (std::size_t k = 0; k < graph.edges.size(); ++k) {
    const SegmentGraph::Edge& e = graph.edges[k];
    const double wa = weights[e.a], wb = weights[e.b];
    out += fmt::format(
        "  {{\"type\": \"segment\", \"a\": {}, \"b\": {}, \"weight\": [{:.17g}, {:.17g}], "
        "\"kernel\": {{\"family\": \"compact\", \"degree\": {}, \"R\": {:.17g}}}}}{}",
        point(graph.nodes[e.a]), point(graph.nodes[e.b]), wa, wb - wa, graph.kernel.degree, graph.kernel.R,
        k + 1 < graph.edges.size() ? ",\n" : "");
  }
  for (std::size_t k = 0; k < point_weights.size(); ++k) {
    if (!(point_weights[k] > 0)) continue;
    out += fmt::format(
        ",\n  {{\"type\": \"point\", \"center\": {}, \"weight\": {:.17g}, "
        "\"kernel\": {{\"family\": \"compact\", \"degree\": {}, \"R\": {:.17g}}}}}",
        point(graph.nodes[k]), point_weights[k], graph.kernel.degree, graph.kernel.R);
  }
  out += fmt::format("\n], \"iso\": {:.17g}}}\n", graph.iso);
  return out;
}

double thickness_along(const Skeleton& field, const Vec3& foot, const Vec3& normal, double iso, double reach,
                       int scan_steps) {
  const auto g = [&](double r) { return field.value(foot + r * normal) - iso; };
  // The outermost crossing: scan inwards from the reach for the first
  // sample at or above iso.
  double hi = reach, g_hi = g(hi);
  if (g_hi >= 0) throw EvaluationError(fmt::format("the field is still above iso at the reach {:.6g}", reach));
  double lo = hi, g_lo = g_hi;
  for (int k = scan_steps - 1; k >= 0 && g_lo < 0; --k) {
    hi = lo, g_hi = g_lo;
    lo = reach * k / scan_steps, g_lo = g(lo);
  }
  if (g_lo < 0) return 0.0;  // below iso down to the skeleton: no surface over this point
  // Regula falsi safeguarded by bisection: a bisection whenever the secant
  // point leaves the middle half of the bracket, so the bracket at least
  // shrinks to 3/4 per step.
  for (int it = 0; it < 200 && hi - lo > 1e-12 * reach; ++it) {
    double r = lo + (hi - lo) * g_lo / (g_lo - g_hi);
    if (!(r > lo + 0.25 * (hi - lo) && r < hi - 0.25 * (hi - lo))) r = 0.5 * (lo + hi);
    const double gr = g(r);
    if (gr >= 0) lo = r, g_lo = gr;
    else hi = r, g_hi = gr;
  }
  return lo + (hi - lo) * g_lo / (g_lo - g_hi);
}

namespace {

void check_options(const SegmentGraph& graph, const ThicknessCorrectionOptions& o) {
  if (!(o.thickness > 0) || !(o.thickness < graph.kernel.R)) {
    throw InputError(fmt::format("must be > 0 and below the kernel's support radius R = {:.6g}, got {:.6g}",
                                 graph.kernel.R, o.thickness),
                     "thickness");
  }
  if (!(o.tolerance > 0 && o.tolerance < 1)) {
    throw InputError(fmt::format("must be in (0, 1), got {:.6g}", o.tolerance), "tolerance");
  }
  if (o.max_iterations < 0) throw InputError("must be >= 0", "max_iterations");
  // Each ramp node is an unknown of the dense least-squares fit, and beyond
  // 100 its spacing R/ramp_nodes is below the samples' (τ/4, τ < R) for any
  // τ above R/25: unknowns no sample tells apart. The bound also keeps an
  // absurd count (1e9) from running without end.
  if (o.ramp_nodes < 1 || o.ramp_nodes > 100) {
    throw InputError(fmt::format("must be in [1, 100], got {}", o.ramp_nodes), "ramp_nodes");
  }
  if (!(o.regularisation >= 0)) throw InputError("must be >= 0", "regularisation");
  if (!(o.samples_per_thickness >= 1 && o.samples_per_thickness <= 100)) {
    throw InputError("must be in [1, 100]", "samples_per_thickness");
  }
}

/// w_τ = iso / f₁(τ), f₁ the field at distance τ from the middle of a
/// segment of weight 1 and half-length R: its support ball (radius R) meets
/// only skeleton, so f₁ is the infinite line's field (Zanni §4.3, fig. 11).
double base_weight(const KernelSpec& kernel, double iso, double tau) {
  const Segment line(Vec3(-kernel.R, 0, 0), Vec3(kernel.R, 0, 0), kernel, {1.0});
  return iso / line.value(Vec3(0, tau, 0));
}

/// Sample feet: on each edge, t = j/n, j = 0..n, n ≥ samples_per_thickness · length / τ.
std::vector<ThicknessSample> sample_layout(const SegmentGraph& g, const ThicknessCorrectionOptions& o) {
  std::vector<ThicknessSample> samples;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const Vec3 a = g.nodes[g.edges[e].a], b = g.nodes[g.edges[e].b];
    const int n = std::max(1, int(std::ceil(o.samples_per_thickness * (b - a).norm() / o.thickness)));
    for (int j = 0; j <= n; ++j) {
      const double t = double(j) / n;
      samples.push_back({e, t, a + t * (b - a), 0.0});
    }
  }
  return samples;
}

void measure(std::vector<ThicknessSample>& samples, const Skeleton& field, const SegmentGraph& g) {
  for (ThicknessSample& s : samples) s.thickness = thickness_along(field, s.foot, g.normal, g.iso, g.kernel.R);
}

double worst_departure(const std::vector<ThicknessSample>& samples, double tau) {
  double worst = 0;
  for (const ThicknessSample& s : samples) worst = std::max(worst, std::abs(s.thickness - tau) / tau);
  return worst;
}

std::vector<std::size_t> nodes_to_correct(const SegmentGraph& g, const std::vector<ThicknessSample>& samples,
                                          const ThicknessCorrectionOptions& o) {
  std::vector<std::size_t> nodes;
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    for (const ThicknessSample& s : samples) {
      if (std::abs(s.thickness - o.thickness) > o.tolerance * o.thickness &&
          (s.foot - g.nodes[n]).norm() < g.kernel.R) {
        nodes.push_back(n);
        break;
      }
    }
  }
  return nodes;
}

/// A split point of an edge: its distance from the edge's node a, and
/// whether its weight is free (a ramp point) or w_τ (the collar at R).
struct SplitPoint {
  double distance;
  bool free;
};

/// Step 4's split: `free_node[k]` says whether node k of the result is free.
SegmentGraph refine(const SegmentGraph& g, const std::vector<std::size_t>& corrected, int ramp_nodes,
                    std::vector<bool>& free_node) {
  std::vector<bool> is_corrected(g.nodes.size(), false);
  for (std::size_t n : corrected) is_corrected[n] = true;
  SegmentGraph r = g;
  r.edges.clear();
  free_node = is_corrected;
  for (const SegmentGraph::Edge& e : g.edges) {
    const Vec3 a = g.nodes[e.a], b = g.nodes[e.b];
    const double length = (b - a).norm();
    std::vector<SplitPoint> splits;
    for (int side = 0; side < 2; ++side) {
      const bool here = is_corrected[side == 0 ? e.a : e.b], there = is_corrected[side == 0 ? e.b : e.a];
      if (!here) continue;
      // Ramps from both ends share the edge: each keeps to its half.
      const double limit = (there ? 0.5 : 1.0) * length * (1 - 1e-9);
      for (int k = 1; k <= ramp_nodes && k * g.kernel.R / ramp_nodes < limit; ++k) {
        const double d = k * g.kernel.R / ramp_nodes;
        splits.push_back({side == 0 ? d : length - d, k < ramp_nodes});
      }
    }
    std::sort(splits.begin(), splits.end(), [](const SplitPoint& x, const SplitPoint& y) { return x.distance < y.distance; });
    std::size_t previous = e.a;
    for (const SplitPoint& s : splits) {
      r.nodes.push_back(a + (s.distance / length) * (b - a));
      free_node.push_back(s.free);
      r.edges.push_back({previous, r.nodes.size() - 1, e.location});
      previous = r.nodes.size() - 1;
    }
    r.edges.push_back({previous, e.b, e.location});
  }
  return r;
}

/// The unknowns: the hat weights of the free nodes and the point weights of
/// the corrected nodes; column[k] / point_column[k] place node k's in the
/// parameter vector (−1: not an unknown).
struct Unknowns {
  std::vector<Eigen::Index> column, point_column;
  Eigen::Index count = 0;
};

/// ∂r_j/∂p for every unknown p: −φ_p(Q_j)/(n·∇f(Q_j)), with φ_p the field
/// of unit weight on p's support (a node's hat function: weight 1 at the
/// node, linear to 0 at its neighbours; a point primitive at the node) and
/// Q_j the measured surface point.
Eigen::MatrixXd thickness_jacobian(const SegmentGraph& r, const std::vector<ThicknessSample>& samples,
                                   const Skeleton& field, const Unknowns& u) {
  std::vector<Segment> from_a, from_b;  // hat pieces: w(t) = 1 − t and w(t) = t
  for (const SegmentGraph::Edge& e : r.edges) {
    from_a.emplace_back(r.nodes[e.a], r.nodes[e.b], r.kernel, std::initializer_list<double>{1.0, -1.0});
    from_b.emplace_back(r.nodes[e.a], r.nodes[e.b], r.kernel, std::initializer_list<double>{0.0, 1.0});
  }
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(Eigen::Index(samples.size()), u.count);
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const Vec3 q = samples[j].foot + samples[j].thickness * r.normal;
    const double slope = r.normal.dot(field.gradient(q));
    if (!(slope < 0)) continue;  // no outward decrease: this sample gives no direction
    const auto row = Eigen::Index(j);
    for (std::size_t e = 0; e < r.edges.size(); ++e) {
      if (u.column[r.edges[e].a] >= 0) jacobian(row, u.column[r.edges[e].a]) -= from_a[e].value(q) / slope;
      if (u.column[r.edges[e].b] >= 0) jacobian(row, u.column[r.edges[e].b]) -= from_b[e].value(q) / slope;
    }
    for (std::size_t k = 0; k < u.point_column.size(); ++k) {
      if (u.point_column[k] >= 0) jacobian(row, u.point_column[k]) -= PointPrimitive(r.nodes[k], r.kernel).value(q) / slope;
    }
  }
  return jacobian;
}

/// The fit's objective Σ |(r − τ)/τ|^p: a high power p approaches the
/// worst departure (what the tolerance bounds) while staying smooth.
double departure_cost(const std::vector<ThicknessSample>& samples, double tau) {
  double sum = 0;
  for (const ThicknessSample& s : samples) sum += std::pow(std::abs(s.thickness - tau) / tau, fit_power);
  return sum;
}

}  // namespace

namespace {

Unknowns unknowns_of(const std::vector<bool>& free_node, const std::vector<std::size_t>& corrected) {
  Unknowns u;
  u.column.assign(free_node.size(), -1);
  u.point_column.assign(free_node.size(), -1);
  for (std::size_t k = 0; k < free_node.size(); ++k) {
    if (free_node[k]) u.column[k] = u.count++;
  }
  for (std::size_t k : corrected) u.point_column[k] = u.count++;
  return u;
}

/// The parameter vector of the current weights, relative to w_τ: the free
/// nodes' hat weights minus w_τ, the point weights.
Eigen::VectorXd parameters(const ThicknessCorrection& c, const Unknowns& u) {
  Eigen::VectorXd x(u.count);
  for (std::size_t k = 0; k < c.weights.size(); ++k) {
    if (u.column[k] >= 0) x(u.column[k]) = c.weights[k] / c.base_weight - 1;
    if (u.point_column[k] >= 0) x(u.point_column[k]) = c.point_weights[k] / c.base_weight;
  }
  return x;
}

/// The fit's objective: Σ|e_j|^p over the samples, e_j = (r_j − τ)/τ, plus
/// the regulariser λ |x|² on the relative weight changes x (options.regularisation).
double fit_cost(const std::vector<ThicknessSample>& samples, double tau, const Eigen::VectorXd& x, double lambda) {
  return departure_cost(samples, tau) + lambda * x.squaredNorm();
}

/// One Levenberg–Marquardt iteration of the fit: damps the Gauss–Newton
/// step (on Σ|e_j|^p: least squares with row weights |e_j|^(p−2)) until it
/// lowers fit_cost; false when no damping does (a local minimum).
bool improve(ThicknessCorrection& out, const SegmentGraph& graph, const Unknowns& u, double tau, double lambda,
             double& damping) {
  const Skeleton field = weighted_skeleton(out.refined, out.weights, out.point_weights);
  // ∂e_j/∂x = (∂r_j/∂w) w_τ/τ
  const Eigen::MatrixXd jac = thickness_jacobian(out.refined, out.after, field, u) * (out.base_weight / tau);
  Eigen::VectorXd residual(jac.rows()), row_weight(jac.rows());
  for (Eigen::Index j = 0; j < jac.rows(); ++j) {
    residual(j) = (out.after[std::size_t(j)].thickness - tau) / tau;
    row_weight(j) = (fit_power / 2) * std::pow(std::abs(residual(j)), fit_power - 2);
  }
  const Eigen::VectorXd x = parameters(out, u);
  Eigen::MatrixXd normal_matrix = jac.transpose() * row_weight.asDiagonal() * jac;
  normal_matrix.diagonal().array() += lambda;
  const Eigen::VectorXd gradient = jac.transpose() * row_weight.asDiagonal() * residual + lambda * x;
  const double cost = fit_cost(out.after, tau, x, lambda);
  for (int attempt = 0; attempt < 12; ++attempt) {
    Eigen::MatrixXd damped = normal_matrix;
    damped.diagonal() += damping * normal_matrix.diagonal();
    const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
    ThicknessCorrection trial = out;
    for (std::size_t k = 0; k < trial.weights.size(); ++k) {
      if (u.column[k] >= 0) trial.weights[k] += step(u.column[k]) * out.base_weight;
      if (u.point_column[k] >= 0) {
        trial.point_weights[k] = std::max(0.0, trial.point_weights[k] + step(u.point_column[k]) * out.base_weight);
      }
    }
    trial.after = out.before;
    measure(trial.after, weighted_skeleton(trial.refined, trial.weights, trial.point_weights), graph);
    if (fit_cost(trial.after, tau, parameters(trial, u), lambda) < cost) {
      out.weights = std::move(trial.weights), out.point_weights = std::move(trial.point_weights);
      out.after = std::move(trial.after);
      damping = std::max(damping / damping_growth, damping_floor);
      return true;
    }
    damping *= damping_growth;
  }
  return false;
}

}  // namespace

ThicknessCorrection correct_thickness(const SegmentGraph& graph, const ThicknessCorrectionOptions& options) {
  check_options(graph, options);
  const double tau = options.thickness;
  ThicknessCorrection out;
  out.base_weight = base_weight(graph.kernel, graph.iso, tau);
  out.before = sample_layout(graph, options);
  measure(out.before, weighted_skeleton(graph, std::vector<double>(graph.nodes.size(), out.base_weight)), graph);
  out.corrected_nodes = nodes_to_correct(graph, out.before, options);
  std::vector<bool> free_node;
  out.refined = refine(graph, out.corrected_nodes, options.ramp_nodes, free_node);
  out.weights.assign(out.refined.nodes.size(), out.base_weight);
  out.point_weights.assign(out.refined.nodes.size(), 0.0);
  out.after = out.before;
  const Unknowns u = unknowns_of(free_node, out.corrected_nodes);
  double damping = damping_start;
  while (u.count > 0 && worst_departure(out.after, tau) > options.tolerance && out.iterations < options.max_iterations) {
    ++out.iterations;
    if (!improve(out, graph, u, tau, options.regularisation, damping)) break;
  }
  out.converged = worst_departure(out.after, tau) <= options.tolerance;
  return out;
}

}  // namespace skelconv
