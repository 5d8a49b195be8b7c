// Implementation of scalis_thickness_correction.hpp (the method in its file
// comment; docs/thickness_correction.md its use).
#include "skelconv/skeleton/scalis_thickness_correction.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "skelconv/errors.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/segment.hpp"
#include "thickness_fit.hpp"

namespace skelconv {
namespace {

void check_scalis_segment(const ScalisSegment& s, const ScalisSegment* first, const std::string& where) {
  const ScalisKernel& k = s.kernel();
  detail::require_correction_family(k.family, where);
  if (first != nullptr && (first->kernel().degree != k.degree || first->kernel().sigma != k.sigma)) {
    throw InputError("differs from primitives[0].kernel: the correction needs one kernel for the whole graph",
                     where + ".kernel");
  }
  const double slope = std::abs(s.tau1() - s.tau0()) / (s.b() - s.a()).norm();
  if (!(k.sigma * slope < 1)) {
    throw InputError(fmt::format("sigma * |tau1 - tau0| / |AB| = {:.6g} must be < 1: a longer cone of this slope has "
                                 "no finite field, so its thickness is undefined",
                                 k.sigma * slope),
                     where + ".radius");
  }
}

/// τ_n: the largest radius of the segments at each node.
std::vector<double> node_radii(const ScalisSegmentGraph& g) {
  std::vector<double> r(g.nodes.size(), 0.0);
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    r[g.edges[e].a] = std::max(r[g.edges[e].a], g.radius[e][0]);
    r[g.edges[e].b] = std::max(r[g.edges[e].b], g.radius[e][1]);
  }
  return r;
}

std::vector<ThicknessSample> sample_layout(const ScalisSegmentGraph& g, const ScalisThicknessCorrectionOptions& o) {
  double count = 0;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const double mean = 0.5 * (g.radius[e][0] + g.radius[e][1]);
    count += std::ceil(o.samples_per_thickness * (g.nodes[g.edges[e].b] - g.nodes[g.edges[e].a]).norm() / mean) + 1;
  }
  if (!(count <= detail::max_thickness_samples)) {
    throw InputError(fmt::format("the radii ask for {:.3g} thickness samples ({} per mean radius along each "
                                 "segment), more than {:.0f}: radii that small against the segments would take hours",
                                 count, o.samples_per_thickness, detail::max_thickness_samples),
                     "primitives");
  }
  std::vector<ThicknessSample> samples;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const Vec3 a = g.nodes[g.edges[e].a], b = g.nodes[g.edges[e].b];
    const double mean = 0.5 * (g.radius[e][0] + g.radius[e][1]);
    const int n = std::max(1, int(std::ceil(o.samples_per_thickness * (b - a).norm() / mean)));
    for (int j = 0; j <= n; ++j) {
      const double t = double(j) / n;
      samples.push_back({e, t, a + t * (b - a), 0.0, g.radius[e][0] + t * (g.radius[e][1] - g.radius[e][0])});
    }
  }
  return samples;
}

/// m_e: the constant multiplier that gives edge e's radius exactly on a
/// long segment of its slope. SCALIS is scale invariant, so on a cone (its
/// apex at the origin, radius s x at x) the thickness is a fixed multiple of
/// the radius; it is measured at x = 1, the cone reaching x = 1/(1 − σ s) + 1,
/// beyond which no support covers the point (|x' − 1| ≥ σ s x' there). A
/// constant radius gives m_e = iso / factor (the normalisation h).
double base_multiplier(const ScalisSegmentGraph& g, std::size_t e) {
  const double length = (g.nodes[g.edges[e].b] - g.nodes[g.edges[e].a]).norm();
  const double slope = std::abs(g.radius[e][1] - g.radius[e][0]) / length;
  const double sigma = g.kernel.sigma;
  const ScalisSegment long_one = slope > 0 ? ScalisSegment(Vec3::Zero(), Vec3(1 / (1 - sigma * slope) + 1, 0, 0), 0.0,
                                                           slope * (1 / (1 - sigma * slope) + 1), g.kernel, g.factor[e])
                                           : ScalisSegment(Vec3(-2 * sigma, 0, 0), Vec3(2 * sigma, 0, 0), 1.0, 1.0,
                                                           g.kernel, g.factor[e]);
  const double radius = slope > 0 ? slope : 1.0;
  const double at_radius = long_one.value(Vec3(slope > 0 ? 1.0 : 0.0, 0, radius));
  return g.iso / at_radius;
}

