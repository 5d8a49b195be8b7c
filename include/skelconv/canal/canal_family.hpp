// skelconv/canal/canal_family.hpp — a one-parameter family of spheres sampled
// at t ∈ [0, 1]: the sphere and its characteristic circle (docs/canal.md §3).
//
// Two families through given spheres S_0 … S_n (t_k = k/n):
//   * lorentz: SphereInterpolation (Algorithm 1 of the paper, with a pole);
//     circles by the Lorentz construction (characteristic_circle);
//   * linear: centre and radius piecewise linear in t between consecutive
//     spheres, the cone frusta of SCALIS segments; circles by the closed
//     form (linear_family_circle). At an interior knot the rates of the
//     following piece are used (the surface has a crease there: the circles
//     of both pieces lie on S_k; the sweep keeps the second).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "skelconv/canal/characteristic_circle.hpp"
#include "skelconv/canal/lorentz.hpp"
#include "skelconv/canal/sphere_interpolation.hpp"
#include "skelconv/errors.hpp"

namespace skelconv::canal {

/// One sample of a family: the parameter, the sphere, and its characteristic
/// circle (nullopt where the family has no real envelope).
template <class T>
struct FamilySample {
  T t = T(0);
  Sphere<T> sphere;
  std::optional<Circle<T>> circle;
};

/// The sample of a Lorentz-interpolated family at t. Throws EvaluationError
/// where γ(t) is a point or a plane (no centre and finite radius).
template <class T>
FamilySample<T> sample_family(const SphereInterpolation<T>& family, T t) {
  const Vector5<T> gamma = family(t);
  const Vector5<T> tangent = family.derivative(t);
  try {
    return {t, sphere_from_vector(gamma), characteristic_circle(gamma, tangent)};
  } catch (const EvaluationError&) {
    throw EvaluationError("the interpolated family is a plane here (its radius is infinite)",
                          fmt::format("t = {}", double(t)));
  }
}

/// Centre and radius piecewise linear in t through the given spheres.
template <class T>
class LinearSphereFamily {
 public:
  /// At least two spheres (radii ≠ 0, any signs); consecutive spheres must
  /// not be nested: |c_{k+1} − c_k|² − (r_{k+1} − r_k)² > tolerance
  /// (|c_{k+1} − c_k|² + (r_{k+1} − r_k)²), else there is no real circle
  /// anywhere between them. Throws InputError located at "spheres[k]".
  explicit LinearSphereFamily(std::vector<Sphere<T>> spheres, T tolerance = T(1e-12)) : spheres_(std::move(spheres)) {
    if (spheres_.size() < 2) {
      throw InputError(fmt::format("at least 2 spheres are needed, got {}", spheres_.size()), "spheres");
    }
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
      try {
        sphere_vector(spheres_[k]);  // validates the radius
      } catch (const InputError& error) {
        throw error.inside(fmt::format("spheres[{}]", k));
      }
    }
    for (std::size_t k = 0; k + 1 < spheres_.size(); ++k) check_piece(k, tolerance);
  }

  const std::vector<Sphere<T>>& spheres() const { return spheres_; }

  FamilySample<T> sample(T t) const {
    const std::size_t k = piece(t);
    const T n = T(spheres_.size() - 1);
    const Sphere<T>& first = spheres_[k];
    const Sphere<T>& second = spheres_[k + 1];
    const T s = t * n - T(k);  // 0 … 1 on the piece
    Sphere<T> sphere{first.center + s * (second.center - first.center), first.radius + s * (second.radius - first.radius)};
    if (s == T(0)) sphere = first;  // the knots exactly
    if (s == T(1)) sphere = second;
    const Vector3<T> center_rate = n * (second.center - first.center);
    const T radius_rate = n * (second.radius - first.radius);
    return {t, sphere, sphere.radius != T(0) ? linear_family_circle(sphere, center_rate, radius_rate) : std::nullopt};
  }

 private:
  std::size_t piece(T t) const {
    using std::floor;
    const std::size_t n = spheres_.size() - 1;
    const T scaled = floor(t * T(n));
    return scaled <= T(0) ? 0 : (scaled >= T(n - 1) ? n - 1 : std::size_t(scaled));
  }

  void check_piece(std::size_t k, T tolerance) const {
    const Sphere<T>& first = spheres_[k];
    const Sphere<T>& second = spheres_[k + 1];
    const T centres = (second.center - first.center).squaredNorm();
    const T radii = (second.radius - first.radius) * (second.radius - first.radius);
    const std::string where = fmt::format("spheres[{}]", k + 1);
    if (centres == T(0) && radii == T(0)) throw repeated_sphere_error(k);
    if (centres - radii <= tolerance * (centres + radii)) {
      throw InputError(fmt::format("spheres[{}] and spheres[{}] are nested: the distance of the centres {} is at "
                                   "most the difference of the radii {}, so no real envelope joins them (the "
                                   "linear family is time-like)",
                                   k, k + 1, double(std::sqrt(centres)), double(std::sqrt(radii))),
                       where);
    }
  }

  std::vector<Sphere<T>> spheres_;
};

}  // namespace skelconv::canal
