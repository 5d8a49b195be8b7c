// skelconv/detail/far_field_series.hpp — segment moments far from the
// segment by the kernel's Taylor (Gegenbauer) series about the midpoint,
// truncated where a proven remainder bound falls below 2^−53 relative.
//
// The moments M_{k,m} = ∫_0^1 t^k q(t)^(−m/2) dt, q = a t² − 2 b t + c
// (docs/mathematics.md §2), for inverse and Cauchy kernels (m > 0, a > 0,
// D = ac − b² ≥ 0). About the midpoint, with v = 2t − 1 ∈ [−1, 1]:
//
//     q = Q (1 + 2 P v + S v²),   Q = q(½) = c − b + a/4,
//     P = (a/2 − b)/(2Q),  S = a/(4Q) = ρ²,   P² ≤ S (since Q a − (a/2 − b)² = D ≥ 0)
//
// Q is α|P − M|² + β (M the midpoint), and ρ = √(a/Q)/2 ≤ |AB|/(2|P − M|):
// the ratio of the half-length to the distance of the kernel's poles. The
// Taylor coefficients h_n of (1 + 2Pv + Sv²)^(−λ), λ = m/2, are Gegenbauer
// polynomials, h_n = C_n^λ(x) ρ^n with x = −P/ρ ∈ [−1, 1], and obey
//
//     (n + 1) h_{n+1} = −2P (n + λ) h_n − S (n − 1 + 2λ) h_{n−1},  h_0 = 1,
//
// so that, integrating term by term (odd powers of v vanish against even
// ones), with V_j = Σ_{n ≡ j (mod 2)} h_n/(n + j + 1):
//
//     M_{k,m} = Q^(−m/2) 2^(−k) Σ_{j≤k} binom(k, j) V_j.
//
// The next lower level follows without a second series from
// q^(−(m−2)/2) = q q^(−m/2): V'_j = V_j + 2P V_{j+1} + S V_{j+2}, with
// Q^(−(m−2)/2) in front (three terms of which the first dominates by
// 1/(2ρ + ρ²): no cancellation for the ρ where the series is used).
//
// Remainder (proof in docs/mathematics.md §2, "Far from the segment"):
// |C_n^λ(x)| ≤ C_n^λ(1) = binom(n + m − 1, n) on [−1, 1], so truncating
// after h_N leaves every V_j off by at most T_N/(N + 2), T_N = Σ_{n>N}
// binom(n + m − 1, n) ρ^n; since q ≤ Q (1 + ρ)² on the segment,
// M_{k,m} ≥ Q^(−m/2) (1 + ρ)^(−m)/(k + 1), and every moment of either
// level is off by at most
//
//     B_N = (k_max + 1) (1 + ρ)^(m_hi) T_N / (N + 2)
//
// relative. The terms t_n = binom(n + m − 1, n) ρ^n fall by the ratio
// ρ (n + m)/(n + 1), which decreases in n, so T_N ≤ t_{N+1}/(1 − r) with
// r = ρ (N + 1 + m)/(N + 2) < 1. The series below stops at the first odd N
// (h_0 … h_N: whole pairs of terms) with that bound ≤ 2^−53: B_N grows with
// ρ, so N comes from a table, per m, of the largest ρ² at which each B_N is
// ≤ 2^−53 (far_series_order_row, computed from far_series_bound).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>

