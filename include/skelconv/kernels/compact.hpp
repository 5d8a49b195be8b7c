// skelconv/kernels/compact.hpp — the compact-support kernel
// k_R^i(r) = (1 − r²/R²)^(i/2) for r < R, else 0 (docs/mathematics.md §1, Hubert 2012 §2.1)
// as a radial kernel trait (radial_kernel.hpp).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"
#include "skelconv/kernels/scalis_description.hpp"

namespace skelconv::kernels {

struct CompactKernel {
  static constexpr KernelFamily family = KernelFamily::compact;
  static constexpr std::string_view name = "compact";
  static constexpr std::array<std::string_view, 1> parameters{"R"};
  /// As on segments: i ≥ 2 so that dK/dr stays bounded at r = R
  /// (i = 1 has dK/dr → −∞ there).
  static constexpr int min_degree = 2, max_degree = 16;
  static constexpr bool has_degree = true;          ///< JSON "degree" is read
  static constexpr unsigned primitives = on_points | on_segments | on_polygons | on_scalis;  ///< all generated
  static constexpr bool singular_at_zero = false;

  int degree = 4;
  double R = 1.0;  ///< support radius, > 0

  explicit CompactKernel(const KernelSpec& spec) : degree(spec.degree), R(spec.R) {
    require_positive(R, "kernel.R");
    require_degree(name, degree, min_degree, max_degree);
  }

  double support_radius() const { return R; }
  static constexpr bool finite_support = true;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;  ///< 0 from r = R on
  /// The thickness corrections (skelconv/skeleton/thickness_correction.hpp,
  /// scalis_thickness_correction.hpp) are written for this family: a finite
  /// support R keeps a weight's change local, the linear-weight segment forms
  /// and the point and SCALIS forms of every degree are generated.
  static constexpr bool thickness_correction = true;
  int scaling_power() const { return 0; }     ///< a function of r/R
  double length_scale() const { return R; }
  double max_value() const { return 1.0; }  ///< K(0)
  /// |K'| = i u (1 − u²)^((i−2)/2) / R with u = r/R, largest at u² = 1/(i − 1)
  /// for i > 2 (at u = 1 for i = 2).
  double max_slope() const {
    const double i = degree;
    const double u = i > 2 ? 1.0 / std::sqrt(i - 1) : 1.0;
    return i * u * std::pow(1.0 - u * u, 0.5 * (i - 2)) / R;
  }

  /// (1 − r²/R²)^(i/2) inside the support, exactly 0 from r = R on. The
  /// test is on r itself, so that an interval r (skelconv/interval/) is
  /// compared exactly; in double, r < R gives u >= 0, and u = 0 gives 0.
  template <class T>
  T value(const T& r) const {
    if (!(r < T(R))) return T(0);
    return half_integer_power(T(1) - (r / T(R)) * (r / T(R)), degree);
  }
  /// −(i r / R²) (1 − r²/R²)^(i/2 − 1) inside, 0 outside (for i = 2 the
  /// one-sided value at r = R: the derivative jumps there).
  template <class T>
  T derivative(const T& r) const {
    const T u = T(1) - (r / T(R)) * (r / T(R));
    if (!(u > T(0))) return T(0);
    return -T(degree) * r / (T(R) * T(R)) * half_integer_power(u, degree - 2);
  }
  /// Radius of the iso-surface K(r) = c around a point: r = R √(1 − c^(2/i)), 0 < c < 1.
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < 1.0)) return std::nullopt;
    return R * std::sqrt(1.0 - std::pow(c, 2.0 / degree));
  }

  // SCALIS (scalis_description.hpp): K(d/σ) = (1 − (d/σ)²)^(i/2), σ > 1.
  static constexpr ScalisSingularity scalis_singularity = ScalisSingularity::none;
  static constexpr bool scalis_segment_generated = false;  ///< scalis_compact_F (primitives/scalis_compact.hpp)
  static constexpr bool scalis_sigma_above_one = true;
  static constexpr double scalis_radius_term = 0.0;  ///< not read: finite support
  static double scalis_line_normalisation(int i, double sigma) {
    return sigma * std::pow(1.0 - 1.0 / (sigma * sigma), (i + 1) / 2.0) * compact_line_integral(i);
  }
  static double scalis_plane_normalisation(int i, double sigma) {
    return 2 * std::numbers::pi * sigma * sigma * std::pow(1.0 - 1.0 / (sigma * sigma), (i + 2) / 2.0) / (i + 2);
  }
  /// k_R^i with R = στ, times 1/τ².
  static ScalisPolygonKernel scalis_polygon_kernel(int i, double sigma, double tau) {
    return {KernelSpec::compact(i, sigma * tau), 1.0 / (tau * tau)};
  }
};

}  // namespace skelconv::kernels
