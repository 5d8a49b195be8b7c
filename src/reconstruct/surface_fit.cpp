// Implementation of skelconv/reconstruct/surface_fit.hpp.
#include "skelconv/reconstruct/surface_fit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "../detail/parallel_for.hpp"
#include "level_test.hpp"

namespace skelconv::reconstruct {
namespace {

bool is_closed(const Branch& b) { return b.first_node == b.last_node; }

/// How many branch ends each node has (a free end has one).
std::map<std::int32_t, int> end_uses(const std::vector<Branch>& branches) {
  std::map<std::int32_t, int> uses;
  for (const Branch& b : branches) ++uses[b.first_node], ++uses[b.last_node];
  return uses;
}

/// True when the radius falls faster than `max_slope` from `inner` to `end`.
bool is_cap_step(const Vec4& inner, const Vec4& end, double max_slope) {
  const double length = (end.head<3>() - inner.head<3>()).norm();
  return inner.w() - end.w() > max_slope * length;
}

/// True when the step from `middle` to `end` turns back from the step
/// from `before` to `middle` (negative dot product: more than 90°).
bool is_hook(const Vec4& before, const Vec4& middle, const Vec4& end) {
  return (end.head<3>() - middle.head<3>()).dot(middle.head<3>() - before.head<3>()) < 0.0;
}

/// Unit chord from the point about one end radius back along `points`
/// (read from the back) to the last point.
Vec3 end_tangent(const std::vector<Vec4>& points) {
  const Vec4& end = points.back();
  std::size_t k = points.size() - 2;
  while (k > 0 && (points[k].head<3>() - end.head<3>()).norm() < end.w()) --k;
  const Vec3 chord = end.head<3>() - points[k].head<3>();
  return chord.norm() > 0.0 ? Vec3(chord.normalized()) : Vec3::Zero();
}

/// The unit tangent of a branch at point i (central difference; cyclic on
/// a closed branch, whose first point repeats as the last).
Vec3 tangent_at(const Branch& b, std::size_t i) {
  const auto& p = b.points;
  const std::size_t n = p.size();
  std::size_t before = i == 0 ? 0 : i - 1, after = std::min(i + 1, n - 1);
  if (is_closed(b) && n > 2 && (i == 0 || i == n - 1)) before = n - 2, after = 1;
  const Vec3 d = p[after].head<3>() - p[before].head<3>();
  return d.norm() > 0.0 ? Vec3(d.normalized()) : Vec3::UnitX();
}

/// `count` unit vectors evenly around the plane normal to `tangent`.
std::vector<Vec3> normal_ring(const Vec3& tangent, int count) {
  const Vec3 helper = std::abs(tangent.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = tangent.cross(helper).normalized(), v = tangent.cross(u);
  std::vector<Vec3> ring;
  for (int k = 0; k < count; ++k) {
    const double a = 2.0 * std::numbers::pi * k / count;
    ring.push_back(std::cos(a) * u + std::sin(a) * v);
  }
  return ring;
}

/// Distance from `origin` along `direction` to where f falls to iso
/// (`level`): steps of `step` out to `reach`, then bisection. 0 if f(origin)
/// < iso; `reach` if f stays above iso that far.
double crossing(const LevelTest& level, const Vec3& origin, const Vec3& direction, double step, double reach,
                int bisection_steps) {
  if (!level.at_or_above(origin)) return 0.0;
  double inside = 0.0, outside = step;
  while (level.at_or_above(origin + outside * direction)) {
    inside = outside;
    outside += step;
    if (outside > reach) return reach;
  }
  for (int k = 0; k < bisection_steps; ++k) {
    const double middle = 0.5 * (inside + outside);
    (level.at_or_above(origin + middle * direction) ? inside : outside) = middle;
  }
  return 0.5 * (inside + outside);
}

/// What the fit measures on the input once: per point, the rays of its ring
/// and their input distances (negative: missed); per extended end, the
/// distance to the input's tip along the end tangent.
struct Targets {
  std::vector<std::vector<std::vector<Vec3>>> rays;         // [branch][point][ray]
  std::vector<std::vector<std::vector<double>>> distances;  // same shape
};

Targets measure_input(const std::vector<Branch>& branches, const SurfaceQuery& input, int directions) {
  Targets t;
  for (const Branch& b : branches) {
    auto& rays = t.rays.emplace_back();
    auto& distances = t.distances.emplace_back();
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      rays.push_back(normal_ring(tangent_at(b, i), directions));
      auto& d = distances.emplace_back();
      for (const Vec3& ray : rays.back()) d.push_back(input.ray_distance(b.points[i].head<3>(), ray).value_or(-1.0));
    }
  }
  return t;
}

bool is_extension(const Branch& b, std::size_t i) {
  return (i == 0 && b.extended_first) || (i + 1 == b.points.size() && b.extended_last);
}

/// The points of `b` within their own radius (arc length) of a free end
/// or of a junction: at a free end their normal rays meet the cap or feel
/// the end's falloff; at a junction they run down the other branches, and
/// the radius fitted there runs away (measured on the tree: 1.2 for a
/// known 0.19, with the next points shrunk to 0.05 to make up). Their
/// radius is not fitted but copied from the first point past that zone;
/// a junction's bulge is the sum blend's. `uses` counts the branch ends at
/// each node. Returns per point the index to copy from (itself if fitted).
std::vector<std::size_t> radius_sources(const Branch& b, const std::map<std::int32_t, int>& uses) {
  const std::size_t n = b.points.size();
  std::vector<std::size_t> source(n);
  for (std::size_t i = 0; i < n; ++i) source[i] = i;
  // start: the first point of the zone (1 after an extension point).
  const auto walk = [&](bool from_front, std::size_t start) {
    const auto at = [&](std::size_t k) -> std::size_t { return from_front ? k : n - 1 - k; };
    double arc = 0.0;
    std::size_t k = start;
    std::vector<std::size_t> zone;
    for (; k + 1 < n; ++k) {
      if (k > start) arc += (b.points[at(k)].head<3>() - b.points[at(k - 1)].head<3>()).norm();
      if (arc >= b.points[at(k)].w()) break;
      zone.push_back(at(k));
    }
    for (std::size_t z : zone) source[z] = at(k);
  };
  if (n <= 3) return source;
  if (b.extended_first) walk(true, 1);
  else if (uses.at(b.first_node) >= 3) walk(true, 0);
  if (b.extended_last) walk(false, 1);
  else if (uses.at(b.last_node) >= 3) walk(false, 0);
  return source;
}

/// True when every ray of a cross-section meets the input, the farthest
/// within `tube_ratio` × the nearest: a tube, not a junction (where rays run
/// down other branches) nor a cap.
bool is_tube_section(const std::vector<double>& input_distances, double tube_ratio) {
  if (input_distances.empty()) return false;
  const auto [lo, hi] = std::minmax_element(input_distances.begin(), input_distances.end());
  return *lo > 0.0 && *hi <= tube_ratio * *lo;
}

/// How one point should change: its radius × `factor`, its centre + `shift`.
struct PointUpdate {
  double factor = 1.0;
  Vec3 shift = Vec3::Zero();
  bool informed = false;  ///< false: no usable crossing, the point stays
};

/// The update of one point from its rays' input distances `target` and the
/// reconstructed surface's `current` ones (0: the centre is outside it).
/// A tube section is fitted in its two lowest harmonics: the radius by the
/// ratio of the mean distances, the centre by the first harmonic of the
/// difference (moving the skeleton by e moves the surface by about e, so
/// the ray along u_k crosses it e·u_k farther; over K evenly spread rays
/// Σ (e·u_k) u_k = (K/2) e, hence e = (2/K) Σ (target_k − current_k) u_k).
/// Elsewhere only the radius, by the ratio of the nearest crossings.
PointUpdate point_update(const std::vector<Vec3>& rays, const std::vector<double>& target,
                         const std::vector<double>& current, double radius, const FitOptions& o) {
  PointUpdate u;
  if (is_tube_section(target, o.tube_ratio) &&
      std::all_of(current.begin(), current.end(), [](double d) { return d > 0.0; })) {
    double sum_target = 0.0, sum_current = 0.0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      sum_target += target[k], sum_current += current[k];
      u.shift += (target[k] - current[k]) * rays[k];
    }
    u.shift *= 2.0 / double(rays.size());
    if (u.shift.norm() > o.largest_shift * radius) u.shift *= o.largest_shift * radius / u.shift.norm();
    u.factor = sum_target / sum_current;
    u.informed = true;
  } else {
    double nearest_target = INFINITY, nearest_current = INFINITY;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      if (target[k] < 0.0) continue;
      nearest_target = std::min(nearest_target, target[k]);
      nearest_current = std::min(nearest_current, current[k]);
    }
    // No input crossing, or the centre is outside the current surface (a
    // larger radius would not bring it in: SCALIS fields fall as 1/τ near a
    // short skeleton): no information, the point stays.
    if (!std::isfinite(nearest_target) || !(nearest_current > 0.0)) return u;
    u.factor = nearest_target / nearest_current;
    u.informed = true;
  }
  u.factor = std::clamp(u.factor, 1.0 / o.largest_step, o.largest_step);
  return u;
}

