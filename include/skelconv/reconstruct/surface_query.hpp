// skelconv/reconstruct/surface_query.hpp — the two questions the fitting
// step (surface_fit.hpp) asks of the input surface: where a ray from an
// inside point leaves it, and how far a point is from it. An AABB tree over
// the input triangles (CGAL, in its own translation unit so that
// -frounding-math stays out of the callers).
#pragma once

#include <memory>
#include <optional>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

class SurfaceQuery {
 public:
  /// Builds the tree over `surface` (kept by copy). Throws InputError if it
  /// has no triangle.
  explicit SurfaceQuery(const TriangleMesh& surface);
  ~SurfaceQuery();
  SurfaceQuery(SurfaceQuery&&) noexcept;
  SurfaceQuery& operator=(SurfaceQuery&&) noexcept;

  /// Distance from `origin` along the unit vector `direction` to the first
  /// triangle the ray meets; nothing if it meets none.
  std::optional<double> ray_distance(const Vec3& origin, const Vec3& direction) const;
  /// Distance from `point` to the nearest point of the surface.
  double distance(const Vec3& point) const;
  /// The same distance, negative where `point` is outside the surface
  /// (which must be closed: CGAL's side-of-triangle-mesh test, built on the
  /// first call) and positive inside or on it.
  double signed_distance(const Vec3& point) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace skelconv::reconstruct
