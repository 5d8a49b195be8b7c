// bench/skeleton_bench.cpp — a whole skeleton on a grid:
// 1,000 compact-support segments, f and ∇f at every point of a
// 128³ grid, through the runtime's public API (skelconv::Skeleton).
//   skeleton/brute_force/grid:32    Skeleton::value_and_gradient over all
//       1,000 primitives, on the 32³ sub-grid (every 4th point of the 128³
//       grid in each direction); 128³ brute force would be 2·10⁹ primitive
//       evaluations, so its time is extrapolated (counter extrapolated_s_128).
//   skeleton/uniform_grid/grid:32   the same points through a uniform grid
//       of cells, each holding a Skeleton of the primitives whose support box
//       (segment bounding box grown by R) meets the cell;
//   skeleton/uniform_grid/grid:128  the full 128³ grid that way;
//   skeleton/build_uniform_grid     building that structure.
// Long runs print progress on stderr (points done, rate, time left).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench_main.hpp"
#include "skelconv/skeleton.hpp"

namespace skelconv::bench {
namespace {

struct Config {
  int primitives = 1000;
  int grid = 128;      // full grid: grid³ points in [0,1]³
  int sub_grid = 32;   // brute-force sub-grid
  int cells = 32;      // uniform grid: cells³ cells over [0,1]³
  double R = 0.06;     // support radius: each primitive touches a small neighbourhood
  int degree = 4;
};
Config config;

struct Primitive {
  Vec3 a, b;
};

std::vector<Primitive> random_segments() {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Primitive> out;
  for (int k = 0; k < config.primitives; ++k) {
    const Vec3 centre(0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng));
    Vec3 direction(normal(rng), normal(rng), normal(rng));
    direction.normalize();
    const double length = 0.05 + 0.1 * unit(rng);
    out.push_back({centre - 0.5 * length * direction, centre + 0.5 * length * direction});
  }
  return out;
}

Skeleton make_skeleton(const std::vector<Primitive>& segments) {
  Skeleton skeleton;
  for (const Primitive& s : segments) skeleton.add(Segment(s.a, s.b, KernelSpec::compact(config.degree, config.R)));
  return skeleton;
}

/// Point (i, j, k) of the n³ grid of cell centres over [0,1]³.
Vec3 grid_point(int n, int i, int j, int k) { return Vec3((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n); }

/// Progress on stderr for long loops: at most once a second, and only once
/// the loop has run for a second.
class Progress {
 public:
  Progress(std::string what, std::size_t total) : what_(std::move(what)), total_(total) {}
  void update(std::size_t done) {
    const double elapsed = seconds_since(start_);
    if (elapsed < 1.0 || seconds_since(last_) < 1.0) return;
    last_ = Clock::now();
    const double rate = double(done) / elapsed;
    std::fprintf(stderr, "  [%s] %zu/%zu points (%.0f%%), %.2f Mpoints/s, %.0f s left\n", what_.c_str(), done,
                 total_, 100.0 * double(done) / double(total_), rate * 1e-6, double(total_ - done) / rate);
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }
  std::string what_;
  std::size_t total_;
  Clock::time_point start_ = Clock::now(), last_ = start_;
};

/// The acceleration structure: a uniform grid of cells over [0,1]³; a cell
/// holds a Skeleton of the primitives whose support box meets it.
class UniformGrid {
 public:
  UniformGrid(const std::vector<Primitive>& segments, int cells) : n_(cells), cells_(std::size_t(cells) * cells * cells) {
    for (const Primitive& s : segments) {
      int lo[3], hi[3];
      for (int c = 0; c < 3; ++c) {
        lo[c] = clamp_cell(std::floor((std::min(s.a[c], s.b[c]) - config.R) * n_));
        hi[c] = clamp_cell(std::floor((std::max(s.a[c], s.b[c]) + config.R) * n_));
      }
      const Segment segment(s.a, s.b, KernelSpec::compact(config.degree, config.R));
      for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int k = lo[2]; k <= hi[2]; ++k) cells_[index(i, j, k)].add(segment);
    }
  }
  const Skeleton& cell_of(const Vec3& p) const {
    return cells_[index(clamp_cell(std::floor(p.x() * n_)), clamp_cell(std::floor(p.y() * n_)),
                        clamp_cell(std::floor(p.z() * n_)))];
  }
  FieldSample value_and_gradient(const Vec3& p) const { return cell_of(p).value_and_gradient(p); }

 private:
  int clamp_cell(double c) const { return std::clamp(int(c), 0, n_ - 1); }
  std::size_t index(int i, int j, int k) const { return (std::size_t(i) * n_ + j) * n_ + k; }
  int n_;
  std::vector<Skeleton> cells_;
};

const std::vector<Primitive>& segments() {
  static const std::vector<Primitive> s = random_segments();
  return s;
}

/// Evaluates `evaluate` on the sub-grid of the config.grid³ grid made of
/// every `stride`-th point; returns a checksum and fills `samples` if given.
template <class Evaluate>
double run_grid(int stride, const std::string& what, Evaluate evaluate, std::vector<FieldSample>* samples = nullptr) {
  const int n = config.grid / stride;
  Progress progress(what, std::size_t(n) * n * n);
  double checksum = 0;
  std::size_t done = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const FieldSample s = evaluate(grid_point(config.grid, i * stride, j * stride, k * stride));
        checksum += s.value + s.gradient.x();
        if (samples) samples->push_back(s);
      }
      done += std::size_t(n);
      progress.update(done);
    }
  }
  return checksum;
}

