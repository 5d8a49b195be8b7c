// bench/public_path_bench.cpp — the public evaluation paths against the
// generated function they wrap, on the same points, in one run.
//
// Skeletons of Cauchy 4 segments, SCALIS (docs/mathematics.md §4; argument kind 0) or
// classical convolution with s = 1 (docs/mathematics.md §2; kind 1): 1 segment, the 24 of
// Zanni's ant (papers_figures/skeletons/zanni_table1_ant.json; its axes for
// the classical kind) and 1,000 random ones; arguments kind, primitives.
// Every benchmark reports ns_per_primitive_point (time per point divided by
// the number of primitives); each public path also reports
// ratio_vs_generated: its time over the generated function's on the same
// points, the two timed back to back in every iteration (bench_public).
//   generated_f_and_grad/N   the generated function (scalis_segment_cauchy_i4
//                            or segment_cauchy_i4_w0) for f+∇f,
//                            called directly on inputs prepared once per
//                            primitive (frame points by one power-of-two
//                            product; the kernel's `prepare` once, then
//                            its per-point part), summed over the primitives;
//   generated_f/N            the same, f alone;
//   value_and_gradient/N     Skeleton::value_and_gradient, point by point;
//   batch/N                  evaluate_batch (field/batch.hpp), one thread,
//                            into a new vector of samples;
//   batch_into/N             evaluate_batch_into into arrays allocated once:
//                            what the Python module's Skeleton.field runs;
//   mesher_value/N           the mesher's adaptor (mesh/implicit_field.hpp)
//                            ImplicitField::value, through its std::function;
//   mesher_value_and_gradient/N  ImplicitField::value_and_gradient.
// Single thread. Points: uniform in the skeleton's box grown by its largest
// radius or segment length (the region a mesher samples).
// Compiled with the runtime's flags (bench/CMakeLists.txt says why).
//
// `--counts`: instead of timing, one pass of each path but the mesher's
// over the first count_points points of every skeleton, each between
// callgrind client requests described "public/<kind>/<primitives>/<path>|<evaluations>"
// (scripts/bench.sh runs it under callgrind; bench/summarize.py divides by
// the evaluations: instructions per primitive and point, repeatable where
// the times are not).
#include <benchmark/benchmark.h>
#include <valgrind/callgrind.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "bench_main.hpp"
#include "generated/scalis_segment_table.hpp"
#include "skelconv/field/batch.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/kernels/segment_kernel_tables.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::bench {
namespace {

/// Points per benchmark pass, per skeleton size: about 2·10⁶ primitive
/// evaluations each, a pass of ~0.1 s.
std::size_t point_count(std::size_t primitives) { return std::max<std::size_t>(200, 2'000'000 / primitives); }

Skeleton random_skeleton(int count) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Skeleton skeleton;
  for (int k = 0; k < count; ++k) {
    const Vec3 centre(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const double length = 0.5 + unit(rng);
    skeleton.add(ScalisSegment(centre - 0.5 * length * direction, centre + 0.5 * length * direction,
                               0.1 + 0.3 * unit(rng), 0.1 + 0.3 * unit(rng), ScalisKernel::cauchy(4, 1.0)));
  }
  return skeleton;
}

/// The SCALIS skeletons, by number of primitives.
const Skeleton& scalis_skeleton_of(std::size_t primitives) {
  static std::map<std::size_t, Skeleton> cache;
  auto [it, inserted] = cache.try_emplace(primitives);
  if (inserted) {
    if (primitives == 1) {
      it->second.add(ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0.2, 0), 0.3, 0.2, ScalisKernel::cauchy(4, 1.0)));
    } else if (primitives == 24) {
      it->second = load_skeleton_file(SKELCONV_ANT_SKELETON);
    } else {
      it->second = random_skeleton(int(primitives));
    }
  }
  return it->second;
}

/// Classical Cauchy 4 segments (s = 1) on the same axes.
const Skeleton& classical_skeleton_of(std::size_t primitives) {
  static std::map<std::size_t, Skeleton> cache;
  auto [it, inserted] = cache.try_emplace(primitives);
  if (inserted) {
    for (const Primitive& p : scalis_skeleton_of(primitives).primitives()) {
      const auto& s = std::get<ScalisSegment>(p);
      it->second.add(Segment(s.a(), s.b(), KernelSpec::cauchy(4, 1.0)));
    }
  }
  return it->second;
}

