// Implementation of skelconv/reconstruct/reconstruct.hpp.
#include "skelconv/reconstruct/reconstruct.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/ball_fit.hpp"
#include "skelconv/reconstruct/bspline.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/medial_parts.hpp"
#include "skelconv/reconstruct/pavlidis.hpp"
#include "skelconv/reconstruct/surface_fit.hpp"
#include "skelconv/reconstruct/surface_query.hpp"
#include "skelconv/primitives/segment.hpp"  // Segment::degenerate_length_ratio
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::reconstruct {
namespace {

void check_options(const ReconstructOptions& o) {
  if (!(o.prune_angle_degrees >= 0.0 && o.prune_angle_degrees < 180.0))
    throw InputError(fmt::format("must be in [0, 180) degrees, got {}", o.prune_angle_degrees), "--prune-angle");
  if (!(o.prune_span >= 0.0 && o.prune_span < 0.5))
    throw InputError(fmt::format("must be in [0, 0.5) (× the bounding-box diagonal), got {}", o.prune_span), "--prune-span");
  if (!(o.epsilon >= 0.0 && o.epsilon < 1.0))
    throw InputError(fmt::format("must be in [0, 1), got {}", o.epsilon), "--epsilon");
  const MedialOptions& m = o.medial;
  if (!(m.prune_angle_degrees >= 0.0 && m.prune_angle_degrees < 180.0))
    throw InputError(fmt::format("must be in [0, 180) degrees, got {}", m.prune_angle_degrees), "--medial-prune-angle");
  if (!(m.prune_span >= 0.0 && m.prune_span < 0.5))
    throw InputError(fmt::format("must be in [0, 0.5) (× the bounding-box diagonal), got {}", m.prune_span),
                     "--medial-prune-span");
  if (m.budget == 0) throw InputError("must be at least 1", "--budget");
  if (o.method == SkeletonMethod::medial && o.junction_triangles)
    throw InputError("joins the branches of a curve skeleton: use it with --method curve or auto, not medial",
                     "--bezier-junctions");
}

Stage make_stage(std::string name, const BranchGraph& graph) {
  Stage stage;
  stage.name = std::move(name);
  stage.branches = graph.branches;
  stage.ends = graph.ends;
  stage.junctions = graph.junctions;
  for (const Branch& b : stage.branches) stage.points += b.points.size();
  return stage;
}

/// The same branches with `transform` applied to each polyline.
template <class Transform>
Stage transformed(const Stage& from, std::string name, Transform transform) {
  Stage stage = from;
  stage.name = std::move(name);
  stage.points = 0;
  for (Branch& b : stage.branches) b.points = transform(b.points), stage.points += b.points.size();
  return stage;
}

/// The largest extent of the bounding box of every point of `stage`.
double skeleton_size(const Stage& stage) {
  Vec4 lo = Vec4::Constant(INFINITY), hi = -lo;
  for (const Branch& b : stage.branches) {
    for (const Vec4& p : b.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  return stage.branches.empty() ? 0.0 : (hi - lo).head<3>().maxCoeff();
}

/// The curve skeleton and branches of `graph` (after optional spur removal).
Stage branches_of(const MedialGraph& graph, const ReconstructOptions& o, std::string name, std::size_t* spurs,
                  const std::vector<WeightedPoint>* surface = nullptr) {
  // No inner ball left (pruned away): no branch; reconstruct() falls back to a ball.
  if (graph.vertices.empty()) {
    Stage empty;
    empty.name = std::move(name);
    return empty;
  }
  std::vector<double> radii;
  for (const MedialVertex& v : graph.vertices) radii.push_back(v.radius);
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  CurveSkeleton curve = level_set_skeleton(graph, {o.bin_factor * radii[radii.size() / 2], 0.95});
  if (spurs != nullptr) {
    SpurRule rule{o.spur_factor, o.spur_protrusion};
    if (o.explained_factor > 0.0) {
      rule.surface = surface;
      rule.explained_factor = o.explained_factor;
      rule.explained_tolerance = o.explained_tolerance;
    }
    *spurs = remove_spurs(curve, rule);
    // Moving junctions can leave two paths between the same junctions or
    // a branch short enough to contract: clean up once more.
    if (o.relocate_junctions && relocate_junctions(curve) > 0) *spurs += remove_spurs(curve, rule);
  }
  return make_stage(std::move(name), extract_branches(curve));
}

/// Each branch smoothed by the uniform cubic B-spline: open branches with
/// tripled ends, closed ones periodic (no kink where the cycle was cut).
Stage smoothed_stage(const Stage& from, int samples) {
  Stage stage = from;
  stage.name = "smoothed";
  stage.points = 0;
  for (Branch& b : stage.branches) {
    b.points = b.first_node == b.last_node ? smooth_closed_bspline(b.points, samples) : smooth_bspline(b.points, samples);
    stage.points += b.points.size();
  }
  return stage;
}

/// The smoothed stage with its free ends extended, then the radii and
/// extensions fitted to `surface` (surface_fit.hpp).
Stage fitted_stage(const Stage& from, const TriangleMesh& surface, const ReconstructOptions& o, FitReport* report) {
  Stage stage = from;
  stage.name = "fitted";
  if (o.junction_triangles) stage.facets = place_junction_triangles(stage.branches, o.junction_k, o.junction_subdivisions,
                                                                  o.junction_cuts_branches);
  const SurfaceQuery input(surface);
  const BranchField field_of = [&o, &stage](const std::vector<Branch>& branches) {
    Stage s;
    s.branches = branches;
    s.facets = stage.facets;
    return parse_skeleton_json(skeleton_file_text(s, o));
  };
  stage.branches = fit_to_surface(extend_free_ends(stage.branches, o.end_extension), input, field_of, o.fit, report);
  stage.points = 0;
  for (const Branch& b : stage.branches) stage.points += b.points.size();
  return stage;
}

double bounding_diagonal(const std::vector<Vec3>& points) {
  Vec3 lo = points.front(), hi = lo;
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

void say(const ReconstructOptions& o, const std::string& line) {
  if (o.progress) o.progress(line);
}

/// Wall-clock seconds since the last lap (or construction).
class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// The `ball` stage: one point primitive per connected component of the
/// surface, its least-squares sphere (ball_fit.hpp), on area-weighted
/// points about 1/32 of the diagonal apart. A sphere wider than the whole
/// surface is no ball of it: a flat part's gets the sphere about its
/// centroid instead (as a point primitive the least-squares one put a CAD
/// patch's centre 2 diagonals outside the input's box, a surface no
/// measuring mesh could cover), and `flat` (if set) counts those.
Stage ball_stage(const TriangleMesh& surface, std::size_t* flat = nullptr) {
  Stage stage;
  stage.name = "ball";
  const double diagonal = bounding_diagonal(surface.vertices);
  stage.balls = fit_component_spheres(surface, diagonal / 32, diagonal, flat);
  stage.points = stage.balls.size();
  return stage;
}

/// The balls of `balls` that hold no point of `stage`'s branches: the
/// components of the surface the curve skeleton missed (pruning can leave
/// no branch in a ball-shaped part beside a tube).
std::vector<Vec4> balls_missed(const Stage& stage, const std::vector<Vec4>& balls) {
  std::vector<Vec4> missed;
  for (const Vec4& ball : balls) {
    bool holds = false;
    for (const Branch& b : stage.branches)
      for (const Vec4& p : b.points) holds = holds || (p.head<3>() - ball.head<3>()).norm() < ball.w();
    if (!holds) missed.push_back(ball);
  }
  return missed;
}

/// Whether `stage` holds more primitives than the budget (--budget), which
/// bounds `auto`'s result whichever path it comes from.
bool over_budget(const Stage& stage, const ReconstructOptions& o) {
  return primitive_counts(stage, o).total() > o.medial.budget;
}

/// Ferley's curve path (reconstruct.hpp): the stages raw … fitted, or a
/// ball when no branch is left or one fits better. Returns whether its last
/// stage is a result: for `auto`, the stages end at `smoothed`, unfitted,
/// when that stage is already over the budget (result.curve_over_budget):
/// the fit keeps every point, so the fitted stage would be too, and `auto`
/// never returns a result over the budget.
bool curve_stages(MedialGraph graph, const TriangleMesh& surface, const ReconstructOptions& o, Reconstruction& result,
                  Stopwatch& clock) {
  result.stages.push_back(branches_of(graph, o, "raw", nullptr));
  result.stages.back().seconds = clock.lap();
  result.pruning = prune_medial_graph(graph, o.prune_angle_degrees * std::numbers::pi / 180.0, 0.05,
                                     o.prune_span * bounding_diagonal(graph.samples));
  say(o, fmt::format("pruned: {} vertices ({} pieces) below the angle, {} small islands removed", result.pruning.vertices_removed,
                     result.pruning.branches_removed, result.pruning.small_pieces_removed));
  // The input's area as points about 1/100 of the diagonal apart, for the
  // spur rule (explained_area): fine enough for the cap of a limb a few
  // hundredths of the diagonal across, coarse enough to be cheap.
  const std::vector<WeightedPoint> area_points = merged_in_cells(
      area_weighted_points(surface, o.explained_spacing * bounding_diagonal(surface.vertices)),
      o.explained_spacing * bounding_diagonal(surface.vertices));
  result.stages.push_back(branches_of(graph, o, "pruned", &result.spurs_removed, &area_points));
  result.stages.back().branches = trim_caps(result.stages.back().branches, o.cap_slope);
  result.stages.back().seconds = clock.lap();
  const Stage pruned = result.stages.back();  // a copy: stages grows below
  say(o, fmt::format("branches: {} ({} ends, {} junctions, {} spurs removed)", pruned.branches.size(), pruned.ends,
                     pruned.junctions, result.spurs_removed));
  if (primitive_counts(pruned, o).total() == 0) {
    // No curve skeleton: the shape is a ball or a blob. The stages without
    // a primitive cannot be meshed, so they go; the ball is the result.
    std::erase_if(result.stages, [&o](const Stage& s) { return primitive_counts(s, o).total() == 0; });
    std::size_t flat = 0;
    result.stages.push_back(ball_stage(surface, &flat));
    result.stages.back().seconds = clock.lap();
    const Vec4& ball = result.stages.back().balls.front();
    say(o, fmt::format("no branch left: {} point primitive(s), the least-squares sphere of each part{}; the first at "
                       "({:.4g}, {:.4g}, {:.4g}), radius {:.4g}", result.stages.back().balls.size(),
                       flat ? fmt::format(" ({} flat: the sphere about its centroid)", flat) : std::string(), ball.x(),
                       ball.y(), ball.z(), ball.w()));
    return true;
  }
  result.tolerance = o.epsilon * skeleton_size(pruned);
  const double tolerance = result.tolerance;
  result.stages.push_back(transformed(pruned, "simplified", [tolerance](const std::vector<Vec4>& p) {
    return pavlidis_split(p, tolerance, PavlidisDimension::space_and_radius);
  }));
  result.stages.back().seconds = clock.lap();
  result.stages.push_back(transformed(pruned, "simplified_3d", [tolerance](const std::vector<Vec4>& p) {
    return pavlidis_split(p, tolerance, PavlidisDimension::space);
  }));
  result.stages.back().seconds = clock.lap();
  const int samples = o.samples_per_span;
  const Stage simplified = result.stages[2];
  result.stages.push_back(smoothed_stage(simplified, samples));
  result.stages.back().seconds = clock.lap();
  say(o, fmt::format("simplified: {} points (3-D only: {}), smoothed: {} points", result.stages[2].points,
                     result.stages[3].points, result.stages[4].points));
  if (o.method == SkeletonMethod::automatic && over_budget(result.stages.back(), o)) {
    result.curve_over_budget = primitive_counts(result.stages.back(), o).total();
    say(o, fmt::format("curve skeleton: {} primitives, more than the budget of {} (--budget): not fitted, the result "
                       "is the medial mesh", result.curve_over_budget, o.medial.budget));
    return false;
  }
  result.stages.push_back(fitted_stage(result.stages[4], surface, o, &result.fit));
  result.stages.back().seconds = clock.lap();
  say(o, fmt::format("fitted: last round changed radii by {:.2g} (relative), end extensions by {:.2g}",
                     result.fit.largest_radius_change, result.fit.largest_tip_change));
  // A curve skeleton can be worse than one ball: a cube's medial axis is
  // made of sheets, and the branches its level sets give are no skeleton of it.
  // Both are compared on the same area-weighted points (first-order
  // distances, cheap); the better one is the result.
  const double diagonal = bounding_diagonal(surface.vertices);
  const std::vector<WeightedPoint> points = area_weighted_points(surface, diagonal / 32);
  std::size_t flat = 0;
  Stage ball = ball_stage(surface, &flat);
  result.stages.back().balls = balls_missed(result.stages.back(), ball.balls);
  result.stages.back().points += result.stages.back().balls.size();
  if (!result.stages.back().balls.empty())
    say(o, fmt::format("{} part(s) of the surface hold no branch: one point primitive each", result.stages.back().balls.size()));
  const double curve_error = first_order_rms(parse_skeleton_json(skeleton_file_text(result.stages.back(), o)), points, diagonal);
  const double ball_error = first_order_rms(parse_skeleton_json(skeleton_file_text(ball, o)), points, diagonal);
  // A part whose least-squares sphere is wider than the whole surface is
  // not ball-shaped (CGAL's camel: a radius of about 1,400 diagonals,
  // closer than its branches by the first-order distance): the branches
  // stay.
  const bool balls_fit = flat == 0;
  if (!balls_fit)
    say(o, "a least-squares sphere is wider than the surface's diagonal: no ball, the branches stay");
  if (balls_fit && ball_error < curve_error) {
    say(o, fmt::format("one ball fits better than the branches (first-order RMS {:.3g} against {:.3g} of the "
                       "diagonal): the result is the ball", ball_error / diagonal, curve_error / diagonal));
    result.stages.push_back(std::move(ball));
    result.stages.back().seconds = clock.lap();
  }
  return true;
}

/// A measured surface's topology, to compare with the input's
/// (same_topology).
MeshTopology topology_of(const StageMeasure& m) {
  MeshTopology t;
  t.components = m.components, t.euler_characteristic = m.euler_characteristic;
  return t;
}

/// Whether the medial stage is better than the curve path's result: when
/// both can be meshed within the measuring budget, the one whose surface
/// keeps the input's Euler characteristic and component count (a detached
/// foot or a tunnel is worse than a larger distance; but one ball only
/// where it is also closer), then the smaller two-sided Hausdorff
/// distance; otherwise the smaller first-order RMS distance on the same
/// area-weighted points (cheap, blind to topology). The measures taken are
/// kept in the stages (Stage::measured), for a report to reuse.
bool choose_between(Stage& curve, Stage& medial, const TriangleMesh& surface, const ReconstructOptions& o) {
  const double diagonal = bounding_diagonal(surface.vertices);
  const auto measurable = [&](const Stage& s) {
    return over_measure_budget(measure_work(surface, s, o), o.measure_budget).empty();
  };
  if (measurable(curve) && measurable(medial)) {
    // A surface the mesher cannot finish (a vertex it cannot project: an
    // EvaluationError) loses; the error is said, not thrown.
    const auto try_measure = [&](Stage& s) {
      try {
        s.measured = measure(surface, s, o);
      } catch (const EvaluationError& error) {
        say(o, fmt::format("{}: not meshed ({}): the other path is kept", s.name, error.what()));
      }
      return s.measured.has_value();
    };
    const bool curve_meshed = try_measure(curve), medial_meshed = try_measure(medial);
    if (!curve_meshed || !medial_meshed) return medial_meshed;
    const MeshTopology input = mesh_topology(surface);
    const auto kept = [&input](const Stage& s) { return same_topology(input, topology_of(*s.measured)); };
    const bool c_kept = kept(curve), m_kept = kept(medial);
    const double c = curve.measured->distance.hausdorff, m = medial.measured->distance.hausdorff;
    // One ball is kept only where it is closer: a ball keeps a genus-0
    // input's topology whatever the shape, so topology alone must not
    // choose it over a medial mesh (a fist, a CAD part).
    const bool better = curve.name == "ball" ? !(c_kept && c < m) : m_kept != c_kept ? m_kept : m < c;
    say(o, fmt::format("{}: Hausdorff {:.3g}, topology {}kept; medial mesh: {:.3g}, {}kept: the result is the {}",
                       curve.name, c / diagonal, c_kept ? "" : "not ", m / diagonal, m_kept ? "" : "not ",
                       better ? "medial mesh" : curve.name));
    return better;
  }
  const std::vector<WeightedPoint> points = area_weighted_points(surface, diagonal / 32);
  const double curve_error = first_order_rms(parse_skeleton_json(skeleton_file_text(curve, o)), points, diagonal);
  const double medial_error = first_order_rms(parse_skeleton_json(skeleton_file_text(medial, o)), points, diagonal);
  say(o, fmt::format("first-order RMS distance: {} {:.3g}, medial mesh {:.3g} of the diagonal: the result is the {}",
                     curve.name, curve_error / diagonal, medial_error / diagonal,
                     medial_error < curve_error ? "medial mesh" : curve.name));
  return medial_error < curve_error;
}

/// Whether `auto` may keep the curve path's result `curve` without the
/// medial path: measurable, meshed, keeping the input's topology, within
/// ReconstructOptions::curve_accepted_hausdorff and _rms. The measure taken
/// stays in the stage (Stage::measured) for a report to reuse.
bool curve_is_good_enough(Stage& curve, const TriangleMesh& surface, const ReconstructOptions& o) {
  if (!over_measure_budget(measure_work(surface, curve, o), o.measure_budget).empty()) return false;
  try {
    curve.measured = measure(surface, curve, o);
  } catch (const EvaluationError&) {
    return false;  // choose_between says why, after the medial path
  }
  const MeshTopology input = mesh_topology(surface);
  const StageMeasure& m = *curve.measured;
  const double diagonal = m.distance.diagonal;
  const bool good = same_topology(input, topology_of(m)) &&
                    m.distance.hausdorff <= o.curve_accepted_hausdorff * diagonal &&
                    m.distance.rms <= o.curve_accepted_rms * diagonal;
  if (good)
    say(o, fmt::format("{}: Hausdorff {:.3g}, RMS {:.3g} of the diagonal, topology kept: within the curve path's goal, "
                       "the result (no medial mesh)", curve.name, m.distance.hausdorff / diagonal,
                       m.distance.rms / diagonal));
  return good;
}

}  // namespace

Reconstruction reconstruct(const TriangleMesh& surface, const ReconstructOptions& o) {
  check_options(o);
  Reconstruction result;
  Stopwatch clock;
  // Whether the curve path's last stage may be `auto`'s result.
  bool curve_candidate = false;
  if (o.method != SkeletonMethod::medial) {
    MedialGraph graph = medial_graph(surface);
    result.samples = graph.samples.size();
    result.medial_vertices = graph.vertices.size();
    result.medial_edges = graph.edges.size();
    result.medial_seconds = clock.lap();
    say(o, fmt::format("medial graph: {} samples, {} inner Voronoi vertices, {} edges", result.samples,
                       result.medial_vertices, result.medial_edges));
    curve_candidate = curve_stages(std::move(graph), surface, o, result, clock);
    if (o.method == SkeletonMethod::curve) {
      // --method curve asks for Ferley's path, whose size --epsilon sets:
      // the budget bounds `auto` and the medial mesh, so it is only said.
      if (over_budget(result.stages.back(), o))
        say(o, fmt::format("the curve skeleton has {} primitives, more than the budget of {} (--budget bounds "
                           "--method auto and medial only)", primitive_counts(result.stages.back(), o).total(),
                           o.medial.budget));
      return result;
    }
    if (curve_candidate && over_budget(result.stages.back(), o)) {
      result.curve_over_budget = primitive_counts(result.stages.back(), o).total();
      say(o, fmt::format("{}: {} primitives, more than the budget of {} (--budget): not a candidate, the result is "
                         "the medial mesh", result.stages.back().name, result.curve_over_budget, o.medial.budget));
      curve_candidate = false;
    }
    if (curve_candidate && curve_is_good_enough(result.stages.back(), surface, o)) return result;
  }
  Stage medial = medial_stage(surface, o, &result.medial_path);
  medial.seconds = clock.lap();
  if (primitive_counts(medial, o).total() == 0) {
    say(o, "medial mesh: pruning left no inner ball");
    // `auto` keeps the curve path's result when it may; otherwise a ball.
    if (!curve_candidate) result.stages.push_back(ball_stage(surface));
    return result;
  }
  if (!curve_candidate) {
    result.stages.push_back(std::move(medial));
    return result;
  }
  // Both paths ran: keep the better (choose_between).
  if (choose_between(result.stages.back(), medial, surface, o)) result.stages.push_back(std::move(medial));
  else result.stages.insert(result.stages.end() - 1, std::move(medial));
  return result;
}

namespace {

/// Whether a segment between two skeleton points is one that skeleton files
/// accept (Segment::degenerate_length_ratio of the larger coordinate). Two
/// points of a branch can come out of the fit equal to within rounding (an
/// open box closed by --repair: 1.1e-16 apart); such a piece adds nothing to
/// the field and would make the written skeleton unreadable, so it is left out
/// (its neighbours still meet at the same point).
bool representable_segment(const Vec3& a, const Vec3& b) {
  const double length = (b - a).norm();
  const double largest_coordinate = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return length > 0 && length >= Segment::degenerate_length_ratio * largest_coordinate;
}

/// The children of a stage's sum blend, one JSON object each, counted by kind.
std::vector<std::string> blend_children(const Stage& stage, const ReconstructOptions& o, PrimitiveCounts* counts) {
  std::vector<std::string> children;
  PrimitiveCounts n;
  const std::string kernel = fmt::format(R"("kernel": {{"family": "cauchy", "degree": {}, "sigma": {:.17g}}})",
                                         o.kernel_degree, o.kernel_sigma);
  for (const Branch& b : extend_free_ends(stage.branches, o.end_extension)) {
    for (std::size_t k = 1; k < b.points.size(); ++k) {
      const Vec4& p = b.points[k - 1];
      const Vec4& q = b.points[k];
      if (!representable_segment(p.head<3>(), q.head<3>())) continue;
      children.push_back(fmt::format("{{\"type\": \"scalis_segment\", \"a\": [{:.17g}, {:.17g}, {:.17g}], "
                                     "\"b\": [{:.17g}, {:.17g}, {:.17g}], \"radius\": [{:.17g}, {:.17g}], {}}}",
                                     p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), p.w(), q.w(), kernel));
      ++n.segments;
    }
  }
  for (const Facet& f : stage.facets) {
    const Vec3 a = f[0].head<3>(), b = f[1].head<3>(), c = f[2].head<3>();
    const double diameter = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // The polygon rule of docs/cli_skeleton.md: area ≥ 1e-8 × diameter² (a patch
    // facet at a corner can be nearly flat); the margin keeps clear of it.
    if ((b - a).cross(c - a).norm() / 2 < 1e-6 * diameter * diameter) continue;
    const double radius = (f[0].w() + f[1].w() + f[2].w()) / 3;
    children.push_back(fmt::format("{{\"type\": \"scalis_triangle\", \"vertices\": [[{:.17g}, {:.17g}, {:.17g}], "
                                   "[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}]], \"radius\": [{:.17g}, {:.17g}, {:.17g}], {}}}",
                                   a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), radius, radius,
                                   radius, kernel));
    ++n.triangles;
  }
  const MedialMesh& m = stage.medial;
  const auto sphere = [&m](std::int32_t i) -> const Vec4& { return m.spheres[std::size_t(i)]; };
  // The medial mesh's primitives have the compact kernel (MedialOptions):
  // finite support, so the field's index evaluates only the few near a point.
  const double sigma = o.medial.kernel_sigma;
  const std::string compact = fmt::format(R"("kernel": {{"family": "compact", "degree": 4, "sigma": {:.17g}}})", sigma);
  for (const auto& [i, j] : m.edges) {
    const Vec4 &p = sphere(i), &q = sphere(j);
    if (!representable_segment(p.head<3>(), q.head<3>())) continue;
    children.push_back(fmt::format("{{\"type\": \"scalis_segment\", \"a\": [{:.17g}, {:.17g}, {:.17g}], "
                                   "\"b\": [{:.17g}, {:.17g}, {:.17g}], \"radius\": [{:.17g}, {:.17g}], {}}}",
                                   p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), p.w(), q.w(), compact));
    ++n.segments;
  }
  for (const auto& t : m.triangles) {
    const Vec4 &a = sphere(t[0]), &b = sphere(t[1]), &c = sphere(t[2]);
    // One radius (medial_mesh.hpp, triangle_radius).
    const double radius = triangle_radius(a.w(), b.w(), c.w(), o.medial.triangle_radius).tau;
    children.push_back(fmt::format("{{\"type\": \"scalis_triangle\", \"vertices\": [[{:.17g}, {:.17g}, {:.17g}], "
                                   "[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}]], \"radius\": [{:.17g}, {:.17g}, {:.17g}], {}}}",
                                   a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), radius, radius,
                                   radius, compact));
    ++n.triangles;
  }
  // An isolated sphere: a compact point w (1 − r²/R²)², R = σ ρ, with w =
  // (1 − 1/σ²)^−2 so that f = iso = 1 at r = ρ.
  for (const std::int32_t i : m.isolated) {
    const Vec4& ball = sphere(i);
    children.push_back(fmt::format("{{\"type\": \"point\", \"center\": [{:.17g}, {:.17g}, {:.17g}], "
                                   "\"kernel\": {{\"family\": \"compact\", \"degree\": 4, \"R\": {:.17g}}}, \"weight\": {:.17g}}}",
                                   ball.x(), ball.y(), ball.z(), sigma * ball.w(),
                                   1.0 / ((1.0 - 1.0 / (sigma * sigma)) * (1.0 - 1.0 / (sigma * sigma)))));
    ++n.points;
  }
  // A point of Cauchy kernel degree 4 is w (1 + s r²)^−2 (docs/cli_blends.md):
  // with w = 4 and s = 1/R², f = iso = 1 exactly at r = R, and |∇f| there is
  // 2/R, the same order as a SCALIS segment's at its surface.
  for (const Vec4& ball : stage.balls) {
    children.push_back(fmt::format("{{\"type\": \"point\", \"center\": [{:.17g}, {:.17g}, {:.17g}], "
                                   "\"kernel\": {{\"family\": \"cauchy\", \"degree\": 4, \"s\": {:.17g}}}, \"weight\": 4}}",
                                   ball.x(), ball.y(), ball.z(), 1.0 / (ball.w() * ball.w())));
    ++n.points;
  }
  if (counts != nullptr) *counts = n;
  return children;
}

}  // namespace

