// generated/scalis_segment_inverse.hpp — SCALIS segment kernels of the inverse family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).
// SCALIS segments (docs/mathematics.md §4, Zanni et al. 2013 §3–4, Table 3): the segment kernel of
// degree i with the weight σ^i τ(t)^(i−1), and for Cauchy q = |P − Γ(t)|² + σ²τ(t)²
// (codegen/segment_families.cpp, ScalisKernelSpec). Unnormalised: f = c F / h is
// the runtime's (skelconv/primitives/scalis_segment.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/detail/exact_cross.hpp>
#include <skelconv/detail/gauss_moments.hpp>
#include <skelconv/primitives/scalis_segment_input.hpp>
#include <skelconv/detail/stable_recurrence.hpp>

namespace skelconv::generated {

/// How many values scalis_segment_inverse_i2_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i2_prepared_size = 18;

/// What scalis_segment_inverse_i2_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 18): computed once per
/// segment; in.p is not read.
/// Operations: 7 +, 7 ×, 1 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i2_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T g_factor = -T(2) * t0 * length;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab0;
  pre[7] = ab2;
  pre[8] = ab1;
  pre[9] = ab_ab;
  const T t1 = T(1) / ab_ab;
  pre[10] = t1;
  pre[11] = -ab_ab * ab_ab;
  pre[12] = tau_lo;
  pre[13] = delta_tau;
  pre[14] = tau_lo + delta_tau;
  pre[15] = t0;
  pre[16] = length;
  pre[17] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i2_prepare); operations per point.
/// Operations: 29 +, 42 ×, 2 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 70037 +, 78617 ×, 25291 /, 539 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i2_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T tau_lo = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[15];
  const T length = pre[16];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * tau_lo + M_panels[1] * delta_tau;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T J2 = atan2(t4, ap_bp) / t4;
    const T log_ratio = log(bp_bp / ap_ap);
    F = (T(1) / T(2)) * (log_ratio + T(2) * ab_ap * J2) * seg0 * delta_tau + tau_lo * J2;
  }
  f = length * seg3 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i2_prepare); operations per point.
/// Operations: 40 +, 66 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 56595 +, 77024 ×, 12650 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i2_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T tau_lo = pre[12];
  const T delta_tau = pre[13];
  const T seg2 = pre[14];
  const T g_factor = pre[17];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * seg0 * ab0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * seg0;
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = M_panels[3] * tau_lo + delta_tau * M_panels[4];
    G_ap = t4;
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - ab_ap * seg0 * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * seg2;
    const T t7 = T(1) / ap_ap;
    G_E = -(T(1) / T(2)) * (t6 - M_panels[0] * delta_tau - t7 * tau_lo) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, ap_bp) * t9;
    const T t10 = T(1) / bp_bp;
    const T t11 = T(1) / ap_ap;
    const T t12 = t10 * a_minus_b + ab_ap * t11 + ab_ab * J2;
    const T t13 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * t12 * tau_lo * t13 + (T(1) / T(2)) * seg0 * (t11 + ab_ap * t12 * t13 - t10) * delta_tau;
    const T t14 = t10 * seg2;
    G_E = -(T(1) / T(2)) * (t14 - delta_tau * J2 - t11 * tau_lo) * seg0;
  }
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i2_prepare); operations per point.
/// Operations: 42 +, 75 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 56596 +, 77028 ×, 12650 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i2_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T tau_lo = pre[12];
  const T delta_tau = pre[13];
  const T seg2 = pre[14];
  const T seg3 = pre[15];
  const T length = pre[16];
  const T g_factor = pre[17];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross2 * plain_cross2 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab2 * ab_ap * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * seg0;
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * seg0;
    foot2 = -(exact_cross[1] * ab0 - ab1 * exact_cross[0]) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t4 = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ap = t4;
    G_E = tau_lo * M_panels[4] + M_panels[5] * delta_tau - t4 * ab_ap * seg0;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + delta_tau * M_panels[1];
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * tau_lo;
    const T t7 = T(1) / bp_bp;
    G_E = (T(1) / T(2)) * (t6 + delta_tau * M_panels[0] - seg2 * t7) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, ap_bp);
    const T t10 = T(1) / ap_ap;
    const T log_ratio = log(t10 * bp_bp);
    F = (T(1) / T(2)) * delta_tau * (log_ratio + T(2) * J2 * ab_ap) * seg0 + J2 * tau_lo;
    const T t11 = T(1) / bp_bp;
    const T t12 = t10 * ab_ap + J2 * ab_ab + a_minus_b * t11;
    const T t13 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * t12 * tau_lo * t13 - (T(1) / T(2)) * (t11 - t10 - t12 * ab_ap * t13) * delta_tau * seg0;
    const T t14 = t10 * tau_lo;
    G_E = (T(1) / T(2)) * (t14 + J2 * delta_tau - seg2 * t11) * seg0;
  }
  f = F * seg3 * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i3_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i3_prepared_size = 22;

/// What scalis_segment_inverse_i3_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 22): computed once per
/// segment; in.p is not read.
/// Operations: 8 +, 12 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i3_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * in.sigma;
  const T g_factor = -T(3) * t1 * length;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab2;
  pre[7] = ab1;
  pre[8] = ab0;
  pre[9] = ab_ab;
  const T t2 = T(1) / ab_ab;
  pre[10] = t2;
  pre[11] = length;
  const T t3 = T(1) / length;
  pre[12] = t3;
  pre[13] = -ab_ab * ab_ab;
  pre[14] = delta_tau;
  pre[15] = tau_lo;
  const T t4 = delta_tau * delta_tau;
  pre[16] = t4;
  const T t5 = tau_lo * tau_lo;
  pre[17] = t5;
  pre[18] = t5 + T(2) * delta_tau * tau_lo + t4;
  pre[19] = t1;
  pre[20] = length;
  pre[21] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i3_prepare); operations per point.
/// Operations: 33 +, 56 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 53912 +, 73979 ×, 16869 /, 7537 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i3_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab1 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T delta_tau = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg7 = pre[19];
  const T length = pre[20];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / cross_cross;
    X = (t2 + r1 * ab_ap) * seg1 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = (a_minus_b - ab_ap) * seg1 / (t4 - r1 * ab_ap);
  }
  const T J1 = asinh(X) * seg2;
  T F;
  const T t5 = seg3 + T(4) * cross_cross;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg5 + seg4 * M_panels[2] + T(2) * delta_tau * M_panels[1] * tau_lo;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg5 + seg4 * M_panels[2] + T(2) * delta_tau * tau_lo * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = t8 * ab_ap + t9 * a_minus_b;
    const T t11 = T(1) / cross_cross;
    const T t12 = t9 - t10 * t11 * ab_ap - t8;
    F = t10 * seg5 * t11 - seg0 * (t10 * ap_ap * t11 + T(2) * seg0 * t12 * ab_ap - J1) * seg4 - T(2) * seg0 * delta_tau * tau_lo * t12;
  }
  f = length * F * seg7;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i3_prepare); operations per point.
/// Operations: 45 +, 95 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 53855 +, 83088 ×, 10112 /, 4518 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i3_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab1 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg3 = pre[13];
  const T delta_tau = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T g_factor = pre[21];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * seg0 * ab_ap;
    foot1 = ap1 - ab1 * seg0 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * seg0;
    foot1 = (ab0 * exact_cross[2] - ab2 * exact_cross[0]) * seg0;
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * seg0;
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t1 = seg3 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(2) * M_panels[5] * delta_tau * tau_lo + seg4 * M_panels[6] + seg5 * M_panels[4];
    G_ap = t4;
    G_E = T(2) * M_panels[6] * delta_tau * tau_lo + seg4 * M_panels[7] + M_panels[5] * seg5 - t4 * seg0 * ab_ap;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[4] * seg5 + seg4 * M_panels[6] + T(2) * M_panels[5] * delta_tau * tau_lo;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * seg5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    G_E = (T(1) / T(3)) * seg0 * (t8 + T(2) * seg4 * M_panels[1] + T(2) * delta_tau * tau_lo * M_panels[0] - t11 * seg6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r1;
    const T t13 = T(1) / r0;
    const T t14 = t12 * a_minus_b + t13 * ab_ap;
    const T t15 = T(1) / cross_cross;
    const T t16 = t13 * t13;
    const T t17 = t12 * t12;
    const T t18 = T(2) * t14 * ab_ab * t15 + t13 * t16 * ab_ap + t17 * t12 * a_minus_b;
    const T t19 = t13 * t16 + t18 * t15 * ab_ap - t17 * t12;
    G_ap = (T(1) / T(3)) * t18 * seg5 * t15 + (T(1) / T(3)) * seg4 * (T(3) * t14 * t15 + T(2) * t19 * seg0 * ab_ap - t18 * ap_ap * t15) * seg0 + (T(2) / T(3)) * t19 * delta_tau * seg0 * tau_lo;
    const T t20 = t13 * t13;
    const T t21 = t20 * t13;
    const T t22 = t21 * seg5;
    const T t23 = t12 * t12;
    const T t24 = t23 * t12;
    G_E = (T(1) / T(3)) * seg0 * (t22 + T(2) * t14 * delta_tau * t15 * tau_lo - t24 * seg6 - T(2) * (t12 - t14 * t15 * ab_ap - t13) * seg4 * seg0);
  }
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i3_prepare); operations per point.
/// Operations: 50 +, 116 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 53858 +, 83101 ×, 10113 /, 4518 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i3_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab1 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T delta_tau = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T length = pre[20];
  const T g_factor = pre[21];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = seg0 * (exact_cross[2] * ab0 - exact_cross[0] * ab2);
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = r1 * ab_ap;
    const T t3 = T(1) / cross_cross;
    X = seg1 * (t2 + a_minus_b * r0) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * ab_ap;
    X = -(a_minus_b - ab_ap) * seg1 / (t4 - a_minus_b * r0);
  }
  const T J1 = asinh(X) * seg2;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * cross_cross + seg3;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross + seg3));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(2) * M_panels[1] * delta_tau * tau_lo + seg4 * M_panels[2] + seg5 * M_panels[0];
    const T t8 = seg4 * M_panels[6] + seg5 * M_panels[4] + T(2) * M_panels[5] * delta_tau * tau_lo;
    G_ap = t8;
    G_E = M_panels[5] * seg5 + M_panels[7] * seg4 + T(2) * delta_tau * tau_lo * M_panels[6] - seg0 * t8 * ab_ap;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg5 + seg4 * M_panels[2] + T(2) * delta_tau * tau_lo * M_panels[1];
    G_ap = M_panels[4] * seg5 + M_panels[6] * seg4 + T(2) * delta_tau * tau_lo * M_panels[5];
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * seg5;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    G_E = (T(1) / T(3)) * seg0 * (T(2) * M_panels[0] * delta_tau * tau_lo + t12 + T(2) * seg4 * M_panels[1] - t15 * seg6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = t16 * ab_ap + a_minus_b * t17;
    const T t19 = T(1) / cross_cross;
    const T t20 = t17 - t18 * t19 * ab_ap - t16;
    F = t18 * seg5 * t19 - seg0 * (ap_ap * t18 * t19 + T(2) * seg0 * t20 * ab_ap - J1) * seg4 - T(2) * seg0 * t20 * delta_tau * tau_lo;
    const T t21 = t17 * t17;
    const T t22 = t16 * t16;
    const T t23 = a_minus_b * t17 * t21 + t22 * t16 * ab_ap + T(2) * t18 * ab_ab * t19;
    const T t24 = t23 * t19 * ab_ap + t22 * t16 - t17 * t21;
    G_ap = (T(1) / T(3)) * t23 * seg5 * t19 + (T(2) / T(3)) * seg0 * delta_tau * tau_lo * t24 - (T(1) / T(3)) * seg0 * seg4 * (ap_ap * t23 * t19 - T(2) * seg0 * t24 * ab_ap - T(3) * t18 * t19);
    const T t25 = t16 * t16;
    const T t26 = t25 * t16;
    const T t27 = t26 * seg5;
    const T t28 = t17 * t17;
    const T t29 = t28 * t17;
    G_E = (T(1) / T(3)) * seg0 * (t27 + T(2) * delta_tau * t18 * tau_lo * t19 - T(2) * seg0 * t20 * seg4 - t29 * seg6);
  }
  f = seg7 * F * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i4_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i4_prepared_size = 22;

/// What scalis_segment_inverse_i4_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 22): computed once per
/// segment; in.p is not read.
/// Operations: 9 +, 16 ×, 1 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i4_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * t0;
  const T g_factor = -T(4) * length * t1;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab1;
  pre[7] = ab0;
  pre[8] = ab2;
  pre[9] = ab_ab;
  const T t2 = T(1) / ab_ab;
  pre[10] = t2;
  pre[11] = -ab_ab * ab_ab;
  const T t3 = tau_lo * tau_lo;
  const T t4 = t3 * tau_lo;
  pre[12] = t4;
  const T t5 = delta_tau * delta_tau;
  pre[13] = t5;
  pre[14] = tau_lo;
  pre[15] = delta_tau;
  pre[16] = t3;
  const T t6 = t5 * delta_tau;
  pre[17] = t6;
  pre[18] = T(3) * t5 * tau_lo + t4 + t6 + T(3) * delta_tau * t3;
  pre[19] = length;
  pre[20] = t1;
  pre[21] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i4_prepare); operations per point.
/// Operations: 39 +, 71 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 45829 +, 55489 ×, 12648 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i4_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab0 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T tau_lo = pre[14];
  const T delta_tau = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T length = pre[19];
  const T seg7 = pre[20];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross + seg1;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross + seg1));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = seg2 * M_panels[0] + T(3) * M_panels[2] * tau_lo * seg3 + M_panels[3] * seg5 + T(3) * seg4 * delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(3) * M_panels[2] * tau_lo * seg3 + T(3) * M_panels[1] * seg4 * delta_tau + M_panels[3] * seg5 + seg2 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t6);
    const T t7 = T(1) / bp_bp;
    const T t8 = ab_ab * J2 + a_minus_b * t7 + ab_ap * t6;
    const T t9 = T(1) / cross_cross;
    const T t10 = t7 - t8 * t9 * ab_ap - t6;
    const T t11 = T(2) * J2 - T(2) * t10 * seg0 * ab_ap - t8 * t9 * ap_ap;
    F = (T(3) / T(2)) * seg0 * t11 * tau_lo * seg3 + (T(1) / T(2)) * t8 * seg2 * t9 + (T(1) / T(2)) * seg0 * (T(2) * seg0 * ab_ap * t11 + seg0 * (log_ratio + T(2) * J2 * ab_ap) + t10 * seg0 * ap_ap) * seg5 - (T(3) / T(2)) * t10 * seg0 * seg4 * delta_tau;
  }
  f = length * seg7 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i4_prepare); operations per point.
