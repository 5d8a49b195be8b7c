// bench/bench_support.cpp — workloads and the quadrature baseline.
#include "bench_support.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "skelconv/detail/clip.hpp"
#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv::bench {
namespace {

/// Uniform points in the bounding box of [bench_a, bench_b] grown by `margin`.
class BoxSampler {
 public:
  BoxSampler(double margin, std::uint64_t seed) : rng_(seed) {
    for (int c = 0; c < 3; ++c) {
      lo_[c] = std::min(bench_a[c], bench_b[c]) - margin;
      hi_[c] = std::max(bench_a[c], bench_b[c]) + margin;
    }
  }
  Vec next() {
    Vec p;
    for (int c = 0; c < 3; ++c) p[c] = lo_[c] + (hi_[c] - lo_[c]) * unit_(rng_);
    return p;
  }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  Vec lo_, hi_;
};

/// x^(i/2) for an integer i of either sign, from integer powers and one sqrt
/// (the cheapest honest way to evaluate the kernels in the integrand).
inline double half_power(double x, int i) {
  const bool negative = i < 0;
  const int n = negative ? -i : i;
  double r = 1.0;
  double base = x;
  for (int k = n / 2; k > 0; k >>= 1) {  // x^(n/2) by squaring
    if (k & 1) r *= base;
    base *= base;
  }
  if (n & 1) r *= std::sqrt(x);
  return negative ? 1.0 / r : r;
}

}  // namespace

double distance_to_segment(const Vec& p) {
  Vec ab, ap;
  for (int c = 0; c < 3; ++c) {
    ab[c] = bench_b[c] - bench_a[c];
    ap[c] = p[c] - bench_a[c];
  }
  const double aa = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const double t = std::clamp((ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2]) / aa, 0.0, 1.0);
  double d2 = 0;
  for (int c = 0; c < 3; ++c) d2 += (ap[c] - t * ab[c]) * (ap[c] - t * ab[c]);
  return std::sqrt(d2);
}

Input segment_input(KernelFamily family) {
  Input in;
  in.a = bench_a;
  in.b = bench_b;
  in.w = bench_weight;
  in.s = bench_s;
  in.R = bench_R;
  (void)family;
  return in;
}

bool clip_compact_support(KernelFamily family, Input& in) {
  if (!kernels::family_facts(family).finite_support) return true;
  const auto clip = clip_to_ball(in.a, in.b, in.p, in.R);
  if (!clip) return false;
  in.t0 = clip->t0;
  in.t1 = clip->t1;
  return true;
}

namespace {

double bench_segment_length() {
  double L = 0;
  for (int c = 0; c < 3; ++c) L += (bench_b[c] - bench_a[c]) * (bench_b[c] - bench_a[c]);
  return std::sqrt(L);
}

/// One draw of a point at `target` (± 10 %) from the bench segment, in any
/// direction from a point of its middle half; none where the draw is
/// rejected (a degenerate direction, a distance off the target, a compact
/// support that misses the segment). Compact kernels get R = compact_R.
std::optional<Input> point_near_distance(KernelFamily family, double target, double compact_R,
                                         std::mt19937_64& random, std::uniform_real_distribution<double>& u) {
  const double t = 0.5 + 0.5 * u(random);
  Vec dir{u(random), u(random), u(random)};
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (n > 1 || n < 1e-3) return std::nullopt;
  const double r = target * (1.0 + 0.5 * u(random));
  Vec p;
  for (int c = 0; c < 3; ++c) p[c] = bench_a[c] + t * (bench_b[c] - bench_a[c]) + r * dir[c] / n;
  const double distance = distance_to_segment(p);
  if (distance < 0.9 * target || distance > 1.1 * target) return std::nullopt;
  Input in = segment_input(family);
  in.p = p;
  if (kernels::family_facts(family).finite_support) in.R = compact_R;
  if (!clip_compact_support(family, in)) return std::nullopt;
  return in;
}

}  // namespace

std::vector<Input> generic_region_inputs(KernelFamily family, double d) {
  std::mt19937_64 random(std::uint64_t(1000 * d) + 15);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double L = bench_segment_length();
  std::vector<Input> inputs;
  while (inputs.size() < generic_region_points)
    if (auto in = point_near_distance(family, d * L, generic_region_compact_R * L, random, u)) inputs.push_back(*in);
  return inputs;
}

