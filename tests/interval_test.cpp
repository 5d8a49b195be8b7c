// The interval tools (include/skelconv/interval/): the exam notes' interval
// square, squared distance and worked example (part 3d–f) against values
// derived exactly here, outward rounding, and the octree's growth.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "skelconv/interval/octree.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::interval {
namespace {

TEST(Interval, SquareIsTheNotesThreeCases) {
  const Interval a = interval_square(Interval(2.0, 3.0)), b = interval_square(Interval(-4.0, -3.0)),
                 c = interval_square(Interval(-1.0, 2.0)), d = interval_square(Interval(-3.0, 1.0));
  EXPECT_EQ(a.lower(), 4.0);
  EXPECT_EQ(a.upper(), 9.0);
  EXPECT_EQ(b.lower(), 9.0);
  EXPECT_EQ(b.upper(), 16.0);
  EXPECT_EQ(c.lower(), 0.0);  // not [−1,2]·[−1,2] = [−2, 4]
  EXPECT_EQ(c.upper(), 4.0);
  EXPECT_EQ(d.lower(), 0.0);
  EXPECT_EQ(d.upper(), 9.0);
}

TEST(Interval, RoundsOutward) {
  // 0.1 + 0.2 is not a double: an outward-rounded sum has two different ends
  // around it (this fails if the rounding mode is not switched, or the
  // compiler folds the sum: -frounding-math).
  const Interval sum = Interval(0.1) + Interval(0.2);
  EXPECT_LT(sum.lower(), sum.upper());
  EXPECT_EQ(sum.upper(), std::nextafter(sum.lower(), 1.0));
  const Interval third = Interval(1.0) / 3.0;
  EXPECT_LT(third.lower(), third.upper());
}

TEST(Interval, SquaredDistanceOfTheNotes) {
  const Box unit{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const Interval d1 = squared_distance(unit, Vec3(0, 0, 0)), d2 = squared_distance(unit, Vec3(4, 0, 0));
  EXPECT_EQ(d1.lower(), 0.0);
  EXPECT_EQ(d1.upper(), 3.0);
  EXPECT_EQ(d2.lower(), 9.0);  // [−4, −3]² + [0, 2] = [9, 16] + [0, 2]
  EXPECT_EQ(d2.upper(), 18.0);
}

// Notes part 3f: soft points of radius r = 2 (iso ½) at (0,0,0) and (4,0,0),
// box [0,1]³. With R² = r²(2 + √2) = 8 + 4√2 (the notes' 13.616 is a
// misprint; 3.7² = 13.69) and f(d²) = (d² − R²)²/R⁴:
//   f1 ∈ [f(3), 1],   f(3) = (5 + 4√2)²/(8 + 4√2)² = (57 + 40√2)/(96 + 64√2) ≈ 0.6089
//   f2 ∈ [0, f(9)],   f(9) = (1 − 4√2)²/(8 + 4√2)² = (33 − 8√2)/(96 + 64√2) ≈ 0.1163
TEST(Interval, WorkedExampleOfTheNotes) {
  const long double s2 = std::numbers::sqrt2_v<long double>;
  const long double f3 = (57 + 40 * s2) / (96 + 64 * s2), f9 = (33 - 8 * s2) / (96 + 64 * s2);
  const double R = std::sqrt(8.0 + 4.0 * std::numbers::sqrt2);
  char json[512];
  std::snprintf(json, sizeof json,
                R"({"iso": 0.5, "primitives": [{"type": "point", "center": [0, 0, 0], "kernel": {"family": "soft", "R": %.17g}},
                {"type": "point", "center": [4, 0, 0], "kernel": {"family": "soft", "R": %.17g}}]})",
                R, R);
  const Skeleton skeleton = parse_skeleton_json(json);
  const Box unit{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const Interval f1 = enclose(skeleton.primitives()[0], unit), f2 = enclose(skeleton.primitives()[1], unit);
  const Interval f = enclose(skeleton, unit);
  EXPECT_NEAR(f1.lower(), double(f3), 1e-12);
  EXPECT_NEAR(f1.upper(), 1.0, 1e-12);
  EXPECT_EQ(f2.lower(), 0.0);
  EXPECT_NEAR(f2.upper(), double(f9), 1e-12);
  EXPECT_NEAR(f.lower(), double(f3), 1e-12);
  EXPECT_NEAR(f.upper(), double(1 + f9), 1e-12);
  EXPECT_EQ(classify(f, 0.5), Classification::inside);
  EXPECT_EQ(classify(f2, 0.5), Classification::outside);
}