/// One Jacobi round over the points (radii, and centres of tube sections);
/// returns the largest relative change of a radius.
double update_points(std::vector<Branch>& branches, const Targets& targets, const LevelTest& level,
                     const FitOptions& o) {
  std::vector<Branch> updated = branches;
  const auto uses = end_uses(branches);
  std::vector<std::vector<std::size_t>> sources;
  // The points fitted, as (branch, point): each one's update reads only
  // `branches` and the field, so they are computed on every core, then
  // applied in this order.
  std::vector<std::pair<std::size_t, std::size_t>> fitted;
  for (std::size_t bi = 0; bi < branches.size(); ++bi) {
    sources.push_back(radius_sources(branches[bi], uses));
    for (std::size_t i = 0; i < branches[bi].points.size(); ++i)
      if (!is_extension(branches[bi], i) && sources[bi][i] == i) fitted.emplace_back(bi, i);
  }
  std::vector<PointUpdate> updates(fitted.size());
  detail::parallel_for(fitted.size(), [&](std::size_t n) {
    const auto [bi, i] = fitted[n];
    const Vec4& point = branches[bi].points[i];
    const auto& rays = targets.rays[bi][i];
    const auto& target = targets.distances[bi][i];
    std::vector<double> current(rays.size(), 0.0);
    for (std::size_t k = 0; k < rays.size(); ++k) {
      if (target[k] >= 0.0)
        current[k] = crossing(level, point.head<3>(), rays[k], 0.25 * point.w(), 4.0 * target[k], o.bisection_steps);
    }
    updates[n] = point_update(rays, target, current, point.w(), o);
  });
  double largest = 0.0;
  std::size_t next = 0;  // the first of `fitted` on this branch or after
  for (std::size_t bi = 0; bi < branches.size(); ++bi) {
    const Branch& b = branches[bi];
    const std::vector<std::size_t>& source = sources[bi];
    for (; next < fitted.size() && fitted[next].first == bi; ++next) {
      const std::size_t i = fitted[next].second;
      const PointUpdate& u = updates[next];
      if (!u.informed) continue;
      updated[bi].points[i].w() *= u.factor;
      updated[bi].points[i].head<3>() += u.shift;
      largest = std::max(largest, std::abs(u.factor - 1.0));
    }
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      if (source[i] != i) updated[bi].points[i].w() = updated[bi].points[source[i]].w();
    }
    // The closing point of a closed branch is its first point again.
    if (is_closed(b) && b.points.size() > 1) updated[bi].points.back() = updated[bi].points.front();
  }
  branches = std::move(updated);
  return largest;
}

