// verify/test_compare.cpp — compare: the rule "worse than k times
// the old maximum and above the floor", disappeared cells fail, new cells do
// not. On synthetic reports; a real perturbed sweep is caught by the ctest
// verify_compare_catches_perturbation.
#include <gtest/gtest.h>

#include "compare.hpp"

namespace skelconv::verify {
namespace {

const CellKey cauchy_generic{KernelFamily::cauchy, 3, 1, Region::generic};
const CellKey cauchy_far{KernelFamily::cauchy, 3, 1, Region::far};

CellStats cell(double f_double, double grad_double = 1e-15, double f_extended = 1e-30, double grad_extended = 1e-30) {
  CellStats c;
  c.points = 100;
  c.in_double.max_f = f_double;
  c.in_double.max_grad = grad_double;
  c.in_extended.max_f = f_extended;
  c.in_extended.max_grad = grad_extended;
  return c;
}

SweepReport report(std::initializer_list<std::pair<CellKey, CellStats>> cells) {
  SweepReport r;
  r.source = "test";
  r.options.progress = false;
  for (const auto& [key, c] : cells) r.result.cells[key] = c;
  return r;
}

TEST(Compare, SameReportPasses) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14)}, {cauchy_far, cell(1e-10)}});
  const Comparison c = compare_reports(base, base, {});
  EXPECT_TRUE(c.passed());
  EXPECT_EQ(c.cells.size(), 2u);
}

TEST(Compare, WorseThanKTimesAboveTheFloorFails) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14)}, {cauchy_far, cell(1e-10)}});
  const SweepReport fresh = report({{cauchy_generic, cell(1e-14)}, {cauchy_far, cell(2.5e-10)}});
  const Comparison c = compare_reports(base, fresh, {});
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(c.failed_cells(), 1u);
  EXPECT_TRUE(c.cells[1].worse[0]);  // cells in key order: generic, far
  CompareOptions loose;
  loose.tolerance_factor = 3;
  EXPECT_TRUE(compare_reports(base, fresh, loose).passed());
}

TEST(Compare, BelowTheFloorIsNoise) {
  // 1.75 → 14 ulps: eight times worse, but still rounding (floor 16 ulps).
  const SweepReport base = report({{cauchy_generic, cell(3.9e-16)}});
  const SweepReport fresh = report({{cauchy_generic, cell(3.1e-15)}});
  EXPECT_TRUE(compare_reports(base, fresh, {}).passed());
  const SweepReport beyond = report({{cauchy_generic, cell(4e-15)}});
  EXPECT_FALSE(compare_reports(base, beyond, {}).passed());
}

TEST(Compare, BinaryOneTwentyEightHasItsOwnFloor) {
  const SweepReport base = report({{cauchy_generic, cell(1e-15, 1e-15, 1e-30)}});
  // 1e-22: 1e8 times worse, but below the reference's flag threshold (1e-20).
  EXPECT_TRUE(compare_reports(base, report({{cauchy_generic, cell(1e-15, 1e-15, 1e-22)}}), {}).passed());
  const Comparison c = compare_reports(base, report({{cauchy_generic, cell(1e-15, 1e-15, 1e-18)}}), {});
  EXPECT_FALSE(c.passed());
  EXPECT_TRUE(c.cells[0].worse[2]);
}

TEST(Compare, GradientAndNonFiniteCount) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14, 1e-14)}});
  EXPECT_FALSE(compare_reports(base, report({{cauchy_generic, cell(1e-14, 1e-12)}}), {}).passed());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(compare_reports(base, report({{cauchy_generic, cell(inf)}}), {}).passed());
}

TEST(Compare, DisappearedFailsNewDoesNot) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14)}, {cauchy_far, cell(1e-10)}});
  const SweepReport fewer = report({{cauchy_generic, cell(1e-14)}});
  const Comparison gone = compare_reports(base, fewer, {});
  EXPECT_FALSE(gone.passed());
  ASSERT_EQ(gone.removed.size(), 1u);
  EXPECT_EQ(gone.removed[0], cauchy_far);
  const CellKey added{KernelFamily::inverse, 17, 0, Region::near_ends};
  const SweepReport more = report({{cauchy_generic, cell(1e-14)}, {cauchy_far, cell(1e-10)}, {added, cell(1)}});
  const Comparison grown = compare_reports(base, more, {});
  EXPECT_TRUE(grown.passed());
  ASSERT_EQ(grown.added.size(), 1u);
  EXPECT_EQ(grown.added[0], added);
}

TEST(Compare, LostComparisonsFail) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14)}});
  CellStats excluded_all = cell(0, 0, 0, 0);
  excluded_all.points = 0;
  excluded_all.excluded = 100;
  EXPECT_FALSE(compare_reports(base, report({{cauchy_generic, excluded_all}}), {}).passed());
}

TEST(Compare, NothingComparedFails) {
  const SweepReport empty = report({});
  EXPECT_FALSE(compare_reports(empty, empty, {}).passed());
}

TEST(Compare, RefusesDifferentSamples) {
  const SweepReport base = report({{cauchy_generic, cell(1e-14)}});
  SweepReport other = base;
  other.options.seed += 1;
  EXPECT_THROW(compare_reports(base, other, {}), ReportError);
  other = base;
  other.options.counts.generic = 7;
  EXPECT_THROW(compare_reports(base, other, {}), ReportError);
}

}  // namespace
}  // namespace skelconv::verify
