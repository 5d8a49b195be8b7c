// verify/generated_kernels.hpp — the generated segment table in double and in
// binary128, instantiated once (generated_kernels.cpp): the generated headers
// are large, and every other verifier file reaches them through here.
#pragma once

#include <span>
#include <vector>

#include "extended_precision.hpp"
#include "skelconv/kernels/segment_kernel_tables.hpp"  // the double tables: instantiated in skelconv_runtime

// The binary128 tables are instantiated once, one family per file
// (generated_kernels_extended_<family>.cpp, compiled in parallel): `extern`
// here keeps every other verifier file from instantiating them again.
namespace skelconv::generated {
extern template std::span<const SegmentKernel<verify::extended>> segment_inverse_kernels<verify::extended>();
extern template std::span<const SegmentKernel<verify::extended>> segment_cauchy_kernels<verify::extended>();
extern template std::span<const SegmentKernel<verify::extended>> segment_compact_kernels<verify::extended>();
}  // namespace skelconv::generated

namespace skelconv::verify {

template <class T>
using GeneratedKernel = generated::SegmentKernel<T>;

/// The generated table followed by the derived kernels (soft, wyvill,
/// gaussian: skelconv/kernels/derived_segment_kernels.hpp), built once.
template <class T>
std::span<const GeneratedKernel<T>> all_segment_kernels() {
  static const std::vector<GeneratedKernel<T>> table = [] {
    std::vector<GeneratedKernel<T>> out(generated::segment_kernels<T>().begin(), generated::segment_kernels<T>().end());
    out.insert(out.end(), derived_segment_kernels<T>().begin(), derived_segment_kernels<T>().end());
    return out;
  }();
  return table;
}

std::span<const GeneratedKernel<double>> generated_kernels_double();
std::span<const GeneratedKernel<extended>> generated_kernels_extended();

/// nullptr when (family, degree, weight degree) was not generated (nor derived).
const GeneratedKernel<double>* find_generated_double(KernelFamily family, int degree, int weight_degree);
const GeneratedKernel<extended>* find_generated_extended(KernelFamily family, int degree, int weight_degree);

}  // namespace skelconv::verify
