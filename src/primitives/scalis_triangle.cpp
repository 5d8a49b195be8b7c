// Implementation of skelconv/primitives/scalis_triangle.hpp.
#include "skelconv/primitives/scalis_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "../detail/input_checks.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "scalis_triangle_quadrature.hpp"
#include "../detail/infinity.hpp"

namespace skelconv {
namespace {

void require_supported_degree(const ScalisKernel& kernel) {
  const std::vector<int> degrees = ScalisTriangle::supported_degrees(kernel.family);
  if (std::find(degrees.begin(), degrees.end(), kernel.degree) != degrees.end()) return;
  const std::string family(family_name(kernel.family));
  if (!kernels::family_facts(kernel.family).finite_support && kernel.degree == 2) {
    throw InputError(fmt::format("degree 2 of the SCALIS {} family is not available on a triangle: its "
                                 "normalisation h = ∬ K(√(1 + |u|²)) du over the plane diverges (K ~ d^-2); "
                                 "supported: {}",
                                 family, detail::format_degree_ranges(degrees)),
                     "kernel.degree");
  }
  throw InputError(fmt::format("unsupported degree {} for the SCALIS {} family on a triangle; supported: {}",
                               kernel.degree, family, detail::format_degree_ranges(degrees)),
                   "kernel.degree");
}

/// Whether the polygon closed forms offer this kernel (for constant radius).
bool polygon_offers(const ScalisKernel& kernel) {
  const std::vector<int> degrees = Polygon::supported_degrees(kernel.family);
  return std::find(degrees.begin(), degrees.end(), kernel.degree) != degrees.end();
}

}  // namespace

double ScalisTriangle::normalisation(KernelFamily family, int degree, double sigma) {
  return kernels::with_trait<kernels::on_scalis>(
      family, [&](auto trait) { return decltype(trait)::type::scalis_plane_normalisation(degree, sigma); });
}

std::vector<int> ScalisTriangle::supported_degrees(KernelFamily family) {
  std::vector<int> degrees;
  // The plane normalisation diverges for i ≤ 2 unless the support is finite
  // (require_plane_degree).
  const kernels::FamilyFacts facts = kernels::family_facts(family);
  const int min = facts.on(kernels::on_scalis) && facts.finite_support ? min_compact_degree : min_degree;
  for (int i = min; i <= max_degree; ++i) degrees.push_back(i);
  return degrees;
}

ScalisTriangle::ScalisTriangle(const std::array<Vec3, 3>& vertices, const std::array<double, 3>& radii,
                               const ScalisKernel& kernel, double iso)
    : vertices_(vertices), radii_(radii), kernel_(kernel), iso_(iso) {
  // The geometry as a polygon: finite vertices, no repeated vertex or
  // degenerate edge, non-zero area, with Polygon's messages. (The kernel
  // given here is only a placeholder the check needs.)
  (void)Polygon(std::span<const Vec3>(vertices.data(), 3), KernelSpec::inverse(3));
  for (int k = 0; k < 3; ++k) detail::require_scalis_radius(radii[k], k);
  if (radii[0] == 0.0 && radii[1] == 0.0 && radii[2] == 0.0) {
    throw InputError("all three radii are zero: the SCALIS field of a triangle of radius 0 is not defined", "radius");
  }
  detail::require_convolution_family(kernel.family, "scalis_triangle");
  detail::require_scalis_sigma(kernel.family, kernel.sigma);
  detail::require_positive_parameter(iso, "iso");
  require_supported_degree(kernel);
  normalisation_ = normalisation(kernel.family, kernel.degree, kernel.sigma);
  may_vanish_ = kernels::family_facts(kernel.family).finite_support;  // outside its support

  // The triangle's frame (skelconv/detail/scaled_frame.hpp): coordinates and radii
  // scaled by the power of two that brings the diameter into [1, 2);
  // F is scale invariant, so both paths run there.
  double diameter = 0.0;
  for (int k = 0; k < 3; ++k) diameter = std::max(diameter, scale_safe_norm(vertices[(k + 1) % 3] - vertices[k]));
  frame_ = ScaledFrame(diameter);
  factors_ = frame_.factors(0);
  for (int k = 0; k < 3; ++k) {
    local_vertices_[k] = frame_.point(vertices[k]);
    local_radii_[k] = frame_.length(radii[k]);
  }
  if (!std::isnormal(normalisation_)) {
    throw InputError(fmt::format("the normalisation h of the SCALIS {} kernel of degree {} on a triangle is {} for "
                                 "sigma = {}, outside the normal range of double precision: choose sigma nearer 1",
                                 family_name(kernel.family), kernel.degree, normalisation_, kernel.sigma),
                     "kernel.sigma");
  }

  if (radii[0] == radii[1] && radii[1] == radii[2] && polygon_offers(kernel)) {
    // Scale by 2^−e so that τ' = τ 2^−e ∈ [1/2, 1): s = 1/(σ²τ'²) and R = στ'
    // stay representable whatever τ is; F is scale invariant.
    int exponent = 0;
    (void)std::frexp(local_radii_[0], &exponent);
    closed_form_scale_ = std::ldexp(1.0, -exponent);
    const double tau = std::ldexp(local_radii_[0], -exponent);
    const kernels::ScalisPolygonKernel classical = kernels::with_trait<kernels::on_scalis>(
        kernel.family,
        [&](auto trait) { return decltype(trait)::type::scalis_polygon_kernel(kernel.degree, kernel.sigma, tau); });
    closed_form_factor_ = classical.factor;
    std::array<Vec3, 3> scaled;
    for (int k = 0; k < 3; ++k) scaled[k] = local_vertices_[k] * closed_form_scale_;
    closed_form_.emplace(std::span<const Vec3>(scaled.data(), 3), classical.kernel);
  }
}

double ScalisTriangle::closed(const Vec3& p, const Vec3& frame_p, Vec3* grad) const {
  const Vec3 scaled = frame_p * closed_form_scale_;
  try {
    if (grad == nullptr) return closed_form_factor_ * closed_form_->value(scaled);
    const FieldSample c = closed_form_->value_and_gradient(scaled);
    *grad = closed_form_factor_ * closed_form_scale_ * c.gradient;
    return closed_form_factor_ * c.value;
  } catch (const EvaluationError& e) {
    throw EvaluationError(fmt::format("constant-radius SCALIS triangle at P = {}: {}", detail::format_point(p),
                                      e.what()));
  }
}

double ScalisTriangle::numerical(const Vec3& p, const Vec3& frame_p, Vec3* grad) const {
  const detail::ScalisTriangleIntegral r =
      detail::integrate_scalis_triangle(local_vertices_, local_radii_, kernel_.family, kernel_.degree, kernel_.sigma,
                                        frame_p, grad != nullptr, requested_tolerance);
  if (r.divergent) {
    if (grad != nullptr) *grad = Vec3::Constant(infinity);
    return infinity;
  }
  const bool finite = std::isfinite(r.F) && std::isfinite(r.F_error) &&
                      (grad == nullptr || (r.gradient.allFinite() && std::isfinite(r.gradient_error)));
  if (!finite) {
    throw EvaluationError(fmt::format("numerical integration of the SCALIS triangle gave a non-finite value at "
                                      "P = {}, where the field is finite (the point may be too close to the "
                                      "triangle, or the coordinates too large)",
                                      detail::format_point(p)));
  }
  // The scales the errors are certified against (absolute_floor, header).
  const double F_scale = std::max(std::abs(r.F), absolute_floor * normalisation_);
  const double largest_radius = std::max({radii_[0], radii_[1], radii_[2]});
  const double gradient_scale = std::max(r.gradient_scale, absolute_floor * normalisation_ / largest_radius);
  const bool F_ok = r.F_error <= certified_tolerance * F_scale;
  const bool gradient_ok = grad == nullptr || r.gradient_error <= certified_tolerance * gradient_scale;
  if (!F_ok || !gradient_ok) {
    throw EvaluationError(fmt::format("numerical integration could not reach {} relative error at P = {}: "
                                      "estimated error of F {:.3g} (F = {:.17g}, scale {:.3g}){} after {} "
                                      "evaluations",
                                      certified_tolerance, detail::format_point(p), r.F_error, r.F, F_scale,
                                      grad == nullptr ? std::string()
                                                      : fmt::format(", of the gradient {:.3g} (scale {:.3g})",
                                                                    r.gradient_error, gradient_scale),
                                      r.evaluations));
  }
  if (grad != nullptr) *grad = r.gradient;
  return r.F;
}

Vec3 ScalisTriangle::frame_point(const Vec3& p) const {
  detail::require_finite_query_point(p);
  // One product by 2^−e where that is a normal double: frame_.point's own fast path.
  const Vec3 frame_p = factors_.to_frame != 0.0 ? Vec3(p * factors_.to_frame) : frame_.point(p);
  if (!frame_p.allFinite()) {
    throw EvaluationError(fmt::format("P = {} is too far from the SCALIS triangle (more than ~2^1000 times its "
                                      "diameter from the origin): the field is outside the range of double precision",
                                      detail::format_point(p)));
  }
  return frame_p;
}

FieldSample ScalisTriangle::restore(double F, const Vec3* grad, const Vec3& p) const {
  // f = iso·F/h is scale invariant, ∇f has units length^−1 (scaled_frame.hpp).
  const char* what = uses_closed_form() ? "the constant-radius SCALIS triangle" : "the SCALIS triangle";
  const double scale = iso_ / normalisation_;
  FieldSample sample;
  // frame_.restore_value's and restore_gradient's common cases first, with the factors computed once.
  if (!restore_value_common(scale * F, factors_.value, sample.value))
    sample.value = frame_.restore_value(scale * F, 0, may_vanish_, what, p);
  if (grad != nullptr && !restore_gradient_common(scale * *grad, factors_.gradient, sample.gradient))
    sample.gradient = frame_.restore_gradient(scale * *grad, -1, may_vanish_, what, p);
  return sample;
}

double ScalisTriangle::value(const Vec3& p) const {
  const Vec3 q = frame_point(p);
  return restore(uses_closed_form() ? closed(p, q, nullptr) : numerical(p, q, nullptr), nullptr, p).value;
}

Vec3 ScalisTriangle::gradient(const Vec3& p) const { return value_and_gradient(p).gradient; }

FieldSample ScalisTriangle::value_and_gradient(const Vec3& p) const {
  const Vec3 q = frame_point(p);
  Vec3 g;
  const double F = uses_closed_form() ? closed(p, q, &g) : numerical(p, q, &g);
  return restore(F, &g, p);
}

FieldSample ScalisTriangle::numerical_value_and_gradient(const Vec3& p) const {
  const Vec3 q = frame_point(p);
  Vec3 g;
  const double F = numerical(p, q, &g);
  return restore(F, &g, p);
}

}  // namespace skelconv
