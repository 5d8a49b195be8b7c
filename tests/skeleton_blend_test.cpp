// Blend nodes (skelconv/skeleton/blend.hpp) through the Skeleton: values
// against the blend definitions written out here on 50-digit point fields,
// gradients against 50-digit central differences (extended_difference.hpp),
// the sum and union against their children's own values, the
// super-elliptic blend's iso-surface, and the +inf marker.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "expect_input_error.hpp"
#include "extended_difference.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "src/detail/infinity.hpp"  // skelconv::infinity

namespace skelconv {
namespace {

using test::Extended;
using ExtendedPoint = std::array<Extended, 3>;

constexpr double ulp = 2.3e-16;  // double's unit roundoff, rounded up

/// Three overlapping children: two infinite-support and one compact.
std::vector<PointPrimitive> children() {
  return {PointPrimitive(Vec3(0, 0, 0), KernelSpec::cauchy(4, 2.0), 1.5),
          PointPrimitive(Vec3(0.8, 0.1, 0), KernelSpec::compact(4, 1.2), 1.2),
          PointPrimitive(Vec3(0.3, 0.7, 0.2), KernelSpec::cauchy(3, 1.0), 0.9)};
}

/// Child k's value and gradient in 50 digits.
ScalarSample<Extended> extended_child(const PointPrimitive& child, const ExtendedPoint& q) {
  const ExtendedPoint c{child.center().x(), child.center().y(), child.center().z()};
  const auto sample = std::visit([&](const auto& k) { return point_field(k, c, Extended(child.weight()), q); },
                                 child.radial_kernel());
  return {sample.value, sample.gradient};
}

/// The blends' definitions (blend.hpp's file comment), on 50 digits.
Extended reference_blend(const Blend& blend, const std::vector<PointPrimitive>& kids, const ExtendedPoint& q) {
  std::vector<ScalarSample<Extended>> f;
  for (const auto& kid : kids) f.push_back(extended_child(kid, q));
  const Extended c(blend.iso), t(blend.t);
  Extended result = 0;
  switch (blend.kind) {
    case BlendKind::sum:
      for (std::size_t k = 0; k < f.size(); ++k) result += Extended(blend.weight_of(k)) * f[k].value;
      return result;
    case BlendKind::union_max:
      result = f[0].value;
      for (const auto& s : f) result = s.value > result ? s.value : result;
      return result;
    case BlendKind::super_elliptic: {
      Extended a = 1;  // 1 − cos θ for the angle-weighted variant
      if (blend.angle_weighted) {
        const auto& g1 = f[0].gradient;
        const auto& g2 = f[1].gradient;
        const Extended dot = g1[0] * g2[0] + g1[1] * g2[1] + g1[2] * g2[2];
        const Extended n1 = sqrt(g1[0] * g1[0] + g1[1] * g1[1] + g1[2] * g1[2]);
        const Extended n2 = sqrt(g2[0] * g2[0] + g2[1] * g2[1] + g2[2] * g2[2]);
        a = 1 - dot / (n1 * n2);
      }
      for (std::size_t k = 0; k < f.size(); ++k) {
        const Extended V = c - f[k].value;  // Ferley's V_k
        const Extended x = 1 - V / (Extended(blend.r_of(k)) * a);
        if (x > 0) result += c * pow(x, t);
      }
      return result;
    }
  }
  return result;
}

/// A skeleton whose root holds one blend node over `kids`.
Skeleton blended(const Blend& blend, const std::vector<PointPrimitive>& kids) {
  Skeleton skeleton;
  const Skeleton::NodeId node = skeleton.add_blend(blend);
  for (const auto& kid : kids) skeleton.add(kid, node);
  return skeleton;
}

std::vector<Vec3> random_points(int count) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.8, 1.6);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.emplace_back(u(rng), u(rng), 0.5 * u(rng));
  return points;
}

