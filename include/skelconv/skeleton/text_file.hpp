// skelconv/skeleton/text_file.hpp — reading a whole input file, with the errors the
// readers of skeleton, canal and mesh files share.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace skelconv {

/// The bytes of `path`. Throws InputError located at the path: "is a
/// directory, not a `what`", "cannot open: <reason>", "cannot read the file".
std::string read_text_file(const std::filesystem::path& path, std::string_view what);

}  // namespace skelconv
