// tests/walk_skeleton.hpp — a random walk of unit Cauchy segments, classical
// (as bench/mesh_bench.cpp builds its skeletons) or SCALIS: the tolerance
// mode's test skeletons (far_segment_rule_test.cpp,
// far_segment_rule_mesh_test.cpp).
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "skelconv/primitives/scalis_segment.hpp"
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

/// The count + 1 vertices of a walk of `count` unit steps in a cube of side
/// 2 count^(1/3) + 2, reflected at its faces, from `seed` (the same steps as
/// bench/mesh_bench.cpp's walk_skeleton).
inline std::vector<Vec3> walk_points(int count, unsigned seed) {
  std::mt19937_64 random(seed);
  const auto uniform = [&random](std::mt19937_64&) { return double(random() >> 11) * 0x1.0p-53; };
  const double side = 2 * std::cbrt(double(count)) + 2;
  std::vector<Vec3> points{Vec3::Constant(side / 2)};
  for (int k = 0; k < count; ++k) {
    const Vec3& p = points.back();
    const double z = 2 * uniform(random) - 1, phi = 2 * M_PI * uniform(random);
    Vec3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    for (int i = 0; i < 3; ++i) {
      if (p[i] + d[i] < 0 || p[i] + d[i] > side) d[i] = -d[i];
    }
    points.push_back(p + d);
  }
  return points;
}

/// `walk.count` Cauchy segments of unit length along walk_points.
inline Skeleton walk_skeleton(const Walk& walk, unsigned seed) {
  KernelSpec kernel;
  kernel.family = KernelFamily::cauchy;
  kernel.degree = walk.degree;
  kernel.s = walk.s;
  const std::vector<Vec3> points = walk_points(walk.count, seed);
  std::vector<Primitive> segments;
  for (int k = 0; k < walk.count; ++k) {
    segments.emplace_back(Segment(points[std::size_t(k)], points[std::size_t(k) + 1], kernel, walk.weight));
  }
  return Skeleton(std::move(segments));
}

struct ScalisWalk {
  int count;
  int degree;
  double sigma;
  double min_radius, max_radius;  ///< the radii at the walk's vertices, uniform in between
};

/// `walk.count` SCALIS Cauchy segments along walk_points(count, seed), the
/// radius continuous from one segment to the next (as in Zanni's ant).
inline Skeleton scalis_walk_skeleton(const ScalisWalk& walk, unsigned seed) {
  const std::vector<Vec3> points = walk_points(walk.count, seed);
  std::mt19937_64 random(seed + 1);
  std::uniform_real_distribution<double> radius(walk.min_radius, walk.max_radius);
  std::vector<double> radii;
  for (std::size_t k = 0; k < points.size(); ++k) radii.push_back(radius(random));
  std::vector<Primitive> segments;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    segments.emplace_back(ScalisSegment(points[k], points[k + 1], radii[k], radii[k + 1],
                                        ScalisKernel::cauchy(walk.degree, walk.sigma)));
  }
  return Skeleton(std::move(segments));
}

}  // namespace skelconv