/// The hats of the fit: on each edge leaving a corrected node n, hat nodes
/// at distances k ρ σ τ_n / m (k = 1..m, ρ = ramp_reach, m = ramp_nodes)
/// from it; the node and the first m − 1 are free, the last is 0 (the
/// ramp's collar). Between two hat nodes of which one is free, a classical compact
/// segment of support R = σ τ_n (n the edge's end nearer to it) whose
/// linear weight interpolates the two hat values, in units of the weight
/// that gives τ_n on a long segment of that kernel. Ramps from both ends of
/// an edge each keep to their half.
struct Ramp {
  std::size_t edge = 0;
  Vec3 a, b;
  KernelSpec kernel;
  double unit = 0;              ///< the weight of hat value 1
  long left = -1, right = -1;   ///< the hat nodes' unknown columns (−1: 0)
};

std::vector<Ramp> ramps_of(const ScalisSegmentGraph& g, const std::vector<std::size_t>& corrected,
                           double ramp_reach, int nodes_per_support, long& count) {
  std::vector<long> column(g.nodes.size(), -1);
  count = 0;
  for (std::size_t n : corrected) column[n] = count++;
  const std::vector<double> tau = node_radii(g);
  std::vector<Ramp> ramps;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const SegmentGraph::Edge& edge = g.edges[e];
    const Vec3 a = g.nodes[edge.a], b = g.nodes[edge.b];
    const double length = (b - a).norm();
    std::vector<std::pair<double, long>> marks{{0.0, column[edge.a]}, {1.0, column[edge.b]}};  // (u, column)
    for (int side = 0; side < 2; ++side) {
      const std::size_t here = side == 0 ? edge.a : edge.b, there = side == 0 ? edge.b : edge.a;
      if (column[here] < 0) continue;
      const double reach = ramp_reach * g.kernel.sigma * tau[here];
      const double limit = (column[there] >= 0 ? 0.5 : 1.0) * length * (1 - 1e-9);
      for (int k = 1; k <= nodes_per_support && k * reach / nodes_per_support < limit; ++k) {
        const double d = k * reach / nodes_per_support / length;
        marks.push_back({side == 0 ? d : 1 - d, k < nodes_per_support ? count++ : -1});
      }
    }
    std::sort(marks.begin(), marks.end());
    for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
      const auto [u0, c0] = marks[i];
      const auto [u1, c1] = marks[i + 1];
      if (c0 < 0 && c1 < 0) continue;
      // The ramp's node: the corrected end (the nearer one if both are).
      const bool from_a = column[edge.a] >= 0 && (column[edge.b] < 0 || 0.5 * (u0 + u1) < 0.5);
      const double near_tau = tau[from_a ? edge.a : edge.b];
      const KernelSpec kernel = KernelSpec::compact(g.kernel.degree, g.kernel.sigma * near_tau);
      ramps.push_back({e, a + u0 * (b - a), a + u1 * (b - a), kernel,
                       detail::long_segment_weight(kernel, g.iso, near_tau), c0, c1});
    }
  }
  return ramps;
}

KernelSpec point_kernel(const ScalisSegmentGraph& g, double support) {
  return KernelSpec::compact(g.kernel.degree, support);
}

void check_options(const ScalisThicknessCorrectionOptions& o) {
  if (!(o.tolerance > 0 && o.tolerance < 1)) {
    throw InputError(fmt::format("must be in (0, 1), got {:.6g}", o.tolerance), "tolerance");
  }
  if (o.max_iterations < 0) throw InputError("must be >= 0", "max_iterations");
  if (!(o.ramp_reach > 0 && o.ramp_reach <= 4)) {
    throw InputError(fmt::format("must be in (0, 4], got {:.6g}", o.ramp_reach), "ramp_reach");
  }
  detail::require_fit_options(o.ramp_nodes, o.samples_per_thickness, o.regularisation, o.point_support_ratio);
}

}  // namespace

