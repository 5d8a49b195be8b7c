// skelconv/detail/integer_power.hpp — x^n for an integer n, the one place the
// hand-written runtime raises to integer powers (the generated code has its
// own memoised powers, written by the generator).
#pragma once

namespace skelconv {

/// x^n by binary powering (⌊log2 n⌋ + popcount(n) − 1 products: 3 for n = 5,
/// instead of 4 by repeated multiplication); n < 0 gives (1/x)^|n|, n = 0
/// gives 1 (also for x = 0). Works for any T with *, / and T(1).
template <class T>
T integer_power(T x, int n) {
  if (n < 0) {
    x = T(1) / x;
    n = -n;
  }
  T result(1);
  while (n > 0) {
    if (n & 1) result *= x;
    n >>= 1;
    if (n > 0) x *= x;
  }
  return result;
}

}  // namespace skelconv
