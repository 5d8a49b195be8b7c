// src/simd/lanes-inl.hpp — `Lanes`, a scalar type whose value is one Highway
// vector of doubles, so that the generated straight-line templates
// (generated/*.hpp, templated on the scalar type T) run on 2, 4 or 8 query
// points at once, unchanged (docs/simd.md).
//
// Per-target header in Highway's style: src/simd/*_batch.cpp include it once
// per target of foreach_target.h (AVX-512, AVX2, and the portable SCALAR
// fallback), each time into that target's namespace skelconv::simd::N_AVX2
// etc., compiled with that target's instruction set.
//
// What makes a generated template run on Lanes:
//   * arithmetic, sqrt, fma, min, max, atan2, log, asinh, cos are hidden friends found
//     by argument-dependent lookup (the generated code writes `using
//     std::sqrt; sqrt(x)`); every one performs exactly the IEEE operation the
//     scalar code performs on each lane (+ − × ÷ √ correctly rounded, min/max
//     as std::min/std::max select, including for ±0), so with
//     -ffp-contract=off (src/CMakeLists.txt) lane results equal the scalar
//     path bit for bit except through atan2, log and asinh: SLEEF's vector
//     versions with 1.0-ulp bounds (glibc's scalar ones are within 1 ulp too);
//   * a comparison gives a LaneMask; `if (mask)` and the kernel's `return
//     mask` convert it to bool through the Divergence of the running group
//     (divergence-inl.hpp): lanes that disagree with the group are set aside
//     and re-run later with lanes that take their side, so every form is
//     evaluated vectorised;
//   * the generated full `<name>_f_and_grad` runs on Lanes, every form
//     vectorised with the scalar path's own arithmetic: the Miller
//     recurrences run as many steps as the neediest lane (miller_steps, end
//     of this file); pow(x, n) is the C library's, lane by lane; the SCALIS
//     Gauss panels are loops over masks, and a pole where q underflows
//     hands the lanes to the scalar path (pole_too_close);
//   * Boost's Gauss–Legendre tables exist for floating-point types only: the
//     specialisation at the end reuses the double tables (nodes broadcast).
//
// Callers must inline the generated template into a function of this target
// (`flatten`, see segment_batch.cpp): a template defined outside the target
// region is compiled for the baseline instruction set unless inlined.
#if defined(SKELCONV_SIMD_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SKELCONV_SIMD_LANES_INL_H_
#undef SKELCONV_SIMD_LANES_INL_H_
#else
#define SKELCONV_SIMD_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <boost/math/quadrature/gauss.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "skelconv/detail/gauss_moments.hpp"
#include "skelconv/not_converged.hpp"
#include "skelconv/detail/stable_recurrence.hpp"
#include "src/simd/divergence.hpp"
#include "src/simd/sleef_declarations.hpp"

HWY_BEFORE_NAMESPACE();
namespace skelconv::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using LaneTag = hn::ScalableTag<double>;
using LaneVector = hn::Vec<LaneTag>;
using LaneVectorMask = hn::Mask<LaneTag>;

/// Lanes of one vector (1 for SCALAR, 4 for AVX2, 8 for AVX-512).
inline size_t lane_count() { return hn::Lanes(LaneTag()); }

/// The divergence bookkeeping of the group of lanes being evaluated; set by
/// run_group (group_runner-inl.hpp) around each generated call.
inline thread_local Divergence* current_divergence = nullptr;

// GCC 12 does not apply the target pragma to friend functions defined
// inside a class (they fail to inline Highway's ops), so the operators are
// free functions of this namespace, found by argument-dependent lookup.

/// The result of comparing two Lanes.
struct LaneMask {
  LaneVectorMask m;

  /// The branch every still-active lane takes (see Divergence::decide).
  operator bool() const {
    uint8_t bits[8] = {};
    hn::StoreMaskBits(LaneTag(), m, bits);
    return current_divergence->decide(bits[0]);
  }
};

inline LaneMask operator&&(LaneMask a, LaneMask b) { return {hn::And(a.m, b.m)}; }
inline LaneMask operator||(LaneMask a, LaneMask b) { return {hn::Or(a.m, b.m)}; }
inline LaneMask operator!(LaneMask a) { return {hn::Not(a.m)}; }

/// One double per lane.
struct Lanes {
  LaneVector v;

  Lanes() = default;
  Lanes(double x) : v(hn::Set(LaneTag(), x)) {}  // NOLINT: T(2), 2 * x in the generated code
  explicit Lanes(LaneVector x) : v(x) {}
  LaneVector vec() const { return v; }

  Lanes& operator+=(Lanes b) { v = hn::Add(v, b.v); return *this; }
  Lanes& operator-=(Lanes b) { v = hn::Sub(v, b.v); return *this; }
  Lanes& operator*=(Lanes b) { v = hn::Mul(v, b.v); return *this; }
  Lanes& operator/=(Lanes b) { v = hn::Div(v, b.v); return *this; }
};

