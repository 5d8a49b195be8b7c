// Implementation of canal_command.hpp.
#include "canal_command.hpp"

#include <cstdio>

#include "exit_status.hpp"
#include "skelconv/canal/canal_file.hpp"
#include "skelconv/canal/canal_mesh.hpp"
#include "skelconv/errors.hpp"

namespace skelconv::cli {
namespace {

constexpr const char* canal_footer = R"(
FILE.json: {"spheres": [{"center": [x, y, z], "radius": r}, ...],
            "interpolation": "lorentz" | "linear",
            "pole": {"center": [...], "radius": r} or {"normal": [...], "offset": d}  (lorentz only),
            "samples": N}
Output (stdout): {"samples": [{"t": t, "sphere": {"center": [...], "radius": r},
                  "circle": {"center": [...], "radius": rho, "normal": [...]} or null}, ...]}
                 at t = j/(N-1), numbers with 17 significant digits.
--mesh OUT.ply:  the canal surface swept by the characteristic circles at the N
                 samples, closed by spherical caps (.ply binary or .obj).
On any error nothing is written to stdout and no mesh file; one
"skelconv: error: ..." line on stderr; exit status 2 for bad input, 1 if the
family cannot be sampled or meshed. See docs/cli.md and docs/canal.md.)";

}  // namespace

CLI::App* add_canal_command(CLI::App& app, CanalOptions& options) {
  CLI::App* canal =
      app.add_subcommand("canal", "Sample a canal surface (a family of spheres through given spheres) and its circles");
  canal->add_option("FILE", options.input_path, "Canal input (JSON)")->required();
  canal->add_option("--mesh", options.mesh_path, "Also write the canal surface as a mesh (.ply or .obj)");
  canal->footer(canal_footer);
  return canal;
}

int run_canal(const CanalOptions& options) {
  return print_all_or_nothing([&] {
    const canal::CanalInput input = canal::load_canal_file(options.input_path);
    std::vector<canal::FamilySample<double>> samples;
    try {
      samples = canal::sample_canal(input);
    } catch (const InputError& error) {
      throw InputError(error.what(), options.input_path);  // "file.json: spheres[2]: ..."
    }
    std::string output = canal::canal_samples_json(samples);
    if (!options.mesh_path.empty()) write_mesh(canal::mesh_canal_surface(samples), options.mesh_path);
    return output;
  });
}

}  // namespace skelconv::cli
