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
/// Operations: 43 +, 63 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 144 +, 243 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + sigma2 * delta_tau * delta_tau;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * delta_tau + tau_lo * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(2, a, D, -b, c, a_minus_b, q1);
    F = (T(1) / T(2)) * t3 * (log_ratio + T(2) * b * t4) * delta_tau + tau_lo * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    const T t6 = T(1) / a;
    F = tau_lo * J2 + (T(1) / T(2)) * t6 * (log_ratio + T(2) * b * J2) * delta_tau;
  }
  f = F * sigma2 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 52 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 168 +, 295 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = ap_ap + tau_lo * tau_lo * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_hi * tau_lo * sigma2 + ap_bp;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * delta_tau + tau_lo * M_flat[0];
    G_ab = M_flat[2] * delta_tau + M_flat[1] * tau_lo;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = delta_tau * M_beyond[1] + M_beyond[0] * tau_lo;
    G_ab = tau_lo * M_beyond[1] + M_beyond[2] * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = t5 * b + a * J2 + a_minus_b * t6;
    const T t8 = T(1) / D;
    const T t9 = t5 + t7 * t8 * b - t6;
    const T t10 = T(1) / a;
    G_ap = (T(1) / T(2)) * t7 * t8 * tau_lo + (T(1) / T(2)) * t9 * delta_tau * t10;
    G_ab = (T(1) / T(2)) * (T(2) * t9 * t10 * b + T(2) * J2 - t7 * c * t8) * delta_tau * t10 + (T(1) / T(2)) * t9 * t10 * tau_lo;
  }
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 54 +, 99 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 229 +, 403 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t0 = T(1) / c;
  const T log_ratio = log(t0 * q1);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * delta_tau + tau_lo * M_flat[0];
    G_ap = M_flat[4] * delta_tau + tau_lo * M_flat[3];
    G_ab = M_flat[4] * tau_lo + delta_tau * M_flat[5];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = a_minus_b * t5;
    const T t7 = t0 * b;
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t6 + t7 - T(2) * t8 * D;
    F = -(T(1) / T(2)) * delta_tau * t4 * (T(2) * t4 * t9 * b - log_ratio) - t4 * tau_lo * t9;
    const T t10 = T(2) * t8 * b + t0 - t5;
    G_ap = (T(1) / T(2)) * t10 * delta_tau * t4 + t8 * tau_lo;
    G_ab = (t10 * t4 * b - c * t8 - t4 * t9) * delta_tau * t4 + (T(1) / T(2)) * t10 * t4 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / a;
    F = J2 * tau_lo + (T(1) / T(2)) * delta_tau * t13 * (log_ratio + T(2) * J2 * b);
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = a_minus_b * t15;
    const T t17 = t0 * b;
    const T t18 = t16 + J2 * a + t17;
    const T t19 = t14 * t18 * b + t0 - t15;
    G_ap = (T(1) / T(2)) * t14 * tau_lo * t18 + (T(1) / T(2)) * delta_tau * t13 * t19;
    G_ab = (T(1) / T(2)) * t13 * tau_lo * t19 - (T(1) / T(2)) * delta_tau * t13 * (c * t14 * t18 - T(2) * J2 - T(2) * t13 * t19 * b);
  }
  const T g_factor = -T(2) * length * sigma2;
  f = length * F * sigma2;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 46 +, 76 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 163 +, 309 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = t3 * t4 * (t5 + b * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = a_minus_b * r0;
    X = -(b - a_minus_b) * t6 / (t7 - b * r1);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  const T t10 = D - T(2) * a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    F = T(2) * M_flat[1] * delta_tau * tau_lo + M_flat[0] * t1 + t0 * M_flat[2];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t13 = J_downward<T>(3, a, D, -b, c, a_minus_b, q1);
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = t14 + b * t13 - t15;
    const T t17 = T(1) / a;
    F = t1 * t13 + T(2) * t16 * delta_tau * t17 * tau_lo - (c * t13 - J1 - T(2) * b * t16 * t17) * t0 * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = b * t19 + a_minus_b * t20;
    const T t22 = T(1) / a;
    const T t23 = t19 + b * t18 * t21 - t20;
    F = t18 * t1 * t21 + T(2) * delta_tau * t22 * tau_lo * t23 - (c * t18 * t21 - J1 - T(2) * b * t22 * t23) * t0 * t22;
  }
  f = sigma2 * in.sigma * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 56 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 187 +, 378 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + sigma2 * t1;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = T(2) * delta_tau * tau_lo * M_flat[1] + M_flat[0] * t1 + M_flat[2] * t0;
    G_ab = M_flat[3] * t0 + t1 * M_flat[1] + T(2) * M_flat[2] * delta_tau * tau_lo;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = T(2) * M_beyond[1] * delta_tau * tau_lo + t1 * M_beyond[0] + M_beyond[2] * t0;
    G_ab = M_beyond[1] * t1 + T(2) * M_beyond[2] * delta_tau * tau_lo + t0 * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / r0;
    const T t8 = t6 * a_minus_b + b * t7;
    const T t9 = t6 * t6;
    const T t10 = t7 * t7;
    const T t11 = T(2) * t5 * a * t8 + t6 * a_minus_b * t9 + b * t7 * t10;
    const T t12 = t6 * t9 - b * t11 * t5 - t7 * t10;
    const T t13 = T(1) / a;
    const T t14 = T(2) * b * t12 * t13 + t11 * c * t5 - T(3) * t5 * t8;
    G_ap = (T(1) / T(3)) * t11 * t5 * t1 - (T(2) / T(3)) * t12 * delta_tau * t13 * tau_lo - (T(1) / T(3)) * t0 * t13 * t14;
    G_ab = -(T(1) / T(3)) * t12 * t13 * t1 - (T(1) / T(3)) * (T(3) * t13 * (t6 - b * t5 * t8 - t7) + T(2) * b * t13 * t14 - c * t12 * t13) * t0 * t13 - (T(2) / T(3)) * delta_tau * t13 * tau_lo * t14;
  }
  const T g_factor = -T(3) * sigma2 * in.sigma * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 61 +, 135 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 270 +, 516 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = sqrt(a);
    const T t4 = r1 * b;
    const T t5 = T(1) / D;
    X = t3 * (t4 + a_minus_b * r0) * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r1 * b;
    X = -t6 * (a_minus_b - b) / (t7 - a_minus_b * r0);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t10 = D - T(2) * a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * t0 + T(2) * tau_lo * M_flat[1] * delta_tau + t1 * M_flat[0];
    G_ap = M_flat[6] * t0 + t1 * M_flat[4] + T(2) * tau_lo * M_flat[5] * delta_tau;
    G_ab = M_flat[7] * t0 + T(2) * tau_lo * M_flat[6] * delta_tau + t1 * M_flat[5];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t13 = T(1) / a;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = a_minus_b * t14 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = b * t18 * t17;
    const T t20 = -b;
    const T t21 = J_downward<T>(5, a, D, t20, c, a_minus_b, q1);
    const T t22 = t16 + t19 - T(3) * D * t21;
    const T t23 = T(2) * t17 - t13 * b * t22 - T(2) * t14;
    F = (T(1) / T(2)) * t13 * (t13 * t22 * c + T(2) * t13 * b * t23 + T(2) * J1) * t0 + t13 * tau_lo * t23 * delta_tau - (T(1) / T(2)) * t13 * t1 * t22;
    const T t24 = t14 * t15;
    const T t25 = t24 - t18 * t17 - T(3) * b * t21;
    const T t26 = T(6) * c * t21 + T(3) * t13 * t22 + T(4) * t13 * b * t25;
    G_ap = t1 * t21 - (T(2) / T(3)) * t13 * tau_lo * t25 * delta_tau - (T(1) / T(6)) * t13 * t26 * t0;
    G_ab = (T(1) / T(6)) * t13 * (T(3) * t13 * t23 + T(2) * t13 * c * t25 - T(2) * t13 * b * t26) * t0 - (T(1) / T(3)) * t13 * t1 * t25 - (T(1) / T(3)) * t13 * tau_lo * t26 * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = T(1) / a;
    const T t28 = T(1) / r0;
    const T t29 = T(1) / r1;
    const T t30 = b * t28 + a_minus_b * t29;
    const T t31 = T(1) / D;
    const T t32 = t30 * b * t31 + t28 - t29;
    F = t27 * (T(2) * t27 * b * t32 + J1 - t30 * c * t31) * t0 + T(2) * t27 * tau_lo * t32 * delta_tau + t30 * t1 * t31;
    const T t33 = t29 * t29;
    const T t34 = a_minus_b * t29 * t33;
    const T t35 = t28 * t28;
    const T t36 = b * t35 * t28;
    const T t37 = T(2) * a * t30 * t31 + t34 + t36;
    const T t38 = t29 * t33;
    const T t39 = t38 - t35 * t28 - b * t37 * t31;
    const T t40 = t37 * c * t31 + T(2) * t27 * b * t39 - T(3) * t30 * t31;
    G_ap = (T(1) / T(3)) * t1 * t37 * t31 - (T(1) / T(3)) * t27 * t40 * t0 - (T(2) / T(3)) * t27 * tau_lo * t39 * delta_tau;
    G_ab = (T(1) / T(3)) * t27 * (T(3) * t27 * t32 + t27 * c * t39 - T(2) * t27 * t40 * b) * t0 - (T(2) / T(3)) * t27 * tau_lo * t40 * delta_tau - (T(1) / T(3)) * t27 * t1 * t39;
  }
  const T g_factor = -T(3) * sigma2 * in.sigma * length;
  f = F * sigma2 * in.sigma * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 53 +, 95 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 186 +, 315 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * delta_tau;
    F = T(3) * tau_lo * t0 * M_flat[2] + M_flat[0] * t6 + M_flat[3] * t7 + T(3) * t1 * delta_tau * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t1 * tau_lo;
    const T t10 = T(1) / a;
    const T t11 = t0 * delta_tau;
    const T t12 = T(1) / q1;
    const T t13 = t12 - t2 - T(2) * t8 * b;
    const T t14 = t2 * b;
    const T t15 = a_minus_b * t12;
    const T t16 = t14 + t15 - T(2) * t8 * D;
    const T t17 = c * t8 + t10 * b * t13 + t16 * t10;
    F = t8 * t9 + (T(1) / T(2)) * t10 * t11 * (c * t10 * t13 + t10 * (log_ratio - T(2) * t16 * t10 * b) - T(4) * t17 * t10 * b) - T(3) * t17 * t10 * tau_lo * t0 - (T(3) / T(2)) * t10 * t1 * delta_tau * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = atan2(t18, c_minus_b) * t19;
    const T t20 = T(1) / D;
    const T t21 = t2 * b;
    const T t22 = T(1) / q1;
    const T t23 = a_minus_b * t22;
    const T t24 = t21 + t23 + a * J2;
    const T t25 = t20 * b * t24 + t2 - t22;
    const T t26 = T(1) / a;
    const T t27 = T(2) * t25 * t26 * b + T(2) * J2 - c * t20 * t24;
    const T t28 = t1 * tau_lo;
    const T t29 = t0 * delta_tau;
    F = (T(3) / T(2)) * t27 * t26 * tau_lo * t0 + (T(3) / T(2)) * t25 * t26 * t1 * delta_tau + (T(1) / T(2)) * t20 * t28 * t24 + (T(1) / T(2)) * t26 * t29 * (T(2) * t27 * t26 * b + (log_ratio + T(2) * J2 * b) * t26 - c * t25 * t26);
  }
  f = length * F * sigma2 * sigma2;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 66 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 212 +, 372 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * tau_hi * sigma2;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * tau_lo;
    const T t6 = t0 * delta_tau;
    G_ap = t5 * M_flat[0] + M_flat[3] * t6 + T(3) * t1 * delta_tau * M_flat[1] + T(3) * tau_lo * t0 * M_flat[2];
    G_ab = T(3) * M_flat[3] * tau_lo * t0 + t5 * M_flat[1] + t6 * M_flat[4] + T(3) * t1 * delta_tau * M_flat[2];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, a, b, D, c, q1, M_beyond.data());
    const T t7 = t1 * tau_lo;
    const T t8 = t0 * delta_tau;
    G_ap = T(3) * M_beyond[1] * t1 * delta_tau + T(3) * tau_lo * t0 * M_beyond[2] + t7 * M_beyond[0] + t8 * M_beyond[3];
    G_ab = T(3) * tau_lo * t0 * M_beyond[3] + M_beyond[1] * t7 + T(3) * t1 * delta_tau * M_beyond[2] + M_beyond[4] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / a;
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = b * t15 + a * J2 + t13 * a_minus_b;
    const T t18 = T(2) * t14 * a_minus_b + T(2) * b * t16 + T(3) * t12 * a * t17;
    const T t19 = t12 * t18 * b + T(2) * t16 - T(2) * t14;
    const T t20 = t1 * tau_lo;
    const T t21 = t0 * delta_tau;
    const T t22 = t12 * t18 * c - T(2) * t11 * t19 * b - T(4) * t12 * t17;
    const T t23 = t12 * t17 * b + t15 - t13;
    const T t24 = T(2) * t11 * t22 * b + t11 * t19 * c - T(4) * t23 * t11;
    G_ap = (T(3) / T(8)) * t11 * t1 * delta_tau * t19 + (T(1) / T(8)) * t12 * t18 * t20 - (T(1) / T(8)) * t11 * t21 * t24 - (T(3) / T(8)) * t11 * tau_lo * t0 * t22;
    G_ab = (T(1) / T(8)) * t11 * t21 * (t11 * t22 * c - T(2) * t11 * b * t24 - T(4) * (t12 * t17 * c - T(2) * J2 - T(2) * t23 * t11 * b) * t11) + (T(1) / T(8)) * t11 * t20 * t19 - (T(3) / T(8)) * t11 * t1 * delta_tau * t22 - (T(3) / T(8)) * t11 * tau_lo * t0 * t24;
  }
  const T g_factor = -T(4) * sigma2 * sigma2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 168 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 315 +, 528 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * delta_tau;
    const T t7 = t1 * tau_lo;
    F = M_flat[3] * t6 + M_flat[0] * t7 + T(3) * delta_tau * t1 * M_flat[1] + T(3) * t0 * tau_lo * M_flat[2];
    G_ap = T(3) * t0 * tau_lo * M_flat[7] + t6 * M_flat[8] + T(3) * M_flat[6] * delta_tau * t1 + t7 * M_flat[5];
    G_ab = M_flat[6] * t7 + T(3) * delta_tau * t1 * M_flat[7] + T(3) * t0 * tau_lo * M_flat[8] + M_flat[9] * t6;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t8 = T(1) / a;
    const T t9 = T(1) / q1;
    const T t10 = t2 * t2;
    const T t11 = t9 * t9;
    const T t12 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t13 = b * t10 + a_minus_b * t11 - T(4) * t12 * D;
    const T t14 = T(3) * t9 + T(2) * t13 * t8 * b - T(3) * t2;
    const T t15 = T(3) * a_minus_b * t9 + T(2) * t13 * t8 * D + T(3) * b * t2;
    const T t16 = t13 * t8 * c - t8 * t15 - t8 * t14 * b;
    const T t17 = t0 * delta_tau;
    const T t18 = t1 * tau_lo;
    F = (T(1) / T(6)) * (t8 * t14 * c + T(4) * t8 * b * t16 - t8 * (T(2) * t8 * b * t15 - T(3) * log_ratio)) * t8 * t17 + t8 * t0 * tau_lo * t16 - (T(1) / T(2)) * t8 * delta_tau * t14 * t1 - (T(1) / T(3)) * t13 * t8 * t18;
    const T t19 = t10 + T(4) * b * t12 - t11;
    const T t20 = T(2) * t13 * t8 + T(6) * t12 * c - T(3) * t8 * b * t19;
    const T t21 = T(2) * t8 * t14 + T(4) * t8 * b * t20 + T(3) * t8 * t19 * c;
    G_ap = (T(3) / T(4)) * t8 * delta_tau * t1 * t19 + t18 * t12 - (T(1) / T(2)) * t8 * t0 * tau_lo * t20 - (T(1) / T(12)) * t8 * t17 * t21;
    G_ab = (T(1) / T(6)) * (T(2) * t8 * t16 + t8 * t20 * c - t8 * b * t21) * t8 * t17 + (T(1) / T(4)) * t8 * t18 * t19 - (T(1) / T(4)) * t8 * t0 * tau_lo * t21 - (T(1) / T(2)) * t8 * delta_tau * t1 * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, c_minus_b) * t23;
    const T t24 = T(1) / q1;
    const T t25 = a * J2 + a_minus_b * t24 + b * t2;
    const T t26 = t1 * tau_lo;
    const T t27 = T(1) / D;
    const T t28 = T(1) / a;
    const T t29 = t24 - t25 * b * t27 - t2;
    const T t30 = t25 * t27 * c + T(2) * t28 * t29 * b - T(2) * J2;
    const T t31 = t0 * delta_tau;
    F = (T(1) / T(2)) * t25 * t26 * t27 + (T(1) / T(2)) * (t28 * t29 * c + (T(2) * J2 * b + log_ratio) * t28 - T(2) * t28 * t30 * b) * t28 * t31 - (T(3) / T(2)) * t28 * delta_tau * t29 * t1 - (T(3) / T(2)) * t28 * t0 * tau_lo * t30;
    const T t32 = t2 * t2;
    const T t33 = t24 * t24;
    const T t34 = T(3) * a * t25 * t27 + T(2) * b * t32 + T(2) * a_minus_b * t33;
    const T t35 = b * t34 * t27 + T(2) * t32 - T(2) * t33;
    const T t36 = T(4) * t25 * t27 + T(2) * t35 * t28 * b - t34 * t27 * c;
    const T t37 = t35 * t28 * c + T(4) * t28 * t29 - T(2) * t28 * t36 * b;
    G_ap = (T(3) / T(8)) * t28 * t0 * tau_lo * t36 + (T(3) / T(8)) * t35 * t28 * delta_tau * t1 + (T(1) / T(8)) * t26 * t34 * t27 - (T(1) / T(8)) * t28 * t31 * t37;
    G_ab = (T(3) / T(8)) * t28 * delta_tau * t1 * t36 + (T(1) / T(8)) * t35 * t28 * t26 - (T(1) / T(8)) * t28 * t31 * (T(4) * t28 * t30 + t28 * t36 * c + T(2) * t28 * t37 * b) - (T(3) / T(8)) * t28 * t0 * t37 * tau_lo;
  }
  const T t38 = sigma2 * sigma2;
  const T g_factor = -T(4) * t38 * length;
  f = F * t38 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 58 +, 125 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 205 +, 402 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
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
    const T t3 = r0 * a_minus_b;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + b * r1) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r0 * a_minus_b;
    X = -t6 * (b - a_minus_b) / (t7 - b * r1);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  const T t10 = D - T(2) * a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * t1;
    const T t15 = t0 * t0;
    const T t16 = t1 * tau_lo;
    F = T(4) * t13 * tau_lo * M_flat[3] + t14 * M_flat[0] + t15 * M_flat[4] + T(6) * t0 * t1 * M_flat[2] + T(4) * M_flat[1] * delta_tau * t16;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t17 = J_downward<T>(5, a, D, -b, c, a_minus_b, q1);
    const T t18 = t1 * t1;
    const T t19 = T(1) / a;
    const T t20 = t1 * tau_lo;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t21 * t22;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = T(3) * t17 * b + t23 - t25 * t24;
    const T t27 = t21 * b * t22;
    const T t28 = t25 * t24 * a_minus_b;
    const T t29 = t27 + t28 - T(3) * D * t17;
    const T t30 = T(3) * t29 * t19 + T(6) * t17 * c - T(4) * t19 * b * t26;
    const T t31 = t0 * delta_tau;
    const T t32 = t29 * t19 * b + T(2) * t24 - T(2) * t21;
    const T t33 = T(3) * t19 * t32 + T(2) * t19 * t30 * b + T(2) * t19 * t26 * c;
    const T t34 = t0 * t0;
    F = t17 * t18 + (T(4) / T(3)) * delta_tau * t19 * t20 * t26 - t0 * t19 * t1 * t30 - (T(2) / T(3)) * t31 * t19 * tau_lo * t33 - (T(1) / T(6)) * t34 * t19 * (T(2) * t19 * b * t33 - T(3) * t19 * (T(2) * J1 + t29 * t19 * c - T(2) * t19 * b * t32) - t19 * t30 * c);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = T(1) / a;
    const T t36 = T(1) / r0;
    const T t37 = t36 * t36;
    const T t38 = t36 * t37;
    const T t39 = T(1) / D;
    const T t40 = t36 * b * t37;
    const T t41 = T(1) / r1;
    const T t42 = t41 * t41;
    const T t43 = t42 * t41 * a_minus_b;
    const T t44 = t36 * b + t41 * a_minus_b;
    const T t45 = t40 + t43 + T(2) * t39 * a * t44;
    const T t46 = t38 + t39 * t45 * b - t42 * t41;
    const T t47 = T(2) * t46 * t35 * b + T(3) * t39 * t44 - t39 * t45 * c;
    const T t48 = t1 * t1;
    const T t49 = t1 * tau_lo;
    const T t50 = t36 + t39 * t44 * b - t41;
    const T t51 = t46 * t35 * c - T(3) * t50 * t35 - T(2) * t35 * b * t47;
    const T t52 = t0 * delta_tau;
    const T t53 = t0 * t0;
    F = T(2) * t0 * t35 * t1 * t47 + (T(1) / T(3)) * t39 * t48 * t45 + (T(4) / T(3)) * delta_tau * t46 * t35 * t49 - (T(4) / T(3)) * t51 * t52 * t35 * tau_lo - (T(1) / T(3)) * (T(2) * t51 * t35 * b + t35 * t47 * c - T(3) * t35 * (T(2) * t50 * t35 * b + J1 - t39 * t44 * c)) * t53 * t35;
  }
  f = F * sigma2 * sigma2 * in.sigma * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 72 +, 179 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 231 +, 477 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t0 * t0;
    const T t6 = t0 * delta_tau;
    const T t7 = t1 * t1;
    const T t8 = t1 * tau_lo;
    G_ap = t5 * M_flat[4] + T(4) * M_flat[3] * t6 * tau_lo + M_flat[0] * t7 + T(6) * M_flat[2] * t0 * t1 + T(4) * M_flat[1] * delta_tau * t8;
    G_ab = T(4) * t6 * tau_lo * M_flat[4] + T(6) * M_flat[3] * t0 * t1 + M_flat[1] * t7 + M_flat[5] * t5 + T(4) * M_flat[2] * delta_tau * t8;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 5, a, b, D, c, q1, M_beyond.data());
    const T t9 = t1 * t1;
    const T t10 = t0 * t0;
    const T t11 = t1 * tau_lo;
    const T t12 = t0 * delta_tau;
    G_ap = M_beyond[0] * t9 + M_beyond[4] * t10 + T(4) * delta_tau * M_beyond[1] * t11 + T(6) * M_beyond[2] * t0 * t1 + T(4) * M_beyond[3] * t12 * tau_lo;
    G_ab = T(4) * M_beyond[4] * t12 * tau_lo + T(4) * M_beyond[2] * delta_tau * t11 + M_beyond[1] * t9 + M_beyond[5] * t10 + T(6) * M_beyond[3] * t0 * t1;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / a;
    const T t14 = t1 * tau_lo;
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = b * t15 + t16 * a_minus_b;
    const T t18 = T(1) / D;
    const T t19 = t15 * t15;
    const T t20 = t16 * t16;
    const T t21 = T(2) * a * t17 * t18 + b * t15 * t19 + t20 * t16 * a_minus_b;
    const T t22 = t19 * t19;
    const T t23 = t20 * t20;
    const T t24 = T(4) * a * t21 * t18 + T(3) * b * t15 * t22 + T(3) * t23 * t16 * a_minus_b;
    const T t25 = t24 * b * t18 + T(3) * t15 * t22 - T(3) * t23 * t16;
    const T t26 = t0 * t0;
    const T t27 = t24 * c * t18 - T(5) * t21 * t18 - T(2) * t13 * b * t25;
    const T t28 = b * t21 * t18 + t15 * t19 - t20 * t16;
    const T t29 = T(3) * t17 * t18 + T(2) * t13 * t28 * b - t21 * c * t18;
    const T t30 = t13 * c * t25 + T(2) * t13 * b * t27 - T(5) * t13 * t28;
    const T t31 = t13 * t27 * c + T(5) * t13 * t29 - T(2) * t13 * t30 * b;
    const T t32 = t1 * t1;
    const T t33 = t0 * delta_tau;
    G_ap = (T(4) / T(15)) * t13 * delta_tau * t14 * t25 + (T(1) / T(15)) * t13 * t26 * t31 + (T(1) / T(15)) * t24 * t18 * t32 - (T(4) / T(15)) * t13 * t30 * t33 * tau_lo - (T(2) / T(5)) * t13 * t27 * t0 * t1;
    G_ab = (T(1) / T(15)) * t13 * t32 * t25 + (T(1) / T(15)) * t13 * (t13 * t30 * c + T(2) * t13 * b * t31 - T(5) * t13 * (t13 * t28 * c - T(3) * t13 * (t15 + b * t17 * t18 - t16) - T(2) * t13 * b * t29)) * t26 + (T(4) / T(15)) * t13 * t33 * tau_lo * t31 - (T(4) / T(15)) * t13 * t27 * delta_tau * t14 - (T(2) / T(5)) * t13 * t30 * t0 * t1;
  }
  const T g_factor = -T(5) * sigma2 * sigma2 * in.sigma * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 81 +, 218 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 356 +, 663 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = r1 * b;
    const T t4 = T(1) / D;
    const T t5 = sqrt(a);
    X = (t3 + r0 * a_minus_b) * t4 * t5;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = r1 * b;
    X = -(a_minus_b - b) * t6 / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  T G_ap;
  T G_ab;
  const T t10 = D - T(2) * a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 12> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * t1;
    const T t15 = t0 * t0;
    const T t16 = t1 * tau_lo;
    F = T(4) * M_flat[3] * tau_lo * t13 + t14 * M_flat[0] + T(6) * M_flat[2] * t1 * t0 + t15 * M_flat[4] + T(4) * t16 * delta_tau * M_flat[1];
    G_ap = T(4) * t16 * delta_tau * M_flat[7] + M_flat[6] * t14 + T(6) * M_flat[8] * t1 * t0 + t15 * M_flat[10] + T(4) * M_flat[9] * tau_lo * t13;
    G_ab = T(6) * M_flat[9] * t1 * t0 + t15 * M_flat[11] + T(4) * M_flat[8] * t16 * delta_tau + t14 * M_flat[7] + T(4) * tau_lo * t13 * M_flat[10];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t17 = T(1) / a;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t21 * t21;
    const T t24 = -b;
    const T t25 = J_downward<T>(7, a, D, t24, c, a_minus_b, q1);
    const T t26 = t22 * t18 * b + t20 * a_minus_b * t23 - T(5) * D * t25;
    const T t27 = T(4) * t19 * t18 - T(4) * t20 * t21 - T(3) * t17 * t26 * b;
    const T t28 = T(4) * t20 * a_minus_b * t21 + T(4) * t19 * t18 * b + T(3) * D * t17 * t26;
    const T t29 = T(4) * t27 * t17 * b + T(6) * c * t17 * t26 - T(3) * t28 * t17;
    const T t30 = t1 * tau_lo;
    const T t31 = t0 * t0;
    const T t32 = t28 * t17 * b + T(8) * t20 - T(8) * t18;
    const T t33 = T(3) * t32 * t17 + T(2) * c * t27 * t17 - T(2) * t17 * b * t29;
    const T t34 = t1 * t1;
    const T t35 = t0 * delta_tau;
    F = (T(1) / T(4)) * t17 * t1 * t0 * t29 + (T(1) / T(3)) * t27 * t17 * t30 * delta_tau + (T(1) / T(24)) * t17 * t31 * (T(3) * t17 * (T(8) * J1 + c * t28 * t17 - T(2) * t32 * t17 * b) - T(2) * t17 * t33 * b - c * t17 * t29) - (T(1) / T(4)) * t17 * t34 * t26 - (T(1) / T(6)) * t17 * tau_lo * t35 * t33;
    const T t36 = T(5) * b * t25 + t22 * t18 - t20 * t23;
    const T t37 = T(8) * t36 * t17 * b - T(5) * t17 * t26 - T(20) * c * t25;
    const T t38 = T(12) * c * t36 * t17 - T(6) * t37 * t17 * b - T(5) * t27 * t17;
    const T t39 = T(4) * t17 * b * t38 + T(6) * c * t37 * t17 - T(5) * t17 * t29;
    G_ap = (T(4) / T(5)) * t36 * t17 * t30 * delta_tau + t34 * t25 + (T(3) / T(10)) * t37 * t17 * t1 * t0 - (T(1) / T(120)) * t39 * t17 * t31 - (T(1) / T(15)) * t17 * tau_lo * t35 * t38;
    G_ab = (T(1) / T(5)) * t36 * t17 * t34 + (T(1) / T(5)) * t37 * t17 * t30 * delta_tau - (T(1) / T(10)) * t17 * t1 * t0 * t38 - (T(1) / T(30)) * t39 * t17 * tau_lo * t35 - (T(1) / T(120)) * (T(2) * t39 * t17 * b + T(5) * t17 * t33 - T(2) * c * t17 * t38) * t17 * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t40 = T(1) / a;
    const T t41 = t1 * tau_lo;
    const T t42 = T(1) / r0;
    const T t43 = t42 * t42;
    const T t44 = T(1) / r1;
    const T t45 = t44 * t44;
    const T t46 = t42 * b + t44 * a_minus_b;
    const T t47 = T(1) / D;
    const T t48 = t44 * a_minus_b * t45 + t43 * t42 * b + T(2) * t46 * t47 * a;
    const T t49 = t43 * t42 + t48 * t47 * b - t44 * t45;
    const T t50 = t1 * t1;
    const T t51 = c * t48 * t47 - T(2) * t40 * b * t49 - T(3) * t46 * t47;
    const T t52 = t46 * t47 * b + t42 - t44;
    const T t53 = T(2) * t51 * t40 * b + c * t40 * t49 - T(3) * t52 * t40;
    const T t54 = t0 * t0;
    const T t55 = t0 * delta_tau;
    F = (T(4) / T(3)) * t40 * t41 * delta_tau * t49 + (T(1) / T(3)) * t48 * t47 * t50 - (T(1) / T(3)) * (T(2) * t40 * t53 * b - T(3) * (J1 + T(2) * t52 * t40 * b - c * t46 * t47) * t40 - c * t51 * t40) * t40 * t54 - (T(4) / T(3)) * t40 * tau_lo * t55 * t53 - T(2) * t51 * t40 * t1 * t0;
    const T t56 = t43 * t43;
    const T t57 = t45 * t45;
    const T t58 = T(3) * t56 * t42 * b + T(4) * t48 * t47 * a + T(3) * t44 * a_minus_b * t57;
    const T t59 = t47 * t58 * b + T(3) * t56 * t42 - T(3) * t44 * t57;
    const T t60 = T(5) * t48 * t47 + T(2) * t59 * t40 * b - c * t47 * t58;
    const T t61 = T(2) * t40 * t60 * b + T(5) * t40 * t49 - c * t59 * t40;
    const T t62 = T(5) * t51 * t40 + c * t40 * t60 - T(2) * t40 * b * t61;
    G_ap = (T(1) / T(15)) * t47 * t58 * t50 + (T(4) / T(15)) * t40 * tau_lo * t55 * t61 + (T(2) / T(5)) * t40 * t1 * t0 * t60 + (T(4) / T(15)) * t59 * t40 * t41 * delta_tau - (T(1) / T(15)) * t62 * t40 * t54;
    G_ab = (T(1) / T(15)) * t59 * t40 * t50 + (T(4) / T(15)) * t40 * t41 * delta_tau * t60 + (T(2) / T(5)) * t40 * t1 * t0 * t61 - (T(1) / T(15)) * (T(2) * t62 * t40 * b + c * t40 * t61 + T(5) * t40 * t53) * t40 * t54 - (T(4) / T(15)) * t62 * t40 * tau_lo * t55;
  }
  const T t63 = sigma2 * sigma2;
  const T g_factor = -T(5) * length * in.sigma * t63;
  f = length * in.sigma * F * t63;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 67 +, 149 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 228 +, 388 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * t0;
    const T t8 = t0 * delta_tau;
    const T t9 = t1 * t1;
    const T t10 = t9 * tau_lo;
    const T t11 = t7 * delta_tau;
    F = T(10) * t0 * t6 * M_flat[2] + T(5) * t7 * tau_lo * M_flat[4] + T(10) * t8 * t1 * M_flat[3] + t10 * M_flat[0] + t11 * M_flat[5] + T(5) * delta_tau * t9 * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t12 = t1 * t1;
    const T t13 = t12 * tau_lo;
    const T t14 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t15 = T(1) / a;
    const T t16 = t2 * t2;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = b * t16 + t18 * a_minus_b - T(4) * D * t14;
    const T t20 = T(2) * D * t15 * t19 + T(3) * t17 * a_minus_b + T(3) * b * t2;
    const T t21 = T(2) * t15 * t19 * b + T(3) * t17 - T(3) * t2;
    const T t22 = t15 * t19 * c - t15 * t20 - t15 * t21 * b;
    const T t23 = t18 - t16 - T(4) * b * t14;
    const T t24 = T(2) * t15 * t19 + T(3) * t15 * t23 * b + T(6) * t14 * c;
    const T t25 = T(2) * t15 * t21 + T(4) * t15 * b * t24 - T(3) * t15 * t23 * c;
    const T t26 = t15 * t25 * b - t15 * c * t24 - T(2) * t22 * t15;
    const T t27 = t0 * t0;
    const T t28 = t27 * delta_tau;
    const T t29 = t0 * delta_tau;
    const T t30 = t1 * tau_lo;
    F = t13 * t14 + (T(1) / T(12)) * (T(2) * t15 * (T(4) * t22 * t15 * b + (T(3) * log_ratio - T(2) * t15 * t20 * b) * t15 + t15 * t21 * c) + t15 * t25 * c - T(4) * t26 * t15 * b) * t28 * t15 - (T(5) / T(6)) * t29 * t1 * t15 * t25 - (T(5) / T(6)) * t26 * t27 * tau_lo * t15 - (T(5) / T(3)) * t0 * t30 * t15 * t24 - (T(5) / T(4)) * delta_tau * t12 * t15 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = t32 * atan2(t31, c_minus_b);
    const T t33 = T(1) / a;
    const T t34 = T(1) / D;
    const T t35 = T(1) / q1;
    const T t36 = t35 * a_minus_b + b * t2 + a * J2;
    const T t37 = t34 * b * t36 + t2 - t35;
    const T t38 = T(2) * t37 * t33 * b + T(2) * J2 - t34 * t36 * c;
    const T t39 = t35 * t35;
    const T t40 = t2 * t2;
    const T t41 = T(2) * b * t40 + T(2) * t39 * a_minus_b + T(3) * t34 * a * t36;
    const T t42 = T(2) * t39 - T(2) * t40 - t34 * t41 * b;
    const T t43 = T(2) * t33 * t42 * b + t34 * t41 * c - T(4) * t34 * t36;
    const T t44 = T(2) * t33 * t43 * b - t33 * t42 * c - T(4) * t37 * t33;
    const T t45 = T(2) * t33 * t44 * b - T(4) * t33 * t38 - t33 * t43 * c;
    const T t46 = t0 * t0;
    const T t47 = t46 * delta_tau;
    const T t48 = t1 * t1;
    const T t49 = t48 * tau_lo;
    const T t50 = t0 * delta_tau;
    const T t51 = t1 * tau_lo;
    F = (T(1) / T(8)) * (T(4) * t33 * (T(2) * t33 * b * t38 + t33 * (T(2) * J2 * b + log_ratio) - t37 * t33 * c) + t33 * t44 * c - T(2) * t33 * b * t45) * t47 * t33 + (T(1) / T(8)) * t34 * t41 * t49 - (T(5) / T(8)) * t46 * tau_lo * t33 * t45 - (T(5) / T(4)) * t50 * t1 * t33 * t44 - (T(5) / T(4)) * t0 * t51 * t33 * t43 - (T(5) / T(8)) * delta_tau * t48 * t33 * t42;
  }
  const T t52 = sigma2 * sigma2;
  const T t53 = t52 * sigma2;
  f = F * t53 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 84 +, 212 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 256 +, 451 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
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
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t0 * t0;
    const T t6 = t5 * delta_tau;
    const T t7 = t1 * t1;
    const T t8 = t7 * tau_lo;
    const T t9 = t0 * delta_tau;
    const T t10 = t1 * tau_lo;
    G_ap = T(5) * t5 * tau_lo * M_flat[4] + M_flat[5] * t6 + t8 * M_flat[0] + T(10) * t9 * M_flat[3] * t1 + T(10) * M_flat[2] * t0 * t10 + T(5) * delta_tau * t7 * M_flat[1];
    G_ab = T(10) * t9 * t1 * M_flat[4] + T(5) * M_flat[5] * t5 * tau_lo + M_flat[6] * t6 + T(5) * M_flat[2] * delta_tau * t7 + t8 * M_flat[1] + T(10) * t0 * M_flat[3] * t10;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 7> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 6, a, b, D, c, q1, M_beyond.data());
    const T t11 = t1 * t1;
    const T t12 = t0 * t0;
    const T t13 = t11 * tau_lo;
    const T t14 = t12 * delta_tau;
    const T t15 = t1 * tau_lo;
    const T t16 = t0 * delta_tau;
    G_ap = T(5) * M_beyond[1] * delta_tau * t11 + T(5) * t12 * tau_lo * M_beyond[4] + t13 * M_beyond[0] + M_beyond[5] * t14 + T(10) * M_beyond[2] * t0 * t15 + T(10) * t16 * t1 * M_beyond[3];
    G_ab = T(10) * t0 * t15 * M_beyond[3] + T(5) * M_beyond[5] * t12 * tau_lo + T(10) * t16 * t1 * M_beyond[4] + t14 * M_beyond[6] + T(5) * M_beyond[2] * delta_tau * t11 + M_beyond[1] * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = atan2(t17, c_minus_b) * t18;
    const T t19 = t0 * t0;
    const T t20 = T(1) / a;
    const T t21 = T(1) / D;
    const T t22 = T(1) / c;
    const T t23 = T(1) / q1;
    const T t24 = a * J2 + t22 * b + a_minus_b * t23;
    const T t25 = t23 * t23;
    const T t26 = t22 * t22;
    const T t27 = T(2) * a_minus_b * t25 + T(3) * t21 * a * t24 + T(2) * t26 * b;
    const T t28 = T(2) * t25 - T(2) * t26 - t21 * t27 * b;
    const T t29 = T(4) * t21 * t24 - T(2) * t28 * t20 * b - c * t21 * t27;
    const T t30 = t25 * t23;
    const T t31 = t26 * t22;
    const T t32 = T(5) * t21 * a * t27 + T(8) * t31 * b + T(8) * a_minus_b * t30;
    const T t33 = T(8) * t30 - T(8) * t31 - t21 * t32 * b;
    const T t34 = T(6) * t21 * t27 - T(2) * t20 * t33 * b - c * t21 * t32;
    const T t35 = c * t20 * t33 + T(2) * t34 * t20 * b - T(6) * t28 * t20;
    const T t36 = T(6) * t20 * t29 + T(2) * t20 * t35 * b - c * t34 * t20;
    const T t37 = t1 * t1;
    const T t38 = t37 * tau_lo;
    const T t39 = t1 * tau_lo;
    const T t40 = t0 * delta_tau;
    const T t41 = t21 * t24 * b + t22 - t23;
    const T t42 = T(4) * t20 * t41 + T(2) * t20 * b * t29 + c * t28 * t20;
    const T t43 = T(6) * t20 * t42 + T(2) * t20 * b * t36 - c * t20 * t35;
    const T t44 = t19 * delta_tau;
    G_ap = (T(5) / T(48)) * t19 * t20 * tau_lo * t36 + (T(1) / T(48)) * t21 * t32 * t38 + (T(5) / T(24)) * t34 * t0 * t20 * t39 + (T(5) / T(24)) * t40 * t20 * t1 * t35 + (T(1) / T(48)) * t43 * t44 * t20 - (T(5) / T(48)) * delta_tau * t20 * t37 * t33;
    G_ab = (T(5) / T(24)) * t40 * t20 * t1 * t36 + (T(5) / T(24)) * t0 * t20 * t39 * t35 + (T(5) / T(48)) * t34 * delta_tau * t20 * t37 + (T(5) / T(48)) * t43 * t19 * t20 * tau_lo - (T(1) / T(48)) * t20 * t38 * t33 - (T(1) / T(48)) * (T(6) * (T(4) * t20 * (c * t21 * t24 - T(2) * t20 * b * t41 - T(2) * J2) + c * t20 * t29 - T(2) * t20 * t42 * b) * t20 + c * t20 * t36 - T(2) * t43 * t20 * b) * t44 * t20;
  }
  const T t45 = sigma2 * sigma2;
  const T t46 = t45 * sigma2;
  const T g_factor = -T(6) * length * t46;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 252 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 401 +, 655 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 14> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * t1;
    const T t7 = t0 * delta_tau;
    const T t8 = t6 * tau_lo;
    const T t9 = t0 * t0;
    const T t10 = t9 * delta_tau;
    const T t11 = t1 * tau_lo;
    F = T(5) * delta_tau * t6 * M_flat[1] + T(10) * t7 * t1 * M_flat[3] + t8 * M_flat[0] + t10 * M_flat[5] + T(5) * t9 * tau_lo * M_flat[4] + T(10) * t0 * t11 * M_flat[2];
    G_ap = t8 * M_flat[7] + t10 * M_flat[12] + T(10) * t0 * t11 * M_flat[9] + T(5) * t9 * tau_lo * M_flat[11] + T(5) * delta_tau * t6 * M_flat[8] + T(10) * t7 * t1 * M_flat[10];
    G_ab = T(10) * t0 * t11 * M_flat[10] + T(5) * delta_tau * t6 * M_flat[9] + T(10) * t7 * t1 * M_flat[11] + T(5) * t9 * tau_lo * M_flat[12] + t10 * M_flat[13] + t8 * M_flat[8];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t12 = t1 * tau_lo;
    const T t13 = t2 * t2;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = t13 * t2;
    const T t17 = t15 * t14;
    const T t18 = J_downward<T>(8, a, D, -b, c, a_minus_b, q1);
    const T t19 = b * t16 + a_minus_b * t17 - T(6) * t18 * D;
    const T t20 = T(1) / a;
    const T t21 = T(5) * t13 - T(5) * t15 - T(4) * b * t19 * t20;
    const T t22 = T(5) * b * t13 + T(5) * a_minus_b * t15 + T(4) * t19 * D * t20;
    const T t23 = T(3) * b * t21 * t20 + T(6) * c * t19 * t20 - T(2) * t22 * t20;
    const T t24 = t1 * t1;
    const T t25 = t0 * delta_tau;
    const T t26 = T(2) * b * t22 * t20 + T(15) * t14 - T(15) * t2;
    const T t27 = T(4) * b * t23 * t20 - T(3) * c * t21 * t20 - T(2) * t26 * t20;
    const T t28 = t0 * t0;
    const T t29 = T(2) * t22 * D * t20 + T(15) * a_minus_b * t14 + T(15) * b * t2;
    const T t30 = t26 * b * t20 + t29 * t20 - t22 * c * t20;
    const T t31 = b * t27 * t20 - c * t23 * t20 - T(2) * t30 * t20;
    const T t32 = t28 * delta_tau;
    const T t33 = t24 * tau_lo;
    F = (T(1) / T(3)) * t0 * t12 * t23 * t20 + (T(1) / T(4)) * delta_tau * t24 * t21 * t20 + (T(1) / T(6)) * t25 * t1 * t27 * t20 + (T(1) / T(6)) * t28 * tau_lo * t31 * t20 - (T(1) / T(60)) * (t27 * c * t20 - T(4) * b * t31 * t20 - T(2) * ((T(15) * log_ratio - T(2) * b * t29 * t20) * t20 + t26 * c * t20 - T(4) * b * t30 * t20) * t20) * t32 * t20 - (T(1) / T(5)) * t33 * t19 * t20;
    const T t34 = t16 + T(6) * b * t18 - t17;
    const T t35 = T(5) * b * t34 * t20 - T(3) * t19 * t20 - T(15) * t18 * c;
    const T t36 = T(3) * t21 * t20 + T(8) * t35 * b * t20 - T(10) * t34 * c * t20;
    const T t37 = b * t36 * t20 + t23 * t20 - T(2) * t35 * c * t20;
    const T t38 = t27 * t20 + T(4) * t37 * b * t20 - t36 * c * t20;
    G_ap = (T(1) / T(60)) * t32 * t38 * t20 + (T(5) / T(6)) * delta_tau * t24 * t34 * t20 + (T(1) / T(6)) * t28 * t37 * tau_lo * t20 + t33 * t18 + (T(2) / T(3)) * t0 * t35 * t12 * t20 + (T(1) / T(6)) * t25 * t1 * t36 * t20;
    G_ab = (T(1) / T(6)) * t33 * t34 * t20 + (T(1) / T(6)) * t0 * t12 * t36 * t20 + (T(1) / T(3)) * t25 * t37 * t1 * t20 + (T(1) / T(12)) * t28 * tau_lo * t38 * t20 + (T(1) / T(3)) * delta_tau * t35 * t24 * t20 - (T(1) / T(30)) * t32 * (t37 * c * t20 - t31 * t20 - t38 * b * t20) * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = atan2(t39, c_minus_b) * t40;
    const T t41 = t1 * t1;
    const T t42 = t41 * tau_lo;
    const T t43 = t2 * t2;
    const T t44 = T(1) / q1;
    const T t45 = t44 * t44;
    const T t46 = J2 * a + a_minus_b * t44 + b * t2;
    const T t47 = T(1) / D;
    const T t48 = T(2) * b * t43 + T(2) * a_minus_b * t45 + T(3) * t46 * t47 * a;
    const T t49 = b * t48 * t47 + T(2) * t43 - T(2) * t45;
    const T t50 = T(1) / a;
    const T t51 = t1 * tau_lo;
    const T t52 = T(2) * b * t49 * t50 + T(4) * t46 * t47 - t48 * c * t47;
    const T t53 = t0 * t0;
    const T t54 = t53 * delta_tau;
    const T t55 = t44 - t2 - b * t46 * t47;
    const T t56 = T(2) * b * t55 * t50 + c * t46 * t47 - T(2) * J2;
    const T t57 = t49 * c * t50 + T(4) * t55 * t50 - T(2) * b * t52 * t50;
    const T t58 = c * t52 * t50 + T(4) * t56 * t50 + T(2) * t57 * b * t50;
    const T t59 = t0 * delta_tau;
    F = (T(1) / T(8)) * t42 * t48 * t47 + (T(5) / T(8)) * delta_tau * t41 * t49 * t50 + (T(5) / T(4)) * t0 * t51 * t52 * t50 - (T(1) / T(8)) * t54 * (T(2) * t58 * b * t50 + T(4) * (T(2) * t56 * b * t50 - (log_ratio + T(2) * b * J2) * t50 - t55 * c * t50) * t50 - t57 * c * t50) * t50 - (T(5) / T(8)) * t58 * t53 * tau_lo * t50 - (T(5) / T(4)) * t59 * t57 * t1 * t50;
    const T t60 = t43 * t2;
    const T t61 = t45 * t44;
    const T t62 = T(8) * b * t60 + T(5) * t48 * t47 * a + T(8) * a_minus_b * t61;
    const T t63 = b * t62 * t47 + T(8) * t60 - T(8) * t61;
    const T t64 = T(6) * t48 * t47 + T(2) * b * t63 * t50 - c * t62 * t47;
    const T t65 = T(6) * t49 * t50 + T(2) * t64 * b * t50 - c * t63 * t50;
    const T t66 = T(2) * b * t65 * t50 + T(6) * t52 * t50 - t64 * c * t50;
    const T t67 = T(6) * t57 * t50 + c * t65 * t50 - T(2) * b * t66 * t50;
    G_ap = (T(1) / T(48)) * t42 * t62 * t47 + (T(5) / T(48)) * t53 * tau_lo * t66 * t50 + (T(5) / T(48)) * delta_tau * t41 * t63 * t50 + (T(5) / T(24)) * t59 * t1 * t65 * t50 + (T(5) / T(24)) * t0 * t51 * t64 * t50 - (T(1) / T(48)) * t54 * t67 * t50;
    G_ab = (T(5) / T(24)) * t59 * t1 * t66 * t50 + (T(5) / T(24)) * t0 * t51 * t65 * t50 + (T(1) / T(48)) * t42 * t63 * t50 + (T(5) / T(48)) * delta_tau * t41 * t64 * t50 - (T(5) / T(48)) * t53 * tau_lo * t67 * t50 - (T(1) / T(48)) * t54 * (T(2) * b * t67 * t50 + T(6) * t58 * t50 + t66 * c * t50) * t50;
  }
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(6) * t69 * length;
  f = F * t69 * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 74 +, 188 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 247 +, 495 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
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
    X = -(b - a_minus_b) * t6 / (t7 - b * r1);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  const T t10 = D - T(2) * a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t15 * delta_tau;
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = t1 * t1;
    const T t20 = t19 * tau_lo;
    F = T(20) * M_flat[3] * t13 * t14 + T(6) * t16 * M_flat[5] * tau_lo + M_flat[0] * t17 + T(15) * M_flat[4] * t15 * t1 + t18 * M_flat[6] + T(6) * M_flat[1] * delta_tau * t20 + T(15) * t0 * t19 * M_flat[2];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = J_downward<T>(7, a, D, -b, c, a_minus_b, q1);
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t23 * t21 + T(5) * b * t24 - t25 * t27;
    const T t29 = T(1) / a;
    const T t30 = t1 * t1;
    const T t31 = t30 * tau_lo;
    const T t32 = t0 * delta_tau;
    const T t33 = t32 * t32;
    const T t34 = b * t23 * t21 + a_minus_b * t25 * t27 - T(5) * t24 * D;
    const T t35 = T(4) * a_minus_b * t25 * t26 + T(4) * b * t22 * t21 + T(3) * t34 * D * t29;
    const T t36 = b * t35 * t29 + T(8) * t25 - T(8) * t21;
    const T t37 = T(4) * t25 * t26 + T(3) * b * t34 * t29 - T(4) * t22 * t21;
    const T t38 = T(6) * c * t34 * t29 - T(4) * b * t37 * t29 - T(3) * t35 * t29;
    const T t39 = T(2) * t37 * c * t29 + T(2) * b * t29 * t38 - T(3) * t29 * t36;
    const T t40 = T(5) * t34 * t29 + T(20) * c * t24 - T(8) * b * t28 * t29;
    const T t41 = T(5) * t37 * t29 + T(6) * b * t40 * t29 + T(12) * c * t28 * t29;
    const T t42 = T(6) * c * t40 * t29 + T(5) * t29 * t38 - T(4) * b * t41 * t29;
    const T t43 = T(5) * t29 * t39 + T(2) * b * t42 * t29 + T(2) * t41 * c * t29;
    const T t44 = t0 * t0;
    const T t45 = t44 * delta_tau;
    const T t46 = t1 * tau_lo;
    const T t47 = t46 * t46;
    F = (T(6) / T(5)) * t28 * delta_tau * t29 * t31 + (T(1) / T(120)) * t33 * t29 * (T(5) * (T(3) * (t35 * c * t29 + T(8) * J1 - T(2) * b * t29 * t36) * t29 + T(2) * b * t29 * t39 - c * t29 * t38) * t29 + T(2) * b * t43 * t29 - c * t42 * t29) + (T(1) / T(20)) * t43 * t45 * t29 * tau_lo + t24 * t47 + (T(1) / T(8)) * t42 * t44 * t29 * t1 - (T(3) / T(4)) * t40 * t0 * t29 * t30 - (T(1) / T(3)) * t41 * t32 * t29 * t46;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = T(1) / a;
    const T t49 = T(1) / r0;
    const T t50 = t49 * t49;
    const T t51 = t50 * t50;
    const T t52 = T(1) / r1;
    const T t53 = t52 * t52;
    const T t54 = t53 * t53;
    const T t55 = T(1) / D;
    const T t56 = a_minus_b * t52 + b * t49;
    const T t57 = T(2) * t55 * a * t56 + a_minus_b * t52 * t53 + b * t50 * t49;
    const T t58 = T(3) * b * t51 * t49 + T(3) * a_minus_b * t52 * t54 + T(4) * t57 * t55 * a;
    const T t59 = T(3) * t51 * t49 + b * t58 * t55 - T(3) * t52 * t54;
    const T t60 = c * t58 * t55 - T(2) * b * t59 * t48 - T(5) * t57 * t55;
    const T t61 = t52 * t53 - b * t57 * t55 - t50 * t49;
    const T t62 = c * t59 * t48 + T(2) * b * t60 * t48 + T(5) * t61 * t48;
    const T t63 = T(3) * t55 * t56 - t57 * c * t55 - T(2) * b * t61 * t48;
    const T t64 = t49 + b * t55 * t56 - t52;
    const T t65 = T(2) * b * t63 * t48 + c * t61 * t48 + T(3) * t64 * t48;
    const T t66 = T(2) * b * t62 * t48 - c * t60 * t48 - T(5) * t63 * t48;
    const T t67 = c * t62 * t48 + T(5) * t65 * t48 - T(2) * b * t66 * t48;
    const T t68 = t0 * delta_tau;
    const T t69 = t68 * t68;
    const T t70 = t1 * t1;
    const T t71 = t70 * tau_lo;
    const T t72 = t1 * tau_lo;
    const T t73 = t72 * t72;
    const T t74 = t0 * t0;
    const T t75 = t74 * delta_tau;
    F = (T(1) / T(15)) * (T(2) * b * t48 * t67 + c * t66 * t48 - T(5) * (T(3) * (c * t55 * t56 - T(2) * b * t64 * t48 - J1) * t48 + c * t63 * t48 - T(2) * b * t65 * t48) * t48) * t69 * t48 + (T(2) / T(5)) * t59 * delta_tau * t48 * t71 + (T(1) / T(15)) * t58 * t55 * t73 + (T(2) / T(5)) * t75 * t48 * t67 * tau_lo - t66 * t74 * t48 * t1 - t60 * t0 * t48 * t70 - (T(4) / T(3)) * t62 * t68 * t48 * t72;
  }
  const T t76 = sigma2 * sigma2;
  const T t77 = t76 * sigma2;
  f = t77 * in.sigma * length * F;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 92 +, 261 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 275 +, 576 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 7, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t0 * t0;
    const T t7 = t6 * delta_tau;
    const T t8 = t0 * delta_tau;
    const T t9 = t8 * t8;
    const T t10 = t5 * tau_lo;
    const T t11 = t1 * tau_lo;
    const T t12 = t11 * t11;
    G_ap = T(15) * t0 * t5 * M_flat[2] + T(15) * t6 * M_flat[4] * t1 + T(6) * t7 * tau_lo * M_flat[5] + M_flat[6] * t9 + T(6) * delta_tau * t10 * M_flat[1] + T(20) * M_flat[3] * t8 * t11 + M_flat[0] * t12;
    G_ab = T(15) * M_flat[3] * t0 * t5 + M_flat[7] * t9 + T(6) * M_flat[6] * t7 * tau_lo + T(6) * delta_tau * t10 * M_flat[2] + T(20) * t8 * M_flat[4] * t11 + t12 * M_flat[1] + T(15) * t6 * t1 * M_flat[5];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 7, a, b, D, c, q1, M_beyond.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t1 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t15 * delta_tau;
    const T t19 = t0 * delta_tau;
    const T t20 = t19 * t19;
    G_ap = T(6) * M_beyond[1] * delta_tau * t14 + T(15) * M_beyond[4] * t15 * t1 + t17 * M_beyond[0] + T(15) * M_beyond[2] * t0 * t13 + T(6) * M_beyond[5] * t18 * tau_lo + T(20) * t19 * t16 * M_beyond[3] + t20 * M_beyond[6];
    G_ab = T(6) * t18 * tau_lo * M_beyond[6] + M_beyond[1] * t17 + T(6) * M_beyond[2] * delta_tau * t14 + T(15) * t0 * t13 * M_beyond[3] + M_beyond[7] * t20 + T(15) * M_beyond[5] * t15 * t1 + T(20) * M_beyond[4] * t19 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / D;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t24 * b + a_minus_b * t22;
    const T t27 = a_minus_b * t22 * t23 + t24 * t25 * b + T(2) * t26 * t21 * a;
    const T t28 = T(1) / a;
    const T t29 = t23 * t23;
    const T t30 = t25 * t25;
    const T t31 = T(4) * t21 * t27 * a + T(3) * a_minus_b * t22 * t29 + T(3) * t24 * t30 * b;
    const T t32 = T(3) * t22 * t29 - T(3) * t24 * t30 - t31 * t21 * b;
    const T t33 = T(5) * t21 * t27 - T(2) * t28 * t32 * b - t31 * c * t21;
    const T t34 = t29 * t23;
    const T t35 = t30 * t25;
    const T t36 = T(2) * t31 * t21 * a + T(5) * t24 * t35 * b + T(5) * a_minus_b * t22 * t34;
    const T t37 = T(5) * t22 * t34 - T(5) * t24 * t35 - t36 * t21 * b;
    const T t38 = T(6) * t37 * t28 * b + T(3) * c * t36 * t21 - T(7) * t31 * t21;
    const T t39 = T(7) * t28 * t32 + T(2) * t38 * t28 * b - T(3) * c * t37 * t28;
    const T t40 = T(7) * t33 * t28 + c * t38 * t28 - T(2) * t39 * t28 * b;
    const T t41 = t0 * t0;
    const T t42 = t24 * t25 + t21 * t27 * b - t22 * t23;
    const T t43 = T(2) * t33 * t28 * b + T(5) * t42 * t28 + c * t28 * t32;
    const T t44 = T(2) * t40 * t28 * b + T(7) * t28 * t43 + t39 * c * t28;
    const T t45 = t41 * delta_tau;
    const T t46 = t1 * tau_lo;
    const T t47 = t46 * t46;
    const T t48 = t1 * t1;
    const T t49 = t0 * delta_tau;
    const T t50 = T(3) * t26 * t21 + T(2) * t42 * t28 * b - c * t21 * t27;
    const T t51 = T(2) * t28 * t43 * b + T(5) * t50 * t28 - c * t33 * t28;
    const T t52 = c * t40 * t28 - T(7) * t28 * t51 - T(2) * t44 * t28 * b;
    const T t53 = t49 * t49;
    const T t54 = t48 * tau_lo;
    G_ap = (T(1) / T(7)) * t40 * t41 * t28 * t1 + (T(2) / T(35)) * t44 * t45 * t28 * tau_lo + (T(1) / T(35)) * t36 * t21 * t47 - (T(1) / T(7)) * t38 * t0 * t28 * t48 - (T(4) / T(21)) * t39 * t49 * t28 * t46 - (T(1) / T(105)) * t52 * t53 * t28 - (T(6) / T(35)) * t37 * delta_tau * t28 * t54;
    G_ab = (T(1) / T(7)) * t44 * t41 * t28 * t1 + (T(4) / T(21)) * t40 * t49 * t28 * t46 - (T(1) / T(35)) * t37 * t28 * t47 - (T(1) / T(7)) * t39 * t0 * t28 * t48 - (T(1) / T(105)) * (T(2) * t52 * t28 * b + c * t44 * t28 + T(7) * (T(5) * (c * t42 * t28 + T(3) * (t22 - t24 - t26 * t21 * b) * t28 - T(2) * t50 * t28 * b) * t28 + c * t28 * t43 - T(2) * t28 * b * t51) * t28) * t53 * t28 - (T(2) / T(35)) * t38 * delta_tau * t28 * t54 - (T(2) / T(35)) * t52 * t45 * t28 * tau_lo;
  }
  const T t55 = sigma2 * sigma2;
  const T t56 = t55 * sigma2;
  const T g_factor = -T(7) * in.sigma * length * t56;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 105 +, 313 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 442 +, 810 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T J1 = asinh(X) * t9;
  T F;
  T G_ap;
  T G_ab;
  const T t10 = D - T(2) * a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 16> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 7, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t1 * t1;
    const T t14 = t13 * tau_lo;
    const T t15 = t1 * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = t0 * t0;
    const T t18 = t17 * delta_tau;
    const T t19 = t0 * delta_tau;
    const T t20 = t19 * t19;
    F = T(15) * M_flat[2] * t0 * t13 + T(6) * delta_tau * t14 * M_flat[1] + t16 * M_flat[0] + T(6) * M_flat[5] * t18 * tau_lo + T(15) * t17 * t1 * M_flat[4] + T(20) * t19 * t15 * M_flat[3] + t20 * M_flat[6];
    G_ap = T(15) * M_flat[12] * t17 * t1 + T(15) * t0 * t13 * M_flat[10] + T(6) * M_flat[9] * delta_tau * t14 + t16 * M_flat[8] + T(6) * t18 * tau_lo * M_flat[13] + t20 * M_flat[14] + T(20) * t19 * t15 * M_flat[11];
    G_ab = M_flat[9] * t16 + M_flat[15] * t20 + T(15) * t17 * t1 * M_flat[13] + T(20) * M_flat[12] * t19 * t15 + T(6) * t18 * tau_lo * M_flat[14] + T(15) * t0 * t13 * M_flat[11] + T(6) * delta_tau * t14 * M_flat[10];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t21 = T(1) / a;
    const T t22 = T(1) / r0;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t24 * t23;
    const T t30 = -b;
    const T t31 = J_downward<T>(9, a, D, t30, c, a_minus_b, q1);
    const T t32 = t25 * a_minus_b * t28 + t22 * b * t29 - T(7) * D * t31;
    const T t33 = T(6) * t22 * t24 - T(6) * t25 * t27 - T(5) * t21 * b * t32;
    const T t34 = T(6) * t25 * a_minus_b * t27 + T(5) * D * t21 * t32 + T(6) * t22 * b * t24;
    const T t35 = T(8) * t21 * b * t33 + T(20) * t21 * c * t32 - T(5) * t21 * t34;
    const T t36 = t1 * t1;
    const T t37 = t36 * tau_lo;
    const T t38 = T(8) * t25 * t26 + t21 * t34 * b - T(8) * t22 * t23;
    const T t39 = T(4) * t21 * t33 * c + T(5) * t21 * t38 - T(2) * t21 * t35 * b;
    const T t40 = T(8) * t22 * b * t23 + D * t21 * t34 + T(8) * t25 * a_minus_b * t26;
    const T t41 = T(4) * t21 * b * t38 + T(3) * t21 * t40 - T(2) * t21 * t34 * c;
    const T t42 = T(4) * t21 * t39 * b + T(5) * t21 * t41 + T(2) * t21 * t35 * c;
    const T t43 = t0 * t0;
    const T t44 = T(16) * t25 + t21 * b * t40 - T(16) * t22;
    const T t45 = T(3) * t44 * t21 + T(2) * t21 * t41 * b - T(2) * t21 * t38 * c;
    const T t46 = T(5) * t45 * t21 + T(2) * t42 * t21 * b - T(2) * t21 * t39 * c;
    const T t47 = t0 * delta_tau;
    const T t48 = t47 * t47;
    const T t49 = t1 * tau_lo;
    const T t50 = t49 * t49;
    const T t51 = t43 * delta_tau;
    F = (T(1) / T(8)) * t0 * t21 * t35 * t36 + (T(1) / T(5)) * delta_tau * t21 * t37 * t33 - (T(1) / T(16)) * t42 * t43 * t21 * t1 - (T(1) / T(240)) * (T(2) * t21 * b * t46 - t42 * t21 * c - T(5) * (T(3) * t21 * (t21 * t40 * c + T(16) * J1 - T(2) * t44 * t21 * b) + t21 * t41 * c - T(2) * t45 * t21 * b) * t21) * t48 * t21 - (T(1) / T(6)) * t21 * t50 * t32 - (T(1) / T(40)) * t51 * t21 * tau_lo * t46 - (T(1) / T(6)) * t47 * t21 * t49 * t39;
    const T t52 = t22 * t29 + T(7) * b * t31 - t25 * t28;
    const T t53 = T(7) * t21 * t32 + T(42) * t31 * c - T(12) * t21 * b * t52;
    const T t54 = T(7) * t21 * t33 - T(10) * t53 * t21 * b - T(30) * t21 * t52 * c;
    const T t55 = T(20) * t53 * t21 * c + T(8) * t21 * b * t54 + T(7) * t21 * t35;
    const T t56 = T(2) * t55 * t21 * b - T(7) * t21 * t39 - T(4) * t21 * t54 * c;
    const T t57 = T(7) * t42 * t21 + T(2) * t55 * t21 * c - T(4) * t21 * b * t56;
    G_ap = (T(1) / T(140)) * t51 * t21 * tau_lo * t56 + t50 * t31 + (T(2) / T(21)) * t47 * t21 * t49 * t54 + (T(6) / T(7)) * delta_tau * t21 * t37 * t52 + (T(1) / T(56)) * t55 * t43 * t21 * t1 - (T(5) / T(14)) * t53 * t0 * t21 * t36 - (T(1) / T(1680)) * t48 * t21 * t57;
    G_ab = (T(1) / T(42)) * t55 * t47 * t21 * t49 + (T(1) / T(56)) * t43 * t21 * t1 * t56 + (T(1) / T(7)) * t21 * t50 * t52 + (T(1) / T(14)) * t0 * t21 * t36 * t54 - (T(1) / T(1680)) * (T(2) * t21 * b * t57 + T(2) * t21 * t56 * c + T(7) * t21 * t46) * t48 * t21 - (T(1) / T(280)) * t51 * t21 * tau_lo * t57 - (T(1) / T(7)) * t53 * delta_tau * t21 * t37;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t58 = T(1) / a;
    const T t59 = t1 * t1;
    const T t60 = t59 * tau_lo;
    const T t61 = T(1) / r0;
    const T t62 = t61 * t61;
    const T t63 = t62 * t62;
    const T t64 = T(1) / D;
    const T t65 = T(1) / r1;
    const T t66 = t65 * t65;
    const T t67 = t66 * t66;
    const T t68 = t65 * a_minus_b + t61 * b;
    const T t69 = T(2) * t64 * a * t68 + t61 * b * t62 + t65 * a_minus_b * t66;
    const T t70 = T(3) * t65 * a_minus_b * t67 + T(4) * t64 * a * t69 + T(3) * t61 * b * t63;
    const T t71 = T(3) * t61 * t63 + t64 * t70 * b - T(3) * t65 * t67;
    const T t72 = t1 * tau_lo;
    const T t73 = t72 * t72;
    const T t74 = t65 * t66 - t61 * t62 - t64 * b * t69;
    const T t75 = t64 * t69 * c + T(2) * t74 * t58 * b - T(3) * t64 * t68;
    const T t76 = t64 * t70 * c - T(5) * t64 * t69 - T(2) * t58 * t71 * b;
    const T t77 = t58 * t71 * c + T(5) * t74 * t58 + T(2) * t58 * b * t76;
    const T t78 = T(5) * t58 * t75 + T(2) * t77 * t58 * b - t58 * t76 * c;
    const T t79 = t0 * t0;
    const T t80 = t79 * delta_tau;
    const T t81 = t65 - t61 - t64 * b * t68;
    const T t82 = T(3) * t58 * t81 + T(2) * t58 * b * t75 - t74 * t58 * c;
    const T t83 = T(5) * t58 * t82 + T(2) * t78 * t58 * b - t77 * t58 * c;
    const T t84 = t0 * delta_tau;
    const T t85 = t84 * t84;
    F = (T(2) / T(5)) * delta_tau * t58 * t60 * t71 + (T(1) / T(15)) * t64 * t73 * t70 - t78 * t79 * t58 * t1 - t0 * t58 * t59 * t76 - (T(2) / T(5)) * t80 * t58 * tau_lo * t83 - (T(1) / T(15)) * (T(5) * t58 * (T(3) * t58 * (t64 * t68 * c + T(2) * t58 * t81 * b - J1) + T(2) * t58 * b * t82 - t58 * c * t75) + T(2) * t58 * t83 * b - t78 * t58 * c) * t85 * t58 - (T(4) / T(3)) * t77 * t84 * t58 * t72;
    const T t86 = t63 * t62;
    const T t87 = t67 * t66;
    const T t88 = T(5) * t65 * a_minus_b * t87 + T(5) * t61 * b * t86 + T(2) * t64 * a * t70;
    const T t89 = T(5) * t61 * t86 + t64 * t88 * b - T(5) * t65 * t87;
    const T t90 = T(3) * t64 * t88 * c - T(6) * t89 * t58 * b - T(7) * t64 * t70;
    const T t91 = T(2) * t58 * b * t90 + T(3) * t89 * t58 * c - T(7) * t58 * t71;
    const T t92 = T(7) * t58 * t76 + T(2) * t58 * b * t91 - t58 * t90 * c;
    const T t93 = T(2) * t58 * t92 * b + T(7) * t77 * t58 - t58 * t91 * c;
    const T t94 = T(7) * t78 * t58 + T(2) * t58 * b * t93 - t58 * t92 * c;
    G_ap = (T(6) / T(35)) * t89 * delta_tau * t58 * t60 + (T(1) / T(35)) * t64 * t73 * t88 - (T(2) / T(35)) * t80 * t58 * tau_lo * t93 - (T(1) / T(105)) * t85 * t58 * t94 - (T(1) / T(7)) * t79 * t58 * t1 * t92 - (T(4) / T(21)) * t84 * t58 * t72 * t91 - (T(1) / T(7)) * t0 * t58 * t59 * t90;
    G_ab = (T(1) / T(105)) * t85 * (t58 * t93 * c - T(2) * t58 * t94 * b - T(7) * t58 * t83) * t58 + (T(1) / T(35)) * t89 * t58 * t73 - (T(2) / T(35)) * delta_tau * t58 * t60 * t90 - (T(1) / T(7)) * t0 * t58 * t59 * t91 - (T(1) / T(7)) * t79 * t58 * t1 * t93 - (T(4) / T(21)) * t84 * t58 * t72 * t92 - (T(2) / T(35)) * t80 * t58 * t94 * tau_lo;
  }
  const T t95 = sigma2 * sigma2;
  const T t96 = t95 * sigma2;
  const T g_factor = -T(7) * t96 * length * in.sigma;
  f = F * t96 * length * in.sigma;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 85 +, 216 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 270 +, 460 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 7, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t1 * t1;
    const T t9 = t8 * tau_lo;
    const T t10 = t0 * t0;
    const T t11 = t10 * delta_tau;
    const T t12 = t1 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t7 * delta_tau;
    const T t15 = t13 * tau_lo;
    F = T(7) * M_flat[6] * t7 * tau_lo + T(21) * t0 * t9 * M_flat[2] + T(21) * t11 * t1 * M_flat[5] + T(7) * M_flat[1] * delta_tau * t13 + T(35) * M_flat[4] * t10 * t12 + M_flat[7] * t14 + M_flat[0] * t15 + T(35) * M_flat[3] * t6 * t8;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t16 = T(1) / a;
    const T t17 = t2 * t2;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t17 * t2;
    const T t21 = t19 * t18;
    const T t22 = J_downward<T>(8, a, D, -b, c, a_minus_b, q1);
    const T t23 = b * t20 + t21 * a_minus_b - T(6) * t22 * D;
    const T t24 = T(5) * t17 - T(5) * t19 - T(4) * t16 * b * t23;
    const T t25 = T(6) * t22 * b + t20 - t21;
    const T t26 = T(3) * t16 * t23 + T(15) * t22 * c - T(5) * t25 * t16 * b;
    const T t27 = T(3) * t16 * t24 - T(10) * t25 * t16 * c - T(8) * t16 * t26 * b;
    const T t28 = T(5) * b * t17 + T(5) * t19 * a_minus_b + T(4) * D * t16 * t23;
    const T t29 = T(6) * t16 * t23 * c + T(3) * t16 * b * t24 - T(2) * t16 * t28;
    const T t30 = t27 * t16 * b + T(2) * t16 * t26 * c + t16 * t29;
    const T t31 = T(15) * t18 + T(2) * t16 * t28 * b - T(15) * t2;
    const T t32 = T(3) * t16 * t24 * c + T(2) * t31 * t16 - T(4) * t16 * t29 * b;
    const T t33 = T(4) * t30 * t16 * b - t16 * t32 - t27 * t16 * c;
    const T t34 = t0 * t0;
    const T t35 = t34 * delta_tau;
    const T t36 = t1 * tau_lo;
    const T t37 = t0 * delta_tau;
    const T t38 = t1 * t1;
    const T t39 = t36 * t36;
    const T t40 = T(2) * D * t16 * t28 + T(15) * t18 * a_minus_b + T(15) * b * t2;
    const T t41 = t16 * t28 * c - t16 * t40 - t31 * t16 * b;
    const T t42 = t16 * t29 * c + t16 * t32 * b - T(2) * t16 * t41;
    const T t43 = t16 * t33 * b - t30 * t16 * c - t16 * t42;
    const T t44 = t37 * t37;
    const T t45 = t44 * delta_tau;
    const T t46 = t39 * tau_lo;
    const T t47 = t38 * tau_lo;
    F = (T(7) / T(20)) * t16 * t33 * t35 * t1 + (T(7) / T(6)) * t30 * t16 * t34 * t36 + (T(7) / T(12)) * t27 * t16 * t37 * t38 + (T(7) / T(6)) * t25 * t16 * delta_tau * t39 + (T(7) / T(30)) * t43 * t16 * t44 * tau_lo + (T(1) / T(60)) * t16 * t45 * (t16 * (T(2) * t16 * (t31 * t16 * c + T(4) * t16 * t41 * b + t16 * (T(15) * log_ratio - T(2) * t16 * b * t40)) + t16 * t32 * c - T(4) * t16 * t42 * b) + T(4) * t43 * t16 * b - t16 * t33 * c) + t22 * t46 - (T(7) / T(5)) * t16 * t0 * t26 * t47;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = sqrt(D);
    const T t49 = T(1) / t48;
    const T J2 = atan2(t48, c_minus_b) * t49;
    const T t50 = T(1) / a;
    const T t51 = t1 * tau_lo;
    const T t52 = t51 * t51;
    const T t53 = T(1) / D;
    const T t54 = t2 * t2;
    const T t55 = t54 * t2;
    const T t56 = T(1) / q1;
    const T t57 = t56 * t56;
    const T t58 = t56 * a_minus_b + a * J2 + b * t2;
    const T t59 = T(2) * b * t54 + T(2) * t57 * a_minus_b + T(3) * t53 * a * t58;
    const T t60 = t57 * t56;
    const T t61 = T(8) * b * t55 + T(5) * t53 * a * t59 + T(8) * t60 * a_minus_b;
    const T t62 = t53 * t61 * b + T(8) * t55 - T(8) * t60;
    const T t63 = t52 * tau_lo;
    const T t64 = t56 - t53 * b * t58 - t2;
    const T t65 = T(2) * J2 - T(2) * t64 * t50 * b - t53 * t58 * c;
    const T t66 = T(2) * t54 + t53 * t59 * b - T(2) * t57;
    const T t67 = t53 * t59 * c - T(2) * t66 * t50 * b - T(4) * t53 * t58;
    const T t68 = t66 * t50 * c + T(4) * t64 * t50 + T(2) * t67 * t50 * b;
    const T t69 = T(4) * t50 * t65 + t67 * t50 * c - T(2) * t50 * t68 * b;
    const T t70 = t53 * t61 * c - T(6) * t53 * t59 - T(2) * t50 * b * t62;
    const T t71 = t50 * c * t62 + T(2) * t50 * b * t70 - T(6) * t66 * t50;
    const T t72 = t50 * t70 * c - T(2) * t50 * t71 * b - T(6) * t67 * t50;
    const T t73 = T(6) * t50 * t68 - T(2) * t50 * t72 * b - t50 * t71 * c;
    const T t74 = t50 * t72 * c + T(2) * t50 * t73 * b - T(6) * t50 * t69;
    const T t75 = t0 * delta_tau;
    const T t76 = t75 * t75;
    const T t77 = t76 * delta_tau;
    const T t78 = t0 * t0;
    const T t79 = t78 * delta_tau;
    const T t80 = t1 * t1;
    const T t81 = t80 * tau_lo;
    F = (T(7) / T(48)) * t50 * delta_tau * t52 * t62 + (T(1) / T(48)) * t53 * t63 * t61 + (T(1) / T(48)) * (T(6) * (T(2) * t50 * t69 * b + t50 * t68 * c + T(4) * t50 * (t50 * (T(2) * J2 * b + log_ratio) + t64 * t50 * c + T(2) * t50 * b * t65)) * t50 + t50 * t73 * c - T(2) * t50 * b * t74) * t50 * t77 + (T(35) / T(48)) * t50 * t78 * t51 * t72 - (T(7) / T(48)) * t50 * t76 * tau_lo * t74 - (T(7) / T(16)) * t50 * t73 * t79 * t1 - (T(35) / T(48)) * t50 * t71 * t75 * t80 - (T(7) / T(16)) * t50 * t0 * t81 * t70;
  }
  const T t82 = sigma2 * sigma2;
  const T t83 = t82 * t82;
  f = length * F * t83;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 106 +, 294 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 300 +, 529 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 9> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 8, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * tau_lo;
    const T t6 = t5 * t5;
    const T t7 = t0 * t0;
    const T t8 = t1 * t1;
    const T t9 = t8 * tau_lo;
    const T t10 = t0 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * tau_lo;
    const T t14 = t7 * delta_tau;
    G_ap = T(7) * delta_tau * t6 * M_flat[1] + T(35) * t7 * t5 * M_flat[4] + T(21) * M_flat[2] * t0 * t9 + t12 * M_flat[7] + T(35) * t10 * t8 * M_flat[3] + t13 * M_flat[0] + T(21) * M_flat[5] * t14 * t1 + T(7) * t11 * M_flat[6] * tau_lo;
    G_ab = T(21) * t0 * t9 * M_flat[3] + t13 * M_flat[1] + T(35) * t10 * t8 * M_flat[4] + T(7) * t11 * tau_lo * M_flat[7] + T(21) * t14 * M_flat[6] * t1 + T(7) * M_flat[2] * delta_tau * t6 + t12 * M_flat[8] + T(35) * M_flat[5] * t7 * t5;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 9> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 8, a, b, D, c, q1, M_beyond.data());
    const T t15 = t1 * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = t16 * tau_lo;
    const T t18 = t1 * t1;
    const T t19 = t18 * tau_lo;
    const T t20 = t0 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t0 * t0;
    const T t23 = t22 * delta_tau;
    const T t24 = t21 * delta_tau;
    G_ap = M_beyond[0] * t17 + T(21) * t0 * t19 * M_beyond[2] + T(7) * M_beyond[6] * t21 * tau_lo + T(7) * delta_tau * t16 * M_beyond[1] + T(35) * M_beyond[3] * t20 * t18 + T(35) * t22 * t15 * M_beyond[4] + T(21) * t23 * t1 * M_beyond[5] + t24 * M_beyond[7];
    G_ab = T(21) * M_beyond[3] * t0 * t19 + T(21) * M_beyond[6] * t23 * t1 + t24 * M_beyond[8] + t17 * M_beyond[1] + T(7) * t21 * tau_lo * M_beyond[7] + T(35) * t20 * t18 * M_beyond[4] + T(7) * delta_tau * t16 * M_beyond[2] + T(35) * t22 * t15 * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(D);
    const T t26 = T(1) / t25;
    const T J2 = t26 * atan2(t25, c_minus_b);
    const T t27 = T(1) / a;
    const T t28 = T(1) / D;
    const T t29 = T(1) / c;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(1) / q1;
    const T t33 = t32 * t32;
    const T t34 = a_minus_b * t32 + a * J2 + t29 * b;
    const T t35 = T(2) * t30 * b + T(2) * a_minus_b * t33 + T(3) * t34 * a * t28;
    const T t36 = t33 * t32;
    const T t37 = T(8) * t31 * b + T(5) * a * t28 * t35 + T(8) * a_minus_b * t36;
    const T t38 = T(8) * t36 - T(8) * t31 - t28 * t37 * b;
    const T t39 = c * t28 * t37 + T(2) * t27 * b * t38 - T(6) * t28 * t35;
    const T t40 = T(2) * t33 - t28 * b * t35 - T(2) * t30;
    const T t41 = T(2) * t27 * b * t39 + T(6) * t27 * t40 - c * t27 * t38;
    const T t42 = T(4) * t34 * t28 - c * t28 * t35 - T(2) * t27 * t40 * b;
    const T t43 = T(6) * t27 * t42 + c * t27 * t39 - T(2) * t27 * b * t41;
    const T t44 = t29 + t34 * t28 * b - t32;
    const T t45 = T(2) * t27 * t42 * b + T(4) * t27 * t44 + c * t27 * t40;
    const T t46 = c * t27 * t41 + T(2) * t27 * b * t43 + T(6) * t27 * t45;
    const T t47 = t30 * t30;
    const T t48 = t33 * t33;
    const T t49 = T(48) * a_minus_b * t48 + T(7) * a * t28 * t37 + T(48) * t47 * b;
    const T t50 = T(48) * t47 + t49 * t28 * b - T(48) * t48;
    const T t51 = T(2) * t50 * t27 * b + T(8) * t28 * t37 - t49 * c * t28;
    const T t52 = c * t50 * t27 + T(8) * t27 * t38 - T(2) * t27 * b * t51;
    const T t53 = c * t27 * t51 + T(2) * t27 * t52 * b + T(8) * t27 * t39;
    const T t54 = T(8) * t27 * t41 + T(2) * t27 * b * t53 - c * t27 * t52;
    const T t55 = T(2) * t27 * t54 * b - T(8) * t27 * t43 - c * t27 * t53;
    const T t56 = T(8) * t27 * t46 + c * t27 * t54 - T(2) * t27 * t55 * b;
    const T t57 = t0 * delta_tau;
    const T t58 = t57 * t57;
    const T t59 = t58 * delta_tau;
    const T t60 = t1 * t1;
    const T t61 = t60 * tau_lo;
    const T t62 = t1 * tau_lo;
    const T t63 = t62 * t62;
    const T t64 = t63 * tau_lo;
    const T t65 = t0 * t0;
    const T t66 = t65 * delta_tau;
    G_ap = (T(1) / T(384)) * t27 * t56 * t59 + (T(7) / T(128)) * t27 * t0 * t61 * t51 + (T(7) / T(384)) * t50 * t27 * delta_tau * t63 + (T(1) / T(384)) * t49 * t28 * t64 - (T(7) / T(128)) * t27 * t66 * t1 * t54 - (T(35) / T(384)) * t27 * t57 * t60 * t52 - (T(7) / T(384)) * t27 * t58 * t55 * tau_lo - (T(35) / T(384)) * t27 * t65 * t62 * t53;
    G_ab = (T(1) / T(384)) * t50 * t27 * t64 + (T(1) / T(384)) * t27 * t59 * (T(2) * t27 * t56 * b + c * t27 * t55 - T(8) * (c * t27 * t43 - T(2) * t27 * t46 * b - T(6) * t27 * (T(4) * t27 * (T(2) * t27 * t44 * b + T(2) * J2 - t34 * c * t28) + T(2) * t27 * t45 * b - c * t27 * t42)) * t27) + (T(7) / T(384)) * t27 * delta_tau * t63 * t51 + (T(7) / T(384)) * t27 * t56 * t58 * tau_lo - (T(35) / T(384)) * t27 * t65 * t62 * t54 - (T(7) / T(128)) * t27 * t0 * t61 * t52 - (T(7) / T(128)) * t27 * t66 * t55 * t1 - (T(35) / T(384)) * t27 * t57 * t60 * t53;
  }
  const T t67 = sigma2 * sigma2;
  const T t68 = t67 * t67;
  const T g_factor = -T(8) * t68 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 120 +, 349 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 487 +, 781 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = delta_tau * ap0 + tau_lo * ab0;
  const T radial1 = tau_lo * ab1 + delta_tau * ap1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 18> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 8, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t6 * t6;
    const T t8 = t1 * t1;
    const T t9 = t8 * tau_lo;
    const T t10 = t7 * tau_lo;
    const T t11 = t0 * t0;
    const T t12 = t0 * delta_tau;
    const T t13 = t12 * t12;
    const T t14 = t13 * delta_tau;
    const T t15 = t11 * delta_tau;
    F = T(7) * delta_tau * t7 * M_flat[1] + T(21) * t0 * t9 * M_flat[2] + t10 * M_flat[0] + T(35) * t11 * t6 * M_flat[4] + t14 * M_flat[7] + T(21) * t15 * t1 * M_flat[5] + T(35) * t12 * t8 * M_flat[3] + T(7) * t13 * tau_lo * M_flat[6];
    G_ap = T(35) * t12 * t8 * M_flat[12] + T(21) * t0 * t9 * M_flat[11] + T(7) * delta_tau * t7 * M_flat[10] + T(35) * t11 * t6 * M_flat[13] + t14 * M_flat[16] + T(7) * t13 * M_flat[15] * tau_lo + t10 * M_flat[9] + T(21) * t15 * t1 * M_flat[14];
    G_ab = t14 * M_flat[17] + T(21) * t15 * M_flat[15] * t1 + T(35) * t12 * t8 * M_flat[13] + T(7) * t13 * tau_lo * M_flat[16] + t10 * M_flat[10] + T(21) * t0 * t9 * M_flat[12] + T(35) * t11 * t6 * M_flat[14] + T(7) * delta_tau * t7 * M_flat[11];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t16 = t1 * tau_lo;
    const T t17 = t16 * t16;
    const T t18 = t2 * t2;
    const T t19 = t18 * t2;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t21 * t21;
    const T t24 = t18 * t18;
    const T t25 = J_downward<T>(10, a, D, -b, c, a_minus_b, q1);
    const T t26 = a_minus_b * t23 + b * t24 - T(8) * t25 * D;
    const T t27 = T(1) / a;
    const T t28 = T(7) * t19 - T(7) * t22 - T(6) * b * t26 * t27;
    const T t29 = t0 * delta_tau;
    const T t30 = t1 * t1;
    const T t31 = T(6) * t26 * D * t27 + T(7) * b * t19 + T(7) * a_minus_b * t22;
    const T t32 = T(35) * t18 - T(4) * b * t31 * t27 - T(35) * t21;
    const T t33 = T(3) * t31 * t27 - T(5) * b * t28 * t27 - T(15) * t26 * c * t27;
    const T t34 = T(3) * t32 * t27 - T(10) * c * t28 * t27 - T(8) * b * t33 * t27;
    const T t35 = t0 * t0;
    const T t36 = T(35) * b * t18 + T(4) * t31 * D * t27 + T(35) * a_minus_b * t21;
    const T t37 = T(3) * t32 * b * t27 + T(6) * t31 * c * t27 - T(2) * t36 * t27;
    const T t38 = T(2) * c * t33 * t27 + b * t34 * t27 + t37 * t27;
    const T t39 = t35 * delta_tau;
    const T t40 = T(105) * t20 + T(2) * b * t36 * t27 - T(105) * t2;
    const T t41 = T(3) * t32 * c * t27 + T(2) * t40 * t27 - T(4) * t37 * b * t27;
    const T t42 = T(4) * b * t38 * t27 - t34 * c * t27 - t41 * t27;
    const T t43 = t30 * tau_lo;
    const T t44 = T(2) * t36 * D * t27 + T(105) * a_minus_b * t20 + T(105) * b * t2;
    const T t45 = c * t36 * t27 - t44 * t27 - b * t40 * t27;
    const T t46 = T(2) * t45 * t27 - t41 * b * t27 - t37 * c * t27;
    const T t47 = c * t38 * t27 - t46 * t27 - t42 * b * t27;
    const T t48 = t29 * t29;
    const T t49 = t17 * tau_lo;
    const T t50 = t48 * delta_tau;
    F = (T(1) / T(6)) * delta_tau * t17 * t28 * t27 + (T(1) / T(12)) * t29 * t30 * t34 * t27 + (T(1) / T(6)) * t35 * t16 * t38 * t27 + (T(1) / T(20)) * t39 * t42 * t1 * t27 - (T(1) / T(5)) * t0 * t43 * t33 * t27 - (T(1) / T(30)) * t47 * t48 * tau_lo * t27 - (T(1) / T(7)) * t49 * t26 * t27 - (T(1) / T(420)) * t50 * (T(4) * t47 * b * t27 + t42 * c * t27 - (T(2) * (c * t40 * t27 + T(4) * t45 * b * t27 + (T(105) * log_ratio - T(2) * t44 * b * t27) * t27) * t27 + T(4) * t46 * b * t27 + t41 * c * t27) * t27) * t27;
    const T t51 = t24 + T(8) * b * t25 - t23;
    const T t52 = T(7) * b * t51 * t27 - T(28) * t25 * c - T(4) * t26 * t27;
    const T t53 = T(12) * b * t52 * t27 + T(4) * t28 * t27 - T(21) * t51 * c * t27;
    const T t54 = T(5) * t53 * b * t27 - T(4) * t33 * t27 - T(15) * c * t52 * t27;
    const T t55 = T(5) * t53 * c * t27 - T(4) * b * t54 * t27 - T(2) * t34 * t27;
    const T t56 = t55 * b * t27 + c * t54 * t27 - T(2) * t38 * t27;
    const T t57 = T(2) * t42 * t27 + t55 * c * t27 - T(4) * b * t56 * t27;
    G_ap = (T(7) / T(8)) * delta_tau * t17 * t51 * t27 + (T(1) / T(840)) * t50 * t57 * t27 + (T(1) / T(12)) * t35 * t16 * t54 * t27 + t49 * t25 + (T(3) / T(4)) * t0 * t43 * t52 * t27 + (T(5) / T(24)) * t29 * t30 * t53 * t27 - (T(1) / T(60)) * t48 * tau_lo * t56 * t27 - (T(1) / T(40)) * t39 * t1 * t55 * t27;
    G_ab = (T(1) / T(120)) * t48 * t57 * tau_lo * t27 + (T(1) / T(12)) * t29 * t30 * t54 * t27 + (T(1) / T(8)) * t49 * t51 * t27 + (T(1) / T(4)) * delta_tau * t17 * t52 * t27 + (T(1) / T(8)) * t0 * t43 * t53 * t27 - (T(1) / T(420)) * t50 * (T(2) * t47 * t27 - t57 * b * t27 - t56 * c * t27) * t27 - (T(1) / T(20)) * t39 * t1 * t56 * t27 - (T(1) / T(24)) * t35 * t16 * t55 * t27;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t58 = sqrt(D);
    const T t59 = T(1) / t58;
    const T J2 = atan2(t58, c_minus_b) * t59;
    const T t60 = t0 * delta_tau;
    const T t61 = t60 * t60;
    const T t62 = t2 * t2;
    const T t63 = T(1) / q1;
    const T t64 = t63 * t63;
    const T t65 = J2 * a + a_minus_b * t63 + b * t2;
    const T t66 = T(1) / D;
    const T t67 = T(2) * b * t62 + T(2) * a_minus_b * t64 + T(3) * t65 * t66 * a;
    const T t68 = T(2) * t62 + b * t67 * t66 - T(2) * t64;
    const T t69 = T(1) / a;
    const T t70 = t67 * c * t66 - T(4) * t65 * t66 - T(2) * b * t68 * t69;
    const T t71 = t63 - b * t65 * t66 - t2;
    const T t72 = c * t68 * t69 + T(4) * t71 * t69 + T(2) * t70 * b * t69;
    const T t73 = T(2) * t71 * b * t69 + c * t65 * t66 - T(2) * J2;
    const T t74 = t70 * c * t69 - T(2) * b * t72 * t69 - T(4) * t73 * t69;
    const T t75 = t62 * t2;
    const T t76 = t64 * t63;
    const T t77 = T(8) * b * t75 + T(8) * a_minus_b * t76 + T(5) * t67 * t66 * a;
    const T t78 = T(8) * t75 + b * t77 * t66 - T(8) * t76;
    const T t79 = T(2) * b * t78 * t69 + T(6) * t67 * t66 - t77 * c * t66;
    const T t80 = T(2) * b * t69 * t79 + T(6) * t68 * t69 - c * t78 * t69;
    const T t81 = c * t69 * t79 + T(6) * t70 * t69 - T(2) * b * t80 * t69;
    const T t82 = c * t80 * t69 + T(2) * b * t81 * t69 + T(6) * t72 * t69;
    const T t83 = T(6) * t74 * t69 + c * t81 * t69 - T(2) * b * t82 * t69;
    const T t84 = t61 * delta_tau;
    const T t85 = t1 * t1;
    const T t86 = t85 * tau_lo;
    const T t87 = t1 * tau_lo;
    const T t88 = t87 * t87;
    const T t89 = t88 * tau_lo;
    const T t90 = t0 * t0;
    const T t91 = t90 * delta_tau;
    F = (T(7) / T(48)) * t61 * tau_lo * t83 * t69 + (T(1) / T(48)) * t84 * (c * t82 * t69 + T(6) * (T(2) * b * t74 * t69 + c * t72 * t69 + T(4) * (t71 * c * t69 + (log_ratio + T(2) * b * J2) * t69 - T(2) * b * t73 * t69) * t69) * t69 + T(2) * b * t83 * t69) * t69 + (T(35) / T(48)) * t60 * t85 * t80 * t69 + (T(7) / T(16)) * t0 * t86 * t69 * t79 + (T(1) / T(48)) * t89 * t77 * t66 + (T(7) / T(48)) * delta_tau * t88 * t78 * t69 - (T(7) / T(16)) * t91 * t1 * t82 * t69 - (T(35) / T(48)) * t90 * t87 * t81 * t69;
    const T t92 = t62 * t62;
    const T t93 = t64 * t64;
    const T t94 = T(48) * a_minus_b * t93 + T(48) * b * t92 + T(7) * t77 * t66 * a;
    const T t95 = T(48) * t92 + b * t94 * t66 - T(48) * t93;
    const T t96 = T(2) * b * t95 * t69 + T(8) * t77 * t66 - t94 * c * t66;
    const T t97 = T(8) * t78 * t69 + T(2) * t96 * b * t69 - t95 * c * t69;
    const T t98 = T(2) * b * t97 * t69 + T(8) * t69 * t79 - t96 * c * t69;
    const T t99 = T(8) * t80 * t69 + T(2) * b * t98 * t69 - t97 * c * t69;
    const T t100 = c * t98 * t69 + T(8) * t81 * t69 - T(2) * b * t99 * t69;
    const T t101 = t99 * c * t69 + T(8) * t82 * t69 + T(2) * b * t100 * t69;
    G_ap = (T(35) / T(384)) * t90 * t87 * t98 * t69 + (T(7) / T(128)) * t0 * t86 * t96 * t69 + (T(1) / T(384)) * t89 * t94 * t66 + (T(35) / T(384)) * t60 * t85 * t97 * t69 + (T(7) / T(384)) * delta_tau * t88 * t95 * t69 + (T(7) / T(128)) * t91 * t1 * t99 * t69 - (T(7) / T(384)) * t61 * tau_lo * t100 * t69 - (T(1) / T(384)) * t84 * t101 * t69;
    G_ab = (T(35) / T(384)) * t60 * t85 * t98 * t69 + (T(1) / T(384)) * t89 * t95 * t69 + (T(1) / T(384)) * t84 * (c * t100 * t69 + T(8) * t83 * t69 - T(2) * b * t101 * t69) * t69 + (T(7) / T(384)) * delta_tau * t88 * t96 * t69 + (T(7) / T(128)) * t0 * t86 * t97 * t69 + (T(35) / T(384)) * t90 * t87 * t99 * t69 - (T(7) / T(128)) * t91 * t1 * t100 * t69 - (T(7) / T(384)) * t61 * tau_lo * t101 * t69;
  }
  const T t102 = sigma2 * sigma2;
  const T t103 = t102 * t102;
  const T g_factor = -T(8) * t103 * length;
  f = F * t103 * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 94 +, 270 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 289 +, 587 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
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
  const T t10 = D - T(2) * a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 9> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 8, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t1 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t14 * tau_lo;
    const T t16 = t0 * t0;
    const T t17 = t1 * t1;
    const T t18 = t16 * t16;
    const T t19 = t17 * t17;
    const T t20 = t0 * delta_tau;
    const T t21 = t20 * t20;
    const T t22 = t21 * delta_tau;
    const T t23 = t17 * tau_lo;
    const T t24 = t16 * delta_tau;
    F = T(8) * delta_tau * t15 * M_flat[1] + T(70) * t16 * t17 * M_flat[4] + T(28) * M_flat[2] * t0 * t14 + M_flat[8] * t18 + t19 * M_flat[0] + T(8) * t22 * tau_lo * M_flat[7] + T(56) * t20 * t23 * M_flat[3] + T(56) * M_flat[5] * t24 * t13 + T(28) * t21 * t1 * M_flat[6];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t25 = T(1) / a;
    const T t26 = t0 * t0;
    const T t27 = t26 * delta_tau;
    const T t28 = t1 * tau_lo;
    const T t29 = J_downward<T>(9, a, D, -b, c, a_minus_b, q1);
    const T t30 = T(1) / r1;
    const T t31 = t30 * t30;
    const T t32 = t31 * t31;
    const T t33 = t32 * t31;
    const T t34 = T(1) / r0;
    const T t35 = t34 * t34;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = t30 * t33 - T(7) * b * t29 - t34 * t37;
    const T t39 = t34 * b * t37 + t30 * a_minus_b * t33 - T(7) * D * t29;
    const T t40 = T(42) * c * t29 + T(12) * t25 * t38 * b + T(7) * t39 * t25;
    const T t41 = T(6) * t30 * t32 + T(5) * t39 * t25 * b - T(6) * t34 * t36;
    const T t42 = T(10) * t25 * t40 * b + T(7) * t25 * t41 - T(30) * t25 * t38 * c;
    const T t43 = T(6) * t34 * b * t36 + T(6) * t30 * a_minus_b * t32 + T(5) * D * t39 * t25;
    const T t44 = T(8) * t34 * t35 - t25 * t43 * b - T(8) * t30 * t31;
    const T t45 = T(5) * t25 * t43 + T(8) * t25 * b * t41 - T(20) * t39 * t25 * c;
    const T t46 = T(4) * t25 * t41 * c + T(5) * t25 * t44 - T(2) * t25 * b * t45;
    const T t47 = T(7) * t25 * t45 + T(8) * t25 * t42 * b - T(20) * t25 * t40 * c;
    const T t48 = T(4) * t25 * t42 * c + T(7) * t25 * t46 - T(2) * t25 * b * t47;
    const T t49 = t1 * t1;
    const T t50 = t49 * t49;
    const T t51 = t0 * delta_tau;
    const T t52 = t51 * t51;
    const T t53 = D * t25 * t43 + T(8) * t30 * a_minus_b * t31 + T(8) * t34 * b * t35;
    const T t54 = T(3) * t25 * t53 - T(4) * t25 * t44 * b - T(2) * t25 * t43 * c;
    const T t55 = T(2) * t25 * c * t45 + T(4) * t25 * t46 * b - T(5) * t25 * t54;
    const T t56 = T(7) * t25 * t55 + T(4) * t25 * b * t48 + T(2) * t25 * c * t47;
    const T t57 = t49 * tau_lo;
    const T t58 = t28 * t28;
    const T t59 = t58 * tau_lo;
    const T t60 = t52 * delta_tau;
    const T t61 = T(16) * t34 - T(16) * t30 - t25 * t53 * b;
    const T t62 = T(2) * t25 * b * t54 + T(2) * t25 * t44 * c - T(3) * t25 * t61;
    const T t63 = T(2) * t25 * t46 * c + T(5) * t25 * t62 - T(2) * t25 * b * t55;
    const T t64 = T(7) * t25 * t63 + T(2) * t25 * t48 * c - T(2) * t25 * t56 * b;
    const T t65 = t26 * t26;
    F = (T(1) / T(15)) * t25 * t27 * t28 * t48 + t50 * t29 + (T(1) / T(60)) * t25 * t52 * t1 * t56 - (T(4) / T(15)) * t25 * t51 * t57 * t42 - (T(1) / T(12)) * t25 * t26 * t49 * t47 - (T(8) / T(7)) * t25 * delta_tau * t38 * t59 - (T(1) / T(210)) * t25 * t60 * tau_lo * t64 - (T(1) / T(1680)) * t25 * t65 * (T(7) * t25 * (T(5) * t25 * (T(2) * t25 * b * t62 - T(3) * t25 * (T(2) * t25 * b * t61 + T(16) * J1 + t25 * t53 * c) - t25 * c * t54) + T(2) * t25 * b * t63 + t25 * t55 * c) + t25 * t56 * c + T(2) * t25 * t64 * b) - (T(2) / T(3)) * t25 * t0 * t40 * t58;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t66 = T(1) / a;
    const T t67 = T(1) / r1;
    const T t68 = t67 * t67;
    const T t69 = t68 * t68;
    const T t70 = T(1) / D;
    const T t71 = T(1) / r0;
    const T t72 = t71 * t71;
    const T t73 = t72 * t72;
    const T t74 = t71 * b + t67 * a_minus_b;
    const T t75 = T(2) * t70 * a * t74 + t67 * a_minus_b * t68 + t71 * b * t72;
    const T t76 = T(3) * t71 * b * t73 + T(4) * t70 * a * t75 + T(3) * t67 * a_minus_b * t69;
    const T t77 = T(3) * t67 * t69 - t70 * b * t76 - T(3) * t71 * t73;
    const T t78 = t70 * b * t75 + t71 * t72 - t67 * t68;
    const T t79 = t70 * c * t76 + T(2) * t66 * b * t77 - T(5) * t70 * t75;
    const T t80 = t66 * c * t77 + T(5) * t66 * t78 - T(2) * t66 * t79 * b;
    const T t81 = t69 * t68;
    const T t82 = t73 * t72;
    const T t83 = T(5) * t71 * b * t82 + T(5) * t67 * a_minus_b * t81 + T(2) * t70 * a * t76;
    const T t84 = T(5) * t67 * t81 - t70 * b * t83 - T(5) * t71 * t82;
    const T t85 = T(7) * t70 * t76 - T(6) * t66 * b * t84 - T(3) * t70 * t83 * c;
    const T t86 = T(7) * t66 * t77 - T(3) * t66 * c * t84 - T(2) * t66 * b * t85;
    const T t87 = T(7) * t66 * t79 + t66 * c * t85 + T(2) * t66 * b * t86;
    const T t88 = T(7) * t66 * t80 + t66 * c * t86 - T(2) * t66 * b * t87;
    const T t89 = t0 * t0;
    const T t90 = t89 * delta_tau;
    const T t91 = t1 * tau_lo;
    const T t92 = t1 * t1;
    const T t93 = t92 * t92;
    const T t94 = t0 * delta_tau;
    const T t95 = t94 * t94;
    const T t96 = t70 * t75 * c - T(2) * t66 * b * t78 - T(3) * t70 * t74;
    const T t97 = T(5) * t66 * t96 - t66 * t79 * c - T(2) * t66 * b * t80;
    const T t98 = t66 * c * t87 + T(2) * t66 * t88 * b - T(7) * t66 * t97;
    const T t99 = t91 * t91;
    const T t100 = t89 * t89;
    const T t101 = t71 + t70 * b * t74 - t67;
    const T t102 = T(3) * t66 * t101 - t66 * c * t78 - T(2) * t66 * b * t96;
    const T t103 = T(2) * t66 * t97 * b + t66 * c * t80 - T(5) * t66 * t102;
    const T t104 = t66 * t88 * c + T(7) * t66 * t103 - T(2) * t66 * b * t98;
    const T t105 = t95 * delta_tau;
    const T t106 = t99 * tau_lo;
    const T t107 = t92 * tau_lo;
    F = (T(8) / T(15)) * t66 * t88 * t90 * t91 + (T(1) / T(35)) * t70 * t93 * t83 + (T(4) / T(15)) * t66 * t95 * t1 * t98 + (T(4) / T(15)) * t66 * t0 * t99 * t85 - (T(1) / T(105)) * t66 * t100 * (t66 * c * t98 + T(2) * t66 * b * t104 - T(7) * t66 * (T(5) * t66 * (t66 * c * t96 + T(2) * t66 * b * t102 + T(3) * t66 * (J1 + T(2) * t66 * b * t101 - t70 * c * t74)) + t66 * t97 * c - T(2) * t66 * b * t103)) - (T(8) / T(105)) * t66 * t105 * tau_lo * t104 - (T(8) / T(35)) * t66 * delta_tau * t106 * t84 - (T(2) / T(3)) * t66 * t89 * t92 * t87 - (T(8) / T(15)) * t66 * t94 * t107 * t86;
  }
  const T t108 = sigma2 * sigma2;
  const T t109 = t108 * t108;
  f = F * t109 * length * in.sigma;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 116 +, 354 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 319 +, 674 ×, 20 /, 23 sqrt, 0 atan, 0 log/asinh.
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - tau_lo * sigma2 * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * tau_lo;
    const T t7 = t0 * delta_tau;
    const T t8 = t1 * tau_lo;
    const T t9 = t0 * t0;
    const T t10 = t9 * delta_tau;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = t12 * tau_lo;
    const T t14 = t5 * t5;
    const T t15 = t7 * t7;
    const T t16 = t15 * delta_tau;
    G_ap = T(56) * t6 * M_flat[3] * t7 + T(56) * t8 * M_flat[5] * t10 + M_flat[8] * t11 + T(8) * t13 * M_flat[1] * delta_tau + t14 * M_flat[0] + T(28) * t12 * M_flat[2] * t0 + T(8) * tau_lo * M_flat[7] * t16 + T(28) * t1 * M_flat[6] * t15 + T(70) * t5 * t9 * M_flat[4];
    G_ab = T(28) * t1 * M_flat[7] * t15 + T(56) * t6 * t7 * M_flat[4] + T(56) * t8 * M_flat[6] * t10 + T(8) * t13 * M_flat[2] * delta_tau + T(8) * tau_lo * M_flat[8] * t16 + T(70) * t5 * M_flat[5] * t9 + t14 * M_flat[1] + T(28) * t12 * M_flat[3] * t0 + M_flat[9] * t11;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 9, a, b, D, c, q1, M_beyond.data());
    const T t17 = t0 * delta_tau;
    const T t18 = t17 * t17;
    const T t19 = t18 * delta_tau;
    const T t20 = t1 * tau_lo;
    const T t21 = t20 * t20;
    const T t22 = t21 * tau_lo;
    const T t23 = t1 * t1;
    const T t24 = t23 * tau_lo;
    const T t25 = t23 * t23;
    const T t26 = t0 * t0;
    const T t27 = t26 * delta_tau;
    const T t28 = t26 * t26;
    G_ap = T(8) * M_beyond[7] * tau_lo * t19 + T(8) * t22 * M_beyond[1] * delta_tau + T(56) * t24 * M_beyond[3] * t17 + T(28) * t1 * M_beyond[6] * t18 + T(28) * t21 * M_beyond[2] * t0 + t25 * M_beyond[0] + T(56) * t20 * M_beyond[5] * t27 + M_beyond[8] * t28 + T(70) * t23 * M_beyond[4] * t26;
    G_ab = T(8) * tau_lo * M_beyond[8] * t19 + T(56) * t24 * M_beyond[4] * t17 + t25 * M_beyond[1] + T(70) * t23 * M_beyond[5] * t26 + T(8) * t22 * M_beyond[2] * delta_tau + M_beyond[9] * t28 + T(28) * t21 * M_beyond[3] * t0 + T(56) * t20 * M_beyond[6] * t27 + T(28) * M_beyond[7] * t1 * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = t1 * t1;
    const T t30 = t29 * t29;
    const T t31 = T(1) / r0;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = T(1) / r1;
    const T t36 = t35 * t35;
    const T t37 = t36 * t36;
    const T t38 = t37 * t36;
    const T t39 = T(1) / D;
    const T t40 = t35 * a_minus_b + b * t31;
    const T t41 = b * t31 * t32 + t36 * t35 * a_minus_b + T(2) * t39 * a * t40;
    const T t42 = T(4) * t41 * t39 * a + T(3) * t37 * t35 * a_minus_b + T(3) * b * t31 * t33;
    const T t43 = t33 * t32;
    const T t44 = T(5) * t38 * t35 * a_minus_b + T(2) * t42 * t39 * a + T(5) * b * t31 * t43;
    const T t45 = t37 * t37;
    const T t46 = T(35) * b * t31 * t34 + T(8) * t44 * t39 * a + T(35) * t45 * t35 * a_minus_b;
    const T t47 = t29 * tau_lo;
    const T t48 = T(1) / a;
    const T t49 = T(5) * t31 * t43 + b * t44 * t39 - T(5) * t38 * t35;
    const T t50 = T(35) * t45 * t35 - T(35) * t31 * t34 - b * t46 * t39;
    const T t51 = T(9) * t44 * t39 - t46 * c * t39 - T(2) * t50 * b * t48;
    const T t52 = T(9) * t49 * t48 + t50 * c * t48 + T(2) * b * t51 * t48;
    const T t53 = t0 * delta_tau;
    const T t54 = T(3) * c * t44 * t39 - T(6) * b * t49 * t48 - T(7) * t42 * t39;
    const T t55 = T(2) * b * t48 * t52 - t51 * c * t48 - T(3) * t54 * t48;
    const T t56 = t0 * t0;
    const T t57 = t1 * tau_lo;
    const T t58 = t57 * t57;
    const T t59 = T(3) * t31 * t33 + b * t42 * t39 - T(3) * t37 * t35;
    const T t60 = T(3) * c * t49 * t48 + T(2) * b * t54 * t48 - T(7) * t48 * t59;
    const T t61 = T(3) * t60 * t48 + c * t48 * t52 - T(2) * b * t55 * t48;
    const T t62 = t56 * delta_tau;
    const T t63 = T(2) * b * t48 * t59 + T(5) * t41 * t39 - c * t42 * t39;
    const T t64 = c * t54 * t48 + T(7) * t63 * t48 - T(2) * b * t60 * t48;
    const T t65 = T(2) * b * t61 * t48 + t55 * c * t48 - T(3) * t64 * t48;
    const T t66 = t53 * t53;
    const T t67 = t36 * t35 - b * t41 * t39 - t31 * t32;
    const T t68 = T(2) * b * t63 * t48 - c * t48 * t59 - T(5) * t48 * t67;
    const T t69 = T(2) * b * t64 * t48 + t60 * c * t48 + T(7) * t68 * t48;
    const T t70 = T(2) * b * t65 * t48 - T(3) * t69 * t48 - t61 * c * t48;
    const T t71 = t66 * delta_tau;
    const T t72 = T(2) * b * t48 * t67 + c * t41 * t39 - T(3) * t39 * t40;
    const T t73 = T(5) * t72 * t48 + t63 * c * t48 - T(2) * b * t68 * t48;
    const T t74 = T(7) * t73 * t48 + t64 * c * t48 - T(2) * t69 * b * t48;
    const T t75 = T(3) * t74 * t48 + T(2) * b * t70 * t48 - t65 * c * t48;
    const T t76 = t56 * t56;
    const T t77 = t58 * tau_lo;
    G_ap = (T(1) / T(315)) * t30 * t46 * t39 + (T(8) / T(45)) * t47 * t48 * t52 * t53 + (T(2) / T(9)) * t29 * t55 * t48 * t56 + (T(4) / T(45)) * t58 * t51 * t48 * t0 - (T(8) / T(45)) * t57 * t61 * t48 * t62 - (T(4) / T(45)) * t1 * t65 * t48 * t66 - (T(8) / T(315)) * tau_lo * t70 * t48 * t71 - (T(1) / T(315)) * t75 * t48 * t76 - (T(8) / T(315)) * t77 * t50 * t48 * delta_tau;
    G_ab = (T(4) / T(45)) * t58 * t48 * t52 * t0 + (T(1) / T(315)) * (c * t70 * t48 - T(3) * (t69 * c * t48 + T(2) * t74 * b * t48 - T(7) * t48 * (T(5) * (T(3) * (t31 + b * t39 * t40 - t35) * t48 + c * t48 * t67 - T(2) * t72 * b * t48) * t48 - c * t68 * t48 - T(2) * b * t73 * t48)) * t48 - T(2) * b * t75 * t48) * t48 * t76 + (T(8) / T(315)) * t77 * t51 * t48 * delta_tau + (T(8) / T(45)) * t47 * t55 * t48 * t53 - (T(1) / T(315)) * t30 * t50 * t48 - (T(8) / T(315)) * tau_lo * t75 * t48 * t71 - (T(8) / T(45)) * t57 * t65 * t48 * t62 - (T(4) / T(45)) * t1 * t70 * t48 * t66 - (T(2) / T(9)) * t29 * t61 * t48 * t56;
  }
  const T t78 = sigma2 * sigma2;
  const T t79 = t78 * t78;
  const T g_factor = -T(9) * t79 * length * in.sigma;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 133 +, 423 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 528 +, 956 ×, 22 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
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
    X = -(a_minus_b - b) * t6 / (t7 - r0 * a_minus_b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = asinh(X) * t9;
  T F;
  T G_ap;
  T G_ab;
  const T t10 = D - T(2) * a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 20> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * t0;
    const T t14 = t13 * delta_tau;
    const T t15 = t1 * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = t16 * tau_lo;
    const T t18 = t0 * delta_tau;
    const T t19 = t18 * t18;
    const T t20 = t1 * t1;
    const T t21 = t20 * tau_lo;
    const T t22 = t20 * t20;
    const T t23 = t19 * delta_tau;
    const T t24 = t13 * t13;
    F = T(56) * M_flat[5] * t14 * t15 + T(28) * M_flat[2] * t0 * t16 + T(8) * delta_tau * t17 * M_flat[1] + T(28) * M_flat[6] * t19 * t1 + T(56) * M_flat[3] * t18 * t21 + T(70) * t13 * t20 * M_flat[4] + M_flat[0] * t22 + T(8) * t23 * tau_lo * M_flat[7] + M_flat[8] * t24;
    G_ap = t22 * M_flat[10] + T(56) * M_flat[15] * t14 * t15 + T(8) * delta_tau * t17 * M_flat[11] + T(8) * t23 * tau_lo * M_flat[17] + M_flat[18] * t24 + T(28) * M_flat[12] * t0 * t16 + T(56) * t18 * t21 * M_flat[13] + T(70) * t13 * t20 * M_flat[14] + T(28) * t19 * M_flat[16] * t1;
    G_ab = T(28) * t0 * t16 * M_flat[13] + T(56) * t14 * M_flat[16] * t15 + M_flat[19] * t24 + T(8) * M_flat[12] * delta_tau * t17 + T(56) * t18 * t21 * M_flat[14] + T(8) * M_flat[18] * t23 * tau_lo + t22 * M_flat[11] + T(28) * t19 * t1 * M_flat[17] + T(70) * M_flat[15] * t13 * t20;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t25 = T(1) / a;
    const T t26 = t0 * t0;
    const T t27 = t1 * t1;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(1) / r1;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = t34 * t33;
    const T t36 = -b;
    const T t37 = J_downward<T>(11, a, D, t36, c, a_minus_b, q1);
    const T t38 = t34 * t34;
    const T t39 = t30 * t30;
    const T t40 = T(9) * t37 * D - t32 * a_minus_b * t38 - t39 * t28 * b;
    const T t41 = T(8) * t31 * t28 * b + T(8) * t32 * a_minus_b * t35 - T(7) * D * t25 * t40;
    const T t42 = T(5) * t25 * t41 * b + T(48) * t32 * t34 - T(48) * t30 * t28;
    const T t43 = T(5) * D * t25 * t41 + T(48) * t32 * a_minus_b * t34 + T(48) * t30 * t28 * b;
    const T t44 = T(20) * c * t25 * t41 - T(8) * t25 * b * t42 - T(5) * t25 * t43;
    const T t45 = T(8) * t32 * t35 - T(8) * t31 * t28 - T(7) * t25 * t40 * b;
    const T t46 = T(7) * t25 * t41 + T(12) * t25 * b * t45 + T(42) * c * t25 * t40;
    const T t47 = T(10) * t25 * b * t46 + T(7) * t25 * t42 - T(30) * c * t25 * t45;
    const T t48 = T(7) * t25 * t44 + T(20) * c * t25 * t46 - T(8) * t47 * t25 * b;
    const T t49 = t0 * delta_tau;
    const T t50 = t49 * t49;
    const T t51 = T(64) * t29 * t28 - T(64) * t32 * t33 - t25 * t43 * b;
    const T t52 = T(2) * t25 * t44 * b + T(5) * t51 * t25 + T(4) * c * t25 * t42;
    const T t53 = T(2) * t25 * b * t48 + T(7) * t25 * t52 + T(4) * c * t47 * t25;
    const T t54 = D * t25 * t43 + T(64) * t29 * t28 * b + T(64) * t32 * a_minus_b * t33;
    const T t55 = T(3) * t25 * t54 - T(2) * c * t25 * t43 - T(4) * t51 * t25 * b;
    const T t56 = T(2) * c * t25 * t44 + T(5) * t55 * t25 - T(4) * t25 * t52 * b;
    const T t57 = T(4) * t25 * t53 * b - T(2) * c * t25 * t48 - T(7) * t56 * t25;
    const T t58 = t26 * delta_tau;
    const T t59 = t1 * tau_lo;
    const T t60 = t27 * t27;
    const T t61 = t59 * t59;
    const T t62 = t27 * tau_lo;
    const T t63 = t25 * t54 * b + T(128) * t32 - T(128) * t28;
    const T t64 = T(2) * c * t51 * t25 + T(3) * t63 * t25 + T(2) * t55 * t25 * b;
    const T t65 = T(2) * c * t25 * t52 + T(5) * t64 * t25 + T(2) * t56 * t25 * b;
    const T t66 = T(2) * c * t25 * t53 + T(7) * t25 * t65 - T(2) * t25 * b * t57;
    const T t67 = t50 * delta_tau;
    const T t68 = t61 * tau_lo;
    const T t69 = t26 * t26;
    F = (T(1) / T(96)) * t25 * t26 * t27 * t48 + (T(1) / T(480)) * t25 * t50 * t1 * t57 + (T(1) / T(120)) * t25 * t58 * t59 * t53 + (T(1) / T(8)) * t25 * t40 * t60 - (T(1) / T(12)) * t25 * t0 * t61 * t46 - (T(1) / T(30)) * t47 * t25 * t49 * t62 - (T(1) / T(1680)) * t66 * t25 * t67 * tau_lo - (T(1) / T(7)) * t25 * delta_tau * t68 * t45 - (T(1) / T(13440)) * t25 * t69 * (T(7) * t25 * (T(2) * t25 * t65 * b + T(5) * t25 * (T(2) * t64 * t25 * b - T(3) * t25 * (T(128) * J1 + c * t25 * t54 - T(2) * t63 * t25 * b) - c * t55 * t25) - c * t56 * t25) + T(2) * t66 * t25 * b + c * t25 * t57);
    const T t70 = t32 * t38 - t39 * t28 - T(9) * t37 * b;
    const T t71 = T(72) * c * t37 + T(16) * t25 * t70 * b - T(9) * t25 * t40;
    const T t72 = T(14) * t71 * t25 * b + T(9) * t25 * t45 - T(56) * c * t25 * t70;
    const T t73 = T(4) * t25 * b * t72 + T(3) * t25 * t46 - T(14) * c * t71 * t25;
    const T t74 = T(10) * t25 * t73 * b + T(3) * t47 * t25 - T(10) * c * t25 * t72;
    const T t75 = T(8) * t25 * b * t74 - T(20) * c * t25 * t73 - T(3) * t25 * t48;
    const T t76 = T(2) * t25 * t75 * b - T(3) * t25 * t53 - T(4) * c * t25 * t74;
    const T t77 = T(4) * t76 * t25 * b - T(2) * c * t25 * t75 - T(3) * t25 * t57;
    G_ap = t37 * t60 - (T(1) / T(720)) * t25 * t50 * t75 * t1 - (T(7) / T(18)) * t71 * t25 * t0 * t61 - (T(8) / T(9)) * t25 * delta_tau * t68 * t70 - (T(1) / T(90)) * t25 * t58 * t59 * t74 - (T(1) / T(2520)) * t76 * t25 * t67 * tau_lo - (T(1) / T(40320)) * t25 * t69 * t77 - (T(5) / T(72)) * t25 * t26 * t27 * t73 - (T(1) / T(9)) * t25 * t49 * t62 * t72;
    G_ab = -(T(1) / T(5040)) * t25 * t67 * tau_lo * t77 - (T(1) / T(18)) * t25 * t0 * t61 * t72 - (T(1) / T(72)) * t25 * t26 * t27 * t74 - (T(1) / T(9)) * t25 * t60 * t70 - (T(1) / T(18)) * t25 * t49 * t62 * t73 - (T(1) / T(40320)) * (T(3) * t66 * t25 + T(2) * t25 * t77 * b - T(2) * c * t76 * t25) * t25 * t69 - (T(1) / T(720)) * t76 * t25 * t50 * t1 - (T(1) / T(9)) * t71 * t25 * delta_tau * t68 - (T(1) / T(360)) * t25 * t58 * t75 * t59;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t78 = T(1) / a;
    const T t79 = T(1) / r1;
    const T t80 = t79 * t79;
    const T t81 = t80 * t80;
    const T t82 = T(1) / r0;
    const T t83 = t82 * t82;
    const T t84 = t83 * t83;
    const T t85 = T(1) / D;
    const T t86 = t82 * b + t79 * a_minus_b;
    const T t87 = T(2) * t86 * t85 * a + t83 * t82 * b + t79 * a_minus_b * t80;
    const T t88 = T(3) * t79 * a_minus_b * t81 + T(3) * t84 * t82 * b + T(4) * t85 * t87 * a;
    const T t89 = t88 * t85 * b + T(3) * t84 * t82 - T(3) * t79 * t81;
    const T t90 = t81 * t80;
    const T t91 = t84 * t83;
    const T t92 = T(5) * t91 * t82 * b + T(2) * t88 * t85 * a + T(5) * t79 * a_minus_b * t90;
    const T t93 = T(5) * t79 * t90 - T(5) * t91 * t82 - t92 * t85 * b;
    const T t94 = T(7) * t88 * t85 - T(3) * c * t92 * t85 - T(6) * t93 * t78 * b;
    const T t95 = T(7) * t78 * t89 + T(3) * c * t93 * t78 + T(2) * t78 * t94 * b;
    const T t96 = t0 * delta_tau;
    const T t97 = t1 * t1;
    const T t98 = t97 * tau_lo;
    const T t99 = t83 * t82 + t85 * t87 * b - t79 * t80;
    const T t100 = T(2) * t78 * b * t99 + T(3) * t86 * t85 - c * t85 * t87;
    const T t101 = t79 - t86 * t85 * b - t82;
    const T t102 = T(2) * t78 * b * t100 - T(3) * t78 * t101 - c * t78 * t99;
    const T t103 = T(5) * t85 * t87 + T(2) * t78 * t89 * b - c * t88 * t85;
    const T t104 = c * t78 * t89 - T(5) * t78 * t99 - T(2) * t103 * t78 * b;
    const T t105 = c * t103 * t78 + T(2) * t78 * t104 * b - T(5) * t78 * t100;
    const T t106 = T(5) * t78 * t102 + c * t78 * t104 - T(2) * t105 * t78 * b;
    const T t107 = c * t78 * t94 - T(7) * t103 * t78 - T(2) * t95 * t78 * b;
    const T t108 = c * t95 * t78 + T(7) * t78 * t104 + T(2) * t78 * t107 * b;
    const T t109 = T(7) * t105 * t78 + T(2) * t78 * t108 * b - c * t78 * t107;
    const T t110 = T(7) * t78 * t106 + c * t78 * t108 - T(2) * t78 * b * t109;
    const T t111 = t0 * t0;
    const T t112 = t111 * t111;
    const T t113 = t96 * t96;
    const T t114 = t113 * delta_tau;
    const T t115 = t1 * tau_lo;
    const T t116 = t115 * t115;
    const T t117 = t97 * t97;
    const T t118 = t116 * tau_lo;
    const T t119 = t111 * delta_tau;
    F = (T(8) / T(15)) * t95 * t78 * t96 * t98 + (T(1) / T(105)) * (T(2) * t78 * b * t110 + T(7) * (T(2) * t78 * b * t106 + c * t105 * t78 + T(5) * t78 * (T(3) * (J1 - c * t86 * t85 - T(2) * t78 * b * t101) * t78 + T(2) * t78 * t102 * b - c * t78 * t100)) * t78 + c * t78 * t109) * t78 * t112 + (T(8) / T(105)) * t78 * t114 * tau_lo * t110 + (T(4) / T(15)) * t78 * t0 * t116 * t94 + (T(1) / T(35)) * t92 * t85 * t117 - (T(8) / T(35)) * t93 * t78 * delta_tau * t118 - (T(2) / T(3)) * t78 * t107 * t111 * t97 - (T(8) / T(15)) * t78 * t108 * t119 * t115 - (T(4) / T(15)) * t78 * t113 * t1 * t109;
    const T t120 = t81 * t81;
    const T t121 = t84 * t84;
    const T t122 = T(8) * t92 * t85 * a + T(35) * t79 * a_minus_b * t120 + T(35) * t121 * t82 * b;
    const T t123 = T(35) * t79 * t120 - T(35) * t121 * t82 - t85 * b * t122;
    const T t124 = c * t85 * t122 + T(2) * t123 * t78 * b - T(9) * t92 * t85;
    const T t125 = T(2) * t124 * t78 * b + T(9) * t93 * t78 - c * t123 * t78;
    const T t126 = T(2) * t125 * t78 * b - T(3) * t78 * t94 - c * t124 * t78;
    const T t127 = t125 * c * t78 + T(3) * t95 * t78 - T(2) * t78 * t126 * b;
    const T t128 = T(2) * t78 * t127 * b + c * t78 * t126 - T(3) * t78 * t107;
    const T t129 = c * t78 * t127 + T(3) * t78 * t108 - T(2) * t78 * t128 * b;
    const T t130 = T(2) * t129 * t78 * b + c * t78 * t128 + T(3) * t78 * t109;
    G_ap = (T(8) / T(45)) * t78 * t119 * t115 * t127 + (T(1) / T(315)) * t85 * t117 * t122 + (T(4) / T(45)) * t78 * t113 * t1 * t128 - (T(8) / T(315)) * t129 * t78 * t114 * tau_lo - (T(8) / T(45)) * t125 * t78 * t96 * t98 - (T(4) / T(45)) * t124 * t78 * t0 * t116 - (T(2) / T(9)) * t78 * t126 * t111 * t97 - (T(1) / T(315)) * t78 * t112 * t130 - (T(8) / T(315)) * t123 * t78 * delta_tau * t118;
    G_ab = (T(8) / T(45)) * t78 * t119 * t115 * t128 + (T(2) / T(9)) * t78 * t111 * t97 * t127 - (T(4) / T(45)) * t125 * t78 * t0 * t116 - (T(1) / T(315)) * t78 * (T(2) * t78 * t130 * b - T(3) * t78 * t110 - c * t129 * t78) * t112 - (T(8) / T(315)) * t78 * t114 * t130 * tau_lo - (T(8) / T(45)) * t78 * t126 * t96 * t98 - (T(1) / T(315)) * t123 * t78 * t117 - (T(4) / T(45)) * t129 * t78 * t113 * t1 - (T(8) / T(315)) * t124 * t78 * delta_tau * t118;
  }
  const T t131 = sigma2 * sigma2;
  const T t132 = t131 * t131;
  const T g_factor = -T(9) * length * in.sigma * t132;
  f = length * in.sigma * F * t132;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 107 +, 298 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 312 +, 533 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial1 * radial1 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * t0;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t0 * delta_tau;
    const T t10 = t1 * tau_lo;
    const T t11 = t10 * t10;
    const T t12 = t1 * t1;
    const T t13 = t12 * t12;
    const T t14 = t9 * t9;
    const T t15 = t14 * delta_tau;
    const T t16 = t6 * delta_tau;
    const T t17 = t11 * tau_lo;
    const T t18 = t13 * tau_lo;
    const T t19 = t12 * tau_lo;
    F = T(9) * M_flat[8] * t7 * tau_lo + M_flat[9] * t8 + T(84) * M_flat[3] * t9 * t11 + T(9) * delta_tau * t13 * M_flat[1] + T(36) * t15 * M_flat[7] * t1 + T(84) * M_flat[6] * t14 * t10 + T(126) * M_flat[5] * t16 * t12 + T(36) * M_flat[2] * t0 * t17 + M_flat[0] * t18 + T(126) * t6 * M_flat[4] * t19;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t20 = T(1) / a;
    const T t21 = t2 * t2;
    const T t22 = t21 * t21;
    const T t23 = T(1) / q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = J_downward<T>(10, a, D, -b, c, a_minus_b, q1);
    const T t27 = t22 * b + a_minus_b * t25 - T(8) * D * t26;
    const T t28 = t21 * t2;
    const T t29 = t24 * t23;
    const T t30 = T(6) * t20 * t27 * D + T(7) * t28 * b + T(7) * a_minus_b * t29;
    const T t31 = T(35) * t24 + T(4) * t30 * t20 * b - T(35) * t21;
    const T t32 = T(35) * t21 * b + T(4) * t30 * t20 * D + T(35) * a_minus_b * t24;
    const T t33 = T(6) * c * t30 * t20 - T(3) * t31 * t20 * b - T(2) * t20 * t32;
    const T t34 = T(6) * t20 * t27 * b + T(7) * t29 - T(7) * t28;
    const T t35 = T(5) * t34 * t20 * b + T(3) * t30 * t20 - T(15) * c * t20 * t27;
    const T t36 = T(8) * t20 * b * t35 + T(3) * t31 * t20 - T(10) * c * t34 * t20;
    const T t37 = t20 * t33 + T(2) * c * t20 * t35 - t20 * t36 * b;
    const T t38 = T(105) * t2 - T(2) * t20 * t32 * b - T(105) * t23;
    const T t39 = T(4) * t20 * t33 * b + T(3) * t31 * c * t20 + T(2) * t38 * t20;
    const T t40 = T(4) * t37 * t20 * b + c * t20 * t36 + t39 * t20;
    const T t41 = t25 - t22 - T(8) * t26 * b;
    const T t42 = T(4) * t20 * t27 + T(7) * t20 * t41 * b + T(28) * c * t26;
    const T t43 = T(4) * t34 * t20 + T(12) * t42 * t20 * b - T(21) * c * t20 * t41;
    const T t44 = T(5) * t43 * t20 * b + T(4) * t20 * t35 - T(15) * t42 * c * t20;
    const T t45 = T(5) * t43 * c * t20 - T(4) * t20 * t44 * b - T(2) * t20 * t36;
    const T t46 = t45 * t20 * b + T(2) * t37 * t20 + c * t20 * t44;
    const T t47 = T(2) * t20 * t40 + T(4) * t20 * t46 * b - c * t45 * t20;
    const T t48 = T(105) * a_minus_b * t23 + T(105) * t2 * b + T(2) * t20 * D * t32;
    const T t49 = t38 * t20 * b + c * t20 * t32 - t20 * t48;
    const T t50 = t39 * t20 * b + T(2) * t49 * t20 - c * t20 * t33;
    const T t51 = t20 * t40 * b + t50 * t20 - c * t37 * t20;
    const T t52 = t47 * t20 * b + T(2) * t51 * t20 - c * t20 * t46;
    const T t53 = t0 * t0;
    const T t54 = t53 * t53;
    const T t55 = t1 * t1;
    const T t56 = t55 * t55;
    const T t57 = t56 * tau_lo;
    const T t58 = t54 * delta_tau;
    const T t59 = t0 * delta_tau;
    const T t60 = t59 * t59;
    const T t61 = t1 * tau_lo;
    const T t62 = t53 * delta_tau;
    const T t63 = t60 * delta_tau;
    const T t64 = t61 * t61;
    const T t65 = t55 * tau_lo;
    const T t66 = t64 * tau_lo;
    F = (T(3) / T(140)) * t52 * t20 * t54 * tau_lo + t57 * t26 + (T(1) / T(840)) * (T(4) * t52 * t20 * b + T(2) * (T(4) * t51 * t20 * b - c * t20 * t40 - (t39 * c * t20 - T(4) * t50 * t20 * b - T(2) * ((T(105) * log_ratio - T(2) * t20 * t48 * b) * t20 + T(4) * t49 * t20 * b - c * t38 * t20) * t20) * t20) * t20 - c * t47 * t20) * t20 * t58 + (T(1) / T(5)) * t20 * t46 * t60 * t61 + (T(3) / T(20)) * t45 * t20 * t62 * t55 + (T(3) / T(70)) * t47 * t20 * t63 * t1 - (T(1) / T(2)) * t43 * t20 * t59 * t64 - (T(3) / T(10)) * t20 * t44 * t53 * t65 - (T(9) / T(8)) * t20 * delta_tau * t41 * t56 - (T(9) / T(7)) * t42 * t20 * t0 * t66;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t67 = sqrt(D);
    const T t68 = T(1) / t67;
    const T J2 = atan2(t67, c_minus_b) * t68;
    const T t69 = T(1) / D;
    const T t70 = t2 * t2;
    const T t71 = t70 * t2;
    const T t72 = T(1) / q1;
    const T t73 = a_minus_b * t72 + a * J2 + t2 * b;
    const T t74 = t72 * t72;
    const T t75 = T(3) * t73 * a * t69 + T(2) * t70 * b + T(2) * a_minus_b * t74;
    const T t76 = t74 * t72;
    const T t77 = T(8) * t71 * b + T(5) * t75 * a * t69 + T(8) * a_minus_b * t76;
    const T t78 = t74 * t74;
    const T t79 = t70 * t70;
    const T t80 = T(7) * a * t69 * t77 + T(48) * t79 * b + T(48) * a_minus_b * t78;
    const T t81 = T(48) * t78 - T(48) * t79 - t80 * t69 * b;
    const T t82 = T(1) / a;
    const T t83 = T(8) * t69 * t77 - T(2) * t81 * t82 * b - t80 * c * t69;
    const T t84 = t1 * tau_lo;
    const T t85 = t84 * t84;
    const T t86 = t85 * tau_lo;
    const T t87 = T(2) * t74 - t75 * t69 * b - T(2) * t70;
    const T t88 = T(2) * t87 * t82 * b + c * t75 * t69 - T(4) * t73 * t69;
    const T t89 = t2 + t73 * t69 * b - t72;
    const T t90 = T(2) * t82 * t89 * b + T(2) * J2 - t73 * c * t69;
    const T t91 = T(2) * t88 * t82 * b - T(4) * t82 * t89 - c * t87 * t82;
    const T t92 = t88 * c * t82 + T(4) * t82 * t90 - T(2) * t91 * t82 * b;
    const T t93 = T(8) * t76 - t69 * t77 * b - T(8) * t71;
    const T t94 = c * t69 * t77 + T(2) * t93 * t82 * b - T(6) * t75 * t69;
    const T t95 = T(2) * t94 * t82 * b + T(6) * t87 * t82 - c * t93 * t82;
    const T t96 = T(2) * t95 * t82 * b + T(6) * t88 * t82 - c * t94 * t82;
    const T t97 = T(2) * t82 * t96 * b + T(6) * t91 * t82 - c * t95 * t82;
    const T t98 = T(2) * t82 * t97 * b - T(6) * t82 * t92 - c * t82 * t96;
    const T t99 = T(2) * t83 * t82 * b + c * t81 * t82 - T(8) * t93 * t82;
    const T t100 = t83 * c * t82 + T(8) * t94 * t82 - T(2) * t99 * t82 * b;
    const T t101 = T(2) * t100 * t82 * b + t99 * c * t82 + T(8) * t95 * t82;
    const T t102 = t100 * c * t82 - T(2) * t101 * t82 * b - T(8) * t82 * t96;
    const T t103 = T(8) * t82 * t97 - c * t101 * t82 - T(2) * t102 * t82 * b;
    const T t104 = c * t102 * t82 + T(2) * t82 * t103 * b + T(8) * t82 * t98;
    const T t105 = t0 * t0;
    const T t106 = t105 * t105;
    const T t107 = t106 * delta_tau;
    const T t108 = t0 * delta_tau;
    const T t109 = t108 * t108;
    const T t110 = t1 * t1;
    const T t111 = t110 * t110;
    const T t112 = t111 * tau_lo;
    const T t113 = t109 * delta_tau;
    const T t114 = t110 * tau_lo;
    const T t115 = t105 * delta_tau;
    F = (T(3) / T(32)) * t83 * t82 * t0 * t86 + (T(1) / T(384)) * (T(8) * (T(6) * (T(2) * t82 * t92 * b + t91 * c * t82 + T(4) * (T(2) * t82 * t90 * b + (log_ratio + T(2) * J2 * b) * t82 - c * t82 * t89) * t82) * t82 + c * t82 * t97 - T(2) * t82 * t98 * b) * t82 + c * t82 * t103 - T(2) * t82 * t104 * b) * t82 * t107 + (T(7) / T(32)) * t99 * t82 * t108 * t85 + (T(7) / T(32)) * t102 * t82 * t109 * t84 + (T(1) / T(384)) * t80 * t69 * t112 - (T(3) / T(32)) * t82 * t113 * t1 * t103 - (T(21) / T(64)) * t100 * t82 * t105 * t114 - (T(3) / T(128)) * t81 * t82 * delta_tau * t111 - (T(21) / T(64)) * t101 * t82 * t115 * t110 - (T(3) / T(128)) * t82 * t104 * t106 * tau_lo;
  }
  const T t116 = sigma2 * sigma2;
  const T t117 = t116 * t116;
  const T t118 = t117 * sigma2;
  f = F * t118 * length;
  return f;
}

