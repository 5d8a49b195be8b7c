// codegen/segment_moments.cpp — see segment_moments.hpp.
#include "segment_moments.hpp"

#include <stdexcept>

namespace skelconv::codegen {

// Stand-ins for the helpers of include/skelconv/detail/stable_recurrence.hpp.
DECLARE_FUNCTION_7P(J_downward)
REGISTER_FUNCTION(J_downward, dummy())
DECLARE_FUNCTION_7P(J_upward_compact)
REGISTER_FUNCTION(J_upward_compact, dummy())

using GiNaC::ex;
using Mode = RecurrenceDirection::Mode;
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
  if (auto it = J_memo_.find(n); it != J_memo_.end()) return it->second;
  ex value;
  const int anchor = direction_.anchor;
  if (direction_.mode == Mode::down_from_top && n >= 2) {
    if (n > anchor) throw std::logic_error("J above the downward anchor");
    value = n == anchor ? J_downward(n, s_.a, s_.D, s_.lo.slope, s_.lo.q, s_.hi.slope, s_.hi.q)
                        : up_index_to_lower(n + 2);
  } else if (direction_.mode == Mode::up_from_bottom && n <= -1) {
    if (n < anchor) throw std::logic_error("J below the upward anchor");
    value = n == anchor ? J_upward_compact(n, s_.a, s_.D, s_.lo.slope, s_.lo.q, s_.hi.slope, s_.hi.q)
                        : lower_index_to_up(n);
  } else if (n == 2) {
    value = s_.J2;
  } else if (n >= 3) {
    value = lower_index_to_up(n);
  } else {
    value = up_index_to_lower(n + 2);
  }
  J_memo_.emplace(n, value);
  return value;
}

// Recurrence (1) at index m: (m−2) D J_m + a (3−m) J_{m−2} = [(a t − b) q^(1−m/2)].
ex MomentRecurrence::lower_index_to_up(int m) {
  return (recurrence_boundary(m) - s_.a * (3 - m) * J(m - 2)) / ((m - 2) * s_.D);
}
ex MomentRecurrence::up_index_to_lower(int m) {
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