inline Lanes operator+(Lanes a, Lanes b) { return Lanes(hn::Add(a.v, b.v)); }
inline Lanes operator-(Lanes a, Lanes b) { return Lanes(hn::Sub(a.v, b.v)); }
inline Lanes operator*(Lanes a, Lanes b) { return Lanes(hn::Mul(a.v, b.v)); }
inline Lanes operator/(Lanes a, Lanes b) { return Lanes(hn::Div(a.v, b.v)); }
inline Lanes operator-(Lanes a) { return Lanes(hn::Neg(a.v)); }

inline LaneMask operator<(Lanes a, Lanes b) { return {hn::Lt(a.v, b.v)}; }
inline LaneMask operator<=(Lanes a, Lanes b) { return {hn::Le(a.v, b.v)}; }
inline LaneMask operator>(Lanes a, Lanes b) { return {hn::Gt(a.v, b.v)}; }
inline LaneMask operator>=(Lanes a, Lanes b) { return {hn::Ge(a.v, b.v)}; }
inline LaneMask operator==(Lanes a, Lanes b) { return {hn::Eq(a.v, b.v)}; }
inline LaneMask operator!=(Lanes a, Lanes b) { return {hn::Ne(a.v, b.v)}; }

inline Lanes sqrt(Lanes a) { return Lanes(hn::Sqrt(a.v)); }
// a·b + c rounded once on the FMA targets (AVX2, AVX-512), as std::fma:
// skelconv/detail/exact_cross.hpp's error-free products need exactly that. The
// SCALAR target hands every point to the scalar path (find_group).
inline Lanes fma(Lanes a, Lanes b, Lanes c) { return Lanes(hn::MulAdd(a.v, b.v, c.v)); }
inline Lanes abs(Lanes a) { return Lanes(hn::Abs(a.v)); }
// std::min(a, b) is (b < a) ? b : a and std::max(a, b) is (a < b) ? b : a;
// the same selects here (hn::Min/Max differ for ±0 and NaN).
inline Lanes min(Lanes a, Lanes b) { return Lanes(hn::IfThenElse(hn::Lt(b.v, a.v), b.v, a.v)); }
inline Lanes max(Lanes a, Lanes b) { return Lanes(hn::IfThenElse(hn::Lt(a.v, b.v), b.v, a.v)); }

/// x^n as std::pow(double, int) computes it, lane by lane (once per Miller
/// recurrence: not worth a vector version that would round differently).
inline Lanes pow(Lanes x, int n) {
  const LaneTag d;
  alignas(64) double v[max_lanes];
  hn::Store(x.v, d, v);
  for (size_t k = 0; k < hn::Lanes(d); ++k) v[k] = std::pow(v[k], n);
  return Lanes(hn::Load(d, v));
}

// atan2, log, asinh, cos (polygons' angle integrals): SLEEF's 1.0-ulp functions for the vector targets; the
// portable target calls the C library lane by lane.
#if HWY_TARGET == HWY_AVX2
inline Lanes atan2(Lanes y, Lanes x) { return Lanes(LaneVector{Sleef_atan2d4_u10avx2(y.v.raw, x.v.raw)}); }
inline Lanes log(Lanes a) { return Lanes(LaneVector{Sleef_logd4_u10avx2(a.v.raw)}); }
inline Lanes asinh(Lanes a) { return Lanes(LaneVector{Sleef_asinhd4_u10avx2(a.v.raw)}); }
inline Lanes cos(Lanes a) { return Lanes(LaneVector{Sleef_cosd4_u10avx2(a.v.raw)}); }
#elif HWY_TARGET == HWY_AVX3
inline Lanes atan2(Lanes y, Lanes x) { return Lanes(LaneVector{Sleef_atan2d8_u10avx512f(y.v.raw, x.v.raw)}); }
inline Lanes log(Lanes a) { return Lanes(LaneVector{Sleef_logd8_u10avx512f(a.v.raw)}); }
inline Lanes asinh(Lanes a) { return Lanes(LaneVector{Sleef_asinhd8_u10avx512f(a.v.raw)}); }
inline Lanes cos(Lanes a) { return Lanes(LaneVector{Sleef_cosd8_u10avx512f(a.v.raw)}); }
#else
/// function(a_k, b_k) in every lane k, by the C library.
template <class Function>
Lanes per_lane(Function function, Lanes a, Lanes b) {
  const LaneTag d;
  alignas(64) double x[max_lanes], y[max_lanes];
  hn::Store(a.v, d, x);
  hn::Store(b.v, d, y);
  for (size_t k = 0; k < hn::Lanes(d); ++k) x[k] = function(x[k], y[k]);
  return Lanes(hn::Load(d, x));
}
inline Lanes atan2(Lanes y, Lanes x) {
  return per_lane([](double u, double v) { return std::atan2(u, v); }, y, x);
}
inline Lanes log(Lanes a) {
  return per_lane([](double u, double) { return std::log(u); }, a, a);
}
inline Lanes asinh(Lanes a) {
  return per_lane([](double u, double) { return std::asinh(u); }, a, a);
}
inline Lanes cos(Lanes a) {
  return per_lane([](double u, double) { return std::cos(u); }, a, a);
}
#endif

