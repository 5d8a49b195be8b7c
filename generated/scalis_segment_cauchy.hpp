// generated/scalis_segment_cauchy.hpp — SCALIS segment kernels of the cauchy family.
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

/// How many values scalis_segment_cauchy_i2_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i2_prepared_size = 29;

/// What scalis_segment_cauchy_i2_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 29): computed once per
/// segment; in.p is not read.
/// Operations: 8 +, 23 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i2_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T g_factor = -T(2) * length * sigma2;
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
  const T t0 = T(1) / ab_ab;
  pre[10] = t0;
  pre[11] = -delta_tau * tau_lo * sigma2;
  pre[12] = tau_lo * tau_lo * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  pre[20] = tau_lo * sigma2 * tau_hi;
  pre[21] = -a * a;
  pre[22] = a;
  pre[23] = tau_lo;
  const T t1 = T(1) / a;
  pre[24] = t1;
  pre[25] = delta_tau + tau_lo;
  pre[26] = tau_lo * ab_ab;
  pre[27] = length;
  pre[28] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i2_prepare); operations per point.
/// Operations: 40 +, 49 ×, 2 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 70048 +, 78624 ×, 25291 /, 539 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i2_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T tau_lo = pre[23];
  const T seg10 = pre[24];
  const T length = pre[27];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
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
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T F;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * tau_lo + delta_tau * M_panels[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    const T log_ratio = log(q1 / c);
    F = (T(1) / T(2)) * seg10 * (T(2) * b * J2 + log_ratio) * delta_tau + tau_lo * J2;
  }
  f = sigma2 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i2_prepare); operations per point.
/// Operations: 55 +, 81 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 56610 +, 77039 ×, 12650 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i2_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T tau_lo = pre[23];
  const T seg10 = pre[24];
  const T seg11 = pre[25];
  const T seg12 = pre[26];
  const T g_factor = pre[28];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * seg0;
    foot1 = (exact_cross[2] * ab0 - exact_cross[0] * ab2) * seg0;
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * seg0;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = seg8 + ap_bp;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t4 = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ap = t4;
    G_E = M_panels[5] * delta_tau + tau_lo * M_panels[4] - t4 * b * seg10;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    G_ap = M_panels[3] * tau_lo + delta_tau * M_panels[4];
    const T t5 = T(1) / c;
    const T t6 = t5 * tau_lo;
    const T t7 = T(1) / q1;
    G_E = (T(1) / T(2)) * (delta_tau * M_panels[0] + t6 - seg11 * t7) * seg10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / q1;
    const T t11 = T(1) / c;
    const T t12 = J2 * a + a_minus_b * t10 + t11 * b;
    const T t13 = T(1) / D;
    G_ap = (T(1) / T(2)) * t12 * t13 * tau_lo - (T(1) / T(2)) * delta_tau * (t10 - t12 * t13 * b - t11) * seg10;
    const T t14 = t11 * tau_lo;
    G_E = (T(1) / T(2)) * (t14 + J2 * delta_tau - seg11 * t10) * seg10;
  }
  const T foot_offset = (seg12 + ab_ap * delta_tau) * delta_tau * seg0 * sigma2 * seg10;
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  grad[0] = -g_factor * (G_E * ab0 - foot_h0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = g_factor * (foot_h2 * G_ap - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i2_prepare); operations per point.
/// Operations: 57 +, 90 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 56611 +, 77043 ×, 12650 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i2_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T tau_lo = pre[23];
  const T seg10 = pre[24];
  const T seg11 = pre[25];
  const T seg12 = pre[26];
  const T length = pre[27];
  const T g_factor = pre[28];
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
    foot0 = (exact_cross[1] * ab2 - exact_cross[2] * ab1) * seg0;
    foot1 = -seg0 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T b = ab_ap + seg1;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = ap_bp + seg8;
  T F;
  T G_ap;
  T G_E;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t4 = tau_lo * M_panels[3] + M_panels[4] * delta_tau;
    G_ap = t4;
    G_E = delta_tau * M_panels[5] + M_panels[4] * tau_lo - t4 * seg10 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    const T t5 = T(1) / c;
    const T t6 = t5 * tau_lo;
    const T t7 = T(1) / q1;
    G_E = (T(1) / T(2)) * seg10 * (t6 + delta_tau * M_panels[0] - t7 * seg11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    const T t10 = T(1) / c;
    const T log_ratio = log(t10 * q1);
    F = J2 * tau_lo + (T(1) / T(2)) * delta_tau * seg10 * (log_ratio + T(2) * J2 * b);
    const T t11 = T(1) / D;
    const T t12 = T(1) / q1;
    const T t13 = a_minus_b * t12 + J2 * a + t10 * b;
    G_ap = (T(1) / T(2)) * tau_lo * t11 * t13 + (T(1) / T(2)) * delta_tau * seg10 * (t11 * t13 * b + t10 - t12);
    const T t14 = t10 * tau_lo;
    G_E = (T(1) / T(2)) * (t14 + J2 * delta_tau - t12 * seg11) * seg10;
  }
  const T foot_offset = delta_tau * seg0 * sigma2 * seg10 * (seg12 + ab_ap * delta_tau);
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  f = length * sigma2 * F;
  grad[0] = (foot_h0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (foot_h1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot_h2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i3_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i3_prepared_size = 33;

/// What scalis_segment_cauchy_i3_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 33): computed once per
/// segment; in.p is not read.
/// Operations: 9 +, 24 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i3_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T g_factor = -T(3) * length * sigma2 * in.sigma;
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
  const T t1 = T(1) / ab_ab;
  pre[10] = t1;
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  pre[12] = t2 * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  const T t3 = sqrt(a);
  pre[20] = t3;
  const T t4 = T(1) / t3;
  pre[21] = t4;
  pre[22] = -a * a;
  pre[23] = a;
  pre[24] = t2;
  pre[25] = t0;
  pre[26] = tau_lo;
  const T t5 = T(1) / a;
  pre[27] = t5;
  pre[28] = t0 + T(2) * delta_tau * tau_lo + t2;
  pre[29] = tau_lo * ab_ab;
  pre[30] = length;
  pre[31] = in.sigma;
  pre[32] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i3_prepare); operations per point.
/// Operations: 43 +, 64 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 53922 +, 73987 ×, 16869 /, 7537 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i3_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T tau_lo = pre[26];
  const T seg13 = pre[27];
  const T length = pre[30];
  const T sigma = pre[31];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = b * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = b * r1;
    const T t3 = T(1) / D;
    X = seg8 * (t2 + r0 * a_minus_b) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = b * r1;
    X = seg8 * (b - a_minus_b) / (t4 - r0 * a_minus_b);
  }
  const T J1 = seg9 * asinh(X);
  T F;
  const T t5 = seg10 + T(4) * D;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg10 + T(100) * D));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * seg12 + T(2) * delta_tau * M_panels[1] * tau_lo + seg11 * M_panels[0];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * seg12 + T(2) * M_panels[1] * delta_tau * tau_lo + seg11 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r1;
    const T t9 = T(1) / r0;
    const T t10 = t8 * a_minus_b + t9 * b;
    const T t11 = T(1) / D;
    const T t12 = b * t10 * t11 + t9 - t8;
    F = seg12 * seg13 * (J1 + T(2) * t12 * b * seg13 - t10 * c * t11) + T(2) * t12 * seg13 * delta_tau * tau_lo + seg11 * t10 * t11;
  }
  f = sigma2 * F * sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i3_prepare); operations per point.
/// Operations: 59 +, 110 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 53869 +, 83103 ×, 10112 /, 4518 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i3_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T tau_lo = pre[26];
  const T seg13 = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T g_factor = pre[32];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
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
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = seg0 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -seg0 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = delta_tau * ap0 + seg3;
  const T radial1 = seg4 + delta_tau * ap1;
  const T radial2 = seg5 + delta_tau * ap2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg10;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg10));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(2) * delta_tau * tau_lo * M_panels[5] + M_panels[4] * seg11 + seg12 * M_panels[6];
    G_ap = t4;
    G_E = M_panels[5] * seg11 + T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[7] * seg12 - t4 * seg13 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    G_ap = M_panels[4] * seg11 + M_panels[6] * seg12 + T(2) * delta_tau * tau_lo * M_panels[5];
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * seg11;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    G_E = (T(1) / T(3)) * seg13 * (T(2) * seg12 * M_panels[1] + t8 + T(2) * delta_tau * tau_lo * M_panels[0] - seg14 * t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / D;
    const T t13 = T(1) / r0;
    const T t14 = T(1) / r1;
    const T t15 = b * t13 + a_minus_b * t14;
    const T t16 = t13 * t13;
    const T t17 = t14 * t14;
    const T t18 = T(2) * t12 * a * t15 + b * t13 * t16 + a_minus_b * t17 * t14;
    const T t19 = t18 * t12 * b + t13 * t16 - t17 * t14;
    G_ap = (T(1) / T(3)) * t18 * t12 * seg11 + (T(1) / T(3)) * seg13 * seg12 * (T(2) * seg13 * t19 * b + T(3) * t12 * t15 - t18 * t12 * c) + (T(2) / T(3)) * delta_tau * tau_lo * seg13 * t19;
    const T t20 = t13 * t13;
    const T t21 = t20 * t13;
    const T t22 = t21 * seg11;
    const T t23 = t14 * t14;
    const T t24 = t23 * t14;
    G_E = (T(1) / T(3)) * (T(2) * delta_tau * tau_lo * t12 * t15 + t22 - seg14 * t24 - T(2) * seg13 * seg12 * (t14 - t12 * b * t15 - t13)) * seg13;
  }
  const T foot_offset = delta_tau * seg0 * seg13 * (delta_tau * ab_ap + seg15) * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = foot1 + ab1 * foot_offset;
  const T foot_h2 = ab2 * foot_offset + foot2;
  grad[0] = g_factor * (foot_h0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = (G_ap * foot_h2 - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i3_prepare); operations per point.
/// Operations: 64 +, 132 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 53872 +, 83117 ×, 10113 /, 4518 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i3_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T tau_lo = pre[26];
  const T seg13 = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T length = pre[30];
  const T sigma = pre[31];
  const T g_factor = pre[32];
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
  T foot0;
  T foot1;
  T foot2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross_cross = plain_cross_cross;
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - ab1 * seg0 * ab_ap;
    foot2 = ap2 - ab2 * seg0 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = (exact_cross[1] * ab2 - exact_cross[2] * ab1) * seg0;
    foot1 = (exact_cross[2] * ab0 - exact_cross[0] * ab2) * seg0;
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = a_minus_b * b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / D;
    const T t3 = r1 * b;
    X = t2 * seg8 * (t3 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * b;
    X = -seg8 * (a_minus_b - b) / (t4 - r0 * a_minus_b);
  }
  const T J1 = asinh(X) * seg9;
  T F;
  T G_ap;
  T G_E;
  const T t5 = seg10 + T(4) * D;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg10 + T(100) * D));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * seg12 + seg11 * M_panels[0] + T(2) * delta_tau * tau_lo * M_panels[1];
    const T t8 = seg11 * M_panels[4] + M_panels[6] * seg12 + T(2) * M_panels[5] * delta_tau * tau_lo;
    G_ap = t8;
    G_E = M_panels[7] * seg12 + T(2) * delta_tau * M_panels[6] * tau_lo + M_panels[5] * seg11 - t8 * b * seg13;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = T(2) * M_panels[1] * delta_tau * tau_lo + M_panels[2] * seg12 + seg11 * M_panels[0];
    G_ap = M_panels[4] * seg11 + seg12 * M_panels[6] + T(2) * delta_tau * tau_lo * M_panels[5];
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = seg14 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    G_E = -(T(1) / T(3)) * (t12 - T(2) * M_panels[1] * seg12 - T(2) * delta_tau * tau_lo * M_panels[0] - t15 * seg11) * seg13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = T(1) / r0;
    const T t19 = a_minus_b * t17 + t18 * b;
    const T t20 = t16 * t19 * b + t18 - t17;
    F = T(2) * t20 * delta_tau * tau_lo * seg13 + seg12 * (J1 + T(2) * t20 * b * seg13 - c * t16 * t19) * seg13 + t16 * seg11 * t19;
    const T t21 = t17 * t17;
    const T t22 = t18 * t18;
    const T t23 = a_minus_b * t17 * t21 + T(2) * t16 * a * t19 + t22 * t18 * b;
    const T t24 = t16 * b * t23 + t22 * t18 - t17 * t21;
    G_ap = (T(2) / T(3)) * delta_tau * tau_lo * t24 * seg13 + (T(1) / T(3)) * t16 * seg11 * t23 - (T(1) / T(3)) * (c * t16 * t23 - T(2) * t24 * b * seg13 - T(3) * t16 * t19) * seg12 * seg13;
    const T t25 = t17 * t17;
    const T t26 = t25 * t17;
    const T t27 = seg14 * t26;
    const T t28 = t18 * t18;
    const T t29 = t28 * t18;
    G_E = -(T(1) / T(3)) * (t27 - T(2) * t20 * seg12 * seg13 - t29 * seg11 - T(2) * t16 * delta_tau * tau_lo * t19) * seg13;
  }
  const T foot_offset = delta_tau * (seg15 + delta_tau * ab_ap) * sigma2 * seg0 * seg13;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  f = length * F * sigma2 * sigma;
  grad[0] = -g_factor * (G_E * ab0 - foot_h0 * G_ap);
  grad[1] = (foot_h1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - foot_h2 * G_ap) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i4_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i4_prepared_size = 34;

/// What scalis_segment_cauchy_i4_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 34): computed once per
/// segment; in.p is not read.
/// Operations: 10 +, 30 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i4_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T t1 = sigma2 * sigma2;
  const T g_factor = -T(4) * length * t1;
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
  const T t2 = T(1) / ab_ab;
  pre[10] = t2;
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t3 = tau_lo * tau_lo;
  pre[12] = t3 * sigma2;
  pre[13] = delta_tau;
  pre[14] = ab0 * tau_lo;
  pre[15] = ab1 * tau_lo;
  pre[16] = ab2 * tau_lo;
  pre[17] = sigma2;
  pre[18] = tau_hi * delta_tau * sigma2;
  pre[19] = tau_hi * tau_hi * sigma2;
  pre[20] = tau_hi * tau_lo * sigma2;
  pre[21] = -a * a;
  pre[22] = a;
  pre[23] = t3;
  const T t4 = t0 * delta_tau;
  pre[24] = t4;
  const T t5 = t3 * tau_lo;
  pre[25] = t5;
  pre[26] = t0;
  pre[27] = tau_lo;
  const T t6 = T(1) / a;
  pre[28] = t6;
  pre[29] = T(3) * t0 * tau_lo + t5 + t4 + T(3) * delta_tau * t3;
  pre[30] = ab_ab * tau_lo;
  pre[31] = length;
  pre[32] = t1;
  pre[33] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i4_prepare); operations per point.
/// Operations: 50 +, 78 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 45840 +, 55496 ×, 12648 /, 270 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i4_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T length = pre[31];
  const T seg17 = pre[32];
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
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + delta_tau * ap0;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T F;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    F = seg11 * M_panels[3] + T(3) * M_panels[1] * delta_tau * seg10 + seg12 * M_panels[0] + T(3) * seg13 * M_panels[2] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    F = seg11 * M_panels[3] + T(3) * M_panels[1] * delta_tau * seg10 + seg12 * M_panels[0] + T(3) * seg13 * M_panels[2] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    const T t6 = T(1) / c;
    const T log_ratio = log(t6 * q1);
    const T t7 = T(1) / q1;
    const T t8 = a_minus_b * t7 + J2 * a + b * t6;
    const T t9 = T(1) / D;
    const T t10 = t7 - b * t8 * t9 - t6;
    const T t11 = T(2) * J2 - T(2) * b * t10 * seg14 - t8 * c * t9;
    F = (T(1) / T(2)) * seg11 * seg14 * (seg14 * (log_ratio + T(2) * J2 * b) + t10 * seg14 * c + T(2) * b * seg14 * t11) + (T(3) / T(2)) * seg13 * seg14 * t11 * tau_lo + (T(1) / T(2)) * t8 * seg12 * t9 - (T(3) / T(2)) * t10 * seg14 * delta_tau * seg10;
  }
  f = F * length * seg17;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i4_prepare); operations per point.
/// Operations: 69 +, 134 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 52034 +, 69214 ×, 8420 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i4_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T g_factor = pre[33];
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
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
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
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = -seg0 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = -seg0 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T G_ap;
  T G_E;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(3) * M_panels[7] * seg13 * tau_lo + T(3) * seg10 * delta_tau * M_panels[6] + M_panels[8] * seg11 + seg12 * M_panels[5];
    G_ap = t4;
    G_E = seg12 * M_panels[6] + T(3) * seg10 * M_panels[7] * delta_tau + T(3) * M_panels[8] * seg13 * tau_lo + M_panels[9] * seg11 - t4 * b * seg14;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    G_ap = seg12 * M_panels[5] + M_panels[8] * seg11 + T(3) * M_panels[7] * seg13 * tau_lo + T(3) * M_panels[6] * seg10 * delta_tau;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    G_E = -(T(1) / T(4)) * (t6 * seg15 - seg12 * t8 - T(3) * seg10 * M_panels[0] * delta_tau - T(3) * M_panels[2] * seg11 - T(6) * M_panels[1] * seg13 * tau_lo) * seg14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = T(1) / q1;
    const T t14 = t13 * t13;
    const T t15 = J2 * a + b * t11 + t13 * a_minus_b;
    const T t16 = T(1) / D;
    const T t17 = T(2) * b * t12 + T(2) * t14 * a_minus_b + T(3) * t15 * t16 * a;
    const T t18 = T(2) * t14 - T(2) * t12 - b * t17 * t16;
    const T t19 = c * t17 * t16 + T(2) * b * seg14 * t18 - T(4) * t15 * t16;
    const T t20 = t11 + b * t15 * t16 - t13;
    G_ap = (T(1) / T(8)) * seg12 * t17 * t16 - (T(1) / T(8)) * seg14 * seg11 * (T(2) * b * seg14 * t19 - T(4) * t20 * seg14 - seg14 * t18 * c) - (T(3) / T(8)) * seg10 * seg14 * t18 * delta_tau - (T(3) / T(8)) * seg14 * seg13 * t19 * tau_lo;
    G_E = -(T(1) / T(8)) * (T(2) * t14 * seg15 - T(6) * t20 * seg14 * seg13 * tau_lo - T(3) * seg10 * t15 * t16 * delta_tau - T(2) * seg12 * t12 - T(3) * (T(2) * J2 + T(2) * t20 * b * seg14 - t15 * c * t16) * seg14 * seg11) * seg14;
  }
  const T foot_offset = seg0 * sigma2 * seg14 * delta_tau * (seg16 + ab_ap * delta_tau);
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  grad[0] = (G_ap * foot_h0 - G_E * ab0) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot_h1) * g_factor;
  grad[2] = (G_ap * foot_h2 - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i4_prepare); operations per point.