/// its gradient ∇_P f, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 132 +, 393 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 344 +, 608 ×, 20 /, 1 sqrt, 0 atan, 0 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 11> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 10, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * t5;
    const T t7 = t0 * t0;
    const T t8 = t7 * delta_tau;
    const T t9 = t7 * t7;
    const T t10 = t9 * delta_tau;
    const T t11 = t6 * tau_lo;
    const T t12 = t0 * delta_tau;
    const T t13 = t1 * tau_lo;
    const T t14 = t13 * t13;
    const T t15 = t12 * t12;
    const T t16 = t5 * tau_lo;
    const T t17 = t14 * tau_lo;
    const T t18 = t15 * delta_tau;
    G_ap = T(9) * delta_tau * t6 * M_flat[1] + T(126) * t8 * t5 * M_flat[5] + M_flat[9] * t10 + t11 * M_flat[0] + T(84) * t12 * M_flat[3] * t14 + T(84) * M_flat[6] * t15 * t13 + T(9) * t9 * tau_lo * M_flat[8] + T(126) * t7 * t16 * M_flat[4] + T(36) * M_flat[2] * t0 * t17 + T(36) * t18 * t1 * M_flat[7];
    G_ab = T(36) * t0 * M_flat[3] * t17 + T(36) * t18 * t1 * M_flat[8] + T(126) * M_flat[6] * t8 * t5 + t11 * M_flat[1] + T(126) * t7 * t16 * M_flat[5] + T(9) * M_flat[9] * t9 * tau_lo + T(84) * t12 * t14 * M_flat[4] + T(9) * M_flat[2] * delta_tau * t6 + t10 * M_flat[10] + T(84) * t15 * t13 * M_flat[7];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 11> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 10, a, b, D, c, q1, M_beyond.data());
    const T t19 = t0 * delta_tau;
    const T t20 = t19 * t19;
    const T t21 = t20 * delta_tau;
    const T t22 = t0 * t0;
    const T t23 = t22 * delta_tau;
    const T t24 = t1 * t1;
    const T t25 = t24 * tau_lo;
    const T t26 = t1 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = t27 * tau_lo;
    const T t29 = t24 * t24;
    const T t30 = t22 * t22;
    const T t31 = t30 * delta_tau;
    const T t32 = t29 * tau_lo;
    G_ap = T(36) * M_beyond[7] * t21 * t1 + T(126) * t23 * t24 * M_beyond[5] + T(126) * M_beyond[4] * t22 * t25 + T(84) * t19 * t27 * M_beyond[3] + T(84) * t20 * t26 * M_beyond[6] + T(36) * t0 * t28 * M_beyond[2] + T(9) * M_beyond[1] * delta_tau * t29 + t31 * M_beyond[9] + t32 * M_beyond[0] + T(9) * t30 * M_beyond[8] * tau_lo;
    G_ab = M_beyond[1] * t32 + T(84) * M_beyond[7] * t20 * t26 + T(126) * t23 * t24 * M_beyond[6] + T(126) * t22 * t25 * M_beyond[5] + T(9) * t30 * tau_lo * M_beyond[9] + T(84) * M_beyond[4] * t19 * t27 + T(36) * t21 * M_beyond[8] * t1 + T(9) * delta_tau * t29 * M_beyond[2] + T(36) * t0 * t28 * M_beyond[3] + M_beyond[10] * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t33 = sqrt(D);
    const T t34 = T(1) / t33;
    const T J2 = t34 * atan2(t33, c_minus_b);
    const T t35 = T(1) / a;
    const T t36 = t1 * t1;
    const T t37 = t36 * t36;
    const T t38 = T(1) / D;
    const T t39 = T(1) / c;
    const T t40 = t39 * t39;
    const T t41 = t40 * t40;
    const T t42 = t41 * t39;
    const T t43 = T(1) / q1;
    const T t44 = t43 * t43;
    const T t45 = t44 * t44;
    const T t46 = t45 * t43;
    const T t47 = t44 * t43;
    const T t48 = t40 * t39;
    const T t49 = a * J2 + a_minus_b * t43 + b * t39;
    const T t50 = T(2) * b * t40 + T(2) * a_minus_b * t44 + T(3) * t38 * a * t49;
    const T t51 = T(8) * a_minus_b * t47 + T(8) * b * t48 + T(5) * t38 * a * t50;
    const T t52 = T(48) * b * t41 + T(7) * t38 * t51 * a + T(48) * a_minus_b * t45;
    const T t53 = T(128) * b * t42 + T(128) * a_minus_b * t46 + T(3) * t38 * a * t52;
    const T t54 = t38 * b * t53 + T(128) * t42 - T(128) * t46;
    const T t55 = t37 * tau_lo;
    const T t56 = t0 * t0;
    const T t57 = t36 * tau_lo;
    const T t58 = t38 * t52 * b + T(48) * t41 - T(48) * t45;
    const T t59 = T(3) * t38 * t53 * c - T(6) * t35 * b * t54 - T(10) * t38 * t52;
    const T t60 = T(10) * t35 * t58 - T(3) * t35 * t54 * c - T(2) * t35 * b * t59;
    const T t61 = t38 * t52 * c - T(8) * t38 * t51 - T(2) * t35 * b * t58;
    const T t62 = T(2) * t60 * t35 * b + t35 * t59 * c - T(10) * t35 * t61;
    const T t63 = t0 * delta_tau;
    const T t64 = t1 * tau_lo;
    const T t65 = t64 * t64;
    const T t66 = t56 * t56;
    const T t67 = T(8) * t47 - T(8) * t48 - t38 * t51 * b;
    const T t68 = t38 * t51 * c + T(2) * t35 * t67 * b - T(6) * t38 * t50;
    const T t69 = T(8) * t35 * t67 + T(2) * t35 * b * t61 + t35 * t58 * c;
    const T t70 = T(8) * t35 * t68 + T(2) * t35 * b * t69 - t35 * t61 * c;
    const T t71 = T(10) * t35 * t69 + t60 * t35 * c - T(2) * t35 * t62 * b;
    const T t72 = T(10) * t70 * t35 + T(2) * t71 * t35 * b + t35 * t62 * c;
    const T t73 = T(2) * t44 - T(2) * t40 - t38 * t50 * b;
    const T t74 = T(2) * t35 * t73 * b + t38 * t50 * c - T(4) * t38 * t49;
    const T t75 = T(2) * t35 * t68 * b + T(6) * t35 * t73 - t35 * t67 * c;
    const T t76 = T(6) * t35 * t74 + T(2) * t75 * t35 * b - t35 * t68 * c;
    const T t77 = T(2) * t70 * t35 * b + T(8) * t75 * t35 - t35 * c * t69;
    const T t78 = T(8) * t35 * t76 + T(2) * t35 * b * t77 - t70 * t35 * c;
    const T t79 = T(10) * t35 * t77 + T(2) * t35 * t72 * b - t71 * t35 * c;
    const T t80 = t35 * t72 * c - T(10) * t78 * t35 - T(2) * t79 * t35 * b;
    const T t81 = t39 + t38 * t49 * b - t43;
    const T t82 = T(2) * t35 * b * t74 - T(4) * t81 * t35 - t35 * t73 * c;
    const T t83 = T(6) * t82 * t35 + T(2) * t35 * t76 * b - t75 * t35 * c;
    const T t84 = T(8) * t35 * t83 + T(2) * t78 * t35 * b - t35 * t77 * c;
    const T t85 = t79 * t35 * c + T(2) * t35 * b * t80 - T(10) * t84 * t35;
    const T t86 = t66 * delta_tau;
    const T t87 = t63 * t63;
    const T t88 = t87 * delta_tau;
    const T t89 = t56 * delta_tau;
    const T t90 = t65 * tau_lo;
    G_ap = (T(9) / T(1280)) * delta_tau * t35 * t37 * t54 + (T(1) / T(1280)) * t38 * t55 * t53 + (T(21) / T(640)) * t56 * t35 * t57 * t62 + (T(7) / T(320)) * t60 * t63 * t35 * t65 + (T(3) / T(1280)) * t66 * t35 * tau_lo * t80 + (T(1) / T(3840)) * t85 * t86 * t35 - (T(7) / T(320)) * t87 * t35 * t64 * t72 - (T(3) / T(320)) * t79 * t88 * t35 * t1 - (T(21) / T(640)) * t71 * t89 * t35 * t36 - (T(3) / T(320)) * t0 * t35 * t90 * t59;
    G_ab = (T(1) / T(1280)) * t35 * t55 * t54 + (T(3) / T(1280)) * t85 * t66 * t35 * tau_lo + (T(7) / T(320)) * t63 * t35 * t65 * t62 + (T(3) / T(320)) * t88 * t35 * t1 * t80 + (T(3) / T(320)) * t60 * t0 * t35 * t90 - (T(21) / T(640)) * t89 * t35 * t36 * t72 - (T(3) / T(1280)) * delta_tau * t35 * t37 * t59 - (T(21) / T(640)) * t71 * t56 * t35 * t57 - (T(1) / T(3840)) * t86 * t35 * (t35 * t80 * c + T(10) * t35 * (T(2) * t84 * t35 * b - t78 * t35 * c - T(8) * t35 * (t35 * t76 * c + T(6) * t35 * (t35 * t74 * c - T(2) * t82 * t35 * b - T(4) * t35 * (t38 * t49 * c - T(2) * t81 * t35 * b - T(2) * J2)) - T(2) * t35 * t83 * b)) - T(2) * t85 * t35 * b) - (T(7) / T(320)) * t79 * t87 * t35 * t64;
  }
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T t93 = t92 * sigma2;
  const T g_factor = -T(10) * t93 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]