namespace skelconv::detail {

/// The series converges and keeps its digits where ρ² = a/(4 q(½)) ≤ this,
/// i.e. P at least 2 |AB| from the midpoint for the inverse kernel (further
/// still for Cauchy), with ≤ 38 terms.
inline constexpr double far_series_max_rho2 = 0.0625;

/// ... and where ρ m ≤ this (m the upper pole order): beyond it the terms'
/// signs alternate over a range of magnitudes ((1 + ρ)/(1 − ρ))^m ≈ e^(2ρm)
/// wide, and their sum loses digits (measured on M_{k,m}, k ≤ 4, m ≤ 18,
/// against long-double quadrature: at most 2.4e-15, the rounding of Q itself,
/// up to ρm = 1.6; 3.4e-15 at 1.8–2, 1.4e-14 at 3).
inline constexpr double far_series_max_rho_m = 1.6;

/// Where it is also cheaper than the Gauss–Legendre rule of
/// gauss_moments.hpp, which is used otherwise: for odd pole orders (the
/// rule then takes a square root and a division per node) with at most
/// this order; for even orders the rule's nodes cost a division only, and
/// it was the cheaper at every distance measured. Measured (-O3, moments of
/// levels m, m + 2, one run): odd m, series/rule 1.0 at N = 25 (3 |AB|
/// from M), 0.75–0.86 at N ≤ 19 (5 |AB|), 0.65–0.93 at N ≤ 17 (10 |AB|),
/// 0.60–0.93 at N ≤ 13 (30 |AB|); even m, 1.3–2.2 up to 10 |AB|, 0.9–1.0
/// at 30 |AB|.
inline constexpr int far_series_cheaper_order = 21;

inline bool far_series_cheaper(int m_hi, int N) { return m_hi % 2 == 1 && N <= far_series_cheaper_order; }

/// The pole orders (m ≤ 20: inverse and Cauchy degree ≤ 18 with ∇f) and the
/// weights (t^k, k ≤ 4: weight degree 3 with ∇f) the order table covers.
inline constexpr int far_series_max_m = 20;
inline constexpr int far_series_max_k = 4;

/// The largest truncation order (odd: h_0 … h_N in whole pairs); beyond it
/// the caller's rule is used. Within far_series_applies N ≤ 37 (m = 6 at
/// ρ² = 1/16 needs the most terms).
inline constexpr int far_series_max_order = 63;

/// The truncation target: 2^−53, the relative rounding unit of double.
inline constexpr double far_series_tolerance = 0x1p-53;

/// 1/n for n = 1…far_series_max_order + 16: the recurrences' and the
/// integrals' divisors as products.
inline const std::array<double, far_series_max_order + 17>& far_series_reciprocals() {
  static const std::array<double, far_series_max_order + 17> table = [] {
    std::array<double, far_series_max_order + 17> r{};
    for (std::size_t n = 1; n < r.size(); ++n) r[n] = 1.0 / double(n);
    return r;
  }();
  return table;
}

/// B_N (above): the remainder bound, relative, on every moment M_{k,m'} with
/// k ≤ k_max and m' = m, m − 2, after the terms h_0 … h_N, for pole order m
/// and ρ² = S; +∞ where r ≥ 1 (the tail bound does not apply).
inline double far_series_bound(int m, int k_max, int N, double S) {
  using std::sqrt;
  const auto& inv = far_series_reciprocals();
  const double rho = sqrt(S);
  const double r = rho * double(N + 1 + m) * inv[N + 2];
  if (!(r < 1)) return std::numeric_limits<double>::infinity();
  double t = 1;  // t_{N+1} = binom(N + m, N + 1) ρ^(N+1), by its ratios t_{j+1}/t_j = ρ (j + m)/(j + 1)
  for (int j = 0; j <= N; ++j) t *= rho * double(j + m) * inv[j + 1];
  double growth = double(k_max + 1);  // (k_max + 1)(1 + ρ)^m
  for (int i = 0; i < m; ++i) growth *= 1 + rho;
  return growth * t * inv[N + 2] / (1 - r);
}

/// For a pole order m ≤ far_series_max_m and each odd order N = 2i + 1, the
/// largest ρ² (to 2^−32 relative, rounded down) at which B_N ≤
/// far_series_tolerance with k_max = far_series_max_k: B_N grows with ρ,
/// so N is the first order whose threshold is ≥ ρ². Each row is computed on
/// its first use, by bisection on far_series_bound (~0.1 ms).
inline constexpr int far_series_orders = (far_series_max_order + 1) / 2;

inline const std::array<double, far_series_orders>& far_series_order_row(int m) {
  struct Table {
    std::array<std::once_flag, far_series_max_m + 1> once;
    std::array<std::array<double, far_series_orders>, far_series_max_m + 1> max_rho2{};
  };
  static Table table;
  std::call_once(table.once[m], [m] {
    for (int i = 0; i < far_series_orders; ++i) {
      double lo = 0, hi = 1;  // B_N(lo) ≤ tolerance < B_N(hi)
      for (int step = 0; step < 32; ++step) {
        const double mid = 0.5 * (lo + hi);
        (far_series_bound(m, far_series_max_k, 2 * i + 1, mid) <= far_series_tolerance ? lo : hi) = mid;
      }
      table.max_rho2[m][i] = lo;
    }
  });
  return table.max_rho2[m];
}

/// The truncation order the series takes for pole order 1 ≤ m ≤
/// far_series_max_m (weights up to t^4) at ρ² = S: the first odd N with
/// B_N ≤ 2^−53; 0 if none up to far_series_max_order.
inline int far_series_order(int m, double S) {
  const auto& row = far_series_order_row(m);
  for (int i = 0; i < far_series_orders; ++i)
    if (S <= row[i]) return 2 * i + 1;
  return 0;
}

/// Whether the series serves pole order m at ρ² = S (the two limits above).
inline bool far_series_applies(int m, double S, double max_rho2 = far_series_max_rho2) {
  return S <= max_rho2 && S * double(m) * double(m) <= far_series_max_rho_m * far_series_max_rho_m;
}

/// V_0 … V_J (above) from h_0 … h_N, N odd, for pole order m: the
/// recurrence in pairs of terms (an even one, then an odd one), so that
/// each V_j is updated by terms of its own parity with compile-time indices
/// (the V_j stay in registers).
template <class T, int J>
void far_series_sums(int m, const T& P, const T& S, int N, std::array<T, J + 1>& V) {
  const auto& inv = far_series_reciprocals();
  auto reciprocal = [&](int n) {  // 1/n to T's precision
    if constexpr (std::is_same_v<T, double>) return inv[n];
    else return T(1) / T(n);
  };
  T h_prev(1);       // h_0
  T h = -T(m) * P;   // h_1 = −2λP
  for (int j = 0; j <= J; ++j) V[j] = (j % 2 == 0 ? T(1) : h) * reciprocal(j % 2 == 0 ? j + 1 : j + 2);
  const T two_P = T(2) * P;
  for (int n = 1; n < N; n += 2) {
    // (n + 1) h_{n+1} = −P (2n + m) h_n − S (n − 1 + m) h_{n−1}
    const T even = -(two_P * T(n + 0.5 * m) * h + S * T(n - 1 + m) * h_prev) * reciprocal(n + 1);
    const T odd = -(two_P * T(n + 1 + 0.5 * m) * even + S * T(n + m) * h) * reciprocal(n + 2);
    for (int j = 0; j <= J; j += 2) V[j] += even * reciprocal(n + j + 2);
    for (int j = 1; j <= J; j += 2) V[j] += odd * reciprocal(n + j + 3);
    h_prev = even;
    h = odd;
  }
}

/// M_{k,m} (layout of segment_moments_far_series) from the terms h_0 … h_N
/// of the series for Q = q(½), P, S as above: the sums alone, whatever N
/// (odd), in the type T (binary128 in the verifier, which checks the bound
/// on them).
template <class T, int J>
void far_series_moments_with(int m_lo, int m_hi, int k_max, const T& Q, const T& P, const T& S, int N, T* out) {
  using std::sqrt;
  std::array<T, J + 1> V;
  far_series_sums<T, J>(m_hi, P, S, N, V);
  // M_{k,m} = Q^(−m/2) 2^(−k) Σ_j binom(k, j) V_j, per level.
  const T inverse_Q = T(1) / Q;  // not (1/√Q)²: that would double the rounding in Q^(−m/2)
  const T inverse_sqrt_Q = T(1) / sqrt(Q);
  static constexpr double binomial[5][5] = {
      {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
  auto write_level = [&](T scale, const T* W, T* dest) {
    for (int k = 0; k <= k_max; ++k) {
      T sum(0);
      for (int j = 0; j <= k; ++j) sum += T(binomial[k][j]) * W[j];
      dest[k] = scale * sum;
      scale *= T(0.5);
    }
  };
  // Q^(−m_lo/2) by squaring, then Q^(−m_hi/2) = Q^(−m_lo/2)/Q.
  T scale_lo = m_lo % 2 == 1 ? inverse_sqrt_Q : T(1);
  T power = inverse_Q;
  for (int e = m_lo / 2; e > 0; e >>= 1) {
    if (e & 1) scale_lo *= power;
    power *= power;
  }
  if constexpr (J >= 2) {  // two levels need J = k_max + 2 (far_series_moments)
    if (m_hi > m_lo) {
      std::array<T, J - 1> lower;
      for (int j = 0; j + 2 <= J; ++j) lower[j] = V[j] + T(2) * P * V[j + 1] + S * V[j + 2];
      write_level(scale_lo, lower.data(), out);
      write_level(scale_lo * inverse_Q, V.data(), out + (k_max + 1));
      return;
    }
  }
  write_level(scale_lo, V.data(), out);
}

template <class T>
void far_series_moments(int m_lo, int m_hi, int k_max, const T& Q, const T& P, const T& S, int N, T* out) {
  switch (k_max + (m_hi - m_lo)) {  // the V_j needed: j ≤ k_max, and two more for the lower level
    case 0: far_series_moments_with<T, 0>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    case 1: far_series_moments_with<T, 1>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    case 2: far_series_moments_with<T, 2>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    case 3: far_series_moments_with<T, 3>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    case 4: far_series_moments_with<T, 4>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    case 5: far_series_moments_with<T, 5>(m_lo, m_hi, k_max, Q, P, S, N, out); break;
    default: far_series_moments_with<T, 6>(m_lo, m_hi, k_max, Q, P, S, N, out); break;  // k_max ≤ far_series_max_k
  }
}

/// Writes M_{k,m} = ∫_0^1 t^k q^(−m/2) dt (k = 0…k_max ≤ 4, m = m_lo and
/// m_lo + 2 ≤ m_hi ≤ 20, m_lo ≥ 1) to out[((m − m_lo)/2)(k_max + 1) + k] by
/// the series above, given Q = q(½) > 0, P and S = ρ² (each formed by the
/// caller without cancellation where it can), truncated at the order
/// far_series_order picks; returns that order N, or 0 (out untouched) where
/// the series is not used: far_series_applies false, other levels or
/// weights, or (only_where_cheaper) where the Gauss rule costs less
/// (far_series_cheaper).
inline int far_series_moments_about_midpoint(int m_lo, int m_hi, int k_max, double Q, double P, double S,
                                             double* out, double max_rho2 = far_series_max_rho2,
                                             bool only_where_cheaper = true) {
  if (m_lo < 1 || m_hi > far_series_max_m || m_hi < m_lo || m_hi - m_lo > 2 || (m_hi - m_lo) % 2 != 0 ||
      k_max < 0 || k_max > far_series_max_k)
    return 0;
  if (!(Q > 0) || !far_series_applies(m_hi, S, max_rho2)) return 0;
  const int N = far_series_order(m_hi, S);
  if (N == 0 || (only_where_cheaper && !far_series_cheaper(m_hi, N))) return 0;
  far_series_moments<double>(m_lo, m_hi, k_max, Q, P, S, N, out);
  return N;
}

/// far_series_moments_about_midpoint for q = a t² − 2 b t + c (a > 0): Q =
/// c − b + a/4, P = (a/2 − b)/(2Q), S = a/(4Q).
inline int segment_moments_far_series(int m_lo, int m_hi, int k_max, double a, double b, double c, double* out,
                                      double max_rho2 = far_series_max_rho2, bool only_where_cheaper = true) {
  const double Q = c - b + 0.25 * a;
  if (!(Q > 0) || !(a > 0)) return 0;
  const double inverse_Q = 1.0 / Q;
  return far_series_moments_about_midpoint(m_lo, m_hi, k_max, Q, 0.5 * (0.5 * a - b) * inverse_Q,
                                           0.25 * a * inverse_Q, out, max_rho2, only_where_cheaper);
}

}  // namespace skelconv::detail
