// src/cli/thickness_command.hpp — `skelconv thickness FILE.json --tau T
// -o OUT.json [--tolerance e] [--max-iterations n] [--ramp-nodes m]
// [--regularisation l] [--point-support r] [--quiet]`.
//
// The thickness correction of Zanni et al. 2013 §5.1
// (skelconv/skeleton/thickness_correction.hpp, docs/thickness_correction.md)
// on a plane graph of compact-kernel segments: writes the corrected skeleton
// (segments with linear weights, point primitives at corrected nodes) to
// OUT.json and prints on stdout the thickness before and after along each
// segment of the input. All-or-nothing: on any error nothing is written, one
// "skelconv: error: ..." line on stderr, exit 2 (bad input) or 1.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

struct ThicknessOptions {
  std::string input_path;
  std::string output_path;
  double tau = 0.0;
  bool tau_given = false;  ///< --tau was on the command line
  double tolerance = 0.01;
  int max_iterations = 30;
  int ramp_nodes = 4;
  bool ramp_nodes_given = false;  ///< else the SCALIS default (ScalisThicknessCorrectionOptions)
  double regularisation = 1e-5;
  double point_support = 1.25;  ///< ThicknessCorrectionOptions::point_support_ratio
  bool quiet = false;           ///< no progress lines on stderr
};

CLI::App* add_thickness_command(CLI::App& app, ThicknessOptions& options);

int run_thickness(const ThicknessOptions& options);

}  // namespace skelconv::cli
