// bench/fast_forms.cpp — bench/fast_forms.hpp: the fast forms of the
// detailed kernels on double, instantiated once here.
#include "fast_forms.hpp"

#include "generated/segment_cauchy.hpp"
#include "generated/segment_compact.hpp"
#include "generated/segment_inverse.hpp"

namespace skelconv::bench {
namespace {

struct Entry {
  KernelKey key;
  FastForm form;
};

// The detailed kernels (bench_support.hpp) with a fast form: the even-degree
// compact kernels integrate by a Gauss rule on their generic path and have
// none (docs/filter.md).
const Entry entries[] = {
    {{KernelFamily::inverse, 3, 1},
     {&generated::segment_inverse_i3_w1_fast_f<double>, &generated::segment_inverse_i3_w1_fast_f_and_grad<double>}},
    {{KernelFamily::cauchy, 4, 1},
     {&generated::segment_cauchy_i4_w1_fast_f<double>, &generated::segment_cauchy_i4_w1_fast_f_and_grad<double>}},
    {{KernelFamily::cauchy, 4, 3},
     {&generated::segment_cauchy_i4_w3_fast_f<double>, &generated::segment_cauchy_i4_w3_fast_f_and_grad<double>}},
    {{KernelFamily::compact, 3, 0},
     {&generated::segment_compact_i3_w0_fast_f<double>, &generated::segment_compact_i3_w0_fast_f_and_grad<double>}},
};

}  // namespace

const FastForm* find_fast_form(const KernelKey& key) {
  for (const Entry& e : entries)
    if (e.key.family == key.family && e.key.degree == key.degree && e.key.weight_degree == key.weight_degree)
      return &e.form;
  return nullptr;
}

std::optional<FilterPaths> filter_paths(const KernelKey& key) {
  const FilteredSegmentKernel* k = FilteredSegmentKernel::find(key.family, key.degree, key.weight_degree);
  const KernelRef* ref = find_kernel(key.family, key.degree, key.weight_degree);
  const FastForm* fast = find_fast_form(key);
  if (!k || !k->has_fast_form() || !ref || !fast) return std::nullopt;
  return FilterPaths{k, ref, fast};
}

}  // namespace skelconv::bench
