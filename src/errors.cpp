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
}  // namespace

LocatedError::LocatedError(std::string problem, std::string where)
    : std::runtime_error(located_message(problem, where)),
      problem_(std::move(problem)),
      where_(std::move(where)) {}

}  // namespace skelconv
