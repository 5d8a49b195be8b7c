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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + sigma2 * delta_tau * delta_tau;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T c = sigma2 * tau_lo * tau_lo + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  const T log_ratio = log(q1 / c);
  T F;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
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
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    F = (T(1) / T(2)) * (log_ratio + T(2) * J2 * b) * delta_tau / a + J2 * tau_lo;
  }
  f = sigma2 * length * F;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t4 = delta_tau * M_panels[4] + tau_lo * M_panels[3];
    G_ap = t4;
    const T t5 = T(1) / a;
    G_E = tau_lo * M_panels[4] + M_panels[5] * delta_tau - t5 * t4 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t6 = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = tau_lo * M_panels[4] + delta_tau * M_panels[5] - t7 * t6 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    const T t10 = T(1) / D;
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = t11 * b + a_minus_b * t12 + a * J2;
    const T t14 = T(1) / a;
    G_ap = (T(1) / T(2)) * (t10 * b * t13 + t11 - t12) * delta_tau * t14 + (T(1) / T(2)) * t10 * tau_lo * t13;
    G_E = (T(1) / T(2)) * t14 * (t11 * tau_lo + delta_tau * J2 - (delta_tau + tau_lo) * t12);
  }
  const T t15 = T(1) / a;
  const T t_star = t15 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
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
    G_E = M_panels[4] * tau_lo + delta_tau * M_panels[5] - b * t6 * t5;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t7 = M_panels[3] * tau_lo + M_panels[4] * delta_tau;
    G_ap = t7;
    const T t8 = T(1) / a;
    G_E = M_panels[4] * tau_lo + delta_tau * M_panels[5] - b * t7 * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / a;
    F = J2 * tau_lo + (T(1) / T(2)) * (T(2) * b * J2 + log_ratio) * delta_tau * t11;
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = b * t1 + t13 * a_minus_b + J2 * a;
    G_ap = (T(1) / T(2)) * tau_lo * t12 * t14 + (T(1) / T(2)) * (t1 + b * t12 * t14 - t13) * delta_tau * t11;
    G_E = -(T(1) / T(2)) * ((delta_tau + tau_lo) * t13 - t1 * tau_lo - delta_tau * J2) * t11;
  }
  const T t15 = T(1) / a;
  const T t_star = b * t15;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(2) * length * sigma2;
  f = length * sigma2 * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
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
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
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
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t2 * M_panels[0] + t1 * M_panels[2] + T(2) * M_panels[1] * delta_tau * tau_lo;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t1 * M_panels[2] + t2 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 * a_minus_b + t16 * b;
    const T t18 = T(1) / a;
    const T t19 = t15 - t16 - t14 * t17 * b;
    F = t2 * t14 * t17 - t1 * t18 * (t14 * t17 * c + T(2) * t18 * b * t19 - J1) - T(2) * delta_tau * tau_lo * t18 * t19;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
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
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
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
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * M_panels[4] + M_panels[6] * t1 + T(2) * delta_tau * tau_lo * M_panels[5];
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = T(2) * M_panels[6] * delta_tau * tau_lo + t1 * M_panels[7] + t2 * M_panels[5] - t7 * t6 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t1 * M_panels[6] + T(2) * M_panels[5] * delta_tau * tau_lo + M_panels[4] * t2;
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = t1 * M_panels[7] + T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[5] * t2 - t9 * t8 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / D;
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 * a_minus_b + b * t12;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * t10 * a * t13 + t14 * b * t12 + t11 * a_minus_b * t15;
    const T t17 = t14 * t12 + t10 * t16 * b - t11 * t15;
    const T t18 = T(1) / a;
    G_ap = (T(1) / T(3)) * t10 * t2 * t16 + (T(2) / T(3)) * t17 * delta_tau * tau_lo * t18 - (T(1) / T(3)) * (c * t10 * t16 - T(3) * t10 * t13 - T(2) * t17 * t18 * b) * t1 * t18;
    const T t19 = t12 * t12;
    const T t20 = t19 * t12;
    const T t21 = t11 * t11;
    const T t22 = t21 * t11;
    G_E = (T(1) / T(3)) * (T(2) * (t10 * t13 * b + t12 - t11) * t1 * t18 + T(2) * delta_tau * t10 * tau_lo * t13 + t2 * t20 - t22 * (T(2) * delta_tau * tau_lo + t1 + t2)) * t18;
  }
  const T t23 = T(1) / a;
  const T t_star = t23 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
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
    X = (a_minus_b - b) * t7 / (t8 - b * r1);
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
    F = T(2) * M_panels[1] * delta_tau * tau_lo + t2 * M_panels[0] + M_panels[2] * t1;
    const T t14 = M_panels[4] * t2 + T(2) * M_panels[5] * delta_tau * tau_lo + t1 * M_panels[6];
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[7] * t1 + M_panels[5] * t2 - b * t14 * t15;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * t1 + M_panels[0] * t2 + T(2) * delta_tau * tau_lo * M_panels[1];
    const T t16 = M_panels[6] * t1 + T(2) * delta_tau * tau_lo * M_panels[5] + t2 * M_panels[4];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = T(2) * M_panels[6] * delta_tau * tau_lo + t2 * M_panels[5] + t1 * M_panels[7] - t16 * b * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = a_minus_b * t19 + b * t20;
    const T t22 = T(1) / D;
    const T t23 = t21 * b * t22 + t20 - t19;
    F = T(2) * delta_tau * tau_lo * t18 * t23 + (J1 + T(2) * b * t18 * t23 - t21 * c * t22) * t1 * t18 + t21 * t2 * t22;
    const T t24 = t20 * t20;
    const T t25 = t19 * t19;
    const T t26 = b * t24 * t20 + T(2) * t21 * t22 * a + a_minus_b * t25 * t19;
    const T t27 = t24 * t20 + b * t26 * t22 - t25 * t19;
    G_ap = (T(1) / T(3)) * t26 * t2 * t22 + (T(2) / T(3)) * t27 * delta_tau * tau_lo * t18 - (T(1) / T(3)) * (t26 * c * t22 - T(2) * b * t27 * t18 - T(3) * t21 * t22) * t1 * t18;
    const T t28 = t20 * t20;
    const T t29 = t28 * t20;
    const T t30 = t19 * t19;
    const T t31 = t30 * t19;
    G_E = (T(1) / T(3)) * t18 * (T(2) * t21 * delta_tau * tau_lo * t22 + T(2) * t1 * t18 * t23 + t2 * t29 - (T(2) * delta_tau * tau_lo + t1 + t2) * t31);
  }
  const T t32 = T(1) / a;
  const T t_star = b * t32;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  f = in.sigma * length * sigma2 * F;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
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
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
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
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    F = M_panels[3] * t7 + T(3) * tau_lo * t1 * M_panels[2] + T(3) * t2 * delta_tau * M_panels[1] + t8 * M_panels[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t9 = t1 * delta_tau;
    const T t10 = t2 * tau_lo;
    F = T(3) * t2 * delta_tau * M_panels[1] + t9 * M_panels[3] + t10 * M_panels[0] + T(3) * tau_lo * t1 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = b * t3 + t15 * a_minus_b + a * J2;
    const T t17 = t3 + t14 * b * t16 - t15;
    const T t18 = T(2) * t17 * t13 * b + T(2) * J2 - t14 * t16 * c;
    const T t19 = t1 * delta_tau;
    const T t20 = t2 * tau_lo;
    F = (T(3) / T(2)) * tau_lo * t1 * t13 * t18 + (T(3) / T(2)) * t17 * t2 * delta_tau * t13 + (T(1) / T(2)) * t19 * t13 * (t13 * (T(2) * J2 * b + log_ratio) + T(2) * t13 * t18 * b - t17 * t13 * c) + (T(1) / T(2)) * t20 * t14 * t16;
  }
  f = sigma2 * sigma2 * F * length;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
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
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * tau_lo;
    const T t7 = t1 * delta_tau;
    const T t8 = T(3) * M_panels[7] * t1 * tau_lo + M_panels[5] * t6 + T(3) * delta_tau * t2 * M_panels[6] + M_panels[8] * t7;
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = t7 * M_panels[9] + T(3) * M_panels[7] * delta_tau * t2 + T(3) * M_panels[8] * t1 * tau_lo + t6 * M_panels[6] - t9 * b * t8;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t10 = t1 * delta_tau;
    const T t11 = t2 * tau_lo;
    const T t12 = T(3) * M_panels[6] * delta_tau * t2 + T(3) * M_panels[7] * t1 * tau_lo + M_panels[8] * t10 + M_panels[5] * t11;
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = T(3) * M_panels[7] * delta_tau * t2 + M_panels[6] * t11 + T(3) * M_panels[8] * t1 * tau_lo + M_panels[9] * t10 - t12 * t13 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, c_minus_b) * t15;
    const T t16 = T(1) / a;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = T(1) / q1;
    const T t20 = t19 * t19;
    const T t21 = t19 * a_minus_b + b * t17 + a * J2;
    const T t22 = T(1) / D;
    const T t23 = T(2) * b * t18 + T(2) * t20 * a_minus_b + T(3) * a * t21 * t22;
    const T t24 = T(2) * t18 + b * t23 * t22 - T(2) * t20;
    const T t25 = T(2) * t16 * t24 * b + T(4) * t21 * t22 - t23 * c * t22;
    const T t26 = t2 * tau_lo;
    const T t27 = b * t21 * t22 + t17 - t19;
    const T t28 = t1 * delta_tau;
    G_ap = (T(3) / T(8)) * t16 * t24 * delta_tau * t2 + (T(3) / T(8)) * t16 * t1 * tau_lo * t25 + (T(1) / T(8)) * t23 * t22 * t26 + (T(1) / T(8)) * t16 * (T(4) * t16 * t27 + T(2) * t16 * b * t25 - t16 * t24 * c) * t28;
    G_E = (T(1) / T(8)) * t16 * (T(3) * t21 * delta_tau * t22 * t2 + T(3) * t16 * (T(2) * J2 + T(2) * t16 * b * t27 - c * t21 * t22) * t28 + T(2) * t18 * t26 + T(6) * t16 * t27 * t1 * tau_lo - T(2) * t20 * (T(3) * t1 * tau_lo + t28 + t26 + T(3) * delta_tau * t2));
  }
  const T t29 = T(1) / a;
  const T t_star = t29 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(4) * sigma2 * sigma2 * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
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
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    F = T(3) * M_panels[1] * delta_tau * t2 + M_panels[0] * t7 + T(3) * t1 * tau_lo * M_panels[2] + M_panels[3] * t8;
    const T t9 = T(3) * M_panels[6] * delta_tau * t2 + t8 * M_panels[8] + t7 * M_panels[5] + T(3) * M_panels[7] * t1 * tau_lo;
    G_ap = t9;
    const T t10 = T(1) / a;
    G_E = M_panels[9] * t8 + T(3) * M_panels[7] * delta_tau * t2 + M_panels[6] * t7 + T(3) * t1 * tau_lo * M_panels[8] - b * t9 * t10;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t11 = t2 * tau_lo;
    const T t12 = t1 * delta_tau;
    F = T(3) * M_panels[2] * t1 * tau_lo + M_panels[0] * t11 + M_panels[3] * t12 + T(3) * delta_tau * M_panels[1] * t2;
    const T t13 = T(3) * M_panels[6] * delta_tau * t2 + M_panels[5] * t11 + T(3) * t1 * M_panels[7] * tau_lo + t12 * M_panels[8];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = M_panels[9] * t12 + M_panels[6] * t11 + T(3) * t1 * tau_lo * M_panels[8] + T(3) * delta_tau * M_panels[7] * t2 - b * t13 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / q1;
    const T t18 = b * t3 + a_minus_b * t17 + J2 * a;
    const T t19 = t2 * tau_lo;
    const T t20 = T(1) / D;
    const T t21 = T(1) / a;
    const T t22 = t17 - t3 - b * t18 * t20;
    const T t23 = t18 * c * t20 + T(2) * b * t22 * t21 - T(2) * J2;
    const T t24 = t1 * delta_tau;
    F = (T(1) / T(2)) * t18 * t19 * t20 - (T(3) / T(2)) * t1 * tau_lo * t21 * t23 - (T(3) / T(2)) * t22 * delta_tau * t2 * t21 - (T(1) / T(2)) * (T(2) * b * t21 * t23 - (T(2) * b * J2 + log_ratio) * t21 - t22 * c * t21) * t24 * t21;
    const T t25 = t3 * t3;
    const T t26 = t17 * t17;
    const T t27 = T(3) * t18 * t20 * a + T(2) * a_minus_b * t26 + T(2) * b * t25;
    const T t28 = T(2) * t25 + b * t27 * t20 - T(2) * t26;
    const T t29 = T(2) * b * t21 * t28 + T(4) * t18 * t20 - t27 * c * t20;
    G_ap = (T(1) / T(8)) * (T(2) * b * t29 * t21 - c * t21 * t28 - T(4) * t22 * t21) * t24 * t21 + (T(3) / T(8)) * delta_tau * t2 * t21 * t28 + (T(1) / T(8)) * t27 * t19 * t20 + (T(3) / T(8)) * t29 * t1 * tau_lo * t21;
    G_E = (T(1) / T(8)) * (T(2) * t25 * t19 + T(3) * t18 * delta_tau * t2 * t20 - T(6) * t22 * t1 * tau_lo * t21 - T(2) * t26 * (T(3) * t1 * tau_lo + t19 + t24 + T(3) * delta_tau * t2) - T(3) * t24 * t21 * t23) * t21;
  }
  const T t30 = T(1) / a;
  const T t_star = b * t30;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t31 = sigma2 * sigma2;
  const T g_factor = -T(4) * length * t31;
  f = F * length * t31;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
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
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
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
  const T J1 = asinh(X) * t10;
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * t2;
    const T t15 = t2 * tau_lo;
    const T t16 = t1 * delta_tau;
    const T t17 = t1 * t1;
    F = M_panels[0] * t14 + T(6) * t2 * t1 * M_panels[2] + T(4) * M_panels[1] * t15 * delta_tau + T(4) * M_panels[3] * tau_lo * t16 + M_panels[4] * t17;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * t2;
    const T t19 = t1 * t1;
    const T t20 = t2 * tau_lo;
    const T t21 = t1 * delta_tau;
    F = M_panels[0] * t18 + T(6) * M_panels[2] * t2 * t1 + M_panels[4] * t19 + T(4) * M_panels[1] * t20 * delta_tau + T(4) * tau_lo * t21 * M_panels[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / r1;
    const T t23 = T(1) / r0;
    const T t24 = t22 * a_minus_b + t23 * b;
    const T t25 = T(1) / D;
    const T t26 = t23 * t23;
    const T t27 = t22 * t22;
    const T t28 = T(2) * t24 * t25 * a + t23 * b * t26 + t22 * a_minus_b * t27;
    const T t29 = t2 * t2;
    const T t30 = t22 * t27 - t23 * t26 - b * t28 * t25;
    const T t31 = T(1) / a;
    const T t32 = T(2) * b * t30 * t31 + t28 * c * t25 - T(3) * t24 * t25;
    const T t33 = t22 - b * t24 * t25 - t23;
    const T t34 = t30 * c * t31 - T(2) * t32 * b * t31 - T(3) * t33 * t31;
    const T t35 = t1 * t1;
    const T t36 = t1 * delta_tau;
    const T t37 = t2 * tau_lo;
    F = (T(1) / T(3)) * t28 * t29 * t25 + (T(1) / T(3)) * (t32 * c * t31 + T(3) * (J1 - t24 * c * t25 - T(2) * b * t33 * t31) * t31 + T(2) * b * t34 * t31) * t35 * t31 + (T(4) / T(3)) * t34 * tau_lo * t36 * t31 - T(2) * t32 * t2 * t1 * t31 - (T(4) / T(3)) * t30 * t37 * delta_tau * t31;
  }
  f = sigma2 * sigma2 * F * in.sigma * length;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
    const T t7 = t2 * t2;
    const T t8 = t1 * delta_tau;
    const T t9 = t1 * t1;
    const T t10 = T(4) * delta_tau * t6 * M_panels[7] + M_panels[6] * t7 + T(6) * t1 * t2 * M_panels[8] + T(4) * M_panels[9] * t8 * tau_lo + t9 * M_panels[10];
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = t9 * M_panels[11] + t7 * M_panels[7] + T(6) * M_panels[9] * t1 * t2 + T(4) * t8 * tau_lo * M_panels[10] + T(4) * delta_tau * t6 * M_panels[8] - t11 * b * t10;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t2 * tau_lo;
    const T t13 = t1 * t1;
    const T t14 = t2 * t2;
    const T t15 = t1 * delta_tau;
    const T t16 = T(4) * M_panels[7] * delta_tau * t12 + M_panels[10] * t13 + T(6) * t1 * t2 * M_panels[8] + t14 * M_panels[6] + T(4) * t15 * tau_lo * M_panels[9];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = T(4) * delta_tau * t12 * M_panels[8] + T(4) * M_panels[10] * t15 * tau_lo + T(6) * t1 * t2 * M_panels[9] + t13 * M_panels[11] + M_panels[7] * t14 - t16 * t17 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = t19 * a_minus_b + b * t20;
    const T t22 = t19 * t19;
    const T t23 = t20 * t20;
    const T t24 = T(2) * t18 * a * t21 + t19 * a_minus_b * t22 + t23 * b * t20;
    const T t25 = t23 * t23;
    const T t26 = t22 * t22;
    const T t27 = T(4) * t18 * a * t24 + T(3) * t25 * b * t20 + T(3) * t19 * a_minus_b * t26;
    const T t28 = t2 * t2;
    const T t29 = T(1) / a;
    const T t30 = T(3) * t25 * t20 + t27 * t18 * b - T(3) * t19 * t26;
    const T t31 = T(2) * t30 * t29 * b + T(5) * t18 * t24 - c * t27 * t18;
    const T t32 = t2 * tau_lo;
    const T t33 = t1 * delta_tau;
    const T t34 = t19 * t22 - t18 * t24 * b - t23 * t20;
    const T t35 = T(2) * t29 * b * t31 - c * t30 * t29 - T(5) * t34 * t29;
    const T t36 = T(2) * t34 * t29 * b + c * t18 * t24 - T(3) * t18 * t21;
    const T t37 = t1 * t1;
    G_ap = (T(1) / T(15)) * t27 * t18 * t28 + (T(2) / T(5)) * t1 * t2 * t29 * t31 + (T(4) / T(15)) * delta_tau * t30 * t32 * t29 + (T(4) / T(15)) * t33 * tau_lo * t29 * t35 - (T(1) / T(15)) * (T(5) * t36 * t29 + c * t29 * t31 - T(2) * t29 * t35 * b) * t37 * t29;
    const T t38 = t20 * t20;
    const T t39 = t38 * t38;
    const T t40 = t39 * t20;
    const T t41 = t19 * t19;
    const T t42 = t41 * t41;
    const T t43 = t42 * t19;
    G_E = (T(1) / T(15)) * t29 * (T(4) * t37 * t29 * (c * t34 * t29 - T(2) * t36 * t29 * b - T(3) * (t19 - t20 - t18 * t21 * b) * t29) + T(3) * t28 * t40 + T(4) * delta_tau * t18 * t32 * t24 - T(3) * t43 * (T(6) * t1 * t2 + T(4) * t33 * tau_lo + t37 + t28 + T(4) * delta_tau * t32) - T(12) * t34 * t1 * t2 * t29 - T(12) * t36 * t33 * tau_lo * t29);
  }
  const T t44 = T(1) / a;
  const T t_star = t44 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T g_factor = -T(5) * length * sigma2 * sigma2 * in.sigma;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[0] * exact_cross[0] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
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
    const T t4 = r0 * a_minus_b;
    const T t5 = T(1) / D;
    const T t6 = sqrt(a);
    X = (t4 + r1 * b) * t5 * t6;
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
  const T t13 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t1 * delta_tau;
    const T t16 = t2 * t2;
    const T t17 = t2 * tau_lo;
    F = M_panels[4] * t14 + T(6) * t2 * M_panels[2] * t1 + T(4) * tau_lo * M_panels[3] * t15 + t16 * M_panels[0] + T(4) * t17 * M_panels[1] * delta_tau;
    const T t18 = T(4) * tau_lo * M_panels[9] * t15 + M_panels[10] * t14 + T(4) * t17 * M_panels[7] * delta_tau + t16 * M_panels[6] + T(6) * t2 * M_panels[8] * t1;
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = M_panels[11] * t14 + t16 * M_panels[7] + T(4) * tau_lo * M_panels[10] * t15 + T(4) * t17 * M_panels[8] * delta_tau + T(6) * t2 * M_panels[9] * t1 - t19 * t18 * b;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * delta_tau;
    const T t21 = t2 * t2;
    const T t22 = t2 * tau_lo;
    const T t23 = t1 * t1;
    F = T(4) * tau_lo * M_panels[3] * t20 + t21 * M_panels[0] + T(4) * t22 * M_panels[1] * delta_tau + T(6) * t2 * M_panels[2] * t1 + M_panels[4] * t23;
    const T t24 = T(6) * t2 * M_panels[8] * t1 + T(4) * t22 * M_panels[7] * delta_tau + M_panels[10] * t23 + M_panels[6] * t21 + T(4) * tau_lo * M_panels[9] * t20;
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(6) * t2 * M_panels[9] * t1 + M_panels[11] * t23 + T(4) * tau_lo * M_panels[10] * t20 + t21 * M_panels[7] + T(4) * t22 * M_panels[8] * delta_tau - t25 * t24 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / a;
    const T t27 = T(1) / D;
    const T t28 = T(1) / r1;
    const T t29 = T(1) / r0;
    const T t30 = t28 * a_minus_b + t29 * b;
    const T t31 = t28 * t28;
    const T t32 = t29 * t29;
    const T t33 = T(2) * t27 * a * t30 + t28 * a_minus_b * t31 + t29 * b * t32;
    const T t34 = t27 * t33 * b + t29 * t32 - t28 * t31;
    const T t35 = T(3) * t27 * t30 + T(2) * t34 * t26 * b - t27 * t33 * c;
    const T t36 = t2 * t2;
    const T t37 = t2 * tau_lo;
    const T t38 = t28 - t27 * b * t30 - t29;
    const T t39 = T(3) * t38 * t26 + t34 * t26 * c - T(2) * t26 * t35 * b;
    const T t40 = t1 * t1;
    const T t41 = t1 * delta_tau;
    F = T(2) * t2 * t26 * t35 * t1 + (T(1) / T(3)) * t36 * t27 * t33 + (T(4) / T(3)) * t34 * t37 * t26 * delta_tau - (T(1) / T(3)) * t26 * (T(3) * t26 * (T(2) * t38 * t26 * b + t27 * t30 * c - J1) + t26 * t35 * c + T(2) * t26 * b * t39) * t40 - (T(4) / T(3)) * tau_lo * t26 * t39 * t41;
    const T t42 = t32 * t32;
    const T t43 = t31 * t31;
    const T t44 = T(3) * t29 * b * t42 + T(3) * t28 * a_minus_b * t43 + T(4) * t27 * a * t33;
    const T t45 = T(3) * t29 * t42 + t27 * t44 * b - T(3) * t28 * t43;
    const T t46 = t27 * t44 * c - T(5) * t27 * t33 - T(2) * t26 * b * t45;
    const T t47 = t26 * c * t45 + T(2) * t46 * t26 * b - T(5) * t34 * t26;
    G_ap = (T(4) / T(15)) * t37 * t26 * t45 * delta_tau + (T(1) / T(15)) * t36 * t27 * t44 + (T(1) / T(15)) * t26 * (t46 * t26 * c + T(5) * t26 * t35 - T(2) * t26 * t47 * b) * t40 - (T(4) / T(15)) * tau_lo * t26 * t47 * t41 - (T(2) / T(5)) * t46 * t2 * t26 * t1;
    const T t48 = t28 * t28;
    const T t49 = t48 * t48;
    const T t50 = t49 * t28;
    const T t51 = t29 * t29;
    const T t52 = t51 * t51;
    const T t53 = t52 * t29;
    G_E = -(T(1) / T(15)) * (T(3) * (T(6) * t2 * t1 + t40 + T(4) * t37 * delta_tau + T(4) * tau_lo * t41 + t36) * t50 + T(4) * t26 * t39 * t40 - T(12) * t34 * t2 * t26 * t1 - T(3) * t36 * t53 - T(4) * t37 * t27 * t33 * delta_tau - T(12) * tau_lo * t26 * t35 * t41) * t26;
  }
  const T t54 = T(1) / a;
  const T t_star = t54 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t55 = sigma2 * sigma2;
  const T g_factor = -T(5) * t55 * in.sigma * length;
  f = t55 * F * in.sigma * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
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
    const T t7 = t1 * delta_tau;
    const T t8 = t1 * t1;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * tau_lo;
    const T t11 = t2 * t2;
    const T t12 = t11 * tau_lo;
    F = T(10) * t7 * t2 * M_panels[3] + t9 * M_panels[5] + T(10) * t1 * t10 * M_panels[2] + T(5) * t8 * tau_lo * M_panels[4] + T(5) * delta_tau * t11 * M_panels[1] + M_panels[0] * t12;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t2 * tau_lo;
    const T t14 = t2 * t2;
    const T t15 = t14 * tau_lo;
    const T t16 = t1 * delta_tau;
    const T t17 = t1 * t1;
    const T t18 = t17 * delta_tau;
    F = T(10) * t1 * t13 * M_panels[2] + t15 * M_panels[0] + T(5) * delta_tau * t14 * M_panels[1] + T(10) * t16 * t2 * M_panels[3] + t18 * M_panels[5] + T(5) * t17 * M_panels[4] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, c_minus_b);
    const T t21 = t1 * t1;
    const T t22 = t21 * delta_tau;
    const T t23 = T(1) / a;
    const T t24 = T(1) / D;
    const T t25 = T(1) / q1;
    const T t26 = t25 * t25;
    const T t27 = t3 * t3;
    const T t28 = b * t3 + t25 * a_minus_b + a * J2;
    const T t29 = T(2) * t26 * a_minus_b + T(2) * b * t27 + T(3) * t24 * a * t28;
    const T t30 = t24 * b * t29 + T(2) * t27 - T(2) * t26;
    const T t31 = t24 * t29 * c - T(2) * t23 * b * t30 - T(4) * t24 * t28;
    const T t32 = t3 + t24 * t28 * b - t25;
    const T t33 = T(4) * t23 * t32 - t23 * c * t30 - T(2) * t23 * b * t31;
    const T t34 = t24 * t28 * c - T(2) * J2 - T(2) * t23 * b * t32;
    const T t35 = t23 * c * t31 + T(2) * t23 * b * t33 - T(4) * t34 * t23;
    const T t36 = t2 * t2;
    const T t37 = t1 * delta_tau;
    const T t38 = t36 * tau_lo;
    const T t39 = t2 * tau_lo;
    F = (T(1) / T(8)) * t22 * (T(2) * t23 * t35 * b - T(4) * t23 * (T(2) * t34 * t23 * b + t23 * t32 * c - t23 * (T(2) * J2 * b + log_ratio)) - t23 * c * t33) * t23 + (T(5) / T(8)) * delta_tau * t36 * t23 * t30 + (T(5) / T(8)) * t21 * tau_lo * t23 * t35 + (T(5) / T(4)) * t37 * t2 * t23 * t33 + (T(1) / T(8)) * t24 * t38 * t29 - (T(5) / T(4)) * t1 * t39 * t23 * t31;
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t2 * t2;
    const T t8 = t1 * t1;
    const T t9 = t8 * delta_tau;
    const T t10 = t7 * tau_lo;
    const T t11 = t2 * tau_lo;
    const T t12 = T(10) * t6 * t2 * M_panels[10] + T(5) * delta_tau * t7 * M_panels[8] + t9 * M_panels[12] + t10 * M_panels[7] + T(10) * t1 * M_panels[9] * t11 + T(5) * t8 * tau_lo * M_panels[11];
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = T(5) * t8 * tau_lo * M_panels[12] + t10 * M_panels[8] + t9 * M_panels[13] + T(5) * delta_tau * M_panels[9] * t7 + T(10) * t6 * t2 * M_panels[11] + T(10) * t1 * t11 * M_panels[10] - t13 * t12 * b;
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
    const T t20 = T(10) * t14 * t2 * M_panels[10] + T(5) * delta_tau * t15 * M_panels[8] + t17 * M_panels[12] + T(5) * t16 * tau_lo * M_panels[11] + T(10) * t1 * t18 * M_panels[9] + t19 * M_panels[7];
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = t17 * M_panels[13] + t19 * M_panels[8] + T(5) * t16 * tau_lo * M_panels[12] + T(10) * t14 * t2 * M_panels[11] + T(5) * delta_tau * t15 * M_panels[9] + T(10) * t1 * t18 * M_panels[10] - t21 * b * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = t23 * atan2(t22, c_minus_b);
    const T t24 = t2 * tau_lo;
    const T t25 = T(1) / a;
    const T t26 = T(1) / D;
    const T t27 = T(1) / c;
    const T t28 = T(1) / q1;
    const T t29 = b * t27 + t28 * a_minus_b + a * J2;
    const T t30 = t28 * t28;
    const T t31 = t27 * t27;
    const T t32 = T(3) * t26 * a * t29 + T(2) * t30 * a_minus_b + T(2) * b * t31;
    const T t33 = t31 * t27;
    const T t34 = t30 * t28;
    const T t35 = T(5) * t26 * a * t32 + T(8) * b * t33 + T(8) * t34 * a_minus_b;
    const T t36 = T(8) * t33 + t26 * t35 * b - T(8) * t34;
    const T t37 = T(6) * t26 * t32 + T(2) * t25 * t36 * b - t26 * t35 * c;
    const T t38 = t2 * t2;
    const T t39 = t1 * t1;
    const T t40 = t26 * b * t32 + T(2) * t31 - T(2) * t30;
    const T t41 = T(4) * t26 * t29 + T(2) * t25 * b * t40 - t26 * c * t32;
    const T t42 = T(2) * t25 * b * t37 + T(6) * t25 * t40 - t25 * t36 * c;
    const T t43 = T(6) * t25 * t41 + T(2) * t42 * t25 * b - t25 * c * t37;
    const T t44 = t1 * delta_tau;
    const T t45 = t39 * delta_tau;
    const T t46 = t27 + t26 * b * t29 - t28;
    const T t47 = T(4) * t46 * t25 + T(2) * t25 * b * t41 - t25 * t40 * c;
    const T t48 = t38 * tau_lo;
    G_ap = (T(5) / T(24)) * t1 * t24 * t25 * t37 + (T(5) / T(48)) * delta_tau * t38 * t25 * t36 + (T(5) / T(48)) * t39 * tau_lo * t25 * t43 + (T(5) / T(24)) * t44 * t42 * t2 * t25 + (T(1) / T(48)) * t45 * (T(6) * t47 * t25 + T(2) * t25 * b * t43 - t42 * t25 * c) * t25 + (T(1) / T(48)) * t26 * t48 * t35;
    G_E = (T(1) / T(48)) * t25 * (T(5) * delta_tau * t26 * t38 * t32 + T(30) * t44 * t2 * t25 * t41 + T(20) * t39 * tau_lo * t47 * t25 + T(5) * t45 * t25 * (T(2) * t47 * t25 * b + T(4) * t25 * (T(2) * t46 * t25 * b + T(2) * J2 - t26 * c * t29) - t25 * t41 * c) + T(20) * t1 * t24 * t25 * t40 + T(8) * t48 * t33 - T(8) * t34 * (T(5) * t39 * tau_lo + T(5) * delta_tau * t38 + T(10) * t1 * t24 + t45 + T(10) * t44 * t2 + t48));
  }
  const T t49 = T(1) / a;
  const T t_star = t49 * b;
  const T foot0 = ap0 - t_star * ab0;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - t_star * ab2;
  const T t50 = sigma2 * sigma2;
  const T t51 = t50 * sigma2;
  const T g_factor = -T(6) * t51 * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
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
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * delta_tau;
    const T t8 = t2 * tau_lo;
    const T t9 = t2 * t2;
    const T t10 = t1 * t1;
    const T t11 = t10 * delta_tau;
    const T t12 = t9 * tau_lo;
    F = T(10) * t7 * t2 * M_panels[3] + T(10) * t1 * t8 * M_panels[2] + T(5) * M_panels[1] * delta_tau * t9 + t11 * M_panels[5] + T(5) * M_panels[4] * t10 * tau_lo + t12 * M_panels[0];
    const T t13 = T(10) * t1 * t8 * M_panels[9] + T(10) * M_panels[10] * t7 * t2 + M_panels[7] * t12 + T(5) * t10 * tau_lo * M_panels[11] + T(5) * delta_tau * t9 * M_panels[8] + t11 * M_panels[12];
    G_ap = t13;
    const T t14 = T(1) / a;
    G_E = T(5) * t10 * tau_lo * M_panels[12] + T(5) * delta_tau * t9 * M_panels[9] + M_panels[13] * t11 + T(10) * M_panels[10] * t1 * t8 + T(10) * t7 * t2 * M_panels[11] + t12 * M_panels[8] - t13 * t14 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t15 = t2 * t2;
    const T t16 = t2 * tau_lo;
    const T t17 = t15 * tau_lo;
    const T t18 = t1 * t1;
    const T t19 = t18 * delta_tau;
    const T t20 = t1 * delta_tau;
    F = T(5) * delta_tau * t15 * M_panels[1] + T(10) * t1 * t16 * M_panels[2] + t17 * M_panels[0] + t19 * M_panels[5] + T(5) * t18 * tau_lo * M_panels[4] + T(10) * t20 * M_panels[3] * t2;
    const T t21 = T(5) * t18 * tau_lo * M_panels[11] + t17 * M_panels[7] + T(10) * t20 * t2 * M_panels[10] + T(10) * M_panels[9] * t1 * t16 + M_panels[12] * t19 + T(5) * delta_tau * t15 * M_panels[8];
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(10) * t20 * t2 * M_panels[11] + T(5) * M_panels[12] * t18 * tau_lo + t19 * M_panels[13] + T(5) * M_panels[9] * delta_tau * t15 + t17 * M_panels[8] + T(10) * t1 * t16 * M_panels[10] - t21 * t22 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = t24 * atan2(t23, c_minus_b);
    const T t25 = t3 * t3;
    const T t26 = T(1) / D;
    const T t27 = T(1) / q1;
    const T t28 = t27 * t27;
    const T t29 = J2 * a + t27 * a_minus_b + t3 * b;
    const T t30 = T(2) * t25 * b + T(2) * t28 * a_minus_b + T(3) * t26 * a * t29;
    const T t31 = T(2) * t25 + t26 * t30 * b - T(2) * t28;
    const T t32 = t2 * t2;
    const T t33 = T(1) / a;
    const T t34 = t32 * tau_lo;
    const T t35 = t1 * t1;
    const T t36 = c * t26 * t30 - T(2) * t31 * t33 * b - T(4) * t26 * t29;
    const T t37 = t26 * b * t29 + t3 - t27;
    const T t38 = c * t26 * t29 - T(2) * t37 * t33 * b - T(2) * J2;
    const T t39 = c * t31 * t33 + T(2) * t36 * t33 * b - T(4) * t37 * t33;
    const T t40 = t36 * c * t33 - T(4) * t33 * t38 - T(2) * t33 * b * t39;
    const T t41 = t35 * delta_tau;
    const T t42 = t2 * tau_lo;
    const T t43 = t1 * delta_tau;
    F = (T(5) / T(8)) * delta_tau * t31 * t32 * t33 + (T(1) / T(8)) * t34 * t26 * t30 + (T(5) / T(8)) * t35 * tau_lo * t33 * t40 + (T(1) / T(8)) * t41 * t33 * (T(2) * t33 * t40 * b + c * t33 * t39 - T(4) * (c * t37 * t33 + T(2) * t33 * t38 * b - (log_ratio + T(2) * J2 * b) * t33) * t33) - (T(5) / T(4)) * t36 * t1 * t42 * t33 - (T(5) / T(4)) * t43 * t2 * t33 * t39;
    const T t44 = t25 * t3;
    const T t45 = t28 * t27;
    const T t46 = T(8) * t44 * b + T(8) * t45 * a_minus_b + T(5) * t26 * t30 * a;
    const T t47 = T(8) * t44 + t26 * b * t46 - T(8) * t45;
    const T t48 = c * t26 * t46 - T(2) * t33 * t47 * b - T(6) * t26 * t30;
    const T t49 = c * t33 * t47 + T(2) * t48 * t33 * b - T(6) * t31 * t33;
    const T t50 = T(6) * t36 * t33 + T(2) * t49 * t33 * b - c * t48 * t33;
    G_ap = (T(5) / T(48)) * delta_tau * t32 * t33 * t47 + (T(1) / T(48)) * t34 * t26 * t46 - (T(5) / T(48)) * t35 * tau_lo * t33 * t50 - (T(1) / T(48)) * t41 * (T(6) * t33 * t39 + T(2) * t33 * b * t50 - t49 * c * t33) * t33 - (T(5) / T(24)) * t49 * t43 * t2 * t33 - (T(5) / T(24)) * t48 * t1 * t42 * t33;
    G_E = -(T(1) / T(48)) * (T(20) * t35 * tau_lo * t33 * t39 + T(8) * t45 * (T(10) * t1 * t42 + T(5) * delta_tau * t32 + t41 + T(10) * t43 * t2 + t34 + T(5) * t35 * tau_lo) + T(30) * t36 * t43 * t2 * t33 - T(20) * t1 * t31 * t42 * t33 - T(5) * t41 * t33 * t40 - T(5) * delta_tau * t32 * t26 * t30 - T(8) * t44 * t34) * t33;
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
  grad[0] = g_factor * (G_ap * foot0 - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = b * a_minus_b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    const T t6 = T(1) / D;
    X = t4 * (t5 + b * r1) * t6;
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
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t2 * t2;
    const T t17 = t1 * t1;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t16 * tau_lo;
    const T t21 = t17 * delta_tau;
    F = t15 * M_panels[0] + T(15) * t16 * M_panels[2] * t1 + T(15) * t2 * M_panels[4] * t17 + M_panels[6] * t19 + T(6) * t20 * delta_tau * M_panels[1] + T(20) * t14 * M_panels[3] * t18 + T(6) * tau_lo * M_panels[5] * t21;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t1 * t1;
    const T t25 = t2 * t2;
    const T t26 = t2 * tau_lo;
    const T t27 = t24 * delta_tau;
    const T t28 = t26 * t26;
    const T t29 = t25 * tau_lo;
    F = M_panels[6] * t23 + T(15) * t2 * M_panels[4] * t24 + T(15) * t25 * M_panels[2] * t1 + T(20) * t26 * M_panels[3] * t22 + T(6) * tau_lo * M_panels[5] * t27 + t28 * M_panels[0] + T(6) * t29 * M_panels[1] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = T(1) / a;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = T(1) / r1;
    const T t34 = t33 * a_minus_b + b * t31;
    const T t35 = T(1) / D;
    const T t36 = t33 * t33;
    const T t37 = T(2) * t34 * a * t35 + t36 * t33 * a_minus_b + b * t31 * t32;
    const T t38 = t31 * t32 + b * t37 * t35 - t36 * t33;
    const T t39 = T(2) * t38 * t30 * b + T(3) * t34 * t35 - t37 * c * t35;
    const T t40 = t32 * t32;
    const T t41 = t36 * t36;
    const T t42 = T(3) * b * t31 * t40 + T(3) * t41 * t33 * a_minus_b + T(4) * a * t37 * t35;
    const T t43 = b * t42 * t35 + T(3) * t31 * t40 - T(3) * t41 * t33;
    const T t44 = T(2) * t30 * b * t43 + T(5) * t37 * t35 - c * t42 * t35;
    const T t45 = T(2) * t30 * b * t44 + T(5) * t38 * t30 - t30 * c * t43;
    const T t46 = T(5) * t30 * t39 + T(2) * t30 * b * t45 - t30 * c * t44;
    const T t47 = t33 - t31 - t34 * b * t35;
    const T t48 = T(3) * t30 * t47 + t38 * t30 * c - T(2) * t30 * b * t39;
    const T t49 = T(2) * t30 * b * t46 - T(5) * t30 * t48 - t30 * c * t45;
    const T t50 = t1 * t1;
    const T t51 = t50 * delta_tau;
    const T t52 = t1 * delta_tau;
    const T t53 = t52 * t52;
    const T t54 = t2 * t2;
    const T t55 = t2 * tau_lo;
    const T t56 = t54 * tau_lo;
    const T t57 = t55 * t55;
    F = (T(2) / T(5)) * tau_lo * t49 * t30 * t51 + (T(1) / T(15)) * (T(2) * t49 * t30 * b - T(5) * t30 * (t30 * t39 * c + T(2) * t30 * b * t48 - T(3) * t30 * (J1 - T(2) * t30 * b * t47 - t34 * c * t35)) - t30 * c * t46) * t30 * t53 + t54 * t30 * t44 * t1 + (T(4) / T(3)) * t55 * t30 * t45 * t52 + t2 * t30 * t46 * t50 + (T(2) / T(5)) * t56 * t30 * t43 * delta_tau + (T(1) / T(15)) * t57 * t42 * t35;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
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
    const T t6 = t2 * t2;
    const T t7 = t6 * tau_lo;
    const T t8 = t1 * delta_tau;
    const T t9 = t2 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t8 * t8;
    const T t12 = t1 * t1;
    const T t13 = t12 * delta_tau;
    const T t14 = T(6) * M_panels[9] * delta_tau * t7 + T(15) * t1 * t6 * M_panels[10] + T(20) * M_panels[11] * t8 * t9 + M_panels[8] * t10 + M_panels[14] * t11 + T(15) * M_panels[12] * t12 * t2 + T(6) * t13 * M_panels[13] * tau_lo;
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(20) * M_panels[12] * t8 * t9 + T(15) * M_panels[11] * t1 * t6 + M_panels[15] * t11 + T(6) * delta_tau * t7 * M_panels[10] + T(6) * M_panels[14] * t13 * tau_lo + T(15) * t12 * M_panels[13] * t2 + M_panels[9] * t10 - b * t14 * t15;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t1 * delta_tau;
    const T t17 = t2 * tau_lo;
    const T t18 = t16 * t16;
    const T t19 = t1 * t1;
    const T t20 = t2 * t2;
    const T t21 = t20 * tau_lo;
    const T t22 = t17 * t17;
    const T t23 = t19 * delta_tau;
    const T t24 = T(20) * M_panels[11] * t16 * t17 + M_panels[14] * t18 + T(15) * M_panels[12] * t19 * t2 + T(6) * M_panels[9] * delta_tau * t21 + M_panels[8] * t22 + T(6) * t23 * tau_lo * M_panels[13] + T(15) * t1 * t20 * M_panels[10];
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(6) * delta_tau * t21 * M_panels[10] + M_panels[15] * t18 + T(6) * M_panels[14] * t23 * tau_lo + T(15) * t19 * t2 * M_panels[13] + T(20) * M_panels[12] * t16 * t17 + T(15) * M_panels[11] * t1 * t20 + M_panels[9] * t22 - b * t24 * t25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / r0;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = T(1) / r1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = T(1) / D;
    const T t33 = b * t26 + t29 * a_minus_b;
    const T t34 = t30 * t29 * a_minus_b + b * t26 * t27 + T(2) * t33 * t32 * a;
    const T t35 = T(3) * b * t26 * t28 + T(3) * t31 * t29 * a_minus_b + T(4) * t32 * t34 * a;
    const T t36 = T(3) * t26 * t28 + t35 * b * t32 - T(3) * t31 * t29;
    const T t37 = T(1) / a;
    const T t38 = t28 * t27;
    const T t39 = t31 * t30;
    const T t40 = T(5) * t39 * t29 * a_minus_b + T(2) * t35 * t32 * a + T(5) * b * t26 * t38;
    const T t41 = T(5) * t26 * t38 + b * t40 * t32 - T(5) * t39 * t29;
    const T t42 = T(6) * b * t41 * t37 + T(7) * t35 * t32 - T(3) * t40 * c * t32;
    const T t43 = T(7) * t36 * t37 + T(2) * b * t42 * t37 - T(3) * c * t41 * t37;
    const T t44 = t1 * delta_tau;
    const T t45 = t2 * tau_lo;
    const T t46 = T(5) * t32 * t34 + T(2) * b * t36 * t37 - t35 * c * t32;
    const T t47 = T(7) * t46 * t37 + T(2) * t43 * b * t37 - t42 * c * t37;
    const T t48 = t1 * t1;
    const T t49 = t2 * t2;
    const T t50 = t49 * tau_lo;
    const T t51 = t45 * t45;
    const T t52 = t30 * t29 - b * t32 * t34 - t26 * t27;
    const T t53 = T(2) * b * t46 * t37 - t36 * c * t37 - T(5) * t52 * t37;
    const T t54 = T(2) * b * t47 * t37 + T(7) * t53 * t37 - t43 * c * t37;
    const T t55 = t48 * delta_tau;
    const T t56 = T(2) * t52 * b * t37 + c * t32 * t34 - T(3) * t33 * t32;
    const T t57 = t46 * c * t37 + T(5) * t56 * t37 - T(2) * b * t53 * t37;
    const T t58 = t44 * t44;
    G_ap = (T(4) / T(21)) * t43 * t44 * t45 * t37 + (T(1) / T(7)) * t47 * t48 * t2 * t37 + (T(1) / T(7)) * t42 * t1 * t49 * t37 + (T(6) / T(35)) * t41 * delta_tau * t50 * t37 + (T(1) / T(35)) * t40 * t32 * t51 + (T(2) / T(35)) * t54 * t55 * tau_lo * t37 - (T(1) / T(105)) * (t47 * c * t37 + T(7) * t57 * t37 - T(2) * b * t54 * t37) * t58 * t37;
    const T t59 = t29 * t29;
    const T t60 = t59 * t29;
    const T t61 = t60 * t60;
    const T t62 = t61 * t29;
    const T t63 = t26 * t26;
    const T t64 = t63 * t26;
    const T t65 = t64 * t64;
    const T t66 = t65 * t26;
    G_E = -(T(1) / T(35)) * (T(5) * (T(15) * t1 * t49 + T(6) * t55 * tau_lo + t51 + T(15) * t48 * t2 + t58 + T(20) * t44 * t45 + T(6) * delta_tau * t50) * t62 + T(2) * (t53 * c * t37 + T(2) * t57 * b * t37 + T(5) * (T(2) * b * t56 * t37 - T(3) * (b * t33 * t32 + t26 - t29) * t37 - t52 * c * t37) * t37) * t58 * t37 + T(10) * t57 * t55 * tau_lo * t37 - T(5) * t66 * t51 - T(20) * t53 * t48 * t2 * t37 - T(20) * t46 * t44 * t45 * t37 - T(2) * t35 * delta_tau * t32 * t50 - T(10) * t36 * t1 * t49 * t37) * t37;
  }
  const T t67 = T(1) / a;
  const T t_star = b * t67;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(7) * t69 * in.sigma * length;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t3 = a_minus_b * b;
  if (t3 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    const T t6 = r1 * b;
    X = t4 * t5 * (t6 + r0 * a_minus_b);
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
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t1 * delta_tau;
    const T t16 = t1 * t1;
    const T t17 = t16 * delta_tau;
    const T t18 = t2 * t2;
    const T t19 = t15 * t15;
    const T t20 = t14 * t14;
    const T t21 = t18 * tau_lo;
    F = T(20) * t14 * t15 * M_panels[3] + T(15) * t2 * t16 * M_panels[4] + T(6) * tau_lo * t17 * M_panels[5] + T(15) * t18 * t1 * M_panels[2] + t19 * M_panels[6] + t20 * M_panels[0] + T(6) * t21 * delta_tau * M_panels[1];
    const T t22 = T(20) * t14 * t15 * M_panels[11] + T(15) * M_panels[12] * t2 * t16 + T(6) * t21 * delta_tau * M_panels[9] + T(15) * t18 * t1 * M_panels[10] + T(6) * tau_lo * t17 * M_panels[13] + t19 * M_panels[14] + t20 * M_panels[8];
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = t20 * M_panels[9] + T(6) * tau_lo * t17 * M_panels[14] + T(20) * M_panels[12] * t14 * t15 + T(6) * t21 * delta_tau * M_panels[10] + T(15) * t2 * t16 * M_panels[13] + M_panels[15] * t19 + T(15) * t18 * t1 * M_panels[11] - t23 * b * t22;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t1 * delta_tau;
    const T t25 = t24 * t24;
    const T t26 = t2 * tau_lo;
    const T t27 = t1 * t1;
    const T t28 = t27 * delta_tau;
    const T t29 = t2 * t2;
    const T t30 = t29 * tau_lo;
    const T t31 = t26 * t26;
    F = t25 * M_panels[6] + T(20) * t26 * t24 * M_panels[3] + T(6) * tau_lo * t28 * M_panels[5] + T(6) * t30 * delta_tau * M_panels[1] + T(15) * t29 * t1 * M_panels[2] + T(15) * t2 * t27 * M_panels[4] + t31 * M_panels[0];
    const T t32 = t25 * M_panels[14] + T(20) * t26 * t24 * M_panels[11] + T(15) * t29 * t1 * M_panels[10] + t31 * M_panels[8] + T(6) * tau_lo * t28 * M_panels[13] + T(6) * t30 * delta_tau * M_panels[9] + T(15) * t2 * t27 * M_panels[12];
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = t31 * M_panels[9] + T(15) * t2 * t27 * M_panels[13] + T(20) * t26 * t24 * M_panels[12] + M_panels[15] * t25 + T(15) * t29 * t1 * M_panels[11] + T(6) * t30 * delta_tau * M_panels[10] + T(6) * tau_lo * t28 * M_panels[14] - t33 * b * t32;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t2 * t2;
    const T t35 = T(1) / a;
    const T t36 = T(1) / r1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = T(1) / D;
    const T t40 = T(1) / r0;
    const T t41 = t40 * t40;
    const T t42 = t36 * a_minus_b + t40 * b;
    const T t43 = t40 * b * t41 + T(2) * t39 * a * t42 + t36 * a_minus_b * t37;
    const T t44 = t41 * t41;
    const T t45 = T(3) * t36 * a_minus_b * t38 + T(4) * t39 * a * t43 + T(3) * t40 * b * t44;
    const T t46 = t45 * t39 * b + T(3) * t40 * t44 - T(3) * t36 * t38;
    const T t47 = T(2) * t35 * b * t46 + T(5) * t39 * t43 - t45 * t39 * c;
    const T t48 = t2 * tau_lo;
    const T t49 = t1 * delta_tau;
    const T t50 = t36 * t37 - t40 * t41 - t39 * b * t43;
    const T t51 = T(2) * t35 * b * t47 - t35 * t46 * c - T(5) * t35 * t50;
    const T t52 = t49 * t49;
    const T t53 = T(2) * t35 * t50 * b + t39 * c * t43 - T(3) * t39 * t42;
    const T t54 = t35 * c * t47 + T(5) * t35 * t53 - T(2) * t35 * b * t51;
    const T t55 = t36 - t39 * t42 * b - t40;
    const T t56 = T(3) * t35 * t55 + T(2) * t35 * t53 * b - t35 * t50 * c;
    const T t57 = T(2) * t35 * t54 * b + t35 * c * t51 + T(5) * t35 * t56;
    const T t58 = t48 * t48;
    const T t59 = t34 * tau_lo;
    const T t60 = t1 * t1;
    const T t61 = t60 * delta_tau;
    F = t34 * t1 * t35 * t47 + (T(4) / T(3)) * t48 * t49 * t35 * t51 + (T(1) / T(15)) * t52 * (t35 * t54 * c - T(2) * t35 * t57 * b - T(5) * t35 * (T(3) * (T(2) * t35 * b * t55 + t39 * t42 * c - J1) * t35 + T(2) * t35 * t56 * b - t35 * t53 * c)) * t35 + (T(1) / T(15)) * t58 * t45 * t39 + (T(2) / T(5)) * t59 * delta_tau * t35 * t46 - (T(2) / T(5)) * tau_lo * t61 * t35 * t57 - t2 * t60 * t35 * t54;
    const T t62 = t38 * t37;
    const T t63 = t44 * t41;
    const T t64 = T(5) * t36 * a_minus_b * t62 + T(2) * t45 * t39 * a + T(5) * t40 * b * t63;
    const T t65 = T(5) * t40 * t63 + t64 * t39 * b - T(5) * t36 * t62;
    const T t66 = T(7) * t45 * t39 + T(6) * t35 * b * t65 - T(3) * t64 * t39 * c;
    const T t67 = T(3) * t35 * c * t65 - T(7) * t35 * t46 - T(2) * t35 * b * t66;
    const T t68 = T(7) * t35 * t47 - T(2) * t67 * t35 * b - t35 * t66 * c;
    const T t69 = T(2) * t35 * b * t68 + t67 * t35 * c + T(7) * t35 * t51;
    G_ap = (T(1) / T(35)) * t64 * t58 * t39 + (T(6) / T(35)) * t59 * delta_tau * t35 * t65 + (T(2) / T(35)) * tau_lo * t61 * t35 * t69 + (T(1) / T(7)) * t2 * t60 * t35 * t68 + (T(1) / T(7)) * t34 * t1 * t35 * t66 - (T(1) / T(105)) * t52 * t35 * (T(7) * t35 * t54 + t35 * c * t68 - T(2) * t35 * b * t69) - (T(4) / T(21)) * t48 * t67 * t49 * t35;
    const T t70 = t40 * t40;
    const T t71 = t70 * t40;
    const T t72 = t71 * t71;
    const T t73 = t72 * t40;
    const T t74 = t36 * t36;
    const T t75 = t74 * t36;
    const T t76 = t75 * t75;
    const T t77 = t76 * t36;
    G_E = (T(1) / T(35)) * (T(5) * t73 * t58 + T(20) * t48 * t49 * t35 * t47 + T(20) * t2 * t60 * t35 * t51 + T(2) * t59 * delta_tau * t45 * t39 + T(10) * t34 * t1 * t35 * t46 - T(5) * t77 * (T(15) * t34 * t1 + T(15) * t2 * t60 + T(6) * t59 * delta_tau + T(6) * tau_lo * t61 + t52 + t58 + T(20) * t48 * t49) - T(2) * t52 * t35 * t57 - T(10) * tau_lo * t61 * t35 * t54) * t35;
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
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
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
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
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
    const T t9 = t1 * t1;
    const T t10 = t9 * delta_tau;
    const T t11 = t2 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t8 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t15 * tau_lo;
    F = T(7) * M_panels[6] * t8 * tau_lo + T(21) * t10 * t2 * M_panels[5] + M_panels[0] * t13 + T(7) * M_panels[1] * delta_tau * t12 + T(35) * M_panels[4] * t9 * t11 + M_panels[7] * t14 + T(21) * t1 * t16 * M_panels[2] + T(35) * M_panels[3] * t7 * t15;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t17 = t2 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t1 * t1;
    const T t20 = t19 * delta_tau;
    const T t21 = t2 * t2;
    const T t22 = t21 * tau_lo;
    const T t23 = t1 * delta_tau;
    const T t24 = t23 * t23;
    const T t25 = t24 * delta_tau;
    const T t26 = t18 * tau_lo;
    F = T(7) * M_panels[1] * delta_tau * t18 + T(21) * M_panels[5] * t20 * t2 + T(21) * M_panels[2] * t1 * t22 + T(35) * t19 * t17 * M_panels[4] + T(35) * t23 * M_panels[3] * t21 + t25 * M_panels[7] + T(7) * t24 * M_panels[6] * tau_lo + t26 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = sqrt(D);
    const T t28 = T(1) / t27;
    const T J2 = atan2(t27, c_minus_b) * t28;
    const T t29 = T(1) / D;
    const T t30 = T(1) / q1;
    const T t31 = t30 * a_minus_b + t3 * b + a * J2;
    const T t32 = t30 * t30;
    const T t33 = t3 * t3;
    const T t34 = T(3) * t31 * t29 * a + T(2) * t32 * a_minus_b + T(2) * t33 * b;
    const T t35 = t33 * t3;
    const T t36 = t32 * t30;
    const T t37 = T(5) * t29 * a * t34 + T(8) * t35 * b + T(8) * t36 * a_minus_b;
    const T t38 = t29 * b * t37 + T(8) * t35 - T(8) * t36;
    const T t39 = T(1) / a;
    const T t40 = t2 * tau_lo;
    const T t41 = t40 * t40;
    const T t42 = T(6) * t29 * t34 + T(2) * t38 * t39 * b - c * t29 * t37;
    const T t43 = t2 * t2;
    const T t44 = t43 * tau_lo;
    const T t45 = t29 * b * t34 + T(2) * t33 - T(2) * t32;
    const T t46 = c * t38 * t39 - T(2) * t39 * t42 * b - T(6) * t39 * t45;
    const T t47 = T(4) * t31 * t29 + T(2) * t39 * b * t45 - c * t29 * t34;
    const T t48 = T(2) * t39 * b * t46 + c * t39 * t42 - T(6) * t47 * t39;
    const T t49 = t30 - t3 - t31 * t29 * b;
    const T t50 = T(2) * t39 * b * t49 + t31 * c * t29 - T(2) * J2;
    const T t51 = c * t39 * t45 + T(4) * t39 * t49 - T(2) * t47 * t39 * b;
    const T t52 = c * t47 * t39 + T(4) * t50 * t39 + T(2) * t51 * t39 * b;
    const T t53 = T(2) * t48 * t39 * b + T(6) * t51 * t39 - c * t39 * t46;
    const T t54 = c * t48 * t39 - T(6) * t52 * t39 - T(2) * t53 * t39 * b;
    const T t55 = t1 * delta_tau;
    const T t56 = t55 * t55;
    const T t57 = t56 * delta_tau;
    const T t58 = t41 * tau_lo;
    const T t59 = t1 * t1;
    const T t60 = t59 * delta_tau;
    F = (T(7) / T(48)) * t38 * t39 * delta_tau * t41 + (T(7) / T(16)) * t39 * t42 * t1 * t44 + (T(1) / T(48)) * (T(2) * t54 * t39 * b + c * t53 * t39 + T(6) * (T(4) * t39 * (c * t39 * t49 + t39 * (T(2) * J2 * b + log_ratio) - T(2) * t50 * t39 * b) + c * t51 * t39 - T(2) * t52 * t39 * b) * t39) * t39 * t57 + (T(1) / T(48)) * t29 * t58 * t37 + (T(7) / T(48)) * t54 * t39 * t56 * tau_lo - (T(7) / T(16)) * t53 * t39 * t60 * t2 - (T(35) / T(48)) * t39 * t55 * t43 * t46 - (T(35) / T(48)) * t48 * t39 * t59 * t40;
  }
  const T t61 = sigma2 * sigma2;
  const T t62 = t61 * t61;
  f = length * F * t62;
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
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
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * delta_tau;
    const T t8 = t1 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t2 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t2 * t2;
    const T t14 = t13 * tau_lo;
    const T t15 = t12 * tau_lo;
    const T t16 = T(21) * M_panels[14] * t7 * t2 + M_panels[16] * t10 + T(7) * t9 * tau_lo * M_panels[15] + T(7) * M_panels[10] * delta_tau * t12 + T(21) * M_panels[11] * t1 * t14 + T(35) * M_panels[12] * t8 * t13 + T(35) * M_panels[13] * t6 * t11 + M_panels[9] * t15;
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[17] * t10 + T(35) * M_panels[14] * t6 * t11 + T(7) * M_panels[16] * t9 * tau_lo + T(21) * t7 * t2 * M_panels[15] + T(7) * M_panels[11] * delta_tau * t12 + M_panels[10] * t15 + T(35) * M_panels[13] * t8 * t13 + T(21) * M_panels[12] * t1 * t14 - t17 * b * t16;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t2 * t2;
    const T t19 = t18 * tau_lo;
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t1 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = t1 * t1;
    const T t26 = t21 * tau_lo;
    const T t27 = t25 * delta_tau;
    const T t28 = T(21) * M_panels[11] * t1 * t19 + T(7) * M_panels[10] * delta_tau * t21 + t24 * M_panels[16] + T(7) * M_panels[15] * t23 * tau_lo + T(35) * M_panels[13] * t25 * t20 + M_panels[9] * t26 + T(35) * M_panels[12] * t22 * t18 + T(21) * M_panels[14] * t27 * t2;
    G_ap = t28;
    const T t29 = T(1) / a;
    G_E = M_panels[10] * t26 + M_panels[17] * t24 + T(7) * t23 * tau_lo * M_panels[16] + T(35) * M_panels[13] * t22 * t18 + T(21) * M_panels[15] * t27 * t2 + T(21) * M_panels[12] * t1 * t19 + T(7) * M_panels[11] * delta_tau * t21 + T(35) * M_panels[14] * t25 * t20 - t29 * t28 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = atan2(t30, c_minus_b) * t31;
    const T t32 = T(1) / a;
    const T t33 = T(1) / c;
    const T t34 = t33 * t33;
    const T t35 = t34 * t33;
    const T t36 = T(1) / q1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t36;
    const T t39 = T(1) / D;
    const T t40 = b * t33 + a * J2 + t36 * a_minus_b;
    const T t41 = T(3) * a * t39 * t40 + T(2) * t37 * a_minus_b + T(2) * b * t34;
    const T t42 = T(8) * t38 * a_minus_b + T(5) * a * t41 * t39 + T(8) * b * t35;
    const T t43 = T(8) * t35 + b * t42 * t39 - T(8) * t38;
    const T t44 = t37 * t37;
    const T t45 = t34 * t34;
    const T t46 = T(7) * a * t42 * t39 + T(48) * b * t45 + T(48) * t44 * a_minus_b;
    const T t47 = T(48) * t44 - T(48) * t45 - t46 * b * t39;
    const T t48 = T(2) * t32 * b * t47 + t46 * c * t39 - T(8) * t42 * t39;
    const T t49 = T(8) * t32 * t43 + t32 * t47 * c - T(2) * t32 * t48 * b;
    const T t50 = t1 * delta_tau;
    const T t51 = t2 * t2;
    const T t52 = t42 * c * t39 - T(2) * t32 * b * t43 - T(6) * t41 * t39;
    const T t53 = T(2) * t32 * b * t49 + t32 * t48 * c - T(8) * t32 * t52;
    const T t54 = t1 * t1;
    const T t55 = t2 * tau_lo;
    const T t56 = t55 * t55;
    const T t57 = t56 * tau_lo;
    const T t58 = T(2) * t37 - T(2) * t34 - b * t41 * t39;
    const T t59 = T(6) * t32 * t58 + T(2) * t32 * b * t52 + t32 * c * t43;
    const T t60 = t32 * c * t49 + T(8) * t32 * t59 - T(2) * t32 * b * t53;
    const T t61 = T(2) * t32 * t58 * b + t41 * c * t39 - T(4) * t39 * t40;
    const T t62 = T(2) * t32 * b * t59 + T(6) * t32 * t61 - t32 * c * t52;
    const T t63 = b * t39 * t40 + t33 - t36;
    const T t64 = T(2) * t32 * b * t61 - t32 * t58 * c - T(4) * t32 * t63;
    const T t65 = t32 * t59 * c - T(2) * t32 * t62 * b - T(6) * t32 * t64;
    const T t66 = T(8) * t32 * t62 + t32 * c * t53 + T(2) * t32 * b * t60;
    const T t67 = t50 * t50;
    const T t68 = t67 * delta_tau;
    const T t69 = t51 * tau_lo;
    const T t70 = t54 * delta_tau;
    G_ap = (T(35) / T(384)) * t32 * t49 * t50 * t51 + (T(35) / T(384)) * t32 * t53 * t54 * t55 + (T(1) / T(384)) * t46 * t39 * t57 + (T(1) / T(384)) * t32 * (t32 * t60 * c + T(8) * t32 * t65 - T(2) * t32 * b * t66) * t68 - (T(7) / T(128)) * t32 * t48 * t1 * t69 - (T(7) / T(384)) * t32 * t66 * t67 * tau_lo - (T(7) / T(128)) * t32 * t60 * t70 * t2 - (T(7) / T(384)) * t32 * t47 * delta_tau * t56;
    G_E = (T(1) / T(384)) * t32 * (T(48) * t45 * t57 + T(42) * t32 * t1 * t69 * t43 + T(7) * t32 * (t32 * t62 * c + T(2) * t32 * b * t65 - T(6) * t32 * (T(4) * t32 * (c * t39 * t40 - T(2) * J2 - T(2) * t32 * t63 * b) + T(2) * t32 * b * t64 - t32 * c * t61)) * t68 + T(42) * t32 * t65 * t67 * tau_lo + T(7) * t42 * delta_tau * t39 * t56 - T(48) * (t57 + T(21) * t1 * t69 + t68 + T(7) * t67 * tau_lo + T(21) * t70 * t2 + T(35) * t50 * t51 + T(35) * t54 * t55 + T(7) * delta_tau * t56) * t44 - T(105) * t32 * t62 * t70 * t2 - T(140) * t32 * t59 * t54 * t55 - T(105) * t32 * t50 * t51 * t52);
  }
  const T t71 = T(1) / a;
  const T t_star = t71 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t72 = sigma2 * sigma2;
  const T t73 = t72 * t72;
  const T g_factor = -T(8) * t73 * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
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
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
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
    const T t7 = t1 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t2 * t2;
    const T t11 = t10 * tau_lo;
    const T t12 = t2 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t13 * tau_lo;
    const T t15 = t1 * t1;
    const T t16 = t15 * delta_tau;
    F = M_panels[7] * t9 + T(35) * M_panels[3] * t7 * t10 + T(21) * M_panels[2] * t1 * t11 + T(7) * M_panels[1] * delta_tau * t13 + M_panels[0] * t14 + T(7) * M_panels[6] * t8 * tau_lo + T(35) * M_panels[4] * t15 * t12 + T(21) * t16 * t2 * M_panels[5];
    const T t17 = T(35) * M_panels[12] * t7 * t10 + T(21) * M_panels[14] * t16 * t2 + T(7) * M_panels[10] * delta_tau * t13 + T(35) * M_panels[13] * t15 * t12 + M_panels[9] * t14 + M_panels[16] * t9 + T(7) * M_panels[15] * t8 * tau_lo + T(21) * M_panels[11] * t1 * t11;
    G_ap = t17;
    const T t18 = T(1) / a;
    G_E = M_panels[17] * t9 + T(35) * M_panels[14] * t15 * t12 + T(7) * M_panels[11] * delta_tau * t13 + T(7) * M_panels[16] * t8 * tau_lo + T(21) * M_panels[12] * t1 * t11 + M_panels[10] * t14 + T(35) * M_panels[13] * t7 * t10 + T(21) * M_panels[15] * t16 * t2 - t18 * b * t17;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t19 = t1 * t1;
    const T t20 = t19 * delta_tau;
    const T t21 = t2 * t2;
    const T t22 = t21 * tau_lo;
    const T t23 = t2 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t27 * delta_tau;
    F = T(21) * M_panels[5] * t20 * t2 + T(21) * M_panels[2] * t1 * t22 + M_panels[0] * t25 + T(7) * M_panels[1] * delta_tau * t24 + T(35) * M_panels[4] * t19 * t23 + M_panels[7] * t28 + T(7) * t27 * tau_lo * M_panels[6] + T(35) * t26 * t21 * M_panels[3];
    const T t29 = T(21) * M_panels[14] * t20 * t2 + M_panels[9] * t25 + T(7) * M_panels[10] * delta_tau * t24 + T(21) * M_panels[11] * t1 * t22 + T(35) * M_panels[13] * t19 * t23 + T(35) * M_panels[12] * t26 * t21 + M_panels[16] * t28 + T(7) * t27 * tau_lo * M_panels[15];
    G_ap = t29;
    const T t30 = T(1) / a;
    G_E = T(7) * M_panels[16] * t27 * tau_lo + T(35) * M_panels[14] * t19 * t23 + M_panels[17] * t28 + T(35) * M_panels[13] * t26 * t21 + T(21) * M_panels[12] * t1 * t22 + T(7) * M_panels[11] * delta_tau * t24 + T(21) * t20 * t2 * M_panels[15] + M_panels[10] * t25 - t30 * b * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = t32 * atan2(t31, c_minus_b);
    const T t33 = T(1) / a;
    const T t34 = t3 * t3;
    const T t35 = t34 * t3;
    const T t36 = T(1) / q1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t36;
    const T t39 = a * J2 + a_minus_b * t36 + b * t3;
    const T t40 = T(1) / D;
    const T t41 = T(2) * b * t34 + T(3) * a * t39 * t40 + T(2) * a_minus_b * t37;
    const T t42 = T(8) * b * t35 + T(8) * a_minus_b * t38 + T(5) * a * t41 * t40;
    const T t43 = T(8) * t35 + t42 * b * t40 - T(8) * t38;
    const T t44 = t42 * c * t40 - T(2) * t33 * b * t43 - T(6) * t41 * t40;
    const T t45 = T(2) * t34 + t41 * b * t40 - T(2) * t37;
    const T t46 = T(6) * t33 * t45 - T(2) * t33 * t44 * b - t33 * t43 * c;
    const T t47 = t41 * c * t40 - T(2) * t33 * b * t45 - T(4) * t39 * t40;
    const T t48 = t33 * t44 * c + T(2) * t33 * b * t46 - T(6) * t33 * t47;
    const T t49 = t1 * t1;
    const T t50 = t2 * tau_lo;
    const T t51 = t50 * t50;
    const T t52 = t1 * delta_tau;
    const T t53 = t2 * t2;
    const T t54 = t51 * tau_lo;
    const T t55 = t36 - b * t39 * t40 - t3;
    const T t56 = T(2) * t33 * t47 * b + T(4) * t33 * t55 + t33 * c * t45;
    const T t57 = T(6) * t33 * t56 + t33 * t46 * c - T(2) * t33 * t48 * b;
    const T t58 = t49 * delta_tau;
    const T t59 = T(2) * t33 * b * t55 + t39 * c * t40 - T(2) * J2;
    const T t60 = T(2) * t33 * b * t56 + T(4) * t33 * t59 - t33 * t47 * c;
    const T t61 = T(2) * t33 * b * t57 + t33 * t48 * c + T(6) * t33 * t60;
    const T t62 = t52 * t52;
    const T t63 = t53 * tau_lo;
    const T t64 = t62 * delta_tau;
    F = (T(35) / T(48)) * t33 * t48 * t49 * t50 + (T(7) / T(48)) * t33 * t43 * delta_tau * t51 + (T(35) / T(48)) * t33 * t46 * t52 * t53 + (T(1) / T(48)) * t42 * t40 * t54 - (T(7) / T(16)) * t33 * t57 * t58 * t2 - (T(7) / T(48)) * t33 * t61 * t62 * tau_lo - (T(7) / T(16)) * t33 * t44 * t1 * t63 - (T(1) / T(48)) * t33 * t64 * (T(6) * t33 * (T(2) * t33 * b * t60 + T(4) * t33 * (T(2) * t33 * b * t59 - t33 * (log_ratio + T(2) * b * J2) - t33 * c * t55) - t33 * t56 * c) + T(2) * t33 * t61 * b - t33 * c * t57);
    const T t65 = t34 * t34;
    const T t66 = t37 * t37;
    const T t67 = T(48) * b * t65 + T(7) * a * t42 * t40 + T(48) * a_minus_b * t66;
    const T t68 = b * t67 * t40 + T(48) * t65 - T(48) * t66;
    const T t69 = t67 * c * t40 - T(2) * t33 * b * t68 - T(8) * t42 * t40;
    const T t70 = T(8) * t33 * t43 - t33 * t68 * c - T(2) * t69 * t33 * b;
    const T t71 = t69 * t33 * c + T(2) * t33 * t70 * b - T(8) * t33 * t44;
    const T t72 = T(2) * t33 * t71 * b + T(8) * t33 * t46 - t33 * t70 * c;
    const T t73 = T(8) * t33 * t48 + T(2) * t33 * t72 * b - t33 * t71 * c;
    G_ap = (T(35) / T(384)) * t33 * t70 * t52 * t53 + (T(7) / T(128)) * t33 * t72 * t58 * t2 + (T(7) / T(384)) * t33 * t68 * delta_tau * t51 + (T(7) / T(384)) * t33 * t73 * t62 * tau_lo + (T(35) / T(384)) * t33 * t71 * t49 * t50 + (T(1) / T(384)) * t67 * t40 * t54 - (T(1) / T(384)) * t33 * (t33 * t72 * c + T(8) * t33 * t57 - T(2) * t33 * b * t73) * t64 - (T(7) / T(128)) * t69 * t33 * t1 * t63;
    G_E = -(T(1) / T(384)) * t33 * (T(42) * t33 * t57 * t62 * tau_lo + T(105) * t33 * t44 * t52 * t53 + T(48) * (T(7) * delta_tau * t51 + t54 + t64 + T(7) * t62 * tau_lo + T(35) * t52 * t53 + T(35) * t49 * t50 + T(21) * t58 * t2 + T(21) * t1 * t63) * t66 + T(7) * t33 * t61 * t64 - T(48) * t65 * t54 - T(105) * t33 * t48 * t58 * t2 - T(42) * t33 * t43 * t1 * t63 - T(140) * t33 * t46 * t49 * t50 - T(7) * t42 * delta_tau * t40 * t51);
  }
  const T t74 = T(1) / a;
  const T t_star = t74 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t75 = sigma2 * sigma2;
  const T t76 = t75 * t75;
  const T g_factor = -T(8) * t76 * length;
  f = t76 * F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
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
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
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
    const T t15 = t14 * t14;
    const T t16 = t1 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = t2 * tau_lo;
    const T t20 = t14 * delta_tau;
    const T t21 = t2 * t2;
    const T t22 = t21 * t21;
    const T t23 = t21 * tau_lo;
    const T t24 = t19 * t19;
    const T t25 = t24 * tau_lo;
    F = M_panels[8] * t15 + T(28) * t2 * M_panels[6] * t17 + T(8) * tau_lo * M_panels[7] * t18 + T(56) * t19 * M_panels[5] * t20 + t22 * M_panels[0] + T(70) * t21 * M_panels[4] * t14 + T(56) * t23 * M_panels[3] * t16 + T(28) * t24 * M_panels[2] * t1 + T(8) * t25 * M_panels[1] * delta_tau;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t1 * delta_tau;
    const T t27 = t26 * t26;
    const T t28 = t2 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = t29 * tau_lo;
    const T t31 = t2 * t2;
    const T t32 = t1 * t1;
    const T t33 = t27 * delta_tau;
    const T t34 = t32 * t32;
    const T t35 = t31 * t31;
    const T t36 = t31 * tau_lo;
    const T t37 = t32 * delta_tau;
    F = T(28) * t2 * M_panels[6] * t27 + T(8) * t30 * M_panels[1] * delta_tau + T(70) * t31 * M_panels[4] * t32 + T(8) * tau_lo * M_panels[7] * t33 + M_panels[8] * t34 + t35 * M_panels[0] + T(56) * t36 * M_panels[3] * t26 + T(56) * M_panels[5] * t28 * t37 + T(28) * t29 * M_panels[2] * t1;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = t2 * tau_lo;
    const T t39 = t38 * t38;
    const T t40 = T(1) / a;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t43 * t42;
    const T t45 = T(1) / D;
    const T t46 = T(1) / r1;
    const T t47 = t46 * t46;
    const T t48 = t47 * t47;
    const T t49 = t41 * b + t46 * a_minus_b;
    const T t50 = t47 * t46 * a_minus_b + T(2) * t49 * t45 * a + t41 * b * t42;
    const T t51 = T(3) * t41 * b * t43 + T(3) * t48 * t46 * a_minus_b + T(4) * t50 * t45 * a;
    const T t52 = t48 * t47;
    const T t53 = T(5) * t41 * b * t44 + T(2) * t45 * a * t51 + T(5) * t52 * t46 * a_minus_b;
    const T t54 = t53 * t45 * b + T(5) * t41 * t44 - T(5) * t52 * t46;
    const T t55 = T(6) * t40 * b * t54 + T(7) * t45 * t51 - T(3) * t53 * t45 * c;
    const T t56 = t45 * b * t51 + T(3) * t41 * t43 - T(3) * t48 * t46;
    const T t57 = T(2) * t40 * b * t56 + T(5) * t50 * t45 - t45 * t51 * c;
    const T t58 = t47 * t46 - t41 * t42 - t50 * t45 * b;
    const T t59 = T(2) * t40 * t57 * b - t40 * t56 * c - T(5) * t58 * t40;
    const T t60 = T(3) * t40 * c * t54 - T(2) * t40 * b * t55 - T(7) * t40 * t56;
    const T t61 = T(2) * t40 * b * t60 + t40 * t55 * c - T(7) * t40 * t57;
    const T t62 = T(7) * t40 * t59 + t40 * c * t60 - T(2) * t40 * b * t61;
    const T t63 = t50 * t45 * c + T(2) * t58 * t40 * b - T(3) * t49 * t45;
    const T t64 = T(2) * t40 * t59 * b - t40 * t57 * c - T(5) * t40 * t63;
    const T t65 = T(2) * t40 * b * t62 + T(7) * t40 * t64 + t40 * t61 * c;
    const T t66 = t1 * delta_tau;
    const T t67 = t66 * t66;
    const T t68 = t41 + t49 * t45 * b - t46;
    const T t69 = T(2) * t40 * b * t63 - t58 * t40 * c - T(3) * t40 * t68;
    const T t70 = T(2) * t40 * b * t64 - t40 * t59 * c - T(5) * t40 * t69;
    const T t71 = T(2) * t40 * b * t65 + T(7) * t70 * t40 - t40 * t62 * c;
    const T t72 = t67 * delta_tau;
    const T t73 = t2 * t2;
    const T t74 = t73 * t73;
    const T t75 = t1 * t1;
    const T t76 = t75 * delta_tau;
    const T t77 = t75 * t75;
    const T t78 = t39 * tau_lo;
    const T t79 = t73 * tau_lo;
    F = (T(4) / T(15)) * t39 * t40 * t55 * t1 + (T(4) / T(15)) * t2 * t40 * t65 * t67 + (T(8) / T(105)) * tau_lo * t40 * t71 * t72 + (T(1) / T(35)) * t74 * t53 * t45 + (T(8) / T(15)) * t38 * t40 * t62 * t76 + (T(1) / T(105)) * t40 * (T(2) * t40 * b * t71 - t40 * t65 * c - T(7) * t40 * (T(5) * t40 * (T(2) * t40 * t69 * b - T(3) * t40 * (T(2) * t40 * t68 * b + J1 - t49 * t45 * c) - t40 * c * t63) + t40 * c * t64 - T(2) * t70 * t40 * b)) * t77 + (T(8) / T(35)) * t78 * t40 * t54 * delta_tau - (T(8) / T(15)) * t79 * t40 * t60 * t66 - (T(2) / T(3)) * t73 * t40 * t61 * t75;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross0 * plain_cross0 + plain_cross1 * plain_cross1;
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
  const T b = ab_ap - delta_tau * sigma2 * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = delta_tau * ap1 + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + delta_tau * ap2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
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
    const T t7 = t6 * t6;
    const T t8 = t1 * delta_tau;
    const T t9 = t2 * t2;
    const T t10 = t9 * tau_lo;
    const T t11 = t9 * t9;
    const T t12 = t6 * delta_tau;
    const T t13 = t2 * tau_lo;
    const T t14 = t8 * t8;
    const T t15 = t14 * delta_tau;
    const T t16 = t13 * t13;
    const T t17 = t16 * tau_lo;
    const T t18 = t7 * M_panels[18] + T(56) * t8 * M_panels[13] * t10 + M_panels[10] * t11 + T(56) * t12 * M_panels[15] * t13 + T(28) * t14 * t2 * M_panels[16] + T(8) * t15 * M_panels[17] * tau_lo + T(28) * t1 * M_panels[12] * t16 + T(8) * delta_tau * M_panels[11] * t17 + T(70) * t6 * M_panels[14] * t9;
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = M_panels[11] * t11 + T(56) * t8 * M_panels[14] * t10 + t7 * M_panels[19] + T(8) * delta_tau * M_panels[12] * t17 + T(56) * t12 * t13 * M_panels[16] + T(70) * t6 * M_panels[15] * t9 + T(28) * t1 * M_panels[13] * t16 + T(8) * t15 * M_panels[18] * tau_lo + T(28) * t14 * M_panels[17] * t2 - t18 * t19 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t1 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * delta_tau;
    const T t23 = t2 * t2;
    const T t24 = t23 * tau_lo;
    const T t25 = t1 * t1;
    const T t26 = t25 * t25;
    const T t27 = t25 * delta_tau;
    const T t28 = t2 * tau_lo;
    const T t29 = t23 * t23;
    const T t30 = t28 * t28;
    const T t31 = t30 * tau_lo;
    const T t32 = T(8) * t22 * M_panels[17] * tau_lo + T(56) * t20 * M_panels[13] * t24 + t26 * M_panels[18] + T(70) * t25 * M_panels[14] * t23 + T(28) * t21 * M_panels[16] * t2 + T(56) * t27 * M_panels[15] * t28 + M_panels[10] * t29 + T(8) * delta_tau * M_panels[11] * t31 + T(28) * t1 * M_panels[12] * t30;
    G_ap = t32;
    const T t33 = T(1) / a;
    G_E = T(8) * delta_tau * M_panels[12] * t31 + T(28) * t21 * M_panels[17] * t2 + M_panels[11] * t29 + T(28) * t1 * M_panels[13] * t30 + T(56) * t27 * M_panels[16] * t28 + t26 * M_panels[19] + T(56) * t20 * M_panels[14] * t24 + T(70) * t25 * M_panels[15] * t23 + T(8) * t22 * M_panels[18] * tau_lo - t33 * b * t32;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = t1 * delta_tau;
    const T t35 = T(1) / a;
    const T t36 = T(1) / r1;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = T(1) / D;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = b * t41 + t36 * a_minus_b;
    const T t45 = t36 * a_minus_b * t37 + T(2) * t40 * a * t44 + b * t41 * t42;
    const T t46 = T(3) * b * t41 * t43 + T(4) * t40 * a * t45 + T(3) * t36 * a_minus_b * t38;
    const T t47 = t43 * t42;
    const T t48 = t38 * t37;
    const T t49 = T(2) * t40 * a * t46 + T(5) * b * t41 * t47 + T(5) * t36 * a_minus_b * t48;
    const T t50 = t43 * t43;
    const T t51 = T(8) * t40 * a * t49 + T(35) * b * t41 * t50 + T(35) * t36 * a_minus_b * t39;
    const T t52 = T(35) * t36 * t39 - t40 * t51 * b - T(35) * t41 * t50;
    const T t53 = t40 * t51 * c + T(2) * t52 * t35 * b - T(9) * t40 * t49;
    const T t54 = T(5) * t36 * t48 - T(5) * t41 * t47 - t40 * t49 * b;
    const T t55 = t52 * t35 * c - T(2) * t35 * b * t53 - T(9) * t35 * t54;
    const T t56 = t2 * t2;
    const T t57 = t56 * tau_lo;
    const T t58 = t56 * t56;
    const T t59 = t1 * t1;
    const T t60 = T(6) * t35 * t54 * b + T(3) * t40 * t49 * c - T(7) * t40 * t46;
    const T t61 = T(2) * t35 * b * t55 + t35 * t53 * c - T(3) * t35 * t60;
    const T t62 = t59 * t59;
    const T t63 = T(3) * t36 * t38 - T(3) * t41 * t43 - t40 * t46 * b;
    const T t64 = T(2) * t35 * b * t63 + t40 * t46 * c - T(5) * t40 * t45;
    const T t65 = T(7) * t35 * t63 + T(2) * t35 * t60 * b - T(3) * t35 * t54 * c;
    const T t66 = T(7) * t64 * t35 + T(2) * t35 * b * t65 - t35 * t60 * c;
    const T t67 = T(3) * t35 * t65 + t35 * t55 * c - T(2) * t35 * t61 * b;
    const T t68 = T(3) * t35 * t66 + T(2) * t35 * t67 * b + t35 * t61 * c;
    const T t69 = t41 * t42 + t40 * b * t45 - t36 * t37;
    const T t70 = T(5) * t69 * t35 + t35 * t63 * c - T(2) * t64 * t35 * b;
    const T t71 = t35 * t65 * c + T(7) * t35 * t70 - T(2) * t35 * t66 * b;
    const T t72 = T(2) * t35 * t68 * b - T(3) * t35 * t71 - t35 * t67 * c;
    const T t73 = t40 * t45 * c - T(2) * t69 * t35 * b - T(3) * t40 * t44;
    const T t74 = T(5) * t35 * t73 - t64 * t35 * c - T(2) * t35 * b * t70;
    const T t75 = T(7) * t35 * t74 - T(2) * t35 * b * t71 - t35 * t66 * c;
    const T t76 = t2 * tau_lo;
    const T t77 = t76 * t76;
    const T t78 = t77 * tau_lo;
    const T t79 = t34 * t34;
    const T t80 = t59 * delta_tau;
    const T t81 = t79 * delta_tau;
    G_ap = (T(8) / T(45)) * t34 * t35 * t55 * t57 + (T(1) / T(315)) * t40 * t51 * t58 + (T(2) / T(9)) * t59 * t35 * t61 * t56 + (T(1) / T(315)) * t62 * t35 * (t35 * t68 * c - T(2) * t35 * t72 * b - T(3) * t35 * t75) - (T(8) / T(315)) * delta_tau * t52 * t35 * t78 - (T(4) / T(45)) * t1 * t35 * t53 * t77 - (T(4) / T(45)) * t79 * t35 * t68 * t2 - (T(8) / T(45)) * t80 * t35 * t67 * t76 - (T(8) / T(315)) * t81 * t35 * t72 * tau_lo;
    const T t82 = t36 * t36;
    const T t83 = t82 * t82;
    const T t84 = t83 * t83;
    const T t85 = t84 * t36;
    const T t86 = t41 * t41;
    const T t87 = t86 * t86;
    const T t88 = t87 * t87;
    const T t89 = t88 * t41;
    G_E = -(T(1) / T(945)) * t35 * (T(168) * t34 * t35 * t60 * t57 + T(56) * t81 * t35 * t75 * tau_lo + T(105) * t85 * (T(70) * t59 * t56 + T(8) * delta_tau * t78 + t62 + t58 + T(28) * t1 * t77 + T(28) * t79 * t2 + T(56) * t34 * t57 + T(56) * t80 * t76 + T(8) * t81 * tau_lo) + T(280) * t59 * t35 * t65 * t56 + T(8) * t62 * t35 * (T(2) * t35 * t75 * b + t35 * c * t71 + T(7) * t35 * (t35 * t70 * c + T(2) * t35 * b * t74 + T(5) * t35 * (T(2) * t35 * b * t73 + t69 * t35 * c - T(3) * (t40 * t44 * b + t41 - t36) * t35))) + T(168) * t1 * t35 * t54 * t77 + T(280) * t80 * t35 * t66 * t76 - T(105) * t89 * t58 - T(24) * delta_tau * t40 * t49 * t78 - T(168) * t79 * t35 * t2 * t71);
  }
  const T t90 = T(1) / a;
  const T t_star = t90 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T g_factor = -T(9) * t92 * in.sigma * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
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
    X = -(a_minus_b - b) * t7 / (t8 - a_minus_b * r0);
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
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t14 * t14;
    const T t16 = t1 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t17 * delta_tau;
    const T t19 = t2 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t14 * delta_tau;
    const T t22 = t20 * tau_lo;
    const T t23 = t2 * t2;
    const T t24 = t23 * t23;
    const T t25 = t23 * tau_lo;
    F = M_panels[8] * t15 + T(8) * M_panels[7] * t18 * tau_lo + T(28) * M_panels[2] * t1 * t20 + T(56) * M_panels[5] * t21 * t19 + T(8) * M_panels[1] * delta_tau * t22 + T(70) * M_panels[4] * t14 * t23 + M_panels[0] * t24 + T(56) * M_panels[3] * t16 * t25 + T(28) * M_panels[6] * t17 * t2;
    const T t26 = T(56) * t21 * M_panels[15] * t19 + T(28) * t1 * t20 * M_panels[12] + T(70) * M_panels[14] * t14 * t23 + T(56) * M_panels[13] * t16 * t25 + T(8) * M_panels[17] * t18 * tau_lo + T(28) * M_panels[16] * t17 * t2 + M_panels[18] * t15 + M_panels[10] * t24 + T(8) * M_panels[11] * delta_tau * t22;
    G_ap = t26;
    const T t27 = T(1) / a;
    G_E = T(28) * M_panels[17] * t17 * t2 + T(28) * M_panels[13] * t1 * t20 + T(70) * t14 * M_panels[15] * t23 + T(56) * M_panels[14] * t16 * t25 + T(8) * M_panels[18] * t18 * tau_lo + M_panels[19] * t15 + T(56) * M_panels[16] * t21 * t19 + T(8) * delta_tau * t22 * M_panels[12] + M_panels[11] * t24 - b * t26 * t27;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t2 * t2;
    const T t31 = t30 * t30;
    const T t32 = t2 * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = t29 * delta_tau;
    const T t36 = t1 * t1;
    const T t37 = t36 * delta_tau;
    const T t38 = t30 * tau_lo;
    const T t39 = t36 * t36;
    F = T(28) * M_panels[6] * t29 * t2 + M_panels[0] * t31 + T(28) * M_panels[2] * t1 * t33 + T(8) * delta_tau * M_panels[1] * t34 + T(8) * M_panels[7] * t35 * tau_lo + T(56) * M_panels[5] * t37 * t32 + T(56) * M_panels[3] * t28 * t38 + T(70) * M_panels[4] * t36 * t30 + t39 * M_panels[8];
    const T t40 = T(28) * M_panels[12] * t1 * t33 + M_panels[18] * t39 + T(70) * t36 * M_panels[14] * t30 + T(56) * M_panels[15] * t37 * t32 + T(8) * t35 * tau_lo * M_panels[17] + M_panels[10] * t31 + T(56) * M_panels[13] * t28 * t38 + T(28) * M_panels[16] * t29 * t2 + T(8) * delta_tau * t34 * M_panels[11];
    G_ap = t40;
    const T t41 = T(1) / a;
    G_E = T(70) * M_panels[15] * t36 * t30 + M_panels[19] * t39 + T(56) * t28 * M_panels[14] * t38 + T(28) * t29 * t2 * M_panels[17] + T(28) * M_panels[13] * t1 * t33 + T(8) * M_panels[18] * t35 * tau_lo + T(56) * M_panels[16] * t37 * t32 + t31 * M_panels[11] + T(8) * M_panels[12] * delta_tau * t34 - t40 * b * t41;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t42 = T(1) / r0;
    const T t43 = T(1) / D;
    const T t44 = T(1) / r1;
    const T t45 = b * t42 + t44 * a_minus_b;
    const T t46 = t42 + t43 * b * t45 - t44;
    const T t47 = T(1) / a;
    const T t48 = t44 * t44;
    const T t49 = t42 * t42;
    const T t50 = t44 * a_minus_b * t48 + T(2) * t43 * t45 * a + b * t49 * t42;
    const T t51 = t43 * b * t50 + t49 * t42 - t44 * t48;
    const T t52 = T(3) * t43 * t45 + T(2) * b * t51 * t47 - t43 * c * t50;
    const T t53 = T(3) * t46 * t47 + T(2) * t52 * b * t47 - c * t51 * t47;
    const T t54 = t48 * t48;
    const T t55 = t49 * t49;
    const T t56 = T(4) * t43 * t50 * a + T(3) * b * t55 * t42 + T(3) * t44 * a_minus_b * t54;
    const T t57 = T(3) * t44 * t54 - T(3) * t55 * t42 - t43 * b * t56;
    const T t58 = T(2) * t57 * b * t47 + t43 * c * t56 - T(5) * t43 * t50;
    const T t59 = t57 * c * t47 + T(5) * t51 * t47 - T(2) * b * t58 * t47;
    const T t60 = t58 * c * t47 + T(5) * t52 * t47 + T(2) * b * t59 * t47;
    const T t61 = T(5) * t53 * t47 + T(2) * b * t60 * t47 - t59 * c * t47;
    const T t62 = t54 * t48;
    const T t63 = t55 * t49;
    const T t64 = T(2) * t43 * t56 * a + T(5) * b * t63 * t42 + T(5) * t44 * a_minus_b * t62;
    const T t65 = T(5) * t44 * t62 - T(5) * t63 * t42 - t43 * b * t64;
    const T t66 = T(6) * t65 * b * t47 + T(3) * t43 * c * t64 - T(7) * t43 * t56;
    const T t67 = T(7) * t57 * t47 + T(2) * b * t66 * t47 - T(3) * t65 * c * t47;
    const T t68 = T(7) * t58 * t47 + T(2) * t67 * b * t47 - t66 * c * t47;
    const T t69 = T(2) * b * t68 * t47 - T(7) * t59 * t47 - t67 * c * t47;
    const T t70 = c * t68 * t47 + T(7) * t60 * t47 - T(2) * b * t69 * t47;
    const T t71 = T(7) * t61 * t47 + T(2) * b * t70 * t47 + t69 * c * t47;
    const T t72 = t1 * delta_tau;
    const T t73 = t72 * t72;
    const T t74 = t73 * delta_tau;
    const T t75 = t2 * t2;
    const T t76 = t75 * t75;
    const T t77 = t1 * t1;
    const T t78 = t77 * delta_tau;
    const T t79 = t2 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = t80 * tau_lo;
    const T t82 = t77 * t77;
    const T t83 = t75 * tau_lo;
    F = (T(8) / T(105)) * t71 * t74 * tau_lo * t47 + (T(4) / T(15)) * t70 * t73 * t2 * t47 + (T(1) / T(35)) * t43 * t76 * t64 - (T(8) / T(15)) * t69 * t78 * t79 * t47 - (T(8) / T(35)) * t65 * delta_tau * t81 * t47 - (T(1) / T(105)) * (t70 * c * t47 + T(7) * (c * t60 * t47 - T(2) * t61 * b * t47 - T(5) * (T(3) * (T(2) * t46 * b * t47 + J1 - t43 * t45 * c) * t47 + T(2) * t53 * b * t47 - t52 * c * t47) * t47) * t47 - T(2) * t71 * b * t47) * t82 * t47 - (T(8) / T(15)) * t67 * t72 * t83 * t47 - (T(4) / T(15)) * t66 * t1 * t80 * t47 - (T(2) / T(3)) * t68 * t77 * t75 * t47;
    const T t84 = t55 * t55;
    const T t85 = t54 * t54;
    const T t86 = T(8) * t43 * a * t64 + T(35) * b * t84 * t42 + T(35) * t44 * a_minus_b * t85;
    const T t87 = T(35) * t44 * t85 - t43 * b * t86 - T(35) * t84 * t42;
    const T t88 = T(9) * t43 * t64 - t43 * t86 * c - T(2) * b * t87 * t47;
    const T t89 = T(2) * b * t88 * t47 + c * t87 * t47 - T(9) * t65 * t47;
    const T t90 = T(3) * t66 * t47 + t88 * c * t47 - T(2) * t89 * b * t47;
    const T t91 = T(2) * b * t90 * t47 + T(3) * t67 * t47 + t89 * c * t47;
    const T t92 = T(2) * b * t91 * t47 + T(3) * t68 * t47 - c * t90 * t47;
    const T t93 = t91 * c * t47 - T(2) * b * t92 * t47 - T(3) * t69 * t47;
    G_ap = (T(8) / T(315)) * t93 * t74 * tau_lo * t47 + (T(4) / T(45)) * t88 * t1 * t80 * t47 + (T(1) / T(315)) * t43 * t86 * t76 + (T(8) / T(45)) * t89 * t72 * t83 * t47 + (T(1) / T(315)) * (T(2) * t93 * b * t47 + t92 * c * t47 + T(3) * t70 * t47) * t82 * t47 - (T(2) / T(9)) * t90 * t77 * t75 * t47 - (T(4) / T(45)) * t92 * t73 * t2 * t47 - (T(8) / T(315)) * delta_tau * t81 * t87 * t47 - (T(8) / T(45)) * t91 * t78 * t79 * t47;
    const T t94 = t42 * t42;
    const T t95 = t94 * t94;
    const T t96 = t95 * t95;
    const T t97 = t96 * t42;
    const T t98 = t44 * t44;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t44;
    G_E = (T(1) / T(945)) * (T(24) * t43 * delta_tau * t81 * t64 + T(8) * t71 * t82 * t47 + T(56) * t70 * t74 * tau_lo * t47 + T(105) * t76 * t97 - T(168) * t66 * t72 * t83 * t47 - T(105) * t101 * (T(8) * delta_tau * t81 + T(70) * t77 * t75 + T(56) * t72 * t83 + T(8) * t74 * tau_lo + T(56) * t78 * t79 + t76 + T(28) * t73 * t2 + t82 + T(28) * t1 * t80) - T(280) * t68 * t78 * t79 * t47 - T(168) * t69 * t73 * t2 * t47 - T(168) * t65 * t1 * t80 * t47 - T(280) * t67 * t77 * t75 * t47) * t47;
  }
  const T t102 = T(1) / a;
  const T t_star = b * t102;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - ab1 * t_star;
  const T foot2 = ap2 - ab2 * t_star;
  const T t103 = sigma2 * sigma2;
  const T t104 = t103 * t103;
  const T g_factor = -T(9) * t104 * in.sigma * length;
  f = t104 * F * in.sigma * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
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
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t2 * t2;
    const T t8 = t1 * t1;
    const T t9 = t8 * delta_tau;
    const T t10 = t1 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t2 * tau_lo;
    const T t14 = t7 * t7;
    const T t15 = t14 * tau_lo;
    const T t16 = t13 * t13;
    const T t17 = t16 * tau_lo;
    const T t18 = t7 * tau_lo;
    const T t19 = t8 * t8;
    const T t20 = t19 * delta_tau;
    F = T(126) * t7 * M_panels[5] * t9 + T(36) * t2 * M_panels[7] * t12 + T(84) * t13 * t11 * M_panels[6] + t15 * M_panels[0] + T(9) * t14 * M_panels[1] * delta_tau + T(36) * t17 * M_panels[2] * t1 + T(126) * t18 * M_panels[4] * t8 + T(9) * tau_lo * M_panels[8] * t19 + T(84) * t16 * M_panels[3] * t10 + M_panels[9] * t20;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t1 * t1;
    const T t22 = t21 * t21;
    const T t23 = t2 * t2;
    const T t24 = t23 * t23;
    const T t25 = t23 * tau_lo;
    const T t26 = t21 * delta_tau;
    const T t27 = t2 * tau_lo;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t29 * delta_tau;
    const T t31 = t27 * t27;
    const T t32 = t31 * tau_lo;
    const T t33 = t24 * tau_lo;
    const T t34 = t22 * delta_tau;
    F = T(9) * tau_lo * M_panels[8] * t22 + T(9) * t24 * M_panels[1] * delta_tau + T(126) * t25 * M_panels[4] * t21 + T(126) * t23 * M_panels[5] * t26 + T(84) * t27 * M_panels[6] * t29 + T(36) * t2 * M_panels[7] * t30 + T(36) * t32 * M_panels[2] * t1 + t33 * M_panels[0] + T(84) * t31 * M_panels[3] * t28 + t34 * M_panels[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = sqrt(D);
    const T t36 = T(1) / t35;
    const T J2 = t36 * atan2(t35, c_minus_b);
    const T t37 = t2 * t2;
    const T t38 = t37 * t37;
    const T t39 = t38 * tau_lo;
    const T t40 = T(1) / D;
    const T t41 = T(1) / q1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t3 * t3;
    const T t45 = t44 * t44;
    const T t46 = a * J2 + b * t3 + t41 * a_minus_b;
    const T t47 = T(2) * t42 * a_minus_b + T(3) * t40 * a * t46 + T(2) * b * t44;
    const T t48 = t42 * t41;
    const T t49 = t44 * t3;
    const T t50 = T(5) * t40 * a * t47 + T(8) * t48 * a_minus_b + T(8) * b * t49;
    const T t51 = T(48) * t43 * a_minus_b + T(48) * b * t45 + T(7) * t40 * a * t50;
    const T t52 = t37 * tau_lo;
    const T t53 = T(1) / a;
    const T t54 = T(48) * t43 - t40 * t51 * b - T(48) * t45;
    const T t55 = T(8) * t49 + t40 * t50 * b - T(8) * t48;
    const T t56 = T(2) * t53 * t54 * b + t40 * t51 * c - T(8) * t40 * t50;
    const T t57 = t53 * t54 * c + T(8) * t55 * t53 - T(2) * t53 * b * t56;
    const T t58 = t40 * t50 * c - T(6) * t40 * t47 - T(2) * t55 * t53 * b;
    const T t59 = T(2) * t53 * b * t57 + t53 * c * t56 - T(8) * t53 * t58;
    const T t60 = t1 * t1;
    const T t61 = t40 * t47 * b + T(2) * t44 - T(2) * t42;
    const T t62 = T(2) * t53 * b * t58 + t55 * t53 * c - T(6) * t53 * t61;
    const T t63 = T(8) * t53 * t62 + t53 * c * t57 - T(2) * t53 * t59 * b;
    const T t64 = T(4) * t40 * t46 + T(2) * t53 * t61 * b - t40 * t47 * c;
    const T t65 = T(6) * t53 * t64 + t53 * t58 * c - T(2) * t53 * b * t62;
    const T t66 = t40 * t46 * b + t3 - t41;
    const T t67 = t53 * t61 * c - T(2) * t53 * b * t64 - T(4) * t53 * t66;
    const T t68 = t53 * t62 * c + T(2) * t53 * b * t65 - T(6) * t53 * t67;
    const T t69 = t53 * t59 * c + T(2) * t53 * t63 * b - T(8) * t53 * t65;
    const T t70 = t53 * t63 * c + T(8) * t53 * t68 - T(2) * t53 * b * t69;
    const T t71 = T(2) * J2 + T(2) * t53 * b * t66 - t40 * t46 * c;
    const T t72 = T(4) * t53 * t71 - t53 * t64 * c - T(2) * t53 * t67 * b;
    const T t73 = T(6) * t53 * t72 + T(2) * t53 * b * t68 - t53 * t65 * c;
    const T t74 = T(2) * t70 * t53 * b + t53 * c * t69 + T(8) * t73 * t53;
    const T t75 = t60 * t60;
    const T t76 = t1 * delta_tau;
    const T t77 = t76 * t76;
    const T t78 = t77 * delta_tau;
    const T t79 = t2 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = t75 * delta_tau;
    const T t82 = t80 * tau_lo;
    const T t83 = t60 * delta_tau;
    F = (T(1) / T(384)) * t39 * t40 * t51 + (T(21) / T(64)) * t52 * t53 * t59 * t60 + (T(3) / T(128)) * tau_lo * t53 * t74 * t75 + (T(3) / T(32)) * t2 * t70 * t53 * t78 + (T(7) / T(32)) * t80 * t53 * t57 * t76 + (T(1) / T(384)) * t53 * (T(8) * t53 * (T(2) * t73 * t53 * b + T(6) * t53 * (t53 * t67 * c + T(4) * (t53 * (T(2) * J2 * b + log_ratio) + T(2) * t53 * b * t71 - t53 * c * t66) * t53 + T(2) * t53 * b * t72) - t53 * c * t68) + T(2) * t53 * b * t74 - t70 * t53 * c) * t81 - (T(3) / T(32)) * t82 * t53 * t56 * t1 - (T(3) / T(128)) * t38 * t53 * t54 * delta_tau - (T(21) / T(64)) * t37 * t53 * t63 * t83 - (T(7) / T(32)) * t79 * t53 * t69 * t77;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t1 * t1;
    const T t10 = t9 * t9;
    const T t11 = t2 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t2 * t2;
    const T t15 = t14 * t14;
    const T t16 = t10 * delta_tau;
    const T t17 = t14 * tau_lo;
    const T t18 = t15 * tau_lo;
    const T t19 = t9 * delta_tau;
    const T t20 = T(36) * t2 * M_panels[18] * t8 + T(9) * tau_lo * M_panels[19] * t10 + T(36) * t13 * M_panels[13] * t1 + T(9) * t15 * M_panels[12] * delta_tau + T(84) * t11 * M_panels[17] * t7 + M_panels[20] * t16 + T(84) * t12 * M_panels[14] * t6 + T(126) * t17 * M_panels[15] * t9 + t18 * M_panels[11] + T(126) * t14 * M_panels[16] * t19;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = t18 * M_panels[12] + T(36) * t2 * M_panels[19] * t8 + T(9) * t15 * M_panels[13] * delta_tau + T(126) * t14 * M_panels[17] * t19 + T(84) * t11 * M_panels[18] * t7 + T(126) * t17 * M_panels[16] * t9 + T(9) * tau_lo * M_panels[20] * t10 + M_panels[21] * t16 + T(36) * t13 * M_panels[14] * t1 + T(84) * t12 * M_panels[15] * t6 - t21 * t20 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * t1;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = t2 * t2;
    const T t26 = t22 * delta_tau;
    const T t27 = t25 * t25;
    const T t28 = t27 * tau_lo;
    const T t29 = t1 * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = t2 * tau_lo;
    const T t33 = t32 * t32;
    const T t34 = t33 * tau_lo;
    const T t35 = t25 * tau_lo;
    const T t36 = M_panels[20] * t24 + T(126) * t25 * M_panels[16] * t26 + T(9) * t27 * M_panels[12] * delta_tau + t28 * M_panels[11] + T(36) * t2 * M_panels[18] * t31 + T(9) * tau_lo * M_panels[19] * t23 + T(36) * t34 * M_panels[13] * t1 + T(84) * t32 * M_panels[17] * t30 + T(126) * t35 * M_panels[15] * t22 + T(84) * t33 * M_panels[14] * t29;
    G_ap = t36;
    const T t37 = T(1) / a;
    G_E = T(84) * t32 * M_panels[18] * t30 + T(126) * t25 * M_panels[17] * t26 + T(126) * t35 * M_panels[16] * t22 + t28 * M_panels[12] + M_panels[21] * t24 + T(9) * tau_lo * M_panels[20] * t23 + T(36) * t34 * M_panels[14] * t1 + T(9) * t27 * M_panels[13] * delta_tau + T(84) * t33 * M_panels[15] * t29 + T(36) * t2 * M_panels[19] * t31 - t37 * t36 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = t39 * atan2(t38, c_minus_b);
    const T t40 = T(1) / a;
    const T t41 = T(1) / q1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = T(1) / c;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = T(1) / D;
    const T t48 = t45 * t44;
    const T t49 = t41 * a_minus_b + a * J2 + b * t44;
    const T t50 = T(2) * b * t45 + T(3) * t47 * a * t49 + T(2) * t42 * a_minus_b;
    const T t51 = t42 * t41;
    const T t52 = T(8) * b * t48 + T(5) * t47 * a * t50 + T(8) * t51 * a_minus_b;
    const T t53 = T(48) * t43 * a_minus_b + T(48) * b * t46 + T(7) * t47 * a * t52;
    const T t54 = T(48) * t43 - T(48) * t46 - t47 * t53 * b;
    const T t55 = T(2) * t40 * b * t54 + t47 * t53 * c - T(8) * t47 * t52;
    const T t56 = t47 * b * t52 + T(8) * t48 - T(8) * t51;
    const T t57 = T(2) * t40 * t55 * b - t40 * t54 * c - T(8) * t40 * t56;
    const T t58 = t47 * t50 * b + T(2) * t45 - T(2) * t42;
    const T t59 = t47 * t52 * c - T(6) * t47 * t50 - T(2) * t40 * b * t56;
    const T t60 = T(6) * t40 * t58 - T(2) * t59 * t40 * b - t40 * c * t56;
    const T t61 = T(8) * t59 * t40 + T(2) * t40 * t57 * b - t40 * t55 * c;
    const T t62 = t40 * t57 * c + T(8) * t40 * t60 - T(2) * t40 * b * t61;
    const T t63 = t43 * t41;
    const T t64 = t46 * t44;
    const T t65 = T(128) * b * t64 + T(128) * t63 * a_minus_b + T(3) * t47 * a * t53;
    const T t66 = T(128) * t63 - t47 * t65 * b - T(128) * t64;
    const T t67 = T(10) * t47 * t53 - T(6) * t40 * t66 * b - T(3) * t47 * t65 * c;
    const T t68 = T(10) * t40 * t54 - T(3) * t40 * t66 * c - T(2) * t67 * t40 * b;
    const T t69 = T(2) * t40 * b * t68 + T(10) * t40 * t55 + t67 * t40 * c;
    const T t70 = T(10) * t40 * t57 + T(2) * t40 * b * t69 - t40 * c * t68;
    const T t71 = t40 * t69 * c - T(10) * t40 * t61 - T(2) * t40 * b * t70;
    const T t72 = T(10) * t40 * t62 + t40 * t70 * c + T(2) * t40 * b * t71;
    const T t73 = T(4) * t47 * t49 + T(2) * t40 * b * t58 - t47 * t50 * c;
    const T t74 = T(2) * t40 * t60 * b + T(6) * t73 * t40 + t59 * t40 * c;
    const T t75 = T(8) * t40 * t74 + T(2) * t40 * b * t62 + t40 * c * t61;
    const T t76 = T(2) * t40 * b * t72 + T(10) * t75 * t40 - t40 * t71 * c;
    const T t77 = t47 * b * t49 + t44 - t41;
    const T t78 = T(2) * t73 * t40 * b + T(4) * t40 * t77 - t40 * t58 * c;
    const T t79 = t40 * t60 * c - T(6) * t40 * t78 - T(2) * t40 * b * t74;
    const T t80 = t40 * t62 * c + T(8) * t40 * t79 - T(2) * t75 * t40 * b;
    const T t81 = t1 * t1;
    const T t82 = t81 * t81;
    const T t83 = t82 * delta_tau;
    const T t84 = t2 * t2;
    const T t85 = t84 * t84;
    const T t86 = t85 * tau_lo;
    const T t87 = t2 * tau_lo;
    const T t88 = t87 * t87;
    const T t89 = t88 * tau_lo;
    const T t90 = t1 * delta_tau;
    const T t91 = t90 * t90;
    const T t92 = t91 * delta_tau;
    const T t93 = t81 * delta_tau;
    const T t94 = t84 * tau_lo;
    G_ap = (T(1) / T(3840)) * (T(2) * t40 * b * t76 - T(10) * t40 * t80 - t40 * c * t72) * t40 * t83 + (T(1) / T(1280)) * t47 * t86 * t65 + (T(3) / T(1280)) * tau_lo * t40 * t82 * t76 + (T(3) / T(320)) * t67 * t89 * t40 * t1 + (T(3) / T(320)) * t2 * t40 * t92 * t72 + (T(7) / T(320)) * t87 * t40 * t71 * t91 - (T(9) / T(1280)) * t85 * t40 * t66 * delta_tau - (T(21) / T(640)) * t84 * t40 * t70 * t93 - (T(7) / T(320)) * t88 * t40 * t68 * t90 - (T(21) / T(640)) * t94 * t40 * t69 * t81;
    G_E = -(T(1) / T(1280)) * (T(128) * (t86 + T(126) * t84 * t93 + T(126) * t94 * t81 + T(36) * t2 * t92 + T(84) * t88 * t90 + T(36) * t89 * t1 + T(84) * t87 * t91 + T(9) * t85 * delta_tau + T(9) * tau_lo * t82 + t83) * t63 + T(84) * t88 * t40 * t55 * t90 + T(168) * t94 * t40 * t57 * t81 + T(24) * t89 * t40 * t54 * t1 + T(210) * t84 * t40 * t61 * t93 + T(24) * tau_lo * t40 * t80 * t82 + T(3) * t40 * (t75 * t40 * c + T(2) * t40 * b * t80 + T(8) * (T(2) * t40 * b * t79 + T(6) * t40 * (t73 * t40 * c - T(2) * t40 * b * t78 - T(4) * t40 * (T(2) * t40 * b * t77 + T(2) * J2 - t47 * t49 * c)) + t40 * t74 * c) * t40) * t83 - T(168) * t87 * t40 * t62 * t91 - T(128) * t86 * t64 - T(3) * t47 * t85 * t53 * delta_tau - T(84) * t2 * t75 * t40 * t92) * t40;
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
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
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
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t1 * t1;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t1 * delta_tau;
    const T t11 = t2 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t2 * t2;
    const T t14 = t13 * t13;
    const T t15 = t12 * tau_lo;
    const T t16 = t10 * t10;
    const T t17 = t16 * delta_tau;
    const T t18 = t13 * tau_lo;
    const T t19 = t14 * tau_lo;
    const T t20 = t7 * delta_tau;
    F = t9 * M_panels[9] + T(84) * t10 * t12 * M_panels[3] + T(9) * M_panels[1] * delta_tau * t14 + T(36) * t1 * t15 * M_panels[2] + T(9) * t8 * M_panels[8] * tau_lo + T(36) * M_panels[7] * t17 * t2 + T(84) * t16 * t11 * M_panels[6] + T(126) * M_panels[4] * t7 * t18 + t19 * M_panels[0] + T(126) * t20 * t13 * M_panels[5];
    const T t21 = T(9) * t8 * tau_lo * M_panels[19] + T(126) * t7 * t18 * M_panels[15] + T(84) * M_panels[14] * t10 * t12 + T(9) * delta_tau * t14 * M_panels[12] + T(36) * t17 * t2 * M_panels[18] + M_panels[20] * t9 + M_panels[11] * t19 + T(84) * M_panels[17] * t16 * t11 + T(36) * M_panels[13] * t1 * t15 + T(126) * M_panels[16] * t20 * t13;
    G_ap = t21;
    const T t22 = T(1) / a;
    G_E = T(84) * t16 * t11 * M_panels[18] + T(36) * M_panels[14] * t1 * t15 + t9 * M_panels[21] + T(126) * M_panels[17] * t20 * t13 + t19 * M_panels[12] + T(9) * M_panels[13] * delta_tau * t14 + T(84) * t10 * t12 * M_panels[15] + T(126) * M_panels[16] * t7 * t18 + T(36) * t17 * t2 * M_panels[19] + T(9) * M_panels[20] * t8 * tau_lo - t22 * t21 * b;
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t23 = t1 * t1;
    const T t24 = t23 * t23;
    const T t25 = t2 * t2;
    const T t26 = t25 * tau_lo;
    const T t27 = t23 * delta_tau;
    const T t28 = t1 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t29 * delta_tau;
    const T t31 = t2 * tau_lo;
    const T t32 = t31 * t31;
    const T t33 = t25 * t25;
    const T t34 = t32 * tau_lo;
    const T t35 = t33 * tau_lo;
    const T t36 = t24 * delta_tau;
    F = T(9) * t24 * M_panels[8] * tau_lo + T(126) * M_panels[4] * t23 * t26 + T(126) * t27 * M_panels[5] * t25 + T(36) * M_panels[7] * t30 * t2 + T(84) * t28 * t32 * M_panels[3] + T(9) * M_panels[1] * delta_tau * t33 + T(36) * t1 * t34 * M_panels[2] + T(84) * t29 * t31 * M_panels[6] + t35 * M_panels[0] + t36 * M_panels[9];
    const T t37 = M_panels[20] * t36 + T(36) * t30 * t2 * M_panels[18] + T(126) * t23 * t26 * M_panels[15] + T(84) * M_panels[14] * t28 * t32 + T(9) * t24 * tau_lo * M_panels[19] + T(36) * t1 * t34 * M_panels[13] + T(84) * M_panels[17] * t29 * t31 + M_panels[11] * t35 + T(126) * t27 * t25 * M_panels[16] + T(9) * delta_tau * t33 * M_panels[12];
    G_ap = t37;
    const T t38 = T(1) / a;
    G_E = T(36) * M_panels[14] * t1 * t34 + T(9) * M_panels[20] * t24 * tau_lo + T(84) * t29 * t31 * M_panels[18] + T(126) * M_panels[17] * t27 * t25 + T(9) * delta_tau * t33 * M_panels[13] + t35 * M_panels[12] + t36 * M_panels[21] + T(36) * t30 * t2 * M_panels[19] + T(126) * t23 * t26 * M_panels[16] + T(84) * t28 * t32 * M_panels[15] - t38 * t37 * b;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = t40 * atan2(t39, c_minus_b);
    const T t41 = t2 * t2;
    const T t42 = t41 * t41;
    const T t43 = T(1) / a;
    const T t44 = t3 * t3;
    const T t45 = t44 * t44;
    const T t46 = T(1) / D;
    const T t47 = T(1) / q1;
    const T t48 = t47 * t47;
    const T t49 = t48 * t48;
    const T t50 = t44 * t3;
    const T t51 = t48 * t47;
    const T t52 = J2 * a + t3 * b + a_minus_b * t47;
    const T t53 = T(3) * t46 * t52 * a + T(2) * t44 * b + T(2) * a_minus_b * t48;
    const T t54 = T(8) * t50 * b + T(8) * a_minus_b * t51 + T(5) * t53 * t46 * a;
    const T t55 = T(48) * a_minus_b * t49 + T(7) * t54 * t46 * a + T(48) * t45 * b;
    const T t56 = T(48) * t45 + t46 * b * t55 - T(48) * t49;
    const T t57 = t42 * tau_lo;
    const T t58 = T(2) * t43 * t56 * b + T(8) * t54 * t46 - c * t46 * t55;
    const T t59 = T(8) * t50 + t54 * t46 * b - T(8) * t51;
    const T t60 = T(2) * t58 * t43 * b + T(8) * t59 * t43 - c * t43 * t56;
    const T t61 = c * t54 * t46 - T(2) * t59 * t43 * b - T(6) * t53 * t46;
    const T t62 = t58 * c * t43 + T(8) * t43 * t61 - T(2) * t60 * t43 * b;
    const T t63 = T(2) * t44 + t53 * t46 * b - T(2) * t48;
    const T t64 = T(2) * t43 * t61 * b + c * t59 * t43 - T(6) * t63 * t43;
    const T t65 = c * t60 * t43 + T(2) * t62 * t43 * b + T(8) * t64 * t43;
    const T t66 = t53 * c * t46 - T(2) * t63 * t43 * b - T(4) * t46 * t52;
    const T t67 = T(6) * t43 * t66 + T(2) * t64 * t43 * b - c * t43 * t61;
    const T t68 = t47 - t46 * t52 * b - t3;
    const T t69 = T(2) * t43 * t66 * b + c * t63 * t43 + T(4) * t68 * t43;
    const T t70 = c * t64 * t43 - T(2) * t43 * t67 * b - T(6) * t69 * t43;
    const T t71 = T(8) * t43 * t67 + T(2) * t65 * t43 * b - c * t62 * t43;
    const T t72 = t65 * c * t43 + T(8) * t70 * t43 - T(2) * t71 * t43 * b;
    const T t73 = T(2) * t68 * t43 * b + c * t46 * t52 - T(2) * J2;
    const T t74 = T(2) * t69 * t43 * b + T(4) * t43 * t73 - c * t43 * t66;
    const T t75 = T(6) * t43 * t74 - c * t43 * t67 - T(2) * t70 * t43 * b;
    const T t76 = T(2) * t72 * t43 * b + c * t71 * t43 - T(8) * t75 * t43;
    const T t77 = t1 * t1;
    const T t78 = t77 * t77;
    const T t79 = t2 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = t80 * tau_lo;
    const T t82 = t78 * delta_tau;
    const T t83 = t1 * delta_tau;
    const T t84 = t83 * t83;
    const T t85 = t84 * delta_tau;
    const T t86 = t77 * delta_tau;
    const T t87 = t41 * tau_lo;
    F = (T(3) / T(128)) * delta_tau * t42 * t43 * t56 + (T(1) / T(384)) * t46 * t57 * t55 + (T(3) / T(128)) * t76 * t78 * tau_lo * t43 + (T(3) / T(32)) * t58 * t1 * t81 * t43 + (T(1) / T(384)) * t82 * t43 * (T(2) * t76 * t43 * b - c * t72 * t43 - T(8) * (T(2) * t75 * t43 * b + c * t70 * t43 + T(6) * (T(2) * t43 * t74 * b - t69 * c * t43 - T(4) * (t43 * (T(2) * J2 * b + log_ratio) + c * t68 * t43 - T(2) * t43 * t73 * b) * t43) * t43) * t43) + (T(3) / T(32)) * t85 * t2 * t72 * t43 + (T(7) / T(32)) * t60 * t83 * t80 * t43 - (T(21) / T(64)) * t65 * t86 * t41 * t43 - (T(21) / T(64)) * t77 * t87 * t62 * t43 - (T(7) / T(32)) * t84 * t79 * t71 * t43;
    const T t88 = t49 * t47;
    const T t89 = t45 * t3;
    const T t90 = T(128) * a_minus_b * t88 + T(3) * t46 * a * t55 + T(128) * t89 * b;
    const T t91 = t90 * t46 * b + T(128) * t89 - T(128) * t88;
    const T t92 = T(6) * t91 * t43 * b + T(10) * t46 * t55 - T(3) * c * t90 * t46;
    const T t93 = T(3) * t91 * c * t43 - T(10) * t43 * t56 - T(2) * t92 * t43 * b;
    const T t94 = c * t92 * t43 + T(2) * t93 * t43 * b - T(10) * t58 * t43;
    const T t95 = T(2) * t94 * t43 * b - T(10) * t60 * t43 - c * t93 * t43;
    const T t96 = c * t94 * t43 - T(2) * t43 * t95 * b - T(10) * t62 * t43;
    const T t97 = T(2) * t43 * t96 * b + c * t43 * t95 - T(10) * t65 * t43;
    const T t98 = T(2) * t97 * t43 * b - T(10) * t71 * t43 - c * t43 * t96;
    G_ap = (T(7) / T(320)) * t84 * t79 * t43 * t96 + (T(3) / T(320)) * t92 * t1 * t81 * t43 + (T(3) / T(320)) * t97 * t85 * t2 * t43 + (T(3) / T(1280)) * t98 * t78 * tau_lo * t43 + (T(9) / T(1280)) * t91 * delta_tau * t42 * t43 + (T(1) / T(1280)) * t90 * t46 * t57 - (T(7) / T(320)) * t93 * t83 * t80 * t43 - (T(21) / T(640)) * t77 * t87 * t94 * t43 - (T(1) / T(3840)) * t82 * t43 * (c * t97 * t43 - T(2) * t98 * t43 * b - T(10) * t72 * t43) - (T(21) / T(640)) * t86 * t41 * t43 * t95;
    G_E = (T(1) / T(1280)) * (T(84) * t58 * t83 * t80 * t43 + T(168) * t60 * t77 * t87 * t43 + T(24) * t78 * tau_lo * t72 * t43 + T(3) * delta_tau * t46 * t42 * t55 + T(128) * t89 * t57 + T(24) * t1 * t81 * t43 * t56 + T(3) * t76 * t82 * t43 - T(128) * (T(84) * t84 * t79 + T(36) * t85 * t2 + T(36) * t1 * t81 + T(9) * delta_tau * t42 + T(84) * t83 * t80 + T(9) * t78 * tau_lo + T(126) * t86 * t41 + T(126) * t77 * t87 + t82 + t57) * t88 - T(168) * t65 * t84 * t79 * t43 - T(210) * t86 * t41 * t62 * t43 - T(84) * t85 * t2 * t71 * t43) * t43;
  }
  const T t99 = T(1) / a;
  const T t_star = t99 * b;
  const T foot0 = ap0 - ab0 * t_star;
  const T foot1 = ap1 - t_star * ab1;
  const T foot2 = ap2 - ab2 * t_star;
  const T t100 = sigma2 * sigma2;
  const T t101 = t100 * t100;
  const T t102 = t101 * sigma2;
  const T g_factor = -T(10) * length * t102;
  f = length * t102 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

}  // namespace skelconv::generated
