// Implementation of skelconv/reconstruct/surface_query.hpp (CGAL TU).
#include "skelconv/reconstruct/surface_query.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
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

namespace {

/// Below this cosine between the offset to the closest point and the
/// pseudonormal, the sign is left to the ray cast. Where the closest
/// feature is found right, the theorem of Bærentzen & Aanæs makes the
/// cosine nonzero; it comes near 0 only for a rounding-level tie between
/// features or at a knife edge (two faces folded back on each other), and
/// the ray cast costs little where it is that rare.
constexpr double sign_margin = 1e-6;

/// The feature of triangle (a, b, c) whose normal cone holds `p`: the
/// Voronoi regions of the triangle (Ericson, Real-Time Collision Detection,
/// 5.1.5). 0–2: the corners a, b, c; 3–5: the sides ab, bc, ca; 6: the face.
int closest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return 0;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return 1;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return 3;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return 2;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return 5;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return 4;
  return 6;
}

Vec3 to_vec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

}  // namespace

struct SurfaceQuery::Tree {
  std::vector<Triangle> triangles;  // the tree points into this vector
  AabbTree tree;
  TriangleMesh surface;  // for the side test, built when first asked
  std::optional<cgal::SurfaceMesh> mesh;
  std::optional<CGAL::Side_of_triangle_mesh<cgal::SurfaceMesh, Kernel>> side;
  // Angle-weighted pseudonormals (outward, not normalised) of each tree
  // triangle's corners, sides (ab, bc, ca) and face, in closest_feature's
  // order; empty where the surface is not a closed, consistently oriented
  // manifold of proper triangles (then the ray cast decides every sign).
  std::vector<std::array<Vec3, 7>> pseudonormals;

  void build_pseudonormals();
  std::optional<bool> outside(const Vec3& point, const Point& closest, std::size_t triangle) const;
};

/// Pseudonormals exist only where every triangle with three distinct
/// corners is in the tree (not degenerate) and every side is shared with
/// exactly one other triangle, which runs it the other way: the conditions
/// of the sign theorem, met by every input that check_closed_mesh passes
/// (its self-intersection test aside, which this does not repeat).
void SurfaceQuery::Tree::build_pseudonormals() {
  std::vector<std::array<std::int32_t, 3>> corners;
  for (const auto& t : surface.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    corners.push_back({t[0], t[1], t[2]});
  }
  if (corners.size() != triangles.size()) return;  // a degenerate triangle left out of the tree
  std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> sides;  // directed side → its triangle
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!sides.emplace(std::pair{corners[i][k], corners[i][(k + 1) % 3]}, i).second) return;
  std::vector<Vec3> face(corners.size());
  std::vector<Vec3> at_vertex(surface.vertices.size(), Vec3::Zero());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const std::array<Vec3, 3> v{surface.vertices[std::size_t(corners[i][0])],
                                surface.vertices[std::size_t(corners[i][1])],
                                surface.vertices[std::size_t(corners[i][2])]};
    face[i] = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = v[(k + 1) % 3] - v[k], e2 = v[(k + 2) % 3] - v[k];
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      at_vertex[std::size_t(corners[i][k])] += angle * face[i];
    }
  }
  if (!std::all_of(face.begin(), face.end(), [](const Vec3& n) { return n.allFinite(); })) return;
  std::vector<std::array<Vec3, 7>> normals(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      normals[i][std::size_t(k)] = at_vertex[std::size_t(corners[i][k])];
      const auto twin = sides.find({corners[i][(k + 1) % 3], corners[i][k]});
      if (twin == sides.end()) return;  // open or inconsistently oriented
      normals[i][std::size_t(3 + k)] = face[i] + face[twin->second];
    }
    normals[i][6] = face[i];
  }
  pseudonormals = std::move(normals);
}

/// Whether `point`, whose closest point on the surface is `closest` on tree
/// triangle `triangle`, is outside: the sign of the offset along the
/// closest feature's pseudonormal; nothing where there are no pseudonormals
/// or the sign is too close to call.
std::optional<bool> SurfaceQuery::Tree::outside(const Vec3& point, const Point& closest, std::size_t triangle) const {
  if (pseudonormals.empty()) return std::nullopt;
  const Triangle& t = triangles[triangle];
  const int feature = closest_feature(point, to_vec(t[0]), to_vec(t[1]), to_vec(t[2]));
  const Vec3& normal = pseudonormals[triangle][std::size_t(feature)];
  const Vec3 offset = point - to_vec(closest);
  const double along = offset.dot(normal);
  if (!(std::abs(along) > sign_margin * offset.norm() * normal.norm())) return std::nullopt;
  return along > 0.0;
}

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
  tree_->build_pseudonormals();
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
  const Point p = to_point(point);
  // The closest point is the one squared_distance measures to (CGAL's
  // AABB_tree::squared_distance is the distance to closest_point, from the
  // same hint): the same distance as distance(point), bit for bit.
  const auto [closest, primitive] = tree_->tree.closest_point_and_primitive(p);
  const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, closest)));
  if (d == 0.0) return d;  // on the surface: "inside or on it"
  const std::size_t triangle = std::size_t(primitive - tree_->triangles.cbegin());
  std::optional<bool> outside = tree_->outside(point, closest, triangle);
  if (!outside) {
    if (!tree_->side) {
      tree_->mesh.emplace(cgal::to_surface_mesh(tree_->surface));
      tree_->side.emplace(*tree_->mesh);
    }
    outside = (*tree_->side)(p) == CGAL::ON_UNBOUNDED_SIDE;
  }
  return *outside ? -d : d;
}

}  // namespace skelconv::reconstruct
