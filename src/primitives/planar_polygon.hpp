// src/primitives/planar_polygon.hpp — exact 2D predicates on a polygon, for the
// Polygon primitive (internal to skelconv_runtime).
//
// Implemented with CGAL (exact predicates on the given doubles: no rounding
// decides a "touches or not"); locate_point first tries a floating-point
// filter with a proven error bound, which answers exactly for every point
// not within a few units in the last place of an edge's line, and calls
// CGAL for the rest. Kept behind this small interface, in its own
// translation unit, because CGAL needs -frounding-math, which must not reach
// the generated kernels compiled into segment.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>

namespace skelconv::detail {

using Point2 = std::array<double, 2>;

/// Edge k runs from vertices[k] to vertices[(k + 1) % n]. For a polygon
/// that is not simple, two edges (i < j) that meet other than consecutive
/// edges at their common vertex (crossing, touching, or a consecutive pair
/// folding back along each other); std::nullopt for a simple polygon.
/// Needs n ≥ 3 and no two consecutive vertices equal.
std::optional<std::pair<std::size_t, std::size_t>> find_crossing_edges(std::span<const Point2> vertices);

enum class PointLocation { inside, on_boundary, outside };

/// Where `point` lies relative to the simple polygon `vertices`.
PointLocation locate_point(std::span<const Point2> vertices, const Point2& point);

}  // namespace skelconv::detail
