// Implementation of tube_ends.hpp.
#include "tube_ends.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace skelconv::detail {

namespace {

/// How far along `u` from the tip the input reaches where it tapers on as
/// a horn does beyond `length` (the sphere beyond), or `length` itself
/// where it does not. The way is walked in steps of at most a quarter
/// radius until it leaves the input (then bisected). It is a taper if
/// - it left more than `reach` × `length` from the tip;
/// - it was nowhere deeper than the tip's radius (deeper, the tube ran
///   into a body);
/// - its last nine tenths of depth were lost gently, over at least three
///   times that depth: a horn's tip (a cone of half-angle under 17°).
///   A tube that goes on at its depth and ends in a cap loses its depth
///   over about its depth (a round cap) or less;
/// - it kept to the middle of something thin: at each point at least a
///   quarter as deep as the tip, the input ends (give or take a tenth of
///   the radius) within twice its depth and half the tip's radius
///   sideways, in four directions across the way. Twice: a horn may be
///   flat; a quarter: a curved horn's last quarter leaves the straight
///   way. A way that runs at a slant across a thick tube towards its wall
///   loses its depth gently too, but has the tube's body on one side.
double tapering_reach(const reconstruct::Vec4& tip, const Vec3& u, double length, double reach,
                      const std::function<double(const Vec3&)>& depth) {
  const double farthest = reach * length + 16 * tip.w();
  std::vector<std::pair<double, double>> way{{0.0, depth(tip.head<3>())}};  // (distance, depth)
  const Vec3 side = u.unitOrthogonal(), other_side = u.cross(side);
  double inside = length, outside = -1.0;
  // Steps of at most the depth where they start (the signed distance: no
  // step crosses the surface, not even into another part across a narrow
  // gap), at least a fiftieth and at most a quarter of the radius.
  double last = depth(tip.head<3>() + length * u);
  for (double t = length + std::clamp(last, 0.02 * tip.w(), 0.25 * tip.w()); t <= farthest;
       t += std::clamp(last, 0.02 * tip.w(), 0.25 * tip.w())) {
    const double d = last = depth(tip.head<3>() + t * u);
    if (d > tip.w()) return length;
    if (d < 0.0) {
      outside = t;
      break;
    }
    const Vec3 p = tip.head<3>() + t * u;
    const double across = 2.0 * d + 0.5 * tip.w();
    if (d >= 0.25 * way.front().second)
      for (const Vec3& v : {side, Vec3(-side), other_side, Vec3(-other_side)})
        if (depth(p + across * v) > 0.1 * tip.w()) return length;
    way.emplace_back(t, d);
    inside = t;
  }
  if (outside < 0.0) return length;  // no exit: not a tip
  for (int k = 0; k < 40; ++k) {
    const double middle = 0.5 * (inside + outside);
    (depth(tip.head<3>() + middle * u) >= 0.0 ? inside : outside) = middle;
  }
  if (inside <= reach * length) return length;
  double deepest = 0.0;
  for (const auto& [t, d] : way) deepest = std::max(deepest, d);
  double last_deep = 0.0;  // the last point of the way still 0.9 × the deepest deep
  for (const auto& [t, d] : way)
    if (d >= 0.9 * deepest) last_deep = t;
  return inside - last_deep >= 3.0 * 0.9 * deepest ? inside : length;
}

}  // namespace

std::size_t extend_tube_ends(reconstruct::MedialMesh& mesh, double factor, double spike_depth, double taper_reach,
                             double bulb_slope, const std::function<double(const Vec3&)>& depth, std::size_t* bulbs) {
  if (factor <= 0.0) return 0;
  std::vector<int> edges(mesh.spheres.size(), 0);
  std::vector<bool> on_sheet(mesh.spheres.size(), false);
  for (const auto& e : mesh.edges) ++edges[std::size_t(e[0])], ++edges[std::size_t(e[1])];
  for (const auto& t : mesh.triangles)
    for (const std::int32_t i : t) on_sheet[std::size_t(i)] = true;
  const std::size_t edge_count = mesh.edges.size();
  std::size_t shortened = 0;
  if (bulbs != nullptr) *bulbs = 0;
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
      else if (bulb_slope > 0.0 && tip.w() - mesh.spheres[std::size_t(other)].w() > bulb_slope * direction.norm() &&
               depth(tip.head<3>() + length * u) < 0.5 * tip.w()) {
        // A bulb: the tip's ball is the round lobe itself, wider than the
        // tube it ends by more than bulb_slope × the edge, and the input
        // ends about where its ball does (the sphere beyond would stick
        // out of the input by more than half its radius). A segment out
        // to a sphere beyond would make a capsule of the ball, a radius
        // longer than the input, which the fit then shrinks, ball and all.
        // Its ball is given as an isolated sphere at the tip instead: its
        // surface is the ball's.
        mesh.spheres.push_back(tip);
        mesh.isolated.push_back(std::int32_t(mesh.spheres.size() - 1));
        if (bulbs != nullptr) ++*bulbs;
        continue;
      }
      else if (taper_reach > 0.0 && tip_depth < tip.w())
        length = std::max(length, tapering_reach(tip, u, length, taper_reach, depth));
      const Vec3 beyond = tip.head<3>() + length * u;
      mesh.spheres.push_back(reconstruct::Vec4(beyond.x(), beyond.y(), beyond.z(), tip.w()));
      mesh.edges.push_back({end, std::int32_t(mesh.spheres.size() - 1)});
    }
  }
  return shortened;
}

std::size_t reach_unreached_tips(reconstruct::MedialMesh& mesh, const std::vector<reconstruct::ReachPoint>& tips,
                                 double reach, double thinness, double radius,
                                 const std::function<double(const Vec3&)>& depth) {
  if (!(radius > 0.0)) return 0;
  const std::size_t spheres = mesh.spheres.size();
  std::size_t added = 0;
  for (const reconstruct::ReachPoint& tip : tips) {
    std::size_t nearest = spheres;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < spheres; ++i)
      if (const double g = (tip.point - mesh.spheres[i].head<3>()).norm() - mesh.spheres[i].w(); g < gap)
        gap = g, nearest = i;
    if (nearest == spheres || gap < reach || gap < thinness * mesh.spheres[nearest].w()) continue;
    // One radius short of the tip: a segment's surface reaches on past its
    // end (on CGAL's drop, ending at the tip itself left its worst point
    // there, 1.29% of the diagonal, one radius short 0.77%).
    const Vec3 c = mesh.spheres[nearest].head<3>();
    const double length = (tip.point - c).norm();
    const Vec3 u = (tip.point - c) / length;
    const Vec3 end = tip.point - std::min(radius, 0.5 * length) * u;
    // A sharp tip: one radius short of it the input is less than half a
    // radius deep (a cone under 30° half-angle); a round end of any width
    // is about a radius deep there, and the surface of the sphere nearest
    // it rounds it as it is.
    if (!(depth(end) < 0.5 * radius)) continue;
    bool inside = true;
    for (int k = 0; k <= 16 && inside; ++k) inside = depth(c + (k / 16.0) * (end - c)) >= 0.0;
    if (!inside) continue;
    mesh.spheres.push_back(reconstruct::Vec4(end.x(), end.y(), end.z(), radius));
    mesh.edges.push_back({std::int32_t(nearest), std::int32_t(mesh.spheres.size() - 1)});
    ++added;
  }
  return added;
}

}  // namespace skelconv::detail
