// skelconv/canal/characteristic_circle.hpp — the circle along which a sphere
// of a one-parameter family touches the envelope (the canal surface), in the
// Lorentz model (canal-surfaces paper §2.2.2, fig. 2; docs/canal.md §3) and in
// the Euclidean closed form of a linear family.
//
// Lorentz construction. γ(t) on Λ⁴ with γ′ space-like (Q(γ′) > 0; the paper
// says "inside the cone", a misprint: space-like vectors are outside it).
// Differentiating Q(γ) = 1 gives L(γ, γ′) = 0, so τ = γ′/√Q(γ′) is a point of
// Λ⁴ orthogonal to γ: a sphere (or plane) cutting γ(t) at right angles, and
// γ(t) ∩ τ is the characteristic circle. To intersect them without caring
// whether τ is a sphere or a plane, take
//     W = τ − κ γ,   κ = r (τ0 − τ4)        (r the radius of γ(t)),
// which has W0 = W4: W = (w, m, w) is the plane {p : m·p = w} of the circle.
// From Q(W) = 1 + κ² = |m|² and L(W, γ) = −κ: the plane is at signed
// distance −κ r/|m| from the centre c of γ(t), so
//     circle centre = c + (κ r/|m|²) m,   radius = |r|/|m| = |r|/√(1 + κ²),
//     normal        = sign(r) m/|m|,
// always real when Q(γ′) > 0. sign(r) orients the normal the way the family
// moves: for a linear family it is c′/|c′| whatever the orientation.
//
// Euclidean closed form. For c(t) = c0 + t c′, r(t) = r0 + t r′ (the 1-jet of
// any family, so it also gives the circle of any family from c, r, c′, r′):
// Q(γ′) = (|c′|² − r′²)/r², κ = −r′ sign(r)/√(|c′|² − r′²), and the formulas
// above become
//     centre c − (r r′/|c′|²) c′,  radius |r| √(1 − r′²/|c′|²),  normal c′/|c′|.
#pragma once

#include <cmath>
#include <optional>

#include "skelconv/canal/lorentz.hpp"

namespace skelconv::canal {

template <class T>
struct Circle {
  Vector3<T> center = Vector3<T>::Zero();
  T radius = T(0);
  Vector3<T> normal = Vector3<T>::UnitZ();  ///< unit normal of the circle's plane
};

/// The characteristic circle of a family of spheres at a point γ (a sphere,
/// not a plane: sphere_from_vector) with tangent γ′; nullopt when γ′ is not
/// space-like (Q(γ′) ≤ tolerance ‖γ′‖²: no real envelope there).
template <class T>
std::optional<Circle<T>> characteristic_circle(const Vector5<T>& gamma, const Vector5<T>& tangent,
                                               T tolerance = default_light_cone_tolerance<T>()) {
  using std::abs;
  using std::sqrt;
  const T q = lorentz_square(tangent);
  if (!(q > tolerance * tangent.squaredNorm())) return std::nullopt;
  const Sphere<T> sphere = sphere_from_vector(gamma);
  const T r = sphere.radius;
  const Vector5<T> tau = tangent / sqrt(q);
  const T kappa = r * (tau[0] - tau[4]);
  const Vector3<T> m = tau.template segment<3>(1) - kappa * gamma.template segment<3>(1);
  const T m_square = m.squaredNorm();
  const T m_length = sqrt(m_square);
  return Circle<T>{sphere.center + (kappa * r / m_square) * m, abs(r) / m_length,
                   (r > T(0) ? T(1) : T(-1)) * m / m_length};
}

/// The closed form for the family with centre c, radius r and rates c′, r′;
/// nullopt when |c′| ≤ |r′| (no real circle).
template <class T>
std::optional<Circle<T>> linear_family_circle(const Sphere<T>& sphere, const Vector3<T>& center_rate, T radius_rate) {
  using std::abs;
  using std::sqrt;
  const T speed_square = center_rate.squaredNorm();
  const T slope_square = radius_rate * radius_rate / speed_square;  // r′²/|c′|²
  if (!(slope_square < T(1))) return std::nullopt;
  const T r = sphere.radius;
  return Circle<T>{sphere.center - (r * radius_rate / speed_square) * center_rate, abs(r) * sqrt(T(1) - slope_square),
                   center_rate / sqrt(speed_square)};
}

}  // namespace skelconv::canal
