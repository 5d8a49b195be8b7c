// The Lorentz model of spheres (skelconv/canal/lorentz.hpp), the uniform
// spline, the interpolation of spheres (Algorithm 1) and the characteristic
// circles, in double and long double. Every expected value comes from
// Euclidean geometry written here (distances, the law of cosines, the
// closed form of a linear family), never from the code under test.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include "skelconv/canal/canal_family.hpp"
#include "skelconv/canal/characteristic_circle.hpp"
#include "skelconv/canal/lorentz.hpp"
#include "skelconv/canal/sphere_interpolation.hpp"
#include "skelconv/canal/uniform_spline.hpp"

namespace skelconv::canal {
namespace {

using std::abs;
using std::cos;
using std::sin;
using std::sqrt;

template <class T>
class CanalTest : public ::testing::Test {
 protected:
  /// Relative accuracy asked of formulas that lose a few digits at most:
  /// about 900 ε in either type: 1e-13 in double, 1e-16 in long double (ε = 1.1e-19).
  static T tolerance() { return std::is_same_v<T, double> ? T(1e-13) : T(1e-16); }

  std::mt19937_64 random{20261201};
  T uniform(T lo, T hi) { return std::uniform_real_distribution<double>(double(lo), double(hi))(random); }
  Vector3<T> point(T scale = T(2)) { return {uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale)}; }
  /// A sphere with |radius| in [0.3, 2], either orientation.
  Sphere<T> sphere() {
    const T size = uniform(T(0.3), T(2));
    return {point(), uniform(0, 1) < 0.5 ? size : -size};
  }
  Vector3<T> unit() { return point(1).normalized(); }
};

using Scalars = ::testing::Types<double, long double>;
TYPED_TEST_SUITE(CanalTest, Scalars);

// --- The maps, both ways ---------------------------------------------------------

TYPED_TEST(CanalTest, SphereMapRoundTripAndOrientation) {
  using T = TypeParam;
  for (int trial = 0; trial < 200; ++trial) {
    const Sphere<T> s = this->sphere();
    const Vector5<T> x = sphere_vector(s);
    EXPECT_NEAR(double(lorentz_square(x)), 1.0, double(this->tolerance())) << "Q = 1 on Λ⁴";
    const Sphere<T> back = sphere_from_vector(x);
    EXPECT_NEAR(double(back.radius), double(s.radius), double(this->tolerance() * abs(s.radius)));
    EXPECT_LT(double((back.center - s.center).norm()), double(this->tolerance() * 10));
    EXPECT_LT(double((sphere_vector(Sphere<T>{s.center, -s.radius}) + x).norm()), double(this->tolerance()))
        << "S(c, −r) = −S(c, r)";
  }
  EXPECT_THROW(sphere_vector(Sphere<T>{Vector3<T>::Zero(), T(0)}), InputError);
  EXPECT_THROW(sphere_from_vector(plane_vector(Plane<T>{Vector3<T>::UnitX(), T(2)})), EvaluationError);
}

TYPED_TEST(CanalTest, PlaneMapRoundTrip) {
  using T = TypeParam;
  for (int trial = 0; trial < 100; ++trial) {
    const Vector3<T> n = this->unit();
    const T d = this->uniform(-3, 3);
    const Vector5<T> x = plane_vector(Plane<T>{T(2.5) * n, T(2.5) * d});  // the same plane, normal not unit
    EXPECT_NEAR(double(lorentz_square(x)), 1.0, double(this->tolerance()));
    EXPECT_EQ(x[0], x[4]);
    const Plane<T> back = plane_from_vector(x);
    EXPECT_LT(double((back.normal - n).norm()), double(this->tolerance()));
    EXPECT_NEAR(double(back.offset), double(d), double(this->tolerance() * 3));
  }
  EXPECT_THROW(plane_vector(Plane<T>{Vector3<T>::Zero(), T(1)}), InputError);
  EXPECT_THROW(plane_from_vector(sphere_vector(Sphere<T>{Vector3<T>::Zero(), T(1)})), EvaluationError);
}

TYPED_TEST(CanalTest, PointMapRoundTripOnTheLightCone) {
  using T = TypeParam;
  for (int trial = 0; trial < 100; ++trial) {
    const Vector3<T> p = this->point(5);
    const Vector5<T> x = point_vector(p);
    EXPECT_LE(double(abs(lorentz_square(x))), double(this->tolerance() * x.squaredNorm())) << "Q = 0";
    EXPECT_NEAR(double(x[0] - x[4]), 1.0, double(this->tolerance() * x.norm()));
    EXPECT_LT(double((point_from_vector(x) - p).norm()), double(this->tolerance() * 10));
    EXPECT_LT(double((point_from_vector(Vector5<T>(T(-3.5) * x)) - p).norm()), double(this->tolerance() * 10))
        << "any multiple is the same point";
  }
  Vector5<T> infinity;
  infinity << 1, 0, 0, 0, 1;  // light-like, x0 = x4
  EXPECT_THROW(point_from_vector(infinity), InputError);
  EXPECT_THROW(point_from_vector(sphere_vector(Sphere<T>{Vector3<T>::Zero(), T(1)})), InputError);
}

// --- L: angles, tangency, incidence -------------------------------------------------

TYPED_TEST(CanalTest, LorentzFormIsTheEuclideanAngleFormula) {
  using T = TypeParam;
  for (int trial = 0; trial < 200; ++trial) {
    const Sphere<T> a = this->sphere(), b = this->sphere();
    const T expected = (a.radius * a.radius + b.radius * b.radius - (a.center - b.center).squaredNorm()) /
                       (T(2) * a.radius * b.radius);
    EXPECT_NEAR(double(lorentz(sphere_vector(a), sphere_vector(b))), double(expected),
                double(this->tolerance() * (T(10) + abs(expected))));
    const Vector3<T> n = this->unit();
    const T d = this->uniform(-2, 2);
    EXPECT_NEAR(double(lorentz(plane_vector(Plane<T>{n, d}), sphere_vector(a))),
                double((n.dot(a.center) - d) / a.radius), double(this->tolerance() * 100));
    const Vector3<T> p = this->point();
    EXPECT_NEAR(double(lorentz(point_vector(p), sphere_vector(a))),
                double(-((p - a.center).squaredNorm() - a.radius * a.radius) / (T(2) * a.radius)),
                double(this->tolerance() * 100));
  }
}

TYPED_TEST(CanalTest, TangencyOrthogonalityAndAngles) {
  using T = TypeParam;
  const T tol = this->tolerance() * 10;
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3<T> c = this->point(), u = this->unit();
    const T r1 = this->uniform(T(0.5), T(2)), r2 = this->uniform(T(0.1), T(0.4));
    const Vector5<T> big = sphere_vector(Sphere<T>{c, r1});
    // Inside and touching: same orientation at the contact, L = +1.
    const Vector5<T> inside = sphere_vector(Sphere<T>{c + (r1 - r2) * u, r2});
    EXPECT_TRUE(are_oriented_tangent(big, inside, tol));
    EXPECT_TRUE(are_tangent(big, inside, tol));
    // Outside and touching, both outward: opposite normals at the contact, L = −1.
    const Vector5<T> outside = sphere_vector(Sphere<T>{c + (r1 + r2) * u, r2});
    EXPECT_TRUE(are_tangent(big, outside, tol));
    EXPECT_FALSE(are_oriented_tangent(big, outside, tol));
    EXPECT_TRUE(are_oriented_tangent(big, Vector5<T>(-outside), tol)) << "reversing one orientation";
    // Orthogonal: d² = r1² + r2².
    const Vector5<T> orthogonal = sphere_vector(Sphere<T>{c + sqrt(r1 * r1 + r2 * r2) * u, -r2});
    EXPECT_TRUE(are_orthogonal(big, orthogonal, tol));
    EXPECT_FALSE(are_tangent(big, orthogonal, tol));
    // Meeting at angle θ: d² = r1² + r2² − 2 r1 r2 cos θ (law of cosines).
    const T theta = this->uniform(T(0.1), T(3));
    const Vector5<T> tilted = sphere_vector(Sphere<T>{c + sqrt(r1 * r1 + r2 * r2 - 2 * r1 * r2 * cos(theta)) * u, r2});
    ASSERT_TRUE(intersection_angle(big, tilted).has_value());
    EXPECT_NEAR(double(*intersection_angle(big, tilted)), double(theta), 1e-9);
    // Apart: no common point.
    EXPECT_FALSE(intersection_angle(big, sphere_vector(Sphere<T>{c + (r1 + 2 * r2) * u, r2})).has_value());
    // A plane at distance |r| from the centre is tangent.
    EXPECT_TRUE(are_tangent(big, plane_vector(Plane<T>{u, u.dot(c) + r1}), tol));
  }
}

