// skelconv/double_word.hpp — double-word arithmetic (a value hi + lo) for
// the exact preambles: support_gap.hpp, plane_height.hpp
// and the Gaussian segment (segment_gaussian.hpp) form differences and
// products of exact inputs in it and round once at the end.
//
// Each double-word × errs by a few ε² of its result, each + by ~ε² of its
// operands (the simple sum, Joldes, Muller and Popescu, ACM TOMS 2017,
// Algorithm 5: its relative bound fails under cancellation, but its absolute
// error stays ~ε² |x|, which is what the preambles need). Any scalar type
// with round-to-nearest +, −, × and an exact fused multiply-add (see
// skelconv/exact_cross.hpp) gets these guarantees in its own precision.
#pragma once

#include <cmath>

#include "skelconv/exact_cross.hpp"

namespace skelconv {
namespace detail {

/// A double-word number hi + lo (|lo| ≤ ulp(hi)/2 after normalisation).
template <class T>
struct DoubleWord {
  T hi;
  T lo;
};

/// x + y as a double-word number (TwoSum of the leading parts; the trailing
/// parts added into the error and the pair renormalised).
template <class T>
DoubleWord<T> word_add(const DoubleWord<T>& x, const DoubleWord<T>& y) {
  T sum, error;
  exact_difference(x.hi, -y.hi, sum, error);  // x.hi + y.hi = sum + error exactly
  error = error + (x.lo + y.lo);
  DoubleWord<T> out;
  exact_difference(sum, -error, out.hi, out.lo);
  return out;
}

template <class T>
DoubleWord<T> word_negate(const DoubleWord<T>& x) {
  return {-x.hi, -x.lo};
}

/// x × y as a double-word number (TwoProduct of the leading parts by fma,
/// the cross terms added into its error; lo × lo is below ε² |xy|).
template <class T>
DoubleWord<T> word_multiply(const DoubleWord<T>& x, const DoubleWord<T>& y) {
  using std::fma;
  const T product = x.hi * y.hi;
  T error = fma(x.hi, y.hi, -product);
  error = error + (x.hi * y.lo + x.lo * y.hi);
  DoubleWord<T> out;
  exact_difference(product, -error, out.hi, out.lo);
  return out;
}

/// x − y for doubles x, y, exactly, as a double-word number.
template <class T>
DoubleWord<T> exact_word_difference(const T& x, const T& y) {
  DoubleWord<T> out;
  exact_difference(x, y, out.hi, out.lo);
  return out;
}

/// |u|² of a double-word vector.
template <class T>
DoubleWord<T> word_norm2(const DoubleWord<T> (&u)[3]) {
  DoubleWord<T> sum = word_multiply(u[0], u[0]);
  sum = word_add(sum, word_multiply(u[1], u[1]));
  return word_add(sum, word_multiply(u[2], u[2]));
}

}  // namespace detail

}  // namespace skelconv
