// verify/test_polygon_reference.cpp — is the polygon reference itself right?
//
// verify/polygon_reference.hpp is what the closed-form polygon kernels will be
// judged by. Here it is checked against facts that share none of its
// machinery:
//  1. p^3: z·f(P) is the solid angle the polygon subtends at P (Van
//     Oosterom–Strackee for a triangle, summed over a fan of a convex polygon);
//  2. k_R^{2j} with the support disc inside the polygon: f = πR² w^(j+1)/(j+1),
//     ∇f = (0, 0, −2π z w^j), w = 1 − z²/R²;
//  3. additivity over a partition of the polygon (different triangulations),
//     convex and non-convex, every family;
//  4. orientation: reversing the vertex order changes nothing;
//  5. the gradient against central differences of the value (binary128).
// Bounds on identities between references are the sums of the references'
// own absolute error estimates: if the estimates are honest, they hold.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "extended_precision.hpp"
#include "polygon_reference.hpp"

namespace skelconv::verify {
namespace {

using LD = long double;

/// Requested accuracy of the long double references below. Well above the
/// rounding floor of long double (≈1e-18, see polygon_reference.hpp), so that
/// the tests run in seconds; the double closed forms are judged at ~1e-16.
constexpr LD ld_tolerance = 1e-16L;

template <class T>
std::vector<Vec3<T>> polygon(std::initializer_list<std::array<double, 3>> corners) {
  std::vector<Vec3<T>> out;
  for (const auto& c : corners) out.push_back({T(c[0]), T(c[1]), T(c[2])});
  return out;
}

std::vector<int> degrees_of(KernelFamily family) {
  if (family == KernelFamily::compact) return {4, 6, 8};
  return {3, 5, 8};
}

/// Van Oosterom & Strackee (1983): tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a).
/// Evaluated in binary128: near the plane the denominator cancels (relative
/// error ~ε·|a|/z), which in long double alone would be ~1e-14 at z = 1e-6.
extended triangle_solid_angle(const Vec3<extended>& p, const Vec3<extended>& q0, const Vec3<extended>& q1,
                              const Vec3<extended>& q2) {
  const Vec3<extended> a = sub(q0, p), b = sub(q1, p), c = sub(q2, p);
  const extended la = norm(a), lb = norm(b), lc = norm(c);
  const extended numerator = abs(dot(a, polygon_detail::cross(b, c)));
  const extended denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * atan2(numerator, denominator);
}

Vec3<extended> widen_ld(const Vec3<LD>& v) { return {extended(v[0]), extended(v[1]), extended(v[2])}; }

/// Solid angle of a convex polygon: sum over a fan.
extended convex_solid_angle(const std::vector<Vec3<LD>>& poly, const Vec3<LD>& p) {
  extended total = 0;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    total += triangle_solid_angle(widen_ld(p), widen_ld(poly[0]), widen_ld(poly[k]), widen_ld(poly[k + 1]));
  return total;
}

TEST(PolygonReference, InverseCubeIsSolidAngleOverHeight) {
  // Convex pentagon in z = 0 and a triangle in a tilted plane (exact corners).
  const auto pentagon = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {1.25, 0.75, 0}, {0.5, 1.25, 0}, {-0.25, 0.75, 0}});
  const auto tilted = polygon<LD>({{0, 0, 0}, {1, 0, 0.5}, {0.25, 1, 0.25}});
  struct Case {
    const std::vector<Vec3<LD>>* poly;
    Vec3<LD> p;
    const char* what;
  };
  const std::vector<Case> cases{
      {&pentagon, {0.3L, 0.4L, 0.5L}, "above, inside"},
      {&pentagon, {0.3L, 0.4L, -0.5L}, "below, inside"},
      {&pentagon, {2.0L, -0.5L, 0.3L}, "outside"},
      {&pentagon, {0.3L, 0.4L, 1e-6L}, "near plane, inside"},
      {&pentagon, {0.5L, 1e-6L, 1e-6L}, "near plane, near edge"},
      {&pentagon, {1.5L, 0.2L, 1e-6L}, "near plane, outside"},
      {&tilted, {0.4L, 0.3L, 0.9L}, "tilted plane"},
  };
  for (const Case& c : cases) {
    const auto& poly = *c.poly;
    PolygonReferenceIntegrator<LD> integrator(poly);
    const auto ref = integrator.evaluate(c.p, KernelFamily::inverse, {3}, 1, 1, ld_tolerance);
    ASSERT_EQ(ref.size(), 1u);
    const Vec3<extended> normal = polygon_detail::cross(sub(widen_ld(poly[1]), widen_ld(poly[0])),
                                                        sub(widen_ld(poly[2]), widen_ld(poly[0])));
    const extended z = abs(dot(sub(widen_ld(c.p), widen_ld(poly[0])), normal)) / norm(normal);
    const extended omega = convex_solid_angle(poly, c.p);
    EXPECT_TRUE(ref[0].trusted) << c.what;
    EXPECT_NEAR(static_cast<double>(extended(ref[0].value) * z / omega), 1.0, 1e-15) << c.what;
  }
}

