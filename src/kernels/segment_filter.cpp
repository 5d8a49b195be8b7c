// The filter of skelconv/kernels/segment_filter.hpp, and the one translation
// unit that instantiates the fast forms (generated/segment_fast_table.hpp) on
// RelativeError<double> (skelconv/kernels/relative_error.hpp).
#include "skelconv/kernels/segment_filter.hpp"

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#else
#include <cfenv>
#endif

#include "generated/segment_fast_table.hpp"
#include "skelconv/kernels/segment_kernel_tables.hpp"

namespace skelconv {

/// One kernel's fast forms as evaluated by the filter (nullptr: none). ∇f
/// alone takes f_and_grad: one flattened wrapper fewer per kernel (this
/// translation unit's compile time), for a few more flops.
struct FastFormWrappers {
  void (*f)(const SegmentInput<double>&, FastEvaluation&);
  void (*f_and_grad)(const SegmentInput<double>&, FastEvaluation&);
  OpCount ops[3];  // f, ∇f, f+∇f: the generated table's counts
};

namespace {

using generated::FastScalar;
using generated::segment_fast_kernel_table;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// RelativeError's model, fl(x ∘ y) = (x ∘ y)(1 + δ), holds in round-to-
// nearest, without flush-to-zero, as long as no operation underflows,
// overflows, divides by zero or is invalid. The scope evaluates with every
// exception masked and those flags clear, says whether they stayed clear,
// and leaves the caller's state (flags included) as it found it.
#if defined(__SSE2__)
class FloatingPointScope {
 public:
  // MXCSR (Intel SDM vol. 1 §10.2.3): flags IE 0x1, ZE 0x4, OE 0x8, UE 0x10,
  // PE 0x20 (DE 0x2: a denormal operand, exact, not a failure); masks
  // 0x1F80; rounding control 0x6000; flush-to-zero 0x8000; DAZ 0x40.
  static constexpr unsigned kFlags = 0x3F, kFailures = 0x1D, kMasks = 0x1F80, kModes = 0x6000 | 0x8000 | 0x40;
  // Writing MXCSR (ldmxcsr) is a slow, partly serialising instruction;
  // reading it is cheap. In the usual state (exceptions masked, default
  // modes, no failure flag raised) nothing is written: a failure flag found
  // after the evaluation was raised by it, and only then is the caller's
  // register restored. Otherwise the flags are cleared first and the
  // register restored at the end.
  FloatingPointScope() : saved_(_mm_getcsr()) {
    usual_ = (saved_ & (kFailures | kModes)) == 0 && (saved_ & kMasks) == kMasks;
    if (!usual_) _mm_setcsr((saved_ | kMasks) & ~kFlags);
  }
  ~FloatingPointScope() {
    if (!usual_ || (_mm_getcsr() & kFailures) != 0) _mm_setcsr(saved_);
  }
  FloatingPointScope(const FloatingPointScope&) = delete;
  FloatingPointScope& operator=(const FloatingPointScope&) = delete;
  bool model_held() const { return (saved_ & kModes) == 0 && (_mm_getcsr() & kFailures) == 0; }

 private:
  unsigned saved_;
  bool usual_;
};
#else
class FloatingPointScope {
 public:
  FloatingPointScope() { std::feholdexcept(&saved_); }
  ~FloatingPointScope() { std::fesetenv(&saved_); }
  FloatingPointScope(const FloatingPointScope&) = delete;
  FloatingPointScope& operator=(const FloatingPointScope&) = delete;
  bool model_held() const {
    return std::fegetround() == FE_TONEAREST &&
           std::fetestexcept(FE_UNDERFLOW | FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID) == 0;
  }

