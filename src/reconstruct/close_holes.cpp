// Implementation of close_holes.hpp. Out of the CGAL library's unity unit
// (src/CMakeLists.txt), as join_overlaps.cpp: hole filling brings in
// refinement, fairing and Eigen's sparse LU, and alone this file compiles
// beside the others instead of lengthening their unit.
#include "close_holes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <fmt/format.h>

#include "cgal_surface.hpp"
#include "union_find.hpp"

namespace skelconv::detail {

namespace {

using Triangle = std::array<std::int32_t, 3>;

/// For each triangle's side k (from corner k to corner k + 1), the
/// triangle glued to it there, or -1 (a boundary). An edge of two
/// triangles glues them; an edge of 2m triangles is split into m edges of
/// two: around the edge, by angle, each triangle running b → a is glued to
/// the next one, which runs a → b, the two bounding one wedge of the solid
/// (its outward normal d × u points to increasing angles for a → b, d = b −
/// a, u its direction away from the edge: the solid lies at decreasing
/// angles of an a → b triangle and increasing ones of a b → a triangle).
/// An edge with more triangles one way than the other is returned in
/// `failure`; the first edge whose wedges nest is described in `nested`.
std::vector<std::array<std::int32_t, 3>> glue_sides(const TriangleMesh& mesh, const std::vector<Triangle>& triangles,
                                                    std::set<std::int32_t>& non_manifold_ends, std::string& nested,
                                                    std::string& failure) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::int32_t, int>>> at_edge;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles[t][std::size_t(k)], b = triangles[t][std::size_t((k + 1) % 3)];
      at_edge[std::minmax(a, b)].emplace_back(std::int32_t(t), k);
    }
  std::vector<std::array<std::int32_t, 3>> glued(triangles.size(), {-1, -1, -1});
  for (const auto& [edge, sides] : at_edge) {
    if (sides.size() == 1) continue;
    const auto forward = [&](const std::pair<std::int32_t, int>& side) {  // runs edge.first -> edge.second
      return triangles[std::size_t(side.first)][std::size_t(side.second)] == edge.first;
    };
    if (sides.size() == 2) {
      glued[std::size_t(sides[0].first)][std::size_t(sides[0].second)] = sides[1].first;
      glued[std::size_t(sides[1].first)][std::size_t(sides[1].second)] = sides[0].first;
      continue;
    }
    non_manifold_ends.insert({edge.first, edge.second});
    const Vec3& a = mesh.vertices[std::size_t(edge.first)];
    const Vec3 d = (mesh.vertices[std::size_t(edge.second)] - a).normalized();
    const auto away = [&](const std::pair<std::int32_t, int>& side) {
      const Vec3 c = mesh.vertices[std::size_t(triangles[std::size_t(side.first)][std::size_t((side.second + 2) % 3)])] - a;
      return Vec3(c - c.dot(d) * d);
    };
    const Vec3 e1 = away(sides[0]).normalized(), e2 = d.cross(e1);
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t k = 0; k < sides.size(); ++k) {
      const Vec3 u = away(sides[k]);
      order.emplace_back(std::atan2(u.dot(e2), u.dot(e1)), k);
    }
    std::sort(order.begin(), order.end());
    // Each b -> a triangle opens a wedge of the solid that the next a -> b
    // triangle by angle closes: matched as brackets, around the circle
    // twice so that a wedge across the angle 0 is closed too. Where the
    // directions alternate, that is the next triangle; where they do not
    // (sheets that cross at the edge), the wedges nest and the surface
    // crosses itself there, which the union of --repair then joins.
    std::size_t forwards = 0;
    for (const auto& side : sides) forwards += forward(side);
    if (2 * forwards != sides.size()) {
      failure = fmt::format("{} of the {} triangles at the edge between vertices {} and {} (counted from 0) run one "
                            "way along it and {} the other",
                            forwards, sides.size(), edge.first, edge.second, sides.size() - forwards);
      return {};
    }
    std::vector<std::size_t> open;
    std::vector<bool> matched(order.size(), false);
    for (std::size_t step = 0; step < 2 * order.size(); ++step) {
      const std::size_t k = step % order.size();
      if (matched[k]) continue;
      const auto& side = sides[order[k].second];
      if (!forward(side)) {
        if (step < order.size()) open.push_back(k);
      } else if (!open.empty()) {
        const auto& opener = sides[order[open.back()].second];
        if ((open.back() + 1) % order.size() != k && nested.empty())
          nested = fmt::format(" (the {} triangles at the edge between vertices {} and {}, counted from 0, do not "
                               "bound separate wedges: sheets cross there)",
                               sides.size(), edge.first, edge.second);
        matched[k] = matched[open.back()] = true;
        open.pop_back();
        glued[std::size_t(opener.first)][std::size_t(opener.second)] = side.first;
        glued[std::size_t(side.first)][std::size_t(side.second)] = opener.first;
      }
    }
  }
  return glued;
}