const Skeleton& skeleton_of(int kind, std::size_t primitives) {
  return kind == 0 ? scalis_skeleton_of(primitives) : classical_skeleton_of(primitives);
}

const std::vector<Vec3>& points_of(std::size_t primitives) {
  static std::map<std::size_t, std::vector<Vec3>> cache;
  auto [it, inserted] = cache.try_emplace(primitives);
  if (inserted) {
    Eigen::AlignedBox3d box;
    double margin = 0;
    for (const Primitive& p : scalis_skeleton_of(primitives).primitives()) {
      const auto& s = std::get<ScalisSegment>(p);
      box.extend(s.a());
      box.extend(s.b());
      margin = std::max({margin, s.tau0(), s.tau1(), (s.b() - s.a()).norm()});
    }
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec3 lo = box.min() - Vec3::Constant(margin), size = box.sizes() + Vec3::Constant(2 * margin);
    for (std::size_t k = 0; k < point_count(primitives); ++k)
      it->second.push_back(lo + size.cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng))));
  }
  return it->second;
}

/// One primitive as the generated function sees it: its input in its own
/// frame (scaled_frame.hpp) but for P, the factor 2^−e of that frame, and
/// for a classical segment its kernel's preparation (`prepare`, once).
template <class Input>
struct RawPrimitive {
  Input input;
  double to_frame = 1;
  std::vector<double> prepared;
};

std::vector<RawPrimitive<ScalisSegmentInput<double>>> raw_scalis(std::size_t primitives) {
  std::vector<RawPrimitive<ScalisSegmentInput<double>>> raw;
  for (const Primitive& p : scalis_skeleton_of(primitives).primitives()) {
    const auto& s = std::get<ScalisSegment>(p);
    const ScaledFrame frame(scale_safe_norm(s.b() - s.a()));
    RawPrimitive<ScalisSegmentInput<double>> r;
    r.input.a = to_array(frame.point(s.a()));
    r.input.b = to_array(frame.point(s.b()));
    r.input.tau0 = frame.length(s.tau0());
    r.input.tau1 = frame.length(s.tau1());
    r.input.sigma = s.kernel().sigma;
    r.to_frame = std::ldexp(1.0, -frame.exponent());
    const auto* kernel = generated::find_scalis_segment_kernel<double>(KernelFamily::cauchy, 4);
    r.prepared.resize(kernel->prepared_size);
    kernel->prepare(r.input, r.prepared.data());
    raw.push_back(r);
  }
  return raw;
}

std::vector<RawPrimitive<SegmentInput<double>>> raw_classical(std::size_t primitives) {
  std::vector<RawPrimitive<SegmentInput<double>>> raw;
  for (const Primitive& p : classical_skeleton_of(primitives).primitives()) {
    const auto& s = std::get<Segment>(p);
    const ScaledFrame frame(scale_safe_norm(s.b() - s.a()));
    RawPrimitive<SegmentInput<double>> r;
    r.input.a = to_array(frame.point(s.a()));
    r.input.b = to_array(frame.point(s.b()));
    r.input.w = {1.0, 0.0, 0.0, 0.0};
    r.input.s = frame.scaled(s.kernel().s, -2);
    r.to_frame = std::ldexp(1.0, -frame.exponent());
    const auto* kernel = find_any_segment_kernel<double>(KernelFamily::cauchy, 4, 0);
    r.prepared.resize(kernel->prepared_size);
    kernel->prepare(r.input, r.prepared.data());
    raw.push_back(r);
  }
  return raw;
}

/// Σ over points and primitives of the generated function `kernel`.
template <bool with_gradient, class Kernel, class Input>
double run_generated(const Kernel* kernel, const std::vector<RawPrimitive<Input>>& raw,
                     const std::vector<Vec3>& points) {
  double sum = 0;
  for (const Vec3& p : points) {
    for (const RawPrimitive<Input>& r : raw) {
      // The kernel's per-point part, on its preparation: it reads P (and a
      // classical segment the clip, [0, 1] for Cauchy).
      const std::array<double, 3> frame_p{p.x() * r.to_frame, p.y() * r.to_frame, p.z() * r.to_frame};
      const auto point = [&] {
        if constexpr (std::is_same_v<Input, SegmentInput<double>>)
          return SegmentPoint<double>{frame_p};
        else
          return frame_p;
      }();
      if constexpr (with_gradient) {
        std::array<double, 3> g;
        sum += kernel->f_and_grad_at(r.prepared.data(), point, g) + g[0];
      } else {
        sum += kernel->f_at(r.prepared.data(), point);
      }
    }
  }
  return sum;
}