ScalisSegmentGraph scalis_segment_graph_of(const Skeleton& skeleton) {
  ScalisSegmentGraph graph;
  graph.iso = skeleton.iso();
  std::vector<const ScalisSegment*> segments;
  for (std::size_t k = 0; k < skeleton.child_count(Skeleton::root); ++k) {
    const std::string where = fmt::format("primitives[{}]", k);
    const auto [is_blend, index] = skeleton.child(Skeleton::root, k);
    if (is_blend) {
      throw InputError("a blend node: the thickness correction works on the sum of top-level segments", where);
    }
    const ScalisSegment* s = std::get_if<ScalisSegment>(&skeleton.primitives()[index]);
    if (s == nullptr) {
      throw InputError("the SCALIS thickness correction supports \"scalis_segment\" primitives only", where + ".type");
    }
    check_scalis_segment(*s, segments.empty() ? nullptr : segments[0], where);
    segments.push_back(s);
  }
  if (segments.empty()) throw InputError("no scalis_segment: there is no graph to correct", "primitives");
  Eigen::AlignedBox3d box;
  for (const ScalisSegment* s : segments) box.extend(s->a()).extend(s->b());
  const double size = box.diagonal().norm();
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const std::size_t a = detail::node_of(graph.nodes, segments[k]->a(), node_merge_ratio * size);
    const std::size_t b = detail::node_of(graph.nodes, segments[k]->b(), node_merge_ratio * size);
    graph.edges.push_back({a, b, fmt::format("primitives[{}]", k)});
    graph.radius.push_back({segments[k]->tau0(), segments[k]->tau1()});
    graph.factor.push_back(segments[k]->iso());
  }
  graph.kernel = segments[0]->kernel();
  graph.normal = detail::plane_normal(graph.nodes, graph.edges, size);
  return graph;
}

Skeleton scalis_corrected_skeleton(const ScalisSegmentGraph& g, const ScalisThicknessCorrection& c) {
  Skeleton skeleton({}, g.iso);
  for (const ScalisThicknessCorrection::Piece& p : c.pieces) {
    skeleton.add(ScalisSegment(p.a, p.b, p.tau_a, p.tau_b, g.kernel, g.factor[p.edge] * p.multiplier));
  }
  for (const ScalisThicknessCorrection::RampSegment& r : c.ramps) {
    if (r.weight[0] != 0 || r.weight[1] != 0) skeleton.add(Segment(r.a, r.b, KernelSpec::compact(g.kernel.degree, r.support), {r.weight[0], r.weight[1] - r.weight[0]}));
  }
  for (const ScalisThicknessCorrection::NodePoint& p : c.points) {
    if (p.weight != 0) skeleton.add(PointPrimitive(g.nodes[p.node], point_kernel(g, p.support), p.weight));
  }
  return skeleton;
}

std::string scalis_corrected_skeleton_json(const ScalisSegmentGraph& g, const ScalisThicknessCorrection& c) {
  const auto point = [](const Vec3& p) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", p.x(), p.y(), p.z()); };
  std::vector<std::string> items;
  for (const ScalisThicknessCorrection::Piece& p : c.pieces) {
    items.push_back(fmt::format(
        "  {{\"type\": \"scalis_segment\", \"a\": {}, \"b\": {}, \"radius\": [{:.17g}, {:.17g}], "
        "\"kernel\": {{\"family\": \"{}\", \"degree\": {}, \"sigma\": {:.17g}}}, \"iso\": {:.17g}}}",
        point(p.a), point(p.b), p.tau_a, p.tau_b, family_name(g.kernel.family), g.kernel.degree, g.kernel.sigma, g.factor[p.edge] * p.multiplier));
  }
  for (const ScalisThicknessCorrection::RampSegment& r : c.ramps) {
    if (r.weight[0] == 0 && r.weight[1] == 0) continue;
    items.push_back(fmt::format(
        "  {{\"type\": \"segment\", \"a\": {}, \"b\": {}, \"weight\": [{:.17g}, {:.17g}], "
        "\"kernel\": {{\"family\": \"compact\", \"degree\": {}, \"R\": {:.17g}}}}}",
        point(r.a), point(r.b), r.weight[0], r.weight[1] - r.weight[0], g.kernel.degree, r.support));
  }
  for (const ScalisThicknessCorrection::NodePoint& p : c.points) {
    if (p.weight == 0) continue;
    items.push_back(fmt::format(
        "  {{\"type\": \"point\", \"center\": {}, \"weight\": {:.17g}, "
        "\"kernel\": {{\"family\": \"compact\", \"degree\": {}, \"R\": {:.17g}}}}}",
        point(g.nodes[p.node]), p.weight, g.kernel.degree, p.support));
  }
  return fmt::format("{{\"primitives\": [\n{}\n], \"iso\": {:.17g}}}\n", fmt::join(items, ",\n"), g.iso);
}

