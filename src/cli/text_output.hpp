// src/cli/text_output.hpp — writing a whole text file or nothing.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace skelconv::cli {

/// Writes `text` to a temporary sibling of `path` and renames it into place;
/// throws InputError located at `path` (nothing left behind) on failure. The
/// temporary's name carries the process id, so that two runs writing the
/// same file (ctest -j) do not remove each other's, as in the mesh writer
/// (triangle_mesh.cpp).
void write_text_atomically(const std::string& text, const std::filesystem::path& path);

/// Several files, all or none: every text is written to its temporary
/// first, and the temporaries are renamed into place only when all were
/// written (a report that cannot be written leaves no skeleton file behind).
/// Throws InputError located at the first path that cannot be written.
void write_texts_atomically(const std::vector<std::pair<std::string, std::filesystem::path>>& files);

/// Throws InputError("cannot write the file", path) unless a file can be
/// created at `path`: the temporary write_text_atomically would use, created
/// empty and removed; and InputError("is a directory: ...") for a directory
/// (whose sibling temporary is writable, but not the rename over it). Run
/// before long work, so that a bad output path is refused at once rather
/// than after it.
void check_writable(const std::filesystem::path& path);

/// InputError at `path` if it names a directory: the rename of a temporary
/// over it would fail only after all the work, with the other outputs
/// already written.
void require_not_directory(const std::filesystem::path& path);

/// Whether `path` ends in `extension` (".json", lower case) whatever the
/// case of its letters: OUT.JSON and out.Json are JSON files too, as the
/// mesh writer and reader take .PLY and .OBJ (triangle_mesh.cpp).
bool has_extension(const std::filesystem::path& path, std::string_view extension);

}  // namespace skelconv::cli