TEST(PolygonReference, CompactDiscInsidePolygon) {
  const auto square = polygon<LD>({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}});
  const LD R = 1.25L;
  PolygonReferenceIntegrator<LD> integrator(square);
  for (const LD z : {0.5L, -0.25L, 1e-6L, 1.2L}) {
    const Vec3<LD> p{0.1L, -0.2L, z};
    const auto ref = integrator.evaluate(p, KernelFamily::compact, {2, 4, 6, 8}, 1, R, ld_tolerance);
    const LD w = 1 - z * z / (R * R);
    for (std::size_t k = 0; k < ref.size(); ++k) {
      const int j = 1 + static_cast<int>(k);
      const LD f = std::numbers::pi_v<LD> * R * R * std::pow(w, j + 1) / (j + 1);
      const LD dfdz = -2 * std::numbers::pi_v<LD> * z * std::pow(w, j);
      EXPECT_LE(ref[k].value_error, ld_tolerance);
      EXPECT_NEAR(static_cast<double>(ref[k].value / f), 1.0, 1e-15) << "z=" << static_cast<double>(z);
      // ∇f → 0 as z → 0 while ∫|K'| does not: at z = 1e-6 the in-plane
      // components are rounding (~1e-19 of ∫|K'|), and the reference must
      // say so (untrusted gradient) rather than claim 1e-16 of |∇f|.
      if (std::abs(z) >= 0.25L) {
        EXPECT_TRUE(ref[k].trusted) << "z=" << static_cast<double>(z) << " j=" << j;
      }
      const Vec3<LD> exact{0, 0, dfdz};
      EXPECT_LE(norm(sub(ref[k].gradient, exact)), ref[k].gradient_error * norm(ref[k].gradient))
          << "z=" << static_cast<double>(z) << " j=" << j;
    }
  }
}

struct Field {
  LD f;
  Vec3<LD> grad;
  LD f_error;     ///< absolute
  LD grad_error;  ///< absolute (norm)
};

std::vector<Field> fields(const std::vector<Vec3<LD>>& poly, const Vec3<LD>& p, KernelFamily family) {
  PolygonReferenceIntegrator<LD> integrator(poly);
  const auto refs = integrator.evaluate(p, family, degrees_of(family), 2, 1.5L, ld_tolerance);
  std::vector<Field> out;
  for (const auto& r : refs) {
    EXPECT_TRUE(r.trusted);
    out.push_back({r.value, r.gradient, r.value_error * std::abs(r.value), r.gradient_error * norm(r.gradient)});
  }
  return out;
}

/// f(whole) = Σ f(parts), with the bound Σ of absolute error estimates.
void expect_additive(const std::vector<Vec3<LD>>& whole, const std::vector<std::vector<Vec3<LD>>>& parts,
                     const Vec3<LD>& p, KernelFamily family) {
  const auto total = fields(whole, p, family);
  std::vector<Field> sum(total.size(), Field{0, {0, 0, 0}, 0, 0});
  for (const auto& part : parts) {
    const auto f = fields(part, p, family);
    for (std::size_t k = 0; k < f.size(); ++k) {
      sum[k].f += f[k].f;
      sum[k].grad = axpy(LD(1), f[k].grad, sum[k].grad);
      sum[k].f_error += f[k].f_error;
      sum[k].grad_error += f[k].grad_error;
    }
  }
  for (std::size_t k = 0; k < total.size(); ++k) {
    EXPECT_LE(std::abs(total[k].f - sum[k].f), total[k].f_error + sum[k].f_error)
        << "family " << int(family) << " degree #" << k;
    EXPECT_LE(norm(sub(total[k].grad, sum[k].grad)), total[k].grad_error + sum[k].grad_error)
        << "family " << int(family) << " degree #" << k;
  }
}

