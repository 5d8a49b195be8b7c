// skelconv/polygon_field.hpp — the convolution field of a planar polygon
// (SPEC §3, Hubert 2012 §5–8), by the contour formula: a sum over the edges,
// no triangulation.
//
//     f(P) = ∬_Ω K(|P − Q|) dQ
//
// This is the contract between the runtime (skelconv/polygon.hpp validates
// the polygon once) and the generated per-edge kernels. The caller
// guarantees: at least 3 vertices in boundary order, counter-clockwise about
// the unit normal `normal`, coplanar, simple, non-zero area; a kernel degree
// the table supports (polygon_supported_degrees).
//
// STUB: the implementation lands with issue 3; until then every evaluation
// throws std::logic_error.
#pragma once

#include <array>
#include <span>
#include <stdexcept>
#include <vector>

#include "skelconv/segment_input.hpp"  // KernelFamily

namespace skelconv {

/// A validated polygon and its kernel, on scalar type T.
template <class T>
struct PolygonInput {
  std::span<const std::array<T, 3>> vertices;  ///< boundary order, CCW about normal
  std::array<T, 3> normal{};                   ///< unit normal of the plane
  KernelFamily family = KernelFamily::inverse;
  int degree = 3;  ///< i of SPEC §1
  T s = T(1);      ///< Cauchy sharpness (cauchy only)
  T R = T(1);      ///< support radius (compact only)
};

/// The degrees the generated table offers for polygons, ascending:
/// inverse 3…12, cauchy 3…12, compact 4, 6, …, 12.
inline std::vector<int> polygon_supported_degrees(KernelFamily family) {
  std::vector<int> degrees;
  if (family == KernelFamily::compact) {
    for (int i = 4; i <= 12; i += 2) degrees.push_back(i);
  } else {
    for (int i = 3; i <= 12; ++i) degrees.push_back(i);
  }
  return degrees;
}

/// f(P). Inverse kernels with P in the closed polygon (z = 0 exactly, P̄ in Ω
/// or on its boundary) give +inf (the integral diverges there).
template <class T>
T polygon_f(const PolygonInput<T>&, const std::array<T, 3>&) {
  throw std::logic_error("polygon_f: not implemented yet");
}

/// ∇f(P); (+inf, +inf, +inf) where f is +inf.
template <class T>
std::array<T, 3> polygon_grad(const PolygonInput<T>&, const std::array<T, 3>&) {
  throw std::logic_error("polygon_grad: not implemented yet");
}

/// f(P) and ∇f(P) together.
template <class T>
T polygon_f_and_grad(const PolygonInput<T>&, const std::array<T, 3>&, std::array<T, 3>&) {
  throw std::logic_error("polygon_f_and_grad: not implemented yet");
}

}  // namespace skelconv