/// Operations: 54 +, 119 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 52019 +, 69199 ×, 8420 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i4_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab0 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T tau_lo = pre[14];
  const T delta_tau = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T g_factor = pre[21];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab2 * ab_ap * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = -(exact_cross[2] * ab1 - ab2 * exact_cross[1]) * seg0;
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * seg0;
    foot2 = (ab1 * exact_cross[0] - ab0 * exact_cross[1]) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(3) * seg3 * tau_lo * M_panels[7] + T(3) * seg4 * M_panels[6] * delta_tau + M_panels[8] * seg5 + seg2 * M_panels[5];
    G_ap = t4;
    G_E = seg2 * M_panels[6] + T(3) * M_panels[8] * seg3 * tau_lo + M_panels[9] * seg5 + T(3) * seg4 * delta_tau * M_panels[7] - ab_ap * t4 * seg0;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = seg2 * M_panels[5] + T(3) * M_panels[7] * seg3 * tau_lo + M_panels[8] * seg5 + T(3) * seg4 * delta_tau * M_panels[6];
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    G_E = -(T(1) / T(4)) * (t6 * seg6 - seg2 * t8 - T(3) * M_panels[2] * seg5 - T(6) * seg3 * M_panels[1] * tau_lo - T(3) * seg4 * delta_tau * M_panels[0]) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, ap_bp) * t10;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / bp_bp;
    const T t13 = T(1) / ap_ap;
    const T t14 = J2 * ab_ab + a_minus_b * t12 + ab_ap * t13;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(2) * ab_ap * t15 + T(3) * t11 * t14 * ab_ab + T(2) * a_minus_b * t16;
    const T t18 = t17 * t11 * ab_ap + T(2) * t15 - T(2) * t16;
    const T t19 = T(4) * t11 * t14 + T(2) * ab_ap * t18 * seg0 - t17 * t11 * ap_ap;
    const T t20 = t12 - t13 - t11 * ab_ap * t14;
    G_ap = (T(3) / T(8)) * seg3 * t19 * tau_lo * seg0 + (T(1) / T(8)) * seg2 * t17 * t11 + (T(1) / T(8)) * seg5 * seg0 * (T(2) * ab_ap * t19 * seg0 - t18 * ap_ap * seg0 - T(4) * t20 * seg0) + (T(3) / T(8)) * seg4 * t18 * delta_tau * seg0;
    G_E = (T(1) / T(8)) * seg0 * (T(3) * (T(2) * J2 - T(2) * ab_ap * t20 * seg0 - t11 * ap_ap * t14) * seg5 * seg0 + T(2) * seg2 * t15 + T(3) * t11 * seg4 * t14 * delta_tau - T(2) * t16 * seg6 - T(6) * seg3 * t20 * tau_lo * seg0);
  }
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i4_prepare); operations per point.
/// Operations: 60 +, 144 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 52022 +, 69209 ×, 8420 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i4_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab0 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T tau_lo = pre[14];
  const T delta_tau = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T length = pre[19];
  const T seg7 = pre[20];
  const T g_factor = pre[21];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab2 * ab_ap * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * seg0;
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * seg0;
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg2 + T(3) * delta_tau * seg4 * M_panels[1] + T(3) * M_panels[2] * tau_lo * seg3 + M_panels[3] * seg5;
    const T t4 = T(3) * delta_tau * seg4 * M_panels[6] + M_panels[5] * seg2 + T(3) * tau_lo * M_panels[7] * seg3 + seg5 * M_panels[8];
    G_ap = t4;
    G_E = M_panels[9] * seg5 + M_panels[6] * seg2 + T(3) * tau_lo * seg3 * M_panels[8] + T(3) * delta_tau * seg4 * M_panels[7] - t4 * ab_ap * seg0;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = seg2 * M_panels[0] + T(3) * tau_lo * M_panels[2] * seg3 + seg5 * M_panels[3] + T(3) * M_panels[1] * delta_tau * seg4;
    G_ap = M_panels[5] * seg2 + T(3) * delta_tau * seg4 * M_panels[6] + T(3) * tau_lo * M_panels[7] * seg3 + M_panels[8] * seg5;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    G_E = -(T(1) / T(4)) * (t6 * seg6 - T(3) * M_panels[2] * seg5 - T(6) * M_panels[1] * tau_lo * seg3 - seg2 * t8 - T(3) * delta_tau * seg4 * M_panels[0]) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, ap_bp) * t10;
    const T t11 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t11);
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * a_minus_b + ab_ap * t11 + ab_ab * J2;
    const T t15 = t11 + t12 * ab_ap * t14 - t13;
    const T t16 = t12 * t14 * ap_ap - T(2) * ab_ap * t15 * seg0 - T(2) * J2;
    F = (T(3) / T(2)) * delta_tau * seg4 * t15 * seg0 + (T(1) / T(2)) * ((log_ratio + T(2) * ab_ap * J2) * seg0 - T(2) * t16 * ab_ap * seg0 - t15 * ap_ap * seg0) * seg5 * seg0 + (T(1) / T(2)) * seg2 * t12 * t14 - (T(3) / T(2)) * t16 * tau_lo * seg3 * seg0;
    const T t17 = t13 * t13;
    const T t18 = t11 * t11;
    const T t19 = T(2) * t17 * a_minus_b + T(2) * ab_ap * t18 + T(3) * ab_ab * t12 * t14;
    const T t20 = T(2) * t17 - t19 * t12 * ab_ap - T(2) * t18;
    const T t21 = T(4) * t12 * t14 - T(2) * t20 * ab_ap * seg0 - t19 * t12 * ap_ap;
    G_ap = (T(1) / T(8)) * seg5 * (T(4) * t15 * seg0 + t20 * ap_ap * seg0 + T(2) * ab_ap * t21 * seg0) * seg0 + (T(1) / T(8)) * t19 * seg2 * t12 + (T(3) / T(8)) * tau_lo * t21 * seg3 * seg0 - (T(3) / T(8)) * delta_tau * seg4 * t20 * seg0;
    G_E = (T(1) / T(8)) * (T(6) * tau_lo * t15 * seg3 * seg0 + T(3) * delta_tau * seg4 * t12 * t14 + T(2) * seg2 * t18 - T(2) * t17 * seg6 - T(3) * t16 * seg5 * seg0) * seg0;
  }
  f = seg7 * length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i5_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i5_prepared_size = 26;

/// What scalis_segment_inverse_i5_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 26): computed once per
/// segment; in.p is not read.
/// Operations: 10 +, 21 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i5_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * t0;
  const T t2 = t1 * in.sigma;
  const T g_factor = -T(5) * length * t2;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab0;
  pre[7] = ab2;
  pre[8] = ab1;
  pre[9] = ab_ab;
  const T t3 = T(1) / ab_ab;
  pre[10] = t3;
  pre[11] = length;
  const T t4 = T(1) / length;
  pre[12] = t4;
  pre[13] = -ab_ab * ab_ab;
  const T t5 = delta_tau * delta_tau;
  const T t6 = t5 * delta_tau;
  pre[14] = t6;
  pre[15] = tau_lo;
  const T t7 = t5 * t5;
  pre[16] = t7;
  const T t8 = tau_lo * tau_lo;
  const T t9 = t8 * t8;
  pre[17] = t9;
  pre[18] = t5;
  pre[19] = t8;
  pre[20] = delta_tau;
  const T t10 = t8 * tau_lo;
  pre[21] = t10;
  pre[22] = T(4) * delta_tau * t10 + T(6) * t5 * t8 + T(4) * t6 * tau_lo + t7 + t9;
  pre[23] = length;
  pre[24] = t2;
  pre[25] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i5_prepare); operations per point.
/// Operations: 45 +, 100 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 40949 +, 61571 ×, 10111 /, 4518 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i5_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T delta_tau = pre[20];
  const T seg9 = pre[21];
  const T length = pre[23];
  const T seg11 = pre[24];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = ab_ap * r1;
    X = t2 * (t3 + a_minus_b * r0) * seg1;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = ab_ap * r1;
    X = -(a_minus_b - ab_ap) * seg1 / (t4 - a_minus_b * r0);
  }
  const T J1 = seg2 * asinh(X);
  T F;
  const T t5 = T(4) * cross_cross + seg3;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross + seg3));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(4) * seg4 * M_panels[3] * tau_lo + M_panels[0] * seg6 + T(6) * seg7 * M_panels[2] * seg8 + T(4) * seg9 * delta_tau * M_panels[1] + seg5 * M_panels[4];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(4) * M_panels[3] * seg4 * tau_lo + seg5 * M_panels[4] + T(4) * seg9 * M_panels[1] * delta_tau + T(6) * seg7 * seg8 * M_panels[2] + M_panels[0] * seg6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / r1;
    const T t11 = a_minus_b * t10 + ab_ap * t8;
    const T t12 = t8 + ab_ap * t9 * t11 - t10;
    const T t13 = t8 * t8;
    const T t14 = t10 * t10;
    const T t15 = T(2) * t9 * t11 * ab_ab + ab_ap * t8 * t13 + a_minus_b * t14 * t10;
    const T t16 = t8 * t13 + ab_ap * t9 * t15 - t14 * t10;
    const T t17 = T(3) * t9 * t11 + T(2) * ab_ap * t16 * seg0 - t9 * ap_ap * t15;
    const T t18 = T(3) * t12 * seg0 + T(2) * ab_ap * t17 * seg0 - ap_ap * t16 * seg0;
    F = (T(1) / T(3)) * seg5 * seg0 * (T(2) * t18 * ab_ap * seg0 + T(3) * (J1 + T(2) * ab_ap * t12 * seg0 - t9 * t11 * ap_ap) * seg0 - ap_ap * t17 * seg0) + T(2) * seg7 * t17 * seg0 * seg8 + (T(1) / T(3)) * t9 * seg6 * t15 + (T(4) / T(3)) * t18 * seg4 * seg0 * tau_lo + (T(4) / T(3)) * seg9 * t16 * seg0 * delta_tau;
  }
  f = seg11 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i5_prepare); operations per point.
/// Operations: 61 +, 160 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 50929 +, 78036 ×, 7245 /, 3237 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i5_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T delta_tau = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T g_factor = pre[25];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * seg0;
    foot1 = -seg0 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t1 = seg3 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(4) * seg4 * M_panels[9] * tau_lo + seg6 * M_panels[6] + M_panels[10] * seg5 + T(4) * delta_tau * seg9 * M_panels[7] + T(6) * seg8 * seg7 * M_panels[8];
    G_ap = t4;
    G_E = T(4) * seg4 * tau_lo * M_panels[10] + T(6) * M_panels[9] * seg8 * seg7 + T(4) * delta_tau * seg9 * M_panels[8] + seg6 * M_panels[7] + seg5 * M_panels[11] - t4 * seg0 * ab_ap;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[6] * seg6 + T(4) * M_panels[7] * delta_tau * seg9 + T(6) * seg8 * M_panels[8] * seg7 + T(4) * M_panels[9] * seg4 * tau_lo + M_panels[10] * seg5;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(5)) * (T(4) * M_panels[3] * seg5 + T(4) * M_panels[0] * delta_tau * seg9 + seg6 * t8 + T(12) * seg8 * M_panels[1] * seg7 + T(12) * seg4 * tau_lo * M_panels[2] - t12 * seg10) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t16 * a_minus_b + t13 * ab_ap;
    const T t19 = T(1) / cross_cross;
    const T t20 = t16 * a_minus_b * t17 + t14 * t13 * ab_ap + T(2) * ab_ab * t18 * t19;
    const T t21 = t17 * t17;
    const T t22 = T(4) * t20 * ab_ab * t19 + T(3) * t15 * t13 * ab_ap + T(3) * t16 * a_minus_b * t21;
    const T t23 = T(3) * t15 * t13 + t22 * t19 * ab_ap - T(3) * t16 * t21;
    const T t24 = ap_ap * t22 * t19 - T(2) * seg0 * t23 * ab_ap - T(5) * t20 * t19;
    const T t25 = t20 * t19 * ab_ap + t14 * t13 - t16 * t17;
    const T t26 = T(2) * t24 * seg0 * ab_ap + ap_ap * seg0 * t23 - T(5) * t25 * seg0;
    const T t27 = T(3) * t18 * t19 + T(2) * t25 * seg0 * ab_ap - ap_ap * t20 * t19;
    G_ap = (T(4) / T(15)) * seg0 * delta_tau * seg9 * t23 + (T(1) / T(15)) * seg6 * t22 * t19 - (T(2) / T(5)) * t24 * seg0 * seg8 * seg7 - (T(1) / T(15)) * (T(2) * seg0 * t26 * ab_ap - t24 * ap_ap * seg0 - T(5) * seg0 * t27) * seg0 * seg5 - (T(4) / T(15)) * seg4 * seg0 * tau_lo * t26;
    const T t28 = t13 * t13;
    const T t29 = t28 * t28;
    const T t30 = t29 * t13;
    const T t31 = t16 * t16;
    const T t32 = t31 * t31;
    const T t33 = t32 * t16;
    G_E = (T(1) / T(15)) * (T(12) * seg4 * seg0 * t27 * tau_lo + T(12) * t25 * seg0 * seg8 * seg7 + T(3) * seg6 * t30 + T(4) * t20 * delta_tau * seg9 * t19 - T(4) * (t25 * ap_ap * seg0 - T(2) * seg0 * t27 * ab_ap - T(3) * seg0 * (t18 * t19 * ab_ap + t13 - t16)) * seg0 * seg5 - T(3) * t33 * seg10) * seg0;
  }
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i5_prepare); operations per point.
/// Operations: 70 +, 198 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 50934 +, 78055 ×, 7246 /, 3237 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i5_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab2 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T delta_tau = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T length = pre[23];
  const T seg11 = pre[24];
  const T g_factor = pre[25];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * ab0 * seg0;
    foot1 = ap1 - ab_ap * ab1 * seg0;
    foot2 = ap2 - ab_ap * ab2 * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * seg0;
    foot1 = (exact_cross[2] * ab0 - exact_cross[0] * ab2) * seg0;
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / cross_cross;
    X = (t2 + ab_ap * r1) * seg1 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = -seg1 * (ab_ap - a_minus_b) / (t4 - ab_ap * r1);
  }
  const T J1 = asinh(X) * seg2;
  T F;
  T G_ap;
  T G_E;
  const T t5 = seg3 + T(4) * cross_cross;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(4) * M_panels[1] * delta_tau * seg9 + T(6) * seg7 * M_panels[2] * seg8 + M_panels[0] * seg6 + M_panels[4] * seg5 + T(4) * seg4 * tau_lo * M_panels[3];
    const T t8 = T(4) * M_panels[7] * delta_tau * seg9 + M_panels[10] * seg5 + M_panels[6] * seg6 + T(4) * seg4 * tau_lo * M_panels[9] + T(6) * seg7 * M_panels[8] * seg8;
    G_ap = t8;
    G_E = T(4) * M_panels[10] * seg4 * tau_lo + M_panels[11] * seg5 + T(6) * seg7 * seg8 * M_panels[9] + T(4) * M_panels[8] * delta_tau * seg9 + M_panels[7] * seg6 - ab_ap * t8 * seg0;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = seg5 * M_panels[4] + T(4) * delta_tau * seg9 * M_panels[1] + T(6) * M_panels[2] * seg7 * seg8 + M_panels[0] * seg6 + T(4) * seg4 * M_panels[3] * tau_lo;
    G_ap = seg5 * M_panels[10] + M_panels[6] * seg6 + T(4) * delta_tau * M_panels[7] * seg9 + T(6) * M_panels[8] * seg7 * seg8 + T(4) * seg4 * M_panels[9] * tau_lo;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t13;
    G_E = (T(1) / T(5)) * (T(4) * M_panels[3] * seg5 + t12 * seg6 + T(4) * delta_tau * M_panels[0] * seg9 + T(12) * M_panels[2] * seg4 * tau_lo + T(12) * seg7 * seg8 * M_panels[1] - seg10 * t16) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = a_minus_b * t19 + ab_ap * t17;
    const T t21 = T(1) / cross_cross;
    const T t22 = t19 * t19;
    const T t23 = ab_ap * t18 * t17 + T(2) * ab_ab * t20 * t21 + t22 * a_minus_b * t19;
    const T t24 = t18 * t17 + ab_ap * t23 * t21 - t22 * t19;
    const T t25 = t23 * ap_ap * t21 - T(2) * ab_ap * t24 * seg0 - T(3) * t20 * t21;
    const T t26 = t19 - t17 - ab_ap * t20 * t21;
    const T t27 = T(2) * ab_ap * t25 * seg0 + T(3) * t26 * seg0 + ap_ap * t24 * seg0;
    F = (T(1) / T(3)) * (ap_ap * t25 * seg0 - T(3) * (ap_ap * t20 * t21 + T(2) * ab_ap * t26 * seg0 - J1) * seg0 - T(2) * ab_ap * t27 * seg0) * seg5 * seg0 + (T(1) / T(3)) * t23 * t21 * seg6 + (T(4) / T(3)) * t24 * delta_tau * seg9 * seg0 - T(2) * seg7 * seg8 * t25 * seg0 - (T(4) / T(3)) * seg4 * t27 * tau_lo * seg0;
    const T t28 = t22 * t22;
    const T t29 = t18 * t18;
    const T t30 = T(4) * t23 * ab_ab * t21 + T(3) * t28 * a_minus_b * t19 + T(3) * ab_ap * t29 * t17;
    const T t31 = T(3) * t28 * t19 - ab_ap * t30 * t21 - T(3) * t29 * t17;
    const T t32 = ap_ap * t30 * t21 + T(2) * ab_ap * t31 * seg0 - T(5) * t23 * t21;
    const T t33 = T(5) * t24 * seg0 + ap_ap * t31 * seg0 - T(2) * t32 * ab_ap * seg0;
    G_ap = (T(1) / T(15)) * t30 * t21 * seg6 + (T(4) / T(15)) * t33 * seg4 * tau_lo * seg0 - (T(1) / T(15)) * seg5 * (T(5) * t25 * seg0 - t32 * ap_ap * seg0 - T(2) * t33 * ab_ap * seg0) * seg0 - (T(2) / T(5)) * t32 * seg7 * seg8 * seg0 - (T(4) / T(15)) * t31 * delta_tau * seg9 * seg0;
    const T t34 = t17 * t17;
    const T t35 = t34 * t34;
    const T t36 = t35 * t17;
    const T t37 = t19 * t19;
    const T t38 = t37 * t37;
    const T t39 = t38 * t19;
    G_E = (T(1) / T(15)) * (T(12) * seg7 * t24 * seg8 * seg0 + T(4) * t23 * delta_tau * seg9 * t21 + T(3) * t36 * seg6 - T(12) * seg4 * tau_lo * t25 * seg0 - T(3) * seg10 * t39 - T(4) * t27 * seg5 * seg0) * seg0;
  }
  f = length * F * seg11;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

/// How many values scalis_segment_inverse_i6_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i6_prepared_size = 26;

/// What scalis_segment_inverse_i6_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 26): computed once per
/// segment; in.p is not read.
/// Operations: 11 +, 25 ×, 1 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i6_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * in.sigma;
  const T t2 = t1 * t1;
  const T g_factor = -T(6) * length * t2;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab1;
  pre[7] = ab2;
  pre[8] = ab0;
  pre[9] = ab_ab;
  const T t3 = T(1) / ab_ab;
  pre[10] = t3;
  pre[11] = -ab_ab * ab_ab;
  pre[12] = delta_tau;
  const T t4 = tau_lo * tau_lo;
  const T t5 = t4 * t4;
  pre[13] = t5;
  const T t6 = delta_tau * delta_tau;
  const T t7 = t6 * t6;
  pre[14] = t7;
  pre[15] = tau_lo;
  const T t8 = t6 * delta_tau;
  pre[16] = t8;
  pre[17] = t4;
  const T t9 = t7 * delta_tau;
  pre[18] = t9;
  const T t10 = t5 * tau_lo;
  pre[19] = t10;
  pre[20] = t6;
  const T t11 = t4 * tau_lo;
  pre[21] = t11;
  pre[22] = T(10) * t8 * t4 + t9 + T(5) * delta_tau * t5 + T(10) * t6 * t11 + T(5) * t7 * tau_lo + t10;
  pre[23] = length;
  pre[24] = t2;
  pre[25] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i6_prepare); operations per point.
