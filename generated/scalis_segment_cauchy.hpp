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

#include <skelconv/gauss_moments.hpp>
#include <skelconv/scalis_segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 43 +, 62 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 6982 +, 8918 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = sigma2 * delta_tau * delta_tau + ab_ab;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T c = sigma2 * tau_lo * tau_lo + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = T(4) * D - a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 2> M_panels;
    segment_moments_gauss_panels<T>(2, 2, 1, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[1] * delta_tau + M_panels[0] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T J2 = atan2(t3, c_minus_b) / t3;
    F = (T(1) / T(2)) * (log_ratio + T(2) * J2 * b) * delta_tau / a + tau_lo * J2;
  }
  f = sigma2 * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 52 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 8066 +, 11089 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  T G_ap;
  T G_ab;
  const T t0 = T(4) * D - a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 2, a, b, a_minus_b, D, M_panels.data());
    G_ap = delta_tau * M_panels[1] + tau_lo * M_panels[0];
    G_ab = tau_lo * M_panels[1] + delta_tau * M_panels[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 2, a, b, a_minus_b, D, M_panels.data());
    G_ap = M_panels[0] * tau_lo + delta_tau * M_panels[1];
    G_ab = tau_lo * M_panels[1] + delta_tau * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = a_minus_b * t6 + b * t7 + a * J2;
    const T t9 = T(1) / a;
    const T t10 = t7 + t5 * t8 * b - t6;
    G_ap = (T(1) / T(2)) * t5 * tau_lo * t8 + (T(1) / T(2)) * t9 * delta_tau * t10;
    G_ab = (T(1) / T(2)) * t9 * tau_lo * t10 + (T(1) / T(2)) * (T(2) * t9 * b * t10 + T(2) * J2 - t5 * t8 * c) * t9 * delta_tau;
  }
  const T g_factor = -T(2) * sigma2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 54 +, 99 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11307 +, 15414 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(4) * D - a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = delta_tau * M_panels[1] + tau_lo * M_panels[0];
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ab = tau_lo * M_panels[4] + M_panels[5] * delta_tau;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(2, 4, 2, a, b, a_minus_b, D, M_panels.data());
    F = tau_lo * M_panels[0] + delta_tau * M_panels[1];
    G_ap = tau_lo * M_panels[3] + delta_tau * M_panels[4];
    G_ab = tau_lo * M_panels[4] + M_panels[5] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(1) / a;
    F = (T(1) / T(2)) * t6 * delta_tau * (log_ratio + T(2) * b * J2) + tau_lo * J2;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = a_minus_b * t8 + a * J2 + b * t0;
    const T t10 = t0 + t7 * t9 * b - t8;
    G_ap = (T(1) / T(2)) * t6 * delta_tau * t10 + (T(1) / T(2)) * t7 * t9 * tau_lo;
    G_ab = (T(1) / T(2)) * t6 * delta_tau * (T(2) * t6 * b * t10 + T(2) * J2 - t7 * t9 * c) + (T(1) / T(2)) * t6 * tau_lo * t10;
  }
  const T g_factor = -T(2) * sigma2 * length;
  f = F * sigma2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 46 +, 76 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 8061 +, 12163 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = b * r1;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + r0 * a_minus_b) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = b * r1;
    X = t6 * (b - a_minus_b) / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  const T t10 = T(4) * D - a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t0 * M_panels[2] + T(2) * M_panels[1] * delta_tau * tau_lo + t1 * M_panels[0];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 3> M_panels;
    segment_moments_gauss_panels<T>(3, 3, 2, a, b, a_minus_b, D, M_panels.data());
    F = t0 * M_panels[2] + t1 * M_panels[0] + T(2) * M_panels[1] * delta_tau * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = t15 * b + t16 * a_minus_b;
    const T t18 = t14 * t17 * b + t15 - t16;
    F = (J1 + T(2) * t13 * b * t18 - t14 * t17 * c) * t0 * t13 + T(2) * delta_tau * t13 * tau_lo * t18 + t14 * t17 * t1;
  }
  f = length * F * sigma2 * in.sigma;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 56 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 9145 +, 15411 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 3, a, b, a_minus_b, D, M_panels.data());
    G_ap = T(2) * delta_tau * tau_lo * M_panels[1] + t0 * M_panels[2] + t1 * M_panels[0];
    G_ab = t1 * M_panels[1] + T(2) * delta_tau * tau_lo * M_panels[2] + M_panels[3] * t0;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 3, a, b, a_minus_b, D, M_panels.data());
    G_ap = t0 * M_panels[2] + T(2) * delta_tau * tau_lo * M_panels[1] + M_panels[0] * t1;
    G_ab = M_panels[3] * t0 + t1 * M_panels[1] + T(2) * delta_tau * tau_lo * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = b * t6 + t8 * a_minus_b;
    const T t11 = b * t6 * t7 + t8 * a_minus_b * t9 + T(2) * t5 * a * t10;
    const T t12 = t6 * t7 + t5 * b * t11 - t8 * t9;
    const T t13 = T(1) / a;
    const T t14 = t5 * t11 * c - T(2) * t12 * t13 * b - T(3) * t5 * t10;
    G_ap = (T(1) / T(3)) * t5 * t1 * t11 + (T(2) / T(3)) * t12 * delta_tau * t13 * tau_lo - (T(1) / T(3)) * t0 * t13 * t14;
    G_ab = (T(1) / T(3)) * (T(3) * t13 * (t5 * b * t10 + t6 - t8) - T(2) * t13 * t14 * b - t12 * t13 * c) * t0 * t13 + (T(1) / T(3)) * t12 * t13 * t1 - (T(2) / T(3)) * delta_tau * t13 * tau_lo * t14;
  }
  const T g_factor = -T(3) * in.sigma * sigma2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 61 +, 135 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 13468 +, 20825 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = t3 * t4 * (t5 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r1 * b;
    X = -t6 * (a_minus_b - b) / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t10 = T(4) * D - a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[0] * t1 + t0 * M_panels[2] + T(2) * M_panels[1] * delta_tau * tau_lo;
    G_ap = M_panels[4] * t1 + t0 * M_panels[6] + T(2) * delta_tau * tau_lo * M_panels[5];
    G_ab = T(2) * delta_tau * tau_lo * M_panels[6] + M_panels[7] * t0 + t1 * M_panels[5];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(3, 5, 3, a, b, a_minus_b, D, M_panels.data());
    F = M_panels[2] * t0 + T(2) * delta_tau * tau_lo * M_panels[1] + t1 * M_panels[0];
    G_ap = t0 * M_panels[6] + T(2) * M_panels[5] * delta_tau * tau_lo + t1 * M_panels[4];
    G_ab = M_panels[5] * t1 + t0 * M_panels[7] + T(2) * delta_tau * M_panels[6] * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t13 * a_minus_b + t14 * b;
    const T t16 = T(1) / D;
    const T t17 = t15 * t16 * b + t14 - t13;
    const T t18 = T(1) / a;
    F = T(2) * t17 * delta_tau * t18 * tau_lo + t15 * t16 * t1 - (t15 * c * t16 - J1 - T(2) * t17 * t18 * b) * t0 * t18;
    const T t19 = t13 * t13;
    const T t20 = t14 * t14;
    const T t21 = t13 * a_minus_b * t19 + t20 * t14 * b + T(2) * t15 * t16 * a;
    const T t22 = t13 * t19 - t20 * t14 - t16 * t21 * b;
    const T t23 = T(3) * t15 * t16 - T(2) * t22 * t18 * b - c * t16 * t21;
    G_ap = (T(1) / T(3)) * t16 * t21 * t1 + (T(1) / T(3)) * t0 * t18 * t23 - (T(2) / T(3)) * t22 * delta_tau * t18 * tau_lo;
    G_ab = (T(2) / T(3)) * delta_tau * t18 * tau_lo * t23 + (T(1) / T(3)) * t0 * t18 * (T(2) * t18 * b * t23 + T(3) * t17 * t18 + c * t22 * t18) - (T(1) / T(3)) * t22 * t18 * t1;
  }
  const T g_factor = -T(3) * in.sigma * length * sigma2;
  f = in.sigma * length * F * sigma2;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 53 +, 95 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 9144 +, 12168 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * delta_tau;
    F = T(3) * M_panels[1] * delta_tau * t1 + T(3) * t0 * tau_lo * M_panels[2] + t6 * M_panels[0] + t7 * M_panels[3];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 4> M_panels;
    segment_moments_gauss_panels<T>(4, 4, 3, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t0 * delta_tau;
    const T t9 = t1 * tau_lo;
    F = T(3) * delta_tau * t1 * M_panels[1] + t8 * M_panels[3] + M_panels[0] * t9 + T(3) * t0 * tau_lo * M_panels[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / q1;
    const T t13 = b * t2 + a_minus_b * t12 + J2 * a;
    const T t14 = T(1) / D;
    const T t15 = t12 - t13 * b * t14 - t2;
    const T t16 = T(1) / a;
    const T t17 = T(2) * J2 - T(2) * b * t15 * t16 - t13 * c * t14;
    const T t18 = t0 * delta_tau;
    const T t19 = t1 * tau_lo;
    F = (T(3) / T(2)) * t0 * tau_lo * t17 * t16 + (T(1) / T(2)) * t18 * (T(2) * t17 * b * t16 + t15 * c * t16 + (log_ratio + T(2) * J2 * b) * t16) * t16 + (T(1) / T(2)) * t19 * t13 * t14 - (T(3) / T(2)) * delta_tau * t1 * t15 * t16;
  }
  f = F * sigma2 * sigma2 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 66 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 10230 +, 14344 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t1;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t1 * tau_lo;
    const T t6 = t0 * delta_tau;
    G_ap = T(3) * M_panels[1] * delta_tau * t1 + T(3) * M_panels[2] * t0 * tau_lo + M_panels[0] * t5 + t6 * M_panels[3];
    G_ab = M_panels[1] * t5 + M_panels[4] * t6 + T(3) * t0 * tau_lo * M_panels[3] + T(3) * M_panels[2] * delta_tau * t1;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t7 = t0 * delta_tau;
    const T t8 = t1 * tau_lo;
    G_ap = T(3) * M_panels[2] * t0 * tau_lo + T(3) * delta_tau * M_panels[1] * t1 + M_panels[3] * t7 + M_panels[0] * t8;
    G_ab = M_panels[1] * t8 + T(3) * M_panels[3] * t0 * tau_lo + T(3) * M_panels[2] * delta_tau * t1 + M_panels[4] * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = T(1) / q1;
    const T t14 = t13 * t13;
    const T t15 = t13 * a_minus_b + a * J2 + b * t11;
    const T t16 = T(1) / D;
    const T t17 = T(2) * b * t12 + T(2) * t14 * a_minus_b + T(3) * a * t15 * t16;
    const T t18 = t1 * tau_lo;
    const T t19 = T(1) / a;
    const T t20 = T(2) * t12 + b * t17 * t16 - T(2) * t14;
    const T t21 = T(2) * t19 * b * t20 + T(4) * t15 * t16 - t17 * c * t16;
    const T t22 = t13 - t15 * b * t16 - t11;
    const T t23 = T(2) * t19 * b * t21 - T(4) * t19 * t22 - t19 * c * t20;
    const T t24 = t0 * delta_tau;
    G_ap = (T(1) / T(8)) * t17 * t16 * t18 + (T(3) / T(8)) * t19 * t21 * t0 * tau_lo + (T(1) / T(8)) * t19 * t23 * t24 + (T(3) / T(8)) * t19 * t20 * delta_tau * t1;
    G_ab = (T(3) / T(8)) * t19 * t23 * t0 * tau_lo + (T(1) / T(8)) * t19 * t20 * t18 + (T(3) / T(8)) * t19 * t21 * delta_tau * t1 - (T(1) / T(8)) * t19 * (t19 * t21 * c + T(4) * t19 * (t15 * c * t16 + T(2) * t19 * b * t22 - T(2) * J2) - T(2) * t19 * b * t23) * t24;
  }
  const T g_factor = -T(4) * sigma2 * sigma2 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 168 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15633 +, 20835 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * delta_tau;
    F = T(3) * M_panels[2] * tau_lo * t0 + T(3) * t1 * delta_tau * M_panels[1] + t6 * M_panels[0] + t7 * M_panels[3];
    G_ap = M_panels[8] * t7 + T(3) * tau_lo * t0 * M_panels[7] + M_panels[5] * t6 + T(3) * t1 * delta_tau * M_panels[6];
    G_ab = T(3) * t1 * delta_tau * M_panels[7] + t7 * M_panels[9] + t6 * M_panels[6] + T(3) * M_panels[8] * tau_lo * t0;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(4, 6, 4, a, b, a_minus_b, D, M_panels.data());
    const T t8 = t0 * delta_tau;
    const T t9 = t1 * tau_lo;
    F = t8 * M_panels[3] + t9 * M_panels[0] + T(3) * tau_lo * t0 * M_panels[2] + T(3) * t1 * delta_tau * M_panels[1];
    G_ap = T(3) * t1 * delta_tau * M_panels[6] + t9 * M_panels[5] + T(3) * tau_lo * t0 * M_panels[7] + M_panels[8] * t8;
    G_ab = t9 * M_panels[6] + T(3) * t1 * delta_tau * M_panels[7] + t8 * M_panels[9] + T(3) * M_panels[8] * tau_lo * t0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / q1;
    const T t13 = b * t2 + a * J2 + a_minus_b * t12;
    const T t14 = t1 * tau_lo;
    const T t15 = T(1) / D;
    const T t16 = T(1) / a;
    const T t17 = t0 * delta_tau;
    const T t18 = t12 - t13 * b * t15 - t2;
    const T t19 = t13 * c * t15 + T(2) * t16 * b * t18 - T(2) * J2;
    F = (T(1) / T(2)) * t13 * t14 * t15 - (T(1) / T(2)) * t16 * t17 * (T(2) * t16 * b * t19 - t16 * t18 * c - t16 * (T(2) * b * J2 + log_ratio)) - (T(3) / T(2)) * t16 * t1 * delta_tau * t18 - (T(3) / T(2)) * t16 * tau_lo * t0 * t19;
    const T t20 = t12 * t12;
    const T t21 = t2 * t2;
    const T t22 = T(3) * t13 * a * t15 + T(2) * a_minus_b * t20 + T(2) * b * t21;
    const T t23 = T(2) * t21 + b * t22 * t15 - T(2) * t20;
    const T t24 = T(4) * t13 * t15 + T(2) * t23 * t16 * b - t22 * c * t15;
    const T t25 = T(4) * t16 * t18 + t23 * t16 * c - T(2) * t16 * t24 * b;
    G_ap = (T(1) / T(8)) * t14 * t22 * t15 + (T(3) / T(8)) * t16 * tau_lo * t0 * t24 + (T(3) / T(8)) * t23 * t16 * t1 * delta_tau - (T(1) / T(8)) * t16 * t17 * t25;
    G_ab = (T(3) / T(8)) * t16 * t1 * delta_tau * t24 + (T(1) / T(8)) * t23 * t16 * t14 - (T(3) / T(8)) * t16 * tau_lo * t0 * t25 - (T(1) / T(8)) * t16 * t17 * (t16 * t24 * c + T(4) * t16 * t19 + T(2) * t16 * b * t25);
  }
  const T t26 = sigma2 * sigma2;
  const T g_factor = -T(4) * t26 * length;
  f = F * t26 * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 58 +, 125 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 10223 +, 16494 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t1;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = a_minus_b * r0;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + b * r1) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = a_minus_b * r0;
    X = -t6 * (b - a_minus_b) / (t7 - b * r1);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  const T t10 = T(4) * D - a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t0 * delta_tau;
    const T t15 = t0 * t0;
    const T t16 = t1 * tau_lo;
    F = M_panels[0] * t13 + T(4) * M_panels[3] * tau_lo * t14 + M_panels[4] * t15 + T(4) * M_panels[1] * t16 * delta_tau + T(6) * t1 * M_panels[2] * t0;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 5> M_panels;
    segment_moments_gauss_panels<T>(5, 5, 4, a, b, a_minus_b, D, M_panels.data());
    const T t17 = t1 * t1;
    const T t18 = t0 * t0;
    const T t19 = t1 * tau_lo;
    const T t20 = t0 * delta_tau;
    F = t17 * M_panels[0] + M_panels[4] * t18 + T(4) * M_panels[1] * t19 * delta_tau + T(4) * M_panels[3] * tau_lo * t20 + T(6) * M_panels[2] * t1 * t0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = T(1) / D;
    const T t27 = t22 * a_minus_b + b * t24;
    const T t28 = b * t25 * t24 + T(2) * t26 * a * t27 + t22 * a_minus_b * t23;
    const T t29 = t22 * t23 - t25 * t24 - b * t26 * t28;
    const T t30 = T(2) * b * t29 * t21 + c * t26 * t28 - T(3) * t26 * t27;
    const T t31 = b * t26 * t27 + t24 - t22;
    const T t32 = t29 * c * t21 + T(3) * t31 * t21 - T(2) * b * t21 * t30;
    const T t33 = t0 * t0;
    const T t34 = t1 * t1;
    const T t35 = t0 * delta_tau;
    const T t36 = t1 * tau_lo;
    F = (T(1) / T(3)) * (c * t21 * t30 + T(3) * t21 * (T(2) * b * t31 * t21 + J1 - c * t26 * t27) + T(2) * b * t32 * t21) * t21 * t33 + (T(1) / T(3)) * t26 * t34 * t28 + (T(4) / T(3)) * t32 * tau_lo * t21 * t35 - T(2) * t1 * t21 * t0 * t30 - (T(4) / T(3)) * t29 * t36 * t21 * delta_tau;
  }
  f = sigma2 * sigma2 * length * in.sigma * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 179 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 11309 +, 19748 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t0 * delta_tau;
    const T t6 = t1 * tau_lo;
    const T t7 = t1 * t1;
    const T t8 = t0 * t0;
    G_ap = T(4) * t5 * tau_lo * M_panels[3] + T(4) * delta_tau * t6 * M_panels[1] + t7 * M_panels[0] + t8 * M_panels[4] + T(6) * t0 * t1 * M_panels[2];
    G_ab = T(6) * t0 * t1 * M_panels[3] + t8 * M_panels[5] + T(4) * delta_tau * t6 * M_panels[2] + T(4) * t5 * tau_lo * M_panels[4] + t7 * M_panels[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t9 = t1 * tau_lo;
    const T t10 = t0 * delta_tau;
    const T t11 = t1 * t1;
    const T t12 = t0 * t0;
    G_ap = T(4) * delta_tau * t9 * M_panels[1] + T(4) * t10 * tau_lo * M_panels[3] + t11 * M_panels[0] + T(6) * t0 * t1 * M_panels[2] + t12 * M_panels[4];
    G_ab = t12 * M_panels[5] + T(6) * t0 * t1 * M_panels[3] + T(4) * delta_tau * t9 * M_panels[2] + T(4) * t10 * tau_lo * M_panels[4] + t11 * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = t1 * tau_lo;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * a_minus_b + b * t14;
    const T t18 = T(1) / D;
    const T t19 = t16 * t16;
    const T t20 = b * t14 * t15 + T(2) * t17 * t18 * a + t19 * t16 * a_minus_b;
    const T t21 = t19 * t19;
    const T t22 = t15 * t15;
    const T t23 = T(4) * t20 * t18 * a + T(3) * t21 * t16 * a_minus_b + T(3) * b * t14 * t22;
    const T t24 = t23 * b * t18 + T(3) * t14 * t22 - T(3) * t21 * t16;
    const T t25 = T(1) / a;
    const T t26 = T(5) * t20 * t18 + T(2) * b * t24 * t25 - t23 * c * t18;
    const T t27 = t1 * t1;
    const T t28 = t0 * t0;
    const T t29 = t19 * t16 - t14 * t15 - b * t20 * t18;
    const T t30 = t24 * c * t25 + T(5) * t29 * t25 - T(2) * b * t26 * t25;
    const T t31 = T(2) * b * t29 * t25 + t20 * c * t18 - T(3) * t17 * t18;
    const T t32 = T(2) * b * t30 * t25 + T(5) * t31 * t25 + t26 * c * t25;
    const T t33 = t0 * delta_tau;
    G_ap = (T(4) / T(15)) * delta_tau * t13 * t24 * t25 + (T(2) / T(5)) * t0 * t1 * t26 * t25 + (T(1) / T(15)) * t27 * t23 * t18 - (T(1) / T(15)) * t28 * t32 * t25 - (T(4) / T(15)) * t33 * tau_lo * t30 * t25;
    G_ab = (T(1) / T(15)) * t27 * t24 * t25 + (T(4) / T(15)) * delta_tau * t13 * t26 * t25 - (T(4) / T(15)) * t33 * tau_lo * t32 * t25 - (T(1) / T(15)) * t28 * (T(2) * b * t32 * t25 + T(5) * (T(3) * (t16 - b * t17 * t18 - t14) * t25 + T(2) * t31 * b * t25 - t29 * c * t25) * t25 - c * t30 * t25) * t25 - (T(2) / T(5)) * t0 * t1 * t30 * t25;
  }
  const T g_factor = -T(5) * sigma2 * sigma2 * length * in.sigma;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 81 +, 218 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 17794 +, 27328 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = r0 * a_minus_b;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + r1 * b) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r0 * a_minus_b;
    X = (a_minus_b - b) * t6 / (t7 - r1 * b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  T G_ap;
  T G_ab;
  const T t10 = T(4) * D - a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t0 * delta_tau;
    const T t15 = t1 * tau_lo;
    const T t16 = t0 * t0;
    F = t13 * M_panels[0] + T(4) * t14 * M_panels[3] * tau_lo + T(6) * M_panels[2] * t0 * t1 + T(4) * delta_tau * t15 * M_panels[1] + t16 * M_panels[4];
    G_ap = t16 * M_panels[10] + T(4) * delta_tau * t15 * M_panels[7] + T(6) * M_panels[8] * t0 * t1 + M_panels[6] * t13 + T(4) * M_panels[9] * t14 * tau_lo;
    G_ab = T(4) * t14 * tau_lo * M_panels[10] + t16 * M_panels[11] + t13 * M_panels[7] + T(4) * M_panels[8] * delta_tau * t15 + T(6) * M_panels[9] * t0 * t1;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 12> M_panels;
    segment_moments_gauss_panels<T>(5, 7, 5, a, b, a_minus_b, D, M_panels.data());
    const T t17 = t0 * delta_tau;
    const T t18 = t0 * t0;
    const T t19 = t1 * t1;
    const T t20 = t1 * tau_lo;
    F = T(4) * M_panels[3] * t17 * tau_lo + t18 * M_panels[4] + M_panels[0] * t19 + T(4) * delta_tau * t20 * M_panels[1] + T(6) * M_panels[2] * t0 * t1;
    G_ap = T(4) * delta_tau * M_panels[7] * t20 + T(4) * M_panels[9] * t17 * tau_lo + M_panels[10] * t18 + M_panels[6] * t19 + T(6) * t0 * t1 * M_panels[8];
    G_ab = T(4) * delta_tau * t20 * M_panels[8] + T(6) * M_panels[9] * t0 * t1 + t18 * M_panels[11] + T(4) * M_panels[10] * t17 * tau_lo + M_panels[7] * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r1;
    const T t25 = t21 * b + t24 * a_minus_b;
    const T t26 = t24 * t24;
    const T t27 = t22 * t21 * b + T(2) * t25 * t23 * a + t24 * a_minus_b * t26;
    const T t28 = t22 * t21 + t23 * b * t27 - t24 * t26;
    const T t29 = T(1) / a;
    const T t30 = T(2) * t28 * t29 * b + T(3) * t25 * t23 - c * t23 * t27;
    const T t31 = t0 * delta_tau;
    const T t32 = t21 + t25 * t23 * b - t24;
    const T t33 = T(2) * t30 * t29 * b + T(3) * t32 * t29 - c * t28 * t29;
    const T t34 = t1 * tau_lo;
    const T t35 = t1 * t1;
    const T t36 = t0 * t0;
    F = T(2) * t30 * t0 * t29 * t1 + (T(4) / T(3)) * t31 * t29 * tau_lo * t33 + (T(4) / T(3)) * delta_tau * t28 * t29 * t34 + (T(1) / T(3)) * t23 * t35 * t27 - (T(1) / T(3)) * (c * t30 * t29 - T(3) * (J1 + T(2) * t32 * t29 * b - c * t25 * t23) * t29 - T(2) * t29 * t33 * b) * t36 * t29;
    const T t37 = t26 * t26;
    const T t38 = t22 * t22;
    const T t39 = T(3) * t24 * a_minus_b * t37 + T(4) * t23 * a * t27 + T(3) * t38 * t21 * b;
    const T t40 = T(3) * t24 * t37 - T(3) * t38 * t21 - t39 * t23 * b;
    const T t41 = T(2) * t40 * t29 * b + t39 * c * t23 - T(5) * t23 * t27;
    const T t42 = T(2) * t29 * t41 * b - T(5) * t28 * t29 - c * t40 * t29;
    const T t43 = T(5) * t30 * t29 + c * t29 * t41 - T(2) * t42 * t29 * b;
    G_ap = (T(1) / T(15)) * t36 * t29 * t43 + (T(1) / T(15)) * t39 * t23 * t35 - (T(4) / T(15)) * t42 * t31 * t29 * tau_lo - (T(4) / T(15)) * delta_tau * t40 * t29 * t34 - (T(2) / T(5)) * t0 * t29 * t1 * t41;
    G_ab = (T(4) / T(15)) * t31 * t29 * tau_lo * t43 + (T(1) / T(15)) * (T(2) * t29 * t43 * b + c * t42 * t29 + T(5) * t29 * t33) * t36 * t29 - (T(4) / T(15)) * delta_tau * t29 * t34 * t41 - (T(1) / T(15)) * t40 * t29 * t35 - (T(2) / T(5)) * t42 * t0 * t29 * t1;
  }
  const T t44 = sigma2 * sigma2;
  const T g_factor = -T(5) * in.sigma * length * t44;
  f = in.sigma * length * F * t44;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 67 +, 149 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 11306 +, 15419 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * tau_hi * sigma2;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t0 * t0;
    const T t7 = t1 * t1;
    const T t8 = t1 * tau_lo;
    const T t9 = t0 * delta_tau;
    const T t10 = t6 * delta_tau;
    const T t11 = t7 * tau_lo;
    F = T(5) * tau_lo * t6 * M_panels[4] + T(5) * t7 * delta_tau * M_panels[1] + T(10) * M_panels[2] * t8 * t0 + T(10) * t1 * t9 * M_panels[3] + M_panels[5] * t10 + t11 * M_panels[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 6> M_panels;
    segment_moments_gauss_panels<T>(6, 6, 5, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t0 * t0;
    const T t13 = t12 * delta_tau;
    const T t14 = t1 * tau_lo;
    const T t15 = t1 * t1;
    const T t16 = t15 * tau_lo;
    const T t17 = t0 * delta_tau;
    F = t13 * M_panels[5] + T(5) * tau_lo * t12 * M_panels[4] + T(10) * t14 * t0 * M_panels[2] + t16 * M_panels[0] + T(10) * t1 * t17 * M_panels[3] + T(5) * t15 * delta_tau * M_panels[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = atan2(t18, c_minus_b) * t19;
    const T t20 = T(1) / a;
    const T t21 = t1 * t1;
    const T t22 = t2 * t2;
    const T t23 = T(1) / q1;
    const T t24 = a_minus_b * t23 + a * J2 + b * t2;
    const T t25 = T(1) / D;
    const T t26 = t23 * t23;
    const T t27 = T(2) * b * t22 + T(3) * a * t24 * t25 + T(2) * a_minus_b * t26;
    const T t28 = b * t27 * t25 + T(2) * t22 - T(2) * t26;
    const T t29 = t1 * tau_lo;
    const T t30 = T(4) * t24 * t25 + T(2) * t20 * t28 * b - t27 * c * t25;
    const T t31 = t0 * t0;
    const T t32 = t31 * delta_tau;
    const T t33 = t23 - b * t24 * t25 - t2;
    const T t34 = T(2) * t20 * t33 * b + t24 * c * t25 - T(2) * J2;
    const T t35 = t20 * t28 * c + T(4) * t20 * t33 - T(2) * t20 * b * t30;
    const T t36 = T(4) * t20 * t34 + t20 * c * t30 + T(2) * t20 * b * t35;
    const T t37 = t21 * tau_lo;
    const T t38 = t0 * delta_tau;
    F = (T(5) / T(8)) * t20 * t21 * delta_tau * t28 + (T(5) / T(4)) * t20 * t29 * t0 * t30 + (T(1) / T(8)) * t20 * t32 * (T(4) * t20 * (t20 * (log_ratio + T(2) * b * J2) + t20 * t33 * c - T(2) * t20 * b * t34) + t20 * t35 * c - T(2) * t20 * b * t36) + (T(1) / T(8)) * t37 * t27 * t25 - (T(5) / T(4)) * t20 * t1 * t38 * t35 - (T(5) / T(8)) * t20 * tau_lo * t31 * t36;
  }
  const T t39 = sigma2 * sigma2;
  const T t40 = t39 * sigma2;
  f = F * t40 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 84 +, 212 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 12394 +, 17601 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t1;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * tau_lo;
    const T t7 = t0 * t0;
    const T t8 = t7 * delta_tau;
    const T t9 = t1 * tau_lo;
    const T t10 = t0 * delta_tau;
    G_ap = M_panels[0] * t6 + M_panels[5] * t8 + T(10) * M_panels[2] * t0 * t9 + T(10) * M_panels[3] * t10 * t1 + T(5) * M_panels[4] * t7 * tau_lo + T(5) * M_panels[1] * delta_tau * t5;
    G_ab = M_panels[6] * t8 + T(10) * M_panels[4] * t10 * t1 + T(5) * M_panels[5] * t7 * tau_lo + T(5) * M_panels[2] * delta_tau * t5 + M_panels[1] * t6 + T(10) * M_panels[3] * t0 * t9;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t11 = t1 * t1;
    const T t12 = t0 * t0;
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * tau_lo;
    const T t15 = t11 * tau_lo;
    const T t16 = t12 * delta_tau;
    G_ap = T(5) * M_panels[1] * delta_tau * t11 + T(5) * M_panels[4] * t12 * tau_lo + T(10) * M_panels[3] * t13 * t1 + T(10) * M_panels[2] * t0 * t14 + M_panels[0] * t15 + M_panels[5] * t16;
    G_ab = T(5) * M_panels[5] * t12 * tau_lo + T(10) * M_panels[3] * t0 * t14 + t16 * M_panels[6] + T(5) * M_panels[2] * delta_tau * t11 + M_panels[1] * t15 + T(10) * M_panels[4] * t13 * t1;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, c_minus_b);
    const T t19 = T(1) / D;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = J2 * a + b * t22 + t20 * a_minus_b;
    const T t25 = T(2) * t21 * a_minus_b + T(2) * b * t23 + T(3) * t24 * t19 * a;
    const T t26 = t21 * t20;
    const T t27 = t23 * t22;
    const T t28 = T(8) * t26 * a_minus_b + T(8) * b * t27 + T(5) * t19 * a * t25;
    const T t29 = T(8) * t26 - T(8) * t27 - b * t28 * t19;
    const T t30 = T(1) / a;
    const T t31 = T(6) * t19 * t25 - c * t28 * t19 - T(2) * b * t29 * t30;
    const T t32 = t1 * tau_lo;
    const T t33 = t1 * t1;
    const T t34 = t33 * tau_lo;
    const T t35 = T(2) * t21 - T(2) * t23 - b * t19 * t25;
    const T t36 = T(6) * t35 * t30 - c * t29 * t30 - T(2) * b * t31 * t30;
    const T t37 = c * t19 * t25 + T(2) * b * t35 * t30 - T(4) * t24 * t19;
    const T t38 = T(2) * b * t36 * t30 + c * t31 * t30 + T(6) * t37 * t30;
    const T t39 = t0 * t0;
    const T t40 = b * t24 * t19 + t22 - t20;
    const T t41 = c * t35 * t30 + T(4) * t40 * t30 - T(2) * b * t37 * t30;
    const T t42 = T(2) * b * t38 * t30 - T(6) * t41 * t30 - c * t36 * t30;
    const T t43 = t39 * delta_tau;
    const T t44 = t0 * delta_tau;
    G_ap = (T(5) / T(24)) * t31 * t30 * t0 * t32 + (T(1) / T(48)) * t28 * t19 * t34 - (T(5) / T(48)) * t38 * t30 * t39 * tau_lo - (T(1) / T(48)) * t42 * t30 * t43 - (T(5) / T(24)) * t36 * t30 * t44 * t1 - (T(5) / T(48)) * t29 * t30 * delta_tau * t33;
    G_ab = (T(5) / T(48)) * t31 * t30 * delta_tau * t33 - (T(1) / T(48)) * t30 * t43 * (T(2) * b * t42 * t30 - t38 * c * t30 - T(6) * (T(2) * t41 * b * t30 + T(4) * (T(2) * J2 + T(2) * b * t40 * t30 - c * t24 * t19) * t30 + c * t37 * t30) * t30) - (T(5) / T(24)) * t36 * t30 * t0 * t32 - (T(5) / T(24)) * t38 * t30 * t44 * t1 - (T(1) / T(48)) * t29 * t30 * t34 - (T(5) / T(48)) * t42 * t30 * t39 * tau_lo;
  }
  const T t45 = sigma2 * sigma2;
  const T t46 = t45 * sigma2;
  const T g_factor = -T(6) * t46 * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 252 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 19959 +, 26258 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * tau_lo;
    const T t8 = t0 * t0;
    const T t9 = t8 * delta_tau;
    const T t10 = t0 * delta_tau;
    const T t11 = t1 * tau_lo;
    F = t7 * M_panels[0] + M_panels[5] * t9 + T(10) * t1 * t10 * M_panels[3] + T(10) * t11 * t0 * M_panels[2] + T(5) * M_panels[1] * t6 * delta_tau + T(5) * tau_lo * t8 * M_panels[4];
    G_ap = t9 * M_panels[12] + T(5) * M_panels[11] * tau_lo * t8 + t7 * M_panels[7] + T(5) * M_panels[8] * t6 * delta_tau + T(10) * t1 * t10 * M_panels[10] + T(10) * t11 * t0 * M_panels[9];
    G_ab = T(5) * tau_lo * t8 * M_panels[12] + T(10) * t11 * t0 * M_panels[10] + M_panels[8] * t7 + T(10) * M_panels[11] * t1 * t10 + t9 * M_panels[13] + T(5) * t6 * delta_tau * M_panels[9];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 14> M_panels;
    segment_moments_gauss_panels<T>(6, 8, 6, a, b, a_minus_b, D, M_panels.data());
    const T t12 = t1 * t1;
    const T t13 = t1 * tau_lo;
    const T t14 = t0 * t0;
    const T t15 = t14 * delta_tau;
    const T t16 = t12 * tau_lo;
    const T t17 = t0 * delta_tau;
    F = T(5) * t12 * delta_tau * M_panels[1] + T(10) * t13 * t0 * M_panels[2] + t15 * M_panels[5] + M_panels[0] * t16 + T(5) * tau_lo * t14 * M_panels[4] + T(10) * M_panels[3] * t1 * t17;
    G_ap = T(10) * t13 * t0 * M_panels[9] + T(5) * tau_lo * t14 * M_panels[11] + T(10) * M_panels[10] * t1 * t17 + t16 * M_panels[7] + T(5) * t12 * delta_tau * M_panels[8] + t15 * M_panels[12];
    G_ab = T(5) * t12 * delta_tau * M_panels[9] + M_panels[13] * t15 + t16 * M_panels[8] + T(10) * t1 * t17 * M_panels[11] + T(5) * tau_lo * t14 * M_panels[12] + T(10) * M_panels[10] * t13 * t0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = t19 * atan2(t18, c_minus_b);
    const T t20 = t1 * tau_lo;
    const T t21 = T(1) / a;
    const T t22 = T(1) / D;
    const T t23 = T(1) / q1;
    const T t24 = a_minus_b * t23 + b * t2 + J2 * a;
    const T t25 = t2 * t2;
    const T t26 = t23 * t23;
    const T t27 = T(2) * b * t25 + T(3) * t22 * t24 * a + T(2) * a_minus_b * t26;
    const T t28 = t22 * t27 * b + T(2) * t25 - T(2) * t26;
    const T t29 = T(4) * t22 * t24 + T(2) * t21 * b * t28 - t22 * t27 * c;
    const T t30 = t1 * t1;
    const T t31 = t23 - t2 - t22 * t24 * b;
    const T t32 = T(4) * t21 * t31 + t21 * c * t28 - T(2) * t21 * t29 * b;
    const T t33 = T(2) * t21 * t31 * b + t22 * t24 * c - T(2) * J2;
    const T t34 = t21 * t29 * c + T(4) * t21 * t33 + T(2) * t32 * t21 * b;
    const T t35 = t0 * t0;
    const T t36 = t35 * delta_tau;
    const T t37 = t30 * tau_lo;
    const T t38 = t0 * delta_tau;
    F = (T(5) / T(4)) * t20 * t0 * t21 * t29 + (T(5) / T(8)) * t30 * delta_tau * t21 * t28 + (T(1) / T(8)) * (t32 * t21 * c + T(4) * t21 * ((T(2) * J2 * b + log_ratio) * t21 + t21 * t31 * c - T(2) * t21 * b * t33) - T(2) * t21 * b * t34) * t36 * t21 + (T(1) / T(8)) * t22 * t27 * t37 - (T(5) / T(8)) * tau_lo * t35 * t21 * t34 - (T(5) / T(4)) * t32 * t1 * t38 * t21;
    const T t39 = t25 * t2;
    const T t40 = t26 * t23;
    const T t41 = T(8) * b * t39 + T(5) * t22 * t27 * a + T(8) * a_minus_b * t40;
    const T t42 = T(8) * t39 + t22 * b * t41 - T(8) * t40;
    const T t43 = t22 * t41 * c - T(2) * t21 * b * t42 - T(6) * t22 * t27;
    const T t44 = T(6) * t21 * t28 - t21 * t42 * c - T(2) * t43 * t21 * b;
    const T t45 = t43 * t21 * c + T(2) * t21 * b * t44 + T(6) * t21 * t29;
    const T t46 = t21 * t44 * c + T(6) * t32 * t21 - T(2) * t21 * b * t45;
    G_ap = (T(5) / T(24)) * t1 * t38 * t21 * t44 + (T(1) / T(48)) * t22 * t37 * t41 + (T(5) / T(48)) * tau_lo * t35 * t21 * t45 + (T(5) / T(48)) * t30 * delta_tau * t21 * t42 - (T(5) / T(24)) * t43 * t20 * t0 * t21 - (T(1) / T(48)) * t36 * t21 * t46;
    G_ab = (T(5) / T(24)) * t1 * t38 * t21 * t45 + (T(1) / T(48)) * t37 * t21 * t42 + (T(5) / T(24)) * t20 * t0 * t21 * t44 - (T(5) / T(48)) * t43 * t30 * delta_tau * t21 - (T(5) / T(48)) * tau_lo * t35 * t21 * t46 - (T(1) / T(48)) * t36 * t21 * (T(6) * t21 * t34 + T(2) * t21 * b * t46 + t21 * t45 * c);
  }
  const T t47 = sigma2 * sigma2;
  const T t48 = t47 * sigma2;
  const T g_factor = -T(6) * length * t48;
  f = length * F * t48;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 74 +, 188 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 12385 +, 20825 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = b * r1;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + r0 * a_minus_b) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = b * r1;
    X = t6 * (b - a_minus_b) / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  const T t10 = T(4) * D - a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t0 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t15 * delta_tau;
    const T t19 = t1 * tau_lo;
    const T t20 = t19 * t19;
    F = T(6) * M_panels[1] * delta_tau * t14 + T(15) * M_panels[4] * t15 * t1 + t17 * M_panels[6] + T(15) * M_panels[2] * t0 * t13 + T(6) * t18 * M_panels[5] * tau_lo + t20 * M_panels[0] + T(20) * t16 * t19 * M_panels[3];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 7> M_panels;
    segment_moments_gauss_panels<T>(7, 7, 6, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t1 * t1;
    const T t22 = t0 * delta_tau;
    const T t23 = t1 * tau_lo;
    const T t24 = t22 * t22;
    const T t25 = t21 * tau_lo;
    const T t26 = t0 * t0;
    const T t27 = t26 * delta_tau;
    const T t28 = t23 * t23;
    F = T(15) * t0 * t21 * M_panels[2] + T(20) * M_panels[3] * t22 * t23 + t24 * M_panels[6] + T(6) * M_panels[1] * delta_tau * t25 + T(15) * M_panels[4] * t26 * t1 + T(6) * t27 * tau_lo * M_panels[5] + M_panels[0] * t28;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = T(1) / a;
    const T t30 = t1 * t1;
    const T t31 = T(1) / D;
    const T t32 = T(1) / r0;
    const T t33 = t32 * t32;
    const T t34 = T(1) / r1;
    const T t35 = t32 * b + t34 * a_minus_b;
    const T t36 = t34 * t34;
    const T t37 = t33 * t32 * b + T(2) * t31 * a * t35 + t36 * t34 * a_minus_b;
    const T t38 = t33 * t33;
    const T t39 = t36 * t36;
    const T t40 = T(3) * t39 * t34 * a_minus_b + T(4) * t31 * a * t37 + T(3) * t38 * t32 * b;
    const T t41 = T(3) * t38 * t32 + t31 * t40 * b - T(3) * t39 * t34;
    const T t42 = T(5) * t31 * t37 + T(2) * t41 * t29 * b - c * t31 * t40;
    const T t43 = t0 * t0;
    const T t44 = t43 * delta_tau;
    const T t45 = t31 * t37 * b + t33 * t32 - t36 * t34;
    const T t46 = T(5) * t45 * t29 + T(2) * t29 * b * t42 - t41 * c * t29;
    const T t47 = c * t31 * t37 - T(3) * t31 * t35 - T(2) * t45 * t29 * b;
    const T t48 = T(2) * t29 * t46 * b - T(5) * t29 * t47 - c * t29 * t42;
    const T t49 = t31 * t35 * b + t32 - t34;
    const T t50 = T(3) * t29 * t49 - c * t45 * t29 - T(2) * t29 * b * t47;
    const T t51 = T(2) * t29 * t48 * b + T(5) * t50 * t29 - c * t29 * t46;
    const T t52 = t30 * tau_lo;
    const T t53 = t0 * delta_tau;
    const T t54 = t1 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t53 * t53;
    F = t29 * t0 * t30 * t42 + (T(2) / T(5)) * t29 * t44 * tau_lo * t51 + (T(2) / T(5)) * t41 * t29 * delta_tau * t52 + t29 * t48 * t43 * t1 + (T(4) / T(3)) * t29 * t46 * t53 * t54 + (T(1) / T(15)) * t31 * t40 * t55 - (T(1) / T(15)) * (c * t29 * t48 - T(2) * t29 * t51 * b - T(5) * t29 * (T(2) * t50 * t29 * b + c * t29 * t47 - T(3) * t29 * (c * t31 * t35 - J1 - T(2) * t29 * t49 * b))) * t29 * t56;
  }
  const T t57 = sigma2 * sigma2;
  const T t58 = t57 * sigma2;
  f = length * in.sigma * F * t58;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 92 +, 261 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 13473 +, 24085 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t0 * t0;
    const T t6 = t0 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t1 * tau_lo;
    const T t9 = t8 * t8;
    const T t10 = t1 * t1;
    const T t11 = t10 * tau_lo;
    const T t12 = t5 * delta_tau;
    G_ap = T(15) * t1 * t5 * M_panels[4] + t7 * M_panels[6] + t9 * M_panels[0] + T(6) * t11 * M_panels[1] * delta_tau + T(15) * t10 * t0 * M_panels[2] + T(6) * tau_lo * t12 * M_panels[5] + T(20) * t8 * t6 * M_panels[3];
    G_ab = T(6) * tau_lo * t12 * M_panels[6] + t9 * M_panels[1] + T(6) * t11 * delta_tau * M_panels[2] + T(15) * t1 * t5 * M_panels[5] + T(20) * t8 * t6 * M_panels[4] + T(15) * t10 * t0 * M_panels[3] + t7 * M_panels[7];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * tau_lo;
    const T t14 = t0 * delta_tau;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t1 * t1;
    const T t18 = t17 * tau_lo;
    const T t19 = t0 * t0;
    const T t20 = t19 * delta_tau;
    G_ap = T(20) * t13 * t14 * M_panels[3] + t15 * M_panels[6] + t16 * M_panels[0] + T(15) * t17 * t0 * M_panels[2] + T(6) * t18 * delta_tau * M_panels[1] + T(15) * t1 * t19 * M_panels[4] + T(6) * tau_lo * t20 * M_panels[5];
    G_ab = T(15) * t1 * t19 * M_panels[5] + t16 * M_panels[1] + T(6) * t18 * delta_tau * M_panels[2] + T(6) * tau_lo * t20 * M_panels[6] + t15 * M_panels[7] + T(20) * t13 * t14 * M_panels[4] + T(15) * t17 * t0 * M_panels[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = t1 * t1;
    const T t23 = t22 * tau_lo;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = a_minus_b * t28 + b * t24;
    const T t32 = T(1) / D;
    const T t33 = T(2) * a * t31 * t32 + t29 * a_minus_b * t28 + b * t24 * t25;
    const T t34 = T(3) * b * t24 * t26 + T(3) * t30 * a_minus_b * t28 + T(4) * a * t33 * t32;
    const T t35 = t30 * t29;
    const T t36 = T(5) * b * t24 * t27 + T(2) * a * t34 * t32 + T(5) * t35 * a_minus_b * t28;
    const T t37 = b * t36 * t32 + T(5) * t24 * t27 - T(5) * t35 * t28;
    const T t38 = t0 * t0;
    const T t39 = t38 * delta_tau;
    const T t40 = b * t34 * t32 + T(3) * t24 * t26 - T(3) * t30 * t28;
    const T t41 = T(2) * t21 * b * t40 + T(5) * t33 * t32 - t34 * c * t32;
    const T t42 = t29 * t28 - t24 * t25 - b * t33 * t32;
    const T t43 = T(2) * t21 * t41 * b - T(5) * t21 * t42 - t21 * t40 * c;
    const T t44 = T(7) * t34 * t32 + T(6) * t21 * b * t37 - T(3) * t36 * c * t32;
    const T t45 = T(2) * t21 * b * t44 + T(7) * t21 * t40 - T(3) * t21 * c * t37;
    const T t46 = t21 * c * t44 - T(2) * t21 * b * t45 - T(7) * t21 * t41;
    const T t47 = T(7) * t21 * t43 - t21 * t45 * c - T(2) * t21 * t46 * b;
    const T t48 = t1 * tau_lo;
    const T t49 = t0 * delta_tau;
    const T t50 = t49 * t49;
    const T t51 = t33 * c * t32 + T(2) * t21 * b * t42 - T(3) * t31 * t32;
    const T t52 = T(5) * t21 * t51 + t21 * t41 * c - T(2) * t21 * b * t43;
    const T t53 = t21 * t46 * c + T(2) * t21 * b * t47 - T(7) * t21 * t52;
    const T t54 = t48 * t48;
    G_ap = (T(6) / T(35)) * t21 * t23 * delta_tau * t37 + (T(2) / T(35)) * t21 * tau_lo * t39 * t47 + (T(1) / T(7)) * t21 * t22 * t0 * t44 + (T(4) / T(21)) * t21 * t48 * t49 * t45 + (T(1) / T(105)) * t21 * t50 * t53 + (T(1) / T(35)) * t54 * t36 * t32 - (T(1) / T(7)) * t21 * t1 * t38 * t46;
    G_ab = (T(2) / T(35)) * t21 * tau_lo * t39 * t53 + (T(1) / T(35)) * t21 * t54 * t37 + (T(1) / T(7)) * t21 * t22 * t0 * t45 + (T(1) / T(7)) * t21 * t1 * t38 * t47 + (T(2) / T(35)) * t21 * t23 * delta_tau * t44 - (T(1) / T(105)) * t21 * t50 * (T(7) * t21 * (T(2) * t21 * b * t52 + t21 * t43 * c - T(5) * t21 * (t21 * c * t42 - T(3) * t21 * (t28 - t24 - b * t31 * t32) - T(2) * t21 * b * t51)) + t21 * c * t47 - T(2) * t21 * b * t53) - (T(4) / T(21)) * t21 * t48 * t49 * t46;
  }
  const T t55 = sigma2 * sigma2;
  const T t56 = t55 * sigma2;
  const T g_factor = -T(7) * t56 * in.sigma * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 105 +, 313 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 22120 +, 33831 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = r0 * a_minus_b;
    const T t5 = sqrt(a);
    X = t3 * (t4 + b * r1) * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r0 * a_minus_b;
    X = -(b - a_minus_b) * t6 / (t7 - b * r1);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  T G_ap;
  T G_ab;
  const T t10 = T(4) * D - a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t0 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t1 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t15 * delta_tau;
    F = T(6) * M_panels[1] * delta_tau * t14 + T(15) * M_panels[4] * t15 * t1 + T(15) * M_panels[2] * t0 * t13 + t17 * M_panels[6] + t19 * M_panels[0] + T(20) * t16 * t18 * M_panels[3] + T(6) * M_panels[5] * t20 * tau_lo;
    G_ap = T(6) * M_panels[9] * delta_tau * t14 + M_panels[14] * t17 + T(6) * t20 * tau_lo * M_panels[13] + M_panels[8] * t19 + T(20) * M_panels[11] * t16 * t18 + T(15) * t0 * t13 * M_panels[10] + T(15) * M_panels[12] * t15 * t1;
    G_ab = T(15) * t15 * t1 * M_panels[13] + T(15) * M_panels[11] * t0 * t13 + T(6) * delta_tau * t14 * M_panels[10] + T(20) * M_panels[12] * t16 * t18 + M_panels[15] * t17 + T(6) * M_panels[14] * t20 * tau_lo + M_panels[9] * t19;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 16> M_panels;
    segment_moments_gauss_panels<T>(7, 9, 7, a, b, a_minus_b, D, M_panels.data());
    const T t21 = t0 * t0;
    const T t22 = t21 * delta_tau;
    const T t23 = t0 * delta_tau;
    const T t24 = t23 * t23;
    const T t25 = t1 * tau_lo;
    const T t26 = t1 * t1;
    const T t27 = t26 * tau_lo;
    const T t28 = t25 * t25;
    F = T(6) * M_panels[5] * t22 * tau_lo + t24 * M_panels[6] + T(15) * M_panels[4] * t21 * t1 + T(20) * t23 * t25 * M_panels[3] + T(6) * M_panels[1] * delta_tau * t27 + T(15) * M_panels[2] * t0 * t26 + t28 * M_panels[0];
    G_ap = T(15) * M_panels[10] * t0 * t26 + T(20) * M_panels[11] * t23 * t25 + T(6) * delta_tau * M_panels[9] * t27 + T(15) * M_panels[12] * t21 * t1 + T(6) * t22 * tau_lo * M_panels[13] + M_panels[8] * t28 + M_panels[14] * t24;
    G_ab = T(6) * M_panels[14] * t22 * tau_lo + M_panels[15] * t24 + T(15) * t21 * t1 * M_panels[13] + T(15) * M_panels[11] * t0 * t26 + T(20) * M_panels[12] * t23 * t25 + M_panels[9] * t28 + T(6) * M_panels[10] * delta_tau * t27;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = T(1) / a;
    const T t30 = T(1) / D;
    const T t31 = T(1) / r1;
    const T t32 = T(1) / r0;
    const T t33 = t31 * a_minus_b + b * t32;
    const T t34 = t31 * t31;
    const T t35 = t32 * t32;
    const T t36 = t34 * t31 * a_minus_b + T(2) * t30 * a * t33 + b * t35 * t32;
    const T t37 = b * t30 * t36 + t35 * t32 - t34 * t31;
    const T t38 = T(3) * t30 * t33 + T(2) * b * t29 * t37 - c * t30 * t36;
    const T t39 = t35 * t35;
    const T t40 = t34 * t34;
    const T t41 = T(3) * b * t39 * t32 + T(3) * t40 * t31 * a_minus_b + T(4) * t30 * a * t36;
    const T t42 = T(3) * t39 * t32 + b * t41 * t30 - T(3) * t40 * t31;
    const T t43 = T(5) * t30 * t36 + T(2) * b * t42 * t29 - c * t41 * t30;
    const T t44 = T(2) * b * t43 * t29 + T(5) * t29 * t37 - c * t42 * t29;
    const T t45 = T(5) * t29 * t38 + T(2) * b * t44 * t29 - t43 * c * t29;
    const T t46 = b * t30 * t33 + t32 - t31;
    const T t47 = c * t29 * t37 - T(2) * b * t29 * t38 - T(3) * t46 * t29;
    const T t48 = T(2) * b * t45 * t29 - c * t44 * t29 - T(5) * t47 * t29;
    const T t49 = t0 * t0;
    const T t50 = t49 * delta_tau;
    const T t51 = t1 * t1;
    const T t52 = t51 * tau_lo;
    const T t53 = t0 * delta_tau;
    const T t54 = t1 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t53 * t53;
    F = (T(2) / T(5)) * t48 * t50 * t29 * tau_lo + (T(2) / T(5)) * t42 * delta_tau * t29 * t52 + t45 * t49 * t29 * t1 + (T(4) / T(3)) * t44 * t53 * t29 * t54 + t43 * t0 * t29 * t51 + (T(1) / T(15)) * t41 * t30 * t55 - (T(1) / T(15)) * (T(5) * (c * t29 * t38 + T(3) * (c * t30 * t33 - J1 - T(2) * b * t46 * t29) * t29 + T(2) * b * t47 * t29) * t29 + c * t45 * t29 - T(2) * b * t48 * t29) * t56 * t29;
    const T t57 = t40 * t34;
    const T t58 = t39 * t35;
    const T t59 = T(5) * t57 * t31 * a_minus_b + T(5) * b * t58 * t32 + T(2) * t41 * t30 * a;
    const T t60 = T(5) * t58 * t32 + b * t59 * t30 - T(5) * t57 * t31;
    const T t61 = T(3) * t59 * c * t30 - T(6) * b * t60 * t29 - T(7) * t41 * t30;
    const T t62 = T(2) * b * t61 * t29 + T(3) * t60 * c * t29 - T(7) * t42 * t29;
    const T t63 = T(7) * t43 * t29 + t61 * c * t29 - T(2) * b * t62 * t29;
    const T t64 = t62 * c * t29 + T(2) * t63 * b * t29 + T(7) * t44 * t29;
    const T t65 = T(2) * b * t64 * t29 + T(7) * t45 * t29 - t63 * c * t29;
    G_ap = (T(1) / T(35)) * t59 * t30 * t55 + (T(1) / T(7)) * t63 * t49 * t29 * t1 + (T(2) / T(35)) * t64 * t50 * t29 * tau_lo + (T(1) / T(105)) * t56 * t65 * t29 + (T(6) / T(35)) * t60 * delta_tau * t29 * t52 - (T(4) / T(21)) * t62 * t53 * t29 * t54 - (T(1) / T(7)) * t61 * t0 * t29 * t51;
    G_ab = (T(1) / T(7)) * t64 * t49 * t29 * t1 + (T(2) / T(35)) * t50 * t65 * t29 * tau_lo + (T(1) / T(35)) * t60 * t29 * t55 + (T(4) / T(21)) * t63 * t53 * t29 * t54 - (T(2) / T(35)) * t61 * delta_tau * t29 * t52 - (T(1) / T(105)) * (t64 * c * t29 - T(2) * b * t65 * t29 - T(7) * t48 * t29) * t56 * t29 - (T(1) / T(7)) * t62 * t0 * t29 * t51;
  }
  const T t66 = sigma2 * sigma2;
  const T t67 = t66 * sigma2;
  const T g_factor = -T(7) * t67 * in.sigma * length;
  f = t67 * in.sigma * length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 85 +, 216 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 13468 +, 18669 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t0 * t0;
    const T t7 = t6 * delta_tau;
    const T t8 = t1 * tau_lo;
    const T t9 = t0 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = t8 * t8;
    const T t13 = t12 * tau_lo;
    const T t14 = t1 * t1;
    const T t15 = t14 * tau_lo;
    F = T(21) * t1 * M_panels[5] * t7 + T(35) * t8 * t6 * M_panels[4] + M_panels[7] * t11 + T(7) * t12 * M_panels[1] * delta_tau + t13 * M_panels[0] + T(7) * tau_lo * M_panels[6] * t10 + T(35) * t14 * M_panels[3] * t9 + T(21) * t15 * M_panels[2] * t0;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 8> M_panels;
    segment_moments_gauss_panels<T>(8, 8, 7, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t1 * t1;
    const T t17 = t16 * tau_lo;
    const T t18 = t0 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t19 * delta_tau;
    const T t21 = t0 * t0;
    const T t22 = t21 * delta_tau;
    const T t23 = t1 * tau_lo;
    const T t24 = t23 * t23;
    const T t25 = t24 * tau_lo;
    F = T(21) * t17 * M_panels[2] * t0 + T(7) * tau_lo * M_panels[6] * t19 + M_panels[7] * t20 + T(21) * t1 * M_panels[5] * t22 + T(35) * t16 * M_panels[3] * t18 + t25 * M_panels[0] + T(7) * t24 * M_panels[1] * delta_tau + T(35) * t23 * M_panels[4] * t21;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = sqrt(D);
    const T t27 = T(1) / t26;
    const T J2 = atan2(t26, c_minus_b) * t27;
    const T t28 = t1 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = T(1) / D;
    const T t31 = t2 * t2;
    const T t32 = t31 * t2;
    const T t33 = T(1) / q1;
    const T t34 = a_minus_b * t33 + b * t2 + a * J2;
    const T t35 = t33 * t33;
    const T t36 = T(2) * b * t31 + T(3) * t34 * t30 * a + T(2) * a_minus_b * t35;
    const T t37 = t35 * t33;
    const T t38 = T(8) * b * t32 + T(5) * t30 * a * t36 + T(8) * a_minus_b * t37;
    const T t39 = b * t30 * t38 + T(8) * t32 - T(8) * t37;
    const T t40 = T(1) / a;
    const T t41 = t29 * tau_lo;
    const T t42 = T(2) * t35 - b * t30 * t36 - T(2) * t31;
    const T t43 = T(4) * t34 * t30 - T(2) * b * t40 * t42 - c * t30 * t36;
    const T t44 = b * t34 * t30 + t2 - t33;
    const T t45 = T(2) * b * t43 * t40 + T(4) * t40 * t44 + c * t40 * t42;
    const T t46 = T(2) * t39 * b * t40 + T(6) * t30 * t36 - c * t30 * t38;
    const T t47 = t39 * c * t40 + T(6) * t40 * t42 - T(2) * b * t46 * t40;
    const T t48 = T(6) * t43 * t40 - t46 * c * t40 - T(2) * b * t47 * t40;
    const T t49 = T(6) * t45 * t40 + T(2) * b * t48 * t40 + t47 * c * t40;
    const T t50 = t0 * t0;
    const T t51 = t50 * delta_tau;
    const T t52 = t34 * c * t30 - T(2) * b * t40 * t44 - T(2) * J2;
    const T t53 = T(2) * b * t45 * t40 - T(4) * t40 * t52 - t43 * c * t40;
    const T t54 = T(2) * b * t49 * t40 + T(6) * t53 * t40 - t48 * c * t40;
    const T t55 = t0 * delta_tau;
    const T t56 = t55 * t55;
    const T t57 = t56 * delta_tau;
    const T t58 = t1 * t1;
    const T t59 = t58 * tau_lo;
    F = (T(7) / T(48)) * t29 * t39 * t40 * delta_tau + (T(1) / T(48)) * t41 * t30 * t38 + (T(7) / T(16)) * t1 * t49 * t40 * t51 + (T(7) / T(48)) * tau_lo * t54 * t40 * t56 + (T(1) / T(48)) * (T(6) * (T(2) * b * t53 * t40 - T(4) * (T(2) * b * t40 * t52 + c * t40 * t44 - (log_ratio + T(2) * b * J2) * t40) * t40 - c * t45 * t40) * t40 + T(2) * b * t54 * t40 - c * t49 * t40) * t40 * t57 + (T(7) / T(16)) * t59 * t46 * t40 * t0 + (T(35) / T(48)) * t28 * t48 * t40 * t50 - (T(35) / T(48)) * t58 * t47 * t40 * t55;
  }
  const T t60 = sigma2 * sigma2;
  const T t61 = t60 * t60;
  f = F * t61 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 106 +, 294 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 14558 +, 20857 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + sigma2 * tau_lo * tau_hi;
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t1 * tau_lo;
    const T t6 = t0 * t0;
    const T t7 = t0 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t1 * t1;
    const T t10 = t9 * tau_lo;
    const T t11 = t8 * delta_tau;
    const T t12 = t5 * t5;
    const T t13 = t12 * tau_lo;
    const T t14 = t6 * delta_tau;
    G_ap = T(35) * M_panels[4] * t5 * t6 + T(7) * tau_lo * M_panels[6] * t8 + T(21) * t10 * M_panels[2] * t0 + M_panels[7] * t11 + T(7) * M_panels[1] * t12 * delta_tau + T(35) * t9 * M_panels[3] * t7 + t13 * M_panels[0] + T(21) * t1 * M_panels[5] * t14;
    G_ab = T(35) * M_panels[4] * t9 * t7 + M_panels[8] * t11 + T(35) * t5 * M_panels[5] * t6 + T(7) * M_panels[7] * tau_lo * t8 + T(21) * t10 * M_panels[3] * t0 + M_panels[1] * t13 + T(21) * t1 * M_panels[6] * t14 + T(7) * t12 * M_panels[2] * delta_tau;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t15 = t0 * delta_tau;
    const T t16 = t15 * t15;
    const T t17 = t16 * delta_tau;
    const T t18 = t1 * t1;
    const T t19 = t1 * tau_lo;
    const T t20 = t0 * t0;
    const T t21 = t19 * t19;
    const T t22 = t21 * tau_lo;
    const T t23 = t18 * tau_lo;
    const T t24 = t20 * delta_tau;
    G_ap = t17 * M_panels[7] + T(35) * t18 * M_panels[3] * t15 + T(35) * t19 * t20 * M_panels[4] + T(7) * M_panels[1] * t21 * delta_tau + t22 * M_panels[0] + T(21) * t23 * M_panels[2] * t0 + T(21) * M_panels[5] * t1 * t24 + T(7) * tau_lo * M_panels[6] * t16;
    G_ab = T(21) * t1 * M_panels[6] * t24 + T(21) * t23 * M_panels[3] * t0 + M_panels[1] * t22 + T(7) * t21 * M_panels[2] * delta_tau + M_panels[8] * t17 + T(35) * t18 * t15 * M_panels[4] + T(7) * tau_lo * t16 * M_panels[7] + T(35) * M_panels[5] * t19 * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(D);
    const T t26 = T(1) / t25;
    const T J2 = atan2(t25, c_minus_b) * t26;
    const T t27 = t1 * t1;
    const T t28 = T(1) / a;
    const T t29 = T(1) / q1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = T(1) / c;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = t30 * t29;
    const T t36 = t33 * t32;
    const T t37 = T(1) / D;
    const T t38 = b * t32 + J2 * a + t29 * a_minus_b;
    const T t39 = T(2) * t30 * a_minus_b + T(3) * t37 * a * t38 + T(2) * b * t33;
    const T t40 = T(8) * t35 * a_minus_b + T(8) * b * t36 + T(5) * t39 * t37 * a;
    const T t41 = T(7) * t40 * t37 * a + T(48) * t31 * a_minus_b + T(48) * b * t34;
    const T t42 = T(48) * t31 - T(48) * t34 - b * t41 * t37;
    const T t43 = T(8) * t35 - b * t40 * t37 - T(8) * t36;
    const T t44 = c * t41 * t37 + T(2) * b * t28 * t42 - T(8) * t40 * t37;
    const T t45 = c * t28 * t42 - T(8) * t43 * t28 - T(2) * b * t44 * t28;
    const T t46 = t0 * delta_tau;
    const T t47 = T(6) * t39 * t37 - T(2) * b * t43 * t28 - c * t40 * t37;
    const T t48 = T(2) * b * t45 * t28 + T(8) * t47 * t28 + c * t44 * t28;
    const T t49 = T(2) * t30 - T(2) * t33 - b * t39 * t37;
    const T t50 = T(6) * t28 * t49 - t43 * c * t28 - T(2) * b * t47 * t28;
    const T t51 = T(2) * b * t48 * t28 - T(8) * t50 * t28 - c * t45 * t28;
    const T t52 = t0 * t0;
    const T t53 = t52 * delta_tau;
    const T t54 = t1 * tau_lo;
    const T t55 = t54 * t54;
    const T t56 = t55 * tau_lo;
    const T t57 = t39 * c * t37 + T(2) * b * t28 * t49 - T(4) * t37 * t38;
    const T t58 = T(2) * b * t50 * t28 + T(6) * t28 * t57 + t47 * c * t28;
    const T t59 = T(2) * b * t51 * t28 - T(8) * t58 * t28 - c * t48 * t28;
    const T t60 = t46 * t46;
    const T t61 = t27 * tau_lo;
    const T t62 = b * t37 * t38 + t32 - t29;
    const T t63 = c * t28 * t49 + T(4) * t62 * t28 - T(2) * b * t28 * t57;
    const T t64 = T(2) * b * t58 * t28 - T(6) * t28 * t63 - c * t50 * t28;
    const T t65 = T(8) * t64 * t28 + t51 * c * t28 - T(2) * b * t28 * t59;
    const T t66 = t60 * delta_tau;
    G_ap = (T(35) / T(384)) * t27 * t45 * t28 * t46 + (T(7) / T(128)) * t1 * t51 * t28 * t53 + (T(35) / T(384)) * t54 * t48 * t28 * t52 + (T(1) / T(384)) * t56 * t41 * t37 + (T(7) / T(384)) * tau_lo * t28 * t59 * t60 - (T(7) / T(128)) * t61 * t44 * t28 * t0 - (T(7) / T(384)) * t55 * t28 * t42 * delta_tau - (T(1) / T(384)) * t65 * t28 * t66;
    G_ab = (T(7) / T(128)) * t1 * t28 * t59 * t53 + (T(7) / T(128)) * t61 * t45 * t28 * t0 + (T(35) / T(384)) * t27 * t48 * t28 * t46 + (T(35) / T(384)) * t54 * t51 * t28 * t52 - (T(1) / T(384)) * t28 * (T(8) * (T(2) * b * t64 * t28 - c * t58 * t28 - T(6) * (c * t28 * t57 + T(4) * (T(2) * b * t62 * t28 + T(2) * J2 - c * t37 * t38) * t28 + T(2) * b * t28 * t63) * t28) * t28 + c * t28 * t59 + T(2) * b * t65 * t28) * t66 - (T(7) / T(384)) * tau_lo * t65 * t28 * t60 - (T(1) / T(384)) * t56 * t28 * t42 - (T(7) / T(384)) * t55 * t44 * t28 * delta_tau;
  }
  const T t67 = sigma2 * sigma2;
  const T t68 = t67 * t67;
  const T g_factor = -T(8) * t68 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 120 +, 349 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 24285 +, 31680 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t0 * t0;
    const T t9 = t0 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t10 * delta_tau;
    const T t12 = t1 * t1;
    const T t13 = t12 * tau_lo;
    const T t14 = t8 * delta_tau;
    const T t15 = t7 * tau_lo;
    F = T(7) * M_panels[1] * delta_tau * t7 + T(35) * M_panels[4] * t8 * t6 + t11 * M_panels[7] + T(21) * t0 * M_panels[2] * t13 + T(35) * t9 * t12 * M_panels[3] + T(21) * M_panels[5] * t14 * t1 + T(7) * t10 * tau_lo * M_panels[6] + t15 * M_panels[0];
    G_ap = T(7) * M_panels[10] * delta_tau * t7 + T(35) * M_panels[13] * t8 * t6 + t15 * M_panels[9] + t11 * M_panels[16] + T(21) * t0 * M_panels[11] * t13 + T(35) * t9 * t12 * M_panels[12] + T(21) * M_panels[14] * t14 * t1 + T(7) * t10 * tau_lo * M_panels[15];
    G_ab = T(35) * M_panels[13] * t9 * t12 + M_panels[10] * t15 + T(7) * t10 * tau_lo * M_panels[16] + M_panels[17] * t11 + T(35) * M_panels[14] * t8 * t6 + T(7) * delta_tau * M_panels[11] * t7 + T(21) * t14 * t1 * M_panels[15] + T(21) * t0 * t13 * M_panels[12];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 18> M_panels;
    segment_moments_gauss_panels<T>(8, 10, 8, a, b, a_minus_b, D, M_panels.data());
    const T t16 = t0 * delta_tau;
    const T t17 = t16 * t16;
    const T t18 = t1 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t1 * t1;
    const T t21 = t20 * tau_lo;
    const T t22 = t19 * tau_lo;
    const T t23 = t17 * delta_tau;
    const T t24 = t0 * t0;
    const T t25 = t24 * delta_tau;
    F = T(7) * t17 * M_panels[6] * tau_lo + T(7) * delta_tau * t19 * M_panels[1] + T(21) * M_panels[2] * t0 * t21 + t22 * M_panels[0] + t23 * M_panels[7] + T(35) * t24 * t18 * M_panels[4] + T(21) * M_panels[5] * t25 * t1 + T(35) * t16 * t20 * M_panels[3];
    G_ap = T(21) * M_panels[11] * t0 * t21 + T(7) * M_panels[15] * t17 * tau_lo + T(7) * delta_tau * t19 * M_panels[10] + T(35) * t24 * t18 * M_panels[13] + t23 * M_panels[16] + M_panels[9] * t22 + T(21) * M_panels[14] * t25 * t1 + T(35) * M_panels[12] * t16 * t20;
    G_ab = t23 * M_panels[17] + T(21) * M_panels[15] * t25 * t1 + T(35) * t16 * t20 * M_panels[13] + T(7) * t17 * tau_lo * M_panels[16] + t22 * M_panels[10] + T(21) * M_panels[12] * t0 * t21 + T(35) * M_panels[14] * t24 * t18 + T(7) * M_panels[11] * delta_tau * t19;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = sqrt(D);
    const T t27 = T(1) / t26;
    const T J2 = t27 * atan2(t26, c_minus_b);
    const T t28 = t0 * delta_tau;
    const T t29 = T(1) / a;
    const T t30 = t1 * t1;
    const T t31 = t2 * t2;
    const T t32 = t31 * t2;
    const T t33 = T(1) / D;
    const T t34 = T(1) / q1;
    const T t35 = J2 * a + a_minus_b * t34 + t2 * b;
    const T t36 = t34 * t34;
    const T t37 = T(2) * t31 * b + T(3) * t33 * a * t35 + T(2) * a_minus_b * t36;
    const T t38 = t36 * t34;
    const T t39 = T(5) * t33 * a * t37 + T(8) * t32 * b + T(8) * a_minus_b * t38;
    const T t40 = T(8) * t32 + t33 * t39 * b - T(8) * t38;
    const T t41 = T(2) * t29 * t40 * b + T(6) * t33 * t37 - c * t33 * t39;
    const T t42 = T(2) * t31 + t33 * t37 * b - T(2) * t36;
    const T t43 = T(2) * t29 * b * t41 + T(6) * t42 * t29 - c * t29 * t40;
    const T t44 = t30 * tau_lo;
    const T t45 = t1 * tau_lo;
    const T t46 = t45 * t45;
    const T t47 = t46 * tau_lo;
    const T t48 = T(4) * t33 * t35 + T(2) * t42 * t29 * b - c * t33 * t37;
    const T t49 = c * t29 * t41 - T(2) * t29 * b * t43 - T(6) * t29 * t48;
    const T t50 = t34 - t33 * b * t35 - t2;
    const T t51 = T(4) * t50 * t29 + c * t42 * t29 - T(2) * t29 * b * t48;
    const T t52 = T(2) * J2 - c * t33 * t35 - T(2) * t50 * t29 * b;
    const T t53 = c * t29 * t48 + T(2) * t29 * t51 * b - T(4) * t29 * t52;
    const T t54 = c * t29 * t43 + T(2) * t29 * b * t49 + T(6) * t29 * t51;
    const T t55 = c * t29 * t49 - T(6) * t29 * t53 - T(2) * t29 * t54 * b;
    const T t56 = t28 * t28;
    const T t57 = t0 * t0;
    const T t58 = t57 * delta_tau;
    const T t59 = t56 * delta_tau;
    F = (T(35) / T(48)) * t28 * t29 * t30 * t43 + (T(7) / T(16)) * t0 * t29 * t44 * t41 + (T(7) / T(48)) * delta_tau * t29 * t40 * t46 + (T(1) / T(48)) * t33 * t47 * t39 + (T(7) / T(48)) * t55 * t56 * t29 * tau_lo - (T(7) / T(16)) * t58 * t29 * t54 * t1 - (T(35) / T(48)) * t57 * t29 * t45 * t49 - (T(1) / T(48)) * (T(6) * t29 * (T(2) * t29 * t53 * b - c * t29 * t51 - T(4) * t29 * (t29 * (T(2) * J2 * b + log_ratio) + T(2) * t29 * t52 * b + c * t50 * t29)) - c * t29 * t54 - T(2) * t55 * t29 * b) * t59 * t29;
    const T t60 = t31 * t31;
    const T t61 = t36 * t36;
    const T t62 = T(48) * t60 * b + T(7) * t33 * a * t39 + T(48) * a_minus_b * t61;
    const T t63 = t62 * t33 * b + T(48) * t60 - T(48) * t61;
    const T t64 = T(2) * t29 * t63 * b + T(8) * t33 * t39 - c * t62 * t33;
    const T t65 = T(8) * t29 * t40 + T(2) * t64 * t29 * b - c * t29 * t63;
    const T t66 = T(2) * t29 * b * t65 + T(8) * t29 * t41 - t64 * c * t29;
    const T t67 = c * t29 * t65 - T(8) * t29 * t43 - T(2) * t66 * t29 * b;
    const T t68 = c * t66 * t29 + T(8) * t29 * t49 + T(2) * t29 * t67 * b;
    const T t69 = T(2) * t29 * t68 * b + T(8) * t29 * t54 - c * t29 * t67;
    G_ap = (T(1) / T(384)) * t62 * t33 * t47 + (T(7) / T(128)) * t64 * t0 * t29 * t44 + (T(7) / T(384)) * delta_tau * t29 * t46 * t63 + (T(35) / T(384)) * t66 * t57 * t29 * t45 + (T(35) / T(384)) * t28 * t29 * t30 * t65 - (T(7) / T(128)) * t58 * t29 * t1 * t67 - (T(7) / T(384)) * t56 * t29 * tau_lo * t68 - (T(1) / T(384)) * t59 * t29 * t69;
    G_ab = (T(7) / T(128)) * t0 * t29 * t44 * t65 + (T(35) / T(384)) * t66 * t28 * t29 * t30 + (T(1) / T(384)) * t59 * t29 * (T(8) * t55 * t29 + c * t29 * t68 - T(2) * t29 * t69 * b) + (T(1) / T(384)) * t29 * t47 * t63 + (T(7) / T(384)) * t64 * delta_tau * t29 * t46 - (T(7) / T(128)) * t58 * t29 * t1 * t68 - (T(7) / T(384)) * t56 * t29 * tau_lo * t69 - (T(35) / T(384)) * t57 * t29 * t45 * t67;
  }
  const T t70 = sigma2 * sigma2;
  const T t71 = t70 * t70;
  const T g_factor = -T(8) * length * t71;
  f = length * F * t71;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 270 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 14547 +, 25155 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = sqrt(a);
    const T t5 = b * r1;
    X = t3 * t4 * (t5 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = b * r1;
    X = t6 * (b - a_minus_b) / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  const T t10 = T(4) * D - a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t0 * delta_tau;
    const T t16 = t0 * t0;
    const T t17 = t16 * t16;
    const T t18 = t1 * tau_lo;
    const T t19 = t16 * delta_tau;
    const T t20 = t13 * t13;
    const T t21 = t15 * t15;
    const T t22 = t18 * t18;
    const T t23 = t21 * delta_tau;
    const T t24 = t22 * tau_lo;
    F = T(56) * t14 * t15 * M_panels[3] + M_panels[8] * t17 + T(70) * t13 * t16 * M_panels[4] + T(56) * M_panels[5] * t18 * t19 + t20 * M_panels[0] + T(28) * t1 * t21 * M_panels[6] + T(28) * t22 * M_panels[2] * t0 + T(8) * tau_lo * t23 * M_panels[7] + T(8) * t24 * delta_tau * M_panels[1];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 9> M_panels;
    segment_moments_gauss_panels<T>(9, 9, 8, a, b, a_minus_b, D, M_panels.data());
    const T t25 = t1 * t1;
    const T t26 = t0 * t0;
    const T t27 = t0 * delta_tau;
    const T t28 = t27 * t27;
    const T t29 = t28 * delta_tau;
    const T t30 = t1 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t31 * tau_lo;
    const T t33 = t26 * delta_tau;
    const T t34 = t26 * t26;
    const T t35 = t25 * tau_lo;
    const T t36 = t25 * t25;
    F = T(70) * t25 * t26 * M_panels[4] + T(8) * tau_lo * t29 * M_panels[7] + T(8) * t32 * delta_tau * M_panels[1] + T(28) * t1 * t28 * M_panels[6] + T(56) * M_panels[5] * t30 * t33 + M_panels[8] * t34 + T(28) * M_panels[2] * t31 * t0 + T(56) * t35 * t27 * M_panels[3] + t36 * M_panels[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t37 = T(1) / a;
    const T t38 = T(1) / r0;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = t40 * t39;
    const T t42 = T(1) / D;
    const T t43 = T(1) / r1;
    const T t44 = t38 * b + a_minus_b * t43;
    const T t45 = t43 * t43;
    const T t46 = T(2) * t42 * t44 * a + t38 * b * t39 + a_minus_b * t43 * t45;
    const T t47 = t45 * t45;
    const T t48 = T(4) * t46 * t42 * a + T(3) * a_minus_b * t43 * t47 + T(3) * t38 * b * t40;
    const T t49 = t47 * t45;
    const T t50 = T(2) * t42 * a * t48 + T(5) * a_minus_b * t43 * t49 + T(5) * t38 * b * t41;
    const T t51 = T(5) * t38 * t41 + t42 * b * t50 - T(5) * t43 * t49;
    const T t52 = T(6) * t37 * b * t51 + T(7) * t42 * t48 - T(3) * t42 * t50 * c;
    const T t53 = t42 * b * t48 + T(3) * t38 * t40 - T(3) * t43 * t47;
    const T t54 = T(2) * t37 * t52 * b + T(7) * t53 * t37 - T(3) * t37 * t51 * c;
    const T t55 = T(2) * t53 * t37 * b + T(5) * t46 * t42 - t42 * t48 * c;
    const T t56 = T(2) * t37 * t54 * b + T(7) * t37 * t55 - t37 * t52 * c;
    const T t57 = t46 * t42 * b + t38 * t39 - t43 * t45;
    const T t58 = t53 * t37 * c - T(2) * t37 * t55 * b - T(5) * t37 * t57;
    const T t59 = T(2) * t37 * b * t56 - T(7) * t37 * t58 - t37 * t54 * c;
    const T t60 = T(2) * t37 * b * t57 + T(3) * t42 * t44 - t46 * t42 * c;
    const T t61 = T(2) * t37 * t58 * b + t37 * t55 * c - T(5) * t37 * t60;
    const T t62 = T(2) * t37 * t59 * b - t37 * t56 * c - T(7) * t61 * t37;
    const T t63 = t0 * delta_tau;
    const T t64 = t63 * t63;
    const T t65 = t1 * t1;
    const T t66 = t65 * t65;
    const T t67 = t65 * tau_lo;
    const T t68 = t0 * t0;
    const T t69 = t1 * tau_lo;
    const T t70 = t68 * delta_tau;
    const T t71 = t69 * t69;
    const T t72 = t71 * tau_lo;
    const T t73 = t68 * t68;
    const T t74 = t42 * t44 * b + t38 - t43;
    const T t75 = t37 * t57 * c - T(2) * t37 * t60 * b - T(3) * t37 * t74;
    const T t76 = T(2) * t61 * t37 * b + T(5) * t37 * t75 - t37 * t58 * c;
    const T t77 = t37 * t59 * c + T(7) * t37 * t76 - T(2) * t62 * t37 * b;
    const T t78 = t64 * delta_tau;
    F = (T(4) / T(15)) * t62 * t37 * t1 * t64 + (T(1) / T(35)) * t42 * t66 * t50 + (T(8) / T(15)) * t37 * t54 * t67 * t63 + (T(2) / T(3)) * t37 * t65 * t68 * t56 + (T(8) / T(15)) * t37 * t59 * t69 * t70 + (T(8) / T(35)) * t37 * t72 * delta_tau * t51 + (T(4) / T(15)) * t37 * t71 * t0 * t52 - (T(1) / T(105)) * t37 * t73 * (t62 * t37 * c + T(7) * t37 * (T(2) * t37 * t76 * b + T(5) * t37 * (t37 * t60 * c + T(2) * t37 * t75 * b - T(3) * t37 * (T(2) * t37 * b * t74 + J1 - t42 * t44 * c)) - t61 * t37 * c) + T(2) * t37 * b * t77) - (T(8) / T(105)) * t37 * tau_lo * t78 * t77;
  }
  const T t79 = sigma2 * sigma2;
  const T t80 = t79 * t79;
  f = F * t80 * in.sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 116 +, 354 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 15637 +, 28421 ×, 2435 /, 1139 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(11, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t1 * tau_lo;
    const T t6 = t0 * t0;
    const T t7 = t6 * delta_tau;
    const T t8 = t0 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t9 * delta_tau;
    const T t11 = t5 * t5;
    const T t12 = t11 * tau_lo;
    const T t13 = t1 * t1;
    const T t14 = t13 * t13;
    const T t15 = t6 * t6;
    const T t16 = t13 * tau_lo;
    G_ap = T(56) * t5 * M_panels[5] * t7 + T(8) * tau_lo * t10 * M_panels[7] + T(28) * t11 * M_panels[2] * t0 + T(28) * t1 * M_panels[6] * t9 + T(8) * t12 * M_panels[1] * delta_tau + t14 * M_panels[0] + T(70) * t13 * M_panels[4] * t6 + M_panels[8] * t15 + T(56) * t16 * M_panels[3] * t8;
    G_ab = T(8) * tau_lo * M_panels[8] * t10 + T(28) * t11 * M_panels[3] * t0 + t14 * M_panels[1] + T(56) * t16 * M_panels[4] * t8 + T(8) * t12 * M_panels[2] * delta_tau + M_panels[9] * t15 + T(28) * t1 * t9 * M_panels[7] + T(70) * t13 * M_panels[5] * t6 + T(56) * t5 * M_panels[6] * t7;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(11, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t17 = t0 * t0;
    const T t18 = t17 * t17;
    const T t19 = t1 * tau_lo;
    const T t20 = t19 * t19;
    const T t21 = t20 * tau_lo;
    const T t22 = t1 * t1;
    const T t23 = t22 * tau_lo;
    const T t24 = t0 * delta_tau;
    const T t25 = t17 * delta_tau;
    const T t26 = t24 * t24;
    const T t27 = t26 * delta_tau;
    const T t28 = t22 * t22;
    G_ap = M_panels[8] * t18 + T(8) * t21 * M_panels[1] * delta_tau + T(70) * t22 * M_panels[4] * t17 + T(56) * t23 * M_panels[3] * t24 + T(56) * t19 * M_panels[5] * t25 + T(28) * t1 * M_panels[6] * t26 + T(8) * tau_lo * M_panels[7] * t27 + t28 * M_panels[0] + T(28) * t20 * M_panels[2] * t0;
    G_ab = T(56) * t19 * M_panels[6] * t25 + T(70) * t22 * M_panels[5] * t17 + T(28) * t1 * M_panels[7] * t26 + t28 * M_panels[1] + T(56) * t23 * M_panels[4] * t24 + T(28) * t20 * M_panels[3] * t0 + M_panels[9] * t18 + T(8) * tau_lo * M_panels[8] * t27 + T(8) * t21 * M_panels[2] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = t1 * t1;
    const T t30 = t29 * t29;
    const T t31 = T(1) / r1;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t32;
    const T t35 = T(1) / r0;
    const T t36 = t35 * t35;
    const T t37 = t36 * t36;
    const T t38 = t37 * t36;
    const T t39 = t31 * a_minus_b + b * t35;
    const T t40 = T(1) / D;
    const T t41 = t32 * t31 * a_minus_b + b * t35 * t36 + T(2) * a * t39 * t40;
    const T t42 = T(4) * a * t41 * t40 + T(3) * t33 * t31 * a_minus_b + T(3) * b * t35 * t37;
    const T t43 = T(5) * t34 * t31 * a_minus_b + T(5) * b * t35 * t38 + T(2) * a * t42 * t40;
    const T t44 = t37 * t37;
    const T t45 = t33 * t33;
    const T t46 = T(8) * a * t43 * t40 + T(35) * b * t35 * t44 + T(35) * t45 * t31 * a_minus_b;
    const T t47 = T(1) / a;
    const T t48 = T(35) * t45 * t31 - T(35) * t35 * t44 - t46 * b * t40;
    const T t49 = T(5) * t35 * t38 + t43 * b * t40 - T(5) * t34 * t31;
    const T t50 = t46 * c * t40 + T(2) * t47 * b * t48 - T(9) * t43 * t40;
    const T t51 = t47 * c * t48 + T(9) * t47 * t49 - T(2) * t47 * b * t50;
    const T t52 = T(6) * t47 * t49 * b + T(7) * t42 * t40 - T(3) * t43 * c * t40;
    const T t53 = T(2) * t47 * t51 * b + t47 * t50 * c + T(3) * t52 * t47;
    const T t54 = t0 * t0;
    const T t55 = t29 * tau_lo;
    const T t56 = t0 * delta_tau;
    const T t57 = t1 * tau_lo;
    const T t58 = T(3) * t35 * t37 + b * t42 * t40 - T(3) * t33 * t31;
    const T t59 = T(7) * t47 * t58 + T(2) * t52 * t47 * b - T(3) * t47 * t49 * c;
    const T t60 = T(2) * t47 * t53 * b + T(3) * t47 * t59 - t47 * t51 * c;
    const T t61 = t54 * delta_tau;
    const T t62 = T(5) * t41 * t40 + T(2) * t47 * b * t58 - c * t42 * t40;
    const T t63 = T(7) * t47 * t62 + T(2) * t47 * b * t59 - t52 * t47 * c;
    const T t64 = T(2) * t47 * b * t60 + T(3) * t47 * t63 - t47 * t53 * c;
    const T t65 = t56 * t56;
    const T t66 = t32 * t31 - b * t41 * t40 - t35 * t36;
    const T t67 = T(2) * t47 * b * t62 - T(5) * t47 * t66 - t47 * c * t58;
    const T t68 = t47 * c * t59 - T(7) * t47 * t67 - T(2) * t47 * b * t63;
    const T t69 = T(3) * t47 * t68 + t47 * c * t60 - T(2) * t47 * b * t64;
    const T t70 = t65 * delta_tau;
    const T t71 = t57 * t57;
    const T t72 = t71 * tau_lo;
    const T t73 = t41 * c * t40 + T(2) * t47 * b * t66 - T(3) * t39 * t40;
    const T t74 = t47 * t62 * c + T(5) * t47 * t73 - T(2) * t47 * b * t67;
    const T t75 = T(7) * t47 * t74 + t47 * c * t63 + T(2) * t47 * b * t68;
    const T t76 = t47 * c * t64 + T(3) * t47 * t75 + T(2) * t47 * b * t69;
    const T t77 = t54 * t54;
    G_ap = (T(1) / T(315)) * t30 * t46 * t40 + (T(2) / T(9)) * t29 * t47 * t53 * t54 + (T(8) / T(45)) * t55 * t47 * t51 * t56 + (T(8) / T(45)) * t57 * t47 * t60 * t61 + (T(4) / T(45)) * t1 * t47 * t64 * t65 - (T(8) / T(315)) * tau_lo * t47 * t69 * t70 - (T(8) / T(315)) * t72 * t47 * delta_tau * t48 - (T(4) / T(45)) * t71 * t47 * t50 * t0 - (T(1) / T(315)) * t47 * t76 * t77;
    G_ab = (T(8) / T(45)) * t55 * t47 * t53 * t56 + (T(1) / T(315)) * t47 * (T(3) * t47 * (t47 * c * t68 - T(7) * t47 * (t47 * t67 * c + T(5) * t47 * (T(3) * t47 * (t31 - t35 - t39 * b * t40) + T(2) * t47 * t73 * b - t47 * t66 * c) + T(2) * t47 * b * t74) - T(2) * t47 * b * t75) + t47 * t69 * c - T(2) * t47 * b * t76) * t77 + (T(2) / T(9)) * t29 * t47 * t60 * t54 + (T(4) / T(45)) * t71 * t47 * t51 * t0 + (T(8) / T(45)) * t57 * t47 * t64 * t61 - (T(8) / T(315)) * t72 * t47 * t50 * delta_tau - (T(1) / T(315)) * t30 * t47 * t48 - (T(8) / T(315)) * tau_lo * t47 * t76 * t70 - (T(4) / T(45)) * t1 * t47 * t69 * t65;
  }
  const T t78 = sigma2 * sigma2;
  const T t79 = t78 * t78;
  const T g_factor = -T(9) * t79 * in.sigma * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 133 +, 423 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 26446 +, 40333 ×, 2437 /, 1141 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = sqrt(a);
    const T t4 = a_minus_b * r0;
    const T t5 = T(1) / D;
    X = t3 * (t4 + r1 * b) * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = a_minus_b * r0;
    X = t6 * (a_minus_b - b) / (t7 - r1 * b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t10 = T(4) * D - a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t14 * delta_tau;
    const T t16 = t0 * t0;
    const T t17 = t16 * t16;
    const T t18 = t16 * delta_tau;
    const T t19 = t1 * tau_lo;
    const T t20 = t1 * t1;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t20 * tau_lo;
    const T t24 = t22 * tau_lo;
    F = T(28) * t14 * t1 * M_panels[6] + T(8) * t15 * tau_lo * M_panels[7] + t17 * M_panels[8] + T(56) * t18 * t19 * M_panels[5] + T(70) * t16 * t20 * M_panels[4] + t21 * M_panels[0] + T(28) * t0 * t22 * M_panels[2] + T(56) * t13 * M_panels[3] * t23 + T(8) * delta_tau * t24 * M_panels[1];
    G_ap = T(56) * t18 * t19 * M_panels[15] + T(70) * t16 * t20 * M_panels[14] + t21 * M_panels[10] + T(56) * t13 * t23 * M_panels[13] + T(28) * t0 * t22 * M_panels[12] + T(8) * t15 * tau_lo * M_panels[17] + T(28) * t14 * t1 * M_panels[16] + t17 * M_panels[18] + T(8) * delta_tau * t24 * M_panels[11];
    G_ab = T(56) * t18 * t19 * M_panels[16] + t17 * M_panels[19] + T(8) * delta_tau * t24 * M_panels[12] + T(70) * t16 * t20 * M_panels[15] + t21 * M_panels[11] + T(56) * t13 * t23 * M_panels[14] + T(8) * t15 * tau_lo * M_panels[18] + T(28) * t14 * t1 * M_panels[17] + T(28) * t0 * t22 * M_panels[13];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 20> M_panels;
    segment_moments_gauss_panels<T>(9, 11, 9, a, b, a_minus_b, D, M_panels.data());
    const T t25 = t0 * delta_tau;
    const T t26 = t25 * t25;
    const T t27 = t26 * delta_tau;
    const T t28 = t1 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = t29 * tau_lo;
    const T t31 = t0 * t0;
    const T t32 = t1 * t1;
    const T t33 = t32 * t32;
    const T t34 = t32 * tau_lo;
    const T t35 = t31 * delta_tau;
    const T t36 = t31 * t31;
    F = T(8) * t27 * tau_lo * M_panels[7] + T(28) * t26 * t1 * M_panels[6] + T(8) * delta_tau * t30 * M_panels[1] + T(70) * t31 * t32 * M_panels[4] + t33 * M_panels[0] + T(56) * t25 * t34 * M_panels[3] + T(28) * t0 * t29 * M_panels[2] + T(56) * t35 * M_panels[5] * t28 + t36 * M_panels[8];
    G_ap = T(56) * t35 * t28 * M_panels[15] + T(70) * t31 * t32 * M_panels[14] + T(56) * t25 * t34 * M_panels[13] + t36 * M_panels[18] + T(28) * t0 * t29 * M_panels[12] + t33 * M_panels[10] + T(8) * t27 * tau_lo * M_panels[17] + T(8) * delta_tau * t30 * M_panels[11] + T(28) * t26 * t1 * M_panels[16];
    G_ab = T(8) * t27 * tau_lo * M_panels[18] + T(28) * t26 * t1 * M_panels[17] + T(56) * t35 * t28 * M_panels[16] + t33 * M_panels[11] + T(8) * delta_tau * t30 * M_panels[12] + T(70) * t31 * t32 * M_panels[15] + T(56) * t25 * t34 * M_panels[14] + T(28) * t0 * t29 * M_panels[13] + t36 * M_panels[19];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t37 = t0 * t0;
    const T t38 = t37 * delta_tau;
    const T t39 = T(1) / a;
    const T t40 = t1 * tau_lo;
    const T t41 = T(1) / r0;
    const T t42 = t41 * t41;
    const T t43 = t42 * t42;
    const T t44 = t43 * t42;
    const T t45 = T(1) / r1;
    const T t46 = t45 * a_minus_b + b * t41;
    const T t47 = T(1) / D;
    const T t48 = t45 * t45;
    const T t49 = b * t42 * t41 + T(2) * a * t46 * t47 + t45 * a_minus_b * t48;
    const T t50 = t48 * t48;
    const T t51 = T(4) * a * t49 * t47 + T(3) * t45 * a_minus_b * t50 + T(3) * b * t43 * t41;
    const T t52 = t50 * t48;
    const T t53 = T(2) * a * t51 * t47 + T(5) * t45 * a_minus_b * t52 + T(5) * b * t44 * t41;
    const T t54 = T(5) * t44 * t41 + b * t53 * t47 - T(5) * t45 * t52;
    const T t55 = t51 * b * t47 + T(3) * t43 * t41 - T(3) * t45 * t50;
    const T t56 = T(7) * t51 * t47 + T(6) * t39 * b * t54 - T(3) * c * t53 * t47;
    const T t57 = T(3) * t39 * c * t54 - T(7) * t39 * t55 - T(2) * t39 * t56 * b;
    const T t58 = t49 * b * t47 + t42 * t41 - t45 * t48;
    const T t59 = T(5) * t49 * t47 + T(2) * t39 * t55 * b - t51 * c * t47;
    const T t60 = T(5) * t39 * t58 + T(2) * t39 * b * t59 - t39 * t55 * c;
    const T t61 = T(2) * t39 * t57 * b + t39 * t56 * c - T(7) * t39 * t59;
    const T t62 = t39 * t57 * c + T(7) * t39 * t60 - T(2) * t39 * b * t61;
    const T t63 = t40 * t40;
    const T t64 = t63 * tau_lo;
    const T t65 = t0 * delta_tau;
    const T t66 = t65 * t65;
    const T t67 = T(3) * t46 * t47 + T(2) * t39 * b * t58 - t49 * c * t47;
    const T t68 = T(2) * t39 * b * t60 + T(5) * t39 * t67 - t39 * t59 * c;
    const T t69 = T(7) * t39 * t68 + T(2) * t39 * b * t62 + t39 * t61 * c;
    const T t70 = t1 * t1;
    const T t71 = t70 * t70;
    const T t72 = t70 * tau_lo;
    const T t73 = t37 * t37;
    const T t74 = t45 - t41 - b * t46 * t47;
    const T t75 = t39 * c * t58 + T(3) * t39 * t74 - T(2) * t39 * b * t67;
    const T t76 = T(5) * t39 * t75 + t39 * t60 * c - T(2) * t39 * b * t68;
    const T t77 = t39 * c * t62 + T(7) * t39 * t76 - T(2) * t39 * b * t69;
    const T t78 = t66 * delta_tau;
    F = (T(8) / T(15)) * t38 * t39 * t40 * t62 + (T(8) / T(35)) * delta_tau * t39 * t64 * t54 + (T(4) / T(15)) * t66 * t39 * t1 * t69 + (T(1) / T(35)) * t71 * t53 * t47 + (T(4) / T(15)) * t0 * t39 * t63 * t56 - (T(8) / T(15)) * t65 * t39 * t72 * t57 - (T(2) / T(3)) * t37 * t39 * t70 * t61 - (T(1) / T(105)) * t73 * t39 * (t39 * c * t69 + T(7) * t39 * (T(5) * t39 * (T(2) * t39 * b * t75 + T(3) * t39 * (c * t46 * t47 + T(2) * t39 * t74 * b - J1) + t39 * c * t67) + t39 * c * t68 + T(2) * t39 * t76 * b) + T(2) * t39 * b * t77) - (T(8) / T(105)) * t78 * t39 * tau_lo * t77;
    const T t79 = t43 * t43;
    const T t80 = t50 * t50;
    const T t81 = T(35) * b * t79 * t41 + T(8) * a * t53 * t47 + T(35) * t45 * a_minus_b * t80;
    const T t82 = T(35) * t45 * t80 - T(35) * t79 * t41 - t81 * b * t47;
    const T t83 = t81 * c * t47 + T(2) * t39 * t82 * b - T(9) * t53 * t47;
    const T t84 = T(9) * t39 * t54 + t39 * t82 * c - T(2) * t39 * b * t83;
    const T t85 = t39 * c * t83 + T(3) * t39 * t56 + T(2) * t39 * b * t84;
    const T t86 = t39 * t84 * c + T(3) * t39 * t57 - T(2) * t39 * t85 * b;
    const T t87 = t39 * t85 * c + T(3) * t39 * t61 + T(2) * t39 * b * t86;
    const T t88 = t39 * c * t86 + T(3) * t39 * t62 - T(2) * t39 * t87 * b;
    const T t89 = T(2) * t39 * b * t88 + T(3) * t39 * t69 + t39 * t87 * c;
    G_ap = (T(2) / T(9)) * t37 * t39 * t70 * t85 + (T(8) / T(315)) * t78 * t39 * tau_lo * t88 + (T(1) / T(315)) * t73 * t39 * t89 + (T(8) / T(45)) * t65 * t39 * t72 * t84 + (T(1) / T(315)) * t71 * t81 * t47 - (T(8) / T(45)) * t38 * t39 * t40 * t86 - (T(8) / T(315)) * delta_tau * t39 * t64 * t82 - (T(4) / T(45)) * t0 * t39 * t63 * t83 - (T(4) / T(45)) * t66 * t39 * t1 * t87;
    G_ab = (T(4) / T(45)) * t66 * t39 * t1 * t88 + (T(4) / T(45)) * t0 * t39 * t63 * t84 + (T(8) / T(45)) * t65 * t39 * t72 * t85 + (T(8) / T(315)) * t78 * t39 * tau_lo * t89 - (T(8) / T(315)) * delta_tau * t39 * t64 * t83 - (T(8) / T(45)) * t38 * t39 * t40 * t87 - (T(2) / T(9)) * t37 * t39 * t70 * t86 - (T(1) / T(315)) * t73 * t39 * (t39 * t88 * c + T(3) * t39 * t77 - T(2) * t39 * b * t89) - (T(1) / T(315)) * t39 * t71 * t82;
  }
  const T t90 = sigma2 * sigma2;
  const T t91 = t90 * t90;
  const T g_factor = -T(9) * t91 * length * in.sigma;
  f = F * t91 * length * in.sigma;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 107 +, 298 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 15630 +, 21920 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_hi * tau_lo * sigma2;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = T(4) * D - a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t0 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t1 * tau_lo;
    const T t12 = t0 * t0;
    const T t13 = t12 * delta_tau;
    const T t14 = t6 * tau_lo;
    const T t15 = t11 * t11;
    const T t16 = t15 * tau_lo;
    const T t17 = t12 * t12;
    const T t18 = t10 * delta_tau;
    const T t19 = t17 * delta_tau;
    F = M_panels[0] * t8 + T(84) * M_panels[6] * t10 * t11 + T(126) * t13 * t6 * M_panels[5] + T(126) * t12 * M_panels[4] * t14 + T(84) * M_panels[3] * t9 * t15 + T(36) * M_panels[2] * t0 * t16 + T(9) * delta_tau * t7 * M_panels[1] + T(9) * t17 * tau_lo * M_panels[8] + T(36) * M_panels[7] * t18 * t1 + M_panels[9] * t19;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 10> M_panels;
    segment_moments_gauss_panels<T>(10, 10, 9, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t0 * t0;
    const T t21 = t1 * t1;
    const T t22 = t21 * tau_lo;
    const T t23 = t0 * delta_tau;
    const T t24 = t23 * t23;
    const T t25 = t24 * delta_tau;
    const T t26 = t1 * tau_lo;
    const T t27 = t20 * delta_tau;
    const T t28 = t20 * t20;
    const T t29 = t26 * t26;
    const T t30 = t29 * tau_lo;
    const T t31 = t28 * delta_tau;
    const T t32 = t21 * t21;
    const T t33 = t32 * tau_lo;
    F = T(126) * t20 * t22 * M_panels[4] + T(36) * t25 * t1 * M_panels[7] + T(84) * M_panels[6] * t24 * t26 + T(126) * M_panels[5] * t27 * t21 + T(9) * M_panels[8] * t28 * tau_lo + T(36) * M_panels[2] * t0 * t30 + M_panels[9] * t31 + T(9) * delta_tau * t32 * M_panels[1] + M_panels[0] * t33 + T(84) * M_panels[3] * t23 * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = sqrt(D);
    const T t35 = T(1) / t34;
    const T J2 = atan2(t34, c_minus_b) * t35;
    const T t36 = T(1) / D;
    const T t37 = T(1) / q1;
    const T t38 = t37 * t37;
    const T t39 = t38 * t38;
    const T t40 = a * J2 + b * t2 + a_minus_b * t37;
    const T t41 = t2 * t2;
    const T t42 = T(2) * a_minus_b * t38 + T(3) * t36 * a * t40 + T(2) * b * t41;
    const T t43 = t38 * t37;
    const T t44 = t41 * t2;
    const T t45 = T(5) * t42 * t36 * a + T(8) * a_minus_b * t43 + T(8) * b * t44;
    const T t46 = t41 * t41;
    const T t47 = T(48) * a_minus_b * t39 + T(7) * t36 * a * t45 + T(48) * b * t46;
    const T t48 = b * t36 * t47 + T(48) * t46 - T(48) * t39;
    const T t49 = T(1) / a;
    const T t50 = t1 * t1;
    const T t51 = t50 * t50;
    const T t52 = T(2) * t38 - b * t42 * t36 - T(2) * t41;
    const T t53 = T(4) * t36 * t40 - t42 * c * t36 - T(2) * b * t52 * t49;
    const T t54 = b * t36 * t45 + T(8) * t44 - T(8) * t43;
    const T t55 = T(2) * b * t54 * t49 + T(6) * t42 * t36 - c * t36 * t45;
    const T t56 = c * t54 * t49 + T(6) * t52 * t49 - T(2) * b * t49 * t55;
    const T t57 = T(6) * t53 * t49 - c * t49 * t55 - T(2) * b * t49 * t56;
    const T t58 = c * t36 * t47 - T(8) * t36 * t45 - T(2) * b * t48 * t49;
    const T t59 = T(2) * b * t58 * t49 + t48 * c * t49 - T(8) * t54 * t49;
    const T t60 = T(2) * b * t49 * t59 - c * t58 * t49 - T(8) * t49 * t55;
    const T t61 = c * t49 * t59 - T(2) * b * t60 * t49 - T(8) * t49 * t56;
    const T t62 = T(8) * t57 * t49 + t60 * c * t49 + T(2) * b * t61 * t49;
    const T t63 = t2 + b * t36 * t40 - t37;
    const T t64 = c * t52 * t49 + T(2) * b * t53 * t49 + T(4) * t63 * t49;
    const T t65 = T(2) * b * t57 * t49 + c * t49 * t56 + T(6) * t64 * t49;
    const T t66 = T(2) * b * t49 * t62 + T(8) * t65 * t49 - t61 * c * t49;
    const T t67 = t0 * delta_tau;
    const T t68 = t67 * t67;
    const T t69 = t68 * delta_tau;
    const T t70 = t51 * tau_lo;
    const T t71 = t0 * t0;
    const T t72 = t71 * delta_tau;
    const T t73 = t1 * tau_lo;
    const T t74 = t73 * t73;
    const T t75 = t74 * tau_lo;
    const T t76 = t50 * tau_lo;
    const T t77 = T(2) * b * t63 * t49 + T(2) * J2 - c * t36 * t40;
    const T t78 = T(4) * t77 * t49 + T(2) * b * t64 * t49 - t53 * c * t49;
    const T t79 = T(2) * b * t65 * t49 + T(6) * t78 * t49 - c * t57 * t49;
    const T t80 = c * t49 * t62 - T(8) * t49 * t79 - T(2) * t66 * b * t49;
    const T t81 = t71 * t71;
    const T t82 = t81 * delta_tau;
    F = (T(3) / T(128)) * t48 * delta_tau * t49 * t51 + (T(3) / T(32)) * t66 * t69 * t49 * t1 + (T(1) / T(384)) * t36 * t47 * t70 + (T(21) / T(64)) * t61 * t72 * t49 * t50 + (T(7) / T(32)) * t68 * t49 * t73 * t62 - (T(3) / T(32)) * t58 * t0 * t49 * t75 - (T(7) / T(32)) * t67 * t49 * t74 * t59 - (T(21) / T(64)) * t60 * t71 * t49 * t76 - (T(3) / T(128)) * t80 * t81 * t49 * tau_lo - (T(1) / T(384)) * (T(8) * (c * t65 * t49 + T(6) * (c * t64 * t49 - T(2) * b * t78 * t49 - T(4) * ((log_ratio + T(2) * b * J2) * t49 + T(2) * b * t77 * t49 - t63 * c * t49) * t49) * t49 - T(2) * b * t49 * t79) * t49 + T(2) * b * t80 * t49 + t66 * c * t49) * t82 * t49;
  }
  const T t83 = sigma2 * sigma2;
  const T t84 = t83 * t83;
  const T t85 = t84 * sigma2;
  f = length * F * t85;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 132 +, 393 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 16722 +, 24114 ×, 2435 /, 57 sqrt, 0 atan, 0 log/asinh.
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
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_ab;
  const T t2 = T(4) * D - a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 11> M_panels;
    segment_moments_gauss_panels<T>(12, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t5 = t0 * t0;
    const T t6 = t5 * t5;
    const T t7 = t6 * delta_tau;
    const T t8 = t0 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t1 * tau_lo;
    const T t11 = t10 * t10;
    const T t12 = t11 * tau_lo;
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t9 * delta_tau;
    const T t16 = t13 * t13;
    const T t17 = t16 * tau_lo;
    const T t18 = t5 * delta_tau;
    G_ap = T(9) * t6 * tau_lo * M_panels[8] + t7 * M_panels[9] + T(84) * t9 * t10 * M_panels[6] + T(36) * t0 * t12 * M_panels[2] + T(126) * M_panels[4] * t5 * t14 + T(36) * M_panels[7] * t15 * t1 + M_panels[0] * t17 + T(84) * M_panels[3] * t8 * t11 + T(9) * delta_tau * M_panels[1] * t16 + T(126) * t18 * t13 * M_panels[5];
    G_ab = M_panels[1] * t17 + M_panels[10] * t7 + T(126) * t18 * t13 * M_panels[6] + T(84) * M_panels[4] * t8 * t11 + T(9) * delta_tau * t16 * M_panels[2] + T(36) * t15 * t1 * M_panels[8] + T(126) * t5 * t14 * M_panels[5] + T(36) * M_panels[3] * t0 * t12 + T(9) * t6 * tau_lo * M_panels[9] + T(84) * M_panels[7] * t9 * t10;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 11> M_panels;
    segment_moments_gauss_panels<T>(12, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t19 = t0 * t0;
    const T t20 = t19 * delta_tau;
    const T t21 = t1 * t1;
    const T t22 = t0 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t23 * delta_tau;
    const T t25 = t19 * t19;
    const T t26 = t25 * delta_tau;
    const T t27 = t1 * tau_lo;
    const T t28 = t27 * t27;
    const T t29 = t21 * tau_lo;
    const T t30 = t28 * tau_lo;
    const T t31 = t21 * t21;
    const T t32 = t31 * tau_lo;
    G_ap = T(126) * M_panels[5] * t20 * t21 + T(36) * t24 * t1 * M_panels[7] + t26 * M_panels[9] + T(84) * t22 * t28 * M_panels[3] + T(126) * t19 * t29 * M_panels[4] + T(9) * M_panels[8] * t25 * tau_lo + T(84) * t23 * t27 * M_panels[6] + T(36) * M_panels[2] * t0 * t30 + T(9) * delta_tau * t31 * M_panels[1] + t32 * M_panels[0];
    G_ab = T(84) * t23 * t27 * M_panels[7] + T(36) * M_panels[8] * t24 * t1 + T(9) * M_panels[2] * delta_tau * t31 + T(126) * M_panels[5] * t19 * t29 + T(126) * t20 * t21 * M_panels[6] + T(9) * t25 * M_panels[9] * tau_lo + T(36) * t0 * t30 * M_panels[3] + t32 * M_panels[1] + t26 * M_panels[10] + T(84) * t22 * t28 * M_panels[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t33 = sqrt(D);
    const T t34 = T(1) / t33;
    const T J2 = atan2(t33, c_minus_b) * t34;
    const T t35 = T(1) / a;
    const T t36 = T(1) / c;
    const T t37 = t36 * t36;
    const T t38 = t37 * t37;
    const T t39 = t37 * t36;
    const T t40 = T(1) / q1;
    const T t41 = t40 * t40;
    const T t42 = t41 * t40;
    const T t43 = t40 * a_minus_b + b * t36 + a * J2;
    const T t44 = T(1) / D;
    const T t45 = T(3) * a * t43 * t44 + T(2) * b * t37 + T(2) * t41 * a_minus_b;
    const T t46 = T(8) * b * t39 + T(8) * t42 * a_minus_b + T(5) * a * t45 * t44;
    const T t47 = t41 * t41;
    const T t48 = T(48) * b * t38 + T(7) * a * t46 * t44 + T(48) * t47 * a_minus_b;
    const T t49 = T(48) * t38 + t48 * b * t44 - T(48) * t47;
    const T t50 = t47 * t40;
    const T t51 = t38 * t36;
    const T t52 = T(3) * a * t48 * t44 + T(128) * b * t51 + T(128) * t50 * a_minus_b;
    const T t53 = T(128) * t50 - T(128) * t51 - b * t52 * t44;
    const T t54 = T(6) * t35 * t53 * b + T(3) * t52 * c * t44 - T(10) * t48 * t44;
    const T t55 = T(10) * t35 * t49 + T(3) * t35 * t53 * c - T(2) * t35 * b * t54;
    const T t56 = t48 * c * t44 - T(8) * t46 * t44 - T(2) * t35 * b * t49;
    const T t57 = T(2) * t55 * t35 * b + t35 * c * t54 - T(10) * t35 * t56;
    const T t58 = t0 * t0;
    const T t59 = t1 * t1;
    const T t60 = t59 * tau_lo;
    const T t61 = t58 * delta_tau;
    const T t62 = T(8) * t42 - b * t46 * t44 - T(8) * t39;
    const T t63 = T(2) * t35 * b * t56 + T(8) * t62 * t35 + t35 * t49 * c;
    const T t64 = T(2) * t35 * t57 * b - T(10) * t63 * t35 - t55 * t35 * c;
    const T t65 = t58 * t58;
    const T t66 = t65 * delta_tau;
    const T t67 = T(2) * t41 - T(2) * t37 - t45 * b * t44;
    const T t68 = T(2) * t62 * t35 * b + t46 * c * t44 - T(6) * t45 * t44;
    const T t69 = T(6) * t35 * t67 + T(2) * t35 * b * t68 - t62 * t35 * c;
    const T t70 = T(2) * t63 * t35 * b + T(8) * t35 * t68 - t35 * t56 * c;
    const T t71 = T(8) * t35 * t69 + T(2) * t70 * t35 * b - t63 * t35 * c;
    const T t72 = T(4) * t43 * t44 - t45 * c * t44 - T(2) * t35 * b * t67;
    const T t73 = T(2) * t35 * b * t69 - t35 * t68 * c - T(6) * t35 * t72;
    const T t74 = t70 * t35 * c - T(8) * t35 * t73 - T(2) * t35 * b * t71;
    const T t75 = b * t43 * t44 + t36 - t40;
    const T t76 = t35 * c * t67 + T(4) * t35 * t75 + T(2) * t35 * t72 * b;
    const T t77 = T(6) * t35 * t76 + t35 * t69 * c - T(2) * t35 * t73 * b;
    const T t78 = t35 * c * t71 + T(2) * t35 * t74 * b + T(8) * t77 * t35;
    const T t79 = t35 * t57 * c + T(10) * t70 * t35 - T(2) * t35 * b * t64;
    const T t80 = t35 * c * t64 + T(10) * t35 * t71 + T(2) * t79 * t35 * b;
    const T t81 = T(2) * t35 * b * t80 - t79 * t35 * c - T(10) * t35 * t74;
    const T t82 = T(10) * t35 * t78 + t35 * c * t80 - T(2) * t35 * b * t81;
    const T t83 = t59 * t59;
    const T t84 = t83 * tau_lo;
    const T t85 = t0 * delta_tau;
    const T t86 = t1 * tau_lo;
    const T t87 = t86 * t86;
    const T t88 = t87 * tau_lo;
    const T t89 = t85 * t85;
    const T t90 = t89 * delta_tau;
    G_ap = (T(21) / T(640)) * t35 * t57 * t58 * t60 + (T(21) / T(640)) * t35 * t61 * t59 * t64 + (T(1) / T(3840)) * t35 * t66 * t82 + (T(1) / T(1280)) * t84 * t52 * t44 + (T(7) / T(320)) * t55 * t35 * t85 * t87 - (T(3) / T(320)) * t35 * t0 * t88 * t54 - (T(7) / T(320)) * t79 * t35 * t89 * t86 - (T(9) / T(1280)) * t35 * t53 * delta_tau * t83 - (T(3) / T(320)) * t35 * t90 * t1 * t80 - (T(3) / T(1280)) * t35 * t65 * tau_lo * t81;
    G_ab = (T(1) / T(3840)) * t35 * t66 * (t35 * c * t81 + T(2) * t35 * b * t82 - T(10) * t35 * (t35 * t74 * c - T(8) * t35 * (T(2) * t77 * t35 * b + t35 * t73 * c - T(6) * t35 * (t35 * t72 * c + T(4) * t35 * (c * t43 * t44 - T(2) * J2 - T(2) * t35 * b * t75) - T(2) * t35 * b * t76)) - T(2) * t35 * b * t78)) + (T(21) / T(640)) * t35 * t58 * t60 * t64 + (T(3) / T(320)) * t55 * t35 * t0 * t88 + (T(7) / T(320)) * t35 * t57 * t85 * t87 + (T(3) / T(1280)) * t35 * t65 * tau_lo * t82 - (T(1) / T(1280)) * t35 * t53 * t84 - (T(3) / T(320)) * t35 * t90 * t1 * t81 - (T(7) / T(320)) * t35 * t89 * t86 * t80 - (T(21) / T(640)) * t79 * t35 * t61 * t59 - (T(3) / T(1280)) * t35 * delta_tau * t83 * t54;
  }
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T t93 = t92 * sigma2;
  const T g_factor = -T(10) * t93 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 150 +, 463 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 28611 +, 37103 ×, 2436 /, 57 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t1;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = T(4) * D - a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P at least |AB|/2 from the line (D ≥ a²/4): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t6 = t0 * t0;
    const T t7 = t6 * delta_tau;
    const T t8 = t1 * t1;
    const T t9 = t1 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t10 * tau_lo;
    const T t12 = t6 * t6;
    const T t13 = t0 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t8 * t8;
    const T t16 = t15 * tau_lo;
    const T t17 = t8 * tau_lo;
    const T t18 = t12 * delta_tau;
    const T t19 = t14 * delta_tau;
    F = T(126) * M_panels[5] * t7 * t8 + T(36) * t0 * M_panels[2] * t11 + T(9) * M_panels[8] * t12 * tau_lo + T(84) * M_panels[6] * t14 * t9 + M_panels[0] * t16 + T(126) * M_panels[4] * t6 * t17 + M_panels[9] * t18 + T(84) * M_panels[3] * t13 * t10 + T(9) * M_panels[1] * delta_tau * t15 + T(36) * M_panels[7] * t19 * t1;
    G_ap = T(9) * M_panels[19] * t12 * tau_lo + M_panels[11] * t16 + T(36) * M_panels[13] * t0 * t11 + M_panels[20] * t18 + T(84) * M_panels[17] * t14 * t9 + T(126) * M_panels[16] * t7 * t8 + T(126) * M_panels[15] * t6 * t17 + T(9) * M_panels[12] * delta_tau * t15 + T(84) * M_panels[14] * t13 * t10 + T(36) * M_panels[18] * t19 * t1;
    G_ab = M_panels[12] * t16 + T(9) * M_panels[13] * delta_tau * t15 + T(126) * M_panels[16] * t6 * t17 + T(36) * M_panels[19] * t19 * t1 + T(84) * M_panels[15] * t13 * t10 + T(9) * M_panels[20] * t12 * tau_lo + M_panels[21] * t18 + T(36) * M_panels[14] * t0 * t11 + T(84) * M_panels[18] * t14 * t9 + T(126) * M_panels[17] * t7 * t8;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): every moment by segment_moments_gauss_panels<T>
    std::array<T, 22> M_panels;
    segment_moments_gauss_panels<T>(10, 12, 10, a, b, a_minus_b, D, M_panels.data());
    const T t20 = t0 * t0;
    const T t21 = t20 * t20;
    const T t22 = t0 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t1 * tau_lo;
    const T t25 = t1 * t1;
    const T t26 = t25 * t25;
    const T t27 = t21 * delta_tau;
    const T t28 = t24 * t24;
    const T t29 = t28 * tau_lo;
    const T t30 = t20 * delta_tau;
    const T t31 = t25 * tau_lo;
    const T t32 = t23 * delta_tau;
    const T t33 = t26 * tau_lo;
    F = T(9) * M_panels[8] * t21 * tau_lo + T(84) * M_panels[6] * t23 * t24 + T(9) * M_panels[1] * delta_tau * t26 + M_panels[9] * t27 + T(36) * t0 * M_panels[2] * t29 + T(126) * t30 * M_panels[5] * t25 + T(126) * M_panels[4] * t20 * t31 + T(36) * M_panels[7] * t32 * t1 + T(84) * M_panels[3] * t22 * t28 + M_panels[0] * t33;
    G_ap = T(84) * M_panels[17] * t23 * t24 + T(84) * M_panels[14] * t22 * t28 + T(9) * M_panels[12] * delta_tau * t26 + T(9) * M_panels[19] * t21 * tau_lo + T(126) * M_panels[15] * t20 * t31 + T(36) * t32 * t1 * M_panels[18] + T(126) * M_panels[16] * t30 * t25 + T(36) * M_panels[13] * t0 * t29 + M_panels[20] * t27 + M_panels[11] * t33;
    G_ab = T(36) * M_panels[19] * t32 * t1 + M_panels[12] * t33 + T(36) * M_panels[14] * t0 * t29 + T(9) * M_panels[13] * delta_tau * t26 + M_panels[21] * t27 + T(84) * M_panels[15] * t22 * t28 + T(84) * t23 * t24 * M_panels[18] + T(126) * M_panels[17] * t30 * t25 + T(9) * M_panels[20] * t21 * tau_lo + T(126) * M_panels[16] * t20 * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t34 = sqrt(D);
    const T t35 = T(1) / t34;
    const T J2 = atan2(t34, c_minus_b) * t35;
    const T t36 = T(1) / q1;
    const T t37 = b * t2 + a_minus_b * t36 + J2 * a;
    const T t38 = T(1) / D;
    const T t39 = t2 * t2;
    const T t40 = t36 * t36;
    const T t41 = T(3) * t37 * t38 * a + T(2) * a_minus_b * t40 + T(2) * b * t39;
    const T t42 = T(2) * t39 + t41 * b * t38 - T(2) * t40;
    const T t43 = T(1) / a;
    const T t44 = T(4) * t37 * t38 + T(2) * b * t42 * t43 - t41 * c * t38;
    const T t45 = t40 * t36;
    const T t46 = t39 * t2;
    const T t47 = T(5) * t41 * t38 * a + T(8) * a_minus_b * t45 + T(8) * b * t46;
    const T t48 = b * t47 * t38 + T(8) * t46 - T(8) * t45;
    const T t49 = T(6) * t41 * t38 + T(2) * b * t48 * t43 - t47 * c * t38;
    const T t50 = T(2) * b * t49 * t43 + T(6) * t42 * t43 - t48 * c * t43;
    const T t51 = T(6) * t44 * t43 + T(2) * b * t50 * t43 - t49 * c * t43;
    const T t52 = t36 - b * t37 * t38 - t2;
    const T t53 = t42 * c * t43 + T(4) * t52 * t43 - T(2) * b * t44 * t43;
    const T t54 = T(2) * b * t51 * t43 - t50 * c * t43 - T(6) * t53 * t43;
    const T t55 = t39 * t39;
    const T t56 = t40 * t40;
    const T t57 = T(48) * b * t55 + T(48) * a_minus_b * t56 + T(7) * t47 * t38 * a;
    const T t58 = T(48) * t55 + b * t38 * t57 - T(48) * t56;
    const T t59 = c * t38 * t57 - T(8) * t47 * t38 - T(2) * t58 * b * t43;
    const T t60 = T(8) * t48 * t43 - t58 * c * t43 - T(2) * b * t59 * t43;
    const T t61 = c * t59 * t43 + T(2) * b * t60 * t43 + T(8) * t49 * t43;
    const T t62 = c * t60 * t43 - T(8) * t50 * t43 - T(2) * b * t61 * t43;
    const T t63 = T(2) * b * t62 * t43 + t61 * c * t43 - T(8) * t51 * t43;
    const T t64 = T(8) * t54 * t43 + c * t62 * t43 - T(2) * b * t63 * t43;
    const T t65 = t0 * delta_tau;
    const T t66 = t65 * t65;
    const T t67 = t66 * delta_tau;
    const T t68 = t1 * tau_lo;
    const T t69 = t68 * t68;
    const T t70 = c * t37 * t38 + T(2) * b * t52 * t43 - T(2) * J2;
    const T t71 = c * t44 * t43 + T(2) * b * t53 * t43 + T(4) * t43 * t70;
    const T t72 = c * t51 * t43 + T(6) * t71 * t43 - T(2) * b * t54 * t43;
    const T t73 = c * t63 * t43 + T(2) * b * t64 * t43 - T(8) * t72 * t43;
    const T t74 = t0 * t0;
    const T t75 = t74 * t74;
    const T t76 = t1 * t1;
    const T t77 = t76 * t76;
    const T t78 = t77 * tau_lo;
    const T t79 = t76 * tau_lo;
    const T t80 = t74 * delta_tau;
    const T t81 = t69 * tau_lo;
    const T t82 = t75 * delta_tau;
    F = (T(3) / T(32)) * t64 * t67 * t43 * t1 + (T(7) / T(32)) * t65 * t60 * t43 * t69 + (T(3) / T(128)) * t73 * t75 * t43 * tau_lo + (T(1) / T(384)) * t38 * t57 * t78 + (T(3) / T(128)) * t58 * delta_tau * t43 * t77 + (T(21) / T(64)) * t61 * t74 * t43 * t79 - (T(21) / T(64)) * t62 * t80 * t43 * t76 - (T(3) / T(32)) * t59 * t0 * t43 * t81 - (T(7) / T(32)) * t63 * t66 * t43 * t68 - (T(1) / T(384)) * (T(8) * (T(2) * b * t72 * t43 + c * t54 * t43 + T(6) * (T(2) * b * t71 * t43 + T(4) * (T(2) * b * t43 * t70 - c * t52 * t43 - (T(2) * b * J2 + log_ratio) * t43) * t43 - t53 * c * t43) * t43) * t43 + t64 * c * t43 - T(2) * b * t73 * t43) * t82 * t43;
    const T t83 = t55 * t2;
    const T t84 = t56 * t36;
    const T t85 = T(128) * b * t83 + T(3) * t38 * t57 * a + T(128) * a_minus_b * t84;
    const T t86 = T(128) * t83 + b * t85 * t38 - T(128) * t84;
    const T t87 = T(6) * b * t86 * t43 + T(10) * t38 * t57 - T(3) * c * t85 * t38;
    const T t88 = T(3) * t86 * c * t43 - T(10) * t58 * t43 - T(2) * b * t87 * t43;
    const T t89 = T(2) * b * t88 * t43 + T(10) * t59 * t43 + t87 * c * t43;
    const T t90 = t88 * c * t43 + T(10) * t60 * t43 - T(2) * b * t89 * t43;
    const T t91 = c * t89 * t43 + T(10) * t61 * t43 + T(2) * b * t90 * t43;
    const T t92 = t90 * c * t43 + T(10) * t62 * t43 - T(2) * b * t91 * t43;
    const T t93 = c * t91 * t43 + T(10) * t63 * t43 + T(2) * b * t92 * t43;
    const T t94 = T(10) * t64 * t43 + t92 * c * t43 - T(2) * b * t93 * t43;
    G_ap = (T(1) / T(1280)) * t85 * t38 * t78 + (T(3) / T(320)) * t87 * t0 * t43 * t81 + (T(1) / T(3840)) * t94 * t82 * t43 + (T(9) / T(1280)) * t86 * delta_tau * t43 * t77 + (T(21) / T(640)) * t90 * t80 * t43 * t76 + (T(7) / T(320)) * t91 * t66 * t43 * t68 - (T(3) / T(1280)) * t93 * t75 * t43 * tau_lo - (T(21) / T(640)) * t89 * t74 * t43 * t79 - (T(3) / T(320)) * t92 * t67 * t43 * t1 - (T(7) / T(320)) * t88 * t65 * t43 * t69;
    G_ab = (T(1) / T(3840)) * (T(10) * t73 * t43 + T(2) * b * t94 * t43 + t93 * c * t43) * t82 * t43 + (T(21) / T(640)) * t90 * t74 * t43 * t79 + (T(3) / T(1280)) * t94 * t75 * t43 * tau_lo + (T(1) / T(1280)) * t86 * t43 * t78 + (T(21) / T(640)) * t91 * t80 * t43 * t76 + (T(3) / T(1280)) * t87 * delta_tau * t43 * t77 - (T(3) / T(320)) * t88 * t0 * t43 * t81 - (T(3) / T(320)) * t93 * t67 * t43 * t1 - (T(7) / T(320)) * t92 * t66 * t43 * t68 - (T(7) / T(320)) * t89 * t65 * t43 * t69;
  }
  const T t95 = sigma2 * sigma2;
  const T t96 = t95 * t95;
  const T t97 = t96 * sigma2;
  const T g_factor = -T(10) * t97 * length;
  f = F * t97 * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

}  // namespace skelconv::generated
