// skelconv/kernels/inverse.hpp — the power-inverse kernel p^i(r) = r^(−i)
// (docs/mathematics.md §1, Hubert 2012 §2.1) as a radial kernel trait (radial_kernel.hpp).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <string_view>

#include "skelconv/detail/integer_power.hpp"
#include "skelconv/kernels/radial_kernel.hpp"
#include "skelconv/kernels/scalis_description.hpp"

namespace skelconv::kernels {

struct InverseKernel {
  static constexpr KernelFamily family = KernelFamily::inverse;
  static constexpr std::string_view name = "inverse";
  static constexpr std::array<std::string_view, 0> parameters{};
  /// The segments' range (docs/cli_skeleton.md), so that a file can turn a segment
  /// into a point without changing its kernel.
  static constexpr int min_degree = 1, max_degree = 16;
  static constexpr bool has_degree = true;          ///< JSON "degree" is read
  static constexpr unsigned primitives = on_points | on_segments | on_polygons | on_scalis;  ///< all generated
  static constexpr bool singular_at_zero = true;

  int degree = 3;

  explicit InverseKernel(const KernelSpec& spec) : degree(spec.degree) {
    require_degree(name, degree, min_degree, max_degree);
  }

  double support_radius() const { return std::numeric_limits<double>::infinity(); }
  static constexpr bool finite_support = false;  ///< support_radius() is finite
  static constexpr bool vanishes_far = false;  ///< r^(−i) > 0 in double up to r ~ 2^(1074/i)
  /// r^(−i) has no length of its own: λ^(−i) K(r/λ) (radial_kernel.hpp).
  int scaling_power() const { return -degree; }
  /// K = (α r² + β)^(−i/2) with α = 1, β = 0: the form the polygon closed
  /// forms take (docs/mathematics.md §3, skelconv/primitives/polygon_field.hpp).
  template <class T>
  static std::array<T, 2> quadratic_form(const T& /*s*/) {
    return {T(1), T(0)};
  }
  /// The one degree the polygon closed forms leave out, and why (the
  /// polygon's message, src/primitives/polygon.cpp): the contour recurrence
  /// of docs/mathematics.md §3, i z² G^(i+2) − (i − 2) G^i = (u² + v² + z²)^(−i/2), reaches
  /// every i ≥ 3 from C^(p³) and C^(p⁴) and excludes i = 2.
  static constexpr int polygon_excluded_degree = 2;
  static constexpr std::string_view polygon_excluded_reason =
      "the contour formula of the polygon closed forms (docs/mathematics.md §3, Hubert 2012 §6) excludes it";
  double length_scale() const { return 1.0; }
  double max_value() const { return std::numeric_limits<double>::infinity(); }  ///< K(0) = +inf
  double max_slope() const { return std::numeric_limits<double>::infinity(); }

  /// r^(−i); r > 0 (r = 0 is the singular centre, handled by the caller).
  template <class T>
  T value(const T& r) const {
    return integer_power(r, -degree);
  }
  /// −i r^(−i−1).
  template <class T>
  T derivative(const T& r) const {
    return -T(degree) * integer_power(r, -degree - 1);
  }
  /// Radius of the iso-surface w K(r) = c around a point of weight 1: r = c^(−1/i).
  /// Width of the peak of u ↦ K(√(d² + u²)) at u = 0: (d² + u²)^(−i/2)
  /// halves within u ~ d (the verifier's quadrature substitution).
  template <class T>
  T peak_width(const T& d) const {
    return d;
  }
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0) || !std::isfinite(c)) return std::nullopt;
    return std::pow(c, -1.0 / degree);
  }

  // SCALIS (scalis_description.hpp): K(d/σ) = (d/σ)^(−i).
  static constexpr ScalisSingularity scalis_singularity = ScalisSingularity::on_segment;
  static constexpr bool scalis_segment_generated = true;
  static constexpr bool scalis_sigma_above_one = false;
  static constexpr double scalis_radius_term = 0.0;  ///< (d/σ)^(−i) ∝ (d²)^(−i/2)
  static double scalis_line_normalisation(int i, double sigma) { return std::pow(sigma, i) * inverse_line_integral(i); }
  /// 2π σ^i / (i − 2); diverges for i ≤ 2.
  static double scalis_plane_normalisation(int i, double sigma) {
    require_plane_degree(name, i);
    return 2 * std::numbers::pi * std::pow(sigma, i) / (i - 2);
  }
  /// p^i itself, times (στ)^i / τ².
  static ScalisPolygonKernel scalis_polygon_kernel(int i, double sigma, double tau) {
    return {KernelSpec::inverse(i), 1.0 / (tau * tau) * std::pow(sigma * tau, i)};
  }
};

}  // namespace skelconv::kernels
