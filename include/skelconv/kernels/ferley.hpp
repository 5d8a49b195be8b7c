// skelconv/kernels/ferley.hpp — the piecewise kernel of Ferley 1996 §1.1.1
// (his figure 1.5, right), a function of r (not r²):
//     K(r) = 1 + k (e − r)            for r < e,
//            (r − R)² / (e − R)²      for e ≤ r < R,
//            0                        beyond,
// e the coating thickness (K(e) = 1: the iso-1 surface of a point is at
// distance e), R the support radius, 0 < e < R. The text leaves the slope k
// free; here k = 2/(R − e), the one value that makes K C¹ at r = e (the outer
// piece has slope 2/(e − R) there). K(0) = (R + e)/(R − e); K decreases on
// [0, R). Point primitives only (kernel_list.hpp): K is not a function of r²,
// so the polynomial segment closed forms do not apply.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "skelconv/kernels/radial_kernel.hpp"

namespace skelconv::kernels {

struct FerleyKernel {
  static constexpr KernelFamily family = KernelFamily::ferley;
  static constexpr std::string_view name = "ferley";
  static constexpr std::array<std::string_view, 2> parameters{"e", "R"};
  static constexpr bool has_degree = false;
  /// Points only: K is a function of r, not of r², so the segment integral
  /// ∫ K(√(h² + u²)) du has pieces like ∫ √(h² + u²) du (asinh terms) whose
  /// closed form is not implemented (file comment).
  static constexpr unsigned primitives = on_points;
  static constexpr int min_degree = 0, max_degree = 0;  ///< no degree
  static constexpr bool singular_at_zero = false;

  double e = 0.5;  ///< coating thickness, 0 < e < R
  double R = 1.0;  ///< support radius

  /// InputError at "kernel.e" (not finite or ≤ 0) or "kernel.R" (≤ e).
  explicit FerleyKernel(const KernelSpec& spec);

  double support_radius() const { return R; }
  static constexpr bool finite_support = true;  ///< support_radius() is finite
  static constexpr bool vanishes_far = true;  ///< 0 from r = R on
  int scaling_power() const { return 0; }     ///< a function of r/R and e/R
  double length_scale() const { return R; }
  /// K(0) = 1 + k e = (R + e)/(R − e), written so (file comment).
  double max_value() const { return (R + e) / (R - e); }
  /// k = 2/(R − e) on r < e, 2(R − r)/(R − e)² ≤ k beyond.
  double max_slope() const { return 2.0 / (R - e); }
  /// The C¹ slope k = 2/(R − e) (file comment).
  double slope() const { return 2.0 / (R - e); }

  template <class T>
  T value(const T& r) const {
    if (!(r < T(R))) return T(0);
    if (r < T(e)) return T(1) + T(slope()) * (T(e) - r);
    const T x = (r - T(R)) / T(e - R);
    return x * x;
  }
  /// −k inside e, 2 (r − R)/(e − R)² between e and R, 0 beyond.
  template <class T>
  T derivative(const T& r) const {
    if (!(r < T(R))) return T(0);
    if (r < T(e)) return T(-slope());
    return T(2) * (r - T(R)) / (T(e - R) * T(e - R));
  }

  /// ρ with K(ρ) = c around a point, 0 < c < K(0): e − (c − 1)/k for c ≥ 1,
  /// R − √c (R − e) below.
  std::optional<double> point_iso_radius(double c) const {
    if (!(c > 0.0 && c < (R + e) / (R - e))) return std::nullopt;
    if (c >= 1.0) return e - (c - 1.0) / slope();
    return R - std::sqrt(c) * (R - e);
  }
  // No line_iso_radius: the line integral of this kernel of r (not r²)
  // involves asinh terms and was not derived (docs/field.md).
};

}  // namespace skelconv::kernels