TYPED_TEST(CanalTest, PointOnSphere) {
  using T = TypeParam;
  for (int trial = 0; trial < 100; ++trial) {
    const Sphere<T> s = this->sphere();
    const Vector3<T> u = this->unit();
    EXPECT_TRUE(point_on_sphere(Vector3<T>(s.center + abs(s.radius) * u), s, this->tolerance() * 10));
    EXPECT_FALSE(point_on_sphere(Vector3<T>(s.center + abs(s.radius) * (1 + T(1e-6)) * u), s, T(1e-9)));
    EXPECT_FALSE(point_on_sphere(s.center, s, T(0.5)));
  }
}

// --- The Lorentz inversion -------------------------------------------------------

TYPED_TEST(CanalTest, InversionIsAnInvolutionAndMapsTheQuadricToAHyperplane) {
  using T = TypeParam;
  for (int trial = 0; trial < 200; ++trial) {
    Vector5<T> m, pole;
    for (int i = 0; i < 5; ++i) m[i] = this->uniform(-3, 3), pole[i] = this->uniform(-3, 3);
    const T k = trial % 2 ? this->uniform(T(0.2), T(4)) : -this->uniform(T(0.2), T(4));
    const Vector5<T> image = lorentz_inversion(m, pole, k);
    const Vector5<T> back = lorentz_inversion(image, pole, k);
    const T scale = T(1) + m.norm() * (T(1) + T(1) / abs(lorentz_square(Vector5<T>(m - pole))));
    EXPECT_LT(double((back - m).norm()), double(this->tolerance() * 10 * scale)) << "involution";

    const Vector5<T> s = sphere_vector(this->sphere()), omega = sphere_vector(this->sphere());
    if (abs(lorentz(s, omega) - T(1)) < T(1e-3)) continue;  // nearly tangent: ill-conditioned, not this test
    const Vector5<T> x = lorentz_inversion(s, omega, T(1));
    EXPECT_NEAR(double(lorentz(x, omega)), 0.5, double(this->tolerance() * 100 * (T(1) + x.squaredNorm())))
        << "Λ⁴ → the hyperplane L(X, Ω) = ½";
  }
  // On the light cone of the pole, and the pole itself: an error, not a NaN.
  const Vector5<T> pole = sphere_vector(Sphere<T>{Vector3<T>(1, 2, 3), T(0.5)});
  EXPECT_THROW(lorentz_inversion(Vector5<T>(pole + point_vector(Vector3<T>(0.3, -1, 2))), pole, T(1)),
               EvaluationError);
  EXPECT_THROW(lorentz_inversion(pole, pole, T(1)), EvaluationError);
}

