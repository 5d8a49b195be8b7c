// skelconv/kernels/relative_error.hpp — a double that carries a bound on its
// own rounding error, for the filter of skelconv/kernels/segment_filter.hpp:
// forward error analysis (Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., §3.1–3.4) whose static part the compiler folds.
//
// The generated fast forms (generated/segment_*.hpp, `<kernel>_fast_*`) are
// templates on the scalar type. On RelativeError<double> every quantity of
// their expression graph carries, beside its computed value x̂, a bound on
// |x̂ − x|, where x is the same expression evaluated in real arithmetic on
// the (exact) double inputs, held in the form its producer makes cheap:
//
//   relative, ρ:  |x̂ − x| ≤ ρ u |x̂|   (products, quotients, roots, libm calls)
//   absolute, A:  |x̂ − x| ≤ A u        (sums: A = ρ|x̂| summed, no division)
//
// with u = 2^−53. Inputs and literals are `exact`; `exact` and the form are
// known at compile time, so that along the straight-line code the compiler
// folds every bound that does not depend on the data: the rounding counts of
// the expression graph, a static filter's constants. What is left at run
// time is the dynamic part: at each sum the operands' absolute errors
// (A_x + A_y + |r̂|: the sum's condition number times its relative error),
// carried through the products of a sum's result, and at each quotient or
// root of one the division A/|x̂| that turns the cancellation into a
// relative error. The filter's wrappers are flattened
// (src/kernels/segment_filter.cpp) so that the folding sees the exact
// inputs.
//
// The rules, with fl(x ∘ y) = (x ∘ y)(1 + δ), |δ| ≤ u, ε = ρu, and the factors
// 1/(1 − u) of passing from exact to computed results left to kBoundSafety:
//
//   x ± y   A = A_x + A_y + |r̂|                  (ρ = 1 if both exact)
//   x + y   ρ = max(ρ_x, ρ_y) + 1  where both are known ≥ 0 and relative
//           (|x̂ − x| + |ŷ − y| ≤ max(ε_x, ε_y)(|x̂| + |ŷ|) = max(ε)|x̂ + ŷ|:
//           a sum of squares cannot cancel, and its bound stays static)
//   x · y   ρ = ρ_x + ρ_y + ρ_x ρ_y u + 1          (|x̂ŷ − xy| ≤ |x̂ŷ|(ε_x + ε_y + ε_x ε_y)),
//           or, where an operand is a sum's result,
//           A = |x̂| A_y + |ŷ| A_x + A_x A_y u + |r̂| (x̂ŷ − xy = x̂ d_y + ŷ d_x − d_x d_y)
//   x / y   ρ = (ρ_x + ρ_y)(1 + 2 ρ_y u) + 1        (ρ_y u ≤ 1/2: 1/(1 − ε) ≤ 1 + 2ε)
//   √x      ρ = 0.586 ρ_x + 1   (ρ_x u ≤ 1/2: |√(1+θ) − 1| ≤ |θ|/(1 + √(1/2)))
//   log x   ρ = 2 ρ_x / |r̂| + L   (ρ_x u ≤ 1/2: |log(1+θ)| ≤ 2|θ|)
//   asinh x ρ = A_x / |r̂| + L      (|asinh'| ≤ 1)
//   atan2   ρ = (π/2)(A_x + A_y)/(h − (A_x + A_y)u)/|r̂| + L, h = max(|x̂|, |ŷ|),
//           ∞ within the error of the branch cut
//   min, max: A = max(A_x, A_y)                     (1-Lipschitz)
//
// with L = 4 the libm's error in units of u (glibc documents at most 1–2 ulp
// for log, atan2 and asinh on x86-64, and 1 ulp ≤ 2u|r|); outside the stated
// ranges the bound is ∞, and a NaN bound (∞ · 0) is never taken for a small
// one. The model fl(x ∘ y) = (x ∘ y)(1 + δ) fails on underflow, overflow,
// division by zero and invalid operations: the caller evaluates with the
// floating-point exception flags cleared and discards the bound where one of
// those is raised, in round-to-nearest without flush-to-zero
// (src/kernels/segment_filter.cpp). The rounding of the bound's own
// arithmetic (relative, about u per operation) and the dropped 1/(1 − u)
// factors are covered by `kBoundSafety` (bound()). verify/filter_check.cpp
// checks the bound against binary128 references.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace skelconv {

