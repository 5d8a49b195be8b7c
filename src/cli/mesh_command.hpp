// src/cli/mesh_command.hpp — `skelconv mesh SKELETON.json -o OUT.ply|OUT.obj`.
//
// Meshes the surface f = iso of the skeleton (mesh_iso_surface.hpp), writes
// it with write_mesh (PLY binary by default, --ascii for ASCII PLY; OBJ by
// extension), and prints what it made on stdout: triangles, vertices,
// connected components, Euler characteristic, closed, manifold, time. A
// progress line goes to stderr about once a second during refinement
// (nothing for runs shorter than that, nothing with --quiet).
//
// The output path is checked (extension, writable directory) before any
// meshing, and the file is written atomically: on any error nothing is
// written, stdout stays empty and stderr holds one "skelconv: error: ..."
// line (the exit codes of exit_status.hpp).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::cli {

struct MeshCommandOptions {
  std::string skeleton_path;
  std::string output_path;
  std::string method = "cgal";
  std::optional<double> iso;
  std::optional<double> size;
  std::optional<double> distance;
  std::optional<std::size_t> max_triangles;  ///< MeshOptions::max_triangles when set
  bool ascii = false;
  bool quiet = false;
  double tolerance = Skeleton::default_tolerance;  ///< --tolerance (skeleton_field)
  unsigned threads = 0;                            ///< --threads (MeshOptions::threads; 0: every core)
};

/// Registers the `mesh` subcommand on `app`, filling `options` when parsed.
CLI::App* add_mesh_command(CLI::App& app, MeshCommandOptions& options);

/// Runs `mesh`; returns the process exit status.
int run_mesh(const MeshCommandOptions& options);

}  // namespace skelconv::cli