 private:
  std::fenv_t saved_;
};
#endif

// Compiler barriers: the evaluation reads its inputs after the scope cleared
// the flags, and has written its results before the scope reads them.
template <class X>
void after_flags_cleared(X& x) {
  asm volatile("" : "+m"(x));
}
template <class X>
void before_flags_read(const X& x) {
  asm volatile("" : : "m"(x));
}

SegmentInput<FastScalar> exact_input(const SegmentInput<double>& in) {
  SegmentInput<FastScalar> x;
  for (int i = 0; i < 3; ++i) {
    x.a[i] = in.a[i];
    x.b[i] = in.b[i];
    x.p[i] = in.p[i];
  }
  for (size_t k = 0; k < in.w.size(); ++k) x.w[k] = in.w[k];
  // Positive by the contract of SegmentInput (checked by inputs_in_contract):
  // sums with them keep static relative bounds (relative_error.hpp).
  x.s = FastScalar::nonnegative_input(in.s);
  x.R = FastScalar::nonnegative_input(in.R);
  x.gaussian_a = FastScalar::nonnegative_input(in.gaussian_a);
  x.gaussian_b = FastScalar::nonnegative_input(in.gaussian_b);
  x.t0 = FastScalar::nonnegative_input(in.t0);
  x.t1 = FastScalar::nonnegative_input(in.t1);
  return x;
}

/// Whether the parameters exact_input takes as nonnegative are (else the
/// bound is discarded).
bool inputs_in_contract(const SegmentInput<double>& in) {
  return in.s >= 0 && in.R >= 0 && in.gaussian_a >= 0 && in.gaussian_b >= 0 && in.t0 >= 0 && in.t1 >= 0;
}

void store_gradient(const std::array<FastScalar, 3>& g, FastEvaluation& out) {
  for (int i = 0; i < 3; ++i) {
    out.grad[i] = g[i].value;
    out.grad_bounds[i] = g[i].bound();
  }
}

// The wrappers of entry I of the generated table. Flattened: the fast form
// is inlined into its wrapper, where the compiler sees that the inputs are
// exact and folds the static part of the bound (relative_error.hpp).
template <std::size_t I>
[[gnu::flatten]] void fast_f(const SegmentInput<double>& input, FastEvaluation& out) {
  FloatingPointScope scope;
  SegmentInput<double> in = input;
  after_flags_cleared(in);
  const FastScalar f = segment_fast_kernel_table[I].f(exact_input(in));
  out.f = f.value;
  out.f_bound = f.bound();
  before_flags_read(out);
  if (!scope.model_held() || !inputs_in_contract(in)) out.f_bound = kInfinity;
}

template <std::size_t I>
[[gnu::flatten]] void fast_f_and_grad(const SegmentInput<double>& input, FastEvaluation& out) {
  FloatingPointScope scope;
  SegmentInput<double> in = input;
  after_flags_cleared(in);
  std::array<FastScalar, 3> g;
  const FastScalar f = segment_fast_kernel_table[I].f_and_grad(exact_input(in), g);
  out.f = f.value;
  out.f_bound = f.bound();
  store_gradient(g, out);
  before_flags_read(out);
  if (!scope.model_held() || !inputs_in_contract(in)) {
    out.f_bound = kInfinity;
    out.grad_bounds.fill(kInfinity);
  }
}

// Whether entry I has fast forms, read from its operation count rather than
// from `f == nullptr`: with -fsanitize GCC does not accept comparing a
// function's address with nullptr in a constant expression. The generator
// writes an empty count exactly where it writes no fast form; build_table
// checks that the two agree.
template <std::size_t I>
constexpr bool has_fast_form() {
  return segment_fast_kernel_table[I].ops_f.total() > 0;
}

template <std::size_t I>
constexpr FastFormWrappers wrappers_of() {
  if constexpr (!has_fast_form<I>()) return {nullptr, nullptr, {}};
  else {
    const auto& e = segment_fast_kernel_table[I];
    return {&fast_f<I>, &fast_f_and_grad<I>, {e.ops_f, e.ops_grad, e.ops_f_and_grad}};
  }
}

template <std::size_t... I>
constexpr std::array<FastFormWrappers, sizeof...(I)> all_wrappers(std::index_sequence<I...>) {
  return {wrappers_of<I>()...};
}

constexpr std::size_t kKernels = std::size(segment_fast_kernel_table);
constexpr std::array<FastFormWrappers, kKernels> kWrappers = all_wrappers(std::make_index_sequence<kKernels>{});

std::vector<FilteredSegmentKernel> build_table() {
  const auto stable = generated::segment_kernels<double>();
  std::vector<FilteredSegmentKernel> table;
  for (size_t i = 0; i < stable.size(); ++i) {
    if (i < kKernels && (kWrappers[i].f != nullptr) != (segment_fast_kernel_table[i].f != nullptr))
      throw std::logic_error("segment_fast_table.hpp: an entry's operation count and fast form disagree");
    table.emplace_back(&stable[i], i < kKernels && kWrappers[i].f ? &kWrappers[i] : nullptr);
  }
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
