// bench/filter_bench.cpp — the filtered segment kernels against the stable
// ones (skelconv/kernels/segment_filter.hpp):
//   filter/<kernel>/<band>/<stable|fast|filtered>/<f|f_and_grad>
// with bands of distance from the segment 0.01–0.1, 0.1–1 and 1–10 |AB|
// (1024 points each, every direction, beyond the ends too; compact kernels
// get a support holding the whole segment). The counter `accepted` is the
// fraction of points the filter let through at the default tolerance.
// stable: the runtime library's generated function (the fallback); fast:
// the fast form alone on double, without its bound (what the formula costs);
// filtered: fast form, bound and fallback. Compare times within one run only.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <skelconv/kernels/segment_filter.hpp>

#include "bench_main.hpp"
#include "bench_support.hpp"
#include "fast_forms.hpp"

namespace skelconv::bench {
namespace {

constexpr std::size_t kPoints = 1024;  // a power of two: index & (count − 1)

struct Band {
  const char* name;
  double lo, hi;  // × |AB|
};
constexpr Band kBands[] = {{"0.01-0.1", 0.01, 0.1}, {"0.1-1", 0.1, 1}, {"1-10", 1, 10}};

std::vector<Input> band_inputs(KernelFamily family, const Band& band) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> u(0, 1);
  const Vec ab{bench_b[0] - bench_a[0], bench_b[1] - bench_a[1], bench_b[2] - bench_a[2]};
  const double L = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
  std::vector<Input> out;
  while (out.size() < kPoints) {
    // A point of the segment's surroundings at the band's distance: a random
    // direction from a random point of [−0.5, 1.5] along AB, scaled so that
    // the distance to the segment lands in the band.
    Input in = segment_input(family);
    const double t = -0.5 + 2 * u(rng);
    const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), r = std::sqrt(1 - z * z);
    const Vec dir{r * std::cos(phi), r * std::sin(phi), z};
    const double target = L * band.lo * std::pow(band.hi / band.lo, u(rng));
    for (int c = 0; c < 3; ++c) in.p[c] = bench_a[c] + t * ab[c] + target * dir[c];
    const double d = distance_to_segment(in.p);
    if (d < L * band.lo || d > L * band.hi) continue;
    in.R = 2 * (d + L);
    if (!clip_compact_support(family, in)) continue;
    out.push_back(in);
  }
  return out;
}

/// What a benchmark times: the runtime's stable function, the fast form
/// alone on double (no bound: the formula's own cost), or the filter.
enum class Path { stable, fast, filtered };

template <Path path, bool gradient>
void bench_eval(benchmark::State& state, const FilteredSegmentKernel* k, const FastForm* fast,
                std::vector<Input> inputs) {
  std::size_t idx = 0, accepted = 0;
  for (auto _ : state) {
    const Input& in = inputs[idx++ & (kPoints - 1)];
    bool ok = false;
    if constexpr (gradient) {
      std::array<double, 3> g;
      double f;
      if constexpr (path == Path::stable) f = k->stable_f_and_grad(in, g);
      else if constexpr (path == Path::fast) f = fast->f_and_grad(in, g);
      else f = k->f_and_grad(in, g, kDefaultFilterTolerance, &ok);
      benchmark::DoNotOptimize(f);
      benchmark::DoNotOptimize(g);
    } else {
      double f;
      if constexpr (path == Path::stable) f = k->stable_f(in);
      else if constexpr (path == Path::fast) f = fast->f(in);
      else f = k->f(in, kDefaultFilterTolerance, &ok);
      benchmark::DoNotOptimize(f);
    }
    accepted += ok;
  }
  state.SetItemsProcessed(state.iterations());
  if (path == Path::filtered) state.counters["accepted"] = double(accepted) / double(state.iterations());
}

void register_all() {
  for (const KernelKey& n : detailed_kernels) {
    const std::optional<FilterPaths> paths = filter_paths(n);
    if (!paths) continue;
    const auto [k, ref, fast] = *paths;
    for (const Band& band : kBands) {
      const std::vector<Input> in = band_inputs(n.family, band);
      const std::string base = "filter/" + ref->name + "/" + band.name + "/";
      benchmark::RegisterBenchmark((base + "stable/f").c_str(), bench_eval<Path::stable, false>, k, fast, in);
      benchmark::RegisterBenchmark((base + "fast/f").c_str(), bench_eval<Path::fast, false>, k, fast, in);
      benchmark::RegisterBenchmark((base + "filtered/f").c_str(), bench_eval<Path::filtered, false>, k, fast, in);
      benchmark::RegisterBenchmark((base + "stable/f_and_grad").c_str(), bench_eval<Path::stable, true>, k, fast, in);
      benchmark::RegisterBenchmark((base + "fast/f_and_grad").c_str(), bench_eval<Path::fast, true>, k, fast, in);
      benchmark::RegisterBenchmark((base + "filtered/f_and_grad").c_str(), bench_eval<Path::filtered, true>, k, fast,
                                   in);
    }
  }
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  skelconv::bench::register_all();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
