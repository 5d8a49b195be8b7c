// Implementation of skelconv/mesh/bounding_region.hpp.
#include "skelconv/mesh/bounding_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>
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

/// The samples of the six faces of `box` that bounding_region tests: the
/// points of the faces nearest the skeleton points (one per `cell`-sized
/// cube of them), nearest first, then an n × n grid on each face. The grid
/// alone misses a small component far from the others: its bump of
/// {f > iso} through a face can be narrower than the grid's spacing, which
/// grows with the skeleton's extent while the bump's width is the margin.
/// Every kernel decays away from its skeleton, so that bump is largest
/// where the face is nearest the skeleton, and a box too small shows it
/// first there.
std::vector<Vec3> face_samples(const std::vector<Vec3>& skeleton_points, const Box3& box, int n, double cell) {
  std::vector<std::pair<double, Vec3>> nearest;  // (distance to its skeleton point, sample)
  std::set<SkeletonCube> used;
  for (const Vec3& p : skeleton_points) {
    const Vec3 c = ((p - box.lo) / cell).array().floor();
    if (!used.insert({c.x(), c.y(), c.z()}).second) continue;
    const Vec3 inside = p.cwiseMax(box.lo).cwiseMin(box.hi);
    for (int axis = 0; axis < 3; ++axis) {
      for (const double side : {box.lo[axis], box.hi[axis]}) {
        Vec3 q = inside;
        q[axis] = side;
        nearest.emplace_back((q - p).norm(), q);
      }
    }
  }
  std::stable_sort(nearest.begin(), nearest.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec3> samples;
  samples.reserve(nearest.size() + 6 * std::size_t(n) * std::size_t(n));
  for (const auto& sample : nearest) samples.push_back(sample.second);
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
          samples.push_back(p);
        }
      }
    }
  }
  return samples;
}

/// True when f < iso at the first `count` of `samples` (all of them by
/// default).
bool below_iso(const ImplicitField& field, double iso, const std::vector<Vec3>& samples,
               std::size_t count = std::numeric_limits<std::size_t>::max()) {
  count = std::min(count, samples.size());
  for (std::size_t k = 0; k < count; ++k)
    if (!(field.value(samples[k]) < iso)) return false;
  return true;
}

/// Face samples that bounding_region's descent evaluates at each margin:
/// those nearest the skeleton, where a box too small fails first.
constexpr std::size_t probe_samples = 6;

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
  const auto samples = [&](double m) {
    return face_samples(field.skeleton_points, widened(skeleton, m), options.face_samples, m);
  };
  // The margin is the smallest of m0 · 2^k (m0 its start, k of either
  // sign) whose faces pass every sample. A piece of the surface holds a
  // skeleton point (its seeds come from them), so one that pokes through
  // the faces at a margin crosses those of every smaller margin too: the
  // faces fail below some margin and pass above it. Rather than testing
  // every sample of every margin on the way down, the descent tests only
  // the samples nearest the skeleton (probe_samples), which fail first, and
  // stops above the first margin where they do; the full test then climbs
  // from there. A margin whose probes fail fails the full test too (they
  // are among its samples), so where the samples fail below one margin and
  // pass above it, as the surface does, the margin is the one that testing
  // every sample from m0 down finds (a bump slipping between the samples
  // of one margin and not of a larger one could make them differ).
  int rescalings = 0;
  while (rescalings < options.max_rescalings && margin / 2 >= least_margin &&
         below_iso(field, iso, samples(margin / 2), probe_samples)) {
    margin /= 2;
    ++rescalings;
  }
  rescalings = 0;
  while (!below_iso(field, iso, samples(margin))) {
    if (rescalings++ >= options.max_rescalings || !std::isfinite(2 * margin)) {
      throw InputError(fmt::format("the surface f = {} does not close: f >= {} on the faces of every box "
                                   "up to {:g} around the skeleton",
                                   iso, iso, margin),
                       "--iso");
    }
    margin *= 2;
  }
  return widened(skeleton, 2 * margin);
}

}  // namespace skelconv