/// Moves every extension point so that the reconstructed surface reaches
/// the input's tip along the end tangent; returns the largest move.
double update_extensions(std::vector<Branch>& branches, const SurfaceQuery& input, const LevelTest& level,
                         const FitOptions& o) {
  double largest = 0.0;
  const auto fit_end = [&](Vec4& tip, const Vec4& end) {
    Vec3 direction = tip.head<3>() - end.head<3>();
    const double length = direction.norm();
    if (length == 0.0) return;
    direction /= length;
    const auto target = input.ray_distance(end.head<3>(), direction);
    if (!target) return;
    const double reached = crossing(level, end.head<3>(), direction, 0.25 * end.w(), 4.0 * *target, o.bisection_steps);
    if (reached == 0.0) return;  // the end itself is outside: no information
    const double moved = std::max(0.0, length + *target - reached) - length;
    tip.head<3>() = end.head<3>() + (length + moved) * direction;
    tip.w() = end.w();
    largest = std::max(largest, std::abs(moved));
  };
  for (Branch& b : branches) {
    const std::size_t n = b.points.size();
    if (b.extended_last && n >= 2) fit_end(b.points[n - 1], b.points[n - 2]);
    if (b.extended_first && n >= 2) fit_end(b.points[0], b.points[1]);
  }
  return largest;
}

}  // namespace

