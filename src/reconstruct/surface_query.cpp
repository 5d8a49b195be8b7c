// Implementation of skelconv/reconstruct/surface_query.hpp (CGAL TU).
#include "skelconv/reconstruct/surface_query.hpp"

#include <cmath>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <boost/variant/get.hpp>  // CGAL 5's intersection results are boost::variant

#include "skelconv/errors.hpp"
#include "cgal_surface.hpp"

namespace skelconv::reconstruct {

using cgal::Kernel;
using cgal::Point;
using cgal::to_point;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct SurfaceQuery::Tree {
  std::vector<Triangle> triangles;  // the tree points into this vector
  AabbTree tree;
  TriangleMesh surface;  // for the side test, built when first asked
  std::optional<cgal::SurfaceMesh> mesh;
  std::optional<CGAL::Side_of_triangle_mesh<cgal::SurfaceMesh, Kernel>> side;
};

SurfaceQuery::SurfaceQuery(const TriangleMesh& surface) : tree_(std::make_unique<Tree>()) {
  if (surface.triangles.empty()) throw InputError("the input surface has no triangles");
  for (const auto& t : surface.triangles) {
    const Triangle triangle(to_point(surface.vertices[t[0]]), to_point(surface.vertices[t[1]]),
                            to_point(surface.vertices[t[2]]));
    if (!triangle.is_degenerate()) tree_->triangles.push_back(triangle);
  }
  if (tree_->triangles.empty()) throw InputError("the input surface has only degenerate triangles");
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
  tree_->surface = surface;
}

SurfaceQuery::~SurfaceQuery() = default;
SurfaceQuery::SurfaceQuery(SurfaceQuery&&) noexcept = default;
SurfaceQuery& SurfaceQuery::operator=(SurfaceQuery&&) noexcept = default;

std::optional<double> SurfaceQuery::ray_distance(const Vec3& origin, const Vec3& direction) const {
  const Kernel::Ray_3 ray(to_point(origin), Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
  const auto hit = tree_->tree.first_intersection(ray);
  if (!hit) return std::nullopt;
  if (const Point* p = boost::get<Point>(&hit->first)) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(*p, ray.source())));
  }
  // The ray runs inside a triangle's plane: the nearer end of the segment.
  const auto& s = boost::get<Kernel::Segment_3>(hit->first);
  return std::sqrt(std::min(CGAL::to_double(CGAL::squared_distance(s.source(), ray.source())),
                            CGAL::to_double(CGAL::squared_distance(s.target(), ray.source()))));
}

double SurfaceQuery::distance(const Vec3& point) const {
  return std::sqrt(CGAL::to_double(tree_->tree.squared_distance(to_point(point))));
}

double SurfaceQuery::signed_distance(const Vec3& point) const {
  if (!tree_->side) {
    tree_->mesh.emplace(cgal::to_surface_mesh(tree_->surface));
    tree_->side.emplace(*tree_->mesh);
  }
  const double d = distance(point);
  return (*tree_->side)(to_point(point)) == CGAL::ON_UNBOUNDED_SIDE ? -d : d;
}

}  // namespace skelconv::reconstruct
