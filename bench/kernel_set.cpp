// bench/kernel_set.cpp — the generated kernel table as plain function
// pointers. The only bench translation unit that includes
// generated/segment_table.hpp.
#include "bench_support.hpp"

#include "skelconv/kernels/segment_kernel_tables.hpp"  // instantiated once, in skelconv_runtime

namespace skelconv::bench {

const std::vector<KernelRef>& generated_kernels() {
  static const std::vector<KernelRef> kernels = [] {
    std::vector<KernelRef> out;
    for (const auto& k : generated::segment_kernels<double>()) {
      out.push_back(KernelRef{k.family, k.degree, k.weight_degree, k.f, k.grad, k.f_and_grad, k.name,
                              k.ops_f, k.ops_grad, k.ops_f_and_grad, k.ops_prepare, k.prepared_size,
                              k.prepare, k.f_at, k.grad_at, k.f_and_grad_at});
    }
    return out;
  }();
  return kernels;
}

const KernelRef* find_kernel(KernelFamily family, int degree, int weight_degree) {
  for (const KernelRef& k : generated_kernels())
    if (k.family == family && k.degree == degree && k.weight_degree == weight_degree) return &k;
  return nullptr;
}

}  // namespace skelconv::bench