TYPED_TEST(CanalTest, SphereTangentIsTheDerivativeOfTheMap) {
  using T = TypeParam;
  for (int trial = 0; trial < 50; ++trial) {
    const Sphere<T> s = this->sphere();
    const Vector3<T> dc = this->point(1);
    const T dr = this->uniform(-1, 1);
    const Vector5<T> tangent = sphere_tangent(s, dc, dr);
    const T scale = T(1) + sphere_vector(s).norm() * tangent.norm();
    EXPECT_NEAR(double(lorentz(sphere_vector(s), tangent)), 0.0, double(this->tolerance() * 10 * scale));
    EXPECT_NEAR(double(lorentz_square(tangent)), double((dc.squaredNorm() - dr * dr) / (s.radius * s.radius)),
                double(this->tolerance() * 10 * scale));
    // Central difference, O(h²) = 1e-10 relative at h = 1e-5 in long double.
    const long double h = 1e-5L;
    const auto at = [&](long double step) {
      return sphere_vector(Sphere<long double>{s.center.template cast<long double>() + step * dc.template cast<long double>(),
                                               (long double)s.radius + step * (long double)dr});
    };
    const Vector5<long double> difference = (at(h) - at(-h)) / (2 * h);
    EXPECT_LT(double((difference - tangent.template cast<long double>()).norm()), 1e-8 * double(scale));
  }
}

