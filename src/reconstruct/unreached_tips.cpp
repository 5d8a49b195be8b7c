// Implementation of unreached_tips.hpp.
#include "unreached_tips.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace skelconv::detail {

namespace {

/// The ball of `graph` falling shortest of q and its gap (|q − c| − r).
struct Nearest {
  std::int32_t vertex = -1;
  double gap = std::numeric_limits<double>::infinity();
};

void consider(const reconstruct::MedialGraph& graph, std::int32_t v, const Vec3& q, Nearest& best) {
  const reconstruct::MedialVertex& ball = graph.vertices[std::size_t(v)];
  const double gap = (q - ball.centre).norm() - ball.radius;
  if (gap < best.gap) best = {v, gap};
}

}  // namespace

std::vector<reconstruct::ReachPoint> unreached_tips(const reconstruct::MedialGraph& graph, double reach,
                                                    double thinness, double apart) {
  if (graph.vertices.empty() || !(reach > 0.0)) return {};
  // The balls' centres in cubes of side `reach`: most samples find a ball
  // within a cube or two that reaches them, and only the few left far from
  // every ball nearby are compared with all of them.
  const double cube = reach;
  const auto key = [cube](const Vec3& p) {
    return std::array<long long, 3>{(long long)std::floor(p.x() / cube), (long long)std::floor(p.y() / cube),
                                    (long long)std::floor(p.z() / cube)};
  };
  struct KeyHash {
    std::size_t operator()(const std::array<long long, 3>& k) const {
      return std::size_t(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  std::unordered_map<std::array<long long, 3>, std::vector<std::int32_t>, KeyHash> cubes;
  for (std::size_t v = 0; v < graph.vertices.size(); ++v) cubes[key(graph.vertices[v].centre)].push_back(std::int32_t(v));
  // A ball's four samples are on its sphere (gap 0).
  std::vector<bool> touched(graph.samples.size(), false);
  for (const reconstruct::MedialVertex& v : graph.vertices)
    for (const std::int32_t s : v.samples) touched[std::size_t(s)] = true;
  // Per vertex, its farthest unreached sample.
  std::vector<double> farthest(graph.vertices.size(), -1.0);
  std::vector<std::int32_t> sample_of(graph.vertices.size(), -1);
  for (std::size_t s = 0; s < graph.samples.size(); ++s) {
    if (touched[s]) continue;
    const Vec3& q = graph.samples[s];
    Nearest best;
    const auto k = key(q);
    for (long long i = -2; i <= 2; ++i)
      for (long long j = -2; j <= 2; ++j)
        for (long long l = -2; l <= 2; ++l)
          if (const auto at = cubes.find({k[0] + i, k[1] + j, k[2] + l}); at != cubes.end())
            for (const std::int32_t v : at->second) consider(graph, v, q, best);
    // A gap under `reach` is not a tip whichever ball is nearest (the
    // true nearest only lowers it).
    if (best.gap < reach) continue;
    for (std::size_t v = 0; v < graph.vertices.size(); ++v) consider(graph, std::int32_t(v), q, best);
    const double radius = graph.vertices[std::size_t(best.vertex)].radius;
    if (best.gap < reach || best.gap < thinness * radius) continue;
    if (best.gap > farthest[std::size_t(best.vertex)])
      farthest[std::size_t(best.vertex)] = best.gap, sample_of[std::size_t(best.vertex)] = std::int32_t(s);
  }
  std::vector<reconstruct::ReachPoint> found;
  for (std::size_t v = 0; v < graph.vertices.size(); ++v)
    if (sample_of[v] >= 0) found.push_back({std::int32_t(v), graph.samples[std::size_t(sample_of[v])]});
  std::vector<reconstruct::ReachPoint> points;
  for (const reconstruct::ReachPoint& p : found)
    if (std::none_of(found.begin(), found.end(), [&p, apart](const reconstruct::ReachPoint& other) {
          return other.vertex != p.vertex && (other.point - p.point).norm() <= apart;
        }))
      points.push_back(p);
  return points;
}

}  // namespace skelconv::detail
