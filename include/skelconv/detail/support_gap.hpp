// skelconv/detail/support_gap.hpp — how far a compact support reaches past a point
// or a line, R² − d², from exact double inputs, rounded once (for a support
// that grazes the segment).
//
// Where the ball |X − P| ≤ R only grazes the segment, R and the distance d
// from P to the segment (to its line, or to an end) agree in their leading
// digits: R² − d² = δ R² with δ as small as the user likes. The field there
// is f ~ δ^((i+2)/2) (docs/mathematics.md §1, k_R^i), so each relative error of δ comes
// back (i+2)/2 times larger. In plain arithmetic δ R² is a difference of
// two numbers ~R², each rounded (P − E, B − A, the squares, the cross
// product): an absolute error ~ε R², i.e. ε/δ relative, 1e-10 at δ = 1e-6
// (measured in plain arithmetic: compact i15 f 1.4e-8 in the verifier's
// support_grazing region).
//
// Here every difference of inputs is split exactly (TwoSum), every product
// of such parts is a double-word number (TwoProduct by fma), and the sums
// are carried in double-word arithmetic (a value hi + lo). Each double-word
// × below errs by a few ε² of its result, each + by ~ε² of its operands
// (the simple sum, Joldes, Muller and Popescu, ACM TOMS 2017, Algorithm 5:
// its relative bound fails under cancellation, but its absolute error stays
// ~ε² |x|, which is what counts here), so the result is R² − d² with an
// error of a few ε² R² (ε² R² |AB|² for the line) plus one rounding: ~ε
// relative as long as δ ≫ ε.
//
// Any scalar type with round-to-nearest +, −, × and an exact fused
// multiply-add (see skelconv/detail/exact_cross.hpp) gets these guarantees in its
// own precision: double, long double, binary128.
#pragma once

#include <cmath>

#include "skelconv/detail/double_word.hpp"

namespace skelconv {

/// R² − |P − E|² for a point E = (e0, e1, e2) (a segment's end), with P and
/// R taken as exact: out[0] is the exact value rounded to within a few ε of
/// itself (header comment). (Argument list in the generated kernels' call
/// convention: scalars, then the array to fill.)
template <class T>
void exact_point_support_gap(const T& e0, const T& e1, const T& e2, const T& p0, const T& p1, const T& p2,
                             const T& R, T* out) {
  using detail::DoubleWord;
  const DoubleWord<T> d[3] = {detail::exact_word_difference(p0, e0), detail::exact_word_difference(p1, e1),
                              detail::exact_word_difference(p2, e2)};
  const DoubleWord<T> radius{R, T(0)};
  const DoubleWord<T> gap = detail::word_add(detail::word_multiply(radius, radius), detail::word_negate(detail::word_norm2(d)));
  out[0] = gap.hi + gap.lo;
}

/// R² |AB|² − |AB × AP|² = |AB|² (R² − h²), h the distance from P to the
/// line AB, with A, B, P and R taken as exact: out[0] is the exact value
/// rounded to within a few ε of itself (header comment).
template <class T>
void exact_line_support_gap(const T& a0, const T& a1, const T& a2, const T& b0, const T& b1, const T& b2, const T& p0,
                            const T& p1, const T& p2, const T& R, T* out) {
  using detail::DoubleWord;
  const DoubleWord<T> u[3] = {detail::exact_word_difference(b0, a0), detail::exact_word_difference(b1, a1),
                              detail::exact_word_difference(b2, a2)};
  const DoubleWord<T> v[3] = {detail::exact_word_difference(p0, a0), detail::exact_word_difference(p1, a1),
                              detail::exact_word_difference(p2, a2)};
  DoubleWord<T> cross[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    cross[i] = detail::word_add(detail::word_multiply(u[j], v[k]), detail::word_negate(detail::word_multiply(u[k], v[j])));
  }
  const DoubleWord<T> radius{R, T(0)};
  const DoubleWord<T> reach = detail::word_multiply(detail::word_multiply(radius, radius), detail::word_norm2(u));
  const DoubleWord<T> gap = detail::word_add(reach, detail::word_negate(detail::word_norm2(cross)));
  out[0] = gap.hi + gap.lo;
}

}  // namespace skelconv
