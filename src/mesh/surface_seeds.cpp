// Implementation of skelconv/mesh/surface_seeds.hpp.
#include "skelconv/mesh/surface_seeds.hpp"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "../detail/parallel_for.hpp"

namespace skelconv {
namespace {

/// Distance from p (inside `box`) to the box boundary along unit axis
/// direction `d`.
double distance_to_exit(const Box3& box, const Vec3& p, const Vec3& d) {
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 0) t = std::min(t, (box.hi[k] - p[k]) / d[k]);
    if (d[k] < 0) t = std::min(t, (box.lo[k] - p[k]) / d[k]);
  }
  return t;
}

/// The first crossing of f = iso found on the ray p + t d (f(p) > iso), or
/// nothing if f ≥ iso up to the box boundary.
std::optional<Vec3> ray_crossing(const ImplicitField& field, double iso, const Box3& box, const Vec3& p,
                                 const Vec3& d, const SurfaceSeedOptions& options) {
  const auto inside = [&field, iso](const Vec3& q) {
    return field.reaches ? field.reaches(q, iso) : field.value(q) >= iso;
  };
  const double t_exit = distance_to_exit(box, p, d);
  double in = 0.0;
  double outside = std::min(options.spacing, t_exit);
  while (inside(p + outside * d)) {
    if (outside >= t_exit) return std::nullopt;
    in = outside;
    outside = std::min(2 * outside, t_exit);
  }
  const double bracket = options.bracket_fraction * options.spacing;
  while (outside - in > bracket) {
    const double middle = 0.5 * (in + outside);
    (inside(p + middle * d) ? in : outside) = middle;
  }
  return p + 0.5 * (in + outside) * d;
}

using Cell = std::tuple<long long, long long, long long>;

Cell cell_of(const Vec3& p, const Vec3& origin, double width) {
  const Vec3 c = ((p - origin) / width).array().floor();
  return {std::llround(c.x()), std::llround(c.y()), std::llround(c.z())};
}

/// Seeds accepted so far, in a hash grid of cell width `radius`, to reject a
/// new seed closer than `radius` to an accepted one of another ray source.
class SeedGrid {
 public:
  SeedGrid(const Vec3& origin, double radius) : origin_(origin), radius_(radius) {}

  /// Adds the crossings of one skeleton point, dropping those closer than
  /// `radius` to a seed of an earlier skeleton point.
  void add_from_one_source(const std::vector<Vec3>& crossings, std::vector<Vec3>& seeds) {
    std::vector<Vec3> kept;
    for (const Vec3& q : crossings) {
      if (!near_accepted(q)) kept.push_back(q);
    }
    for (const Vec3& q : kept) {
      remember(q);
      seeds.push_back(q);
    }
  }

  /// Counts `q` as a seed accepted before (of another skeleton point).
  void remember(const Vec3& q) { cells_[cell_of(q, origin_, radius_)].push_back(q); }

 private:
  bool near_accepted(const Vec3& q) const {
    const auto [i, j, k] = cell_of(q, origin_, radius_);
    for (long long a = i - 1; a <= i + 1; ++a) {
      for (long long b = j - 1; b <= j + 1; ++b) {
        for (long long c = k - 1; c <= k + 1; ++c) {
          const auto found = cells_.find({a, b, c});
          if (found == cells_.end()) continue;
          for (const Vec3& s : found->second) {
            if ((s - q).norm() < radius_) return true;
          }
        }
      }
    }
    return false;
  }

  Vec3 origin_;
  double radius_;
  std::map<Cell, std::vector<Vec3>> cells_;
};

const Vec3 ray_directions[] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(),
                               -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};

