// Implementation of skelconv/reconstruct/surface_distance.hpp (CGAL TU).
#include "skelconv/reconstruct/surface_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <vector>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Random.h>

#include "skelconv/errors.hpp"
#include "cgal_surface.hpp"

namespace skelconv::reconstruct {
namespace {

using cgal::Kernel;
using cgal::Point;
using cgal::SurfaceMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The mesh to compare as a CGAL surface mesh; it must have triangles.
SurfaceMesh comparable_mesh(const TriangleMesh& surface) {
  if (surface.triangles.empty()) throw InputError("a mesh to compare has no triangles");
  return cgal::to_surface_mesh(surface);
}

/// PMP's sampling: `density` random points per unit area, plus the
/// vertices and points on the edges. random_seed(0) seeds only the choice
/// of triangles; the point inside a triangle and the edge points are drawn
/// from CGAL's default generator, which is seeded by the clock (two runs
/// gave 0.714 and 0.718). reseed() fixes that one before every sampling,
/// as src/mesh/cgal_surface_mesher.cpp does for Mesh_3.
auto sampling(double density) { return CGAL::parameters::number_of_points_per_area_unit(density).random_seed(0); }
void reseed() { CGAL::get_default_random() = CGAL::Random(0); }

/// The largest distance from a vertex of `from` to the surface `to`, each
/// position asked once (split_to_edge_length repeats a corner for every
/// triangle round it: six times on a fine mesh).
double largest_vertex_distance(const TriangleMesh& from, const SurfaceMesh& to) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  Tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  std::vector<std::array<double, 3>> points;
  points.reserve(from.vertices.size());
  for (const Vec3& v : from.vertices) points.push_back({v.x(), v.y(), v.z()});
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  double largest = 0.0;
  for (const auto& v : points) largest = std::max(largest, tree.squared_distance(Point(v[0], v[1], v[2])));
  return std::sqrt(largest);
}

/// Sum of squared distances from samples of `from` to `to`, and their count.
std::pair<double, std::size_t> squared_distances(const SurfaceMesh& from, const SurfaceMesh& to, double density) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  Tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  std::vector<Point> samples;
  reseed();
  PMP::sample_triangle_mesh(from, std::back_inserter(samples), sampling(density));
  double sum = 0.0;
  for (const Point& p : samples) sum += tree.squared_distance(p);
  return {sum, samples.size()};
}

}  // namespace

SurfaceDistance surface_distance(const TriangleMesh& a, const TriangleMesh& b, double samples_per_area) {
  const SurfaceMesh ma = comparable_mesh(a), mb = comparable_mesh(b);
  Vec3 lo = a.vertices.front(), hi = lo;
  for (const Vec3& v : a.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  SurfaceDistance result;
  result.diagonal = (hi - lo).norm();
  const double density = samples_per_area / (result.diagonal * result.diagonal);
  const auto options = sampling(density);
  reseed();
  const double ab = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(ma, mb, options);
  reseed();
  const double ba = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(mb, ma, options);
  const double dense_ab = largest_vertex_distance(split_to_edge_length(a, dense_sample_spacing * result.diagonal), mb);
  const double dense_ba = largest_vertex_distance(b, ma);
  result.hausdorff = std::max({ab, ba, dense_ab, dense_ba});
  const auto [sum_ab, n_ab] = squared_distances(ma, mb, density);
  const auto [sum_ba, n_ba] = squared_distances(mb, ma, density);
  result.rms = std::sqrt((sum_ab + sum_ba) / double(n_ab + n_ba));
  return result;
}

TriangleMesh split_to_edge_length(const TriangleMesh& mesh, double edge) {
  TriangleMesh out;
  for (const auto& t : mesh.triangles) {
    const std::array<Vec3, 3> c{mesh.vertices[std::size_t(t[0])], mesh.vertices[std::size_t(t[1])],
                                mesh.vertices[std::size_t(t[2])]};
    const double longest = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
    const int n = std::clamp(int(std::ceil(longest / edge)), 1, 64);
    const auto point = [&](int i, int j) { return c[0] + (double(i) / n) * (c[1] - c[0]) + (double(j) / n) * (c[2] - c[0]); };
    const auto index = [&](int i, int j) {
      out.vertices.push_back(point(i, j));
      return std::int32_t(out.vertices.size() - 1);
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        out.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
        if (i + j + 1 < n) out.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
      }
    }
  }
  return out;
}

}  // namespace skelconv::reconstruct
