// src/cli/bound_command.hpp — `skelconv bound SKELETON.json [--iso c]`
// and `skelconv bound SKELETON.json --octree DEPTH --box x0 y0 z0 x1 y1 z1`.
//
// Box mode: reads boxes "x0 y0 z0 x1 y1 z1" (min corner, max corner) from
// stdin, one per line (blank lines skipped), and writes "lo hi" per box
// (%.17g), a sound enclosure of the field over the box
// (skelconv/interval/enclosure.hpp), followed by "inside", "outside" or
// "undetermined" when --iso is given. Octree mode: classifies the --box to
// DEPTH levels against the iso (--iso, default the file's) and writes one
// line "level inside outside undetermined" per level. All-or-nothing like
// eval: a bad line (wrong count, NaN, min > max) is an input error at
// "line N" and nothing reaches stdout.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

struct BoundOptions {
  std::string skeleton_path;
  std::optional<double> iso;
  std::optional<int> octree_depth;
  std::vector<double> box;  ///< --box: 6 numbers
};

CLI::App* add_bound_command(CLI::App& app, BoundOptions& options);
int run_bound(const BoundOptions& options);

}  // namespace skelconv::cli
