// verify/test_reference_selfcheck.cpp — is the reference itself right?
//
// The sweep judges generated code by verify/reference_quadrature.hpp. Here that
// reference is checked against things that share none of its machinery:
//  1. closed forms of J_i written independently here from docs/mathematics.md §2 (J_1 with
//     asinh, J_2 with atan, J_3 algebraic; the a < 0 form of J_1 and the
//     recurrence downwards for compact kernels; J_{-2}, J_{-4} as
//     polynomials), through docs/mathematics.md §2's mapping of each family to J;
//  2. the gradient against 4th-order central differences of the reference f
//     (checks the hand-written K'(r)/r of kernel_definitions.hpp);
//  3. an independent quadrature: 50-digit cpp_bin_float with adaptive
//     Gauss–Kronrod on the plain weighted integrand (no moments, no sinh
//     substitution, no shared nodes), including near-line and weighted cases;
//  4. the tanh-sinh rule itself (tanh_sinh_moments.hpp) on integrals with
//     known values.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "extended_precision.hpp"
#include "kernel_definitions.hpp"
#include "reference_quadrature.hpp"
#include "sampling.hpp"
#include "tanh_sinh_moments.hpp"

namespace skelconv::verify {
namespace {

/// The reference promises ~1e-25 (ReferenceTolerances::requested); agreement
/// with an exact formula evaluated in binary128 (rounding ~1e-33 at generic
/// points, where ac − b² is not small) must be at least that good.
constexpr double closed_form_tolerance = 1e-25;

/// 4th-order central differences with step h = 1e-6 d (d = distance to the
/// segment): truncation h⁴/30 |f⁽⁵⁾| ≲ 1e-24 · (i+1)…(i+4)/30 ≤ 5e-21 relative
/// for i ≤ 16, and the reference's own error (≤ 1e-25 relative, estimated)
/// amplified by 1.5/h·d/i ≲ 2e-19. 1e-17 keeps a factor 50 over that bound;
/// a wrong K' is wrong at O(1).
constexpr double finite_difference_tolerance = 1e-17;
constexpr double finite_difference_step = 1e-6;

/// Independent 50-digit quadrature, asked for 1e-32: the two references must
/// agree to the binary128 one's promise.
constexpr double independent_tolerance = 1e-25;
/// ... and the 50-digit quadrature must itself claim convergence to well
/// below that (its estimate, relative to its L1 norm), or the test proves nothing.
constexpr double independent_converged = 1e-28;

constexpr int samples_per_case = 6;

struct Abc {
  extended a, b, c;
};

// ---- closed forms, docs/mathematics.md §2 (Hubert 2012 §3.1), written independently ----

extended j1_positive(const Abc& q) {  // a > 0, ac − b² > 0
  const extended d = sqrt(q.a * q.c - q.b * q.b);
  return (asinh((q.a - q.b) / d) + asinh(q.b / d)) / sqrt(q.a);
}
extended j2_positive(const Abc& q) {
  const extended d = sqrt(q.a * q.c - q.b * q.b);
  return (atan((q.a - q.b) / d) + atan(q.b / d)) / d;
}
extended j3_positive(const Abc& q) {
  return ((q.a - q.b) / sqrt(q.a - 2 * q.b + q.c) + q.b / sqrt(q.c)) / (q.a * q.c - q.b * q.b);
}
extended j_positive(int i, const Abc& q) {
  switch (i) {
    case 1: return j1_positive(q);
    case 2: return j2_positive(q);
    default: return j3_positive(q);
  }
}

/// a < 0 < b² − ac (compact kernels, on the clipped segment where q ≥ 0).
extended j1_negative(const Abc& q) {
  const extended m = sqrt(-q.a);
  const extended q1 = std::max<extended>(0, q.a - 2 * q.b + q.c), q0 = std::max<extended>(0, q.c);
  return -(atan((q.a - q.b) / (m * sqrt(q1))) + atan(q.b / (m * sqrt(q0)))) / m;
}
/// J_{-1}, J_{-3} from recurrence (1) taken at i = 1 and i = −1:
///   (i−2)(ca−b²)J_i + a(3−i)J_{i−2} = (a−b) q(1)^{(2−i)/2} + b q(0)^{(2−i)/2}
extended j_minus1(const Abc& q) {
  const extended q1 = std::max<extended>(0, q.a - 2 * q.b + q.c), q0 = std::max<extended>(0, q.c);
  return ((q.a - q.b) * sqrt(q1) + q.b * sqrt(q0) + (q.c * q.a - q.b * q.b) * j1_negative(q)) / (2 * q.a);
}
extended j_minus3(const Abc& q) {
  const extended q1 = std::max<extended>(0, q.a - 2 * q.b + q.c), q0 = std::max<extended>(0, q.c);
  return ((q.a - q.b) * q1 * sqrt(q1) + q.b * q0 * sqrt(q0) + 3 * (q.c * q.a - q.b * q.b) * j_minus1(q)) / (4 * q.a);
}
/// J_{-2} = ∫ q, J_{-4} = ∫ q², q = a t² − 2 b t + c: polynomials.
extended j_minus2(const Abc& q) { return q.a / 3 - q.b + q.c; }
extended j_minus4(const Abc& q) {
  return q.a * q.a / 5 - q.a * q.b + (4 * q.b * q.b + 2 * q.a * q.c) / 3 - 2 * q.b * q.c + q.c * q.c;
}

struct Geometry {
  Vec3<extended> a, b, p;
};
Geometry widen_problem(const SweepProblem& pb) { return {widen(pb.a), widen(pb.b), widen(pb.p)}; }

extended reference_f(ReferenceIntegrator& integrator, const KernelDefinition<extended>& kernel, const Geometry& g,
                     const std::array<extended, 4>& w, int weight_degree, ReferenceField* out = nullptr) {
  const ReferenceField field = integrator.field(integrator.moments(kernel, g.a, g.b, g.p), w, weight_degree);
  EXPECT_FALSE(field.flagged) << "reference flagged: estimate " << field.f_relative_error;
  if (out) *out = field;
  return field.f;
}

constexpr std::array<extended, 4> unit_weight{1, 0, 0, 0};

TEST(ReferenceSelfCheck, InverseMatchesClosedFormsJ1J2J3) {
  ReferenceIntegrator integrator;
  for (int i = 1; i <= 3; ++i)
    for (int k = 0; k < samples_per_case; ++k) {
      const SweepProblem pb = draw_problem(7, KernelFamily::inverse, i, Region::generic, k);
      const Geometry g = widen_problem(pb);
      const Vec3<extended> ab = sub(g.b, g.a), ap = sub(g.p, g.a);
      const Abc q{dot(ab, ab), dot(ab, ap), dot(ap, ap)};  // p^i: C = |AB| J_i(|AB|², AB·AP, |AP|²)
      const extended expected = norm(ab) * j_positive(i, q);
      const extended got = reference_f(integrator, {KernelFamily::inverse, i}, g, unit_weight, 0);
      EXPECT_LE(static_cast<double>(abs(got / expected - 1)), closed_form_tolerance) << "i=" << i << " k=" << k;
    }
}

TEST(ReferenceSelfCheck, CauchyMatchesClosedFormsThroughItsMapping) {
  ReferenceIntegrator integrator;
  for (int i = 1; i <= 3; ++i)
    for (int k = 0; k < samples_per_case; ++k) {
      const SweepProblem pb = draw_problem(8, KernelFamily::cauchy, i, Region::generic, k);
      const Geometry g = widen_problem(pb);
      const extended s(pb.s);
      const Vec3<extended> ab = sub(g.b, g.a), ap = sub(g.p, g.a);
      // c_s^i: C = |AB| J_i(s|AB|², s AB·AP, 1 + s|AP|²)
      const Abc q{s * dot(ab, ab), s * dot(ab, ap), 1 + s * dot(ap, ap)};
      const extended expected = norm(ab) * j_positive(i, q);
      const extended got = reference_f(integrator, {KernelFamily::cauchy, i, s}, g, unit_weight, 0);
      EXPECT_LE(static_cast<double>(abs(got / expected - 1)), closed_form_tolerance) << "i=" << i << " k=" << k;
    }
}

TEST(ReferenceSelfCheck, CompactMatchesNegativeIndexClosedForms) {
  ReferenceIntegrator integrator;
  for (int i = 1; i <= 4; ++i)
    for (Region region : {Region::generic, Region::support_boundary})
      for (int k = 0; k < samples_per_case; ++k) {
        const SweepProblem pb = draw_problem(9, KernelFamily::compact, i, region, 3 * k);  // 3k: sphere cuts
        const Geometry g = widen_problem(pb);
        const extended R(pb.R);
        const auto clip = clip_to_ball(g.a, g.b, g.p, R);
        ASSERT_TRUE(clip.has_value());
        // k_R^i on the clipped [A_P, B_P]: C = |A_PB_P| J_{-i}(−|A_PB_P|²/R², −A_PP·A_PB_P/R², 1 − |A_PP|²/R²)
        const Vec3<extended> ab = sub(g.b, g.a);
        const Vec3<extended> ap_start = axpy(clip->t0, ab, g.a), ap_end = axpy(clip->t1, ab, g.a);
        const Vec3<extended> sub_ab = sub(ap_end, ap_start), sub_ap = sub(g.p, ap_start);
        const Abc q{-dot(sub_ab, sub_ab) / (R * R), -dot(sub_ap, sub_ab) / (R * R), 1 - dot(sub_ap, sub_ap) / (R * R)};
        const extended j = i == 1 ? j_minus1(q) : i == 2 ? j_minus2(q) : i == 3 ? j_minus3(q) : j_minus4(q);
        const extended expected = norm(sub_ab) * j;
        // Degree 1 is not generated (k_R^1 is not smooth) but its value is a
        // fine test of the reference; its K'/r is singular at r = R, so only
        // f is compared here.
        const ReferenceField field =
            integrator.field(integrator.moments({KernelFamily::compact, i, 1, R}, g.a, g.b, g.p), unit_weight, 0);
        if (i > 1) {
          EXPECT_FALSE(field.flagged);
        }
        EXPECT_LE(static_cast<double>(abs(field.f / expected - 1)), closed_form_tolerance)
            << "i=" << i << " region=" << region_name(region) << " k=" << k;
      }
}

/// ∇f of the reference against 4th-order central differences of its f.
TEST(ReferenceSelfCheck, GradientMatchesFiniteDifferencesOfF) {
  ReferenceIntegrator integrator;
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact})
    for (int i : {2, 3, 8, 16})
      for (int k = 0; k < 3; ++k) {
        const SweepProblem pb = draw_problem(10, family, i, Region::generic, k);
        const Geometry g = widen_problem(pb);
        const KernelDefinition<extended> kernel{family, i, extended(pb.s), extended(pb.R)};
        std::array<extended, 4> w{};
        for (int c = 0; c < 4; ++c) w[c] = extended(pb.w[c]);
        ReferenceField field;
        reference_f(integrator, kernel, g, w, 3, &field);
        const extended h = extended(finite_difference_step) * distance_to_segment(pb.a, pb.b, pb.p);
        Vec3<extended> fd{};
        for (int c = 0; c < 3; ++c) {
          const auto f_at = [&](int steps) {
            Geometry moved = g;
            moved.p[c] += steps * h;
            return reference_f(integrator, kernel, moved, w, 3);
          };
          fd[c] = (f_at(-2) - 8 * f_at(-1) + 8 * f_at(1) - f_at(2)) / (12 * h);
        }
        const double error = static_cast<double>(norm(sub(fd, field.grad)) / norm(field.grad));
        EXPECT_LE(error, finite_difference_tolerance) << family_name(family) << " i=" << i << " k=" << k;
      }
}

