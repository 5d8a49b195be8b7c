// Implementation of skelconv/segment.hpp.
#include "skelconv/segment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "skelconv/derived_segment_kernels.hpp"
#include "convergence_guard.hpp"
#include "input_checks.hpp"
#include "skelconv/clip.hpp"

namespace skelconv {
namespace {

using detail::format_degree_ranges;
using detail::format_point;

constexpr double infinity = std::numeric_limits<double>::infinity();

/// Degree of w(t) = Σ w_k t^k after dropping trailing zero coefficients.
int validated_weight_degree(std::span<const double> weight) {
  if (weight.empty()) throw InputError("needs at least one coefficient", "weight");
  if (weight.size() > Segment::max_weight_coefficients) {
    throw InputError(fmt::format("at most {} coefficients (w(t) of degree <= {}), got {}",
                                 Segment::max_weight_coefficients, max_weight_degree, weight.size()),
                     "weight");
  }
  int degree = -1;
  for (std::size_t k = 0; k < weight.size(); ++k) {
    if (!std::isfinite(weight[k])) {
      throw InputError(fmt::format("must be finite, got {}", weight[k]), fmt::format("weight[{}]", k));
    }
    if (weight[k] != 0.0) degree = int(k);
  }
  if (degree < 0) throw InputError("all coefficients are zero: the primitive would contribute nothing", "weight");
  return degree;
}

}  // namespace

Segment::Segment(const Vec3& a, const Vec3& b, const KernelSpec& kernel, std::span<const double> weight)
    : a_(a), b_(b), kernel_(kernel) {
  detail::require_finite_point(a, "a");
  detail::require_finite_point(b, "b");
  detail::require_non_degenerate(a, b, degenerate_length_ratio);
  weight_degree_ = validated_weight_degree(weight);
  detail::require_convolution_family(kernel.family, "segment");
  detail::require_valid_kernel_parameter(kernel);

  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  generated_ = find_any_segment_kernel<double>(kernel.family, kernel.degree, weight_degree_);
  if (generated_ == nullptr) {
    const std::string family = std::string(family_name(kernel.family));
    throw InputError(
        weight_degree_ == 0
            ? fmt::format("unsupported degree {} for the {} family; supported: {}", kernel.degree, family,
                          format_degree_ranges(supported_degrees(kernel.family, 0)))
            : fmt::format("unsupported degree {} for the {} family with a weight of degree {}; supported: {}",
                          kernel.degree, family, weight_degree_,
                          format_degree_ranges(supported_degrees(kernel.family, weight_degree_))),
        "kernel.degree");
  }

  input_.a = to_array(a);
  input_.b = to_array(b);
  input_.w = {0.0, 0.0, 0.0, 0.0};
  for (int k = 0; k <= weight_degree_; ++k) input_.w[std::size_t(k)] = weight[std::size_t(k)];
  input_.s = kernel.s;
  input_.R = kernel.R;
  input_.gaussian_a = kernel.a;
  input_.gaussian_b = kernel.b;
  support_radius_ = kernels::support_radius(kernels::make_radial_kernel(kernel));
  singular_at_zero_ = facts.singular_at_zero;
}

std::string Segment::generated_name() const { return generated_->name; }

std::vector<int> Segment::supported_degrees(KernelFamily family, int weight_degree) {
  std::vector<int> degrees;
  if (!kernels::family_facts(family).has_degree) return degrees;  // no degree (derived_segment_kernels.hpp)
  for (const auto& kernel : generated::segment_kernels<double>()) {
    if (kernel.family == family && kernel.weight_degree == weight_degree) degrees.push_back(kernel.degree);
  }
  std::sort(degrees.begin(), degrees.end());
  return degrees;
}

Segment::Case Segment::prepare(const Vec3& p, SegmentInput<double>& input) const {
  detail::require_finite_query_point(p);
  input = input_;
  input.p = to_array(p);

  if (singular_at_zero_) {
    // Exact test on the doubles (see the file comment of segment.hpp).
    const Vec3 ab = b_ - a_;
    const Vec3 ap = p - a_;
    const double projection = ab.dot(ap);  // t |AB|²
    if (ab.cross(ap) == Vec3::Zero() && projection >= 0.0 && projection <= ab.squaredNorm()) {
      return Case::on_inverse_singularity;
    }
  }
  if (std::isfinite(support_radius_)) {
    // Hubert 2012 §3.4: only the part of [A,B] inside the ball of radius R
    // around P contributes; the generated code integrates over [t0, t1].
    const std::optional<ParameterInterval<double>> inside = clip_to_ball(input.a, input.b, input.p, support_radius_);
    if (!inside) return Case::outside_compact_support;
    input.t0 = inside->t0;
    input.t1 = inside->t1;
  }
  return Case::call_generated;
}

void Segment::require_finite(std::initializer_list<double> results, const Vec3& p) const {
  for (double x : results) {
    if (!std::isfinite(x)) {
      throw EvaluationError(fmt::format("{} returned {} at P = {}, where the field is finite: the closed form "
                                        "failed in double precision (the point may be too close to the segment "
                                        "or its line, or the coordinates too large)",
                                        generated_->name, x, format_point(p)));
    }
  }
}

double Segment::value(const Vec3& p) const {
  SegmentInput<double> input;
  switch (prepare(p, input)) {
    case Case::outside_compact_support: return 0.0;
    case Case::on_inverse_singularity: return infinity;
    case Case::call_generated: break;
  }
  const double f = detail::evaluate_converged(generated_->name, p, [&] { return generated_->f(input); });
  require_finite({f}, p);
  return f;
}

Vec3 Segment::gradient(const Vec3& p) const {
  SegmentInput<double> input;
  switch (prepare(p, input)) {
    case Case::outside_compact_support: return Vec3::Zero();
    case Case::on_inverse_singularity: return Vec3::Constant(infinity);
    case Case::call_generated: break;
  }
  const std::array<double, 3> g = detail::evaluate_converged(generated_->name, p, [&] { return generated_->grad(input); });
  require_finite({g[0], g[1], g[2]}, p);
  return to_vec3(g);
}

FieldSample Segment::value_and_gradient(const Vec3& p) const {
  SegmentInput<double> input;
  switch (prepare(p, input)) {
    case Case::outside_compact_support: return {0.0, Vec3::Zero()};
    case Case::on_inverse_singularity: return {infinity, Vec3::Constant(infinity)};
    case Case::call_generated: break;
  }
  std::array<double, 3> g{};
  const double f = detail::evaluate_converged(generated_->name, p, [&] { return generated_->f_and_grad(input, g); });
  require_finite({f, g[0], g[1], g[2]}, p);
  return {f, to_vec3(g)};
}

}  // namespace skelconv
