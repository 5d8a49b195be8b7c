// skelconv/detail/scaled_frame.hpp — a primitive-relative frame scaled by a power
// of two, so that every primitive is evaluated at unit size whatever its
// position and size (any scale, never silently wrong).
//
// A primitive of size L (any L that is a positive normal double, at
// coordinates anywhere from 1e-150 to 1e150) is evaluated in the frame
//
//     x' = x · 2^−e,      e = ilogb(L)   (so L' = L 2^−e ∈ [1, 2)),
//
// where its squared lengths and the powers the closed forms take (|AB|^16,
// s|AB|², …) can neither overflow nor underflow. The scaling is exact
// (std::ldexp), and it commutes with every rounding of the closed forms
// (each operation's result just scales by a power of two), so inside the
// double range the frame gives bit-for-bit the old results, scaled. There is
// no translation: the degeneracy rules (Segment::degenerate_length_ratio,
// the polygon's edges) bound every coordinate of a valid primitive by 1e8 L,
// so its frame coordinates stay below ~1e8, and a translation would round
// each difference twice (x − O, then the closed form's own differences).
// A query point P farther than ~2^1000 L from the origin overflows in the
// frame, where the field is far outside the double range anyway.
//
// The field is brought back by the kernel's homogeneity (docs/mathematics.md §1–4): a
// quantity with units length^m is q' = q·2^(−m e) in the frame (the kernel
// parameters too: the Cauchy s has m = −2, s' = s·2^(2e); R has m = 1), and
// f = f'·2^(m e). The value power m of f:
//
//     segment  inverse p^i: m = 1 − i;   cauchy, compact: m = 1
//     polygon  inverse p^i: m = 2 − i;   cauchy, compact: m = 2
//     SCALIS   m = 0 (F is scale invariant when the radii scale too)
//
// and the gradient power is the value power minus one. Restoring is exact
// (std::ldexp) when the result is a normal double. Where it is not, the
// field of the given primitive at P is outside the double range (or lost
// below it in the frame) and cannot be returned: restore() throws
// EvaluationError naming the value as m·2^k, never a wrong number.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "skelconv/geometry.hpp"

namespace skelconv {

/// A frame point farther than this (2^40, about 1e12 sizes of the primitive,
/// whose own frame coordinates stay below ~1e8) is far from the primitive:
/// ∇f there is never exactly 0, and a 0 from the closed form (f or ∇f) is
/// its underflow, reported as such (ScaledFrame::restore_value,
/// restore_gradient).
inline constexpr double far_frame_distance = 0x1p40;

/// 2^n when that is a normal double (−1022 ≤ n ≤ 1023), else 0.
double normal_power_of_two_or_zero(int n);

/// A primitive's frame factors for a field of value power m, computed once
/// per primitive (ScaledFrame::factors), so that an evaluation scales by
/// products alone. A factor that is not a normal double is 0: the primitive
/// then takes ScaledFrame's careful functions, which handle every case.
struct FrameFactors {
  double to_frame = 0;  ///< 2^−e: ScaledFrame::point is P·to_frame
  double value = 0;     ///< 2^(m e): restore_value's product
  double gradient = 0;  ///< 2^((m − 1) e): restore_gradient's product
};

/// restore_value's common case: f' and f'·factor both normal doubles (a
/// factor of 0 never is). Sets `world` and returns true there; false sends
/// the caller to ScaledFrame::restore_value, which decides every other case.
inline bool restore_value_common(double value, double factor, double& world) {
  world = value * factor;
  return std::isnormal(value) && std::isnormal(world);
}

/// restore_gradient's common case: every component finite, the largest a
/// normal double, and still one after the product (a product by a power of
/// two scales every component alike, so the largest stays the largest).
inline bool restore_gradient_common(const Vec3& gradient, double factor, Vec3& world) {
  constexpr double largest_finite = std::numeric_limits<double>::max();
  constexpr double smallest_normal = std::numeric_limits<double>::min();
  const double ax = std::abs(gradient.x()), ay = std::abs(gradient.y()), az = std::abs(gradient.z());
  // (false for NaN)
  if (!(ax <= largest_finite && ay <= largest_finite && az <= largest_finite) || factor == 0.0) return false;
  const double largest = std::max({ax, ay, az});
  const double world_largest = largest * factor;
  world = gradient * factor;
  return largest >= smallest_normal && world_largest >= smallest_normal && world_largest <= largest_finite;
}

/// x' = x · 2^−exponent (see the file comment).
class ScaledFrame {
 public:
  ScaledFrame() = default;
  /// The frame in which a length `size` (> 0, finite) becomes size·2^−e ∈ [1, 2).
  explicit ScaledFrame(double size);

  /// e: a length l of the world is l·2^−e in the frame.
  int exponent() const { return exponent_; }

  /// The factors of a field of value power `value_power` (file comment).
  FrameFactors factors(int value_power) const;

  /// A point (or vector) of the world in the frame: x·2^−e componentwise.
  /// Not finite when it overflows (P ≳ 2^1000 sizes away).
  Vec3 point(const Vec3& x) const;
  /// A length of the world in the frame: l·2^−e.
  double length(double l) const { return std::ldexp(l, -exponent_); }
  /// A quantity of the world with units length^power, in the frame:
  /// q·2^(−power·e) (e.g. power −2 for the Cauchy sharpness s).
  double scaled(double q, int power) const { return std::ldexp(q, -power * exponent_); }

  /// A frame value f' of a quantity with units length^power (the value
  /// power of the file comment) back in the world: f'·2^(power·e).
  /// +inf (the singular marker) stays +inf. Throws EvaluationError, naming
  /// `what` and P, when f' is not finite, or when f' or the world value is
  /// not a normal double (0, subnormal: digits lost; or overflow) — unless
  /// `may_vanish` (a field that can be 0 or tiny: compact support, signed
  /// weights), where a finite 0 or subnormal value is returned as it is.
  double restore_value(double value, int power, bool may_vanish, const char* what, const Vec3& p) const;
  /// A frame gradient back in the world: g'·2^(power·e) componentwise. The
  /// largest component must come back a normal double (or all be 0, but
  /// not at a P farther than far_frame_distance in the frame: an
  /// underflow there); the others may underflow (they are below 2^−1022 of
  /// |∇f| relative to it). With `may_vanish` (a kernel that is 0 or
  /// underflows far away: compact support, the Gaussian) a frame gradient
  /// that is 0 or subnormal is returned as it is.
  Vec3 restore_gradient(const Vec3& gradient, int power, bool may_vanish, const char* what, const Vec3& p) const;

 private:
  int exponent_ = 0;
};

/// "1.2345678901234567e-400": m·2^k printed in decimal even where it is
/// beyond the double range (for messages: lengths, areas and values of
/// primitives scaled far from 1).
std::string format_scaled(double mantissa, int power_of_two);

/// |v| without overflow or underflow of the squares (std::hypot), for
/// checks and messages at any scale. Overflows only when |v| itself does.
inline double scale_safe_norm(const Vec3& v) { return std::hypot(v.x(), v.y(), v.z()); }

}  // namespace skelconv
