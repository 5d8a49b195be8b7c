// src/reconstruct/cgal_surface.hpp — what the reconstruction's CGAL files
// (medial_graph.cpp, surface_distance.cpp, surface_query.cpp) share: the
// kernel (exact predicates, double constructions), CGAL's surface mesh over
// it, and the conversions from skelconv's types. Internal: not installed.
#pragma once

#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

inline Point to_point(const Vec3& v) { return Point(v.x(), v.y(), v.z()); }

/// `surface` as a CGAL surface mesh: the same vertices and triangles, in the
/// same order (vertex i of `surface` is vertex i of the result).
inline SurfaceMesh to_surface_mesh(const TriangleMesh& surface) {
  SurfaceMesh mesh;
  std::vector<SurfaceMesh::Vertex_index> index;
  index.reserve(surface.vertices.size());
  for (const Vec3& v : surface.vertices) index.push_back(mesh.add_vertex(to_point(v)));
  for (const auto& t : surface.triangles) mesh.add_face(index[t[0]], index[t[1]], index[t[2]]);
  return mesh;
}

}  // namespace skelconv::reconstruct::cgal