TEST(PolygonReference, AdditiveOverPartitions) {
  const auto square = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const auto lower = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}});
  const auto upper = polygon<LD>({{0, 0.5, 0}, {1, 0.5, 0}, {1, 1, 0}, {0, 1, 0}});
  const auto diagonal_a = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  const auto diagonal_b = polygon<LD>({{0, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const auto other_a = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const auto other_b = polygon<LD>({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  // Non-convex L = [0,2]×[0,1] ∪ [0,1]×[1,2].
  const auto ell = polygon<LD>({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  const auto ell_bottom = polygon<LD>({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
  const auto ell_top = polygon<LD>({{0, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  for (const KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    for (const Vec3<LD>& p : {Vec3<LD>{0.3L, 0.6L, 0.4L}, Vec3<LD>{0.7L, 0.5L + 1e-5L, 1e-4L}}) {
      expect_additive(square, {lower, upper}, p, family);
      expect_additive(square, {diagonal_a, diagonal_b}, p, family);
      expect_additive(square, {other_a, other_b}, p, family);
    }
    // Near the re-entrant corner (1, 1) of the L, and generic.
    for (const Vec3<LD>& p : {Vec3<LD>{1.3L, 1.2L, 0.3L}, Vec3<LD>{1.0L + 1e-5L, 1.0L + 2e-5L, 1e-5L}})
      expect_additive(ell, {ell_bottom, ell_top}, p, family);
  }
}

TEST(PolygonReference, OrientationDoesNotMatter) {
  auto ell = polygon<LD>({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  auto reversed = ell;
  std::reverse(reversed.begin(), reversed.end());
  const Vec3<LD> p{1.4L, 0.9L, 0.35L};
  for (const KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    const auto forward = fields(ell, p, family);
    const auto backward = fields(reversed, p, family);
    for (std::size_t k = 0; k < forward.size(); ++k) {
      EXPECT_LE(std::abs(forward[k].f - backward[k].f), forward[k].f_error + backward[k].f_error);
      EXPECT_LE(norm(sub(forward[k].grad, backward[k].grad)), forward[k].grad_error + backward[k].grad_error);
    }
  }
}

TEST(PolygonReference, GradientMatchesCentralDifferencesInBinary128) {
  // Non-convex L in a tilted plane (exactly coplanar corners: z = x/2).
  const auto ell = std::vector<Vec3<extended>>{{0, 0, 0}, {2, 0, 1}, {2, 1, 1}, {1, 1, 0.5}, {1, 2, 0.5}, {0, 2, 0}};
  PolygonReferenceIntegrator<extended> integrator(ell);
  const extended tolerance = 1e-24;
  const extended step = 1e-8;
  const Vec3<extended> p{extended(1.3), extended(0.8), extended(0.9)};
  for (const KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    const std::vector<int> degree{family == KernelFamily::compact ? 6 : 5};
    const auto at_p = integrator.evaluate(p, family, degree, extended(2), extended(1.5), tolerance);
    ASSERT_TRUE(at_p[0].trusted);
    for (int c = 0; c < 3; ++c) {
      Vec3<extended> plus = p, minus = p;
      plus[c] += step;
      minus[c] -= step;
      const auto f_plus = integrator.evaluate(plus, family, degree, extended(2), extended(1.5), tolerance);
      const auto f_minus = integrator.evaluate(minus, family, degree, extended(2), extended(1.5), tolerance);
      const extended difference = (f_plus[0].value - f_minus[0].value) / (2 * step);
      // Truncation h²|f'''|/6 ~ 1e-17 relative (h = 1e-8, distances ~1);
      // the references' own error 1e-24·|f|/h ~ 1e-16. 1e-13 of |∇f| leaves
      // a margin of ~1000 over both and still catches a wrong K' (O(1)).
      EXPECT_LE(static_cast<double>(abs(difference - at_p[0].gradient[c]) / norm(at_p[0].gradient)), 1e-13)
          << "family " << int(family) << " component " << c;
    }
  }
}

TEST(PolygonReference, InverseOnThePolygonIsInfinite) {
  const auto square = polygon<LD>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const auto ref = polygon_reference<LD>(square, {0.25L, 0.5L, 0}, KernelFamily::inverse, {3, 4}, 1, 1, ld_tolerance);
  for (const auto& r : ref) {
    EXPECT_TRUE(std::isinf(r.value));
    EXPECT_TRUE(r.trusted);
  }
}

TEST(PolygonReference, RejectsSelfIntersectingPolygon) {
  const auto bowtie = polygon<LD>({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}});
  EXPECT_THROW(PolygonReferenceIntegrator<LD>{bowtie}, std::invalid_argument);
}

}  // namespace
}  // namespace skelconv::verify