/// Operations: 53 +, 120 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 37691 +, 51275 ×, 8418 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i6_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T delta_tau = pre[12];
  const T seg2 = pre[13];
  const T seg3 = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T length = pre[23];
  const T seg11 = pre[24];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(5) * seg3 * tau_lo * M_panels[4] + T(5) * delta_tau * M_panels[1] * seg2 + T(10) * seg8 * seg9 * M_panels[2] + T(10) * M_panels[3] * seg5 * seg4 + seg6 * M_panels[5] + M_panels[0] * seg7;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg7 + M_panels[5] * seg6 + T(5) * delta_tau * M_panels[1] * seg2 + T(10) * seg8 * seg9 * M_panels[2] + T(5) * seg3 * M_panels[4] * tau_lo + T(10) * M_panels[3] * seg5 * seg4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(1) / ap_ap;
    const T log_ratio = log(t6 * bp_bp);
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / bp_bp;
    const T t10 = a_minus_b * t9 + t6 * ab_ap + J2 * ab_ab;
    const T t11 = t9 * t9;
    const T t12 = T(2) * t7 * ab_ap + T(3) * ab_ab * t8 * t10 + T(2) * a_minus_b * t11;
    const T t13 = T(2) * t7 + t12 * t8 * ab_ap - T(2) * t11;
    const T t14 = T(2) * seg0 * t13 * ab_ap + T(4) * t8 * t10 - ap_ap * t12 * t8;
    const T t15 = t8 * t10 * ab_ap + t6 - t9;
    const T t16 = T(4) * t15 * seg0 + T(2) * seg0 * t14 * ab_ap - ap_ap * seg0 * t13;
    const T t17 = T(2) * t15 * seg0 * ab_ap + T(2) * J2 - ap_ap * t8 * t10;
    const T t18 = ap_ap * seg0 * t14 - T(4) * t17 * seg0 - T(2) * seg0 * t16 * ab_ap;
    F = (T(5) / T(8)) * delta_tau * seg0 * seg2 * t13 + (T(1) / T(8)) * t12 * t8 * seg7 + (T(5) / T(4)) * seg8 * seg0 * seg9 * t14 + (T(5) / T(4)) * seg5 * seg0 * t16 * seg4 - (T(1) / T(8)) * seg0 * seg6 * (T(2) * t18 * seg0 * ab_ap + ap_ap * seg0 * t16 - T(4) * (seg0 * (T(2) * J2 * ab_ap + log_ratio) + T(2) * t17 * seg0 * ab_ap - ap_ap * t15 * seg0) * seg0) - (T(5) / T(8)) * seg3 * t18 * tau_lo * seg0;
  }
  f = F * seg11 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i6_prepare); operations per point.
/// Operations: 72 +, 183 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 49693 +, 65243 ×, 6305 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i6_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T delta_tau = pre[12];
  const T seg2 = pre[13];
  const T seg3 = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T g_factor = pre[25];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab_ap * ab0;
    foot1 = ap1 - seg0 * ab_ap * ab1;
    foot2 = ap2 - seg0 * ab_ap * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -seg0 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = -seg0 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(5) * M_panels[11] * seg3 * tau_lo + T(5) * M_panels[8] * delta_tau * seg2 + seg6 * M_panels[12] + seg7 * M_panels[7] + T(10) * seg4 * M_panels[10] * seg5 + T(10) * seg9 * M_panels[9] * seg8;
    G_ap = t4;
    G_E = T(10) * seg9 * M_panels[10] * seg8 + T(5) * M_panels[9] * delta_tau * seg2 + M_panels[8] * seg7 + T(5) * M_panels[12] * seg3 * tau_lo + seg6 * M_panels[13] + T(10) * M_panels[11] * seg4 * seg5 - seg0 * ab_ap * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = T(5) * M_panels[8] * delta_tau * seg2 + M_panels[7] * seg7 + seg6 * M_panels[12] + T(10) * seg9 * seg8 * M_panels[9] + T(5) * M_panels[11] * seg3 * tau_lo + T(10) * M_panels[10] * seg4 * seg5;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    G_E = (T(1) / T(6)) * seg0 * (T(30) * seg4 * M_panels[2] * seg5 + t7 * seg7 + T(20) * seg9 * M_panels[1] * seg8 + T(5) * seg6 * M_panels[4] + T(5) * M_panels[0] * delta_tau * seg2 + T(20) * M_panels[3] * seg3 * tau_lo - t10 * seg10);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = ab_ap * t16 + a_minus_b * t13 + J2 * ab_ab;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(2) * a_minus_b * t14 + T(3) * t19 * ab_ab * t20 + T(2) * ab_ap * t17;
    const T t22 = T(8) * a_minus_b * t15 + T(8) * ab_ap * t18 + T(5) * t21 * ab_ab * t20;
    const T t23 = T(2) * t14 - ab_ap * t21 * t20 - T(2) * t17;
    const T t24 = ab_ap * t19 * t20 + t16 - t13;
    const T t25 = T(2) * seg0 * ab_ap * t23 + t21 * ap_ap * t20 - T(4) * t19 * t20;
    const T t26 = seg0 * t23 * ap_ap + T(4) * seg0 * t24 - T(2) * seg0 * t25 * ab_ap;
    const T t27 = T(8) * t15 - ab_ap * t22 * t20 - T(8) * t18;
    const T t28 = ap_ap * t22 * t20 + T(2) * seg0 * ab_ap * t27 - T(6) * t21 * t20;
    const T t29 = T(2) * seg0 * ab_ap * t28 + T(6) * seg0 * t23 - seg0 * t27 * ap_ap;
    const T t30 = T(6) * seg0 * t25 + T(2) * seg0 * ab_ap * t29 - seg0 * ap_ap * t28;
    G_ap = (T(1) / T(48)) * seg7 * t22 * t20 + (T(1) / T(48)) * seg0 * seg6 * (T(6) * seg0 * t26 + seg0 * ap_ap * t29 - T(2) * seg0 * ab_ap * t30) - (T(5) / T(24)) * seg0 * seg4 * seg5 * t29 - (T(5) / T(48)) * seg0 * seg3 * tau_lo * t30 - (T(5) / T(24)) * seg0 * seg9 * t28 * seg8 - (T(5) / T(48)) * seg0 * t27 * delta_tau * seg2;
    G_E = (T(1) / T(48)) * seg0 * (T(5) * seg0 * seg6 * (T(2) * seg0 * ab_ap * t26 + T(4) * seg0 * (T(2) * J2 + T(2) * seg0 * ab_ap * t24 - t19 * ap_ap * t20) + seg0 * t25 * ap_ap) + T(20) * seg0 * seg3 * t26 * tau_lo + T(8) * t18 * seg7 + T(5) * t21 * delta_tau * seg2 * t20 - T(8) * t15 * seg10 - T(30) * seg0 * t25 * seg4 * seg5 - T(20) * seg0 * seg9 * t23 * seg8);
  }
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i6_prepare); operations per point.
/// Operations: 82 +, 223 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 49698 +, 65259 ×, 6305 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i6_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T delta_tau = pre[12];
  const T seg2 = pre[13];
  const T seg3 = pre[14];
  const T tau_lo = pre[15];
  const T seg4 = pre[16];
  const T seg5 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T length = pre[23];
  const T seg11 = pre[24];
  const T g_factor = pre[25];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * ab0 * seg0;
    foot1 = ap1 - ab_ap * ab1 * seg0;
    foot2 = ap2 - ab_ap * ab2 * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * seg0;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * seg0;
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(5) * M_panels[1] * seg2 * delta_tau + T(5) * M_panels[4] * tau_lo * seg3 + M_panels[5] * seg6 + M_panels[0] * seg7 + T(10) * seg4 * seg5 * M_panels[3] + T(10) * seg8 * M_panels[2] * seg9;
    const T t4 = T(5) * M_panels[11] * tau_lo * seg3 + T(10) * seg8 * seg9 * M_panels[9] + M_panels[7] * seg7 + T(10) * M_panels[10] * seg4 * seg5 + M_panels[12] * seg6 + T(5) * M_panels[8] * seg2 * delta_tau;
    G_ap = t4;
    G_E = M_panels[8] * seg7 + T(10) * M_panels[10] * seg8 * seg9 + T(5) * tau_lo * M_panels[12] * seg3 + T(5) * seg2 * delta_tau * M_panels[9] + T(10) * seg4 * M_panels[11] * seg5 + seg6 * M_panels[13] - ab_ap * t4 * seg0;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(5) * seg2 * delta_tau * M_panels[1] + seg6 * M_panels[5] + T(10) * seg8 * seg9 * M_panels[2] + T(5) * M_panels[4] * tau_lo * seg3 + M_panels[0] * seg7 + T(10) * seg4 * M_panels[3] * seg5;
    G_ap = M_panels[12] * seg6 + T(10) * M_panels[9] * seg8 * seg9 + M_panels[7] * seg7 + T(5) * tau_lo * seg3 * M_panels[11] + T(10) * seg4 * seg5 * M_panels[10] + T(5) * seg2 * delta_tau * M_panels[8];
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    G_E = (T(1) / T(6)) * (T(5) * M_panels[0] * seg2 * delta_tau + T(20) * M_panels[3] * tau_lo * seg3 + t7 * seg7 + T(20) * seg8 * M_panels[1] * seg9 + T(5) * M_panels[4] * seg6 + T(30) * seg4 * seg5 * M_panels[2] - t10 * seg10) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t13);
    const T t14 = T(1) / bp_bp;
    const T t15 = t14 * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = ab_ap * t13 + t14 * a_minus_b + J2 * ab_ab;
    const T t18 = t13 * t13;
    const T t19 = T(2) * t15 * a_minus_b + T(3) * ab_ab * t16 * t17 + T(2) * ab_ap * t18;
    const T t20 = ab_ap * t16 * t17 + t13 - t14;
    const T t21 = T(2) * J2 + T(2) * ab_ap * t20 * seg0 - ap_ap * t16 * t17;
    const T t22 = T(2) * t15 - ab_ap * t19 * t16 - T(2) * t18;
    const T t23 = T(2) * ab_ap * t22 * seg0 + ap_ap * t19 * t16 - T(4) * t16 * t17;
    const T t24 = T(2) * ab_ap * seg0 * t23 - T(4) * t20 * seg0 - t22 * ap_ap * seg0;
    const T t25 = T(4) * t21 * seg0 + ap_ap * seg0 * t23 - T(2) * ab_ap * t24 * seg0;
    F = (T(1) / T(8)) * t19 * t16 * seg7 + (T(5) / T(8)) * t25 * tau_lo * seg3 * seg0 + (T(1) / T(8)) * (ap_ap * t24 * seg0 + T(2) * ab_ap * t25 * seg0 + T(4) * seg0 * (T(2) * ab_ap * t21 * seg0 + (T(2) * ab_ap * J2 + log_ratio) * seg0 - ap_ap * t20 * seg0)) * seg6 * seg0 - (T(5) / T(4)) * seg8 * seg9 * seg0 * t23 - (T(5) / T(8)) * t22 * seg2 * delta_tau * seg0 - (T(5) / T(4)) * seg4 * seg5 * t24 * seg0;
    const T t26 = t15 * t14;
    const T t27 = t18 * t13;
    const T t28 = T(5) * ab_ab * t19 * t16 + T(8) * t26 * a_minus_b + T(8) * ab_ap * t27;
    const T t29 = ab_ap * t28 * t16 + T(8) * t27 - T(8) * t26;
    const T t30 = t28 * ap_ap * t16 - T(2) * ab_ap * t29 * seg0 - T(6) * t19 * t16;
    const T t31 = T(2) * ab_ap * t30 * seg0 + T(6) * t22 * seg0 + ap_ap * t29 * seg0;
    const T t32 = T(2) * ab_ap * t31 * seg0 + T(6) * seg0 * t23 - ap_ap * t30 * seg0;
    G_ap = (T(1) / T(48)) * t28 * t16 * seg7 + (T(5) / T(48)) * seg2 * delta_tau * t29 * seg0 - (T(5) / T(48)) * tau_lo * t32 * seg3 * seg0 - (T(5) / T(24)) * seg8 * seg9 * t30 * seg0 - (T(5) / T(24)) * seg4 * seg5 * t31 * seg0 - (T(1) / T(48)) * seg6 * (T(2) * ab_ap * t32 * seg0 + T(6) * t24 * seg0 - ap_ap * t31 * seg0) * seg0;
    G_E = -(T(1) / T(48)) * (T(30) * seg4 * seg5 * seg0 * t23 + T(20) * seg8 * t22 * seg9 * seg0 + T(8) * t26 * seg10 + T(20) * t24 * tau_lo * seg3 * seg0 - T(5) * t25 * seg6 * seg0 - T(8) * t27 * seg7 - T(5) * seg2 * delta_tau * t19 * t16) * seg0;
  }
  f = length * seg11 * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i7_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i7_prepared_size = 30;

/// What scalis_segment_inverse_i7_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 30): computed once per
/// segment; in.p is not read.
/// Operations: 12 +, 30 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i7_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * in.sigma;
  const T t2 = t1 * t1;
  const T t3 = t2 * in.sigma;
  const T g_factor = -T(7) * t3 * length;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab2;
  pre[7] = ab0;
  pre[8] = ab1;
  pre[9] = ab_ab;
  const T t4 = T(1) / ab_ab;
  pre[10] = t4;
  pre[11] = length;
  const T t5 = T(1) / length;
  pre[12] = t5;
  pre[13] = -ab_ab * ab_ab;
  const T t6 = delta_tau * delta_tau;
  pre[14] = t6;
  const T t7 = tau_lo * tau_lo;
  const T t8 = t7 * t7;
  pre[15] = t8;
  const T t9 = t7 * tau_lo;
  const T t10 = t9 * t9;
  pre[16] = t10;
  const T t11 = t6 * delta_tau;
  pre[17] = t11;
  pre[18] = t9;
  const T t12 = t11 * t11;
  pre[19] = t12;
  const T t13 = t6 * t6;
  pre[20] = t13;
  pre[21] = t7;
  pre[22] = delta_tau;
  const T t14 = t8 * tau_lo;
  pre[23] = t14;
  const T t15 = t13 * delta_tau;
  pre[24] = t15;
  pre[25] = tau_lo;
  pre[26] = T(15) * t13 * t7 + T(6) * t15 * tau_lo + T(15) * t6 * t8 + t10 + T(6) * delta_tau * t14 + t12 + T(20) * t11 * t9;
  pre[27] = t3;
  pre[28] = length;
  pre[29] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i7_prepare); operations per point.
/// Operations: 61 +, 158 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 35521 +, 59531 ×, 7244 /, 3237 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i7_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T seg7 = pre[17];
  const T seg8 = pre[18];
  const T seg9 = pre[19];
  const T seg10 = pre[20];
  const T seg11 = pre[21];
  const T delta_tau = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T tau_lo = pre[25];
  const T seg15 = pre[27];
  const T length = pre[28];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = r0 * a_minus_b;
    X = t2 * (t3 + ab_ap * r1) * seg1;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * seg1 / (t4 - ab_ap * r1);
  }
  const T J1 = asinh(X) * seg2;
  T F;
  const T t5 = T(4) * cross_cross + seg3;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross + seg3));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(6) * M_panels[5] * seg13 * tau_lo + M_panels[0] * seg6 + T(20) * M_panels[3] * seg7 * seg8 + M_panels[6] * seg9 + T(15) * M_panels[2] * seg4 * seg5 + T(6) * seg12 * delta_tau * M_panels[1] + T(15) * seg11 * seg10 * M_panels[4];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg6 + seg9 * M_panels[6] + T(15) * seg11 * seg10 * M_panels[4] + T(6) * seg12 * delta_tau * M_panels[1] + T(15) * seg4 * M_panels[2] * seg5 + T(6) * M_panels[5] * seg13 * tau_lo + T(20) * seg7 * M_panels[3] * seg8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t9 * ab_ap + t12 * a_minus_b;
    const T t16 = T(2) * t8 * t15 * ab_ab + t13 * t12 * a_minus_b + t9 * ab_ap * t10;
    const T t17 = T(3) * t9 * ab_ap * t11 + T(3) * t14 * t12 * a_minus_b + T(4) * t8 * t16 * ab_ab;
    const T t18 = T(3) * t14 * t12 - t8 * ab_ap * t17 - T(3) * t9 * t11;
    const T t19 = T(5) * t8 * t16 - T(2) * ab_ap * t18 * seg0 - t8 * t17 * ap_ap;
    const T t20 = t9 * t10 + t8 * ab_ap * t16 - t13 * t12;
    const T t21 = T(2) * ab_ap * seg0 * t19 + T(5) * t20 * seg0 + t18 * ap_ap * seg0;
    const T t22 = t8 * ap_ap * t16 - T(2) * ab_ap * t20 * seg0 - T(3) * t8 * t15;
    const T t23 = t12 - t9 - t8 * ab_ap * t15;
    const T t24 = T(2) * ab_ap * t22 * seg0 + T(3) * t23 * seg0 + ap_ap * t20 * seg0;
    const T t25 = T(5) * t22 * seg0 + ap_ap * seg0 * t19 - T(2) * t21 * ab_ap * seg0;
    const T t26 = T(5) * t24 * seg0 + t21 * ap_ap * seg0 + T(2) * ab_ap * t25 * seg0;
    F = (T(1) / T(15)) * t8 * t17 * seg6 + (T(4) / T(3)) * t21 * seg7 * seg0 * seg8 + seg4 * seg5 * seg0 * t19 - (T(2) / T(5)) * seg13 * tau_lo * seg0 * t26 - seg11 * seg10 * t25 * seg0 - (T(1) / T(15)) * seg9 * (T(2) * ab_ap * seg0 * t26 - T(5) * seg0 * (T(3) * seg0 * (J1 - t8 * ap_ap * t15 - T(2) * ab_ap * t23 * seg0) + t22 * ap_ap * seg0 - T(2) * ab_ap * t24 * seg0) - ap_ap * t25 * seg0) * seg0 - (T(2) / T(5)) * seg12 * t18 * delta_tau * seg0;
  }
  f = seg15 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i7_prepare); operations per point.
