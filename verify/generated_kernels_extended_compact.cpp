// The binary128 instantiation of the compact family's generated segment kernels
// (generated_kernels_extended.cpp says why it has its own file).
#include "generated/segment_compact.hpp"  // the formulas, instantiated here
#include "generated_kernels.hpp"

namespace skelconv::generated {
template std::span<const SegmentKernel<verify::extended>> segment_compact_kernels<verify::extended>();
}  // namespace skelconv::generated
