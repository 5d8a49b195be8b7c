// skelconv/kernels/wyvill.hpp — Wyvill's soft-object kernel (Ferley 1996
// §1.1.1, "éléments clefs", with d² scaled by the support radius R):
//     K(r) = 1 − 22/9 u + 17/9 u² − 4/9 u³,  u = r²/R², for r < R; 0 beyond.
// It equals v² (5 + 4v)/9 with v = 1 − u (= 5/9 (1−u)² + 4/9 (1−u)³), the
// form evaluated here: no cancellation near the support's edge. K(0) = 1,
// K(R) = K'(R) = 0; dK/du = −v (10 + 12v)/9 < 0 on [0, R), so K decreases.
// On points, segments and polygons (compact_levels below), not SCALIS primitives.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"

namespace skelconv::kernels {

struct WyvillKernel {
  static constexpr KernelFamily family = KernelFamily::wyvill;
  static constexpr std::string_view name = "wyvill";
  static constexpr std::array<std::string_view, 1> parameters{"R"};
  static constexpr bool has_degree = false;
  static constexpr unsigned primitives = on_points | on_segments | on_polygons;  ///< not SCALIS (see soft.hpp)
  /// K = 5/9 k_R^4 + 4/9 k_R^6 exactly (file comment): segments and polygons
  /// add the generated compact i = 4 and i = 6 closed forms.
  static constexpr std::array<CompactLevel, 2> compact_levels{{{5, 9, 4}, {4, 9, 6}}};
  static constexpr int min_degree = 0, max_degree = 0;  ///< no degree
  static constexpr bool singular_at_zero = false;

  double R = 1.0;  ///< support radius, > 0

  explicit WyvillKernel(const KernelSpec& spec) : R(spec.R) { require_positive(R, "kernel.R"); }

  double support_radius() const { return R; }
  static constexpr bool finite_support = true;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;  ///< 0 from r = R on
  int scaling_power() const { return 0; }     ///< a function of r/R
  double length_scale() const { return R; }
  double max_value() const { return 1.0; }  ///< K(0)
  /// |K'| = 2 u (1 − u²)(22 − 12 u²)/(9R) = (44u − 68u³ + 24u⁵)/(9R) with
  /// u = r/R, largest where 22 − 102 u² + 60 u⁴ = 0, u² = (102 − √5124)/120.
  double max_slope() const {
    const double u2 = (102.0 - std::sqrt(5124.0)) / 120.0, u = std::sqrt(u2);
    return 2.0 * u * (1.0 - u2) * (22.0 - 12.0 * u2) / (9.0 * R);
  }

  /// v² (5 + 4v) / 9, v = 1 − r²/R²; 0 from r = R on.
  template <class T>
  T value(const T& r) const {
    if (!(r < T(R))) return T(0);
    const T v = T(1) - (r / T(R)) * (r / T(R));
    return v * v * (T(5) + T(4) * v) / T(9);
  }
  /// dK/du · du/dr = −v (10 + 12v)/9 · 2r/R².
  template <class T>
  T derivative(const T& r) const {
    if (!(r < T(R))) return T(0);
    const T v = T(1) - (r / T(R)) * (r / T(R));
    return -v * (T(10) + T(12) * v) / T(9) * (T(2) * r / (T(R) * T(R)));
  }

  /// ρ with K(ρ) = c around a point, 0 < c < 1: the root v of
  /// v²(5 + 4v) = 9c in (0, 1) (increasing in v), ρ = R √(1 − v).
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < 1.0)) return std::nullopt;
    const double v = bisect_increasing([](double x) { return x * x * (5.0 + 4.0 * x) / 9.0; }, 0.0, 1.0, c);
    return R * std::sqrt(1.0 - v);
  }
  /// Distance d with F(d) = c around an infinite line: with h = √(R² − d²),
  /// F = 5/9 · 16h⁵/(15R⁴) + 4/9 · 32h⁷/(35R⁶) (∫(h² − t²)ⁿ dt over [−h, h]),
  /// increasing in h; exists for 0 < c < F(R) = 16R/27 + 128R/315.
  std::optional<double> line_iso_radius(double c) const {
    const auto line = [this](double h) {
      const double x = h / R;
      return R * (16.0 / 27.0 * std::pow(x, 5) + 128.0 / 315.0 * std::pow(x, 7));
    };
    if (!(c > 0.0 && c < line(R))) return std::nullopt;
    const double h = bisect_increasing(line, 0.0, R, c);
    return std::sqrt(std::max(0.0, R * R - h * h));
  }
};

}  // namespace skelconv::kernels
