// The curve fit's level test (src/reconstruct/level_test.hpp) against the
// exact field it stands for: every decision f(P) ≥ iso must be the exact
// evaluation's, on points spread through a skeleton of Cauchy segments and on
// points bisected to within rounding of its surface (where the tolerance mode
// cannot decide and the exact evaluation must be asked).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/skeleton/skeleton.hpp"
#include "../src/reconstruct/level_test.hpp"

namespace skelconv::reconstruct {
namespace {

/// A random walk of `count` SCALIS Cauchy segments (degree 4, σ 1.5, the
/// curve path's kernel) in the unit box, under one sum node, as the
/// reconstruction writes its skeletons.
Skeleton walk_of_segments(int count, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Skeleton skeleton;
  const Skeleton::NodeId sum = skeleton.add_blend(Blend::sum());
  Vec3 p(0.5, 0.5, 0.5), d(1, 0, 0);
  for (int k = 0; k < count; ++k) {
    d = (d + 0.4 * Vec3(normal(random), normal(random), normal(random))).normalized();
    const Vec3 q = p + 0.03 * d;
    const double r0 = 0.01 + 0.01 * unit(random), r1 = 0.01 + 0.01 * unit(random);
    skeleton.add(ScalisSegment(p, q, r0, r1, ScalisKernel::cauchy(4, 1.5)), sum);
    p = q;
  }
  return skeleton;
}

TEST(LevelTest, DecidesAsTheExactFieldEverywhere) {
  const Skeleton skeleton = walk_of_segments(200, 7);
  const LevelTest level(skeleton);
  ASSERT_TRUE(level.filtered());
  const double iso = skeleton.iso();
  const auto exact = [&](const Vec3& p) { return skeleton.value(p) >= iso; };
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  int inside = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(unit(random), unit(random), unit(random));
    ASSERT_EQ(level.at_or_above(p), exact(p)) << k;
    inside += exact(p);
  }
  EXPECT_GT(inside, 0);  // both answers were asked for
  EXPECT_EQ(level.exact_questions(), 0u);  // far from the surface: never the exact field
  // Rays from the skeleton's points bisected with the exact field to 60
  // halvings (far below the tolerance mode's 1e-12): the midpoints near the
  // end lie within rounding of f = iso, where only the exact field decides.
  const std::vector<Vec3> starts = skeleton.skeleton_points(1);
  std::size_t near_surface = 0, rays = 0;
  for (std::size_t s = 0; s < starts.size(); s += 5) {
    const Vec3 origin = starts[s], direction = Vec3(unit(random), unit(random), unit(random)).normalized();
    double in = 0.0, out = 0.5;
    // (A free end's point may lie outside: the walk's surface falls short
    // of its radius there.)
    if (!exact(origin) || exact(origin + out * direction)) continue;
    for (int k = 0; k < 60; ++k) {
      const double middle = 0.5 * (in + out);
      const Vec3 p = origin + middle * direction;
      ASSERT_EQ(level.at_or_above(p), exact(p)) << s << " " << k;
      (exact(p) ? in : out) = middle;
      near_surface += k >= 40;
    }
    ++rays;
  }
  EXPECT_GT(rays, starts.size() / 10);
  EXPECT_GT(near_surface, 0u);
  EXPECT_GT(level.exact_questions(), 0u);
  EXPECT_LT(level.exact_questions(), near_surface * 2);  // the early halvings were the filter's
}

TEST(LevelTest, OtherSkeletonsAskTheExactFieldOnly) {
  // Fewer segments than the tolerance mode takes, and a union node: no
  // filter, the same answers.
  const Skeleton few = walk_of_segments(int(Skeleton::min_far_rule_segments) - 1, 3);
  EXPECT_FALSE(LevelTest(few).filtered());
  Skeleton with_union = walk_of_segments(40, 5);
  const Skeleton::NodeId node = with_union.add_blend(Blend::union_max());
  with_union.add(ScalisSegment(Vec3(0, 0, 0), Vec3(0.1, 0, 0), 0.02, 0.02, ScalisKernel::cauchy(4, 1.5)),
                 node);
  const LevelTest level(with_union);
  EXPECT_FALSE(level.filtered());
  EXPECT_EQ(level.at_or_above(Vec3(0.05, 0, 0)), with_union.value(Vec3(0.05, 0, 0)) >= with_union.iso());
  EXPECT_EQ(level.exact_questions(), 1u);
}

}  // namespace
}  // namespace skelconv::reconstruct
