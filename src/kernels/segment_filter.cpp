// The filter of skelconv/kernels/segment_filter.hpp, and the one translation
// unit that instantiates the fast forms (generated/segment_fast_table.hpp) on
// RunningError<double>.
#include "skelconv/kernels/segment_filter.hpp"

#include <cmath>
#include <vector>

#include "generated/segment_fast_table.hpp"
#include "skelconv/kernels/segment_kernel_tables.hpp"

namespace skelconv {

namespace {

using generated::FastScalar;

SegmentInput<FastScalar> exact_input(const SegmentInput<double>& in) {
  SegmentInput<FastScalar> x;
  for (int i = 0; i < 3; ++i) {
    x.a[i] = in.a[i];
    x.b[i] = in.b[i];
    x.p[i] = in.p[i];
  }
  for (size_t k = 0; k < in.w.size(); ++k) x.w[k] = in.w[k];
  x.s = in.s;
  x.R = in.R;
  x.gaussian_a = in.gaussian_a;
  x.gaussian_b = in.gaussian_b;
  x.t0 = in.t0;
  x.t1 = in.t1;
  return x;
}

// The gradient's bound: the sum of its components' bounds, ≥ the Euclidean
// norm of the error vector (|e|₂ ≤ |e|₁), without a square root. Rounding
// of the two additions: relative 2u, inside the bounds' own kBoundSafety.
void store_gradient(const std::array<FastScalar, 3>& g, FastEvaluation& out) {
  for (int i = 0; i < 3; ++i) out.grad[i] = g[i].value;
  out.grad_bound = g[0].bound() + g[1].bound() + g[2].bound();
}

std::vector<FilteredSegmentKernel> build_table() {
  const auto stable = generated::segment_kernels<double>();
  const auto fast = generated::segment_fast_kernels();
  std::vector<FilteredSegmentKernel> table;
  for (size_t i = 0; i < stable.size(); ++i) table.emplace_back(&stable[i], fast[i].f ? &fast[i] : nullptr);
  return table;
}

}  // namespace

const FilteredSegmentKernel* FilteredSegmentKernel::find(KernelFamily family, int degree, int weight_degree) {
  static const std::vector<FilteredSegmentKernel> table = build_table();
  for (const FilteredSegmentKernel& k : table)
    if (k.stable_->family == family && k.stable_->degree == degree && k.stable_->weight_degree == weight_degree)
      return &k;
  return nullptr;
}

bool FilteredSegmentKernel::evaluate_fast(const SegmentInput<double>& in, int which, FastEvaluation& out) const {
  if (!fast_) return false;
  const SegmentInput<FastScalar> x = exact_input(in);
  out = {};
  if (which == 0) {
    const FastScalar f = fast_->f(x);
    out.f = f.value;
    out.f_bound = f.bound();
  } else if (which == 1) {
    store_gradient(fast_->grad(x), out);
  } else {
    std::array<FastScalar, 3> g;
    const FastScalar f = fast_->f_and_grad(x, g);
    out.f = f.value;
    out.f_bound = f.bound();
    store_gradient(g, out);
  }
  return true;
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
  const bool ok = evaluate_fast(in, 1, e) && filter_accepts_gradient(e.grad, e.grad_bound, tolerance);
  if (accepted) *accepted = ok;
  return ok ? e.grad : stable_->grad(in);
}

double FilteredSegmentKernel::f_and_grad(const SegmentInput<double>& in, std::array<double, 3>& grad,
                                         double tolerance, bool* accepted) const {
  FastEvaluation e;
  const bool ok = evaluate_fast(in, 2, e) && filter_accepts(std::abs(e.f), e.f_bound, tolerance) &&
                  filter_accepts_gradient(e.grad, e.grad_bound, tolerance);
  if (accepted) *accepted = ok;
  if (!ok) return stable_->f_and_grad(in, grad);
  grad = e.grad;
  return e.f;
}

}  // namespace skelconv
