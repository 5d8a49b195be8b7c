// src/detail/whole_files.hpp — writing whole files or nothing, for every
// writer in skelconv (meshes, skeletons, reports, pages). Internal: not an
// installed header.
//
// Each text goes to a temporary sibling of its path and is renamed into
// place only when written whole, so that a failure (a full disk, a missing
// folder) never leaves a half-written file where a user expects a result.
// The temporary's name carries the process id, so that two runs writing
// the same file (ctest -j) do not remove each other's.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace skelconv::detail {

/// Writes `text` to `path` whole; throws InputError located at `path`
/// (nothing left behind) on failure.
void write_file_atomically(const std::string& text, const std::filesystem::path& path);

/// Several files, all or none: every text is written to its temporary
/// first, and the temporaries are renamed into place only when all were
/// written (a report that cannot be written leaves no skeleton file behind).
/// Throws InputError located at the first path that cannot be written.
void write_files_atomically(const std::vector<std::pair<std::string, std::filesystem::path>>& files);

/// InputError at `path` if it names a directory: the rename of a temporary
/// over it would fail only after all the work, with the other outputs
/// already written.
void require_not_directory(const std::filesystem::path& path);

/// Throws InputError("cannot write the file", path) unless a file can be
/// created at `path` (the temporary write_file_atomically would use, created
/// empty and removed), and for a directory as require_not_directory. Run
/// before long work, so that a bad output path is refused at once rather
/// than after it.
void check_writable(const std::filesystem::path& path);

}  // namespace skelconv::detail