/// The blends under test, with the gradient tolerance each one's formula
/// justifies, relative to max(|∇f|, 1): the closed-form blends add a few
/// rounded terms (64 ulps cover them and the children's own); the
/// angle-weighted blend's ∇a comes from central differences of double
/// gradients (skeleton.hpp, angle_hessian_step: ~1e-10 relative on this
/// unit-size skeleton, amplified by at most V/(r a²) ≤ 1e3 where a ≥ 0.2).
struct Case {
  const char* name;
  Blend blend;
  double gradient_tolerance;
};
std::vector<Case> cases() {
  return {{"sum", Blend::sum(), 64 * ulp},
          {"weighted sum", Blend::sum({0.5, -1.25, 2.0}), 64 * ulp},
          {"union", Blend::union_max(), 64 * ulp},
          {"super_elliptic t=2", Blend::super_elliptic(2.0, {0.6}), 64 * ulp},
          {"super_elliptic t=3.5 per-child r", Blend::super_elliptic(3.5, {0.4, 0.9, 0.7}, 1.3), 64 * ulp}};
}

TEST(SkeletonBlend, ValuesAndGradientsMatchTheDefinitions) {
  const std::vector<PointPrimitive> kids = children();
  for (const Case& test_case : cases()) {
    const Skeleton skeleton = blended(test_case.blend, kids);
    const auto extended_value = [&](const ExtendedPoint& q) { return reference_blend(test_case.blend, kids, q); };
    int checked = 0;
    double worst = 0.0;
    for (const Vec3& p : random_points(300)) {
      const FieldSample sample = skeleton.value_and_gradient(p);
      const double expected = static_cast<double>(extended_value({p.x(), p.y(), p.z()}));
      EXPECT_NEAR(sample.value, expected, 64 * ulp * std::max(1.0, std::abs(expected))) << test_case.name;
      // Central differences need the blend smooth within h of p: skip points
      // where the union's maximum switches or a band edge passes, within
      // 1e-9 (the difference's step is 1e-15).
      const Vec3 expected_gradient = to_vec3(test::extended_gradient(extended_value, to_array(p)));
      const Vec3 other = to_vec3(test::extended_gradient(extended_value, to_array(p), 1e-12));
      if ((expected_gradient - other).norm() > 1e-9 * std::max(1.0, other.norm())) continue;
      ++checked;
      worst = std::max(worst, (sample.gradient - expected_gradient).norm() / std::max(1.0, expected_gradient.norm()));
      EXPECT_LE((sample.gradient - expected_gradient).norm(),
                test_case.gradient_tolerance * std::max(1.0, expected_gradient.norm()))
          << test_case.name << " at " << p.transpose() << ": " << sample.gradient.transpose() << " vs "
          << expected_gradient.transpose();
      EXPECT_EQ(skeleton.value(p), sample.value) << test_case.name;
    }
    EXPECT_GT(checked, 250) << test_case.name;
    std::printf("%s: worst gradient error %.2g relative (%d points)\n", test_case.name, worst, checked);
  }
}

TEST(SkeletonBlend, AngleWeightedGradientMatchesTheDefinition) {
  const std::vector<PointPrimitive> kids = {children()[0], children()[2]};
  const Blend blend = Blend::super_elliptic(2.0, {0.5, 0.8}, 1.0, true);
  const Skeleton skeleton = blended(blend, kids);
  const auto extended_value = [&](const ExtendedPoint& q) { return reference_blend(blend, kids, q); };
  int checked = 0;
  double worst = 0.0;
  for (const Vec3& p : random_points(300)) {
    const auto g1 = kids[0].gradient(p), g2 = kids[1].gradient(p);
    if (1.0 - g1.normalized().dot(g2.normalized()) < 0.2) continue;  // see Case: a ≥ 0.2
    const FieldSample sample = skeleton.value_and_gradient(p);
    const double expected = static_cast<double>(extended_value({p.x(), p.y(), p.z()}));
    EXPECT_NEAR(sample.value, expected, 64 * ulp * std::max(1.0, std::abs(expected)));
    const Vec3 expected_gradient = to_vec3(test::extended_gradient(extended_value, to_array(p)));
    const Vec3 other = to_vec3(test::extended_gradient(extended_value, to_array(p), 1e-12));
    if ((expected_gradient - other).norm() > 1e-9 * std::max(1.0, other.norm())) continue;
    ++checked;
    const double error = (sample.gradient - expected_gradient).norm() / std::max(1.0, expected_gradient.norm());
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-7) << p.transpose() << ": " << sample.gradient.transpose() << " vs "
                           << expected_gradient.transpose();
  }
  EXPECT_GT(checked, 100);
  std::printf("angle-weighted blend: worst gradient error %.2g relative (%d points)\n", worst, checked);
}

