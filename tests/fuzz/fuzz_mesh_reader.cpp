// libFuzzer harness for the PLY/OBJ/OFF/STL reader (skelconv::read_mesh): the
// input's first byte picks the format (modulo 4: .ply, .obj, .off, .stl), the rest
// is the file.
// read_mesh takes a path, so the bytes go to a file of this process first.
// Any outcome but a mesh or an InputError is a finding (ASan, UBSan, an
// uncaught exception, a mesh with an index out of range).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_reader.hpp"

namespace {

std::filesystem::path scratch(const char* extension) {
  const char* dir = std::getenv("TMPDIR");
  return std::filesystem::path(dir ? dir : "/tmp") /
         ("skelconv_fuzz_mesh_" + std::to_string(::getpid()) + extension);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const extensions[] = {".ply", ".obj", ".off", ".stl"};
  const auto path = scratch(extensions[data[0] % 4]);
  if (std::FILE* file = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, file);
    std::fclose(file);
  } else {
    std::abort();  // the harness cannot run: not a finding in the reader
  }
  try {
    const skelconv::TriangleMesh mesh = skelconv::read_mesh(path);
    const auto vertices = mesh.vertices.size();
    for (const auto& triangle : mesh.triangles)
      for (const std::int32_t index : triangle)
        if (index < 0 || static_cast<std::size_t>(index) >= vertices) std::abort();  // a face the reader let through
  } catch (const skelconv::InputError&) {
    // the documented refusal
  }
  return 0;
}
