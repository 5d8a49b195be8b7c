// src/reconstruct/cgal_soup.hpp — a checked closed mesh as a CGAL halfedge
// mesh, for the files that test or repair its crossings
// (self_intersection.cpp, join_overlaps.cpp). Internal: not installed.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include "cgal_surface.hpp"

namespace skelconv::reconstruct::cgal {

/// A mesh's proper triangles as a halfedge mesh, with the vertices split
/// where closed parts meet at a single vertex.
struct SplitSurface {
  SurfaceMesh mesh;  ///< face k is polygons[k]
  std::vector<std::array<std::size_t, 3>> polygons;  ///< after the split
  std::vector<std::size_t> triangle_of;  ///< polygon k is the input's triangles[triangle_of[k]]
};

/// Two closed parts that share only a vertex are valid input but not a
/// valid halfedge mesh: orient_polygon_soup duplicates such vertices (the
/// orientation is already consistent, checked before). Triangles with a
/// repeated vertex are left out, as by check_closed_mesh. Faces keep the
/// triangles' order.
inline SplitSurface to_split_surface_mesh(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  SplitSurface out;
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.push_back(to_point(v));
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    out.polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    out.triangle_of.push_back(k);
  }
  PMP::orient_polygon_soup(points, out.polygons);
  PMP::polygon_soup_to_polygon_mesh(points, out.polygons, out.mesh);
  return out;
}

}  // namespace skelconv::reconstruct::cgal