// --- The uniform spline ------------------------------------------------------------

using Point2 = Eigen::Matrix<double, 2, 1>;

/// P(t) = a + b t + c t² + d t³ with fixed coefficients, zeroed above `degree`.
Point2 polynomial(double t, int degree) {
  const Point2 a(0.3, -1.0), b(1.5, 0.25), c(-2.0, 0.75), d(0.8, -1.2);
  return a + b * t + (degree >= 2 ? t * t : 0.0) * c + (degree >= 3 ? t * t * t : 0.0) * d;
}

TEST(UniformSpline, ReproducesPolynomialsOfItsDegreeAndHitsTheKnotsExactly) {
  // Two points: linear; three: quadratic; four or more with not-a-knot ends: every cubic.
  for (int points = 2; points <= 10; ++points) {
    const int degree = std::min(points - 1, 3);
    std::vector<Point2> knots;
    for (int k = 0; k < points; ++k) knots.push_back(polynomial(double(k) / (points - 1), degree));
    const UniformSpline<Point2> spline(knots);
    for (int k = 0; k < points; ++k) EXPECT_EQ(spline.value(double(k) / (points - 1)), knots[k]) << "knot " << k;
    for (double t = 0.013; t < 1; t += 0.0517) {
      EXPECT_LT((spline.value(t) - polynomial(t, degree)).norm(), 1e-14) << points << " points, t = " << t;
    }
  }
}

TEST(UniformSpline, IsTwiceContinuouslyDifferentiableAtTheKnots) {
  std::vector<Point2> knots;
  for (int k = 0; k <= 7; ++k) knots.push_back(Point2(std::sin(3.0 * k), std::cos(5.0 * k * k)));
  const UniformSpline<Point2> spline(knots);
  const double h = 1e-7;
  for (int k = 1; k < 7; ++k) {
    const double t = k / 7.0;
    // One-sided differences agree to O(h) when X′ and X″ are continuous.
    EXPECT_LT((spline.derivative(t - h) - spline.derivative(t + h)).norm(), 1e-4) << "C¹ at knot " << k;
    EXPECT_LT((spline.second_derivative(t - h) - spline.second_derivative(t + h)).norm(), 1e-3) << "C² at knot " << k;
    EXPECT_LT((spline.derivative(t) - (spline.value(t + h) - spline.value(t - h)) / (2 * h)).norm(), 1e-5);
  }
}

// --- Interpolation of spheres (Algorithm 1) ------------------------------------------

/// Spheres along a gently curved skeleton, overlapping their neighbours.
template <class T>
std::vector<Vector5<T>> curved_spheres(int count) {
  std::vector<Vector5<T>> spheres;
  for (int k = 0; k < count; ++k) {
    const T s = T(k) / T(std::max(count - 1, 1));
    spheres.push_back(sphere_vector(Sphere<T>{Vector3<T>(2 * s, T(0.5) * sin(3 * s), T(0.2) * s * s), T(0.3) + T(0.2) * s}));
  }
  return spheres;
}

/// A pole far from the spheres (not nested with any).
template <class T>
Vector5<T> far_pole() {
  return sphere_vector(Sphere<T>{Vector3<T>(-5, 4, 3), T(1)});
}