PrimitiveCounts primitive_counts(const Stage& stage, const ReconstructOptions& o) {
  PrimitiveCounts counts;
  blend_children(stage, o, &counts);
  return counts;
}

std::string skeleton_file_text(const Stage& stage, const ReconstructOptions& o) {
  const std::vector<std::string> children = blend_children(stage, o, nullptr);
  if (children.empty()) throw std::logic_error("skeleton_file_text: the stage " + stage.name + " has no primitive");
  const auto sum = [](const std::vector<std::string>& terms, const std::string& indent) {
    std::string text = "{\"blend\": \"sum\", \"children\": [";
    for (std::size_t k = 0; k < terms.size(); ++k) text += (k == 0 ? "\n" : ",\n") + indent + terms[k];
    return text + "]}";
  };
  // A medial mesh of several parts of the input: one sum per part that has
  // primitives, in the parts' order, joined by a union, so that the fields
  // of two parts never add up (medial_parts.hpp).
  if (part_count(stage.medial) > 1) {
    std::vector<std::string> groups;
    for (std::size_t p = 0; p < part_count(stage.medial); ++p) {
      Stage part = stage;
      part.medial = medial_mesh_part(stage.medial, std::int32_t(p));
      const std::vector<std::string> terms = blend_children(part, o, nullptr);
      if (!terms.empty()) groups.push_back(sum(terms, "      "));
    }
    if (groups.size() > 1) {
      std::string text = "{\"iso\": 1, \"primitives\": [\n  {\"blend\": \"union\", \"children\": [";
      for (std::size_t k = 0; k < groups.size(); ++k) text += (k == 0 ? "\n    " : ",\n    ") + groups[k];
      return text + "]}]}\n";
    }
  }
  return "{\"iso\": 1, \"primitives\": [\n  " + sum(children, "    ") + "]}\n";
}

}  // namespace skelconv::reconstruct

