// src/cli/view_command.hpp — `skelconv view SKELETON.json -o VIEW.html`.
//
// Writes one self-contained HTML page that ray-marches the skeleton's
// surface f = iso on the GPU with WebGL2 (skelconv/view/view_page.hpp,
// docs/view.md). The page is written atomically and only when the whole
// skeleton can be shown: otherwise one "skelconv: error: ..." line naming
// the JSON path of what the viewer cannot evaluate, exit 2, no file.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace skelconv::cli {

struct ViewOptions {
  std::string skeleton_path;
  std::string output_path;
  bool mesh_preview = false;  ///< --mesh-preview: the mesh preview whatever the skeleton
};

/// Registers the `view` subcommand on `app`, filling `options` when parsed.
CLI::App* add_view_command(CLI::App& app, ViewOptions& options);

/// Runs `view`; returns the process exit status.
int run_view(const ViewOptions& options);

}  // namespace skelconv::cli
