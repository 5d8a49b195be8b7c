// bench/batch_bench.cpp — the batch (structure-of-arrays) API of
// bench/batch_eval.hpp against the scalar loop.
//   batch/<kernel>/scalar   one call per point through the generated table's
//                           function pointer (what the runtime does today);
//                           compact: skelconv::clip_to_ball with its branches,
//                           and no call when the clip is empty;
//   batch/<kernel>/simd     bench::f_and_grad_batch / compact_f_and_grad_batch:
//                           the generated *_f_and_grad_generic inlined in
//                           a loop GCC vectorises (AVX2), branch-free clip,
//                           then *_f_and_grad for the lanes it declined.
//   batch/<kernel>/runtime  one Segment::value_and_gradient per point (the
//                           runtime's scalar path, built for the baseline ISA:
//                           what skelconv::simd reproduces);
//   batch/<kernel>/highway  skelconv::simd::value_and_gradient (src/simd/,
//                           docs/simd.md), Highway's run-time choice (AVX-512
//                           here); /highway_avx2 forced to AVX2. Counters:
//                           set_aside_fraction (lanes re-run by form),
//                           scalar_fraction (points left to the scalar path),
//                           max_rel_diff against the runtime path.
//   batch/scalis_<family>_i<i>/{runtime,highway}: the same for SCALIS
//                           segments (radius 0.1 → 0.3, σ = 1.5);
//   batch/polygon_<family>_i<i>/{runtime,highway}: the same for a tilted
//                           quadrilateral across the segment (Polygon).
// Points: uniform in the segment's box grown by 1.5 R (about a third outside
// the compact support). Both variants write the same SoA outputs. Before
// any timing, every batch is checked against the scalar loop on these
// points (per point, relative 1e-13 plus 1e-15 of the batch's largest
// value — see relative_tolerance; the program fails otherwise, the smoke
// test too). Counters: max_rel_diff (per point), diff_over_tolerance (≤ 1
// passes), and fallback_fraction, the share of lanes the batch re-evaluated
// with the full scalar function.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "batch_kernels.hpp"
#include "bench_main.hpp"
#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/simd/batch.hpp"