/// Independent quadrature: 50 digits, Gauss–Kronrod 61, plain integrand.
using wide = boost::multiprecision::cpp_bin_float_50;

struct IndependentField {
  wide f;
  std::array<wide, 3> grad;
  bool converged = true;  ///< Gauss–Kronrod's own error estimate met `independent_converged`
};

IndependentField independent_field(const SweepProblem& pb) {
  const KernelDefinition<wide> kernel{pb.family, pb.degree, wide(pb.s), wide(pb.R)};
  std::array<wide, 3> ab, ap;
  for (int c = 0; c < 3; ++c) ab[c] = wide(pb.b[c]) - wide(pb.a[c]), ap[c] = wide(pb.p[c]) - wide(pb.a[c]);
  const wide aa = dot(ab, ab), bb = dot(ab, ap);
  wide t0 = 0, t1 = 1;
  if (pb.family == KernelFamily::compact) {  // roots of |AP − t AB|² = R², by the quadratic formula
    const wide cc = dot(ap, ap) - wide(pb.R) * wide(pb.R);
    const wide half_width = sqrt(bb * bb - aa * cc) / aa;
    t0 = std::max<wide>(0, bb / aa - half_width);
    t1 = std::min<wide>(1, bb / aa + half_width);
  }
  const wide t_star = std::min<wide>(std::max<wide>(bb / aa, t0), t1);
  const wide length = sqrt(aa);
  IndependentField out;
  // component 0 → f, 1..3 → ∇f
  for (int component = 0; component < 4; ++component) {
    const auto integrand = [&](const wide& t) {
      std::array<wide, 3> d;
      for (int c = 0; c < 3; ++c) d[c] = ap[c] - t * ab[c];
      const wide r = sqrt(dot(d, d));
      const wide w = wide(pb.w[0]) + t * (wide(pb.w[1]) + t * (wide(pb.w[2]) + t * wide(pb.w[3])));
      return component == 0 ? w * kernel.value(r) : w * kernel.derivative_over_r(r) * d[component - 1];
    };
    // Pieces [t0, t*] and [t*, t1]. For the compact family an end that is on
    // the support sphere makes the integrand behave like (t − t_end)^((i−2)/2)
    // (half-integer for odd i: Gauss–Kronrod converges slowly); t = t_end ±
    // (t* − t_end) y² makes it smooth, dt = 2 |t* − t_end| y dy.
    wide sum = 0;
    for (const auto& [end, peak] : {std::pair{t0, t_star}, std::pair{t1, t_star}}) {
      if (end == peak) continue;
      const wide span = peak - end;
      const auto in_y = [&](const wide& y) { return integrand(end + span * y * y) * 2 * abs(span) * y; };
      wide err = 0, l1 = 0;
      sum += boost::math::quadrature::gauss_kronrod<wide, 61>::integrate(in_y, wide(0), wide(1), 40, wide(1e-32), &err,
                                                                         &l1);
      out.converged = out.converged && err <= wide(independent_converged) * l1;
    }
    if (component == 0) out.f = length * sum;
    else out.grad[component - 1] = length * sum;
  }
  return out;
}

