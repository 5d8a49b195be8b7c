// Implementation of skelconv/mesh/bounding_region.hpp.
#include "skelconv/mesh/bounding_region.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

Box3 widened(const Box3& box, double margin) {
  const Vec3 m = Vec3::Constant(margin);
  return {box.lo - m, box.hi + m};
}

/// A cube of the skeleton-point thinning, by its floored coordinates (kept
/// as doubles: far from the box corner they exceed a long long).
using SkeletonCube = std::tuple<double, double, double>;

/// True when f < iso at every sample of the six faces of `box`, and at the
/// points of the faces nearest the skeleton points (one per `cell`-sized
/// cube of them). The n × n grid alone misses a small component far from
/// the others: its bump of {f > iso} through a face can be narrower than
/// the grid's spacing, which grows with the skeleton's extent while the
/// bump's width is the margin. Every kernel decays away from its skeleton,
/// so that bump is largest where the face is nearest the skeleton.
bool faces_below_iso(const ImplicitField& field, double iso, const Box3& box, int n, double cell) {
  std::set<SkeletonCube> used;
  for (const Vec3& p : field.skeleton_points) {
    const Vec3 c = ((p - box.lo) / cell).array().floor();
    if (!used.insert({c.x(), c.y(), c.z()}).second) continue;
    const Vec3 inside = p.cwiseMax(box.lo).cwiseMin(box.hi);
    for (int axis = 0; axis < 3; ++axis) {
      for (const double side : {box.lo[axis], box.hi[axis]}) {
        Vec3 q = inside;
        q[axis] = side;
        if (!(field.value(q) < iso)) return false;
      }
    }
  }
  const Vec3 extent = box.hi - box.lo;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          Vec3 p;
          p[axis] = side == 0 ? box.lo[axis] : box.hi[axis];
          p[u] = box.lo[u] + extent[u] * double(i) / double(n - 1);
          p[v] = box.lo[v] + extent[v] * double(j) / double(n - 1);
          if (!(field.value(p) < iso)) return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

Box3 bounding_box(const std::vector<Vec3>& points) {
  Box3 box{points.front(), points.front()};
  for (const Vec3& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

Box3 bounding_region(const ImplicitField& field, double iso, const BoundingRegionOptions& options) {
  const Box3 skeleton = bounding_box(field.skeleton_points);
  const double diagonal = skeleton.diagonal();
  // A margin of a few doubles' spacing at the skeleton's coordinates leaves
  // the faces on the skeleton's own points (1e100 from the origin, doubles
  // are 2e84 apart), where f >= iso: the surface would seem not to close.
  // From 16 spacings on, the faces are apart from the skeleton, and the
  // mesher's precision check (mesh_iso_surface.cpp) refuses a box this
  // fine with the reason.
  const double magnitude = std::max(skeleton.lo.cwiseAbs().maxCoeff(), skeleton.hi.cwiseAbs().maxCoeff());
  const double least_margin = 16 * (std::nextafter(magnitude, INFINITY) - magnitude);
  double margin = std::max(diagonal > 0 ? diagonal / 4 : 1.0, least_margin);
  const auto passes = [&](double m) {
    return faces_below_iso(field, iso, widened(skeleton, m), options.face_samples, m);
  };
  int rescalings = 0;
  if (passes(margin)) {
    while (rescalings++ < options.max_rescalings && margin / 2 >= least_margin && passes(margin / 2)) margin /= 2;
  } else {
    while (true) {
      if (rescalings++ >= options.max_rescalings || !std::isfinite(2 * margin)) {
        throw InputError(fmt::format("the surface f = {} does not close: f >= {} on the faces of every box "
                                     "up to {:g} around the skeleton",
                                     iso, iso, margin),
                         "--iso");
      }
      margin *= 2;
      if (passes(margin)) break;
    }
  }
  return widened(skeleton, 2 * margin);
}

}  // namespace skelconv
