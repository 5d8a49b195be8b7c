// Implementation of thickness_command.hpp.
#include "thickness_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "exit_status.hpp"
#include "progress_lines.hpp"
#include "../detail/whole_files.hpp"
#include "text_output.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"
#include "skelconv/skeleton/scalis_thickness_correction.hpp"
#include "skelconv/skeleton/thickness_correction.hpp"

namespace skelconv::cli {
namespace {

constexpr const char* thickness_footer = R"(
FILE.json: a skeleton of "segment" primitives with one "compact" kernel, in one
           plane, at the top level (their sum); their weights are replaced.
           Or of "scalis_segment" primitives (one "compact" kernel, in one
           plane): then the radii are the thickness asked for, and --tau is
           not given.
Output:    OUT.json, the corrected skeleton; on stdout the thickness (distance
           from the skeleton to the surface along the plane's normal) at the
           samples of each input segment, before (base weight w_tau everywhere)
           and after the correction. See docs/thickness_correction.md.
Progress:  in a run longer than a second, about one line a second on stderr,
           "skelconv thickness: iteration K of at most N, worst departure
           X%, T s" (each iteration re-measures every sample); none with
           --quiet.)";

/// min, max and worst |r − τ|/τ of the samples on edge `edge`.
struct EdgeSummary {
  double min = INFINITY, max = 0, worst = 0;
  int count = 0;
};

EdgeSummary summarise(const std::vector<ThicknessSample>& samples, std::size_t edge, double tau) {
  EdgeSummary s;
  for (const ThicknessSample& x : samples) {
    if (x.edge != edge) continue;
    s.min = std::min(s.min, x.thickness), s.max = std::max(s.max, x.thickness);
    s.worst = std::max(s.worst, std::abs(x.thickness - tau) / tau);
    ++s.count;
  }
  return s;
}

std::string report(const SegmentGraph& g, const ThicknessCorrection& c, double tau, double tolerance,
                   const std::string& output) {
  std::string text = fmt::format("output: {}\ntau: {:.6g}\nbase_weight: {:.9g}\ncorrected_nodes:", output, tau,
                                 c.base_weight);
  for (std::size_t n : c.corrected_nodes) {
    text += fmt::format(" ({:.6g}, {:.6g}, {:.6g})", g.nodes[n].x(), g.nodes[n].y(), g.nodes[n].z());
  }
  double worst_after = 0;
  for (const ThicknessSample& x : c.after) worst_after = std::max(worst_after, std::abs(x.thickness - tau) / tau);
  // Not converged is not failure: say how far the result is from the tolerance.
  text += fmt::format("\niterations: {}\nconverged: {} (worst after: {:.2f}%, tolerance {:.2f}%)\n", c.iterations,
                      c.converged ? "yes" : "no", 100 * worst_after, 100 * tolerance);
  text += "segment          samples  before: min      max      worst    after: min      max      worst\n";
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const EdgeSummary b = summarise(c.before, e, tau), a = summarise(c.after, e, tau);
    text += fmt::format("{:<16} {:>7}  {:>12.6f} {:>8.6f} {:>7.2f}%  {:>11.6f} {:>8.6f} {:>7.2f}%\n",
                        g.edges[e].location, b.count, b.min, b.max, 100 * b.worst, a.min, a.max, 100 * a.worst);
  }
  return text;
}

/// The SCALIS report: as report(), relative to each sample's target τ(t).
std::string scalis_report(const ScalisSegmentGraph& g, const ScalisThicknessCorrection& c, double tolerance,
                          const std::string& output) {
  std::size_t points = 0;
  for (const ScalisThicknessCorrection::NodePoint& p : c.points) points += p.weight != 0 ? 1 : 0;
  std::string text = fmt::format("output: {}\nadded: {} ramp segments, {} points\ncorrected_nodes:", output,
                                 c.ramps.size(), points);
  for (std::size_t n : c.corrected_nodes) {
    text += fmt::format(" ({:.6g}, {:.6g}, {:.6g})", g.nodes[n].x(), g.nodes[n].y(), g.nodes[n].z());
  }
  const auto worst = [](const std::vector<ThicknessSample>& samples, std::size_t edge) {
    double w = 0;
    for (const ThicknessSample& x : samples) {
      if (x.target > 0 && (edge == SIZE_MAX || x.edge == edge)) w = std::max(w, std::abs(x.thickness / x.target - 1));
    }
    return w;
  };
  text += fmt::format("\niterations: {}\nconverged: {} (worst after: {:.2f}%, tolerance {:.2f}%)\n", c.iterations,
                      c.converged ? "yes" : "no", 100 * worst(c.after, SIZE_MAX), 100 * tolerance);
  text += "segment          radius                worst |r/tau - 1|: before   after\n";
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    text += fmt::format("{:<16} {:>9.6f} {:>9.6f}  {:>26.2f}% {:>7.2f}%\n", g.edges[e].location, g.radius[e][0],
                        g.radius[e][1], 100 * worst(c.before, e), 100 * worst(c.after, e));
  }
  return text;
}

/// The library names the options by their field; the user typed flags.
InputError as_flag(const InputError& error) {
  std::string flag = error.where() == "thickness"             ? "tau"
                     : error.where() == "point_support_ratio" ? "point_support"
                                                              : error.where();
  std::replace(flag.begin(), flag.end(), '_', '-');
  return InputError(error.problem(), "--" + flag);
}

}  // namespace

