// skelconv/primitives/generic.hpp — opt-in: a segment primitive's closed form evaluated
// in another scalar type (docs/api.md, "Other scalar types").
//
// The generated kernels (generated/segment_*.hpp, docs/generated_api.md) are
// templates on the scalar type T: float, double, long double,
// Boost.Multiprecision's cpp_bin_float_50 and float128 all compile (tests/
// scalar_types_test.cpp, verify/). This header gives them a Segment's
// parameters: segment_input() fills the generated code's SegmentInput<T>
// (with the clip of a compact kernel's support), and
// segment_value_and_gradient() looks the kernel up in the table of every
// generated segment kernel.
//
// Cost: the table instantiates every generated segment function for T (tens
// of thousands of lines; minutes to compile for long double or
// Boost.Multiprecision), so include this header in one translation unit. To
// compile only one kernel, call it by name instead, e.g.
// generated::segment_cauchy_i4_w0_prepare<T>(input, pre), then
// generated::segment_cauchy_i4_w0_f_and_grad<T>(pre, point_of(input), gradient)
// from generated/segment_cauchy.hpp (docs/generated_api.md).
//
// Unlike Segment (double), nothing here checks the result: a point on an
// inverse-kernel segment gives inf or NaN, and lower precisions overflow
// sooner (float: |P − A|^(−i) beyond ~1e38).
#pragma once

#include <array>
#include <optional>
#include <string>

// The formulas of every family, for the table of segment_value_and_gradient<T>
// and for calls of one kernel by name.
#include "generated/segment_cauchy.hpp"
#include "generated/segment_compact.hpp"
#include "generated/segment_inverse.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/detail/clip.hpp"
#include "skelconv/kernels/read_trait.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv {

/// The generated code's input for `segment` at P, in T; std::nullopt when P
/// is outside a compact kernel's support, where f = 0 and ∇f = 0.
template <class T>
std::optional<SegmentInput<T>> segment_input(const Segment& segment, const std::array<T, 3>& p) {
  SegmentInput<T> input;
  for (int c = 0; c < 3; ++c) {
    input.a[c] = T(segment.a()[c]);
    input.b[c] = T(segment.b()[c]);
  }
  input.p = p;
  const std::span<const double> w = segment.weight();
  for (std::size_t k = 0; k < input.w.size(); ++k) input.w[k] = k < w.size() ? T(w[k]) : T(0);
  input.s = T(segment.kernel().s);
  input.R = T(segment.kernel().R);
  if (kernels::has_finite_support(segment.kernel().family)) {  // clipped to the support ball
    const std::optional<ParameterInterval<T>> inside = clip_to_ball(input.a, input.b, input.p, input.R);
    if (!inside) return std::nullopt;
    input.t0 = inside->t0;
    input.t1 = inside->t1;
  }
  return input;
}

/// f(P) of `segment` computed in T, and ∇f(P) in `gradient`, by the same
/// generated closed form Segment uses in double.
template <class T>
T segment_value_and_gradient(const Segment& segment, const std::array<T, 3>& p, std::array<T, 3>& gradient) {
  const std::optional<SegmentInput<T>> input = segment_input(segment, p);
  if (!input) {
    gradient = {T(0), T(0), T(0)};
    return T(0);
  }
  const KernelSpec& kernel = segment.kernel();
  const auto* generated = generated::find_segment_kernel<T>(kernel.family, kernel.degree, segment.weight_degree());
  // Soft, Wyvill and Gaussian segments are not in the generated table (the
  // double API builds them from compact levels or a hand-written closed
  // form, docs/field.md): say so rather than call through a null entry.
  if (generated == nullptr) {
    throw InputError(std::string("no generated closed form for a ") + std::string(family_name(kernel.family)) +
                     " segment of degree " + std::to_string(kernel.degree) + " with weight degree " +
                     std::to_string(segment.weight_degree()) +
                     ": segment_value_and_gradient<T> covers the generated segment kernels only");
  }
  return generated->f_and_grad(*input, gradient);
}

}  // namespace skelconv
