// skelconv/canal/lorentz.hpp — oriented spheres, oriented planes and points
// of ℝ³ as vectors of the Lorentz space ℝ⁵ (canal-surfaces paper §2.1,
// Table 1 and eq. 1–3; the formulas are reconstructed in docs/canal.md §1).
//
// Conventions (all templated on the scalar type T):
//   * coordinate 0 is the time-like one:
//         L(x, y) = −x0 y0 + x1 y1 + x2 y2 + x3 y3 + x4 y4,   Q(u) = L(u, u);
//   * an oriented sphere has a centre c and a signed radius r ≠ 0; the sign
//     is the orientation: r > 0 means its unit normal (p − c)/r points
//     outwards, r < 0 inwards. It is the point of Λ⁴ = {Q = 1}
//         S(c, r) = ((|c|² − r² + 1)/(2r), c/r, (|c|² − r² − 1)/(2r)),
//     so S(c, −r) = −S(c, r), and back r = 1/(x0 − x4), c = r (x1, x2, x3);
//   * an oriented plane {x : n·x = d}, |n| = 1, oriented by n, is the point
//     (d, n, d) of Λ⁴ (x0 = x4: a sphere of infinite radius);
//   * a point p of ℝ³ is the light-cone vector
//         P(p) = ((|p|² + 1)/2, p, (|p|² − 1)/2)       (Q(P) = 0, x0 − x4 = 1),
//     and any non-zero multiple of it stands for the same point.
// With these, for spheres S1, S2, a plane Π and a point p:
//     L(S1, S2) = (r1² + r2² − |c1 − c2|²) / (2 r1 r2)
//               = cos of the angle between the oriented normals where they
//                 meet: 0 orthogonal, +1 tangent with the same orientation
//                 at the contact, −1 tangent with opposite orientations,
//                 |L| > 1 no common point;
//     L(Π, S)   = (n·c − d)/r;       L(P(p), S) = −(|p − c|² − r²)/(2r).
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Core>
#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::canal {

template <class T>
using Vector5 = Eigen::Matrix<T, 5, 1>;
template <class T>
using Vector3 = Eigen::Matrix<T, 3, 1>;

/// An oriented sphere: centre and signed radius (≠ 0; the sign is the orientation).
template <class T>
struct Sphere {
  Vector3<T> center = Vector3<T>::Zero();
  T radius = T(1);
};

/// An oriented plane {x : normal·x = offset}, |normal| = 1, oriented by normal.
template <class T>
struct Plane {
  Vector3<T> normal = Vector3<T>::UnitZ();
  T offset = T(0);
};

/// The Lorentz form L(x, y) = −x0 y0 + x1 y1 + x2 y2 + x3 y3 + x4 y4.
template <class T>
T lorentz(const Vector5<T>& x, const Vector5<T>& y) {
  return -x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] + x[4] * y[4];
}

/// Q(u) = L(u, u): > 0 space-like, 0 light-like, < 0 time-like.
template <class T>
T lorentz_square(const Vector5<T>& u) {
  return lorentz(u, u);
}

/// Rounding of Q: Q(u) is computed with an error of a few ε ‖u‖² (‖·‖ the
/// Euclidean norm of ℝ⁵), so its sign means something only when
/// |Q(u)| > tolerance ‖u‖². This default, 16 ε of T, is what the functions
/// below use to call a vector light-like unless told otherwise.
template <class T>
constexpr T default_light_cone_tolerance() {
  return T(16) * std::numeric_limits<T>::epsilon();
}

/// True when |Q(u)| ≤ tolerance ‖u‖²: u is light-like as far as its
/// rounding can tell (u = 0 included).
template <class T>
bool is_light_like(const Vector5<T>& u, T tolerance = default_light_cone_tolerance<T>()) {
  using std::abs;
  return abs(lorentz_square(u)) <= tolerance * u.squaredNorm();
}

// --- Spheres, planes and points → ℝ⁵ ------------------------------------------