TEST(SkeletonBlend, SumAndUnionAreTheirChildrensSumAndMaximum) {
  // Segments and a polygon: double-only primitives, compared with their
  // own values, bit for bit (same additions in the same order).
  const Segment segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::cauchy(4, 2.0));
  const Polygon polygon({Vec3(0, 0.5, 0), Vec3(1, 0.5, 0), Vec3(1, 1.5, 0)}, KernelSpec::compact(6, 1.0));
  const PointPrimitive point(Vec3(0.5, 0.5, 0.5), KernelSpec::inverse(3), 0.25);
  for (const Blend& blend : {Blend::sum({2.0, -0.5, 1.5}), Blend::union_max()}) {
    Skeleton skeleton;
    const Skeleton::NodeId node = skeleton.add_blend(blend);
    skeleton.add(segment, node);
    skeleton.add(polygon, node);
    skeleton.add(point, node);
    for (const Vec3& p : random_points(50)) {
      const FieldSample parts[] = {segment.value_and_gradient(p), polygon.value_and_gradient(p),
                                   point.value_and_gradient(p)};
      FieldSample expected;
      if (blend.kind == BlendKind::sum) {
        for (int k = 0; k < 3; ++k) {
          expected.value += blend.weights[std::size_t(k)] * parts[k].value;
          expected.gradient += blend.weights[std::size_t(k)] * parts[k].gradient;
        }
      } else {
        expected = parts[0];
        for (const FieldSample& part : parts)
          if (part.value > expected.value) expected = part;
      }
      const FieldSample sample = skeleton.value_and_gradient(p);
      EXPECT_EQ(sample.value, expected.value);
      EXPECT_EQ(sample.gradient, expected.gradient);
    }
  }
}

TEST(SkeletonBlend, UnionTieReturnsTheFirstChildsGradient) {
  const PointPrimitive left(Vec3(-1, 0, 0), KernelSpec::cauchy(4, 1.0));
  const PointPrimitive right(Vec3(1, 0, 0), KernelSpec::cauchy(4, 1.0));
  const Skeleton skeleton = blended(Blend::union_max(), {left, right});
  const Vec3 p(0, 0.3, 0.1);  // equidistant: the values tie exactly
  ASSERT_EQ(left.value(p), right.value(p));
  EXPECT_EQ(skeleton.gradient(p), left.gradient(p));
  EXPECT_NE(left.gradient(p), right.gradient(p));
  const Skeleton reversed = blended(Blend::union_max(), {right, left});
  EXPECT_EQ(reversed.gradient(p), right.gradient(p));
}

TEST(SkeletonBlend, SuperEllipticSurfaceIsTheChildsAwayFromTheOther) {
  // Two compact points far apart, r ≤ c: beyond both bands f = 0 exactly,
  // and where child 0 is at its iso (f_0 = c) outside child 1's band the
  // blend is at its iso too: f = c.
  const double c = 0.5;
  const PointPrimitive near(Vec3(0, 0, 0), KernelSpec::compact(4, 1.0));
  const PointPrimitive far(Vec3(5, 0, 0), KernelSpec::compact(4, 1.0));
  const Skeleton skeleton = blended(Blend::super_elliptic(2.0, {0.3}, c), {near, far});
  EXPECT_EQ(skeleton.value(Vec3(2.5, 0, 0)), 0.0);
  // f_0 = (1 − x²)² = c at x = √(1 − √c).
  const double x = std::sqrt(1.0 - std::sqrt(c));
  EXPECT_NEAR(skeleton.value(Vec3(-x, 0, 0)), c, 8 * ulp);
  EXPECT_GT(skeleton.value(Vec3(-0.9 * x, 0, 0)), c);  // inside
  EXPECT_LT(skeleton.value(Vec3(-1.1 * x, 0, 0)), c);  // outside
}