TEST(ReferenceSelfCheck, AgreesWithIndependent50DigitGaussKronrod) {
  ReferenceIntegrator integrator;
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact})
    for (Region region : {Region::generic, Region::near_line_beside, Region::near_ends, Region::far})
      for (int i : {3, 16}) {
        const SweepProblem pb = draw_problem(11, family, i, region, 0);
        const Geometry g = widen_problem(pb);
        std::array<extended, 4> w{};
        for (int c = 0; c < 4; ++c) w[c] = extended(pb.w[c]);
        ReferenceField field;
        reference_f(integrator, {family, i, extended(pb.s), extended(pb.R)}, g, w, 3, &field);
        const IndependentField other = independent_field(pb);
        EXPECT_TRUE(other.converged) << family_name(family) << " i=" << i << " " << region_name(region);
        const double f_error = static_cast<double>(abs(wide(field.f) / other.f - 1));
        std::array<wide, 3> diff;
        for (int c = 0; c < 3; ++c) diff[c] = wide(field.grad[c]) - other.grad[c];
        const double grad_error = static_cast<double>(sqrt(dot(diff, diff) / dot(other.grad, other.grad)));
        EXPECT_LE(f_error, independent_tolerance) << family_name(family) << " i=" << i << " " << region_name(region);
        EXPECT_LE(grad_error, independent_tolerance) << family_name(family) << " i=" << i << " " << region_name(region);
      }
}

