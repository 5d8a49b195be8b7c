// skelconv/detail/support_gap.hpp: R² − |P − E|² and R²|AB|² − |AB × AP|² of exact
// double inputs, rounded once, where the ball barely reaches E or the line
// (R² − d² = δ R², δ down to 1e-13). The reference is the same expression in
// 50-digit arithmetic (cpp_bin_float_50), where every difference and
// product of the double inputs is exact and the sums err by ~1e-50 R⁴: an
// independent evaluation of the definition, not of the code under test.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "skelconv/detail/plane_height.hpp"
#include "skelconv/detail/support_gap.hpp"

namespace {

using Wide = boost::multiprecision::cpp_bin_float_50;
using Vec = std::array<double, 3>;

// A point at distance `distance` from `from`, in a random direction.
Vec point_at(std::mt19937_64& rng, const Vec& from, double distance) {
  std::normal_distribution<double> normal;
  Vec d{normal(rng), normal(rng), normal(rng)};
  const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {from[0] + distance * d[0] / norm, from[1] + distance * d[1] / norm, from[2] + distance * d[2] / norm};
}

Wide wide_point_gap(const Vec& e, const Vec& p, double R) {
  Wide sum = 0;
  for (int i = 0; i < 3; ++i) sum += (Wide(p[i]) - e[i]) * (Wide(p[i]) - e[i]);
  return Wide(R) * R - sum;
}

Wide wide_line_gap(const Vec& a, const Vec& b, const Vec& p, double R) {
  Wide u[3], v[3], ab2 = 0, cross2 = 0;
  for (int i = 0; i < 3; ++i) {
    u[i] = Wide(b[i]) - a[i];
    v[i] = Wide(p[i]) - a[i];
    ab2 += u[i] * u[i];
  }
  for (int i = 0; i < 3; ++i) {
    const Wide c = u[(i + 1) % 3] * v[(i + 2) % 3] - u[(i + 2) % 3] * v[(i + 1) % 3];
    cross2 += c * c;
  }
  return Wide(R) * R * ab2 - cross2;
}

// ε = 2^−53; a few of them is what one rounding of the exact value plus
// the ε²-terms of the double-word sums leave (the header's bound).
constexpr double kAllowed = 4 * std::numeric_limits<double>::epsilon() / 2;

TEST(SupportGap, PointGapIsRoundedOnceWhereTheBallBarelyReachesTheEnd) {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> coordinate(-3, 3), radius(0.2, 3), exponent(-13, -3);
  double worst = 0, plain_worst = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec e{coordinate(rng), coordinate(rng), coordinate(rng)};
    const double R = radius(rng);
    const Vec p = point_at(rng, e, R * (1 - std::pow(10.0, exponent(rng))));
    double gap;
    skelconv::exact_point_support_gap(e[0], e[1], e[2], p[0], p[1], p[2], R, &gap);
    const Wide reference = wide_point_gap(e, p, R);
    ASSERT_GT(reference, 0);
    worst = std::max(worst, static_cast<double>(abs((Wide(gap) - reference) / reference)));
    double plain = R * R;
    for (int i = 0; i < 3; ++i) plain -= (p[i] - e[i]) * (p[i] - e[i]);
    plain_worst = std::max(plain_worst, static_cast<double>(abs((Wide(plain) - reference) / reference)));
  }
  EXPECT_LE(worst, kAllowed);
  // What the header is for: plain arithmetic loses ~ε/δ there.
  EXPECT_GT(plain_worst, 1e-6);
  std::printf("point gap: worst relative error %.2g (plain arithmetic %.2g)\n", worst, plain_worst);
}

TEST(SupportGap, LineGapIsRoundedOnceWhereTheBallBarelyReachesTheLine) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-3, 3), radius(0.2, 3), exponent(-13, -3), along(0, 1);
  double worst = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec a{coordinate(rng), coordinate(rng), coordinate(rng)};
    const Vec b{coordinate(rng), coordinate(rng), coordinate(rng)};
    const double R = radius(rng);
    // P at distance R(1 − δ) from the line, beside a point of the segment.
    const double t = along(rng);
    const Vec foot{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    const Vec ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    Vec off = point_at(rng, {0, 0, 0}, 1);
    const double ab2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const double along_ab = (off[0] * ab[0] + off[1] * ab[1] + off[2] * ab[2]) / ab2;
    for (int i = 0; i < 3; ++i) off[i] -= along_ab * ab[i];
    const double off_norm = std::sqrt(off[0] * off[0] + off[1] * off[1] + off[2] * off[2]);
    const double h = R * (1 - std::pow(10.0, exponent(rng)));
    const Vec p{foot[0] + h * off[0] / off_norm, foot[1] + h * off[1] / off_norm, foot[2] + h * off[2] / off_norm};
    double gap;
    skelconv::exact_line_support_gap(a[0], a[1], a[2], b[0], b[1], b[2], p[0], p[1], p[2], R, &gap);
    const Wide reference = wide_line_gap(a, b, p, R);
    if (!(reference > 0)) continue;  // the rounded P fell outside the ball: nothing to grade
    worst = std::max(worst, static_cast<double>(abs((Wide(gap) - reference) / reference)));
  }
  EXPECT_LE(worst, kAllowed);
  std::printf("line gap: worst relative error %.2g\n", worst);
}

