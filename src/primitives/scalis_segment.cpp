// Implementation of skelconv/primitives/scalis_segment.hpp.
#include "skelconv/primitives/scalis_segment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "generated/scalis_segment_table.hpp"
#include "../detail/convergence_guard.hpp"
#include "../detail/input_checks.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/scalis_compact.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/segment.hpp"  // Segment::degenerate_length_ratio
#include "../detail/infinity.hpp"

namespace skelconv {
namespace {

}  // namespace

double ScalisSegment::normalisation(KernelFamily family, int degree, double sigma) {
  return kernels::with_trait<kernels::on_scalis>(
      family, [&](auto trait) { return decltype(trait)::type::scalis_line_normalisation(degree, sigma); });
}

std::vector<int> ScalisSegment::supported_degrees(KernelFamily family) {
  std::vector<int> degrees;
  const kernels::FamilyFacts facts = kernels::family_facts(family);
  if (facts.on(kernels::on_scalis) && !facts.scalis_segment_generated) {  // scalis_compact_F's range
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
    : a_(a), b_(b), tau0_(tau0), tau1_(tau1), kernel_(kernel), iso_(iso) {
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
  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  if (facts.scalis_segment_generated) {
    generated_ = generated::find_scalis_segment_kernel<double>(kernel.family, kernel.degree);
    name_ = generated_->name;
  }
  diverges_on_segment_ = facts.scalis_singularity == kernels::ScalisSingularity::on_segment;
  diverges_at_zero_radius_ = facts.scalis_singularity == kernels::ScalisSingularity::at_zero_radius;
  may_vanish_ = facts.finite_support;  // outside its support

  // The segment's frame (skelconv/detail/scaled_frame.hpp): F is scale invariant
  // when the radii scale with the coordinates, so F' = F and ∇F = ∇'F'·2^−e.
  frame_ = ScaledFrame(scale_safe_norm(b - a));
  factors_ = frame_.factors(0);
  input_.a = to_array(frame_.point(a));
  input_.b = to_array(frame_.point(b));
  input_.tau0 = frame_.length(tau0);
  input_.tau1 = frame_.length(tau1);
  input_.sigma = kernel.sigma;
  normalisation_ = normalisation(kernel.family, kernel.degree, kernel.sigma);
  evaluation_normalisation_ = normalisation_;
  if (facts.scale_free) {
    // K(d/σ) = σ^−p K(d) for a kernel without a length of its own (inverse,
    // p = −i: radial_kernel.hpp), and h carries the same σ^−p: σ cancels
    // exactly, so evaluate at σ = 1 (σ^i may be outside the double range).
    input_.sigma = 1.0;
    evaluation_normalisation_ = normalisation(kernel.family, kernel.degree, 1.0);
  }
  field_scale_ = iso_ / evaluation_normalisation_;
  if (generated_ != nullptr) {
    prepared_.resize(generated_->prepared_size);
    generated_->prepare(input_, prepared_.data());
  } else {
    compact_ = std::make_shared<const detail::CompactSegment<double>>(detail::prepare_segment(kernel.degree, input_));
  }
  if (!std::isnormal(evaluation_normalisation_)) {
    throw InputError(fmt::format("the normalisation h of the SCALIS {} kernel of degree {} is {} for sigma = {}, "
                                 "outside the normal range of double precision: choose sigma nearer 1",
                                 family_name(kernel.family), kernel.degree, evaluation_normalisation_, kernel.sigma),
                     "kernel.sigma");
  }
  if (kernel.family == KernelFamily::cauchy) {
    far_rule_ = FarSegmentRule::make_scalis(a, b, kernel.degree, kernel.sigma, tau0, tau1, field_scale_);
  }
}

std::string ScalisSegment::evaluator_name() const { return name_; }

[[gnu::always_inline]] inline bool ScalisSegment::is_divergent_point(const Vec3& p, const Vec3& frame_p) const {
  if (diverges_on_segment_) {
    // P on the closed segment, exactly on the frame's doubles (as Segment does).
    const Vec3 ab = to_vec3(input_.b) - to_vec3(input_.a);
    const Vec3 ap = frame_p - to_vec3(input_.a);
    const double projection = ab.dot(ap);
    return ab.cross(ap) == Vec3::Zero() && projection >= 0.0 && projection <= ab.squaredNorm();
  }
  if (diverges_at_zero_radius_) return (tau0_ == 0.0 && p == a_) || (tau1_ == 0.0 && p == b_);
  return false;  // compact: left to scalis_compact_F
}

[[gnu::always_inline]] inline double ScalisSegment::evaluate(const Vec3& p, bool want_value,
                                                             std::array<double, 3>* grad) const {
  detail::require_finite_query_point(p);
  const Vec3 frame_p = factors_.to_frame != 0.0 ? Vec3(p * factors_.to_frame) : frame_.point(p);
  if (factors_.to_frame > 1.0 && !frame_p.allFinite()) {  // a factor 2^−e ≤ 1 keeps a finite P finite
    throw EvaluationError(fmt::format("P = {} is too far from the SCALIS segment (more than ~2^1000 times its "
                                      "length from the origin): the field is outside the range of double precision",
                                      detail::format_point(p)));
  }
  if (is_divergent_point(p, frame_p)) {
    if (grad != nullptr) *grad = {infinity, infinity, infinity};
    return infinity;
  }
  const std::array<double, 3> point = to_array(frame_p);
  const double F = detail::evaluate_converged(name_, p, [&] {
    if (generated_ == nullptr) return scalis_compact_F(*compact_, point, grad);
    if (grad == nullptr) return generated_->f_at(prepared_.data(), point);
    if (!want_value) {
      *grad = generated_->grad_at(prepared_.data(), point);
      return 0.0;
    }
    return generated_->f_and_grad_at(prepared_.data(), point, *grad);
  });
  // Normalised in the frame, then brought back (F is scale invariant, ∇F
  // has units length^−1); a result outside the double range is an error.
  const double scale = field_scale_;
  if (grad != nullptr) {
    const Vec3 scaled = scale * to_vec3(*grad);
    Vec3 world;
    *grad = to_array(restore_gradient_common(scaled, factors_.gradient, world)
                         ? world
                         : frame_.restore_gradient(scaled, -1, may_vanish_, name_, p));
  }
  if (!want_value) return 0.0;
  double world;
  return restore_value_common(scale * F, factors_.value, world) ? world
                                                                : frame_.restore_value(scale * F, 0, may_vanish_, name_, p);
}

double ScalisSegment::value(const Vec3& p) const { return evaluate(p, true, nullptr); }

Vec3 ScalisSegment::gradient(const Vec3& p) const {
  std::array<double, 3> g{};
  evaluate(p, false, &g);
  return to_vec3(g);
}

FieldSample ScalisSegment::value_and_gradient(const Vec3& p) const {
  std::array<double, 3> g{};
  const double f = evaluate(p, true, &g);
  return {f, to_vec3(g)};
}

}  // namespace skelconv
