// grid_surface_mesh (grid_surface_mesher.hpp) by the OpenVDB module
// libskelconv_grid_mesher.so, opened on the first call.
//
// Why a module: OpenVDB's shared library costs every process that links it
// ~46 ms of relocations at start-up (measured with an empty program: 1.6 ms
// without it, 48 ms with it), which `skelconv eval` paid on every run
// (60 ms against 9) although only `mesh --method grid` uses it; the figure
// programs start the command hundreds of times. Opened here on demand, it
// costs the grid method those milliseconds once.
//
// Where the module is looked for, in order:
//   1. the path in the environment variable SKELCONV_GRID_MESHER;
//   2. where this build wrote it (SKELCONV_GRID_MESHER_BUILD_PATH);
//   3. where `cmake --install` puts it (SKELCONV_GRID_MESHER_INSTALL_PATH,
//      <libdir>/skelconv/libskelconv_grid_mesher.so under the configured prefix);
//   4. beside the program or shared object that holds this code: the Python
//      module installed by pip (setup.py) carries the module next to itself,
//      wherever the environment is.
// If none opens, the grid method fails with an EvaluationError naming them.
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "grid_surface_mesher.hpp"
#include "skelconv/errors.hpp"

namespace skelconv::detail {
namespace {

using GridMeshEntry = void (*)(const GridSurfaceRequest*, TriangleMesh*);

/// The module's path beside the file (program or shared object) this
/// function was loaded from; empty if the loader cannot tell.
std::string beside_this_binary() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&beside_this_binary), &info) == 0 || info.dli_fname == nullptr) return {};
  const std::string self = info.dli_fname;
  const std::size_t slash = self.rfind('/');
  const std::string directory = slash == std::string::npos ? "." : self.substr(0, slash);
  return directory + "/" + std::string(SKELCONV_GRID_MESHER_FILE_NAME);
}

/// The module's entry point, opened once (thread-safe); throws if no
/// candidate path holds a loadable module.
GridMeshEntry grid_mesher_entry() {
  static GridMeshEntry entry = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    std::vector<std::string> candidates;
    if (const char* path = std::getenv("SKELCONV_GRID_MESHER"); path != nullptr && *path != '\0')
      candidates.emplace_back(path);
    candidates.emplace_back(SKELCONV_GRID_MESHER_BUILD_PATH);
    candidates.emplace_back(SKELCONV_GRID_MESHER_INSTALL_PATH);
    if (std::string beside = beside_this_binary(); !beside.empty()) candidates.push_back(std::move(beside));
    std::string tried;
    for (const std::string& path : candidates) {
      // RTLD_LOCAL: OpenVDB's symbols stay inside the module.
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle == nullptr) {
        const char* why = dlerror();
        tried += fmt::format("\n  {}: {}", path, why != nullptr ? why : "not loadable");
        continue;
      }
      entry = reinterpret_cast<GridMeshEntry>(dlsym(handle, "skelconv_grid_surface_mesh"));
      if (entry != nullptr) return;
      tried += fmt::format("\n  {}: no symbol skelconv_grid_surface_mesh", path);
    }
    failure = fmt::format(
        "the grid method (--method grid) needs the OpenVDB module libskelconv_grid_mesher.so; none of these "
        "opened:{}\nset SKELCONV_GRID_MESHER to its path, or use the default method (cgal)",
        tried);
  });
  if (entry == nullptr) throw EvaluationError(failure);
  return entry;
}

}  // namespace

TriangleMesh grid_surface_mesh(const GridSurfaceRequest& request) {
  TriangleMesh mesh;
  try {
    grid_mesher_entry()(&request, &mesh);
  } catch (const std::runtime_error& error) {  // OpenVDB's, from the module (grid_surface_mesher.cpp)
    throw EvaluationError(fmt::format("the grid method (OpenVDB) cannot mesh this box at grid spacing {:g}: {}",
                                      request.voxel, error.what()));
  }
  return mesh;
}

}  // namespace skelconv::detail
