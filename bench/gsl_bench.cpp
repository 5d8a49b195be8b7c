// bench/gsl_bench.cpp — the closed forms against the method numerical
// skeleton libraries use: GSL's adaptive QAG with the 61-point
// Gauss–Kronrod rule (gsl_integration_qag, GSL_INTEG_GAUSS61), relative
// tolerance 1e-8 or 1e-12, four integrals (f and the three components of
// ∇f), at distances 0.1, 0.3, 1 and 3 |AB| from the segment, for every
// family (inverse i3 and i8, Cauchy i4 and i8, compact i6).
//   gsl/<kernel>/d:<d>/closed      the generated f_and_grad per point (the segment
//                                  prepared beforehand, as Segment does)
//   gsl/<kernel>/d:<d>/qag:<tol>   the 4 QAG integrals
// and the closed form alone for inverse and Cauchy i = 1…8, weight degree 0
// (the generic-path goal: ≤ 25 ns at every distance); and per distance band
// (0.01–0.1, 0.1–1, 1–10 |AB|, distances log-uniform: the ≥ 300× goal)
//   gsl/<kernel>/band:<lo>-<hi>/closed, …/qag:1e-08.
// Points: 256 per distance, every direction (beyond the ends too): P at
// distance within 10 % of d|AB| from the segment. The compact kernel has
// R = 5 |AB| here, so that every distance is inside its support; its inputs
// come clipped, for both methods. Counters: integrand evaluations per point
// and the largest relative difference to the closed form (f; ∇f over |∇f|),
// so that both are known to compute the same field.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "bench_main.hpp"
#include "bench_support.hpp"

namespace skelconv::bench {
namespace {

struct Case {
  KernelFamily family;
  int degree, weight_degree;
};
constexpr Case cases[] = {{KernelFamily::inverse, 3, 1}, {KernelFamily::inverse, 8, 0}, {KernelFamily::cauchy, 4, 1},
                          {KernelFamily::cauchy, 8, 0}, {KernelFamily::compact, 6, 0}};
/// The generic-path goal (f and ∇f ≤ 25 ns for inverse and
/// Cauchy up to i = 8 at 0.1–3 |AB|): the closed form alone, weight degree
/// 0, every degree (gsl/<kernel>/d:<d>/closed without QAG rows).
constexpr int generic_max_degree = 8;

/// Times f and ∇f of the closed form over `inputs`, one point per iteration,
/// each segment prepared before the timing (PreparedPoints).
void time_closed(benchmark::State& state, const KernelRef* k, const std::vector<Input>& inputs) {
  const PreparedPoints points(*k, inputs);
  std::size_t j = 0;
  for (auto _ : state) {
    Vec g;
    benchmark::DoNotOptimize(points.f_and_grad(j, g));
    benchmark::DoNotOptimize(g);
    j = (j + 1) % inputs.size();
  }
}

/// Times GSL QAG-61 at `tolerance` over `inputs`, one point per iteration.
void time_qag(benchmark::State& state, const KernelRef* k, const std::vector<Input>& inputs, double tolerance) {
  std::size_t j = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        quadrature(k->family, k->degree, k->weight_degree, inputs[j], tolerance, true, AdaptiveRule::gsl_qag_61));
    j = (j + 1) % inputs.size();
  }
}

void bench_closed(benchmark::State& state, const KernelRef* k, double d) {
  time_closed(state, k, generic_region_inputs(k->family, d));
}

void bench_qag(benchmark::State& state, const KernelRef* k, double d, double tolerance) {
  const std::vector<Input> inputs = generic_region_inputs(k->family, d);
  // Agreement with the closed form, and evaluations per point, on every point.
  double diff_f = 0, diff_g = 0, evaluations = 0;
  for (const Input& in : inputs) {
    const QuadratureResult q =
        quadrature(k->family, k->degree, k->weight_degree, in, tolerance, true, AdaptiveRule::gsl_qag_61);
    Vec g;
    const double f = k->f_and_grad(in, g);
    const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    diff_f = std::max(diff_f, std::abs(q.f - f) / std::abs(f));
    for (int c = 0; c < 3; ++c) diff_g = std::max(diff_g, std::abs(q.grad[c] - g[c]) / gn);
    evaluations += double(q.evaluations) / double(inputs.size());
  }
  time_qag(state, k, inputs, tolerance);
  state.counters["integrand_evals"] = evaluations;
  state.counters["max_rel_diff_f"] = diff_f;
  state.counters["max_rel_diff_grad"] = diff_g;
}

/// The closed form and QAG 1e-8 over one distance band (bench_support.hpp,
/// distance_bands): gsl/<kernel>/band:<lo>-<hi>/<closed|qag:1e-08>.
void bench_band_closed(benchmark::State& state, const KernelRef* k, DistanceBand band) {
  time_closed(state, k, band_inputs(k->family, band));
}

void bench_band_qag(benchmark::State& state, const KernelRef* k, DistanceBand band) {
  time_qag(state, k, band_inputs(k->family, band), 1e-8);
}

void register_all() {
  for (const KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy}) {
    for (int degree = 1; degree <= generic_max_degree; ++degree) {
      const KernelRef* k = find_kernel(family, degree, 0);
      const bool with_qag = std::any_of(std::begin(cases), std::end(cases), [&](const Case& c) {
        return c.family == family && c.degree == degree && c.weight_degree == 0;
      });
      if (!k || with_qag) continue;  // the QAG cases register their closed form below
      for (const double d : generic_region_distances) {
        char distance[16];
        std::snprintf(distance, sizeof distance, "d:%g", d);
        benchmark::RegisterBenchmark(("gsl/" + k->name + "/" + distance + "/closed").c_str(), bench_closed, k, d);
      }
    }
  }
  for (const Case& c : cases) {
    const KernelRef* k = find_kernel(c.family, c.degree, c.weight_degree);
    if (!k) continue;
    for (const DistanceBand band : distance_bands) {
      char name[32];
      std::snprintf(name, sizeof name, "band:%g-%g", band.lo, band.hi);
      const std::string base = "gsl/" + k->name + "/" + name + "/";
      benchmark::RegisterBenchmark((base + "closed").c_str(), bench_band_closed, k, band);
      benchmark::RegisterBenchmark((base + "qag:1e-08").c_str(), bench_band_qag, k, band);
    }
    for (const double d : generic_region_distances) {
      char distance[16];
      std::snprintf(distance, sizeof distance, "d:%g", d);
      const std::string base = "gsl/" + k->name + "/" + distance + "/";
      benchmark::RegisterBenchmark((base + "closed").c_str(), bench_closed, k, d);
      for (const double tolerance : {1e-8, 1e-12}) {
        char tol[16];
        std::snprintf(tol, sizeof tol, "qag:%.0e", tolerance);
        benchmark::RegisterBenchmark((base + tol).c_str(), bench_qag, k, d, tolerance);
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
