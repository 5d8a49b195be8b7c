// SCALIS segments against their ideal shape, the canal surface of the
// spheres (Γ(t), τ(t)) (skelconv/canal/scalis_deviation.hpp, docs/canal.md §5).
// The bounds come from the table of docs/canal.md (|AB| = 1, measured with
// 200 frustum and 40 cap samples; here 40 and 10, to stay fast).
#include <gtest/gtest.h>

#include "skelconv/canal/scalis_deviation.hpp"

namespace skelconv::canal {
namespace {

const DeviationOptions fast{.frustum_samples = 40, .cap_samples = 10};

ScalisDeviation measure(double tau0, double tau1, const ScalisKernel& kernel) {
  return measure_scalis_deviation(ScalisSegment(Vec3(0.3, -0.2, 0.1), Vec3(0.9, 0.6, 0.1), tau0, tau1, kernel), fast);
}

TEST(CanalScalis, CompactCylinderIsExactlyTheCanalSurfaceInTheMiddle) {
  // Zanni §4.3: with |AB| ≥ 2τ√(σ² − 1) the compact kernel's surface is
  // exactly at distance τ away from the ends (docs/mathematics.md §4). The measurement must
  // find 0 to its bisection tolerance (1e-10 τ): this checks the probes too.
  const ScalisDeviation deviation = measure(0.1, 0.1, ScalisKernel::compact(4, 1.5));
  EXPECT_LT(std::abs(deviation.middle.extreme), 1e-9);
  EXPECT_EQ(deviation.middle.missing, 0);
}

TEST(CanalScalis, MiddleOfAGentleConeIsWithinHalfAPercentOfTau) {
  // Radius 0.05 → 0.15 over |AB| = 1 (slope 0.1). Measured middle extremes:
  // inverse 6: +1.7e-3, cauchy 8 σ = 1: +2.6e-3, compact 4 σ = 1.5: +1.7e-3,
  // compact 8 σ = 2: +2.6e-3. The bound 5e-3 is twice the worst.
  for (const ScalisKernel& kernel : {ScalisKernel::inverse(6, 1.0), ScalisKernel::cauchy(8, 1.0),
                                     ScalisKernel::compact(4, 1.5), ScalisKernel::compact(8, 2.0)}) {
    const ScalisDeviation deviation = measure(0.05, 0.15, kernel);
    EXPECT_LT(std::abs(deviation.middle.extreme), 5e-3) << family_name(kernel.family) << " " << kernel.degree;
    EXPECT_GT(std::abs(deviation.middle.extreme), 1e-4) << "a cone is not exactly reproduced";
  }
}

TEST(CanalScalis, EndsRetractWellInsideTheCaps) {
  // At the ends only half the segment contributes: every measured case whose
  // caps the surface reaches retracts by 20% to 68% of τ there (table),
  // never outwards.
  for (const ScalisKernel& kernel : {ScalisKernel::inverse(3, 1.0), ScalisKernel::cauchy(4, 0.5),
                                     ScalisKernel::compact(4, 1.5)}) {
    const ScalisDeviation deviation = measure(0.1, 0.1, kernel);
    EXPECT_LT(deviation.ends.extreme, -0.2);
    EXPECT_GT(deviation.ends.extreme, -0.7);
  }
}

}  // namespace
}  // namespace skelconv::canal
