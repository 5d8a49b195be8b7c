// verify/generated_kernels.hpp — the generated segment table in double and in
// binary128, instantiated once (generated_kernels.cpp): the generated headers
// are large, and every other verifier file reaches them through here.
#pragma once

#include <span>

#include "extended_precision.hpp"
#include "generated/segment_table.hpp"

namespace skelconv::verify {

template <class T>
using GeneratedKernel = generated::SegmentKernel<T>;

std::span<const GeneratedKernel<double>> generated_kernels_double();
std::span<const GeneratedKernel<extended>> generated_kernels_extended();

/// nullptr when (family, degree, weight degree) was not generated.
const GeneratedKernel<double>* find_generated_double(KernelFamily family, int degree, int weight_degree);
const GeneratedKernel<extended>* find_generated_extended(KernelFamily family, int degree, int weight_degree);

}  // namespace skelconv::verify
