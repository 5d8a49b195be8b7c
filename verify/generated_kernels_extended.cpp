// verify/generated_kernels_extended.cpp — the binary128 instantiation of the
// generated templates for the verifier (see generated_kernels.hpp). Each
// family's table is instantiated in its own file,
// generated_kernels_extended_<family>.cpp, so that the three (the build's
// largest translation units) compile in parallel; generated_kernels.hpp
// declares them `extern`.
#include "generated_kernels.hpp"

namespace skelconv::verify {

std::span<const GeneratedKernel<extended>> generated_kernels_extended() { return all_segment_kernels<extended>(); }

const GeneratedKernel<extended>* find_generated_extended(KernelFamily family, int degree, int weight_degree) {
  return find_any_segment_kernel<extended>(family, degree, weight_degree);
}

}  // namespace skelconv::verify
