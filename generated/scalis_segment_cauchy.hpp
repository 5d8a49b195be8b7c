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

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 47 +, 70 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 54187 +, 68248 ×, 20003 /, 541 sqrt, 0 atan, 0 log/asinh.
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
  T F;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
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
    F = (T(1) / T(2)) * (log_ratio + T(2) * J2 * b) * delta_tau / a + J2 * tau_lo;
  }
  f = sigma2 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 63 +, 106 ×, 8 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 43620 +, 58866 ×, 10056 /, 272 sqrt, 0 atan, 0 log/asinh.
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
    foot1 = -(exact_cross[0] * ab2 - exact_cross[2] * ab0) * t2;
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
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
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    const T t6 = delta_tau * M_panels[4] + tau_lo * M_panels[3];
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = tau_lo * M_panels[4] + delta_tau * M_panels[5] - t7 * b * t6;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    G_ap = delta_tau * M_panels[4] + M_panels[3] * tau_lo;
    const T t8 = T(1) / a;
    const T t9 = T(1) / c;
    const T t10 = tau_lo * t9;
    const T t11 = T(1) / q1;
    G_E = (T(1) / T(2)) * t8 * (t10 + delta_tau * M_panels[0] - (delta_tau + tau_lo) * t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / D;
    const T t15 = T(1) / c;
    const T t16 = T(1) / q1;
    const T t17 = b * t15 + a_minus_b * t16 + a * J2;
    const T t18 = T(1) / a;
    G_ap = (T(1) / T(2)) * t14 * tau_lo * t17 + (T(1) / T(2)) * delta_tau * t18 * (t15 + t14 * b * t17 - t16);
    const T t19 = tau_lo * t15;
    G_E = (T(1) / T(2)) * (t19 + delta_tau * J2 - (delta_tau + tau_lo) * t16) * t18;
  }
  const T t20 = T(1) / a;
  const T t21 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t20 * sigma2 * (tau_lo * ab_ab + ab_ap * delta_tau) * t21;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = (G_ap * foot_h0 - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = -g_factor * (ab2 * G_E - foot_h2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 65 +, 115 ×, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 43621 +, 58870 ×, 10056 /, 272 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
    foot0 = ap0 - ab0 * t1 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (exact_cross[2] * ab1 - ab2 * exact_cross[1]);
    foot1 = t2 * (ab0 * exact_cross[2] - ab2 * exact_cross[0]);
    foot2 = t2 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + ab2 * tau_lo;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    const T t6 = M_panels[4] * delta_tau + M_panels[3] * tau_lo;
    G_ap = t6;
    const T t7 = T(1) / a;
    G_E = M_panels[4] * tau_lo + delta_tau * M_panels[5] - t7 * t6 * b;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + M_panels[1] * delta_tau;
    G_ap = M_panels[4] * delta_tau + tau_lo * M_panels[3];
    const T t8 = T(1) / c;
    const T t9 = t8 * tau_lo;
    const T t10 = T(1) / q1;
    const T t11 = T(1) / a;
    G_E = (T(1) / T(2)) * (delta_tau * M_panels[0] + t9 - t10 * (delta_tau + tau_lo)) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / c;
    const T log_ratio = log(q1 * t14);
    const T t15 = T(1) / a;
    F = (T(1) / T(2)) * delta_tau * (T(2) * J2 * b + log_ratio) * t15 + J2 * tau_lo;
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = t17 * a_minus_b + J2 * a + t14 * b;
    G_ap = (T(1) / T(2)) * delta_tau * t15 * (t16 * b * t18 + t14 - t17) + (T(1) / T(2)) * tau_lo * t16 * t18;
    const T t19 = t14 * tau_lo;
    G_E = (T(1) / T(2)) * t15 * (J2 * delta_tau + t19 - t17 * (delta_tau + tau_lo));
  }
  const T t20 = T(1) / ab_ab;
  const T t21 = T(1) / a;
  const T foot_offset = t20 * delta_tau * (ab_ap * delta_tau + ab_ab * tau_lo) * t21 * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  const T g_factor = -T(2) * length * sigma2;
  f = length * sigma2 * F;
  grad[0] = -g_factor * (ab0 * G_E - foot_h0 * G_ap);
  grad[1] = g_factor * (G_ap * foot_h1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot_h2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 50 +, 84 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 41681 +, 61934 ×, 13372 /, 5791 sqrt, 0 atan, 1 log/asinh.
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
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
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
  const T t13 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t1 * M_panels[2] + T(2) * delta_tau * M_panels[1] * tau_lo + t2 * M_panels[0];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = T(2) * M_panels[1] * delta_tau * tau_lo + t2 * M_panels[0] + t1 * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 * a_minus_b + t16 * b;
    const T t18 = T(1) / a;
    const T t19 = t16 + t14 * t17 * b - t15;
    F = t14 * t2 * t17 + t1 * (J1 + T(2) * t18 * t19 * b - t14 * t17 * c) * t18 + T(2) * delta_tau * tau_lo * t18 * t19;
  }
  f = sigma2 * F * in.sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 68 +, 136 ×, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 41520 +, 63561 ×, 8058 /, 3490 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
    foot1 = -t2 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t4 * M_panels[4] + T(2) * delta_tau * tau_lo * M_panels[5] + t3 * M_panels[6];
    G_ap = t8;
    const T t9 = T(1) / a;
    G_E = T(2) * delta_tau * tau_lo * M_panels[6] + t3 * M_panels[7] + t4 * M_panels[5] - t9 * t8 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    G_ap = t4 * M_panels[4] + t3 * M_panels[6] + T(2) * M_panels[5] * delta_tau * tau_lo;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t4 * t12;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / a;
    G_E = (T(1) / T(3)) * (t13 + T(2) * t3 * M_panels[1] + T(2) * delta_tau * tau_lo * M_panels[0] - (T(2) * delta_tau * tau_lo + t3 + t4) * t16) * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = t18 * a_minus_b + b * t20;
    const T t24 = t18 * a_minus_b * t19 + b * t20 * t21 + T(2) * t22 * a * t23;
    const T t25 = T(1) / a;
    const T t26 = t24 * t22 * b + t20 * t21 - t18 * t19;
    G_ap = (T(1) / T(3)) * t24 * t4 * t22 + (T(2) / T(3)) * delta_tau * tau_lo * t25 * t26 - (T(1) / T(3)) * (t24 * t22 * c - T(2) * t25 * b * t26 - T(3) * t22 * t23) * t3 * t25;
    const T t27 = t20 * t20;
    const T t28 = t27 * t20;
    const T t29 = t4 * t28;
    const T t30 = t18 * t18;
    const T t31 = t30 * t18;
    G_E = (T(1) / T(3)) * t25 * (t29 + T(2) * t3 * t25 * (t20 + t22 * t23 * b - t18) + T(2) * delta_tau * tau_lo * t22 * t23 - (T(2) * delta_tau * tau_lo + t3 + t4) * t31);
  }
  const T t32 = T(1) / a;
  const T t33 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t32 * sigma2 * t33 * (tau_lo * ab_ab + ab_ap * delta_tau);
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T g_factor = -T(3) * length * sigma2 * in.sigma;
  grad[0] = -g_factor * (ab0 * G_E - foot_h0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = (foot_h2 * G_ap - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 73 +, 158 ×, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 41523 +, 63575 ×, 8060 /, 3492 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
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
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * t2;
    foot1 = -t2 * (exact_cross[0] * ab2 - ab0 * exact_cross[2]);
    foot2 = -(ab0 * exact_cross[1] - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t5 = a_minus_b * b;
  if (t5 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t6 = r0 * a_minus_b;
    const T t7 = T(1) / D;
    const T t8 = sqrt(a);
    X = (t6 + r1 * b) * t7 * t8;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t9 = sqrt(a);
    const T t10 = r0 * a_minus_b;
    X = (a_minus_b - b) * t9 / (t10 - r1 * b);
  }
  const T t11 = sqrt(a);
  const T t12 = T(1) / t11;
  const T J1 = t12 * asinh(X);
  T F;
  T G_ap;
  T G_E;
  const T t13 = T(4) * D - a * a;
  const T t14 = -a_minus_b * b;
  const T t15 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t13 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = T(2) * delta_tau * tau_lo * M_panels[1] + t4 * M_panels[0] + M_panels[2] * t3;
    const T t16 = t3 * M_panels[6] + T(2) * M_panels[5] * delta_tau * tau_lo + t4 * M_panels[4];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = M_panels[5] * t4 + t3 * M_panels[7] + T(2) * delta_tau * tau_lo * M_panels[6] - t17 * t16 * b;
  } else if (t14 >= T(0) && t15 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t4 + T(2) * delta_tau * M_panels[1] * tau_lo + t3 * M_panels[2];
    G_ap = M_panels[4] * t4 + T(2) * delta_tau * tau_lo * M_panels[5] + M_panels[6] * t3;
    const T t18 = T(1) / a;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(2) * delta_tau * tau_lo + t3 + t4;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    G_E = (T(1) / T(3)) * t18 * (T(2) * M_panels[0] * delta_tau * tau_lo + T(2) * t3 * M_panels[1] + t21 * t4 - t22 * t25);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / D;
    const T t27 = T(1) / r0;
    const T t28 = T(1) / r1;
    const T t29 = t27 * b + a_minus_b * t28;
    const T t30 = t27 + t26 * t29 * b - t28;
    const T t31 = T(1) / a;
    F = t4 * t26 * t29 + (J1 + T(2) * t30 * t31 * b - c * t26 * t29) * t3 * t31 + T(2) * t30 * delta_tau * tau_lo * t31;
    const T t32 = t27 * t27;
    const T t33 = t28 * t28;
    const T t34 = T(2) * t26 * t29 * a + t32 * t27 * b + t33 * a_minus_b * t28;
    const T t35 = t26 * t34 * b + t32 * t27 - t33 * t28;
    G_ap = (T(1) / T(3)) * t4 * t26 * t34 + (T(1) / T(3)) * (T(3) * t26 * t29 + T(2) * t35 * t31 * b - c * t26 * t34) * t3 * t31 + (T(2) / T(3)) * t35 * delta_tau * tau_lo * t31;
    const T t36 = T(2) * delta_tau * tau_lo + t3 + t4;
    const T t37 = t28 * t28;
    const T t38 = t37 * t28;
    const T t39 = t27 * t27;
    const T t40 = t39 * t27;
    G_E = -(T(1) / T(3)) * (t36 * t38 - T(2) * delta_tau * tau_lo * t26 * t29 - T(2) * t30 * t3 * t31 - t40 * t4) * t31;
  }
  const T t41 = T(1) / a;
  const T t42 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t41 * sigma2 * (tau_lo * ab_ab + ab_ap * delta_tau) * t42;
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  f = in.sigma * length * sigma2 * F;
  grad[0] = (foot_h0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot_h1) * g_factor;
  grad[2] = (G_ap * foot_h2 - G_E * ab2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 57 +, 103 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 35449 +, 46603 ×, 10050 /, 272 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = sigma2 * t1 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t2;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * delta_tau;
    const T t7 = t2 * tau_lo;
    F = T(3) * M_panels[1] * delta_tau * t2 + M_panels[3] * t6 + T(3) * M_panels[2] * t1 * tau_lo + M_panels[0] * t7;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t1 * delta_tau;
    const T t9 = t2 * tau_lo;
    F = T(3) * M_panels[2] * t1 * tau_lo + T(3) * M_panels[1] * delta_tau * t2 + M_panels[3] * t8 + M_panels[0] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, c_minus_b);
    const T t12 = T(1) / c;
    const T log_ratio = log(t12 * q1);
    const T t13 = T(1) / D;
    const T t14 = T(1) / q1;
    const T t15 = a * J2 + b * t12 + a_minus_b * t14;
    const T t16 = t2 * tau_lo;
    const T t17 = t13 * b * t15 + t12 - t14;
    const T t18 = T(1) / a;
    const T t19 = T(2) * J2 + T(2) * t17 * t18 * b - t13 * t15 * c;
    const T t20 = t1 * delta_tau;
    F = (T(1) / T(2)) * t13 * t15 * t16 + (T(3) / T(2)) * t17 * t18 * delta_tau * t2 + (T(3) / T(2)) * t18 * t19 * t1 * tau_lo + (T(1) / T(2)) * t18 * (t18 * (T(2) * J2 * b + log_ratio) + T(2) * t18 * t19 * b - t17 * t18 * c) * t20;
  }
  f = sigma2 * sigma2 * F * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 79 +, 166 ×, 8 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 40146 +, 53098 ×, 6726 /, 182 sqrt, 0 atan, 0 log/asinh.
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
    const T t1 = T(1) / ab_ab;
    foot0 = ap0 - t1 * ab0 * ab_ap;
    foot1 = ap1 - t1 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t1 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (ab2 * exact_cross[1] - ab1 * exact_cross[2]);
    foot1 = (exact_cross[2] * ab0 - ab2 * exact_cross[0]) * t2;
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t4 * tau_lo;
    const T t10 = T(3) * M_panels[7] * t3 * tau_lo + M_panels[8] * t8 + M_panels[5] * t9 + T(3) * delta_tau * M_panels[6] * t4;
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = M_panels[9] * t8 + M_panels[6] * t9 + T(3) * M_panels[7] * delta_tau * t4 + T(3) * M_panels[8] * t3 * tau_lo - b * t10 * t11;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t3 * delta_tau;
    const T t13 = t4 * tau_lo;
    G_ap = M_panels[8] * t12 + M_panels[5] * t13 + T(3) * M_panels[7] * t3 * tau_lo + T(3) * delta_tau * t4 * M_panels[6];
    const T t14 = T(1) / c;
    const T t15 = t14 * t14;
    const T t16 = T(3) * t3 * tau_lo + t13 + t12 + T(3) * delta_tau * t4;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / a;
    G_E = (T(1) / T(4)) * (T(3) * M_panels[2] * t12 + T(6) * M_panels[1] * t3 * tau_lo + T(3) * M_panels[0] * delta_tau * t4 + t15 * t13 - t16 * t18) * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(D);
    const T t21 = T(1) / t20;
    const T J2 = atan2(t20, c_minus_b) * t21;
    const T t22 = T(1) / D;
    const T t23 = T(1) / q1;
    const T t24 = T(1) / c;
    const T t25 = a_minus_b * t23 + J2 * a + b * t24;
    const T t26 = t24 * t24;
    const T t27 = t23 * t23;
    const T t28 = T(3) * t25 * t22 * a + T(2) * b * t26 + T(2) * a_minus_b * t27;
    const T t29 = b * t22 * t28 + T(2) * t26 - T(2) * t27;
    const T t30 = T(1) / a;
    const T t31 = T(2) * b * t29 * t30 + T(4) * t25 * t22 - c * t22 * t28;
    const T t32 = t25 * b * t22 + t24 - t23;
    const T t33 = t3 * delta_tau;
    const T t34 = t4 * tau_lo;
    G_ap = (T(3) / T(8)) * t31 * t3 * tau_lo * t30 + (T(1) / T(8)) * (T(4) * t32 * t30 + T(2) * b * t31 * t30 - c * t29 * t30) * t33 * t30 + (T(1) / T(8)) * t22 * t34 * t28 + (T(3) / T(8)) * t29 * delta_tau * t4 * t30;
    const T t35 = T(3) * t3 * tau_lo + t34 + t33 + T(3) * delta_tau * t4;
    G_E = (T(1) / T(8)) * t30 * (T(3) * t25 * t22 * delta_tau * t4 + T(6) * t3 * tau_lo * t32 * t30 + T(3) * (T(2) * J2 + T(2) * b * t32 * t30 - t25 * c * t22) * t33 * t30 + T(2) * t26 * t34 - T(2) * t35 * t27);
  }
  const T t36 = T(1) / ab_ab;
  const T t37 = T(1) / a;
  const T foot_offset = t36 * (ab_ap * delta_tau + ab_ab * tau_lo) * delta_tau * t37 * sigma2;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  const T g_factor = -T(4) * length * sigma2 * sigma2;
  grad[0] = (foot_h0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot_h1 * G_ap);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 85 +, 191 ×, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 40149 +, 53108 ×, 6726 /, 182 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
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
    foot0 = (exact_cross[1] * ab2 - ab1 * exact_cross[2]) * t2;
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * t2;
    foot2 = -t2 * (ab0 * exact_cross[1] - exact_cross[0] * ab1);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t4 * tau_lo;
    const T t9 = t3 * delta_tau;
    F = T(3) * M_panels[1] * delta_tau * t4 + T(3) * t3 * tau_lo * M_panels[2] + t8 * M_panels[0] + t9 * M_panels[3];
    const T t10 = t8 * M_panels[5] + T(3) * M_panels[7] * t3 * tau_lo + T(3) * delta_tau * t4 * M_panels[6] + t9 * M_panels[8];
    G_ap = t10;
    const T t11 = T(1) / a;
    G_E = T(3) * M_panels[7] * delta_tau * t4 + t9 * M_panels[9] + T(3) * t3 * M_panels[8] * tau_lo + t8 * M_panels[6] - t10 * t11 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t3 * delta_tau;
    const T t13 = t4 * tau_lo;
    F = T(3) * delta_tau * t4 * M_panels[1] + M_panels[3] * t12 + M_panels[0] * t13 + T(3) * t3 * tau_lo * M_panels[2];
    G_ap = T(3) * M_panels[6] * delta_tau * t4 + t13 * M_panels[5] + t12 * M_panels[8] + T(3) * M_panels[7] * t3 * tau_lo;
    const T t14 = T(1) / a;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = T(3) * delta_tau * t4 + T(3) * t3 * tau_lo + t13 + t12;
    G_E = (T(1) / T(4)) * t14 * (t16 * t13 + T(3) * t12 * M_panels[2] + T(6) * t3 * tau_lo * M_panels[1] + T(3) * M_panels[0] * delta_tau * t4 - t18 * t19);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(D);
    const T t21 = T(1) / t20;
    const T J2 = t21 * atan2(t20, c_minus_b);
    const T t22 = T(1) / c;
    const T log_ratio = log(q1 * t22);
    const T t23 = t3 * delta_tau;
    const T t24 = T(1) / a;
    const T t25 = T(1) / q1;
    const T t26 = T(1) / D;
    const T t27 = J2 * a + t22 * b + t25 * a_minus_b;
    const T t28 = t25 - t22 - t26 * t27 * b;
    const T t29 = c * t26 * t27 + T(2) * t24 * t28 * b - T(2) * J2;
    const T t30 = t4 * tau_lo;
    F = (T(1) / T(2)) * t23 * t24 * (c * t24 * t28 + (T(2) * J2 * b + log_ratio) * t24 - T(2) * t29 * t24 * b) + (T(1) / T(2)) * t30 * t26 * t27 - (T(3) / T(2)) * delta_tau * t4 * t24 * t28 - (T(3) / T(2)) * t29 * t3 * tau_lo * t24;
    const T t31 = t25 * t25;
    const T t32 = t22 * t22;
    const T t33 = T(3) * t26 * t27 * a + T(2) * t31 * a_minus_b + T(2) * t32 * b;
    const T t34 = T(2) * t32 + t33 * t26 * b - T(2) * t31;
    const T t35 = t33 * c * t26 - T(4) * t26 * t27 - T(2) * t34 * t24 * b;
    G_ap = (T(1) / T(8)) * t33 * t30 * t26 + (T(3) / T(8)) * t34 * delta_tau * t4 * t24 - (T(3) / T(8)) * t35 * t3 * tau_lo * t24 - (T(1) / T(8)) * t23 * (t34 * c * t24 + T(4) * t24 * t28 + T(2) * t35 * t24 * b) * t24;
    const T t36 = T(3) * delta_tau * t4 + T(3) * t3 * tau_lo + t30 + t23;
    G_E = (T(1) / T(8)) * (T(3) * delta_tau * t4 * t26 * t27 + T(2) * t32 * t30 - T(6) * t3 * tau_lo * t24 * t28 - T(2) * t31 * t36 - T(3) * t29 * t23 * t24) * t24;
  }
  const T t37 = T(1) / a;
  const T t38 = T(1) / ab_ab;
  const T foot_offset = delta_tau * (tau_lo * ab_ab + ab_ap * delta_tau) * t37 * sigma2 * t38;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  const T t39 = sigma2 * sigma2;
  const T g_factor = -T(4) * length * t39;
  f = length * t39 * F;
  grad[0] = g_factor * (G_ap * foot_h0 - ab0 * G_E);
  grad[1] = -(G_E * ab1 - G_ap * foot_h1) * g_factor;
  grad[2] = (G_ap * foot_h2 - G_E * ab2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 62 +, 133 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 31698 +, 50456 ×, 8054 /, 3492 sqrt, 0 atan, 1 log/asinh.
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
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
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
    X = t4 * t5 * (t6 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = b * r1;
    X = (b - a_minus_b) * t7 / (t8 - a_minus_b * r0);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * t1;
    const T t15 = t2 * t2;
    const T t16 = t1 * delta_tau;
    const T t17 = t2 * tau_lo;
    F = M_panels[4] * t14 + M_panels[0] * t15 + T(6) * t1 * t2 * M_panels[2] + T(4) * M_panels[3] * t16 * tau_lo + T(4) * M_panels[1] * delta_tau * t17;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t1 * delta_tau;
    const T t19 = t2 * t2;
    const T t20 = t1 * t1;
    const T t21 = t2 * tau_lo;
    F = T(4) * t18 * tau_lo * M_panels[3] + t19 * M_panels[0] + T(6) * M_panels[2] * t1 * t2 + M_panels[4] * t20 + T(4) * M_panels[1] * delta_tau * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / D;
    const T t23 = t2 * t2;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = T(1) / r0;
    const T t27 = b * t26 + t24 * a_minus_b;
    const T t28 = t26 * t26;
    const T t29 = t24 * a_minus_b * t25 + T(2) * t27 * t22 * a + b * t28 * t26;
    const T t30 = T(1) / a;
    const T t31 = b * t22 * t29 + t28 * t26 - t24 * t25;
    const T t32 = T(3) * t27 * t22 + T(2) * b * t30 * t31 - c * t22 * t29;
    const T t33 = t2 * tau_lo;
    const T t34 = t26 + b * t27 * t22 - t24;
    const T t35 = c * t30 * t31 - T(3) * t30 * t34 - T(2) * b * t32 * t30;
    const T t36 = t1 * delta_tau;
    const T t37 = t1 * t1;
    F = (T(1) / T(3)) * t22 * t23 * t29 + T(2) * t32 * t1 * t2 * t30 + (T(4) / T(3)) * delta_tau * t33 * t30 * t31 - (T(4) / T(3)) * t35 * t36 * tau_lo * t30 - (T(1) / T(3)) * (t32 * c * t30 + T(3) * (t27 * c * t22 - J1 - T(2) * b * t30 * t34) * t30 + T(2) * b * t35 * t30) * t37 * t30;
  }
  f = in.sigma * length * sigma2 * sigma2 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 86 +, 210 ×, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 50956 +, 78088 ×, 7251 /, 3239 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
    foot2 = ap2 - t1 * ab2 * ab_ap;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = -t2 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = t2 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t3;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t3 * t3;
    const T t10 = t4 * tau_lo;
    const T t11 = t4 * t4;
    const T t12 = T(4) * tau_lo * M_panels[9] * t8 + M_panels[10] * t9 + T(6) * t4 * M_panels[8] * t3 + T(4) * t10 * M_panels[7] * delta_tau + t11 * M_panels[6];
    G_ap = t12;
    const T t13 = T(1) / a;
    G_E = M_panels[11] * t9 + t11 * M_panels[7] + T(4) * t10 * M_panels[8] * delta_tau + T(6) * t4 * M_panels[9] * t3 + T(4) * M_panels[10] * tau_lo * t8 - t13 * b * t12;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t3 * t3;
    const T t15 = t4 * t4;
    const T t16 = t4 * tau_lo;
    const T t17 = t3 * delta_tau;
    G_ap = M_panels[10] * t14 + t15 * M_panels[6] + T(4) * t16 * M_panels[7] * delta_tau + T(4) * tau_lo * M_panels[9] * t17 + T(6) * t4 * M_panels[8] * t3;
    const T t18 = T(1) / a;
    const T t19 = t14 + T(6) * t4 * t3 + T(4) * t16 * delta_tau + T(4) * tau_lo * t17 + t15;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t20;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t24;
    G_E = -(T(1) / T(5)) * t18 * (t19 * t23 - T(12) * tau_lo * M_panels[2] * t17 - t15 * t27 - T(4) * M_panels[3] * t14 - T(4) * t16 * M_panels[0] * delta_tau - T(12) * t4 * M_panels[1] * t3);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t28 = T(1) / a;
    const T t29 = T(1) / D;
    const T t30 = T(1) / r0;
    const T t31 = T(1) / r1;
    const T t32 = b * t30 + t31 * a_minus_b;
    const T t33 = t30 * t30;
    const T t34 = t31 * t31;
    const T t35 = T(2) * t29 * a * t32 + t34 * t31 * a_minus_b + b * t30 * t33;
    const T t36 = t30 * t33 + t29 * b * t35 - t34 * t31;
    const T t37 = T(3) * t29 * t32 + T(2) * t28 * b * t36 - t29 * c * t35;
    const T t38 = t33 * t33;
    const T t39 = t34 * t34;
    const T t40 = T(3) * b * t30 * t38 + T(4) * t29 * a * t35 + T(3) * t39 * t31 * a_minus_b;
    const T t41 = t29 * b * t40 + T(3) * t30 * t38 - T(3) * t39 * t31;
    const T t42 = t29 * t40 * c - T(2) * t28 * t41 * b - T(5) * t29 * t35;
    const T t43 = T(5) * t28 * t36 - t28 * t41 * c - T(2) * t28 * t42 * b;
    const T t44 = t3 * t3;
    const T t45 = t4 * tau_lo;
    const T t46 = t4 * t4;
    const T t47 = t3 * delta_tau;
    G_ap = (T(1) / T(15)) * t28 * (T(5) * t28 * t37 + t28 * t42 * c + T(2) * t28 * b * t43) * t44 + (T(4) / T(15)) * t45 * t28 * t41 * delta_tau + (T(1) / T(15)) * t46 * t29 * t40 + (T(4) / T(15)) * tau_lo * t28 * t43 * t47 - (T(2) / T(5)) * t4 * t28 * t42 * t3;
    const T t48 = t44 + T(6) * t4 * t3 + T(4) * t45 * delta_tau + T(4) * tau_lo * t47 + t46;
    const T t49 = t31 * t31;
    const T t50 = t49 * t49;
    const T t51 = t50 * t31;
    const T t52 = t30 * t30;
    const T t53 = t52 * t52;
    const T t54 = t53 * t30;
    G_E = -(T(1) / T(15)) * t28 * (T(4) * t28 * (t28 * c * t36 + T(3) * t28 * (t31 - t30 - t29 * b * t32) - T(2) * t28 * t37 * b) * t44 + T(3) * t48 * t51 - T(4) * t45 * t29 * t35 * delta_tau - T(3) * t46 * t54 - T(12) * tau_lo * t28 * t37 * t47 - T(12) * t4 * t28 * t3 * t36);
  }
  const T t55 = T(1) / a;
  const T t56 = T(1) / ab_ab;
  const T foot_offset = t55 * sigma2 * (tau_lo * ab_ab + ab_ap * delta_tau) * t56 * delta_tau;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  const T g_factor = -T(5) * sigma2 * sigma2 * in.sigma * length;
  grad[0] = -(ab0 * G_E - G_ap * foot_h0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot_h1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot_h2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 95 +, 249 ×, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 50961 +, 78108 ×, 7253 /, 3241 sqrt, 0 atan, 1 log/asinh.
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
    foot0 = -t2 * (exact_cross[2] * ab1 - ab2 * exact_cross[1]);
    foot1 = -t2 * (ab2 * exact_cross[0] - exact_cross[2] * ab0);
    foot2 = t2 * (ab1 * exact_cross[0] - ab0 * exact_cross[1]);
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + delta_tau * ap1;
  const T radial2 = ab2 * tau_lo + delta_tau * ap2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t5 = a_minus_b * b;
  if (t5 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t6 = a_minus_b * r0;
    const T t7 = T(1) / D;
    const T t8 = sqrt(a);
    X = (t6 + b * r1) * t7 * t8;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t9 = sqrt(a);
    const T t10 = a_minus_b * r0;
    X = (a_minus_b - b) * t9 / (t10 - b * r1);
  }
  const T t11 = sqrt(a);
  const T t12 = T(1) / t11;
  const T J1 = asinh(X) * t12;
  T F;
  T G_ap;
  T G_E;
  const T t13 = T(4) * D - a * a;
  const T t14 = -a_minus_b * b;
  const T t15 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t13 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t3 * t3;
    const T t17 = t4 * t4;
    const T t18 = t4 * tau_lo;
    const T t19 = t3 * delta_tau;
    F = T(6) * t3 * M_panels[2] * t4 + M_panels[4] * t16 + t17 * M_panels[0] + T(4) * M_panels[1] * delta_tau * t18 + T(4) * t19 * tau_lo * M_panels[3];
    const T t20 = T(4) * M_panels[7] * delta_tau * t18 + T(6) * M_panels[8] * t3 * t4 + t17 * M_panels[6] + T(4) * t19 * tau_lo * M_panels[9] + M_panels[10] * t16;
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = M_panels[11] * t16 + M_panels[7] * t17 + T(4) * M_panels[10] * t19 * tau_lo + T(4) * M_panels[8] * delta_tau * t18 + T(6) * t3 * t4 * M_panels[9] - b * t20 * t21;
  } else if (t14 >= T(0) && t15 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t4 * tau_lo;
    const T t23 = t4 * t4;
    const T t24 = t3 * delta_tau;
    const T t25 = t3 * t3;
    F = T(4) * delta_tau * t22 * M_panels[1] + t23 * M_panels[0] + T(6) * M_panels[2] * t3 * t4 + T(4) * t24 * M_panels[3] * tau_lo + t25 * M_panels[4];
    G_ap = T(4) * delta_tau * t22 * M_panels[7] + T(4) * M_panels[9] * t24 * tau_lo + M_panels[6] * t23 + t25 * M_panels[10] + T(6) * M_panels[8] * t3 * t4;
    const T t26 = T(4) * delta_tau * t22 + t23 + T(4) * t24 * tau_lo + T(6) * t3 * t4 + t25;
    const T t27 = T(1) / r1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t27;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t31;
    const T t35 = T(1) / a;
    G_E = -(T(1) / T(5)) * (t26 * t30 - T(4) * t25 * M_panels[3] - T(12) * M_panels[2] * t24 * tau_lo - T(12) * t3 * t4 * M_panels[1] - T(4) * delta_tau * t22 * M_panels[0] - t34 * t23) * t35;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t36 = T(1) / r1;
    const T t37 = T(1) / r0;
    const T t38 = a_minus_b * t36 + b * t37;
    const T t39 = T(1) / D;
    const T t40 = t37 * t37;
    const T t41 = t36 * t36;
    const T t42 = T(2) * t38 * t39 * a + b * t40 * t37 + a_minus_b * t41 * t36;
    const T t43 = t4 * t4;
    const T t44 = t40 * t37 + b * t42 * t39 - t41 * t36;
    const T t45 = t4 * tau_lo;
    const T t46 = T(1) / a;
    const T t47 = c * t42 * t39 - T(3) * t38 * t39 - T(2) * t44 * b * t46;
    const T t48 = t38 * b * t39 + t37 - t36;
    const T t49 = t44 * c * t46 + T(2) * b * t47 * t46 - T(3) * t48 * t46;
    const T t50 = t3 * t3;
    const T t51 = t3 * delta_tau;
    F = (T(1) / T(3)) * t42 * t43 * t39 + (T(4) / T(3)) * t44 * delta_tau * t45 * t46 + (T(1) / T(3)) * (c * t47 * t46 - T(3) * (t38 * c * t39 - J1 - T(2) * b * t48 * t46) * t46 - T(2) * b * t49 * t46) * t50 * t46 - T(2) * t3 * t47 * t4 * t46 - (T(4) / T(3)) * t51 * tau_lo * t49 * t46;
    const T t52 = t41 * t41;
    const T t53 = t40 * t40;
    const T t54 = T(3) * a_minus_b * t52 * t36 + T(3) * b * t53 * t37 + T(4) * t42 * t39 * a;
    const T t55 = b * t54 * t39 + T(3) * t53 * t37 - T(3) * t52 * t36;
    const T t56 = T(5) * t42 * t39 + T(2) * b * t55 * t46 - t54 * c * t39;
    const T t57 = T(5) * t44 * t46 + T(2) * b * t56 * t46 - c * t55 * t46;
    G_ap = (T(1) / T(15)) * t54 * t43 * t39 + (T(4) / T(15)) * delta_tau * t45 * t55 * t46 + (T(2) / T(5)) * t3 * t56 * t4 * t46 + (T(4) / T(15)) * t57 * t51 * tau_lo * t46 - (T(1) / T(15)) * t50 * (T(5) * t47 * t46 + c * t56 * t46 - T(2) * b * t57 * t46) * t46;
    const T t58 = T(4) * delta_tau * t45 + t43 + T(4) * t51 * tau_lo + T(6) * t3 * t4 + t50;
    const T t59 = t36 * t36;
    const T t60 = t59 * t59;
    const T t61 = t60 * t36;
    const T t62 = t37 * t37;
    const T t63 = t62 * t62;
    const T t64 = t63 * t37;
    G_E = -(T(1) / T(15)) * (T(3) * t58 * t61 + T(12) * t51 * t47 * tau_lo * t46 + T(4) * t50 * t49 * t46 - T(4) * delta_tau * t42 * t45 * t39 - T(3) * t64 * t43 - T(12) * t44 * t3 * t4 * t46) * t46;
  }
  const T t65 = T(1) / ab_ab;
  const T t66 = T(1) / a;
  const T foot_offset = t65 * delta_tau * (ab_ap * delta_tau + ab_ab * tau_lo) * t66 * sigma2;
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = foot1 + ab1 * foot_offset;
  const T foot_h2 = ab2 * foot_offset + foot2;
  const T t67 = sigma2 * sigma2;
  const T g_factor = -T(5) * in.sigma * length * t67;
  f = F * in.sigma * length * t67;
  grad[0] = g_factor * (G_ap * foot_h0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot_h1 * G_ap);
  grad[2] = (G_ap * foot_h2 - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 71 +, 157 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 37711 +, 51314 ×, 8420 /, 182 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t1;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t2 = tau_lo * tau_lo;
  const T c = sigma2 * t2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_hi * sigma2 * tau_lo + ap_bp;
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t2 * t2;
    const T t7 = t1 * t1;
    const T t8 = t6 * tau_lo;
    const T t9 = t7 * delta_tau;
    const T t10 = t1 * delta_tau;
    const T t11 = t2 * tau_lo;
    F = T(5) * M_panels[1] * t6 * delta_tau + T(5) * M_panels[4] * tau_lo * t7 + M_panels[0] * t8 + t9 * M_panels[5] + T(10) * M_panels[3] * t2 * t10 + T(10) * t11 * M_panels[2] * t1;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t1 * t1;
    const T t13 = t2 * t2;
    const T t14 = t2 * tau_lo;
    const T t15 = t12 * delta_tau;
    const T t16 = t13 * tau_lo;
    const T t17 = t1 * delta_tau;
    F = T(5) * M_panels[4] * tau_lo * t12 + T(5) * M_panels[1] * t13 * delta_tau + T(10) * M_panels[2] * t14 * t1 + M_panels[5] * t15 + M_panels[0] * t16 + T(10) * M_panels[3] * t2 * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = atan2(t18, c_minus_b) * t19;
    const T t20 = T(1) / c;
    const T log_ratio = log(q1 * t20);
    const T t21 = T(1) / q1;
    const T t22 = T(1) / D;
    const T t23 = t21 * a_minus_b + b * t20 + J2 * a;
    const T t24 = t21 - t20 - b * t22 * t23;
    const T t25 = T(1) / a;
    const T t26 = t20 * t20;
    const T t27 = t21 * t21;
    const T t28 = T(3) * t22 * t23 * a + T(2) * b * t26 + T(2) * t27 * a_minus_b;
    const T t29 = b * t22 * t28 + T(2) * t26 - T(2) * t27;
    const T t30 = t22 * c * t28 - T(2) * t29 * b * t25 - T(4) * t22 * t23;
    const T t31 = T(4) * t24 * t25 + t29 * c * t25 + T(2) * t30 * b * t25;
    const T t32 = t22 * c * t23 + T(2) * b * t24 * t25 - T(2) * J2;
    const T t33 = T(4) * t32 * t25 + T(2) * b * t31 * t25 - t30 * c * t25;
    const T t34 = t1 * t1;
    const T t35 = t34 * delta_tau;
    const T t36 = t2 * t2;
    const T t37 = t36 * tau_lo;
    const T t38 = t1 * delta_tau;
    const T t39 = t2 * tau_lo;
    F = (T(1) / T(8)) * (c * t31 * t25 - T(4) * (T(2) * b * t32 * t25 - t24 * c * t25 - (T(2) * b * J2 + log_ratio) * t25) * t25 - T(2) * b * t33 * t25) * t35 * t25 + (T(1) / T(8)) * t22 * t28 * t37 + (T(5) / T(8)) * t29 * t36 * delta_tau * t25 - (T(5) / T(4)) * t31 * t2 * t38 * t25 - (T(5) / T(4)) * t30 * t39 * t1 * t25 - (T(5) / T(8)) * t33 * tau_lo * t34 * t25;
  }
  const T t40 = sigma2 * sigma2;
  const T t41 = t40 * sigma2;
  f = t41 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 99 +, 239 ×, 8 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 49722 +, 65301 ×, 6311 /, 137 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (ab2 * exact_cross[1] - exact_cross[2] * ab1);
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t3 * t3;
    const T t10 = t9 * delta_tau;
    const T t11 = t4 * t4;
    const T t12 = t4 * tau_lo;
    const T t13 = t11 * tau_lo;
    const T t14 = T(10) * t8 * t4 * M_panels[10] + M_panels[12] * t10 + T(5) * M_panels[8] * delta_tau * t11 + T(10) * t3 * M_panels[9] * t12 + T(5) * M_panels[11] * t9 * tau_lo + t13 * M_panels[7];
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(10) * M_panels[11] * t8 * t4 + T(5) * M_panels[12] * t9 * tau_lo + M_panels[8] * t13 + T(10) * t3 * t12 * M_panels[10] + t10 * M_panels[13] + T(5) * delta_tau * M_panels[9] * t11 - t14 * t15 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t4 * t4;
    const T t17 = t16 * tau_lo;
    const T t18 = t3 * delta_tau;
    const T t19 = t3 * t3;
    const T t20 = t19 * delta_tau;
    const T t21 = t4 * tau_lo;
    G_ap = M_panels[7] * t17 + T(5) * delta_tau * t16 * M_panels[8] + T(10) * M_panels[10] * t18 * t4 + t20 * M_panels[12] + T(10) * M_panels[9] * t3 * t21 + T(5) * t19 * tau_lo * M_panels[11];
    const T t22 = T(1) / a;
    const T t23 = T(1) / c;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(1) / q1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = T(5) * t19 * tau_lo + T(5) * delta_tau * t16 + T(10) * t3 * t21 + t20 + T(10) * t18 * t4 + t17;
    G_E = (T(1) / T(6)) * t22 * (T(5) * M_panels[4] * t20 + T(20) * M_panels[1] * t3 * t21 + T(30) * t18 * t4 * M_panels[2] + t25 * t17 + T(20) * M_panels[3] * t19 * tau_lo + T(5) * M_panels[0] * delta_tau * t16 - t28 * t29);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = atan2(t30, c_minus_b) * t31;
    const T t32 = t4 * t4;
    const T t33 = t32 * tau_lo;
    const T t34 = T(1) / D;
    const T t35 = T(1) / c;
    const T t36 = T(1) / q1;
    const T t37 = J2 * a + t35 * b + a_minus_b * t36;
    const T t38 = t36 * t36;
    const T t39 = t35 * t35;
    const T t40 = T(3) * t37 * t34 * a + T(2) * a_minus_b * t38 + T(2) * t39 * b;
    const T t41 = t38 * t36;
    const T t42 = t39 * t35;
    const T t43 = T(5) * t40 * t34 * a + T(8) * a_minus_b * t41 + T(8) * t42 * b;
    const T t44 = t34 * t43 * b + T(8) * t42 - T(8) * t41;
    const T t45 = T(1) / a;
    const T t46 = T(6) * t40 * t34 + T(2) * t44 * t45 * b - c * t34 * t43;
    const T t47 = t4 * tau_lo;
    const T t48 = t40 * t34 * b + T(2) * t39 - T(2) * t38;
    const T t49 = T(6) * t45 * t48 + T(2) * t46 * t45 * b - c * t44 * t45;
    const T t50 = t3 * delta_tau;
    const T t51 = t3 * t3;
    const T t52 = t40 * c * t34 - T(2) * t45 * t48 * b - T(4) * t37 * t34;
    const T t53 = T(6) * t52 * t45 + c * t46 * t45 - T(2) * t49 * t45 * b;
    const T t54 = t36 - t37 * t34 * b - t35;
    const T t55 = c * t45 * t48 + T(4) * t54 * t45 + T(2) * t52 * t45 * b;
    const T t56 = t51 * delta_tau;
    G_ap = (T(1) / T(48)) * t33 * t34 * t43 + (T(5) / T(24)) * t46 * t3 * t47 * t45 + (T(5) / T(24)) * t49 * t50 * t4 * t45 + (T(5) / T(48)) * t44 * delta_tau * t32 * t45 - (T(5) / T(48)) * t51 * tau_lo * t45 * t53 - (T(1) / T(48)) * (T(2) * t45 * b * t53 + T(6) * t45 * t55 + c * t49 * t45) * t56 * t45;
    const T t57 = T(5) * t51 * tau_lo + T(5) * delta_tau * t32 + T(10) * t3 * t47 + t56 + T(10) * t50 * t4 + t33;
    G_E = -(T(1) / T(48)) * (T(30) * t52 * t50 * t4 * t45 + T(20) * t51 * tau_lo * t45 * t55 + T(8) * t41 * t57 + T(5) * (T(2) * t45 * t55 * b - T(4) * (T(2) * J2 - T(2) * t54 * t45 * b - t37 * c * t34) * t45 - t52 * c * t45) * t56 * t45 - T(5) * t40 * delta_tau * t32 * t34 - T(20) * t3 * t47 * t45 * t48 - T(8) * t42 * t33) * t45;
  }
  const T t58 = T(1) / ab_ab;
  const T t59 = T(1) / a;
  const T foot_offset = t58 * delta_tau * (ab_ab * tau_lo + ab_ap * delta_tau) * t59 * sigma2;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  const T t60 = sigma2 * sigma2;
  const T t61 = t60 * sigma2;
  const T g_factor = -T(6) * length * t61;
  grad[0] = (foot_h0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = g_factor * (foot_h1 * G_ap - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 109 +, 279 ×, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 49727 +, 65317 ×, 6311 /, 137 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
    foot0 = -t2 * (exact_cross[2] * ab1 - exact_cross[1] * ab2);
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * t2;
    foot2 = t2 * (ab1 * exact_cross[0] - exact_cross[1] * ab0);
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t3;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t3 * t3;
    const T t10 = t9 * delta_tau;
    const T t11 = t4 * t4;
    const T t12 = t11 * tau_lo;
    const T t13 = t4 * tau_lo;
    F = T(10) * t4 * M_panels[3] * t8 + t10 * M_panels[5] + T(5) * tau_lo * M_panels[4] * t9 + t12 * M_panels[0] + T(10) * t13 * M_panels[2] * t3 + T(5) * t11 * M_panels[1] * delta_tau;
    const T t14 = T(10) * t4 * M_panels[10] * t8 + T(10) * t13 * M_panels[9] * t3 + t12 * M_panels[7] + T(5) * tau_lo * M_panels[11] * t9 + M_panels[12] * t10 + T(5) * t11 * M_panels[8] * delta_tau;
    G_ap = t14;
    const T t15 = T(1) / a;
    G_E = T(10) * t4 * M_panels[11] * t8 + M_panels[13] * t10 + t12 * M_panels[8] + T(10) * t13 * M_panels[10] * t3 + T(5) * tau_lo * M_panels[12] * t9 + T(5) * t11 * M_panels[9] * delta_tau - t15 * b * t14;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t3 * delta_tau;
    const T t17 = t3 * t3;
    const T t18 = t4 * tau_lo;
    const T t19 = t4 * t4;
    const T t20 = t17 * delta_tau;
    const T t21 = t19 * tau_lo;
    F = T(10) * t4 * M_panels[3] * t16 + T(5) * tau_lo * M_panels[4] * t17 + T(10) * t18 * M_panels[2] * t3 + T(5) * t19 * M_panels[1] * delta_tau + M_panels[5] * t20 + t21 * M_panels[0];
    G_ap = T(10) * t18 * M_panels[9] * t3 + M_panels[12] * t20 + T(10) * t4 * t16 * M_panels[10] + T(5) * tau_lo * M_panels[11] * t17 + t21 * M_panels[7] + T(5) * t19 * M_panels[8] * delta_tau;
    const T t22 = T(1) / a;
    const T t23 = T(1) / c;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(10) * t18 * t3 + t20 + T(5) * tau_lo * t17 + T(10) * t4 * t16 + T(5) * t19 * delta_tau + t21;
    const T t27 = T(1) / q1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    G_E = (T(1) / T(6)) * t22 * (T(20) * tau_lo * M_panels[3] * t17 + t21 * t25 + T(5) * M_panels[4] * t20 + T(20) * t18 * M_panels[1] * t3 + T(5) * t19 * M_panels[0] * delta_tau + T(30) * t4 * M_panels[2] * t16 - t26 * t29);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = sqrt(D);
    const T t31 = T(1) / t30;
    const T J2 = atan2(t30, c_minus_b) * t31;
    const T t32 = T(1) / c;
    const T log_ratio = log(q1 * t32);
    const T t33 = T(1) / a;
    const T t34 = T(1) / q1;
    const T t35 = a_minus_b * t34 + b * t32 + a * J2;
    const T t36 = T(1) / D;
    const T t37 = t32 * t32;
    const T t38 = t34 * t34;
    const T t39 = T(2) * b * t37 + T(2) * a_minus_b * t38 + T(3) * a * t35 * t36;
    const T t40 = T(2) * t37 + t39 * b * t36 - T(2) * t38;
    const T t41 = T(4) * t35 * t36 + T(2) * t33 * b * t40 - t39 * c * t36;
    const T t42 = t34 - t35 * b * t36 - t32;
    const T t43 = T(2) * t33 * b * t41 - T(4) * t33 * t42 - t33 * c * t40;
    const T t44 = T(2) * t33 * b * t42 + t35 * c * t36 - T(2) * J2;
    const T t45 = T(2) * t43 * t33 * b - t33 * t41 * c - T(4) * t33 * t44;
    const T t46 = t3 * t3;
    const T t47 = t46 * delta_tau;
    const T t48 = t4 * t4;
    const T t49 = t3 * delta_tau;
    const T t50 = t48 * tau_lo;
    const T t51 = t4 * tau_lo;
    F = (T(1) / T(8)) * t33 * (T(2) * t33 * t45 * b + T(4) * t33 * (t33 * (log_ratio + T(2) * b * J2) + t33 * c * t42 - T(2) * t33 * t44 * b) - t43 * t33 * c) * t47 + (T(5) / T(8)) * t48 * t33 * t40 * delta_tau + (T(5) / T(4)) * t43 * t4 * t33 * t49 + (T(1) / T(8)) * t50 * t39 * t36 + (T(5) / T(8)) * tau_lo * t33 * t45 * t46 + (T(5) / T(4)) * t51 * t33 * t41 * t3;
    const T t52 = t37 * t32;
    const T t53 = t38 * t34;
    const T t54 = T(8) * b * t52 + T(8) * a_minus_b * t53 + T(5) * a * t39 * t36;
    const T t55 = T(8) * t52 + b * t36 * t54 - T(8) * t53;
    const T t56 = T(6) * t39 * t36 + T(2) * t33 * b * t55 - c * t36 * t54;
    const T t57 = T(2) * t33 * t56 * b + T(6) * t33 * t40 - t33 * c * t55;
    const T t58 = T(6) * t33 * t41 + T(2) * t33 * t57 * b - t33 * t56 * c;
    G_ap = (T(5) / T(48)) * t48 * t33 * t55 * delta_tau + (T(5) / T(24)) * t51 * t33 * t56 * t3 + (T(1) / T(48)) * t50 * t36 * t54 + (T(1) / T(48)) * t33 * (T(2) * t33 * b * t58 + T(6) * t43 * t33 - t33 * t57 * c) * t47 + (T(5) / T(24)) * t4 * t33 * t57 * t49 + (T(5) / T(48)) * tau_lo * t33 * t58 * t46;
    const T t59 = T(10) * t51 * t3 + t47 + T(5) * tau_lo * t46 + T(10) * t4 * t49 + T(5) * t48 * delta_tau + t50;
    G_E = (T(1) / T(48)) * (T(8) * t50 * t52 + T(20) * t43 * tau_lo * t33 * t46 + T(5) * t48 * t39 * t36 * delta_tau + T(5) * t33 * t45 * t47 + T(30) * t4 * t33 * t41 * t49 + T(20) * t51 * t33 * t40 * t3 - T(8) * t59 * t53) * t33;
  }
  const T t60 = T(1) / a;
  const T t61 = T(1) / ab_ab;
  const T foot_offset = t60 * (ab_ap * delta_tau + tau_lo * ab_ab) * sigma2 * t61 * delta_tau;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  const T t62 = sigma2 * sigma2;
  const T t63 = t62 * sigma2;
  const T g_factor = -T(6) * t63 * length;
  f = F * t63 * length;
  grad[0] = (G_ap * foot_h0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot_h1) * g_factor;
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 78 +, 196 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 35540 +, 59571 ×, 7247 /, 3241 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = delta_tau * ap2 + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
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
    const T t6 = a_minus_b * r0;
    X = t4 * t5 * (t6 + b * r1);
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
  const T t13 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t2 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t1 * t1;
    const T t17 = t16 * delta_tau;
    const T t18 = t1 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t2 * t2;
    const T t21 = t20 * tau_lo;
    F = M_panels[0] * t15 + T(6) * t17 * tau_lo * M_panels[5] + M_panels[6] * t19 + T(6) * delta_tau * M_panels[1] * t21 + T(20) * M_panels[3] * t18 * t14 + T(15) * t1 * t20 * M_panels[2] + T(15) * M_panels[4] * t16 * t2;
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t1 * delta_tau;
    const T t23 = t2 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t2 * t2;
    const T t26 = t23 * t23;
    const T t27 = t1 * t1;
    const T t28 = t27 * delta_tau;
    const T t29 = t25 * tau_lo;
    F = T(20) * M_panels[3] * t22 * t23 + M_panels[6] * t24 + T(15) * t1 * t25 * M_panels[2] + M_panels[0] * t26 + T(15) * t27 * t2 * M_panels[4] + T(6) * M_panels[5] * t28 * tau_lo + T(6) * delta_tau * t29 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t30 = T(1) / a;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = T(1) / r1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t35;
    const T t37 = b * t31 + a_minus_b * t34;
    const T t38 = T(1) / D;
    const T t39 = T(2) * t37 * t38 * a + a_minus_b * t34 * t35 + b * t32 * t31;
    const T t40 = T(3) * b * t33 * t31 + T(3) * a_minus_b * t34 * t36 + T(4) * t39 * t38 * a;
    const T t41 = T(3) * t33 * t31 + b * t40 * t38 - T(3) * t34 * t36;
    const T t42 = c * t40 * t38 - T(5) * t39 * t38 - T(2) * b * t41 * t30;
    const T t43 = t34 * t35 - b * t39 * t38 - t32 * t31;
    const T t44 = T(2) * b * t43 * t30 + t39 * c * t38 - T(3) * t37 * t38;
    const T t45 = T(5) * t43 * t30 + t41 * c * t30 + T(2) * b * t30 * t42;
    const T t46 = c * t30 * t42 - T(5) * t44 * t30 - T(2) * b * t45 * t30;
    const T t47 = t1 * t1;
    const T t48 = t34 - b * t37 * t38 - t31;
    const T t49 = T(2) * b * t44 * t30 + T(3) * t48 * t30 - t43 * c * t30;
    const T t50 = c * t45 * t30 + T(2) * b * t46 * t30 - T(5) * t30 * t49;
    const T t51 = t47 * delta_tau;
    const T t52 = t2 * tau_lo;
    const T t53 = t52 * t52;
    const T t54 = t2 * t2;
    const T t55 = t54 * tau_lo;
    const T t56 = t1 * delta_tau;
    const T t57 = t56 * t56;
    F = t46 * t47 * t2 * t30 + (T(2) / T(5)) * t50 * t51 * tau_lo * t30 + (T(1) / T(15)) * t53 * t40 * t38 + (T(2) / T(5)) * t41 * delta_tau * t55 * t30 - t1 * t54 * t30 * t42 - (T(4) / T(3)) * t45 * t56 * t52 * t30 - (T(1) / T(15)) * (t46 * c * t30 + T(5) * (T(3) * (t37 * c * t38 + T(2) * b * t48 * t30 - J1) * t30 + T(2) * b * t30 * t49 - c * t44 * t30) * t30 - T(2) * b * t50 * t30) * t57 * t30;
  }
  const T t58 = sigma2 * sigma2;
  const T t59 = t58 * sigma2;
  f = in.sigma * length * t59 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 108 +, 298 ×, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48932 +, 74681 ×, 5606 /, 2504 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t4 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t3 * delta_tau;
    const T t11 = t3 * t3;
    const T t12 = t4 * t4;
    const T t13 = t12 * tau_lo;
    const T t14 = t11 * delta_tau;
    const T t15 = t10 * t10;
    const T t16 = t9 * M_panels[8] + T(20) * t10 * t8 * M_panels[11] + T(15) * M_panels[12] * t11 * t4 + T(6) * M_panels[9] * delta_tau * t13 + T(6) * t14 * tau_lo * M_panels[13] + t15 * M_panels[14] + T(15) * t3 * t12 * M_panels[10];
    G_ap = t16;
    const T t17 = T(1) / a;
    G_E = t15 * M_panels[15] + T(6) * delta_tau * t13 * M_panels[10] + T(6) * t14 * tau_lo * M_panels[14] + T(15) * t3 * t12 * M_panels[11] + T(15) * t11 * t4 * M_panels[13] + M_panels[9] * t9 + T(20) * M_panels[12] * t10 * t8 - t17 * t16 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t18 = t3 * t3;
    const T t19 = t4 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t3 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t4 * t4;
    const T t24 = t23 * tau_lo;
    const T t25 = t18 * delta_tau;
    G_ap = T(15) * M_panels[12] * t18 * t4 + t20 * M_panels[8] + t22 * M_panels[14] + T(6) * M_panels[9] * delta_tau * t24 + T(6) * t25 * tau_lo * M_panels[13] + T(15) * t3 * t23 * M_panels[10] + T(20) * t21 * t19 * M_panels[11];
    const T t26 = T(1) / a;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = t30 * t27;
    const T t32 = T(1) / r1;
    const T t33 = t32 * t32;
    const T t34 = t33 * t32;
    const T t35 = t34 * t34;
    const T t36 = t35 * t32;
    const T t37 = T(15) * t3 * t23 + T(6) * t25 * tau_lo + t20 + T(15) * t18 * t4 + t22 + T(20) * t21 * t19 + T(6) * delta_tau * t24;
    G_E = (T(1) / T(7)) * t26 * (T(30) * t3 * t23 * M_panels[1] + T(60) * M_panels[3] * t18 * t4 + T(6) * delta_tau * M_panels[0] * t24 + T(6) * t22 * M_panels[5] + T(30) * t25 * tau_lo * M_panels[4] + T(60) * t21 * t19 * M_panels[2] + t20 * t31 - t36 * t37);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / D;
    const T t39 = t4 * tau_lo;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = T(1) / r1;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t44 * a_minus_b + b * t41;
    const T t48 = t44 * a_minus_b * t45 + T(2) * t47 * t38 * a + b * t41 * t42;
    const T t49 = T(3) * b * t41 * t43 + T(3) * t44 * a_minus_b * t46 + T(4) * t38 * a * t48;
    const T t50 = t43 * t42;
    const T t51 = t46 * t45;
    const T t52 = T(2) * t38 * a * t49 + T(5) * b * t41 * t50 + T(5) * t44 * a_minus_b * t51;
    const T t53 = t4 * t4;
    const T t54 = t53 * tau_lo;
    const T t55 = T(5) * t41 * t50 + t38 * t52 * b - T(5) * t44 * t51;
    const T t56 = T(1) / a;
    const T t57 = t3 * t3;
    const T t58 = t38 * t49 * b + T(3) * t41 * t43 - T(3) * t44 * t46;
    const T t59 = T(2) * t56 * b * t58 + T(5) * t38 * t48 - t38 * t49 * c;
    const T t60 = T(7) * t38 * t49 + T(6) * t55 * t56 * b - T(3) * t38 * t52 * c;
    const T t61 = T(3) * t55 * t56 * c - T(2) * t60 * t56 * b - T(7) * t56 * t58;
    const T t62 = T(7) * t59 * t56 - t60 * t56 * c - T(2) * t56 * t61 * b;
    const T t63 = t57 * delta_tau;
    const T t64 = t38 * b * t48 + t41 * t42 - t44 * t45;
    const T t65 = T(5) * t64 * t56 + T(2) * t59 * t56 * b - t56 * t58 * c;
    const T t66 = t56 * t61 * c + T(7) * t65 * t56 + T(2) * t56 * b * t62;
    const T t67 = t3 * delta_tau;
    const T t68 = t67 * t67;
    const T t69 = T(3) * t47 * t38 + T(2) * t64 * t56 * b - t38 * t48 * c;
    const T t70 = t59 * t56 * c - T(5) * t56 * t69 - T(2) * t65 * t56 * b;
    G_ap = (T(1) / T(35)) * t38 * t40 * t52 + (T(6) / T(35)) * delta_tau * t54 * t55 * t56 + (T(1) / T(7)) * t57 * t4 * t56 * t62 + (T(1) / T(7)) * t3 * t60 * t53 * t56 + (T(2) / T(35)) * t63 * tau_lo * t56 * t66 - (T(1) / T(105)) * t68 * t56 * (t56 * t62 * c + T(7) * t70 * t56 - T(2) * t56 * b * t66) - (T(4) / T(21)) * t67 * t39 * t56 * t61;
    const T t71 = t44 * t44;
    const T t72 = t71 * t44;
    const T t73 = t72 * t72;
    const T t74 = t73 * t44;
    const T t75 = T(15) * t3 * t53 + T(6) * t63 * tau_lo + t40 + T(15) * t57 * t4 + t68 + T(20) * t67 * t39 + T(6) * delta_tau * t54;
    const T t76 = t41 * t41;
    const T t77 = t76 * t41;
    const T t78 = t77 * t77;
    const T t79 = t78 * t41;
    G_E = -(T(1) / T(35)) * t56 * (T(10) * t70 * t63 * tau_lo * t56 + T(5) * t74 * t75 + T(2) * t68 * (T(2) * t70 * t56 * b + t65 * t56 * c - T(5) * t56 * (T(2) * t56 * t69 * b + T(3) * t56 * (t41 + t47 * t38 * b - t44) - t64 * t56 * c)) * t56 - T(20) * t65 * t57 * t4 * t56 - T(2) * t38 * delta_tau * t54 * t49 - T(10) * t3 * t53 * t56 * t58 - T(5) * t40 * t79 - T(20) * t67 * t39 * t59 * t56);
  }
  const T t80 = T(1) / a;
  const T t81 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t80 * sigma2 * (tau_lo * ab_ab + ab_ap * delta_tau) * t81;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T t82 = sigma2 * sigma2;
  const T t83 = t82 * sigma2;
  const T g_factor = -T(7) * length * t83 * in.sigma;
  grad[0] = -(ab0 * G_E - G_ap * foot_h0) * g_factor;
  grad[1] = (G_ap * foot_h1 - ab1 * G_E) * g_factor;
  grad[2] = (foot_h2 * G_ap - ab2 * G_E) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 121 +, 350 ×, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48939 +, 74707 ×, 5608 /, 2506 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t5 = a_minus_b * b;
  if (t5 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t6 = T(1) / D;
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = t6 * t7 * (t8 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t9 = sqrt(a);
    const T t10 = r0 * a_minus_b;
    X = t9 * (a_minus_b - b) / (t10 - r1 * b);
  }
  const T t11 = sqrt(a);
  const T t12 = T(1) / t11;
  const T J1 = asinh(X) * t12;
  T F;
  T G_ap;
  T G_E;
  const T t13 = T(4) * D - a * a;
  const T t14 = -a_minus_b * b;
  const T t15 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t13 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t3 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t3 * t3;
    const T t19 = t4 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t4 * t4;
    const T t22 = t21 * tau_lo;
    const T t23 = t18 * delta_tau;
    F = t17 * M_panels[6] + T(15) * t4 * t18 * M_panels[4] + t20 * M_panels[0] + T(6) * M_panels[1] * t22 * delta_tau + T(20) * t19 * t16 * M_panels[3] + T(6) * M_panels[5] * tau_lo * t23 + T(15) * M_panels[2] * t21 * t3;
    const T t24 = T(6) * M_panels[9] * t22 * delta_tau + T(20) * M_panels[11] * t19 * t16 + T(6) * tau_lo * t23 * M_panels[13] + T(15) * M_panels[12] * t4 * t18 + M_panels[8] * t20 + T(15) * t21 * t3 * M_panels[10] + M_panels[14] * t17;
    G_ap = t24;
    const T t25 = T(1) / a;
    G_E = T(6) * t22 * delta_tau * M_panels[10] + M_panels[15] * t17 + T(6) * M_panels[14] * tau_lo * t23 + T(15) * M_panels[11] * t21 * t3 + M_panels[9] * t20 + T(15) * t4 * t18 * M_panels[13] + T(20) * M_panels[12] * t19 * t16 - t24 * t25 * b;
  } else if (t14 >= T(0) && t15 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t3 * t3;
    const T t27 = t4 * t4;
    const T t28 = t3 * delta_tau;
    const T t29 = t28 * t28;
    const T t30 = t26 * delta_tau;
    const T t31 = t27 * tau_lo;
    const T t32 = t4 * tau_lo;
    const T t33 = t32 * t32;
    F = T(15) * M_panels[4] * t4 * t26 + T(15) * M_panels[2] * t27 * t3 + t29 * M_panels[6] + T(6) * M_panels[5] * tau_lo * t30 + T(6) * M_panels[1] * t31 * delta_tau + t33 * M_panels[0] + T(20) * t32 * t28 * M_panels[3];
    G_ap = T(15) * t27 * t3 * M_panels[10] + T(6) * t31 * delta_tau * M_panels[9] + M_panels[8] * t33 + T(6) * tau_lo * t30 * M_panels[13] + M_panels[14] * t29 + T(20) * M_panels[11] * t32 * t28 + T(15) * M_panels[12] * t4 * t26;
    const T t34 = T(1) / r0;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = t36 * t36;
    const T t38 = t37 * t34;
    const T t39 = T(1) / r1;
    const T t40 = t39 * t39;
    const T t41 = t40 * t39;
    const T t42 = t41 * t41;
    const T t43 = t42 * t39;
    const T t44 = T(15) * t27 * t3 + T(6) * t31 * delta_tau + T(15) * t4 * t26 + T(6) * tau_lo * t30 + T(20) * t32 * t28 + t29 + t33;
    const T t45 = T(1) / a;
    G_E = (T(1) / T(7)) * (T(6) * t31 * delta_tau * M_panels[0] + t38 * t33 + T(60) * M_panels[2] * t32 * t28 + T(60) * t4 * t26 * M_panels[3] + T(30) * M_panels[1] * t27 * t3 + T(6) * M_panels[5] * t29 + T(30) * M_panels[4] * tau_lo * t30 - t43 * t44) * t45;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t46 = T(1) / r0;
    const T t47 = t46 * t46;
    const T t48 = t47 * t47;
    const T t49 = T(1) / D;
    const T t50 = T(1) / r1;
    const T t51 = t50 * t50;
    const T t52 = t51 * t51;
    const T t53 = t50 * a_minus_b + t46 * b;
    const T t54 = T(2) * t53 * t49 * a + t51 * t50 * a_minus_b + t47 * t46 * b;
    const T t55 = T(3) * t48 * t46 * b + T(3) * t52 * t50 * a_minus_b + T(4) * t54 * t49 * a;
    const T t56 = T(3) * t48 * t46 + t49 * t55 * b - T(3) * t52 * t50;
    const T t57 = t4 * t4;
    const T t58 = t57 * tau_lo;
    const T t59 = T(1) / a;
    const T t60 = t51 * t50 - t54 * t49 * b - t47 * t46;
    const T t61 = T(3) * t53 * t49 - T(2) * t60 * t59 * b - c * t54 * t49;
    const T t62 = T(2) * t56 * t59 * b + T(5) * t54 * t49 - c * t49 * t55;
    const T t63 = T(2) * t62 * t59 * b - c * t56 * t59 - T(5) * t60 * t59;
    const T t64 = T(5) * t61 * t59 + T(2) * t63 * t59 * b - c * t62 * t59;
    const T t65 = t46 + t53 * t49 * b - t50;
    const T t66 = T(3) * t65 * t59 + t60 * c * t59 + T(2) * t61 * t59 * b;
    const T t67 = T(2) * t64 * t59 * b + T(5) * t59 * t66 - t63 * c * t59;
    const T t68 = t3 * t3;
    const T t69 = t68 * delta_tau;
    const T t70 = t3 * delta_tau;
    const T t71 = t70 * t70;
    const T t72 = t4 * tau_lo;
    const T t73 = t72 * t72;
    F = (T(2) / T(5)) * t56 * t58 * delta_tau * t59 + (T(2) / T(5)) * t67 * tau_lo * t69 * t59 + t64 * t4 * t68 * t59 + t57 * t3 * t62 * t59 + (T(1) / T(15)) * (T(2) * t67 * t59 * b - T(5) * (c * t61 * t59 - T(2) * t59 * t66 * b - T(3) * t59 * (J1 + T(2) * t65 * t59 * b - c * t53 * t49)) * t59 - c * t64 * t59) * t71 * t59 + (T(4) / T(3)) * t63 * t72 * t70 * t59 + (T(1) / T(15)) * t73 * t49 * t55;
    const T t74 = t48 * t47;
    const T t75 = t52 * t51;
    const T t76 = T(5) * t75 * t50 * a_minus_b + T(2) * t49 * t55 * a + T(5) * t74 * t46 * b;
    const T t77 = T(5) * t74 * t46 + t49 * t76 * b - T(5) * t75 * t50;
    const T t78 = T(3) * c * t49 * t76 - T(7) * t49 * t55 - T(6) * t77 * t59 * b;
    const T t79 = T(7) * t56 * t59 - T(3) * t77 * c * t59 - T(2) * t78 * t59 * b;
    const T t80 = T(2) * t79 * t59 * b + c * t78 * t59 + T(7) * t62 * t59;
    const T t81 = T(2) * t80 * t59 * b + T(7) * t63 * t59 - c * t79 * t59;
    G_ap = (T(4) / T(21)) * t79 * t72 * t70 * t59 + (T(2) / T(35)) * t81 * tau_lo * t69 * t59 + (T(6) / T(35)) * t77 * t58 * delta_tau * t59 + (T(1) / T(35)) * t73 * t49 * t76 + (T(1) / T(7)) * t80 * t4 * t68 * t59 + (T(1) / T(105)) * t71 * t59 * (T(2) * t81 * t59 * b + T(7) * t64 * t59 - c * t80 * t59) - (T(1) / T(7)) * t57 * t78 * t3 * t59;
    const T t82 = t46 * t46;
    const T t83 = t82 * t46;
    const T t84 = t83 * t83;
    const T t85 = t84 * t46;
    const T t86 = t50 * t50;
    const T t87 = t86 * t50;
    const T t88 = t87 * t87;
    const T t89 = t88 * t50;
    const T t90 = T(15) * t57 * t3 + T(6) * t58 * delta_tau + T(15) * t4 * t68 + T(6) * tau_lo * t69 + T(20) * t72 * t70 + t71 + t73;
    G_E = (T(1) / T(35)) * (T(2) * t67 * t71 * t59 + T(2) * t58 * t49 * t55 * delta_tau + T(10) * t64 * tau_lo * t69 * t59 + T(5) * t85 * t73 + T(20) * t63 * t4 * t68 * t59 + T(10) * t56 * t57 * t3 * t59 + T(20) * t72 * t70 * t62 * t59 - T(5) * t89 * t90) * t59;
  }
  const T t91 = T(1) / a;
  const T t92 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t91 * sigma2 * t92 * (ab_ap * delta_tau + tau_lo * ab_ab);
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = foot2 + ab2 * foot_offset;
  const T t93 = sigma2 * sigma2;
  const T t94 = t93 * sigma2;
  const T g_factor = -T(7) * in.sigma * length * t94;
  f = in.sigma * length * F * t94;
  grad[0] = (G_ap * foot_h0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot_h1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot_h2 - ab2 * G_E) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 89 +, 224 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 33623 +, 46494 ×, 6305 /, 137 sqrt, 0 atan, 0 log/asinh.
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
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t2 * tau_lo;
    const T t8 = t1 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t2 * t2;
    const T t12 = t11 * tau_lo;
    const T t13 = t10 * tau_lo;
    const T t14 = t6 * delta_tau;
    const T t15 = t9 * delta_tau;
    F = T(35) * t6 * t7 * M_panels[4] + T(7) * M_panels[6] * t9 * tau_lo + T(7) * delta_tau * t10 * M_panels[1] + T(21) * M_panels[2] * t1 * t12 + M_panels[0] * t13 + T(21) * M_panels[5] * t14 * t2 + T(35) * M_panels[3] * t8 * t11 + t15 * M_panels[7];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t1 * delta_tau;
    const T t17 = t2 * t2;
    const T t18 = t1 * t1;
    const T t19 = t18 * delta_tau;
    const T t20 = t16 * t16;
    const T t21 = t2 * tau_lo;
    const T t22 = t20 * delta_tau;
    const T t23 = t17 * tau_lo;
    const T t24 = t21 * t21;
    const T t25 = t24 * tau_lo;
    F = T(35) * M_panels[3] * t16 * t17 + T(21) * t19 * M_panels[5] * t2 + T(7) * M_panels[6] * t20 * tau_lo + T(35) * M_panels[4] * t18 * t21 + M_panels[7] * t22 + T(21) * t1 * t23 * M_panels[2] + T(7) * M_panels[1] * delta_tau * t24 + M_panels[0] * t25;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = sqrt(D);
    const T t27 = T(1) / t26;
    const T J2 = atan2(t26, c_minus_b) * t27;
    const T t28 = T(1) / c;
    const T log_ratio = log(t28 * q1);
    const T t29 = t1 * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = T(1) / a;
    const T t33 = T(1) / q1;
    const T t34 = a_minus_b * t33 + b * t28 + a * J2;
    const T t35 = T(1) / D;
    const T t36 = t28 + b * t34 * t35 - t33;
    const T t37 = T(2) * b * t36 * t32 + T(2) * J2 - t34 * c * t35;
    const T t38 = t33 * t33;
    const T t39 = t28 * t28;
    const T t40 = T(3) * t34 * t35 * a + T(2) * b * t39 + T(2) * a_minus_b * t38;
    const T t41 = T(2) * t38 - b * t40 * t35 - T(2) * t39;
    const T t42 = T(2) * b * t41 * t32 + t40 * c * t35 - T(4) * t34 * t35;
    const T t43 = T(4) * t36 * t32 + c * t41 * t32 - T(2) * b * t42 * t32;
    const T t44 = T(4) * t37 * t32 + T(2) * b * t43 * t32 + t42 * c * t32;
    const T t45 = t39 * t28;
    const T t46 = t38 * t33;
    const T t47 = T(5) * t40 * t35 * a + T(8) * b * t45 + T(8) * a_minus_b * t46;
    const T t48 = T(8) * t46 - T(8) * t45 - b * t35 * t47;
    const T t49 = c * t35 * t47 + T(2) * b * t48 * t32 - T(6) * t40 * t35;
    const T t50 = T(2) * b * t49 * t32 + T(6) * t41 * t32 - t48 * c * t32;
    const T t51 = c * t49 * t32 - T(2) * b * t50 * t32 - T(6) * t42 * t32;
    const T t52 = T(6) * t43 * t32 + t50 * c * t32 + T(2) * b * t51 * t32;
    const T t53 = T(6) * t32 * t44 + T(2) * b * t52 * t32 - t51 * c * t32;
    const T t54 = t1 * t1;
    const T t55 = t2 * tau_lo;
    const T t56 = t54 * delta_tau;
    const T t57 = t55 * t55;
    const T t58 = t57 * tau_lo;
    const T t59 = t2 * t2;
    const T t60 = t59 * tau_lo;
    F = (T(1) / T(48)) * t31 * t32 * (T(6) * t32 * (T(2) * b * t32 * t44 + T(4) * (T(2) * b * t37 * t32 + (T(2) * b * J2 + log_ratio) * t32 - c * t36 * t32) * t32 - c * t43 * t32) + T(2) * b * t53 * t32 - t52 * c * t32) + (T(35) / T(48)) * t51 * t54 * t55 * t32 + (T(7) / T(48)) * t53 * t30 * tau_lo * t32 + (T(7) / T(16)) * t52 * t56 * t2 * t32 + (T(1) / T(48)) * t35 * t58 * t47 - (T(7) / T(16)) * t1 * t60 * t49 * t32 - (T(35) / T(48)) * t50 * t29 * t59 * t32 - (T(7) / T(48)) * t48 * delta_tau * t57 * t32;
  }
  const T t61 = sigma2 * sigma2;
  const T t62 = t61 * t61;
  f = F * length * t62;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 123 +, 325 ×, 8 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 48748 +, 63485 ×, 5089 /, 111 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
    foot0 = -(ab1 * exact_cross[2] - exact_cross[1] * ab2) * t2;
    foot1 = (ab0 * exact_cross[2] - exact_cross[0] * ab2) * t2;
    foot2 = t2 * (exact_cross[0] * ab1 - exact_cross[1] * ab0);
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t3 * t3;
    const T t11 = t10 * delta_tau;
    const T t12 = t4 * t4;
    const T t13 = t12 * tau_lo;
    const T t14 = t4 * tau_lo;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    const T t17 = t9 * delta_tau;
    const T t18 = T(7) * t9 * M_panels[15] * tau_lo + T(21) * t11 * t4 * M_panels[14] + T(21) * M_panels[11] * t3 * t13 + T(35) * t8 * t12 * M_panels[12] + t16 * M_panels[9] + T(7) * delta_tau * t15 * M_panels[10] + T(35) * t10 * t14 * M_panels[13] + t17 * M_panels[16];
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = t16 * M_panels[10] + t17 * M_panels[17] + T(35) * t10 * t14 * M_panels[14] + T(35) * t8 * t12 * M_panels[13] + T(21) * t11 * M_panels[15] * t4 + T(7) * M_panels[11] * delta_tau * t15 + T(7) * t9 * tau_lo * M_panels[16] + T(21) * t3 * t13 * M_panels[12] - t18 * t19 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t3 * delta_tau;
    const T t21 = t4 * t4;
    const T t22 = t20 * t20;
    const T t23 = t4 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t21 * tau_lo;
    const T t26 = t24 * tau_lo;
    const T t27 = t3 * t3;
    const T t28 = t22 * delta_tau;
    const T t29 = t27 * delta_tau;
    G_ap = T(35) * M_panels[12] * t20 * t21 + T(7) * t22 * tau_lo * M_panels[15] + T(7) * delta_tau * t24 * M_panels[10] + T(21) * t3 * t25 * M_panels[11] + M_panels[9] * t26 + T(35) * t27 * t23 * M_panels[13] + t28 * M_panels[16] + T(21) * t29 * t4 * M_panels[14];
    const T t30 = T(1) / c;
    const T t31 = t30 * t30;
    const T t32 = t31 * t31;
    const T t33 = T(21) * t3 * t25 + t26 + T(7) * t22 * tau_lo + T(21) * t29 * t4 + T(35) * t20 * t21 + T(35) * t27 * t23 + t28 + T(7) * delta_tau * t24;
    const T t34 = T(1) / q1;
    const T t35 = t34 * t34;
    const T t36 = t35 * t35;
    const T t37 = T(1) / a;
    G_E = (T(1) / T(8)) * (T(7) * M_panels[0] * delta_tau * t24 + T(105) * t20 * t21 * M_panels[2] + T(42) * t3 * t25 * M_panels[1] + T(42) * t22 * tau_lo * M_panels[5] + T(7) * M_panels[6] * t28 + t32 * t26 + T(140) * M_panels[3] * t27 * t23 + T(105) * t29 * t4 * M_panels[4] - t33 * t36) * t37;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = atan2(t38, c_minus_b) * t39;
    const T t40 = T(1) / c;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = T(1) / D;
    const T t44 = T(1) / q1;
    const T t45 = t44 * t44;
    const T t46 = t45 * t44;
    const T t47 = a * J2 + t40 * b + a_minus_b * t44;
    const T t48 = T(2) * a_minus_b * t45 + T(3) * t43 * a * t47 + T(2) * t41 * b;
    const T t49 = t41 * t40;
    const T t50 = T(8) * a_minus_b * t46 + T(5) * t43 * a * t48 + T(8) * t49 * b;
    const T t51 = t45 * t45;
    const T t52 = T(48) * t42 * b + T(7) * t50 * t43 * a + T(48) * a_minus_b * t51;
    const T t53 = T(48) * t42 + t43 * t52 * b - T(48) * t51;
    const T t54 = t4 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = T(1) / a;
    const T t57 = t3 * delta_tau;
    const T t58 = t4 * t4;
    const T t59 = T(2) * t53 * t56 * b + T(8) * t50 * t43 - c * t43 * t52;
    const T t60 = T(8) * t46 - T(8) * t49 - t50 * t43 * b;
    const T t61 = T(2) * t56 * b * t59 - T(8) * t56 * t60 - t53 * c * t56;
    const T t62 = t58 * tau_lo;
    const T t63 = t55 * tau_lo;
    const T t64 = t57 * t57;
    const T t65 = t64 * delta_tau;
    const T t66 = T(2) * t45 - t43 * t48 * b - T(2) * t41;
    const T t67 = T(2) * t56 * b * t60 + c * t50 * t43 - T(6) * t43 * t48;
    const T t68 = c * t56 * t60 - T(6) * t56 * t66 - T(2) * t67 * t56 * b;
    const T t69 = T(2) * t56 * b * t66 + c * t43 * t48 - T(4) * t43 * t47;
    const T t70 = T(2) * t56 * b * t68 + c * t67 * t56 - T(6) * t69 * t56;
    const T t71 = t40 + t43 * t47 * b - t44;
    const T t72 = T(4) * t56 * t71 + c * t56 * t66 - T(2) * t69 * t56 * b;
    const T t73 = c * t56 * t68 - T(2) * t56 * b * t70 - T(6) * t56 * t72;
    const T t74 = c * t56 * t59 + T(8) * t67 * t56 - T(2) * t56 * b * t61;
    const T t75 = c * t56 * t61 + T(2) * t56 * t74 * b - T(8) * t56 * t68;
    const T t76 = T(2) * t75 * t56 * b - c * t56 * t74 - T(8) * t56 * t70;
    const T t77 = t3 * t3;
    const T t78 = t77 * delta_tau;
    G_ap = (T(7) / T(384)) * t53 * delta_tau * t55 * t56 + (T(35) / T(384)) * t57 * t58 * t56 * t61 + (T(7) / T(128)) * t3 * t62 * t56 * t59 + (T(1) / T(384)) * t63 * t43 * t52 - (T(1) / T(384)) * t65 * t56 * (T(8) * t56 * t73 + T(2) * t76 * t56 * b - c * t75 * t56) - (T(7) / T(128)) * t75 * t78 * t4 * t56 - (T(7) / T(384)) * t76 * t64 * tau_lo * t56 - (T(35) / T(384)) * t77 * t54 * t56 * t74;
    const T t79 = T(21) * t3 * t62 + t63 + T(7) * t64 * tau_lo + T(21) * t78 * t4 + T(35) * t57 * t58 + T(35) * t77 * t54 + t65 + T(7) * delta_tau * t55;
    G_E = -(T(1) / T(384)) * (T(42) * t3 * t62 * t56 * t60 + T(105) * t57 * t58 * t67 * t56 + T(48) * t79 * t51 + T(7) * (c * t56 * t70 + T(2) * t56 * t73 * b - T(6) * t56 * (c * t69 * t56 + T(2) * t56 * b * t72 - T(4) * t56 * (c * t43 * t47 - T(2) * t56 * t71 * b - T(2) * J2))) * t65 * t56 + T(42) * t64 * tau_lo * t56 * t73 - T(140) * t77 * t54 * t56 * t68 - T(7) * t50 * delta_tau * t55 * t43 - T(105) * t78 * t4 * t56 * t70 - T(48) * t42 * t63) * t56;
  }
  const T t80 = T(1) / a;
  const T t81 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t80 * sigma2 * (ab_ap * delta_tau + tau_lo * ab_ab) * t81;
  const T foot_h0 = foot0 + ab0 * foot_offset;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = ab2 * foot_offset + foot2;
  const T t82 = sigma2 * sigma2;
  const T t83 = t82 * t82;
  const T g_factor = -T(8) * length * t83;
  grad[0] = g_factor * (foot_h0 * G_ap - G_E * ab0);
  grad[1] = (foot_h1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * foot_h2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 137 +, 380 ×, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 48755 +, 63507 ×, 5089 /, 111 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
    foot2 = (exact_cross[0] * ab1 - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -b * a_minus_b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t4 * t4;
    const T t10 = t8 * t8;
    const T t11 = t9 * tau_lo;
    const T t12 = t10 * delta_tau;
    const T t13 = t4 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = t3 * t3;
    const T t17 = t16 * delta_tau;
    F = T(35) * t8 * t9 * M_panels[3] + T(7) * t10 * tau_lo * M_panels[6] + T(21) * t3 * t11 * M_panels[2] + t12 * M_panels[7] + t15 * M_panels[0] + T(35) * t16 * t13 * M_panels[4] + T(7) * M_panels[1] * delta_tau * t14 + T(21) * t17 * t4 * M_panels[5];
    const T t18 = T(35) * t8 * t9 * M_panels[12] + T(7) * t10 * tau_lo * M_panels[15] + T(21) * t3 * t11 * M_panels[11] + T(7) * delta_tau * t14 * M_panels[10] + T(21) * t17 * M_panels[14] * t4 + T(35) * t16 * t13 * M_panels[13] + t12 * M_panels[16] + t15 * M_panels[9];
    G_ap = t18;
    const T t19 = T(1) / a;
    G_E = T(7) * delta_tau * t14 * M_panels[11] + t15 * M_panels[10] + T(35) * t16 * M_panels[14] * t13 + T(21) * t17 * t4 * M_panels[15] + T(21) * t3 * t11 * M_panels[12] + M_panels[17] * t12 + T(7) * t10 * tau_lo * M_panels[16] + T(35) * t8 * t9 * M_panels[13] - t18 * t19 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t4 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t21 * tau_lo;
    const T t23 = t3 * t3;
    const T t24 = t23 * delta_tau;
    const T t25 = t3 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = t4 * t4;
    const T t29 = t28 * tau_lo;
    F = T(7) * delta_tau * t21 * M_panels[1] + t22 * M_panels[0] + T(21) * M_panels[5] * t24 * t4 + T(35) * t23 * t20 * M_panels[4] + t27 * M_panels[7] + T(21) * t3 * t29 * M_panels[2] + T(35) * t25 * t28 * M_panels[3] + T(7) * t26 * tau_lo * M_panels[6];
    G_ap = T(21) * t3 * t29 * M_panels[11] + T(35) * t25 * t28 * M_panels[12] + t22 * M_panels[9] + T(7) * delta_tau * t21 * M_panels[10] + T(7) * t26 * M_panels[15] * tau_lo + T(35) * t23 * t20 * M_panels[13] + t27 * M_panels[16] + T(21) * t24 * t4 * M_panels[14];
    const T t30 = T(1) / a;
    const T t31 = T(1) / c;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = T(7) * t26 * tau_lo + T(21) * t24 * t4 + T(35) * t25 * t28 + T(35) * t23 * t20 + T(21) * t3 * t29 + t22 + T(7) * delta_tau * t21 + t27;
    const T t35 = T(1) / q1;
    const T t36 = t35 * t35;
    const T t37 = t36 * t36;
    G_E = (T(1) / T(8)) * t30 * (T(42) * M_panels[5] * t26 * tau_lo + t22 * t33 + T(105) * t24 * t4 * M_panels[4] + T(140) * t23 * t20 * M_panels[3] + T(7) * delta_tau * t21 * M_panels[0] + T(105) * t25 * t28 * M_panels[2] + T(42) * t3 * t29 * M_panels[1] + T(7) * t27 * M_panels[6] - t34 * t37);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = sqrt(D);
    const T t39 = T(1) / t38;
    const T J2 = t39 * atan2(t38, c_minus_b);
    const T t40 = T(1) / c;
    const T log_ratio = log(t40 * q1);
    const T t41 = t4 * tau_lo;
    const T t42 = t41 * t41;
    const T t43 = T(1) / a;
    const T t44 = T(1) / D;
    const T t45 = T(1) / q1;
    const T t46 = J2 * a + b * t40 + a_minus_b * t45;
    const T t47 = t45 * t45;
    const T t48 = t40 * t40;
    const T t49 = T(3) * t46 * a * t44 + T(2) * a_minus_b * t47 + T(2) * b * t48;
    const T t50 = t48 * t40;
    const T t51 = t47 * t45;
    const T t52 = T(5) * a * t44 * t49 + T(8) * b * t50 + T(8) * a_minus_b * t51;
    const T t53 = t52 * t44 * b + T(8) * t50 - T(8) * t51;
    const T t54 = t3 * delta_tau;
    const T t55 = t4 * t4;
    const T t56 = T(2) * t43 * b * t53 + T(6) * t44 * t49 - t52 * t44 * c;
    const T t57 = t44 * t49 * b + T(2) * t48 - T(2) * t47;
    const T t58 = T(2) * t56 * t43 * b + T(6) * t43 * t57 - t43 * t53 * c;
    const T t59 = t55 * tau_lo;
    const T t60 = t3 * t3;
    const T t61 = T(2) * t43 * b * t57 + T(4) * t46 * t44 - t44 * t49 * c;
    const T t62 = T(2) * t43 * t58 * b + T(6) * t61 * t43 - t56 * t43 * c;
    const T t63 = t42 * tau_lo;
    const T t64 = t60 * delta_tau;
    const T t65 = t45 - t40 - t46 * t44 * b;
    const T t66 = t43 * t57 * c + T(4) * t65 * t43 - T(2) * t61 * t43 * b;
    const T t67 = t43 * t58 * c + T(6) * t66 * t43 - T(2) * t43 * b * t62;
    const T t68 = t54 * t54;
    const T t69 = T(2) * J2 - T(2) * t65 * t43 * b - t46 * t44 * c;
    const T t70 = t61 * t43 * c + T(2) * t66 * t43 * b - T(4) * t69 * t43;
    const T t71 = T(2) * t43 * b * t67 + T(6) * t70 * t43 + t43 * t62 * c;
    const T t72 = t68 * delta_tau;
    F = (T(7) / T(48)) * delta_tau * t42 * t43 * t53 + (T(35) / T(48)) * t54 * t55 * t43 * t58 + (T(7) / T(16)) * t56 * t3 * t59 * t43 + (T(35) / T(48)) * t60 * t41 * t43 * t62 + (T(1) / T(48)) * t63 * t52 * t44 - (T(7) / T(16)) * t64 * t4 * t43 * t67 - (T(7) / T(48)) * t68 * t71 * tau_lo * t43 - (T(1) / T(48)) * t72 * (T(6) * t43 * (T(2) * t70 * t43 * b - t66 * t43 * c - T(4) * t43 * (t65 * t43 * c + T(2) * t69 * t43 * b + t43 * (log_ratio + T(2) * J2 * b))) + T(2) * t71 * t43 * b - t43 * t67 * c) * t43;
    const T t73 = t47 * t47;
    const T t74 = t48 * t48;
    const T t75 = T(48) * b * t74 + T(7) * a * t52 * t44 + T(48) * a_minus_b * t73;
    const T t76 = T(48) * t73 - T(48) * t74 - t44 * b * t75;
    const T t77 = T(8) * t52 * t44 - T(2) * t43 * t76 * b - t44 * t75 * c;
    const T t78 = t43 * t76 * c + T(2) * t77 * t43 * b + T(8) * t43 * t53;
    const T t79 = t77 * t43 * c - T(2) * t43 * b * t78 - T(8) * t56 * t43;
    const T t80 = T(2) * t43 * b * t79 + t43 * c * t78 - T(8) * t43 * t58;
    const T t81 = T(8) * t43 * t62 + t43 * t79 * c - T(2) * t80 * t43 * b;
    G_ap = (T(35) / T(384)) * t54 * t55 * t43 * t78 + (T(1) / T(384)) * t72 * t43 * (t80 * t43 * c + T(2) * t43 * t81 * b - T(8) * t43 * t67) + (T(7) / T(384)) * t68 * tau_lo * t43 * t81 + (T(1) / T(384)) * t63 * t44 * t75 + (T(7) / T(128)) * t77 * t3 * t59 * t43 - (T(7) / T(384)) * delta_tau * t42 * t43 * t76 - (T(35) / T(384)) * t60 * t41 * t43 * t79 - (T(7) / T(128)) * t64 * t4 * t80 * t43;
    const T t82 = T(7) * t68 * tau_lo + T(21) * t64 * t4 + T(35) * t54 * t55 + T(35) * t60 * t41 + T(21) * t3 * t59 + t63 + T(7) * delta_tau * t42 + t72;
    G_E = -(T(1) / T(384)) * t43 * (T(42) * t68 * tau_lo * t43 * t67 + T(7) * t72 * t71 * t43 + T(48) * t82 * t73 - T(105) * t56 * t54 * t55 * t43 - T(48) * t63 * t74 - T(140) * t60 * t41 * t43 * t58 - T(42) * t3 * t59 * t43 * t53 - T(7) * delta_tau * t42 * t52 * t44 - T(105) * t64 * t4 * t43 * t62);
  }
  const T t83 = T(1) / a;
  const T t84 = T(1) / ab_ab;
  const T foot_offset = delta_tau * (delta_tau * ab_ap + tau_lo * ab_ab) * t83 * sigma2 * t84;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T t85 = sigma2 * sigma2;
  const T t86 = t85 * t85;
  const T g_factor = -T(8) * t86 * length;
  f = t86 * F * length;
  grad[0] = g_factor * (foot_h0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot_h1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot_h2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 98 +, 278 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 32252 +, 55591 ×, 5602 /, 2506 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t1 = delta_tau * delta_tau;
  const T a = ab_ab + t1 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = t2 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
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
    X = t4 * t5 * (t6 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t7 = sqrt(a);
    const T t8 = r0 * a_minus_b;
    X = -t7 * (b - a_minus_b) / (t8 - r1 * b);
  }
  const T t9 = sqrt(a);
  const T t10 = T(1) / t9;
  const T J1 = t10 * asinh(X);
  T F;
  const T t11 = T(4) * D - a * a;
  const T t12 = -b * a_minus_b;
  const T t13 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t11 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t14 = t1 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t15 * tau_lo;
    const T t17 = t1 * t1;
    const T t18 = t17 * delta_tau;
    const T t19 = t2 * tau_lo;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    const T t22 = t21 * delta_tau;
    const T t23 = t19 * t19;
    const T t24 = t23 * tau_lo;
    const T t25 = t17 * t17;
    F = T(56) * t14 * t16 * M_panels[3] + T(70) * M_panels[4] * t17 * t15 + T(56) * t18 * t19 * M_panels[5] + t20 * M_panels[0] + T(8) * M_panels[7] * t22 * tau_lo + T(28) * t1 * t23 * M_panels[2] + T(8) * M_panels[1] * delta_tau * t24 + T(28) * t21 * t2 * M_panels[6] + t25 * M_panels[8];
  } else if (t12 >= T(0) && t13 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t26 = t1 * delta_tau;
    const T t27 = t2 * t2;
    const T t28 = t27 * tau_lo;
    const T t29 = t2 * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t30 * tau_lo;
    const T t32 = t1 * t1;
    const T t33 = t32 * delta_tau;
    const T t34 = t26 * t26;
    const T t35 = t34 * delta_tau;
    const T t36 = t27 * t27;
    const T t37 = t32 * t32;
    F = T(56) * t26 * t28 * M_panels[3] + T(8) * M_panels[1] * delta_tau * t31 + T(70) * M_panels[4] * t32 * t27 + T(56) * t33 * t29 * M_panels[5] + T(8) * M_panels[7] * t35 * tau_lo + T(28) * t34 * t2 * M_panels[6] + t36 * M_panels[0] + T(28) * t1 * M_panels[2] * t30 + t37 * M_panels[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t38 = T(1) / D;
    const T t39 = t2 * t2;
    const T t40 = t39 * t39;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t43 * t42;
    const T t45 = T(1) / r1;
    const T t46 = t45 * t45;
    const T t47 = t45 * a_minus_b + t41 * b;
    const T t48 = t45 * t46 * a_minus_b + t42 * t41 * b + T(2) * t47 * t38 * a;
    const T t49 = t46 * t46;
    const T t50 = T(3) * t43 * t41 * b + T(4) * t38 * a * t48 + T(3) * t45 * t49 * a_minus_b;
    const T t51 = t49 * t46;
    const T t52 = T(5) * t44 * t41 * b + T(2) * t38 * a * t50 + T(5) * t45 * t51 * a_minus_b;
    const T t53 = t1 * t1;
    const T t54 = t53 * delta_tau;
    const T t55 = t2 * tau_lo;
    const T t56 = T(1) / a;
    const T t57 = T(3) * t45 * t49 - t38 * t50 * b - T(3) * t43 * t41;
    const T t58 = T(5) * t38 * t48 - T(2) * t57 * t56 * b - c * t38 * t50;
    const T t59 = t42 * t41 + t38 * b * t48 - t45 * t46;
    const T t60 = c * t57 * t56 + T(2) * t58 * t56 * b + T(5) * t59 * t56;
    const T t61 = T(5) * t45 * t51 - t38 * t52 * b - T(5) * t44 * t41;
    const T t62 = T(3) * c * t38 * t52 + T(6) * t56 * t61 * b - T(7) * t38 * t50;
    const T t63 = T(2) * t56 * t62 * b + T(7) * t57 * t56 - T(3) * c * t56 * t61;
    const T t64 = T(2) * t56 * b * t63 - T(7) * t58 * t56 - c * t56 * t62;
    const T t65 = T(7) * t60 * t56 + c * t56 * t63 - T(2) * t56 * t64 * b;
    const T t66 = t1 * delta_tau;
    const T t67 = t66 * t66;
    const T t68 = T(2) * t59 * t56 * b + T(3) * t47 * t38 - c * t38 * t48;
    const T t69 = T(2) * t60 * t56 * b + T(5) * t56 * t68 - c * t58 * t56;
    const T t70 = T(7) * t69 * t56 + T(2) * t56 * b * t65 + c * t56 * t64;
    const T t71 = t55 * t55;
    const T t72 = t71 * tau_lo;
    const T t73 = t45 - t41 - t47 * t38 * b;
    const T t74 = T(2) * t56 * b * t68 - T(3) * t56 * t73 - c * t59 * t56;
    const T t75 = T(5) * t74 * t56 + T(2) * t69 * t56 * b - t60 * c * t56;
    const T t76 = c * t56 * t65 - T(2) * t56 * t70 * b - T(7) * t75 * t56;
    const T t77 = t53 * t53;
    const T t78 = t39 * tau_lo;
    const T t79 = t67 * delta_tau;
    F = (T(1) / T(35)) * t38 * t40 * t52 + (T(8) / T(15)) * t54 * t55 * t56 * t65 + (T(4) / T(15)) * t67 * t2 * t56 * t70 - (T(8) / T(35)) * delta_tau * t72 * t56 * t61 - (T(1) / T(105)) * (c * t56 * t70 + T(2) * t76 * t56 * b + T(7) * (t69 * c * t56 - T(2) * t75 * t56 * b - T(5) * (T(2) * t74 * t56 * b - c * t56 * t68 - T(3) * t56 * (c * t47 * t38 + T(2) * t56 * b * t73 - J1)) * t56) * t56) * t77 * t56 - (T(8) / T(15)) * t66 * t78 * t56 * t63 - (T(4) / T(15)) * t1 * t71 * t56 * t62 - (T(2) / T(3)) * t53 * t39 * t56 * t64 - (T(8) / T(105)) * t79 * t76 * tau_lo * t56;
  }
  const T t80 = sigma2 * sigma2;
  const T t81 = t80 * t80;
  f = in.sigma * length * t81 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 134 +, 395 ×, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 48168 +, 73315 ×, 4619 /, 2063 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
    foot0 = -(exact_cross[2] * ab1 - exact_cross[1] * ab2) * t2;
    foot1 = (exact_cross[2] * ab0 - exact_cross[0] * ab2) * t2;
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t4 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t9 * tau_lo;
    const T t11 = t3 * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t12 * delta_tau;
    const T t14 = t4 * t4;
    const T t15 = t14 * t14;
    const T t16 = t3 * t3;
    const T t17 = t14 * tau_lo;
    const T t18 = t16 * t16;
    const T t19 = t16 * delta_tau;
    const T t20 = T(8) * delta_tau * t10 * M_panels[11] + T(8) * t13 * tau_lo * M_panels[17] + T(28) * t3 * t9 * M_panels[12] + M_panels[10] * t15 + T(28) * M_panels[16] * t12 * t4 + T(70) * t16 * t14 * M_panels[14] + T(56) * M_panels[13] * t11 * t17 + t18 * M_panels[18] + T(56) * t19 * t8 * M_panels[15];
    G_ap = t20;
    const T t21 = T(1) / a;
    G_E = M_panels[19] * t18 + T(56) * M_panels[16] * t19 * t8 + T(70) * t16 * t14 * M_panels[15] + T(56) * t11 * t17 * M_panels[14] + T(8) * delta_tau * t10 * M_panels[12] + T(8) * t13 * tau_lo * M_panels[18] + T(28) * t12 * t4 * M_panels[17] + t15 * M_panels[11] + T(28) * M_panels[13] * t3 * t9 - t20 * t21 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t22 = t3 * t3;
    const T t23 = t4 * t4;
    const T t24 = t22 * delta_tau;
    const T t25 = t4 * tau_lo;
    const T t26 = t3 * delta_tau;
    const T t27 = t23 * tau_lo;
    const T t28 = t26 * t26;
    const T t29 = t28 * delta_tau;
    const T t30 = t22 * t22;
    const T t31 = t25 * t25;
    const T t32 = t31 * tau_lo;
    const T t33 = t23 * t23;
    G_ap = T(70) * t22 * t23 * M_panels[14] + T(56) * M_panels[15] * t24 * t25 + T(56) * t26 * t27 * M_panels[13] + T(8) * t29 * tau_lo * M_panels[17] + M_panels[18] * t30 + T(8) * delta_tau * t32 * M_panels[11] + T(28) * t28 * t4 * M_panels[16] + t33 * M_panels[10] + T(28) * M_panels[12] * t3 * t31;
    const T t34 = T(1) / a;
    const T t35 = T(1) / r0;
    const T t36 = t35 * t35;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = t38 * t35;
    const T t40 = T(1) / r1;
    const T t41 = t40 * t40;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t43 * t40;
    const T t45 = T(8) * delta_tau * t32 + T(70) * t22 * t23 + T(8) * t29 * tau_lo + T(56) * t24 * t25 + t33 + T(56) * t26 * t27 + t30 + T(28) * t28 * t4 + T(28) * t3 * t31;
    G_E = (T(1) / T(9)) * t34 * (T(56) * t3 * t31 * M_panels[1] + T(8) * t30 * M_panels[7] + T(168) * M_panels[2] * t26 * t27 + t33 * t39 + T(168) * M_panels[5] * t28 * t4 + T(8) * delta_tau * t32 * M_panels[0] + T(280) * t24 * t25 * M_panels[4] + T(280) * t22 * t23 * M_panels[3] + T(56) * t29 * tau_lo * M_panels[6] - t44 * t45);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t46 = t4 * tau_lo;
    const T t47 = t46 * t46;
    const T t48 = t47 * tau_lo;
    const T t49 = T(1) / a;
    const T t50 = T(1) / D;
    const T t51 = T(1) / r0;
    const T t52 = t51 * t51;
    const T t53 = t52 * t52;
    const T t54 = t53 * t52;
    const T t55 = T(1) / r1;
    const T t56 = t55 * t55;
    const T t57 = t56 * t56;
    const T t58 = t57 * t56;
    const T t59 = t55 * a_minus_b + b * t51;
    const T t60 = t55 * a_minus_b * t56 + T(2) * t50 * a * t59 + t52 * b * t51;
    const T t61 = T(3) * t53 * b * t51 + T(3) * t55 * a_minus_b * t57 + T(4) * t50 * a * t60;
    const T t62 = T(5) * t54 * b * t51 + T(5) * t55 * a_minus_b * t58 + T(2) * t50 * a * t61;
    const T t63 = t53 * t53;
    const T t64 = t57 * t57;
    const T t65 = T(8) * t50 * a * t62 + T(35) * t63 * b * t51 + T(35) * t55 * a_minus_b * t64;
    const T t66 = t65 * t50 * b + T(35) * t63 * t51 - T(35) * t55 * t64;
    const T t67 = T(2) * t49 * b * t66 + T(9) * t50 * t62 - c * t65 * t50;
    const T t68 = T(5) * t54 * t51 + t50 * b * t62 - T(5) * t55 * t58;
    const T t69 = T(2) * t67 * t49 * b + T(9) * t49 * t68 - c * t49 * t66;
    const T t70 = T(7) * t50 * t61 + T(6) * t49 * b * t68 - T(3) * c * t50 * t62;
    const T t71 = T(2) * t49 * t69 * b + T(3) * t49 * t70 - c * t67 * t49;
    const T t72 = t3 * t3;
    const T t73 = t4 * t4;
    const T t74 = t52 * t51 + t50 * t60 * b - t55 * t56;
    const T t75 = T(2) * t49 * b * t74 + T(3) * t50 * t59 - c * t50 * t60;
    const T t76 = t50 * t61 * b + T(3) * t53 * t51 - T(3) * t55 * t57;
    const T t77 = c * t50 * t61 - T(5) * t50 * t60 - T(2) * t76 * t49 * b;
    const T t78 = T(2) * t77 * t49 * b + c * t76 * t49 - T(5) * t49 * t74;
    const T t79 = T(5) * t49 * t75 + c * t77 * t49 - T(2) * t78 * t49 * b;
    const T t80 = T(2) * t49 * t70 * b + T(7) * t76 * t49 - T(3) * c * t49 * t68;
    const T t81 = T(2) * t49 * b * t80 - c * t49 * t70 - T(7) * t77 * t49;
    const T t82 = T(7) * t78 * t49 + c * t49 * t80 - T(2) * t49 * t81 * b;
    const T t83 = T(7) * t79 * t49 - T(2) * t82 * t49 * b - c * t49 * t81;
    const T t84 = c * t49 * t69 - T(2) * t71 * t49 * b - T(3) * t49 * t80;
    const T t85 = T(2) * t49 * b * t84 + c * t71 * t49 - T(3) * t49 * t81;
    const T t86 = T(3) * t82 * t49 + T(2) * t49 * t85 * b - c * t49 * t84;
    const T t87 = t72 * t72;
    const T t88 = t3 * delta_tau;
    const T t89 = t73 * tau_lo;
    const T t90 = t73 * t73;
    const T t91 = t88 * t88;
    const T t92 = t72 * delta_tau;
    const T t93 = t91 * delta_tau;
    G_ap = (T(8) / T(315)) * delta_tau * t48 * t49 * t66 + (T(4) / T(45)) * t67 * t3 * t47 * t49 + (T(2) / T(9)) * t71 * t72 * t73 * t49 + (T(1) / T(315)) * (T(3) * t83 * t49 + c * t49 * t85 - T(2) * t49 * t86 * b) * t87 * t49 + (T(8) / T(45)) * t88 * t89 * t49 * t69 + (T(1) / T(315)) * t65 * t90 * t50 - (T(4) / T(45)) * t91 * t4 * t49 * t85 - (T(8) / T(45)) * t92 * t46 * t49 * t84 - (T(8) / T(315)) * t93 * tau_lo * t49 * t86;
    const T t94 = t51 * t51;
    const T t95 = t94 * t94;
    const T t96 = t95 * t95;
    const T t97 = t96 * t51;
    const T t98 = t55 * t55;
    const T t99 = t98 * t98;
    const T t100 = t99 * t99;
    const T t101 = t100 * t55;
    const T t102 = T(8) * delta_tau * t48 + T(70) * t72 * t73 + T(8) * t93 * tau_lo + T(56) * t92 * t46 + t90 + T(56) * t88 * t89 + t87 + T(28) * t91 * t4 + T(28) * t3 * t47;
    G_E = (T(1) / T(945)) * (T(8) * t87 * (T(7) * t49 * (T(2) * t79 * t49 * b + c * t78 * t49 + T(5) * (T(3) * (t50 * t59 * b + t51 - t55) * t49 + T(2) * t49 * t75 * b - c * t49 * t74) * t49) + c * t82 * t49 + T(2) * t83 * t49 * b) * t49 + T(280) * t92 * t46 * t49 * t81 + T(24) * delta_tau * t48 * t50 * t62 + T(105) * t90 * t97 + T(168) * t3 * t47 * t49 * t68 + T(168) * t88 * t89 * t49 * t70 + T(280) * t72 * t73 * t49 * t80 + T(56) * t93 * tau_lo * t83 * t49 - T(168) * t82 * t91 * t4 * t49 - T(105) * t101 * t102) * t49;
  }
  const T t103 = T(1) / a;
  const T t104 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t103 * sigma2 * (ab_ap * delta_tau + tau_lo * ab_ab) * t104;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T t105 = sigma2 * sigma2;
  const T t106 = t105 * t105;
  const T g_factor = -T(9) * in.sigma * length * t106;
  grad[0] = g_factor * (foot_h0 * G_ap - G_E * ab0);
  grad[1] = (foot_h1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * foot_h2 - G_E * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 151 +, 464 ×, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 48177 +, 73347 ×, 4621 /, 2065 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
    foot0 = t2 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -t2 * (exact_cross[0] * ab2 - exact_cross[2] * ab0);
    foot2 = -(exact_cross[1] * ab0 - exact_cross[0] * ab1) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = t3 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t5 = a_minus_b * b;
  if (t5 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t6 = T(1) / D;
    const T t7 = sqrt(a);
    const T t8 = r1 * b;
    X = t6 * t7 * (t8 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t9 = sqrt(a);
    const T t10 = r1 * b;
    X = -t9 * (a_minus_b - b) / (t10 - r0 * a_minus_b);
  }
  const T t11 = sqrt(a);
  const T t12 = T(1) / t11;
  const T J1 = asinh(X) * t12;
  T F;
  T G_ap;
  T G_E;
  const T t13 = T(4) * D - a * a;
  const T t14 = -a_minus_b * b;
  const T t15 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t13 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t3 * delta_tau;
    const T t17 = t4 * t4;
    const T t18 = t17 * tau_lo;
    const T t19 = t16 * t16;
    const T t20 = t19 * delta_tau;
    const T t21 = t17 * t17;
    const T t22 = t4 * tau_lo;
    const T t23 = t22 * t22;
    const T t24 = t23 * tau_lo;
    const T t25 = t3 * t3;
    const T t26 = t25 * t25;
    const T t27 = t25 * delta_tau;
    F = T(56) * t16 * t18 * M_panels[3] + T(8) * t20 * tau_lo * M_panels[7] + t21 * M_panels[0] + T(28) * t3 * t23 * M_panels[2] + T(8) * delta_tau * t24 * M_panels[1] + T(70) * t25 * t17 * M_panels[4] + T(28) * t19 * t4 * M_panels[6] + t26 * M_panels[8] + T(56) * t27 * t22 * M_panels[5];
    const T t28 = T(28) * t19 * t4 * M_panels[16] + T(8) * t20 * tau_lo * M_panels[17] + t21 * M_panels[10] + T(56) * M_panels[15] * t27 * t22 + t26 * M_panels[18] + T(56) * t16 * t18 * M_panels[13] + T(28) * M_panels[12] * t3 * t23 + T(70) * t25 * t17 * M_panels[14] + T(8) * delta_tau * t24 * M_panels[11];
    G_ap = t28;
    const T t29 = T(1) / a;
    G_E = t26 * M_panels[19] + T(56) * t16 * t18 * M_panels[14] + t21 * M_panels[11] + T(28) * t3 * t23 * M_panels[13] + T(8) * M_panels[12] * delta_tau * t24 + T(28) * t19 * t4 * M_panels[17] + T(56) * t27 * t22 * M_panels[16] + T(70) * M_panels[15] * t25 * t17 + T(8) * t20 * tau_lo * M_panels[18] - t29 * b * t28;
  } else if (t14 >= T(0) && t15 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t30 = t4 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t3 * t3;
    const T t33 = t32 * t32;
    const T t34 = t4 * t4;
    const T t35 = t32 * delta_tau;
    const T t36 = t3 * delta_tau;
    const T t37 = t34 * tau_lo;
    const T t38 = t31 * tau_lo;
    const T t39 = t36 * t36;
    const T t40 = t39 * delta_tau;
    const T t41 = t34 * t34;
    F = T(28) * t3 * t31 * M_panels[2] + t33 * M_panels[8] + T(70) * t32 * t34 * M_panels[4] + T(56) * t35 * t30 * M_panels[5] + T(56) * t36 * t37 * M_panels[3] + T(8) * delta_tau * t38 * M_panels[1] + T(8) * t40 * tau_lo * M_panels[7] + T(28) * t39 * t4 * M_panels[6] + t41 * M_panels[0];
    G_ap = T(56) * t36 * t37 * M_panels[13] + t41 * M_panels[10] + T(28) * t3 * t31 * M_panels[12] + T(8) * M_panels[17] * t40 * tau_lo + T(70) * t32 * t34 * M_panels[14] + T(56) * t35 * t30 * M_panels[15] + T(8) * M_panels[11] * delta_tau * t38 + T(28) * t39 * t4 * M_panels[16] + t33 * M_panels[18];
    const T t42 = T(1) / a;
    const T t43 = T(1) / r0;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t45;
    const T t47 = t46 * t43;
    const T t48 = T(1) / r1;
    const T t49 = t48 * t48;
    const T t50 = t49 * t49;
    const T t51 = t50 * t50;
    const T t52 = t51 * t48;
    const T t53 = T(56) * t35 * t30 + T(8) * t40 * tau_lo + t41 + T(56) * t36 * t37 + T(28) * t39 * t4 + t33 + T(28) * t3 * t31 + T(8) * delta_tau * t38 + T(70) * t32 * t34;
    G_E = (T(1) / T(9)) * t42 * (T(8) * delta_tau * t38 * M_panels[0] + T(56) * t40 * tau_lo * M_panels[6] + t47 * t41 + T(56) * t3 * t31 * M_panels[1] + T(280) * t32 * t34 * M_panels[3] + T(168) * t39 * t4 * M_panels[5] + T(168) * t36 * t37 * M_panels[2] + T(8) * t33 * M_panels[7] + T(280) * t35 * t30 * M_panels[4] - t52 * t53);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t54 = t3 * t3;
    const T t55 = t54 * t54;
    const T t56 = T(1) / a;
    const T t57 = T(1) / r0;
    const T t58 = t57 * t57;
    const T t59 = t58 * t58;
    const T t60 = T(1) / D;
    const T t61 = T(1) / r1;
    const T t62 = t61 * t61;
    const T t63 = t61 * a_minus_b + t57 * b;
    const T t64 = t57 * b * t58 + t61 * a_minus_b * t62 + T(2) * t63 * t60 * a;
    const T t65 = t62 * t62;
    const T t66 = T(4) * t60 * a * t64 + T(3) * t61 * a_minus_b * t65 + T(3) * t57 * b * t59;
    const T t67 = T(3) * t57 * t59 + t60 * b * t66 - T(3) * t61 * t65;
    const T t68 = t61 * t62 - t60 * b * t64 - t57 * t58;
    const T t69 = T(2) * t67 * t56 * b + T(5) * t60 * t64 - t60 * c * t66;
    const T t70 = t67 * t56 * c + T(5) * t56 * t68 - T(2) * t56 * t69 * b;
    const T t71 = t61 - t63 * t60 * b - t57;
    const T t72 = t60 * c * t64 + T(2) * t56 * t68 * b - T(3) * t63 * t60;
    const T t73 = t56 * t68 * c - T(3) * t56 * t71 - T(2) * t56 * t72 * b;
    const T t74 = t56 * t69 * c + T(2) * t56 * t70 * b + T(5) * t56 * t72;
    const T t75 = t56 * t70 * c + T(5) * t56 * t73 - T(2) * t56 * b * t74;
    const T t76 = t59 * t58;
    const T t77 = t65 * t62;
    const T t78 = T(5) * t61 * a_minus_b * t77 + T(2) * t60 * a * t66 + T(5) * t57 * b * t76;
    const T t79 = T(5) * t57 * t76 + t60 * b * t78 - T(5) * t61 * t77;
    const T t80 = T(3) * t60 * t78 * c - T(6) * t56 * b * t79 - T(7) * t60 * t66;
    const T t81 = T(3) * t56 * t79 * c + T(2) * t56 * b * t80 - T(7) * t67 * t56;
    const T t82 = T(2) * t81 * t56 * b - t56 * t80 * c - T(7) * t56 * t69;
    const T t83 = T(7) * t56 * t70 + T(2) * t56 * b * t82 - t81 * t56 * c;
    const T t84 = T(7) * t56 * t74 + T(2) * t56 * t83 * b - t56 * t82 * c;
    const T t85 = T(7) * t56 * t75 + t56 * t83 * c - T(2) * t84 * t56 * b;
    const T t86 = t4 * t4;
    const T t87 = t86 * t86;
    const T t88 = t3 * delta_tau;
    const T t89 = t88 * t88;
    const T t90 = t89 * delta_tau;
    const T t91 = t4 * tau_lo;
    const T t92 = t91 * t91;
    const T t93 = t92 * tau_lo;
    const T t94 = t86 * tau_lo;
    const T t95 = t54 * delta_tau;
    F = (T(1) / T(105)) * t55 * t56 * (T(2) * t85 * t56 * b + t84 * t56 * c + T(7) * t56 * (T(5) * t56 * (T(2) * t56 * b * t73 + t56 * t72 * c - T(3) * t56 * (t63 * t60 * c + T(2) * t56 * b * t71 - J1)) + t56 * t74 * c + T(2) * t56 * t75 * b)) + (T(1) / T(35)) * t87 * t60 * t78 + (T(8) / T(105)) * t85 * t90 * tau_lo * t56 + (T(8) / T(35)) * delta_tau * t93 * t56 * t79 - (T(2) / T(3)) * t54 * t86 * t56 * t82 - (T(4) / T(15)) * t3 * t92 * t56 * t80 - (T(8) / T(15)) * t81 * t88 * t94 * t56 - (T(8) / T(15)) * t95 * t91 * t56 * t83 - (T(4) / T(15)) * t89 * t84 * t4 * t56;
    const T t96 = t65 * t65;
    const T t97 = t59 * t59;
    const T t98 = T(35) * t61 * a_minus_b * t96 + T(8) * t60 * a * t78 + T(35) * t57 * b * t97;
    const T t99 = t98 * t60 * b + T(35) * t57 * t97 - T(35) * t61 * t96;
    const T t100 = T(2) * t56 * b * t99 + T(9) * t60 * t78 - t98 * t60 * c;
    const T t101 = T(2) * t100 * t56 * b + T(9) * t56 * t79 - t56 * c * t99;
    const T t102 = T(3) * t56 * t80 + t100 * t56 * c - T(2) * t56 * t101 * b;
    const T t103 = t56 * t101 * c + T(3) * t81 * t56 + T(2) * t102 * t56 * b;
    const T t104 = t102 * t56 * c - T(2) * t56 * b * t103 - T(3) * t56 * t82;
    const T t105 = T(2) * t104 * t56 * b + t56 * t103 * c - T(3) * t56 * t83;
    G_ap = (T(1) / T(315)) * t98 * t87 * t60 + (T(8) / T(315)) * t90 * t105 * tau_lo * t56 + (T(8) / T(315)) * delta_tau * t93 * t56 * t99 + (T(8) / T(45)) * t88 * t94 * t56 * t101 + (T(1) / T(315)) * t55 * t56 * (T(2) * t105 * t56 * b - t104 * t56 * c - T(3) * t84 * t56) + (T(4) / T(45)) * t104 * t89 * t4 * t56 + (T(4) / T(45)) * t100 * t3 * t92 * t56 - (T(2) / T(9)) * t54 * t102 * t86 * t56 - (T(8) / T(45)) * t95 * t91 * t56 * t103;
    const T t106 = t61 * t61;
    const T t107 = t106 * t106;
    const T t108 = t107 * t107;
    const T t109 = t108 * t61;
    const T t110 = T(56) * t95 * t91 + T(8) * t90 * tau_lo + t87 + T(56) * t88 * t94 + T(28) * t89 * t4 + t55 + T(28) * t3 * t92 + T(8) * delta_tau * t93 + T(70) * t54 * t86;
    const T t111 = t57 * t57;
    const T t112 = t111 * t111;
    const T t113 = t112 * t112;
    const T t114 = t113 * t57;
    G_E = -(T(1) / T(945)) * t56 * (T(280) * t95 * t91 * t56 * t82 + T(280) * t81 * t54 * t86 * t56 + T(105) * t109 * t110 + T(56) * t90 * t84 * tau_lo * t56 + T(168) * t88 * t94 * t56 * t80 + T(168) * t89 * t4 * t56 * t83 - T(105) * t114 * t87 - T(168) * t3 * t92 * t56 * t79 - T(8) * t85 * t55 * t56 - T(24) * delta_tau * t93 * t60 * t78);
  }
  const T t115 = T(1) / a;
  const T t116 = T(1) / ab_ab;
  const T foot_offset = delta_tau * (tau_lo * ab_ab + delta_tau * ab_ap) * t115 * sigma2 * t116;
  const T foot_h0 = ab0 * foot_offset + foot0;
  const T foot_h1 = ab1 * foot_offset + foot1;
  const T foot_h2 = ab2 * foot_offset + foot2;
  const T t117 = sigma2 * sigma2;
  const T t118 = t117 * t117;
  const T g_factor = -T(9) * t118 * in.sigma * length;
  f = t118 * F * in.sigma * length;
  grad[0] = -g_factor * (G_E * ab0 - foot_h0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot_h1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot_h2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 111 +, 306 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 31445 +, 43989 ×, 5083 /, 111 sqrt, 0 atan, 0 log/asinh.
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
  const T a = t1 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t2 = tau_lo * tau_lo;
  const T c = ap_ap + t2 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t2 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t10 * tau_lo;
    const T t12 = t1 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t13 * delta_tau;
    const T t15 = t2 * t2;
    const T t16 = t15 * tau_lo;
    const T t17 = t15 * t15;
    const T t18 = t17 * tau_lo;
    const T t19 = t6 * delta_tau;
    F = T(9) * t7 * tau_lo * M_panels[8] + M_panels[9] * t8 + T(36) * t1 * t11 * M_panels[2] + T(36) * t14 * t2 * M_panels[7] + T(126) * t6 * t16 * M_panels[4] + M_panels[0] * t18 + T(84) * M_panels[3] * t12 * t10 + T(9) * delta_tau * t17 * M_panels[1] + T(84) * t13 * M_panels[6] * t9 + T(126) * t19 * t15 * M_panels[5];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t2 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t21 * tau_lo;
    const T t23 = t2 * t2;
    const T t24 = t23 * t23;
    const T t25 = t1 * t1;
    const T t26 = t25 * delta_tau;
    const T t27 = t1 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t25 * t25;
    const T t31 = t30 * delta_tau;
    const T t32 = t23 * tau_lo;
    const T t33 = t24 * tau_lo;
    F = T(36) * t1 * t22 * M_panels[2] + T(9) * delta_tau * t24 * M_panels[1] + T(126) * t26 * t23 * M_panels[5] + T(36) * t29 * t2 * M_panels[7] + t31 * M_panels[9] + T(84) * t27 * t21 * M_panels[3] + T(9) * t30 * tau_lo * M_panels[8] + T(126) * t25 * t32 * M_panels[4] + T(84) * t28 * t20 * M_panels[6] + t33 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = sqrt(D);
    const T t35 = T(1) / t34;
    const T J2 = t35 * atan2(t34, c_minus_b);
    const T t36 = T(1) / c;
    const T log_ratio = log(t36 * q1);
    const T t37 = t1 * delta_tau;
    const T t38 = t37 * t37;
    const T t39 = t38 * delta_tau;
    const T t40 = T(1) / a;
    const T t41 = T(1) / D;
    const T t42 = T(1) / q1;
    const T t43 = t42 * a_minus_b + a * J2 + t36 * b;
    const T t44 = t36 * t36;
    const T t45 = t42 * t42;
    const T t46 = T(2) * t44 * b + T(2) * t45 * a_minus_b + T(3) * t41 * a * t43;
    const T t47 = T(2) * t44 + t41 * t46 * b - T(2) * t45;
    const T t48 = T(4) * t41 * t43 + T(2) * t40 * t47 * b - c * t41 * t46;
    const T t49 = t44 * t36;
    const T t50 = t45 * t42;
    const T t51 = T(8) * t49 * b + T(5) * t41 * a * t46 + T(8) * t50 * a_minus_b;
    const T t52 = T(8) * t49 + t41 * t51 * b - T(8) * t50;
    const T t53 = T(6) * t41 * t46 + T(2) * t52 * t40 * b - c * t41 * t51;
    const T t54 = T(6) * t40 * t47 + T(2) * t53 * t40 * b - c * t52 * t40;
    const T t55 = T(6) * t48 * t40 + T(2) * t54 * t40 * b - c * t53 * t40;
    const T t56 = t44 * t44;
    const T t57 = t45 * t45;
    const T t58 = T(48) * t57 * a_minus_b + T(48) * t56 * b + T(7) * t41 * a * t51;
    const T t59 = T(48) * t56 + t41 * b * t58 - T(48) * t57;
    const T t60 = T(8) * t41 * t51 + T(2) * t59 * t40 * b - c * t41 * t58;
    const T t61 = T(8) * t52 * t40 + T(2) * t40 * t60 * b - c * t59 * t40;
    const T t62 = T(8) * t53 * t40 + T(2) * t40 * b * t61 - c * t40 * t60;
    const T t63 = T(2) * t40 * t62 * b + T(8) * t54 * t40 - c * t40 * t61;
    const T t64 = T(8) * t40 * t55 + T(2) * t40 * t63 * b - c * t40 * t62;
    const T t65 = t42 - t36 - t41 * b * t43;
    const T t66 = T(4) * t40 * t65 + c * t40 * t47 - T(2) * t48 * t40 * b;
    const T t67 = c * t54 * t40 + T(6) * t66 * t40 - T(2) * t40 * t55 * b;
    const T t68 = T(2) * t40 * t64 * b - c * t40 * t63 - T(8) * t40 * t67;
    const T t69 = t2 * tau_lo;
    const T t70 = t69 * t69;
    const T t71 = t70 * tau_lo;
    const T t72 = t1 * t1;
    const T t73 = t72 * delta_tau;
    const T t74 = t2 * t2;
    const T t75 = t74 * tau_lo;
    const T t76 = t74 * t74;
    const T t77 = t76 * tau_lo;
    const T t78 = t72 * t72;
    const T t79 = t78 * delta_tau;
    const T t80 = c * t41 * t43 + T(2) * t40 * t65 * b - T(2) * J2;
    const T t81 = c * t48 * t40 + T(2) * t66 * t40 * b + T(4) * t40 * t80;
    const T t82 = c * t40 * t55 + T(6) * t81 * t40 + T(2) * t40 * t67 * b;
    const T t83 = T(8) * t40 * t82 + c * t40 * t64 - T(2) * t68 * t40 * b;
    F = (T(3) / T(32)) * t39 * t2 * t68 * t40 + (T(3) / T(32)) * t1 * t71 * t40 * t60 + (T(7) / T(32)) * t37 * t70 * t40 * t61 + (T(21) / T(64)) * t73 * t74 * t40 * t63 + (T(21) / T(64)) * t72 * t75 * t40 * t62 + (T(3) / T(128)) * delta_tau * t59 * t76 * t40 + (T(7) / T(32)) * t38 * t69 * t40 * t64 + (T(1) / T(384)) * t77 * t41 * t58 - (T(1) / T(384)) * t79 * t40 * (T(2) * t40 * t83 * b + c * t68 * t40 - T(8) * t40 * (c * t40 * t67 + T(6) * (c * t66 * t40 + T(4) * t40 * (c * t40 * t65 + t40 * (T(2) * J2 * b + log_ratio) - T(2) * t40 * t80 * b) - T(2) * t81 * t40 * b) * t40 - T(2) * t40 * b * t82)) - (T(3) / T(128)) * t78 * tau_lo * t40 * t83;
  }
  const T t84 = sigma2 * sigma2;
  const T t85 = t84 * t84;
  const T t86 = t85 * sigma2;
  f = length * t86 * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 151 +, 428 ×, 8 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 47854 +, 61960 ×, 4243 /, 93 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
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
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
    const T t2 = T(1) / ab_ab;
    foot0 = t2 * (exact_cross[1] * ab2 - exact_cross[2] * ab1);
    foot1 = -(ab2 * exact_cross[0] - exact_cross[2] * ab0) * t2;
    foot2 = (ab1 * exact_cross[0] - exact_cross[1] * ab0) * t2;
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = ap_ap + t4 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * a * min(T(c), T(q1)) - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * t3;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t4 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t3 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t15 * delta_tau;
    const T t17 = t4 * t4;
    const T t18 = t17 * tau_lo;
    const T t19 = t17 * t17;
    const T t20 = t19 * tau_lo;
    const T t21 = t8 * delta_tau;
    const T t22 = t10 * M_panels[20] + T(9) * t9 * tau_lo * M_panels[19] + T(36) * t3 * t13 * M_panels[13] + T(36) * M_panels[18] * t16 * t4 + T(84) * t14 * t12 * M_panels[14] + T(84) * t15 * t11 * M_panels[17] + T(126) * t8 * M_panels[15] * t18 + t20 * M_panels[11] + T(9) * M_panels[12] * delta_tau * t19 + T(126) * t21 * t17 * M_panels[16];
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = M_panels[21] * t10 + T(84) * t14 * M_panels[15] * t12 + T(84) * M_panels[18] * t15 * t11 + T(9) * t9 * tau_lo * M_panels[20] + T(9) * delta_tau * t19 * M_panels[13] + T(126) * t21 * t17 * M_panels[17] + T(126) * t8 * t18 * M_panels[16] + M_panels[12] * t20 + T(36) * t3 * t13 * M_panels[14] + T(36) * t16 * t4 * M_panels[19] - t23 * t22 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t3 * t3;
    const T t25 = t24 * t24;
    const T t26 = t25 * delta_tau;
    const T t27 = t3 * delta_tau;
    const T t28 = t4 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = t27 * t27;
    const T t31 = t4 * t4;
    const T t32 = t31 * t31;
    const T t33 = t32 * tau_lo;
    const T t34 = t29 * tau_lo;
    const T t35 = t31 * tau_lo;
    const T t36 = t30 * delta_tau;
    const T t37 = t24 * delta_tau;
    G_ap = t26 * M_panels[20] + T(84) * t27 * t29 * M_panels[14] + T(9) * t25 * tau_lo * M_panels[19] + T(84) * t30 * t28 * M_panels[17] + T(9) * delta_tau * M_panels[12] * t32 + t33 * M_panels[11] + T(36) * t3 * t34 * M_panels[13] + T(126) * M_panels[15] * t24 * t35 + T(36) * M_panels[18] * t36 * t4 + T(126) * t37 * t31 * M_panels[16];
    const T t38 = T(1) / a;
    const T t39 = T(1) / c;
    const T t40 = t39 * t39;
    const T t41 = t40 * t40;
    const T t42 = t41 * t39;
    const T t43 = T(1) / q1;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t43;
    const T t47 = T(126) * t37 * t31 + T(126) * t24 * t35 + t26 + t33 + T(36) * t36 * t4 + T(84) * t30 * t28 + T(36) * t3 * t34 + T(9) * delta_tau * t32 + T(9) * t25 * tau_lo + T(84) * t27 * t29;
    G_E = (T(1) / T(10)) * t38 * (T(630) * t37 * t31 * M_panels[4] + T(72) * t3 * t34 * M_panels[1] + T(9) * delta_tau * t32 * M_panels[0] + T(252) * t27 * t29 * M_panels[2] + T(9) * t26 * M_panels[8] + T(504) * t30 * t28 * M_panels[5] + T(252) * t36 * M_panels[6] * t4 + T(504) * t24 * t35 * M_panels[3] + T(72) * t25 * tau_lo * M_panels[7] + t33 * t42 - t46 * t47);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = sqrt(D);
    const T t49 = T(1) / t48;
    const T J2 = t49 * atan2(t48, c_minus_b);
    const T t50 = t3 * t3;
    const T t51 = t50 * delta_tau;
    const T t52 = t4 * t4;
    const T t53 = T(1) / a;
    const T t54 = T(1) / D;
    const T t55 = T(1) / c;
    const T t56 = T(1) / q1;
    const T t57 = b * t55 + a_minus_b * t56 + a * J2;
    const T t58 = t56 * t56;
    const T t59 = t55 * t55;
    const T t60 = T(3) * t54 * a * t57 + T(2) * a_minus_b * t58 + T(2) * b * t59;
    const T t61 = t58 * t56;
    const T t62 = t59 * t55;
    const T t63 = T(5) * t54 * a * t60 + T(8) * a_minus_b * t61 + T(8) * b * t62;
    const T t64 = t54 * t63 * b + T(8) * t62 - T(8) * t61;
    const T t65 = t59 * t59;
    const T t66 = t58 * t58;
    const T t67 = T(48) * b * t65 + T(7) * t54 * t63 * a + T(48) * a_minus_b * t66;
    const T t68 = t54 * t67 * b + T(48) * t65 - T(48) * t66;
    const T t69 = T(8) * t54 * t63 + T(2) * t53 * b * t68 - t54 * t67 * c;
    const T t70 = T(8) * t64 * t53 + T(2) * t69 * t53 * b - t53 * c * t68;
    const T t71 = t65 * t55;
    const T t72 = t66 * t56;
    const T t73 = T(128) * b * t71 + T(128) * a_minus_b * t72 + T(3) * t54 * t67 * a;
    const T t74 = t54 * t73 * b + T(128) * t71 - T(128) * t72;
    const T t75 = T(10) * t54 * t67 + T(6) * t74 * t53 * b - T(3) * t54 * t73 * c;
    const T t76 = T(3) * t74 * t53 * c - T(10) * t53 * t68 - T(2) * t75 * t53 * b;
    const T t77 = T(10) * t69 * t53 - t75 * t53 * c - T(2) * t53 * b * t76;
    const T t78 = T(10) * t70 * t53 + T(2) * t53 * t77 * b + t53 * c * t76;
    const T t79 = t52 * tau_lo;
    const T t80 = t52 * t52;
    const T t81 = t50 * t50;
    const T t82 = t81 * delta_tau;
    const T t83 = T(2) * t64 * t53 * b + T(6) * t54 * t60 - t54 * t63 * c;
    const T t84 = t69 * t53 * c - T(8) * t53 * t83 - T(2) * t70 * t53 * b;
    const T t85 = t54 * b * t60 + T(2) * t59 - T(2) * t58;
    const T t86 = t64 * t53 * c - T(6) * t53 * t85 - T(2) * t53 * t83 * b;
    const T t87 = t70 * t53 * c + T(2) * t53 * b * t84 + T(8) * t53 * t86;
    const T t88 = T(2) * t53 * t78 * b - T(10) * t53 * t84 - t53 * t77 * c;
    const T t89 = t53 * t78 * c + T(10) * t87 * t53 - T(2) * t53 * b * t88;
    const T t90 = T(4) * t54 * t57 + T(2) * t53 * b * t85 - t54 * t60 * c;
    const T t91 = T(2) * t53 * b * t86 + t53 * t83 * c - T(6) * t53 * t90;
    const T t92 = t53 * t84 * c - T(2) * t87 * t53 * b - T(8) * t91 * t53;
    const T t93 = t53 * t88 * c + T(2) * t89 * t53 * b - T(10) * t53 * t92;
    const T t94 = t56 - t55 - t54 * t57 * b;
    const T t95 = t53 * t85 * c + T(4) * t53 * t94 - T(2) * t53 * t90 * b;
    const T t96 = T(2) * t91 * t53 * b + T(6) * t53 * t95 - t53 * t86 * c;
    const T t97 = T(8) * t53 * t96 - t87 * t53 * c - T(2) * t53 * b * t92;
    const T t98 = t3 * delta_tau;
    const T t99 = t98 * t98;
    const T t100 = t4 * tau_lo;
    const T t101 = t100 * t100;
    const T t102 = t101 * tau_lo;
    const T t103 = t80 * tau_lo;
    const T t104 = t99 * delta_tau;
    G_ap = (T(21) / T(640)) * t51 * t52 * t53 * t78 + (T(21) / T(640)) * t50 * t79 * t53 * t77 + (T(9) / T(1280)) * delta_tau * t74 * t80 * t53 + (T(1) / T(3840)) * t82 * t53 * (t89 * t53 * c - T(2) * t53 * b * t93 - T(10) * t53 * t97) + (T(7) / T(320)) * t99 * t100 * t53 * t88 + (T(3) / T(320)) * t75 * t3 * t102 * t53 + (T(1) / T(1280)) * t54 * t103 * t73 - (T(3) / T(320)) * t104 * t89 * t4 * t53 - (T(3) / T(1280)) * t81 * tau_lo * t53 * t93 - (T(7) / T(320)) * t98 * t101 * t53 * t76;
    const T t105 = T(126) * t51 * t52 + T(126) * t50 * t79 + t82 + t103 + T(36) * t104 * t4 + T(84) * t99 * t100 + T(36) * t3 * t102 + T(9) * delta_tau * t80 + T(9) * t81 * tau_lo + T(84) * t98 * t101;
    G_E = -(T(1) / T(1280)) * (T(24) * t81 * tau_lo * t53 * t97 + T(168) * t99 * t87 * t100 * t53 + T(128) * t72 * t105 + T(3) * t82 * t53 * (T(2) * t53 * b * t97 + T(8) * t53 * (T(6) * t53 * (t53 * t90 * c + T(4) * t53 * (T(2) * t53 * t94 * b + t54 * t57 * c - T(2) * J2) + T(2) * t53 * t95 * b) + T(2) * t53 * t96 * b - t91 * t53 * c) + t53 * c * t92) + T(210) * t51 * t52 * t53 * t84 - T(84) * t104 * t4 * t53 * t92 - T(168) * t70 * t50 * t79 * t53 - T(3) * t54 * delta_tau * t80 * t67 - T(84) * t69 * t98 * t101 * t53 - T(24) * t3 * t102 * t53 * t68 - T(128) * t103 * t71) * t53;
  }
  const T t106 = T(1) / a;
  const T t107 = T(1) / ab_ab;
  const T foot_offset = delta_tau * t106 * (delta_tau * ab_ap + tau_lo * ab_ab) * sigma2 * t107;
  const T foot_h0 = foot0 + foot_offset * ab0;
  const T foot_h1 = foot1 + foot_offset * ab1;
  const T foot_h2 = foot2 + foot_offset * ab2;
  const T t108 = sigma2 * sigma2;
  const T t109 = t108 * t108;
  const T t110 = t109 * sigma2;
  const T g_factor = -T(10) * t110 * length;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot_h0);
  grad[1] = g_factor * (G_ap * foot_h1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 169 +, 498 ×, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 47863 +, 61988 ×, 4243 /, 93 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
    foot1 = t2 * (exact_cross[2] * ab0 - ab2 * exact_cross[0]);
    foot2 = -t2 * (ab0 * exact_cross[1] - ab1 * exact_cross[0]);
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t3 = delta_tau * delta_tau;
  const T a = ab_ab + t3 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t4 = tau_lo * tau_lo;
  const T c = t4 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T F;
  T G_ap;
  T G_E;
  const T t5 = T(4) * D - a * a;
  const T t6 = -a_minus_b * b;
  const T t7 = max(T((T(7) / T(10)) * min(T(c), T(q1)) * a - D), T(T(100) * D - a * a));
  if (t5 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t3 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t4 * tau_lo;
    const T t12 = t11 * t11;
    const T t13 = t12 * tau_lo;
    const T t14 = t4 * t4;
    const T t15 = t14 * t14;
    const T t16 = t15 * tau_lo;
    const T t17 = t3 * t3;
    const T t18 = t14 * tau_lo;
    const T t19 = t17 * t17;
    const T t20 = t19 * delta_tau;
    const T t21 = t17 * delta_tau;
    F = T(36) * M_panels[7] * t10 * t4 + T(36) * t3 * t13 * M_panels[2] + T(84) * t8 * t12 * M_panels[3] + t16 * M_panels[0] + T(84) * M_panels[6] * t9 * t11 + T(9) * M_panels[1] * delta_tau * t15 + T(126) * M_panels[4] * t17 * t18 + t20 * M_panels[9] + T(9) * t19 * tau_lo * M_panels[8] + T(126) * t21 * M_panels[5] * t14;
    const T t22 = T(9) * delta_tau * t15 * M_panels[12] + T(9) * M_panels[19] * t19 * tau_lo + T(126) * M_panels[16] * t21 * t14 + T(84) * M_panels[17] * t9 * t11 + T(36) * M_panels[13] * t3 * t13 + T(84) * t8 * M_panels[14] * t12 + t16 * M_panels[11] + T(126) * t17 * t18 * M_panels[15] + M_panels[20] * t20 + T(36) * t10 * t4 * M_panels[18];
    G_ap = t22;
    const T t23 = T(1) / a;
    G_E = T(9) * M_panels[13] * delta_tau * t15 + T(84) * t8 * t12 * M_panels[15] + T(36) * M_panels[19] * t10 * t4 + t20 * M_panels[21] + T(9) * M_panels[20] * t19 * tau_lo + t16 * M_panels[12] + T(126) * M_panels[16] * t17 * t18 + T(126) * M_panels[17] * t21 * t14 + T(36) * t3 * M_panels[14] * t13 + T(84) * t9 * t11 * M_panels[18] - t23 * t22 * b;
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t24 = t4 * t4;
    const T t25 = t24 * t24;
    const T t26 = t25 * tau_lo;
    const T t27 = t3 * t3;
    const T t28 = t27 * delta_tau;
    const T t29 = t4 * tau_lo;
    const T t30 = t29 * t29;
    const T t31 = t30 * tau_lo;
    const T t32 = t3 * delta_tau;
    const T t33 = t27 * t27;
    const T t34 = t32 * t32;
    const T t35 = t24 * tau_lo;
    const T t36 = t33 * delta_tau;
    const T t37 = t34 * delta_tau;
    F = M_panels[0] * t26 + T(126) * t28 * t24 * M_panels[5] + T(36) * t3 * t31 * M_panels[2] + T(84) * M_panels[3] * t32 * t30 + T(9) * t33 * tau_lo * M_panels[8] + T(84) * t34 * t29 * M_panels[6] + T(126) * M_panels[4] * t27 * t35 + t36 * M_panels[9] + T(36) * M_panels[7] * t37 * t4 + T(9) * M_panels[1] * delta_tau * t25;
    G_ap = T(36) * M_panels[13] * t3 * t31 + T(9) * M_panels[19] * t33 * tau_lo + T(126) * M_panels[16] * t28 * t24 + M_panels[20] * t36 + T(9) * delta_tau * t25 * M_panels[12] + T(84) * M_panels[17] * t34 * t29 + T(126) * t27 * t35 * M_panels[15] + M_panels[11] * t26 + T(84) * M_panels[14] * t32 * t30 + T(36) * t37 * t4 * M_panels[18];
    const T t38 = T(1) / a;
    const T t39 = T(1) / c;
    const T t40 = t39 * t39;
    const T t41 = t40 * t40;
    const T t42 = t41 * t39;
    const T t43 = T(1) / q1;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t43;
    const T t47 = T(126) * t27 * t35 + T(126) * t28 * t24 + t26 + T(36) * t3 * t31 + T(36) * t37 * t4 + T(84) * t34 * t29 + T(9) * t33 * tau_lo + T(84) * t32 * t30 + t36 + T(9) * delta_tau * t25;
    G_E = (T(1) / T(10)) * t38 * (T(504) * t34 * t29 * M_panels[5] + T(9) * t36 * M_panels[8] + T(504) * M_panels[3] * t27 * t35 + T(9) * M_panels[0] * delta_tau * t25 + t42 * t26 + T(252) * t37 * t4 * M_panels[6] + T(72) * M_panels[1] * t3 * t31 + T(72) * M_panels[7] * t33 * tau_lo + T(252) * t32 * t30 * M_panels[2] + T(630) * M_panels[4] * t28 * t24 - t46 * t47);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = sqrt(D);
    const T t49 = T(1) / t48;
    const T J2 = t49 * atan2(t48, c_minus_b);
    const T t50 = T(1) / c;
    const T log_ratio = log(q1 * t50);
    const T t51 = t4 * tau_lo;
    const T t52 = t51 * t51;
    const T t53 = t52 * tau_lo;
    const T t54 = T(1) / a;
    const T t55 = T(1) / D;
    const T t56 = t50 * t50;
    const T t57 = t56 * t50;
    const T t58 = T(1) / q1;
    const T t59 = t58 * t58;
    const T t60 = t59 * t58;
    const T t61 = t58 * a_minus_b + J2 * a + t50 * b;
    const T t62 = T(3) * t55 * a * t61 + T(2) * t56 * b + T(2) * t59 * a_minus_b;
    const T t63 = T(8) * t57 * b + T(8) * t60 * a_minus_b + T(5) * t55 * t62 * a;
    const T t64 = t59 * t59;
    const T t65 = t56 * t56;
    const T t66 = T(48) * t64 * a_minus_b + T(48) * t65 * b + T(7) * t55 * a * t63;
    const T t67 = T(48) * t64 - t66 * t55 * b - T(48) * t65;
    const T t68 = T(8) * t55 * t63 - T(2) * t54 * t67 * b - c * t66 * t55;
    const T t69 = t3 * t3;
    const T t70 = t69 * t69;
    const T t71 = t55 * t62 * b + T(2) * t56 - T(2) * t59;
    const T t72 = c * t55 * t62 - T(4) * t55 * t61 - T(2) * t54 * b * t71;
    const T t73 = T(8) * t57 + t55 * t63 * b - T(8) * t60;
    const T t74 = T(6) * t55 * t62 + T(2) * t73 * t54 * b - c * t55 * t63;
    const T t75 = T(6) * t54 * t71 + T(2) * t74 * t54 * b - c * t73 * t54;
    const T t76 = T(6) * t54 * t72 + c * t74 * t54 - T(2) * t75 * t54 * b;
    const T t77 = T(8) * t73 * t54 + c * t54 * t67 + T(2) * t54 * b * t68;
    const T t78 = T(8) * t74 * t54 + T(2) * t77 * t54 * b - c * t54 * t68;
    const T t79 = T(2) * t54 * t78 * b + T(8) * t75 * t54 - t77 * c * t54;
    const T t80 = T(8) * t76 * t54 + c * t54 * t78 - T(2) * t54 * b * t79;
    const T t81 = t55 * t61 * b + t50 - t58;
    const T t82 = T(2) * t54 * t72 * b + c * t54 * t71 - T(4) * t54 * t81;
    const T t83 = c * t75 * t54 + T(6) * t82 * t54 + T(2) * t76 * t54 * b;
    const T t84 = T(2) * t80 * t54 * b + T(8) * t83 * t54 + c * t54 * t79;
    const T t85 = T(2) * J2 + T(2) * t54 * t81 * b - c * t55 * t61;
    const T t86 = T(2) * t82 * t54 * b - T(4) * t54 * t85 - c * t54 * t72;
    const T t87 = T(2) * t83 * t54 * b + T(6) * t54 * t86 - t76 * c * t54;
    const T t88 = c * t80 * t54 - T(2) * t54 * t84 * b - T(8) * t54 * t87;
    const T t89 = t70 * delta_tau;
    const T t90 = t3 * delta_tau;
    const T t91 = t4 * t4;
    const T t92 = t91 * tau_lo;
    const T t93 = t91 * t91;
    const T t94 = t93 * tau_lo;
    const T t95 = t69 * delta_tau;
    const T t96 = t90 * t90;
    const T t97 = t96 * delta_tau;
    F = (T(3) / T(32)) * t3 * t53 * t54 * t68 + (T(3) / T(128)) * t70 * t88 * tau_lo * t54 + (T(1) / T(384)) * (c * t54 * t84 + T(8) * t54 * (t83 * c * t54 - T(6) * t54 * (T(2) * t54 * t86 * b - T(4) * t54 * ((T(2) * J2 * b + log_ratio) * t54 + T(2) * t54 * b * t85 - c * t54 * t81) - c * t82 * t54) - T(2) * t54 * t87 * b) + T(2) * t88 * t54 * b) * t89 * t54 + (T(7) / T(32)) * t77 * t90 * t52 * t54 + (T(21) / T(64)) * t69 * t92 * t54 * t78 + (T(1) / T(384)) * t66 * t55 * t94 + (T(21) / T(64)) * t95 * t91 * t54 * t79 - (T(3) / T(32)) * t97 * t4 * t54 * t84 - (T(3) / T(128)) * delta_tau * t93 * t54 * t67 - (T(7) / T(32)) * t80 * t96 * t51 * t54;
    const T t98 = t64 * t58;
    const T t99 = t65 * t50;
    const T t100 = T(128) * t98 * a_minus_b + T(3) * t66 * t55 * a + T(128) * t99 * b;
    const T t101 = T(128) * t98 - T(128) * t99 - t100 * t55 * b;
    const T t102 = T(10) * t66 * t55 - T(3) * c * t100 * t55 - T(6) * t54 * b * t101;
    const T t103 = T(10) * t54 * t67 - T(2) * t54 * t102 * b - T(3) * c * t54 * t101;
    const T t104 = c * t54 * t102 + T(2) * t54 * t103 * b - T(10) * t54 * t68;
    const T t105 = T(2) * t104 * t54 * b - T(10) * t77 * t54 - c * t54 * t103;
    const T t106 = t104 * c * t54 + T(10) * t54 * t78 - T(2) * t54 * t105 * b;
    const T t107 = T(10) * t54 * t79 + T(2) * t54 * b * t106 + c * t54 * t105;
    const T t108 = c * t54 * t106 + T(10) * t80 * t54 - T(2) * t54 * b * t107;
    G_ap = (T(3) / T(320)) * t3 * t53 * t54 * t102 + (T(7) / T(320)) * t96 * t51 * t54 * t106 + (T(1) / T(1280)) * t100 * t55 * t94 + (T(3) / T(320)) * t97 * t4 * t54 * t107 - (T(3) / T(1280)) * t108 * t70 * tau_lo * t54 - (T(7) / T(320)) * t90 * t52 * t54 * t103 - (T(9) / T(1280)) * delta_tau * t93 * t54 * t101 - (T(21) / T(640)) * t104 * t69 * t92 * t54 - (T(21) / T(640)) * t95 * t91 * t54 * t105 - (T(1) / T(3840)) * (c * t54 * t107 + T(2) * t108 * t54 * b + T(10) * t54 * t84) * t89 * t54;
    const T t109 = T(126) * t69 * t92 + T(126) * t95 * t91 + t94 + T(36) * t3 * t53 + T(36) * t97 * t4 + T(84) * t96 * t51 + T(9) * t70 * tau_lo + T(84) * t90 * t52 + t89 + T(9) * delta_tau * t93;
    G_E = (T(1) / T(1280)) * (T(3) * t89 * t88 * t54 + T(168) * t77 * t69 * t92 * t54 + T(84) * t90 * t52 * t54 * t68 + T(210) * t95 * t91 * t54 * t78 + T(128) * t99 * t94 + T(168) * t96 * t51 * t54 * t79 + T(3) * t66 * t55 * delta_tau * t93 - T(24) * t3 * t53 * t54 * t67 - T(128) * t98 * t109 - T(24) * t70 * tau_lo * t54 * t84 - T(84) * t80 * t97 * t4 * t54) * t54;
  }
  const T t110 = T(1) / ab_ab;
  const T t111 = T(1) / a;
  const T foot_offset = t110 * delta_tau * t111 * (ab_ab * tau_lo + ab_ap * delta_tau) * sigma2;
  const T foot_h0 = foot_offset * ab0 + foot0;
  const T foot_h1 = foot_offset * ab1 + foot1;
  const T foot_h2 = foot_offset * ab2 + foot2;
  const T t112 = sigma2 * sigma2;
  const T t113 = t112 * t112;
  const T t114 = t113 * sigma2;
  const T g_factor = -T(10) * length * t114;
  f = length * t114 * F;
  grad[0] = (G_ap * foot_h0 - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot_h1 - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (G_ap * foot_h2 - ab2 * G_E);
  return f;
}

}  // namespace skelconv::generated
