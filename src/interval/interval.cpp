// Implementation of skelconv/interval/interval.hpp (compiled with
// -frounding-math, src/CMakeLists.txt).
#include "skelconv/interval/interval.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::interval {

Box box_from_corners(std::span<const double> v) {
  if (v.size() != 6) {
    throw InputError(fmt::format("expected six numbers \"x0 y0 z0 x1 y1 z1\", got {} value{}", v.size(),
                                 v.size() == 1 ? "" : "s"));
  }
  for (double x : v)
    if (!std::isfinite(x)) throw InputError(fmt::format("every coordinate must be finite, got {}", x));
  Box box{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
  for (int i = 0; i < 3; ++i) {
    if (box.lo[i] > box.hi[i]) {
      throw InputError(fmt::format("min corner above max corner along {}: {} > {}", "xyz"[i], box.lo[i], box.hi[i]));
    }
  }
  return box;
}

IntervalPoint to_interval_point(const Box& box) {
  return {Interval(box.lo.x(), box.hi.x()), Interval(box.lo.y(), box.hi.y()), Interval(box.lo.z(), box.hi.z())};
}

IntervalPoint to_interval_point(const Vec3& p) { return {Interval(p.x()), Interval(p.y()), Interval(p.z())}; }

Interval interval_square(const Interval& x) {
  // boost::numeric::square is exactly the notes' three cases, with the
  // products rounded outward by the policy.
  return boost::numeric::square(x);
}

Interval squared_distance(const Box& box, const Vec3& c) {
  const IntervalPoint b = to_interval_point(box);
  return interval_square(b[0] - c.x()) + interval_square(b[1] - c.y()) + interval_square(b[2] - c.z());
}

Interval squared_distance(const IntervalPoint& p, const IntervalPoint& q) {
  return interval_square(p[0] - q[0]) + interval_square(p[1] - q[1]) + interval_square(p[2] - q[2]);
}

Interval interval_sqrt(const Interval& x) {
  return boost::numeric::sqrt(Interval(std::max(0.0, x.lower()), std::max(0.0, x.upper())));
}

Interval safe_product(const Interval& w, const Interval& k) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (k.upper() == 0.0 || (w.lower() == 0.0 && w.upper() == 0.0)) return Interval(0.0);
  if (k.upper() < infinity) return w * k;
  // k reaches +inf: the box touches an inverse kernel's skeleton, where the
  // field evaluates to the +inf marker whatever the weight's sign
  // (skeleton/blend.hpp, docs/cli.md). The enclosure holds what the field
  // prints, so hi = +inf even for a negative weight, whose limit near the
  // skeleton is −inf; k = +inf exactly (a point of the skeleton) is the
  // marker alone.
  if (k.lower() == infinity) return Interval(infinity);
  // k = [k0, +inf]: w k ranges from −inf (if w reaches below 0) or w k0, to
  // the marker +inf.
  const Interval finite = w * Interval(k.lower());
  return Interval(w.lower() < 0.0 ? -infinity : finite.lower(), infinity);
}

Interval hull(const Interval& a, const Interval& b) { return boost::numeric::hull(a, b); }

}  // namespace skelconv::interval
