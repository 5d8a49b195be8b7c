// skelconv/kernel_spec.hpp — which kernel a primitive convolves with.
//
// The kernels of SPEC §1 (Hubert 2012 §2.1), for a distance r ≥ 0:
//   inverse  p^i(r)   = r^(-i)
//   cauchy   c_s^i(r) = (1 + s r²)^(-i/2),                 s > 0
//   compact  k_R^i(r) = (1 − r²/R²)^(i/2) for r < R, else 0, R > 0
// Which degrees i exist is decided by the generator (docs/generated_api.md),
// so the runtime asks the generated table instead of hard-coding a range.
#pragma once

#include <optional>
#include <string_view>

#include "skelconv/segment_input.hpp"  // KernelFamily, family_name

namespace skelconv {

/// Family, degree i and the family's parameter. Only the parameter of the
/// chosen family is read (s for cauchy, R for compact); the other is ignored.
/// Values are checked where the kernel is used (Segment's constructor).
struct KernelSpec {
  KernelFamily family = KernelFamily::inverse;
  int degree = 3;  ///< the exponent i of SPEC §1
  double s = 1.0;  ///< Cauchy sharpness, > 0 (cauchy only)
  double R = 1.0;  ///< support radius, > 0 (compact only)

  static KernelSpec inverse(int degree) { return {KernelFamily::inverse, degree, 1.0, 1.0}; }
  static KernelSpec cauchy(int degree, double s) { return {KernelFamily::cauchy, degree, s, 1.0}; }
  static KernelSpec compact(int degree, double R) { return {KernelFamily::compact, degree, 1.0, R}; }
};

/// The family named "inverse", "cauchy" or "compact" (the spelling of
/// family_name); std::nullopt for any other text.
constexpr std::optional<KernelFamily> family_from_name(std::string_view name) {
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    if (family_name(family) == name) return family;
  }
  return std::nullopt;
}

}  // namespace skelconv
