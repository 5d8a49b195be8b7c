// Implementation of planar_polygon.hpp with CGAL's exact-predicates kernel.
#include "planar_polygon.hpp"

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
  const std::vector<CgalPoint> points = to_cgal(vertices);
  switch (CGAL::bounded_side_2(points.begin(), points.end(), CgalPoint(point[0], point[1]), Kernel())) {
    case CGAL::ON_BOUNDED_SIDE: return PointLocation::inside;
    case CGAL::ON_BOUNDARY: return PointLocation::on_boundary;
    case CGAL::ON_UNBOUNDED_SIDE: return PointLocation::outside;
  }
  return PointLocation::outside;  // unreachable
}

}  // namespace skelconv::detail
