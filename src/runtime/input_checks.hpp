// src/runtime/input_checks.hpp — checks and message formatting shared by the
// primitives' constructors (Segment, Polygon, ScalisSegment, ScalisTriangle) and
// Skeleton. Internal to
// skelconv_runtime: not an installed header.
//
// Each check throws InputError with the problem and, where the caller names
// one, the field ("kernel.R", "vertices[3]"); the JSON reader later prefixes
// the primitive's path.
#pragma once

#include <string>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernel_spec.hpp"

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

/// A kernel parameter in a primitive's frame (skelconv/scaled_frame.hpp),
/// e.g. s·|AB|² or R/|AB|: throws InputError at `where` unless it is a
/// normal double (the kernel is then too sharp or too wide for the
/// primitive's size to be evaluated in double precision).
void require_normal_in_frame(double value, const char* name, const char* where);

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
