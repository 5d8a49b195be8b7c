// verify/generated_kernels.cpp — the double instantiation of the generated
// templates for the verifier (see generated_kernels.hpp); the binary128 one is
// in generated_kernels_extended.cpp, so the two compile in parallel.
#include "generated_kernels.hpp"

namespace skelconv::verify {

std::span<const GeneratedKernel<double>> generated_kernels_double() { return all_segment_kernels<double>(); }

const GeneratedKernel<double>* find_generated_double(KernelFamily family, int degree, int weight_degree) {
  return find_any_segment_kernel<double>(family, degree, weight_degree);
}

}  // namespace skelconv::verify
