// codegen/segment_moments.cpp — see segment_moments.hpp.
#include "segment_moments.hpp"

#include <stdexcept>

namespace skelconv::codegen {

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::pow;

ex MomentRecurrence::half_power(const QuadraticEnd& end, int e) const {
  if (e % 2 == 0) return pow(end.q, e / 2);
  // q^(e/2) = q^((e−1)/2) √q for e > 0, and q^((e+1)/2) / √q for e < 0: every
  // half-integer power shares the one √q of its end.
  return e > 0 ? pow(end.q, (e - 1) / 2) * end.root : pow(end.q, (e + 1) / 2) / end.root;
}

ex MomentRecurrence::recurrence_boundary(int n) const {
  return s_.hi.slope * half_power(s_.hi, 2 - n) - s_.lo.slope * half_power(s_.lo, 2 - n);
}

ex MomentRecurrence::J(int n) {
  if (n == 0) return s_.hi.t - s_.lo.t;
  if (n == 1) return s_.J1;
  if (n == 2) return s_.J2;
  if (n >= 3) {
    // Upwards: J_n = ([…] − a(3−n) J_{n−2}) / ((n−2) D).
    return (recurrence_boundary(n) - s_.a * (3 - n) * J(n - 2)) / ((n - 2) * s_.D);
  }
  // Downwards (n ≤ −1), recurrence (1) at index m = n + 2 ≤ 1:
  // J_n = ([…]_m − (m−2) D J_m) / (a (3−m)).
  const int m = n + 2;
  return (recurrence_boundary(m) - (m - 2) * s_.D * J(m)) / (s_.a * (3 - m));
}

ex MomentRecurrence::M(int k, int n) {
  if (k < 0) throw std::logic_error("negative moment");
  const auto key = std::make_pair(k, n);
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  ex value;
  if (k == 0) {
    value = J(n);
  } else if (k == 1) {
    const ex boundary = n == 2 ? numeric(1, 2) * s_.log_ratio
                               : (half_power(s_.hi, 2 - n) - half_power(s_.lo, 2 - n)) / (2 - n);
    value = (s_.b * J(n) + boundary) / s_.a;
  } else {
    value = (M(k - 2, n - 2) + 2 * s_.b * M(k - 1, n) - s_.c * M(k - 2, n)) / s_.a;
  }
  memo_.emplace(key, value);
  return value;
}

}  // namespace skelconv::codegen
