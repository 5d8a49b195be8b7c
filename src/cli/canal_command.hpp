// src/cli/canal_command.hpp — `skelconv canal FILE.json [--mesh OUT.ply]`.
//
// Reads a family of spheres (skelconv/canal/canal_file.hpp: the spheres, the
// interpolation "lorentz" with its pole or "linear", the number of samples),
// writes on stdout the sampled spheres and their characteristic circles as
// JSON, and with --mesh the canal surface swept by the circles, capped at
// both ends (PLY or OBJ by extension, skelconv/mesh/triangle_mesh.hpp).
//
// All-or-nothing like `eval`: everything is computed first; on any error
// nothing reaches stdout, no mesh file is written, and stderr holds one
// "skelconv: error: ..." line (exit 2 bad input, 1 cannot be computed).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

struct CanalOptions {
  std::string input_path;
  std::string mesh_path;  ///< empty: no mesh
};

/// Registers the `canal` subcommand on `app`, filling `options` when parsed.
CLI::App* add_canal_command(CLI::App& app, CanalOptions& options);

/// Runs `canal`; returns the process exit status.
int run_canal(const CanalOptions& options);

}  // namespace skelconv::cli