/// A triangle list as a polygon soup that CGAL's halfedge mesh takes: the
/// sides glued as glue_sides says, and every vertex around which the
/// triangles do not form one disk or one half-disk split, one copy per fan
/// after the first (original[i]: the input vertex of soup point i).
struct Soup {
  std::vector<reconstruct::cgal::Point> points;
  std::vector<std::array<std::size_t, 3>> polygons;  ///< polygon k is triangles[k]
  std::vector<std::int32_t> original;
  std::set<std::int32_t> non_manifold_ends;  ///< the ends of edges of more than two triangles
};

Soup split_fans(const TriangleMesh& mesh, const std::vector<Triangle>& triangles, std::string& failure) {
  Soup soup;
  std::string nested;
  const auto glued = glue_sides(mesh, triangles, soup.non_manifold_ends, nested, failure);
  if (!failure.empty()) return soup;
  // Corner (t, k) is joined to the corner of the same vertex in the
  // triangle glued to either side of t at it: the classes are the fans.
  // (Polygon_mesh_processing::duplicate_non_manifold_edges_in_polygon_soup
  // cuts a vertex at every non-manifold edge around it instead: a vertex
  // beside two merged copies of one position, as on CGAL's diplodocus,
  // was cut in two as well, leaving holes of zero width that no
  // triangulation fills.)
  std::vector<std::int32_t> parent(3 * triangles.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
  const auto corner_of = [&](std::int32_t t, std::int32_t v) {
    const Triangle& tri = triangles[std::size_t(t)];
    return std::int32_t(3 * t + (tri[0] == v ? 0 : tri[1] == v ? 1 : 2));
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t other = glued[t][std::size_t(k)];
      if (other < 0) continue;
      for (const int end : {k, (k + 1) % 3}) {
        const std::int32_t v = triangles[t][std::size_t(end)];
        parent[std::size_t(find_root(parent, std::int32_t(3 * t + end)))] = find_root(parent, corner_of(other, v));
      }
    }
  for (const Vec3& v : mesh.vertices) soup.points.push_back(reconstruct::cgal::to_point(v));
  soup.original.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < soup.original.size(); ++i) soup.original[i] = std::int32_t(i);
  std::map<std::int32_t, std::int32_t> first_fan;    // vertex -> the root of its first fan
  std::map<std::int32_t, std::int32_t> copy_of_fan;  // root of a later fan -> its copy
  soup.polygons.resize(triangles.size());
  for (std::size_t c = 0; c < 3 * triangles.size(); ++c) {
    const std::int32_t v = triangles[c / 3][c % 3], root = find_root(parent, std::int32_t(c));
    std::int32_t index = v;
    const auto [first, added] = first_fan.emplace(v, root);
    if (!added && first->second != root) {
      const auto [copy, new_copy] = copy_of_fan.emplace(root, std::int32_t(soup.points.size()));
      if (new_copy) soup.points.push_back(soup.points[std::size_t(v)]), soup.original.push_back(v);
      index = copy->second;
    }
    soup.polygons[c / 3][c % 3] = std::size_t(index);
  }
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    failure = "splitting its non-manifold edges and vertices did not give a manifold surface" + nested;
  return soup;
}