#include "skelconv/field/support_box.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"

namespace skelconv::reconstruct {

namespace {

/// The facet size measure_stage meshes at: `size`, or the diagonal /
/// ReconstructOptions::measure_divisions.
double measure_size(const Vec3& lo, const Vec3& hi, double size, const ReconstructOptions& o) {
  return size > 0.0 ? size : (hi - lo).norm() / o.measure_divisions;
}

std::pair<Vec3, Vec3> bounding_box(const TriangleMesh& surface) {
  Vec3 lo = surface.vertices.front(), hi = lo;
  for (const Vec3& v : surface.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return {lo, hi};
}

}  // namespace

MeasureWork measure_work(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                         double size) {
  const auto [lo, hi] = bounding_box(surface);
  const double h = measure_size(lo, hi, size, options);
  // Nodes of the box at spacing h, one voxel of margin each side (the
  // mesher's box holds the whole surface with a margin; a narrow band
  // evaluates fewer, so this is an upper estimate): node k of an axis is
  // at lo − h + k h, k < n.
  const Vec3 origin = lo - Vec3::Constant(h);
  Eigen::Array3d n;
  for (int axis = 0; axis < 3; ++axis) n[axis] = std::floor((hi[axis] - lo[axis]) / h) + 3.0;
  MeasureWork work;
  work.grid_nodes = n.prod();
  // The mesher's field index visits a compact primitive only at the nodes
  // inside its support box (field/support_box.hpp), and an
  // infinite-support one (Cauchy) at every node. (A sum of fewer than
  // Skeleton::min_indexed_children is not indexed: its few compact
  // primitives cost every node, at most 7 grids, far under any budget.)
  if (primitive_counts(stage, options).total() == 0) return work;
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(stage, options));
  work.primitives = skeleton.primitives().size();
  for (const Primitive& primitive : skeleton.primitives()) {
    const std::optional<SupportBox> box = support_box(primitive);
    if (!box) {
      work.evaluations += work.grid_nodes;
      continue;
    }
    double inside = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double first = std::max(0.0, std::ceil((box->lo[axis] - origin[axis]) / h));
      const double last = std::min(n[axis] - 1.0, std::floor((box->hi[axis] - origin[axis]) / h));
      inside *= std::max(0.0, last - first + 1.0);
    }
    work.evaluations += inside;
  }
  return work;
}

