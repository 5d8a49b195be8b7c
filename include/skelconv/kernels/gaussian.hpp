// skelconv/kernels/gaussian.hpp — the Gaussian kernel of Blinn and Muraki
// (Ferley 1996 §1.1.1 and §1.1.3: f_i(P) = b_i exp(−a_i ‖P − P_i‖²)):
//     K(r) = b exp(−a r²),  a > 0, b > 0,
// infinite support, decreasing. Ferley §2.2.5 convolves h = exp(−‖P‖²/2)
// along segments (an erf closed form): skelconv/primitives/segment_gaussian.hpp. On
// points and segments; polygons and SCALIS primitives refuse it.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "skelconv/detail/exp_pieces.hpp"
#include "skelconv/kernels/radial_kernel.hpp"
#include "skelconv/primitives/segment_gaussian.hpp"

namespace skelconv::kernels {

struct GaussianKernel {
  static constexpr KernelFamily family = KernelFamily::gaussian;
  static constexpr std::string_view name = "gaussian";
  static constexpr std::array<std::string_view, 2> parameters{"a", "b"};
  static constexpr bool has_degree = false;
  /// Segments by the erf closed form of skelconv/primitives/segment_gaussian.hpp;
  /// polygons have no closed form here (the 2-D integral of exp(−a r²) over
  /// a fan triangle is an Owen-T-like function, not generated), and SCALIS
  /// primitives are defined for inverse, Cauchy and compact only.
  static constexpr unsigned primitives = on_points | on_segments;
  /// Its segment field, f and ∇f for weight degree W (hand-written: see there).
  template <class T, int W>
  using SegmentClosedForm = detail::gaussian_segment::ClosedForm<T, W>;
  static constexpr const char* segment_equation = "b |AB| ∫_0^1 w(t) exp(−a |P − Γ(t)|²) dt";
  static constexpr int min_degree = 0, max_degree = 0;  ///< no degree
  static constexpr bool singular_at_zero = false;

  double a = 1.0;  ///< sharpness, > 0
  double b = 1.0;  ///< height K(0), > 0

  explicit GaussianKernel(const KernelSpec& spec) : a(spec.a), b(spec.b) {
    require_positive(a, "kernel.a");
    require_positive(b, "kernel.b");
  }

  double support_radius() const { return std::numeric_limits<double>::infinity(); }
  /// exp(−a r²) underflows to 0 at a finite r (0 is then its correctly
  /// rounded value).
  static constexpr bool finite_support = false;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;
  int scaling_power() const { return 0; }  ///< a function of a r²
  double length_scale() const { return 1.0 / std::sqrt(a); }
  double max_value() const { return b; }  ///< K(0)
  /// |K'| = 2abr exp(−ar²), largest at r = 1/√(2a): b √(2a) e^(−1/2).
  double max_slope() const { return b * std::sqrt(2.0 * a) * std::exp(-0.5); }

  template <class T>
  T value(const T& r) const {
    return times_exp_minus(T(b), T(a) * r * r);
  }
  template <class T>
  T derivative(const T& r) const {
    return times_exp_minus(T(-2) * T(a) * T(b) * r, T(a) * r * r);
  }

  /// c e^(−x), x ≥ 0: far away (x above ~700 in double) in normal pieces,
  /// so that a large c (the height b) is not lost to the exponential's
  /// underflow (detail/exp_pieces.hpp); elsewhere the plain product, bit for
  /// bit. Always the plain product for an enclosure type (Interval: no
  /// numeric_limits), whose bounds are outward-rounded either way.
  template <class T>
  static T times_exp_minus(const T& c, const T& x) {
    using std::exp;
    if constexpr (!std::numeric_limits<T>::is_specialized) {
      return c * exp(-x);
    } else {
      return detail::ExpPieces<T>(x).times(c);
    }
  }

  /// Width of the peak of u ↦ K(√(d² + u²)) = K(d) e^(−a u²): 1/√a.
  template <class T>
  T peak_width(const T&) const {
    using std::sqrt;
    return T(1) / sqrt(T(a));
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