std::vector<Input> band_inputs(KernelFamily family, DistanceBand band) {
  std::mt19937_64 random(std::uint64_t(1000 * band.lo) + 29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double L = bench_segment_length();
  std::vector<Input> inputs;
  while (inputs.size() < generic_region_points) {
    // the target distance log-uniform in the band
    const double target = L * band.lo * std::pow(band.hi / band.lo, 0.5 + 0.5 * u(random));
    if (auto in = point_near_distance(family, target, (band.hi + 2) * L, random, u)) inputs.push_back(*in);
  }
  return inputs;
}

std::vector<Input> make_inputs(KernelFamily family, std::size_t count, std::uint64_t seed, double min_distance,
                               double max_distance) {
  BoxSampler sampler(bench_R, seed);
  std::vector<Input> inputs;
  inputs.reserve(count);
  while (inputs.size() < count) {
    const Vec p = sampler.next();
    const double d = distance_to_segment(p);
    if (d < min_distance || d > max_distance) continue;
    Input in = segment_input(family);
    in.p = p;
    if (!clip_compact_support(family, in)) continue;
    inputs.push_back(in);
  }
  return inputs;
}

std::vector<Vec> make_box_points(std::size_t count, std::uint64_t seed) {
  BoxSampler sampler(1.5 * bench_R, seed);
  std::vector<Vec> points;
  points.reserve(count);
  while (points.size() < count) {
    const Vec p = sampler.next();
    if (distance_to_segment(p) < 0.05) continue;  // keep off the inverse singularity
    points.push_back(p);
  }
  return points;
}

namespace {
/// GSL's adaptive QAG, 61-point rule, relative tolerance only.
template <class Function>
double gsl_qag_61(Function& function, double t0, double t1, double tolerance) {
  // A rule that cannot reach the tolerance returns its best estimate (as
  // Boost's does) instead of aborting the program.
  static const gsl_error_handler_t* previous = gsl_set_error_handler_off();
  (void)previous;
  constexpr std::size_t max_subintervals = 1000;
  static thread_local gsl_integration_workspace* workspace = gsl_integration_workspace_alloc(max_subintervals);
  gsl_function integrand{[](double t, void* f) { return (*static_cast<Function*>(f))(t); }, &function};
  double result = 0, error = 0;
  gsl_integration_qag(&integrand, t0, t1, 0.0, tolerance, max_subintervals, GSL_INTEG_GAUSS61, workspace, &result,
                      &error);
  return result;
}
}  // namespace

QuadratureResult quadrature(KernelFamily family, int degree, int weight_degree, const Input& in,
                            double tolerance, bool with_gradient, AdaptiveRule rule) {
  using Rule = boost::math::quadrature::gauss_kronrod<double, 61>;
  Vec ab, ap;
  for (int c = 0; c < 3; ++c) {
    ab[c] = in.b[c] - in.a[c];
    ap[c] = in.p[c] - in.a[c];
  }
  const double length = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
  KernelSpec spec;  // the family's trait (skelconv/kernels/) with the input's parameters
  spec.family = family;
  spec.degree = degree;
  spec.s = in.s;
  spec.R = in.R;
  spec.a = in.gaussian_a;
  spec.b = in.gaussian_b;
  const kernels::RadialKernel trait = kernels::make_radial_kernel(spec);
  const bool clipped = kernels::family_facts(family).finite_support;
  const double t0 = clipped ? in.t0 : 0.0;
  const double t1 = clipped ? in.t1 : 1.0;
  std::size_t evaluations = 0;

  auto weight = [&](double t) {
    double w = 0;
    for (int k = weight_degree; k >= 0; --k) w = w * t + in.w[k];
    return w;
  };
  // P − Γ(t) and q = |P − Γ(t)|².
  auto offset = [&](double t, Vec& d) {
    for (int c = 0; c < 3; ++c) d[c] = ap[c] - t * ab[c];
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  };
  // K as a function of q = r², and dK/dq = K'(r)/(2r).
  auto kernel = [&](double q) { return std::visit([&](const auto& k) { return k.value(std::sqrt(q)); }, trait); };
  auto kernel_derivative = [&](double q) {
    const double r = std::sqrt(q);
    return std::visit([&](const auto& k) { return k.derivative(r); }, trait) / (2.0 * r);
  };

  auto integrate = [&](auto& integrand) {
    return rule == AdaptiveRule::gsl_qag_61 ? gsl_qag_61(integrand, t0, t1, tolerance)
                                            : Rule::integrate(integrand, t0, t1, 15, tolerance);
  };
  QuadratureResult result;
  auto f_integrand = [&](double t) {
    ++evaluations;
    Vec d;
    return weight(t) * kernel(offset(t, d));
  };
  result.f = length * integrate(f_integrand);
  if (with_gradient) {
    for (int c = 0; c < 3; ++c) {
      // ∇_P K(|P − Γ(t)|²) = K'(q) 2 (P − Γ(t)).
      auto g_integrand = [&, c](double t) {
        ++evaluations;
        Vec d;
        const double q = offset(t, d);
        return weight(t) * kernel_derivative(q) * 2.0 * d[c];
      };
      result.grad[c] = length * integrate(g_integrand);
    }
  }
  result.evaluations = evaluations;
  return result;
}

}  // namespace skelconv::bench
