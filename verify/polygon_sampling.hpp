// verify/polygon_sampling.hpp — deterministic random polygons and query
// points for the polygon accuracy sweep (verify/polygon_sweep.cpp).
//
// Each region stresses one way the contour formulas (docs/mathematics.md §3) can lose
// digits: the 1/ζ² of the recurrence near the plane, P̄ near an edge or a
// vertex (h → 0, the fan angle jumps), the cancelling fans far away, and for
// the compact family the support sphere cutting the edges. Every sample has
// its own engine, seeded from (seed, family, region, index), as in
// verify/sampling.hpp, so samples do not depend on chunking or threads.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <vector>

#include "sampling.hpp"

namespace skelconv::verify {

enum class PolygonRegion {
  generic,            ///< height 0.05–2 diameters, P̄ anywhere within 1.5 diameters
                      ///< (compact: R = 1.5–4 times the distance from P to the polygon)
  near_plane_inside,  ///< P̄ inside, ≥ 0.05 diam from the boundary, |z| = 1e-6–1e-2 diam
  plane_outside,      ///< P̄ outside, 0.05–1.5 diam from the boundary, z = 0 or |z| = 1e-6–1e-2 diam
  near_edges,         ///< P̄ within 1e-6–1e-2 diam of an edge or a vertex, |z| = 1e-6–0.1 diam
  far,                ///< 3–1e4 diameters from the polygon's centre
  support_crossing,   ///< compact only: the support sphere cuts the polygon's edges
};

inline constexpr std::array<PolygonRegion, 6> all_polygon_regions{
    PolygonRegion::generic,    PolygonRegion::near_plane_inside, PolygonRegion::plane_outside,
    PolygonRegion::near_edges, PolygonRegion::far,               PolygonRegion::support_crossing};

constexpr std::string_view polygon_region_name(PolygonRegion region) {
  switch (region) {
    case PolygonRegion::generic: return "generic";
    case PolygonRegion::near_plane_inside: return "near_plane_inside";
    case PolygonRegion::plane_outside: return "plane_outside";
    case PolygonRegion::near_edges: return "near_edges";
    case PolygonRegion::far: return "far";
    case PolygonRegion::support_crossing: return "support_crossing";
  }
  return "?";
}

constexpr bool polygon_region_applies(PolygonRegion region, KernelFamily family) {
  return region != PolygonRegion::support_crossing || family == KernelFamily::compact;
}

/// One polygon sample: the polygon (CCW about `normal`), the point and the
/// kernel parameters. Every degree of the family is checked on it.
struct PolygonProblem {
  KernelFamily family = KernelFamily::inverse;
  PolygonRegion region = PolygonRegion::generic;
  std::uint64_t index = 0;
  std::vector<Vec3<double>> vertices;
  Vec3<double> normal{};
  Vec3<double> p{};
  double s = 1, R = 1;
  double diameter = 1;
};

namespace detail {

/// The in-plane outlines the sweep uses, counter-clockwise: a triangle, a
/// regular pentagon, an L-shaped hexagon and a concave 8-pointed star.
inline std::vector<std::array<double, 2>> polygon_outline(int shape, DeterministicRandom& rng) {
  std::vector<std::array<double, 2>> out;
  switch (shape) {
    case 0:  // a random, not too thin triangle
      out = {{0, 0}, {1, rng.uniform(-0.2, 0.2)}, {rng.uniform(0.1, 0.9), rng.uniform(0.4, 1.0)}};
      break;
    case 1:
      for (int k = 0; k < 5; ++k) {
        const double angle = 2 * std::numbers::pi * k / 5;
        out.push_back({0.5 * std::cos(angle), 0.5 * std::sin(angle)});
      }
      break;
    case 2:
      out = {{0, 0}, {1, 0}, {1, 0.4}, {0.4, 0.4}, {0.4, 1}, {0, 1}};
      break;
    default:
      for (int k = 0; k < 16; ++k) {
        const double angle = 2 * std::numbers::pi * k / 16, radius = k % 2 == 0 ? 0.5 : 0.22;
        out.push_back({radius * std::cos(angle), radius * std::sin(angle)});
      }
      break;
  }
  return out;
}

/// Winding number test in the plane (even–odd on a simple polygon).
inline bool inside_outline(const std::vector<std::array<double, 2>>& poly, double x, double y) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) inside = !inside;
  }
  return inside;
}

