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

/// Newton from p: the final sample if it is within the tolerance (p moved
/// there), else nothing (p where Newton stopped). `evaluate` is the field's
/// f and ∇f near the start.
template <class Evaluate>
std::optional<FieldSample> newton(Vec3& p, FieldSample& s, const Evaluate& evaluate, double iso,
                                  const ProjectionOptions& options) {
  for (int iteration = 0; usable(s); ++iteration) {
    if (first_order_distance(s, iso) <= options.tolerance) return s;
    if (iteration == options.max_iterations) break;
    Vec3 step = -(s.value - iso) / s.gradient.squaredNorm() * s.gradient;
    if (step.norm() > options.max_step) step *= options.max_step / step.norm();
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

/// p moved onto the surface; its final sample. Throws on failure.
FieldSample project_point(Vec3& p, const ImplicitField& field, double iso, const ProjectionOptions& options) {
  const Vec3 start = p;
  const std::function<FieldSample(const Vec3&)> near =
      field.value_and_gradient_near ? field.value_and_gradient_near(start, shared_fraction * options.max_step)
                                    : field.value_and_gradient;
  const FieldSample at_start = near(p);
  FieldSample s = at_start;
  if (const auto done = newton(p, s, near, iso, options)) return *done;
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