TYPED_TEST(CanalTest, InterpolationPassesThroughTheSpheresAndStaysOnTheQuadric) {
  using T = TypeParam;
  for (int count = 2; count <= 6; ++count) {
    const std::vector<Vector5<T>> spheres = curved_spheres<T>(count);
    const SphereInterpolation<T> family(spheres, far_pole<T>());
    for (int k = 0; k < count; ++k) EXPECT_EQ(family(T(k) / T(count - 1)), spheres[k]) << "knot " << k;
    for (T t = T(0.01); t < 1; t += T(0.037)) {
      const Vector5<T> gamma = family(t);
      EXPECT_NEAR(double(lorentz_square(gamma)), 1.0, double(this->tolerance() * 10 * gamma.squaredNorm())) << t;
      // The hyperplane curve's knots are the inverted spheres: the round trip is the identity.
      const T h = T(1e-5);  // central difference: O(h²) and rounding ε‖Ω‖/h, both ≪ 1e-7
      const Vector5<T> difference = (family(t + h) - family(t - h)) / (2 * h);
      EXPECT_LT(double((difference - family.derivative(t)).norm()), 1e-7 * double(1 + family.derivative(t).norm()));
    }
    // The hyperplane points invert back to the spheres. X_k = Ω + Y_k carries
    // an error ε‖Ω‖, which the inversion multiplies by ‖S_k − Ω‖² (|Y_k| is
    // 1/‖S_k − Ω‖ and S_k − Ω = Y_k/Q(Y_k)).
    for (int k = 0; k < count; ++k) {
      const Vector5<T> x = family.hyperplane_points()[k];
      EXPECT_NEAR(double(lorentz(x, far_pole<T>())), 0.5, double(this->tolerance() * x.squaredNorm()));
      const Vector5<T> back = lorentz_inversion(x, far_pole<T>(), T(1));
      const T scale = far_pole<T>().norm() * (spheres[k] - far_pole<T>()).squaredNorm();
      EXPECT_LT(double((back - spheres[k]).norm()), double(this->tolerance() * 10 * scale));
    }
  }
}

TYPED_TEST(CanalTest, TwoSpheresGiveTheConicThroughThePole) {
  // The line X0 + t (X1 − X0) of H inverts into the plane of Ω, S0, S1: γ(t) − Ω
  // is a combination of S0 − Ω and S1 − Ω, so another pole gives another curve.
  using T = TypeParam;
  const std::vector<Vector5<T>> spheres = curved_spheres<T>(2);
  const Vector5<T> poles[] = {far_pole<T>(), sphere_vector(Sphere<T>{Vector3<T>(1, -3, 0.5), T(-0.7)}),
                              plane_vector(Plane<T>{Vector3<T>(0, 0, 1), T(-2)})};
  std::vector<Vector5<T>> middles;
  for (const Vector5<T>& pole : poles) {
    const SphereInterpolation<T> family(spheres, pole);
    Eigen::Matrix<T, 5, 2> basis;
    basis << spheres[0] - pole, spheres[1] - pole;
    for (T t : {T(0.2), T(0.5), T(0.9)}) {
      const Vector5<T> offset = family(t) - pole;
      const Eigen::Matrix<T, 2, 1> coefficients = basis.colPivHouseholderQr().solve(offset);
      EXPECT_LT(double((basis * coefficients - offset).norm()), double(this->tolerance() * 100 * offset.norm()));
    }
    middles.push_back(family(T(0.5)));
  }
  EXPECT_GT(double((middles[0] - middles[1]).norm()), 1e-3);
  EXPECT_GT(double((middles[0] - middles[2]).norm()), 1e-3);
}

