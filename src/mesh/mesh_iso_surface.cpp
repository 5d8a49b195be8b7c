// Implementation of skelconv/mesh/mesh_iso_surface.hpp.
#include "skelconv/mesh/mesh_iso_surface.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <cmath>
#include <limits>
#include <type_traits>

#include <fmt/format.h>

#include "cgal_surface_mesher.hpp"
#include "grid_surface_mesher.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/mesh/surface_projection.hpp"
#include "skelconv/mesh/surface_seeds.hpp"
#include "../detail/parallel_for.hpp"
#include "../detail/tick_clock.hpp"

namespace skelconv {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Counts and times the field's evaluations, and reports progress (during
/// refinement) at most once per options.progress_interval seconds.
class FieldMeter {
 public:
  FieldMeter(const ImplicitField& field, const MeshOptions& options) : field_(field), options_(options) {}

  /// `field_` with every call metered, its coarse field's too; valid while
  /// *this lives.
  ImplicitField metered() { return metered(field_); }
  void report_progress(bool on) { reporting_ = on && bool(options_.progress); }
  std::size_t evaluations() const { return evaluations_.load(); }
  double seconds() const { return clock_.seconds(ticks_.load()); }

 private:
  /// `field` (field_ or a field it holds) with every call metered.
  ImplicitField metered(const ImplicitField& field) {
    ImplicitField m = field;
    m.value = [this, &field](const Vec3& p) { return measure([&] { return field.value(p); }); };
    m.value_and_gradient = [this, &field](const Vec3& p) { return measure([&] { return field.value_and_gradient(p); }); };
    if (field.reaches)
      m.reaches = [this, &field](const Vec3& p, double level) { return measure([&] { return field.reaches(p, level); }); };
    m.value_and_gradient_near = metered_near(field.value_and_gradient_near);
    m.value_near = metered_near(field.value_near);
    if (field.coarse) m.coarse = std::make_shared<const ImplicitField>(metered(*field.coarse));
    return m;
  }

  /// A field's `..._near` metered: the shared work (choosing for the ball)
  /// timed as the field's, each point's evaluation counted. Unset if unset.
  template <class Sample>
  using Near = std::function<std::function<Sample(const Vec3&)>(const Vec3& centre, double radius)>;
  template <class Sample>
  Near<Sample> metered_near(const Near<Sample>& near_of) {
    if (!near_of) return {};
    return [this, &near_of](const Vec3& centre, double radius) {
      const detail::TickClock::Ticks start = detail::TickClock::now();
      auto near = near_of(centre, radius);
      ticks_.fetch_add(detail::TickClock::now() - start, std::memory_order_relaxed);
      return std::function<Sample(const Vec3&)>(
          [this, near = std::move(near)](const Vec3& p) { return measure([&] { return near(p); }); });
    };
  }

  /// The clock is read twice per evaluation: the tick counter, whose reads
  /// cost less than steady_clock's (tick_clock.hpp; ~3% of the grid
  /// method's CPU time on Zanni's ant with steady_clock). The progress
  /// check reads steady_clock once per `progress_stride` evaluations.
  template <class Evaluate>
  std::invoke_result_t<Evaluate> measure(Evaluate evaluate) {
    const detail::TickClock::Ticks start = detail::TickClock::now();
    auto result = evaluate();
    ticks_.fetch_add(detail::TickClock::now() - start, std::memory_order_relaxed);
    const std::size_t evaluations = evaluations_.fetch_add(1, std::memory_order_relaxed) + 1;
    if (reporting_ && evaluations % progress_stride == 0) {
      // The seeds are cast on every core: one thread reports at a time.
      const std::unique_lock<std::mutex> lock(progress_mutex_, std::try_to_lock);
      const Clock::time_point end = Clock::now();
      if (lock.owns_lock() && std::chrono::duration<double>(end - last_report_).count() >= options_.progress_interval) {
        last_report_ = end;
        options_.progress(MeshProgress{evaluations, seconds_since(begin_)});
      }
    }
    return result;
  }

