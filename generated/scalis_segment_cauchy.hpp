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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab + delta_tau * delta_tau * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * tau_lo + M_flat[1] * delta_tau;
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / a;
    F = tau_lo * t3 + (T(1) / T(2)) * (T(2) * b * t3 + log_ratio) * t4 * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    const T t6 = T(1) / a;
    F = (T(1) / T(2)) * t6 * delta_tau * (T(2) * J2 * b + log_ratio) + J2 * tau_lo;
  }
  f = length * F * sigma2;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = delta_tau * M_flat[1] + M_flat[0] * tau_lo;
    G_ab = M_flat[2] * delta_tau + tau_lo * M_flat[1];
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
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = a * J2 + t5 * b + a_minus_b * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / a;
    const T t10 = t7 * t8 * b + t5 - t6;
    G_ap = (T(1) / T(2)) * t7 * t8 * tau_lo + (T(1) / T(2)) * t9 * delta_tau * t10;
    G_ab = (T(1) / T(2)) * t9 * tau_lo * t10 - (T(1) / T(2)) * (c * t7 * t8 - T(2) * t9 * b * t10 - T(2) * J2) * t9 * delta_tau;
  }
  const T g_factor = -T(2) * length * sigma2;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = delta_tau * delta_tau * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T c = tau_lo * tau_lo * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    F = tau_lo * M_flat[0] + M_flat[1] * delta_tau;
    G_ap = M_flat[4] * delta_tau + tau_lo * M_flat[3];
    G_ab = M_flat[5] * delta_tau + M_flat[4] * tau_lo;
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t6 = T(1) / q1;
    const T t7 = T(2) * D * t5 - a_minus_b * t6 - b * t0;
    F = (T(1) / T(2)) * t4 * delta_tau * (log_ratio + T(2) * t7 * t4 * b) + t7 * t4 * tau_lo;
    const T t8 = t0 + T(2) * t5 * b - t6;
    G_ap = tau_lo * t5 + (T(1) / T(2)) * t8 * t4 * delta_tau;
    G_ab = t4 * delta_tau * (t8 * t4 * b + t7 * t4 - t5 * c) + (T(1) / T(2)) * t8 * t4 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / a;
    F = J2 * tau_lo + (T(1) / T(2)) * t11 * delta_tau * (T(2) * J2 * b + log_ratio);
    const T t12 = T(1) / q1;
    const T t13 = a_minus_b * t12 + b * t0 + J2 * a;
    const T t14 = T(1) / D;
    const T t15 = t0 + t13 * t14 * b - t12;
    G_ap = (T(1) / T(2)) * t13 * t14 * tau_lo + (T(1) / T(2)) * t15 * t11 * delta_tau;
    G_ab = (T(1) / T(2)) * t15 * t11 * tau_lo + (T(1) / T(2)) * t11 * (T(2) * t15 * t11 * b + T(2) * J2 - t13 * t14 * c) * delta_tau;
  }
  const T g_factor = -T(2) * length * sigma2;
  f = length * F * sigma2;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
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
    const T t5 = a_minus_b * r0;
    X = t3 * t4 * (t5 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t6 = sqrt(a);
    const T t7 = a_minus_b * r0;
    X = (a_minus_b - b) * t6 / (t7 - r1 * b);
  }
  const T t8 = sqrt(a);
  const T t9 = T(1) / t8;
  const T J1 = t9 * asinh(X);
  T F;
  const T t10 = D - T(2) * a * a;
  const T t11 = -a_minus_b * b;
  const T t12 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * t0 + T(2) * M_flat[1] * delta_tau * tau_lo + t1 * M_flat[0];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t13 = -b;
    const T t14 = J_downward<T>(3, a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / a;
    const T t16 = T(1) / r1;
    const T t17 = T(1) / r0;
    const T t18 = t16 - t14 * b - t17;
    F = t14 * t1 - t15 * t0 * (c * t14 + T(2) * t15 * t18 * b - J1) - T(2) * t15 * delta_tau * tau_lo * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = t19 * a_minus_b + t20 * b;
    const T t22 = T(1) / D;
    const T t23 = t21 * t22 * b + t20 - t19;
    const T t24 = T(1) / a;
    F = (T(2) * t23 * t24 * b + J1 - t21 * c * t22) * t24 * t0 + t21 * t22 * t1 + T(2) * t23 * t24 * delta_tau * tau_lo;
  }
  f = length * in.sigma * F * sigma2;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = T(2) * M_flat[1] * delta_tau * tau_lo + M_flat[0] * t1 + t0 * M_flat[2];
    G_ab = M_flat[3] * t0 + T(2) * delta_tau * tau_lo * M_flat[2] + M_flat[1] * t1;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = T(2) * delta_tau * tau_lo * M_beyond[1] + M_beyond[2] * t0 + M_beyond[0] * t1;
    G_ab = t1 * M_beyond[1] + T(2) * M_beyond[2] * delta_tau * tau_lo + M_beyond[3] * t0;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / r0;
    const T t8 = t6 * a_minus_b + t7 * b;
    const T t9 = t6 * t6;
    const T t10 = t7 * t7;
    const T t11 = T(2) * t5 * a * t8 + t6 * a_minus_b * t9 + t7 * t10 * b;
    const T t12 = T(1) / a;
    const T t13 = t6 * t9 - t7 * t10 - t5 * b * t11;
    const T t14 = T(3) * t5 * t8 - T(2) * t13 * t12 * b - c * t5 * t11;
    G_ap = (T(1) / T(3)) * t5 * t1 * t11 + (T(1) / T(3)) * t12 * t0 * t14 - (T(2) / T(3)) * t13 * t12 * delta_tau * tau_lo;
    G_ab = (T(1) / T(3)) * t12 * (T(2) * t12 * t14 * b + c * t13 * t12 - T(3) * t12 * (t6 - t5 * t8 * b - t7)) * t0 + (T(2) / T(3)) * t12 * delta_tau * t14 * tau_lo - (T(1) / T(3)) * t13 * t12 * t1;
  }
  const T g_factor = -T(3) * sigma2 * length * in.sigma;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = b * a_minus_b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = t3 * t4 * (t5 + b * r1);
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
  const T t10 = D - T(2) * a * a;
  const T t11 = -b * a_minus_b;
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * t0 + M_flat[0] * t1 + T(2) * M_flat[1] * delta_tau * tau_lo;
    G_ap = M_flat[4] * t1 + T(2) * M_flat[5] * delta_tau * tau_lo + M_flat[6] * t0;
    G_ab = M_flat[5] * t1 + M_flat[7] * t0 + T(2) * M_flat[6] * delta_tau * tau_lo;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t13 = J_downward<T>(5, a, D, -b, c, a_minus_b, q1);
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = T(3) * D * t13 - b * t15 * t14 - t17 * t16 * a_minus_b;
    const T t19 = T(1) / a;
    const T t20 = T(2) * t16 - T(2) * t14 - b * t18 * t19;
    F = (T(1) / T(2)) * t18 * t19 * t1 - t20 * t19 * delta_tau * tau_lo - (T(1) / T(2)) * (T(2) * b * t20 * t19 + t18 * c * t19 - T(2) * J1) * t19 * t0;
    const T t21 = t15 * t14;
    const T t22 = T(3) * b * t13 + t21 - t17 * t16;
    const T t23 = T(6) * c * t13 - T(3) * t18 * t19 - T(4) * b * t19 * t22;
    G_ap = (T(2) / T(3)) * t19 * delta_tau * t22 * tau_lo + t1 * t13 - (T(1) / T(6)) * t23 * t19 * t0;
    G_ab = (T(1) / T(3)) * t19 * t22 * t1 - (T(1) / T(6)) * (T(2) * b * t23 * t19 + T(3) * t20 * t19 + T(2) * c * t19 * t22) * t19 * t0 - (T(1) / T(3)) * t23 * t19 * delta_tau * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = b * t24 + t25 * a_minus_b;
    const T t27 = T(1) / D;
    const T t28 = T(1) / a;
    const T t29 = t25 - b * t26 * t27 - t24;
    F = t26 * t27 * t1 - t28 * t0 * (T(2) * b * t29 * t28 + t26 * c * t27 - J1) - T(2) * t29 * t28 * delta_tau * tau_lo;
    const T t30 = t24 * t24;
    const T t31 = t25 * t25;
    const T t32 = T(2) * t26 * t27 * a + b * t30 * t24 + t31 * t25 * a_minus_b;
    const T t33 = t30 * t24;
    const T t34 = b * t32 * t27 + t33 - t31 * t25;
    const T t35 = T(3) * t26 * t27 + T(2) * b * t28 * t34 - t32 * c * t27;
    G_ap = (T(1) / T(3)) * t28 * t0 * t35 + (T(2) / T(3)) * t28 * delta_tau * t34 * tau_lo + (T(1) / T(3)) * t32 * t27 * t1;
    G_ab = (T(2) / T(3)) * t28 * delta_tau * t35 * tau_lo + (T(1) / T(3)) * t28 * t34 * t1 - (T(1) / T(3)) * (T(3) * t29 * t28 + c * t28 * t34 - T(2) * b * t28 * t35) * t28 * t0;
  }
  const T g_factor = -T(3) * sigma2 * length * in.sigma;
  f = F * sigma2 * length * in.sigma;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
  const T a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = sigma2 * tau_hi * tau_lo + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * delta_tau;
    F = T(3) * delta_tau * t1 * M_flat[1] + M_flat[0] * t6 + M_flat[3] * t7 + T(3) * M_flat[2] * t0 * tau_lo;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t1 * tau_lo;
    const T t10 = T(1) / q1;
    const T t11 = T(2) * b * t8 + t2 - t10;
    const T t12 = T(1) / a;
    const T t13 = T(2) * D * t8 - b * t2 - a_minus_b * t10;
    const T t14 = c * t8 - t11 * b * t12 - t13 * t12;
    const T t15 = t0 * delta_tau;
    F = t8 * t9 + (T(3) / T(2)) * t11 * delta_tau * t12 * t1 - T(3) * t14 * t0 * t12 * tau_lo - (T(1) / T(2)) * (T(4) * b * t14 * t12 + t11 * c * t12 - (T(2) * b * t13 * t12 + log_ratio) * t12) * t15 * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = atan2(t16, c_minus_b) * t17;
    const T t18 = T(1) / q1;
    const T t19 = a * J2 + b * t2 + a_minus_b * t18;
    const T t20 = T(1) / D;
    const T t21 = t2 + b * t19 * t20 - t18;
    const T t22 = T(1) / a;
    const T t23 = T(2) * b * t21 * t22 + T(2) * J2 - c * t19 * t20;
    const T t24 = t0 * delta_tau;
    const T t25 = t1 * tau_lo;
    F = (T(3) / T(2)) * delta_tau * t21 * t22 * t1 + (T(1) / T(2)) * ((T(2) * b * J2 + log_ratio) * t22 + T(2) * b * t23 * t22 - c * t21 * t22) * t24 * t22 + (T(3) / T(2)) * t23 * t0 * t22 * tau_lo + (T(1) / T(2)) * t19 * t20 * t25;
  }
  f = F * sigma2 * sigma2 * length;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
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
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t0 * delta_tau;
    const T t6 = t1 * tau_lo;
    G_ap = T(3) * M_flat[2] * t0 * tau_lo + T(3) * delta_tau * t1 * M_flat[1] + t5 * M_flat[3] + t6 * M_flat[0];
    G_ab = t6 * M_flat[1] + T(3) * M_flat[2] * delta_tau * t1 + t5 * M_flat[4] + T(3) * t0 * M_flat[3] * tau_lo;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, a, b, D, c, q1, M_beyond.data());
    const T t7 = t1 * tau_lo;
    const T t8 = t0 * delta_tau;
    G_ap = M_beyond[0] * t7 + T(3) * t0 * tau_lo * M_beyond[2] + M_beyond[3] * t8 + T(3) * M_beyond[1] * delta_tau * t1;
    G_ab = T(3) * delta_tau * t1 * M_beyond[2] + T(3) * M_beyond[3] * t0 * tau_lo + M_beyond[4] * t8 + M_beyond[1] * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / D;
    const T t12 = t1 * tau_lo;
    const T t13 = T(1) / q1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / c;
    const T t16 = t15 * b + a * J2 + a_minus_b * t13;
    const T t17 = t15 * t15;
    const T t18 = T(2) * a_minus_b * t14 + T(3) * t11 * a * t16 + T(2) * t17 * b;
    const T t19 = T(1) / a;
    const T t20 = t11 * t18 * b + T(2) * t17 - T(2) * t14;
    const T t21 = T(2) * t20 * t19 * b + T(4) * t11 * t16 - c * t11 * t18;
    const T t22 = t11 * t16 * b + t15 - t13;
    const T t23 = T(2) * t19 * b * t21 + T(4) * t22 * t19 - c * t20 * t19;
    const T t24 = t0 * delta_tau;
    G_ap = (T(1) / T(8)) * t11 * t12 * t18 + (T(3) / T(8)) * t0 * t19 * tau_lo * t21 + (T(1) / T(8)) * t23 * t24 * t19 + (T(3) / T(8)) * t20 * delta_tau * t19 * t1;
    G_ab = (T(3) / T(8)) * delta_tau * t19 * t1 * t21 + (T(1) / T(8)) * (T(2) * t23 * t19 * b - c * t19 * t21 - T(4) * t19 * (c * t11 * t16 - T(2) * t22 * t19 * b - T(2) * J2)) * t24 * t19 + (T(1) / T(8)) * t20 * t19 * t12 + (T(3) / T(8)) * t23 * t0 * t19 * tau_lo;
  }
  const T g_factor = -T(4) * length * sigma2 * sigma2;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = ap_bp + tau_hi * sigma2 * tau_lo;
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
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * delta_tau;
    F = T(3) * M_flat[1] * t1 * delta_tau + M_flat[0] * t6 + t7 * M_flat[3] + T(3) * M_flat[2] * tau_lo * t0;
    G_ap = M_flat[5] * t6 + T(3) * t1 * delta_tau * M_flat[6] + T(3) * M_flat[7] * tau_lo * t0 + M_flat[8] * t7;
    G_ab = T(3) * M_flat[7] * t1 * delta_tau + T(3) * M_flat[8] * tau_lo * t0 + t7 * M_flat[9] + t6 * M_flat[6];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t8 = T(1) / a;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t2 * t2;
    const T t12 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t13 = t10 * a_minus_b + t11 * b - T(4) * D * t12;
    const T t14 = T(2) * t8 * b * t13 + T(3) * t9 - T(3) * t2;
    const T t15 = T(3) * t2 * b + T(2) * D * t8 * t13 + T(3) * t9 * a_minus_b;
    const T t16 = t14 * t8 * b + t15 * t8 - c * t8 * t13;
    const T t17 = t0 * delta_tau;
    const T t18 = t1 * tau_lo;
    F = -t16 * t8 * tau_lo * t0 - (T(1) / T(2)) * t14 * t8 * t1 * delta_tau - (T(1) / T(6)) * t8 * t17 * ((T(2) * t15 * t8 * b - T(3) * log_ratio) * t8 + T(4) * t16 * t8 * b - c * t14 * t8) - (T(1) / T(3)) * t8 * t18 * t13;
    const T t19 = t10 - T(4) * t12 * b - t11;
    const T t20 = T(3) * t19 * t8 * b + T(6) * c * t12 + T(2) * t8 * t13;
    const T t21 = T(3) * c * t19 * t8 - T(2) * t14 * t8 - T(4) * t20 * t8 * b;
    G_ap = (T(1) / T(12)) * t21 * t8 * t17 + t18 * t12 - (T(3) / T(4)) * t19 * t8 * t1 * delta_tau - (T(1) / T(2)) * t20 * t8 * tau_lo * t0;
    G_ab = (T(1) / T(6)) * (t21 * t8 * b + c * t20 * t8 - T(2) * t16 * t8) * t8 * t17 + (T(1) / T(4)) * t21 * t8 * tau_lo * t0 - (T(1) / T(4)) * t19 * t8 * t18 - (T(1) / T(2)) * t20 * t8 * t1 * delta_tau;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, c_minus_b) * t23;
    const T t24 = T(1) / D;
    const T t25 = T(1) / q1;
    const T t26 = t2 * b + t25 * a_minus_b + J2 * a;
    const T t27 = t2 + t24 * b * t26 - t25;
    const T t28 = T(1) / a;
    const T t29 = t1 * tau_lo;
    const T t30 = c * t24 * t26 - T(2) * J2 - T(2) * t27 * t28 * b;
    const T t31 = t0 * delta_tau;
    F = (T(3) / T(2)) * t27 * t28 * t1 * delta_tau + (T(1) / T(2)) * t24 * t29 * t26 - (T(3) / T(2)) * t28 * t30 * tau_lo * t0 - (T(1) / T(2)) * (c * t27 * t28 + T(2) * t28 * t30 * b - t28 * (T(2) * J2 * b + log_ratio)) * t28 * t31;
    const T t32 = t25 * t25;
    const T t33 = t2 * t2;
    const T t34 = T(3) * t24 * a * t26 + T(2) * t32 * a_minus_b + T(2) * t33 * b;
    const T t35 = t34 * t24 * b + T(2) * t33 - T(2) * t32;
    const T t36 = T(2) * t35 * t28 * b + T(4) * t24 * t26 - t34 * c * t24;
    const T t37 = T(4) * t27 * t28 + T(2) * t28 * t36 * b - t35 * c * t28;
    G_ap = (T(3) / T(8)) * t35 * t28 * t1 * delta_tau + (T(1) / T(8)) * t37 * t28 * t31 + (T(3) / T(8)) * t28 * tau_lo * t0 * t36 + (T(1) / T(8)) * t34 * t24 * t29;
    G_ab = (T(3) / T(8)) * t37 * t28 * tau_lo * t0 + (T(1) / T(8)) * t35 * t28 * t29 + (T(3) / T(8)) * t28 * t1 * delta_tau * t36 - (T(1) / T(8)) * t28 * (T(4) * t28 * t30 + c * t28 * t36 - T(2) * t37 * t28 * b) * t31;
  }
  const T t38 = sigma2 * sigma2;
  const T g_factor = -T(4) * t38 * length;
  f = t38 * length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
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
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 4, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * t1;
    const T t15 = t0 * t0;
    const T t16 = t1 * tau_lo;
    F = T(4) * t13 * tau_lo * M_flat[3] + t14 * M_flat[0] + t15 * M_flat[4] + T(4) * delta_tau * t16 * M_flat[1] + T(6) * M_flat[2] * t0 * t1;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t17 = T(1) / a;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t18 * a_minus_b * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t21 * b * t22;
    const T t24 = J_downward<T>(5, a, D, -b, c, a_minus_b, q1);
    const T t25 = t20 + t23 - T(3) * D * t24;
    const T t26 = T(2) * t21 - T(2) * t18 - t17 * b * t25;
    const T t27 = t21 * t22;
    const T t28 = t27 + T(3) * b * t24 - t18 * t19;
    const T t29 = T(4) * t17 * b * t28 - T(3) * t17 * t25 - T(6) * c * t24;
    const T t30 = T(2) * t17 * b * t29 + T(3) * t17 * t26 - T(2) * t17 * t28 * c;
    const T t31 = t0 * t0;
    const T t32 = t0 * delta_tau;
    const T t33 = t1 * tau_lo;
    const T t34 = t1 * t1;
    F = (T(1) / T(6)) * (T(3) * t17 * (T(2) * J1 + t17 * c * t25 + T(2) * t17 * t26 * b) + T(2) * t17 * b * t30 - t17 * c * t29) * t17 * t31 + (T(2) / T(3)) * t17 * t32 * tau_lo * t30 + (T(4) / T(3)) * t17 * delta_tau * t33 * t28 + t34 * t24 + t17 * t0 * t1 * t29;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t35 = T(1) / a;
    const T t36 = T(1) / D;
    const T t37 = T(1) / r0;
    const T t38 = T(1) / r1;
    const T t39 = t37 * b + t38 * a_minus_b;
    const T t40 = t38 * t38;
    const T t41 = t38 * a_minus_b * t40;
    const T t42 = t37 * t37;
    const T t43 = t37 * b * t42;
    const T t44 = T(2) * t36 * a * t39 + t41 + t43;
    const T t45 = t37 * t42;
    const T t46 = t36 * b * t44 + t45 - t38 * t40;
    const T t47 = t1 * tau_lo;
    const T t48 = t1 * t1;
    const T t49 = t36 * t44 * c - T(2) * t35 * t46 * b - T(3) * t36 * t39;
    const T t50 = t0 * delta_tau;
    const T t51 = t36 * b * t39 + t37 - t38;
    const T t52 = T(2) * t49 * t35 * b + t35 * t46 * c - T(3) * t35 * t51;
    const T t53 = t0 * t0;
    F = (T(4) / T(3)) * t35 * delta_tau * t46 * t47 + (T(1) / T(3)) * t36 * t48 * t44 - T(2) * t49 * t35 * t0 * t1 - (T(4) / T(3)) * t35 * t50 * t52 * tau_lo - (T(1) / T(3)) * t35 * t53 * (T(2) * t35 * t52 * b - T(3) * t35 * (J1 + T(2) * t35 * b * t51 - t36 * t39 * c) - t49 * t35 * c);
  }
  f = F * sigma2 * sigma2 * length * in.sigma;
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
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * delta_tau * tau_lo;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2);
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
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t0 * t0;
    const T t6 = t1 * tau_lo;
    const T t7 = t1 * t1;
    const T t8 = t0 * delta_tau;
    G_ap = M_flat[4] * t5 + T(4) * M_flat[1] * delta_tau * t6 + M_flat[0] * t7 + T(6) * M_flat[2] * t0 * t1 + T(4) * M_flat[3] * t8 * tau_lo;
    G_ab = M_flat[1] * t7 + T(4) * M_flat[4] * t8 * tau_lo + M_flat[5] * t5 + T(4) * M_flat[2] * delta_tau * t6 + T(6) * M_flat[3] * t0 * t1;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 5, a, b, D, c, q1, M_beyond.data());
    const T t9 = t0 * delta_tau;
    const T t10 = t1 * t1;
    const T t11 = t0 * t0;
    const T t12 = t1 * tau_lo;
    G_ap = T(4) * M_beyond[3] * t9 * tau_lo + M_beyond[0] * t10 + T(6) * M_beyond[2] * t0 * t1 + M_beyond[4] * t11 + T(4) * M_beyond[1] * delta_tau * t12;
    G_ab = T(6) * M_beyond[3] * t0 * t1 + M_beyond[5] * t11 + M_beyond[1] * t10 + T(4) * M_beyond[2] * delta_tau * t12 + T(4) * M_beyond[4] * t9 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / D;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = b * t14 + t16 * a_minus_b;
    const T t18 = t16 * t16;
    const T t19 = b * t14 * t15 + T(2) * t17 * t13 * a + t16 * a_minus_b * t18;
    const T t20 = t18 * t18;
    const T t21 = t15 * t15;
    const T t22 = T(4) * t19 * t13 * a + T(3) * t16 * a_minus_b * t20 + T(3) * b * t14 * t21;
    const T t23 = t1 * t1;
    const T t24 = t14 * t15 + b * t19 * t13 - t16 * t18;
    const T t25 = T(1) / a;
    const T t26 = T(3) * t16 * t20 - T(3) * t14 * t21 - b * t13 * t22;
    const T t27 = c * t13 * t22 + T(2) * b * t26 * t25 - T(5) * t19 * t13;
    const T t28 = T(5) * t24 * t25 + t26 * c * t25 - T(2) * b * t27 * t25;
    const T t29 = t0 * delta_tau;
    const T t30 = c * t19 * t13 - T(2) * b * t24 * t25 - T(3) * t17 * t13;
    const T t31 = T(5) * t30 * t25 - t27 * c * t25 - T(2) * b * t28 * t25;
    const T t32 = t0 * t0;
    const T t33 = t1 * tau_lo;
    G_ap = (T(1) / T(15)) * t13 * t22 * t23 + (T(4) / T(15)) * t28 * t25 * t29 * tau_lo - (T(1) / T(15)) * t25 * t31 * t32 - (T(4) / T(15)) * t26 * t25 * delta_tau * t33 - (T(2) / T(5)) * t27 * t25 * t0 * t1;
    G_ab = (T(1) / T(15)) * (T(5) * (T(3) * (t14 + b * t17 * t13 - t16) * t25 - T(2) * b * t30 * t25 - t24 * c * t25) * t25 - c * t28 * t25 - T(2) * b * t25 * t31) * t25 * t32 + (T(2) / T(5)) * t28 * t25 * t0 * t1 - (T(4) / T(15)) * t25 * t31 * t29 * tau_lo - (T(4) / T(15)) * t27 * t25 * delta_tau * t33 - (T(1) / T(15)) * t26 * t25 * t23;
  }
  const T g_factor = -T(5) * sigma2 * sigma2 * length * in.sigma;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
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
    X = t3 * t4 * (t5 + a_minus_b * r0);
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
    std::array<T, 12> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t1 * t1;
    F = T(4) * t13 * tau_lo * M_flat[3] + T(4) * delta_tau * t14 * M_flat[1] + t15 * M_flat[4] + t16 * M_flat[0] + T(6) * M_flat[2] * t0 * t1;
    G_ap = T(4) * M_flat[9] * t13 * tau_lo + T(6) * t0 * t1 * M_flat[8] + M_flat[6] * t16 + T(4) * delta_tau * t14 * M_flat[7] + t15 * M_flat[10];
    G_ab = t16 * M_flat[7] + T(6) * M_flat[9] * t0 * t1 + t15 * M_flat[11] + T(4) * delta_tau * t14 * M_flat[8] + T(4) * t13 * tau_lo * M_flat[10];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t17 = t0 * t0;
    const T t18 = T(1) / a;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = -b;
    const T t26 = J_downward<T>(7, a, D, t25, c, a_minus_b, q1);
    const T t27 = b * t21 * t19 + t22 * a_minus_b * t24 - T(5) * D * t26;
    const T t28 = T(3) * D * t18 * t27 + T(4) * t22 * a_minus_b * t23 + T(4) * b * t20 * t19;
    const T t29 = T(4) * t20 * t19 - T(3) * t18 * t27 * b - T(4) * t22 * t23;
    const T t30 = T(3) * t18 * t28 - T(4) * t18 * t29 * b - T(6) * t18 * t27 * c;
    const T t31 = T(8) * t22 + t18 * b * t28 - T(8) * t19;
    const T t32 = T(3) * t18 * t31 + T(2) * t18 * t29 * c + T(2) * t18 * b * t30;
    const T t33 = t1 * tau_lo;
    const T t34 = t0 * delta_tau;
    const T t35 = t1 * t1;
    F = (T(1) / T(24)) * t17 * t18 * (t18 * t30 * c + T(3) * (T(8) * J1 + t18 * t28 * c - T(2) * t18 * t31 * b) * t18 - T(2) * t18 * t32 * b) + (T(1) / T(3)) * delta_tau * t18 * t33 * t29 - (T(1) / T(6)) * t34 * t18 * t32 * tau_lo - (T(1) / T(4)) * t0 * t18 * t1 * t30 - (T(1) / T(4)) * t18 * t35 * t27;
    const T t36 = t21 * t19 + T(5) * t26 * b - t22 * t24;
    const T t37 = T(5) * t18 * t27 + T(20) * t26 * c - T(8) * t36 * t18 * b;
    const T t38 = T(5) * t18 * t29 - T(6) * t18 * t37 * b - T(12) * t36 * t18 * c;
    const T t39 = T(4) * t18 * t38 * b + T(6) * t18 * t37 * c - T(5) * t18 * t30;
    G_ap = (T(1) / T(15)) * t34 * t18 * tau_lo * t38 + t35 * t26 + (T(4) / T(5)) * t36 * delta_tau * t18 * t33 + (T(1) / T(120)) * t39 * t17 * t18 - (T(3) / T(10)) * t0 * t18 * t1 * t37;
    G_ab = (T(1) / T(5)) * t36 * t18 * t35 + (T(1) / T(30)) * t39 * t34 * t18 * tau_lo + (T(1) / T(10)) * t0 * t18 * t1 * t38 - (T(1) / T(5)) * delta_tau * t18 * t33 * t37 - (T(1) / T(120)) * t17 * t18 * (T(5) * t18 * t32 + T(2) * t18 * t38 * c - T(2) * t39 * t18 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t40 = T(1) / a;
    const T t41 = T(1) / D;
    const T t42 = T(1) / r1;
    const T t43 = T(1) / r0;
    const T t44 = t42 * a_minus_b + b * t43;
    const T t45 = t43 * t43;
    const T t46 = t42 * t42;
    const T t47 = T(2) * t41 * a * t44 + t42 * a_minus_b * t46 + b * t45 * t43;
    const T t48 = t45 * t43 + t41 * b * t47 - t42 * t46;
    const T t49 = T(3) * t41 * t44 + T(2) * t40 * t48 * b - t41 * c * t47;
    const T t50 = t1 * tau_lo;
    const T t51 = t0 * delta_tau;
    const T t52 = t41 * b * t44 + t43 - t42;
    const T t53 = T(2) * t40 * b * t49 + T(3) * t52 * t40 - t40 * t48 * c;
    const T t54 = t1 * t1;
    const T t55 = t0 * t0;
    F = T(2) * t0 * t40 * t1 * t49 + (T(4) / T(3)) * delta_tau * t40 * t50 * t48 + (T(4) / T(3)) * t51 * t40 * tau_lo * t53 + (T(1) / T(3)) * t41 * t54 * t47 + (T(1) / T(3)) * t55 * t40 * (T(3) * (J1 + T(2) * t52 * t40 * b - t41 * c * t44) * t40 + T(2) * t40 * b * t53 - t40 * t49 * c);
    const T t56 = t45 * t45;
    const T t57 = t46 * t46;
    const T t58 = T(3) * b * t56 * t43 + T(3) * t42 * a_minus_b * t57 + T(4) * t41 * a * t47;
    const T t59 = t41 * b * t58 + T(3) * t56 * t43 - T(3) * t42 * t57;
    const T t60 = T(5) * t41 * t47 + T(2) * t40 * b * t59 - t41 * c * t58;
    const T t61 = t40 * c * t59 - T(5) * t40 * t48 - T(2) * t40 * t60 * b;
    const T t62 = t40 * t60 * c + T(2) * t40 * t61 * b - T(5) * t40 * t49;
    G_ap = (T(4) / T(15)) * delta_tau * t40 * t50 * t59 + (T(1) / T(15)) * t41 * t54 * t58 + (T(2) / T(5)) * t0 * t40 * t1 * t60 - (T(4) / T(15)) * t51 * t40 * tau_lo * t61 - (T(1) / T(15)) * t55 * t40 * t62;
    G_ab = (T(4) / T(15)) * delta_tau * t40 * t50 * t60 + (T(1) / T(15)) * t40 * t54 * t59 + (T(1) / T(15)) * t55 * t40 * (T(5) * t40 * t53 + t40 * t61 * c - T(2) * t40 * t62 * b) - (T(4) / T(15)) * t51 * t40 * tau_lo * t62 - (T(2) / T(5)) * t0 * t40 * t1 * t61;
  }
  const T t63 = sigma2 * sigma2;
  const T g_factor = -T(5) * t63 * in.sigma * length;
  f = F * t63 * in.sigma * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 5, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * tau_lo;
    const T t8 = t0 * delta_tau;
    const T t9 = t1 * tau_lo;
    const T t10 = t0 * t0;
    const T t11 = t10 * delta_tau;
    F = t7 * M_flat[0] + T(10) * t8 * t1 * M_flat[3] + T(5) * M_flat[1] * delta_tau * t6 + T(10) * t0 * t9 * M_flat[2] + t11 * M_flat[5] + T(5) * M_flat[4] * t10 * tau_lo;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t12 = T(1) / a;
    const T t13 = t0 * delta_tau;
    const T t14 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t15 = T(1) / q1;
    const T t16 = t15 * t15;
    const T t17 = t2 * t2;
    const T t18 = T(4) * D * t14 - a_minus_b * t16 - b * t17;
    const T t19 = t17 + T(4) * b * t14 - t16;
    const T t20 = T(2) * t12 * t18 + T(3) * t12 * b * t19 - T(6) * c * t14;
    const T t21 = T(2) * t12 * t18 * b + T(3) * t2 - T(3) * t15;
    const T t22 = T(4) * t12 * b * t20 + T(2) * t12 * t21 - T(3) * t12 * t19 * c;
    const T t23 = t0 * t0;
    const T t24 = T(3) * b * t2 + T(3) * a_minus_b * t15 - T(2) * D * t12 * t18;
    const T t25 = t12 * b * t21 - t12 * t24 - t12 * t18 * c;
    const T t26 = t12 * b * t22 + T(2) * t12 * t25 - t12 * t20 * c;
    const T t27 = t1 * tau_lo;
    const T t28 = t1 * t1;
    const T t29 = t28 * tau_lo;
    const T t30 = t23 * delta_tau;
    F = (T(5) / T(6)) * t12 * t13 * t1 * t22 + (T(5) / T(6)) * t12 * t23 * tau_lo * t26 + (T(5) / T(3)) * t12 * t0 * t27 * t20 + (T(5) / T(4)) * t12 * delta_tau * t28 * t19 + t29 * t14 - (T(1) / T(12)) * t12 * t30 * (T(2) * t12 * (t12 * t21 * c - T(4) * t12 * t25 * b - t12 * (T(3) * log_ratio - T(2) * t12 * b * t24)) + t12 * c * t22 - T(4) * t12 * b * t26);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t31 = sqrt(D);
    const T t32 = T(1) / t31;
    const T J2 = t32 * atan2(t31, c_minus_b);
    const T t33 = T(1) / D;
    const T t34 = T(1) / q1;
    const T t35 = t34 * t34;
    const T t36 = a * J2 + b * t2 + a_minus_b * t34;
    const T t37 = t2 * t2;
    const T t38 = T(2) * a_minus_b * t35 + T(3) * t33 * a * t36 + T(2) * b * t37;
    const T t39 = t1 * t1;
    const T t40 = t39 * tau_lo;
    const T t41 = T(1) / a;
    const T t42 = T(2) * t37 + t33 * t38 * b - T(2) * t35;
    const T t43 = t0 * delta_tau;
    const T t44 = t34 - t33 * b * t36 - t2;
    const T t45 = t33 * t38 * c - T(4) * t33 * t36 - T(2) * t41 * t42 * b;
    const T t46 = t41 * t42 * c + T(4) * t41 * t44 + T(2) * t41 * b * t45;
    const T t47 = t0 * t0;
    const T t48 = T(2) * J2 - T(2) * t41 * t44 * b - t33 * t36 * c;
    const T t49 = T(2) * t41 * b * t46 - t41 * c * t45 - T(4) * t41 * t48;
    const T t50 = t47 * delta_tau;
    const T t51 = t1 * tau_lo;
    F = (T(1) / T(8)) * t33 * t38 * t40 + (T(5) / T(8)) * t41 * t42 * delta_tau * t39 - (T(5) / T(4)) * t41 * t43 * t1 * t46 - (T(5) / T(8)) * t41 * t47 * tau_lo * t49 - (T(1) / T(8)) * t41 * t50 * (T(2) * t41 * b * t49 - T(4) * t41 * (t41 * (T(2) * J2 * b + log_ratio) + T(2) * t41 * b * t48 + t41 * t44 * c) - t41 * c * t46) - (T(5) / T(4)) * t41 * t0 * t51 * t45;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -b * a_minus_b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t0 * t0;
    const T t7 = t5 * tau_lo;
    const T t8 = t1 * tau_lo;
    const T t9 = t0 * delta_tau;
    const T t10 = t6 * delta_tau;
    G_ap = T(5) * M_flat[1] * delta_tau * t5 + T(5) * M_flat[4] * t6 * tau_lo + M_flat[0] * t7 + T(10) * t0 * t8 * M_flat[2] + T(10) * t9 * t1 * M_flat[3] + t10 * M_flat[5];
    G_ab = T(10) * t0 * t8 * M_flat[3] + t10 * M_flat[6] + M_flat[1] * t7 + T(5) * t6 * tau_lo * M_flat[5] + T(5) * delta_tau * t5 * M_flat[2] + T(10) * M_flat[4] * t9 * t1;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 7> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 6, a, b, D, c, q1, M_beyond.data());
    const T t11 = t0 * t0;
    const T t12 = t0 * delta_tau;
    const T t13 = t1 * tau_lo;
    const T t14 = t1 * t1;
    const T t15 = t14 * tau_lo;
    const T t16 = t11 * delta_tau;
    G_ap = T(5) * t11 * tau_lo * M_beyond[4] + T(10) * M_beyond[3] * t12 * t1 + T(10) * t0 * t13 * M_beyond[2] + M_beyond[0] * t15 + t16 * M_beyond[5] + T(5) * delta_tau * t14 * M_beyond[1];
    G_ab = T(5) * delta_tau * t14 * M_beyond[2] + T(10) * t12 * t1 * M_beyond[4] + T(10) * M_beyond[3] * t0 * t13 + T(5) * t11 * tau_lo * M_beyond[5] + t15 * M_beyond[1] + M_beyond[6] * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = atan2(t17, c_minus_b) * t18;
    const T t19 = T(1) / q1;
    const T t20 = t19 * t19;
    const T t21 = T(1) / c;
    const T t22 = b * t21 + t19 * a_minus_b + a * J2;
    const T t23 = T(1) / D;
    const T t24 = t21 * t21;
    const T t25 = T(2) * t20 * a_minus_b + T(3) * a * t22 * t23 + T(2) * b * t24;
    const T t26 = t20 * t19;
    const T t27 = t24 * t21;
    const T t28 = T(8) * t26 * a_minus_b + T(5) * a * t25 * t23 + T(8) * b * t27;
    const T t29 = T(8) * t26 - T(8) * t27 - b * t28 * t23;
    const T t30 = T(1) / a;
    const T t31 = T(6) * t25 * t23 - t28 * c * t23 - T(2) * t29 * t30 * b;
    const T t32 = t1 * tau_lo;
    const T t33 = T(2) * t20 - T(2) * t24 - b * t25 * t23;
    const T t34 = t29 * t30 * c + T(2) * t31 * t30 * b - T(6) * t30 * t33;
    const T t35 = t0 * delta_tau;
    const T t36 = t1 * t1;
    const T t37 = t36 * tau_lo;
    const T t38 = t0 * t0;
    const T t39 = t38 * delta_tau;
    const T t40 = t25 * c * t23 + T(2) * t30 * b * t33 - T(4) * t22 * t23;
    const T t41 = t31 * t30 * c + T(6) * t30 * t40 - T(2) * t34 * t30 * b;
    const T t42 = t21 + t22 * b * t23 - t19;
    const T t43 = T(4) * t42 * t30 + t30 * c * t33 - T(2) * t30 * t40 * b;
    const T t44 = t34 * t30 * c + T(2) * t30 * b * t41 - T(6) * t30 * t43;
    G_ap = (T(5) / T(24)) * t31 * t30 * t0 * t32 + (T(5) / T(24)) * t34 * t30 * t35 * t1 + (T(1) / T(48)) * t37 * t28 * t23 - (T(1) / T(48)) * t30 * t39 * t44 - (T(5) / T(48)) * t29 * t30 * delta_tau * t36 - (T(5) / T(48)) * t30 * t38 * tau_lo * t41;
    G_ab = (T(5) / T(48)) * t31 * t30 * delta_tau * t36 + (T(1) / T(48)) * (t30 * t41 * c + T(6) * t30 * (t30 * t40 * c + T(4) * t30 * (T(2) * t42 * t30 * b + T(2) * J2 - t22 * c * t23) + T(2) * t30 * t43 * b) - T(2) * t30 * t44 * b) * t30 * t39 + (T(5) / T(24)) * t34 * t30 * t0 * t32 - (T(1) / T(48)) * t29 * t30 * t37 - (T(5) / T(24)) * t30 * t35 * t1 * t41 - (T(5) / T(48)) * t30 * t38 * t44 * tau_lo;
  }
  const T t45 = sigma2 * sigma2;
  const T t46 = t45 * sigma2;
  const T g_factor = -T(6) * t46 * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = delta_tau * ap0 + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 14> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * t0;
    const T t7 = t6 * delta_tau;
    const T t8 = t1 * t1;
    const T t9 = t8 * tau_lo;
    const T t10 = t1 * tau_lo;
    const T t11 = t0 * delta_tau;
    F = M_flat[5] * t7 + T(5) * t6 * tau_lo * M_flat[4] + t9 * M_flat[0] + T(10) * t0 * M_flat[2] * t10 + T(10) * t11 * t1 * M_flat[3] + T(5) * M_flat[1] * delta_tau * t8;
    G_ap = T(10) * t0 * t10 * M_flat[9] + t7 * M_flat[12] + t9 * M_flat[7] + T(10) * t11 * t1 * M_flat[10] + T(5) * M_flat[11] * t6 * tau_lo + T(5) * M_flat[8] * delta_tau * t8;
    G_ab = T(10) * M_flat[11] * t11 * t1 + T(5) * delta_tau * t8 * M_flat[9] + M_flat[8] * t9 + T(10) * t0 * t10 * M_flat[10] + T(5) * t6 * tau_lo * M_flat[12] + t7 * M_flat[13];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t12 = T(1) / a;
    const T t13 = t1 * t1;
    const T t14 = J_downward<T>(8, a, D, -b, c, a_minus_b, q1);
    const T t15 = T(1) / q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = t2 * t2;
    const T t19 = t18 * t2;
    const T t20 = T(6) * t14 * D - a_minus_b * t17 - t19 * b;
    const T t21 = T(4) * t12 * b * t20 + T(5) * t18 - T(5) * t16;
    const T t22 = t13 * tau_lo;
    const T t23 = t1 * tau_lo;
    const T t24 = T(4) * D * t12 * t20 - T(5) * t18 * b - T(5) * a_minus_b * t16;
    const T t25 = T(3) * t12 * b * t21 + T(2) * t24 * t12 - T(6) * c * t12 * t20;
    const T t26 = t0 * t0;
    const T t27 = t26 * delta_tau;
    const T t28 = T(15) * t15 - T(15) * t2 - T(2) * t24 * t12 * b;
    const T t29 = T(15) * a_minus_b * t15 + T(15) * t2 * b - T(2) * D * t24 * t12;
    const T t30 = t12 * b * t28 + t12 * t29 + c * t24 * t12;
    const T t31 = T(2) * t12 * t28 + T(3) * c * t12 * t21 - T(4) * t12 * t25 * b;
    const T t32 = c * t12 * t25 + T(2) * t12 * t30 + t31 * t12 * b;
    const T t33 = t0 * delta_tau;
    F = (T(1) / T(4)) * delta_tau * t12 * t13 * t21 + (T(1) / T(5)) * t12 * t22 * t20 + (T(1) / T(3)) * t0 * t12 * t23 * t25 - (T(1) / T(60)) * t27 * t12 * (T(4) * t12 * b * t32 + T(2) * t12 * (t12 * (T(2) * t12 * t29 * b - T(15) * log_ratio) + T(4) * t12 * t30 * b - c * t12 * t28) - c * t31 * t12) - (T(1) / T(6)) * t26 * t12 * tau_lo * t32 - (T(1) / T(6)) * t31 * t33 * t12 * t1;
    const T t34 = T(6) * t14 * b + t19 - t17;
    const T t35 = T(15) * c * t14 - T(5) * t34 * t12 * b - T(3) * t12 * t20;
    const T t36 = T(3) * t12 * t21 - T(8) * t35 * t12 * b - T(10) * c * t34 * t12;
    const T t37 = t12 * t25 + T(2) * c * t35 * t12 + t12 * b * t36;
    const T t38 = c * t12 * t36 + t31 * t12 - T(4) * t37 * t12 * b;
    G_ap = (T(5) / T(6)) * delta_tau * t34 * t12 * t13 + t14 * t22 + (T(1) / T(6)) * t37 * t26 * t12 * tau_lo + (T(1) / T(6)) * t33 * t12 * t1 * t36 - (T(2) / T(3)) * t35 * t0 * t12 * t23 - (T(1) / T(60)) * t38 * t27 * t12;
    G_ab = (T(1) / T(3)) * t37 * t33 * t12 * t1 + (T(1) / T(6)) * t34 * t12 * t22 + (T(1) / T(6)) * t0 * t12 * t23 * t36 - (T(1) / T(30)) * t27 * t12 * (c * t37 * t12 + t38 * t12 * b + t12 * t32) - (T(1) / T(12)) * t38 * t26 * t12 * tau_lo - (T(1) / T(3)) * t35 * delta_tau * t12 * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t39 = sqrt(D);
    const T t40 = T(1) / t39;
    const T J2 = atan2(t39, c_minus_b) * t40;
    const T t41 = t2 * t2;
    const T t42 = T(1) / q1;
    const T t43 = t42 * t42;
    const T t44 = T(1) / D;
    const T t45 = J2 * a + a_minus_b * t42 + t2 * b;
    const T t46 = T(2) * t41 * b + T(2) * a_minus_b * t43 + T(3) * t44 * a * t45;
    const T t47 = t1 * t1;
    const T t48 = t47 * tau_lo;
    const T t49 = T(1) / a;
    const T t50 = T(2) * t41 + t46 * t44 * b - T(2) * t43;
    const T t51 = t1 * tau_lo;
    const T t52 = T(2) * t49 * b * t50 + T(4) * t44 * t45 - c * t46 * t44;
    const T t53 = t0 * delta_tau;
    const T t54 = t44 * t45 * b + t2 - t42;
    const T t55 = T(2) * t49 * b * t52 + T(4) * t49 * t54 - c * t49 * t50;
    const T t56 = t0 * t0;
    const T t57 = T(2) * J2 + T(2) * t49 * b * t54 - c * t44 * t45;
    const T t58 = c * t49 * t52 - T(2) * t49 * t55 * b - T(4) * t57 * t49;
    const T t59 = t56 * delta_tau;
    F = (T(1) / T(8)) * t46 * t44 * t48 + (T(5) / T(8)) * delta_tau * t49 * t47 * t50 + (T(5) / T(4)) * t0 * t49 * t51 * t52 + (T(5) / T(4)) * t53 * t49 * t1 * t55 - (T(5) / T(8)) * t56 * t49 * tau_lo * t58 - (T(1) / T(8)) * t59 * t49 * (c * t49 * t55 + T(2) * t49 * t58 * b + T(4) * t49 * (c * t49 * t54 - T(2) * t57 * t49 * b - t49 * (log_ratio + T(2) * J2 * b)));
    const T t60 = t41 * t2;
    const T t61 = t43 * t42;
    const T t62 = T(8) * a_minus_b * t61 + T(8) * t60 * b + T(5) * t46 * t44 * a;
    const T t63 = T(8) * t60 + t62 * t44 * b - T(8) * t61;
    const T t64 = T(6) * t46 * t44 + T(2) * t49 * b * t63 - c * t62 * t44;
    const T t65 = T(6) * t49 * t50 + T(2) * t64 * t49 * b - c * t49 * t63;
    const T t66 = c * t64 * t49 - T(6) * t49 * t52 - T(2) * t49 * t65 * b;
    const T t67 = T(2) * t66 * t49 * b + c * t49 * t65 - T(6) * t49 * t55;
    G_ap = (T(5) / T(48)) * delta_tau * t49 * t47 * t63 + (T(5) / T(24)) * t64 * t0 * t49 * t51 + (T(5) / T(24)) * t53 * t49 * t65 * t1 + (T(1) / T(48)) * t62 * t44 * t48 - (T(5) / T(48)) * t66 * t56 * t49 * tau_lo - (T(1) / T(48)) * t59 * t49 * t67;
    G_ab = (T(1) / T(48)) * t49 * t48 * t63 + (T(5) / T(48)) * t64 * delta_tau * t49 * t47 + (T(5) / T(24)) * t0 * t49 * t65 * t51 - (T(5) / T(48)) * t56 * t49 * tau_lo * t67 - (T(1) / T(48)) * (T(6) * t49 * t58 + T(2) * t49 * t67 * b - c * t66 * t49) * t59 * t49 - (T(5) / T(24)) * t66 * t53 * t49 * t1;
  }
  const T t68 = sigma2 * sigma2;
  const T t69 = t68 * sigma2;
  const T g_factor = -T(6) * length * t69;
  f = length * F * t69;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = delta_tau * ap1 + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + delta_tau * ap2;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
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
    std::array<T, 7> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 6, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t13 * t13;
    const T t15 = t0 * t0;
    const T t16 = t15 * delta_tau;
    const T t17 = t1 * tau_lo;
    const T t18 = t17 * t17;
    const T t19 = t1 * t1;
    const T t20 = t19 * tau_lo;
    F = t14 * M_flat[6] + T(6) * t16 * tau_lo * M_flat[5] + T(15) * t15 * t1 * M_flat[4] + t18 * M_flat[0] + T(20) * t13 * t17 * M_flat[3] + T(15) * t0 * t19 * M_flat[2] + T(6) * delta_tau * t20 * M_flat[1];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t21 = T(1) / a;
    const T t22 = t1 * t1;
    const T t23 = t22 * tau_lo;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = J_downward<T>(7, a, D, -b, c, a_minus_b, q1);
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t24 * t26 + T(5) * t27 * b - t30 * t28;
    const T t32 = t24 * b * t26 + t30 * t28 * a_minus_b - T(5) * D * t27;
    const T t33 = T(20) * t27 * c + T(5) * t21 * t32 - T(8) * t21 * b * t31;
    const T t34 = T(4) * t29 * t28 + T(3) * t21 * b * t32 - T(4) * t24 * t25;
    const T t35 = T(12) * t21 * c * t31 + T(5) * t34 * t21 + T(6) * t21 * b * t33;
    const T t36 = T(4) * t29 * t28 * a_minus_b + T(3) * D * t21 * t32 + T(4) * t24 * b * t25;
    const T t37 = T(4) * t34 * t21 * b + T(3) * t21 * t36 - T(6) * t21 * t32 * c;
    const T t38 = T(6) * t21 * c * t33 - T(4) * t21 * t35 * b - T(5) * t21 * t37;
    const T t39 = T(8) * t24 - t21 * t36 * b - T(8) * t28;
    const T t40 = T(3) * t21 * t39 + T(2) * t34 * t21 * c - T(2) * t21 * t37 * b;
    const T t41 = T(2) * t21 * t38 * b + T(2) * t21 * t35 * c + T(5) * t21 * t40;
    const T t42 = t0 * t0;
    const T t43 = t42 * delta_tau;
    const T t44 = t1 * tau_lo;
    const T t45 = t44 * t44;
    const T t46 = t0 * delta_tau;
    const T t47 = t46 * t46;
    F = (T(6) / T(5)) * delta_tau * t21 * t23 * t31 + (T(1) / T(20)) * t41 * t43 * t21 * tau_lo + t45 * t27 + (T(1) / T(8)) * t42 * t21 * t1 * t38 + (T(1) / T(120)) * t47 * t21 * (T(2) * t41 * t21 * b + T(5) * t21 * (t21 * t37 * c + T(2) * t21 * b * t40 + T(3) * t21 * (T(8) * J1 + t21 * t36 * c + T(2) * t21 * t39 * b)) - t21 * t38 * c) - (T(1) / T(3)) * t46 * t21 * t44 * t35 - (T(3) / T(4)) * t0 * t21 * t22 * t33;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = T(1) / a;
    const T t49 = t1 * t1;
    const T t50 = t49 * tau_lo;
    const T t51 = T(1) / D;
    const T t52 = T(1) / r1;
    const T t53 = t52 * t52;
    const T t54 = T(1) / r0;
    const T t55 = t54 * t54;
    const T t56 = t52 * a_minus_b + t54 * b;
    const T t57 = t53 * t52 * a_minus_b + t54 * b * t55 + T(2) * t51 * a * t56;
    const T t58 = t55 * t55;
    const T t59 = t53 * t53;
    const T t60 = T(4) * t51 * a * t57 + T(3) * t54 * b * t58 + T(3) * t59 * t52 * a_minus_b;
    const T t61 = t51 * t60 * b + T(3) * t54 * t58 - T(3) * t59 * t52;
    const T t62 = t0 * t0;
    const T t63 = t51 * t57 * b + t54 * t55 - t53 * t52;
    const T t64 = T(5) * t51 * t57 + T(2) * t48 * t61 * b - t51 * t60 * c;
    const T t65 = T(5) * t48 * t63 + T(2) * t48 * t64 * b - t48 * t61 * c;
    const T t66 = T(3) * t51 * t56 + T(2) * t48 * b * t63 - t51 * t57 * c;
    const T t67 = T(2) * t48 * t65 * b + T(5) * t48 * t66 - t48 * t64 * c;
    const T t68 = t0 * delta_tau;
    const T t69 = t1 * tau_lo;
    const T t70 = t69 * t69;
    const T t71 = t54 + t51 * t56 * b - t52;
    const T t72 = t48 * t63 * c - T(2) * t48 * b * t66 - T(3) * t48 * t71;
    const T t73 = T(2) * t48 * b * t67 - T(5) * t48 * t72 - t48 * t65 * c;
    const T t74 = t62 * delta_tau;
    const T t75 = t68 * t68;
    F = (T(2) / T(5)) * delta_tau * t48 * t50 * t61 + t62 * t48 * t1 * t67 + (T(4) / T(3)) * t68 * t48 * t69 * t65 + (T(1) / T(15)) * t51 * t70 * t60 + (T(2) / T(5)) * t73 * t74 * t48 * tau_lo + t0 * t48 * t49 * t64 - (T(1) / T(15)) * t75 * t48 * (t48 * t67 * c + T(5) * t48 * (T(2) * t48 * b * t72 + t48 * t66 * c - T(3) * t48 * (J1 + T(2) * t48 * t71 * b - t51 * t56 * c)) - T(2) * t73 * t48 * b);
  }
  const T t76 = sigma2 * sigma2;
  const T t77 = t76 * sigma2;
  f = F * t77 * in.sigma * length;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ab2 * tau_lo + ap2 * delta_tau;
  const T D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
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
    const T t6 = t5 * tau_lo;
    const T t7 = t0 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t1 * tau_lo;
    const T t10 = t0 * t0;
    const T t11 = t10 * delta_tau;
    const T t12 = t9 * t9;
    G_ap = T(6) * M_flat[1] * delta_tau * t6 + M_flat[6] * t8 + T(20) * M_flat[3] * t7 * t9 + T(6) * t11 * tau_lo * M_flat[5] + M_flat[0] * t12 + T(15) * t10 * M_flat[4] * t1 + T(15) * t0 * t5 * M_flat[2];
    G_ab = T(6) * delta_tau * t6 * M_flat[2] + M_flat[7] * t8 + M_flat[1] * t12 + T(15) * t10 * t1 * M_flat[5] + T(20) * t7 * M_flat[4] * t9 + T(6) * M_flat[6] * t11 * tau_lo + T(15) * M_flat[3] * t0 * t5;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 7, a, b, D, c, q1, M_beyond.data());
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * tau_lo;
    const T t15 = t0 * t0;
    const T t16 = t15 * delta_tau;
    const T t17 = t1 * t1;
    const T t18 = t17 * tau_lo;
    const T t19 = t14 * t14;
    const T t20 = t13 * t13;
    G_ap = T(20) * t13 * t14 * M_beyond[3] + T(6) * M_beyond[5] * t16 * tau_lo + T(6) * delta_tau * t18 * M_beyond[1] + T(15) * t15 * t1 * M_beyond[4] + t19 * M_beyond[0] + T(15) * M_beyond[2] * t0 * t17 + t20 * M_beyond[6];
    G_ab = T(6) * t16 * tau_lo * M_beyond[6] + t20 * M_beyond[7] + T(15) * t0 * t17 * M_beyond[3] + T(15) * M_beyond[5] * t15 * t1 + T(6) * M_beyond[2] * delta_tau * t18 + T(20) * t13 * t14 * M_beyond[4] + t19 * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = t0 * t0;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = T(1) / r0;
    const T t27 = b * t26 + t24 * a_minus_b;
    const T t28 = t26 * t26;
    const T t29 = t24 * a_minus_b * t25 + T(2) * t23 * a * t27 + t28 * b * t26;
    const T t30 = t28 * t28;
    const T t31 = t25 * t25;
    const T t32 = T(4) * t23 * t29 * a + T(3) * t30 * b * t26 + T(3) * t24 * a_minus_b * t31;
    const T t33 = t23 * b * t32 + T(3) * t30 * t26 - T(3) * t24 * t31;
    const T t34 = T(2) * t21 * b * t33 + T(5) * t23 * t29 - c * t23 * t32;
    const T t35 = t30 * t28;
    const T t36 = t31 * t25;
    const T t37 = T(2) * t23 * a * t32 + T(5) * t35 * b * t26 + T(5) * t24 * a_minus_b * t36;
    const T t38 = T(5) * t24 * t36 - T(5) * t35 * t26 - t23 * t37 * b;
    const T t39 = T(3) * c * t23 * t37 + T(6) * t21 * t38 * b - T(7) * t23 * t32;
    const T t40 = T(2) * t21 * t39 * b - T(3) * c * t21 * t38 - T(7) * t21 * t33;
    const T t41 = T(7) * t21 * t34 + c * t21 * t39 - T(2) * t21 * t40 * b;
    const T t42 = t23 * t29 * b + t28 * t26 - t24 * t25;
    const T t43 = T(2) * t21 * b * t34 + T(5) * t42 * t21 - c * t21 * t33;
    const T t44 = T(7) * t21 * t43 + T(2) * t21 * t41 * b + c * t21 * t40;
    const T t45 = t22 * delta_tau;
    const T t46 = t1 * tau_lo;
    const T t47 = t46 * t46;
    const T t48 = t0 * delta_tau;
    const T t49 = T(3) * t23 * t27 + T(2) * t42 * t21 * b - c * t23 * t29;
    const T t50 = c * t21 * t34 - T(2) * t21 * t43 * b - T(5) * t49 * t21;
    const T t51 = T(7) * t21 * t50 + c * t21 * t41 - T(2) * t44 * t21 * b;
    const T t52 = t48 * t48;
    const T t53 = t1 * t1;
    const T t54 = t53 * tau_lo;
    G_ap = (T(1) / T(7)) * t21 * t22 * t41 * t1 + (T(2) / T(35)) * t44 * t21 * t45 * tau_lo + (T(1) / T(35)) * t23 * t47 * t37 - (T(4) / T(21)) * t21 * t40 * t48 * t46 - (T(1) / T(105)) * t21 * t51 * t52 - (T(1) / T(7)) * t21 * t0 * t53 * t39 - (T(6) / T(35)) * t21 * delta_tau * t54 * t38;
    G_ab = (T(4) / T(21)) * t21 * t48 * t41 * t46 + (T(1) / T(7)) * t44 * t21 * t22 * t1 - (T(1) / T(105)) * (c * t44 * t21 + T(7) * t21 * (T(2) * t21 * b * t50 + c * t21 * t43 + T(5) * t21 * (c * t42 * t21 - T(3) * (t26 + t23 * t27 * b - t24) * t21 - T(2) * t49 * t21 * b)) + T(2) * t21 * t51 * b) * t21 * t52 - (T(2) / T(35)) * t21 * delta_tau * t54 * t39 - (T(1) / T(35)) * t21 * t47 * t38 - (T(2) / T(35)) * t21 * t51 * t45 * tau_lo - (T(1) / T(7)) * t21 * t40 * t0 * t53;
  }
  const T t55 = sigma2 * sigma2;
  const T t56 = t55 * sigma2;
  const T g_factor = -T(7) * length * in.sigma * t56;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t2 = a_minus_b * b;
  if (t2 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t3 = T(1) / D;
    const T t4 = r1 * b;
    const T t5 = sqrt(a);
    X = t3 * (t4 + r0 * a_minus_b) * t5;
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
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 16> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 7, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t1 * t1;
    const T t14 = t0 * t0;
    const T t15 = t14 * delta_tau;
    const T t16 = t13 * tau_lo;
    const T t17 = t0 * delta_tau;
    const T t18 = t1 * tau_lo;
    const T t19 = t17 * t17;
    const T t20 = t18 * t18;
    F = T(15) * t0 * t13 * M_flat[2] + T(6) * t15 * tau_lo * M_flat[5] + T(6) * delta_tau * t16 * M_flat[1] + T(20) * M_flat[3] * t17 * t18 + T(15) * t14 * t1 * M_flat[4] + M_flat[6] * t19 + M_flat[0] * t20;
    G_ap = T(20) * t17 * t18 * M_flat[11] + T(15) * M_flat[12] * t14 * t1 + T(6) * M_flat[9] * delta_tau * t16 + T(15) * t0 * t13 * M_flat[10] + T(6) * t15 * tau_lo * M_flat[13] + t19 * M_flat[14] + t20 * M_flat[8];
    G_ab = T(15) * t0 * t13 * M_flat[11] + T(6) * delta_tau * t16 * M_flat[10] + M_flat[9] * t20 + T(6) * t15 * tau_lo * M_flat[14] + T(20) * M_flat[12] * t17 * t18 + T(15) * t14 * t1 * M_flat[13] + t19 * M_flat[15];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t21 = T(1) / a;
    const T t22 = t1 * t1;
    const T t23 = t22 * tau_lo;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(1) / r1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t26 * t25;
    const T t32 = -b;
    const T t33 = J_downward<T>(9, a, D, t32, c, a_minus_b, q1);
    const T t34 = t27 * a_minus_b * t30 + t24 * b * t31 - T(7) * D * t33;
    const T t35 = T(6) * t24 * t26 - T(6) * t27 * t29 - T(5) * t21 * t34 * b;
    const T t36 = T(6) * t24 * b * t26 + T(6) * t27 * a_minus_b * t29 + T(5) * D * t21 * t34;
    const T t37 = T(20) * t21 * t34 * c + T(8) * t21 * b * t35 - T(5) * t21 * t36;
    const T t38 = t0 * t0;
    const T t39 = t38 * delta_tau;
    const T t40 = D * t21 * t36 + T(8) * t24 * b * t25 + T(8) * t27 * a_minus_b * t28;
    const T t41 = t21 * t36 * b + T(8) * t27 * t28 - T(8) * t24 * t25;
    const T t42 = T(2) * t21 * t36 * c - T(3) * t21 * t40 - T(4) * t21 * t41 * b;
    const T t43 = T(16) * t27 + t21 * t40 * b - T(16) * t24;
    const T t44 = T(2) * t21 * b * t42 + T(2) * t21 * t41 * c - T(3) * t21 * t43;
    const T t45 = T(4) * t21 * c * t35 + T(5) * t21 * t41 - T(2) * t21 * b * t37;
    const T t46 = T(2) * t21 * c * t37 + T(4) * t21 * b * t45 - T(5) * t21 * t42;
    const T t47 = T(5) * t44 * t21 + T(2) * t21 * c * t45 - T(2) * t46 * t21 * b;
    const T t48 = t1 * tau_lo;
    const T t49 = t48 * t48;
    const T t50 = t0 * delta_tau;
    const T t51 = t50 * t50;
    F = (T(1) / T(5)) * t21 * delta_tau * t23 * t35 + (T(1) / T(8)) * t21 * t0 * t22 * t37 + (T(1) / T(40)) * t21 * t39 * tau_lo * t47 - (T(1) / T(16)) * t46 * t21 * t38 * t1 - (T(1) / T(6)) * t21 * t34 * t49 - (T(1) / T(6)) * t21 * t50 * t48 * t45 - (T(1) / T(240)) * t21 * t51 * (T(5) * t21 * (t21 * t42 * c + T(3) * (T(2) * t21 * t43 * b - t21 * t40 * c - T(16) * J1) * t21 - T(2) * t44 * t21 * b) - T(2) * t21 * t47 * b - t46 * t21 * c);
    const T t52 = t24 * t31 + T(7) * t33 * b - t27 * t30;
    const T t53 = T(7) * t21 * t34 + T(42) * t33 * c - T(12) * t52 * t21 * b;
    const T t54 = T(10) * t21 * t53 * b + T(30) * t52 * t21 * c - T(7) * t21 * t35;
    const T t55 = T(8) * t21 * b * t54 - T(20) * t21 * t53 * c - T(7) * t21 * t37;
    const T t56 = T(4) * t21 * t54 * c - T(7) * t21 * t45 - T(2) * t21 * t55 * b;
    const T t57 = T(7) * t46 * t21 - T(4) * t21 * b * t56 - T(2) * t21 * t55 * c;
    G_ap = (T(1) / T(140)) * t21 * t39 * tau_lo * t56 + (T(6) / T(7)) * t52 * t21 * delta_tau * t23 + t33 * t49 - (T(1) / T(1680)) * t21 * t57 * t51 - (T(2) / T(21)) * t21 * t50 * t48 * t54 - (T(1) / T(56)) * t21 * t55 * t38 * t1 - (T(5) / T(14)) * t21 * t0 * t22 * t53;
    G_ab = (T(1) / T(7)) * t52 * t21 * t49 + (T(1) / T(1680)) * t21 * t51 * (T(7) * t21 * t47 - T(2) * t21 * t57 * b - T(2) * t21 * t56 * c) + (T(1) / T(56)) * t21 * t38 * t1 * t56 - (T(1) / T(7)) * t21 * delta_tau * t23 * t53 - (T(1) / T(42)) * t21 * t55 * t50 * t48 - (T(1) / T(14)) * t21 * t0 * t22 * t54 - (T(1) / T(280)) * t21 * t57 * t39 * tau_lo;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t58 = T(1) / a;
    const T t59 = t0 * t0;
    const T t60 = T(1) / D;
    const T t61 = T(1) / r1;
    const T t62 = T(1) / r0;
    const T t63 = t61 * a_minus_b + t62 * b;
    const T t64 = t61 * t61;
    const T t65 = t62 * t62;
    const T t66 = T(2) * t60 * a * t63 + t62 * b * t65 + t61 * a_minus_b * t64;
    const T t67 = t61 * t64 - t60 * b * t66 - t62 * t65;
    const T t68 = T(3) * t60 * t63 - T(2) * t58 * b * t67 - t60 * t66 * c;
    const T t69 = t65 * t65;
    const T t70 = t64 * t64;
    const T t71 = T(3) * t62 * b * t69 + T(3) * t61 * a_minus_b * t70 + T(4) * t60 * a * t66;
    const T t72 = T(3) * t62 * t69 + t60 * t71 * b - T(3) * t61 * t70;
    const T t73 = t60 * t71 * c - T(5) * t60 * t66 - T(2) * t58 * t72 * b;
    const T t74 = t58 * t72 * c + T(2) * t58 * t73 * b + T(5) * t58 * t67;
    const T t75 = T(5) * t58 * t68 + t58 * t73 * c - T(2) * t58 * b * t74;
    const T t76 = t1 * t1;
    const T t77 = t76 * tau_lo;
    const T t78 = t59 * delta_tau;
    const T t79 = t61 - t60 * b * t63 - t62;
    const T t80 = T(2) * t58 * b * t68 + t58 * t67 * c - T(3) * t58 * t79;
    const T t81 = t58 * t74 * c + T(5) * t58 * t80 + T(2) * t58 * b * t75;
    const T t82 = t1 * tau_lo;
    const T t83 = t82 * t82;
    const T t84 = t0 * delta_tau;
    const T t85 = t84 * t84;
    F = t58 * t59 * t1 * t75 + (T(2) / T(5)) * t58 * delta_tau * t77 * t72 + (T(2) / T(5)) * t58 * t78 * tau_lo * t81 + (T(1) / T(15)) * t60 * t83 * t71 - (T(1) / T(15)) * t58 * (T(5) * t58 * (T(3) * (T(2) * t58 * b * t79 + t60 * t63 * c - J1) * t58 + t58 * t68 * c - T(2) * t58 * b * t80) + t58 * c * t75 - T(2) * t58 * b * t81) * t85 - (T(4) / T(3)) * t58 * t84 * t82 * t74 - t58 * t0 * t76 * t73;
    const T t86 = t70 * t64;
    const T t87 = t69 * t65;
    const T t88 = T(5) * t61 * a_minus_b * t86 + T(5) * t62 * b * t87 + T(2) * t60 * a * t71;
    const T t89 = T(5) * t62 * t87 + t60 * b * t88 - T(5) * t61 * t86;
    const T t90 = T(6) * t89 * t58 * b + T(7) * t60 * t71 - T(3) * t60 * t88 * c;
    const T t91 = T(2) * t58 * t90 * b + T(7) * t58 * t72 - T(3) * t89 * t58 * c;
    const T t92 = T(2) * t58 * b * t91 - T(7) * t58 * t73 - t58 * t90 * c;
    const T t93 = T(7) * t58 * t74 + t58 * t91 * c - T(2) * t58 * t92 * b;
    const T t94 = T(2) * t58 * t93 * b + t58 * t92 * c - T(7) * t58 * t75;
    G_ap = (T(1) / T(35)) * t60 * t83 * t88 + (T(4) / T(21)) * t58 * t84 * t82 * t91 + (T(1) / T(7)) * t58 * t0 * t76 * t90 + (T(6) / T(35)) * t89 * t58 * delta_tau * t77 + (T(1) / T(7)) * t58 * t92 * t59 * t1 - (T(1) / T(105)) * t58 * t85 * t94 - (T(2) / T(35)) * t58 * t78 * t93 * tau_lo;
    G_ab = (T(1) / T(7)) * t58 * t0 * t76 * t91 + (T(4) / T(21)) * t58 * t92 * t84 * t82 + (T(1) / T(35)) * t89 * t58 * t83 + (T(2) / T(35)) * t58 * delta_tau * t77 * t90 - (T(2) / T(35)) * t58 * t78 * tau_lo * t94 - (T(1) / T(105)) * t58 * t85 * (T(2) * t58 * b * t94 - t58 * t93 * c - T(7) * t58 * t81) - (T(1) / T(7)) * t58 * t59 * t93 * t1;
  }
  const T t95 = sigma2 * sigma2;
  const T t96 = t95 * sigma2;
  const T g_factor = -T(7) * t96 * length * in.sigma;
  f = F * t96 * length * in.sigma;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ap0 * delta_tau + tau_lo * ab0;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = tau_lo * tau_hi * sigma2 + ap_bp;
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
    const T t6 = t1 * t1;
    const T t7 = t6 * tau_lo;
    const T t8 = t1 * tau_lo;
    const T t9 = t0 * t0;
    const T t10 = t8 * t8;
    const T t11 = t0 * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t12 * delta_tau;
    const T t14 = t10 * tau_lo;
    const T t15 = t9 * delta_tau;
    F = T(21) * t7 * t0 * M_flat[2] + T(35) * M_flat[4] * t8 * t9 + T(7) * t10 * M_flat[1] * delta_tau + M_flat[7] * t13 + T(35) * t6 * t11 * M_flat[3] + t14 * M_flat[0] + T(7) * tau_lo * t12 * M_flat[6] + T(21) * t1 * t15 * M_flat[5];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t16 = T(1) / a;
    const T t17 = t1 * tau_lo;
    const T t18 = t0 * t0;
    const T t19 = T(1) / q1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t2 * t2;
    const T t23 = t22 * t2;
    const T t24 = J_downward<T>(8, a, D, -b, c, a_minus_b, q1);
    const T t25 = t21 * a_minus_b + b * t23 - T(6) * D * t24;
    const T t26 = T(5) * t20 * a_minus_b + T(4) * D * t16 * t25 + T(5) * b * t22;
    const T t27 = T(5) * t20 + T(4) * t16 * b * t25 - T(5) * t22;
    const T t28 = T(6) * t16 * c * t25 - T(2) * t26 * t16 - T(3) * t16 * t27 * b;
    const T t29 = T(6) * t24 * b + t23 - t21;
    const T t30 = T(3) * t16 * t25 + T(15) * t24 * c - T(5) * t16 * b * t29;
    const T t31 = T(3) * t16 * t27 + T(8) * t16 * b * t30 + T(10) * t16 * t29 * c;
    const T t32 = t16 * t28 + T(2) * t16 * t30 * c - t16 * b * t31;
    const T t33 = t17 * t17;
    const T t34 = t33 * tau_lo;
    const T t35 = t0 * delta_tau;
    const T t36 = t35 * t35;
    const T t37 = T(15) * t2 - T(2) * t26 * t16 * b - T(15) * t19;
    const T t38 = T(15) * b * t2 + T(2) * D * t26 * t16 + T(15) * t19 * a_minus_b;
    const T t39 = t26 * t16 * c + t16 * t37 * b - t16 * t38;
    const T t40 = T(3) * t16 * t27 * c + T(2) * t16 * t37 + T(4) * t16 * t28 * b;
    const T t41 = T(2) * t16 * t39 + t16 * b * t40 - t16 * t28 * c;
    const T t42 = t16 * c * t31 + T(4) * t16 * b * t32 + t16 * t40;
    const T t43 = t16 * t41 + t16 * b * t42 - t16 * t32 * c;
    const T t44 = t18 * delta_tau;
    const T t45 = t36 * delta_tau;
    const T t46 = t1 * t1;
    const T t47 = t46 * tau_lo;
    F = (T(7) / T(6)) * t16 * t17 * t18 * t32 + t34 * t24 + (T(7) / T(6)) * t16 * t33 * delta_tau * t29 + (T(7) / T(30)) * t16 * tau_lo * t36 * t43 + (T(7) / T(20)) * t16 * t1 * t44 * t42 - (T(1) / T(60)) * t16 * t45 * ((t16 * c * t40 + T(2) * t16 * (t16 * t37 * c + t16 * (T(2) * t16 * b * t38 - T(15) * log_ratio) - T(4) * t16 * b * t39) - T(4) * t16 * t41 * b) * t16 + t16 * t42 * c - T(4) * t16 * t43 * b) - (T(7) / T(5)) * t16 * t47 * t0 * t30 - (T(7) / T(12)) * t16 * t46 * t35 * t31;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t48 = sqrt(D);
    const T t49 = T(1) / t48;
    const T J2 = t49 * atan2(t48, c_minus_b);
    const T t50 = T(1) / D;
    const T t51 = t1 * tau_lo;
    const T t52 = t51 * t51;
    const T t53 = t52 * tau_lo;
    const T t54 = T(1) / q1;
    const T t55 = t54 * t54;
    const T t56 = t55 * t54;
    const T t57 = b * t2 + a * J2 + t54 * a_minus_b;
    const T t58 = t2 * t2;
    const T t59 = T(2) * t55 * a_minus_b + T(3) * t50 * a * t57 + T(2) * b * t58;
    const T t60 = t58 * t2;
    const T t61 = T(8) * t56 * a_minus_b + T(5) * t50 * a * t59 + T(8) * b * t60;
    const T t62 = T(1) / a;
    const T t63 = t1 * t1;
    const T t64 = t63 * tau_lo;
    const T t65 = t50 * t61 * b + T(8) * t60 - T(8) * t56;
    const T t66 = T(6) * t50 * t59 + T(2) * t62 * t65 * b - t50 * t61 * c;
    const T t67 = t0 * delta_tau;
    const T t68 = t67 * t67;
    const T t69 = T(2) * t55 - t50 * t59 * b - T(2) * t58;
    const T t70 = t50 * t59 * c + T(2) * t62 * b * t69 - T(4) * t50 * t57;
    const T t71 = T(6) * t62 * t69 + t62 * t65 * c - T(2) * t62 * b * t66;
    const T t72 = T(6) * t70 * t62 + T(2) * t62 * b * t71 + t62 * t66 * c;
    const T t73 = t2 + t50 * b * t57 - t54;
    const T t74 = T(2) * t70 * t62 * b - T(4) * t73 * t62 - t62 * t69 * c;
    const T t75 = t62 * c * t71 - T(2) * t72 * t62 * b - T(6) * t62 * t74;
    const T t76 = T(2) * t73 * t62 * b + T(2) * J2 - t50 * t57 * c;
    const T t77 = T(2) * t62 * b * t74 - T(4) * t62 * t76 - t70 * t62 * c;
    const T t78 = t72 * t62 * c + T(2) * t75 * t62 * b - T(6) * t62 * t77;
    const T t79 = t0 * t0;
    const T t80 = t79 * delta_tau;
    const T t81 = t68 * delta_tau;
    F = (T(1) / T(48)) * t50 * t53 * t61 + (T(7) / T(16)) * t62 * t64 * t0 * t66 + (T(7) / T(48)) * t62 * t52 * delta_tau * t65 + (T(7) / T(48)) * t62 * tau_lo * t68 * t78 + (T(7) / T(16)) * t75 * t62 * t1 * t80 - (T(35) / T(48)) * t72 * t62 * t51 * t79 - (T(1) / T(48)) * t62 * (t75 * t62 * c + T(6) * t62 * (T(2) * t62 * b * t77 - t62 * t74 * c - T(4) * t62 * (T(2) * t62 * b * t76 + (T(2) * J2 * b + log_ratio) * t62 - t73 * t62 * c)) - T(2) * t62 * t78 * b) * t81 - (T(35) / T(48)) * t62 * t63 * t67 * t71;
  }
  const T t82 = sigma2 * sigma2;
  const T t83 = t82 * t82;
  f = F * t83 * length;
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
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 9> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 8, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * tau_lo;
    const T t7 = t0 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t1 * tau_lo;
    const T t10 = t0 * t0;
    const T t11 = t9 * t9;
    const T t12 = t11 * tau_lo;
    const T t13 = t10 * delta_tau;
    const T t14 = t8 * delta_tau;
    G_ap = T(21) * t6 * t0 * M_flat[2] + T(7) * M_flat[6] * tau_lo * t8 + T(35) * t9 * t10 * M_flat[4] + T(35) * M_flat[3] * t5 * t7 + T(7) * t11 * delta_tau * M_flat[1] + t12 * M_flat[0] + T(21) * t1 * t13 * M_flat[5] + t14 * M_flat[7];
    G_ab = T(7) * t11 * delta_tau * M_flat[2] + T(35) * t9 * t10 * M_flat[5] + T(7) * tau_lo * t8 * M_flat[7] + T(35) * t5 * t7 * M_flat[4] + T(21) * M_flat[3] * t6 * t0 + t14 * M_flat[8] + T(21) * M_flat[6] * t1 * t13 + t12 * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 9> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 8, a, b, D, c, q1, M_beyond.data());
    const T t15 = t1 * tau_lo;
    const T t16 = t0 * t0;
    const T t17 = t15 * t15;
    const T t18 = t17 * tau_lo;
    const T t19 = t1 * t1;
    const T t20 = t0 * delta_tau;
    const T t21 = t16 * delta_tau;
    const T t22 = t20 * t20;
    const T t23 = t22 * delta_tau;
    const T t24 = t19 * tau_lo;
    G_ap = T(35) * t15 * t16 * M_beyond[4] + M_beyond[0] * t18 + T(35) * M_beyond[3] * t19 * t20 + T(21) * t1 * t21 * M_beyond[5] + T(7) * tau_lo * t22 * M_beyond[6] + T(7) * t17 * delta_tau * M_beyond[1] + t23 * M_beyond[7] + T(21) * t24 * t0 * M_beyond[2];
    G_ab = T(7) * tau_lo * t22 * M_beyond[7] + t18 * M_beyond[1] + T(35) * t19 * t20 * M_beyond[4] + t23 * M_beyond[8] + T(21) * M_beyond[3] * t24 * t0 + T(21) * t1 * t21 * M_beyond[6] + T(7) * t17 * delta_tau * M_beyond[2] + T(35) * t15 * t16 * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(D);
    const T t26 = T(1) / t25;
    const T J2 = t26 * atan2(t25, c_minus_b);
    const T t27 = T(1) / a;
    const T t28 = t1 * tau_lo;
    const T t29 = t28 * t28;
    const T t30 = T(1) / D;
    const T t31 = T(1) / c;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t32 * t31;
    const T t35 = T(1) / q1;
    const T t36 = a_minus_b * t35 + b * t31 + a * J2;
    const T t37 = t35 * t35;
    const T t38 = T(2) * b * t32 + T(3) * t30 * t36 * a + T(2) * a_minus_b * t37;
    const T t39 = t37 * t35;
    const T t40 = T(8) * b * t34 + T(5) * t30 * a * t38 + T(8) * a_minus_b * t39;
    const T t41 = t37 * t37;
    const T t42 = T(48) * b * t33 + T(7) * t30 * a * t40 + T(48) * a_minus_b * t41;
    const T t43 = t30 * t42 * b + T(48) * t33 - T(48) * t41;
    const T t44 = t0 * delta_tau;
    const T t45 = t44 * t44;
    const T t46 = t30 * b * t38 + T(2) * t32 - T(2) * t37;
    const T t47 = t30 * b * t40 + T(8) * t34 - T(8) * t39;
    const T t48 = T(2) * t27 * b * t47 + T(6) * t30 * t38 - t30 * c * t40;
    const T t49 = T(6) * t27 * t46 + T(2) * t48 * t27 * b - t27 * c * t47;
    const T t50 = t30 * t42 * c - T(8) * t30 * t40 - T(2) * t27 * t43 * b;
    const T t51 = T(2) * t27 * b * t50 + t27 * t43 * c - T(8) * t27 * t47;
    const T t52 = t27 * t50 * c + T(8) * t48 * t27 - T(2) * t51 * t27 * b;
    const T t53 = T(8) * t49 * t27 + T(2) * t27 * t52 * b + t51 * t27 * c;
    const T t54 = t30 * t38 * c - T(2) * t27 * b * t46 - T(4) * t30 * t36;
    const T t55 = T(6) * t27 * t54 + t48 * t27 * c - T(2) * t49 * t27 * b;
    const T t56 = T(2) * t27 * b * t53 - t27 * t52 * c - T(8) * t27 * t55;
    const T t57 = t29 * tau_lo;
    const T t58 = t0 * t0;
    const T t59 = t58 * delta_tau;
    const T t60 = t31 + t30 * t36 * b - t35;
    const T t61 = t27 * t46 * c + T(2) * t27 * t54 * b - T(4) * t27 * t60;
    const T t62 = T(6) * t27 * t61 + T(2) * t27 * t55 * b + t49 * t27 * c;
    const T t63 = T(8) * t62 * t27 + t27 * c * t53 - T(2) * t27 * b * t56;
    const T t64 = t45 * delta_tau;
    const T t65 = t1 * t1;
    const T t66 = t65 * tau_lo;
    G_ap = (T(7) / T(384)) * t27 * t29 * delta_tau * t43 + (T(7) / T(384)) * t27 * tau_lo * t45 * t56 + (T(1) / T(384)) * t30 * t42 * t57 + (T(35) / T(384)) * t27 * t28 * t58 * t52 + (T(7) / T(128)) * t27 * t1 * t59 * t53 - (T(1) / T(384)) * t27 * t63 * t64 - (T(35) / T(384)) * t51 * t27 * t65 * t44 - (T(7) / T(128)) * t27 * t66 * t0 * t50;
    G_ab = (T(1) / T(384)) * (T(8) * t27 * (t27 * t55 * c + T(6) * t27 * (T(4) * t27 * (T(2) * t27 * t60 * b + T(2) * J2 - t30 * t36 * c) + t27 * t54 * c - T(2) * t27 * t61 * b) - T(2) * t62 * t27 * b) - t27 * c * t56 - T(2) * t27 * t63 * b) * t27 * t64 + (T(1) / T(384)) * t27 * t57 * t43 + (T(35) / T(384)) * t27 * t65 * t44 * t52 + (T(35) / T(384)) * t27 * t28 * t58 * t53 + (T(7) / T(128)) * t27 * t1 * t59 * t56 - (T(7) / T(128)) * t51 * t27 * t66 * t0 - (T(7) / T(384)) * t27 * tau_lo * t63 * t45 - (T(7) / T(384)) * t27 * t29 * delta_tau * t50;
  }
  const T t67 = sigma2 * sigma2;
  const T t68 = t67 * t67;
  const T g_factor = -T(8) * t68 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + sigma2 * t0;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ap0 * delta_tau + ab0 * tau_lo;
  const T radial1 = ab1 * tau_lo + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = sigma2 * (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) + cross_cross;
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  const T c_minus_b = ap_bp + tau_hi * sigma2 * tau_lo;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  T G_ap;
  T G_ab;
  const T t3 = D - T(2) * a * a;
  const T t4 = -b * a_minus_b;
  const T t5 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 18> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 8, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * tau_lo;
    const T t7 = t0 * t0;
    const T t8 = t7 * delta_tau;
    const T t9 = t0 * delta_tau;
    const T t10 = t9 * t9;
    const T t11 = t6 * t6;
    const T t12 = t1 * t1;
    const T t13 = t11 * tau_lo;
    const T t14 = t10 * delta_tau;
    const T t15 = t12 * tau_lo;
    F = T(35) * t6 * t7 * M_flat[4] + T(21) * M_flat[5] * t1 * t8 + T(7) * M_flat[6] * tau_lo * t10 + T(7) * M_flat[1] * t11 * delta_tau + T(35) * M_flat[3] * t12 * t9 + M_flat[0] * t13 + M_flat[7] * t14 + T(21) * M_flat[2] * t15 * t0;
    G_ap = T(35) * M_flat[13] * t6 * t7 + T(21) * M_flat[11] * t15 * t0 + T(7) * t11 * delta_tau * M_flat[10] + T(21) * M_flat[14] * t1 * t8 + M_flat[16] * t14 + T(7) * M_flat[15] * tau_lo * t10 + T(35) * M_flat[12] * t12 * t9 + M_flat[9] * t13;
    G_ab = T(35) * M_flat[13] * t12 * t9 + M_flat[17] * t14 + T(7) * M_flat[11] * t11 * delta_tau + t13 * M_flat[10] + T(35) * M_flat[14] * t6 * t7 + T(21) * M_flat[12] * t15 * t0 + T(21) * M_flat[15] * t1 * t8 + T(7) * M_flat[16] * tau_lo * t10;
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t16 = t2 * t2;
    const T t17 = t16 * t2;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(1) / a;
    const T t22 = t16 * t16;
    const T t23 = t19 * t19;
    const T t24 = J_downward<T>(10, a, D, -b, c, a_minus_b, q1);
    const T t25 = b * t22 + a_minus_b * t23 - T(8) * t24 * D;
    const T t26 = T(7) * b * t17 + T(7) * a_minus_b * t20 + T(6) * D * t21 * t25;
    const T t27 = T(4) * b * t26 * t21 + T(35) * t19 - T(35) * t16;
    const T t28 = T(6) * b * t21 * t25 + T(7) * t20 - T(7) * t17;
    const T t29 = T(3) * t26 * t21 + T(5) * b * t28 * t21 - T(15) * c * t21 * t25;
    const T t30 = T(3) * t27 * t21 + T(8) * t29 * b * t21 - T(10) * t28 * c * t21;
    const T t31 = T(35) * b * t16 + T(35) * a_minus_b * t19 + T(4) * D * t26 * t21;
    const T t32 = T(3) * b * t27 * t21 + T(2) * t31 * t21 - T(6) * c * t26 * t21;
    const T t33 = T(105) * t2 - T(105) * t18 - T(2) * t31 * b * t21;
    const T t34 = T(4) * b * t21 * t32 - T(2) * t33 * t21 - T(3) * t27 * c * t21;
    const T t35 = t21 * t32 + b * t30 * t21 - T(2) * t29 * c * t21;
    const T t36 = c * t30 * t21 - t21 * t34 - T(4) * b * t35 * t21;
    const T t37 = t0 * t0;
    const T t38 = t37 * delta_tau;
    const T t39 = t1 * t1;
    const T t40 = t0 * delta_tau;
    const T t41 = T(105) * a_minus_b * t18 + T(105) * b * t2 + T(2) * t31 * D * t21;
    const T t42 = b * t33 * t21 + t31 * c * t21 - t41 * t21;
    const T t43 = b * t21 * t34 - T(2) * t42 * t21 - c * t21 * t32;
    const T t44 = t43 * t21 - b * t36 * t21 - c * t35 * t21;
    const T t45 = t40 * t40;
    const T t46 = t45 * delta_tau;
    const T t47 = t1 * tau_lo;
    const T t48 = t47 * t47;
    const T t49 = t39 * tau_lo;
    const T t50 = t48 * tau_lo;
    F = (T(1) / T(20)) * t36 * t21 * t1 * t38 - (T(1) / T(12)) * t30 * t21 * t39 * t40 - (T(1) / T(420)) * (T(4) * b * t44 * t21 + t36 * c * t21 + (T(4) * b * t43 * t21 + T(2) * (t33 * c * t21 - T(4) * b * t42 * t21 - (T(105) * log_ratio - T(2) * b * t41 * t21) * t21) * t21 - c * t21 * t34) * t21) * t21 * t46 - (T(1) / T(6)) * t28 * t21 * t48 * delta_tau - (T(1) / T(5)) * t29 * t21 * t49 * t0 - (T(1) / T(30)) * t44 * t21 * tau_lo * t45 - (T(1) / T(7)) * t21 * t50 * t25 - (T(1) / T(6)) * t35 * t21 * t47 * t37;
    const T t51 = T(8) * t24 * b + t22 - t23;
    const T t52 = T(4) * t21 * t25 + T(28) * t24 * c - T(7) * b * t21 * t51;
    const T t53 = T(12) * b * t52 * t21 + T(4) * t28 * t21 + T(21) * c * t21 * t51;
    const T t54 = T(4) * t29 * t21 + T(5) * b * t53 * t21 - T(15) * c * t52 * t21;
    const T t55 = T(4) * b * t21 * t54 + T(2) * t30 * t21 - T(5) * t53 * c * t21;
    const T t56 = b * t21 * t55 + T(2) * t35 * t21 - c * t21 * t54;
    const T t57 = c * t21 * t55 + T(2) * t36 * t21 - T(4) * b * t56 * t21;
    G_ap = (T(1) / T(840)) * t57 * t21 * t46 + t24 * t50 + (T(7) / T(8)) * t21 * t48 * t51 * delta_tau - (T(1) / T(40)) * t21 * t1 * t38 * t55 - (T(5) / T(24)) * t53 * t21 * t39 * t40 - (T(3) / T(4)) * t52 * t21 * t49 * t0 - (T(1) / T(60)) * t56 * t21 * tau_lo * t45 - (T(1) / T(12)) * t21 * t47 * t37 * t54;
    G_ab = (T(1) / T(8)) * t21 * t50 * t51 + (T(1) / T(120)) * t57 * t21 * tau_lo * t45 - (T(1) / T(420)) * t21 * (T(2) * t44 * t21 - c * t56 * t21 - b * t57 * t21) * t46 - (T(1) / T(4)) * t52 * t21 * t48 * delta_tau - (T(1) / T(8)) * t53 * t21 * t49 * t0 - (T(1) / T(20)) * t56 * t21 * t1 * t38 - (T(1) / T(12)) * t21 * t39 * t40 * t54 - (T(1) / T(24)) * t21 * t47 * t37 * t55;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t58 = sqrt(D);
    const T t59 = T(1) / t58;
    const T J2 = atan2(t58, c_minus_b) * t59;
    const T t60 = t2 * t2;
    const T t61 = T(1) / q1;
    const T t62 = t61 * t61;
    const T t63 = T(1) / D;
    const T t64 = J2 * a + a_minus_b * t61 + b * t2;
    const T t65 = T(2) * b * t60 + T(2) * a_minus_b * t62 + T(3) * t63 * t64 * a;
    const T t66 = b * t65 * t63 + T(2) * t60 - T(2) * t62;
    const T t67 = T(1) / a;
    const T t68 = t60 * t2;
    const T t69 = t62 * t61;
    const T t70 = T(5) * t65 * t63 * a + T(8) * b * t68 + T(8) * a_minus_b * t69;
    const T t71 = b * t70 * t63 + T(8) * t68 - T(8) * t69;
    const T t72 = T(6) * t65 * t63 + T(2) * t71 * b * t67 - t70 * c * t63;
    const T t73 = T(6) * t66 * t67 + T(2) * b * t72 * t67 - t71 * c * t67;
    const T t74 = T(4) * t63 * t64 + T(2) * t66 * b * t67 - c * t65 * t63;
    const T t75 = T(2) * b * t73 * t67 + T(6) * t74 * t67 - t72 * c * t67;
    const T t76 = t1 * tau_lo;
    const T t77 = t0 * t0;
    const T t78 = t1 * t1;
    const T t79 = t78 * tau_lo;
    const T t80 = t76 * t76;
    const T t81 = t0 * delta_tau;
    const T t82 = t80 * tau_lo;
    const T t83 = b * t63 * t64 + t2 - t61;
    const T t84 = T(2) * b * t74 * t67 + T(4) * t83 * t67 - t66 * c * t67;
    const T t85 = T(6) * t84 * t67 + T(2) * b * t75 * t67 - c * t73 * t67;
    const T t86 = t77 * delta_tau;
    const T t87 = T(2) * b * t83 * t67 + T(2) * J2 - c * t63 * t64;
    const T t88 = c * t74 * t67 - T(2) * t84 * b * t67 - T(4) * t87 * t67;
    const T t89 = t75 * c * t67 + T(6) * t88 * t67 - T(2) * t85 * b * t67;
    const T t90 = t81 * t81;
    const T t91 = t90 * delta_tau;
    F = (T(35) / T(48)) * t75 * t67 * t76 * t77 + (T(7) / T(16)) * t72 * t67 * t79 * t0 + (T(7) / T(48)) * t71 * t67 * t80 * delta_tau + (T(35) / T(48)) * t73 * t67 * t78 * t81 + (T(1) / T(48)) * t70 * t63 * t82 + (T(7) / T(16)) * t85 * t67 * t1 * t86 - (T(1) / T(48)) * (t85 * c * t67 + T(2) * b * t89 * t67 - T(6) * (T(4) * ((log_ratio + T(2) * J2 * b) * t67 + T(2) * b * t87 * t67 - t83 * c * t67) * t67 - t84 * c * t67 - T(2) * b * t88 * t67) * t67) * t67 * t91 - (T(7) / T(48)) * t89 * t67 * tau_lo * t90;
    const T t92 = t62 * t62;
    const T t93 = t60 * t60;
    const T t94 = T(48) * b * t93 + T(7) * t70 * t63 * a + T(48) * a_minus_b * t92;
    const T t95 = T(48) * t92 - b * t94 * t63 - T(48) * t93;
    const T t96 = T(2) * b * t95 * t67 + t94 * c * t63 - T(8) * t70 * t63;
    const T t97 = T(2) * b * t96 * t67 - T(8) * t71 * t67 - c * t95 * t67;
    const T t98 = T(8) * t72 * t67 + c * t96 * t67 - T(2) * b * t97 * t67;
    const T t99 = T(2) * b * t98 * t67 + T(8) * t73 * t67 + t97 * c * t67;
    const T t100 = T(2) * b * t99 * t67 + T(8) * t75 * t67 - c * t98 * t67;
    const T t101 = T(8) * t85 * t67 + T(2) * t100 * b * t67 - t99 * c * t67;
    G_ap = (T(1) / T(384)) * t101 * t67 * t91 + (T(7) / T(384)) * t100 * t67 * tau_lo * t90 + (T(1) / T(384)) * t94 * t63 * t82 + (T(35) / T(384)) * t98 * t67 * t76 * t77 + (T(7) / T(128)) * t99 * t67 * t1 * t86 - (T(7) / T(384)) * t95 * t67 * t80 * delta_tau - (T(7) / T(128)) * t96 * t67 * t79 * t0 - (T(35) / T(384)) * t97 * t67 * t78 * t81;
    G_ab = (T(35) / T(384)) * t99 * t67 * t76 * t77 + (T(7) / T(384)) * t101 * t67 * tau_lo * t90 + (T(35) / T(384)) * t98 * t67 * t78 * t81 + (T(7) / T(128)) * t100 * t67 * t1 * t86 - (T(1) / T(384)) * t95 * t67 * t82 - (T(7) / T(384)) * t96 * t67 * t80 * delta_tau - (T(7) / T(128)) * t97 * t67 * t79 * t0 - (T(1) / T(384)) * (t100 * c * t67 + T(8) * t89 * t67 - T(2) * b * t101 * t67) * t67 * t91;
  }
  const T t102 = sigma2 * sigma2;
  const T t103 = t102 * t102;
  const T g_factor = -T(8) * t103 * length;
  f = F * t103 * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = ab0 * tau_lo + delta_tau * ap0;
  const T radial1 = tau_lo * ab1 + ap1 * delta_tau;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
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
    X = (b - a_minus_b) * t6 / (t7 - r0 * a_minus_b);
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
    const T t13 = t0 * delta_tau;
    const T t14 = t1 * t1;
    const T t15 = t14 * tau_lo;
    const T t16 = t0 * t0;
    const T t17 = t14 * t14;
    const T t18 = t1 * tau_lo;
    const T t19 = t18 * t18;
    const T t20 = t16 * t16;
    const T t21 = t19 * tau_lo;
    const T t22 = t13 * t13;
    const T t23 = t22 * delta_tau;
    const T t24 = t16 * delta_tau;
    F = T(56) * t13 * t15 * M_flat[3] + T(70) * M_flat[4] * t16 * t14 + t17 * M_flat[0] + T(28) * t0 * t19 * M_flat[2] + M_flat[8] * t20 + T(8) * M_flat[1] * delta_tau * t21 + T(28) * t22 * t1 * M_flat[6] + T(8) * t23 * tau_lo * M_flat[7] + T(56) * t24 * M_flat[5] * t18;
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t25 = t0 * t0;
    const T t26 = T(1) / a;
    const T t27 = t1 * t1;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(1) / r0;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = t34 * t33;
    const T t36 = J_downward<T>(9, a, D, -b, c, a_minus_b, q1);
    const T t37 = t31 * a_minus_b * t28 + t32 * b * t35 - T(7) * t36 * D;
    const T t38 = T(7) * t36 * b + t32 * t35 - t31 * t28;
    const T t39 = T(7) * t26 * t37 + T(42) * t36 * c - T(12) * t38 * t26 * b;
    const T t40 = T(5) * t26 * t37 * b + T(6) * t30 * t28 - T(6) * t32 * t34;
    const T t41 = T(6) * t32 * b * t34 + T(6) * t30 * a_minus_b * t28 + T(5) * D * t26 * t37;
    const T t42 = T(20) * t26 * t37 * c - T(8) * t26 * b * t40 - T(5) * t26 * t41;
    const T t43 = T(7) * t26 * t40 + T(30) * t38 * t26 * c + T(10) * t26 * t39 * b;
    const T t44 = T(20) * t26 * t39 * c + T(7) * t26 * t42 - T(8) * t26 * b * t43;
    const T t45 = t25 * delta_tau;
    const T t46 = t1 * tau_lo;
    const T t47 = T(8) * t32 * t33 - T(8) * t29 * t28 - t26 * t41 * b;
    const T t48 = T(5) * t26 * t47 + T(2) * t26 * b * t42 + T(4) * t26 * c * t40;
    const T t49 = T(2) * t26 * b * t44 + T(4) * t26 * t43 * c + T(7) * t26 * t48;
    const T t50 = t0 * delta_tau;
    const T t51 = t50 * t50;
    const T t52 = D * t26 * t41 + T(8) * t32 * b * t33 + T(8) * t29 * a_minus_b * t28;
    const T t53 = T(2) * t26 * t41 * c + T(4) * t26 * b * t47 - T(3) * t26 * t52;
    const T t54 = T(4) * t26 * b * t48 + T(5) * t26 * t53 - T(2) * t26 * t42 * c;
    const T t55 = T(7) * t54 * t26 + T(4) * t26 * t49 * b - T(2) * t26 * t44 * c;
    const T t56 = t27 * t27;
    const T t57 = t46 * t46;
    const T t58 = t57 * tau_lo;
    const T t59 = T(16) * t28 + t26 * b * t52 - T(16) * t32;
    const T t60 = T(3) * t26 * t59 + T(2) * t26 * c * t47 - T(2) * t26 * b * t53;
    const T t61 = T(5) * t26 * t60 + T(2) * t26 * t48 * c - T(2) * t54 * t26 * b;
    const T t62 = T(7) * t61 * t26 + T(2) * t26 * t49 * c - T(2) * t26 * t55 * b;
    const T t63 = t25 * t25;
    const T t64 = t51 * delta_tau;
    const T t65 = t27 * tau_lo;
    F = (T(1) / T(12)) * t25 * t26 * t27 * t44 + (T(1) / T(15)) * t45 * t26 * t46 * t49 + (T(1) / T(60)) * t51 * t26 * t1 * t55 + t36 * t56 + (T(8) / T(7)) * t38 * delta_tau * t26 * t58 - (T(1) / T(1680)) * (T(2) * t26 * t62 * b + t26 * t55 * c + T(7) * t26 * (T(5) * t26 * (t26 * t53 * c + T(2) * t26 * b * t60 - T(3) * t26 * (T(16) * J1 + t26 * t52 * c - T(2) * t26 * b * t59)) + T(2) * t61 * t26 * b + t54 * t26 * c)) * t63 * t26 - (T(2) / T(3)) * t0 * t26 * t39 * t57 - (T(1) / T(210)) * t64 * t26 * tau_lo * t62 - (T(4) / T(15)) * t50 * t26 * t65 * t43;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t66 = t0 * t0;
    const T t67 = T(1) / a;
    const T t68 = t1 * t1;
    const T t69 = T(1) / D;
    const T t70 = T(1) / r0;
    const T t71 = t70 * t70;
    const T t72 = T(1) / r1;
    const T t73 = t72 * t72;
    const T t74 = a_minus_b * t72 + t70 * b;
    const T t75 = t70 * b * t71 + t73 * a_minus_b * t72 + T(2) * t69 * a * t74;
    const T t76 = t71 * t71;
    const T t77 = t73 * t73;
    const T t78 = T(3) * t70 * b * t76 + T(3) * t77 * a_minus_b * t72 + T(4) * t69 * a * t75;
    const T t79 = t78 * t69 * b + T(3) * t70 * t76 - T(3) * t77 * t72;
    const T t80 = T(5) * t69 * t75 + T(2) * t79 * t67 * b - t78 * t69 * c;
    const T t81 = t77 * t73;
    const T t82 = t76 * t71;
    const T t83 = T(5) * t81 * a_minus_b * t72 + T(5) * t70 * b * t82 + T(2) * t78 * t69 * a;
    const T t84 = t69 * t83 * b + T(5) * t70 * t82 - T(5) * t81 * t72;
    const T t85 = T(3) * t69 * t83 * c - T(6) * t67 * b * t84 - T(7) * t78 * t69;
    const T t86 = T(3) * t67 * t84 * c + T(2) * t67 * b * t85 - T(7) * t79 * t67;
    const T t87 = T(7) * t80 * t67 + t67 * t85 * c - T(2) * t67 * b * t86;
    const T t88 = t68 * t68;
    const T t89 = t66 * delta_tau;
    const T t90 = t1 * tau_lo;
    const T t91 = t69 * b * t75 + t70 * t71 - t73 * t72;
    const T t92 = T(5) * t67 * t91 + T(2) * t80 * t67 * b - t79 * t67 * c;
    const T t93 = t67 * t86 * c + T(7) * t92 * t67 + T(2) * t67 * b * t87;
    const T t94 = t90 * t90;
    const T t95 = t94 * tau_lo;
    const T t96 = t0 * delta_tau;
    const T t97 = t96 * t96;
    const T t98 = T(3) * t69 * t74 + T(2) * t67 * b * t91 - t69 * t75 * c;
    const T t99 = T(5) * t98 * t67 + T(2) * t92 * t67 * b - t80 * t67 * c;
    const T t100 = T(7) * t67 * t99 + T(2) * t67 * t93 * b - t67 * t87 * c;
    const T t101 = t68 * tau_lo;
    const T t102 = t72 - t69 * b * t74 - t70;
    const T t103 = T(2) * t98 * t67 * b - T(3) * t67 * t102 - t67 * t91 * c;
    const T t104 = t92 * t67 * c - T(5) * t67 * t103 - T(2) * t67 * b * t99;
    const T t105 = T(7) * t104 * t67 + t67 * t93 * c - T(2) * t67 * b * t100;
    const T t106 = t97 * delta_tau;
    const T t107 = t66 * t66;
    F = (T(2) / T(3)) * t66 * t67 * t68 * t87 + (T(1) / T(35)) * t69 * t88 * t83 + (T(8) / T(15)) * t89 * t67 * t90 * t93 + (T(8) / T(35)) * delta_tau * t67 * t95 * t84 + (T(4) / T(15)) * t97 * t67 * t1 * t100 - (T(8) / T(15)) * t96 * t67 * t101 * t86 - (T(8) / T(105)) * t105 * t106 * t67 * tau_lo - (T(4) / T(15)) * t0 * t67 * t94 * t85 - (T(1) / T(105)) * (T(2) * t105 * t67 * b + t67 * t100 * c + T(7) * t67 * (T(2) * t104 * t67 * b + T(5) * (T(3) * t67 * (T(2) * t67 * b * t102 + t69 * t74 * c - J1) + t98 * t67 * c - T(2) * t67 * b * t103) * t67 + t67 * t99 * c)) * t107 * t67;
  }
  const T t108 = sigma2 * sigma2;
  const T t109 = t108 * t108;
  f = in.sigma * length * F * t109;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = t1 * sigma2 + ap_ap;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = tau_lo * ab2 + ap2 * delta_tau;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
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
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * tau_lo;
    const T t7 = t0 * delta_tau;
    const T t8 = t7 * t7;
    const T t9 = t8 * delta_tau;
    const T t10 = t0 * t0;
    const T t11 = t10 * t10;
    const T t12 = t1 * tau_lo;
    const T t13 = t12 * t12;
    const T t14 = t13 * tau_lo;
    const T t15 = t5 * t5;
    const T t16 = t10 * delta_tau;
    G_ap = T(56) * t6 * t7 * M_flat[3] + T(8) * M_flat[7] * tau_lo * t9 + t11 * M_flat[8] + T(28) * t13 * t0 * M_flat[2] + T(8) * t14 * delta_tau * M_flat[1] + M_flat[0] * t15 + T(28) * t1 * t8 * M_flat[6] + T(56) * t12 * t16 * M_flat[5] + T(70) * t5 * t10 * M_flat[4];
    G_ab = T(56) * t12 * t16 * M_flat[6] + t15 * M_flat[1] + T(56) * t6 * t7 * M_flat[4] + T(70) * t5 * t10 * M_flat[5] + T(28) * t13 * t0 * M_flat[3] + t11 * M_flat[9] + T(8) * t14 * delta_tau * M_flat[2] + T(8) * tau_lo * t9 * M_flat[8] + T(28) * M_flat[7] * t1 * t8;
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 9, a, b, D, c, q1, M_beyond.data());
    const T t17 = t1 * tau_lo;
    const T t18 = t0 * t0;
    const T t19 = t18 * delta_tau;
    const T t20 = t18 * t18;
    const T t21 = t0 * delta_tau;
    const T t22 = t21 * t21;
    const T t23 = t22 * delta_tau;
    const T t24 = t1 * t1;
    const T t25 = t24 * tau_lo;
    const T t26 = t24 * t24;
    const T t27 = t17 * t17;
    const T t28 = t27 * tau_lo;
    G_ap = T(56) * t17 * t19 * M_beyond[5] + t20 * M_beyond[8] + T(8) * tau_lo * t23 * M_beyond[7] + T(56) * M_beyond[3] * t25 * t21 + t26 * M_beyond[0] + T(28) * M_beyond[6] * t1 * t22 + T(70) * t24 * t18 * M_beyond[4] + T(28) * t27 * t0 * M_beyond[2] + T(8) * t28 * delta_tau * M_beyond[1];
    G_ab = T(56) * t25 * t21 * M_beyond[4] + T(28) * M_beyond[3] * t27 * t0 + T(8) * t28 * delta_tau * M_beyond[2] + T(28) * t1 * t22 * M_beyond[7] + M_beyond[9] * t20 + T(8) * tau_lo * t23 * M_beyond[8] + T(70) * t24 * t18 * M_beyond[5] + T(56) * M_beyond[6] * t17 * t19 + t26 * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t29 = t0 * delta_tau;
    const T t30 = t29 * t29;
    const T t31 = t30 * delta_tau;
    const T t32 = T(1) / a;
    const T t33 = T(1) / r0;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = T(1) / D;
    const T t38 = T(1) / r1;
    const T t39 = t38 * t38;
    const T t40 = t39 * t39;
    const T t41 = t40 * t39;
    const T t42 = b * t33 + t38 * a_minus_b;
    const T t43 = T(2) * t37 * t42 * a + b * t33 * t34 + t38 * a_minus_b * t39;
    const T t44 = T(3) * t38 * a_minus_b * t40 + T(3) * b * t33 * t35 + T(4) * t37 * a * t43;
    const T t45 = T(5) * t38 * a_minus_b * t41 + T(5) * b * t33 * t36 + T(2) * t37 * a * t44;
    const T t46 = T(5) * t33 * t36 + t37 * t45 * b - T(5) * t38 * t41;
    const T t47 = T(3) * t37 * t45 * c - T(7) * t37 * t44 - T(6) * t32 * t46 * b;
    const T t48 = T(3) * t33 * t35 + t37 * t44 * b - T(3) * t38 * t40;
    const T t49 = T(3) * t32 * t46 * c + T(2) * t32 * b * t47 - T(7) * t32 * t48;
    const T t50 = t35 * t35;
    const T t51 = t40 * t40;
    const T t52 = T(35) * t38 * a_minus_b * t51 + T(8) * t37 * t45 * a + T(35) * b * t33 * t50;
    const T t53 = T(35) * t33 * t50 + t37 * t52 * b - T(35) * t38 * t51;
    const T t54 = T(9) * t37 * t45 + T(2) * t53 * t32 * b - t37 * t52 * c;
    const T t55 = T(2) * t32 * b * t54 + T(9) * t32 * t46 - t53 * t32 * c;
    const T t56 = T(2) * t32 * t55 * b - t32 * t54 * c - T(3) * t32 * t47;
    const T t57 = T(3) * t49 * t32 + t32 * t55 * c - T(2) * t32 * t56 * b;
    const T t58 = t38 * t39 - t33 * t34 - t37 * b * t43;
    const T t59 = T(2) * t32 * b * t48 + T(5) * t37 * t43 - t37 * t44 * c;
    const T t60 = t32 * t48 * c + T(5) * t32 * t58 - T(2) * t32 * t59 * b;
    const T t61 = T(2) * t49 * t32 * b - t32 * t47 * c - T(7) * t32 * t59;
    const T t62 = T(7) * t32 * t60 + T(2) * t32 * b * t61 - t49 * t32 * c;
    const T t63 = T(3) * t32 * t61 + t32 * t56 * c + T(2) * t57 * t32 * b;
    const T t64 = t57 * t32 * c - T(3) * t62 * t32 - T(2) * t63 * t32 * b;
    const T t65 = t1 * t1;
    const T t66 = t0 * t0;
    const T t67 = t1 * tau_lo;
    const T t68 = t67 * t67;
    const T t69 = t65 * tau_lo;
    const T t70 = t68 * tau_lo;
    const T t71 = T(2) * t32 * t58 * b + t37 * t43 * c - T(3) * t37 * t42;
    const T t72 = T(5) * t32 * t71 + t32 * t59 * c + T(2) * t32 * b * t60;
    const T t73 = T(7) * t72 * t32 + T(2) * t62 * t32 * b - t32 * t61 * c;
    const T t74 = t63 * t32 * c + T(2) * t32 * b * t64 - T(3) * t32 * t73;
    const T t75 = t66 * t66;
    const T t76 = t65 * t65;
    const T t77 = t66 * delta_tau;
    G_ap = (T(8) / T(315)) * tau_lo * t31 * t32 * t64 + (T(2) / T(9)) * t65 * t66 * t32 * t56 + (T(4) / T(45)) * t68 * t0 * t32 * t54 + (T(8) / T(45)) * t69 * t29 * t32 * t55 + (T(8) / T(315)) * t53 * t70 * delta_tau * t32 + (T(1) / T(315)) * t74 * t75 * t32 + (T(1) / T(315)) * t37 * t52 * t76 - (T(4) / T(45)) * t63 * t1 * t30 * t32 - (T(8) / T(45)) * t57 * t67 * t77 * t32;
    G_ab = (T(8) / T(315)) * t70 * delta_tau * t32 * t54 + (T(8) / T(315)) * t74 * tau_lo * t31 * t32 + (T(8) / T(45)) * t69 * t29 * t32 * t56 + (T(4) / T(45)) * t68 * t0 * t32 * t55 + (T(1) / T(315)) * t53 * t76 * t32 + (T(4) / T(45)) * t1 * t30 * t32 * t64 - (T(2) / T(9)) * t57 * t65 * t66 * t32 - (T(8) / T(45)) * t63 * t67 * t77 * t32 - (T(1) / T(315)) * t75 * t32 * (T(3) * (T(2) * t32 * b * t73 - t62 * t32 * c - T(7) * t32 * (T(5) * (T(3) * t32 * (t33 + t37 * t42 * b - t38) + t32 * t58 * c - T(2) * t32 * t71 * b) * t32 + t32 * t60 * c - T(2) * t72 * t32 * b)) * t32 + t32 * t64 * c - T(2) * t74 * t32 * b);
  }
  const T t78 = sigma2 * sigma2;
  const T t79 = t78 * t78;
  const T g_factor = -T(9) * t79 * in.sigma * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = ab_ab + t0 * sigma2;
  const T b = ab_ap - tau_lo * delta_tau * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = ap2 * delta_tau + tau_lo * ab2;
  const T D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * tau_hi * sigma2 - ab_bp;
  const T q1 = tau_hi * tau_hi * sigma2 + bp_bp;
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
  const T t12 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t10 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 20> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t13 = t1 * tau_lo;
    const T t14 = t0 * t0;
    const T t15 = t14 * delta_tau;
    const T t16 = t1 * t1;
    const T t17 = t0 * delta_tau;
    const T t18 = t17 * t17;
    const T t19 = t18 * delta_tau;
    const T t20 = t13 * t13;
    const T t21 = t20 * tau_lo;
    const T t22 = t16 * tau_lo;
    const T t23 = t16 * t16;
    const T t24 = t14 * t14;
    F = T(56) * t13 * t15 * M_flat[5] + T(70) * t16 * t14 * M_flat[4] + T(8) * tau_lo * t19 * M_flat[7] + T(8) * t21 * delta_tau * M_flat[1] + T(56) * M_flat[3] * t22 * t17 + T(28) * M_flat[6] * t1 * t18 + T(28) * t20 * t0 * M_flat[2] + t23 * M_flat[0] + t24 * M_flat[8];
    G_ap = T(56) * t22 * t17 * M_flat[13] + T(56) * M_flat[15] * t13 * t15 + t23 * M_flat[10] + T(8) * t21 * delta_tau * M_flat[11] + M_flat[18] * t24 + T(28) * t1 * t18 * M_flat[16] + T(8) * tau_lo * t19 * M_flat[17] + T(28) * M_flat[12] * t20 * t0 + T(70) * t16 * t14 * M_flat[14];
    G_ab = T(28) * t1 * t18 * M_flat[17] + T(8) * M_flat[18] * tau_lo * t19 + T(56) * t22 * t17 * M_flat[14] + T(56) * t13 * t15 * M_flat[16] + M_flat[19] * t24 + T(28) * t20 * t0 * M_flat[13] + T(8) * M_flat[12] * t21 * delta_tau + T(70) * M_flat[15] * t16 * t14 + t23 * M_flat[11];
  } else if (t11 >= T(0) && t12 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t25 = T(1) / a;
    const T t26 = t1 * tau_lo;
    const T t27 = t26 * t26;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = T(1) / r1;
    const T t33 = t32 * t32;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = -b;
    const T t37 = J_downward<T>(11, a, D, t36, c, a_minus_b, q1);
    const T t38 = t28 * b * t31 + t32 * a_minus_b * t35 - T(9) * D * t37;
    const T t39 = t30 * t29;
    const T t40 = t34 * t33;
    const T t41 = T(8) * t28 * t39 - T(8) * t32 * t40 - T(7) * t25 * t38 * b;
    const T t42 = T(7) * D * t25 * t38 + T(8) * t32 * a_minus_b * t40 + T(8) * t28 * b * t39;
    const T t43 = T(42) * t25 * t38 * c + T(12) * t25 * b * t41 - T(7) * t25 * t42;
    const T t44 = t27 * tau_lo;
    const T t45 = t0 * t0;
    const T t46 = t45 * t45;
    const T t47 = T(48) * t28 * t30 - T(48) * t32 * t34 - T(5) * t25 * t42 * b;
    const T t48 = T(5) * D * t25 * t42 + T(48) * t32 * a_minus_b * t34 + T(48) * t28 * b * t30;
    const T t49 = T(20) * t25 * t42 * c + T(8) * t47 * t25 * b - T(5) * t48 * t25;
    const T t50 = T(64) * t32 * t33 + t48 * t25 * b - T(64) * t28 * t29;
    const T t51 = T(5) * t50 * t25 + T(4) * t47 * t25 * c - T(2) * t25 * b * t49;
    const T t52 = T(64) * t28 * b * t29 + t48 * D * t25 + T(64) * t32 * a_minus_b * t33;
    const T t53 = T(2) * t48 * t25 * c - T(3) * t25 * t52 - T(4) * t50 * t25 * b;
    const T t54 = T(2) * t25 * t49 * c + T(4) * t25 * b * t51 - T(5) * t25 * t53;
    const T t55 = T(128) * t32 + t25 * b * t52 - T(128) * t28;
    const T t56 = T(2) * t25 * b * t53 + T(2) * t50 * t25 * c - T(3) * t25 * t55;
    const T t57 = T(5) * t56 * t25 + T(2) * t25 * t51 * c - T(2) * t25 * t54 * b;
    const T t58 = T(30) * t25 * t41 * c - T(7) * t47 * t25 - T(10) * t25 * b * t43;
    const T t59 = T(20) * t25 * c * t43 + T(8) * t25 * b * t58 - T(7) * t25 * t49;
    const T t60 = T(7) * t25 * t51 + T(2) * t59 * t25 * b - T(4) * t25 * c * t58;
    const T t61 = T(4) * t60 * t25 * b + T(7) * t25 * t54 - T(2) * t59 * t25 * c;
    const T t62 = T(2) * t61 * t25 * b - T(7) * t57 * t25 - T(2) * t60 * t25 * c;
    const T t63 = t0 * delta_tau;
    const T t64 = t63 * t63;
    const T t65 = t1 * t1;
    const T t66 = t65 * tau_lo;
    const T t67 = t64 * delta_tau;
    const T t68 = t45 * delta_tau;
    const T t69 = t65 * t65;
    F = (T(1) / T(12)) * t25 * t27 * t0 * t43 + (T(1) / T(7)) * t25 * t44 * delta_tau * t41 + (T(1) / T(13440)) * t25 * t46 * (T(7) * t25 * (t25 * t54 * c + T(5) * t25 * (T(3) * (T(128) * J1 + t25 * t52 * c - T(2) * t25 * b * t55) * t25 + T(2) * t56 * t25 * b - t25 * t53 * c) + T(2) * t57 * t25 * b) + t61 * t25 * c - T(2) * t25 * b * t62) - (T(1) / T(480)) * t61 * t25 * t1 * t64 - (T(1) / T(30)) * t25 * t66 * t63 * t58 - (T(1) / T(1680)) * t25 * tau_lo * t67 * t62 - (T(1) / T(120)) * t60 * t25 * t26 * t68 - (T(1) / T(8)) * t25 * t69 * t38 - (T(1) / T(96)) * t59 * t25 * t65 * t45;
    const T t70 = t28 * t31 + T(9) * b * t37 - t32 * t35;
    const T t71 = T(16) * t25 * b * t70 - T(9) * t25 * t38 - T(72) * t37 * c;
    const T t72 = T(14) * t25 * b * t71 + T(9) * t25 * t41 - T(56) * t25 * t70 * c;
    const T t73 = T(4) * t25 * t72 * b + T(3) * t25 * t43 - T(14) * t25 * t71 * c;
    const T t74 = T(3) * t25 * t58 + T(10) * t25 * t72 * c - T(10) * t25 * b * t73;
    const T t75 = T(8) * t74 * t25 * b + T(3) * t59 * t25 + T(20) * t25 * t73 * c;
    const T t76 = T(2) * t25 * b * t75 + T(3) * t60 * t25 - T(4) * t74 * t25 * c;
    const T t77 = T(3) * t61 * t25 + T(4) * t25 * b * t76 - T(2) * t25 * t75 * c;
    G_ap = (T(8) / T(9)) * t25 * t44 * delta_tau * t70 + (T(5) / T(72)) * t25 * t65 * t45 * t73 + (T(1) / T(9)) * t25 * t72 * t66 * t63 + t69 * t37 + (T(7) / T(18)) * t25 * t27 * t0 * t71 - (T(1) / T(90)) * t74 * t25 * t26 * t68 - (T(1) / T(40320)) * t25 * t46 * t77 - (T(1) / T(2520)) * t25 * tau_lo * t67 * t76 - (T(1) / T(720)) * t25 * t1 * t64 * t75;
    G_ab = (T(1) / T(18)) * t25 * t72 * t27 * t0 + (T(1) / T(9)) * t25 * t69 * t70 + (T(1) / T(9)) * t25 * t44 * delta_tau * t71 + (T(1) / T(18)) * t25 * t66 * t63 * t73 - (T(1) / T(40320)) * t25 * t46 * (T(3) * t25 * t62 + T(2) * t25 * b * t77 - T(2) * t25 * c * t76) - (T(1) / T(360)) * t25 * t26 * t68 * t75 - (T(1) / T(720)) * t25 * t1 * t64 * t76 - (T(1) / T(5040)) * t25 * tau_lo * t67 * t77 - (T(1) / T(72)) * t74 * t25 * t65 * t45;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t78 = T(1) / a;
    const T t79 = t1 * tau_lo;
    const T t80 = t79 * t79;
    const T t81 = T(1) / r0;
    const T t82 = t81 * t81;
    const T t83 = t82 * t82;
    const T t84 = t83 * t82;
    const T t85 = T(1) / D;
    const T t86 = T(1) / r1;
    const T t87 = t86 * t86;
    const T t88 = t87 * t87;
    const T t89 = t88 * t87;
    const T t90 = t81 * b + t86 * a_minus_b;
    const T t91 = t81 * b * t82 + T(2) * t85 * a * t90 + t86 * a_minus_b * t87;
    const T t92 = T(3) * t86 * a_minus_b * t88 + T(3) * t81 * b * t83 + T(4) * t85 * a * t91;
    const T t93 = T(5) * t86 * a_minus_b * t89 + T(2) * t85 * t92 * a + T(5) * t81 * b * t84;
    const T t94 = T(5) * t81 * t84 + t85 * b * t93 - T(5) * t86 * t89;
    const T t95 = T(6) * t78 * t94 * b + T(7) * t85 * t92 - T(3) * t85 * c * t93;
    const T t96 = t1 * t1;
    const T t97 = t96 * tau_lo;
    const T t98 = t0 * delta_tau;
    const T t99 = T(3) * t81 * t83 + t85 * t92 * b - T(3) * t86 * t88;
    const T t100 = T(7) * t78 * t99 + T(2) * t78 * t95 * b - T(3) * t78 * t94 * c;
    const T t101 = t98 * t98;
    const T t102 = t101 * delta_tau;
    const T t103 = t85 * t92 * c - T(5) * t85 * t91 - T(2) * t78 * t99 * b;
    const T t104 = t85 * t91 * b + t81 * t82 - t86 * t87;
    const T t105 = t78 * t99 * c + T(2) * t78 * t103 * b - T(5) * t104 * t78;
    const T t106 = t78 * t95 * c + T(7) * t78 * t103 - T(2) * t78 * b * t100;
    const T t107 = t78 * t100 * c + T(7) * t105 * t78 + T(2) * t78 * t106 * b;
    const T t108 = T(2) * t104 * t78 * b + T(3) * t85 * t90 - t85 * t91 * c;
    const T t109 = t78 * t103 * c + T(5) * t78 * t108 - T(2) * t105 * t78 * b;
    const T t110 = T(7) * t78 * t109 + t78 * t106 * c - T(2) * t78 * b * t107;
    const T t111 = t85 * t90 * b + t81 - t86;
    const T t112 = T(3) * t78 * t111 + T(2) * t78 * b * t108 - t104 * t78 * c;
    const T t113 = t105 * t78 * c + T(2) * t78 * b * t109 + T(5) * t78 * t112;
    const T t114 = t78 * c * t107 + T(2) * t78 * t110 * b + T(7) * t113 * t78;
    const T t115 = t96 * t96;
    const T t116 = t0 * t0;
    const T t117 = t116 * t116;
    const T t118 = t80 * tau_lo;
    const T t119 = t116 * delta_tau;
    F = (T(4) / T(15)) * t78 * t80 * t0 * t95 + (T(8) / T(15)) * t78 * t97 * t98 * t100 + (T(8) / T(105)) * t78 * tau_lo * t102 * t114 + (T(1) / T(35)) * t85 * t115 * t93 + (T(1) / T(105)) * t78 * (T(2) * t78 * b * t114 - T(7) * t78 * (T(5) * (t78 * c * t108 - T(3) * t78 * (J1 + T(2) * t78 * b * t111 - t85 * t90 * c) - T(2) * t78 * b * t112) * t78 + t78 * t109 * c - T(2) * t113 * t78 * b) - t78 * t110 * c) * t117 + (T(4) / T(15)) * t78 * t1 * t101 * t110 + (T(8) / T(35)) * t78 * t118 * t94 * delta_tau - (T(2) / T(3)) * t78 * t96 * t116 * t106 - (T(8) / T(15)) * t78 * t79 * t119 * t107;
    const T t120 = t83 * t83;
    const T t121 = t88 * t88;
    const T t122 = T(35) * t81 * b * t120 + T(35) * t86 * a_minus_b * t121 + T(8) * t85 * a * t93;
    const T t123 = T(35) * t81 * t120 + t85 * b * t122 - T(35) * t86 * t121;
    const T t124 = t85 * c * t122 - T(2) * t78 * b * t123 - T(9) * t85 * t93;
    const T t125 = T(9) * t78 * t94 - T(2) * t124 * t78 * b - t78 * t123 * c;
    const T t126 = T(3) * t78 * t95 + t124 * t78 * c + T(2) * t125 * t78 * b;
    const T t127 = T(2) * t78 * b * t126 + T(3) * t78 * t100 - t125 * t78 * c;
    const T t128 = t78 * t126 * c + T(3) * t78 * t106 - T(2) * t78 * b * t127;
    const T t129 = T(2) * t128 * t78 * b + t78 * t127 * c + T(3) * t78 * t107;
    const T t130 = t128 * t78 * c + T(3) * t78 * t110 - T(2) * t78 * t129 * b;
    G_ap = (T(8) / T(45)) * t78 * t79 * t119 * t127 + (T(8) / T(45)) * t125 * t78 * t97 * t98 + (T(2) / T(9)) * t78 * t96 * t116 * t126 + (T(8) / T(315)) * t78 * t118 * delta_tau * t123 + (T(1) / T(315)) * t78 * t117 * t130 + (T(1) / T(315)) * t85 * t115 * t122 - (T(4) / T(45)) * t128 * t78 * t1 * t101 - (T(4) / T(45)) * t124 * t78 * t80 * t0 - (T(8) / T(315)) * t78 * tau_lo * t102 * t129;
    G_ab = (T(8) / T(45)) * t78 * t97 * t98 * t126 + (T(2) / T(9)) * t78 * t96 * t116 * t127 + (T(1) / T(315)) * t78 * t115 * t123 + (T(4) / T(45)) * t125 * t78 * t80 * t0 + (T(1) / T(315)) * t78 * (t78 * t129 * c + T(2) * t78 * t130 * b + T(3) * t78 * t114) * t117 + (T(8) / T(315)) * t78 * tau_lo * t102 * t130 - (T(4) / T(45)) * t78 * t1 * t101 * t129 - (T(8) / T(45)) * t128 * t78 * t79 * t119 - (T(8) / T(315)) * t124 * t78 * t118 * delta_tau;
  }
  const T t131 = sigma2 * sigma2;
  const T t132 = t131 * t131;
  const T g_factor = -T(9) * t132 * in.sigma * length;
  f = F * t132 * in.sigma * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = sigma2 * t0 + ab_ab;
  const T b = ab_ap - sigma2 * tau_lo * delta_tau;
  const T t1 = tau_lo * tau_lo;
  const T c = sigma2 * t1 + ap_ap;
  const T radial0 = ab0 * tau_lo + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + ab1 * tau_lo;
  const T radial2 = ap2 * delta_tau + ab2 * tau_lo;
  const T D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  const T a_minus_b = tau_hi * sigma2 * delta_tau - ab_bp;
  const T q1 = bp_bp + tau_hi * tau_hi * sigma2;
  const T c_minus_b = ap_bp + tau_hi * sigma2 * tau_lo;
  const T t2 = T(1) / c;
  const T log_ratio = log(t2 * q1);
  T F;
  const T t3 = D - T(2) * a * a;
  const T t4 = -a_minus_b * b;
  const T t5 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 9, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t0 * delta_tau;
    const T t7 = t6 * t6;
    const T t8 = t7 * delta_tau;
    const T t9 = t1 * tau_lo;
    const T t10 = t9 * t9;
    const T t11 = t1 * t1;
    const T t12 = t11 * tau_lo;
    const T t13 = t0 * t0;
    const T t14 = t11 * t11;
    const T t15 = t13 * delta_tau;
    const T t16 = t10 * tau_lo;
    const T t17 = t14 * tau_lo;
    const T t18 = t13 * t13;
    const T t19 = t18 * delta_tau;
    F = T(36) * M_flat[7] * t1 * t8 + T(84) * M_flat[3] * t10 * t6 + T(126) * M_flat[4] * t12 * t13 + T(9) * t14 * M_flat[1] * delta_tau + T(126) * t11 * t15 * M_flat[5] + T(36) * M_flat[2] * t16 * t0 + M_flat[0] * t17 + T(84) * M_flat[6] * t9 * t7 + M_flat[9] * t19 + T(9) * tau_lo * t18 * M_flat[8];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t20 = J_downward<T>(10, a, D, -b, c, a_minus_b, q1);
    const T t21 = t2 * t2;
    const T t22 = t21 * t21;
    const T t23 = T(1) / q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = T(8) * t20 * b + t22 - t25;
    const T t27 = T(1) / a;
    const T t28 = t1 * t1;
    const T t29 = t28 * t28;
    const T t30 = t1 * tau_lo;
    const T t31 = t30 * t30;
    const T t32 = t31 * tau_lo;
    const T t33 = t22 * b + a_minus_b * t25 - T(8) * D * t20;
    const T t34 = T(7) * t26 * t27 * b - T(28) * c * t20 - T(4) * t27 * t33;
    const T t35 = t29 * tau_lo;
    const T t36 = t24 * t23;
    const T t37 = t21 * t2;
    const T t38 = T(7) * a_minus_b * t36 + T(6) * D * t27 * t33 + T(7) * t37 * b;
    const T t39 = T(7) * t36 + T(6) * t27 * t33 * b - T(7) * t37;
    const T t40 = T(3) * t27 * t38 + T(5) * t39 * t27 * b - T(15) * c * t27 * t33;
    const T t41 = T(4) * t27 * t38 * b + T(35) * t24 - T(35) * t21;
    const T t42 = T(8) * t40 * t27 * b + T(3) * t27 * t41 - T(10) * c * t39 * t27;
    const T t43 = T(4) * D * t27 * t38 + T(35) * a_minus_b * t24 + T(35) * t21 * b;
    const T t44 = T(6) * c * t27 * t38 - T(2) * t27 * t43 - T(3) * t27 * t41 * b;
    const T t45 = t27 * t42 * b - T(2) * c * t40 * t27 - t44 * t27;
    const T t46 = T(21) * c * t26 * t27 + T(4) * t39 * t27 - T(12) * t27 * t34 * b;
    const T t47 = T(5) * t27 * t46 * b + T(15) * c * t27 * t34 + T(4) * t40 * t27;
    const T t48 = T(4) * t27 * b * t47 + T(2) * t27 * t42 - T(5) * c * t27 * t46;
    const T t49 = T(2) * t45 * t27 + t27 * t48 * b - c * t27 * t47;
    const T t50 = T(105) * t2 - T(105) * t23 - T(2) * t27 * t43 * b;
    const T t51 = T(2) * t50 * t27 + T(4) * t44 * t27 * b + T(3) * c * t27 * t41;
    const T t52 = c * t27 * t42 + t51 * t27 - T(4) * t45 * t27 * b;
    const T t53 = T(105) * t2 * b + T(105) * a_minus_b * t23 + T(2) * D * t27 * t43;
    const T t54 = t53 * t27 - t50 * t27 * b - c * t27 * t43;
    const T t55 = T(2) * t54 * t27 + c * t44 * t27 - t51 * t27 * b;
    const T t56 = c * t45 * t27 + t27 * t52 * b - t27 * t55;
    const T t57 = T(4) * t49 * t27 * b - T(2) * t27 * t52 - c * t27 * t48;
    const T t58 = t49 * c * t27 + T(2) * t56 * t27 - t57 * t27 * b;
    const T t59 = t0 * t0;
    const T t60 = t59 * t59;
    const T t61 = t60 * delta_tau;
    const T t62 = t59 * delta_tau;
    const T t63 = t0 * delta_tau;
    const T t64 = t28 * tau_lo;
    const T t65 = t63 * t63;
    const T t66 = t65 * delta_tau;
    F = (T(9) / T(8)) * t26 * t27 * t29 * delta_tau + (T(9) / T(7)) * t27 * t32 * t0 * t34 + t35 * t20 + (T(3) / T(140)) * t58 * t27 * tau_lo * t60 + (T(1) / T(840)) * t27 * (c * t57 * t27 + T(4) * t58 * t27 * b + T(2) * (T(4) * t56 * t27 * b - t27 * (T(4) * t27 * b * t55 + T(2) * t27 * (t50 * c * t27 + T(4) * t54 * t27 * b - (T(105) * log_ratio - T(2) * t53 * t27 * b) * t27) + c * t51 * t27) - c * t27 * t52) * t27) * t61 - (T(3) / T(20)) * t27 * t28 * t62 * t48 - (T(1) / T(2)) * t27 * t31 * t63 * t46 - (T(3) / T(10)) * t27 * t64 * t59 * t47 - (T(3) / T(70)) * t57 * t27 * t1 * t66 - (T(1) / T(5)) * t49 * t27 * t30 * t65;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t67 = sqrt(D);
    const T t68 = T(1) / t67;
    const T J2 = atan2(t67, c_minus_b) * t68;
    const T t69 = T(1) / a;
    const T t70 = t1 * t1;
    const T t71 = t70 * tau_lo;
    const T t72 = t0 * t0;
    const T t73 = T(1) / D;
    const T t74 = T(1) / q1;
    const T t75 = a * J2 + t2 * b + a_minus_b * t74;
    const T t76 = t74 * t74;
    const T t77 = t2 * t2;
    const T t78 = T(3) * t73 * a * t75 + T(2) * a_minus_b * t76 + T(2) * t77 * b;
    const T t79 = t76 * t74;
    const T t80 = t77 * t2;
    const T t81 = T(5) * t78 * t73 * a + T(8) * a_minus_b * t79 + T(8) * t80 * b;
    const T t82 = t81 * t73 * b + T(8) * t80 - T(8) * t79;
    const T t83 = t77 * t77;
    const T t84 = t76 * t76;
    const T t85 = T(48) * t83 * b + T(48) * a_minus_b * t84 + T(7) * t81 * t73 * a;
    const T t86 = T(48) * t83 + t73 * t85 * b - T(48) * t84;
    const T t87 = T(8) * t81 * t73 + T(2) * t86 * t69 * b - c * t73 * t85;
    const T t88 = T(8) * t82 * t69 + T(2) * t69 * t87 * b - c * t86 * t69;
    const T t89 = c * t81 * t73 - T(2) * t82 * t69 * b - T(6) * t78 * t73;
    const T t90 = T(2) * t88 * t69 * b - T(8) * t89 * t69 - c * t69 * t87;
    const T t91 = t70 * t70;
    const T t92 = t1 * tau_lo;
    const T t93 = t92 * t92;
    const T t94 = t0 * delta_tau;
    const T t95 = t91 * tau_lo;
    const T t96 = t93 * tau_lo;
    const T t97 = t78 * t73 * b + T(2) * t77 - T(2) * t76;
    const T t98 = t82 * c * t69 + T(2) * t89 * t69 * b - T(6) * t97 * t69;
    const T t99 = T(2) * t69 * t90 * b - T(8) * t98 * t69 - c * t88 * t69;
    const T t100 = t72 * delta_tau;
    const T t101 = t94 * t94;
    const T t102 = T(2) * t97 * t69 * b + T(4) * t73 * t75 - c * t78 * t73;
    const T t103 = T(2) * t98 * t69 * b - T(6) * t69 * t102 - c * t89 * t69;
    const T t104 = T(2) * t99 * t69 * b - c * t69 * t90 - T(8) * t103 * t69;
    const T t105 = t101 * delta_tau;
    const T t106 = t2 + t73 * b * t75 - t74;
    const T t107 = T(4) * t106 * t69 + T(2) * t69 * t102 * b - c * t97 * t69;
    const T t108 = T(2) * t103 * t69 * b - T(6) * t69 * t107 - t98 * c * t69;
    const T t109 = T(8) * t108 * t69 + c * t99 * t69 - T(2) * t69 * t104 * b;
    const T t110 = c * t73 * t75 - T(2) * J2 - T(2) * t106 * t69 * b;
    const T t111 = c * t69 * t102 + T(4) * t110 * t69 - T(2) * t69 * t107 * b;
    const T t112 = T(6) * t111 * t69 + T(2) * t108 * t69 * b - c * t103 * t69;
    const T t113 = T(8) * t112 * t69 + T(2) * t69 * t109 * b + c * t69 * t104;
    const T t114 = t72 * t72;
    const T t115 = t114 * delta_tau;
    F = (T(21) / T(64)) * t69 * t71 * t72 * t90 + (T(3) / T(128)) * t86 * t69 * t91 * delta_tau + (T(7) / T(32)) * t88 * t69 * t93 * t94 + (T(1) / T(384)) * t73 * t85 * t95 + (T(3) / T(32)) * t69 * t96 * t0 * t87 + (T(21) / T(64)) * t99 * t69 * t70 * t100 + (T(7) / T(32)) * t69 * t92 * t101 * t104 - (T(3) / T(32)) * t69 * t1 * t105 * t109 - (T(3) / T(128)) * t113 * t69 * tau_lo * t114 - (T(1) / T(384)) * (T(2) * t113 * t69 * b + T(8) * (T(2) * t112 * t69 * b + T(6) * t69 * (c * t69 * t107 + T(2) * t111 * t69 * b + T(4) * t69 * (c * t106 * t69 + T(2) * t110 * t69 * b - (log_ratio + T(2) * J2 * b) * t69)) - t108 * c * t69) * t69 - c * t69 * t109) * t69 * t115;
  }
  const T t116 = sigma2 * sigma2;
  const T t117 = t116 * t116;
  const T t118 = t117 * sigma2;
  f = t118 * length * F;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2 + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  T G_ap;
  T G_ab;
  const T t2 = D - T(2) * a * a;
  const T t3 = -a_minus_b * b;
  const T t4 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t2 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 11> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 10, a, b, c, T(0), T(1), M_flat.data());
    const T t5 = t1 * t1;
    const T t6 = t5 * t5;
    const T t7 = t0 * t0;
    const T t8 = t7 * delta_tau;
    const T t9 = t7 * t7;
    const T t10 = t0 * delta_tau;
    const T t11 = t10 * t10;
    const T t12 = t11 * delta_tau;
    const T t13 = t6 * tau_lo;
    const T t14 = t9 * delta_tau;
    const T t15 = t1 * tau_lo;
    const T t16 = t15 * t15;
    const T t17 = t16 * tau_lo;
    const T t18 = t5 * tau_lo;
    G_ap = T(9) * delta_tau * t6 * M_flat[1] + T(126) * t8 * t5 * M_flat[5] + T(9) * t9 * tau_lo * M_flat[8] + T(36) * t12 * t1 * M_flat[7] + M_flat[0] * t13 + M_flat[9] * t14 + T(36) * t0 * t17 * M_flat[2] + T(84) * t11 * M_flat[6] * t15 + T(126) * t7 * t18 * M_flat[4] + T(84) * M_flat[3] * t10 * t16;
    G_ab = t13 * M_flat[1] + T(126) * t7 * t18 * M_flat[5] + T(9) * M_flat[9] * t9 * tau_lo + T(9) * delta_tau * t6 * M_flat[2] + T(84) * t10 * t16 * M_flat[4] + T(84) * t11 * t15 * M_flat[7] + T(36) * M_flat[3] * t0 * t17 + t14 * M_flat[10] + T(126) * t8 * M_flat[6] * t5 + T(36) * t12 * t1 * M_flat[8];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 11> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 10, a, b, D, c, q1, M_beyond.data());
    const T t19 = t0 * t0;
    const T t20 = t19 * t19;
    const T t21 = t20 * delta_tau;
    const T t22 = t0 * delta_tau;
    const T t23 = t22 * t22;
    const T t24 = t1 * tau_lo;
    const T t25 = t1 * t1;
    const T t26 = t25 * t25;
    const T t27 = t26 * tau_lo;
    const T t28 = t23 * delta_tau;
    const T t29 = t24 * t24;
    const T t30 = t25 * tau_lo;
    const T t31 = t29 * tau_lo;
    const T t32 = t19 * delta_tau;
    G_ap = t21 * M_beyond[9] + T(84) * t23 * t24 * M_beyond[6] + T(9) * t20 * M_beyond[8] * tau_lo + t27 * M_beyond[0] + T(36) * t28 * t1 * M_beyond[7] + T(9) * M_beyond[1] * delta_tau * t26 + T(84) * t22 * t29 * M_beyond[3] + T(126) * M_beyond[4] * t19 * t30 + T(36) * t0 * t31 * M_beyond[2] + T(126) * t32 * t25 * M_beyond[5];
    G_ab = T(84) * M_beyond[4] * t22 * t29 + T(126) * t32 * t25 * M_beyond[6] + T(9) * delta_tau * t26 * M_beyond[2] + T(36) * t0 * t31 * M_beyond[3] + T(36) * t28 * M_beyond[8] * t1 + T(84) * t23 * t24 * M_beyond[7] + T(126) * t19 * t30 * M_beyond[5] + T(9) * t20 * tau_lo * M_beyond[9] + M_beyond[1] * t27 + t21 * M_beyond[10];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t33 = sqrt(D);
    const T t34 = T(1) / t33;
    const T J2 = t34 * atan2(t33, c_minus_b);
    const T t35 = T(1) / D;
    const T t36 = t1 * t1;
    const T t37 = t36 * t36;
    const T t38 = t37 * tau_lo;
    const T t39 = T(1) / c;
    const T t40 = t39 * t39;
    const T t41 = t40 * t40;
    const T t42 = T(1) / q1;
    const T t43 = b * t39 + a_minus_b * t42 + a * J2;
    const T t44 = t42 * t42;
    const T t45 = T(3) * t35 * a * t43 + T(2) * a_minus_b * t44 + T(2) * b * t40;
    const T t46 = t44 * t42;
    const T t47 = t40 * t39;
    const T t48 = T(5) * t35 * a * t45 + T(8) * a_minus_b * t46 + T(8) * b * t47;
    const T t49 = t44 * t44;
    const T t50 = T(48) * b * t41 + T(7) * t35 * a * t48 + T(48) * a_minus_b * t49;
    const T t51 = t41 * t39;
    const T t52 = t49 * t42;
    const T t53 = T(3) * t35 * a * t50 + T(128) * b * t51 + T(128) * a_minus_b * t52;
    const T t54 = T(1) / a;
    const T t55 = t0 * delta_tau;
    const T t56 = t1 * tau_lo;
    const T t57 = t56 * t56;
    const T t58 = t35 * b * t53 + T(128) * t51 - T(128) * t52;
    const T t59 = T(6) * t54 * b * t58 + T(10) * t35 * t50 - T(3) * t35 * t53 * c;
    const T t60 = T(48) * t41 + t35 * b * t50 - T(48) * t49;
    const T t61 = T(2) * t54 * b * t59 + T(10) * t54 * t60 - T(3) * t54 * t58 * c;
    const T t62 = t57 * tau_lo;
    const T t63 = t0 * t0;
    const T t64 = t63 * delta_tau;
    const T t65 = T(8) * t47 + t35 * t48 * b - T(8) * t46;
    const T t66 = T(2) * t54 * t60 * b + T(8) * t35 * t48 - t35 * c * t50;
    const T t67 = T(8) * t65 * t54 + T(2) * t54 * b * t66 - t54 * t60 * c;
    const T t68 = T(10) * t54 * t66 + T(2) * t54 * b * t61 - t54 * t59 * c;
    const T t69 = T(10) * t54 * t67 + T(2) * t54 * b * t68 - t54 * c * t61;
    const T t70 = t63 * t63;
    const T t71 = t70 * delta_tau;
    const T t72 = t35 * t48 * c - T(6) * t35 * t45 - T(2) * t65 * t54 * b;
    const T t73 = T(8) * t54 * t72 + t54 * c * t66 - T(2) * t54 * b * t67;
    const T t74 = t54 * t68 * c + T(10) * t54 * t73 - T(2) * t54 * b * t69;
    const T t75 = t35 * t45 * b + T(2) * t40 - T(2) * t44;
    const T t76 = T(4) * t35 * t43 + T(2) * t54 * b * t75 - t35 * t45 * c;
    const T t77 = T(6) * t54 * t75 - T(2) * t54 * t72 * b - t65 * t54 * c;
    const T t78 = T(6) * t54 * t76 + T(2) * t54 * b * t77 + t54 * t72 * c;
    const T t79 = T(8) * t54 * t77 - T(2) * t54 * b * t73 - t54 * c * t67;
    const T t80 = t54 * t73 * c + T(8) * t54 * t78 + T(2) * t54 * t79 * b;
    const T t81 = t54 * c * t69 + T(2) * t54 * b * t74 - T(10) * t54 * t79;
    const T t82 = t54 * t74 * c + T(10) * t54 * t80 - T(2) * t54 * b * t81;
    const T t83 = t42 - t35 * b * t43 - t39;
    const T t84 = t54 * t75 * c + T(4) * t54 * t83 - T(2) * t54 * b * t76;
    const T t85 = T(6) * t54 * t84 + t54 * c * t77 - T(2) * t54 * t78 * b;
    const T t86 = t54 * t79 * c + T(8) * t54 * t85 - T(2) * t54 * b * t80;
    const T t87 = T(2) * t54 * b * t82 + t54 * c * t81 - T(10) * t86 * t54;
    const T t88 = t36 * tau_lo;
    const T t89 = t55 * t55;
    const T t90 = t89 * delta_tau;
    G_ap = (T(1) / T(1280)) * t35 * t38 * t53 + (T(7) / T(320)) * t54 * t55 * t57 * t61 + (T(3) / T(320)) * t54 * t0 * t62 * t59 + (T(9) / T(1280)) * t54 * delta_tau * t37 * t58 + (T(21) / T(640)) * t54 * t64 * t36 * t69 + (T(1) / T(3840)) * t54 * t71 * t87 + (T(21) / T(640)) * t54 * t63 * t88 * t68 + (T(3) / T(1280)) * t54 * t70 * tau_lo * t82 - (T(3) / T(320)) * t54 * t90 * t1 * t81 - (T(7) / T(320)) * t54 * t89 * t56 * t74;
    G_ab = (T(1) / T(1280)) * t54 * t38 * t58 + (T(3) / T(320)) * t54 * t90 * t1 * t82 + (T(7) / T(320)) * t54 * t55 * t57 * t68 + (T(3) / T(320)) * t54 * t0 * t62 * t61 + (T(3) / T(1280)) * t54 * delta_tau * t37 * t59 + (T(21) / T(640)) * t54 * t63 * t88 * t69 + (T(3) / T(1280)) * t54 * t70 * tau_lo * t87 - (T(1) / T(3840)) * t54 * t71 * (T(10) * t54 * (t54 * t80 * c + T(8) * t54 * (t54 * t78 * c + T(2) * t54 * b * t85 - T(6) * t54 * (T(4) * t54 * (T(2) * J2 - T(2) * t54 * b * t83 - t35 * c * t43) - T(2) * t54 * t84 * b - t54 * c * t76)) + T(2) * t86 * t54 * b) + t54 * t82 * c - T(2) * t54 * b * t87) - (T(21) / T(640)) * t54 * t64 * t36 * t74 - (T(7) / T(320)) * t54 * t89 * t56 * t81;
  }
  const T t91 = sigma2 * sigma2;
  const T t92 = t91 * t91;
  const T t93 = t92 * sigma2;
  const T g_factor = -T(10) * t93 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + bp2 * ap2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T t0 = delta_tau * delta_tau;
  const T a = t0 * sigma2 + ab_ab;
  const T b = ab_ap - delta_tau * tau_lo * sigma2;
  const T t1 = tau_lo * tau_lo;
  const T c = ap_ap + t1 * sigma2;
  const T radial0 = tau_lo * ab0 + ap0 * delta_tau;
  const T radial1 = ap1 * delta_tau + tau_lo * ab1;
  const T radial2 = delta_tau * ap2 + tau_lo * ab2;
  const T D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  const T a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  const T q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  const T c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
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
    std::array<T, 22> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 10, a, b, c, T(0), T(1), M_flat.data());
    const T t6 = t1 * t1;
    const T t7 = t6 * t6;
    const T t8 = t7 * tau_lo;
    const T t9 = t0 * t0;
    const T t10 = t6 * tau_lo;
    const T t11 = t0 * delta_tau;
    const T t12 = t11 * t11;
    const T t13 = t1 * tau_lo;
    const T t14 = t9 * t9;
    const T t15 = t13 * t13;
    const T t16 = t15 * tau_lo;
    const T t17 = t12 * delta_tau;
    const T t18 = t14 * delta_tau;
    const T t19 = t9 * delta_tau;
    F = t8 * M_flat[0] + T(9) * delta_tau * t7 * M_flat[1] + T(126) * t9 * t10 * M_flat[4] + T(84) * t12 * t13 * M_flat[6] + T(9) * M_flat[8] * t14 * tau_lo + T(84) * t11 * t15 * M_flat[3] + T(36) * M_flat[2] * t0 * t16 + T(36) * t17 * t1 * M_flat[7] + t18 * M_flat[9] + T(126) * M_flat[5] * t19 * t6;
    G_ap = T(36) * t0 * t16 * M_flat[13] + T(36) * M_flat[18] * t17 * t1 + t8 * M_flat[11] + T(126) * t19 * t6 * M_flat[16] + T(84) * t11 * t15 * M_flat[14] + T(9) * delta_tau * t7 * M_flat[12] + T(126) * t9 * M_flat[15] * t10 + T(9) * t14 * tau_lo * M_flat[19] + T(84) * t12 * t13 * M_flat[17] + t18 * M_flat[20];
    G_ab = T(84) * M_flat[18] * t12 * t13 + T(126) * t9 * t10 * M_flat[16] + t8 * M_flat[12] + T(9) * t14 * tau_lo * M_flat[20] + T(36) * t17 * t1 * M_flat[19] + T(84) * t11 * M_flat[15] * t15 + T(9) * delta_tau * t7 * M_flat[13] + T(36) * t0 * t16 * M_flat[14] + M_flat[21] * t18 + T(126) * t19 * t6 * M_flat[17];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t20 = T(1) / a;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t22 * t22;
    const T t25 = t24 * t21;
    const T t26 = t2 * t2;
    const T t27 = t26 * t26;
    const T t28 = t27 * t2;
    const T t29 = J_downward<T>(12, a, D, -b, c, a_minus_b, q1);
    const T t30 = a_minus_b * t25 + b * t28 - T(10) * D * t29;
    const T t31 = T(9) * a_minus_b * t24 + T(8) * D * t20 * t30 + T(9) * b * t27;
    const T t32 = t26 * t2;
    const T t33 = T(21) * a_minus_b * t23 + T(2) * D * t20 * t31 + T(21) * b * t32;
    const T t34 = T(105) * t22 + T(4) * t20 * t33 * b - T(105) * t26;
    const T t35 = T(21) * t32 - T(21) * t23 - T(2) * t20 * b * t31;
    const T t36 = T(5) * t20 * t31 * c + T(5) * t20 * b * t35 - T(3) * t20 * t33;
    const T t37 = T(3) * t20 * t34 + T(10) * t20 * c * t35 - T(8) * t20 * b * t36;
    const T t38 = T(105) * a_minus_b * t22 + T(4) * D * t20 * t33 + T(105) * b * t26;
    const T t39 = T(3) * t20 * b * t34 + T(2) * t20 * t38 - T(6) * t20 * t33 * c;
    const T t40 = T(2) * t20 * b * t38 + T(315) * t21 - T(315) * t2;
    const T t41 = T(3) * t20 * t34 * c - T(4) * t20 * b * t39 - T(2) * t20 * t40;
    const T t42 = t20 * t39 + T(2) * t20 * c * t36 + t37 * t20 * b;
    const T t43 = t37 * t20 * c + t20 * t41 - T(4) * t20 * b * t42;
    const T t44 = T(315) * b * t2 + T(2) * D * t20 * t38 + T(315) * a_minus_b * t21;
    const T t45 = t20 * t38 * c - t20 * t44 - t20 * t40 * b;
    const T t46 = t20 * b * t41 + t20 * c * t39 + T(2) * t45 * t20;
    const T t47 = t20 * t43 * b + t20 * c * t42 + t20 * t46;
    const T t48 = T(9) * t24 + T(8) * t20 * b * t30 - T(9) * t27;
    const T t49 = T(28) * t20 * t30 * c - T(4) * t20 * t31 - T(7) * t20 * t48 * b;
    const T t50 = T(7) * t20 * t48 * c + T(4) * t20 * b * t49 + T(4) * t20 * t35;
    const T t51 = T(4) * t20 * t36 + T(5) * t20 * b * t50 - T(5) * t20 * t49 * c;
    const T t52 = T(5) * t20 * t50 * c + T(2) * t37 * t20 - T(4) * t20 * t51 * b;
    const T t53 = T(2) * t20 * t42 + t20 * t51 * c + t20 * b * t52;
    const T t54 = T(4) * t20 * b * t53 - T(2) * t20 * t43 - t20 * c * t52;
    const T t55 = t20 * b * t54 - T(2) * t20 * t47 - t20 * t53 * c;
    const T t56 = t0 * t0;
    const T t57 = t56 * t56;
    const T t58 = t57 * delta_tau;
    const T t59 = t1 * tau_lo;
    const T t60 = t59 * t59;
    const T t61 = t60 * tau_lo;
    const T t62 = t1 * t1;
    const T t63 = t62 * tau_lo;
    const T t64 = t0 * delta_tau;
    const T t65 = t62 * t62;
    const T t66 = t65 * tau_lo;
    const T t67 = t64 * t64;
    const T t68 = t56 * delta_tau;
    const T t69 = t67 * delta_tau;
    F = (T(1) / T(2520)) * (T(2) * t20 * (T(4) * t20 * t47 * b + (T(4) * t20 * b * t46 + T(2) * t20 * (T(4) * t45 * t20 * b + t20 * t40 * c - t20 * (T(2) * t20 * t44 * b - T(315) * log_ratio)) - t20 * t41 * c) * t20 - t20 * t43 * c) + t20 * c * t54 - T(4) * t55 * t20 * b) * t20 * t58 + (T(1) / T(7)) * t20 * t0 * t61 * t49 + (T(1) / T(10)) * t20 * t56 * t63 * t51 + (T(1) / T(6)) * t20 * t64 * t60 * t50 - (T(1) / T(9)) * t20 * t66 * t30 - (T(1) / T(15)) * t20 * t67 * t59 * t53 - (T(1) / T(8)) * t20 * t48 * delta_tau * t65 - (T(1) / T(20)) * t20 * t68 * t62 * t52 - (T(1) / T(140)) * t55 * t20 * t57 * tau_lo - (T(1) / T(70)) * t20 * t69 * t1 * t54;
    const T t70 = T(10) * b * t29 + t28 - t25;
    const T t71 = T(45) * c * t29 + T(5) * t20 * t30 - T(9) * t70 * t20 * b;
    const T t72 = T(5) * t20 * t48 + T(36) * t70 * t20 * c + T(16) * t20 * b * t71;
    const T t73 = T(28) * t20 * t71 * c + T(5) * t20 * t49 - T(7) * t20 * b * t72;
    const T t74 = T(7) * t20 * t72 * c + T(4) * t20 * t73 * b + T(5) * t20 * t50;
    const T t75 = t20 * t51 + t20 * b * t74 - t20 * t73 * c;
    const T t76 = t20 * t74 * c + t20 * t52 - T(4) * t20 * b * t75;
    const T t77 = t20 * t75 * c + t20 * b * t76 + t20 * t53;
    const T t78 = t20 * t54 + T(4) * t20 * b * t77 - t20 * c * t76;
    G_ap = (T(9) / T(10)) * t70 * t20 * delta_tau * t65 + t66 * t29 + (T(1) / T(10)) * t20 * t56 * t73 * t63 + (T(1) / T(20)) * t20 * t68 * t62 * t74 + (T(1) / T(15)) * t20 * t67 * t59 * t75 - (T(1) / T(2520)) * t20 * t58 * t78 - (T(1) / T(140)) * t20 * t57 * tau_lo * t77 - (T(7) / T(30)) * t20 * t64 * t60 * t72 - (T(1) / T(70)) * t20 * t69 * t1 * t76 - (T(4) / T(5)) * t20 * t0 * t61 * t71;
    G_ab = (T(1) / T(15)) * t20 * t64 * t73 * t60 + (T(1) / T(10)) * t70 * t20 * t66 + (T(1) / T(10)) * t20 * t68 * t62 * t75 + (T(1) / T(1260)) * t20 * t58 * (t20 * c * t77 - t55 * t20 - t20 * b * t78) + (T(1) / T(20)) * t20 * t56 * t63 * t74 - (T(1) / T(5)) * t20 * delta_tau * t65 * t71 - (T(1) / T(10)) * t20 * t0 * t61 * t72 - (T(1) / T(280)) * t20 * t57 * tau_lo * t78 - (T(1) / T(30)) * t20 * t67 * t59 * t76 - (T(1) / T(35)) * t20 * t69 * t1 * t77;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t79 = sqrt(D);
    const T t80 = T(1) / t79;
    const T J2 = t80 * atan2(t79, c_minus_b);
    const T t81 = T(1) / q1;
    const T t82 = t81 * t81;
    const T t83 = t82 * t82;
    const T t84 = t2 * t2;
    const T t85 = t84 * t84;
    const T t86 = T(1) / D;
    const T t87 = t82 * t81;
    const T t88 = b * t2 + a_minus_b * t81 + a * J2;
    const T t89 = T(2) * a_minus_b * t82 + T(3) * t86 * a * t88 + T(2) * b * t84;
    const T t90 = t84 * t2;
    const T t91 = T(8) * a_minus_b * t87 + T(5) * t86 * a * t89 + T(8) * b * t90;
    const T t92 = T(48) * a_minus_b * t83 + T(48) * b * t85 + T(7) * t86 * a * t91;
    const T t93 = t1 * t1;
    const T t94 = t93 * t93;
    const T t95 = t94 * tau_lo;
    const T t96 = T(1) / a;
    const T t97 = T(2) * t82 - T(2) * t84 - t86 * b * t89;
    const T t98 = T(4) * t86 * t88 - T(2) * t96 * b * t97 - t86 * t89 * c;
    const T t99 = t86 * b * t91 + T(8) * t90 - T(8) * t87;
    const T t100 = t86 * t91 * c - T(6) * t86 * t89 - T(2) * t96 * b * t99;
    const T t101 = T(6) * t96 * t97 + T(2) * t96 * b * t100 + t96 * c * t99;
    const T t102 = T(6) * t96 * t98 + t96 * t100 * c - T(2) * t96 * b * t101;
    const T t103 = t92 * t86 * b + T(48) * t85 - T(48) * t83;
    const T t104 = t92 * t86 * c - T(8) * t86 * t91 - T(2) * t96 * t103 * b;
    const T t105 = T(8) * t96 * t99 - T(2) * t104 * t96 * b - t96 * t103 * c;
    const T t106 = T(2) * t105 * t96 * b + t104 * t96 * c - T(8) * t96 * t100;
    const T t107 = T(8) * t96 * t101 + t105 * t96 * c - T(2) * t96 * b * t106;
    const T t108 = T(8) * t96 * t102 - T(2) * t107 * t96 * b - t96 * c * t106;
    const T t109 = t0 * delta_tau;
    const T t110 = t109 * t109;
    const T t111 = t1 * tau_lo;
    const T t112 = t110 * delta_tau;
    const T t113 = t86 * t88 * b + t2 - t81;
    const T t114 = T(4) * t96 * t113 + t96 * c * t97 + T(2) * t96 * b * t98;
    const T t115 = t96 * t101 * c + T(6) * t96 * t114 + T(2) * t96 * b * t102;
    const T t116 = t107 * t96 * c + T(8) * t96 * t115 + T(2) * t96 * t108 * b;
    const T t117 = t0 * t0;
    const T t118 = t93 * tau_lo;
    const T t119 = t111 * t111;
    const T t120 = t117 * delta_tau;
    const T t121 = t117 * t117;
    const T t122 = t121 * delta_tau;
    const T t123 = T(2) * t96 * t113 * b + T(2) * J2 - t86 * t88 * c;
    const T t124 = t96 * c * t98 - T(4) * t96 * t123 - T(2) * t96 * t114 * b;
    const T t125 = T(6) * t96 * t124 + t96 * c * t102 - T(2) * t96 * t115 * b;
    const T t126 = t96 * t108 * c + T(8) * t96 * t125 - T(2) * t96 * b * t116;
    const T t127 = t119 * tau_lo;
    F = (T(1) / T(384)) * t92 * t86 * t95 + (T(7) / T(32)) * t96 * t108 * t110 * t111 + (T(3) / T(128)) * t96 * t103 * delta_tau * t94 + (T(3) / T(32)) * t96 * t112 * t1 * t116 + (T(21) / T(64)) * t96 * t117 * t118 * t106 + (T(7) / T(32)) * t105 * t96 * t109 * t119 - (T(21) / T(64)) * t107 * t96 * t120 * t93 - (T(1) / T(384)) * t96 * t122 * (t96 * t116 * c + T(8) * (T(6) * t96 * (t96 * t114 * c + T(2) * t96 * b * t124 - T(4) * t96 * (t96 * (log_ratio + T(2) * b * J2) + T(2) * t96 * b * t123 - t96 * t113 * c)) + T(2) * t96 * b * t125 + t96 * t115 * c) * t96 + T(2) * t96 * b * t126) - (T(3) / T(128)) * t96 * t121 * tau_lo * t126 - (T(3) / T(32)) * t104 * t96 * t0 * t127;
    const T t128 = t83 * t81;
    const T t129 = t85 * t2;
    const T t130 = T(128) * a_minus_b * t128 + T(128) * b * t129 + T(3) * t92 * t86 * a;
    const T t131 = T(128) * t128 - T(128) * t129 - t86 * b * t130;
    const T t132 = T(6) * t96 * b * t131 + T(3) * t86 * c * t130 - T(10) * t92 * t86;
    const T t133 = T(2) * t96 * b * t132 - T(10) * t96 * t103 - T(3) * t96 * t131 * c;
    const T t134 = T(2) * t96 * b * t133 + T(10) * t104 * t96 - t96 * t132 * c;
    const T t135 = t96 * t133 * c + T(10) * t105 * t96 - T(2) * t134 * t96 * b;
    const T t136 = T(10) * t96 * t106 + T(2) * t96 * t135 * b + t134 * t96 * c;
    const T t137 = t96 * t135 * c + T(10) * t107 * t96 - T(2) * t96 * t136 * b;
    const T t138 = T(2) * t96 * b * t137 + t96 * t136 * c - T(10) * t96 * t108;
    const T t139 = T(10) * t96 * t116 + t96 * c * t137 - T(2) * t96 * b * t138;
    G_ap = (T(7) / T(320)) * t96 * t110 * t111 * t136 + (T(21) / T(640)) * t96 * t120 * t135 * t93 + (T(1) / T(3840)) * t96 * t122 * t139 + (T(1) / T(1280)) * t86 * t95 * t130 - (T(3) / T(1280)) * t96 * t121 * tau_lo * t138 - (T(3) / T(320)) * t96 * t0 * t127 * t132 - (T(21) / T(640)) * t134 * t96 * t117 * t118 - (T(3) / T(320)) * t96 * t112 * t1 * t137 - (T(9) / T(1280)) * t96 * delta_tau * t94 * t131 - (T(7) / T(320)) * t96 * t109 * t119 * t133;
    G_ab = (T(21) / T(640)) * t96 * t117 * t135 * t118 + (T(21) / T(640)) * t96 * t120 * t93 * t136 + (T(3) / T(1280)) * t96 * t121 * tau_lo * t139 - (T(7) / T(320)) * t134 * t96 * t109 * t119 - (T(1) / T(1280)) * t96 * t95 * t131 - (T(1) / T(3840)) * t96 * t122 * (T(10) * t96 * t126 - T(2) * t96 * b * t139 - t96 * c * t138) - (T(3) / T(320)) * t96 * t0 * t127 * t133 - (T(7) / T(320)) * t96 * t110 * t111 * t137 - (T(3) / T(320)) * t96 * t112 * t1 * t138 - (T(3) / T(1280)) * t96 * delta_tau * t94 * t132;
  }
  const T t140 = sigma2 * sigma2;
  const T t141 = t140 * t140;
  const T t142 = t141 * sigma2;
  const T g_factor = -T(10) * t142 * length;
  f = F * t142 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

}  // namespace skelconv::generated