/// Operations: 75 +, 159 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 52037 +, 69224 ×, 8420 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i4_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T length = pre[31];
  const T seg17 = pre[32];
  const T g_factor = pre[33];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = seg0 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = seg0 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -seg0 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T F;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    F = T(3) * tau_lo * seg13 * M_panels[2] + M_panels[0] * seg12 + M_panels[3] * seg11 + T(3) * seg10 * M_panels[1] * delta_tau;
    const T t4 = seg12 * M_panels[5] + T(3) * M_panels[7] * tau_lo * seg13 + T(3) * M_panels[6] * seg10 * delta_tau + seg11 * M_panels[8];
    G_ap = t4;
    G_E = seg11 * M_panels[9] + T(3) * seg10 * M_panels[7] * delta_tau + T(3) * M_panels[8] * tau_lo * seg13 + M_panels[6] * seg12 - seg14 * b * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * seg12 + T(3) * tau_lo * seg13 * M_panels[2] + T(3) * seg10 * M_panels[1] * delta_tau + M_panels[3] * seg11;
    G_ap = T(3) * M_panels[7] * tau_lo * seg13 + seg12 * M_panels[5] + seg11 * M_panels[8] + T(3) * seg10 * M_panels[6] * delta_tau;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    G_E = (T(1) / T(4)) * seg14 * (t6 * seg12 + T(3) * seg11 * M_panels[2] + T(6) * M_panels[1] * tau_lo * seg13 + T(3) * seg10 * M_panels[0] * delta_tau - t8 * seg15);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / c;
    const T log_ratio = log(q1 * t11);
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = b * t11 + J2 * a + t13 * a_minus_b;
    const T t15 = t11 + b * t12 * t14 - t13;
    const T t16 = c * t12 * t14 - T(2) * J2 - T(2) * seg14 * b * t15;
    F = (T(3) / T(2)) * seg14 * seg10 * delta_tau * t15 + (T(1) / T(2)) * seg12 * t12 * t14 + (T(1) / T(2)) * seg14 * (seg14 * (T(2) * b * J2 + log_ratio) - seg14 * c * t15 - T(2) * seg14 * b * t16) * seg11 - (T(3) / T(2)) * seg14 * t16 * tau_lo * seg13;
    const T t17 = t13 * t13;
    const T t18 = t11 * t11;
    const T t19 = T(3) * t12 * t14 * a + T(2) * t17 * a_minus_b + T(2) * b * t18;
    const T t20 = b * t12 * t19 + T(2) * t18 - T(2) * t17;
    const T t21 = T(2) * seg14 * b * t20 + T(4) * t12 * t14 - c * t12 * t19;
    G_ap = (T(1) / T(8)) * seg12 * t12 * t19 + (T(1) / T(8)) * seg14 * seg11 * (T(4) * seg14 * t15 + T(2) * seg14 * b * t21 - seg14 * c * t20) + (T(3) / T(8)) * seg14 * t21 * tau_lo * seg13 + (T(3) / T(8)) * seg14 * seg10 * delta_tau * t20;
    G_E = (T(1) / T(8)) * seg14 * (T(2) * t18 * seg12 + T(6) * seg14 * t15 * tau_lo * seg13 + T(3) * seg10 * t12 * delta_tau * t14 - T(2) * t17 * seg15 - T(3) * seg14 * t16 * seg11);
  }
  const T foot_offset = seg14 * seg0 * delta_tau * (ab_ap * delta_tau + seg16) * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  f = length * F * seg17;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot_h0);
  grad[1] = g_factor * (foot_h1 * G_ap - ab1 * G_E);
  grad[2] = -(ab2 * G_E - G_ap * foot_h2) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i5_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i5_prepared_size = 38;

/// What scalis_segment_cauchy_i5_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 38): computed once per
/// segment; in.p is not read.
/// Operations: 11 +, 33 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i5_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T t1 = sigma2 * sigma2;
  const T g_factor = -T(5) * t1 * in.sigma * length;
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
  const T t2 = T(1) / ab_ab;
  pre[10] = t2;
  pre[11] = -sigma2 * delta_tau * tau_lo;
  const T t3 = tau_lo * tau_lo;
  pre[12] = sigma2 * t3;
  pre[13] = delta_tau;
  pre[14] = ab0 * tau_lo;
  pre[15] = ab1 * tau_lo;
  pre[16] = ab2 * tau_lo;
  pre[17] = sigma2;
  pre[18] = sigma2 * tau_hi * delta_tau;
  pre[19] = sigma2 * tau_hi * tau_hi;
  const T t4 = sqrt(a);
  pre[20] = t4;
  const T t5 = T(1) / t4;
  pre[21] = t5;
  pre[22] = -a * a;
  pre[23] = a;
  const T t6 = t3 * t3;
  pre[24] = t6;
  const T t7 = t3 * tau_lo;
  pre[25] = t7;
  pre[26] = t0;
  pre[27] = t3;
  const T t8 = t0 * t0;
  pre[28] = t8;
  const T t9 = t0 * delta_tau;
  pre[29] = t9;
  pre[30] = tau_lo;
  const T t10 = T(1) / a;
  pre[31] = t10;
  pre[32] = T(4) * t9 * tau_lo + T(6) * t0 * t3 + t6 + t8 + T(4) * delta_tau * t7;
  pre[33] = ab_ab * tau_lo;
  pre[34] = t1;
  pre[35] = in.sigma;
  pre[36] = length;
  pre[37] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i5_prepare); operations per point.
/// Operations: 55 +, 108 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 40959 +, 61579 ×, 10111 /, 4518 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i5_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T tau_lo = pre[30];
  const T seg17 = pre[31];
  const T seg20 = pre[34];
  const T sigma = pre[35];
  const T length = pre[36];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = b * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = r0 * a_minus_b;
    const T t3 = T(1) / D;
    X = seg8 * (t2 + b * r1) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r0 * a_minus_b;
    X = -seg8 * (b - a_minus_b) / (t4 - b * r1);
  }
  const T J1 = asinh(X) * seg9;
  T F;
  const T t5 = T(4) * D + seg10;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg10));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    F = T(4) * seg12 * M_panels[1] * delta_tau + T(6) * M_panels[2] * seg13 * seg14 + seg15 * M_panels[4] + T(4) * seg16 * M_panels[3] * tau_lo + M_panels[0] * seg11;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    F = T(6) * seg13 * M_panels[2] * seg14 + seg11 * M_panels[0] + T(4) * seg16 * tau_lo * M_panels[3] + T(4) * seg12 * M_panels[1] * delta_tau + M_panels[4] * seg15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = t8 * b + t9 * a_minus_b;
    const T t11 = T(1) / D;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(2) * t10 * t11 * a + t8 * b * t12 + t9 * a_minus_b * t13;
    const T t15 = t8 * t12 + t14 * b * t11 - t9 * t13;
    const T t16 = T(3) * t10 * t11 + T(2) * seg17 * b * t15 - t14 * c * t11;
    const T t17 = t9 - b * t10 * t11 - t8;
    const T t18 = T(2) * t16 * seg17 * b - seg17 * t15 * c - T(3) * seg17 * t17;
    F = T(2) * t16 * seg17 * seg13 * seg14 + (T(4) / T(3)) * seg17 * seg12 * t15 * delta_tau + (T(1) / T(3)) * t14 * seg11 * t11 + (T(4) / T(3)) * seg17 * seg16 * t18 * tau_lo - (T(1) / T(3)) * seg17 * seg15 * (t16 * seg17 * c - T(3) * (J1 - t10 * c * t11 - T(2) * seg17 * b * t17) * seg17 - T(2) * seg17 * b * t18);
  }
  f = F * seg20 * sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i5_prepare); operations per point.
/// Operations: 75 +, 175 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 50943 +, 78051 ×, 7245 /, 3237 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i5_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T tau_lo = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T g_factor = pre[37];
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
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * seg0;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * seg0;
    foot2 = -seg0 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = delta_tau * ap0 + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg10;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D + seg10));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t4 = M_panels[10] * seg15 + seg11 * M_panels[6] + T(4) * tau_lo * seg16 * M_panels[9] + T(6) * seg13 * seg14 * M_panels[8] + T(4) * delta_tau * seg12 * M_panels[7];
    G_ap = t4;
    G_E = T(4) * delta_tau * seg12 * M_panels[8] + T(6) * seg13 * seg14 * M_panels[9] + M_panels[7] * seg11 + T(4) * M_panels[10] * tau_lo * seg16 + M_panels[11] * seg15 - seg17 * b * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    G_ap = M_panels[6] * seg11 + T(6) * seg13 * seg14 * M_panels[8] + M_panels[10] * seg15 + T(4) * delta_tau * seg12 * M_panels[7] + T(4) * tau_lo * seg16 * M_panels[9];
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(5)) * seg17 * (T(12) * tau_lo * M_panels[2] * seg16 + T(4) * seg15 * M_panels[3] + t8 * seg11 + T(12) * M_panels[1] * seg13 * seg14 + T(4) * delta_tau * seg12 * M_panels[0] - t12 * seg18);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / D;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = b * t14 + t16 * a_minus_b;
    const T t19 = b * t14 * t15 + t16 * a_minus_b * t17 + T(2) * t13 * a * t18;
    const T t20 = t17 * t17;
    const T t21 = t15 * t15;
    const T t22 = T(3) * t16 * a_minus_b * t20 + T(4) * t13 * a * t19 + T(3) * b * t14 * t21;
    const T t23 = t13 * t22 * b + T(3) * t14 * t21 - T(3) * t16 * t20;
    const T t24 = T(5) * t13 * t19 + T(2) * seg17 * b * t23 - t13 * t22 * c;
    const T t25 = t14 * t15 + t13 * b * t19 - t16 * t17;
    const T t26 = T(5) * seg17 * t25 + T(2) * seg17 * t24 * b - seg17 * c * t23;
    const T t27 = T(2) * seg17 * b * t25 + T(3) * t13 * t18 - t13 * t19 * c;
    G_ap = (T(2) / T(5)) * seg17 * seg13 * seg14 * t24 + (T(1) / T(15)) * t13 * t22 * seg11 + (T(4) / T(15)) * seg17 * delta_tau * seg12 * t23 + (T(4) / T(15)) * seg17 * tau_lo * seg16 * t26 - (T(1) / T(15)) * seg17 * (seg17 * t24 * c - T(5) * seg17 * t27 - T(2) * seg17 * b * t26) * seg15;
    const T t28 = t16 * t16;
    const T t29 = t28 * t28;
    const T t30 = t29 * t16;
    const T t31 = t14 * t14;
    const T t32 = t31 * t31;
    const T t33 = t32 * t14;
    G_E = -(T(1) / T(15)) * seg17 * (T(3) * t30 * seg18 - T(4) * delta_tau * t13 * seg12 * t19 - T(3) * t33 * seg11 - T(12) * seg17 * tau_lo * seg16 * t27 - T(12) * seg17 * seg13 * seg14 * t25 - T(4) * seg17 * seg15 * (T(2) * seg17 * b * t27 + T(3) * seg17 * (t13 * b * t18 + t14 - t16) - seg17 * t25 * c));
  }
  const T foot_offset = seg17 * delta_tau * sigma2 * seg0 * (delta_tau * ab_ap + seg19);
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = ab2 * foot_offset + foot2;
  grad[0] = (foot_h0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (foot_h1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot_h2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i5_prepare); operations per point.
/// Operations: 84 +, 214 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 50948 +, 78071 ×, 7246 /, 3237 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i5_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T tau_lo = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T sigma = pre[35];
  const T length = pre[36];
  const T g_factor = pre[37];
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
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
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
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + delta_tau * ap0;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = a_minus_b * b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / D;
    X = (t2 + r1 * b) * seg8 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = (a_minus_b - b) * seg8 / (t4 - r1 * b);
  }
  const T J1 = seg9 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t5 = seg10 + T(4) * D;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg10 + T(100) * D));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    F = seg15 * M_panels[4] + T(4) * seg12 * M_panels[1] * delta_tau + T(6) * seg13 * M_panels[2] * seg14 + M_panels[0] * seg11 + T(4) * M_panels[3] * seg16 * tau_lo;
    const T t8 = T(4) * seg12 * M_panels[7] * delta_tau + T(6) * seg13 * M_panels[8] * seg14 + T(4) * seg16 * M_panels[9] * tau_lo + M_panels[6] * seg11 + seg15 * M_panels[10];
    G_ap = t8;
    G_E = T(4) * seg12 * M_panels[8] * delta_tau + seg15 * M_panels[11] + M_panels[7] * seg11 + T(4) * M_panels[10] * seg16 * tau_lo + T(6) * seg13 * seg14 * M_panels[9] - b * t8 * seg17;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[4] * seg15 + T(6) * M_panels[2] * seg13 * seg14 + T(4) * M_panels[1] * seg12 * delta_tau + T(4) * seg16 * M_panels[3] * tau_lo + M_panels[0] * seg11;
    G_ap = T(4) * M_panels[7] * seg12 * delta_tau + T(6) * M_panels[8] * seg13 * seg14 + M_panels[10] * seg15 + T(4) * seg16 * M_panels[9] * tau_lo + M_panels[6] * seg11;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t13;
    G_E = (T(1) / T(5)) * (T(4) * seg15 * M_panels[3] + t12 * seg11 + T(4) * seg12 * M_panels[0] * delta_tau + T(12) * M_panels[1] * seg13 * seg14 + T(12) * seg16 * M_panels[2] * tau_lo - seg18 * t16) * seg17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = b * t17 + t19 * a_minus_b;
    const T t22 = T(1) / D;
    const T t23 = b * t18 * t17 + t19 * a_minus_b * t20 + T(2) * t21 * t22 * a;
    const T t24 = t18 * t17 + b * t23 * t22 - t19 * t20;
    const T t25 = T(3) * t21 * t22 + T(2) * t24 * b * seg17 - t23 * c * t22;
    const T t26 = t17 + b * t21 * t22 - t19;
    const T t27 = T(2) * b * t25 * seg17 + T(3) * t26 * seg17 - t24 * c * seg17;
    F = (T(1) / T(3)) * t23 * seg11 * t22 + (T(4) / T(3)) * t27 * seg16 * seg17 * tau_lo + T(2) * seg13 * t25 * seg17 * seg14 + (T(4) / T(3)) * seg12 * t24 * seg17 * delta_tau - (T(1) / T(3)) * seg15 * (t25 * c * seg17 - T(3) * seg17 * (T(2) * b * t26 * seg17 + J1 - c * t21 * t22) - T(2) * b * t27 * seg17) * seg17;
    const T t28 = t20 * t20;
    const T t29 = t18 * t18;
    const T t30 = T(4) * t23 * t22 * a + T(3) * t19 * a_minus_b * t28 + T(3) * b * t29 * t17;
    const T t31 = T(3) * t19 * t28 - b * t30 * t22 - T(3) * t29 * t17;
    const T t32 = T(5) * t23 * t22 - T(2) * t31 * b * seg17 - t30 * c * t22;
    const T t33 = T(2) * b * t32 * seg17 + t31 * c * seg17 + T(5) * t24 * seg17;
    G_ap = (T(1) / T(15)) * seg15 * (T(5) * t25 * seg17 + T(2) * t33 * b * seg17 - t32 * c * seg17) * seg17 + (T(2) / T(5)) * t32 * seg13 * seg17 * seg14 + (T(4) / T(15)) * t33 * seg16 * seg17 * tau_lo + (T(1) / T(15)) * t30 * seg11 * t22 - (T(4) / T(15)) * t31 * seg12 * seg17 * delta_tau;
    const T t34 = t17 * t17;
    const T t35 = t34 * t34;
    const T t36 = t35 * t17;
    const T t37 = t19 * t19;
    const T t38 = t37 * t37;
    const T t39 = t38 * t19;
    G_E = (T(1) / T(15)) * seg17 * (T(12) * t24 * seg13 * seg17 * seg14 + T(3) * t36 * seg11 + T(4) * seg12 * t23 * delta_tau * t22 + T(12) * seg16 * t25 * seg17 * tau_lo + T(4) * seg15 * t27 * seg17 - T(3) * seg18 * t39);
  }
  const T foot_offset = (ab_ap * delta_tau + seg19) * sigma2 * seg0 * seg17 * delta_tau;
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = foot1 + ab1 * foot_offset;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  f = F * sigma * length * seg20;
  grad[0] = (G_ap * foot_h0 - ab0 * G_E) * g_factor;
  grad[1] = (foot_h1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot_h2) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i6_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i6_prepared_size = 38;

