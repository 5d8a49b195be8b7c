// Implementation of skelconv/reconstruct/skeleton_comparison.hpp.
#include "skelconv/reconstruct/skeleton_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

namespace skelconv::reconstruct {
namespace {

/// Running max and mean of a set of errors.
void add(ErrorStatistics& s, double error) {
  s.max = std::max(s.max, error);
  s.mean += (error - s.mean) / double(++s.count);
}

struct Nearest {
  double distance = INFINITY;
  double radius = 0.0;  ///< the known radius there
};

/// The nearest point of the known skeleton to `p`, and its radius.
Nearest nearest_known(const Vec3& p, const std::vector<KnownSegment>& known) {
  Nearest best;
  for (const KnownSegment& s : known) {
    const Vec3 ab = s.b - s.a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - s.a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    const double d = (p - (s.a + t * ab)).norm();
    if (d < best.distance) best = {d, (1.0 - t) * s.radius_a + t * s.radius_b};
  }
  return best;
}

}  // namespace

std::vector<KnownSegment> known_segments(const Skeleton& skeleton) {
  std::vector<KnownSegment> out;
  for (const Primitive& p : skeleton.primitives()) {
    if (const auto* s = std::get_if<ScalisSegment>(&p)) out.push_back({s->a(), s->b(), s->tau0(), s->tau1()});
  }
  return out;
}

std::vector<Vec3> known_junctions(const std::vector<KnownSegment>& known, double tolerance) {
  std::vector<Vec3> points;
  std::vector<int> uses;
  const auto use = [&](const Vec3& p) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      if ((points[k] - p).norm() <= tolerance) return void(++uses[k]);
    }
    points.push_back(p), uses.push_back(1);
  };
  for (const KnownSegment& s : known) use(s.a), use(s.b);
  std::vector<Vec3> junctions;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (uses[k] >= 3) junctions.push_back(points[k]);
  }
  return junctions;
}

SkeletonComparison compare_with_known(const std::vector<Branch>& branches, const std::vector<KnownSegment>& known,
                                      double tolerance) {
  SkeletonComparison result;
  const std::vector<Vec3> junctions = known_junctions(known, tolerance);
  result.known_junctions = junctions.size();
  // A recovered junction: a node with three or more branch ends (a closed
  // branch's node counts twice), at the branch's first or last point.
  std::map<std::int32_t, int> uses;
  std::map<std::int32_t, Vec3> where;
  for (const Branch& b : branches) {
    ++uses[b.first_node], ++uses[b.last_node];
    where[b.first_node] = b.points.front().head<3>();
    where[b.last_node] = b.points.back().head<3>();
  }
  for (const auto& [node, count] : uses) {
    if (count < 3 || junctions.empty()) continue;
    double nearest = INFINITY;
    for (const Vec3& j : junctions) nearest = std::min(nearest, (j - where[node]).norm());
    add(result.junction, nearest);
  }
  for (const Branch& b : branches) {
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      if ((i == 0 && b.extended_first) || (i + 1 == b.points.size() && b.extended_last)) continue;
      const Nearest n = nearest_known(b.points[i].head<3>(), known);
      if (!std::isfinite(n.distance)) continue;  // no known segment
      add(result.axis, n.distance);
      add(result.radius, std::abs(b.points[i].w() - n.radius));
    }
  }
  return result;
}

}  // namespace skelconv::reconstruct
