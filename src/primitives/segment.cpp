// Implementation of skelconv/primitives/segment.hpp.
#include "skelconv/primitives/segment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "skelconv/kernels/segment_kernel_tables.hpp"
#include "../detail/convergence_guard.hpp"
#include "../detail/input_checks.hpp"
#include "skelconv/detail/clip.hpp"
#include "reversed_segment.hpp"
#include "../detail/infinity.hpp"

namespace skelconv {
namespace {

using detail::format_degree_ranges;
using detail::format_point;

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

/// A length parameter of the kernel, in the segment's frame: a normal
/// double, or InputError at its key (s, a have units length^−2, R length
/// and a range of its own; b has none and is not scaled).
void require_parameter_in_frame(std::string_view key, const SegmentInput<double>& input) {
  struct Scaled {
    std::string_view key;
    double SegmentInput<double>::* field;
    const char* description;
    const char* where;
  };
  static constexpr Scaled scaled[] = {
      {"s", &SegmentInput<double>::s, "s in units of the segment's length (s·4^e, 2^e <= |b - a| < 2^(e+1))",
       "kernel.s"},
      {"a", &SegmentInput<double>::gaussian_a,
       "a in units of the segment's length (a·4^e, 2^e <= |b - a| < 2^(e+1))", "kernel.a"},
  };
  for (const Scaled& p : scaled) {
    if (p.key == key) detail::require_normal_in_frame(input.*p.field, p.description, p.where);
  }
  if (key == "R") detail::require_support_radius_in_frame(input.R, "segment's length");
}

/// The EvaluationError of a P whose frame coordinates overflow.
[[noreturn, gnu::cold, gnu::noinline]] void throw_too_far(const Vec3& p) {
  throw EvaluationError(fmt::format("P = {} is too far from the segment (more than ~2^1000 times its length "
                                    "from the origin): the field is outside the range of double precision",
                                    format_point(p)));
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

  // The frame (scaled_frame.hpp): the kernel parameters scale with the
  // lengths, s as length^−2 and R as length.
  frame_ = ScaledFrame(scale_safe_norm(b - a));
  // f scales as |AB| K: λ^(1 + p) (the trait's scaling_power, radial_kernel.hpp).
  value_power_ = 1 + kernels::scaling_power(kernel);
  factors_ = frame_.factors(value_power_);
  // A positive kernel and weight give f > 0, so a 0 there is an underflow;
  // except where the kernel itself vanishes or underflows (beyond a finite
  // support, far from a Gaussian: 0 is then the correctly rounded value).
  may_vanish_ = facts.vanishes_far || std::any_of(weight.begin(), weight.end(), [](double w) { return w < 0.0; });
  kernel_vanishes_far_ = facts.vanishes_far;
  input_.a = to_array(frame_.point(a));
  input_.b = to_array(frame_.point(b));
  input_.w = {0.0, 0.0, 0.0, 0.0};
  for (int k = 0; k <= weight_degree_; ++k) input_.w[std::size_t(k)] = weight[std::size_t(k)];
  for (const double w : weight) largest_weight_ = std::max(largest_weight_, std::abs(w));
  input_.s = frame_.scaled(kernel.s, -2);
  input_.R = frame_.scaled(kernel.R, 1);
  input_.gaussian_a = frame_.scaled(kernel.a, -2);  // exp(−a d²): a has units length^−2
  input_.gaussian_b = kernel.b;                      // K(0): no units
  support_radius_ = kernels::support_radius(kernels::make_radial_kernel(kernel));
  singular_at_zero_ = facts.singular_at_zero;
  for (std::string_view key : facts.parameters) require_parameter_in_frame(key, input_);
  if (generated_->prepare != nullptr) {
    prepared_.resize(generated_->prepared_size);
    generated_->prepare(input_, prepared_.data());
    if (std::isfinite(support_radius_)) {
      input_from_b_ = detail::reversed_segment(input_);
      prepared_from_b_.resize(generated_->prepared_size);
      generated_->prepare(input_from_b_, prepared_from_b_.data());
    }
  }
  if (kernel.family == KernelFamily::cauchy) {
    far_rule_ = FarSegmentRule::make(a, b, kernel.degree, kernel.s, this->weight());
  }
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

// P, and for a compact kernel the clip, in the frame. It runs once per
// primitive and point: the error's formatting is out of line
// (throw_too_far), which leaves locate small enough for the compiler to
// inline into its three callers.
[[gnu::always_inline]] inline Segment::Case Segment::locate(const Vec3& p, SegmentPoint<double>& point,
                                                          const double*& prepared) const {
  detail::require_finite_query_point(p);
  const Vec3 frame_p = factors_.to_frame != 0.0 ? Vec3(p * factors_.to_frame) : frame_.point(p);
  // A factor 2^−e ≤ 1 cannot take a finite P out of the double range.
  if (factors_.to_frame > 1.0 && !frame_p.allFinite()) throw_too_far(p);
  point.p = to_array(frame_p);
  prepared = prepared_.empty() ? nullptr : prepared_.data();

  if (singular_at_zero_) {
    // Exact test on the frame's doubles (see the file comment of segment.hpp).
    const Vec3 ab = to_vec3(input_.b) - to_vec3(input_.a);
    const Vec3 ap = frame_p - to_vec3(input_.a);
    const double projection = ab.dot(ap);  // t |AB|²
    if (ab.cross(ap) == Vec3::Zero() && projection >= 0.0 && projection <= ab.squaredNorm()) {
      return Case::on_inverse_singularity;
    }
  }
  if (std::isfinite(support_radius_)) {
    // From the end nearer P (reversed_segment.hpp), where the kernel has a
    // preparation (all finite-support ones do) and so prepared_from_b_.
    const bool from_b = !prepared_from_b_.empty() && detail::foot_on_b_half(input_.a, input_.b, point.p);
    const SegmentInput<double>& segment = from_b ? input_from_b_ : input_;
    if (from_b) prepared = prepared_from_b_.data();
    // Hubert 2012 §3.4: only the part of [A,B] inside the ball of radius R
    // around P contributes; the generated code integrates over [t0, t1].
    const std::optional<ParameterInterval<double>> inside = clip_to_ball(segment.a, segment.b, point.p, segment.R);  // R in the frame
    if (!inside) return Case::outside_compact_support;
    point.t0 = inside->t0;
    point.t1 = inside->t1;
  }
  return Case::call_generated;
}

namespace {

// The derived Gaussian kernel (derived_segment_kernels.hpp) has no preparation:
// they read the whole SegmentInput (`segment`, with the point's P and clip)
// at each point.
[[gnu::always_inline]] inline SegmentInput<double> input_at(const SegmentInput<double>& segment,
                                                           const SegmentPoint<double>& point) {
  SegmentInput<double> input = segment;
  input.p = point.p;
  input.t0 = point.t0;
  input.t1 = point.t1;
  return input;
}

}  // namespace

[[gnu::always_inline]] inline double Segment::call_f(const SegmentPoint<double>& point, const double* prepared) const {
  if (prepared != nullptr) return generated_->f_at(prepared, point);
  return generated_->f(input_at(input_, point));
}

[[gnu::always_inline]] inline std::array<double, 3> Segment::call_grad(const SegmentPoint<double>& point,
                                                                         const double* prepared) const {
  if (prepared != nullptr) return generated_->grad_at(prepared, point);
  return generated_->grad(input_at(input_, point));
}

[[gnu::always_inline]] inline double Segment::call_f_and_grad(const SegmentPoint<double>& point, const double* prepared,
                                                              std::array<double, 3>& g) const {
  if (prepared != nullptr) return generated_->f_and_grad_at(prepared, point, g);
  return generated_->f_and_grad(input_at(input_, point), g);
}

void Segment::require_weight_headroom(const std::string& what, const Vec3& p) const {
  if (!(largest_weight_ >= weight_overflow_start)) return;
  throw EvaluationError(fmt::format("a coefficient of magnitude {:g} overflows the closed form {} at P = {} (it "
                                    "returned {}): weights from {:g} on leave no headroom in double precision; "
                                    "divide the weights and the iso by a common factor",
                                    largest_weight_, generated_->name, detail::format_point(p), what,
                                    weight_overflow_start),
                        "weight");
}

[[gnu::always_inline]] inline double Segment::restore_value(double f, const Vec3& p) const {
  double world;
  if (restore_value_common(f, factors_.value, world)) return world;
  if (std::isnan(f) || f == -infinity) require_weight_headroom(fmt::format("{}", f), p);
  return frame_.restore_value(f, value_power_, may_vanish_, generated_->name, p);
}

[[gnu::always_inline]] inline Vec3 Segment::restore_gradient(const std::array<double, 3>& g, const Vec3& p) const {
  Vec3 world;
  if (restore_gradient_common(to_vec3(g), factors_.gradient, world)) return world;
  if (!to_vec3(g).allFinite() && !(to_vec3(g).array() == infinity).all())
    require_weight_headroom(fmt::format("the gradient {}", detail::format_point(to_vec3(g))), p);
  return frame_.restore_gradient(to_vec3(g), value_power_ - 1, kernel_vanishes_far_, generated_->name, p);
}

double Segment::value(const Vec3& p) const {
  SegmentPoint<double> point;
  const double* prepared = nullptr;
  switch (locate(p, point, prepared)) {
    case Case::outside_compact_support: return 0.0;
    case Case::on_inverse_singularity: return infinity;
    case Case::call_generated: break;
  }
  return restore_value(detail::evaluate_converged(generated_->name, p, [&] { return call_f(point, prepared); }), p);
}

Vec3 Segment::gradient(const Vec3& p) const {
  SegmentPoint<double> point;
  const double* prepared = nullptr;
  switch (locate(p, point, prepared)) {
    case Case::outside_compact_support: return Vec3::Zero();
    case Case::on_inverse_singularity: return Vec3::Constant(infinity);
    case Case::call_generated: break;
  }
  return restore_gradient(detail::evaluate_converged(generated_->name, p, [&] { return call_grad(point, prepared); }), p);
}

FieldSample Segment::value_and_gradient(const Vec3& p) const {
  SegmentPoint<double> point;
  const double* prepared = nullptr;
  switch (locate(p, point, prepared)) {
    case Case::outside_compact_support: return {0.0, Vec3::Zero()};
    case Case::on_inverse_singularity: return {infinity, Vec3::Constant(infinity)};
    case Case::call_generated: break;
  }
  std::array<double, 3> g{};
  const double f = detail::evaluate_converged(generated_->name, p, [&] { return call_f_and_grad(point, prepared, g); });
  return {restore_value(f, p), restore_gradient(g, p)};
}

}  // namespace skelconv