/// ns_per_primitive_point is timed around the whole benchmark loop (wall
/// clock, one thread), the same way for every path, so that the ratios
/// compare like with like.
void report(benchmark::State& state, std::size_t primitives, double ns_per_primitive_point) {
  const double evaluations = double(points_of(primitives).size()) * double(primitives);
  state.SetItemsProcessed(std::int64_t(double(state.iterations()) * evaluations));
  state.counters["ns_per_primitive_point"] = ns_per_primitive_point;
  state.counters["primitives"] = double(primitives);
}

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

/// One pass of the generated function over `points` for skeleton (kind, n).
template <bool with_gradient>
class GeneratedPass {
 public:
  GeneratedPass(int kind, std::size_t n) : kind_(kind), scalis_(raw_scalis(n)), classical_(raw_classical(n)) {}
  double operator()(const std::vector<Vec3>& points) const {
    return kind_ == 0 ? run_generated<with_gradient>(scalis_kernel_, scalis_, points)
                      : run_generated<with_gradient>(classical_kernel_, classical_, points);
  }

 private:
  int kind_;
  std::vector<RawPrimitive<ScalisSegmentInput<double>>> scalis_;
  std::vector<RawPrimitive<SegmentInput<double>>> classical_;
  const generated::ScalisSegmentKernel<double>* scalis_kernel_ =
      generated::find_scalis_segment_kernel<double>(KernelFamily::cauchy, 4);
  const generated::SegmentKernel<double>* classical_kernel_ = find_any_segment_kernel<double>(KernelFamily::cauchy, 4, 0);
};

template <bool with_gradient>
void bench_generated(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(1));
  const std::vector<Vec3>& points = points_of(n);
  const GeneratedPass<with_gradient> pass(int(state.range(0)), n);
  const auto start = Clock::now();
  std::int64_t passes = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pass(points));
    ++passes;
  }
  report(state, n, seconds_between(start, Clock::now()) * 1e9 / (double(passes) * double(points.size()) * double(n)));
}

/// A public path: `evaluate(skeleton, points)` returns a checksum. Every
/// iteration times one pass of it and one pass of the generated function
/// (f+∇f or f, as the path) on the same points, back to back, so that the
/// ratio compares two measurements taken under the same load.
template <bool with_gradient, class Evaluate>
void bench_public(benchmark::State& state, Evaluate evaluate) {
  const int kind = int(state.range(0));
  const std::size_t n = std::size_t(state.range(1));
  const Skeleton& skeleton = skeleton_of(kind, n);
  const std::vector<Vec3>& points = points_of(n);
  const GeneratedPass<with_gradient> generated_pass(kind, n);
  skeleton.prepare();
  double public_seconds = 0, generated_seconds = 0;
  std::int64_t passes = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    benchmark::DoNotOptimize(evaluate(skeleton, points));
    const auto t1 = Clock::now();
    benchmark::DoNotOptimize(generated_pass(points));
    public_seconds += seconds_between(t0, t1);
    generated_seconds += seconds_between(t1, Clock::now());
    ++passes;
  }
  state.counters["ratio_vs_generated"] = public_seconds / generated_seconds;
  report(state, n, public_seconds * 1e9 / (double(passes) * double(points.size()) * double(n)));
}

void bench_value_and_gradient(benchmark::State& state) {
  bench_public<true>(state, [](const Skeleton& skeleton, const std::vector<Vec3>& points) {
    double sum = 0;
    for (const Vec3& p : points) {
      const FieldSample s = skeleton.value_and_gradient(p);
      sum += s.value + s.gradient.x();
    }
    return sum;
  });
}

void bench_batch(benchmark::State& state) {
  bench_public<true>(state, [](const Skeleton& skeleton, const std::vector<Vec3>& points) {
    const BatchResult result = evaluate_batch(skeleton, points, {.threads = 1});
    return result.samples.back().value;
  });
}