void set_per_point(benchmark::State& state, int stride) {
  const int n = config.grid / stride;
  const double points = double(n) * n * n;
  state.SetItemsProcessed(std::int64_t(state.iterations() * points));
  state.counters["points"] = points;
  state.counters["ns_per_point"] = benchmark::Counter(points * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                                         benchmark::Counter::kInvert);
}

void bench_brute_force(benchmark::State& state) {
  const Skeleton skeleton = make_skeleton(segments());
  const int stride = config.grid / config.sub_grid;
  for (auto _ : state) {
    double checksum = run_grid(stride, "brute force", [&](const Vec3& p) {
      return skeleton.value_and_gradient(p, Skeleton::Acceleration::plain);  // no index: every primitive
    });
    benchmark::DoNotOptimize(checksum);
  }
  set_per_point(state, stride);
  state.counters["primitives"] = config.primitives;
}

void bench_uniform_grid(benchmark::State& state, bool sub_grid) {
  const UniformGrid grid(segments(), config.cells);
  const int stride = sub_grid ? config.grid / config.sub_grid : 1;
  // Candidates per point, and agreement with brute force on the sub-grid.
  const int n = config.grid / stride;
  double candidates = 0;
  for (int i = 0; i < n; i += 2)
    for (int j = 0; j < n; j += 2)
      for (int k = 0; k < n; k += 2)
        candidates += double(grid.cell_of(grid_point(config.grid, i * stride, j * stride, k * stride)).size());
  const int half = (n + 1) / 2;
  state.counters["candidates_per_point"] = candidates / (double(half) * half * half);
  if (sub_grid) {
    const Skeleton skeleton = make_skeleton(segments());
    std::vector<FieldSample> brute, fast;
    run_grid(
        stride, "check",
        [&](const Vec3& p) { return skeleton.value_and_gradient(p, Skeleton::Acceleration::plain); }, &brute);
    run_grid(stride, "check", [&](const Vec3& p) { return grid.value_and_gradient(p); }, &fast);
    double diff = 0, scale = 0;
    for (std::size_t k = 0; k < brute.size(); ++k) {
      diff = std::max(diff, std::abs(brute[k].value - fast[k].value));
      scale = std::max(scale, std::abs(brute[k].value));
    }
    state.counters["max_rel_diff_vs_brute"] = diff / scale;
  }
  for (auto _ : state) {
    double checksum = run_grid(stride, "uniform grid", [&](const Vec3& p) { return grid.value_and_gradient(p); });
    benchmark::DoNotOptimize(checksum);
  }
  set_per_point(state, stride);
}

void bench_build(benchmark::State& state) {
  for (auto _ : state) {
    UniformGrid grid(segments(), config.cells);
    benchmark::DoNotOptimize(grid);
  }
  state.counters["cells"] = double(config.cells) * config.cells * config.cells;
}

void register_all() {
  const std::string sub = std::to_string(config.sub_grid), full = std::to_string(config.grid);
  benchmark::RegisterBenchmark("skeleton/build_uniform_grid", bench_build)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("skeleton/brute_force/grid:" + sub).c_str(), bench_brute_force)
      ->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
  benchmark::RegisterBenchmark(("skeleton/uniform_grid/grid:" + sub).c_str(), bench_uniform_grid, true)
      ->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
  benchmark::RegisterBenchmark(("skeleton/uniform_grid/grid:" + full).c_str(), bench_uniform_grid, false)
      ->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  // --smoke (CTest): 100 primitives, 16³ grid, 8³ sub-grid.
  if (skelconv::bench::take_flag(argc, argv, "--smoke")) {
    skelconv::bench::config.primitives = 100;
    skelconv::bench::config.grid = 16;
    skelconv::bench::config.sub_grid = 8;
    skelconv::bench::config.cells = 8;
  }
  std::fprintf(stderr, "skeleton: %d compact segments (degree %d, R = %g), %d^3 grid, brute force on %d^3, %d^3 cells\n",
               skelconv::bench::config.primitives, skelconv::bench::config.degree, skelconv::bench::config.R,
               skelconv::bench::config.grid, skelconv::bench::config.sub_grid, skelconv::bench::config.cells);
  skelconv::bench::register_all();
  return skelconv::bench::run_registered_benchmarks(argc, argv);
}