std::string over_measure_budget(const MeasureWork& work, double budget) {
  if (work.evaluations <= budget) return {};
  return fmt::format("not measured: meshing its {} primitives on a grid of about {:.3g} nodes would take about "
                     "{:.2g} primitive evaluations, more than the budget of {:.2g}",
                     work.primitives, work.grid_nodes, work.evaluations, budget);
}

namespace {

/// The mesher's options of mesh_stage for `skeleton`.
MeshOptions stage_mesh_options(const TriangleMesh& surface, const Skeleton& skeleton,
                               const ReconstructOptions& options, double size, bool project) {
  const auto [lo, hi] = bounding_box(surface);
  MeshOptions mesh_options;
  mesh_options.iso = skeleton.iso();
  mesh_options.method = MeshMethod::grid;
  mesh_options.size = measure_size(lo, hi, size, options);
  mesh_options.project = project;
  return mesh_options;
}

}  // namespace

TriangleMesh mesh_stage(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                        double size) {
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(stage, options));
  return mesh_iso_surface(skeleton_field(skeleton), stage_mesh_options(surface, skeleton, options, size, true));
}

TriangleMesh mesh_stage_unprojected(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                                    double size) {
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(stage, options));
  return mesh_iso_surface(skeleton_field(skeleton), stage_mesh_options(surface, skeleton, options, size, false));
}