void bench_batch_into(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(1));
  std::vector<double> xyz;
  for (const Vec3& p : points_of(n)) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  std::vector<double> values(xyz.size() / 3), gradients(xyz.size());
  bench_public<true>(state, [&](const Skeleton& skeleton, const std::vector<Vec3>&) {
    (void)evaluate_batch_into(skeleton, xyz, values, gradients, {.threads = 1});
    return values.back();
  });
}

void bench_mesher_value(benchmark::State& state) {
  const ImplicitField field = skeleton_field(skeleton_of(int(state.range(0)), std::size_t(state.range(1))));
  bench_public<false>(state, [&field](const Skeleton&, const std::vector<Vec3>& points) {
    double sum = 0;
    for (const Vec3& p : points) sum += field.value(p);
    return sum;
  });
}

void bench_mesher_value_and_gradient(benchmark::State& state) {
  const ImplicitField field = skeleton_field(skeleton_of(int(state.range(0)), std::size_t(state.range(1))));
  bench_public<true>(state, [&field](const Skeleton&, const std::vector<Vec3>& points) {
    double sum = 0;
    for (const Vec3& p : points) {
      const FieldSample s = field.value_and_gradient(p);
      sum += s.value + s.gradient.x();
    }
    return sum;
  });
}

/// Points per skeleton in --counts mode: enough that what a pass pays once
/// (the batch's set-up, the index's walk to its first leaf) is a few percent.
constexpr std::size_t count_points = 200;

/// --counts: the callgrind regions (file comment).
int run_counts() {
  for (int kind : {0, 1}) {
    for (std::size_t n : {std::size_t(1), std::size_t(24), std::size_t(1000)}) {
      const Skeleton& skeleton = skeleton_of(kind, n);
      skeleton.prepare();
      const std::vector<Vec3> points(points_of(n).begin(), points_of(n).begin() + count_points);
      const std::string base = "public/" + std::to_string(kind) + "/" + std::to_string(n) + "/";
      const std::string evaluations = "|" + std::to_string(count_points * n);
      double sink = 0;
      const auto region = [&](const std::string& path, auto&& pass) {
        const std::string description = base + path + evaluations;
        // A first, uncounted pass: the one-off costs of a path's first use
        // (lazy tables, the dynamic linker's symbol lookups, cold caches of
        // the allocator) are not costs per point.
        sink += pass();
        CALLGRIND_ZERO_STATS;
        sink += pass();
        CALLGRIND_DUMP_STATS_AT(description.c_str());
      };
      const GeneratedPass<true> generated_f_and_grad(kind, n);
      const GeneratedPass<false> generated_f(kind, n);
      region("generated_f_and_grad", [&] { return generated_f_and_grad(points); });
      region("generated_f", [&] { return generated_f(points); });
      region("value_and_gradient", [&] {
        double sum = 0;
        for (const Vec3& p : points) sum += skeleton.value_and_gradient(p).value;
        return sum;
      });
      region("value", [&] {
        double sum = 0;
        for (const Vec3& p : points) sum += skeleton.value(p);
        return sum;
      });
      std::vector<double> xyz;
      for (const Vec3& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
      std::vector<double> values(points.size()), gradients(xyz.size());
      region("batch_into", [&] {
        (void)evaluate_batch_into(skeleton, xyz, values, gradients, {.threads = 1});
        return values.back();
      });
      benchmark::DoNotOptimize(sink);
    }
  }
  std::printf("done: %s\n", RUNNING_ON_VALGRIND ? "under valgrind" : "not under valgrind (client requests ignored)");
  return 0;
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgsProduct({{0, 1}, {1, 24, 1000}})->ArgNames({"kind", "primitives"})->Unit(benchmark::kMillisecond);
}

BENCHMARK(bench_generated<true>)->Name("generated_f_and_grad")->Apply(sizes);
BENCHMARK(bench_generated<false>)->Name("generated_f")->Apply(sizes);
BENCHMARK(bench_value_and_gradient)->Name("value_and_gradient")->Apply(sizes);
BENCHMARK(bench_batch)->Name("batch")->Apply(sizes);
BENCHMARK(bench_batch_into)->Name("batch_into")->Apply(sizes);
BENCHMARK(bench_mesher_value)->Name("mesher_value")->Apply(sizes);
BENCHMARK(bench_mesher_value_and_gradient)->Name("mesher_value_and_gradient")->Apply(sizes);

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  if (skelconv::bench::take_flag(argc, argv, "--counts")) return skelconv::bench::run_counts();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
