// skelconv/detail/stable_recurrence.hpp — J_n where recurrence (1) is unstable.
//
// Generated segment kernels evaluate J_n = ∫_{t0}^{t1} q(t)^(-n/2) dt,
// q = a t² − 2 b t + c, D = ac − b² ≥ 0 (docs/mathematics.md §2), by recurrence (1) of
// Hubert & Cani. Upwards from J_1, J_2 it divides by D at every step. When P
// projects beyond an end of the segment and lies close to its line, J_n is
// the *minimal* solution of the recurrence: going up multiplies rounding
// errors by ~1/ρ a step (ρ = D / (a q_near) < 1), going down multiplies them
// by ~ρ. This header evaluates the top J_n of a generated kernel downwards,
// in the manner of Miller's algorithm: start from J_top = 0 high enough that
// ρ^steps is below rounding, then apply
//
//     J_{m−2} = ([(a t − b) q^(1−m/2)]_{t0}^{t1} − (m−2) D J_m) / (a (3−m)).
//
// The values are carried scaled, Ĵ_m = J_m q_near^((m−1)/2) with q_near the
// smaller end value of q, so that the high powers of q never overflow; the
// far end enters through (q_near/q_far)^((m−2)/2) ≤ 1. With D = 0 (P on the
// line beyond an end) one step is exact.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "skelconv/detail/gauss_moments.hpp"
#include "skelconv/not_converged.hpp"

namespace skelconv {

/// Relative size below which the neglected start value no longer matters:
/// a hundredth of the scalar type's rounding unit (so float128 gets its
/// 34 digits, not double's 16).
template <class T>
T recurrence_tolerance() {
  return std::numeric_limits<T>::epsilon() / 100;
}

/// The largest per-step factor ρ the generated code hands to these helpers
/// is 17/20 (compact kernels; 7/10 for the others,
/// codegen/segment_program_builder.hpp). The cap on the number of steps is
/// what ρ = 9/10 needs at T's tolerance, a margin over 17/20 that rounding in
/// the generated branch conditions cannot use up.
inline constexpr double recurrence_cap_rho = 0.9;

/// Upper bound on the number of steps for scalar type T: the least k with
/// recurrence_cap_rho^k < recurrence_tolerance<T>() (386 for double, 459 for
/// 64-bit long double, 781 for binary128, 1143 for cpp_bin_float_50). Computed by repeated
/// multiplication so that it is a compile-time constant (it sizes arrays).
template <class T>
constexpr int recurrence_max_steps() {
  double tolerance = 1.0 / 100;  // recurrence_tolerance<T>() = ε/100, ε = 2^(1 − digits)
  for (int bit = 1; bit < std::numeric_limits<T>::digits; ++bit) tolerance /= 2;
  int steps = 0;
  for (double shrink = 1.0; !(shrink < tolerance); shrink *= recurrence_cap_rho) ++steps;
  return steps;
}

namespace detail {

/// Steps of Miller's algorithm for a start error shrinking by rho per step.
/// Throws NotConvergedError when more than recurrence_max_steps<T>() would be
/// needed (ρ above recurrence_cap_rho, or not a number): the run would stop
/// before the neglected start value is below rounding.
template <class T>
int miller_steps(const T& rho) {
  using std::ceil;
  using std::log;
  if (rho != rho) throw NotConvergedError("Miller's recurrence: the per-step factor rho is not a number");
  if (!(rho > T(0))) return 1;  // exact in one step (D = 0, or −0 by rounding)
  const T wanted = rho < T(1) ? ceil(log(recurrence_tolerance<T>()) / log(rho)) : T(recurrence_max_steps<T>() + 1);
  if (!(wanted <= T(recurrence_max_steps<T>()))) {
    throw NotConvergedError("Miller's recurrence: per-step factor rho = " + std::to_string(static_cast<double>(rho)) +
                            " needs more than the cap of " + std::to_string(recurrence_max_steps<T>()) +
                            " steps to reach the scalar type's rounding");
  }
  return std::max(1, static_cast<int>(wanted));
}

/// 1/(a j), the divisor of one downward step. The steps multiply by it
/// instead of dividing by a j: the division does not depend on the value
/// carried down, so it runs beside the dependency chain (one product and
/// one difference a step) instead of on it (a division's ~13–20 cycles of
/// latency a step; perf put 36 % of the generic-distance time of inverse i3
/// and Cauchy i8 in these loops). The extra rounding (≤ 1 ulp a step) is
/// damped like every other by ρ < 1 per step going down.
template <class T>
T step_scale(const T& a, int j) {
  return T(1) / (a * T(j));
}

/// powers[j] = x^j for j = 0…count−1 (x ≤ 1: the tail may underflow to 0,
/// which is then its true size to rounding, never rescaled back up).
template <class T>
void fill_powers(const T& x, int count, T* powers) {
  powers[0] = T(1);
  for (int j = 1; j < count; ++j) powers[j] = powers[j - 1] * x;
}

/// The scaled downward Miller run shared by J_downward and
/// segment_moments_beyond_end: which end is near, how far up to start, and
/// the powers of q_near/q_far that bring the far end in.
template <class T>
struct DownwardStart {
  T q_near;         ///< the smaller end value of q
  T d_scaled;       ///< D / q_near
  T inv_root_near;  ///< 1/√q_near
  int top;          ///< start index: J_top (or M_{k,top}) = 0
  std::array<T, 2 * recurrence_max_steps<T>() + 40> far_powers;  ///< (q_near/q_far)^(j/2)