template <class T>
struct RelativeError {
  T value{};
  /// The bound in units of u: relative to |value| (ρ), or absolute (A = ρ|x̂|)
  /// where `absolute_form` (results of sums, see the top).
  T err{};
  bool exact = true;           ///< an input or a literal: no error, known at compile time
  bool absolute_form = false;  ///< err is A rather than ρ, known at compile time
  /// Both the computed and the exact value are ≥ 0, known at compile time:
  /// squares, sqrt, and sums, products and quotients of such (sums of
  /// squares: the dot products of the generated code).
  bool nonneg = false;

  RelativeError() = default;
  // NOLINTNEXTLINE(google-explicit-constructor): literals and inputs are exact
  RelativeError(T v) : value(v) {}
  // Literals like T(7) in the generated code: exact small integers.
  explicit RelativeError(int v) : value(T(v)), nonneg(v >= 0) {}

  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T kLibm = 4;  // libm error bound, units of u (see above)
  static constexpr T inf = std::numeric_limits<T>::infinity();

  /// An input known to be ≥ 0 (the caller checks it: a kernel parameter
  /// such as s or R, a clipped parameter t0, t1).
  static RelativeError nonnegative_input(T v) { return {v, T(0), true, false, true}; }
  static RelativeError relative(T v, T rho, bool nonneg = false) { return {v, rho, false, false, nonneg}; }
  static RelativeError absolute(T v, T a, bool nonneg = false) { return {v, a, false, true, nonneg}; }

  /// ρ (a division where the bound is held in absolute form).
  static T rho_of(const RelativeError& x) {
    return x.exact ? T(0) : (x.absolute_form ? x.err / std::abs(x.value) : x.err);
  }
  /// A = ρ|x̂| (NaN where ρ = ∞ and x̂ = 0: every rule then gives an
  /// unbounded result).
  static T abs_of(const RelativeError& x) {
    return x.exact ? T(0) : (x.absolute_form ? x.err : x.err * std::abs(x.value));
  }
  /// The larger of two bounds; ∞ if either is NaN (never a NaN dropped).
  static T worst(T a, T b) { return a >= b ? a : (b >= a ? b : inf); }

  RelativeError operator-() const {
    RelativeError r = *this;
    r.value = -value;
    r.nonneg = false;
    return r;
  }
  RelativeError& operator+=(const RelativeError& y) { return *this = *this + y; }
  RelativeError& operator-=(const RelativeError& y) { return *this = *this - y; }
  RelativeError& operator*=(const RelativeError& y) { return *this = *this * y; }
  RelativeError& operator/=(const RelativeError& y) { return *this = *this / y; }

