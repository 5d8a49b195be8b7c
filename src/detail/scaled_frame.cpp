// Implementation of skelconv/detail/scaled_frame.hpp.
#include "skelconv/detail/scaled_frame.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "input_checks.hpp"
#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

constexpr double smallest_normal = std::numeric_limits<double>::min();

/// Whether 2^n is a normal double.
bool normal_power_of_two(int n) {
  return n >= std::numeric_limits<double>::min_exponent - 1 && n <= std::numeric_limits<double>::max_exponent - 1;
}
/// 2^n for normal_power_of_two(n) (IEEE binary64: biased exponent n + 1023).
double power_of_two(int n) { return std::bit_cast<double>(std::uint64_t(n + 1023) << 52); }

/// x·2^n, the same double as std::ldexp(x, n) (both round the exact product
/// once, to nearest), by one product when 2^n is a normal double: the
/// per-point frame changes then cost a multiplication, not a libm call.
double times_power_of_two(double x, int n) {
  if (!normal_power_of_two(n)) return std::ldexp(x, n);
  return x * power_of_two(n);
}

[[noreturn]] void throw_out_of_range(const char* what, const Vec3& p, double frame_value, int exponent) {
  throw EvaluationError(fmt::format(
      "{} at P = {} is {}, outside the range of double precision (normal doubles are {:g} to {:g}): the field of "
      "this primitive cannot be returned at that point",
      what, detail::format_point(p), format_scaled(frame_value, exponent), smallest_normal,
      std::numeric_limits<double>::max()));
}

}  // namespace

double normal_power_of_two_or_zero(int n) { return normal_power_of_two(n) ? power_of_two(n) : 0.0; }

ScaledFrame::ScaledFrame(double size) : exponent_(std::ilogb(size)) {}

FrameFactors ScaledFrame::factors(int value_power) const {
  return {normal_power_of_two_or_zero(-exponent_), normal_power_of_two_or_zero(value_power * exponent_),
          normal_power_of_two_or_zero((value_power - 1) * exponent_)};
}

Vec3 ScaledFrame::point(const Vec3& x) const {
  // |e| ≤ 1022 for every frame of a normal length: one factor for all three.
  if (normal_power_of_two(-exponent_)) return x * power_of_two(-exponent_);
  return {times_power_of_two(x.x(), -exponent_), times_power_of_two(x.y(), -exponent_),
          times_power_of_two(x.z(), -exponent_)};
}

