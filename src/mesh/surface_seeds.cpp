// Implementation of skelconv/mesh/surface_seeds.hpp.
#include "skelconv/mesh/surface_seeds.hpp"

#include <cmath>
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
      cells_[cell_of(q, origin_, radius_)].push_back(q);
      seeds.push_back(q);
    }
  }

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

}  // namespace

std::vector<Vec3> surface_seeds(const ImplicitField& field, double iso, const Box3& box,
                                const SurfaceSeedOptions& options) {
  const Vec3 directions[] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(),
                             -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  std::set<Cell> used_cells;
  SeedGrid grid(box.lo, options.separation * options.spacing);
  std::vector<Vec3> seeds;
  double largest = -std::numeric_limits<double>::infinity();
  Vec3 largest_at = field.skeleton_points.front();
  std::optional<EvaluationError> first_failure;
  // The field's values and the rays are computed on every core, each
  // skeleton point's into its own slot, and taken in the points' order: the
  // seeds, and the error thrown, are the one-thread loop's. A failure is
  // kept with its point, and thrown where that loop would have met it.
  const std::vector<Vec3>& points = field.skeleton_points;
  std::vector<double> values(points.size(), 0.0);
  std::vector<std::exception_ptr> value_failures(points.size());
  const unsigned threads = options.threads == 0 ? detail::parallel_threads() : options.threads;
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
  // The points that cast rays, up to the first failure that is fatal.
  std::vector<std::size_t> sources;
  std::exception_ptr fatal;
  for (std::size_t k = 0; k < points.size() && !fatal; ++k) {
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
        if (!field.infinite_on_skeleton) fatal = value_failures[k];
        else if (!first_failure) first_failure = error;
      } catch (...) {
        fatal = value_failures[k];
      }
      continue;
    }
    const double f = values[k];
    if (f > largest) std::tie(largest, largest_at) = std::make_tuple(f, p);
    if (!(f > iso)) continue;
    if (!used_cells.insert(cell_of(p, box.lo, options.spacing)).second) continue;
    sources.push_back(k);
  }
  std::vector<std::vector<Vec3>> crossings(sources.size());
  const auto cast_rays = [&](std::size_t n) {
    for (const Vec3& d : directions) {
      // A ray in the plane of an inverse-kernel polygon may land on one of its
      // edges or vertices (f infinite, refused as above): that ray gives no
      // seed; the other rays and skeleton points seed the component.
      try {
        if (auto crossing = ray_crossing(field, iso, box, points[sources[n]], d, options))
          crossings[n].push_back(*crossing);
      } catch (const EvaluationError&) {
        if (!field.infinite_on_skeleton) throw;
      }
    }
  };
  detail::parallel_for(sources.size(), cast_rays, 16, threads);
  if (fatal) std::rethrow_exception(fatal);
  for (const std::vector<Vec3>& found : crossings) grid.add_from_one_source(found, seeds);
  if (largest == -std::numeric_limits<double>::infinity() && first_failure) throw *first_failure;
  if (largest <= iso) {
    throw InputError(fmt::format("no surface at iso {}: the field is below it on the whole skeleton "
                                 "(largest value {:.6g} at ({}, {}, {}))",
                                 iso, largest, largest_at.x(), largest_at.y(), largest_at.z()),
                     "--iso");
  }
  return seeds;
}

}  // namespace skelconv
