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
#include "thickness_fit.hpp"

namespace skelconv {
namespace {

const char* primitive_type_name(const Primitive& p) {
  static constexpr const char* names[] = {"segment", "polygon", "scalis_segment", "scalis_triangle", "point"};
  return names[p.index()];
}

void check_segment(const Segment& s, const Segment* first, const std::string& where) {
  const KernelSpec& k = s.kernel();
  detail::require_correction_family(k.family, where);
  const std::vector<int> degrees = Segment::supported_degrees(k.family, 1);
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

/// The graph's kernel with support radius R: the node points are "a point
/// primitive of the same kernel family" (thickness_correction.hpp).
KernelSpec with_support(KernelSpec kernel, double R) {
  kernel.R = R;
  return kernel;
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
    const std::size_t a = detail::node_of(graph.nodes, segments[k]->a(), node_merge_ratio * size);
    const std::size_t b = detail::node_of(graph.nodes, segments[k]->b(), node_merge_ratio * size);
    graph.edges.push_back({a, b, fmt::format("primitives[{}]", k)});
  }
  graph.kernel = segments[0]->kernel();
  graph.normal = detail::plane_normal(graph.nodes, graph.edges, size);
  return graph;
}

Skeleton weighted_skeleton(const SegmentGraph& graph, const std::vector<double>& weights,
                           const std::vector<double>& point_weights, double point_support) {
  const KernelSpec point_kernel = with_support(graph.kernel, point_support);
  Skeleton skeleton({}, graph.iso);
  for (const SegmentGraph::Edge& e : graph.edges) {
    const double wa = weights[e.a], wb = weights[e.b];
    skeleton.add(Segment(graph.nodes[e.a], graph.nodes[e.b], graph.kernel, {wa, wb - wa}));
  }
  for (std::size_t k = 0; k < point_weights.size(); ++k) {
    if (point_weights[k] > 0) skeleton.add(PointPrimitive(graph.nodes[k], point_kernel, point_weights[k]));
  }
  return skeleton;
}

std::string weighted_skeleton_json(const SegmentGraph& graph, const std::vector<double>& weights,
                                   const std::vector<double>& point_weights, double point_support) {
  const auto point = [](const Vec3& p) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", p.x(), p.y(), p.z()); };
  std::string out = "{\"primitives\": [\n";
  for (std::size_t k = 0; k < graph.edges.size(); ++k) {
    const SegmentGraph::Edge& e = graph.edges[k];
    const double wa = weights[e.a], wb = weights[e.b];
    out += fmt::format(
        "  {{\"type\": \"segment\", \"a\": {}, \"b\": {}, \"weight\": [{:.17g}, {:.17g}], "
        "\"kernel\": {{\"family\": \"{}\", \"degree\": {}, \"R\": {:.17g}}}}}{}",
        point(graph.nodes[e.a]), point(graph.nodes[e.b]), wa, wb - wa, family_name(graph.kernel.family),
        graph.kernel.degree, graph.kernel.R,
        k + 1 < graph.edges.size() ? ",\n" : "");
  }
  for (std::size_t k = 0; k < point_weights.size(); ++k) {
    if (!(point_weights[k] > 0)) continue;
    out += fmt::format(
        ",\n  {{\"type\": \"point\", \"center\": {}, \"weight\": {:.17g}, "
        "\"kernel\": {{\"family\": \"{}\", \"degree\": {}, \"R\": {:.17g}}}}}",
        point(graph.nodes[k]), point_weights[k], family_name(graph.kernel.family), graph.kernel.degree, point_support);
  }
  out += fmt::format("\n], \"iso\": {:.17g}}}\n", graph.iso);
  return out;
}

Skeleton corrected_skeleton(const ThicknessCorrection& c) {
  return weighted_skeleton(c.refined, c.weights, c.point_weights, c.point_support);
}

std::string corrected_skeleton_json(const ThicknessCorrection& c) {
  return weighted_skeleton_json(c.refined, c.weights, c.point_weights, c.point_support);
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
  detail::require_fit_options(o.ramp_nodes, o.samples_per_thickness, o.regularisation, o.point_support_ratio);
}

/// Sample feet: on each edge, t = j/n, j = 0..n, n ≥ samples_per_thickness · length / τ.
std::vector<ThicknessSample> sample_layout(const SegmentGraph& g, const ThicknessCorrectionOptions& o) {
  double count = 0;
  for (const SegmentGraph::Edge& edge : g.edges)
    count += std::ceil(o.samples_per_thickness * (g.nodes[edge.b] - g.nodes[edge.a]).norm() / o.thickness) + 1;
  if (!(count <= detail::max_thickness_samples)) {
    throw InputError(fmt::format("{:.6g} asks for {:.3g} thickness samples ({} per thickness along the segments), "
                                 "more than {:.0f}: a thickness that small against the segments would take hours",
                                 o.thickness, count, o.samples_per_thickness, detail::max_thickness_samples),
                     "thickness");
  }
  std::vector<ThicknessSample> samples;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const Vec3 a = g.nodes[g.edges[e].a], b = g.nodes[g.edges[e].b];
    const int n = std::max(1, int(std::ceil(o.samples_per_thickness * (b - a).norm() / o.thickness)));
    for (int j = 0; j <= n; ++j) {
      const double t = double(j) / n;
      samples.push_back({e, t, a + t * (b - a), 0.0, o.thickness});
    }
  }
  return samples;
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

/// The model of the fit (thickness_fit.hpp): unknown k is the relative
/// change x of a free node's hat weight (weight w_τ (1 + x): basis w_τ times
/// the hat, weight 1 at the node, linear to 0 at its neighbours) or the
/// point weight at a corrected node (weight x w_τ R ≥ 0). `node_of_unknown[k]`
/// is its node; `is_point[k]` says which kind.
struct ClassicalModel {
  detail::LinearThicknessModel model;
  std::vector<std::size_t> node_of_unknown;
  std::vector<bool> is_point;
};

/// The point weight of x = 1: w_τ R, about the field of a segment of weight
/// w_τ and length R. A segment's weight is a field per length (w_τ scales as
/// 1/length) and a point's weight a field, so with w_τ alone the point's x
/// would scale with the skeleton, and the penalty λ x² and the damping with
/// it: the fit would not be the same at every scale.
double point_unit(const ThicknessCorrection& c) { return c.base_weight * c.refined.kernel.R; }

/// The weights of `c.refined` and its point weights for the fit's x.
void apply(ThicknessCorrection& c, const ClassicalModel& m, const Eigen::VectorXd& x) {
  c.weights.assign(c.refined.nodes.size(), c.base_weight);
  c.point_weights.assign(c.refined.nodes.size(), 0.0);
  for (std::size_t k = 0; k < m.node_of_unknown.size(); ++k) {
    const auto xk = x(Eigen::Index(k));
    if (m.is_point[k]) c.point_weights[m.node_of_unknown[k]] = xk * point_unit(c);
    else c.weights[m.node_of_unknown[k]] = (1 + xk) * c.base_weight;
  }
}

ClassicalModel classical_model(const ThicknessCorrection& c, const std::vector<bool>& free_node) {
  ClassicalModel m;
  const SegmentGraph& r = c.refined;
  const KernelSpec point_kernel = with_support(r.kernel, c.point_support);
  for (std::size_t k = 0; k < free_node.size(); ++k) {
    if (!free_node[k]) continue;
    Skeleton hat({}, r.iso);
    for (const SegmentGraph::Edge& e : r.edges) {
      if (e.a == k) hat.add(Segment(r.nodes[e.a], r.nodes[e.b], r.kernel, {c.base_weight, -c.base_weight}));
      if (e.b == k) hat.add(Segment(r.nodes[e.a], r.nodes[e.b], r.kernel, {0.0, c.base_weight}));
    }
    m.model.basis.push_back(std::move(hat));
    m.model.lower.push_back(-INFINITY);
    m.node_of_unknown.push_back(k), m.is_point.push_back(false);
  }
  for (std::size_t k : c.corrected_nodes) {
    Skeleton point({}, r.iso);
    point.add(PointPrimitive(r.nodes[k], point_kernel, point_unit(c)));
    m.model.basis.push_back(std::move(point));
    m.model.lower.push_back(0.0);
    m.node_of_unknown.push_back(k), m.is_point.push_back(true);
  }
  return m;
}

}  // namespace

ThicknessCorrection correct_thickness(const SegmentGraph& graph, const ThicknessCorrectionOptions& options) {
  check_options(graph, options);
  ThicknessCorrection out;
  out.base_weight = detail::long_segment_weight(graph.kernel, graph.iso, options.thickness);
  out.point_support = options.point_support_ratio * graph.kernel.R;
  detail::ThicknessFitSettings settings;
  settings.normal = graph.normal, settings.iso = graph.iso;
  // Every primitive's support, points included, ends within this distance.
  settings.reach = std::max(graph.kernel.R, out.point_support);
  settings.tolerance = options.tolerance, settings.max_iterations = options.max_iterations;
  settings.regularisation = options.regularisation;
  settings.progress = options.progress;
  out.before = sample_layout(graph, options);
  detail::measure_thickness(out.before,
                            weighted_skeleton(graph, std::vector<double>(graph.nodes.size(), out.base_weight)),
                            settings);
  out.corrected_nodes = nodes_to_correct(graph, out.before, options);
  std::vector<bool> free_node;
  out.refined = refine(graph, out.corrected_nodes, options.ramp_nodes, free_node);
  ClassicalModel m = classical_model(out, free_node);
  const ThicknessCorrection* shape = &out;  // build() reads the refined graph and the base weight
  m.model.build = [&m, shape](const Eigen::VectorXd& x) {
    ThicknessCorrection c = *shape;
    apply(c, m, x);
    return corrected_skeleton(c);
  };
  const detail::ThicknessFitResult fit =
      detail::fit_thickness(m.model, Eigen::VectorXd::Zero(Eigen::Index(m.node_of_unknown.size())), out.before, settings);
  apply(out, m, fit.x);
  out.after = fit.after;
  out.iterations = fit.iterations;
  out.converged = fit.converged;
  return out;
}

}  // namespace skelconv
