// bench/kernels_bench.cpp — per-evaluation cost of the generated segment
// kernels:
//   eval/<kernel>/<variant>        f, grad, f_and_grad, and f plus a
//                                  finite-difference gradient (central: 7
//                                  evaluations of f, forward: 4);
//   quadrature/<kernel>/tol:<tol>[/near]  adaptive Gauss–Kronrod 61 of f
//                                  and ∇f (4 integrals), the baseline; /near:
//                                  points 0.01–0.1 from the segment (also
//                                  eval/<kernel>/f_and_grad/near);
//   degree/<family>/w0/i:<i>/<f|f_and_grad>   cost as the degree grows;
//   preamble/cross/<plain|exact>, eval/<kernel>/f_and_grad/beside   the
//                                  exact preamble's cost (below).
// One iteration is one evaluation at one point, the segment prepared
// beforehand as Segment prepares it (PreparedPoints); the points cycle through
// 1024 fixed query points around one segment (bench_support.hpp), so the
// branches of the closed forms see a realistic mix. Compare times within one
// run only (bench/summarize.py makes the ratios).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <skelconv/detail/exact_cross.hpp>

#include "bench_main.hpp"
#include "bench_support.hpp"

namespace skelconv::bench {
namespace {

constexpr std::size_t point_count = 1024;  // a power of two: index & (count − 1)

std::vector<Input> beside_inputs(KernelFamily family);

/// Which query points a benchmark cycles through.
enum class Workload {
  default_points,  ///< 0.1 ≤ d ≤ 0.9 from the segment (bench_support.hpp)
  near,            ///< 0.01 ≤ d ≤ 0.1
  beside,          ///< 1e-6…1e-2 |AB| beside the line (beside_inputs, below)
};

/// The 1024 query points of a family: the default workload (0.1 ≤ d ≤ 0.9)
/// or the near one (0.01 ≤ d ≤ 0.1), see bench_support.hpp.
const std::vector<Input>& inputs_for(KernelFamily family, bool near = false);

const std::vector<Input>& inputs_for(KernelFamily family, Workload workload) {
  if (workload != Workload::beside) return inputs_for(family, workload == Workload::near);
  static std::vector<Input> cache[3];
  std::vector<Input>& in = cache[int(family)];
  if (in.empty()) in = beside_inputs(family);
  return in;
}

const std::vector<Input>& inputs_for(KernelFamily family, bool near) {
  static std::vector<Input> cache[3][2];
  std::vector<Input>& in = cache[int(family)][near];
  if (in.empty()) {
    in = near ? make_inputs(family, point_count, 43, near_min_distance, near_max_distance)
              : make_inputs(family, point_count);
  }
  return in;
}

void bench_f(benchmark::State& state, const KernelRef* k) {
  const PreparedPoints in(*k, inputs_for(k->family));
  std::size_t idx = 0;
  for (auto _ : state) {
    double f = in.f(idx++ & (point_count - 1));
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(state.iterations());
}

void bench_grad(benchmark::State& state, const KernelRef* k) {
  const PreparedPoints in(*k, inputs_for(k->family));
  std::size_t idx = 0;
  for (auto _ : state) {
    Vec g = in.grad(idx++ & (point_count - 1));
    benchmark::DoNotOptimize(g);
  }
  state.SetItemsProcessed(state.iterations());
}

void bench_f_and_grad(benchmark::State& state, const KernelRef* k, Workload workload = Workload::default_points) {
  const PreparedPoints in(*k, inputs_for(k->family, workload));
  std::size_t idx = 0;
  for (auto _ : state) {
    Vec g;
    double f = in.f_and_grad(idx++ & (point_count - 1), g);
    benchmark::DoNotOptimize(f);
    benchmark::DoNotOptimize(g);
  }
  state.SetItemsProcessed(state.iterations());
}

/// f and a finite-difference gradient (bench_support.hpp): central (7
/// evaluations of f) or forward (4).
template <bool central>
void bench_fd(benchmark::State& state, const KernelRef* k) {
  const auto& in = inputs_for(k->family);
  std::size_t idx = 0;
  for (auto _ : state) {
    Vec g;
    double f = f_and_fd_gradient<central>(*k, in[idx++ & (point_count - 1)], g);
    benchmark::DoNotOptimize(f);
    benchmark::DoNotOptimize(g);
  }
  state.SetItemsProcessed(state.iterations());
}

/// Adaptive GK61 of f and ∇f. Counters (computed before timing, on the first
/// 256 points): integrand evaluations per point, and the largest relative
/// difference to the closed form, so the two sides are known to compute the
/// same field.
void bench_quadrature(benchmark::State& state, const KernelRef* k, double tolerance, bool near) {
  const auto& in = inputs_for(k->family, near);
  double evaluations = 0, max_rel_f = 0, max_rel_grad = 0;
  constexpr std::size_t checked = 256;
  for (std::size_t j = 0; j < checked; ++j) {
    const QuadratureResult q = quadrature(k->family, k->degree, k->weight_degree, in[j], tolerance, true);
    Vec g;
    const double f = k->f_and_grad(in[j], g);
    evaluations += double(q.evaluations);
    max_rel_f = std::max(max_rel_f, std::abs(q.f - f) / std::abs(f));
    const double gn = std::hypot(g[0], g[1], g[2]);
    max_rel_grad = std::max(max_rel_grad, std::hypot(q.grad[0] - g[0], q.grad[1] - g[1], q.grad[2] - g[2]) / gn);
  }
  std::size_t idx = 0;
  for (auto _ : state) {
    QuadratureResult q = quadrature(k->family, k->degree, k->weight_degree, in[idx++ & (point_count - 1)],
                                    tolerance, true);
    benchmark::DoNotOptimize(q);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["integrand_evals"] = evaluations / checked;
  state.counters["max_rel_diff_f"] = max_rel_f;
  state.counters["max_rel_diff_grad"] = max_rel_grad;
}

// --- The exact preamble ------------------------------------------------------
//
// preamble/cross/{plain,exact}: AB × AP as the previous code formed it (the
// plain products of rounded differences, what the generated kernels still
// do away from the line) against skelconv/detail/exact_cross.hpp's exactly rounded
// one, at the same points; eval/<kernel>/f_and_grad/beside: the kernels at
// points 1e-6…1e-2 |AB| beside the line, where they take the exact path
// (sin∠(AB, AP) < 1/16), against …/f_and_grad at the default points.

/// `count` points beside the segment's line: t ∈ [0.05, 0.95], distance
/// log-uniform in [1e-6, 1e-2] |AB|, in a direction perpendicular to AB.
std::vector<Input> beside_inputs(KernelFamily family) {
  std::vector<Input> inputs;
  const Vec ab{bench_b[0] - bench_a[0], bench_b[1] - bench_a[1], bench_b[2] - bench_a[2]};
  const double length = std::hypot(ab[0], ab[1], ab[2]);
  // Two unit vectors perpendicular to AB.
  Vec u{ab[1], -ab[0], 0};
  const double un = std::hypot(u[0], u[1], u[2]);
  for (double& x : u) x /= un;
  Vec v{ab[1] * u[2] - ab[2] * u[1], ab[2] * u[0] - ab[0] * u[2], ab[0] * u[1] - ab[1] * u[0]};
  for (double& x : v) x /= length;
  std::mt19937_64 random(44);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto uniform = [&] { return unit(random); };
  while (inputs.size() < point_count) {
    const double t = 0.05 + 0.9 * uniform();
    const double distance = length * std::pow(10.0, -6.0 + 4.0 * uniform());
    const double angle = 2 * 3.141592653589793 * uniform();
    Input in = segment_input(family);
    for (int c = 0; c < 3; ++c)
      in.p[c] = bench_a[c] + t * ab[c] + distance * (std::cos(angle) * u[c] + std::sin(angle) * v[c]);
    if (!clip_compact_support(family, in)) continue;
    inputs.push_back(in);
  }
  return inputs;
}

template <bool exact>
void bench_cross(benchmark::State& state) {
  const auto& in = inputs_for(KernelFamily::inverse, Workload::beside);
  std::size_t idx = 0;
  for (auto _ : state) {
    const Input& x = in[idx++ & (point_count - 1)];
    double cross[3];
    if constexpr (exact) {
      segment_exact_cross(x.a[0], x.a[1], x.a[2], x.b[0], x.b[1], x.b[2], x.p[0], x.p[1], x.p[2], cross);
    } else {
      const double ab[3] = {x.b[0] - x.a[0], x.b[1] - x.a[1], x.b[2] - x.a[2]};
      const double ap[3] = {x.p[0] - x.a[0], x.p[1] - x.a[1], x.p[2] - x.a[2]};
      cross[0] = ab[1] * ap[2] - ab[2] * ap[1];
      cross[1] = ab[2] * ap[0] - ab[0] * ap[2];
      cross[2] = ab[0] * ap[1] - ab[1] * ap[0];
    }
    benchmark::DoNotOptimize(cross);
  }
  state.SetItemsProcessed(state.iterations());
}

void register_all() {
  benchmark::RegisterBenchmark("preamble/cross/plain", bench_cross<false>);
  benchmark::RegisterBenchmark("preamble/cross/exact", bench_cross<true>);
  for (const KernelKey& n : detailed_kernels)
    if (const KernelRef* k = find_kernel(n.family, n.degree, n.weight_degree))
      benchmark::RegisterBenchmark(("eval/" + k->name + "/f_and_grad/beside").c_str(), bench_f_and_grad, k,
                                   Workload::beside);
  for (const KernelKey& n : detailed_kernels) {
    const KernelRef* k = find_kernel(n.family, n.degree, n.weight_degree);
    if (!k) {
      std::fprintf(stderr, "note: %s i=%d w=%d not generated, skipped\n",
                   std::string(family_name(n.family)).c_str(), n.degree, n.weight_degree);
      continue;
    }
    const std::string base = "eval/" + k->name + "/";
    benchmark::RegisterBenchmark((base + "f").c_str(), bench_f, k);
    benchmark::RegisterBenchmark((base + "grad").c_str(), bench_grad, k);
    benchmark::RegisterBenchmark((base + "f_and_grad").c_str(), bench_f_and_grad, k, Workload::default_points);
    benchmark::RegisterBenchmark((base + "f+central_fd").c_str(), bench_fd<true>, k);
    benchmark::RegisterBenchmark((base + "f+forward_fd").c_str(), bench_fd<false>, k);
  }
  for (const KernelKey& n : detailed_kernels) {
    const KernelRef* k = find_kernel(n.family, n.degree, n.weight_degree);
    if (!k) continue;
    benchmark::RegisterBenchmark(("eval/" + k->name + "/f_and_grad/near").c_str(), bench_f_and_grad, k, Workload::near);
    for (bool near : {false, true}) {
      for (const char* tol : {"1e-08", "1e-12"}) {
        benchmark::RegisterBenchmark(("quadrature/" + k->name + "/tol:" + tol + (near ? "/near" : "")).c_str(),
                                     bench_quadrature, k, std::stod(tol), near);
      }
    }
  }
  for (const KernelRef& k : generated_kernels()) {
    if (k.weight_degree != 0) continue;
    const std::string base =
        "degree/" + std::string(family_name(k.family)) + "/w0/i:" + std::to_string(k.degree) + "/";
    benchmark::RegisterBenchmark((base + "f").c_str(), bench_f, &k);
    benchmark::RegisterBenchmark((base + "f_and_grad").c_str(), bench_f_and_grad, &k, Workload::default_points);
  }
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  skelconv::bench::register_all();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
