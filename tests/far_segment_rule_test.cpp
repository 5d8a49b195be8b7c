// Skeleton's tolerance mode (docs/field.md, "Tolerance"; far_segment_rule.hpp)
// against the exact field: on random walks of Cauchy segments of several
// degrees, sharpnesses and weights, at points on and around them, every f
// must be within tolerance · f of the exact sum and every component of ∇f
// within tolerance · max (i/2) √s · f. The reference is the exact
// evaluation (the generated functions, which verify/ checks against float128
// quadrature), summed directly. The mesh half (the 1,000-segment walk's mesh
// vertices) is far_segment_rule_mesh_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/field/batch.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "walk_skeleton.hpp"

namespace skelconv {
namespace {

/// Points near the skeleton (within 1.5 of a segment's end: where a mesh's
/// surface lies) and across the whole box and beyond.
std::vector<Vec3> probe_points(const Skeleton& skeleton, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::AlignedBox3d box;
  for (const Primitive& primitive : skeleton.primitives()) {
    box.extend(std::get<Segment>(primitive).a());
    box.extend(std::get<Segment>(primitive).b());
  }
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const Segment& segment = std::get<Segment>(skeleton.primitives()[std::size_t(k) % skeleton.size()]);
    const Vec3 offset(unit(random), unit(random), unit(random));
    if (k % 3 != 2) {
      points.push_back(segment.a() + 1.5 * offset);
    } else {
      points.push_back(box.center() + 1.5 * offset.cwiseProduct(box.sizes()));  // to a box's width outside
    }
  }
  return points;
}

/// The largest (i/2) √s of the skeleton's segments: ∇f's tolerance scale.
double gradient_scale(const Skeleton& skeleton) {
  double scale = 0;
  for (const Primitive& primitive : skeleton.primitives()) {
    const KernelSpec& kernel = std::get<Segment>(primitive).kernel();
    scale = std::max(scale, kernel.degree / 2.0 * std::sqrt(kernel.s));
  }
  return scale;
}

struct Worst {
  double f = 0, gradient = 0;  ///< largest error over its allowance
  int approximated = 0;        ///< points whose f differs from the exact one
};

Worst check_walk(const Skeleton& skeleton, const std::vector<Vec3>& points, double tolerance) {
  Worst worst;
  const double scale = gradient_scale(skeleton);
  for (const Vec3& p : points) {
    const FieldSample exact = skeleton.value_and_gradient(p);
    const FieldSample within = skeleton.value_and_gradient(p, tolerance);
    worst.f = std::max(worst.f, std::abs(within.value - exact.value) / (tolerance * exact.value));
    worst.gradient = std::max(worst.gradient,
                              (within.gradient - exact.gradient).cwiseAbs().maxCoeff() / (tolerance * scale * exact.value));
    worst.approximated += within.value != exact.value;
    // value() alone, as the mesher asks for it.
    worst.f = std::max(worst.f, std::abs(skeleton.value(p, tolerance) - exact.value) / (tolerance * exact.value));
  }
  return worst;
}

TEST(FarSegmentRule, WithinTheToleranceOnRandomWalks) {
  const std::vector<Walk> walks = {
      {200, 4, 4.0, {1.0}},             // the benchmark's kernel
      {120, 2, 1.0, {1.0}},             // slow decay: far segments matter most
      {120, 3, 2.0, {0.5}},             // half-integer power
      {80, 8, 9.0, {1.0, 2.0}},         // steep, linear weight
      {80, 6, 0.5, {0.2, 0.0, 0.0, 1.5}},  // cubic weight
      {60, 16, 3.0, {1.0}},             // the highest degree
  };
  unsigned seed = 1;
  for (const Walk& walk : walks) {
    const Skeleton skeleton = walk_skeleton(walk, seed);
    const std::vector<Vec3> points = probe_points(skeleton, 300, seed + 100);
    for (double tolerance : {1e-12, 1e-9, 1e-6, 1e-3}) {
      const Worst worst = check_walk(skeleton, points, tolerance);
      SCOPED_TRACE(testing::Message() << walk.count << " segments, degree " << walk.degree << ", tolerance "
                                      << tolerance);
      EXPECT_LE(worst.f, 1.0);
      EXPECT_LE(worst.gradient, 1.0);
      // The mode is used: at 1e-6 and above nearly every point takes a rule somewhere.
      if (tolerance >= 1e-6) {
        EXPECT_GT(worst.approximated, int(points.size()) / 2);
      }
      std::printf("%3d segments, i = %2d, tolerance %.0e: worst error / allowance %.2e (f), %.2e (grad f); "
                  "%d of %zu points approximated\n",
                  walk.count, walk.degree, tolerance, worst.f, worst.gradient, worst.approximated, points.size());
    }
    ++seed;
  }
}

TEST(FarSegmentRule, ZeroIsTheExactField) {
  const Skeleton skeleton = walk_skeleton({50, 4, 4.0, {1.0}}, 7);
  for (const Vec3& p : probe_points(skeleton, 100, 8)) {
    const FieldSample exact = skeleton.value_and_gradient(p);
    const FieldSample zero = skeleton.value_and_gradient(p, 0.0);
    EXPECT_EQ(zero.value, exact.value);
    EXPECT_EQ(zero.gradient, exact.gradient);
  }
}

TEST(FarSegmentRule, OnlyListsOfCauchySegmentsWithoutNegativeWeights) {
  KernelSpec cauchy;
  cauchy.family = KernelFamily::cauchy;
  cauchy.degree = 4;
  cauchy.s = 4;
  KernelSpec inverse;
  inverse.family = KernelFamily::inverse;
  inverse.degree = 3;
  EXPECT_NE(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), cauchy).far_rule(), nullptr);
  EXPECT_EQ(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), cauchy, {1.0, -0.5}).far_rule(), nullptr);
  EXPECT_EQ(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), inverse).far_rule(), nullptr);
  // A negative weight anywhere leaves the whole list exact (f̲ would not bound f).
  std::vector<Primitive> segments;
  for (int k = 0; k < 20; ++k) segments.emplace_back(Segment(Vec3(k, 0, 0), Vec3(k + 1, 0, 0), cauchy));
  segments.emplace_back(Segment(Vec3(0, 1, 0), Vec3(1, 1, 0), cauchy, {1.0, -0.5}));
  const Skeleton mixed(std::move(segments));
  const Vec3 p(3, 5, 1);
  EXPECT_EQ(mixed.value_and_gradient(p, 1e-3).value, mixed.value_and_gradient(p).value);
}

