// skelconv/detail/exp_pieces.hpp — e^(−x) in normal pieces, for a product
// c e^(−x) whose factor e^(−x) alone would be subnormal or 0 while c lifts
// the product back into the normal range (the Gaussian kernel b e^(−a r²)
// with a large height b: b = 1e300 at r = 28/√a is 3.3e-41, computed as 0 by
// the plain product). The Gaussian point kernel (kernels/gaussian.hpp) and
// segment (primitives/segment_gaussian.hpp) both apply it.
#pragma once

#include <cmath>
#include <limits>

namespace skelconv::detail {

/// e^(−x), x ≥ 0, as `count` equal factors e^(−x/count) (x/count exact), each
/// a normal number: count is 1 where e^(−x) itself is normal (x below ~700
/// in double), 2 or 4 beyond, and 0 below e^(−2800) (or for a NaN x), where
/// the product is 0 in double whatever multiplies it. Apply the first factor
/// with the large coefficient and the others last (times_rest), so that only
/// the final product rounds into the subnormal range.
template <class T>
struct ExpPieces {
  int count = 1;
  T piece = T(1);  ///< e^(−x/count); e^(−x) itself when count is 1

  explicit ExpPieces(const T& x) {
    using std::exp;
    const T limit = T(0.69) * T(-std::numeric_limits<T>::min_exponent);  // e^(−limit) is normal
    if (!(x < T(4) * limit)) {
      count = 0;
      piece = T(0);
      return;
    }
    count = x < limit ? 1 : x < T(2) * limit ? 2 : 4;
    piece = exp(-x / T(count));
  }
  /// Whether e^(−x) times any double is 0.
  bool vanishes() const { return count == 0; }
  /// `value` times the factors after the first.
  T times_rest(T value) const {
    for (int k = 1; k < count; ++k) value *= piece;
    return value;
  }
  /// c e^(−x): c times the first factor, then the others.
  T times(const T& c) const { return vanishes() ? T(0) : times_rest(c * piece); }
};

}  // namespace skelconv::detail
