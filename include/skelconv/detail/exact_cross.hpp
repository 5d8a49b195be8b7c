// skelconv/detail/exact_cross.hpp — the cross product AB × AP of exact double
// inputs, rounded once: the exact preamble of the generated segment code.
//
// Near the segment's line, AB × AP is a difference of nearly equal products,
// and in plain arithmetic each difference B − A, P − A already rounds by
// ε|AB|, ε|AP|: the cross product then carries an absolute error ~ε|AB||AP|,
// i.e. a relative error ε / sin∠(AB, AP). D = |AB × AP|² (docs/mathematics.md §2) enters
// every closed form near the line, so in plain arithmetic f loses up to 1e-10
// at 1e-6 |AB| from the line (measured on the verifier's default sweep).
//
// The generated kernels (codegen/segment_program_builder.hpp) compute the
// plain cross product first and call `segment_exact_cross` only where
// sin∠ < 1/16 (a cheap test on numbers they have anyway); above it the plain
// product's relative error is at most ~32ε.
//
// Method (error-free transformations, Ogita–Rump–Oishi 2005): each
// difference u = b − a is split exactly into u_hi + u_lo (TwoSum, six
// additions); each cross component u_j v_k − u_k v_j then is
//     u_hi,j v_hi,k − u_hi,k v_hi,j                    (TwoProduct by fma: exact)
//   + u_hi,j v_lo,k + u_lo,j v_hi,k − u_hi,k v_lo,j − u_lo,k v_hi,j
//   + O(ε²|u||v|)                                      (dropped)
// The two leading products differ by at most a few ulps where the
// component cancels, so their difference is exact (Sterbenz); the small
// terms add errors of order ε²|u||v|. The result is the exact component
// rounded to within ~2ε of itself, as long as |AB × AP| ≫ ε²|AB||AP|
// (sin∠ ≫ 1e-32): on the line itself (D = 0) the closed forms take their
// on-line forms anyway.
//
// Any scalar type with round-to-nearest +, −, × and an exact fused
// multiply-add found as `fma` (std::fma for double and long double,
// Boost.Multiprecision's for binary128) gives these guarantees in its own
// precision.
#pragma once

#include <cmath>

namespace skelconv {

/// x − y = difference + error exactly (Knuth's TwoSum, no ordering needed).
template <class T>
inline void exact_difference(const T& x, const T& y, T& difference, T& error) {
  difference = x - y;
  const T y_virtual = x - difference;   // what of x − y was kept, seen from x
  const T x_virtual = difference + y_virtual;
  error = (x - x_virtual) + (y_virtual - y);
}

/// One component u_j v_k − u_k v_j of u × v from the exact splits
/// u = uh + ul, v = vh + vl (see the header comment).
template <class T>
inline T exact_cross_component(const T& uh_j, const T& ul_j, const T& uh_k, const T& ul_k, const T& vh_j,
                               const T& vl_j, const T& vh_k, const T& vl_k) {
  using std::fma;
  const T first = uh_j * vh_k;
  const T first_error = fma(uh_j, vh_k, -first);
  const T second = uh_k * vh_j;
  const T second_error = fma(uh_k, vh_j, -second);
  const T small = (first_error - second_error) + ((uh_j * vl_k + ul_j * vh_k) - (uh_k * vl_j + ul_k * vh_j));
  return (first - second) + small;
}

/// AB × AP for A = (a0, a1, a2), B, P taken as exact: each component is
/// the exact value rounded to within ~2ε of itself. Fills cross[0..2].
/// (Argument list in the generated kernels' call convention: scalars, then
/// the array to fill.)
template <class T>
void segment_exact_cross(const T& a0, const T& a1, const T& a2, const T& b0, const T& b1, const T& b2, const T& p0,
                         const T& p1, const T& p2, T* cross) {
  T uh[3], ul[3], vh[3], vl[3];  // u = B − A, v = P − A, split exactly
  exact_difference(b0, a0, uh[0], ul[0]);
  exact_difference(b1, a1, uh[1], ul[1]);
  exact_difference(b2, a2, uh[2], ul[2]);
  exact_difference(p0, a0, vh[0], vl[0]);
  exact_difference(p1, a1, vh[1], vl[1]);
  exact_difference(p2, a2, vh[2], vl[2]);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    cross[i] = exact_cross_component(uh[j], ul[j], uh[k], ul[k], vh[j], vl[j], vh[k], vl[k]);
  }
}

}  // namespace skelconv
