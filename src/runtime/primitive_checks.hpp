// src/runtime/primitive_checks.hpp — input checks shared by the primitives
// (Segment, ScalisSegment): one wording for one problem. Each throws
// InputError naming the field.
#pragma once

#include <string>
#include <vector>

#include "skelconv/geometry.hpp"

namespace skelconv::detail {

/// "(x, y, z)"
std::string format_point(const Vec3& p);
/// "1..16", or "2..5, 7..16" should a table have gaps; "none" when empty.
std::string format_degree_ranges(const std::vector<int>& degrees);
/// Throws unless every coordinate of v is finite.
void require_finite_point(const Vec3& v, const char* where);
/// Throws for a = b, a length below `degenerate_length_ratio` (see
/// Segment::degenerate_length_ratio) times the largest coordinate
/// magnitude, or a squared length that is not a normal double.
void require_non_degenerate(const Vec3& a, const Vec3& b, double degenerate_length_ratio);
/// Throws unless value is finite and > 0.
void require_positive_parameter(double value, const char* where);

}  // namespace skelconv::detail
