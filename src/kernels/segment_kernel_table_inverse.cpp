// The one double-precision instantiation of the inverse family's segment
// kernels (skelconv/kernels/segment_kernel_tables.hpp says why it has its own file).
#include "generated/segment_inverse.hpp"  // the formulas, instantiated here
#include "skelconv/kernels/segment_kernel_tables.hpp"

namespace skelconv::generated {
template std::span<const SegmentKernel<double>> segment_inverse_kernels<double>();
}  // namespace skelconv::generated