/// Operations: 81 +, 239 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48903 +, 74620 ×, 5600 /, 2502 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i7_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T seg7 = pre[17];
  const T seg8 = pre[18];
  const T seg9 = pre[19];
  const T seg10 = pre[20];
  const T seg11 = pre[21];
  const T delta_tau = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T tau_lo = pre[25];
  const T seg14 = pre[26];
  const T g_factor = pre[29];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * seg0 * ab0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -seg0 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * seg0;
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t1 = seg3 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(6) * seg13 * tau_lo * M_panels[13] + M_panels[14] * seg9 + T(15) * M_panels[12] * seg10 * seg11 + T(20) * M_panels[11] * seg7 * seg8 + M_panels[8] * seg6 + T(6) * seg12 * M_panels[9] * delta_tau + T(15) * seg5 * M_panels[10] * seg4;
    G_ap = t4;
    G_E = T(6) * M_panels[14] * seg13 * tau_lo + M_panels[9] * seg6 + T(20) * seg7 * M_panels[12] * seg8 + T(6) * seg12 * delta_tau * M_panels[10] + T(15) * seg10 * M_panels[13] * seg11 + T(15) * M_panels[11] * seg5 * seg4 + seg9 * M_panels[15] - ab_ap * seg0 * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[8] * seg6 + T(6) * seg12 * M_panels[9] * delta_tau + seg9 * M_panels[14] + T(15) * seg5 * seg4 * M_panels[10] + T(15) * seg10 * M_panels[12] * seg11 + T(20) * M_panels[11] * seg7 * seg8 + T(6) * seg13 * tau_lo * M_panels[13];
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    G_E = (T(1) / T(7)) * (T(60) * seg10 * M_panels[3] * seg11 + T(6) * seg9 * M_panels[5] + t9 * seg6 + T(30) * seg13 * tau_lo * M_panels[4] + T(6) * seg12 * delta_tau * M_panels[0] + T(30) * seg5 * seg4 * M_panels[1] + T(60) * seg7 * M_panels[2] * seg8 - t14 * seg14) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = ab_ap * t15 + a_minus_b * t18;
    const T t22 = T(1) / cross_cross;
    const T t23 = a_minus_b * t19 * t18 + ab_ap * t16 * t15 + T(2) * t21 * ab_ab * t22;
    const T t24 = T(3) * ab_ap * t17 * t15 + T(3) * a_minus_b * t20 * t18 + T(4) * t23 * ab_ab * t22;
    const T t25 = t17 * t16;
    const T t26 = t20 * t19;
    const T t27 = T(2) * t24 * ab_ab * t22 + T(5) * ab_ap * t25 * t15 + T(5) * a_minus_b * t26 * t18;
    const T t28 = ab_ap * t27 * t22 + T(5) * t25 * t15 - T(5) * t26 * t18;
    const T t29 = ab_ap * t24 * t22 + T(3) * t17 * t15 - T(3) * t20 * t18;
    const T t30 = ap_ap * t24 * t22 - T(5) * t23 * t22 - T(2) * ab_ap * t29 * seg0;
    const T t31 = t19 * t18 - t16 * t15 - ab_ap * t23 * t22;
    const T t32 = t29 * ap_ap * seg0 + T(2) * ab_ap * seg0 * t30 + T(5) * seg0 * t31;
    const T t33 = ap_ap * t23 * t22 + T(2) * ab_ap * seg0 * t31 - T(3) * t21 * t22;
    const T t34 = ap_ap * seg0 * t30 - T(2) * ab_ap * seg0 * t32 - T(5) * seg0 * t33;
    const T t35 = T(6) * ab_ap * seg0 * t28 + T(7) * t24 * t22 - T(3) * ap_ap * t27 * t22;
    const T t36 = T(3) * ap_ap * seg0 * t28 - T(2) * ab_ap * seg0 * t35 - T(7) * t29 * seg0;
    const T t37 = ap_ap * seg0 * t35 + T(7) * seg0 * t30 + T(2) * ab_ap * seg0 * t36;
    const T t38 = ap_ap * seg0 * t36 - T(7) * seg0 * t32 - T(2) * ab_ap * t37 * seg0;
    G_ap = (T(1) / T(35)) * t27 * seg6 * t22 + (T(6) / T(35)) * seg0 * seg12 * t28 * delta_tau + (T(1) / T(105)) * seg9 * seg0 * (T(7) * seg0 * t34 + T(2) * ab_ap * seg0 * t38 + t37 * ap_ap * seg0) + (T(1) / T(7)) * seg5 * seg0 * seg4 * t35 + (T(2) / T(35)) * seg0 * seg13 * tau_lo * t38 - (T(1) / T(7)) * t37 * seg0 * seg10 * seg11 - (T(4) / T(21)) * seg7 * seg0 * seg8 * t36;
    const T t39 = t15 * t15;
    const T t40 = t39 * t15;
    const T t41 = t40 * t40;
    const T t42 = t41 * t15;
    const T t43 = t18 * t18;
    const T t44 = t43 * t18;
    const T t45 = t44 * t44;
    const T t46 = t45 * t18;
    G_E = (T(1) / T(35)) * (T(5) * t42 * seg6 + T(10) * seg0 * t34 * seg13 * tau_lo + T(2) * seg9 * seg0 * (T(5) * seg0 * (ap_ap * seg0 * t31 + T(3) * (t15 + ab_ap * t21 * t22 - t18) * seg0 - T(2) * ab_ap * seg0 * t33) + ap_ap * seg0 * t32 + T(2) * ab_ap * seg0 * t34) + T(10) * t29 * seg5 * seg0 * seg4 + T(2) * seg12 * t24 * delta_tau * t22 - T(20) * seg0 * seg10 * seg11 * t32 - T(20) * seg7 * seg0 * seg8 * t30 - T(5) * t46 * seg14) * seg0;
  }
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i7_prepare); operations per point.
/// Operations: 94 +, 290 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48910 +, 74645 ×, 5601 /, 2502 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i7_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T seg7 = pre[17];
  const T seg8 = pre[18];
  const T seg9 = pre[19];
  const T seg10 = pre[20];
  const T seg11 = pre[21];
  const T delta_tau = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T tau_lo = pre[25];
  const T seg14 = pre[26];
  const T seg15 = pre[27];
  const T length = pre[28];
  const T g_factor = pre[29];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = seg0 * (ab0 * exact_cross[2] - ab2 * exact_cross[0]);
    foot2 = -(ab0 * exact_cross[1] - exact_cross[0] * ab1) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / cross_cross;
    X = (t2 + ab_ap * r1) * t3 * seg1;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = -(ab_ap - a_minus_b) * seg1 / (t4 - ab_ap * r1);
  }
  const T J1 = seg2 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t5 = seg3 + T(4) * cross_cross;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(20) * seg8 * M_panels[3] * seg7 + T(15) * seg10 * M_panels[4] * seg11 + T(6) * M_panels[5] * tau_lo * seg13 + T(15) * seg5 * M_panels[2] * seg4 + seg9 * M_panels[6] + seg6 * M_panels[0] + T(6) * seg12 * delta_tau * M_panels[1];
    const T t8 = T(15) * seg5 * seg4 * M_panels[10] + M_panels[8] * seg6 + T(6) * tau_lo * seg13 * M_panels[13] + T(6) * seg12 * M_panels[9] * delta_tau + T(15) * M_panels[12] * seg10 * seg11 + T(20) * seg8 * M_panels[11] * seg7 + M_panels[14] * seg9;
    G_ap = t8;
    G_E = T(6) * M_panels[14] * tau_lo * seg13 + seg6 * M_panels[9] + T(20) * seg8 * M_panels[12] * seg7 + T(15) * seg5 * M_panels[11] * seg4 + T(15) * seg10 * M_panels[13] * seg11 + seg9 * M_panels[15] + T(6) * seg12 * delta_tau * M_panels[10] - ab_ap * t8 * seg0;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(6) * M_panels[1] * seg12 * delta_tau + seg9 * M_panels[6] + T(15) * seg10 * seg11 * M_panels[4] + T(15) * seg5 * M_panels[2] * seg4 + T(20) * seg8 * M_panels[3] * seg7 + T(6) * M_panels[5] * tau_lo * seg13 + seg6 * M_panels[0];
    G_ap = M_panels[8] * seg6 + M_panels[14] * seg9 + T(6) * seg12 * M_panels[9] * delta_tau + T(15) * M_panels[12] * seg10 * seg11 + T(15) * seg5 * seg4 * M_panels[10] + T(20) * seg8 * M_panels[11] * seg7 + T(6) * tau_lo * seg13 * M_panels[13];
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = t16 * t16;
    const T t18 = t17 * t14;
    G_E = (T(1) / T(7)) * seg0 * (T(60) * seg8 * M_panels[2] * seg7 + seg6 * t13 + T(60) * seg10 * M_panels[3] * seg11 + T(6) * seg12 * delta_tau * M_panels[0] + T(6) * M_panels[5] * seg9 + T(30) * M_panels[1] * seg5 * seg4 + T(30) * tau_lo * seg13 * M_panels[4] - t18 * seg14);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = T(1) / cross_cross;
    const T t24 = a_minus_b * t21 + ab_ap * t19;
    const T t25 = ab_ap * t20 * t19 + a_minus_b * t21 * t22 + T(2) * t23 * ab_ab * t24;
    const T t26 = t22 * t22;
    const T t27 = t20 * t20;
    const T t28 = T(4) * t25 * t23 * ab_ab + T(3) * a_minus_b * t21 * t26 + T(3) * ab_ap * t27 * t19;
    const T t29 = ab_ap * t28 * t23 + T(3) * t27 * t19 - T(3) * t21 * t26;
    const T t30 = t20 * t19 + t25 * ab_ap * t23 - t21 * t22;
    const T t31 = T(5) * t25 * t23 + T(2) * ab_ap * t29 * seg0 - ap_ap * t28 * t23;
    const T t32 = T(5) * t30 * seg0 + T(2) * ab_ap * t31 * seg0 - ap_ap * t29 * seg0;
    const T t33 = T(3) * t23 * t24 + T(2) * t30 * ab_ap * seg0 - t25 * ap_ap * t23;
    const T t34 = T(2) * ab_ap * t32 * seg0 + T(5) * t33 * seg0 - t31 * ap_ap * seg0;
    const T t35 = ab_ap * t23 * t24 + t19 - t21;
    const T t36 = T(3) * t35 * seg0 + T(2) * ab_ap * t33 * seg0 - t30 * ap_ap * seg0;
    const T t37 = T(2) * ab_ap * t34 * seg0 + T(5) * seg0 * t36 - ap_ap * t32 * seg0;
    F = (T(2) / T(5)) * seg12 * t29 * seg0 * delta_tau + t34 * seg0 * seg10 * seg11 + (T(2) / T(5)) * t37 * seg0 * tau_lo * seg13 + seg5 * t31 * seg0 * seg4 + (T(4) / T(3)) * seg8 * t32 * seg0 * seg7 + (T(1) / T(15)) * seg6 * t28 * t23 - (T(1) / T(15)) * seg9 * (t34 * ap_ap * seg0 - T(5) * (T(2) * ab_ap * seg0 * t36 + T(3) * seg0 * (J1 + T(2) * ab_ap * t35 * seg0 - ap_ap * t23 * t24) - t33 * ap_ap * seg0) * seg0 - T(2) * t37 * ab_ap * seg0) * seg0;
    const T t38 = t26 * t22;
    const T t39 = t27 * t20;
    const T t40 = T(2) * t28 * t23 * ab_ab + T(5) * a_minus_b * t21 * t38 + T(5) * ab_ap * t39 * t19;
    const T t41 = ab_ap * t23 * t40 + T(5) * t39 * t19 - T(5) * t21 * t38;
    const T t42 = T(3) * ap_ap * t23 * t40 - T(6) * t41 * ab_ap * seg0 - T(7) * t28 * t23;
    const T t43 = T(2) * ab_ap * t42 * seg0 + T(3) * t41 * ap_ap * seg0 - T(7) * t29 * seg0;
    const T t44 = t42 * ap_ap * seg0 + T(7) * t31 * seg0 - T(2) * ab_ap * t43 * seg0;
    const T t45 = t43 * ap_ap * seg0 + T(7) * t32 * seg0 + T(2) * ab_ap * seg0 * t44;
    G_ap = (T(1) / T(35)) * seg6 * t23 * t40 + (T(1) / T(7)) * seg0 * seg10 * t44 * seg11 + (T(2) / T(35)) * seg0 * tau_lo * seg13 * t45 + (T(6) / T(35)) * t41 * seg12 * seg0 * delta_tau + (T(1) / T(105)) * (T(7) * t34 * seg0 + T(2) * ab_ap * seg0 * t45 - ap_ap * seg0 * t44) * seg9 * seg0 - (T(4) / T(21)) * seg8 * t43 * seg0 * seg7 - (T(1) / T(7)) * seg5 * t42 * seg0 * seg4;
    const T t46 = t19 * t19;
    const T t47 = t46 * t19;
    const T t48 = t47 * t47;
    const T t49 = t48 * t19;
    const T t50 = t21 * t21;
    const T t51 = t50 * t21;
    const T t52 = t51 * t51;
    const T t53 = t52 * t21;
    G_E = (T(1) / T(35)) * seg0 * (T(5) * seg6 * t49 + T(10) * seg5 * t29 * seg0 * seg4 + T(20) * seg8 * t31 * seg0 * seg7 + T(2) * t37 * seg9 * seg0 + T(20) * t32 * seg0 * seg10 * seg11 + T(10) * t34 * seg0 * tau_lo * seg13 + T(2) * seg12 * delta_tau * t28 * t23 - T(5) * t53 * seg14);
  }
  f = F * seg15 * length;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i8_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i8_prepared_size = 30;

/// What scalis_segment_inverse_i8_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 30): computed once per
/// segment; in.p is not read.
/// Operations: 13 +, 33 ×, 1 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i8_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T g_factor = -T(8) * length * t2;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab1;
  pre[7] = ab2;
  pre[8] = ab0;
  pre[9] = ab_ab;
  const T t3 = T(1) / ab_ab;
  pre[10] = t3;
  pre[11] = -ab_ab * ab_ab;
  const T t4 = delta_tau * delta_tau;
  const T t5 = t4 * t4;
  const T t6 = t5 * delta_tau;
  pre[12] = t6;
  const T t7 = tau_lo * tau_lo;
  pre[13] = t7;
  const T t8 = t4 * delta_tau;
  pre[14] = t8;
  const T t9 = t7 * t7;
  pre[15] = t9;
  const T t10 = t8 * t8;
  pre[16] = t10;
  pre[17] = tau_lo;
  pre[18] = delta_tau;
  const T t11 = t7 * tau_lo;
  const T t12 = t11 * t11;
  pre[19] = t12;
  pre[20] = t5;
  pre[21] = t11;
  const T t13 = t10 * delta_tau;
  pre[22] = t13;
  pre[23] = t4;
  const T t14 = t9 * tau_lo;
  pre[24] = t14;
  const T t15 = t12 * tau_lo;
  pre[25] = t15;
  pre[26] = T(7) * delta_tau * t12 + t15 + T(21) * t4 * t14 + t13 + T(35) * t5 * t11 + T(35) * t8 * t9 + T(21) * t6 * t7 + T(7) * t10 * tau_lo;
  pre[27] = length;
  pre[28] = t2;
  pre[29] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i8_prepare); operations per point.
/// Operations: 71 +, 183 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 33603 +, 46451 ×, 6303 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i8_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T delta_tau = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T length = pre[27];
  const T seg15 = pre[28];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross + seg1;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross + seg1));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * seg13 + T(21) * M_panels[2] * seg11 * seg12 + M_panels[7] * seg10 + T(35) * M_panels[3] * seg4 * seg5 + T(21) * seg2 * M_panels[5] * seg3 + T(7) * seg6 * M_panels[6] * tau_lo + T(35) * seg9 * M_panels[4] * seg8 + T(7) * seg7 * delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(35) * seg4 * M_panels[3] * seg5 + T(35) * seg9 * M_panels[4] * seg8 + T(21) * seg2 * seg3 * M_panels[5] + T(7) * seg6 * tau_lo * M_panels[6] + T(21) * seg11 * M_panels[2] * seg12 + T(7) * M_panels[1] * seg7 * delta_tau + M_panels[0] * seg13 + M_panels[7] * seg10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, ap_bp);
    const T t6 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t6);
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / bp_bp;
    const T t11 = ab_ap * t6 + t10 * a_minus_b + J2 * ab_ab;
    const T t12 = t10 * t10;
    const T t13 = T(3) * t9 * t11 * ab_ab + T(2) * t12 * a_minus_b + T(2) * ab_ap * t7;
    const T t14 = t12 * t10;
    const T t15 = T(5) * t9 * t13 * ab_ab + T(8) * t14 * a_minus_b + T(8) * ab_ap * t8;
    const T t16 = T(8) * t8 + t9 * ab_ap * t15 - T(8) * t14;
    const T t17 = T(2) * ab_ap * seg0 * t16 + T(6) * t9 * t13 - t9 * t15 * ap_ap;
    const T t18 = T(2) * t7 + t9 * ab_ap * t13 - T(2) * t12;
    const T t19 = seg0 * ap_ap * t16 - T(2) * t17 * ab_ap * seg0 - T(6) * seg0 * t18;
    const T t20 = T(2) * ab_ap * seg0 * t18 + T(4) * t9 * t11 - t9 * ap_ap * t13;
    const T t21 = t10 - t6 - t9 * ab_ap * t11;
    const T t22 = T(2) * ab_ap * seg0 * t20 - T(4) * seg0 * t21 - seg0 * t18 * ap_ap;
    const T t23 = T(2) * t19 * ab_ap * seg0 + t17 * seg0 * ap_ap - T(6) * seg0 * t20;
    const T t24 = t19 * seg0 * ap_ap + T(6) * seg0 * t22 - T(2) * ab_ap * seg0 * t23;
    const T t25 = t9 * ap_ap * t11 + T(2) * ab_ap * seg0 * t21 - T(2) * J2;
    const T t26 = T(2) * ab_ap * seg0 * t22 - T(4) * seg0 * t25 - seg0 * ap_ap * t20;
    const T t27 = seg0 * ap_ap * t23 + T(6) * t26 * seg0 + T(2) * ab_ap * seg0 * t24;
    F = (T(7) / T(16)) * t17 * seg0 * seg11 * seg12 + (T(1) / T(48)) * t9 * t15 * seg13 + (T(7) / T(16)) * seg2 * seg0 * seg3 * t24 + (T(7) / T(48)) * t27 * seg6 * seg0 * tau_lo + (T(7) / T(48)) * seg0 * seg7 * t16 * delta_tau - (T(35) / T(48)) * seg9 * seg0 * t23 * seg8 - (T(35) / T(48)) * t19 * seg0 * seg4 * seg5 - (T(1) / T(48)) * (seg0 * ap_ap * t24 - T(2) * t27 * ab_ap * seg0 - T(6) * seg0 * (T(2) * t26 * ab_ap * seg0 + T(4) * seg0 * ((log_ratio + T(2) * ab_ap * J2) * seg0 + seg0 * t21 * ap_ap - T(2) * ab_ap * seg0 * t25) - seg0 * ap_ap * t22)) * seg0 * seg10;
  }
  f = length * F * seg15;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i8_prepare); operations per point.
