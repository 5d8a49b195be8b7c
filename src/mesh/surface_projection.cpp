// Implementation of skelconv/mesh/surface_projection.hpp.
#include "skelconv/mesh/surface_projection.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "../detail/parallel_for.hpp"

namespace skelconv {
namespace {

/// |f − iso| / |∇f|: the distance to the surface to first order.
double first_order_distance(const FieldSample& s, double iso) { return std::abs(s.value - iso) / s.gradient.norm(); }

bool usable(const FieldSample& s) { return std::isfinite(s.value) && s.gradient.allFinite() && s.gradient.norm() > 0; }

/// The ball around a vertex's start in which Newton's iterates share the
/// field's work (ImplicitField::value_and_gradient_near), as a fraction of
/// max_step (the mesh's facet size): a grid vertex starts ~1% of the
/// spacing from the surface and the steps shrink from there, so nearly
/// every iterate stays inside; a larger ball would make the shared work
/// hold over more space (longer rules) for nothing. An iterate outside is
/// evaluated as usual.
constexpr double shared_fraction = 1.0 / 16;

/// Newton's step from a sample: −(f − iso) ∇f / |∇f|², at most max_step long.
Vec3 newton_step(const FieldSample& s, double iso, const ProjectionOptions& options) {
  Vec3 step = -(s.value - iso) / s.gradient.squaredNorm() * s.gradient;
  if (step.norm() > options.max_step) step *= options.max_step / step.norm();
  return step;
}

/// Newton from p: the final sample if it is within the tolerance (p moved
/// there), else nothing (p where Newton stopped). `evaluate` is the field's
/// f and ∇f near the start; `steps_taken` the steps already taken towards
/// p (they count towards options.max_iterations).
template <class Evaluate>
std::optional<FieldSample> newton(Vec3& p, FieldSample& s, const Evaluate& evaluate, double iso,
                                  const ProjectionOptions& options, int steps_taken) {
  for (int iteration = steps_taken; usable(s); ++iteration) {
    if (first_order_distance(s, iso) <= options.tolerance) return s;
    if (iteration == options.max_iterations) break;
    Vec3 step = newton_step(s, iso, options);
    // Halve the step until |f − iso| decreases (at most 40 times: 1e-12 of it).
    for (int halving = 0; halving < 40; ++halving, step /= 2) {
      const FieldSample next = evaluate(p + step);
      if (usable(next) && std::abs(next.value - iso) < std::abs(s.value - iso)) {
        p += step;
        s = next;
        break;
      }
    }
  }
  return std::nullopt;
}

/// Where Newton cannot go on: p outside every compact support (f = 0,
/// ∇f = 0: no direction), or steps that stop reducing |f − iso| at a kink
/// or a near-critical point. The surface is within max_step of a mesher's
/// vertex, so look there for a point q on the other side of the level,
/// nearest radii first (max_step/64 … max_step), along ±∇f and then the 26
/// directions to a cube's faces, edges and corners; then bisect [p, q]
/// until it is at most `tolerance` long. The level crosses that interval
/// (f is continuous), so its middle is within the tolerance of the surface,
/// which is what Newton's first-order test stands for. Nothing if no point
/// on the other side is found, or the gradient vanishes at the end (no
/// normal).
std::optional<FieldSample> bisect_to_surface(Vec3& p, const FieldSample& at_p, const ImplicitField& field,
                                             double iso, const ProjectionOptions& options) {
  if (!std::isfinite(at_p.value)) return std::nullopt;
  const bool inside = at_p.value > iso;
  std::vector<Vec3> directions;
  if (at_p.gradient.allFinite() && at_p.gradient.norm() > 0) {
    directions.push_back(at_p.gradient.normalized());
    directions.push_back(-at_p.gradient.normalized());
  }
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) directions.push_back(Vec3(x, y, z).normalized());
  for (double radius = options.max_step / 64; radius <= options.max_step * (1 + 1e-12); radius *= 2) {
    for (const Vec3& d : directions) {
      Vec3 near = p, far = p + radius * d;
      const FieldSample at_far = field.value_and_gradient(far);
      if (!std::isfinite(at_far.value) || (at_far.value > iso) == inside || at_far.value == iso) {
        if (at_far.value != iso) continue;
        near = far;  // exactly on the level
      }
      // (f(near) − iso) and (f(far) − iso) differ in sign: bisect.
      while ((far - near).norm() > options.tolerance) {
        const Vec3 middle = 0.5 * (near + far);
        // Far from the origin the tolerance can be below the spacing of
        // doubles (a ball of radius 0.5 at (1e7, 1e7, 1e7): doubles 1.9e-9
        // apart, the tolerance 8.7e-10): the interval stops at neighbouring
        // doubles, as near as coordinates get (the bisection never ended).
        if (middle == near || middle == far) break;
        const double value = field.value_and_gradient(middle).value;
        if (!std::isfinite(value)) return std::nullopt;
        ((value > iso) == inside ? near : far) = middle;
      }
      p = 0.5 * (near + far);
      const FieldSample s = field.value_and_gradient(p);
      if (!usable(s)) return std::nullopt;
      return s;
    }
  }
  return std::nullopt;
}

/// How far from the surface, in units of the coarse field's error bound
/// ε |f̃| / |∇f̃|, a vertex's coarse sample must put it for its first Newton
/// step to be taken from that sample: the step then moves it towards the
/// surface by nearly its whole distance (the coarse value's error is at most
/// a quarter of it).
constexpr double coarse_step_margin = 4.0;

/// The first Newton step from p taken on the coarse field (ImplicitField::
/// coarse): its error (~1e-6 of f) moves the step's end by far less than
/// the ~1% of a voxel a grid vertex starts from the surface, so Newton goes
/// on from there in as many steps, each evaluation after it on the field.
/// The step is kept, p moved and its end's sample returned, only if |f − iso|
/// there is below the start's coarse |f̃ − iso| (the halving test's
/// condition); else nothing (p unchanged), and Newton starts from p on the
/// field as it would without a coarse field.
template <class Evaluate>
std::optional<FieldSample> coarse_first_step(Vec3& p, const ImplicitField& field, const Evaluate& evaluate, double iso,
                                             const ProjectionOptions& options) {
  const FieldSample rough = field.coarse->value_and_gradient(p);
  if (!usable(rough)) return std::nullopt;
  // A start the coarse field puts within the tolerance may need no step at
  // all: the field decides.
  const double distance = first_order_distance(rough, iso);
  if (!(distance > options.tolerance &&
        distance > coarse_step_margin * field.coarse_tolerance * std::abs(rough.value) / rough.gradient.norm())) {
    return std::nullopt;
  }
  const Vec3 next = p + newton_step(rough, iso, options);
  const FieldSample at_next = evaluate(next);
  if (!usable(at_next) || !(std::abs(at_next.value - iso) < std::abs(rough.value - iso))) return std::nullopt;
  p = next;
  return at_next;
}

/// p moved onto the surface; its final sample. Throws on failure.
FieldSample project_point(Vec3& p, const ImplicitField& field, double iso, const ProjectionOptions& options) {
  const Vec3 start = p;
  const std::function<FieldSample(const Vec3&)> near =
      field.value_and_gradient_near ? field.value_and_gradient_near(start, shared_fraction * options.max_step)
                                    : field.value_and_gradient;
  std::optional<FieldSample> first;
  if (field.coarse) first = coarse_first_step(p, field, near, iso, options);
  const std::optional<FieldSample> on_field_at_start = first ? std::nullopt : std::optional(near(p));
  FieldSample s = first ? *first : *on_field_at_start;
  if (const auto done = newton(p, s, near, iso, options, first ? 1 : 0)) return *done;
  // The bisection's side is the field's at the start, not the coarse one's.
  const FieldSample at_start = on_field_at_start ? *on_field_at_start : near(start);
  // Bisection from where Newton started: its last point may have wandered.
  Vec3 q = start;
  if (const auto done = bisect_to_surface(q, at_start, field, iso, options)) {
    p = q;
    return *done;
  }
  throw EvaluationError(fmt::format("cannot project onto the surface: f = {:.17g}, |grad f| = {:.3g} at ({:.17g}, {:.17g}, {:.17g}), "
                                    "and no point on the other side of the level within {:.3g}",
                                    s.value, s.gradient.norm(), p.x(), p.y(), p.z(), options.max_step));
}

}  // namespace

void project_to_surface(TriangleMesh& mesh, const ImplicitField& field, double iso, const ProjectionOptions& options) {
  mesh.normals.resize(mesh.vertices.size());
  // Each vertex on its own (on every core): the same mesh, and the error of
  // the lowest vertex that fails, as one thread in order gives.
  detail::parallel_for(
      mesh.vertices.size(),
      [&](std::size_t k) {
        try {
          const FieldSample s = project_point(mesh.vertices[k], field, iso, options);
          mesh.normals[k] = -s.gradient.normalized();
        } catch (const EvaluationError& error) {
          throw EvaluationError(error.problem(), fmt::format("mesh vertex {}", k));
        }
      },
      256, options.threads == 0 ? detail::parallel_threads() : options.threads);
}

}  // namespace skelconv
