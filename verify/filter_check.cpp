// verify/filter_check.cpp — skelconv-verify-filter: is the filter's error
// bound honest? (skelconv/kernels/segment_filter.hpp)
//
// For every generated segment kernel with a fast form, on the sweep's samples
// of every region (sampling.hpp), on adversarial ones and on points found by
// bisection across the filter's threshold (below), the fast form's value and
// its error bound (FilteredSegmentKernel::evaluate_fast: RelativeError<double>
// under the filter's floating-point scope) are compared with the reference:
// the stable generated function evaluated in binary128 on the same double
// input (the same clipped [t0, t1] for compact kernels), whose own error (about 1e-28 relative where the sweeps compare
// it with quadrature of the definition, docs/verify.md) is allowed for by
// kReferenceSlack. A point where |fast − reference| exceeds the bound fails
// the check, accepted by the filter or not; the table counts the filter's
// accepted and rejected points per family and region.
//
// --bound-scale s < 1 (test only) multiplies every bound by s before the
// filter and the check: ctest verify_filter_weakened_bound must fail.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "generated_kernels.hpp"
#include "point_evaluation.hpp"
#include "sampling.hpp"
#include "skelconv/kernels/segment_filter.hpp"

namespace skelconv::verify {
namespace {

// The binary128 reference's own relative error allowance (see the top).
constexpr double kReferenceSlack = 1e-24;
// Threshold bisection on log10(h / |AB|) over [−12, 4]: 30 halvings end
// within 16 · 2^−30 decades (a relative step of ~3e−8 in h) of a change.
constexpr int kBisectionSteps = 30;

struct Tally {
  long points = 0, accepted = 0, rejected = 0, violations = 0;
  long near_threshold = 0;        // points whose bound is within ×10 of the filter's threshold
  double worst_ratio = 0;         // max |fast − ref| / bound, over points with a finite bound
  double worst_accepted_rel = 0;  // max relative error of an accepted fast value
};

// Adversarial samples: P at height h = |AB| · 10^[−12, 4] over the line, at a
// parameter τ inside, just beyond or far beyond an end, the whole scene
// scaled by 10^[−6, 6] (the Cauchy sharpness s by its inverse square, the
// compact radius with it): near the line, near the ends, the far field, at
// every scale, and across the filter's threshold in each.
// `log_height` (threshold bisection) replaces the drawn log10(h / |AB|).
SweepProblem adversarial_problem(KernelFamily family, int degree, std::uint64_t index,
                                 std::optional<double> log_height = std::nullopt) {
  SweepProblem pb = draw_problem(20261204, family, degree, Region::generic, index);
  DeterministicRandom rng(point_seed(99, family, degree, Region::generic, index));
  const double scale = rng.log_uniform(1e-6, 1e6);
  const Vec3<double> ab = sub(pb.b, pb.a);
  const double L = std::sqrt(dot(ab, ab));
  const Vec3<double> dir{ab[0] / L, ab[1] / L, ab[2] / L};
  const double drawn = rng.log_uniform(1e-12, 1e4);
  const double h = L * (log_height ? std::pow(10.0, *log_height) : drawn);
  double tau = 0;
  switch (index % 4) {
    case 0: tau = rng.uniform(0, 1); break;
    case 1: tau = -rng.log_uniform(1e-10, 30); break;
    case 2: tau = 1 + rng.log_uniform(1e-10, 30); break;
    default: tau = rng.coin() ? 0.0 : 1.0; break;
  }
  const Vec3<double> p = axpy(h, rng.unit_perpendicular(dir), axpy(tau * L, dir, pb.a));
  for (int c = 0; c < 3; ++c) pb.a[c] *= scale, pb.b[c] *= scale, pb.p[c] = p[c] * scale;
  pb.s /= scale * scale;
  pb.R = (distance_to_segment(pb.a, pb.b, pb.p) + scale * L * rng.log_uniform(1e-6, 3)) * 1.0;
  pb.region = Region::generic;
  return pb;
}

// How far a bound is from the filter's threshold: bound / (tolerance ·
// (magnitude − bound)), ≤ 1 where the filter accepts; ∞ without a margin.
double threshold_ratio(double magnitude, double bound, double tolerance) {
  return magnitude > bound ? bound / (tolerance * (magnitude - bound)) : INFINITY;
}

// One point of one kernel: the check and the tally; whether the filter
// accepts the point (nullopt without a fast form).
std::optional<bool> check_point(const FilteredSegmentKernel& kernel, const GeneratedKernel<extended>& reference,
                                const SegmentInput<double>& in, double bound_scale, double tolerance, Tally& t) {
  FastEvaluation fast;
  if (!kernel.evaluate_fast(in, 2, fast)) return std::nullopt;
  SegmentInput<extended> x;
  for (int c = 0; c < 3; ++c) x.a[c] = in.a[c], x.b[c] = in.b[c], x.p[c] = in.p[c];
  for (int k = 0; k <= max_weight_degree; ++k) x.w[k] = in.w[k];
  x.s = in.s, x.R = in.R, x.t0 = in.t0, x.t1 = in.t1;
  std::array<extended, 3> g_ref{};
  const extended f_ref = reference.f_and_grad(x, g_ref);
  const double f_bound = fast.f_bound * bound_scale, g_bound = fast.grad_bound() * bound_scale;
  std::array<double, 3> g_bounds = fast.grad_bounds;
  for (double& b : g_bounds) b *= bound_scale;
  const double f_err = static_cast<double>(abs(extended(fast.f) - f_ref));
  extended g_err2 = 0, g_norm2 = 0;
  for (int c = 0; c < 3; ++c) {
    const extended d = extended(fast.grad[c]) - g_ref[c];
    g_err2 += d * d;
    g_norm2 += g_ref[c] * g_ref[c];
  }
  const double g_err = static_cast<double>(sqrt(g_err2)), g_ref_norm = static_cast<double>(sqrt(g_norm2));
  const double f_abs = static_cast<double>(abs(f_ref));
  ++t.points;
  // The filter's own decision (FilteredSegmentKernel::f_and_grad), on the scaled bounds.
  const bool accepted = std::isfinite(fast.f) && filter_accepts(std::abs(fast.f), f_bound, tolerance) &&
                        filter_accepts_gradient(fast.grad, g_bounds, tolerance);
  ++(accepted ? t.accepted : t.rejected);
  const double ratio = std::max(threshold_ratio(std::abs(fast.f), f_bound, tolerance),
                                threshold_ratio(std::hypot(fast.grad[0], fast.grad[1], fast.grad[2]), g_bound, tolerance));
  if (ratio >= 0.1 && ratio <= 10) ++t.near_threshold;
  auto judge = [&](double err, double bound, double magnitude) {
    if (!std::isfinite(bound)) return;
    if (!(err <= bound + kReferenceSlack * magnitude)) {
      ++t.violations;
      std::printf("  error %.6g > bound %.6g (|reference| %.6g; fast f %.17g, reference f %.17g)\n", err, bound,
                  magnitude, fast.f, static_cast<double>(f_ref));
    }
    if (bound > 0) t.worst_ratio = std::max(t.worst_ratio, err / bound);
    else if (err > kReferenceSlack * magnitude) t.worst_ratio = INFINITY;
  };
  judge(f_err, f_bound, f_abs);
  judge(g_err, g_bound, g_ref_norm);
  if (accepted) {
    // What acceptance promises: relative error ≤ tolerance (implied by an
    // honest bound; checked on its own, with the reference's allowance).
    const double rel = std::max(f_abs > 0 ? f_err / f_abs : 0.0, g_ref_norm > 0 ? g_err / g_ref_norm : 0.0);
    t.worst_accepted_rel = std::max(t.worst_accepted_rel, rel);
    if (!(rel <= tolerance + kReferenceSlack)) {
      ++t.violations;
      std::printf("  accepted with relative error %.3g > tolerance %.3g\n", rel, tolerance);
    }
  }
  return accepted;
}

int run(long points, double bound_scale, double tolerance) {
  std::map<std::pair<std::string, std::string>, Tally> tallies;  // (family, region)
  long violations = 0;
  for (const GeneratedKernel<double>& k : generated::segment_kernels<double>()) {
    const FilteredSegmentKernel* kernel = FilteredSegmentKernel::find(k.family, k.degree, k.weight_degree);
    const GeneratedKernel<extended>* reference = find_generated_extended(k.family, k.degree, k.weight_degree);
    if (!kernel || !kernel->has_fast_form() || !reference) continue;
    const std::string family(family_name(k.family));
    auto run_sample = [&](const SweepProblem& pb, const std::string& region) -> std::optional<bool> {
      SweepProblem weighted = pb;
      for (int d = k.weight_degree + 1; d <= max_weight_degree; ++d) weighted.w[d] = 0;
      const auto in = generated_input<double>(weighted);
      if (!in) return std::nullopt;
      Tally& t = tallies[{family, region}];
      const long before = t.violations;
      const std::optional<bool> accepted = check_point(*kernel, *reference, *in, bound_scale, tolerance, t);
      if (t.violations > before && violations++ < 5)
        std::printf("bound violated: %s, %s, sample %llu\n", k.name, region.c_str(),
                    static_cast<unsigned long long>(pb.index));
      return accepted;
    };
    for (Region region : all_regions) {
      if (!region_applies(region, k.family)) continue;
      for (long i = 0; i < points; ++i) run_sample(draw_problem(20240601, k.family, k.degree, region, i),
                                                   std::string(region_name(region)));
    }
    for (long i = 0; i < 4 * points; ++i) run_sample(adversarial_problem(k.family, k.degree, i), "adversarial");
    // Across the threshold: on the line through an adversarial sample's foot,
    // bisect log10(h / |AB|) between a height the filter accepts and one it
    // rejects; every point of the bisection is checked.
    for (long i = 0; i < points; ++i) {
      auto at = [&](double log_h) { return run_sample(adversarial_problem(k.family, k.degree, i, log_h), "threshold"); };
      double lo = -12, hi = 4;
      const std::optional<bool> accept_lo = at(lo), accept_hi = at(hi);
      if (!accept_lo || !accept_hi || *accept_lo == *accept_hi) continue;
      for (int step = 0; step < kBisectionSteps; ++step) {
        const double mid = (lo + hi) / 2;
        const std::optional<bool> accept_mid = at(mid);
        if (!accept_mid) break;
        (*accept_mid == *accept_lo ? lo : hi) = mid;
      }
    }
  }
  std::printf("| family | region | points | accepted | rejected | bound within ×10 of the threshold | "
              "bound violations | max err/bound | max rel. error accepted |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  long total_violations = 0;
  for (const auto& [key, t] : tallies) {
    std::printf("| %s | %s | %ld | %ld | %ld | %ld | %ld | %.3g | %.3g |\n", key.first.c_str(), key.second.c_str(),
                t.points, t.accepted, t.rejected, t.near_threshold, t.violations, t.worst_ratio, t.worst_accepted_rel);
    total_violations += t.violations;
  }
  std::printf("filter check (tolerance %g, bound scale %g): %ld bound violations\n", tolerance, bound_scale,
              total_violations);
  return total_violations == 0 ? 0 : 1;
}

}  // namespace
}  // namespace skelconv::verify

int main(int argc, char** argv) {
  CLI::App app{"skelconv-verify-filter: the filter's running error bound against binary128 references"};
  long points = 20;
  double bound_scale = 1;
  double tolerance = skelconv::kDefaultFilterTolerance;
  app.add_option("--points", points, "samples per kernel and region (adversarial: 4 times as many)")
      ->check(CLI::Range(1L, 1000000L));
  app.add_option("--bound-scale", bound_scale, "test only: multiply every bound by this (< 1 must fail)")
      ->check(CLI::PositiveNumber);
  app.add_option("--tolerance", tolerance, "the filter's relative tolerance")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  return skelconv::verify::run(points, bound_scale, tolerance);
}