  static constexpr std::size_t progress_stride = 256;  ///< a few hundred µs of evaluations
  const ImplicitField& field_;
  const MeshOptions& options_;
  std::atomic<std::size_t> evaluations_{0};
  detail::TickClock clock_;
  std::atomic<detail::TickClock::Ticks> ticks_{0};  ///< in the field, summed over the threads
  std::mutex progress_mutex_;
  bool reporting_ = false;
  Clock::time_point begin_ = Clock::now();
  Clock::time_point last_report_ = Clock::now();
};

void check_options(const ImplicitField& field, const MeshOptions& options) {
  if (!std::isfinite(options.iso)) throw InputError(fmt::format("must be a finite number, got {}", options.iso), "--iso");
  if (options.iso <= field.far_field) {
    throw InputError(fmt::format("the surface f = {} is unbounded: the field tends to {} far from the skeleton, "
                                 "so the iso must be above {}",
                                 options.iso, field.far_field, field.far_field),
                     "--iso");
  }
  // Below the smallest normal double, f − iso and the gradients near the
  // surface are subnormal or zero: the seeds' bisection, the grid's signs and
  // the projection's Newton steps have no digits left to work with.
  if (std::abs(options.iso) < std::numeric_limits<double>::min()) {
    throw InputError(fmt::format("must be at least {} (the smallest normal double; the field near a smaller "
                                 "level has no precision left), got {}",
                                 std::numeric_limits<double>::min(), options.iso),
                     "--iso");
  }
  for (const auto& [value, name] : {std::pair{options.size, "--size"}, std::pair{options.distance, "--distance"}}) {
    if (value && !(std::isfinite(*value) && *value > 0)) {
      throw InputError(fmt::format("must be a finite number > 0, got {}", *value), name);
    }
  }
  if (field.skeleton_points.empty()) throw InputError("the skeleton is empty: there is no surface to mesh");
}

/// About how many triangles CGAL makes of a surface inside `box` at facet
/// distance d whatever the facet size: the box's surface area over
/// (diagonal × d). A facet of circumradius r on a surface of curvature
/// radius ρ strays about r²/(2ρ) from it, so d allows r ≈ √(2ρd); a ball
/// (ρ = diagonal / (2√3)) then makes about 0.7 times this estimate, and
/// shapes with thinner parts more (twice, for two SCALIS segments of radii
/// 0.2–0.6 across a diagonal of 6.8). Like estimate_triangles, an order of
/// magnitude that refuses absurd distances before the work starts.
double estimate_triangles_for_distance(const Box3& box, double distance) {
  const double box_area = estimate_triangles(box, 1.0);  // area / h² at h = 1
  return box_area / (box.diagonal() * distance);
}

/// "about N" for a triangle estimate; an estimate that overflowed (a size of
/// 1e-300: area / h² is inf) is "more than 1e+308", not "about inf".
std::string about_count(double estimate) {
  if (std::isfinite(estimate)) return fmt::format("about {:.2g}", estimate);
  return fmt::format("more than {:.2g}", std::numeric_limits<double>::max());
}

/// Refuses a facet size, or for CGAL a facet distance, whose mesh would
/// exceed options.max_triangles.
void check_output_size(const Box3& box, double size, double distance, const MeshOptions& options) {
  const double estimate = estimate_triangles(box, size);
  if (!(estimate <= double(options.max_triangles)) && !options.size) {
    // The user gave no --size: the limit is what they chose. The estimate
    // goes as 1/h², so the size that meets it is h·√(estimate / limit),
    // shown rounded up to 3 digits (rounded down it would be refused).
    const double needed = size * std::sqrt(estimate / double(options.max_triangles));
    const double digit = std::pow(10.0, std::floor(std::log10(needed)) - 2);
    if (!(needed <= box.diagonal())) {
      throw InputError(fmt::format("{} triangles are fewer than any facet size makes: the largest, the diagonal {:g} "
                                   "of the box that holds the surface, makes {}; raise --max-triangles",
                                   options.max_triangles, box.diagonal(),
                                   about_count(estimate_triangles(box, box.diagonal()))),
                       "--max-triangles");
    }
    throw InputError(fmt::format("the default facet size {:g} (the diagonal {:g} of the box that holds the surface "
                                 "/ 50) makes {} triangles, more than the limit {}: raise --max-triangles, or "
                                 "choose a --size of at least {:.3g}",
                                 size, box.diagonal(), about_count(estimate), options.max_triangles,
                                 std::ceil(needed / digit) * digit),
                     "--max-triangles");
  }
  if (!(estimate <= double(options.max_triangles))) {
    throw InputError(fmt::format("a facet size of {:g} in a box of diagonal {:g} makes {} triangles, "
                                 "more than the limit {} (--max-triangles): choose a larger --size, or raise "
                                 "--max-triangles if the memory and time are there",
                                 size, box.diagonal(), about_count(estimate), options.max_triangles),
                     "--size");
  }
  if (options.method != MeshMethod::cgal) return;  // the grid has no facet distance
  const double by_distance = estimate_triangles_for_distance(box, distance);
  if (!(by_distance <= double(options.max_triangles))) {
    throw InputError(fmt::format("a facet distance of {:g} in a box of diagonal {:g} makes {} "
                                 "triangles, more than the limit {} (--max-triangles): choose a larger --distance, "
                                 "or raise --max-triangles if the memory and time are there",
                                 distance, box.diagonal(), about_count(by_distance), options.max_triangles),
                     "--distance");
  }
}

/// CGAL's intersections are bisected to the facet distance over this: its
/// distance test then sees the surface, not the bisection. The grid's
/// vertices are held to the voxel size over the same.
constexpr double accuracy_divisor = 100.0;

/// Refuses a surface so far from the origin that doubles there are too
/// coarse for the mesher's accuracy: CGAL places the surface's points to
/// the facet distance / accuracy_divisor, the grid its vertices to a
/// fraction of a voxel, taken as the size / accuracy_divisor. Below 4 spacings per that accuracy, CGAL's
/// bisection and distance test never settle (a ball of radius 1 at
/// 7e11 from the origin refined without end) and the grid's vertices are
/// rounded to steps a visible part of a voxel.
void check_coordinate_precision(const Box3& box, double size, double distance, const MeshOptions& options) {
  const bool cgal = options.method == MeshMethod::cgal;
  const double accuracy = (cgal ? distance : size) / accuracy_divisor;
  const double magnitude = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  const double spacing = std::nextafter(magnitude, INFINITY) - magnitude;
  if (spacing <= accuracy / 4) return;
  // 400 spacings, rounded up to 3 digits (rounded down it would be refused).
  const double needed = 400 * spacing, digit = std::pow(10.0, std::floor(std::log10(needed)) - 2);
  throw InputError(fmt::format("the surface lies up to {:.3g} from the origin, where doubles are {:.3g} apart: too "
                               "coarse to place the mesh's points to {:.3g} (a hundredth of the {} {:.3g}); move "
                               "the skeleton nearer the origin, or choose a {} of at least {:.3g}",
                               magnitude, spacing, accuracy, cgal ? "facet distance" : "voxel size",
                               cgal ? distance : size, cgal ? "--distance" : "--size", std::ceil(needed / digit) * digit),
                   cgal ? "--distance" : "--size");
}

/// How far an enclosure must stay from the iso, relative to it, before the
/// grid method trusts its sign: the enclosure bounds the exact field, the
/// sampled values carry the closed forms' rounding (≤ 1e-13 relative,
/// docs/accuracy.md) and are rounded to float, where a level below float's
/// smallest normal (~1.2e-38) could flush to a zero of the wrong side. 1e-9
/// covers both with a wide margin and costs no block in practice.
constexpr double enclosure_margin = 1e-9;
/// How closely the grid method's seeds are bracketed, in voxels (see
/// mesh_iso_surface): well inside the 3 × 3 × 3 cells sampled around each.
constexpr double grid_seed_bracket = 0.25;
/// See level_sign: boxes whose centre lies within this many half diagonals
/// of the surface (to first order) are sampled without an enclosure. The
/// mesher's coarse enclosures (implicit_field.cpp) of a sum of infinite-
/// support kernels are several times wider than the field's variation over
/// the box, so a box this close to the surface is rarely proven empty.
constexpr double first_order_reach = 8.0;

/// The grid method's sign_over (grid_surface_mesher.hpp) from the field's
/// enclosure: the sign of iso − f over a box, or 0 when not proven.
std::function<int(const Eigen::AlignedBox3d&)> level_sign(const ImplicitField& field, double iso) {
  if (!field.enclosure) return {};
  return [&field, iso](const Eigen::AlignedBox3d& box) {
    try {
      // An enclosure costs about a hundred evaluations, and cannot succeed
      // where the surface crosses the box: when the first-order distance
      // from the centre to the surface, |f − c| / |∇f|, is within the box's
      // half diagonal times first_order_reach, the box is sampled without
      // trying. Only speed depends on this guess; what is proven, and
      // hence the mesh, does not.
      const FieldSample centre = field.value_and_gradient(box.center());
      const double half_diagonal = 0.5 * box.sizes().norm();
      if (std::abs(centre.value - iso) <= first_order_reach * centre.gradient.norm() * half_diagonal) return 0;
      const auto [lo, hi] = field.enclosure(box);
      const double margin = enclosure_margin * std::abs(iso);
      if (hi < iso - margin) return 1;  // f below the iso: outside, level > 0
      if (lo > iso + margin) return -1;
    } catch (const std::exception&) {
      // No claim: the block is sampled.
    }
    return 0;
  };
}

/// How far, in voxels, a grid node on an inverse primitive's skeleton looks
/// for the field's side (see grid_level): far below what the grid resolves.
constexpr double skeleton_node_nudge = 1e-3;

/// The grid method's level iso − f. f = +inf marks a point on an inverse
/// primitive's skeleton whatever the primitive's weight (docs/field.md), so
/// a node there would count as inside even on a carving (negative-weight)
/// primitive, where f tends to −inf: such a node takes the level of a point
/// `skeleton_node_nudge` voxels away instead, which is on the side the
/// field tends to (two fixed directions, in case the skeleton runs along
/// the first).
std::function<double(const Vec3&)> grid_level(const ImplicitField& field, double iso, double voxel,
                                              std::function<double(const Vec3&)> value = {}) {
  if (!value) value = field.value;
  return [&field, iso, voxel, value = std::move(value)](const Vec3& p) {
    const double f = value(p);
    if (!(f == std::numeric_limits<double>::infinity() && field.infinite_on_skeleton)) return iso - f;
    for (const Vec3& d : {Vec3(0.36, 0.48, 0.8), Vec3(-0.8, 0.36, 0.48)}) {
      const double near = field.value(p + skeleton_node_nudge * voxel * d);
      if (std::isfinite(near)) return iso - near;
    }
    return iso - f;
  };
}

/// How far from the iso, in units of the coarse field's error bound, a
/// coarse value f̃ must lie for the grid to take its sign: |f̃ − f| ≤ ε |f|
/// ≤ 2ε |f̃| (ε ≤ 1/2), so |iso − f̃| > 4ε |f̃| leaves |iso − f| > 2ε |f̃|
/// with the same sign, far more than the field's own error (a tolerance
/// below ε, plus rounding), whose value then has that sign too.
constexpr double coarse_sign_margin = 4.0;

/// grid_level from the coarse value `coarse` (ImplicitField::coarse) where
/// it decides the sign of iso − f (coarse_sign_margin), else from the field:
/// every node gets the sign the field's own value gives it, hence the same
/// cells, faces and triangles; the values, which only place the grid's
/// vertices before the projection moves them onto the surface, differ by
/// about the coarse field's error.
std::function<double(const Vec3&)> coarse_grid_level(const ImplicitField& field, double iso, double voxel,
                                                     std::function<double(const Vec3&)> coarse) {
  return [iso, margin = coarse_sign_margin * field.coarse_tolerance, coarse = std::move(coarse),
          fine = grid_level(field, iso, voxel)](const Vec3& p) {
    const double rough = coarse(p);
    if (std::isfinite(rough) && std::abs(iso - rough) > margin * std::abs(rough)) return iso - rough;
    return fine(p);
  };
}

/// The grid method's level: coarse_grid_level where the field has a coarse
/// field, else grid_level.
std::function<double(const Vec3&)> grid_level_of(const ImplicitField& field, double iso, double voxel) {
  if (field.coarse) return coarse_grid_level(field, iso, voxel, field.coarse->value);
  return grid_level(field, iso, voxel);
}

/// grid_level_of for points near `centre` (GridSurfaceRequest::level_near),
/// through ImplicitField::value_near (the coarse field's where there is
/// one; the few values it leaves to the field are evaluated alone); none
/// where the field has no value_near.
std::function<std::function<double(const Vec3&)>(const Vec3&, double)> grid_level_near(const ImplicitField& field,
                                                                                      double iso, double voxel) {
  if (field.coarse && field.coarse->value_near) {
    return [&field, iso, voxel](const Vec3& centre, double radius) {
      return coarse_grid_level(field, iso, voxel, field.coarse->value_near(centre, radius));
    };
  }
  if (!field.value_near) return {};
  return [&field, iso, voxel](const Vec3& centre, double radius) {
    return grid_level(field, iso, voxel, field.value_near(centre, radius));
  };
}

/// How far from a seed, in grid spacings, a vertex of the grid mesh shows
/// that the seed's part of the surface was meshed: the mesh of a part has a
/// vertex in every cell the surface crosses, within √3 spacings of any of its
/// points (a vertex moved by the projection stays within a spacing of it).
/// Twice that: the tip of a cone (a SCALIS radius 0), which no grid resolves,
/// ends a few spacings short of its seed and is not a lost part (at 2
/// spacings the test skeleton scalis_segments.json's tip was reported at
/// every --size).
constexpr double seed_coverage_reach = 4.0;

/// A mesh's vertices in a hash grid of cells `reach` wide, to ask whether
/// one lies within `reach` of a point.
class NearVertices {
 public:
  NearVertices(const std::vector<Vec3>& vertices, double reach) : vertices_(vertices), reach_(reach) {
    for (std::size_t v = 0; v < vertices.size(); ++v) cells_[cell_of(vertices[v])].push_back(v);
  }

