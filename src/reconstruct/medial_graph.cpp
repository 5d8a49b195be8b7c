// Implementation of skelconv/reconstruct/medial_graph.hpp. CGAL is confined
// to this translation unit (its own OBJECT library, src/CMakeLists.txt).
#include "skelconv/reconstruct/medial_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/medial_parts.hpp"
#include "skelconv/reconstruct/surface_samples.hpp"
#include "cgal_surface.hpp"

namespace skelconv::reconstruct {
namespace {

using cgal::Kernel;
using cgal::Point;
using cgal::SurfaceMesh;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

void check_surface(const TriangleMesh& surface, const std::vector<Vec3>& samples, std::size_t minimum_samples) {
  std::set<std::array<double, 3>> distinct;
  for (const Vec3& v : samples) distinct.insert({v.x(), v.y(), v.z()});
  if (distinct.size() < minimum_samples) {
    throw InputError(fmt::format("{} distinct surface samples; a skeleton needs at least {} (is the mesh degenerate?)", distinct.size(), minimum_samples));
  }
  if (surface.triangles.empty()) {
    throw InputError("the mesh has no faces: the inside of the shape is needed (give a closed mesh)");
  }
  if (!mesh_topology(surface).closed) {
    throw InputError("the mesh is not closed (an edge is not shared by exactly two faces): its inside is undefined");
  }
}

/// Whether a cell's circumcentre (its Voronoi vertex) can be constructed in
/// double. The construction divides by the orientation determinant of the
/// cell's edge vectors AB, AC, AD. For a sliver, four samples within rounding
/// of a plane (a flat face sampled on a grid gives many), that determinant
/// is below its own rounding error, a few ε |AB||AC||AD|: it rounds to noise
/// or to 0, and the centre to an arbitrary or infinite point (CGAL asserts
/// on it where assertions are on). Such cells are left out of the graph: the
/// Voronoi vertex of a sliver lies far off its face or nowhere definite, and
/// it is the well-shaped cells around it that carry the medial axis.
bool circumcentre_is_computable(const Delaunay::Cell_handle& cell) {
  const Point& p = cell->vertex(0)->point();
  auto edge = [&](int k) {
    const Point& q = cell->vertex(k)->point();
    return Vec3(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
  };
  const Vec3 a = edge(1), b = edge(2), c = edge(3);
  const double det = a.dot(b.cross(c));
  // 64 ε covers the determinant's rounding (about 10 ε of |a||b||c|) with margin.
  return std::abs(det) > 64 * std::numeric_limits<double>::epsilon() * a.norm() * b.norm() * c.norm();
}

/// The cyclic polygon started at its smallest vertex and run towards the
/// smaller of that vertex's two neighbours: the same polygon whatever
/// vertex and direction it was read from.
std::vector<std::int32_t> canonical_polygon(std::vector<std::int32_t> polygon) {
  std::rotate(polygon.begin(), std::min_element(polygon.begin(), polygon.end()), polygon.end());
  if (polygon.back() < polygon[1]) std::reverse(polygon.begin() + 1, polygon.end());
  return polygon;
}

/// MedialGraph::sample_parts for the samples of surface_samples(surface,
/// sampling); empty when the surface is one part.
std::vector<std::int32_t> sample_parts(const TriangleMesh& surface, const SamplingOptions& sampling) {
  const std::vector<std::int32_t> triangle_part = triangle_parts(surface);
  if (triangle_part.empty() || *std::max_element(triangle_part.begin(), triangle_part.end()) == 0) return {};
  std::vector<std::int32_t> parts;
  for (std::int32_t t : sample_triangles(surface, sampling)) parts.push_back(t < 0 ? 0 : triangle_part[std::size_t(t)]);
  return parts;
}

}  // namespace

MedialGraph medial_graph(const TriangleMesh& surface, std::size_t minimum_samples, const SamplingOptions& sampling) {
  MedialGraph graph;
  graph.samples = surface_samples(surface, sampling);
  check_surface(surface, graph.samples, minimum_samples);
  graph.sample_parts = sample_parts(surface, sampling);
  const SurfaceMesh mesh = cgal::to_surface_mesh(surface);
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel> side(mesh);

  std::vector<std::pair<Point, std::int32_t>> points;
  for (std::size_t k = 0; k < graph.samples.size(); ++k) {
    const Vec3& v = graph.samples[k];
    points.emplace_back(Point(v.x(), v.y(), v.z()), std::int32_t(k));
  }
  // The range insertion sorts the points along a space-filling curve with a
  // random shuffle drawn from CGAL's global generator, whose state the
  // previous calls of the process moved: the cell order, and with it the
  // order of the medial vertices and every tie after, would depend on what
  // ran before. Reseeding makes the graph a function of the input alone
  // (the command and the Python module give the same skeleton).
  CGAL::get_default_random() = CGAL::Random(0);
  const Delaunay delaunay(points.begin(), points.end());

  // Inner Voronoi vertices, numbered in the triangulation's cell order (a
  // deterministic order for the same input).
  std::map<Delaunay::Cell_handle, std::int32_t> number;  // lookup only: never iterated
  std::vector<Delaunay::Cell_handle> inner_cells;
  for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end(); ++cell) {
    if (!circumcentre_is_computable(cell)) continue;
    const Point centre = delaunay.dual(cell);
    if (side(centre) != CGAL::ON_BOUNDED_SIDE) continue;
    MedialVertex vertex;
    vertex.centre = Vec3(centre.x(), centre.y(), centre.z());
    for (int k = 0; k < 4; ++k) vertex.samples[k] = cell->vertex(k)->info();
    vertex.radius = (vertex.centre - graph.samples[std::size_t(vertex.samples[0])]).norm();
    number.emplace(cell, std::int32_t(graph.vertices.size()));
    inner_cells.push_back(cell);
    graph.vertices.push_back(vertex);
  }
  for (std::int32_t a = 0; a < std::int32_t(inner_cells.size()); ++a) {
    const Delaunay::Cell_handle cell = inner_cells[a];
    for (int k = 0; k < 4; ++k) {
      const auto found = number.find(cell->neighbor(k));
      if (found == number.end() || found->second < a) continue;  // each edge once
      MedialEdge edge{a, found->second, {}};
      for (int j = 0, n = 0; j < 4; ++j) {
        if (j != k) edge.facet[n++] = cell->vertex(j)->info();
      }
      graph.edges.push_back(edge);
    }
  }
  // Voronoi faces: the cells around each Delaunay edge, in the order the
  // circulator gives (cyclic), kept when every one is an inner vertex.
  // CGAL's edge iterator reports each edge from the incident cell it ranks
  // first by handle, that is by memory address: which edge comes when, and
  // at which cell each circulation starts, depend on the allocator's state,
  // so on what the process ran before. Each polygon is therefore turned to
  // start at its smallest vertex (the faces are cut into triangles from
  // their first vertex) and the list sorted.
  std::vector<std::int32_t> polygon;
  for (auto edge = delaunay.finite_edges_begin(); edge != delaunay.finite_edges_end(); ++edge) {
    polygon.clear();
    bool inner = true;
    auto cell = delaunay.incident_cells(*edge);
    const auto first = cell;
    do {
      const auto found = number.find(cell);
      if (found == number.end()) {
        inner = false;
        break;
      }
      polygon.push_back(found->second);
    } while (++cell != first);
    if (inner && polygon.size() >= 3) graph.faces.push_back(canonical_polygon(polygon));
  }
  std::sort(graph.faces.begin(), graph.faces.end());
  return graph;
}

}  // namespace skelconv::reconstruct
