// Implementation of tube_ends.hpp.
#include "tube_ends.hpp"

#include <algorithm>

namespace skelconv::detail {

std::size_t extend_tube_ends(reconstruct::MedialMesh& mesh, double factor, double spike_depth,
                             const std::function<double(const Vec3&)>& depth) {
  if (factor <= 0.0) return 0;
  std::vector<int> edges(mesh.spheres.size(), 0);
  std::vector<bool> on_sheet(mesh.spheres.size(), false);
  for (const auto& e : mesh.edges) ++edges[std::size_t(e[0])], ++edges[std::size_t(e[1])];
  for (const auto& t : mesh.triangles)
    for (const std::int32_t i : t) on_sheet[std::size_t(i)] = true;
  const std::size_t edge_count = mesh.edges.size();
  std::size_t shortened = 0;
  for (std::size_t k = 0; k < edge_count; ++k) {
    for (int side = 0; side < 2; ++side) {
      const std::int32_t end = mesh.edges[k][std::size_t(side)], other = mesh.edges[k][std::size_t(1 - side)];
      if (edges[std::size_t(end)] != 1 || on_sheet[std::size_t(end)]) continue;
      const reconstruct::Vec4 tip = mesh.spheres[std::size_t(end)];
      const Vec3 direction = tip.head<3>() - mesh.spheres[std::size_t(other)].head<3>();
      if (!(direction.norm() > 0.0)) continue;
      const Vec3 u = direction.normalized();
      double length = factor * tip.w();
      const double tip_depth = depth(tip.head<3>());
      if (tip_depth < spike_depth * tip.w() && depth(tip.head<3>() + length * u) < 0.0) {
        // A spike: its sphere beyond goes back to the input's surface, the
        // last point of the way that is inside (bisection; the way is
        // shorter than the tip's radius, the input turns back across it
        // nowhere on a spike's scale).
        if (tip_depth < 0.0) continue;
        double inside = 0.0;
        for (int step = 0; step < 40; ++step) {
          const double middle = 0.5 * (inside + length);
          (depth(tip.head<3>() + middle * u) >= 0.0 ? inside : length) = middle;
        }
        length = inside;
        ++shortened;
        // Too short a segment for the skeleton file (under 1e-8 of the
        // coordinates, with margin): no sphere beyond.
        const Vec3 beyond = tip.head<3>() + length * u;
        if (length <= 1e-6 * std::max(tip.head<3>().cwiseAbs().maxCoeff(), beyond.cwiseAbs().maxCoeff())) continue;
      }
      const Vec3 beyond = tip.head<3>() + length * u;
      mesh.spheres.push_back(reconstruct::Vec4(beyond.x(), beyond.y(), beyond.z(), tip.w()));
      mesh.edges.push_back({end, std::int32_t(mesh.spheres.size() - 1)});
    }
  }
  return shortened;
}

}  // namespace skelconv::detail
