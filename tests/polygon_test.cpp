// Polygon: validation, canonical orientation, the inverse-kernel +inf
// convention and the compact kernels' exact 0 (suites Polygon*, except
// PolygonValues), and values against references computed here
// independently of the closed forms.
//
// PolygonValues checks the closed forms of polygon_field.hpp. Its
// references share no code with them:
//   - inverse p^3: f(P) · z = Ω(P), the solid angle of the polygon seen from
//     P (∬ z / r³ dQ), by the Van Oosterom–Strackee formula per fan
//     triangle of a convex polygon; ∇f by central differences of it;
//   - every family and degree: Gauss–Legendre product quadrature of the
//     definition ∬ K(|P − Q|) dQ over fan triangles (Duffy's collapsed
//     square), in long double.
#include "skelconv/primitives/polygon.hpp"

#include <cmath>
#include <stdexcept>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expect_input_error.hpp"
#include "reference_quadrature.hpp"  // GaussLegendreRule
#include "src/detail/infinity.hpp"  // skelconv::infinity

namespace skelconv {
namespace {

using test::expect_input_error;

const KernelSpec inverse3 = KernelSpec::inverse(3);
const std::vector<Vec3> unit_square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

// --- Validation ---------------------------------------------------------------

TEST(PolygonValidation, VertexCountAndRepeats) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}}, inverse3); }, "vertices",
                     "a polygon needs at least 3 vertices, got 2");
  expect_input_error([] { Polygon(std::vector<Vec3>{}, inverse3); }, "vertices",
                     "a polygon needs at least 3 vertices, got 0");
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}}, inverse3); }, "vertices[3]",
                     "the last vertex repeats the first one (0, 0, 0): the boundary closes by itself");
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, inverse3); }, "vertices[2]",
                     "the last vertex repeats the first one");
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}, inverse3); }, "vertices[2]",
                     "repeats the previous vertex (1, 0, 0): consecutive vertices must differ");
  expect_input_error([&] { Polygon({{0, 0, 0}, {1, nan, 0}, {0, 1, 0}}, inverse3); }, "vertices[1]",
                     "must be finite");
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {0, infinity, 0}}, inverse3); }, "vertices[2]",
                     "must be finite");
}

TEST(PolygonValidation, DegenerateGeometry) {
  // Edge too short for its position (the segment rule, per edge).
  expect_input_error([] { Polygon({{1e6, 0, 0}, {1e6, 1e-3, 0}, {1e6, 0, 1e-3}}, inverse3); }, "vertices",
                     "degenerate edge from vertices[0] to vertices[1]: length 0.001 is below 1e-08 times the "
                     "largest coordinate magnitude 1000000");
  // Collinear vertices, and a sliver below degenerate_area_ratio · diameter².
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 1, 1}, {3, 3, 3}}, inverse3); }, "vertices",
                     "zero area: area 0 is below 1e-08 times the squared diameter");
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {0.5, 1e-9, 0}}, inverse3); }, "vertices", "zero area");
  // Just above the threshold: accepted.
  EXPECT_NO_THROW(Polygon({{0, 0, 0}, {1, 0, 0}, {0.5, 1e-7, 0}}, inverse3));
  // Coordinates whose squares overflow are fine (any scale);
  // only a diameter that overflows is too large.
  EXPECT_NO_THROW(Polygon({{1e200, 0, 0}, {-1e200, 0, 0}, {0, 1e200, 0}}, inverse3));
  expect_input_error([] { Polygon({{1.5e308, 0, 0}, {-1.5e308, 0, 0}, {0, 1e308, 0}}, inverse3); }, "vertices",
                     "polygon too large");
}

TEST(PolygonValidation, Coplanarity) {
  expect_input_error([] { Polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-3}}, inverse3); }, "vertices",
                     "vertices not coplanar: vertices[");
  // Within Polygon::coplanarity_tolerance of the diameter: accepted.
  EXPECT_NO_THROW(Polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-10}}, inverse3));
  // A tilted square, rotated in double: coplanar to rounding, accepted.
  const double c = std::cos(0.7), s = std::sin(0.7);
  std::vector<Vec3> tilted;
  for (const Vec3& v : unit_square) tilted.emplace_back(v.x(), c * v.y() - s * v.z() + 3, s * v.y() + c * v.z() - 2);
  EXPECT_NO_THROW(Polygon(tilted, inverse3));
}