/// Operations: 94 +, 261 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 48717 +, 63419 ×, 5083 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i8_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T delta_tau = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T seg14 = pre[26];
  const T g_factor = pre[29];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -seg0 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = -seg0 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(7) * M_panels[15] * seg6 * tau_lo + T(21) * seg12 * M_panels[11] * seg11 + M_panels[9] * seg13 + T(7) * delta_tau * M_panels[10] * seg7 + T(35) * M_panels[12] * seg4 * seg5 + M_panels[16] * seg10 + T(21) * seg3 * M_panels[14] * seg2 + T(35) * seg8 * M_panels[13] * seg9;
    G_ap = t4;
    G_E = T(21) * M_panels[12] * seg12 * seg11 + T(35) * M_panels[13] * seg4 * seg5 + T(21) * M_panels[15] * seg3 * seg2 + seg13 * M_panels[10] + T(35) * seg8 * seg9 * M_panels[14] + seg10 * M_panels[17] + T(7) * delta_tau * M_panels[11] * seg7 + T(7) * seg6 * M_panels[16] * tau_lo - seg0 * t4 * ab_ap;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = seg13 * M_panels[9] + seg10 * M_panels[16] + T(35) * seg4 * M_panels[12] * seg5 + T(7) * seg6 * tau_lo * M_panels[15] + T(35) * M_panels[13] * seg8 * seg9 + T(21) * seg3 * M_panels[14] * seg2 + T(21) * seg12 * M_panels[11] * seg11 + T(7) * M_panels[10] * delta_tau * seg7;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    G_E = (T(1) / T(8)) * seg0 * (T(7) * seg10 * M_panels[6] + t7 * seg13 + T(42) * seg12 * M_panels[1] * seg11 + T(105) * M_panels[2] * seg4 * seg5 + T(42) * seg6 * tau_lo * M_panels[5] + T(7) * delta_tau * seg7 * M_panels[0] + T(140) * seg8 * seg9 * M_panels[3] + T(105) * seg3 * M_panels[4] * seg2 - seg14 * t10);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * t16;
    const T t18 = a_minus_b * t16 + t14 * ab_ap + ab_ab * J2;
    const T t19 = T(2) * t15 * ab_ap + T(2) * a_minus_b * t17 + T(3) * ab_ab * t13 * t18;
    const T t20 = t13 * ab_ap * t19 + T(2) * t15 - T(2) * t17;
    const T t21 = t17 * t16;
    const T t22 = t15 * t14;
    const T t23 = T(8) * a_minus_b * t21 + T(8) * t22 * ab_ap + T(5) * ab_ab * t13 * t19;
    const T t24 = t23 * t13 * ab_ap + T(8) * t22 - T(8) * t21;
    const T t25 = ap_ap * t23 * t13 - T(2) * seg0 * t24 * ab_ap - T(6) * t13 * t19;
    const T t26 = T(6) * seg0 * t20 - T(2) * seg0 * t25 * ab_ap - ap_ap * seg0 * t24;
    const T t27 = T(2) * seg0 * t20 * ab_ap + T(4) * t13 * t18 - ap_ap * t13 * t19;
    const T t28 = T(2) * seg0 * t26 * ab_ap + T(6) * seg0 * t27 + ap_ap * seg0 * t25;
    const T t29 = t15 * t15;
    const T t30 = t17 * t17;
    const T t31 = T(48) * a_minus_b * t30 + T(7) * ab_ab * t23 * t13 + T(48) * t29 * ab_ap;
    const T t32 = T(48) * t29 + t31 * t13 * ab_ap - T(48) * t30;
    const T t33 = T(8) * t23 * t13 + T(2) * seg0 * ab_ap * t32 - ap_ap * t31 * t13;
    const T t34 = T(2) * seg0 * t33 * ab_ap + T(8) * seg0 * t24 - ap_ap * seg0 * t32;
    const T t35 = T(2) * seg0 * t34 * ab_ap - T(8) * seg0 * t25 - ap_ap * seg0 * t33;
    const T t36 = T(8) * seg0 * t26 + T(2) * seg0 * t35 * ab_ap - ap_ap * seg0 * t34;
    const T t37 = T(8) * seg0 * t28 + T(2) * seg0 * t36 * ab_ap - ap_ap * seg0 * t35;
    const T t38 = t13 * ab_ap * t18 + t14 - t16;
    const T t39 = ap_ap * seg0 * t20 - T(2) * seg0 * t27 * ab_ap - T(4) * seg0 * t38;
    const T t40 = T(2) * seg0 * t28 * ab_ap - ap_ap * seg0 * t26 - T(6) * seg0 * t39;
    G_ap = (T(7) / T(384)) * seg0 * seg6 * tau_lo * t37 + (T(35) / T(384)) * seg0 * t35 * seg8 * seg9 + (T(7) / T(384)) * seg0 * delta_tau * seg7 * t32 + (T(35) / T(384)) * seg0 * t34 * seg4 * seg5 + (T(7) / T(128)) * seg0 * seg3 * t36 * seg2 + (T(1) / T(384)) * seg13 * t31 * t13 + (T(7) / T(128)) * seg0 * seg12 * t33 * seg11 - (T(1) / T(384)) * seg0 * (ap_ap * seg0 * t36 - T(2) * seg0 * t37 * ab_ap - T(8) * seg0 * t40) * seg10;
    G_E = (T(1) / T(384)) * seg0 * (T(48) * t29 * seg13 + T(7) * seg0 * (T(6) * seg0 * (T(4) * seg0 * (T(2) * seg0 * ab_ap * t38 + T(2) * J2 - ap_ap * t13 * t18) - T(2) * seg0 * ab_ap * t39 - ap_ap * seg0 * t27) + T(2) * seg0 * t40 * ab_ap - ap_ap * seg0 * t28) * seg10 + T(42) * seg0 * seg12 * t24 * seg11 + T(7) * delta_tau * t23 * t13 * seg7 + T(105) * seg0 * seg3 * t28 * seg2 + T(42) * seg0 * seg6 * tau_lo * t40 + T(140) * seg0 * seg8 * t26 * seg9 - T(105) * seg0 * t25 * seg4 * seg5 - T(48) * seg14 * t30);
  }
  grad[0] = (G_ap * foot0 - G_E * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i8_prepare); operations per point.
/// Operations: 108 +, 316 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 48724 +, 63441 ×, 5083 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i8_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab1 = pre[6];
  const T ab2 = pre[7];
  const T ab0 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T delta_tau = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T seg14 = pre[26];
  const T length = pre[27];
  const T seg15 = pre[28];
  const T g_factor = pre[29];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * seg0 * ab0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -seg0 * (ab1 * exact_cross[2] - exact_cross[1] * ab2);
    foot1 = seg0 * (exact_cross[2] * ab0 - exact_cross[0] * ab2);
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * seg0;
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = T(4) * cross_cross + seg1;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross + seg1));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(35) * seg4 * seg5 * M_panels[3] + T(7) * M_panels[1] * seg7 * delta_tau + M_panels[0] * seg13 + T(35) * M_panels[4] * seg8 * seg9 + M_panels[7] * seg10 + T(21) * seg3 * M_panels[5] * seg2 + T(21) * seg11 * M_panels[2] * seg12 + T(7) * seg6 * tau_lo * M_panels[6];
    const T t4 = T(21) * seg3 * M_panels[14] * seg2 + seg13 * M_panels[9] + T(35) * seg4 * seg5 * M_panels[12] + T(7) * M_panels[10] * seg7 * delta_tau + T(35) * M_panels[13] * seg8 * seg9 + T(7) * seg6 * tau_lo * M_panels[15] + T(21) * M_panels[11] * seg11 * seg12 + M_panels[16] * seg10;
    G_ap = t4;
    G_E = T(35) * M_panels[13] * seg4 * seg5 + T(21) * seg11 * M_panels[12] * seg12 + T(7) * seg7 * M_panels[11] * delta_tau + M_panels[10] * seg13 + seg10 * M_panels[17] + T(21) * seg3 * M_panels[15] * seg2 + T(35) * M_panels[14] * seg8 * seg9 + T(7) * seg6 * M_panels[16] * tau_lo - t4 * ab_ap * seg0;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(35) * seg4 * M_panels[3] * seg5 + T(7) * seg6 * M_panels[6] * tau_lo + T(35) * M_panels[4] * seg8 * seg9 + T(21) * M_panels[2] * seg11 * seg12 + T(7) * M_panels[1] * seg7 * delta_tau + seg13 * M_panels[0] + T(21) * seg3 * M_panels[5] * seg2 + seg10 * M_panels[7];
    G_ap = T(7) * seg7 * delta_tau * M_panels[10] + T(21) * M_panels[11] * seg11 * seg12 + T(21) * M_panels[14] * seg3 * seg2 + T(35) * seg8 * M_panels[13] * seg9 + T(7) * seg6 * M_panels[15] * tau_lo + T(35) * seg4 * M_panels[12] * seg5 + seg10 * M_panels[16] + seg13 * M_panels[9];
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    G_E = (T(1) / T(8)) * (seg13 * t7 + T(105) * M_panels[4] * seg3 * seg2 + T(7) * seg10 * M_panels[6] + T(105) * M_panels[2] * seg4 * seg5 + T(140) * M_panels[3] * seg8 * seg9 + T(7) * seg7 * delta_tau * M_panels[0] + T(42) * seg6 * M_panels[5] * tau_lo + T(42) * M_panels[1] * seg11 * seg12 - t10 * seg14) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t13);
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = ab_ap * t13 + t15 * a_minus_b + J2 * ab_ab;
    const T t17 = t15 * t15;
    const T t18 = t13 * t13;
    const T t19 = T(3) * t14 * t16 * ab_ab + T(2) * t17 * a_minus_b + T(2) * ab_ap * t18;
    const T t20 = T(2) * t17 - ab_ap * t14 * t19 - T(2) * t18;
    const T t21 = T(4) * t14 * t16 - T(2) * ab_ap * seg0 * t20 - t14 * ap_ap * t19;
    const T t22 = t13 + ab_ap * t14 * t16 - t15;
    const T t23 = T(2) * ab_ap * seg0 * t21 + T(4) * seg0 * t22 + seg0 * ap_ap * t20;
    const T t24 = t17 * t15;
    const T t25 = t18 * t13;
    const T t26 = T(8) * t24 * a_minus_b + T(8) * ab_ap * t25 + T(5) * t14 * t19 * ab_ab;
    const T t27 = T(8) * t24 - ab_ap * t14 * t26 - T(8) * t25;
    const T t28 = T(2) * ab_ap * seg0 * t27 + t14 * ap_ap * t26 - T(6) * t14 * t19;
    const T t29 = T(2) * ab_ap * t28 * seg0 + T(6) * seg0 * t20 - seg0 * ap_ap * t27;
    const T t30 = T(2) * ab_ap * t29 * seg0 - T(6) * seg0 * t21 - t28 * seg0 * ap_ap;
    const T t31 = T(6) * seg0 * t23 + t29 * seg0 * ap_ap - T(2) * ab_ap * seg0 * t30;
    const T t32 = t14 * ap_ap * t16 - T(2) * ab_ap * seg0 * t22 - T(2) * J2;
    const T t33 = seg0 * t21 * ap_ap + T(4) * seg0 * t32 - T(2) * ab_ap * seg0 * t23;
    const T t34 = T(2) * t31 * ab_ap * seg0 + seg0 * ap_ap * t30 - T(6) * seg0 * t33;
    F = (T(7) / T(48)) * seg6 * seg0 * tau_lo * t34 + (T(7) / T(16)) * t31 * seg3 * seg0 * seg2 + (T(1) / T(48)) * t14 * seg13 * t26 + (T(1) / T(48)) * seg0 * seg10 * (T(2) * ab_ap * seg0 * t34 - T(6) * seg0 * (T(4) * seg0 * (seg0 * ap_ap * t22 + T(2) * ab_ap * seg0 * t32 - seg0 * (log_ratio + T(2) * ab_ap * J2)) + seg0 * t23 * ap_ap + T(2) * ab_ap * seg0 * t33) - t31 * seg0 * ap_ap) - (T(7) / T(16)) * t28 * seg0 * seg11 * seg12 - (T(35) / T(48)) * t29 * seg0 * seg4 * seg5 - (T(35) / T(48)) * seg0 * seg8 * t30 * seg9 - (T(7) / T(48)) * seg0 * seg7 * t27 * delta_tau;
    const T t35 = t17 * t17;
    const T t36 = t18 * t18;
    const T t37 = T(48) * t35 * a_minus_b + T(48) * ab_ap * t36 + T(7) * t14 * ab_ab * t26;
    const T t38 = T(48) * t35 - T(48) * t36 - ab_ap * t14 * t37;
    const T t39 = T(2) * t38 * ab_ap * seg0 + t14 * ap_ap * t37 - T(8) * t14 * t26;
    const T t40 = T(8) * seg0 * t27 + T(2) * ab_ap * seg0 * t39 - t38 * seg0 * ap_ap;
    const T t41 = T(8) * t28 * seg0 + T(2) * ab_ap * seg0 * t40 - seg0 * ap_ap * t39;
    const T t42 = T(8) * t29 * seg0 + T(2) * ab_ap * seg0 * t41 - seg0 * ap_ap * t40;
    const T t43 = T(2) * ab_ap * seg0 * t42 + T(8) * seg0 * t30 - seg0 * ap_ap * t41;
    G_ap = (T(1) / T(384)) * t14 * seg13 * t37 + (T(1) / T(384)) * seg0 * seg10 * (T(8) * t31 * seg0 + seg0 * ap_ap * t42 - T(2) * ab_ap * seg0 * t43) - (T(35) / T(384)) * seg0 * t41 * seg8 * seg9 - (T(7) / T(384)) * seg6 * seg0 * t43 * tau_lo - (T(35) / T(384)) * seg0 * seg4 * t40 * seg5 - (T(7) / T(384)) * t38 * seg0 * seg7 * delta_tau - (T(7) / T(128)) * seg0 * t39 * seg11 * seg12 - (T(7) / T(128)) * seg3 * seg0 * seg2 * t42;
    G_E = -(T(1) / T(384)) * seg0 * (T(105) * seg3 * seg0 * t30 * seg2 + T(48) * t35 * seg14 + T(140) * t29 * seg0 * seg8 * seg9 + T(105) * t28 * seg0 * seg4 * seg5 + T(42) * seg0 * t27 * seg11 * seg12 - T(7) * seg0 * seg10 * t34 - T(48) * seg13 * t36 - T(42) * t31 * seg6 * seg0 * tau_lo - T(7) * t14 * seg7 * delta_tau * t26);
  }
  f = length * F * seg15;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

/// How many values scalis_segment_inverse_i9_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i9_prepared_size = 34;

/// What scalis_segment_inverse_i9_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 34): computed once per
/// segment; in.p is not read.
/// Operations: 14 +, 38 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i9_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * in.sigma;
  const T g_factor = -T(9) * length * t3;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab2;
  pre[7] = ab0;
  pre[8] = ab1;
  pre[9] = ab_ab;
  const T t4 = T(1) / ab_ab;
  pre[10] = t4;
  pre[11] = length;
  const T t5 = T(1) / length;
  pre[12] = t5;
  pre[13] = -ab_ab * ab_ab;
  const T t6 = tau_lo * tau_lo;
  const T t7 = t6 * tau_lo;
  const T t8 = t7 * t7;
  pre[14] = t8;
  const T t9 = delta_tau * delta_tau;
  pre[15] = t9;
  const T t10 = t9 * t9;
  const T t11 = t10 * t10;
  pre[16] = t11;
  pre[17] = tau_lo;
  const T t12 = t9 * delta_tau;
  const T t13 = t12 * t12;
  const T t14 = t13 * delta_tau;
  pre[18] = t14;
  const T t15 = t6 * t6;
  const T t16 = t15 * tau_lo;
  pre[19] = t16;
  pre[20] = t12;
  const T t17 = t8 * tau_lo;
  pre[21] = t17;
  pre[22] = delta_tau;
  const T t18 = t15 * t15;
  pre[23] = t18;
  pre[24] = t15;
  pre[25] = t10;
  pre[26] = t6;
  pre[27] = t13;
  pre[28] = t7;
  const T t19 = t10 * delta_tau;
  pre[29] = t19;
  pre[30] = t11 + t18 + T(70) * t15 * t10 + T(8) * tau_lo * t14 + T(28) * t8 * t9 + T(28) * t6 * t13 + T(56) * t7 * t19 + T(56) * t16 * t12 + T(8) * t17 * delta_tau;
  pre[31] = length;
  pre[32] = t3;
  pre[33] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i9_prepare); operations per point.
