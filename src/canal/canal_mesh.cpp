// Implementation of skelconv/canal/canal_mesh.hpp.
#include "skelconv/canal/canal_mesh.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::canal {
namespace {

using Index = std::int32_t;

/// An orthonormal frame around a circle: e2 = normal × e1.
struct Frame {
  Vec3 e1, e2;
};

/// A ring of vertex indices; one index for an apex.
using Ring = std::vector<Index>;

class CanalMesher {
 public:
  CanalMesher(const std::vector<FamilySample<double>>& samples, const CanalMeshOptions& options)
      : samples_(samples), options_(options) {}

  TriangleMesh run() {
    check_samples();
    std::vector<Ring> rings;
    Frame frame = first_frame(samples_.front().circle->normal);
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      if (i > 0) frame = carried_frame(frame, *samples_[i].circle, samples_[i].t);
      if (i == 0) first_frame_ = frame;
      rings.push_back(add_circle_ring(samples_[i], frame));
    }
    const Frame last_frame = frame;
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) stitch(rings[i], rings[i + 1]);
    if (options_.caps) {
      add_cap(samples_.front(), first_frame_, rings.front(), /*at_start=*/true);
      add_cap(samples_.back(), last_frame, rings.back(), /*at_start=*/false);
    }
    return std::move(mesh_);
  }

 private:
  void check_samples() const {
    if (samples_.size() < 2) throw InputError(fmt::format("at least 2 samples are needed, got {}", samples_.size()));
    if (options_.ring_points < 3) throw InputError(fmt::format("ring_points must be >= 3, got {}", options_.ring_points));
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const FamilySample<double>& sample = samples_[i];
      if (!sample.circle) {
        throw EvaluationError(fmt::format(
            "no real characteristic circle at t = {} (the family is not space-like there): cannot mesh", sample.t));
      }
      if (i > 0 && (sample.sphere.radius > 0) != (samples_[i - 1].sphere.radius > 0)) {
        throw EvaluationError(fmt::format("the radius changes sign between t = {} and t = {} (the family passes "
                                          "through a point or a plane; the surface pinches there): cannot mesh",
                                          samples_[i - 1].t, sample.t));
      }
    }
  }

  /// e1: the coordinate axis least aligned with n, made orthogonal to n.
  static Frame first_frame(const Vec3& normal) {
    Eigen::Index axis = 0;
    normal.cwiseAbs().minCoeff(&axis);
    const Vec3 e1 = (Vec3::Unit(axis) - normal[axis] * normal).normalized();
    return {e1, normal.cross(e1)};
  }

  Frame carried_frame(const Frame& previous, const Circle<double>& circle, double t) const {
    const Vec3& n = circle.normal;
    const Vec3 projected = previous.e1 - previous.e1.dot(n) * n;
    if (projected.norm() < options_.min_projected_frame) {
      throw EvaluationError(fmt::format(
          "the circle normal turns by almost 90 degrees just before t = {}: use more samples to mesh", t));
    }
    const Vec3 e1 = projected.normalized();
    return {e1, n.cross(e1)};
  }

  Index add_vertex(const Vec3& point, const Sphere<double>& sphere) {
    mesh_.vertices.push_back(point);
    mesh_.normals.push_back((point - sphere.center).normalized());
    return Index(mesh_.vertices.size() - 1);
  }

  /// cos ψ e1 + sin ψ e2 for the j-th of the ring's points.
  Vec3 radial(const Frame& frame, int j) const {
    const double psi = 2.0 * std::numbers::pi * j / options_.ring_points;
    return std::cos(psi) * frame.e1 + std::sin(psi) * frame.e2;
  }

  Ring add_circle_ring(const FamilySample<double>& sample, const Frame& frame) {
    const Circle<double>& circle = *sample.circle;
    Ring ring;
    for (int j = 0; j < options_.ring_points; ++j) {
      ring.push_back(add_vertex(circle.center + circle.radius * radial(frame, j), sample.sphere));
    }
    return ring;
  }

  /// Joins `lower` to `upper` (the next ring in the direction of the circle
  /// normals), counter-clockwise seen from outside. Either may be an apex.
  void stitch(const Ring& lower, const Ring& upper) {
    const std::size_t count = std::max(lower.size(), upper.size());
    auto at = [count](const Ring& ring, std::size_t j) { return ring.size() == 1 ? ring[0] : ring[j % count]; };
    for (std::size_t j = 0; j < count; ++j) {
      const Index a = at(lower, j), b = at(lower, j + 1), c = at(upper, j + 1), d = at(upper, j);
      if (lower.size() > 1) mesh_.triangles.push_back({a, b, c});
      if (upper.size() > 1) mesh_.triangles.push_back({a, c, d});
    }
  }

  /// The part of the end sphere beyond the end circle, in rings from the
  /// circle (reused: shared vertices keep the mesh watertight) to the apex.
  void add_cap(const FamilySample<double>& sample, const Frame& frame, const Ring& circle_ring, bool at_start) {
    const Sphere<double>& sphere = sample.sphere;
    const Circle<double>& circle = *sample.circle;
    const double radius = std::abs(sphere.radius);
    const Vec3 axis = at_start ? Vec3(-circle.normal) : circle.normal;
    // Angle from the axis to the circle, seen from the sphere's centre.
    const double circle_angle = std::atan2(circle.radius, (circle.center - sphere.center).dot(axis));
    const double step = 2.0 * std::numbers::pi / options_.ring_points;
    const int ring_count = std::max(1, int(std::ceil(circle_angle / step)));
    std::vector<Ring> rings{circle_ring};
    for (int k = 1; k < ring_count; ++k) {
      const double angle = circle_angle * (1.0 - double(k) / ring_count);
      Ring ring;
      for (int j = 0; j < options_.ring_points; ++j) {
        const Vec3 point =
            sphere.center + radius * (std::cos(angle) * axis + std::sin(angle) * radial(frame, j));
        ring.push_back(add_vertex(point, sphere));
      }
      rings.push_back(ring);
    }
    rings.push_back(Ring{add_vertex(sphere.center + radius * axis, sphere)});
    for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
      // At the start the cap runs against the normals: its next ring is the lower one.
      if (at_start) stitch(rings[k + 1], rings[k]);
      else stitch(rings[k], rings[k + 1]);
    }
  }

  const std::vector<FamilySample<double>>& samples_;
  const CanalMeshOptions& options_;
  TriangleMesh mesh_;
  Frame first_frame_;
};

}  // namespace

TriangleMesh mesh_canal_surface(const std::vector<FamilySample<double>>& samples, const CanalMeshOptions& options) {
  return CanalMesher(samples, options).run();
}

}  // namespace skelconv::canal
