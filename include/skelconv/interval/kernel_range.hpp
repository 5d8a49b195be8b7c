// skelconv/interval/kernel_range.hpp — the range of a radial kernel trait
// (skelconv/kernels/) over an interval of distances, enclosed.
//
// Every trait is non-increasing in r (radial_kernel.hpp), so over
// r ∈ [r0, r1] the kernel takes values in [K(r1), K(r0)]: the notes'
// inclusion function (part 3e), written for any kernel. The two ends are
// evaluated with the trait's own value() on a point interval, so the
// formula is written once (in the trait) and its rounding is enclosed.
// Beyond a compact support the trait returns 0: with r0 ≥ R the range is
// [0, 0], with r1 ≥ R > r0 it is [0, K(r0)], as in the notes.
#pragma once

#include <limits>

#include "skelconv/interval/interval.hpp"

namespace skelconv::interval {

/// [K(r.upper), K(r.lower)] outward-rounded; K(0) of a kernel singular at 0
/// (inverse) is +inf, and K(+inf) = 0 for every family.
template <class Kernel>
Interval kernel_range(const Kernel& kernel, const Interval& r) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (Kernel::singular_at_zero && r.upper() <= 0.0) return Interval(infinity);  // the box is the centre
  const double low = r.upper() == infinity ? 0.0 : kernel.value(Interval(r.upper())).lower();
  double high = infinity;
  if (!(Kernel::singular_at_zero && r.lower() <= 0.0)) high = kernel.value(Interval(r.lower())).upper();
  return Interval(low < 0.0 ? 0.0 : low, high);
}

}  // namespace skelconv::interval