inline double distance_to_outline(const std::vector<std::array<double, 2>>& poly, double x, double y) {
  double best = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    double t = ((x - a[0]) * ex + (y - a[1]) * ey) / (ex * ex + ey * ey);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    best = std::min(best, std::hypot(x - a[0] - t * ex, y - a[1] - t * ey));
  }
  return best;
}

}  // namespace detail

/// Where a sample's outline is placed: vertex = origin + step·(x·u + y·v),
/// points off the plane + step·z·w, with u, v, w orthogonal of equal length
/// `length`; the unit normal is w / length. The sweep's frame has unit
/// u, v, w drawn at random (step = the scale); the exact frame of the
/// certified spot checks (test_certified_references.cpp) has integer u, v, w
/// and a power-of-two step, so that its vertices are exactly coplanar doubles.
struct PolygonFrame {
  Vec3<double> origin{}, u{}, v{}, w{};
  double step = 1;
  double length = 1;  ///< |u| = |v| = |w|
  /// Outline coordinates are rounded to multiples of this (0: not rounded),
  /// so that x·u + y·v is exact.
  double grid = 0;
};

/// The sweep's frame: a random orthonormal (e1, e2, n), a scale giving a
/// diameter of 0.5–2, an origin in [−1, 1]³ (`outline_diameter`: the
/// outline's own diameter).
inline PolygonFrame random_polygon_frame(DeterministicRandom& rng, double outline_diameter) {
  PolygonFrame frame;
  const Vec3<double> n = rng.unit_vector();
  const Vec3<double> e1 = rng.unit_perpendicular(n);
  frame.u = e1;
  frame.v = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
  frame.w = n;
  frame.step = rng.log_uniform(0.5, 2.0) / outline_diameter;
  frame.origin = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
  return frame;
}

