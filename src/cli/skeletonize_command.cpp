// Implementation of skeletonize_command.hpp.
#include "skeletonize_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "count_option.hpp"
#include "exit_status.hpp"
#include "report_image.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/mesh_check.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/sample_noise.hpp"
#include "../detail/whole_files.hpp"
#include "text_output.hpp"

namespace skelconv::cli {
namespace {

std::string summary(const reconstruct::Reconstruction& r, const std::string& output,
                    const reconstruct::ReconstructOptions& options) {
  std::string text = fmt::format("output: {}\n", output);
  // Each path's own counts, only for the paths that ran (--method medial
  // runs no curve path, --method curve no medial path).
  if (options.method != reconstruct::SkeletonMethod::medial) {
    text += fmt::format("samples: {}\nmedial_vertices: {}\npruned_vertices: {}\npruned_branches: {}\nspurs_removed: {}\n",
                        r.samples, r.medial_vertices, r.pruning.vertices_removed, r.pruning.branches_removed,
                        r.spurs_removed);
  }
  if (options.method != reconstruct::SkeletonMethod::curve) {
    const reconstruct::MedialPathReport& m = r.medial_path;
    text += fmt::format("medial_path_samples: {}\nmedial_path_vertices: {}\nmedial_path_pruned: {}\n", m.samples,
                        m.vertices, m.pruned);
  }
  for (const auto& s : r.stages) {
    if (s.name == "medial") {
      text += fmt::format("stage medial: spheres {}, triangles {}, edges {}, isolated {}\n", s.medial.spheres.size(),
                          s.medial.triangles.size(), s.medial.edges.size(), s.medial.isolated.size());
    } else {
      text += fmt::format("stage {}: branches {}, ends {}, junctions {}, points {}\n", s.name, s.branches.size(),
                          s.ends, s.junctions, s.points);
    }
  }
  const reconstruct::PrimitiveCounts n = reconstruct::primitive_counts(r.stages.back(), options);
  return text + fmt::format("result: {} ({} scalis_segment, {} scalis_triangle, {} point)\n", r.stages.back().name,
                            n.segments, n.triangles, n.points);
}

/// One stage's entry of the report: counts, distances and Euler
/// characteristic of its meshed surface, times.
std::string stage_report(const reconstruct::Stage& s, const TriangleMesh& input,
                         const reconstruct::ReconstructOptions& options,
                         const std::function<void(std::string_view)>& progress, bool measure) {
  const reconstruct::PrimitiveCounts n = reconstruct::primitive_counts(s, options);
  std::string text = fmt::format("{{\"name\": \"{}\", \"branches\": {}, \"ends\": {}, \"junctions\": {}, \"points\": {}, "
                                 "\"primitives\": {{\"scalis_segment\": {}, \"scalis_triangle\": {}, \"point\": {}}}, "
                                 "\"seconds\": {:.3g}",
                                 s.name, s.branches.size(), s.ends, s.junctions, s.points, n.segments, n.triangles,
                                 n.points, s.seconds);
  if (!measure) return text + "}";
  const std::string refused = reconstruct::over_measure_budget(reconstruct::measure_work(input, s, options),
                                                               options.measure_budget);
  if (!refused.empty()) {
    if (progress) progress(fmt::format("stage {}: {}", s.name, refused));
    return text + fmt::format(", \"not_measured\": \"{}\"}}", refused);
  }
  if (progress && !s.measured) progress(fmt::format("measuring {}: {} primitives", s.name, n.total()));
  const reconstruct::StageMeasure m = reconstruct::measure(input, s, options);
  const reconstruct::SurfaceDistance& d = m.distance;
  if (progress) progress(fmt::format("measured {}: Hausdorff {:.4g}, RMS {:.4g} of the diagonal, Euler characteristic {}",
                                     s.name, d.hausdorff / d.diagonal, d.rms / d.diagonal, m.euler_characteristic));
  return text + fmt::format(", \"hausdorff\": {:.6g}, \"rms\": {:.6g}, \"diagonal\": {:.17g}, \"euler_characteristic\": {}, "
                            "\"components\": {}, \"measure_seconds\": {:.3g}}}",
                            d.hausdorff / d.diagonal, d.rms / d.diagonal, d.diagonal, m.euler_characteristic,
                            m.components, m.seconds);
}

/// The report's "input_repair": null, or what --repair did to the mesh
/// (reconstruct::InputRepair): "holes" (an open or non-manifold surface
/// closed) and "self_intersection" (crossings joined), each null when not
/// needed.
std::string repair_json(const reconstruct::InputRepair& repair, double seconds) {
  const reconstruct::SurfaceRepair& s = repair.surface;
  const reconstruct::OverlapRepair& o = repair.overlaps;
  if (!s.repaired() && o.crossing_pairs == 0) return "null";
  const std::string holes =
      s.repaired() ? fmt::format("{{\"non_manifold_edges\": {}, \"vertices_split\": {}, \"isolated_vertices_removed\": {}, "
                                 "\"boundary_edges\": {}, \"holes_filled\": {}, \"holes_not_faired\": {}, "
                                 "\"triangles_added\": {}, \"vertices_added\": {}, \"largest_hole_area\": {:.4g}, "
                                 "\"triangles_reoriented\": {}, \"triangles_flipped\": {}, \"parts_flipped\": {}}}",
                                 s.non_manifold_edges, s.vertices_split, s.isolated_vertices_removed, s.boundary_edges,
                                 s.holes_filled, s.holes_not_faired, s.triangles_added, s.vertices_added,
                                 s.largest_hole_area, s.triangles_reoriented, s.triangles_flipped, s.parts_flipped)
                   : "null";
  const std::string union_ =
      o.crossing_pairs > 0 ? fmt::format("{{\"crossing_pairs\": {}, \"action\": \"boolean_union\", "
                                         "\"triangles_removed\": {}, \"triangles_added\": {}, \"cavities_filled\": {}}}",
                                         o.crossing_pairs, o.triangles_removed, o.triangles_added, o.cavities_filled)
                           : "null";
  return fmt::format("{{\"holes\": {}, \"self_intersection\": {}, \"seconds\": {:.3g}}}", holes, union_, seconds);
}

std::string report_json(const reconstruct::Reconstruction& r, const TriangleMesh& input,
                        const reconstruct::ReconstructOptions& options,
                        const std::function<void(std::string_view)>& progress, bool result_only,
                        const std::string& input_repair) {
  const MeshTopology input_topology = mesh_topology(input);
  std::string text = fmt::format("{{\"samples\": {}, \"medial_vertices\": {}, \"pruned_vertices\": {}, "
                                 "\"pruned_branches\": {}, \"spurs_removed\": {}, \"tolerance\": {:.17g}, "
                                 "\"input_repair\": {}, \"budget\": {}, \"medial_error\": {:.17g}, \"curve_over_budget\": {}, "
                                 "\"input_euler_characteristic\": {}, \"input_components\": {}, \"input_pinches\": {}, "
                                 "\"medial_seconds\": {:.3g}, "
                                 "\"result\": \"{}\", \"stages\": [",
                                 r.samples, r.medial_vertices, r.pruning.vertices_removed,
                                 r.pruning.branches_removed, r.spurs_removed, r.tolerance, input_repair,
                                 options.medial.budget, options.medial.error_target,
                                 r.curve_over_budget > 0 ? std::to_string(r.curve_over_budget) : std::string("null"),
                                 input_topology.euler_characteristic, input_topology.components, input_topology.pinches,
                                 r.medial_seconds, r.stages.back().name);
  // A stage `auto` already meshed to choose its result carries its
  // distances whatever result_only says: they cost nothing more.
  for (std::size_t k = 0; k < r.stages.size(); ++k)
    text += (k == 0 ? "\n  " : ",\n  ") +
            stage_report(r.stages[k], input, options, progress,
                         !result_only || k + 1 == r.stages.size() || r.stages[k].measured.has_value());
  text += "]";
  if (options.method != reconstruct::SkeletonMethod::curve) {
    // The medial path's own graph and its fit, round by round (absolute
    // distances: the RMS of the first stage's first-order start and of the
    // first stage (the inside points' cavities included), the L^p mean of
    // the second;
    // reconstruct/medial_fit.hpp).
    const reconstruct::MedialPathReport& m = r.medial_path;
    text += fmt::format(",\n \"medial_path\": {{\"samples\": {}, \"medial_vertices\": {}, \"pruned_vertices\": {}, "
                        "\"spheres\": {}, \"fit_first_order\": [",
                        m.samples, m.vertices, m.pruned, m.spheres);
    for (std::size_t k = 0; k < m.fit.first_order.size(); ++k)
      text += fmt::format("{}{:.6g}", k == 0 ? "" : ", ", m.fit.first_order[k]);
    text += "], \"fit_rms\": [";
    for (std::size_t k = 0; k < m.fit.rms.size(); ++k) text += fmt::format("{}{:.6g}", k == 0 ? "" : ", ", m.fit.rms[k]);
    text += "], \"fit_worst\": [";
    for (std::size_t k = 0; k < m.fit.worst.size(); ++k)
      text += fmt::format("{}{:.6g}", k == 0 ? "" : ", ", m.fit.worst[k]);
    // The rounds kept when the fit went back to keep the topology, else null.
    text += "], \"fit_rounds_kept\": " + (m.fit.rounds_kept ? fmt::format("{}", *m.fit.rounds_kept) : "null");
    // After a failed repair, whether the fit went back to the repair's last
    // round that keeps the topology; else null.
    text += ", \"fit_back_to_repair\": " +
            (m.fit.back_to_repair ? std::string(*m.fit.back_to_repair ? "true" : "false") : "null") + "}";
  }
  return text + "}\n";
}

}  // namespace

CLI::App* add_skeletonize_command(CLI::App& app, SkeletonizeOptions& options) {
  CLI::App* command =
      app.add_subcommand("skeletonize", "Reconstruct a skeleton file of SCALIS primitives from a closed mesh");
  command->add_option("INPUT", options.input_path, "Closed mesh: .ply (ASCII or binary), .obj, .off or .stl (binary or ASCII)")->required();
  command->add_option("-o,--output", options.output_path, "Output skeleton file (JSON)")->required();
  command->add_option("--method", options.method,
                      "auto (default): the curve skeleton when it is within 1% (Hausdorff) and 0.2% (RMS) of the diagonal "
                      "with the input's topology, else both skeletons below and keep the one closer to the input; curve: "
                      "Ferley's curve skeleton (tubes, branches, junctions); medial: a medial mesh (sheets as SCALIS "
                      "triangles, tubes as SCALIS segments)")
      ->check(CLI::IsMember({"auto", "curve", "medial"}));
  command->add_option("--budget", options.budget,
                      "At most this many primitives in the result of --method auto and medial (default 500): the medial mesh "
                      "is simplified to it, and auto does not keep a curve skeleton of more (--method curve only "
                      "says so); fewer primitives, larger error")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  command->add_option("--medial-error", options.medial.error_target,
                      fmt::format("Fewer primitives where they are not needed: once within --budget, the medial mesh is "
                                  "simplified further while each merged sphere stays within this × the diagonal of every "
                                  "tangent plane of the input at the samples it stands for (default {}: off, "
                                  "simplified to the budget; 0.008 gives a dumbbell 16 primitives)",
                                  options.medial.error_target))
      ->check(CLI::Range(0.0, 1.0));
  command->add_option("--medial-prune-angle", options.medial.prune_angle_degrees,
                      fmt::format("Pruning threshold θ in degrees of the medial path (default {})",
                                  options.medial.prune_angle_degrees));
  command->add_option("--medial-prune-span", options.medial.prune_span,
                      fmt::format("The medial path also prunes Voronoi vertices whose contact samples span less than "
                                  "this × the diagonal (default {})", options.medial.prune_span));
  command->add_flag("--medial-inside-points", options.medial.inside_points,
                    "The medial fit also keeps the medial vertices at least 3 facets deep inside the result (a fit "
                    "that hollows a thick part out; better on some shapes, worse on others: "
                    "docs/reconstruction_medial.md, \"Inside points\")");
  command->add_option("--medial-radius-weight", options.medial.quadric_radius_weight,
                      fmt::format("The medial mesh's simplification also counts the radius varying along an edge, "
                                  "this × (r_u − r_v)² a plane, so that sheets keep smaller triangles where their "
                                  "radius varies, as at sharp edges (default {}; docs/reconstruction_medial.md, "
                                  "\"The medial mesh\")",
                                  options.medial.quadric_radius_weight))
      ->check(CLI::Range(0.0, 1e6));
  command->add_option("--medial-newton-steps", options.medial.fit.newton_steps,
                      "Newton steps along the gradient for each fit point's distance to the result, after a first-order "
                      "start (default 1, at most 3; 0: first-order distances only): 1 measures sharp edges and corners "
                      "truly (docs/reconstruction_medial.md, \"The fit\")")
      ->check(CLI::Range(0, 3));
  command->add_option("--medial-bound-ties", options.medial.fit.bound_tie_passes,
                      fmt::format("Where no damping makes a round of the medial fit descend, the round is tried again with "
                                  "the radii the radius bound lowered tied to the neighbour that bounded them, each "
                                  "step solved again at most this many times (default {}: never; 3 was measured; "
                                  "docs/reconstruction_medial.md, \"The fit\")",
                                  options.medial.fit.bound_tie_passes))
      ->check(CLI::Range(0, 10));
  command->add_flag("--medial-thin-walls,!--no-medial-thin-walls", options.medial.thin_walls,
                    "The medial path samples the input again, up to 2.5 times finer, where a part of it is a thin wall "
                    "(a medial sheet under 1.5 sample spacings thick and about 6 or more across), so that the wall's "
                    "sheet is not a net of holes; on by default, --no-medial-thin-walls leaves every part at one "
                    "spacing (docs/reconstruction_medial.md, \"Thin walls\")");
  command
      ->add_option_function<std::string>(
          "--medial-join-tips",
          [&options](const std::string& when) {
            options.medial.tip_join = when == "never"    ? reconstruct::TipJoin::never
                                      : when == "always" ? reconstruct::TipJoin::always
                                                         : reconstruct::TipJoin::where_apart;
          },
          "When the medial path joins each thin protrusion it keeps (a piece the pruning cut off: a tail, a teat) to "
          "the body again, along the pruned medial path or by an edge between overlapping balls: where-apart "
          "(default: only where the result with them apart has more components than the input, the medial path "
          "run again), always, never (docs/reconstruction_medial.md, \"Thin protrusions\")")
      ->check(CLI::IsMember({"never", "where-apart", "always"}));
  command->add_flag("--medial-grow-within-input", options.medial.grow_within_input,
                    "Where the medial fit's radius bound finds a ball inside its neighbour's, it first grows the "
                    "smaller up to its centre's distance to the input, then shrinks the larger (better on some "
                    "shapes, worse on others: docs/reconstruction_medial.md, \"What limits it\")");
  command->add_flag("--medial-tip-tubes,!--no-medial-tip-tubes", options.medial.tip_end_tube,
                    "Where the simplified medial mesh still falls short of a sharp tip (a cone under 30 degrees "
                    "half-angle) by half a sample spacing or more, a tube edge is added out towards it; on by "
                    "default, --no-medial-tip-tubes adds none (docs/reconstruction_medial.md, \"Sharp tips the mesh "
                    "still falls short of\")");
  CLI::Option* geometric_radius = command->add_flag_callback(
      "--medial-geometric-triangle-radius",
      [&options] { options.medial.triangle_radius = reconstruct::TriangleRadiusRule::geometric(); },
      "Each medial triangle takes the geometric mean of its spheres' radii, not only the steepest fans: a "
      "sheet fanning out to a thin part no longer fills the crease where that part meets the body (better "
      "on some shapes, worse on others: docs/reconstruction_medial.md, \"The primitives\")");
  command
      ->add_flag_callback(
          "--medial-arithmetic-triangle-radius",
          [&options] { options.medial.triangle_radius = reconstruct::TriangleRadiusRule::arithmetic(); },
          "Each medial triangle takes the arithmetic mean of its spheres' radii, the steepest fans too (by "
          "default those take the geometric mean: docs/reconstruction_medial.md, \"The primitives\")")
      ->excludes(geometric_radius);
  command->add_flag("--medial-fit-facings", options.medial.fit_by_facing,
                    "The medial fit keeps one point per facing within each cell of its grid, not one per cell: a "
                    "sharp edge's two faces and a thin wall's two faces are each seen (better on most CAD parts, "
                    "worse on others: docs/reconstruction_medial.md, \"What limits it\")");
  auto* all_filled = command->add_flag_callback(
      "--medial-guard-counts-filled-cavities",
      [&options] { options.medial.guard_filled_cavities = reconstruct::GuardFilledCavities::all; },
      "The medial fit's topology guard counts each fitted round as the cavity fill after the fit leaves it, hollows "
      "inside the input too (by default only bubbles of a crease's air; worse on CGAL's Chinese dragon: "
      "docs/reconstruction_medial.md, \"The guard counting a crease's bubbles of air as filled\")");
  command
      ->add_flag_callback(
          "--medial-guard-counts-every-cavity",
          [&options] { options.medial.guard_filled_cavities = reconstruct::GuardFilledCavities::none; },
          "The medial fit's topology guard counts every cavity of a fitted round as a defect, bubbles of a "
          "crease's air too (docs/reconstruction_medial.md, \"The guard counting a crease's bubbles of air as filled\")")
      ->excludes(all_filled);
  command->add_flag_callback(
      "--no-medial-plug-air-tunnels", [&options] { options.medial.plug_air_tunnels = false; },
      "Where the medial result has more tunnels than the input, leave a tunnel through a pipe of air unplugged "
      "(by default an isolated sphere plugs it: docs/reconstruction_medial.md, \"Tunnels through air\")");
  command->add_flag_callback(
      "--no-medial-bridge-pieces", [&options] { options.medial.bridge_pieces = false; },
      "Where the medial result has more components than the input, leave a piece apart as it is (by default an "
      "isolated sphere bridges it to the nearest other: docs/reconstruction_medial.md, \"Pieces apart\")");
  command->add_option("--prune-angle", options.prune_angle, "Pruning threshold θ in degrees of the curve path (default 90)");
  command->add_option("--prune-span", options.prune_span,
                      "Also prune Voronoi vertices whose contact samples span less than this × the diagonal "
                      "(default 0; about 4 × the noise amplitude for noisy samples)");
  command->add_option("--epsilon", options.epsilon, "Pavlidis tolerance × skeleton size (default 0.02)");
  command->add_option("--report", options.report_path, "Also mesh the result (every stage with --report-stages all) and write each stage's primitive counts and times, and the meshed ones' two-sided Hausdorff and RMS distances to the input and Euler characteristics (JSON)");
  command->add_option("--report-image", options.report_image_path,
                      "Also write a picture (PNG): the input, the skeleton, and its meshed surface coloured by the "
                      "distance to the input, with the Hausdorff and RMS distances and the Euler characteristics");
  command->add_option_function<std::string>(
               "--report-stages", [&options](const std::string& which) { options.report_result_only = which == "result"; },
               "result (default): mesh and measure the result stage only (the others keep their counts and times, and the "
               "distances of a stage --method auto measured to choose); "
               "all: every stage (each a meshing: minutes on a large input)")
      ->check(CLI::IsMember({"all", "result"}));
  command->add_option("--measure-divisions", options.measure_divisions,
                      "--report and --method auto mesh the skeleton with facets of the diagonal / this (default 100)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double value = 0.0;
            // A non-number is left to CLI11's own conversion, which names it;
            // the range is written as the other options write theirs.
            if (!CLI::detail::lexical_cast(text, value) || (value >= 10 && value <= 1000)) return {};
            return "must be a number from 10 to 1000, got " + text;
          },
          "10..1000"));
  command->add_flag("--bezier-junctions", options.bezier_junctions,
                    "Join three branches by a cubic Bézier triangle (Ferley §2.4) of SCALIS triangles");
  command->add_option("--noise", options.noise,
                      "Test robustness: move every sample by up to this × the diagonal (seed 0); --report still "
                      "measures against the clean input");
  command->add_option("--max-triangles", options.max_triangles,
                      fmt::format("Refuse a mesh of more triangles or vertices than this (default {}), while "
                                  "reading it: the work grows with the number of samples",
                                  options.max_triangles))
      ->check(count_option(1));
  command->add_flag("--repair", options.repair,
                    "Repair the mesh instead of refusing it: split edges shared by more than two triangles, fill "
                    "holes (each at most 25% of the closed surface's area), and replace a mesh whose triangles cross "
                    "by the boolean union of its overlapping parts");
  command->add_flag("--quiet", options.quiet, "No progress lines on stderr");
  command->footer("Details: docs/reconstruction.md. Exit status 2 for bad input, 1 if a field cannot be evaluated.");
  return command;
}

