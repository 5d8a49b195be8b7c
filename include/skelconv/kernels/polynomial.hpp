// skelconv/kernels/polynomial.hpp — the polynomial kernel
//     K(r) = (1 − r²/R²)^k for r < R, 0 beyond,
// k ≥ 1 an integer (JSON "degree") and R > 0 the support radius. It is the
// compact kernel k_R^(2k) of docs/mathematics.md §1 written with the exponent of the
// polynomial itself (k = 2 is the soft kernel, k = 3 the "poly6" kernel of
// smoothed-particle hydrodynamics); a family of its own so that a skeleton
// file says the polynomial it means. Points only (primitives below): a
// segment or polygon of it is the compact one of degree 2k.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"

namespace skelconv::kernels {

struct PolynomialKernel {
  static constexpr KernelFamily family = KernelFamily::polynomial;
  static constexpr std::string_view name = "polynomial";
  static constexpr std::array<std::string_view, 1> parameters{"R"};
  static constexpr bool has_degree = true;  ///< JSON "degree" is k
  /// Points only: the segment and polygon closed forms of (1 − r²/R²)^k are
  /// those of compact degree 2k, reached through the compact family.
  static constexpr unsigned primitives = on_points;
  /// k ≥ 1 keeps dK/dr bounded (k = 1 jumps from −2/R to 0 at r = R, as
  /// compact i = 2 does); k ≤ 8 is compact's i ≤ 16, the same range.
  static constexpr int min_degree = 1, max_degree = 8;
  static constexpr bool singular_at_zero = false;

  int degree = 2;  ///< the exponent k
  double R = 1.0;  ///< support radius, > 0

  /// InputError at "kernel.R" (not finite or ≤ 0) or "kernel.degree"
  /// (outside min_degree..max_degree).
  explicit PolynomialKernel(const KernelSpec& spec) : degree(spec.degree), R(spec.R) {
    require_positive(R, "kernel.R");
    require_degree(name, degree, min_degree, max_degree);
  }

  double support_radius() const { return R; }
  static constexpr bool finite_support = true;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;    ///< 0 from r = R on
  int scaling_power() const { return 0; }       ///< a function of r/R
  double length_scale() const { return R; }
  double max_value() const { return 1.0; }  ///< K(0)
  /// |K'| = 2k u (1 − u²)^(k−1) / R with u = r/R; its derivative in u
  /// vanishes at u² = 1/(2k − 1) (u = 1 for k = 1, where K' = −2u/R).
  double max_slope() const {
    const double k = degree;
    const double u = 1.0 / std::sqrt(2.0 * k - 1.0);
    return 2.0 * k * u * std::pow(1.0 - u * u, k - 1.0) / R;
  }

  /// (1 − r²/R²)^k, exactly 0 from r = R on (the test is on r: compact.hpp).
  template <class T>
  T value(const T& r) const {
    if (!(r < T(R))) return T(0);
    return half_integer_power(T(1) - (r / T(R)) * (r / T(R)), 2 * degree);
  }
  /// −(2k r / R²) (1 − r²/R²)^(k−1) inside, 0 outside.
  template <class T>
  T derivative(const T& r) const {
    if (!(r < T(R))) return T(0);
    return -T(2 * degree) * r / (T(R) * T(R)) * half_integer_power(T(1) - (r / T(R)) * (r / T(R)), 2 * degree - 2);
  }

  /// ρ with K(ρ) = c around a point: R √(1 − c^(1/k)), 0 < c < 1.
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < 1.0)) return std::nullopt;
    return R * std::sqrt(1.0 - std::pow(c, 1.0 / degree));
  }
  /// Distance d with F(d) = c around an infinite line: with h² = R² − d²,
  /// F(d) = ∫ ((h² − t²)/R²)^k dt over |t| < h = B_k h^(2k+1) / R^(2k),
  /// B_k = ∫_−1^1 (1 − x²)^k dx = 2 Π_{j=1..k} 2j/(2j + 1) (B_0 = 2,
  /// B_j = B_(j−1) 2j/(2j + 1), by parts); exists for 0 < c < B_k R = F(0).
  std::optional<double> line_iso_radius(double c) const {
    double beta = 2.0;
    for (int j = 1; j <= degree; ++j) beta *= 2.0 * j / (2.0 * j + 1.0);
    if (!(c > 0.0 && c < beta * R)) return std::nullopt;
    // h^(2k+1) = c R^(2k) / B_k, written as (c / (B_k R))^(1/(2k+1)) R.
    const double h = R * std::pow(c / (beta * R), 1.0 / (2 * degree + 1));
    return std::sqrt(std::max(0.0, R * R - h * h));
  }
};

}  // namespace skelconv::kernels
