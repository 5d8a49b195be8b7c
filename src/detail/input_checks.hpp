// src/detail/input_checks.hpp — checks and message formatting shared by the
// primitives' constructors (Segment, Polygon, ScalisSegment, ScalisTriangle) and
// Skeleton. Internal to
// skelconv_runtime: not an installed header.
//
// Each check throws InputError with the problem and, where the caller names
// one, the field ("kernel.R", "vertices[3]"); the JSON reader later prefixes
// the primitive's path.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"

namespace skelconv::detail {

/// "(1, 2, 3)", the shortest text that reads back as the same doubles.
std::string format_point(const Vec3& p);

/// "1..16", or "2..5, 7..16" should the table have gaps; "4, 6, 8" for a
/// table of even degrees; "none" for an empty list. `degrees` ascending.
std::string format_degree_ranges(const std::vector<int>& degrees);

/// Throws InputError("must be finite, got (…)", where) unless every
/// coordinate of v is finite.
void require_finite_point(const Vec3& v, const std::string& where);

/// The InputError of require_finite_query_point, out of line (cold path).
[[noreturn]] void throw_non_finite_query_point(const Vec3& p);
/// Throws InputError("query point must be finite, got (…)") unless p is
/// finite. No location: the caller knows which point (a line, a call).
/// Inline: every primitive evaluation runs it, and the test is one compare
/// per coordinate.
inline void require_finite_query_point(const Vec3& p) {
  if (!p.allFinite()) throw_non_finite_query_point(p);
}

/// Throws unless value is finite and > 0 ("must be > 0, got …", where).
void require_positive_parameter(double value, const char* where);

/// Throws for a = b, a length below `degenerate_length_ratio` (see
/// Segment::degenerate_length_ratio) times the largest coordinate
/// magnitude, or a length that is not a normal double (computed without
/// squaring, so the same at every scale).
void require_non_degenerate(const Vec3& a, const Vec3& b, double degenerate_length_ratio);

/// A kernel parameter in a primitive's frame (skelconv/detail/scaled_frame.hpp),
/// e.g. s·|AB|² or R/|AB|: throws InputError at `where` unless it is a
/// normal double (the kernel is then too sharp or too wide for the
/// primitive's size to be evaluated in double precision).
void require_normal_in_frame(double value, const char* name, const char* where);

/// JSON documents (skeleton and canal files) may nest objects and arrays
/// this deep at most: their readers walk them recursively, and a document
/// nested 100,000 deep would overflow the stack instead of being refused.
/// 256 leaves room for 126 nested blend nodes (each an object and its
/// "children" array, inside the document and its "primitives" array), far
/// beyond any hand-written or generated file.
inline constexpr std::size_t max_json_nesting = 256;

/// Called by the JSON parsers as an object or array opens at `depth` (0 for
/// the document itself): throws InputError at `where` beyond max_json_nesting.
void require_json_nesting(std::size_t depth, const std::string& where);

/// JSON text holds no NUL byte, but nlohmann's lexer reads one as the end of
/// the input: `{"primitives": []}\0junk` would parse as a valid document.
/// Throws InputError("a NUL byte at line L, column C ...") if `text` has one.
void require_no_nul_byte(std::string_view text);

/// The support radius R of a compact kernel (compact, soft, wyvill) on a
/// segment or polygon, in the primitive's frame (R·2^−e, 2^e ≤ the length or
/// diameter < 2^(e+1)): throws InputError at "kernel.R" unless it lies in
/// [min_support_in_frame, max_support_in_frame]. Outside, the evaluation
/// would print a wrong number rather than fail: a support 2^−48 of the
/// segment's length spans a few units in the last place of the parameter
/// t ∈ [0, 1] (the clipped chord, and so f, rounds to 0), and beyond 2^500
/// the squares of R the clipping and the closed forms form overflow (the
/// segment printed 0, the polygon 3e307, where f ≈ 1 and 0.5).
inline constexpr double min_support_in_frame = 0x1p-48;
inline constexpr double max_support_in_frame = 0x1p500;
void require_support_radius_in_frame(double R_in_frame, const char* unit);

/// A SCALIS radius τ_k ("radius[k]"): finite and >= 0.
void require_scalis_radius(double tau, int k);

/// The scale σ of a SCALIS kernel ("kernel.sigma"): finite, > 0, and > 1
/// for the compact family (its kernel vanishes at distance στ).
void require_scalis_sigma(KernelFamily family, double sigma);

/// The kernel's own parameters, as its trait checks them (s > 0 for cauchy
/// at "kernel.s", R > 0 at "kernel.R", …), finite. The degree is checked by
/// each primitive against its own table.
void require_valid_kernel_parameter(const KernelSpec& kernel);

/// `family` has a field on a `what` primitive ("segment", "polygon",
/// "scalis_segment", "scalis_triangle": its trait's `primitives` bits); else
/// throws InputError at "kernel.family" naming where the family is defined
/// and which families a `what` takes.
void require_convolution_family(KernelFamily family, std::string_view what);

}  // namespace skelconv::detail