/// Operations: 81 +, 236 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 32233 +, 55547 ×, 5599 /, 2502 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i9_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T delta_tau = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T seg14 = pre[26];
  const T seg15 = pre[27];
  const T seg16 = pre[28];
  const T seg17 = pre[29];
  const T length = pre[31];
  const T seg19 = pre[32];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = r1 * ab_ap;
    const T t3 = T(1) / cross_cross;
    X = (t2 + a_minus_b * r0) * seg1 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * ab_ap;
    X = -seg1 * (a_minus_b - ab_ap) / (t4 - a_minus_b * r0);
  }
  const T J1 = asinh(X) * seg2;
  T F;
  const T t5 = seg3 + T(4) * cross_cross;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg3 + T(100) * cross_cross));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(28) * seg15 * seg14 * M_panels[6] + T(8) * seg7 * M_panels[7] * tau_lo + T(8) * delta_tau * M_panels[1] * seg10 + seg11 * M_panels[0] + T(56) * seg17 * seg16 * M_panels[5] + T(70) * seg12 * M_panels[4] * seg13 + T(28) * seg5 * M_panels[2] * seg4 + T(56) * M_panels[3] * seg9 * seg8 + M_panels[8] * seg6;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(28) * seg15 * seg14 * M_panels[6] + T(8) * seg7 * M_panels[7] * tau_lo + T(8) * delta_tau * M_panels[1] * seg10 + T(56) * M_panels[3] * seg9 * seg8 + T(56) * seg17 * seg16 * M_panels[5] + seg11 * M_panels[0] + T(70) * seg12 * M_panels[4] * seg13 + T(28) * seg5 * M_panels[2] * seg4 + M_panels[8] * seg6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = T(1) / cross_cross;
    const T t15 = ab_ap * t8 + t11 * a_minus_b;
    const T t16 = t11 * a_minus_b * t12 + T(2) * t15 * ab_ab * t14 + t9 * ab_ap * t8;
    const T t17 = T(3) * t10 * ab_ap * t8 + T(3) * t11 * a_minus_b * t13 + T(4) * ab_ab * t14 * t16;
    const T t18 = t13 * t12;
    const T t19 = t10 * t9;
    const T t20 = T(2) * t17 * ab_ab * t14 + T(5) * t11 * a_minus_b * t18 + T(5) * t19 * ab_ap * t8;
    const T t21 = t9 * t8 + t14 * ab_ap * t16 - t11 * t12;
    const T t22 = T(3) * t10 * t8 + t17 * t14 * ab_ap - T(3) * t11 * t13;
    const T t23 = T(5) * t14 * t16 + T(2) * t22 * seg0 * ab_ap - t17 * ap_ap * t14;
    const T t24 = T(5) * seg0 * t21 + T(2) * seg0 * t23 * ab_ap - t22 * ap_ap * seg0;
    const T t25 = T(3) * t15 * t14 + T(2) * seg0 * t21 * ab_ap - ap_ap * t14 * t16;
    const T t26 = T(2) * t24 * seg0 * ab_ap + T(5) * t25 * seg0 - ap_ap * seg0 * t23;
    const T t27 = T(5) * t11 * t18 - T(5) * t19 * t8 - t20 * t14 * ab_ap;
    const T t28 = T(7) * t17 * t14 - T(6) * seg0 * t27 * ab_ap - T(3) * ap_ap * t20 * t14;
    const T t29 = T(7) * t22 * seg0 + T(3) * ap_ap * seg0 * t27 + T(2) * seg0 * ab_ap * t28;
    const T t30 = T(2) * t29 * seg0 * ab_ap + T(7) * seg0 * t23 - ap_ap * seg0 * t28;
    const T t31 = t29 * ap_ap * seg0 - T(7) * t24 * seg0 - T(2) * t30 * seg0 * ab_ap;
    const T t32 = T(7) * t26 * seg0 - t30 * ap_ap * seg0 - T(2) * seg0 * t31 * ab_ap;
    const T t33 = t8 + t15 * t14 * ab_ap - t11;
    const T t34 = T(2) * t25 * seg0 * ab_ap + T(3) * seg0 * t33 - ap_ap * seg0 * t21;
    const T t35 = t24 * ap_ap * seg0 - T(5) * seg0 * t34 - T(2) * t26 * seg0 * ab_ap;
    const T t36 = T(2) * seg0 * t32 * ab_ap + ap_ap * seg0 * t31 - T(7) * t35 * seg0;
    F = (T(1) / T(35)) * seg11 * t20 * t14 + (T(4) / T(15)) * seg15 * seg0 * seg14 * t32 + (T(8) / T(15)) * t29 * seg0 * seg9 * seg8 + (T(2) / T(3)) * t30 * seg12 * seg0 * seg13 + (T(4) / T(15)) * seg0 * seg5 * seg4 * t28 + (T(8) / T(105)) * t36 * seg7 * seg0 * tau_lo - (T(1) / T(105)) * (ap_ap * seg0 * t32 + T(7) * seg0 * (T(2) * t35 * seg0 * ab_ap + t26 * ap_ap * seg0 - T(5) * seg0 * (T(3) * seg0 * (T(2) * seg0 * t33 * ab_ap + J1 - t15 * ap_ap * t14) + T(2) * seg0 * t34 * ab_ap - ap_ap * t25 * seg0)) - T(2) * t36 * seg0 * ab_ap) * seg0 * seg6 - (T(8) / T(35)) * delta_tau * seg0 * t27 * seg10 - (T(8) / T(15)) * seg17 * seg0 * seg16 * t31;
  }
  f = F * seg19 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i9_prepare); operations per point.
/// Operations: 105 +, 328 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48137 +, 73246 ×, 4613 /, 2061 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i9_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T delta_tau = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T seg14 = pre[26];
  const T seg15 = pre[27];
  const T seg16 = pre[28];
  const T seg17 = pre[29];
  const T seg18 = pre[30];
  const T g_factor = pre[33];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab_ap * seg0 * ab0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -seg0 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t1 = T(4) * cross_cross + seg3;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross + seg3));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(8) * seg7 * tau_lo * M_panels[17] + M_panels[18] * seg6 + T(56) * seg17 * M_panels[15] * seg16 + T(28) * seg4 * M_panels[12] * seg5 + T(56) * seg9 * M_panels[13] * seg8 + seg11 * M_panels[10] + T(8) * delta_tau * seg10 * M_panels[11] + T(28) * seg15 * seg14 * M_panels[16] + T(70) * M_panels[14] * seg13 * seg12;
    G_ap = t4;
    G_E = T(28) * seg15 * seg14 * M_panels[17] + M_panels[19] * seg6 + T(70) * M_panels[15] * seg13 * seg12 + T(56) * seg17 * seg16 * M_panels[16] + T(8) * seg7 * M_panels[18] * tau_lo + T(8) * M_panels[12] * delta_tau * seg10 + seg11 * M_panels[11] + T(56) * M_panels[14] * seg9 * seg8 + T(28) * seg4 * M_panels[13] * seg5 - ab_ap * seg0 * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = T(56) * seg17 * seg16 * M_panels[15] + T(28) * seg15 * seg14 * M_panels[16] + M_panels[18] * seg6 + T(8) * M_panels[17] * seg7 * tau_lo + T(70) * M_panels[14] * seg13 * seg12 + T(8) * M_panels[11] * delta_tau * seg10 + M_panels[10] * seg11 + T(28) * seg4 * M_panels[12] * seg5 + T(56) * seg9 * seg8 * M_panels[13];
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    G_E = (T(1) / T(9)) * seg0 * (t9 * seg11 + T(168) * M_panels[2] * seg9 * seg8 + T(8) * M_panels[7] * seg6 + T(280) * seg17 * M_panels[4] * seg16 + T(56) * M_panels[1] * seg4 * seg5 + T(168) * seg15 * M_panels[5] * seg14 + T(56) * seg7 * tau_lo * M_panels[6] + T(280) * seg13 * M_panels[3] * seg12 + T(8) * delta_tau * seg10 * M_panels[0] - t14 * seg18);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t17 * t16;
    const T t24 = t21 * t20;
    const T t25 = ab_ap * t19 + t15 * a_minus_b;
    const T t26 = T(1) / cross_cross;
    const T t27 = t16 * t15 * a_minus_b + ab_ap * t19 * t20 + T(2) * t25 * ab_ab * t26;
    const T t28 = T(3) * ab_ap * t19 * t21 + T(4) * t27 * ab_ab * t26 + T(3) * t17 * t15 * a_minus_b;
    const T t29 = T(5) * t23 * t15 * a_minus_b + T(5) * ab_ap * t19 * t24 + T(2) * t28 * ab_ab * t26;
    const T t30 = T(8) * t29 * ab_ab * t26 + T(35) * t18 * t15 * a_minus_b + T(35) * ab_ap * t19 * t22;
    const T t31 = T(35) * t18 * t15 - T(35) * t19 * t22 - ab_ap * t30 * t26;
    const T t32 = ap_ap * t30 * t26 + T(2) * ab_ap * seg0 * t31 - T(9) * t29 * t26;
    const T t33 = T(5) * t23 * t15 - T(5) * t19 * t24 - ab_ap * t29 * t26;
    const T t34 = seg0 * ap_ap * t31 - T(2) * ab_ap * seg0 * t32 - T(9) * seg0 * t33;
    const T t35 = T(3) * ap_ap * t29 * t26 + T(6) * ab_ap * seg0 * t33 - T(7) * t28 * t26;
    const T t36 = T(2) * ab_ap * seg0 * t34 + seg0 * ap_ap * t32 - T(3) * seg0 * t35;
    const T t37 = ab_ap * t28 * t26 + T(3) * t19 * t21 - T(3) * t17 * t15;
    const T t38 = T(2) * ab_ap * seg0 * t37 + T(5) * t27 * t26 - t28 * ap_ap * t26;
    const T t39 = T(7) * seg0 * t37 + T(3) * seg0 * ap_ap * t33 - T(2) * ab_ap * seg0 * t35;
    const T t40 = T(7) * seg0 * t38 + T(2) * ab_ap * seg0 * t39 + seg0 * ap_ap * t35;
    const T t41 = seg0 * ap_ap * t34 - T(3) * seg0 * t39 - T(2) * ab_ap * seg0 * t36;
    const T t42 = T(3) * seg0 * t40 - T(2) * ab_ap * seg0 * t41 - seg0 * t36 * ap_ap;
    const T t43 = t19 * t20 + ab_ap * t27 * t26 - t16 * t15;
    const T t44 = seg0 * ap_ap * t37 - T(2) * ab_ap * seg0 * t38 - T(5) * seg0 * t43;
    const T t45 = seg0 * ap_ap * t39 + T(7) * seg0 * t44 - T(2) * ab_ap * seg0 * t40;
    const T t46 = T(2) * ab_ap * seg0 * t42 + seg0 * t41 * ap_ap - T(3) * seg0 * t45;
    const T t47 = ap_ap * t27 * t26 - T(3) * t25 * t26 - T(2) * ab_ap * seg0 * t43;
    const T t48 = T(2) * ab_ap * seg0 * t44 + seg0 * t38 * ap_ap + T(5) * seg0 * t47;
    const T t49 = T(7) * seg0 * t48 + T(2) * ab_ap * seg0 * t45 + seg0 * ap_ap * t40;
    G_ap = (T(8) / T(45)) * seg0 * seg9 * t34 * seg8 + (T(2) / T(9)) * seg0 * t36 * seg13 * seg12 + (T(4) / T(45)) * seg0 * seg15 * seg14 * t42 + (T(8) / T(315)) * seg0 * seg7 * t46 * tau_lo + (T(1) / T(315)) * seg11 * t30 * t26 - (T(8) / T(45)) * seg0 * seg17 * t41 * seg16 - (T(1) / T(315)) * seg0 * (T(3) * seg0 * t49 + seg0 * ap_ap * t42 - T(2) * ab_ap * seg0 * t46) * seg6 - (T(4) / T(45)) * seg0 * seg4 * t32 * seg5 - (T(8) / T(315)) * seg0 * delta_tau * seg10 * t31;
    const T t50 = t19 * t19;
    const T t51 = t50 * t50;
    const T t52 = t51 * t51;
    const T t53 = t52 * t19;
    const T t54 = t15 * t15;
    const T t55 = t54 * t54;
    const T t56 = t55 * t55;
    const T t57 = t56 * t15;
    G_E = (T(1) / T(945)) * seg0 * (T(105) * t53 * seg11 + T(280) * seg0 * seg13 * t39 * seg12 + T(24) * t29 * delta_tau * seg10 * t26 + T(280) * seg0 * seg17 * t40 * seg16 - T(168) * seg0 * seg4 * t33 * seg5 - T(8) * seg0 * seg6 * (T(2) * ab_ap * seg0 * t49 + T(7) * seg0 * (T(2) * ab_ap * seg0 * t48 - T(5) * seg0 * (T(3) * seg0 * (ab_ap * t25 * t26 + t19 - t15) - seg0 * t43 * ap_ap - T(2) * ab_ap * seg0 * t47) - seg0 * t44 * ap_ap) - seg0 * ap_ap * t45) - T(168) * seg0 * t35 * seg9 * seg8 - T(168) * seg0 * seg15 * seg14 * t45 - T(105) * t57 * seg18 - T(56) * seg0 * seg7 * tau_lo * t49);
  }
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i9_prepare); operations per point.
/// Operations: 122 +, 396 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48146 +, 73277 ×, 4614 /, 2061 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i9_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T seg5 = pre[15];
  const T seg6 = pre[16];
  const T tau_lo = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T delta_tau = pre[22];
  const T seg11 = pre[23];
  const T seg12 = pre[24];
  const T seg13 = pre[25];
  const T seg14 = pre[26];
  const T seg15 = pre[27];
  const T seg16 = pre[28];
  const T seg17 = pre[29];
  const T seg18 = pre[30];
  const T length = pre[31];
  const T seg19 = pre[32];
  const T g_factor = pre[33];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -seg0 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * seg0;
    foot2 = -(ab0 * exact_cross[1] - exact_cross[0] * ab1) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = r1 * ab_ap;
    X = seg1 * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * ab_ap;
    X = seg1 * (ab_ap - a_minus_b) / (t4 - a_minus_b * r0);
  }
  const T J1 = seg2 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * cross_cross + seg3;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross + seg3));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(8) * tau_lo * M_panels[7] * seg7 + T(56) * seg17 * M_panels[5] * seg16 + T(56) * seg8 * seg9 * M_panels[3] + T(28) * seg4 * seg5 * M_panels[2] + M_panels[8] * seg6 + M_panels[0] * seg11 + T(8) * M_panels[1] * delta_tau * seg10 + T(28) * seg14 * seg15 * M_panels[6] + T(70) * M_panels[4] * seg12 * seg13;
    const T t8 = T(8) * M_panels[11] * delta_tau * seg10 + seg6 * M_panels[18] + T(70) * M_panels[14] * seg12 * seg13 + T(28) * M_panels[16] * seg14 * seg15 + T(56) * M_panels[13] * seg8 * seg9 + T(28) * seg4 * seg5 * M_panels[12] + T(8) * tau_lo * M_panels[17] * seg7 + seg11 * M_panels[10] + T(56) * seg17 * seg16 * M_panels[15];
    G_ap = t8;
    G_E = T(8) * tau_lo * M_panels[18] * seg7 + T(28) * seg4 * M_panels[13] * seg5 + T(28) * seg14 * M_panels[17] * seg15 + T(56) * seg8 * M_panels[14] * seg9 + T(8) * delta_tau * M_panels[12] * seg10 + seg11 * M_panels[11] + seg6 * M_panels[19] + T(56) * M_panels[16] * seg17 * seg16 + T(70) * seg12 * M_panels[15] * seg13 - ab_ap * seg0 * t8;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = seg11 * M_panels[0] + T(28) * seg14 * M_panels[6] * seg15 + T(56) * seg17 * seg16 * M_panels[5] + T(56) * M_panels[3] * seg8 * seg9 + T(70) * seg12 * M_panels[4] * seg13 + seg6 * M_panels[8] + T(28) * seg4 * seg5 * M_panels[2] + T(8) * M_panels[1] * delta_tau * seg10 + T(8) * tau_lo * M_panels[7] * seg7;
    G_ap = T(8) * tau_lo * M_panels[17] * seg7 + T(56) * seg8 * M_panels[13] * seg9 + T(8) * delta_tau * M_panels[11] * seg10 + T(28) * seg14 * M_panels[16] * seg15 + seg11 * M_panels[10] + seg6 * M_panels[18] + T(28) * seg4 * M_panels[12] * seg5 + T(70) * seg12 * M_panels[14] * seg13 + T(56) * M_panels[15] * seg17 * seg16;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t14;
    G_E = (T(1) / T(9)) * (seg11 * t13 + T(8) * M_panels[7] * seg6 + T(8) * M_panels[0] * delta_tau * seg10 + T(168) * seg8 * seg9 * M_panels[2] + T(56) * seg4 * seg5 * M_panels[1] + T(168) * seg14 * seg15 * M_panels[5] + T(56) * tau_lo * M_panels[6] * seg7 + T(280) * seg17 * M_panels[4] * seg16 + T(280) * M_panels[3] * seg12 * seg13 - t18 * seg18) * seg0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = ab_ap * t20 + t23 * a_minus_b;
    const T t26 = t23 * t24 * a_minus_b + T(2) * t19 * ab_ab * t25 + ab_ap * t21 * t20;
    const T t27 = t24 * t24;
    const T t28 = T(3) * ab_ap * t22 * t20 + T(4) * t19 * t26 * ab_ab + T(3) * t23 * t27 * a_minus_b;
    const T t29 = t22 * t21;
    const T t30 = t27 * t24;
    const T t31 = T(2) * t19 * t28 * ab_ab + T(5) * ab_ap * t29 * t20 + T(5) * t23 * t30 * a_minus_b;
    const T t32 = t19 * ab_ap * t31 + T(5) * t29 * t20 - T(5) * t23 * t30;
    const T t33 = T(6) * ab_ap * t32 * seg0 + T(7) * t19 * t28 - T(3) * t19 * ap_ap * t31;
    const T t34 = t19 * ab_ap * t28 + T(3) * t22 * t20 - T(3) * t23 * t27;
    const T t35 = T(2) * ab_ap * t33 * seg0 + T(7) * t34 * seg0 - T(3) * t32 * ap_ap * seg0;
    const T t36 = T(5) * t19 * t26 + T(2) * t34 * ab_ap * seg0 - t19 * ap_ap * t28;
    const T t37 = T(2) * t35 * ab_ap * seg0 + T(7) * t36 * seg0 - ap_ap * t33 * seg0;
    const T t38 = t21 * t20 + t19 * ab_ap * t26 - t23 * t24;
    const T t39 = T(2) * ab_ap * t36 * seg0 + T(5) * t38 * seg0 - t34 * ap_ap * seg0;
    const T t40 = T(7) * seg0 * t39 + T(2) * ab_ap * t37 * seg0 - t35 * ap_ap * seg0;
    const T t41 = T(2) * ab_ap * t38 * seg0 + T(3) * t19 * t25 - t19 * ap_ap * t26;
    const T t42 = T(5) * t41 * seg0 + T(2) * ab_ap * seg0 * t39 - ap_ap * t36 * seg0;
    const T t43 = T(2) * ab_ap * t40 * seg0 + T(7) * t42 * seg0 - t37 * ap_ap * seg0;
    const T t44 = t20 + t19 * ab_ap * t25 - t23;
    const T t45 = T(3) * seg0 * t44 + T(2) * t41 * ab_ap * seg0 - ap_ap * t38 * seg0;
    const T t46 = T(5) * t45 * seg0 + T(2) * ab_ap * t42 * seg0 - ap_ap * seg0 * t39;
    const T t47 = ap_ap * t40 * seg0 - T(2) * ab_ap * t43 * seg0 - T(7) * seg0 * t46;
    F = (T(2) / T(3)) * t37 * seg12 * seg0 * seg13 + (T(4) / T(15)) * seg4 * seg5 * t33 * seg0 + (T(8) / T(15)) * seg17 * t40 * seg0 * seg16 + (T(1) / T(35)) * t19 * seg11 * t31 + (T(4) / T(15)) * seg14 * t43 * seg15 * seg0 + (T(8) / T(15)) * t35 * seg8 * seg9 * seg0 + (T(8) / T(35)) * t32 * seg0 * delta_tau * seg10 - (T(8) / T(105)) * tau_lo * t47 * seg0 * seg7 - (T(1) / T(105)) * seg6 * seg0 * (t43 * ap_ap * seg0 + T(7) * (T(5) * seg0 * (t41 * ap_ap * seg0 + T(3) * (t19 * ap_ap * t25 - J1 - T(2) * ab_ap * seg0 * t44) * seg0 - T(2) * ab_ap * t45 * seg0) + t42 * ap_ap * seg0 - T(2) * ab_ap * seg0 * t46) * seg0 + T(2) * ab_ap * t47 * seg0);
    const T t48 = t22 * t22;
    const T t49 = t27 * t27;
    const T t50 = T(8) * t19 * ab_ab * t31 + T(35) * t23 * t49 * a_minus_b + T(35) * ab_ap * t48 * t20;
    const T t51 = T(35) * t48 * t20 + t19 * ab_ap * t50 - T(35) * t23 * t49;
    const T t52 = T(9) * t19 * t31 + T(2) * ab_ap * seg0 * t51 - t19 * t50 * ap_ap;
    const T t53 = ap_ap * seg0 * t51 - T(9) * t32 * seg0 - T(2) * ab_ap * seg0 * t52;
    const T t54 = ap_ap * seg0 * t52 + T(2) * ab_ap * t53 * seg0 - T(3) * t33 * seg0;
    const T t55 = t53 * ap_ap * seg0 + T(3) * t35 * seg0 - T(2) * ab_ap * t54 * seg0;
    const T t56 = T(3) * t37 * seg0 + T(2) * ab_ap * t55 * seg0 + t54 * ap_ap * seg0;
    const T t57 = T(2) * ab_ap * t56 * seg0 + T(3) * t40 * seg0 - t55 * ap_ap * seg0;
    G_ap = (T(4) / T(45)) * seg14 * t56 * seg15 * seg0 + (T(1) / T(315)) * t19 * t50 * seg11 + (T(8) / T(45)) * seg17 * t55 * seg0 * seg16 + (T(4) / T(45)) * seg4 * seg5 * seg0 * t52 + (T(8) / T(315)) * tau_lo * t57 * seg0 * seg7 + (T(8) / T(315)) * seg0 * delta_tau * seg10 * t51 + (T(1) / T(315)) * (T(3) * t43 * seg0 + T(2) * ab_ap * t57 * seg0 - t56 * ap_ap * seg0) * seg6 * seg0 - (T(8) / T(45)) * seg8 * t53 * seg9 * seg0 - (T(2) / T(9)) * t54 * seg12 * seg0 * seg13;
    const T t58 = t23 * t23;
    const T t59 = t58 * t58;
    const T t60 = t59 * t59;
    const T t61 = t60 * t23;
    const T t62 = t20 * t20;
    const T t63 = t62 * t62;
    const T t64 = t63 * t63;
    const T t65 = t64 * t20;
    G_E = -(T(1) / T(945)) * (T(8) * t47 * seg6 * seg0 + T(105) * t61 * seg18 - T(105) * seg11 * t65 - T(56) * tau_lo * t43 * seg0 * seg7 - T(168) * seg4 * t32 * seg5 * seg0 - T(168) * seg14 * seg15 * t40 * seg0 - T(168) * seg8 * t33 * seg9 * seg0 - T(24) * t19 * delta_tau * seg10 * t31 - T(280) * t35 * seg12 * seg0 * seg13 - T(280) * seg17 * t37 * seg0 * seg16) * seg0;
  }
  f = length * F * seg19;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

