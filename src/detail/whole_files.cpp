// Implementation of whole_files.hpp.
#include "whole_files.hpp"

#include <fstream>
#include <system_error>

#include <unistd.h>  // getpid

#include "skelconv/errors.hpp"

namespace skelconv::detail {

namespace {

std::filesystem::path temporary_for(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".skelconv-partial-" + std::to_string(::getpid());
  return temporary;
}

bool write_whole(const std::string& text, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  return out && out.write(text.data(), std::streamsize(text.size())) && out.flush();
}

}  // namespace

void write_files_atomically(const std::vector<std::pair<std::string, std::filesystem::path>>& files) {
  std::error_code ignored;
  const auto remove_temporaries = [&](std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) std::filesystem::remove(temporary_for(files[k].second), ignored);
  };
  for (const auto& file : files) require_not_directory(file.second);  // before any is written
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (!write_whole(files[k].first, temporary_for(files[k].second))) {
      remove_temporaries(k + 1);
      throw InputError("cannot write the file", files[k].second.string());
    }
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code error;
    std::filesystem::rename(temporary_for(files[k].second), files[k].second, error);
    if (error) {
      // Those renamed already stay: a rename in a folder just written to
      // fails only if the folder changed meanwhile.
      for (std::size_t j = k; j < files.size(); ++j) std::filesystem::remove(temporary_for(files[j].second), ignored);
      throw InputError("cannot write the file", files[k].second.string());
    }
  }
}

void write_file_atomically(const std::string& text, const std::filesystem::path& path) {
  write_files_atomically({{text, path}});
}

void require_not_directory(const std::filesystem::path& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw InputError("is a directory: the output must be a file name", path.string());
}

void check_writable(const std::filesystem::path& path) {
  require_not_directory(path);
  const std::filesystem::path probe = temporary_for(path);
  const bool writable = write_whole(std::string(), probe);
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
  if (!writable) throw InputError("cannot write the file", path.string());
}

}  // namespace skelconv::detail