TEST(PolygonValidation, SelfIntersection) {
  // Two edges crossing.
  expect_input_error([] { Polygon({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {3, 2, 0}}, inverse3); }, "vertices",
                     "self-intersecting boundary: edges vertices[1]-vertices[2] and vertices[3]-vertices[0] meet");
  // The same boundary given the other way round names the same edges.
  expect_input_error([] { Polygon({{3, 2, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 0}}, inverse3); }, "vertices",
                     "self-intersecting boundary: edges");
  // A vertex touching another edge.
  expect_input_error([] { Polygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0, 0}, {0, 2, 0}}, inverse3); },
                     "vertices", "self-intersecting boundary");
  // Two loops sharing a vertex (the vertex listed twice, not consecutively).
  expect_input_error(
      [] { Polygon({{0, 1, 0}, {-1, 1, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, inverse3); },
      "vertices", "self-intersecting boundary");
  // Consecutive edges folding back along each other.
  expect_input_error([] { Polygon({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}}, inverse3); }, "vertices",
                     "self-intersecting boundary: edges vertices[0]-vertices[1] and vertices[1]-vertices[2] meet");
  // A crossing in a tilted plane.
  expect_input_error([] { Polygon({{0, 0, 0}, {2, 0, 2}, {0, 1, 0}, {3, 2, 3}}, inverse3); }, "vertices",
                     "self-intersecting boundary");
  // A straight vertex in the middle of an edge, and a non-convex polygon: simple.
  EXPECT_NO_THROW(Polygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}}, inverse3));
  EXPECT_NO_THROW(Polygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 0.2, 0}, {0, 1, 0}}, inverse3));
}

TEST(PolygonValidation, Kernel) {
  expect_input_error([] { Polygon(unit_square, KernelSpec::inverse(2)); }, "kernel.degree",
                     "degree 2 of the inverse family is not available on a polygon: the contour formula of the "
                     "polygon closed forms (docs/mathematics.md §3, Hubert 2012 §6) excludes it; supported: 3..12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::inverse(1)); }, "kernel.degree",
                     "unsupported degree 1 for the inverse family on a polygon; supported: 3..12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::inverse(13)); }, "kernel.degree",
                     "unsupported degree 13 for the inverse family on a polygon; supported: 3..12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::cauchy(2, 1.0)); }, "kernel.degree",
                     "unsupported degree 2 for the cauchy family on a polygon; supported: 3..12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::compact(5, 1.0)); }, "kernel.degree",
                     "unsupported degree 5 for the compact family on a polygon; supported: 4, 6, 8, 10, 12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::compact(2, 1.0)); }, "kernel.degree",
                     "supported: 4, 6, 8, 10, 12");
  expect_input_error([] { Polygon(unit_square, KernelSpec::compact(4, -1.0)); }, "kernel.R", "must be > 0, got -1");
  expect_input_error([] { Polygon(unit_square, KernelSpec::cauchy(4, 0.0)); }, "kernel.s", "must be > 0, got 0");
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    for (int degree : Polygon::supported_degrees(family)) {
      EXPECT_NO_THROW(Polygon(unit_square, KernelSpec{family, degree, 2.0, 1.5}));
    }
  }
}

// --- Canonical form -------------------------------------------------------------

/// Σ_k (Q_k × Q_{k+1}) · n: twice the signed area about n, > 0 for a
/// counter-clockwise boundary.
double signed_double_area(const std::vector<Vec3>& vertices, const Vec3& normal) {
  double sum = 0;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    sum += vertices[k].cross(vertices[(k + 1) % vertices.size()]).dot(normal);
  }
  return sum;
}

/// A convex pentagon in the tilted plane x − 2y + 2z = 1 (exactly coplanar).
const std::vector<Vec3> tilted_pentagon{{1, 0, 0}, {3, 1, 0}, {3, 2, 1}, {1, 2, 2}, {-1, 0, 1}};

TEST(PolygonCanonicalForm, EitherOrientationStoresTheSamePolygon) {
  const std::vector<Vec3>& given = tilted_pentagon;
  const std::vector<Vec3> reversed(given.rbegin(), given.rend());
  std::vector<Vec3> rotated(given.begin() + 2, given.end());
  rotated.insert(rotated.end(), given.begin(), given.begin() + 2);
  const Polygon forward_polygon(given, inverse3);
  const Polygon reversed_polygon(reversed, inverse3);
  const Polygon rotated_polygon(rotated, inverse3);
  EXPECT_EQ(forward_polygon.vertices(), reversed_polygon.vertices());
  EXPECT_EQ(forward_polygon.vertices(), rotated_polygon.vertices());
  EXPECT_EQ(forward_polygon.normal(), reversed_polygon.normal());
  EXPECT_EQ(forward_polygon.area(), reversed_polygon.area());
  EXPECT_GT(signed_double_area(forward_polygon.vertices(), forward_polygon.normal()), 0);
}

