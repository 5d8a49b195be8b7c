// verify/extended_precision.hpp — the extended-precision type of the verifier.
//
// The reference integrals (docs/mathematics.md §2 definition, by quadrature) and the
// "extended" evaluation of the generated code use IEEE binary128 (113-bit
// significand, ≈34 decimal digits) through Boost.Multiprecision's float128
// wrapper of GCC's __float128 (libquadmath). The brief requires ≥ 30 digits so
// that a reference accurate to ~1e-25 can judge a double result (~1e-16).
#pragma once

#include <array>
#include <cstddef>

#include <boost/multiprecision/float128.hpp>

namespace skelconv::verify {

using extended = boost::multiprecision::float128;

/// A 3-vector in any scalar type (the generated API uses std::array<T, 3>).
template <class T>
using Vec3 = std::array<T, 3>;

/// Exact widening: every double is a float128.
inline Vec3<extended> widen(const Vec3<double>& v) { return {extended(v[0]), extended(v[1]), extended(v[2])}; }

template <class T>
T dot(const Vec3<T>& u, const Vec3<T>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

template <class T>
Vec3<T> sub(const Vec3<T>& u, const Vec3<T>& v) {
  return {u[0] - v[0], u[1] - v[1], u[2] - v[2]};
}

template <class T>
Vec3<T> axpy(const T& alpha, const Vec3<T>& x, const Vec3<T>& y) {  // alpha x + y
  return {alpha * x[0] + y[0], alpha * x[1] + y[1], alpha * x[2] + y[2]};
}

template <class T>
T norm(const Vec3<T>& v) {
  using std::sqrt;
  return sqrt(dot(v, v));
}

}  // namespace skelconv::verify