TEST(SupportGap, ExactWhereNothingCancels) {
  // 3-4-5: R² − |P − E|² = 25 − 9 − 16 = 0 and 36 − 25 = 11, exactly.
  double gap;
  skelconv::exact_point_support_gap(1.0, 1.0, 1.0, 4.0, 5.0, 1.0, 5.0, &gap);
  EXPECT_EQ(gap, 0.0);
  skelconv::exact_point_support_gap(1.0, 1.0, 1.0, 4.0, 5.0, 1.0, 6.0, &gap);
  EXPECT_EQ(gap, 11.0);
  // Line x, P at height 3: R²|AB|² − |AB × AP|² = 25·4 − (2·3)² = 64.
  skelconv::exact_line_support_gap(0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 1.0, 3.0, 0.0, 5.0, &gap);
  EXPECT_EQ(gap, 64.0);
}

}  // namespace

// skelconv/detail/plane_height.hpp: the height of P above the plane of exactly
// coplanar vertices. The polygon lies in an integer frame (u, v orthogonal
// integer vectors, outline coordinates small integers): its vertices are
// exact doubles, exactly coplanar, with normal u × v. P = V + z·w/|w| rounded,
// z from 1e-12 to 1e-3 of the polygon's size; the reference is
// (u × v)·(P − V₀)/|u × v| in 50 digits from the rounded P itself.
TEST(PlaneHeight, HeightIsRoundedOnceNearThePlaneOfExactlyCoplanarVertices) {
  std::mt19937_64 rng(20261203);
  std::uniform_int_distribution<int> small(-9, 9), corner(-40, 40);
  std::uniform_real_distribution<double> exponent(-12, -3), unit(0, 1);
  double worst = 0, plain_worst = 0;
  int tried = 0;
  for (int n = 0; n < 1000; ++n) {
    const Vec u{double(small(rng)), double(small(rng)), double(small(rng))};
    Vec v{double(small(rng)), double(small(rng)), double(small(rng))};
    const Vec w{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};  // u × v, exact
    const double w_norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (!(w_norm > 0)) continue;
    ++tried;
    // A pentagon (convex or not) of integer outline points, placed at a
    // dyadic origin, everything scaled by 2^−6 (exact).
    const Vec origin{corner(rng) / 64.0 + 0.25, corner(rng) / 64.0 - 0.75, corner(rng) / 64.0 + 0.125};
    const int outline[5][2] = {{0, 0}, {4, 0}, {5, 3}, {2, 1 + n % 3}, {0, 3}};
    std::vector<Vec> vertices;
    for (const auto& q : outline)
      vertices.push_back({origin[0] + (q[0] * u[0] + q[1] * v[0]) / 64.0, origin[1] + (q[0] * u[1] + q[1] * v[1]) / 64.0,
                          origin[2] + (q[0] * u[2] + q[1] * v[2]) / 64.0});
    // P above a point inside, at height z·size.
    const double size = w_norm / 64.0;
    const double height = std::pow(10.0, exponent(rng)) * size * (unit(rng) < 0.5 ? -1 : 1);
    const double a = 1 + 2 * unit(rng), b = 1 + unit(rng);
    Vec p;
    for (int i = 0; i < 3; ++i) p[i] = origin[i] + (a * u[i] + b * v[i]) / 64.0 + height * w[i] / w_norm;
    Wide numerator = 0;
    for (int i = 0; i < 3; ++i) numerator += Wide(w[i]) * (Wide(p[i]) - vertices[0][i]);
    const Wide reference = numerator / Wide(w_norm);
    const double exact = skelconv::exact_plane_height<double>(vertices, p);
    const Vec unit_normal{w[0] / w_norm, w[1] / w_norm, w[2] / w_norm};
    const double plain = skelconv::plain_plane_height(p, vertices[0], unit_normal);
    worst = std::max(worst, double(abs((Wide(exact) - reference) / reference)));
    plain_worst = std::max(plain_worst, double(abs((Wide(plain) - reference) / reference)));
    EXPECT_TRUE(skelconv::needs_exact_plane_height(plain, p, vertices[0])) << "sample " << n;
  }
  std::printf("plane height: worst %.1e rounded once, %.1e in plain arithmetic (%d polygons)\n", worst, plain_worst,
              tried);
  EXPECT_GT(tried, 900);
  EXPECT_LE(worst, kAllowed);
  EXPECT_GT(plain_worst, 1e-8);  // the plain height does lose digits here: the test can tell
}
