// Implementation of skelconv/errors.hpp.
#include "skelconv/errors.hpp"

#include <utility>

namespace skelconv {

std::string join_location(std::string_view outer, std::string_view inner) {
  if (outer.empty()) return std::string(inner);
  if (inner.empty()) return std::string(outer);
  std::string joined(outer);
  if (inner.front() != '[') joined += '.';
  joined += inner;
  return joined;
}

namespace {
std::string located_message(const std::string& problem, const std::string& where) {
  return where.empty() ? problem : where + ": " + problem;
}

/// `text` with each NUL byte written \x00. A message quotes the user's
/// bytes (a JSON key may hold "\u0000"), and what() is a C string: a NUL
/// would end the message there, cutting off the rest of the key and the
/// problem after it.
std::string without_nul(std::string text) {
  for (std::size_t at = text.find('\0'); at != std::string::npos; at = text.find('\0', at + 4))
    text.replace(at, 1, "\\x00");
  return text;
}
}  // namespace

LocatedError::LocatedError(std::string problem, std::string where)
    : std::runtime_error(located_message(without_nul(problem), without_nul(where))),
      problem_(without_nul(std::move(problem))),
      where_(without_nul(std::move(where))) {}

}  // namespace skelconv