/// One hole's boundary: vertices (input indices) in the order of the
/// border halfedges (the hole on their left), and for the edge from
/// vertex i to i + 1 the third vertex of the surface's triangle there.
struct Loop {
  std::vector<std::int32_t> vertices, third;
};

/// The border cycle at `h` as loops of the input's vertices: a cycle that
/// passes twice through one input vertex (split into copies, where holes
/// touch) is cut there, each part a hole of its own (going round a vertex
/// where holes touch, the split mesh goes from one hole's border to the
/// other's).
std::vector<Loop> border_loops(const reconstruct::cgal::SurfaceMesh& surface,
                               reconstruct::cgal::SurfaceMesh::Halfedge_index h,
                               const std::vector<std::int32_t>& original) {
  std::vector<std::int32_t> vertices, third;
  for (const auto e : CGAL::halfedges_around_face(h, surface)) {
    vertices.push_back(original[std::size_t(surface.target(e))]);
    third.push_back(original[std::size_t(surface.target(surface.next(surface.opposite(surface.next(e)))))]);
  }
  std::vector<Loop> loops;
  Loop open;
  std::map<std::int32_t, std::size_t> at;  // vertex -> its position in open
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto [it, added] = at.emplace(vertices[i], open.vertices.size());
    if (!added) {
      Loop loop;
      const std::size_t from = it->second;
      loop.vertices.assign(open.vertices.begin() + std::ptrdiff_t(from), open.vertices.end());
      loop.third.assign(open.third.begin() + std::ptrdiff_t(from), open.third.end());
      for (std::size_t k = from + 1; k < open.vertices.size(); ++k) at.erase(open.vertices[k]);
      open.vertices.resize(from);
      open.third.resize(from);
      loops.push_back(std::move(loop));
      open.vertices.push_back(vertices[i]);
      open.third.push_back(third[i]);
      continue;
    }
    open.vertices.push_back(vertices[i]);
    open.third.push_back(third[i]);
  }
  if (!open.vertices.empty()) loops.push_back(std::move(open));
  return loops;
}

}  // namespace

