// Implementation of point_lines.hpp.
#include "point_lines.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::cli {
namespace {

constexpr std::string_view blanks = " \t\r\v\f";

std::vector<std::string_view> split_on_blanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t start = line.find_first_not_of(blanks);
  while (start != std::string_view::npos) {
    const std::size_t end = std::min(line.find_first_of(blanks, start), line.size());
    tokens.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(blanks, end);
  }
  return tokens;
}

/// The number in `token`, or the reason it is not an acceptable coordinate.
struct ParsedNumber {
  double value = 0.0;
  std::string problem;  // empty when value is valid
};

ParsedNumber parse_coordinate(std::string_view token) {
  // std::from_chars is locale-independent and rejects "0x1p3" and leading
  // blanks; it does not take a leading '+', which we allow.
  std::string_view digits = token;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (end != digits.data() + digits.size() || error == std::errc::invalid_argument) {
    return {0.0, fmt::format("\"{}\" is not a number", token)};
  }
  if (error == std::errc::result_out_of_range) {
    // Too large (overflows to infinity) or too small (underflows to 0 or a
    // subnormal). strtod tells which; underflow is an acceptable coordinate.
    const double rounded = std::strtod(std::string(digits).c_str(), nullptr);
    if (std::isinf(rounded)) return {0.0, fmt::format("\"{}\" is too large for double precision", token)};
    return {rounded, {}};
  }
  if (!std::isfinite(value)) return {0.0, fmt::format("\"{}\" is not a finite number", token)};
  return {value, {}};
}

/// Long lines are cut in messages, so that one message stays one line.
std::string excerpt(std::string_view line) {
  constexpr std::size_t max_length = 60;
  if (line.size() <= max_length) return std::string(line);
  return std::string(line.substr(0, max_length - 3)) + "...";
}

}  // namespace

std::optional<Vec3> parse_point_line(std::string_view line) {
  if (line.ends_with('\r')) line.remove_suffix(1);
  const std::vector<std::string_view> tokens = split_on_blanks(line);
  if (tokens.empty()) return std::nullopt;

  const auto fail = [&](const std::string& detail) {
    throw InputError(fmt::format("expected three numbers \"x y z\", got \"{}\" ({})", excerpt(line), detail));
  };
  if (tokens.size() != 3) fail(fmt::format("{} value{}", tokens.size(), tokens.size() == 1 ? "" : "s"));
  Vec3 point;
  for (int k = 0; k < 3; ++k) {
    const ParsedNumber number = parse_coordinate(tokens[std::size_t(k)]);
    if (!number.problem.empty()) fail(number.problem);
    point[k] = number.value;
  }
  return point;
}

}  // namespace skelconv::cli
