// Implementation of skelconv/canal/scalis_deviation.hpp.
#include "skelconv/canal/scalis_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::canal {
namespace {

/// A probe: a point of the canal surface, its outward normal, its radius τ.
struct Probe {
  Vec3 point, normal;
  double radius;
};

/// δ/τ at a probe, or nullopt when f < iso all the way in to the skeleton.
/// Steps of 5%, 10%, 20% … of τ outwards (or inwards, to 99.9%: the point
/// p − τν is on the skeleton) find a bracket; bisection narrows it.
std::optional<double> relative_offset(const ScalisSegment& segment, const Probe& probe, double tolerance) {
  const auto excess = [&](double s) { return segment.value(probe.point + s * probe.radius * probe.normal) - segment.iso(); };
  const double at_surface = excess(0.0);
  const double direction = at_surface > 0 ? 1.0 : -1.0;
  double inner = 0.0, outer = 0.0;
  bool bracketed = false;
  for (double step = 0.05; !bracketed; step *= 2) {
    outer = direction > 0 ? step : -std::min(step, 0.999);
    bracketed = (excess(outer) > 0) != (at_surface > 0);
    if (!bracketed && direction > 0 && step > 1e3) {
      throw EvaluationError(fmt::format("f > iso up to {} radii outside the canal surface", step));
    }
    if (!bracketed && direction < 0 && step >= 0.999) return std::nullopt;
    if (!bracketed) inner = outer;
  }
  while (std::abs(outer - inner) > tolerance) {
    const double middle = 0.5 * (inner + outer);
    ((excess(middle) > 0) == (at_surface > 0) ? inner : outer) = middle;
  }
  return 0.5 * (inner + outer);
}

class StatsBuilder {
 public:
  void add(std::optional<double> offset) {
    const double value = offset.value_or(-1.0);
    if (!offset) ++stats_.missing;
    if (std::abs(value) >= std::abs(stats_.extreme)) stats_.extreme = value;
    sum_square_ += value * value;
    ++stats_.points;
  }
  DeviationStats done() const {
    DeviationStats stats = stats_;
    stats.rms = stats.points > 0 ? std::sqrt(sum_square_ / stats.points) : 0.0;
    return stats;
  }

 private:
  DeviationStats stats_;
  double sum_square_ = 0;
};

/// A unit vector orthogonal to `axis`.
Vec3 orthogonal_unit(const Vec3& axis) {
  Eigen::Index smallest = 0;
  axis.cwiseAbs().minCoeff(&smallest);
  return (Vec3::Unit(smallest) - axis[smallest] * axis).normalized();
}

}  // namespace

ScalisDeviation measure_scalis_deviation(const ScalisSegment& segment, const DeviationOptions& options) {
  const Vec3 axis_vector = segment.b() - segment.a();
  const double length = axis_vector.norm();
  const Vec3 u = axis_vector / length, e = orthogonal_unit(u);
  const double slope = (segment.tau1() - segment.tau0()) / length;  // r′/|c′|
  if (!(std::abs(slope) < 1)) {
    throw InputError(fmt::format("the end spheres are nested (|tau1 - tau0| / |AB| = {} >= 1): no canal surface",
                                 std::abs(slope)));
  }
  const double across = std::sqrt(1 - slope * slope);
  const Vec3 frustum_normal = -slope * u + across * e;
  StatsBuilder middle, ends;

  for (int i = 0; i < options.frustum_samples; ++i) {
    const double t = (i + 0.5) / options.frustum_samples;
    const double tau = segment.tau0() + t * (segment.tau1() - segment.tau0());
    const Vec3 center = segment.a() + t * axis_vector;
    const Probe probe{center - tau * slope * u + tau * across * e, frustum_normal, tau};
    const std::optional<double> offset = relative_offset(segment, probe, options.offset_tolerance);
    (t >= options.middle_begin && t <= options.middle_end ? middle : ends).add(offset);
  }
  // The caps: polar angle φ from the outward axis to the end circle (cos φ_c = ∓slope).
  const auto add_cap = [&](const Vec3& center, double tau, const Vec3& outward, double cos_circle_angle) {
    if (tau <= 0) return;
    const double circle_angle = std::acos(cos_circle_angle);
    for (int j = 0; j < options.cap_samples; ++j) {
      const double phi = (j + 0.5) / options.cap_samples * circle_angle;
      const Vec3 normal = std::cos(phi) * outward + std::sin(phi) * e;
      ends.add(relative_offset(segment, {center + tau * normal, normal, tau}, options.offset_tolerance));
    }
  };
  add_cap(segment.a(), segment.tau0(), -u, slope);
  add_cap(segment.b(), segment.tau1(), u, -slope);
  return {middle.done(), ends.done()};
}

std::vector<ScalisDeviationCase> scalis_deviation_cases() {
  struct Shape {
    const char* name;
    double tau0, tau1;
  };
  const Shape shapes[] = {{"cylinder 0.02", 0.02, 0.02},
                          {"cylinder 0.1", 0.1, 0.1},
                          {"growing 0.05-0.15", 0.05, 0.15},
                          {"growing 0.1-0.3", 0.1, 0.3},
                          {"cone 0-0.2", 0.0, 0.2}};
  const ScalisKernel kernels[] = {ScalisKernel::inverse(3, 1.0),  ScalisKernel::inverse(6, 1.0),
                                  ScalisKernel::inverse(10, 1.0), ScalisKernel::cauchy(4, 0.5),
                                  ScalisKernel::cauchy(4, 2.0),   ScalisKernel::cauchy(8, 1.0),
                                  ScalisKernel::compact(4, 1.5),  ScalisKernel::compact(4, 3.0),
                                  ScalisKernel::compact(8, 2.0)};
  std::vector<ScalisDeviationCase> cases;
  for (const ScalisKernel& kernel : kernels) {
    for (const Shape& shape : shapes) {
      const std::string family = std::string(family_name(kernel.family));
      cases.push_back({fmt::format("{} i={} σ={} | {}", family, kernel.degree, kernel.sigma, shape.name), shape.tau0,
                       shape.tau1, kernel});
    }
  }
  return cases;
}

}  // namespace skelconv::canal
