// Implementation of skelconv/reconstruct/medial_slope.hpp.
#include "skelconv/reconstruct/medial_slope.hpp"

#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace skelconv::reconstruct {

void limit_radius_slope(MedialMesh& mesh, double slope) {
  const std::size_t n = mesh.spheres.size();
  std::vector<std::vector<std::size_t>> neighbours(n);
  const auto join = [&](std::int32_t a, std::int32_t b) {
    neighbours[std::size_t(a)].push_back(std::size_t(b));
    neighbours[std::size_t(b)].push_back(std::size_t(a));
  };
  for (const auto& e : mesh.edges) join(e[0], e[1]);
  for (const auto& t : mesh.triangles) join(t[0], t[1]), join(t[1], t[2]), join(t[0], t[2]);
  // Dijkstra from every sphere at once, each starting at its own radius,
  // an edge costing slope × its length: the smallest radius settles first
  // and bounds its neighbours, which settle in turn.
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t i = 0; i < n; ++i) queue.emplace(mesh.spheres[i].w(), i);
  std::vector<bool> settled(n, false);
  while (!queue.empty()) {
    const auto [radius, i] = queue.top();
    queue.pop();
    if (settled[i]) continue;
    settled[i] = true;
    for (const std::size_t j : neighbours[i]) {
      const double bound = radius + slope * (mesh.spheres[i].head<3>() - mesh.spheres[j].head<3>()).norm();
      if (!settled[j] && bound < mesh.spheres[j].w()) {
        mesh.spheres[j].w() = bound;
        queue.emplace(bound, j);
      }
    }
  }
}

}  // namespace skelconv::reconstruct
