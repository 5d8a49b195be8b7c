// Implementation of skelconv/scalis_segment.hpp.
#include "skelconv/scalis_segment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "generated/scalis_segment_table.hpp"
#include "convergence_guard.hpp"
#include "input_checks.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/scalis_compact.hpp"
#include "skelconv/segment.hpp"  // Segment::degenerate_length_ratio

namespace skelconv {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

double ScalisSegment::normalisation(KernelFamily family, int degree, double sigma) {
  return kernels::with_trait<kernels::on_scalis>(
      family, [&](auto trait) { return decltype(trait)::type::scalis_line_normalisation(degree, sigma); });
}

std::vector<int> ScalisSegment::supported_degrees(KernelFamily family) {
  std::vector<int> degrees;
  if (family == KernelFamily::compact) {
    for (int i = min_compact_degree; i <= max_compact_degree; ++i) degrees.push_back(i);
    return degrees;
  }
  for (const auto& kernel : generated::scalis_segment_kernels<double>())
    if (kernel.family == family) degrees.push_back(kernel.degree);
  std::sort(degrees.begin(), degrees.end());
  return degrees;
}

ScalisSegment::ScalisSegment(const Vec3& a, const Vec3& b, double tau0, double tau1, const ScalisKernel& kernel,
                             double iso)
    : a_(a), b_(b), kernel_(kernel), iso_(iso) {
  detail::require_finite_point(a, "a");
  detail::require_finite_point(b, "b");
  detail::require_non_degenerate(a, b, Segment::degenerate_length_ratio);
  detail::require_scalis_radius(tau0, 0);
  detail::require_scalis_radius(tau1, 1);
  if (tau0 == 0.0 && tau1 == 0.0) {
    throw InputError("both radii are zero: the SCALIS field of a segment of radius 0 is not defined", "radius");
  }
  detail::require_convolution_family(kernel.family, "scalis_segment");
  detail::require_scalis_sigma(kernel.family, kernel.sigma);
  detail::require_positive_parameter(iso, "iso");

  const std::vector<int> degrees = supported_degrees(kernel.family);
  if (std::find(degrees.begin(), degrees.end(), kernel.degree) == degrees.end()) {
    throw InputError(fmt::format("unsupported degree {} for the SCALIS {} family; supported: {}", kernel.degree,
                                 family_name(kernel.family), detail::format_degree_ranges(degrees)),
                     "kernel.degree");
  }
  if (kernel.family != KernelFamily::compact)
    generated_ = generated::find_scalis_segment_kernel<double>(kernel.family, kernel.degree);

  input_.a = to_array(a);
  input_.b = to_array(b);
  input_.tau0 = tau0;
  input_.tau1 = tau1;
  input_.sigma = kernel.sigma;
  normalisation_ = normalisation(kernel.family, kernel.degree, kernel.sigma);
}

std::string ScalisSegment::evaluator_name() const {
  return generated_ != nullptr ? generated_->name : "scalis_compact_F";
}

bool ScalisSegment::is_divergent_point(const Vec3& p) const {
  const kernels::ScalisSingularity singularity = kernels::with_trait<kernels::on_scalis>(
      kernel_.family, [](auto trait) { return decltype(trait)::type::scalis_singularity; });
  switch (singularity) {
    case kernels::ScalisSingularity::on_segment: {
      // P on the closed segment, exactly (as Segment does).
      const Vec3 ab = b_ - a_;
      const Vec3 ap = p - a_;
      const double projection = ab.dot(ap);
      return ab.cross(ap) == Vec3::Zero() && projection >= 0.0 && projection <= ab.squaredNorm();
    }
    case kernels::ScalisSingularity::at_zero_radius:
      return (input_.tau0 == 0.0 && p == a_) || (input_.tau1 == 0.0 && p == b_);
    case kernels::ScalisSingularity::none:
      return false;  // compact: left to scalis_compact_F
  }
  return false;
}

double ScalisSegment::evaluate(const Vec3& p, bool want_value, std::array<double, 3>* grad) const {
  if (!p.allFinite()) throw InputError(fmt::format("query point must be finite, got {}", detail::format_point(p)));
  if (is_divergent_point(p)) {
    if (grad != nullptr) *grad = {infinity, infinity, infinity};
    return infinity;
  }
  ScalisSegmentInput<double> input = input_;
  input.p = to_array(p);
  const double F = detail::evaluate_converged(evaluator_name(), p, [&] {
    if (generated_ == nullptr) return scalis_compact_F(kernel_.degree, input, grad);
    if (grad == nullptr) return generated_->f(input);
    if (!want_value) {
      *grad = generated_->grad(input);
      return 0.0;
    }
    return generated_->f_and_grad(input, *grad);
  });
  const bool finite = std::isfinite(F) && (grad == nullptr || std::all_of(grad->begin(), grad->end(),
                                                                           [](double g) { return std::isfinite(g); }));
  if (!finite) {
    throw EvaluationError(fmt::format("{} returned a non-finite value at P = {}, where the field is finite: the "
                                      "closed form failed in double precision (the point may be too close to the "
                                      "segment or its line, or the coordinates too large)",
                                      evaluator_name(), detail::format_point(p)));
  }
  return F;
}

double ScalisSegment::value(const Vec3& p) const { return iso_ * evaluate(p, true, nullptr) / normalisation_; }

Vec3 ScalisSegment::gradient(const Vec3& p) const {
  std::array<double, 3> g{};
  evaluate(p, false, &g);
  return iso_ * to_vec3(g) / normalisation_;
}

FieldSample ScalisSegment::value_and_gradient(const Vec3& p) const {
  std::array<double, 3> g{};
  const double F = evaluate(p, true, &g);
  return {iso_ * F / normalisation_, iso_ * to_vec3(g) / normalisation_};
}

}  // namespace skelconv