/// The crossings of the six rays from each of `points`, computed on
/// `threads` threads, each point's into its own slot: the same as one
/// thread going through the points in order, failures included.
std::vector<std::vector<Vec3>> cast_rays(const ImplicitField& field, double iso, const Box3& box,
                                         const std::vector<Vec3>& points, const SurfaceSeedOptions& options,
                                         unsigned threads) {
  std::vector<std::vector<Vec3>> crossings(points.size());
  const auto cast = [&](std::size_t n) {
    for (const Vec3& d : ray_directions) {
      // A ray in the plane of an inverse-kernel polygon may land on one of its
      // edges or vertices (f infinite, refused as in scan_skeleton): that ray
      // gives no seed; the other rays and skeleton points seed the component.
      try {
        if (auto crossing = ray_crossing(field, iso, box, points[n], d, options)) crossings[n].push_back(*crossing);
      } catch (const EvaluationError&) {
        if (!field.infinite_on_skeleton) throw;
      }
    }
  };
  detail::parallel_for(points.size(), cast, 16, threads);
  return crossings;
}

/// What the skeleton points' own values tell before any ray is cast.
struct SkeletonScan {
  /// Per skeleton point: evaluated and f > iso (points after a fatal
  /// failure are not looked at).
  std::vector<char> inside;
  /// The points that cast rays: inside, and the first in their cell of
  /// width `spacing`.
  std::vector<std::size_t> sources;
  /// The failure to throw once the sources' rays are cast, if any.
  std::exception_ptr fatal;
  std::optional<EvaluationError> first_failure;
  double largest = -std::numeric_limits<double>::infinity();
  Vec3 largest_at = Vec3::Zero();
};

SkeletonScan scan_skeleton(const ImplicitField& field, double iso, const Box3& box,
                           const SurfaceSeedOptions& options, unsigned threads) {
  // The field's values are computed on every core, each skeleton point's
  // into its own slot, and taken in the points' order: the sources, and the
  // error thrown, are the one-thread loop's. A failure is kept with its
  // point, and thrown where that loop would have met it.
  const std::vector<Vec3>& points = field.skeleton_points;
  std::vector<double> values(points.size(), 0.0);
  std::vector<std::exception_ptr> value_failures(points.size());
  detail::parallel_for(
      points.size(),
      [&](std::size_t k) {
        try {
          values[k] = field.value(points[k]);
        } catch (...) {
          value_failures[k] = std::current_exception();
        }
      },
      64, threads);
  SkeletonScan scan;
  scan.inside.assign(points.size(), 0);
  scan.largest_at = points.front();
  std::set<Cell> used_cells;
  for (std::size_t k = 0; k < points.size() && !scan.fatal; ++k) {
    const Vec3& p = points[k];
    // On an inverse-kernel polygon or segment a skeleton point lies on (or,
    // after rounding, next to) the set where f is infinite, and the closed
    // form may refuse it (EvaluationError: "returned inf where the field is
    // finite"). Such a point is skipped, not fatal: the others (the centroid,
    // the points inside) seed the same component. Only when every skeleton
    // point failed is the first failure reported. A field finite everywhere
    // has no such excuse: its errors surface at once.
    if (value_failures[k]) {
      try {
        std::rethrow_exception(value_failures[k]);
      } catch (const EvaluationError& error) {
        if (!field.infinite_on_skeleton) scan.fatal = value_failures[k];
        else if (!scan.first_failure) scan.first_failure = error;
      } catch (...) {
        scan.fatal = value_failures[k];
      }
      continue;
    }
    const double f = values[k];
    if (f > scan.largest) std::tie(scan.largest, scan.largest_at) = std::make_tuple(f, p);
    if (!(f > iso)) continue;
    scan.inside[k] = 1;
    if (!used_cells.insert(cell_of(p, box.lo, options.spacing)).second) continue;
    scan.sources.push_back(k);
  }
  return scan;
}

/// Throws the scan's "no surface" errors (after the rays, as the one-thread
/// loop met them).
void check_some_surface(const SkeletonScan& scan, double iso) {
  if (scan.largest == -std::numeric_limits<double>::infinity() && scan.first_failure) throw *scan.first_failure;
  if (scan.largest <= iso) {
    throw InputError(fmt::format("no surface at iso {}: the field is below it on the whole skeleton "
                                 "(largest value {:.6g} at ({}, {}, {}))",
                                 iso, scan.largest, scan.largest_at.x(), scan.largest_at.y(), scan.largest_at.z()),
                     "--iso");
  }
}

