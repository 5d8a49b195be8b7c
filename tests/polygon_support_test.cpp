// The polygon's cheap support and location tests against exact references:
//
//   - PolygonPointLocation: detail::locate_point (a floating-point filter in
//     front of CGAL's exact predicates) against the same question answered
//     in exact rational arithmetic, on points on, at and a few units in the
//     last place beside edges and their lines, where a filter with too small
//     an error bound decides wrongly;
//   - PolygonCompactSupport: the field of a compact kernel is exactly 0 at
//     points 1e-12 · R (relative) outside the support of random tilted
//     triangles, and positive at points as far inside it, beside the face,
//     an edge and a vertex: a support test that rejects a point of the
//     support fails the second half.
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

#include "skelconv/primitives/polygon.hpp"
#include "src/primitives/planar_polygon.hpp"

namespace skelconv {
namespace {

using detail::Point2;
using detail::PointLocation;
using Rational = boost::multiprecision::cpp_rational;

/// The sign of (a − q) × (b − q), exactly (doubles are rationals).
int exact_orientation(const Point2& a, const Point2& b, const Point2& q) {
  const Rational ax(a[0]), ay(a[1]), bx(b[0]), by(b[1]), qx(q[0]), qy(q[1]);
  const Rational determinant = (ax - qx) * (by - qy) - (ay - qy) * (bx - qx);
  return determinant > 0 ? 1 : determinant < 0 ? -1 : 0;
}

/// Where q lies, exactly: on the boundary when on a closed edge, else by
/// the winding number (crossings of the horizontal ray from q).
PointLocation exact_location(std::span<const Point2> polygon, const Point2& q) {
  const std::size_t n = polygon.size();
  int winding = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = polygon[k];
    const Point2& b = polygon[(k + 1) % n];
    const int side = exact_orientation(a, b, q);
    const bool between = std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) &&
                         std::min(a[1], b[1]) <= q[1] && q[1] <= std::max(a[1], b[1]);
    if (side == 0 && between) return PointLocation::on_boundary;
    if (a[1] <= q[1] && b[1] > q[1] && side > 0) ++winding;
    if (a[1] > q[1] && b[1] <= q[1] && side < 0) --winding;
  }
  return winding != 0 ? PointLocation::inside : PointLocation::outside;
}

/// q moved by `steps` units in the last place along x and y.
Point2 nudged(const Point2& q, int x_steps, int y_steps) {
  Point2 r = q;
  for (int i = 0; i < std::abs(x_steps); ++i) r[0] = std::nextafter(r[0], x_steps > 0 ? INFINITY : -INFINITY);
  for (int i = 0; i < std::abs(y_steps); ++i) r[1] = std::nextafter(r[1], y_steps > 0 ? INFINITY : -INFINITY);
  return r;
}

