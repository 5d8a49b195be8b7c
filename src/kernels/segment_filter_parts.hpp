// src/kernels/segment_filter_parts.hpp — how the filter's wrappers are split
// over translation units.
//
// Each kernel's two wrappers (segment_filter_part.cpp) are flattened: its
// fast form inlined into them on RelativeError<double>, so that the compiler
// folds the static part of the bound. That is most of the runtime's compile
// time, so the wrappers are compiled in kFilterParts translation units that
// build in parallel (src/CMakeLists.txt writes one source per part, each
// including segment_filter_part.cpp with its own SKELCONV_FILTER_PART). Part
// P holds the entries P, P + kFilterParts, P + 2 kFilterParts, … of
// generated::segment_fast_kernel_table: its order runs by family, degree and
// weight degree, and a kernel's cost grows with its degree, so every part
// gets a share of the cheap and of the costly ones.
#pragma once

#include <cstddef>
#include <span>

#include "skelconv/kernels/op_count.hpp"
#include "skelconv/primitives/segment_input.hpp"

#ifndef SKELCONV_FILTER_PARTS
#error "SKELCONV_FILTER_PARTS (the number of parts) is set by src/CMakeLists.txt"
#endif

namespace skelconv {

struct FastEvaluation;

/// One kernel's fast forms as evaluated by the filter (nullptr: none). ∇f
/// alone takes f_and_grad: one flattened wrapper fewer per kernel (compile
/// time), for a few more flops.
struct FastFormWrappers {
  void (*f)(const SegmentInput<double>&, FastEvaluation&);
  void (*f_and_grad)(const SegmentInput<double>&, FastEvaluation&);
  OpCount ops[3];  // f, ∇f, f+∇f: the generated table's counts
};

namespace detail {

inline constexpr std::size_t kFilterParts = SKELCONV_FILTER_PARTS;
static_assert(kFilterParts >= 1);

/// The wrappers of part `Part`: element j is entry Part + j·kFilterParts of
/// the generated table ({nullptr, nullptr, {}} where it has no fast form).
/// Defined and explicitly instantiated in that part's translation unit only.
template <std::size_t Part>
std::span<const FastFormWrappers> filter_wrappers_part();

}  // namespace detail
}  // namespace skelconv