/// What scalis_segment_cauchy_i6_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 38): computed once per
/// segment; in.p is not read.
/// Operations: 12 +, 39 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i6_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T t1 = sigma2 * sigma2;
  const T t2 = t1 * sigma2;
  const T g_factor = -T(6) * length * t2;
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
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  pre[12] = t4 * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  pre[20] = tau_lo * sigma2 * tau_hi;
  pre[21] = -a * a;
  pre[22] = a;
  const T t5 = t4 * t4;
  pre[23] = t5;
  const T t6 = t0 * t0;
  pre[24] = t6;
  pre[25] = tau_lo;
  const T t7 = t5 * tau_lo;
  pre[26] = t7;
  const T t8 = t6 * delta_tau;
  pre[27] = t8;
  pre[28] = t0;
  const T t9 = t4 * tau_lo;
  pre[29] = t9;
  const T t10 = t0 * delta_tau;
  pre[30] = t10;
  pre[31] = t4;
  const T t11 = T(1) / a;
  pre[32] = t11;
  pre[33] = T(10) * t0 * t9 + T(5) * delta_tau * t5 + t8 + T(10) * t10 * t4 + t7 + T(5) * t6 * tau_lo;
  pre[34] = tau_lo * ab_ab;
  pre[35] = length;
  pre[36] = t2;
  pre[37] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i6_prepare); operations per point.
/// Operations: 64 +, 127 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 37702 +, 51282 ×, 8418 /, 180 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i6_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T tau_lo = pre[25];
  const T seg12 = pre[26];
  const T seg13 = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T length = pre[35];
  const T seg21 = pre[36];
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + delta_tau * ap0;
  const T radial1 = delta_tau * ap1 + seg4;
  const T radial2 = seg5 + delta_tau * ap2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = seg8 + ap_bp;
  T F;
  const T t1 = T(4) * D + seg9;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    F = T(5) * M_panels[4] * seg11 * tau_lo + seg13 * M_panels[5] + seg12 * M_panels[0] + T(10) * seg15 * M_panels[2] * seg14 + T(10) * seg17 * M_panels[3] * seg16 + T(5) * delta_tau * M_panels[1] * seg10;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    F = T(5) * M_panels[4] * seg11 * tau_lo + seg12 * M_panels[0] + T(5) * delta_tau * M_panels[1] * seg10 + T(10) * seg15 * M_panels[2] * seg14 + T(10) * seg17 * M_panels[3] * seg16 + seg13 * M_panels[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(1) / c;
    const T log_ratio = log(q1 * t6);
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = b * t6 + a * J2 + t8 * a_minus_b;
    const T t11 = t6 * t6;
    const T t12 = T(2) * t9 * a_minus_b + T(3) * t7 * a * t10 + T(2) * b * t11;
    const T t13 = t7 * t12 * b + T(2) * t11 - T(2) * t9;
    const T t14 = t7 * t10 * b + t6 - t8;
    const T t15 = T(2) * J2 + T(2) * b * seg18 * t14 - t7 * t10 * c;
    const T t16 = T(2) * b * seg18 * t13 + T(4) * t7 * t10 - t7 * t12 * c;
    const T t17 = T(4) * seg18 * t14 + T(2) * t16 * b * seg18 - seg18 * c * t13;
    const T t18 = t16 * seg18 * c - T(2) * t17 * b * seg18 - T(4) * t15 * seg18;
    F = (T(1) / T(8)) * seg12 * t7 * t12 + (T(5) / T(8)) * delta_tau * seg18 * seg10 * t13 + (T(1) / T(8)) * seg13 * (T(4) * seg18 * (T(2) * t15 * b * seg18 + (T(2) * J2 * b + log_ratio) * seg18 - seg18 * c * t14) - t17 * seg18 * c - T(2) * b * seg18 * t18) * seg18 + (T(5) / T(4)) * t17 * seg17 * seg18 * seg16 + (T(5) / T(4)) * seg15 * t16 * seg18 * seg14 - (T(5) / T(8)) * seg18 * t18 * seg11 * tau_lo;
  }
  f = F * seg21 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i6_prepare); operations per point.
/// Operations: 87 +, 198 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 49708 +, 65258 ×, 6305 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i6_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T tau_lo = pre[25];
  const T seg12 = pre[26];
  const T seg13 = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T g_factor = pre[37];
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
    foot0 = seg0 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -seg0 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = seg0 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + delta_tau * ap0;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = seg8 + ap_bp;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(5) * delta_tau * M_panels[8] * seg10 + seg13 * M_panels[12] + M_panels[7] * seg12 + T(10) * M_panels[9] * seg14 * seg15 + T(10) * seg17 * M_panels[10] * seg16 + T(5) * tau_lo * seg11 * M_panels[11];
    G_ap = t4;
    G_E = T(10) * seg17 * M_panels[11] * seg16 + T(5) * tau_lo * seg11 * M_panels[12] + seg13 * M_panels[13] + T(10) * seg14 * M_panels[10] * seg15 + seg12 * M_panels[8] + T(5) * M_panels[9] * delta_tau * seg10 - t4 * b * seg18;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    G_ap = seg13 * M_panels[12] + seg12 * M_panels[7] + T(5) * M_panels[8] * delta_tau * seg10 + T(5) * M_panels[11] * tau_lo * seg11 + T(10) * seg17 * M_panels[10] * seg16 + T(10) * seg14 * M_panels[9] * seg15;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    G_E = (T(1) / T(6)) * (T(5) * seg13 * M_panels[4] + T(20) * tau_lo * M_panels[3] * seg11 + T(30) * seg17 * M_panels[2] * seg16 + T(5) * delta_tau * M_panels[0] * seg10 + T(20) * seg14 * seg15 * M_panels[1] + t7 * seg12 - seg19 * t10) * seg18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / D;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = a * J2 + t17 * b + a_minus_b * t14;
    const T t21 = T(2) * a_minus_b * t15 + T(2) * t18 * b + T(3) * t20 * t13 * a;
    const T t22 = T(8) * a_minus_b * t16 + T(8) * t19 * b + T(5) * t13 * a * t21;
    const T t23 = t13 * b * t22 + T(8) * t19 - T(8) * t16;
    const T t24 = T(6) * t13 * t21 + T(2) * t23 * b * seg18 - c * t13 * t22;
    const T t25 = T(2) * t18 + t13 * b * t21 - T(2) * t15;
    const T t26 = T(2) * b * seg18 * t25 + T(4) * t20 * t13 - c * t13 * t21;
    const T t27 = c * t23 * seg18 - T(2) * t24 * b * seg18 - T(6) * seg18 * t25;
    const T t28 = T(6) * t26 * seg18 - T(2) * t27 * b * seg18 - c * t24 * seg18;
    const T t29 = t20 * t13 * b + t17 - t14;
    const T t30 = T(2) * t26 * b * seg18 + T(4) * t29 * seg18 - c * seg18 * t25;
    G_ap = (T(1) / T(48)) * t13 * seg12 * t22 + (T(5) / T(48)) * t23 * delta_tau * seg18 * seg10 + (T(5) / T(24)) * t24 * seg14 * seg15 * seg18 + (T(5) / T(48)) * tau_lo * seg11 * seg18 * t28 + (T(1) / T(48)) * seg13 * (T(2) * b * seg18 * t28 + c * t27 * seg18 + T(6) * t30 * seg18) * seg18 - (T(5) / T(24)) * seg17 * t27 * seg18 * seg16;
    G_E = (T(1) / T(48)) * (T(20) * t30 * tau_lo * seg11 * seg18 + T(20) * seg14 * seg15 * seg18 * t25 + T(30) * seg17 * t26 * seg18 * seg16 + T(5) * delta_tau * t13 * seg10 * t21 + T(8) * t19 * seg12 - T(8) * seg19 * t16 - T(5) * seg13 * (c * t26 * seg18 - T(4) * (T(2) * t29 * b * seg18 + T(2) * J2 - c * t20 * t13) * seg18 - T(2) * t30 * b * seg18) * seg18) * seg18;
  }
  const T foot_offset = seg0 * delta_tau * sigma2 * seg18 * (seg20 + ab_ap * delta_tau);
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  grad[0] = -g_factor * (ab0 * G_E - foot_h0 * G_ap);
  grad[1] = -(ab1 * G_E - foot_h1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * foot_h2 - ab2 * G_E);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i6_prepare); operations per point.
/// Operations: 97 +, 238 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 49713 +, 65274 ×, 6305 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i6_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T tau_lo = pre[25];
  const T seg12 = pre[26];
  const T seg13 = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T length = pre[35];
  const T seg21 = pre[36];
  const T g_factor = pre[37];
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
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
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
    foot0 = -seg0 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = seg0 * (exact_cross[2] * ab0 - exact_cross[0] * ab2);
    foot2 = -seg0 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = seg8 + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    F = T(5) * M_panels[1] * seg10 * delta_tau + M_panels[0] * seg12 + T(10) * M_panels[2] * seg14 * seg15 + seg13 * M_panels[5] + T(10) * seg16 * seg17 * M_panels[3] + T(5) * tau_lo * seg11 * M_panels[4];
    const T t4 = T(10) * seg16 * seg17 * M_panels[10] + seg13 * M_panels[12] + T(5) * seg10 * M_panels[8] * delta_tau + T(10) * seg14 * M_panels[9] * seg15 + seg12 * M_panels[7] + T(5) * M_panels[11] * tau_lo * seg11;
    G_ap = t4;
    G_E = T(5) * tau_lo * seg11 * M_panels[12] + T(5) * seg10 * delta_tau * M_panels[9] + T(10) * M_panels[11] * seg16 * seg17 + M_panels[8] * seg12 + T(10) * seg14 * M_panels[10] * seg15 + seg13 * M_panels[13] - t4 * b * seg18;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * seg12 + seg13 * M_panels[5] + T(10) * seg14 * M_panels[2] * seg15 + T(5) * tau_lo * M_panels[4] * seg11 + T(5) * seg10 * delta_tau * M_panels[1] + T(10) * M_panels[3] * seg16 * seg17;
    G_ap = T(5) * tau_lo * seg11 * M_panels[11] + T(5) * seg10 * delta_tau * M_panels[8] + T(10) * seg16 * M_panels[10] * seg17 + seg13 * M_panels[12] + T(10) * seg14 * seg15 * M_panels[9] + M_panels[7] * seg12;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    G_E = (T(1) / T(6)) * (T(5) * M_panels[0] * seg10 * delta_tau + T(30) * seg16 * seg17 * M_panels[2] + T(20) * M_panels[3] * tau_lo * seg11 + T(20) * seg14 * M_panels[1] * seg15 + T(5) * seg13 * M_panels[4] + seg12 * t7 - seg19 * t10) * seg18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / c;
    const T log_ratio = log(q1 * t13);
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = a_minus_b * t15 + b * t13 + J2 * a;
    const T t17 = t13 * t13;
    const T t18 = t15 * t15;
    const T t19 = T(3) * t14 * a * t16 + T(2) * b * t17 + T(2) * a_minus_b * t18;
    const T t20 = t14 * b * t19 + T(2) * t17 - T(2) * t18;
    const T t21 = t14 * t19 * c - T(2) * b * seg18 * t20 - T(4) * t14 * t16;
    const T t22 = t15 - t13 - t14 * b * t16;
    const T t23 = seg18 * t20 * c + T(2) * t21 * b * seg18 + T(4) * seg18 * t22;
    const T t24 = T(2) * J2 - T(2) * b * seg18 * t22 - t14 * t16 * c;
    const T t25 = t21 * seg18 * c + T(4) * t24 * seg18 - T(2) * t23 * b * seg18;
    F = (T(1) / T(8)) * seg13 * (t23 * seg18 * c + T(4) * (seg18 * t22 * c + T(2) * t24 * b * seg18 + (T(2) * J2 * b + log_ratio) * seg18) * seg18 + T(2) * b * seg18 * t25) * seg18 + (T(1) / T(8)) * t14 * seg12 * t19 + (T(5) / T(8)) * seg10 * delta_tau * seg18 * t20 + (T(5) / T(8)) * tau_lo * seg11 * seg18 * t25 - (T(5) / T(4)) * seg16 * t23 * seg17 * seg18 - (T(5) / T(4)) * t21 * seg14 * seg18 * seg15;
    const T t26 = t17 * t13;
    const T t27 = t18 * t15;
    const T t28 = T(5) * t14 * a * t19 + T(8) * b * t26 + T(8) * a_minus_b * t27;
    const T t29 = T(8) * t26 + t14 * b * t28 - T(8) * t27;
    const T t30 = t14 * t28 * c - T(2) * t29 * b * seg18 - T(6) * t14 * t19;
    const T t31 = T(6) * seg18 * t20 - t29 * seg18 * c - T(2) * t30 * b * seg18;
    const T t32 = T(2) * t31 * b * seg18 + t30 * seg18 * c - T(6) * t21 * seg18;
    G_ap = (T(1) / T(48)) * t14 * t28 * seg12 + (T(5) / T(48)) * seg10 * delta_tau * t29 * seg18 + (T(5) / T(24)) * seg16 * t31 * seg17 * seg18 + (T(5) / T(48)) * tau_lo * seg11 * seg18 * t32 - (T(1) / T(48)) * seg13 * (t31 * seg18 * c + T(6) * t23 * seg18 - T(2) * b * seg18 * t32) * seg18 - (T(5) / T(24)) * t30 * seg14 * seg18 * seg15;
    G_E = (T(1) / T(48)) * (T(5) * seg10 * t14 * delta_tau * t19 + T(5) * seg13 * seg18 * t25 + T(8) * seg12 * t26 + T(20) * seg14 * seg18 * t20 * seg15 - T(30) * seg16 * t21 * seg17 * seg18 - T(20) * tau_lo * t23 * seg11 * seg18 - T(8) * seg19 * t27) * seg18;
  }
  const T foot_offset = seg0 * delta_tau * sigma2 * seg18 * (seg20 + delta_tau * ab_ap);
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  f = length * F * seg21;
  grad[0] = -(G_E * ab0 - foot_h0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot_h1 * G_ap) * g_factor;
  grad[2] = (foot_h2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i7_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i7_prepared_size = 42;

/// What scalis_segment_cauchy_i7_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 42): computed once per
/// segment; in.p is not read.
/// Operations: 13 +, 42 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i7_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T t1 = sigma2 * sigma2;
  const T t2 = t1 * sigma2;
  const T g_factor = -T(7) * t2 * in.sigma * length;
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
  const T t3 = T(1) / ab_ab;
  pre[10] = t3;
  pre[11] = -sigma2 * tau_lo * delta_tau;
  const T t4 = tau_lo * tau_lo;
  pre[12] = sigma2 * t4;
  pre[13] = delta_tau;
  pre[14] = ab0 * tau_lo;
  pre[15] = ab1 * tau_lo;
  pre[16] = ab2 * tau_lo;
  pre[17] = sigma2;
  pre[18] = tau_hi * sigma2 * delta_tau;
  pre[19] = tau_hi * tau_hi * sigma2;
  const T t5 = sqrt(a);
  pre[20] = t5;
  const T t6 = T(1) / t5;
  pre[21] = t6;
  pre[22] = -a * a;
  pre[23] = a;
  pre[24] = t4;
  const T t7 = t0 * t0;
  pre[25] = t7;
  const T t8 = t4 * t4;
  const T t9 = t8 * tau_lo;
  pre[26] = t9;
  pre[27] = tau_lo;
  const T t10 = t7 * delta_tau;
  pre[28] = t10;
  const T t11 = t4 * tau_lo;
  const T t12 = t11 * t11;
  pre[29] = t12;
  pre[30] = t8;
  pre[31] = t0;
  const T t13 = t0 * delta_tau;
  const T t14 = t13 * t13;
  pre[32] = t14;
  pre[33] = t11;
  pre[34] = t13;
  const T t15 = T(1) / a;
  pre[35] = t15;
  pre[36] = T(20) * t11 * t13 + t14 + t12 + T(6) * tau_lo * t10 + T(15) * t4 * t7 + T(6) * t9 * delta_tau + T(15) * t8 * t0;
  pre[37] = ab_ab * tau_lo;
  pre[38] = t2;
  pre[39] = in.sigma;
  pre[40] = length;
  pre[41] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i7_prepare); operations per point.
/// Operations: 71 +, 166 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 35531 +, 59539 ×, 7244 /, 3237 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i7_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg24 = pre[38];
  const T sigma = pre[39];
  const T length = pre[40];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
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
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = b * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = r0 * a_minus_b;
    const T t3 = T(1) / D;
    X = (t2 + b * r1) * seg8 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r0 * a_minus_b;
    X = -(b - a_minus_b) * seg8 / (t4 - b * r1);
  }
  const T J1 = seg9 * asinh(X);
  T F;
  const T t5 = seg10 + T(4) * D;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg10 + T(100) * D));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    F = T(15) * seg17 * M_panels[2] * seg16 + T(6) * M_panels[5] * seg14 * tau_lo + seg15 * M_panels[0] + T(20) * seg19 * M_panels[3] * seg20 + T(15) * seg12 * seg11 * M_panels[4] + T(6) * M_panels[1] * seg13 * delta_tau + M_panels[6] * seg18;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    F = T(6) * seg13 * delta_tau * M_panels[1] + T(15) * seg17 * M_panels[2] * seg16 + seg15 * M_panels[0] + T(6) * M_panels[5] * seg14 * tau_lo + T(15) * seg12 * seg11 * M_panels[4] + T(20) * seg19 * M_panels[3] * seg20 + M_panels[6] * seg18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t8 * b + a_minus_b * t10;
    const T t13 = T(1) / D;
    const T t14 = t8 * b * t9 + a_minus_b * t10 * t11 + T(2) * a * t12 * t13;
    const T t15 = t11 * t11;
    const T t16 = t9 * t9;
    const T t17 = T(4) * t14 * a * t13 + T(3) * a_minus_b * t10 * t15 + T(3) * t8 * b * t16;
    const T t18 = t8 * t9 + t14 * b * t13 - t10 * t11;
    const T t19 = b * t17 * t13 + T(3) * t8 * t16 - T(3) * t10 * t15;
    const T t20 = T(5) * t14 * t13 + T(2) * b * t19 * seg21 - t17 * c * t13;
    const T t21 = T(5) * t18 * seg21 + T(2) * b * seg21 * t20 - t19 * c * seg21;
    const T t22 = t14 * c * t13 - T(2) * b * t18 * seg21 - T(3) * t12 * t13;
    const T t23 = T(2) * b * t21 * seg21 - c * seg21 * t20 - T(5) * t22 * seg21;
    const T t24 = t8 + t12 * b * t13 - t10;
    const T t25 = T(2) * t22 * b * seg21 + t18 * c * seg21 - T(3) * t24 * seg21;
    const T t26 = T(5) * t25 * seg21 + c * t21 * seg21 - T(2) * t23 * b * seg21;
    F = (T(1) / T(15)) * seg15 * t17 * t13 + seg12 * t23 * seg11 * seg21 + (T(2) / T(5)) * t19 * seg13 * delta_tau * seg21 + (T(4) / T(3)) * seg19 * seg20 * t21 * seg21 + seg17 * seg16 * seg21 * t20 - (T(1) / T(15)) * (T(2) * t26 * b * seg21 + t23 * c * seg21 - T(5) * (T(3) * (J1 + T(2) * t24 * b * seg21 - t12 * c * t13) * seg21 + t22 * c * seg21 - T(2) * b * t25 * seg21) * seg21) * seg18 * seg21 - (T(2) / T(5)) * t26 * seg14 * seg21 * tau_lo;
  }
  f = F * seg24 * sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i7_prepare); operations per point.
