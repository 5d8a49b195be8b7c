// skelconv/segment_kernel_tables.hpp — the double-precision segment kernel
// tables, instantiated once, in the runtime library.
//
// generated/segment_table.hpp holds ~55,000 lines of templates; taking the
// address of every kernel in segment_kernels<double>() instantiates all of
// them, about 40 s of compiling per translation unit. Including this header
// instead of generated/segment_table.hpp declares those two instantiations
// `extern` (C++ [temp.explicit]): the compiler parses the templates but
// instantiates nothing, and the linker takes the one instantiation of
// src/runtime/segment_kernel_tables.cpp (library skelconv_runtime). Other
// scalar types (long double, binary128) are still instantiated where they are
// used, as before.
#pragma once

#include <span>

#include "generated/segment_table.hpp"
#include "skelconv/derived_segment_kernels.hpp"

namespace skelconv::generated {
extern template std::span<const SegmentKernel<double>> segment_kernels<double>();
}  // namespace skelconv::generated

namespace skelconv {
extern template std::span<const generated::SegmentKernel<double>> derived_segment_kernels<double>();
}  // namespace skelconv
