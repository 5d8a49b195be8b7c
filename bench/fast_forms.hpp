// bench/fast_forms.hpp — the generated fast forms (<kernel>_fast_*) on
// plain double, for the detailed kernels that have one: what the filter's
// formula costs without its error bound (bench/filter_bench.cpp and the
// callgrind regions of bench/instruction_counts.cpp).
#pragma once

#include <array>

#include "bench_support.hpp"

namespace skelconv::bench {

struct FastForm {
  double (*f)(const Input&);
  double (*f_and_grad)(const Input&, Vec&);
};

/// nullptr where the kernel is not among detailed_kernels or has no fast form.
const FastForm* find_fast_form(const KernelKey& key);

}  // namespace skelconv::bench