int run_skeletonize(const SkeletonizeOptions& options) {
  return print_all_or_nothing([&] {
    if (!has_extension(options.output_path, ".json"))
      throw InputError("the skeleton file must end in .json", options.output_path);
    if (options.report_image_path && !has_extension(*options.report_image_path, ".png"))
      throw InputError("the report image must end in .png", *options.report_image_path);
    // The outputs are probed before the work, which can take minutes.
    detail::check_writable(options.output_path);
    if (options.report_path) detail::check_writable(*options.report_path);
    if (options.report_image_path) detail::check_writable(*options.report_image_path);
    reconstruct::ReconstructOptions ro;
    ro.method = options.method == "curve"    ? reconstruct::SkeletonMethod::curve
                : options.method == "medial" ? reconstruct::SkeletonMethod::medial
                                             : reconstruct::SkeletonMethod::automatic;
    ro.medial = options.medial;
    ro.medial.budget = options.budget;
    ro.prune_angle_degrees = options.prune_angle;
    ro.prune_span = options.prune_span;
    ro.epsilon = options.epsilon;
    ro.junction_triangles = options.bezier_junctions;
    ro.measure_divisions = options.measure_divisions;
    if (!options.quiet) ro.progress = [](std::string_view line) {
      std::fprintf(stderr, "skelconv skeletonize: %.*s\n", int(line.size()), line.data());
    };
    TriangleMesh input = read_mesh(options.input_path, options.max_triangles);
    const std::size_t merged = reconstruct::merge_coincident_vertices(input);
    const std::size_t read_vertices = input.vertices.size() + merged, read_triangles = input.triangles.size();
    reconstruct::InputRepair repair;
    const auto repair_start = std::chrono::steady_clock::now();
    try {
      reconstruct::check_mesh_size(input, options.max_triangles);
      if (options.repair) {
        repair = reconstruct::check_closed_mesh_repairing(input);
      } else {
        reconstruct::check_closed_mesh_offering_repair(input, "--repair");
      }
    } catch (const InputError& error) {
      throw error.inside(options.input_path);
    }
    const std::size_t unused = reconstruct::remove_unused_vertices(input);
    const double repair_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - repair_start).count();
    if (ro.progress) {
      std::vector<std::string> cleaned;
      if (merged) cleaned.push_back(fmt::format("{} vertices at the position of another merged into it", merged));
      if (unused) cleaned.push_back(fmt::format("{} vertices of no triangle removed", unused));
      ro.progress(fmt::format("read {} vertices, {} triangles{}", read_vertices, read_triangles,
                              cleaned.empty() ? std::string() : fmt::format(" ({})", fmt::join(cleaned, "; "))));
      if (const reconstruct::SurfaceRepair& s = repair.surface; s.repaired()) {
        std::string done;
        if (s.non_manifold_edges)
          done += fmt::format("split {} edge(s) of more than two triangles ({} vertices left split)",
                              s.non_manifold_edges, s.vertices_split);
        if (s.holes_filled)
          done += fmt::format("{}filled {} hole(s) ({} boundary edges, the largest {:.3g}% of the closed area{}), +{} "
                              "triangles, +{} vertices",
                              done.empty() ? "" : "; ", s.holes_filled, s.boundary_edges, 100.0 * s.largest_hole_area,
                              s.holes_not_faired ? fmt::format(", {} not faired", s.holes_not_faired) : std::string(),
                              s.triangles_added, s.vertices_added);
        if (s.isolated_vertices_removed)
          done += fmt::format("{}removed {} vertices of no triangle", done.empty() ? "" : "; ",
                              s.isolated_vertices_removed);
        if (s.triangles_reoriented)
          done += fmt::format("{}turned {} triangles round to agree with their neighbours", done.empty() ? "" : "; ",
                              s.triangles_reoriented);
        if (s.triangles_flipped)
          done += fmt::format("{}turned {} inward-facing part(s) round ({} triangles)", done.empty() ? "" : "; ",
                              s.parts_flipped, s.triangles_flipped);
        std::vector<std::string> problems;
        if (s.triangles_reoriented) problems.emplace_back("inconsistently oriented");
        if (s.non_manifold_edges) problems.emplace_back("not manifold");
        if (s.holes_filled || (s.isolated_vertices_removed && !s.non_manifold_edges)) problems.emplace_back("open");
        if (s.triangles_flipped) problems.emplace_back("inside out");
        ro.progress(fmt::format("the mesh is {}: {} ({:.3g} s, --repair)", fmt::join(problems, " and "), done,
                                repair_seconds));
      }
      if (const reconstruct::OverlapRepair& o = repair.overlaps; o.crossing_pairs > 0)
        ro.progress(fmt::format("the mesh intersects itself ({} crossing pairs): joined the overlapping parts "
                                "(boolean union), +{}/-{} triangles, {} in all{} ({:.3g} s, --repair)",
                                o.crossing_pairs, o.triangles_added, o.triangles_removed, input.triangles.size(),
                                o.cavities_filled ? fmt::format(", {} cavity(ies) they close off filled", o.cavities_filled)
                                                  : std::string(),
                                repair_seconds));
    }
    const TriangleMesh samples = reconstruct::with_sample_noise(input, options.noise);
    reconstruct::Reconstruction r = [&] {
      try {
        return reconstruct::reconstruct(samples, ro);
      } catch (const InputError& error) {
        if (error.where().starts_with("--")) throw;
        throw error.inside(options.input_path);
      }
    }();
    const std::string skeleton = reconstruct::skeleton_file_text(r.stages.back(), ro);
    std::string image;
    if (options.report_image_path) {
      // Measured once: the JSON report reads the same measure.
      reconstruct::Stage& result = r.stages.back();
      if (!result.measured) {
        if (ro.progress) ro.progress(fmt::format("measuring {} for the report image", result.name));
        result.measured = reconstruct::measure(input, result, ro);
      }
      image = report_image_png(input, result, *result.measured, ro);
    }
    std::string report;
    if (options.report_path) report = report_json(r, input, ro, ro.progress, options.report_result_only,
                                                      repair_json(repair, repair_seconds));
    std::vector<std::pair<std::string, std::filesystem::path>> files = {{skeleton, options.output_path}};
    if (options.report_path) files.emplace_back(report, *options.report_path);
    if (options.report_image_path) files.emplace_back(image, *options.report_image_path);
    detail::write_files_atomically(files);
    std::string text = summary(r, options.output_path, ro);
    if (options.report_image_path) text += fmt::format("report_image: {}\n", *options.report_image_path);
    return text;
  });
}

}  // namespace skelconv::cli