TYPED_TEST(CanalTest, APoleOnTheLinearFamilyGivesTheConeFrustum) {
  // c(u) = c0 + u c′, r(u) = r0 + u r′ is a conic on Λ⁴; with the pole on it
  // (u = 2.5), the two-sphere interpolation traces the same spheres (another
  // parametrisation) and so the same characteristic circles.
  using T = TypeParam;
  const Vector3<T> c0(0.2, -0.1, 0.4), dc(1.5, 0.5, -0.3);
  const T r0 = T(0.3), dr = T(0.4);
  const auto linear = [&](T u) { return Sphere<T>{c0 + u * dc, r0 + u * dr}; };
  const SphereInterpolation<T> family({sphere_vector(linear(0)), sphere_vector(linear(1))}, sphere_vector(linear(T(2.5))));
  for (T t = T(0.05); t < 1; t += T(0.1)) {
    const FamilySample<T> sample = sample_family(family, t);
    const T u = (sample.sphere.center - c0).dot(dc) / dc.squaredNorm();
    EXPECT_GT(double(u), 0.0);
    EXPECT_LT(double(u), 1.0);
    EXPECT_LT(double((sample.sphere.center - linear(u).center).norm()), double(this->tolerance() * 100));
    EXPECT_NEAR(double(sample.sphere.radius), double(linear(u).radius), double(this->tolerance() * 100));
    const Circle<T> expected = *linear_family_circle(linear(u), dc, dr);
    ASSERT_TRUE(sample.circle.has_value());
    EXPECT_LT(double((sample.circle->center - expected.center).norm()), double(this->tolerance() * 100));
    EXPECT_NEAR(double(sample.circle->radius), double(expected.radius), double(this->tolerance() * 100));
    EXPECT_LT(double((sample.circle->normal - expected.normal).norm()), double(this->tolerance() * 100));
  }
}

