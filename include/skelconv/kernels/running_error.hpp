// skelconv/kernels/running_error.hpp — a double that carries a bound on its
// own rounding error: running error analysis (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., §3.3) as a scalar type.
//
// The generated fast forms (generated/segment_*.hpp, `<kernel>_*_fast`) are
// templates on the scalar type; instantiated on RunningError<double> every
// operation of their expression graph also updates `err`, a bound on
// |value − exact| where `exact` is the same expression evaluated in real
// arithmetic on the (exact) double inputs. The rules, with u = 2^−53 the unit
// roundoff and fl(x ∘ y) = (x ∘ y)(1 + δ), |δ| ≤ u:
//
//   x ± y   e = e_x + e_y + u |r|
//   x · y   e = |x| e_y + |y| e_x + e_x e_y + u |r| + η
//   x / y   e = (e_x + |r| e_y) / (|y| − e_y) + u |r| + η      (∞ if e_y ≥ |y|)
//   √x      e = min(e_x / √x, √e_x) + u |r|  (√X − √x = (X − x)/(√X + √x))
//   log x   e = e_x / (x − e_x) + L u |r|  (mean value theorem; ∞ if e_x ≥ x)
//   asinh x e = e_x + L u |r|              (|asinh'| ≤ 1)
//   atan2   e = (π/2)(e_x + e_y)/√(x² + y²) + L u |r|  (∞ near the branch cut)
//   min, max: e = max(e_x, e_y)            (1-Lipschitz in the max norm)
//
// with η the smallest subnormal (underflow), L = 4 the libm's error in units of u (glibc documents at most 1–2 ulp
// for log, atan2 and asinh on x86-64, and 1 ulp ≤ 2u|r|). The rounding of
// the bound's own arithmetic (about u per operation, relative to the bound)
// is covered by `kBoundSafety` at the end (bound()). The bound is honest
// where the rules hold; the verifier checks it against float128 references
// (verify/filter_check.cpp).
#pragma once

#include <cmath>
#include <limits>

namespace skelconv {

template <class T>
struct RunningError {
  T value{};
  T err{};

  RunningError() = default;
  // NOLINTNEXTLINE(google-explicit-constructor): literals and inputs are exact
  RunningError(T v) : value(v), err(0) {}
  RunningError(T v, T e) : value(v), err(e) {}
  // Literals like T(7) in the generated code: exact small integers.
  explicit RunningError(int v) : value(T(v)), err(0) {}

  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T kLibm = 4;  // libm error bound, units of u (see above)
  static constexpr T inf = std::numeric_limits<T>::infinity();
  // Underflow: fl(x ∘ y) = (x ∘ y)(1 + δ) + η with |η| ≤ the smallest
  // subnormal for × and / (Higham §2.1; sums of doubles are exact there).
  static constexpr T eta = std::numeric_limits<T>::denorm_min();

  RunningError operator-() const { return {-value, err}; }
  RunningError& operator+=(const RunningError& y) { return *this = *this + y; }
  RunningError& operator-=(const RunningError& y) { return *this = *this - y; }
  RunningError& operator*=(const RunningError& y) { return *this = *this * y; }
  RunningError& operator/=(const RunningError& y) { return *this = *this / y; }

  friend RunningError operator+(const RunningError& x, const RunningError& y) {
    const T r = x.value + y.value;
    return {r, x.err + y.err + u * std::abs(r)};
  }
  friend RunningError operator-(const RunningError& x, const RunningError& y) {
    const T r = x.value - y.value;
    return {r, x.err + y.err + u * std::abs(r)};
  }
  friend RunningError operator*(const RunningError& x, const RunningError& y) {
    const T r = x.value * y.value;
    // |x| e_y + |y| e_x + e_x e_y, with one product fewer.
    return {r, (std::abs(x.value) + x.err) * y.err + std::abs(y.value) * x.err + (u * std::abs(r) + eta)};
  }
  friend RunningError operator/(const RunningError& x, const RunningError& y) {
    const T r = x.value / y.value;
    const T margin = std::abs(y.value) - y.err;
    if (!(margin > 0)) return {r, inf};
    return {r, (x.err + std::abs(r) * y.err) / margin + u * std::abs(r) + eta};
  }
  friend RunningError sqrt(const RunningError& x) {
    const T r = std::sqrt(x.value);
    if (x.err == 0) return {r, u * r};
    if (!(x.value >= 0)) return {r, inf};
    // Also |√X − √x| ≤ √|X − x| for X, x ≥ 0: finite where x → 0.
    const T propagated = std::sqrt(x.err);
    return {r, (r > 0 && x.err / r < propagated ? x.err / r : propagated) + u * r};
  }
  friend RunningError log(const RunningError& x) {
    const T r = std::log(x.value);
    const T margin = x.value - x.err;
    if (!(margin > 0)) return {r, inf};
    return {r, x.err / margin + kLibm * u * std::abs(r)};
  }
  friend RunningError asinh(const RunningError& x) {
    const T r = std::asinh(x.value);
    return {r, x.err + kLibm * u * std::abs(r)};
  }
  friend RunningError atan2(const RunningError& y, const RunningError& x) {
    const T r = std::atan2(y.value, x.value);
    const T radius = std::hypot(x.value, y.value);
    const T shift = x.err + y.err;
    // Within `shift` of the cut (negative x axis) the angle may jump by 2π.
    if (!(shift < radius) || (x.value < 0 && std::abs(y.value) <= y.err)) return {r, inf};
    return {r, T(1.5707963267948968) * shift / (radius - shift) + kLibm * u * std::abs(r)};
  }
  friend RunningError max(const RunningError& x, const RunningError& y) {
    return {x.value >= y.value ? x.value : y.value, x.err > y.err ? x.err : y.err};
  }
  friend RunningError min(const RunningError& x, const RunningError& y) {
    return {x.value <= y.value ? x.value : y.value, x.err > y.err ? x.err : y.err};
  }
  /// sgn(x), exact unless x is within its error of 0.
  friend RunningError sgn(const RunningError& x) {
    const T r = x.value > 0 ? T(1) : (x.value < 0 ? T(-1) : T(0));
    return {r, std::abs(x.value) > x.err ? T(0) : inf};
  }

  /// The error bound, enlarged to cover the rounding of its own arithmetic
  /// (relative ~u per operation; 1/1024 allows 2^43 operations).
  T bound() const { return err * kBoundSafety; }
  static constexpr T kBoundSafety = T(1) + T(1) / 1024;
};

}  // namespace skelconv
