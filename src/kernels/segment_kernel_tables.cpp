// The one instantiation of the double-precision segment kernel tables
// (skelconv/kernels/segment_kernel_tables.hpp says why).
#include "skelconv/kernels/segment_kernel_tables.hpp"

namespace skelconv::generated {
template std::span<const SegmentKernel<double>> segment_kernels<double>();
}  // namespace skelconv::generated

namespace skelconv {
template std::span<const generated::SegmentKernel<double>> derived_segment_kernels<double>();
}  // namespace skelconv
