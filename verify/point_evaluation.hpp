// verify/point_evaluation.hpp — one sweep sample: the reference (quadrature
// of the definition) against the generated functions in double and in
// binary128, for every weight degree.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <stdexcept>

#include "error_stats.hpp"
#include "extended_precision.hpp"
#include "generated_kernels.hpp"
#include "reference_quadrature.hpp"
#include "sampling.hpp"
#include "skelconv/detail/clip.hpp"

namespace skelconv::verify {

/// The generated functions of one (family, degree), per weight degree, in both
/// precisions (nullptr where not generated).
struct KernelPair {
  const GeneratedKernel<double>* in_double = nullptr;
  const GeneratedKernel<extended>* in_extended = nullptr;
};
using KernelsByWeightDegree = std::array<KernelPair, max_weight_degree + 1>;

inline KernelsByWeightDegree find_kernels(KernelFamily family, int degree) {  // generated or derived
  KernelsByWeightDegree out{};
  for (int d = 0; d <= max_weight_degree; ++d)
    out[d] = {find_generated_double(family, degree, d),
              find_generated_extended(family, degree, d)};
  return out;
}

inline KernelDefinition<extended> reference_kernel(const SweepProblem& pb) {
  return {pb.family, pb.degree, extended(pb.s), extended(pb.R), extended(pb.gaussian_a), extended(pb.gaussian_b)};
}

/// The generated input for `pb` in precision T. For a finite-support family
/// the support is clipped in T, as the runtime does (skelconv/detail/clip.hpp);
/// nullopt when the clip is empty (the generated function must not be
/// called; f = 0).
template <class T>
std::optional<SegmentInput<T>> generated_input(const SweepProblem& pb) {
  SegmentInput<T> in;
  for (int c = 0; c < 3; ++c) in.a[c] = T(pb.a[c]), in.b[c] = T(pb.b[c]), in.p[c] = T(pb.p[c]);
  for (int k = 0; k <= max_weight_degree; ++k) in.w[k] = T(pb.w[k]);
  in.s = T(pb.s);
  in.R = T(pb.R);
  in.gaussian_a = T(pb.gaussian_a);
  in.gaussian_b = T(pb.gaussian_b);
  const double support = static_cast<double>(reference_kernel(pb).support_radius());
  if (std::isfinite(support)) {
    const auto clip = clip_to_ball(in.a, in.b, in.p, T(support));
    if (!clip) return std::nullopt;
    in.t0 = clip->t0;
    in.t1 = clip->t1;
  }
  return in;
}

/// Worst relative errors over the three entry points f, grad and f_and_grad,
/// each result multiplied by `scale` (1 except in a test perturbation,
/// TestPerturbation in sweep.hpp).
template <class T>
RelativeErrors evaluate_generated(const GeneratedKernel<T>& kernel, const std::optional<SegmentInput<T>>& in,
                                  const ReferenceField& ref, double scale = 1.0) {
  if (!in) {  // clip empty in T while the reference sees the support: the pipeline returns 0
    const Vec3<T> zero{};
    return relative_errors(T(0), zero, ref.f, ref.grad);
  }
  const T factor(scale);
  const auto scaled = [&](Vec3<T> g) { return Vec3<T>{g[0] * factor, g[1] * factor, g[2] * factor}; };
  const T f = kernel.f(*in) * factor;
  const Vec3<T> grad = scaled(kernel.grad(*in));
  Vec3<T> grad_joint{};
  const T f_joint = kernel.f_and_grad(*in, grad_joint) * factor;
  grad_joint = scaled(grad_joint);
  return worst_of(relative_errors(f, grad, ref.f, ref.grad), relative_errors(f_joint, grad_joint, ref.f, ref.grad));
}

/// The two references of a sweep: the standard one, and the stronger one a
/// flagged sample is retried with (ReferenceTolerances::retry) before it is
/// excluded.
struct ReferenceIntegrators {
  ReferenceIntegrator standard;
  ReferenceIntegrator stronger;
  explicit ReferenceIntegrators(const ReferenceTolerances& tolerances)
      : standard(tolerances), stronger(tolerances.retry()) {}
};

/// Moments of `pb`'s definition integral by `integrator`; nullopt when Boost
/// gives up (a non-finite integrand).
inline std::optional<SegmentMoments> try_moments(ReferenceIntegrator& integrator, const SweepProblem& pb) {
  try {
    return integrator.moments(reference_kernel(pb), widen(pb.a), widen(pb.b), widen(pb.p));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// Evaluates sample `pb` for every weight degree and adds it to `cells[d]`.
/// A weight degree whose reference is flagged (or that has none, Boost having
/// given up) is retried with the stronger reference, computed at most once
/// per sample; only what that still flags is excluded. `scale`: see
/// evaluate_generated.
inline void evaluate_sample(const SweepProblem& pb, const KernelsByWeightDegree& kernels,
                            ReferenceIntegrators& integrators, const AccuracyTargets& targets,
                            std::span<CellStats, max_weight_degree + 1> cells, double scale = 1.0) {
  std::optional<std::optional<SegmentMoments>> stronger;  // computed on the first flag
  const auto stronger_moments = [&]() -> const std::optional<SegmentMoments>& {
    if (!stronger) stronger = try_moments(integrators.stronger, pb);
    return *stronger;
  };
  const std::optional<SegmentMoments> standard = try_moments(integrators.standard, pb);
  const std::optional<SegmentMoments>& moments = standard ? standard : stronger_moments();
  const auto generated = [&](int d) { return kernels[d].in_double && kernels[d].in_extended; };
  if (!moments) {
    for (int d = 0; d <= max_weight_degree; ++d)
      if (generated(d)) ++cells[d].retried, ++cells[d].excluded;
    return;
  }
  const auto in_double = generated_input<double>(pb);
  const auto in_extended = generated_input<extended>(pb);
  std::array<extended, 4> w{};
  for (int k = 0; k < 4; ++k) w[k] = extended(pb.w[k]);

  for (int d = 0; d <= max_weight_degree; ++d) {
    if (!generated(d)) continue;
    CellStats& cell = cells[d];
    if (!standard) ++cell.retried;
    if (moments->empty) {  // f = 0 exactly: nothing to compare, only the double clip's verdict
      if (in_double) ++cell.support_mismatch;
      else ++cell.outside_support;
      continue;
    }
    if (!in_double) ++cell.support_mismatch;  // counted, and compared below as f = 0
    ReferenceField ref = integrators.standard.field(*moments, w, d);
    if (ref.flagged && standard) {
      ++cell.retried;
      if (const std::optional<SegmentMoments>& retry = stronger_moments()) ref = integrators.stronger.field(*retry, w, d);
    }
    if (ref.flagged) {
      ++cell.excluded;
      continue;
    }
    ++cell.points;
    cell.max_reference_error = std::max(
        {cell.max_reference_error, static_cast<double>(ref.f_relative_error), static_cast<double>(ref.grad_relative_error)});
    const KernelPair& kernel = kernels[d];
    cell.in_double.add(evaluate_generated(*kernel.in_double, in_double, ref, scale), pb, targets);
    cell.in_extended.add(evaluate_generated(*kernel.in_extended, in_extended, ref, scale), pb, targets);
  }
}

}  // namespace skelconv::verify
