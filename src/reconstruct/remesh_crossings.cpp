// Implementation of remesh_crossings (join_overlaps.hpp). Out of the CGAL
// library's unity unit, as join_overlaps.cpp: repair_self_intersections
// (hole filling, smoothing) is as heavy as corefinement.
#include <exception>

#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <fmt/format.h>

#include "cgal_soup.hpp"
#include "join_overlaps.hpp"

namespace skelconv::detail {

JoinedMesh remesh_crossings(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  reconstruct::cgal::SplitSurface split = reconstruct::cgal::to_split_surface_mesh(mesh);
  try {
    if (!PMP::experimental::remove_self_intersections(split.mesh))
      return {std::nullopt, "CGAL's local remeshing left crossings it could not remove"};
  } catch (const std::exception& e) {
    return {std::nullopt, fmt::format("CGAL's local remeshing failed ({})", e.what())};
  }
  return to_triangle_mesh(split.mesh, "CGAL's local remeshing");
}

}  // namespace skelconv::detail
