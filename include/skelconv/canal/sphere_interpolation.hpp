// skelconv/canal/sphere_interpolation.hpp — a curve of spheres through given
// spheres S_0 … S_n, by the canal-surfaces paper's Algorithm 1 (§3; the
// inversion of §2.2.1; docs/canal.md §2):
//
//   1. choose a pole Ω on Λ⁴ (a sphere or a plane);
//   2. invert every S_k with pole Ω and power 1: X_k = Ω + (S_k − Ω)/Q(S_k − Ω).
//      Q(S_k − Ω) = 2 − 2 L(S_k, Ω), so this needs Ω not tangent to S_k
//      with the same orientation (L ≠ 1), and the X_k lie in the hyperplane
//      H = {X : L(X, Ω) = ½};
//   3. interpolate the X_k in H at t_k = k/n (UniformSpline: linear,
//      quadratic, or the not-a-knot C² cubic spline); every affine
//      combination of points of H stays in H;
//   4. invert back: γ(t) = Ω + Y/Q(Y), Y = X(t) − Ω, which lies on Λ⁴
//      (Q(γ) = 1 for every Y with L(Y + Ω, Ω) = ½) and is rational in t
//      (degree 2, 4, 6 for linear, quadratic, cubic pieces).
//
// The inversion is conformal for L: Q(γ′) = Q(X′)/Q(Y)², so γ is space-like
// (has a real envelope, §2.2.2) exactly where X is; and in H, Q(Y) = Q(X).
// Two consequences checked here, at construction (InputError):
//   * a chord X_{k+1} − X_k is space-like iff Q(S_{k+1} − S_k) and the two
//     Q(S_j − Ω) have product > 0 (Q(ΔX) = Q(ΔS)/(Q(S_k − Ω) Q(S_{k+1} − Ω))).
//     A time-like ΔS means nested spheres (L(S_k, S_{k+1}) > 1): no real
//     envelope joins them. A pole nested with one of them and not the
//     other (L(S_j, Ω) on both sides of 1) turns a space-like ΔS time-like.
//     Both are refused, with their own messages;
//   * the result depends on Ω (the paper, end of §2.2.1): for two spheres,
//     γ is the arc from S_0 to S_1 of the conic Λ⁴ ∩ (the affine plane
//     through Ω, S_0, S_1), the arc that avoids Ω (tests/canal_test.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "skelconv/canal/lorentz.hpp"
#include "skelconv/canal/uniform_spline.hpp"
#include "skelconv/errors.hpp"

namespace skelconv::canal {

/// The refusal of spheres[k + 1] equal to spheres[k] (centre and radius),
/// the same for every family.
inline InputError repeated_sphere_error(std::size_t k) {
  return InputError(fmt::format("the same sphere as spheres[{}] (centre and radius): consecutive spheres must "
                                "differ, no canal surface joins a sphere to itself",
                                k),
                    fmt::format("spheres[{}]", k + 1));
}

/// The tolerances of SphereInterpolation, relative (see is_light_like).
template <class T>
struct InterpolationTolerances {
  /// A chord or a vector S − Ω with |Q| ≤ light_cone ‖·‖² is treated as
  /// light-like: tangency of the pole, tangent (light-like) chords. 1e-12
  /// leaves room above the ~16 ε rounding of Q for inputs that were
  /// converted from (centre, radius) in double.
  T light_cone = T(1e-12);
  /// |Q(S) − 1| ≤ on_quadric ‖S‖² for inputs said to lie on Λ⁴.
  T on_quadric = T(1e-9);
};

template <class T>
class SphereInterpolation {
 public:
  /// `spheres`: points of Λ⁴ (sphere_vector), at least two; `pole` on Λ⁴
  /// (sphere_vector or plane_vector). Throws InputError located at
  /// "spheres", "spheres[k]" or "pole" (messages in the file comment).
  SphereInterpolation(const std::vector<Vector5<T>>& spheres, const Vector5<T>& pole,
                      InterpolationTolerances<T> tolerances = {})
      : pole_(pole), tolerances_(tolerances), spline_(checked_images(spheres, pole, tolerances)), spheres_(spheres) {}

  const Vector5<T>& pole() const { return pole_; }
  /// The inputs S_k.
  const std::vector<Vector5<T>>& spheres() const { return spheres_; }
  /// Their images in the hyperplane, X_k = Ω + Y_k.
  std::vector<Vector5<T>> hyperplane_points() const {
    std::vector<Vector5<T>> points;
    for (const Vector5<T>& y : spline_.points()) points.push_back(pole_ + y);
    return points;
  }

  /// γ(t) ∈ Λ⁴ for t in [0, 1]. At a knot t = k/n it returns S_k itself (the
  /// round trip through the inversion would change it by a few ulps).
  /// Throws EvaluationError where γ is not defined: where X(t) is on the
  /// light cone of Ω, i.e. γ(t) is a sphere of radius 0 (the family passes
  /// through a point there).
  Vector5<T> operator()(T t) const {
    if (const std::optional<std::size_t> k = knot_index(t)) return spheres_[*k];
    const Vector5<T> y = from_pole(t);
    return pole_ + y / lorentz_square(y);
  }