  bool near(const Vec3& p) const {
    const Cell c = cell_of(p);
    for (long long i = c[0] - 1; i <= c[0] + 1; ++i)
      for (long long j = c[1] - 1; j <= c[1] + 1; ++j)
        for (long long k = c[2] - 1; k <= c[2] + 1; ++k) {
          const auto found = cells_.find({i, j, k});
          if (found == cells_.end()) continue;
          for (const std::size_t v : found->second)
            if ((vertices_[v] - p).norm() <= reach_) return true;
        }
    return false;
  }

 private:
  using Cell = std::array<long long, 3>;
  Cell cell_of(const Vec3& p) const {
    return {std::llround(std::floor(p.x() / reach_)), std::llround(std::floor(p.y() / reach_)),
            std::llround(std::floor(p.z() / reach_))};
  }

  const std::vector<Vec3>& vertices_;
  double reach_;
  std::map<Cell, std::vector<std::size_t>> cells_;
};

/// The parts of the surface no vertex of the grid mesh is near: the seeds
/// without a vertex within seed_coverage_reach spacings, grouped by
/// proximity (seeds within the same reach of a group's first seed), thickest
/// first. A part thinner than the spacing has no grid node inside it, and
/// OpenVDB's volumeToMesh makes nothing of it, without a word.
std::vector<MissedPart> find_missed_parts(const TriangleMesh& mesh, const std::vector<Vec3>& seeds, double spacing) {
  const double reach = seed_coverage_reach * spacing;
  const NearVertices vertices(mesh.vertices, reach);
  const auto covered = [&vertices](const Vec3& seed) { return vertices.near(seed); };
  struct Group {
    Vec3 first, sum = Vec3::Zero();
    Box3 box;
    std::size_t count = 0;
  };
  std::vector<Group> groups;
  for (const Vec3& seed : seeds) {
    if (covered(seed)) continue;
    auto group = std::find_if(groups.begin(), groups.end(),
                              [&](const Group& g) { return (g.first - seed).norm() <= reach; });
    if (group == groups.end()) {
      groups.push_back({.first = seed, .box = {seed, seed}});
      group = groups.end() - 1;
    }
    group->sum += seed;
    group->box.lo = group->box.lo.cwiseMin(seed);
    group->box.hi = group->box.hi.cwiseMax(seed);
    ++group->count;
  }
  std::vector<MissedPart> parts;
  for (const Group& g : groups) {
    double thickness = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double side = g.box.hi[k] - g.box.lo[k];
      if (side > 0.0 && (thickness == 0.0 || side < thickness)) thickness = side;
    }
    parts.push_back({.centre = g.sum / double(g.count), .thickness = thickness, .seeds = g.count});
  }
  std::stable_sort(parts.begin(), parts.end(),
                   [](const MissedPart& a, const MissedPart& b) { return a.thickness > b.thickness; });
  return parts;
}

