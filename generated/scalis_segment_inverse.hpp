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
/// Operations: 31 +, 40 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 6970 +, 8896 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + tau_lo * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T J2 = atan2(t3, ap_bp) / t3;
    F = J2 * tau_lo + (T(1) / T(2)) * delta_tau * (log_ratio + T(2) * J2 * ab_ap) / ab_ab;
  }
  f = F * length * in.sigma * in.sigma;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 40 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 8054 +, 11067 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[0] * tau_lo + delta_tau * M_panels[1];
    G_ab = tau_lo * M_panels[1] + M_panels[2] * delta_tau;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[0] * tau_lo + delta_tau * M_panels[1];
    G_ab = M_panels[2] * delta_tau + tau_lo * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = T(1) / bp_bp;
    const T t7 = ab_ap * t5 + ab_ab * J2 + a_minus_b * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = ab_ap * t7 * t8 + t5 - t6;
    const T t10 = T(1) / ab_ab;
    G_ap = (T(1) / T(2)) * t7 * t8 * tau_lo + (T(1) / T(2)) * t9 * delta_tau * t10;
    G_ab = (T(1) / T(2)) * t9 * tau_lo * t10 - (T(1) / T(2)) * (t7 * ap_ap * t8 - T(2) * t9 * ab_ap * t10 - T(2) * J2) * delta_tau * t10;
  }
  const T g_factor = -T(2) * length * in.sigma * in.sigma;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 42 +, 77 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11295 +, 15392 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + tau_lo * M_panels[0];
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ab = M_panels[5] * delta_tau + tau_lo * M_panels[4];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + M_panels[0] * tau_lo;
    G_ap = M_panels[3] * tau_lo + M_panels[4] * delta_tau;
    G_ab = M_panels[4] * tau_lo + delta_tau * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, ap_bp);
    const T t6 = T(1) / ab_ab;
    F = (T(1) / T(2)) * (log_ratio + T(2) * J2 * ab_ap) * delta_tau * t6 + J2 * tau_lo;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / bp_bp;
    const T t9 = a_minus_b * t8 + t0 * ab_ap + J2 * ab_ab;
    const T t10 = t8 - t0 - t7 * t9 * ab_ap;
    G_ap = (T(1) / T(2)) * t7 * tau_lo * t9 - (T(1) / T(2)) * delta_tau * t6 * t10;
    G_ab = (T(1) / T(2)) * delta_tau * t6 * (T(2) * J2 - ap_ap * t7 * t9 - T(2) * t6 * t10 * ab_ap) - (T(1) / T(2)) * tau_lo * t6 * t10;
  }
  const T t11 = in.sigma * in.sigma;
  const T g_factor = -T(2) * t11 * length;
  f = t11 * F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 35 +, 58 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 8050 +, 12145 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = delta_tau * delta_tau;
    F = T(2) * M_panels[1] * delta_tau * tau_lo + M_panels[0] * t8 + M_panels[2] * t9;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t10 = tau_lo * tau_lo;
    const T t11 = delta_tau * delta_tau;
    F = M_panels[0] * t10 + M_panels[2] * t11 + T(2) * M_panels[1] * delta_tau * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = tau_lo * tau_lo;
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + t15 * ab_ap;
    const T t17 = T(1) / ab_ab;
    const T t18 = t14 - ab_ap * t12 * t16 - t15;
    const T t19 = delta_tau * delta_tau;
    F = t12 * t13 * t16 - T(2) * t17 * t18 * delta_tau * tau_lo - t17 * (T(2) * t17 * ab_ap * t18 + ap_ap * t12 * t16 - J1) * t19;
  }
  const T t20 = in.sigma * in.sigma;
  const T t21 = t20 * in.sigma;
  f = length * F * t21;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 45 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 9134 +, 15393 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = tau_lo * tau_lo;
    G_ap = t3 * M_panels[2] + T(2) * delta_tau * M_panels[1] * tau_lo + M_panels[0] * t4;
    G_ab = T(2) * delta_tau * M_panels[2] * tau_lo + t3 * M_panels[3] + M_panels[1] * t4;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t5 = tau_lo * tau_lo;
    const T t6 = delta_tau * delta_tau;
    G_ap = T(2) * delta_tau * M_panels[1] * tau_lo + M_panels[0] * t5 + t6 * M_panels[2];
    G_ab = M_panels[1] * t5 + t6 * M_panels[3] + T(2) * delta_tau * M_panels[2] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = a_minus_b * t10 + ab_ap * t8;
    const T t13 = ab_ap * t8 * t9 + a_minus_b * t11 * t10 + T(2) * t7 * ab_ab * t12;
    const T t14 = tau_lo * tau_lo;
    const T t15 = delta_tau * delta_tau;
    const T t16 = T(1) / ab_ab;
    const T t17 = t8 * t9 + t7 * ab_ap * t13 - t11 * t10;
    const T t18 = T(3) * t7 * t12 + T(2) * t16 * t17 * ab_ap - t7 * ap_ap * t13;
    G_ap = (T(1) / T(3)) * t7 * t13 * t14 + (T(1) / T(3)) * t15 * t16 * t18 + (T(2) / T(3)) * delta_tau * t16 * t17 * tau_lo;
    G_ab = (T(2) / T(3)) * delta_tau * t16 * t18 * tau_lo + (T(1) / T(3)) * t16 * t17 * t14 - (T(1) / T(3)) * (t16 * t17 * ap_ap + T(3) * t16 * (t10 - t8 - t7 * ab_ap * t12) - T(2) * t16 * t18 * ab_ap) * t15 * t16;
  }
  const T t19 = in.sigma * in.sigma;
  const T t20 = t19 * in.sigma;
  const T g_factor = -T(3) * length * t20;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 50 +, 116 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 13457 +, 20806 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = delta_tau * delta_tau;
    F = t8 * M_panels[0] + M_panels[2] * t9 + T(2) * delta_tau * tau_lo * M_panels[1];
    G_ap = T(2) * M_panels[5] * delta_tau * tau_lo + t9 * M_panels[6] + t8 * M_panels[4];
    G_ab = T(2) * delta_tau * M_panels[6] * tau_lo + t9 * M_panels[7] + M_panels[5] * t8;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t10 = tau_lo * tau_lo;
    const T t11 = delta_tau * delta_tau;
    F = T(2) * delta_tau * tau_lo * M_panels[1] + M_panels[0] * t10 + t11 * M_panels[2];
    G_ap = M_panels[4] * t10 + M_panels[6] * t11 + T(2) * delta_tau * tau_lo * M_panels[5];
    G_ab = T(2) * M_panels[6] * delta_tau * tau_lo + t10 * M_panels[5] + M_panels[7] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r0;
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / r1;
    const T t15 = t12 * ab_ap + a_minus_b * t14;
    const T t16 = t12 + t13 * t15 * ab_ap - t14;
    const T t17 = T(1) / ab_ab;
    const T t18 = tau_lo * tau_lo;
    const T t19 = delta_tau * delta_tau;
    F = T(2) * delta_tau * tau_lo * t16 * t17 + t13 * t18 * t15 - t19 * (ap_ap * t13 * t15 - J1 - T(2) * t16 * t17 * ab_ap) * t17;
    const T t20 = t12 * t12;
    const T t21 = t14 * t14;
    const T t22 = T(2) * t13 * ab_ab * t15 + a_minus_b * t14 * t21 + t20 * t12 * ab_ap;
    const T t23 = t20 * t12 + t22 * t13 * ab_ap - t14 * t21;
    const T t24 = T(2) * t17 * t23 * ab_ap + T(3) * t13 * t15 - t22 * ap_ap * t13;
    G_ap = (T(2) / T(3)) * delta_tau * tau_lo * t17 * t23 + (T(1) / T(3)) * t19 * t24 * t17 + (T(1) / T(3)) * t22 * t13 * t18;
    G_ab = (T(1) / T(3)) * t19 * t17 * (T(3) * t16 * t17 + T(2) * t24 * t17 * ab_ap - ap_ap * t17 * t23) + (T(1) / T(3)) * t18 * t17 * t23 + (T(2) / T(3)) * delta_tau * t24 * tau_lo * t17;
  }
  const T t25 = in.sigma * in.sigma;
  const T t26 = t25 * in.sigma;
  const T g_factor = -T(3) * t26 * length;
  f = t26 * length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 41 +, 75 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 9132 +, 12148 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * tau_lo;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    F = M_panels[0] * t5 + T(3) * M_panels[1] * delta_tau * t4 + M_panels[3] * t7 + T(3) * t6 * tau_lo * M_panels[2];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = delta_tau * delta_tau;
    const T t11 = t10 * delta_tau;
    F = M_panels[0] * t9 + M_panels[3] * t11 + T(3) * t10 * tau_lo * M_panels[2] + T(3) * delta_tau * t8 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / bp_bp;
    const T t15 = a_minus_b * t14 + ab_ap * t0 + J2 * ab_ab;
    const T t16 = T(1) / cross_cross;
    const T t17 = t0 + ab_ap * t15 * t16 - t14;
    const T t18 = tau_lo * tau_lo;
    const T t19 = T(1) / ab_ab;
    const T t20 = t18 * tau_lo;
    const T t21 = T(2) * J2 + T(2) * ab_ap * t17 * t19 - t15 * ap_ap * t16;
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * delta_tau;
    F = (T(3) / T(2)) * t17 * delta_tau * t18 * t19 + (T(1) / T(2)) * t15 * t16 * t20 + (T(3) / T(2)) * t21 * t22 * tau_lo * t19 - (T(1) / T(2)) * (t17 * ap_ap * t19 - (log_ratio + T(2) * ab_ap * J2) * t19 - T(2) * t21 * ab_ap * t19) * t23 * t19;
  }
  const T t24 = in.sigma * in.sigma;
  const T t25 = t24 * t24;
  f = t25 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 54 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 10218 +, 14324 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = tau_lo * tau_lo;
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = t3 * tau_lo;
    G_ap = T(3) * delta_tau * t3 * M_panels[1] + M_panels[3] * t5 + T(3) * t4 * tau_lo * M_panels[2] + M_panels[0] * t6;
    G_ab = t5 * M_panels[4] + t6 * M_panels[1] + T(3) * M_panels[3] * t4 * tau_lo + T(3) * delta_tau * t3 * M_panels[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t7 = tau_lo * tau_lo;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t7 * tau_lo;
    G_ap = T(3) * M_panels[1] * delta_tau * t7 + T(3) * t8 * M_panels[2] * tau_lo + t9 * M_panels[3] + t10 * M_panels[0];
    G_ab = M_panels[1] * t10 + T(3) * delta_tau * M_panels[2] * t7 + T(3) * t8 * tau_lo * M_panels[3] + M_panels[4] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = delta_tau * delta_tau;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t14 * ab_ap + ab_ab * J2 + a_minus_b * t17;
    const T t20 = T(2) * a_minus_b * t18 + T(2) * t15 * ab_ap + T(3) * t19 * t16 * ab_ab;
    const T t21 = T(2) * t15 + t16 * t20 * ab_ap - T(2) * t18;
    const T t22 = T(1) / ab_ab;
    const T t23 = T(2) * t21 * t22 * ab_ap + T(4) * t19 * t16 - ap_ap * t16 * t20;
    const T t24 = t13 * delta_tau;
    const T t25 = t17 - t14 - t19 * t16 * ab_ap;
    const T t26 = T(2) * t23 * t22 * ab_ap - T(4) * t22 * t25 - ap_ap * t21 * t22;
    const T t27 = tau_lo * tau_lo;
    const T t28 = t27 * tau_lo;
    G_ap = (T(3) / T(8)) * t13 * tau_lo * t23 * t22 + (T(1) / T(8)) * t24 * t22 * t26 + (T(3) / T(8)) * t21 * delta_tau * t27 * t22 + (T(1) / T(8)) * t16 * t28 * t20;
    G_ab = (T(3) / T(8)) * delta_tau * t27 * t23 * t22 + (T(3) / T(8)) * t13 * tau_lo * t22 * t26 + (T(1) / T(8)) * t21 * t28 * t22 - (T(1) / T(8)) * t24 * t22 * (T(4) * (T(2) * t22 * t25 * ab_ap + ap_ap * t19 * t16 - T(2) * J2) * t22 + ap_ap * t23 * t22 - T(2) * t22 * ab_ap * t26);
  }
  const T t29 = in.sigma * in.sigma;
  const T t30 = t29 * t29;
  const T g_factor = -T(4) * t30 * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 60 +, 148 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15621 +, 20815 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * tau_lo;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    F = t5 * M_panels[0] + T(3) * M_panels[2] * tau_lo * t6 + t7 * M_panels[3] + T(3) * t4 * delta_tau * M_panels[1];
    G_ap = T(3) * t4 * delta_tau * M_panels[6] + T(3) * tau_lo * t6 * M_panels[7] + M_panels[8] * t7 + M_panels[5] * t5;
    G_ab = t5 * M_panels[6] + T(3) * t4 * delta_tau * M_panels[7] + M_panels[9] * t7 + T(3) * M_panels[8] * tau_lo * t6;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = tau_lo * tau_lo;
    const T t11 = t10 * tau_lo;
    F = t9 * M_panels[3] + T(3) * t10 * delta_tau * M_panels[1] + t11 * M_panels[0] + T(3) * M_panels[2] * tau_lo * t8;
    G_ap = M_panels[5] * t11 + T(3) * tau_lo * t8 * M_panels[7] + M_panels[8] * t9 + T(3) * t10 * delta_tau * M_panels[6];
    G_ab = t9 * M_panels[9] + T(3) * t10 * delta_tau * M_panels[7] + T(3) * M_panels[8] * tau_lo * t8 + t11 * M_panels[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * tau_lo;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = t0 * ab_ap + ab_ab * J2 + t17 * a_minus_b;
    const T t19 = t17 - t0 - t16 * t18 * ab_ap;
    const T t20 = T(1) / ab_ab;
    const T t21 = delta_tau * delta_tau;
    const T t22 = T(2) * t19 * t20 * ab_ap + ap_ap * t16 * t18 - T(2) * J2;
    const T t23 = t21 * delta_tau;
    F = (T(1) / T(2)) * t15 * t16 * t18 - (T(3) / T(2)) * t19 * t14 * delta_tau * t20 - (T(3) / T(2)) * tau_lo * t21 * t20 * t22 - (T(1) / T(2)) * t23 * t20 * (T(2) * t20 * t22 * ab_ap - (log_ratio + T(2) * ab_ap * J2) * t20 - ap_ap * t19 * t20);
    const T t24 = t0 * t0;
    const T t25 = t17 * t17;
    const T t26 = T(3) * t16 * ab_ab * t18 + T(2) * t25 * a_minus_b + T(2) * t24 * ab_ap;
    const T t27 = T(2) * t24 + t16 * t26 * ab_ap - T(2) * t25;
    const T t28 = T(4) * t16 * t18 + T(2) * t27 * t20 * ab_ap - ap_ap * t16 * t26;
    const T t29 = T(2) * t20 * ab_ap * t28 - T(4) * t19 * t20 - ap_ap * t27 * t20;
    G_ap = (T(3) / T(8)) * t27 * t14 * delta_tau * t20 + (T(3) / T(8)) * tau_lo * t21 * t20 * t28 + (T(1) / T(8)) * t29 * t23 * t20 + (T(1) / T(8)) * t15 * t16 * t26;
    G_ab = (T(3) / T(8)) * t14 * delta_tau * t20 * t28 + (T(1) / T(8)) * t27 * t15 * t20 + (T(3) / T(8)) * t29 * tau_lo * t21 * t20 - (T(1) / T(8)) * (ap_ap * t20 * t28 + T(4) * t20 * t22 - T(2) * t29 * t20 * ab_ap) * t23 * t20;
  }
  const T t30 = in.sigma * in.sigma;
  const T t31 = t30 * t30;
  const T g_factor = -T(4) * t31 * length;
  f = t31 * length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 47 +, 107 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 10212 +, 16476 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
    X = length * (t1 + r0 * a_minus_b) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * tau_lo;
    const T t11 = t8 * delta_tau;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    F = T(6) * M_panels[2] * t8 * t9 + T(4) * M_panels[1] * delta_tau * t10 + T(4) * M_panels[3] * t11 * tau_lo + M_panels[4] * t12 + M_panels[0] * t13;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * tau_lo;
    const T t16 = delta_tau * delta_tau;
    const T t17 = t14 * t14;
    const T t18 = t16 * delta_tau;
    const T t19 = t16 * t16;
    F = T(4) * M_panels[1] * delta_tau * t15 + T(6) * M_panels[2] * t16 * t14 + t17 * M_panels[0] + T(4) * t18 * M_panels[3] * tau_lo + M_panels[4] * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / ab_ab;
    const T t21 = T(1) / r0;
    const T t22 = T(1) / r1;
    const T t23 = t21 * ab_ap + t22 * a_minus_b;
    const T t24 = T(1) / cross_cross;
    const T t25 = ab_ap * t23 * t24 + t21 - t22;
    const T t26 = t22 * t22;
    const T t27 = t21 * t21;
    const T t28 = t26 * t22 * a_minus_b + T(2) * ab_ab * t23 * t24 + t21 * ab_ap * t27;
    const T t29 = t26 * t22 - t21 * t27 - ab_ap * t28 * t24;
    const T t30 = ap_ap * t28 * t24 + T(2) * t20 * ab_ap * t29 - T(3) * t23 * t24;
    const T t31 = T(3) * t20 * t25 + t20 * ap_ap * t29 - T(2) * t20 * ab_ap * t30;
    const T t32 = delta_tau * delta_tau;
    const T t33 = t32 * delta_tau;
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * t34;
    const T t36 = t32 * t32;
    const T t37 = t34 * tau_lo;
    F = (T(4) / T(3)) * t20 * t31 * t33 * tau_lo + (T(1) / T(3)) * t28 * t24 * t35 + (T(1) / T(3)) * t20 * (T(3) * t20 * (J1 + T(2) * t20 * ab_ap * t25 - ap_ap * t23 * t24) + T(2) * t20 * ab_ap * t31 + t20 * ap_ap * t30) * t36 - (T(4) / T(3)) * t20 * t29 * delta_tau * t37 - T(2) * t20 * t32 * t30 * t34;
  }
  const T t38 = in.sigma * in.sigma;
  const T t39 = t38 * t38;
  const T t40 = t39 * in.sigma;
  f = length * F * t40;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 61 +, 161 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 11298 +, 19730 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = t3 * delta_tau;
    const T t5 = tau_lo * tau_lo;
    const T t6 = t5 * tau_lo;
    const T t7 = t3 * t3;
    const T t8 = t5 * t5;
    G_ap = T(4) * M_panels[3] * tau_lo * t4 + T(4) * t6 * delta_tau * M_panels[1] + T(6) * t5 * t3 * M_panels[2] + t7 * M_panels[4] + M_panels[0] * t8;
    G_ab = t8 * M_panels[1] + t7 * M_panels[5] + T(6) * M_panels[3] * t5 * t3 + T(4) * tau_lo * t4 * M_panels[4] + T(4) * t6 * delta_tau * M_panels[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * tau_lo;
    const T t11 = t9 * t9;
    const T t12 = delta_tau * delta_tau;
    const T t13 = t12 * delta_tau;
    const T t14 = t12 * t12;
    G_ap = T(4) * t10 * delta_tau * M_panels[1] + t11 * M_panels[0] + T(4) * tau_lo * t13 * M_panels[3] + T(6) * t9 * t12 * M_panels[2] + M_panels[4] * t14;
    G_ab = T(6) * t9 * t12 * M_panels[3] + t11 * M_panels[1] + t14 * M_panels[5] + T(4) * t10 * delta_tau * M_panels[2] + T(4) * tau_lo * M_panels[4] * t13;
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
    const T t25 = t18 * a_minus_b + ab_ap * t21;
    const T t26 = T(2) * t24 * ab_ab * t25 + ab_ap * t21 * t22 + t18 * a_minus_b * t19;
    const T t27 = T(3) * t18 * a_minus_b * t20 + T(3) * ab_ap * t21 * t23 + T(4) * t26 * t24 * ab_ab;
    const T t28 = T(3) * t21 * t23 + t27 * t24 * ab_ap - T(3) * t18 * t20;
    const T t29 = t27 * t24 * ap_ap - T(2) * t17 * t28 * ab_ap - T(5) * t26 * t24;
    const T t30 = t18 * t19 - t21 * t22 - t26 * t24 * ab_ap;
    const T t31 = t26 * t24 * ap_ap + T(2) * t17 * t30 * ab_ap - T(3) * t24 * t25;
    const T t32 = t17 * t28 * ap_ap + T(5) * t17 * t30 + T(2) * t17 * t29 * ab_ap;
    const T t33 = t17 * t29 * ap_ap - T(5) * t17 * t31 - T(2) * t32 * t17 * ab_ap;
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * t34;
    const T t36 = t34 * tau_lo;
    const T t37 = t15 * delta_tau;
    G_ap = (T(1) / T(15)) * t16 * t17 * t33 + (T(1) / T(15)) * t27 * t35 * t24 + (T(4) / T(15)) * t36 * delta_tau * t17 * t28 - (T(4) / T(15)) * t32 * tau_lo * t37 * t17 - (T(2) / T(5)) * t34 * t15 * t17 * t29;
    G_ab = (T(4) / T(15)) * tau_lo * t37 * t17 * t33 + (T(1) / T(15)) * t35 * t17 * t28 + (T(1) / T(15)) * t16 * t17 * (t32 * t17 * ap_ap + T(5) * (t17 * t30 * ap_ap + T(3) * t17 * (t21 + t24 * t25 * ab_ap - t18) - T(2) * t17 * ab_ap * t31) * t17 + T(2) * t17 * t33 * ab_ap) - (T(2) / T(5)) * t32 * t34 * t15 * t17 - (T(4) / T(15)) * t36 * delta_tau * t17 * t29;
  }
  const T t38 = in.sigma * in.sigma;
  const T t39 = t38 * t38;
  const T t40 = t39 * in.sigma;
  const T g_factor = -T(5) * length * t40;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 70 +, 199 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 17783 +, 27309 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = -(a_minus_b - ab_ap) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = delta_tau * delta_tau;
    const T t11 = t10 * delta_tau;
    const T t12 = t8 * t8;
    const T t13 = t10 * t10;
    F = T(4) * delta_tau * t9 * M_panels[1] + T(4) * t11 * M_panels[3] * tau_lo + M_panels[0] * t12 + T(6) * M_panels[2] * t10 * t8 + t13 * M_panels[4];
    G_ap = T(4) * delta_tau * t9 * M_panels[7] + T(4) * M_panels[9] * t11 * tau_lo + M_panels[6] * t12 + t13 * M_panels[10] + T(6) * M_panels[8] * t10 * t8;
    G_ab = T(4) * M_panels[8] * delta_tau * t9 + T(6) * M_panels[9] * t10 * t8 + t12 * M_panels[7] + M_panels[11] * t13 + T(4) * t11 * M_panels[10] * tau_lo;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = tau_lo * tau_lo;
    const T t17 = t16 * tau_lo;
    const T t18 = t16 * t16;
    const T t19 = t14 * delta_tau;
    F = t15 * M_panels[4] + T(4) * delta_tau * M_panels[1] * t17 + T(6) * M_panels[2] * t14 * t16 + M_panels[0] * t18 + T(4) * M_panels[3] * t19 * tau_lo;
    G_ap = M_panels[6] * t18 + t15 * M_panels[10] + T(4) * delta_tau * M_panels[7] * t17 + T(6) * M_panels[8] * t14 * t16 + T(4) * M_panels[9] * t19 * tau_lo;
    G_ab = T(4) * t19 * M_panels[10] * tau_lo + T(4) * M_panels[8] * delta_tau * t17 + t15 * M_panels[11] + T(6) * M_panels[9] * t14 * t16 + M_panels[7] * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = T(1) / r0;
    const T t23 = T(1) / r1;
    const T t24 = t22 * ab_ap + a_minus_b * t23;
    const T t25 = T(1) / cross_cross;
    const T t26 = t23 * t23;
    const T t27 = t22 * t22;
    const T t28 = T(2) * t24 * t25 * ab_ab + t27 * t22 * ab_ap + a_minus_b * t23 * t26;
    const T t29 = t23 * t26 - t27 * t22 - t28 * t25 * ab_ap;
    const T t30 = T(1) / ab_ab;
    const T t31 = T(3) * t24 * t25 - T(2) * t29 * t30 * ab_ap - t28 * ap_ap * t25;
    const T t32 = t22 + t24 * t25 * ab_ap - t23;
    const T t33 = T(2) * t31 * t30 * ab_ap + ap_ap * t29 * t30 + T(3) * t32 * t30;
    const T t34 = tau_lo * tau_lo;
    const T t35 = t34 * t34;
    const T t36 = t20 * delta_tau;
    const T t37 = t34 * tau_lo;
    F = (T(1) / T(3)) * t21 * (T(2) * t33 * t30 * ab_ap + T(3) * (J1 + T(2) * t32 * t30 * ab_ap - ap_ap * t24 * t25) * t30 - t31 * ap_ap * t30) * t30 + (T(1) / T(3)) * t28 * t25 * t35 + T(2) * t31 * t20 * t30 * t34 + (T(4) / T(3)) * t36 * t33 * t30 * tau_lo - (T(4) / T(3)) * t29 * delta_tau * t30 * t37;
    const T t38 = t26 * t26;
    const T t39 = t27 * t27;
    const T t40 = T(4) * t28 * t25 * ab_ab + T(3) * a_minus_b * t23 * t38 + T(3) * t39 * t22 * ab_ap;
    const T t41 = t25 * t40 * ab_ap + T(3) * t39 * t22 - T(3) * t23 * t38;
    const T t42 = T(5) * t28 * t25 + T(2) * t41 * t30 * ab_ap - ap_ap * t25 * t40;
    const T t43 = T(2) * t42 * t30 * ab_ap - T(5) * t29 * t30 - ap_ap * t41 * t30;
    const T t44 = ap_ap * t42 * t30 - T(5) * t31 * t30 - T(2) * t30 * t43 * ab_ap;
    G_ap = (T(4) / T(15)) * t36 * t30 * tau_lo * t43 + (T(1) / T(15)) * t25 * t40 * t35 + (T(2) / T(5)) * t20 * t42 * t30 * t34 + (T(4) / T(15)) * t41 * delta_tau * t30 * t37 - (T(1) / T(15)) * t44 * t21 * t30;
    G_ab = (T(4) / T(15)) * delta_tau * t42 * t30 * t37 + (T(2) / T(5)) * t20 * t30 * t34 * t43 + (T(1) / T(15)) * t41 * t30 * t35 - (T(4) / T(15)) * t44 * t36 * t30 * tau_lo - (T(1) / T(15)) * (ap_ap * t30 * t43 + T(2) * t44 * t30 * ab_ap - T(5) * t33 * t30) * t21 * t30;
  }
  const T t45 = in.sigma * in.sigma;
  const T t46 = t45 * t45;
  const T t47 = t46 * in.sigma;
  const T g_factor = -T(5) * t47 * length;
  f = F * t47 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 55 +, 129 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11294 +, 15399 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = tau_lo * tau_lo;
    const T t6 = t5 * tau_lo;
    const T t7 = t4 * delta_tau;
    const T t8 = t5 * t5;
    const T t9 = t4 * t4;
    const T t10 = t9 * delta_tau;
    const T t11 = t8 * tau_lo;
    F = T(10) * t4 * t6 * M_panels[2] + T(10) * t7 * t5 * M_panels[3] + T(5) * M_panels[1] * delta_tau * t8 + t10 * M_panels[5] + T(5) * t9 * tau_lo * M_panels[4] + t11 * M_panels[0];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = delta_tau * delta_tau;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * tau_lo;
    const T t15 = t12 * delta_tau;
    const T t16 = t13 * t13;
    const T t17 = t12 * t12;
    const T t18 = t17 * delta_tau;
    const T t19 = t16 * tau_lo;
    F = T(10) * t12 * M_panels[2] * t14 + T(10) * t15 * t13 * M_panels[3] + T(5) * delta_tau * t16 * M_panels[1] + t18 * M_panels[5] + t19 * M_panels[0] + T(5) * t17 * tau_lo * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = t21 * atan2(t20, ap_bp);
    const T t22 = T(1) / cross_cross;
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = T(1) / bp_bp;
    const T t27 = a_minus_b * t26 + ab_ap * t0 + J2 * ab_ab;
    const T t28 = t0 * t0;
    const T t29 = t26 * t26;
    const T t30 = T(3) * t22 * ab_ab * t27 + T(2) * ab_ap * t28 + T(2) * a_minus_b * t29;
    const T t31 = delta_tau * delta_tau;
    const T t32 = t31 * delta_tau;
    const T t33 = T(1) / ab_ab;
    const T t34 = t0 + t22 * ab_ap * t27 - t26;
    const T t35 = T(2) * t29 - t22 * t30 * ab_ap - T(2) * t28;
    const T t36 = t22 * t30 * ap_ap + T(2) * t35 * t33 * ab_ap - T(4) * t22 * t27;
    const T t37 = T(4) * t34 * t33 + t35 * t33 * ap_ap - T(2) * t33 * t36 * ab_ap;
    const T t38 = t31 * t31;
    const T t39 = T(2) * J2 + T(2) * t34 * t33 * ab_ap - t22 * t27 * ap_ap;
    const T t40 = T(4) * t33 * t39 + T(2) * t33 * t37 * ab_ap + t33 * t36 * ap_ap;
    const T t41 = t38 * delta_tau;
    const T t42 = t23 * tau_lo;
    F = (T(1) / T(8)) * t22 * t25 * t30 + (T(5) / T(4)) * t32 * t23 * t33 * t37 + (T(5) / T(8)) * t38 * tau_lo * t40 * t33 + (T(1) / T(8)) * (T(2) * t40 * t33 * ab_ap + T(4) * (t33 * (T(2) * J2 * ab_ap + log_ratio) + T(2) * t33 * ab_ap * t39 - t34 * t33 * ap_ap) * t33 - t33 * t37 * ap_ap) * t41 * t33 - (T(5) / T(8)) * t35 * delta_tau * t24 * t33 - (T(5) / T(4)) * t31 * t42 * t33 * t36;
  }
  const T t43 = in.sigma * in.sigma;
  const T t44 = t43 * in.sigma;
  const T t45 = t44 * t44;
  f = length * t45 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 192 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 12382 +, 17581 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = t3 * t3;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t3 * delta_tau;
    const T t9 = t6 * t6;
    const T t10 = t9 * tau_lo;
    G_ap = t5 * M_panels[5] + T(10) * t3 * t7 * M_panels[2] + T(5) * t4 * tau_lo * M_panels[4] + T(10) * M_panels[3] * t8 * t6 + M_panels[0] * t10 + T(5) * delta_tau * t9 * M_panels[1];
    G_ab = T(5) * delta_tau * t9 * M_panels[2] + T(10) * M_panels[3] * t3 * t7 + T(10) * t8 * t6 * M_panels[4] + t5 * M_panels[6] + T(5) * t4 * tau_lo * M_panels[5] + t10 * M_panels[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t11 * tau_lo;
    const T t17 = t15 * delta_tau;
    const T t18 = t14 * delta_tau;
    G_ap = M_panels[0] * t13 + T(5) * delta_tau * t12 * M_panels[1] + T(5) * t15 * tau_lo * M_panels[4] + T(10) * t14 * t16 * M_panels[2] + t17 * M_panels[5] + T(10) * M_panels[3] * t18 * t11;
    G_ab = t13 * M_panels[1] + T(5) * t15 * tau_lo * M_panels[5] + T(10) * t18 * t11 * M_panels[4] + T(5) * delta_tau * t12 * M_panels[2] + T(10) * M_panels[3] * t14 * t16 + t17 * M_panels[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, ap_bp) * t20;
    const T t21 = delta_tau * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = T(1) / cross_cross;
    const T t27 = T(1) / bp_bp;
    const T t28 = a_minus_b * t27 + t24 * ab_ap + ab_ab * J2;
    const T t29 = t27 * t27;
    const T t30 = T(2) * t25 * ab_ap + T(3) * t26 * ab_ab * t28 + T(2) * a_minus_b * t29;
    const T t31 = T(2) * t25 + t26 * t30 * ab_ap - T(2) * t29;
    const T t32 = t25 * t24;
    const T t33 = t29 * t27;
    const T t34 = T(8) * t32 * ab_ap + T(5) * t26 * ab_ab * t30 + T(8) * a_minus_b * t33;
    const T t35 = T(8) * t32 + t26 * ab_ap * t34 - T(8) * t33;
    const T t36 = T(6) * t26 * t30 + T(2) * t35 * t23 * ab_ap - ap_ap * t26 * t34;
    const T t37 = T(6) * t23 * t31 + T(2) * t23 * t36 * ab_ap - ap_ap * t35 * t23;
    const T t38 = ap_ap * t26 * t30 - T(4) * t26 * t28 - T(2) * t23 * t31 * ab_ap;
    const T t39 = T(2) * t23 * t37 * ab_ap - ap_ap * t23 * t36 - T(6) * t23 * t38;
    const T t40 = tau_lo * tau_lo;
    const T t41 = t40 * t40;
    const T t42 = t40 * tau_lo;
    const T t43 = t21 * delta_tau;
    const T t44 = t41 * tau_lo;
    const T t45 = t22 * delta_tau;
    const T t46 = t27 - t24 - t26 * t28 * ab_ap;
    const T t47 = T(2) * t23 * ab_ap * t38 + T(4) * t46 * t23 + ap_ap * t23 * t31;
    const T t48 = ap_ap * t23 * t37 + T(6) * t47 * t23 - T(2) * t23 * t39 * ab_ap;
    G_ap = (T(5) / T(48)) * t22 * tau_lo * t23 * t39 + (T(5) / T(48)) * t35 * delta_tau * t41 * t23 + (T(5) / T(24)) * t21 * t42 * t23 * t36 + (T(5) / T(24)) * t43 * t40 * t23 * t37 + (T(1) / T(48)) * t26 * t44 * t34 - (T(1) / T(48)) * t45 * t48 * t23;
    G_ab = (T(5) / T(24)) * t43 * t40 * t23 * t39 + (T(1) / T(48)) * t35 * t44 * t23 + (T(5) / T(48)) * delta_tau * t41 * t23 * t36 + (T(5) / T(24)) * t21 * t42 * t23 * t37 - (T(1) / T(48)) * (T(2) * t48 * t23 * ab_ap + ap_ap * t23 * t39 - T(6) * (ap_ap * t23 * t38 - T(2) * t47 * t23 * ab_ap - T(4) * (ap_ap * t26 * t28 + T(2) * t46 * t23 * ab_ap - T(2) * J2) * t23) * t23) * t45 * t23 - (T(5) / T(48)) * t22 * t48 * tau_lo * t23;
  }
  const T t49 = in.sigma * in.sigma;
  const T t50 = t49 * in.sigma;
  const T t51 = t50 * t50;
  const T g_factor = -T(6) * length * t51;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 82 +, 232 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 19947 +, 26238 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = t4 * tau_lo;
    const T t9 = t5 * tau_lo;
    const T t10 = t6 * t6;
    const T t11 = t10 * delta_tau;
    F = T(5) * delta_tau * t5 * M_panels[1] + T(10) * t7 * t4 * M_panels[3] + T(10) * M_panels[2] * t6 * t8 + t9 * M_panels[0] + M_panels[5] * t11 + T(5) * t10 * tau_lo * M_panels[4];
    G_ap = T(5) * M_panels[8] * delta_tau * t5 + t11 * M_panels[12] + T(5) * M_panels[11] * t10 * tau_lo + T(10) * M_panels[9] * t6 * t8 + T(10) * t7 * t4 * M_panels[10] + t9 * M_panels[7];
    G_ab = M_panels[8] * t9 + T(10) * M_panels[11] * t7 * t4 + t11 * M_panels[13] + T(10) * t6 * t8 * M_panels[10] + T(5) * M_panels[9] * delta_tau * t5 + T(5) * t10 * M_panels[12] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = delta_tau * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t12 * delta_tau;
    const T t17 = t14 * tau_lo;
    const T t18 = t15 * tau_lo;
    const T t19 = t13 * delta_tau;
    F = T(5) * M_panels[4] * t13 * tau_lo + T(5) * M_panels[1] * delta_tau * t15 + T(10) * M_panels[3] * t16 * t14 + T(10) * t12 * t17 * M_panels[2] + M_panels[0] * t18 + t19 * M_panels[5];
    G_ap = T(10) * t12 * t17 * M_panels[9] + t19 * M_panels[12] + M_panels[7] * t18 + T(5) * delta_tau * t15 * M_panels[8] + T(10) * M_panels[10] * t16 * t14 + T(5) * t13 * M_panels[11] * tau_lo;
    G_ab = M_panels[13] * t19 + T(5) * delta_tau * t15 * M_panels[9] + t18 * M_panels[8] + T(10) * t16 * M_panels[11] * t14 + T(10) * M_panels[10] * t12 * t17 + T(5) * t13 * tau_lo * M_panels[12];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = atan2(t20, ap_bp) * t21;
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = T(1) / ab_ab;
    const T t26 = T(1) / bp_bp;
    const T t27 = J2 * ab_ab + a_minus_b * t26 + t0 * ab_ap;
    const T t28 = T(1) / cross_cross;
    const T t29 = t26 - t0 - t27 * t28 * ab_ap;
    const T t30 = T(2) * J2 - ap_ap * t27 * t28 - T(2) * t29 * t25 * ab_ap;
    const T t31 = t0 * t0;
    const T t32 = t26 * t26;
    const T t33 = T(3) * t27 * t28 * ab_ab + T(2) * t31 * ab_ap + T(2) * a_minus_b * t32;
    const T t34 = t28 * t33 * ab_ap + T(2) * t31 - T(2) * t32;
    const T t35 = T(4) * t27 * t28 + T(2) * t25 * ab_ap * t34 - ap_ap * t28 * t33;
    const T t36 = T(2) * t25 * t35 * ab_ap - T(4) * t29 * t25 - ap_ap * t25 * t34;
    const T t37 = T(2) * t36 * t25 * ab_ap + T(4) * t30 * t25 - ap_ap * t25 * t35;
    const T t38 = tau_lo * tau_lo;
    const T t39 = t38 * t38;
    const T t40 = t38 * tau_lo;
    const T t41 = t22 * delta_tau;
    const T t42 = t39 * tau_lo;
    F = (T(1) / T(8)) * t24 * (T(4) * t25 * (T(2) * t30 * t25 * ab_ap + (log_ratio + T(2) * J2 * ab_ap) * t25 + t29 * ap_ap * t25) + T(2) * t25 * t37 * ab_ap - ap_ap * t36 * t25) * t25 + (T(5) / T(8)) * delta_tau * t39 * t25 * t34 + (T(5) / T(4)) * t22 * t40 * t25 * t35 + (T(5) / T(4)) * t41 * t36 * t38 * t25 + (T(1) / T(8)) * t28 * t42 * t33 + (T(5) / T(8)) * t23 * tau_lo * t25 * t37;
    const T t43 = t32 * t26;
    const T t44 = t31 * t0;
    const T t45 = T(5) * t28 * ab_ab * t33 + T(8) * a_minus_b * t43 + T(8) * t44 * ab_ap;
    const T t46 = T(8) * t43 - t45 * t28 * ab_ap - T(8) * t44;
    const T t47 = ap_ap * t45 * t28 + T(2) * t46 * t25 * ab_ap - T(6) * t28 * t33;
    const T t48 = T(2) * t47 * t25 * ab_ap - t46 * ap_ap * t25 - T(6) * t25 * t34;
    const T t49 = ap_ap * t47 * t25 + T(6) * t25 * t35 - T(2) * t48 * t25 * ab_ap;
    const T t50 = T(2) * t49 * t25 * ab_ap + T(6) * t36 * t25 + t48 * ap_ap * t25;
    G_ap = (T(1) / T(48)) * t45 * t28 * t42 + (T(1) / T(48)) * t50 * t24 * t25 + (T(5) / T(48)) * t49 * t23 * tau_lo * t25 - (T(5) / T(24)) * t48 * t41 * t38 * t25 - (T(5) / T(48)) * t46 * delta_tau * t39 * t25 - (T(5) / T(24)) * t22 * t40 * t47 * t25;
    G_ab = (T(1) / T(48)) * t24 * t25 * (T(2) * t50 * t25 * ab_ap + T(6) * t25 * t37 - ap_ap * t49 * t25) + (T(5) / T(48)) * t50 * t23 * tau_lo * t25 + (T(5) / T(24)) * t49 * t41 * t38 * t25 - (T(5) / T(24)) * t48 * t22 * t40 * t25 - (T(5) / T(48)) * delta_tau * t39 * t47 * t25 - (T(1) / T(48)) * t46 * t42 * t25;
  }
  const T t51 = in.sigma * in.sigma;
  const T t52 = t51 * in.sigma;
  const T t53 = t52 * t52;
  const T g_factor = -T(6) * t53 * length;
  f = F * t53 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 63 +, 170 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 12374 +, 20807 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t11 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t8 * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t12 * tau_lo;
    F = T(6) * t10 * tau_lo * M_panels[5] + T(15) * t8 * t12 * M_panels[2] + M_panels[0] * t14 + T(20) * M_panels[3] * t15 * t13 + T(15) * M_panels[4] * t9 * t11 + t16 * M_panels[6] + T(6) * M_panels[1] * delta_tau * t17;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t18 = delta_tau * delta_tau;
    const T t19 = t18 * delta_tau;
    const T t20 = t19 * t19;
    const T t21 = t18 * t18;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t24 * tau_lo;
    const T t26 = t21 * delta_tau;
    const T t27 = t23 * t23;
    F = M_panels[6] * t20 + T(15) * M_panels[4] * t21 * t22 + T(20) * M_panels[3] * t19 * t23 + T(6) * delta_tau * M_panels[1] * t25 + T(6) * t26 * tau_lo * M_panels[5] + M_panels[0] * t27 + T(15) * t18 * t24 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = T(1) / cross_cross;
    const T t35 = t28 * a_minus_b + ab_ap * t31;
    const T t36 = t28 * a_minus_b * t29 + ab_ap * t32 * t31 + T(2) * t34 * t35 * ab_ab;
    const T t37 = T(4) * t36 * t34 * ab_ab + T(3) * ab_ap * t33 * t31 + T(3) * t28 * a_minus_b * t30;
    const T t38 = T(3) * t28 * t30 - T(3) * t33 * t31 - ab_ap * t34 * t37;
    const T t39 = T(1) / ab_ab;
    const T t40 = ab_ap * t36 * t34 + t32 * t31 - t28 * t29;
    const T t41 = T(2) * ab_ap * t38 * t39 + ap_ap * t34 * t37 - T(5) * t36 * t34;
    const T t42 = ap_ap * t38 * t39 + T(5) * t40 * t39 - T(2) * ab_ap * t41 * t39;
    const T t43 = delta_tau * delta_tau;
    const T t44 = t43 * delta_tau;
    const T t45 = tau_lo * tau_lo;
    const T t46 = t45 * tau_lo;
    const T t47 = t43 * t43;
    const T t48 = T(2) * ab_ap * t40 * t39 + T(3) * t34 * t35 - t36 * ap_ap * t34;
    const T t49 = T(5) * t39 * t48 + ap_ap * t41 * t39 + T(2) * ab_ap * t42 * t39;
    const T t50 = t46 * t46;
    const T t51 = t31 + ab_ap * t34 * t35 - t28;
    const T t52 = ap_ap * t40 * t39 - T(3) * t39 * t51 - T(2) * ab_ap * t39 * t48;
    const T t53 = T(5) * t52 * t39 + t42 * ap_ap * t39 - T(2) * ab_ap * t39 * t49;
    const T t54 = t47 * delta_tau;
    const T t55 = t44 * t44;
    const T t56 = t45 * t45;
    const T t57 = t56 * tau_lo;
    F = (T(4) / T(3)) * t42 * t44 * t46 * t39 + t47 * t45 * t39 * t49 + (T(1) / T(15)) * t34 * t50 * t37 - (T(2) / T(5)) * t53 * t54 * tau_lo * t39 - (T(1) / T(15)) * (T(2) * ab_ap * t53 * t39 + ap_ap * t39 * t49 + T(5) * (T(2) * t52 * ab_ap * t39 + T(3) * t39 * (ap_ap * t34 * t35 - J1 - T(2) * ab_ap * t39 * t51) + ap_ap * t39 * t48) * t39) * t55 * t39 - t43 * t41 * t56 * t39 - (T(2) / T(5)) * t38 * delta_tau * t57 * t39;
  }
  const T t58 = in.sigma * in.sigma;
  const T t59 = t58 * in.sigma;
  const T t60 = t59 * t59;
  const T t61 = t60 * in.sigma;
  f = F * t61 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 81 +, 243 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 13462 +, 24067 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = t3 * t3;
    const T t5 = tau_lo * tau_lo;
    const T t6 = t4 * delta_tau;
    const T t7 = t5 * t5;
    const T t8 = t7 * tau_lo;
    const T t9 = t3 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t5 * tau_lo;
    const T t12 = t11 * t11;
    G_ap = T(15) * t4 * t5 * M_panels[4] + T(6) * t6 * tau_lo * M_panels[5] + T(6) * delta_tau * t8 * M_panels[1] + T(15) * t3 * t7 * M_panels[2] + t10 * M_panels[6] + T(20) * t9 * t11 * M_panels[3] + M_panels[0] * t12;
    G_ab = t12 * M_panels[1] + T(15) * t3 * t7 * M_panels[3] + T(20) * t9 * t11 * M_panels[4] + T(15) * t4 * t5 * M_panels[5] + T(6) * delta_tau * t8 * M_panels[2] + T(6) * t6 * tau_lo * M_panels[6] + t10 * M_panels[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t13 = delta_tau * delta_tau;
    const T t14 = t13 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = tau_lo * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t17 * tau_lo;
    const T t19 = t13 * t13;
    const T t20 = t19 * delta_tau;
    const T t21 = t16 * tau_lo;
    const T t22 = t21 * t21;
    G_ap = t15 * M_panels[6] + T(15) * M_panels[2] * t13 * t17 + T(6) * delta_tau * t18 * M_panels[1] + T(6) * M_panels[5] * t20 * tau_lo + t22 * M_panels[0] + T(20) * t14 * t21 * M_panels[3] + T(15) * t19 * t16 * M_panels[4];
    G_ab = T(20) * t14 * t21 * M_panels[4] + t22 * M_panels[1] + T(6) * t20 * tau_lo * M_panels[6] + T(15) * t13 * t17 * M_panels[3] + T(6) * M_panels[2] * delta_tau * t18 + t15 * M_panels[7] + T(15) * M_panels[5] * t19 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(1) / cross_cross;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(1) / r0;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = a_minus_b * t28 + ab_ap * t32;
    const T t36 = ab_ap * t32 * t33 + T(2) * t27 * ab_ab * t35 + a_minus_b * t29 * t28;
    const T t37 = T(3) * a_minus_b * t30 * t28 + T(3) * ab_ap * t32 * t34 + T(4) * t27 * ab_ab * t36;
    const T t38 = t34 * t33;
    const T t39 = T(5) * a_minus_b * t31 * t28 + T(2) * t27 * ab_ab * t37 + T(5) * ab_ap * t32 * t38;
    const T t40 = t27 * ab_ap * t39 + T(5) * t32 * t38 - T(5) * t31 * t28;
    const T t41 = delta_tau * delta_tau;
    const T t42 = t41 * t41;
    const T t43 = t42 * delta_tau;
    const T t44 = T(6) * t26 * ab_ap * t40 + T(7) * t27 * t37 - T(3) * t27 * t39 * ap_ap;
    const T t45 = t27 * ab_ap * t37 + T(3) * t32 * t34 - T(3) * t30 * t28;
    const T t46 = T(3) * t26 * t40 * ap_ap - T(2) * t44 * t26 * ab_ap - T(7) * t26 * t45;
    const T t47 = t27 * t37 * ap_ap - T(2) * t26 * t45 * ab_ap - T(5) * t27 * t36;
    const T t48 = T(2) * t26 * ab_ap * t46 + t44 * t26 * ap_ap + T(7) * t26 * t47;
    const T t49 = t27 * t36 * ab_ap + t32 * t33 - t29 * t28;
    const T t50 = T(2) * t26 * t47 * ab_ap + t26 * t45 * ap_ap - T(5) * t26 * t49;
    const T t51 = t26 * t46 * ap_ap - T(2) * t26 * ab_ap * t48 - T(7) * t26 * t50;
    const T t52 = t41 * delta_tau;
    const T t53 = t52 * t52;
    const T t54 = T(2) * t26 * ab_ap * t49 + T(3) * t27 * t35 - t27 * t36 * ap_ap;
    const T t55 = T(2) * t26 * ab_ap * t50 - T(5) * t26 * t54 - t26 * t47 * ap_ap;
    const T t56 = T(2) * t26 * ab_ap * t51 + t26 * t48 * ap_ap - T(7) * t26 * t55;
    const T t57 = t23 * tau_lo;
    const T t58 = t57 * t57;
    G_ap = (T(6) / T(35)) * delta_tau * t25 * t26 * t40 + (T(2) / T(35)) * t43 * tau_lo * t26 * t51 + (T(1) / T(7)) * t44 * t41 * t24 * t26 + (T(1) / T(105)) * t53 * t26 * t56 + (T(1) / T(35)) * t27 * t58 * t39 - (T(4) / T(21)) * t52 * t57 * t26 * t46 - (T(1) / T(7)) * t42 * t23 * t26 * t48;
    G_ab = (T(2) / T(35)) * t44 * delta_tau * t25 * t26 + (T(2) / T(35)) * t43 * tau_lo * t26 * t56 + (T(1) / T(7)) * t42 * t23 * t26 * t51 + (T(1) / T(35)) * t58 * t26 * t40 - (T(1) / T(7)) * t41 * t24 * t26 * t46 - (T(1) / T(105)) * t53 * t26 * (t26 * t51 * ap_ap + T(7) * (T(2) * t26 * t55 * ab_ap - t26 * t50 * ap_ap - T(5) * t26 * (T(2) * t26 * ab_ap * t54 + T(3) * t26 * (t27 * ab_ap * t35 + t32 - t28) - t26 * t49 * ap_ap)) * t26 - T(2) * t26 * t56 * ab_ap) - (T(4) / T(21)) * t52 * t57 * t26 * t48;
  }
  const T t59 = in.sigma * in.sigma;
  const T t60 = t59 * in.sigma;
  const T t61 = t60 * t60;
  const T t62 = t61 * in.sigma;
  const T g_factor = -T(7) * length * t62;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 294 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 22109 +, 33812 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = a_minus_b * r0;
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = -(ab_ap - a_minus_b) * length / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t11 * t11;
    const T t15 = t14 * delta_tau;
    const T t16 = t8 * t8;
    const T t17 = t16 * tau_lo;
    F = t10 * M_panels[0] + t13 * M_panels[6] + T(6) * t15 * tau_lo * M_panels[5] + T(15) * t14 * t8 * M_panels[4] + T(6) * delta_tau * t17 * M_panels[1] + T(15) * t11 * t16 * M_panels[2] + T(20) * t12 * t9 * M_panels[3];
    G_ap = t10 * M_panels[8] + t13 * M_panels[14] + T(6) * t15 * tau_lo * M_panels[13] + T(6) * M_panels[9] * delta_tau * t17 + T(15) * M_panels[12] * t14 * t8 + T(15) * t11 * t16 * M_panels[10] + T(20) * t12 * t9 * M_panels[11];
    G_ab = T(20) * M_panels[12] * t12 * t9 + T(15) * t14 * t8 * M_panels[13] + T(6) * t15 * tau_lo * M_panels[14] + T(6) * delta_tau * t17 * M_panels[10] + M_panels[15] * t13 + M_panels[9] * t10 + T(15) * t11 * t16 * M_panels[11];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t18 = tau_lo * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t19 * tau_lo;
    const T t21 = delta_tau * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t21 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t18 * tau_lo;
    const T t27 = t26 * t26;
    F = T(6) * delta_tau * t20 * M_panels[1] + T(6) * t23 * tau_lo * M_panels[5] + t25 * M_panels[6] + t27 * M_panels[0] + T(15) * t21 * t19 * M_panels[2] + T(15) * t22 * t18 * M_panels[4] + T(20) * t24 * t26 * M_panels[3];
    G_ap = T(6) * t23 * tau_lo * M_panels[13] + t27 * M_panels[8] + T(15) * M_panels[12] * t22 * t18 + T(15) * t21 * t19 * M_panels[10] + T(20) * t24 * t26 * M_panels[11] + t25 * M_panels[14] + T(6) * delta_tau * M_panels[9] * t20;
    G_ab = M_panels[9] * t27 + T(6) * t23 * tau_lo * M_panels[14] + T(15) * t22 * t18 * M_panels[13] + T(6) * delta_tau * t20 * M_panels[10] + T(15) * t21 * t19 * M_panels[11] + M_panels[15] * t25 + T(20) * M_panels[12] * t24 * t26;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = delta_tau * delta_tau;
    const T t29 = t28 * delta_tau;
    const T t30 = tau_lo * tau_lo;
    const T t31 = t30 * tau_lo;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = T(1) / cross_cross;
    const T t36 = T(1) / r1;
    const T t37 = ab_ap * t33 + t36 * a_minus_b;
    const T t38 = t36 * t36;
    const T t39 = T(2) * t35 * t37 * ab_ab + t36 * t38 * a_minus_b + ab_ap * t34 * t33;
    const T t40 = t34 * t33 + t39 * t35 * ab_ap - t36 * t38;
    const T t41 = t38 * t38;
    const T t42 = t34 * t34;
    const T t43 = T(3) * ab_ap * t42 * t33 + T(4) * t39 * t35 * ab_ab + T(3) * t36 * t41 * a_minus_b;
    const T t44 = T(3) * t36 * t41 - T(3) * t42 * t33 - t35 * ab_ap * t43;
    const T t45 = T(2) * t32 * t44 * ab_ap + t35 * t43 * ap_ap - T(5) * t39 * t35;
    const T t46 = T(5) * t40 * t32 + t32 * t44 * ap_ap - T(2) * t32 * t45 * ab_ap;
    const T t47 = t31 * t31;
    const T t48 = t28 * t28;
    const T t49 = t39 * t35 * ap_ap - T(2) * t40 * t32 * ab_ap - T(3) * t35 * t37;
    const T t50 = T(2) * t32 * ab_ap * t46 + t32 * t45 * ap_ap - T(5) * t49 * t32;
    const T t51 = t30 * t30;
    const T t52 = t51 * tau_lo;
    const T t53 = t48 * delta_tau;
    const T t54 = t36 - t35 * t37 * ab_ap - t33;
    const T t55 = T(2) * t49 * t32 * ab_ap + T(3) * t32 * t54 + t40 * t32 * ap_ap;
    const T t56 = t32 * t46 * ap_ap + T(5) * t32 * t55 - T(2) * t32 * t50 * ab_ap;
    const T t57 = t29 * t29;
    F = (T(4) / T(3)) * t29 * t31 * t32 * t46 + (T(1) / T(15)) * t35 * t47 * t43 + t48 * t30 * t32 * t50 - t28 * t51 * t32 * t45 - (T(2) / T(5)) * delta_tau * t52 * t32 * t44 - (T(2) / T(5)) * t53 * tau_lo * t32 * t56 - (T(1) / T(15)) * t57 * (t32 * t50 * ap_ap + T(2) * t32 * ab_ap * t56 + T(5) * t32 * (T(2) * t32 * ab_ap * t55 + T(3) * (T(2) * t32 * t54 * ab_ap + t35 * t37 * ap_ap - J1) * t32 - t49 * t32 * ap_ap)) * t32;
    const T t58 = t41 * t38;
    const T t59 = t42 * t34;
    const T t60 = T(5) * ab_ap * t59 * t33 + T(5) * t36 * t58 * a_minus_b + T(2) * t35 * ab_ab * t43;
    const T t61 = T(5) * t36 * t58 - T(5) * t59 * t33 - t35 * ab_ap * t60;
    const T t62 = T(3) * t35 * t60 * ap_ap + T(6) * t32 * t61 * ab_ap - T(7) * t35 * t43;
    const T t63 = T(3) * t32 * t61 * ap_ap - T(2) * t62 * t32 * ab_ap - T(7) * t32 * t44;
    const T t64 = T(2) * t63 * t32 * ab_ap + t62 * t32 * ap_ap - T(7) * t32 * t45;
    const T t65 = t63 * t32 * ap_ap - T(2) * t32 * t64 * ab_ap - T(7) * t32 * t46;
    const T t66 = t32 * t64 * ap_ap + T(2) * t32 * t65 * ab_ap - T(7) * t32 * t50;
    G_ap = (T(4) / T(21)) * t63 * t29 * t31 * t32 + (T(1) / T(35)) * t35 * t47 * t60 + (T(1) / T(7)) * t48 * t30 * t32 * t64 - (T(1) / T(7)) * t62 * t28 * t51 * t32 - (T(2) / T(35)) * t53 * tau_lo * t32 * t65 - (T(6) / T(35)) * delta_tau * t52 * t32 * t61 - (T(1) / T(105)) * t57 * t32 * t66;
    G_ab = (T(1) / T(7)) * t63 * t28 * t51 * t32 + (T(1) / T(105)) * t57 * (t32 * t65 * ap_ap - T(7) * t32 * t56 - T(2) * t32 * ab_ap * t66) * t32 + (T(4) / T(21)) * t29 * t31 * t32 * t64 - (T(1) / T(35)) * t47 * t32 * t61 - (T(2) / T(35)) * t62 * delta_tau * t52 * t32 - (T(2) / T(35)) * t53 * tau_lo * t32 * t66 - (T(1) / T(7)) * t48 * t30 * t32 * t65;
  }
  const T t67 = in.sigma * in.sigma;
  const T t68 = t67 * in.sigma;
  const T t69 = t68 * t68;
  const T t70 = t69 * in.sigma;
  const T g_factor = -T(7) * length * t70;
  f = length * F * t70;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 73 +, 196 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 13456 +, 18649 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * t4;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t8 * tau_lo;
    const T t10 = t5 * delta_tau;
    const T t11 = t4 * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t12 * delta_tau;
    const T t14 = t6 * t6;
    const T t15 = t14 * tau_lo;
    F = T(35) * M_panels[4] * t5 * t7 + T(7) * M_panels[1] * delta_tau * t8 + t9 * M_panels[0] + T(21) * t10 * t6 * M_panels[5] + M_panels[7] * t13 + T(35) * t11 * t14 * M_panels[3] + T(7) * t12 * tau_lo * M_panels[6] + T(21) * t4 * t15 * M_panels[2];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = tau_lo * tau_lo;
    const T t17 = t16 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = delta_tau * delta_tau;
    const T t20 = t19 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * delta_tau;
    const T t23 = t18 * tau_lo;
    const T t24 = t19 * t19;
    const T t25 = t24 * delta_tau;
    const T t26 = t16 * t16;
    const T t27 = t26 * tau_lo;
    F = T(7) * delta_tau * t18 * M_panels[1] + t22 * M_panels[7] + t23 * M_panels[0] + T(21) * M_panels[5] * t25 * t16 + T(7) * t21 * tau_lo * M_panels[6] + T(35) * t20 * M_panels[3] * t26 + T(21) * M_panels[2] * t19 * t27 + T(35) * t24 * t17 * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = sqrt(cross_cross);
    const T t29 = T(1) / t28;
    const T J2 = atan2(t28, ap_bp) * t29;
    const T t30 = t0 * t0;
    const T t31 = t30 * t0;
    const T t32 = T(1) / cross_cross;
    const T t33 = T(1) / bp_bp;
    const T t34 = a_minus_b * t33 + J2 * ab_ab + t0 * ab_ap;
    const T t35 = t33 * t33;
    const T t36 = T(3) * t34 * t32 * ab_ab + T(2) * t30 * ab_ap + T(2) * a_minus_b * t35;
    const T t37 = t35 * t33;
    const T t38 = T(8) * t31 * ab_ap + T(5) * t32 * t36 * ab_ab + T(8) * a_minus_b * t37;
    const T t39 = T(8) * t31 + t32 * t38 * ab_ap - T(8) * t37;
    const T t40 = tau_lo * tau_lo;
    const T t41 = t40 * tau_lo;
    const T t42 = t41 * t41;
    const T t43 = T(1) / ab_ab;
    const T t44 = t34 * t32 * ab_ap + t0 - t33;
    const T t45 = T(2) * t30 + t32 * t36 * ab_ap - T(2) * t35;
    const T t46 = T(4) * t34 * t32 + T(2) * t43 * t45 * ab_ap - ap_ap * t32 * t36;
    const T t47 = T(4) * t43 * t44 + T(2) * t43 * ab_ap * t46 - ap_ap * t43 * t45;
    const T t48 = T(6) * t32 * t36 + T(2) * t39 * t43 * ab_ap - ap_ap * t32 * t38;
    const T t49 = T(2) * t48 * t43 * ab_ap + T(6) * t43 * t45 - t39 * ap_ap * t43;
    const T t50 = ap_ap * t48 * t43 - T(2) * t43 * t49 * ab_ap - T(6) * t43 * t46;
    const T t51 = T(6) * t43 * t47 - T(2) * t43 * t50 * ab_ap - ap_ap * t43 * t49;
    const T t52 = t34 * ap_ap * t32 - T(2) * J2 - T(2) * t43 * t44 * ab_ap;
    const T t53 = ap_ap * t43 * t46 + T(4) * t52 * t43 - T(2) * t43 * t47 * ab_ap;
    const T t54 = T(2) * t51 * t43 * ab_ap + ap_ap * t43 * t50 - T(6) * t43 * t53;
    const T t55 = delta_tau * delta_tau;
    const T t56 = t55 * delta_tau;
    const T t57 = t56 * t56;
    const T t58 = t40 * t40;
    const T t59 = t58 * tau_lo;
    const T t60 = t42 * tau_lo;
    const T t61 = t55 * t55;
    const T t62 = t61 * delta_tau;
    const T t63 = t57 * delta_tau;
    F = (T(7) / T(48)) * t39 * delta_tau * t42 * t43 + (T(7) / T(48)) * t54 * t57 * tau_lo * t43 + (T(7) / T(16)) * t48 * t55 * t59 * t43 + (T(35) / T(48)) * t56 * t58 * t43 * t49 + (T(1) / T(48)) * t32 * t60 * t38 + (T(7) / T(16)) * t51 * t62 * t40 * t43 - (T(35) / T(48)) * t61 * t41 * t43 * t50 - (T(1) / T(48)) * t63 * (T(6) * (T(4) * t43 * (T(2) * t52 * t43 * ab_ap + ap_ap * t43 * t44 - t43 * (log_ratio + T(2) * J2 * ab_ap)) + ap_ap * t43 * t47 + T(2) * t43 * t53 * ab_ap) * t43 + t51 * ap_ap * t43 - T(2) * t54 * t43 * ab_ap) * t43;
  }
  const T t64 = in.sigma * in.sigma;
  const T t65 = t64 * t64;
  const T t66 = t65 * t65;
  f = t66 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 274 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 14546 +, 20837 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
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
    G_ap = M_panels[0] * t6 + T(21) * M_panels[5] * t9 * t3 + T(35) * M_panels[3] * t10 * t11 + t13 * M_panels[7] + T(35) * t8 * t4 * M_panels[4] + T(7) * delta_tau * t5 * M_panels[1] + T(7) * M_panels[6] * t12 * tau_lo + T(21) * M_panels[2] * t7 * t14;
    G_ab = T(35) * M_panels[5] * t8 * t4 + T(7) * M_panels[2] * delta_tau * t5 + t6 * M_panels[1] + T(35) * t10 * t11 * M_panels[4] + T(21) * M_panels[3] * t7 * t14 + T(7) * t12 * M_panels[7] * tau_lo + t13 * M_panels[8] + T(21) * M_panels[6] * t9 * t3;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t15 = delta_tau * delta_tau;
    const T t16 = t15 * delta_tau;
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t15 * t15;
    const T t20 = t17 * tau_lo;
    const T t21 = t18 * tau_lo;
    const T t22 = t20 * t20;
    const T t23 = t16 * t16;
    const T t24 = t23 * delta_tau;
    const T t25 = t22 * tau_lo;
    const T t26 = t19 * delta_tau;
    G_ap = T(35) * M_panels[3] * t16 * t18 + T(35) * t19 * M_panels[4] * t20 + T(21) * t15 * t21 * M_panels[2] + T(7) * M_panels[1] * delta_tau * t22 + T(7) * M_panels[6] * t23 * tau_lo + M_panels[7] * t24 + M_panels[0] * t25 + T(21) * t26 * t17 * M_panels[5];
    G_ab = T(7) * M_panels[7] * t23 * tau_lo + T(35) * t16 * M_panels[4] * t18 + T(21) * M_panels[3] * t15 * t21 + M_panels[1] * t25 + T(21) * M_panels[6] * t26 * t17 + t24 * M_panels[8] + T(35) * t19 * t20 * M_panels[5] + T(7) * delta_tau * t22 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(cross_cross);
    const T t28 = T(1) / t27;
    const T J2 = atan2(t27, ap_bp) * t28;
    const T t29 = T(1) / cross_cross;
    const T t30 = T(1) / bp_bp;
    const T t31 = t30 * t30;
    const T t32 = T(1) / ap_ap;
    const T t33 = ab_ap * t32 + ab_ab * J2 + a_minus_b * t30;
    const T t34 = t32 * t32;
    const T t35 = T(2) * a_minus_b * t31 + T(3) * t29 * ab_ab * t33 + T(2) * ab_ap * t34;
    const T t36 = t31 * t30;
    const T t37 = t34 * t32;
    const T t38 = T(5) * t35 * t29 * ab_ab + T(8) * a_minus_b * t36 + T(8) * ab_ap * t37;
    const T t39 = t31 * t31;
    const T t40 = t34 * t34;
    const T t41 = T(7) * t38 * t29 * ab_ab + T(48) * a_minus_b * t39 + T(48) * ab_ap * t40;
    const T t42 = tau_lo * tau_lo;
    const T t43 = t42 * tau_lo;
    const T t44 = t43 * t43;
    const T t45 = t44 * tau_lo;
    const T t46 = T(1) / ab_ab;
    const T t47 = T(8) * t36 - T(8) * t37 - ab_ap * t38 * t29;
    const T t48 = T(2) * t34 + ab_ap * t35 * t29 - T(2) * t31;
    const T t49 = T(2) * ab_ap * t47 * t46 + t38 * ap_ap * t29 - T(6) * t35 * t29;
    const T t50 = ap_ap * t47 * t46 + T(6) * t48 * t46 - T(2) * ab_ap * t49 * t46;
    const T t51 = T(48) * t40 + ab_ap * t29 * t41 - T(48) * t39;
    const T t52 = ap_ap * t29 * t41 - T(8) * t38 * t29 - T(2) * ab_ap * t51 * t46;
    const T t53 = t51 * ap_ap * t46 + T(8) * t47 * t46 + T(2) * t52 * ab_ap * t46;
    const T t54 = t52 * ap_ap * t46 - T(8) * t49 * t46 - T(2) * ab_ap * t53 * t46;
    const T t55 = T(8) * t46 * t50 + ap_ap * t53 * t46 + T(2) * ab_ap * t54 * t46;
    const T t56 = delta_tau * delta_tau;
    const T t57 = t56 * t56;
    const T t58 = t57 * delta_tau;
    const T t59 = t30 - ab_ap * t29 * t33 - t32;
    const T t60 = T(2) * ab_ap * t48 * t46 + T(4) * t29 * t33 - ap_ap * t35 * t29;
    const T t61 = T(4) * t59 * t46 + ap_ap * t48 * t46 - T(2) * ab_ap * t60 * t46;
    const T t62 = T(6) * t60 * t46 + ap_ap * t49 * t46 + T(2) * ab_ap * t46 * t50;
    const T t63 = ap_ap * t46 * t50 + T(6) * t61 * t46 - T(2) * ab_ap * t62 * t46;
    const T t64 = ap_ap * t54 * t46 - T(8) * t62 * t46 - T(2) * ab_ap * t55 * t46;
    const T t65 = T(8) * t63 * t46 + T(2) * ab_ap * t64 * t46 + t55 * ap_ap * t46;
    const T t66 = t56 * delta_tau;
    const T t67 = t66 * t66;
    const T t68 = t67 * delta_tau;
    const T t69 = t42 * t42;
    const T t70 = t69 * tau_lo;
    G_ap = (T(1) / T(384)) * t29 * t41 * t45 + (T(7) / T(128)) * t55 * t58 * t42 * t46 + (T(35) / T(384)) * t54 * t57 * t43 * t46 + (T(7) / T(384)) * t51 * delta_tau * t44 * t46 - (T(1) / T(384)) * t65 * t68 * t46 - (T(7) / T(128)) * t52 * t56 * t70 * t46 - (T(35) / T(384)) * t66 * t69 * t53 * t46 - (T(7) / T(384)) * t64 * t67 * tau_lo * t46;
    G_ab = (T(1) / T(384)) * t51 * t45 * t46 + (T(35) / T(384)) * t55 * t57 * t43 * t46 + (T(35) / T(384)) * t54 * t66 * t69 * t46 - (T(7) / T(128)) * t56 * t70 * t53 * t46 - (T(7) / T(128)) * t64 * t58 * t42 * t46 - (T(7) / T(384)) * t65 * t67 * tau_lo * t46 - (T(7) / T(384)) * t52 * delta_tau * t44 * t46 - (T(1) / T(384)) * t68 * t46 * (T(8) * (T(6) * (T(2) * ab_ap * t61 * t46 + T(4) * (T(2) * ab_ap * t59 * t46 + ap_ap * t29 * t33 - T(2) * J2) * t46 + ap_ap * t60 * t46) * t46 + T(2) * ab_ap * t63 * t46 + t62 * ap_ap * t46) * t46 + T(2) * ab_ap * t65 * t46 - t64 * ap_ap * t46);
  }
  const T t71 = in.sigma * in.sigma;
  const T t72 = t71 * t71;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * t73 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 108 +, 329 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 24273 +, 31660 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * tau_lo;
    const T t6 = t5 * t5;
    const T t7 = delta_tau * delta_tau;
    const T t8 = t4 * t4;
    const T t9 = t8 * tau_lo;
    const T t10 = t7 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * tau_lo;
    const T t14 = t7 * t7;
    const T t15 = t14 * delta_tau;
    F = T(7) * delta_tau * t6 * M_panels[1] + T(21) * t7 * t9 * M_panels[2] + t12 * M_panels[7] + t13 * M_panels[0] + T(35) * t14 * t5 * M_panels[4] + T(21) * t15 * t4 * M_panels[5] + T(35) * t10 * t8 * M_panels[3] + T(7) * t11 * tau_lo * M_panels[6];
    G_ap = t13 * M_panels[9] + T(35) * t10 * t8 * M_panels[12] + T(21) * t7 * t9 * M_panels[11] + T(7) * delta_tau * t6 * M_panels[10] + T(35) * t14 * t5 * M_panels[13] + t12 * M_panels[16] + T(21) * t15 * t4 * M_panels[14] + T(7) * t11 * M_panels[15] * tau_lo;
    G_ab = t12 * M_panels[17] + T(21) * t15 * M_panels[15] * t4 + T(7) * t11 * tau_lo * M_panels[16] + T(35) * t10 * t8 * M_panels[13] + T(21) * t7 * t9 * M_panels[12] + t13 * M_panels[10] + T(7) * delta_tau * t6 * M_panels[11] + T(35) * t14 * t5 * M_panels[14];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = tau_lo * tau_lo;
    const T t20 = t16 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t19 * tau_lo;
    const T t24 = t22 * tau_lo;
    const T t25 = t23 * t23;
    const T t26 = t25 * tau_lo;
    const T t27 = t21 * delta_tau;
    F = T(21) * t18 * t19 * M_panels[5] + T(7) * M_panels[6] * t21 * tau_lo + T(35) * t20 * t22 * M_panels[3] + T(35) * t17 * t23 * M_panels[4] + T(21) * t16 * t24 * M_panels[2] + M_panels[0] * t26 + t27 * M_panels[7] + T(7) * delta_tau * t25 * M_panels[1];
    G_ap = T(7) * delta_tau * t25 * M_panels[10] + T(35) * t17 * t23 * M_panels[13] + t26 * M_panels[9] + t27 * M_panels[16] + T(21) * t18 * t19 * M_panels[14] + T(7) * t21 * tau_lo * M_panels[15] + T(35) * t20 * t22 * M_panels[12] + T(21) * t16 * t24 * M_panels[11];
    G_ab = T(35) * t20 * t22 * M_panels[13] + T(7) * delta_tau * t25 * M_panels[11] + T(21) * t16 * t24 * M_panels[12] + t27 * M_panels[17] + T(35) * t17 * t23 * M_panels[14] + T(7) * t21 * M_panels[16] * tau_lo + t26 * M_panels[10] + T(21) * t18 * t19 * M_panels[15];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = sqrt(cross_cross);
    const T t29 = T(1) / t28;
    const T J2 = t29 * atan2(t28, ap_bp);
    const T t30 = T(1) / cross_cross;
    const T t31 = tau_lo * tau_lo;
    const T t32 = t31 * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = T(1) / bp_bp;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = t0 * t0;
    const T t39 = ab_ab * J2 + ab_ap * t0 + t35 * a_minus_b;
    const T t40 = T(2) * t36 * a_minus_b + T(2) * ab_ap * t38 + T(3) * t30 * ab_ab * t39;
    const T t41 = t38 * t0;
    const T t42 = T(8) * t37 * a_minus_b + T(5) * t40 * t30 * ab_ab + T(8) * ab_ap * t41;
    const T t43 = delta_tau * delta_tau;
    const T t44 = t43 * t43;
    const T t45 = T(1) / ab_ab;
    const T t46 = t40 * t30 * ab_ap + T(2) * t38 - T(2) * t36;
    const T t47 = T(2) * t45 * t46 * ab_ap + T(4) * t30 * t39 - t40 * t30 * ap_ap;
    const T t48 = t30 * ab_ap * t42 + T(8) * t41 - T(8) * t37;
    const T t49 = t30 * t42 * ap_ap - T(6) * t40 * t30 - T(2) * t45 * ab_ap * t48;
    const T t50 = t45 * ap_ap * t48 + T(2) * t45 * ab_ap * t49 - T(6) * t45 * t46;
    const T t51 = T(6) * t45 * t47 + t45 * t49 * ap_ap - T(2) * t45 * ab_ap * t50;
    const T t52 = t43 * delta_tau;
    const T t53 = t52 * t52;
    const T t54 = t53 * delta_tau;
    const T t55 = t35 - t0 - t30 * ab_ap * t39;
    const T t56 = T(4) * t45 * t55 + t45 * t46 * ap_ap - T(2) * t45 * ab_ap * t47;
    const T t57 = T(2) * t45 * t55 * ab_ap + t30 * t39 * ap_ap - T(2) * J2;
    const T t58 = T(4) * t45 * t57 + t45 * t47 * ap_ap + T(2) * t45 * ab_ap * t56;
    const T t59 = T(6) * t45 * t56 - T(2) * t45 * ab_ap * t51 - t45 * t50 * ap_ap;
    const T t60 = T(6) * t45 * t58 + T(2) * t45 * ab_ap * t59 + t45 * t51 * ap_ap;
    const T t61 = t44 * delta_tau;
    const T t62 = t31 * t31;
    const T t63 = t62 * tau_lo;
    F = (T(1) / T(48)) * t30 * t34 * t42 + (T(35) / T(48)) * t44 * t32 * t45 * t51 + (T(7) / T(48)) * delta_tau * t33 * t45 * t48 + (T(1) / T(48)) * t54 * t45 * (T(6) * t45 * (t45 * ap_ap * t56 + T(4) * (t45 * t55 * ap_ap + t45 * (log_ratio + T(2) * ab_ap * J2) - T(2) * t45 * ab_ap * t57) * t45 - T(2) * t45 * ab_ap * t58) + t45 * t59 * ap_ap - T(2) * t45 * ab_ap * t60) - (T(7) / T(16)) * t61 * t31 * t45 * t59 - (T(7) / T(48)) * t53 * tau_lo * t45 * t60 - (T(7) / T(16)) * t43 * t63 * t45 * t49 - (T(35) / T(48)) * t52 * t62 * t45 * t50;
    const T t64 = t38 * t38;
    const T t65 = t36 * t36;
    const T t66 = T(7) * t30 * ab_ab * t42 + T(48) * ab_ap * t64 + T(48) * t65 * a_minus_b;
    const T t67 = t30 * ab_ap * t66 + T(48) * t64 - T(48) * t65;
    const T t68 = T(8) * t30 * t42 + T(2) * t45 * t67 * ab_ap - t30 * t66 * ap_ap;
    const T t69 = t45 * t67 * ap_ap - T(8) * t45 * t48 - T(2) * t68 * t45 * ab_ap;
    const T t70 = t68 * t45 * ap_ap + T(8) * t45 * t49 + T(2) * t45 * ab_ap * t69;
    const T t71 = T(8) * t45 * t50 + T(2) * t45 * ab_ap * t70 - t45 * t69 * ap_ap;
    const T t72 = T(8) * t45 * t51 + t45 * t70 * ap_ap - T(2) * t71 * t45 * ab_ap;
    const T t73 = T(2) * t45 * t72 * ab_ap + t71 * t45 * ap_ap - T(8) * t45 * t59;
    G_ap = (T(7) / T(384)) * t53 * tau_lo * t45 * t72 + (T(1) / T(384)) * t30 * t34 * t66 + (T(7) / T(128)) * t68 * t43 * t63 * t45 + (T(7) / T(384)) * delta_tau * t33 * t45 * t67 + (T(1) / T(384)) * t54 * t45 * t73 - (T(35) / T(384)) * t44 * t32 * t45 * t70 - (T(7) / T(128)) * t61 * t31 * t71 * t45 - (T(35) / T(384)) * t52 * t62 * t45 * t69;
    G_ab = (T(7) / T(128)) * t61 * t31 * t45 * t72 + (T(1) / T(384)) * t34 * t45 * t67 + (T(7) / T(384)) * t53 * tau_lo * t45 * t73 + (T(7) / T(384)) * t68 * delta_tau * t33 * t45 - (T(35) / T(384)) * t52 * t62 * t45 * t70 - (T(35) / T(384)) * t44 * t32 * t71 * t45 - (T(1) / T(384)) * t54 * (T(8) * t45 * t60 + t45 * t72 * ap_ap - T(2) * t45 * ab_ap * t73) * t45 - (T(7) / T(128)) * t43 * t63 * t45 * t69;
  }
  const T t74 = in.sigma * in.sigma;
  const T t75 = t74 * t74;
  const T t76 = t75 * t75;
  const T g_factor = -T(8) * length * t76;
  f = length * t76 * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 83 +, 252 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 14536 +, 25137 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
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
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t8 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t14 * t14;
    const T t18 = t17 * delta_tau;
    const T t19 = t17 * t17;
    const T t20 = t16 * delta_tau;
    const T t21 = t9 * tau_lo;
    F = M_panels[0] * t10 + T(8) * M_panels[1] * delta_tau * t13 + T(28) * M_panels[6] * t16 * t8 + T(56) * t18 * t11 * M_panels[5] + t19 * M_panels[8] + T(70) * M_panels[4] * t17 * t9 + T(28) * t14 * t12 * M_panels[2] + T(8) * M_panels[7] * t20 * tau_lo + T(56) * M_panels[3] * t15 * t21;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * delta_tau;
    const T t24 = tau_lo * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t22 * t22;
    const T t28 = t23 * t23;
    const T t29 = t24 * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t30 * tau_lo;
    const T t32 = t25 * t25;
    const T t33 = t27 * delta_tau;
    const T t34 = t28 * delta_tau;
    const T t35 = t27 * t27;
    F = T(56) * M_panels[3] * t23 * t26 + T(70) * M_panels[4] * t27 * t25 + T(28) * t28 * t24 * M_panels[6] + T(8) * M_panels[1] * delta_tau * t31 + T(28) * M_panels[2] * t22 * t30 + M_panels[0] * t32 + T(56) * M_panels[5] * t33 * t29 + T(8) * M_panels[7] * t34 * tau_lo + M_panels[8] * t35;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = delta_tau * delta_tau;
    const T t37 = t36 * delta_tau;
    const T t38 = tau_lo * tau_lo;
    const T t39 = t38 * t38;
    const T t40 = t39 * tau_lo;
    const T t41 = T(1) / ab_ab;
    const T t42 = T(1) / r0;
    const T t43 = t42 * t42;
    const T t44 = t43 * t43;
    const T t45 = T(1) / r1;
    const T t46 = ab_ap * t42 + t45 * a_minus_b;
    const T t47 = T(1) / cross_cross;
    const T t48 = t45 * t45;
    const T t49 = T(2) * t46 * t47 * ab_ab + t48 * t45 * a_minus_b + ab_ap * t43 * t42;
    const T t50 = t48 * t48;
    const T t51 = T(3) * ab_ap * t44 * t42 + T(4) * t49 * t47 * ab_ab + T(3) * t50 * t45 * a_minus_b;
    const T t52 = t44 * t43;
    const T t53 = t50 * t48;
    const T t54 = T(5) * t53 * t45 * a_minus_b + T(5) * ab_ap * t52 * t42 + T(2) * t51 * t47 * ab_ab;
    const T t55 = T(5) * t52 * t42 + ab_ap * t54 * t47 - T(5) * t53 * t45;
    const T t56 = T(7) * t51 * t47 + T(6) * t55 * ab_ap * t41 - T(3) * t54 * ap_ap * t47;
    const T t57 = T(3) * t44 * t42 + ab_ap * t51 * t47 - T(3) * t50 * t45;
    const T t58 = T(2) * ab_ap * t41 * t56 + T(7) * t57 * t41 - T(3) * t55 * ap_ap * t41;
    const T t59 = t38 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = t60 * tau_lo;
    const T t62 = t39 * t39;
    const T t63 = t36 * t36;
    const T t64 = ap_ap * t51 * t47 - T(5) * t49 * t47 - T(2) * t57 * ab_ap * t41;
    const T t65 = T(2) * ab_ap * t41 * t58 - ap_ap * t41 * t56 - T(7) * t64 * t41;
    const T t66 = t63 * delta_tau;
    const T t67 = t49 * ab_ap * t47 + t43 * t42 - t48 * t45;
    const T t68 = T(5) * t67 * t41 - t57 * ap_ap * t41 - T(2) * ab_ap * t64 * t41;
    const T t69 = ap_ap * t41 * t58 - T(7) * t68 * t41 - T(2) * ab_ap * t41 * t65;
    const T t70 = t37 * t37;
    const T t71 = t70 * delta_tau;
    const T t72 = t45 - ab_ap * t46 * t47 - t42;
    const T t73 = t49 * ap_ap * t47 - T(2) * ab_ap * t67 * t41 - T(3) * t46 * t47;
    const T t74 = ap_ap * t67 * t41 + T(3) * t72 * t41 + T(2) * ab_ap * t73 * t41;
    const T t75 = T(2) * ab_ap * t68 * t41 + t64 * ap_ap * t41 - T(5) * t73 * t41;
    const T t76 = t68 * ap_ap * t41 + T(5) * t74 * t41 - T(2) * ab_ap * t75 * t41;
    const T t77 = ap_ap * t41 * t65 + T(2) * ab_ap * t41 * t69 - T(7) * t75 * t41;
    const T t78 = T(7) * t76 * t41 + T(2) * t77 * ab_ap * t41 - ap_ap * t41 * t69;
    const T t79 = t63 * t63;
    F = (T(8) / T(15)) * t37 * t40 * t41 * t58 + (T(8) / T(35)) * t55 * delta_tau * t61 * t41 + (T(4) / T(15)) * t36 * t60 * t41 * t56 + (T(1) / T(35)) * t54 * t47 * t62 + (T(2) / T(3)) * t63 * t39 * t41 * t65 - (T(8) / T(15)) * t66 * t59 * t41 * t69 - (T(8) / T(105)) * t71 * tau_lo * t41 * t78 - (T(1) / T(105)) * t79 * t41 * (T(7) * t41 * (T(2) * t76 * ab_ap * t41 + ap_ap * t75 * t41 + T(5) * (T(3) * (t46 * ap_ap * t47 + T(2) * ab_ap * t72 * t41 - J1) * t41 + T(2) * t74 * ab_ap * t41 - t73 * ap_ap * t41) * t41) + T(2) * ab_ap * t41 * t78 - t77 * ap_ap * t41) - (T(4) / T(15)) * t77 * t70 * t38 * t41;
  }
  const T t80 = in.sigma * in.sigma;
  const T t81 = t80 * t80;
  const T t82 = t81 * t81;
  const T t83 = t82 * in.sigma;
  f = length * F * t83;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 105 +, 336 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 15626 +, 28403 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(11, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = t3 * delta_tau;
    const T t5 = t4 * t4;
    const T t6 = t5 * delta_tau;
    const T t7 = tau_lo * tau_lo;
    const T t8 = t3 * t3;
    const T t9 = t8 * t8;
    const T t10 = t7 * tau_lo;
    const T t11 = t10 * t10;
    const T t12 = t7 * t7;
    const T t13 = t8 * delta_tau;
    const T t14 = t12 * t12;
    const T t15 = t11 * tau_lo;
    const T t16 = t12 * tau_lo;
    G_ap = T(8) * t6 * M_panels[7] * tau_lo + T(28) * M_panels[6] * t5 * t7 + M_panels[8] * t9 + T(28) * M_panels[2] * t3 * t11 + T(70) * t8 * t12 * M_panels[4] + T(56) * M_panels[5] * t13 * t10 + M_panels[0] * t14 + T(8) * delta_tau * t15 * M_panels[1] + T(56) * M_panels[3] * t4 * t16;
    G_ab = T(56) * M_panels[6] * t13 * t10 + M_panels[9] * t9 + T(28) * t5 * M_panels[7] * t7 + T(70) * M_panels[5] * t8 * t12 + T(8) * M_panels[8] * t6 * tau_lo + T(8) * M_panels[2] * delta_tau * t15 + t14 * M_panels[1] + T(56) * t4 * t16 * M_panels[4] + T(28) * M_panels[3] * t3 * t11;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(11, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t17 = delta_tau * delta_tau;
    const T t18 = tau_lo * tau_lo;
    const T t19 = t18 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t17 * t17;
    const T t22 = t18 * t18;
    const T t23 = t21 * delta_tau;
    const T t24 = t22 * t22;
    const T t25 = t17 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = t21 * t21;
    const T t29 = t20 * tau_lo;
    const T t30 = t22 * tau_lo;
    G_ap = T(28) * M_panels[2] * t17 * t20 + T(70) * t21 * t22 * M_panels[4] + T(56) * M_panels[5] * t23 * t19 + M_panels[0] * t24 + T(8) * t27 * tau_lo * M_panels[7] + M_panels[8] * t28 + T(8) * delta_tau * t29 * M_panels[1] + T(56) * M_panels[3] * t25 * t30 + T(28) * M_panels[6] * t26 * t18;
    G_ab = T(28) * t26 * t18 * M_panels[7] + M_panels[9] * t28 + T(8) * M_panels[8] * t27 * tau_lo + T(28) * M_panels[3] * t17 * t20 + T(56) * M_panels[6] * t23 * t19 + T(56) * t25 * t30 * M_panels[4] + T(70) * M_panels[5] * t21 * t22 + T(8) * M_panels[2] * delta_tau * t29 + t24 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = T(1) / r1;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = T(1) / r0;
    const T t36 = t35 * t35;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = T(1) / cross_cross;
    const T t40 = t33 * t32;
    const T t41 = t37 * t36;
    const T t42 = ab_ap * t35 + t31 * a_minus_b;
    const T t43 = ab_ap * t35 * t36 + t32 * t31 * a_minus_b + T(2) * t42 * t39 * ab_ab;
    const T t44 = T(4) * t43 * t39 * ab_ab + T(3) * t33 * t31 * a_minus_b + T(3) * ab_ap * t35 * t37;
    const T t45 = T(5) * t40 * t31 * a_minus_b + T(5) * ab_ap * t35 * t41 + T(2) * t39 * ab_ab * t44;
    const T t46 = T(35) * t34 * t31 * a_minus_b + T(35) * ab_ap * t35 * t38 + T(8) * t39 * ab_ab * t45;
    const T t47 = tau_lo * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t48 * t48;
    const T t50 = T(35) * t35 * t38 + ab_ap * t46 * t39 - T(35) * t34 * t31;
    const T t51 = T(1) / ab_ab;
    const T t52 = T(2) * ab_ap * t50 * t51 + T(9) * t39 * t45 - t46 * ap_ap * t39;
    const T t53 = delta_tau * delta_tau;
    const T t54 = t47 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = ab_ap * t39 * t45 + T(5) * t35 * t41 - T(5) * t40 * t31;
    const T t57 = ab_ap * t39 * t44 + T(3) * t35 * t37 - T(3) * t33 * t31;
    const T t58 = T(6) * ab_ap * t56 * t51 + T(7) * t39 * t44 - T(3) * ap_ap * t39 * t45;
    const T t59 = T(3) * ap_ap * t56 * t51 - T(7) * t57 * t51 - T(2) * ab_ap * t58 * t51;
    const T t60 = T(2) * ab_ap * t57 * t51 + T(5) * t43 * t39 - ap_ap * t39 * t44;
    const T t61 = T(2) * t59 * ab_ap * t51 + ap_ap * t58 * t51 - T(7) * t51 * t60;
    const T t62 = T(2) * ab_ap * t52 * t51 + T(9) * t56 * t51 - t50 * ap_ap * t51;
    const T t63 = T(3) * t58 * t51 + T(2) * ab_ap * t62 * t51 - t52 * ap_ap * t51;
    const T t64 = T(3) * t59 * t51 + t62 * ap_ap * t51 - T(2) * ab_ap * t63 * t51;
    const T t65 = T(3) * t61 * t51 + T(2) * ab_ap * t51 * t64 + ap_ap * t63 * t51;
    const T t66 = ab_ap * t43 * t39 + t35 * t36 - t32 * t31;
    const T t67 = T(2) * ab_ap * t51 * t60 + T(5) * t66 * t51 - t57 * ap_ap * t51;
    const T t68 = T(2) * ab_ap * t61 * t51 - t59 * ap_ap * t51 - T(7) * t67 * t51;
    const T t69 = ap_ap * t51 * t64 - T(2) * ab_ap * t65 * t51 - T(3) * t51 * t68;
    const T t70 = ap_ap * t43 * t39 - T(2) * t66 * ab_ap * t51 - T(3) * t42 * t39;
    const T t71 = T(2) * ab_ap * t67 * t51 - T(5) * t70 * t51 - ap_ap * t51 * t60;
    const T t72 = t61 * ap_ap * t51 + T(7) * t71 * t51 - T(2) * ab_ap * t51 * t68;
    const T t73 = ap_ap * t65 * t51 + T(2) * ab_ap * t69 * t51 + T(3) * t72 * t51;
    const T t74 = t53 * t53;
    const T t75 = t74 * t74;
    const T t76 = t53 * delta_tau;
    const T t77 = t48 * tau_lo;
    const T t78 = t55 * tau_lo;
    const T t79 = t76 * t76;
    const T t80 = t79 * delta_tau;
    const T t81 = t74 * delta_tau;
    G_ap = (T(1) / T(315)) * t46 * t39 * t49 + (T(4) / T(45)) * t52 * t53 * t55 * t51 + (T(1) / T(315)) * t73 * t75 * t51 + (T(8) / T(45)) * t62 * t76 * t77 * t51 + (T(2) / T(9)) * t74 * t48 * t63 * t51 + (T(8) / T(315)) * t50 * delta_tau * t78 * t51 + (T(8) / T(315)) * t69 * t80 * tau_lo * t51 - (T(8) / T(45)) * t81 * t54 * t51 * t64 - (T(4) / T(45)) * t79 * t47 * t65 * t51;
    G_ab = (T(4) / T(45)) * t62 * t53 * t55 * t51 + (T(4) / T(45)) * t69 * t79 * t47 * t51 + (T(8) / T(45)) * t76 * t77 * t63 * t51 + (T(8) / T(315)) * t73 * t80 * tau_lo * t51 + (T(8) / T(315)) * t52 * delta_tau * t78 * t51 + (T(1) / T(315)) * t50 * t49 * t51 - (T(2) / T(9)) * t74 * t48 * t51 * t64 - (T(8) / T(45)) * t81 * t54 * t65 * t51 - (T(1) / T(315)) * (ap_ap * t69 * t51 - T(2) * t73 * ab_ap * t51 - T(3) * (T(2) * ab_ap * t72 * t51 + ap_ap * t51 * t68 - T(7) * (T(5) * (t66 * ap_ap * t51 + T(2) * ab_ap * t70 * t51 - T(3) * (ab_ap * t42 * t39 + t35 - t31) * t51) * t51 + t67 * ap_ap * t51 - T(2) * ab_ap * t71 * t51) * t51) * t51) * t75 * t51;
  }
  const T t82 = in.sigma * in.sigma;
  const T t83 = t82 * t82;
  const T t84 = t83 * t83;
  const T t85 = t84 * in.sigma;
  const T g_factor = -T(9) * t85 * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 122 +, 404 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 26435 +, 40314 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * (t2 + a_minus_b * r0) * length;
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
  const T t5 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t13 * tau_lo;
    const T t15 = t8 * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t16 * delta_tau;
    const T t18 = t11 * t11;
    const T t19 = t18 * t18;
    const T t20 = t18 * tau_lo;
    const T t21 = t9 * t9;
    F = T(56) * M_panels[5] * t10 * t12 + T(8) * M_panels[1] * delta_tau * t14 + T(8) * M_panels[7] * t17 * tau_lo + T(70) * M_panels[4] * t9 * t18 + t19 * M_panels[0] + T(28) * t16 * M_panels[6] * t11 + T(56) * t15 * t20 * M_panels[3] + M_panels[8] * t21 + T(28) * M_panels[2] * t8 * t13;
    G_ap = T(28) * t16 * t11 * M_panels[16] + M_panels[10] * t19 + T(70) * M_panels[14] * t9 * t18 + T(56) * M_panels[15] * t10 * t12 + T(56) * M_panels[13] * t15 * t20 + T(28) * t8 * M_panels[12] * t13 + T(8) * M_panels[17] * t17 * tau_lo + T(8) * M_panels[11] * delta_tau * t14 + M_panels[18] * t21;
    G_ab = T(28) * M_panels[13] * t8 * t13 + T(8) * M_panels[18] * t17 * tau_lo + M_panels[11] * t19 + T(8) * delta_tau * M_panels[12] * t14 + T(70) * M_panels[15] * t9 * t18 + T(56) * t10 * t12 * M_panels[16] + t21 * M_panels[19] + T(28) * M_panels[17] * t16 * t11 + T(56) * M_panels[14] * t15 * t20;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = delta_tau * delta_tau;
    const T t27 = t26 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t22 * t22;
    const T t31 = t30 * t30;
    const T t32 = t26 * t26;
    const T t33 = t32 * delta_tau;
    const T t34 = t32 * t32;
    const T t35 = t30 * tau_lo;
    F = T(8) * M_panels[1] * delta_tau * t25 + T(8) * M_panels[7] * t29 * tau_lo + T(28) * t26 * t24 * M_panels[2] + M_panels[0] * t31 + T(70) * M_panels[4] * t32 * t30 + T(56) * t33 * t23 * M_panels[5] + t34 * M_panels[8] + T(56) * M_panels[3] * t27 * t35 + T(28) * M_panels[6] * t28 * t22;
    G_ap = T(56) * M_panels[13] * t27 * t35 + T(8) * M_panels[17] * t29 * tau_lo + T(56) * M_panels[15] * t33 * t23 + T(8) * delta_tau * t25 * M_panels[11] + M_panels[10] * t31 + T(28) * M_panels[16] * t28 * t22 + M_panels[18] * t34 + T(28) * M_panels[12] * t26 * t24 + T(70) * t32 * M_panels[14] * t30;
    G_ab = M_panels[19] * t34 + T(8) * M_panels[12] * delta_tau * t25 + T(28) * M_panels[17] * t28 * t22 + T(56) * t27 * M_panels[14] * t35 + T(28) * M_panels[13] * t26 * t24 + T(70) * M_panels[15] * t32 * t30 + T(8) * M_panels[18] * t29 * tau_lo + t31 * M_panels[11] + T(56) * M_panels[16] * t33 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = T(1) / ab_ab;
    const T t37 = T(1) / r0;
    const T t38 = t37 * t37;
    const T t39 = T(1) / r1;
    const T t40 = t39 * t39;
    const T t41 = t39 * a_minus_b + ab_ap * t37;
    const T t42 = T(1) / cross_cross;
    const T t43 = ab_ap * t38 * t37 + t39 * t40 * a_minus_b + T(2) * t41 * t42 * ab_ab;
    const T t44 = t40 * t40;
    const T t45 = t38 * t38;
    const T t46 = T(4) * t43 * t42 * ab_ab + T(3) * t39 * t44 * a_minus_b + T(3) * ab_ap * t45 * t37;
    const T t47 = ab_ap * t46 * t42 + T(3) * t45 * t37 - T(3) * t39 * t44;
    const T t48 = t46 * ap_ap * t42 - T(5) * t43 * t42 - T(2) * ab_ap * t36 * t47;
    const T t49 = ab_ap * t43 * t42 + t38 * t37 - t39 * t40;
    const T t50 = ap_ap * t36 * t47 + T(2) * ab_ap * t36 * t48 - T(5) * t49 * t36;
    const T t51 = T(3) * t41 * t42 + T(2) * t49 * ab_ap * t36 - t43 * ap_ap * t42;
    const T t52 = ap_ap * t36 * t48 + T(5) * t51 * t36 - T(2) * ab_ap * t50 * t36;
    const T t53 = ab_ap * t41 * t42 + t37 - t39;
    const T t54 = T(2) * ab_ap * t51 * t36 + T(3) * t53 * t36 - t49 * ap_ap * t36;
    const T t55 = ap_ap * t50 * t36 + T(2) * ab_ap * t52 * t36 + T(5) * t54 * t36;
    const T t56 = t44 * t40;
    const T t57 = t45 * t38;
    const T t58 = T(2) * t46 * t42 * ab_ab + T(5) * ab_ap * t57 * t37 + T(5) * t39 * t56 * a_minus_b;
    const T t59 = T(5) * t39 * t56 - ab_ap * t58 * t42 - T(5) * t57 * t37;
    const T t60 = T(3) * ap_ap * t58 * t42 + T(6) * ab_ap * t59 * t36 - T(7) * t46 * t42;
    const T t61 = T(7) * t36 * t47 + T(3) * t59 * ap_ap * t36 - T(2) * ab_ap * t60 * t36;
    const T t62 = T(2) * ab_ap * t61 * t36 + ap_ap * t60 * t36 - T(7) * t36 * t48;
    const T t63 = t61 * ap_ap * t36 + T(7) * t50 * t36 - T(2) * ab_ap * t62 * t36;
    const T t64 = T(7) * t52 * t36 - ap_ap * t62 * t36 - T(2) * ab_ap * t63 * t36;
    const T t65 = T(7) * t55 * t36 + T(2) * ab_ap * t64 * t36 + ap_ap * t63 * t36;
    const T t66 = delta_tau * delta_tau;
    const T t67 = t66 * delta_tau;
    const T t68 = t67 * t67;
    const T t69 = t68 * delta_tau;
    const T t70 = t66 * t66;
    const T t71 = tau_lo * tau_lo;
    const T t72 = t71 * t71;
    const T t73 = t72 * t72;
    const T t74 = t72 * tau_lo;
    const T t75 = t71 * tau_lo;
    const T t76 = t75 * t75;
    const T t77 = t76 * tau_lo;
    const T t78 = t70 * delta_tau;
    const T t79 = t70 * t70;
    F = (T(8) / T(105)) * t65 * t69 * tau_lo * t36 + (T(2) / T(3)) * t70 * t72 * t62 * t36 + (T(1) / T(35)) * t58 * t42 * t73 + (T(4) / T(15)) * t68 * t71 * t64 * t36 + (T(8) / T(15)) * t61 * t67 * t74 * t36 - (T(4) / T(15)) * t66 * t76 * t60 * t36 - (T(8) / T(35)) * t59 * delta_tau * t77 * t36 - (T(8) / T(15)) * t78 * t63 * t75 * t36 - (T(1) / T(105)) * (ap_ap * t64 * t36 + T(7) * (t52 * ap_ap * t36 - T(5) * (T(2) * t54 * ab_ap * t36 + T(3) * (T(2) * ab_ap * t53 * t36 + J1 - t41 * ap_ap * t42) * t36 - t51 * ap_ap * t36) * t36 - T(2) * t55 * ab_ap * t36) * t36 - T(2) * ab_ap * t65 * t36) * t79 * t36;
    const T t80 = t44 * t44;
    const T t81 = t45 * t45;
    const T t82 = T(35) * t39 * t80 * a_minus_b + T(35) * ab_ap * t81 * t37 + T(8) * t58 * t42 * ab_ab;
    const T t83 = ab_ap * t82 * t42 + T(35) * t81 * t37 - T(35) * t39 * t80;
    const T t84 = t82 * ap_ap * t42 - T(2) * ab_ap * t36 * t83 - T(9) * t58 * t42;
    const T t85 = ap_ap * t36 * t83 + T(9) * t59 * t36 + T(2) * ab_ap * t84 * t36;
    const T t86 = T(2) * ab_ap * t85 * t36 + T(3) * t60 * t36 - ap_ap * t84 * t36;
    const T t87 = T(3) * t61 * t36 + t85 * ap_ap * t36 - T(2) * ab_ap * t86 * t36;
    const T t88 = T(2) * t87 * ab_ap * t36 + t86 * ap_ap * t36 + T(3) * t62 * t36;
    const T t89 = T(2) * ab_ap * t88 * t36 - T(3) * t63 * t36 - t87 * ap_ap * t36;
    const T t90 = ap_ap * t88 * t36 - T(3) * t64 * t36 - T(2) * ab_ap * t36 * t89;
    G_ap = (T(1) / T(315)) * t82 * t42 * t73 + (T(8) / T(315)) * t69 * tau_lo * t36 * t89 + (T(8) / T(45)) * t87 * t78 * t75 * t36 + (T(4) / T(45)) * t68 * t88 * t71 * t36 + (T(8) / T(315)) * delta_tau * t77 * t36 * t83 - (T(4) / T(45)) * t66 * t76 * t84 * t36 - (T(1) / T(315)) * t90 * t79 * t36 - (T(8) / T(45)) * t85 * t67 * t74 * t36 - (T(2) / T(9)) * t86 * t70 * t72 * t36;
    G_ab = (T(1) / T(315)) * t73 * t36 * t83 + (T(2) / T(9)) * t87 * t70 * t72 * t36 + (T(8) / T(45)) * t78 * t88 * t75 * t36 + (T(4) / T(45)) * t68 * t71 * t36 * t89 - (T(8) / T(315)) * t90 * t69 * tau_lo * t36 - (T(4) / T(45)) * t85 * t66 * t76 * t36 - (T(8) / T(45)) * t86 * t67 * t74 * t36 - (T(8) / T(315)) * delta_tau * t77 * t84 * t36 - (T(1) / T(315)) * t79 * (T(2) * ab_ap * t90 * t36 + ap_ap * t36 * t89 - T(3) * t65 * t36) * t36;
  }
  const T t91 = in.sigma * in.sigma;
  const T t92 = t91 * t91;
  const T t93 = t92 * t92;
  const T t94 = t93 * in.sigma;
  const T g_factor = -T(9) * length * t94;
  f = length * t94 * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 95 +, 278 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15618 +, 21900 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * delta_tau;
    const T t8 = t4 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = tau_lo * tau_lo;
    const T t11 = t10 * tau_lo;
    const T t12 = t5 * delta_tau;
    const T t13 = t10 * t10;
    const T t14 = t11 * t11;
    const T t15 = t13 * t13;
    const T t16 = t15 * tau_lo;
    const T t17 = t14 * tau_lo;
    const T t18 = t9 * delta_tau;
    const T t19 = t13 * tau_lo;
    F = M_panels[9] * t7 + T(84) * M_panels[6] * t9 * t11 + T(126) * t12 * t13 * M_panels[5] + T(9) * t6 * M_panels[8] * tau_lo + T(84) * M_panels[3] * t8 * t14 + M_panels[0] * t16 + T(36) * t4 * t17 * M_panels[2] + T(36) * M_panels[7] * t18 * t10 + T(126) * M_panels[4] * t5 * t19 + T(9) * M_panels[1] * delta_tau * t15;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t20 * delta_tau;
    const T t24 = t23 * t23;
    const T t25 = t24 * delta_tau;
    const T t26 = tau_lo * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * tau_lo;
    const T t30 = t26 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t27 * tau_lo;
    const T t33 = t31 * tau_lo;
    const T t34 = t22 * delta_tau;
    const T t35 = t21 * delta_tau;
    F = T(9) * t22 * tau_lo * M_panels[8] + T(36) * M_panels[7] * t25 * t26 + T(9) * M_panels[1] * delta_tau * t28 + M_panels[0] * t29 + T(84) * M_panels[3] * t23 * t31 + T(126) * t21 * M_panels[4] * t32 + T(36) * t20 * t33 * M_panels[2] + M_panels[9] * t34 + T(84) * M_panels[6] * t24 * t30 + T(126) * t35 * t27 * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = sqrt(cross_cross);
    const T t37 = T(1) / t36;
    const T J2 = atan2(t36, ap_bp) * t37;
    const T t38 = delta_tau * delta_tau;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = T(1) / ab_ab;
    const T t42 = T(1) / bp_bp;
    const T t43 = t42 * a_minus_b + ab_ap * t0 + J2 * ab_ab;
    const T t44 = T(1) / cross_cross;
    const T t45 = t0 + ab_ap * t43 * t44 - t42;
    const T t46 = t42 * t42;
    const T t47 = t0 * t0;
    const T t48 = T(2) * ab_ap * t47 + T(2) * t46 * a_minus_b + T(3) * t43 * t44 * ab_ab;
    const T t49 = T(2) * t46 - T(2) * t47 - ab_ap * t44 * t48;
    const T t50 = T(2) * ab_ap * t41 * t49 + ap_ap * t44 * t48 - T(4) * t43 * t44;
    const T t51 = T(4) * t45 * t41 + ap_ap * t41 * t49 - T(2) * ab_ap * t50 * t41;
    const T t52 = t46 * t42;
    const T t53 = t47 * t0;
    const T t54 = T(8) * t52 * a_minus_b + T(8) * ab_ap * t53 + T(5) * t44 * t48 * ab_ab;
    const T t55 = T(8) * t52 - ab_ap * t44 * t54 - T(8) * t53;
    const T t56 = ap_ap * t44 * t54 + T(2) * ab_ap * t55 * t41 - T(6) * t44 * t48;
    const T t57 = T(6) * t41 * t49 + T(2) * ab_ap * t56 * t41 - ap_ap * t55 * t41;
    const T t58 = T(2) * t57 * ab_ap * t41 + T(6) * t50 * t41 - t56 * ap_ap * t41;
    const T t59 = T(6) * t41 * t51 + t57 * ap_ap * t41 - T(2) * ab_ap * t58 * t41;
    const T t60 = T(2) * ab_ap * t45 * t41 + T(2) * J2 - ap_ap * t43 * t44;
    const T t61 = T(2) * ab_ap * t41 * t51 + t50 * ap_ap * t41 + T(4) * t60 * t41;
    const T t62 = T(2) * ab_ap * t41 * t59 + ap_ap * t58 * t41 + T(6) * t61 * t41;
    const T t63 = t46 * t46;
    const T t64 = t47 * t47;
    const T t65 = T(48) * ab_ap * t64 + T(7) * t44 * ab_ab * t54 + T(48) * t63 * a_minus_b;
    const T t66 = T(48) * t63 - ab_ap * t65 * t44 - T(48) * t64;
    const T t67 = T(2) * t66 * ab_ap * t41 + ap_ap * t65 * t44 - T(8) * t44 * t54;
    const T t68 = t66 * ap_ap * t41 - T(8) * t55 * t41 - T(2) * ab_ap * t67 * t41;
    const T t69 = T(2) * ab_ap * t68 * t41 + t67 * ap_ap * t41 - T(8) * t56 * t41;
    const T t70 = T(8) * t57 * t41 + ap_ap * t68 * t41 - T(2) * ab_ap * t69 * t41;
    const T t71 = T(8) * t58 * t41 + ap_ap * t69 * t41 + T(2) * ab_ap * t41 * t70;
    const T t72 = T(8) * t41 * t59 + ap_ap * t41 * t70 - T(2) * ab_ap * t41 * t71;
    const T t73 = T(8) * t41 * t62 + ap_ap * t41 * t71 + T(2) * ab_ap * t72 * t41;
    const T t74 = tau_lo * tau_lo;
    const T t75 = t74 * t74;
    const T t76 = t75 * tau_lo;
    const T t77 = t75 * t75;
    const T t78 = t77 * tau_lo;
    const T t79 = t38 * delta_tau;
    const T t80 = t79 * t79;
    const T t81 = t80 * delta_tau;
    const T t82 = t74 * tau_lo;
    const T t83 = t82 * t82;
    const T t84 = t39 * delta_tau;
    const T t85 = t83 * tau_lo;
    const T t86 = t40 * delta_tau;
    F = (T(3) / T(128)) * t40 * t73 * tau_lo * t41 + (T(21) / T(64)) * t39 * t76 * t69 * t41 + (T(1) / T(384)) * t65 * t44 * t78 + (T(3) / T(32)) * t81 * t72 * t74 * t41 + (T(7) / T(32)) * t79 * t83 * t68 * t41 - (T(21) / T(64)) * t84 * t75 * t41 * t70 - (T(3) / T(128)) * t66 * delta_tau * t77 * t41 - (T(7) / T(32)) * t80 * t82 * t41 * t71 - (T(3) / T(32)) * t67 * t38 * t85 * t41 - (T(1) / T(384)) * (ap_ap * t72 * t41 - T(8) * (T(2) * ab_ap * t41 * t62 - T(6) * (T(4) * (ap_ap * t45 * t41 - (T(2) * ab_ap * J2 + log_ratio) * t41 - T(2) * ab_ap * t60 * t41) * t41 + ap_ap * t41 * t51 - T(2) * ab_ap * t61 * t41) * t41 - ap_ap * t41 * t59) * t41 - T(2) * ab_ap * t73 * t41) * t86 * t41;
  }
  const T t87 = in.sigma * in.sigma;
  const T t88 = t87 * t87;
  const T t89 = t88 * in.sigma;
  const T t90 = t89 * t89;
  f = F * t90 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 120 +, 373 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 16710 +, 24094 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 11> M_panels;
    segment_moments_gauss_panels<T>(12, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t3 = delta_tau * delta_tau;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t8 * tau_lo;
    const T t10 = t3 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * t6;
    const T t14 = t13 * tau_lo;
    const T t15 = t13 * t13;
    const T t16 = t15 * tau_lo;
    const T t17 = t5 * delta_tau;
    const T t18 = t4 * delta_tau;
    G_ap = T(9) * t5 * M_panels[8] * tau_lo + T(36) * t3 * t9 * M_panels[2] + T(84) * t10 * t8 * M_panels[3] + T(36) * t12 * t6 * M_panels[7] + T(126) * t4 * t14 * M_panels[4] + t16 * M_panels[0] + t17 * M_panels[9] + T(126) * t18 * t13 * M_panels[5] + T(9) * delta_tau * t15 * M_panels[1] + T(84) * t11 * t7 * M_panels[6];
    G_ab = t17 * M_panels[10] + T(9) * t5 * tau_lo * M_panels[9] + T(36) * t12 * M_panels[8] * t6 + T(84) * t11 * t7 * M_panels[7] + T(36) * t3 * t9 * M_panels[3] + T(9) * delta_tau * t15 * M_panels[2] + T(84) * t10 * t8 * M_panels[4] + t16 * M_panels[1] + T(126) * t18 * t13 * M_panels[6] + T(126) * t4 * t14 * M_panels[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 11> M_panels;
    segment_moments_gauss_panels<T>(12, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t19 = delta_tau * delta_tau;
    const T t20 = tau_lo * tau_lo;
    const T t21 = t20 * tau_lo;
    const T t22 = t21 * t21;
    const T t23 = t22 * tau_lo;
    const T t24 = t19 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t19 * t19;
    const T t27 = t20 * t20;
    const T t28 = t27 * tau_lo;
    const T t29 = t25 * delta_tau;
    const T t30 = t26 * t26;
    const T t31 = t30 * delta_tau;
    const T t32 = t26 * delta_tau;
    const T t33 = t27 * t27;
    const T t34 = t33 * tau_lo;
    G_ap = T(36) * t19 * t23 * M_panels[2] + T(84) * M_panels[6] * t25 * t21 + T(126) * t26 * t28 * M_panels[4] + T(36) * t29 * t20 * M_panels[7] + T(9) * t30 * tau_lo * M_panels[8] + t31 * M_panels[9] + T(126) * t32 * t27 * M_panels[5] + M_panels[0] * t34 + T(9) * delta_tau * t33 * M_panels[1] + T(84) * M_panels[3] * t24 * t22;
    G_ab = t31 * M_panels[10] + T(84) * t25 * t21 * M_panels[7] + T(36) * t29 * t20 * M_panels[8] + T(126) * M_panels[6] * t32 * t27 + T(9) * t30 * tau_lo * M_panels[9] + T(9) * delta_tau * t33 * M_panels[2] + T(84) * t24 * t22 * M_panels[4] + t34 * M_panels[1] + T(126) * t26 * t28 * M_panels[5] + T(36) * M_panels[3] * t19 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(cross_cross);
    const T t36 = T(1) / t35;
    const T J2 = t36 * atan2(t35, ap_bp);
    const T t37 = tau_lo * tau_lo;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = T(1) / ab_ab;
    const T t41 = T(1) / cross_cross;
    const T t42 = T(1) / ap_ap;
    const T t43 = t42 * t42;
    const T t44 = t43 * t43;
    const T t45 = t44 * t42;
    const T t46 = T(1) / bp_bp;
    const T t47 = t46 * t46;
    const T t48 = a_minus_b * t46 + ab_ap * t42 + J2 * ab_ab;
    const T t49 = T(2) * ab_ap * t43 + T(2) * a_minus_b * t47 + T(3) * t41 * ab_ab * t48;
    const T t50 = t43 * t42;
    const T t51 = t47 * t46;
    const T t52 = T(5) * t41 * ab_ab * t49 + T(8) * ab_ap * t50 + T(8) * a_minus_b * t51;
    const T t53 = t47 * t47;
    const T t54 = T(48) * ab_ap * t44 + T(7) * t41 * ab_ab * t52 + T(48) * a_minus_b * t53;
    const T t55 = t53 * t46;
    const T t56 = T(128) * ab_ap * t45 + T(3) * t41 * t54 * ab_ab + T(128) * a_minus_b * t55;
    const T t57 = t41 * ab_ap * t56 + T(128) * t45 - T(128) * t55;
    const T t58 = T(48) * t44 + t41 * t54 * ab_ap - T(48) * t53;
    const T t59 = T(6) * t40 * ab_ap * t57 + T(10) * t41 * t54 - T(3) * t41 * t56 * ap_ap;
    const T t60 = T(10) * t40 * t58 + T(2) * t40 * ab_ap * t59 - T(3) * t40 * t57 * ap_ap;
    const T t61 = T(2) * t40 * t58 * ab_ap + T(8) * t41 * t52 - t41 * t54 * ap_ap;
    const T t62 = T(2) * t40 * ab_ap * t60 + T(10) * t40 * t61 - t40 * t59 * ap_ap;
    const T t63 = delta_tau * delta_tau;
    const T t64 = t63 * t63;
    const T t65 = t38 * tau_lo;
    const T t66 = t63 * delta_tau;
    const T t67 = t37 * tau_lo;
    const T t68 = t67 * t67;
    const T t69 = T(8) * t51 - t41 * t52 * ab_ap - T(8) * t50;
    const T t70 = T(2) * t40 * ab_ap * t69 + t41 * t52 * ap_ap - T(6) * t41 * t49;
    const T t71 = T(8) * t40 * t69 + t40 * t58 * ap_ap - T(2) * t40 * t61 * ab_ap;
    const T t72 = T(8) * t40 * t70 + t40 * t61 * ap_ap + T(2) * t71 * t40 * ab_ap;
    const T t73 = T(10) * t71 * t40 + t40 * t60 * ap_ap - T(2) * t62 * t40 * ab_ap;
    const T t74 = T(10) * t72 * t40 + T(2) * t73 * t40 * ab_ap + t62 * t40 * ap_ap;
    const T t75 = T(2) * t43 + t41 * ab_ap * t49 - T(2) * t47;
    const T t76 = T(6) * t40 * t75 + t40 * t69 * ap_ap - T(2) * t40 * ab_ap * t70;
    const T t77 = T(2) * t72 * t40 * ab_ap - T(8) * t40 * t76 - t71 * t40 * ap_ap;
    const T t78 = T(2) * t74 * t40 * ab_ap + T(10) * t40 * t77 - t73 * t40 * ap_ap;
    const T t79 = t41 * ab_ap * t48 + t42 - t46;
    const T t80 = T(2) * t40 * ab_ap * t75 + T(4) * t41 * t48 - t41 * t49 * ap_ap;
    const T t81 = T(4) * t40 * t79 + T(2) * t40 * t80 * ab_ap - t40 * t75 * ap_ap;
    const T t82 = t40 * ap_ap * t70 + T(6) * t40 * t80 + T(2) * t40 * t76 * ab_ap;
    const T t83 = T(6) * t40 * t81 + T(2) * t40 * t82 * ab_ap - t40 * t76 * ap_ap;
    const T t84 = T(8) * t40 * t82 + t72 * t40 * ap_ap - T(2) * t40 * t77 * ab_ap;
    const T t85 = T(8) * t40 * t83 + t40 * t77 * ap_ap + T(2) * t84 * t40 * ab_ap;
    const T t86 = T(10) * t84 * t40 + t74 * t40 * ap_ap - T(2) * t78 * t40 * ab_ap;
    const T t87 = t78 * t40 * ap_ap + T(10) * t85 * t40 + T(2) * t86 * t40 * ab_ap;
    const T t88 = t64 * t64;
    const T t89 = t88 * delta_tau;
    const T t90 = t39 * tau_lo;
    const T t91 = t68 * tau_lo;
    const T t92 = t66 * t66;
    const T t93 = t64 * delta_tau;
    const T t94 = t92 * delta_tau;
    G_ap = (T(9) / T(1280)) * delta_tau * t39 * t40 * t57 + (T(21) / T(640)) * t62 * t64 * t65 * t40 + (T(7) / T(320)) * t66 * t68 * t40 * t60 + (T(1) / T(3840)) * t87 * t89 * t40 + (T(1) / T(1280)) * t41 * t90 * t56 + (T(3) / T(320)) * t63 * t91 * t40 * t59 + (T(3) / T(1280)) * t86 * t88 * tau_lo * t40 - (T(7) / T(320)) * t92 * t67 * t74 * t40 - (T(21) / T(640)) * t73 * t93 * t38 * t40 - (T(3) / T(320)) * t94 * t78 * t37 * t40;
    G_ab = (T(3) / T(1280)) * delta_tau * t39 * t40 * t59 + (T(3) / T(320)) * t86 * t94 * t37 * t40 + (T(3) / T(1280)) * t87 * t88 * tau_lo * t40 + (T(3) / T(320)) * t63 * t91 * t40 * t60 + (T(7) / T(320)) * t62 * t66 * t68 * t40 + (T(1) / T(1280)) * t90 * t40 * t57 - (T(21) / T(640)) * t73 * t64 * t65 * t40 - (T(1) / T(3840)) * t89 * t40 * (T(10) * t40 * (t84 * t40 * ap_ap + T(8) * t40 * (t40 * t82 * ap_ap + T(6) * t40 * (t40 * t80 * ap_ap - T(4) * t40 * (T(2) * J2 + T(2) * t40 * ab_ap * t79 - t41 * t48 * ap_ap) - T(2) * t40 * ab_ap * t81) - T(2) * t40 * ab_ap * t83) - T(2) * t85 * t40 * ab_ap) + t86 * t40 * ap_ap - T(2) * t87 * t40 * ab_ap) - (T(21) / T(640)) * t93 * t38 * t74 * t40 - (T(7) / T(320)) * t92 * t78 * t67 * t40;
  }
  const T t95 = in.sigma * in.sigma;
  const T t96 = t95 * t95;
  const T t97 = t96 * in.sigma;
  const T t98 = t97 * t97;
  const T g_factor = -T(10) * length * t98;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 138 +, 443 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 28599 +, 37083 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = t5 * t5;
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t9 * tau_lo;
    const T t11 = t4 * t4;
    const T t12 = t11 * delta_tau;
    const T t13 = t7 * t7;
    const T t14 = t6 * delta_tau;
    const T t15 = t11 * t11;
    const T t16 = t15 * delta_tau;
    const T t17 = t13 * tau_lo;
    const T t18 = t13 * t13;
    const T t19 = t18 * tau_lo;
    F = T(84) * t6 * M_panels[6] * t8 + T(84) * t5 * t9 * M_panels[3] + T(36) * M_panels[2] * t4 * t10 + T(126) * M_panels[5] * t12 * t13 + T(36) * t14 * t7 * M_panels[7] + T(9) * M_panels[8] * t15 * tau_lo + M_panels[9] * t16 + T(126) * M_panels[4] * t11 * t17 + t19 * M_panels[0] + T(9) * M_panels[1] * delta_tau * t18;
    G_ap = T(84) * M_panels[17] * t6 * t8 + T(126) * t12 * t13 * M_panels[16] + M_panels[20] * t16 + T(36) * t4 * t10 * M_panels[13] + T(84) * M_panels[14] * t5 * t9 + T(36) * M_panels[18] * t14 * t7 + T(9) * M_panels[12] * delta_tau * t18 + M_panels[11] * t19 + T(126) * M_panels[15] * t11 * t17 + T(9) * t15 * tau_lo * M_panels[19];
    G_ab = T(84) * M_panels[15] * t5 * t9 + T(36) * t14 * t7 * M_panels[19] + T(126) * t11 * t17 * M_panels[16] + T(126) * M_panels[17] * t12 * t13 + T(9) * delta_tau * t18 * M_panels[13] + T(84) * M_panels[18] * t6 * t8 + T(36) * M_panels[14] * t4 * t10 + T(9) * M_panels[20] * t15 * tau_lo + M_panels[21] * t16 + M_panels[12] * t19;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t20 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    const T t29 = t24 * t24;
    const T t30 = t29 * tau_lo;
    const T t31 = t23 * tau_lo;
    const T t32 = t31 * t31;
    const T t33 = t21 * delta_tau;
    const T t34 = t32 * tau_lo;
    const T t35 = t22 * delta_tau;
    F = T(9) * M_panels[8] * t22 * tau_lo + T(126) * t21 * t25 * M_panels[4] + T(36) * t28 * t23 * M_panels[7] + t30 * M_panels[0] + T(84) * t26 * M_panels[3] * t32 + T(126) * M_panels[5] * t33 * t24 + T(84) * M_panels[6] * t27 * t31 + T(36) * M_panels[2] * t20 * t34 + M_panels[9] * t35 + T(9) * delta_tau * t29 * M_panels[1];
    G_ap = T(9) * t22 * tau_lo * M_panels[19] + T(84) * M_panels[17] * t27 * t31 + T(84) * M_panels[14] * t26 * t32 + T(9) * M_panels[12] * delta_tau * t29 + T(36) * t20 * t34 * M_panels[13] + t35 * M_panels[20] + T(36) * M_panels[18] * t28 * t23 + M_panels[11] * t30 + T(126) * t33 * t24 * M_panels[16] + T(126) * M_panels[15] * t21 * t25;
    G_ab = M_panels[12] * t30 + T(36) * M_panels[14] * t20 * t34 + T(84) * M_panels[15] * t26 * t32 + M_panels[21] * t35 + T(9) * t22 * tau_lo * M_panels[20] + T(126) * t21 * t25 * M_panels[16] + T(9) * delta_tau * t29 * M_panels[13] + T(126) * M_panels[17] * t33 * t24 + T(84) * M_panels[18] * t27 * t31 + T(36) * t28 * t23 * M_panels[19];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = sqrt(cross_cross);
    const T t37 = T(1) / t36;
    const T J2 = atan2(t36, ap_bp) * t37;
    const T t38 = t0 * t0;
    const T t39 = t38 * t38;
    const T t40 = T(1) / cross_cross;
    const T t41 = T(1) / bp_bp;
    const T t42 = t41 * t41;
    const T t43 = J2 * ab_ab + a_minus_b * t41 + t0 * ab_ap;
    const T t44 = T(2) * t38 * ab_ap + T(2) * a_minus_b * t42 + T(3) * t43 * t40 * ab_ab;
    const T t45 = t42 * t41;
    const T t46 = t38 * t0;
    const T t47 = T(5) * t40 * ab_ab * t44 + T(8) * a_minus_b * t45 + T(8) * t46 * ab_ap;
    const T t48 = t42 * t42;
    const T t49 = T(7) * t40 * ab_ab * t47 + T(48) * t39 * ab_ap + T(48) * a_minus_b * t48;
    const T t50 = T(48) * t39 + t40 * t49 * ab_ap - T(48) * t48;
    const T t51 = T(1) / ab_ab;
    const T t52 = T(2) * t50 * t51 * ab_ap + T(8) * t40 * t47 - ap_ap * t40 * t49;
    const T t53 = t40 * t47 * ab_ap + T(8) * t46 - T(8) * t45;
    const T t54 = T(2) * t52 * t51 * ab_ap + T(8) * t53 * t51 - ap_ap * t50 * t51;
    const T t55 = T(2) * t53 * t51 * ab_ap + T(6) * t40 * t44 - ap_ap * t40 * t47;
    const T t56 = t40 * t44 * ab_ap + T(2) * t38 - T(2) * t42;
    const T t57 = T(2) * t51 * t55 * ab_ap + T(6) * t56 * t51 - t53 * ap_ap * t51;
    const T t58 = T(8) * t51 * t55 + T(2) * t54 * t51 * ab_ap - t52 * ap_ap * t51;
    const T t59 = ap_ap * t54 * t51 - T(8) * t57 * t51 - T(2) * t58 * t51 * ab_ap;
    const T t60 = T(2) * t56 * t51 * ab_ap + T(4) * t43 * t40 - ap_ap * t40 * t44;
    const T t61 = ap_ap * t51 * t55 - T(2) * t57 * t51 * ab_ap - T(6) * t51 * t60;
    const T t62 = T(8) * t61 * t51 + t58 * ap_ap * t51 + T(2) * t59 * t51 * ab_ap;
    const T t63 = t0 + t43 * t40 * ab_ap - t41;
    const T t64 = T(2) * t51 * t60 * ab_ap + T(4) * t51 * t63 - ap_ap * t56 * t51;
    const T t65 = ap_ap * t57 * t51 + T(2) * t61 * t51 * ab_ap - T(6) * t64 * t51;
    const T t66 = ap_ap * t59 * t51 - T(2) * t62 * t51 * ab_ap - T(8) * t51 * t65;
    const T t67 = T(2) * J2 + T(2) * t51 * ab_ap * t63 - ap_ap * t43 * t40;
    const T t68 = T(2) * t64 * t51 * ab_ap + T(4) * t67 * t51 - ap_ap * t51 * t60;
    const T t69 = ap_ap * t61 * t51 + T(6) * t68 * t51 - T(2) * t51 * t65 * ab_ap;
    const T t70 = T(2) * t66 * t51 * ab_ap + t62 * ap_ap * t51 + T(8) * t69 * t51;
    const T t71 = delta_tau * delta_tau;
    const T t72 = t71 * t71;
    const T t73 = t72 * t72;
    const T t74 = tau_lo * tau_lo;
    const T t75 = t74 * t74;
    const T t76 = t75 * tau_lo;
    const T t77 = t75 * t75;
    const T t78 = t77 * tau_lo;
    const T t79 = t71 * delta_tau;
    const T t80 = t74 * tau_lo;
    const T t81 = t80 * t80;
    const T t82 = t81 * tau_lo;
    const T t83 = t79 * t79;
    const T t84 = t83 * delta_tau;
    const T t85 = t72 * delta_tau;
    const T t86 = t73 * delta_tau;
    F = (T(3) / T(128)) * t70 * t73 * tau_lo * t51 + (T(21) / T(64)) * t58 * t72 * t76 * t51 + (T(1) / T(384)) * t40 * t78 * t49 + (T(3) / T(128)) * delta_tau * t50 * t77 * t51 + (T(7) / T(32)) * t54 * t79 * t81 * t51 + (T(3) / T(32)) * t52 * t71 * t82 * t51 + (T(3) / T(32)) * t66 * t84 * t74 * t51 - (T(21) / T(64)) * t59 * t85 * t75 * t51 - (T(1) / T(384)) * t86 * t51 * (t66 * ap_ap * t51 + T(8) * t51 * (T(6) * (t64 * ap_ap * t51 - T(4) * ((log_ratio + T(2) * J2 * ab_ap) * t51 + T(2) * t67 * t51 * ab_ap - ap_ap * t51 * t63) * t51 - T(2) * t68 * t51 * ab_ap) * t51 - T(2) * t69 * t51 * ab_ap - ap_ap * t51 * t65) - T(2) * t70 * t51 * ab_ap) - (T(7) / T(32)) * t62 * t83 * t80 * t51;
    const T t87 = t39 * t0;
    const T t88 = t48 * t41;
    const T t89 = T(128) * t87 * ab_ap + T(3) * t40 * ab_ab * t49 + T(128) * a_minus_b * t88;
    const T t90 = t89 * t40 * ab_ap + T(128) * t87 - T(128) * t88;
    const T t91 = T(6) * t90 * t51 * ab_ap + T(10) * t40 * t49 - T(3) * t89 * ap_ap * t40;
    const T t92 = T(2) * t91 * t51 * ab_ap + T(10) * t50 * t51 - T(3) * ap_ap * t90 * t51;
    const T t93 = T(2) * t92 * t51 * ab_ap + T(10) * t52 * t51 - ap_ap * t91 * t51;
    const T t94 = T(10) * t54 * t51 + T(2) * t93 * t51 * ab_ap - t92 * ap_ap * t51;
    const T t95 = T(2) * t94 * t51 * ab_ap + T(10) * t58 * t51 - ap_ap * t93 * t51;
    const T t96 = T(10) * t59 * t51 + ap_ap * t94 * t51 - T(2) * t95 * t51 * ab_ap;
    const T t97 = T(10) * t62 * t51 + T(2) * t96 * t51 * ab_ap + ap_ap * t95 * t51;
    const T t98 = ap_ap * t96 * t51 + T(10) * t66 * t51 - T(2) * t97 * t51 * ab_ap;
    G_ap = (T(21) / T(640)) * t93 * t72 * t76 * t51 + (T(9) / T(1280)) * t90 * delta_tau * t77 * t51 + (T(7) / T(320)) * t92 * t79 * t81 * t51 + (T(1) / T(1280)) * t89 * t40 * t78 + (T(21) / T(640)) * t94 * t85 * t75 * t51 + (T(1) / T(3840)) * t86 * t51 * t98 + (T(3) / T(320)) * t91 * t71 * t82 * t51 + (T(7) / T(320)) * t95 * t83 * t80 * t51 - (T(3) / T(1280)) * t73 * tau_lo * t97 * t51 - (T(3) / T(320)) * t96 * t84 * t74 * t51;
    G_ab = (T(1) / T(1280)) * t90 * t78 * t51 + (T(3) / T(1280)) * t73 * tau_lo * t51 * t98 + (T(3) / T(1280)) * t91 * delta_tau * t77 * t51 + (T(21) / T(640)) * t95 * t85 * t75 * t51 + (T(1) / T(3840)) * t86 * t51 * (ap_ap * t97 * t51 + T(2) * t51 * t98 * ab_ap + T(10) * t70 * t51) + (T(7) / T(320)) * t93 * t79 * t81 * t51 + (T(3) / T(320)) * t92 * t71 * t82 * t51 + (T(21) / T(640)) * t94 * t72 * t76 * t51 - (T(3) / T(320)) * t84 * t74 * t97 * t51 - (T(7) / T(320)) * t96 * t83 * t80 * t51;
  }
  const T t99 = in.sigma * in.sigma;
  const T t100 = t99 * t99;
  const T t101 = t100 * in.sigma;
  const T t102 = t101 * t101;
  const T g_factor = -T(10) * t102 * length;
  f = F * t102 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

}  // namespace skelconv::generated