TEST(SkeletonBlend, InfiniteChildMakesEveryBlendInfinite) {
  const PointPrimitive singular(Vec3(0, 0, 0), KernelSpec::inverse(2));
  const PointPrimitive other(Vec3(1, 0, 0), KernelSpec::cauchy(2, 1.0), -3.0);
  for (const Blend& blend : {Blend::sum({-1.0, 1.0}), Blend::union_max(), Blend::super_elliptic(2, {0.5}),
                             Blend::super_elliptic(2, {0.5}, 1.0, true)}) {
    const FieldSample sample = blended(blend, {singular, other}).value_and_gradient(Vec3(0, 0, 0));
    EXPECT_EQ(sample.value, infinity) << blend_name(blend.kind);
    EXPECT_EQ(sample.gradient, Vec3::Constant(infinity)) << blend_name(blend.kind);
  }
}

TEST(SkeletonBlend, OverflowIsAnEvaluationErrorOfTheNode) {
  // Two finite children of 1e308 each: their sum overflows double. That is
  // an evaluation error at the node, not a value passing for the marker.
  const PointPrimitive huge(Vec3(0, 0, 0), KernelSpec::cauchy(2, 1.0), 1e308);
  const Skeleton node_sum = blended(Blend::sum(), {huge, huge});
  try {
    node_sum.value(Vec3(0, 0, 0));
    ADD_FAILURE() << "no EvaluationError";
  } catch (const EvaluationError& error) {
    EXPECT_EQ(error.where(), "primitives[0]");
  }
  Skeleton top_level;
  top_level.add(huge);
  top_level.add(huge);
  try {
    top_level.value_and_gradient(Vec3(0, 0, 0));
    ADD_FAILURE() << "no EvaluationError";
  } catch (const EvaluationError& error) {
    EXPECT_EQ(error.where(), "primitives");
  }
}

TEST(SkeletonBlend, NestedNodesAreLocatedLikeTheFile) {
  Skeleton skeleton;
  skeleton.add(PointPrimitive(Vec3(0, 0, 0), KernelSpec::cauchy(2, 1.0)));
  const Skeleton::NodeId outer = skeleton.add_blend(Blend::union_max());
  skeleton.add(PointPrimitive(Vec3(1, 0, 0), KernelSpec::cauchy(2, 1.0)), outer);
  skeleton.add_blend(Blend::sum(), outer);  // left empty: invalid
  EXPECT_EQ(skeleton.location(0), "primitives[0]");
  EXPECT_EQ(skeleton.location(1), "primitives[1].children[0]");
  test::expect_input_error([&] { skeleton.value(Vec3(0, 0, 1)); }, "primitives[1].children[1].children",
                           "a sum blend needs at least one child");
}

TEST(SkeletonBlend, MovedFromSkeletonIsEmptyAndUsable) {
  Skeleton source = blended(Blend::union_max(), children());
  const double expected = source.value(Vec3(0.2, 0.1, 0));
  const Skeleton moved(std::move(source));
  EXPECT_EQ(moved.value(Vec3(0.2, 0.1, 0)), expected);
  EXPECT_TRUE(source.empty());  // NOLINT(bugprone-use-after-move): the documented state
  EXPECT_EQ(source.value(Vec3(0.2, 0.1, 0)), 0.0);
}

TEST(SkeletonBlend, SkeletonPointsReachEveryLeaf) {
  Skeleton skeleton;
  const Skeleton::NodeId node = skeleton.add_blend(Blend::union_max());
  skeleton.add(PointPrimitive(Vec3(4, 5, 6), KernelSpec::cauchy(2, 1.0)), node);
  skeleton.add(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::cauchy(2, 1.0)), node);
  const std::vector<Vec3> points = skeleton.skeleton_points(2);
  ASSERT_EQ(points.size(), 4u);  // the centre, then a, the midpoint and b
  EXPECT_EQ(points[0], Vec3(4, 5, 6));
  EXPECT_EQ(points[3], Vec3(1, 0, 0));
}

}  // namespace
}  // namespace skelconv
