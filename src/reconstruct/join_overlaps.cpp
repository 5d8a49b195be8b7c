// Implementation of join_overlaps.hpp. Out of the CGAL library's unity unit
// (src/CMakeLists.txt): corefinement is the heaviest of its headers, and
// alone it compiles beside the others.
#include "join_overlaps.hpp"

#include <exception>

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <fmt/format.h>

#include "cgal_soup.hpp"

namespace skelconv::detail {

JoinedMesh join_overlapping_parts(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  reconstruct::cgal::SplitSurface split = reconstruct::cgal::to_split_surface_mesh(mesh);
  reconstruct::cgal::SurfaceMesh& surface = split.mesh;
  try {
    if (!PMP::experimental::autorefine_and_remove_self_intersections(surface))
      return {std::nullopt, "CGAL's autorefinement left crossings it could not remove"};
  } catch (const std::exception& e) {
    return {std::nullopt, fmt::format("CGAL's autorefinement failed ({})", e.what())};
  }
  return to_triangle_mesh(surface, "CGAL's autorefinement");
}

}  // namespace skelconv::detail
