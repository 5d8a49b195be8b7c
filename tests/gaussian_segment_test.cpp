// The Gaussian segment closed form (include/skelconv/primitives/segment_gaussian.hpp)
// against the definition integral |AB| ∫ w(t) b exp(−a |P − Γ(t)|²) dt by
// composite Gauss–Legendre in long double (2000 panels × 20 points: the
// narrowest Gaussian sampled, width 0.03 |AB|, spans 60 panels, so the
// reference is exact to long double rounding). Weight of degree 3, widths
// 1/√a from 0.03 to 10 |AB| (c = a|AB|² from 1e-2 to 1e3: both methods of
// the closed form, both sides of its switch), P beside, near the line
// (1e-6…1e-2 |AB|, projecting inside or beyond an end, or beside the middle,
// within 5e-7 of t = 1/2, where ∇f along AB is a small difference of the two
// halves) and far (10…1e4 |AB|), at weight degrees 3 and 0. The double
// inputs are taken as exact (B − A and P − A formed in long double).
// Measured worst over the 800 samples: f 1.1e-14, ∇f 3.8e-13 per component
// (of |∇f|). That largest one is beside the middle, and it is the
// reference's: the closed form evaluated in long double agrees with the
// double one to 6e-17 there, while the quadrature's long-double sum of
// ±|AP| K terms keeps ~ε_LD |AB| / d. Before the exact preamble and the
// sides' difference (segment_gaussian.hpp) this test failed 91 comparisons.
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "skelconv/primitives/segment_gaussian.hpp"

namespace skelconv {
namespace {

using LD = long double;

TEST(GaussianSegment, MatchesTheDefinitionIntegral) {
  static const detail::gaussian_segment::GaussLegendre<LD, 20> rule;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  for (int n = 0; n < 800; ++n) {
    SegmentInput<double> in;
    for (int i = 0; i < 3; ++i) in.a[i] = 4 * U(rng) - 2, in.b[i] = in.a[i] + 2 * U(rng) - 1;
    std::array<double, 3> ab{};
    double L2 = 0;
    for (int i = 0; i < 3; ++i) ab[i] = in.b[i] - in.a[i], L2 += ab[i] * ab[i];
    const double L = std::sqrt(L2);
    // beside, near the line, far, and near the line beside the middle (where
    // the component of ∇f along AB is a small difference of the two halves)
    const int region = n % 4;
    const double t = region == 1 ? U(rng) * 3 - 1 : region == 3 ? 0.5 + 1e-6 * (U(rng) - 0.5) : U(rng) * 2 - 0.5;
    const double dist = region == 0   ? L * std::pow(10, U(rng) * 1.5 - 1)
                        : region == 2 ? L * std::pow(10, 1 + 3 * U(rng))
                                      : L * std::pow(10, -6 + 4 * U(rng));
    std::array<double, 3> dir{U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5};
    double along = 0;
    for (int i = 0; i < 3; ++i) along += dir[i] * ab[i];
    for (int i = 0; i < 3; ++i) dir[i] -= along / L2 * ab[i];
    const double norm = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int i = 0; i < 3; ++i) in.p[i] = in.a[i] + t * ab[i] + dist * dir[i] / norm;
    const double nearest2 = dist * dist + (t < 0 ? t * t * L2 : t > 1 ? (t - 1) * (t - 1) * L2 : 0);
    // K at the nearest point ≥ e^(−30) b: f stays far above underflow.
    in.gaussian_a = std::min(std::pow(10, -2 + 5 * U(rng)) / L2, 30 / nearest2);
    in.gaussian_b = 1.3;
    for (int k = 0; k < 4; ++k) in.w[k] = 0.2 + 1.8 * U(rng);
    const bool constant_weight = n % 8 >= 4;  // half the samples at weight degree 0
    if (constant_weight) in.w = {in.w[0], 0, 0, 0};

    LD f = 0, g[3] = {0, 0, 0};
    constexpr int panels = 2000;
    for (int k = 0; k < panels; ++k) {
      for (int j = 0; j < 20; ++j) {
        const LD tt = (k + rule.x[j]) / LD(panels), weight = rule.w[j] / LD(panels);
        LD d[3], r2 = 0;
        for (int i = 0; i < 3; ++i)  // the double inputs taken as exact: B − A, P − A in long double
          d[i] = (LD(in.p[i]) - LD(in.a[i])) - tt * (LD(in.b[i]) - LD(in.a[i])), r2 += d[i] * d[i];
        LD w = 0;
        for (int q = 3; q >= 0; --q) w = w * tt + in.w[q];
        const LD K = LD(in.gaussian_b) * std::exp(-LD(in.gaussian_a) * r2);
        f += weight * w * K;
        for (int i = 0; i < 3; ++i) g[i] += weight * w * K * (-2 * LD(in.gaussian_a)) * d[i];
      }
    }
    f *= L;
    for (LD& gi : g) gi *= L;
    std::array<double, 3> grad{};
    const double value = constant_weight ? detail::gaussian_segment::ClosedForm<double, 0>::f_and_grad(in, grad)
                                         : detail::gaussian_segment::ClosedForm<double, 3>::f_and_grad(in, grad);
    EXPECT_NEAR(value, double(f), 1e-13 * double(f)) << "sample " << n;
    const double gnorm = double(std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(grad[i], double(g[i]), 1e-12 * gnorm) << "sample " << n;
  }
}

}  // namespace
}  // namespace skelconv