  /// γ′(t) = Y′/Q(Y) − 2 L(Y, Y′) Y/Q(Y)², Y = X(t) − Ω.
  Vector5<T> derivative(T t) const {
    const Vector5<T> y = from_pole(t);
    const Vector5<T> dy = spline_.derivative(t);  // X′ = Y′
    const T q = lorentz_square(y);
    return dy / q - (T(2) * lorentz(y, dy) / (q * q)) * y;
  }

 private:
  /// Y(t) = X(t) − Ω, checked off the light cone of Ω.
  Vector5<T> from_pole(T t) const {
    const Vector5<T> y = spline_.value(t);
    if (is_light_like(y, tolerances_.light_cone)) {
      throw EvaluationError(
          "the interpolated family passes through a point (a sphere of radius 0): its curve meets the light cone "
          "of the pole there",
          fmt::format("t = {}", double(t)));
    }
    return y;
  }

  /// k if t is the knot k/n exactly (t·n an integer in 0 … n), else nullopt.
  std::optional<std::size_t> knot_index(T t) const {
    using std::round;
    const std::size_t n = spheres_.size() - 1;
    const T scaled = t * T(n);
    const T nearest = round(scaled);
    if (scaled != nearest || nearest < T(0) || nearest > T(n)) return std::nullopt;
    return std::size_t(nearest);
  }

  static void check_on_quadric(const Vector5<T>& x, const std::string& where, T tolerance) {
    using std::abs;
    if (!x.allFinite() || abs(lorentz_square(x) - T(1)) > tolerance * x.squaredNorm()) {
      throw InputError(fmt::format("is not on the quadric Λ⁴ (Q = {}, must be 1)", double(lorentz_square(x))), where);
    }
  }

  /// The images relative to the pole, Y_k = X_k − Ω = (S_k − Ω)/Q(S_k − Ω),
  /// after every check of the file comment. The spline interpolates the Y_k
  /// (the same curve as the X_k, shifted by Ω): forming X_k = Ω + Y_k and
  /// subtracting Ω again would lose the digits of Y_k that Ω's size hides.
  static std::vector<Vector5<T>> checked_images(const std::vector<Vector5<T>>& spheres, const Vector5<T>& pole,
                                                const InterpolationTolerances<T>& tolerances) {
    if (spheres.size() < 2) {
      throw InputError(fmt::format("at least 2 spheres are needed, got {}", spheres.size()), "spheres");
    }
    check_on_quadric(pole, "pole", tolerances.on_quadric);
    std::vector<Vector5<T>> images;
    for (std::size_t k = 0; k < spheres.size(); ++k) {
      const std::string where = fmt::format("spheres[{}]", k);
      check_on_quadric(spheres[k], where, tolerances.on_quadric);
      if (is_light_like(Vector5<T>(spheres[k] - pole), tolerances.light_cone)) {
        throw InputError(fmt::format("is tangent to {} with the same orientation (L = {}): the Lorentz inversion "
                                     "of this pole is undefined there; choose another pole",
                                     where, double(lorentz(spheres[k], pole))),
                         "pole");
      }
      const Vector5<T> from_pole = spheres[k] - pole;
      images.push_back(from_pole / lorentz_square(from_pole));
    }
    for (std::size_t k = 0; k + 1 < spheres.size(); ++k) check_chord(spheres, pole, images, k, tolerances.light_cone);
    return images;
  }

  /// Refuses a chord X_{k+1} − X_k that is not space-like, naming the cause.
  static void check_chord(const std::vector<Vector5<T>>& spheres, const Vector5<T>& pole,
                          const std::vector<Vector5<T>>& images, std::size_t k, T tolerance) {
    const Vector5<T> image_chord = images[k + 1] - images[k];
    if (lorentz_square(image_chord) > tolerance * image_chord.squaredNorm()) return;
    const std::string first = fmt::format("spheres[{}]", k), second = fmt::format("spheres[{}]", k + 1);
    const Vector5<T> chord = spheres[k + 1] - spheres[k];
    if (chord.squaredNorm() == T(0)) throw repeated_sphere_error(k);
    if (lorentz_square(chord) <= tolerance * chord.squaredNorm()) {
      throw InputError(fmt::format("{} and {} are nested (L = {} ≥ 1, as oriented spheres): their chord is "
                                   "time-like or light-like, so no real envelope joins them",
                                   first, second, double(lorentz(spheres[k], spheres[k + 1]))),
                       second);
    }
    throw InputError(fmt::format("is nested with one of {} and {} but not with the other (L = {} and {}, one "
                                 "≥ 1, one < 1): after the inversion their chord is time-like; choose a pole "
                                 "nested with all the spheres or with none",
                                 first, second, double(lorentz(spheres[k], pole)),
                                 double(lorentz(spheres[k + 1], pole))),
                     "pole");
  }

  Vector5<T> pole_;
  InterpolationTolerances<T> tolerances_;
  UniformSpline<Vector5<T>> spline_;
  std::vector<Vector5<T>> spheres_;
};

}  // namespace skelconv::canal
