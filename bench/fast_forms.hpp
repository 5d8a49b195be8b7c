// bench/fast_forms.hpp — the generated fast forms (<kernel>_fast_*) on
// plain double, for the detailed kernels that have one: what the filter's
// formula costs without its error bound (bench/filter_bench.cpp and the
// callgrind regions of bench/instruction_counts.cpp).
#pragma once

#include <array>
#include <optional>

#include "bench_support.hpp"

#include <skelconv/kernels/segment_filter.hpp>

namespace skelconv::bench {

struct FastForm {
  double (*f)(const Input&);
  double (*f_and_grad)(const Input&, Vec&);
};

/// nullptr where the kernel is not among detailed_kernels or has no fast form.
const FastForm* find_fast_form(const KernelKey& key);

/// The three paths the filter is compared on, for one detailed kernel: the
/// filter (its stable function is the fallback), the bench's table entry
/// (name), and the fast form alone; std::nullopt where one is missing.
struct FilterPaths {
  const FilteredSegmentKernel* filtered;
  const KernelRef* ref;
  const FastForm* fast;
};
std::optional<FilterPaths> filter_paths(const KernelKey& key);

}  // namespace skelconv::bench
