// Implementation of skelconv/reconstruct/medial_slope.hpp.
#include "skelconv/reconstruct/medial_slope.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace skelconv::reconstruct {
namespace {

using Neighbours = std::vector<std::vector<std::size_t>>;

/// Each sphere's neighbours along the tube edges and triangle sides.
Neighbours neighbours_of(const MedialMesh& mesh) {
  Neighbours neighbours(mesh.spheres.size());
  const auto join = [&](std::int32_t a, std::int32_t b) {
    neighbours[std::size_t(a)].push_back(std::size_t(b));
    neighbours[std::size_t(b)].push_back(std::size_t(a));
  };
  for (const auto& e : mesh.edges) join(e[0], e[1]);
  for (const auto& t : mesh.triangles) join(t[0], t[1]), join(t[1], t[2]), join(t[0], t[2]);
  return neighbours;
}

double length(const MedialMesh& mesh, std::size_t i, std::size_t j) {
  return (mesh.spheres[i].head<3>() - mesh.spheres[j].head<3>()).norm();
}

using Entry = std::pair<double, std::size_t>;  // (radius, sphere)

/// Dijkstra from every sphere at once, each starting at its own radius:
/// spheres settle in the order `first` puts their radii (std::less:
/// smallest first), and each settled sphere i offers each neighbour j not
/// yet settled the radius offer(r_i, i, j), which j takes where `first`
/// puts it before j's own; j then settles in turn. `from` (if set) gets for
/// each sphere the one whose offer it took last (itself where it took none).
template <class First, class Offer>
void settle(MedialMesh& mesh, const Neighbours& neighbours, First first, const Offer& offer,
            std::vector<std::size_t>* from = nullptr) {
  if (from != nullptr) {
    from->resize(mesh.spheres.size());
    for (std::size_t i = 0; i < mesh.spheres.size(); ++i) (*from)[i] = i;
  }
  const auto later = [first](const Entry& a, const Entry& b) { return first(b, a); };
  std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) queue.emplace(mesh.spheres[i].w(), i);
  std::vector<bool> settled(mesh.spheres.size(), false);
  while (!queue.empty()) {
    const auto [radius, i] = queue.top();
    queue.pop();
    if (settled[i]) continue;
    settled[i] = true;
    for (const std::size_t j : neighbours[i]) {
      const double offered = offer(radius, i, j);
      if (!settled[j] && first(Entry(offered, j), Entry(mesh.spheres[j].w(), j))) {
        mesh.spheres[j].w() = offered;
        if (from != nullptr) (*from)[j] = i;
        queue.emplace(offered, j);
      }
    }
  }
}

}  // namespace

void limit_radius_slope(MedialMesh& mesh, double slope, const Clearance& clearance,
                        std::vector<std::size_t>* bounded_by) {
  const Neighbours neighbours = neighbours_of(mesh);
  if (clearance) {
    std::vector<double> room(mesh.spheres.size());
    for (std::size_t i = 0; i < mesh.spheres.size(); ++i) room[i] = clearance(mesh.spheres[i].head<3>());
    // Pass 1: the largest radius settles first and grows its neighbours,
    // each edge lowering what it passes on by slope × its length, each
    // sphere taking at most its clearance.
    settle(mesh, neighbours, std::greater<Entry>(), [&](double radius, std::size_t i, std::size_t j) {
      return std::min(room[j], radius - slope * length(mesh, i, j));
    });
  }
  // Pass 2: the smallest radius settles first and bounds its neighbours, an
  // edge costing slope × its length.
  settle(mesh, neighbours, std::less<Entry>(),
         [&](double radius, std::size_t i, std::size_t j) { return radius + slope * length(mesh, i, j); }, bounded_by);
}

}  // namespace skelconv::reconstruct
