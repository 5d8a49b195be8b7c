// verify/kernel_definitions.hpp — the kernels of docs/mathematics.md §1 and the soft objects, as
// functions of the distance r with their derivatives, taken from the one
// description of each family (its trait, skelconv/kernels/). This is the
// ground truth of the verifier: it shares no algebra with the closed forms.
#pragma once

#include <cmath>
#include <limits>
#include <variant>

#include "skelconv/kernels/kernel_list.hpp"

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

/// One kernel K with its parameters, evaluated from the DEFINITION that its
/// runtime trait states (skelconv/kernels/: K(r) and dK/dr written directly
/// from the formula, in any scalar type). It shares no algebra with the
/// segment closed forms (no a, b, c, no J recurrences, no erf).
template <class T>
struct KernelDefinition {
  KernelFamily family = KernelFamily::inverse;
  int degree = 1;  ///< i (families with a degree)
  T s = T(1);      ///< Cauchy sharpness (cauchy only)
  T R = T(1);      ///< support radius (compact, soft, wyvill)
  T a = T(1);      ///< Gaussian sharpness (gaussian only)
  T b = T(1);      ///< Gaussian height (gaussian only)

  /// The trait of `family` with these parameters (they are doubles in every
  /// sweep, so the conversion is exact).
  kernels::RadialKernel trait() const {
    KernelSpec spec;
    spec.family = family;
    spec.degree = degree;
    spec.s = static_cast<double>(s);
    spec.R = static_cast<double>(R);
    spec.a = static_cast<double>(a);
    spec.b = static_cast<double>(b);
    return kernels::make_radial_kernel(spec);
  }

  /// K(r). The three families of docs/mathematics.md §1 are written here in T with their
  /// parameters in T: the SCALIS and thickness references pass parameters
  /// that are not doubles (s = 1/(σ²τ²), R = στ in binary128), which the
  /// trait (double members) would round. The verifier's own definitions,
  /// independent of the runtime:
  ///   p^i(r)   = r^-i
  ///   c_s^i(r) = (1 + s r²)^(-i/2)
  ///   k_R^i(r) = (1 - r²/R²)^(i/2) for r < R, else 0 (any i ≥ 1)
  /// The other families come from their traits (their sweeps draw double
  /// parameters, so the conversion in trait() is exact).
  T value(const T& r) const {
    switch (family) {
      case KernelFamily::inverse: return T(1) / integer_power(r, degree);
      case KernelFamily::cauchy: return half_integer_power(T(1) + s * r * r, -degree);
      case KernelFamily::compact:
        if (!(r < R)) return T(0);
        return half_integer_power(T(1) - (r / R) * (r / R), degree);
      default: return std::visit([&](const auto& k) { return k.template value<T>(r); }, trait());
    }
  }
  /// K'(r)/r, so that ∇_P K(|P − Γ|) = K'(r)/r · (P − Γ) (docs/mathematics.md §2, gradient
  /// under the integral); r > 0.
  ///   p^i:   K'/r = -i r^(-i-2)
  ///   c_s^i: K'/r = -i s (1+sr²)^(-(i+2)/2)
  ///   k_R^i: K'/r = -(i/R²)(1-r²/R²)^((i-2)/2)  (i ≥ 2: → 0 at r = R)
  T derivative_over_r(const T& r) const {
    switch (family) {
      case KernelFamily::inverse: return -T(degree) / integer_power(r, degree + 2);
      case KernelFamily::cauchy: return -T(degree) * s * half_integer_power(T(1) + s * r * r, -(degree + 2));
      case KernelFamily::compact:
        if (!(r < R)) return T(0);
        return -T(degree) / (R * R) * half_integer_power(T(1) - (r / R) * (r / R), degree - 2);
      default: return std::visit([&](const auto& k) { return k.template derivative<T>(r) / r; }, trait());
    }
  }
  /// K = 0 beyond this distance (+inf: no support limit).
  T support_radius() const {
    if (family == KernelFamily::compact) return R;  // exact in T (see value)
    if (family == KernelFamily::inverse || family == KernelFamily::cauchy) return std::numeric_limits<T>::infinity();
    return T(kernels::support_radius(trait()));
  }
  /// Width, in distance units, of the peak of u ↦ K(√(d² + u²)) at u = 0 for
  /// a point at distance d from the line (the trait's peak_width; +inf where
  /// it has none: no narrower peak than the support).
  T peak_width(const T& d) const {
    // k_R^i has no peak narrower than its support (and i = 1, which the
    // self-check integrates, is not a kernel its trait accepts).
    if (family == KernelFamily::compact) return std::numeric_limits<T>::infinity();
    return std::visit(
        [&](const auto& k) -> T {
          if constexpr (requires { k.template peak_width<T>(d); }) {
            return k.template peak_width<T>(d);
          } else {
            return std::numeric_limits<T>::infinity();
          }
        },
        trait());
  }
};

}  // namespace skelconv::verify
