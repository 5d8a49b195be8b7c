// Implementation of join_overlaps.hpp. Out of the CGAL library's unity unit
// (src/CMakeLists.txt): corefinement is the heaviest of its headers, and
// alone it compiles beside the others.
#include "join_overlaps.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <fmt/format.h>

#include "cgal_soup.hpp"
#include "union_find.hpp"
#include "winding_number.hpp"

namespace skelconv::detail {
namespace {

/// A halfedge mesh's faces as triangles, vertices renumbered in order
/// (removed elements are skipped by vertices() and faces()); none when a
/// face is not a triangle.
std::optional<TriangleMesh> to_triangles(const reconstruct::cgal::SurfaceMesh& surface) {
  TriangleMesh out;
  std::vector<std::int32_t> index(surface.num_vertices() + surface.number_of_removed_vertices(), -1);
  for (const auto v : surface.vertices()) {
    index[std::size_t(v)] = std::int32_t(out.vertices.size());
    const reconstruct::cgal::Point& p = surface.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : surface.faces()) {
    if (surface.degree(f) != 3) return std::nullopt;
    std::array<std::int32_t, 3> t{};
    std::size_t n = 0;
    for (const auto v : vertices_around_face(surface.halfedge(f), surface)) t[n++] = index[std::size_t(v)];
    out.triangles.push_back(t);
  }
  return out;
}

/// Whether two meshes have the same triangles, corners compared on a grid
/// of 1e-9 of a's diagonal (the cut's vertices, rounded to double by two
/// routes, differ in their last bits), each triangle from its least corner
/// with its orientation. A corner near a grid line may round to both
/// sides: then the meshes count as different, the safe side.
bool same_triangles(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.triangles.size() != b.triangles.size()) return false;
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const Vec3& v : a.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double step = 1e-9 * (hi - lo).norm();
  using Corner = std::array<long long, 3>;
  const auto keys = [&](const TriangleMesh& m) {
    std::vector<std::array<Corner, 3>> out;
    for (const auto& t : m.triangles) {
      std::array<Corner, 3> c;
      for (std::size_t k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
          c[k][std::size_t(i)] = std::llround((m.vertices[std::size_t(t[k])][i] - lo[i]) / step);
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  return keys(a) == keys(b);
}

/// Removes from `boundary` (the union's, oriented outwards, closed once its
/// vertices at one position are joined) its inward-facing parts: voids
/// that the overlapping parts close off (the winding number is 0 there but
/// the solid surrounds them; a fold's pocket by CGAL's man's armpit). The skeleton of
/// a solid has no cavities (check_closed_mesh refuses them): they are
/// filled. Parts by shared edges between positions; `cavities` counts them.
void fill_cavities(TriangleMesh& boundary, std::size_t& cavities) {
  std::map<std::array<double, 3>, std::int32_t> at;
  std::vector<std::int32_t> position(boundary.vertices.size());
  for (std::size_t i = 0; i < position.size(); ++i) {
    const Vec3& v = boundary.vertices[i];
    position[i] = at.emplace(std::array<double, 3>{v.x(), v.y(), v.z()}, std::int32_t(at.size())).first->second;
  }
  std::vector<std::int32_t> parent(boundary.triangles.size());
  for (std::size_t t = 0; t < parent.size(); ++t) parent[t] = std::int32_t(t);
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> first_at;
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto& tri = boundary.triangles[t];
      const auto edge = std::minmax(position[std::size_t(tri[k])], position[std::size_t(tri[(k + 1) % 3])]);
      const auto [it, added] = first_at.emplace(edge, std::int32_t(t));
      if (!added)
        parent[std::size_t(find_root(parent, std::int32_t(t)))] = find_root(parent, it->second);
    }
  // Six times each part's volume, from one of its corners (exact for a
  // closed part whatever the origin; near it, little cancellation).
  std::map<std::int32_t, double> volume;
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t) {
    const std::int32_t root = find_root(parent, std::int32_t(t));
    const auto& o = boundary.vertices[std::size_t(boundary.triangles[std::size_t(root)][0])];
    const auto& tri = boundary.triangles[t];
    const Vec3 a = boundary.vertices[std::size_t(tri[0])] - o, b = boundary.vertices[std::size_t(tri[1])] - o,
               c = boundary.vertices[std::size_t(tri[2])] - o;
    volume[root] += a.dot(b.cross(c));
  }
  cavities = 0;
  for (const auto& [root, v] : volume) cavities += v < 0.0;
  if (cavities == 0) return;
  std::vector<std::array<std::int32_t, 3>> kept;
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t)
    if (volume[find_root(parent, std::int32_t(t))] >= 0.0) kept.push_back(boundary.triangles[t]);
  boundary.triangles = std::move(kept);
  // Only the vertices of kept triangles: each is a surface sample.
  std::vector<std::int32_t> index(boundary.vertices.size(), -1);
  std::vector<Vec3> vertices;
  for (auto& tri : boundary.triangles)
    for (std::int32_t& i : tri) {
      std::int32_t& k = index[std::size_t(i)];
      if (k < 0) k = std::int32_t(vertices.size()), vertices.push_back(boundary.vertices[std::size_t(i)]);
      i = k;
    }
  boundary.vertices = std::move(vertices);
}

/// The triangles of `refined`, a closed outward surface cut along its
/// crossings (no two triangles cross inside), that bound the solid where
/// its winding number is at least 1/2: those with winding number 0 in
/// front and 1 behind. Crossing an outward sheet from front to back adds
/// one, so the value just in front decides; at a point inside a triangle,
/// the winding number of the others is the mean of its two sides, the
/// front's plus 1/2. Unlike a choice of pieces along crossing curves, this
/// holds where a crossing curve ends inside the surface (a fold), and
/// removes what lies inside another part whether it crosses it or not.
/// `failure` is set when a triangle has no whole winding number in front
/// at any of the points tried (another sheet lies on it or grazes it
/// there, closer than the winding number's accuracy).
TriangleMesh union_boundary(const TriangleMesh& refined, std::optional<std::string>& failure, std::size_t& cavities) {
  const WindingNumber winding(refined.vertices, refined.triangles);
  // Barycentric points inside a triangle: its centroid first, then towards
  // each corner in turn, where a sheet grazing the centroid may be farther.
  static constexpr std::array<std::array<double, 3>, 4> tried{
      {{1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.25, 0.25}, {0.25, 0.5, 0.25}, {0.25, 0.25, 0.5}}};
  // A whole winding number to within this: the dipole clusters' error is
  // a few hundredths; a sheet at the point counts ±1/2.
  constexpr double whole_tolerance = 0.25;
  std::vector<std::size_t> kept;
  for (std::size_t t = 0; t < refined.triangles.size(); ++t) {
    const auto& tri = refined.triangles[t];
    const Vec3 &a = refined.vertices[std::size_t(tri[0])], &b = refined.vertices[std::size_t(tri[1])],
               &c = refined.vertices[std::size_t(tri[2])];
    bool decided = false;
    for (const auto& w : tried) {
      const double front = winding.at(w[0] * a + w[1] * b + w[2] * c, t) - 0.5;
      const double whole = std::round(front);
      if (!(std::abs(front - whole) <= whole_tolerance)) continue;
      if (whole == 0.0) kept.push_back(t);
      decided = true;
      break;
    }
    if (!decided) {
      failure = fmt::format("the winding number in front of a triangle of the cut surface, near ({:.6g}, {:.6g}, "
                            "{:.6g}), is not a whole number (another sheet lies on it)",
                            a.x(), a.y(), a.z());
      return {};
    }
  }
  // Vertices of kept triangles only (every vertex of the repaired mesh is
  // a surface sample, and none may be buried inside), in their order.
  std::vector<std::int32_t> index(refined.vertices.size(), -1);
  for (std::size_t t : kept)
    for (std::int32_t i : refined.triangles[t]) index[std::size_t(i)] = 0;
  TriangleMesh out;
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] == 0) index[i] = std::int32_t(out.vertices.size()), out.vertices.push_back(refined.vertices[i]);
  for (std::size_t t : kept) {
    std::array<std::int32_t, 3> tri = refined.triangles[t];
    for (std::int32_t& i : tri) i = index[std::size_t(i)];
    out.triangles.push_back(tri);
  }
  fill_cavities(out, cavities);
  return out;
}

}  // namespace

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
  // CGAL's own union first, on a copy: where it is the same surface as the
  // winding number's, to rounding, it is kept, so that the meshes it
  // joined before (CGAL's bull and camel) give the same bytes; it differs
  // in the last bits of the cut's vertices and in their order.
  std::optional<TriangleMesh> cgal_union;
  try {
    reconstruct::cgal::SurfaceMesh copy = surface;
    if (PMP::experimental::autorefine_and_remove_self_intersections(copy)) cgal_union = to_triangles(copy);
  } catch (const std::exception&) {
    // the winding number's union below decides
  }
  try {
    PMP::experimental::autorefine(surface);
  } catch (const std::exception& e) {
    return {std::nullopt, fmt::format("CGAL's autorefinement failed ({})", e.what())};
  }
  // The refined surface as a soup: each sheet cut along the curves where
  // others cross it, the cut's vertices in each sheet (one position, as
  // CGAL rounds each exact crossing point once).
  const std::optional<TriangleMesh> refined = to_triangles(surface);
  if (!refined) return {std::nullopt, "CGAL's autorefinement returned a face that is not a triangle"};
  std::optional<std::string> failure;
  std::size_t cavities = 0;
  TriangleMesh out = union_boundary(*refined, failure, cavities);
  if (failure) return {std::nullopt, *failure};
  if (out.triangles.empty())
    return {std::nullopt, "no triangle bounds the solid (the winding number is nowhere 0 in front of the surface)"};
  if (cgal_union && same_triangles(*cgal_union, out)) return {std::move(*cgal_union), {}, false, 0};
  return {std::move(out), {}, false, cavities};
}

}  // namespace skelconv::detail
