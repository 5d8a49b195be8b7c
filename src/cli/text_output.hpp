// src/cli/text_output.hpp — the output files' names (writing them whole:
// src/detail/whole_files.hpp).
#pragma once

#include <filesystem>
#include <string_view>

namespace skelconv::cli {

/// Whether `path` ends in `extension` (".json", lower case) whatever the
/// case of its letters: OUT.JSON and out.Json are JSON files too, as the
/// mesh writer and reader take .PLY and .OBJ (triangle_mesh.cpp).
bool has_extension(const std::filesystem::path& path, std::string_view extension);

}  // namespace skelconv::cli
