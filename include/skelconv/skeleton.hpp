// skelconv/skeleton.hpp — a skeleton: a list of primitives whose fields add.
//
// Convolution is linear in the skeleton (Hubert 2012 §2: the field of a union
// of skeleton pieces is the sum of their fields), so
//     f(P) = Σ_k f_k(P),   ∇f(P) = Σ_k ∇f_k(P).
// Primitives are a std::variant: segments (SPEC §2), polygons (SPEC §3),
// SCALIS segments and triangles (SPEC §4); every alternative provides
// value(), gradient() and value_and_gradient().
#pragma once

#include <cstddef>
#include <variant>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/polygon.hpp"
#include "skelconv/scalis_segment.hpp"
#include "skelconv/scalis_triangle.hpp"
#include "skelconv/segment.hpp"

namespace skelconv {

/// One skeleton element.
using Primitive = std::variant<Segment, Polygon, ScalisSegment, ScalisTriangle>;

class Skeleton {
 public:
  Skeleton() = default;
  explicit Skeleton(std::vector<Primitive> primitives) : primitives_(std::move(primitives)) {}

  void add(Primitive primitive) { primitives_.push_back(std::move(primitive)); }
  const std::vector<Primitive>& primitives() const { return primitives_; }
  std::size_t size() const { return primitives_.size(); }
  bool empty() const { return primitives_.empty(); }

  /// Sum of the primitives' fields (0 for an empty skeleton). An inverse
  /// primitive evaluated on its own segment or polygon contributes +inf
  /// (segment.hpp, polygon.hpp), so the sum is +inf there. Errors of primitive k are rethrown located
  /// at "primitives[k]".
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  FieldSample value_and_gradient(const Vec3& p) const;

  /// Points on the skeleton itself: for every primitive its defining points
  /// (ends, vertices) and `per_element` − 1 evenly spaced points between
  /// them (along each segment and polygon edge, and a fan of points inside
  /// each polygon and triangle towards its centroid), so that every
  /// connected piece of the skeleton holds some of them. The mesher
  /// (skelconv mesh) shoots rays from them to find every component of the
  /// surface. `per_element` ≥ 1.
  std::vector<Vec3> skeleton_points(int per_element = 4) const;

 private:
  std::vector<Primitive> primitives_;
};

}  // namespace skelconv
