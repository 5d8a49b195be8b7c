// skelconv/kernels/soft.hpp — the "soft object" kernel of the exam notes
// (docs/mathematics.md §1 and References, the exam notes part 3b):
//     K(r) = (1 − r²/R²)² for r < R, 0 beyond,
// i.e. the compact kernel k_R^4 under its own name and with no degree. The
// notes parameterise it by the radius ρ of the primitive's surface at iso c:
//     K(ρ) = c  ⇔  R = ρ / √(1 − √c)   (at c = ½: R = ρ √(2 + √2)).
// On points, segments and polygons: its segment and polygon closed forms are
// those of compact i = 4 (compact_levels below), not SCALIS primitives.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"

namespace skelconv::kernels {

struct SoftKernel {
  static constexpr KernelFamily family = KernelFamily::soft;
  static constexpr std::string_view name = "soft";
  static constexpr std::array<std::string_view, 1> parameters{"R"};
  static constexpr bool has_degree = false;
  /// Not on SCALIS primitives: their kernel is scaled by the radius τ and
  /// normalised per family (docs/mathematics.md §4); only inverse, Cauchy, compact are.
  static constexpr unsigned primitives = on_points | on_segments | on_polygons;
  /// K = k_R^4 exactly: segments and polygons use the generated compact i = 4.
  static constexpr std::array<CompactLevel, 1> compact_levels{{{1, 1, 4}}};
  static constexpr int min_degree = 0, max_degree = 0;  ///< no degree
  static constexpr bool singular_at_zero = false;

  double R = 1.0;  ///< support radius, > 0

  explicit SoftKernel(const KernelSpec& spec) : R(spec.R) { require_positive(R, "kernel.R"); }

  double support_radius() const { return R; }
  static constexpr bool finite_support = true;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;  ///< 0 from r = R on
  int scaling_power() const { return 0; }     ///< a function of r/R
  double length_scale() const { return R; }
  double max_value() const { return 1.0; }  ///< K(0)
  /// |K'| = 4 u (1 − u²)/R with u = r/R, largest at u² = 1/3: 8/(3√3 R).
  double max_slope() const { return 8.0 / (3.0 * std::sqrt(3.0) * R); }

  /// (1 − r²/R²)², 0 from r = R on (the test is on r: see compact.hpp).
  template <class T>
  T value(const T& r) const {
    if (!(r < T(R))) return T(0);
    const T v = T(1) - (r / T(R)) * (r / T(R));
    return v * v;
  }
  /// −4 r (1 − r²/R²) / R².
  template <class T>
  T derivative(const T& r) const {
    if (!(r < T(R))) return T(0);
    return T(-4) * r / (T(R) * T(R)) * (T(1) - (r / T(R)) * (r / T(R)));
  }

  /// The support radius R that puts the iso-c surface of a point at radius
  /// ρ (file comment), 0 < c < 1, ρ > 0.
  static std::optional<double> support_for_radius(double rho, double c) {
    if (!(c > 0.0 && c < 1.0 && rho > 0.0 && std::isfinite(rho))) return std::nullopt;
    return rho / std::sqrt(1.0 - std::sqrt(c));
  }
  /// ρ with K(ρ) = c around a point: R √(1 − √c), 0 < c < 1.
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < 1.0)) return std::nullopt;
    return R * std::sqrt(1.0 - std::sqrt(c));
  }
  /// Distance d with F(d) = c around an infinite line (longer than 2R either
  /// side of the foot): F(d) = ∫ K(√(d² + t²)) dt = 16 h⁵ / (15 R⁴),
  /// h = √(R² − d²); exists for 0 < c < 16R/15 = F(0).
  std::optional<double> line_iso_radius(double c) const {
    if (!(c > 0.0 && c < 16.0 * R / 15.0)) return std::nullopt;
    const double h = std::pow(15.0 * c * R * R * R * R / 16.0, 0.2);
    return std::sqrt(std::max(0.0, R * R - h * h));
  }
};

}  // namespace skelconv::kernels
