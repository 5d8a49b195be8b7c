// Implementation of skelconv/skeleton/text_file.hpp.
#include "skelconv/skeleton/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv {

std::string read_text_file(const std::filesystem::path& path, std::string_view what) {
  const std::string name = path.string();
  std::error_code error_code;
  if (std::filesystem::is_directory(path, error_code)) throw InputError(fmt::format("is a directory, not a {}", what), name);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(fmt::format("cannot open: {}", std::strerror(errno)), name);
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) throw InputError("cannot read the file", name);
  return contents.str();
}

}  // namespace skelconv
