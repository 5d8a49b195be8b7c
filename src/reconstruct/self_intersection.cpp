// Implementation of check_no_self_intersection (skelconv/reconstruct/
// mesh_check.hpp): CGAL Polygon_mesh_processing::self_intersections, in the
// CGAL object library with the other reconstruction files that need CGAL.
#include <cstddef>
#include <utility>
#include <vector>

#include <boost/iterator/function_output_iterator.hpp>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/reconstruct/mesh_check.hpp"
#include "cgal_surface.hpp"

namespace skelconv::reconstruct {

void check_no_self_intersection(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Face = cgal::SurfaceMesh::Face_index;
  std::vector<cgal::Point> points;
  for (const Vec3& v : mesh.vertices) points.push_back(cgal::to_point(v));
  std::vector<std::array<std::size_t, 3>> polygons;
  std::vector<std::size_t> triangle_of;  // polygon k is mesh.triangles[triangle_of[k]]
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // ignored, as by check_closed_mesh
    polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    triangle_of.push_back(k);
  }
  // Two closed parts that share only a vertex are valid input but not a
  // valid halfedge mesh: orient_polygon_soup duplicates such vertices (the
  // orientation is already consistent, checked before). Faces keep the
  // polygons' order.
  PMP::orient_polygon_soup(points, polygons);
  cgal::SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  // Two triangles at such a vertex no longer share it and are reported as
  // meeting there: a pair that shares fewer vertices now than in the input
  // touches at a split vertex and is not counted (a crossing elsewhere in
  // that pair would go unseen; the other pairs are checked exactly).
  const auto shared = [](const auto& a, const auto& b) {
    int n = 0;
    for (auto i : a)
      for (auto j : b) n += i == j;
    return n;
  };
  std::size_t pairs = 0;
  std::pair<std::size_t, std::size_t> first;
  PMP::self_intersections(faces(surface), surface, boost::make_function_output_iterator([&](const std::pair<Face, Face>& p) {
    const std::size_t a = std::size_t(p.first), b = std::size_t(p.second);
    if (shared(mesh.triangles[triangle_of[a]], mesh.triangles[triangle_of[b]]) > shared(polygons[a], polygons[b])) return;
    if (pairs++ == 0) first = std::minmax(triangle_of[a], triangle_of[b]);
  }));
  if (pairs > 0)
    throw InputError(fmt::format("the mesh intersects itself: triangles {} and {} cross ({} crossing pair(s) in all); "
                                 "overlapping parts must be joined by a boolean union first",
                                 first.first, first.second, pairs));
}

}  // namespace skelconv::reconstruct