/// Operations: 95 +, 254 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48917 +, 74635 ×, 5600 /, 2502 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i7_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T g_factor = pre[41];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
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
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab2 * ab_ap * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    foot0 = -(ab1 * exact_cross[2] - ab2 * exact_cross[1]) * seg0;
    foot1 = -(ab2 * exact_cross[0] - ab0 * exact_cross[2]) * seg0;
    foot2 = seg0 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T b = ab_ap + seg1;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg10;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg10));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(6) * M_panels[9] * delta_tau * seg13 + seg15 * M_panels[8] + M_panels[14] * seg18 + T(15) * seg11 * M_panels[12] * seg12 + T(20) * M_panels[11] * seg20 * seg19 + T(6) * tau_lo * M_panels[13] * seg14 + T(15) * seg16 * M_panels[10] * seg17;
    G_ap = t4;
    G_E = M_panels[15] * seg18 + T(20) * seg20 * M_panels[12] * seg19 + T(6) * delta_tau * seg13 * M_panels[10] + T(15) * seg11 * M_panels[13] * seg12 + T(15) * M_panels[11] * seg16 * seg17 + T(6) * tau_lo * seg14 * M_panels[14] + M_panels[9] * seg15 - b * seg21 * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    G_ap = seg18 * M_panels[14] + T(15) * seg16 * M_panels[10] * seg17 + T(6) * tau_lo * seg14 * M_panels[13] + M_panels[8] * seg15 + T(15) * seg11 * M_panels[12] * seg12 + T(20) * M_panels[11] * seg20 * seg19 + T(6) * M_panels[9] * delta_tau * seg13;
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
    G_E = (T(1) / T(7)) * seg21 * (T(60) * seg11 * M_panels[3] * seg12 + T(30) * seg16 * M_panels[1] * seg17 + T(6) * delta_tau * M_panels[0] * seg13 + T(30) * tau_lo * seg14 * M_panels[4] + T(6) * M_panels[5] * seg18 + T(60) * seg20 * M_panels[2] * seg19 + t9 * seg15 - t14 * seg22);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / D;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = b * t16 + t19 * a_minus_b;
    const T t23 = T(2) * t15 * t22 * a + t19 * a_minus_b * t20 + b * t16 * t17;
    const T t24 = T(3) * b * t16 * t18 + T(3) * t19 * a_minus_b * t21 + T(4) * t15 * a * t23;
    const T t25 = t18 * t17;
    const T t26 = t21 * t20;
    const T t27 = T(5) * b * t16 * t25 + T(2) * t15 * a * t24 + T(5) * t19 * a_minus_b * t26;
    const T t28 = T(5) * t19 * t26 - T(5) * t16 * t25 - b * t27 * t15;
    const T t29 = T(7) * t15 * t24 - T(3) * t27 * c * t15 - T(6) * b * t28 * seg21;
    const T t30 = b * t15 * t24 + T(3) * t16 * t18 - T(3) * t19 * t21;
    const T t31 = T(3) * t28 * seg21 * c + T(7) * t30 * seg21 + T(2) * b * seg21 * t29;
    const T t32 = T(5) * t15 * t23 + T(2) * b * t30 * seg21 - c * t15 * t24;
    const T t33 = T(2) * b * seg21 * t31 + T(7) * t32 * seg21 - seg21 * c * t29;
    const T t34 = b * t15 * t23 + t16 * t17 - t19 * t20;
    const T t35 = T(5) * seg21 * t34 + T(2) * b * t32 * seg21 - t30 * seg21 * c;
    const T t36 = T(2) * b * t33 * seg21 + T(7) * seg21 * t35 - seg21 * c * t31;
    const T t37 = T(2) * b * seg21 * t34 + T(3) * t15 * t22 - c * t15 * t23;
    const T t38 = t32 * seg21 * c - T(2) * b * seg21 * t35 - T(5) * seg21 * t37;
    G_ap = (T(1) / T(7)) * seg21 * seg16 * seg17 * t29 + (T(1) / T(35)) * t27 * t15 * seg15 + (T(2) / T(35)) * seg21 * t36 * tau_lo * seg14 + (T(1) / T(7)) * t33 * seg21 * seg11 * seg12 + (T(4) / T(21)) * seg20 * seg21 * seg19 * t31 - (T(1) / T(105)) * seg21 * (T(7) * seg21 * t38 + t33 * seg21 * c - T(2) * b * seg21 * t36) * seg18 - (T(6) / T(35)) * t28 * seg21 * delta_tau * seg13;
    const T t39 = t16 * t16;
    const T t40 = t39 * t16;
    const T t41 = t40 * t40;
    const T t42 = t41 * t16;
    const T t43 = t19 * t19;
    const T t44 = t43 * t19;
    const T t45 = t44 * t44;
    const T t46 = t45 * t19;
    G_E = (T(1) / T(35)) * seg21 * (T(10) * t30 * seg21 * seg16 * seg17 + T(20) * seg21 * seg11 * t35 * seg12 + T(2) * delta_tau * t15 * seg13 * t24 + T(5) * t42 * seg15 + T(20) * seg20 * t32 * seg21 * seg19 - T(10) * seg21 * t38 * tau_lo * seg14 - T(2) * seg21 * (T(2) * b * seg21 * t38 + seg21 * c * t35 + T(5) * seg21 * (seg21 * c * t34 - T(2) * b * seg21 * t37 - T(3) * seg21 * (t16 + b * t15 * t22 - t19))) * seg18 - T(5) * t46 * seg22);
  }
  const T foot_offset = seg21 * (ab_ap * delta_tau + seg23) * delta_tau * seg0 * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  grad[0] = -(ab0 * G_E - G_ap * foot_h0) * g_factor;
  grad[1] = (foot_h1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (foot_h2 * G_ap - ab2 * G_E);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i7_prepare); operations per point.
/// Operations: 108 +, 306 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48924 +, 74661 ×, 5601 /, 2502 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i7_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T tau_lo = pre[27];
  const T seg14 = pre[28];
  const T seg15 = pre[29];
  const T seg16 = pre[30];
  const T seg17 = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T sigma = pre[39];
  const T length = pre[40];
  const T g_factor = pre[41];
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
    foot0 = (exact_cross[1] * ab2 - exact_cross[2] * ab1) * seg0;
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * seg0;
    foot2 = -seg0 * (exact_cross[1] * ab0 - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = a_minus_b * b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / D;
    X = seg8 * (t2 + b * r1) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = seg8 * (a_minus_b - b) / (t4 - b * r1);
  }
  const T J1 = seg9 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D + seg10;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg10));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    F = T(20) * M_panels[3] * seg20 * seg19 + seg18 * M_panels[6] + T(6) * M_panels[1] * seg13 * delta_tau + M_panels[0] * seg15 + T(6) * seg14 * M_panels[5] * tau_lo + T(15) * seg17 * seg16 * M_panels[2] + T(15) * seg11 * M_panels[4] * seg12;
    const T t8 = M_panels[14] * seg18 + T(20) * seg20 * M_panels[11] * seg19 + T(15) * seg11 * seg12 * M_panels[12] + T(15) * seg17 * M_panels[10] * seg16 + T(6) * seg13 * delta_tau * M_panels[9] + T(6) * seg14 * M_panels[13] * tau_lo + seg15 * M_panels[8];
    G_ap = t8;
    G_E = T(20) * seg20 * seg19 * M_panels[12] + seg18 * M_panels[15] + seg15 * M_panels[9] + T(6) * seg14 * M_panels[14] * tau_lo + T(6) * M_panels[10] * seg13 * delta_tau + T(15) * seg17 * M_panels[11] * seg16 + T(15) * M_panels[13] * seg11 * seg12 - t8 * b * seg21;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    F = T(6) * seg14 * M_panels[5] * tau_lo + M_panels[0] * seg15 + T(15) * seg11 * M_panels[4] * seg12 + T(20) * seg20 * M_panels[3] * seg19 + T(15) * seg17 * seg16 * M_panels[2] + T(6) * M_panels[1] * seg13 * delta_tau + M_panels[6] * seg18;
    G_ap = T(6) * seg14 * M_panels[13] * tau_lo + T(15) * seg11 * seg12 * M_panels[12] + T(6) * seg13 * delta_tau * M_panels[9] + T(20) * seg20 * M_panels[11] * seg19 + T(15) * seg17 * M_panels[10] * seg16 + seg15 * M_panels[8] + seg18 * M_panels[14];
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
    G_E = (T(1) / T(7)) * (T(6) * M_panels[0] * seg13 * delta_tau + T(60) * seg20 * seg19 * M_panels[2] + T(30) * seg14 * M_panels[4] * tau_lo + T(60) * M_panels[3] * seg11 * seg12 + T(30) * seg17 * M_panels[1] * seg16 + T(6) * seg18 * M_panels[5] + seg15 * t13 - seg22 * t18) * seg21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = T(1) / r0;
    const T t24 = a_minus_b * t19 + b * t23;
    const T t25 = t23 * t23;
    const T t26 = a_minus_b * t20 * t19 + T(2) * t22 * t24 * a + b * t25 * t23;
    const T t27 = t25 * t25;
    const T t28 = T(4) * t26 * t22 * a + T(3) * b * t27 * t23 + T(3) * a_minus_b * t21 * t19;
    const T t29 = T(3) * t21 * t19 - b * t22 * t28 - T(3) * t27 * t23;
    const T t30 = T(2) * b * seg21 * t29 + c * t22 * t28 - T(5) * t26 * t22;
    const T t31 = t26 * b * t22 + t25 * t23 - t20 * t19;
    const T t32 = T(5) * seg21 * t31 + seg21 * t29 * c - T(2) * t30 * b * seg21;
    const T t33 = t26 * c * t22 - T(3) * t22 * t24 - T(2) * b * seg21 * t31;
    const T t34 = t30 * seg21 * c + T(2) * t32 * b * seg21 - T(5) * seg21 * t33;
    const T t35 = t19 - b * t22 * t24 - t23;
    const T t36 = seg21 * c * t31 + T(3) * seg21 * t35 + T(2) * b * seg21 * t33;
    const T t37 = T(2) * t34 * b * seg21 - t32 * seg21 * c - T(5) * seg21 * t36;
    F = seg11 * t34 * seg21 * seg12 + (T(2) / T(5)) * t37 * seg14 * seg21 * tau_lo + (T(1) / T(15)) * seg21 * seg18 * (T(2) * t37 * b * seg21 + T(5) * seg21 * (seg21 * c * t33 - T(3) * seg21 * (T(2) * b * seg21 * t35 + c * t22 * t24 - J1) - T(2) * b * seg21 * t36) - t34 * seg21 * c) + (T(1) / T(15)) * seg15 * t22 * t28 + (T(4) / T(3)) * t32 * seg20 * seg21 * seg19 - t30 * seg17 * seg21 * seg16 - (T(2) / T(5)) * seg21 * t29 * seg13 * delta_tau;
    const T t38 = t21 * t20;
    const T t39 = t27 * t25;
    const T t40 = T(2) * t22 * t28 * a + T(5) * a_minus_b * t38 * t19 + T(5) * b * t39 * t23;
    const T t41 = T(5) * t38 * t19 - b * t40 * t22 - T(5) * t39 * t23;
    const T t42 = T(7) * t22 * t28 - T(3) * c * t40 * t22 - T(6) * t41 * b * seg21;
    const T t43 = T(7) * seg21 * t29 - T(2) * t42 * b * seg21 - T(3) * t41 * seg21 * c;
    const T t44 = T(7) * t30 * seg21 + T(2) * t43 * b * seg21 + t42 * seg21 * c;
    const T t45 = T(2) * b * seg21 * t44 - t43 * seg21 * c - T(7) * t32 * seg21;
    G_ap = (T(1) / T(35)) * seg15 * t40 * t22 + (T(1) / T(7)) * t42 * seg17 * seg21 * seg16 - (T(1) / T(7)) * seg11 * seg21 * seg12 * t44 - (T(4) / T(21)) * seg20 * t43 * seg21 * seg19 - (T(1) / T(105)) * seg21 * seg18 * (T(2) * b * seg21 * t45 - seg21 * c * t44 - T(7) * t34 * seg21) - (T(2) / T(35)) * seg14 * seg21 * t45 * tau_lo - (T(6) / T(35)) * t41 * seg21 * seg13 * delta_tau;
    const T t46 = t23 * t23;
    const T t47 = t46 * t23;
    const T t48 = t47 * t47;
    const T t49 = t48 * t23;
    const T t50 = t19 * t19;
    const T t51 = t50 * t19;
    const T t52 = t51 * t51;
    const T t53 = t52 * t19;
    G_E = (T(1) / T(35)) * seg21 * (T(20) * t32 * seg11 * seg21 * seg12 + T(10) * seg14 * t34 * seg21 * tau_lo + T(2) * seg13 * t22 * t28 * delta_tau + T(2) * t37 * seg21 * seg18 + T(5) * seg15 * t49 - T(10) * seg17 * seg21 * t29 * seg16 - T(5) * seg22 * t53 - T(20) * t30 * seg20 * seg21 * seg19);
  }
  const T foot_offset = sigma2 * (seg23 + ab_ap * delta_tau) * seg21 * seg0 * delta_tau;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  f = F * seg24 * sigma * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot_h0);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = (foot_h2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i8_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i8_prepared_size = 42;

/// What scalis_segment_cauchy_i8_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 42): computed once per
/// segment; in.p is not read.
/// Operations: 14 +, 47 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i8_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T t1 = sigma2 * sigma2;
  const T t2 = t1 * t1;
  const T g_factor = -T(8) * length * t2;
  pre[0] = end_a[0];
  pre[1] = end_b[0];
  pre[2] = end_a[1];
  pre[3] = end_b[1];
  pre[4] = end_a[2];
  pre[5] = end_b[2];
  pre[6] = ab0;
  pre[7] = ab1;
  pre[8] = ab2;
  pre[9] = ab_ab;
  const T t3 = T(1) / ab_ab;
  pre[10] = t3;
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  pre[12] = t4 * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  pre[20] = tau_lo * sigma2 * tau_hi;
  pre[21] = -a * a;
  pre[22] = a;
  pre[23] = t0;
  const T t5 = t4 * t4;
  const T t6 = t5 * tau_lo;
  pre[24] = t6;
  const T t7 = t0 * t0;
  pre[25] = t7;
  const T t8 = t4 * tau_lo;
  pre[26] = t8;
  const T t9 = t7 * delta_tau;
  pre[27] = t9;
  pre[28] = t4;
  const T t10 = t0 * delta_tau;
  const T t11 = t10 * t10;
  const T t12 = t11 * delta_tau;
  pre[29] = t12;
  const T t13 = t8 * t8;
  const T t14 = t13 * tau_lo;
  pre[30] = t14;
  pre[31] = t11;
  pre[32] = tau_lo;
  pre[33] = t13;
  pre[34] = t10;
  pre[35] = t5;
  const T t15 = T(1) / a;
  pre[36] = t15;
  pre[37] = T(7) * delta_tau * t13 + t14 + t12 + T(7) * t11 * tau_lo + T(35) * t10 * t5 + T(35) * t7 * t8 + T(21) * t9 * t4 + T(21) * t0 * t6;
  pre[38] = tau_lo * ab_ab;
  pre[39] = length;
  pre[40] = t2;
  pre[41] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i8_prepare); operations per point.
