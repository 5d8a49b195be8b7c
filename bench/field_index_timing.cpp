// bench/field_index_timing.cpp — the field of many compact primitives on a
// grid, with and without the runtime's bounding-volume index
// (docs/field.md, "Measured").
//
// One run measures, on the same skeleton and the same machine state:
//   indexed, 1 thread    evaluate_batch over the full grid³ grid (cell
//                        centres of [0,1]³), Acceleration::indexed;
//   indexed, all cores   the same, every core (and checks the bytes agree);
//   plain, 1 thread      Acceleration::plain (every primitive at every
//                        point) on the sub-grid of every `stride`-th point
//                        in each direction (the full grid would take
//                        ~100× the indexed time), and indexed on the same
//                        sub-grid;
// and prints ns per point of each, the ratio plain / indexed on the same
// points, and checks
// that indexed and plain agree bit for bit on the sub-grid (exit 1 if not).
// Nothing about time is asserted.
//
// Skeleton: `--primitives` compact-support primitives in [0.1, 0.9]³, the
// workload of bench/skeleton_bench.cpp (segments of length 0.05–0.15,
// k_R^4 with R = 0.06) with every 4th primitive a compact point (R = 0.06)
// instead.
//
// Usage: skelconv_field_index_timing [--grid N] [--stride S] [--primitives P] [--smoke]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "skelconv/field/batch.hpp"
#include "skelconv/skeleton.hpp"

namespace {

using namespace skelconv;
using Clock = std::chrono::steady_clock;

struct Config {
  int grid = 128;
  int stride = 4;
  int primitives = 1000;
  double R = 0.06;
  int degree = 4;
};

Skeleton make_skeleton(const Config& config) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Skeleton skeleton;
  for (int k = 0; k < config.primitives; ++k) {
    const Vec3 centre(0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng));
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const double length = 0.05 + 0.1 * unit(rng);
    if (k % 4 == 3) {
      skeleton.add(PointPrimitive(centre, KernelSpec::compact(config.degree, config.R)));
    } else {
      skeleton.add(Segment(centre - 0.5 * length * direction, centre + 0.5 * length * direction,
                           KernelSpec::compact(config.degree, config.R)));
    }
  }
  return skeleton;
}

/// Cell centres of the n³ grid over [0,1]³, every `stride`-th in each direction.
std::vector<Vec3> grid_points(int n, int stride) {
  std::vector<Vec3> points;
  for (int i = 0; i < n; i += stride)
    for (int j = 0; j < n; j += stride)
      for (int k = 0; k < n; k += stride) points.emplace_back((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
  return points;
}

/// Seconds per point of evaluate_batch on `points`.
double seconds_per_point(const Skeleton& skeleton, const std::vector<Vec3>& points, unsigned threads,
                         Skeleton::Acceleration acceleration, BatchResult& result) {
  BatchOptions options;
  options.threads = threads;
  options.acceleration = acceleration;
  const auto start = Clock::now();
  result = evaluate_batch(skeleton, points, options);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (result.failure) {
    std::fprintf(stderr, "evaluation failed at point %zu\n", result.failure->index);
    std::exit(1);
  }
  return seconds / double(points.size());
}

bool same_bytes(const std::vector<FieldSample>& a, const std::vector<FieldSample>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(FieldSample)) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  Config config;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const auto next = [&] { return k + 1 < argc ? std::atoi(argv[++k]) : 0; };
    if (arg == "--grid") config.grid = next();
    else if (arg == "--stride") config.stride = next();
    else if (arg == "--primitives") config.primitives = next();
    else if (arg == "--smoke") config = {16, 4, 100};
    else {
      std::fprintf(stderr, "usage: %s [--grid N] [--stride S] [--primitives P] [--smoke]\n", argv[0]);
      return 2;
    }
  }
  const Skeleton skeleton = make_skeleton(config);
  const auto build_start = Clock::now();
  skeleton.prepare();
  const double build_seconds = std::chrono::duration<double>(Clock::now() - build_start).count();

  const std::vector<Vec3> full = grid_points(config.grid, 1);
  const std::vector<Vec3> sub = grid_points(config.grid, config.stride);
  BatchResult indexed_full, indexed_parallel, indexed_sub, plain_sub;
  const double indexed = seconds_per_point(skeleton, full, 1, Skeleton::Acceleration::indexed, indexed_full);
  const double parallel = seconds_per_point(skeleton, full, 0, Skeleton::Acceleration::indexed, indexed_parallel);
  const double indexed_on_sub = seconds_per_point(skeleton, sub, 1, Skeleton::Acceleration::indexed, indexed_sub);
  const double plain = seconds_per_point(skeleton, sub, 1, Skeleton::Acceleration::plain, plain_sub);

  std::printf("skeleton: %d compact primitives (R = %g, degree %d); index built in %.3f ms\n", config.primitives,
              config.R, config.degree, build_seconds * 1e3);
  std::printf("indexed, 1 thread:    %9.1f ns/point  (%d^3 = %zu points, %.2f s)\n", indexed * 1e9, config.grid,
              full.size(), indexed * double(full.size()));
  std::printf("indexed, %u threads:   %9.1f ns/point  (same bytes as 1 thread: %s)\n", default_thread_count(),
              parallel * 1e9, same_bytes(indexed_full.samples, indexed_parallel.samples) ? "yes" : "NO");
  std::printf("plain, 1 thread:      %9.1f ns/point  (%zu points: every %d-th of the grid)\n", plain * 1e9,
              sub.size(), config.stride);
  std::printf("indexed, 1 thread:    %9.1f ns/point  (the same %zu points)\n", indexed_on_sub * 1e9, sub.size());
  std::printf("ratio plain / indexed on the same points: %.1f\n", plain / indexed_on_sub);
  const bool exact = same_bytes(indexed_sub.samples, plain_sub.samples) &&
                     same_bytes(indexed_full.samples, indexed_parallel.samples);
  std::printf("indexed == plain bit for bit on the sub-grid: %s\n", exact ? "yes" : "NO");
  return exact ? 0 : 1;
}