std::vector<Branch> trim_caps(std::vector<Branch> branches, double max_slope) {
  const auto uses = end_uses(branches);
  for (Branch& b : branches) {
    if (is_closed(b)) continue;
    auto& p = b.points;
    const auto last_is_trimmed = [&] {
      const std::size_t n = p.size();
      return is_cap_step(p[n - 2], p[n - 1], max_slope) || (n > 2 && is_hook(p[n - 3], p[n - 2], p[n - 1]));
    };
    const auto first_is_trimmed = [&] {
      return is_cap_step(p[1], p[0], max_slope) || (p.size() > 2 && is_hook(p[2], p[1], p[0]));
    };
    if (uses.at(b.last_node) == 1) {
      while (p.size() > 2 && last_is_trimmed()) p.pop_back();
    }
    if (uses.at(b.first_node) == 1) {
      while (p.size() > 2 && first_is_trimmed()) p.erase(p.begin());
    }
  }
  return branches;
}

std::vector<Branch> extend_free_ends(std::vector<Branch> branches, double factor) {
  const auto uses = end_uses(branches);
  const auto extension = [factor](std::vector<Vec4> points) {
    const Vec4& end = points.back();
    const Vec3 tip = end.head<3>() + factor * end.w() * end_tangent(points);
    return Vec4(tip.x(), tip.y(), tip.z(), end.w());
  };
  for (Branch& b : branches) {
    if (factor <= 0.0 || b.points.size() < 2 || is_closed(b)) continue;
    if (uses.at(b.last_node) == 1 && !b.extended_last) b.points.push_back(extension(b.points)), b.extended_last = true;
    if (uses.at(b.first_node) == 1 && !b.extended_first) {
      std::vector<Vec4> reversed(b.points.rbegin(), b.points.rend());
      b.points.insert(b.points.begin(), extension(reversed));
      b.extended_first = true;
    }
  }
  return branches;
}

std::vector<Branch> fit_to_surface(std::vector<Branch> branches, const SurfaceQuery& input, const BranchField& field_of,
                                   const FitOptions& o, FitReport* report) {
  FitReport r;
  for (int round = 0; round < o.iterations; ++round) {
    {
      // The input is measured again each round: the rays leave from the
      // moved centres.
      const Targets targets = measure_input(branches, input, o.directions);
      const Skeleton skeleton = field_of(branches);
      r.largest_radius_change = update_points(branches, targets, LevelTest(skeleton), o);
    }
    const Skeleton skeleton = field_of(branches);
    r.largest_tip_change = update_extensions(branches, input, LevelTest(skeleton), o);
  }
  if (report != nullptr) *report = r;
  return branches;
}

}  // namespace skelconv::reconstruct
