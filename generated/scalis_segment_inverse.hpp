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

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 35 +, 48 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 54175 +, 68226 ×, 20003 /, 541 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + M_panels[0] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = M_panels[0] * tau_lo + M_panels[1] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T J2 = atan2(t4, ap_bp) / t4;
    const T log_ratio = log(bp_bp / ap_ap);
    F = (T(1) / T(2)) * delta_tau * (log_ratio + T(2) * ab_ap * J2) / ab_ab + tau_lo * J2;
  }
  f = length * in.sigma * in.sigma * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 47 +, 75 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 43604 +, 58835 ×, 10054 /, 272 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = -t2 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = -t2 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    G_ap = t6;
    const T t7 = T(1) / ab_ab;
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - t7 * t6 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    G_ap = M_panels[3] * tau_lo + delta_tau * M_panels[4];
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * tau_lo;
    const T t10 = T(1) / bp_bp;
    const T t11 = T(1) / ab_ab;
    G_E = (T(1) / T(2)) * (M_panels[0] * delta_tau + t9 - (delta_tau + tau_lo) * t10) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / ap_ap;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * a_minus_b + ab_ab * J2 + t15 * ab_ap;
    const T t18 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * delta_tau * t14 * (t15 + t17 * t18 * ab_ap - t16) + (T(1) / T(2)) * tau_lo * t17 * t18;
    const T t19 = t15 * tau_lo;
    G_E = (T(1) / T(2)) * (delta_tau * J2 + t19 - (delta_tau + tau_lo) * t16) * t14;
  }
  const T g_factor = -T(2) * in.sigma * in.sigma * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 49 +, 84 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 43605 +, 58839 ×, 10054 /, 272 sqrt, 0 atan, 0 log/asinh.
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
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * t2;
    foot2 = t2 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = delta_tau * M_panels[1] + tau_lo * M_panels[0];
    const T t6 = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ap = t6;
    const T t7 = T(1) / ab_ab;
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - t7 * t6 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    F = tau_lo * M_panels[0] + delta_tau * M_panels[1];
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    const T t8 = T(1) / ab_ab;
    const T t9 = T(1) / ap_ap;
    const T t10 = tau_lo + delta_tau;
    const T t11 = T(1) / bp_bp;
    G_E = (T(1) / T(2)) * t8 * (delta_tau * M_panels[0] + tau_lo * t9 - t10 * t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t14);
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(2)) * delta_tau * t15 * (log_ratio + T(2) * ab_ap * J2) + tau_lo * J2;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = ab_ap * t14 + t17 * a_minus_b + ab_ab * J2;
    G_ap = (T(1) / T(2)) * tau_lo * t16 * t18 + (T(1) / T(2)) * (t14 + t16 * ab_ap * t18 - t17) * delta_tau * t15;
    const T t19 = tau_lo + delta_tau;
    G_E = -(T(1) / T(2)) * t15 * (t19 * t17 - delta_tau * J2 - tau_lo * t14);
  }
  const T t20 = in.sigma * in.sigma;
  const T g_factor = -T(2) * length * t20;
  f = F * length * t20;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 39 +, 66 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 41670 +, 61916 ×, 13372 /, 5789 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
    const T t3 = a_minus_b * r0;
    X = length * t2 * (t3 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = (a_minus_b - ab_ap) * length / (t4 - r1 * ab_ap);
  }
  const T t5 = T(1) / length;
  const T J1 = t5 * asinh(X);
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = tau_lo * tau_lo;
    const T t10 = delta_tau * delta_tau;
    F = t9 * M_panels[0] + T(2) * delta_tau * M_panels[1] * tau_lo + t10 * M_panels[2];
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = delta_tau * delta_tau;
    F = t11 * M_panels[0] + t12 * M_panels[2] + T(2) * delta_tau * tau_lo * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / r0;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r1;
    const T t17 = t16 * a_minus_b + t14 * ab_ap;
    const T t18 = t14 + t15 * ab_ap * t17 - t16;
    const T t19 = tau_lo * tau_lo;
    const T t20 = delta_tau * delta_tau;
    F = T(2) * delta_tau * tau_lo * t13 * t18 + t19 * t15 * t17 - t20 * t13 * (ap_ap * t15 * t17 - J1 - T(2) * t13 * t18 * ab_ap);
  }
  const T t21 = in.sigma * in.sigma;
  const T t22 = t21 * in.sigma;
  f = F * length * t22;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 53 +, 109 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 41505 +, 63534 ×, 8056 /, 3490 sqrt, 0 atan, 0 log/asinh.
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - ab_ap * t1 * ab0;
    foot1 = ap1 - ab_ap * t1 * ab1;
    foot2 = ap2 - ab_ap * ab2 * t1;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -t2 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = -t2 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = delta_tau * delta_tau;
    const T t8 = T(2) * M_panels[5] * delta_tau * tau_lo + t6 * M_panels[4] + t7 * M_panels[6];
    G_ap = t8;
    const T t9 = T(1) / ab_ab;
    G_E = T(2) * delta_tau * M_panels[6] * tau_lo + M_panels[5] * t6 + t7 * M_panels[7] - ab_ap * t8 * t9;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t10 = delta_tau * delta_tau;
    const T t11 = tau_lo * tau_lo;
    G_ap = M_panels[6] * t10 + T(2) * delta_tau * tau_lo * M_panels[5] + M_panels[4] * t11;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t14 * t11;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / ab_ab;
    G_E = (T(1) / T(3)) * (t15 + T(2) * M_panels[1] * t10 + T(2) * M_panels[0] * delta_tau * tau_lo - t18 * (t10 + t11 + T(2) * delta_tau * tau_lo)) * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = tau_lo * tau_lo;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = T(1) / r1;
    const T t24 = t23 * a_minus_b + ab_ap * t21;
    const T t25 = T(1) / cross_cross;
    const T t26 = t23 * t23;
    const T t27 = ab_ap * t21 * t22 + T(2) * t24 * ab_ab * t25 + t26 * t23 * a_minus_b;
    const T t28 = delta_tau * delta_tau;
    const T t29 = t26 * t23 - t21 * t22 - ab_ap * t27 * t25;
    const T t30 = T(1) / ab_ab;
    G_ap = (T(1) / T(3)) * t20 * t27 * t25 - (T(1) / T(3)) * t28 * (ap_ap * t27 * t25 + T(2) * ab_ap * t29 * t30 - T(3) * t24 * t25) * t30 - (T(2) / T(3)) * t29 * delta_tau * tau_lo * t30;
    const T t31 = t21 * t21;
    const T t32 = t31 * t21;
    const T t33 = t32 * t20;
    const T t34 = t23 * t23;
    const T t35 = t34 * t23;
    G_E = (T(1) / T(3)) * t30 * (t33 + T(2) * t28 * t30 * (t21 + ab_ap * t24 * t25 - t23) + T(2) * t24 * delta_tau * tau_lo * t25 - t35 * (t28 + t20 + T(2) * delta_tau * tau_lo));
  }
  const T t36 = in.sigma * in.sigma;
  const T t37 = t36 * in.sigma;
  const T g_factor = -T(3) * length * t37;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 58 +, 130 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 41508 +, 63547 ×, 8058 /, 3490 sqrt, 0 atan, 1 log/asinh.
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
    foot0 = t2 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -t2 * (exact_cross[0] * ab2 - ab0 * exact_cross[2]);
    foot2 = (exact_cross[0] * ab1 - ab0 * exact_cross[1]) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = ab_ap * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r1 * ab_ap;
    const T t5 = T(1) / cross_cross;
    X = (t4 + a_minus_b * r0) * t5 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t6 - a_minus_b * r0);
  }
  const T t7 = T(1) / length;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = delta_tau * delta_tau;
    F = t11 * M_panels[0] + T(2) * M_panels[1] * delta_tau * tau_lo + M_panels[2] * t12;
    const T t13 = T(2) * M_panels[5] * delta_tau * tau_lo + M_panels[4] * t11 + t12 * M_panels[6];
    G_ap = t13;
    const T t14 = T(1) / ab_ab;
    G_E = M_panels[7] * t12 + T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[5] * t11 - t13 * ab_ap * t14;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t15 = tau_lo * tau_lo;
    const T t16 = delta_tau * delta_tau;
    F = T(2) * delta_tau * tau_lo * M_panels[1] + M_panels[0] * t15 + M_panels[2] * t16;
    G_ap = t15 * M_panels[4] + M_panels[6] * t16 + T(2) * M_panels[5] * delta_tau * tau_lo;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t15;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / ab_ab;
    G_E = (T(1) / T(3)) * (t20 + T(2) * M_panels[0] * delta_tau * tau_lo + T(2) * t16 * M_panels[1] - t23 * (t16 + T(2) * delta_tau * tau_lo + t15)) * t24;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / r1;
    const T t27 = T(1) / r0;
    const T t28 = t26 * a_minus_b + ab_ap * t27;
    const T t29 = tau_lo * tau_lo;
    const T t30 = t25 * ab_ap * t28 + t27 - t26;
    const T t31 = T(1) / ab_ab;
    const T t32 = delta_tau * delta_tau;
    F = t25 * t28 * t29 + T(2) * t30 * delta_tau * tau_lo * t31 + (T(2) * ab_ap * t30 * t31 + J1 - t25 * ap_ap * t28) * t32 * t31;
    const T t33 = t27 * t27;
    const T t34 = t26 * t26;
    const T t35 = ab_ap * t33 * t27 + T(2) * t25 * t28 * ab_ab + t26 * t34 * a_minus_b;
    const T t36 = t26 * t34 - t33 * t27 - t35 * t25 * ab_ap;
    G_ap = (T(1) / T(3)) * t35 * t25 * t29 - (T(2) / T(3)) * t36 * delta_tau * tau_lo * t31 - (T(1) / T(3)) * t32 * t31 * (T(2) * ab_ap * t36 * t31 + t35 * t25 * ap_ap - T(3) * t25 * t28);
    const T t37 = t27 * t27;
    const T t38 = t37 * t27;
    const T t39 = t38 * t29;
    const T t40 = t26 * t26;
    const T t41 = t40 * t26;
    G_E = (T(1) / T(3)) * (t39 + T(2) * t30 * t32 * t31 + T(2) * t25 * t28 * delta_tau * tau_lo - t41 * (t32 + T(2) * delta_tau * tau_lo + t29)) * t31;
  }
  const T t42 = in.sigma * in.sigma;
  const T t43 = t42 * in.sigma;
  const T g_factor = -T(3) * length * t43;
  f = length * t43 * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 45 +, 83 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 35437 +, 46583 ×, 10050 /, 272 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    F = t5 * M_panels[3] + t7 * M_panels[0] + T(3) * tau_lo * t4 * M_panels[2] + T(3) * t6 * delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t8 = delta_tau * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t8 * delta_tau;
    const T t11 = t9 * tau_lo;
    F = T(3) * tau_lo * t8 * M_panels[2] + T(3) * t9 * delta_tau * M_panels[1] + t10 * M_panels[3] + t11 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t14);
    const T t15 = tau_lo * tau_lo;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(1) / bp_bp;
    const T t18 = ab_ab * J2 + a_minus_b * t17 + ab_ap * t14;
    const T t19 = T(1) / cross_cross;
    const T t20 = t14 + t18 * ab_ap * t19 - t17;
    const T t21 = t15 * tau_lo;
    const T t22 = T(2) * J2 + T(2) * t16 * ab_ap * t20 - t18 * t19 * ap_ap;
    const T t23 = delta_tau * delta_tau;
    const T t24 = t23 * delta_tau;
    F = (T(3) / T(2)) * t15 * delta_tau * t16 * t20 + (T(1) / T(2)) * t21 * t18 * t19 + (T(3) / T(2)) * tau_lo * t22 * t23 * t16 - (T(1) / T(2)) * t24 * (t16 * t20 * ap_ap - t16 * (log_ratio + T(2) * J2 * ab_ap) - T(2) * t22 * t16 * ab_ap) * t16;
  }
  const T t25 = in.sigma * in.sigma;
  const T t26 = t25 * t25;
  f = length * t26 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 63 +, 137 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 40130 +, 53069 ×, 6724 /, 182 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
    foot2 = t2 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * tau_lo;
    const T t9 = t6 * delta_tau;
    const T t10 = T(3) * tau_lo * M_panels[7] * t6 + t8 * M_panels[5] + M_panels[8] * t9 + T(3) * t7 * M_panels[6] * delta_tau;
    G_ap = t10;
    const T t11 = T(1) / ab_ab;
    G_E = t8 * M_panels[6] + T(3) * tau_lo * M_panels[8] * t6 + M_panels[9] * t9 + T(3) * t7 * M_panels[7] * delta_tau - t11 * ab_ap * t10;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = delta_tau * delta_tau;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * tau_lo;
    const T t15 = t12 * delta_tau;
    G_ap = T(3) * tau_lo * M_panels[7] * t12 + t14 * M_panels[5] + T(3) * t13 * M_panels[6] * delta_tau + M_panels[8] * t15;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = T(3) * t13 * delta_tau + t14 + T(3) * tau_lo * t12 + t15;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    G_E = (T(1) / T(4)) * t16 * (t14 * t18 + T(6) * tau_lo * M_panels[1] * t12 + T(3) * t13 * M_panels[0] * delta_tau + T(3) * M_panels[2] * t15 - t19 * t21);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(cross_cross);
    const T t23 = T(1) / t22;
    const T J2 = t23 * atan2(t22, ap_bp);
    const T t24 = T(1) / ap_ap;
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / bp_bp;
    const T t27 = ab_ab * J2 + ab_ap * t24 + a_minus_b * t26;
    const T t28 = t24 + t25 * ab_ap * t27 - t26;
    const T t29 = T(1) / ab_ab;
    const T t30 = t26 * t26;
    const T t31 = t24 * t24;
    const T t32 = T(2) * a_minus_b * t30 + T(2) * ab_ap * t31 + T(3) * ab_ab * t25 * t27;
    const T t33 = T(2) * t30 - t32 * t25 * ab_ap - T(2) * t31;
    const T t34 = T(2) * t33 * t29 * ab_ap + t32 * t25 * ap_ap - T(4) * t25 * t27;
    const T t35 = delta_tau * delta_tau;
    const T t36 = t35 * delta_tau;
    const T t37 = tau_lo * tau_lo;
    const T t38 = t37 * tau_lo;
    G_ap = (T(1) / T(8)) * (T(4) * t28 * t29 + t33 * t29 * ap_ap - T(2) * t29 * t34 * ab_ap) * t29 * t36 + (T(1) / T(8)) * t38 * t32 * t25 - (T(3) / T(8)) * tau_lo * t29 * t34 * t35 - (T(3) / T(8)) * t33 * t37 * t29 * delta_tau;
    const T t39 = T(3) * t37 * delta_tau + t38 + T(3) * tau_lo * t35 + t36;
    G_E = (T(1) / T(8)) * t29 * (T(2) * t38 * t31 + T(3) * t37 * t25 * t27 * delta_tau + T(6) * tau_lo * t28 * t29 * t35 - T(3) * t29 * t36 * (t25 * ap_ap * t27 - T(2) * J2 - T(2) * t28 * t29 * ab_ap) - T(2) * t39 * t30);
  }
  const T t40 = in.sigma * in.sigma;
  const T t41 = t40 * t40;
  const T g_factor = -T(4) * length * t41;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 69 +, 162 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 40133 +, 53079 ×, 6724 /, 182 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
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
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * t2;
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = tau_lo * tau_lo;
    const T t8 = t7 * tau_lo;
    const T t9 = t6 * delta_tau;
    F = T(3) * t6 * tau_lo * M_panels[2] + t8 * M_panels[0] + t9 * M_panels[3] + T(3) * M_panels[1] * delta_tau * t7;
    const T t10 = T(3) * t6 * tau_lo * M_panels[7] + M_panels[8] * t9 + T(3) * delta_tau * t7 * M_panels[6] + M_panels[5] * t8;
    G_ap = t10;
    const T t11 = T(1) / ab_ab;
    G_E = T(3) * delta_tau * t7 * M_panels[7] + t9 * M_panels[9] + T(3) * M_panels[8] * t6 * tau_lo + t8 * M_panels[6] - t10 * t11 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = tau_lo * tau_lo;
    const T t13 = t12 * tau_lo;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * delta_tau;
    F = t13 * M_panels[0] + t15 * M_panels[3] + T(3) * delta_tau * M_panels[1] * t12 + T(3) * t14 * tau_lo * M_panels[2];
    G_ap = t13 * M_panels[5] + t15 * M_panels[8] + T(3) * delta_tau * t12 * M_panels[6] + T(3) * M_panels[7] * t14 * tau_lo;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = T(3) * t14 * tau_lo + t13 + t15 + T(3) * delta_tau * t12;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    G_E = (T(1) / T(4)) * t16 * (t18 * t13 + T(3) * delta_tau * t12 * M_panels[0] + T(6) * t14 * M_panels[1] * tau_lo + T(3) * t15 * M_panels[2] - t19 * t21);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(cross_cross);
    const T t23 = T(1) / t22;
    const T J2 = t23 * atan2(t22, ap_bp);
    const T t24 = T(1) / ap_ap;
    const T log_ratio = log(t24 * bp_bp);
    const T t25 = delta_tau * delta_tau;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(1) / bp_bp;
    const T t28 = J2 * ab_ab + t24 * ab_ap + a_minus_b * t27;
    const T t29 = T(1) / cross_cross;
    const T t30 = t28 * t29 * ab_ap + t24 - t27;
    const T t31 = T(2) * J2 + T(2) * t26 * t30 * ab_ap - ap_ap * t28 * t29;
    const T t32 = tau_lo * tau_lo;
    const T t33 = t32 * tau_lo;
    const T t34 = t25 * delta_tau;
    F = (T(3) / T(2)) * t25 * tau_lo * t31 * t26 + (T(1) / T(2)) * t33 * t28 * t29 + (T(3) / T(2)) * delta_tau * t32 * t26 * t30 - (T(1) / T(2)) * t34 * t26 * (ap_ap * t26 * t30 - T(2) * t31 * t26 * ab_ap - t26 * (T(2) * J2 * ab_ap + log_ratio));
    const T t35 = t24 * t24;
    const T t36 = t27 * t27;
    const T t37 = T(3) * t28 * ab_ab * t29 + T(2) * a_minus_b * t36 + T(2) * t35 * ab_ap;
    const T t38 = T(2) * t35 + t29 * ab_ap * t37 - T(2) * t36;
    const T t39 = ap_ap * t29 * t37 - T(4) * t28 * t29 - T(2) * t38 * t26 * ab_ap;
    G_ap = (T(1) / T(8)) * (T(4) * t26 * t30 - ap_ap * t38 * t26 - T(2) * t26 * t39 * ab_ap) * t34 * t26 + (T(1) / T(8)) * t33 * t29 * t37 + (T(3) / T(8)) * t38 * delta_tau * t32 * t26 - (T(3) / T(8)) * t25 * tau_lo * t26 * t39;
    const T t40 = T(3) * t25 * tau_lo + t33 + t34 + T(3) * delta_tau * t32;
    G_E = (T(1) / T(8)) * t26 * (T(2) * t35 * t33 + T(6) * t25 * tau_lo * t26 * t30 + T(3) * delta_tau * t32 * t28 * t29 + T(3) * t34 * t31 * t26 - T(2) * t40 * t36);
  }
  const T t41 = in.sigma * in.sigma;
  const T t42 = t41 * t41;
  const T g_factor = -T(4) * length * t42;
  f = F * length * t42;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 51 +, 115 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 31687 +, 50438 ×, 8054 /, 3490 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
    const T t3 = a_minus_b * r0;
    X = length * t2 * (t3 + ab_ap * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t4 - ab_ap * r1);
  }
  const T t5 = T(1) / length;
  const T J1 = t5 * asinh(X);
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * tau_lo;
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t11 * delta_tau;
    const T t14 = t9 * t9;
    F = T(4) * t10 * delta_tau * M_panels[1] + M_panels[4] * t12 + T(4) * tau_lo * t13 * M_panels[3] + T(6) * t9 * t11 * M_panels[2] + t14 * M_panels[0];
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t15 = delta_tau * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t15 * delta_tau;
    const T t18 = tau_lo * tau_lo;
    const T t19 = t18 * tau_lo;
    const T t20 = t18 * t18;
    F = t16 * M_panels[4] + T(4) * tau_lo * t17 * M_panels[3] + T(4) * t19 * delta_tau * M_panels[1] + T(6) * t18 * t15 * M_panels[2] + t20 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = tau_lo * tau_lo;
    const T t22 = t21 * tau_lo;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = T(1) / cross_cross;
    const T t29 = a_minus_b * t26 + t24 * ab_ap;
    const T t30 = a_minus_b * t27 * t26 + t24 * ab_ap * t25 + T(2) * ab_ab * t28 * t29;
    const T t31 = t24 * t25 + t30 * t28 * ab_ap - t27 * t26;
    const T t32 = delta_tau * delta_tau;
    const T t33 = t32 * t32;
    const T t34 = t28 * ab_ap * t29 + t24 - t26;
    const T t35 = t30 * t28 * ap_ap - T(3) * t28 * t29 - T(2) * t23 * ab_ap * t31;
    const T t36 = t23 * t31 * ap_ap + T(2) * t35 * t23 * ab_ap - T(3) * t23 * t34;
    const T t37 = t21 * t21;
    const T t38 = t32 * delta_tau;
    F = (T(4) / T(3)) * t22 * delta_tau * t23 * t31 + (T(1) / T(3)) * t33 * t23 * (T(3) * t23 * (T(2) * t23 * ab_ap * t34 + J1 - t28 * ap_ap * t29) + t35 * t23 * ap_ap - T(2) * t23 * t36 * ab_ap) + (T(1) / T(3)) * t37 * t30 * t28 - T(2) * t21 * t32 * t35 * t23 - (T(4) / T(3)) * tau_lo * t38 * t23 * t36;
  }
  const T t39 = in.sigma * in.sigma;
  const T t40 = t39 * t39;
  const T t41 = t40 * in.sigma;
  f = length * t41 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 71 +, 183 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 50941 +, 78061 ×, 7249 /, 3239 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - exact_cross[2] * ab1) * t2;
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * t2;
    foot2 = -t2 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * delta_tau;
    const T t10 = t8 * t8;
    const T t11 = t6 * t6;
    const T t12 = T(4) * t7 * delta_tau * M_panels[7] + T(4) * M_panels[9] * tau_lo * t9 + t10 * M_panels[10] + M_panels[6] * t11 + T(6) * t6 * t8 * M_panels[8];
    G_ap = t12;
    const T t13 = T(1) / ab_ab;
    G_E = t10 * M_panels[11] + t11 * M_panels[7] + T(6) * M_panels[9] * t6 * t8 + T(4) * t7 * delta_tau * M_panels[8] + T(4) * tau_lo * t9 * M_panels[10] - t13 * ab_ap * t12;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t14 = tau_lo * tau_lo;
    const T t15 = t14 * tau_lo;
    const T t16 = t14 * t14;
    const T t17 = delta_tau * delta_tau;
    const T t18 = t17 * delta_tau;
    const T t19 = t17 * t17;
    G_ap = T(4) * M_panels[7] * t15 * delta_tau + t16 * M_panels[6] + T(4) * tau_lo * t18 * M_panels[9] + M_panels[10] * t19 + T(6) * t14 * t17 * M_panels[8];
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t20;
    const T t24 = T(4) * tau_lo * t18 + t19 + t16 + T(6) * t14 * t17 + T(4) * t15 * delta_tau;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t25;
    const T t29 = T(1) / ab_ab;
    G_E = (T(1) / T(5)) * (T(12) * t14 * t17 * M_panels[1] + t16 * t23 + T(12) * tau_lo * t18 * M_panels[2] + T(4) * t19 * M_panels[3] + T(4) * M_panels[0] * t15 * delta_tau - t24 * t28) * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = delta_tau * delta_tau;
    const T t31 = t30 * delta_tau;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = T(1) / r1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = T(1) / cross_cross;
    const T t40 = ab_ap * t33 + t36 * a_minus_b;
    const T t41 = t36 * a_minus_b * t37 + ab_ap * t34 * t33 + T(2) * ab_ab * t39 * t40;
    const T t42 = T(3) * ab_ap * t35 * t33 + T(3) * t36 * a_minus_b * t38 + T(4) * ab_ab * t39 * t41;
    const T t43 = T(3) * t35 * t33 + t42 * t39 * ab_ap - T(3) * t36 * t38;
    const T t44 = T(2) * t32 * t43 * ab_ap + T(5) * t39 * t41 - t42 * t39 * ap_ap;
    const T t45 = t36 * t37 - t34 * t33 - t39 * ab_ap * t41;
    const T t46 = T(2) * t32 * t44 * ab_ap - t32 * t43 * ap_ap - T(5) * t32 * t45;
    const T t47 = tau_lo * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t47 * tau_lo;
    const T t50 = t30 * t30;
    const T t51 = t39 * t41 * ap_ap + T(2) * t32 * t45 * ab_ap - T(3) * t39 * t40;
    G_ap = (T(4) / T(15)) * tau_lo * t31 * t32 * t46 + (T(2) / T(5)) * t47 * t30 * t32 * t44 + (T(1) / T(15)) * t42 * t48 * t39 + (T(4) / T(15)) * t49 * delta_tau * t32 * t43 - (T(1) / T(15)) * t50 * t32 * (T(5) * t32 * t51 + t32 * t44 * ap_ap - T(2) * t32 * ab_ap * t46);
    const T t52 = t33 * t33;
    const T t53 = t52 * t52;
    const T t54 = t53 * t33;
    const T t55 = T(4) * tau_lo * t31 + t50 + t48 + T(6) * t47 * t30 + T(4) * t49 * delta_tau;
    const T t56 = t36 * t36;
    const T t57 = t56 * t56;
    const T t58 = t57 * t36;
    G_E = (T(1) / T(15)) * t32 * (T(3) * t48 * t54 + T(4) * t49 * delta_tau * t39 * t41 + T(4) * t50 * t32 * (t32 * t45 * ap_ap + T(3) * t32 * (t39 * ab_ap * t40 + t33 - t36) - T(2) * t32 * t51 * ab_ap) - T(12) * tau_lo * t31 * t32 * t51 - T(12) * t47 * t30 * t32 * t45 - T(3) * t55 * t58);
  }
  const T t59 = in.sigma * in.sigma;
  const T t60 = t59 * t59;
  const T t61 = t60 * in.sigma;
  const T g_factor = -T(5) * length * t61;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 80 +, 221 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 50946 +, 78080 ×, 7251 /, 3239 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab1 * ab_ap * t1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * t2;
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
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
    X = t4 * (t5 + a_minus_b * r0) * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t6 - a_minus_b * r0);
  }
  const T t7 = T(1) / length;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * tau_lo;
    const T t15 = t13 * t13;
    const T t16 = t11 * delta_tau;
    F = M_panels[4] * t12 + T(4) * M_panels[1] * delta_tau * t14 + T(6) * t11 * M_panels[2] * t13 + M_panels[0] * t15 + T(4) * M_panels[3] * t16 * tau_lo;
    const T t17 = T(4) * M_panels[9] * t16 * tau_lo + M_panels[10] * t12 + T(6) * M_panels[8] * t11 * t13 + M_panels[6] * t15 + T(4) * M_panels[7] * delta_tau * t14;
    G_ap = t17;
    const T t18 = T(1) / ab_ab;
    G_E = T(6) * M_panels[9] * t11 * t13 + T(4) * M_panels[8] * delta_tau * t14 + M_panels[7] * t15 + M_panels[11] * t12 + T(4) * M_panels[10] * t16 * tau_lo - ab_ap * t17 * t18;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t19 = delta_tau * delta_tau;
    const T t20 = tau_lo * tau_lo;
    const T t21 = t19 * delta_tau;
    const T t22 = t19 * t19;
    const T t23 = t20 * t20;
    const T t24 = t20 * tau_lo;
    F = T(6) * M_panels[2] * t19 * t20 + T(4) * t21 * tau_lo * M_panels[3] + M_panels[4] * t22 + t23 * M_panels[0] + T(4) * M_panels[1] * delta_tau * t24;
    G_ap = M_panels[6] * t23 + T(4) * M_panels[7] * delta_tau * t24 + M_panels[10] * t22 + T(4) * t21 * tau_lo * M_panels[9] + T(6) * M_panels[8] * t19 * t20;
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t25;
    const T t29 = T(1) / r1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t31 * t29;
    const T t33 = T(6) * t19 * t20 + T(4) * t21 * tau_lo + t22 + t23 + T(4) * delta_tau * t24;
    const T t34 = T(1) / ab_ab;
    G_E = (T(1) / T(5)) * (T(12) * M_panels[1] * t19 * t20 + T(4) * delta_tau * t24 * M_panels[0] + T(12) * M_panels[2] * t21 * tau_lo + T(4) * t22 * M_panels[3] + t23 * t28 - t32 * t33) * t34;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = T(1) / r0;
    const T t36 = T(1) / r1;
    const T t37 = ab_ap * t35 + t36 * a_minus_b;
    const T t38 = T(1) / cross_cross;
    const T t39 = t37 * t38 * ab_ap + t35 - t36;
    const T t40 = T(1) / ab_ab;
    const T t41 = t36 * t36;
    const T t42 = t35 * t35;
    const T t43 = T(2) * t37 * t38 * ab_ab + t36 * t41 * a_minus_b + ab_ap * t42 * t35;
    const T t44 = t38 * ab_ap * t43 + t42 * t35 - t36 * t41;
    const T t45 = t38 * ap_ap * t43 - T(2) * ab_ap * t44 * t40 - T(3) * t37 * t38;
    const T t46 = T(3) * t39 * t40 - ap_ap * t44 * t40 - T(2) * ab_ap * t45 * t40;
    const T t47 = delta_tau * delta_tau;
    const T t48 = t47 * t47;
    const T t49 = t47 * delta_tau;
    const T t50 = tau_lo * tau_lo;
    const T t51 = t50 * t50;
    const T t52 = t50 * tau_lo;
    F = (T(1) / T(3)) * (T(3) * (T(2) * ab_ap * t39 * t40 + J1 - t37 * t38 * ap_ap) * t40 + T(2) * ab_ap * t46 * t40 + ap_ap * t45 * t40) * t48 * t40 + (T(4) / T(3)) * t46 * t49 * tau_lo * t40 + (T(1) / T(3)) * t38 * t43 * t51 + (T(4) / T(3)) * t44 * delta_tau * t52 * t40 - T(2) * t45 * t47 * t50 * t40;
    const T t53 = t42 * t42;
    const T t54 = t41 * t41;
    const T t55 = T(3) * ab_ap * t53 * t35 + T(4) * t38 * t43 * ab_ab + T(3) * t36 * t54 * a_minus_b;
    const T t56 = T(3) * t53 * t35 + t38 * t55 * ab_ap - T(3) * t36 * t54;
    const T t57 = T(2) * ab_ap * t56 * t40 + T(5) * t38 * t43 - t38 * t55 * ap_ap;
    const T t58 = T(2) * t57 * ab_ap * t40 + T(5) * t44 * t40 - t56 * ap_ap * t40;
    G_ap = (T(4) / T(15)) * t58 * t49 * tau_lo * t40 + (T(4) / T(15)) * t56 * delta_tau * t52 * t40 + (T(2) / T(5)) * t57 * t47 * t50 * t40 + (T(1) / T(15)) * t38 * t55 * t51 - (T(1) / T(15)) * t48 * t40 * (t57 * ap_ap * t40 + T(5) * t45 * t40 - T(2) * t58 * ab_ap * t40);
    const T t59 = t35 * t35;
    const T t60 = t59 * t59;
    const T t61 = t60 * t35;
    const T t62 = t36 * t36;
    const T t63 = t62 * t62;
    const T t64 = t63 * t36;
    const T t65 = T(6) * t47 * t50 + T(4) * t49 * tau_lo + t48 + t51 + T(4) * delta_tau * t52;
    G_E = (T(1) / T(15)) * (T(12) * t44 * t47 * t50 * t40 + T(4) * t38 * t43 * delta_tau * t52 + T(3) * t51 * t61 + T(4) * t46 * t48 * t40 - T(3) * t64 * t65 - T(12) * t45 * t49 * tau_lo * t40) * t40;
  }
  const T t66 = in.sigma * in.sigma;
  const T t67 = t66 * t66;
  const T t68 = t67 * in.sigma;
  const T g_factor = -T(5) * length * t68;
  f = length * t68 * F;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 59 +, 137 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 37699 +, 51294 ×, 8420 /, 182 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * delta_tau;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t4 * t4;
    const T t9 = t8 * delta_tau;
    const T t10 = t6 * tau_lo;
    const T t11 = t7 * tau_lo;
    F = T(10) * M_panels[3] * t5 * t6 + T(5) * delta_tau * M_panels[1] * t7 + M_panels[5] * t9 + T(10) * M_panels[2] * t4 * t10 + T(5) * t8 * tau_lo * M_panels[4] + M_panels[0] * t11;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t12 = tau_lo * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = delta_tau * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t15 * delta_tau;
    const T t17 = t14 * delta_tau;
    const T t18 = t12 * tau_lo;
    const T t19 = t13 * tau_lo;
    F = T(5) * delta_tau * M_panels[1] * t13 + t16 * M_panels[5] + T(10) * M_panels[3] * t17 * t12 + T(5) * M_panels[4] * t15 * tau_lo + T(10) * M_panels[2] * t14 * t18 + M_panels[0] * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = t21 * atan2(t20, ap_bp);
    const T t22 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t22);
    const T t23 = T(1) / cross_cross;
    const T t24 = T(1) / bp_bp;
    const T t25 = ab_ap * t22 + t24 * a_minus_b + J2 * ab_ab;
    const T t26 = t22 * t22;
    const T t27 = t24 * t24;
    const T t28 = T(3) * t23 * t25 * ab_ab + T(2) * ab_ap * t26 + T(2) * t27 * a_minus_b;
    const T t29 = tau_lo * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t30 * tau_lo;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(2) * t26 + t23 * ab_ap * t28 - T(2) * t27;
    const T t34 = delta_tau * delta_tau;
    const T t35 = t34 * t34;
    const T t36 = t35 * delta_tau;
    const T t37 = t23 * t28 * ap_ap - T(2) * ab_ap * t32 * t33 - T(4) * t23 * t25;
    const T t38 = t24 - t22 - t23 * t25 * ab_ap;
    const T t39 = T(2) * ab_ap * t37 * t32 + T(4) * t38 * t32 + ap_ap * t32 * t33;
    const T t40 = T(2) * ab_ap * t38 * t32 + t23 * t25 * ap_ap - T(2) * J2;
    const T t41 = T(4) * t40 * t32 + T(2) * ab_ap * t39 * t32 - ap_ap * t37 * t32;
    const T t42 = t29 * tau_lo;
    const T t43 = t34 * delta_tau;
    F = (T(1) / T(8)) * t23 * t28 * t31 + (T(5) / T(8)) * delta_tau * t30 * t32 * t33 + (T(1) / T(8)) * t36 * t32 * (ap_ap * t39 * t32 + T(4) * ((log_ratio + T(2) * ab_ap * J2) * t32 + ap_ap * t38 * t32 - T(2) * ab_ap * t40 * t32) * t32 - T(2) * ab_ap * t41 * t32) - (T(5) / T(4)) * t37 * t34 * t42 * t32 - (T(5) / T(8)) * t35 * t41 * tau_lo * t32 - (T(5) / T(4)) * t43 * t39 * t29 * t32;
  }
  const T t44 = in.sigma * in.sigma;
  const T t45 = t44 * in.sigma;
  const T t46 = t45 * t45;
  f = length * t46 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 83 +, 210 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 49706 +, 65272 ×, 6309 /, 137 sqrt, 0 atan, 0 log/asinh.
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
    foot0 = ap0 - ab0 * t1 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = t2 * (ab0 * exact_cross[2] - ab2 * exact_cross[0]);
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t6 * t6;
    const T t10 = t9 * delta_tau;
    const T t11 = t8 * t8;
    const T t12 = t11 * tau_lo;
    const T t13 = t8 * tau_lo;
    const T t14 = T(10) * M_panels[10] * t7 * t8 + T(5) * M_panels[11] * t9 * tau_lo + M_panels[12] * t10 + T(5) * M_panels[8] * delta_tau * t11 + M_panels[7] * t12 + T(10) * M_panels[9] * t6 * t13;
    G_ap = t14;
    const T t15 = T(1) / ab_ab;
    G_E = M_panels[8] * t12 + T(10) * M_panels[10] * t6 * t13 + M_panels[13] * t10 + T(10) * M_panels[11] * t7 * t8 + T(5) * M_panels[12] * t9 * tau_lo + T(5) * M_panels[9] * delta_tau * t11 - t15 * ab_ap * t14;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = delta_tau * delta_tau;
    const T t17 = tau_lo * tau_lo;
    const T t18 = t17 * tau_lo;
    const T t19 = t16 * t16;
    const T t20 = t17 * t17;
    const T t21 = t16 * delta_tau;
    const T t22 = t20 * tau_lo;
    const T t23 = t19 * delta_tau;
    G_ap = T(10) * M_panels[9] * t16 * t18 + T(5) * t19 * M_panels[11] * tau_lo + T(5) * delta_tau * t20 * M_panels[8] + T(10) * M_panels[10] * t21 * t17 + M_panels[7] * t22 + M_panels[12] * t23;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t22 + T(10) * t16 * t18 + T(5) * delta_tau * t20 + T(10) * t21 * t17 + t23 + T(5) * t19 * tau_lo;
    const T t31 = T(1) / ab_ab;
    G_E = (T(1) / T(6)) * (T(20) * M_panels[1] * t16 * t18 + t26 * t22 + T(5) * M_panels[0] * delta_tau * t20 + T(5) * M_panels[4] * t23 + T(30) * M_panels[2] * t21 * t17 + T(20) * M_panels[3] * t19 * tau_lo - t29 * t30) * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t32 = sqrt(cross_cross);
    const T t33 = T(1) / t32;
    const T J2 = atan2(t32, ap_bp) * t33;
    const T t34 = T(1) / cross_cross;
    const T t35 = T(1) / ap_ap;
    const T t36 = t35 * t35;
    const T t37 = T(1) / bp_bp;
    const T t38 = ab_ab * J2 + a_minus_b * t37 + ab_ap * t35;
    const T t39 = t37 * t37;
    const T t40 = T(2) * ab_ap * t36 + T(3) * ab_ab * t34 * t38 + T(2) * a_minus_b * t39;
    const T t41 = t36 * t35;
    const T t42 = t39 * t37;
    const T t43 = T(5) * ab_ab * t34 * t40 + T(8) * ab_ap * t41 + T(8) * a_minus_b * t42;
    const T t44 = tau_lo * tau_lo;
    const T t45 = t44 * t44;
    const T t46 = t45 * tau_lo;
    const T t47 = T(1) / ab_ab;
    const T t48 = t34 * ab_ap * t43 + T(8) * t41 - T(8) * t42;
    const T t49 = delta_tau * delta_tau;
    const T t50 = t44 * tau_lo;
    const T t51 = T(6) * t34 * t40 + T(2) * t47 * ab_ap * t48 - t34 * t43 * ap_ap;
    const T t52 = t49 * t49;
    const T t53 = T(2) * t39 - T(2) * t36 - t34 * ab_ap * t40;
    const T t54 = t34 * ap_ap * t40 + T(2) * t47 * ab_ap * t53 - T(4) * t34 * t38;
    const T t55 = T(6) * t47 * t53 + t47 * ap_ap * t48 - T(2) * t47 * ab_ap * t51;
    const T t56 = T(6) * t47 * t54 + T(2) * t55 * t47 * ab_ap + t47 * ap_ap * t51;
    const T t57 = t35 + t34 * t38 * ab_ap - t37;
    const T t58 = t47 * t53 * ap_ap + T(4) * t47 * t57 - T(2) * t47 * t54 * ab_ap;
    const T t59 = t52 * delta_tau;
    const T t60 = t49 * delta_tau;
    G_ap = (T(1) / T(48)) * t34 * t43 * t46 + (T(5) / T(48)) * t47 * delta_tau * t48 * t45 + (T(5) / T(24)) * t47 * t49 * t50 * t51 - (T(5) / T(48)) * t47 * t52 * tau_lo * t56 - (T(1) / T(48)) * t47 * (T(2) * t47 * ab_ap * t56 - T(6) * t47 * t58 - t55 * t47 * ap_ap) * t59 - (T(5) / T(24)) * t55 * t47 * t60 * t44;
    const T t61 = t46 + T(10) * t49 * t50 + T(5) * delta_tau * t45 + T(10) * t60 * t44 + t59 + T(5) * t52 * tau_lo;
    G_E = -(T(1) / T(48)) * t47 * (T(30) * t47 * t54 * t60 * t44 + T(20) * t47 * t53 * t49 * t50 + T(5) * t47 * (T(4) * t47 * (t34 * t38 * ap_ap - T(2) * t47 * t57 * ab_ap - T(2) * J2) - t47 * t54 * ap_ap - T(2) * t47 * t58 * ab_ap) * t59 + T(8) * t42 * t61 - T(8) * t41 * t46 - T(20) * t47 * t58 * t52 * tau_lo - T(5) * t34 * delta_tau * t40 * t45);
  }
  const T t62 = in.sigma * in.sigma;
  const T t63 = t62 * in.sigma;
  const T t64 = t63 * t63;
  const T g_factor = -T(6) * length * t64;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 93 +, 250 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 49711 +, 65288 ×, 6309 /, 137 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab1 * ab_ap * t1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * t2;
    foot2 = t2 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * delta_tau;
    const T t11 = t9 * t9;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * tau_lo;
    F = M_panels[0] * t8 + T(5) * M_panels[1] * delta_tau * t7 + T(10) * M_panels[3] * t10 * t6 + t12 * M_panels[5] + T(10) * M_panels[2] * t9 * t13 + T(5) * M_panels[4] * t11 * tau_lo;
    const T t14 = M_panels[12] * t12 + T(5) * M_panels[8] * delta_tau * t7 + T(5) * M_panels[11] * t11 * tau_lo + T(10) * M_panels[10] * t10 * t6 + T(10) * M_panels[9] * t9 * t13 + M_panels[7] * t8;
    G_ap = t14;
    const T t15 = T(1) / ab_ab;
    G_E = T(10) * M_panels[10] * t9 * t13 + M_panels[8] * t8 + M_panels[13] * t12 + T(5) * M_panels[9] * delta_tau * t7 + T(10) * M_panels[11] * t10 * t6 + T(5) * M_panels[12] * t11 * tau_lo - ab_ap * t14 * t15;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = tau_lo * tau_lo;
    const T t19 = t18 * tau_lo;
    const T t20 = t16 * delta_tau;
    const T t21 = t18 * t18;
    const T t22 = t21 * tau_lo;
    const T t23 = t17 * delta_tau;
    F = T(5) * t17 * M_panels[4] * tau_lo + T(10) * M_panels[2] * t16 * t19 + T(10) * M_panels[3] * t20 * t18 + T(5) * delta_tau * t21 * M_panels[1] + M_panels[0] * t22 + M_panels[5] * t23;
    G_ap = t22 * M_panels[7] + T(10) * M_panels[9] * t16 * t19 + T(10) * t20 * M_panels[10] * t18 + T(5) * M_panels[8] * delta_tau * t21 + M_panels[12] * t23 + T(5) * M_panels[11] * t17 * tau_lo;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(5) * delta_tau * t21 + t22 + T(10) * t16 * t19 + t23 + T(10) * t20 * t18 + T(5) * t17 * tau_lo;
    const T t28 = T(1) / bp_bp;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = T(1) / ab_ab;
    G_E = (T(1) / T(6)) * (T(30) * M_panels[2] * t20 * t18 + T(20) * M_panels[3] * t17 * tau_lo + T(5) * M_panels[0] * delta_tau * t21 + T(5) * t23 * M_panels[4] + t26 * t22 + T(20) * t16 * t19 * M_panels[1] - t27 * t30) * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t32 = sqrt(cross_cross);
    const T t33 = T(1) / t32;
    const T J2 = t33 * atan2(t32, ap_bp);
    const T t34 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t34);
    const T t35 = t34 * t34;
    const T t36 = T(1) / cross_cross;
    const T t37 = T(1) / bp_bp;
    const T t38 = J2 * ab_ab + t37 * a_minus_b + ab_ap * t34;
    const T t39 = t37 * t37;
    const T t40 = T(3) * t38 * t36 * ab_ab + T(2) * ab_ap * t35 + T(2) * t39 * a_minus_b;
    const T t41 = T(2) * t35 + t36 * ab_ap * t40 - T(2) * t39;
    const T t42 = tau_lo * tau_lo;
    const T t43 = t42 * t42;
    const T t44 = T(1) / ab_ab;
    const T t45 = delta_tau * delta_tau;
    const T t46 = T(2) * ab_ap * t41 * t44 + T(4) * t38 * t36 - t36 * ap_ap * t40;
    const T t47 = t42 * tau_lo;
    const T t48 = t43 * tau_lo;
    const T t49 = t37 - t38 * t36 * ab_ap - t34;
    const T t50 = T(4) * t49 * t44 + ap_ap * t41 * t44 - T(2) * ab_ap * t46 * t44;
    const T t51 = T(2) * J2 - t38 * t36 * ap_ap - T(2) * t49 * ab_ap * t44;
    const T t52 = ap_ap * t46 * t44 + T(2) * ab_ap * t50 * t44 - T(4) * t51 * t44;
    const T t53 = t45 * t45;
    const T t54 = t53 * delta_tau;
    const T t55 = t45 * delta_tau;
    F = (T(5) / T(8)) * t41 * delta_tau * t43 * t44 + (T(5) / T(4)) * t45 * t46 * t47 * t44 + (T(1) / T(8)) * t36 * t40 * t48 + (T(1) / T(8)) * (t50 * ap_ap * t44 + T(4) * (T(2) * t51 * ab_ap * t44 + (T(2) * ab_ap * J2 + log_ratio) * t44 + t49 * ap_ap * t44) * t44 - T(2) * ab_ap * t52 * t44) * t54 * t44 - (T(5) / T(4)) * t50 * t55 * t42 * t44 - (T(5) / T(8)) * t52 * t53 * tau_lo * t44;
    const T t56 = t35 * t34;
    const T t57 = t39 * t37;
    const T t58 = T(8) * ab_ap * t56 + T(5) * t36 * t40 * ab_ab + T(8) * t57 * a_minus_b;
    const T t59 = T(8) * t56 + t36 * ab_ap * t58 - T(8) * t57;
    const T t60 = T(2) * ab_ap * t59 * t44 + T(6) * t36 * t40 - t36 * ap_ap * t58;
    const T t61 = ap_ap * t59 * t44 - T(2) * ab_ap * t60 * t44 - T(6) * t41 * t44;
    const T t62 = T(6) * t46 * t44 - T(2) * ab_ap * t61 * t44 - ap_ap * t60 * t44;
    G_ap = (T(5) / T(48)) * t62 * t53 * tau_lo * t44 + (T(1) / T(48)) * (T(2) * ab_ap * t62 * t44 + t61 * ap_ap * t44 - T(6) * t50 * t44) * t54 * t44 + (T(5) / T(24)) * t45 * t60 * t47 * t44 + (T(1) / T(48)) * t36 * t48 * t58 + (T(5) / T(48)) * delta_tau * t59 * t43 * t44 - (T(5) / T(24)) * t61 * t55 * t42 * t44;
    const T t63 = T(5) * delta_tau * t43 + t48 + T(10) * t45 * t47 + t54 + T(10) * t55 * t42 + T(5) * t53 * tau_lo;
    G_E = (T(1) / T(48)) * (T(5) * t36 * delta_tau * t40 * t43 + T(20) * t41 * t45 * t47 * t44 + T(30) * t55 * t46 * t42 * t44 + T(8) * t56 * t48 - T(5) * t52 * t54 * t44 - T(8) * t63 * t57 - T(20) * t50 * t53 * tau_lo * t44) * t44;
  }
  const T t64 = in.sigma * in.sigma;
  const T t65 = t64 * in.sigma;
  const T t66 = t65 * t65;
  const T g_factor = -T(6) * length * t66;
  f = length * t66 * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 67 +, 178 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 35529 +, 59553 ×, 7247 /, 3239 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = a_minus_b * ab_ap;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / cross_cross;
    const T t3 = a_minus_b * r0;
    X = length * t2 * (t3 + ab_ap * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t4 - ab_ap * r1);
  }
  const T t5 = T(1) / length;
  const T J1 = t5 * asinh(X);
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -a_minus_b * ab_ap;
  const T t8 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = tau_lo * tau_lo;
    const T t13 = t12 * tau_lo;
    const T t14 = t9 * delta_tau;
    const T t15 = t12 * t12;
    const T t16 = t15 * tau_lo;
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    F = T(6) * tau_lo * M_panels[5] * t11 + T(20) * t13 * M_panels[3] * t14 + T(15) * t15 * M_panels[2] * t9 + T(15) * t12 * M_panels[4] * t10 + T(6) * t16 * M_panels[1] * delta_tau + M_panels[6] * t17 + t18 * M_panels[0];
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t19 = delta_tau * delta_tau;
    const T t20 = t19 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t19 * t19;
    const T t26 = t22 * t22;
    const T t27 = t26 * tau_lo;
    const T t28 = t25 * delta_tau;
    F = M_panels[6] * t21 + M_panels[0] * t24 + T(15) * t22 * M_panels[4] * t25 + T(20) * t23 * M_panels[3] * t20 + T(6) * t27 * M_panels[1] * delta_tau + T(6) * tau_lo * M_panels[5] * t28 + T(15) * t26 * M_panels[2] * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = tau_lo * tau_lo;
    const T t30 = t29 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = T(1) / cross_cross;
    const T t33 = T(1) / r1;
    const T t34 = t33 * t33;
    const T t35 = T(1) / r0;
    const T t36 = t35 * t35;
    const T t37 = t35 * ab_ap + a_minus_b * t33;
    const T t38 = a_minus_b * t34 * t33 + t35 * ab_ap * t36 + T(2) * ab_ab * t32 * t37;
    const T t39 = t36 * t36;
    const T t40 = t34 * t34;
    const T t41 = T(4) * ab_ab * t32 * t38 + T(3) * t35 * ab_ap * t39 + T(3) * a_minus_b * t40 * t33;
    const T t42 = t29 * t29;
    const T t43 = T(1) / ab_ab;
    const T t44 = t41 * t32 * ab_ap + T(3) * t35 * t39 - T(3) * t40 * t33;
    const T t45 = T(2) * t43 * ab_ap * t44 + T(5) * t32 * t38 - t41 * t32 * ap_ap;
    const T t46 = delta_tau * delta_tau;
    const T t47 = t35 * t36 + t32 * ab_ap * t38 - t34 * t33;
    const T t48 = T(2) * t43 * t45 * ab_ap + T(5) * t43 * t47 - t43 * ap_ap * t44;
    const T t49 = t46 * delta_tau;
    const T t50 = t42 * tau_lo;
    const T t51 = T(3) * t32 * t37 + T(2) * t43 * ab_ap * t47 - t32 * t38 * ap_ap;
    const T t52 = T(2) * t43 * t48 * ab_ap + T(5) * t43 * t51 - t43 * t45 * ap_ap;
    const T t53 = t46 * t46;
    const T t54 = t33 - t35 - t32 * t37 * ab_ap;
    const T t55 = t43 * t47 * ap_ap + T(3) * t43 * t54 - T(2) * t43 * t51 * ab_ap;
    const T t56 = T(5) * t43 * t55 + t43 * t48 * ap_ap - T(2) * t43 * ab_ap * t52;
    const T t57 = t49 * t49;
    const T t58 = t53 * delta_tau;
    F = (T(1) / T(15)) * t31 * t41 * t32 + t42 * t43 * t45 * t46 + (T(4) / T(3)) * t30 * t43 * t48 * t49 + (T(2) / T(5)) * t50 * t43 * t44 * delta_tau + t29 * t43 * t52 * t53 - (T(1) / T(15)) * (T(5) * t43 * (T(2) * t43 * t55 * ab_ap + t43 * t51 * ap_ap + T(3) * t43 * (T(2) * t43 * t54 * ab_ap + t32 * t37 * ap_ap - J1)) + t43 * t52 * ap_ap + T(2) * t56 * t43 * ab_ap) * t43 * t57 - (T(2) / T(5)) * t56 * tau_lo * t43 * t58;
  }
  const T t59 = in.sigma * in.sigma;
  const T t60 = t59 * in.sigma;
  const T t61 = t60 * t60;
  const T t62 = t61 * in.sigma;
  f = length * t62 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 93 +, 271 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48917 +, 74654 ×, 5604 /, 2504 sqrt, 0 atan, 0 log/asinh.
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
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab1 * ab_ap * t1;
    foot2 = ap2 - ab2 * ab_ap * t1;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -(ab1 * exact_cross[2] - ab2 * exact_cross[1]) * t2;
    foot1 = (ab0 * exact_cross[2] - ab2 * exact_cross[0]) * t2;
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t9 * t9;
    const T t13 = t12 * delta_tau;
    const T t14 = t6 * t6;
    const T t15 = t14 * tau_lo;
    const T t16 = t8 * M_panels[8] + T(20) * t10 * M_panels[11] * t7 + M_panels[14] * t11 + T(6) * M_panels[13] * t13 * tau_lo + T(15) * M_panels[12] * t12 * t6 + T(6) * M_panels[9] * delta_tau * t15 + T(15) * M_panels[10] * t9 * t14;
    G_ap = t16;
    const T t17 = T(1) / ab_ab;
    G_E = T(15) * M_panels[13] * t12 * t6 + T(6) * M_panels[10] * delta_tau * t15 + M_panels[9] * t8 + T(15) * t9 * M_panels[11] * t14 + T(20) * M_panels[12] * t10 * t7 + T(6) * M_panels[14] * t13 * tau_lo + M_panels[15] * t11 - ab_ap * t16 * t17;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t18 = delta_tau * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = tau_lo * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t21 * tau_lo;
    const T t23 = t20 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t18 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t19 * delta_tau;
    G_ap = T(15) * M_panels[12] * t19 * t20 + T(6) * M_panels[9] * delta_tau * t22 + M_panels[8] * t24 + T(15) * M_panels[10] * t18 * t21 + t26 * M_panels[14] + T(20) * t25 * t23 * M_panels[11] + T(6) * M_panels[13] * t27 * tau_lo;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t30 * t30;
    const T t32 = t31 * t28;
    const T t33 = t24 + T(15) * t18 * t21 + t26 + T(6) * t27 * tau_lo + T(15) * t19 * t20 + T(20) * t25 * t23 + T(6) * delta_tau * t22;
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = t36 * t36;
    const T t38 = t37 * t34;
    const T t39 = T(1) / ab_ab;
    G_E = (T(1) / T(7)) * (T(6) * M_panels[0] * delta_tau * t22 + T(30) * M_panels[4] * t27 * tau_lo + T(6) * t26 * M_panels[5] + T(30) * M_panels[1] * t18 * t21 + t32 * t24 + T(60) * M_panels[2] * t25 * t23 + T(60) * M_panels[3] * t19 * t20 - t33 * t38) * t39;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t40 = T(1) / r0;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = t42 * t41;
    const T t44 = T(1) / r1;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = T(1) / cross_cross;
    const T t48 = t40 * ab_ap + t44 * a_minus_b;
    const T t49 = T(2) * t47 * t48 * ab_ab + t40 * ab_ap * t41 + t44 * a_minus_b * t45;
    const T t50 = T(3) * t44 * a_minus_b * t46 + T(3) * t40 * ab_ap * t42 + T(4) * t49 * t47 * ab_ab;
    const T t51 = t46 * t45;
    const T t52 = T(5) * t40 * ab_ap * t43 + T(2) * t50 * t47 * ab_ab + T(5) * t44 * a_minus_b * t51;
    const T t53 = tau_lo * tau_lo;
    const T t54 = t53 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = T(3) * t40 * t42 + t50 * ab_ap * t47 - T(3) * t44 * t46;
    const T t57 = T(1) / ab_ab;
    const T t58 = T(5) * t49 * t47 + T(2) * ab_ap * t56 * t57 - t50 * ap_ap * t47;
    const T t59 = T(5) * t40 * t43 + t52 * ab_ap * t47 - T(5) * t44 * t51;
    const T t60 = T(6) * ab_ap * t59 * t57 + T(7) * t50 * t47 - T(3) * t52 * ap_ap * t47;
    const T t61 = T(7) * t56 * t57 + T(2) * ab_ap * t60 * t57 - T(3) * ap_ap * t59 * t57;
    const T t62 = T(7) * t58 * t57 + T(2) * ab_ap * t61 * t57 - ap_ap * t60 * t57;
    const T t63 = t44 * t45 - t40 * t41 - t49 * ab_ap * t47;
    const T t64 = T(5) * t63 * t57 + ap_ap * t56 * t57 - T(2) * ab_ap * t58 * t57;
    const T t65 = T(2) * t62 * ab_ap * t57 - ap_ap * t61 * t57 - T(7) * t64 * t57;
    const T t66 = delta_tau * delta_tau;
    const T t67 = t66 * t66;
    const T t68 = t67 * delta_tau;
    const T t69 = t53 * t53;
    const T t70 = t66 * delta_tau;
    const T t71 = t69 * tau_lo;
    const T t72 = T(3) * t47 * t48 - T(2) * ab_ap * t63 * t57 - t49 * ap_ap * t47;
    const T t73 = t58 * ap_ap * t57 + T(2) * ab_ap * t64 * t57 - T(5) * t72 * t57;
    const T t74 = t70 * t70;
    G_ap = (T(1) / T(35)) * t52 * t47 * t55 + (T(2) / T(35)) * t65 * t68 * tau_lo * t57 + (T(1) / T(7)) * t62 * t67 * t53 * t57 + (T(1) / T(7)) * t60 * t66 * t69 * t57 + (T(4) / T(21)) * t61 * t70 * t54 * t57 + (T(6) / T(35)) * t59 * delta_tau * t71 * t57 - (T(1) / T(105)) * (t62 * ap_ap * t57 + T(7) * t73 * t57 - T(2) * ab_ap * t65 * t57) * t74 * t57;
    const T t75 = t55 + T(15) * t66 * t69 + t74 + T(6) * t68 * tau_lo + T(15) * t67 * t53 + T(20) * t70 * t54 + T(6) * delta_tau * t71;
    const T t76 = t44 * t44;
    const T t77 = t76 * t44;
    const T t78 = t77 * t77;
    const T t79 = t78 * t44;
    const T t80 = t40 * t40;
    const T t81 = t80 * t40;
    const T t82 = t81 * t81;
    const T t83 = t82 * t40;
    G_E = -(T(1) / T(35)) * (T(20) * t64 * t67 * t53 * t57 + T(10) * t73 * t68 * tau_lo * t57 + T(5) * t75 * t79 - T(2) * (ap_ap * t64 * t57 + T(5) * (T(2) * t72 * ab_ap * t57 + T(3) * (ab_ap * t47 * t48 + t40 - t44) * t57 + t63 * ap_ap * t57) * t57 - T(2) * ab_ap * t73 * t57) * t74 * t57 - T(5) * t83 * t55 - T(20) * t58 * t70 * t54 * t57 - T(10) * t56 * t66 * t69 * t57 - T(2) * t50 * t47 * delta_tau * t71) * t57;
  }
  const T t84 = in.sigma * in.sigma;
  const T t85 = t84 * in.sigma;
  const T t86 = t85 * t85;
  const T t87 = t86 * in.sigma;
  const T g_factor = -T(7) * t87 * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 106 +, 322 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48924 +, 74679 ×, 5606 /, 2504 sqrt, 0 atan, 1 log/asinh.
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
    foot0 = (exact_cross[1] * ab2 - exact_cross[2] * ab1) * t2;
    foot1 = (exact_cross[2] * ab0 - exact_cross[0] * ab2) * t2;
    foot2 = t2 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = a_minus_b * ab_ap;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r1 * ab_ap;
    const T t5 = T(1) / cross_cross;
    X = (t4 + a_minus_b * r0) * length * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = r1 * ab_ap;
    X = -(a_minus_b - ab_ap) * length / (t6 - a_minus_b * r0);
  }
  const T t7 = T(1) / length;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -a_minus_b * ab_ap;
  const T t10 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = delta_tau * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = tau_lo * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t13 * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = t11 * delta_tau;
    const T t18 = t14 * tau_lo;
    const T t19 = t12 * delta_tau;
    const T t20 = t17 * t17;
    F = T(15) * M_panels[4] * t12 * t13 + T(15) * t11 * M_panels[2] * t14 + t16 * M_panels[0] + T(20) * t17 * t15 * M_panels[3] + T(6) * M_panels[1] * delta_tau * t18 + T(6) * M_panels[5] * t19 * tau_lo + t20 * M_panels[6];
    const T t21 = M_panels[14] * t20 + M_panels[8] * t16 + T(6) * M_panels[13] * t19 * tau_lo + T(20) * t17 * M_panels[11] * t15 + T(15) * M_panels[10] * t11 * t14 + T(6) * delta_tau * t18 * M_panels[9] + T(15) * t12 * t13 * M_panels[12];
    G_ap = t21;
    const T t22 = T(1) / ab_ab;
    G_E = T(15) * M_panels[13] * t12 * t13 + T(15) * t11 * M_panels[11] * t14 + T(20) * t17 * t15 * M_panels[12] + T(6) * M_panels[10] * delta_tau * t18 + t20 * M_panels[15] + T(6) * M_panels[14] * t19 * tau_lo + t16 * M_panels[9] - t21 * t22 * ab_ap;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t23 = delta_tau * delta_tau;
    const T t24 = t23 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t26 * delta_tau;
    const T t28 = tau_lo * tau_lo;
    const T t29 = t28 * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t28 * t28;
    const T t32 = t31 * tau_lo;
    F = t25 * M_panels[6] + T(6) * t27 * tau_lo * M_panels[5] + t30 * M_panels[0] + T(15) * t23 * t31 * M_panels[2] + T(6) * M_panels[1] * delta_tau * t32 + T(15) * M_panels[4] * t26 * t28 + T(20) * t24 * t29 * M_panels[3];
    G_ap = T(15) * M_panels[10] * t23 * t31 + T(15) * t26 * t28 * M_panels[12] + T(20) * t24 * M_panels[11] * t29 + T(6) * M_panels[13] * t27 * tau_lo + T(6) * delta_tau * t32 * M_panels[9] + M_panels[8] * t30 + M_panels[14] * t25;
    const T t33 = T(1) / ab_ab;
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = t36 * t36;
    const T t38 = t37 * t34;
    const T t39 = t30 + T(6) * t27 * tau_lo + t25 + T(15) * t23 * t31 + T(15) * t26 * t28 + T(20) * t24 * t29 + T(6) * delta_tau * t32;
    const T t40 = T(1) / r0;
    const T t41 = t40 * t40;
    const T t42 = t41 * t40;
    const T t43 = t42 * t42;
    const T t44 = t43 * t40;
    G_E = -(T(1) / T(7)) * t33 * (t38 * t39 - T(60) * t24 * t29 * M_panels[2] - T(60) * t26 * t28 * M_panels[3] - T(30) * M_panels[1] * t23 * t31 - T(6) * delta_tau * t32 * M_panels[0] - t30 * t44 - T(6) * t25 * M_panels[5] - T(30) * M_panels[4] * t27 * tau_lo);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t45 = T(1) / r0;
    const T t46 = t45 * t45;
    const T t47 = t46 * t46;
    const T t48 = T(1) / cross_cross;
    const T t49 = T(1) / r1;
    const T t50 = t45 * ab_ap + a_minus_b * t49;
    const T t51 = t49 * t49;
    const T t52 = T(2) * ab_ab * t48 * t50 + a_minus_b * t49 * t51 + t46 * t45 * ab_ap;
    const T t53 = t51 * t51;
    const T t54 = T(3) * t47 * t45 * ab_ap + T(4) * ab_ab * t52 * t48 + T(3) * a_minus_b * t49 * t53;
    const T t55 = tau_lo * tau_lo;
    const T t56 = t55 * tau_lo;
    const T t57 = t56 * t56;
    const T t58 = T(3) * t49 * t53 - t54 * t48 * ab_ap - T(3) * t47 * t45;
    const T t59 = T(1) / ab_ab;
    const T t60 = t46 * t45 + t52 * t48 * ab_ap - t49 * t51;
    const T t61 = t54 * ap_ap * t48 + T(2) * t58 * t59 * ab_ap - T(5) * t52 * t48;
    const T t62 = ap_ap * t58 * t59 + T(5) * t60 * t59 - T(2) * t59 * ab_ap * t61;
    const T t63 = delta_tau * delta_tau;
    const T t64 = t63 * delta_tau;
    const T t65 = t64 * t64;
    const T t66 = ap_ap * t52 * t48 - T(2) * t60 * t59 * ab_ap - T(3) * t48 * t50;
    const T t67 = t48 * ab_ap * t50 + t45 - t49;
    const T t68 = ap_ap * t60 * t59 + T(2) * t66 * t59 * ab_ap - T(3) * t67 * t59;
    const T t69 = T(5) * t66 * t59 - T(2) * t62 * t59 * ab_ap - ap_ap * t59 * t61;
    const T t70 = T(5) * t59 * t68 + t62 * ap_ap * t59 + T(2) * t69 * t59 * ab_ap;
    const T t71 = t63 * t63;
    const T t72 = t71 * delta_tau;
    const T t73 = t55 * t55;
    const T t74 = t73 * tau_lo;
    F = (T(1) / T(15)) * t54 * t57 * t48 + (T(4) / T(3)) * t62 * t64 * t56 * t59 - (T(1) / T(15)) * t65 * t59 * (T(5) * t59 * (T(2) * t59 * t68 * ab_ap + T(3) * (ap_ap * t48 * t50 - J1 - T(2) * t67 * t59 * ab_ap) * t59 - ap_ap * t66 * t59) + T(2) * t70 * t59 * ab_ap - t69 * ap_ap * t59) - (T(2) / T(5)) * t70 * t72 * tau_lo * t59 - t63 * t73 * t59 * t61 - t69 * t71 * t55 * t59 - (T(2) / T(5)) * delta_tau * t58 * t74 * t59;
    const T t75 = t47 * t46;
    const T t76 = t53 * t51;
    const T t77 = T(2) * t54 * ab_ab * t48 + T(5) * t75 * t45 * ab_ap + T(5) * a_minus_b * t49 * t76;
    const T t78 = t48 * ab_ap * t77 + T(5) * t75 * t45 - T(5) * t49 * t76;
    const T t79 = T(6) * t78 * t59 * ab_ap + T(7) * t54 * t48 - T(3) * ap_ap * t48 * t77;
    const T t80 = T(7) * t58 * t59 + T(3) * ap_ap * t78 * t59 - T(2) * t79 * t59 * ab_ap;
    const T t81 = ap_ap * t79 * t59 + T(2) * t80 * t59 * ab_ap + T(7) * t59 * t61;
    const T t82 = t80 * ap_ap * t59 + T(7) * t62 * t59 - T(2) * t81 * t59 * ab_ap;
    G_ap = (T(1) / T(105)) * t65 * t59 * (T(2) * t82 * t59 * ab_ap + ap_ap * t81 * t59 - T(7) * t69 * t59) + (T(1) / T(35)) * t57 * t48 * t77 + (T(2) / T(35)) * t82 * t72 * tau_lo * t59 + (T(6) / T(35)) * t78 * delta_tau * t74 * t59 + (T(1) / T(7)) * t79 * t63 * t73 * t59 - (T(1) / T(7)) * t81 * t71 * t55 * t59 - (T(4) / T(21)) * t80 * t64 * t56 * t59;
    const T t83 = t49 * t49;
    const T t84 = t83 * t49;
    const T t85 = t84 * t84;
    const T t86 = t85 * t49;
    const T t87 = t57 + T(6) * t72 * tau_lo + t65 + T(15) * t63 * t73 + T(15) * t71 * t55 + T(20) * t64 * t56 + T(6) * delta_tau * t74;
    const T t88 = t45 * t45;
    const T t89 = t88 * t45;
    const T t90 = t89 * t89;
    const T t91 = t90 * t45;
    G_E = -(T(1) / T(35)) * t59 * (T(5) * t86 * t87 + T(20) * t64 * t56 * t59 * t61 + T(10) * t63 * t58 * t73 * t59 + T(10) * t69 * t72 * tau_lo * t59 + T(2) * t70 * t65 * t59 - T(2) * t54 * delta_tau * t74 * t48 - T(5) * t57 * t91 - T(20) * t62 * t71 * t55 * t59);
  }
  const T t92 = in.sigma * in.sigma;
  const T t93 = t92 * in.sigma;
  const T t94 = t93 * t93;
  const T t95 = t94 * in.sigma;
  const T g_factor = -T(7) * t95 * length;
  f = t95 * F * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 77 +, 204 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 33611 +, 46474 ×, 6305 /, 137 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = delta_tau * delta_tau;
    const T t5 = t4 * t4;
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * tau_lo;
    const T t8 = t6 * t6;
    const T t9 = t8 * tau_lo;
    const T t10 = t4 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t5 * delta_tau;
    const T t14 = t7 * t7;
    const T t15 = t14 * tau_lo;
    F = T(35) * M_panels[4] * t5 * t7 + T(21) * M_panels[2] * t4 * t9 + t12 * M_panels[7] + T(21) * M_panels[5] * t13 * t6 + T(35) * M_panels[3] * t10 * t8 + T(7) * delta_tau * M_panels[1] * t14 + M_panels[0] * t15 + T(7) * M_panels[6] * t11 * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t16 = delta_tau * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = tau_lo * tau_lo;
    const T t20 = t16 * delta_tau;
    const T t21 = t19 * t19;
    const T t22 = t21 * tau_lo;
    const T t23 = t20 * t20;
    const T t24 = t19 * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * delta_tau;
    F = T(21) * M_panels[5] * t18 * t19 + T(35) * M_panels[3] * t20 * t21 + T(21) * M_panels[2] * t16 * t22 + T(7) * M_panels[6] * t23 * tau_lo + M_panels[0] * t26 + T(7) * M_panels[1] * delta_tau * t25 + T(35) * M_panels[4] * t17 * t24 + M_panels[7] * t27;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = sqrt(cross_cross);
    const T t29 = T(1) / t28;
    const T J2 = atan2(t28, ap_bp) * t29;
    const T t30 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t30);
    const T t31 = T(1) / cross_cross;
    const T t32 = T(1) / bp_bp;
    const T t33 = t32 * t32;
    const T t34 = t33 * t32;
    const T t35 = ab_ap * t30 + J2 * ab_ab + a_minus_b * t32;
    const T t36 = t30 * t30;
    const T t37 = T(3) * ab_ab * t31 * t35 + T(2) * a_minus_b * t33 + T(2) * ab_ap * t36;
    const T t38 = t36 * t30;
    const T t39 = T(8) * a_minus_b * t34 + T(5) * ab_ab * t31 * t37 + T(8) * ab_ap * t38;
    const T t40 = tau_lo * tau_lo;
    const T t41 = t40 * tau_lo;
    const T t42 = t41 * t41;
    const T t43 = t42 * tau_lo;
    const T t44 = T(1) / ab_ab;
    const T t45 = T(8) * t38 + t31 * t39 * ab_ap - T(8) * t34;
    const T t46 = t31 * t39 * ap_ap - T(6) * t31 * t37 - T(2) * t44 * ab_ap * t45;
    const T t47 = T(2) * t36 + t31 * ab_ap * t37 - T(2) * t33;
    const T t48 = T(2) * t46 * t44 * ab_ap + t44 * t45 * ap_ap - T(6) * t44 * t47;
    const T t49 = t31 * t37 * ap_ap - T(4) * t31 * t35 - T(2) * t44 * t47 * ab_ap;
    const T t50 = T(2) * t44 * ab_ap * t48 + T(6) * t49 * t44 - t46 * t44 * ap_ap;
    const T t51 = t31 * t35 * ab_ap + t30 - t32;
    const T t52 = t44 * t47 * ap_ap + T(2) * t49 * t44 * ab_ap - T(4) * t44 * t51;
    const T t53 = T(2) * t50 * t44 * ab_ap + T(6) * t44 * t52 - t44 * ap_ap * t48;
    const T t54 = T(2) * J2 + T(2) * t44 * ab_ap * t51 - t31 * t35 * ap_ap;
    const T t55 = t49 * t44 * ap_ap + T(4) * t44 * t54 - T(2) * t44 * ab_ap * t52;
    const T t56 = T(2) * t44 * ab_ap * t53 - T(6) * t44 * t55 - t50 * t44 * ap_ap;
    const T t57 = delta_tau * delta_tau;
    const T t58 = t57 * delta_tau;
    const T t59 = t58 * t58;
    const T t60 = t59 * delta_tau;
    const T t61 = t57 * t57;
    const T t62 = t61 * delta_tau;
    const T t63 = t40 * t40;
    const T t64 = t63 * tau_lo;
    F = (T(1) / T(48)) * t31 * t39 * t43 + (T(7) / T(48)) * t44 * t45 * delta_tau * t42 + (T(1) / T(48)) * t44 * (t44 * ap_ap * t53 + T(6) * t44 * (t44 * t52 * ap_ap + T(4) * t44 * (T(2) * t44 * ab_ap * t54 + t44 * (log_ratio + T(2) * J2 * ab_ap) - t44 * t51 * ap_ap) + T(2) * t44 * ab_ap * t55) - T(2) * t44 * t56 * ab_ap) * t60 - (T(7) / T(16)) * t44 * t53 * t62 * t40 - (T(35) / T(48)) * t44 * t58 * t48 * t63 - (T(35) / T(48)) * t50 * t44 * t61 * t41 - (T(7) / T(16)) * t46 * t44 * t57 * t64 - (T(7) / T(48)) * t44 * t56 * t59 * tau_lo;
  }
  const T t65 = in.sigma * in.sigma;
  const T t66 = t65 * t65;
  const T t67 = t66 * t66;
  f = length * t67 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 107 +, 296 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 48732 +, 63456 ×, 5087 /, 111 sqrt, 0 atan, 0 log/asinh.
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
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * t2;
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = tau_lo * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t10 * tau_lo;
    const T t12 = t9 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t6 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t15 * delta_tau;
    const T t17 = t13 * tau_lo;
    const T t18 = T(21) * t8 * t9 * M_panels[14] + T(21) * M_panels[11] * t6 * t11 + T(7) * delta_tau * t13 * M_panels[10] + T(35) * M_panels[12] * t14 * t10 + t16 * M_panels[16] + M_panels[9] * t17 + T(7) * M_panels[15] * t15 * tau_lo + T(35) * t7 * t12 * M_panels[13];
    G_ap = t18;
    const T t19 = T(1) / ab_ab;
    G_E = t16 * M_panels[17] + T(35) * t7 * t12 * M_panels[14] + T(7) * M_panels[11] * delta_tau * t13 + t17 * M_panels[10] + T(21) * M_panels[12] * t6 * t11 + T(7) * t15 * tau_lo * M_panels[16] + T(35) * t14 * t10 * M_panels[13] + T(21) * M_panels[15] * t8 * t9 - t19 * t18 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = delta_tau * delta_tau;
    const T t21 = tau_lo * tau_lo;
    const T t22 = t21 * t21;
    const T t23 = t22 * tau_lo;
    const T t24 = t20 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t21 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t20 * t20;
    const T t30 = t25 * delta_tau;
    const T t31 = t29 * delta_tau;
    G_ap = T(21) * t20 * t23 * M_panels[11] + T(7) * t25 * tau_lo * M_panels[15] + T(35) * t24 * t22 * M_panels[12] + M_panels[9] * t28 + T(7) * M_panels[10] * delta_tau * t27 + T(35) * M_panels[13] * t29 * t26 + M_panels[16] * t30 + T(21) * t31 * t21 * M_panels[14];
    const T t32 = T(1) / ab_ab;
    const T t33 = T(1) / ap_ap;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = t28 + T(21) * t20 * t23 + t30 + T(7) * t25 * tau_lo + T(35) * t24 * t22 + T(35) * t29 * t26 + T(21) * t31 * t21 + T(7) * delta_tau * t27;
    const T t37 = T(1) / bp_bp;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    G_E = (T(1) / T(8)) * t32 * (t35 * t28 + T(105) * M_panels[4] * t31 * t21 + T(42) * t25 * tau_lo * M_panels[5] + T(105) * t24 * t22 * M_panels[2] + T(42) * t20 * M_panels[1] * t23 + T(7) * M_panels[0] * delta_tau * t27 + T(140) * M_panels[3] * t29 * t26 + T(7) * M_panels[6] * t30 - t36 * t39);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t40 = sqrt(cross_cross);
    const T t41 = T(1) / t40;
    const T J2 = atan2(t40, ap_bp) * t41;
    const T t42 = tau_lo * tau_lo;
    const T t43 = t42 * tau_lo;
    const T t44 = t43 * t43;
    const T t45 = T(1) / ab_ab;
    const T t46 = T(1) / ap_ap;
    const T t47 = t46 * t46;
    const T t48 = t47 * t47;
    const T t49 = T(1) / bp_bp;
    const T t50 = t49 * t49;
    const T t51 = t50 * t50;
    const T t52 = t50 * t49;
    const T t53 = t47 * t46;
    const T t54 = t46 * ab_ap + a_minus_b * t49 + ab_ab * J2;
    const T t55 = T(1) / cross_cross;
    const T t56 = T(2) * a_minus_b * t50 + T(2) * t47 * ab_ap + T(3) * ab_ab * t54 * t55;
    const T t57 = T(8) * a_minus_b * t52 + T(8) * t53 * ab_ap + T(5) * ab_ab * t56 * t55;
    const T t58 = T(48) * a_minus_b * t51 + T(7) * ab_ab * t57 * t55 + T(48) * t48 * ab_ap;
    const T t59 = T(48) * t48 + t58 * ab_ap * t55 - T(48) * t51;
    const T t60 = T(8) * t53 + t57 * ab_ap * t55 - T(8) * t52;
    const T t61 = T(2) * t45 * t59 * ab_ap + T(8) * t57 * t55 - ap_ap * t58 * t55;
    const T t62 = T(8) * t45 * t60 + T(2) * t61 * t45 * ab_ap - ap_ap * t45 * t59;
    const T t63 = delta_tau * delta_tau;
    const T t64 = t63 * delta_tau;
    const T t65 = t42 * t42;
    const T t66 = T(2) * t47 + t56 * ab_ap * t55 - T(2) * t50;
    const T t67 = T(6) * t56 * t55 + T(2) * t45 * ab_ap * t60 - ap_ap * t57 * t55;
    const T t68 = ap_ap * t45 * t60 - T(6) * t66 * t45 - T(2) * t45 * t67 * ab_ap;
    const T t69 = ap_ap * t61 * t45 - T(8) * t45 * t67 - T(2) * t62 * t45 * ab_ap;
    const T t70 = T(8) * t68 * t45 + T(2) * t45 * t69 * ab_ap + ap_ap * t62 * t45;
    const T t71 = T(2) * t66 * t45 * ab_ap + T(4) * t54 * t55 - ap_ap * t56 * t55;
    const T t72 = T(6) * t45 * t71 - T(2) * t68 * t45 * ab_ap - ap_ap * t45 * t67;
    const T t73 = t49 - t54 * ab_ap * t55 - t46;
    const T t74 = ap_ap * t66 * t45 + T(4) * t73 * t45 - T(2) * t45 * ab_ap * t71;
    const T t75 = ap_ap * t68 * t45 + T(2) * t72 * t45 * ab_ap - T(6) * t74 * t45;
    const T t76 = T(2) * t70 * t45 * ab_ap - T(8) * t72 * t45 - ap_ap * t45 * t69;
    const T t77 = t64 * t64;
    const T t78 = t77 * delta_tau;
    const T t79 = t44 * tau_lo;
    const T t80 = t65 * tau_lo;
    const T t81 = t63 * t63;
    const T t82 = t81 * delta_tau;
    G_ap = (T(7) / T(384)) * delta_tau * t44 * t45 * t59 + (T(35) / T(384)) * t62 * t64 * t65 * t45 + (T(1) / T(384)) * (ap_ap * t70 * t45 + T(8) * t45 * t75 - T(2) * t45 * t76 * ab_ap) * t78 * t45 + (T(1) / T(384)) * t58 * t79 * t55 + (T(7) / T(128)) * t61 * t63 * t80 * t45 - (T(7) / T(128)) * t70 * t82 * t42 * t45 - (T(35) / T(384)) * t81 * t43 * t45 * t69 - (T(7) / T(384)) * t77 * tau_lo * t45 * t76;
    const T t83 = t79 + T(21) * t63 * t80 + t78 + T(7) * t77 * tau_lo + T(35) * t64 * t65 + T(35) * t81 * t43 + T(21) * t82 * t42 + T(7) * delta_tau * t44;
    G_E = -(T(1) / T(384)) * t45 * (T(7) * (T(6) * t45 * (ap_ap * t45 * t71 + T(4) * t45 * (T(2) * t73 * t45 * ab_ap + ap_ap * t54 * t55 - T(2) * J2) + T(2) * t74 * t45 * ab_ap) + t72 * ap_ap * t45 - T(2) * t45 * ab_ap * t75) * t78 * t45 + T(48) * t83 * t51 + T(140) * t68 * t81 * t43 * t45 - T(48) * t48 * t79 - T(105) * t64 * t65 * t45 * t67 - T(7) * delta_tau * t44 * t57 * t55 - T(105) * t72 * t82 * t42 * t45 - T(42) * t77 * tau_lo * t45 * t75 - T(42) * t63 * t80 * t45 * t60);
  }
  const T t84 = in.sigma * in.sigma;
  const T t85 = t84 * t84;
  const T t86 = t85 * t85;
  const T g_factor = -T(8) * length * t86;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 121 +, 351 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 48739 +, 63478 ×, 5087 /, 111 sqrt, 0 atan, 0 log/asinh.
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
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab1 * ab_ap * t1;
    foot2 = ap2 - ab2 * ab_ap * t1;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -(exact_cross[2] * ab1 - ab2 * exact_cross[1]) * t2;
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * t2;
    foot2 = (ab1 * exact_cross[0] - ab0 * exact_cross[1]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t6 * t6;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * tau_lo;
    const T t13 = t11 * t11;
    const T t14 = t10 * delta_tau;
    const T t15 = t13 * tau_lo;
    const T t16 = t12 * t12;
    const T t17 = t16 * tau_lo;
    F = M_panels[7] * t9 + T(35) * M_panels[4] * t10 * t12 + T(7) * M_panels[6] * t8 * tau_lo + T(35) * M_panels[3] * t7 * t13 + T(21) * M_panels[5] * t14 * t11 + T(21) * M_panels[2] * t6 * t15 + T(7) * M_panels[1] * delta_tau * t16 + M_panels[0] * t17;
    const T t18 = M_panels[16] * t9 + T(35) * M_panels[12] * t7 * t13 + T(21) * M_panels[14] * t14 * t11 + T(21) * M_panels[11] * t6 * t15 + T(35) * M_panels[13] * t10 * t12 + T(7) * M_panels[10] * delta_tau * t16 + M_panels[9] * t17 + T(7) * t8 * tau_lo * M_panels[15];
    G_ap = t18;
    const T t19 = T(1) / ab_ab;
    G_E = T(21) * M_panels[12] * t6 * t15 + M_panels[17] * t9 + T(7) * M_panels[11] * delta_tau * t16 + T(7) * M_panels[16] * t8 * tau_lo + T(35) * M_panels[14] * t10 * t12 + M_panels[10] * t17 + T(21) * t14 * t11 * M_panels[15] + T(35) * M_panels[13] * t7 * t13 - ab_ap * t18 * t19;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = delta_tau * delta_tau;
    const T t21 = t20 * delta_tau;
    const T t22 = tau_lo * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t20 * t20;
    const T t25 = t24 * delta_tau;
    const T t26 = t22 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t21 * t21;
    const T t30 = t29 * delta_tau;
    const T t31 = t23 * tau_lo;
    F = T(35) * M_panels[3] * t21 * t23 + T(21) * M_panels[5] * t25 * t22 + T(7) * M_panels[1] * delta_tau * t27 + T(35) * M_panels[4] * t24 * t26 + M_panels[0] * t28 + M_panels[7] * t30 + T(21) * M_panels[2] * t20 * t31 + T(7) * t29 * M_panels[6] * tau_lo;
    G_ap = T(35) * M_panels[12] * t21 * t23 + T(21) * M_panels[14] * t25 * t22 + M_panels[9] * t28 + T(7) * M_panels[10] * delta_tau * t27 + T(35) * M_panels[13] * t24 * t26 + t30 * M_panels[16] + T(7) * M_panels[15] * t29 * tau_lo + T(21) * M_panels[11] * t20 * t31;
    const T t32 = T(1) / ap_ap;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = T(7) * delta_tau * t27 + t28 + t30 + T(21) * t25 * t22 + T(35) * t21 * t23 + T(35) * t24 * t26 + T(7) * t29 * tau_lo + T(21) * t20 * t31;
    const T t36 = T(1) / bp_bp;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = T(1) / ab_ab;
    G_E = (T(1) / T(8)) * (T(140) * M_panels[3] * t24 * t26 + T(7) * delta_tau * M_panels[0] * t27 + T(42) * M_panels[5] * t29 * tau_lo + T(42) * M_panels[1] * t20 * t31 + T(105) * M_panels[2] * t21 * t23 + T(7) * t30 * M_panels[6] + T(105) * M_panels[4] * t25 * t22 + t34 * t28 - t35 * t38) * t39;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t40 = sqrt(cross_cross);
    const T t41 = T(1) / t40;
    const T J2 = t41 * atan2(t40, ap_bp);
    const T t42 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t42);
    const T t43 = T(1) / cross_cross;
    const T t44 = t42 * t42;
    const T t45 = T(1) / bp_bp;
    const T t46 = t45 * t45;
    const T t47 = J2 * ab_ab + t45 * a_minus_b + ab_ap * t42;
    const T t48 = T(2) * ab_ap * t44 + T(2) * t46 * a_minus_b + T(3) * t43 * t47 * ab_ab;
    const T t49 = t44 * t42;
    const T t50 = t46 * t45;
    const T t51 = T(8) * ab_ap * t49 + T(8) * t50 * a_minus_b + T(5) * t43 * t48 * ab_ab;
    const T t52 = t43 * ab_ap * t51 + T(8) * t49 - T(8) * t50;
    const T t53 = T(1) / ab_ab;
    const T t54 = T(6) * t43 * t48 + T(2) * t52 * ab_ap * t53 - t43 * t51 * ap_ap;
    const T t55 = delta_tau * delta_tau;
    const T t56 = tau_lo * tau_lo;
    const T t57 = t56 * t56;
    const T t58 = t57 * tau_lo;
    const T t59 = t56 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = t60 * tau_lo;
    const T t62 = T(2) * t44 + t43 * ab_ap * t48 - T(2) * t46;
    const T t63 = T(2) * ab_ap * t62 * t53 + T(4) * t43 * t47 - t43 * ap_ap * t48;
    const T t64 = t45 - t43 * ab_ap * t47 - t42;
    const T t65 = T(2) * t63 * ab_ap * t53 - ap_ap * t62 * t53 - T(4) * t64 * t53;
    const T t66 = T(2) * t64 * ab_ap * t53 + t43 * t47 * ap_ap - T(2) * J2;
    const T t67 = T(4) * t66 * t53 + t63 * ap_ap * t53 - T(2) * ab_ap * t65 * t53;
    const T t68 = t52 * ap_ap * t53 - T(2) * ab_ap * t54 * t53 - T(6) * t62 * t53;
    const T t69 = T(2) * ab_ap * t68 * t53 + ap_ap * t54 * t53 - T(6) * t63 * t53;
    const T t70 = T(2) * t69 * ab_ap * t53 - ap_ap * t68 * t53 - T(6) * t65 * t53;
    const T t71 = T(2) * ab_ap * t70 * t53 + T(6) * t67 * t53 - t69 * ap_ap * t53;
    const T t72 = t55 * delta_tau;
    const T t73 = t72 * t72;
    const T t74 = t73 * delta_tau;
    const T t75 = t55 * t55;
    const T t76 = t75 * delta_tau;
    F = (T(7) / T(16)) * t54 * t55 * t58 * t53 + (T(7) / T(48)) * t52 * delta_tau * t60 * t53 + (T(1) / T(48)) * t43 * t51 * t61 - (T(1) / T(48)) * (T(6) * (ap_ap * t65 * t53 + T(2) * ab_ap * t67 * t53 - T(4) * (t64 * ap_ap * t53 + (T(2) * ab_ap * J2 + log_ratio) * t53 - T(2) * t66 * ab_ap * t53) * t53) * t53 + T(2) * t71 * ab_ap * t53 - t70 * ap_ap * t53) * t74 * t53 - (T(7) / T(48)) * t71 * t73 * tau_lo * t53 - (T(35) / T(48)) * t69 * t75 * t59 * t53 - (T(7) / T(16)) * t70 * t76 * t56 * t53 - (T(35) / T(48)) * t72 * t68 * t57 * t53;
    const T t77 = t44 * t44;
    const T t78 = t46 * t46;
    const T t79 = T(7) * t43 * t51 * ab_ab + T(48) * ab_ap * t77 + T(48) * t78 * a_minus_b;
    const T t80 = t43 * ab_ap * t79 + T(48) * t77 - T(48) * t78;
    const T t81 = t43 * ap_ap * t79 - T(2) * ab_ap * t80 * t53 - T(8) * t43 * t51;
    const T t82 = T(8) * t52 * t53 - T(2) * ab_ap * t81 * t53 - t80 * ap_ap * t53;
    const T t83 = T(8) * t54 * t53 + T(2) * t82 * ab_ap * t53 + t81 * ap_ap * t53;
    const T t84 = T(2) * ab_ap * t83 * t53 - T(8) * t68 * t53 - t82 * ap_ap * t53;
    const T t85 = T(8) * t69 * t53 + ap_ap * t83 * t53 - T(2) * t84 * ab_ap * t53;
    G_ap = (T(7) / T(128)) * t84 * t76 * t56 * t53 + (T(7) / T(384)) * t80 * delta_tau * t60 * t53 + (T(35) / T(384)) * t82 * t72 * t57 * t53 + (T(35) / T(384)) * t83 * t75 * t59 * t53 + (T(1) / T(384)) * t43 * t79 * t61 - (T(1) / T(384)) * (T(8) * t70 * t53 + T(2) * ab_ap * t85 * t53 + t84 * ap_ap * t53) * t74 * t53 - (T(7) / T(128)) * t81 * t55 * t58 * t53 - (T(7) / T(384)) * t85 * t73 * tau_lo * t53;
    const T t86 = T(7) * delta_tau * t60 + t61 + t74 + T(21) * t76 * t56 + T(35) * t72 * t57 + T(35) * t75 * t59 + T(7) * t73 * tau_lo + T(21) * t55 * t58;
    G_E = (T(1) / T(384)) * (T(42) * t52 * t55 * t58 * t53 + T(7) * t43 * t51 * delta_tau * t60 + T(105) * t54 * t72 * t57 * t53 + T(48) * t77 * t61 - T(105) * t69 * t76 * t56 * t53 - T(42) * t70 * t73 * tau_lo * t53 - T(140) * t75 * t68 * t59 * t53 - T(48) * t86 * t78 - T(7) * t71 * t74 * t53) * t53;
  }
  const T t87 = in.sigma * in.sigma;
  const T t88 = t87 * t87;
  const T t89 = t88 * t88;
  const T g_factor = -T(8) * length * t89;
  f = length * t89 * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 87 +, 260 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 32241 +, 55573 ×, 5602 /, 2504 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t1 = ab_ap * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = r0 * a_minus_b;
    const T t3 = T(1) / cross_cross;
    X = (t2 + ab_ap * r1) * length * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t4 - ab_ap * r1);
  }
  const T t5 = T(1) / length;
  const T J1 = asinh(X) * t5;
  T F;
  const T t6 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t7 = -ab_ap * a_minus_b;
  const T t8 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t6 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t9 = delta_tau * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t11 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t9 * delta_tau;
    const T t17 = t12 * tau_lo;
    const T t18 = t16 * t16;
    const T t19 = t18 * delta_tau;
    const T t20 = t10 * t10;
    const T t21 = t10 * delta_tau;
    const T t22 = t15 * tau_lo;
    F = T(70) * M_panels[4] * t10 * t12 + M_panels[0] * t13 + T(28) * t9 * t15 * M_panels[2] + T(56) * M_panels[3] * t16 * t17 + T(8) * M_panels[7] * t19 * tau_lo + T(28) * M_panels[6] * t18 * t11 + t20 * M_panels[8] + T(56) * t21 * t14 * M_panels[5] + T(8) * delta_tau * M_panels[1] * t22;
  } else if (t7 >= T(0) && t8 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t23 = delta_tau * delta_tau;
    const T t24 = tau_lo * tau_lo;
    const T t25 = t24 * tau_lo;
    const T t26 = t25 * t25;
    const T t27 = t23 * t23;
    const T t28 = t27 * t27;
    const T t29 = t23 * delta_tau;
    const T t30 = t24 * t24;
    const T t31 = t30 * tau_lo;
    const T t32 = t29 * t29;
    const T t33 = t32 * delta_tau;
    const T t34 = t26 * tau_lo;
    const T t35 = t27 * delta_tau;
    const T t36 = t30 * t30;
    F = T(28) * t23 * t26 * M_panels[2] + t28 * M_panels[8] + T(56) * M_panels[3] * t29 * t31 + T(8) * M_panels[7] * t33 * tau_lo + T(70) * M_panels[4] * t27 * t30 + T(8) * M_panels[1] * delta_tau * t34 + T(28) * M_panels[6] * t32 * t24 + T(56) * t35 * t25 * M_panels[5] + M_panels[0] * t36;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t37 = T(1) / r0;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = t39 * t38;
    const T t41 = T(1) / r1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t41 * a_minus_b + ab_ap * t37;
    const T t45 = T(1) / cross_cross;
    const T t46 = ab_ap * t37 * t38 + t42 * t41 * a_minus_b + T(2) * t44 * ab_ab * t45;
    const T t47 = T(3) * t43 * t41 * a_minus_b + T(3) * ab_ap * t37 * t39 + T(4) * t46 * ab_ab * t45;
    const T t48 = t43 * t42;
    const T t49 = T(2) * t47 * ab_ab * t45 + T(5) * ab_ap * t37 * t40 + T(5) * t48 * t41 * a_minus_b;
    const T t50 = T(5) * t37 * t40 + ab_ap * t49 * t45 - T(5) * t48 * t41;
    const T t51 = tau_lo * tau_lo;
    const T t52 = t51 * tau_lo;
    const T t53 = t52 * t52;
    const T t54 = t53 * tau_lo;
    const T t55 = T(1) / ab_ab;
    const T t56 = T(6) * ab_ap * t50 * t55 + T(7) * t47 * t45 - T(3) * ap_ap * t49 * t45;
    const T t57 = delta_tau * delta_tau;
    const T t58 = t51 * t51;
    const T t59 = t58 * t58;
    const T t60 = t42 * t41 - t37 * t38 - ab_ap * t46 * t45;
    const T t61 = T(3) * t37 * t39 + ab_ap * t47 * t45 - T(3) * t43 * t41;
    const T t62 = T(2) * ab_ap * t61 * t55 + T(5) * t46 * t45 - ap_ap * t47 * t45;
    const T t63 = T(5) * t60 * t55 + t61 * ap_ap * t55 - T(2) * ab_ap * t62 * t55;
    const T t64 = t41 - t37 - ab_ap * t44 * t45;
    const T t65 = ap_ap * t46 * t45 + T(2) * ab_ap * t60 * t55 - T(3) * t44 * t45;
    const T t66 = T(3) * t64 * t55 + T(2) * ab_ap * t65 * t55 - ap_ap * t60 * t55;
    const T t67 = T(2) * ab_ap * t55 * t63 + T(5) * t65 * t55 + t62 * ap_ap * t55;
    const T t68 = ap_ap * t55 * t63 - T(5) * t66 * t55 - T(2) * ab_ap * t67 * t55;
    const T t69 = T(3) * ap_ap * t50 * t55 - T(7) * t61 * t55 - T(2) * ab_ap * t56 * t55;
    const T t70 = T(2) * ab_ap * t55 * t69 + ap_ap * t56 * t55 - T(7) * t62 * t55;
    const T t71 = T(7) * t55 * t63 + T(2) * ab_ap * t70 * t55 - ap_ap * t55 * t69;
    const T t72 = t70 * ap_ap * t55 - T(2) * ab_ap * t55 * t71 - T(7) * t67 * t55;
    const T t73 = T(7) * t68 * t55 + T(2) * ab_ap * t72 * t55 + ap_ap * t55 * t71;
    const T t74 = t57 * delta_tau;
    const T t75 = t74 * t74;
    const T t76 = t75 * delta_tau;
    const T t77 = t58 * tau_lo;
    const T t78 = t57 * t57;
    const T t79 = t78 * t78;
    const T t80 = t78 * delta_tau;
    F = (T(8) / T(35)) * delta_tau * t50 * t54 * t55 + (T(4) / T(15)) * t56 * t57 * t53 * t55 + (T(1) / T(35)) * t49 * t59 * t45 + (T(8) / T(105)) * t73 * t76 * tau_lo * t55 + (T(4) / T(15)) * t75 * t72 * t51 * t55 - (T(8) / T(15)) * t74 * t77 * t55 * t69 - (T(2) / T(3)) * t70 * t78 * t58 * t55 - (T(1) / T(105)) * t79 * t55 * (ap_ap * t72 * t55 - T(2) * ab_ap * t73 * t55 - T(7) * (T(2) * ab_ap * t68 * t55 + T(5) * t55 * (t65 * ap_ap * t55 + T(3) * (J1 - T(2) * ab_ap * t64 * t55 - t44 * ap_ap * t45) * t55 - T(2) * ab_ap * t66 * t55) + t67 * ap_ap * t55) * t55) - (T(8) / T(15)) * t80 * t52 * t55 * t71;
  }
  const T t81 = in.sigma * in.sigma;
  const T t82 = t81 * t81;
  const T t83 = t82 * t82;
  const T t84 = t83 * in.sigma;
  f = length * t84 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 119 +, 368 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48153 +, 73288 ×, 4617 /, 2063 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab_ap * ab0;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * t2;
    foot2 = -t2 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -a_minus_b * ab_ap;
  const T t5 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t6 * delta_tau;
    const T t12 = t9 * tau_lo;
    const T t13 = t11 * t11;
    const T t14 = t13 * delta_tau;
    const T t15 = t7 * delta_tau;
    const T t16 = t8 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t9 * t9;
    const T t19 = t17 * tau_lo;
    const T t20 = T(70) * t7 * t9 * M_panels[14] + M_panels[18] * t10 + T(56) * M_panels[13] * t11 * t12 + T(28) * M_panels[16] * t13 * t8 + T(8) * t14 * tau_lo * M_panels[17] + T(56) * M_panels[15] * t15 * t16 + T(28) * M_panels[12] * t6 * t17 + M_panels[10] * t18 + T(8) * delta_tau * t19 * M_panels[11];
    G_ap = t20;
    const T t21 = T(1) / ab_ab;
    G_E = T(56) * M_panels[16] * t15 * t16 + T(8) * M_panels[18] * t14 * tau_lo + T(28) * M_panels[13] * t6 * t17 + t18 * M_panels[11] + T(70) * M_panels[15] * t7 * t9 + T(8) * M_panels[12] * delta_tau * t19 + M_panels[19] * t10 + T(56) * t11 * t12 * M_panels[14] + T(28) * t13 * t8 * M_panels[17] - t20 * t21 * ab_ap;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t22 = delta_tau * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = tau_lo * tau_lo;
    const T t26 = t25 * tau_lo;
    const T t27 = t22 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t23 * t23;
    const T t31 = t25 * t25;
    const T t32 = t31 * t31;
    const T t33 = t26 * t26;
    const T t34 = t33 * tau_lo;
    const T t35 = t31 * tau_lo;
    G_ap = T(56) * M_panels[15] * t24 * t26 + T(8) * M_panels[17] * t29 * tau_lo + M_panels[18] * t30 + T(70) * M_panels[14] * t23 * t31 + t32 * M_panels[10] + T(8) * M_panels[11] * delta_tau * t34 + T(56) * t27 * t35 * M_panels[13] + T(28) * t28 * t25 * M_panels[16] + T(28) * M_panels[12] * t22 * t33;
    const T t36 = T(1) / ab_ab;
    const T t37 = T(1) / r0;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = t40 * t37;
    const T t42 = t32 + T(8) * t29 * tau_lo + T(56) * t24 * t26 + T(56) * t27 * t35 + T(28) * t22 * t33 + T(28) * t28 * t25 + t30 + T(8) * delta_tau * t34 + T(70) * t23 * t31;
    const T t43 = T(1) / r1;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t43;
    G_E = (T(1) / T(9)) * t36 * (t41 * t32 + T(168) * M_panels[2] * t27 * t35 + T(280) * M_panels[3] * t23 * t31 + T(56) * M_panels[6] * t29 * tau_lo + T(56) * t22 * t33 * M_panels[1] + T(168) * M_panels[5] * t28 * t25 + T(8) * t30 * M_panels[7] + T(280) * t24 * t26 * M_panels[4] + T(8) * delta_tau * M_panels[0] * t34 - t42 * t47);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = T(1) / cross_cross;
    const T t49 = tau_lo * tau_lo;
    const T t50 = t49 * t49;
    const T t51 = t50 * t50;
    const T t52 = T(1) / r0;
    const T t53 = t52 * t52;
    const T t54 = t53 * t53;
    const T t55 = t54 * t54;
    const T t56 = T(1) / r1;
    const T t57 = t56 * t56;
    const T t58 = t57 * t57;
    const T t59 = t58 * t57;
    const T t60 = t54 * t53;
    const T t61 = t56 * a_minus_b + t52 * ab_ap;
    const T t62 = t52 * t53 * ab_ap + T(2) * ab_ab * t48 * t61 + t56 * a_minus_b * t57;
    const T t63 = T(4) * ab_ab * t48 * t62 + T(3) * t56 * a_minus_b * t58 + T(3) * t52 * t54 * ab_ap;
    const T t64 = T(5) * t56 * a_minus_b * t59 + T(5) * t52 * t60 * ab_ap + T(2) * t63 * ab_ab * t48;
    const T t65 = t58 * t58;
    const T t66 = T(35) * t52 * t55 * ab_ap + T(8) * t64 * ab_ab * t48 + T(35) * t56 * a_minus_b * t65;
    const T t67 = T(1) / ab_ab;
    const T t68 = delta_tau * delta_tau;
    const T t69 = t68 * delta_tau;
    const T t70 = t69 * t69;
    const T t71 = T(35) * t56 * t65 - t48 * ab_ap * t66 - T(35) * t52 * t55;
    const T t72 = t64 * t48 * ab_ap + T(5) * t52 * t60 - T(5) * t56 * t59;
    const T t73 = T(2) * t71 * t67 * ab_ap + ap_ap * t48 * t66 - T(9) * t64 * t48;
    const T t74 = t71 * ap_ap * t67 + T(9) * t72 * t67 - T(2) * t73 * t67 * ab_ap;
    const T t75 = T(6) * t72 * t67 * ab_ap + T(7) * t63 * t48 - T(3) * ap_ap * t64 * t48;
    const T t76 = T(2) * t74 * t67 * ab_ap + t73 * ap_ap * t67 + T(3) * t67 * t75;
    const T t77 = t63 * t48 * ab_ap + T(3) * t52 * t54 - T(3) * t56 * t58;
    const T t78 = T(7) * t77 * t67 + T(2) * t67 * ab_ap * t75 - T(3) * ap_ap * t72 * t67;
    const T t79 = T(2) * t67 * ab_ap * t76 + T(3) * t67 * t78 - ap_ap * t74 * t67;
    const T t80 = ap_ap * t63 * t48 - T(5) * t48 * t62 - T(2) * t77 * t67 * ab_ap;
    const T t81 = ap_ap * t67 * t75 + T(7) * t67 * t80 - T(2) * t67 * ab_ap * t78;
    const T t82 = T(2) * t67 * ab_ap * t79 - ap_ap * t67 * t76 - T(3) * t81 * t67;
    const T t83 = t68 * t68;
    const T t84 = t50 * tau_lo;
    const T t85 = t83 * delta_tau;
    const T t86 = t49 * tau_lo;
    const T t87 = t86 * t86;
    const T t88 = t56 * t57 - t52 * t53 - t48 * t62 * ab_ap;
    const T t89 = T(5) * t67 * t88 + T(2) * t67 * t80 * ab_ap + t77 * ap_ap * t67;
    const T t90 = ap_ap * t67 * t78 + T(7) * t89 * t67 + T(2) * t81 * t67 * ab_ap;
    const T t91 = ap_ap * t67 * t79 + T(3) * t67 * t90 - T(2) * t67 * t82 * ab_ap;
    const T t92 = t70 * delta_tau;
    const T t93 = t83 * t83;
    const T t94 = ap_ap * t48 * t62 + T(2) * t67 * t88 * ab_ap - T(3) * t48 * t61;
    const T t95 = T(2) * t89 * t67 * ab_ap + T(5) * t94 * t67 - ap_ap * t67 * t80;
    const T t96 = ap_ap * t81 * t67 - T(2) * t67 * ab_ap * t90 - T(7) * t67 * t95;
    const T t97 = t87 * tau_lo;
    G_ap = (T(1) / T(315)) * t48 * t51 * t66 + (T(4) / T(45)) * t67 * t70 * t49 * t82 + (T(2) / T(9)) * t67 * t83 * t50 * t76 + (T(8) / T(45)) * t74 * t67 * t69 * t84 + (T(8) / T(45)) * t67 * t85 * t86 * t79 - (T(4) / T(45)) * t73 * t67 * t68 * t87 - (T(8) / T(315)) * t91 * t67 * t92 * tau_lo - (T(1) / T(315)) * t67 * t93 * (T(2) * t91 * t67 * ab_ap + ap_ap * t67 * t82 - T(3) * t96 * t67) - (T(8) / T(315)) * t71 * t67 * delta_tau * t97;
    const T t98 = t52 * t52;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t52;
    const T t102 = t51 + T(8) * t92 * tau_lo + T(56) * t85 * t86 + T(56) * t69 * t84 + T(28) * t68 * t87 + T(28) * t70 * t49 + t93 + T(8) * delta_tau * t97 + T(70) * t83 * t50;
    const T t103 = t56 * t56;
    const T t104 = t103 * t103;
    const T t105 = t104 * t104;
    const T t106 = t105 * t56;
    G_E = (T(1) / T(945)) * t67 * (T(105) * t101 * t51 + T(56) * t96 * t67 * t92 * tau_lo + T(168) * t72 * t67 * t68 * t87 + T(280) * t67 * t83 * t50 * t78 + T(8) * t67 * t93 * (T(2) * t96 * t67 * ab_ap + ap_ap * t67 * t90 - T(7) * (T(2) * t67 * ab_ap * t95 + T(5) * (T(2) * t94 * t67 * ab_ap + T(3) * (t56 - t52 - t48 * ab_ap * t61) * t67 - ap_ap * t67 * t88) * t67 - ap_ap * t89 * t67) * t67) + T(168) * t67 * t69 * t84 * t75 + T(24) * t64 * delta_tau * t48 * t97 - T(168) * t67 * t70 * t49 * t90 - T(105) * t102 * t106 - T(280) * t81 * t67 * t85 * t86);
  }
  const T t107 = in.sigma * in.sigma;
  const T t108 = t107 * t107;
  const T t109 = t108 * t108;
  const T t110 = t109 * in.sigma;
  const T g_factor = -T(9) * t110 * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 136 +, 436 ×, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48162 +, 73319 ×, 4619 /, 2063 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t3 = ab_ap * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / cross_cross;
    const T t5 = ab_ap * r1;
    X = length * t4 * (t5 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = ab_ap * r1;
    X = length * (ab_ap - a_minus_b) / (t6 - r0 * a_minus_b);
  }
  const T t7 = T(1) / length;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_E;
  const T t8 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t9 = -ab_ap * a_minus_b;
  const T t10 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t8 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t11 = tau_lo * tau_lo;
    const T t12 = t11 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t13 * tau_lo;
    const T t15 = t11 * t11;
    const T t16 = t15 * tau_lo;
    const T t17 = delta_tau * delta_tau;
    const T t18 = t17 * delta_tau;
    const T t19 = t17 * t17;
    const T t20 = t19 * t19;
    const T t21 = t19 * delta_tau;
    const T t22 = t18 * t18;
    const T t23 = t15 * t15;
    const T t24 = t22 * delta_tau;
    F = T(8) * M_panels[1] * t14 * delta_tau + T(56) * M_panels[3] * t16 * t18 + M_panels[8] * t20 + T(28) * t13 * t17 * M_panels[2] + T(70) * M_panels[4] * t15 * t19 + T(56) * M_panels[5] * t12 * t21 + T(28) * M_panels[6] * t11 * t22 + M_panels[0] * t23 + T(8) * M_panels[7] * tau_lo * t24;
    const T t25 = T(8) * M_panels[17] * tau_lo * t24 + T(28) * M_panels[16] * t11 * t22 + T(28) * M_panels[12] * t13 * t17 + T(8) * M_panels[11] * t14 * delta_tau + T(56) * M_panels[15] * t12 * t21 + T(56) * M_panels[13] * t16 * t18 + T(70) * M_panels[14] * t15 * t19 + M_panels[10] * t23 + M_panels[18] * t20;
    G_ap = t25;
    const T t26 = T(1) / ab_ab;
    G_E = T(8) * M_panels[12] * t14 * delta_tau + T(56) * M_panels[14] * t16 * t18 + T(56) * M_panels[16] * t12 * t21 + T(70) * M_panels[15] * t15 * t19 + M_panels[19] * t20 + M_panels[11] * t23 + T(8) * M_panels[18] * tau_lo * t24 + T(28) * M_panels[17] * t11 * t22 + T(28) * M_panels[13] * t13 * t17 - t26 * ab_ap * t25;
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t27 = tau_lo * tau_lo;
    const T t28 = t27 * t27;
    const T t29 = delta_tau * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t27 * tau_lo;
    const T t32 = t30 * delta_tau;
    const T t33 = t30 * t30;
    const T t34 = t31 * t31;
    const T t35 = t28 * t28;
    const T t36 = t34 * tau_lo;
    const T t37 = t29 * delta_tau;
    const T t38 = t37 * t37;
    const T t39 = t38 * delta_tau;
    const T t40 = t28 * tau_lo;
    F = T(70) * t28 * t30 * M_panels[4] + T(56) * M_panels[5] * t31 * t32 + M_panels[8] * t33 + T(28) * M_panels[2] * t34 * t29 + M_panels[0] * t35 + T(8) * t36 * M_panels[1] * delta_tau + T(8) * M_panels[7] * tau_lo * t39 + T(28) * M_panels[6] * t27 * t38 + T(56) * M_panels[3] * t40 * t37;
    G_ap = T(8) * M_panels[11] * t36 * delta_tau + T(70) * M_panels[14] * t28 * t30 + T(56) * M_panels[15] * t31 * t32 + T(56) * M_panels[13] * t40 * t37 + M_panels[18] * t33 + T(28) * M_panels[16] * t27 * t38 + M_panels[10] * t35 + T(28) * M_panels[12] * t34 * t29 + T(8) * M_panels[17] * tau_lo * t39;
    const T t41 = T(1) / ab_ab;
    const T t42 = T(1) / r0;
    const T t43 = t42 * t42;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t42;
    const T t47 = T(56) * t31 * t32 + T(8) * t36 * delta_tau + T(56) * t40 * t37 + T(28) * t27 * t38 + T(28) * t34 * t29 + t35 + T(8) * tau_lo * t39 + t33 + T(70) * t28 * t30;
    const T t48 = T(1) / r1;
    const T t49 = t48 * t48;
    const T t50 = t49 * t49;
    const T t51 = t50 * t50;
    const T t52 = t51 * t48;
    G_E = (T(1) / T(9)) * t41 * (T(56) * M_panels[6] * tau_lo * t39 + T(280) * M_panels[3] * t28 * t30 + T(8) * M_panels[0] * t36 * delta_tau + T(8) * M_panels[7] * t33 + T(168) * M_panels[5] * t27 * t38 + T(168) * M_panels[2] * t40 * t37 + T(56) * t34 * M_panels[1] * t29 + T(280) * t31 * t32 * M_panels[4] + t46 * t35 - t47 * t52);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t53 = T(1) / ab_ab;
    const T t54 = T(1) / r0;
    const T t55 = t54 * t54;
    const T t56 = t55 * t55;
    const T t57 = T(1) / cross_cross;
    const T t58 = T(1) / r1;
    const T t59 = t54 * ab_ap + t58 * a_minus_b;
    const T t60 = t58 * t58;
    const T t61 = T(2) * ab_ab * t57 * t59 + t54 * ab_ap * t55 + t60 * t58 * a_minus_b;
    const T t62 = t60 * t60;
    const T t63 = T(3) * t54 * ab_ap * t56 + T(4) * ab_ab * t57 * t61 + T(3) * t62 * t58 * a_minus_b;
    const T t64 = t56 * t55;
    const T t65 = t62 * t60;
    const T t66 = T(5) * t54 * ab_ap * t64 + T(2) * t63 * ab_ab * t57 + T(5) * t65 * t58 * a_minus_b;
    const T t67 = t66 * t57 * ab_ap + T(5) * t54 * t64 - T(5) * t65 * t58;
    const T t68 = T(7) * t63 * t57 + T(6) * t53 * ab_ap * t67 - T(3) * t66 * t57 * ap_ap;
    const T t69 = t63 * t57 * ab_ap + T(3) * t54 * t56 - T(3) * t62 * t58;
    const T t70 = T(2) * t53 * ab_ap * t68 + T(7) * t53 * t69 - T(3) * t53 * ap_ap * t67;
    const T t71 = T(2) * t53 * t69 * ab_ap + T(5) * t57 * t61 - t63 * t57 * ap_ap;
    const T t72 = T(2) * t70 * t53 * ab_ap + T(7) * t53 * t71 - t53 * t68 * ap_ap;
    const T t73 = tau_lo * tau_lo;
    const T t74 = t73 * t73;
    const T t75 = delta_tau * delta_tau;
    const T t76 = t75 * t75;
    const T t77 = t74 * t74;
    const T t78 = t74 * tau_lo;
    const T t79 = t75 * delta_tau;
    const T t80 = t73 * tau_lo;
    const T t81 = t80 * t80;
    const T t82 = t81 * tau_lo;
    const T t83 = t60 * t58 - t57 * ab_ap * t61 - t54 * t55;
    const T t84 = t53 * t69 * ap_ap + T(5) * t53 * t83 - T(2) * t53 * t71 * ab_ap;
    const T t85 = T(7) * t53 * t84 + t70 * t53 * ap_ap - T(2) * t53 * t72 * ab_ap;
    const T t86 = t57 * t61 * ap_ap + T(2) * t53 * t83 * ab_ap - T(3) * t57 * t59;
    const T t87 = T(5) * t53 * t86 + T(2) * t53 * ab_ap * t84 + t53 * t71 * ap_ap;
    const T t88 = t53 * t72 * ap_ap + T(2) * t53 * t85 * ab_ap + T(7) * t53 * t87;
    const T t89 = t79 * t79;
    const T t90 = t57 * ab_ap * t59 + t54 - t58;
    const T t91 = T(2) * t53 * ab_ap * t86 - t53 * t83 * ap_ap - T(3) * t53 * t90;
    const T t92 = T(2) * t53 * ab_ap * t87 + T(5) * t53 * t91 - t53 * t84 * ap_ap;
    const T t93 = T(2) * t53 * t88 * ab_ap + T(7) * t92 * t53 - t53 * t85 * ap_ap;
    const T t94 = t76 * t76;
    const T t95 = t76 * delta_tau;
    const T t96 = t89 * delta_tau;
    F = (T(2) / T(3)) * t53 * t72 * t74 * t76 + (T(1) / T(35)) * t66 * t57 * t77 + (T(8) / T(15)) * t70 * t53 * t78 * t79 + (T(4) / T(15)) * t53 * t68 * t81 * t75 + (T(8) / T(35)) * t53 * t67 * t82 * delta_tau - (T(4) / T(15)) * t53 * t88 * t73 * t89 - (T(1) / T(105)) * t53 * (T(7) * t53 * (T(2) * t92 * t53 * ab_ap - t53 * t87 * ap_ap - T(5) * t53 * (t53 * ap_ap * t86 + T(3) * t53 * (J1 + T(2) * t53 * ab_ap * t90 - t57 * t59 * ap_ap) - T(2) * t53 * ab_ap * t91)) + T(2) * t53 * t93 * ab_ap - t53 * t88 * ap_ap) * t94 - (T(8) / T(15)) * t53 * t85 * t80 * t95 - (T(8) / T(105)) * t53 * t93 * tau_lo * t96;
    const T t97 = t56 * t56;
    const T t98 = t62 * t62;
    const T t99 = T(35) * t54 * ab_ap * t97 + T(35) * t98 * t58 * a_minus_b + T(8) * t66 * ab_ab * t57;
    const T t100 = t99 * t57 * ab_ap + T(35) * t54 * t97 - T(35) * t98 * t58;
    const T t101 = T(2) * t53 * t100 * ab_ap + T(9) * t66 * t57 - t99 * t57 * ap_ap;
    const T t102 = T(9) * t53 * t67 + T(2) * t53 * t101 * ab_ap - t53 * t100 * ap_ap;
    const T t103 = T(2) * t53 * ab_ap * t102 + T(3) * t53 * t68 - t53 * t101 * ap_ap;
    const T t104 = t53 * ap_ap * t102 - T(2) * t53 * t103 * ab_ap - T(3) * t70 * t53;
    const T t105 = t53 * t103 * ap_ap + T(2) * t53 * ab_ap * t104 - T(3) * t53 * t72;
    const T t106 = T(3) * t53 * t85 + T(2) * t105 * t53 * ab_ap - t53 * ap_ap * t104;
    G_ap = (T(1) / T(315)) * t99 * t57 * t77 + (T(4) / T(45)) * t53 * t101 * t81 * t75 + (T(8) / T(45)) * t53 * t102 * t78 * t79 + (T(8) / T(315)) * t53 * t100 * t82 * delta_tau + (T(2) / T(9)) * t53 * t103 * t74 * t76 - (T(1) / T(315)) * t53 * (T(2) * t53 * ab_ap * t106 + T(3) * t53 * t88 - t105 * t53 * ap_ap) * t94 - (T(4) / T(45)) * t105 * t53 * t73 * t89 - (T(8) / T(45)) * t53 * t104 * t80 * t95 - (T(8) / T(315)) * t53 * t106 * tau_lo * t96;
    const T t107 = t54 * t54;
    const T t108 = t107 * t107;
    const T t109 = t108 * t108;
    const T t110 = t109 * t54;
    const T t111 = T(56) * t80 * t95 + T(8) * t82 * delta_tau + T(56) * t78 * t79 + T(28) * t73 * t89 + T(28) * t81 * t75 + t77 + T(8) * tau_lo * t96 + t94 + T(70) * t74 * t76;
    const T t112 = t58 * t58;
    const T t113 = t112 * t112;
    const T t114 = t113 * t113;
    const T t115 = t114 * t58;
    G_E = (T(1) / T(945)) * t53 * (T(24) * t66 * t57 * t82 * delta_tau + T(280) * t70 * t53 * t74 * t76 + T(105) * t110 * t77 + T(168) * t53 * t68 * t78 * t79 + T(168) * t53 * t67 * t81 * t75 + T(280) * t53 * t72 * t80 * t95 - T(8) * t53 * t93 * t94 - T(168) * t53 * t85 * t73 * t89 - T(105) * t111 * t115 - T(56) * t53 * t88 * tau_lo * t96);
  }
  const T t116 = in.sigma * in.sigma;
  const T t117 = t116 * t116;
  const T t118 = t117 * t117;
  const T t119 = t118 * in.sigma;
  const T g_factor = -T(9) * length * t119;
  f = length * t119 * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 99 +, 286 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 31433 +, 43969 ×, 5083 /, 111 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t1 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = max(T((T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t4 = tau_lo * tau_lo;
    const T t5 = t4 * t4;
    const T t6 = t5 * tau_lo;
    const T t7 = delta_tau * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t4 * tau_lo;
    const T t10 = t7 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t8 * delta_tau;
    const T t13 = t5 * t5;
    const T t14 = t13 * tau_lo;
    const T t15 = t9 * t9;
    const T t16 = t15 * tau_lo;
    const T t17 = t11 * delta_tau;
    const T t18 = t8 * t8;
    const T t19 = t18 * delta_tau;
    F = T(126) * t6 * M_panels[4] * t8 + T(84) * t9 * M_panels[6] * t11 + T(126) * t5 * M_panels[5] * t12 + t14 * M_panels[0] + T(9) * M_panels[1] * t13 * delta_tau + T(36) * t16 * M_panels[2] * t7 + T(36) * t4 * M_panels[7] * t17 + T(84) * t15 * M_panels[3] * t10 + M_panels[9] * t19 + T(9) * tau_lo * M_panels[8] * t18;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t20 = tau_lo * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * tau_lo;
    const T t24 = delta_tau * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t25 * delta_tau;
    const T t27 = t25 * t25;
    const T t28 = t27 * delta_tau;
    const T t29 = t21 * tau_lo;
    const T t30 = t24 * delta_tau;
    const T t31 = t30 * t30;
    const T t32 = t31 * delta_tau;
    const T t33 = t20 * tau_lo;
    const T t34 = t33 * t33;
    const T t35 = t34 * tau_lo;
    F = t23 * M_panels[0] + T(126) * t21 * M_panels[5] * t26 + M_panels[9] * t28 + T(126) * t29 * M_panels[4] * t25 + T(9) * t22 * M_panels[1] * delta_tau + T(36) * t20 * M_panels[7] * t32 + T(9) * tau_lo * M_panels[8] * t27 + T(84) * t34 * M_panels[3] * t30 + T(36) * t35 * M_panels[2] * t24 + T(84) * t33 * M_panels[6] * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = sqrt(cross_cross);
    const T t37 = T(1) / t36;
    const T J2 = t37 * atan2(t36, ap_bp);
    const T t38 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t38);
    const T t39 = T(1) / ab_ab;
    const T t40 = T(1) / bp_bp;
    const T t41 = t40 * t40;
    const T t42 = t38 * t38;
    const T t43 = T(1) / cross_cross;
    const T t44 = J2 * ab_ab + ab_ap * t38 + a_minus_b * t40;
    const T t45 = T(2) * a_minus_b * t41 + T(2) * ab_ap * t42 + T(3) * ab_ab * t43 * t44;
    const T t46 = T(2) * t41 - T(2) * t42 - t43 * t45 * ab_ap;
    const T t47 = T(2) * t39 * ab_ap * t46 + t43 * t45 * ap_ap - T(4) * t43 * t44;
    const T t48 = t41 * t40;
    const T t49 = t42 * t38;
    const T t50 = T(5) * ab_ab * t43 * t45 + T(8) * a_minus_b * t48 + T(8) * ab_ap * t49;
    const T t51 = t50 * t43 * ab_ap + T(8) * t49 - T(8) * t48;
    const T t52 = T(6) * t43 * t45 + T(2) * t39 * t51 * ab_ap - t50 * t43 * ap_ap;
    const T t53 = T(2) * t39 * ab_ap * t52 - t39 * t51 * ap_ap - T(6) * t39 * t46;
    const T t54 = T(6) * t39 * t47 + t39 * ap_ap * t52 - T(2) * t39 * t53 * ab_ap;
    const T t55 = t42 * t42;
    const T t56 = t41 * t41;
    const T t57 = T(48) * ab_ap * t55 + T(48) * a_minus_b * t56 + T(7) * t50 * ab_ab * t43;
    const T t58 = T(48) * t55 + t43 * ab_ap * t57 - T(48) * t56;
    const T t59 = t43 * ap_ap * t57 - T(2) * t39 * ab_ap * t58 - T(8) * t50 * t43;
    const T t60 = t39 * ap_ap * t58 + T(2) * t39 * ab_ap * t59 - T(8) * t39 * t51;
    const T t61 = T(2) * t60 * t39 * ab_ap - t39 * t59 * ap_ap - T(8) * t39 * t52;
    const T t62 = T(2) * t39 * ab_ap * t61 - t60 * t39 * ap_ap - T(8) * t39 * t53;
    const T t63 = T(8) * t39 * t54 + T(2) * t39 * t62 * ab_ap - t39 * ap_ap * t61;
    const T t64 = t38 + t43 * ab_ap * t44 - t40;
    const T t65 = T(4) * t39 * t64 + t39 * ap_ap * t46 - T(2) * t39 * t47 * ab_ap;
    const T t66 = T(2) * J2 + T(2) * t39 * ab_ap * t64 - t43 * t44 * ap_ap;
    const T t67 = t39 * t47 * ap_ap + T(2) * t39 * t65 * ab_ap + T(4) * t39 * t66;
    const T t68 = t39 * t53 * ap_ap + T(2) * t39 * ab_ap * t54 - T(6) * t39 * t65;
    const T t69 = t39 * t54 * ap_ap + T(6) * t39 * t67 - T(2) * t68 * t39 * ab_ap;
    const T t70 = T(2) * t39 * ab_ap * t63 + T(8) * t68 * t39 - t39 * t62 * ap_ap;
    const T t71 = t39 * t63 * ap_ap + T(8) * t69 * t39 - T(2) * t39 * t70 * ab_ap;
    const T t72 = delta_tau * delta_tau;
    const T t73 = t72 * t72;
    const T t74 = t73 * t73;
    const T t75 = tau_lo * tau_lo;
    const T t76 = t75 * t75;
    const T t77 = t76 * t76;
    const T t78 = t74 * delta_tau;
    const T t79 = t77 * tau_lo;
    const T t80 = t75 * tau_lo;
    const T t81 = t80 * t80;
    const T t82 = t72 * delta_tau;
    const T t83 = t73 * delta_tau;
    const T t84 = t81 * tau_lo;
    const T t85 = t82 * t82;
    const T t86 = t85 * delta_tau;
    const T t87 = t76 * tau_lo;
    F = (T(3) / T(128)) * tau_lo * t39 * t71 * t74 + (T(3) / T(128)) * t77 * t39 * t58 * delta_tau + (T(1) / T(384)) * t39 * (T(8) * t39 * (T(2) * t69 * t39 * ab_ap + T(6) * t39 * (T(2) * t39 * t67 * ab_ap + T(4) * t39 * (T(2) * t39 * t66 * ab_ap + t39 * (log_ratio + T(2) * J2 * ab_ap) - t39 * t64 * ap_ap) - t39 * t65 * ap_ap) + t68 * t39 * ap_ap) + T(2) * t39 * t71 * ab_ap + t39 * t70 * ap_ap) * t78 + (T(1) / T(384)) * t79 * t43 * t57 - (T(7) / T(32)) * t81 * t60 * t39 * t82 - (T(21) / T(64)) * t76 * t39 * t62 * t83 - (T(3) / T(32)) * t84 * t39 * t59 * t72 - (T(3) / T(32)) * t75 * t39 * t70 * t86 - (T(21) / T(64)) * t87 * t39 * t73 * t61 - (T(7) / T(32)) * t80 * t39 * t63 * t85;
  }
  const T t88 = in.sigma * in.sigma;
  const T t89 = t88 * t88;
  const T t90 = t89 * in.sigma;
  const T t91 = t90 * t90;
  f = length * t91 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 135 +, 399 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 47838 +, 61931 ×, 4241 /, 93 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * ab_ap * t1;
    foot1 = ap1 - ab1 * ab_ap * t1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = -(exact_cross[0] * ab2 - ab0 * exact_cross[2]) * t2;
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = tau_lo * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = delta_tau * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t6 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t8 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t15 * delta_tau;
    const T t17 = t7 * tau_lo;
    const T t18 = t7 * t7;
    const T t19 = t9 * t9;
    const T t20 = t19 * delta_tau;
    const T t21 = t18 * tau_lo;
    const T t22 = T(126) * t7 * t10 * M_panels[16] + T(36) * t13 * t8 * M_panels[13] + T(84) * M_panels[14] * t12 * t14 + T(36) * M_panels[18] * t6 * t16 + T(126) * M_panels[15] * t17 * t9 + T(9) * M_panels[12] * t18 * delta_tau + M_panels[20] * t20 + T(9) * M_panels[19] * tau_lo * t19 + T(84) * M_panels[17] * t11 * t15 + M_panels[11] * t21;
    G_ap = t22;
    const T t23 = T(1) / ab_ab;
    G_E = T(36) * M_panels[14] * t13 * t8 + T(126) * M_panels[17] * t7 * t10 + T(9) * M_panels[20] * tau_lo * t19 + T(126) * t17 * t9 * M_panels[16] + T(84) * M_panels[18] * t11 * t15 + M_panels[12] * t21 + T(84) * M_panels[15] * t12 * t14 + T(36) * M_panels[19] * t6 * t16 + M_panels[21] * t20 + T(9) * t18 * delta_tau * M_panels[13] - t22 * ab_ap * t23;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t24 = tau_lo * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * tau_lo;
    const T t28 = t24 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = t29 * tau_lo;
    const T t31 = delta_tau * delta_tau;
    const T t32 = t31 * delta_tau;
    const T t33 = t32 * t32;
    const T t34 = t33 * delta_tau;
    const T t35 = t25 * tau_lo;
    const T t36 = t31 * t31;
    const T t37 = t36 * t36;
    const T t38 = t37 * delta_tau;
    const T t39 = t36 * delta_tau;
    G_ap = M_panels[11] * t27 + T(36) * t30 * t31 * M_panels[13] + T(36) * M_panels[18] * t24 * t34 + T(84) * M_panels[14] * t29 * t32 + T(126) * M_panels[15] * t35 * t36 + M_panels[20] * t38 + T(84) * M_panels[17] * t28 * t33 + T(126) * M_panels[16] * t25 * t39 + T(9) * tau_lo * M_panels[19] * t37 + T(9) * M_panels[12] * t26 * delta_tau;
    const T t40 = T(1) / ap_ap;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = t42 * t40;
    const T t44 = T(126) * t25 * t39 + T(126) * t35 * t36 + t38 + T(84) * t28 * t33 + t27 + T(9) * t26 * delta_tau + T(9) * tau_lo * t37 + T(36) * t24 * t34 + T(84) * t29 * t32 + T(36) * t30 * t31;
    const T t45 = T(1) / bp_bp;
    const T t46 = t45 * t45;
    const T t47 = t46 * t46;
    const T t48 = t47 * t45;
    const T t49 = T(1) / ab_ab;
    G_E = (T(1) / T(10)) * (T(630) * M_panels[4] * t25 * t39 + T(72) * t30 * t31 * M_panels[1] + t43 * t27 + T(504) * M_panels[5] * t28 * t33 + T(9) * M_panels[0] * t26 * delta_tau + T(252) * M_panels[6] * t24 * t34 + T(72) * tau_lo * t37 * M_panels[7] + T(9) * M_panels[8] * t38 + T(504) * M_panels[3] * t35 * t36 + T(252) * M_panels[2] * t29 * t32 - t44 * t48) * t49;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t50 = sqrt(cross_cross);
    const T t51 = T(1) / t50;
    const T J2 = t51 * atan2(t50, ap_bp);
    const T t52 = T(1) / cross_cross;
    const T t53 = T(1) / bp_bp;
    const T t54 = t53 * t53;
    const T t55 = T(1) / ap_ap;
    const T t56 = ab_ap * t55 + J2 * ab_ab + a_minus_b * t53;
    const T t57 = t55 * t55;
    const T t58 = T(2) * a_minus_b * t54 + T(3) * t52 * t56 * ab_ab + T(2) * ab_ap * t57;
    const T t59 = t54 * t53;
    const T t60 = t57 * t55;
    const T t61 = T(5) * t52 * t58 * ab_ab + T(8) * a_minus_b * t59 + T(8) * ab_ap * t60;
    const T t62 = t52 * ab_ap * t61 + T(8) * t60 - T(8) * t59;
    const T t63 = T(1) / ab_ab;
    const T t64 = t54 * t54;
    const T t65 = t57 * t57;
    const T t66 = T(7) * t52 * t61 * ab_ab + T(48) * a_minus_b * t64 + T(48) * ab_ap * t65;
    const T t67 = T(48) * t65 + t52 * ab_ap * t66 - T(48) * t64;
    const T t68 = t52 * ap_ap * t66 - T(2) * ab_ap * t67 * t63 - T(8) * t52 * t61;
    const T t69 = T(8) * t62 * t63 - T(2) * t68 * ab_ap * t63 - ap_ap * t67 * t63;
    const T t70 = t65 * t55;
    const T t71 = t64 * t53;
    const T t72 = T(3) * t52 * t66 * ab_ab + T(128) * a_minus_b * t71 + T(128) * ab_ap * t70;
    const T t73 = T(128) * t70 + t52 * ab_ap * t72 - T(128) * t71;
    const T t74 = T(3) * t52 * ap_ap * t72 - T(10) * t52 * t66 - T(6) * t73 * ab_ap * t63;
    const T t75 = T(3) * t73 * ap_ap * t63 + T(2) * ab_ap * t74 * t63 - T(10) * t67 * t63;
    const T t76 = T(2) * ab_ap * t63 * t75 + T(10) * t68 * t63 - t74 * ap_ap * t63;
    const T t77 = T(10) * t69 * t63 + ap_ap * t63 * t75 - T(2) * ab_ap * t76 * t63;
    const T t78 = tau_lo * tau_lo;
    const T t79 = t78 * t78;
    const T t80 = delta_tau * delta_tau;
    const T t81 = t80 * t80;
    const T t82 = t81 * delta_tau;
    const T t83 = t79 * t79;
    const T t84 = t83 * tau_lo;
    const T t85 = T(2) * ab_ap * t62 * t63 + T(6) * t52 * t58 - t52 * t61 * ap_ap;
    const T t86 = t68 * ap_ap * t63 + T(2) * ab_ap * t69 * t63 + T(8) * t85 * t63;
    const T t87 = ap_ap * t76 * t63 + T(10) * t86 * t63 + T(2) * ab_ap * t77 * t63;
    const T t88 = T(2) * t57 + t52 * ab_ap * t58 - T(2) * t54;
    const T t89 = T(2) * ab_ap * t85 * t63 + T(6) * t88 * t63 - t62 * ap_ap * t63;
    const T t90 = T(8) * t89 * t63 + T(2) * ab_ap * t86 * t63 - t69 * ap_ap * t63;
    const T t91 = T(2) * ab_ap * t87 * t63 + T(10) * t90 * t63 - t77 * ap_ap * t63;
    const T t92 = t80 * delta_tau;
    const T t93 = t92 * t92;
    const T t94 = t93 * delta_tau;
    const T t95 = t78 * tau_lo;
    const T t96 = T(4) * t52 * t56 + T(2) * t88 * ab_ap * t63 - t52 * t58 * ap_ap;
    const T t97 = T(6) * t96 * t63 + T(2) * t89 * ab_ap * t63 - ap_ap * t85 * t63;
    const T t98 = T(2) * t90 * ab_ap * t63 + T(8) * t97 * t63 - ap_ap * t86 * t63;
    const T t99 = ap_ap * t87 * t63 - T(10) * t98 * t63 - T(2) * t91 * ab_ap * t63;
    const T t100 = t81 * t81;
    const T t101 = t95 * t95;
    const T t102 = t101 * tau_lo;
    const T t103 = t53 - t52 * ab_ap * t56 - t55;
    const T t104 = t88 * ap_ap * t63 + T(4) * t63 * t103 - T(2) * ab_ap * t96 * t63;
    const T t105 = t89 * ap_ap * t63 + T(6) * t104 * t63 - T(2) * ab_ap * t97 * t63;
    const T t106 = T(2) * ab_ap * t98 * t63 - t90 * ap_ap * t63 - T(8) * t63 * t105;
    const T t107 = t100 * delta_tau;
    const T t108 = t79 * tau_lo;
    G_ap = (T(21) / T(640)) * t77 * t79 * t82 * t63 + (T(9) / T(1280)) * t73 * t83 * delta_tau * t63 + (T(1) / T(1280)) * t52 * t72 * t84 + (T(3) / T(320)) * t91 * t78 * t94 * t63 + (T(7) / T(320)) * t87 * t95 * t93 * t63 - (T(3) / T(1280)) * t99 * tau_lo * t100 * t63 - (T(7) / T(320)) * t101 * t92 * t63 * t75 - (T(3) / T(320)) * t74 * t102 * t80 * t63 - (T(1) / T(3840)) * (t91 * ap_ap * t63 + T(2) * ab_ap * t99 * t63 - T(10) * t63 * t106) * t107 * t63 - (T(21) / T(640)) * t76 * t108 * t81 * t63;
    const T t109 = T(126) * t79 * t82 + T(126) * t108 * t81 + t107 + T(84) * t95 * t93 + t84 + T(9) * t83 * delta_tau + T(9) * tau_lo * t100 + T(36) * t78 * t94 + T(84) * t101 * t92 + T(36) * t102 * t80;
    G_E = (T(1) / T(1280)) * (T(84) * t98 * t78 * t94 * t63 + T(24) * tau_lo * t100 * t63 * t106 + T(24) * t102 * t80 * t67 * t63 + T(3) * t52 * t66 * t83 * delta_tau + T(128) * t70 * t84 + T(168) * t90 * t95 * t93 * t63 + T(210) * t86 * t79 * t82 * t63 + T(3) * (T(2) * ab_ap * t63 * t106 - T(8) * (T(2) * ab_ap * t63 * t105 + ap_ap * t97 * t63 + T(6) * t63 * (ap_ap * t96 * t63 + T(2) * ab_ap * t104 * t63 - T(4) * t63 * (T(2) * J2 - T(2) * ab_ap * t63 * t103 - t52 * t56 * ap_ap))) * t63 - ap_ap * t98 * t63) * t107 * t63 + T(168) * t69 * t108 * t81 * t63 - T(84) * t68 * t101 * t92 * t63 - T(128) * t109 * t71) * t63;
  }
  const T t110 = in.sigma * in.sigma;
  const T t111 = t110 * t110;
  const T t112 = t111 * in.sigma;
  const T t113 = t112 * t112;
  const T g_factor = -T(10) * length * t113;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 153 +, 469 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 47847 +, 61959 ×, 4241 /, 93 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    foot0 = ap0 - ab_ap * ab0 * t1;
    foot1 = ap1 - ab_ap * ab1 * t1;
    foot2 = ap2 - ab_ap * t1 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    const T t2 = T(1) / ab_ab;
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = t2 * (ab0 * exact_cross[2] - exact_cross[0] * ab2);
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * cross_cross - ab_ab * ab_ab;
  const T t4 = -ab_ap * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross), T(T(100) * cross_cross - ab_ab * ab_ab));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t6 = delta_tau * delta_tau;
    const T t7 = t6 * delta_tau;
    const T t8 = tau_lo * tau_lo;
    const T t9 = t8 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t7 * t7;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * t6;
    const T t14 = t13 * delta_tau;
    const T t15 = t8 * t8;
    const T t16 = t15 * tau_lo;
    const T t17 = t15 * t15;
    const T t18 = t13 * t13;
    const T t19 = t18 * delta_tau;
    const T t20 = t17 * tau_lo;
    const T t21 = t10 * tau_lo;
    F = T(84) * M_panels[3] * t7 * t10 + T(36) * M_panels[7] * t12 * t8 + T(126) * t14 * M_panels[5] * t15 + T(126) * M_panels[4] * t13 * t16 + T(9) * M_panels[1] * delta_tau * t17 + T(84) * t11 * t9 * M_panels[6] + t19 * M_panels[9] + M_panels[0] * t20 + T(36) * t6 * t21 * M_panels[2] + T(9) * M_panels[8] * t18 * tau_lo;
    const T t22 = M_panels[11] * t20 + T(36) * t12 * t8 * M_panels[18] + T(84) * M_panels[14] * t7 * t10 + T(9) * delta_tau * t17 * M_panels[12] + T(126) * t13 * t16 * M_panels[15] + T(84) * M_panels[17] * t11 * t9 + T(9) * M_panels[19] * t18 * tau_lo + T(126) * M_panels[16] * t14 * t15 + M_panels[20] * t19 + T(36) * M_panels[13] * t6 * t21;
    G_ap = t22;
    const T t23 = T(1) / ab_ab;
    G_E = T(84) * t7 * t10 * M_panels[15] + T(84) * t11 * t9 * M_panels[18] + T(9) * M_panels[20] * t18 * tau_lo + T(36) * M_panels[14] * t6 * t21 + T(126) * M_panels[17] * t14 * t15 + T(36) * M_panels[19] * t12 * t8 + T(9) * M_panels[13] * delta_tau * t17 + T(126) * M_panels[16] * t13 * t16 + t19 * M_panels[21] + t20 * M_panels[12] - ab_ap * t23 * t22;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, ab_ab, ab_ap, a_minus_b, cross_cross, M_panels.data());
    const T t24 = delta_tau * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = t24 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = tau_lo * tau_lo;
    const T t31 = t30 * tau_lo;
    const T t32 = t30 * t30;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = t31 * t31;
    const T t36 = t35 * tau_lo;
    const T t37 = t29 * delta_tau;
    const T t38 = t32 * tau_lo;
    const T t39 = t25 * delta_tau;
    F = t27 * M_panels[9] + T(84) * t29 * t31 * M_panels[6] + M_panels[0] * t34 + T(36) * t24 * M_panels[2] * t36 + T(36) * M_panels[7] * t37 * t30 + T(126) * M_panels[4] * t25 * t38 + T(84) * t28 * t35 * M_panels[3] + T(9) * M_panels[8] * t26 * tau_lo + T(126) * M_panels[5] * t39 * t32 + T(9) * M_panels[1] * delta_tau * t33;
    G_ap = M_panels[11] * t34 + T(126) * M_panels[16] * t39 * t32 + T(84) * M_panels[17] * t29 * t31 + T(36) * M_panels[13] * t24 * t36 + M_panels[20] * t27 + T(126) * t25 * t38 * M_panels[15] + T(9) * delta_tau * t33 * M_panels[12] + T(9) * t26 * tau_lo * M_panels[19] + T(84) * M_panels[14] * t28 * t35 + T(36) * t37 * t30 * M_panels[18];
    const T t40 = T(1) / ap_ap;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = t42 * t40;
    const T t44 = T(1) / bp_bp;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t44;
    const T t48 = T(9) * delta_tau * t33 + t27 + T(84) * t28 * t35 + T(9) * t26 * tau_lo + t34 + T(84) * t29 * t31 + T(36) * t37 * t30 + T(36) * t24 * t36 + T(126) * t39 * t32 + T(126) * t25 * t38;
    const T t49 = T(1) / ab_ab;
    G_E = (T(1) / T(10)) * (T(504) * t25 * t38 * M_panels[3] + T(72) * M_panels[7] * t26 * tau_lo + T(252) * t37 * t30 * M_panels[6] + T(9) * M_panels[0] * delta_tau * t33 + T(504) * M_panels[5] * t29 * t31 + T(9) * M_panels[8] * t27 + T(252) * t28 * M_panels[2] * t35 + T(72) * M_panels[1] * t24 * t36 + T(630) * M_panels[4] * t39 * t32 + t43 * t34 - t47 * t48) * t49;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t50 = sqrt(cross_cross);
    const T t51 = T(1) / t50;
    const T J2 = t51 * atan2(t50, ap_bp);
    const T t52 = T(1) / ap_ap;
    const T log_ratio = log(bp_bp * t52);
    const T t53 = delta_tau * delta_tau;
    const T t54 = t53 * t53;
    const T t55 = t54 * delta_tau;
    const T t56 = tau_lo * tau_lo;
    const T t57 = t56 * t56;
    const T t58 = T(1) / cross_cross;
    const T t59 = T(1) / bp_bp;
    const T t60 = ab_ap * t52 + J2 * ab_ab + t59 * a_minus_b;
    const T t61 = t59 * t59;
    const T t62 = t52 * t52;
    const T t63 = T(3) * t58 * t60 * ab_ab + T(2) * t61 * a_minus_b + T(2) * ab_ap * t62;
    const T t64 = t58 * ab_ap * t63 + T(2) * t62 - T(2) * t61;
    const T t65 = T(1) / ab_ab;
    const T t66 = t61 * t59;
    const T t67 = t62 * t52;
    const T t68 = T(5) * t58 * t63 * ab_ab + T(8) * t66 * a_minus_b + T(8) * ab_ap * t67;
    const T t69 = t58 * t68 * ab_ap + T(8) * t67 - T(8) * t66;
    const T t70 = t58 * t68 * ap_ap - T(2) * t69 * ab_ap * t65 - T(6) * t58 * t63;
    const T t71 = T(6) * t64 * t65 - t69 * ap_ap * t65 - T(2) * ab_ap * t70 * t65;
    const T t72 = t61 * t61;
    const T t73 = t62 * t62;
    const T t74 = T(48) * t72 * a_minus_b + T(7) * t58 * t68 * ab_ab + T(48) * ab_ap * t73;
    const T t75 = T(48) * t73 + t58 * ab_ap * t74 - T(48) * t72;
    const T t76 = t58 * ap_ap * t74 - T(8) * t58 * t68 - T(2) * ab_ap * t75 * t65;
    const T t77 = T(2) * t76 * ab_ap * t65 + ap_ap * t75 * t65 - T(8) * t69 * t65;
    const T t78 = T(2) * ab_ap * t65 * t77 + T(8) * t70 * t65 - t76 * ap_ap * t65;
    const T t79 = T(8) * t71 * t65 + ap_ap * t65 * t77 - T(2) * ab_ap * t78 * t65;
    const T t80 = t57 * t57;
    const T t81 = t80 * tau_lo;
    const T t82 = T(4) * t58 * t60 + T(2) * ab_ap * t64 * t65 - t58 * ap_ap * t63;
    const T t83 = ap_ap * t70 * t65 + T(6) * t82 * t65 + T(2) * ab_ap * t71 * t65;
    const T t84 = ap_ap * t78 * t65 + T(8) * t83 * t65 + T(2) * ab_ap * t79 * t65;
    const T t85 = t59 - t52 - t58 * ab_ap * t60;
    const T t86 = T(2) * ab_ap * t82 * t65 - ap_ap * t64 * t65 - T(4) * t85 * t65;
    const T t87 = T(6) * t86 * t65 + T(2) * ab_ap * t83 * t65 - ap_ap * t71 * t65;
    const T t88 = T(2) * ab_ap * t84 * t65 + T(8) * t65 * t87 - ap_ap * t79 * t65;
    const T t89 = t53 * delta_tau;
    const T t90 = t89 * t89;
    const T t91 = t90 * delta_tau;
    const T t92 = t56 * tau_lo;
    const T t93 = T(2) * t85 * ab_ap * t65 + t58 * ap_ap * t60 - T(2) * J2;
    const T t94 = t82 * ap_ap * t65 + T(4) * t93 * t65 - T(2) * ab_ap * t86 * t65;
    const T t95 = T(2) * ab_ap * t65 * t87 - T(6) * t65 * t94 - t83 * ap_ap * t65;
    const T t96 = T(8) * t95 * t65 + T(2) * t88 * ab_ap * t65 - t84 * ap_ap * t65;
    const T t97 = t54 * t54;
    const T t98 = t92 * t92;
    const T t99 = t98 * tau_lo;
    const T t100 = t97 * delta_tau;
    const T t101 = t57 * tau_lo;
    F = (T(21) / T(64)) * t55 * t57 * t79 * t65 + (T(1) / T(384)) * t58 * t81 * t74 + (T(3) / T(32)) * t88 * t91 * t56 * t65 + (T(7) / T(32)) * t84 * t90 * t92 * t65 + (T(3) / T(128)) * t75 * delta_tau * t80 * t65 + (T(3) / T(128)) * t96 * t97 * tau_lo * t65 - (T(7) / T(32)) * t89 * t98 * t65 * t77 - (T(3) / T(32)) * t76 * t53 * t99 * t65 - (T(1) / T(384)) * t100 * (T(8) * (T(6) * (T(2) * ab_ap * t65 * t94 + T(4) * (T(2) * ab_ap * t93 * t65 - t85 * ap_ap * t65 - (T(2) * ab_ap * J2 + log_ratio) * t65) * t65 + t86 * ap_ap * t65) * t65 + ap_ap * t65 * t87 - T(2) * ab_ap * t95 * t65) * t65 + t88 * ap_ap * t65 - T(2) * ab_ap * t96 * t65) * t65 - (T(21) / T(64)) * t54 * t101 * t78 * t65;
    const T t102 = t73 * t52;
    const T t103 = t72 * t59;
    const T t104 = T(128) * t103 * a_minus_b + T(3) * t58 * ab_ab * t74 + T(128) * ab_ap * t102;
    const T t105 = T(128) * t102 + t58 * ab_ap * t104 - T(128) * t103;
    const T t106 = T(10) * t58 * t74 + T(6) * ab_ap * t105 * t65 - T(3) * t58 * ap_ap * t104;
    const T t107 = T(10) * t75 * t65 + T(2) * ab_ap * t106 * t65 - T(3) * t105 * ap_ap * t65;
    const T t108 = T(2) * t107 * ab_ap * t65 - t106 * ap_ap * t65 - T(10) * t76 * t65;
    const T t109 = T(2) * ab_ap * t108 * t65 - t107 * ap_ap * t65 - T(10) * t65 * t77;
    const T t110 = T(10) * t78 * t65 + t108 * ap_ap * t65 - T(2) * ab_ap * t109 * t65;
    const T t111 = T(10) * t79 * t65 - T(2) * ab_ap * t110 * t65 - t109 * ap_ap * t65;
    const T t112 = T(2) * ab_ap * t65 * t111 + T(10) * t84 * t65 + ap_ap * t110 * t65;
    G_ap = (T(3) / T(1280)) * t97 * tau_lo * t112 * t65 + (T(1) / T(1280)) * t58 * t81 * t104 + (T(3) / T(320)) * t106 * t53 * t99 * t65 + (T(1) / T(3840)) * (T(2) * ab_ap * t112 * t65 + T(10) * t88 * t65 - ap_ap * t65 * t111) * t100 * t65 + (T(21) / T(640)) * t108 * t54 * t101 * t65 + (T(7) / T(320)) * t107 * t89 * t98 * t65 + (T(9) / T(1280)) * t105 * delta_tau * t80 * t65 + (T(21) / T(640)) * t109 * t55 * t57 * t65 + (T(3) / T(320)) * t91 * t56 * t65 * t111 - (T(7) / T(320)) * t90 * t92 * t110 * t65;
    const T t113 = T(9) * delta_tau * t80 + t100 + T(84) * t89 * t98 + T(9) * t97 * tau_lo + t81 + T(84) * t90 * t92 + T(36) * t91 * t56 + T(36) * t53 * t99 + T(126) * t55 * t57 + T(126) * t54 * t101;
    G_E = -(T(1) / T(1280)) * (T(210) * t55 * t57 * t78 * t65 + T(168) * t54 * t101 * t65 * t77 + T(128) * t103 * t113 + T(84) * t76 * t89 * t98 * t65 - T(168) * t90 * t92 * t79 * t65 - T(84) * t84 * t91 * t56 * t65 - T(24) * t75 * t53 * t99 * t65 - T(3) * t58 * delta_tau * t80 * t74 - T(3) * t96 * t100 * t65 - T(24) * t88 * t97 * tau_lo * t65 - T(128) * t102 * t81) * t65;
  }
  const T t114 = in.sigma * in.sigma;
  const T t115 = t114 * t114;
  const T t116 = t115 * in.sigma;
  const T t117 = t116 * t116;
  const T g_factor = -T(10) * length * t117;
  f = length * t117 * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

}  // namespace skelconv::generated
