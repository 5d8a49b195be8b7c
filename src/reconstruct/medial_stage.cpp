// The `medial` stage of reconstruct.hpp: the inner Voronoi graph pruned,
// simplified to a medial mesh, its tube ends extended and its spheres (centres and radii) fitted
// (docs/reconstruction_medial.md).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/ball_fit.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/medial_parts.hpp"
#include "skelconv/reconstruct/medial_quadric.hpp"
#include "skelconv/reconstruct/pruning.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/surface_query.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"
#include "fill_cavities.hpp"
#include "plug_tunnels.hpp"
#include "thin_walls.hpp"
#include "tube_ends.hpp"
#include "unreached_tips.hpp"

namespace skelconv::reconstruct {
namespace {

/// A hash of a point's three coordinates' bits (boost's hash_combine).
struct CentreHash {
  std::size_t operator()(const std::array<std::uint64_t, 3>& key) const {
    std::size_t h = 0;
    for (const std::uint64_t k : key) h ^= std::hash<std::uint64_t>{}(k) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
  }
};

/// Whether two medial meshes are the same skeleton: equal spheres (centres
/// and radii) joined the same way.
bool same(const MedialMesh& a, const MedialMesh& b) {
  return a.spheres == b.spheres && a.edges == b.edges && a.triangles == b.triangles && a.isolated == b.isolated &&
         a.parts == b.parts;
}

std::size_t primitives(const MedialMesh& mesh) {
  return mesh.edges.size() + mesh.triangles.size() + mesh.isolated.size();
}

}  // namespace

Stage medial_stage(const TriangleMesh& surface, const ReconstructOptions& o, MedialPathReport* report) {
  const MedialOptions& m = o.medial;
  const double diagonal = bounding_box(surface.vertices).diagonal();
  SamplingOptions sampling;
  sampling.diagonal_divisions = m.sample_divisions;
  MedialGraph graph = medial_graph(surface, 20, sampling);
  MedialPathReport r;
  std::size_t tips_kept = 0;
  const auto prune = [&](MedialGraph& g) {
    if (o.progress)
      o.progress(fmt::format("medial path: {} samples, {} inner Voronoi vertices", g.samples.size(),
                             g.vertices.size()));
    r.samples = g.samples.size();
    r.vertices = g.vertices.size();
    const PruningReport pruned =
        prune_medial_graph(g, m.prune_angle_degrees * std::numbers::pi / 180.0, 0.05,
                           std::max(m.prune_span, o.prune_span) * diagonal, m.lobes,
                           TipOptions{m.tip_reach * diagonal / m.sample_divisions, m.tip_thinness,
                                      m.tip_join == TipJoin::always});
    r.pruned = pruned.vertices_removed;
    tips_kept = pruned.tips_kept;
    if (o.progress && pruned.lobes_kept > 0)
      o.progress(fmt::format("medial path: {} small pieces kept as lobes (deep balls outside the large pieces')",
                             pruned.lobes_kept));
    if (o.progress && pruned.tips_kept > 0)
      o.progress(fmt::format("medial path: {} small pieces kept as thin protrusions (a ball reaching {} sample "
                             "spacings and {} radii beyond the large pieces')",
                             pruned.tips_kept, m.tip_reach, m.tip_thinness));
    if (o.progress && pruned.tips_connected + pruned.tips_bridged > 0)
      o.progress(fmt::format("medial path: thin protrusions joined to the body again: {} along their medial path ({} "
                             "pruned vertices kept), {} by an edge between balls (overlapping, or the tube between them clear of "
                             "the samples)",
                             pruned.tips_connected, pruned.connecting_vertices, pruned.tips_bridged));
  };
  prune(graph);
  // Thin walls sampled finer (thin_walls.hpp), the rest of the shape as it
  // was: where none is found, the graph is the one built above.
  if (m.thin_walls) {
    const double h = diagonal / m.sample_divisions;
    const detail::ThinWalls walls =
        detail::find_thin_walls(surface, graph, sampling, h, m.thin_wall_radius, m.thin_wall_max_refinement);
    if (!walls.triangle_refinement.empty()) {
      sampling.triangle_refinement = walls.triangle_refinement;
      if (o.progress)
        o.progress(fmt::format("medial path: thin walls found ({} of {} thin medial vertices on a wall, {} "
                               "walls): {} of {} triangles sampled again, up to {:.2f} times finer",
                               walls.wall_vertices, walls.thin_vertices, walls.walls, walls.triangles,
                               surface.triangles.size(), walls.finest));
      graph = medial_graph(surface, 20, sampling);
      prune(graph);
    } else if (o.progress) {
      o.progress(fmt::format("medial path: no thin wall ({} thin medial vertices, none on a wall)",
                             walls.thin_vertices));
    }
  }
  QuadricOptions quadric;
  quadric.budget = m.budget;
  quadric.radius_weight = m.quadric_radius_weight;
  // The quadric knows planes, not the inside: a sphere merged from a sheet
  // collapsed round a bore may be tangent to all its planes from inside the
  // bore (CGAL's joint: 25 of 296 spheres, up to 18% of the diagonal out).
  // One query per centre: each candidate asks the depth at the centres of
  // the two balls it merges, and the budget loop below reruns the
  // simplification from the same graph, which asks the same centres again.
  // Hashed by the centre's bits (a large shape asks about hundreds of
  // thousands of centres: CGAL's cheese 287k vertices; an ordered map's
  // lookups were 8% of its medial path).
  const SurfaceQuery shape(surface);
  std::unordered_map<std::array<std::uint64_t, 3>, double, CentreHash> depth_at;
  quadric.depth = [&shape, &depth_at](const Vec3& c) {
    const std::array<std::uint64_t, 3> key{std::bit_cast<std::uint64_t>(c.x()), std::bit_cast<std::uint64_t>(c.y()),
                                           std::bit_cast<std::uint64_t>(c.z())};
    if (const auto at = depth_at.find(key); at != depth_at.end()) return at->second;
    return depth_at.emplace(key, shape.signed_distance(c)).first->second;
  };
  quadric.overhang = m.merged_overhang * diagonal;
  quadric.error_target = m.error_target * diagonal;
  // The closed parts of the input (medial_parts.hpp): with more than one,
  // each sphere and inside point belongs to the part it lies deepest in
  // (largest signed distance; a sphere, where the budget is shared out per
  // part, to the part whose graph it was simplified from), each fit point
  // to the part whose surface it was sampled on, and the skeleton sums
  // each part's primitives apart.
  const std::vector<std::int32_t> triangle_part = triangle_parts(surface);
  const std::size_t part_total =
      triangle_part.empty() ? 1 : std::size_t(*std::max_element(triangle_part.begin(), triangle_part.end())) + 1;
  std::vector<TriangleMesh> part_surfaces;
  std::vector<SurfaceQuery> part_queries;
  if (part_total > 1)
    for (std::size_t p = 0; p < part_total; ++p) {
      part_surfaces.push_back(surface_part(surface, triangle_part, std::int32_t(p)));
      part_queries.emplace_back(part_surfaces.back());
    }
  const auto part_of = [&part_queries](const Vec3& point) {
    std::int32_t best = 0;
    double deepest = -std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < part_queries.size(); ++p)
      if (const double d = part_queries[p].signed_distance(point); d > deepest) deepest = d, best = std::int32_t(p);
    return best;
  };
  // With several parts, each part's medial graph is simplified alone
  // under its own share of the budget (medial_parts.hpp, part_budgets).
  std::vector<double> areas(part_total, 0.0);
  std::vector<std::size_t> shares{m.budget};
  if (part_total > 1) {
    for (std::size_t p = 0; p < part_total; ++p)
      for (const auto& t : part_surfaces[p].triangles) {
        const Vec3& a = part_surfaces[p].vertices[std::size_t(t[0])];
        areas[p] += 0.5 * (part_surfaces[p].vertices[std::size_t(t[1])] - a)
                              .cross(part_surfaces[p].vertices[std::size_t(t[2])] - a)
                              .norm();
      }
    shares = part_budgets(areas, m.budget, m.part_minimum_budget);
  }
  // With MedialOptions::tip_end_tube, the sharp tips the simplified mesh
  // still falls short of by `tip_tube_reach` spacings get a tube out to
  // them (tube_ends.hpp, reach_unreached_tips), its end at the fit's
  // radius floor.
  const auto reach_tips = [&](const QuadricOptions& options, MedialMesh& mesh) -> std::size_t {
    if (!m.tip_end_tube) return 0;
    return detail::reach_unreached_tips(
        mesh, options.reach_points, m.tip_tube_reach * diagonal / m.sample_divisions, m.tip_end_thinness,
        m.min_radius_facets * diagonal / o.measure_divisions, quadric.depth);
  };
  // What the tube ends' steps did to a simplified mesh: spikes' spheres
  // beyond moved back (extend_tube_ends), tubes added out to sharp tips
  // (reach_unreached_tips).
  struct EndCounts {
    std::size_t spikes = 0, tip_tubes = 0, bulbs = 0;
  };
  // The simplified medial mesh of `g`, its tube ends extended, at most
  // `budget` primitives; `inside_samples` as QuadricOptions's.
  const auto simplified = [&](const MedialGraph& g, std::size_t budget, int inside_samples, QuadricReport& q,
                              EndCounts& ends) {
    QuadricOptions options = quadric;
    options.budget = budget;
    options.inside_samples = inside_samples;
    options.inside_tolerance = 0.5 * diagonal / o.measure_divisions;
    if (m.tip_end_thinness > 0.0) {
      options.reach_points =
          detail::unreached_tips(g, m.tip_end_reach * diagonal / m.sample_divisions, m.tip_end_thinness,
                                 diagonal / m.sample_divisions);
      options.reach_weight = m.tip_end_weight;
    }
    MedialMesh mesh = quadric_medial_mesh(g, options, &q);
    ends.spikes = detail::extend_tube_ends(mesh, m.end_extension, m.end_spike_depth, m.end_taper_reach,
                                           m.end_bulb_slope, quadric.depth, &ends.bulbs);
    ends.tip_tubes = reach_tips(options, mesh);
    // Each tube end got one more edge: simplified further where that
    // overruns the budget.
    while (primitives(mesh) > budget && options.budget > 1) {
      options.budget -= std::min(options.budget - 1, primitives(mesh) - budget);
      mesh = quadric_medial_mesh(g, options, &q);
      ends.spikes = detail::extend_tube_ends(mesh, m.end_extension, m.end_spike_depth, m.end_taper_reach,
                                             m.end_bulb_slope, quadric.depth, &ends.bulbs);
      ends.tip_tubes = reach_tips(options, mesh);
    }
    return mesh;
  };
  const auto medial_mesh = [&](int inside_samples) {
    std::vector<std::size_t> budgets = shares;
    QuadricReport q;
    EndCounts ends;
    // The single simplification first; with several parts, each sphere
    // given the part its centre is deepest in. Where it leaves every part
    // at least its minimum it is kept (the shares would only reorder the
    // same spheres: the fit, which sums the primitives in the file's
    // order, may then end elsewhere: the close balls fused once so).
    MedialMesh mesh = simplified(graph, m.budget, inside_samples, q, ends);
    bool starved = false;
    std::size_t mixed = 0;
    if (part_total > 1) {
      for (const Vec4& sphere : mesh.spheres) mesh.parts.push_back(part_of(sphere.head<3>()));
      for (const auto& edge : mesh.edges) mixed += mesh.parts[std::size_t(edge[0])] != mesh.parts[std::size_t(edge[1])];
      for (const auto& t : mesh.triangles)
        mixed += mesh.parts[std::size_t(t[0])] != mesh.parts[std::size_t(t[1])] ||
                 mesh.parts[std::size_t(t[0])] != mesh.parts[std::size_t(t[2])];
      const std::size_t floor_share = std::min(m.part_minimum_budget, m.budget / part_total);
      for (std::size_t p = 0; p < part_total; ++p)
        starved = starved || primitives(medial_mesh_part(mesh, std::int32_t(p))) < floor_share;
    }
    if (starved) {
      q = QuadricReport{};
      ends = EndCounts{};
      const std::vector<std::int32_t> graph_parts = vertex_parts(graph);
      std::vector<MedialGraph> graphs;
      for (std::size_t p = 0; p < part_total; ++p) graphs.push_back(medial_graph_part(graph, graph_parts, std::int32_t(p)));
      std::vector<MedialMesh> meshes(part_total);
      std::vector<QuadricReport> reports(part_total);
      std::vector<EndCounts> part_ends(part_total);
      std::vector<std::size_t> done_at(part_total, 0);
      std::vector<bool> settled(part_total, false);
      // The link condition may hold a part above its share (a sheet's
      // loops): it keeps what it holds, and the parts not yet over theirs
      // share out what is left, until none is over.
      for (std::size_t pass = 0; pass < part_total; ++pass) {
        for (std::size_t p = 0; p < part_total; ++p)
          if (!settled[p] && (pass == 0 || done_at[p] != budgets[p])) {
            meshes[p] = simplified(graphs[p], budgets[p], inside_samples, reports[p], part_ends[p]);
            done_at[p] = budgets[p];
          }
        std::size_t held = 0;
        bool over = false;
        for (std::size_t p = 0; p < part_total; ++p)
          if (settled[p] || primitives(meshes[p]) > budgets[p]) {
            over = over || !settled[p];
            settled[p] = true;
            held += primitives(meshes[p]);
          }
        if (!over) break;
        std::vector<double> rest_areas;
        for (std::size_t p = 0; p < part_total; ++p)
          if (!settled[p]) rest_areas.push_back(areas[p]);
        const std::vector<std::size_t> rest =
            part_budgets(rest_areas, m.budget > held ? m.budget - held : 0, m.part_minimum_budget);
        for (std::size_t p = 0, k = 0; p < part_total; ++p)
          if (!settled[p]) budgets[p] = rest[k++];
      }
      for (std::size_t p = 0; p < part_total; ++p) {
        const QuadricReport& pr = reports[p];
        ends.spikes += part_ends[p].spikes, ends.tip_tubes += part_ends[p].tip_tubes;
        ends.bulbs += part_ends[p].bulbs;
        q.collapses += pr.collapses, q.refused_by_link += pr.refused_by_link;
        q.loops_closed += pr.loops_closed, q.loops_closed_inside += pr.loops_closed_inside;
        q.bridges_closed += pr.bridges_closed, q.holes_closed += pr.holes_closed, q.tips_held += pr.tips_held;
        q.euler_before += pr.euler_before, q.euler_after += pr.euler_after;
        q.stopped_at_budget += pr.stopped_at_budget, q.stopped_at_error += pr.stopped_at_error;
        q.stopped_without_collapse += pr.stopped_without_collapse;
        q.collapses_under_budget += pr.collapses_under_budget, q.over_error_target += pr.over_error_target;
      }
      mesh = joined_part_meshes(meshes);
    }
    if (o.progress)
      o.progress(fmt::format("medial mesh: {} spheres, {} triangles, {} tube edges, {} isolated spheres (budget {} "
                             "primitives); {} collapses ({} refused by the link condition, {} covered loops closed{}), "
                             "Euler characteristic of the medial complex {} -> {}",
                             mesh.spheres.size(), mesh.triangles.size(), mesh.edges.size(), mesh.isolated.size(),
                             m.budget, q.collapses, q.refused_by_link, q.loops_closed,
                             inside_samples > 0 ? fmt::format(", {} of them inside the input, not the balls; {} bridged "
                                                              "sheets and {} holes through sheets closed",
                                                              q.loops_closed_inside, q.bridges_closed, q.holes_closed)
                                                : std::string(),
                             q.euler_before, q.euler_after));
    if (o.progress) {
      // Why the collapses stopped: one reason per simplification (each
      // part's own where the parts were simplified apart).
      std::vector<std::string> why;
      if (q.stopped_at_budget > 0) why.push_back(fmt::format("the budget reached ({})", q.stopped_at_budget));
      if (q.stopped_at_error > 0)
        why.push_back(fmt::format("within the budget, every collapse left over the error target of {:.3g}% of the "
                                  "diagonal or refused by the link condition ({})",
                                  100 * m.error_target, q.stopped_at_error));
      if (q.stopped_without_collapse > 0)
        why.push_back(fmt::format("over the budget, no collapse the link condition allows ({})",
                                  q.stopped_without_collapse));
      o.progress(fmt::format("medial mesh: {} primitives, the collapses stopped at: {}{}", primitives(mesh),
                             fmt::join(why, "; "),
                             m.error_target > 0.0
                                 ? fmt::format("; {} collapses within the budget, {} left undone over the target",
                                               q.collapses_under_budget, q.over_error_target)
                                 : std::string()));
    }
    if (o.progress && q.tips_held > 0)
      o.progress(fmt::format("medial mesh: {} balls held in place through the collapses, each the nearest to a sample "
                             "at a protrusion's end that the pruned balls fall short of",
                             q.tips_held));
    if (o.progress && ends.spikes > 0)
      o.progress(fmt::format("medial mesh: {} spikes' spheres beyond their ends moved back to the input's surface",
                             ends.spikes));
    if (o.progress && ends.tip_tubes > 0)
      o.progress(fmt::format("medial mesh: {} tubes added out to sharp tips the mesh falls short of by half a sample "
                             "spacing or more",
                             ends.tip_tubes));
    if (o.progress && ends.bulbs > 0)
      o.progress(fmt::format("medial mesh: {} bulbs (a tube end's ball wider than its tube, the input ending with it) "
                             "given as isolated spheres, no sphere beyond",
                             ends.bulbs));
    if (part_total > 1 && o.progress) {
      std::vector<std::size_t> held(part_total, 0);
      for (std::size_t p = 0; p < part_total; ++p) held[p] = primitives(medial_mesh_part(mesh, std::int32_t(p)));
      if (starved)
        o.progress(fmt::format("medial mesh: {} parts of the input, a part under its minimum in one simplification: "
                               "each simplified alone and its own sum of fields, joined by a union; budgets {}, "
                               "primitives {}",
                               part_total, fmt::join(budgets, " "), fmt::join(held, " ")));
      else
        o.progress(fmt::format("medial mesh: {} parts of the input, each its own sum of fields, joined by a union "
                               "({} edges and triangles join spheres of two parts; primitives {})",
                               part_total, mixed, fmt::join(held, " ")));
    }
    return mesh;
  };
  const MedialMesh mesh = medial_mesh(0);
  Stage stage;
  stage.name = "medial";
  // The fit's points on the input itself (one per cell, not the cell's
  // centroid): a centroid in a crease lies in the air above it, and the fit
  // would fill the crease to reach it.
  // With several parts, each part's points apart: a cell holding two
  // parts' points would merge them into one on either.
  const bool on_surface = true;
  // Within a cell, the faces that face apart (a thin wall's two sides, a
  // sharp edge's two faces) keep a point each where each holds enough of
  // the cell (MedialOptions::fit_by_facing, fit_facing_angle_degrees,
  // fit_facing_least_area); without fit_by_facing, one point per cell.
  const double facing_angle =
      m.fit_by_facing ? m.fit_facing_angle_degrees * std::numbers::pi / 180.0 : std::numbers::pi;
  const auto fit_points_of = [&](const TriangleMesh& part) {
    return surface_points_in_cells(part, m.fit_spacing * diagonal, facing_angle, m.fit_facing_least_area);
  };
  std::vector<WeightedPoint> points;
  std::vector<std::int32_t> point_parts;
  if (part_total == 1) {
    points = fit_points_of(surface);
  } else {
    for (std::size_t p = 0; p < part_total; ++p) {
      const std::vector<WeightedPoint> part = fit_points_of(part_surfaces[p]);
      points.insert(points.end(), part.begin(), part.end());
      point_parts.insert(point_parts.end(), part.size(), std::int32_t(p));
    }
  }
  const MedialField field_of = [&o](const MedialMesh& medial) {
    Stage s;
    s.medial = medial;
    return parse_skeleton_json(skeleton_file_text(s, o));
  };
  // The fit's inside points (with MedialOptions::inside_points): the
  // pruned medial graph's vertices deeper than `inside_depth_facets`
  // facets of the measuring mesh, one per cell of the fit's spacing. The
  // surface points see only where the
  // reconstruction misses the input's surface, never a cavity opening
  // deep inside it (a sheet's radius shrunk below what the sheets around
  // it leave covered), which the meshed surface then shows as an inner
  // wall far from the input. The shallow vertices (the spikes towards
  // ridges and corners, which the smooth surface rounds) are left out:
  // holding the surface out to them would fatten it everywhere else.
  std::vector<std::vector<WeightedPoint>> centres(part_total);
  const double facet = diagonal / o.measure_divisions;
  for (const MedialVertex& v : graph.vertices)
    if (m.inside_points && v.radius >= m.inside_depth_facets * facet)
      centres[part_total > 1 ? std::size_t(part_of(v.centre)) : 0].push_back({v.centre, 1.0});
  std::vector<Vec3> inside;
  std::vector<std::int32_t> inside_parts;
  for (std::size_t p = 0; p < part_total; ++p)
    for (const WeightedPoint& c : merged_in_cells(centres[p], m.fit_spacing * diagonal, on_surface)) {
      inside.push_back(c.point);
      if (part_total > 1) inside_parts.push_back(std::int32_t(p));
    }
  point_parts.insert(point_parts.end(), inside_parts.begin(), inside_parts.end());
  // The topology error: each component and each handle too many or too
  // few counts one (topology_defects). Measured by χ and the component
  // count alone, a tunnel and a cavity opened together would cancel
  // (CGAL's camel: its hind legs fused and a hollow opened in its head,
  // which the fit's guard took for one defect, fewer than a detached hoof's).
  const MeshTopology input_topology = mesh_topology(surface);
  const bool input_hollow = detail::encloses_empty_space(surface);
  const auto depth = [&shape](const Vec3& c) { return shape.signed_distance(c); };
  // The guard needs the topology alone: it meshes without projecting the
  // vertices (mesh_stage_unprojected, the same triangles), about a sixth
  // of a meshing's work less. Each surface it meshes is kept with its
  // medial mesh (a few megabytes each, at most 3 + (topology_repairs + 1)
  // × (log2(rounds) + 1) + localize_checks + topology_checks of them):
  // where the guard ran, the fit's result is one of them, projected once
  // at the end (project_stage_mesh: mesh_stage's mesh to the bit), and
  // measuring the result (`auto`, the report) then meshes nothing again.
  //
  // The same medial mesh may be asked twice (the fit's bisection over its
  // rounds starts at the middle round, which it has tested just before
  // when the unfitted spheres were no better): the surface kept for it is
  // taken again, moved to the back as a new one would be, and nothing is
  // meshed (the mesh, and so its topology, is a function of the skeleton).
  std::vector<std::pair<MedialMesh, TriangleMesh>> meshed;
  // One progress line a meshing: a search of the guard meshes a dozen to
  // twenty times, a few seconds each, and would be silent for minutes.
  std::size_t meshings = 0;
  // `as_filled`: the cavities of the surface that fill_cavities.hpp fills
  // after the fit (hollows inside the input's solid, bubbles of a crease's
  // air where the input encloses none), all, the bubbles alone or none,
  // counted as the fill leaves them, one component and the cavity's χ
  // fewer each (topology_after_fill).
  const auto defects = [&](const MedialMesh& medial, GuardFilledCavities as_filled) {
    const auto known =
        std::find_if(meshed.begin(), meshed.end(), [&medial](const auto& entry) { return same(entry.first, medial); });
    const bool fresh = known == meshed.end();
    if (!fresh) {
      std::rotate(known, known + 1, meshed.end());
    } else {
      Stage s;
      s.name = "medial";
      s.medial = medial;
      meshed.emplace_back(medial, mesh_stage_unprojected(surface, s, o));
    }
    const long long found = topology_defects(
        input_topology,
        detail::topology_after_fill(meshed.back().second,
                                    as_filled == GuardFilledCavities::none
                                        ? std::vector<detail::Cavity>{}
                                        : detail::spurious_cavities(meshed.back().second, depth, input_hollow,
                                                                    facet, m.kernel_sigma),
                                    as_filled));
    if (fresh && o.progress)
      o.progress(fmt::format("medial fit: topology test {}: the skeleton meshed at the diagonal / {}, {} defect{}",
                             ++meshings, o.measure_divisions, found, found == 1 ? "" : "s"));
    return found;
  };
  const TopologyError topology_error = [&](const MedialMesh& medial) {
    return defects(medial, GuardFilledCavities::none);
  };
  // The guard meshes the skeleton as the measure does, so it is off where
  // the measure would refuse that work (--measure-budget): the fit never
  // changes the primitive count, so one estimate holds for every round.
  Stage estimate;
  estimate.name = "medial";
  estimate.medial = mesh;
  const std::string too_much = over_measure_budget(measure_work(surface, estimate, o, 0.0), o.measure_budget);
  if (!too_much.empty() && o.progress) o.progress("medial fit: topology not guarded: " + too_much);
  // With MedialOptions::grow_within_input, where a ball is out of the
  // radius bound with its neighbour, the smaller first grows up to its
  // centre's distance to the input's surface (medial_slope.hpp).
  std::optional<SurfaceQuery> input;
  Clearance clearance;
  if (m.grow_within_input) {
    input.emplace(surface);
    clearance = [&input](const Vec3& centre) { return input->distance(centre); };
  }
  MedialFitOptions fit = m.fit;
  fit.min_radius = m.min_radius_facets * diagonal / o.measure_divisions;
  fit.triangle_radius = m.triangle_radius;
  // The fit's guard (fit_medial_mesh) bounds each round's topology error
  // by the unfitted spheres'. The unfitted surface is counted as it is
  // (what the result would be without the fit), each fitted one with the
  // cavities MedialOptions::guard_filled_cavities names as the fill will
  // leave them: by default the bubbles of a crease's air, which the fill
  // takes away. Counted as losses, a bubble stops the fit where its rounds
  // seal a crease's mouth (CGAL's man: round 5 of 30 sealed one under the
  // chin, and the fit stopped after round 4 at 3.64 / 0.482). A hollow in
  // the input's solid stays a loss: counted as filled, the hollows a round
  // opens no longer pay for the tunnels it opens too, and the guard takes
  // rounds with both (CGAL's Chinese dragon: χ 2 → −2). The unfitted
  // surface counted as filled too bounds the rounds by a tunnel of the
  // unfitted spheres that the input's sub-facet tunnels make look like
  // progress (the man's first round closed it: the fit kept round 0).
  GuardFilledCavities as_filled = m.guard_filled_cavities;
  const auto fitted = [&](const MedialMesh& start, MedialFitReport* fit_report) {
    Stage s;
    s.name = "medial";
    const std::vector<Vec4> unfitted = fit_start(start, fit, clearance).spheres;
    TopologyError guard;
    if (too_much.empty())
      guard = [&](const MedialMesh& medial) {
        return defects(medial, medial.spheres != unfitted ? as_filled : GuardFilledCavities::none);
      };
    if (!start.spheres.empty())
      s.medial = fit_medial_mesh(start, points, inside, field_of, fit, fit_report, o.progress, guard, clearance,
                                 point_parts);
    for (auto& [medial, surface_mesh] : meshed)
      if (same(medial, s.medial)) s.meshed = std::move(surface_mesh);
    meshed.clear();
    return s;
  };
  const auto handles_doubled = [](const MeshTopology& t) {
    return 2 * (long long)t.components - t.euler_characteristic;
  };
  // Each cavity of `s`'s surface (spurious_cavities) filled by an isolated
  // sphere, at most `room` of them, and meshed again; how many.
  const auto fill = [&](Stage& s, std::size_t room) {
    std::vector<detail::Cavity> balls =
        detail::spurious_cavities(*s.meshed, depth, input_hollow, facet, m.kernel_sigma);
    if (balls.size() > room) balls.resize(room);
    for (const detail::Cavity& cavity : balls) {
      s.medial.isolated.push_back(std::int32_t(s.medial.spheres.size()));
      s.medial.spheres.push_back(cavity.ball);
      if (part_total > 1) s.medial.parts.push_back(part_of(cavity.ball.head<3>()));
    }
    if (!balls.empty()) {
      topology_error(s.medial);
      s.meshed = std::move(meshed.back().second);
      meshed.clear();
    }
    return balls.size();
  };
  // The fit and the fill, first with the guard counting the fit's rounds
  // as the fill leaves them (`as_filled`); where the fill then leaves a
  // cavity open and the result has more components than the unfitted
  // spheres', the cavity the guard let through was no loss the fill could
  // take away (CGAL's femur: a hollow the capped sphere did not close, 2
  // components for 1), and both run again with every cavity counted.
  for (const GuardFilledCavities counted : {m.guard_filled_cavities, GuardFilledCavities::none}) {
    as_filled = counted;
    {
      Stage first = fitted(mesh, &r.fit);
      stage.medial = std::move(first.medial);
      stage.meshed = std::move(first.meshed);
    }
    // A tunnel too many: a hole in a sheet of the medial mesh that the sum
    // of fields leaves open, where the input has none (a wall thinner than
    // the samples' spacing, or pruning, punched it). The medial mesh again,
    // with every loop the input holds a disc across closed
    // (QuadricOptions::inside_samples), fitted again; kept where its
    // topology is closer to the input's. Only then: elsewhere the sum of
    // fields covers such holes, and the result stays as it was.
    // (Where the input touches itself at a vertex, the most it may have:
    // every such point read as a neck, topology_defects.)
    if (too_much.empty() && m.close_inside_samples > 0 && stage.meshed &&
        handles_doubled(mesh_topology(*stage.meshed)) >
            handles_doubled(input_topology) + (long long)input_topology.pinches) {
      const long long before = topology_defects(input_topology, mesh_topology(*stage.meshed));
      if (o.progress)
        o.progress(fmt::format("medial path: the result has more tunnels than the input (Euler characteristic {} "
                               "against {}): the medial mesh again, its loops across the input closed",
                               mesh_topology(*stage.meshed).euler_characteristic, input_topology.euler_characteristic));
      MedialFitReport again_report;
      Stage again = fitted(medial_mesh(m.close_inside_samples), &again_report);
      if (!again.meshed && !again.medial.spheres.empty()) {
        topology_error(again.medial);
        again.meshed = std::move(meshed.back().second);
        meshed.clear();
      }
      const long long after =
          again.meshed ? topology_defects(input_topology, mesh_topology(*again.meshed)) : before;
      if (o.progress)
        o.progress(fmt::format("medial path: topology defects {} -> {}{}: {}", before, after,
                               again.meshed ? fmt::format(" (Euler characteristic {})",
                                                          mesh_topology(*again.meshed).euler_characteristic)
                                            : std::string(),
                               after < before ? "kept" : "not kept"));
      if (after < before) {
        stage.medial = std::move(again.medial);
        stage.meshed = std::move(again.meshed);
        r.fit = again_report;
      }
    }
    // A cavity: the fit shrank the sheets about a place inside a solid part
    // of the input until their sum fell below iso there, and no surface point
    // sees the hollow (CGAL's Chinese dragon: a wall of 100 triangles, 3
    // facets across, 2.3% of the diagonal inside the input). The guard lets it through where the
    // unfitted spheres were as far from the input's topology in another way
    // (the dragon's: a piece apart and a tunnel, 2 defects; the fit, its
    // steps tested, ended at 1, the cavity), and the guard counts the fit's
    // rounds as this fill leaves them. Or a bubble of a crease's air that the
    // result sealed at the crease's mouth, where the input encloses no empty
    // space (CGAL's man: under the chin, 0.02 across; in the armpits). Each
    // such cavity is filled by an
    // isolated sphere that holds it (fill_cavities.hpp); the surface is
    // meshed again and kept where it is closer to the input's topology. The
    // spheres count in the budget: where there is no room for them, as many
    // of the smallest primitives are dropped. (Simplifying the medial mesh
    // to fewer primitives and fitting it again instead took the dragon twice
    // as long and ended at 2 defects, its own.)
    if (too_much.empty() && stage.meshed) {
      const std::size_t cavities =
          detail::spurious_cavities(*stage.meshed, depth, input_hollow, facet, m.kernel_sigma).size();
      if (cavities > 0) {
        const long long before = topology_defects(input_topology, mesh_topology(*stage.meshed));
        Stage filled;
        filled.medial = stage.medial;
        filled.meshed = stage.meshed;
        const std::size_t used = primitives(stage.medial);
        const std::size_t dropped = used + cavities > m.budget
                                        ? detail::drop_smallest_primitives(filled.medial, used + cavities - m.budget,
                                                                           m.kernel_sigma)
                                        : 0;
        const std::size_t added = fill(filled, m.budget - std::min(m.budget, primitives(filled.medial)));
        const long long after = added > 0 ? topology_defects(input_topology, mesh_topology(*filled.meshed)) : before;
        if (o.progress)
          o.progress(fmt::format("medial path: {} cavities of the result (hollows inside the input, bubbles of its "
                                 "creases' air) filled by as many isolated spheres{}; topology defects {} -> {}: {}",
                                 added,
                                 dropped > 0 ? fmt::format(" ({} smallest primitives dropped to make room within the "
                                                           "budget of {})",
                                                           dropped, m.budget)
                                             : std::string(),
                                 before, after, after < before ? "kept" : "not kept"));
        if (after < before) {
          stage.medial = std::move(filled.medial);
          stage.meshed = std::move(filled.meshed);
        }
      }
    }
    if (as_filled == GuardFilledCavities::none || !stage.meshed) break;
    if (detail::spurious_cavities(*stage.meshed, depth, input_hollow, facet, m.kernel_sigma).empty()) break;
    Stage unfitted;
    unfitted.name = "medial";
    unfitted.medial = fit_start(mesh, fit, clearance);
    const std::size_t start_components = mesh_topology(mesh_stage_unprojected(surface, unfitted, o)).components;
    const std::size_t end_components = mesh_topology(*stage.meshed).components;
    if (end_components <= start_components) break;
    if (o.progress)
      o.progress(fmt::format("medial path: a cavity left open, {} components where the unfitted spheres have {}: "
                             "fitted again with every cavity counted as a topology defect",
                             end_components, start_components));
    r.fit = MedialFitReport{};
  }
  // A tunnel too many that runs through air: a crease of the input sealed
  // at its mouth along a stretch, both its ends open (homer's mouth, a slit
  // between the lips narrower than the measure's facet, rotated: a pipe of
  // air through the head). It is there before the fit, so the guard keeps
  // it, and no loop of the medial mesh runs round it for the second medial
  // mesh to close. Found where a small box of the meshed surface's
  // triangles is a band whose removal lowers the genus, and the input's
  // triangles there ring no tunnel of its own (plug_tunnels.hpp); plugged
  // by an isolated sphere across it, smallest first, meshed again (any
  // bubble the plug closes off filled as the fill fills one) and kept
  // where the topology defects drop and the farthest distance between the
  // surface and the input (its vertices to the input, the fit's points to
  // it) stays within the larger of what it was and two facets of the
  // measure; of those, the nearest. A plug buries the slit it seals, and
  // the input's points deep in it move away from the surface (homer
  // rotated: a sphere of radius 0.024 closed the tunnel and left the
  // slit's bottom 2.6% of the diagonal inside). Two places are tried per
  // box size, each a meshing; only where the result has more tunnels than
  // the input, so elsewhere the skeleton is the same bytes.
  const auto excess = [&](const TriangleMesh& s) {
    return handles_doubled(mesh_topology(s)) - handles_doubled(input_topology) - (long long)input_topology.pinches;
  };
  // The two-sided farthest distance, as far as it is cheap to see: the
  // surface's vertices to the input, and the fit's points on the input
  // to the surface (a plug that buries a deep slit moves the input's
  // points in it away from the surface; the smallest primitive dropped
  // for room may uncover a part of the input).
  const auto farthest = [&](const TriangleMesh& s) {
    double far = 0.0;
    for (const Vec3& v : s.vertices) far = std::max(far, shape.distance(v));
    const SurfaceQuery result(s);
    for (const WeightedPoint& p : points) far = std::max(far, result.distance(p.point));
    return far;
  };
  // An isolated sphere `ball` added to the result (the smallest primitive
  // dropped first where the budget has no room, nothing where even that
  // leaves none), meshed again, any cavity it closes off filled as the fill
  // fills one; its topology defects against `before`, and where they drop,
  // its farthest distance to the input.
  struct Trial {
    Stage stage;
    std::size_t dropped = 0, filled = 0;
    long long after = 0;
    double far = 0.0;
  };
  const auto with_sphere = [&](const Vec4& ball, long long before) -> std::optional<Trial> {
    Trial t;
    t.stage.medial = stage.medial;
    t.dropped = primitives(t.stage.medial) + 1 > m.budget
                    ? detail::drop_smallest_primitives(t.stage.medial, 1, m.kernel_sigma)
                    : 0;
    if (primitives(t.stage.medial) + 1 > m.budget) return std::nullopt;
    t.stage.medial.isolated.push_back(std::int32_t(t.stage.medial.spheres.size()));
    t.stage.medial.spheres.push_back(ball);
    if (part_total > 1) t.stage.medial.parts.push_back(part_of(ball.head<3>()));
    topology_error(t.stage.medial);
    t.stage.meshed = std::move(meshed.back().second);
    meshed.clear();
    t.filled = fill(t.stage, m.budget - std::min(m.budget, primitives(t.stage.medial)));
    t.after = topology_defects(input_topology, mesh_topology(*t.stage.meshed));
    if (t.after < before) t.far = farthest(*t.stage.meshed);
    return t;
  };
  const auto trial_line = [](const Vec4& ball, const char* where, const Trial& t, long long before,
                             std::optional<double> bound) {
    return fmt::format(
        "medial path: an isolated sphere of radius {:.4g} at ({:.4g}, {:.4g}, {:.4g}) {}{}{}: topology defects {} -> "
        "{}{}",
        ball.w(), ball.x(), ball.y(), ball.z(), where,
        t.dropped > 0 ? ", the smallest primitive dropped to make room within the budget" : "",
        t.filled > 0 ? fmt::format(", {} cavities it closed filled", t.filled) : std::string(), before, t.after,
        t.after < before && bound
            ? fmt::format(", farthest distance to the input {:.4g} against at most {:.4g}", t.far, *bound)
            : std::string());
  };
  constexpr double bound_facets = 2.0;
  if (too_much.empty() && m.plug_air_tunnels && stage.meshed) {
    // Cut boxes of 2, 3 and 4 facets a side: a pipe's wall narrower than
    // a facet fits in the first where it runs along the grid, the others
    // hold it where it runs across (homer rotated: 1.5 facets).
    constexpr std::array<double, 3> cells{1.0, 1.5, 2.0};
    constexpr std::size_t tries = 2;
    std::optional<double> bound;
    while (excess(*stage.meshed) > 0) {
      const long long before = topology_defects(input_topology, mesh_topology(*stage.meshed));
      std::optional<Stage> best;
      double best_far = 0.0;
      for (const double cell : cells) {
        const std::vector<Vec4> plugs = detail::air_tunnel_plugs(*stage.meshed, surface, cell * facet);
        if (o.progress)
          o.progress(fmt::format("medial path: the result has more tunnels than the input (Euler characteristic {} "
                                 "against {}): {} boxes of {} facets a side cut a tunnel of its surface the input "
                                 "does not have",
                                 mesh_topology(*stage.meshed).euler_characteristic,
                                 input_topology.euler_characteristic, plugs.size(), 2.0 * cell));
        if (!plugs.empty() && !bound) bound = std::max(farthest(*stage.meshed), bound_facets * facet);
        for (std::size_t i = 0; i < std::min(tries, plugs.size()); ++i) {
          std::optional<Trial> t = with_sphere(plugs[i], before);
          if (!t) break;
          if (o.progress) o.progress(trial_line(plugs[i], "across the tunnel", *t, before, bound));
          if (t->after < before && t->far <= *bound && (!best || t->far < best_far)) {
            best = std::move(t->stage);
            best_far = t->far;
          }
        }
      }
      if (o.progress)
        o.progress(best ? fmt::format("medial path: the plug of the least farthest distance kept ({:.4g})", best_far)
                        : std::string("medial path: no plug kept"));
      if (!best) break;
      stage.medial = std::move(best->medial);
      stage.meshed = std::move(best->meshed);
    }
  }
  // A thin protrusion kept (TipOptions) that leaves the result farther
  // from the input's topology than the input has: its piece, apart from
  // the body's sheet, may meet the body's surface round a loop (homer's
  // ears: a tunnel). The medial path again without the tips, kept where
  // its topology is closer (the result is then the one before the tips).
  if (tips_kept > 0 && stage.meshed) {
    const long long with = topology_defects(input_topology, mesh_topology(*stage.meshed));
    // A piece kept apart that came back apart (CGAL's camel: the tail's
    // neck, where two tube ends' spheres overlap, thinner than the
    // measure's facet): the medial path again with the pieces joined to the
    // body (TipJoin). Where that has defects still, it tries without the
    // tips itself, so the better of the three is kept.
    if (m.tip_join == TipJoin::where_apart && mesh_topology(*stage.meshed).components > input_topology.components) {
      if (o.progress)
        o.progress(fmt::format("medial path: {} components with the thin protrusions kept apart, {} in the input: "
                               "the medial path again with them joined to the body",
                               mesh_topology(*stage.meshed).components, input_topology.components));
      ReconstructOptions joined = o;
      joined.medial.tip_join = TipJoin::always;
      MedialPathReport again_report;
      Stage again = medial_stage(surface, joined, &again_report);
      const long long after =
          again.meshed ? topology_defects(input_topology, mesh_topology(*again.meshed)) : with;
      if (o.progress)
        o.progress(fmt::format("medial path: topology defects with the thin protrusions joined {} against {}: {}",
                               after, with, after < with ? "kept" : "not kept"));
      if (after < with) {
        if (report != nullptr) *report = again_report;
        return again;
      }
    } else if (with > 0) {
      if (o.progress)
        o.progress(fmt::format("medial path: {} topology defects with the thin protrusions kept: the medial path "
                               "again without them",
                               with));
      ReconstructOptions without = o;
      without.medial.tip_reach = 0.0;
      MedialPathReport again_report;
      Stage again = medial_stage(surface, without, &again_report);
      const long long after =
          again.meshed ? topology_defects(input_topology, mesh_topology(*again.meshed)) : with;
      if (o.progress)
        o.progress(fmt::format("medial path: topology defects without the thin protrusions {} against {}: {}", after,
                               with, after < with ? "kept" : "not kept"));
      if (after < with) {
        if (report != nullptr) *report = again_report;
        return again;
      }
    }
  }
  // A piece apart: an outer shell of the result too many (the dino
  // rotated: a toe's tip beyond a neck the fit thinned below the measure's
  // facet, 12 triangles 0.07 from the foot). It comes after the fit, so the
  // guard, bounded by the unfitted spheres' defects, may keep it, and after
  // the thin protrusions' passes, which join a piece the pruning cut off.
  // Bridged by an isolated sphere across the gap to the nearest other
  // shell (piece_bridges), the smallest piece first, meshed again and kept
  // as a plug is: where the topology defects drop and the farthest distance
  // between the surface and the input stays within the larger of what it
  // was and two facets of the measure. Where the sphere that only touches
  // both shells leaves the joint below the facet, one a facet larger.
  if (too_much.empty() && m.bridge_pieces && stage.meshed) {
    std::optional<double> bound;
    for (;;) {
      const std::vector<Vec4> bridges = detail::piece_bridges(*stage.meshed, input_topology.components);
      if (bridges.empty()) break;
      if (o.progress)
        o.progress(fmt::format("medial path: the result has {} components, {} in the input: {} pieces apart, "
                               "each bridged to the nearest other",
                               mesh_topology(*stage.meshed).components, input_topology.components, bridges.size()));
      if (!bound) bound = std::max(farthest(*stage.meshed), bound_facets * facet);
      const long long before = topology_defects(input_topology, mesh_topology(*stage.meshed));
      std::optional<Stage> kept;
      for (const double grown : {0.0, facet}) {
        const Vec4 ball(bridges.front().x(), bridges.front().y(), bridges.front().z(), bridges.front().w() + grown);
        std::optional<Trial> t = with_sphere(ball, before);
        if (!t) break;
        if (o.progress) o.progress(trial_line(ball, "across the gap", *t, before, bound));
        if (t->after < before && t->far <= *bound) {
          kept = std::move(t->stage);
          break;
        }
      }
      if (o.progress) o.progress(kept ? "medial path: the bridge kept" : "medial path: no bridge kept");
      if (!kept) break;
      stage.medial = std::move(kept->medial);
      stage.meshed = std::move(kept->meshed);
    }
  }
  if (stage.meshed) {
    Stage s;  // as topology_error meshed it
    s.name = "medial";
    s.medial = stage.medial;
    project_stage_mesh(*stage.meshed, surface, s, o);
  }
  stage.points = r.spheres = stage.medial.spheres.size();
  if (report != nullptr) *report = r;
  return stage;
}

}  // namespace skelconv::reconstruct
