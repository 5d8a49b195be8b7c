// src/cli/text_output.hpp — writing a whole text file or nothing.
#pragma once

#include <filesystem>
#include <string>

namespace skelconv::cli {

/// Writes `text` to a temporary sibling of `path` and renames it into place;
/// throws InputError located at `path` (nothing left behind) on failure. The
/// temporary's name carries the process id, so that two runs writing the
/// same file (ctest -j) do not remove each other's, as in the mesh writer
/// (triangle_mesh.cpp).
void write_text_atomically(const std::string& text, const std::filesystem::path& path);

}  // namespace skelconv::cli