/// How far apart, in `spacing`s, two skeleton points inside may be and
/// still be joined into one region (when the grid's nodes between them are
/// inside): the points of one element, a few per element, lie farther
/// apart than a fine spacing; much farther apart and the checks would cost
/// as much as the rays they spare.
constexpr double region_link_reach = 4.0;

/// The nodes of the grid of `spacing` from `origin` nearest to the points of
/// the segment [p, q], from p's to q's, each a face neighbour of the one
/// before (one axis at a time, x then y then z, where the nearest nodes
/// of two points of the segment differ in more than one).
std::vector<Cell> node_path(const Vec3& p, const Vec3& q, const Vec3& origin, double spacing) {
  const auto node_of = [&](const Vec3& x) {
    const Vec3 c = ((x - origin) / spacing).array().round();
    return Cell{std::llround(c.x()), std::llround(c.y()), std::llround(c.z())};
  };
  // Points a quarter spacing apart: no node nearest the segment is skipped
  // between two of them but by a step of more than one axis, filled in.
  const int steps = std::max(1, int(std::ceil(4 * (q - p).norm() / spacing)));
  std::vector<Cell> path{node_of(p)};
  for (int n = 1; n <= steps; ++n) {
    const Cell next = node_of(p + (double(n) / steps) * (q - p));
    Cell at = path.back();
    auto& [ai, aj, ak] = at;
    const auto [ni, nj, nk] = next;
    while (ai != ni) ai += ni > ai ? 1 : -1, path.push_back(at);
    while (aj != nj) aj += nj > aj ? 1 : -1, path.push_back(at);
    while (ak != nk) ak += nk > ak ? 1 : -1, path.push_back(at);
  }
  return path;
}

/// The region of every skeleton point inside (RegionSeeds), as the index of
/// its first point; −1 outside. Each point inside is joined to the nearest
/// earlier point inside within region_link_reach spacings (the lowest
/// index among equals) when f ≥ iso at every node of the grid (spacing
/// `spacing` from box.lo, the grid method's) on a path of face neighbours
/// from the node nearest one to the node nearest the other (node_path): the
/// grid then has the two points in one piece, nodes inside joined by edges
/// the surface does not cross. A piece thinner than the grid resolves
/// (its nodes outside) keeps its points apart, each casting its rays, and
/// so seeded, or reported missing. On a field infinite on its skeleton
/// every point is a region of its own: f = +inf marks an inverse
/// primitive's skeleton whatever its weight (docs/field.md), so f ≥ iso at
/// the nodes between two points does not show them in one piece (along a
/// capsule carved on its axis, the carving's points would join the
/// capsule's, and the rays from them that find the cavity would not be
/// cast).
std::vector<std::int64_t> point_regions(const ImplicitField& field, double iso, const Box3& box,
                                        const SkeletonScan& scan, double spacing, unsigned threads) {
  const std::vector<Vec3>& points = field.skeleton_points;
  if (field.infinite_on_skeleton) {
    std::vector<std::int64_t> region(points.size(), -1);
    for (std::size_t k = 0; k < points.size(); ++k)
      if (scan.inside[k]) region[k] = std::int64_t(k);
    return region;
  }
  // Each point's nearest earlier point inside within reach, through a hash
  // grid of cells `reach` wide.
  std::vector<std::int64_t> nearest(points.size(), -1);
  const double reach = region_link_reach * spacing;
  std::map<Cell, std::vector<std::size_t>> cells;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (!scan.inside[k]) continue;
    const auto [i, j, l] = cell_of(points[k], box.lo, reach);
    double best = std::numeric_limits<double>::infinity();
    for (long long a = i - 1; a <= i + 1; ++a)
      for (long long b = j - 1; b <= j + 1; ++b)
        for (long long c = l - 1; c <= l + 1; ++c) {
          const auto found = cells.find({a, b, c});
          if (found == cells.end()) continue;
          for (const std::size_t earlier : found->second) {
            const double distance = (points[earlier] - points[k]).norm();
            if (distance > reach) continue;
            if (distance < best || (distance == best && std::int64_t(earlier) < nearest[k]))
              best = distance, nearest[k] = std::int64_t(earlier);
          }
        }
    cells[{i, j, l}].push_back(k);
  }
  // Each link's grid nodes, then each node needed evaluated once, on
  // `threads` threads into its own slot.
  std::vector<std::vector<Cell>> paths(points.size());
  std::map<Cell, std::size_t> node_index;
  std::vector<Cell> nodes;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (nearest[k] < 0) continue;
    paths[k] = node_path(points[std::size_t(nearest[k])], points[k], box.lo, spacing);
    for (const Cell& node : paths[k])
      if (node_index.emplace(node, nodes.size()).second) nodes.push_back(node);
  }
  std::vector<char> node_inside(nodes.size(), 0);
  detail::parallel_for(
      nodes.size(),
      [&](std::size_t n) {
        const auto [i, j, l] = nodes[n];
        const Vec3 q = box.lo + spacing * Vec3(double(i), double(j), double(l));
        node_inside[n] = field.reaches ? field.reaches(q, iso) : field.value(q) >= iso;
      },
      64, threads);
  std::vector<char> joined(points.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (nearest[k] < 0) continue;
    joined[k] = std::all_of(paths[k].begin(), paths[k].end(),
                            [&](const Cell& node) { return node_inside[node_index.at(node)] != 0; });
  }
  std::vector<std::int64_t> region(points.size(), -1);
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (!scan.inside[k]) continue;
    region[k] = joined[k] ? region[std::size_t(nearest[k])] : std::int64_t(k);
  }
  return region;
}

}  // namespace

