// src/cli/point_lines.hpp — parsing the "x y z" query lines of `skelconv eval`.
#pragma once

#include <optional>
#include <string_view>

#include "skelconv/geometry.hpp"

namespace skelconv::cli {

/// Parses one input line: three finite decimal numbers separated by spaces or
/// tabs (a trailing '\r' of a CRLF file is ignored; a leading '+' is
/// allowed). Returns std::nullopt for a blank line, which the caller skips.
/// Throws skelconv::InputError with the problem only (the caller adds the
/// line number), e.g. `expected three numbers "x y z", got "1 2" (2 values)`.
std::optional<Vec3> parse_point_line(std::string_view line);

}  // namespace skelconv::cli