namespace skelconv::bench {
namespace {

std::size_t batch_size = 4096;
/// The batch must reproduce the scalar path (a correctness check, not a
/// timing assertion). Per point and output (f, then ∇f as one vector, |·|∞):
///     |batch − scalar| ≤ 1e-13 |scalar| + 1e-15 max over the batch |scalar|
/// (relative 1e-13, plus an absolute term of a few ulps of the field's own
/// scale). The absolute term is for the rim of a compact support: there f
/// and ∇f are tiny (f ∝ (t1 − t0)^(i+1)), formed from q = c + t(at − 2b)
/// after cancellation, and their own relative rounding error grows past
/// 1e-13; vector and scalar code contract different products into FMAs, so
/// they round differently (measured: 2e-11 relative at f = 1e-10 of the
/// batch's largest value, i.e. |Δ| ~ 1e-20 of it).
constexpr double relative_tolerance = 1e-13;
constexpr double absolute_tolerance = 1e-15;  // times the batch's largest magnitude
constexpr std::size_t check_size = 4096;      // the benchmark's points, always

struct Agreement {
  double max_rel_diff = 0;  ///< per point, |Δ|/|scalar|, worst over the batch (information)
  double worst = 0;         ///< max |Δ| / (tolerance above): ≤ 1 passes
  std::size_t fallbacks = 0;  ///< lanes the batch re-evaluated with the full function
  std::size_t points = 0;
};

/// Batch against the scalar loop on the benchmark's 4,096 points.
Agreement compare(const KernelRef& k, BatchFunction batch) {
  Batch a(check_size), b(check_size);
  const Input segment = segment_input(k.family);
  scalar_loop(k, segment, a.points(), a.field());
  Agreement r;
  r.points = check_size;
  r.fallbacks = batch(segment, b.points(), b.field());
  auto gnorm = [](const Batch& x, std::size_t j) {
    return std::max({std::abs(x.gx[j]), std::abs(x.gy[j]), std::abs(x.gz[j])});
  };
  double f_max = 0, g_max = 0;
  for (std::size_t j = 0; j < check_size; ++j) {
    f_max = std::max(f_max, std::abs(a.f[j]));
    g_max = std::max(g_max, gnorm(a, j));
  }
  for (std::size_t j = 0; j < check_size; ++j) {
    const double df = std::abs(a.f[j] - b.f[j]);
    const double dg = std::max({std::abs(a.gx[j] - b.gx[j]), std::abs(a.gy[j] - b.gy[j]), std::abs(a.gz[j] - b.gz[j])});
    const double f_scale = std::abs(a.f[j]), g_scale = gnorm(a, j);
    const double worst = std::max(df / (relative_tolerance * f_scale + absolute_tolerance * f_max),
                                  dg / (relative_tolerance * g_scale + absolute_tolerance * g_max));
    const double rel = std::max(f_scale > 0 ? df / f_scale : df, g_scale > 0 ? dg / g_scale : dg);
    // NaN anywhere counts as a disagreement.
    r.worst = std::isnan(worst) ? INFINITY : std::max(r.worst, worst);
    r.max_rel_diff = std::isnan(rel) ? INFINITY : std::max(r.max_rel_diff, rel);
  }
  return r;
}

/// Every batch entry against the scalar path; false when one disagrees.
bool check_all() {
  bool ok = true;
  for (const BatchEntry& e : batch_entries) {
    const KernelRef* k = find_kernel(e.key.family, e.key.degree, e.key.weight_degree);
    if (!k) continue;
    const Agreement r = compare(*k, e.batch);
    const bool good = r.worst <= 1.0;
    std::fprintf(stderr,
                 "batch check %-22s per-point rel diff %.1e, |diff|/tolerance %.2f, %4zu of %zu lanes re-evaluated "
                 "by f_and_grad: %s\n",
                 k->name.c_str(), r.max_rel_diff, r.worst, r.fallbacks, r.points, good ? "ok" : "FAILED");
    ok = ok && good;
  }
  return ok;
}

void bench_scalar(benchmark::State& state, const KernelRef* k) {
  Batch batch(batch_size);
  const Input segment = segment_input(k->family);
  for (auto _ : state) {
    scalar_loop(*k, segment, batch.points(), batch.field());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
}

void bench_simd(benchmark::State& state, const KernelRef* k, BatchFunction function) {
  const Agreement agreement = compare(*k, function);
  Batch batch(batch_size);
  const Input segment = segment_input(k->family);
  for (auto _ : state) {
    benchmark::DoNotOptimize(function(segment, batch.points(), batch.field()));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
  state.counters["max_rel_diff"] = agreement.max_rel_diff;
  state.counters["diff_over_tolerance"] = agreement.worst;
  state.counters["fallback_fraction"] = double(agreement.fallbacks) / double(agreement.points);
}

/// The runtime's Segment with the benchmark's A, B, weight, s and R.
Segment runtime_segment(const KernelRef& k) {
  // Each family reads only its own parameters (kernel_spec.hpp).
  KernelSpec spec;
  spec.family = k.family;
  spec.degree = k.degree;
  spec.s = bench_s;
  spec.R = bench_R;
  return Segment(Vec3(bench_a[0], bench_a[1], bench_a[2]), Vec3(bench_b[0], bench_b[1], bench_b[2]), spec,
                 std::span<const double>(bench_weight.data(), std::size_t(k.weight_degree + 1)));
}

void runtime_loop(const Segment& segment, PointsSoA p, FieldSoA out) {
  for (std::size_t j = 0; j < p.n; ++j) {
    const FieldSample s = segment.value_and_gradient(Vec3(p.x[j], p.y[j], p.z[j]));
    out.f[j] = s.value;
    out.gx[j] = s.gradient[0];
    out.gy[j] = s.gradient[1];
    out.gz[j] = s.gradient[2];
  }
}

void bench_runtime(benchmark::State& state, const KernelRef* k) {
  Batch batch(batch_size);
  const Segment segment = runtime_segment(*k);
  for (auto _ : state) {
    runtime_loop(segment, batch.points(), batch.field());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
}

simd::BatchCounts highway(const Segment& segment, const Batch& batch, Batch& out) {
  return simd::value_and_gradient(segment, {batch.x.data(), batch.y.data(), batch.z.data(), batch.x.size()},
                                  {out.f.data(), out.gx.data(), out.gy.data(), out.gz.data()});
}

/// skelconv::simd on `target` ("" = Highway's choice); checked against the
/// runtime path on the same points first (ctest checks 1e-13 on every form).
void bench_highway(benchmark::State& state, const KernelRef* k, std::string target) {
  if (!simd::force_target(target)) {
    state.SkipWithError(("target " + target + " not available").c_str());
    return;
  }
  const Segment segment = runtime_segment(*k);
  Batch batch(batch_size), reference(batch_size);
  runtime_loop(segment, reference.points(), reference.field());
  const simd::BatchCounts counts = highway(segment, reference, batch);
  double max_rel = 0;
  for (std::size_t j = 0; j < batch_size; ++j) {
    const double g = std::max({std::abs(reference.gx[j]), std::abs(reference.gy[j]), std::abs(reference.gz[j])});
    const double df = reference.f[j] == batch.f[j] ? 0 : std::abs(reference.f[j] - batch.f[j]) / std::abs(reference.f[j]);
    const double dg = std::max({std::abs(reference.gx[j] - batch.gx[j]), std::abs(reference.gy[j] - batch.gy[j]),
                                std::abs(reference.gz[j] - batch.gz[j])});
    max_rel = std::max({max_rel, df, g > 0 ? dg / g : dg});
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(highway(segment, reference, batch));
    benchmark::ClobberMemory();
  }
  simd::force_target("");
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
  state.SetLabel(target.empty() ? simd::active_target() : target);
  state.counters["max_rel_diff"] = max_rel;
  state.counters["set_aside_fraction"] = double(counts.set_aside) / double(batch_size);
  state.counters["scalar_fraction"] = double(counts.scalar_points) / double(batch_size);
}

/// SCALIS segments (radius 0.1 → 0.3, σ = 1.5, as bench/scalis_bench.cpp):
/// the runtime per point against the Highway batch, on the same points.
template <class Primitive>
void runtime_points(const Primitive& primitive, const Batch& in, Batch& out) {
  for (std::size_t j = 0; j < in.x.size(); ++j) {
    const FieldSample s = primitive.value_and_gradient(Vec3(in.x[j], in.y[j], in.z[j]));
    out.f[j] = s.value;
    out.gx[j] = s.gradient[0];
    out.gy[j] = s.gradient[1];
    out.gz[j] = s.gradient[2];
  }
}

ScalisSegment bench_scalis(KernelFamily family, int degree) {
  return ScalisSegment(Vec3(bench_a[0], bench_a[1], bench_a[2]), Vec3(bench_b[0], bench_b[1], bench_b[2]), 0.1, 0.3,
                       ScalisKernel{family, degree, 1.5}, 1.0);
}

/// A tilted quadrilateral spanned by the bench segment AB and a vector
/// across it, in the middle of the points' box.
Polygon bench_polygon(const KernelSpec& kernel) {
  const Vec3 a(bench_a[0], bench_a[1], bench_a[2]), b(bench_b[0], bench_b[1], bench_b[2]);
  const Vec3 across = 0.6 * (b - a).unitOrthogonal() + Vec3(0.0, 0.0, 0.1);
  return Polygon({a, b, b + across, a + 0.8 * across}, kernel);
}

/// The runtime per point (SCALIS segments, polygons).
template <class Primitive>
void bench_primitive_runtime(benchmark::State& state, const Primitive& primitive) {
  Batch batch(batch_size), out(batch_size);
  for (auto _ : state) {
    runtime_points(primitive, batch, out);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
}

/// skelconv::simd on the same points, checked against the runtime first.
template <class Primitive>
void bench_primitive_highway(benchmark::State& state, const Primitive& primitive) {
  Batch batch(batch_size), reference(batch_size);
  runtime_points(primitive, batch, reference);
  auto run = [&] {
    return simd::value_and_gradient(primitive, {batch.x.data(), batch.y.data(), batch.z.data(), batch_size},
                                    {batch.f.data(), batch.gx.data(), batch.gy.data(), batch.gz.data()});
  };
  const simd::BatchCounts counts = run();
  double max_rel = 0;
  for (std::size_t j = 0; j < batch_size; ++j) {
    const double g = std::max({std::abs(reference.gx[j]), std::abs(reference.gy[j]), std::abs(reference.gz[j])});
    const double df = reference.f[j] == batch.f[j] ? 0 : std::abs(reference.f[j] - batch.f[j]) / std::abs(reference.f[j]);
    const double dg = std::max({std::abs(reference.gx[j] - batch.gx[j]), std::abs(reference.gy[j] - batch.gy[j]),
                                std::abs(reference.gz[j] - batch.gz[j])});
    max_rel = std::max({max_rel, df, g > 0 ? dg / g : dg});
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(run());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
  state.SetLabel(simd::active_target());
  state.counters["max_rel_diff"] = max_rel;
  state.counters["set_aside_fraction"] = double(counts.set_aside) / double(batch_size);
  state.counters["scalar_fraction"] = double(counts.scalar_points) / double(batch_size);
}

void register_all() {
  for (const auto& [family, degree] : {std::pair{KernelFamily::inverse, 3}, std::pair{KernelFamily::cauchy, 4}}) {
    const std::string name = "batch/scalis_" + std::string(family_name(family)) + "_i" + std::to_string(degree);
    const ScalisSegment segment = bench_scalis(family, degree);
    benchmark::RegisterBenchmark((name + "/runtime").c_str(), bench_primitive_runtime<ScalisSegment>, segment);
    benchmark::RegisterBenchmark((name + "/highway").c_str(), bench_primitive_highway<ScalisSegment>, segment);
  }
  for (const KernelSpec& kernel : {KernelSpec::inverse(3), KernelSpec::cauchy(4, 2.0)}) {
    const std::string name = "batch/polygon_" + std::string(family_name(kernel.family)) + "_i" +
                             std::to_string(kernel.degree);
    const Polygon polygon = bench_polygon(kernel);
    benchmark::RegisterBenchmark((name + "/runtime").c_str(), bench_primitive_runtime<Polygon>, polygon);
    benchmark::RegisterBenchmark((name + "/highway").c_str(), bench_primitive_highway<Polygon>, polygon);
  }
  for (const BatchEntry& e : batch_entries) {
    const KernelRef* k = find_kernel(e.key.family, e.key.degree, e.key.weight_degree);
    if (!k) continue;
    benchmark::RegisterBenchmark(("batch/" + k->name + "/scalar").c_str(), bench_scalar, k);
    benchmark::RegisterBenchmark(("batch/" + k->name + "/simd").c_str(), bench_simd, k, e.batch);
    benchmark::RegisterBenchmark(("batch/" + k->name + "/runtime").c_str(), bench_runtime, k);
    benchmark::RegisterBenchmark(("batch/" + k->name + "/highway").c_str(), bench_highway, k, std::string());
    benchmark::RegisterBenchmark(("batch/" + k->name + "/highway_avx2").c_str(), bench_highway, k,
                                 std::string("AVX2"));
  }
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  // --smoke (CTest): tiny batches.
  if (skelconv::bench::take_flag(argc, argv, "--smoke")) skelconv::bench::batch_size = 64;
  // Batch and scalar must agree (on every run, smoke test included).
  if (!skelconv::bench::check_all()) {
    std::fprintf(stderr, "batch and scalar results disagree beyond %.0e relative (+ %.0e absolute)\n",
                 skelconv::bench::relative_tolerance, skelconv::bench::absolute_tolerance);
    return 1;
  }
  skelconv::bench::register_all();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