/// The tanh-sinh rule the references share (tanh_sinh_moments.hpp), on
/// integrals with known values: several integrands summed on one set of
/// nodes, each within 1e-30 of its value, and its error never above the
/// rule's own estimate (plus binary128's rounding). The shapes are those the
/// references hand it: smooth, a narrow peak at the end x = 0 (the
/// references put theirs there), an integrable end singularity.
TEST(ReferenceSelfCheck, TanhSinhRuleMeetsItsEstimates) {
  TanhSinhMoments rule(15);
  const extended rounding = 1e-32;
  const auto check = [&](const auto& integrals, const std::array<extended, 4>& exact, const char* what) {
    for (std::size_t m = 0; m < exact.size(); ++m) {
      const extended error = abs(integrals.value[m] - exact[m]);
      EXPECT_LE(static_cast<double>(error / abs(exact[m])), 1e-30) << what << " integral " << m;
      EXPECT_LE(error, integrals.error[m] + rounding * abs(exact[m])) << what << " integral " << m;
    }
  };
  const extended x_end = 3;
  const auto smooth = rule.integrate<4>(
      [](const extended& x) { return std::array<extended, 4>{1, x, x * x * x * x * x, exp(-x)}; }, x_end,
      extended(1e-25));
  check(smooth, {x_end, x_end * x_end / 2, pow(x_end, 6) / 6, 1 - exp(-x_end)}, "smooth");

  const extended w = 1e-3;  // peaks of width w at x = 0, and x^(−1/2)
  const auto peaked = rule.integrate<4>(
      [&](const extended& x) {
        return std::array<extended, 4>{w / (x * x + w * w), w * w / ((x * x + w * w) * (x * x + w * w)),
                                       1 / sqrt(x), x / (x * x + w * w)};
      },
      extended(1), extended(1e-25));
  const extended atan_term = atan(1 / w);
  check(peaked,
        {atan_term, (atan_term + w / (1 + w * w)) / (2 * w), extended(2), log1p(1 / (w * w)) / 2}, "peaked");
  EXPECT_GT(peaked.levels, smooth.levels) << "the peak needs finer levels than the smooth integrands";

  EXPECT_THROW(rule.integrate<1>(
                   [](const extended& x) {
                     return std::array<extended, 1>{x < 0.5 ? std::numeric_limits<extended>::quiet_NaN() : x};
                   },
                   extended(1), extended(1e-25)),
               std::domain_error);
}

}  // namespace
}  // namespace skelconv::verify