/// Operations: 82 +, 190 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 33614 +, 46458 ×, 6303 /, 135 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i8_f(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab1 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T tau_lo = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T length = pre[39];
  const T seg25 = pre[40];
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = seg8 + ap_bp;
  T F;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    F = seg16 * M_panels[7] + T(7) * M_panels[6] * tau_lo * seg18 + T(7) * seg19 * delta_tau * M_panels[1] + T(35) * M_panels[3] * seg20 * seg21 + T(21) * seg10 * seg11 * M_panels[2] + T(35) * M_panels[4] * seg12 * seg13 + M_panels[0] * seg17 + T(21) * seg14 * M_panels[5] * seg15;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[7] * seg16 + T(7) * tau_lo * M_panels[6] * seg18 + T(21) * M_panels[5] * seg14 * seg15 + T(35) * seg20 * seg21 * M_panels[3] + T(7) * M_panels[1] * seg19 * delta_tau + T(35) * M_panels[4] * seg12 * seg13 + T(21) * M_panels[2] * seg10 * seg11 + seg17 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(1) / c;
    const T log_ratio = log(t6 * q1);
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = a * J2 + a_minus_b * t9 + t6 * b;
    const T t12 = T(2) * t7 * b + T(2) * a_minus_b * t10 + T(3) * t11 * t8 * a;
    const T t13 = T(2) * t7 + t8 * t12 * b - T(2) * t10;
    const T t14 = T(2) * t13 * seg22 * b + T(4) * t11 * t8 - c * t8 * t12;
    const T t15 = t7 * t6;
    const T t16 = t10 * t9;
    const T t17 = T(8) * t15 * b + T(8) * a_minus_b * t16 + T(5) * t8 * a * t12;
    const T t18 = T(8) * t15 + t17 * t8 * b - T(8) * t16;
    const T t19 = T(2) * seg22 * b * t18 + T(6) * t8 * t12 - t17 * c * t8;
    const T t20 = seg22 * c * t18 - T(2) * t19 * seg22 * b - T(6) * t13 * seg22;
    const T t21 = T(6) * t14 * seg22 - T(2) * seg22 * b * t20 - t19 * seg22 * c;
    const T t22 = t9 - t11 * t8 * b - t6;
    const T t23 = t13 * seg22 * c + T(4) * t22 * seg22 - T(2) * t14 * seg22 * b;
    const T t24 = T(2) * seg22 * t21 * b + seg22 * c * t20 - T(6) * seg22 * t23;
    const T t25 = c * t11 * t8 + T(2) * t22 * seg22 * b - T(2) * J2;
    const T t26 = T(4) * seg22 * t25 + t14 * seg22 * c + T(2) * seg22 * t23 * b;
    const T t27 = seg22 * c * t21 + T(6) * seg22 * t26 - T(2) * seg22 * t24 * b;
    F = (T(35) / T(48)) * seg22 * t21 * seg12 * seg13 + (T(7) / T(16)) * seg22 * t24 * seg14 * seg15 + (T(7) / T(48)) * seg22 * seg19 * delta_tau * t18 + (T(1) / T(48)) * seg22 * seg16 * (T(6) * seg22 * (seg22 * c * t23 + T(4) * seg22 * (seg22 * (log_ratio + T(2) * J2 * b) + t22 * seg22 * c - T(2) * seg22 * t25 * b) - T(2) * seg22 * t26 * b) - T(2) * seg22 * t27 * b - seg22 * c * t24) + (T(7) / T(16)) * t19 * seg22 * seg10 * seg11 + (T(1) / T(48)) * t17 * seg17 * t8 - (T(35) / T(48)) * seg22 * seg20 * seg21 * t20 - (T(7) / T(48)) * seg22 * tau_lo * t27 * seg18;
  }
  f = length * seg25 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i8_prepare); operations per point.
/// Operations: 109 +, 276 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 48732 +, 63434 ×, 5083 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i8_grad(const T* pre, const std::array<T, 3>& p) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab1 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T tau_lo = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T g_factor = pre[41];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    foot0 = ap0 - ab0 * ab_ap * seg0;
    foot1 = ap1 - ab1 * ab_ap * seg0;
    foot2 = ap2 - ab2 * ab_ap * seg0;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = -(exact_cross[2] * ab1 - ab2 * exact_cross[1]) * seg0;
    foot1 = seg0 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -(ab0 * exact_cross[1] - ab1 * exact_cross[0]) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = ap_bp + seg8;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(7) * seg19 * delta_tau * M_panels[10] + seg16 * M_panels[16] + T(35) * seg21 * M_panels[12] * seg20 + T(21) * seg10 * M_panels[11] * seg11 + T(35) * seg12 * M_panels[13] * seg13 + T(21) * M_panels[14] * seg15 * seg14 + T(7) * seg18 * M_panels[15] * tau_lo + M_panels[9] * seg17;
    G_ap = t4;
    G_E = T(7) * seg19 * M_panels[11] * delta_tau + T(21) * seg15 * M_panels[15] * seg14 + M_panels[17] * seg16 + T(7) * seg18 * tau_lo * M_panels[16] + T(35) * seg21 * M_panels[13] * seg20 + T(21) * seg10 * seg11 * M_panels[12] + T(35) * M_panels[14] * seg12 * seg13 + seg17 * M_panels[10] - t4 * seg22 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    G_ap = T(7) * M_panels[15] * seg18 * tau_lo + T(35) * M_panels[13] * seg12 * seg13 + T(35) * M_panels[12] * seg21 * seg20 + T(21) * seg10 * seg11 * M_panels[11] + M_panels[16] * seg16 + M_panels[9] * seg17 + T(21) * seg15 * M_panels[14] * seg14 + T(7) * seg19 * delta_tau * M_panels[10];
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    G_E = (T(1) / T(8)) * (T(105) * seg15 * M_panels[4] * seg14 + T(7) * M_panels[6] * seg16 + t7 * seg17 + T(105) * M_panels[2] * seg21 * seg20 + T(7) * seg19 * M_panels[0] * delta_tau + T(42) * M_panels[5] * seg18 * tau_lo + T(140) * M_panels[3] * seg12 * seg13 + T(42) * seg10 * seg11 * M_panels[1] - t10 * seg23) * seg22;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / D;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = T(1) / c;
    const T t17 = t16 * t16;
    const T t18 = J2 * a + a_minus_b * t14 + t16 * b;
    const T t19 = T(2) * a_minus_b * t15 + T(2) * t17 * b + T(3) * t18 * t13 * a;
    const T t20 = t15 * t14;
    const T t21 = t17 * t16;
    const T t22 = T(5) * t19 * t13 * a + T(8) * a_minus_b * t20 + T(8) * t21 * b;
    const T t23 = t13 * t22 * b + T(8) * t21 - T(8) * t20;
    const T t24 = t17 * t17;
    const T t25 = t15 * t15;
    const T t26 = T(48) * t24 * b + T(7) * t13 * a * t22 + T(48) * a_minus_b * t25;
    const T t27 = t26 * t13 * b + T(48) * t24 - T(48) * t25;
    const T t28 = T(8) * t13 * t22 + T(2) * t27 * seg22 * b - t26 * c * t13;
    const T t29 = T(8) * t23 * seg22 + T(2) * t28 * seg22 * b - c * t27 * seg22;
    const T t30 = T(2) * t17 + t19 * t13 * b - T(2) * t15;
    const T t31 = T(6) * t19 * t13 + T(2) * t23 * seg22 * b - c * t13 * t22;
    const T t32 = t23 * c * seg22 - T(6) * t30 * seg22 - T(2) * seg22 * b * t31;
    const T t33 = t19 * c * t13 - T(4) * t18 * t13 - T(2) * t30 * seg22 * b;
    const T t34 = t14 - t16 - t18 * t13 * b;
    const T t35 = T(2) * t33 * seg22 * b + t30 * c * seg22 + T(4) * t34 * seg22;
    const T t36 = T(6) * t33 * seg22 + c * seg22 * t31 + T(2) * seg22 * b * t32;
    const T t37 = c * seg22 * t32 - T(6) * t35 * seg22 - T(2) * seg22 * t36 * b;
    const T t38 = T(8) * seg22 * t31 + T(2) * t29 * seg22 * b - c * t28 * seg22;
    const T t39 = T(8) * seg22 * t32 + c * t29 * seg22 - T(2) * seg22 * b * t38;
    const T t40 = T(8) * seg22 * t36 + c * seg22 * t38 + T(2) * t39 * seg22 * b;
    G_ap = (T(35) / T(384)) * seg21 * t29 * seg22 * seg20 + (T(7) / T(384)) * seg19 * t27 * delta_tau * seg22 + (T(1) / T(384)) * (T(8) * seg22 * t37 + t39 * c * seg22 - T(2) * seg22 * t40 * b) * seg16 * seg22 + (T(1) / T(384)) * t26 * t13 * seg17 + (T(7) / T(128)) * seg10 * seg11 * t28 * seg22 + (T(35) / T(384)) * seg12 * seg22 * seg13 * t38 - (T(7) / T(128)) * t39 * seg15 * seg22 * seg14 - (T(7) / T(384)) * seg18 * tau_lo * seg22 * t40;
    G_E = (T(1) / T(384)) * (T(105) * seg21 * seg22 * seg20 * t31 + T(7) * (T(6) * seg22 * (c * t33 * seg22 + T(4) * (T(2) * J2 - T(2) * t34 * seg22 * b - c * t18 * t13) * seg22 - T(2) * t35 * seg22 * b) + c * seg22 * t36 + T(2) * seg22 * b * t37) * seg16 * seg22 + T(48) * t24 * seg17 + T(42) * seg18 * tau_lo * seg22 * t37 + T(42) * t23 * seg10 * seg11 * seg22 + T(7) * seg19 * delta_tau * t13 * t22 - T(48) * t25 * seg23 - T(140) * seg12 * seg22 * seg13 * t32 - T(105) * seg15 * seg22 * t36 * seg14) * seg22;
  }
  const T foot_offset = (seg24 + ab_ap * delta_tau) * delta_tau * seg22 * seg0 * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = ab2 * foot_offset + foot2;
  grad[0] = (foot_h0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot_h1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot_h2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i8_prepare); operations per point.
/// Operations: 123 +, 331 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 48739 +, 63456 ×, 5083 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i8_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T A0 = pre[0];
  const T B0 = pre[1];
  const T A1 = pre[2];
  const T B1 = pre[3];
  const T A2 = pre[4];
  const T B2 = pre[5];
  const T ab0 = pre[6];
  const T ab1 = pre[7];
  const T ab2 = pre[8];
  const T ab_ab = pre[9];
  const T seg0 = pre[10];
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T tau_lo = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T length = pre[39];
  const T seg25 = pre[40];
  const T g_factor = pre[41];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = seg0 * (ab0 * exact_cross[2] - exact_cross[0] * ab2);
    foot2 = -seg0 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = seg4 + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + seg5;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T c_minus_b = seg8 + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    F = T(35) * seg20 * seg21 * M_panels[3] + T(7) * seg19 * M_panels[1] * delta_tau + T(21) * M_panels[5] * seg14 * seg15 + T(7) * tau_lo * M_panels[6] * seg18 + T(35) * seg12 * M_panels[4] * seg13 + seg17 * M_panels[0] + M_panels[7] * seg16 + T(21) * seg10 * M_panels[2] * seg11;
    const T t4 = seg16 * M_panels[16] + seg17 * M_panels[9] + T(21) * M_panels[11] * seg10 * seg11 + T(7) * tau_lo * M_panels[15] * seg18 + T(21) * M_panels[14] * seg14 * seg15 + T(7) * M_panels[10] * seg19 * delta_tau + T(35) * seg20 * M_panels[12] * seg21 + T(35) * M_panels[13] * seg12 * seg13;
    G_ap = t4;
    G_E = T(7) * tau_lo * seg18 * M_panels[16] + T(35) * M_panels[13] * seg20 * seg21 + T(21) * M_panels[15] * seg14 * seg15 + M_panels[10] * seg17 + T(35) * seg12 * M_panels[14] * seg13 + M_panels[17] * seg16 + T(21) * seg10 * M_panels[12] * seg11 + T(7) * seg19 * delta_tau * M_panels[11] - seg22 * t4 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    F = T(7) * tau_lo * M_panels[6] * seg18 + M_panels[0] * seg17 + seg16 * M_panels[7] + T(35) * seg20 * M_panels[3] * seg21 + T(21) * M_panels[5] * seg14 * seg15 + T(7) * seg19 * delta_tau * M_panels[1] + T(35) * seg12 * seg13 * M_panels[4] + T(21) * M_panels[2] * seg10 * seg11;
    G_ap = T(21) * M_panels[11] * seg10 * seg11 + T(35) * seg12 * seg13 * M_panels[13] + T(21) * seg14 * seg15 * M_panels[14] + T(7) * seg19 * delta_tau * M_panels[10] + T(35) * M_panels[12] * seg20 * seg21 + M_panels[9] * seg17 + seg16 * M_panels[16] + T(7) * M_panels[15] * tau_lo * seg18;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    G_E = (T(1) / T(8)) * seg22 * (T(7) * seg19 * delta_tau * M_panels[0] + T(42) * seg10 * seg11 * M_panels[1] + T(42) * M_panels[5] * tau_lo * seg18 + T(105) * seg14 * M_panels[4] * seg15 + T(140) * seg12 * seg13 * M_panels[3] + T(105) * M_panels[2] * seg20 * seg21 + t7 * seg17 + T(7) * seg16 * M_panels[6] - t10 * seg23);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / c;
    const T log_ratio = log(q1 * t13);
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / q1;
    const T t17 = t16 * t16;
    const T t18 = T(1) / D;
    const T t19 = J2 * a + t13 * b + t16 * a_minus_b;
    const T t20 = T(2) * t17 * a_minus_b + T(2) * t14 * b + T(3) * t18 * t19 * a;
    const T t21 = t17 * t16;
    const T t22 = T(8) * t15 * b + T(5) * t20 * t18 * a + T(8) * t21 * a_minus_b;
    const T t23 = T(8) * t15 + t22 * t18 * b - T(8) * t21;
    const T t24 = c * t22 * t18 - T(6) * t20 * t18 - T(2) * seg22 * t23 * b;
    const T t25 = T(2) * t14 + t20 * t18 * b - T(2) * t17;
    const T t26 = T(2) * seg22 * t24 * b + seg22 * c * t23 - T(6) * seg22 * t25;
    const T t27 = c * t20 * t18 - T(4) * t18 * t19 - T(2) * seg22 * b * t25;
    const T t28 = T(2) * seg22 * t26 * b + T(6) * seg22 * t27 - seg22 * t24 * c;
    const T t29 = t18 * t19 * b + t13 - t16;
    const T t30 = T(2) * seg22 * t27 * b + seg22 * c * t25 - T(4) * seg22 * t29;
    const T t31 = T(2) * seg22 * t28 * b + T(6) * seg22 * t30 - seg22 * c * t26;
    const T t32 = c * t18 * t19 - T(2) * J2 - T(2) * seg22 * t29 * b;
    const T t33 = T(4) * seg22 * t32 + T(2) * seg22 * t30 * b - seg22 * c * t27;
    const T t34 = T(2) * seg22 * t31 * b + T(6) * seg22 * t33 - seg22 * c * t28;
    F = (T(7) / T(48)) * seg22 * seg19 * delta_tau * t23 + (T(1) / T(48)) * t22 * t18 * seg17 - (T(7) / T(16)) * seg22 * t24 * seg10 * seg11 - (T(7) / T(16)) * seg22 * t31 * seg14 * seg15 - (T(1) / T(48)) * seg22 * seg16 * (T(6) * seg22 * (T(2) * seg22 * t33 * b + T(4) * seg22 * (T(2) * seg22 * t32 * b + seg22 * c * t29 - seg22 * (log_ratio + T(2) * J2 * b)) - seg22 * c * t30) + T(2) * seg22 * t34 * b - seg22 * c * t31) - (T(35) / T(48)) * seg22 * t26 * seg20 * seg21 - (T(7) / T(48)) * seg22 * t34 * tau_lo * seg18 - (T(35) / T(48)) * seg12 * seg22 * seg13 * t28;
    const T t35 = t17 * t17;
    const T t36 = t14 * t14;
    const T t37 = T(48) * t35 * a_minus_b + T(7) * t22 * t18 * a + T(48) * t36 * b;
    const T t38 = T(48) * t35 - t18 * t37 * b - T(48) * t36;
    const T t39 = T(2) * seg22 * t38 * b + c * t18 * t37 - T(8) * t22 * t18;
    const T t40 = T(2) * seg22 * t39 * b - seg22 * c * t38 - T(8) * seg22 * t23;
    const T t41 = seg22 * c * t39 - T(8) * seg22 * t24 - T(2) * seg22 * t40 * b;
    const T t42 = seg22 * c * t40 + T(2) * seg22 * t41 * b - T(8) * seg22 * t26;
    const T t43 = seg22 * c * t41 + T(8) * seg22 * t28 - T(2) * seg22 * t42 * b;
    G_ap = (T(35) / T(384)) * seg12 * seg22 * seg13 * t41 + (T(1) / T(384)) * t18 * seg17 * t37 + (T(7) / T(128)) * seg22 * t42 * seg14 * seg15 - (T(1) / T(384)) * seg22 * seg16 * (T(2) * seg22 * b * t43 + T(8) * seg22 * t31 + seg22 * c * t42) - (T(7) / T(384)) * seg22 * tau_lo * seg18 * t43 - (T(35) / T(384)) * seg22 * t40 * seg20 * seg21 - (T(7) / T(128)) * seg22 * seg10 * t39 * seg11 - (T(7) / T(384)) * seg22 * seg19 * delta_tau * t38;
    G_E = -(T(1) / T(384)) * seg22 * (T(105) * seg22 * t28 * seg14 * seg15 + T(48) * t35 * seg23 + T(7) * seg22 * t34 * seg16 + T(140) * seg12 * seg22 * t26 * seg13 + T(105) * seg22 * t24 * seg20 * seg21 + T(42) * seg22 * tau_lo * t31 * seg18 - T(7) * seg19 * delta_tau * t22 * t18 - T(48) * t36 * seg17 - T(42) * seg22 * seg10 * t23 * seg11);
  }
  const T foot_offset = seg22 * seg0 * delta_tau * (ab_ap * delta_tau + seg24) * sigma2;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  f = seg25 * length * F;
  grad[0] = g_factor * (G_ap * foot_h0 - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot_h1);
  grad[2] = -(G_E * ab2 - G_ap * foot_h2) * g_factor;
  return f;
}

/// How many values scalis_segment_cauchy_i9_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i9_prepared_size = 46;

/// What scalis_segment_cauchy_i9_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 46): computed once per
/// segment; in.p is not read.
/// Operations: 15 +, 50 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i9_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T t1 = sigma2 * sigma2;
  const T t2 = t1 * t1;
  const T g_factor = -T(9) * length * t2 * in.sigma;
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
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  pre[12] = t4 * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  const T t5 = sqrt(a);
  pre[20] = t5;
  const T t6 = T(1) / t5;
  pre[21] = t6;
  pre[22] = -a * a;
  pre[23] = a;
  pre[24] = t0;
  const T t7 = t4 * tau_lo;
  const T t8 = t7 * t7;
  pre[25] = t8;
  const T t9 = t0 * t0;
  const T t10 = t9 * delta_tau;
  pre[26] = t10;
  pre[27] = t7;
  pre[28] = t9;
  const T t11 = t4 * t4;
  pre[29] = t11;
  const T t12 = t0 * delta_tau;
  const T t13 = t12 * t12;
  const T t14 = t13 * delta_tau;
  pre[30] = t14;
  pre[31] = tau_lo;
  pre[32] = t13;
  pre[33] = t4;
  const T t15 = t9 * t9;
  pre[34] = t15;
  const T t16 = t11 * t11;
  pre[35] = t16;
  pre[36] = t12;
  const T t17 = t11 * tau_lo;
  pre[37] = t17;
  const T t18 = t8 * tau_lo;
  pre[38] = t18;
  const T t19 = T(1) / a;
  pre[39] = t19;
  pre[40] = T(8) * delta_tau * t18 + T(70) * t9 * t11 + T(56) * t10 * t7 + T(8) * t14 * tau_lo + T(56) * t12 * t17 + T(28) * t13 * t4 + T(28) * t0 * t8 + t16 + t15;
  pre[41] = tau_lo * ab_ab;
  pre[42] = length;
  pre[43] = t2;
  pre[44] = in.sigma;
  pre[45] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i9_prepare); operations per point.
