// verify/kernel_definitions.hpp — the kernels of SPEC §1, written directly
// from their definitions as functions of the distance r, with hand-written
// derivatives. This is the ground truth of the verifier: it shares no algebra
// with the generated closed forms (no a, b, c, no J recurrences).
#pragma once

#include <cmath>

#include "skelconv/segment_input.hpp"

namespace skelconv::verify {

/// x^n for an integer n ≥ 0 by repeated squaring (no pow: exact enough and
/// fast on software binary128).
template <class T>
T integer_power(T x, int n) {
  T result(1);
  while (n > 0) {
    if (n & 1) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

/// x^(n/2) for x ≥ 0 and any integer n (negative allowed): √x raised to n.
template <class T>
T half_integer_power(const T& x, int n) {
  using std::sqrt;
  const T root = sqrt(x);
  return n >= 0 ? integer_power(root, n) : T(1) / integer_power(root, -n);
}

/// One kernel K of SPEC §1 with its parameters.
template <class T>
struct KernelDefinition {
  KernelFamily family = KernelFamily::inverse;
  int degree = 1;  ///< i
  T s = T(1);      ///< Cauchy sharpness (cauchy only)
  T R = T(1);      ///< support radius (compact only)

  /// K(r), SPEC §1:
  ///   p^i(r)   = r^-i
  ///   c_s^i(r) = (1 + s r²)^(-i/2)
  ///   k_R^i(r) = (1 - r²/R²)^(i/2) for r < R, else 0
  T value(const T& r) const {
    switch (family) {
      case KernelFamily::inverse: return T(1) / integer_power(r, degree);
      case KernelFamily::cauchy: return half_integer_power(T(1) + s * r * r, -degree);
      case KernelFamily::compact:
        if (!(r < R)) return T(0);
        return half_integer_power(T(1) - (r / R) * (r / R), degree);
    }
    return T(0);
  }

  /// K'(r)/r, so that ∇_P K(|P − Γ|) = K'(r)/r · (P − Γ) (SPEC §2, gradient
  /// under the integral). Derivatives by hand:
  ///   p^i:   K' = -i r^(-i-1)                       ⇒ K'/r = -i r^(-i-2)
  ///   c_s^i: K' = -(i/2)(1+sr²)^(-i/2-1) · 2sr       ⇒ K'/r = -i s (1+sr²)^(-(i+2)/2)
  ///   k_R^i: K' = (i/2)(1-r²/R²)^(i/2-1) · (-2r/R²)  ⇒ K'/r = -(i/R²)(1-r²/R²)^((i-2)/2)
  /// (k_R^i for i ≥ 2 only, so the last power is ≥ 0 and K'/r → 0 at r = R.)
  T derivative_over_r(const T& r) const {
    switch (family) {
      case KernelFamily::inverse: return -T(degree) / integer_power(r, degree + 2);
      case KernelFamily::cauchy: return -T(degree) * s * half_integer_power(T(1) + s * r * r, -(degree + 2));
      case KernelFamily::compact:
        if (!(r < R)) return T(0);
        return -T(degree) / (R * R) * half_integer_power(T(1) - (r / R) * (r / R), degree - 2);
    }
    return T(0);
  }
};

}  // namespace skelconv::verify
