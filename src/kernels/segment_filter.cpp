// The filter of skelconv/kernels/segment_filter.hpp. Its wrappers of the fast
// forms (generated/segment_fast_table.hpp) on RelativeError<double> are
// compiled in parts (segment_filter_parts.hpp, segment_filter_part.cpp);
// this file gathers them.
#include "skelconv/kernels/segment_filter.hpp"

#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "segment_filter_parts.hpp"
#include "skelconv/kernels/segment_kernel_tables.hpp"

namespace skelconv {

namespace {

/// The table: each stable kernel of segment_kernels<double>() with its
/// wrappers, entry i in part i mod kFilterParts at i / kFilterParts
/// (segment_filter_parts.hpp). Only the parts include the fast forms
/// (generated/segment_fast_table.hpp, in the stable table's order): naming
/// that table here would compile every fast form once more, unflattened.
template <std::size_t... P>
std::vector<FilteredSegmentKernel> build_table(std::index_sequence<P...>) {
  const std::span<const FastFormWrappers> parts[] = {detail::filter_wrappers_part<P>()...};
  const auto stable = generated::segment_kernels<double>();
  if ((... + parts[P].size()) != stable.size())
    throw std::logic_error("segment_fast_table.hpp and segment_table.hpp list different kernels");
  std::vector<FilteredSegmentKernel> table;
  for (std::size_t i = 0; i < stable.size(); ++i) {
    const FastFormWrappers& w = parts[i % detail::kFilterParts][i / detail::kFilterParts];
    table.emplace_back(&stable[i], w.f ? &w : nullptr);
  }
  return table;
}

}  // namespace

const FilteredSegmentKernel* FilteredSegmentKernel::find(KernelFamily family, int degree, int weight_degree) {
  static const std::vector<FilteredSegmentKernel> table =
      build_table(std::make_index_sequence<detail::kFilterParts>{});
  for (const FilteredSegmentKernel& k : table)
    if (k.stable_->family == family && k.stable_->degree == degree && k.stable_->weight_degree == weight_degree)
      return &k;
  return nullptr;
}

bool FilteredSegmentKernel::evaluate_fast(const SegmentInput<double>& in, int which, FastEvaluation& out) const {
  if (!fast_) return false;
  out = {};
  if (which == 0) {
    fast_->f(in, out);
  } else {
    fast_->f_and_grad(in, out);
    if (which == 1) out.f = out.f_bound = 0;
  }
  return true;
}

OpCount FilteredSegmentKernel::fast_operation_count(int which) const { return fast_ ? fast_->ops[which] : OpCount{}; }

double FilteredSegmentKernel::stable_f(const SegmentInput<double>& in) const { return stable_->f(in); }

double FilteredSegmentKernel::stable_f_and_grad(const SegmentInput<double>& in, std::array<double, 3>& grad) const {
  return stable_->f_and_grad(in, grad);
}

double FilteredSegmentKernel::f(const SegmentInput<double>& in, double tolerance, bool* accepted) const {
  FastEvaluation e;
  const bool ok = evaluate_fast(in, 0, e) && filter_accepts(std::abs(e.f), e.f_bound, tolerance);
  if (accepted) *accepted = ok;
  return ok ? e.f : stable_->f(in);
}

std::array<double, 3> FilteredSegmentKernel::grad(const SegmentInput<double>& in, double tolerance,
                                                  bool* accepted) const {
  FastEvaluation e;
  const bool ok = evaluate_fast(in, 1, e) && filter_accepts_gradient(e.grad, e.grad_bounds, tolerance);
  if (accepted) *accepted = ok;
  return ok ? e.grad : stable_->grad(in);
}

double FilteredSegmentKernel::f_and_grad(const SegmentInput<double>& in, std::array<double, 3>& grad,
                                         double tolerance, bool* accepted) const {
  FastEvaluation e;
  const bool ok = evaluate_fast(in, 2, e) && filter_accepts(std::abs(e.f), e.f_bound, tolerance) &&
                  filter_accepts_gradient(e.grad, e.grad_bounds, tolerance);
  if (accepted) *accepted = ok;
  if (!ok) return stable_->f_and_grad(in, grad);
  grad = e.grad;
  return e.f;
}

}  // namespace skelconv
