// Implementation of mesh_command.hpp.
#include "mesh_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include <unistd.h>  // getpid

#include <fmt/format.h>

#include "count_option.hpp"
#include "exit_status.hpp"
#include "../detail/whole_files.hpp"
#include "text_output.hpp"
#include "thread_option.hpp"
#include "tolerance_option.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/mesh/missed_parts.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::cli {
namespace {

/// The iso used when --iso is not given: the file's top-level "iso"
/// (default 1, docs/cli_skeleton.md).
double default_iso(const Skeleton& skeleton) { return skeleton.iso(); }

constexpr const char* mesh_footer = R"(
Meshes the surface f = iso with CGAL Mesh_3 (Delaunay refinement from seeds on
every component; --method grid: OpenVDB volumeToMesh on a grid of spacing
--size, faster, no topology guarantee below the grid spacing), projects every vertex onto the surface (|f - iso|/|grad f| <=
1e-9 x the bounding-box diagonal) and writes the exact unit normals -grad f/|grad f|.
Output: .ply (binary; --ascii for text) or .obj, chosen by the extension.
Prints triangles, vertices, components, Euler characteristic, closed, manifold
and times on stdout. Exit status 2 for bad input (including an iso with no
surface or an unbounded one, and an unwritable output path), 1 if the field
cannot be evaluated. Details: docs/mesh.md.)";

/// Throws InputError (located at the output path) unless a mesh can be
/// written there: checks the extension and the directory with a probe file
/// written by write_mesh itself, then removed.
void check_output_path(const std::filesystem::path& path) {
  detail::require_not_directory(path);
  std::filesystem::path probe = path;
  // The process id keeps two runs writing to the same place (ctest -j) from
  // removing each other's probe.
  probe.replace_filename(".skelconv-probe-" + std::to_string(::getpid()) + "-" + path.filename().string());
  try {
    write_mesh(TriangleMesh{}, probe);
  } catch (const InputError& error) {
    throw InputError(error.problem(), path.string());
  }
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

std::string summary(const TriangleMesh& mesh, const MeshReport& report, const std::string& path) {
  const MeshTopology topology = mesh_topology(mesh);
  const auto yes_no = [](bool b) { return b ? "yes" : "no"; };
  std::string text;
  text += fmt::format("output: {}\n", path);
  text += fmt::format("triangles: {}\nvertices: {}\ncomponents: {}\neuler_characteristic: {}\n", topology.triangles,
                      topology.vertices, topology.components, topology.euler_characteristic);
  text += fmt::format("closed: {}\nmanifold: {}\n", yes_no(topology.closed), yes_no(topology.manifold));
  text += fmt::format("size: {:.6g}\ndistance: {:.6g}\nseeds: {}\n", report.size, report.distance, report.seeds);
  // The field's seconds are summed over the threads that evaluate it, so
  // on more than one core they may exceed the wall time: no "mesher" share
  // is derived from the two.
  text += fmt::format("time: {:.3f} s (field {:.3f} s in {} evaluations, summed over the threads)\n",
                      report.total_seconds, report.field_seconds, report.field_evaluations);
  text += fmt::format("triangles_per_second: {:.0f}\n", double(topology.triangles) / report.total_seconds);
  return text;
}

}  // namespace

CLI::App* add_mesh_command(CLI::App& app, MeshCommandOptions& options) {
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh the surface f = iso of a skeleton into a PLY or OBJ file");
  mesh->add_option("SKELETON", options.skeleton_path, "Skeleton file (JSON)")->required();
  mesh->add_option("-o,--output", options.output_path, "Output mesh: .ply or .obj")->required();
  mesh->add_option("--method", options.method,
                   "cgal (default: CGAL Mesh_3, closed manifold, certified) or grid (OpenVDB, fast)")
      ->check(CLI::IsMember({"cgal", "grid"}));
  mesh->add_option("--iso", options.iso, "Level c of the surface f = c (default 1)");
  mesh->add_option("--size", options.size, "Largest facet circumradius h (default: box diagonal / 50)");
  mesh->add_option("--distance", options.distance, "Largest facet-to-surface distance d (default h / 10)");
  mesh->add_option("--max-triangles", options.max_triangles,
                   "Refuse a --size whose mesh would have more triangles than this (estimated from the box "
                   "before meshing; default 4000000)")
      ->check(count_option(1));
  mesh->add_option("--tolerance", options.tolerance,
                   "Relative tolerance of the field (default 1e-12; 0: exact to rounding): Cauchy segments far "
                   "from a point take short quadrature rules within it (docs/field.md, \"Tolerance\")")
      ->check(tolerance_range());
  add_thread_option(mesh, options.threads,
                    "Threads for the seeds' rays, the grid's continuation and the projection (0, the default: every "
                    "core; at most 1024); the mesh is the same bytes for any value");
  mesh->add_flag("--ascii", options.ascii, "Write ASCII PLY instead of binary");
  mesh->add_flag("--quiet", options.quiet, "No progress line on stderr");
  mesh->footer(mesh_footer);
  return mesh;
}

int run_mesh(const MeshCommandOptions& options) {
  return print_all_or_nothing([&] {
    const Skeleton skeleton = load_skeleton_file(options.skeleton_path);
    check_output_path(options.output_path);
    MeshOptions mesh_options;
    mesh_options.iso = options.iso.value_or(default_iso(skeleton));
    mesh_options.method = options.method == "grid" ? MeshMethod::grid : MeshMethod::cgal;
    mesh_options.size = options.size;
    mesh_options.distance = options.distance;
    if (options.max_triangles) mesh_options.max_triangles = *options.max_triangles;
    mesh_options.threads = options.threads;
    if (!options.quiet) {
      mesh_options.progress = [](const MeshProgress& p) {
        std::fprintf(stderr, "skelconv mesh: refining, %zu field evaluations, %.1f s\n", p.field_evaluations,
                     p.seconds);
      };
    }
    MeshReport report;
    const TriangleMesh mesh = [&] {
      try {
        return mesh_iso_surface(skeleton_field(skeleton, 4, options.tolerance), mesh_options, &report);
      } catch (const InputError& error) {
        // The mesher names its option; without --iso the level is the file's.
        if (options.iso || error.where() != "--iso") throw;
        throw InputError(fmt::format("iso: {} (the file's iso, 1 unless it sets one; --iso meshes another level)",
                                     error.problem()),
                         options.skeleton_path);
      }
    }();
    write_mesh(mesh, options.output_path, options.ascii ? PlyEncoding::ascii : PlyEncoding::binary);
    if (!report.missed_parts.empty()) {
      std::fputs(fmt::format("skelconv mesh: warning: --size {:g}: {}\n", report.size,
                             missed_parts_problem(skeleton, report)).c_str(),
                 stderr);
    }
    return summary(mesh, report, options.output_path);
  });
}

}  // namespace skelconv::cli
