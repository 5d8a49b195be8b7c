// skelconv/kernels/cauchy.hpp — the Cauchy kernel c_s^i(r) = (1 + s r²)^(−i/2)
// (docs/mathematics.md §1, Hubert 2012 §2.1) as a radial kernel trait (radial_kernel.hpp).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"
#include "skelconv/kernels/scalis_description.hpp"

namespace skelconv::kernels {

struct CauchyKernel {
  static constexpr KernelFamily family = KernelFamily::cauchy;
  static constexpr std::string_view name = "cauchy";
  static constexpr std::array<std::string_view, 1> parameters{"s"};
  static constexpr int min_degree = 1, max_degree = 16;  ///< as on segments
  static constexpr bool has_degree = true;          ///< JSON "degree" is read
  static constexpr unsigned primitives = on_points | on_segments | on_polygons | on_scalis;  ///< all generated
  static constexpr bool singular_at_zero = false;

  int degree = 4;
  double s = 1.0;  ///< sharpness, > 0

  explicit CauchyKernel(const KernelSpec& spec) : degree(spec.degree), s(spec.s) {
    require_positive(s, "kernel.s");
    require_degree(name, degree, min_degree, max_degree);
  }

  double support_radius() const { return std::numeric_limits<double>::infinity(); }
  static constexpr bool finite_support = false;  ///< support_radius() is finite
  static constexpr bool vanishes_far = false;  ///< decays as a power, (s r²)^(−i/2)
  int scaling_power() const { return 0; }      ///< a function of s r²
  /// K = (α r² + β)^(−i/2) with α = s, β = 1 (as inverse.hpp).
  template <class T>
  static std::array<T, 2> quadratic_form(const T& s) {
    return {s, T(1)};
  }
  double length_scale() const { return 1.0 / std::sqrt(s); }
  double max_value() const { return 1.0; }  ///< K(0)
  /// |K'| = i s r q^(−i/2−1), q = 1 + s r², is largest where q = (i + 2) s r²,
  /// i.e. s r² = 1/(i + 1): i √s (i + 1)^(−1/2) ((i + 2)/(i + 1))^(−(i+2)/2).
  double max_slope() const {
    const double i = degree;
    return i * std::sqrt(s / (i + 1)) * std::pow((i + 2) / (i + 1), -0.5 * (i + 2));
  }

  /// (1 + s r²)^(−i/2).
  template <class T>
  T value(const T& r) const {
    return T(1) / half_integer_power(T(1) + T(s) * r * r, degree);
  }
  /// −i s r (1 + s r²)^(−i/2 − 1).
  template <class T>
  T derivative(const T& r) const {
    const T q = T(1) + T(s) * r * r;
    return -T(degree) * T(s) * r / (half_integer_power(q, degree) * q);
  }
  /// Radius of the iso-surface K(r) = c around a point: r = √((c^(−2/i) − 1)/s), 0 < c < 1.
  /// Width of the peak of u ↦ K(√(d² + u²)) at u = 0:
  /// 1 + s(d² + u²) = s(u² + d² + 1/s), width √(d² + 1/s).
  template <class T>
  T peak_width(const T& d) const {
    using std::sqrt;
    return sqrt(d * d + T(1) / T(s));
  }
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < 1.0)) return std::nullopt;
    return std::sqrt((std::pow(c, -2.0 / degree) - 1.0) / s);
  }

  // SCALIS (scalis_description.hpp): K(d/σ) = (1 + (d/σ)²)^(−i/2).
  static constexpr ScalisSingularity scalis_singularity = ScalisSingularity::at_zero_radius;
  static constexpr bool scalis_segment_generated = true;
  static constexpr bool scalis_sigma_above_one = false;
  static constexpr double scalis_radius_term = 1.0;  ///< (1 + (d/στ)²)^(−i/2) ∝ (d² + σ²τ²)^(−i/2)
  static double scalis_line_normalisation(int i, double sigma) {
    return std::pow(sigma, i) * std::pow(1.0 + sigma * sigma, (1.0 - i) / 2) * inverse_line_integral(i);
  }
  /// 2π σ² (1 + 1/σ²)^(1 − i/2) / (i − 2); diverges for i ≤ 2.
  static double scalis_plane_normalisation(int i, double sigma) {
    require_plane_degree(name, i);
    return 2 * std::numbers::pi * sigma * sigma * std::pow(1.0 + 1.0 / (sigma * sigma), 1.0 - i / 2.0) / (i - 2);
  }
  /// c_s^i with s = 1/(στ)², times 1/τ².
  static ScalisPolygonKernel scalis_polygon_kernel(int i, double sigma, double tau) {
    return {KernelSpec::cauchy(i, 1.0 / (sigma * sigma * tau * tau)), 1.0 / (tau * tau)};
  }
};

}  // namespace skelconv::kernels