namespace {

/// Unknowns: the hat values (Ramp), then per corrected node the point
/// weights in units of `unit[k]`, the weight at which the point alone gives
/// iso at distance τ_n from the node. Every unknown has either sign: the sum
/// is what defines the surface.
struct ScalisModel {
  detail::LinearThicknessModel model;
  std::vector<Ramp> ramps;
  long hat_count = 0;
  std::vector<double> unit;
};

ScalisModel scalis_model(const ScalisSegmentGraph& g, const ScalisThicknessCorrection& c, std::vector<Ramp> ramps,
                         long hat_count) {
  ScalisModel m;
  m.ramps = std::move(ramps);
  m.hat_count = hat_count;
  m.model.basis.assign(std::size_t(hat_count), Skeleton({}, g.iso));
  for (const Ramp& r : m.ramps) {
    if (r.left >= 0) m.model.basis[std::size_t(r.left)].add(Segment(r.a, r.b, r.kernel, {r.unit, -r.unit}));
    if (r.right >= 0) m.model.basis[std::size_t(r.right)].add(Segment(r.a, r.b, r.kernel, {0.0, r.unit}));
  }
  const std::vector<double> tau = node_radii(g);
  for (const ScalisThicknessCorrection::NodePoint& p : c.points) {
    const PointPrimitive one(g.nodes[p.node], point_kernel(g, p.support), 1.0);
    m.unit.push_back(g.iso / one.value(g.nodes[p.node] + tau[p.node] * g.normal));
    Skeleton point({}, g.iso);
    point.add(PointPrimitive(g.nodes[p.node], point_kernel(g, p.support), m.unit.back()));
    m.model.basis.push_back(std::move(point));
  }
  m.model.lower.assign(m.model.basis.size(), -INFINITY);
  return m;
}

void apply(ScalisThicknessCorrection& c, const ScalisModel& m, const Eigen::VectorXd& x) {
  c.ramps.clear();
  for (const Ramp& r : m.ramps) {
    const double w0 = r.left >= 0 ? x(Eigen::Index(r.left)) * r.unit : 0.0;
    const double w1 = r.right >= 0 ? x(Eigen::Index(r.right)) * r.unit : 0.0;
    c.ramps.push_back({r.edge, r.a, r.b, r.kernel.R, {w0, w1}});
  }
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    c.points[k].weight = x(Eigen::Index(std::size_t(m.hat_count) + k)) * m.unit[k];
  }
}

}  // namespace

ScalisThicknessCorrection correct_scalis_thickness(const ScalisSegmentGraph& g,
                                                   const ScalisThicknessCorrectionOptions& options) {
  check_options(options);
  ScalisThicknessCorrection out;
  const std::vector<double> tau = node_radii(g);
  const double largest = *std::max_element(tau.begin(), tau.end());
  detail::ThicknessFitSettings settings;
  settings.normal = g.normal, settings.iso = g.iso;
  // Every support, the points' included, ends within this distance.
  settings.reach = options.point_support_ratio * g.kernel.sigma * largest;
  settings.tolerance = options.tolerance, settings.max_iterations = options.max_iterations;
  settings.regularisation = options.regularisation;
  settings.progress = options.progress;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {  // the input, unsplit, for the measure before
    out.pieces.push_back({e, g.nodes[g.edges[e].a], g.nodes[g.edges[e].b], g.radius[e][0], g.radius[e][1], 1.0});
  }
  out.before = sample_layout(g, options);
  detail::measure_thickness(out.before, scalis_corrected_skeleton(g, out), settings);
  // Detection on the base multipliers (what the fit starts from).
  for (std::size_t e = 0; e < g.edges.size(); ++e) out.pieces[e].multiplier = base_multiplier(g, e);
  std::vector<ThicknessSample> based = out.before;
  detail::measure_thickness(based, scalis_corrected_skeleton(g, out), settings);
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    if (!(tau[n] > 0)) continue;  // a tip: nothing to integrate is missing there
    for (const ThicknessSample& s : based) {
      if (s.target > 0 && std::abs(s.thickness - s.target) > options.tolerance * s.target &&
          (s.foot - g.nodes[n]).norm() < g.kernel.sigma * tau[n]) {
        out.corrected_nodes.push_back(n);
        out.points.push_back({n, options.point_support_ratio * g.kernel.sigma * tau[n], 0.0});
        break;
      }
    }
  }
  long hat_count = 0;
  std::vector<Ramp> ramps = ramps_of(g, out.corrected_nodes, options.ramp_reach, options.ramp_nodes, hat_count);
  out.after = out.before;
  ScalisModel m = scalis_model(g, out, std::move(ramps), hat_count);
  ScalisThicknessCorrection shape = out;
  m.model.build = [&m, &shape, &g](const Eigen::VectorXd& x) {
    apply(shape, m, x);
    return scalis_corrected_skeleton(g, shape);
  };
  const detail::ThicknessFitResult fit = detail::fit_thickness(
      m.model, Eigen::VectorXd::Zero(Eigen::Index(m.model.basis.size())), out.before, settings);
  apply(out, m, fit.x);
  out.after = fit.after;
  out.iterations = fit.iterations;
  out.converged = fit.converged;
  return out;
}

}  // namespace skelconv