TEST(PolygonCanonicalForm, CounterClockwiseAboutAUnitNormal) {
  for (const std::vector<Vec3>& given : {unit_square, std::vector<Vec3>(unit_square.rbegin(), unit_square.rend())}) {
    const Polygon polygon(given, inverse3);
    EXPECT_EQ(polygon.normal(), Vec3(0, 0, 1));  // largest coordinate positive
    EXPECT_EQ(polygon.vertices().front(), Vec3(0, 0, 0));  // lexicographically smallest first
    EXPECT_GT(signed_double_area(polygon.vertices(), polygon.normal()), 0);
    EXPECT_EQ(polygon.area(), 1.0);
  }
  const Polygon tilted({{0, 0, 1}, {1, 0, 1}, {0, 1, 2}}, inverse3);
  EXPECT_NEAR(tilted.normal().norm(), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(tilted.normal().dot(Vec3(0, -1, 1).normalized())), 1.0, 1e-15);
  EXPECT_GT(signed_double_area(tilted.vertices(), tilted.normal()), 0);
  EXPECT_NEAR(tilted.area(), std::sqrt(2.0) / 2, 1e-15);
}

// --- The +inf convention of inverse kernels --------------------------------------

TEST(PolygonInverseSingularity, PointsOfTheClosedPolygonGiveInfinity) {
  const std::vector<Vec3> in_closed_square{{0.5, 0.5, 0}, {0.5, 0, 0}, {1, 1, 0}, {0, 0.25, 0}, {1e-300, 1e-300, 0}};
  for (int degree : Polygon::supported_degrees(KernelFamily::inverse)) {
    const Polygon polygon(unit_square, KernelSpec::inverse(degree));
    for (const Vec3& p : in_closed_square) {
      SCOPED_TRACE(testing::Message() << "degree " << degree << ", P = " << p.transpose());
      EXPECT_EQ(polygon.value(p), infinity);
      EXPECT_EQ(polygon.gradient(p), Vec3::Constant(infinity));
      const FieldSample both = polygon.value_and_gradient(p);
      EXPECT_EQ(both.value, infinity);
      EXPECT_EQ(both.gradient, Vec3::Constant(infinity));
    }
  }
  // A tilted plane: points whose offsets from the vertices are exact.
  const Polygon tilted({{0, 0, 1}, {0, 1, 2}, {1, 0, 1}}, KernelSpec::inverse(4));
  for (const Vec3& p : {Vec3(0.25, 0.25, 1.25), Vec3(0, 0.5, 1.5), Vec3(1, 0, 1)}) {
    EXPECT_EQ(tilted.value_and_gradient(p).value, infinity) << p.transpose();
  }
}

TEST(PolygonInverseSingularity, NonFiniteQueryPointIsAnInputError) {
  const Polygon polygon(unit_square, inverse3);
  EXPECT_THROW(polygon.value(Vec3(std::nan(""), 0, 0)), InputError);
  EXPECT_THROW(polygon.value_and_gradient(Vec3(0, infinity, 0)), InputError);
}

TEST(PolygonCompactSupport, BallMissingThePolygonGivesExactlyZero) {
  // R = 0.5 around points at distance ≥ 0.5 from the closed unit square:
  // above it, beside an edge in its plane, beyond a corner, far away.
  for (int degree : Polygon::supported_degrees(KernelFamily::compact)) {
    const Polygon polygon(unit_square, KernelSpec::compact(degree, 0.5));
    for (const Vec3& p : {Vec3(0.5, 0.5, 0.6), Vec3(0.5, 0.5, -0.5), Vec3(1.5, 0.5, 0), Vec3(1.4, 1.4, 0.1),
                          Vec3(3, 3, 0), Vec3(-1e10, 0, 0)}) {
      SCOPED_TRACE(testing::Message() << "degree " << degree << ", P = " << p.transpose());
      EXPECT_EQ(polygon.value(p), 0.0);
      EXPECT_EQ(polygon.gradient(p), Vec3::Zero());
      const FieldSample both = polygon.value_and_gradient(p);
      EXPECT_EQ(both.value, 0.0);
      EXPECT_EQ(both.gradient, Vec3::Zero());
    }
  }
}

