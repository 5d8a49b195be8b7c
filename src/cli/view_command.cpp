// Implementation of view_command.hpp.
#include "view_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "exit_status.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"
#include "skelconv/view/view_page.hpp"
#include "../detail/whole_files.hpp"
#include "text_output.hpp"

namespace skelconv::cli {

CLI::App* add_view_command(CLI::App& app, ViewOptions& options) {
  CLI::App* view = app.add_subcommand("view", "Write an HTML page that shows the surface f = iso in a browser (WebGL2)");
  view->add_option("SKELETON", options.skeleton_path, "Skeleton file (JSON)")->required();
  view->add_option("-o,--output", options.output_path, "Output page: .html")->required();
  view->add_flag("--mesh-preview", options.mesh_preview,
                 "Embed a triangle mesh and rasterise it even where the page could ray-march (slow GPUs)");
  view->footer(R"(
Writes one self-contained HTML file (no network needed to open it): a WebGL2
ray marcher of the blended field with orbit and zoom (mouse), an iso slider,
the skeleton overlay and per-primitive toggles. Ray-marches sums of
segments, points and SCALIS segments with the kernels of generated/glsl/;
anything else (polygons, SCALIS triangles, other blends, more than 256
primitives...) gets a mesh preview instead: a triangle mesh of f = iso drawn
by the browser, the reason printed and shown. An invalid skeleton is refused
(exit 2, no file). Details: docs/view.md.)");
  return view;
}

int run_view(const ViewOptions& options) {
  return print_all_or_nothing([&] {
    const std::filesystem::path output(options.output_path);
    if (!has_extension(output, ".html")) throw InputError("the page must be an .html file", options.output_path);
    detail::check_writable(output);
    const Skeleton skeleton = load_skeleton_file(options.skeleton_path);
    ViewPageOptions page_options;
    page_options.name = std::filesystem::path(options.skeleton_path).filename().string();
    page_options.force_mesh_preview = options.mesh_preview;
    std::string page;
    ViewPageReport report;
    try {
      page = make_view_page(skeleton, page_options, &report);
    } catch (const InputError& error) {
      // Located like the reader's errors: "skel.json: primitives[2]: ...".
      throw InputError(error.what(), options.skeleton_path);
    }
    detail::write_file_atomically(page, output);
    std::string text = fmt::format("output: {}\nprimitives: {}\nbytes: {}\nmode: {}\n", options.output_path,
                                   skeleton.size(), page.size(), report.mesh_preview ? "mesh preview" : "ray marching");
    if (report.mesh_preview) text += fmt::format("triangles: {}\nreason: {}\n", report.triangles, report.reason);
    return text;
  });
}

}  // namespace skelconv::cli
