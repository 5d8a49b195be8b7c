// bench/scalis_bench.cpp — per-evaluation cost of SCALIS segments:
// skelconv::ScalisSegment::value_and_gradient (the generated inverse and
// Cauchy kernels, scalis_compact_F for the compact family) against adaptive
// Gauss–Kronrod quadrature of the definition (docs/mathematics.md §4), the numerical route.
//
//   scalis/<kernel>/<near|far>/closed_form     f and ∇f, one point
//   scalis/<kernel>/<near|far>/quadrature/tol:<1e-08|1e-12>
//                                              Boost gauss_kronrod<double, 61>,
//                                              4 adaptive integrals (f, ∇f),
//                                              that relative tolerance (compact:
//                                              over its support, found first)
// <kernel>: Zanni et al. 2013 Table 4's SCALIS rows (inverse 3, Cauchy 4, compact 4 and 6)
// and compact 3 (odd: two panels). Workloads: 1024 points at 0.05–0.4 |AB|
// from the segment ("near": the inverse and Cauchy closed forms run the
// recurrence there) or 0.6–2 |AB| ("far": they take the Gauss panels of
// skelconv/detail/gauss_moments.hpp); compact points are kept only inside the
// support (compact: near only, its support ends at 0.45 < 0.6 |AB|). Counter max_rel_diff: the largest |f_quad − f| / |f| seen, so
// both are known to compute the same field. Compare times within one run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "bench_main.hpp"
#include "bench_support.hpp"  // bench_a, bench_b, distance_to_segment
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/kernels/read_trait.hpp"
#include "skelconv/primitives/scalis_segment.hpp"