TYPED_TEST(CanalTest, InterpolationRefusals) {
  using T = TypeParam;
  const Sphere<T> a{Vector3<T>(0, 0, 0), T(1)}, b{Vector3<T>(1.5, 0, 0), T(0.8)};
  const auto message = [](auto construct) {
    try {
      construct();
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  // Fewer than two spheres.
  EXPECT_EQ(message([&] { SphereInterpolation<T>({sphere_vector(a)}, far_pole<T>()); }),
            "spheres: at least 2 spheres are needed, got 1");
  // A pole tangent to b with the same orientation (inside b, touching it).
  const Vector5<T> tangent_pole = sphere_vector(Sphere<T>{Vector3<T>(1.8, 0, 0), T(0.5)});
  EXPECT_TRUE(message([&] { SphereInterpolation<T>({sphere_vector(a), sphere_vector(b)}, tangent_pole); })
                  .starts_with("pole: is tangent to spheres[1] with the same orientation"));
  // Nested spheres: time-like chord.
  const Sphere<T> nested{Vector3<T>(0.1, 0, 0), T(0.5)};
  EXPECT_TRUE(message([&] { SphereInterpolation<T>({sphere_vector(a), sphere_vector(nested)}, far_pole<T>()); })
                  .starts_with("spheres[1]: spheres[0] and spheres[1] are nested"));
  // A pole nested with a (inside it) but not with b: the chord turns time-like.
  const Vector5<T> separating = sphere_vector(Sphere<T>{Vector3<T>(-0.2, 0, 0), T(0.3)});
  EXPECT_TRUE(message([&] { SphereInterpolation<T>({sphere_vector(a), sphere_vector(b)}, separating); })
                  .starts_with("pole: is nested with one of spheres[0] and spheres[1] but not with the other"));
  // The same sphere twice.
  EXPECT_EQ(message([&] { SphereInterpolation<T>({sphere_vector(a), sphere_vector(a)}, far_pole<T>()); }),
            "spheres[1]: the same sphere as spheres[0] (centre and radius): consecutive spheres must differ, no canal surface joins a sphere to itself");
  // The linear family refuses nested spheres too.
  EXPECT_TRUE(message([&] { LinearSphereFamily<T>({a, nested}); }).starts_with("spheres[1]: spheres[0] and spheres[1] are nested"));
}

// --- Characteristic circles ----------------------------------------------------------

TYPED_TEST(CanalTest, LorentzCircleMatchesTheClosedFormOfLinearFamilies) {
  using T = TypeParam;
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Sphere<T> s = this->sphere();
    const Vector3<T> dc = this->point(1);
    // r′ up to 0.99 |c′| (space-like); 1 in 4 a cylinder (r′ = 0: τ is a plane).
    const T dr = trial % 4 == 0 ? T(0) : this->uniform(T(-0.99), T(0.99)) * dc.norm();
    const std::optional<Circle<T>> lorentz_circle = characteristic_circle(sphere_vector(s), sphere_tangent(s, dc, dr));
    // The closed form, written out here: c − (r r′/|c′|²) c′, |r| √(1 − r′²/|c′|²), c′/|c′|.
    const Vector3<T> center = s.center - (s.radius * dr / dc.squaredNorm()) * dc;
    const T radius = abs(s.radius) * sqrt(T(1) - dr * dr / dc.squaredNorm());
    ASSERT_TRUE(lorentz_circle.has_value());
    const T scale = T(1) + s.center.norm();
    EXPECT_LT(double((lorentz_circle->center - center).norm()), double(this->tolerance() * scale)) << trial;
    EXPECT_NEAR(double(lorentz_circle->radius), double(radius), double(this->tolerance() * scale)) << trial;
    EXPECT_LT(double((lorentz_circle->normal - dc.normalized()).norm()), double(this->tolerance() * scale)) << trial;
    // The same through linear_family_circle.
    const Circle<T> closed = *linear_family_circle(s, dc, dr);
    EXPECT_LT(double((closed.center - center).norm()), double(this->tolerance() * scale));
    EXPECT_NEAR(double(closed.radius), double(radius), double(this->tolerance() * scale));
    ++checked;
  }
  EXPECT_EQ(checked, 400);
}

TYPED_TEST(CanalTest, NoCircleWhereTheFamilyIsNotSpaceLike) {
  using T = TypeParam;
  const Sphere<T> s{Vector3<T>(1, 2, 3), T(0.5)};
  const Vector3<T> dc(0.3, 0, 0);
  EXPECT_FALSE(characteristic_circle(sphere_vector(s), sphere_tangent(s, dc, T(0.4))).has_value()) << "time-like";
  EXPECT_FALSE(characteristic_circle(sphere_vector(s), sphere_tangent(s, dc, T(0.3))).has_value()) << "light-like";
  EXPECT_FALSE(linear_family_circle(s, dc, T(0.4)).has_value());
  EXPECT_TRUE(characteristic_circle(sphere_vector(s), sphere_tangent(s, dc, T(0.29))).has_value());
}

TYPED_TEST(CanalTest, CirclesOfAnInterpolatedFamilyLieOnBothSpheres) {
  // The circle is γ(t) ∩ τ with τ = γ′/√Q(γ′): its points are on the sphere
  // γ(t) and on τ (L(P(p), ·) = 0 for both).
  using T = TypeParam;
  const SphereInterpolation<T> family(curved_spheres<T>(5), far_pole<T>());
  for (T t = T(0.03); t < 1; t += T(0.07)) {
    const FamilySample<T> sample = sample_family(family, t);
    ASSERT_TRUE(sample.circle.has_value()) << t;
    const Vector5<T> tangent = family.derivative(t);
    const Vector5<T> tau = tangent / sqrt(lorentz_square(tangent));
    const Vector3<T> e1 = sample.circle->normal.unitOrthogonal(), e2 = sample.circle->normal.cross(e1);
    for (int j = 0; j < 8; ++j) {
      const T psi = T(2) * std::numbers::pi_v<T> * T(j) / T(8);
      const Vector3<T> p = sample.circle->center + sample.circle->radius * (cos(psi) * e1 + sin(psi) * e2);
      EXPECT_LT(double(abs(lorentz(point_vector(p), family(t)))), double(this->tolerance() * 1000)) << t;
      EXPECT_LT(double(abs(lorentz(point_vector(p), tau))), double(this->tolerance() * 1000)) << t;
    }
  }
}

}  // namespace
}  // namespace skelconv::canal
