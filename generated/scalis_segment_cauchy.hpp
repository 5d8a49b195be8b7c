// generated/scalis_segment_cauchy.hpp — SCALIS segment kernels of the cauchy family.
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
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 44 +, 64 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 7048 +, 8947 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i2_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = sigma2 * delta_tau * delta_tau + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T c = ap_ap + sigma2 * tau_lo * tau_lo;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  const T log_ratio = log(q1 / c);
  T F;
  const T t1 = T(4) * D - a * a;
  const T t2 = -b * a_minus_b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * tau_lo + M_panels[1] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    F = J2 * tau_lo + (T(1) / T(2)) * (T(2) * J2 * b + log_ratio) * delta_tau / a;
  }
  f = sigma2 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 56 +, 89 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 11376 +, 15444 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i2_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = delta_tau * ap1 + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + delta_tau * ap2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D - a * a;
  const T t2 = -b * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t4 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t4;
    const T t5 = T(1) / a;
    G_E = M_panels[5] * delta_tau + M_panels[4] * tau_lo - b * t4 * t5;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t6 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = M_panels[5] * delta_tau + M_panels[4] * tau_lo - b * t6 * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / a;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = J2 * a + t11 * a_minus_b + b * t12;
    const T t14 = T(1) / D;
    G_ap = (T(1) / T(2)) * delta_tau * t10 * (b * t13 * t14 + t12 - t11) + (T(1) / T(2)) * tau_lo * t13 * t14;
    G_E = (T(1) / T(2)) * (t12 * tau_lo + J2 * delta_tau - (delta_tau + tau_lo) * t11) * t10;
  }
  const T t15 = T(1) / a;
  const T t_star = b * t15;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 58 +, 98 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11377 +, 15449 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i2_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + sigma2 * delta_tau * delta_tau;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t1 = T(1) / c;
  const T log_ratio = log(q1 * t1);
  T F;
  T G_ap;
  T G_E;
  const T t2 = T(4) * D - a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t5 = delta_tau * M_panels[4] + tau_lo * M_panels[3];
    G_ap = t5;
    const T t6 = T(1) / a;
    G_E = tau_lo * M_panels[4] + M_panels[5] * delta_tau - t6 * t5 * b;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t7 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t7;
    const T t8 = T(1) / a;
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - t7 * t8 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / a;
    F = tau_lo * J2 + (T(1) / T(2)) * t11 * (T(2) * b * J2 + log_ratio) * delta_tau;
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = a_minus_b * t13 + a * J2 + b * t1;
    G_ap = (T(1) / T(2)) * tau_lo * t12 * t14 + (T(1) / T(2)) * t11 * (t1 + t12 * b * t14 - t13) * delta_tau;
    G_E = (T(1) / T(2)) * t11 * (tau_lo * t1 + J2 * delta_tau - (tau_lo + delta_tau) * t13);
  }
  const T t15 = T(1) / a;
  const T t_star = t15 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(2) * sigma2 * length;
  f = sigma2 * F * length;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 47 +, 78 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 8127 +, 12192 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i3_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = a_minus_b * r0;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + b * r1) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = a_minus_b * r0;
    X = -(b - a_minus_b) * t7 / (t8 - b * r1);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = asinh(X) * t10;
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t1 * M_panels[2] + T(2) * M_panels[1] * tau_lo * delta_tau + M_panels[0] * t2;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t2 + T(2) * M_panels[1] * tau_lo * delta_tau + t1 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + b * t15;
    const T t17 = T(1) / D;
    const T t18 = T(1) / a;
    const T t19 = t14 - t15 - b * t16 * t17;
    F = t16 * t2 * t17 - t1 * t18 * (T(2) * b * t19 * t18 + t16 * c * t17 - J1) - T(2) * t19 * tau_lo * delta_tau * t18;
  }
  f = sigma2 * F * in.sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 61 +, 119 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 13535 +, 20846 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i3_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t6 = M_panels[6] * t1 + M_panels[4] * t2 + T(2) * delta_tau * M_panels[5] * tau_lo;
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = M_panels[7] * t1 + T(2) * M_panels[6] * delta_tau * tau_lo + M_panels[5] * t2 - t6 * t7 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = M_panels[6] * t1 + T(2) * M_panels[5] * delta_tau * tau_lo + M_panels[4] * t2;
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = M_panels[5] * t2 + T(2) * M_panels[6] * delta_tau * tau_lo + M_panels[7] * t1 - t9 * t8 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / a;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = T(1) / D;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t11 * b + a_minus_b * t14;
    const T t17 = a_minus_b * t14 * t15 + t11 * t12 * b + T(2) * t13 * a * t16;
    const T t18 = t11 * t12 + t13 * t17 * b - t14 * t15;
    G_ap = (T(2) / T(3)) * t10 * t18 * delta_tau * tau_lo + (T(1) / T(3)) * t13 * t17 * t2 - (T(1) / T(3)) * (c * t13 * t17 - T(3) * t13 * t16 - T(2) * t10 * t18 * b) * t10 * t1;
    const T t19 = t14 * t14;
    const T t20 = t19 * t14;
    const T t21 = t11 * t11;
    const T t22 = t21 * t11;
    G_E = -(T(1) / T(3)) * (t20 * (t1 + t2 + T(2) * delta_tau * tau_lo) + T(2) * t10 * (t14 - t11 - t13 * b * t16) * t1 - T(2) * t13 * delta_tau * tau_lo * t16 - t22 * t2) * t10;
  }
  const T t23 = T(1) / a;
  const T t_star = t23 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(3) * sigma2 * length * in.sigma;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 66 +, 141 ×, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 13538 +, 20860 ×, 2439 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i3_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    const T t6 = r0 * a_minus_b;
    X = t4 * t5 * (t6 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = (a_minus_b - b) * t7 / (t8 - r1 * b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = t2 * M_panels[0] + T(2) * M_panels[1] * delta_tau * tau_lo + M_panels[2] * t1;
    const T t14 = t2 * M_panels[4] + T(2) * M_panels[5] * delta_tau * tau_lo + t1 * M_panels[6];
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = M_panels[5] * t2 + t1 * M_panels[7] + T(2) * delta_tau * tau_lo * M_panels[6] - t15 * t14 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t2 + T(2) * delta_tau * tau_lo * M_panels[1] + t1 * M_panels[2];
    const T t16 = T(2) * delta_tau * tau_lo * M_panels[5] + M_panels[6] * t1 + M_panels[4] * t2;
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = t2 * M_panels[5] + M_panels[7] * t1 + T(2) * M_panels[6] * delta_tau * tau_lo - t16 * t17 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = t19 * a_minus_b + t20 * b;
    const T t22 = T(1) / D;
    const T t23 = t21 * t22 * b + t20 - t19;
    F = T(2) * delta_tau * tau_lo * t18 * t23 + t21 * t2 * t22 + t1 * t18 * (T(2) * t18 * t23 * b + J1 - t21 * c * t22);
    const T t24 = t19 * t19;
    const T t25 = t20 * t20;
    const T t26 = t24 * t19 * a_minus_b + T(2) * t21 * t22 * a + t25 * t20 * b;
    const T t27 = t22 * t26 * b + t25 * t20 - t24 * t19;
    G_ap = (T(1) / T(3)) * t2 * t22 * t26 + (T(2) / T(3)) * t27 * delta_tau * tau_lo * t18 - (T(1) / T(3)) * (c * t22 * t26 - T(3) * t21 * t22 - T(2) * t27 * t18 * b) * t1 * t18;
    const T t28 = t20 * t20;
    const T t29 = t28 * t20;
    const T t30 = t19 * t19;
    const T t31 = t30 * t19;
    G_E = (T(1) / T(3)) * t18 * (T(2) * t1 * t18 * t23 + t29 * t2 + T(2) * t21 * delta_tau * tau_lo * t22 - (t2 + T(2) * delta_tau * tau_lo + t1) * t31);
  }
  const T t32 = T(1) / a;
  const T t_star = t32 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  f = in.sigma * length * sigma2 * F;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 54 +, 97 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 9210 +, 12197 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i4_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
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
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    F = T(3) * t1 * tau_lo * M_panels[2] + M_panels[0] * t7 + T(3) * delta_tau * t2 * M_panels[1] + t8 * M_panels[3];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t9 = t1 * delta_tau;
    const T t10 = t2 * tau_lo;
    F = T(3) * delta_tau * t2 * M_panels[1] + t9 * M_panels[3] + T(3) * t1 * tau_lo * M_panels[2] + t10 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = t15 * a_minus_b + b * t3 + a * J2;
    const T t17 = t14 * t16 * b + t3 - t15;
    const T t18 = T(2) * t13 * t17 * b + T(2) * J2 - t14 * t16 * c;
    const T t19 = t1 * delta_tau;
    const T t20 = t2 * tau_lo;
    F = (T(3) / T(2)) * t1 * tau_lo * t13 * t18 + (T(1) / T(2)) * t19 * t13 * (T(2) * t13 * b * t18 + (T(2) * J2 * b + log_ratio) * t13 - t13 * t17 * c) + (T(1) / T(2)) * t14 * t20 * t16 + (T(3) / T(2)) * delta_tau * t2 * t13 * t17;
  }
  f = length * sigma2 * sigma2 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 149 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 15700 +, 20859 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i4_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial2 * radial2 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t2 * tau_lo;
    const T t8 = M_panels[8] * t6 + M_panels[5] * t7 + T(3) * delta_tau * t2 * M_panels[6] + T(3) * t1 * tau_lo * M_panels[7];
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = t7 * M_panels[6] + T(3) * delta_tau * t2 * M_panels[7] + T(3) * M_panels[8] * t1 * tau_lo + t6 * M_panels[9] - t8 * t9 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t10 = t2 * tau_lo;
    const T t11 = t1 * delta_tau;
    const T t12 = t10 * M_panels[5] + t11 * M_panels[8] + T(3) * delta_tau * t2 * M_panels[6] + T(3) * t1 * tau_lo * M_panels[7];
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = t10 * M_panels[6] + T(3) * t1 * M_panels[8] * tau_lo + t11 * M_panels[9] + T(3) * delta_tau * t2 * M_panels[7] - t13 * t12 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, c_minus_b) * t15;
    const T t16 = t1 * delta_tau;
    const T t17 = T(1) / a;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = b * t20 + a * J2 + a_minus_b * t18;
    const T t24 = T(2) * a_minus_b * t19 + T(3) * a * t22 * t23 + T(2) * b * t21;
    const T t25 = T(2) * t19 - T(2) * t21 - t24 * t22 * b;
    const T t26 = t22 * b * t23 + t20 - t18;
    const T t27 = t24 * t22 * c + T(2) * t25 * t17 * b - T(4) * t22 * t23;
    const T t28 = t2 * tau_lo;
    G_ap = (T(1) / T(8)) * t16 * t17 * (t25 * t17 * c + T(4) * t17 * t26 - T(2) * t27 * t17 * b) + (T(1) / T(8)) * t24 * t28 * t22 - (T(3) / T(8)) * t25 * delta_tau * t2 * t17 - (T(3) / T(8)) * t1 * tau_lo * t27 * t17;
    G_E = (T(1) / T(8)) * (T(6) * t1 * tau_lo * t17 * t26 + T(3) * delta_tau * t2 * t22 * t23 + T(2) * t28 * t21 - T(2) * (T(3) * t1 * tau_lo + t28 + t16 + T(3) * delta_tau * t2) * t19 - T(3) * t16 * t17 * (t22 * t23 * c - T(2) * t17 * b * t26 - T(2) * J2)) * t17;
  }
  const T t29 = T(1) / a;
  const T t_star = t29 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(4) * length * sigma2 * sigma2;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 78 +, 174 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15703 +, 20870 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i4_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    F = T(3) * delta_tau * t2 * M_panels[1] + t7 * M_panels[3] + T(3) * t1 * tau_lo * M_panels[2] + t8 * M_panels[0];
    const T t9 = T(3) * t1 * tau_lo * M_panels[7] + T(3) * delta_tau * t2 * M_panels[6] + t7 * M_panels[8] + t8 * M_panels[5];
    G_ap = t9;
    const T t10 = T(1) / a;
    G_E = t8 * M_panels[6] + T(3) * delta_tau * t2 * M_panels[7] + t7 * M_panels[9] + T(3) * t1 * M_panels[8] * tau_lo - t10 * t9 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t11 = t2 * tau_lo;
    const T t12 = t1 * delta_tau;
    F = T(3) * delta_tau * M_panels[1] * t2 + t11 * M_panels[0] + T(3) * t1 * tau_lo * M_panels[2] + t12 * M_panels[3];
    const T t13 = t12 * M_panels[8] + T(3) * t1 * tau_lo * M_panels[7] + t11 * M_panels[5] + T(3) * delta_tau * t2 * M_panels[6];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = T(3) * t1 * tau_lo * M_panels[8] + T(3) * delta_tau * t2 * M_panels[7] + t12 * M_panels[9] + t11 * M_panels[6] - t14 * b * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / a;
    const T t18 = T(1) / D;
    const T t19 = T(1) / q1;
    const T t20 = a * J2 + a_minus_b * t19 + b * t3;
    const T t21 = t3 + t18 * b * t20 - t19;
    const T t22 = t2 * tau_lo;
    const T t23 = t1 * delta_tau;
    const T t24 = t18 * c * t20 - T(2) * t17 * b * t21 - T(2) * J2;
    F = (T(3) / T(2)) * delta_tau * t2 * t17 * t21 + (T(1) / T(2)) * t18 * t22 * t20 - (T(1) / T(2)) * t23 * (t17 * c * t21 + T(2) * t17 * b * t24 - t17 * (log_ratio + T(2) * b * J2)) * t17 - (T(3) / T(2)) * t1 * tau_lo * t17 * t24;
    const T t25 = t19 * t19;
    const T t26 = t3 * t3;
    const T t27 = T(2) * b * t26 + T(2) * a_minus_b * t25 + T(3) * t18 * a * t20;
    const T t28 = T(2) * t25 - t18 * t27 * b - T(2) * t26;
    const T t29 = T(4) * t18 * t20 - t18 * t27 * c - T(2) * t17 * b * t28;
    G_ap = (T(1) / T(8)) * t23 * (t17 * c * t28 + T(4) * t17 * t21 + T(2) * t17 * b * t29) * t17 + (T(3) / T(8)) * t1 * tau_lo * t17 * t29 + (T(1) / T(8)) * t18 * t27 * t22 - (T(3) / T(8)) * delta_tau * t2 * t17 * t28;
    G_E = -(T(1) / T(8)) * (T(2) * (t22 + t23 + T(3) * delta_tau * t2 + T(3) * t1 * tau_lo) * t25 + T(3) * t23 * t17 * t24 - T(2) * t22 * t26 - T(6) * t1 * tau_lo * t17 * t21 - T(3) * delta_tau * t18 * t2 * t20) * t17;
  }
  const T t30 = T(1) / a;
  const T t_star = t30 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t31 = sigma2 * sigma2;
  const T g_factor = -T(4) * t31 * length;
  f = t31 * F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 59 +, 127 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 10289 +, 16523 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i5_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    const T t6 = b * r1;
    X = t4 * t5 * (t6 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
    X = (b - a_minus_b) * t7 / (t8 - r0 * a_minus_b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t2 * tau_lo;
    const T t16 = t2 * t2;
    const T t17 = t1 * t1;
    F = T(4) * t14 * tau_lo * M_panels[3] + T(4) * M_panels[1] * delta_tau * t15 + T(6) * t1 * t2 * M_panels[2] + t16 * M_panels[0] + M_panels[4] * t17;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * tau_lo;
    const T t19 = t1 * delta_tau;
    const T t20 = t1 * t1;
    const T t21 = t2 * t2;
    F = T(4) * delta_tau * t18 * M_panels[1] + T(4) * t19 * tau_lo * M_panels[3] + t20 * M_panels[4] + T(6) * M_panels[2] * t1 * t2 + t21 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / D;
    const T t23 = t2 * t2;
    const T t24 = T(1) / r1;
    const T t25 = T(1) / r0;
    const T t26 = t24 * a_minus_b + t25 * b;
    const T t27 = t25 * t25;
    const T t28 = t24 * t24;
    const T t29 = T(2) * t22 * a * t26 + t27 * t25 * b + t28 * t24 * a_minus_b;
    const T t30 = t2 * tau_lo;
    const T t31 = T(1) / a;
    const T t32 = t28 * t24 - t22 * b * t29 - t27 * t25;
    const T t33 = c * t22 * t29 + T(2) * t31 * b * t32 - T(3) * t22 * t26;
    const T t34 = t24 - t22 * b * t26 - t25;
    const T t35 = T(2) * t33 * t31 * b + T(3) * t31 * t34 - c * t31 * t32;
    const T t36 = t1 * delta_tau;
    const T t37 = t1 * t1;
    F = (T(1) / T(3)) * t22 * t23 * t29 - (T(4) / T(3)) * delta_tau * t30 * t31 * t32 - (T(4) / T(3)) * t35 * t36 * tau_lo * t31 - (T(1) / T(3)) * t37 * t31 * (T(2) * t35 * t31 * b + T(3) * (T(2) * t31 * b * t34 + c * t22 * t26 - J1) * t31 - c * t33 * t31) - T(2) * t33 * t1 * t2 * t31;
  }
  f = length * sigma2 * sigma2 * F * in.sigma;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 79 +, 193 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 17859 +, 27343 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i5_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial2 * radial2 + radial0 * radial0 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * t2;
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    const T t9 = t1 * t1;
    const T t10 = M_panels[6] * t6 + T(4) * M_panels[9] * t7 * tau_lo + T(4) * M_panels[7] * delta_tau * t8 + T(6) * t1 * t2 * M_panels[8] + M_panels[10] * t9;
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = t9 * M_panels[11] + M_panels[7] * t6 + T(4) * M_panels[10] * t7 * tau_lo + T(4) * delta_tau * t8 * M_panels[8] + T(6) * M_panels[9] * t1 * t2 - b * t10 * t11;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t1 * delta_tau;
    const T t13 = t1 * t1;
    const T t14 = t2 * tau_lo;
    const T t15 = t2 * t2;
    const T t16 = T(6) * M_panels[8] * t1 * t2 + T(4) * t12 * tau_lo * M_panels[9] + M_panels[10] * t13 + T(4) * M_panels[7] * delta_tau * t14 + t15 * M_panels[6];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[7] * t15 + T(6) * t1 * t2 * M_panels[9] + M_panels[11] * t13 + T(4) * M_panels[8] * delta_tau * t14 + T(4) * M_panels[10] * t12 * tau_lo - b * t16 * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = b * t19 + t20 * a_minus_b;
    const T t22 = t20 * t20;
    const T t23 = t19 * t19;
    const T t24 = T(2) * t21 * t18 * a + t20 * a_minus_b * t22 + b * t23 * t19;
    const T t25 = b * t18 * t24 + t23 * t19 - t20 * t22;
    const T t26 = T(1) / a;
    const T t27 = t23 * t23;
    const T t28 = t22 * t22;
    const T t29 = T(3) * b * t27 * t19 + T(4) * t18 * t24 * a + T(3) * t20 * a_minus_b * t28;
    const T t30 = t29 * b * t18 + T(3) * t27 * t19 - T(3) * t20 * t28;
    const T t31 = T(5) * t18 * t24 + T(2) * b * t30 * t26 - t29 * c * t18;
    const T t32 = T(5) * t25 * t26 + T(2) * b * t31 * t26 - t30 * c * t26;
    const T t33 = t1 * delta_tau;
    const T t34 = t2 * t2;
    const T t35 = t2 * tau_lo;
    const T t36 = t1 * t1;
    const T t37 = c * t18 * t24 - T(3) * t21 * t18 - T(2) * b * t25 * t26;
    G_ap = (T(4) / T(15)) * t32 * t33 * tau_lo * t26 + (T(2) / T(5)) * t31 * t1 * t2 * t26 + (T(1) / T(15)) * t29 * t18 * t34 + (T(4) / T(15)) * t30 * delta_tau * t35 * t26 - (T(1) / T(15)) * t36 * (t31 * c * t26 + T(5) * t37 * t26 - T(2) * b * t32 * t26) * t26;
    const T t38 = t20 * t20;
    const T t39 = t38 * t38;
    const T t40 = t39 * t20;
    const T t41 = t19 * t19;
    const T t42 = t41 * t41;
    const T t43 = t42 * t19;
    G_E = -(T(1) / T(15)) * t26 * (T(12) * t33 * t37 * tau_lo * t26 + T(3) * t40 * (T(4) * delta_tau * t35 + t34 + t36 + T(6) * t1 * t2 + T(4) * t33 * tau_lo) + T(4) * t36 * t26 * (t25 * c * t26 + T(2) * b * t37 * t26 - T(3) * t26 * (t19 + b * t21 * t18 - t20)) - T(3) * t34 * t43 - T(4) * t18 * delta_tau * t24 * t35 - T(12) * t25 * t1 * t2 * t26);
  }
  const T t44 = T(1) / a;
  const T t_star = b * t44;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(5) * in.sigma * length * sigma2 * sigma2;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 88 +, 232 ×, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 17864 +, 27363 ×, 2439 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i5_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    const T t6 = a_minus_b * r0;
    X = t4 * t5 * (t6 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = a_minus_b * r0;
    X = t7 * (a_minus_b - b) / (t8 - r1 * b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t1 * delta_tau;
    const T t16 = t1 * t1;
    const T t17 = t2 * tau_lo;
    F = t14 * M_panels[0] + T(6) * t2 * M_panels[2] * t1 + T(4) * tau_lo * M_panels[3] * t15 + M_panels[4] * t16 + T(4) * t17 * M_panels[1] * delta_tau;
    const T t18 = T(6) * t2 * M_panels[8] * t1 + T(4) * t17 * M_panels[7] * delta_tau + t14 * M_panels[6] + T(4) * tau_lo * M_panels[9] * t15 + M_panels[10] * t16;
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = T(4) * tau_lo * M_panels[10] * t15 + T(6) * t2 * M_panels[9] * t1 + t14 * M_panels[7] + M_panels[11] * t16 + T(4) * t17 * M_panels[8] * delta_tau - t18 * t19 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * delta_tau;
    const T t21 = t1 * t1;
    const T t22 = t2 * t2;
    const T t23 = t2 * tau_lo;
    F = T(4) * tau_lo * M_panels[3] * t20 + M_panels[4] * t21 + M_panels[0] * t22 + T(4) * t23 * M_panels[1] * delta_tau + T(6) * t2 * M_panels[2] * t1;
    const T t24 = M_panels[10] * t21 + T(4) * t23 * M_panels[7] * delta_tau + T(6) * t2 * M_panels[8] * t1 + t22 * M_panels[6] + T(4) * tau_lo * M_panels[9] * t20;
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(6) * t2 * M_panels[9] * t1 + T(4) * t23 * M_panels[8] * delta_tau + t22 * M_panels[7] + T(4) * tau_lo * M_panels[10] * t20 + M_panels[11] * t21 - t25 * t24 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = t2 * t2;
    const T t27 = T(1) / D;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = T(1) / r1;
    const T t31 = t30 * t30;
    const T t32 = t30 * a_minus_b + b * t28;
    const T t33 = b * t29 * t28 + t30 * a_minus_b * t31 + T(2) * t27 * t32 * a;
    const T t34 = T(1) / a;
    const T t35 = t27 * t32 * b + t28 - t30;
    const T t36 = t30 * t31 - t29 * t28 - t27 * t33 * b;
    const T t37 = T(2) * t34 * b * t36 + t27 * t33 * c - T(3) * t27 * t32;
    const T t38 = T(2) * t34 * b * t37 - t34 * c * t36 - T(3) * t34 * t35;
    const T t39 = t1 * t1;
    const T t40 = t2 * tau_lo;
    const T t41 = t1 * delta_tau;
    F = (T(1) / T(3)) * t26 * t27 * t33 + (T(1) / T(3)) * t34 * (T(3) * (T(2) * t34 * t35 * b + J1 - t27 * t32 * c) * t34 + t34 * c * t37 - T(2) * t34 * b * t38) * t39 - (T(4) / T(3)) * t40 * t34 * t36 * delta_tau - (T(4) / T(3)) * tau_lo * t34 * t38 * t41 - T(2) * t2 * t34 * t1 * t37;
    const T t42 = t31 * t31;
    const T t43 = t29 * t29;
    const T t44 = T(3) * t30 * a_minus_b * t42 + T(3) * b * t43 * t28 + T(4) * t27 * a * t33;
    const T t45 = t27 * t44 * b + T(3) * t43 * t28 - T(3) * t30 * t42;
    const T t46 = T(5) * t27 * t33 + T(2) * t34 * b * t45 - t27 * t44 * c;
    const T t47 = T(2) * t34 * b * t46 - t34 * t45 * c - T(5) * t34 * t36;
    G_ap = (T(4) / T(15)) * t40 * t34 * t45 * delta_tau + (T(4) / T(15)) * tau_lo * t47 * t34 * t41 + (T(2) / T(5)) * t2 * t34 * t46 * t1 + (T(1) / T(15)) * t26 * t27 * t44 + (T(1) / T(15)) * t34 * (T(2) * t47 * t34 * b - T(5) * t34 * t37 - t34 * c * t46) * t39;
    const T t48 = t30 * t30;
    const T t49 = t48 * t48;
    const T t50 = t49 * t30;
    const T t51 = t28 * t28;
    const T t52 = t51 * t51;
    const T t53 = t52 * t28;
    G_E = -(T(1) / T(15)) * t34 * (T(3) * t50 * (t39 + T(6) * t2 * t1 + T(4) * t40 * delta_tau + T(4) * tau_lo * t41 + t26) + T(12) * t2 * t34 * t36 * t1 + T(12) * tau_lo * t34 * t41 * t37 + T(4) * t34 * t38 * t39 - T(4) * t40 * t27 * t33 * delta_tau - T(3) * t26 * t53);
  }
  const T t54 = T(1) / a;
  const T t_star = t54 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t55 = sigma2 * sigma2;
  const T g_factor = -T(5) * t55 * in.sigma * length;
  f = t55 * F * in.sigma * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 68 +, 151 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11372 +, 15448 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i6_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t7 * delta_tau;
    const T t9 = t1 * delta_tau;
    const T t10 = t2 * tau_lo;
    const T t11 = t2 * t2;
    const T t12 = t11 * tau_lo;
    F = t8 * M_panels[5] + T(10) * t9 * t2 * M_panels[3] + T(5) * t7 * tau_lo * M_panels[4] + T(10) * t1 * t10 * M_panels[2] + T(5) * delta_tau * t11 * M_panels[1] + M_panels[0] * t12;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * delta_tau;
    const T t15 = t1 * delta_tau;
    const T t16 = t2 * tau_lo;
    const T t17 = t2 * t2;
    const T t18 = t17 * tau_lo;
    F = t14 * M_panels[5] + T(10) * t15 * t2 * M_panels[3] + T(10) * t1 * t16 * M_panels[2] + T(5) * delta_tau * t17 * M_panels[1] + t18 * M_panels[0] + T(5) * t13 * tau_lo * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, c_minus_b);
    const T t21 = t1 * delta_tau;
    const T t22 = T(1) / a;
    const T t23 = T(1) / D;
    const T t24 = T(1) / q1;
    const T t25 = b * t3 + t24 * a_minus_b + a * J2;
    const T t26 = t3 + t23 * t25 * b - t24;
    const T t27 = t24 * t24;
    const T t28 = t3 * t3;
    const T t29 = T(3) * t23 * a * t25 + T(2) * t27 * a_minus_b + T(2) * b * t28;
    const T t30 = T(2) * t27 - t23 * b * t29 - T(2) * t28;
    const T t31 = t23 * t29 * c + T(2) * t22 * b * t30 - T(4) * t23 * t25;
    const T t32 = T(4) * t22 * t26 + t22 * t30 * c - T(2) * t22 * b * t31;
    const T t33 = t1 * t1;
    const T t34 = T(2) * J2 + T(2) * t22 * t26 * b - t23 * t25 * c;
    const T t35 = T(2) * t22 * b * t32 + t22 * t31 * c + T(4) * t22 * t34;
    const T t36 = t33 * delta_tau;
    const T t37 = t2 * t2;
    const T t38 = t37 * tau_lo;
    const T t39 = t2 * tau_lo;
    F = (T(5) / T(4)) * t21 * t2 * t22 * t32 + (T(5) / T(8)) * t33 * tau_lo * t22 * t35 + (T(1) / T(8)) * t36 * t22 * (T(2) * t22 * b * t35 + T(4) * t22 * (T(2) * t22 * t34 * b + t22 * (T(2) * J2 * b + log_ratio) - t22 * t26 * c) - t22 * t32 * c) + (T(1) / T(8)) * t23 * t38 * t29 - (T(5) / T(4)) * t1 * t39 * t22 * t31 - (T(5) / T(8)) * delta_tau * t37 * t22 * t30;
  }
  const T t40 = sigma2 * sigma2;
  const T t41 = t40 * sigma2;
  f = t41 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 92 +, 222 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 20024 +, 26276 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i6_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[0] * exact_cross[0] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t2 * t2;
    const T t8 = t2 * tau_lo;
    const T t9 = t7 * tau_lo;
    const T t10 = t1 * t1;
    const T t11 = t10 * delta_tau;
    const T t12 = T(10) * t6 * t2 * M_panels[10] + T(5) * M_panels[8] * delta_tau * t7 + T(10) * t1 * t8 * M_panels[9] + t9 * M_panels[7] + t11 * M_panels[12] + T(5) * M_panels[11] * t10 * tau_lo;
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = t11 * M_panels[13] + T(5) * delta_tau * t7 * M_panels[9] + T(10) * M_panels[11] * t6 * t2 + M_panels[8] * t9 + T(5) * t10 * tau_lo * M_panels[12] + T(10) * t1 * t8 * M_panels[10] - b * t12 * t13;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t2 * tau_lo;
    const T t17 = t1 * t1;
    const T t18 = t17 * delta_tau;
    const T t19 = t1 * delta_tau;
    const T t20 = T(5) * delta_tau * t14 * M_panels[8] + M_panels[7] * t15 + T(10) * M_panels[9] * t1 * t16 + M_panels[12] * t18 + T(5) * t17 * tau_lo * M_panels[11] + T(10) * M_panels[10] * t19 * t2;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = t15 * M_panels[8] + M_panels[13] * t18 + T(5) * M_panels[9] * delta_tau * t14 + T(10) * t19 * t2 * M_panels[11] + T(10) * M_panels[10] * t1 * t16 + T(5) * M_panels[12] * t17 * tau_lo - b * t20 * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = t23 * atan2(t22, c_minus_b);
    const T t24 = T(1) / a;
    const T t25 = T(1) / D;
    const T t26 = T(1) / q1;
    const T t27 = T(1) / c;
    const T t28 = a_minus_b * t26 + b * t27 + J2 * a;
    const T t29 = t27 * t27;
    const T t30 = t26 * t26;
    const T t31 = T(3) * t25 * t28 * a + T(2) * b * t29 + T(2) * a_minus_b * t30;
    const T t32 = b * t31 * t25 + T(2) * t29 - T(2) * t30;
    const T t33 = t29 * t27;
    const T t34 = t30 * t26;
    const T t35 = T(8) * b * t33 + T(5) * t31 * t25 * a + T(8) * a_minus_b * t34;
    const T t36 = b * t35 * t25 + T(8) * t33 - T(8) * t34;
    const T t37 = T(2) * b * t36 * t24 + T(6) * t31 * t25 - c * t35 * t25;
    const T t38 = T(6) * t24 * t32 + T(2) * b * t37 * t24 - t36 * c * t24;
    const T t39 = t1 * delta_tau;
    const T t40 = t1 * t1;
    const T t41 = T(2) * b * t24 * t32 + T(4) * t25 * t28 - t31 * c * t25;
    const T t42 = T(2) * b * t38 * t24 + T(6) * t24 * t41 - t37 * c * t24;
    const T t43 = t2 * tau_lo;
    const T t44 = t40 * delta_tau;
    const T t45 = t27 + b * t25 * t28 - t26;
    const T t46 = c * t24 * t32 - T(4) * t45 * t24 - T(2) * b * t24 * t41;
    const T t47 = t2 * t2;
    const T t48 = t47 * tau_lo;
    G_ap = (T(5) / T(24)) * t38 * t39 * t2 * t24 + (T(5) / T(48)) * t40 * tau_lo * t42 * t24 + (T(5) / T(24)) * t37 * t1 * t43 * t24 + (T(1) / T(48)) * t44 * t24 * (T(2) * b * t42 * t24 - t38 * c * t24 - T(6) * t46 * t24) + (T(5) / T(48)) * t36 * delta_tau * t47 * t24 + (T(1) / T(48)) * t35 * t48 * t25;
    G_E = (T(1) / T(48)) * (T(20) * t1 * t43 * t24 * t32 + T(5) * t31 * delta_tau * t47 * t25 + T(8) * t33 * t48 + T(30) * t39 * t2 * t24 * t41 - T(20) * t46 * t40 * tau_lo * t24 - T(5) * t44 * t24 * (c * t24 * t41 + T(4) * t24 * (c * t25 * t28 - T(2) * J2 - T(2) * b * t45 * t24) + T(2) * b * t46 * t24) - T(8) * (t44 + T(5) * delta_tau * t47 + T(10) * t1 * t43 + T(10) * t39 * t2 + T(5) * t40 * tau_lo + t48) * t34) * t24;
  }
  const T t49 = T(1) / a;
  const T t_star = b * t49;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - ab2 * t_star;
  const T t50 = sigma2 * sigma2;
  const T t51 = t50 * sigma2;
  const T g_factor = -T(6) * length * t51;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 102 +, 262 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 20029 +, 26293 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i6_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t2 * t2;
    const T t9 = t8 * tau_lo;
    const T t10 = t1 * delta_tau;
    const T t11 = t1 * t1;
    const T t12 = t11 * delta_tau;
    F = T(10) * t1 * t7 * M_panels[2] + M_panels[0] * t9 + T(10) * M_panels[3] * t10 * t2 + T(5) * M_panels[4] * t11 * tau_lo + T(5) * M_panels[1] * delta_tau * t8 + t12 * M_panels[5];
    const T t13 = M_panels[12] * t12 + T(10) * M_panels[10] * t10 * t2 + T(5) * M_panels[8] * delta_tau * t8 + M_panels[7] * t9 + T(10) * M_panels[9] * t1 * t7 + T(5) * t11 * tau_lo * M_panels[11];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = T(10) * M_panels[10] * t1 * t7 + M_panels[13] * t12 + M_panels[8] * t9 + T(5) * M_panels[12] * t11 * tau_lo + T(10) * t10 * t2 * M_panels[11] + T(5) * M_panels[9] * delta_tau * t8 - b * t13 * t14;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t15 = t2 * t2;
    const T t16 = t15 * tau_lo;
    const T t17 = t2 * tau_lo;
    const T t18 = t1 * delta_tau;
    const T t19 = t1 * t1;
    const T t20 = t19 * delta_tau;
    F = t16 * M_panels[0] + T(10) * M_panels[2] * t1 * t17 + T(5) * M_panels[1] * delta_tau * t15 + T(10) * t18 * M_panels[3] * t2 + M_panels[5] * t20 + T(5) * M_panels[4] * t19 * tau_lo;
    const T t21 = M_panels[7] * t16 + T(10) * M_panels[9] * t1 * t17 + T(5) * M_panels[11] * t19 * tau_lo + T(10) * M_panels[10] * t18 * t2 + T(5) * M_panels[8] * delta_tau * t15 + M_panels[12] * t20;
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = M_panels[13] * t20 + T(5) * M_panels[12] * t19 * tau_lo + T(10) * M_panels[11] * t18 * t2 + T(5) * M_panels[9] * delta_tau * t15 + M_panels[8] * t16 + T(10) * M_panels[10] * t1 * t17 - t21 * b * t22;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = atan2(t23, c_minus_b) * t24;
    const T t25 = T(1) / D;
    const T t26 = T(1) / q1;
    const T t27 = J2 * a + a_minus_b * t26 + b * t3;
    const T t28 = t3 * t3;
    const T t29 = t26 * t26;
    const T t30 = T(3) * t27 * t25 * a + T(2) * b * t28 + T(2) * a_minus_b * t29;
    const T t31 = b * t25 * t30 + T(2) * t28 - T(2) * t29;
    const T t32 = t2 * t2;
    const T t33 = T(1) / a;
    const T t34 = t27 * b * t25 + t3 - t26;
    const T t35 = T(2) * b * t31 * t33 + T(4) * t27 * t25 - c * t25 * t30;
    const T t36 = T(4) * t34 * t33 + T(2) * b * t35 * t33 - t31 * c * t33;
    const T t37 = t1 * delta_tau;
    const T t38 = t32 * tau_lo;
    const T t39 = t2 * tau_lo;
    const T t40 = t27 * c * t25 - T(2) * b * t34 * t33 - T(2) * J2;
    const T t41 = t35 * c * t33 + T(4) * t40 * t33 - T(2) * t36 * b * t33;
    const T t42 = t1 * t1;
    const T t43 = t42 * delta_tau;
    F = (T(5) / T(8)) * t31 * delta_tau * t32 * t33 + (T(5) / T(4)) * t36 * t37 * t2 * t33 + (T(1) / T(8)) * t25 * t38 * t30 + (T(5) / T(4)) * t35 * t1 * t39 * t33 - (T(5) / T(8)) * t41 * t42 * tau_lo * t33 - (T(1) / T(8)) * (t36 * c * t33 + T(4) * (c * t34 * t33 + T(2) * b * t40 * t33 - (log_ratio + T(2) * b * J2) * t33) * t33 + T(2) * t41 * b * t33) * t43 * t33;
    const T t44 = t28 * t3;
    const T t45 = t29 * t26;
    const T t46 = T(8) * b * t44 + T(5) * t25 * t30 * a + T(8) * a_minus_b * t45;
    const T t47 = T(8) * t44 + b * t46 * t25 - T(8) * t45;
    const T t48 = T(6) * t25 * t30 + T(2) * b * t47 * t33 - t46 * c * t25;
    const T t49 = T(2) * t48 * b * t33 + T(6) * t31 * t33 - c * t47 * t33;
    const T t50 = T(6) * t35 * t33 + T(2) * b * t49 * t33 - t48 * c * t33;
    G_ap = (T(5) / T(24)) * t49 * t37 * t2 * t33 + (T(5) / T(48)) * t47 * delta_tau * t32 * t33 + (T(5) / T(24)) * t48 * t1 * t39 * t33 + (T(5) / T(48)) * t42 * tau_lo * t50 * t33 + (T(1) / T(48)) * t46 * t25 * t38 - (T(1) / T(48)) * (t49 * c * t33 - T(2) * b * t50 * t33 - T(6) * t36 * t33) * t43 * t33;
    G_E = (T(1) / T(48)) * (T(20) * t31 * t1 * t39 * t33 + T(30) * t35 * t37 * t2 * t33 + T(8) * t44 * t38 + T(20) * t36 * t42 * tau_lo * t33 + T(5) * delta_tau * t25 * t32 * t30 - T(5) * t41 * t43 * t33 - T(8) * (t38 + T(10) * t37 * t2 + t43 + T(5) * delta_tau * t32 + T(10) * t1 * t39 + T(5) * t42 * tau_lo) * t45) * t33;
  }
  const T t51 = T(1) / a;
  const T t_star = b * t51;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t52 = sigma2 * sigma2;
  const T t53 = t52 * sigma2;
  const T g_factor = -T(6) * t53 * length;
  f = t53 * F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 75 +, 190 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 12451 +, 20854 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i7_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r1 * b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + a_minus_b * r0) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r1 * b;
    X = -t7 * (a_minus_b - b) / (t8 - a_minus_b * r0);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t1 * t1;
    const T t17 = t16 * delta_tau;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    F = T(15) * t14 * t1 * M_panels[2] + T(6) * M_panels[1] * t15 * delta_tau + T(15) * M_panels[4] * t2 * t16 + T(6) * tau_lo * t17 * M_panels[5] + M_panels[6] * t19 + M_panels[0] * t21 + T(20) * M_panels[3] * t20 * t18;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t2 * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t1 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t2 * t2;
    const T t27 = t26 * tau_lo;
    const T t28 = t1 * t1;
    const T t29 = t28 * delta_tau;
    F = M_panels[0] * t23 + M_panels[6] * t25 + T(20) * M_panels[3] * t22 * t24 + T(15) * t26 * t1 * M_panels[2] + T(6) * t27 * delta_tau * M_panels[1] + T(15) * t2 * t28 * M_panels[4] + T(6) * tau_lo * t29 * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = T(1) / a;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t35;
    const T t37 = T(1) / D;
    const T t38 = t31 * b + t34 * a_minus_b;
    const T t39 = t32 * t31 * b + T(2) * t38 * t37 * a + t34 * a_minus_b * t35;
    const T t40 = T(3) * t34 * a_minus_b * t36 + T(4) * t37 * a * t39 + T(3) * t33 * t31 * b;
    const T t41 = T(3) * t33 * t31 + t40 * t37 * b - T(3) * t34 * t36;
    const T t42 = T(2) * t30 * t41 * b + T(5) * t37 * t39 - t40 * c * t37;
    const T t43 = t37 * t39 * b + t32 * t31 - t34 * t35;
    const T t44 = T(2) * t30 * t42 * b + T(5) * t43 * t30 - c * t30 * t41;
    const T t45 = T(2) * t43 * t30 * b + T(3) * t38 * t37 - c * t37 * t39;
    const T t46 = T(2) * t30 * t44 * b + T(5) * t45 * t30 - c * t30 * t42;
    const T t47 = t1 * t1;
    const T t48 = t2 * t2;
    const T t49 = t48 * tau_lo;
    const T t50 = t31 + t38 * t37 * b - t34;
    const T t51 = t43 * c * t30 - T(2) * t45 * t30 * b - T(3) * t30 * t50;
    const T t52 = T(2) * t46 * t30 * b - T(5) * t51 * t30 - c * t30 * t44;
    const T t53 = t47 * delta_tau;
    const T t54 = t2 * tau_lo;
    const T t55 = t1 * delta_tau;
    const T t56 = t54 * t54;
    const T t57 = t55 * t55;
    F = t46 * t2 * t47 * t30 + (T(2) / T(5)) * t49 * delta_tau * t30 * t41 + (T(2) / T(5)) * t52 * tau_lo * t53 * t30 + t48 * t1 * t30 * t42 + (T(4) / T(3)) * t54 * t55 * t30 * t44 + (T(1) / T(15)) * t40 * t56 * t37 - (T(1) / T(15)) * t57 * t30 * (t46 * c * t30 + T(5) * (T(2) * t51 * t30 * b + c * t45 * t30 - T(3) * (T(2) * t30 * t50 * b + J1 - t38 * c * t37) * t30) * t30 - T(2) * t52 * t30 * b);
  }
  const T t58 = sigma2 * sigma2;
  const T t59 = t58 * sigma2;
  f = in.sigma * length * t59 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 101 +, 281 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 22183 +, 33840 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i7_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * delta_tau;
    const T t8 = t2 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t1 * delta_tau;
    const T t11 = t2 * t2;
    const T t12 = t11 * tau_lo;
    const T t13 = t10 * t10;
    const T t14 = T(6) * t7 * tau_lo * M_panels[13] + M_panels[8] * t9 + T(15) * t6 * t2 * M_panels[12] + T(20) * M_panels[11] * t10 * t8 + T(15) * t1 * t11 * M_panels[10] + T(6) * delta_tau * t12 * M_panels[9] + M_panels[14] * t13;
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = t13 * M_panels[15] + T(6) * delta_tau * t12 * M_panels[10] + T(20) * t10 * t8 * M_panels[12] + T(15) * t6 * t2 * M_panels[13] + T(6) * M_panels[14] * t7 * tau_lo + T(15) * M_panels[11] * t1 * t11 + t9 * M_panels[9] - b * t15 * t14;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t1 * t1;
    const T t17 = t2 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t1 * delta_tau;
    const T t20 = t19 * t19;
    const T t21 = t2 * t2;
    const T t22 = t21 * tau_lo;
    const T t23 = t16 * delta_tau;
    const T t24 = T(15) * t16 * t2 * M_panels[12] + t18 * M_panels[8] + M_panels[14] * t20 + T(20) * t19 * M_panels[11] * t17 + T(6) * delta_tau * t22 * M_panels[9] + T(15) * t1 * t21 * M_panels[10] + T(6) * t23 * tau_lo * M_panels[13];
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(6) * delta_tau * t22 * M_panels[10] + T(6) * M_panels[14] * t23 * tau_lo + T(15) * t16 * t2 * M_panels[13] + t20 * M_panels[15] + T(20) * t19 * t17 * M_panels[12] + t18 * M_panels[9] + T(15) * t1 * M_panels[11] * t21 - b * t24 * t25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = T(1) / a;
    const T t29 = T(1) / r1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t31 * t30;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = b * t33 + t29 * a_minus_b;
    const T t38 = T(1) / D;
    const T t39 = t30 * t29 * a_minus_b + b * t33 * t34 + T(2) * t37 * t38 * a;
    const T t40 = T(4) * t39 * t38 * a + T(3) * t31 * t29 * a_minus_b + T(3) * b * t33 * t35;
    const T t41 = T(5) * t32 * t29 * a_minus_b + T(5) * b * t33 * t36 + T(2) * t40 * t38 * a;
    const T t42 = b * t41 * t38 + T(5) * t33 * t36 - T(5) * t32 * t29;
    const T t43 = T(3) * t41 * c * t38 - T(6) * b * t42 * t28 - T(7) * t40 * t38;
    const T t44 = b * t40 * t38 + T(3) * t33 * t35 - T(3) * t31 * t29;
    const T t45 = t40 * c * t38 - T(5) * t39 * t38 - T(2) * b * t44 * t28;
    const T t46 = T(2) * b * t43 * t28 + T(3) * t42 * c * t28 - T(7) * t44 * t28;
    const T t47 = t43 * c * t28 - T(7) * t45 * t28 - T(2) * b * t46 * t28;
    const T t48 = t33 * t34 + t39 * b * t38 - t30 * t29;
    const T t49 = T(5) * t48 * t28 - T(2) * b * t45 * t28 - c * t44 * t28;
    const T t50 = T(2) * b * t47 * t28 + T(7) * t49 * t28 + t46 * c * t28;
    const T t51 = t39 * c * t38 - T(2) * b * t48 * t28 - T(3) * t37 * t38;
    const T t52 = t45 * c * t28 + T(2) * b * t49 * t28 - T(5) * t51 * t28;
    const T t53 = t1 * t1;
    const T t54 = t53 * delta_tau;
    const T t55 = t2 * tau_lo;
    const T t56 = t55 * t55;
    const T t57 = t2 * t2;
    const T t58 = t57 * tau_lo;
    G_ap = (T(1) / T(105)) * t27 * t28 * (T(2) * b * t50 * t28 + T(7) * t52 * t28 - t47 * c * t28) + (T(2) / T(35)) * t54 * tau_lo * t50 * t28 + (T(1) / T(35)) * t56 * t41 * t38 + (T(6) / T(35)) * delta_tau * t58 * t42 * t28 + (T(1) / T(7)) * t53 * t2 * t47 * t28 - (T(4) / T(21)) * t26 * t55 * t46 * t28 - (T(1) / T(7)) * t1 * t57 * t43 * t28;
    const T t59 = t33 * t33;
    const T t60 = t59 * t33;
    const T t61 = t60 * t60;
    const T t62 = t61 * t33;
    const T t63 = t29 * t29;
    const T t64 = t63 * t29;
    const T t65 = t64 * t64;
    const T t66 = t65 * t29;
    G_E = (T(1) / T(35)) * (T(10) * t1 * t57 * t44 * t28 + T(2) * delta_tau * t58 * t40 * t38 + T(10) * t52 * t54 * tau_lo * t28 + T(5) * t56 * t62 + T(20) * t53 * t2 * t49 * t28 - T(20) * t26 * t55 * t45 * t28 - T(5) * t66 * (T(20) * t26 * t55 + T(6) * delta_tau * t58 + T(15) * t1 * t57 + t56 + T(6) * t54 * tau_lo + t27 + T(15) * t53 * t2) - T(2) * t27 * (T(5) * (T(2) * b * t51 * t28 + c * t48 * t28 - T(3) * (t33 + b * t37 * t38 - t29) * t28) * t28 + c * t49 * t28 - T(2) * t52 * b * t28) * t28) * t28;
  }
  const T t67 = T(1) / a;
  const T t_star = b * t67;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(7) * t69 * length * in.sigma;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 114 +, 333 ×, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 22190 +, 33866 ×, 2439 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i7_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = r1 * b;
    const T t6 = sqrt(a);
    X = t4 * (t5 + a_minus_b * r0) * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r1 * b;
    X = -t7 * (a_minus_b - b) / (t8 - a_minus_b * r0);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = asinh(X) * t10;
  T F;
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t2 * t2;
    const T t17 = t16 * tau_lo;
    const T t18 = t2 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t1 * t1;
    const T t21 = t20 * delta_tau;
    F = M_panels[6] * t15 + T(6) * t17 * M_panels[1] * delta_tau + t19 * M_panels[0] + T(6) * tau_lo * M_panels[5] * t21 + T(15) * t2 * M_panels[4] * t20 + T(15) * t16 * M_panels[2] * t1 + T(20) * t18 * M_panels[3] * t14;
    const T t22 = T(20) * t18 * M_panels[11] * t14 + T(6) * tau_lo * M_panels[13] * t21 + T(6) * t17 * M_panels[9] * delta_tau + T(15) * M_panels[12] * t2 * t20 + T(15) * t16 * M_panels[10] * t1 + t19 * M_panels[8] + M_panels[14] * t15;
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = M_panels[15] * t15 + T(20) * M_panels[12] * t18 * t14 + t19 * M_panels[9] + T(6) * t17 * M_panels[10] * delta_tau + T(6) * tau_lo * M_panels[14] * t21 + T(15) * t2 * M_panels[13] * t20 + T(15) * t16 * M_panels[11] * t1 - t23 * t22 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t1 * t1;
    const T t25 = t2 * tau_lo;
    const T t26 = t1 * delta_tau;
    const T t27 = t2 * t2;
    const T t28 = t26 * t26;
    const T t29 = t25 * t25;
    const T t30 = t27 * tau_lo;
    const T t31 = t24 * delta_tau;
    F = T(15) * t2 * M_panels[4] * t24 + T(20) * t25 * M_panels[3] * t26 + T(15) * M_panels[2] * t27 * t1 + M_panels[6] * t28 + t29 * M_panels[0] + T(6) * t30 * M_panels[1] * delta_tau + T(6) * tau_lo * M_panels[5] * t31;
    const T t32 = M_panels[14] * t28 + T(6) * t30 * M_panels[9] * delta_tau + t29 * M_panels[8] + T(6) * tau_lo * M_panels[13] * t31 + T(15) * t27 * M_panels[10] * t1 + T(15) * t2 * M_panels[12] * t24 + T(20) * t25 * M_panels[11] * t26;
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(15) * t27 * M_panels[11] * t1 + T(15) * t2 * M_panels[13] * t24 + t29 * M_panels[9] + T(20) * t25 * M_panels[12] * t26 + T(6) * tau_lo * M_panels[14] * t31 + M_panels[15] * t28 + T(6) * t30 * M_panels[10] * delta_tau - t32 * t33 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t2 * t2;
    const T t35 = T(1) / a;
    const T t36 = T(1) / D;
    const T t37 = T(1) / r1;
    const T t38 = T(1) / r0;
    const T t39 = t37 * a_minus_b + b * t38;
    const T t40 = t38 * t38;
    const T t41 = t37 * t37;
    const T t42 = T(2) * t36 * a * t39 + b * t40 * t38 + t37 * a_minus_b * t41;
    const T t43 = t41 * t41;
    const T t44 = t40 * t40;
    const T t45 = T(3) * t37 * a_minus_b * t43 + T(3) * b * t44 * t38 + T(4) * t36 * a * t42;
    const T t46 = t36 * b * t45 + T(3) * t44 * t38 - T(3) * t37 * t43;
    const T t47 = T(5) * t36 * t42 + T(2) * t35 * b * t46 - t36 * t45 * c;
    const T t48 = t40 * t38 + t36 * b * t42 - t37 * t41;
    const T t49 = t35 * c * t46 - T(2) * t35 * t47 * b - T(5) * t35 * t48;
    const T t50 = T(3) * t36 * t39 + T(2) * t35 * b * t48 - t36 * t42 * c;
    const T t51 = t35 * t47 * c + T(2) * t35 * t49 * b - T(5) * t50 * t35;
    const T t52 = t37 - t38 - t36 * b * t39;
    const T t53 = t35 * t48 * c + T(3) * t35 * t52 - T(2) * t50 * t35 * b;
    const T t54 = t35 * t49 * c - T(2) * t35 * b * t51 - T(5) * t35 * t53;
    const T t55 = t1 * delta_tau;
    const T t56 = t55 * t55;
    const T t57 = t2 * tau_lo;
    const T t58 = t57 * t57;
    const T t59 = t34 * tau_lo;
    const T t60 = t1 * t1;
    const T t61 = t60 * delta_tau;
    F = t34 * t35 * t47 * t1 + (T(1) / T(15)) * t35 * (t35 * c * t51 + T(2) * t35 * b * t54 - T(5) * t35 * (T(2) * t35 * b * t53 + t50 * t35 * c - T(3) * (J1 - t36 * t39 * c - T(2) * t35 * t52 * b) * t35)) * t56 + (T(1) / T(15)) * t58 * t36 * t45 + (T(2) / T(5)) * t59 * t35 * delta_tau * t46 + (T(2) / T(5)) * tau_lo * t35 * t54 * t61 - t2 * t35 * t51 * t60 - (T(4) / T(3)) * t57 * t35 * t49 * t55;
    const T t62 = t43 * t41;
    const T t63 = t44 * t40;
    const T t64 = T(2) * t36 * a * t45 + T(5) * t37 * a_minus_b * t62 + T(5) * b * t63 * t38;
    const T t65 = t64 * t36 * b + T(5) * t63 * t38 - T(5) * t37 * t62;
    const T t66 = T(7) * t36 * t45 + T(6) * t35 * t65 * b - T(3) * t64 * t36 * c;
    const T t67 = T(7) * t35 * t46 + T(2) * t35 * b * t66 - T(3) * t35 * t65 * c;
    const T t68 = T(7) * t35 * t47 + T(2) * t35 * t67 * b - t35 * t66 * c;
    const T t69 = T(2) * t35 * t68 * b - T(7) * t35 * t49 - t35 * t67 * c;
    G_ap = (T(6) / T(35)) * t59 * t35 * t65 * delta_tau + (T(4) / T(21)) * t57 * t35 * t67 * t55 + (T(1) / T(35)) * t64 * t58 * t36 + (T(2) / T(35)) * tau_lo * t69 * t35 * t61 + (T(1) / T(7)) * t2 * t35 * t68 * t60 + (T(1) / T(7)) * t34 * t35 * t66 * t1 - (T(1) / T(105)) * t35 * (T(7) * t35 * t51 + t35 * t68 * c - T(2) * t69 * t35 * b) * t56;
    const T t70 = t37 * t37;
    const T t71 = t70 * t37;
    const T t72 = t71 * t71;
    const T t73 = t72 * t37;
    const T t74 = t38 * t38;
    const T t75 = t74 * t38;
    const T t76 = t75 * t75;
    const T t77 = t76 * t38;
    G_E = -(T(1) / T(35)) * t35 * (T(20) * t2 * t35 * t49 * t60 + T(5) * (t56 + T(20) * t57 * t55 + T(6) * tau_lo * t61 + T(6) * t59 * delta_tau + T(15) * t2 * t60 + T(15) * t34 * t1 + t58) * t73 + T(10) * tau_lo * t35 * t51 * t61 - T(5) * t58 * t77 - T(2) * t59 * t36 * t45 * delta_tau - T(10) * t34 * t35 * t1 * t46 - T(20) * t57 * t35 * t47 * t55 - T(2) * t35 * t54 * t56);
  }
  const T t78 = T(1) / a;
  const T t_star = t78 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t79 = sigma2 * sigma2;
  const T t80 = t79 * sigma2;
  const T g_factor = -T(7) * t80 * in.sigma * length;
  f = t80 * F * in.sigma * length;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 86 +, 218 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 13534 +, 18698 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i8_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * t2;
    const T t11 = t10 * tau_lo;
    const T t12 = t1 * t1;
    const T t13 = t12 * delta_tau;
    const T t14 = t2 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    F = t9 * M_panels[7] + T(21) * M_panels[2] * t1 * t11 + T(7) * M_panels[6] * t8 * tau_lo + T(21) * M_panels[5] * t13 * t2 + T(35) * M_panels[3] * t7 * t10 + M_panels[0] * t16 + T(7) * delta_tau * t15 * M_panels[1] + T(35) * t12 * t14 * M_panels[4];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t17 = t1 * delta_tau;
    const T t18 = t17 * t17;
    const T t19 = t18 * delta_tau;
    const T t20 = t2 * t2;
    const T t21 = t20 * tau_lo;
    const T t22 = t2 * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t1 * t1;
    const T t26 = t25 * delta_tau;
    F = M_panels[7] * t19 + T(21) * t1 * t21 * M_panels[2] + t24 * M_panels[0] + T(35) * M_panels[3] * t17 * t20 + T(7) * M_panels[6] * t18 * tau_lo + T(35) * M_panels[4] * t25 * t22 + T(7) * M_panels[1] * delta_tau * t23 + T(21) * t26 * t2 * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(D);
    const T t28 = T(1) / t27;
    const T J2 = atan2(t27, c_minus_b) * t28;
    const T t29 = t1 * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = T(1) / q1;
    const T t33 = b * t3 + a_minus_b * t32 + a * J2;
    const T t34 = T(1) / D;
    const T t35 = b * t33 * t34 + t3 - t32;
    const T t36 = T(1) / a;
    const T t37 = T(2) * b * t35 * t36 + T(2) * J2 - t33 * c * t34;
    const T t38 = t32 * t32;
    const T t39 = t3 * t3;
    const T t40 = T(2) * a_minus_b * t38 + T(3) * t33 * t34 * a + T(2) * b * t39;
    const T t41 = b * t40 * t34 + T(2) * t39 - T(2) * t38;
    const T t42 = c * t40 * t34 - T(2) * b * t41 * t36 - T(4) * t33 * t34;
    const T t43 = c * t41 * t36 + T(2) * b * t42 * t36 - T(4) * t35 * t36;
    const T t44 = T(2) * t43 * b * t36 - T(4) * t37 * t36 - t42 * c * t36;
    const T t45 = t38 * t32;
    const T t46 = t39 * t3;
    const T t47 = T(8) * a_minus_b * t45 + T(5) * t40 * t34 * a + T(8) * b * t46;
    const T t48 = b * t47 * t34 + T(8) * t46 - T(8) * t45;
    const T t49 = c * t47 * t34 - T(2) * b * t48 * t36 - T(6) * t40 * t34;
    const T t50 = T(6) * t41 * t36 - t48 * c * t36 - T(2) * b * t49 * t36;
    const T t51 = T(6) * t42 * t36 - T(2) * b * t50 * t36 - c * t49 * t36;
    const T t52 = T(2) * t51 * b * t36 + T(6) * t43 * t36 + c * t50 * t36;
    const T t53 = T(6) * t36 * t44 + T(2) * b * t52 * t36 - t51 * c * t36;
    const T t54 = t2 * t2;
    const T t55 = t2 * tau_lo;
    const T t56 = t55 * t55;
    const T t57 = t56 * tau_lo;
    const T t58 = t1 * t1;
    const T t59 = t54 * tau_lo;
    const T t60 = t58 * delta_tau;
    F = (T(1) / T(48)) * t31 * (T(6) * (T(4) * (T(2) * t37 * b * t36 + (log_ratio + T(2) * b * J2) * t36 - t35 * c * t36) * t36 + t43 * c * t36 - T(2) * b * t36 * t44) * t36 + c * t52 * t36 - T(2) * b * t36 * t53) * t36 + (T(35) / T(48)) * t29 * t54 * t50 * t36 + (T(1) / T(48)) * t47 * t34 * t57 + (T(7) / T(48)) * t48 * delta_tau * t56 * t36 - (T(35) / T(48)) * t51 * t58 * t55 * t36 - (T(7) / T(16)) * t49 * t1 * t59 * t36 - (T(7) / T(16)) * t60 * t2 * t52 * t36 - (T(7) / T(48)) * t30 * tau_lo * t36 * t53;
  }
  const T t61 = sigma2 * sigma2;
  const T t62 = t61 * t61;
  f = length * t62 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 116 +, 308 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 24348 +, 31692 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i8_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t7 * t7;
    const T t12 = t2 * t2;
    const T t13 = t11 * tau_lo;
    const T t14 = t6 * delta_tau;
    const T t15 = t12 * tau_lo;
    const T t16 = T(35) * t6 * t7 * M_panels[13] + t10 * M_panels[16] + T(7) * delta_tau * t11 * M_panels[10] + T(35) * t8 * M_panels[12] * t12 + t13 * M_panels[9] + T(21) * t14 * t2 * M_panels[14] + T(21) * M_panels[11] * t1 * t15 + T(7) * M_panels[15] * t9 * tau_lo;
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = T(35) * t8 * t12 * M_panels[13] + t13 * M_panels[10] + T(7) * M_panels[11] * delta_tau * t11 + T(7) * t9 * tau_lo * M_panels[16] + T(35) * t6 * t7 * M_panels[14] + T(21) * t1 * M_panels[12] * t15 + t10 * M_panels[17] + T(21) * M_panels[15] * t14 * t2 - t16 * t17 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t1 * t1;
    const T t19 = t18 * delta_tau;
    const T t20 = t2 * tau_lo;
    const T t21 = t1 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t20 * t20;
    const T t25 = t24 * tau_lo;
    const T t26 = t2 * t2;
    const T t27 = t26 * tau_lo;
    const T t28 = T(21) * t19 * t2 * M_panels[14] + T(35) * t18 * M_panels[13] * t20 + M_panels[16] * t23 + M_panels[9] * t25 + T(7) * t22 * tau_lo * M_panels[15] + T(7) * delta_tau * t24 * M_panels[10] + T(21) * t1 * t27 * M_panels[11] + T(35) * M_panels[12] * t21 * t26;
    G_ap = t28;
    const T t29 = T(1) / a;
    G_E = T(7) * delta_tau * t24 * M_panels[11] + t23 * M_panels[17] + T(35) * t18 * t20 * M_panels[14] + T(35) * t21 * M_panels[13] * t26 + T(21) * t19 * t2 * M_panels[15] + T(21) * M_panels[12] * t1 * t27 + t25 * M_panels[10] + T(7) * M_panels[16] * t22 * tau_lo - t28 * t29 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = t31 * atan2(t30, c_minus_b);
    const T t32 = t1 * delta_tau;
    const T t33 = t2 * t2;
    const T t34 = T(1) / a;
    const T t35 = T(1) / D;
    const T t36 = T(1) / q1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t36;
    const T t39 = T(1) / c;
    const T t40 = t39 * t39;
    const T t41 = t40 * t39;
    const T t42 = a * J2 + t39 * b + a_minus_b * t36;
    const T t43 = T(2) * a_minus_b * t37 + T(3) * t35 * a * t42 + T(2) * t40 * b;
    const T t44 = T(8) * a_minus_b * t38 + T(8) * t41 * b + T(5) * t43 * t35 * a;
    const T t45 = t40 * t40;
    const T t46 = t37 * t37;
    const T t47 = T(48) * t45 * b + T(48) * a_minus_b * t46 + T(7) * t35 * a * t44;
    const T t48 = t35 * b * t47 + T(48) * t45 - T(48) * t46;
    const T t49 = T(8) * t35 * t44 + T(2) * t34 * t48 * b - c * t35 * t47;
    const T t50 = T(8) * t38 - T(8) * t41 - t35 * t44 * b;
    const T t51 = T(2) * t34 * t49 * b - T(8) * t34 * t50 - c * t34 * t48;
    const T t52 = t2 * tau_lo;
    const T t53 = t52 * t52;
    const T t54 = t53 * tau_lo;
    const T t55 = t33 * tau_lo;
    const T t56 = t1 * t1;
    const T t57 = T(6) * t43 * t35 - T(2) * t34 * b * t50 - c * t35 * t44;
    const T t58 = T(8) * t34 * t57 + T(2) * t34 * b * t51 - c * t34 * t49;
    const T t59 = t32 * t32;
    const T t60 = t59 * delta_tau;
    const T t61 = T(2) * t37 - T(2) * t40 - t43 * t35 * b;
    const T t62 = c * t34 * t50 + T(2) * t34 * t57 * b - T(6) * t34 * t61;
    const T t63 = c * t34 * t51 - T(2) * t34 * t58 * b - T(8) * t34 * t62;
    const T t64 = T(2) * t34 * b * t61 + c * t43 * t35 - T(4) * t35 * t42;
    const T t65 = T(2) * t34 * b * t62 - c * t34 * t57 - T(6) * t64 * t34;
    const T t66 = T(2) * t34 * t63 * b + c * t34 * t58 - T(8) * t65 * t34;
    const T t67 = t39 + t35 * t42 * b - t36;
    const T t68 = T(4) * t67 * t34 + c * t34 * t61 - T(2) * t64 * t34 * b;
    const T t69 = T(2) * t65 * t34 * b + T(6) * t68 * t34 - c * t34 * t62;
    const T t70 = t56 * delta_tau;
    G_ap = (T(35) / T(384)) * t32 * t33 * t34 * t51 + (T(1) / T(384)) * t35 * t54 * t47 + (T(7) / T(128)) * t1 * t55 * t34 * t49 + (T(35) / T(384)) * t56 * t52 * t34 * t58 + (T(7) / T(384)) * delta_tau * t53 * t34 * t48 - (T(1) / T(384)) * t60 * t34 * (T(2) * t34 * t66 * b - T(8) * t69 * t34 - c * t34 * t63) - (T(7) / T(384)) * t59 * tau_lo * t34 * t66 - (T(7) / T(128)) * t70 * t2 * t34 * t63;
    G_E = (T(1) / T(384)) * (T(140) * t56 * t52 * t34 * t62 + T(7) * t60 * (T(6) * (c * t64 * t34 + T(4) * (T(2) * t67 * t34 * b + T(2) * J2 - c * t35 * t42) * t34 + T(2) * t68 * t34 * b) * t34 + T(2) * t69 * t34 * b - c * t65 * t34) * t34 + T(42) * t59 * tau_lo * t69 * t34 + T(48) * t45 * t54 + T(7) * delta_tau * t35 * t53 * t44 + T(105) * t32 * t33 * t34 * t57 + T(105) * t70 * t2 * t65 * t34 - T(42) * t1 * t55 * t34 * t50 - T(48) * t46 * (T(7) * delta_tau * t53 + t54 + t60 + T(7) * t59 * tau_lo + T(21) * t70 * t2 + T(35) * t56 * t52 + T(35) * t32 * t33 + T(21) * t1 * t55)) * t34;
  }
  const T t71 = T(1) / a;
  const T t_star = t71 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - ab2 * t_star;
  const T t72 = sigma2 * sigma2;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * length * t73;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 130 +, 363 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 24355 +, 31715 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i8_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t1 * t1;
    const T t11 = t2 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t10 * delta_tau;
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t12 * tau_lo;
    F = t9 * M_panels[7] + T(35) * M_panels[4] * t10 * t11 + T(7) * M_panels[1] * delta_tau * t12 + T(21) * t13 * t2 * M_panels[5] + T(21) * t1 * t15 * M_panels[2] + T(7) * t8 * tau_lo * M_panels[6] + T(35) * t7 * t14 * M_panels[3] + t16 * M_panels[0];
    const T t17 = T(35) * t10 * t11 * M_panels[13] + T(7) * delta_tau * t12 * M_panels[10] + t9 * M_panels[16] + T(21) * t1 * M_panels[11] * t15 + t16 * M_panels[9] + T(21) * M_panels[14] * t13 * t2 + T(35) * t7 * t14 * M_panels[12] + T(7) * t8 * tau_lo * M_panels[15];
    G_ap = t17;
    const T t18 = T(1) / a;
    G_E = T(35) * t7 * t14 * M_panels[13] + M_panels[17] * t9 + T(7) * t8 * tau_lo * M_panels[16] + T(21) * t1 * t15 * M_panels[12] + t16 * M_panels[10] + T(7) * delta_tau * M_panels[11] * t12 + T(35) * M_panels[14] * t10 * t11 + T(21) * t13 * t2 * M_panels[15] - t17 * t18 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t19 = t1 * t1;
    const T t20 = t19 * delta_tau;
    const T t21 = t1 * delta_tau;
    const T t22 = t2 * t2;
    const T t23 = t21 * t21;
    const T t24 = t2 * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * delta_tau;
    const T t28 = t22 * tau_lo;
    F = T(21) * M_panels[5] * t20 * t2 + T(35) * t21 * t22 * M_panels[3] + T(7) * t23 * tau_lo * M_panels[6] + T(7) * delta_tau * t25 * M_panels[1] + t26 * M_panels[0] + T(35) * t19 * t24 * M_panels[4] + t27 * M_panels[7] + T(21) * M_panels[2] * t1 * t28;
    const T t29 = T(21) * t20 * t2 * M_panels[14] + T(7) * delta_tau * t25 * M_panels[10] + T(7) * M_panels[15] * t23 * tau_lo + T(21) * t1 * t28 * M_panels[11] + T(35) * t19 * t24 * M_panels[13] + t27 * M_panels[16] + t26 * M_panels[9] + T(35) * t21 * M_panels[12] * t22;
    G_ap = t29;
    const T t30 = T(1) / a;
    G_E = T(7) * delta_tau * t25 * M_panels[11] + t26 * M_panels[10] + T(35) * t19 * t24 * M_panels[14] + t27 * M_panels[17] + T(21) * t1 * M_panels[12] * t28 + T(21) * M_panels[15] * t20 * t2 + T(35) * t21 * t22 * M_panels[13] + T(7) * t23 * tau_lo * M_panels[16] - t30 * b * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = t32 * atan2(t31, c_minus_b);
    const T t33 = t2 * t2;
    const T t34 = t33 * tau_lo;
    const T t35 = T(1) / D;
    const T t36 = t3 * t3;
    const T t37 = T(1) / q1;
    const T t38 = a_minus_b * t37 + J2 * a + t3 * b;
    const T t39 = t37 * t37;
    const T t40 = T(2) * t36 * b + T(3) * t38 * t35 * a + T(2) * a_minus_b * t39;
    const T t41 = T(1) / a;
    const T t42 = t36 * t3;
    const T t43 = t39 * t37;
    const T t44 = T(8) * t42 * b + T(8) * a_minus_b * t43 + T(5) * t35 * t40 * a;
    const T t45 = T(8) * t42 + t44 * t35 * b - T(8) * t43;
    const T t46 = T(6) * t35 * t40 + T(2) * t41 * t45 * b - c * t44 * t35;
    const T t47 = t1 * t1;
    const T t48 = t2 * tau_lo;
    const T t49 = T(2) * t36 + t35 * t40 * b - T(2) * t39;
    const T t50 = T(2) * t46 * t41 * b + T(6) * t41 * t49 - c * t41 * t45;
    const T t51 = T(2) * t41 * t49 * b + T(4) * t38 * t35 - c * t35 * t40;
    const T t52 = T(2) * t41 * b * t50 + T(6) * t51 * t41 - c * t46 * t41;
    const T t53 = t1 * delta_tau;
    const T t54 = t48 * t48;
    const T t55 = t37 - t38 * t35 * b - t3;
    const T t56 = c * t41 * t49 + T(4) * t55 * t41 - T(2) * t51 * t41 * b;
    const T t57 = T(2) * J2 - T(2) * t55 * t41 * b - c * t38 * t35;
    const T t58 = T(2) * t56 * t41 * b + c * t51 * t41 - T(4) * t41 * t57;
    const T t59 = T(6) * t56 * t41 + c * t41 * t50 - T(2) * t41 * b * t52;
    const T t60 = T(6) * t58 * t41 + T(2) * t59 * t41 * b + c * t41 * t52;
    const T t61 = t53 * t53;
    const T t62 = t61 * delta_tau;
    const T t63 = t54 * tau_lo;
    const T t64 = t47 * delta_tau;
    F = (T(7) / T(16)) * t1 * t34 * t46 * t41 + (T(35) / T(48)) * t47 * t48 * t41 * t52 + (T(35) / T(48)) * t53 * t33 * t41 * t50 + (T(7) / T(48)) * delta_tau * t54 * t41 * t45 + (T(1) / T(48)) * (T(6) * (c * t56 * t41 + T(4) * t41 * (T(2) * t41 * b * t57 + t41 * (log_ratio + T(2) * J2 * b) + c * t55 * t41) - T(2) * t58 * t41 * b) * t41 + c * t59 * t41 - T(2) * t41 * t60 * b) * t62 * t41 + (T(1) / T(48)) * t44 * t35 * t63 - (T(7) / T(16)) * t59 * t64 * t2 * t41 - (T(7) / T(48)) * t61 * tau_lo * t41 * t60;
    const T t65 = t36 * t36;
    const T t66 = t39 * t39;
    const T t67 = T(7) * t44 * t35 * a + T(48) * t65 * b + T(48) * a_minus_b * t66;
    const T t68 = T(48) * t65 + t35 * t67 * b - T(48) * t66;
    const T t69 = T(2) * t68 * t41 * b + T(8) * t44 * t35 - c * t35 * t67;
    const T t70 = T(8) * t41 * t45 + T(2) * t41 * t69 * b - t68 * c * t41;
    const T t71 = c * t41 * t69 - T(8) * t46 * t41 - T(2) * t70 * t41 * b;
    const T t72 = c * t70 * t41 + T(2) * t71 * t41 * b - T(8) * t41 * t50;
    const T t73 = c * t71 * t41 + T(8) * t41 * t52 - T(2) * t72 * t41 * b;
    G_ap = (T(7) / T(384)) * t68 * delta_tau * t54 * t41 + (T(1) / T(384)) * t35 * t63 * t67 + (T(7) / T(384)) * t61 * tau_lo * t41 * t73 + (T(7) / T(128)) * t1 * t34 * t41 * t69 + (T(1) / T(384)) * t62 * t41 * (T(2) * t41 * b * t73 + c * t72 * t41 - T(8) * t59 * t41) + (T(35) / T(384)) * t53 * t33 * t70 * t41 - (T(35) / T(384)) * t47 * t48 * t71 * t41 - (T(7) / T(128)) * t72 * t64 * t2 * t41;
    G_E = (T(1) / T(384)) * t41 * (T(105) * t64 * t2 * t41 * t52 + T(105) * t53 * t33 * t46 * t41 + T(140) * t47 * t48 * t41 * t50 + T(42) * t1 * t34 * t41 * t45 + T(7) * t44 * delta_tau * t35 * t54 + T(48) * t65 * t63 - T(48) * (T(21) * t1 * t34 + t63 + T(7) * t61 * tau_lo + T(21) * t64 * t2 + T(35) * t53 * t33 + T(35) * t47 * t48 + t62 + T(7) * delta_tau * t54) * t66 - T(7) * t62 * t41 * t60 - T(42) * t59 * t61 * tau_lo * t41);
  }
  const T t74 = T(1) / a;
  const T t_star = t74 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t75 = sigma2 * sigma2;
  const T t76 = t75 * t75;
  const T g_factor = -T(8) * length * t76;
  f = length * t76 * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 95 +, 272 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 14613 +, 25184 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i9_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r0 * a_minus_b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + b * r1) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = -(b - a_minus_b) * t7 / (t8 - b * r1);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t1 * t1;
    const T t17 = t16 * t16;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t19 * delta_tau;
    const T t21 = t15 * tau_lo;
    const T t22 = t2 * t2;
    const T t23 = t22 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t16 * delta_tau;
    F = T(28) * M_panels[2] * t1 * t15 + M_panels[8] * t17 + T(8) * t20 * tau_lo * M_panels[7] + T(28) * t19 * t2 * M_panels[6] + T(8) * delta_tau * t21 * M_panels[1] + T(70) * t16 * t22 * M_panels[4] + T(56) * t18 * t23 * M_panels[3] + t24 * M_panels[0] + T(56) * M_panels[5] * t25 * t14;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t2 * t2;
    const T t27 = t26 * t26;
    const T t28 = t1 * t1;
    const T t29 = t28 * delta_tau;
    const T t30 = t2 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t31 * tau_lo;
    const T t33 = t28 * t28;
    const T t34 = t1 * delta_tau;
    const T t35 = t34 * t34;
    const T t36 = t35 * delta_tau;
    const T t37 = t26 * tau_lo;
    F = t27 * M_panels[0] + T(56) * M_panels[5] * t29 * t30 + T(8) * delta_tau * t32 * M_panels[1] + T(70) * t28 * t26 * M_panels[4] + t33 * M_panels[8] + T(8) * t36 * tau_lo * M_panels[7] + T(56) * t34 * M_panels[3] * t37 + T(28) * M_panels[6] * t35 * t2 + T(28) * M_panels[2] * t1 * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / a;
    const T t39 = t1 * t1;
    const T t40 = t2 * t2;
    const T t41 = T(1) / D;
    const T t42 = T(1) / r1;
    const T t43 = t42 * t42;
    const T t44 = T(1) / r0;
    const T t45 = t42 * a_minus_b + t44 * b;
    const T t46 = t44 * t44;
    const T t47 = t43 * t42 * a_minus_b + T(2) * t41 * a * t45 + t44 * b * t46;
    const T t48 = t46 * t46;
    const T t49 = t43 * t43;
    const T t50 = T(4) * t41 * t47 * a + T(3) * t44 * b * t48 + T(3) * t49 * t42 * a_minus_b;
    const T t51 = t41 * t50 * b + T(3) * t44 * t48 - T(3) * t49 * t42;
    const T t52 = T(5) * t41 * t47 + T(2) * t38 * b * t51 - t41 * t50 * c;
    const T t53 = t49 * t43;
    const T t54 = t48 * t46;
    const T t55 = T(5) * t53 * t42 * a_minus_b + T(2) * t41 * a * t50 + T(5) * t44 * b * t54;
    const T t56 = t41 * b * t55 + T(5) * t44 * t54 - T(5) * t53 * t42;
    const T t57 = T(7) * t41 * t50 + T(6) * t56 * t38 * b - T(3) * t41 * t55 * c;
    const T t58 = T(7) * t38 * t51 + T(2) * t57 * t38 * b - T(3) * t56 * t38 * c;
    const T t59 = T(7) * t38 * t52 + T(2) * t38 * t58 * b - t57 * t38 * c;
    const T t60 = t2 * tau_lo;
    const T t61 = t60 * t60;
    const T t62 = t61 * tau_lo;
    const T t63 = t1 * delta_tau;
    const T t64 = t40 * tau_lo;
    const T t65 = t40 * t40;
    const T t66 = t39 * t39;
    const T t67 = t43 * t42 - t41 * t47 * b - t44 * t46;
    const T t68 = T(2) * t38 * t52 * b - T(5) * t38 * t67 - t38 * t51 * c;
    const T t69 = T(3) * t41 * t45 - t41 * t47 * c - T(2) * t38 * t67 * b;
    const T t70 = t38 * t52 * c - T(5) * t38 * t69 - T(2) * t68 * t38 * b;
    const T t71 = t44 + t41 * t45 * b - t42;
    const T t72 = T(2) * t38 * b * t69 + t38 * t67 * c + T(3) * t38 * t71;
    const T t73 = t68 * t38 * c + T(2) * t38 * t70 * b - T(5) * t38 * t72;
    const T t74 = t38 * t58 * c - T(2) * t38 * b * t59 - T(7) * t68 * t38;
    const T t75 = T(7) * t38 * t70 + T(2) * t74 * t38 * b + t38 * c * t59;
    const T t76 = T(7) * t38 * t73 + T(2) * t38 * t75 * b - t74 * t38 * c;
    const T t77 = t63 * t63;
    const T t78 = t77 * delta_tau;
    const T t79 = t39 * delta_tau;
    F = (T(2) / T(3)) * t38 * t39 * t40 * t59 + (T(8) / T(35)) * t56 * t38 * delta_tau * t62 + (T(8) / T(15)) * t38 * t58 * t63 * t64 + (T(4) / T(15)) * t57 * t38 * t1 * t61 + (T(1) / T(35)) * t41 * t65 * t55 - (T(1) / T(105)) * t38 * t66 * (T(2) * t38 * b * t76 - t38 * t75 * c - T(7) * t38 * (T(5) * t38 * (T(3) * t38 * (J1 + T(2) * t38 * b * t71 - t41 * t45 * c) + T(2) * t38 * b * t72 - t38 * t69 * c) + t38 * t70 * c - T(2) * t38 * t73 * b)) - (T(4) / T(15)) * t38 * t75 * t77 * t2 - (T(8) / T(105)) * t38 * t78 * tau_lo * t76 - (T(8) / T(15)) * t74 * t38 * t79 * t60;
  }
  const T t80 = sigma2 * sigma2;
  const T t81 = t80 * t80;
  f = in.sigma * F * t81 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 127 +, 378 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 26507 +, 40336 ×, 2437 /, 1139 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i9_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t2 * tau_lo;
    const T t10 = t1 * t1;
    const T t11 = t10 * delta_tau;
    const T t12 = t2 * t2;
    const T t13 = t10 * t10;
    const T t14 = t9 * t9;
    const T t15 = t14 * tau_lo;
    const T t16 = t12 * t12;
    const T t17 = t12 * tau_lo;
    const T t18 = T(8) * tau_lo * M_panels[17] * t8 + T(56) * t9 * M_panels[15] * t11 + T(70) * t12 * M_panels[14] * t10 + M_panels[18] * t13 + T(8) * t15 * M_panels[11] * delta_tau + t16 * M_panels[10] + T(56) * t17 * M_panels[13] * t6 + T(28) * t2 * M_panels[16] * t7 + T(28) * t14 * M_panels[12] * t1;
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = t13 * M_panels[19] + T(28) * t14 * M_panels[13] * t1 + T(56) * t9 * M_panels[16] * t11 + T(56) * t17 * M_panels[14] * t6 + t16 * M_panels[11] + T(70) * t12 * M_panels[15] * t10 + T(8) * tau_lo * M_panels[18] * t8 + T(28) * t2 * M_panels[17] * t7 + T(8) * t15 * M_panels[12] * delta_tau - t19 * b * t18;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t2 * tau_lo;
    const T t21 = t1 * t1;
    const T t22 = t21 * delta_tau;
    const T t23 = t2 * t2;
    const T t24 = t21 * t21;
    const T t25 = t20 * t20;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * tau_lo;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t29 * delta_tau;
    const T t31 = t23 * t23;
    const T t32 = T(56) * t20 * M_panels[15] * t22 + T(70) * t23 * M_panels[14] * t21 + t24 * M_panels[18] + T(8) * t26 * M_panels[11] * delta_tau + T(56) * t27 * M_panels[13] * t28 + T(28) * t2 * M_panels[16] * t29 + T(8) * tau_lo * M_panels[17] * t30 + T(28) * t25 * M_panels[12] * t1 + t31 * M_panels[10];
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(28) * t2 * M_panels[17] * t29 + T(8) * tau_lo * t30 * M_panels[18] + T(28) * t25 * M_panels[13] * t1 + T(56) * t20 * M_panels[16] * t22 + T(56) * t27 * M_panels[14] * t28 + t31 * M_panels[11] + M_panels[19] * t24 + T(8) * t26 * M_panels[12] * delta_tau + T(70) * t23 * M_panels[15] * t21 - t33 * b * t32;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t2 * t2;
    const T t35 = T(1) / a;
    const T t36 = T(1) / D;
    const T t37 = T(1) / r0;
    const T t38 = t37 * t37;
    const T t39 = T(1) / r1;
    const T t40 = t39 * a_minus_b + b * t37;
    const T t41 = t39 * t39;
    const T t42 = b * t37 * t38 + T(2) * t36 * a * t40 + t41 * t39 * a_minus_b;
    const T t43 = t41 * t41;
    const T t44 = t38 * t38;
    const T t45 = T(4) * t36 * a * t42 + T(3) * t43 * t39 * a_minus_b + T(3) * b * t37 * t44;
    const T t46 = t44 * t38;
    const T t47 = t43 * t41;
    const T t48 = T(2) * t36 * a * t45 + T(5) * b * t37 * t46 + T(5) * t47 * t39 * a_minus_b;
    const T t49 = t36 * t48 * b + T(5) * t37 * t46 - T(5) * t47 * t39;
    const T t50 = T(7) * t36 * t45 + T(6) * t35 * b * t49 - T(3) * t36 * t48 * c;
    const T t51 = t44 * t44;
    const T t52 = t43 * t43;
    const T t53 = T(35) * t52 * t39 * a_minus_b + T(8) * t36 * a * t48 + T(35) * b * t37 * t51;
    const T t54 = T(35) * t37 * t51 + t36 * t53 * b - T(35) * t52 * t39;
    const T t55 = T(2) * t35 * t54 * b + T(9) * t36 * t48 - t36 * t53 * c;
    const T t56 = t35 * t54 * c - T(2) * t55 * t35 * b - T(9) * t35 * t49;
    const T t57 = T(3) * t35 * t50 - T(2) * t35 * b * t56 - t55 * t35 * c;
    const T t58 = t1 * t1;
    const T t59 = t2 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = T(3) * t37 * t44 + t36 * b * t45 - T(3) * t43 * t39;
    const T t62 = T(2) * t35 * b * t50 + T(7) * t35 * t61 - T(3) * t35 * c * t49;
    const T t63 = t35 * t56 * c + T(2) * t35 * b * t57 + T(3) * t62 * t35;
    const T t64 = t58 * delta_tau;
    const T t65 = t60 * tau_lo;
    const T t66 = t34 * t34;
    const T t67 = T(5) * t36 * t42 + T(2) * t35 * t61 * b - t36 * c * t45;
    const T t68 = t35 * t50 * c - T(7) * t35 * t67 - T(2) * t62 * t35 * b;
    const T t69 = T(3) * t35 * t68 + t35 * c * t57 - T(2) * t35 * t63 * b;
    const T t70 = t36 * t42 * b + t37 * t38 - t41 * t39;
    const T t71 = T(2) * t35 * b * t67 + T(5) * t35 * t70 - t35 * t61 * c;
    const T t72 = T(2) * t35 * b * t68 + t62 * t35 * c - T(7) * t71 * t35;
    const T t73 = T(2) * t35 * t69 * b + T(3) * t35 * t72 + t35 * t63 * c;
    const T t74 = T(2) * t35 * t70 * b + T(3) * t36 * t40 - t36 * t42 * c;
    const T t75 = T(2) * t71 * t35 * b + T(5) * t35 * t74 - t35 * t67 * c;
    const T t76 = T(7) * t35 * t75 + t35 * c * t68 - T(2) * t35 * t72 * b;
    const T t77 = t58 * t58;
    const T t78 = t1 * delta_tau;
    const T t79 = t78 * t78;
    const T t80 = t34 * tau_lo;
    const T t81 = t79 * delta_tau;
    G_ap = (T(2) / T(9)) * t34 * t35 * t57 * t58 + (T(4) / T(45)) * t60 * t55 * t35 * t1 + (T(8) / T(45)) * t59 * t35 * t63 * t64 + (T(8) / T(315)) * t65 * t35 * t54 * delta_tau + (T(1) / T(315)) * t36 * t66 * t53 - (T(1) / T(315)) * (T(2) * t35 * t73 * b - t35 * t69 * c - T(3) * t35 * t76) * t35 * t77 - (T(4) / T(45)) * t2 * t35 * t69 * t79 - (T(8) / T(45)) * t80 * t35 * t56 * t78 - (T(8) / T(315)) * tau_lo * t35 * t73 * t81;
    const T t82 = t37 * t37;
    const T t83 = t82 * t82;
    const T t84 = t83 * t83;
    const T t85 = t84 * t37;
    const T t86 = t39 * t39;
    const T t87 = t86 * t86;
    const T t88 = t87 * t87;
    const T t89 = t88 * t39;
    G_E = (T(1) / T(945)) * t35 * (T(280) * t34 * t62 * t35 * t58 + T(105) * t66 * t85 + T(168) * t60 * t35 * t49 * t1 + T(56) * tau_lo * t35 * t76 * t81 + T(8) * t35 * (T(7) * t35 * (T(2) * t35 * b * t75 + T(5) * t35 * (T(2) * t35 * b * t74 - t35 * t70 * c - T(3) * t35 * (t39 - t36 * b * t40 - t37)) - t71 * t35 * c) + T(2) * t35 * t76 * b + t35 * t72 * c) * t77 + T(168) * t80 * t35 * t50 * t78 + T(24) * t36 * t65 * t48 * delta_tau - T(105) * (T(70) * t34 * t58 + T(8) * tau_lo * t81 + t66 + t77 + T(28) * t60 * t1 + T(28) * t2 * t79 + T(56) * t80 * t78 + T(8) * t65 * delta_tau + T(56) * t59 * t64) * t89 - T(280) * t59 * t35 * t68 * t64 - T(168) * t2 * t35 * t72 * t79);
  }
  const T t90 = T(1) / a;
  const T t_star = t90 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T g_factor = -T(9) * t92 * in.sigma * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 144 +, 447 ×, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 26516 +, 40368 ×, 2439 /, 1141 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i9_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    const T t6 = T(1) / D;
    X = t4 * (t5 + r1 * b) * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = a_minus_b * r0;
    X = t7 * (a_minus_b - b) / (t8 - r1 * b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t1 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t15 * tau_lo;
    const T t19 = t1 * t1;
    const T t20 = t2 * t2;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t19 * delta_tau;
    const T t24 = t17 * delta_tau;
    const T t25 = t20 * tau_lo;
    F = T(28) * M_panels[2] * t1 * t15 + T(28) * t17 * t2 * M_panels[6] + T(8) * M_panels[1] * delta_tau * t18 + T(70) * M_panels[4] * t19 * t20 + M_panels[0] * t21 + M_panels[8] * t22 + T(56) * M_panels[5] * t23 * t14 + T(8) * M_panels[7] * t24 * tau_lo + T(56) * M_panels[3] * t16 * t25;
    const T t26 = T(56) * M_panels[15] * t23 * t14 + T(56) * M_panels[13] * t16 * t25 + M_panels[10] * t21 + T(70) * M_panels[14] * t19 * t20 + T(8) * M_panels[17] * t24 * tau_lo + M_panels[18] * t22 + T(8) * M_panels[11] * delta_tau * t18 + T(28) * M_panels[16] * t17 * t2 + T(28) * M_panels[12] * t1 * t15;
    G_ap = t26;
    const T t27 = T(1) / a;
    G_E = M_panels[11] * t21 + T(8) * M_panels[12] * delta_tau * t18 + T(28) * M_panels[17] * t17 * t2 + T(28) * M_panels[13] * t1 * t15 + T(56) * M_panels[14] * t16 * t25 + T(8) * M_panels[18] * t24 * tau_lo + T(70) * M_panels[15] * t19 * t20 + M_panels[19] * t22 + T(56) * M_panels[16] * t23 * t14 - t27 * t26 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t28 = t2 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = t1 * delta_tau;
    const T t31 = t30 * t30;
    const T t32 = t2 * t2;
    const T t33 = t32 * t32;
    const T t34 = t31 * delta_tau;
    const T t35 = t32 * tau_lo;
    const T t36 = t1 * t1;
    const T t37 = t36 * delta_tau;
    const T t38 = t36 * t36;
    const T t39 = t29 * tau_lo;
    F = T(28) * t1 * t29 * M_panels[2] + T(28) * M_panels[6] * t31 * t2 + M_panels[0] * t33 + T(8) * M_panels[7] * t34 * tau_lo + T(56) * M_panels[3] * t30 * t35 + T(56) * t37 * t28 * M_panels[5] + t38 * M_panels[8] + T(70) * M_panels[4] * t36 * t32 + T(8) * M_panels[1] * delta_tau * t39;
    const T t40 = T(56) * M_panels[13] * t30 * t35 + M_panels[10] * t33 + T(70) * t36 * t32 * M_panels[14] + T(56) * M_panels[15] * t37 * t28 + M_panels[18] * t38 + T(8) * M_panels[11] * delta_tau * t39 + T(8) * t34 * M_panels[17] * tau_lo + T(28) * M_panels[16] * t31 * t2 + T(28) * M_panels[12] * t1 * t29;
    G_ap = t40;
    const T t41 = T(1) / a;
    G_E = T(8) * M_panels[12] * delta_tau * t39 + T(28) * t31 * M_panels[17] * t2 + T(28) * M_panels[13] * t1 * t29 + M_panels[19] * t38 + T(56) * M_panels[16] * t37 * t28 + T(8) * M_panels[18] * t34 * tau_lo + M_panels[11] * t33 + T(70) * M_panels[15] * t36 * t32 + T(56) * t30 * t35 * M_panels[14] - t41 * b * t40;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t42 = T(1) / a;
    const T t43 = T(1) / r0;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t44;
    const T t47 = T(1) / r1;
    const T t48 = t47 * t47;
    const T t49 = t47 * a_minus_b + b * t43;
    const T t50 = T(1) / D;
    const T t51 = b * t44 * t43 + t47 * a_minus_b * t48 + T(2) * a * t49 * t50;
    const T t52 = t48 * t48;
    const T t53 = T(4) * a * t51 * t50 + T(3) * t47 * a_minus_b * t52 + T(3) * b * t45 * t43;
    const T t54 = t52 * t48;
    const T t55 = T(2) * a * t53 * t50 + T(5) * t47 * a_minus_b * t54 + T(5) * b * t46 * t43;
    const T t56 = T(5) * t46 * t43 + t55 * b * t50 - T(5) * t47 * t54;
    const T t57 = t2 * tau_lo;
    const T t58 = t57 * t57;
    const T t59 = t58 * tau_lo;
    const T t60 = T(6) * t42 * t56 * b + T(7) * t53 * t50 - T(3) * t55 * c * t50;
    const T t61 = t2 * t2;
    const T t62 = t61 * t61;
    const T t63 = T(3) * t47 * t52 - T(3) * t45 * t43 - b * t53 * t50;
    const T t64 = T(7) * t42 * t63 + T(3) * t42 * t56 * c - T(2) * t42 * b * t60;
    const T t65 = T(5) * t51 * t50 - T(2) * t42 * b * t63 - t53 * c * t50;
    const T t66 = t42 * c * t60 + T(2) * t42 * b * t64 - T(7) * t42 * t65;
    const T t67 = t1 * t1;
    const T t68 = t1 * delta_tau;
    const T t69 = t61 * tau_lo;
    const T t70 = b * t51 * t50 + t44 * t43 - t47 * t48;
    const T t71 = t51 * c * t50 - T(2) * t42 * t70 * b - T(3) * t49 * t50;
    const T t72 = b * t49 * t50 + t43 - t47;
    const T t73 = T(2) * t42 * b * t71 + t42 * t70 * c - T(3) * t42 * t72;
    const T t74 = t42 * t63 * c + T(2) * t42 * b * t65 + T(5) * t42 * t70;
    const T t75 = t42 * t65 * c + T(5) * t42 * t71 - T(2) * t42 * b * t74;
    const T t76 = T(5) * t42 * t73 + T(2) * t42 * t75 * b + t42 * t74 * c;
    const T t77 = T(2) * t66 * t42 * b - T(7) * t42 * t74 - t42 * t64 * c;
    const T t78 = T(2) * t42 * b * t77 + T(7) * t42 * t75 - t66 * t42 * c;
    const T t79 = T(7) * t42 * t76 + T(2) * t42 * b * t78 - t42 * t77 * c;
    const T t80 = t67 * t67;
    const T t81 = t68 * t68;
    const T t82 = t81 * delta_tau;
    const T t83 = t67 * delta_tau;
    F = (T(8) / T(35)) * t42 * t56 * delta_tau * t59 + (T(4) / T(15)) * t42 * t1 * t58 * t60 + (T(1) / T(35)) * t55 * t50 * t62 - (T(2) / T(3)) * t66 * t42 * t67 * t61 - (T(8) / T(15)) * t42 * t64 * t68 * t69 - (T(1) / T(105)) * t42 * (T(7) * t42 * (T(5) * t42 * (T(2) * t42 * b * t73 - T(3) * t42 * (T(2) * t42 * b * t72 + J1 - c * t49 * t50) - t42 * t71 * c) + T(2) * t42 * b * t76 - t42 * t75 * c) + T(2) * t42 * t79 * b - t42 * t78 * c) * t80 - (T(8) / T(105)) * t42 * t79 * t82 * tau_lo - (T(4) / T(15)) * t42 * t78 * t81 * t2 - (T(8) / T(15)) * t42 * t77 * t83 * t57;
    const T t84 = t52 * t52;
    const T t85 = t45 * t45;
    const T t86 = T(35) * b * t85 * t43 + T(8) * a * t55 * t50 + T(35) * t47 * a_minus_b * t84;
    const T t87 = T(35) * t47 * t84 - t86 * b * t50 - T(35) * t85 * t43;
    const T t88 = T(9) * t55 * t50 - T(2) * t42 * t87 * b - t86 * c * t50;
    const T t89 = t42 * t87 * c + T(9) * t42 * t56 + T(2) * t42 * t88 * b;
    const T t90 = t42 * t88 * c - T(3) * t42 * t60 - T(2) * t42 * b * t89;
    const T t91 = t42 * t89 * c + T(3) * t42 * t64 + T(2) * t42 * b * t90;
    const T t92 = t42 * c * t90 - T(2) * t42 * b * t91 - T(3) * t66 * t42;
    const T t93 = t42 * c * t91 + T(2) * t42 * t92 * b - T(3) * t42 * t77;
    G_ap = (T(8) / T(315)) * t42 * t93 * t82 * tau_lo + (T(4) / T(45)) * t42 * t88 * t1 * t58 + (T(1) / T(315)) * t42 * (T(2) * t42 * t93 * b - T(3) * t42 * t78 - t42 * t92 * c) * t80 + (T(4) / T(45)) * t42 * t92 * t81 * t2 + (T(8) / T(45)) * t42 * t89 * t68 * t69 + (T(1) / T(315)) * t86 * t50 * t62 - (T(8) / T(315)) * t42 * t87 * delta_tau * t59 - (T(8) / T(45)) * t42 * t83 * t91 * t57 - (T(2) / T(9)) * t42 * t67 * t90 * t61;
    const T t94 = t47 * t47;
    const T t95 = t94 * t94;
    const T t96 = t95 * t95;
    const T t97 = t96 * t47;
    const T t98 = t43 * t43;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t43;
    G_E = -(T(1) / T(945)) * t42 * (T(8) * t42 * t79 * t80 + T(168) * t42 * t77 * t81 * t2 + T(105) * t97 * (T(8) * delta_tau * t59 + T(70) * t67 * t61 + T(56) * t68 * t69 + t62 + T(8) * t82 * tau_lo + T(56) * t83 * t57 + t80 + T(28) * t1 * t58 + T(28) * t81 * t2) + T(280) * t66 * t42 * t83 * t57 + T(56) * t42 * t78 * t82 * tau_lo + T(280) * t42 * t64 * t67 * t61 - T(105) * t101 * t62 - T(168) * t42 * t68 * t69 * t60 - T(24) * t55 * delta_tau * t50 * t59 - T(168) * t42 * t56 * t1 * t58);
  }
  const T t102 = T(1) / a;
  const T t_star = t102 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t103 = sigma2 * sigma2;
  const T t104 = t103 * t103;
  const T g_factor = -T(9) * t104 * in.sigma * length;
  f = t104 * F * in.sigma * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 108 +, 300 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15696 +, 21949 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i10_f(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * sigma2 * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ab1 * tau_lo + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t2 * t2;
    const T t9 = t8 * tau_lo;
    const T t10 = t7 * t7;
    const T t11 = t10 * delta_tau;
    const T t12 = t8 * t8;
    const T t13 = t1 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t14 * delta_tau;
    const T t16 = t7 * delta_tau;
    const T t17 = t2 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t12 * tau_lo;
    const T t20 = t18 * tau_lo;
    F = T(126) * t7 * M_panels[4] * t9 + t11 * M_panels[9] + T(9) * delta_tau * M_panels[1] * t12 + T(36) * t15 * M_panels[7] * t2 + T(9) * t10 * M_panels[8] * tau_lo + T(126) * t16 * M_panels[5] * t8 + T(84) * t13 * M_panels[3] * t18 + M_panels[0] * t19 + T(36) * t1 * M_panels[2] * t20 + T(84) * t14 * M_panels[6] * t17;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t2 * tau_lo;
    const T t22 = t21 * t21;
    const T t23 = t22 * tau_lo;
    const T t24 = t1 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t25 * delta_tau;
    const T t27 = t1 * t1;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t2 * t2;
    const T t31 = t30 * t30;
    const T t32 = t31 * tau_lo;
    const T t33 = t27 * delta_tau;
    const T t34 = t30 * tau_lo;
    F = T(36) * t1 * M_panels[2] * t23 + T(36) * t26 * M_panels[7] * t2 + T(84) * t25 * M_panels[6] * t21 + T(9) * t28 * M_panels[8] * tau_lo + t29 * M_panels[9] + T(9) * delta_tau * M_panels[1] * t31 + M_panels[0] * t32 + T(126) * t33 * M_panels[5] * t30 + T(84) * t24 * M_panels[3] * t22 + T(126) * t27 * M_panels[4] * t34;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(D);
    const T t36 = T(1) / t35;
    const T J2 = t36 * atan2(t35, c_minus_b);
    const T t37 = T(1) / a;
    const T t38 = T(1) / D;
    const T t39 = T(1) / q1;
    const T t40 = t39 * t39;
    const T t41 = t40 * t39;
    const T t42 = t3 * t3;
    const T t43 = t42 * t3;
    const T t44 = a * J2 + b * t3 + t39 * a_minus_b;
    const T t45 = T(2) * t40 * a_minus_b + T(2) * b * t42 + T(3) * t38 * a * t44;
    const T t46 = T(8) * t41 * a_minus_b + T(8) * b * t43 + T(5) * t38 * a * t45;
    const T t47 = t40 * t40;
    const T t48 = t42 * t42;
    const T t49 = T(7) * t38 * a * t46 + T(48) * t47 * a_minus_b + T(48) * b * t48;
    const T t50 = T(48) * t47 - t38 * b * t49 - T(48) * t48;
    const T t51 = T(8) * t38 * t46 - T(2) * t37 * t50 * b - t38 * t49 * c;
    const T t52 = t2 * tau_lo;
    const T t53 = t52 * t52;
    const T t54 = t53 * tau_lo;
    const T t55 = t1 * t1;
    const T t56 = t55 * t55;
    const T t57 = t56 * delta_tau;
    const T t58 = T(2) * t40 - t38 * t45 * b - T(2) * t42;
    const T t59 = T(2) * t58 * t37 * b + t38 * t45 * c - T(4) * t38 * t44;
    const T t60 = t3 + t38 * b * t44 - t39;
    const T t61 = T(2) * t37 * b * t59 - T(4) * t37 * t60 - t58 * t37 * c;
    const T t62 = t38 * b * t46 + T(8) * t43 - T(8) * t41;
    const T t63 = t38 * c * t46 - T(2) * t37 * t62 * b - T(6) * t38 * t45;
    const T t64 = T(2) * t37 * b * t63 + T(6) * t58 * t37 + t37 * t62 * c;
    const T t65 = T(2) * t64 * t37 * b + T(6) * t37 * t59 - t37 * t63 * c;
    const T t66 = T(6) * t37 * t61 + T(2) * t37 * t65 * b - t64 * t37 * c;
    const T t67 = T(2) * J2 + T(2) * t37 * b * t60 - t38 * t44 * c;
    const T t68 = T(4) * t37 * t67 + t37 * c * t59 - T(2) * t37 * b * t61;
    const T t69 = T(2) * t37 * b * t66 - T(6) * t37 * t68 - t37 * t65 * c;
    const T t70 = t37 * t50 * c + T(2) * t37 * t51 * b + T(8) * t37 * t62;
    const T t71 = t37 * t51 * c + T(8) * t37 * t63 - T(2) * t37 * b * t70;
    const T t72 = t37 * c * t70 + T(2) * t71 * t37 * b + T(8) * t64 * t37;
    const T t73 = T(8) * t37 * t65 + T(2) * t37 * b * t72 - t71 * t37 * c;
    const T t74 = T(2) * t73 * t37 * b + T(8) * t37 * t66 - t37 * t72 * c;
    const T t75 = T(8) * t37 * t69 + T(2) * t74 * t37 * b - t73 * t37 * c;
    const T t76 = t2 * t2;
    const T t77 = t76 * t76;
    const T t78 = t77 * tau_lo;
    const T t79 = t1 * delta_tau;
    const T t80 = t79 * t79;
    const T t81 = t80 * delta_tau;
    const T t82 = t55 * delta_tau;
    const T t83 = t76 * tau_lo;
    F = (T(3) / T(32)) * t1 * t37 * t51 * t54 + (T(1) / T(384)) * t57 * t37 * (T(8) * t37 * (t37 * c * t66 + T(6) * t37 * (T(4) * t37 * (T(2) * t37 * b * t67 + (log_ratio + T(2) * J2 * b) * t37 - t37 * t60 * c) + t37 * c * t61 + T(2) * t37 * b * t68) - T(2) * t37 * t69 * b) + t74 * t37 * c - T(2) * t37 * t75 * b) + (T(1) / T(384)) * t38 * t49 * t78 + (T(7) / T(32)) * t79 * t37 * t70 * t53 - (T(3) / T(128)) * delta_tau * t37 * t50 * t77 - (T(3) / T(32)) * t81 * t74 * t37 * t2 - (T(21) / T(64)) * t82 * t37 * t72 * t76 - (T(21) / T(64)) * t55 * t71 * t37 * t83 - (T(3) / T(128)) * t56 * t37 * t75 * tau_lo - (T(7) / T(32)) * t80 * t73 * t37 * t52;
  }
  const T t84 = sigma2 * sigma2;
  const T t85 = t84 * t84;
  const T t86 = t85 * sigma2;
  f = t86 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 144 +, 411 ×, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 28672 +, 37109 ×, 2437 /, 57 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i10_grad(const ScalisSegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + delta_tau * ap2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t2 * t2;
    const T t8 = t7 * tau_lo;
    const T t9 = t6 * delta_tau;
    const T t10 = t2 * tau_lo;
    const T t11 = t10 * t10;
    const T t12 = t11 * tau_lo;
    const T t13 = t1 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t6 * t6;
    const T t16 = t7 * t7;
    const T t17 = t16 * tau_lo;
    const T t18 = t15 * delta_tau;
    const T t19 = t14 * delta_tau;
    const T t20 = T(126) * t6 * t8 * M_panels[15] + T(126) * M_panels[16] * t9 * t7 + T(36) * M_panels[13] * t1 * t12 + T(84) * M_panels[17] * t14 * t10 + T(9) * M_panels[19] * t15 * tau_lo + T(9) * M_panels[12] * delta_tau * t16 + M_panels[11] * t17 + M_panels[20] * t18 + T(36) * t19 * M_panels[18] * t2 + T(84) * M_panels[14] * t13 * t11;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = T(126) * M_panels[16] * t6 * t8 + T(36) * M_panels[19] * t19 * t2 + T(9) * M_panels[13] * delta_tau * t16 + M_panels[12] * t17 + T(84) * t13 * t11 * M_panels[15] + T(126) * M_panels[17] * t9 * t7 + T(36) * M_panels[14] * t1 * t12 + T(84) * t14 * M_panels[18] * t10 + M_panels[21] * t18 + T(9) * M_panels[20] * t15 * tau_lo - t21 * b * t20;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * t1;
    const T t23 = t22 * t22;
    const T t24 = t2 * t2;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t24 * tau_lo;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t2 * tau_lo;
    const T t31 = t23 * delta_tau;
    const T t32 = t22 * delta_tau;
    const T t33 = t30 * t30;
    const T t34 = t33 * tau_lo;
    const T t35 = t29 * delta_tau;
    const T t36 = T(9) * M_panels[19] * t23 * tau_lo + M_panels[11] * t26 + T(126) * t22 * M_panels[15] * t27 + T(84) * M_panels[17] * t29 * t30 + M_panels[20] * t31 + T(126) * M_panels[16] * t32 * t24 + T(36) * M_panels[13] * t1 * t34 + T(84) * M_panels[14] * t28 * t33 + T(9) * delta_tau * t25 * M_panels[12] + T(36) * M_panels[18] * t35 * t2;
    G_ap = t36;
    const T t37 = T(1) / a;
    G_E = M_panels[21] * t31 + T(9) * M_panels[13] * delta_tau * t25 + T(36) * M_panels[19] * t35 * t2 + T(126) * M_panels[16] * t22 * t27 + T(9) * M_panels[20] * t23 * tau_lo + t26 * M_panels[12] + T(126) * M_panels[17] * t32 * t24 + T(84) * t28 * M_panels[15] * t33 + T(36) * M_panels[14] * t1 * t34 + T(84) * M_panels[18] * t29 * t30 - t37 * t36 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = t39 * atan2(t38, c_minus_b);
    const T t40 = T(1) / a;
    const T t41 = T(1) / D;
    const T t42 = T(1) / q1;
    const T t43 = t42 * t42;
    const T t44 = t43 * t42;
    const T t45 = T(1) / c;
    const T t46 = t45 * t45;
    const T t47 = t46 * t45;
    const T t48 = a * J2 + t42 * a_minus_b + b * t45;
    const T t49 = T(2) * b * t46 + T(3) * t41 * a * t48 + T(2) * t43 * a_minus_b;
    const T t50 = T(8) * t44 * a_minus_b + T(8) * b * t47 + T(5) * t41 * a * t49;
    const T t51 = t46 * t46;
    const T t52 = t43 * t43;
    const T t53 = T(48) * b * t51 + T(7) * t41 * a * t50 + T(48) * t52 * a_minus_b;
    const T t54 = t41 * b * t53 + T(48) * t51 - T(48) * t52;
    const T t55 = T(8) * t41 * t50 + T(2) * t40 * b * t54 - t41 * c * t53;
    const T t56 = T(8) * t44 - t41 * b * t50 - T(8) * t47;
    const T t57 = T(2) * t40 * t55 * b - T(8) * t40 * t56 - t40 * c * t54;
    const T t58 = T(2) * t40 * b * t56 + t41 * t50 * c - T(6) * t41 * t49;
    const T t59 = T(2) * t40 * b * t57 - T(8) * t40 * t58 - t40 * t55 * c;
    const T t60 = T(2) * t43 - t41 * t49 * b - T(2) * t46;
    const T t61 = t40 * t56 * c - T(6) * t40 * t60 - T(2) * t40 * b * t58;
    const T t62 = T(2) * t40 * b * t59 + T(8) * t40 * t61 - t40 * c * t57;
    const T t63 = t52 * t42;
    const T t64 = t51 * t45;
    const T t65 = T(128) * b * t64 + T(3) * t41 * a * t53 + T(128) * t63 * a_minus_b;
    const T t66 = T(128) * t63 - T(128) * t64 - t41 * t65 * b;
    const T t67 = T(10) * t41 * t53 - T(3) * t41 * t65 * c - T(6) * t66 * t40 * b;
    const T t68 = T(3) * t66 * t40 * c + T(2) * t40 * b * t67 + T(10) * t40 * t54;
    const T t69 = t40 * t67 * c - T(10) * t40 * t55 - T(2) * t40 * t68 * b;
    const T t70 = T(10) * t40 * t57 - t40 * t68 * c - T(2) * t40 * b * t69;
    const T t71 = T(2) * t40 * b * t70 + t40 * t69 * c + T(10) * t40 * t59;
    const T t72 = T(10) * t40 * t62 + T(2) * t40 * t71 * b - t40 * c * t70;
    const T t73 = t1 * delta_tau;
    const T t74 = t73 * t73;
    const T t75 = t74 * delta_tau;
    const T t76 = t2 * tau_lo;
    const T t77 = t76 * t76;
    const T t78 = t77 * tau_lo;
    const T t79 = t2 * t2;
    const T t80 = t79 * t79;
    const T t81 = t80 * tau_lo;
    const T t82 = t1 * t1;
    const T t83 = t82 * delta_tau;
    const T t84 = T(4) * t41 * t48 - t41 * t49 * c - T(2) * t40 * t60 * b;
    const T t85 = T(2) * t40 * t61 * b + t40 * t58 * c + T(6) * t40 * t84;
    const T t86 = t40 * t59 * c - T(2) * t40 * b * t62 - T(8) * t40 * t85;
    const T t87 = t40 * t71 * c + T(10) * t40 * t86 - T(2) * t40 * b * t72;
    const T t88 = t82 * t82;
    const T t89 = t41 * b * t48 + t45 - t42;
    const T t90 = T(2) * t40 * b * t84 + t40 * t60 * c + T(4) * t40 * t89;
    const T t91 = T(2) * t40 * b * t85 + T(6) * t90 * t40 - t40 * t61 * c;
    const T t92 = T(2) * t40 * b * t86 + t40 * t62 * c - T(8) * t40 * t91;
    const T t93 = t88 * delta_tau;
    const T t94 = t79 * tau_lo;
    G_ap = (T(3) / T(320)) * t40 * t72 * t75 * t2 + (T(7) / T(320)) * t40 * t68 * t73 * t77 + (T(3) / T(320)) * t40 * t67 * t1 * t78 + (T(1) / T(1280)) * t41 * t65 * t81 + (T(21) / T(640)) * t40 * t83 * t79 * t70 + (T(7) / T(320)) * t40 * t71 * t74 * t76 - (T(9) / T(1280)) * t66 * t40 * delta_tau * t80 - (T(3) / T(1280)) * t40 * t87 * t88 * tau_lo - (T(1) / T(3840)) * t40 * (T(10) * t40 * t92 + T(2) * t40 * b * t87 + t40 * t72 * c) * t93 - (T(21) / T(640)) * t40 * t69 * t82 * t94;
    G_E = (T(1) / T(1280)) * t40 * (T(84) * t40 * t55 * t73 * t77 + T(210) * t40 * t59 * t83 * t79 + T(168) * t40 * t62 * t74 * t76 + T(128) * t64 * t81 + T(24) * t40 * t1 * t78 * t54 + T(3) * t41 * t53 * delta_tau * t80 + T(168) * t40 * t82 * t94 * t57 - T(3) * (T(2) * t40 * t92 * b - t40 * c * t86 - T(8) * t40 * (T(2) * t40 * b * t91 + T(6) * t40 * (T(4) * t40 * (T(2) * J2 + T(2) * t40 * t89 * b - t41 * c * t48) + T(2) * t90 * t40 * b - t40 * t84 * c) - t40 * c * t85)) * t40 * t93 - T(24) * t40 * t92 * t88 * tau_lo - T(128) * t63 * (T(126) * t83 * t79 + T(126) * t82 * t94 + T(9) * delta_tau * t80 + t93 + T(84) * t73 * t77 + T(9) * t88 * tau_lo + t81 + T(84) * t74 * t76 + T(36) * t75 * t2 + T(36) * t1 * t78) - T(84) * t40 * t75 * t2 * t86);
  }
  const T t95 = T(1) / a;
  const T t_star = t95 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t96 = sigma2 * sigma2;
  const T t97 = t96 * t96;
  const T t98 = t97 * sigma2;
  const T g_factor = -T(10) * t98 * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 162 +, 481 ×, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 28681 +, 37138 ×, 2438 /, 57 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i10_f_and_grad(const ScalisSegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t7 * delta_tau;
    const T t9 = t2 * t2;
    const T t10 = t1 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t9 * tau_lo;
    const T t14 = t9 * t9;
    const T t15 = t14 * tau_lo;
    const T t16 = t7 * t7;
    const T t17 = t16 * delta_tau;
    const T t18 = t2 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t19 * tau_lo;
    F = T(126) * t8 * t9 * M_panels[5] + T(36) * M_panels[7] * t12 * t2 + T(126) * M_panels[4] * t7 * t13 + T(9) * M_panels[1] * delta_tau * t14 + t15 * M_panels[0] + t17 * M_panels[9] + T(84) * t11 * t18 * M_panels[6] + T(36) * t1 * t20 * M_panels[2] + T(84) * t10 * t19 * M_panels[3] + T(9) * t16 * tau_lo * M_panels[8];
    const T t21 = M_panels[20] * t17 + T(126) * t8 * t9 * M_panels[16] + T(9) * delta_tau * t14 * M_panels[12] + T(84) * t10 * M_panels[14] * t19 + t15 * M_panels[11] + T(84) * M_panels[17] * t11 * t18 + T(126) * t7 * t13 * M_panels[15] + T(36) * t12 * t2 * M_panels[18] + T(36) * M_panels[13] * t1 * t20 + T(9) * t16 * tau_lo * M_panels[19];
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(36) * t12 * t2 * M_panels[19] + T(126) * M_panels[17] * t8 * t9 + T(84) * t10 * t19 * M_panels[15] + T(126) * t7 * t13 * M_panels[16] + T(9) * M_panels[20] * t16 * tau_lo + T(9) * M_panels[13] * delta_tau * t14 + T(36) * t1 * M_panels[14] * t20 + t17 * M_panels[21] + t15 * M_panels[12] + T(84) * t11 * t18 * M_panels[18] - t21 * t22 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t23 = t1 * t1;
    const T t24 = t23 * delta_tau;
    const T t25 = t2 * t2;
    const T t26 = t25 * t25;
    const T t27 = t26 * tau_lo;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t2 * tau_lo;
    const T t31 = t29 * delta_tau;
    const T t32 = t25 * tau_lo;
    const T t33 = t30 * t30;
    const T t34 = t33 * tau_lo;
    const T t35 = t23 * t23;
    const T t36 = t35 * delta_tau;
    F = T(126) * t24 * t25 * M_panels[5] + t27 * M_panels[0] + T(84) * t29 * t30 * M_panels[6] + T(36) * M_panels[7] * t31 * t2 + T(126) * M_panels[4] * t23 * t32 + T(36) * t1 * t34 * M_panels[2] + t36 * M_panels[9] + T(84) * t28 * t33 * M_panels[3] + T(9) * M_panels[1] * delta_tau * t26 + T(9) * t35 * tau_lo * M_panels[8];
    const T t37 = T(9) * delta_tau * t26 * M_panels[12] + T(126) * t24 * t25 * M_panels[16] + M_panels[20] * t36 + T(36) * t1 * t34 * M_panels[13] + T(126) * t23 * t32 * M_panels[15] + M_panels[11] * t27 + T(36) * t31 * t2 * M_panels[18] + T(84) * M_panels[14] * t28 * t33 + T(84) * M_panels[17] * t29 * t30 + T(9) * t35 * tau_lo * M_panels[19];
    G_ap = t37;
    const T t38 = T(1) / a;
    G_E = T(36) * t31 * t2 * M_panels[19] + T(9) * M_panels[20] * t35 * tau_lo + T(84) * t28 * t33 * M_panels[15] + T(126) * t23 * t32 * M_panels[16] + T(126) * M_panels[17] * t24 * t25 + T(36) * M_panels[14] * t1 * t34 + T(9) * delta_tau * t26 * M_panels[13] + t27 * M_panels[12] + t36 * M_panels[21] + T(84) * t29 * t30 * M_panels[18] - t37 * t38 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = atan2(t39, c_minus_b) * t40;
    const T t41 = T(1) / a;
    const T t42 = t3 * t3;
    const T t43 = T(1) / D;
    const T t44 = T(1) / q1;
    const T t45 = t44 * t44;
    const T t46 = J2 * a + t3 * b + t44 * a_minus_b;
    const T t47 = T(2) * t45 * a_minus_b + T(2) * t42 * b + T(3) * t43 * a * t46;
    const T t48 = T(2) * t42 + t43 * b * t47 - T(2) * t45;
    const T t49 = T(2) * t41 * t48 * b + T(4) * t43 * t46 - c * t43 * t47;
    const T t50 = t44 - t43 * t46 * b - t3;
    const T t51 = T(2) * t49 * t41 * b - c * t41 * t48 - T(4) * t50 * t41;
    const T t52 = t42 * t3;
    const T t53 = t45 * t44;
    const T t54 = T(8) * t52 * b + T(8) * t53 * a_minus_b + T(5) * t43 * a * t47;
    const T t55 = T(8) * t52 + t54 * t43 * b - T(8) * t53;
    const T t56 = T(2) * t55 * t41 * b + T(6) * t43 * t47 - c * t54 * t43;
    const T t57 = c * t55 * t41 - T(6) * t41 * t48 - T(2) * t41 * t56 * b;
    const T t58 = T(6) * t49 * t41 - T(2) * t57 * t41 * b - c * t41 * t56;
    const T t59 = T(6) * t41 * t51 + T(2) * t41 * b * t58 + c * t57 * t41;
    const T t60 = t45 * t45;
    const T t61 = t42 * t42;
    const T t62 = T(48) * t60 * a_minus_b + T(48) * t61 * b + T(7) * t54 * t43 * a;
    const T t63 = T(48) * t60 - T(48) * t61 - t43 * b * t62;
    const T t64 = c * t43 * t62 + T(2) * t63 * t41 * b - T(8) * t54 * t43;
    const T t65 = c * t63 * t41 + T(8) * t55 * t41 - T(2) * t41 * t64 * b;
    const T t66 = T(2) * t41 * t65 * b + T(8) * t41 * t56 + c * t41 * t64;
    const T t67 = T(2) * t66 * t41 * b - T(8) * t57 * t41 - c * t41 * t65;
    const T t68 = t66 * c * t41 - T(8) * t41 * t58 - T(2) * t67 * t41 * b;
    const T t69 = T(8) * t41 * t59 - T(2) * t68 * t41 * b - c * t67 * t41;
    const T t70 = t1 * delta_tau;
    const T t71 = t70 * t70;
    const T t72 = t71 * delta_tau;
    const T t73 = t1 * t1;
    const T t74 = t73 * t73;
    const T t75 = t74 * delta_tau;
    const T t76 = T(2) * J2 - T(2) * t50 * t41 * b - c * t43 * t46;
    const T t77 = c * t49 * t41 - T(4) * t76 * t41 - T(2) * t41 * t51 * b;
    const T t78 = c * t41 * t58 + T(6) * t77 * t41 - T(2) * t41 * t59 * b;
    const T t79 = T(2) * t69 * t41 * b + c * t68 * t41 - T(8) * t41 * t78;
    const T t80 = t2 * t2;
    const T t81 = t80 * tau_lo;
    const T t82 = t73 * delta_tau;
    const T t83 = t80 * t80;
    const T t84 = t83 * tau_lo;
    const T t85 = t2 * tau_lo;
    const T t86 = t85 * t85;
    const T t87 = t86 * tau_lo;
    F = (T(3) / T(32)) * t69 * t72 * t2 * t41 + (T(1) / T(384)) * t75 * t41 * (T(2) * t79 * t41 * b - T(8) * (c * t41 * t59 + T(6) * (c * t41 * t51 + T(2) * t77 * t41 * b - T(4) * t41 * (T(2) * t76 * t41 * b + t41 * (log_ratio + T(2) * J2 * b) + c * t50 * t41)) * t41 + T(2) * t41 * t78 * b) * t41 - t69 * c * t41) + (T(3) / T(128)) * t79 * t74 * tau_lo * t41 + (T(21) / T(64)) * t66 * t73 * t81 * t41 + (T(21) / T(64)) * t82 * t67 * t80 * t41 + (T(1) / T(384)) * t84 * t43 * t62 + (T(7) / T(32)) * t70 * t86 * t41 * t65 - (T(7) / T(32)) * t71 * t85 * t68 * t41 - (T(3) / T(128)) * delta_tau * t83 * t63 * t41 - (T(3) / T(32)) * t1 * t87 * t41 * t64;
    const T t88 = t60 * t44;
    const T t89 = t61 * t3;
    const T t90 = T(3) * t43 * a * t62 + T(128) * t88 * a_minus_b + T(128) * t89 * b;
    const T t91 = T(128) * t88 - t43 * t90 * b - T(128) * t89;
    const T t92 = T(3) * c * t43 * t90 + T(6) * t91 * t41 * b - T(10) * t43 * t62;
    const T t93 = T(10) * t63 * t41 + T(2) * t92 * t41 * b - T(3) * c * t91 * t41;
    const T t94 = c * t92 * t41 - T(10) * t41 * t64 - T(2) * t41 * t93 * b;
    const T t95 = c * t41 * t93 + T(2) * t41 * t94 * b + T(10) * t41 * t65;
    const T t96 = c * t41 * t94 - T(2) * t41 * t95 * b - T(10) * t66 * t41;
    const T t97 = T(10) * t67 * t41 - T(2) * t41 * t96 * b - c * t41 * t95;
    const T t98 = c * t41 * t96 + T(2) * t41 * b * t97 - T(10) * t68 * t41;
    G_ap = (T(21) / T(640)) * t73 * t81 * t41 * t94 + (T(21) / T(640)) * t82 * t80 * t41 * t95 + (T(1) / T(1280)) * t84 * t43 * t90 + (T(3) / T(320)) * t72 * t2 * t41 * t97 + (T(3) / T(1280)) * t74 * tau_lo * t41 * t98 + (T(1) / T(3840)) * t75 * t41 * (T(2) * t41 * t98 * b + T(10) * t69 * t41 - c * t41 * t97) - (T(7) / T(320)) * t70 * t86 * t41 * t93 - (T(3) / T(320)) * t92 * t1 * t87 * t41 - (T(7) / T(320)) * t71 * t85 * t41 * t96 - (T(9) / T(1280)) * t91 * delta_tau * t83 * t41;
    G_E = -(T(1) / T(1280)) * t41 * (T(24) * t1 * t87 * t63 * t41 + T(84) * t72 * t2 * t68 * t41 + T(128) * t88 * (T(126) * t73 * t81 + T(126) * t82 * t80 + T(9) * t74 * tau_lo + t75 + T(84) * t70 * t86 + t84 + T(9) * delta_tau * t83 + T(36) * t1 * t87 + T(36) * t72 * t2 + T(84) * t71 * t85) + T(84) * t70 * t86 * t41 * t64 - T(3) * t79 * t75 * t41 - T(3) * delta_tau * t83 * t43 * t62 - T(128) * t89 * t84 - T(168) * t73 * t81 * t41 * t65 - T(168) * t71 * t67 * t85 * t41 - T(24) * t69 * t74 * tau_lo * t41 - T(210) * t66 * t82 * t80 * t41);
  }
  const T t99 = T(1) / a;
  const T t_star = t99 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - t_star * ab2;
  const T t100 = sigma2 * sigma2;
  const T t101 = t100 * t100;
  const T t102 = t101 * sigma2;
  const T g_factor = -T(10) * length * t102;
  f = length * t102 * F;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

}  // namespace skelconv::generated
