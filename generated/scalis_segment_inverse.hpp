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

#include <skelconv/exact_cross.hpp>
#include <skelconv/gauss_moments.hpp>
#include <skelconv/scalis_segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 32 +, 42 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 7036 +, 8925 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + tau_lo * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T J2 = atan2(t4, ap_bp) / t4;
    F = (T(1) / T(2)) * delta_tau * (log_ratio + T(2) * J2 * ab_ap) / ab_ab + tau_lo * J2;
  }
  f = length * in.sigma * in.sigma * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 44 +, 69 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 11364 +, 15427 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab_ap * t1 * ab1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * t2;
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * t2;
    foot2 = -(ab0 * exact_cross[1] - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    G_ap = t6;
    const T t7 = T(1) / ab_ab;
    G_E = tau_lo * M_panels[4] + M_panels[5] * delta_tau - ab_ap * t7 * t6;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    G_ap = t8;
    const T t9 = T(1) / ab_ab;
    G_E = tau_lo * M_panels[4] + M_panels[5] * delta_tau - ab_ap * t9 * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / ap_ap;
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / bp_bp;
    const T t15 = a_minus_b * t14 + ab_ap * t12 + J2 * ab_ab;
    const T t16 = T(1) / ab_ab;
    G_ap = (T(1) / T(2)) * (t12 + t13 * ab_ap * t15 - t14) * delta_tau * t16 + (T(1) / T(2)) * t13 * tau_lo * t15;
    G_E = (T(1) / T(2)) * (t12 * tau_lo + J2 * delta_tau - t14 * (tau_lo + delta_tau)) * t16;
  }
  const T g_factor = -T(2) * length * in.sigma * in.sigma;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 46 +, 78 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11365 +, 15432 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - ab_ap * t1 * ab0;
    foot1 = ap1 - ab_ap * t1 * ab1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * t2;
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t3 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t7 = M_panels[4] * delta_tau + tau_lo * M_panels[3];
    G_ap = t7;
    const T t8 = T(1) / ab_ab;
    G_E = M_panels[4] * tau_lo + M_panels[5] * delta_tau - ab_ap * t7 * t8;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[1] * delta_tau + tau_lo * M_panels[0];
    const T t9 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t9;
    const T t10 = T(1) / ab_ab;
    G_E = M_panels[4] * tau_lo + M_panels[5] * delta_tau - t9 * ab_ap * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(2)) * (T(2) * ab_ap * J2 + log_ratio) * delta_tau * t13 + J2 * tau_lo;
    const T t14 = T(1) / bp_bp;
    const T t15 = t14 * a_minus_b + J2 * ab_ab + ab_ap * t3;
    const T t16 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * delta_tau * t13 * (t3 + ab_ap * t15 * t16 - t14) + (T(1) / T(2)) * t15 * tau_lo * t16;
    G_E = -(T(1) / T(2)) * (t14 * (delta_tau + tau_lo) - J2 * delta_tau - t3 * tau_lo) * t13;
  }
  const T t17 = in.sigma * in.sigma;
  const T g_factor = -T(2) * length * t17;
  f = length * t17 * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 36 +, 60 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 8116 +, 12174 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = ab_ap * r1;
    X = t2 * (t3 + r0 * a_minus_b) * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t4 - r0 * a_minus_b);
  }
  const T t5 = T(1) / length;
  const T J1 = asinh(X) * t5;
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -ab_ap * a_minus_b;
  const T t8 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = tau_lo * tau_lo;
    F = M_panels[2] * t9 + T(2) * tau_lo * delta_tau * M_panels[1] + M_panels[0] * t10;
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = delta_tau * delta_tau;
    F = M_panels[0] * t11 + T(2) * tau_lo * M_panels[1] * delta_tau + t12 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + ab_ap * t15;
    const T t17 = tau_lo * tau_lo;
    const T t18 = delta_tau * delta_tau;
    const T t19 = T(1) / ab_ab;
    const T t20 = t14 - t13 * ab_ap * t16 - t15;
    F = t13 * t16 * t17 + t18 * t19 * (J1 - T(2) * ab_ap * t20 * t19 - t13 * ap_ap * t16) - T(2) * t20 * tau_lo * delta_tau * t19;
  }
  const T t21 = in.sigma * in.sigma;
  const T t22 = t21 * in.sigma;
  f = length * t22 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 50 +, 103 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 13524 +, 20833 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = (ab1 * exact_cross[0] - ab0 * exact_cross[1]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = tau_lo * tau_lo;
    const T t8 = M_panels[6] * t6 + t7 * M_panels[4] + T(2) * tau_lo * M_panels[5] * delta_tau;
    G_ap = t8;
    const T t9 = T(1) / ab_ab;
    G_E = M_panels[7] * t6 + T(2) * tau_lo * M_panels[6] * delta_tau + t7 * M_panels[5] - t9 * t8 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t10 = delta_tau * delta_tau;
    const T t11 = tau_lo * tau_lo;
    const T t12 = M_panels[6] * t10 + t11 * M_panels[4] + T(2) * tau_lo * M_panels[5] * delta_tau;
    G_ap = t12;
    const T t13 = T(1) / ab_ab;
    G_E = T(2) * tau_lo * M_panels[6] * delta_tau + M_panels[7] * t10 + t11 * M_panels[5] - t13 * ab_ap * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = tau_lo * tau_lo;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 * a_minus_b + ab_ap * t16;
    const T t18 = T(1) / cross_cross;
    const T t19 = t16 * t16;
    const T t20 = t15 * t15;
    const T t21 = T(2) * t17 * ab_ab * t18 + ab_ap * t19 * t16 + t15 * a_minus_b * t20;
    const T t22 = T(1) / ab_ab;
    const T t23 = t15 * t20 - t21 * t18 * ab_ap - t19 * t16;
    const T t24 = delta_tau * delta_tau;
    G_ap = (T(1) / T(3)) * t14 * t21 * t18 - (T(1) / T(3)) * t22 * (t21 * t18 * ap_ap + T(2) * t22 * ab_ap * t23 - T(3) * t17 * t18) * t24 - (T(2) / T(3)) * tau_lo * t22 * t23 * delta_tau;
    const T t25 = t15 * t15;
    const T t26 = t25 * t15;
    const T t27 = t16 * t16;
    const T t28 = t27 * t16;
    G_E = -(T(1) / T(3)) * t22 * (t26 * (t14 + t24 + T(2) * tau_lo * delta_tau) - t14 * t28 - T(2) * tau_lo * t17 * t18 * delta_tau - T(2) * t22 * t24 * (t16 + t17 * t18 * ab_ap - t15));
  }
  const T t29 = in.sigma * in.sigma;
  const T t30 = t29 * in.sigma;
  const T g_factor = -T(3) * length * t30;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 55 +, 124 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 13527 +, 20846 ×, 2439 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (ab1 * exact_cross[2] - ab2 * exact_cross[1]);
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = t2 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = ab_ap * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / cross_cross;
    const T t5 = r1 * ab_ap;
    X = length * t4 * (t5 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = length * (ab_ap - a_minus_b) / (t6 - r0 * a_minus_b);
  }
  const T t7 = T(1) / length;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = delta_tau * delta_tau;
    F = t11 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1] + t12 * M_panels[2];
    const T t13 = T(2) * delta_tau * M_panels[5] * tau_lo + t12 * M_panels[6] + t11 * M_panels[4];
    G_ap = t13;
    const T t14 = T(1) / ab_ab;
    G_E = M_panels[5] * t11 + t12 * M_panels[7] + T(2) * delta_tau * tau_lo * M_panels[6] - t14 * ab_ap * t13;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t15 = tau_lo * tau_lo;
    const T t16 = delta_tau * delta_tau;
    F = t15 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1] + t16 * M_panels[2];
    const T t17 = t16 * M_panels[6] + T(2) * delta_tau * tau_lo * M_panels[5] + t15 * M_panels[4];
    G_ap = t17;
    const T t18 = T(1) / ab_ab;
    G_E = t15 * M_panels[5] + t16 * M_panels[7] + T(2) * delta_tau * tau_lo * M_panels[6] - t18 * ab_ap * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = tau_lo * tau_lo;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / r0;
    const T t22 = T(1) / r1;
    const T t23 = t21 * ab_ap + t22 * a_minus_b;
    const T t24 = delta_tau * delta_tau;
    const T t25 = T(1) / ab_ab;
    const T t26 = t22 - t20 * ab_ap * t23 - t21;
    F = t19 * t20 * t23 + t24 * t25 * (J1 - t20 * t23 * ap_ap - T(2) * t25 * ab_ap * t26) - T(2) * delta_tau * tau_lo * t25 * t26;
    const T t27 = t22 * t22;
    const T t28 = t21 * t21;
    const T t29 = t22 * t27 * a_minus_b + t21 * ab_ap * t28 + T(2) * ab_ab * t20 * t23;
    const T t30 = t22 * t27 - t29 * t20 * ab_ap - t21 * t28;
    G_ap = (T(1) / T(3)) * t19 * t29 * t20 + (T(1) / T(3)) * t24 * t25 * (T(3) * t20 * t23 - t29 * t20 * ap_ap - T(2) * t25 * ab_ap * t30) - (T(2) / T(3)) * delta_tau * tau_lo * t25 * t30;
    const T t31 = t22 * t22;
    const T t32 = t31 * t22;
    const T t33 = t21 * t21;
    const T t34 = t33 * t21;
    G_E = -(T(1) / T(3)) * t25 * (T(2) * t24 * t25 * t26 + (t24 + T(2) * delta_tau * tau_lo + t19) * t32 - T(2) * delta_tau * tau_lo * t20 * t23 - t34 * t19);
  }
  const T t35 = in.sigma * in.sigma;
  const T t36 = t35 * in.sigma;
  const T g_factor = -T(3) * length * t36;
  f = length * t36 * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 42 +, 77 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 9198 +, 12177 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t1 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t1);
  T F;
  const T t2 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t3 = -a_minus_b * ab_ap;
  const T t4 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t5 = tau_lo * tau_lo;
    const T t6 = delta_tau * delta_tau;
    const T t7 = t5 * tau_lo;
    const T t8 = t6 * delta_tau;
    F = T(3) * delta_tau * M_panels[1] * t5 + T(3) * t6 * tau_lo * M_panels[2] + M_panels[0] * t7 + M_panels[3] * t8;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = tau_lo * tau_lo;
    const T t11 = t9 * delta_tau;
    const T t12 = t10 * tau_lo;
    F = T(3) * M_panels[2] * t9 * tau_lo + T(3) * delta_tau * t10 * M_panels[1] + t11 * M_panels[3] + M_panels[0] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / bp_bp;
    const T t16 = J2 * ab_ab + t1 * ab_ap + t15 * a_minus_b;
    const T t17 = T(1) / cross_cross;
    const T t18 = t1 + t16 * t17 * ab_ap - t15;
    const T t19 = tau_lo * tau_lo;
    const T t20 = T(1) / ab_ab;
    const T t21 = t19 * tau_lo;
    const T t22 = t16 * ap_ap * t17 - T(2) * t18 * t20 * ab_ap - T(2) * J2;
    const T t23 = delta_tau * delta_tau;
    const T t24 = t23 * delta_tau;
    F = (T(3) / T(2)) * t18 * delta_tau * t19 * t20 + (T(1) / T(2)) * t16 * t21 * t17 - (T(3) / T(2)) * t22 * t23 * tau_lo * t20 - (T(1) / T(2)) * (T(2) * t22 * t20 * ab_ap + t18 * ap_ap * t20 - t20 * (T(2) * J2 * ab_ap + log_ratio)) * t24 * t20;
  }
  const T t25 = in.sigma * in.sigma;
  const T t26 = t25 * t25;
  f = length * t26 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 60 +, 131 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 15688 +, 20844 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t1 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[0] * exact_cross[0] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = -(exact_cross[2] * ab1 - ab2 * exact_cross[1]) * t2;
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t7 * M_panels[5] + t9 * M_panels[8] + T(3) * M_panels[7] * t8 * tau_lo + T(3) * delta_tau * t6 * M_panels[6];
    G_ap = t10;
    const T t11 = T(1) / ab_ab;
    G_E = T(3) * M_panels[7] * delta_tau * t6 + T(3) * t8 * tau_lo * M_panels[8] + t7 * M_panels[6] + t9 * M_panels[9] - t10 * t11 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = delta_tau * delta_tau;
    const T t13 = t12 * delta_tau;
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * tau_lo;
    const T t16 = t13 * M_panels[8] + t15 * M_panels[5] + T(3) * M_panels[6] * delta_tau * t14 + T(3) * t12 * M_panels[7] * tau_lo;
    G_ap = t16;
    const T t17 = T(1) / ab_ab;
    G_E = T(3) * t12 * tau_lo * M_panels[8] + T(3) * delta_tau * M_panels[7] * t14 + M_panels[6] * t15 + M_panels[9] * t13 - t16 * t17 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(cross_cross);
    const T t19 = T(1) / t18;
    const T J2 = t19 * atan2(t18, ap_bp);
    const T t20 = delta_tau * delta_tau;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / ap_ap;
    const T t23 = t22 * t22;
    const T t24 = T(1) / cross_cross;
    const T t25 = T(1) / bp_bp;
    const T t26 = a_minus_b * t25 + J2 * ab_ab + t22 * ab_ap;
    const T t27 = t25 * t25;
    const T t28 = T(2) * t23 * ab_ap + T(3) * ab_ab * t24 * t26 + T(2) * a_minus_b * t27;
    const T t29 = T(2) * t23 + t28 * t24 * ab_ap - T(2) * t27;
    const T t30 = T(2) * t21 * t29 * ab_ap + T(4) * t24 * t26 - t28 * ap_ap * t24;
    const T t31 = tau_lo * tau_lo;
    const T t32 = t31 * tau_lo;
    const T t33 = t20 * delta_tau;
    const T t34 = t25 - t22 - t24 * ab_ap * t26;
    G_ap = (T(3) / T(8)) * t20 * tau_lo * t21 * t30 + (T(3) / T(8)) * delta_tau * t31 * t21 * t29 + (T(1) / T(8)) * t28 * t32 * t24 - (T(1) / T(8)) * t33 * (ap_ap * t21 * t29 + T(4) * t34 * t21 - T(2) * t21 * t30 * ab_ap) * t21;
    G_E = -(T(1) / T(8)) * (T(3) * t33 * (T(2) * t34 * t21 * ab_ap + ap_ap * t24 * t26 - T(2) * J2) * t21 + T(2) * (T(3) * delta_tau * t31 + T(3) * t20 * tau_lo + t32 + t33) * t27 + T(6) * t34 * t20 * tau_lo * t21 - T(2) * t23 * t32 - T(3) * delta_tau * t31 * t24 * t26) * t21;
  }
  const T t35 = in.sigma * in.sigma;
  const T t36 = t35 * t35;
  const T g_factor = -T(4) * t36 * length;
  grad[0] = (G_ap * foot0 - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 66 +, 156 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15691 +, 20855 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t1 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (ab1 * exact_cross[2] - exact_cross[1] * ab2);
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * t2;
    foot2 = -(exact_cross[1] * ab0 - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t3 = T(1) / ap_ap;
  const T log_ratio = log(t3 * bp_bp);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * tau_lo;
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * delta_tau;
    F = t8 * M_panels[0] + T(3) * delta_tau * t7 * M_panels[1] + t10 * M_panels[3] + T(3) * t9 * M_panels[2] * tau_lo;
    const T t11 = M_panels[8] * t10 + T(3) * t9 * tau_lo * M_panels[7] + M_panels[5] * t8 + T(3) * delta_tau * t7 * M_panels[6];
    G_ap = t11;
    const T t12 = T(1) / ab_ab;
    G_E = t10 * M_panels[9] + t8 * M_panels[6] + T(3) * delta_tau * t7 * M_panels[7] + T(3) * M_panels[8] * t9 * tau_lo - t11 * t12 * ab_ap;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t13 = tau_lo * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t13 * tau_lo;
    const T t16 = t14 * delta_tau;
    F = T(3) * M_panels[1] * delta_tau * t13 + T(3) * t14 * tau_lo * M_panels[2] + t15 * M_panels[0] + t16 * M_panels[3];
    const T t17 = t16 * M_panels[8] + T(3) * t14 * tau_lo * M_panels[7] + M_panels[5] * t15 + T(3) * delta_tau * t13 * M_panels[6];
    G_ap = t17;
    const T t18 = T(1) / ab_ab;
    G_E = t15 * M_panels[6] + T(3) * delta_tau * t13 * M_panels[7] + T(3) * t14 * M_panels[8] * tau_lo + t16 * M_panels[9] - t17 * t18 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, ap_bp) * t20;
    const T t21 = T(1) / bp_bp;
    const T t22 = a_minus_b * t21 + t3 * ab_ap + ab_ab * J2;
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * tau_lo;
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / ab_ab;
    const T t27 = t22 * t25 * ab_ap + t3 - t21;
    const T t28 = ap_ap * t22 * t25 - T(2) * t27 * t26 * ab_ap - T(2) * J2;
    const T t29 = delta_tau * delta_tau;
    const T t30 = t29 * delta_tau;
    F = (T(1) / T(2)) * t22 * t24 * t25 + (T(1) / T(2)) * (t26 * (log_ratio + T(2) * ab_ap * J2) - T(2) * t26 * t28 * ab_ap - ap_ap * t27 * t26) * t30 * t26 + (T(3) / T(2)) * delta_tau * t27 * t23 * t26 - (T(3) / T(2)) * t29 * tau_lo * t26 * t28;
    const T t31 = t3 * t3;
    const T t32 = t21 * t21;
    const T t33 = T(3) * t22 * ab_ab * t25 + T(2) * t31 * ab_ap + T(2) * a_minus_b * t32;
    const T t34 = T(2) * t31 + t25 * t33 * ab_ap - T(2) * t32;
    const T t35 = T(2) * t34 * t26 * ab_ap + T(4) * t22 * t25 - ap_ap * t25 * t33;
    G_ap = (T(3) / T(8)) * t29 * tau_lo * t26 * t35 + (T(3) / T(8)) * delta_tau * t34 * t23 * t26 + (T(1) / T(8)) * t24 * t25 * t33 - (T(1) / T(8)) * t30 * (ap_ap * t34 * t26 - T(4) * t27 * t26 - T(2) * t26 * ab_ap * t35) * t26;
    G_E = (T(1) / T(8)) * (T(2) * t31 * t24 + T(6) * t29 * t27 * tau_lo * t26 + T(3) * delta_tau * t22 * t23 * t25 - T(3) * t30 * t26 * t28 - T(2) * (T(3) * t29 * tau_lo + t30 + T(3) * delta_tau * t23 + t24) * t32) * t26;
  }
  const T t36 = in.sigma * in.sigma;
  const T t37 = t36 * t36;
  const T g_factor = -T(4) * t37 * length;
  f = t37 * F * length;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 48 +, 109 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 10278 +, 16505 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = ab_ap * r1;
    X = length * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = ab_ap * r1;
    X = -length * (a_minus_b - ab_ap) / (t4 - a_minus_b * r0);
  }
  const T t5 = T(1) / length;
  const T J1 = t5 * asinh(X);
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * delta_tau;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * tau_lo;
    const T t13 = t9 * t9;
    const T t14 = t11 * t11;
    F = T(4) * t10 * tau_lo * M_panels[3] + T(4) * delta_tau * M_panels[1] * t12 + T(6) * t9 * t11 * M_panels[2] + t13 * M_panels[4] + t14 * M_panels[0];
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t15 = delta_tau * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t17 * tau_lo;
    const T t20 = t15 * delta_tau;
    F = t16 * M_panels[4] + t18 * M_panels[0] + T(4) * delta_tau * t19 * M_panels[1] + T(4) * t20 * tau_lo * M_panels[3] + T(6) * t15 * M_panels[2] * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = tau_lo * tau_lo;
    const T t22 = t21 * t21;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / r1;
    const T t27 = a_minus_b * t26 + t23 * ab_ap;
    const T t28 = t26 * t26;
    const T t29 = t23 * ab_ap * t24 + T(2) * ab_ab * t25 * t27 + a_minus_b * t28 * t26;
    const T t30 = delta_tau * delta_tau;
    const T t31 = T(1) / ab_ab;
    const T t32 = t29 * t25 * ab_ap + t23 * t24 - t28 * t26;
    const T t33 = T(3) * t25 * t27 + T(2) * t31 * t32 * ab_ap - t29 * t25 * ap_ap;
    const T t34 = t30 * delta_tau;
    const T t35 = t26 - t25 * ab_ap * t27 - t23;
    const T t36 = T(2) * t31 * ab_ap * t33 - t31 * t32 * ap_ap - T(3) * t31 * t35;
    const T t37 = t21 * tau_lo;
    const T t38 = t30 * t30;
    F = (T(1) / T(3)) * t22 * t29 * t25 + T(2) * t30 * t21 * t31 * t33 + (T(4) / T(3)) * t34 * tau_lo * t31 * t36 + (T(4) / T(3)) * delta_tau * t37 * t31 * t32 - (T(1) / T(3)) * t38 * t31 * (T(3) * t31 * (T(2) * t31 * ab_ap * t35 + t25 * t27 * ap_ap - J1) + t31 * t33 * ap_ap - T(2) * t31 * ab_ap * t36);
  }
  const T t39 = in.sigma * in.sigma;
  const T t40 = t39 * t39;
  const T t41 = t40 * in.sigma;
  f = length * t41 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 68 +, 177 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 17848 +, 27330 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - ab_ap * t1 * ab0;
    foot1 = ap1 - ab_ap * t1 * ab1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -t2 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t6 * tau_lo;
    const T t11 = t8 * delta_tau;
    const T t12 = M_panels[6] * t7 + t9 * M_panels[10] + T(6) * M_panels[8] * t8 * t6 + T(4) * delta_tau * t10 * M_panels[7] + T(4) * M_panels[9] * t11 * tau_lo;
    G_ap = t12;
    const T t13 = T(1) / ab_ab;
    G_E = t7 * M_panels[7] + M_panels[11] * t9 + T(4) * t11 * tau_lo * M_panels[10] + T(4) * M_panels[8] * delta_tau * t10 + T(6) * M_panels[9] * t8 * t6 - ab_ap * t12 * t13;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t14 * delta_tau;
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * tau_lo;
    const T t19 = t17 * t17;
    const T t20 = t15 * M_panels[10] + T(4) * M_panels[9] * t16 * tau_lo + T(4) * delta_tau * t18 * M_panels[7] + M_panels[6] * t19 + T(6) * M_panels[8] * t14 * t17;
    G_ap = t20;
    const T t21 = T(1) / ab_ab;
    G_E = T(6) * M_panels[9] * t14 * t17 + T(4) * M_panels[8] * delta_tau * t18 + t19 * M_panels[7] + T(4) * t16 * tau_lo * M_panels[10] + t15 * M_panels[11] - ab_ap * t20 * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t22 * a_minus_b + ab_ap * t25;
    const T t29 = T(1) / cross_cross;
    const T t30 = ab_ap * t25 * t26 + t23 * t22 * a_minus_b + T(2) * t28 * ab_ab * t29;
    const T t31 = T(3) * t24 * t22 * a_minus_b + T(3) * ab_ap * t25 * t27 + T(4) * t30 * ab_ab * t29;
    const T t32 = tau_lo * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = T(3) * t25 * t27 + ab_ap * t31 * t29 - T(3) * t24 * t22;
    const T t35 = t32 * tau_lo;
    const T t36 = T(1) / ab_ab;
    const T t37 = delta_tau * delta_tau;
    const T t38 = t37 * delta_tau;
    const T t39 = t31 * ap_ap * t29 - T(5) * t30 * t29 - T(2) * t34 * ab_ap * t36;
    const T t40 = t23 * t22 - t25 * t26 - ab_ap * t30 * t29;
    const T t41 = T(2) * ab_ap * t39 * t36 + t34 * ap_ap * t36 + T(5) * t40 * t36;
    const T t42 = t37 * t37;
    const T t43 = ap_ap * t30 * t29 + T(2) * ab_ap * t40 * t36 - T(3) * t28 * t29;
    G_ap = (T(1) / T(15)) * t31 * t33 * t29 + (T(4) / T(15)) * t34 * delta_tau * t35 * t36 - (T(4) / T(15)) * t38 * tau_lo * t36 * t41 - (T(1) / T(15)) * t42 * t36 * (T(5) * t36 * t43 + T(2) * ab_ap * t36 * t41 - ap_ap * t39 * t36) - (T(2) / T(5)) * t37 * t32 * t39 * t36;
    const T t44 = t25 * t25;
    const T t45 = t44 * t44;
    const T t46 = t45 * t25;
    const T t47 = t22 * t22;
    const T t48 = t47 * t47;
    const T t49 = t48 * t22;
    G_E = (T(1) / T(15)) * (T(3) * t46 * t33 + T(4) * (T(3) * (t25 + ab_ap * t28 * t29 - t22) * t36 + ap_ap * t40 * t36 - T(2) * ab_ap * t36 * t43) * t42 * t36 + T(4) * delta_tau * t30 * t35 * t29 - T(12) * t40 * t37 * t32 * t36 - T(3) * (T(4) * delta_tau * t35 + t33 + t42 + T(6) * t37 * t32 + T(4) * t38 * tau_lo) * t49 - T(12) * t38 * tau_lo * t36 * t43) * t36;
  }
  const T t50 = in.sigma * in.sigma;
  const T t51 = t50 * t50;
  const T t52 = t51 * in.sigma;
  const T g_factor = -T(5) * length * t52;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 77 +, 215 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 17853 +, 27349 ×, 2439 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -(exact_cross[1] * ab0 - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = ab_ap * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / cross_cross;
    const T t5 = r0 * a_minus_b;
    X = length * t4 * (t5 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t6 - r1 * ab_ap);
  }
  const T t7 = T(1) / length;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t13 * tau_lo;
    const T t16 = t11 * delta_tau;
    F = t12 * M_panels[4] + t14 * M_panels[0] + T(4) * delta_tau * t15 * M_panels[1] + T(6) * t11 * M_panels[2] * t13 + T(4) * t16 * tau_lo * M_panels[3];
    const T t17 = t12 * M_panels[10] + t14 * M_panels[6] + T(6) * M_panels[8] * t11 * t13 + T(4) * t16 * tau_lo * M_panels[9] + T(4) * delta_tau * t15 * M_panels[7];
    G_ap = t17;
    const T t18 = T(1) / ab_ab;
    G_E = T(4) * t16 * tau_lo * M_panels[10] + t14 * M_panels[7] + t12 * M_panels[11] + T(4) * M_panels[8] * delta_tau * t15 + T(6) * t11 * t13 * M_panels[9] - t18 * ab_ap * t17;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t19 = tau_lo * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = delta_tau * delta_tau;
    const T t22 = t21 * delta_tau;
    const T t23 = t21 * t21;
    const T t24 = t19 * tau_lo;
    F = t20 * M_panels[0] + T(6) * M_panels[2] * t21 * t19 + T(4) * t22 * tau_lo * M_panels[3] + t23 * M_panels[4] + T(4) * delta_tau * t24 * M_panels[1];
    const T t25 = t23 * M_panels[10] + T(4) * M_panels[9] * t22 * tau_lo + T(4) * delta_tau * t24 * M_panels[7] + T(6) * t21 * t19 * M_panels[8] + M_panels[6] * t20;
    G_ap = t25;
    const T t26 = T(1) / ab_ab;
    G_E = T(4) * delta_tau * t24 * M_panels[8] + t23 * M_panels[11] + t20 * M_panels[7] + T(4) * t22 * tau_lo * M_panels[10] + T(6) * M_panels[9] * t21 * t19 - t26 * t25 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = tau_lo * tau_lo;
    const T t28 = t27 * tau_lo;
    const T t29 = T(1) / ab_ab;
    const T t30 = T(1) / cross_cross;
    const T t31 = T(1) / r0;
    const T t32 = T(1) / r1;
    const T t33 = t31 * ab_ap + t32 * a_minus_b;
    const T t34 = t32 * t32;
    const T t35 = t31 * t31;
    const T t36 = T(2) * t33 * ab_ab * t30 + t32 * t34 * a_minus_b + t35 * t31 * ab_ap;
    const T t37 = t30 * ab_ap * t36 + t35 * t31 - t32 * t34;
    const T t38 = delta_tau * delta_tau;
    const T t39 = t38 * t38;
    const T t40 = t31 + t33 * t30 * ab_ap - t32;
    const T t41 = T(3) * t33 * t30 + T(2) * t29 * t37 * ab_ap - ap_ap * t30 * t36;
    const T t42 = ap_ap * t29 * t37 - T(2) * t41 * t29 * ab_ap - T(3) * t29 * t40;
    const T t43 = t27 * t27;
    const T t44 = t38 * delta_tau;
    F = (T(4) / T(3)) * delta_tau * t28 * t29 * t37 + (T(1) / T(3)) * t39 * t29 * (T(3) * t29 * (J1 + T(2) * t29 * t40 * ab_ap - ap_ap * t33 * t30) - T(2) * t29 * ab_ap * t42 - ap_ap * t41 * t29) + T(2) * t38 * t41 * t27 * t29 + (T(1) / T(3)) * t43 * t30 * t36 - (T(4) / T(3)) * t44 * tau_lo * t29 * t42;
    const T t45 = t34 * t34;
    const T t46 = t35 * t35;
    const T t47 = T(3) * t32 * t45 * a_minus_b + T(3) * t46 * t31 * ab_ap + T(4) * ab_ab * t30 * t36;
    const T t48 = t30 * t47 * ab_ap + T(3) * t46 * t31 - T(3) * t32 * t45;
    const T t49 = T(5) * t30 * t36 + T(2) * t48 * t29 * ab_ap - ap_ap * t30 * t47;
    const T t50 = T(5) * t29 * t37 + T(2) * t49 * t29 * ab_ap - ap_ap * t48 * t29;
    G_ap = (T(1) / T(15)) * t43 * t30 * t47 + (T(1) / T(15)) * t39 * (T(2) * t50 * t29 * ab_ap + T(5) * t41 * t29 - ap_ap * t49 * t29) * t29 + (T(2) / T(5)) * t38 * t49 * t27 * t29 + (T(4) / T(15)) * t44 * tau_lo * t50 * t29 + (T(4) / T(15)) * t48 * delta_tau * t28 * t29;
    const T t51 = t31 * t31;
    const T t52 = t51 * t51;
    const T t53 = t52 * t31;
    const T t54 = t32 * t32;
    const T t55 = t54 * t54;
    const T t56 = t55 * t32;
    G_E = (T(1) / T(15)) * (T(12) * t44 * t41 * tau_lo * t29 + T(12) * t38 * t27 * t29 * t37 + T(4) * delta_tau * t28 * t30 * t36 + T(3) * t43 * t53 - T(4) * t39 * t29 * t42 - T(3) * (t43 + T(4) * delta_tau * t28 + t39 + T(6) * t38 * t27 + T(4) * t44 * tau_lo) * t56) * t29;
  }
  const T t57 = in.sigma * in.sigma;
  const T t58 = t57 * t57;
  const T t59 = t58 * in.sigma;
  const T g_factor = -T(5) * length * t59;
  f = length * t59 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 56 +, 131 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11360 +, 15428 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross1 * plain_cross1 + plain_cross2 * plain_cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t1 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t1);
  T F;
  const T t2 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t3 = -a_minus_b * ab_ap;
  const T t4 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t5 = tau_lo * tau_lo;
    const T t6 = t5 * tau_lo;
    const T t7 = delta_tau * delta_tau;
    const T t8 = t7 * delta_tau;
    const T t9 = t7 * t7;
    const T t10 = t5 * t5;
    const T t11 = t9 * delta_tau;
    const T t12 = t10 * tau_lo;
    F = T(10) * t6 * t7 * M_panels[2] + T(10) * t5 * t8 * M_panels[3] + T(5) * tau_lo * t9 * M_panels[4] + T(5) * t10 * delta_tau * M_panels[1] + t11 * M_panels[5] + t12 * M_panels[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = t16 * delta_tau;
    const T t20 = t13 * tau_lo;
    F = T(5) * t14 * delta_tau * M_panels[1] + t15 * M_panels[0] + t18 * M_panels[5] + T(10) * t13 * t19 * M_panels[3] + T(5) * M_panels[4] * tau_lo * t17 + T(10) * t20 * t16 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(cross_cross);
    const T t22 = T(1) / t21;
    const T J2 = atan2(t21, ap_bp) * t22;
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = T(1) / bp_bp;
    const T t27 = ab_ab * J2 + a_minus_b * t26 + ab_ap * t1;
    const T t28 = T(1) / cross_cross;
    const T t29 = t1 * t1;
    const T t30 = t26 * t26;
    const T t31 = T(3) * t27 * ab_ab * t28 + T(2) * ab_ap * t29 + T(2) * a_minus_b * t30;
    const T t32 = T(1) / ab_ab;
    const T t33 = t31 * ab_ap * t28 + T(2) * t29 - T(2) * t30;
    const T t34 = delta_tau * delta_tau;
    const T t35 = t34 * delta_tau;
    const T t36 = T(4) * t27 * t28 + T(2) * t32 * ab_ap * t33 - t31 * t28 * ap_ap;
    const T t37 = t1 + t27 * ab_ap * t28 - t26;
    const T t38 = T(2) * t32 * ab_ap * t36 + T(4) * t37 * t32 - t32 * t33 * ap_ap;
    const T t39 = t23 * tau_lo;
    const T t40 = t34 * t34;
    const T t41 = t27 * t28 * ap_ap - T(2) * t37 * t32 * ab_ap - T(2) * J2;
    const T t42 = t32 * ap_ap * t36 + T(4) * t32 * t41 - T(2) * t32 * ab_ap * t38;
    const T t43 = t40 * delta_tau;
    F = (T(1) / T(8)) * t25 * t31 * t28 + (T(5) / T(8)) * t24 * delta_tau * t32 * t33 + (T(5) / T(4)) * t23 * t35 * t32 * t38 + (T(5) / T(4)) * t39 * t34 * t32 * t36 - (T(5) / T(8)) * tau_lo * t40 * t32 * t42 - (T(1) / T(8)) * t43 * t32 * (T(2) * t32 * t42 * ab_ap + t32 * t38 * ap_ap + T(4) * (T(2) * t32 * ab_ap * t41 + t37 * t32 * ap_ap - t32 * (T(2) * J2 * ab_ap + log_ratio)) * t32);
  }
  const T t44 = in.sigma * in.sigma;
  const T t45 = t44 * in.sigma;
  const T t46 = t45 * t45;
  f = length * t46 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 80 +, 204 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 20012 +, 26261 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * tau_lo;
    const T t11 = t9 * t9;
    const T t12 = t11 * tau_lo;
    const T t13 = t6 * delta_tau;
    const T t14 = T(5) * t7 * tau_lo * M_panels[11] + M_panels[12] * t8 + T(10) * M_panels[9] * t6 * t10 + t12 * M_panels[7] + T(10) * t13 * t9 * M_panels[10] + T(5) * delta_tau * t11 * M_panels[8];
    G_ap = t14;
    const T t15 = T(1) / ab_ab;
    G_E = T(10) * t6 * t10 * M_panels[10] + t12 * M_panels[8] + T(10) * t13 * t9 * M_panels[11] + T(5) * M_panels[9] * delta_tau * t11 + t8 * M_panels[13] + T(5) * M_panels[12] * t7 * tau_lo - t14 * t15 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * delta_tau;
    const T t18 = tau_lo * tau_lo;
    const T t19 = t16 * t16;
    const T t20 = t19 * delta_tau;
    const T t21 = t18 * tau_lo;
    const T t22 = t18 * t18;
    const T t23 = t22 * tau_lo;
    const T t24 = T(10) * t17 * t18 * M_panels[10] + t20 * M_panels[12] + T(10) * t16 * t21 * M_panels[9] + M_panels[7] * t23 + T(5) * M_panels[8] * delta_tau * t22 + T(5) * M_panels[11] * t19 * tau_lo;
    G_ap = t24;
    const T t25 = T(1) / ab_ab;
    G_E = M_panels[8] * t23 + T(10) * M_panels[11] * t17 * t18 + T(5) * delta_tau * t22 * M_panels[9] + T(5) * t19 * tau_lo * M_panels[12] + T(10) * t16 * t21 * M_panels[10] + t20 * M_panels[13] - t24 * t25 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = sqrt(cross_cross);
    const T t27 = T(1) / t26;
    const T J2 = atan2(t26, ap_bp) * t27;
    const T t28 = T(1) / cross_cross;
    const T t29 = T(1) / ap_ap;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(1) / bp_bp;
    const T t33 = a_minus_b * t32 + ab_ab * J2 + t29 * ab_ap;
    const T t34 = t32 * t32;
    const T t35 = T(2) * t30 * ab_ap + T(3) * t33 * ab_ab * t28 + T(2) * a_minus_b * t34;
    const T t36 = t34 * t32;
    const T t37 = T(8) * t31 * ab_ap + T(5) * t35 * ab_ab * t28 + T(8) * a_minus_b * t36;
    const T t38 = t28 * t37 * ab_ap + T(8) * t31 - T(8) * t36;
    const T t39 = tau_lo * tau_lo;
    const T t40 = t39 * t39;
    const T t41 = T(1) / ab_ab;
    const T t42 = ap_ap * t28 * t37 - T(6) * t35 * t28 - T(2) * t38 * t41 * ab_ap;
    const T t43 = T(2) * t30 + t35 * t28 * ab_ap - T(2) * t34;
    const T t44 = T(2) * t41 * t43 * ab_ap + T(4) * t33 * t28 - ap_ap * t35 * t28;
    const T t45 = T(2) * t41 * t42 * ab_ap + ap_ap * t38 * t41 - T(6) * t41 * t43;
    const T t46 = ap_ap * t41 * t42 + T(6) * t44 * t41 - T(2) * t45 * t41 * ab_ap;
    const T t47 = t32 - t33 * t28 * ab_ap - t29;
    const T t48 = ap_ap * t41 * t43 + T(4) * t47 * t41 - T(2) * t44 * t41 * ab_ap;
    const T t49 = delta_tau * delta_tau;
    const T t50 = t49 * t49;
    const T t51 = t50 * delta_tau;
    const T t52 = t40 * tau_lo;
    const T t53 = t49 * delta_tau;
    const T t54 = t39 * tau_lo;
    G_ap = (T(5) / T(48)) * t38 * delta_tau * t40 * t41 + (T(1) / T(48)) * (T(2) * t41 * t46 * ab_ap + t45 * ap_ap * t41 - T(6) * t41 * t48) * t51 * t41 + (T(5) / T(48)) * t50 * tau_lo * t41 * t46 + (T(1) / T(48)) * t52 * t28 * t37 - (T(5) / T(24)) * t45 * t53 * t39 * t41 - (T(5) / T(24)) * t49 * t54 * t41 * t42;
    G_E = (T(1) / T(48)) * t41 * (T(30) * t44 * t53 * t39 * t41 + T(5) * t35 * delta_tau * t40 * t28 + T(8) * t31 * t52 + T(20) * t49 * t54 * t41 * t43 - T(8) * (T(5) * delta_tau * t40 + T(10) * t49 * t54 + t52 + T(10) * t53 * t39 + t51 + T(5) * t50 * tau_lo) * t36 - T(20) * t50 * tau_lo * t41 * t48 - T(5) * t51 * (T(4) * (T(2) * t47 * t41 * ab_ap + t33 * ap_ap * t28 - T(2) * J2) * t41 + T(2) * t41 * ab_ap * t48 + t44 * ap_ap * t41) * t41);
  }
  const T t55 = in.sigma * in.sigma;
  const T t56 = t55 * in.sigma;
  const T t57 = t56 * t56;
  const T g_factor = -T(6) * t57 * length;
  grad[0] = g_factor * (G_ap * foot0 - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 90 +, 244 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 20017 +, 26278 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * t2;
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = t2 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t3 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t7 = delta_tau * delta_tau;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = t8 * t8;
    const T t11 = t10 * tau_lo;
    const T t12 = t7 * t7;
    const T t13 = t12 * delta_tau;
    const T t14 = t7 * delta_tau;
    F = T(10) * t7 * M_panels[2] * t9 + T(5) * delta_tau * t10 * M_panels[1] + t11 * M_panels[0] + M_panels[5] * t13 + T(5) * t12 * tau_lo * M_panels[4] + T(10) * t14 * t8 * M_panels[3];
    const T t15 = T(5) * delta_tau * t10 * M_panels[8] + T(10) * t14 * t8 * M_panels[10] + T(10) * t7 * t9 * M_panels[9] + t13 * M_panels[12] + T(5) * t12 * tau_lo * M_panels[11] + t11 * M_panels[7];
    G_ap = t15;
    const T t16 = T(1) / ab_ab;
    G_E = T(5) * delta_tau * t10 * M_panels[9] + t11 * M_panels[8] + t13 * M_panels[13] + T(5) * t12 * tau_lo * M_panels[12] + T(10) * t14 * t8 * M_panels[11] + T(10) * t7 * t9 * M_panels[10] - t15 * t16 * ab_ap;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t18 * tau_lo;
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t17 * tau_lo;
    const T t23 = t20 * delta_tau;
    const T t24 = t21 * delta_tau;
    F = T(5) * delta_tau * t18 * M_panels[1] + t19 * M_panels[0] + T(5) * t21 * M_panels[4] * tau_lo + T(10) * t20 * t22 * M_panels[2] + T(10) * t23 * t17 * M_panels[3] + t24 * M_panels[5];
    const T t25 = T(5) * delta_tau * t18 * M_panels[8] + T(10) * M_panels[10] * t23 * t17 + t24 * M_panels[12] + T(10) * t20 * t22 * M_panels[9] + M_panels[7] * t19 + T(5) * t21 * tau_lo * M_panels[11];
    G_ap = t25;
    const T t26 = T(1) / ab_ab;
    G_E = t24 * M_panels[13] + T(5) * t21 * tau_lo * M_panels[12] + t19 * M_panels[8] + T(10) * M_panels[10] * t20 * t22 + T(5) * delta_tau * t18 * M_panels[9] + T(10) * t23 * t17 * M_panels[11] - t25 * t26 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(cross_cross);
    const T t28 = T(1) / t27;
    const T J2 = t28 * atan2(t27, ap_bp);
    const T t29 = delta_tau * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = T(1) / ab_ab;
    const T t32 = T(1) / cross_cross;
    const T t33 = T(1) / bp_bp;
    const T t34 = ab_ap * t3 + ab_ab * J2 + t33 * a_minus_b;
    const T t35 = t3 + t32 * t34 * ab_ap - t33;
    const T t36 = T(2) * t31 * t35 * ab_ap + T(2) * J2 - t32 * t34 * ap_ap;
    const T t37 = t33 * t33;
    const T t38 = t3 * t3;
    const T t39 = T(2) * t37 * a_minus_b + T(2) * ab_ap * t38 + T(3) * ab_ab * t32 * t34;
    const T t40 = T(2) * t37 - T(2) * t38 - t32 * ab_ap * t39;
    const T t41 = T(4) * t32 * t34 - T(2) * t40 * t31 * ab_ap - t32 * t39 * ap_ap;
    const T t42 = T(2) * t31 * t41 * ab_ap + t40 * t31 * ap_ap + T(4) * t31 * t35;
    const T t43 = T(4) * t31 * t36 + T(2) * t31 * t42 * ab_ap - t31 * t41 * ap_ap;
    const T t44 = tau_lo * tau_lo;
    const T t45 = t44 * t44;
    const T t46 = t45 * tau_lo;
    const T t47 = t29 * delta_tau;
    const T t48 = t44 * tau_lo;
    const T t49 = t30 * delta_tau;
    F = (T(5) / T(8)) * t30 * tau_lo * t31 * t43 + (T(1) / T(8)) * t46 * t32 * t39 + (T(5) / T(4)) * t47 * t44 * t31 * t42 + (T(5) / T(4)) * t29 * t48 * t31 * t41 - (T(1) / T(8)) * t49 * t31 * (t31 * t42 * ap_ap + T(4) * t31 * (t31 * t35 * ap_ap - t31 * (log_ratio + T(2) * ab_ap * J2) - T(2) * t31 * ab_ap * t36) - T(2) * t31 * ab_ap * t43) - (T(5) / T(8)) * t40 * delta_tau * t45 * t31;
    const T t50 = t37 * t33;
    const T t51 = t38 * t3;
    const T t52 = T(5) * ab_ab * t32 * t39 + T(8) * ab_ap * t51 + T(8) * t50 * a_minus_b;
    const T t53 = T(8) * t50 - T(8) * t51 - t32 * t52 * ab_ap;
    const T t54 = t32 * t52 * ap_ap + T(2) * t31 * t53 * ab_ap - T(6) * t32 * t39;
    const T t55 = t31 * t53 * ap_ap - T(6) * t40 * t31 - T(2) * t31 * ab_ap * t54;
    const T t56 = T(2) * t55 * t31 * ab_ap + T(6) * t31 * t41 + t31 * t54 * ap_ap;
    G_ap = (T(5) / T(48)) * t30 * tau_lo * t31 * t56 + (T(1) / T(48)) * t46 * t32 * t52 + (T(5) / T(24)) * t47 * t44 * t55 * t31 + (T(1) / T(48)) * t49 * (T(2) * t31 * t56 * ab_ap + T(6) * t31 * t42 - t55 * t31 * ap_ap) * t31 - (T(5) / T(48)) * delta_tau * t45 * t31 * t53 - (T(5) / T(24)) * t29 * t48 * t31 * t54;
    G_E = -(T(1) / T(48)) * t31 * (T(8) * t50 * (T(10) * t47 * t44 + T(10) * t29 * t48 + T(5) * delta_tau * t45 + t49 + T(5) * t30 * tau_lo + t46) + T(20) * t40 * t29 * t48 * t31 - T(30) * t47 * t44 * t31 * t41 - T(5) * delta_tau * t45 * t32 * t39 - T(8) * t46 * t51 - T(5) * t49 * t31 * t43 - T(20) * t30 * tau_lo * t31 * t42);
  }
  const T t57 = in.sigma * in.sigma;
  const T t58 = t57 * in.sigma;
  const T t59 = t58 * t58;
  const T g_factor = -T(6) * length * t59;
  f = length * t59 * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 64 +, 172 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 12440 +, 20836 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = r1 * ab_ap;
    X = length * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t4 - a_minus_b * r0);
  }
  const T t5 = T(1) / length;
  const T J1 = asinh(X) * t5;
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = tau_lo * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t13 * tau_lo;
    const T t15 = t9 * delta_tau;
    const T t16 = t12 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t15 * t15;
    F = T(6) * t11 * tau_lo * M_panels[5] + T(15) * t10 * t12 * M_panels[4] + T(6) * delta_tau * t14 * M_panels[1] + T(15) * t9 * t13 * M_panels[2] + T(20) * M_panels[3] * t15 * t16 + M_panels[0] * t17 + t18 * M_panels[6];
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t19 = delta_tau * delta_tau;
    const T t20 = t19 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t19 * t19;
    const T t26 = t25 * delta_tau;
    const T t27 = t22 * t22;
    const T t28 = t27 * tau_lo;
    F = M_panels[6] * t21 + M_panels[0] * t24 + T(6) * t26 * tau_lo * M_panels[5] + T(15) * t25 * t22 * M_panels[4] + T(20) * t20 * M_panels[3] * t23 + T(15) * M_panels[2] * t19 * t27 + T(6) * delta_tau * t28 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = delta_tau * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = tau_lo * tau_lo;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(1) / cross_cross;
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t35;
    const T t37 = T(1) / r0;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = t34 * a_minus_b + ab_ap * t37;
    const T t41 = T(2) * t40 * ab_ab * t33 + t34 * a_minus_b * t35 + t38 * ab_ap * t37;
    const T t42 = T(3) * t34 * a_minus_b * t36 + T(3) * t39 * ab_ap * t37 + T(4) * ab_ab * t41 * t33;
    const T t43 = T(3) * t39 * t37 + t33 * ab_ap * t42 - T(3) * t34 * t36;
    const T t44 = ap_ap * t33 * t42 - T(2) * t32 * ab_ap * t43 - T(5) * t41 * t33;
    const T t45 = t34 * t35 - t41 * t33 * ab_ap - t38 * t37;
    const T t46 = T(2) * t32 * t45 * ab_ap + ap_ap * t41 * t33 - T(3) * t40 * t33;
    const T t47 = ap_ap * t32 * t43 + T(2) * t44 * t32 * ab_ap + T(5) * t32 * t45;
    const T t48 = ap_ap * t44 * t32 - T(5) * t32 * t46 - T(2) * t47 * t32 * ab_ap;
    const T t49 = t31 * t31;
    const T t50 = t49 * tau_lo;
    const T t51 = t31 * tau_lo;
    const T t52 = t51 * t51;
    const T t53 = t30 * delta_tau;
    const T t54 = t37 + t40 * t33 * ab_ap - t34;
    const T t55 = ap_ap * t32 * t45 + T(3) * t54 * t32 - T(2) * t32 * t46 * ab_ap;
    const T t56 = T(5) * t32 * t55 + ap_ap * t47 * t32 + T(2) * t32 * t48 * ab_ap;
    const T t57 = t29 * delta_tau;
    const T t58 = t57 * t57;
    F = t30 * t31 * t32 * t48 + (T(2) / T(5)) * delta_tau * t50 * t32 * t43 + (T(1) / T(15)) * t52 * t33 * t42 + (T(2) / T(5)) * t53 * tau_lo * t32 * t56 - (T(1) / T(15)) * t58 * t32 * (ap_ap * t32 * t48 - T(5) * (ap_ap * t32 * t46 + T(3) * t32 * (T(2) * t54 * t32 * ab_ap + J1 - ap_ap * t40 * t33) + T(2) * t32 * ab_ap * t55) * t32 - T(2) * t32 * t56 * ab_ap) - t44 * t29 * t49 * t32 - (T(4) / T(3)) * t57 * t51 * t47 * t32;
  }
  const T t59 = in.sigma * in.sigma;
  const T t60 = t59 * in.sigma;
  const T t61 = t60 * t60;
  const T t62 = t61 * in.sigma;
  f = F * length * t62;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 90 +, 265 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 22172 +, 33827 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t7 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t6 * t6;
    const T t12 = t11 * delta_tau;
    const T t13 = t8 * tau_lo;
    const T t14 = t6 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = T(15) * t6 * t8 * M_panels[10] + t10 * M_panels[8] + T(6) * t12 * tau_lo * M_panels[13] + T(6) * M_panels[9] * delta_tau * t13 + T(15) * t11 * t7 * M_panels[12] + t15 * M_panels[14] + T(20) * t14 * t9 * M_panels[11];
    G_ap = t16;
    const T t17 = T(1) / ab_ab;
    G_E = T(20) * t14 * t9 * M_panels[12] + M_panels[9] * t10 + T(6) * t12 * tau_lo * M_panels[14] + T(15) * t11 * t7 * M_panels[13] + M_panels[15] * t15 + T(6) * delta_tau * t13 * M_panels[10] + T(15) * t6 * t8 * M_panels[11] - t16 * t17 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
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
    const T t25 = t18 * tau_lo;
    const T t26 = t25 * t25;
    const T t27 = t24 * t24;
    const T t28 = T(6) * M_panels[9] * delta_tau * t20 + T(6) * t23 * tau_lo * M_panels[13] + T(15) * t21 * t19 * M_panels[10] + T(15) * M_panels[12] * t22 * t18 + T(20) * t24 * t25 * M_panels[11] + t26 * M_panels[8] + t27 * M_panels[14];
    G_ap = t28;
    const T t29 = T(1) / ab_ab;
    G_E = M_panels[9] * t26 + T(6) * delta_tau * t20 * M_panels[10] + T(20) * M_panels[12] * t24 * t25 + T(6) * t23 * tau_lo * M_panels[14] + T(15) * t21 * t19 * M_panels[11] + M_panels[15] * t27 + T(15) * t22 * t18 * M_panels[13] - t29 * t28 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = T(1) / r0;
    const T t31 = t30 * t30;
    const T t32 = t31 * t31;
    const T t33 = t32 * t31;
    const T t34 = T(1) / cross_cross;
    const T t35 = T(1) / r1;
    const T t36 = t35 * t35;
    const T t37 = t35 * a_minus_b + ab_ap * t30;
    const T t38 = t35 * a_minus_b * t36 + t31 * ab_ap * t30 + T(2) * ab_ab * t34 * t37;
    const T t39 = t36 * t36;
    const T t40 = T(3) * t32 * ab_ap * t30 + T(4) * ab_ab * t34 * t38 + T(3) * t35 * a_minus_b * t39;
    const T t41 = t39 * t36;
    const T t42 = T(2) * ab_ab * t34 * t40 + T(5) * t35 * a_minus_b * t41 + T(5) * t33 * ab_ap * t30;
    const T t43 = T(5) * t33 * t30 + t34 * t42 * ab_ap - T(5) * t35 * t41;
    const T t44 = tau_lo * tau_lo;
    const T t45 = t44 * t44;
    const T t46 = t45 * tau_lo;
    const T t47 = T(1) / ab_ab;
    const T t48 = delta_tau * delta_tau;
    const T t49 = t48 * t48;
    const T t50 = t49 * delta_tau;
    const T t51 = T(3) * ap_ap * t34 * t42 - T(6) * t43 * t47 * ab_ap - T(7) * t34 * t40;
    const T t52 = T(3) * t35 * t39 - T(3) * t32 * t30 - t34 * ab_ap * t40;
    const T t53 = T(5) * t34 * t38 - T(2) * t47 * ab_ap * t52 - ap_ap * t34 * t40;
    const T t54 = T(2) * t47 * t51 * ab_ap + T(3) * ap_ap * t43 * t47 + T(7) * t47 * t52;
    const T t55 = ap_ap * t47 * t51 + T(7) * t53 * t47 - T(2) * t47 * t54 * ab_ap;
    const T t56 = t34 * ab_ap * t38 + t31 * t30 - t35 * t36;
    const T t57 = T(5) * t47 * t56 + T(2) * t53 * t47 * ab_ap + ap_ap * t47 * t52;
    const T t58 = T(2) * t55 * t47 * ab_ap + ap_ap * t47 * t54 + T(7) * t47 * t57;
    const T t59 = t44 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = t48 * delta_tau;
    const T t62 = t61 * t61;
    const T t63 = T(2) * t47 * ab_ap * t56 + T(3) * t34 * t37 - ap_ap * t34 * t38;
    const T t64 = ap_ap * t53 * t47 - T(5) * t47 * t63 - T(2) * t47 * ab_ap * t57;
    G_ap = (T(6) / T(35)) * delta_tau * t43 * t46 * t47 + (T(2) / T(35)) * t50 * tau_lo * t58 * t47 + (T(1) / T(35)) * t60 * t34 * t42 + (T(1) / T(7)) * t55 * t49 * t44 * t47 - (T(1) / T(105)) * t62 * t47 * (ap_ap * t55 * t47 + T(7) * t64 * t47 - T(2) * t58 * t47 * ab_ap) - (T(4) / T(21)) * t61 * t59 * t47 * t54 - (T(1) / T(7)) * t48 * t45 * t47 * t51;
    const T t65 = t30 * t30;
    const T t66 = t65 * t30;
    const T t67 = t66 * t66;
    const T t68 = t67 * t30;
    const T t69 = t35 * t35;
    const T t70 = t69 * t35;
    const T t71 = t70 * t70;
    const T t72 = t71 * t35;
    G_E = (T(1) / T(35)) * t47 * (T(20) * t49 * t44 * t47 * t57 + T(2) * delta_tau * t46 * t34 * t40 + T(20) * t61 * t59 * t53 * t47 + T(5) * t60 * t68 - T(5) * t72 * (T(15) * t49 * t44 + T(15) * t48 * t45 + T(6) * t50 * tau_lo + t60 + t62 + T(6) * delta_tau * t46 + T(20) * t61 * t59) - T(2) * (T(2) * t64 * t47 * ab_ap + ap_ap * t47 * t57 - T(5) * t47 * (T(2) * t47 * t63 * ab_ap + T(3) * t47 * (t30 + t34 * ab_ap * t37 - t35) - ap_ap * t47 * t56)) * t62 * t47 - T(10) * t50 * tau_lo * t64 * t47 - T(10) * t48 * t45 * t47 * t52);
  }
  const T t73 = in.sigma * in.sigma;
  const T t74 = t73 * in.sigma;
  const T t75 = t74 * t74;
  const T t76 = t75 * in.sigma;
  const T g_factor = -T(7) * length * t76;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 103 +, 316 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 22179 +, 33852 ×, 2439 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t1 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (ab1 * exact_cross[2] - exact_cross[1] * ab2);
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * t2;
    foot2 = -(exact_cross[1] * ab0 - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = a_minus_b * ab_ap;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / cross_cross;
    const T t5 = r1 * ab_ap;
    X = length * t4 * (t5 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t6 - a_minus_b * r0);
  }
  const T t7 = T(1) / length;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -a_minus_b * ab_ap;
  const T t10 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t14 * delta_tau;
    const T t17 = t11 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t15 * delta_tau;
    const T t20 = t16 * t16;
    F = T(6) * delta_tau * t13 * M_panels[1] + T(15) * M_panels[4] * t15 * t11 + T(20) * t16 * t17 * M_panels[3] + T(15) * t14 * M_panels[2] * t12 + t18 * M_panels[0] + T(6) * M_panels[5] * t19 * tau_lo + t20 * M_panels[6];
    const T t21 = T(15) * t15 * t11 * M_panels[12] + M_panels[14] * t20 + M_panels[8] * t18 + T(15) * t14 * t12 * M_panels[10] + T(20) * M_panels[11] * t16 * t17 + T(6) * t19 * tau_lo * M_panels[13] + T(6) * delta_tau * t13 * M_panels[9];
    G_ap = t21;
    const T t22 = T(1) / ab_ab;
    G_E = T(15) * M_panels[11] * t14 * t12 + T(6) * delta_tau * t13 * M_panels[10] + t20 * M_panels[15] + T(15) * t15 * t11 * M_panels[13] + T(6) * M_panels[14] * t19 * tau_lo + T(20) * t16 * t17 * M_panels[12] + t18 * M_panels[9] - t21 * t22 * ab_ap;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t23 = delta_tau * delta_tau;
    const T t24 = tau_lo * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t24 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t23 * t23;
    const T t29 = t28 * delta_tau;
    const T t30 = t25 * tau_lo;
    const T t31 = t23 * delta_tau;
    const T t32 = t31 * t31;
    F = T(15) * t23 * M_panels[2] * t25 + t27 * M_panels[0] + T(15) * M_panels[4] * t28 * t24 + T(6) * M_panels[5] * t29 * tau_lo + T(6) * M_panels[1] * delta_tau * t30 + T(20) * t31 * t26 * M_panels[3] + t32 * M_panels[6];
    const T t33 = T(20) * M_panels[11] * t31 * t26 + M_panels[8] * t27 + T(15) * t23 * t25 * M_panels[10] + T(6) * delta_tau * t30 * M_panels[9] + T(15) * t28 * t24 * M_panels[12] + T(6) * t29 * tau_lo * M_panels[13] + M_panels[14] * t32;
    G_ap = t33;
    const T t34 = T(1) / ab_ab;
    G_E = T(6) * delta_tau * t30 * M_panels[10] + T(15) * t28 * t24 * M_panels[13] + T(20) * t31 * t26 * M_panels[12] + t32 * M_panels[15] + T(6) * M_panels[14] * t29 * tau_lo + T(15) * M_panels[11] * t23 * t25 + t27 * M_panels[9] - t34 * t33 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = delta_tau * delta_tau;
    const T t36 = t35 * delta_tau;
    const T t37 = t36 * t36;
    const T t38 = T(1) / ab_ab;
    const T t39 = T(1) / r0;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r1;
    const T t42 = t39 * ab_ap + a_minus_b * t41;
    const T t43 = T(1) / cross_cross;
    const T t44 = t41 * t41;
    const T t45 = t40 * t39 * ab_ap + T(2) * t42 * ab_ab * t43 + a_minus_b * t41 * t44;
    const T t46 = t45 * t43 * ab_ap + t40 * t39 - t41 * t44;
    const T t47 = T(2) * t38 * t46 * ab_ap + T(3) * t42 * t43 - ap_ap * t45 * t43;
    const T t48 = t42 * t43 * ab_ap + t39 - t41;
    const T t49 = T(2) * t47 * t38 * ab_ap + T(3) * t38 * t48 - ap_ap * t38 * t46;
    const T t50 = t44 * t44;
    const T t51 = t40 * t40;
    const T t52 = T(4) * ab_ab * t45 * t43 + T(3) * a_minus_b * t41 * t50 + T(3) * t51 * t39 * ab_ap;
    const T t53 = t52 * t43 * ab_ap + T(3) * t51 * t39 - T(3) * t41 * t50;
    const T t54 = ap_ap * t52 * t43 - T(2) * t38 * t53 * ab_ap - T(5) * t45 * t43;
    const T t55 = T(2) * t38 * t54 * ab_ap + ap_ap * t38 * t53 - T(5) * t38 * t46;
    const T t56 = T(2) * t55 * t38 * ab_ap - ap_ap * t38 * t54 - T(5) * t47 * t38;
    const T t57 = T(5) * t49 * t38 + ap_ap * t55 * t38 - T(2) * t56 * t38 * ab_ap;
    const T t58 = tau_lo * tau_lo;
    const T t59 = t58 * t58;
    const T t60 = t59 * tau_lo;
    const T t61 = t35 * t35;
    const T t62 = t61 * delta_tau;
    const T t63 = t58 * tau_lo;
    const T t64 = t63 * t63;
    F = (T(1) / T(15)) * t37 * t38 * (T(2) * t57 * t38 * ab_ap + ap_ap * t56 * t38 - T(5) * (ap_ap * t47 * t38 - T(3) * (J1 + T(2) * t38 * t48 * ab_ap - t42 * ap_ap * t43) * t38 - T(2) * t49 * t38 * ab_ap) * t38) + (T(2) / T(5)) * delta_tau * t60 * t38 * t53 + (T(2) / T(5)) * t62 * tau_lo * t57 * t38 + (T(1) / T(15)) * t52 * t64 * t43 - t56 * t61 * t58 * t38 - t35 * t59 * t38 * t54 - (T(4) / T(3)) * t36 * t63 * t55 * t38;
    const T t65 = t50 * t44;
    const T t66 = t51 * t40;
    const T t67 = T(5) * a_minus_b * t41 * t65 + T(2) * t52 * ab_ab * t43 + T(5) * t66 * t39 * ab_ap;
    const T t68 = T(5) * t41 * t65 - T(5) * t66 * t39 - t67 * t43 * ab_ap;
    const T t69 = T(3) * t67 * ap_ap * t43 + T(6) * t68 * t38 * ab_ap - T(7) * t52 * t43;
    const T t70 = T(2) * t69 * t38 * ab_ap - T(3) * ap_ap * t68 * t38 - T(7) * t38 * t53;
    const T t71 = T(2) * t70 * t38 * ab_ap + T(7) * t38 * t54 - t69 * ap_ap * t38;
    const T t72 = ap_ap * t70 * t38 - T(7) * t55 * t38 - T(2) * t38 * t71 * ab_ap;
    G_ap = (T(1) / T(35)) * t67 * t64 * t43 + (T(2) / T(35)) * t62 * t72 * tau_lo * t38 - (T(1) / T(105)) * t37 * t38 * (T(7) * t56 * t38 - ap_ap * t38 * t71 - T(2) * t72 * t38 * ab_ap) - (T(1) / T(7)) * t61 * t58 * t38 * t71 - (T(1) / T(7)) * t69 * t35 * t59 * t38 - (T(4) / T(21)) * t70 * t36 * t63 * t38 - (T(6) / T(35)) * delta_tau * t68 * t60 * t38;
    const T t73 = t39 * t39;
    const T t74 = t73 * t39;
    const T t75 = t74 * t74;
    const T t76 = t75 * t39;
    const T t77 = t41 * t41;
    const T t78 = t77 * t41;
    const T t79 = t78 * t78;
    const T t80 = t79 * t41;
    G_E = (T(1) / T(35)) * (T(5) * t76 * t64 + T(10) * t35 * t59 * t38 * t53 + T(2) * t52 * delta_tau * t60 * t43 + T(2) * t37 * t57 * t38 - T(5) * (t64 + T(15) * t35 * t59 + t37 + T(6) * t62 * tau_lo + T(15) * t61 * t58 + T(20) * t36 * t63 + T(6) * delta_tau * t60) * t80 - T(10) * t56 * t62 * tau_lo * t38 - T(20) * t61 * t58 * t55 * t38 - T(20) * t36 * t63 * t38 * t54) * t38;
  }
  const T t81 = in.sigma * in.sigma;
  const T t82 = t81 * in.sigma;
  const T t83 = t82 * t82;
  const T t84 = t83 * in.sigma;
  const T g_factor = -T(7) * t84 * length;
  f = t84 * F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 74 +, 198 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 13522 +, 18678 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t1 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t1);
  T F;
  const T t2 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t3 = -a_minus_b * ab_ap;
  const T t4 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t5 = delta_tau * delta_tau;
    const T t6 = t5 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t9 * tau_lo;
    const T t11 = t8 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t7 * delta_tau;
    const T t15 = t5 * t5;
    const T t16 = t15 * delta_tau;
    F = T(7) * M_panels[6] * t7 * tau_lo + T(21) * M_panels[2] * t5 * t10 + T(7) * delta_tau * t12 * M_panels[1] + M_panels[0] * t13 + T(35) * M_panels[3] * t6 * t9 + t14 * M_panels[7] + T(21) * M_panels[5] * t16 * t8 + T(35) * t15 * t11 * M_panels[4];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t20 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t19 * tau_lo;
    const T t25 = t17 * t17;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * delta_tau;
    const T t28 = t21 * delta_tau;
    F = T(7) * M_panels[1] * delta_tau * t19 + T(35) * M_panels[4] * t21 * t18 + T(7) * M_panels[6] * t23 * tau_lo + M_panels[0] * t24 + T(21) * t20 * M_panels[2] * t26 + M_panels[7] * t27 + T(21) * M_panels[5] * t28 * t17 + T(35) * M_panels[3] * t22 * t25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = sqrt(cross_cross);
    const T t30 = T(1) / t29;
    const T J2 = t30 * atan2(t29, ap_bp);
    const T t31 = T(1) / cross_cross;
    const T t32 = T(1) / bp_bp;
    const T t33 = a_minus_b * t32 + ab_ap * t1 + J2 * ab_ab;
    const T t34 = t1 * t1;
    const T t35 = t32 * t32;
    const T t36 = T(3) * t31 * t33 * ab_ab + T(2) * ab_ap * t34 + T(2) * a_minus_b * t35;
    const T t37 = t34 * t1;
    const T t38 = t35 * t32;
    const T t39 = T(5) * t31 * t36 * ab_ab + T(8) * ab_ap * t37 + T(8) * a_minus_b * t38;
    const T t40 = tau_lo * tau_lo;
    const T t41 = t40 * tau_lo;
    const T t42 = t41 * t41;
    const T t43 = t42 * tau_lo;
    const T t44 = delta_tau * delta_tau;
    const T t45 = t44 * t44;
    const T t46 = t45 * delta_tau;
    const T t47 = T(1) / ab_ab;
    const T t48 = t31 * ab_ap * t36 + T(2) * t34 - T(2) * t35;
    const T t49 = T(2) * ab_ap * t48 * t47 + T(4) * t31 * t33 - t31 * t36 * ap_ap;
    const T t50 = T(8) * t37 + t31 * ab_ap * t39 - T(8) * t38;
    const T t51 = t31 * t39 * ap_ap - T(2) * ab_ap * t50 * t47 - T(6) * t31 * t36;
    const T t52 = T(2) * ab_ap * t51 * t47 + t50 * ap_ap * t47 - T(6) * t48 * t47;
    const T t53 = T(6) * t49 * t47 + ap_ap * t51 * t47 - T(2) * ab_ap * t52 * t47;
    const T t54 = t32 - t31 * ab_ap * t33 - t1;
    const T t55 = T(4) * t54 * t47 + ap_ap * t48 * t47 - T(2) * ab_ap * t49 * t47;
    const T t56 = T(2) * ab_ap * t53 * t47 + ap_ap * t52 * t47 - T(6) * t47 * t55;
    const T t57 = T(2) * J2 - t31 * t33 * ap_ap - T(2) * t54 * ab_ap * t47;
    const T t58 = t49 * ap_ap * t47 + T(2) * ab_ap * t47 * t55 - T(4) * t57 * t47;
    const T t59 = T(2) * ab_ap * t47 * t56 - ap_ap * t53 * t47 - T(6) * t58 * t47;
    const T t60 = t44 * delta_tau;
    const T t61 = t60 * t60;
    const T t62 = t40 * t40;
    const T t63 = t61 * delta_tau;
    const T t64 = t62 * tau_lo;
    F = (T(1) / T(48)) * t31 * t39 * t43 + (T(7) / T(16)) * t46 * t40 * t47 * t56 + (T(7) / T(48)) * t50 * delta_tau * t42 * t47 + (T(7) / T(48)) * t59 * t61 * tau_lo * t47 + (T(35) / T(48)) * t53 * t45 * t41 * t47 - (T(35) / T(48)) * t60 * t52 * t62 * t47 - (T(1) / T(48)) * (ap_ap * t47 * t56 - T(2) * ab_ap * t59 * t47 - T(6) * (T(4) * ((T(2) * J2 * ab_ap + log_ratio) * t47 + T(2) * ab_ap * t57 * t47 + t54 * ap_ap * t47) * t47 + ap_ap * t47 * t55 - T(2) * ab_ap * t58 * t47) * t47) * t63 * t47 - (T(7) / T(16)) * t51 * t44 * t64 * t47;
  }
  const T t65 = in.sigma * in.sigma;
  const T t66 = t65 * t65;
  const T t67 = t66 * t66;
  f = length * t67 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 104 +, 290 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 24336 +, 31677 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * t2;
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * delta_tau;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t11 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    const T t17 = t8 * delta_tau;
    const T t18 = T(7) * M_panels[15] * t8 * tau_lo + T(21) * t10 * t11 * M_panels[14] + T(35) * M_panels[12] * t7 * t12 + T(21) * t6 * t13 * M_panels[11] + T(35) * t9 * t14 * M_panels[13] + M_panels[9] * t16 + T(7) * delta_tau * t15 * M_panels[10] + t17 * M_panels[16];
    G_ap = t18;
    const T t19 = T(1) / ab_ab;
    G_E = T(21) * M_panels[12] * t6 * t13 + T(35) * t9 * t14 * M_panels[14] + T(21) * M_panels[15] * t10 * t11 + t17 * M_panels[17] + T(35) * t7 * t12 * M_panels[13] + t16 * M_panels[10] + T(7) * t8 * tau_lo * M_panels[16] + T(7) * delta_tau * t15 * M_panels[11] - t19 * ab_ap * t18;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * delta_tau;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t22 * tau_lo;
    const T t26 = t25 * t25;
    const T t27 = t21 * t21;
    const T t28 = t27 * delta_tau;
    const T t29 = t20 * t20;
    const T t30 = t29 * delta_tau;
    const T t31 = t26 * tau_lo;
    const T t32 = T(35) * t21 * t23 * M_panels[12] + T(21) * t20 * t24 * M_panels[11] + T(7) * M_panels[10] * delta_tau * t26 + M_panels[16] * t28 + T(35) * M_panels[13] * t29 * t25 + T(21) * t30 * t22 * M_panels[14] + t31 * M_panels[9] + T(7) * t27 * tau_lo * M_panels[15];
    G_ap = t32;
    const T t33 = T(1) / ab_ab;
    G_E = T(7) * M_panels[16] * t27 * tau_lo + T(35) * M_panels[13] * t21 * t23 + T(7) * delta_tau * t26 * M_panels[11] + M_panels[10] * t31 + T(21) * t20 * t24 * M_panels[12] + T(35) * t29 * t25 * M_panels[14] + T(21) * t30 * t22 * M_panels[15] + t28 * M_panels[17] - t33 * t32 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = sqrt(cross_cross);
    const T t35 = T(1) / t34;
    const T J2 = t35 * atan2(t34, ap_bp);
    const T t36 = delta_tau * delta_tau;
    const T t37 = t36 * delta_tau;
    const T t38 = tau_lo * tau_lo;
    const T t39 = t38 * t38;
    const T t40 = T(1) / ab_ab;
    const T t41 = T(1) / ap_ap;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = T(1) / bp_bp;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = T(1) / cross_cross;
    const T t48 = t45 * t44;
    const T t49 = t41 * ab_ap + ab_ab * J2 + a_minus_b * t44;
    const T t50 = T(3) * ab_ab * t47 * t49 + T(2) * a_minus_b * t45 + T(2) * t42 * ab_ap;
    const T t51 = t42 * t41;
    const T t52 = T(8) * a_minus_b * t48 + T(5) * t50 * ab_ab * t47 + T(8) * t51 * ab_ap;
    const T t53 = T(48) * t43 * ab_ap + T(48) * a_minus_b * t46 + T(7) * ab_ab * t47 * t52;
    const T t54 = T(48) * t43 + t53 * t47 * ab_ap - T(48) * t46;
    const T t55 = T(2) * t40 * t54 * ab_ap + T(8) * t47 * t52 - ap_ap * t53 * t47;
    const T t56 = T(8) * t51 + t47 * ab_ap * t52 - T(8) * t48;
    const T t57 = T(2) * t55 * t40 * ab_ap + T(8) * t56 * t40 - ap_ap * t40 * t54;
    const T t58 = t39 * tau_lo;
    const T t59 = t38 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = t60 * tau_lo;
    const T t62 = t36 * t36;
    const T t63 = T(2) * t56 * t40 * ab_ap + T(6) * t50 * t47 - ap_ap * t47 * t52;
    const T t64 = ap_ap * t55 * t40 - T(2) * t57 * t40 * ab_ap - T(8) * t40 * t63;
    const T t65 = t50 * t47 * ab_ap + T(2) * t42 - T(2) * t45;
    const T t66 = T(2) * t40 * ab_ap * t63 + T(6) * t40 * t65 - t56 * ap_ap * t40;
    const T t67 = ap_ap * t57 * t40 + T(2) * t40 * ab_ap * t64 - T(8) * t66 * t40;
    const T t68 = T(2) * t40 * t65 * ab_ap + T(4) * t47 * t49 - t50 * ap_ap * t47;
    const T t69 = T(2) * t66 * t40 * ab_ap + T(6) * t40 * t68 - ap_ap * t40 * t63;
    const T t70 = T(2) * t67 * t40 * ab_ap - ap_ap * t40 * t64 - T(8) * t40 * t69;
    const T t71 = t37 * t37;
    const T t72 = t62 * delta_tau;
    const T t73 = t71 * delta_tau;
    const T t74 = t44 - t41 - t47 * t49 * ab_ap;
    const T t75 = T(4) * t74 * t40 + ap_ap * t40 * t65 - T(2) * t40 * ab_ap * t68;
    const T t76 = T(6) * t75 * t40 + ap_ap * t66 * t40 - T(2) * t40 * ab_ap * t69;
    G_ap = (T(35) / T(384)) * t37 * t39 * t57 * t40 + (T(7) / T(128)) * t55 * t36 * t58 * t40 + (T(7) / T(384)) * delta_tau * t60 * t40 * t54 + (T(1) / T(384)) * t53 * t61 * t47 - (T(35) / T(384)) * t62 * t59 * t40 * t64 - (T(7) / T(384)) * t70 * t71 * tau_lo * t40 - (T(7) / T(128)) * t72 * t38 * t67 * t40 - (T(1) / T(384)) * t73 * t40 * (T(8) * t76 * t40 + T(2) * t70 * t40 * ab_ap - ap_ap * t67 * t40);
    G_E = (T(1) / T(384)) * (T(7) * delta_tau * t60 * t47 * t52 + T(105) * t72 * t38 * t40 * t69 + T(42) * t56 * t36 * t58 * t40 + T(140) * t62 * t59 * t66 * t40 + T(105) * t37 * t39 * t40 * t63 + T(48) * t43 * t61 - T(48) * (T(7) * delta_tau * t60 + t61 + t73 + T(7) * t71 * tau_lo + T(35) * t37 * t39 + T(35) * t62 * t59 + T(21) * t72 * t38 + T(21) * t36 * t58) * t46 - T(7) * t73 * t40 * (ap_ap * t40 * t69 + T(2) * t76 * t40 * ab_ap + T(6) * (T(2) * t75 * t40 * ab_ap + T(4) * t40 * (ap_ap * t47 * t49 + T(2) * t74 * t40 * ab_ap - T(2) * J2) + ap_ap * t40 * t68) * t40) - T(42) * t71 * t76 * tau_lo * t40) * t40;
  }
  const T t77 = in.sigma * in.sigma;
  const T t78 = t77 * t77;
  const T t79 = t78 * t78;
  const T g_factor = -T(8) * length * t79;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 118 +, 345 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 24343 +, 31700 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (ab1 * exact_cross[2] - exact_cross[1] * ab2);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -(exact_cross[1] * ab0 - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t3 = T(1) / ap_ap;
  const T log_ratio = log(t3 * bp_bp);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t7 = delta_tau * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = tau_lo * tau_lo;
    const T t11 = t10 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t7 * delta_tau;
    const T t15 = t10 * t10;
    const T t16 = t14 * t14;
    const T t17 = t16 * delta_tau;
    const T t18 = t15 * tau_lo;
    F = T(21) * M_panels[5] * t9 * t10 + t13 * M_panels[0] + T(35) * t14 * t15 * M_panels[3] + T(7) * t16 * tau_lo * M_panels[6] + t17 * M_panels[7] + T(35) * t8 * t11 * M_panels[4] + T(7) * delta_tau * t12 * M_panels[1] + T(21) * t7 * M_panels[2] * t18;
    const T t19 = T(35) * t8 * t11 * M_panels[13] + T(21) * M_panels[11] * t7 * t18 + T(21) * M_panels[14] * t9 * t10 + t17 * M_panels[16] + t13 * M_panels[9] + T(7) * t16 * tau_lo * M_panels[15] + T(35) * t14 * t15 * M_panels[12] + T(7) * delta_tau * t12 * M_panels[10];
    G_ap = t19;
    const T t20 = T(1) / ab_ab;
    G_E = M_panels[17] * t17 + T(35) * t14 * t15 * M_panels[13] + T(21) * t7 * t18 * M_panels[12] + T(7) * t16 * tau_lo * M_panels[16] + T(35) * M_panels[14] * t8 * t11 + T(21) * t9 * t10 * M_panels[15] + t13 * M_panels[10] + T(7) * M_panels[11] * delta_tau * t12 - t20 * t19 * ab_ap;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t21 = delta_tau * delta_tau;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t22 * tau_lo;
    const T t26 = t25 * t25;
    const T t27 = t21 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t21 * t21;
    const T t31 = t26 * tau_lo;
    const T t32 = t30 * delta_tau;
    F = T(21) * t21 * t24 * M_panels[2] + T(7) * delta_tau * t26 * M_panels[1] + t29 * M_panels[7] + T(35) * t30 * t25 * M_panels[4] + T(7) * M_panels[6] * t28 * tau_lo + M_panels[0] * t31 + T(35) * M_panels[3] * t27 * t23 + T(21) * t32 * t22 * M_panels[5];
    const T t33 = T(7) * M_panels[15] * t28 * tau_lo + T(21) * t21 * t24 * M_panels[11] + T(35) * t30 * t25 * M_panels[13] + M_panels[9] * t31 + T(7) * delta_tau * t26 * M_panels[10] + T(35) * M_panels[12] * t27 * t23 + t29 * M_panels[16] + T(21) * t32 * t22 * M_panels[14];
    G_ap = t33;
    const T t34 = T(1) / ab_ab;
    G_E = T(21) * M_panels[15] * t32 * t22 + t29 * M_panels[17] + T(35) * t27 * t23 * M_panels[13] + t31 * M_panels[10] + T(7) * t28 * tau_lo * M_panels[16] + T(7) * delta_tau * t26 * M_panels[11] + T(21) * M_panels[12] * t21 * t24 + T(35) * t30 * t25 * M_panels[14] - t33 * t34 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(cross_cross);
    const T t36 = T(1) / t35;
    const T J2 = t36 * atan2(t35, ap_bp);
    const T t37 = T(1) / bp_bp;
    const T t38 = t37 * t37;
    const T t39 = t38 * t37;
    const T t40 = T(1) / cross_cross;
    const T t41 = t3 * t3;
    const T t42 = a_minus_b * t37 + t3 * ab_ap + J2 * ab_ab;
    const T t43 = T(2) * a_minus_b * t38 + T(2) * t41 * ab_ap + T(3) * ab_ab * t40 * t42;
    const T t44 = t41 * t3;
    const T t45 = T(8) * a_minus_b * t39 + T(5) * ab_ab * t40 * t43 + T(8) * t44 * ab_ap;
    const T t46 = tau_lo * tau_lo;
    const T t47 = t46 * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t48 * tau_lo;
    const T t50 = T(2) * t41 + t40 * ab_ap * t43 - T(2) * t38;
    const T t51 = T(1) / ab_ab;
    const T t52 = t45 * t40 * ab_ap + T(8) * t44 - T(8) * t39;
    const T t53 = ap_ap * t45 * t40 - T(6) * t40 * t43 - T(2) * t51 * t52 * ab_ap;
    const T t54 = T(6) * t50 * t51 - ap_ap * t51 * t52 - T(2) * t51 * t53 * ab_ap;
    const T t55 = delta_tau * delta_tau;
    const T t56 = t55 * delta_tau;
    const T t57 = t46 * t46;
    const T t58 = ap_ap * t40 * t43 - T(4) * t40 * t42 - T(2) * t50 * t51 * ab_ap;
    const T t59 = t37 - t3 - t40 * ab_ap * t42;
    const T t60 = T(2) * J2 - ap_ap * t40 * t42 - T(2) * t51 * t59 * ab_ap;
    const T t61 = T(2) * t51 * t58 * ab_ap + T(4) * t51 * t59 + ap_ap * t50 * t51;
    const T t62 = ap_ap * t51 * t58 + T(4) * t51 * t60 - T(2) * t51 * ab_ap * t61;
    const T t63 = T(6) * t51 * t58 - ap_ap * t51 * t53 - T(2) * t54 * t51 * ab_ap;
    const T t64 = T(2) * t63 * t51 * ab_ap + T(6) * t51 * t61 + ap_ap * t54 * t51;
    const T t65 = T(2) * t64 * t51 * ab_ap - ap_ap * t63 * t51 - T(6) * t51 * t62;
    const T t66 = t56 * t56;
    const T t67 = t66 * delta_tau;
    const T t68 = t55 * t55;
    const T t69 = t68 * delta_tau;
    const T t70 = t57 * tau_lo;
    F = (T(1) / T(48)) * t45 * t49 * t40 + (T(35) / T(48)) * t54 * t56 * t57 * t51 + (T(7) / T(48)) * delta_tau * t48 * t51 * t52 + (T(1) / T(48)) * (T(6) * (T(2) * t51 * t62 * ab_ap + T(4) * (ap_ap * t51 * t59 + t51 * (log_ratio + T(2) * J2 * ab_ap) + T(2) * t51 * t60 * ab_ap) * t51 + ap_ap * t51 * t61) * t51 + ap_ap * t64 * t51 - T(2) * t51 * t65 * ab_ap) * t67 * t51 - (T(7) / T(48)) * t66 * tau_lo * t51 * t65 - (T(7) / T(16)) * t69 * t46 * t64 * t51 - (T(7) / T(16)) * t55 * t70 * t51 * t53 - (T(35) / T(48)) * t63 * t68 * t47 * t51;
    const T t71 = t41 * t41;
    const T t72 = t38 * t38;
    const T t73 = T(7) * t45 * ab_ab * t40 + T(48) * t71 * ab_ap + T(48) * a_minus_b * t72;
    const T t74 = T(48) * t71 + t40 * t73 * ab_ap - T(48) * t72;
    const T t75 = ap_ap * t40 * t73 - T(2) * t51 * t74 * ab_ap - T(8) * t45 * t40;
    const T t76 = T(8) * t51 * t52 - ap_ap * t51 * t74 - T(2) * t75 * t51 * ab_ap;
    const T t77 = ap_ap * t75 * t51 + T(2) * t76 * t51 * ab_ap - T(8) * t51 * t53;
    const T t78 = T(8) * t54 * t51 + T(2) * t51 * ab_ap * t77 - ap_ap * t76 * t51;
    const T t79 = ap_ap * t51 * t77 + T(8) * t63 * t51 - T(2) * t78 * t51 * ab_ap;
    G_ap = (T(7) / T(128)) * t78 * t69 * t46 * t51 + (T(35) / T(384)) * t76 * t56 * t57 * t51 + (T(7) / T(384)) * delta_tau * t48 * t51 * t74 + (T(1) / T(384)) * t49 * t40 * t73 + (T(35) / T(384)) * t68 * t47 * t51 * t77 - (T(7) / T(128)) * t55 * t70 * t75 * t51 - (T(1) / T(384)) * t67 * (t78 * ap_ap * t51 + T(8) * t64 * t51 + T(2) * t51 * t79 * ab_ap) * t51 - (T(7) / T(384)) * t66 * tau_lo * t51 * t79;
    G_E = (T(1) / T(384)) * t51 * (T(7) * delta_tau * t45 * t48 * t40 + T(140) * t54 * t68 * t47 * t51 + T(48) * t71 * t49 + T(42) * t55 * t70 * t51 * t52 - T(7) * t67 * t51 * t65 - T(105) * t56 * t57 * t51 * t53 - T(42) * t66 * tau_lo * t64 * t51 - T(105) * t63 * t69 * t46 * t51 - T(48) * (T(7) * delta_tau * t48 + t49 + t67 + T(21) * t69 * t46 + T(35) * t68 * t47 + T(35) * t56 * t57 + T(7) * t66 * tau_lo + T(21) * t55 * t70) * t72);
  }
  const T t80 = in.sigma * in.sigma;
  const T t81 = t80 * t80;
  const T t82 = t81 * t81;
  const T g_factor = -T(8) * length * t82;
  f = F * length * t82;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 84 +, 254 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 14602 +, 25166 ×, 2437 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = ab_ap * r1;
    X = length * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = ab_ap * r1;
    X = -(a_minus_b - ab_ap) * length / (t4 - a_minus_b * r0);
  }
  const T t5 = T(1) / length;
  const T J1 = t5 * asinh(X);
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t11 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t14 * delta_tau;
    const T t16 = t10 * tau_lo;
    const T t17 = t9 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t18 * tau_lo;
    const T t20 = t10 * t10;
    const T t21 = t12 * t12;
    const T t22 = t12 * delta_tau;
    F = T(70) * t10 * M_panels[4] * t12 + T(8) * tau_lo * M_panels[7] * t15 + T(28) * t9 * M_panels[6] * t14 + T(56) * t16 * M_panels[3] * t13 + T(8) * t19 * M_panels[1] * delta_tau + t20 * M_panels[0] + M_panels[8] * t21 + T(28) * t18 * M_panels[2] * t11 + T(56) * t17 * M_panels[5] * t22;
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t23 = tau_lo * tau_lo;
    const T t24 = t23 * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * t23;
    const T t28 = delta_tau * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t27 * t27;
    const T t31 = t27 * tau_lo;
    const T t32 = t28 * delta_tau;
    const T t33 = t29 * t29;
    const T t34 = t32 * t32;
    const T t35 = t34 * delta_tau;
    const T t36 = t29 * delta_tau;
    F = T(8) * t26 * delta_tau * M_panels[1] + T(70) * t27 * M_panels[4] * t29 + t30 * M_panels[0] + T(56) * t31 * M_panels[3] * t32 + M_panels[8] * t33 + T(8) * tau_lo * M_panels[7] * t35 + T(56) * t24 * M_panels[5] * t36 + T(28) * t25 * M_panels[2] * t28 + T(28) * t23 * M_panels[6] * t34;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t37 = tau_lo * tau_lo;
    const T t38 = t37 * t37;
    const T t39 = t38 * tau_lo;
    const T t40 = T(1) / ab_ab;
    const T t41 = T(1) / r1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = T(1) / cross_cross;
    const T t45 = T(1) / r0;
    const T t46 = t45 * t45;
    const T t47 = ab_ap * t45 + a_minus_b * t41;
    const T t48 = ab_ap * t45 * t46 + a_minus_b * t42 * t41 + T(2) * ab_ab * t47 * t44;
    const T t49 = t46 * t46;
    const T t50 = T(3) * a_minus_b * t43 * t41 + T(4) * ab_ab * t44 * t48 + T(3) * ab_ap * t45 * t49;
    const T t51 = t50 * t44 * ab_ap + T(3) * t45 * t49 - T(3) * t43 * t41;
    const T t52 = t43 * t42;
    const T t53 = t49 * t46;
    const T t54 = T(5) * a_minus_b * t52 * t41 + T(2) * t50 * ab_ab * t44 + T(5) * ab_ap * t45 * t53;
    const T t55 = T(5) * t45 * t53 + t44 * t54 * ab_ap - T(5) * t52 * t41;
    const T t56 = T(3) * t44 * t54 * ap_ap - T(7) * t50 * t44 - T(6) * t40 * ab_ap * t55;
    const T t57 = T(7) * t40 * t51 - T(2) * t40 * ab_ap * t56 - T(3) * t40 * t55 * ap_ap;
    const T t58 = delta_tau * delta_tau;
    const T t59 = t58 * delta_tau;
    const T t60 = t38 * t38;
    const T t61 = t50 * t44 * ap_ap - T(5) * t44 * t48 - T(2) * t40 * t51 * ab_ap;
    const T t62 = t40 * t56 * ap_ap + T(2) * t40 * ab_ap * t57 - T(7) * t40 * t61;
    const T t63 = t58 * t58;
    const T t64 = t37 * tau_lo;
    const T t65 = t64 * t64;
    const T t66 = t65 * tau_lo;
    const T t67 = t42 * t41 - t44 * ab_ap * t48 - t45 * t46;
    const T t68 = T(2) * t40 * ab_ap * t61 + t40 * t51 * ap_ap + T(5) * t40 * t67;
    const T t69 = t40 * t57 * ap_ap + T(7) * t68 * t40 - T(2) * t40 * ab_ap * t62;
    const T t70 = t63 * delta_tau;
    const T t71 = t44 * t48 * ap_ap + T(2) * t40 * ab_ap * t67 - T(3) * t47 * t44;
    const T t72 = t41 - t47 * t44 * ab_ap - t45;
    const T t73 = T(2) * t40 * ab_ap * t71 + T(3) * t40 * t72 - t40 * ap_ap * t67;
    const T t74 = t40 * ap_ap * t61 - T(2) * t68 * t40 * ab_ap - T(5) * t40 * t71;
    const T t75 = T(5) * t40 * t73 - t68 * t40 * ap_ap - T(2) * t74 * t40 * ab_ap;
    const T t76 = t40 * t62 * ap_ap + T(2) * t69 * t40 * ab_ap - T(7) * t74 * t40;
    const T t77 = T(7) * t40 * t75 + T(2) * t40 * t76 * ab_ap - t69 * t40 * ap_ap;
    const T t78 = t59 * t59;
    const T t79 = t78 * delta_tau;
    const T t80 = t63 * t63;
    F = (T(8) / T(15)) * t39 * t40 * t57 * t59 + (T(1) / T(35)) * t60 * t44 * t54 + (T(2) / T(3)) * t38 * t40 * t62 * t63 + (T(8) / T(35)) * t66 * t40 * t55 * delta_tau - (T(8) / T(15)) * t64 * t69 * t40 * t70 - (T(8) / T(105)) * tau_lo * t40 * t77 * t79 - (T(4) / T(15)) * t37 * t40 * t76 * t78 - (T(4) / T(15)) * t65 * t40 * t56 * t58 - (T(1) / T(105)) * t40 * t80 * (T(2) * t40 * t77 * ab_ap + T(7) * t40 * (T(2) * t40 * ab_ap * t75 + t74 * t40 * ap_ap - T(5) * t40 * (t40 * t71 * ap_ap - T(3) * t40 * (t47 * t44 * ap_ap + T(2) * t40 * t72 * ab_ap - J1) - T(2) * t40 * ab_ap * t73)) - t40 * t76 * ap_ap);
  }
  const T t81 = in.sigma * in.sigma;
  const T t82 = t81 * t81;
  const T t83 = t82 * t82;
  const T t84 = t83 * in.sigma;
  f = length * t84 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 116 +, 362 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 26496 +, 40323 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = t2 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t7 * delta_tau;
    const T t12 = t8 * tau_lo;
    const T t13 = t9 * t9;
    const T t14 = t6 * delta_tau;
    const T t15 = t9 * tau_lo;
    const T t16 = t14 * t14;
    const T t17 = t16 * delta_tau;
    const T t18 = t12 * t12;
    const T t19 = t18 * tau_lo;
    const T t20 = T(70) * t7 * t9 * M_panels[14] + t10 * M_panels[18] + T(56) * t11 * t12 * M_panels[15] + t13 * M_panels[10] + T(56) * t14 * t15 * M_panels[13] + T(8) * t17 * tau_lo * M_panels[17] + T(8) * delta_tau * t19 * M_panels[11] + T(28) * t16 * M_panels[16] * t8 + T(28) * t6 * t18 * M_panels[12];
    G_ap = t20;
    const T t21 = T(1) / ab_ab;
    G_E = M_panels[19] * t10 + T(8) * t17 * tau_lo * M_panels[18] + T(8) * delta_tau * t19 * M_panels[12] + T(56) * t11 * M_panels[16] * t12 + t13 * M_panels[11] + T(28) * t6 * t18 * M_panels[13] + T(56) * t14 * t15 * M_panels[14] + T(28) * t16 * t8 * M_panels[17] + T(70) * t7 * t9 * M_panels[15] - t21 * t20 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = delta_tau * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t27 * delta_tau;
    const T t30 = t22 * t22;
    const T t31 = t30 * t30;
    const T t32 = t26 * delta_tau;
    const T t33 = t32 * t32;
    const T t34 = t33 * delta_tau;
    const T t35 = t30 * tau_lo;
    const T t36 = T(8) * delta_tau * t25 * M_panels[11] + t28 * M_panels[18] + T(56) * t29 * M_panels[15] * t23 + T(28) * t26 * t24 * M_panels[12] + T(70) * t27 * t30 * M_panels[14] + t31 * M_panels[10] + T(8) * M_panels[17] * t34 * tau_lo + T(28) * t33 * t22 * M_panels[16] + T(56) * t32 * t35 * M_panels[13];
    G_ap = t36;
    const T t37 = T(1) / ab_ab;
    G_E = T(28) * t26 * t24 * M_panels[13] + T(8) * t34 * tau_lo * M_panels[18] + t31 * M_panels[11] + T(56) * t32 * t35 * M_panels[14] + T(56) * t29 * t23 * M_panels[16] + T(8) * delta_tau * t25 * M_panels[12] + T(28) * M_panels[17] * t33 * t22 + T(70) * t27 * M_panels[15] * t30 + t28 * M_panels[19] - t36 * t37 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = tau_lo * tau_lo;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = T(1) / cross_cross;
    const T t42 = T(1) / r0;
    const T t43 = t42 * t42;
    const T t44 = T(1) / r1;
    const T t45 = t44 * t44;
    const T t46 = t44 * a_minus_b + ab_ap * t42;
    const T t47 = ab_ap * t42 * t43 + t44 * a_minus_b * t45 + T(2) * ab_ab * t41 * t46;
    const T t48 = t43 * t43;
    const T t49 = t45 * t45;
    const T t50 = T(4) * ab_ab * t41 * t47 + T(3) * ab_ap * t42 * t48 + T(3) * t44 * a_minus_b * t49;
    const T t51 = t49 * t45;
    const T t52 = t48 * t43;
    const T t53 = T(2) * ab_ab * t50 * t41 + T(5) * t44 * a_minus_b * t51 + T(5) * ab_ap * t42 * t52;
    const T t54 = t48 * t48;
    const T t55 = t49 * t49;
    const T t56 = T(8) * t53 * ab_ab * t41 + T(35) * ab_ap * t42 * t54 + T(35) * t44 * a_minus_b * t55;
    const T t57 = delta_tau * delta_tau;
    const T t58 = t57 * delta_tau;
    const T t59 = t39 * tau_lo;
    const T t60 = T(1) / ab_ab;
    const T t61 = T(35) * t44 * t55 - T(35) * t42 * t54 - t56 * t41 * ab_ap;
    const T t62 = T(5) * t44 * t51 - t53 * t41 * ab_ap - T(5) * t42 * t52;
    const T t63 = t56 * t41 * ap_ap + T(2) * t61 * t60 * ab_ap - T(9) * t53 * t41;
    const T t64 = t61 * t60 * ap_ap - T(9) * t60 * t62 - T(2) * t60 * t63 * ab_ap;
    const T t65 = t58 * t58;
    const T t66 = T(3) * t53 * t41 * ap_ap + T(6) * t60 * t62 * ab_ap - T(7) * t50 * t41;
    const T t67 = T(3) * t60 * t66 - t60 * t63 * ap_ap - T(2) * t60 * ab_ap * t64;
    const T t68 = T(3) * t44 * t49 - t50 * t41 * ab_ap - T(3) * t42 * t48;
    const T t69 = T(3) * t60 * t62 * ap_ap - T(7) * t68 * t60 - T(2) * t60 * t66 * ab_ap;
    const T t70 = t60 * t64 * ap_ap + T(2) * t67 * t60 * ab_ap - T(3) * t60 * t69;
    const T t71 = T(2) * t68 * t60 * ab_ap + t50 * t41 * ap_ap - T(5) * t41 * t47;
    const T t72 = T(7) * t60 * t71 - T(2) * t60 * t69 * ab_ap - t60 * t66 * ap_ap;
    const T t73 = T(2) * t70 * t60 * ab_ap + T(3) * t60 * t72 - t67 * t60 * ap_ap;
    const T t74 = t38 * tau_lo;
    const T t75 = t74 * t74;
    const T t76 = t75 * tau_lo;
    const T t77 = t57 * t57;
    const T t78 = t77 * t77;
    const T t79 = t42 * t43 + t41 * ab_ap * t47 - t44 * t45;
    const T t80 = T(5) * t60 * t79 + t68 * t60 * ap_ap - T(2) * t60 * t71 * ab_ap;
    const T t81 = t60 * t69 * ap_ap + T(2) * t60 * ab_ap * t72 - T(7) * t60 * t80;
    const T t82 = T(3) * t81 * t60 + T(2) * t60 * ab_ap * t73 - t70 * t60 * ap_ap;
    const T t83 = T(3) * t41 * t46 + T(2) * t60 * t79 * ab_ap - t41 * t47 * ap_ap;
    const T t84 = T(2) * t60 * ab_ap * t80 + T(5) * t60 * t83 + t60 * t71 * ap_ap;
    const T t85 = t60 * t72 * ap_ap + T(7) * t60 * t84 - T(2) * t81 * t60 * ab_ap;
    const T t86 = t77 * delta_tau;
    const T t87 = t65 * delta_tau;
    G_ap = (T(1) / T(315)) * t40 * t56 * t41 + (T(8) / T(45)) * t58 * t59 * t60 * t64 - (T(4) / T(45)) * t65 * t38 * t60 * t73 - (T(4) / T(45)) * t57 * t75 * t60 * t63 - (T(8) / T(315)) * t61 * delta_tau * t76 * t60 - (T(1) / T(315)) * t78 * t60 * (T(2) * t82 * t60 * ab_ap - T(3) * t60 * t85 - t60 * t73 * ap_ap) - (T(8) / T(45)) * t86 * t70 * t74 * t60 - (T(8) / T(315)) * t87 * t82 * tau_lo * t60 - (T(2) / T(9)) * t77 * t39 * t67 * t60;
    const T t88 = t42 * t42;
    const T t89 = t88 * t88;
    const T t90 = t89 * t89;
    const T t91 = t90 * t42;
    const T t92 = t44 * t44;
    const T t93 = t92 * t92;
    const T t94 = t93 * t93;
    const T t95 = t94 * t44;
    G_E = (T(1) / T(945)) * t60 * (T(105) * t40 * t91 + T(280) * t77 * t39 * t60 * t69 + T(8) * t78 * t60 * (T(2) * t60 * ab_ap * t85 + T(7) * t60 * (T(2) * t60 * ab_ap * t84 + T(5) * (T(3) * t60 * (t41 * ab_ap * t46 + t42 - t44) + T(2) * t60 * t83 * ab_ap - t60 * t79 * ap_ap) * t60 - t60 * t80 * ap_ap) + t81 * t60 * ap_ap) + T(56) * t87 * tau_lo * t60 * t85 + T(24) * t53 * delta_tau * t76 * t41 - T(168) * t81 * t65 * t38 * t60 - T(168) * t57 * t75 * t60 * t62 - T(105) * t95 * (T(70) * t77 * t39 + t40 + t78 + T(8) * delta_tau * t76 + T(28) * t57 * t75 + T(28) * t65 * t38 + T(8) * t87 * tau_lo + T(56) * t86 * t74 + T(56) * t58 * t59) - T(280) * t86 * t74 * t60 * t72 - T(168) * t58 * t59 * t60 * t66);
  }
  const T t96 = in.sigma * in.sigma;
  const T t97 = t96 * t96;
  const T t98 = t97 * t97;
  const T t99 = t98 * in.sigma;
  const T g_factor = -T(9) * length * t99;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 133 +, 430 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 26505 +, 40354 ×, 2439 /, 1139 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (ab1 * exact_cross[2] - ab2 * exact_cross[1]);
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * t2;
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = ab_ap * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / cross_cross;
    const T t5 = r1 * ab_ap;
    X = length * t4 * (t5 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = length * (ab_ap - a_minus_b) / (t6 - a_minus_b * r0);
  }
  const T t7 = T(1) / length;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t11 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    const T t17 = delta_tau * delta_tau;
    const T t18 = t17 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t17 * t17;
    const T t21 = t20 * t20;
    const T t22 = t12 * tau_lo;
    const T t23 = t20 * delta_tau;
    const T t24 = t19 * delta_tau;
    F = M_panels[0] * t13 + T(8) * M_panels[1] * delta_tau * t16 + T(28) * M_panels[6] * t19 * t11 + M_panels[8] * t21 + T(28) * t17 * M_panels[2] * t15 + T(56) * M_panels[3] * t18 * t22 + T(70) * M_panels[4] * t20 * t12 + T(56) * M_panels[5] * t23 * t14 + T(8) * M_panels[7] * t24 * tau_lo;
    const T t25 = T(28) * t17 * t15 * M_panels[12] + T(56) * M_panels[13] * t18 * t22 + T(8) * M_panels[17] * t24 * tau_lo + T(8) * M_panels[11] * delta_tau * t16 + T(70) * M_panels[14] * t20 * t12 + T(56) * t23 * M_panels[15] * t14 + M_panels[10] * t13 + t21 * M_panels[18] + T(28) * M_panels[16] * t19 * t11;
    G_ap = t25;
    const T t26 = T(1) / ab_ab;
    G_E = T(70) * t20 * M_panels[15] * t12 + M_panels[19] * t21 + T(28) * M_panels[17] * t19 * t11 + M_panels[11] * t13 + T(28) * M_panels[13] * t17 * t15 + T(56) * M_panels[16] * t23 * t14 + T(56) * M_panels[14] * t18 * t22 + T(8) * t24 * M_panels[18] * tau_lo + T(8) * delta_tau * t16 * M_panels[12] - t26 * ab_ap * t25;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t27 = delta_tau * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = tau_lo * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t28 * delta_tau;
    const T t32 = t29 * tau_lo;
    const T t33 = t27 * delta_tau;
    const T t34 = t30 * tau_lo;
    const T t35 = t28 * t28;
    const T t36 = t33 * t33;
    const T t37 = t32 * t32;
    const T t38 = t36 * delta_tau;
    const T t39 = t37 * tau_lo;
    const T t40 = t30 * t30;
    F = T(70) * M_panels[4] * t28 * t30 + T(56) * M_panels[5] * t31 * t32 + T(56) * M_panels[3] * t33 * t34 + t35 * M_panels[8] + T(28) * M_panels[6] * t36 * t29 + T(28) * M_panels[2] * t27 * t37 + T(8) * M_panels[7] * t38 * tau_lo + T(8) * M_panels[1] * delta_tau * t39 + M_panels[0] * t40;
    const T t41 = T(70) * t28 * t30 * M_panels[14] + T(28) * M_panels[16] * t36 * t29 + T(28) * M_panels[12] * t27 * t37 + M_panels[18] * t35 + M_panels[10] * t40 + T(8) * t38 * M_panels[17] * tau_lo + T(56) * M_panels[13] * t33 * t34 + T(8) * delta_tau * t39 * M_panels[11] + T(56) * M_panels[15] * t31 * t32;
    G_ap = t41;
    const T t42 = T(1) / ab_ab;
    G_E = T(70) * M_panels[15] * t28 * t30 + T(8) * M_panels[18] * t38 * tau_lo + t40 * M_panels[11] + T(56) * M_panels[16] * t31 * t32 + M_panels[19] * t35 + T(28) * M_panels[13] * t27 * t37 + T(28) * t36 * M_panels[17] * t29 + T(8) * M_panels[12] * delta_tau * t39 + T(56) * t33 * t34 * M_panels[14] - t42 * ab_ap * t41;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t43 = T(1) / cross_cross;
    const T t44 = T(1) / r0;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t45;
    const T t48 = T(1) / r1;
    const T t49 = t48 * t48;
    const T t50 = t49 * t49;
    const T t51 = t50 * t49;
    const T t52 = ab_ap * t44 + t48 * a_minus_b;
    const T t53 = T(2) * ab_ab * t52 * t43 + ab_ap * t45 * t44 + t48 * t49 * a_minus_b;
    const T t54 = T(3) * t48 * t50 * a_minus_b + T(3) * ab_ap * t46 * t44 + T(4) * ab_ab * t43 * t53;
    const T t55 = T(5) * ab_ap * t47 * t44 + T(5) * t48 * t51 * a_minus_b + T(2) * ab_ab * t43 * t54;
    const T t56 = tau_lo * tau_lo;
    const T t57 = t56 * t56;
    const T t58 = t57 * t57;
    const T t59 = T(1) / ab_ab;
    const T t60 = t43 * ab_ap * t55 + T(5) * t47 * t44 - T(5) * t48 * t51;
    const T t61 = T(6) * t59 * ab_ap * t60 + T(7) * t43 * t54 - T(3) * t43 * ap_ap * t55;
    const T t62 = t43 * ab_ap * t54 + T(3) * t46 * t44 - T(3) * t48 * t50;
    const T t63 = T(2) * t59 * ab_ap * t61 + T(7) * t62 * t59 - T(3) * t59 * t60 * ap_ap;
    const T t64 = delta_tau * delta_tau;
    const T t65 = t64 * delta_tau;
    const T t66 = t57 * tau_lo;
    const T t67 = T(2) * t62 * t59 * ab_ap + T(5) * t43 * t53 - t43 * ap_ap * t54;
    const T t68 = t45 * t44 + t43 * ab_ap * t53 - t48 * t49;
    const T t69 = T(2) * t59 * ab_ap * t67 + T(5) * t59 * t68 - t62 * t59 * ap_ap;
    const T t70 = T(2) * t59 * ab_ap * t68 + T(3) * t52 * t43 - t43 * ap_ap * t53;
    const T t71 = T(2) * t59 * ab_ap * t69 + T(5) * t59 * t70 - t59 * t67 * ap_ap;
    const T t72 = T(2) * t59 * ab_ap * t63 + T(7) * t59 * t67 - t59 * t61 * ap_ap;
    const T t73 = T(7) * t59 * t69 + T(2) * t59 * ab_ap * t72 - t59 * ap_ap * t63;
    const T t74 = T(7) * t59 * t71 + T(2) * t59 * ab_ap * t73 - t59 * t72 * ap_ap;
    const T t75 = t44 + t52 * t43 * ab_ap - t48;
    const T t76 = T(2) * t59 * t70 * ab_ap + T(3) * t59 * t75 - t59 * ap_ap * t68;
    const T t77 = T(2) * t59 * t71 * ab_ap + T(5) * t76 * t59 - t59 * ap_ap * t69;
    const T t78 = T(2) * t59 * ab_ap * t74 + T(7) * t59 * t77 - t59 * ap_ap * t73;
    const T t79 = t65 * t65;
    const T t80 = t79 * delta_tau;
    const T t81 = t64 * t64;
    const T t82 = t81 * t81;
    const T t83 = t56 * tau_lo;
    const T t84 = t83 * t83;
    const T t85 = t84 * tau_lo;
    const T t86 = t81 * delta_tau;
    F = (T(1) / T(35)) * t43 * t55 * t58 + (T(8) / T(15)) * t59 * t63 * t65 * t66 + (T(8) / T(105)) * t59 * t78 * t80 * tau_lo + (T(1) / T(105)) * t59 * t82 * (T(7) * t59 * (T(2) * t59 * ab_ap * t77 + T(5) * t59 * (T(2) * t76 * t59 * ab_ap - T(3) * t59 * (t52 * t43 * ap_ap - J1 - T(2) * t59 * t75 * ab_ap) - t59 * t70 * ap_ap) - t59 * t71 * ap_ap) + T(2) * t59 * t78 * ab_ap - t59 * t74 * ap_ap) + (T(2) / T(3)) * t59 * t72 * t81 * t57 + (T(8) / T(35)) * t59 * t60 * delta_tau * t85 + (T(4) / T(15)) * t59 * t61 * t64 * t84 + (T(8) / T(15)) * t59 * t73 * t86 * t83 + (T(4) / T(15)) * t59 * t74 * t79 * t56;
    const T t87 = t46 * t46;
    const T t88 = t50 * t50;
    const T t89 = T(35) * t48 * t88 * a_minus_b + T(8) * ab_ab * t43 * t55 + T(35) * ab_ap * t87 * t44;
    const T t90 = T(35) * t87 * t44 + t43 * ab_ap * t89 - T(35) * t48 * t88;
    const T t91 = T(2) * t59 * ab_ap * t90 + T(9) * t43 * t55 - t43 * t89 * ap_ap;
    const T t92 = T(2) * t59 * ab_ap * t91 + T(9) * t59 * t60 - t59 * ap_ap * t90;
    const T t93 = T(2) * t59 * ab_ap * t92 + T(3) * t59 * t61 - t59 * ap_ap * t91;
    const T t94 = t59 * t92 * ap_ap - T(2) * t59 * ab_ap * t93 - T(3) * t59 * t63;
    const T t95 = T(3) * t59 * t72 - t59 * ap_ap * t93 - T(2) * t59 * ab_ap * t94;
    const T t96 = t59 * ap_ap * t94 + T(3) * t59 * t73 + T(2) * t59 * t95 * ab_ap;
    G_ap = (T(4) / T(45)) * t59 * t91 * t64 * t84 + (T(4) / T(45)) * t59 * t95 * t79 * t56 + (T(2) / T(9)) * t59 * t93 * t81 * t57 + (T(8) / T(315)) * t59 * t96 * t80 * tau_lo + (T(8) / T(45)) * t59 * t92 * t65 * t66 + (T(1) / T(315)) * t43 * t89 * t58 + (T(8) / T(315)) * t59 * t90 * delta_tau * t85 - (T(8) / T(45)) * t59 * t86 * t94 * t83 - (T(1) / T(315)) * t59 * (t59 * t95 * ap_ap - T(3) * t59 * t74 - T(2) * t59 * ab_ap * t96) * t82;
    const T t97 = t44 * t44;
    const T t98 = t97 * t97;
    const T t99 = t98 * t98;
    const T t100 = t99 * t44;
    const T t101 = t48 * t48;
    const T t102 = t101 * t101;
    const T t103 = t102 * t102;
    const T t104 = t103 * t48;
    G_E = (T(1) / T(945)) * t59 * (T(105) * t100 * t58 + T(280) * t59 * t72 * t86 * t83 + T(168) * t59 * t60 * t64 * t84 + T(168) * t59 * t73 * t79 * t56 + T(56) * t59 * t74 * t80 * tau_lo + T(24) * t43 * t55 * delta_tau * t85 + T(8) * t59 * t78 * t82 + T(168) * t59 * t61 * t65 * t66 + T(280) * t59 * t63 * t81 * t57 - T(105) * t104 * (T(8) * delta_tau * t85 + T(70) * t81 * t57 + T(56) * t65 * t66 + t58 + T(56) * t86 * t83 + T(8) * t80 * tau_lo + t82 + T(28) * t64 * t84 + T(28) * t79 * t56));
  }
  const T t105 = in.sigma * in.sigma;
  const T t106 = t105 * t105;
  const T t107 = t106 * t106;
  const T t108 = t107 * in.sigma;
  const T g_factor = -T(9) * length * t108;
  f = length * t108 * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 96 +, 280 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15684 +, 21929 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t1 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t1);
  T F;
  const T t2 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t3 = -a_minus_b * ab_ap;
  const T t4 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t5 = delta_tau * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t8 * tau_lo;
    const T t10 = t5 * t5;
    const T t11 = t10 * delta_tau;
    const T t12 = t6 * t6;
    const T t13 = t10 * t10;
    const T t14 = t5 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t12 * t12;
    const T t17 = t16 * tau_lo;
    const T t18 = t12 * tau_lo;
    const T t19 = t15 * delta_tau;
    const T t20 = t13 * delta_tau;
    F = T(36) * M_panels[2] * t5 * t9 + T(126) * M_panels[5] * t11 * t12 + T(9) * M_panels[8] * t13 * tau_lo + T(84) * M_panels[6] * t15 * t7 + T(9) * delta_tau * t16 * M_panels[1] + M_panels[0] * t17 + T(126) * t10 * t18 * M_panels[4] + T(36) * t19 * t6 * M_panels[7] + T(84) * M_panels[3] * t14 * t8 + M_panels[9] * t20;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t21 = delta_tau * delta_tau;
    const T t22 = t21 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = tau_lo * tau_lo;
    const T t26 = t25 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t21 * t21;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = t29 * delta_tau;
    const T t33 = t25 * t25;
    const T t34 = t33 * t33;
    const T t35 = t33 * tau_lo;
    const T t36 = t34 * tau_lo;
    F = T(36) * M_panels[7] * t24 * t25 + T(36) * M_panels[2] * t21 * t28 + M_panels[9] * t31 + T(126) * M_panels[5] * t32 * t33 + T(84) * M_panels[3] * t22 * t27 + T(9) * M_panels[1] * delta_tau * t34 + T(84) * t23 * M_panels[6] * t26 + T(126) * t29 * t35 * M_panels[4] + T(9) * M_panels[8] * t30 * tau_lo + M_panels[0] * t36;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t37 = sqrt(cross_cross);
    const T t38 = T(1) / t37;
    const T J2 = t38 * atan2(t37, ap_bp);
    const T t39 = T(1) / ab_ab;
    const T t40 = T(1) / cross_cross;
    const T t41 = T(1) / bp_bp;
    const T t42 = a_minus_b * t41 + ab_ap * t1 + ab_ab * J2;
    const T t43 = t1 * t1;
    const T t44 = t41 * t41;
    const T t45 = T(2) * ab_ap * t43 + T(3) * ab_ab * t40 * t42 + T(2) * a_minus_b * t44;
    const T t46 = T(2) * t43 + t45 * t40 * ab_ap - T(2) * t44;
    const T t47 = T(4) * t40 * t42 + T(2) * t39 * ab_ap * t46 - t45 * t40 * ap_ap;
    const T t48 = t41 - t40 * t42 * ab_ap - t1;
    const T t49 = T(2) * t39 * ab_ap * t47 - T(4) * t39 * t48 - t39 * ap_ap * t46;
    const T t50 = t43 * t1;
    const T t51 = t44 * t41;
    const T t52 = T(8) * ab_ap * t50 + T(8) * a_minus_b * t51 + T(5) * ab_ab * t45 * t40;
    const T t53 = T(8) * t50 + t52 * t40 * ab_ap - T(8) * t51;
    const T t54 = t52 * t40 * ap_ap - T(2) * t39 * ab_ap * t53 - T(6) * t45 * t40;
    const T t55 = t39 * ap_ap * t53 + T(2) * t39 * ab_ap * t54 - T(6) * t39 * t46;
    const T t56 = T(6) * t39 * t47 + t39 * t54 * ap_ap - T(2) * t39 * ab_ap * t55;
    const T t57 = T(6) * t39 * t49 + t39 * t55 * ap_ap + T(2) * t39 * ab_ap * t56;
    const T t58 = T(2) * t39 * t48 * ab_ap + t40 * t42 * ap_ap - T(2) * J2;
    const T t59 = T(4) * t39 * t58 + t39 * t47 * ap_ap - T(2) * t39 * ab_ap * t49;
    const T t60 = T(2) * t39 * ab_ap * t57 - t39 * ap_ap * t56 - T(6) * t39 * t59;
    const T t61 = t43 * t43;
    const T t62 = t44 * t44;
    const T t63 = T(7) * ab_ab * t52 * t40 + T(48) * ab_ap * t61 + T(48) * a_minus_b * t62;
    const T t64 = t40 * ab_ap * t63 + T(48) * t61 - T(48) * t62;
    const T t65 = T(2) * t39 * ab_ap * t64 + T(8) * t52 * t40 - t40 * ap_ap * t63;
    const T t66 = T(8) * t39 * t53 + T(2) * t39 * t65 * ab_ap - t39 * t64 * ap_ap;
    const T t67 = T(8) * t39 * t54 + t39 * t65 * ap_ap - T(2) * t39 * ab_ap * t66;
    const T t68 = T(8) * t39 * t55 + t39 * ap_ap * t66 + T(2) * t39 * ab_ap * t67;
    const T t69 = T(8) * t39 * t56 + t39 * t67 * ap_ap - T(2) * t39 * ab_ap * t68;
    const T t70 = t39 * t68 * ap_ap + T(2) * t39 * ab_ap * t69 + T(8) * t39 * t57;
    const T t71 = T(8) * t39 * t60 + T(2) * t39 * ab_ap * t70 - t39 * ap_ap * t69;
    const T t72 = delta_tau * delta_tau;
    const T t73 = t72 * t72;
    const T t74 = t73 * t73;
    const T t75 = tau_lo * tau_lo;
    const T t76 = t75 * t75;
    const T t77 = t76 * t76;
    const T t78 = t72 * delta_tau;
    const T t79 = t75 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = t78 * t78;
    const T t82 = t80 * tau_lo;
    const T t83 = t77 * tau_lo;
    const T t84 = t81 * delta_tau;
    const T t85 = t73 * delta_tau;
    const T t86 = t74 * delta_tau;
    const T t87 = t76 * tau_lo;
    F = (T(3) / T(128)) * t39 * t71 * t74 * tau_lo + (T(3) / T(128)) * t39 * t64 * delta_tau * t77 + (T(7) / T(32)) * t39 * t78 * t80 * t66 + (T(7) / T(32)) * t39 * t81 * t79 * t69 + (T(3) / T(32)) * t39 * t65 * t72 * t82 + (T(1) / T(384)) * t40 * t83 * t63 + (T(3) / T(32)) * t39 * t70 * t84 * t75 - (T(21) / T(64)) * t39 * t68 * t85 * t76 - (T(1) / T(384)) * t39 * (t39 * t70 * ap_ap + T(8) * t39 * (T(6) * t39 * (T(2) * t39 * ab_ap * t59 + t39 * t49 * ap_ap + T(4) * t39 * (T(2) * t39 * ab_ap * t58 - t39 * t48 * ap_ap - t39 * (log_ratio + T(2) * ab_ap * J2))) + t39 * t57 * ap_ap - T(2) * t39 * ab_ap * t60) - T(2) * t39 * ab_ap * t71) * t86 - (T(21) / T(64)) * t39 * t67 * t73 * t87;
  }
  const T t88 = in.sigma * in.sigma;
  const T t89 = t88 * t88;
  const T t90 = t89 * in.sigma;
  const T t91 = t90 * t90;
  f = length * t91 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 132 +, 393 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 28660 +, 37094 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - ab_ap * t1 * ab0;
    foot1 = ap1 - ab_ap * t1 * ab1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * t2;
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * tau_lo;
    const T t13 = t6 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t9 * tau_lo;
    const T t16 = t14 * delta_tau;
    const T t17 = t10 * tau_lo;
    const T t18 = t8 * delta_tau;
    const T t19 = t7 * delta_tau;
    const T t20 = t15 * t15;
    const T t21 = t20 * tau_lo;
    const T t22 = T(9) * M_panels[19] * t8 * tau_lo + M_panels[11] * t12 + T(84) * M_panels[17] * t14 * t15 + T(36) * t16 * t9 * M_panels[18] + T(9) * M_panels[12] * delta_tau * t11 + T(126) * M_panels[15] * t7 * t17 + M_panels[20] * t18 + T(126) * t19 * M_panels[16] * t10 + T(84) * t13 * t20 * M_panels[14] + T(36) * t6 * t21 * M_panels[13];
    G_ap = t22;
    const T t23 = T(1) / ab_ab;
    G_E = T(9) * delta_tau * t11 * M_panels[13] + t18 * M_panels[21] + T(36) * M_panels[19] * t16 * t9 + T(84) * M_panels[15] * t13 * t20 + T(84) * t14 * t15 * M_panels[18] + T(36) * t6 * t21 * M_panels[14] + M_panels[12] * t12 + T(9) * M_panels[20] * t8 * tau_lo + T(126) * t7 * M_panels[16] * t17 + T(126) * M_panels[17] * t19 * t10 - ab_ap * t23 * t22;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t24 = delta_tau * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = tau_lo * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t24 * delta_tau;
    const T t30 = t26 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t29 * t29;
    const T t33 = t32 * delta_tau;
    const T t34 = t27 * t27;
    const T t35 = t34 * tau_lo;
    const T t36 = t25 * delta_tau;
    const T t37 = t25 * t25;
    const T t38 = t31 * tau_lo;
    const T t39 = t37 * delta_tau;
    const T t40 = T(126) * t25 * t28 * M_panels[15] + T(84) * M_panels[14] * t29 * t31 + T(36) * t33 * t26 * M_panels[18] + M_panels[11] * t35 + T(126) * M_panels[16] * t36 * t27 + T(84) * M_panels[17] * t32 * t30 + T(9) * delta_tau * t34 * M_panels[12] + T(9) * M_panels[19] * t37 * tau_lo + T(36) * M_panels[13] * t24 * t38 + M_panels[20] * t39;
    G_ap = t40;
    const T t41 = T(1) / ab_ab;
    G_E = T(126) * M_panels[17] * t36 * t27 + T(9) * M_panels[20] * t37 * tau_lo + T(84) * t32 * t30 * M_panels[18] + T(36) * M_panels[14] * t24 * t38 + T(36) * M_panels[19] * t33 * t26 + T(9) * M_panels[13] * delta_tau * t34 + T(84) * t29 * t31 * M_panels[15] + T(126) * M_panels[16] * t25 * t28 + t35 * M_panels[12] + t39 * M_panels[21] - t40 * ab_ap * t41;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t42 = sqrt(cross_cross);
    const T t43 = T(1) / t42;
    const T J2 = atan2(t42, ap_bp) * t43;
    const T t44 = delta_tau * delta_tau;
    const T t45 = t44 * delta_tau;
    const T t46 = T(1) / ab_ab;
    const T t47 = T(1) / bp_bp;
    const T t48 = t47 * t47;
    const T t49 = t48 * t48;
    const T t50 = t49 * t47;
    const T t51 = T(1) / ap_ap;
    const T t52 = t51 * t51;
    const T t53 = t52 * t52;
    const T t54 = t53 * t51;
    const T t55 = t48 * t47;
    const T t56 = ab_ap * t51 + t47 * a_minus_b + ab_ab * J2;
    const T t57 = T(1) / cross_cross;
    const T t58 = T(3) * ab_ab * t56 * t57 + T(2) * t48 * a_minus_b + T(2) * ab_ap * t52;
    const T t59 = t52 * t51;
    const T t60 = T(8) * t55 * a_minus_b + T(5) * t58 * ab_ab * t57 + T(8) * ab_ap * t59;
    const T t61 = T(48) * t49 * a_minus_b + T(7) * t60 * ab_ab * t57 + T(48) * ab_ap * t53;
    const T t62 = T(128) * t50 * a_minus_b + T(128) * ab_ap * t54 + T(3) * t61 * ab_ab * t57;
    const T t63 = T(128) * t50 - T(128) * t54 - ab_ap * t62 * t57;
    const T t64 = ab_ap * t61 * t57 + T(48) * t53 - T(48) * t49;
    const T t65 = T(3) * ap_ap * t62 * t57 + T(6) * ab_ap * t46 * t63 - T(10) * t61 * t57;
    const T t66 = T(3) * ap_ap * t46 * t63 + T(10) * t64 * t46 - T(2) * ab_ap * t65 * t46;
    const T t67 = tau_lo * tau_lo;
    const T t68 = t67 * tau_lo;
    const T t69 = t68 * t68;
    const T t70 = t44 * t44;
    const T t71 = t70 * t70;
    const T t72 = T(8) * t55 - T(8) * t59 - ab_ap * t60 * t57;
    const T t73 = T(8) * t60 * t57 + T(2) * ab_ap * t64 * t46 - ap_ap * t61 * t57;
    const T t74 = t64 * ap_ap * t46 + T(8) * t72 * t46 - T(2) * ab_ap * t73 * t46;
    const T t75 = ap_ap * t60 * t57 + T(2) * t72 * ab_ap * t46 - T(6) * t58 * t57;
    const T t76 = T(2) * ab_ap * t74 * t46 + t73 * ap_ap * t46 + T(8) * t75 * t46;
    const T t77 = T(2) * t48 - T(2) * t52 - ab_ap * t58 * t57;
    const T t78 = t58 * ap_ap * t57 + T(2) * ab_ap * t77 * t46 - T(4) * t56 * t57;
    const T t79 = T(2) * ab_ap * t75 * t46 + T(6) * t77 * t46 - t72 * ap_ap * t46;
    const T t80 = T(6) * t78 * t46 + T(2) * ab_ap * t79 * t46 - t75 * ap_ap * t46;
    const T t81 = T(8) * t79 * t46 + T(2) * ab_ap * t46 * t76 - ap_ap * t74 * t46;
    const T t82 = ap_ap * t46 * t76 - T(8) * t80 * t46 - T(2) * ab_ap * t81 * t46;
    const T t83 = T(10) * t73 * t46 + t65 * ap_ap * t46 + T(2) * ab_ap * t66 * t46;
    const T t84 = ap_ap * t66 * t46 + T(10) * t74 * t46 - T(2) * ab_ap * t83 * t46;
    const T t85 = T(10) * t46 * t76 + T(2) * ab_ap * t46 * t84 + ap_ap * t83 * t46;
    const T t86 = ap_ap * t46 * t84 - T(10) * t81 * t46 - T(2) * ab_ap * t46 * t85;
    const T t87 = T(10) * t82 * t46 + ap_ap * t46 * t85 + T(2) * ab_ap * t46 * t86;
    const T t88 = t67 * t67;
    const T t89 = t88 * t88;
    const T t90 = t89 * tau_lo;
    const T t91 = t88 * tau_lo;
    const T t92 = t45 * t45;
    const T t93 = t92 * delta_tau;
    const T t94 = t51 + ab_ap * t56 * t57 - t47;
    const T t95 = T(2) * ab_ap * t78 * t46 - ap_ap * t77 * t46 - T(4) * t94 * t46;
    const T t96 = T(6) * t46 * t95 + T(2) * t80 * ab_ap * t46 - t79 * ap_ap * t46;
    const T t97 = T(8) * t96 * t46 - t81 * ap_ap * t46 - T(2) * ab_ap * t82 * t46;
    const T t98 = t71 * delta_tau;
    const T t99 = t70 * delta_tau;
    const T t100 = t69 * tau_lo;
    G_ap = (T(7) / T(320)) * t45 * t66 * t69 * t46 + (T(3) / T(1280)) * t71 * tau_lo * t46 * t87 + (T(1) / T(1280)) * t90 * t62 * t57 + (T(21) / T(640)) * t70 * t91 * t83 * t46 + (T(3) / T(320)) * t93 * t67 * t46 * t86 - (T(1) / T(3840)) * (ap_ap * t46 * t86 + T(10) * t97 * t46 - T(2) * ab_ap * t46 * t87) * t98 * t46 - (T(7) / T(320)) * t92 * t68 * t46 * t85 - (T(9) / T(1280)) * delta_tau * t89 * t46 * t63 - (T(21) / T(640)) * t99 * t88 * t46 * t84 - (T(3) / T(320)) * t65 * t44 * t100 * t46;
    G_E = (T(1) / T(1280)) * (T(3) * delta_tau * t89 * t61 * t57 + T(128) * t54 * t90 + T(84) * t73 * t45 * t69 * t46 + T(24) * t64 * t44 * t100 * t46 + T(84) * t93 * t82 * t67 * t46 - T(128) * t50 * (T(84) * t45 * t69 + T(9) * t71 * tau_lo + T(9) * delta_tau * t89 + t98 + T(36) * t44 * t100 + t90 + T(84) * t92 * t68 + T(36) * t93 * t67 + T(126) * t70 * t91 + T(126) * t99 * t88) - T(210) * t99 * t88 * t46 * t76 - T(3) * (ap_ap * t82 * t46 + T(2) * ab_ap * t97 * t46 + T(8) * (T(2) * ab_ap * t96 * t46 - t80 * ap_ap * t46 - T(6) * (t78 * ap_ap * t46 + T(4) * (T(2) * ab_ap * t94 * t46 + T(2) * J2 - ap_ap * t56 * t57) * t46 - T(2) * ab_ap * t46 * t95) * t46) * t46) * t98 * t46 - T(168) * t81 * t92 * t68 * t46 - T(24) * t97 * t71 * tau_lo * t46 - T(168) * t70 * t91 * t74 * t46) * t46;
  }
  const T t101 = in.sigma * in.sigma;
  const T t102 = t101 * t101;
  const T t103 = t102 * in.sigma;
  const T t104 = t103 * t103;
  const T g_factor = -T(10) * length * t104;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 150 +, 463 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 28669 +, 37123 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (exact_cross[2] * ab1 - ab2 * exact_cross[1]);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = (ab1 * exact_cross[0] - ab0 * exact_cross[1]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t3 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t7 = delta_tau * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t7 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    const T t17 = t13 * t13;
    const T t18 = t17 * tau_lo;
    const T t19 = t8 * delta_tau;
    const T t20 = t9 * delta_tau;
    const T t21 = t17 * t17;
    const T t22 = t21 * tau_lo;
    F = T(9) * t9 * M_panels[8] * tau_lo + T(36) * t12 * M_panels[7] * t13 + T(84) * t11 * M_panels[6] * t14 + T(36) * t7 * M_panels[2] * t16 + T(126) * t8 * M_panels[4] * t18 + T(84) * t10 * M_panels[3] * t15 + T(126) * t19 * M_panels[5] * t17 + t20 * M_panels[9] + M_panels[0] * t22 + T(9) * delta_tau * M_panels[1] * t21;
    const T t23 = T(84) * t11 * M_panels[17] * t14 + T(36) * t12 * M_panels[18] * t13 + T(36) * t7 * M_panels[13] * t16 + T(84) * t10 * M_panels[14] * t15 + M_panels[11] * t22 + T(126) * t8 * M_panels[15] * t18 + T(126) * t19 * M_panels[16] * t17 + t20 * M_panels[20] + T(9) * t9 * M_panels[19] * tau_lo + T(9) * delta_tau * M_panels[12] * t21;
    G_ap = t23;
    const T t24 = T(1) / ab_ab;
    G_E = T(84) * t11 * M_panels[18] * t14 + T(36) * t7 * M_panels[14] * t16 + t20 * M_panels[21] + T(9) * delta_tau * M_panels[13] * t21 + T(84) * t10 * M_panels[15] * t15 + T(126) * t19 * M_panels[17] * t17 + T(9) * t9 * M_panels[20] * tau_lo + T(36) * t12 * M_panels[19] * t13 + T(126) * t8 * M_panels[16] * t18 + M_panels[12] * t22 - t23 * t24 * ab_ap;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t25 = delta_tau * delta_tau;
    const T t26 = tau_lo * tau_lo;
    const T t27 = t26 * tau_lo;
    const T t28 = t27 * t27;
    const T t29 = t28 * tau_lo;
    const T t30 = t25 * delta_tau;
    const T t31 = t30 * t30;
    const T t32 = t31 * delta_tau;
    const T t33 = t26 * t26;
    const T t34 = t33 * t33;
    const T t35 = t34 * tau_lo;
    const T t36 = t25 * t25;
    const T t37 = t36 * delta_tau;
    const T t38 = t33 * tau_lo;
    const T t39 = t36 * t36;
    const T t40 = t39 * delta_tau;
    F = T(36) * t25 * M_panels[2] * t29 + T(36) * t32 * M_panels[7] * t26 + T(84) * t31 * M_panels[6] * t27 + M_panels[0] * t35 + T(126) * t37 * M_panels[5] * t33 + T(84) * t30 * M_panels[3] * t28 + T(9) * delta_tau * M_panels[1] * t34 + T(126) * t36 * M_panels[4] * t38 + t40 * M_panels[9] + T(9) * t39 * M_panels[8] * tau_lo;
    const T t41 = M_panels[11] * t35 + T(9) * t39 * M_panels[19] * tau_lo + T(126) * t36 * M_panels[15] * t38 + t40 * M_panels[20] + T(84) * t31 * M_panels[17] * t27 + T(36) * t25 * M_panels[13] * t29 + T(9) * delta_tau * M_panels[12] * t34 + T(126) * t37 * M_panels[16] * t33 + T(84) * t30 * M_panels[14] * t28 + T(36) * t32 * M_panels[18] * t26;
    G_ap = t41;
    const T t42 = T(1) / ab_ab;
    G_E = T(9) * t39 * M_panels[20] * tau_lo + T(36) * t32 * M_panels[19] * t26 + T(36) * t25 * M_panels[14] * t29 + T(84) * t31 * M_panels[18] * t27 + T(84) * t30 * M_panels[15] * t28 + M_panels[12] * t35 + T(126) * t36 * M_panels[16] * t38 + T(126) * t37 * M_panels[17] * t33 + T(9) * delta_tau * M_panels[13] * t34 + t40 * M_panels[21] - t42 * t41 * ab_ap;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t43 = sqrt(cross_cross);
    const T t44 = T(1) / t43;
    const T J2 = t44 * atan2(t43, ap_bp);
    const T t45 = delta_tau * delta_tau;
    const T t46 = t45 * t45;
    const T t47 = T(1) / ab_ab;
    const T t48 = T(1) / cross_cross;
    const T t49 = T(1) / bp_bp;
    const T t50 = ab_ab * J2 + ab_ap * t3 + t49 * a_minus_b;
    const T t51 = t49 * t49;
    const T t52 = t3 * t3;
    const T t53 = T(3) * ab_ab * t50 * t48 + T(2) * t51 * a_minus_b + T(2) * ab_ap * t52;
    const T t54 = t52 * t3;
    const T t55 = t51 * t49;
    const T t56 = T(8) * t55 * a_minus_b + T(5) * ab_ab * t48 * t53 + T(8) * ab_ap * t54;
    const T t57 = T(8) * t54 + t48 * ab_ap * t56 - T(8) * t55;
    const T t58 = T(6) * t48 * t53 + T(2) * t57 * t47 * ab_ap - t48 * t56 * ap_ap;
    const T t59 = t51 * t51;
    const T t60 = t52 * t52;
    const T t61 = T(7) * ab_ab * t48 * t56 + T(48) * t59 * a_minus_b + T(48) * ab_ap * t60;
    const T t62 = T(48) * t60 + t48 * ab_ap * t61 - T(48) * t59;
    const T t63 = t48 * t61 * ap_ap - T(8) * t48 * t56 - T(2) * t47 * ab_ap * t62;
    const T t64 = t47 * ap_ap * t62 + T(2) * t47 * ab_ap * t63 - T(8) * t57 * t47;
    const T t65 = T(8) * t47 * t58 + t47 * ap_ap * t63 - T(2) * t47 * ab_ap * t64;
    const T t66 = tau_lo * tau_lo;
    const T t67 = t66 * t66;
    const T t68 = t67 * tau_lo;
    const T t69 = t67 * t67;
    const T t70 = t46 * t46;
    const T t71 = t70 * delta_tau;
    const T t72 = t49 - t50 * t48 * ab_ap - t3;
    const T t73 = T(2) * t72 * t47 * ab_ap + t50 * t48 * ap_ap - T(2) * J2;
    const T t74 = T(2) * t52 + t48 * ab_ap * t53 - T(2) * t51;
    const T t75 = T(2) * t47 * ab_ap * t74 + T(4) * t50 * t48 - t48 * t53 * ap_ap;
    const T t76 = t47 * t74 * ap_ap + T(4) * t72 * t47 - T(2) * t47 * t75 * ab_ap;
    const T t77 = t47 * t75 * ap_ap + T(4) * t47 * t73 + T(2) * t47 * ab_ap * t76;
    const T t78 = T(6) * t47 * t74 + T(2) * t47 * ab_ap * t58 - t57 * t47 * ap_ap;
    const T t79 = T(6) * t47 * t75 + T(2) * t47 * ab_ap * t78 - t47 * t58 * ap_ap;
    const T t80 = T(6) * t47 * t76 + t47 * t78 * ap_ap - T(2) * t47 * ab_ap * t79;
    const T t81 = T(6) * t47 * t77 + t47 * ap_ap * t79 + T(2) * t47 * t80 * ab_ap;
    const T t82 = T(8) * t47 * t78 + T(2) * t47 * t65 * ab_ap + t47 * ap_ap * t64;
    const T t83 = T(8) * t47 * t79 + T(2) * t47 * ab_ap * t82 - t47 * t65 * ap_ap;
    const T t84 = T(8) * t47 * t80 + t47 * ap_ap * t82 - T(2) * t47 * ab_ap * t83;
    const T t85 = T(8) * t47 * t81 + T(2) * t47 * ab_ap * t84 + t47 * ap_ap * t83;
    const T t86 = t46 * delta_tau;
    const T t87 = t69 * tau_lo;
    const T t88 = t45 * delta_tau;
    const T t89 = t88 * t88;
    const T t90 = t66 * tau_lo;
    const T t91 = t90 * t90;
    const T t92 = t91 * tau_lo;
    const T t93 = t89 * delta_tau;
    F = (T(21) / T(64)) * t46 * t47 * t65 * t68 + (T(3) / T(128)) * delta_tau * t47 * t62 * t69 + (T(1) / T(384)) * t71 * t47 * (T(8) * t47 * (T(6) * t47 * (T(4) * t47 * (t72 * t47 * ap_ap + t47 * (T(2) * ab_ap * J2 + log_ratio) - T(2) * t47 * t73 * ab_ap) + t47 * ap_ap * t76 - T(2) * t47 * ab_ap * t77) + t47 * t80 * ap_ap - T(2) * t47 * ab_ap * t81) + t47 * t84 * ap_ap - T(2) * t47 * t85 * ab_ap) + (T(21) / T(64)) * t86 * t47 * t82 * t67 + (T(1) / T(384)) * t48 * t61 * t87 + (T(7) / T(32)) * t89 * t47 * t83 * t90 - (T(3) / T(32)) * t45 * t47 * t63 * t92 - (T(3) / T(128)) * t70 * t47 * t85 * tau_lo - (T(7) / T(32)) * t88 * t47 * t64 * t91 - (T(3) / T(32)) * t93 * t47 * t84 * t66;
    const T t94 = t60 * t3;
    const T t95 = t59 * t49;
    const T t96 = T(128) * ab_ap * t94 + T(3) * ab_ab * t48 * t61 + T(128) * t95 * a_minus_b;
    const T t97 = T(128) * t94 + t48 * ab_ap * t96 - T(128) * t95;
    const T t98 = T(10) * t48 * t61 + T(6) * t47 * ab_ap * t97 - T(3) * t48 * t96 * ap_ap;
    const T t99 = T(10) * t47 * t62 + T(2) * t47 * t98 * ab_ap - T(3) * t47 * t97 * ap_ap;
    const T t100 = t47 * t98 * ap_ap + T(10) * t47 * t63 - T(2) * t47 * ab_ap * t99;
    const T t101 = T(2) * t47 * t100 * ab_ap + T(10) * t47 * t64 + t47 * ap_ap * t99;
    const T t102 = T(2) * t47 * ab_ap * t101 - T(10) * t47 * t65 - t47 * t100 * ap_ap;
    const T t103 = T(10) * t47 * t82 + t47 * t101 * ap_ap - T(2) * t102 * t47 * ab_ap;
    const T t104 = T(10) * t47 * t83 + t102 * t47 * ap_ap + T(2) * t47 * t103 * ab_ap;
    G_ap = (T(7) / T(320)) * t88 * t47 * t99 * t91 + (T(9) / T(1280)) * delta_tau * t47 * t97 * t69 + (T(3) / T(320)) * t45 * t47 * t98 * t92 + (T(1) / T(1280)) * t48 * t96 * t87 + (T(3) / T(1280)) * t70 * t47 * t104 * tau_lo + (T(3) / T(320)) * t93 * t47 * t103 * t66 - (T(7) / T(320)) * t89 * t102 * t47 * t90 - (T(21) / T(640)) * t46 * t47 * t100 * t68 - (T(21) / T(640)) * t86 * t47 * t101 * t67 - (T(1) / T(3840)) * t71 * t47 * (T(10) * t47 * t84 + t47 * t103 * ap_ap - T(2) * t47 * t104 * ab_ap);
    G_E = -(T(1) / T(1280)) * t47 * (T(168) * t46 * t47 * t64 * t68 + T(128) * t95 * (t71 + T(126) * t86 * t67 + T(126) * t46 * t68 + T(84) * t89 * t90 + T(36) * t93 * t66 + T(36) * t45 * t92 + T(9) * delta_tau * t69 + t87 + T(84) * t88 * t91 + T(9) * t70 * tau_lo) + T(84) * t88 * t47 * t63 * t91 + T(24) * t70 * t47 * t84 * tau_lo + T(3) * t71 * t47 * t85 - T(84) * t93 * t47 * t83 * t66 - T(24) * t45 * t47 * t62 * t92 - T(3) * delta_tau * t48 * t61 * t69 - T(210) * t86 * t47 * t65 * t67 - T(128) * t94 * t87 - T(168) * t89 * t47 * t82 * t90);
  }
  const T t105 = in.sigma * in.sigma;
  const T t106 = t105 * t105;
  const T t107 = t106 * in.sigma;
  const T t108 = t107 * t107;
  const T g_factor = -T(10) * length * t108;
  f = length * t108 * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

}  // namespace skelconv::generated