TEST(PolygonPointLocation, AgreesWithExactArithmeticOnAndBesideTheBoundary) {
  std::mt19937_64 random(53);
  std::uniform_real_distribution<double> coordinate(-1.0, 2.0), unit(0.0, 1.0);
  std::vector<std::vector<Point2>> polygons{
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                  // dyadic: exact points on its edges
      {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},  // non-convex L
      {{0.1, 0.2}, {1.3, 0.1}, {0.7, 0.4}, {1.1, 1.3}, {0.2, 0.9}},  // non-convex, no dyadic edges
  };
  for (int k = 0; k < 40; ++k) {  // random triangles, counter-clockwise
    Point2 a{coordinate(random), coordinate(random)}, b{coordinate(random), coordinate(random)},
        c{coordinate(random), coordinate(random)};
    const int turn = exact_orientation(a, b, c);
    if (turn == 0) continue;
    if (turn < 0) std::swap(b, c);
    polygons.push_back({a, b, c});
  }
  int on_boundary = 0, inside = 0, outside = 0;
  for (const std::vector<Point2>& polygon : polygons) {
    std::vector<Point2> points;
    const std::size_t n = polygon.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Point2& a = polygon[k];
      const Point2& b = polygon[(k + 1) % n];
      // On the edge and its line's extensions (rounded: on it or an ulp
      // or so beside it), at the vertex, then a few units in the last place
      // around each.
      for (double t : {0.0, 0.25, 0.5, unit(random), unit(random), -0.5, 1.5}) {
        const Point2 q{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
        for (int dx = -3; dx <= 3; ++dx)
          for (int dy = -3; dy <= 3; ++dy) points.push_back(nudged(q, dx, dy));
      }
    }
    for (int k = 0; k < 200; ++k) points.push_back({coordinate(random), coordinate(random)});
    for (const Point2& q : points) {
      const PointLocation expected = exact_location(polygon, q);
      on_boundary += expected == PointLocation::on_boundary;
      inside += expected == PointLocation::inside;
      outside += expected == PointLocation::outside;
      ASSERT_EQ(detail::locate_point(polygon, q), expected)
          << "q = (" << q[0] << ", " << q[1] << ") (%a: " << std::hexfloat << q[0] << ", " << q[1] << ")";
    }
  }
  // The sample holds every answer, many of each.
  EXPECT_GT(on_boundary, 100);
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

/// Unit vectors uniformly on the sphere.
Vec3 random_direction(std::mt19937_64& random) {
  std::normal_distribution<double> normal;
  Vec3 d;
  do d = Vec3(normal(random), normal(random), normal(random));
  while (d.norm() < 1e-3);
  return d.normalized();
}

TEST(PolygonCompactSupport, ZeroJustOutsideTheSupportPositiveJustInside) {
  // Points at distance R (1 ± 1e-12) from a random tilted triangle, the
  // nearest point of the triangle in its face, on an edge or at a vertex:
  // P = Q + r d with d in the triangle's normal cone at Q. Q and P rounded
  // to double move r by ~1e-16 of the coordinates, far below the 1e-12 R.
  constexpr double relative_gap = 1e-12;
  std::mt19937_64 random(1253);
  std::uniform_real_distribution<double> coordinate(-2.0, 3.0), unit(0.0, 1.0), radius(0.05, 0.8);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::array<Vec3, 3> v{Vec3(coordinate(random), coordinate(random), coordinate(random)),
                                Vec3(coordinate(random), coordinate(random), coordinate(random)),
                                Vec3(coordinate(random), coordinate(random), coordinate(random))};
    const Vec3 normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const double diameter = std::max({(v[1] - v[0]).norm(), (v[2] - v[1]).norm(), (v[0] - v[2]).norm()});
    if (normal.norm() < 0.05 * diameter * diameter) continue;  // keep the triangles fat enough to sample
    const Vec3 n = normal.normalized();
    const double R = radius(random) * diameter;
    for (int degree : {4, 6}) {
      const Polygon triangle(std::span<const Vec3>(v.data(), 3), KernelSpec::compact(degree, R));
      // Each sample: a point Q of the triangle and a direction d of its normal cone there.
      std::vector<std::pair<Vec3, Vec3>> samples;
      for (int k = 0; k < 4; ++k) {  // face
        double a = unit(random), b = unit(random);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Vec3 q = v[0] + a * (v[1] - v[0]) + b * (v[2] - v[0]);
        samples.push_back({q, k % 2 == 0 ? n : Vec3(-n)});
      }
      for (int e = 0; e < 3; ++e) {  // edges: d between ±n and the outward in-plane normal
        const Vec3 edge = v[(e + 1) % 3] - v[e];
        Vec3 outward = edge.cross(n).normalized();
        if (outward.dot(v[(e + 2) % 3] - v[e]) > 0) outward = -outward;
        for (int k = 0; k < 3; ++k) {
          const double angle = (unit(random) - 0.5) * M_PI;
          samples.push_back({v[e] + unit(random) * edge, std::cos(angle) * outward + std::sin(angle) * n});
        }
      }
      for (int corner = 0; corner < 3; ++corner) {  // vertices: d·(edge away from the vertex) ≤ 0 for both edges
        const Vec3 to_next = v[(corner + 1) % 3] - v[corner], to_previous = v[(corner + 2) % 3] - v[corner];
        for (int found = 0, tries = 0; found < 3 && tries < 1000; ++tries) {
          const Vec3 d = random_direction(random);
          if (d.dot(to_next) >= 0 || d.dot(to_previous) >= 0) continue;
          samples.push_back({v[corner], d});
          ++found;
        }
      }
      for (const auto& [q, d] : samples) {
        const Vec3 outside = q + R * (1 + relative_gap) * d;
        const Vec3 inside = q + R * (1 - relative_gap) * d;
        SCOPED_TRACE(testing::Message() << "trial " << trial << ", degree " << degree << ", R = " << R << ", Q = ("
                                        << q.transpose() << "), d = (" << d.transpose() << ")");
        const FieldSample beyond = triangle.value_and_gradient(outside);
        EXPECT_EQ(beyond.value, 0.0);
        EXPECT_EQ(beyond.gradient, Vec3::Zero());
        EXPECT_EQ(triangle.value(outside), 0.0);
        EXPECT_GT(triangle.value(inside), 0.0);
        EXPECT_GT(triangle.value_and_gradient(inside).value, 0.0);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace skelconv
