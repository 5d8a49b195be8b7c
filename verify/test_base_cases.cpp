// verify/test_base_cases.cpp — the base cases of the
// recurrences, checked against quadrature of the definition.
//
// The recurrence test of test_properties.cpp compares generated J_i with
// generated J_{i−2}; both come from the same J_1, J_2 (J_0, J_1 for compact
// kernels), so a wrong base case passes it. Here the generated functions of
// the lowest degrees (the base cases themselves: inverse and Cauchy i = 1, 2;
// compact i = 2 and 3, one step from J_0, J_{−1}) and of a high degree per
// family (16, and 15 for the compact odd branch) are compared, in binary128,
// with the binary128 quadrature of the definition (reference_quadrature.hpp),
// at a point in every stable-form branch the generator chooses between
// (codegen/segment_program_builder.hpp). Each point's branch is asserted from
// the branch conditions recomputed here, so a point that drifts out of its
// branch fails instead of silently testing another one.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "point_evaluation.hpp"

namespace skelconv::verify {
namespace {

// About ten times the worst relative error measured here in binary128
// (2.8e-26; the far branch's 20-point rule 1.1e-33, far below its a-priori
// bound of ~1e-19): a wrong base case, even in its 25th digit, fails.
constexpr double binary128_tolerance = 3e-25;

enum class Branch { flat, beyond_downward, upward, compact_upward, compact_downward, compact_even };

std::string branch_name(Branch branch) {
  switch (branch) {
    case Branch::flat: return "flat (Gauss rule, D >= 2a^2)";
    case Branch::beyond_downward: return "beyond an end, rho <= 7/10 (downward)";
    case Branch::upward: return "upward from J_1, J_2";
    case Branch::compact_upward: return "compact, vertex outside, q_e/q_max <= 17/20 (J_upward_compact)";
    case Branch::compact_downward: return "compact, downward from J_0, J_1";
    case Branch::compact_even: return "compact even degree (exact Gauss rule)";
  }
  return "";
}

// A = (0.1, −0.2, 0.3), AB = (0.8, 0.4, −0.2) (|AB| ≈ 0.917), and P at
// parameter t along AB and distance `distance` from the line along a unit
// normal of AB.
SweepProblem problem(KernelFamily family, int degree, double t, double distance, double s, double R) {
  SweepProblem pb;
  pb.family = family;
  pb.degree = degree;
  pb.a = {0.1, -0.2, 0.3};
  const Vec3<double> ab{0.8, 0.4, -0.2};
  for (int c = 0; c < 3; ++c) pb.b[c] = pb.a[c] + ab[c];
  const Vec3<double> normal{0.0, 0.4472135954999579, 0.8944271909999159};  // ⟂ AB: 0.4·0.447… − 0.2·0.894… = 0
  for (int c = 0; c < 3; ++c) pb.p[c] = pb.a[c] + t * ab[c] + distance * normal[c];
  pb.w = {1.0, 0.5, 0.25, 0.125};
  pb.s = s;
  pb.R = R;
  return pb;
}

// The branch the generated code takes at pb (conditions of
// segment_program_builder.hpp, recomputed in long double from the inputs).
Branch branch_of(const SweepProblem& pb) {
  using L = long double;
  L ab[3], ap[3];
  for (int c = 0; c < 3; ++c) ab[c] = L(pb.b[c]) - L(pb.a[c]), ap[c] = L(pb.p[c]) - L(pb.a[c]);
  const L aa = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const L bb = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
  const L cc = ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2];
  if (pb.family == KernelFamily::compact) {
    if (pb.degree % 2 == 0) return Branch::compact_even;
    // q = 1 − r²/R²: a = −|AB|²/R², b = −AB·AP/R², c = 1 − |AP|²/R².
    const L R2 = L(pb.R) * L(pb.R), a = -aa / R2, b = -bb / R2, c = 1 - cc / R2, D = a * c - b * b;
    const L root = std::sqrt(b * b - a * c);  // q = 0 at (b ∓ root)/a
    const L t0 = std::max(L(0), (b + root) / a), t1 = std::min(L(1), (b - root) / a);
    const auto q = [&](L t) { return (a * t - 2 * b) * t + c; };
    const L vertex = b / a;
    const bool outside = vertex < t0 || vertex > t1;
    const L q_e = std::max(q(t0), q(t1));
    return outside && a * q_e - L(17) / 20 * D >= 0 ? Branch::compact_upward : Branch::compact_downward;
  }
  const L s = pb.family == KernelFamily::cauchy ? L(pb.s) : L(1);
  const L a = s * aa, b = s * bb, c = (pb.family == KernelFamily::cauchy ? 1 : 0) + s * cc, D = a * c - b * b;
  if (D - 2 * a * a >= 0) return Branch::flat;
  const L q_near = std::min(c, a - 2 * b + c);
  if (-b * (a - b) >= 0 && L(7) / 10 * a * q_near - D >= 0) return Branch::beyond_downward;
  return Branch::upward;
}

struct Case {
  KernelFamily family;
  std::vector<int> degrees;
  double t, distance, s, R;
  Branch branch;
};

std::vector<Case> cases() {
  const std::vector<int> inverse_cauchy{1, 2, 16};
  return {
      {KernelFamily::inverse, inverse_cauchy, 0.4, 0.5, 1, 1, Branch::upward},             // generic, beside
      {KernelFamily::inverse, inverse_cauchy, 0.6, 1e-3, 1, 1, Branch::upward},            // near the line, beside
      {KernelFamily::inverse, inverse_cauchy, 1.1, 0.5, 1, 1, Branch::upward},             // beyond B, ρ ≈ 0.96
      {KernelFamily::inverse, inverse_cauchy, 1.3, 0.05, 1, 1, Branch::beyond_downward},   // beyond B, near the line
      {KernelFamily::inverse, inverse_cauchy, -0.25, 0.02, 1, 1, Branch::beyond_downward}, // beyond A
      {KernelFamily::inverse, inverse_cauchy, 0.5, 3.0, 1, 1, Branch::flat},               // far
      {KernelFamily::cauchy, inverse_cauchy, 0.4, 0.5, 1, 1, Branch::upward},
      {KernelFamily::cauchy, inverse_cauchy, 0.6, 1e-3, 100, 1, Branch::upward},
      {KernelFamily::cauchy, inverse_cauchy, 1.3, 0.05, 100, 1, Branch::beyond_downward},
      {KernelFamily::cauchy, inverse_cauchy, -0.25, 0.02, 100, 1, Branch::beyond_downward},
      {KernelFamily::cauchy, inverse_cauchy, 0.5, 3.0, 1, 1, Branch::flat},
      {KernelFamily::compact, {3, 15}, 0.5, 0.3, 1, 1.0, Branch::compact_downward},  // beside, vertex inside
      {KernelFamily::compact, {3, 15}, 1.2, 0.3, 1, 1.0, Branch::compact_downward},  // beyond, q_e/q_max ≈ 0.95
      {KernelFamily::compact, {3, 15}, 1.5, 0.1, 1, 0.8, Branch::compact_upward},    // beyond, q_e/q_max ≈ 0.6
      {KernelFamily::compact, {2, 16}, 0.5, 0.3, 1, 1.0, Branch::compact_even},
      {KernelFamily::compact, {2, 16}, 1.5, 0.1, 1, 0.8, Branch::compact_even},
  };
}

TEST(BaseCases, LowAndHighDegreesMatchTheDefinitionInEveryBranch) {
  ReferenceIntegrator integrator;
  double worst_flat = 0, worst_other = 0;
  for (const Case& c : cases()) {
    for (int degree : c.degrees) {
      const SweepProblem pb = problem(c.family, degree, c.t, c.distance, c.s, c.R);
      const std::string what = std::string(family_name(c.family)) + " i=" + std::to_string(degree) + " t=" +
                               std::to_string(c.t) + " distance=" + std::to_string(c.distance) + ", " +
                               branch_name(c.branch);
      ASSERT_EQ(branch_of(pb), c.branch) << what << ": the point is not in the branch it is meant to test";
      const SegmentMoments moments = integrator.moments(reference_kernel(pb), widen(pb.a), widen(pb.b), widen(pb.p));
      ASSERT_FALSE(moments.empty) << what;
      const auto in = generated_input<extended>(pb);
      ASSERT_TRUE(in.has_value()) << what;
      std::array<extended, 4> w{};
      for (int k = 0; k < 4; ++k) w[k] = extended(pb.w[k]);
      for (int weight_degree : {0, 3}) {
        const GeneratedKernel<extended>* kernel = find_generated_extended(c.family, degree, weight_degree);
        ASSERT_NE(kernel, nullptr) << what;
        const ReferenceField ref = integrator.field(moments, w, weight_degree);
        ASSERT_FALSE(ref.flagged) << what;
        const RelativeErrors e = evaluate_generated(*kernel, in, ref);
        EXPECT_LE(e.f, binary128_tolerance) << what << " w=" << weight_degree;
        EXPECT_LE(e.grad, binary128_tolerance) << what << " w=" << weight_degree;
        double& worst = c.branch == Branch::flat ? worst_flat : worst_other;
        worst = std::max({worst, e.f, e.grad});
      }
    }
  }
  std::printf("base cases and high degrees, binary128 vs the definition: worst relative %.2e, flat branch %.2e\n",
              worst_other, worst_flat);
}

}  // namespace
}  // namespace skelconv::verify
