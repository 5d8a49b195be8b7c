// Implementation of skelconv/reconstruct/reconstruct.hpp.
#include "skelconv/reconstruct/reconstruct.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/reconstruct/bspline.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/pavlidis.hpp"
#include "skelconv/reconstruct/surface_fit.hpp"
#include "skelconv/reconstruct/surface_query.hpp"
#include "skelconv/skeleton_file.hpp"

namespace skelconv::reconstruct {
namespace {

void check_options(const ReconstructOptions& o) {
  if (!(o.prune_angle_degrees >= 0.0 && o.prune_angle_degrees < 180.0))
    throw InputError(fmt::format("must be in [0, 180) degrees, got {}", o.prune_angle_degrees), "--prune-angle");
  if (!(o.prune_span >= 0.0 && o.prune_span < 0.5))
    throw InputError(fmt::format("must be in [0, 0.5) (× the bounding-box diagonal), got {}", o.prune_span), "--prune-span");
  if (!(o.epsilon >= 0.0 && o.epsilon < 1.0))
    throw InputError(fmt::format("must be in [0, 1), got {}", o.epsilon), "--epsilon");
}

Stage make_stage(std::string name, const BranchGraph& graph) {
  Stage stage{std::move(name), graph.branches, {}, graph.ends, graph.junctions, 0};
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
Stage branches_of(const MedialGraph& graph, const ReconstructOptions& o, std::string name, std::size_t* spurs) {
  if (graph.vertices.empty()) throw InputError("no inner Voronoi vertex is left: the shape has no skeleton (too few samples, or the prune angle too large)");
  std::vector<double> radii;
  for (const MedialVertex& v : graph.vertices) radii.push_back(v.radius);
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  CurveSkeleton curve = level_set_skeleton(graph, {o.bin_factor * radii[radii.size() / 2], 0.95});
  if (spurs != nullptr) {
    *spurs = remove_spurs(curve, o.spur_factor, o.spur_protrusion);
    // Moving junctions can leave two paths between the same junctions or
    // a branch short enough to contract: clean up once more.
    if (o.relocate_junctions && relocate_junctions(curve) > 0) *spurs += remove_spurs(curve, o.spur_factor, o.spur_protrusion);
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

}  // namespace

Reconstruction reconstruct(const TriangleMesh& surface, const ReconstructOptions& o) {
  check_options(o);
  Reconstruction result;
  MedialGraph graph = medial_graph(surface);
  result.samples = graph.samples.size();
  result.medial_vertices = graph.vertices.size();
  result.medial_edges = graph.edges.size();
  say(o, fmt::format("medial graph: {} samples, {} inner Voronoi vertices, {} edges", result.samples,
                     result.medial_vertices, result.medial_edges));
  result.stages.push_back(branches_of(graph, o, "raw", nullptr));
  result.pruning = prune_medial_graph(graph, o.prune_angle_degrees * std::numbers::pi / 180.0, 0.05,
                                     o.prune_span * bounding_diagonal(graph.samples));
  say(o, fmt::format("pruned: {} vertices ({} pieces) below the angle, {} small islands removed", result.pruning.vertices_removed,
                     result.pruning.branches_removed, result.pruning.small_pieces_removed));
  result.stages.push_back(branches_of(graph, o, "pruned", &result.spurs_removed));
  result.stages.back().branches = trim_caps(result.stages.back().branches, o.cap_slope);
  const Stage pruned = result.stages.back();  // a copy: stages grows below
  say(o, fmt::format("branches: {} ({} ends, {} junctions, {} spurs removed)", pruned.branches.size(), pruned.ends,
                     pruned.junctions, result.spurs_removed));
  result.tolerance = o.epsilon * skeleton_size(pruned);
  const double tolerance = result.tolerance;
  result.stages.push_back(transformed(pruned, "simplified", [tolerance](const std::vector<Vec4>& p) {
    return pavlidis_split(p, tolerance, PavlidisDimension::space_and_radius);
  }));
  result.stages.push_back(transformed(pruned, "simplified_3d", [tolerance](const std::vector<Vec4>& p) {
    return pavlidis_split(p, tolerance, PavlidisDimension::space);
  }));
  const int samples = o.samples_per_span;
  const Stage simplified = result.stages[2];
  result.stages.push_back(smoothed_stage(simplified, samples));
  say(o, fmt::format("simplified: {} points (3-D only: {}), smoothed: {} points", result.stages[2].points,
                     result.stages[3].points, result.stages[4].points));
  result.stages.push_back(fitted_stage(result.stages[4], surface, o, &result.fit));
  say(o, fmt::format("fitted: last round changed radii by {:.2g} (relative), end extensions by {:.2g}",
                     result.fit.largest_radius_change, result.fit.largest_tip_change));
  return result;
}

std::string skeleton_file_text(const Stage& stage, const ReconstructOptions& o) {
  std::string text = "{\"iso\": 1, \"primitives\": [\n  {\"blend\": \"sum\", \"children\": [";
  const std::string kernel = fmt::format(R"("kernel": {{"family": "cauchy", "degree": {}, "sigma": {:.17g}}})",
                                         o.kernel_degree, o.kernel_sigma);
  bool first = true;
  for (const Branch& b : extend_free_ends(stage.branches, o.end_extension)) {
    for (std::size_t k = 1; k < b.points.size(); ++k) {
      const Vec4& p = b.points[k - 1];
      const Vec4& q = b.points[k];
      if (p.head<3>() == q.head<3>()) continue;  // a repeated point: no segment
      text += fmt::format("{}\n    {{\"type\": \"scalis_segment\", \"a\": [{:.17g}, {:.17g}, {:.17g}], "
                          "\"b\": [{:.17g}, {:.17g}, {:.17g}], \"radius\": [{:.17g}, {:.17g}], {}}}",
                          first ? "" : ",", p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), p.w(), q.w(), kernel);
      first = false;
    }
  }
  for (const Facet& f : stage.facets) {
    const Vec3 a = f[0].head<3>(), b = f[1].head<3>(), c = f[2].head<3>();
    const double diameter = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // The polygon rule of docs/cli_skeleton.md: area ≥ 1e-8 × diameter² (a patch
    // facet at a corner can be nearly flat); the margin keeps clear of it.
    if ((b - a).cross(c - a).norm() / 2 < 1e-6 * diameter * diameter) continue;
    const double radius = (f[0].w() + f[1].w() + f[2].w()) / 3;
    text += fmt::format("{}\n    {{\"type\": \"scalis_triangle\", \"vertices\": [[{:.17g}, {:.17g}, {:.17g}], "
                        "[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}]], \"radius\": [{:.17g}, {:.17g}, {:.17g}], {}}}",
                        first ? "" : ",", a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), radius, radius,
                        radius, kernel);
    first = false;
  }
  return text + "]}]}\n";
}

}  // namespace skelconv::reconstruct

#include "skelconv/mesh/mesh_iso_surface.hpp"

namespace skelconv::reconstruct {

SurfaceDistance measure_stage(const TriangleMesh& surface, const Stage& stage, const ReconstructOptions& options,
                              double size, TriangleMesh* mesh_out) {
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(stage, options));
  Vec3 lo = surface.vertices.front(), hi = lo;
  for (const Vec3& v : surface.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  MeshOptions mesh_options;
  mesh_options.iso = skeleton.iso();
  mesh_options.method = MeshMethod::grid;
  mesh_options.size = size > 0.0 ? size : (hi - lo).norm() / 100.0;
  const TriangleMesh mesh = mesh_iso_surface(skeleton_field(skeleton), mesh_options);
  if (mesh_out != nullptr) *mesh_out = mesh;
  return surface_distance(surface, mesh);
}

}  // namespace skelconv::reconstruct
