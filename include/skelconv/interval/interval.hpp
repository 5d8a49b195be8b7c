// skelconv/interval/interval.hpp — the interval type of the enclosures
// (docs/bound.md) and the interval geometry of the exam notes (part 3d).
//
// Interval is Boost.Interval on double with Boost's own rounding policies:
// every operation rounds its lower end down and its upper end up. The policy
// is rounded_arith_opp (inside rounded_transc_opp, under save_state): the
// FPU is switched to upward rounding once per operation and lower ends are
// computed as −(−x − y), so no two identical operations run under different
// modes. The simpler rounded_arith_std (switch down, add, switch up, add)
// came out WRONG here: GCC merges the two identical additions across the
// mode switch (GCC bug 34678, even with -frounding-math), giving
// Interval(0.1) + Interval(0.2) zero width (tests/interval_test.cpp,
// RoundsOutward). exp and log (the Gaussian kernel, the super-elliptic
// blend's powers) call the C library under the directed mode; their
// soundness rests on glibc's exp/log honouring it (they are accurate to
// < 1 ulp in every rounding mode), which the soundness sweep exercises.
// No rounding is done by hand. EVERY translation unit that does arithmetic
// on Interval must be compiled with -frounding-math (src/CMakeLists.txt: the
// OBJECT library skelconv_interval, away from the generated kernels):
// without it GCC folds Interval(0.1) + Interval(0.2) at compile time into a
// zero-width, wrong enclosure (tests/interval_test.cpp, RoundsOutward).
// Reading lower() and upper() needs nothing.
//
// checking_base: intervals may have infinite ends ([0, +inf] is the
// enclosure of an inverse kernel over a box touching its skeleton); the code
// never forms 0 · inf (safe_product below).
#pragma once

#include <array>
#include <span>

#include <boost/numeric/interval.hpp>

#include "skelconv/geometry.hpp"

namespace skelconv::interval {

using Policies = boost::numeric::interval_lib::policies<
    boost::numeric::interval_lib::save_state<boost::numeric::interval_lib::rounded_transc_opp<double>>,
    boost::numeric::interval_lib::checking_base<double>>;
using Interval = boost::numeric::interval<double, Policies>;

/// An axis-aligned box [lo, hi] (lo ≤ hi coordinatewise).
struct Box {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  Vec3 center() const { return 0.5 * (lo + hi); }
  double diagonal() const { return (hi - lo).norm(); }
};

/// The box with corners (v[0], v[1], v[2]) and (v[3], v[4], v[5]), the form
/// `skelconv bound` reads and the Python module's Skeleton.bound takes.
/// Throws InputError (no location: the caller knows the line or row) unless
/// v holds six finite numbers with the first corner below the second.
Box box_from_corners(std::span<const double> v);

/// A point with interval coordinates (a box, or a rounded computed point).
using IntervalPoint = std::array<Interval, 3>;

IntervalPoint to_interval_point(const Box& box);
IntervalPoint to_interval_point(const Vec3& p);

/// The notes' interval square: [a², b²] if a ≥ 0, [b², a²] if b ≤ 0, and
/// [0, max(−a, b)²] when a < 0 < b (not [a, b]·[a, b], which would be
/// [ab, …] < 0), rounded outward.
Interval interval_square(const Interval& x);

/// The notes' squared distance from every point of `box` to the point c:
/// Σ_i (X_i − c_i)² with the interval square.
Interval squared_distance(const Box& box, const Vec3& c);

/// Squared distance between two interval points (boxes): the range of
/// |P − Q|² over P ∈ p, Q ∈ q, enclosed.
Interval squared_distance(const IntervalPoint& p, const IntervalPoint& q);

/// √ of a non-negative enclosure (its negative part, from rounding, is cut).
Interval interval_sqrt(const Interval& x);

/// w · k for k ⊂ [0, +inf], w finite or not, without forming 0 · inf
/// (0 · anything is 0: a zero factor contributes nothing). Where k reaches
/// +inf (a box touching an inverse skeleton) the upper end is +inf whatever
/// w's sign: on the skeleton the field is the +inf marker (docs/bound.md).
Interval safe_product(const Interval& w, const Interval& k);

/// The smallest interval holding a and b.
Interval hull(const Interval& a, const Interval& b);

}  // namespace skelconv::interval
