// Implementation of skelconv/primitives/point.hpp.
#include "skelconv/primitives/point.hpp"

#include <fmt/format.h>

#include "../detail/input_checks.hpp"
#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv {

PointPrimitive::PointPrimitive(const Vec3& center, const KernelSpec& kernel, double weight)
    : center_(center), kernel_(kernel), radial_(kernels::make_radial_kernel(kernel)), weight_(weight) {
  detail::require_finite_point(center, "center");
  if (!std::isfinite(weight)) throw InputError(fmt::format("must be finite, got {}", weight), "weight");
  if (weight == 0.0) throw InputError("must be non-zero: the primitive would contribute nothing", "weight");
}

FieldSample PointPrimitive::value_and_gradient(const Vec3& p) const {
  detail::require_finite_query_point(p);
  if ((p - center_).norm() >= support_radius()) return {0.0, Vec3::Zero()};
  const PointFieldSample<double> sample = std::visit(
      [&](const auto& kernel) { return point_field(kernel, to_array(center_), weight_, to_array(p)); }, radial_);
  const FieldSample result{sample.value, to_vec3(sample.gradient)};
  const bool at_singular_centre = p == center_ && std::isinf(sample.value);
  if (!at_singular_centre && !(std::isfinite(result.value) && result.gradient.allFinite())) {
    throw EvaluationError(fmt::format("the point field overflowed double precision at P = {}, {} from its centre",
                                      detail::format_point(p), (p - center_).norm()));
  }
  // A kernel that neither vanishes nor underflows far away by design
  // (inverse, Cauchy: powers of r) is positive at every r, so a 0 or
  // subnormal off the centre is f outside the double range (an inverse
  // i = 16 point at r = 1e25: f = 1e-400, which printed 0 0 0 0), refused
  // as a segment refuses it (scaled_frame.hpp); so is a subnormal ∇f (at
  // r = 1e19, f = 1e-304 but ∇f = −1.6e-322, two digits).
  if (p != center_ && !kernels::family_facts(kernel_.family).vanishes_far) {
    const double largest_slope = result.gradient.cwiseAbs().maxCoeff();
    const bool value_out = !std::isnormal(result.value);
    if (value_out || (largest_slope != 0.0 && !std::isnormal(largest_slope))) {
      throw EvaluationError(fmt::format("{}the point field at P = {}, {} from its centre, is {}, outside the range of "
                                        "double precision (normal doubles are {:g} to {:g}): it cannot be returned "
                                        "at that point",
                                        value_out ? "" : "the gradient of ", detail::format_point(p),
                                        (p - center_).norm(), value_out ? result.value : largest_slope,
                                        std::numeric_limits<double>::min(), std::numeric_limits<double>::max()));
    }
  }
  // Off the centre, inside the support, ∇f = w K'(r) (P − C)/r is not 0
  // where f is not: a 0 is an underflow of K' (a Cauchy point at r = 1.4e100:
  // K' about −7e-301, computed through (1 + s r²)^−2 = 0), refused as the
  // frame of a segment or a polygon refuses it (scaled_frame.hpp).
  if (p != center_ && result.value != 0.0 && result.gradient == Vec3::Zero()) {
    throw EvaluationError(fmt::format("the gradient of the point field at P = {}, {} from its centre, underflows to "
                                      "0 in double precision (f = {}): it cannot be returned at that point",
                                      detail::format_point(p), (p - center_).norm(), result.value));
  }
  return result;
}

}  // namespace skelconv