/// Operations: 91 +, 244 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 32243 +, 55555 ×, 5599 /, 2502 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i9_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T tau_lo = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T length = pre[42];
  const T seg28 = pre[43];
  const T sigma = pre[44];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
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
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[0] * exact_cross[0] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T b = ab_ap + seg1;
  const T c = seg2 + ap_ap;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = b * a_minus_b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = a_minus_b * r0;
    const T t3 = T(1) / D;
    X = (t2 + b * r1) * seg8 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = a_minus_b * r0;
    X = -seg8 * (b - a_minus_b) / (t4 - b * r1);
  }
  const T J1 = asinh(X) * seg9;
  T F;
  const T t5 = T(4) * D + seg10;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D + seg10));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    F = T(56) * M_panels[3] * seg22 * seg23 + T(56) * seg14 * M_panels[5] * seg13 + seg20 * M_panels[8] + T(8) * seg24 * delta_tau * M_panels[1] + T(28) * seg12 * seg11 * M_panels[2] + T(28) * M_panels[6] * seg18 * seg19 + T(70) * seg16 * M_panels[4] * seg15 + T(8) * M_panels[7] * tau_lo * seg17 + M_panels[0] * seg21;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    F = seg20 * M_panels[8] + T(56) * M_panels[3] * seg22 * seg23 + T(70) * seg16 * M_panels[4] * seg15 + T(28) * seg12 * M_panels[2] * seg11 + T(8) * seg24 * M_panels[1] * delta_tau + T(28) * seg18 * seg19 * M_panels[6] + seg21 * M_panels[0] + T(56) * seg14 * M_panels[5] * seg13 + T(8) * M_panels[7] * tau_lo * seg17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(1) / D;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = b * t8 + a_minus_b * t13;
    const T t16 = a_minus_b * t13 * t14 + T(2) * t15 * t12 * a + b * t9 * t8;
    const T t17 = t14 * t14;
    const T t18 = T(3) * b * t10 * t8 + T(4) * t12 * a * t16 + T(3) * a_minus_b * t13 * t17;
    const T t19 = t17 * t14;
    const T t20 = T(5) * b * t11 * t8 + T(2) * t12 * a * t18 + T(5) * a_minus_b * t13 * t19;
    const T t21 = b * t20 * t12 + T(5) * t11 * t8 - T(5) * t13 * t19;
    const T t22 = b * t12 * t18 + T(3) * t10 * t8 - T(3) * t13 * t17;
    const T t23 = T(2) * b * seg25 * t22 + T(5) * t12 * t16 - c * t12 * t18;
    const T t24 = b * t12 * t16 + t9 * t8 - t13 * t14;
    const T t25 = T(2) * b * seg25 * t23 + T(5) * seg25 * t24 - c * seg25 * t22;
    const T t26 = T(2) * b * seg25 * t24 + T(3) * t15 * t12 - c * t12 * t16;
    const T t27 = T(2) * t25 * b * seg25 + T(5) * t26 * seg25 - c * seg25 * t23;
    const T t28 = t13 - b * t15 * t12 - t8;
    const T t29 = T(2) * b * t26 * seg25 - T(3) * seg25 * t28 - c * seg25 * t24;
    const T t30 = T(2) * b * t27 * seg25 + T(5) * seg25 * t29 - t25 * c * seg25;
    const T t31 = T(3) * t20 * c * t12 - T(6) * b * t21 * seg25 - T(7) * t12 * t18;
    const T t32 = T(2) * b * seg25 * t31 + T(3) * c * t21 * seg25 - T(7) * seg25 * t22;
    const T t33 = T(2) * b * seg25 * t32 - T(7) * seg25 * t23 - c * seg25 * t31;
    const T t34 = T(2) * b * t33 * seg25 - c * seg25 * t32 - T(7) * t25 * seg25;
    const T t35 = t33 * c * seg25 + T(7) * t27 * seg25 - T(2) * b * seg25 * t34;
    const T t36 = T(7) * seg25 * t30 + T(2) * b * seg25 * t35 + c * seg25 * t34;
    F = (T(8) / T(35)) * seg24 * t21 * seg25 * delta_tau + (T(1) / T(35)) * t20 * seg21 * t12 + (T(1) / T(105)) * seg25 * seg20 * (T(2) * b * seg25 * t36 - T(7) * seg25 * (T(5) * seg25 * (t26 * c * seg25 + T(3) * (T(2) * b * seg25 * t28 + t15 * c * t12 - J1) * seg25 - T(2) * b * seg25 * t29) + t27 * c * seg25 - T(2) * b * seg25 * t30) - c * seg25 * t35) + (T(4) / T(15)) * seg18 * seg25 * seg19 * t35 + (T(8) / T(105)) * seg25 * tau_lo * t36 * seg17 - (T(2) / T(3)) * seg16 * t33 * seg25 * seg15 - (T(8) / T(15)) * seg22 * seg25 * seg23 * t32 - (T(8) / T(15)) * seg14 * seg25 * t34 * seg13 - (T(4) / T(15)) * seg12 * seg25 * t31 * seg11;
  }
  f = sigma * length * seg28 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i9_prepare); operations per point.
/// Operations: 119 +, 343 ×, 3 /, 2 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48151 +, 73261 ×, 4613 /, 2061 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i9_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T tau_lo = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T seg26 = pre[40];
  const T seg27 = pre[41];
  const T g_factor = pre[45];
  const T ap0 = p[0] - A0;
  const T bp0 = p[0] - B0;
  const T ap1 = p[1] - A1;
  const T bp1 = p[1] - B1;
  const T ap2 = p[2] - A2;
  const T bp2 = p[2] - B2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    foot0 = ap0 - seg0 * ab0 * ab_ap;
    foot1 = ap1 - seg0 * ab1 * ab_ap;
    foot2 = ap2 - seg0 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    foot0 = seg0 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = seg0 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -seg0 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t1 = seg10 + T(4) * D;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(seg10 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(56) * seg23 * M_panels[13] * seg22 + T(28) * seg19 * M_panels[16] * seg18 + T(28) * seg11 * M_panels[12] * seg12 + M_panels[10] * seg21 + T(70) * seg15 * seg16 * M_panels[14] + M_panels[18] * seg20 + T(8) * tau_lo * seg17 * M_panels[17] + T(56) * M_panels[15] * seg13 * seg14 + T(8) * seg24 * delta_tau * M_panels[11];
    G_ap = t4;
    G_E = T(56) * M_panels[16] * seg13 * seg14 + T(8) * M_panels[18] * tau_lo * seg17 + M_panels[19] * seg20 + T(70) * M_panels[15] * seg15 * seg16 + T(28) * seg19 * M_panels[17] * seg18 + T(28) * seg11 * seg12 * M_panels[13] + seg21 * M_panels[11] + T(56) * seg23 * M_panels[14] * seg22 + T(8) * seg24 * M_panels[12] * delta_tau - seg25 * t4 * b;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    G_ap = T(8) * seg24 * M_panels[11] * delta_tau + T(28) * seg11 * seg12 * M_panels[12] + M_panels[18] * seg20 + T(56) * seg23 * seg22 * M_panels[13] + seg21 * M_panels[10] + T(28) * seg19 * M_panels[16] * seg18 + T(56) * seg13 * M_panels[15] * seg14 + T(8) * M_panels[17] * tau_lo * seg17 + T(70) * M_panels[14] * seg15 * seg16;
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
    G_E = (T(1) / T(9)) * seg25 * (T(168) * seg23 * M_panels[2] * seg22 + T(8) * seg24 * delta_tau * M_panels[0] + T(168) * seg19 * M_panels[5] * seg18 + t9 * seg21 + T(8) * M_panels[7] * seg20 + T(280) * seg15 * seg16 * M_panels[3] + T(56) * seg11 * seg12 * M_panels[1] + T(56) * tau_lo * seg17 * M_panels[6] + T(280) * M_panels[4] * seg13 * seg14 - seg26 * t14);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / D;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t18 * t17;
    const T t25 = t22 * t21;
    const T t26 = t20 * b + t16 * a_minus_b;
    const T t27 = T(2) * t26 * t15 * a + t20 * t21 * b + t16 * a_minus_b * t17;
    const T t28 = T(3) * t16 * a_minus_b * t18 + T(3) * t20 * t22 * b + T(4) * t27 * t15 * a;
    const T t29 = T(5) * t16 * a_minus_b * t24 + T(5) * t20 * t25 * b + T(2) * t28 * t15 * a;
    const T t30 = T(35) * t16 * a_minus_b * t19 + T(35) * t20 * t23 * b + T(8) * t29 * t15 * a;
    const T t31 = t15 * t30 * b + T(35) * t20 * t23 - T(35) * t16 * t19;
    const T t32 = T(2) * seg25 * t31 * b + T(9) * t29 * t15 - c * t15 * t30;
    const T t33 = t29 * t15 * b + T(5) * t20 * t25 - T(5) * t16 * t24;
    const T t34 = T(2) * seg25 * t32 * b + T(9) * seg25 * t33 - seg25 * c * t31;
    const T t35 = T(3) * t29 * c * t15 - T(6) * seg25 * t33 * b - T(7) * t28 * t15;
    const T t36 = T(2) * seg25 * b * t34 - seg25 * c * t32 - T(3) * seg25 * t35;
    const T t37 = t28 * t15 * b + T(3) * t20 * t22 - T(3) * t16 * t18;
    const T t38 = T(2) * seg25 * t35 * b + T(3) * seg25 * c * t33 - T(7) * seg25 * t37;
    const T t39 = T(2) * seg25 * t36 * b - seg25 * c * t34 - T(3) * seg25 * t38;
    const T t40 = c * t28 * t15 - T(2) * seg25 * t37 * b - T(5) * t27 * t15;
    const T t41 = t27 * t15 * b + t20 * t21 - t16 * t17;
    const T t42 = seg25 * c * t37 + T(2) * seg25 * t40 * b - T(5) * seg25 * t41;
    const T t43 = T(2) * seg25 * t38 * b + T(7) * seg25 * t40 - seg25 * c * t35;
    const T t44 = T(7) * seg25 * t42 + T(2) * seg25 * b * t43 - seg25 * c * t38;
    const T t45 = seg25 * c * t36 + T(3) * seg25 * t43 - T(2) * seg25 * t39 * b;
    const T t46 = seg25 * c * t39 + T(3) * seg25 * t44 + T(2) * seg25 * t45 * b;
    const T t47 = T(2) * seg25 * t41 * b + T(3) * t26 * t15 - c * t27 * t15;
    const T t48 = T(2) * seg25 * t42 * b - T(5) * seg25 * t47 - seg25 * c * t40;
    const T t49 = T(7) * t48 * seg25 + T(2) * seg25 * t44 * b - seg25 * c * t43;
    G_ap = (T(4) / T(45)) * seg11 * seg25 * seg12 * t32 + (T(2) / T(9)) * seg25 * seg15 * t36 * seg16 + (T(8) / T(45)) * seg25 * seg23 * seg22 * t34 + (T(8) / T(45)) * seg25 * seg13 * t39 * seg14 + (T(1) / T(315)) * seg21 * t15 * t30 + (T(8) / T(315)) * seg24 * seg25 * t31 * delta_tau - (T(8) / T(315)) * seg25 * tau_lo * seg17 * t46 - (T(4) / T(45)) * seg25 * seg19 * t45 * seg18 - (T(1) / T(315)) * seg25 * (T(3) * seg25 * t49 + T(2) * seg25 * t46 * b - seg25 * c * t45) * seg20;
    const T t50 = t16 * t16;
    const T t51 = t50 * t50;
    const T t52 = t51 * t51;
    const T t53 = t52 * t16;
    const T t54 = t20 * t20;
    const T t55 = t54 * t54;
    const T t56 = t55 * t55;
    const T t57 = t56 * t20;
    G_E = -(T(1) / T(945)) * seg25 * (T(168) * seg25 * t44 * seg19 * seg18 + T(280) * seg25 * seg13 * seg14 * t43 + T(56) * seg25 * tau_lo * seg17 * t49 + T(105) * seg26 * t53 + T(280) * seg25 * seg15 * seg16 * t38 + T(168) * seg25 * seg23 * t35 * seg22 - T(105) * t57 * seg21 - T(168) * seg11 * seg25 * t33 * seg12 - T(24) * t29 * seg24 * delta_tau * t15 - T(8) * seg25 * (seg25 * t44 * c - T(7) * seg25 * (T(2) * t48 * seg25 * b - seg25 * c * t42 - T(5) * seg25 * (T(2) * seg25 * t47 * b - T(3) * seg25 * (t16 - t20 - t26 * t15 * b) - seg25 * c * t41)) - T(2) * seg25 * b * t49) * seg20);
  }
  const T foot_offset = seg0 * seg25 * delta_tau * sigma2 * (seg27 + ab_ap * delta_tau);
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = foot1 + ab1 * foot_offset;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  grad[0] = -g_factor * (ab0 * G_E - foot_h0 * G_ap);
  grad[1] = (foot_h1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot_h2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i9_prepare); operations per point.