// --- PolygonValues: AWAIT THE CLOSED FORMS ----------------------------------------

/// Solid angle of the convex polygon `vertices` seen from p: the sum over
/// the fan triangles (Q_0, Q_k, Q_{k+1}) of the Van Oosterom–Strackee
/// formula tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a).
long double solid_angle(const std::vector<Vec3>& vertices, const Vec3& p) {
  using V = Eigen::Matrix<long double, 3, 1>;
  const auto from_p = [&](const Vec3& q) -> V { return (q - p).cast<long double>(); };
  long double total = 0;
  for (std::size_t k = 1; k + 1 < vertices.size(); ++k) {
    const V a = from_p(vertices[0]), b = from_p(vertices[k]), c = from_p(vertices[k + 1]);
    const long double la = a.norm(), lb = b.norm(), lc = c.norm();
    const long double numerator = std::fabs(a.dot(b.cross(c)));
    const long double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total;
}

/// Distance of p from the plane of the (coplanar) polygon.
long double height_above(const std::vector<Vec3>& vertices, const Vec3& p) {
  const Vec3 normal = (vertices[1] - vertices[0]).cross(vertices[2] - vertices[0]).normalized();
  return std::fabs(normal.dot(p - vertices[0]));
}

/// f for inverse p^3 from the solid angle: f = Ω / z.
long double inverse3_reference(const std::vector<Vec3>& vertices, const Vec3& p) {
  return solid_angle(vertices, p) / height_above(vertices, p);
}

/// K(q) and dK/dq for q = r², in long double.
struct KernelValue {
  long double k = 0, dk_dq = 0;
};
KernelValue kernel_at(const KernelSpec& kernel, long double q) {
  const long double half_i = kernel.degree / 2.0L;
  switch (kernel.family) {
    case KernelFamily::inverse: {
      const long double k = std::pow(q, -half_i);
      return {k, -half_i * k / q};
    }
    case KernelFamily::cauchy: {
      const long double base = 1 + kernel.s * q;
      const long double k = std::pow(base, -half_i);
      return {k, -half_i * kernel.s * k / base};
    }
    case KernelFamily::compact: {
      const long double R2 = (long double)kernel.R * kernel.R;
      const long double base = 1 - q / R2;
      if (base <= 0) return {};
      return {std::pow(base, half_i), -half_i / R2 * std::pow(base, half_i - 1)};
    }
    default: throw std::logic_error("the generated families only (the others: kernel_families_test.cpp)");
  }
  return {};
}

struct ReferenceSample {
  long double value = 0;
  Eigen::Matrix<long double, 3, 1> gradient = Eigen::Matrix<long double, 3, 1>::Zero();
};

/// ∬ K(|P − Q|) dQ and its gradient over the convex polygon `vertices`, by a
/// composite 16-point Gauss–Legendre product rule on each fan triangle
/// (A, B, C) mapped from the unit square: Q = A + u (B − A) + u v (C − B),
/// dQ = u |(B − A) × (C − B)| du dv.
ReferenceSample integrate_polygon(const std::vector<Vec3>& vertices, const KernelSpec& kernel, const Vec3& p,
                                  int panels) {
  using V = Eigen::Matrix<long double, 3, 1>;
  static const test::GaussLegendreRule rule(16);
  ReferenceSample sum;
  const V pl = p.cast<long double>();
  for (std::size_t k = 1; k + 1 < vertices.size(); ++k) {
    const V a = vertices[0].cast<long double>(), b = vertices[k].cast<long double>(),
            c = vertices[k + 1].cast<long double>();
    const long double jacobian = (b - a).cross(c - b).norm();
    for (int pu = 0; pu < panels; ++pu) {
      for (int pv = 0; pv < panels; ++pv) {
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
          for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
            const long double u = (pu + (1 + rule.nodes[i]) / 2) / panels;
            const long double v = (pv + (1 + rule.nodes[j]) / 2) / panels;
            const long double weight = rule.weights[i] * rule.weights[j] / (4.0L * panels * panels) * u * jacobian;
            const V d = pl - (a + u * (b - a) + u * v * (c - b));  // P − Q
            const KernelValue kv = kernel_at(kernel, d.squaredNorm());
            sum.value += weight * kv.k;
            sum.gradient += weight * kv.dk_dq * 2 * d;
          }
        }
      }
    }
  }
  return sum;
}