  static RelativeError sum(T r, const RelativeError& x, const RelativeError& y) {
    if (x.exact && y.exact) return relative(r, T(1));  // one rounding
    return absolute(r, abs_of(x) + abs_of(y) + std::abs(r));
  }
  friend RelativeError operator+(const RelativeError& x, const RelativeError& y) {
    const T r = x.value + y.value;
    if (x.nonneg && y.nonneg && !x.absolute_form && !y.absolute_form && !(x.exact && y.exact))
      return relative(r, worst(rho_of(x), rho_of(y)) + 1, true);  // no cancellation (see the top)
    RelativeError s = sum(r, x, y);
    s.nonneg = x.nonneg && y.nonneg;
    return s;
  }
  friend RelativeError operator-(const RelativeError& x, const RelativeError& y) { return sum(x.value - y.value, x, y); }
  friend RelativeError operator*(const RelativeError& x, const RelativeError& y) {
    const T r = x.value * y.value;
    // x · x is a square; otherwise the signs multiply.
    const bool nonneg = &x == &y || (x.nonneg && y.nonneg);
    if (x.absolute_form || y.absolute_form) {
      // A sum's result: stay absolute rather than divide (see the top).
      const T ax = abs_of(x), ay = abs_of(y);
      const T second_order = x.exact || y.exact ? T(0) : ax * ay * u;
      return absolute(r, std::abs(x.value) * ay + std::abs(y.value) * ax + second_order + std::abs(r), nonneg);
    }
    const T rx = rho_of(x), ry = rho_of(y);
    const T second_order = x.exact || y.exact ? T(0) : rx * ry * u;
    return relative(r, rx + ry + second_order + 1, nonneg);
  }
  friend RelativeError operator/(const RelativeError& x, const RelativeError& y) {
    const T r = x.value / y.value;
    const bool nonneg = x.nonneg && y.nonneg;
    if (y.exact) return relative(r, rho_of(x) + 1, nonneg);
    // A_y/|ŷ| = A_y |q̂|/|x̂| up to a rounding (kBoundSafety): for a literal
    // numerator (1/y, the generated code's reciprocals) a product.
    const T ry = x.exact && y.absolute_form ? y.err * std::abs(r) / std::abs(x.value) : rho_of(y);
    if (!(ry * u <= T(0.5))) return relative(r, inf, nonneg);
    return relative(r, (rho_of(x) + ry) * (1 + 2 * ry * u) + 1, nonneg);
  }
  friend RelativeError sqrt(const RelativeError& x) {
    const T r = std::sqrt(x.value);
    if (x.exact) return relative(r, T(1), true);
    const T rx = rho_of(x);
    return relative(r, rx * u <= T(0.5) ? T(0.586) * rx + 1 : inf, true);
  }
  friend RelativeError log(const RelativeError& x) {
    const T r = std::log(x.value);
    if (x.exact) return relative(r, kLibm);
    const T rx = rho_of(x);
    if (!(rx * u <= T(0.5))) return relative(r, inf);
    return relative(r, 2 * rx / std::abs(r) + kLibm);
  }
  friend RelativeError asinh(const RelativeError& x) {
    const T r = std::asinh(x.value);
    if (x.exact) return relative(r, kLibm);
    return relative(r, abs_of(x) / std::abs(r) + kLibm);
  }
  friend RelativeError atan2(const RelativeError& y, const RelativeError& x) {
    const T r = std::atan2(y.value, x.value);
    if (x.exact && y.exact) return relative(r, kLibm);
    // max(|x̂|, |ŷ|) ≤ hypot(x̂, ŷ): a lower bound of the radius, no libm call.
    const T radius = std::max(std::abs(x.value), std::abs(y.value));
    const T propagated = abs_of(x) + abs_of(y);
    const T shift = propagated * u;
    // Within `shift` of the cut (negative x axis) the angle may jump by 2π.
    if (!(shift < radius) || (x.value < 0 && !(std::abs(y.value) > abs_of(y) * u))) return relative(r, inf);
    return relative(r, T(1.5707963267948968) * propagated / (radius - shift) / std::abs(r) + kLibm);
  }
  static RelativeError select(const RelativeError& pick, const RelativeError& x, const RelativeError& y) {
    if (x.exact && y.exact) return pick;
    return absolute(pick.value, worst(abs_of(x), abs_of(y)));
  }
  friend RelativeError max(const RelativeError& x, const RelativeError& y) {
    return select(x.value >= y.value ? x : y, x, y);
  }
  friend RelativeError min(const RelativeError& x, const RelativeError& y) {
    return select(x.value <= y.value ? x : y, x, y);
  }
  /// sgn(x), exact unless x is within its error of 0.
  friend RelativeError sgn(const RelativeError& x) {
    const T r = x.value > 0 ? T(1) : (x.value < 0 ? T(-1) : T(0));
    if (x.exact || abs_of(x) * u < std::abs(x.value) || (x.value == 0 && abs_of(x) == 0)) return RelativeError(r);
    return relative(r, inf);
  }

  /// The absolute error bound, enlarged to cover the rounding of its own
  /// arithmetic and the dropped 1/(1 − u) factors (relative ~2u per
  /// operation; 1/1024 allows 2^42 operations).
  T bound() const { return abs_of(*this) * u * kBoundSafety; }
  static constexpr T kBoundSafety = T(1) + T(1) / 1024;

 private:
  RelativeError(T v, T e, bool x, bool a, bool n) : value(v), err(e), exact(x), absolute_form(a), nonneg(n) {}
};

}  // namespace skelconv
