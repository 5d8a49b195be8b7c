// skelconv — command-line front end of the runtime.
//
// Subcommands live in their own files (eval_command.*, mesh_command.*); add new ones next to
// it and register them below. The verifier is a separate executable (verify/).
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "bound_command.hpp"
#include "canal_command.hpp"
#include "eval_command.hpp"
#include "exit_status.hpp"
#include "mesh_command.hpp"
#include "skeletonize_command.hpp"
#include "thickness_command.hpp"
#include "view_command.hpp"

#ifndef SKELCONV_VERSION
#error "SKELCONV_VERSION must be defined by the build (src/CMakeLists.txt)"
#endif

namespace {

/// "eval, ..." — the names of the subcommands, for messages.
std::string subcommand_names(CLI::App& app) {
  std::string names;
  for (const CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) {
    names += (names.empty() ? "" : ", ") + subcommand->get_name();
  }
  return names;
}

/// Grows the heap by `reserve` bytes at once and asks the kernel to back
/// that part with transparent huge pages (2 MiB) where it allows them on
/// request (THP "madvise" mode, the common default): `mesh` touches tens of
/// megabytes of fresh heap (the grids, the mesh, its topology, the PLY
/// text), a page fault per 4 KiB page otherwise (~5,500 for Zanni's ant at
/// --size 0.04, ~10 µs each on a virtual machine, besides the TLB misses).
/// What glibc's tunable glibc.malloc.hugetlb=1 does, which a program cannot
/// set for itself. The reserve is address space only until touched; beyond
/// it the heap grows in ordinary pages. Best effort: any step that fails
/// leaves the heap as it was, and no value computed depends on it.
void heap_in_huge_pages(std::size_t reserve) {
  constexpr std::uintptr_t huge_page = std::uintptr_t(2) << 20;
  mallopt(M_TOP_PAD, int(reserve));
  const std::uintptr_t before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  // Larger than what the start-up allocations leave at the heap's top, so
  // that malloc extends the heap now, by this block and the pad; freed, it
  // returns to the top (nothing is trimmed below M_TRIM_THRESHOLD).
  void* block = std::malloc(std::size_t(1) << 20);
  const std::uintptr_t after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(block);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again for later growth
  const std::uintptr_t first = (before + huge_page - 1) & ~(huge_page - 1), last = after & ~(huge_page - 1);
  if (block == nullptr || last <= first) return;
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // a refusal changes nothing
}

/// True when the first argument is a word (not an option) that names no
/// subcommand. CLI11 would report it as "A subcommand is required".
bool first_argument_is_unknown_subcommand(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  for (const CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) {
    if (subcommand->check_name(argv[1])) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace skelconv::cli;
  // A command runs once and exits: memory it frees is worth keeping for its
  // next allocations rather than handing back to the system, which maps
  // fresh zeroed pages again at the next touch (a page fault each). glibc
  // by default unmaps blocks above ~128 KiB on free and trims the heap's
  // top above 128 KiB; `mesh` allocates and frees blocks of megabytes (the
  // grid, the mesh, its topology, the PLY text) and took ~1,300 page faults
  // fewer of ~6,800 with these (Zanni's ant at --size 0.04). 32 MiB is
  // glibc's largest mmap threshold on 64-bit systems.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);

  CLI::App app("Closed-form convolution-surface fields of skeleton primitives.", "skelconv");
  app.set_version_flag("--version", std::string("skelconv ") + SKELCONV_VERSION);
  app.require_subcommand(1);

  EvalOptions eval_options;
  const CLI::App* eval = add_eval_command(app, eval_options);
  CanalOptions canal_options;
  const CLI::App* canal = add_canal_command(app, canal_options);
  BoundOptions bound_options;
  const CLI::App* bound = add_bound_command(app, bound_options);
  MeshCommandOptions mesh_options;
  const CLI::App* mesh = add_mesh_command(app, mesh_options);
  SkeletonizeOptions skeletonize_options;
  const CLI::App* skeletonize = add_skeletonize_command(app, skeletonize_options);
  ThicknessOptions thickness_options;
  const CLI::App* thickness = add_thickness_command(app, thickness_options);
  ViewOptions view_options;
  const CLI::App* view = add_view_command(app, view_options);

  if (first_argument_is_unknown_subcommand(app, argc, argv)) {
    report_error(std::string("unknown subcommand \"") + argv[1] + "\" (available: " + subcommand_names(app) + ")");
    return exit_bad_input;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version are "errors" with exit code 0: CLI11 prints them.
    if (error.get_exit_code() == 0) return app.exit(error);
    report_error(std::string(error.what()) + " (see skelconv --help)");
    return exit_bad_input;
  }

  try {
    if (eval->parsed()) return run_eval(eval_options);
    if (canal->parsed()) return run_canal(canal_options);
    if (bound->parsed()) return run_bound(bound_options);
    if (mesh->parsed()) {
      heap_in_huge_pages(std::size_t(256) << 20);
      return run_mesh(mesh_options);
    }
    if (skeletonize->parsed()) return run_skeletonize(skeletonize_options);
    if (thickness->parsed()) return run_thickness(thickness_options);
    if (view->parsed()) return run_view(view_options);
  } catch (const std::exception& error) {
    report_error(std::string("internal error: ") + error.what());
    return exit_evaluation_failed;
  }
  return exit_success;  // unreachable: require_subcommand(1)
}