namespace skelconv::bench {
namespace {

constexpr std::size_t point_count = 1024;  // a power of two: index & (count − 1)

/// The benchmark segment (bench_support.hpp's, |AB| ≈ 1.27), radius growing
/// from 0.1 to 0.3, σ = 1.5 (compact needs σ > 1).
const Vec3 scalis_a(bench_a[0], bench_a[1], bench_a[2]), scalis_b(bench_b[0], bench_b[1], bench_b[2]);
constexpr double scalis_tau0 = 0.1, scalis_tau1 = 0.3, scalis_sigma = 1.5;

ScalisSegment make_segment(KernelFamily family, int degree) {
  return ScalisSegment(scalis_a, scalis_b, scalis_tau0, scalis_tau1, ScalisKernel{family, degree, scalis_sigma});
}

/// 1024 points, uniform in the segment's box grown by hi |AB|, kept at
/// distance [lo, hi] × |AB| from the segment (and with f > 0).
std::vector<Vec3> make_points(const ScalisSegment& segment, double lo, double hi, std::uint64_t seed) {
  const double length = (scalis_b - scalis_a).norm();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 box_lo = scalis_a.cwiseMin(scalis_b).array() - hi * length;
  const Vec3 box_hi = scalis_a.cwiseMax(scalis_b).array() + hi * length;
  std::vector<Vec3> points;
  for (std::size_t tries = 0; points.size() < point_count; ++tries) {
    if (tries > 100 * point_count) throw std::runtime_error("scalis_bench: no points in the workload");
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = box_lo[c] + (box_hi[c] - box_lo[c]) * unit(rng);
    const double d = distance_to_segment(Vec{p[0], p[1], p[2]}) / length;
    if (d < lo || d > hi || !(segment.value(p) > 0)) continue;
    points.push_back(p);
  }
  return points;
}

/// f and ∇f from the definition: f = iso/h · |AB| ∫ K(|P − Γ|/τ)/τ dt, by
/// 4 adaptive Gauss–Kronrod integrals (relative tolerance `tolerance`).
FieldSample quadrature(const ScalisSegment& segment, const Vec3& p, double tolerance) {
  using Rule = boost::math::quadrature::gauss_kronrod<double, 61>;
  const Vec3 ab = segment.b() - segment.a();
  const double length = ab.norm(), scale = segment.iso() / segment.normalisation();
  const double sigma = segment.kernel().sigma, dtau = segment.tau1() - segment.tau0();
  const int i = segment.kernel().degree;
  const KernelFamily family = segment.kernel().family;
  // K(x/σ) and its x-derivative over x, x = d/τ (docs/mathematics.md §1, SCALIS kernels):
  // the family's trait at s = 1, R = 1 (skelconv/kernels/).
  KernelSpec spec;
  spec.family = family;
  spec.degree = i;
  const kernels::RadialKernel trait = kernels::make_radial_kernel(spec);
  auto kernel = [&](double x, double& derivative_over_x) {
    const double y = x / sigma;
    derivative_over_x = std::visit([&](const auto& k) { return k.derivative(y); }, trait) / (sigma * x);
    return std::visit([&](const auto& k) { return k.value(y); }, trait);
  };
  // component −1: F; 0..2: ∂F/∂P_c = ∫ K'(x)/x · (P − Γ)_c / τ² · |AB| dt / τ.
  auto integrand = [&](int component) {
    return [&, component](double t) {
      const double tau = segment.tau0() + dtau * t;
      const Vec3 d = p - (segment.a() + t * ab);
      double derivative_over_x = 0;
      const double k = kernel(d.norm() / tau, derivative_over_x);
      return component < 0 ? k / tau : derivative_over_x * d[component] / (tau * tau * tau);
    };
  };
  // The compact kernel is integrated over its support {g > 0}, g(t) = στ(t)
  // − |P − Γ(t)| (concave: golden-section search for its peak, bisection for
  // the ends), as a numerical library would clip it first; over [0, 1] the
  // rule's first nodes can all miss a narrow support and return 0 with a
  // zero error estimate.
  double t_lo = 0, t_hi = 1;
  if (kernels::has_finite_support(family)) {
    auto g = [&](double t) { return sigma * (segment.tau0() + dtau * t) - (p - (segment.a() + t * ab)).norm(); };
    double lo = 0, hi = 1;
    const double inv_phi = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 80; ++it) {
      const double x1 = hi - inv_phi * (hi - lo), x2 = lo + inv_phi * (hi - lo);
      if (g(x1) < g(x2)) lo = x1;
      else hi = x2;
    }
    const double peak = (lo + hi) / 2;
    auto root = [&](double inside, double outside) {  // g(inside) > 0 ≥ g(outside)
      for (int it = 0; it < 60; ++it) {
        const double mid = (inside + outside) / 2;
        (g(mid) > 0 ? inside : outside) = mid;
      }
      return outside;
    };
    if (g(0) <= 0) t_lo = root(peak, 0);
    if (g(1) <= 0) t_hi = root(peak, 1);
  }
  auto integrate = [&](auto f) { return scale * length * Rule::integrate(f, t_lo, t_hi, 15, tolerance); };
  FieldSample sample;
  sample.value = integrate(integrand(-1));
  for (int c = 0; c < 3; ++c) sample.gradient[c] = integrate(integrand(c));
  return sample;
}

struct Workload {
  const char* name;
  double lo, hi;
  std::uint64_t seed;
};
constexpr Workload workloads[] = {{"near", 0.05, 0.4, 11}, {"far", 0.6, 2.0, 12}};

void bench_closed_form(benchmark::State& state, KernelFamily family, int degree, Workload workload) {
  const ScalisSegment segment = make_segment(family, degree);
  const std::vector<Vec3> points = make_points(segment, workload.lo, workload.hi, workload.seed);
  std::size_t idx = 0;
  for (auto _ : state) {
    FieldSample s = segment.value_and_gradient(points[idx++ & (point_count - 1)]);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}

void bench_quadrature(benchmark::State& state, KernelFamily family, int degree, Workload workload,
                      double tolerance) {
  const ScalisSegment segment = make_segment(family, degree);
  const std::vector<Vec3> points = make_points(segment, workload.lo, workload.hi, workload.seed);
  std::size_t idx = 0;
  double max_rel_diff = 0;
  for (auto _ : state) {
    const Vec3& p = points[idx++ & (point_count - 1)];
    FieldSample s = quadrature(segment, p, tolerance);
    benchmark::DoNotOptimize(s);
    state.PauseTiming();
    const double f = segment.value(p);
    max_rel_diff = std::max(max_rel_diff, std::abs(s.value - f) / std::abs(f));
    state.ResumeTiming();
  }
  state.counters["max_rel_diff"] = max_rel_diff;
  state.SetItemsProcessed(state.iterations());
}

struct Row {
  KernelFamily family;
  int degree;
};
constexpr Row rows[] = {{KernelFamily::inverse, 3}, {KernelFamily::cauchy, 4}, {KernelFamily::compact, 4},
                        {KernelFamily::compact, 6}, {KernelFamily::compact, 3}};

void register_all() {
  for (const Row& row : rows) {
    const std::string kernel = std::string(family_name(row.family)) + "_i" + std::to_string(row.degree);
    for (const Workload& w : workloads) {
      // The compact support reaches σ τ1 = 0.45 < 0.6 |AB|: no far points.
      if (kernels::has_finite_support(row.family) && w.lo > 0.5) continue;
      const std::string base = "scalis/" + kernel + "/" + w.name + "/";
      benchmark::RegisterBenchmark((base + "closed_form").c_str(), bench_closed_form, row.family, row.degree, w);
      for (double tolerance : {1e-8, 1e-12}) {
        const std::string name = base + (tolerance == 1e-8 ? "quadrature/tol:1e-08" : "quadrature/tol:1e-12");
        benchmark::RegisterBenchmark(name.c_str(), bench_quadrature, row.family, row.degree, w, tolerance);
      }
    }
  }
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  skelconv::bench::register_all();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
