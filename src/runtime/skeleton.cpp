// Implementation of skelconv/skeleton.hpp.
#include "skelconv/skeleton.hpp"

#include <span>
#include <type_traits>

#include <fmt/format.h>

#include "input_checks.hpp"

namespace skelconv {
namespace {

// FieldSample has no operator+=; sum its parts.
FieldSample& operator+=(FieldSample& total, const FieldSample& term) {
  total.value += term.value;
  total.gradient += term.gradient;
  return total;
}

/// Calls `evaluate(primitive)` for every primitive, adding up the results;
/// a primitive's error is rethrown with its index as location, so a message
/// reads like the skeleton file: "primitives[2]: ...".
template <class Result, class Evaluate>
Result sum_over(const std::vector<Primitive>& primitives, const Vec3& p, Result total, Evaluate evaluate) {
  // Checked once here, so that a bad point is not blamed on primitives[0].
  detail::require_finite_query_point(p);
  for (std::size_t k = 0; k < primitives.size(); ++k) {
    try {
      total += std::visit(evaluate, primitives[k]);
    } catch (const InputError& error) {
      throw error.inside(fmt::format("primitives[{}]", k));
    } catch (const EvaluationError& error) {
      throw error.inside(fmt::format("primitives[{}]", k));
    }
  }
  return total;
}

}  // namespace

double Skeleton::value(const Vec3& p) const {
  return sum_over(primitives_, p, 0.0, [&](const auto& primitive) { return primitive.value(p); });
}

Vec3 Skeleton::gradient(const Vec3& p) const {
  return sum_over(primitives_, p, Vec3(Vec3::Zero()), [&](const auto& primitive) { return primitive.gradient(p); });
}

FieldSample Skeleton::value_and_gradient(const Vec3& p) const {
  return sum_over(primitives_, p, FieldSample{},
                  [&](const auto& primitive) { return primitive.value_and_gradient(p); });
}

namespace {

/// a, the points a + (b − a) k / n for k = 1 … n − 1 (not b).
void add_points_along(const Vec3& a, const Vec3& b, int n, std::vector<Vec3>& points) {
  for (int k = 0; k < n; ++k) points.push_back(a + (b - a) * (double(k) / n));
}

/// Every vertex, the points along every edge of the closed polygon, and the
/// points from each vertex towards the centroid.
void add_polygon_points(std::span<const Vec3> vertices, int n, std::vector<Vec3>& points) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& v : vertices) centroid += v;
  centroid /= double(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    add_points_along(vertices[k], vertices[(k + 1) % vertices.size()], n, points);
    // Towards the centroid, without the vertex itself (already added); for a
    // non-convex polygon these may leave it, which only adds seeds.
    for (int j = 1; j < n; ++j) points.push_back(vertices[k] + (centroid - vertices[k]) * (double(j) / n));
  }
  points.push_back(centroid);
}

}  // namespace

std::vector<Vec3> Skeleton::skeleton_points(int per_element) const {
  if (per_element < 1) throw InputError(fmt::format("per_element must be >= 1, got {}", per_element));
  std::vector<Vec3> points;
  for (const Primitive& primitive : primitives_) {
    std::visit(
        [&](const auto& p) {
          using P = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<P, Segment> || std::is_same_v<P, ScalisSegment>) {
            add_points_along(p.a(), p.b(), per_element, points);
            points.push_back(p.b());
          } else if constexpr (std::is_same_v<P, Polygon>) {
            add_polygon_points(p.vertices(), per_element, points);
          } else {
            static_assert(std::is_same_v<P, ScalisTriangle>, "a new primitive type needs its skeleton points");
            add_polygon_points(p.vertices(), per_element, points);
          }
        },
        primitive);
  }
  return points;
}

}  // namespace skelconv
