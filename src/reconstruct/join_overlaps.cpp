// Implementation of join_overlaps.hpp. Out of the CGAL library's unity unit
// (src/CMakeLists.txt): corefinement is the heaviest of its headers, and
// alone it compiles beside the others.
#include "join_overlaps.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <map>
#include <vector>

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <fmt/format.h>

#include "cgal_soup.hpp"

namespace skelconv::detail {

JoinedMesh join_overlapping_parts(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  reconstruct::cgal::SplitSurface split = reconstruct::cgal::to_split_surface_mesh(mesh);
  reconstruct::cgal::SurfaceMesh& surface = split.mesh;
  using reconstruct::cgal::Point;
  std::map<std::array<double, 3>, int> at_position;
  for (const auto v : surface.vertices()) {
    const Point& p = surface.point(v);
    ++at_position[{p.x(), p.y(), p.z()}];
  }
  std::vector<Point> shared;
  for (const auto& [p, n] : at_position)
    if (n > 1) shared.emplace_back(p[0], p[1], p[2]);
  if (!shared.empty())
    for (const auto f : surface.faces()) {
      std::array<Point, 3> c;
      std::size_t n = 0;
      for (const auto v : vertices_around_face(surface.halfedge(f), surface)) c[n++] = surface.point(v);
      const CGAL::Bbox_3 box = c[0].bbox() + c[1].bbox() + c[2].bbox();
      for (const Point& q : shared) {
        if (!CGAL::do_overlap(box, q.bbox()) || q == c[0] || q == c[1] || q == c[2]) continue;
        if (!reconstruct::cgal::Kernel::Triangle_3(c[0], c[1], c[2]).has_on(q)) continue;
        std::size_t vertex = 0;
        while (reconstruct::cgal::to_point(mesh.vertices[vertex]) != q) ++vertex;
        return {std::nullopt,
                fmt::format("vertex {} (counted from 0), shared by closed parts that touch there only, lies on "
                            "triangle {} of another part",
                            vertex, split.triangle_of[std::size_t(f)]),
                true};
      }
    }
  try {
    if (!PMP::experimental::autorefine_and_remove_self_intersections(surface))
      return {std::nullopt, "CGAL's autorefinement left crossings it could not remove"};
  } catch (const std::exception& e) {
    return {std::nullopt, fmt::format("CGAL's autorefinement failed ({})", e.what())};
  }
  // Removed elements are skipped by vertices() and faces(); the others are
  // renumbered in order.
  TriangleMesh out;
  std::vector<std::int32_t> index(surface.num_vertices() + surface.number_of_removed_vertices(), -1);
  for (const auto v : surface.vertices()) {
    index[std::size_t(v)] = std::int32_t(out.vertices.size());
    const reconstruct::cgal::Point& p = surface.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : surface.faces()) {
    if (surface.degree(f) != 3) return {std::nullopt, "CGAL's autorefinement returned a face that is not a triangle"};
    std::array<std::int32_t, 3> t{};
    std::size_t n = 0;
    for (const auto v : vertices_around_face(surface.halfedge(f), surface)) t[n++] = index[std::size_t(v)];
    out.triangles.push_back(t);
  }
  if (out.triangles.empty()) return {std::nullopt, "CGAL's autorefinement removed every triangle"};
  return {std::move(out), {}};
}

}  // namespace skelconv::detail