/// How many values scalis_segment_inverse_i10_prepare writes.
inline constexpr std::size_t scalis_segment_inverse_i10_prepared_size = 34;

/// What scalis_segment_inverse_i10_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 34): computed once per
/// segment; in.p is not read.
/// Operations: 15 +, 42 ×, 1 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_inverse_i10_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = in.sigma * in.sigma;
  const T t1 = t0 * t0;
  const T t2 = t1 * in.sigma;
  const T t3 = t2 * t2;
  const T g_factor = -T(10) * t3 * length;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab2;
  pre[7] = ab0;
  pre[8] = ab1;
  pre[9] = ab_ab;
  const T t4 = T(1) / ab_ab;
  pre[10] = t4;
  pre[11] = -ab_ab * ab_ab;
  const T t5 = delta_tau * delta_tau;
  const T t6 = t5 * t5;
  pre[12] = t6;
  const T t7 = tau_lo * tau_lo;
  const T t8 = t7 * t7;
  const T t9 = t8 * tau_lo;
  pre[13] = t9;
  const T t10 = t6 * t6;
  pre[14] = t10;
  pre[15] = tau_lo;
  const T t11 = t5 * delta_tau;
  pre[16] = t11;
  const T t12 = t7 * tau_lo;
  const T t13 = t12 * t12;
  pre[17] = t13;
  const T t14 = t8 * t8;
  const T t15 = t14 * tau_lo;
  pre[18] = t15;
  const T t16 = t11 * t11;
  const T t17 = t16 * delta_tau;
  pre[19] = t17;
  pre[20] = t7;
  pre[21] = t5;
  const T t18 = t13 * tau_lo;
  pre[22] = t18;
  const T t19 = t6 * delta_tau;
  pre[23] = t19;
  pre[24] = t8;
  pre[25] = t16;
  pre[26] = t12;
  const T t20 = t10 * delta_tau;
  pre[27] = t20;
  pre[28] = delta_tau;
  pre[29] = t14;
  pre[30] = T(126) * t19 * t8 + T(126) * t6 * t9 + T(9) * delta_tau * t14 + t20 + T(84) * t11 * t13 + T(9) * t10 * tau_lo + t15 + T(84) * t16 * t12 + T(36) * t17 * t7 + T(36) * t5 * t18;
  pre[31] = t3;
  pre[32] = length;
  pre[33] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i10_prepare); operations per point.
/// Operations: 93 +, 260 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 31425 +, 43941 ×, 5081 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i10_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T seg11 = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T seg14 = pre[25];
  const T seg15 = pre[26];
  const T seg16 = pre[27];
  const T delta_tau = pre[28];
  const T seg17 = pre[29];
  const T seg19 = pre[31];
  const T length = pre[32];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(9) * seg4 * M_panels[8] * tau_lo + T(126) * seg2 * seg3 * M_panels[4] + M_panels[0] * seg7 + M_panels[9] * seg16 + T(84) * seg15 * M_panels[6] * seg14 + T(9) * delta_tau * M_panels[1] * seg17 + T(126) * seg13 * seg12 * M_panels[5] + T(84) * seg5 * M_panels[3] * seg6 + T(36) * M_panels[2] * seg10 * seg11 + T(36) * seg9 * M_panels[7] * seg8;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(9) * seg4 * M_panels[8] * tau_lo + T(84) * seg15 * M_panels[6] * seg14 + T(36) * seg9 * M_panels[7] * seg8 + T(126) * seg2 * seg3 * M_panels[4] + seg7 * M_panels[0] + T(36) * M_panels[2] * seg10 * seg11 + T(84) * seg5 * seg6 * M_panels[3] + M_panels[9] * seg16 + T(126) * M_panels[5] * seg13 * seg12 + T(9) * delta_tau * seg17 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t6);
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t6 * t6;
    const T t11 = t10 * t6;
    const T t12 = ab_ap * t6 + ab_ab * J2 + t7 * a_minus_b;
    const T t13 = T(1) / cross_cross;
    const T t14 = T(2) * t8 * a_minus_b + T(2) * ab_ap * t10 + T(3) * t12 * ab_ab * t13;
    const T t15 = T(8) * t9 * a_minus_b + T(8) * ab_ap * t11 + T(5) * t14 * ab_ab * t13;
    const T t16 = t8 * t8;
    const T t17 = t10 * t10;
    const T t18 = T(48) * t16 * a_minus_b + T(7) * t15 * ab_ab * t13 + T(48) * ab_ap * t17;
    const T t19 = t18 * ab_ap * t13 + T(48) * t17 - T(48) * t16;
    const T t20 = T(8) * t15 * t13 + T(2) * t19 * ab_ap * seg0 - t18 * ap_ap * t13;
    const T t21 = T(2) * t8 - T(2) * t10 - ab_ap * t14 * t13;
    const T t22 = t14 * ap_ap * t13 + T(2) * ab_ap * t21 * seg0 - T(4) * t12 * t13;
    const T t23 = T(8) * t9 - T(8) * t11 - ab_ap * t15 * t13;
    const T t24 = t15 * ap_ap * t13 + T(2) * ab_ap * t23 * seg0 - T(6) * t14 * t13;
    const T t25 = T(2) * ab_ap * seg0 * t24 + T(6) * t21 * seg0 - ap_ap * t23 * seg0;
    const T t26 = T(6) * t22 * seg0 + T(2) * ab_ap * t25 * seg0 - ap_ap * seg0 * t24;
    const T t27 = ab_ap * t12 * t13 + t6 - t7;
    const T t28 = ap_ap * t21 * seg0 + T(4) * seg0 * t27 - T(2) * ab_ap * t22 * seg0;
    const T t29 = T(2) * ab_ap * t26 * seg0 - ap_ap * t25 * seg0 - T(6) * t28 * seg0;
    const T t30 = T(2) * ab_ap * seg0 * t27 + T(2) * J2 - ap_ap * t12 * t13;
    const T t31 = T(4) * t30 * seg0 + T(2) * t28 * ab_ap * seg0 + t22 * ap_ap * seg0;
    const T t32 = T(6) * t31 * seg0 + ap_ap * t26 * seg0 - T(2) * ab_ap * t29 * seg0;
    const T t33 = T(8) * t23 * seg0 + t19 * ap_ap * seg0 - T(2) * t20 * ab_ap * seg0;
    const T t34 = t20 * ap_ap * seg0 + T(2) * ab_ap * seg0 * t33 + T(8) * seg0 * t24;
    const T t35 = T(2) * ab_ap * t34 * seg0 + T(8) * t25 * seg0 - ap_ap * seg0 * t33;
    const T t36 = T(2) * ab_ap * t35 * seg0 + T(8) * t26 * seg0 - ap_ap * t34 * seg0;
    const T t37 = T(2) * ab_ap * t36 * seg0 + T(8) * t29 * seg0 - ap_ap * t35 * seg0;
    const T t38 = T(2) * ab_ap * seg0 * t37 - ap_ap * t36 * seg0 - T(8) * t32 * seg0;
    F = (T(3) / T(32)) * t20 * seg10 * seg11 * seg0 + (T(1) / T(384)) * (T(8) * (ap_ap * t29 * seg0 + T(2) * ab_ap * t32 * seg0 + T(6) * seg0 * (T(4) * (T(2) * ab_ap * t30 * seg0 + seg0 * (log_ratio + T(2) * ab_ap * J2) - ap_ap * seg0 * t27) * seg0 + T(2) * ab_ap * t31 * seg0 - t28 * ap_ap * seg0)) * seg0 + ap_ap * seg0 * t37 - T(2) * ab_ap * t38 * seg0) * seg16 * seg0 + (T(3) / T(128)) * t19 * delta_tau * seg0 * seg17 + (T(1) / T(384)) * t18 * seg7 * t13 - (T(21) / T(64)) * seg13 * t35 * seg0 * seg12 - (T(7) / T(32)) * seg15 * t36 * seg14 * seg0 - (T(7) / T(32)) * seg5 * seg6 * seg0 * t33 - (T(3) / T(128)) * seg4 * tau_lo * t38 * seg0 - (T(21) / T(64)) * seg2 * t34 * seg3 * seg0 - (T(3) / T(32)) * seg9 * seg0 * seg8 * t37;
  }
  f = seg19 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i10_prepare); operations per point.
