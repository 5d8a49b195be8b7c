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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T log_ratio = log(q1 / c);
  T F;
  const T t1 = T(4) * D - a * a;
  const T t2 = -b * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * tau_lo + delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + tau_lo * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    F = tau_lo * J2 + (T(1) / T(2)) * delta_tau * (T(2) * J2 * b + log_ratio) / a;
  }
  f = length * sigma2 * F;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
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
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial0 * radial0 + radial1 * radial1 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t4 = delta_tau * M_panels[4] + tau_lo * M_panels[3];
    G_ap = t4;
    const T t5 = T(1) / a;
    G_E = tau_lo * M_panels[4] + delta_tau * M_panels[5] - t4 * t5 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t6 = delta_tau * M_panels[4] + tau_lo * M_panels[3];
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = tau_lo * M_panels[4] + delta_tau * M_panels[5] - t7 * t6 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a_minus_b * t11 + b * t12 + a * J2;
    const T t14 = T(1) / a;
    G_ap = (T(1) / T(2)) * tau_lo * t10 * t13 + (T(1) / T(2)) * delta_tau * t14 * (t12 + t10 * b * t13 - t11);
    G_E = (T(1) / T(2)) * t14 * (tau_lo * t12 + delta_tau * J2 - t11 * (delta_tau + tau_lo));
  }
  const T t15 = T(1) / a;
  const T t_star = t15 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(2) * sigma2 * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
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
    const T t5 = M_panels[4] * delta_tau + tau_lo * M_panels[3];
    G_ap = t5;
    const T t6 = T(1) / a;
    G_E = M_panels[4] * tau_lo + delta_tau * M_panels[5] - t6 * b * t5;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t7 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t7;
    const T t8 = T(1) / a;
    G_E = M_panels[5] * delta_tau + M_panels[4] * tau_lo - t7 * t8 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / a;
    F = (T(1) / T(2)) * (log_ratio + T(2) * J2 * b) * delta_tau * t11 + J2 * tau_lo;
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = J2 * a + t1 * b + t13 * a_minus_b;
    G_ap = (T(1) / T(2)) * tau_lo * t12 * t14 - (T(1) / T(2)) * delta_tau * t11 * (t13 - t1 - t12 * t14 * b);
    G_E = (T(1) / T(2)) * t11 * (t1 * tau_lo + J2 * delta_tau - t13 * (tau_lo + delta_tau));
  }
  const T t15 = T(1) / a;
  const T t_star = t15 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(2) * length * sigma2;
  f = length * sigma2 * F;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
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
    X = -t7 * (b - a_minus_b) / (t8 - b * r1);
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
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t1 * M_panels[2] + t2 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t2 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1] + t1 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 * a_minus_b + t16 * b;
    const T t18 = T(1) / a;
    const T t19 = t14 * t17 * b + t16 - t15;
    F = t14 * t2 * t17 + t1 * t18 * (T(2) * t18 * t19 * b + J1 - t14 * t17 * c) + T(2) * delta_tau * tau_lo * t18 * t19;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * M_panels[6] + T(2) * delta_tau * tau_lo * M_panels[5] + t2 * M_panels[4];
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = t1 * M_panels[7] + t2 * M_panels[5] + T(2) * delta_tau * tau_lo * M_panels[6] - t7 * t6 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t1 * M_panels[6] + t2 * M_panels[4] + T(2) * delta_tau * tau_lo * M_panels[5];
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = T(2) * delta_tau * M_panels[6] * tau_lo + t1 * M_panels[7] + t2 * M_panels[5] - t8 * t9 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / D;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t11 * a_minus_b + b * t13;
    const T t15 = t13 * t13;
    const T t16 = t11 * a_minus_b * t12 + T(2) * t14 * t10 * a + b * t13 * t15;
    const T t17 = t10 * t16 * b + t13 * t15 - t11 * t12;
    const T t18 = T(1) / a;
    G_ap = (T(2) / T(3)) * delta_tau * t17 * tau_lo * t18 + (T(1) / T(3)) * t10 * t2 * t16 - (T(1) / T(3)) * t1 * t18 * (t10 * t16 * c - T(2) * t17 * t18 * b - T(3) * t14 * t10);
    const T t19 = t13 * t13;
    const T t20 = t19 * t13;
    const T t21 = t11 * t11;
    const T t22 = t21 * t11;
    G_E = (T(1) / T(3)) * t18 * (T(2) * t1 * (t13 + t14 * t10 * b - t11) * t18 + T(2) * t14 * delta_tau * t10 * tau_lo + t2 * t20 - t22 * (t1 + t2 + T(2) * delta_tau * tau_lo));
  }
  const T t23 = T(1) / a;
  const T t_star = t23 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(3) * length * sigma2 * in.sigma;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    const T t6 = r1 * b;
    X = t4 * t5 * (t6 + a_minus_b * r0);
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
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = T(2) * tau_lo * delta_tau * M_panels[1] + t1 * M_panels[2] + t2 * M_panels[0];
    const T t14 = T(2) * tau_lo * delta_tau * M_panels[5] + t1 * M_panels[6] + t2 * M_panels[4];
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(2) * tau_lo * delta_tau * M_panels[6] + t2 * M_panels[5] + t1 * M_panels[7] - t15 * t14 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = T(2) * tau_lo * delta_tau * M_panels[1] + t2 * M_panels[0] + t1 * M_panels[2];
    const T t16 = M_panels[4] * t2 + T(2) * tau_lo * delta_tau * M_panels[5] + t1 * M_panels[6];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = T(2) * tau_lo * delta_tau * M_panels[6] + t2 * M_panels[5] + t1 * M_panels[7] - t17 * t16 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = t19 * a_minus_b + b * t20;
    const T t22 = T(1) / a;
    const T t23 = t19 - t20 - t18 * b * t21;
    F = t2 * t18 * t21 - t1 * t22 * (t18 * c * t21 + T(2) * t22 * b * t23 - J1) - T(2) * tau_lo * delta_tau * t22 * t23;
    const T t24 = t19 * t19;
    const T t25 = t20 * t20;
    const T t26 = t19 * a_minus_b * t24 + T(2) * t18 * a * t21 + b * t25 * t20;
    const T t27 = t18 * t26 * b + t25 * t20 - t19 * t24;
    G_ap = (T(1) / T(3)) * t2 * t18 * t26 + (T(2) / T(3)) * tau_lo * delta_tau * t22 * t27 + (T(1) / T(3)) * t1 * t22 * (T(3) * t18 * t21 + T(2) * t22 * b * t27 - t18 * t26 * c);
    const T t28 = t20 * t20;
    const T t29 = t28 * t20;
    const T t30 = t19 * t19;
    const T t31 = t30 * t19;
    G_E = (T(1) / T(3)) * t22 * (t2 * t29 + T(2) * tau_lo * delta_tau * t18 * t21 - T(2) * t1 * t22 * t23 - (T(2) * tau_lo * delta_tau + t2 + t1) * t31);
  }
  const T t32 = T(1) / a;
  const T t_star = t32 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(3) * sigma2 * in.sigma * length;
  f = sigma2 * F * in.sigma * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = delta_tau * ap2 + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    F = T(3) * delta_tau * t2 * M_panels[1] + M_panels[0] * t7 + M_panels[3] * t8 + T(3) * M_panels[2] * t1 * tau_lo;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t9 = t2 * tau_lo;
    const T t10 = t1 * delta_tau;
    F = t9 * M_panels[0] + T(3) * M_panels[1] * delta_tau * t2 + T(3) * M_panels[2] * t1 * tau_lo + t10 * M_panels[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / q1;
    const T t14 = b * t3 + a_minus_b * t13 + a * J2;
    const T t15 = t2 * tau_lo;
    const T t16 = T(1) / D;
    const T t17 = t3 + t14 * b * t16 - t13;
    const T t18 = T(1) / a;
    const T t19 = T(2) * b * t17 * t18 + T(2) * J2 - t14 * c * t16;
    const T t20 = t1 * delta_tau;
    F = (T(1) / T(2)) * t14 * t15 * t16 + (T(3) / T(2)) * t1 * tau_lo * t19 * t18 + (T(1) / T(2)) * ((log_ratio + T(2) * b * J2) * t18 + T(2) * b * t19 * t18 - c * t17 * t18) * t20 * t18 + (T(3) / T(2)) * t17 * delta_tau * t2 * t18;
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
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t1 * delta_tau;
    const T t8 = M_panels[5] * t6 + T(3) * t2 * delta_tau * M_panels[6] + T(3) * M_panels[7] * tau_lo * t1 + M_panels[8] * t7;
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = T(3) * M_panels[7] * t2 * delta_tau + T(3) * M_panels[8] * tau_lo * t1 + t7 * M_panels[9] + t6 * M_panels[6] - b * t8 * t9;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t10 = t2 * tau_lo;
    const T t11 = t1 * delta_tau;
    const T t12 = T(3) * M_panels[7] * tau_lo * t1 + T(3) * t2 * delta_tau * M_panels[6] + M_panels[5] * t10 + t11 * M_panels[8];
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = M_panels[9] * t11 + T(3) * tau_lo * t1 * M_panels[8] + T(3) * M_panels[7] * t2 * delta_tau + t10 * M_panels[6] - t12 * b * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, c_minus_b) * t15;
    const T t16 = T(1) / a;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / c;
    const T t20 = t19 * t19;
    const T t21 = T(1) / D;
    const T t22 = b * t19 + J2 * a + t17 * a_minus_b;
    const T t23 = T(2) * t18 * a_minus_b + T(3) * t21 * a * t22 + T(2) * b * t20;
    const T t24 = T(2) * t18 - T(2) * t20 - b * t23 * t21;
    const T t25 = c * t23 * t21 + T(2) * b * t16 * t24 - T(4) * t21 * t22;
    const T t26 = t17 - t19 - b * t21 * t22;
    const T t27 = t1 * delta_tau;
    const T t28 = t2 * tau_lo;
    G_ap = (T(1) / T(8)) * (c * t16 * t24 - T(2) * b * t25 * t16 - T(4) * t26 * t16) * t27 * t16 + (T(1) / T(8)) * t23 * t28 * t21 - (T(3) / T(8)) * t2 * delta_tau * t16 * t24 - (T(3) / T(8)) * t25 * tau_lo * t1 * t16;
    G_E = -(T(1) / T(8)) * (T(2) * t18 * (t28 + t27 + T(3) * t2 * delta_tau + T(3) * tau_lo * t1) + T(3) * t27 * (c * t21 * t22 + T(2) * t26 * b * t16 - T(2) * J2) * t16 + T(6) * t26 * tau_lo * t1 * t16 - T(2) * t20 * t28 - T(3) * t2 * delta_tau * t21 * t22) * t16;
  }
  const T t29 = T(1) / a;
  const T t_star = b * t29;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(4) * sigma2 * sigma2 * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  T G_ap;
  T G_E;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    F = M_panels[0] * t7 + t8 * M_panels[3] + T(3) * t1 * tau_lo * M_panels[2] + T(3) * M_panels[1] * delta_tau * t2;
    const T t9 = T(3) * M_panels[7] * t1 * tau_lo + T(3) * M_panels[6] * delta_tau * t2 + t7 * M_panels[5] + t8 * M_panels[8];
    G_ap = t9;
    const T t10 = T(1) / a;
    G_E = M_panels[6] * t7 + t8 * M_panels[9] + T(3) * t1 * tau_lo * M_panels[8] + T(3) * M_panels[7] * delta_tau * t2 - b * t9 * t10;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t11 = t2 * tau_lo;
    const T t12 = t1 * delta_tau;
    F = T(3) * t1 * tau_lo * M_panels[2] + M_panels[0] * t11 + T(3) * delta_tau * M_panels[1] * t2 + M_panels[3] * t12;
    const T t13 = t11 * M_panels[5] + t12 * M_panels[8] + T(3) * M_panels[6] * delta_tau * t2 + T(3) * M_panels[7] * t1 * tau_lo;
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = M_panels[6] * t11 + M_panels[9] * t12 + T(3) * M_panels[7] * delta_tau * t2 + T(3) * t1 * tau_lo * M_panels[8] - b * t13 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / a;
    const T t18 = T(1) / q1;
    const T t19 = b * t3 + J2 * a + t18 * a_minus_b;
    const T t20 = T(1) / D;
    const T t21 = t3 + b * t19 * t20 - t18;
    const T t22 = t2 * tau_lo;
    const T t23 = T(2) * J2 + T(2) * b * t17 * t21 - t19 * c * t20;
    const T t24 = t1 * delta_tau;
    F = (T(3) / T(2)) * delta_tau * t2 * t17 * t21 + (T(1) / T(2)) * t19 * t22 * t20 + (T(3) / T(2)) * t23 * t1 * tau_lo * t17 - (T(1) / T(2)) * t24 * (c * t17 * t21 - T(2) * b * t23 * t17 - (log_ratio + T(2) * b * J2) * t17) * t17;
    const T t25 = t18 * t18;
    const T t26 = t3 * t3;
    const T t27 = T(2) * t25 * a_minus_b + T(3) * t19 * t20 * a + T(2) * b * t26;
    const T t28 = b * t27 * t20 + T(2) * t26 - T(2) * t25;
    const T t29 = T(4) * t19 * t20 + T(2) * b * t28 * t17 - c * t27 * t20;
    G_ap = (T(3) / T(8)) * t28 * delta_tau * t2 * t17 + (T(1) / T(8)) * (T(2) * b * t17 * t29 + T(4) * t17 * t21 - t28 * c * t17) * t24 * t17 + (T(3) / T(8)) * t1 * tau_lo * t17 * t29 + (T(1) / T(8)) * t27 * t22 * t20;
    G_E = (T(1) / T(8)) * (T(6) * t1 * tau_lo * t17 * t21 + T(3) * t19 * delta_tau * t2 * t20 + T(3) * t23 * t24 * t17 + T(2) * t26 * t22 - T(2) * t25 * (t22 + t24 + T(3) * delta_tau * t2 + T(3) * t1 * tau_lo)) * t17;
  }
  const T t30 = T(1) / a;
  const T t_star = b * t30;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t31 = sigma2 * sigma2;
  const T g_factor = -T(4) * length * t31;
  f = length * t31 * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + delta_tau * ap2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = b * r1;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r0 * a_minus_b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
    X = (b - a_minus_b) * t7 / (t8 - r0 * a_minus_b);
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
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t2 * t2;
    const T t16 = t1 * delta_tau;
    const T t17 = t1 * t1;
    F = T(4) * delta_tau * M_panels[1] * t14 + M_panels[0] * t15 + T(6) * t1 * t2 * M_panels[2] + T(4) * M_panels[3] * t16 * tau_lo + M_panels[4] * t17;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * t2;
    const T t19 = t2 * tau_lo;
    const T t20 = t1 * delta_tau;
    const T t21 = t1 * t1;
    F = t18 * M_panels[0] + T(4) * M_panels[1] * delta_tau * t19 + T(4) * t20 * tau_lo * M_panels[3] + M_panels[4] * t21 + T(6) * M_panels[2] * t1 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = t2 * t2;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r1;
    const T t26 = a_minus_b * t25 + t23 * b;
    const T t27 = T(1) / D;
    const T t28 = t25 * t25;
    const T t29 = t23 * b * t24 + T(2) * t26 * t27 * a + a_minus_b * t25 * t28;
    const T t30 = t23 * t24 + b * t29 * t27 - t25 * t28;
    const T t31 = t2 * tau_lo;
    const T t32 = T(1) / a;
    const T t33 = T(3) * t26 * t27 + T(2) * b * t30 * t32 - c * t29 * t27;
    const T t34 = t26 * b * t27 + t23 - t25;
    const T t35 = T(2) * b * t33 * t32 + T(3) * t34 * t32 - c * t30 * t32;
    const T t36 = t1 * delta_tau;
    const T t37 = t1 * t1;
    F = (T(1) / T(3)) * t22 * t29 * t27 + (T(4) / T(3)) * delta_tau * t30 * t31 * t32 + (T(4) / T(3)) * t35 * t36 * tau_lo * t32 + T(2) * t1 * t33 * t2 * t32 + (T(1) / T(3)) * (T(3) * (J1 + T(2) * b * t34 * t32 - t26 * c * t27) * t32 + T(2) * b * t35 * t32 - c * t33 * t32) * t37 * t32;
  }
  f = F * in.sigma * length * sigma2 * sigma2;
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * t2;
    const T t9 = t1 * t1;
    const T t10 = T(4) * delta_tau * t6 * M_panels[7] + T(4) * t7 * tau_lo * M_panels[9] + t8 * M_panels[6] + T(6) * t1 * t2 * M_panels[8] + t9 * M_panels[10];
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = T(4) * delta_tau * t6 * M_panels[8] + t9 * M_panels[11] + T(6) * t1 * t2 * M_panels[9] + T(4) * t7 * M_panels[10] * tau_lo + t8 * M_panels[7] - t10 * t11 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t2 * tau_lo;
    const T t13 = t2 * t2;
    const T t14 = t1 * delta_tau;
    const T t15 = t1 * t1;
    const T t16 = T(4) * delta_tau * t12 * M_panels[7] + t13 * M_panels[6] + T(6) * t1 * t2 * M_panels[8] + T(4) * t14 * tau_lo * M_panels[9] + t15 * M_panels[10];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = t15 * M_panels[11] + t13 * M_panels[7] + T(4) * delta_tau * t12 * M_panels[8] + T(4) * t14 * tau_lo * M_panels[10] + T(6) * t1 * t2 * M_panels[9] - t17 * b * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = t2 * t2;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = T(1) / r1;
    const T t23 = b * t20 + t22 * a_minus_b;
    const T t24 = t22 * t22;
    const T t25 = b * t20 * t21 + T(2) * t18 * a * t23 + t22 * a_minus_b * t24;
    const T t26 = t24 * t24;
    const T t27 = t21 * t21;
    const T t28 = T(4) * t18 * a * t25 + T(3) * t22 * a_minus_b * t26 + T(3) * b * t20 * t27;
    const T t29 = T(1) / a;
    const T t30 = t18 * t28 * b + T(3) * t20 * t27 - T(3) * t22 * t26;
    const T t31 = T(2) * t29 * b * t30 + T(5) * t18 * t25 - t18 * t28 * c;
    const T t32 = t2 * tau_lo;
    const T t33 = t1 * delta_tau;
    const T t34 = t20 * t21 + t18 * b * t25 - t22 * t24;
    const T t35 = T(5) * t29 * t34 + T(2) * t29 * t31 * b - t29 * t30 * c;
    const T t36 = t1 * t1;
    const T t37 = T(3) * t18 * t23 + T(2) * t29 * t34 * b - t18 * t25 * c;
    G_ap = (T(1) / T(15)) * t18 * t19 * t28 + (T(2) / T(5)) * t1 * t2 * t29 * t31 + (T(4) / T(15)) * delta_tau * t32 * t29 * t30 + (T(4) / T(15)) * t33 * tau_lo * t35 * t29 - (T(1) / T(15)) * t36 * t29 * (t29 * t31 * c - T(2) * t35 * t29 * b - T(5) * t29 * t37);
    const T t38 = t20 * t20;
    const T t39 = t38 * t38;
    const T t40 = t39 * t20;
    const T t41 = t22 * t22;
    const T t42 = t41 * t41;
    const T t43 = t42 * t22;
    G_E = (T(1) / T(15)) * t29 * (T(12) * t33 * tau_lo * t29 * t37 + T(4) * t36 * (T(2) * t29 * b * t37 + T(3) * t29 * (t18 * t23 * b + t20 - t22) - t29 * t34 * c) * t29 + T(12) * t1 * t2 * t29 * t34 + T(4) * delta_tau * t18 * t32 * t25 + T(3) * t19 * t40 - T(3) * t43 * (T(6) * t1 * t2 + T(4) * t33 * tau_lo + t36 + T(4) * delta_tau * t32 + t19));
  }
  const T t44 = T(1) / a;
  const T t_star = t44 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(5) * sigma2 * sigma2 * in.sigma * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r0 * a_minus_b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r1 * b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = (a_minus_b - b) * t7 / (t8 - r1 * b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = asinh(X) * t10;
  T F;
  T G_ap;
  T G_E;
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t1 * t1;
    const T t16 = t1 * delta_tau;
    const T t17 = t2 * tau_lo;
    F = t14 * M_panels[0] + t15 * M_panels[4] + T(6) * M_panels[2] * t2 * t1 + T(4) * tau_lo * t16 * M_panels[3] + T(4) * t17 * delta_tau * M_panels[1];
    const T t18 = T(4) * tau_lo * t16 * M_panels[9] + t15 * M_panels[10] + T(6) * M_panels[8] * t2 * t1 + T(4) * t17 * delta_tau * M_panels[7] + t14 * M_panels[6];
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = M_panels[11] * t15 + t14 * M_panels[7] + T(4) * M_panels[8] * t17 * delta_tau + T(6) * t2 * t1 * M_panels[9] + T(4) * tau_lo * t16 * M_panels[10] - t18 * t19 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t2 * tau_lo;
    const T t21 = t2 * t2;
    const T t22 = t1 * delta_tau;
    const T t23 = t1 * t1;
    F = T(4) * t20 * delta_tau * M_panels[1] + M_panels[0] * t21 + T(4) * M_panels[3] * tau_lo * t22 + t23 * M_panels[4] + T(6) * t2 * t1 * M_panels[2];
    const T t24 = T(4) * t20 * delta_tau * M_panels[7] + T(4) * M_panels[9] * tau_lo * t22 + M_panels[6] * t21 + T(6) * t2 * t1 * M_panels[8] + t23 * M_panels[10];
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = t21 * M_panels[7] + t23 * M_panels[11] + T(4) * tau_lo * t22 * M_panels[10] + T(4) * t20 * delta_tau * M_panels[8] + T(6) * M_panels[9] * t2 * t1 - t24 * t25 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = t2 * tau_lo;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = T(1) / D;
    const T t30 = T(1) / r1;
    const T t31 = t30 * t30;
    const T t32 = t27 * b + t30 * a_minus_b;
    const T t33 = t30 * a_minus_b * t31 + T(2) * t29 * a * t32 + t28 * t27 * b;
    const T t34 = t28 * t27 + t29 * t33 * b - t30 * t31;
    const T t35 = T(1) / a;
    const T t36 = t2 * t2;
    const T t37 = T(2) * t34 * t35 * b + T(3) * t29 * t32 - c * t29 * t33;
    const T t38 = t27 + t29 * b * t32 - t30;
    const T t39 = c * t34 * t35 - T(2) * t35 * b * t37 - T(3) * t38 * t35;
    const T t40 = t1 * delta_tau;
    const T t41 = t1 * t1;
    F = (T(4) / T(3)) * t26 * delta_tau * t34 * t35 + (T(1) / T(3)) * t36 * t29 * t33 + T(2) * t2 * t1 * t35 * t37 - (T(4) / T(3)) * t39 * tau_lo * t40 * t35 - (T(1) / T(3)) * t41 * t35 * (T(3) * (c * t29 * t32 - J1 - T(2) * t38 * t35 * b) * t35 + T(2) * t39 * t35 * b + c * t35 * t37);
    const T t42 = t31 * t31;
    const T t43 = t28 * t28;
    const T t44 = T(3) * t43 * t27 * b + T(4) * t29 * a * t33 + T(3) * t30 * a_minus_b * t42;
    const T t45 = T(3) * t30 * t42 - t29 * b * t44 - T(3) * t43 * t27;
    const T t46 = T(2) * t35 * b * t45 + c * t29 * t44 - T(5) * t29 * t33;
    const T t47 = c * t35 * t45 + T(5) * t34 * t35 - T(2) * t46 * t35 * b;
    G_ap = (T(4) / T(15)) * tau_lo * t40 * t35 * t47 + (T(1) / T(15)) * (T(2) * t35 * b * t47 + c * t46 * t35 + T(5) * t35 * t37) * t41 * t35 + (T(1) / T(15)) * t36 * t29 * t44 - (T(4) / T(15)) * t26 * delta_tau * t35 * t45 - (T(2) / T(5)) * t46 * t2 * t1 * t35;
    const T t48 = t30 * t30;
    const T t49 = t48 * t48;
    const T t50 = t49 * t30;
    const T t51 = t27 * t27;
    const T t52 = t51 * t51;
    const T t53 = t52 * t27;
    G_E = -(T(1) / T(15)) * t35 * (T(3) * (T(6) * t2 * t1 + t41 + T(4) * t26 * delta_tau + t36 + T(4) * tau_lo * t40) * t50 + T(4) * t39 * t41 * t35 - T(12) * tau_lo * t40 * t35 * t37 - T(4) * t26 * delta_tau * t29 * t33 - T(12) * t2 * t1 * t34 * t35 - T(3) * t53 * t36);
  }
  const T t54 = T(1) / a;
  const T t_star = t54 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t55 = sigma2 * sigma2;
  const T g_factor = -T(5) * in.sigma * length * t55;
  f = in.sigma * length * t55 * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t2 * t2;
    const T t9 = t8 * tau_lo;
    const T t10 = t1 * delta_tau;
    const T t11 = t1 * t1;
    const T t12 = t11 * delta_tau;
    F = T(10) * t7 * t1 * M_panels[2] + M_panels[0] * t9 + T(10) * M_panels[3] * t2 * t10 + T(5) * tau_lo * t11 * M_panels[4] + M_panels[5] * t12 + T(5) * t8 * delta_tau * M_panels[1];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t2 * t2;
    const T t14 = t13 * tau_lo;
    const T t15 = t2 * tau_lo;
    const T t16 = t1 * t1;
    const T t17 = t1 * delta_tau;
    const T t18 = t16 * delta_tau;
    F = M_panels[0] * t14 + T(10) * t15 * t1 * M_panels[2] + T(5) * tau_lo * t16 * M_panels[4] + T(10) * M_panels[3] * t2 * t17 + T(5) * t13 * delta_tau * M_panels[1] + t18 * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, c_minus_b) * t20;
    const T t21 = t2 * t2;
    const T t22 = t3 * t3;
    const T t23 = T(1) / D;
    const T t24 = T(1) / q1;
    const T t25 = a * J2 + a_minus_b * t24 + t3 * b;
    const T t26 = t24 * t24;
    const T t27 = T(3) * t23 * a * t25 + T(2) * t22 * b + T(2) * a_minus_b * t26;
    const T t28 = T(2) * t22 + t23 * b * t27 - T(2) * t26;
    const T t29 = T(1) / a;
    const T t30 = T(4) * t23 * t25 + T(2) * t28 * t29 * b - c * t23 * t27;
    const T t31 = t2 * tau_lo;
    const T t32 = t21 * tau_lo;
    const T t33 = t23 * t25 * b + t3 - t24;
    const T t34 = T(2) * t30 * t29 * b + T(4) * t33 * t29 - c * t28 * t29;
    const T t35 = t1 * delta_tau;
    const T t36 = t1 * t1;
    const T t37 = t36 * delta_tau;
    const T t38 = T(2) * t33 * t29 * b + T(2) * J2 - c * t23 * t25;
    const T t39 = t30 * c * t29 - T(4) * t38 * t29 - T(2) * t34 * t29 * b;
    F = (T(5) / T(8)) * t21 * delta_tau * t28 * t29 + (T(5) / T(4)) * t30 * t31 * t1 * t29 + (T(1) / T(8)) * t32 * t23 * t27 + (T(5) / T(4)) * t34 * t2 * t35 * t29 - (T(1) / T(8)) * t37 * t29 * (c * t34 * t29 + T(4) * (t33 * c * t29 - T(2) * t38 * t29 * b - t29 * (log_ratio + T(2) * J2 * b)) * t29 + T(2) * t29 * b * t39) - (T(5) / T(8)) * tau_lo * t36 * t29 * t39;
  }
  const T t40 = sigma2 * sigma2;
  const T t41 = t40 * sigma2;
  f = length * t41 * F;
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t1 * t1;
    const T t8 = t7 * delta_tau;
    const T t9 = t2 * t2;
    const T t10 = t9 * tau_lo;
    const T t11 = t1 * delta_tau;
    const T t12 = T(10) * M_panels[9] * t1 * t6 + t8 * M_panels[12] + M_panels[7] * t10 + T(5) * M_panels[11] * t7 * tau_lo + T(10) * M_panels[10] * t11 * t2 + T(5) * M_panels[8] * delta_tau * t9;
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = M_panels[13] * t8 + T(10) * M_panels[11] * t11 * t2 + T(5) * t7 * tau_lo * M_panels[12] + T(5) * M_panels[9] * delta_tau * t9 + T(10) * M_panels[10] * t1 * t6 + M_panels[8] * t10 - b * t12 * t13;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t1 * delta_tau;
    const T t16 = t2 * t2;
    const T t17 = t14 * delta_tau;
    const T t18 = t16 * tau_lo;
    const T t19 = t2 * tau_lo;
    const T t20 = T(5) * M_panels[11] * t14 * tau_lo + T(10) * M_panels[10] * t15 * t2 + T(5) * M_panels[8] * delta_tau * t16 + M_panels[12] * t17 + M_panels[7] * t18 + T(10) * M_panels[9] * t1 * t19;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = T(10) * M_panels[10] * t1 * t19 + M_panels[8] * t18 + T(10) * M_panels[11] * t15 * t2 + T(5) * M_panels[12] * t14 * tau_lo + M_panels[13] * t17 + T(5) * M_panels[9] * delta_tau * t16 - b * t20 * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, c_minus_b) * t23;
    const T t24 = t1 * t1;
    const T t25 = t24 * delta_tau;
    const T t26 = T(1) / a;
    const T t27 = T(1) / q1;
    const T t28 = t27 * t27;
    const T t29 = T(1) / c;
    const T t30 = t29 * t29;
    const T t31 = J2 * a + t27 * a_minus_b + b * t29;
    const T t32 = T(1) / D;
    const T t33 = T(2) * b * t30 + T(2) * t28 * a_minus_b + T(3) * t31 * t32 * a;
    const T t34 = T(2) * t28 - T(2) * t30 - b * t33 * t32;
    const T t35 = t29 + b * t31 * t32 - t27;
    const T t36 = T(2) * t34 * b * t26 + t33 * c * t32 - T(4) * t31 * t32;
    const T t37 = t34 * c * t26 + T(4) * t35 * t26 - T(2) * b * t36 * t26;
    const T t38 = t28 * t27;
    const T t39 = t30 * t29;
    const T t40 = T(8) * t38 * a_minus_b + T(8) * b * t39 + T(5) * t33 * t32 * a;
    const T t41 = b * t40 * t32 + T(8) * t39 - T(8) * t38;
    const T t42 = T(6) * t33 * t32 + T(2) * b * t41 * t26 - c * t40 * t32;
    const T t43 = T(2) * b * t42 * t26 - c * t41 * t26 - T(6) * t34 * t26;
    const T t44 = T(2) * b * t43 * t26 - c * t42 * t26 - T(6) * t36 * t26;
    const T t45 = t2 * t2;
    const T t46 = t2 * tau_lo;
    const T t47 = t1 * delta_tau;
    const T t48 = t45 * tau_lo;
    G_ap = (T(1) / T(48)) * t25 * t26 * (T(6) * t37 * t26 + T(2) * b * t44 * t26 - t43 * c * t26) + (T(5) / T(48)) * delta_tau * t45 * t41 * t26 + (T(5) / T(24)) * t1 * t42 * t46 * t26 + (T(5) / T(48)) * t44 * t24 * tau_lo * t26 + (T(5) / T(24)) * t43 * t47 * t2 * t26 + (T(1) / T(48)) * t40 * t48 * t32;
    G_E = (T(1) / T(48)) * (T(8) * t39 * t48 + T(5) * (T(4) * (T(2) * b * t35 * t26 + T(2) * J2 - c * t31 * t32) * t26 + c * t36 * t26 + T(2) * b * t37 * t26) * t25 * t26 + T(5) * t33 * delta_tau * t45 * t32 + T(20) * t37 * t24 * tau_lo * t26 - T(20) * t34 * t1 * t46 * t26 - T(30) * t47 * t2 * t36 * t26 - T(8) * t38 * (T(10) * t1 * t46 + T(5) * delta_tau * t45 + t25 + T(10) * t47 * t2 + t48 + T(5) * t24 * tau_lo)) * t26;
  }
  const T t49 = T(1) / a;
  const T t_star = b * t49;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t50 = sigma2 * sigma2;
  const T t51 = t50 * sigma2;
  const T g_factor = -T(6) * t51 * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
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
    const T t7 = t2 * t2;
    const T t8 = t1 * delta_tau;
    const T t9 = t1 * t1;
    const T t10 = t7 * tau_lo;
    const T t11 = t2 * tau_lo;
    const T t12 = t9 * delta_tau;
    F = T(5) * M_panels[1] * t7 * delta_tau + T(10) * t2 * t8 * M_panels[3] + T(5) * M_panels[4] * tau_lo * t9 + t10 * M_panels[0] + T(10) * t11 * t1 * M_panels[2] + t12 * M_panels[5];
    const T t13 = T(10) * t2 * t8 * M_panels[10] + T(10) * t11 * t1 * M_panels[9] + T(5) * M_panels[11] * tau_lo * t9 + t10 * M_panels[7] + t12 * M_panels[12] + T(5) * t7 * delta_tau * M_panels[8];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = T(10) * M_panels[11] * t2 * t8 + t10 * M_panels[8] + T(5) * t7 * delta_tau * M_panels[9] + T(10) * t11 * t1 * M_panels[10] + T(5) * tau_lo * t9 * M_panels[12] + t12 * M_panels[13] - t14 * t13 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t15 = t1 * t1;
    const T t16 = t2 * t2;
    const T t17 = t16 * tau_lo;
    const T t18 = t2 * tau_lo;
    const T t19 = t15 * delta_tau;
    const T t20 = t1 * delta_tau;
    F = T(5) * tau_lo * t15 * M_panels[4] + M_panels[0] * t17 + T(10) * t18 * t1 * M_panels[2] + t19 * M_panels[5] + T(5) * t16 * delta_tau * M_panels[1] + T(10) * M_panels[3] * t2 * t20;
    const T t21 = T(10) * t2 * t20 * M_panels[10] + t17 * M_panels[7] + T(5) * t16 * delta_tau * M_panels[8] + T(5) * tau_lo * t15 * M_panels[11] + t19 * M_panels[12] + T(10) * M_panels[9] * t18 * t1;
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(5) * tau_lo * t15 * M_panels[12] + T(5) * M_panels[9] * t16 * delta_tau + T(10) * t2 * t20 * M_panels[11] + T(10) * t18 * t1 * M_panels[10] + t19 * M_panels[13] + t17 * M_panels[8] - t22 * t21 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = t24 * atan2(t23, c_minus_b);
    const T t25 = t2 * t2;
    const T t26 = t25 * tau_lo;
    const T t27 = T(1) / D;
    const T t28 = T(1) / q1;
    const T t29 = a_minus_b * t28 + b * t3 + J2 * a;
    const T t30 = t3 * t3;
    const T t31 = t28 * t28;
    const T t32 = T(3) * t27 * a * t29 + T(2) * b * t30 + T(2) * a_minus_b * t31;
    const T t33 = t1 * t1;
    const T t34 = t33 * delta_tau;
    const T t35 = T(1) / a;
    const T t36 = t28 - t3 - t27 * b * t29;
    const T t37 = T(2) * J2 - t27 * t29 * c - T(2) * t35 * b * t36;
    const T t38 = t27 * t32 * b + T(2) * t30 - T(2) * t31;
    const T t39 = T(2) * t35 * t38 * b + T(4) * t27 * t29 - t27 * t32 * c;
    const T t40 = t35 * t38 * c + T(4) * t35 * t36 - T(2) * t35 * t39 * b;
    const T t41 = t35 * t39 * c + T(2) * t40 * t35 * b - T(4) * t37 * t35;
    const T t42 = t2 * tau_lo;
    const T t43 = t1 * delta_tau;
    F = (T(1) / T(8)) * t26 * t27 * t32 + (T(1) / T(8)) * t34 * t35 * (T(4) * t35 * (t35 * (T(2) * J2 * b + log_ratio) + t35 * t36 * c + T(2) * t37 * t35 * b) + t40 * t35 * c - T(2) * t35 * t41 * b) + (T(5) / T(8)) * t25 * delta_tau * t35 * t38 + (T(5) / T(4)) * t42 * t1 * t35 * t39 - (T(5) / T(4)) * t2 * t43 * t40 * t35 - (T(5) / T(8)) * tau_lo * t33 * t35 * t41;
    const T t44 = t30 * t3;
    const T t45 = t31 * t28;
    const T t46 = T(8) * b * t44 + T(8) * a_minus_b * t45 + T(5) * t27 * t32 * a;
    const T t47 = t27 * b * t46 + T(8) * t44 - T(8) * t45;
    const T t48 = T(6) * t27 * t32 + T(2) * t35 * b * t47 - t27 * t46 * c;
    const T t49 = T(2) * t35 * t48 * b + T(6) * t35 * t38 - t35 * c * t47;
    const T t50 = T(2) * t35 * t49 * b + T(6) * t35 * t39 - t35 * t48 * c;
    G_ap = (T(5) / T(24)) * t42 * t1 * t35 * t48 + (T(5) / T(48)) * t25 * delta_tau * t35 * t47 + (T(1) / T(48)) * t26 * t27 * t46 + (T(5) / T(48)) * t50 * tau_lo * t33 * t35 + (T(1) / T(48)) * t34 * t35 * (T(2) * t50 * t35 * b - T(6) * t40 * t35 - t35 * t49 * c) + (T(5) / T(24)) * t2 * t43 * t35 * t49;
    G_E = (T(1) / T(48)) * t35 * (T(5) * t25 * delta_tau * t27 * t32 + T(30) * t2 * t43 * t35 * t39 + T(8) * t26 * t44 + T(20) * t42 * t1 * t35 * t38 - T(5) * t34 * t35 * t41 - T(8) * t45 * (T(5) * t25 * delta_tau + t34 + T(10) * t42 * t1 + t26 + T(10) * t2 * t43 + T(5) * tau_lo * t33) - T(20) * tau_lo * t33 * t40 * t35);
  }
  const T t51 = T(1) / a;
  const T t_star = t51 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t52 = sigma2 * sigma2;
  const T t53 = t52 * sigma2;
  const T g_factor = -T(6) * length * t53;
  f = length * t53 * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = sqrt(a);
    const T t5 = b * r1;
    const T t6 = T(1) / D;
    X = t4 * (t5 + r0 * a_minus_b) * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
    X = t7 * (b - a_minus_b) / (t8 - r0 * a_minus_b);
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
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t2 * tau_lo;
    const T t17 = t1 * delta_tau;
    const T t18 = t1 * t1;
    const T t19 = t18 * delta_tau;
    const T t20 = t16 * t16;
    const T t21 = t17 * t17;
    F = T(6) * t15 * M_panels[1] * delta_tau + T(20) * t16 * M_panels[3] * t17 + T(6) * tau_lo * M_panels[5] * t19 + t20 * M_panels[0] + T(15) * t2 * M_panels[4] * t18 + T(15) * t14 * M_panels[2] * t1 + M_panels[6] * t21;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t2 * t2;
    const T t23 = t1 * t1;
    const T t24 = t23 * delta_tau;
    const T t25 = t1 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t2 * tau_lo;
    const T t28 = t27 * t27;
    const T t29 = t22 * tau_lo;
    F = T(15) * t22 * M_panels[2] * t1 + T(6) * tau_lo * M_panels[5] * t24 + M_panels[6] * t26 + T(20) * t27 * M_panels[3] * t25 + t28 * M_panels[0] + T(6) * t29 * M_panels[1] * delta_tau + T(15) * t2 * t23 * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = t2 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = T(1) / r0;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = T(1) / r1;
    const T t36 = t35 * t35;
    const T t37 = t35 * a_minus_b + t32 * b;
    const T t38 = T(1) / D;
    const T t39 = t35 * a_minus_b * t36 + T(2) * a * t37 * t38 + t32 * b * t33;
    const T t40 = t36 * t36;
    const T t41 = T(3) * t32 * b * t34 + T(4) * t39 * a * t38 + T(3) * t35 * a_minus_b * t40;
    const T t42 = T(1) / a;
    const T t43 = T(3) * t32 * t34 + t41 * b * t38 - T(3) * t35 * t40;
    const T t44 = t41 * c * t38 - T(5) * t39 * t38 - T(2) * t42 * t43 * b;
    const T t45 = t35 * t36 - t39 * b * t38 - t32 * t33;
    const T t46 = T(3) * t37 * t38 - T(2) * t42 * b * t45 - t39 * c * t38;
    const T t47 = t42 * t43 * c + T(2) * t42 * t44 * b + T(5) * t42 * t45;
    const T t48 = t42 * t44 * c + T(5) * t42 * t46 - T(2) * t42 * t47 * b;
    const T t49 = b * t37 * t38 + t32 - t35;
    const T t50 = T(2) * t42 * t46 * b + t42 * t45 * c + T(3) * t49 * t42;
    const T t51 = T(2) * t42 * b * t48 + T(5) * t42 * t50 + t42 * t47 * c;
    const T t52 = t1 * t1;
    const T t53 = t52 * delta_tau;
    const T t54 = t1 * delta_tau;
    const T t55 = t54 * t54;
    const T t56 = t2 * t2;
    const T t57 = t56 * tau_lo;
    F = (T(1) / T(15)) * t31 * t41 * t38 + (T(2) / T(5)) * tau_lo * t42 * t51 * t53 + (T(1) / T(15)) * (T(2) * t42 * t51 * b + T(5) * t42 * (T(2) * t42 * t50 * b + T(3) * (T(2) * t49 * t42 * b + J1 - c * t37 * t38) * t42 - t42 * t46 * c) - t42 * t48 * c) * t42 * t55 + (T(2) / T(5)) * t57 * t42 * t43 * delta_tau + t2 * t42 * t48 * t52 - t56 * t42 * t44 * t1 - (T(4) / T(3)) * t30 * t42 * t47 * t54;
  }
  const T t58 = sigma2 * sigma2;
  const T t59 = t58 * sigma2;
  f = t59 * F * in.sigma * length;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
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
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * delta_tau;
    const T t8 = t2 * t2;
    const T t9 = t2 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t8 * tau_lo;
    const T t12 = t1 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = T(15) * t2 * t6 * M_panels[12] + T(6) * M_panels[13] * tau_lo * t7 + T(15) * M_panels[10] * t8 * t1 + t10 * M_panels[8] + T(6) * t11 * delta_tau * M_panels[9] + M_panels[14] * t13 + T(20) * t9 * t12 * M_panels[11];
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(15) * t8 * t1 * M_panels[11] + T(20) * t9 * t12 * M_panels[12] + T(6) * M_panels[10] * t11 * delta_tau + T(6) * M_panels[14] * tau_lo * t7 + T(15) * M_panels[13] * t2 * t6 + t13 * M_panels[15] + t10 * M_panels[9] - t15 * b * t14;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t1 * t1;
    const T t17 = t2 * t2;
    const T t18 = t17 * tau_lo;
    const T t19 = t2 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t1 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t16 * delta_tau;
    const T t24 = T(15) * t2 * t16 * M_panels[12] + T(6) * M_panels[9] * t18 * delta_tau + t20 * M_panels[8] + T(15) * M_panels[10] * t17 * t1 + M_panels[14] * t22 + T(20) * t19 * t21 * M_panels[11] + T(6) * M_panels[13] * tau_lo * t23;
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(15) * M_panels[13] * t2 * t16 + T(20) * t19 * t21 * M_panels[12] + T(15) * t17 * t1 * M_panels[11] + M_panels[9] * t20 + t22 * M_panels[15] + T(6) * tau_lo * M_panels[14] * t23 + T(6) * M_panels[10] * t18 * delta_tau - t24 * t25 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / D;
    const T t27 = t2 * tau_lo;
    const T t28 = t27 * t27;
    const T t29 = T(1) / r0;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = T(1) / r1;
    const T t33 = t32 * t32;
    const T t34 = b * t29 + t32 * a_minus_b;
    const T t35 = t32 * a_minus_b * t33 + T(2) * t26 * t34 * a + t30 * b * t29;
    const T t36 = t33 * t33;
    const T t37 = T(3) * t31 * b * t29 + T(4) * t26 * a * t35 + T(3) * t32 * a_minus_b * t36;
    const T t38 = t31 * t30;
    const T t39 = t36 * t33;
    const T t40 = T(2) * t26 * a * t37 + T(5) * t38 * b * t29 + T(5) * t32 * a_minus_b * t39;
    const T t41 = T(1) / a;
    const T t42 = T(5) * t32 * t39 - T(5) * t38 * t29 - t26 * t40 * b;
    const T t43 = T(3) * t32 * t36 - T(3) * t31 * t29 - t26 * b * t37;
    const T t44 = T(3) * c * t26 * t40 + T(6) * t41 * b * t42 - T(7) * t26 * t37;
    const T t45 = T(3) * c * t41 * t42 - T(7) * t41 * t43 - T(2) * t44 * t41 * b;
    const T t46 = t1 * delta_tau;
    const T t47 = t1 * t1;
    const T t48 = T(5) * t26 * t35 - T(2) * t41 * t43 * b - c * t26 * t37;
    const T t49 = T(7) * t48 * t41 + c * t44 * t41 + T(2) * t45 * t41 * b;
    const T t50 = t2 * t2;
    const T t51 = t47 * delta_tau;
    const T t52 = t30 * t29 + t26 * b * t35 - t32 * t33;
    const T t53 = T(2) * t48 * t41 * b + T(5) * t41 * t52 + c * t41 * t43;
    const T t54 = c * t45 * t41 - T(2) * t41 * t49 * b - T(7) * t53 * t41;
    const T t55 = t50 * tau_lo;
    const T t56 = T(3) * t26 * t34 + T(2) * t41 * t52 * b - c * t26 * t35;
    const T t57 = T(5) * t56 * t41 + T(2) * t53 * t41 * b - c * t48 * t41;
    const T t58 = t46 * t46;
    G_ap = (T(1) / T(35)) * t26 * t28 * t40 + (T(4) / T(21)) * t45 * t27 * t46 * t41 + (T(1) / T(7)) * t2 * t47 * t41 * t49 - (T(1) / T(7)) * t50 * t1 * t44 * t41 - (T(2) / T(35)) * tau_lo * t51 * t41 * t54 - (T(6) / T(35)) * t55 * delta_tau * t41 * t42 - (T(1) / T(105)) * (T(2) * t41 * b * t54 + c * t41 * t49 - T(7) * t57 * t41) * t58 * t41;
    const T t59 = t29 * t29;
    const T t60 = t59 * t29;
    const T t61 = t60 * t60;
    const T t62 = t61 * t29;
    const T t63 = t32 * t32;
    const T t64 = t63 * t32;
    const T t65 = t64 * t64;
    const T t66 = t65 * t32;
    G_E = (T(1) / T(35)) * t41 * (T(20) * t48 * t27 * t46 * t41 + T(20) * t53 * t2 * t47 * t41 + T(10) * t57 * tau_lo * t51 * t41 + T(2) * t26 * t55 * delta_tau * t37 + T(5) * t28 * t62 - T(10) * t50 * t1 * t41 * t43 - T(5) * t66 * (T(15) * t50 * t1 + T(6) * t55 * delta_tau + T(15) * t2 * t47 + T(6) * tau_lo * t51 + t58 + T(20) * t27 * t46 + t28) - T(2) * t58 * t41 * (c * t53 * t41 - T(5) * t41 * (T(3) * (t29 + t26 * t34 * b - t32) * t41 + T(2) * t56 * t41 * b - c * t41 * t52) - T(2) * t57 * t41 * b));
  }
  const T t67 = T(1) / a;
  const T t_star = t67 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(7) * in.sigma * length * t69;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r0 * a_minus_b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r1 * b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = (a_minus_b - b) * t7 / (t8 - r1 * b);
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
    const T t14 = t1 * t1;
    const T t15 = t14 * delta_tau;
    const T t16 = t2 * t2;
    const T t17 = t16 * tau_lo;
    const T t18 = t1 * delta_tau;
    const T t19 = t2 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t18 * t18;
    F = T(6) * M_panels[5] * t15 * tau_lo + T(6) * M_panels[1] * delta_tau * t17 + T(20) * t18 * t19 * M_panels[3] + T(15) * t14 * t2 * M_panels[4] + T(15) * M_panels[2] * t1 * t16 + t20 * M_panels[0] + t21 * M_panels[6];
    const T t22 = M_panels[8] * t20 + T(6) * delta_tau * M_panels[9] * t17 + M_panels[14] * t21 + T(15) * t1 * t16 * M_panels[10] + T(20) * M_panels[11] * t18 * t19 + T(6) * t15 * tau_lo * M_panels[13] + T(15) * t14 * t2 * M_panels[12];
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = T(6) * M_panels[14] * t15 * tau_lo + T(6) * delta_tau * t17 * M_panels[10] + M_panels[9] * t20 + T(20) * t18 * t19 * M_panels[12] + T(15) * t14 * t2 * M_panels[13] + T(15) * M_panels[11] * t1 * t16 + t21 * M_panels[15] - t22 * t23 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t2 * t2;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t1 * delta_tau;
    const T t28 = t2 * tau_lo;
    const T t29 = t27 * t27;
    const T t30 = t28 * t28;
    const T t31 = t26 * delta_tau;
    F = T(6) * M_panels[1] * delta_tau * t25 + T(15) * t1 * M_panels[2] * t24 + T(15) * M_panels[4] * t26 * t2 + T(20) * t27 * t28 * M_panels[3] + t29 * M_panels[6] + t30 * M_panels[0] + T(6) * M_panels[5] * t31 * tau_lo;
    const T t32 = M_panels[14] * t29 + T(20) * M_panels[11] * t27 * t28 + T(15) * t1 * t24 * M_panels[10] + T(6) * delta_tau * t25 * M_panels[9] + T(6) * t31 * tau_lo * M_panels[13] + T(15) * t26 * t2 * M_panels[12] + M_panels[8] * t30;
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(6) * delta_tau * t25 * M_panels[10] + T(15) * t26 * t2 * M_panels[13] + t30 * M_panels[9] + T(20) * t27 * t28 * M_panels[12] + T(6) * M_panels[14] * t31 * tau_lo + t29 * M_panels[15] + T(15) * M_panels[11] * t1 * t24 - t32 * t33 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = T(1) / D;
    const T t37 = T(1) / r0;
    const T t38 = a_minus_b * t34 + t37 * b;
    const T t39 = t37 * t37;
    const T t40 = T(2) * t36 * a * t38 + t35 * a_minus_b * t34 + t39 * t37 * b;
    const T t41 = t35 * t34 - t40 * t36 * b - t39 * t37;
    const T t42 = T(1) / a;
    const T t43 = T(3) * t36 * t38 - T(2) * t41 * t42 * b - c * t40 * t36;
    const T t44 = t34 - t37 - t36 * t38 * b;
    const T t45 = t41 * c * t42 + T(2) * t42 * t43 * b - T(3) * t44 * t42;
    const T t46 = t39 * t39;
    const T t47 = t35 * t35;
    const T t48 = T(3) * t46 * t37 * b + T(3) * t47 * a_minus_b * t34 + T(4) * t40 * t36 * a;
    const T t49 = t48 * t36 * b + T(3) * t46 * t37 - T(3) * t47 * t34;
    const T t50 = T(2) * t49 * t42 * b + T(5) * t40 * t36 - t48 * c * t36;
    const T t51 = T(5) * t41 * t42 + c * t49 * t42 - T(2) * t50 * t42 * b;
    const T t52 = T(2) * t42 * t51 * b + t50 * c * t42 - T(5) * t42 * t43;
    const T t53 = T(5) * t45 * t42 + c * t42 * t51 - T(2) * t52 * t42 * b;
    const T t54 = t1 * t1;
    const T t55 = t54 * delta_tau;
    const T t56 = t1 * delta_tau;
    const T t57 = t56 * t56;
    const T t58 = t2 * tau_lo;
    const T t59 = t58 * t58;
    const T t60 = t2 * t2;
    const T t61 = t60 * tau_lo;
    F = (T(2) / T(5)) * t53 * t55 * tau_lo * t42 + (T(1) / T(15)) * t57 * t42 * (T(2) * t53 * t42 * b + t52 * c * t42 - T(5) * (c * t42 * t43 + T(3) * (c * t36 * t38 + T(2) * t44 * t42 * b - J1) * t42 - T(2) * t45 * t42 * b) * t42) + (T(1) / T(15)) * t48 * t36 * t59 + (T(2) / T(5)) * t49 * delta_tau * t61 * t42 + t50 * t1 * t60 * t42 - t52 * t54 * t2 * t42 - (T(4) / T(3)) * t56 * t58 * t42 * t51;
    const T t62 = t46 * t39;
    const T t63 = t47 * t35;
    const T t64 = T(5) * t62 * t37 * b + T(5) * t63 * a_minus_b * t34 + T(2) * t48 * t36 * a;
    const T t65 = t36 * t64 * b + T(5) * t62 * t37 - T(5) * t63 * t34;
    const T t66 = T(3) * c * t36 * t64 - T(6) * t65 * t42 * b - T(7) * t48 * t36;
    const T t67 = T(7) * t49 * t42 - T(2) * t66 * t42 * b - T(3) * c * t65 * t42;
    const T t68 = T(7) * t50 * t42 + T(2) * t67 * t42 * b + c * t66 * t42;
    const T t69 = c * t67 * t42 + T(7) * t42 * t51 - T(2) * t68 * t42 * b;
    G_ap = (T(4) / T(21)) * t56 * t58 * t67 * t42 + (T(1) / T(7)) * t68 * t54 * t2 * t42 + (T(1) / T(35)) * t36 * t59 * t64 + (T(6) / T(35)) * t65 * delta_tau * t61 * t42 - (T(1) / T(105)) * t57 * t42 * (T(2) * t42 * b * t69 + T(7) * t52 * t42 + c * t68 * t42) - (T(1) / T(7)) * t1 * t66 * t60 * t42 - (T(2) / T(35)) * t55 * tau_lo * t42 * t69;
    const T t70 = t37 * t37;
    const T t71 = t70 * t37;
    const T t72 = t71 * t71;
    const T t73 = t72 * t37;
    const T t74 = t34 * t34;
    const T t75 = t74 * t34;
    const T t76 = t75 * t75;
    const T t77 = t76 * t34;
    G_E = (T(1) / T(35)) * (T(20) * t50 * t56 * t58 * t42 + T(2) * t53 * t57 * t42 + T(10) * t49 * t1 * t60 * t42 + T(5) * t73 * t59 + T(2) * t48 * delta_tau * t36 * t61 - T(5) * (T(20) * t56 * t58 + t57 + T(6) * delta_tau * t61 + T(6) * t55 * tau_lo + T(15) * t1 * t60 + T(15) * t54 * t2 + t59) * t77 - T(10) * t52 * t55 * tau_lo * t42 - T(20) * t54 * t2 * t42 * t51) * t42;
  }
  const T t78 = T(1) / a;
  const T t_star = t78 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t79 = sigma2 * sigma2;
  const T t80 = t79 * sigma2;
  const T g_factor = -T(7) * in.sigma * length * t80;
  f = in.sigma * length * t80 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(q1 * t3);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t2 * tau_lo;
    const T t9 = t7 * delta_tau;
    const T t10 = t8 * t8;
    const T t11 = t10 * tau_lo;
    const T t12 = t1 * delta_tau;
    const T t13 = t2 * t2;
    const T t14 = t12 * t12;
    const T t15 = t13 * tau_lo;
    const T t16 = t14 * delta_tau;
    F = T(35) * t7 * t8 * M_panels[4] + T(21) * t9 * t2 * M_panels[5] + t11 * M_panels[0] + T(35) * t12 * t13 * M_panels[3] + T(7) * t14 * tau_lo * M_panels[6] + T(21) * t1 * t15 * M_panels[2] + T(7) * delta_tau * t10 * M_panels[1] + t16 * M_panels[7];
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
    const T t24 = t1 * t1;
    const T t25 = t24 * delta_tau;
    const T t26 = t23 * tau_lo;
    F = t19 * M_panels[7] + T(35) * t17 * t20 * M_panels[3] + T(7) * t18 * tau_lo * M_panels[6] + T(21) * t1 * t21 * M_panels[2] + T(7) * delta_tau * t23 * M_panels[1] + T(21) * t25 * M_panels[5] * t2 + t26 * M_panels[0] + T(35) * t24 * t22 * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(D);
    const T t28 = T(1) / t27;
    const T J2 = t28 * atan2(t27, c_minus_b);
    const T t29 = t1 * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = T(1) / a;
    const T t33 = T(1) / D;
    const T t34 = T(1) / q1;
    const T t35 = b * t3 + t34 * a_minus_b + a * J2;
    const T t36 = t3 + t33 * t35 * b - t34;
    const T t37 = t33 * t35 * c - T(2) * J2 - T(2) * t32 * t36 * b;
    const T t38 = t34 * t34;
    const T t39 = t3 * t3;
    const T t40 = T(2) * t38 * a_minus_b + T(2) * b * t39 + T(3) * t33 * a * t35;
    const T t41 = T(2) * t38 - t40 * t33 * b - T(2) * t39;
    const T t42 = t40 * t33 * c + T(2) * t41 * t32 * b - T(4) * t33 * t35;
    const T t43 = T(2) * t42 * t32 * b - t41 * t32 * c - T(4) * t32 * t36;
    const T t44 = T(4) * t37 * t32 + T(2) * t32 * b * t43 - t42 * t32 * c;
    const T t45 = t38 * t34;
    const T t46 = t39 * t3;
    const T t47 = T(5) * t40 * t33 * a + T(8) * t45 * a_minus_b + T(8) * b * t46;
    const T t48 = T(8) * t45 - t33 * b * t47 - T(8) * t46;
    const T t49 = T(2) * t48 * t32 * b + t33 * t47 * c - T(6) * t40 * t33;
    const T t50 = T(2) * t32 * t49 * b + T(6) * t41 * t32 - t48 * t32 * c;
    const T t51 = T(6) * t42 * t32 + T(2) * t32 * b * t50 - t32 * t49 * c;
    const T t52 = T(6) * t32 * t43 + T(2) * t51 * t32 * b - t32 * c * t50;
    const T t53 = T(6) * t32 * t44 + T(2) * t32 * b * t52 - t51 * t32 * c;
    const T t54 = t2 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t55 * tau_lo;
    const T t57 = t1 * t1;
    const T t58 = t2 * t2;
    const T t59 = t57 * delta_tau;
    const T t60 = t58 * tau_lo;
    F = (T(1) / T(48)) * t31 * t32 * (T(6) * t32 * (T(4) * t32 * (t32 * (T(2) * J2 * b + log_ratio) - T(2) * t37 * t32 * b - t32 * t36 * c) + t32 * t43 * c - T(2) * t32 * b * t44) + t32 * c * t52 - T(2) * t32 * b * t53) + (T(1) / T(48)) * t56 * t33 * t47 - (T(35) / T(48)) * t57 * t51 * t54 * t32 - (T(7) / T(48)) * delta_tau * t55 * t48 * t32 - (T(35) / T(48)) * t29 * t58 * t32 * t50 - (T(7) / T(16)) * t59 * t2 * t32 * t52 - (T(7) / T(48)) * t30 * tau_lo * t32 * t53 - (T(7) / T(16)) * t1 * t60 * t32 * t49;
  }
  const T t61 = sigma2 * sigma2;
  const T t62 = t61 * t61;
  f = t62 * F * length;
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
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_hi * sigma2 * tau_lo;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * t2;
    const T t7 = t6 * tau_lo;
    const T t8 = t2 * tau_lo;
    const T t9 = t1 * t1;
    const T t10 = t1 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t8 * t8;
    const T t14 = t13 * tau_lo;
    const T t15 = t9 * delta_tau;
    const T t16 = T(21) * M_panels[11] * t7 * t1 + T(35) * M_panels[13] * t8 * t9 + M_panels[16] * t12 + t14 * M_panels[9] + T(7) * M_panels[10] * t13 * delta_tau + T(35) * t6 * M_panels[12] * t10 + T(7) * tau_lo * M_panels[15] * t11 + T(21) * M_panels[14] * t2 * t15;
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[10] * t14 + T(35) * M_panels[13] * t6 * t10 + T(7) * M_panels[11] * t13 * delta_tau + T(21) * t2 * M_panels[15] * t15 + M_panels[17] * t12 + T(35) * M_panels[14] * t8 * t9 + T(21) * t7 * M_panels[12] * t1 + T(7) * M_panels[16] * tau_lo * t11 - b * t16 * t17;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t2 * t2;
    const T t21 = t20 * tau_lo;
    const T t22 = t19 * tau_lo;
    const T t23 = t1 * t1;
    const T t24 = t23 * delta_tau;
    const T t25 = t1 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = T(7) * t19 * delta_tau * M_panels[10] + T(21) * M_panels[11] * t21 * t1 + M_panels[9] * t22 + T(21) * M_panels[14] * t2 * t24 + T(35) * t18 * M_panels[13] * t23 + T(7) * M_panels[15] * tau_lo * t26 + T(35) * M_panels[12] * t20 * t25 + M_panels[16] * t27;
    G_ap = t28;
    const T t29 = T(1) / a;
    G_E = t22 * M_panels[10] + T(21) * M_panels[15] * t2 * t24 + T(7) * tau_lo * M_panels[16] * t26 + M_panels[17] * t27 + T(7) * M_panels[11] * t19 * delta_tau + T(35) * t20 * M_panels[13] * t25 + T(21) * M_panels[12] * t21 * t1 + T(35) * M_panels[14] * t18 * t23 - b * t28 * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = atan2(t30, c_minus_b) * t31;
    const T t32 = t2 * t2;
    const T t33 = t32 * tau_lo;
    const T t34 = T(1) / a;
    const T t35 = T(1) / c;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = T(1) / q1;
    const T t39 = J2 * a + t38 * a_minus_b + b * t35;
    const T t40 = T(1) / D;
    const T t41 = t38 * t38;
    const T t42 = T(3) * t39 * t40 * a + T(2) * b * t36 + T(2) * t41 * a_minus_b;
    const T t43 = t41 * t38;
    const T t44 = T(8) * b * t37 + T(5) * t42 * t40 * a + T(8) * t43 * a_minus_b;
    const T t45 = t36 * t36;
    const T t46 = t41 * t41;
    const T t47 = T(48) * b * t45 + T(7) * t44 * t40 * a + T(48) * t46 * a_minus_b;
    const T t48 = T(48) * t45 + b * t47 * t40 - T(48) * t46;
    const T t49 = T(8) * t44 * t40 + T(2) * b * t48 * t34 - t47 * c * t40;
    const T t50 = T(8) * t43 - t44 * b * t40 - T(8) * t37;
    const T t51 = T(2) * t41 - b * t42 * t40 - T(2) * t36;
    const T t52 = t44 * c * t40 + T(2) * t50 * b * t34 - T(6) * t42 * t40;
    const T t53 = t50 * c * t34 - T(6) * t51 * t34 - T(2) * b * t34 * t52;
    const T t54 = T(4) * t39 * t40 - c * t42 * t40 - T(2) * t51 * b * t34;
    const T t55 = T(2) * b * t53 * t34 + T(6) * t54 * t34 + c * t34 * t52;
    const T t56 = b * t39 * t40 + t35 - t38;
    const T t57 = t51 * c * t34 + T(2) * t54 * b * t34 + T(4) * t56 * t34;
    const T t58 = T(2) * b * t55 * t34 + T(6) * t57 * t34 - c * t53 * t34;
    const T t59 = T(8) * t50 * t34 + t48 * c * t34 - T(2) * b * t34 * t49;
    const T t60 = c * t34 * t49 + T(8) * t34 * t52 + T(2) * b * t59 * t34;
    const T t61 = T(2) * b * t60 * t34 - T(8) * t53 * t34 - t59 * c * t34;
    const T t62 = T(2) * b * t61 * t34 - T(8) * t55 * t34 - t60 * c * t34;
    const T t63 = t1 * delta_tau;
    const T t64 = t63 * t63;
    const T t65 = t64 * delta_tau;
    const T t66 = t2 * tau_lo;
    const T t67 = t66 * t66;
    const T t68 = t67 * tau_lo;
    const T t69 = t1 * t1;
    const T t70 = t69 * delta_tau;
    G_ap = (T(7) / T(128)) * t33 * t1 * t34 * t49 + (T(1) / T(384)) * (T(8) * t58 * t34 + t61 * c * t34 - T(2) * t62 * b * t34) * t65 * t34 + (T(7) / T(384)) * t48 * t67 * delta_tau * t34 + (T(1) / T(384)) * t47 * t68 * t40 - (T(7) / T(384)) * t62 * tau_lo * t64 * t34 - (T(35) / T(384)) * t59 * t32 * t63 * t34 - (T(35) / T(384)) * t60 * t66 * t69 * t34 - (T(7) / T(128)) * t61 * t2 * t70 * t34;
    G_E = -(T(1) / T(384)) * (T(48) * (T(21) * t2 * t70 + t65 + T(7) * t67 * delta_tau + T(35) * t32 * t63 + T(35) * t66 * t69 + T(21) * t33 * t1 + t68 + T(7) * tau_lo * t64) * t46 + T(105) * t32 * t63 * t34 * t52 + T(42) * t50 * t33 * t1 * t34 - T(105) * t55 * t2 * t70 * t34 - T(7) * t44 * t67 * delta_tau * t40 - T(48) * t45 * t68 - T(42) * t58 * tau_lo * t64 * t34 - T(7) * (T(2) * b * t58 * t34 + T(6) * (T(4) * (T(2) * J2 + T(2) * b * t56 * t34 - c * t39 * t40) * t34 + T(2) * b * t57 * t34 - t54 * c * t34) * t34 - t55 * c * t34) * t65 * t34 - T(140) * t53 * t66 * t69 * t34) * t34;
  }
  const T t71 = T(1) / a;
  const T t_star = b * t71;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t72 = sigma2 * sigma2;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * t73 * length;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
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
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * t2;
    const T t8 = t7 * tau_lo;
    const T t9 = t2 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t1 * t1;
    const T t12 = t11 * delta_tau;
    const T t13 = t1 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t14 * delta_tau;
    const T t16 = t10 * tau_lo;
    F = T(21) * t1 * t8 * M_panels[2] + T(7) * M_panels[1] * delta_tau * t10 + T(35) * M_panels[4] * t11 * t9 + T(21) * t12 * t2 * M_panels[5] + T(7) * M_panels[6] * t14 * tau_lo + M_panels[7] * t15 + M_panels[0] * t16 + T(35) * M_panels[3] * t13 * t7;
    const T t17 = T(21) * t1 * t8 * M_panels[11] + T(35) * M_panels[13] * t11 * t9 + T(7) * M_panels[10] * delta_tau * t10 + M_panels[9] * t16 + T(21) * t12 * t2 * M_panels[14] + T(7) * M_panels[15] * t14 * tau_lo + T(35) * M_panels[12] * t13 * t7 + M_panels[16] * t15;
    G_ap = t17;
    const T t18 = T(1) / a;
    G_E = M_panels[10] * t16 + t15 * M_panels[17] + T(35) * M_panels[13] * t13 * t7 + T(35) * t11 * t9 * M_panels[14] + T(21) * M_panels[15] * t12 * t2 + T(21) * M_panels[12] * t1 * t8 + T(7) * delta_tau * t10 * M_panels[11] + T(7) * M_panels[16] * t14 * tau_lo - b * t18 * t17;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t19 = t1 * t1;
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t2 * t2;
    const T t23 = t22 * tau_lo;
    const T t24 = t1 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t25 * delta_tau;
    const T t27 = t21 * tau_lo;
    const T t28 = t19 * delta_tau;
    F = T(35) * M_panels[4] * t19 * t20 + T(7) * M_panels[1] * delta_tau * t21 + T(21) * M_panels[2] * t1 * t23 + M_panels[7] * t26 + t27 * M_panels[0] + T(35) * t24 * t22 * M_panels[3] + T(21) * M_panels[5] * t28 * t2 + T(7) * t25 * tau_lo * M_panels[6];
    const T t29 = t27 * M_panels[9] + T(7) * t25 * tau_lo * M_panels[15] + T(21) * M_panels[14] * t28 * t2 + T(35) * t24 * t22 * M_panels[12] + t26 * M_panels[16] + T(21) * M_panels[11] * t1 * t23 + T(7) * M_panels[10] * delta_tau * t21 + T(35) * M_panels[13] * t19 * t20;
    G_ap = t29;
    const T t30 = T(1) / a;
    G_E = T(21) * t1 * t23 * M_panels[12] + T(21) * t28 * t2 * M_panels[15] + M_panels[10] * t27 + T(7) * M_panels[11] * delta_tau * t21 + T(35) * M_panels[14] * t19 * t20 + M_panels[17] * t26 + T(7) * t25 * tau_lo * M_panels[16] + T(35) * M_panels[13] * t24 * t22 - t29 * b * t30;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = atan2(t31, c_minus_b) * t32;
    const T t33 = T(1) / q1;
    const T t34 = b * t3 + a_minus_b * t33 + J2 * a;
    const T t35 = T(1) / D;
    const T t36 = t33 * t33;
    const T t37 = t3 * t3;
    const T t38 = T(3) * t34 * t35 * a + T(2) * a_minus_b * t36 + T(2) * b * t37;
    const T t39 = t36 * t33;
    const T t40 = t37 * t3;
    const T t41 = T(5) * t38 * t35 * a + T(8) * a_minus_b * t39 + T(8) * b * t40;
    const T t42 = t2 * tau_lo;
    const T t43 = t42 * t42;
    const T t44 = t43 * tau_lo;
    const T t45 = b * t41 * t35 + T(8) * t40 - T(8) * t39;
    const T t46 = T(1) / a;
    const T t47 = T(2) * t45 * b * t46 + T(6) * t38 * t35 - t41 * c * t35;
    const T t48 = T(2) * t37 + t38 * b * t35 - T(2) * t36;
    const T t49 = T(2) * b * t47 * t46 + T(6) * t48 * t46 - t45 * c * t46;
    const T t50 = t1 * delta_tau;
    const T t51 = t2 * t2;
    const T t52 = t38 * c * t35 - T(4) * t34 * t35 - T(2) * b * t48 * t46;
    const T t53 = T(2) * t49 * b * t46 - t47 * c * t46 - T(6) * t52 * t46;
    const T t54 = t1 * t1;
    const T t55 = t51 * tau_lo;
    const T t56 = t33 - t3 - b * t34 * t35;
    const T t57 = T(2) * b * t52 * t46 + T(4) * t56 * t46 + c * t48 * t46;
    const T t58 = T(6) * t57 * t46 + t49 * c * t46 - T(2) * t53 * b * t46;
    const T t59 = t34 * c * t35 + T(2) * b * t56 * t46 - T(2) * J2;
    const T t60 = T(4) * t59 * t46 + T(2) * t57 * b * t46 - t52 * c * t46;
    const T t61 = t53 * c * t46 + T(2) * b * t58 * t46 + T(6) * t60 * t46;
    const T t62 = t50 * t50;
    const T t63 = t62 * delta_tau;
    const T t64 = t54 * delta_tau;
    F = (T(1) / T(48)) * t41 * t44 * t35 + (T(35) / T(48)) * t49 * t50 * t51 * t46 + (T(35) / T(48)) * t53 * t54 * t42 * t46 + (T(7) / T(16)) * t47 * t1 * t55 * t46 + (T(7) / T(48)) * t45 * delta_tau * t43 * t46 + (T(1) / T(48)) * (c * t58 * t46 + T(6) * (t57 * c * t46 + T(4) * ((T(2) * b * J2 + log_ratio) * t46 + c * t56 * t46 - T(2) * t59 * b * t46) * t46 - T(2) * t60 * b * t46) * t46 - T(2) * b * t61 * t46) * t63 * t46 - (T(7) / T(16)) * t64 * t2 * t58 * t46 - (T(7) / T(48)) * t62 * tau_lo * t61 * t46;
    const T t65 = t37 * t37;
    const T t66 = t36 * t36;
    const T t67 = T(48) * b * t65 + T(7) * t41 * t35 * a + T(48) * a_minus_b * t66;
    const T t68 = T(48) * t65 + b * t67 * t35 - T(48) * t66;
    const T t69 = c * t67 * t35 - T(8) * t41 * t35 - T(2) * b * t68 * t46;
    const T t70 = t68 * c * t46 + T(2) * b * t69 * t46 - T(8) * t45 * t46;
    const T t71 = T(8) * t47 * t46 + c * t69 * t46 - T(2) * b * t70 * t46;
    const T t72 = t70 * c * t46 + T(8) * t49 * t46 + T(2) * b * t71 * t46;
    const T t73 = T(2) * b * t72 * t46 + T(8) * t53 * t46 - t71 * c * t46;
    G_ap = (T(1) / T(384)) * t67 * t44 * t35 + (T(1) / T(384)) * (T(2) * t73 * b * t46 - T(8) * t58 * t46 - c * t72 * t46) * t63 * t46 + (T(7) / T(384)) * t68 * delta_tau * t43 * t46 + (T(7) / T(384)) * t73 * t62 * tau_lo * t46 + (T(7) / T(128)) * t64 * t72 * t2 * t46 + (T(35) / T(384)) * t71 * t54 * t42 * t46 - (T(7) / T(128)) * t1 * t55 * t69 * t46 - (T(35) / T(384)) * t70 * t50 * t51 * t46;
    G_E = -(T(1) / T(384)) * t46 * (T(42) * t62 * tau_lo * t58 * t46 + T(7) * t63 * t61 * t46 + T(48) * t66 * (T(7) * t62 * tau_lo + T(35) * t50 * t51 + T(35) * t54 * t42 + T(21) * t64 * t2 + T(21) * t1 * t55 + T(7) * delta_tau * t43 + t44 + t63) - T(7) * t41 * delta_tau * t43 * t35 - T(48) * t65 * t44 - T(105) * t47 * t50 * t51 * t46 - T(42) * t45 * t1 * t55 * t46 - T(140) * t49 * t54 * t42 * t46 - T(105) * t53 * t64 * t2 * t46);
  }
  const T t74 = T(1) / a;
  const T t_star = b * t74;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t75 = sigma2 * sigma2;
  const T t76 = t75 * t75;
  const T g_factor = -T(8) * length * t76;
  f = F * length * t76;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = b * r1;
    const T t5 = sqrt(a);
    const T t6 = T(1) / D;
    X = (t4 + r0 * a_minus_b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
    X = t7 * (b - a_minus_b) / (t8 - r0 * a_minus_b);
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
    const T t14 = t1 * t1;
    const T t15 = t2 * t2;
    const T t16 = t14 * delta_tau;
    const T t17 = t2 * tau_lo;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t19 * delta_tau;
    const T t21 = t15 * tau_lo;
    const T t22 = t14 * t14;
    const T t23 = t17 * t17;
    const T t24 = t23 * tau_lo;
    const T t25 = t15 * t15;
    F = T(70) * M_panels[4] * t14 * t15 + T(56) * M_panels[5] * t16 * t17 + T(8) * M_panels[7] * t20 * tau_lo + T(56) * t18 * t21 * M_panels[3] + M_panels[8] * t22 + T(28) * M_panels[2] * t1 * t23 + T(28) * t19 * M_panels[6] * t2 + T(8) * M_panels[1] * delta_tau * t24 + M_panels[0] * t25;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t1 * t1;
    const T t27 = t26 * t26;
    const T t28 = t1 * delta_tau;
    const T t29 = t2 * t2;
    const T t30 = t29 * tau_lo;
    const T t31 = t26 * delta_tau;
    const T t32 = t2 * tau_lo;
    const T t33 = t28 * t28;
    const T t34 = t33 * delta_tau;
    const T t35 = t29 * t29;
    const T t36 = t32 * t32;
    const T t37 = t36 * tau_lo;
    F = M_panels[8] * t27 + T(56) * M_panels[3] * t28 * t30 + T(56) * M_panels[5] * t31 * t32 + T(70) * M_panels[4] * t26 * t29 + T(8) * M_panels[7] * t34 * tau_lo + M_panels[0] * t35 + T(8) * M_panels[1] * delta_tau * t37 + T(28) * M_panels[2] * t1 * t36 + T(28) * M_panels[6] * t33 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / a;
    const T t39 = T(1) / r0;
    const T t40 = t39 * t39;
    const T t41 = t40 * t40;
    const T t42 = t41 * t40;
    const T t43 = T(1) / r1;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t44;
    const T t47 = T(1) / D;
    const T t48 = t43 * a_minus_b + t39 * b;
    const T t49 = t43 * a_minus_b * t44 + t39 * b * t40 + T(2) * a * t48 * t47;
    const T t50 = T(4) * a * t49 * t47 + T(3) * t39 * b * t41 + T(3) * t43 * a_minus_b * t45;
    const T t51 = T(5) * t39 * b * t42 + T(5) * t43 * a_minus_b * t46 + T(2) * a * t47 * t50;
    const T t52 = T(5) * t39 * t42 + b * t51 * t47 - T(5) * t43 * t46;
    const T t53 = t2 * tau_lo;
    const T t54 = t53 * t53;
    const T t55 = t54 * tau_lo;
    const T t56 = t43 * t44 - t39 * t40 - b * t49 * t47;
    const T t57 = T(3) * t48 * t47 - T(2) * t38 * b * t56 - t49 * c * t47;
    const T t58 = b * t48 * t47 + t39 - t43;
    const T t59 = T(2) * t38 * t57 * b + T(3) * t38 * t58 + t38 * t56 * c;
    const T t60 = T(3) * t39 * t41 + b * t47 * t50 - T(3) * t43 * t45;
    const T t61 = T(2) * t60 * t38 * b + T(5) * t49 * t47 - c * t47 * t50;
    const T t62 = T(5) * t38 * t56 + t60 * t38 * c - T(2) * t38 * b * t61;
    const T t63 = T(2) * t38 * t62 * b + t38 * c * t61 - T(5) * t38 * t57;
    const T t64 = T(5) * t38 * t59 + t38 * t62 * c - T(2) * t38 * b * t63;
    const T t65 = T(3) * c * t51 * t47 - T(7) * t47 * t50 - T(6) * t38 * b * t52;
    const T t66 = T(3) * t38 * c * t52 + T(2) * t38 * b * t65 - T(7) * t60 * t38;
    const T t67 = T(7) * t38 * t61 + t38 * c * t65 - T(2) * t38 * b * t66;
    const T t68 = t38 * c * t66 + T(2) * t38 * t67 * b - T(7) * t38 * t62;
    const T t69 = t38 * t67 * c + T(7) * t38 * t63 - T(2) * t38 * b * t68;
    const T t70 = T(7) * t38 * t64 - t38 * t68 * c - T(2) * t38 * t69 * b;
    const T t71 = t1 * delta_tau;
    const T t72 = t71 * t71;
    const T t73 = t72 * delta_tau;
    const T t74 = t1 * t1;
    const T t75 = t2 * t2;
    const T t76 = t74 * t74;
    const T t77 = t75 * t75;
    const T t78 = t74 * delta_tau;
    const T t79 = t75 * tau_lo;
    F = (T(8) / T(35)) * t38 * t52 * delta_tau * t55 + (T(8) / T(105)) * t38 * t70 * t73 * tau_lo + (T(2) / T(3)) * t38 * t67 * t74 * t75 + (T(1) / T(105)) * t38 * (t38 * t69 * c + T(7) * t38 * (t38 * c * t63 + T(5) * t38 * (T(3) * t38 * (T(2) * t38 * b * t58 + J1 - t48 * c * t47) + T(2) * t38 * t59 * b - t38 * t57 * c) + T(2) * t38 * t64 * b) + T(2) * t38 * b * t70) * t76 + (T(1) / T(35)) * t51 * t47 * t77 + (T(8) / T(15)) * t38 * t68 * t78 * t53 - (T(8) / T(15)) * t38 * t71 * t66 * t79 - (T(4) / T(15)) * t38 * t69 * t72 * t2 - (T(4) / T(15)) * t38 * t65 * t1 * t54;
  }
  const T t80 = sigma2 * sigma2;
  const T t81 = t80 * t80;
  f = t81 * F * in.sigma * length;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
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
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t1 * t1;
    const T t10 = t9 * delta_tau;
    const T t11 = t2 * t2;
    const T t12 = t1 * delta_tau;
    const T t13 = t11 * tau_lo;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = t14 * delta_tau;
    const T t17 = t9 * t9;
    const T t18 = T(8) * delta_tau * t8 * M_panels[11] + T(56) * t10 * t6 * M_panels[15] + T(70) * t9 * t11 * M_panels[14] + T(56) * t12 * M_panels[13] * t13 + T(28) * M_panels[16] * t14 * t2 + T(28) * M_panels[12] * t1 * t7 + M_panels[10] * t15 + T(8) * t16 * tau_lo * M_panels[17] + t17 * M_panels[18];
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = T(8) * t16 * tau_lo * M_panels[18] + t15 * M_panels[11] + T(8) * M_panels[12] * delta_tau * t8 + M_panels[19] * t17 + T(28) * t14 * t2 * M_panels[17] + T(70) * t9 * t11 * M_panels[15] + T(56) * M_panels[16] * t10 * t6 + T(28) * t1 * M_panels[13] * t7 + T(56) * t12 * t13 * M_panels[14] - t18 * t19 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * delta_tau;
    const T t23 = t2 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t26 * t26;
    const T t28 = t2 * t2;
    const T t29 = t26 * delta_tau;
    const T t30 = t28 * tau_lo;
    const T t31 = t28 * t28;
    const T t32 = T(8) * t22 * tau_lo * M_panels[17] + T(28) * t21 * t2 * M_panels[16] + T(8) * M_panels[11] * delta_tau * t25 + M_panels[18] * t27 + T(70) * t26 * t28 * M_panels[14] + T(56) * M_panels[15] * t29 * t23 + T(28) * t1 * M_panels[12] * t24 + T(56) * t20 * t30 * M_panels[13] + t31 * M_panels[10];
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(8) * delta_tau * M_panels[12] * t25 + t27 * M_panels[19] + T(28) * t1 * t24 * M_panels[13] + T(8) * M_panels[18] * t22 * tau_lo + T(56) * t20 * t30 * M_panels[14] + T(70) * M_panels[15] * t26 * t28 + T(28) * t21 * t2 * M_panels[17] + M_panels[11] * t31 + T(56) * t29 * t23 * M_panels[16] - t32 * t33 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t1 * delta_tau;
    const T t35 = t34 * t34;
    const T t36 = t35 * delta_tau;
    const T t37 = T(1) / a;
    const T t38 = T(1) / D;
    const T t39 = T(1) / r1;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t41 * b + a_minus_b * t39;
    const T t44 = a_minus_b * t39 * t40 + t41 * t42 * b + T(2) * t38 * a * t43;
    const T t45 = t42 * t42;
    const T t46 = t40 * t40;
    const T t47 = T(4) * t38 * a * t44 + T(3) * t41 * t45 * b + T(3) * a_minus_b * t39 * t46;
    const T t48 = t47 * t38 * b + T(3) * t41 * t45 - T(3) * t39 * t46;
    const T t49 = T(5) * t38 * t44 + T(2) * t48 * t37 * b - t47 * c * t38;
    const T t50 = t41 * t42 + t38 * b * t44 - t39 * t40;
    const T t51 = T(2) * t37 * b * t49 + T(5) * t37 * t50 - t48 * c * t37;
    const T t52 = t45 * t42;
    const T t53 = t46 * t40;
    const T t54 = T(5) * t41 * t52 * b + T(5) * a_minus_b * t39 * t53 + T(2) * t47 * t38 * a;
    const T t55 = t38 * t54 * b + T(5) * t41 * t52 - T(5) * t39 * t53;
    const T t56 = T(7) * t47 * t38 + T(6) * t55 * t37 * b - T(3) * c * t38 * t54;
    const T t57 = T(2) * t56 * t37 * b + T(7) * t48 * t37 - T(3) * t55 * c * t37;
    const T t58 = T(2) * t57 * t37 * b + T(7) * t37 * t49 - c * t56 * t37;
    const T t59 = T(7) * t37 * t51 + T(2) * t37 * t58 * b - c * t57 * t37;
    const T t60 = t45 * t45;
    const T t61 = t46 * t46;
    const T t62 = T(35) * t41 * t60 * b + T(8) * t38 * a * t54 + T(35) * a_minus_b * t39 * t61;
    const T t63 = t38 * t62 * b + T(35) * t41 * t60 - T(35) * t39 * t61;
    const T t64 = T(2) * t63 * t37 * b + T(9) * t38 * t54 - c * t38 * t62;
    const T t65 = c * t63 * t37 - T(9) * t55 * t37 - T(2) * t37 * t64 * b;
    const T t66 = T(2) * t37 * b * t65 + c * t37 * t64 - T(3) * t56 * t37;
    const T t67 = c * t37 * t65 + T(3) * t57 * t37 - T(2) * t37 * t66 * b;
    const T t68 = T(3) * t37 * t58 + c * t37 * t66 + T(2) * t67 * t37 * b;
    const T t69 = T(3) * t37 * t59 + T(2) * t68 * t37 * b - c * t67 * t37;
    const T t70 = t1 * t1;
    const T t71 = t70 * delta_tau;
    const T t72 = t2 * tau_lo;
    const T t73 = t72 * t72;
    const T t74 = t2 * t2;
    const T t75 = t74 * t74;
    const T t76 = t73 * tau_lo;
    const T t77 = t70 * t70;
    const T t78 = T(3) * t38 * t43 + T(2) * t37 * b * t50 - c * t38 * t44;
    const T t79 = T(2) * t37 * t51 * b + T(5) * t37 * t78 - c * t37 * t49;
    const T t80 = T(2) * t37 * t59 * b + T(7) * t79 * t37 - c * t37 * t58;
    const T t81 = t74 * tau_lo;
    G_ap = (T(8) / T(315)) * t36 * tau_lo * t69 * t37 + (T(8) / T(45)) * t67 * t71 * t72 * t37 + (T(4) / T(45)) * t1 * t73 * t37 * t64 + (T(1) / T(315)) * t38 * t75 * t62 + (T(8) / T(315)) * delta_tau * t76 * t63 * t37 + (T(4) / T(45)) * t68 * t35 * t2 * t37 - (T(2) / T(9)) * t70 * t74 * t37 * t66 - (T(1) / T(315)) * t77 * t37 * (t68 * c * t37 - T(3) * t37 * t80 - T(2) * t69 * t37 * b) - (T(8) / T(45)) * t34 * t81 * t37 * t65;
    const T t82 = t41 * t41;
    const T t83 = t82 * t82;
    const T t84 = t83 * t83;
    const T t85 = t84 * t41;
    const T t86 = t39 * t39;
    const T t87 = t86 * t86;
    const T t88 = t87 * t87;
    const T t89 = t88 * t39;
    G_E = (T(1) / T(945)) * t37 * (T(24) * delta_tau * t38 * t76 * t54 + T(280) * t70 * t57 * t74 * t37 + T(168) * t55 * t1 * t73 * t37 + T(8) * (T(2) * t37 * t80 * b - T(7) * t37 * (T(5) * t37 * (c * t37 * t50 - T(2) * t37 * b * t78 - T(3) * (t38 * t43 * b + t41 - t39) * t37) + c * t37 * t51 - T(2) * t79 * t37 * b) - c * t37 * t59) * t77 * t37 + T(280) * t71 * t72 * t37 * t58 + T(168) * t35 * t2 * t37 * t59 + T(168) * t34 * t81 * t56 * t37 + T(105) * t85 * t75 + T(56) * t36 * tau_lo * t37 * t80 - T(105) * t89 * (T(70) * t70 * t74 + T(8) * delta_tau * t76 + t75 + T(28) * t1 * t73 + T(28) * t35 * t2 + T(56) * t34 * t81 + T(56) * t71 * t72 + t77 + T(8) * t36 * tau_lo));
  }
  const T t90 = T(1) / a;
  const T t_star = t90 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T g_factor = -T(9) * in.sigma * length * t92;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = r0 * a_minus_b;
    const T t6 = sqrt(a);
    X = t4 * (t5 + r1 * b) * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
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
    const T t16 = t1 * t1;
    const T t17 = t16 * t16;
    const T t18 = t2 * t2;
    const T t19 = t16 * delta_tau;
    const T t20 = t1 * delta_tau;
    const T t21 = t18 * tau_lo;
    const T t22 = t20 * t20;
    const T t23 = t22 * delta_tau;
    const T t24 = t15 * tau_lo;
    const T t25 = t18 * t18;
    F = T(28) * M_panels[2] * t1 * t15 + t17 * M_panels[8] + T(70) * t16 * t18 * M_panels[4] + T(56) * t19 * t14 * M_panels[5] + T(56) * t20 * t21 * M_panels[3] + T(8) * t23 * tau_lo * M_panels[7] + T(8) * delta_tau * t24 * M_panels[1] + T(28) * t22 * t2 * M_panels[6] + t25 * M_panels[0];
    const T t26 = t25 * M_panels[10] + M_panels[18] * t17 + T(8) * t23 * tau_lo * M_panels[17] + T(56) * M_panels[15] * t19 * t14 + T(8) * delta_tau * t24 * M_panels[11] + T(70) * t16 * t18 * M_panels[14] + T(28) * t22 * t2 * M_panels[16] + T(56) * t20 * t21 * M_panels[13] + T(28) * t1 * M_panels[12] * t15;
    G_ap = t26;
    const T t27 = T(1) / a;
    G_E = t17 * M_panels[19] + T(28) * t1 * t15 * M_panels[13] + T(8) * delta_tau * M_panels[12] * t24 + T(56) * t19 * t14 * M_panels[16] + T(56) * t20 * t21 * M_panels[14] + T(70) * M_panels[15] * t16 * t18 + T(28) * t22 * t2 * M_panels[17] + t25 * M_panels[11] + T(8) * M_panels[18] * t23 * tau_lo - t27 * t26 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t1 * t1;
    const T t31 = t30 * delta_tau;
    const T t32 = t2 * tau_lo;
    const T t33 = t30 * t30;
    const T t34 = t29 * delta_tau;
    const T t35 = t2 * t2;
    const T t36 = t35 * t35;
    const T t37 = t35 * tau_lo;
    const T t38 = t32 * t32;
    const T t39 = t38 * tau_lo;
    F = T(28) * t29 * t2 * M_panels[6] + T(56) * t31 * t32 * M_panels[5] + t33 * M_panels[8] + T(8) * t34 * tau_lo * M_panels[7] + t36 * M_panels[0] + T(56) * t28 * t37 * M_panels[3] + T(8) * M_panels[1] * delta_tau * t39 + T(28) * t1 * t38 * M_panels[2] + T(70) * t30 * t35 * M_panels[4];
    const T t40 = T(28) * t1 * t38 * M_panels[12] + t33 * M_panels[18] + T(8) * delta_tau * M_panels[11] * t39 + T(56) * t31 * t32 * M_panels[15] + T(56) * t28 * t37 * M_panels[13] + T(8) * M_panels[17] * t34 * tau_lo + T(70) * M_panels[14] * t30 * t35 + T(28) * t29 * t2 * M_panels[16] + t36 * M_panels[10];
    G_ap = t40;
    const T t41 = T(1) / a;
    G_E = T(56) * t31 * t32 * M_panels[16] + M_panels[11] * t36 + T(56) * M_panels[14] * t28 * t37 + T(8) * t34 * tau_lo * M_panels[18] + T(28) * t1 * t38 * M_panels[13] + t33 * M_panels[19] + T(28) * M_panels[17] * t29 * t2 + T(8) * delta_tau * t39 * M_panels[12] + T(70) * t30 * t35 * M_panels[15] - t41 * t40 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t42 = T(1) / D;
    const T t43 = t2 * t2;
    const T t44 = t43 * t43;
    const T t45 = T(1) / r0;
    const T t46 = t45 * t45;
    const T t47 = t46 * t46;
    const T t48 = t47 * t46;
    const T t49 = T(1) / r1;
    const T t50 = a_minus_b * t49 + t45 * b;
    const T t51 = t49 * t49;
    const T t52 = T(2) * t50 * t42 * a + a_minus_b * t49 * t51 + t45 * b * t46;
    const T t53 = t51 * t51;
    const T t54 = T(4) * t42 * a * t52 + T(3) * t45 * b * t47 + T(3) * a_minus_b * t49 * t53;
    const T t55 = t53 * t51;
    const T t56 = T(5) * t45 * b * t48 + T(2) * t42 * a * t54 + T(5) * a_minus_b * t49 * t55;
    const T t57 = t2 * tau_lo;
    const T t58 = t57 * t57;
    const T t59 = T(1) / a;
    const T t60 = T(5) * t49 * t55 - t42 * b * t56 - T(5) * t45 * t48;
    const T t61 = T(7) * t42 * t54 - T(3) * t42 * t56 * c - T(6) * t59 * t60 * b;
    const T t62 = t1 * delta_tau;
    const T t63 = t62 * t62;
    const T t64 = T(3) * t49 * t53 - t42 * b * t54 - T(3) * t45 * t47;
    const T t65 = T(7) * t64 * t59 - T(3) * t59 * t60 * c - T(2) * t59 * b * t61;
    const T t66 = t42 * t54 * c + T(2) * t64 * t59 * b - T(5) * t42 * t52;
    const T t67 = T(2) * t65 * t59 * b + t59 * t61 * c + T(7) * t59 * t66;
    const T t68 = t42 * t52 * b + t45 * t46 - t49 * t51;
    const T t69 = T(2) * t68 * t59 * b + T(3) * t50 * t42 - t42 * t52 * c;
    const T t70 = t64 * t59 * c + T(5) * t68 * t59 - T(2) * t59 * t66 * b;
    const T t71 = t59 * t66 * c + T(5) * t59 * t69 + T(2) * t59 * t70 * b;
    const T t72 = T(2) * t59 * b * t67 - T(7) * t59 * t70 - t65 * t59 * c;
    const T t73 = t59 * t67 * c + T(7) * t59 * t71 - T(2) * t59 * t72 * b;
    const T t74 = t58 * tau_lo;
    const T t75 = t63 * delta_tau;
    const T t76 = t49 - t50 * t42 * b - t45;
    const T t77 = T(3) * t59 * t76 + t68 * t59 * c - T(2) * t59 * b * t69;
    const T t78 = t59 * t70 * c + T(5) * t59 * t77 - T(2) * t59 * b * t71;
    const T t79 = T(7) * t78 * t59 - t59 * t72 * c - T(2) * t73 * t59 * b;
    const T t80 = t1 * t1;
    const T t81 = t80 * t80;
    const T t82 = t43 * tau_lo;
    const T t83 = t80 * delta_tau;
    F = (T(1) / T(35)) * t42 * t44 * t56 + (T(4) / T(15)) * t1 * t58 * t59 * t61 + (T(4) / T(15)) * t63 * t73 * t2 * t59 - (T(8) / T(35)) * delta_tau * t74 * t59 * t60 - (T(8) / T(105)) * t75 * tau_lo * t79 * t59 - (T(2) / T(3)) * t80 * t43 * t59 * t67 - (T(1) / T(105)) * (T(7) * t59 * (T(2) * t78 * t59 * b + t59 * t71 * c - T(5) * t59 * (T(3) * t59 * (J1 - t50 * t42 * c - T(2) * t59 * b * t76) - t59 * t69 * c - T(2) * t59 * b * t77)) + T(2) * t79 * t59 * b + t73 * t59 * c) * t81 * t59 - (T(8) / T(15)) * t62 * t82 * t65 * t59 - (T(8) / T(15)) * t83 * t57 * t59 * t72;
    const T t84 = t53 * t53;
    const T t85 = t47 * t47;
    const T t86 = T(8) * t42 * a * t56 + T(35) * a_minus_b * t49 * t84 + T(35) * t45 * b * t85;
    const T t87 = t86 * t42 * b + T(35) * t45 * t85 - T(35) * t49 * t84;
    const T t88 = T(2) * t87 * t59 * b + T(9) * t42 * t56 - t86 * t42 * c;
    const T t89 = T(2) * t59 * b * t88 - T(9) * t59 * t60 - t87 * t59 * c;
    const T t90 = T(3) * t59 * t61 + T(2) * t59 * t89 * b - t59 * t88 * c;
    const T t91 = T(3) * t65 * t59 + t59 * t89 * c - T(2) * t59 * t90 * b;
    const T t92 = t59 * t90 * c + T(3) * t59 * t67 + T(2) * t59 * b * t91;
    const T t93 = t59 * t91 * c - T(2) * t92 * t59 * b - T(3) * t59 * t72;
    G_ap = (T(8) / T(45)) * t62 * t82 * t59 * t89 + (T(8) / T(315)) * t75 * tau_lo * t59 * t93 + (T(4) / T(45)) * t1 * t58 * t59 * t88 + (T(1) / T(315)) * t81 * (t92 * t59 * c + T(3) * t73 * t59 + T(2) * t59 * b * t93) * t59 + (T(2) / T(9)) * t80 * t43 * t59 * t90 + (T(8) / T(315)) * delta_tau * t74 * t87 * t59 + (T(1) / T(315)) * t86 * t42 * t44 - (T(4) / T(45)) * t92 * t63 * t2 * t59 - (T(8) / T(45)) * t83 * t57 * t59 * t91;
    const T t94 = t49 * t49;
    const T t95 = t94 * t94;
    const T t96 = t95 * t95;
    const T t97 = t96 * t49;
    const T t98 = t45 * t45;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t45;
    G_E = -(T(1) / T(945)) * t59 * (T(280) * t83 * t57 * t59 * t67 + T(280) * t80 * t43 * t65 * t59 + T(105) * t97 * (t81 + T(28) * t63 * t2 + T(28) * t1 * t58 + T(56) * t83 * t57 + T(8) * t75 * tau_lo + T(56) * t62 * t82 + T(70) * t80 * t43 + t44 + T(8) * delta_tau * t74) + T(8) * t81 * t79 * t59 + T(168) * t63 * t2 * t59 * t72 + T(168) * t1 * t58 * t59 * t60 - T(105) * t101 * t44 - T(56) * t75 * t73 * tau_lo * t59 - T(168) * t62 * t82 * t59 * t61 - T(24) * delta_tau * t42 * t74 * t56);
  }
  const T t102 = T(1) / a;
  const T t_star = t102 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t103 = sigma2 * sigma2;
  const T t104 = t103 * t103;
  const T g_factor = -T(9) * length * t104 * in.sigma;
  f = length * t104 * F * in.sigma;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t2 * tau_lo;
    const T t10 = t1 * t1;
    const T t11 = t10 * t10;
    const T t12 = t2 * t2;
    const T t13 = t12 * tau_lo;
    const T t14 = t12 * t12;
    const T t15 = t14 * tau_lo;
    const T t16 = t10 * delta_tau;
    const T t17 = t9 * t9;
    const T t18 = t17 * tau_lo;
    const T t19 = t11 * delta_tau;
    const T t20 = t8 * delta_tau;
    F = T(84) * M_panels[6] * t8 * t9 + T(9) * t11 * tau_lo * M_panels[8] + T(126) * t10 * t13 * M_panels[4] + T(9) * delta_tau * t14 * M_panels[1] + M_panels[0] * t15 + T(126) * t16 * t12 * M_panels[5] + T(36) * t1 * t18 * M_panels[2] + M_panels[9] * t19 + T(84) * M_panels[3] * t7 * t17 + T(36) * t20 * t2 * M_panels[7];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t1 * t1;
    const T t22 = t2 * t2;
    const T t23 = t22 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t24 * tau_lo;
    const T t26 = t21 * t21;
    const T t27 = t1 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t2 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t31 * tau_lo;
    const T t33 = t21 * delta_tau;
    const T t34 = t26 * delta_tau;
    F = T(126) * t21 * t23 * M_panels[4] + M_panels[0] * t25 + T(9) * t26 * tau_lo * M_panels[8] + T(36) * t29 * t2 * M_panels[7] + T(36) * M_panels[2] * t1 * t32 + T(84) * M_panels[6] * t28 * t30 + T(126) * M_panels[5] * t33 * t22 + T(84) * M_panels[3] * t27 * t31 + M_panels[9] * t34 + T(9) * delta_tau * t24 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(D);
    const T t36 = T(1) / t35;
    const T J2 = t36 * atan2(t35, c_minus_b);
    const T t37 = t2 * t2;
    const T t38 = t37 * t37;
    const T t39 = T(1) / a;
    const T t40 = T(1) / D;
    const T t41 = T(1) / q1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t3 * t3;
    const T t45 = t44 * t3;
    const T t46 = a * J2 + a_minus_b * t41 + t3 * b;
    const T t47 = T(3) * t40 * a * t46 + T(2) * t44 * b + T(2) * a_minus_b * t42;
    const T t48 = t42 * t41;
    const T t49 = T(8) * t45 * b + T(5) * t40 * a * t47 + T(8) * a_minus_b * t48;
    const T t50 = t44 * t44;
    const T t51 = T(48) * a_minus_b * t43 + T(7) * t40 * a * t49 + T(48) * t50 * b;
    const T t52 = t40 * t51 * b + T(48) * t50 - T(48) * t43;
    const T t53 = T(2) * t44 + t40 * t47 * b - T(2) * t42;
    const T t54 = T(8) * t45 + t40 * t49 * b - T(8) * t48;
    const T t55 = T(6) * t40 * t47 + T(2) * t54 * t39 * b - c * t40 * t49;
    const T t56 = T(6) * t39 * t53 + T(2) * t55 * t39 * b - c * t54 * t39;
    const T t57 = T(2) * t39 * t52 * b + T(8) * t40 * t49 - c * t40 * t51;
    const T t58 = c * t39 * t52 - T(2) * t39 * t57 * b - T(8) * t54 * t39;
    const T t59 = T(8) * t55 * t39 - T(2) * t39 * b * t58 - c * t39 * t57;
    const T t60 = T(8) * t39 * t56 + c * t39 * t58 + T(2) * t59 * t39 * b;
    const T t61 = c * t40 * t47 - T(2) * t39 * t53 * b - T(4) * t40 * t46;
    const T t62 = c * t55 * t39 + T(6) * t39 * t61 - T(2) * t39 * b * t56;
    const T t63 = T(2) * t39 * t60 * b - c * t59 * t39 - T(8) * t39 * t62;
    const T t64 = t1 * delta_tau;
    const T t65 = t64 * t64;
    const T t66 = t2 * tau_lo;
    const T t67 = t38 * tau_lo;
    const T t68 = t1 * t1;
    const T t69 = t68 * delta_tau;
    const T t70 = t37 * tau_lo;
    const T t71 = t66 * t66;
    const T t72 = t71 * tau_lo;
    const T t73 = t68 * t68;
    const T t74 = t73 * delta_tau;
    const T t75 = t41 - t40 * t46 * b - t3;
    const T t76 = T(2) * t39 * t61 * b + c * t39 * t53 + T(4) * t75 * t39;
    const T t77 = c * t39 * t56 + T(2) * t39 * t62 * b + T(6) * t76 * t39;
    const T t78 = T(8) * t39 * t77 + c * t39 * t60 - T(2) * t63 * t39 * b;
    const T t79 = c * t40 * t46 + T(2) * t75 * t39 * b - T(2) * J2;
    const T t80 = T(2) * t76 * t39 * b + T(4) * t79 * t39 - c * t39 * t61;
    const T t81 = T(2) * t39 * t77 * b + T(6) * t80 * t39 - c * t39 * t62;
    const T t82 = T(8) * t81 * t39 + T(2) * t39 * b * t78 + t63 * c * t39;
    const T t83 = t65 * delta_tau;
    F = (T(3) / T(128)) * delta_tau * t38 * t39 * t52 + (T(7) / T(32)) * t63 * t65 * t66 * t39 + (T(1) / T(384)) * t40 * t51 * t67 + (T(21) / T(64)) * t69 * t37 * t39 * t60 + (T(21) / T(64)) * t68 * t59 * t70 * t39 + (T(3) / T(32)) * t1 * t72 * t39 * t57 + (T(1) / T(384)) * t74 * (c * t39 * t78 - T(2) * t82 * t39 * b - T(8) * t39 * (T(6) * t39 * (T(2) * t80 * t39 * b - c * t76 * t39 - T(4) * ((log_ratio + T(2) * J2 * b) * t39 + c * t75 * t39 - T(2) * t79 * t39 * b) * t39) + T(2) * t81 * t39 * b - c * t39 * t77)) * t39 - (T(3) / T(32)) * t83 * t2 * t39 * t78 - (T(3) / T(128)) * t73 * t82 * tau_lo * t39 - (T(7) / T(32)) * t64 * t71 * t39 * t58;
  }
  const T t84 = sigma2 * sigma2;
  const T t85 = t84 * t84;
  const T t86 = t85 * sigma2;
  f = length * t86 * F;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
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
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * t2;
    const T t7 = t6 * t6;
    const T t8 = t1 * delta_tau;
    const T t9 = t2 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t1 * t1;
    const T t12 = t11 * delta_tau;
    const T t13 = t10 * tau_lo;
    const T t14 = t11 * t11;
    const T t15 = t14 * delta_tau;
    const T t16 = t6 * tau_lo;
    const T t17 = t8 * t8;
    const T t18 = t17 * delta_tau;
    const T t19 = t7 * tau_lo;
    const T t20 = T(9) * delta_tau * t7 * M_panels[12] + T(84) * t8 * t10 * M_panels[14] + T(126) * t12 * t6 * M_panels[16] + T(36) * t1 * t13 * M_panels[13] + t15 * M_panels[20] + T(9) * t14 * tau_lo * M_panels[19] + T(126) * t11 * t16 * M_panels[15] + T(36) * t18 * M_panels[18] * t2 + T(84) * t17 * t9 * M_panels[17] + M_panels[11] * t19;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = T(126) * t11 * t16 * M_panels[16] + T(9) * t14 * tau_lo * M_panels[20] + T(84) * t8 * t10 * M_panels[15] + t19 * M_panels[12] + T(36) * t18 * t2 * M_panels[19] + T(126) * t12 * t6 * M_panels[17] + T(9) * delta_tau * t7 * M_panels[13] + M_panels[21] * t15 + T(36) * t1 * t13 * M_panels[14] + T(84) * t17 * M_panels[18] * t9 - t21 * b * t20;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t2 * t2;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t2 * tau_lo;
    const T t26 = t25 * t25;
    const T t27 = t26 * tau_lo;
    const T t28 = t1 * t1;
    const T t29 = t28 * delta_tau;
    const T t30 = t1 * delta_tau;
    const T t31 = t28 * t28;
    const T t32 = t31 * delta_tau;
    const T t33 = t22 * tau_lo;
    const T t34 = t30 * t30;
    const T t35 = t34 * delta_tau;
    const T t36 = t24 * M_panels[11] + T(36) * t1 * t27 * M_panels[13] + T(126) * t29 * t22 * M_panels[16] + T(84) * t30 * t26 * M_panels[14] + T(9) * delta_tau * t23 * M_panels[12] + T(9) * t31 * tau_lo * M_panels[19] + t32 * M_panels[20] + T(126) * t28 * M_panels[15] * t33 + T(36) * t35 * M_panels[18] * t2 + T(84) * t34 * t25 * M_panels[17];
    G_ap = t36;
    const T t37 = T(1) / a;
    G_E = T(126) * t28 * t33 * M_panels[16] + T(9) * t31 * tau_lo * M_panels[20] + T(36) * t35 * t2 * M_panels[19] + T(84) * t30 * M_panels[15] * t26 + t24 * M_panels[12] + M_panels[21] * t32 + T(9) * delta_tau * t23 * M_panels[13] + T(84) * t34 * M_panels[18] * t25 + T(36) * t1 * t27 * M_panels[14] + T(126) * t29 * t22 * M_panels[17] - t36 * t37 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = t39 * atan2(t38, c_minus_b);
    const T t40 = T(1) / q1;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = t42 * t40;
    const T t44 = T(1) / c;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t44;
    const T t48 = T(1) / D;
    const T t49 = a_minus_b * t40 + a * J2 + t44 * b;
    const T t50 = T(2) * t45 * b + T(3) * t49 * t48 * a + T(2) * a_minus_b * t41;
    const T t51 = t45 * t44;
    const T t52 = t41 * t40;
    const T t53 = T(5) * t50 * t48 * a + T(8) * t51 * b + T(8) * a_minus_b * t52;
    const T t54 = T(7) * t48 * t53 * a + T(48) * t46 * b + T(48) * a_minus_b * t42;
    const T t55 = T(128) * a_minus_b * t43 + T(128) * t47 * b + T(3) * t48 * a * t54;
    const T t56 = t2 * t2;
    const T t57 = t56 * t56;
    const T t58 = t57 * tau_lo;
    const T t59 = T(128) * t47 + t55 * t48 * b - T(128) * t43;
    const T t60 = T(1) / a;
    const T t61 = t1 * delta_tau;
    const T t62 = t2 * tau_lo;
    const T t63 = t62 * t62;
    const T t64 = T(10) * t48 * t54 + T(6) * t59 * t60 * b - T(3) * c * t55 * t48;
    const T t65 = T(48) * t46 + t48 * t54 * b - T(48) * t42;
    const T t66 = T(2) * t64 * t60 * b + T(10) * t60 * t65 - T(3) * c * t59 * t60;
    const T t67 = t1 * t1;
    const T t68 = t67 * delta_tau;
    const T t69 = T(2) * t60 * b * t65 + T(8) * t48 * t53 - c * t48 * t54;
    const T t70 = T(2) * t60 * t66 * b + T(10) * t69 * t60 - c * t64 * t60;
    const T t71 = T(8) * t52 - T(8) * t51 - t48 * t53 * b;
    const T t72 = T(2) * t69 * t60 * b - T(8) * t71 * t60 - c * t60 * t65;
    const T t73 = T(2) * t60 * b * t70 + T(10) * t60 * t72 - c * t60 * t66;
    const T t74 = t63 * tau_lo;
    const T t75 = t56 * tau_lo;
    const T t76 = t67 * t67;
    const T t77 = T(2) * t71 * t60 * b + c * t48 * t53 - T(6) * t50 * t48;
    const T t78 = T(8) * t77 * t60 + c * t69 * t60 - T(2) * t60 * b * t72;
    const T t79 = T(2) * t41 - T(2) * t45 - t50 * t48 * b;
    const T t80 = T(2) * t77 * t60 * b + T(6) * t60 * t79 - c * t71 * t60;
    const T t81 = T(2) * t78 * t60 * b + T(8) * t80 * t60 + c * t60 * t72;
    const T t82 = c * t50 * t48 + T(2) * t60 * b * t79 - T(4) * t49 * t48;
    const T t83 = T(2) * t80 * t60 * b + T(6) * t60 * t82 - c * t77 * t60;
    const T t84 = c * t78 * t60 - T(2) * t60 * b * t81 - T(8) * t60 * t83;
    const T t85 = T(10) * t78 * t60 + c * t60 * t70 - T(2) * t60 * b * t73;
    const T t86 = c * t60 * t73 + T(10) * t60 * t81 + T(2) * t85 * t60 * b;
    const T t87 = T(10) * t60 * t84 + c * t85 * t60 - T(2) * t86 * t60 * b;
    const T t88 = t76 * delta_tau;
    const T t89 = t44 + t49 * t48 * b - t40;
    const T t90 = T(2) * t60 * b * t82 - T(4) * t89 * t60 - c * t60 * t79;
    const T t91 = T(2) * t60 * b * t83 + T(6) * t60 * t90 - c * t80 * t60;
    const T t92 = T(8) * t91 * t60 - T(2) * t60 * t84 * b - c * t60 * t81;
    const T t93 = t61 * t61;
    const T t94 = t93 * delta_tau;
    G_ap = (T(1) / T(1280)) * t55 * t48 * t58 + (T(9) / T(1280)) * delta_tau * t59 * t57 * t60 + (T(7) / T(320)) * t61 * t63 * t60 * t66 + (T(21) / T(640)) * t68 * t56 * t60 * t73 + (T(3) / T(320)) * t64 * t1 * t74 * t60 + (T(21) / T(640)) * t67 * t75 * t60 * t70 + (T(3) / T(1280)) * t76 * tau_lo * t60 * t87 + (T(1) / T(3840)) * t88 * t60 * (c * t86 * t60 + T(2) * t60 * b * t87 - T(10) * t60 * t92) - (T(7) / T(320)) * t85 * t93 * t62 * t60 - (T(3) / T(320)) * t94 * t86 * t2 * t60;
    G_E = -(T(1) / T(1280)) * t60 * (T(168) * t93 * t62 * t60 * t81 + T(3) * (T(8) * t60 * (T(6) * t60 * (T(2) * t60 * b * t90 + T(4) * t60 * (c * t49 * t48 - T(2) * t89 * t60 * b - T(2) * J2) - c * t60 * t82) + T(2) * t91 * t60 * b - c * t60 * t83) + c * t60 * t84 + T(2) * t60 * t92 * b) * t88 * t60 + T(24) * t76 * tau_lo * t60 * t92 + T(128) * t43 * (T(36) * t1 * t74 + T(84) * t93 * t62 + T(36) * t94 * t2 + T(84) * t61 * t63 + T(9) * t76 * tau_lo + T(9) * delta_tau * t57 + t88 + T(126) * t67 * t75 + t58 + T(126) * t68 * t56) + T(210) * t78 * t68 * t56 * t60 - T(128) * t47 * t58 - T(84) * t69 * t61 * t63 * t60 - T(84) * t94 * t2 * t60 * t84 - T(24) * t1 * t74 * t60 * t65 - T(3) * delta_tau * t48 * t57 * t54 - T(168) * t67 * t75 * t60 * t72);
  }
  const T t95 = T(1) / a;
  const T t_star = t95 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t96 = sigma2 * sigma2;
  const T t97 = t96 * t96;
  const T t98 = t97 * sigma2;
  const T g_factor = -T(10) * length * t98;
  grad[0] = g_factor * (G_ap * foot0 - G_E * ab0);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
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
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_hi * tau_lo * sigma2;
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
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * t2;
    const T t11 = t10 * t10;
    const T t12 = t1 * delta_tau;
    const T t13 = t2 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t7 * delta_tau;
    const T t16 = t12 * t12;
    const T t17 = t11 * tau_lo;
    const T t18 = t10 * tau_lo;
    const T t19 = t14 * tau_lo;
    const T t20 = t16 * delta_tau;
    F = t9 * M_panels[9] + T(9) * M_panels[1] * delta_tau * t11 + T(84) * M_panels[3] * t12 * t14 + T(126) * M_panels[5] * t15 * t10 + T(84) * t16 * t13 * M_panels[6] + M_panels[0] * t17 + T(126) * M_panels[4] * t7 * t18 + T(9) * M_panels[8] * t8 * tau_lo + T(36) * t1 * t19 * M_panels[2] + T(36) * M_panels[7] * t20 * t2;
    const T t21 = M_panels[20] * t9 + M_panels[11] * t17 + T(84) * M_panels[17] * t16 * t13 + T(9) * t8 * tau_lo * M_panels[19] + T(126) * M_panels[15] * t7 * t18 + T(9) * delta_tau * M_panels[12] * t11 + T(36) * t1 * t19 * M_panels[13] + T(126) * t15 * t10 * M_panels[16] + T(36) * M_panels[18] * t20 * t2 + T(84) * M_panels[14] * t12 * t14;
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(84) * M_panels[15] * t12 * t14 + T(9) * delta_tau * t11 * M_panels[13] + M_panels[21] * t9 + M_panels[12] * t17 + T(9) * M_panels[20] * t8 * tau_lo + T(36) * M_panels[14] * t1 * t19 + T(126) * t7 * t18 * M_panels[16] + T(36) * t20 * t2 * M_panels[19] + T(126) * M_panels[17] * t15 * t10 + T(84) * M_panels[18] * t16 * t13 - b * t21 * t22;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t23 = t2 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    const T t29 = t26 * delta_tau;
    const T t30 = t2 * t2;
    const T t31 = t1 * delta_tau;
    const T t32 = t31 * t31;
    const T t33 = t30 * t30;
    const T t34 = t33 * tau_lo;
    const T t35 = t30 * tau_lo;
    const T t36 = t32 * delta_tau;
    F = T(36) * M_panels[2] * t1 * t25 + t28 * M_panels[9] + T(126) * M_panels[5] * t29 * t30 + T(84) * t32 * t23 * M_panels[6] + T(9) * M_panels[8] * t27 * tau_lo + T(84) * t31 * t24 * M_panels[3] + t34 * M_panels[0] + T(126) * M_panels[4] * t26 * t35 + T(36) * M_panels[7] * t36 * t2 + T(9) * M_panels[1] * delta_tau * t33;
    const T t37 = T(84) * M_panels[17] * t32 * t23 + T(9) * M_panels[12] * delta_tau * t33 + M_panels[11] * t34 + T(9) * t27 * tau_lo * M_panels[19] + T(36) * M_panels[18] * t36 * t2 + T(36) * t1 * t25 * M_panels[13] + T(126) * M_panels[15] * t26 * t35 + M_panels[20] * t28 + T(126) * t29 * t30 * M_panels[16] + T(84) * M_panels[14] * t31 * t24;
    G_ap = t37;
    const T t38 = T(1) / a;
    G_E = M_panels[12] * t34 + T(9) * delta_tau * t33 * M_panels[13] + T(84) * M_panels[15] * t31 * t24 + T(84) * M_panels[18] * t32 * t23 + T(126) * M_panels[17] * t29 * t30 + T(126) * t26 * t35 * M_panels[16] + T(36) * M_panels[14] * t1 * t25 + T(36) * t36 * t2 * M_panels[19] + T(9) * M_panels[20] * t27 * tau_lo + M_panels[21] * t28 - b * t37 * t38;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = atan2(t39, c_minus_b) * t40;
    const T t41 = t3 * t3;
    const T t42 = t41 * t3;
    const T t43 = T(1) / q1;
    const T t44 = a_minus_b * t43 + b * t3 + J2 * a;
    const T t45 = T(1) / D;
    const T t46 = t43 * t43;
    const T t47 = T(3) * t44 * t45 * a + T(2) * a_minus_b * t46 + T(2) * b * t41;
    const T t48 = t46 * t43;
    const T t49 = T(8) * b * t42 + T(5) * t47 * t45 * a + T(8) * a_minus_b * t48;
    const T t50 = T(1) / a;
    const T t51 = t46 * t46;
    const T t52 = t41 * t41;
    const T t53 = T(7) * t49 * t45 * a + T(48) * a_minus_b * t51 + T(48) * b * t52;
    const T t54 = b * t53 * t45 + T(48) * t52 - T(48) * t51;
    const T t55 = T(8) * t49 * t45 + T(2) * b * t50 * t54 - t53 * c * t45;
    const T t56 = b * t49 * t45 + T(8) * t42 - T(8) * t48;
    const T t57 = c * t50 * t54 - T(8) * t56 * t50 - T(2) * b * t55 * t50;
    const T t58 = T(6) * t47 * t45 + T(2) * b * t56 * t50 - c * t49 * t45;
    const T t59 = c * t55 * t50 + T(2) * b * t57 * t50 - T(8) * t58 * t50;
    const T t60 = b * t47 * t45 + T(2) * t41 - T(2) * t46;
    const T t61 = T(6) * t60 * t50 + T(2) * b * t58 * t50 - c * t56 * t50;
    const T t62 = T(8) * t61 * t50 + t57 * c * t50 - T(2) * t59 * b * t50;
    const T t63 = T(4) * t44 * t45 + T(2) * b * t60 * t50 - c * t47 * t45;
    const T t64 = T(6) * t63 * t50 + T(2) * b * t61 * t50 - c * t58 * t50;
    const T t65 = t59 * c * t50 + T(2) * t62 * b * t50 + T(8) * t64 * t50;
    const T t66 = t1 * delta_tau;
    const T t67 = t66 * t66;
    const T t68 = t2 * tau_lo;
    const T t69 = t2 * t2;
    const T t70 = t69 * t69;
    const T t71 = t70 * tau_lo;
    const T t72 = t68 * t68;
    const T t73 = t72 * tau_lo;
    const T t74 = t1 * t1;
    const T t75 = t74 * delta_tau;
    const T t76 = t43 - t3 - t44 * b * t45;
    const T t77 = T(4) * t50 * t76 + t60 * c * t50 - T(2) * t63 * b * t50;
    const T t78 = T(6) * t50 * t77 + c * t61 * t50 - T(2) * b * t64 * t50;
    const T t79 = T(2) * b * t65 * t50 - T(8) * t78 * t50 - t62 * c * t50;
    const T t80 = t67 * delta_tau;
    const T t81 = t74 * t74;
    const T t82 = t44 * c * t45 + T(2) * b * t50 * t76 - T(2) * J2;
    const T t83 = t63 * c * t50 + T(2) * b * t50 * t77 + T(4) * t82 * t50;
    const T t84 = T(2) * b * t78 * t50 + T(6) * t50 * t83 + t64 * c * t50;
    const T t85 = T(8) * t84 * t50 + t65 * c * t50 - T(2) * b * t79 * t50;
    const T t86 = t69 * tau_lo;
    const T t87 = t81 * delta_tau;
    F = (T(7) / T(32)) * t65 * t67 * t68 * t50 + (T(1) / T(384)) * t53 * t71 * t45 + (T(3) / T(128)) * delta_tau * t70 * t50 * t54 + (T(3) / T(32)) * t1 * t73 * t55 * t50 + (T(21) / T(64)) * t62 * t75 * t69 * t50 + (T(3) / T(32)) * t79 * t80 * t2 * t50 - (T(3) / T(128)) * t81 * tau_lo * t85 * t50 - (T(21) / T(64)) * t59 * t74 * t86 * t50 - (T(1) / T(384)) * (T(2) * b * t85 * t50 + t79 * c * t50 - T(8) * (c * t78 * t50 + T(6) * (c * t50 * t77 + T(4) * (t50 * (T(2) * b * J2 + log_ratio) + c * t50 * t76 - T(2) * b * t82 * t50) * t50 - T(2) * b * t50 * t83) * t50 - T(2) * b * t84 * t50) * t50) * t87 * t50 - (T(7) / T(32)) * t57 * t66 * t72 * t50;
    const T t88 = t51 * t43;
    const T t89 = t52 * t3;
    const T t90 = T(3) * t53 * t45 * a + T(128) * a_minus_b * t88 + T(128) * b * t89;
    const T t91 = T(128) * t88 - T(128) * t89 - b * t45 * t90;
    const T t92 = T(3) * c * t45 * t90 + T(6) * b * t50 * t91 - T(10) * t53 * t45;
    const T t93 = T(10) * t50 * t54 + T(3) * c * t50 * t91 - T(2) * b * t92 * t50;
    const T t94 = t92 * c * t50 + T(10) * t55 * t50 + T(2) * b * t50 * t93;
    const T t95 = c * t50 * t93 + T(10) * t57 * t50 - T(2) * b * t94 * t50;
    const T t96 = T(10) * t59 * t50 + T(2) * t95 * b * t50 + t94 * c * t50;
    const T t97 = T(2) * b * t96 * t50 - t95 * c * t50 - T(10) * t62 * t50;
    const T t98 = t96 * c * t50 + T(10) * t65 * t50 - T(2) * b * t50 * t97;
    G_ap = (T(1) / T(1280)) * t71 * t45 * t90 + (T(21) / T(640)) * t94 * t74 * t86 * t50 + (T(3) / T(1280)) * t81 * tau_lo * t50 * t98 + (T(1) / T(3840)) * t87 * t50 * (c * t50 * t97 + T(10) * t79 * t50 + T(2) * b * t50 * t98) + (T(7) / T(320)) * t66 * t72 * t50 * t93 - (T(3) / T(320)) * t80 * t2 * t50 * t97 - (T(7) / T(320)) * t96 * t67 * t68 * t50 - (T(21) / T(640)) * t95 * t75 * t69 * t50 - (T(9) / T(1280)) * delta_tau * t70 * t50 * t91 - (T(3) / T(320)) * t92 * t1 * t73 * t50;
    G_E = -(T(1) / T(1280)) * t50 * (T(210) * t59 * t75 * t69 * t50 + T(168) * t57 * t74 * t86 * t50 + T(3) * t87 * t85 * t50 + T(128) * t88 * (T(126) * t75 * t69 + T(126) * t74 * t86 + t87 + t71 + T(84) * t67 * t68 + T(36) * t80 * t2 + T(36) * t1 * t73 + T(9) * delta_tau * t70 + T(84) * t66 * t72 + T(9) * t81 * tau_lo) - T(24) * t79 * t81 * tau_lo * t50 - T(84) * t65 * t80 * t2 * t50 - T(128) * t89 * t71 - T(84) * t66 * t72 * t55 * t50 - T(3) * t53 * delta_tau * t70 * t45 - T(168) * t62 * t67 * t68 * t50 - T(24) * t1 * t73 * t50 * t54);
  }
  const T t99 = T(1) / a;
  const T t_star = b * t99;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t100 = sigma2 * sigma2;
  const T t101 = t100 * t100;
  const T t102 = t101 * sigma2;
  const T g_factor = -T(10) * length * t102;
  f = F * length * t102;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

}  // namespace skelconv::generated
