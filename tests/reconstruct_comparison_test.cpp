// Unit tests of skelconv/reconstruct/skeleton_comparison.hpp: a recovered
// Y against the known Y it stands for. Expected values are derived by hand
// in the comments.
#include <gtest/gtest.h>

#include "skelconv/reconstruct/skeleton_comparison.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::reconstruct {
namespace {

// Known: three SCALIS segments from the origin along x, y and z, radius
// 0.2 at the origin to 0.1 at the far end.
std::vector<KnownSegment> known_y() {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
    {"type": "scalis_segment", "a": [0, 0, 0], "b": [1, 0, 0], "radius": [0.2, 0.1], "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5}},
    {"type": "scalis_segment", "a": [0, 0, 0], "b": [0, 1, 0], "radius": [0.2, 0.1], "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5}},
    {"type": "scalis_segment", "a": [0, 0, 0], "b": [0, 0, 1], "radius": [0.2, 0.1], "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5}}]})");
  return known_segments(skeleton);
}

TEST(Comparison, KnownSegmentsAndJunctions) {
  const auto known = known_y();
  ASSERT_EQ(known.size(), 3u);
  EXPECT_EQ(known[1].b, Vec3(0, 1, 0));
  EXPECT_EQ(known[1].radius_a, 0.2);
  EXPECT_EQ(known[1].radius_b, 0.1);
  // Only the origin is shared by three segments; the far ends are single.
  const auto junctions = known_junctions(known, 1e-9);
  ASSERT_EQ(junctions.size(), 1u);
  EXPECT_EQ(junctions[0], Vec3::Zero());
}

// Recovered: a junction at (0.03, 0.04, 0), 0.05 from the known one; three
// branches from it. On the x branch, (0.5, 0.1, 0) is 0.1 from the x axis,
// whose radius there is 0.15: radius 0.16 is 0.01 off. The extension point
// (5, 5, 5) is not a skeleton point and is not compared.
TEST(Comparison, JunctionAxisAndRadiusErrors) {
  const Vec4 junction(0.03, 0.04, 0, 0.2);
  std::vector<Branch> branches(3);
  branches[0].points = {junction, Vec4(0.5, 0.1, 0, 0.16), Vec4(5, 5, 5, 0.1)};
  branches[0].extended_last = true;
  branches[1].points = {junction, Vec4(0, 1, 0, 0.1)};
  branches[2].points = {junction, Vec4(0, 0, 1, 0.1)};
  for (int k = 0; k < 3; ++k) branches[k].first_node = 0, branches[k].last_node = k + 1;
  const SkeletonComparison c = compare_with_known(branches, known_y(), 1e-9);
  EXPECT_EQ(c.known_junctions, 1u);
  ASSERT_EQ(c.junction.count, 1u);
  EXPECT_NEAR(c.junction.max, 0.05, 1e-15);
  // 6 points. The junction, thrice: 0.04 from the x axis, 0.03 from the y
  // axis at (0, 0.04, 0) (the nearest; radius 0.2 − 0.1 × 0.04 = 0.196, so
  // 0.004 off), 0.05 from the z axis. (0.5, 0.1, 0): 0.1 and 0.01. The far
  // ends (0, 1, 0) and (0, 0, 1): 0 and 0.
  ASSERT_EQ(c.axis.count, 6u);
  EXPECT_NEAR(c.axis.max, 0.1, 1e-15);
  EXPECT_NEAR(c.axis.mean, (3 * 0.03 + 0.1) / 6, 1e-15);
  EXPECT_NEAR(c.radius.max, 0.01, 1e-15);
  EXPECT_NEAR(c.radius.mean, (3 * 0.004 + 0.01) / 6, 1e-15);
}

}  // namespace
}  // namespace skelconv::reconstruct