void project_stage_mesh(TriangleMesh& mesh, const TriangleMesh& surface, const Stage& stage,
                        const ReconstructOptions& options, double size) {
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(stage, options));
  const MeshOptions mesh_options = stage_mesh_options(surface, skeleton, options, size, true);
  project_iso_surface(mesh, skeleton_field(skeleton), mesh_options, *mesh_options.size);
}

SurfaceDistance measure_stage(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                              double size, TriangleMesh* mesh_out) {
  const std::string refused = over_measure_budget(measure_work(surface, stage, options, size), options.measure_budget);
  if (!refused.empty()) throw InputError(refused, "stage " + stage.name);
  const TriangleMesh mesh = mesh_stage(surface, stage, options, size);
  if (mesh_out != nullptr) *mesh_out = mesh;
  return surface_distance(surface, mesh);
}

StageMeasure measure(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options) {
  if (stage.measured) return *stage.measured;
  const auto start = std::chrono::steady_clock::now();
  StageMeasure m;
  if (stage.meshed) {
    m.surface = *stage.meshed;
    m.distance = surface_distance(surface, m.surface);
  } else {
    m.distance = measure_stage(surface, stage, options, 0.0, &m.surface);
  }
  const MeshTopology topology = mesh_topology(m.surface);
  m.euler_characteristic = topology.euler_characteristic;
  m.components = topology.components;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

}  // namespace skelconv::reconstruct
