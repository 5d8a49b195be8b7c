// Implementation of skelconv/reconstruct/pavlidis.hpp.
#include "skelconv/reconstruct/pavlidis.hpp"

#include <algorithm>

namespace skelconv::reconstruct {
namespace {

/// Distance from p to the segment [a, b] (to a if a = b).
double segment_distance(const Vec4& p, const Vec4& a, const Vec4& b) {
  const Vec4 ab = b - a;
  const double squared = ab.squaredNorm();
  const double t = squared > 0.0 ? std::clamp((p - a).dot(ab) / squared, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

void split(const std::vector<Vec4>& points, std::size_t i, std::size_t j, double tolerance, std::vector<bool>& keep) {
  if (j <= i + 1) return;
  std::size_t farthest = i;
  double largest = -1.0;
  for (std::size_t k = i + 1; k < j; ++k) {
    const double d = segment_distance(points[k], points[i], points[j]);
    if (d > largest) largest = d, farthest = k;
  }
  if (largest <= tolerance) return;
  keep[farthest] = true;
  split(points, i, farthest, tolerance, keep);
  split(points, farthest, j, tolerance, keep);
}

}  // namespace

std::vector<Vec4> pavlidis_split(const std::vector<Vec4>& points, double tolerance, PavlidisDimension dimension) {
  if (points.size() <= 2) return points;
  std::vector<Vec4> measured = points;
  if (dimension == PavlidisDimension::space) {
    for (Vec4& p : measured) p.w() = 0.0;
  }
  std::vector<bool> keep(points.size(), false);
  keep.front() = keep.back() = true;
  split(measured, 0, points.size() - 1, tolerance, keep);
  std::vector<Vec4> kept;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (keep[k]) kept.push_back(points[k]);
  }
  return kept;
}

}  // namespace skelconv::reconstruct
