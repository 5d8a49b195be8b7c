// src/cli/point_lines.hpp — parsing the "x y z" query lines of `skelconv eval`
// (and the box lines of `skelconv bound`).
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skelconv/geometry.hpp"

namespace skelconv::cli {

/// What `skelconv eval` accepts on standard input before it starts any work.
/// The command holds its whole input, every point and every output line in
/// memory until the last point is evaluated (all-or-nothing output), about
/// 300 bytes a point with "%.17g" input lines, so the number of points is
/// bounded; a line is bounded
/// so that input without line breaks (a binary file, /dev/zero) is refused at
/// once instead of read to its end.
struct PointInputLimits {
  /// --max-points: at most this many point lines (blank lines do not count);
  /// 10 million points hold about 3 GB.
  std::size_t max_points = 10'000'000;
  /// A point line is three numbers: "%.17g" writes at most 24 characters
  /// each (sign, 17 digits, point, "e-308"), so 4096 leaves room for any
  /// padding or longer decimal forms a tool may write.
  std::size_t max_line_length = 4096;
};

/// All of `in` (standard input), read in chunks (the query lines of `eval`,
/// and of `bound`, which keeps the line limit only). Throws InputError located
/// at "line N" as soon as line N is longer than limits.max_line_length
/// characters (the line break and a CRLF file's '\r' not counted), or the
/// input holds more than limits.max_points non-blank lines (the message
/// names --max-points); InputError if `in` cannot be read. `chunk_read`, if
/// set, is called after each chunk with the non-blank lines read so far
/// (`eval`'s progress line).
std::string read_point_input(std::FILE* in, const PointInputLimits& limits,
                             const std::function<void(std::size_t)>& chunk_read = nullptr);

/// Parses one input line: three finite decimal numbers separated by spaces or
/// tabs (a trailing '\r' of a CRLF file is ignored; a leading '+' is
/// allowed). Returns std::nullopt for a blank line, which the caller skips.
/// Throws skelconv::InputError with the problem only (the caller adds the
/// line number), e.g. `expected three numbers "x y z", got "1 2" (2 values)`.
std::optional<Vec3> parse_point_line(std::string_view line);

/// The same for a line of `count` numbers (at most 6), e.g. a box of `bound`:
/// `expected` names them in messages ("six numbers \"x0 y0 z0 x1 y1 z1\"").
std::optional<std::vector<double>> parse_number_line(std::string_view line, std::size_t count,
                                                     std::string_view expected);

}  // namespace skelconv::cli
