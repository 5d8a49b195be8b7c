// verify/polygon_triangulation.cpp — the polygon reference's partition into
// triangles (verify/polygon_reference.hpp, "Partition"): CGAL's constrained
// Delaunay triangulation of the polygon projected on an orthonormal frame of
// its plane, keeping the faces of odd nesting level (CGAL's "polygon
// triangulation" example). Doubles, combinatorics only. The one verifier file
// that includes CGAL, so that the reference's three users do not parse it.
#include <list>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "polygon_reference.hpp"

namespace skelconv::verify::polygon_detail {
namespace {

struct FaceNesting {
  int nesting_level = -1;
  bool in_domain() const { return nesting_level % 2 == 1; }
};

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalVertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, CgalKernel>;
using CgalFaceBase =
    CGAL::Constrained_triangulation_face_base_2<CgalKernel,
                                                CGAL::Triangulation_face_base_with_info_2<FaceNesting, CgalKernel>>;
using CgalTds = CGAL::Triangulation_data_structure_2<CgalVertexBase, CgalFaceBase>;
// No_constraint_intersection_tag: crossing edges (a non-simple polygon) throw
// instead of silently creating Steiner vertices.
using CgalCdt = CGAL::Constrained_Delaunay_triangulation_2<CgalKernel, CgalTds, CGAL::No_constraint_intersection_tag>;

void mark_domain(CgalCdt& cdt, CgalCdt::Face_handle start, int level, std::list<CgalCdt::Edge>& border) {
  if (start->info().nesting_level != -1) return;
  std::list<CgalCdt::Face_handle> queue{start};
  while (!queue.empty()) {
    CgalCdt::Face_handle face = queue.front();
    queue.pop_front();
    if (face->info().nesting_level != -1) continue;
    face->info().nesting_level = level;
    for (int i = 0; i < 3; ++i) {
      const CgalCdt::Edge edge(face, i);
      CgalCdt::Face_handle neighbor = face->neighbor(i);
      if (neighbor->info().nesting_level != -1) continue;
      if (cdt.is_constrained(edge))
        border.push_back(edge);
      else
        queue.push_back(neighbor);
    }
  }
}

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_planar_polygon(const std::vector<Vec3<double>>& points,
                                                                   const Vec3<double>& normal) {
  const std::size_t n = points.size();
  // First frame axis: the coordinate axis least aligned with the normal, made orthogonal.
  std::size_t least = 0;
  for (std::size_t c = 1; c < 3; ++c)
    if (std::abs(normal[c]) < std::abs(normal[least])) least = c;
  Vec3<double> axis{0, 0, 0};
  axis[least] = 1;
  Vec3<double> e1 = axpy(-dot(axis, normal), normal, axis);
  e1 = scaled(1 / norm(e1), e1);
  const Vec3<double> e2 = cross(normal, e1);

  CgalCdt cdt;
  std::vector<CgalCdt::Vertex_handle> handles;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3<double>& q = points[k];
    CgalCdt::Vertex_handle h = cdt.insert(CgalKernel::Point_2(dot(q, e1), dot(q, e2)));
    h->info() = k;
    handles.push_back(h);
  }
  if (cdt.number_of_vertices() != n) throw std::invalid_argument("polygon_reference: repeated vertex");
  try {
    for (std::size_t k = 0; k < n; ++k) cdt.insert_constraint(handles[k], handles[(k + 1) % n]);
  } catch (const std::exception&) {
    throw std::invalid_argument("polygon_reference: polygon edges intersect (not simple)");
  }
  for (CgalCdt::Face_handle f : cdt.all_face_handles()) f->info().nesting_level = -1;
  std::list<CgalCdt::Edge> border;
  mark_domain(cdt, cdt.infinite_face(), 0, border);
  while (!border.empty()) {
    const CgalCdt::Edge edge = border.front();
    border.pop_front();
    CgalCdt::Face_handle neighbor = edge.first->neighbor(edge.second);
    if (neighbor->info().nesting_level == -1)
      mark_domain(cdt, neighbor, edge.first->info().nesting_level + 1, border);
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for (CgalCdt::Face_handle f : cdt.finite_face_handles()) {
    if (!f->info().in_domain()) continue;
    triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  if (triangles.size() != n - 2)
    throw std::invalid_argument("polygon_reference: triangulation has " + std::to_string(triangles.size()) +
                                " triangles, expected " + std::to_string(n - 2) + " (not a simple polygon?)");
  return triangles;
}


}  // namespace skelconv::verify::polygon_detail