/// Operations: 120 +, 355 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 47821 +, 61885 ×, 4237 /, 91 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i10_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T seg11 = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T seg14 = pre[25];
  const T seg15 = pre[26];
  const T seg16 = pre[27];
  const T delta_tau = pre[28];
  const T seg17 = pre[29];
  const T seg18 = pre[30];
  const T g_factor = pre[33];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * seg0;
    foot2 = seg0 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t1 = T(4) * cross_cross + seg1;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross + seg1));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = T(9) * seg4 * M_panels[19] * tau_lo + T(126) * M_panels[15] * seg3 * seg2 + seg16 * M_panels[20] + T(84) * seg5 * M_panels[14] * seg6 + T(84) * seg15 * seg14 * M_panels[17] + T(36) * M_panels[18] * seg9 * seg8 + M_panels[11] * seg7 + T(126) * M_panels[16] * seg13 * seg12 + T(9) * M_panels[12] * delta_tau * seg17 + T(36) * seg11 * M_panels[13] * seg10;
    G_ap = t4;
    G_E = M_panels[21] * seg16 + M_panels[12] * seg7 + T(84) * M_panels[15] * seg5 * seg6 + T(9) * delta_tau * M_panels[13] * seg17 + T(9) * seg4 * tau_lo * M_panels[20] + T(36) * seg11 * seg10 * M_panels[14] + T(84) * M_panels[18] * seg15 * seg14 + T(126) * seg13 * M_panels[17] * seg12 + T(36) * seg9 * M_panels[19] * seg8 + T(126) * seg3 * M_panels[16] * seg2 - seg0 * t4 * ab_ap;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = T(36) * seg11 * M_panels[13] * seg10 + T(84) * seg5 * M_panels[14] * seg6 + T(9) * M_panels[12] * delta_tau * seg17 + M_panels[11] * seg7 + T(126) * M_panels[16] * seg13 * seg12 + seg16 * M_panels[20] + T(36) * seg9 * seg8 * M_panels[18] + T(126) * M_panels[15] * seg3 * seg2 + T(9) * seg4 * tau_lo * M_panels[19] + T(84) * seg15 * M_panels[17] * seg14;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(10)) * seg0 * (T(630) * seg13 * M_panels[4] * seg12 + T(504) * seg15 * seg14 * M_panels[5] + T(252) * seg9 * M_panels[6] * seg8 + T(72) * seg11 * M_panels[1] * seg10 + T(504) * seg3 * M_panels[3] * seg2 + T(9) * seg16 * M_panels[8] + t8 * seg7 + T(9) * M_panels[0] * delta_tau * seg17 + T(252) * seg5 * seg6 * M_panels[2] + T(72) * seg4 * tau_lo * M_panels[7] - seg18 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / bp_bp;
    const T t20 = a_minus_b * t19 + ab_ab * J2 + t16 * ab_ap;
    const T t21 = t19 * t19;
    const T t22 = T(3) * ab_ab * t20 * t15 + T(2) * t17 * ab_ap + T(2) * a_minus_b * t21;
    const T t23 = t21 * t19;
    const T t24 = T(8) * t18 * ab_ap + T(5) * t22 * ab_ab * t15 + T(8) * a_minus_b * t23;
    const T t25 = t17 * t17;
    const T t26 = t21 * t21;
    const T t27 = T(7) * ab_ab * t15 * t24 + T(48) * t25 * ab_ap + T(48) * a_minus_b * t26;
    const T t28 = t25 * t16;
    const T t29 = t26 * t19;
    const T t30 = T(3) * ab_ab * t27 * t15 + T(128) * t28 * ab_ap + T(128) * a_minus_b * t29;
    const T t31 = t30 * t15 * ab_ap + T(128) * t28 - T(128) * t29;
    const T t32 = T(3) * ap_ap * t30 * t15 - T(6) * seg0 * t31 * ab_ap - T(10) * t27 * t15;
    const T t33 = T(48) * t25 + t27 * t15 * ab_ap - T(48) * t26;
    const T t34 = T(10) * seg0 * t33 - T(3) * ap_ap * seg0 * t31 - T(2) * t32 * seg0 * ab_ap;
    const T t35 = T(8) * t15 * t24 + T(2) * seg0 * t33 * ab_ap - ap_ap * t27 * t15;
    const T t36 = t32 * ap_ap * seg0 + T(2) * seg0 * t34 * ab_ap + T(10) * t35 * seg0;
    const T t37 = T(8) * t18 + t15 * t24 * ab_ap - T(8) * t23;
    const T t38 = ap_ap * seg0 * t33 - T(2) * t35 * seg0 * ab_ap - T(8) * t37 * seg0;
    const T t39 = T(2) * t36 * seg0 * ab_ap - ap_ap * seg0 * t34 - T(10) * t38 * seg0;
    const T t40 = ap_ap * t15 * t24 - T(6) * t22 * t15 - T(2) * t37 * seg0 * ab_ap;
    const T t41 = T(2) * t38 * seg0 * ab_ap + ap_ap * t35 * seg0 + T(8) * t40 * seg0;
    const T t42 = T(10) * t41 * seg0 + ap_ap * t36 * seg0 - T(2) * t39 * seg0 * ab_ap;
    const T t43 = T(2) * t17 + t22 * t15 * ab_ap - T(2) * t21;
    const T t44 = T(2) * t40 * seg0 * ab_ap + ap_ap * t37 * seg0 - T(6) * seg0 * t43;
    const T t45 = T(8) * seg0 * t44 + T(2) * t41 * seg0 * ab_ap - ap_ap * t38 * seg0;
    const T t46 = T(2) * seg0 * t42 * ab_ap + T(10) * seg0 * t45 + ap_ap * t39 * seg0;
    const T t47 = T(4) * t20 * t15 + T(2) * seg0 * ab_ap * t43 - ap_ap * t22 * t15;
    const T t48 = T(2) * seg0 * t44 * ab_ap - T(6) * seg0 * t47 - ap_ap * t40 * seg0;
    const T t49 = ap_ap * t41 * seg0 - T(8) * t48 * seg0 - T(2) * seg0 * ab_ap * t45;
    const T t50 = T(2) * seg0 * ab_ap * t46 - ap_ap * seg0 * t42 - T(10) * seg0 * t49;
    const T t51 = t20 * t15 * ab_ap + t16 - t19;
    const T t52 = T(4) * seg0 * t51 + T(2) * seg0 * t47 * ab_ap - ap_ap * seg0 * t43;
    const T t53 = ap_ap * seg0 * t44 + T(6) * seg0 * t52 - T(2) * t48 * seg0 * ab_ap;
    const T t54 = T(8) * t53 * seg0 + ap_ap * seg0 * t45 + T(2) * seg0 * ab_ap * t49;
    G_ap = (T(1) / T(1280)) * t30 * t15 * seg7 + (T(21) / T(640)) * seg3 * t36 * seg0 * seg2 + (T(21) / T(640)) * t39 * seg0 * seg13 * seg12 + (T(9) / T(1280)) * delta_tau * seg0 * t31 * seg17 + (T(7) / T(320)) * seg5 * seg0 * t34 * seg6 - (T(7) / T(320)) * seg15 * seg0 * seg14 * t42 - (T(3) / T(320)) * seg9 * seg0 * seg8 * t46 - (T(1) / T(3840)) * seg16 * seg0 * (T(2) * seg0 * t50 * ab_ap - T(10) * seg0 * t54 - ap_ap * seg0 * t46) - (T(3) / T(320)) * t32 * seg11 * seg0 * seg10 - (T(3) / T(1280)) * seg4 * tau_lo * seg0 * t50;
    G_E = (T(1) / T(1280)) * seg0 * (T(3) * delta_tau * t27 * t15 * seg17 + T(24) * seg11 * seg0 * t33 * seg10 + T(84) * seg9 * seg0 * seg8 * t49 + T(24) * seg4 * tau_lo * seg0 * t54 + T(3) * seg16 * (T(2) * seg0 * t54 * ab_ap + T(8) * (T(2) * t53 * seg0 * ab_ap + ap_ap * t48 * seg0 - T(6) * seg0 * (ap_ap * seg0 * t47 + T(4) * (ap_ap * t20 * t15 - T(2) * seg0 * t51 * ab_ap - T(2) * J2) * seg0 - T(2) * seg0 * t52 * ab_ap)) * seg0 - ap_ap * seg0 * t49) * seg0 + T(84) * t35 * seg5 * seg0 * seg6 + T(128) * t28 * seg7 - T(210) * t41 * seg0 * seg13 * seg12 - T(128) * seg18 * t29 - T(168) * t38 * seg3 * seg0 * seg2 - T(168) * seg15 * seg0 * seg14 * t45);
  }
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_inverse_i10_prepare); operations per point.
/// Operations: 138 +, 425 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 47830 +, 61913 ×, 4237 /, 91 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_inverse_i10_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab2 = pre[6];
  const T ab0 = pre[7];
  const T ab1 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T seg3 = pre[13];
  const T seg4 = pre[14];
  const T tau_lo = pre[15];
  const T seg5 = pre[16];
  const T seg6 = pre[17];
  const T seg7 = pre[18];
  const T seg8 = pre[19];
  const T seg9 = pre[20];
  const T seg10 = pre[21];
  const T seg11 = pre[22];
  const T seg12 = pre[23];
  const T seg13 = pre[24];
  const T seg14 = pre[25];
  const T seg15 = pre[26];
  const T seg16 = pre[27];
  const T delta_tau = pre[28];
  const T seg17 = pre[29];
  const T seg18 = pre[30];
  const T seg19 = pre[31];
  const T length = pre[32];
  const T g_factor = pre[33];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = seg0 * (exact_cross[2] * ab0 - exact_cross[0] * ab2);
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = seg1 + T(4) * cross_cross;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(seg1 + T(100) * cross_cross));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(84) * seg14 * M_panels[6] * seg15 + T(9) * M_panels[8] * seg4 * tau_lo + T(126) * seg2 * seg3 * M_panels[4] + seg16 * M_panels[9] + seg7 * M_panels[0] + T(9) * M_panels[1] * delta_tau * seg17 + T(84) * seg5 * M_panels[3] * seg6 + T(126) * seg13 * M_panels[5] * seg12 + T(36) * seg10 * M_panels[2] * seg11 + T(36) * seg8 * M_panels[7] * seg9;
    const T t4 = M_panels[11] * seg7 + T(126) * M_panels[15] * seg2 * seg3 + T(36) * seg10 * seg11 * M_panels[13] + M_panels[20] * seg16 + T(84) * M_panels[14] * seg5 * seg6 + T(9) * seg4 * tau_lo * M_panels[19] + T(36) * M_panels[18] * seg8 * seg9 + T(9) * delta_tau * seg17 * M_panels[12] + T(84) * M_panels[17] * seg14 * seg15 + T(126) * seg13 * M_panels[16] * seg12;
    G_ap = t4;
    G_E = T(36) * M_panels[14] * seg10 * seg11 + T(84) * M_panels[18] * seg14 * seg15 + T(126) * M_panels[17] * seg13 * seg12 + T(126) * seg2 * M_panels[16] * seg3 + T(36) * seg8 * M_panels[19] * seg9 + T(9) * delta_tau * seg17 * M_panels[13] + T(84) * M_panels[15] * seg5 * seg6 + T(9) * M_panels[20] * seg4 * tau_lo + seg16 * M_panels[21] + seg7 * M_panels[12] - seg0 * t4 * ab_ap;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = T(126) * seg2 * M_panels[4] * seg3 + T(36) * seg8 * M_panels[7] * seg9 + T(126) * seg13 * M_panels[5] * seg12 + T(84) * seg5 * M_panels[3] * seg6 + seg7 * M_panels[0] + T(84) * seg14 * M_panels[6] * seg15 + seg16 * M_panels[9] + T(9) * M_panels[8] * seg4 * tau_lo + T(36) * seg10 * M_panels[2] * seg11 + T(9) * delta_tau * seg17 * M_panels[1];
    G_ap = T(126) * seg13 * M_panels[16] * seg12 + M_panels[11] * seg7 + T(84) * M_panels[14] * seg5 * seg6 + T(126) * M_panels[15] * seg2 * seg3 + T(84) * M_panels[17] * seg14 * seg15 + T(36) * seg10 * seg11 * M_panels[13] + T(36) * M_panels[18] * seg8 * seg9 + seg16 * M_panels[20] + T(9) * seg4 * tau_lo * M_panels[19] + T(9) * delta_tau * seg17 * M_panels[12];
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(10)) * seg0 * (T(9) * seg16 * M_panels[8] + T(72) * seg10 * seg11 * M_panels[1] + T(72) * seg4 * tau_lo * M_panels[7] + T(9) * delta_tau * seg17 * M_panels[0] + T(504) * M_panels[3] * seg2 * seg3 + T(504) * M_panels[5] * seg14 * seg15 + T(630) * seg13 * seg12 * M_panels[4] + T(252) * M_panels[2] * seg5 * seg6 + T(252) * M_panels[6] * seg8 * seg9 + t8 * seg7 - seg18 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / ap_ap;
    const T log_ratio = log(t15 * bp_bp);
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t16 * t15;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = J2 * ab_ab + a_minus_b * t19 + t15 * ab_ap;
    const T t23 = T(1) / cross_cross;
    const T t24 = T(2) * t16 * ab_ap + T(3) * t22 * ab_ab * t23 + T(2) * a_minus_b * t20;
    const T t25 = T(8) * t18 * ab_ap + T(8) * a_minus_b * t21 + T(5) * t24 * ab_ab * t23;
    const T t26 = t20 * t20;
    const T t27 = T(7) * t25 * ab_ab * t23 + T(48) * a_minus_b * t26 + T(48) * t17 * ab_ap;
    const T t28 = T(48) * t17 + t27 * t23 * ab_ap - T(48) * t26;
    const T t29 = T(2) * seg0 * t28 * ab_ap + T(8) * t25 * t23 - ap_ap * t27 * t23;
    const T t30 = T(8) * t18 + t25 * t23 * ab_ap - T(8) * t21;
    const T t31 = seg0 * ap_ap * t28 - T(2) * seg0 * t29 * ab_ap - T(8) * seg0 * t30;
    const T t32 = ap_ap * t25 * t23 - T(6) * t24 * t23 - T(2) * seg0 * t30 * ab_ap;
    const T t33 = T(2) * t16 + t24 * t23 * ab_ap - T(2) * t20;
    const T t34 = T(2) * seg0 * t32 * ab_ap + seg0 * ap_ap * t30 - T(6) * seg0 * t33;
    const T t35 = seg0 * ap_ap * t29 + T(2) * seg0 * ab_ap * t31 + T(8) * seg0 * t32;
    const T t36 = seg0 * ap_ap * t31 - T(8) * seg0 * t34 - T(2) * seg0 * t35 * ab_ap;
    const T t37 = T(4) * t22 * t23 + T(2) * seg0 * t33 * ab_ap - ap_ap * t24 * t23;
    const T t38 = T(2) * seg0 * t34 * ab_ap - seg0 * ap_ap * t32 - T(6) * seg0 * t37;
    const T t39 = t22 * t23 * ab_ap + t15 - t19;
    const T t40 = T(4) * seg0 * t39 + T(2) * seg0 * t37 * ab_ap - seg0 * ap_ap * t33;
    const T t41 = T(2) * seg0 * t38 * ab_ap - seg0 * ap_ap * t34 - T(6) * seg0 * t40;
    const T t42 = T(2) * J2 + T(2) * seg0 * t39 * ab_ap - ap_ap * t22 * t23;
    const T t43 = T(2) * seg0 * t40 * ab_ap + T(4) * seg0 * t42 - seg0 * t37 * ap_ap;
    const T t44 = T(6) * seg0 * t43 + seg0 * ap_ap * t38 - T(2) * seg0 * t41 * ab_ap;
    const T t45 = T(8) * seg0 * t38 - seg0 * ap_ap * t35 - T(2) * seg0 * t36 * ab_ap;
    const T t46 = seg0 * ap_ap * t36 + T(8) * seg0 * t41 + T(2) * t45 * seg0 * ab_ap;
    const T t47 = T(2) * seg0 * t46 * ab_ap - t45 * seg0 * ap_ap - T(8) * seg0 * t44;
    F = (T(21) / T(64)) * seg0 * seg13 * t36 * seg12 + (T(3) / T(32)) * seg0 * seg10 * t29 * seg11 + (T(1) / T(384)) * seg0 * seg16 * (T(8) * seg0 * (seg0 * ap_ap * t41 + T(2) * seg0 * t44 * ab_ap - T(6) * seg0 * (seg0 * ap_ap * t40 - T(4) * seg0 * (T(2) * seg0 * t42 * ab_ap + seg0 * (log_ratio + T(2) * J2 * ab_ap) - seg0 * ap_ap * t39) - T(2) * seg0 * t43 * ab_ap)) + seg0 * ap_ap * t46 - T(2) * seg0 * t47 * ab_ap) + (T(1) / T(384)) * t27 * seg7 * t23 + (T(3) / T(128)) * seg0 * delta_tau * seg17 * t28 - (T(3) / T(32)) * seg0 * seg8 * t46 * seg9 - (T(7) / T(32)) * seg0 * seg5 * seg6 * t31 - (T(21) / T(64)) * seg0 * seg2 * t35 * seg3 - (T(7) / T(32)) * t45 * seg0 * seg14 * seg15 - (T(3) / T(128)) * seg0 * seg4 * tau_lo * t47;
    const T t48 = t17 * t15;
    const T t49 = t26 * t19;
    const T t50 = T(128) * a_minus_b * t49 + T(128) * t48 * ab_ap + T(3) * t27 * ab_ab * t23;
    const T t51 = T(128) * t48 + t23 * t50 * ab_ap - T(128) * t49;
    const T t52 = T(6) * seg0 * t51 * ab_ap + T(10) * t27 * t23 - T(3) * ap_ap * t23 * t50;
    const T t53 = T(3) * seg0 * ap_ap * t51 - T(2) * seg0 * t52 * ab_ap - T(10) * seg0 * t28;
    const T t54 = seg0 * ap_ap * t52 + T(2) * seg0 * t53 * ab_ap - T(10) * seg0 * t29;
    const T t55 = seg0 * ap_ap * t53 - T(2) * seg0 * t54 * ab_ap - T(10) * seg0 * t31;
    const T t56 = seg0 * ap_ap * t54 + T(2) * seg0 * t55 * ab_ap - T(10) * seg0 * t35;
    const T t57 = seg0 * ap_ap * t55 - T(10) * seg0 * t36 - T(2) * seg0 * t56 * ab_ap;
    const T t58 = T(10) * t45 * seg0 + seg0 * ap_ap * t56 + T(2) * seg0 * ab_ap * t57;
    G_ap = (T(1) / T(3840)) * seg0 * (seg0 * ap_ap * t57 - T(10) * seg0 * t46 - T(2) * seg0 * t58 * ab_ap) * seg16 + (T(9) / T(1280)) * seg0 * delta_tau * seg17 * t51 + (T(3) / T(320)) * seg0 * seg10 * t52 * seg11 + (T(21) / T(640)) * seg0 * seg13 * t55 * seg12 + (T(1) / T(1280)) * seg7 * t23 * t50 + (T(7) / T(320)) * seg0 * seg14 * t56 * seg15 - (T(7) / T(320)) * seg0 * t53 * seg5 * seg6 - (T(3) / T(1280)) * seg0 * seg4 * tau_lo * t58 - (T(3) / T(320)) * seg0 * seg8 * seg9 * t57 - (T(21) / T(640)) * seg0 * t54 * seg2 * seg3;
    G_E = -(T(1) / T(1280)) * seg0 * (T(210) * seg0 * seg13 * t35 * seg12 + T(24) * seg0 * seg4 * tau_lo * t46 + T(128) * seg18 * t49 + T(84) * t45 * seg0 * seg8 * seg9 + T(168) * seg0 * seg2 * t31 * seg3 + T(3) * seg0 * seg16 * t47 - T(168) * seg0 * t36 * seg14 * seg15 - T(24) * seg0 * seg10 * seg11 * t28 - T(84) * seg0 * t29 * seg5 * seg6 - T(3) * t27 * delta_tau * seg17 * t23 - T(128) * t48 * seg7);
  }
  f = seg19 * F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

}  // namespace skelconv::generated
