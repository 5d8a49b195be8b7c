// skelconv/detail/clip.hpp — the part of a segment inside a ball (compact kernels).
//
// For k_R^i the field only sees the part of [A,B] within distance R of P
// (Hubert 2012 §3.4). We keep the segment's own parameter t, so the weight
// polynomial w(t) needs no re-parameterisation: the generated code integrates
// over [t0, t1] ⊆ [0, 1].
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "skelconv/detail/support_gap.hpp"

namespace skelconv {

/// Parameter interval of a segment inside a ball.
template <class T>
struct ParameterInterval {
  T t0;
  T t1;
};

/// Solves |P − Γ(t)|² < R² for t ∈ [0, 1], i.e. a t² − 2 b t + c − R² < 0 with
/// a = |AB|², b = AB·AP, c = |AP|². Empty (std::nullopt) when the segment
/// misses the open ball. The discriminant b² − a(c − R²) = a R² − |AB × AP|²
/// is formed from the cross product, so it keeps its digits near the line.
template <class T>
std::optional<ParameterInterval<T>> clip_to_ball(const std::array<T, 3>& A, const std::array<T, 3>& B,
                                                 const std::array<T, 3>& P, const T& R) {
  using std::sqrt;
  const T ab[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
  const T ap[3] = {P[0] - A[0], P[1] - A[1], P[2] - A[2]};
  const T a = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const T b = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
  const T cx = ab[1] * ap[2] - ab[2] * ap[1];
  const T cy = ab[2] * ap[0] - ab[0] * ap[2];
  const T cz = ab[0] * ap[1] - ab[1] * ap[0];
  const T disc = a * R * R - (cx * cx + cy * cy + cz * cz);
  if (!(disc > T(0))) return std::nullopt;  // tangent or missing: measure zero
  // Within its rounding of 0 (a few ε a R²), disc cannot tell a line tangent
  // to the sphere from one that cuts it: P on the support sphere beside an
  // end would get a chord of width ~√ε where the exact one is a point, and
  // the generated chord formulas, which read the exact gap
  // (skelconv/detail/support_gap.hpp), would divide 0 by 0 there. Decide
  // those cases on that same exact gap.
  if (disc <= T(64) * std::numeric_limits<T>::epsilon() * (a * R * R)) {
    T gap;
    exact_line_support_gap<T>(A[0], A[1], A[2], B[0], B[1], B[2], P[0], P[1], P[2], R, &gap);
    if (!(gap > T(0))) return std::nullopt;
  }
  const T half_width = sqrt(disc) / a;     // the roots are b/a ± half_width
  const T centre = b / a;
  const T t0 = std::max(T(0), centre - half_width);
  const T t1 = std::min(T(1), centre + half_width);
  if (!(t0 < t1)) return std::nullopt;
  return ParameterInterval<T>{t0, t1};
}

}  // namespace skelconv