TEST(Interval, InverseKernelsNearTheirSkeleton) {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
      {"type": "point", "center": [0, 0, 0], "kernel": {"family": "inverse", "degree": 3}}]})");
  // A box that is the centre itself: f = +inf there (the marker), never NaN.
  const Interval at_centre = enclose(skeleton, Box{Vec3::Zero(), Vec3::Zero()});
  EXPECT_EQ(at_centre.lower(), INFINITY);
  EXPECT_EQ(at_centre.upper(), INFINITY);
  // A box around it: [K(d_max), +inf], d_max = √3 · 0.1.
  const Interval around = enclose(skeleton, Box{Vec3::Constant(-0.1), Vec3::Constant(0.1)});
  EXPECT_NEAR(around.lower(), std::pow(0.03, -1.5), 1e-9);
  EXPECT_EQ(around.upper(), INFINITY);
  // A box at distance 1 along x, 2 at its far corner: [1/8 … , 1].
  const Interval away = enclose(skeleton, Box{Vec3(1, 0, 0), Vec3(1.5, 1, std::sqrt(0.75))});
  EXPECT_NEAR(away.upper(), 1.0, 1e-15);
  EXPECT_NEAR(away.lower(), 1.0 / 8.0, 1e-15);
}

// A negative weight makes a primitive's enclosure [lo, 0] where the box
// reaches beyond its compact support; the sums above it must keep lo.
TEST(Interval, NegativeWeightBeyondTheSupport) {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
      {"blend": "sum", "weights": [2], "children": [
        {"type": "point", "center": [0, 0, 0], "weight": -1, "kernel": {"family": "soft", "R": 1}}]},
      {"type": "segment", "a": [0, 3, 0], "b": [1, 3, 0], "weight": [-1],
       "kernel": {"family": "compact", "degree": 4, "R": 1}}]})");
  // The point's box holds its centre (f = 2 · −1 · K(0) = −2) and points
  // beyond R (f = 0); the segment's box is the segment itself, where
  // f = −∫ (1 − x²)² dx over [−t, 1 − t] ≤ −8/15 (t = 0, the end).
  const Interval point_box = enclose(skeleton, Box{Vec3(0, 0, 0), Vec3(2, 2, 2)});
  EXPECT_LE(point_box.lower(), -2.0);
  EXPECT_GE(point_box.upper(), 0.0);
  const Interval segment_box = enclose(skeleton, Box{Vec3(0, 3, 0), Vec3(1, 3, 0)});
  EXPECT_LE(segment_box.lower(), -8.0 / 15.0);
  EXPECT_GE(segment_box.upper(), -8.0 / 15.0);
}

TEST(Interval, OctreeUndeterminedCellsGrowLikeArea) {
  // One soft point: the surface is a sphere of radius 1 (R = √(2 + √2)).
  const Skeleton skeleton = parse_skeleton_json(
      R"({"iso": 0.5, "primitives": [{"type": "point", "center": [0.1, 0.2, 0.05],
          "kernel": {"family": "soft", "R": 1.8477590650225735}}]})");
  const auto counts = classify_octree(skeleton, Box{Vec3(-2, -2, -2), Vec3(2, 2, 2)}, 6, 0.5);
  ASSERT_EQ(counts.size(), 7u);
  // Area / cell²: ×4 per level (×8 would be volume).
  for (int level = 4; level <= 6; ++level) {
    const double ratio = double(counts[level].undetermined) / double(counts[level - 1].undetermined);
    EXPECT_GT(ratio, 3.5) << level;
    EXPECT_LT(ratio, 5.0) << level;
  }
  EXPECT_EQ(counts[0].undetermined, 1u);
}

}  // namespace
}  // namespace skelconv::interval