namespace {

// The cases restore_value and restore_gradient do not settle on their first
// test, out of line: the error messages' formatting stays off the path every
// evaluation takes.
[[gnu::noinline, gnu::cold]] double restore_value_rare(double value, int shift, bool may_vanish, const char* what,
                                                       const Vec3& p, const Vec3& frame_p) {
  if (value == std::numeric_limits<double>::infinity()) return value;
  if (!std::isfinite(value)) {
    throw EvaluationError(fmt::format("{} returned {} at P = {}, where the field is finite: the closed form failed "
                                      "in double precision",
                                      what, value, detail::format_point(p)));
  }
  const double world = times_power_of_two(value, shift);
  if (std::isnormal(value) && std::isnormal(world)) return world;
  if (may_vanish && std::isfinite(world)) return world;
  // A 0 far from the primitive is the closed form's underflow, not the
  // field's value: a Cauchy i = 4 segment at 1e70 lengths has f = 1e-280.
  const double distance = frame_p.cwiseAbs().maxCoeff();
  if (value == 0.0 && distance >= far_frame_distance) {
    throw EvaluationError(fmt::format("{} at P = {} underflows to 0 in its closed form, P being {:.2g} sizes of the "
                                      "primitive from it (the field there can still be a normal double): it cannot "
                                      "be returned at that point",
                                      what, detail::format_point(p), distance));
  }
  throw_out_of_range(what, p, value, shift);
}

[[gnu::noinline, gnu::cold]] Vec3 restore_gradient_rare(const Vec3& gradient, int shift, bool may_vanish,
                                                        const char* what, const Vec3& p, const Vec3& frame_p) {
  const double ax = std::abs(gradient.x()), ay = std::abs(gradient.y()), az = std::abs(gradient.z());
  constexpr double largest_finite = std::numeric_limits<double>::max();
  if (ax <= largest_finite && ay <= largest_finite && az <= largest_finite) {  // false for NaN
    const double largest = std::max({ax, ay, az});
    if (largest >= smallest_normal) {
      const double world_largest = times_power_of_two(largest, shift);
      if (world_largest >= smallest_normal && world_largest <= largest_finite) {
        return {times_power_of_two(gradient.x(), shift), times_power_of_two(gradient.y(), shift),
                times_power_of_two(gradient.z(), shift)};
      }
    }
  }
  if (gradient.allFinite() == false) {
    if ((gradient.array() == std::numeric_limits<double>::infinity()).all()) return gradient;  // singular marker
    throw EvaluationError(fmt::format("{} returned the gradient {} at P = {}, where the field is finite: the closed "
                                      "form failed in double precision",
                                      what, detail::format_point(gradient), detail::format_point(p)));
  }
  const Vec3 world{times_power_of_two(gradient.x(), shift), times_power_of_two(gradient.y(), shift),
                   times_power_of_two(gradient.z(), shift)};
  const double largest = gradient.cwiseAbs().maxCoeff();
  // A kernel that vanishes or underflows far away (compact support, the
  // Gaussian) has a gradient that does too: a 0 or subnormal in the frame is
  // then its value rounded, as restore_value's may_vanish (a Gaussian
  // segment at 27 widths: f = 1e-317, ∇f = 1e-315, then 0; a compact SCALIS
  // segment 1e13 lengths from its support: 0). A normal frame gradient that
  // the scale takes out of the double range is still refused below.
  if (may_vanish && !(largest >= smallest_normal)) return world;
  if (largest == 0.0) {
    // Beyond far_frame_distance the primitive (whose frame
    // coordinates stay below ~1e8, file comment of scaled_frame.hpp) is a
    // speck seen from P, and ∇f points towards it: it is not 0. The closed
    // forms' intermediate powers of the distance underflow there before ∇f
    // does (an inverse i = 3 segment at 1e70 lengths: f = 1e-210, ∇f about
    // 3e-280, computed as 0), so a 0 is refused, never printed.
    if (frame_p.cwiseAbs().maxCoeff() >= far_frame_distance) {
      throw EvaluationError(fmt::format(
          "the gradient of {} at P = {} underflows to 0 in its closed form, P being {:.2g} sizes of the primitive "
          "from it (a gradient there is not 0): it cannot be returned at that point",
          what, detail::format_point(p), frame_p.cwiseAbs().maxCoeff()));
    }
    return world;
  }
  if (!std::isnormal(largest) || !std::isnormal(world.cwiseAbs().maxCoeff())) {
    throw_out_of_range(fmt::format("the gradient of {}", what).c_str(), p, largest, shift);
  }
  return world;
}

}  // namespace

double ScaledFrame::restore_value(double value, int power, bool may_vanish, const char* what, const Vec3& p) const {
  // The common case first: a normal value that stays normal in the world,
  // by one product (the same double as std::ldexp); anything else, the
  // singular marker included, is decided by restore_value_rare.
  const int shift = power * exponent_;
  double world;
  if (restore_value_common(value, normal_power_of_two_or_zero(shift), world)) return world;
  // A compact support's 0 (most terms of a sum of compact primitives, at a
  // point outside their supports) is next: ±0·2^shift is ±0, the answer
  // restore_value_rare gives it, without forming the frame point for it.
  if (value == 0.0 && may_vanish) return value;
  return restore_value_rare(value, shift, may_vanish, what, p, point(p));
}

Vec3 ScaledFrame::restore_gradient(const Vec3& gradient, int power, bool may_vanish, const char* what,
                                   const Vec3& p) const {
  // The common case first: all components finite, the largest a normal
  // double, and so is the largest after the shift (a product by 2^shift
  // scales every component alike, so the largest stays the largest).
  const int shift = power * exponent_;
  Vec3 world;
  if (restore_gradient_common(gradient, normal_power_of_two_or_zero(shift), world)) return world;
  // As restore_value: each ±0 component times 2^shift is itself.
  if (may_vanish && gradient.x() == 0.0 && gradient.y() == 0.0 && gradient.z() == 0.0) return gradient;
  return restore_gradient_rare(gradient, shift, may_vanish, what, p, point(p));
}

std::string format_scaled(double mantissa, int power_of_two) {
  const double as_double = std::ldexp(mantissa, power_of_two);
  if (std::isnormal(as_double) || (as_double == 0.0 && mantissa == 0.0)) return fmt::format("{}", as_double);
  // Beyond the double range: long double reaches 2^±16382 on x86-64; the
  // last line is for a platform where long double is double.
  const long double whole = std::ldexp(static_cast<long double>(mantissa), power_of_two);
  if (std::isfinite(whole) && whole != 0.0L) return fmt::format("{:.17g}", whole);
  return fmt::format("{}·2^{}", mantissa, power_of_two);
}

}  // namespace skelconv