/// S(c, r) ∈ Λ⁴. Throws InputError("radius", ...) if r is 0 or not finite,
/// InputError if the coordinates overflow (|c|² − r² or 1/r beyond the
/// range of T).
template <class T>
Vector5<T> sphere_vector(const Sphere<T>& sphere) {
  using std::isfinite;
  const T r = sphere.radius;
  if (!(r != T(0)) || !isfinite(double(r))) {
    throw InputError(fmt::format("must be a finite non-zero number (a sphere of radius 0 is a point), got {}",
                                 double(r)),
                     "radius");
  }
  const Vector3<T>& c = sphere.center;
  const T power = c.squaredNorm() - r * r;  // |c|² − r², the power of the origin
  Vector5<T> x;
  x << (power + T(1)) / (T(2) * r), c / r, (power - T(1)) / (T(2) * r);
  if (!x.allFinite()) {
    throw InputError(fmt::format("centre ({}, {}, {}) and radius {} overflow the coordinates of the sphere "
                                 "(|c|² − r² or 1/r beyond the floating-point range)",
                                 double(c[0]), double(c[1]), double(c[2]), double(r)));
  }
  return x;
}

/// (d, n, d) ∈ Λ⁴ for the plane {x : n·x = d}; n need not be a unit vector
/// (n and d are divided by |n|). Throws InputError("normal", ...) if n = 0.
template <class T>
Vector5<T> plane_vector(const Plane<T>& plane) {
  const T length = plane.normal.norm();
  if (!(length > T(0))) throw InputError("must be a non-zero vector", "normal");
  const T d = plane.offset / length;
  Vector5<T> x;
  x << d, plane.normal / length, d;
  return x;
}

/// P(p) = ((|p|² + 1)/2, p, (|p|² − 1)/2), on the light cone.
template <class T>
Vector5<T> point_vector(const Vector3<T>& p) {
  const T square = p.squaredNorm();
  Vector5<T> x;
  x << (square + T(1)) / T(2), p, (square - T(1)) / T(2);
  return x;
}

// --- ℝ⁵ → spheres, planes and points ------------------------------------------

/// The sphere of x ∈ Λ⁴: r = 1/(x0 − x4), c = r (x1, x2, x3). Throws
/// EvaluationError if x0 = x4 (x is a plane) or the result is not finite.
template <class T>
Sphere<T> sphere_from_vector(const Vector5<T>& x) {
  using std::isfinite;
  const T inverse_radius = x[0] - x[4];
  const T r = T(1) / inverse_radius;
  Sphere<T> sphere{r * x.template segment<3>(1), r};
  if (!(inverse_radius != T(0)) || !isfinite(double(r)) || !sphere.center.allFinite()) {
    throw EvaluationError("the vector is a plane (x0 = x4), not a sphere of finite radius");
  }
  return sphere;
}

/// True when x ∈ Λ⁴ is a plane: |x0 − x4| ≤ tolerance (|x0| + |x4|).
template <class T>
bool is_plane_vector(const Vector5<T>& x, T tolerance = default_light_cone_tolerance<T>()) {
  using std::abs;
  return abs(x[0] - x[4]) <= tolerance * (abs(x[0]) + abs(x[4]));
}

/// The plane of x ∈ Λ⁴ with x0 = x4 (see is_plane_vector): n = (x1, x2, x3)
/// normalised, d = (x0 + x4)/2 divided by the same length. Throws
/// EvaluationError if x is not a plane to `tolerance`.
template <class T>
Plane<T> plane_from_vector(const Vector5<T>& x, T tolerance = default_light_cone_tolerance<T>()) {
  const T length = x.template segment<3>(1).norm();
  if (!is_plane_vector(x, tolerance) || !(length > T(0))) {
    throw EvaluationError(fmt::format("the vector is not a plane: x0 − x4 = {}", double(x[0] - x[4])));
  }
  return {x.template segment<3>(1) / length, (x[0] + x[4]) / (T(2) * length)};
}

/// The point of ℝ³ of a light-cone vector x (any non-zero multiple of
/// P(p)): p = (x1, x2, x3)/(x0 − x4). Throws InputError if x is not
/// light-like to `tolerance` (is_light_like) or is the point at infinity
/// (x0 = x4).
template <class T>
Vector3<T> point_from_vector(const Vector5<T>& x, T tolerance = default_light_cone_tolerance<T>()) {
  using std::isfinite;
  if (!is_light_like(x, tolerance) || x.squaredNorm() == T(0)) {
    throw InputError(fmt::format("not on the light cone: Q = {}", double(lorentz_square(x))));
  }
  const Vector3<T> p = x.template segment<3>(1) / (x[0] - x[4]);
  if (!p.allFinite()) throw InputError("the point at infinity (x0 = x4) is not a point of ℝ³");
  return p;
}

