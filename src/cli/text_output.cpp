// Implementation of text_output.hpp.
#include "text_output.hpp"

#include <fstream>

#include <unistd.h>  // getpid

#include "skelconv/errors.hpp"

namespace skelconv::cli {

void write_text_atomically(const std::string& text, const std::filesystem::path& path) {
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
