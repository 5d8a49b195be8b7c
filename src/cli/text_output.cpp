// Implementation of text_output.hpp.
#include "text_output.hpp"

#include <algorithm>
#include <cctype>

namespace skelconv::cli {

bool has_extension(const std::filesystem::path& path, std::string_view extension) {
  const std::string actual = path.extension().string();
  return std::equal(actual.begin(), actual.end(), extension.begin(), extension.end(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

}  // namespace skelconv::cli
