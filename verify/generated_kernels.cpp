// verify/generated_kernels.cpp — the double tables for the verifier: the
// generated code under test is the runtime's own instantiation
// (skelconv/kernels/segment_kernel_tables.hpp); the binary128 one is instantiated in
// generated_kernels_extended*.cpp.
#include "generated_kernels.hpp"

namespace skelconv::verify {

std::span<const GeneratedKernel<double>> generated_kernels_double() { return all_segment_kernels<double>(); }

const GeneratedKernel<double>* find_generated_double(KernelFamily family, int degree, int weight_degree) {
  return find_any_segment_kernel<double>(family, degree, weight_degree);
}

}  // namespace skelconv::verify
