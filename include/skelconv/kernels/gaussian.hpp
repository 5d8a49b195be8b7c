// skelconv/kernels/gaussian.hpp — the Gaussian kernel of Blinn and Muraki
// (Ferley 1996 §1.1.1 and §1.1.3: f_i(P) = b_i exp(−a_i ‖P − P_i‖²)):
//     K(r) = b exp(−a r²),  a > 0, b > 0,
// infinite support, decreasing. Ferley §2.2.5 convolves h = exp(−‖P‖²/2)
// along segments (an erf closed form); that closed form is not generated
// yet, so this is a point-only family (kernel_list.hpp).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"

namespace skelconv::kernels {

struct GaussianKernel {
  static constexpr KernelFamily family = KernelFamily::gaussian;
  static constexpr std::string_view name = "gaussian";
  static constexpr std::array<std::string_view, 2> parameters{"a", "b"};
  static constexpr bool has_degree = false, on_every_primitive = false;
  static constexpr int min_degree = 0, max_degree = 0;  ///< no degree
  static constexpr bool singular_at_zero = false;

  double a = 1.0;  ///< sharpness, > 0
  double b = 1.0;  ///< height K(0), > 0

  explicit GaussianKernel(const KernelSpec& spec) : a(spec.a), b(spec.b) {
    require_positive(a, "kernel.a");
    require_positive(b, "kernel.b");
  }

  double support_radius() const { return std::numeric_limits<double>::infinity(); }

  template <class T>
  T value(const T& r) const {
    using std::exp;
    return T(b) * exp(-T(a) * r * r);
  }
  template <class T>
  T derivative(const T& r) const {
    using std::exp;
    return T(-2) * T(a) * T(b) * r * exp(-T(a) * r * r);
  }

  /// ρ with K(ρ) = c around a point: √(ln(b/c)/a), 0 < c < b.
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < b)) return std::nullopt;
    return std::sqrt(std::log(b / c) / a);
  }
  /// Around an infinite line F(d) = b √(π/a) exp(−a d²):
  /// d = √(ln(b √(π/a) / c)/a), 0 < c < b √(π/a).
  std::optional<double> line_iso_radius(double c) const {
    const double peak = b * std::sqrt(std::numbers::pi / a);
    if (!(c > 0.0 && c < peak)) return std::nullopt;
    return std::sqrt(std::log(peak / c) / a);
  }
};

}  // namespace skelconv::kernels