ClosedMesh close_holes(const TriangleMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using reconstruct::cgal::Point;
  using reconstruct::cgal::SurfaceMesh;
  ClosedMesh out;
  std::vector<Triangle> triangles;
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    triangles.push_back(t);
    for (std::int32_t i : t) used[std::size_t(i)] = true;
  }
  for (bool u : used) out.isolated_vertices_removed += !u;

  // The holes, found on the split surface, each triangulated by the
  // minimal-area (and least dihedral angle) triangulation of its border
  // (triangulate_hole_polyline: the search that triangulate_hole runs on a
  // mesh, given the border's points and the vertices across its edges).
  // Not triangulate_hole on the split mesh itself: where two holes touch at
  // a vertex, the split mesh has one border through both copies of it, and
  // one patch across both holes.
  std::vector<FilledHole> holes;
  std::vector<std::size_t> patch_start;  // hole k's triangles start here in `closed`
  std::vector<Triangle> closed = triangles;
  {
    Soup open = split_fans(mesh, triangles, out.failure);
    if (!out.failure.empty()) return out;
    SurfaceMesh surface;
    PMP::polygon_soup_to_polygon_mesh(open.points, open.polygons, surface);
    std::vector<SurfaceMesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(surface, std::back_inserter(cycles));
    for (const auto h : cycles)
      for (const Loop& loop : border_loops(surface, h, open.original)) {
        FilledHole hole;
        hole.edges = loop.vertices.size();
        std::vector<Point> points, third;
        for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
          points.push_back(reconstruct::cgal::to_point(mesh.vertices[std::size_t(loop.vertices[i])]));
          third.push_back(reconstruct::cgal::to_point(mesh.vertices[std::size_t(loop.third[i])]));
          hole.length += (mesh.vertices[std::size_t(loop.vertices[i])] -
                          mesh.vertices[std::size_t(loop.vertices[(i + 1) % loop.vertices.size()])]).norm();
        }
        std::vector<CGAL::Triple<int, int, int>> patch;
        try {
          PMP::triangulate_hole_polyline(points, third, std::back_inserter(patch));
        } catch (const std::exception& e) {
          out.failure = fmt::format("CGAL's hole filling failed on a hole of {} edges ({})", hole.edges, e.what());
          return out;
        }
        if (patch.empty()) {
          out.failure = fmt::format("CGAL found no triangulation of a hole of {} edges", hole.edges);
          return out;
        }
        patch_start.push_back(closed.size());
        for (const auto& t : patch)
          closed.push_back({loop.vertices[std::size_t(t.first)], loop.vertices[std::size_t(t.second)],
                            loop.vertices[std::size_t(t.third)]});
        holes.push_back(hole);
      }
  }
  patch_start.push_back(closed.size());

  // The closed surface (split again where it still touches itself: edges
  // of more than two triangles), each patch refined to the density of the
  // edges around it and faired, as triangulate_refine_and_fair_hole does
  // after its triangulation. Where the fairing's linear system fails, the
  // refined patch is kept as it is (triangulate_and_refine_hole's result).
  Soup soup = split_fans(mesh, closed, out.failure);
  if (!out.failure.empty()) return out;
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, surface);
  for (std::size_t k = 0; k < holes.size(); ++k) {
    std::vector<SurfaceMesh::Face_index> faces;
    for (std::size_t f = patch_start[k]; f < patch_start[k + 1]; ++f) faces.push_back(SurfaceMesh::Face_index(std::uint32_t(f)));
    std::vector<SurfaceMesh::Vertex_index> added;
    std::vector<SurfaceMesh::Face_index> refined = faces;
    try {
      PMP::refine(surface, faces, std::back_inserter(refined), std::back_inserter(added));
      holes[k].faired = added.empty() || PMP::fair(surface, added);
    } catch (const std::exception& e) {
      out.failure = fmt::format("CGAL's hole filling failed on a hole of {} edges ({})", holes[k].edges, e.what());
      return out;
    }
    holes[k].triangles = refined.size();
    holes[k].vertices = added.size();
    for (const auto f : refined) holes[k].patch_area += PMP::face_area(f, surface);
  }
  out.holes = std::move(holes);

  // Surface_mesh keeps the soup's isolated points as isolated vertices:
  // they are left out, the others renumbered in order. A copy made where
  // closed parts touch at a vertex only is that vertex again (a valid
  // input: check_closed_mesh counts edges); copies at an edge of more than
  // two triangles stay, each at its original's position.
  TriangleMesh result;
  std::vector<std::int32_t> index(surface.num_vertices(), -1);
  for (const auto v : surface.vertices()) {
    if (surface.is_isolated(v)) continue;
    if (std::size_t(v) < soup.original.size()) {
      const std::int32_t o = soup.original[std::size_t(v)];
      if (o != std::int32_t(v) && !soup.non_manifold_ends.count(o)) continue;
      if (o != std::int32_t(v)) ++out.vertices_split;
    }
    index[std::size_t(v)] = std::int32_t(result.vertices.size());
    const Point& p = surface.point(v);
    result.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : surface.faces()) {
    if (surface.degree(f) != 3) {
      out.failure = "CGAL's hole filling returned a face that is not a triangle";
      return out;
    }
    Triangle t{};
    std::size_t n = 0;
    for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      const bool merged = std::size_t(v) < soup.original.size() && index[std::size_t(v)] < 0;
      t[n++] = index[merged ? std::size_t(soup.original[std::size_t(v)]) : std::size_t(v)];
    }
    result.triangles.push_back(t);
  }
  out.mesh = std::move(result);
  return out;
}

}  // namespace skelconv::detail
