// Implementation of skelconv/detail/scaled_frame.hpp.
#include "skelconv/detail/scaled_frame.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "input_checks.hpp"
#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

constexpr double smallest_normal = std::numeric_limits<double>::min();

[[noreturn]] void throw_out_of_range(const char* what, const Vec3& p, double frame_value, int power_of_two) {
  throw EvaluationError(fmt::format(
      "{} at P = {} is {}, outside the range of double precision (normal doubles are {:g} to {:g}): the field of "
      "this primitive cannot be returned at that point",
      what, detail::format_point(p), format_scaled(frame_value, power_of_two), smallest_normal,
      std::numeric_limits<double>::max()));
}

}  // namespace

ScaledFrame::ScaledFrame(double size) : exponent_(std::ilogb(size)) {}

Vec3 ScaledFrame::point(const Vec3& x) const {
  return {std::ldexp(x.x(), -exponent_), std::ldexp(x.y(), -exponent_), std::ldexp(x.z(), -exponent_)};
}

double ScaledFrame::restore_value(double value, int power, bool may_vanish, const char* what, const Vec3& p) const {
  if (value == std::numeric_limits<double>::infinity()) return value;
  if (!std::isfinite(value)) {
    throw EvaluationError(fmt::format("{} returned {} at P = {}, where the field is finite: the closed form failed "
                                      "in double precision",
                                      what, value, detail::format_point(p)));
  }
  const int shift = power * exponent_;
  const double world = std::ldexp(value, shift);
  if (std::isnormal(value) && std::isnormal(world)) return world;
  if (may_vanish && std::isfinite(world)) return world;
  throw_out_of_range(what, p, value, shift);
}

Vec3 ScaledFrame::restore_gradient(const Vec3& gradient, int power, const char* what, const Vec3& p) const {
  if (gradient.allFinite() == false) {
    if ((gradient.array() == std::numeric_limits<double>::infinity()).all()) return gradient;  // singular marker
    throw EvaluationError(fmt::format("{} returned the gradient {} at P = {}, where the field is finite: the closed "
                                      "form failed in double precision",
                                      what, detail::format_point(gradient), detail::format_point(p)));
  }
  const int shift = power * exponent_;
  const Vec3 world{std::ldexp(gradient.x(), shift), std::ldexp(gradient.y(), shift),
                   std::ldexp(gradient.z(), shift)};
  const double largest = gradient.cwiseAbs().maxCoeff();
  if (largest == 0.0) return world;
  if (!std::isnormal(largest) || !std::isnormal(world.cwiseAbs().maxCoeff())) {
    throw_out_of_range(fmt::format("the gradient of {}", what).c_str(), p, largest, shift);
  }
  return world;
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
