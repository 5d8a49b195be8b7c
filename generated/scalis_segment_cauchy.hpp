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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T log_ratio = log(q1 / c);
  T F;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = delta_tau * M_panels[1] + M_panels[0] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    F = (T(1) / T(2)) * delta_tau * (log_ratio + T(2) * J2 * b) / a + tau_lo * J2;
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
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
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - t5 * b * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t6 = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = tau_lo * M_panels[4] + delta_tau * M_panels[5] - t7 * b * t6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / D;
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = b * t11 + a * J2 + a_minus_b * t12;
    const T t14 = T(1) / a;
    G_ap = (T(1) / T(2)) * delta_tau * (t10 * t13 * b + t11 - t12) * t14 + (T(1) / T(2)) * tau_lo * t10 * t13;
    G_E = (T(1) / T(2)) * (tau_lo * t11 + delta_tau * J2 - t12 * (delta_tau + tau_lo)) * t14;
  }
  const T t15 = T(1) / a;
  const T t_star = t15 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t1 = T(1) / c;
  const T log_ratio = log(q1 * t1);
  T F;
  T G_ap;
  T G_E;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * tau_lo + M_panels[1] * delta_tau;
    const T t5 = M_panels[3] * tau_lo + M_panels[4] * delta_tau;
    G_ap = t5;
    const T t6 = T(1) / a;
    G_E = delta_tau * M_panels[5] + M_panels[4] * tau_lo - b * t6 * t5;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * tau_lo + M_panels[1] * delta_tau;
    const T t7 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t7;
    const T t8 = T(1) / a;
    G_E = M_panels[5] * delta_tau + M_panels[4] * tau_lo - b * t8 * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / a;
    F = (T(1) / T(2)) * (T(2) * b * J2 + log_ratio) * delta_tau * t11 + J2 * tau_lo;
    const T t12 = T(1) / q1;
    const T t13 = b * t1 + t12 * a_minus_b + J2 * a;
    const T t14 = T(1) / D;
    G_ap = (T(1) / T(2)) * delta_tau * t11 * (b * t13 * t14 + t1 - t12) + (T(1) / T(2)) * t13 * tau_lo * t14;
    G_E = -(T(1) / T(2)) * (t12 * (tau_lo + delta_tau) - t1 * tau_lo - J2 * delta_tau) * t11;
  }
  const T t15 = T(1) / a;
  const T t_star = b * t15;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(2) * length * sigma2;
  f = length * sigma2 * F;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = b * r1;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + a_minus_b * r0) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
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
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t2 + T(2) * delta_tau * tau_lo * M_panels[1] + t1 * M_panels[2];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t1 * M_panels[2] + T(2) * delta_tau * tau_lo * M_panels[1] + t2 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = a_minus_b * t15 + t16 * b;
    const T t18 = t15 - t14 * t17 * b - t16;
    const T t19 = T(1) / a;
    F = t2 * t14 * t17 + (J1 - T(2) * t18 * t19 * b - c * t14 * t17) * t1 * t19 - T(2) * delta_tau * tau_lo * t18 * t19;
  }
  f = length * sigma2 * F * in.sigma;
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
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
    const T t6 = T(2) * delta_tau * tau_lo * M_panels[5] + t2 * M_panels[4] + M_panels[6] * t1;
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = t2 * M_panels[5] + t1 * M_panels[7] + T(2) * M_panels[6] * delta_tau * tau_lo - t6 * t7 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t1 * M_panels[6] + T(2) * delta_tau * M_panels[5] * tau_lo + M_panels[4] * t2;
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[7] * t1 + M_panels[5] * t2 - t9 * t8 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / r1;
    const T t11 = T(1) / r0;
    const T t12 = t10 * a_minus_b + t11 * b;
    const T t13 = T(1) / D;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * t12 * t13 * a + t11 * t14 * b + t10 * a_minus_b * t15;
    const T t17 = t10 * t15 - t11 * t14 - t16 * t13 * b;
    const T t18 = T(1) / a;
    G_ap = (T(1) / T(3)) * t16 * t13 * t2 - (T(1) / T(3)) * (t16 * c * t13 + T(2) * t17 * t18 * b - T(3) * t12 * t13) * t1 * t18 - (T(2) / T(3)) * t17 * delta_tau * tau_lo * t18;
    const T t19 = t10 * t10;
    const T t20 = t19 * t10;
    const T t21 = t11 * t11;
    const T t22 = t21 * t11;
    G_E = -(T(1) / T(3)) * (T(2) * t1 * t18 * (t10 - t12 * t13 * b - t11) + (t2 + T(2) * delta_tau * tau_lo + t1) * t20 - t22 * t2 - T(2) * t12 * delta_tau * t13 * tau_lo) * t18;
  }
  const T t23 = T(1) / a;
  const T t_star = t23 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = a_minus_b * r0;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r1 * b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = a_minus_b * r0;
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
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * t1 + t2 * M_panels[0] + T(2) * M_panels[1] * tau_lo * delta_tau;
    const T t14 = M_panels[4] * t2 + t1 * M_panels[6] + T(2) * M_panels[5] * tau_lo * delta_tau;
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = M_panels[7] * t1 + M_panels[5] * t2 + T(2) * tau_lo * delta_tau * M_panels[6] - b * t15 * t14;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t2 + M_panels[2] * t1 + T(2) * tau_lo * delta_tau * M_panels[1];
    const T t16 = M_panels[6] * t1 + t2 * M_panels[4] + T(2) * M_panels[5] * tau_lo * delta_tau;
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[7] * t1 + M_panels[5] * t2 + T(2) * M_panels[6] * tau_lo * delta_tau - b * t16 * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / r1;
    const T t19 = T(1) / r0;
    const T t20 = t18 * a_minus_b + b * t19;
    const T t21 = T(1) / D;
    const T t22 = t20 * b * t21 + t19 - t18;
    const T t23 = T(1) / a;
    F = t20 * t2 * t21 + T(2) * t22 * tau_lo * delta_tau * t23 - (t20 * c * t21 - T(2) * b * t22 * t23 - J1) * t1 * t23;
    const T t24 = t19 * t19;
    const T t25 = t18 * t18;
    const T t26 = t18 * a_minus_b * t25 + T(2) * t20 * t21 * a + b * t24 * t19;
    const T t27 = t24 * t19 + b * t26 * t21 - t18 * t25;
    G_ap = (T(2) / T(3)) * t27 * tau_lo * delta_tau * t23 + (T(1) / T(3)) * t26 * t2 * t21 - (T(1) / T(3)) * t1 * (t26 * c * t21 - T(2) * t27 * b * t23 - T(3) * t20 * t21) * t23;
    const T t28 = t19 * t19;
    const T t29 = t28 * t19;
    const T t30 = t18 * t18;
    const T t31 = t30 * t18;
    G_E = (T(1) / T(3)) * t23 * (t2 * t29 + T(2) * t20 * tau_lo * delta_tau * t21 + T(2) * t22 * t1 * t23 - t31 * (T(2) * tau_lo * delta_tau + t2 + t1));
  }
  const T t32 = T(1) / a;
  const T t_star = b * t32;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(3) * sigma2 * in.sigma * length;
  f = sigma2 * F * in.sigma * length;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
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
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    F = T(3) * t1 * tau_lo * M_panels[2] + M_panels[3] * t7 + T(3) * delta_tau * t2 * M_panels[1] + M_panels[0] * t8;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t9 = t1 * delta_tau;
    const T t10 = t2 * tau_lo;
    F = T(3) * delta_tau * t2 * M_panels[1] + T(3) * M_panels[2] * t1 * tau_lo + t9 * M_panels[3] + t10 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / q1;
    const T t14 = t3 * b + t13 * a_minus_b + a * J2;
    const T t15 = T(1) / D;
    const T t16 = t2 * tau_lo;
    const T t17 = T(1) / a;
    const T t18 = t14 * t15 * b + t3 - t13;
    const T t19 = c * t14 * t15 - T(2) * t17 * t18 * b - T(2) * J2;
    const T t20 = t1 * delta_tau;
    F = (T(1) / T(2)) * t14 * t15 * t16 + (T(3) / T(2)) * delta_tau * t2 * t17 * t18 - (T(3) / T(2)) * t19 * t1 * tau_lo * t17 - (T(1) / T(2)) * t20 * t17 * (T(2) * t19 * t17 * b + c * t17 * t18 - t17 * (T(2) * J2 * b + log_ratio));
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
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t2 * tau_lo;
    const T t8 = T(3) * tau_lo * t1 * M_panels[7] + M_panels[8] * t6 + M_panels[5] * t7 + T(3) * t2 * delta_tau * M_panels[6];
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = T(3) * t2 * delta_tau * M_panels[7] + t7 * M_panels[6] + t6 * M_panels[9] + T(3) * M_panels[8] * tau_lo * t1 - t9 * t8 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t10 = t1 * delta_tau;
    const T t11 = t2 * tau_lo;
    const T t12 = M_panels[8] * t10 + T(3) * M_panels[7] * tau_lo * t1 + T(3) * t2 * delta_tau * M_panels[6] + M_panels[5] * t11;
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = t10 * M_panels[9] + t11 * M_panels[6] + T(3) * M_panels[8] * tau_lo * t1 + T(3) * M_panels[7] * t2 * delta_tau - t13 * t12 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / a;
    const T t17 = T(1) / D;
    const T t18 = T(1) / c;
    const T t19 = T(1) / q1;
    const T t20 = t18 * b + a_minus_b * t19 + a * J2;
    const T t21 = t19 * t19;
    const T t22 = t18 * t18;
    const T t23 = T(3) * t17 * a * t20 + T(2) * a_minus_b * t21 + T(2) * t22 * b;
    const T t24 = t17 * t23 * b + T(2) * t22 - T(2) * t21;
    const T t25 = T(2) * t16 * t24 * b + T(4) * t17 * t20 - c * t17 * t23;
    const T t26 = t2 * tau_lo;
    const T t27 = t17 * t20 * b + t18 - t19;
    const T t28 = t1 * delta_tau;
    G_ap = (T(3) / T(8)) * t2 * delta_tau * t16 * t24 + (T(3) / T(8)) * t25 * tau_lo * t1 * t16 + (T(1) / T(8)) * t26 * t17 * t23 + (T(1) / T(8)) * (T(4) * t27 * t16 + T(2) * t25 * t16 * b - c * t16 * t24) * t28 * t16;
    G_E = (T(1) / T(8)) * (T(3) * t2 * delta_tau * t17 * t20 + T(3) * t28 * (T(2) * t27 * t16 * b + T(2) * J2 - c * t17 * t20) * t16 + T(6) * t27 * tau_lo * t1 * t16 + T(2) * t22 * t26 - T(2) * (T(3) * tau_lo * t1 + t26 + t28 + T(3) * t2 * delta_tau) * t21) * t16;
  }
  const T t29 = T(1) / a;
  const T t_star = t29 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(4) * length * sigma2 * sigma2;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
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
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    F = t7 * M_panels[3] + t8 * M_panels[0] + T(3) * t1 * tau_lo * M_panels[2] + T(3) * M_panels[1] * delta_tau * t2;
    const T t9 = t8 * M_panels[5] + T(3) * delta_tau * t2 * M_panels[6] + T(3) * M_panels[7] * t1 * tau_lo + t7 * M_panels[8];
    G_ap = t9;
    const T t10 = T(1) / a;
    G_E = T(3) * M_panels[7] * delta_tau * t2 + t7 * M_panels[9] + t8 * M_panels[6] + T(3) * t1 * tau_lo * M_panels[8] - t10 * b * t9;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t11 = t2 * tau_lo;
    const T t12 = t1 * delta_tau;
    F = M_panels[0] * t11 + T(3) * t1 * tau_lo * M_panels[2] + T(3) * delta_tau * t2 * M_panels[1] + t12 * M_panels[3];
    const T t13 = T(3) * t1 * M_panels[7] * tau_lo + t11 * M_panels[5] + T(3) * delta_tau * t2 * M_panels[6] + t12 * M_panels[8];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = t11 * M_panels[6] + T(3) * delta_tau * M_panels[7] * t2 + t12 * M_panels[9] + T(3) * t1 * tau_lo * M_panels[8] - t14 * t13 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / q1;
    const T t18 = J2 * a + t3 * b + a_minus_b * t17;
    const T t19 = t2 * tau_lo;
    const T t20 = T(1) / D;
    const T t21 = T(1) / a;
    const T t22 = t17 - t3 - t18 * t20 * b;
    const T t23 = T(2) * J2 - c * t18 * t20 - T(2) * t22 * t21 * b;
    const T t24 = t1 * delta_tau;
    F = (T(1) / T(2)) * t18 * t19 * t20 + (T(3) / T(2)) * t1 * tau_lo * t21 * t23 + (T(1) / T(2)) * t24 * t21 * (t21 * (T(2) * J2 * b + log_ratio) + T(2) * t21 * b * t23 + c * t22 * t21) - (T(3) / T(2)) * t22 * delta_tau * t2 * t21;
    const T t25 = t17 * t17;
    const T t26 = t3 * t3;
    const T t27 = T(2) * a_minus_b * t25 + T(2) * t26 * b + T(3) * t18 * t20 * a;
    const T t28 = t27 * t20 * b + T(2) * t26 - T(2) * t25;
    const T t29 = T(2) * t21 * t28 * b + T(4) * t18 * t20 - t27 * c * t20;
    G_ap = (T(3) / T(8)) * t1 * tau_lo * t21 * t29 + (T(1) / T(8)) * t24 * t21 * (T(2) * t21 * t29 * b - T(4) * t22 * t21 - c * t21 * t28) + (T(3) / T(8)) * delta_tau * t2 * t21 * t28 + (T(1) / T(8)) * t27 * t19 * t20;
    G_E = (T(1) / T(8)) * t21 * (T(2) * t26 * t19 + T(3) * t18 * delta_tau * t2 * t20 + T(3) * t24 * t21 * t23 - T(6) * t22 * t1 * tau_lo * t21 - T(2) * (T(3) * t1 * tau_lo + t19 + t24 + T(3) * delta_tau * t2) * t25);
  }
  const T t30 = T(1) / a;
  const T t_star = t30 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t31 = sigma2 * sigma2;
  const T g_factor = -T(4) * length * t31;
  f = length * t31 * F;
  grad[0] = g_factor * (G_ap * foot0 - G_E * ab0);
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
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
  const T t11 = T(4) * D - a * a;
  const T t12 = -a_minus_b * b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t2 * tau_lo;
    const T t16 = t1 * t1;
    const T t17 = t2 * t2;
    F = T(6) * M_panels[2] * t1 * t2 + T(4) * t14 * tau_lo * M_panels[3] + T(4) * delta_tau * t15 * M_panels[1] + t16 * M_panels[4] + t17 * M_panels[0];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t1 * delta_tau;
    const T t19 = t2 * t2;
    const T t20 = t2 * tau_lo;
    const T t21 = t1 * t1;
    F = T(4) * M_panels[3] * t18 * tau_lo + M_panels[0] * t19 + T(4) * delta_tau * t20 * M_panels[1] + t21 * M_panels[4] + T(6) * t1 * t2 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / a;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = T(1) / D;
    const T t28 = a_minus_b * t25 + t23 * b;
    const T t29 = a_minus_b * t26 * t25 + T(2) * t27 * a * t28 + t24 * t23 * b;
    const T t30 = t24 * t23 + t29 * t27 * b - t26 * t25;
    const T t31 = T(2) * t22 * t30 * b + T(3) * t27 * t28 - c * t29 * t27;
    const T t32 = t23 + t27 * t28 * b - t25;
    const T t33 = T(2) * t31 * t22 * b + T(3) * t22 * t32 - c * t22 * t30;
    const T t34 = t1 * delta_tau;
    const T t35 = t2 * tau_lo;
    const T t36 = t2 * t2;
    const T t37 = t1 * t1;
    F = (T(4) / T(3)) * t33 * t34 * tau_lo * t22 + T(2) * t31 * t1 * t2 * t22 + (T(4) / T(3)) * delta_tau * t35 * t22 * t30 + (T(1) / T(3)) * t29 * t27 * t36 - (T(1) / T(3)) * t37 * t22 * (t31 * c * t22 - T(3) * t22 * (J1 + T(2) * t22 * t32 * b - c * t27 * t28) - T(2) * t33 * t22 * b);
  }
  f = in.sigma * length * sigma2 * sigma2 * F;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
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
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t1 * t1;
    const T t8 = t1 * delta_tau;
    const T t9 = t2 * t2;
    const T t10 = T(4) * delta_tau * t6 * M_panels[7] + T(6) * t1 * t2 * M_panels[8] + t7 * M_panels[10] + T(4) * M_panels[9] * t8 * tau_lo + M_panels[6] * t9;
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = T(4) * t8 * M_panels[10] * tau_lo + t7 * M_panels[11] + T(6) * M_panels[9] * t1 * t2 + t9 * M_panels[7] + T(4) * delta_tau * t6 * M_panels[8] - t11 * t10 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t1 * delta_tau;
    const T t13 = t1 * t1;
    const T t14 = t2 * t2;
    const T t15 = t2 * tau_lo;
    const T t16 = T(4) * M_panels[9] * t12 * tau_lo + M_panels[10] * t13 + M_panels[6] * t14 + T(4) * M_panels[7] * delta_tau * t15 + T(6) * t1 * t2 * M_panels[8];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[7] * t14 + T(6) * M_panels[9] * t1 * t2 + T(4) * delta_tau * t15 * M_panels[8] + T(4) * M_panels[10] * t12 * tau_lo + t13 * M_panels[11] - t16 * t17 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / D;
    const T t22 = T(1) / r1;
    const T t23 = t22 * a_minus_b + t18 * b;
    const T t24 = t22 * t22;
    const T t25 = T(2) * t23 * t21 * a + t18 * t19 * b + t22 * a_minus_b * t24;
    const T t26 = t24 * t24;
    const T t27 = T(4) * t21 * t25 * a + T(3) * t22 * a_minus_b * t26 + T(3) * t18 * t20 * b;
    const T t28 = T(3) * t18 * t20 + t21 * t27 * b - T(3) * t22 * t26;
    const T t29 = t2 * tau_lo;
    const T t30 = T(1) / a;
    const T t31 = T(2) * t28 * t30 * b + T(5) * t21 * t25 - c * t21 * t27;
    const T t32 = t2 * t2;
    const T t33 = t1 * delta_tau;
    const T t34 = t22 * t24 - t21 * t25 * b - t18 * t19;
    const T t35 = c * t28 * t30 + T(5) * t30 * t34 - T(2) * t30 * t31 * b;
    const T t36 = T(2) * t30 * b * t34 + c * t21 * t25 - T(3) * t23 * t21;
    const T t37 = t1 * t1;
    G_ap = (T(4) / T(15)) * t28 * delta_tau * t29 * t30 + (T(2) / T(5)) * t1 * t2 * t30 * t31 + (T(1) / T(15)) * t21 * t27 * t32 - (T(4) / T(15)) * t33 * tau_lo * t35 * t30 - (T(1) / T(15)) * (c * t30 * t31 + T(5) * t36 * t30 + T(2) * t35 * t30 * b) * t37 * t30;
    const T t38 = t18 * t18;
    const T t39 = t38 * t38;
    const T t40 = t39 * t18;
    const T t41 = t22 * t22;
    const T t42 = t41 * t41;
    const T t43 = t42 * t22;
    G_E = (T(1) / T(15)) * (T(3) * t40 * t32 + T(4) * delta_tau * t21 * t29 * t25 + T(4) * t37 * (c * t30 * t34 - T(3) * (t22 - t18 - t23 * t21 * b) * t30 - T(2) * t36 * t30 * b) * t30 - T(3) * t43 * (t37 + T(6) * t1 * t2 + T(4) * t33 * tau_lo + T(4) * delta_tau * t29 + t32) - T(12) * t36 * t33 * tau_lo * t30 - T(12) * t1 * t2 * t30 * t34) * t30;
  }
  const T t44 = T(1) / a;
  const T t_star = t44 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(5) * in.sigma * length * sigma2 * sigma2;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
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
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = r1 * b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r0 * a_minus_b) * t5 * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r1 * b;
    X = -(a_minus_b - b) * t7 / (t8 - r0 * a_minus_b);
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
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t2 * tau_lo;
    const T t17 = t1 * t1;
    F = T(4) * tau_lo * t14 * M_panels[3] + t15 * M_panels[0] + T(4) * t16 * delta_tau * M_panels[1] + T(6) * t2 * M_panels[2] * t1 + t17 * M_panels[4];
    const T t18 = t17 * M_panels[10] + t15 * M_panels[6] + T(4) * t16 * delta_tau * M_panels[7] + T(4) * tau_lo * t14 * M_panels[9] + T(6) * M_panels[8] * t2 * t1;
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = t15 * M_panels[7] + t17 * M_panels[11] + T(4) * tau_lo * t14 * M_panels[10] + T(6) * t2 * t1 * M_panels[9] + T(4) * M_panels[8] * t16 * delta_tau - t19 * b * t18;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * delta_tau;
    const T t21 = t2 * tau_lo;
    const T t22 = t2 * t2;
    const T t23 = t1 * t1;
    F = T(4) * tau_lo * M_panels[3] * t20 + T(4) * t21 * delta_tau * M_panels[1] + t22 * M_panels[0] + t23 * M_panels[4] + T(6) * t2 * t1 * M_panels[2];
    const T t24 = T(4) * M_panels[9] * tau_lo * t20 + T(4) * t21 * delta_tau * M_panels[7] + t22 * M_panels[6] + t23 * M_panels[10] + T(6) * t2 * t1 * M_panels[8];
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(4) * tau_lo * t20 * M_panels[10] + T(4) * t21 * delta_tau * M_panels[8] + t23 * M_panels[11] + T(6) * M_panels[9] * t2 * t1 + t22 * M_panels[7] - t25 * t24 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = t1 * t1;
    const T t27 = T(1) / a;
    const T t28 = T(1) / D;
    const T t29 = T(1) / r0;
    const T t30 = T(1) / r1;
    const T t31 = t29 * b + t30 * a_minus_b;
    const T t32 = t30 * t30;
    const T t33 = t29 * t29;
    const T t34 = t33 * t29 * b + T(2) * t28 * a * t31 + t30 * a_minus_b * t32;
    const T t35 = t30 * t32 - t33 * t29 - t34 * t28 * b;
    const T t36 = T(3) * t28 * t31 - T(2) * t27 * b * t35 - c * t34 * t28;
    const T t37 = t30 - t29 - t28 * t31 * b;
    const T t38 = T(2) * t27 * t36 * b + c * t27 * t35 - T(3) * t37 * t27;
    const T t39 = t2 * t2;
    const T t40 = t1 * delta_tau;
    const T t41 = t2 * tau_lo;
    F = (T(1) / T(3)) * t26 * t27 * (T(2) * t27 * t38 * b + T(3) * (J1 - T(2) * t37 * t27 * b - c * t28 * t31) * t27 - c * t27 * t36) + (T(1) / T(3)) * t39 * t34 * t28 + (T(4) / T(3)) * tau_lo * t40 * t27 * t38 + T(2) * t2 * t1 * t27 * t36 - (T(4) / T(3)) * t41 * delta_tau * t27 * t35;
    const T t42 = t32 * t32;
    const T t43 = t33 * t33;
    const T t44 = T(4) * t34 * t28 * a + T(3) * t30 * a_minus_b * t42 + T(3) * t43 * t29 * b;
    const T t45 = t44 * t28 * b + T(3) * t43 * t29 - T(3) * t30 * t42;
    const T t46 = T(5) * t34 * t28 + T(2) * t27 * t45 * b - c * t44 * t28;
    const T t47 = T(5) * t27 * t35 + c * t27 * t45 - T(2) * t46 * t27 * b;
    G_ap = (T(1) / T(15)) * t44 * t39 * t28 + (T(1) / T(15)) * t26 * (T(5) * t27 * t36 - T(2) * t47 * t27 * b - t46 * c * t27) * t27 + (T(2) / T(5)) * t46 * t2 * t1 * t27 + (T(4) / T(15)) * t41 * delta_tau * t27 * t45 - (T(4) / T(15)) * tau_lo * t40 * t47 * t27;
    const T t48 = t29 * t29;
    const T t49 = t48 * t48;
    const T t50 = t49 * t29;
    const T t51 = t30 * t30;
    const T t52 = t51 * t51;
    const T t53 = t52 * t30;
    G_E = (T(1) / T(15)) * (T(4) * t41 * t34 * delta_tau * t28 + T(4) * t26 * t27 * t38 + T(12) * tau_lo * t40 * t27 * t36 + T(3) * t39 * t50 - T(3) * (t26 + T(4) * tau_lo * t40 + T(4) * t41 * delta_tau + t39 + T(6) * t2 * t1) * t53 - T(12) * t2 * t1 * t27 * t35) * t27;
  }
  const T t54 = T(1) / a;
  const T t_star = t54 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t55 = sigma2 * sigma2;
  const T g_factor = -T(5) * length * t55 * in.sigma;
  f = length * t55 * F * in.sigma;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -a_minus_b * b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t1 * t1;
    const T t9 = t2 * tau_lo;
    const T t10 = t2 * t2;
    const T t11 = t8 * delta_tau;
    const T t12 = t10 * tau_lo;
    F = T(10) * M_panels[3] * t2 * t7 + T(5) * tau_lo * t8 * M_panels[4] + T(10) * t9 * t1 * M_panels[2] + T(5) * t10 * delta_tau * M_panels[1] + t11 * M_panels[5] + M_panels[0] * t12;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * delta_tau;
    const T t14 = t2 * tau_lo;
    const T t15 = t1 * t1;
    const T t16 = t15 * delta_tau;
    const T t17 = t2 * t2;
    const T t18 = t17 * tau_lo;
    F = T(10) * M_panels[3] * t2 * t13 + T(10) * t14 * t1 * M_panels[2] + t16 * M_panels[5] + M_panels[0] * t18 + T(5) * t17 * delta_tau * M_panels[1] + T(5) * tau_lo * t15 * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, c_minus_b);
    const T t21 = t2 * t2;
    const T t22 = T(1) / a;
    const T t23 = t3 * t3;
    const T t24 = T(1) / D;
    const T t25 = T(1) / q1;
    const T t26 = t25 * t25;
    const T t27 = a_minus_b * t25 + t3 * b + a * J2;
    const T t28 = T(2) * t23 * b + T(2) * a_minus_b * t26 + T(3) * t27 * a * t24;
    const T t29 = T(2) * t23 + t24 * b * t28 - T(2) * t26;
    const T t30 = t21 * tau_lo;
    const T t31 = t2 * tau_lo;
    const T t32 = T(2) * t22 * b * t29 + T(4) * t27 * t24 - c * t24 * t28;
    const T t33 = t25 - t27 * t24 * b - t3;
    const T t34 = T(4) * t22 * t33 + c * t22 * t29 - T(2) * t22 * b * t32;
    const T t35 = T(2) * t22 * t33 * b + c * t27 * t24 - T(2) * J2;
    const T t36 = T(2) * t34 * t22 * b + c * t22 * t32 + T(4) * t35 * t22;
    const T t37 = t1 * t1;
    const T t38 = t37 * delta_tau;
    const T t39 = t1 * delta_tau;
    F = (T(5) / T(8)) * t21 * delta_tau * t22 * t29 + (T(1) / T(8)) * t30 * t24 * t28 + (T(5) / T(4)) * t31 * t1 * t22 * t32 - (T(5) / T(8)) * t36 * tau_lo * t37 * t22 - (T(1) / T(8)) * t38 * t22 * (T(2) * t36 * t22 * b - T(4) * t22 * (t22 * (T(2) * J2 * b + log_ratio) + c * t22 * t33 - T(2) * t35 * t22 * b) - c * t34 * t22) - (T(5) / T(4)) * t34 * t2 * t39 * t22;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t2 * t2;
    const T t8 = t7 * tau_lo;
    const T t9 = t1 * t1;
    const T t10 = t9 * delta_tau;
    const T t11 = t1 * delta_tau;
    const T t12 = T(10) * t1 * t6 * M_panels[9] + M_panels[7] * t8 + t10 * M_panels[12] + T(5) * M_panels[11] * t9 * tau_lo + T(10) * M_panels[10] * t11 * t2 + T(5) * M_panels[8] * delta_tau * t7;
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = M_panels[8] * t8 + T(10) * M_panels[11] * t11 * t2 + T(5) * t9 * M_panels[12] * tau_lo + T(5) * delta_tau * t7 * M_panels[9] + T(10) * M_panels[10] * t1 * t6 + M_panels[13] * t10 - b * t12 * t13;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t1 * t1;
    const T t17 = t16 * delta_tau;
    const T t18 = t2 * tau_lo;
    const T t19 = t15 * tau_lo;
    const T t20 = T(10) * M_panels[10] * t14 * t2 + T(5) * delta_tau * t15 * M_panels[8] + M_panels[12] * t17 + T(5) * t16 * tau_lo * M_panels[11] + T(10) * M_panels[9] * t1 * t18 + M_panels[7] * t19;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = M_panels[13] * t17 + T(10) * M_panels[10] * t1 * t18 + t19 * M_panels[8] + T(5) * M_panels[12] * t16 * tau_lo + T(5) * M_panels[9] * delta_tau * t15 + T(10) * t14 * t2 * M_panels[11] - b * t20 * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, c_minus_b) * t23;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(1) / c;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = J2 * a + b * t27 + t24 * a_minus_b;
    const T t31 = T(1) / D;
    const T t32 = T(2) * t25 * a_minus_b + T(2) * b * t28 + T(3) * t30 * t31 * a;
    const T t33 = T(8) * t26 * a_minus_b + T(8) * b * t29 + T(5) * t32 * t31 * a;
    const T t34 = b * t33 * t31 + T(8) * t29 - T(8) * t26;
    const T t35 = t2 * t2;
    const T t36 = T(1) / a;
    const T t37 = T(6) * t32 * t31 + T(2) * b * t34 * t36 - c * t33 * t31;
    const T t38 = t2 * tau_lo;
    const T t39 = t35 * tau_lo;
    const T t40 = t1 * t1;
    const T t41 = T(2) * t25 - b * t32 * t31 - T(2) * t28;
    const T t42 = T(4) * t30 * t31 - T(2) * b * t36 * t41 - t32 * c * t31;
    const T t43 = T(6) * t36 * t41 + c * t34 * t36 - T(2) * b * t37 * t36;
    const T t44 = T(6) * t42 * t36 - t37 * c * t36 - T(2) * b * t43 * t36;
    const T t45 = t40 * delta_tau;
    const T t46 = b * t30 * t31 + t27 - t24;
    const T t47 = T(4) * t46 * t36 + T(2) * b * t42 * t36 + c * t36 * t41;
    const T t48 = t1 * delta_tau;
    G_ap = (T(5) / T(48)) * t34 * delta_tau * t35 * t36 + (T(5) / T(24)) * t37 * t1 * t38 * t36 + (T(1) / T(48)) * t33 * t39 * t31 + (T(5) / T(48)) * t40 * tau_lo * t36 * t44 + (T(1) / T(48)) * t45 * (T(2) * b * t36 * t44 + c * t43 * t36 + T(6) * t47 * t36) * t36 - (T(5) / T(24)) * t48 * t43 * t2 * t36;
    G_E = (T(1) / T(48)) * (T(5) * t45 * (T(2) * b * t47 * t36 + T(4) * (T(2) * J2 + T(2) * b * t46 * t36 - c * t30 * t31) * t36 - c * t42 * t36) * t36 + T(20) * t47 * t40 * tau_lo * t36 + T(8) * t29 * t39 + T(5) * t32 * delta_tau * t35 * t31 + T(30) * t48 * t2 * t42 * t36 - T(20) * t1 * t38 * t36 * t41 - T(8) * t26 * (T(10) * t48 * t2 + T(5) * delta_tau * t35 + T(10) * t1 * t38 + t45 + T(5) * t40 * tau_lo + t39)) * t36;
  }
  const T t49 = T(1) / a;
  const T t_star = b * t49;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t50 = sigma2 * sigma2;
  const T t51 = t50 * sigma2;
  const T g_factor = -T(6) * length * t51;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * tau_hi * sigma2;
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
    const T t8 = t7 * tau_lo;
    const T t9 = t2 * tau_lo;
    const T t10 = t1 * delta_tau;
    const T t11 = t1 * t1;
    const T t12 = t11 * delta_tau;
    F = t8 * M_panels[0] + T(10) * t9 * t1 * M_panels[2] + T(10) * t2 * t10 * M_panels[3] + T(5) * t7 * delta_tau * M_panels[1] + T(5) * tau_lo * t11 * M_panels[4] + t12 * M_panels[5];
    const T t13 = T(5) * M_panels[11] * tau_lo * t11 + t12 * M_panels[12] + T(10) * t9 * t1 * M_panels[9] + t8 * M_panels[7] + T(10) * t2 * t10 * M_panels[10] + T(5) * t7 * delta_tau * M_panels[8];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = T(10) * M_panels[11] * t2 * t10 + T(10) * t9 * t1 * M_panels[10] + T(5) * t7 * delta_tau * M_panels[9] + t8 * M_panels[8] + t12 * M_panels[13] + T(5) * tau_lo * t11 * M_panels[12] - t14 * b * t13;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t15 = t2 * t2;
    const T t16 = t1 * t1;
    const T t17 = t16 * delta_tau;
    const T t18 = t15 * tau_lo;
    const T t19 = t1 * delta_tau;
    const T t20 = t2 * tau_lo;
    F = T(5) * t15 * delta_tau * M_panels[1] + t17 * M_panels[5] + M_panels[0] * t18 + T(10) * t2 * t19 * M_panels[3] + T(5) * tau_lo * t16 * M_panels[4] + T(10) * t20 * t1 * M_panels[2];
    const T t21 = T(10) * t2 * t19 * M_panels[10] + T(10) * t20 * t1 * M_panels[9] + t17 * M_panels[12] + T(5) * tau_lo * t16 * M_panels[11] + T(5) * t15 * delta_tau * M_panels[8] + t18 * M_panels[7];
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = t18 * M_panels[8] + T(10) * t2 * t19 * M_panels[11] + T(5) * t15 * delta_tau * M_panels[9] + t17 * M_panels[13] + T(10) * t20 * t1 * M_panels[10] + T(5) * tau_lo * t16 * M_panels[12] - t22 * t21 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = t24 * atan2(t23, c_minus_b);
    const T t25 = t3 * t3;
    const T t26 = T(1) / q1;
    const T t27 = t26 * t26;
    const T t28 = T(1) / D;
    const T t29 = a * J2 + a_minus_b * t26 + b * t3;
    const T t30 = T(2) * b * t25 + T(2) * a_minus_b * t27 + T(3) * t28 * a * t29;
    const T t31 = t2 * t2;
    const T t32 = t31 * tau_lo;
    const T t33 = t1 * delta_tau;
    const T t34 = T(1) / a;
    const T t35 = t3 + t28 * b * t29 - t26;
    const T t36 = T(2) * t27 - t30 * t28 * b - T(2) * t25;
    const T t37 = t30 * t28 * c + T(2) * t34 * t36 * b - T(4) * t28 * t29;
    const T t38 = T(4) * t34 * t35 + t34 * t36 * c - T(2) * t34 * b * t37;
    const T t39 = t1 * t1;
    const T t40 = t28 * c * t29 - T(2) * t34 * b * t35 - T(2) * J2;
    const T t41 = T(2) * t34 * b * t38 + t34 * t37 * c - T(4) * t34 * t40;
    const T t42 = t2 * tau_lo;
    const T t43 = t39 * delta_tau;
    F = (T(1) / T(8)) * t30 * t32 * t28 + (T(5) / T(4)) * t2 * t33 * t34 * t38 + (T(5) / T(8)) * tau_lo * t39 * t34 * t41 - (T(5) / T(4)) * t42 * t1 * t34 * t37 - (T(1) / T(8)) * t43 * t34 * (T(4) * t34 * (t34 * c * t35 + T(2) * t34 * b * t40 - t34 * (log_ratio + T(2) * b * J2)) + t34 * c * t38 - T(2) * t34 * b * t41) - (T(5) / T(8)) * t31 * delta_tau * t34 * t36;
    const T t44 = t27 * t26;
    const T t45 = t25 * t3;
    const T t46 = T(8) * b * t45 + T(5) * t30 * t28 * a + T(8) * a_minus_b * t44;
    const T t47 = T(8) * t44 - T(8) * t45 - t46 * t28 * b;
    const T t48 = T(2) * t34 * b * t47 + t46 * t28 * c - T(6) * t30 * t28;
    const T t49 = t34 * c * t47 - T(6) * t34 * t36 - T(2) * t34 * b * t48;
    const T t50 = T(6) * t34 * t37 - T(2) * t34 * b * t49 - t34 * t48 * c;
    G_ap = (T(5) / T(24)) * t2 * t33 * t34 * t49 + (T(1) / T(48)) * t32 * t46 * t28 - (T(1) / T(48)) * t43 * t34 * (t34 * t49 * c + T(2) * t34 * b * t50 - T(6) * t34 * t38) - (T(5) / T(48)) * tau_lo * t39 * t34 * t50 - (T(5) / T(24)) * t42 * t1 * t34 * t48 - (T(5) / T(48)) * t31 * delta_tau * t34 * t47;
    G_E = (T(1) / T(48)) * t34 * (T(20) * tau_lo * t39 * t34 * t38 + T(5) * t43 * t34 * t41 + T(5) * t30 * t31 * delta_tau * t28 + T(8) * t32 * t45 - T(30) * t2 * t33 * t34 * t37 - T(8) * (T(5) * t31 * delta_tau + t43 + T(5) * tau_lo * t39 + T(10) * t2 * t33 + T(10) * t42 * t1 + t32) * t44 - T(20) * t42 * t1 * t34 * t36);
  }
  const T t51 = T(1) / a;
  const T t_star = t51 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t52 = sigma2 * sigma2;
  const T t53 = t52 * sigma2;
  const T g_factor = -T(6) * t53 * length;
  f = t53 * F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
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
    X = t7 * (b - a_minus_b) / (t8 - r0 * a_minus_b);
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
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t2 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t1 * t1;
    const T t19 = t18 * delta_tau;
    const T t20 = t1 * delta_tau;
    const T t21 = t20 * t20;
    F = T(6) * M_panels[1] * delta_tau * t15 + M_panels[0] * t17 + T(6) * M_panels[5] * t19 * tau_lo + T(15) * M_panels[2] * t1 * t14 + t21 * M_panels[6] + T(20) * t20 * t16 * M_panels[3] + T(15) * M_panels[4] * t18 * t2;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t2 * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t2 * t2;
    const T t27 = t26 * tau_lo;
    const T t28 = t1 * t1;
    const T t29 = t28 * delta_tau;
    F = t23 * M_panels[6] + M_panels[0] * t25 + T(15) * M_panels[2] * t1 * t26 + T(6) * M_panels[1] * delta_tau * t27 + T(15) * M_panels[4] * t28 * t2 + T(20) * t22 * t24 * M_panels[3] + T(6) * M_panels[5] * t29 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = T(1) / a;
    const T t31 = T(1) / r1;
    const T t32 = t31 * t31;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = T(1) / D;
    const T t36 = t31 * a_minus_b + t33 * b;
    const T t37 = T(2) * t35 * a * t36 + t32 * t31 * a_minus_b + t34 * t33 * b;
    const T t38 = t32 * t31 - t34 * t33 - t35 * b * t37;
    const T t39 = t34 * t34;
    const T t40 = t32 * t32;
    const T t41 = T(4) * t35 * a * t37 + T(3) * t39 * t33 * b + T(3) * t40 * t31 * a_minus_b;
    const T t42 = t35 * b * t41 + T(3) * t39 * t33 - T(3) * t40 * t31;
    const T t43 = T(2) * t30 * t42 * b + T(5) * t35 * t37 - c * t35 * t41;
    const T t44 = T(5) * t30 * t38 + c * t30 * t42 - T(2) * t43 * t30 * b;
    const T t45 = T(3) * t35 * t36 - T(2) * t30 * t38 * b - c * t35 * t37;
    const T t46 = t31 - t35 * b * t36 - t33;
    const T t47 = T(2) * t30 * b * t45 + c * t30 * t38 - T(3) * t30 * t46;
    const T t48 = T(2) * t44 * t30 * b + c * t43 * t30 - T(5) * t30 * t45;
    const T t49 = c * t44 * t30 + T(5) * t47 * t30 - T(2) * t48 * t30 * b;
    const T t50 = t1 * delta_tau;
    const T t51 = t50 * t50;
    const T t52 = t1 * t1;
    const T t53 = t52 * delta_tau;
    const T t54 = t2 * t2;
    const T t55 = t2 * tau_lo;
    const T t56 = t55 * t55;
    const T t57 = t54 * tau_lo;
    F = (T(1) / T(15)) * (T(2) * t30 * b * t49 + c * t48 * t30 - T(5) * (c * t30 * t45 + T(3) * t30 * (T(2) * t30 * b * t46 + c * t35 * t36 - J1) - T(2) * t47 * t30 * b) * t30) * t30 * t51 + (T(2) / T(5)) * t30 * t53 * tau_lo * t49 + t43 * t30 * t1 * t54 + (T(1) / T(15)) * t35 * t56 * t41 + (T(2) / T(5)) * t30 * t42 * delta_tau * t57 - (T(4) / T(3)) * t44 * t30 * t50 * t55 - t48 * t30 * t52 * t2;
  }
  const T t58 = sigma2 * sigma2;
  const T t59 = t58 * sigma2;
  f = t59 * length * in.sigma * F;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
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
    const T t6 = t2 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t1 * t1;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * t2;
    const T t11 = t10 * tau_lo;
    const T t12 = t1 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = M_panels[8] * t7 + T(6) * M_panels[13] * tau_lo * t9 + T(6) * M_panels[9] * t11 * delta_tau + T(15) * t10 * t1 * M_panels[10] + T(15) * M_panels[12] * t2 * t8 + M_panels[14] * t13 + T(20) * M_panels[11] * t6 * t12;
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(15) * M_panels[11] * t10 * t1 + T(20) * M_panels[12] * t6 * t12 + M_panels[15] * t13 + T(15) * M_panels[13] * t2 * t8 + T(6) * M_panels[14] * tau_lo * t9 + T(6) * t11 * delta_tau * M_panels[10] + M_panels[9] * t7 - t14 * b * t15;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t2 * t2;
    const T t17 = t16 * tau_lo;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t1 * t1;
    const T t23 = t22 * delta_tau;
    const T t24 = T(6) * M_panels[9] * t17 * delta_tau + M_panels[14] * t19 + M_panels[8] * t21 + T(15) * M_panels[12] * t2 * t22 + T(20) * M_panels[11] * t20 * t18 + T(15) * M_panels[10] * t16 * t1 + T(6) * M_panels[13] * tau_lo * t23;
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(15) * M_panels[13] * t2 * t22 + T(20) * M_panels[12] * t20 * t18 + M_panels[9] * t21 + T(15) * M_panels[11] * t16 * t1 + T(6) * M_panels[14] * tau_lo * t23 + T(6) * M_panels[10] * t17 * delta_tau + M_panels[15] * t19 - b * t24 * t25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = T(1) / r0;
    const T t30 = t29 * t29;
    const T t31 = t26 * a_minus_b + b * t29;
    const T t32 = T(1) / D;
    const T t33 = b * t29 * t30 + T(2) * t31 * t32 * a + t27 * t26 * a_minus_b;
    const T t34 = t30 * t30;
    const T t35 = T(3) * t28 * t26 * a_minus_b + T(4) * t33 * t32 * a + T(3) * b * t29 * t34;
    const T t36 = t28 * t27;
    const T t37 = t34 * t30;
    const T t38 = T(2) * t35 * t32 * a + T(5) * t36 * t26 * a_minus_b + T(5) * b * t29 * t37;
    const T t39 = t2 * tau_lo;
    const T t40 = t39 * t39;
    const T t41 = b * t38 * t32 + T(5) * t29 * t37 - T(5) * t36 * t26;
    const T t42 = t2 * t2;
    const T t43 = t42 * tau_lo;
    const T t44 = T(1) / a;
    const T t45 = T(3) * t38 * c * t32 - T(7) * t35 * t32 - T(6) * t41 * b * t44;
    const T t46 = t35 * b * t32 + T(3) * t29 * t34 - T(3) * t28 * t26;
    const T t47 = T(2) * b * t45 * t44 + T(3) * t41 * c * t44 - T(7) * t46 * t44;
    const T t48 = T(5) * t33 * t32 + T(2) * b * t46 * t44 - t35 * c * t32;
    const T t49 = T(2) * t47 * b * t44 - T(7) * t48 * t44 - t45 * c * t44;
    const T t50 = t29 * t30 + b * t33 * t32 - t27 * t26;
    const T t51 = c * t46 * t44 - T(2) * b * t48 * t44 - T(5) * t50 * t44;
    const T t52 = t47 * c * t44 - T(2) * b * t49 * t44 - T(7) * t51 * t44;
    const T t53 = t1 * t1;
    const T t54 = t53 * delta_tau;
    const T t55 = T(3) * t31 * t32 + T(2) * b * t50 * t44 - t33 * c * t32;
    const T t56 = T(5) * t55 * t44 - T(2) * b * t51 * t44 - c * t48 * t44;
    const T t57 = t1 * delta_tau;
    const T t58 = t57 * t57;
    G_ap = (T(1) / T(35)) * t38 * t40 * t32 + (T(6) / T(35)) * t41 * t43 * delta_tau * t44 + (T(2) / T(35)) * t52 * tau_lo * t54 * t44 + (T(1) / T(105)) * (T(2) * t52 * b * t44 + c * t49 * t44 + T(7) * t56 * t44) * t58 * t44 - (T(1) / T(7)) * t49 * t2 * t53 * t44 - (T(1) / T(7)) * t45 * t42 * t1 * t44 - (T(4) / T(21)) * t47 * t39 * t57 * t44;
    const T t59 = t26 * t26;
    const T t60 = t59 * t26;
    const T t61 = t60 * t60;
    const T t62 = t61 * t26;
    const T t63 = t29 * t29;
    const T t64 = t63 * t29;
    const T t65 = t64 * t64;
    const T t66 = t65 * t29;
    G_E = -(T(1) / T(35)) * (T(5) * (T(6) * t43 * delta_tau + T(15) * t2 * t53 + t58 + t40 + T(15) * t42 * t1 + T(20) * t39 * t57 + T(6) * tau_lo * t54) * t62 + T(20) * t51 * t2 * t53 * t44 - T(2) * t35 * t43 * delta_tau * t32 - T(20) * t48 * t39 * t57 * t44 - T(5) * t66 * t40 - T(10) * t56 * tau_lo * t54 * t44 - T(2) * t58 * (T(5) * (T(2) * b * t55 * t44 + T(3) * (b * t31 * t32 + t29 - t26) * t44 - c * t50 * t44) * t44 + T(2) * b * t56 * t44 + t51 * c * t44) * t44 - T(10) * t42 * t46 * t1 * t44) * t44;
  }
  const T t67 = T(1) / a;
  const T t_star = b * t67;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(7) * t69 * in.sigma * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
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
    const T t5 = sqrt(a);
    const T t6 = r0 * a_minus_b;
    X = t4 * t5 * (t6 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = t7 * (a_minus_b - b) / (t8 - r1 * b);
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
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t14 * delta_tau;
    const T t16 = t2 * t2;
    const T t17 = t16 * tau_lo;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    F = T(6) * M_panels[5] * t15 * tau_lo + T(6) * delta_tau * t17 * M_panels[1] + t19 * M_panels[6] + T(15) * t14 * t2 * M_panels[4] + T(20) * t18 * t20 * M_panels[3] + T(15) * M_panels[2] * t1 * t16 + t21 * M_panels[0];
    const T t22 = t19 * M_panels[14] + T(15) * t1 * t16 * M_panels[10] + T(6) * delta_tau * M_panels[9] * t17 + T(6) * t15 * tau_lo * M_panels[13] + T(20) * t18 * t20 * M_panels[11] + t21 * M_panels[8] + T(15) * t14 * M_panels[12] * t2;
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = M_panels[15] * t19 + T(20) * t18 * M_panels[12] * t20 + T(6) * t15 * tau_lo * M_panels[14] + T(6) * delta_tau * t17 * M_panels[10] + T(15) * t1 * t16 * M_panels[11] + M_panels[9] * t21 + T(15) * t14 * t2 * M_panels[13] - t23 * t22 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t2 * tau_lo;
    const T t25 = t24 * t24;
    const T t26 = t1 * t1;
    const T t27 = t26 * delta_tau;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t2 * t2;
    const T t31 = t30 * tau_lo;
    F = t25 * M_panels[0] + T(6) * M_panels[5] * t27 * tau_lo + T(15) * t26 * t2 * M_panels[4] + t29 * M_panels[6] + T(15) * M_panels[2] * t1 * t30 + T(6) * delta_tau * t31 * M_panels[1] + T(20) * t28 * t24 * M_panels[3];
    const T t32 = T(15) * t1 * t30 * M_panels[10] + t29 * M_panels[14] + T(6) * t27 * tau_lo * M_panels[13] + T(6) * delta_tau * t31 * M_panels[9] + T(15) * t26 * t2 * M_panels[12] + t25 * M_panels[8] + T(20) * M_panels[11] * t28 * t24;
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(15) * M_panels[11] * t1 * t30 + t29 * M_panels[15] + t25 * M_panels[9] + T(6) * t27 * tau_lo * M_panels[14] + T(15) * t26 * t2 * M_panels[13] + T(20) * t28 * t24 * M_panels[12] + T(6) * delta_tau * t31 * M_panels[10] - t32 * t33 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = T(1) / a;
    const T t35 = T(1) / D;
    const T t36 = T(1) / r1;
    const T t37 = t36 * t36;
    const T t38 = T(1) / r0;
    const T t39 = a_minus_b * t36 + t38 * b;
    const T t40 = t38 * t38;
    const T t41 = a_minus_b * t36 * t37 + T(2) * t35 * a * t39 + t40 * t38 * b;
    const T t42 = t40 * t40;
    const T t43 = t37 * t37;
    const T t44 = T(4) * t35 * a * t41 + T(3) * t42 * t38 * b + T(3) * a_minus_b * t36 * t43;
    const T t45 = t35 * t44 * b + T(3) * t42 * t38 - T(3) * t36 * t43;
    const T t46 = t35 * b * t41 + t40 * t38 - t36 * t37;
    const T t47 = T(5) * t35 * t41 + T(2) * t34 * b * t45 - c * t35 * t44;
    const T t48 = c * t34 * t45 - T(5) * t46 * t34 - T(2) * t47 * t34 * b;
    const T t49 = T(2) * t46 * t34 * b + T(3) * t35 * t39 - c * t35 * t41;
    const T t50 = T(2) * t34 * b * t48 + c * t47 * t34 - T(5) * t49 * t34;
    const T t51 = t35 * b * t39 + t38 - t36;
    const T t52 = T(3) * t34 * t51 + T(2) * t49 * t34 * b - c * t46 * t34;
    const T t53 = T(5) * t52 * t34 + c * t34 * t48 - T(2) * t34 * b * t50;
    const T t54 = t1 * delta_tau;
    const T t55 = t54 * t54;
    const T t56 = t1 * t1;
    const T t57 = t56 * delta_tau;
    const T t58 = t2 * tau_lo;
    const T t59 = t58 * t58;
    const T t60 = t2 * t2;
    const T t61 = t60 * tau_lo;
    F = (T(1) / T(15)) * (c * t34 * t50 + T(2) * t34 * b * t53 - T(5) * t34 * (c * t49 * t34 + T(3) * t34 * (c * t35 * t39 - J1 - T(2) * t34 * t51 * b) - T(2) * t52 * t34 * b)) * t55 * t34 + (T(2) / T(5)) * t57 * tau_lo * t34 * t53 + (T(1) / T(15)) * t35 * t59 * t44 + t47 * t1 * t60 * t34 + (T(2) / T(5)) * delta_tau * t61 * t34 * t45 - (T(4) / T(3)) * t54 * t58 * t34 * t48 - t56 * t2 * t34 * t50;
    const T t62 = t42 * t40;
    const T t63 = t43 * t37;
    const T t64 = T(5) * t62 * t38 * b + T(5) * a_minus_b * t36 * t63 + T(2) * t35 * a * t44;
    const T t65 = t35 * b * t64 + T(5) * t62 * t38 - T(5) * t36 * t63;
    const T t66 = T(3) * c * t35 * t64 - T(6) * t65 * t34 * b - T(7) * t35 * t44;
    const T t67 = T(2) * t66 * t34 * b + T(3) * c * t65 * t34 - T(7) * t34 * t45;
    const T t68 = T(2) * t34 * b * t67 - T(7) * t47 * t34 - c * t66 * t34;
    const T t69 = T(2) * t68 * t34 * b + T(7) * t34 * t48 - c * t34 * t67;
    G_ap = (T(6) / T(35)) * delta_tau * t65 * t61 * t34 + (T(1) / T(105)) * t55 * t34 * (c * t68 * t34 - T(7) * t34 * t50 - T(2) * t69 * t34 * b) + (T(1) / T(35)) * t35 * t59 * t64 - (T(2) / T(35)) * t57 * t69 * tau_lo * t34 - (T(4) / T(21)) * t54 * t58 * t34 * t67 - (T(1) / T(7)) * t56 * t2 * t68 * t34 - (T(1) / T(7)) * t1 * t60 * t66 * t34;
    const T t70 = t38 * t38;
    const T t71 = t70 * t38;
    const T t72 = t71 * t71;
    const T t73 = t72 * t38;
    const T t74 = t36 * t36;
    const T t75 = t74 * t36;
    const T t76 = t75 * t75;
    const T t77 = t76 * t36;
    G_E = (T(1) / T(35)) * (T(10) * t1 * t60 * t34 * t45 + T(20) * t47 * t54 * t58 * t34 + T(2) * delta_tau * t35 * t61 * t44 + T(2) * t55 * t34 * t53 + T(5) * t73 * t59 - T(5) * t77 * (T(15) * t1 * t60 + T(6) * t57 * tau_lo + t59 + T(15) * t56 * t2 + t55 + T(20) * t54 * t58 + T(6) * delta_tau * t61) - T(20) * t56 * t2 * t34 * t48 - T(10) * t57 * tau_lo * t34 * t50) * t34;
  }
  const T t78 = T(1) / a;
  const T t_star = t78 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t79 = sigma2 * sigma2;
  const T t80 = t79 * sigma2;
  const T g_factor = -T(7) * length * t80 * in.sigma;
  f = length * t80 * F * in.sigma;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_hi * sigma2 * tau_lo;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * tau_lo;
    const T t11 = t10 * t10;
    const T t12 = t11 * tau_lo;
    const T t13 = t2 * t2;
    const T t14 = t13 * tau_lo;
    const T t15 = t1 * t1;
    const T t16 = t15 * delta_tau;
    F = T(7) * M_panels[6] * t8 * tau_lo + M_panels[7] * t9 + M_panels[0] * t12 + T(21) * M_panels[2] * t1 * t14 + T(21) * M_panels[5] * t16 * t2 + T(35) * t15 * t10 * M_panels[4] + T(35) * M_panels[3] * t7 * t13 + T(7) * M_panels[1] * delta_tau * t11;
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
    F = M_panels[7] * t19 + T(21) * t1 * t21 * M_panels[2] + M_panels[0] * t24 + T(21) * t26 * M_panels[5] * t2 + T(35) * M_panels[4] * t25 * t22 + T(7) * M_panels[6] * t18 * tau_lo + T(7) * M_panels[1] * delta_tau * t23 + T(35) * M_panels[3] * t17 * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(D);
    const T t28 = T(1) / t27;
    const T J2 = atan2(t27, c_minus_b) * t28;
    const T t29 = T(1) / a;
    const T t30 = t3 * t3;
    const T t31 = T(1) / q1;
    const T t32 = t31 * t31;
    const T t33 = a_minus_b * t31 + a * J2 + b * t3;
    const T t34 = T(1) / D;
    const T t35 = T(2) * b * t30 + T(2) * a_minus_b * t32 + T(3) * a * t33 * t34;
    const T t36 = t30 * t3;
    const T t37 = t32 * t31;
    const T t38 = T(8) * b * t36 + T(5) * a * t35 * t34 + T(8) * a_minus_b * t37;
    const T t39 = T(8) * t36 + b * t38 * t34 - T(8) * t37;
    const T t40 = T(6) * t35 * t34 + T(2) * t29 * b * t39 - c * t38 * t34;
    const T t41 = t2 * t2;
    const T t42 = t41 * tau_lo;
    const T t43 = T(2) * t30 + t35 * b * t34 - T(2) * t32;
    const T t44 = T(2) * t29 * b * t43 + T(4) * t33 * t34 - t35 * c * t34;
    const T t45 = t29 * c * t39 - T(2) * t29 * b * t40 - T(6) * t29 * t43;
    const T t46 = T(6) * t29 * t44 - t29 * c * t40 - T(2) * t29 * b * t45;
    const T t47 = t1 * t1;
    const T t48 = t2 * tau_lo;
    const T t49 = t48 * t48;
    const T t50 = t49 * tau_lo;
    const T t51 = t31 - t33 * b * t34 - t3;
    const T t52 = T(4) * t29 * t51 + t29 * c * t43 - T(2) * t29 * b * t44;
    const T t53 = T(2) * J2 - t33 * c * t34 - T(2) * t29 * b * t51;
    const T t54 = T(2) * t29 * b * t52 + t29 * c * t44 - T(4) * t29 * t53;
    const T t55 = T(6) * t29 * t52 - t29 * t45 * c - T(2) * t29 * b * t46;
    const T t56 = T(2) * t29 * t55 * b + t29 * c * t46 + T(6) * t29 * t54;
    const T t57 = t1 * delta_tau;
    const T t58 = t57 * t57;
    const T t59 = t58 * delta_tau;
    const T t60 = t47 * delta_tau;
    F = (T(7) / T(16)) * t29 * t40 * t1 * t42 + (T(35) / T(48)) * t29 * t46 * t47 * t48 + (T(7) / T(48)) * t29 * t39 * delta_tau * t49 + (T(1) / T(48)) * t50 * t38 * t34 - (T(1) / T(48)) * t29 * (T(6) * t29 * (T(2) * t29 * t54 * b - t29 * t52 * c - T(4) * t29 * (T(2) * t29 * b * t53 + t29 * (T(2) * J2 * b + log_ratio) + t29 * t51 * c)) + T(2) * t29 * t56 * b - t29 * t55 * c) * t59 - (T(35) / T(48)) * t29 * t45 * t57 * t41 - (T(7) / T(48)) * t29 * t56 * t58 * tau_lo - (T(7) / T(16)) * t29 * t55 * t60 * t2;
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t2 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t1 * t1;
    const T t11 = t10 * delta_tau;
    const T t12 = t2 * t2;
    const T t13 = t12 * tau_lo;
    const T t14 = t7 * delta_tau;
    const T t15 = t9 * tau_lo;
    const T t16 = T(7) * tau_lo * M_panels[15] * t7 + T(7) * t9 * delta_tau * M_panels[10] + T(35) * t8 * t10 * M_panels[13] + T(21) * M_panels[14] * t2 * t11 + T(21) * M_panels[11] * t13 * t1 + T(35) * t12 * t6 * M_panels[12] + t14 * M_panels[16] + t15 * M_panels[9];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = T(7) * tau_lo * t7 * M_panels[16] + t15 * M_panels[10] + T(35) * M_panels[14] * t8 * t10 + M_panels[17] * t14 + T(35) * t12 * t6 * M_panels[13] + T(7) * M_panels[11] * t9 * delta_tau + T(21) * t13 * t1 * M_panels[12] + T(21) * t2 * M_panels[15] * t11 - t16 * t17 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t19 * tau_lo;
    const T t21 = t1 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t2 * t2;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t26 * delta_tau;
    const T t28 = M_panels[9] * t20 + T(7) * M_panels[15] * tau_lo * t22 + M_panels[16] * t23 + T(21) * t25 * t1 * M_panels[11] + T(35) * t18 * t26 * M_panels[13] + T(21) * t2 * t27 * M_panels[14] + T(35) * M_panels[12] * t24 * t21 + T(7) * t19 * delta_tau * M_panels[10];
    G_ap = t28;
    const T t29 = T(1) / a;
    G_E = T(35) * t18 * t26 * M_panels[14] + T(7) * t19 * delta_tau * M_panels[11] + T(21) * M_panels[15] * t2 * t27 + T(21) * M_panels[12] * t25 * t1 + t20 * M_panels[10] + T(35) * t24 * t21 * M_panels[13] + t23 * M_panels[17] + T(7) * tau_lo * M_panels[16] * t22 - t28 * t29 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = atan2(t30, c_minus_b) * t31;
    const T t32 = t1 * t1;
    const T t33 = t32 * delta_tau;
    const T t34 = T(1) / a;
    const T t35 = T(1) / c;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = T(1) / q1;
    const T t39 = t38 * t38;
    const T t40 = t39 * t38;
    const T t41 = T(1) / D;
    const T t42 = a_minus_b * t38 + J2 * a + t35 * b;
    const T t43 = T(3) * a * t41 * t42 + T(2) * t36 * b + T(2) * a_minus_b * t39;
    const T t44 = T(8) * t37 * b + T(8) * a_minus_b * t40 + T(5) * t43 * a * t41;
    const T t45 = t39 * t39;
    const T t46 = t36 * t36;
    const T t47 = T(7) * t44 * a * t41 + T(48) * a_minus_b * t45 + T(48) * t46 * b;
    const T t48 = t47 * t41 * b + T(48) * t46 - T(48) * t45;
    const T t49 = c * t47 * t41 - T(2) * t34 * t48 * b - T(8) * t44 * t41;
    const T t50 = T(8) * t37 + t44 * t41 * b - T(8) * t40;
    const T t51 = T(2) * t49 * t34 * b + c * t34 * t48 - T(8) * t34 * t50;
    const T t52 = c * t44 * t41 - T(6) * t43 * t41 - T(2) * t34 * t50 * b;
    const T t53 = c * t49 * t34 - T(2) * t34 * t51 * b - T(8) * t52 * t34;
    const T t54 = T(2) * t36 + t43 * t41 * b - T(2) * t39;
    const T t55 = T(6) * t54 * t34 - T(2) * t52 * t34 * b - c * t34 * t50;
    const T t56 = T(2) * t53 * t34 * b + c * t34 * t51 + T(8) * t55 * t34;
    const T t57 = t2 * tau_lo;
    const T t58 = t57 * t57;
    const T t59 = t58 * tau_lo;
    const T t60 = t2 * t2;
    const T t61 = t60 * tau_lo;
    const T t62 = t1 * delta_tau;
    const T t63 = t62 * t62;
    const T t64 = c * t43 * t41 - T(4) * t41 * t42 - T(2) * t54 * t34 * b;
    const T t65 = c * t52 * t34 + T(2) * t55 * t34 * b - T(6) * t34 * t64;
    const T t66 = c * t53 * t34 - T(8) * t65 * t34 - T(2) * t34 * t56 * b;
    const T t67 = t63 * delta_tau;
    const T t68 = t38 - t35 - t41 * t42 * b;
    const T t69 = T(2) * t34 * t64 * b + T(4) * t68 * t34 + t54 * c * t34;
    const T t70 = c * t55 * t34 + T(6) * t69 * t34 - T(2) * t65 * t34 * b;
    G_ap = (T(7) / T(128)) * t2 * t33 * t34 * t56 + (T(35) / T(384)) * t57 * t53 * t32 * t34 + (T(1) / T(384)) * t47 * t59 * t41 + (T(7) / T(384)) * t58 * delta_tau * t34 * t48 - (T(7) / T(128)) * t49 * t61 * t1 * t34 - (T(7) / T(384)) * tau_lo * t63 * t34 * t66 - (T(1) / T(384)) * t67 * t34 * (T(2) * t34 * t66 * b + T(8) * t34 * t70 + c * t34 * t56) - (T(35) / T(384)) * t60 * t62 * t34 * t51;
    G_E = -(T(1) / T(384)) * (T(48) * (t59 + T(7) * tau_lo * t63 + T(21) * t2 * t33 + T(7) * t58 * delta_tau + T(21) * t61 * t1 + T(35) * t60 * t62 + T(35) * t57 * t32 + t67) * t45 + T(7) * (c * t65 * t34 + T(6) * t34 * (T(2) * t69 * t34 * b - c * t34 * t64 - T(4) * (T(2) * J2 - c * t41 * t42 - T(2) * t68 * t34 * b) * t34) + T(2) * t34 * t70 * b) * t67 * t34 + T(105) * t60 * t62 * t52 * t34 + T(42) * tau_lo * t63 * t34 * t70 - T(105) * t65 * t2 * t33 * t34 - T(48) * t46 * t59 - T(140) * t55 * t57 * t32 * t34 - T(42) * t61 * t1 * t34 * t50 - T(7) * t44 * t58 * delta_tau * t41) * t34;
  }
  const T t71 = T(1) / a;
  const T t_star = t71 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - t_star * ab2;
  const T t72 = sigma2 * sigma2;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * length * t73;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
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
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t7 * t7;
    const T t9 = t8 * tau_lo;
    const T t10 = t1 * t1;
    const T t11 = t10 * delta_tau;
    const T t12 = t1 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t13 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t15 * tau_lo;
    F = t9 * M_panels[0] + T(7) * M_panels[1] * delta_tau * t8 + T(21) * t11 * t2 * M_panels[5] + t14 * M_panels[7] + T(21) * t1 * t16 * M_panels[2] + T(35) * M_panels[4] * t10 * t7 + T(7) * t13 * tau_lo * M_panels[6] + T(35) * t12 * t15 * M_panels[3];
    const T t17 = T(35) * t10 * t7 * M_panels[13] + t14 * M_panels[16] + t9 * M_panels[9] + T(35) * t12 * M_panels[12] * t15 + T(21) * M_panels[11] * t1 * t16 + T(7) * M_panels[15] * t13 * tau_lo + T(21) * M_panels[14] * t11 * t2 + T(7) * delta_tau * t8 * M_panels[10];
    G_ap = t17;
    const T t18 = T(1) / a;
    G_E = T(35) * t12 * t15 * M_panels[13] + T(7) * t13 * tau_lo * M_panels[16] + t9 * M_panels[10] + T(21) * M_panels[15] * t11 * t2 + t14 * M_panels[17] + T(7) * M_panels[11] * delta_tau * t8 + T(21) * t1 * M_panels[12] * t16 + T(35) * M_panels[14] * t10 * t7 - t17 * t18 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t19 = t2 * t2;
    const T t20 = t19 * tau_lo;
    const T t21 = t1 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t2 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t22 * delta_tau;
    const T t28 = t26 * delta_tau;
    F = T(21) * t1 * t20 * M_panels[2] + T(7) * M_panels[6] * t22 * tau_lo + T(7) * delta_tau * t24 * M_panels[1] + M_panels[0] * t25 + T(35) * t26 * t23 * M_panels[4] + T(35) * M_panels[3] * t21 * t19 + t27 * M_panels[7] + T(21) * t28 * t2 * M_panels[5];
    const T t29 = T(35) * t26 * M_panels[13] * t23 + T(21) * t28 * t2 * M_panels[14] + T(21) * t1 * t20 * M_panels[11] + M_panels[16] * t27 + T(35) * M_panels[12] * t21 * t19 + T(7) * delta_tau * t24 * M_panels[10] + T(7) * M_panels[15] * t22 * tau_lo + M_panels[9] * t25;
    G_ap = t29;
    const T t30 = T(1) / a;
    G_E = T(35) * t21 * M_panels[13] * t19 + t25 * M_panels[10] + T(21) * M_panels[12] * t1 * t20 + T(35) * t26 * t23 * M_panels[14] + t27 * M_panels[17] + T(7) * M_panels[16] * t22 * tau_lo + T(21) * M_panels[15] * t28 * t2 + T(7) * delta_tau * t24 * M_panels[11] - t29 * t30 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = atan2(t31, c_minus_b) * t32;
    const T t33 = t3 * t3;
    const T t34 = T(1) / D;
    const T t35 = T(1) / q1;
    const T t36 = t35 * a_minus_b + J2 * a + t3 * b;
    const T t37 = t35 * t35;
    const T t38 = T(2) * t33 * b + T(3) * t34 * t36 * a + T(2) * t37 * a_minus_b;
    const T t39 = T(1) / a;
    const T t40 = t33 * t3;
    const T t41 = t37 * t35;
    const T t42 = T(8) * t40 * b + T(5) * t38 * t34 * a + T(8) * t41 * a_minus_b;
    const T t43 = T(8) * t40 + t34 * t42 * b - T(8) * t41;
    const T t44 = T(6) * t38 * t34 + T(2) * t39 * b * t43 - c * t34 * t42;
    const T t45 = t2 * t2;
    const T t46 = t45 * tau_lo;
    const T t47 = t2 * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t48 * tau_lo;
    const T t50 = t1 * delta_tau;
    const T t51 = T(2) * t33 + t38 * t34 * b - T(2) * t37;
    const T t52 = T(6) * t39 * t51 + T(2) * t44 * t39 * b - c * t39 * t43;
    const T t53 = t35 - t3 - t34 * t36 * b;
    const T t54 = c * t38 * t34 - T(4) * t34 * t36 - T(2) * t39 * t51 * b;
    const T t55 = T(4) * t39 * t53 + c * t39 * t51 + T(2) * t39 * t54 * b;
    const T t56 = c * t34 * t36 + T(2) * t39 * t53 * b - T(2) * J2;
    const T t57 = T(2) * t55 * t39 * b + T(4) * t39 * t56 - c * t39 * t54;
    const T t58 = t44 * c * t39 + T(6) * t39 * t54 - T(2) * t39 * t52 * b;
    const T t59 = c * t39 * t52 + T(2) * t58 * t39 * b + T(6) * t55 * t39;
    const T t60 = T(6) * t57 * t39 + T(2) * t59 * t39 * b - c * t58 * t39;
    const T t61 = t50 * t50;
    const T t62 = t61 * delta_tau;
    const T t63 = t1 * t1;
    const T t64 = t63 * delta_tau;
    F = (T(7) / T(16)) * t44 * t1 * t46 * t39 + (T(7) / T(48)) * delta_tau * t48 * t39 * t43 + (T(1) / T(48)) * t34 * t49 * t42 + (T(35) / T(48)) * t50 * t45 * t39 * t52 - (T(1) / T(48)) * (T(2) * t60 * t39 * b + T(6) * (T(4) * (T(2) * t39 * t56 * b - c * t39 * t53 - t39 * (log_ratio + T(2) * J2 * b)) * t39 + T(2) * t57 * t39 * b - c * t55 * t39) * t39 - c * t59 * t39) * t62 * t39 - (T(7) / T(48)) * t60 * t61 * tau_lo * t39 - (T(35) / T(48)) * t63 * t47 * t58 * t39 - (T(7) / T(16)) * t59 * t64 * t2 * t39;
    const T t65 = t37 * t37;
    const T t66 = t33 * t33;
    const T t67 = T(48) * t65 * a_minus_b + T(7) * t34 * t42 * a + T(48) * t66 * b;
    const T t68 = T(48) * t65 - t67 * t34 * b - T(48) * t66;
    const T t69 = t67 * c * t34 + T(2) * t39 * t68 * b - T(8) * t34 * t42;
    const T t70 = T(8) * t39 * t43 + c * t39 * t68 - T(2) * t39 * t69 * b;
    const T t71 = c * t39 * t69 + T(2) * t70 * t39 * b + T(8) * t44 * t39;
    const T t72 = T(8) * t39 * t52 + T(2) * t39 * t71 * b - c * t70 * t39;
    const T t73 = T(8) * t58 * t39 + c * t39 * t71 - T(2) * t39 * t72 * b;
    G_ap = (T(7) / T(128)) * t64 * t2 * t39 * t72 + (T(35) / T(384)) * t63 * t47 * t39 * t71 + (T(35) / T(384)) * t70 * t50 * t45 * t39 + (T(1) / T(384)) * t67 * t34 * t49 - (T(7) / T(384)) * t61 * t73 * tau_lo * t39 - (T(7) / T(384)) * delta_tau * t48 * t39 * t68 - (T(7) / T(128)) * t1 * t46 * t39 * t69 - (T(1) / T(384)) * t62 * t39 * (T(2) * t73 * t39 * b + T(8) * t59 * t39 + c * t39 * t72);
    G_E = (T(1) / T(384)) * (T(48) * t66 * t49 + T(105) * t44 * t50 * t45 * t39 + T(7) * delta_tau * t34 * t48 * t42 + T(140) * t63 * t47 * t39 * t52 + T(42) * t1 * t46 * t39 * t43 - T(48) * t65 * (t49 + T(7) * delta_tau * t48 + t62 + T(7) * t61 * tau_lo + T(21) * t64 * t2 + T(35) * t50 * t45 + T(35) * t63 * t47 + T(21) * t1 * t46) - T(105) * t64 * t2 * t58 * t39 - T(7) * t60 * t62 * t39 - T(42) * t59 * t61 * tau_lo * t39) * t39;
  }
  const T t74 = T(1) / a;
  const T t_star = t74 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - t_star * ab2;
  const T t75 = sigma2 * sigma2;
  const T t76 = t75 * t75;
  const T g_factor = -T(8) * length * t76;
  f = length * t76 * F;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
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
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
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
    const T t6 = r0 * a_minus_b;
    X = t4 * t5 * (t6 + b * r1);
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
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t14 * delta_tau;
    const T t16 = t2 * tau_lo;
    const T t17 = t14 * t14;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t19 * delta_tau;
    const T t21 = t16 * t16;
    const T t22 = t21 * tau_lo;
    const T t23 = t2 * t2;
    const T t24 = t23 * t23;
    const T t25 = t23 * tau_lo;
    F = T(56) * t15 * t16 * M_panels[5] + t17 * M_panels[8] + T(8) * t20 * tau_lo * M_panels[7] + T(28) * t19 * t2 * M_panels[6] + T(8) * M_panels[1] * delta_tau * t22 + T(70) * M_panels[4] * t14 * t23 + t24 * M_panels[0] + T(56) * t18 * t25 * M_panels[3] + T(28) * t1 * t21 * M_panels[2];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    const T t29 = t2 * t2;
    const T t30 = t29 * t29;
    const T t31 = t2 * tau_lo;
    const T t32 = t31 * t31;
    const T t33 = t32 * tau_lo;
    const T t34 = t1 * t1;
    const T t35 = t29 * tau_lo;
    const T t36 = t34 * delta_tau;
    const T t37 = t34 * t34;
    F = T(8) * t28 * tau_lo * M_panels[7] + T(28) * t27 * t2 * M_panels[6] + t30 * M_panels[0] + T(8) * delta_tau * t33 * M_panels[1] + T(70) * t34 * t29 * M_panels[4] + T(56) * t26 * t35 * M_panels[3] + T(28) * t1 * M_panels[2] * t32 + T(56) * t36 * M_panels[5] * t31 + M_panels[8] * t37;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / D;
    const T t39 = t2 * t2;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = T(1) / r1;
    const T t45 = t44 * t44;
    const T t46 = t44 * a_minus_b + t41 * b;
    const T t47 = t45 * t44 * a_minus_b + t41 * b * t42 + T(2) * t38 * a * t46;
    const T t48 = t45 * t45;
    const T t49 = T(3) * t41 * b * t43 + T(4) * t47 * t38 * a + T(3) * t48 * t44 * a_minus_b;
    const T t50 = t48 * t45;
    const T t51 = t43 * t42;
    const T t52 = T(2) * t38 * a * t49 + T(5) * t50 * t44 * a_minus_b + T(5) * t41 * b * t51;
    const T t53 = T(5) * t41 * t51 + t38 * t52 * b - T(5) * t50 * t44;
    const T t54 = t2 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t55 * tau_lo;
    const T t57 = T(1) / a;
    const T t58 = T(7) * t38 * t49 + T(6) * t53 * t57 * b - T(3) * t38 * t52 * c;
    const T t59 = t44 - t41 - t38 * b * t46;
    const T t60 = t45 * t44 - t41 * t42 - t47 * t38 * b;
    const T t61 = T(2) * t60 * t57 * b + t47 * t38 * c - T(3) * t38 * t46;
    const T t62 = T(3) * t59 * t57 + T(2) * t61 * t57 * b - t60 * t57 * c;
    const T t63 = T(3) * t41 * t43 + t38 * t49 * b - T(3) * t48 * t44;
    const T t64 = t38 * t49 * c - T(5) * t47 * t38 - T(2) * t57 * t63 * b;
    const T t65 = T(2) * t57 * b * t64 + T(5) * t60 * t57 + t57 * t63 * c;
    const T t66 = T(2) * t57 * t65 * b + T(5) * t61 * t57 - t57 * t64 * c;
    const T t67 = T(5) * t62 * t57 + T(2) * t57 * t66 * b - t57 * t65 * c;
    const T t68 = T(3) * t53 * t57 * c - T(2) * t57 * t58 * b - T(7) * t57 * t63;
    const T t69 = T(2) * t68 * t57 * b + T(7) * t57 * t64 + t57 * t58 * c;
    const T t70 = T(7) * t57 * t65 + T(2) * t57 * t69 * b - t68 * t57 * c;
    const T t71 = T(2) * t57 * b * t70 + T(7) * t57 * t66 - t57 * t69 * c;
    const T t72 = T(7) * t57 * t67 + T(2) * t71 * t57 * b - t57 * t70 * c;
    const T t73 = t1 * t1;
    const T t74 = t73 * t73;
    const T t75 = t1 * delta_tau;
    const T t76 = t75 * t75;
    const T t77 = t39 * tau_lo;
    const T t78 = t73 * delta_tau;
    const T t79 = t76 * delta_tau;
    F = (T(1) / T(35)) * t38 * t40 * t52 + (T(8) / T(35)) * delta_tau * t53 * t56 * t57 + (T(4) / T(15)) * t1 * t55 * t57 * t58 - (T(1) / T(105)) * (T(2) * t57 * b * t72 - T(7) * t57 * (t57 * t66 * c + T(5) * t57 * (t61 * t57 * c + T(3) * t57 * (J1 - t38 * t46 * c - T(2) * t59 * t57 * b) - T(2) * t62 * t57 * b) - T(2) * t57 * t67 * b) - t71 * t57 * c) * t74 * t57 - (T(4) / T(15)) * t71 * t76 * t2 * t57 - (T(8) / T(15)) * t68 * t75 * t77 * t57 - (T(8) / T(15)) * t78 * t54 * t57 * t70 - (T(8) / T(105)) * t79 * tau_lo * t57 * t72 - (T(2) / T(3)) * t73 * t39 * t57 * t69;
  }
  const T t80 = sigma2 * sigma2;
  const T t81 = t80 * t80;
  f = length * t81 * F * in.sigma;
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
    const T t6 = t1 * t1;
    const T t7 = t2 * t2;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t1 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * delta_tau;
    const T t14 = t2 * tau_lo;
    const T t15 = t7 * tau_lo;
    const T t16 = t14 * t14;
    const T t17 = t16 * tau_lo;
    const T t18 = T(70) * t6 * t7 * M_panels[14] + M_panels[10] * t8 + t9 * M_panels[18] + T(8) * t12 * tau_lo * M_panels[17] + T(56) * t13 * t14 * M_panels[15] + T(56) * t10 * M_panels[13] * t15 + T(8) * delta_tau * t17 * M_panels[11] + T(28) * M_panels[16] * t11 * t2 + T(28) * t1 * t16 * M_panels[12];
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = T(28) * t1 * M_panels[13] * t16 + T(8) * delta_tau * t17 * M_panels[12] + T(8) * t12 * tau_lo * M_panels[18] + M_panels[19] * t9 + t8 * M_panels[11] + T(56) * M_panels[16] * t13 * t14 + T(28) * t11 * t2 * M_panels[17] + T(70) * t6 * t7 * M_panels[15] + T(56) * t10 * t15 * M_panels[14] - t18 * t19 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * t1;
    const T t21 = t20 * t20;
    const T t22 = t2 * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t1 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = t2 * t2;
    const T t29 = t28 * t28;
    const T t30 = t20 * delta_tau;
    const T t31 = t28 * tau_lo;
    const T t32 = M_panels[18] * t21 + T(8) * delta_tau * t24 * M_panels[11] + T(8) * t27 * tau_lo * M_panels[17] + t29 * M_panels[10] + T(56) * M_panels[15] * t30 * t22 + T(70) * t20 * t28 * M_panels[14] + T(28) * t26 * t2 * M_panels[16] + T(56) * t25 * t31 * M_panels[13] + T(28) * t1 * M_panels[12] * t23;
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(28) * t1 * t23 * M_panels[13] + t21 * M_panels[19] + T(8) * delta_tau * M_panels[12] * t24 + T(56) * t30 * t22 * M_panels[16] + T(56) * t25 * t31 * M_panels[14] + T(28) * t26 * t2 * M_panels[17] + T(70) * M_panels[15] * t20 * t28 + t29 * M_panels[11] + T(8) * M_panels[18] * t27 * tau_lo - t32 * t33 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t1 * delta_tau;
    const T t35 = t34 * t34;
    const T t36 = t35 * delta_tau;
    const T t37 = T(1) / a;
    const T t38 = T(1) / r0;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = T(1) / D;
    const T t42 = T(1) / r1;
    const T t43 = t42 * t42;
    const T t44 = t43 * t43;
    const T t45 = a_minus_b * t42 + b * t38;
    const T t46 = T(2) * t41 * a * t45 + t39 * b * t38 + a_minus_b * t42 * t43;
    const T t47 = T(3) * a_minus_b * t42 * t44 + T(3) * t40 * b * t38 + T(4) * t46 * t41 * a;
    const T t48 = T(3) * t40 * t38 + t41 * t47 * b - T(3) * t42 * t44;
    const T t49 = t40 * t39;
    const T t50 = t44 * t43;
    const T t51 = T(2) * t41 * t47 * a + T(5) * a_minus_b * t42 * t50 + T(5) * t49 * b * t38;
    const T t52 = T(5) * t49 * t38 + t41 * b * t51 - T(5) * t42 * t50;
    const T t53 = T(6) * t37 * t52 * b + T(7) * t41 * t47 - T(3) * c * t41 * t51;
    const T t54 = T(7) * t37 * t48 + T(2) * t37 * t53 * b - T(3) * c * t37 * t52;
    const T t55 = T(2) * t37 * t48 * b + T(5) * t46 * t41 - c * t41 * t47;
    const T t56 = T(2) * t37 * b * t54 + T(7) * t37 * t55 - c * t37 * t53;
    const T t57 = t46 * t41 * b + t39 * t38 - t42 * t43;
    const T t58 = c * t37 * t48 - T(5) * t37 * t57 - T(2) * t37 * b * t55;
    const T t59 = T(2) * t56 * t37 * b - T(7) * t58 * t37 - c * t37 * t54;
    const T t60 = t44 * t44;
    const T t61 = t40 * t40;
    const T t62 = T(35) * t61 * b * t38 + T(35) * a_minus_b * t42 * t60 + T(8) * t41 * a * t51;
    const T t63 = T(35) * t42 * t60 - t41 * t62 * b - T(35) * t61 * t38;
    const T t64 = c * t41 * t62 + T(2) * t63 * t37 * b - T(9) * t41 * t51;
    const T t65 = c * t63 * t37 + T(9) * t37 * t52 - T(2) * t64 * t37 * b;
    const T t66 = T(2) * t37 * b * t65 + c * t64 * t37 + T(3) * t37 * t53;
    const T t67 = T(2) * t37 * b * t66 + T(3) * t37 * t54 - c * t37 * t65;
    const T t68 = T(3) * t56 * t37 + T(2) * t37 * t67 * b - c * t37 * t66;
    const T t69 = T(3) * t59 * t37 + T(2) * t68 * t37 * b - c * t37 * t67;
    const T t70 = t2 * t2;
    const T t71 = t70 * tau_lo;
    const T t72 = t70 * t70;
    const T t73 = t1 * t1;
    const T t74 = t73 * delta_tau;
    const T t75 = t2 * tau_lo;
    const T t76 = t73 * t73;
    const T t77 = T(2) * t37 * b * t57 + T(3) * t41 * t45 - c * t46 * t41;
    const T t78 = c * t37 * t55 + T(2) * t58 * t37 * b - T(5) * t77 * t37;
    const T t79 = T(2) * t59 * t37 * b - c * t56 * t37 - T(7) * t37 * t78;
    const T t80 = t75 * t75;
    const T t81 = t80 * tau_lo;
    G_ap = (T(8) / T(315)) * t36 * tau_lo * t37 * t69 + (T(4) / T(45)) * t35 * t2 * t68 * t37 + (T(8) / T(45)) * t34 * t71 * t37 * t65 + (T(1) / T(315)) * t41 * t72 * t62 + (T(2) / T(9)) * t73 * t70 * t37 * t66 + (T(8) / T(45)) * t74 * t75 * t37 * t67 - (T(1) / T(315)) * t76 * t37 * (c * t68 * t37 - T(3) * t79 * t37 - T(2) * t37 * b * t69) - (T(8) / T(315)) * delta_tau * t81 * t63 * t37 - (T(4) / T(45)) * t64 * t1 * t80 * t37;
    const T t82 = t38 * t38;
    const T t83 = t82 * t82;
    const T t84 = t83 * t83;
    const T t85 = t84 * t38;
    const T t86 = t42 * t42;
    const T t87 = t86 * t86;
    const T t88 = t87 * t87;
    const T t89 = t88 * t42;
    G_E = (T(1) / T(945)) * t37 * (T(168) * t1 * t80 * t37 * t52 + T(56) * t36 * tau_lo * t79 * t37 + T(280) * t56 * t74 * t75 * t37 + T(168) * t34 * t71 * t37 * t53 + T(24) * delta_tau * t41 * t81 * t51 + T(168) * t59 * t35 * t2 * t37 + T(280) * t73 * t70 * t37 * t54 + T(105) * t72 * t85 - T(105) * t89 * (t76 + T(28) * t35 * t2 + T(28) * t1 * t80 + T(8) * t36 * tau_lo + T(56) * t74 * t75 + T(56) * t34 * t71 + T(70) * t73 * t70 + T(8) * delta_tau * t81 + t72) - T(8) * t76 * t37 * (c * t59 * t37 - T(2) * t79 * t37 * b - T(7) * (c * t58 * t37 - T(5) * t37 * (c * t37 * t57 - T(2) * t77 * t37 * b - T(3) * (t38 + t41 * b * t45 - t42) * t37) - T(2) * t37 * b * t78) * t37));
  }
  const T t90 = T(1) / a;
  const T t_star = t90 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T g_factor = -T(9) * length * t92 * in.sigma;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
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
    X = t4 * (t5 + r0 * a_minus_b) * t6;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r1 * b;
    X = -t7 * (a_minus_b - b) / (t8 - r0 * a_minus_b);
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
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t2 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t17 * tau_lo;
    const T t19 = t1 * t1;
    const T t20 = t19 * delta_tau;
    const T t21 = t15 * delta_tau;
    const T t22 = t2 * t2;
    const T t23 = t22 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t19 * t19;
    F = T(28) * t2 * M_panels[6] * t15 + T(8) * t18 * M_panels[1] * delta_tau + T(56) * t16 * M_panels[5] * t20 + T(28) * t17 * M_panels[2] * t1 + T(8) * tau_lo * M_panels[7] * t21 + T(56) * t23 * M_panels[3] * t14 + t24 * M_panels[0] + T(70) * t22 * M_panels[4] * t19 + M_panels[8] * t25;
    const T t26 = t25 * M_panels[18] + T(28) * t17 * M_panels[12] * t1 + T(28) * t2 * M_panels[16] * t15 + T(8) * t18 * M_panels[11] * delta_tau + T(56) * t16 * M_panels[15] * t20 + T(56) * t23 * M_panels[13] * t14 + T(8) * tau_lo * M_panels[17] * t21 + T(70) * t22 * M_panels[14] * t19 + t24 * M_panels[10];
    G_ap = t26;
    const T t27 = T(1) / a;
    G_E = T(28) * t2 * M_panels[17] * t15 + T(8) * t18 * M_panels[12] * delta_tau + T(8) * tau_lo * t21 * M_panels[18] + T(28) * t17 * M_panels[13] * t1 + t24 * M_panels[11] + T(56) * t23 * M_panels[14] * t14 + T(70) * t22 * M_panels[15] * t19 + T(56) * t16 * M_panels[16] * t20 + M_panels[19] * t25 - t27 * b * t26;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t28 = t2 * t2;
    const T t29 = t28 * t28;
    const T t30 = t1 * t1;
    const T t31 = t30 * t30;
    const T t32 = t2 * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = t28 * tau_lo;
    const T t36 = t1 * delta_tau;
    const T t37 = t36 * t36;
    const T t38 = t37 * delta_tau;
    const T t39 = t30 * delta_tau;
    F = t29 * M_panels[0] + M_panels[8] * t31 + T(8) * t34 * M_panels[1] * delta_tau + T(56) * t35 * M_panels[3] * t36 + T(28) * t33 * M_panels[2] * t1 + T(28) * t2 * M_panels[6] * t37 + T(8) * tau_lo * M_panels[7] * t38 + T(56) * t32 * M_panels[5] * t39 + T(70) * t28 * M_panels[4] * t30;
    const T t40 = T(28) * t2 * M_panels[16] * t37 + T(8) * tau_lo * t38 * M_panels[17] + T(28) * t33 * M_panels[12] * t1 + T(56) * t32 * M_panels[15] * t39 + T(56) * t35 * M_panels[13] * t36 + t29 * M_panels[10] + T(70) * t28 * M_panels[14] * t30 + T(8) * t34 * M_panels[11] * delta_tau + M_panels[18] * t31;
    G_ap = t40;
    const T t41 = T(1) / a;
    G_E = t29 * M_panels[11] + T(8) * t34 * M_panels[12] * delta_tau + T(8) * tau_lo * M_panels[18] * t38 + T(56) * t35 * M_panels[14] * t36 + T(28) * t33 * M_panels[13] * t1 + T(56) * t32 * M_panels[16] * t39 + T(70) * t28 * M_panels[15] * t30 + M_panels[19] * t31 + T(28) * t2 * t37 * M_panels[17] - t40 * t41 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t42 = t2 * tau_lo;
    const T t43 = T(1) / a;
    const T t44 = T(1) / D;
    const T t45 = T(1) / r0;
    const T t46 = t45 * t45;
    const T t47 = t46 * t46;
    const T t48 = T(1) / r1;
    const T t49 = t48 * t48;
    const T t50 = t49 * t49;
    const T t51 = a_minus_b * t48 + t45 * b;
    const T t52 = a_minus_b * t48 * t49 + t45 * b * t46 + T(2) * t44 * t51 * a;
    const T t53 = T(3) * t45 * b * t47 + T(3) * a_minus_b * t48 * t50 + T(4) * t44 * a * t52;
    const T t54 = t47 * t46;
    const T t55 = t50 * t49;
    const T t56 = T(2) * t44 * a * t53 + T(5) * t45 * b * t54 + T(5) * a_minus_b * t48 * t55;
    const T t57 = t44 * t56 * b + T(5) * t45 * t54 - T(5) * t48 * t55;
    const T t58 = T(6) * t43 * b * t57 + T(7) * t44 * t53 - T(3) * t44 * t56 * c;
    const T t59 = T(3) * t45 * t47 + t44 * b * t53 - T(3) * t48 * t50;
    const T t60 = T(2) * t43 * t58 * b + T(7) * t43 * t59 - T(3) * t43 * t57 * c;
    const T t61 = t44 * t53 * c - T(2) * t43 * t59 * b - T(5) * t44 * t52;
    const T t62 = T(2) * t60 * t43 * b - t43 * t58 * c - T(7) * t43 * t61;
    const T t63 = t44 * b * t52 + t45 * t46 - t48 * t49;
    const T t64 = T(2) * t43 * b * t61 + t43 * t59 * c - T(5) * t63 * t43;
    const T t65 = T(2) * t43 * t62 * b - t60 * t43 * c - T(7) * t43 * t64;
    const T t66 = t1 * t1;
    const T t67 = t66 * delta_tau;
    const T t68 = t2 * t2;
    const T t69 = t68 * tau_lo;
    const T t70 = t1 * delta_tau;
    const T t71 = t42 * t42;
    const T t72 = t71 * tau_lo;
    const T t73 = t68 * t68;
    const T t74 = T(3) * t44 * t51 + T(2) * t63 * t43 * b - t44 * t52 * c;
    const T t75 = T(2) * t43 * b * t64 - T(5) * t74 * t43 - t43 * t61 * c;
    const T t76 = T(7) * t43 * t75 + t43 * t62 * c - T(2) * t43 * b * t65;
    const T t77 = t44 * t51 * b + t45 - t48;
    const T t78 = t63 * t43 * c - T(2) * t74 * t43 * b - T(3) * t43 * t77;
    const T t79 = t43 * t64 * c - T(2) * t43 * b * t75 - T(5) * t43 * t78;
    const T t80 = t43 * t65 * c + T(2) * t43 * b * t76 - T(7) * t79 * t43;
    const T t81 = t70 * t70;
    const T t82 = t81 * delta_tau;
    const T t83 = t66 * t66;
    F = (T(8) / T(15)) * t42 * t43 * t65 * t67 + (T(2) / T(3)) * t68 * t43 * t62 * t66 + (T(8) / T(15)) * t69 * t60 * t43 * t70 + (T(8) / T(35)) * t72 * t43 * t57 * delta_tau + (T(1) / T(35)) * t73 * t44 * t56 + (T(4) / T(15)) * t71 * t43 * t58 * t1 - (T(8) / T(105)) * tau_lo * t43 * t80 * t82 - (T(4) / T(15)) * t2 * t43 * t76 * t81 - (T(1) / T(105)) * t43 * (T(2) * t43 * t80 * b - t43 * c * t76 - T(7) * t43 * (T(5) * t43 * (T(3) * t43 * (J1 + T(2) * t43 * b * t77 - t44 * t51 * c) - T(2) * t43 * b * t78 - t74 * t43 * c) + t43 * t75 * c + T(2) * t79 * t43 * b)) * t83;
    const T t84 = t47 * t47;
    const T t85 = t50 * t50;
    const T t86 = T(35) * t45 * b * t84 + T(8) * t44 * a * t56 + T(35) * a_minus_b * t48 * t85;
    const T t87 = T(35) * t48 * t85 - T(35) * t45 * t84 - t86 * t44 * b;
    const T t88 = t86 * t44 * c + T(2) * t43 * b * t87 - T(9) * t44 * t56;
    const T t89 = t43 * t87 * c + T(9) * t43 * t57 - T(2) * t88 * t43 * b;
    const T t90 = T(2) * t43 * b * t89 + t88 * t43 * c + T(3) * t43 * t58;
    const T t91 = t43 * t89 * c - T(2) * t43 * b * t90 - T(3) * t60 * t43;
    const T t92 = t43 * t90 * c + T(2) * t91 * t43 * b - T(3) * t43 * t62;
    const T t93 = T(2) * t43 * t92 * b - t91 * t43 * c - T(3) * t43 * t65;
    G_ap = (T(1) / T(315)) * t73 * t86 * t44 + (T(8) / T(45)) * t69 * t43 * t89 * t70 + (T(2) / T(9)) * t68 * t43 * t90 * t66 - (T(8) / T(315)) * tau_lo * t93 * t43 * t82 - (T(4) / T(45)) * t71 * t88 * t43 * t1 - (T(4) / T(45)) * t2 * t43 * t92 * t81 - (T(1) / T(315)) * t43 * (T(2) * t93 * t43 * b + T(3) * t43 * t76 - t43 * t92 * c) * t83 - (T(8) / T(45)) * t91 * t42 * t43 * t67 - (T(8) / T(315)) * t72 * t43 * t87 * delta_tau;
    const T t94 = t45 * t45;
    const T t95 = t94 * t94;
    const T t96 = t95 * t95;
    const T t97 = t96 * t45;
    const T t98 = t48 * t48;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t48;
    G_E = (T(1) / T(945)) * (T(168) * t69 * t43 * t58 * t70 + T(280) * t68 * t60 * t43 * t66 + T(105) * t73 * t97 + T(168) * t2 * t43 * t65 * t81 + T(24) * t72 * t44 * t56 * delta_tau + T(280) * t42 * t43 * t62 * t67 + T(168) * t71 * t43 * t57 * t1 - T(105) * t101 * (T(70) * t68 * t66 + t73 + T(8) * tau_lo * t82 + T(28) * t2 * t81 + T(28) * t71 * t1 + t83 + T(56) * t69 * t70 + T(8) * t72 * delta_tau + T(56) * t42 * t67) - T(8) * t43 * t80 * t83 - T(56) * tau_lo * t43 * t76 * t82) * t43;
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
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t3 = T(1) / c;
  const T log_ratio = log(t3 * q1);
  T F;
  const T t4 = T(4) * D - a * a;
  const T t5 = -b * a_minus_b;
  const T t6 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t4 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t7 * delta_tau;
    const T t9 = t2 * t2;
    const T t10 = t1 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t2 * tau_lo;
    const T t13 = t7 * t7;
    const T t14 = t13 * delta_tau;
    const T t15 = t12 * t12;
    const T t16 = t15 * tau_lo;
    const T t17 = t9 * t9;
    const T t18 = t11 * delta_tau;
    const T t19 = t17 * tau_lo;
    const T t20 = t9 * tau_lo;
    F = T(126) * t8 * t9 * M_panels[5] + T(84) * M_panels[6] * t11 * t12 + t14 * M_panels[9] + T(84) * M_panels[3] * t10 * t15 + T(36) * t1 * t16 * M_panels[2] + T(9) * delta_tau * t17 * M_panels[1] + T(36) * t18 * t2 * M_panels[7] + T(9) * t13 * tau_lo * M_panels[8] + M_panels[0] * t19 + T(126) * t7 * t20 * M_panels[4];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t1 * t1;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t2 * t2;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    const T t29 = t2 * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t21 * delta_tau;
    const T t32 = t24 * t24;
    const T t33 = t32 * tau_lo;
    const T t34 = t30 * tau_lo;
    F = t23 * M_panels[9] + T(126) * t21 * t25 * M_panels[4] + T(36) * t28 * t2 * M_panels[7] + T(9) * t22 * tau_lo * M_panels[8] + T(84) * t26 * M_panels[3] * t30 + T(126) * t31 * t24 * M_panels[5] + t33 * M_panels[0] + T(36) * t1 * t34 * M_panels[2] + T(84) * t27 * t29 * M_panels[6] + T(9) * delta_tau * t32 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(D);
    const T t36 = T(1) / t35;
    const T J2 = atan2(t35, c_minus_b) * t36;
    const T t37 = t1 * t1;
    const T t38 = t37 * t37;
    const T t39 = t38 * delta_tau;
    const T t40 = T(1) / a;
    const T t41 = T(1) / q1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t41;
    const T t44 = t3 * t3;
    const T t45 = t44 * t3;
    const T t46 = T(1) / D;
    const T t47 = t3 * b + t41 * a_minus_b + a * J2;
    const T t48 = T(3) * t46 * a * t47 + T(2) * t42 * a_minus_b + T(2) * t44 * b;
    const T t49 = T(8) * t43 * a_minus_b + T(8) * t45 * b + T(5) * t46 * a * t48;
    const T t50 = T(8) * t43 - T(8) * t45 - t46 * b * t49;
    const T t51 = T(2) * t50 * t40 * b + c * t46 * t49 - T(6) * t46 * t48;
    const T t52 = T(2) * t42 - T(2) * t44 - t46 * t48 * b;
    const T t53 = c * t50 * t40 - T(6) * t40 * t52 - T(2) * t51 * t40 * b;
    const T t54 = T(4) * t46 * t47 - T(2) * t40 * b * t52 - c * t46 * t48;
    const T t55 = t51 * c * t40 + T(2) * t53 * t40 * b + T(6) * t54 * t40;
    const T t56 = t3 + t46 * b * t47 - t41;
    const T t57 = T(4) * t40 * t56 + c * t40 * t52 + T(2) * t54 * t40 * b;
    const T t58 = T(2) * t40 * b * t55 + T(6) * t40 * t57 - c * t53 * t40;
    const T t59 = T(2) * t40 * t56 * b + T(2) * J2 - c * t46 * t47;
    const T t60 = T(2) * t40 * t57 * b + T(4) * t40 * t59 - c * t54 * t40;
    const T t61 = T(2) * t40 * b * t58 + T(6) * t40 * t60 - c * t40 * t55;
    const T t62 = t44 * t44;
    const T t63 = t42 * t42;
    const T t64 = T(48) * t62 * b + T(7) * t46 * a * t49 + T(48) * t63 * a_minus_b;
    const T t65 = T(48) * t62 + t64 * t46 * b - T(48) * t63;
    const T t66 = t64 * c * t46 - T(8) * t46 * t49 - T(2) * t65 * t40 * b;
    const T t67 = t65 * c * t40 + T(2) * t66 * t40 * b + T(8) * t50 * t40;
    const T t68 = T(8) * t51 * t40 + T(2) * t40 * b * t67 - c * t66 * t40;
    const T t69 = c * t40 * t67 + T(8) * t53 * t40 - T(2) * t40 * b * t68;
    const T t70 = c * t40 * t68 + T(8) * t40 * t55 + T(2) * t69 * t40 * b;
    const T t71 = T(2) * t40 * b * t70 + T(8) * t40 * t58 - c * t69 * t40;
    const T t72 = T(8) * t40 * t61 + T(2) * t40 * t71 * b - c * t40 * t70;
    const T t73 = t1 * delta_tau;
    const T t74 = t73 * t73;
    const T t75 = t2 * tau_lo;
    const T t76 = t74 * delta_tau;
    const T t77 = t2 * t2;
    const T t78 = t77 * t77;
    const T t79 = t78 * tau_lo;
    const T t80 = t37 * delta_tau;
    const T t81 = t75 * t75;
    const T t82 = t81 * tau_lo;
    const T t83 = t77 * tau_lo;
    F = (T(1) / T(384)) * t39 * (T(2) * t40 * b * t72 + T(8) * t40 * (T(6) * t40 * (T(2) * t40 * b * t60 + T(4) * t40 * (T(2) * t40 * b * t59 + t40 * (log_ratio + T(2) * J2 * b) - c * t40 * t56) - c * t40 * t57) + T(2) * t40 * t61 * b - c * t40 * t58) - c * t40 * t71) * t40 + (T(7) / T(32)) * t74 * t75 * t40 * t70 + (T(3) / T(32)) * t76 * t2 * t40 * t71 + (T(3) / T(128)) * t65 * delta_tau * t78 * t40 + (T(1) / T(384)) * t64 * t79 * t46 + (T(21) / T(64)) * t80 * t77 * t69 * t40 + (T(3) / T(128)) * t38 * tau_lo * t40 * t72 - (T(3) / T(32)) * t1 * t82 * t66 * t40 - (T(21) / T(64)) * t37 * t83 * t40 * t68 - (T(7) / T(32)) * t73 * t81 * t40 * t67;
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
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
    const T t6 = t2 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t1 * t1;
    const T t10 = t2 * t2;
    const T t11 = t10 * tau_lo;
    const T t12 = t1 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t13 * delta_tau;
    const T t15 = t10 * t10;
    const T t16 = t9 * delta_tau;
    const T t17 = t9 * t9;
    const T t18 = t17 * delta_tau;
    const T t19 = t15 * tau_lo;
    const T t20 = T(36) * t1 * t8 * M_panels[13] + T(126) * M_panels[15] * t9 * t11 + T(36) * M_panels[18] * t14 * t2 + T(9) * delta_tau * M_panels[12] * t15 + T(126) * t16 * t10 * M_panels[16] + T(84) * t12 * t7 * M_panels[14] + t18 * M_panels[20] + T(9) * t17 * tau_lo * M_panels[19] + T(84) * t13 * t6 * M_panels[17] + t19 * M_panels[11];
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = T(36) * t14 * t2 * M_panels[19] + T(126) * t9 * t11 * M_panels[16] + T(84) * M_panels[18] * t13 * t6 + T(9) * t17 * tau_lo * M_panels[20] + T(36) * t1 * t8 * M_panels[14] + t18 * M_panels[21] + M_panels[12] * t19 + T(126) * t16 * t10 * M_panels[17] + T(84) * M_panels[15] * t12 * t7 + T(9) * delta_tau * t15 * M_panels[13] - t21 * b * t20;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t2 * tau_lo;
    const T t25 = t1 * t1;
    const T t26 = t25 * delta_tau;
    const T t27 = t2 * t2;
    const T t28 = t24 * t24;
    const T t29 = t28 * tau_lo;
    const T t30 = t27 * t27;
    const T t31 = t23 * delta_tau;
    const T t32 = t25 * t25;
    const T t33 = t27 * tau_lo;
    const T t34 = t30 * tau_lo;
    const T t35 = t32 * delta_tau;
    const T t36 = T(84) * t23 * M_panels[17] * t24 + T(126) * t26 * t27 * M_panels[16] + T(36) * t1 * t29 * M_panels[13] + T(9) * delta_tau * t30 * M_panels[12] + T(84) * t22 * t28 * M_panels[14] + T(36) * t31 * t2 * M_panels[18] + T(9) * t32 * tau_lo * M_panels[19] + T(126) * t25 * t33 * M_panels[15] + t34 * M_panels[11] + t35 * M_panels[20];
    G_ap = t36;
    const T t37 = T(1) / a;
    G_E = T(9) * t32 * tau_lo * M_panels[20] + T(126) * t26 * M_panels[17] * t27 + T(84) * t22 * t28 * M_panels[15] + T(36) * t31 * t2 * M_panels[19] + t35 * M_panels[21] + t34 * M_panels[12] + T(126) * t25 * t33 * M_panels[16] + T(84) * t23 * t24 * M_panels[18] + T(36) * t1 * t29 * M_panels[14] + T(9) * delta_tau * t30 * M_panels[13] - t37 * b * t36;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = t39 * atan2(t38, c_minus_b);
    const T t40 = T(1) / D;
    const T t41 = t2 * t2;
    const T t42 = t41 * t41;
    const T t43 = t42 * tau_lo;
    const T t44 = T(1) / q1;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t44;
    const T t48 = t45 * t44;
    const T t49 = T(1) / c;
    const T t50 = t49 * t49;
    const T t51 = t50 * t49;
    const T t52 = a * J2 + b * t49 + a_minus_b * t44;
    const T t53 = T(3) * t52 * t40 * a + T(2) * a_minus_b * t45 + T(2) * b * t50;
    const T t54 = T(8) * a_minus_b * t48 + T(8) * b * t51 + T(5) * t40 * a * t53;
    const T t55 = t50 * t50;
    const T t56 = T(48) * a_minus_b * t46 + T(7) * t40 * a * t54 + T(48) * b * t55;
    const T t57 = t55 * t49;
    const T t58 = T(128) * a_minus_b * t47 + T(3) * t40 * t56 * a + T(128) * b * t57;
    const T t59 = T(1) / a;
    const T t60 = t40 * b * t58 + T(128) * t57 - T(128) * t47;
    const T t61 = t1 * delta_tau;
    const T t62 = t61 * t61;
    const T t63 = t62 * delta_tau;
    const T t64 = T(2) * t50 + t40 * b * t53 - T(2) * t45;
    const T t65 = t40 * t54 * b + T(8) * t51 - T(8) * t48;
    const T t66 = T(2) * t59 * t65 * b + T(6) * t40 * t53 - t40 * t54 * c;
    const T t67 = T(6) * t59 * t64 + T(2) * t59 * b * t66 - t59 * t65 * c;
    const T t68 = T(48) * t55 + t40 * t56 * b - T(48) * t46;
    const T t69 = t40 * t56 * c - T(8) * t40 * t54 - T(2) * t68 * t59 * b;
    const T t70 = T(2) * t59 * b * t69 + t68 * t59 * c - T(8) * t59 * t65;
    const T t71 = T(8) * t59 * t66 + t59 * t69 * c - T(2) * t59 * b * t70;
    const T t72 = T(8) * t59 * t67 + t59 * t70 * c + T(2) * t59 * b * t71;
    const T t73 = T(10) * t40 * t56 + T(6) * t59 * b * t60 - T(3) * t40 * t58 * c;
    const T t74 = T(3) * t59 * c * t60 - T(10) * t68 * t59 - T(2) * t59 * t73 * b;
    const T t75 = T(2) * t59 * b * t74 + t59 * t73 * c + T(10) * t59 * t69;
    const T t76 = T(10) * t59 * t70 + T(2) * t59 * b * t75 - t59 * t74 * c;
    const T t77 = t59 * t75 * c + T(10) * t59 * t71 - T(2) * t76 * t59 * b;
    const T t78 = T(10) * t59 * t72 + T(2) * t59 * b * t77 + t76 * t59 * c;
    const T t79 = t2 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = t80 * tau_lo;
    const T t82 = t1 * t1;
    const T t83 = t82 * t82;
    const T t84 = T(4) * t52 * t40 + T(2) * t59 * b * t64 - t40 * t53 * c;
    const T t85 = T(6) * t59 * t84 + T(2) * t59 * t67 * b - t59 * t66 * c;
    const T t86 = t59 * c * t71 - T(8) * t59 * t85 - T(2) * t59 * b * t72;
    const T t87 = T(10) * t59 * t86 + t59 * t77 * c - T(2) * t59 * b * t78;
    const T t88 = t83 * delta_tau;
    const T t89 = t44 - t49 - t52 * t40 * b;
    const T t90 = t59 * c * t64 + T(4) * t89 * t59 - T(2) * t59 * b * t84;
    const T t91 = t59 * t67 * c + T(6) * t90 * t59 - T(2) * t59 * b * t85;
    const T t92 = T(8) * t59 * t91 + t59 * t72 * c + T(2) * t59 * b * t86;
    const T t93 = t41 * tau_lo;
    const T t94 = t82 * delta_tau;
    G_ap = (T(1) / T(1280)) * t40 * t43 * t58 + (T(9) / T(1280)) * delta_tau * t42 * t59 * t60 + (T(3) / T(320)) * t63 * t2 * t59 * t78 + (T(3) / T(320)) * t1 * t81 * t59 * t73 + (T(7) / T(320)) * t62 * t79 * t59 * t77 - (T(7) / T(320)) * t61 * t80 * t59 * t74 - (T(3) / T(1280)) * t83 * tau_lo * t87 * t59 - (T(1) / T(3840)) * t88 * (t59 * t78 * c + T(2) * t87 * t59 * b + T(10) * t92 * t59) * t59 - (T(21) / T(640)) * t82 * t93 * t59 * t75 - (T(21) / T(640)) * t76 * t94 * t41 * t59;
    G_E = -(T(1) / T(1280)) * t59 * (T(84) * t61 * t80 * t59 * t69 + T(24) * t83 * t92 * tau_lo * t59 + T(3) * t88 * t59 * (T(8) * t59 * (T(6) * t59 * (T(2) * t90 * t59 * b + t59 * t84 * c + T(4) * t59 * (T(2) * t89 * t59 * b + t52 * t40 * c - T(2) * J2)) + t59 * t85 * c + T(2) * t59 * t91 * b) + T(2) * t92 * t59 * b - t59 * t86 * c) + T(84) * t63 * t2 * t59 * t86 + T(128) * (T(9) * delta_tau * t42 + T(9) * t83 * tau_lo + t88 + T(84) * t61 * t80 + T(36) * t63 * t2 + t43 + T(84) * t62 * t79 + T(36) * t1 * t81 + T(126) * t94 * t41 + T(126) * t82 * t93) * t47 + T(168) * t82 * t93 * t59 * t70 - T(210) * t94 * t41 * t59 * t71 - T(168) * t62 * t79 * t59 * t72 - T(24) * t68 * t1 * t81 * t59 - T(3) * delta_tau * t40 * t56 * t42 - T(128) * t43 * t57);
  }
  const T t95 = T(1) / a;
  const T t_star = t95 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t96 = sigma2 * sigma2;
  const T t97 = t96 * t96;
  const T t98 = t97 * sigma2;
  const T g_factor = -T(10) * t98 * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
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
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
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
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * t2;
    const T t8 = t1 * t1;
    const T t9 = t8 * delta_tau;
    const T t10 = t8 * t8;
    const T t11 = t10 * delta_tau;
    const T t12 = t2 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t1 * delta_tau;
    const T t15 = t7 * tau_lo;
    const T t16 = t14 * t14;
    const T t17 = t16 * delta_tau;
    const T t18 = t7 * t7;
    const T t19 = t18 * tau_lo;
    const T t20 = t13 * tau_lo;
    F = T(126) * t7 * M_panels[5] * t9 + M_panels[9] * t11 + T(84) * t13 * M_panels[3] * t14 + T(126) * t15 * M_panels[4] * t8 + T(84) * t12 * M_panels[6] * t16 + T(36) * t2 * M_panels[7] * t17 + T(9) * tau_lo * M_panels[8] * t10 + T(9) * t18 * M_panels[1] * delta_tau + t19 * M_panels[0] + T(36) * t20 * M_panels[2] * t1;
    const T t21 = T(36) * t20 * M_panels[13] * t1 + T(84) * t12 * M_panels[17] * t16 + T(84) * t13 * M_panels[14] * t14 + T(126) * t15 * M_panels[15] * t8 + M_panels[20] * t11 + M_panels[11] * t19 + T(36) * t2 * M_panels[18] * t17 + T(9) * tau_lo * M_panels[19] * t10 + T(126) * t7 * M_panels[16] * t9 + T(9) * t18 * M_panels[12] * delta_tau;
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(9) * tau_lo * M_panels[20] * t10 + T(84) * t13 * M_panels[15] * t14 + T(36) * t2 * M_panels[19] * t17 + T(36) * t20 * M_panels[14] * t1 + t19 * M_panels[12] + T(9) * t18 * M_panels[13] * delta_tau + M_panels[21] * t11 + T(84) * t12 * M_panels[18] * t16 + T(126) * t7 * M_panels[17] * t9 + T(126) * t15 * M_panels[16] * t8 - t22 * b * t21;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t23 = t2 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    const T t29 = t1 * t1;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = t2 * t2;
    const T t33 = t32 * t32;
    const T t34 = t32 * tau_lo;
    const T t35 = t29 * delta_tau;
    const T t36 = t33 * tau_lo;
    F = T(36) * t25 * M_panels[2] * t1 + T(84) * t24 * M_panels[3] * t26 + T(36) * t2 * M_panels[7] * t28 + T(9) * tau_lo * t30 * M_panels[8] + M_panels[9] * t31 + T(9) * t33 * M_panels[1] * delta_tau + T(126) * t34 * M_panels[4] * t29 + T(126) * t32 * M_panels[5] * t35 + T(84) * t23 * M_panels[6] * t27 + t36 * M_panels[0];
    const T t37 = M_panels[20] * t31 + t36 * M_panels[11] + T(84) * t23 * t27 * M_panels[17] + T(9) * t33 * M_panels[12] * delta_tau + T(126) * t34 * M_panels[15] * t29 + T(126) * t32 * M_panels[16] * t35 + T(84) * t24 * M_panels[14] * t26 + T(36) * t25 * M_panels[13] * t1 + T(36) * t2 * M_panels[18] * t28 + T(9) * tau_lo * M_panels[19] * t30;
    G_ap = t37;
    const T t38 = T(1) / a;
    G_E = T(126) * t34 * M_panels[16] * t29 + T(9) * tau_lo * M_panels[20] * t30 + T(84) * t23 * M_panels[18] * t27 + M_panels[21] * t31 + T(84) * t24 * M_panels[15] * t26 + t36 * M_panels[12] + T(126) * t32 * t35 * M_panels[17] + T(36) * t2 * M_panels[19] * t28 + T(36) * t25 * M_panels[14] * t1 + T(9) * t33 * M_panels[13] * delta_tau - t38 * b * t37;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = t40 * atan2(t39, c_minus_b);
    const T t41 = T(1) / a;
    const T t42 = T(1) / q1;
    const T t43 = t42 * t42;
    const T t44 = t3 * t3;
    const T t45 = T(1) / D;
    const T t46 = a * J2 + b * t3 + a_minus_b * t42;
    const T t47 = T(2) * a_minus_b * t43 + T(2) * b * t44 + T(3) * t45 * a * t46;
    const T t48 = T(2) * t43 - T(2) * t44 - t45 * b * t47;
    const T t49 = t3 + t45 * t46 * b - t42;
    const T t50 = T(2) * t41 * t48 * b + t45 * c * t47 - T(4) * t45 * t46;
    const T t51 = t41 * t48 * c + T(4) * t49 * t41 - T(2) * t50 * t41 * b;
    const T t52 = t43 * t42;
    const T t53 = t44 * t3;
    const T t54 = T(8) * a_minus_b * t52 + T(8) * b * t53 + T(5) * t45 * a * t47;
    const T t55 = T(8) * t52 - t45 * b * t54 - T(8) * t53;
    const T t56 = T(2) * t41 * b * t55 + t45 * t54 * c - T(6) * t45 * t47;
    const T t57 = T(6) * t41 * t48 + T(2) * t41 * b * t56 - t41 * c * t55;
    const T t58 = t41 * t56 * c - T(6) * t50 * t41 - T(2) * t41 * b * t57;
    const T t59 = T(6) * t41 * t51 + t41 * t57 * c + T(2) * t41 * b * t58;
    const T t60 = T(2) * t49 * t41 * b + T(2) * J2 - t45 * t46 * c;
    const T t61 = T(4) * t41 * t60 + T(2) * t41 * b * t51 + t50 * t41 * c;
    const T t62 = T(2) * t41 * b * t59 + T(6) * t41 * t61 - t41 * c * t58;
    const T t63 = t43 * t43;
    const T t64 = t44 * t44;
    const T t65 = T(48) * b * t64 + T(48) * a_minus_b * t63 + T(7) * t45 * a * t54;
    const T t66 = T(48) * t63 - T(48) * t64 - t45 * t65 * b;
    const T t67 = T(2) * t41 * b * t66 + t45 * t65 * c - T(8) * t45 * t54;
    const T t68 = T(2) * t41 * b * t67 + T(8) * t41 * t55 - t41 * c * t66;
    const T t69 = T(2) * t41 * t68 * b + T(8) * t41 * t56 - t41 * c * t67;
    const T t70 = T(2) * t41 * b * t69 + T(8) * t41 * t57 - t41 * t68 * c;
    const T t71 = t41 * c * t69 + T(8) * t41 * t58 - T(2) * t70 * t41 * b;
    const T t72 = t70 * t41 * c + T(8) * t41 * t59 + T(2) * t41 * b * t71;
    const T t73 = T(8) * t41 * t62 + T(2) * t41 * b * t72 - t41 * t71 * c;
    const T t74 = t1 * t1;
    const T t75 = t74 * t74;
    const T t76 = t2 * t2;
    const T t77 = t76 * t76;
    const T t78 = t77 * tau_lo;
    const T t79 = t2 * tau_lo;
    const T t80 = t1 * delta_tau;
    const T t81 = t80 * t80;
    const T t82 = t81 * delta_tau;
    const T t83 = t75 * delta_tau;
    const T t84 = t76 * tau_lo;
    const T t85 = t79 * t79;
    const T t86 = t85 * tau_lo;
    const T t87 = t74 * delta_tau;
    F = (T(3) / T(128)) * t73 * tau_lo * t41 * t75 + (T(1) / T(384)) * t78 * t45 * t65 + (T(7) / T(32)) * t79 * t41 * t71 * t81 + (T(3) / T(32)) * t2 * t41 * t72 * t82 - (T(3) / T(128)) * t77 * t41 * t66 * delta_tau - (T(1) / T(384)) * (t41 * t72 * c - T(8) * t41 * (T(6) * t41 * (T(2) * t41 * t61 * b - T(4) * t41 * (t49 * t41 * c - T(2) * t41 * b * t60 - (log_ratio + T(2) * b * J2) * t41) - t41 * t51 * c) + T(2) * t41 * b * t62 - t41 * c * t59) - T(2) * t73 * t41 * b) * t41 * t83 - (T(21) / T(64)) * t84 * t41 * t69 * t74 - (T(3) / T(32)) * t86 * t41 * t1 * t67 - (T(21) / T(64)) * t76 * t70 * t41 * t87 - (T(7) / T(32)) * t85 * t41 * t68 * t80;
    const T t88 = t63 * t42;
    const T t89 = t64 * t3;
    const T t90 = T(128) * b * t89 + T(3) * t45 * t65 * a + T(128) * a_minus_b * t88;
    const T t91 = T(128) * t88 - T(128) * t89 - t45 * t90 * b;
    const T t92 = T(6) * t41 * t91 * b + T(3) * t45 * t90 * c - T(10) * t45 * t65;
    const T t93 = T(2) * t41 * b * t92 + T(10) * t41 * t66 - T(3) * t41 * t91 * c;
    const T t94 = T(2) * t93 * t41 * b + T(10) * t41 * t67 - t41 * c * t92;
    const T t95 = T(2) * t94 * t41 * b + T(10) * t41 * t68 - t93 * t41 * c;
    const T t96 = T(2) * t95 * t41 * b + T(10) * t41 * t69 - t94 * t41 * c;
    const T t97 = t95 * t41 * c - T(10) * t70 * t41 - T(2) * t41 * b * t96;
    const T t98 = T(10) * t41 * t71 + T(2) * t41 * t97 * b + t41 * t96 * c;
    G_ap = (T(1) / T(3840)) * t41 * (T(10) * t41 * t72 + T(2) * t41 * b * t98 - t41 * t97 * c) * t83 + (T(3) / T(320)) * t2 * t41 * t97 * t82 + (T(1) / T(1280)) * t78 * t45 * t90 + (T(3) / T(1280)) * tau_lo * t41 * t98 * t75 - (T(21) / T(640)) * t76 * t95 * t41 * t87 - (T(7) / T(320)) * t79 * t41 * t96 * t81 - (T(9) / T(1280)) * t77 * t41 * t91 * delta_tau - (T(21) / T(640)) * t84 * t94 * t41 * t74 - (T(3) / T(320)) * t86 * t41 * t92 * t1 - (T(7) / T(320)) * t85 * t93 * t41 * t80;
    G_E = (T(1) / T(1280)) * t41 * (T(128) * t78 * t89 + T(84) * t2 * t41 * t71 * t82 + T(3) * t73 * t41 * t83 + T(24) * tau_lo * t41 * t72 * t75 + T(3) * t77 * t45 * t65 * delta_tau - T(210) * t76 * t41 * t69 * t87 - T(168) * t79 * t70 * t41 * t81 - T(128) * (T(126) * t84 * t74 + t78 + T(126) * t76 * t87 + T(36) * t86 * t1 + T(84) * t85 * t80 + T(36) * t2 * t82 + T(9) * tau_lo * t75 + T(9) * t77 * delta_tau + t83 + T(84) * t79 * t81) * t88 - T(84) * t85 * t41 * t80 * t67 - T(168) * t84 * t41 * t68 * t74 - T(24) * t86 * t41 * t66 * t1);
  }
  const T t99 = T(1) / a;
  const T t_star = t99 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - ab2 * t_star;
  const T t100 = sigma2 * sigma2;
  const T t101 = t100 * t100;
  const T t102 = t101 * sigma2;
  const T g_factor = -T(10) * t102 * length;
  f = t102 * F * length;
  grad[0] = (G_ap * foot0 - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

}  // namespace skelconv::generated
