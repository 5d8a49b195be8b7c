// verify/test_verdict.cpp — the sweep's verdict fails when
// a (family, degree, region) cell excludes more than ExclusionLimits allows
// or compares too few, even with every compared point within its target.
#include <gtest/gtest.h>

#include "report.hpp"

namespace skelconv::verify {
namespace {

// A result with `cells_per_weight` per weight degree 0..3 of cauchy i = 3.
SweepResult result_with(Region region, const CellStats& per_weight_degree) {
  SweepResult result;
  for (int d = 0; d <= 3; ++d) result.cells[{KernelFamily::cauchy, 3, d, region}] = per_weight_degree;
  CellStats generic;  // a clean generic cell, so that `compared` > 0
  generic.points = 100;
  for (int d = 0; d <= 3; ++d) result.cells[{KernelFamily::cauchy, 3, d, Region::generic}].merge(generic);
  return result;
}

CellStats cell(std::uint64_t points, std::uint64_t excluded, std::uint64_t outside = 0) {
  CellStats c;
  c.points = points;
  c.excluded = excluded;
  c.retried = excluded;
  c.outside_support = outside;
  return c;
}

TEST(Verdict, CleanSweepPasses) {
  const GenericVerdict verdict = generic_verdict(result_with(Region::far, cell(200, 0)), ExclusionLimits{});
  EXPECT_TRUE(verdict.passed());
  EXPECT_EQ(verdict.failing_exclusion_cells, 0u);
}

TEST(Verdict, ExclusionStormFails) {
  // 20 of 200 per weight degree excluded (10%): every compared point is fine,
  // but a cluster of errors could hide there. The old verdict passed this.
  const GenericVerdict verdict = generic_verdict(result_with(Region::near_ends, cell(180, 20)), ExclusionLimits{});
  EXPECT_FALSE(verdict.passed());
  EXPECT_EQ(verdict.failing_exclusion_cells, 1u);
  EXPECT_EQ(verdict.failing_points, 0u);
}

TEST(Verdict, ExclusionsAtTheLimitPass) {
  // 2 of 200 (1%) is at the limit, 3 of 200 (1.5%) beyond it.
  EXPECT_TRUE(generic_verdict(result_with(Region::near_ends, cell(198, 2)), ExclusionLimits{}).passed());
  EXPECT_FALSE(generic_verdict(result_with(Region::near_ends, cell(197, 3)), ExclusionLimits{}).passed());
}

TEST(Verdict, TooFewComparedFails) {
  // Nothing excluded, but 150 of 200 outside the support: 25% compared.
  EXPECT_FALSE(generic_verdict(result_with(Region::support_boundary, cell(50, 0, 150)), ExclusionLimits{}).passed());
  // The design share of support_boundary (1/3 outside) passes.
  EXPECT_TRUE(generic_verdict(result_with(Region::support_boundary, cell(134, 0, 66)), ExclusionLimits{}).passed());
}

TEST(Verdict, ExclusionTablePerFamilyDegreeRegion) {
  const std::vector<ExclusionCell> cells =
      exclusion_cells(result_with(Region::near_ends, cell(180, 20)), ExclusionLimits{});
  ASSERT_EQ(cells.size(), 2u);  // generic, near_ends: weight degrees summed
  EXPECT_EQ(cells[1].region, Region::near_ends);
  EXPECT_EQ(cells[1].evaluations, 800u);
  EXPECT_EQ(cells[1].excluded, 80u);
  EXPECT_DOUBLE_EQ(cells[1].excluded_share(), 0.1);
  EXPECT_FALSE(cells[1].passed);
  EXPECT_TRUE(cells[0].passed);
}

}  // namespace
}  // namespace skelconv::verify
