// generated/scalis_segment_inverse.hpp — SCALIS segment kernels of the inverse family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC §2, Hubert 2012 §3).
// SCALIS segments (SPEC §4, Zanni et al. 2013 §3–4, Table 3): the segment kernel of
// degree i with the weight σ^i τ(t)^(i−1), and for Cauchy q = |P − Γ(t)|² + σ²τ(t)²
// (codegen/segment_families.cpp, ScalisKernelSpec). Unnormalised: f = c F / h is
// the runtime's (skelconv/scalis_segment.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/gauss_moments.hpp>
#include <skelconv/scalis_segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 31 +, 41 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 132 +, 221 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i2_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * delta_tau + M_flat[0] * tau_lo;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ab_ab;
    F = t3 * tau_lo + (T(1) / T(2)) * (T(2) * ab_ap * t3 + log_ratio) * delta_tau * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(cross_cross);
    const T J2 = atan2(t5, ap_bp) / t5;
    const T t6 = T(1) / ab_ab;
    F = J2 * tau_lo + (T(1) / T(2)) * delta_tau * (T(2) * ab_ap * J2 + log_ratio) * t6;
  }
  f = F * in.sigma * in.sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 40 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 156 +, 273 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i2_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = delta_tau * M_flat[1] + M_flat[0] * tau_lo;
    G_ab = tau_lo * M_flat[1] + delta_tau * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * tau_lo + delta_tau * M_beyond[1];
    G_ab = tau_lo * M_beyond[1] + delta_tau * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = ab_ab * J2 + a_minus_b * t5 + t6 * ab_ap;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / ab_ab;
    const T t10 = t7 * t8 * ab_ap + t6 - t5;
    G_ap = (T(1) / T(2)) * t7 * t8 * tau_lo + (T(1) / T(2)) * delta_tau * t9 * t10;
    G_ab = (T(1) / T(2)) * tau_lo * t9 * t10 - (T(1) / T(2)) * delta_tau * (ap_ap * t7 * t8 - T(2) * J2 - T(2) * t9 * ab_ap * t10) * t9;
  }
  const T g_factor = -T(2) * in.sigma * in.sigma * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 42 +, 77 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 217 +, 381 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i2_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = delta_tau * M_flat[1] + tau_lo * M_flat[0];
    G_ap = delta_tau * M_flat[4] + tau_lo * M_flat[3];
    G_ab = delta_tau * M_flat[5] + tau_lo * M_flat[4];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / ab_ab;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * a_minus_b;
    const T t7 = ab_ap * t0;
    const T t8 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t6 + t7 - T(2) * cross_cross * t8;
    F = -tau_lo * t4 * t9 - (T(1) / T(2)) * delta_tau * t4 * (T(2) * t4 * ab_ap * t9 - log_ratio);
    const T t10 = t0 + T(2) * ab_ap * t8 - t5;
    G_ap = (T(1) / T(2)) * delta_tau * t4 * t10 + tau_lo * t8;
    G_ab = (T(1) / T(2)) * tau_lo * t4 * t10 - delta_tau * t4 * (ap_ap * t8 + t4 * t9 - t4 * t10 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(2)) * delta_tau * t13 * (T(2) * ab_ap * J2 + log_ratio) + tau_lo * J2;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * a_minus_b;
    const T t17 = ab_ap * t0;
    const T t18 = ab_ab * J2 + t16 + t17;
    const T t19 = t0 + t14 * t18 * ab_ap - t15;
    G_ap = (T(1) / T(2)) * delta_tau * t13 * t19 + (T(1) / T(2)) * t14 * tau_lo * t18;
    G_ab = (T(1) / T(2)) * tau_lo * t13 * t19 - (T(1) / T(2)) * delta_tau * t13 * (t14 * t18 * ap_ap - T(2) * J2 - T(2) * t13 * ab_ap * t19);
  }
  const T t20 = in.sigma * in.sigma;
  const T g_factor = -T(2) * length * t20;
  f = length * F * t20;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 35 +, 58 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 152 +, 291 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i3_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = ab_ap * r1;
    X = t1 * length * (t2 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = delta_tau * delta_tau;
    F = T(2) * M_flat[1] * delta_tau * tau_lo + t8 * M_flat[0] + t9 * M_flat[2];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = tau_lo * tau_lo;
    const T t11 = -ab_ap;
    const T t12 = J_downward<T>(3, ab_ab, cross_cross, t11, ap_ap, a_minus_b, bp_bp);
    const T t13 = delta_tau * delta_tau;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 - ab_ap * t12 - t16;
    F = t10 * t12 - t13 * t14 * (T(2) * t17 * t14 * ab_ap + ap_ap * t12 - J1) - T(2) * delta_tau * tau_lo * t17 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / cross_cross;
    const T t19 = tau_lo * tau_lo;
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = a_minus_b * t20 + t21 * ab_ap;
    const T t23 = t20 - t21 - t18 * t22 * ab_ap;
    const T t24 = T(1) / ab_ab;
    const T t25 = delta_tau * delta_tau;
    F = t18 * t19 * t22 - T(2) * t23 * delta_tau * tau_lo * t24 - t25 * t24 * (T(2) * t23 * t24 * ab_ap + ap_ap * t18 * t22 - J1);
  }
  const T t26 = in.sigma * in.sigma;
  const T t27 = t26 * in.sigma;
  f = length * t27 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 45 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 176 +, 360 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i3_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = tau_lo * tau_lo;
    G_ap = t3 * M_flat[2] + T(2) * delta_tau * tau_lo * M_flat[1] + M_flat[0] * t4;
    G_ab = M_flat[3] * t3 + t4 * M_flat[1] + T(2) * delta_tau * tau_lo * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t5 = delta_tau * delta_tau;
    const T t6 = tau_lo * tau_lo;
    G_ap = M_beyond[2] * t5 + t6 * M_beyond[0] + T(2) * delta_tau * tau_lo * M_beyond[1];
    G_ab = T(2) * M_beyond[2] * delta_tau * tau_lo + t6 * M_beyond[1] + t5 * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / r0;
    const T t8 = T(1) / r1;
    const T t9 = t7 * ab_ap + t8 * a_minus_b;
    const T t10 = T(1) / cross_cross;
    const T t11 = t7 * t7;
    const T t12 = t8 * t8;
    const T t13 = t7 * t11 * ab_ap + t8 * a_minus_b * t12 + T(2) * t9 * t10 * ab_ab;
    const T t14 = t10 * ab_ap * t13 + t7 * t11 - t8 * t12;
    const T t15 = T(1) / ab_ab;
    const T t16 = T(3) * t9 * t10 + T(2) * t14 * t15 * ab_ap - ap_ap * t10 * t13;
    const T t17 = delta_tau * delta_tau;
    const T t18 = tau_lo * tau_lo;
    G_ap = (T(1) / T(3)) * t16 * t17 * t15 + (T(2) / T(3)) * delta_tau * t14 * tau_lo * t15 + (T(1) / T(3)) * t10 * t18 * t13;
    G_ab = (T(1) / T(3)) * t14 * t18 * t15 + (T(1) / T(3)) * (T(2) * t16 * t15 * ab_ap - T(3) * (t8 - t9 * t10 * ab_ap - t7) * t15 - ap_ap * t14 * t15) * t17 * t15 + (T(2) / T(3)) * t16 * delta_tau * tau_lo * t15;
  }
  const T t19 = in.sigma * in.sigma;
  const T t20 = t19 * in.sigma;
  const T g_factor = -T(3) * length * t20;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 50 +, 116 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 259 +, 497 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i3_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = delta_tau * delta_tau;
    F = T(2) * M_flat[1] * delta_tau * tau_lo + t8 * M_flat[0] + M_flat[2] * t9;
    G_ap = T(2) * M_flat[5] * delta_tau * tau_lo + t9 * M_flat[6] + M_flat[4] * t8;
    G_ab = M_flat[5] * t8 + M_flat[7] * t9 + T(2) * delta_tau * M_flat[6] * tau_lo;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = ab_ap * t12 * t11;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t14 * t15 * a_minus_b;
    const T t17 = J_downward<T>(5, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t18 = t13 + t16 - T(3) * t17 * cross_cross;
    const T t19 = T(2) * t14 + ab_ap * t10 * t18 - T(2) * t11;
    const T t20 = delta_tau * delta_tau;
    const T t21 = tau_lo * tau_lo;
    F = (T(1) / T(2)) * (ap_ap * t10 * t18 + T(2) * J1 - T(2) * t19 * ab_ap * t10) * t20 * t10 - (T(1) / T(2)) * t21 * t10 * t18 - t19 * delta_tau * tau_lo * t10;
    const T t22 = t14 * t15;
    const T t23 = t22 - t12 * t11 - T(3) * ab_ap * t17;
    const T t24 = T(4) * t23 * ab_ap * t10 + T(6) * t17 * ap_ap + T(3) * t10 * t18;
    G_ap = t17 * t21 - (T(2) / T(3)) * t23 * delta_tau * tau_lo * t10 - (T(1) / T(6)) * t24 * t20 * t10;
    G_ab = -(T(1) / T(6)) * (T(3) * t19 * t10 + T(2) * ab_ap * t24 * t10 - T(2) * t23 * ap_ap * t10) * t20 * t10 - (T(1) / T(3)) * t24 * delta_tau * tau_lo * t10 - (T(1) / T(3)) * t23 * t21 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = delta_tau * delta_tau;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(1) / r1;
    const T t28 = T(1) / r0;
    const T t29 = t27 * a_minus_b + ab_ap * t28;
    const T t30 = T(1) / cross_cross;
    const T t31 = t29 * ab_ap * t30 + t28 - t27;
    const T t32 = tau_lo * tau_lo;
    F = t25 * t26 * (T(2) * t31 * ab_ap * t26 + J1 - t29 * ap_ap * t30) + t29 * t30 * t32 + T(2) * t31 * delta_tau * tau_lo * t26;
    const T t33 = t27 * t27;
    const T t34 = t27 * t33;
    const T t35 = t28 * t28;
    const T t36 = ab_ap * t35 * t28;
    const T t37 = t27 * t33 * a_minus_b;
    const T t38 = t36 + t37 + T(2) * t29 * t30 * ab_ab;
    const T t39 = t34 - t35 * t28 - t38 * ab_ap * t30;
    const T t40 = T(3) * t29 * t30 - T(2) * ab_ap * t39 * t26 - t38 * ap_ap * t30;
    G_ap = (T(1) / T(3)) * t40 * t25 * t26 + (T(1) / T(3)) * t38 * t30 * t32 - (T(2) / T(3)) * t39 * delta_tau * tau_lo * t26;
    G_ab = (T(1) / T(3)) * t25 * (t39 * ap_ap * t26 + T(2) * ab_ap * t40 * t26 + T(3) * t31 * t26) * t26 + (T(2) / T(3)) * t40 * delta_tau * tau_lo * t26 - (T(1) / T(3)) * t39 * t32 * t26;
  }
  const T t41 = in.sigma * in.sigma;
  const T t42 = t41 * in.sigma;
  const T g_factor = -T(3) * length * t42;
  f = length * F * t42;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 41 +, 75 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 174 +, 295 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i4_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * tau_lo;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    F = t5 * M_flat[0] + T(3) * t6 * tau_lo * M_flat[2] + M_flat[3] * t7 + T(3) * M_flat[1] * delta_tau * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t8 = tau_lo * tau_lo;
    const T t9 = T(1) / ab_ab;
    const T t10 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = T(1) / bp_bp;
    const T t12 = T(2) * t10 * ab_ap + t0 - t11;
    const T t13 = t8 * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * delta_tau;
    const T t16 = t0 * ab_ap;
    const T t17 = a_minus_b * t11;
    const T t18 = t16 + t17 - T(2) * cross_cross * t10;
    const T t19 = t9 * t18 + ap_ap * t10 - t9 * t12 * ab_ap;
    F = (T(3) / T(2)) * delta_tau * t8 * t9 * t12 + t13 * t10 - (T(1) / T(2)) * t15 * t9 * (ap_ap * t9 * t12 + T(4) * t9 * ab_ap * t19 - (log_ratio - T(2) * t9 * t18 * ab_ap) * t9) - T(3) * t14 * tau_lo * t9 * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = t21 * atan2(t20, ap_bp);
    const T t22 = delta_tau * delta_tau;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(1) / bp_bp;
    const T t25 = T(1) / cross_cross;
    const T t26 = t0 * ab_ap;
    const T t27 = a_minus_b * t24;
    const T t28 = t26 + J2 * ab_ab + t27;
    const T t29 = t24 - t25 * t28 * ab_ap - t0;
    const T t30 = T(2) * J2 - T(2) * t29 * t23 * ab_ap - ap_ap * t25 * t28;
    const T t31 = t22 * delta_tau;
    const T t32 = tau_lo * tau_lo;
    const T t33 = t32 * tau_lo;
    F = (T(3) / T(2)) * t22 * tau_lo * t23 * t30 + (T(1) / T(2)) * ((T(2) * J2 * ab_ap + log_ratio) * t23 + t29 * ap_ap * t23 + T(2) * t23 * t30 * ab_ap) * t31 * t23 + (T(1) / T(2)) * t25 * t33 * t28 - (T(3) / T(2)) * t29 * delta_tau * t32 * t23;
  }
  const T t34 = in.sigma * in.sigma;
  const T t35 = t34 * t34;
  f = F * t35 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 54 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 200 +, 352 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i4_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * tau_lo;
    const T t5 = delta_tau * delta_tau;
    const T t6 = t5 * delta_tau;
    G_ap = t4 * M_flat[0] + T(3) * tau_lo * M_flat[2] * t5 + M_flat[3] * t6 + T(3) * t3 * M_flat[1] * delta_tau;
    G_ab = T(3) * tau_lo * M_flat[3] * t5 + M_flat[4] * t6 + t4 * M_flat[1] + T(3) * t3 * M_flat[2] * delta_tau;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * tau_lo;
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * delta_tau;
    G_ap = t8 * M_beyond[0] + T(3) * tau_lo * t9 * M_beyond[2] + M_beyond[3] * t10 + T(3) * t7 * M_beyond[1] * delta_tau;
    G_ab = T(3) * t7 * delta_tau * M_beyond[2] + T(3) * tau_lo * M_beyond[3] * t9 + t8 * M_beyond[1] + M_beyond[4] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = tau_lo * tau_lo;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = ab_ap * t17 + a_minus_b * t15 + ab_ab * J2;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(2) * a_minus_b * t16 + T(2) * ab_ap * t18 + T(3) * ab_ab * t19 * t20;
    const T t22 = ab_ap * t21 * t20 + T(2) * t18 - T(2) * t16;
    const T t23 = T(4) * t19 * t20 + T(2) * t14 * ab_ap * t22 - ap_ap * t21 * t20;
    const T t24 = delta_tau * delta_tau;
    const T t25 = t13 * tau_lo;
    const T t26 = t15 - t17 - t19 * ab_ap * t20;
    const T t27 = t14 * t22 * ap_ap + T(4) * t14 * t26 - T(2) * t23 * t14 * ab_ap;
    const T t28 = t24 * delta_tau;
    G_ap = (T(3) / T(8)) * t13 * t14 * t22 * delta_tau + (T(3) / T(8)) * tau_lo * t23 * t14 * t24 + (T(1) / T(8)) * t25 * t21 * t20 - (T(1) / T(8)) * t14 * t27 * t28;
    G_ab = (T(3) / T(8)) * t13 * t23 * t14 * delta_tau + (T(1) / T(8)) * t25 * t14 * t22 - (T(3) / T(8)) * tau_lo * t14 * t27 * t24 - (T(1) / T(8)) * t14 * (T(2) * t14 * ab_ap * t27 + T(4) * t14 * (t19 * ap_ap * t20 + T(2) * t14 * ab_ap * t26 - T(2) * J2) + t23 * t14 * ap_ap) * t28;
  }
  const T t29 = in.sigma * in.sigma;
  const T t30 = t29 * t29;
  const T g_factor = -T(4) * length * t30;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 60 +, 148 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 303 +, 508 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i4_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    F = T(3) * tau_lo * M_flat[2] * t4 + M_flat[3] * t5 + t7 * M_flat[0] + T(3) * t6 * M_flat[1] * delta_tau;
    G_ap = T(3) * t6 * delta_tau * M_flat[6] + t7 * M_flat[5] + M_flat[8] * t5 + T(3) * tau_lo * M_flat[7] * t4;
    G_ab = M_flat[9] * t5 + T(3) * t6 * M_flat[7] * delta_tau + t7 * M_flat[6] + T(3) * tau_lo * M_flat[8] * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = T(1) / ab_ab;
    const T t11 = J_downward<T>(6, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = t0 * t0;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = T(4) * t11 * cross_cross - ab_ap * t12 - t14 * a_minus_b;
    const T t16 = T(2) * t10 * ab_ap * t15 + T(3) * t0 - T(3) * t13;
    const T t17 = T(3) * t13 * a_minus_b + T(3) * ab_ap * t0 - T(2) * t10 * t15 * cross_cross;
    const T t18 = t10 * t15 * ap_ap + t10 * t17 - t10 * ab_ap * t16;
    const T t19 = delta_tau * delta_tau;
    const T t20 = t19 * delta_tau;
    F = (T(1) / T(3)) * t9 * t10 * t15 + (T(1) / T(2)) * t8 * t10 * t16 * delta_tau - tau_lo * t10 * t18 * t19 - (T(1) / T(6)) * t10 * (t10 * t16 * ap_ap + T(4) * t10 * ab_ap * t18 + t10 * (T(2) * t10 * ab_ap * t17 - T(3) * log_ratio)) * t20;
    const T t21 = t12 + T(4) * ab_ap * t11 - t14;
    const T t22 = T(6) * t11 * ap_ap - T(2) * t10 * t15 - T(3) * t10 * ab_ap * t21;
    const T t23 = T(2) * t10 * t16 - T(4) * t10 * t22 * ab_ap - T(3) * t10 * t21 * ap_ap;
    G_ap = (T(3) / T(4)) * t8 * t10 * t21 * delta_tau + t9 * t11 + (T(1) / T(12)) * t10 * t23 * t20 - (T(1) / T(2)) * tau_lo * t10 * t22 * t19;
    G_ab = (T(1) / T(4)) * tau_lo * t10 * t23 * t19 + (T(1) / T(4)) * t9 * t10 * t21 - (T(1) / T(2)) * t8 * t10 * t22 * delta_tau - (T(1) / T(6)) * t10 * (T(2) * t10 * t18 - t10 * t22 * ap_ap - t10 * t23 * ab_ap) * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = sqrt(cross_cross);
    const T t25 = T(1) / t24;
    const T J2 = atan2(t24, ap_bp) * t25;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * a_minus_b + ab_ap * t0 + ab_ab * J2;
    const T t29 = T(1) / cross_cross;
    const T t30 = t27 - ab_ap * t28 * t29 - t0;
    const T t31 = T(2) * J2 - T(2) * t26 * ab_ap * t30 - ap_ap * t28 * t29;
    const T t32 = delta_tau * delta_tau;
    const T t33 = t32 * delta_tau;
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * tau_lo;
    F = (T(1) / T(2)) * t26 * (t26 * ap_ap * t30 + t26 * (T(2) * ab_ap * J2 + log_ratio) + T(2) * t26 * t31 * ab_ap) * t33 + (T(3) / T(2)) * tau_lo * t26 * t31 * t32 + (T(1) / T(2)) * t35 * t28 * t29 - (T(3) / T(2)) * t34 * t26 * t30 * delta_tau;
    const T t36 = t0 * t0;
    const T t37 = t27 * t27;
    const T t38 = T(3) * ab_ab * t28 * t29 + T(2) * ab_ap * t36 + T(2) * t37 * a_minus_b;
    const T t39 = T(2) * t36 + ab_ap * t38 * t29 - T(2) * t37;
    const T t40 = T(4) * t28 * t29 + T(2) * t26 * ab_ap * t39 - ap_ap * t38 * t29;
    const T t41 = T(4) * t26 * t30 + t26 * ap_ap * t39 - T(2) * t26 * ab_ap * t40;
    G_ap = (T(3) / T(8)) * tau_lo * t26 * t32 * t40 + (T(1) / T(8)) * t35 * t38 * t29 + (T(3) / T(8)) * t34 * t26 * t39 * delta_tau - (T(1) / T(8)) * t26 * t41 * t33;
    G_ab = (T(1) / T(8)) * t35 * t26 * t39 + (T(3) / T(8)) * t34 * t26 * delta_tau * t40 + (T(1) / T(8)) * t26 * (T(4) * t26 * t31 - T(2) * t26 * ab_ap * t41 - t26 * ap_ap * t40) * t33 - (T(3) / T(8)) * tau_lo * t26 * t41 * t32;
  }
  const T t42 = in.sigma * in.sigma;
  const T t43 = t42 * t42;
  const T g_factor = -T(4) * length * t43;
  f = length * F * t43;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 47 +, 107 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 194 +, 384 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i5_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r0 * a_minus_b) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = t8 * t8;
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t11 * delta_tau;
    F = T(4) * M_flat[1] * t9 * delta_tau + M_flat[0] * t10 + M_flat[4] * t12 + T(4) * M_flat[3] * tau_lo * t13 + T(6) * t8 * t11 * M_flat[2];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t14 = J_downward<T>(5, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = tau_lo * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t17 * t18;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t19 + T(3) * t14 * ab_ap - t21 * t20;
    const T t23 = T(1) / ab_ab;
    const T t24 = t17 * ab_ap * t18;
    const T t25 = t21 * t20 * a_minus_b;
    const T t26 = t24 + t25 - T(3) * t14 * cross_cross;
    const T t27 = T(4) * ab_ap * t22 * t23 - T(6) * t14 * ap_ap - T(3) * t26 * t23;
    const T t28 = delta_tau * delta_tau;
    const T t29 = T(2) * t20 + ab_ap * t26 * t23 - T(2) * t17;
    const T t30 = T(3) * t29 * t23 + T(2) * ap_ap * t22 * t23 - T(2) * ab_ap * t27 * t23;
    const T t31 = t28 * t28;
    const T t32 = t15 * tau_lo;
    const T t33 = t28 * delta_tau;
    F = t14 * t16 + t27 * t15 * t28 * t23 + (T(1) / T(6)) * (T(3) * (T(2) * J1 + ap_ap * t26 * t23 - T(2) * ab_ap * t29 * t23) * t23 - T(2) * ab_ap * t30 * t23 - t27 * ap_ap * t23) * t31 * t23 + (T(4) / T(3)) * t22 * t32 * delta_tau * t23 - (T(2) / T(3)) * t30 * tau_lo * t33 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * t34;
    const T t36 = T(1) / cross_cross;
    const T t37 = T(1) / r0;
    const T t38 = T(1) / r1;
    const T t39 = t37 * ab_ap + t38 * a_minus_b;
    const T t40 = t37 * t37;
    const T t41 = t37 * ab_ap * t40;
    const T t42 = t38 * t38;
    const T t43 = t42 * t38 * a_minus_b;
    const T t44 = T(2) * t39 * t36 * ab_ab + t41 + t43;
    const T t45 = t37 * t40;
    const T t46 = t45 + ab_ap * t36 * t44 - t42 * t38;
    const T t47 = T(1) / ab_ab;
    const T t48 = T(2) * ab_ap * t46 * t47 + T(3) * t39 * t36 - ap_ap * t36 * t44;
    const T t49 = delta_tau * delta_tau;
    const T t50 = t34 * tau_lo;
    const T t51 = ab_ap * t39 * t36 + t37 - t38;
    const T t52 = T(3) * t51 * t47 + T(2) * t48 * ab_ap * t47 - ap_ap * t46 * t47;
    const T t53 = t49 * delta_tau;
    const T t54 = t49 * t49;
    F = (T(1) / T(3)) * t35 * t36 * t44 + T(2) * t48 * t34 * t49 * t47 + (T(4) / T(3)) * t46 * t50 * delta_tau * t47 + (T(4) / T(3)) * t52 * tau_lo * t53 * t47 - (T(1) / T(3)) * (t48 * ap_ap * t47 - T(2) * t52 * ab_ap * t47 - T(3) * (J1 + T(2) * ab_ap * t51 * t47 - t39 * ap_ap * t36) * t47) * t54 * t47;
  }
  const T t55 = in.sigma * in.sigma;
  const T t56 = t55 * t55;
  const T t57 = t56 * in.sigma;
  f = length * F * t57;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 61 +, 161 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 220 +, 459 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i5_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 5, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * tau_lo;
    const T t5 = delta_tau * delta_tau;
    const T t6 = t3 * t3;
    const T t7 = t5 * t5;
    const T t8 = t5 * delta_tau;
    G_ap = T(4) * delta_tau * t4 * M_flat[1] + T(6) * M_flat[2] * t5 * t3 + M_flat[0] * t6 + t7 * M_flat[4] + T(4) * M_flat[3] * t8 * tau_lo;
    G_ab = T(4) * t8 * tau_lo * M_flat[4] + t6 * M_flat[1] + M_flat[5] * t7 + T(6) * M_flat[3] * t5 * t3 + T(4) * M_flat[2] * delta_tau * t4;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 5, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * tau_lo;
    const T t11 = t9 * t9;
    const T t12 = delta_tau * delta_tau;
    const T t13 = t12 * delta_tau;
    const T t14 = t12 * t12;
    G_ap = T(4) * delta_tau * M_beyond[1] * t10 + M_beyond[0] * t11 + T(6) * t12 * t9 * M_beyond[2] + T(4) * M_beyond[3] * t13 * tau_lo + M_beyond[4] * t14;
    G_ab = M_beyond[1] * t11 + T(4) * delta_tau * t10 * M_beyond[2] + T(4) * M_beyond[4] * t13 * tau_lo + T(6) * M_beyond[3] * t12 * t9 + t14 * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = delta_tau * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = T(1) / cross_cross;
    const T t25 = ab_ap * t21 + t18 * a_minus_b;
    const T t26 = T(2) * t25 * t24 * ab_ab + ab_ap * t21 * t22 + t18 * a_minus_b * t19;
    const T t27 = T(3) * ab_ap * t21 * t23 + T(4) * t24 * t26 * ab_ab + T(3) * t18 * a_minus_b * t20;
    const T t28 = T(3) * t18 * t20 - T(3) * t21 * t23 - ab_ap * t24 * t27;
    const T t29 = t21 * t22 + ab_ap * t24 * t26 - t18 * t19;
    const T t30 = ap_ap * t24 * t27 + T(2) * t28 * ab_ap * t17 - T(5) * t24 * t26;
    const T t31 = t28 * ap_ap * t17 + T(5) * t29 * t17 - T(2) * ab_ap * t30 * t17;
    const T t32 = T(2) * ab_ap * t29 * t17 + T(3) * t25 * t24 - ap_ap * t24 * t26;
    const T t33 = T(2) * t31 * ab_ap * t17 + ap_ap * t30 * t17 + T(5) * t32 * t17;
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * t34;
    const T t36 = t15 * delta_tau;
    const T t37 = t34 * tau_lo;
    G_ap = (T(1) / T(15)) * t16 * t17 * t33 + (T(1) / T(15)) * t24 * t27 * t35 + (T(4) / T(15)) * t31 * t36 * tau_lo * t17 - (T(2) / T(5)) * t15 * t34 * t30 * t17 - (T(4) / T(15)) * t28 * delta_tau * t37 * t17;
    G_ab = (T(2) / T(5)) * t31 * t15 * t34 * t17 + (T(4) / T(15)) * t36 * tau_lo * t17 * t33 - (T(4) / T(15)) * delta_tau * t37 * t30 * t17 - (T(1) / T(15)) * (T(5) * (T(3) * (t18 - ab_ap * t25 * t24 - t21) * t17 + ap_ap * t29 * t17 - T(2) * ab_ap * t32 * t17) * t17 + t31 * ap_ap * t17 - T(2) * ab_ap * t17 * t33) * t16 * t17 - (T(1) / T(15)) * t28 * t35 * t17;
  }
  const T t38 = in.sigma * in.sigma;
  const T t39 = t38 * t38;
  const T t40 = t39 * in.sigma;
  const T g_factor = -T(5) * t40 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 70 +, 199 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 345 +, 644 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i5_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r1 * ab_ap) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 12> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 5, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t8 * t8;
    const T t11 = t9 * tau_lo;
    const T t12 = t8 * delta_tau;
    const T t13 = t9 * t9;
    F = T(6) * M_flat[2] * t8 * t9 + t10 * M_flat[4] + T(4) * delta_tau * t11 * M_flat[1] + T(4) * t12 * tau_lo * M_flat[3] + t13 * M_flat[0];
    G_ap = t10 * M_flat[10] + M_flat[6] * t13 + T(4) * M_flat[9] * t12 * tau_lo + T(6) * t8 * t9 * M_flat[8] + T(4) * delta_tau * t11 * M_flat[7];
    G_ab = T(6) * M_flat[9] * t8 * t9 + T(4) * t12 * tau_lo * M_flat[10] + T(4) * delta_tau * t11 * M_flat[8] + t13 * M_flat[7] + t10 * M_flat[11];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = J_downward<T>(7, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = T(5) * cross_cross * t17 - t18 * t20 * a_minus_b - t23 * t21 * ab_ap;
    const T t25 = t14 * tau_lo;
    const T t26 = T(3) * t16 * ab_ap * t24 + T(4) * t22 * t21 - T(4) * t18 * t19;
    const T t27 = T(4) * t22 * t21 * ab_ap + T(4) * t18 * t19 * a_minus_b - T(3) * cross_cross * t16 * t24;
    const T t28 = T(4) * t16 * ab_ap * t26 - T(3) * t16 * t27 - T(6) * ap_ap * t16 * t24;
    const T t29 = delta_tau * delta_tau;
    const T t30 = T(8) * t18 + t16 * ab_ap * t27 - T(8) * t21;
    const T t31 = T(3) * t30 * t16 + T(2) * ap_ap * t16 * t26 - T(2) * t28 * t16 * ab_ap;
    const T t32 = t29 * t29;
    const T t33 = t29 * delta_tau;
    F = (T(1) / T(4)) * t15 * t16 * t24 + (T(1) / T(3)) * delta_tau * t25 * t16 * t26 + (T(1) / T(4)) * t28 * t29 * t14 * t16 + (T(1) / T(24)) * (T(3) * t16 * (T(8) * J1 + ap_ap * t16 * t27 - T(2) * t30 * t16 * ab_ap) - T(2) * t16 * ab_ap * t31 - t28 * ap_ap * t16) * t32 * t16 - (T(1) / T(6)) * t33 * tau_lo * t16 * t31;
    const T t34 = t18 * t20 - T(5) * ab_ap * t17 - t23 * t21;
    const T t35 = T(8) * t16 * ab_ap * t34 + T(20) * ap_ap * t17 - T(5) * t16 * t24;
    const T t36 = T(6) * t16 * ab_ap * t35 - T(5) * t16 * t26 - T(12) * ap_ap * t16 * t34;
    const T t37 = T(5) * t28 * t16 + T(6) * ap_ap * t16 * t35 - T(4) * t16 * ab_ap * t36;
    G_ap = t15 * t17 + (T(1) / T(120)) * t32 * t16 * t37 - (T(4) / T(5)) * delta_tau * t25 * t16 * t34 - (T(3) / T(10)) * t29 * t14 * t16 * t35 - (T(1) / T(15)) * t33 * tau_lo * t16 * t36;
    G_ab = (T(1) / T(30)) * t33 * tau_lo * t16 * t37 + (T(1) / T(120)) * t32 * (T(2) * t16 * ab_ap * t37 + T(2) * ap_ap * t16 * t36 - T(5) * t16 * t31) * t16 - (T(1) / T(5)) * t15 * t16 * t34 - (T(1) / T(5)) * delta_tau * t25 * t16 * t35 - (T(1) / T(10)) * t29 * t14 * t16 * t36;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / ab_ab;
    const T t39 = T(1) / r0;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r1;
    const T t42 = t41 * t41;
    const T t43 = T(1) / cross_cross;
    const T t44 = t39 * ab_ap + t41 * a_minus_b;
    const T t45 = t40 * t39 * ab_ap + t41 * t42 * a_minus_b + T(2) * t43 * ab_ab * t44;
    const T t46 = t40 * t39 + t45 * t43 * ab_ap - t41 * t42;
    const T t47 = T(2) * t38 * t46 * ab_ap + T(3) * t43 * t44 - ap_ap * t45 * t43;
    const T t48 = delta_tau * delta_tau;
    const T t49 = tau_lo * tau_lo;
    const T t50 = t49 * t49;
    const T t51 = t49 * tau_lo;
    const T t52 = t48 * delta_tau;
    const T t53 = t41 - t39 - t43 * t44 * ab_ap;
    const T t54 = ap_ap * t38 * t46 + T(3) * t38 * t53 - T(2) * t47 * t38 * ab_ap;
    const T t55 = t48 * t48;
    F = T(2) * t47 * t48 * t49 * t38 + (T(1) / T(3)) * t45 * t43 * t50 + (T(4) / T(3)) * delta_tau * t51 * t38 * t46 - (T(4) / T(3)) * t52 * tau_lo * t38 * t54 - (T(1) / T(3)) * (T(3) * (ap_ap * t43 * t44 + T(2) * t38 * t53 * ab_ap - J1) * t38 + T(2) * t38 * t54 * ab_ap + ap_ap * t47 * t38) * t55 * t38;
    const T t56 = t42 * t42;
    const T t57 = t40 * t40;
    const T t58 = T(4) * t45 * t43 * ab_ab + T(3) * t41 * t56 * a_minus_b + T(3) * t57 * t39 * ab_ap;
    const T t59 = T(3) * t41 * t56 - t43 * ab_ap * t58 - T(3) * t57 * t39;
    const T t60 = ap_ap * t43 * t58 + T(2) * t38 * ab_ap * t59 - T(5) * t45 * t43;
    const T t61 = T(5) * t38 * t46 + ap_ap * t38 * t59 - T(2) * t38 * t60 * ab_ap;
    const T t62 = T(5) * t47 * t38 + ap_ap * t38 * t60 + T(2) * t61 * t38 * ab_ap;
    G_ap = (T(1) / T(15)) * t55 * t38 * t62 + (T(1) / T(15)) * t43 * t50 * t58 + (T(4) / T(15)) * t61 * t52 * tau_lo * t38 - (T(4) / T(15)) * delta_tau * t51 * t38 * t59 - (T(2) / T(5)) * t48 * t49 * t38 * t60;
    G_ab = (T(4) / T(15)) * t52 * tau_lo * t38 * t62 + (T(2) / T(5)) * t61 * t48 * t49 * t38 - (T(1) / T(15)) * (T(5) * t38 * t54 + ap_ap * t61 * t38 - T(2) * t38 * t62 * ab_ap) * t55 * t38 - (T(1) / T(15)) * t50 * t38 * t59 - (T(4) / T(15)) * delta_tau * t51 * t38 * t60;
  }
  const T t63 = in.sigma * in.sigma;
  const T t64 = t63 * t63;
  const T t65 = t64 * in.sigma;
  const T g_factor = -T(5) * t65 * length;
  f = t65 * length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 55 +, 129 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 216 +, 368 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i6_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 5, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t4 * t4;
    const T t8 = t7 * delta_tau;
    const T t9 = t6 * tau_lo;
    const T t10 = t6 * t6;
    const T t11 = t10 * tau_lo;
    F = T(10) * t5 * t6 * M_flat[3] + T(5) * M_flat[4] * t7 * tau_lo + t8 * M_flat[5] + T(10) * t4 * t9 * M_flat[2] + t11 * M_flat[0] + T(5) * M_flat[1] * delta_tau * t10;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t12 = J_downward<T>(6, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = T(1) / ab_ab;
    const T t20 = t0 * t0;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = ab_ap * t20 + a_minus_b * t22 - T(4) * t12 * cross_cross;
    const T t24 = t22 - T(4) * t12 * ab_ap - t20;
    const T t25 = T(2) * t23 * t19 + T(6) * t12 * ap_ap + T(3) * t19 * t24 * ab_ap;
    const T t26 = T(3) * t0 - T(3) * t21 - T(2) * t23 * t19 * ab_ap;
    const T t27 = T(2) * t23 * cross_cross * t19 + T(3) * a_minus_b * t21 + T(3) * ab_ap * t0;
    const T t28 = t19 * t26 * ab_ap + t23 * t19 * ap_ap - t19 * t27;
    const T t29 = T(3) * t19 * t24 * ap_ap + T(2) * t19 * t26 - T(4) * t19 * ab_ap * t25;
    const T t30 = t19 * t25 * ap_ap + T(2) * t19 * t28 + t19 * ab_ap * t29;
    const T t31 = t16 * delta_tau;
    const T t32 = t13 * tau_lo;
    F = t12 * t15 + (T(1) / T(12)) * t18 * t19 * (T(4) * t30 * t19 * ab_ap + T(2) * (T(4) * t19 * ab_ap * t28 - t19 * t26 * ap_ap - (T(2) * t19 * t27 * ab_ap - T(3) * log_ratio) * t19) * t19 - t19 * t29 * ap_ap) + (T(5) / T(6)) * t17 * tau_lo * t30 * t19 + (T(5) / T(6)) * t31 * t13 * t19 * t29 - (T(5) / T(3)) * t16 * t32 * t19 * t25 - (T(5) / T(4)) * delta_tau * t14 * t19 * t24;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t33 = sqrt(cross_cross);
    const T t34 = T(1) / t33;
    const T J2 = atan2(t33, ap_bp) * t34;
    const T t35 = T(1) / ab_ab;
    const T t36 = T(1) / bp_bp;
    const T t37 = t36 * t36;
    const T t38 = t0 * t0;
    const T t39 = T(1) / cross_cross;
    const T t40 = a_minus_b * t36 + ab_ap * t0 + J2 * ab_ab;
    const T t41 = T(2) * ab_ap * t38 + T(3) * t39 * ab_ab * t40 + T(2) * a_minus_b * t37;
    const T t42 = T(2) * t37 - T(2) * t38 - t39 * t41 * ab_ap;
    const T t43 = t0 + t39 * ab_ap * t40 - t36;
    const T t44 = t39 * t41 * ap_ap + T(2) * t35 * t42 * ab_ap - T(4) * t39 * t40;
    const T t45 = t35 * t42 * ap_ap + T(4) * t43 * t35 - T(2) * t44 * t35 * ab_ap;
    const T t46 = delta_tau * delta_tau;
    const T t47 = t46 * delta_tau;
    const T t48 = tau_lo * tau_lo;
    const T t49 = t48 * t48;
    const T t50 = t49 * tau_lo;
    const T t51 = t46 * t46;
    const T t52 = T(2) * J2 + T(2) * t43 * t35 * ab_ap - t39 * ap_ap * t40;
    const T t53 = T(4) * t35 * t52 + t44 * t35 * ap_ap + T(2) * t45 * t35 * ab_ap;
    const T t54 = t48 * tau_lo;
    const T t55 = t51 * delta_tau;
    F = (T(5) / T(4)) * t45 * t47 * t48 * t35 + (T(1) / T(8)) * t39 * t50 * t41 + (T(5) / T(8)) * t51 * tau_lo * t35 * t53 - (T(5) / T(4)) * t44 * t46 * t54 * t35 - (T(1) / T(8)) * t55 * (t45 * t35 * ap_ap + T(4) * t35 * (t43 * t35 * ap_ap - (T(2) * J2 * ab_ap + log_ratio) * t35 - T(2) * t35 * ab_ap * t52) - T(2) * t35 * ab_ap * t53) * t35 - (T(5) / T(8)) * delta_tau * t49 * t35 * t42;
  }
  const T t56 = in.sigma * in.sigma;
  const T t57 = t56 * in.sigma;
  const T t58 = t57 * t57;
  f = length * F * t58;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 192 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 244 +, 431 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i6_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 6, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * t3;
    const T t5 = delta_tau * delta_tau;
    const T t6 = t5 * delta_tau;
    const T t7 = t5 * t5;
    const T t8 = t7 * delta_tau;
    const T t9 = t3 * tau_lo;
    const T t10 = t4 * tau_lo;
    G_ap = T(5) * delta_tau * t4 * M_flat[1] + T(10) * M_flat[3] * t6 * t3 + T(5) * t7 * tau_lo * M_flat[4] + t8 * M_flat[5] + T(10) * t5 * t9 * M_flat[2] + M_flat[0] * t10;
    G_ab = T(5) * t7 * tau_lo * M_flat[5] + t10 * M_flat[1] + T(10) * M_flat[3] * t5 * t9 + M_flat[6] * t8 + T(10) * t6 * t3 * M_flat[4] + T(5) * delta_tau * t4 * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 7> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 6, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t11 * delta_tau;
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t12 * delta_tau;
    const T t17 = t14 * tau_lo;
    const T t18 = t15 * tau_lo;
    G_ap = T(5) * t12 * tau_lo * M_beyond[4] + T(10) * t13 * t14 * M_beyond[3] + T(5) * delta_tau * t15 * M_beyond[1] + M_beyond[5] * t16 + T(10) * M_beyond[2] * t11 * t17 + t18 * M_beyond[0];
    G_ab = T(10) * t13 * t14 * M_beyond[4] + T(5) * M_beyond[5] * t12 * tau_lo + t18 * M_beyond[1] + T(5) * M_beyond[2] * delta_tau * t15 + T(10) * t11 * t17 * M_beyond[3] + t16 * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, ap_bp);
    const T t21 = T(1) / cross_cross;
    const T t22 = T(1) / ap_ap;
    const T t23 = t22 * t22;
    const T t24 = T(1) / bp_bp;
    const T t25 = ab_ab * J2 + a_minus_b * t24 + t22 * ab_ap;
    const T t26 = t24 * t24;
    const T t27 = T(2) * t23 * ab_ap + T(3) * t21 * t25 * ab_ab + T(2) * a_minus_b * t26;
    const T t28 = t23 * t22;
    const T t29 = t26 * t24;
    const T t30 = T(8) * t28 * ab_ap + T(5) * t21 * ab_ab * t27 + T(8) * a_minus_b * t29;
    const T t31 = T(8) * t28 + t21 * t30 * ab_ap - T(8) * t29;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(6) * t21 * t27 + T(2) * t31 * t32 * ab_ap - ap_ap * t21 * t30;
    const T t34 = delta_tau * delta_tau;
    const T t35 = tau_lo * tau_lo;
    const T t36 = t35 * tau_lo;
    const T t37 = t35 * t35;
    const T t38 = t37 * tau_lo;
    const T t39 = t34 * t34;
    const T t40 = T(2) * t23 + t21 * t27 * ab_ap - T(2) * t26;
    const T t41 = ap_ap * t31 * t32 - T(6) * t32 * t40 - T(2) * t33 * t32 * ab_ap;
    const T t42 = T(2) * t32 * t40 * ab_ap + T(4) * t21 * t25 - ap_ap * t21 * t27;
    const T t43 = T(2) * t32 * t41 * ab_ap + t33 * ap_ap * t32 - T(6) * t32 * t42;
    const T t44 = t34 * delta_tau;
    const T t45 = t21 * t25 * ab_ap + t22 - t24;
    const T t46 = T(4) * t32 * t45 + T(2) * t32 * t42 * ab_ap - ap_ap * t32 * t40;
    const T t47 = T(2) * t43 * t32 * ab_ap - ap_ap * t32 * t41 - T(6) * t46 * t32;
    const T t48 = t39 * delta_tau;
    G_ap = (T(5) / T(24)) * t33 * t34 * t36 * t32 + (T(5) / T(48)) * delta_tau * t37 * t31 * t32 + (T(1) / T(48)) * t38 * t21 * t30 - (T(5) / T(48)) * t39 * t43 * tau_lo * t32 - (T(5) / T(24)) * t44 * t35 * t32 * t41 - (T(1) / T(48)) * t47 * t48 * t32;
    G_ab = (T(5) / T(48)) * t33 * delta_tau * t37 * t32 + (T(1) / T(48)) * (ap_ap * t43 * t32 + T(6) * (T(2) * t46 * t32 * ab_ap - ap_ap * t32 * t42 - T(4) * t32 * (ap_ap * t21 * t25 - T(2) * t32 * ab_ap * t45 - T(2) * J2)) * t32 - T(2) * t47 * t32 * ab_ap) * t48 * t32 + (T(1) / T(48)) * t38 * t31 * t32 - (T(5) / T(24)) * t44 * t43 * t35 * t32 - (T(5) / T(48)) * t47 * t39 * tau_lo * t32 - (T(5) / T(24)) * t34 * t36 * t32 * t41;
  }
  const T t49 = in.sigma * in.sigma;
  const T t50 = t49 * in.sigma;
  const T t51 = t50 * t50;
  const T g_factor = -T(6) * length * t51;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 82 +, 232 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 389 +, 635 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i6_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 14> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 6, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * t4;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t4 * delta_tau;
    const T t10 = t6 * tau_lo;
    const T t11 = t5 * delta_tau;
    F = T(5) * M_flat[4] * t5 * tau_lo + T(5) * M_flat[1] * delta_tau * t7 + t8 * M_flat[0] + T(10) * t9 * t6 * M_flat[3] + T(10) * M_flat[2] * t4 * t10 + M_flat[5] * t11;
    G_ap = T(5) * M_flat[8] * delta_tau * t7 + t8 * M_flat[7] + T(10) * t9 * t6 * M_flat[10] + t11 * M_flat[12] + T(5) * M_flat[11] * t5 * tau_lo + T(10) * M_flat[9] * t4 * t10;
    G_ab = M_flat[8] * t8 + T(5) * t5 * M_flat[12] * tau_lo + T(5) * M_flat[9] * delta_tau * t7 + T(10) * t4 * t10 * M_flat[10] + t11 * M_flat[13] + T(10) * M_flat[11] * t9 * t6;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t0 * t0;
    const T t16 = t15 * t0;
    const T t17 = J_downward<T>(8, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t18 = a_minus_b * t14 + ab_ap * t16 - T(6) * cross_cross * t17;
    const T t19 = T(1) / ab_ab;
    const T t20 = T(4) * ab_ap * t18 * t19 + T(5) * t13 - T(5) * t15;
    const T t21 = T(5) * a_minus_b * t13 + T(4) * t18 * cross_cross * t19 + T(5) * ab_ap * t15;
    const T t22 = T(6) * t18 * ap_ap * t19 - T(3) * ab_ap * t20 * t19 - T(2) * t21 * t19;
    const T t23 = delta_tau * delta_tau;
    const T t24 = tau_lo * tau_lo;
    const T t25 = t24 * tau_lo;
    const T t26 = t24 * t24;
    const T t27 = t26 * tau_lo;
    const T t28 = T(2) * ab_ap * t21 * t19 + T(15) * t12 - T(15) * t0;
    const T t29 = T(2) * t19 * t28 - T(4) * ab_ap * t22 * t19 - T(3) * ap_ap * t20 * t19;
    const T t30 = T(2) * t21 * cross_cross * t19 + T(15) * ab_ap * t0 + T(15) * a_minus_b * t12;
    const T t31 = ap_ap * t21 * t19 - ab_ap * t19 * t28 - t30 * t19;
    const T t32 = t29 * ab_ap * t19 + ap_ap * t22 * t19 - T(2) * t31 * t19;
    const T t33 = t23 * t23;
    const T t34 = t33 * delta_tau;
    const T t35 = t23 * delta_tau;
    F = (T(1) / T(3)) * t22 * t23 * t25 * t19 - (T(1) / T(5)) * t18 * t27 * t19 - (T(1) / T(4)) * t20 * delta_tau * t26 * t19 - (T(1) / T(6)) * t32 * t33 * tau_lo * t19 - (T(1) / T(60)) * t34 * (T(4) * ab_ap * t32 * t19 - t29 * ap_ap * t19 - T(2) * (ap_ap * t19 * t28 + T(4) * t31 * ab_ap * t19 - (T(2) * ab_ap * t30 * t19 - T(15) * log_ratio) * t19) * t19) * t19 - (T(1) / T(6)) * t29 * t35 * t24 * t19;
    const T t36 = T(6) * ab_ap * t17 + t16 - t14;
    const T t37 = T(5) * ab_ap * t36 * t19 - T(3) * t18 * t19 - T(15) * ap_ap * t17;
    const T t38 = T(10) * t36 * ap_ap * t19 + T(3) * t20 * t19 - T(8) * ab_ap * t19 * t37;
    const T t39 = T(2) * ap_ap * t19 * t37 + ab_ap * t19 * t38 - t22 * t19;
    const T t40 = t29 * t19 + T(4) * ab_ap * t19 * t39 - ap_ap * t19 * t38;
    G_ap = (T(2) / T(3)) * t23 * t25 * t19 * t37 + t27 * t17 + (T(5) / T(6)) * t36 * delta_tau * t26 * t19 - (T(1) / T(6)) * t33 * tau_lo * t19 * t39 - (T(1) / T(6)) * t35 * t24 * t19 * t38 - (T(1) / T(60)) * t40 * t34 * t19;
    G_ab = (T(1) / T(30)) * t34 * (ap_ap * t19 * t39 - ab_ap * t40 * t19 - t32 * t19) * t19 + (T(1) / T(6)) * t36 * t27 * t19 + (T(1) / T(3)) * delta_tau * t26 * t19 * t37 - (T(1) / T(6)) * t23 * t25 * t19 * t38 - (T(1) / T(3)) * t35 * t24 * t19 * t39 - (T(1) / T(12)) * t40 * t33 * tau_lo * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t41 = sqrt(cross_cross);
    const T t42 = T(1) / t41;
    const T J2 = atan2(t41, ap_bp) * t42;
    const T t43 = T(1) / bp_bp;
    const T t44 = J2 * ab_ab + ab_ap * t0 + a_minus_b * t43;
    const T t45 = T(1) / cross_cross;
    const T t46 = t43 * t43;
    const T t47 = t0 * t0;
    const T t48 = T(3) * t44 * t45 * ab_ab + T(2) * a_minus_b * t46 + T(2) * ab_ap * t47;
    const T t49 = tau_lo * tau_lo;
    const T t50 = t49 * t49;
    const T t51 = t50 * tau_lo;
    const T t52 = T(1) / ab_ab;
    const T t53 = t43 - t0 - ab_ap * t44 * t45;
    const T t54 = T(2) * J2 - t44 * ap_ap * t45 - T(2) * ab_ap * t53 * t52;
    const T t55 = t48 * ab_ap * t45 + T(2) * t47 - T(2) * t46;
    const T t56 = T(4) * t44 * t45 + T(2) * ab_ap * t55 * t52 - t48 * ap_ap * t45;
    const T t57 = T(4) * t53 * t52 + ap_ap * t55 * t52 - T(2) * ab_ap * t56 * t52;
    const T t58 = T(4) * t52 * t54 - t56 * ap_ap * t52 - T(2) * ab_ap * t57 * t52;
    const T t59 = delta_tau * delta_tau;
    const T t60 = t59 * t59;
    const T t61 = t60 * delta_tau;
    const T t62 = t49 * tau_lo;
    const T t63 = t59 * delta_tau;
    F = (T(1) / T(8)) * t48 * t45 * t51 + (T(5) / T(8)) * t58 * t60 * tau_lo * t52 + (T(1) / T(8)) * (T(4) * (t52 * (T(2) * ab_ap * J2 + log_ratio) + T(2) * ab_ap * t52 * t54 + t53 * ap_ap * t52) * t52 + ap_ap * t57 * t52 + T(2) * ab_ap * t58 * t52) * t61 * t52 + (T(5) / T(8)) * t55 * delta_tau * t50 * t52 + (T(5) / T(4)) * t56 * t59 * t62 * t52 - (T(5) / T(4)) * t63 * t49 * t57 * t52;
    const T t64 = t46 * t43;
    const T t65 = t47 * t0;
    const T t66 = T(5) * t48 * t45 * ab_ab + T(8) * a_minus_b * t64 + T(8) * ab_ap * t65;
    const T t67 = ab_ap * t66 * t45 + T(8) * t65 - T(8) * t64;
    const T t68 = t66 * ap_ap * t45 - T(2) * ab_ap * t52 * t67 - T(6) * t48 * t45;
    const T t69 = ap_ap * t52 * t67 + T(2) * ab_ap * t68 * t52 - T(6) * t55 * t52;
    const T t70 = T(2) * ab_ap * t69 * t52 - t68 * ap_ap * t52 - T(6) * t56 * t52;
    const T t71 = T(2) * t70 * ab_ap * t52 + T(6) * t57 * t52 - ap_ap * t69 * t52;
    G_ap = (T(5) / T(48)) * delta_tau * t50 * t52 * t67 + (T(1) / T(48)) * t66 * t45 * t51 - (T(1) / T(48)) * t61 * t71 * t52 - (T(5) / T(24)) * t63 * t49 * t69 * t52 - (T(5) / T(24)) * t68 * t59 * t62 * t52 - (T(5) / T(48)) * t70 * t60 * tau_lo * t52;
    G_ab = (T(1) / T(48)) * t51 * t52 * t67 - (T(1) / T(48)) * (T(2) * ab_ap * t71 * t52 - T(6) * t58 * t52 - t70 * ap_ap * t52) * t61 * t52 - (T(5) / T(48)) * t68 * delta_tau * t50 * t52 - (T(5) / T(24)) * t59 * t62 * t69 * t52 - (T(5) / T(48)) * t60 * t71 * tau_lo * t52 - (T(5) / T(24)) * t70 * t63 * t49 * t52;
  }
  const T t72 = in.sigma * in.sigma;
  const T t73 = t72 * in.sigma;
  const T t74 = t73 * t73;
  const T g_factor = -T(6) * t74 * length;
  f = F * t74 * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 63 +, 170 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 236 +, 477 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i7_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = a_minus_b * r0;
    X = t1 * (t2 + ab_ap * r1) * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 6, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t8 * t8;
    const T t12 = t11 * delta_tau;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = t13 * tau_lo;
    const T t17 = t16 * t16;
    F = t10 * M_flat[6] + T(6) * t12 * tau_lo * M_flat[5] + T(6) * M_flat[1] * delta_tau * t15 + T(15) * M_flat[4] * t11 * t13 + T(15) * t8 * t14 * M_flat[2] + t17 * M_flat[0] + T(20) * t9 * t16 * M_flat[3];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t18 = delta_tau * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t19 * delta_tau;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = -ab_ap;
    const T t29 = J_downward<T>(7, ab_ab, cross_cross, t28, ap_ap, a_minus_b, bp_bp);
    const T t30 = a_minus_b * t24 * t22 + t27 * t25 * ab_ap - T(5) * t29 * cross_cross;
    const T t31 = T(4) * t26 * t25 - T(3) * t21 * t30 * ab_ap - T(4) * t23 * t22;
    const T t32 = T(3) * cross_cross * t21 * t30 + T(4) * t26 * t25 * ab_ap + T(4) * a_minus_b * t23 * t22;
    const T t33 = T(6) * ap_ap * t21 * t30 + T(4) * t21 * ab_ap * t31 - T(3) * t21 * t32;
    const T t34 = T(8) * t22 + t21 * t32 * ab_ap - T(8) * t25;
    const T t35 = T(2) * t33 * t21 * ab_ap - T(3) * t34 * t21 - T(2) * ap_ap * t21 * t31;
    const T t36 = t24 * t22 - T(5) * t29 * ab_ap - t27 * t25;
    const T t37 = T(5) * t21 * t30 + T(20) * t29 * ap_ap + T(8) * t21 * ab_ap * t36;
    const T t38 = T(6) * t21 * t37 * ab_ap - T(12) * ap_ap * t21 * t36 - T(5) * t21 * t31;
    const T t39 = T(5) * t33 * t21 + T(6) * ap_ap * t21 * t37 - T(4) * t38 * t21 * ab_ap;
    const T t40 = T(5) * t21 * t35 + T(2) * ap_ap * t38 * t21 + T(2) * t39 * t21 * ab_ap;
    const T t41 = tau_lo * tau_lo;
    const T t42 = t18 * delta_tau;
    const T t43 = t42 * t42;
    const T t44 = t41 * tau_lo;
    const T t45 = t44 * t44;
    const T t46 = t41 * t41;
    const T t47 = t46 * tau_lo;
    F = (T(1) / T(20)) * t20 * tau_lo * t40 * t21 + (T(1) / T(8)) * t19 * t41 * t39 * t21 + (T(1) / T(120)) * t43 * t21 * (T(5) * t21 * (T(2) * t21 * t35 * ab_ap - ap_ap * t33 * t21 - T(3) * (T(2) * t34 * t21 * ab_ap - T(8) * J1 - ap_ap * t21 * t32) * t21) + T(2) * t40 * t21 * ab_ap - ap_ap * t39 * t21) + t29 * t45 - (T(1) / T(3)) * t42 * t44 * t38 * t21 - (T(3) / T(4)) * t18 * t46 * t21 * t37 - (T(6) / T(5)) * delta_tau * t47 * t21 * t36;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = tau_lo * tau_lo;
    const T t49 = t48 * t48;
    const T t50 = t49 * tau_lo;
    const T t51 = T(1) / cross_cross;
    const T t52 = T(1) / r1;
    const T t53 = T(1) / r0;
    const T t54 = a_minus_b * t52 + t53 * ab_ap;
    const T t55 = t53 * t53;
    const T t56 = t52 * t52;
    const T t57 = T(2) * t51 * ab_ab * t54 + t55 * t53 * ab_ap + a_minus_b * t56 * t52;
    const T t58 = t56 * t56;
    const T t59 = t55 * t55;
    const T t60 = T(4) * t57 * t51 * ab_ab + T(3) * a_minus_b * t58 * t52 + T(3) * t59 * t53 * ab_ap;
    const T t61 = t51 * ab_ap * t60 + T(3) * t59 * t53 - T(3) * t58 * t52;
    const T t62 = T(1) / ab_ab;
    const T t63 = delta_tau * delta_tau;
    const T t64 = t63 * t63;
    const T t65 = t64 * delta_tau;
    const T t66 = ap_ap * t51 * t60 - T(5) * t57 * t51 - T(2) * t61 * t62 * ab_ap;
    const T t67 = t55 * t53 + t57 * t51 * ab_ap - t56 * t52;
    const T t68 = ap_ap * t61 * t62 + T(2) * t66 * t62 * ab_ap - T(5) * t62 * t67;
    const T t69 = T(3) * t51 * t54 + T(2) * t62 * ab_ap * t67 - ap_ap * t57 * t51;
    const T t70 = t52 - t51 * ab_ap * t54 - t53;
    const T t71 = T(2) * t62 * ab_ap * t69 - T(3) * t62 * t70 - ap_ap * t62 * t67;
    const T t72 = T(2) * t62 * t68 * ab_ap - T(5) * t62 * t69 - ap_ap * t66 * t62;
    const T t73 = ap_ap * t62 * t68 + T(5) * t71 * t62 - T(2) * t62 * t72 * ab_ap;
    const T t74 = t48 * tau_lo;
    const T t75 = t74 * t74;
    const T t76 = t63 * delta_tau;
    const T t77 = t76 * t76;
    F = (T(2) / T(5)) * delta_tau * t50 * t61 * t62 + (T(2) / T(5)) * t65 * tau_lo * t62 * t73 + (T(1) / T(15)) * t75 * t51 * t60 + (T(1) / T(15)) * t77 * t62 * (T(2) * t62 * ab_ap * t73 + ap_ap * t62 * t72 + T(5) * t62 * (T(2) * t71 * t62 * ab_ap - T(3) * t62 * (ap_ap * t51 * t54 + T(2) * t62 * ab_ap * t70 - J1) - ap_ap * t62 * t69)) - t63 * t49 * t66 * t62 - t64 * t48 * t62 * t72 - (T(4) / T(3)) * t76 * t74 * t62 * t68;
  }
  const T t78 = in.sigma * in.sigma;
  const T t79 = t78 * in.sigma;
  const T t80 = t79 * t79;
  const T t81 = t80 * in.sigma;
  f = length * t81 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 81 +, 243 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 264 +, 558 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i7_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 7, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = t3 * t3;
    const T t7 = t6 * tau_lo;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t8 * t8;
    const T t12 = t11 * delta_tau;
    G_ap = M_flat[0] * t5 + T(6) * t7 * delta_tau * M_flat[1] + M_flat[6] * t10 + T(20) * M_flat[3] * t4 * t9 + T(15) * M_flat[2] * t6 * t8 + T(15) * t3 * t11 * M_flat[4] + T(6) * M_flat[5] * tau_lo * t12;
    G_ab = T(15) * M_flat[5] * t3 * t11 + T(6) * M_flat[6] * tau_lo * t12 + T(15) * M_flat[3] * t6 * t8 + T(6) * M_flat[2] * t7 * delta_tau + T(20) * t4 * t9 * M_flat[4] + t5 * M_flat[1] + t10 * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 7, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * delta_tau;
    const T t18 = t17 * t17;
    const T t19 = t16 * t16;
    const T t20 = t19 * delta_tau;
    const T t21 = t13 * tau_lo;
    const T t22 = t21 * t21;
    G_ap = T(6) * M_beyond[1] * t15 * delta_tau + t18 * M_beyond[6] + T(15) * t14 * M_beyond[2] * t16 + T(6) * M_beyond[5] * tau_lo * t20 + T(20) * t21 * t17 * M_beyond[3] + T(15) * M_beyond[4] * t13 * t19 + M_beyond[0] * t22;
    G_ab = T(15) * M_beyond[5] * t13 * t19 + T(6) * tau_lo * t20 * M_beyond[6] + M_beyond[7] * t18 + T(6) * t15 * M_beyond[2] * delta_tau + T(20) * M_beyond[4] * t21 * t17 + T(15) * t14 * t16 * M_beyond[3] + M_beyond[1] * t22;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = T(1) / cross_cross;
    const T t32 = t23 * a_minus_b + ab_ap * t27;
    const T t33 = t24 * t23 * a_minus_b + T(2) * t32 * t31 * ab_ab + ab_ap * t27 * t28;
    const T t34 = T(4) * t31 * ab_ab * t33 + T(3) * ab_ap * t27 * t29 + T(3) * t25 * t23 * a_minus_b;
    const T t35 = T(5) * t26 * t23 * a_minus_b + T(5) * ab_ap * t27 * t30 + T(2) * t31 * ab_ab * t34;
    const T t36 = ab_ap * t35 * t31 + T(5) * t27 * t30 - T(5) * t26 * t23;
    const T t37 = T(1) / ab_ab;
    const T t38 = T(6) * ab_ap * t36 * t37 + T(7) * t31 * t34 - T(3) * t35 * ap_ap * t31;
    const T t39 = tau_lo * tau_lo;
    const T t40 = t39 * t39;
    const T t41 = delta_tau * delta_tau;
    const T t42 = t39 * tau_lo;
    const T t43 = t41 * delta_tau;
    const T t44 = ab_ap * t31 * t34 + T(3) * t27 * t29 - T(3) * t25 * t23;
    const T t45 = T(2) * ab_ap * t38 * t37 + T(7) * t44 * t37 - T(3) * ap_ap * t36 * t37;
    const T t46 = t42 * t42;
    const T t47 = T(2) * t44 * ab_ap * t37 + T(5) * t31 * t33 - ap_ap * t31 * t34;
    const T t48 = T(7) * t37 * t47 + T(2) * ab_ap * t37 * t45 - t38 * ap_ap * t37;
    const T t49 = t41 * t41;
    const T t50 = t40 * tau_lo;
    const T t51 = ab_ap * t31 * t33 + t27 * t28 - t24 * t23;
    const T t52 = T(5) * t51 * t37 + T(2) * ab_ap * t37 * t47 - t44 * ap_ap * t37;
    const T t53 = ap_ap * t37 * t45 - T(2) * ab_ap * t48 * t37 - T(7) * t52 * t37;
    const T t54 = t49 * delta_tau;
    const T t55 = T(2) * ab_ap * t51 * t37 + T(3) * t32 * t31 - ap_ap * t31 * t33;
    const T t56 = ap_ap * t37 * t47 - T(2) * ab_ap * t52 * t37 - T(5) * t37 * t55;
    const T t57 = T(7) * t56 * t37 + T(2) * ab_ap * t53 * t37 + t48 * ap_ap * t37;
    const T t58 = t43 * t43;
    G_ap = (T(1) / T(7)) * t38 * t40 * t41 * t37 + (T(4) / T(21)) * t42 * t43 * t37 * t45 + (T(1) / T(35)) * t35 * t46 * t31 + (T(1) / T(7)) * t48 * t39 * t49 * t37 + (T(6) / T(35)) * t50 * delta_tau * t36 * t37 - (T(2) / T(35)) * t53 * tau_lo * t54 * t37 - (T(1) / T(105)) * t57 * t58 * t37;
    G_ab = (T(1) / T(7)) * t40 * t41 * t37 * t45 + (T(4) / T(21)) * t48 * t42 * t43 * t37 + (T(1) / T(35)) * t46 * t36 * t37 + (T(2) / T(35)) * t38 * t50 * delta_tau * t37 - (T(1) / T(105)) * (T(2) * ab_ap * t57 * t37 + T(7) * (t52 * ap_ap * t37 + T(5) * t37 * (t51 * ap_ap * t37 - T(2) * ab_ap * t37 * t55 - T(3) * (ab_ap * t32 * t31 + t27 - t23) * t37) + T(2) * t56 * ab_ap * t37) * t37 - t53 * ap_ap * t37) * t58 * t37 - (T(2) / T(35)) * t57 * tau_lo * t54 * t37 - (T(1) / T(7)) * t53 * t39 * t49 * t37;
  }
  const T t59 = in.sigma * in.sigma;
  const T t60 = t59 * in.sigma;
  const T t61 = t60 * t60;
  const T t62 = t61 * in.sigma;
  const T g_factor = -T(7) * t62 * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 294 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 431 +, 791 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i7_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * length * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 16> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 7, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t8 * t8;
    const T t12 = t8 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t10 * tau_lo;
    const T t15 = t11 * delta_tau;
    const T t16 = t9 * tau_lo;
    const T t17 = t16 * t16;
    F = T(15) * M_flat[2] * t8 * t10 + T(15) * M_flat[4] * t11 * t9 + t13 * M_flat[6] + T(6) * M_flat[1] * delta_tau * t14 + T(6) * M_flat[5] * t15 * tau_lo + T(20) * t12 * t16 * M_flat[3] + t17 * M_flat[0];
    G_ap = T(15) * t8 * t10 * M_flat[10] + M_flat[8] * t17 + T(6) * t15 * tau_lo * M_flat[13] + T(15) * M_flat[12] * t11 * t9 + M_flat[14] * t13 + T(6) * delta_tau * M_flat[9] * t14 + T(20) * M_flat[11] * t12 * t16;
    G_ab = M_flat[15] * t13 + T(15) * M_flat[11] * t8 * t10 + T(20) * M_flat[12] * t12 * t16 + M_flat[9] * t17 + T(6) * M_flat[14] * t15 * tau_lo + T(15) * t11 * t9 * M_flat[13] + T(6) * delta_tau * t14 * M_flat[10];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t18 = delta_tau * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = tau_lo * tau_lo;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / r0;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = -ab_ap;
    const T t31 = J_downward<T>(9, ab_ab, cross_cross, t30, ap_ap, a_minus_b, bp_bp);
    const T t32 = t25 * t22 * ab_ap + a_minus_b * t26 * t29 - T(7) * t31 * cross_cross;
    const T t33 = T(5) * t32 * t21 * ab_ap + T(6) * t26 * t28 - T(6) * t24 * t22;
    const T t34 = T(6) * a_minus_b * t26 * t28 + T(5) * t32 * t21 * cross_cross + T(6) * t24 * t22 * ab_ap;
    const T t35 = T(8) * t23 * t22 - T(8) * t26 * t27 - t21 * ab_ap * t34;
    const T t36 = T(20) * t32 * ap_ap * t21 - T(5) * t21 * t34 - T(8) * t21 * t33 * ab_ap;
    const T t37 = T(4) * ap_ap * t21 * t33 + T(5) * t35 * t21 + T(2) * t21 * ab_ap * t36;
    const T t38 = T(8) * t23 * t22 * ab_ap + t21 * cross_cross * t34 + T(8) * a_minus_b * t26 * t27;
    const T t39 = T(4) * t35 * t21 * ab_ap + T(2) * ap_ap * t21 * t34 - T(3) * t38 * t21;
    const T t40 = T(4) * t37 * t21 * ab_ap + T(5) * t39 * t21 - T(2) * ap_ap * t21 * t36;
    const T t41 = t18 * delta_tau;
    const T t42 = t20 * tau_lo;
    const T t43 = t20 * t20;
    const T t44 = t41 * t41;
    const T t45 = T(16) * t22 - t38 * t21 * ab_ap - T(16) * t26;
    const T t46 = T(2) * t39 * t21 * ab_ap + T(3) * t21 * t45 - T(2) * ap_ap * t35 * t21;
    const T t47 = T(2) * ap_ap * t37 * t21 - T(2) * t21 * t40 * ab_ap - T(5) * t46 * t21;
    const T t48 = t43 * tau_lo;
    const T t49 = t19 * delta_tau;
    const T t50 = t42 * t42;
    F = (T(1) / T(16)) * t19 * t20 * t21 * t40 + (T(1) / T(6)) * t41 * t37 * t42 * t21 + (T(1) / T(8)) * t18 * t43 * t21 * t36 + (T(1) / T(240)) * t44 * t21 * (T(5) * (T(2) * t46 * t21 * ab_ap + T(3) * t21 * (T(2) * t21 * t45 * ab_ap + ap_ap * t38 * t21 + T(16) * J1) - ap_ap * t39 * t21) * t21 - T(2) * t47 * t21 * ab_ap - ap_ap * t21 * t40) - (T(1) / T(5)) * delta_tau * t48 * t21 * t33 - (T(1) / T(40)) * t47 * t49 * tau_lo * t21 - (T(1) / T(6)) * t32 * t50 * t21;
    const T t51 = T(7) * t31 * ab_ap + t25 * t22 - t26 * t29;
    const T t52 = T(12) * t51 * t21 * ab_ap - T(7) * t32 * t21 - T(42) * ap_ap * t31;
    const T t53 = T(30) * t51 * ap_ap * t21 + T(7) * t21 * t33 - T(10) * t52 * t21 * ab_ap;
    const T t54 = T(7) * t21 * t36 - T(20) * t52 * ap_ap * t21 - T(8) * t21 * ab_ap * t53;
    const T t55 = T(4) * ap_ap * t21 * t53 + T(2) * t54 * t21 * ab_ap + T(7) * t37 * t21;
    const T t56 = T(4) * t55 * t21 * ab_ap + T(7) * t21 * t40 - T(2) * ap_ap * t54 * t21;
    G_ap = (T(1) / T(56)) * t19 * t54 * t20 * t21 + (T(1) / T(140)) * t55 * t49 * tau_lo * t21 + (T(1) / T(1680)) * t44 * t21 * t56 + (T(6) / T(7)) * t51 * delta_tau * t48 * t21 + (T(5) / T(14)) * t52 * t18 * t43 * t21 + t31 * t50 - (T(2) / T(21)) * t41 * t42 * t21 * t53;
    G_ab = (T(1) / T(7)) * t52 * delta_tau * t48 * t21 + (T(1) / T(56)) * t55 * t19 * t20 * t21 + (T(1) / T(42)) * t41 * t54 * t42 * t21 + (T(1) / T(280)) * t49 * tau_lo * t21 * t56 + (T(1) / T(7)) * t51 * t50 * t21 - (T(1) / T(14)) * t18 * t43 * t21 * t53 - (T(1) / T(1680)) * t44 * (T(2) * t55 * ap_ap * t21 + T(7) * t47 * t21 - T(2) * t21 * t56 * ab_ap) * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t57 = delta_tau * delta_tau;
    const T t58 = t57 * t57;
    const T t59 = tau_lo * tau_lo;
    const T t60 = T(1) / ab_ab;
    const T t61 = T(1) / r0;
    const T t62 = T(1) / r1;
    const T t63 = t61 * ab_ap + a_minus_b * t62;
    const T t64 = T(1) / cross_cross;
    const T t65 = t61 * t61;
    const T t66 = t62 * t62;
    const T t67 = t65 * t61 * ab_ap + T(2) * t63 * ab_ab * t64 + a_minus_b * t62 * t66;
    const T t68 = t67 * t64 * ab_ap + t65 * t61 - t62 * t66;
    const T t69 = T(3) * t63 * t64 + T(2) * t60 * ab_ap * t68 - ap_ap * t67 * t64;
    const T t70 = t66 * t66;
    const T t71 = t65 * t65;
    const T t72 = T(4) * t67 * ab_ab * t64 + T(3) * a_minus_b * t62 * t70 + T(3) * t71 * t61 * ab_ap;
    const T t73 = t64 * t72 * ab_ap + T(3) * t71 * t61 - T(3) * t62 * t70;
    const T t74 = ap_ap * t64 * t72 - T(5) * t67 * t64 - T(2) * t73 * t60 * ab_ap;
    const T t75 = T(2) * t60 * t74 * ab_ap + t73 * ap_ap * t60 - T(5) * t60 * t68;
    const T t76 = T(5) * t60 * t69 + ap_ap * t60 * t74 - T(2) * t60 * t75 * ab_ap;
    const T t77 = t59 * tau_lo;
    const T t78 = t77 * t77;
    const T t79 = t61 + t63 * t64 * ab_ap - t62;
    const T t80 = T(2) * t60 * t69 * ab_ap + T(3) * t60 * t79 - ap_ap * t60 * t68;
    const T t81 = T(5) * t60 * t80 + T(2) * t60 * t76 * ab_ap + ap_ap * t60 * t75;
    const T t82 = t58 * delta_tau;
    const T t83 = t59 * t59;
    const T t84 = t83 * tau_lo;
    const T t85 = t57 * delta_tau;
    const T t86 = t85 * t85;
    F = t58 * t59 * t60 * t76 + (T(1) / T(15)) * t78 * t64 * t72 + (T(2) / T(5)) * t81 * t82 * tau_lo * t60 + (T(2) / T(5)) * t73 * delta_tau * t84 * t60 - t57 * t83 * t60 * t74 - (T(4) / T(3)) * t85 * t77 * t60 * t75 - (T(1) / T(15)) * t86 * t60 * (ap_ap * t60 * t76 + T(5) * (T(3) * (ap_ap * t63 * t64 - J1 - T(2) * t60 * t79 * ab_ap) * t60 + ap_ap * t60 * t69 - T(2) * t60 * ab_ap * t80) * t60 - T(2) * t81 * t60 * ab_ap);
    const T t87 = t71 * t65;
    const T t88 = t70 * t66;
    const T t89 = T(5) * t87 * t61 * ab_ap + T(5) * a_minus_b * t62 * t88 + T(2) * ab_ab * t64 * t72;
    const T t90 = t89 * t64 * ab_ap + T(5) * t87 * t61 - T(5) * t62 * t88;
    const T t91 = T(6) * t90 * t60 * ab_ap + T(7) * t64 * t72 - T(3) * ap_ap * t89 * t64;
    const T t92 = T(3) * ap_ap * t90 * t60 - T(2) * t60 * t91 * ab_ap - T(7) * t73 * t60;
    const T t93 = T(7) * t60 * t74 + T(2) * t92 * t60 * ab_ap + ap_ap * t60 * t91;
    const T t94 = T(7) * t60 * t75 + T(2) * t60 * ab_ap * t93 - t92 * ap_ap * t60;
    const T t95 = ap_ap * t60 * t93 + T(7) * t60 * t76 - T(2) * t60 * ab_ap * t94;
    G_ap = (T(1) / T(105)) * t86 * t60 * t95 + (T(1) / T(7)) * t57 * t83 * t60 * t91 + (T(6) / T(35)) * t90 * delta_tau * t84 * t60 + (T(1) / T(35)) * t89 * t78 * t64 - (T(4) / T(21)) * t92 * t85 * t77 * t60 - (T(1) / T(7)) * t58 * t59 * t60 * t93 - (T(2) / T(35)) * t82 * tau_lo * t60 * t94;
    G_ab = (T(2) / T(35)) * t82 * tau_lo * t60 * t95 + (T(1) / T(105)) * t86 * (T(7) * t81 * t60 + T(2) * t60 * t95 * ab_ap + ap_ap * t60 * t94) * t60 + (T(2) / T(35)) * delta_tau * t84 * t60 * t91 + (T(1) / T(35)) * t90 * t78 * t60 - (T(1) / T(7)) * t92 * t57 * t83 * t60 - (T(1) / T(7)) * t58 * t59 * t60 * t94 - (T(4) / T(21)) * t85 * t77 * t60 * t93;
  }
  const T t96 = in.sigma * in.sigma;
  const T t97 = t96 * in.sigma;
  const T t98 = t97 * t97;
  const T t99 = t98 * in.sigma;
  const T g_factor = -T(7) * t99 * length;
  f = F * t99 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 73 +, 196 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 258 +, 440 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i8_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 7, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * tau_lo;
    const T t6 = t5 * t5;
    const T t7 = t6 * tau_lo;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = t8 * t8;
    const T t13 = t12 * delta_tau;
    const T t14 = t4 * t4;
    const T t15 = t14 * tau_lo;
    F = M_flat[0] * t7 + M_flat[7] * t11 + T(35) * M_flat[4] * t12 * t5 + T(7) * M_flat[6] * t10 * tau_lo + T(21) * t13 * t4 * M_flat[5] + T(7) * M_flat[1] * delta_tau * t6 + T(21) * t8 * t15 * M_flat[2] + T(35) * M_flat[3] * t9 * t14;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t16 = t0 * t0;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t16 * t0;
    const T t21 = J_downward<T>(8, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t22 = t19 * a_minus_b + ab_ap * t20 - T(6) * t21 * cross_cross;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(5) * t16 - T(5) * t18 - T(4) * ab_ap * t22 * t23;
    const T t25 = T(5) * ab_ap * t16 + T(5) * t18 * a_minus_b + T(4) * t22 * cross_cross * t23;
    const T t26 = T(2) * t25 * t23 - T(3) * ab_ap * t24 * t23 - T(6) * t22 * ap_ap * t23;
    const T t27 = T(2) * ab_ap * t25 * t23 + T(15) * t17 - T(15) * t0;
    const T t28 = T(3) * t24 * ap_ap * t23 + T(4) * ab_ap * t26 * t23 + T(2) * t27 * t23;
    const T t29 = T(2) * t25 * cross_cross * t23 + T(15) * t17 * a_minus_b + T(15) * ab_ap * t0;
    const T t30 = t29 * t23 + ab_ap * t27 * t23 - t25 * ap_ap * t23;
    const T t31 = T(2) * t30 * t23 + ab_ap * t28 * t23 - ap_ap * t26 * t23;
    const T t32 = t19 - t20 - T(6) * ab_ap * t21;
    const T t33 = T(5) * t32 * ab_ap * t23 + T(15) * ap_ap * t21 + T(3) * t22 * t23;
    const T t34 = T(3) * t24 * t23 + T(10) * t32 * ap_ap * t23 - T(8) * ab_ap * t33 * t23;
    const T t35 = ab_ap * t34 * t23 + T(2) * ap_ap * t33 * t23 - t26 * t23;
    const T t36 = t34 * ap_ap * t23 + t28 * t23 - T(4) * ab_ap * t35 * t23;
    const T t37 = t31 * t23 + t35 * ap_ap * t23 + ab_ap * t36 * t23;
    const T t38 = delta_tau * delta_tau;
    const T t39 = t38 * delta_tau;
    const T t40 = t39 * t39;
    const T t41 = t40 * delta_tau;
    const T t42 = tau_lo * tau_lo;
    const T t43 = t42 * tau_lo;
    const T t44 = t43 * t43;
    const T t45 = t44 * tau_lo;
    const T t46 = t38 * t38;
    const T t47 = t42 * t42;
    const T t48 = t46 * delta_tau;
    const T t49 = t47 * tau_lo;
    F = (T(1) / T(60)) * ((t28 * ap_ap * t23 - T(4) * ab_ap * t31 * t23 - T(2) * (T(4) * t30 * ab_ap * t23 + (T(2) * t29 * ab_ap * t23 - T(15) * log_ratio) * t23 - t27 * ap_ap * t23) * t23) * t23 + ap_ap * t36 * t23 - T(4) * t37 * ab_ap * t23) * t41 * t23 + t21 * t45 + (T(7) / T(6)) * t35 * t46 * t43 * t23 + (T(7) / T(12)) * t34 * t39 * t47 * t23 - (T(7) / T(20)) * t36 * t48 * t42 * t23 - (T(7) / T(5)) * t33 * t38 * t49 * t23 - (T(7) / T(6)) * t32 * delta_tau * t44 * t23 - (T(7) / T(30)) * t37 * t40 * tau_lo * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t50 = sqrt(cross_cross);
    const T t51 = T(1) / t50;
    const T J2 = atan2(t50, ap_bp) * t51;
    const T t52 = t0 * t0;
    const T t53 = T(1) / bp_bp;
    const T t54 = t53 * t53;
    const T t55 = J2 * ab_ab + t53 * a_minus_b + ab_ap * t0;
    const T t56 = T(1) / cross_cross;
    const T t57 = T(2) * ab_ap * t52 + T(2) * t54 * a_minus_b + T(3) * t55 * t56 * ab_ab;
    const T t58 = T(2) * t52 + t57 * ab_ap * t56 - T(2) * t54;
    const T t59 = T(1) / ab_ab;
    const T t60 = T(2) * ab_ap * t58 * t59 + T(4) * t55 * t56 - t57 * ap_ap * t56;
    const T t61 = t54 * t53;
    const T t62 = t52 * t0;
    const T t63 = T(8) * t61 * a_minus_b + T(8) * ab_ap * t62 + T(5) * t57 * t56 * ab_ab;
    const T t64 = ab_ap * t56 * t63 + T(8) * t62 - T(8) * t61;
    const T t65 = T(2) * ab_ap * t64 * t59 + T(6) * t57 * t56 - ap_ap * t56 * t63;
    const T t66 = T(6) * t58 * t59 + T(2) * ab_ap * t65 * t59 - t64 * ap_ap * t59;
    const T t67 = T(6) * t60 * t59 + T(2) * t66 * ab_ap * t59 - t65 * ap_ap * t59;
    const T t68 = delta_tau * delta_tau;
    const T t69 = t68 * t68;
    const T t70 = tau_lo * tau_lo;
    const T t71 = t70 * tau_lo;
    const T t72 = t71 * t71;
    const T t73 = t53 - t0 - ab_ap * t55 * t56;
    const T t74 = T(2) * ab_ap * t60 * t59 - T(4) * t73 * t59 - t58 * ap_ap * t59;
    const T t75 = T(2) * ab_ap * t67 * t59 + T(6) * t59 * t74 - t66 * ap_ap * t59;
    const T t76 = t69 * delta_tau;
    const T t77 = t72 * tau_lo;
    const T t78 = t70 * t70;
    const T t79 = t78 * tau_lo;
    const T t80 = t68 * delta_tau;
    const T t81 = t80 * t80;
    const T t82 = T(2) * ab_ap * t73 * t59 + ap_ap * t55 * t56 - T(2) * J2;
    const T t83 = T(4) * t82 * t59 + t60 * ap_ap * t59 - T(2) * ab_ap * t59 * t74;
    const T t84 = ap_ap * t67 * t59 + T(6) * t83 * t59 - T(2) * t75 * ab_ap * t59;
    const T t85 = t81 * delta_tau;
    F = (T(35) / T(48)) * t67 * t69 * t71 * t59 + (T(7) / T(48)) * t64 * delta_tau * t72 * t59 + (T(7) / T(16)) * t75 * t76 * t70 * t59 + (T(1) / T(48)) * t56 * t77 * t63 + (T(7) / T(16)) * t65 * t68 * t79 * t59 + (T(35) / T(48)) * t66 * t80 * t78 * t59 - (T(7) / T(48)) * t81 * tau_lo * t84 * t59 - (T(1) / T(48)) * (T(2) * ab_ap * t84 * t59 + T(6) * t59 * (T(4) * (T(2) * ab_ap * t82 * t59 - t73 * ap_ap * t59 - (T(2) * ab_ap * J2 + log_ratio) * t59) * t59 + ap_ap * t59 * t74 + T(2) * t83 * ab_ap * t59) + t75 * ap_ap * t59) * t85 * t59;
  }
  const T t86 = in.sigma * in.sigma;
  const T t87 = t86 * t86;
  const T t88 = t87 * t87;
  f = length * F * t88;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 274 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 288 +, 509 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i8_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 9> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 8, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = t5 * tau_lo;
    const T t7 = delta_tau * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t7 * delta_tau;
    const T t11 = t3 * t3;
    const T t12 = t10 * t10;
    const T t13 = t12 * delta_tau;
    const T t14 = t11 * tau_lo;
    G_ap = M_flat[0] * t6 + T(21) * t9 * t3 * M_flat[5] + T(35) * M_flat[3] * t10 * t11 + T(7) * M_flat[6] * t12 * tau_lo + T(35) * t8 * t4 * M_flat[4] + t13 * M_flat[7] + T(21) * t7 * t14 * M_flat[2] + T(7) * delta_tau * t5 * M_flat[1];
    G_ab = T(21) * M_flat[3] * t7 * t14 + t13 * M_flat[8] + T(7) * delta_tau * t5 * M_flat[2] + T(35) * t8 * t4 * M_flat[5] + T(21) * M_flat[6] * t9 * t3 + t6 * M_flat[1] + T(35) * t10 * t11 * M_flat[4] + T(7) * t12 * tau_lo * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 9> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 8, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t15 = delta_tau * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t16 * delta_tau;
    const T t18 = tau_lo * tau_lo;
    const T t19 = t18 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t20 * tau_lo;
    const T t22 = t15 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = t18 * t18;
    const T t26 = t25 * tau_lo;
    G_ap = T(21) * t17 * t18 * M_beyond[5] + M_beyond[0] * t21 + t24 * M_beyond[7] + T(35) * t16 * t19 * M_beyond[4] + T(35) * M_beyond[3] * t22 * t25 + T(21) * t15 * t26 * M_beyond[2] + T(7) * delta_tau * t20 * M_beyond[1] + T(7) * M_beyond[6] * t23 * tau_lo;
    G_ab = T(21) * M_beyond[3] * t15 * t26 + T(7) * t23 * M_beyond[7] * tau_lo + T(7) * delta_tau * t20 * M_beyond[2] + T(35) * t16 * t19 * M_beyond[5] + T(35) * t22 * t25 * M_beyond[4] + T(21) * M_beyond[6] * t17 * t18 + t21 * M_beyond[1] + t24 * M_beyond[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(cross_cross);
    const T t28 = T(1) / t27;
    const T J2 = atan2(t27, ap_bp) * t28;
    const T t29 = T(1) / bp_bp;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = T(1) / ap_ap;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = T(1) / cross_cross;
    const T t36 = t33 * t32;
    const T t37 = t30 * t29;
    const T t38 = ab_ab * J2 + t32 * ab_ap + t29 * a_minus_b;
    const T t39 = T(2) * t30 * a_minus_b + T(3) * t38 * t35 * ab_ab + T(2) * t33 * ab_ap;
    const T t40 = T(8) * t36 * ab_ap + T(8) * t37 * a_minus_b + T(5) * t39 * t35 * ab_ab;
    const T t41 = T(48) * t31 * a_minus_b + T(7) * t35 * ab_ab * t40 + T(48) * t34 * ab_ap;
    const T t42 = T(48) * t31 - T(48) * t34 - t35 * t41 * ab_ap;
    const T t43 = T(1) / ab_ab;
    const T t44 = T(8) * t36 + t35 * t40 * ab_ap - T(8) * t37;
    const T t45 = T(2) * t42 * t43 * ab_ap + ap_ap * t35 * t41 - T(8) * t35 * t40;
    const T t46 = ap_ap * t42 * t43 + T(8) * t44 * t43 - T(2) * t43 * t45 * ab_ap;
    const T t47 = delta_tau * delta_tau;
    const T t48 = t47 * delta_tau;
    const T t49 = tau_lo * tau_lo;
    const T t50 = t49 * t49;
    const T t51 = ap_ap * t35 * t40 - T(2) * t44 * t43 * ab_ap - T(6) * t39 * t35;
    const T t52 = ap_ap * t43 * t45 + T(2) * t46 * t43 * ab_ap - T(8) * t51 * t43;
    const T t53 = t47 * t47;
    const T t54 = t49 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t55 * tau_lo;
    const T t57 = t48 * t48;
    const T t58 = T(2) * t33 + t39 * t35 * ab_ap - T(2) * t30;
    const T t59 = ap_ap * t44 * t43 + T(2) * t51 * t43 * ab_ap - T(6) * t58 * t43;
    const T t60 = T(8) * t43 * t59 + t46 * ap_ap * t43 - T(2) * t52 * t43 * ab_ap;
    const T t61 = T(4) * t38 * t35 + T(2) * t58 * t43 * ab_ap - t39 * ap_ap * t35;
    const T t62 = ap_ap * t51 * t43 + T(6) * t61 * t43 - T(2) * t43 * ab_ap * t59;
    const T t63 = T(2) * t60 * t43 * ab_ap + ap_ap * t52 * t43 - T(8) * t62 * t43;
    const T t64 = t53 * delta_tau;
    const T t65 = t57 * delta_tau;
    const T t66 = t29 - t32 - t38 * t35 * ab_ap;
    const T t67 = T(2) * t61 * t43 * ab_ap - ap_ap * t58 * t43 - T(4) * t66 * t43;
    const T t68 = T(6) * t43 * t67 + T(2) * t62 * t43 * ab_ap + ap_ap * t43 * t59;
    const T t69 = T(2) * t43 * t63 * ab_ap - ap_ap * t60 * t43 - T(8) * t43 * t68;
    const T t70 = t50 * tau_lo;
    G_ap = (T(35) / T(384)) * t46 * t48 * t50 * t43 + (T(35) / T(384)) * t52 * t53 * t54 * t43 + (T(1) / T(384)) * t35 * t56 * t41 - (T(7) / T(384)) * t42 * delta_tau * t55 * t43 - (T(7) / T(384)) * t57 * tau_lo * t43 * t63 - (T(7) / T(128)) * t60 * t64 * t49 * t43 - (T(1) / T(384)) * t65 * t43 * t69 - (T(7) / T(128)) * t47 * t70 * t43 * t45;
    G_ab = (T(7) / T(128)) * t46 * t47 * t70 * t43 + (T(35) / T(384)) * t52 * t48 * t50 * t43 - (T(1) / T(384)) * t42 * t56 * t43 - (T(7) / T(128)) * t64 * t49 * t43 * t63 - (T(35) / T(384)) * t60 * t53 * t54 * t43 - (T(1) / T(384)) * (T(8) * (T(6) * t43 * (ap_ap * t61 * t43 + T(4) * t43 * (T(2) * t66 * t43 * ab_ap + t38 * ap_ap * t35 - T(2) * J2) - T(2) * t43 * t67 * ab_ap) + ap_ap * t62 * t43 - T(2) * t43 * t68 * ab_ap) * t43 + T(2) * t43 * t69 * ab_ap - ap_ap * t43 * t63) * t65 * t43 - (T(7) / T(384)) * t57 * tau_lo * t43 * t69 - (T(7) / T(384)) * delta_tau * t55 * t43 * t45;
  }
  const T t71 = in.sigma * in.sigma;
  const T t72 = t71 * t71;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * t73 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 108 +, 329 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 475 +, 761 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i8_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 18> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 8, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = t4 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t9 * tau_lo;
    const T t11 = t7 * t7;
    const T t12 = t6 * t6;
    const T t13 = t12 * delta_tau;
    const T t14 = t5 * tau_lo;
    const T t15 = t11 * delta_tau;
    F = T(35) * t5 * t7 * M_flat[3] + t10 * M_flat[0] + T(7) * t9 * delta_tau * M_flat[1] + T(7) * tau_lo * t11 * M_flat[6] + T(21) * t4 * t13 * M_flat[5] + T(35) * t8 * t12 * M_flat[4] + T(21) * t14 * t6 * M_flat[2] + t15 * M_flat[7];
    G_ap = t10 * M_flat[9] + T(21) * t14 * t6 * M_flat[11] + t15 * M_flat[16] + T(7) * tau_lo * t11 * M_flat[15] + T(35) * t5 * t7 * M_flat[12] + T(21) * t4 * t13 * M_flat[14] + T(7) * t9 * delta_tau * M_flat[10] + T(35) * t8 * t12 * M_flat[13];
    G_ab = T(7) * t9 * delta_tau * M_flat[11] + t15 * M_flat[17] + T(7) * tau_lo * t11 * M_flat[16] + T(21) * t4 * t13 * M_flat[15] + T(35) * t8 * t12 * M_flat[14] + T(21) * t14 * t6 * M_flat[12] + t10 * M_flat[10] + T(35) * t5 * t7 * M_flat[13];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t16 = tau_lo * tau_lo;
    const T t17 = delta_tau * delta_tau;
    const T t18 = t17 * t17;
    const T t19 = t18 * delta_tau;
    const T t20 = T(1) / ab_ab;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t0 * t0;
    const T t24 = t23 * t23;
    const T t25 = t22 * t22;
    const T t26 = J_downward<T>(10, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t27 = ab_ap * t24 + t25 * a_minus_b - T(8) * cross_cross * t26;
    const T t28 = t23 * t0;
    const T t29 = t22 * t21;
    const T t30 = T(6) * cross_cross * t20 * t27 + T(7) * ab_ap * t28 + T(7) * t29 * a_minus_b;
    const T t31 = T(35) * t22 + T(4) * t20 * t30 * ab_ap - T(35) * t23;
    const T t32 = T(4) * cross_cross * t20 * t30 + T(35) * ab_ap * t23 + T(35) * t22 * a_minus_b;
    const T t33 = T(2) * t20 * ab_ap * t32 + T(105) * t21 - T(105) * t0;
    const T t34 = T(3) * t20 * ab_ap * t31 + T(2) * t20 * t32 - T(6) * t20 * t30 * ap_ap;
    const T t35 = T(3) * t20 * ap_ap * t31 - T(2) * t33 * t20 - T(4) * t20 * ab_ap * t34;
    const T t36 = T(6) * t20 * t27 * ab_ap + T(7) * t29 - T(7) * t28;
    const T t37 = T(5) * t20 * ab_ap * t36 + T(3) * t20 * t30 - T(15) * t20 * t27 * ap_ap;
    const T t38 = T(8) * t20 * ab_ap * t37 + T(3) * t20 * t31 - T(10) * t20 * ap_ap * t36;
    const T t39 = t20 * t34 + t20 * ab_ap * t38 - T(2) * t20 * ap_ap * t37;
    const T t40 = t20 * t35 + t20 * t38 * ap_ap - T(4) * t20 * t39 * ab_ap;
    const T t41 = t17 * delta_tau;
    const T t42 = t41 * t41;
    const T t43 = T(105) * t21 * a_minus_b + T(2) * cross_cross * t20 * t32 + T(105) * ab_ap * t0;
    const T t44 = t33 * t20 * ab_ap + t20 * t43 - t20 * ap_ap * t32;
    const T t45 = T(2) * t20 * t44 - t20 * t34 * ap_ap - t20 * ab_ap * t35;
    const T t46 = t20 * t40 * ab_ap + t20 * t39 * ap_ap - t20 * t45;
    const T t47 = t16 * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t16 * t16;
    const T t50 = t49 * tau_lo;
    const T t51 = t48 * tau_lo;
    const T t52 = t42 * delta_tau;
    F = (T(1) / T(20)) * t16 * t19 * t20 * t40 + (T(1) / T(30)) * tau_lo * t42 * t20 * t46 - (T(1) / T(6)) * t48 * delta_tau * t20 * t36 - (T(1) / T(5)) * t50 * t17 * t20 * t37 - (T(1) / T(6)) * t47 * t18 * t20 * t39 - (T(1) / T(7)) * t51 * t20 * t27 - (T(1) / T(12)) * t49 * t41 * t20 * t38 - (T(1) / T(420)) * t52 * t20 * (t20 * (T(4) * t20 * ab_ap * t45 + t20 * t35 * ap_ap - T(2) * t20 * (t33 * t20 * ap_ap - T(4) * t20 * t44 * ab_ap - t20 * (T(2) * t20 * ab_ap * t43 - T(105) * log_ratio))) + t20 * t40 * ap_ap - T(4) * t20 * ab_ap * t46);
    const T t53 = T(8) * ab_ap * t26 + t24 - t25;
    const T t54 = T(28) * t26 * ap_ap + T(4) * t20 * t27 - T(7) * t20 * ab_ap * t53;
    const T t55 = T(12) * t20 * ab_ap * t54 + T(21) * t20 * t53 * ap_ap + T(4) * t20 * t36;
    const T t56 = T(5) * t20 * ab_ap * t55 + T(4) * t20 * t37 - T(15) * t20 * t54 * ap_ap;
    const T t57 = T(5) * t20 * t55 * ap_ap - T(2) * t20 * t38 - T(4) * t20 * ab_ap * t56;
    const T t58 = t20 * t56 * ap_ap + t20 * ab_ap * t57 - T(2) * t20 * t39;
    const T t59 = T(2) * t20 * t40 + T(4) * t58 * t20 * ab_ap - t20 * ap_ap * t57;
    G_ap = (T(1) / T(840)) * t52 * t20 * t59 + (T(1) / T(40)) * t16 * t19 * t20 * t57 + t51 * t26 + (T(1) / T(60)) * tau_lo * t42 * t58 * t20 + (T(7) / T(8)) * t48 * delta_tau * t20 * t53 - (T(5) / T(24)) * t49 * t41 * t20 * t55 - (T(3) / T(4)) * t50 * t17 * t20 * t54 - (T(1) / T(12)) * t47 * t18 * t20 * t56;
    G_ab = (T(1) / T(420)) * t52 * t20 * (T(2) * t20 * t46 + t20 * ab_ap * t59 - t58 * t20 * ap_ap) + (T(1) / T(8)) * t51 * t20 * t53 + (T(1) / T(24)) * t47 * t18 * t20 * t57 + (T(1) / T(120)) * tau_lo * t42 * t20 * t59 + (T(1) / T(20)) * t16 * t19 * t58 * t20 - (T(1) / T(8)) * t50 * t17 * t20 * t55 - (T(1) / T(4)) * t48 * delta_tau * t20 * t54 - (T(1) / T(12)) * t49 * t41 * t20 * t56;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t60 = sqrt(cross_cross);
    const T t61 = T(1) / t60;
    const T J2 = t61 * atan2(t60, ap_bp);
    const T t62 = tau_lo * tau_lo;
    const T t63 = t62 * tau_lo;
    const T t64 = delta_tau * delta_tau;
    const T t65 = t64 * t64;
    const T t66 = T(1) / ab_ab;
    const T t67 = T(1) / bp_bp;
    const T t68 = t67 * t67;
    const T t69 = t68 * t67;
    const T t70 = T(1) / cross_cross;
    const T t71 = t0 * t0;
    const T t72 = t67 * a_minus_b + ab_ab * J2 + ab_ap * t0;
    const T t73 = T(2) * ab_ap * t71 + T(3) * t70 * ab_ab * t72 + T(2) * t68 * a_minus_b;
    const T t74 = t71 * t0;
    const T t75 = T(5) * t70 * ab_ab * t73 + T(8) * ab_ap * t74 + T(8) * t69 * a_minus_b;
    const T t76 = T(8) * t69 - t70 * ab_ap * t75 - T(8) * t74;
    const T t77 = t70 * ab_ap * t73 + T(2) * t71 - T(2) * t68;
    const T t78 = t70 * ap_ap * t75 + T(2) * t66 * ab_ap * t76 - T(6) * t70 * t73;
    const T t79 = t66 * t76 * ap_ap + T(6) * t66 * t77 - T(2) * t66 * ab_ap * t78;
    const T t80 = T(2) * t66 * t77 * ab_ap + T(4) * t70 * t72 - t70 * t73 * ap_ap;
    const T t81 = T(2) * t66 * ab_ap * t79 + t66 * ap_ap * t78 + T(6) * t66 * t80;
    const T t82 = t62 * t62;
    const T t83 = t64 * delta_tau;
    const T t84 = t63 * t63;
    const T t85 = t84 * tau_lo;
    const T t86 = t65 * delta_tau;
    const T t87 = t70 * t72 * ab_ap + t0 - t67;
    const T t88 = t66 * t77 * ap_ap - T(4) * t87 * t66 - T(2) * t66 * t80 * ab_ap;
    const T t89 = T(2) * t81 * t66 * ab_ap - t66 * ap_ap * t79 - T(6) * t66 * t88;
    const T t90 = t82 * tau_lo;
    const T t91 = t83 * t83;
    const T t92 = t91 * delta_tau;
    const T t93 = t70 * t72 * ap_ap - T(2) * J2 - T(2) * t87 * t66 * ab_ap;
    const T t94 = T(2) * t66 * t88 * ab_ap + T(4) * t66 * t93 + t66 * t80 * ap_ap;
    const T t95 = t81 * t66 * ap_ap + T(6) * t66 * t94 - T(2) * t66 * t89 * ab_ap;
    F = (T(35) / T(48)) * t63 * t65 * t81 * t66 + (T(35) / T(48)) * t82 * t83 * t66 * t79 + (T(1) / T(48)) * t85 * t70 * t75 + (T(7) / T(16)) * t62 * t86 * t66 * t89 - (T(7) / T(16)) * t90 * t64 * t66 * t78 - (T(1) / T(48)) * t92 * t66 * (T(2) * t95 * t66 * ab_ap + t66 * t89 * ap_ap - T(6) * t66 * (t66 * t88 * ap_ap - T(2) * t66 * ab_ap * t94 - T(4) * t66 * (T(2) * t66 * t93 * ab_ap + t87 * t66 * ap_ap - t66 * (log_ratio + T(2) * ab_ap * J2)))) - (T(7) / T(48)) * tau_lo * t91 * t95 * t66 - (T(7) / T(48)) * t84 * delta_tau * t66 * t76;
    const T t96 = t71 * t71;
    const T t97 = t68 * t68;
    const T t98 = T(48) * ab_ap * t96 + T(48) * t97 * a_minus_b + T(7) * t70 * ab_ab * t75;
    const T t99 = T(48) * t96 + t70 * ab_ap * t98 - T(48) * t97;
    const T t100 = t70 * ap_ap * t98 - T(2) * t99 * t66 * ab_ap - T(8) * t70 * t75;
    const T t101 = T(8) * t66 * t76 + T(2) * t66 * ab_ap * t100 + t99 * t66 * ap_ap;
    const T t102 = T(2) * t101 * t66 * ab_ap + T(8) * t66 * t78 - t66 * ap_ap * t100;
    const T t103 = T(2) * t66 * t102 * ab_ap - T(8) * t66 * t79 - t101 * t66 * ap_ap;
    const T t104 = T(2) * t66 * ab_ap * t103 - t66 * t102 * ap_ap - T(8) * t81 * t66;
    const T t105 = T(2) * t66 * ab_ap * t104 - T(8) * t66 * t89 - t66 * ap_ap * t103;
    G_ap = (T(1) / T(384)) * t85 * t70 * t98 + (T(7) / T(384)) * t84 * delta_tau * t99 * t66 - (T(7) / T(384)) * tau_lo * t91 * t66 * t104 - (T(7) / T(128)) * t90 * t64 * t66 * t100 - (T(7) / T(128)) * t62 * t86 * t66 * t103 - (T(35) / T(384)) * t101 * t82 * t83 * t66 - (T(35) / T(384)) * t63 * t65 * t66 * t102 - (T(1) / T(384)) * t92 * t66 * t105;
    G_ab = (T(1) / T(384)) * t85 * t99 * t66 - (T(7) / T(384)) * tau_lo * t91 * t66 * t105 - (T(7) / T(384)) * t84 * delta_tau * t66 * t100 - (T(7) / T(128)) * t62 * t86 * t66 * t104 - (T(35) / T(384)) * t63 * t65 * t66 * t103 - (T(7) / T(128)) * t101 * t90 * t64 * t66 - (T(35) / T(384)) * t82 * t83 * t66 * t102 - (T(1) / T(384)) * t92 * t66 * (T(2) * t66 * t105 * ab_ap + T(8) * t95 * t66 - t66 * ap_ap * t104);
  }
  const T t106 = in.sigma * in.sigma;
  const T t107 = t106 * t106;
  const T t108 = t107 * t107;
  const T g_factor = -T(8) * length * t108;
  f = length * F * t108;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 83 +, 252 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 278 +, 569 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i9_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / cross_cross;
    X = length * (t1 + ab_ap * r1) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 9> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 8, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t10 * tau_lo;
    const T t12 = delta_tau * delta_tau;
    const T t13 = t12 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t12 * t12;
    const T t16 = t15 * t15;
    const T t17 = t8 * t8;
    const T t18 = t17 * tau_lo;
    const T t19 = t15 * delta_tau;
    const T t20 = t14 * delta_tau;
    const T t21 = t17 * t17;
    F = T(8) * M_flat[1] * delta_tau * t11 + T(28) * M_flat[2] * t12 * t10 + T(28) * M_flat[6] * t14 * t8 + t16 * M_flat[8] + T(56) * M_flat[3] * t13 * t18 + T(56) * M_flat[5] * t19 * t9 + T(8) * M_flat[7] * t20 * tau_lo + T(70) * M_flat[4] * t15 * t17 + M_flat[0] * t21;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t22 = J_downward<T>(9, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = T(1) / r1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t28 * t28;
    const T t33 = t32 * t28;
    const T t34 = t31 * t30;
    const T t35 = T(7) * t22 * cross_cross - t27 * ab_ap * t33 - t34 * t29 * a_minus_b;
    const T t36 = T(6) * t31 * t29 * a_minus_b + T(6) * t27 * ab_ap * t32 - T(5) * t26 * t35 * cross_cross;
    const T t37 = T(8) * t27 * t28 - t26 * ab_ap * t36 - T(8) * t30 * t29;
    const T t38 = T(6) * t31 * t29 - T(6) * t27 * t32 - T(5) * t26 * ab_ap * t35;
    const T t39 = T(20) * t26 * t35 * ap_ap + T(8) * t26 * t38 * ab_ap + T(5) * t26 * t36;
    const T t40 = T(5) * t26 * t37 + T(4) * t26 * t38 * ap_ap - T(2) * t26 * ab_ap * t39;
    const T t41 = t34 * t29 - T(7) * ab_ap * t22 - t27 * t33;
    const T t42 = T(12) * t41 * t26 * ab_ap + T(42) * t22 * ap_ap - T(7) * t26 * t35;
    const T t43 = T(10) * t26 * t42 * ab_ap + T(7) * t26 * t38 - T(30) * t41 * t26 * ap_ap;
    const T t44 = T(8) * t26 * ab_ap * t43 + T(7) * t26 * t39 - T(20) * t26 * t42 * ap_ap;
    const T t45 = T(7) * t26 * t40 + T(4) * t26 * ap_ap * t43 - T(2) * t44 * t26 * ab_ap;
    const T t46 = delta_tau * delta_tau;
    const T t47 = t46 * t46;
    const T t48 = t47 * delta_tau;
    const T t49 = t23 * tau_lo;
    const T t50 = t26 * t36 * cross_cross + T(8) * t30 * t29 * a_minus_b + T(8) * t27 * ab_ap * t28;
    const T t51 = T(2) * t26 * ap_ap * t36 + T(4) * t26 * t37 * ab_ap - T(3) * t26 * t50;
    const T t52 = T(4) * t26 * ab_ap * t40 + T(2) * t26 * t39 * ap_ap + T(5) * t51 * t26;
    const T t53 = T(4) * t26 * t45 * ab_ap + T(2) * t44 * t26 * ap_ap + T(7) * t26 * t52;
    const T t54 = t46 * delta_tau;
    const T t55 = t54 * t54;
    const T t56 = T(16) * t29 + t26 * ab_ap * t50 - T(16) * t27;
    const T t57 = T(2) * t51 * t26 * ab_ap - T(3) * t26 * t56 - T(2) * t26 * t37 * ap_ap;
    const T t58 = T(2) * t26 * ab_ap * t52 + T(5) * t26 * t57 - T(2) * t26 * ap_ap * t40;
    const T t59 = T(2) * t26 * t45 * ap_ap - T(2) * t26 * ab_ap * t53 - T(7) * t26 * t58;
    const T t60 = t47 * t47;
    const T t61 = t24 * tau_lo;
    const T t62 = t49 * t49;
    const T t63 = t62 * tau_lo;
    const T t64 = t55 * delta_tau;
    F = t22 * t25 + (T(1) / T(15)) * t26 * t45 * t48 * t49 + (T(1) / T(60)) * t26 * t53 * t55 * t23 - (T(1) / T(1680)) * t26 * (t26 * t53 * ap_ap + T(2) * t26 * t59 * ab_ap - T(7) * t26 * (T(2) * t26 * t58 * ab_ap + T(5) * t26 * (T(2) * t26 * ab_ap * t57 + T(3) * t26 * (T(16) * J1 + t26 * t50 * ap_ap - T(2) * t26 * t56 * ab_ap) - t51 * t26 * ap_ap) - t26 * ap_ap * t52)) * t60 - (T(4) / T(15)) * t26 * t54 * t43 * t61 - (T(2) / T(3)) * t26 * t42 * t46 * t62 - (T(1) / T(12)) * t44 * t26 * t47 * t24 - (T(8) / T(7)) * t41 * t26 * delta_tau * t63 - (T(1) / T(210)) * t26 * t59 * t64 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t65 = T(1) / ab_ab;
    const T t66 = T(1) / r1;
    const T t67 = t66 * t66;
    const T t68 = t67 * t67;
    const T t69 = T(1) / r0;
    const T t70 = t69 * t69;
    const T t71 = t70 * t70;
    const T t72 = t69 * ab_ap + t66 * a_minus_b;
    const T t73 = T(1) / cross_cross;
    const T t74 = T(2) * ab_ab * t72 * t73 + t67 * t66 * a_minus_b + t69 * ab_ap * t70;
    const T t75 = T(4) * ab_ab * t74 * t73 + T(3) * t68 * t66 * a_minus_b + T(3) * t69 * ab_ap * t71;
    const T t76 = T(3) * t68 * t66 - T(3) * t69 * t71 - ab_ap * t75 * t73;
    const T t77 = t69 * t70 + ab_ap * t74 * t73 - t67 * t66;
    const T t78 = t75 * ap_ap * t73 + T(2) * t65 * ab_ap * t76 - T(5) * t74 * t73;
    const T t79 = t65 * t76 * ap_ap + T(5) * t77 * t65 - T(2) * t65 * t78 * ab_ap;
    const T t80 = t71 * t70;
    const T t81 = t68 * t67;
    const T t82 = T(5) * t69 * ab_ap * t80 + T(2) * ab_ab * t75 * t73 + T(5) * t81 * t66 * a_minus_b;
    const T t83 = T(5) * t81 * t66 - T(5) * t69 * t80 - t82 * ab_ap * t73;
    const T t84 = T(3) * t82 * ap_ap * t73 + T(6) * t65 * ab_ap * t83 - T(7) * t75 * t73;
    const T t85 = T(2) * t65 * t84 * ab_ap + T(7) * t65 * t76 - T(3) * t65 * ap_ap * t83;
    const T t86 = T(2) * t85 * t65 * ab_ap + T(7) * t65 * t78 - t65 * t84 * ap_ap;
    const T t87 = T(7) * t65 * t79 + t85 * t65 * ap_ap - T(2) * t65 * ab_ap * t86;
    const T t88 = delta_tau * delta_tau;
    const T t89 = t88 * t88;
    const T t90 = t89 * delta_tau;
    const T t91 = tau_lo * tau_lo;
    const T t92 = t91 * tau_lo;
    const T t93 = t88 * delta_tau;
    const T t94 = t93 * t93;
    const T t95 = T(2) * t77 * t65 * ab_ap + T(3) * t72 * t73 - t74 * ap_ap * t73;
    const T t96 = t65 * t78 * ap_ap + T(5) * t65 * t95 + T(2) * t65 * ab_ap * t79;
    const T t97 = T(7) * t65 * t96 + T(2) * t87 * t65 * ab_ap + t65 * t86 * ap_ap;
    const T t98 = ab_ap * t72 * t73 + t69 - t66;
    const T t99 = T(2) * t65 * t95 * ab_ap + T(3) * t65 * t98 - t77 * t65 * ap_ap;
    const T t100 = t65 * t79 * ap_ap - T(2) * t65 * ab_ap * t96 - T(5) * t65 * t99;
    const T t101 = T(2) * t65 * ab_ap * t97 - t87 * t65 * ap_ap - T(7) * t65 * t100;
    const T t102 = t94 * delta_tau;
    const T t103 = t91 * t91;
    const T t104 = t103 * t103;
    const T t105 = t89 * t89;
    const T t106 = t92 * t92;
    const T t107 = t103 * tau_lo;
    const T t108 = t106 * tau_lo;
    F = (T(8) / T(15)) * t87 * t65 * t90 * t92 + (T(4) / T(15)) * t65 * t94 * t91 * t97 + (T(8) / T(105)) * t65 * t101 * t102 * tau_lo + (T(1) / T(35)) * t82 * t104 * t73 + (T(1) / T(105)) * t65 * (T(2) * t65 * t101 * ab_ap - t65 * ap_ap * t97 - T(7) * t65 * (T(2) * t65 * ab_ap * t100 + t65 * t96 * ap_ap - T(5) * t65 * (T(2) * t65 * ab_ap * t99 + T(3) * t65 * (J1 + T(2) * t65 * ab_ap * t98 - t72 * ap_ap * t73) - t65 * t95 * ap_ap))) * t105 - (T(2) / T(3)) * t65 * t86 * t89 * t103 - (T(4) / T(15)) * t65 * t84 * t88 * t106 - (T(8) / T(15)) * t85 * t65 * t93 * t107 - (T(8) / T(35)) * t65 * delta_tau * t108 * t83;
  }
  const T t109 = in.sigma * in.sigma;
  const T t110 = t109 * t109;
  const T t111 = t110 * t110;
  const T t112 = t111 * in.sigma;
  f = length * t112 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 105 +, 336 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 308 +, 656 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i9_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 9, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t3 * t3;
    const T t10 = t9 * tau_lo;
    const T t11 = t6 * delta_tau;
    const T t12 = t7 * t7;
    const T t13 = t11 * t11;
    const T t14 = t13 * delta_tau;
    const T t15 = t9 * t9;
    const T t16 = t5 * tau_lo;
    G_ap = T(28) * M_flat[2] * t5 * t6 + T(56) * M_flat[5] * t4 * t8 + T(56) * M_flat[3] * t10 * t11 + T(70) * M_flat[4] * t9 * t7 + M_flat[8] * t12 + T(8) * M_flat[7] * tau_lo * t14 + M_flat[0] * t15 + T(8) * M_flat[1] * t16 * delta_tau + T(28) * M_flat[6] * t3 * t13;
    G_ab = T(8) * M_flat[2] * t16 * delta_tau + M_flat[9] * t12 + T(28) * M_flat[7] * t3 * t13 + T(8) * M_flat[8] * tau_lo * t14 + T(28) * M_flat[3] * t5 * t6 + M_flat[1] * t15 + T(56) * M_flat[4] * t10 * t11 + T(56) * M_flat[6] * t4 * t8 + T(70) * M_flat[5] * t9 * t7;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 9, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = delta_tau * delta_tau;
    const T t20 = t19 * t19;
    const T t21 = t19 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t18 * t18;
    const T t25 = t18 * tau_lo;
    const T t26 = t17 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t20 * t20;
    const T t30 = t20 * delta_tau;
    G_ap = T(70) * M_beyond[4] * t18 * t20 + T(8) * M_beyond[7] * tau_lo * t23 + t24 * M_beyond[0] + T(56) * M_beyond[3] * t25 * t21 + T(8) * M_beyond[1] * t28 * delta_tau + M_beyond[8] * t29 + T(56) * M_beyond[5] * t26 * t30 + T(28) * M_beyond[2] * t27 * t19 + T(28) * M_beyond[6] * t17 * t22;
    G_ab = T(28) * M_beyond[3] * t27 * t19 + M_beyond[9] * t29 + T(70) * M_beyond[5] * t18 * t20 + T(8) * M_beyond[8] * tau_lo * t23 + M_beyond[1] * t24 + T(56) * M_beyond[4] * t25 * t21 + T(8) * M_beyond[2] * t28 * delta_tau + T(28) * M_beyond[7] * t17 * t22 + T(56) * M_beyond[6] * t26 * t30;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = T(1) / ab_ab;
    const T t32 = T(1) / cross_cross;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = T(1) / r1;
    const T t36 = t35 * t35;
    const T t37 = ab_ap * t33 + a_minus_b * t35;
    const T t38 = ab_ap * t33 * t34 + a_minus_b * t36 * t35 + T(2) * t32 * ab_ab * t37;
    const T t39 = t36 * t36;
    const T t40 = t34 * t34;
    const T t41 = T(4) * t32 * ab_ab * t38 + T(3) * a_minus_b * t39 * t35 + T(3) * ab_ap * t33 * t40;
    const T t42 = t40 * t34;
    const T t43 = t39 * t36;
    const T t44 = T(2) * t32 * ab_ab * t41 + T(5) * ab_ap * t33 * t42 + T(5) * a_minus_b * t43 * t35;
    const T t45 = T(5) * t43 * t35 - t32 * ab_ap * t44 - T(5) * t33 * t42;
    const T t46 = T(3) * t32 * t44 * ap_ap + T(6) * t31 * ab_ap * t45 - T(7) * t32 * t41;
    const T t47 = T(3) * t39 * t35 - t32 * ab_ap * t41 - T(3) * t33 * t40;
    const T t48 = T(3) * t31 * ap_ap * t45 - T(2) * t31 * ab_ap * t46 - T(7) * t47 * t31;
    const T t49 = t32 * ap_ap * t41 + T(2) * t47 * t31 * ab_ap - T(5) * t32 * t38;
    const T t50 = t31 * t46 * ap_ap + T(2) * t31 * ab_ap * t48 - T(7) * t31 * t49;
    const T t51 = t39 * t39;
    const T t52 = t40 * t40;
    const T t53 = T(35) * a_minus_b * t51 * t35 + T(8) * t32 * ab_ab * t44 + T(35) * ab_ap * t33 * t52;
    const T t54 = t32 * t53 * ab_ap + T(35) * t33 * t52 - T(35) * t51 * t35;
    const T t55 = T(9) * t32 * t44 + T(2) * t31 * ab_ap * t54 - t32 * t53 * ap_ap;
    const T t56 = T(2) * t31 * ab_ap * t55 - T(9) * t31 * t45 - t31 * ap_ap * t54;
    const T t57 = T(3) * t31 * t46 + t31 * t55 * ap_ap - T(2) * t31 * ab_ap * t56;
    const T t58 = T(3) * t31 * t48 - T(2) * t31 * ab_ap * t57 - t31 * t56 * ap_ap;
    const T t59 = T(3) * t31 * t50 + T(2) * t31 * t58 * ab_ap + t31 * t57 * ap_ap;
    const T t60 = tau_lo * tau_lo;
    const T t61 = delta_tau * delta_tau;
    const T t62 = t61 * delta_tau;
    const T t63 = t62 * t62;
    const T t64 = t60 * t60;
    const T t65 = t64 * t64;
    const T t66 = t64 * tau_lo;
    const T t67 = t60 * tau_lo;
    const T t68 = t67 * t67;
    const T t69 = t61 * t61;
    const T t70 = t69 * delta_tau;
    const T t71 = t68 * tau_lo;
    const T t72 = t33 * t34 + t32 * ab_ap * t38 - t36 * t35;
    const T t73 = T(2) * t31 * ab_ap * t49 - t47 * t31 * ap_ap - T(5) * t72 * t31;
    const T t74 = T(2) * t31 * ab_ap * t50 - t31 * ap_ap * t48 - T(7) * t31 * t73;
    const T t75 = t31 * t58 * ap_ap - T(2) * t31 * ab_ap * t59 - T(3) * t31 * t74;
    const T t76 = t63 * delta_tau;
    const T t77 = T(3) * t32 * t37 + T(2) * t72 * t31 * ab_ap - t32 * t38 * ap_ap;
    const T t78 = T(5) * t31 * t77 + t31 * ap_ap * t49 - T(2) * t31 * ab_ap * t73;
    const T t79 = T(7) * t31 * t78 + T(2) * t31 * ab_ap * t74 - t31 * t50 * ap_ap;
    const T t80 = T(2) * t31 * t75 * ab_ap + t31 * t59 * ap_ap - T(3) * t31 * t79;
    const T t81 = t69 * t69;
    G_ap = (T(4) / T(45)) * t31 * t59 * t60 * t63 + (T(1) / T(315)) * t32 * t53 * t65 + (T(8) / T(45)) * t31 * t56 * t66 * t62 + (T(4) / T(45)) * t31 * t55 * t68 * t61 + (T(8) / T(45)) * t31 * t58 * t67 * t70 + (T(8) / T(315)) * t31 * t54 * t71 * delta_tau - (T(8) / T(315)) * t31 * t75 * tau_lo * t76 - (T(1) / T(315)) * t31 * t80 * t81 - (T(2) / T(9)) * t31 * t57 * t64 * t69;
    G_ab = (T(2) / T(9)) * t31 * t58 * t64 * t69 + (T(8) / T(45)) * t31 * t59 * t67 * t70 + (T(8) / T(315)) * t31 * t55 * t71 * delta_tau + (T(1) / T(315)) * t31 * t54 * t65 + (T(4) / T(45)) * t31 * t56 * t68 * t61 - (T(8) / T(45)) * t31 * t57 * t66 * t62 - (T(1) / T(315)) * t31 * (T(2) * t31 * ab_ap * t80 + T(3) * t31 * (t31 * t74 * ap_ap + T(7) * t31 * (T(5) * t31 * (T(3) * t31 * (t35 - t33 - t32 * t37 * ab_ap) + t72 * t31 * ap_ap - T(2) * t31 * ab_ap * t77) - T(2) * t31 * ab_ap * t78 - t31 * t73 * ap_ap) - T(2) * t31 * ab_ap * t79) - t31 * t75 * ap_ap) * t81 - (T(8) / T(315)) * t31 * t80 * tau_lo * t76 - (T(4) / T(45)) * t31 * t75 * t60 * t63;
  }
  const T t82 = in.sigma * in.sigma;
  const T t83 = t82 * t82;
  const T t84 = t83 * t83;
  const T t85 = t84 * in.sigma;
  const T g_factor = -T(9) * length * t85;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 122 +, 404 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 517 +, 937 ×, 22 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i9_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r1 * ab_ap) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 20> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 9, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = tau_lo * tau_lo;
    const T t13 = t12 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = t12 * t12;
    const T t17 = t16 * t16;
    const T t18 = t8 * t8;
    const T t19 = t16 * tau_lo;
    const T t20 = t18 * t18;
    const T t21 = t18 * delta_tau;
    F = T(8) * t11 * tau_lo * M_flat[7] + T(8) * delta_tau * t15 * M_flat[1] + t17 * M_flat[0] + T(28) * t8 * t14 * M_flat[2] + T(70) * t18 * t16 * M_flat[4] + T(56) * t9 * t19 * M_flat[3] + T(28) * t10 * t12 * M_flat[6] + t20 * M_flat[8] + T(56) * t21 * t13 * M_flat[5];
    G_ap = T(70) * t18 * t16 * M_flat[14] + M_flat[18] * t20 + T(8) * t11 * tau_lo * M_flat[17] + T(28) * t10 * t12 * M_flat[16] + T(56) * t21 * M_flat[15] * t13 + t17 * M_flat[10] + T(28) * t8 * M_flat[12] * t14 + T(56) * t9 * t19 * M_flat[13] + T(8) * delta_tau * t15 * M_flat[11];
    G_ab = t17 * M_flat[11] + T(8) * M_flat[18] * t11 * tau_lo + T(8) * delta_tau * M_flat[12] * t15 + T(28) * t8 * t14 * M_flat[13] + T(28) * t10 * t12 * M_flat[17] + T(70) * t18 * M_flat[15] * t16 + T(56) * t9 * t19 * M_flat[14] + t20 * M_flat[19] + T(56) * t21 * t13 * M_flat[16];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * delta_tau;
    const T t24 = t23 * t23;
    const T t25 = T(1) / ab_ab;
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = T(1) / r0;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t31 * t30;
    const T t33 = t28 * t27;
    const T t34 = t31 * t31;
    const T t35 = t28 * t28;
    const T t36 = J_downward<T>(11, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t37 = t29 * ab_ap * t34 + t26 * t35 * a_minus_b - T(9) * cross_cross * t36;
    const T t38 = T(8) * t29 * ab_ap * t32 + T(8) * t26 * t33 * a_minus_b + T(7) * t37 * cross_cross * t25;
    const T t39 = T(48) * t26 * t28 * a_minus_b + T(48) * t29 * ab_ap * t31 + T(5) * cross_cross * t38 * t25;
    const T t40 = t25 * t39 * ab_ap + T(64) * t26 * t27 - T(64) * t29 * t30;
    const T t41 = T(64) * t29 * ab_ap * t30 + cross_cross * t25 * t39 + T(64) * t26 * t27 * a_minus_b;
    const T t42 = T(4) * t25 * ab_ap * t40 + T(3) * t25 * t41 - T(2) * t25 * t39 * ap_ap;
    const T t43 = T(5) * t38 * t25 * ab_ap + T(48) * t26 * t28 - T(48) * t29 * t31;
    const T t44 = T(5) * t25 * t39 + T(8) * t43 * t25 * ab_ap - T(20) * t38 * t25 * ap_ap;
    const T t45 = T(2) * t44 * t25 * ab_ap + T(5) * t25 * t40 - T(4) * t43 * t25 * ap_ap;
    const T t46 = T(5) * t42 * t25 + T(4) * t25 * t45 * ab_ap - T(2) * t44 * t25 * ap_ap;
    const T t47 = T(8) * t26 * t33 + T(7) * t37 * t25 * ab_ap - T(8) * t29 * t32;
    const T t48 = T(7) * t38 * t25 + T(12) * t47 * t25 * ab_ap - T(42) * t37 * t25 * ap_ap;
    const T t49 = T(7) * t43 * t25 + T(10) * t25 * t48 * ab_ap - T(30) * t47 * t25 * ap_ap;
    const T t50 = T(8) * t25 * t49 * ab_ap + T(7) * t44 * t25 - T(20) * t25 * t48 * ap_ap;
    const T t51 = T(2) * t25 * ab_ap * t50 + T(7) * t25 * t45 - T(4) * t25 * t49 * ap_ap;
    const T t52 = T(7) * t25 * t46 + T(4) * t25 * ab_ap * t51 - T(2) * t25 * t50 * ap_ap;
    const T t53 = tau_lo * tau_lo;
    const T t54 = t53 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t53 * t53;
    const T t57 = t56 * t56;
    const T t58 = t24 * delta_tau;
    const T t59 = t25 * ab_ap * t41 + T(128) * t26 - T(128) * t29;
    const T t60 = T(2) * t25 * t40 * ap_ap - T(3) * t25 * t59 - T(2) * t42 * t25 * ab_ap;
    const T t61 = T(2) * t25 * t46 * ab_ap - T(2) * t25 * t45 * ap_ap - T(5) * t60 * t25;
    const T t62 = T(7) * t25 * t61 + T(2) * t52 * t25 * ab_ap - T(2) * t25 * t51 * ap_ap;
    const T t63 = t22 * t22;
    const T t64 = t63 * t63;
    const T t65 = t56 * tau_lo;
    const T t66 = t63 * delta_tau;
    const T t67 = t55 * tau_lo;
    F = -(T(1) / T(480)) * t24 * t52 * t53 * t25 - (T(1) / T(12)) * t22 * t55 * t25 * t48 - (T(1) / T(8)) * t37 * t57 * t25 - (T(1) / T(1680)) * t58 * tau_lo * t62 * t25 - (T(1) / T(13440)) * t64 * t25 * (T(7) * (T(2) * t25 * t61 * ab_ap - T(5) * (t42 * t25 * ap_ap + T(2) * t60 * t25 * ab_ap + T(3) * t25 * (T(128) * J1 + t25 * t41 * ap_ap - T(2) * t25 * ab_ap * t59)) * t25 - t25 * t46 * ap_ap) * t25 + T(2) * t62 * t25 * ab_ap - t52 * t25 * ap_ap) - (T(1) / T(30)) * t23 * t65 * t25 * t49 - (T(1) / T(96)) * t63 * t56 * t25 * t50 - (T(1) / T(120)) * t66 * t54 * t25 * t51 - (T(1) / T(7)) * delta_tau * t67 * t47 * t25;
    const T t68 = t29 * t34 + T(9) * t36 * ab_ap - t26 * t35;
    const T t69 = T(72) * t36 * ap_ap + T(9) * t37 * t25 - T(16) * t68 * t25 * ab_ap;
    const T t70 = T(56) * t68 * t25 * ap_ap + T(9) * t47 * t25 + T(14) * t25 * ab_ap * t69;
    const T t71 = T(3) * t25 * t48 + T(4) * t25 * t70 * ab_ap - T(14) * t25 * t69 * ap_ap;
    const T t72 = T(3) * t25 * t49 + T(10) * t25 * t71 * ab_ap - T(10) * t25 * t70 * ap_ap;
    const T t73 = T(20) * t25 * t71 * ap_ap - T(8) * t25 * ab_ap * t72 - T(3) * t25 * t50;
    const T t74 = T(2) * t25 * ab_ap * t73 + T(4) * t25 * t72 * ap_ap - T(3) * t25 * t51;
    const T t75 = T(2) * t25 * t73 * ap_ap + T(3) * t52 * t25 - T(4) * t74 * t25 * ab_ap;
    G_ap = (T(1) / T(2520)) * t58 * tau_lo * t74 * t25 + t57 * t36 + (T(1) / T(720)) * t24 * t53 * t25 * t73 + (T(8) / T(9)) * delta_tau * t67 * t68 * t25 - (T(1) / T(40320)) * t64 * t75 * t25 - (T(1) / T(9)) * t23 * t65 * t25 * t70 - (T(7) / T(18)) * t22 * t55 * t25 * t69 - (T(1) / T(90)) * t66 * t54 * t25 * t72 - (T(5) / T(72)) * t63 * t56 * t25 * t71;
    G_ab = (T(1) / T(720)) * t24 * t53 * t74 * t25 + (T(1) / T(9)) * t57 * t68 * t25 + (T(1) / T(360)) * t66 * t54 * t25 * t73 - (T(1) / T(18)) * t23 * t65 * t25 * t71 - (T(1) / T(9)) * delta_tau * t67 * t25 * t69 - (T(1) / T(40320)) * t64 * t25 * (T(2) * t75 * t25 * ab_ap + T(3) * t62 * t25 + T(2) * t74 * t25 * ap_ap) - (T(1) / T(18)) * t22 * t55 * t25 * t70 - (T(1) / T(5040)) * t58 * tau_lo * t75 * t25 - (T(1) / T(72)) * t63 * t56 * t25 * t72;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t76 = delta_tau * delta_tau;
    const T t77 = t76 * delta_tau;
    const T t78 = t77 * t77;
    const T t79 = T(1) / ab_ab;
    const T t80 = T(1) / cross_cross;
    const T t81 = T(1) / r0;
    const T t82 = t81 * t81;
    const T t83 = t82 * t82;
    const T t84 = t83 * t82;
    const T t85 = T(1) / r1;
    const T t86 = t85 * t85;
    const T t87 = t86 * t86;
    const T t88 = t87 * t86;
    const T t89 = t85 * a_minus_b + t81 * ab_ap;
    const T t90 = t81 * ab_ap * t82 + T(2) * t80 * ab_ab * t89 + t85 * t86 * a_minus_b;
    const T t91 = T(3) * t85 * t87 * a_minus_b + T(3) * t81 * ab_ap * t83 + T(4) * t80 * ab_ab * t90;
    const T t92 = T(5) * t81 * ab_ap * t84 + T(5) * t85 * t88 * a_minus_b + T(2) * t80 * ab_ab * t91;
    const T t93 = T(5) * t85 * t88 - T(5) * t81 * t84 - t80 * t92 * ab_ap;
    const T t94 = T(3) * t80 * t92 * ap_ap + T(6) * t79 * t93 * ab_ap - T(7) * t80 * t91;
    const T t95 = T(3) * t85 * t87 - T(3) * t81 * t83 - t80 * ab_ap * t91;
    const T t96 = T(2) * t79 * ab_ap * t94 + T(7) * t79 * t95 - T(3) * t79 * t93 * ap_ap;
    const T t97 = T(2) * t79 * ab_ap * t95 + t80 * t91 * ap_ap - T(5) * t80 * t90;
    const T t98 = T(2) * t96 * t79 * ab_ap + T(7) * t79 * t97 - t79 * t94 * ap_ap;
    const T t99 = t80 * ab_ap * t90 + t81 * t82 - t85 * t86;
    const T t100 = t79 * t95 * ap_ap + T(5) * t79 * t99 - T(2) * t79 * ab_ap * t97;
    const T t101 = t80 * t90 * ap_ap - T(3) * t80 * t89 - T(2) * t79 * ab_ap * t99;
    const T t102 = t79 * t97 * ap_ap + T(2) * t79 * t100 * ab_ap - T(5) * t79 * t101;
    const T t103 = T(2) * t98 * t79 * ab_ap - t96 * t79 * ap_ap - T(7) * t79 * t100;
    const T t104 = t98 * t79 * ap_ap + T(7) * t79 * t102 - T(2) * t79 * ab_ap * t103;
    const T t105 = tau_lo * tau_lo;
    const T t106 = t78 * delta_tau;
    const T t107 = t85 - t80 * ab_ap * t89 - t81;
    const T t108 = T(2) * t79 * ab_ap * t101 + t79 * t99 * ap_ap + T(3) * t79 * t107;
    const T t109 = t79 * t100 * ap_ap + T(5) * t79 * t108 - T(2) * t79 * t102 * ab_ap;
    const T t110 = t79 * t103 * ap_ap + T(2) * t104 * t79 * ab_ap - T(7) * t79 * t109;
    const T t111 = t105 * t105;
    const T t112 = t111 * t111;
    const T t113 = t111 * tau_lo;
    const T t114 = t105 * tau_lo;
    const T t115 = t114 * t114;
    const T t116 = t115 * tau_lo;
    const T t117 = t76 * t76;
    const T t118 = t117 * t117;
    const T t119 = t117 * delta_tau;
    F = (T(4) / T(15)) * t78 * t104 * t105 * t79 + (T(8) / T(105)) * t106 * tau_lo * t79 * t110 + (T(1) / T(35)) * t112 * t80 * t92 - (T(8) / T(15)) * t77 * t113 * t96 * t79 - (T(8) / T(35)) * delta_tau * t116 * t79 * t93 - (T(2) / T(3)) * t117 * t111 * t98 * t79 - (T(4) / T(15)) * t76 * t115 * t79 * t94 - (T(1) / T(105)) * t118 * t79 * (t104 * t79 * ap_ap + T(7) * t79 * (T(5) * t79 * (T(2) * t79 * t108 * ab_ap - t79 * t101 * ap_ap - T(3) * t79 * (J1 - T(2) * t79 * ab_ap * t107 - t80 * t89 * ap_ap)) + T(2) * t79 * ab_ap * t109 + t79 * t102 * ap_ap) - T(2) * t79 * t110 * ab_ap) - (T(8) / T(15)) * t119 * t114 * t79 * t103;
    const T t120 = t83 * t83;
    const T t121 = t87 * t87;
    const T t122 = T(8) * t80 * t92 * ab_ab + T(35) * t81 * ab_ap * t120 + T(35) * t85 * t121 * a_minus_b;
    const T t123 = T(35) * t81 * t120 + t80 * t122 * ab_ap - T(35) * t85 * t121;
    const T t124 = T(2) * t79 * ab_ap * t123 + T(9) * t80 * t92 - t80 * t122 * ap_ap;
    const T t125 = T(2) * t124 * t79 * ab_ap - t79 * t123 * ap_ap - T(9) * t79 * t93;
    const T t126 = t124 * t79 * ap_ap + T(3) * t79 * t94 - T(2) * t125 * t79 * ab_ap;
    const T t127 = t125 * t79 * ap_ap + T(3) * t96 * t79 + T(2) * t126 * t79 * ab_ap;
    const T t128 = T(2) * t79 * ab_ap * t127 + T(3) * t98 * t79 - t126 * t79 * ap_ap;
    const T t129 = t79 * t127 * ap_ap - T(3) * t79 * t103 - T(2) * t79 * t128 * ab_ap;
    const T t130 = T(2) * t129 * t79 * ab_ap + t79 * t128 * ap_ap + T(3) * t104 * t79;
    G_ap = (T(8) / T(315)) * delta_tau * t116 * t79 * t123 + (T(8) / T(45)) * t77 * t125 * t113 * t79 + (T(1) / T(315)) * t118 * t130 * t79 + (T(4) / T(45)) * t76 * t115 * t124 * t79 + (T(8) / T(315)) * t106 * t129 * tau_lo * t79 + (T(1) / T(315)) * t112 * t80 * t122 - (T(8) / T(45)) * t119 * t114 * t79 * t127 - (T(4) / T(45)) * t78 * t105 * t79 * t128 - (T(2) / T(9)) * t117 * t111 * t126 * t79;
    G_ab = (T(1) / T(315)) * t118 * t79 * (T(3) * t79 * t110 + T(2) * t130 * t79 * ab_ap - t129 * t79 * ap_ap) + (T(8) / T(315)) * delta_tau * t116 * t124 * t79 + (T(4) / T(45)) * t76 * t125 * t115 * t79 + (T(8) / T(315)) * t106 * tau_lo * t130 * t79 + (T(4) / T(45)) * t78 * t129 * t105 * t79 + (T(1) / T(315)) * t112 * t79 * t123 - (T(8) / T(45)) * t77 * t113 * t126 * t79 - (T(8) / T(45)) * t119 * t114 * t79 * t128 - (T(2) / T(9)) * t117 * t111 * t79 * t127;
  }
  const T t131 = in.sigma * in.sigma;
  const T t132 = t131 * t131;
  const T t133 = t132 * t132;
  const T t134 = t133 * in.sigma;
  const T g_factor = -T(9) * length * t134;
  f = length * t134 * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 95 +, 278 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 300 +, 513 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i10_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 9, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = t8 * tau_lo;
    const T t11 = t9 * delta_tau;
    const T t12 = t4 * t4;
    const T t13 = t6 * t6;
    const T t14 = t13 * tau_lo;
    const T t15 = t12 * t12;
    const T t16 = t15 * delta_tau;
    const T t17 = t12 * delta_tau;
    const T t18 = t13 * t13;
    const T t19 = t18 * tau_lo;
    F = T(84) * M_flat[3] * t5 * t8 + T(84) * t9 * t7 * M_flat[6] + T(36) * t4 * t10 * M_flat[2] + T(36) * M_flat[7] * t11 * t6 + T(126) * M_flat[4] * t12 * t14 + T(9) * t15 * tau_lo * M_flat[8] + M_flat[9] * t16 + T(126) * t17 * t13 * M_flat[5] + M_flat[0] * t19 + T(9) * M_flat[1] * delta_tau * t18;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t20 = delta_tau * delta_tau;
    const T t21 = J_downward<T>(10, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t22 = t0 * t0;
    const T t23 = t22 * t22;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(8) * ab_ap * t21 + t23 - t26;
    const T t28 = T(1) / ab_ab;
    const T t29 = T(8) * cross_cross * t21 - ab_ap * t23 - a_minus_b * t26;
    const T t30 = T(7) * ab_ap * t27 * t28 + T(4) * t29 * t28 - T(28) * ap_ap * t21;
    const T t31 = tau_lo * tau_lo;
    const T t32 = t31 * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = t31 * t31;
    const T t36 = t35 * t35;
    const T t37 = t36 * tau_lo;
    const T t38 = t22 * t0;
    const T t39 = t25 * t24;
    const T t40 = T(6) * ab_ap * t29 * t28 + T(7) * t38 - T(7) * t39;
    const T t41 = T(21) * ap_ap * t27 * t28 - T(4) * t40 * t28 - T(12) * ab_ap * t30 * t28;
    const T t42 = T(6) * cross_cross * t29 * t28 - T(7) * a_minus_b * t39 - T(7) * ab_ap * t38;
    const T t43 = T(15) * ap_ap * t29 * t28 - T(3) * t42 * t28 - T(5) * t40 * ab_ap * t28;
    const T t44 = T(15) * ap_ap * t30 * t28 + T(5) * ab_ap * t41 * t28 + T(4) * t43 * t28;
    const T t45 = T(4) * ab_ap * t42 * t28 + T(35) * t22 - T(35) * t25;
    const T t46 = T(10) * t40 * ap_ap * t28 + T(8) * ab_ap * t43 * t28 - T(3) * t28 * t45;
    const T t47 = T(5) * ap_ap * t41 * t28 - T(4) * ab_ap * t44 * t28 - T(2) * t46 * t28;
    const T t48 = t20 * t20;
    const T t49 = t48 * delta_tau;
    const T t50 = t20 * delta_tau;
    const T t51 = t50 * t50;
    const T t52 = T(4) * cross_cross * t42 * t28 - T(35) * ab_ap * t22 - T(35) * a_minus_b * t25;
    const T t53 = T(2) * t52 * t28 + T(3) * ab_ap * t28 * t45 - T(6) * ap_ap * t42 * t28;
    const T t54 = t53 * t28 + T(2) * ap_ap * t43 * t28 - ab_ap * t46 * t28;
    const T t55 = T(2) * t54 * t28 + ab_ap * t47 * t28 + ap_ap * t44 * t28;
    const T t56 = t35 * tau_lo;
    const T t57 = T(105) * ab_ap * t0 + T(105) * a_minus_b * t24 - T(2) * t52 * cross_cross * t28;
    const T t58 = T(105) * t24 - T(105) * t0 - T(2) * ab_ap * t52 * t28;
    const T t59 = t28 * t57 + t52 * ap_ap * t28 + ab_ap * t58 * t28;
    const T t60 = T(2) * t58 * t28 + T(3) * ap_ap * t28 * t45 - T(4) * ab_ap * t53 * t28;
    const T t61 = ap_ap * t53 * t28 + ab_ap * t60 * t28 + T(2) * t28 * t59;
    const T t62 = T(4) * ab_ap * t54 * t28 + ap_ap * t46 * t28 - t60 * t28;
    const T t63 = ab_ap * t62 * t28 - t61 * t28 - t54 * ap_ap * t28;
    const T t64 = ap_ap * t47 * t28 - T(4) * ab_ap * t28 * t55 - T(2) * t62 * t28;
    const T t65 = ap_ap * t28 * t55 + ab_ap * t64 * t28 - T(2) * t63 * t28;
    const T t66 = t48 * t48;
    const T t67 = t66 * delta_tau;
    const T t68 = t51 * delta_tau;
    F = (T(9) / T(7)) * t20 * t30 * t34 * t28 + t37 * t21 + (T(3) / T(20)) * t47 * t49 * t35 * t28 + (T(1) / T(5)) * t51 * t32 * t28 * t55 + (T(9) / T(8)) * t27 * delta_tau * t36 * t28 - (T(3) / T(10)) * t44 * t48 * t56 * t28 - (T(1) / T(2)) * t41 * t50 * t33 * t28 - (T(1) / T(840)) * (T(2) * ((T(2) * t28 * ((T(2) * ab_ap * t28 * t57 - T(105) * log_ratio) * t28 + T(4) * ab_ap * t28 * t59 - t58 * ap_ap * t28) + T(4) * ab_ap * t61 * t28 - ap_ap * t60 * t28) * t28 + t62 * ap_ap * t28 - T(4) * t63 * ab_ap * t28) * t28 + T(4) * t65 * ab_ap * t28 - ap_ap * t64 * t28) * t67 * t28 - (T(3) / T(70)) * t68 * t64 * t31 * t28 - (T(3) / T(140)) * t65 * t66 * tau_lo * t28;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t69 = sqrt(cross_cross);
    const T t70 = T(1) / t69;
    const T J2 = t70 * atan2(t69, ap_bp);
    const T t71 = t0 * t0;
    const T t72 = T(1) / bp_bp;
    const T t73 = t72 * t72;
    const T t74 = T(1) / cross_cross;
    const T t75 = ab_ap * t0 + a_minus_b * t72 + J2 * ab_ab;
    const T t76 = T(2) * ab_ap * t71 + T(2) * a_minus_b * t73 + T(3) * t74 * t75 * ab_ab;
    const T t77 = t73 * t72;
    const T t78 = t71 * t0;
    const T t79 = T(5) * t76 * t74 * ab_ab + T(8) * a_minus_b * t77 + T(8) * ab_ap * t78;
    const T t80 = t71 * t71;
    const T t81 = t73 * t73;
    const T t82 = T(7) * t79 * t74 * ab_ab + T(48) * ab_ap * t80 + T(48) * a_minus_b * t81;
    const T t83 = tau_lo * tau_lo;
    const T t84 = t83 * t83;
    const T t85 = t84 * t84;
    const T t86 = t85 * tau_lo;
    const T t87 = delta_tau * delta_tau;
    const T t88 = t87 * delta_tau;
    const T t89 = t88 * t88;
    const T t90 = t83 * tau_lo;
    const T t91 = T(1) / ab_ab;
    const T t92 = ab_ap * t79 * t74 + T(8) * t78 - T(8) * t77;
    const T t93 = t79 * ap_ap * t74 - T(2) * ab_ap * t92 * t91 - T(6) * t76 * t74;
    const T t94 = ab_ap * t76 * t74 + T(2) * t71 - T(2) * t73;
    const T t95 = t92 * ap_ap * t91 + T(2) * ab_ap * t91 * t93 - T(6) * t94 * t91;
    const T t96 = t76 * ap_ap * t74 - T(2) * ab_ap * t94 * t91 - T(4) * t74 * t75;
    const T t97 = ap_ap * t91 * t93 - T(2) * ab_ap * t95 * t91 - T(6) * t96 * t91;
    const T t98 = T(48) * t81 - T(48) * t80 - ab_ap * t82 * t74;
    const T t99 = T(2) * ab_ap * t98 * t91 + ap_ap * t82 * t74 - T(8) * t79 * t74;
    const T t100 = T(8) * t92 * t91 + ap_ap * t98 * t91 - T(2) * ab_ap * t91 * t99;
    const T t101 = ap_ap * t91 * t99 + T(2) * ab_ap * t100 * t91 - T(8) * t91 * t93;
    const T t102 = T(2) * ab_ap * t101 * t91 - ap_ap * t100 * t91 - T(8) * t95 * t91;
    const T t103 = T(8) * t91 * t97 + T(2) * ab_ap * t91 * t102 - ap_ap * t101 * t91;
    const T t104 = t87 * t87;
    const T t105 = t84 * tau_lo;
    const T t106 = ab_ap * t74 * t75 + t0 - t72;
    const T t107 = ap_ap * t94 * t91 + T(2) * ab_ap * t96 * t91 - T(4) * t106 * t91;
    const T t108 = t95 * ap_ap * t91 + T(2) * ab_ap * t91 * t97 - T(6) * t107 * t91;
    const T t109 = ap_ap * t91 * t102 - T(2) * ab_ap * t103 * t91 - T(8) * t108 * t91;
    const T t110 = T(2) * J2 + T(2) * ab_ap * t106 * t91 - ap_ap * t74 * t75;
    const T t111 = t96 * ap_ap * t91 + T(4) * t110 * t91 - T(2) * ab_ap * t107 * t91;
    const T t112 = ap_ap * t91 * t97 - T(2) * ab_ap * t108 * t91 - T(6) * t111 * t91;
    const T t113 = T(2) * ab_ap * t109 * t91 + T(8) * t112 * t91 + ap_ap * t103 * t91;
    const T t114 = t104 * t104;
    const T t115 = t114 * delta_tau;
    const T t116 = t90 * t90;
    const T t117 = t104 * delta_tau;
    const T t118 = t116 * tau_lo;
    const T t119 = t89 * delta_tau;
    F = (T(1) / T(384)) * t82 * t74 * t86 + (T(7) / T(32)) * t89 * t90 * t103 * t91 + (T(21) / T(64)) * t101 * t104 * t105 * t91 + (T(1) / T(384)) * (t109 * ap_ap * t91 - T(8) * (t108 * ap_ap * t91 + T(2) * ab_ap * t112 * t91 - T(6) * (T(2) * ab_ap * t111 * t91 + T(4) * ((T(2) * ab_ap * J2 + log_ratio) * t91 + T(2) * ab_ap * t110 * t91 - t106 * ap_ap * t91) * t91 + ap_ap * t107 * t91) * t91) * t91 - T(2) * ab_ap * t113 * t91) * t115 * t91 + (T(7) / T(32)) * t100 * t88 * t116 * t91 + (T(21) / T(64)) * t117 * t84 * t91 * t102 - (T(3) / T(32)) * t87 * t118 * t91 * t99 - (T(3) / T(128)) * t113 * t114 * tau_lo * t91 - (T(3) / T(128)) * t98 * delta_tau * t85 * t91 - (T(3) / T(32)) * t109 * t119 * t83 * t91;
  }
  const T t120 = in.sigma * in.sigma;
  const T t121 = t120 * t120;
  const T t122 = t121 * in.sigma;
  const T t123 = t122 * t122;
  f = t123 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 120 +, 373 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 332 +, 588 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_inverse_i10_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 11> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 10, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = t3 * t3;
    const T t5 = t4 * tau_lo;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t4 * t4;
    const T t9 = t8 * tau_lo;
    const T t10 = t3 * tau_lo;
    const T t11 = t6 * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t7 * t7;
    const T t14 = t12 * delta_tau;
    const T t15 = t10 * t10;
    const T t16 = t13 * delta_tau;
    const T t17 = t7 * delta_tau;
    const T t18 = t15 * tau_lo;
    G_ap = T(126) * t5 * M_flat[4] * t7 + t9 * M_flat[0] + T(84) * t10 * M_flat[6] * t12 + T(9) * tau_lo * t13 * M_flat[8] + T(36) * t3 * M_flat[7] * t14 + T(84) * t15 * M_flat[3] * t11 + M_flat[9] * t16 + T(126) * t4 * M_flat[5] * t17 + T(36) * t18 * M_flat[2] * t6 + T(9) * t8 * M_flat[1] * delta_tau;
    G_ab = T(36) * t18 * M_flat[3] * t6 + T(84) * t15 * M_flat[4] * t11 + t9 * M_flat[1] + T(9) * tau_lo * M_flat[9] * t13 + T(9) * t8 * M_flat[2] * delta_tau + M_flat[10] * t16 + T(126) * t4 * M_flat[6] * t17 + T(84) * t10 * M_flat[7] * t12 + T(126) * t5 * M_flat[5] * t7 + T(36) * t3 * t14 * M_flat[8];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 11> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 10, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    const T t19 = tau_lo * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t20 * tau_lo;
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t20 * t20;
    const T t25 = t19 * tau_lo;
    const T t26 = t22 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t24 * tau_lo;
    const T t29 = t23 * t23;
    const T t30 = t25 * t25;
    const T t31 = t27 * delta_tau;
    const T t32 = t29 * delta_tau;
    const T t33 = t23 * delta_tau;
    const T t34 = t30 * tau_lo;
    G_ap = T(126) * t21 * M_beyond[4] * t23 + T(9) * t24 * M_beyond[1] * delta_tau + T(84) * t25 * M_beyond[6] * t27 + t28 * M_beyond[0] + T(9) * tau_lo * M_beyond[8] * t29 + T(84) * t30 * M_beyond[3] * t26 + T(36) * t19 * M_beyond[7] * t31 + M_beyond[9] * t32 + T(126) * t20 * M_beyond[5] * t33 + T(36) * t34 * M_beyond[2] * t22;
    G_ab = T(36) * t19 * M_beyond[8] * t31 + T(84) * t30 * M_beyond[4] * t26 + T(36) * t34 * M_beyond[3] * t22 + T(9) * tau_lo * M_beyond[9] * t29 + t28 * M_beyond[1] + T(9) * t24 * M_beyond[2] * delta_tau + T(126) * t21 * M_beyond[5] * t23 + T(84) * t25 * M_beyond[7] * t27 + T(126) * t20 * M_beyond[6] * t33 + M_beyond[10] * t32;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(cross_cross);
    const T t36 = T(1) / t35;
    const T J2 = atan2(t35, ap_bp) * t36;
    const T t37 = tau_lo * tau_lo;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = t39 * tau_lo;
    const T t41 = T(1) / cross_cross;
    const T t42 = T(1) / ap_ap;
    const T t43 = t42 * t42;
    const T t44 = t43 * t42;
    const T t45 = T(1) / bp_bp;
    const T t46 = t45 * t45;
    const T t47 = t46 * t45;
    const T t48 = a_minus_b * t45 + ab_ap * t42 + ab_ab * J2;
    const T t49 = T(2) * ab_ap * t43 + T(2) * a_minus_b * t46 + T(3) * t48 * t41 * ab_ab;
    const T t50 = T(8) * ab_ap * t44 + T(8) * a_minus_b * t47 + T(5) * t41 * ab_ab * t49;
    const T t51 = t43 * t43;
    const T t52 = t46 * t46;
    const T t53 = T(7) * t41 * t50 * ab_ab + T(48) * ab_ap * t51 + T(48) * a_minus_b * t52;
    const T t54 = t51 * t42;
    const T t55 = t52 * t45;
    const T t56 = T(3) * t41 * t53 * ab_ab + T(128) * ab_ap * t54 + T(128) * a_minus_b * t55;
    const T t57 = T(48) * t51 + ab_ap * t41 * t53 - T(48) * t52;
    const T t58 = T(1) / ab_ab;
    const T t59 = ap_ap * t41 * t53 - T(8) * t41 * t50 - T(2) * ab_ap * t57 * t58;
    const T t60 = ab_ap * t41 * t50 + T(8) * t44 - T(8) * t47;
    const T t61 = t57 * ap_ap * t58 + T(2) * t59 * ab_ap * t58 - T(8) * t58 * t60;
    const T t62 = ab_ap * t41 * t49 + T(2) * t43 - T(2) * t46;
    const T t63 = ap_ap * t41 * t50 - T(2) * ab_ap * t58 * t60 - T(6) * t41 * t49;
    const T t64 = T(6) * t58 * t62 - ap_ap * t58 * t60 - T(2) * ab_ap * t58 * t63;
    const T t65 = T(8) * t58 * t63 + T(2) * ab_ap * t61 * t58 - t59 * ap_ap * t58;
    const T t66 = ap_ap * t61 * t58 + T(8) * t64 * t58 - T(2) * ab_ap * t65 * t58;
    const T t67 = ab_ap * t41 * t56 + T(128) * t54 - T(128) * t55;
    const T t68 = T(10) * t41 * t53 + T(6) * ab_ap * t67 * t58 - T(3) * ap_ap * t41 * t56;
    const T t69 = T(3) * ap_ap * t67 * t58 - T(10) * t57 * t58 - T(2) * ab_ap * t68 * t58;
    const T t70 = t68 * ap_ap * t58 + T(2) * ab_ap * t69 * t58 + T(10) * t59 * t58;
    const T t71 = T(10) * t61 * t58 + T(2) * ab_ap * t70 * t58 - ap_ap * t69 * t58;
    const T t72 = t70 * ap_ap * t58 - T(2) * ab_ap * t71 * t58 - T(10) * t65 * t58;
    const T t73 = T(10) * t66 * t58 + T(2) * ab_ap * t72 * t58 + ap_ap * t71 * t58;
    const T t74 = delta_tau * delta_tau;
    const T t75 = t74 * delta_tau;
    const T t76 = t75 * t75;
    const T t77 = t76 * delta_tau;
    const T t78 = T(4) * t48 * t41 + T(2) * ab_ap * t58 * t62 - ap_ap * t41 * t49;
    const T t79 = ap_ap * t58 * t63 + T(2) * t64 * ab_ap * t58 + T(6) * t78 * t58;
    const T t80 = T(8) * t79 * t58 + T(2) * t66 * ab_ap * t58 + ap_ap * t65 * t58;
    const T t81 = T(10) * t58 * t80 + T(2) * ab_ap * t73 * t58 - t72 * ap_ap * t58;
    const T t82 = t74 * t74;
    const T t83 = t82 * t82;
    const T t84 = t37 * tau_lo;
    const T t85 = t84 * t84;
    const T t86 = t85 * tau_lo;
    const T t87 = t82 * delta_tau;
    const T t88 = t38 * tau_lo;
    const T t89 = t83 * delta_tau;
    const T t90 = t45 - t42 - ab_ap * t48 * t41;
    const T t91 = ap_ap * t58 * t62 + T(4) * t90 * t58 - T(2) * ab_ap * t78 * t58;
    const T t92 = t64 * ap_ap * t58 + T(6) * t91 * t58 - T(2) * ab_ap * t79 * t58;
    const T t93 = t66 * ap_ap * t58 + T(8) * t92 * t58 - T(2) * ab_ap * t58 * t80;
    const T t94 = ap_ap * t73 * t58 + T(10) * t58 * t93 - T(2) * t81 * ab_ap * t58;
    G_ap = (T(1) / T(1280)) * t40 * t41 * t56 + (T(3) / T(320)) * t37 * t73 * t58 * t77 + (T(3) / T(1280)) * tau_lo * t81 * t58 * t83 + (T(7) / T(320)) * t84 * t72 * t58 * t76 + (T(3) / T(320)) * t86 * t68 * t58 * t74 + (T(9) / T(1280)) * t39 * t67 * t58 * delta_tau - (T(21) / T(640)) * t38 * t71 * t58 * t87 - (T(21) / T(640)) * t88 * t70 * t58 * t82 - (T(1) / T(3840)) * t58 * t89 * t94 - (T(7) / T(320)) * t85 * t69 * t58 * t75;
    G_ab = (T(21) / T(640)) * t38 * t72 * t58 * t87 + (T(3) / T(320)) * t37 * t81 * t58 * t77 + (T(7) / T(320)) * t84 * t73 * t58 * t76 + (T(3) / T(1280)) * t39 * t68 * t58 * delta_tau + (T(1) / T(1280)) * t40 * t67 * t58 - (T(7) / T(320)) * t85 * t70 * t58 * t75 - (T(3) / T(320)) * t86 * t69 * t58 * t74 - (T(1) / T(3840)) * (t81 * ap_ap * t58 + T(10) * (T(8) * (T(2) * ab_ap * t92 * t58 + ap_ap * t79 * t58 + T(6) * (T(4) * (T(2) * t90 * ab_ap * t58 + t48 * ap_ap * t41 - T(2) * J2) * t58 + t78 * ap_ap * t58 + T(2) * ab_ap * t91 * t58) * t58) * t58 + ap_ap * t58 * t80 + T(2) * ab_ap * t58 * t93) * t58 + T(2) * ab_ap * t58 * t94) * t58 * t89 - (T(3) / T(1280)) * tau_lo * t58 * t83 * t94 - (T(21) / T(640)) * t88 * t71 * t58 * t82;
  }
  const T t95 = in.sigma * in.sigma;
  const T t96 = t95 * t95;
  const T t97 = t96 * in.sigma;
  const T t98 = t97 * t97;
  const T g_factor = -T(10) * t98 * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 138 +, 443 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 561 +, 888 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_inverse_i10_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T ab0 = end_b[0] - end_a[0];
  const T ap0 = in.p[0] - end_a[0];
  const T bp0 = in.p[0] - end_b[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ap1 = in.p[1] - end_a[1];
  const T bp1 = in.p[1] - end_b[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ap2 = in.p[2] - end_a[2];
  const T bp2 = in.p[2] - end_b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 22> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 10, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = tau_lo * tau_lo;
    const T t6 = t5 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t5 * t5;
    const T t10 = t9 * t9;
    const T t11 = t4 * delta_tau;
    const T t12 = t4 * t4;
    const T t13 = t12 * t12;
    const T t14 = t13 * delta_tau;
    const T t15 = t12 * delta_tau;
    const T t16 = t10 * tau_lo;
    const T t17 = t11 * t11;
    const T t18 = t17 * delta_tau;
    const T t19 = t9 * tau_lo;
    F = T(36) * M_flat[2] * t4 * t8 + T(9) * delta_tau * t10 * M_flat[1] + T(84) * t11 * t7 * M_flat[3] + T(9) * M_flat[8] * t13 * tau_lo + t14 * M_flat[9] + T(126) * M_flat[5] * t15 * t9 + t16 * M_flat[0] + T(36) * t18 * t5 * M_flat[7] + T(84) * t17 * t6 * M_flat[6] + T(126) * t12 * t19 * M_flat[4];
    G_ap = t14 * M_flat[20] + T(9) * t13 * tau_lo * M_flat[19] + T(84) * t11 * t7 * M_flat[14] + T(126) * t15 * t9 * M_flat[16] + T(36) * t4 * t8 * M_flat[13] + t16 * M_flat[11] + T(36) * M_flat[18] * t18 * t5 + T(84) * t17 * t6 * M_flat[17] + T(126) * M_flat[15] * t12 * t19 + T(9) * delta_tau * M_flat[12] * t10;
    G_ab = M_flat[21] * t14 + T(9) * t13 * tau_lo * M_flat[20] + T(126) * t12 * t19 * M_flat[16] + T(84) * M_flat[15] * t11 * t7 + T(126) * t15 * t9 * M_flat[17] + T(36) * t4 * t8 * M_flat[14] + M_flat[12] * t16 + T(9) * delta_tau * t10 * M_flat[13] + T(84) * M_flat[18] * t17 * t6 + T(36) * t18 * t5 * M_flat[19];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t20 = T(1) / ab_ab;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t0 * t0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t0;
    const T t27 = t23 * t21;
    const T t28 = J_downward<T>(12, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t29 = t26 * ab_ap + t27 * a_minus_b - T(10) * cross_cross * t28;
    const T t30 = T(9) * t23 * a_minus_b + T(9) * t25 * ab_ap + T(8) * cross_cross * t20 * t29;
    const T t31 = T(9) * t25 - T(9) * t23 - T(8) * t20 * t29 * ab_ap;
    const T t32 = T(4) * t30 * t20 - T(28) * ap_ap * t20 * t29 - T(7) * t31 * t20 * ab_ap;
    const T t33 = t24 * t0;
    const T t34 = t22 * t21;
    const T t35 = T(21) * t33 - T(2) * t30 * t20 * ab_ap - T(21) * t34;
    const T t36 = T(2) * t30 * cross_cross * t20 + T(21) * t33 * ab_ap + T(21) * t34 * a_minus_b;
    const T t37 = T(5) * t30 * ap_ap * t20 + T(5) * t20 * t35 * ab_ap - T(3) * t20 * t36;
    const T t38 = T(4) * t20 * t32 * ab_ap + T(7) * ap_ap * t31 * t20 - T(4) * t20 * t35;
    const T t39 = T(5) * ap_ap * t20 * t32 + T(4) * t37 * t20 - T(5) * t20 * t38 * ab_ap;
    const T t40 = T(4) * t20 * t36 * ab_ap + T(105) * t22 - T(105) * t24;
    const T t41 = T(8) * t37 * t20 * ab_ap - T(10) * ap_ap * t20 * t35 - T(3) * t20 * t40;
    const T t42 = T(4) * t20 * t39 * ab_ap + T(5) * ap_ap * t20 * t38 + T(2) * t41 * t20;
    const T t43 = T(4) * cross_cross * t20 * t36 + T(105) * t24 * ab_ap + T(105) * t22 * a_minus_b;
    const T t44 = T(315) * t21 + T(2) * t43 * t20 * ab_ap - T(315) * t0;
    const T t45 = T(6) * ap_ap * t20 * t36 - T(2) * t43 * t20 - T(3) * t20 * ab_ap * t40;
    const T t46 = T(2) * t20 * t44 - T(3) * ap_ap * t20 * t40 - T(4) * t20 * t45 * ab_ap;
    const T t47 = t20 * t45 + t41 * t20 * ab_ap - T(2) * ap_ap * t37 * t20;
    const T t48 = ap_ap * t41 * t20 + t20 * t46 - T(4) * t47 * t20 * ab_ap;
    const T t49 = ap_ap * t20 * t39 - T(2) * t47 * t20 - t42 * t20 * ab_ap;
    const T t50 = t42 * ap_ap * t20 + T(2) * t20 * t48 + T(4) * t20 * ab_ap * t49;
    const T t51 = T(315) * t21 * a_minus_b + T(2) * t43 * cross_cross * t20 + T(315) * t0 * ab_ap;
    const T t52 = ap_ap * t43 * t20 - t20 * t44 * ab_ap - t20 * t51;
    const T t53 = T(2) * t52 * t20 - ap_ap * t20 * t45 - t20 * t46 * ab_ap;
    const T t54 = t20 * t48 * ab_ap + ap_ap * t47 * t20 - t20 * t53;
    const T t55 = T(2) * t54 * t20 + t20 * t50 * ab_ap - ap_ap * t20 * t49;
    const T t56 = delta_tau * delta_tau;
    const T t57 = t56 * t56;
    const T t58 = t57 * t57;
    const T t59 = t58 * delta_tau;
    const T t60 = tau_lo * tau_lo;
    const T t61 = t60 * t60;
    const T t62 = t61 * tau_lo;
    const T t63 = t61 * t61;
    const T t64 = t57 * delta_tau;
    const T t65 = t60 * tau_lo;
    const T t66 = t65 * t65;
    const T t67 = t66 * tau_lo;
    const T t68 = t56 * delta_tau;
    const T t69 = t68 * t68;
    const T t70 = t69 * delta_tau;
    const T t71 = t63 * tau_lo;
    F = (T(1) / T(2520)) * (ap_ap * t20 * t50 + T(2) * (ap_ap * t20 * t48 + (T(4) * t20 * t53 * ab_ap + ap_ap * t20 * t46 + T(2) * (ap_ap * t20 * t44 + t20 * (T(315) * log_ratio - T(2) * t20 * t51 * ab_ap) + T(4) * t52 * t20 * ab_ap) * t20) * t20 - T(4) * t54 * t20 * ab_ap) * t20 - T(4) * t20 * ab_ap * t55) * t59 * t20 + (T(1) / T(10)) * t57 * t62 * t20 * t39 + (T(1) / T(8)) * t31 * delta_tau * t63 * t20 + (T(1) / T(20)) * t42 * t64 * t61 * t20 - (T(1) / T(7)) * t56 * t67 * t20 * t32 - (T(1) / T(70)) * t70 * t60 * t20 * t50 - (T(1) / T(15)) * t69 * t65 * t20 * t49 - (T(1) / T(6)) * t68 * t66 * t20 * t38 - (T(1) / T(140)) * t58 * tau_lo * t20 * t55 - (T(1) / T(9)) * t71 * t20 * t29;
    const T t72 = t26 + T(10) * ab_ap * t28 - t27;
    const T t73 = T(5) * t20 * t29 + T(45) * ap_ap * t28 - T(9) * t72 * t20 * ab_ap;
    const T t74 = T(5) * t31 * t20 - T(16) * t73 * t20 * ab_ap - T(36) * t72 * ap_ap * t20;
    const T t75 = T(28) * ap_ap * t73 * t20 + T(7) * t20 * t74 * ab_ap - T(5) * t20 * t32;
    const T t76 = T(7) * ap_ap * t20 * t74 + T(5) * t20 * t38 - T(4) * t75 * t20 * ab_ap;
    const T t77 = t76 * t20 * ab_ap + ap_ap * t75 * t20 - t20 * t39;
    const T t78 = ap_ap * t76 * t20 + t42 * t20 - T(4) * t77 * t20 * ab_ap;
    const T t79 = t20 * t49 - t20 * t78 * ab_ap - t77 * ap_ap * t20;
    const T t80 = ap_ap * t20 * t78 + t20 * t50 + T(4) * t79 * t20 * ab_ap;
    G_ap = (T(9) / T(10)) * t72 * delta_tau * t63 * t20 + (T(7) / T(30)) * t68 * t66 * t20 * t74 + t71 * t28 + (T(1) / T(70)) * t70 * t60 * t20 * t78 + (T(1) / T(10)) * t57 * t62 * t75 * t20 - (T(1) / T(20)) * t64 * t76 * t61 * t20 - (T(1) / T(140)) * t58 * t79 * tau_lo * t20 - (T(1) / T(15)) * t77 * t69 * t65 * t20 - (T(1) / T(2520)) * t59 * t20 * t80 - (T(4) / T(5)) * t73 * t56 * t67 * t20;
    G_ab = (T(1) / T(10)) * t56 * t67 * t20 * t74 + (T(1) / T(1260)) * (ap_ap * t79 * t20 - t20 * t55 - t20 * ab_ap * t80) * t59 * t20 + (T(1) / T(10)) * t72 * t71 * t20 + (T(1) / T(30)) * t69 * t65 * t20 * t78 + (T(1) / T(15)) * t68 * t66 * t75 * t20 - (T(1) / T(5)) * t73 * delta_tau * t63 * t20 - (T(1) / T(10)) * t77 * t64 * t61 * t20 - (T(1) / T(35)) * t70 * t79 * t60 * t20 - (T(1) / T(20)) * t57 * t76 * t62 * t20 - (T(1) / T(280)) * t58 * tau_lo * t20 * t80;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t81 = sqrt(cross_cross);
    const T t82 = T(1) / t81;
    const T J2 = atan2(t81, ap_bp) * t82;
    const T t83 = tau_lo * tau_lo;
    const T t84 = t83 * t83;
    const T t85 = t84 * t84;
    const T t86 = T(1) / ab_ab;
    const T t87 = t0 * t0;
    const T t88 = t87 * t87;
    const T t89 = T(1) / bp_bp;
    const T t90 = t89 * t89;
    const T t91 = t90 * t90;
    const T t92 = T(1) / cross_cross;
    const T t93 = t89 * a_minus_b + t0 * ab_ap + ab_ab * J2;
    const T t94 = T(3) * t93 * t92 * ab_ab + T(2) * t87 * ab_ap + T(2) * t90 * a_minus_b;
    const T t95 = t87 * t0;
    const T t96 = t90 * t89;
    const T t97 = T(5) * t94 * t92 * ab_ab + T(8) * t95 * ab_ap + T(8) * t96 * a_minus_b;
    const T t98 = T(48) * t91 * a_minus_b + T(48) * t88 * ab_ap + T(7) * t92 * t97 * ab_ab;
    const T t99 = T(48) * t88 + t98 * t92 * ab_ap - T(48) * t91;
    const T t100 = T(2) * t87 + t94 * t92 * ab_ap - T(2) * t90;
    const T t101 = T(4) * t93 * t92 + T(2) * t100 * t86 * ab_ap - t94 * ap_ap * t92;
    const T t102 = T(8) * t95 + t92 * t97 * ab_ap - T(8) * t96;
    const T t103 = T(6) * t94 * t92 + T(2) * t102 * t86 * ab_ap - ap_ap * t92 * t97;
    const T t104 = ap_ap * t102 * t86 - T(2) * t103 * t86 * ab_ap - T(6) * t100 * t86;
    const T t105 = T(6) * t101 * t86 - ap_ap * t103 * t86 - T(2) * t86 * ab_ap * t104;
    const T t106 = T(8) * t92 * t97 + T(2) * t86 * ab_ap * t99 - t98 * ap_ap * t92;
    const T t107 = ap_ap * t86 * t99 - T(8) * t102 * t86 - T(2) * t106 * t86 * ab_ap;
    const T t108 = ap_ap * t106 * t86 + T(2) * t86 * ab_ap * t107 - T(8) * t103 * t86;
    const T t109 = T(8) * t86 * t104 + T(2) * t108 * t86 * ab_ap - ap_ap * t86 * t107;
    const T t110 = T(8) * t86 * t105 + ap_ap * t108 * t86 - T(2) * t109 * t86 * ab_ap;
    const T t111 = t89 - t0 - t93 * t92 * ab_ap;
    const T t112 = T(4) * t111 * t86 + t100 * ap_ap * t86 - T(2) * t101 * t86 * ab_ap;
    const T t113 = T(6) * t112 * t86 - ap_ap * t86 * t104 - T(2) * t86 * ab_ap * t105;
    const T t114 = T(2) * t86 * t110 * ab_ap + ap_ap * t109 * t86 - T(8) * t86 * t113;
    const T t115 = delta_tau * delta_tau;
    const T t116 = t115 * delta_tau;
    const T t117 = t116 * t116;
    const T t118 = t117 * delta_tau;
    const T t119 = t83 * tau_lo;
    const T t120 = t119 * t119;
    const T t121 = t120 * tau_lo;
    const T t122 = t115 * t115;
    const T t123 = t122 * t122;
    const T t124 = T(2) * t111 * t86 * ab_ap + t93 * ap_ap * t92 - T(2) * J2;
    const T t125 = ap_ap * t101 * t86 + T(4) * t124 * t86 + T(2) * t112 * t86 * ab_ap;
    const T t126 = T(6) * t86 * t125 + T(2) * t86 * ab_ap * t113 + ap_ap * t86 * t105;
    const T t127 = T(2) * t114 * t86 * ab_ap - T(8) * t86 * t126 - ap_ap * t86 * t110;
    const T t128 = t85 * tau_lo;
    const T t129 = t122 * delta_tau;
    const T t130 = t84 * tau_lo;
    const T t131 = t123 * delta_tau;
    F = (T(3) / T(128)) * delta_tau * t85 * t86 * t99 + (T(3) / T(32)) * t114 * t118 * t83 * t86 + (T(3) / T(32)) * t115 * t121 * t106 * t86 + (T(3) / T(128)) * t123 * tau_lo * t86 * t127 + (T(1) / T(384)) * t98 * t92 * t128 + (T(7) / T(32)) * t117 * t119 * t86 * t110 - (T(21) / T(64)) * t129 * t84 * t109 * t86 - (T(21) / T(64)) * t108 * t122 * t130 * t86 - (T(1) / T(384)) * t131 * t86 * (ap_ap * t114 * t86 - T(2) * t86 * ab_ap * t127 - T(8) * t86 * (T(6) * (T(4) * (ap_ap * t111 * t86 + t86 * (log_ratio + T(2) * ab_ap * J2) - T(2) * t124 * t86 * ab_ap) * t86 + ap_ap * t112 * t86 - T(2) * t86 * ab_ap * t125) * t86 + ap_ap * t86 * t113 - T(2) * t86 * ab_ap * t126)) - (T(7) / T(32)) * t116 * t120 * t86 * t107;
    const T t132 = t88 * t0;
    const T t133 = t91 * t89;
    const T t134 = T(128) * t132 * ab_ap + T(128) * t133 * a_minus_b + T(3) * t98 * t92 * ab_ab;
    const T t135 = T(128) * t132 + t92 * t134 * ab_ap - T(128) * t133;
    const T t136 = T(10) * t98 * t92 + T(6) * t86 * t135 * ab_ap - T(3) * ap_ap * t92 * t134;
    const T t137 = T(10) * t86 * t99 + T(2) * t86 * t136 * ab_ap - T(3) * ap_ap * t86 * t135;
    const T t138 = T(10) * t106 * t86 + T(2) * t86 * ab_ap * t137 - ap_ap * t86 * t136;
    const T t139 = T(10) * t86 * t107 + ap_ap * t86 * t137 - T(2) * t86 * ab_ap * t138;
    const T t140 = T(10) * t108 * t86 + T(2) * t139 * t86 * ab_ap + ap_ap * t86 * t138;
    const T t141 = T(10) * t109 * t86 + T(2) * t86 * t140 * ab_ap - ap_ap * t139 * t86;
    const T t142 = ap_ap * t86 * t140 + T(10) * t86 * t110 - T(2) * t86 * t141 * ab_ap;
    const T t143 = ap_ap * t86 * t141 + T(2) * t86 * t142 * ab_ap + T(10) * t114 * t86;
    G_ap = (T(1) / T(1280)) * t92 * t128 * t134 + (T(1) / T(3840)) * t143 * t131 * t86 + (T(3) / T(1280)) * t123 * tau_lo * t86 * t142 + (T(7) / T(320)) * t116 * t120 * t86 * t137 + (T(3) / T(320)) * t115 * t121 * t86 * t136 + (T(9) / T(1280)) * delta_tau * t85 * t86 * t135 + (T(21) / T(640)) * t122 * t130 * t86 * t138 - (T(21) / T(640)) * t139 * t129 * t84 * t86 - (T(7) / T(320)) * t117 * t119 * t86 * t140 - (T(3) / T(320)) * t118 * t83 * t86 * t141;
    G_ab = (T(3) / T(1280)) * delta_tau * t85 * t86 * t136 + (T(1) / T(1280)) * t128 * t86 * t135 + (T(3) / T(320)) * t115 * t121 * t86 * t137 + (T(1) / T(3840)) * t131 * t86 * (T(10) * t86 * t127 + T(2) * t143 * t86 * ab_ap - ap_ap * t86 * t142) + (T(3) / T(1280)) * t143 * t123 * tau_lo * t86 + (T(7) / T(320)) * t116 * t120 * t86 * t138 + (T(3) / T(320)) * t118 * t83 * t86 * t142 - (T(21) / T(640)) * t139 * t122 * t130 * t86 - (T(7) / T(320)) * t117 * t119 * t86 * t141 - (T(21) / T(640)) * t129 * t84 * t86 * t140;
  }
  const T t144 = in.sigma * in.sigma;
  const T t145 = t144 * t144;
  const T t146 = t145 * in.sigma;
  const T t147 = t146 * t146;
  const T g_factor = -T(10) * length * t147;
  f = F * length * t147;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

}  // namespace skelconv::generated