  /// For the highest index `highest` needed, with q_near < q_far.
  DownwardStart(int highest, const T& a, const T& D, const T& near_q, const T& far_q) {
    using std::sqrt;
    q_near = near_q;
    // Per step, the start error shrinks by about ρ = D/(a q_near) < 1.
    top = highest + 2 * miller_steps(D / (a * q_near));
    d_scaled = D / q_near;
    inv_root_near = T(1) / sqrt(q_near);
    fill_powers(sqrt(q_near / far_q), top - 1, far_powers.data());
  }
};

}  // namespace detail

/// J_n (n ≥ 2) over [t0, t1] for P beyond an end, from the ends' slopes
/// s = a t − b and values q. Requires a > 0, D ≥ 0, q0, q1 > 0.
template <class T>
T J_downward(int n, const T& a, const T& D, const T& slope0, const T& q0, const T& slope1, const T& q1) {
  using std::pow;
  const bool lo_is_near = q0 <= q1;
  const T& q_near = lo_is_near ? q0 : q1;
  const T& q_far = lo_is_near ? q1 : q0;
  // Away from the segment (|P − midpoint| ≥ 7 |AB|): a Gauss rule
  // (gauss_moments.hpp, beyond_end_moments_gauss). b_near: b = −slope0 beyond A, a − b = slope1 beyond B.
  T J_rule;
  if (detail::beyond_end_moments_gauss(n, n, 0, a, lo_is_near ? -slope0 : slope1, q_near, q_far, !lo_is_near,
                                       &J_rule))
    return J_rule;
  const detail::DownwardStart<T> start(n, a, D, q_near, q_far);
  const T& inv_root_near = start.inv_root_near;
  T J_scaled = 0;  // Ĵ_top
  for (int m = start.top; m > n; m -= 2) {
    // B̂_m = [(a t − b) q^(1−m/2)]_{t0}^{t1} q_near^((m−3)/2)
    const T& far_power = start.far_powers[m - 2];
    const T B_scaled = lo_is_near ? (slope1 * far_power - slope0) * inv_root_near
                                  : (slope1 - slope0 * far_power) * inv_root_near;
    // Only the product and the difference depend on the previous Ĵ: the
    // division is formed beside the chain (detail::step_scale).
    J_scaled = (B_scaled - T(m - 2) * start.d_scaled * J_scaled) * detail::step_scale(a, 3 - m);
  }
  return J_scaled * pow(inv_root_near, n - 1);
}

/// The weighted moments M_{k,m} = ∫_0^1 t^k q^(−m/2) dt, k = 0…k_max, at the
/// levels m = m_lo, m_lo + 2, …, m_hi, for P beyond an end of [0, 1] (the
/// infinite-support kernels). Written to out[((m − m_lo)/2)(k_max + 1) + k].
/// Requires m_lo ≥ k_max + 2, a > 0, D ≥ 0, q0 = q(0) > 0, q1 = q(1) > 0,
/// and a_minus_b = a − b formed by the caller without cancellation (AB·BP).
///
/// Why not J_n and a M_{1,n} = b J_n + [q^(1−n/2)]/(2−n)? Beyond an end the
/// kernel's mass sits at that end and the two terms cancel to ~1/n² of their
/// size, more for each further moment. Instead:
///  * the parameter is σ, the distance in t from the near end (σ = t beyond
///    A, σ = 1 − t beyond B), so that σ^k is small where the mass is;
///  * differentiating σ^k (a σ − b) q^(1−m/2) gives, for every k,
///        a (3−m+k) M_{k,m−2} = [σ^k (aσ − b) q^(1−m/2)]_0^1 + k b M_{k−1,m−2} − (m−2) D M_{k,m},
///    run downwards from M_{k,top} = 0 as in J_downward; near the end the
///    near end's boundary term dominates and has the sign of the left
///    (b < 0), so nothing cancels; away from the segment (|P − midpoint| ≥
///    7 |AB|, beyond_end_rule_min_z) the far end's term does not fade and cancels, and a Gauss
///    rule takes over (gauss_moments.hpp, beyond_end_moments_gauss);
///  * beyond B the t-moments are recovered from t^k = (1 − σ)^k, a sum
///    whose terms shrink (σ is small where the mass is).
template <class T>
void segment_moments_beyond_end(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& a_minus_b,
                                const T& D, const T& q0, const T& q1, T* out) {
  using std::pow;
  constexpr int max_k = 10;  // SCALIS i = 10: ∇F needs k ≤ 10
  T M[max_k + 1];  // M̂_{k,m} at the current level
  if (k_max > max_k || m_lo < k_max + 2) throw std::invalid_argument("segment_moments_beyond_end: k_max out of range");
  const bool beyond_B = q1 < q0;
  // b in the σ parameter: a − b beyond B, passed in rather than formed here,
  // where it would cancel: a − b = AB·BP is ~|BP|/|AB| times a near B
  // (measured: every moment 3.0e-13 off at |BP| = 1.4e-4 |AB|, inverse i15
  // f 4.7e-12), while the caller has it from BP = P − B directly.
  const T& b_near = beyond_B ? a_minus_b : b;
  const T& b_far = beyond_B ? b : a_minus_b;  // a − b_near
  const T& q_near = beyond_B ? q1 : q0;
  const T& q_far = beyond_B ? q0 : q1;
  // Away from the segment the far end's boundary term cancels against
  // k b_near M_{k−1} (see beyond_end_moments_gauss): a Gauss rule there.
  if (detail::beyond_end_moments_gauss(m_lo, m_hi, k_max, a, b_near, q_near, q_far, beyond_B, out))
    return;
  const detail::DownwardStart<T> start(m_hi, a, D, q_near, q_far);
  const T& inv_root_near = start.inv_root_near;
  const T far_slope = b_far * inv_root_near;         // (aσ − b) at σ = 1, scaled
  const T near_slope = -b_near * inv_root_near;      // (aσ − b) at σ = 0, scaled
  for (int k = 0; k <= k_max; ++k) M[k] = T(0);  // M̂_{k,top}
  for (int m = start.top; m > m_lo; m -= 2) {
    // Level m − 2 from level m, k upwards (M̂_{k−1,m−2} is already new).
    const T boundary_far = far_slope * start.far_powers[m - 2];
    for (int k = 0; k <= k_max; ++k) {
      const T boundary = k == 0 ? boundary_far - near_slope : boundary_far;
      const T lower = k == 0 ? T(0) : T(k) * b_near * M[k - 1];
      M[k] = (boundary + lower - T(m - 2) * start.d_scaled * M[k]) * detail::step_scale(a, 3 - m + k);
    }
    const int level = m - 2;
    if (level <= m_hi && (level - m_lo) % 2 == 0) {
      const T unscale = pow(inv_root_near, level - 1);
      T* row = out + ((level - m_lo) / 2) * (k_max + 1);
      for (int k = 0; k <= k_max; ++k) {
        if (!beyond_B) {
          row[k] = M[k] * unscale;
        } else {
          // t^k = (1 − σ)^k = Σ_j C(k,j) (−σ)^j
          T sum = 0, binomial = 1;
          for (int j = 0; j <= k; ++j) {
            sum += (j % 2 == 0 ? binomial : -binomial) * M[j];
            binomial = binomial * T(k - j) / T(j + 1);
          }
          row[k] = sum * unscale;
        }
      }
    }
  }
}

/// J_n (n ≤ 0) for a compact kernel, q = 1 − |P − Γ(t)|²/R² (a < 0, D < 0),
/// when the vertex t* = b/a of q lies outside [t0, t1] (P projects beyond an
/// end of the clipped segment). The generated code otherwise goes down from
/// J_0, J_1, which multiplies errors by about q_max/q_e > 1 a step
/// (q_max = D/a the vertex value, q_e the larger end value); here J_n is the
/// minimal solution going down, so it is computed upwards from J_bottom = 0,
/// where each step multiplies the start error by about q_e/q_max < 1:
///
///     J_m = ([(a t − b) q^(1−m/2)]_{t0}^{t1} − a (3−m) J_{m−2}) / ((m−2) D).
///
/// Scaled as Ĵ_m = J_m q_e^(m/2) so that high powers of q never underflow.
template <class T>
T J_upward_compact(int n, const T& a, const T& D, const T& slope0, const T& q0, const T& slope1, const T& q1) {
  using std::ceil;
  using std::log;
  using std::pow;
  using std::sqrt;
  const bool lo_is_larger = q0 >= q1;
  const T q_e = lo_is_larger ? q0 : q1;
  const T ratio = lo_is_larger ? q1 / q0 : q0 / q1;  // smaller / larger end value, in [0, 1]
  const int steps = detail::miller_steps(a * q_e / D);  // q_e / q_max < 1
  const int bottom = n - 2 * steps;
  // small_powers[j] = ratio^(j/2); the smaller end's weight at m is ratio^(1−m/2).
  std::array<T, 2 * recurrence_max_steps<T>() + 40> small_powers;
  detail::fill_powers(sqrt(ratio), 2 - bottom, small_powers.data());
  T J_scaled = 0;  // Ĵ_bottom
  for (int m = bottom + 2; m <= n; m += 2) {
    // B̂_m = [(a t − b) q^(1−m/2)]_{t0}^{t1} q_e^(m/2), with the smaller end
    // entering as ratio^(1−m/2) ≤ 1 (0 at a clipped end).
    const T& small_power = small_powers[2 - m];
    const T B_scaled = lo_is_larger ? q_e * (slope1 * small_power - slope0) : q_e * (slope1 - slope0 * small_power);
    J_scaled = (B_scaled - a * T(3 - m) * q_e * J_scaled) / (T(m - 2) * D);
  }
  return J_scaled * pow(sqrt(q_e), -n);
}

}  // namespace skelconv