CLI::App* add_thickness_command(CLI::App& app, ThicknessOptions& options) {
  CLI::App* c = app.add_subcommand(
      "thickness", "Correct the thickness of a graph of compact-kernel segments (Zanni 2013 5.1)");
  c->add_option("FILE", options.input_path, "Skeleton (JSON)")->required();
  c->add_option("--tau", options.tau, "Requested thickness tau (> 0, below the kernel's R); classical segments only")
      ->each([&options](const std::string&) { options.tau_given = true; });
  c->add_option("-o,--output", options.output_path, "Corrected skeleton (JSON)")->required();
  c->add_option("--tolerance", options.tolerance, "Relative departure |r - tau|/tau that needs correction")->capture_default_str();
  c->add_option("--max-iterations", options.max_iterations, "Levenberg-Marquardt iterations at most")->capture_default_str();
  c->add_option("--ramp-nodes", options.ramp_nodes,
                "Split points per segment leaving a corrected node (default 4; SCALIS: 8)")
      ->each([&options](const std::string&) { options.ramp_nodes_given = true; });
  c->add_option("--regularisation", options.regularisation, "Penalty on the relative weight changes")->capture_default_str();
  c->add_option("--point-support", options.point_support, "Support radius of the node points, in units of R")->capture_default_str();
  c->add_flag("--quiet", options.quiet, "No progress line on stderr");
  c->footer(thickness_footer);
  return c;
}

namespace {

/// The options' progress callback: a line a second at most (ProgressLines).
ThicknessProgress progress_printer(ProgressLines& lines, int max_iterations) {
  if (lines.quiet()) return {};
  return [&lines, max_iterations](int iteration, double worst) {
    if (lines.due())
      lines.print(fmt::format("iteration {} of at most {}, worst departure {:.2f}%", iteration, max_iterations,
                              100 * worst));
  };
}

/// Whether the file's top level holds SCALIS segments (then the radii are
/// the targets and --tau is not used).
bool is_scalis_graph(const Skeleton& skeleton) {
  for (std::size_t k = 0; k < skeleton.child_count(Skeleton::root); ++k) {
    const auto [is_blend, index] = skeleton.child(Skeleton::root, k);
    if (!is_blend && std::holds_alternative<ScalisSegment>(skeleton.primitives()[index])) return true;
  }
  return false;
}

template <class Graph, class Build>
Graph located_graph(const ThicknessOptions& options, Build build) {
  try {
    return build();
  } catch (const InputError& error) {
    throw InputError(error.what(), options.input_path);  // "file.json: primitives[2].kernel.family: ..."
  }
}

std::string run_classical(const Skeleton& skeleton, const ThicknessOptions& options, ProgressLines& lines) {
  const SegmentGraph graph = located_graph<SegmentGraph>(options, [&] { return segment_graph_of(skeleton); });
  if (!options.tau_given) throw InputError("required for a graph of classical segments", "--tau");
  ThicknessCorrectionOptions o;
  o.thickness = options.tau;
  o.tolerance = options.tolerance;
  o.max_iterations = options.max_iterations;
  o.ramp_nodes = options.ramp_nodes;
  o.regularisation = options.regularisation;
  o.point_support_ratio = options.point_support;
  o.progress = progress_printer(lines, options.max_iterations);
  ThicknessCorrection c;
  try {
    c = correct_thickness(graph, o);
  } catch (const InputError& error) {
    throw as_flag(error);
  }
  detail::write_file_atomically(corrected_skeleton_json(c), options.output_path);
  return report(graph, c, options.tau, options.tolerance, options.output_path);
}

std::string run_scalis(const Skeleton& skeleton, const ThicknessOptions& options, ProgressLines& lines) {
  const ScalisSegmentGraph graph =
      located_graph<ScalisSegmentGraph>(options, [&] { return scalis_segment_graph_of(skeleton); });
  if (options.tau_given) throw InputError("not used for SCALIS segments: their radii are the thickness", "--tau");
  ScalisThicknessCorrectionOptions o;
  o.tolerance = options.tolerance;
  o.max_iterations = options.max_iterations;
  if (options.ramp_nodes_given) o.ramp_nodes = options.ramp_nodes;
  o.regularisation = options.regularisation;
  o.point_support_ratio = options.point_support;
  o.progress = progress_printer(lines, options.max_iterations);
  ScalisThicknessCorrection c;
  try {
    c = correct_scalis_thickness(graph, o);
  } catch (const InputError& error) {
    // The radii are the file's: "file.json: primitives: ...".
    if (error.where().starts_with("primitives")) throw InputError(error.what(), options.input_path);
    throw as_flag(error);
  }
  detail::write_file_atomically(scalis_corrected_skeleton_json(graph, c), options.output_path);
  return scalis_report(graph, c, options.tolerance, options.output_path);
}

}  // namespace

int run_thickness(const ThicknessOptions& options) {
  return print_all_or_nothing([&] {
    if (!has_extension(options.output_path, ".json"))
      throw InputError("the skeleton file must end in .json", options.output_path);
    detail::check_writable(options.output_path);  // before the fit's minutes, not after them
    ProgressLines lines("thickness", options.quiet);
    const Skeleton skeleton = load_skeleton_file(options.input_path);
    return is_scalis_graph(skeleton) ? run_scalis(skeleton, options, lines) : run_classical(skeleton, options, lines);
  });
}

}  // namespace skelconv::cli