/// The vertices of a fresh mesh of facet size `size` projected onto the
/// surface (mesh_iso_surface's last step).
void project_vertices(TriangleMesh& mesh, const ImplicitField& field, const MeshOptions& options, double size) {
  const double diagonal = bounding_box(mesh.vertices).diagonal();
  // Half the required tolerance: the bounding box moves slightly with the
  // projection, and the check is made on the final box.
  project_to_surface(mesh, field, options.iso,
                     {.tolerance = 0.5 * options.projection_tolerance * diagonal, .max_step = size,
                      .threads = options.threads});
}

}  // namespace

double estimate_triangles(const Box3& box, double size) {
  const Vec3 e = box.hi - box.lo;
  const double area = 2 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
  return area / (size * size);
}

TriangleMesh mesh_iso_surface(const ImplicitField& field, const MeshOptions& options, MeshReport* report) {
  const Clock::time_point start = Clock::now();
  check_options(field, options);
  FieldMeter meter(field, options);
  const ImplicitField metered = meter.metered();
  const double iso = options.iso;

  MeshReport run;
  run.box = bounding_region(metered, iso);
  // A facet or voxel larger than the box holding the whole surface means
  // nothing more than one of the box's size, and the projection, which looks
  // for the surface within one facet size, would search far outside it.
  if (options.size && !(*options.size <= run.box.diagonal())) {
    throw InputError(fmt::format("must be at most {:.6g}, the diagonal of the box that holds the whole surface "
                                 "(default: a fiftieth of it), got {:g}",
                                 run.box.diagonal(), *options.size),
                     "--size");
  }
  run.size = options.size.value_or(run.box.diagonal() / 50);
  run.distance = options.distance.value_or(run.size / 10);
  check_output_size(run.box, run.size, run.distance, options);
  check_coordinate_precision(run.box, run.size, run.distance, options);
  // The seeds start CGAL's refinement and the grid's continuation; finding
  // none tells "no surface at this iso" apart from a surface a mesher misses.
  // The grid's continuation needs only the cell a seed lies in (it then
  // samples the cells around it): a quarter of a voxel brackets it, where
  // CGAL's refinement starts from the seeds themselves. On a dense skeleton
  // the bisection to 1e-4 of a voxel was half the grid method's time.
  const unsigned threads = options.threads == 0 ? detail::parallel_threads() : options.threads;
  // The grid's continuation meshes a whole surface from any one seed on it:
  // one ray source per region of the skeleton (region_seeds) instead of
  // one per voxel, the others deferred to after the mesh (below).
  const bool from_seeds = options.method == MeshMethod::grid && options.grid_from_seeds;
  const SurfaceSeedOptions seed_options{
      .spacing = run.size,
      .bracket_fraction = from_seeds ? grid_seed_bracket : SurfaceSeedOptions{}.bracket_fraction,
      .threads = threads};
  RegionSeeds found = from_seeds ? region_seeds(metered, iso, run.box, seed_options)
                                 : RegionSeeds{.seeds = surface_seeds(metered, iso, run.box, seed_options), .deferred = {}};
  std::vector<Vec3> seeds = std::move(found.seeds);
  if (seeds.empty() && !found.deferred.empty()) {
    // No ray of the regions' first sources found a crossing: the others
    // try, as surface_seeds would have.
    seeds = seeds_from_points(metered, iso, run.box, found.deferred, {}, seed_options);
    found.deferred.clear();
  }
  if (seeds.empty()) {
    throw EvaluationError(fmt::format("no surface point found by the rays from the skeleton at iso {}", iso));
  }

  const Clock::time_point refine_start = Clock::now();
  meter.report_progress(true);
  const auto level = [&metered, iso](const Vec3& p) { return iso - metered.value(p); };
  const auto grid_mesh = [&](const std::vector<Vec3>& from) {
    return detail::grid_surface_mesh({.level = grid_level_of(metered, iso, run.size),
                                      .level_near = grid_level_near(metered, iso, run.size),
                                      .box = run.box,
                                      .voxel = run.size,
                                      .support_boxes = field.support_boxes ? &*field.support_boxes : nullptr,
                                      .empty_level = iso - 0.0,  // level(p) where f(p) = 0
                                      .sign_over = level_sign(metered, iso),
                                      .seeds = options.grid_from_seeds ? from : std::vector<Vec3>{},
                                      .threads = threads});
  };
  TriangleMesh mesh = options.method == MeshMethod::grid
                          ? grid_mesh(seeds)
                          : detail::cgal_surface_mesh({
                                .level = level,
                                .box = run.box,
                                .seeds = seeds,
                                .facet_size = run.size,
                                .facet_distance = run.distance,
                                .facet_angle = options.facet_angle,
                                .relative_error_bound = run.distance / accuracy_divisor / run.box.diagonal(),
                                .random_seed = options.random_seed,
                            });
  if (!found.deferred.empty()) {
    // A deferred source with no vertex near it may lie in a part the
    // regions' first rays did not reach (a cavity, a piece the grid did not
    // resolve): such sources cast their rays now. If one of their seeds
    // has no vertex near it either, the grid is sampled again from every
    // seed, so that a part the grid resolves is meshed, and one it does not
    // is reported (missed_parts), as if every source had cast its rays.
    const NearVertices near(mesh.vertices, seed_coverage_reach * run.size);
    std::vector<Vec3> far;
    for (const Vec3& p : found.deferred)
      if (!near.near(p)) far.push_back(p);
    const std::vector<Vec3> more = seeds_from_points(metered, iso, run.box, far, seeds, seed_options);
    seeds.insert(seeds.end(), more.begin(), more.end());
    if (std::any_of(more.begin(), more.end(), [&near](const Vec3& q) { return !near.near(q); }))
      mesh = grid_mesh(seeds);
  }
  run.seeds = seeds.size();
  meter.report_progress(false);
  run.refine_seconds = seconds_since(refine_start);
  if (mesh.triangles.empty() && options.method == MeshMethod::grid) {
    // The seeds prove a surface is there, but no grid node lies inside it:
    // every part of it is thinner than the spacing.
    throw InputError(fmt::format("no grid node of spacing {:g} lies inside the surface ({} surface points were "
                                 "found): it is thinner than the spacing; choose a smaller --size (or "
                                 "--method cgal)",
                                 run.size, seeds.size()),
                     "--size");
  }
  if (mesh.triangles.empty()) {
    throw EvaluationError(fmt::format("the mesher produced no triangles from {} surface seeds", seeds.size()));
  }

  if (options.project) project_vertices(mesh, metered, options, run.size);
  if (options.method == MeshMethod::grid) run.missed_parts = find_missed_parts(mesh, seeds, run.size);

  run.field_evaluations = meter.evaluations();
  run.field_seconds = meter.seconds();
  run.total_seconds = seconds_since(start);
  if (report != nullptr) *report = run;
  return mesh;
}

void project_iso_surface(TriangleMesh& mesh, const ImplicitField& field, const MeshOptions& options, double size) {
  project_vertices(mesh, field, options, size);
}

}  // namespace skelconv
