// tests/walk_skeleton.hpp — a random walk of unit Cauchy segments, as
// bench/mesh_bench.cpp builds its skeletons: the tolerance mode's test
// skeletons (far_segment_rule_test.cpp, far_segment_rule_mesh_test.cpp).
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "skelconv/primitives/segment.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

struct Walk {
  int count;
  int degree;
  double s;
  std::vector<double> weight;
};

/// Seed of bench/mesh_bench.cpp's walks: walk_skeleton({1000, 4, 4.0, {1.0}},
/// bench_walk_seed) is its 1,000-segment Cauchy skeleton.
inline constexpr unsigned bench_walk_seed = 20131;

/// `walk.count` segments of unit length along a random walk in a cube of
/// side 2 count^(1/3) + 2, reflected at its faces, from `seed` (the same
/// steps as bench/mesh_bench.cpp's walk_skeleton).
inline Skeleton walk_skeleton(const Walk& walk, unsigned seed) {
  std::mt19937_64 random(seed);
  const auto uniform = [&random](std::mt19937_64&) { return double(random() >> 11) * 0x1.0p-53; };
  const double side = 2 * std::cbrt(double(walk.count)) + 2;
  Vec3 p = Vec3::Constant(side / 2);
  std::vector<Primitive> segments;
  KernelSpec kernel;
  kernel.family = KernelFamily::cauchy;
  kernel.degree = walk.degree;
  kernel.s = walk.s;
  for (int k = 0; k < walk.count; ++k) {
    const double z = 2 * uniform(random) - 1, phi = 2 * M_PI * uniform(random);
    Vec3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    for (int i = 0; i < 3; ++i) {
      if (p[i] + d[i] < 0 || p[i] + d[i] > side) d[i] = -d[i];
    }
    segments.emplace_back(Segment(p, p + d, kernel, walk.weight));
    p += d;
  }
  return Skeleton(std::move(segments));
}

}  // namespace skelconv