// --- Incidence, tangency, angles ---------------------------------------------

/// True when p lies on the sphere: |L(P(p), S)| · 2/|r| = ||p − c|²/r² − 1|
/// is at most `relative_tolerance`.
template <class T>
bool point_on_sphere(const Vector3<T>& p, const Sphere<T>& sphere, T relative_tolerance) {
  using std::abs;
  const T l = lorentz(point_vector(p), sphere_vector(sphere));  // −(|p − c|² − r²)/(2r)
  return abs(T(2) * l / sphere.radius) <= relative_tolerance;
}

/// L of two unit vectors of Λ⁴ (spheres or planes): the cosine of the angle
/// between their oriented normals where they meet (|L| ≤ 1); |L| > 1 when
/// they do not meet.
template <class T>
T angle_cosine(const Vector5<T>& s1, const Vector5<T>& s2) {
  return lorentz(s1, s2);
}

/// The angle in [0, π] between the oriented normals of two intersecting
/// spheres or planes, or nullopt when they do not meet (|L| > 1).
template <class T>
std::optional<T> intersection_angle(const Vector5<T>& s1, const Vector5<T>& s2) {
  using std::abs;
  using std::acos;
  const T l = lorentz(s1, s2);
  if (abs(l) > T(1)) return std::nullopt;
  return acos(l);
}

/// Tangent: |L| = 1 to `tolerance` (+1: same orientation at the contact).
template <class T>
bool are_tangent(const Vector5<T>& s1, const Vector5<T>& s2, T tolerance) {
  using std::abs;
  return abs(abs(lorentz(s1, s2)) - T(1)) <= tolerance;
}

/// Tangent with the same orientation at the contact point: L = +1 to
/// `tolerance`. This is the tangency that makes Q(s1 − s2) = 2 − 2L vanish.
template <class T>
bool are_oriented_tangent(const Vector5<T>& s1, const Vector5<T>& s2, T tolerance) {
  using std::abs;
  return abs(lorentz(s1, s2) - T(1)) <= tolerance;
}

/// Orthogonal: L = 0 to `tolerance`.
template <class T>
bool are_orthogonal(const Vector5<T>& s1, const Vector5<T>& s2, T tolerance) {
  using std::abs;
  return abs(lorentz(s1, s2)) <= tolerance;
}

// --- Lorentz inversion (§2.2.1, Definition 1) ------------------------------------

/// The inversion of pole Ω and power k ≠ 0: M′ = Ω + k (M − Ω)/Q(M − Ω).
/// It is an involution of ℝ⁵ minus the light cone C_Ω = {M : Q(M − Ω) = 0},
/// where it is undefined: when |Q(M − Ω)| ≤ tolerance ‖M − Ω‖² (M on C_Ω as
/// far as rounding can tell, M = Ω included) it throws EvaluationError.
template <class T>
Vector5<T> lorentz_inversion(const Vector5<T>& m, const Vector5<T>& pole, T k,
                             T tolerance = default_light_cone_tolerance<T>()) {
  const Vector5<T> from_pole = m - pole;
  if (is_light_like(from_pole, tolerance)) {
    throw EvaluationError(fmt::format(
        "the point is on the light cone of the pole (Q(M − Ω) = {}): the Lorentz inversion is undefined there",
        double(lorentz_square(from_pole))));
  }
  return pole + (k / lorentz_square(from_pole)) * from_pole;
}

/// dS/dt for a sphere moving with dc/dt = c′, dr/dt = r′ (the differential
/// of S(c, r) above): (1/r) [(c·c′ − r r′, c′, c·c′ − r r′) − r′ S(c, r)].
/// On Λ⁴ it satisfies L(S, S′) = 0 and Q(S′) = (|c′|² − r′²)/r².
template <class T>
Vector5<T> sphere_tangent(const Sphere<T>& sphere, const Vector3<T>& center_rate, T radius_rate) {
  const Vector3<T>& c = sphere.center;
  const T r = sphere.radius;
  const T a = c.dot(center_rate) - r * radius_rate;
  Vector5<T> moving;
  moving << a, center_rate, a;
  return (moving - radius_rate * sphere_vector(sphere)) / r;
}

}  // namespace skelconv::canal