/// Operations: 136 +, 412 ×, 4 /, 2 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48160 +, 73293 ×, 4614 /, 2061 sqrt, 0 atan, 1 log/asinh.
template <class T>
T scalis_segment_cauchy_i9_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T seg10 = pre[22];
  const T a = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T tau_lo = pre[31];
  const T seg18 = pre[32];
  const T seg19 = pre[33];
  const T seg20 = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T seg26 = pre[40];
  const T seg27 = pre[41];
  const T length = pre[42];
  const T seg28 = pre[43];
  const T sigma = pre[44];
  const T g_factor = pre[45];
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
    foot0 = ap0 - ab_ap * seg0 * ab0;
    foot1 = ap1 - ab_ap * seg0 * ab1;
    foot2 = ap2 - ab_ap * seg0 * ab2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(A0, A1, A2, B0, B1, B2, p[0], p[1], p[2], exact_cross.data());
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * seg0;
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * seg0;
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T b = seg1 + ab_ap;
  const T c = seg2 + ap_ap;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = seg5 + ap2 * delta_tau;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = bp_bp + seg7;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t1 = a_minus_b * b;
  if (t1 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t2 = T(1) / D;
    const T t3 = r1 * b;
    X = seg8 * t2 * (t3 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = r1 * b;
    X = -(a_minus_b - b) * seg8 / (t4 - r0 * a_minus_b);
  }
  const T J1 = asinh(X) * seg9;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D + seg10;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D + seg10));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    F = T(56) * M_panels[3] * seg22 * seg23 + T(70) * seg15 * seg16 * M_panels[4] + seg20 * M_panels[8] + T(56) * seg14 * M_panels[5] * seg13 + seg21 * M_panels[0] + T(28) * M_panels[2] * seg11 * seg12 + T(28) * seg18 * M_panels[6] * seg19 + T(8) * seg24 * delta_tau * M_panels[1] + T(8) * seg17 * tau_lo * M_panels[7];
    const T t8 = T(28) * seg18 * M_panels[16] * seg19 + seg21 * M_panels[10] + T(8) * seg17 * tau_lo * M_panels[17] + T(70) * seg15 * seg16 * M_panels[14] + seg20 * M_panels[18] + T(8) * seg24 * delta_tau * M_panels[11] + T(56) * seg14 * M_panels[15] * seg13 + T(28) * seg11 * M_panels[12] * seg12 + T(56) * M_panels[13] * seg22 * seg23;
    G_ap = t8;
    G_E = T(70) * M_panels[15] * seg15 * seg16 + T(28) * seg18 * seg19 * M_panels[17] + T(56) * seg22 * M_panels[14] * seg23 + T(56) * seg14 * M_panels[16] * seg13 + seg21 * M_panels[11] + seg20 * M_panels[19] + T(8) * seg17 * M_panels[18] * tau_lo + T(28) * seg11 * seg12 * M_panels[13] + T(8) * seg24 * M_panels[12] * delta_tau - t8 * seg25 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    F = T(28) * seg11 * seg12 * M_panels[2] + T(70) * M_panels[4] * seg15 * seg16 + seg20 * M_panels[8] + T(56) * seg22 * M_panels[3] * seg23 + T(8) * M_panels[1] * seg24 * delta_tau + T(28) * seg18 * seg19 * M_panels[6] + seg21 * M_panels[0] + T(56) * seg14 * M_panels[5] * seg13 + T(8) * M_panels[7] * seg17 * tau_lo;
    G_ap = T(56) * seg22 * M_panels[13] * seg23 + T(70) * M_panels[14] * seg15 * seg16 + T(56) * seg14 * M_panels[15] * seg13 + seg20 * M_panels[18] + T(8) * seg17 * tau_lo * M_panels[17] + T(28) * seg18 * M_panels[16] * seg19 + seg21 * M_panels[10] + T(28) * seg11 * seg12 * M_panels[12] + T(8) * seg24 * M_panels[11] * delta_tau;
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
    G_E = (T(1) / T(9)) * (T(280) * seg15 * seg16 * M_panels[3] + t13 * seg21 + T(280) * seg14 * M_panels[4] * seg13 + T(56) * seg11 * M_panels[1] * seg12 + T(8) * seg20 * M_panels[7] + T(168) * seg18 * M_panels[5] * seg19 + T(8) * seg24 * delta_tau * M_panels[0] + T(168) * M_panels[2] * seg22 * seg23 + T(56) * seg17 * tau_lo * M_panels[6] - t18 * seg26) * seg25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / D;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t20 * b + t24 * a_minus_b;
    const T t28 = T(2) * t27 * t19 * a + t21 * t20 * b + t24 * a_minus_b * t25;
    const T t29 = T(3) * t24 * a_minus_b * t26 + T(3) * t22 * t20 * b + T(4) * t19 * a * t28;
    const T t30 = t26 * t25;
    const T t31 = T(5) * t23 * t20 * b + T(2) * t19 * a * t29 + T(5) * t24 * a_minus_b * t30;
    const T t32 = T(3) * t24 * t26 - t19 * b * t29 - T(3) * t22 * t20;
    const T t33 = T(5) * t19 * t28 - c * t19 * t29 - T(2) * seg25 * t32 * b;
    const T t34 = t21 * t20 + t19 * t28 * b - t24 * t25;
    const T t35 = c * seg25 * t32 + T(2) * t33 * seg25 * b + T(5) * t34 * seg25;
    const T t36 = T(5) * t24 * t30 - t19 * b * t31 - T(5) * t23 * t20;
    const T t37 = T(6) * seg25 * t36 * b + T(3) * c * t19 * t31 - T(7) * t19 * t29;
    const T t38 = T(2) * t37 * seg25 * b + T(7) * seg25 * t32 - T(3) * c * seg25 * t36;
    const T t39 = c * t37 * seg25 + T(7) * t33 * seg25 - T(2) * seg25 * t38 * b;
    const T t40 = T(7) * seg25 * t35 + c * seg25 * t38 + T(2) * t39 * seg25 * b;
    const T t41 = c * t19 * t28 - T(3) * t27 * t19 - T(2) * t34 * seg25 * b;
    const T t42 = T(2) * seg25 * b * t35 - c * t33 * seg25 - T(5) * seg25 * t41;
    const T t43 = c * t39 * seg25 - T(7) * t42 * seg25 - T(2) * t40 * seg25 * b;
    const T t44 = t24 - t20 - t27 * t19 * b;
    const T t45 = c * t34 * seg25 + T(2) * seg25 * b * t41 + T(3) * t44 * seg25;
    const T t46 = c * seg25 * t35 + T(5) * seg25 * t45 - T(2) * t42 * seg25 * b;
    const T t47 = T(2) * t43 * seg25 * b + c * t40 * seg25 + T(7) * t46 * seg25;
    F = (T(1) / T(35)) * seg21 * t19 * t31 + (T(8) / T(15)) * seg14 * t40 * seg25 * seg13 + (T(2) / T(3)) * t39 * seg15 * seg25 * seg16 - (T(4) / T(15)) * t43 * seg18 * seg25 * seg19 - (T(1) / T(105)) * seg20 * (T(2) * t47 * seg25 * b + T(7) * seg25 * (T(5) * (T(2) * seg25 * b * t45 + T(3) * (c * t27 * t19 + T(2) * t44 * seg25 * b - J1) * seg25 - c * seg25 * t41) * seg25 + c * t42 * seg25 + T(2) * t46 * seg25 * b) - c * t43 * seg25) * seg25 - (T(8) / T(15)) * seg25 * t38 * seg22 * seg23 - (T(8) / T(105)) * seg17 * tau_lo * t47 * seg25 - (T(4) / T(15)) * t37 * seg11 * seg12 * seg25 - (T(8) / T(35)) * seg24 * delta_tau * seg25 * t36;
    const T t48 = t26 * t26;
    const T t49 = t22 * t22;
    const T t50 = T(8) * t19 * a * t31 + T(35) * t24 * a_minus_b * t48 + T(35) * t49 * t20 * b;
    const T t51 = T(35) * t24 * t48 - T(35) * t49 * t20 - t19 * t50 * b;
    const T t52 = T(2) * t51 * seg25 * b + c * t19 * t50 - T(9) * t19 * t31;
    const T t53 = T(9) * seg25 * t36 + T(2) * seg25 * b * t52 - c * t51 * seg25;
    const T t54 = T(2) * seg25 * t53 * b + T(3) * t37 * seg25 - c * seg25 * t52;
    const T t55 = T(3) * seg25 * t38 + T(2) * t54 * seg25 * b - c * seg25 * t53;
    const T t56 = c * t54 * seg25 + T(3) * t39 * seg25 - T(2) * t55 * seg25 * b;
    const T t57 = c * t55 * seg25 + T(3) * t40 * seg25 + T(2) * seg25 * b * t56;
    G_ap = (T(1) / T(315)) * seg21 * t19 * t50 + (T(4) / T(45)) * seg18 * seg25 * seg19 * t56 + (T(8) / T(315)) * seg17 * tau_lo * seg25 * t57 - (T(4) / T(45)) * seg11 * seg12 * seg25 * t52 - (T(8) / T(45)) * seg14 * t55 * seg25 * seg13 - (T(2) / T(9)) * t54 * seg15 * seg25 * seg16 - (T(1) / T(315)) * seg20 * seg25 * (T(3) * t43 * seg25 + c * seg25 * t56 - T(2) * seg25 * b * t57) - (T(8) / T(315)) * seg24 * t51 * delta_tau * seg25 - (T(8) / T(45)) * seg25 * t53 * seg22 * seg23;
    const T t58 = t24 * t24;
    const T t59 = t58 * t58;
    const T t60 = t59 * t59;
    const T t61 = t60 * t24;
    const T t62 = t20 * t20;
    const T t63 = t62 * t62;
    const T t64 = t63 * t63;
    const T t65 = t64 * t20;
    G_E = -(T(1) / T(945)) * seg25 * (T(280) * seg15 * seg25 * t38 * seg16 + T(168) * seg11 * seg12 * seg25 * t36 + T(168) * t37 * seg25 * seg22 * seg23 + T(56) * seg17 * t43 * tau_lo * seg25 + T(8) * seg20 * t47 * seg25 + T(105) * t61 * seg26 - T(24) * seg24 * delta_tau * t19 * t31 - T(105) * t65 * seg21 - T(168) * t40 * seg18 * seg25 * seg19 - T(280) * seg14 * t39 * seg25 * seg13);
  }
  const T foot_offset = delta_tau * seg25 * sigma2 * seg0 * (seg27 + ab_ap * delta_tau);
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  f = length * seg28 * F * sigma;
  grad[0] = g_factor * (foot_h0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot_h1 * G_ap - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - foot_h2 * G_ap);
  return f;
}

/// How many values scalis_segment_cauchy_i10_prepare writes.
inline constexpr std::size_t scalis_segment_cauchy_i10_prepared_size = 46;

/// What scalis_segment_cauchy_i10_f, _grad and _f_and_grad read that depends on the segment
/// alone (A, B, the radii, σ), into pre[0 .. 46): computed once per
/// segment; in.p is not read.
/// Operations: 16 +, 56 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
void scalis_segment_cauchy_i10_prepare(const ScalisSegmentInput<T>& in, T* pre) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).
  const bool swap_ends = in.tau1 < in.tau0;
  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;
  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;
  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;
  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;
  const T delta_tau = tau_hi - tau_lo;
  const T sigma2 = in.sigma * in.sigma;
  const T ab0 = end_b[0] - end_a[0];
  const T ab1 = end_b[1] - end_a[1];
  const T ab2 = end_b[2] - end_a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T t1 = sigma2 * sigma2;
  const T t2 = t1 * t1;
  const T t3 = t2 * sigma2;
  const T g_factor = -T(10) * length * t3;
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
  pre[11] = -delta_tau * tau_lo * sigma2;
  const T t5 = tau_lo * tau_lo;
  pre[12] = t5 * sigma2;
  pre[13] = delta_tau;
  pre[14] = tau_lo * ab0;
  pre[15] = tau_lo * ab1;
  pre[16] = tau_lo * ab2;
  pre[17] = sigma2;
  pre[18] = delta_tau * sigma2 * tau_hi;
  pre[19] = sigma2 * tau_hi * tau_hi;
  pre[20] = tau_lo * sigma2 * tau_hi;
  pre[21] = -a * a;
  pre[22] = a;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * tau_lo;
  pre[23] = t8;
  pre[24] = t0;
  const T t9 = t5 * tau_lo;
  const T t10 = t9 * t9;
  const T t11 = t10 * tau_lo;
  pre[25] = t11;
  const T t12 = t0 * delta_tau;
  const T t13 = t12 * t12;
  pre[26] = t13;
  pre[27] = t9;
  const T t14 = t0 * t0;
  const T t15 = t14 * delta_tau;
  pre[28] = t15;
  pre[29] = t6;
  const T t16 = t14 * t14;
  const T t17 = t16 * delta_tau;
  pre[30] = t17;
  pre[31] = t14;
  const T t18 = t6 * tau_lo;
  pre[32] = t18;
  pre[33] = t16;
  pre[34] = tau_lo;
  const T t19 = t13 * delta_tau;
  pre[35] = t19;
  pre[36] = t5;
  pre[37] = t7;
  pre[38] = t12;
  pre[39] = t10;
  const T t20 = T(1) / a;
  pre[40] = t20;
  pre[41] = T(126) * t15 * t6 + T(126) * t14 * t18 + t17 + T(9) * delta_tau * t7 + T(9) * t16 * tau_lo + t8 + T(84) * t12 * t10 + T(36) * t19 * t5 + T(84) * t13 * t9 + T(36) * t0 * t11;
  pre[42] = tau_lo * ab_ab;
  pre[43] = length;
  pre[44] = t3;
  pre[45] = g_factor;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i10_prepare); operations per point.
/// Operations: 104 +, 267 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 31436 +, 43948 ×, 5081 /, 109 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i10_f(const T* pre, const std::array<T, 3>& p) {
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
  const T seg1 = pre[11];
  const T seg2 = pre[12];
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T seg19 = pre[32];
  const T seg20 = pre[33];
  const T tau_lo = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T seg26 = pre[40];
  const T length = pre[43];
  const T seg29 = pre[44];
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = seg3 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + seg4;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T F;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    F = T(36) * M_panels[7] * seg21 * seg22 + T(84) * seg25 * seg24 * M_panels[3] + T(126) * M_panels[4] * seg19 * seg18 + T(126) * M_panels[5] * seg16 * seg15 + seg17 * M_panels[9] + seg10 * M_panels[0] + T(36) * seg11 * M_panels[2] * seg12 + T(9) * M_panels[1] * seg23 * delta_tau + T(84) * seg14 * seg13 * M_panels[6] + T(9) * tau_lo * M_panels[8] * seg20;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    F = seg17 * M_panels[9] + T(126) * seg19 * M_panels[4] * seg18 + T(126) * seg16 * M_panels[5] * seg15 + T(36) * seg11 * M_panels[2] * seg12 + T(9) * M_panels[1] * seg23 * delta_tau + T(9) * tau_lo * M_panels[8] * seg20 + T(84) * M_panels[3] * seg25 * seg24 + T(36) * seg21 * M_panels[7] * seg22 + T(84) * seg14 * seg13 * M_panels[6] + M_panels[0] * seg10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(1) / c;
    const T log_ratio = log(q1 * t6);
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t8 * t6;
    const T t14 = a * J2 + b * t6 + t10 * a_minus_b;
    const T t15 = T(2) * t11 * a_minus_b + T(3) * t7 * a * t14 + T(2) * b * t8;
    const T t16 = T(8) * t12 * a_minus_b + T(8) * b * t13 + T(5) * t7 * a * t15;
    const T t17 = t11 * t11;
    const T t18 = T(48) * b * t9 + T(7) * t7 * a * t16 + T(48) * t17 * a_minus_b;
    const T t19 = t7 * b * t15 + T(2) * t8 - T(2) * t11;
    const T t20 = T(8) * t12 - t7 * b * t16 - T(8) * t13;
    const T t21 = T(6) * t7 * t15 - t7 * c * t16 - T(2) * t20 * seg26 * b;
    const T t22 = T(6) * t19 * seg26 + t20 * seg26 * c + T(2) * t21 * seg26 * b;
    const T t23 = T(48) * t17 - T(48) * t9 - t7 * b * t18;
    const T t24 = T(2) * seg26 * b * t23 + t7 * t18 * c - T(8) * t7 * t16;
    const T t25 = seg26 * t23 * c - T(8) * t20 * seg26 - T(2) * seg26 * b * t24;
    const T t26 = seg26 * c * t24 + T(2) * seg26 * b * t25 + T(8) * t21 * seg26;
    const T t27 = T(8) * seg26 * t22 + T(2) * seg26 * b * t26 - seg26 * t25 * c;
    const T t28 = T(2) * t19 * seg26 * b + T(4) * t7 * t14 - t7 * c * t15;
    const T t29 = T(2) * seg26 * b * t22 + T(6) * t28 * seg26 - t21 * seg26 * c;
    const T t30 = T(2) * seg26 * b * t27 + T(8) * seg26 * t29 - seg26 * t26 * c;
    const T t31 = t6 + t7 * t14 * b - t10;
    const T t32 = t19 * seg26 * c - T(2) * t28 * seg26 * b - T(4) * seg26 * t31;
    const T t33 = T(2) * seg26 * b * t29 - seg26 * t22 * c - T(6) * seg26 * t32;
    const T t34 = T(2) * t30 * seg26 * b + T(8) * seg26 * t33 - seg26 * t27 * c;
    const T t35 = T(2) * J2 + T(2) * seg26 * t31 * b - t7 * t14 * c;
    const T t36 = t28 * seg26 * c + T(2) * seg26 * b * t32 - T(4) * seg26 * t35;
    const T t37 = seg26 * t29 * c + T(6) * seg26 * t36 - T(2) * seg26 * b * t33;
    const T t38 = T(2) * t34 * seg26 * b - t30 * seg26 * c - T(8) * seg26 * t37;
    F = (T(1) / T(384)) * t7 * seg10 * t18 + (T(3) / T(128)) * tau_lo * seg26 * seg20 * t38 + (T(21) / T(64)) * seg26 * seg16 * t27 * seg15 + (T(7) / T(32)) * t30 * seg26 * seg14 * seg13 + (T(21) / T(64)) * seg19 * seg26 * t26 * seg18 + (T(7) / T(32)) * seg25 * seg26 * seg24 * t25 + (T(3) / T(32)) * t34 * seg21 * seg26 * seg22 - (T(3) / T(32)) * seg11 * seg26 * seg12 * t24 - (T(3) / T(128)) * seg26 * t23 * seg23 * delta_tau - (T(1) / T(384)) * seg17 * seg26 * (t34 * seg26 * c + T(8) * seg26 * (seg26 * t33 * c + T(2) * seg26 * b * t37 - T(6) * seg26 * (T(4) * seg26 * (T(2) * seg26 * b * t35 + (log_ratio + T(2) * J2 * b) * seg26 - seg26 * t31 * c) + seg26 * c * t32 - T(2) * seg26 * t36 * b)) - T(2) * seg26 * b * t38);
  }
  f = F * seg29 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i10_prepare); operations per point.
