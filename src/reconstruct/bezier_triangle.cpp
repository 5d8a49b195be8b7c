// Implementation of skelconv/reconstruct/bezier_triangle.hpp.
#include "skelconv/reconstruct/bezier_triangle.hpp"

#include <algorithm>
#include <map>

#include "skelconv/errors.hpp"

namespace skelconv::reconstruct {

Vec4 bezier_triangle_point(const BezierNet& p, double r, double s, double t) {
  return r * r * r * p[0] + s * s * s * p[1] + t * t * t * p[2] + 3 * r * r * s * p[3] + 3 * r * s * s * p[4] +
         3 * s * s * t * p[5] + 3 * s * t * t * p[6] + 3 * r * t * t * p[7] + 3 * r * r * t * p[8] + 6 * r * s * t * p[9];
}

BezierNet junction_net(const Vec4& centre, const Vec4& c0, const Vec4& c1, const Vec4& c2) {
  const auto third = [&centre](const Vec4& corner) -> Vec4 { return corner + (centre - corner) / 3.0; };
  // P3, P8 are next to P0; P4, P5 next to P1; P6, P7 next to P2.
  return {c0, c1, c2, third(c0), third(c1), third(c1), third(c2), third(c2), third(c0), centre};
}

std::vector<Facet> tessellate(const BezierNet& net, int n) {
  if (n < 1) throw InputError("must be ≥ 1", "subdivisions");
  // Domain point (i, j) ↦ r = 1 − (i + j)/n, s = i/n, t = j/n.
  const auto at = [&](int i, int j) { return bezier_triangle_point(net, 1.0 - double(i + j) / n, double(i) / n, double(j) / n); };
  std::vector<Facet> facets;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      facets.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < n) facets.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return facets;
}

namespace {

/// One branch end at a junction: the branch and whether it is its front.
struct Incidence {
  std::size_t branch;
  bool front;
};

/// How many points to cut from the junction end of `points` (oriented with
/// the junction first): walk until the distance to the junction reaches
/// `reach`, or the arc length `share`, or `last` (the last index allowed).
std::size_t corner_index(const std::vector<Vec4>& points, double reach, double share, std::size_t last) {
  double arc = 0.0;
  std::size_t i = 1;
  for (; i < last; ++i) {
    arc += (points[i].head<3>() - points[i - 1].head<3>()).norm();
    if ((points[i].head<3>() - points[0].head<3>()).norm() >= reach || arc >= share) break;
  }
  return std::min(i, last);
}

}  // namespace

std::vector<Facet> place_junction_triangles(std::vector<Branch>& branches, double k, int n, bool cut_branches) {
  if (!(k > 0.0)) throw InputError("must be > 0", "junction k");
  std::map<std::int32_t, std::vector<Incidence>> at_node;
  for (std::size_t b = 0; b < branches.size(); ++b) {
    at_node[branches[b].first_node].push_back({b, true});
    at_node[branches[b].last_node].push_back({b, false});
  }
  std::vector<std::size_t> cut_front(branches.size(), 0), cut_back(branches.size(), 0);
  std::vector<Facet> facets;
  for (const auto& [node, ends] : at_node) {
    if (ends.size() != 3) continue;
    bool loop = false;
    for (const Incidence& e : ends) loop |= branches[e.branch].first_node == branches[e.branch].last_node;
    if (loop) continue;
    std::array<Vec4, 3> corners;
    Vec4 centre = Vec4::Zero();
    for (int c = 0; c < 3; ++c) {
      const Branch& b = branches[ends[c].branch];
      std::vector<Vec4> p = b.points;
      if (!ends[c].front) std::reverse(p.begin(), p.end());
      centre = p.front();
      const std::int32_t other = ends[c].front ? b.last_node : b.first_node;
      const bool other_free = at_node.at(other).size() == 1;
      const double length = polyline_length(p);
      const double share = other_free ? length : length * p.front().w() / (p.front().w() + p.back().w());
      const std::size_t i = corner_index(p, k * p.front().w(), share, p.size() - 2);
      (ends[c].front ? cut_front : cut_back)[ends[c].branch] = i;
      corners[c] = p[i];
    }
    const std::vector<Facet> patch = tessellate(junction_net(centre, corners[0], corners[1], corners[2]), n);
    facets.insert(facets.end(), patch.begin(), patch.end());
  }
  for (std::size_t b = 0; b < branches.size() && cut_branches; ++b) {  // keep [first corner, last corner]
    const std::vector<Vec4>& p = branches[b].points;
    const std::size_t first = cut_front[b], last = std::max(first, p.size() - 1 - cut_back[b]);
    std::vector<Vec4> kept(p.begin() + std::ptrdiff_t(first), p.begin() + std::ptrdiff_t(last) + 1);
    if (kept.size() == 1) kept.push_back(kept.front());  // both corners met: no segment is written
    branches[b].points = std::move(kept);
  }
  return facets;
}

}  // namespace skelconv::reconstruct
