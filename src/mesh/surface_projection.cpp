// Implementation of skelconv/mesh/surface_projection.hpp.
#include "skelconv/mesh/surface_projection.hpp"

#include <cmath>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

/// |f − iso| / |∇f|: the distance to the surface to first order.
double first_order_distance(const FieldSample& s, double iso) { return std::abs(s.value - iso) / s.gradient.norm(); }

bool usable(const FieldSample& s) { return std::isfinite(s.value) && s.gradient.allFinite() && s.gradient.norm() > 0; }

/// Newton from p; returns the final sample and moves p. Throws on failure.
FieldSample project_point(Vec3& p, const ImplicitField& field, double iso, const ProjectionOptions& options) {
  FieldSample s = field.value_and_gradient(p);
  for (int iteration = 0; usable(s); ++iteration) {
    if (first_order_distance(s, iso) <= options.tolerance) return s;
    if (iteration == options.max_iterations) break;
    Vec3 step = -(s.value - iso) / s.gradient.squaredNorm() * s.gradient;
    if (step.norm() > options.max_step) step *= options.max_step / step.norm();
    // Halve the step until |f − iso| decreases (at most 40 times: 1e-12 of it).
    for (int halving = 0; halving < 40; ++halving, step /= 2) {
      const FieldSample next = field.value_and_gradient(p + step);
      if (usable(next) && std::abs(next.value - iso) < std::abs(s.value - iso)) {
        p += step;
        s = next;
        break;
      }
    }
  }
  throw EvaluationError(fmt::format("cannot project onto the surface: f = {:.17g}, |grad f| = {:.3g} at ({:.17g}, {:.17g}, {:.17g})",
                                    s.value, s.gradient.norm(), p.x(), p.y(), p.z()));
}

}  // namespace

void project_to_surface(TriangleMesh& mesh, const ImplicitField& field, double iso, const ProjectionOptions& options) {
  mesh.normals.resize(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    try {
      const FieldSample s = project_point(mesh.vertices[k], field, iso, options);
      mesh.normals[k] = -s.gradient.normalized();
    } catch (const EvaluationError& error) {
      throw EvaluationError(error.problem(), fmt::format("mesh vertex {}", k));
    }
  }
}

}  // namespace skelconv