TEST(FarSegmentRule, BadToleranceIsAnInputError) {
  const Skeleton skeleton = walk_skeleton({10, 4, 4.0, {1.0}}, 3);
  for (double bad : {-1e-12, 1.0, std::nan(""), double(INFINITY)}) {
    try {
      (void)skeleton.value_and_gradient(Vec3(0, 0, 0), bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), "tolerance") << error.what();
    }
    BatchOptions options;
    options.tolerance = bad;
    const std::vector<Vec3> points{Vec3(0, 0, 0)};
    EXPECT_THROW(evaluate_batch(skeleton, points, options), InputError);
  }
}

TEST(FarSegmentRule, BatchesGiveTheSameBytesOnAnyThreadCount) {
  const Skeleton skeleton = walk_skeleton({100, 4, 4.0, {1.0}}, 5);
  const std::vector<Vec3> points = probe_points(skeleton, 500, 6);
  BatchOptions one;
  one.threads = 1;
  one.tolerance = 1e-12;
  BatchOptions three = one;
  three.threads = 3;
  const BatchResult a = evaluate_batch(skeleton, points, one), b = evaluate_batch(skeleton, points, three);
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(a.samples[k].value, b.samples[k].value);
    EXPECT_EQ(a.samples[k].gradient, b.samples[k].gradient);
    EXPECT_EQ(a.samples[k].value, skeleton.value_and_gradient(points[k], 1e-12).value);
  }
}

}  // namespace
}  // namespace skelconv