std::vector<Vec3> surface_seeds(const ImplicitField& field, double iso, const Box3& box,
                                const SurfaceSeedOptions& options) {
  const unsigned threads = options.threads == 0 ? detail::parallel_threads() : options.threads;
  const SkeletonScan scan = scan_skeleton(field, iso, box, options, threads);
  std::vector<Vec3> sources;
  for (const std::size_t k : scan.sources) sources.push_back(field.skeleton_points[k]);
  const std::vector<std::vector<Vec3>> crossings = cast_rays(field, iso, box, sources, options, threads);
  if (scan.fatal) std::rethrow_exception(scan.fatal);
  SeedGrid grid(box.lo, options.separation * options.spacing);
  std::vector<Vec3> seeds;
  for (const std::vector<Vec3>& found : crossings) grid.add_from_one_source(found, seeds);
  check_some_surface(scan, iso);
  return seeds;
}

RegionSeeds region_seeds(const ImplicitField& field, double iso, const Box3& box, const SurfaceSeedOptions& options) {
  const unsigned threads = options.threads == 0 ? detail::parallel_threads() : options.threads;
  const SkeletonScan scan = scan_skeleton(field, iso, box, options, threads);
  const std::vector<std::int64_t> region = point_regions(field, iso, box, scan, options.spacing, threads);
  RegionSeeds result;
  std::vector<Vec3> firsts;
  std::set<std::int64_t> seeded;
  for (const std::size_t k : scan.sources) {
    const Vec3& p = field.skeleton_points[k];
    (seeded.insert(region[k]).second ? firsts : result.deferred).push_back(p);
  }
  const std::vector<std::vector<Vec3>> crossings = cast_rays(field, iso, box, firsts, options, threads);
  if (scan.fatal) std::rethrow_exception(scan.fatal);
  SeedGrid grid(box.lo, options.separation * options.spacing);
  for (const std::vector<Vec3>& found : crossings) grid.add_from_one_source(found, result.seeds);
  check_some_surface(scan, iso);
  return result;
}

std::vector<Vec3> seeds_from_points(const ImplicitField& field, double iso, const Box3& box,
                                    const std::vector<Vec3>& points, const std::vector<Vec3>& existing,
                                    const SurfaceSeedOptions& options) {
  const unsigned threads = options.threads == 0 ? detail::parallel_threads() : options.threads;
  const std::vector<std::vector<Vec3>> crossings = cast_rays(field, iso, box, points, options, threads);
  SeedGrid grid(box.lo, options.separation * options.spacing);
  for (const Vec3& q : existing) grid.remember(q);
  std::vector<Vec3> seeds;
  for (const std::vector<Vec3>& found : crossings) grid.add_from_one_source(found, seeds);
  return seeds;
}

}  // namespace skelconv
