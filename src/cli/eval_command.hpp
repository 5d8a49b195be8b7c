// src/cli/eval_command.hpp — `skelconv eval SKELETON.json`.
//
// Reads query points from stdin, one "x y z" per line, and writes one line
// "f gx gy gz" per point (printf "%.17g": round-trips every double; +inf is
// printed "inf"). Blank lines are skipped and produce no output line. The
// points are evaluated by evaluate_batch (skelconv/field/batch.hpp) on
// --threads threads (default: every core), same bytes for any count; the
// error reported is the one of the first failing line, as if evaluated in
// order.
//
// All-or-nothing: output is buffered and written only after every point has
// been evaluated, so on any error stdout stays empty and stderr holds one
// "skelconv: error: ..." line (exit codes in exit_status.hpp), after the
// progress lines of a run longer than a second (about one a second on
// stderr while the points are read and evaluated; none with --quiet). So the input
// is bounded before any point is evaluated: at most --max-points points, and
// lines of at most 4096 characters (PointInputLimits).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "point_lines.hpp"

namespace skelconv::cli {

struct EvalOptions {
  std::string skeleton_path;
  unsigned threads = 0;  ///< --threads: 0 = every core (field/batch.hpp)
  PointInputLimits limits;  ///< --max-points (point_lines.hpp)
  double tolerance = 0.0;   ///< --tolerance: Skeleton's tolerance mode, 0 = exact
  bool quiet = false;       ///< --quiet: no progress line on stderr
};

/// Registers the `eval` subcommand on `app`, filling `options` when parsed.
CLI::App* add_eval_command(CLI::App& app, EvalOptions& options);

/// Runs `eval`; returns the process exit status.
int run_eval(const EvalOptions& options);

}  // namespace skelconv::cli