/// Operations: 135 +, 370 ×, 4 /, 1 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 47836 +, 61900 ×, 4237 /, 91 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> scalis_segment_cauchy_i10_grad(const T* pre, const std::array<T, 3>& p) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T seg19 = pre[32];
  const T seg20 = pre[33];
  const T tau_lo = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T seg26 = pre[40];
  const T seg27 = pre[41];
  const T seg28 = pre[42];
  const T g_factor = pre[45];
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
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
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
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * seg0;
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * seg0;
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * seg0;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T b = seg1 + ab_ap;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = ap_bp + seg8;
  T G_ap;
  T G_E;
  const T t1 = seg9 + T(4) * D;
  const T t2 = -b * a_minus_b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(seg9 + T(100) * D));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t4 = T(84) * seg13 * seg14 * M_panels[17] + T(9) * M_panels[19] * seg20 * tau_lo + T(36) * seg22 * seg21 * M_panels[18] + seg17 * M_panels[20] + T(9) * seg23 * M_panels[12] * delta_tau + T(126) * M_panels[16] * seg15 * seg16 + M_panels[11] * seg10 + T(126) * seg18 * seg19 * M_panels[15] + T(36) * seg11 * M_panels[13] * seg12 + T(84) * seg25 * M_panels[14] * seg24;
    G_ap = t4;
    G_E = T(84) * seg25 * seg24 * M_panels[15] + T(36) * seg11 * seg12 * M_panels[14] + T(9) * M_panels[13] * seg23 * delta_tau + seg17 * M_panels[21] + M_panels[12] * seg10 + T(9) * M_panels[20] * seg20 * tau_lo + T(36) * seg22 * M_panels[19] * seg21 + T(84) * seg13 * seg14 * M_panels[18] + T(126) * seg18 * M_panels[16] * seg19 + T(126) * seg15 * M_panels[17] * seg16 - seg26 * b * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    G_ap = T(36) * seg22 * seg21 * M_panels[18] + T(126) * M_panels[16] * seg15 * seg16 + T(9) * seg23 * delta_tau * M_panels[12] + T(84) * seg25 * M_panels[14] * seg24 + seg17 * M_panels[20] + T(36) * M_panels[13] * seg11 * seg12 + M_panels[11] * seg10 + T(126) * seg18 * seg19 * M_panels[15] + T(9) * M_panels[19] * seg20 * tau_lo + T(84) * seg13 * seg14 * M_panels[17];
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(10)) * (t8 * seg10 + T(72) * seg11 * M_panels[1] * seg12 + T(504) * seg13 * seg14 * M_panels[5] + T(72) * M_panels[7] * seg20 * tau_lo + T(504) * M_panels[3] * seg18 * seg19 + T(252) * seg22 * seg21 * M_panels[6] + T(9) * M_panels[0] * seg23 * delta_tau + T(252) * seg25 * M_panels[2] * seg24 + T(630) * M_panels[4] * seg15 * seg16 + T(9) * seg17 * M_panels[8] - t12 * seg27) * seg26;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t18 * a_minus_b + a * J2 + b * t15;
    const T t21 = T(1) / D;
    const T t22 = T(2) * b * t16 + T(2) * t19 * a_minus_b + T(3) * a * t20 * t21;
    const T t23 = t19 * t18;
    const T t24 = t16 * t15;
    const T t25 = T(5) * a * t22 * t21 + T(8) * t23 * a_minus_b + T(8) * b * t24;
    const T t26 = t19 * t19;
    const T t27 = T(48) * b * t17 + T(7) * a * t25 * t21 + T(48) * t26 * a_minus_b;
    const T t28 = t17 * t15;
    const T t29 = t26 * t18;
    const T t30 = T(128) * b * t28 + T(3) * t27 * a * t21 + T(128) * t29 * a_minus_b;
    const T t31 = T(128) * t29 - T(128) * t28 - b * t30 * t21;
    const T t32 = T(10) * t27 * t21 - T(3) * c * t30 * t21 - T(6) * t31 * seg26 * b;
    const T t33 = T(48) * t26 - T(48) * t17 - t27 * b * t21;
    const T t34 = T(2) * seg26 * t32 * b + T(3) * t31 * seg26 * c - T(10) * seg26 * t33;
    const T t35 = b * t25 * t21 + T(8) * t24 - T(8) * t23;
    const T t36 = t27 * c * t21 + T(2) * seg26 * b * t33 - T(8) * t25 * t21;
    const T t37 = seg26 * t33 * c + T(8) * t35 * seg26 - T(2) * seg26 * b * t36;
    const T t38 = seg26 * t32 * c + T(10) * seg26 * t36 - T(2) * seg26 * b * t34;
    const T t39 = T(10) * seg26 * t37 - seg26 * c * t34 - T(2) * t38 * seg26 * b;
    const T t40 = T(6) * t22 * t21 + T(2) * t35 * seg26 * b - t25 * c * t21;
    const T t41 = seg26 * c * t36 + T(8) * seg26 * t40 + T(2) * seg26 * b * t37;
    const T t42 = T(10) * seg26 * t41 + T(2) * seg26 * b * t39 + t38 * seg26 * c;
    const T t43 = t22 * b * t21 + T(2) * t16 - T(2) * t19;
    const T t44 = T(6) * seg26 * t43 + T(2) * seg26 * b * t40 - t35 * seg26 * c;
    const T t45 = T(8) * seg26 * t44 + T(2) * seg26 * t41 * b - seg26 * t37 * c;
    const T t46 = seg26 * c * t39 - T(2) * seg26 * b * t42 - T(10) * seg26 * t45;
    const T t47 = T(2) * seg26 * b * t43 + T(4) * t20 * t21 - t22 * c * t21;
    const T t48 = seg26 * c * t40 - T(2) * seg26 * b * t44 - T(6) * seg26 * t47;
    const T t49 = seg26 * t41 * c + T(8) * t48 * seg26 - T(2) * seg26 * b * t45;
    const T t50 = seg26 * c * t42 + T(10) * t49 * seg26 + T(2) * seg26 * b * t46;
    const T t51 = b * t20 * t21 + t15 - t18;
    const T t52 = seg26 * c * t43 - T(2) * seg26 * b * t47 - T(4) * seg26 * t51;
    const T t53 = T(6) * seg26 * t52 + seg26 * c * t44 + T(2) * t48 * seg26 * b;
    const T t54 = seg26 * t45 * c + T(8) * seg26 * t53 + T(2) * t49 * seg26 * b;
    G_ap = (T(3) / T(320)) * seg26 * t32 * seg11 * seg12 + (T(1) / T(1280)) * t30 * seg10 * t21 + (T(7) / T(320)) * seg25 * seg26 * seg24 * t34 + (T(21) / T(640)) * seg26 * seg15 * seg16 * t39 + (T(7) / T(320)) * seg13 * seg26 * seg14 * t42 - (T(3) / T(320)) * seg22 * seg26 * seg21 * t46 - (T(3) / T(1280)) * seg26 * t50 * seg20 * tau_lo - (T(9) / T(1280)) * t31 * seg26 * seg23 * delta_tau - (T(1) / T(3840)) * seg26 * seg17 * (T(10) * seg26 * t54 + T(2) * seg26 * b * t50 - seg26 * c * t46) - (T(21) / T(640)) * t38 * seg18 * seg26 * seg19;
    G_E = (T(1) / T(1280)) * seg26 * (T(128) * t28 * seg10 + T(210) * seg26 * t41 * seg15 * seg16 + T(168) * seg13 * seg26 * seg14 * t45 + T(168) * seg18 * seg26 * t37 * seg19 + T(3) * t27 * seg23 * delta_tau * t21 + T(3) * seg26 * seg17 * (t49 * seg26 * c - T(8) * (T(2) * seg26 * t53 * b + T(6) * seg26 * (seg26 * t47 * c + T(2) * seg26 * b * t52 - T(4) * (T(2) * J2 + T(2) * seg26 * t51 * b - t20 * c * t21) * seg26) - t48 * seg26 * c) * seg26 - T(2) * seg26 * b * t54) - T(84) * seg22 * t49 * seg26 * seg21 - T(128) * t29 * seg27 - T(24) * seg26 * seg11 * t33 * seg12 - T(84) * seg25 * seg26 * seg24 * t36 - T(24) * seg26 * t54 * seg20 * tau_lo);
  }
  const T foot_offset = (ab_ap * delta_tau + seg28) * sigma2 * seg26 * delta_tau * seg0;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  grad[0] = -(ab0 * G_E - G_ap * foot_h0) * g_factor;
  grad[1] = g_factor * (G_ap * foot_h1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// At one point, from the segment's pre[] (scalis_segment_cauchy_i10_prepare); operations per point.
/// Operations: 153 +, 440 ×, 4 /, 1 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 47845 +, 61928 ×, 4237 /, 91 sqrt, 0 atan, 0 log/asinh.
template <class T>
T scalis_segment_cauchy_i10_f_and_grad(const T* pre, const std::array<T, 3>& p, std::array<T, 3>& grad) {
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
  const T delta_tau = pre[13];
  const T seg3 = pre[14];
  const T seg4 = pre[15];
  const T seg5 = pre[16];
  const T sigma2 = pre[17];
  const T seg6 = pre[18];
  const T seg7 = pre[19];
  const T seg8 = pre[20];
  const T seg9 = pre[21];
  const T a = pre[22];
  const T seg10 = pre[23];
  const T seg11 = pre[24];
  const T seg12 = pre[25];
  const T seg13 = pre[26];
  const T seg14 = pre[27];
  const T seg15 = pre[28];
  const T seg16 = pre[29];
  const T seg17 = pre[30];
  const T seg18 = pre[31];
  const T seg19 = pre[32];
  const T seg20 = pre[33];
  const T tau_lo = pre[34];
  const T seg21 = pre[35];
  const T seg22 = pre[36];
  const T seg23 = pre[37];
  const T seg24 = pre[38];
  const T seg25 = pre[39];
  const T seg26 = pre[40];
  const T seg27 = pre[41];
  const T seg28 = pre[42];
  const T length = pre[43];
  const T seg29 = pre[44];
  const T g_factor = pre[45];
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
    foot0 = seg0 * (exact_cross[1] * ab2 - ab1 * exact_cross[2]);
    foot1 = seg0 * (ab0 * exact_cross[2] - exact_cross[0] * ab2);
    foot2 = -seg0 * (exact_cross[1] * ab0 - exact_cross[0] * ab1);
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T b = ab_ap + seg1;
  const T c = ap_ap + seg2;
  const T radial0 = ap0 * delta_tau + seg3;
  const T radial1 = seg4 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + seg5;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = seg6 - ab_bp;
  const T q1 = seg7 + bp_bp;
  const T c_minus_b = seg8 + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t1 = T(4) * D + seg9;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D + seg9));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    F = T(84) * seg24 * M_panels[3] * seg25 + seg10 * M_panels[0] + T(36) * M_panels[7] * seg21 * seg22 + T(84) * seg13 * seg14 * M_panels[6] + T(126) * seg19 * M_panels[4] * seg18 + T(36) * seg11 * M_panels[2] * seg12 + T(9) * seg20 * tau_lo * M_panels[8] + T(9) * M_panels[1] * seg23 * delta_tau + T(126) * seg16 * M_panels[5] * seg15 + seg17 * M_panels[9];
    const T t4 = seg10 * M_panels[11] + T(9) * seg20 * tau_lo * M_panels[19] + T(9) * seg23 * delta_tau * M_panels[12] + T(36) * M_panels[18] * seg21 * seg22 + T(84) * seg13 * M_panels[17] * seg14 + T(126) * seg16 * seg15 * M_panels[16] + M_panels[20] * seg17 + T(126) * seg19 * M_panels[15] * seg18 + T(84) * M_panels[14] * seg24 * seg25 + T(36) * seg11 * seg12 * M_panels[13];
    G_ap = t4;
    G_E = seg17 * M_panels[21] + T(126) * seg19 * seg18 * M_panels[16] + T(84) * seg24 * M_panels[15] * seg25 + T(9) * M_panels[20] * seg20 * tau_lo + T(9) * seg23 * delta_tau * M_panels[13] + T(36) * M_panels[14] * seg11 * seg12 + T(36) * seg21 * M_panels[19] * seg22 + T(126) * seg16 * M_panels[17] * seg15 + seg10 * M_panels[12] + T(84) * seg13 * seg14 * M_panels[18] - seg26 * b * t4;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    F = T(9) * seg20 * tau_lo * M_panels[8] + T(84) * seg24 * M_panels[3] * seg25 + T(36) * seg11 * M_panels[2] * seg12 + T(126) * seg19 * M_panels[4] * seg18 + T(36) * M_panels[7] * seg21 * seg22 + seg10 * M_panels[0] + T(84) * seg13 * seg14 * M_panels[6] + T(9) * M_panels[1] * seg23 * delta_tau + T(126) * seg16 * M_panels[5] * seg15 + seg17 * M_panels[9];
    G_ap = T(84) * seg13 * M_panels[17] * seg14 + T(126) * seg19 * M_panels[15] * seg18 + T(9) * seg20 * tau_lo * M_panels[19] + seg10 * M_panels[11] + T(36) * M_panels[18] * seg21 * seg22 + T(84) * M_panels[14] * seg24 * seg25 + M_panels[20] * seg17 + T(126) * seg16 * seg15 * M_panels[16] + T(9) * seg23 * delta_tau * M_panels[12] + T(36) * seg11 * seg12 * M_panels[13];
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    G_E = (T(1) / T(10)) * seg26 * (T(252) * M_panels[2] * seg24 * seg25 + T(504) * seg19 * seg18 * M_panels[3] + T(504) * seg13 * M_panels[5] * seg14 + T(630) * seg16 * M_panels[4] * seg15 + T(252) * seg21 * M_panels[6] * seg22 + T(9) * seg23 * delta_tau * M_panels[0] + T(9) * M_panels[8] * seg17 + T(72) * M_panels[1] * seg11 * seg12 + T(72) * M_panels[7] * seg20 * tau_lo + t8 * seg10 - seg27 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / c;
    const T log_ratio = log(t15 * q1);
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = J2 * a + t15 * b + a_minus_b * t17;
    const T t19 = t17 - t16 * t18 * b - t15;
    const T t20 = T(2) * J2 - c * t16 * t18 - T(2) * seg26 * b * t19;
    const T t21 = t17 * t17;
    const T t22 = t15 * t15;
    const T t23 = T(3) * t16 * a * t18 + T(2) * a_minus_b * t21 + T(2) * t22 * b;
    const T t24 = T(2) * t22 + t16 * t23 * b - T(2) * t21;
    const T t25 = c * t16 * t23 - T(2) * seg26 * t24 * b - T(4) * t16 * t18;
    const T t26 = T(4) * seg26 * t19 + c * seg26 * t24 + T(2) * seg26 * t25 * b;
    const T t27 = T(4) * seg26 * t20 + c * seg26 * t25 - T(2) * seg26 * t26 * b;
    const T t28 = t21 * t17;
    const T t29 = t22 * t15;
    const T t30 = T(8) * a_minus_b * t28 + T(5) * t16 * a * t23 + T(8) * t29 * b;
    const T t31 = T(8) * t29 + t16 * t30 * b - T(8) * t28;
    const T t32 = c * t16 * t30 - T(2) * seg26 * t31 * b - T(6) * t16 * t23;
    const T t33 = T(6) * seg26 * t24 - T(2) * seg26 * b * t32 - c * seg26 * t31;
    const T t34 = T(2) * t33 * seg26 * b + c * seg26 * t32 - T(6) * seg26 * t25;
    const T t35 = t33 * c * seg26 + T(6) * seg26 * t26 - T(2) * t34 * seg26 * b;
    const T t36 = T(6) * t27 * seg26 - T(2) * seg26 * t35 * b - t34 * c * seg26;
    const T t37 = t22 * t22;
    const T t38 = t21 * t21;
    const T t39 = T(48) * t37 * b + T(7) * t16 * a * t30 + T(48) * a_minus_b * t38;
    const T t40 = T(48) * t37 + t16 * t39 * b - T(48) * t38;
    const T t41 = T(2) * seg26 * t40 * b + T(8) * t16 * t30 - c * t16 * t39;
    const T t42 = T(8) * seg26 * t31 + T(2) * seg26 * t41 * b - c * seg26 * t40;
    const T t43 = T(8) * seg26 * t32 + c * seg26 * t41 - T(2) * seg26 * t42 * b;
    const T t44 = c * seg26 * t42 + T(2) * seg26 * t43 * b - T(8) * t33 * seg26;
    const T t45 = T(8) * t34 * seg26 + c * seg26 * t43 - T(2) * t44 * seg26 * b;
    const T t46 = c * t44 * seg26 + T(2) * seg26 * b * t45 - T(8) * seg26 * t35;
    const T t47 = T(8) * seg26 * t36 + T(2) * seg26 * b * t46 - c * seg26 * t45;
    F = (T(1) / T(384)) * seg26 * (T(2) * seg26 * t47 * b + T(8) * seg26 * (T(6) * seg26 * (T(4) * (seg26 * (T(2) * J2 * b + log_ratio) + T(2) * seg26 * b * t20 + c * seg26 * t19) * seg26 + T(2) * t27 * seg26 * b + c * seg26 * t26) + c * seg26 * t35 + T(2) * seg26 * t36 * b) - c * seg26 * t46) * seg17 + (T(3) / T(128)) * seg26 * seg23 * delta_tau * t40 + (T(7) / T(32)) * seg13 * seg26 * seg14 * t45 + (T(3) / T(32)) * seg26 * seg21 * t46 * seg22 + (T(7) / T(32)) * seg26 * t42 * seg24 * seg25 + (T(3) / T(32)) * seg26 * seg11 * seg12 * t41 + (T(1) / T(384)) * seg10 * t16 * t39 + (T(3) / T(128)) * seg26 * seg20 * tau_lo * t47 - (T(21) / T(64)) * seg16 * t44 * seg26 * seg15 - (T(21) / T(64)) * seg19 * seg26 * t43 * seg18;
    const T t48 = t37 * t15;
    const T t49 = t38 * t17;
    const T t50 = T(128) * t48 * b + T(3) * t16 * a * t39 + T(128) * a_minus_b * t49;
    const T t51 = T(128) * t48 + t16 * b * t50 - T(128) * t49;
    const T t52 = T(10) * t16 * t39 + T(6) * seg26 * t51 * b - T(3) * c * t16 * t50;
    const T t53 = T(2) * t52 * seg26 * b + T(10) * seg26 * t40 - T(3) * c * seg26 * t51;
    const T t54 = T(10) * seg26 * t41 + T(2) * seg26 * t53 * b - c * t52 * seg26;
    const T t55 = T(2) * seg26 * t54 * b + T(10) * seg26 * t42 - c * seg26 * t53;
    const T t56 = T(2) * t55 * seg26 * b - T(10) * seg26 * t43 - c * seg26 * t54;
    const T t57 = T(2) * t56 * seg26 * b - t55 * c * seg26 - T(10) * t44 * seg26;
    const T t58 = T(10) * seg26 * t45 + T(2) * seg26 * t57 * b - c * t56 * seg26;
    G_ap = (T(7) / T(320)) * seg13 * t56 * seg26 * seg14 + (T(1) / T(1280)) * seg10 * t16 * t50 + (T(21) / T(640)) * seg19 * seg26 * t54 * seg18 + (T(3) / T(320)) * seg26 * t57 * seg21 * seg22 + (T(21) / T(640)) * t55 * seg16 * seg26 * seg15 + (T(3) / T(1280)) * seg26 * seg20 * tau_lo * t58 + (T(3) / T(320)) * t52 * seg26 * seg11 * seg12 + (T(7) / T(320)) * seg26 * t53 * seg24 * seg25 + (T(9) / T(1280)) * seg26 * seg23 * delta_tau * t51 + (T(1) / T(3840)) * seg26 * seg17 * (T(10) * seg26 * t46 + T(2) * seg26 * t58 * b - c * seg26 * t57);
    G_E = (T(1) / T(1280)) * seg26 * (T(84) * seg26 * seg24 * t41 * seg25 + T(24) * seg26 * seg11 * t40 * seg12 + T(24) * seg26 * seg20 * tau_lo * t46 + T(3) * seg23 * delta_tau * t16 * t39 + T(168) * seg19 * seg26 * t42 * seg18 + T(84) * seg26 * seg21 * t45 * seg22 + T(128) * t48 * seg10 + T(3) * seg26 * seg17 * t47 - T(128) * seg27 * t49 - T(210) * seg16 * seg26 * t43 * seg15 - T(168) * t44 * seg13 * seg26 * seg14);
  }
  const T foot_offset = seg0 * (seg28 + ab_ap * delta_tau) * seg26 * delta_tau * sigma2;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  f = length * seg29 * F;
  grad[0] = g_factor * (G_ap * foot_h0 - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot_h1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot_h2);
  return f;
}

}  // namespace skelconv::generated
