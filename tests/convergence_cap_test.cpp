// tests/convergence_cap_test.cpp — a helper that reaches its
// iteration cap reports it (skelconv::NotConvergedError), and the runtime
// turns that into EvaluationError (the CLI's "could not be computed", exit 1),
// instead of returning an unconverged value as if it had converged.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "../src/runtime/convergence_guard.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/gauss_moments.hpp"
#include "skelconv/not_converged.hpp"
#include "skelconv/scalis_compact.hpp"
#include "skelconv/stable_recurrence.hpp"

namespace {

using skelconv::NotConvergedError;

// q(t) = a t² − 2 b t + c over [0, 1] with P beyond t = 0: b < 0. The per-step
// factor of J_downward is ρ = D / (a q_near), q_near = q(0) = c.
struct Quadratic {
  double a, b, c;
  double D() const { return a * c - b * b; }
  double slope(double t) const { return a * t - b; }
  double q(double t) const { return (a * t - 2 * b) * t + c; }
};

// c chosen so that ρ = D/(a c) = rho: c = b²/(a(1 − ρ)). P just beyond
// t = 0 (b = −0.01: |P − midpoint| ≈ 0.52 |AB|), where J_downward runs
// Miller's recurrence (from 1.55 |AB| on a Gauss rule takes over,
// gauss_moments.hpp, and no cap applies).
Quadratic beyond_end_with_rho(double rho) {
  const double a = 1.0, b = -0.01;
  return {a, b, b * b / (a * (1 - rho))};
}

double j_downward(const Quadratic& q, int n) {
  return skelconv::J_downward(n, q.a, q.D(), q.slope(0), q.q(0), q.slope(1), q.q(1));
}

TEST(ConvergenceCap, MillerCapIsBeyondEveryFactorTheGeneratedCodeUses) {
  // The generated code calls the helpers for ρ < 7/10 (17/20 compact): well
  // inside the cap, in double and in binary128-size types alike.
  EXPECT_LT(skelconv::detail::miller_steps(0.85), skelconv::recurrence_max_steps<double>());
  EXPECT_LT(skelconv::detail::miller_steps(0.85L), skelconv::recurrence_max_steps<long double>());
  EXPECT_NO_THROW(j_downward(beyond_end_with_rho(0.7), 5));
}

TEST(ConvergenceCap, JDownwardReachingTheCapThrows) {
  // ρ = 0.99 needs ~4100 steps in double, far above the cap of 386: before
  // this issue the run stopped at the cap and returned the value silently.
  EXPECT_THROW(j_downward(beyond_end_with_rho(0.99), 5), NotConvergedError);
  EXPECT_THROW(j_downward(beyond_end_with_rho(1.5), 5), NotConvergedError);  // ρ ≥ 1: never converges
}

TEST(ConvergenceCap, JUpwardCompactReachingTheCapThrows) {
  // Compact kernel: a < 0, D < 0, per-step factor a q_e / D = 0.99.
  const double a = -1.0, D = -1.0, q_e = 0.99, q_small = 0.5;
  EXPECT_THROW(skelconv::J_upward_compact(-4, a, D, 0.3, q_e, 0.8, q_small), NotConvergedError);
  EXPECT_NO_THROW(skelconv::J_upward_compact(-4, a, D, 0.3, 0.8, 0.8, q_small));  // factor 0.8
}

TEST(ConvergenceCap, CompactScalisPanelDepthCapThrows) {
  // A cone (radius 0 at A) and P 1e-1000 from its tip, in long double (range
  // to 1e-4951): the panels bisect towards the tip ~log2(1e1000) ≈ 3300
  // times, beyond the cap of 1100 levels. Before this issue the panel at the
  // cap was accepted as if it had passed the Bernstein test.
  skelconv::ScalisSegmentInput<long double> in;
  in.a = {0.0L, 0.0L, 0.0L};
  in.b = {1.0L, 0.0L, 0.0L};
  in.tau0 = 0.0L;
  in.tau1 = 0.5L;
  in.sigma = 2.0L;
  in.p = {1e-1000L, 1e-1000L, 0.0L};
  EXPECT_THROW(skelconv::scalis_compact_F(4, in, nullptr), NotConvergedError);
  // 1e-200 from the tip (~660 levels) stays within the cap and is finite.
  in.p = {1e-200L, 1e-200L, 0.0L};
  long double f = 0;
  EXPECT_NO_THROW(f = skelconv::scalis_compact_F(4, in, nullptr));
  EXPECT_TRUE(std::isfinite(f));
}

TEST(ConvergenceCap, GaussPanelsResolvePolesNextToAnEndAndReportUnderflow) {
  // segment_moments_gauss_panels with the pole 1e-20 beyond t = 1 on the
  // line (a = 1, b = 1 (+1e-20, below rounding), a − b = −1e-20, D = 0).
  // Nodes placed by t could not step by 0.9e-20 at t = 1 (the panel loop
  // would not advance); placed by their offset from the end they need ~70
  // panels, and are exact. M_{k,m} = ∫_0^1 t^k (1 + e − t)^(−m) dt,
  // e = 1e-20, is (e^(1−m) − (1 + e)^(1−m))/(m − 1) for k = 0, and within
  // a relative e of it for every k ≤ 10 (t^k = 1 − O(1 − t), and the
  // integral's mass is within ~e of t = 1).
  const double e = 1e-20;
  std::array<double, 2 * 11> out{};
  ASSERT_NO_THROW(skelconv::segment_moments_gauss_panels<double>(3, 5, 10, 1.0, 1.0, -e, 0.0, out.data()));
  for (int level = 0; level < 2; ++level) {
    const int m = 3 + 2 * level;
    const double expected = (std::pow(e, 1 - m) - 1.0) / (m - 1);
    for (int k = 0; k <= 10; ++k) EXPECT_NEAR(out[level * 11 + k] / expected, 1.0, 1e-14) << "k=" << k << " m=" << m;
  }
  // q underflowing at the pivot (the pole 1e-170 beyond the end; q = 1e-340):
  // the integral is not resolvable, reported rather than returned as inf.
  EXPECT_THROW(skelconv::segment_moments_gauss_panels<double>(3, 5, 10, 1.0, 1.0, -1e-170, 0.0, out.data()),
               NotConvergedError);
}

TEST(ConvergenceCap, RuntimeTurnsItIntoEvaluationError) {
  const skelconv::Vec3 p(1, 2, 3);
  try {
    skelconv::detail::evaluate_converged("segment_cauchy_i5_w0_f", p,
                                         []() -> double { throw NotConvergedError("cap reached"); });
    FAIL() << "no exception";
  } catch (const skelconv::EvaluationError& error) {
    EXPECT_STREQ(error.what(), "segment_cauchy_i5_w0_f did not converge at P = (1, 2, 3): cap reached");
  }
  EXPECT_EQ(skelconv::detail::evaluate_converged("f", p, [] { return 2.5; }), 2.5);
}

}  // namespace
