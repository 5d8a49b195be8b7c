// skelconv/kernels/kernel_spec.hpp — which kernel a primitive convolves with.
//
// The kernels of docs/mathematics.md §1 (Hubert 2012 §2.1), for a distance r ≥ 0:
//   inverse  p^i(r)   = r^(-i)
//   cauchy   c_s^i(r) = (1 + s r²)^(-i/2),                 s > 0
//   compact  k_R^i(r) = (1 − r²/R²)^(i/2) for r < R, else 0, R > 0
// and, on point primitives only (include/skelconv/kernels/, no degree):
//   soft     (1 − r²/R²)² for r < R,                          R > 0
//   wyvill   1 − 22/9 u + 17/9 u² − 4/9 u³, u = r²/R², r < R,  R > 0
//   ferley   1 + k(e − r) for r < e, (r − R)²/(e − R)² for e ≤ r < R,  0 < e < R
//   gaussian b exp(−a r²),                                     a, b > 0
// and, with a degree k ≥ 1 and on points only:
//   polynomial (1 − r²/R²)^k for r < R,                        R > 0
// Which degrees i exist is decided by the generator (docs/generated_api.md),
// so the runtime asks the generated table instead of hard-coding a range.
#pragma once

#include <optional>
#include <string_view>

#include "skelconv/primitives/segment_input.hpp"  // KernelFamily, family_name

namespace skelconv {

/// Family, degree i and the family's parameters. Only the parameters of the
/// chosen family are read (s for cauchy; R for compact, soft, wyvill, polynomial; e and R
/// for ferley; a and b for gaussian); the others are ignored.
/// Values are checked where the kernel is used (Segment's constructor).
struct KernelSpec {
  KernelFamily family = KernelFamily::inverse;
  int degree = 3;  ///< the exponent i of docs/mathematics.md §1
  double s = 1.0;  ///< Cauchy sharpness, > 0 (cauchy only)
  double R = 1.0;  ///< support radius, > 0 (compact, soft, wyvill, ferley, polynomial)
  double e = 0.5;  ///< Ferley's coating thickness, 0 < e < R (ferley only)
  double a = 1.0;  ///< Gaussian sharpness, > 0 (gaussian only)
  double b = 1.0;  ///< Gaussian height K(0), > 0 (gaussian only)

  static KernelSpec inverse(int degree) { return {KernelFamily::inverse, degree, 1.0, 1.0}; }
  static KernelSpec cauchy(int degree, double s) { return {KernelFamily::cauchy, degree, s, 1.0}; }
  static KernelSpec compact(int degree, double R) { return {KernelFamily::compact, degree, 1.0, R}; }
  // The point-only families have no degree (0 here, not read).
  static KernelSpec soft(double R) { return {KernelFamily::soft, 0, 1.0, R}; }
  static KernelSpec wyvill(double R) { return {KernelFamily::wyvill, 0, 1.0, R}; }
  static KernelSpec ferley(double e, double R) { return {KernelFamily::ferley, 0, 1.0, R, e}; }
  static KernelSpec gaussian(double a, double b) { return {KernelFamily::gaussian, 0, 1.0, 1.0, 0.5, a, b}; }
  /// (1 − r²/R²)^k: the degree is the exponent k itself.
  static KernelSpec polynomial(int k, double R) { return {KernelFamily::polynomial, k, 1.0, R}; }
};

/// Every family, in the order of the enum.
inline constexpr KernelFamily all_kernel_families[] = {
    KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact,  KernelFamily::soft,
    KernelFamily::wyvill,  KernelFamily::ferley, KernelFamily::gaussian, KernelFamily::polynomial};

/// The family named family_name(family); std::nullopt for any other text.
constexpr std::optional<KernelFamily> family_from_name(std::string_view name) {
  for (KernelFamily family : all_kernel_families) {
    if (family_name(family) == name) return family;
  }
  return std::nullopt;
}

/// The parameter of `spec` that the JSON key `name` sets ("s", "R", "e",
/// "a", "b"), or nullptr for any other key. The kernel traits list their
/// keys (kernels/radial_kernel.hpp); the reader sets them through this.
constexpr double* kernel_parameter(KernelSpec& spec, std::string_view name) {
  if (name == "s") return &spec.s;
  if (name == "R") return &spec.R;
  if (name == "e") return &spec.e;
  if (name == "a") return &spec.a;
  if (name == "b") return &spec.b;
  return nullptr;
}

}  // namespace skelconv