/// The sample `index` of (family, region) for `seed`, its outline placed by
/// `make_frame(rng, outline_diameter)` (the sweep: random_polygon_frame).
template <class MakeFrame>
PolygonProblem draw_polygon_problem(std::uint64_t seed, KernelFamily family, PolygonRegion region, std::uint64_t index,
                                    MakeFrame make_frame) {
  DeterministicRandom rng(point_seed(seed ^ 0x706f6c79676f6eULL, family, 0, static_cast<Region>(region), index));
  PolygonProblem pb;
  pb.family = family;
  pb.region = region;
  pb.index = index;
  auto outline = detail::polygon_outline(static_cast<int>(index % 4), rng);
  double diameter = 0;
  for (const auto& u : outline)
    for (const auto& v : outline) diameter = std::max(diameter, std::hypot(u[0] - v[0], u[1] - v[1]));
  const PolygonFrame frame = make_frame(rng, diameter);
  if (frame.grid > 0)
    for (auto& u : outline) u = {std::round(u[0] / frame.grid) * frame.grid, std::round(u[1] / frame.grid) * frame.grid};
  const double scale = frame.step * frame.length;  // outline units → distance
  auto place = [&](double x, double y, double z) {
    const Vec3<double>&o = frame.origin, &u = frame.u, &v = frame.v, &w = frame.w;
    return Vec3<double>{o[0] + frame.step * (x * u[0] + y * v[0] + z * w[0]),
                        o[1] + frame.step * (x * u[1] + y * v[1] + z * w[1]),
                        o[2] + frame.step * (x * u[2] + y * v[2] + z * w[2])};
  };
  for (const auto& u : outline) pb.vertices.push_back(place(u[0], u[1], 0));
  pb.normal = {frame.w[0] / frame.length, frame.w[1] / frame.length, frame.w[2] / frame.length};
  pb.diameter = scale * diameter;
  // Kernel parameters relative to the polygon's size.
  pb.s = rng.log_uniform(0.1, 10) / (pb.diameter * pb.diameter);
  pb.R = rng.uniform(0.3, 2.0) * pb.diameter;

  // The point, in outline units (diameter `diameter`).
  double bx = 0, by = 0, bz = 0;
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
  for (const auto& u : outline) {
    lo_x = std::min(lo_x, u[0]), hi_x = std::max(hi_x, u[0]);
    lo_y = std::min(lo_y, u[1]), hi_y = std::max(hi_y, u[1]);
  }
  const double cx = (lo_x + hi_x) / 2, cy = (lo_y + hi_y) / 2;
  auto signed_height = [&](double lo, double hi) { return (rng.coin() ? 1 : -1) * rng.log_uniform(lo, hi) * diameter; };
  switch (region) {
    case PolygonRegion::generic:
    case PolygonRegion::support_crossing:
      bx = cx + rng.uniform(-1.5, 1.5) * diameter;
      by = cy + rng.uniform(-1.5, 1.5) * diameter;
      bz = signed_height(0.05, 2.0);
      break;
    case PolygonRegion::near_plane_inside:
      for (;;) {
        bx = rng.uniform(lo_x, hi_x), by = rng.uniform(lo_y, hi_y);
        if (detail::inside_outline(outline, bx, by) && detail::distance_to_outline(outline, bx, by) >= 0.05 * diameter)
          break;
      }
      bz = signed_height(1e-6, 1e-2);
      break;
    case PolygonRegion::plane_outside:
      for (;;) {
        bx = cx + rng.uniform(-1.5, 1.5) * diameter, by = cy + rng.uniform(-1.5, 1.5) * diameter;
        if (!detail::inside_outline(outline, bx, by) && detail::distance_to_outline(outline, bx, by) >= 0.05 * diameter)
          break;
      }
      bz = index % 2 == 0 ? 0.0 : signed_height(1e-6, 1e-2);
      break;
    case PolygonRegion::near_edges: {
      // Near an edge's interior, or (one in four) near a vertex.
      const std::size_t m = static_cast<std::size_t>(rng.uniform01() * outline.size()) % outline.size();
      const auto& a = outline[m];
      const auto& b = outline[(m + 1) % outline.size()];
      const double t = index % 4 == 3 ? 0.0 : rng.uniform(0.05, 0.95);
      const double ex = b[0] - a[0], ey = b[1] - a[1], len = std::hypot(ex, ey);
      const double offset = rng.log_uniform(1e-6, 1e-2) * diameter;
      const double angle = index % 4 == 3 ? rng.uniform(0, 2 * std::numbers::pi) : (rng.coin() ? 0.5 : -0.5) * std::numbers::pi;
      const double dx = ex / len, dy = ey / len;
      bx = a[0] + t * ex + offset * (std::cos(angle) * dx - std::sin(angle) * dy);
      by = a[1] + t * ey + offset * (std::sin(angle) * dx + std::cos(angle) * dy);
      bz = signed_height(1e-6, 1e-1);
      break;
    }
    case PolygonRegion::far: {
      const Vec3<double> d = rng.unit_vector();
      const double r = rng.log_uniform(3, 1e4) * diameter;
      bx = cx + r * d[0], by = cy + r * d[1], bz = r * d[2];
      break;
    }
  }
  if (frame.grid > 0) {  // so that z = 0 is exactly in the plane
    bx = std::round(bx / frame.grid) * frame.grid;
    by = std::round(by / frame.grid) * frame.grid;
  }
  pb.p = place(bx, by, bz);
  if (region == PolygonRegion::generic) {
    // Compact kernels: a support ball reaching well into the polygon (1.5–4
    // times the distance from P to it); barely touching it is
    // support_crossing's business (f → 0 there).
    const double in_plane =
        detail::inside_outline(outline, bx, by) ? 0.0 : detail::distance_to_outline(outline, bx, by);
    pb.R = rng.uniform(1.5, 4.0) * std::hypot(in_plane, bz) * scale;
  }
  if (region == PolygonRegion::support_crossing) {
    // R between the distances from P to the nearest and the farthest vertex:
    // the support sphere then cuts the boundary.
    double near = 1e300, far = 0;
    for (const auto& q : pb.vertices) {
      const double d = norm(sub(q, pb.p));
      near = std::min(near, d), far = std::max(far, d);
    }
    pb.R = rng.uniform(near, far);
  }
  return pb;
}

/// The sweep's sample `index` of (family, region) for `seed`.
inline PolygonProblem draw_polygon_problem(std::uint64_t seed, KernelFamily family, PolygonRegion region,
                                           std::uint64_t index) {
  return draw_polygon_problem(seed, family, region, index, random_polygon_frame);
}

}  // namespace skelconv::verify
