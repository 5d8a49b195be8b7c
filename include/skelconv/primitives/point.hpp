// skelconv/primitives/point.hpp — the point primitive: a weighted radial
// kernel around a centre C (Blinn's and Wyvill's "blobs"; the kernels of
// docs/mathematics.md §1 through their traits, skelconv/kernels/).
//
//     f(P) = w K(r),   ∇f(P) = w K'(r) (P − C) / r,   r = |P − C|
//
// in closed form, for any trait and any scalar type (point_field below; the
// class PointPrimitive is its double-precision, validated form).
//
// At the centre (r = 0):
//   - a kernel singular there (inverse: K(0) = +inf) gives value +inf and
//     gradient (+inf, +inf, +inf), the marker the segment and polygon use
//     on their own skeleton (segment.hpp), whatever the weight's sign;
//   - otherwise f = w K(0) and ∇f = 0: the radial field is even in P − C,
//     so its gradient at C is 0 when K'(0) = 0 (Cauchy, compact) and, for a
//     kernel with a corner at 0, 0 is the average of the one-sided slopes.
// Beyond a compact kernel's support (r ≥ R) f = 0 and ∇f = 0 exactly.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"
#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv {

/// f and ∇f on any scalar type.
template <class T>
struct PointFieldSample {
  T value;
  std::array<T, 3> gradient;
};

/// f = w K(|P − C|) and its gradient (file comment), for a kernel trait
/// (skelconv/kernels/radial_kernel.hpp) and any scalar type T.
template <class Kernel, class T>
PointFieldSample<T> point_field(const Kernel& kernel, const std::array<T, 3>& center, const T& weight,
                                const std::array<T, 3>& p) {
  using std::sqrt;
  const std::array<T, 3> d{p[0] - center[0], p[1] - center[1], p[2] - center[2]};
  const T r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (r == T(0)) {
    if constexpr (Kernel::singular_at_zero) {
      const T infinity = std::numeric_limits<T>::infinity();
      return {infinity, {infinity, infinity, infinity}};
    } else {
      return {weight * kernel.value(r), {T(0), T(0), T(0)}};
    }
  }
  const T derivative = weight * kernel.derivative(r);  // w K'(r)
  const T slope = derivative / r;
  if constexpr (std::is_floating_point_v<T>) {
    // Far from the centre w K'(r)/r underflows before w K'(r) (P − C)/r does
    // (an inverse i = 3 point at r = 1e70: K' = −3e-280, K'/r = −3e-350):
    // there the unit vector is formed first, so that ∇f keeps its digits.
    if (derivative != T(0) && std::abs(slope) < std::numeric_limits<T>::min())
      return {weight * kernel.value(r), {derivative * (d[0] / r), derivative * (d[1] / r), derivative * (d[2] / r)}};
  }
  return {weight * kernel.value(r), {slope * d[0], slope * d[1], slope * d[2]}};
}

class PointPrimitive {
 public:
  /// Validates everything; throws InputError naming the field ("center",
  /// "weight", "kernel.degree", "kernel.s", "kernel.R"). `weight` must be
  /// finite and non-zero (a zero weight would contribute nothing).
  PointPrimitive(const Vec3& center, const KernelSpec& kernel, double weight = 1.0);

  const Vec3& center() const { return center_; }
  double weight() const { return weight_; }
  const KernelSpec& kernel() const { return kernel_; }
  const kernels::RadialKernel& radial_kernel() const { return radial_; }
  /// R for a compact kernel, +inf otherwise.
  double support_radius() const { return kernels::support_radius(radial_); }

  /// f(P), ∇f(P). Throws InputError if P is not finite, EvaluationError if
  /// a finite field overflows double (P within ~1e-20 of an inverse
  /// point's centre, for instance).
  double value(const Vec3& p) const { return value_and_gradient(p).value; }
  Vec3 gradient(const Vec3& p) const { return value_and_gradient(p).gradient; }
  FieldSample value_and_gradient(const Vec3& p) const;

 private:
  Vec3 center_;
  KernelSpec kernel_;
  kernels::RadialKernel radial_;
  double weight_ = 1.0;
};

}  // namespace skelconv
