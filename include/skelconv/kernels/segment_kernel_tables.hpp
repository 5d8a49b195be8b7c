// skelconv/kernels/segment_kernel_tables.hpp — the double-precision segment kernel
// tables, instantiated once, in the runtime library.
//
// generated/segment_table.hpp holds ~80,000 lines of templates; taking the
// address of every kernel in segment_<family>_kernels<double>() instantiates
// all of them, about 70 s of compiling. Including this header instead of
// generated/segment_table.hpp declares those instantiations `extern` (C++
// [temp.explicit]): the compiler parses the templates but instantiates
// nothing, and the linker takes the one instantiation of skelconv_runtime
// (src/kernels/segment_kernel_tables.cpp and, one family per translation unit
// so that they compile in parallel, segment_kernel_table_<family>.cpp). Other
// scalar types (long double, binary128) are still instantiated where they are
// used.
#pragma once

#include <span>

#include "generated/segment_table.hpp"
#include "skelconv/kernels/derived_segment_kernels.hpp"

namespace skelconv::generated {
extern template std::span<const SegmentKernel<double>> segment_inverse_kernels<double>();
extern template std::span<const SegmentKernel<double>> segment_cauchy_kernels<double>();
extern template std::span<const SegmentKernel<double>> segment_compact_kernels<double>();
extern template std::span<const SegmentKernel<double>> segment_kernels<double>();
}  // namespace skelconv::generated

namespace skelconv {
extern template std::span<const generated::SegmentKernel<double>> derived_segment_kernels<double>();
}  // namespace skelconv
