// Implementation of planar_polygon.hpp with CGAL's exact-predicates kernel.
#include "planar_polygon.hpp"

#include <cmath>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

namespace skelconv::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_2;
using CgalSegment = Kernel::Segment_2;

std::vector<CgalPoint> to_cgal(std::span<const Point2> vertices) {
  std::vector<CgalPoint> points;
  points.reserve(vertices.size());
  for (const Point2& v : vertices) points.emplace_back(v[0], v[1]);
  return points;
}

/// Consecutive edges before → at → after overlap beyond their common vertex
/// `at` when the three points are collinear and `at` is not strictly
/// between the others (the boundary folds back on itself).
bool folds_back(const CgalPoint& before, const CgalPoint& at, const CgalPoint& after) {
  return CGAL::collinear(before, at, after) && !CGAL::collinear_are_strictly_ordered_along_line(before, at, after);
}

/// The sign of the orientation of (a, b, q) — +1 when q lies left of the
/// line a→b, −1 right of it — when the floating-point determinant decides
/// it, else 0 (q on the line, or too near it for the filter). This is the
/// first stage of Shewchuk's orient2d (Adaptive precision floating-point
/// arithmetic and fast robust geometric predicates, 1997, §4.3): the
/// determinant (a − q) × (b − q) from the four rounded differences and two
/// rounded products errs by at most ccwerrboundA · (|left| + |right|),
/// ccwerrboundA = (3 + 16ε)ε with ε = 2^−53, so a computed value beyond
/// that bound has the exact sign. The bound assumes no underflow: below
/// 2^−900 (products of differences under ~2^−450, far below any
/// coordinate difference of a polygon scaled to its frame) the filter
/// declines rather than reason about subnormal products; NaN or an
/// overflow (a point ~2^500 away) fails the comparison and declines too.
int filtered_orientation(const Point2& a, const Point2& b, const Point2& q) {
  constexpr double epsilon = 0x1.0p-53;
  constexpr double error_bound = (3.0 + 16.0 * epsilon) * epsilon;
  constexpr double smallest_trusted_sum = 0x1.0p-900;
  const double left = (a[0] - q[0]) * (b[1] - q[1]);
  const double right = (a[1] - q[1]) * (b[0] - q[0]);
  const double determinant = left - right;
  const double sum = std::abs(left) + std::abs(right);
  if (!(sum >= smallest_trusted_sum) || !(std::abs(determinant) > error_bound * sum)) return 0;
  return determinant > 0.0 ? 1 : -1;
}

/// The winding number of the boundary about `point` (±1 inside a simple
/// polygon, 0 outside) by Sunday's crossing rule on the horizontal ray
/// from it, when the filter decides the orientation of `point` against
/// every edge's line; std::nullopt otherwise. Every edge decided means
/// `point` lies on no edge's line, so not on the boundary, and the
/// half-open crossing rule (an edge crosses the ray when exactly one end
/// is strictly above `point`; the comparisons of coordinates are exact)
/// counts each crossing once: the winding number is exact. Only the
/// points nearer an edge's line than a few units in the last place of
/// their differences go on to CGAL.
std::optional<int> filtered_winding_number(std::span<const Point2> vertices, const Point2& point) {
  const std::size_t n = vertices.size();
  int winding = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = vertices[k];
    const Point2& b = vertices[(k + 1) % n];
    const int side = filtered_orientation(a, b, point);
    if (side == 0) return std::nullopt;
    const bool a_above = a[1] > point[1], b_above = b[1] > point[1];
    if (!a_above && b_above && side > 0) ++winding;  // upward, point on its left
    if (a_above && !b_above && side < 0) --winding;  // downward, point on its right
  }
  return winding;
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> find_crossing_edges(std::span<const Point2> vertices) {
  const std::vector<CgalPoint> points = to_cgal(vertices);
  // O(n log n) sweep first; the O(n²) search below only names the culprits.
  if (CGAL::is_simple_2(points.begin(), points.end(), Kernel())) return std::nullopt;

  const std::size_t n = points.size();
  const auto edge = [&](std::size_t k) { return CgalSegment(points[k], points[(k + 1) % n]); };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1) {  // share vertex j
        if (folds_back(points[i], points[j], points[(j + 1) % n])) return std::pair{i, j};
      } else if (i == 0 && j == n - 1) {  // share vertex 0
        if (folds_back(points[n - 1], points[0], points[1])) return std::pair{i, j};
      } else if (CGAL::do_intersect(edge(i), edge(j))) {
        return std::pair{i, j};
      }
    }
  }
  // is_simple_2 said no, but no pair was found: report the first pair rather
  // than accept a polygon CGAL calls not simple.
  return std::pair<std::size_t, std::size_t>{0, 1};
}

PointLocation locate_point(std::span<const Point2> vertices, const Point2& point) {
  if (const std::optional<int> winding = filtered_winding_number(vertices, point)) {
    return *winding != 0 ? PointLocation::inside : PointLocation::outside;
  }
  const std::vector<CgalPoint> points = to_cgal(vertices);
  switch (CGAL::bounded_side_2(points.begin(), points.end(), CgalPoint(point[0], point[1]), Kernel())) {
    case CGAL::ON_BOUNDED_SIDE: return PointLocation::inside;
    case CGAL::ON_BOUNDARY: return PointLocation::on_boundary;
    case CGAL::ON_UNBOUNDED_SIDE: return PointLocation::outside;
  }
  return PointLocation::outside;  // unreachable
}

}  // namespace skelconv::detail