/// Compares value, gradient and value_and_gradient with the reference.
void expect_matches(const Polygon& polygon, const Vec3& p, double expected_value, const Vec3& expected_gradient,
                    double tolerance) {
  SCOPED_TRACE(testing::Message() << family_name(polygon.kernel().family) << " degree " << polygon.kernel().degree
                                  << " at P = (" << p.transpose() << ")");
  // Gradient scale: |∇f|, or f / diameter where it nearly cancels.
  const double gradient_scale = std::max(expected_gradient.norm(), std::abs(expected_value));
  try {
    EXPECT_NEAR(polygon.value(p), expected_value, tolerance * std::abs(expected_value));
    EXPECT_LE((polygon.gradient(p) - expected_gradient).norm(), tolerance * gradient_scale);
    const FieldSample both = polygon.value_and_gradient(p);
    EXPECT_NEAR(both.value, expected_value, tolerance * std::abs(expected_value));
    EXPECT_LE((both.gradient - expected_gradient).norm(), tolerance * gradient_scale);
  } catch (const std::exception& error) {  // the stub's std::logic_error, or EvaluationError
    ADD_FAILURE() << error.what();
  }
}

/// Convex test polygons: a triangle, the unit square, the tilted pentagon.
std::vector<std::vector<Vec3>> convex_polygons() {
  return {
      {{0, 0, 0}, {1, 0, 0}, {0.25, 0.75, 0}},
      unit_square,
      tilted_pentagon,
  };
}

/// Points off each polygon's plane, by at least 0.3 of its size, where
/// every kernel is smooth over the polygon.
std::vector<Vec3> points_around(const std::vector<Vec3>& vertices) {
  const Vec3 normal = (vertices[1] - vertices[0]).cross(vertices[2] - vertices[0]).normalized();
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& v : vertices) centroid += v;
  centroid /= double(vertices.size());
  const double size = (vertices[1] - vertices[0]).norm();
  return {
      centroid + 0.5 * size * normal,                                   // above the middle
      centroid - 0.3 * size * normal,                                   // below, the other side
      vertices[0] + 0.4 * size * normal,                                // above a vertex
      vertices[0] + 1.5 * (vertices[0] - centroid) + 0.3 * size * normal,  // beyond a vertex, outside
      centroid + Vec3(7, -4, 5) * size,                                 // far away
  };
}

TEST(PolygonValues, Inverse3IsTheSolidAngleOverTheHeight) {
  for (const auto& vertices : convex_polygons()) {
    const Polygon polygon(vertices, inverse3);
    for (const Vec3& p : points_around(vertices)) {
      const double h = 1e-5;  // central differences of the analytic reference
      Vec3 gradient;
      for (int c = 0; c < 3; ++c) {
        const Vec3 step = h * Vec3::Unit(c);
        gradient[c] = double((inverse3_reference(vertices, p + step) - inverse3_reference(vertices, p - step)) / (2 * h));
      }
      expect_matches(polygon, p, double(inverse3_reference(vertices, p)), gradient, 1e-8);
    }
  }
}

TEST(PolygonValues, EveryFamilyAndDegreeMatchesQuadrature) {
  for (const auto& vertices : convex_polygons()) {
    for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
      for (int degree : Polygon::supported_degrees(family)) {
        // R large enough that the support ball holds the whole polygon at
        // the near points (a polynomial integrand); the far point gets 0.
        const KernelSpec kernel{family, degree, 1.7, 6.0};
        const Polygon polygon(vertices, kernel);
        for (const Vec3& p : points_around(vertices)) {
          const ReferenceSample expected = integrate_polygon(vertices, kernel, p, 4);
          expect_matches(polygon, p, double(expected.value), expected.gradient.cast<double>(), 1e-9);
        }
      }
    }
  }
}