/// The largest of count(v…) over the active lanes, v the lanes' values of
/// `values`: the Gauss rules chosen by the poles' distance
/// (gauss_moments.hpp) take the most nodes any active lane needs, so that
/// the lanes stay together (more nodes only make a lane's rule more exact:
/// its result differs from the scalar path's by rounding).
template <class Count, class... Values>
int most_any_active_lane_needs(const Count& count, const Values&... values) {
  constexpr std::size_t n = sizeof...(Values);
  alignas(64) double lanes[n][max_lanes];
  std::size_t i = 0;
  (hn::Store(values.v, LaneTag(), lanes[i++]), ...);
  const Divergence& divergence = *current_divergence;
  int most = 0;
  for (std::size_t k = 0; k < lane_count(); ++k) {
    if (!(divergence.active() >> k & 1u)) continue;
    const int needs = [&]<std::size_t... j>(std::index_sequence<j...>) {
      return count(lanes[j][k]...);
    }(std::make_index_sequence<n>{});
    most = std::max(most, needs);
  }
  return most;
}
}  // namespace skelconv::simd::HWY_NAMESPACE

namespace boost::math::quadrature {
/// Gauss–Legendre nodes and weights for Lanes: the double tables (each node
/// is broadcast to every lane where it is used).
template <unsigned N, class Policy>
class gauss<skelconv::simd::HWY_NAMESPACE::Lanes, N, Policy> : public gauss<double, N, Policy> {};
}  // namespace boost::math::quadrature

namespace skelconv {
#define SimdLanes simd::HWY_NAMESPACE::Lanes  // this target's (an alias would clash across targets)
namespace detail {
/// The Miller recurrences (stable_recurrence.hpp) on Lanes: every lane runs
/// the largest number of steps any active lane needs. Starting higher only
/// shrinks the neglected start value further (below ε/100 either way), so a
/// lane's result differs from the scalar path's by rounding. A lane whose
/// recurrence would not converge is handed to the scalar path, which reports
/// it.
template <>
inline int miller_steps<SimdLanes>(const SimdLanes& rho) {
  simd::Divergence& divergence = *simd::HWY_NAMESPACE::current_divergence;
  alignas(64) double r[simd::max_lanes];
  hwy::HWY_NAMESPACE::Store(rho.v, simd::HWY_NAMESPACE::LaneTag(), r);
  int steps = 1;
  for (std::size_t k = 0; k < simd::HWY_NAMESPACE::lane_count(); ++k) {
    if (!(divergence.active() >> k & 1u)) continue;
    try {
      steps = std::max(steps, miller_steps<double>(r[k]));
    } catch (const NotConvergedError&) {
      divergence.hand_lane_to_scalar(k);
    }
  }
  return steps;
}

/// The Gauss rules chosen by the poles' distance: the most nodes any active
/// lane needs (most_any_active_lane_needs).
template <>
inline int rule_nodes<SimdLanes>(const SimdLanes& x, double x7, double x10, double x15, int most) {
  return simd::HWY_NAMESPACE::most_any_active_lane_needs(
      [&](double v) { return rule_nodes<double>(v, x7, x10, x15, most); }, x);
}

template <>
inline int panel_nodes<SimdLanes>(const SimdLanes& x_star2, const SimdLanes& y2, const PanelNodeThresholds& c) {
  return simd::HWY_NAMESPACE::most_any_active_lane_needs(
      [&](double x, double y) { return panel_nodes<double>(x, y, c); }, x_star2, y2);
}

/// SCALIS segments' Gauss panels (gauss_moments.hpp) with the pole so close
/// to the segment that q underflows: the active lanes go to the scalar path,
/// which reports the error.
template <>
inline void pole_too_close<SimdLanes>(const SimdLanes&) {
  simd::HWY_NAMESPACE::current_divergence->hand_to_scalar();
}
}  // namespace detail
#undef SimdLanes
}  // namespace skelconv

namespace std {
/// What gauss_panel_points<T>() asks of a scalar type: the digits of double.
template <>
class numeric_limits<skelconv::simd::HWY_NAMESPACE::Lanes> : public numeric_limits<double> {};
}  // namespace std
HWY_AFTER_NAMESPACE();

#endif  // SKELCONV_SIMD_LANES_INL_H_
