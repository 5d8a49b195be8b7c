// src/cli/skeletonize_command.hpp — `skelconv skeletonize INPUT.ply|.obj -o
// SKELETON.json [--prune-angle deg] [--epsilon e] [--report REPORT.json
// [--report-stages result|all]]`.
//
// Reads a closed mesh (mesh_reader.hpp), reconstructs its skeleton
// (reconstruct/reconstruct.hpp: medial graph, pruning, branches, Pavlidis,
// B-splines) and writes a skelconv skeleton file of SCALIS segments whose
// surface f = iso approximates the input. Progress lines go to stderr (not
// with --quiet); a summary (counts per stage, the result's primitives) to
// stdout. --report also meshes the result stage (or, with --report-stages
// all, every stage) and writes per stage the primitive counts, times and,
// where meshed, the distances to the input and Euler characteristic as JSON.
// Errors: one "skelconv: error: ..." line, exit 2, nothing written.
// The work grows with the input's size: a mesh of more than --max-triangles
// triangles (or vertices) is refused while it is read, before any work.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/surface_samples.hpp"

namespace skelconv::cli {

struct SkeletonizeOptions {
  std::string input_path;
  std::string output_path;
  std::optional<std::string> report_path;
  std::optional<std::string> report_image_path;  ///< --report-image: a PNG (report_image.hpp)
  /// --report-stages result (the default): mesh and measure the result stage
  /// only (a stage `auto` measured to choose keeps its distances too); all: every stage too, each a meshing as long as the result's (a
  /// curve stage of CGAL's joint.off took minutes where the whole medial path
  /// took one), which only someone comparing the stages wants to wait for.
  bool report_result_only = true;
  std::string method = "auto";  ///< --method: auto, curve or medial (ReconstructOptions::method)
  std::size_t budget = 500;     ///< --budget: the medial path's primitives (MedialOptions::budget)
  reconstruct::MedialOptions medial;  ///< --medial-*: the medial path's other options
  double prune_angle = 90.0;
  double prune_span = 0.0;  ///< × the diagonal (ReconstructOptions::prune_span)
  double epsilon = 0.02;
  bool bezier_junctions = false;
  double noise = 0.0;
  double measure_divisions = 100.0;  ///< --measure-divisions (ReconstructOptions::measure_divisions)
  bool quiet = false;
  /// --repair: join the overlapping parts of a mesh whose triangles cross
  /// (reconstruct::check_closed_mesh_joining_overlaps) instead of refusing it.
  bool repair = false;
  /// --max-triangles. The medial graph is the Delaunay triangulation of the
  /// samples: the vertices plus points spread over coarse triangles, at most
  /// SamplingOptions::max_samples of them, unless the vertices alone are
  /// more (surface_samples.hpp). A closed mesh of T triangles has about T/2
  /// vertices, so beyond 2 × max_samples triangles the vertices exceed the
  /// sample budget the reconstruction is sized for; the vertex count is
  /// held to the same limit (unused vertices are samples too).
  std::size_t max_triangles = 2 * reconstruct::SamplingOptions{}.max_samples;
};

CLI::App* add_skeletonize_command(CLI::App& app, SkeletonizeOptions& options);

int run_skeletonize(const SkeletonizeOptions& options);

}  // namespace skelconv::cli