/// Operations: 150 +, 463 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 573 +, 908 ×, 21 /, 1 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = delta_tau * ap1 + ab1 * tau_lo;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(q1 * t2);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 22> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 10, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * t0;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t0 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t1 * tau_lo;
    const T t12 = t6 * delta_tau;
    const T t13 = t1 * t1;
    const T t14 = t13 * t13;
    const T t15 = t13 * tau_lo;
    const T t16 = t11 * t11;
    const T t17 = t14 * tau_lo;
    const T t18 = t16 * tau_lo;
    const T t19 = t10 * delta_tau;
    F = t8 * M_flat[9] + T(84) * t10 * t11 * M_flat[6] + T(126) * t12 * M_flat[5] * t13 + T(9) * M_flat[1] * delta_tau * t14 + T(126) * t6 * t15 * M_flat[4] + T(84) * t9 * t16 * M_flat[3] + t17 * M_flat[0] + T(9) * M_flat[8] * t7 * tau_lo + T(36) * t0 * t18 * M_flat[2] + T(36) * t19 * t1 * M_flat[7];
    G_ap = M_flat[20] * t8 + T(9) * delta_tau * t14 * M_flat[12] + M_flat[11] * t17 + T(84) * M_flat[14] * t9 * t16 + T(126) * t12 * t13 * M_flat[16] + T(126) * t6 * t15 * M_flat[15] + T(84) * M_flat[17] * t10 * t11 + T(9) * t7 * tau_lo * M_flat[19] + T(36) * t0 * t18 * M_flat[13] + T(36) * t19 * t1 * M_flat[18];
    G_ab = T(84) * t9 * t16 * M_flat[15] + T(36) * M_flat[14] * t0 * t18 + T(9) * delta_tau * t14 * M_flat[13] + T(9) * M_flat[20] * t7 * tau_lo + t17 * M_flat[12] + T(126) * M_flat[17] * t12 * t13 + T(36) * t19 * t1 * M_flat[19] + t8 * M_flat[21] + T(84) * t10 * t11 * M_flat[18] + T(126) * t6 * t15 * M_flat[16];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t20 = t0 * t0;
    const T t21 = t1 * t1;
    const T t22 = t21 * tau_lo;
    const T t23 = T(1) / a;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t2 * t2;
    const T t28 = t27 * t27;
    const T t29 = t28 * t2;
    const T t30 = t26 * t24;
    const T t31 = J_downward<T>(12, a, D, -b, c, a_minus_b, q1);
    const T t32 = b * t29 + a_minus_b * t30 - T(10) * t31 * D;
    const T t33 = T(9) * a_minus_b * t26 + T(9) * b * t28 + T(8) * D * t23 * t32;
    const T t34 = T(9) * t26 + T(8) * t23 * b * t32 - T(9) * t28;
    const T t35 = T(4) * t33 * t23 + T(7) * t23 * t34 * b - T(28) * t23 * t32 * c;
    const T t36 = t27 * t2;
    const T t37 = t25 * t24;
    const T t38 = T(2) * t33 * D * t23 + T(21) * b * t36 + T(21) * a_minus_b * t37;
    const T t39 = T(2) * t33 * t23 * b + T(21) * t37 - T(21) * t36;
    const T t40 = T(3) * t23 * t38 + T(5) * t39 * t23 * b - T(5) * t33 * t23 * c;
    const T t41 = T(4) * t39 * t23 + T(4) * t23 * b * t35 - T(7) * t23 * t34 * c;
    const T t42 = T(5) * t23 * t35 * c - T(4) * t23 * t40 - T(5) * t41 * t23 * b;
    const T t43 = t20 * t20;
    const T t44 = T(105) * b * t27 + T(105) * a_minus_b * t25 + T(4) * D * t23 * t38;
    const T t45 = T(105) * t27 - T(105) * t25 - T(4) * t23 * b * t38;
    const T t46 = T(2) * t44 * t23 - T(3) * t45 * t23 * b - T(6) * t23 * t38 * c;
    const T t47 = T(8) * t23 * t40 * b - T(10) * t39 * t23 * c - T(3) * t45 * t23;
    const T t48 = t23 * t46 + t23 * b * t47 - T(2) * t23 * t40 * c;
    const T t49 = T(2) * t44 * t23 * b + T(315) * t24 - T(315) * t2;
    const T t50 = T(4) * t23 * t46 * b + T(2) * t23 * t49 + T(3) * t45 * t23 * c;
    const T t51 = t23 * t47 * c - T(4) * t23 * t48 * b - t23 * t50;
    const T t52 = T(2) * D * t44 * t23 + T(315) * a_minus_b * t24 + T(315) * b * t2;
    const T t53 = t23 * t49 * b + t23 * t52 - t44 * t23 * c;
    const T t54 = t23 * b * t50 + T(2) * t53 * t23 - t23 * t46 * c;
    const T t55 = t23 * t48 * c + t51 * t23 * b - t54 * t23;
    const T t56 = T(2) * t23 * t47 - T(5) * t41 * t23 * c - T(4) * t23 * b * t42;
    const T t57 = t23 * t42 * c + T(2) * t23 * t48 + t23 * b * t56;
    const T t58 = t23 * t56 * c + T(2) * t51 * t23 - T(4) * t23 * b * t57;
    const T t59 = T(2) * t55 * t23 + t23 * t57 * c + t23 * t58 * b;
    const T t60 = t0 * delta_tau;
    const T t61 = t60 * t60;
    const T t62 = t61 * delta_tau;
    const T t63 = t1 * tau_lo;
    const T t64 = t63 * t63;
    const T t65 = t20 * delta_tau;
    const T t66 = t43 * delta_tau;
    const T t67 = t64 * tau_lo;
    const T t68 = t21 * t21;
    const T t69 = t68 * tau_lo;
    F = (T(1) / T(10)) * t20 * t22 * t23 * t42 + (T(1) / T(140)) * t43 * tau_lo * t23 * t59 + (T(1) / T(70)) * t62 * t1 * t23 * t58 - (T(1) / T(6)) * t41 * t60 * t64 * t23 - (T(1) / T(20)) * t65 * t21 * t23 * t56 - (T(1) / T(15)) * t61 * t63 * t23 * t57 - (T(1) / T(2520)) * t66 * t23 * (t23 * t58 * c - T(4) * t23 * t59 * b - T(2) * t23 * (T(4) * t55 * t23 * b - t51 * t23 * c - (T(2) * (T(4) * t53 * t23 * b - t23 * (T(315) * log_ratio - T(2) * t23 * t52 * b) - t23 * t49 * c) * t23 + T(4) * t54 * t23 * b - t23 * t50 * c) * t23)) - (T(1) / T(7)) * t0 * t67 * t23 * t35 - (T(1) / T(9)) * t69 * t23 * t32 - (T(1) / T(8)) * delta_tau * t68 * t23 * t34;
    const T t70 = T(10) * t31 * b + t29 - t30;
    const T t71 = T(9) * t23 * t70 * b - T(5) * t23 * t32 - T(45) * t31 * c;
    const T t72 = T(16) * t23 * t71 * b - T(5) * t23 * t34 - T(36) * t23 * t70 * c;
    const T t73 = T(5) * t23 * t35 + T(28) * t23 * t71 * c - T(7) * t72 * t23 * b;
    const T t74 = T(4) * t73 * t23 * b + T(7) * t72 * t23 * c + T(5) * t41 * t23;
    const T t75 = t23 * b * t74 - t23 * t42 - t73 * t23 * c;
    const T t76 = t23 * t56 + T(4) * t75 * t23 * b - t23 * t74 * c;
    const T t77 = t23 * t57 + t76 * t23 * b - t75 * t23 * c;
    const T t78 = T(4) * t77 * t23 * b - t76 * t23 * c - t23 * t58;
    G_ap = (T(9) / T(10)) * delta_tau * t68 * t23 * t70 + t31 * t69 + (T(7) / T(30)) * t60 * t72 * t64 * t23 + (T(4) / T(5)) * t0 * t67 * t23 * t71 - (T(1) / T(10)) * t73 * t20 * t22 * t23 - (T(1) / T(2520)) * t66 * t78 * t23 - (T(1) / T(70)) * t76 * t62 * t1 * t23 - (T(1) / T(20)) * t65 * t21 * t23 * t74 - (T(1) / T(140)) * t77 * t43 * tau_lo * t23 - (T(1) / T(15)) * t75 * t61 * t63 * t23;
    G_ab = (T(1) / T(1260)) * t66 * t23 * (t23 * t59 + t77 * t23 * c - t78 * t23 * b) + (T(1) / T(5)) * delta_tau * t68 * t23 * t71 + (T(1) / T(10)) * t0 * t72 * t67 * t23 + (T(1) / T(10)) * t69 * t23 * t70 - (T(1) / T(20)) * t20 * t22 * t23 * t74 - (T(1) / T(35)) * t77 * t62 * t1 * t23 - (T(1) / T(30)) * t76 * t61 * t63 * t23 - (T(1) / T(280)) * t43 * tau_lo * t78 * t23 - (T(1) / T(15)) * t73 * t60 * t64 * t23 - (T(1) / T(10)) * t75 * t65 * t21 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t79 = sqrt(D);
    const T t80 = T(1) / t79;
    const T J2 = atan2(t79, c_minus_b) * t80;
    const T t81 = t0 * t0;
    const T t82 = t81 * delta_tau;
    const T t83 = t1 * t1;
    const T t84 = T(1) / a;
    const T t85 = T(1) / q1;
    const T t86 = t85 * t85;
    const T t87 = t86 * t86;
    const T t88 = T(1) / D;
    const T t89 = t2 * t2;
    const T t90 = t89 * t89;
    const T t91 = t89 * t2;
    const T t92 = t86 * t85;
    const T t93 = a_minus_b * t85 + b * t2 + J2 * a;
    const T t94 = T(2) * b * t89 + T(2) * a_minus_b * t86 + T(3) * t88 * a * t93;
    const T t95 = T(8) * b * t91 + T(8) * a_minus_b * t92 + T(5) * t88 * a * t94;
    const T t96 = T(48) * a_minus_b * t87 + T(48) * b * t90 + T(7) * t88 * a * t95;
    const T t97 = T(48) * t87 - t88 * b * t96 - T(48) * t90;
    const T t98 = T(8) * t91 + t88 * b * t95 - T(8) * t92;
    const T t99 = t88 * t96 * c + T(2) * t97 * t84 * b - T(8) * t88 * t95;
    const T t100 = t97 * t84 * c + T(8) * t84 * t98 - T(2) * t84 * b * t99;
    const T t101 = T(6) * t88 * t94 + T(2) * t84 * b * t98 - t88 * t95 * c;
    const T t102 = T(2) * t84 * t100 * b + t84 * t99 * c + T(8) * t101 * t84;
    const T t103 = t88 * b * t94 + T(2) * t89 - T(2) * t86;
    const T t104 = t84 * t98 * c - T(6) * t103 * t84 - T(2) * t101 * t84 * b;
    const T t105 = T(2) * t84 * t102 * b - T(8) * t104 * t84 - t84 * t100 * c;
    const T t106 = t83 * tau_lo;
    const T t107 = t0 * delta_tau;
    const T t108 = t1 * tau_lo;
    const T t109 = t108 * t108;
    const T t110 = t83 * t83;
    const T t111 = t110 * tau_lo;
    const T t112 = t107 * t107;
    const T t113 = t112 * delta_tau;
    const T t114 = T(4) * t88 * t93 + T(2) * t103 * t84 * b - t88 * t94 * c;
    const T t115 = t101 * t84 * c + T(2) * t104 * t84 * b - T(6) * t84 * t114;
    const T t116 = t85 - t88 * b * t93 - t2;
    const T t117 = T(2) * t84 * b * t114 - T(4) * t84 * t116 - t103 * t84 * c;
    const T t118 = T(2) * t84 * b * t115 - t104 * t84 * c - T(6) * t84 * t117;
    const T t119 = T(8) * t84 * t115 + t84 * t102 * c - T(2) * t84 * b * t105;
    const T t120 = T(8) * t118 * t84 + t84 * t105 * c + T(2) * t119 * t84 * b;
    const T t121 = t81 * t81;
    const T t122 = t121 * delta_tau;
    const T t123 = T(2) * J2 - T(2) * t84 * t116 * b - t88 * t93 * c;
    const T t124 = T(4) * t123 * t84 + T(2) * t84 * t117 * b - t84 * t114 * c;
    const T t125 = T(6) * t84 * t124 + t84 * t115 * c - T(2) * t118 * t84 * b;
    const T t126 = T(2) * t84 * t120 * b - T(8) * t84 * t125 - t119 * t84 * c;
    const T t127 = t109 * tau_lo;
    F = (T(21) / T(64)) * t82 * t83 * t84 * t105 + (T(21) / T(64)) * t81 * t106 * t84 * t102 + (T(7) / T(32)) * t107 * t109 * t84 * t100 + (T(1) / T(384)) * t88 * t111 * t96 - (T(3) / T(32)) * t113 * t1 * t84 * t120 - (T(1) / T(384)) * t122 * t84 * (T(8) * t84 * (T(6) * t84 * (t84 * t117 * c - T(2) * t84 * b * t124 - T(4) * t84 * (T(2) * t123 * t84 * b + t84 * (T(2) * J2 * b + log_ratio) + t84 * t116 * c)) - t118 * t84 * c - T(2) * t84 * t125 * b) + T(2) * t84 * b * t126 - t84 * t120 * c) - (T(3) / T(128)) * t97 * delta_tau * t110 * t84 - (T(7) / T(32)) * t112 * t119 * t108 * t84 - (T(3) / T(32)) * t0 * t127 * t84 * t99 - (T(3) / T(128)) * t121 * tau_lo * t84 * t126;
    const T t128 = t87 * t85;
    const T t129 = t90 * t2;
    const T t130 = T(128) * b * t129 + T(3) * t88 * a * t96 + T(128) * a_minus_b * t128;
    const T t131 = T(128) * t128 - t88 * t130 * b - T(128) * t129;
    const T t132 = T(3) * t88 * t130 * c + T(6) * t84 * t131 * b - T(10) * t88 * t96;
    const T t133 = T(3) * t84 * t131 * c - T(2) * t84 * t132 * b - T(10) * t97 * t84;
    const T t134 = T(10) * t84 * t99 - T(2) * t133 * t84 * b - t84 * t132 * c;
    const T t135 = T(2) * t84 * b * t134 + t133 * t84 * c - T(10) * t84 * t100;
    const T t136 = t84 * t134 * c + T(10) * t84 * t102 - T(2) * t84 * b * t135;
    const T t137 = t84 * t135 * c + T(10) * t84 * t105 + T(2) * t136 * t84 * b;
    const T t138 = T(10) * t119 * t84 + t136 * t84 * c - T(2) * t137 * t84 * b;
    const T t139 = t137 * t84 * c + T(10) * t84 * t120 + T(2) * t84 * t138 * b;
    G_ap = (T(7) / T(320)) * t133 * t107 * t109 * t84 + (T(3) / T(320)) * t113 * t137 * t1 * t84 + (T(1) / T(1280)) * t88 * t111 * t130 + (T(7) / T(320)) * t136 * t112 * t108 * t84 - (T(9) / T(1280)) * delta_tau * t110 * t84 * t131 - (T(1) / T(3840)) * t139 * t122 * t84 - (T(3) / T(1280)) * t121 * tau_lo * t84 * t138 - (T(21) / T(640)) * t82 * t83 * t84 * t135 - (T(21) / T(640)) * t81 * t106 * t84 * t134 - (T(3) / T(320)) * t0 * t127 * t84 * t132;
    G_ab = (T(3) / T(320)) * t133 * t0 * t127 * t84 + (T(21) / T(640)) * t136 * t82 * t83 * t84 + (T(7) / T(320)) * t112 * t137 * t108 * t84 - (T(3) / T(1280)) * delta_tau * t110 * t84 * t132 - (T(21) / T(640)) * t81 * t106 * t84 * t135 - (T(7) / T(320)) * t107 * t109 * t84 * t134 - (T(1) / T(3840)) * t122 * t84 * (T(10) * t84 * t126 + T(2) * t139 * t84 * b - t84 * t138 * c) - (T(1) / T(1280)) * t111 * t84 * t131 - (T(3) / T(1280)) * t139 * t121 * tau_lo * t84 - (T(3) / T(320)) * t113 * t1 * t84 * t138;
  }
  const T t140 = sigma2 * sigma2;
  const T t141 = t140 * t140;
  const T t142 = t141 * sigma2;
  const T g_factor = -T(10) * length * t142;
  f = length * F * t142;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

}  // namespace skelconv::generated
