// Part SKELCONV_FILTER_PART of the filter's wrappers (segment_filter_parts.hpp
// says how they are split): the fast forms of generated/segment_fast_table.hpp
// on RelativeError<double> (skelconv/kernels/relative_error.hpp), each
// inlined into the wrappers that evaluate it under a floating-point scope.
// Not compiled by itself: src/CMakeLists.txt writes one source per part
// that defines SKELCONV_FILTER_PART and includes this file.
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

#if defined(__SSE2__)
#include <xmmintrin.h>
#else
#include <cfenv>
#endif

#include "generated/segment_fast_table.hpp"
#include "segment_filter_parts.hpp"
#include "skelconv/kernels/segment_filter.hpp"

#ifndef SKELCONV_FILTER_PART
#error "SKELCONV_FILTER_PART (this part's number) is set by the source src/CMakeLists.txt writes"
#endif

namespace skelconv {

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

// Entries Part, Part + kFilterParts, … (the table's size is past the last).
template <std::size_t Part, std::size_t... J>
constexpr std::array<FastFormWrappers, sizeof...(J)> strided_wrappers(std::index_sequence<J...>) {
  return {wrappers_of<Part + J * detail::kFilterParts>()...};
}

constexpr std::size_t kKernels = std::size(segment_fast_kernel_table);

// Whether has_fast_form agrees with the table's pointers for entries Part,
// Part + kFilterParts, … (checked when the table is built: with -fsanitize
// GCC does not fold the pointer comparison in a constant expression).
template <std::size_t Part, std::size_t... J>
bool counts_agree_with_pointers(std::index_sequence<J...>) {
  return (... && (has_fast_form<Part + J * detail::kFilterParts>() ==
                  (segment_fast_kernel_table[Part + J * detail::kFilterParts].f != nullptr)));
}

}  // namespace

template <std::size_t Part>
std::span<const FastFormWrappers> detail::filter_wrappers_part() {
  static_assert(Part < kFilterParts);
  constexpr std::size_t count = (kKernels - Part + kFilterParts - 1) / kFilterParts;
  static constexpr std::array<FastFormWrappers, count> wrappers =
      strided_wrappers<Part>(std::make_index_sequence<count>{});
  if (!counts_agree_with_pointers<Part>(std::make_index_sequence<count>{}))
    throw std::logic_error("segment_fast_table.hpp: an entry's operation count and fast form disagree");
  return wrappers;
}

template std::span<const FastFormWrappers> detail::filter_wrappers_part<SKELCONV_FILTER_PART>();

}  // namespace skelconv