TEST(PolygonValues, CompactSupportCuttingThePolygon) {
  // The sphere of radius R around P crosses the square: the integrand is
  // only C^(i/2 - 1) there, hence many panels and a looser tolerance (24
  // panels agree with 48 to 5e-10 in f and 4e-7 in ∇f for degree 4).
  for (int degree : Polygon::supported_degrees(KernelFamily::compact)) {
    const KernelSpec kernel = KernelSpec::compact(degree, 0.8);
    const Polygon polygon(unit_square, kernel);
    for (const Vec3& p : {Vec3(0.2, 0.3, 0.3), Vec3(1.2, 0.5, 0.1), Vec3(0.5, 0.5, 0.0)}) {
      const ReferenceSample expected = integrate_polygon(unit_square, kernel, p, 24);
      expect_matches(polygon, p, double(expected.value), expected.gradient.cast<double>(), 1e-5);
    }
  }
}

TEST(PolygonValues, CompactSupportHoldingOneCornerNearItsRim) {
  // P's foot (−0.35, −0.35) beyond the corner (0, 0) of the unit square,
  // support disc radius √(R² − z²) ≈ 0.59: the disc holds that corner, 0.49
  // from the foot, and clips both edges that meet there, whose lines pass
  // 0.35 from the foot, beyond half the disc radius. Each of the two edges
  // is then summed by the chord form near the rim, which reads the exact
  // support gap at the corner: at the start of the edge (0, 0) → (1, 0)
  // and at the end of the edge (0, 1) → (0, 0). The support meets only
  // [0, 0.3]², so the reference integrates that square, finely.
  const std::vector<Vec3> corner{{0, 0, 0}, {0.3, 0, 0}, {0.3, 0.3, 0}, {0, 0.3, 0}};
  for (int degree : Polygon::supported_degrees(KernelFamily::compact)) {
    const KernelSpec kernel = KernelSpec::compact(degree, 0.6);
    const Polygon polygon(unit_square, kernel);
    for (const Vec3& p : {Vec3(-0.35, -0.35, 0.1), Vec3(-0.35, -0.35, -0.05)}) {
      const ReferenceSample expected = integrate_polygon(corner, kernel, p, 48);
      expect_matches(polygon, p, double(expected.value), expected.gradient.cast<double>(), 1e-6);
    }
  }
}

TEST(PolygonValues, NonConvexPolygonIsTheSumOfItsParts) {
  // An L shape = two rectangles sharing the edge x = 1, 0 ≤ y ≤ 1: the field
  // is additive over the region (no reference closed form involved).
  const std::vector<Vec3> l_shape{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const std::vector<Vec3> bottom_right{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  const std::vector<Vec3> left{{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}};
  for (const KernelSpec& kernel : {KernelSpec::inverse(3), KernelSpec::cauchy(5, 2.0), KernelSpec::compact(6, 1.2)}) {
    const Polygon whole(l_shape, kernel), part1(bottom_right, kernel), part2(left, kernel);
    for (const Vec3& p : {Vec3(1.5, 1.5, 0.3), Vec3(0.5, 0.5, -0.4), Vec3(1.5, 1.5, 0.0), Vec3(3, -1, 0.5)}) {
      SCOPED_TRACE(testing::Message() << family_name(kernel.family) << " at P = (" << p.transpose() << ")");
      try {
        const FieldSample sum_of_parts{part1.value(p) + part2.value(p), part1.gradient(p) + part2.gradient(p)};
        const FieldSample both = whole.value_and_gradient(p);
        EXPECT_NEAR(both.value, sum_of_parts.value, 1e-12 * std::abs(sum_of_parts.value));
        EXPECT_LE((both.gradient - sum_of_parts.gradient).norm(),
                  1e-12 * std::max(sum_of_parts.gradient.norm(), std::abs(sum_of_parts.value)));
      } catch (const std::exception& error) {
        ADD_FAILURE() << error.what();
      }
    }
  }
}

TEST(PolygonValues, BothOrientationsGiveTheSameField) {
  const std::vector<Vec3>& forward = tilted_pentagon;
  const std::vector<Vec3> backward(forward.rbegin(), forward.rend());
  for (const KernelSpec& kernel : {KernelSpec::inverse(4), KernelSpec::cauchy(3, 1.0), KernelSpec::compact(8, 3.0)}) {
    const Polygon a(forward, kernel), b(backward, kernel);
    for (const Vec3& p : points_around(forward)) {
      try {
        const FieldSample fa = a.value_and_gradient(p), fb = b.value_and_gradient(p);
        EXPECT_EQ(fa.value, fb.value);
        EXPECT_EQ(fa.gradient, fb.gradient);
      } catch (const std::exception& error) {
        ADD_FAILURE() << error.what();
      }
    }
  }
}

}  // namespace
}  // namespace skelconv
