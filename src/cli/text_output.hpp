// src/cli/text_output.hpp — writing an output file all at once.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "skelconv/errors.hpp"

namespace skelconv::cli {

/// Writes `text` to a temporary sibling of `path` and renames it into place;
/// throws InputError (nothing left behind) on failure. The temporary's name
/// carries the process id, so that two runs writing the same file (ctest -j)
/// do not remove each other's, as in the mesh writer (triangle_mesh.cpp).
inline void write_text_atomically(const std::string& text, const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".skelconv-partial-" + std::to_string(::getpid());
  std::error_code error;
  {
    std::ofstream out(temporary, std::ios::binary);
    if (out && out.write(text.data(), std::streamsize(text.size())) && out.flush()) {
      out.close();
      std::filesystem::rename(temporary, path, error);
      if (!error) return;
    }
  }
  std::filesystem::remove(temporary, error);
  throw InputError("cannot write the file", path.string());
}

}  // namespace skelconv::cli
