// Implementation of point_lines.hpp.
#include "point_lines.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "exit_status.hpp"

namespace skelconv::cli {
namespace {

constexpr std::string_view blanks = " \t\r\v\f";

/// The most numbers a line holds: six, a box of `bound`.
constexpr std::size_t max_numbers = 6;

/// The first max_numbers blank-separated tokens of a line and how many there
/// are in all: a line of a million values costs no more memory than one of seven.
struct Tokens {
  std::array<std::string_view, max_numbers> first;
  std::size_t count = 0;
};

Tokens split_on_blanks(std::string_view line) {
  Tokens tokens;
  std::size_t start = line.find_first_not_of(blanks);
  while (start != std::string_view::npos) {
    const std::size_t end = std::min(line.find_first_of(blanks, start), line.size());
    if (tokens.count < tokens.first.size()) tokens.first[tokens.count] = line.substr(start, end - start);
    ++tokens.count;
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
  if (line.size() <= max_length) return printable(line);
  return printable(line.substr(0, max_length - 3)) + "...";
}

}  // namespace

std::optional<std::vector<double>> parse_number_line(std::string_view line, std::size_t count,
                                                     std::string_view expected) {
  if (line.ends_with('\r')) line.remove_suffix(1);
  const Tokens tokens = split_on_blanks(line);
  if (tokens.count == 0) return std::nullopt;

  const auto fail = [&](const std::string& detail) {
    throw InputError(fmt::format("expected {}, got \"{}\" ({})", expected, excerpt(line), printable(detail)));
  };
  if (tokens.count != count) fail(fmt::format("{} value{}", tokens.count, tokens.count == 1 ? "" : "s"));
  std::vector<double> values;
  for (std::size_t k = 0; k < count; ++k) {
    const ParsedNumber number = parse_coordinate(tokens.first[k]);
    if (!number.problem.empty()) fail(number.problem);
    values.push_back(number.value);
  }
  return values;
}

std::optional<Vec3> parse_point_line(std::string_view line) {
  const std::optional<std::vector<double>> values = parse_number_line(line, 3, "three numbers \"x y z\"");
  if (!values) return std::nullopt;
  return Vec3((*values)[0], (*values)[1], (*values)[2]);
}

std::string read_point_input(std::FILE* in, const PointInputLimits& limits,
                             const std::function<void(std::size_t)>& chunk_read) {
  std::string text;
  std::size_t line_number = 1, line_length = 0, points = 0;
  bool line_has_value = false;
  char chunk[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(chunk, 1, sizeof chunk, in)) > 0) {
    for (std::size_t k = 0; k < count; ++k) {
      const char c = chunk[k];
      if (c == '\n') {
        ++line_number, line_length = 0, line_has_value = false;
        continue;
      }
      // A CRLF file's '\r' is not part of the line (parse_point_line).
      if (c != '\r' && ++line_length > limits.max_line_length) {
        throw InputError(fmt::format("longer than {} characters: a line holds one query, a few numbers",
                                     limits.max_line_length),
                         fmt::format("line {}", line_number));
      }
      if (!line_has_value && blanks.find(c) == std::string_view::npos) {
        line_has_value = true;
        if (++points > limits.max_points) {
          throw InputError(fmt::format("more than {} points, the limit (--max-points): every point and its "
                                       "output line are held in memory until the last one is evaluated; split "
                                       "the input, or raise --max-points if the memory is there",
                                       limits.max_points),
                           fmt::format("line {}", line_number));
        }
      }
    }
    text.append(chunk, count);
    if (chunk_read) chunk_read(points);
  }
  // errno names the cause: "Is a directory" for `skelconv eval < folder`.
  if (std::ferror(in)) throw InputError(fmt::format("cannot read standard input: {}", std::strerror(errno)));
  return text;
}

}  // namespace skelconv::cli
