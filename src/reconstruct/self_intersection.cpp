// Implementation of find_self_intersections and check_no_self_intersection
// (skelconv/reconstruct/mesh_check.hpp): CGAL
// Polygon_mesh_processing::self_intersections, in the CGAL object library
// with the other reconstruction files that need CGAL.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <boost/iterator/function_output_iterator.hpp>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/reconstruct/mesh_check.hpp"
#include "cgal_soup.hpp"

namespace skelconv::reconstruct {

SelfIntersections find_self_intersections(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Face = cgal::SurfaceMesh::Face_index;
  const cgal::SplitSurface split = cgal::to_split_surface_mesh(mesh);
  // Two triangles at a split vertex no longer share it and are reported as
  // meeting there: a pair whose corners share more positions in the input
  // than vertices after the split touches at a split vertex and is not
  // counted (a crossing elsewhere in that pair would go unseen; the other
  // pairs are checked exactly). Positions, not indices: the vertices that
  // --repair leaves split where the surface touches itself along an edge
  // (check_closed_mesh_repairing) are distinct vertices at one position.
  const auto shared = [](const auto& a, const auto& b) {
    int n = 0;
    for (auto i : a)
      for (auto j : b) n += i == j;
    return n;
  };
  const auto shared_positions = [&mesh](const std::array<std::int32_t, 3>& a, const std::array<std::int32_t, 3>& b) {
    int n = 0;
    for (auto i : a)
      for (auto j : b) n += mesh.vertices[std::size_t(i)] == mesh.vertices[std::size_t(j)];
    return n;
  };
  SelfIntersections found;
  PMP::self_intersections(faces(split.mesh), split.mesh,
                          boost::make_function_output_iterator([&](const std::pair<Face, Face>& p) {
                            const std::size_t a = std::size_t(p.first), b = std::size_t(p.second);
                            const std::size_t ta = split.triangle_of[a], tb = split.triangle_of[b];
                            if (shared_positions(mesh.triangles[ta], mesh.triangles[tb]) >
                                shared(split.polygons[a], split.polygons[b]))
                              return;
                            if (found.pairs++ == 0) std::tie(found.first, found.second) = std::minmax(ta, tb);
                          }));
  return found;
}

std::string self_intersection_problem(const SelfIntersections& found) {
  return fmt::format("the mesh intersects itself: triangles {} and {} cross ({} crossing pair(s) in all)", found.first,
                     found.second, found.pairs);
}

void check_no_self_intersection(const TriangleMesh& mesh) {
  const SelfIntersections found = find_self_intersections(mesh);
  if (found.pairs > 0)
    throw InputError(self_intersection_problem(found) + "; overlapping parts must be joined by a boolean union first");
}

}  // namespace skelconv::reconstruct
