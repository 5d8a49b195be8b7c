// generated/segment_inverse.hpp — segment kernels of the inverse family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC §2, Hubert 2012 §3).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/gauss_moments.hpp>
#include <skelconv/segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 26 +, 32 ×, 2 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 111 +, 197 ×, 25 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    X = length * (t1 + a_minus_b * r0) / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t2 - a_minus_b * r0);
  }
  const T J1 = asinh(X) / length;
  T F;
  const T t3 = cross_cross - T(2) * ab_ab * ab_ab;
  if (t3 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = in.w[0] * J1;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 32 +, 45 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1536 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + ab_ap * t5;
    G_ap = in.w[0] * t3 * t6;
    G_ab = (t3 * t6 * ab_ap + t5 - t4) * in.w[0] / ab_ab;
  }
  const T g_factor = -length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 33 +, 54 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 262 +, 967 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i1_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r0 * a_minus_b) * length * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = J1 * in.w[0];
    F = t8;
    const T t9 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t9 * in.w[0];
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / r0;
    const T t12 = T(1) / r1;
    G_ab = in.w[0] * t10 * (t11 + t9 * ab_ap - t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = J1 * in.w[0];
    F = t13;
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + t15 * ab_ap;
    const T t17 = T(1) / cross_cross;
    G_ap = t16 * in.w[0] * t17;
    const T t18 = T(1) / ab_ab;
    G_ab = in.w[0] * t18 * (t16 * t17 * ab_ap + t15 - t14);
  }
  const T g_factor = -length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Returns false where segment_inverse_i1_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 33 +, 54 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i1_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / cross_cross;
    X = length * (t1 + r1 * ab_ap) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = J1 * in.w[0];
    F = t8;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = ab_ap * t9 + t10 * a_minus_b;
    const T t12 = T(1) / cross_cross;
    G_ap = in.w[0] * t11 * t12;
    const T t13 = T(1) / ab_ab;
    G_ab = t13 * in.w[0] * (t9 + ab_ap * t11 * t12 - t10);
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 29 +, 36 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 132 +, 219 ×, 25 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    X = length * (t1 + a_minus_b * r0) / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t2 - a_minus_b * r0);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
  const T t4 = cross_cross - T(2) * ab_ab * ab_ab;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / ab_ab;
    F = in.w[0] * J1 + (r1 + ab_ap * J1 - r0) * in.w[1] * t5;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 37 +, 61 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 266 +, 973 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / cross_cross;
    X = length * (t1 + ab_ap * r1) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = -ab_ap;
    const T t9 = J_downward<T>(3, ab_ab, cross_cross, t8, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 - t12 - ab_ap * t9;
    G_ap = in.w[0] * t9 - t10 * in.w[1] * t13;
    G_ab = -t10 * (ap_ap * t9 + T(2) * t10 * ab_ap * t13 - J1) * in.w[1] - t10 * in.w[0] * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = ab_ap * t14 + a_minus_b * t15;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / ab_ab;
    const T t19 = t15 - t14 - t16 * ab_ap * t17;
    G_ap = t16 * in.w[0] * t17 - t18 * t19 * in.w[1];
    G_ab = t18 * (J1 - t16 * ap_ap * t17 - T(2) * t18 * t19 * ab_ap) * in.w[1] - t18 * t19 * in.w[0];
  }
  const T g_factor = -length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 40 +, 66 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 269 +, 978 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i1_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * length * (t2 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = length * (ab_ap - a_minus_b) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = T(1) / ab_ab;
    const T t9 = in.w[0] * J1 + in.w[1] * t8 * (ab_ap * J1 + r1 - r0);
    F = t9;
    const T t10 = T(1) / r0;
    const T t11 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = T(1) / r1;
    const T t13 = t10 + t11 * ab_ap - t12;
    G_ap = in.w[1] * t8 * t13 + t11 * in.w[0];
    G_ab = t8 * in.w[0] * t13 - in.w[1] * t8 * (t11 * ap_ap - J1 - T(2) * t8 * ab_ap * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / ab_ab;
    const T t15 = in.w[0] * J1 + in.w[1] * t14 * (ab_ap * J1 + r1 - r0);
    F = t15;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / r1;
    const T t18 = T(1) / r0;
    const T t19 = t17 * a_minus_b + ab_ap * t18;
    const T t20 = t18 + t16 * t19 * ab_ap - t17;
    G_ap = t16 * t19 * in.w[0] + in.w[1] * t14 * t20;
    G_ab = t14 * t20 * in.w[0] - in.w[1] * t14 * (t16 * t19 * ap_ap - J1 - T(2) * t14 * t20 * ab_ap);
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Returns false where segment_inverse_i1_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 40 +, 66 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i1_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = -(a_minus_b - ab_ap) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / ab_ab;
    const T t9 = in.w[0] * J1 - in.w[1] * t8 * (r0 - J1 * ab_ap - r1);
    F = t9;
    const T t10 = T(1) / r0;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / r1;
    const T t13 = t10 * ab_ap + a_minus_b * t12;
    const T t14 = t10 + t11 * t13 * ab_ap - t12;
    G_ap = t14 * in.w[1] * t8 + in.w[0] * t11 * t13;
    G_ab = in.w[1] * (T(2) * t14 * t8 * ab_ap + J1 - ap_ap * t11 * t13) * t8 + in.w[0] * t14 * t8;
  }
  const T g_factor = -length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 34 +, 48 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 153 +, 240 ×, 25 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    X = length * (t1 + a_minus_b * r0) / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = ab_ap * r1;
    X = -length * (a_minus_b - ab_ap) / (t2 - a_minus_b * r0);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
  const T t4 = cross_cross - T(2) * ab_ab * ab_ab;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / ab_ab;
    const T t6 = r0 - J1 * ab_ap - r1;
    F = J1 * in.w[0] + (T(1) / T(2)) * in.w[2] * t5 * (t5 * (cross_cross * J1 + r0 * ab_ap + a_minus_b * r1) - T(4) * t6 * t5 * ab_ap - T(2) * J1 * ap_ap) - t6 * t5 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 43 +, 72 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 272 +, 984 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = ab_ap * r1;
    X = t1 * length * (t2 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ab = M_flat[1] * in.w[0] + in.w[2] * M_flat[3] + M_flat[2] * in.w[1];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = -ab_ap;
    const T t9 = J_downward<T>(3, ab_ab, cross_cross, t8, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 - t12 - t9 * ab_ap;
    const T t14 = t9 * ap_ap + T(2) * t10 * t13 * ab_ap - J1;
    G_ap = t9 * in.w[0] - t10 * t13 * in.w[1] - in.w[2] * t10 * t14;
    const T t15 = t10 * (ab_ap * J1 + r1 - r0);
    G_ab = in.w[2] * t10 * (t15 + t10 * t13 * ap_ap - T(2) * t10 * t14 * ab_ap) - t10 * t14 * in.w[1] - t10 * t13 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = ab_ap * t16 + a_minus_b * t17;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / ab_ab;
    const T t21 = t17 - t18 * t19 * ab_ap - t16;
    const T t22 = T(2) * t20 * ab_ap * t21 + t18 * t19 * ap_ap - J1;
    G_ap = t18 * t19 * in.w[0] - t20 * t21 * in.w[1] - in.w[2] * t20 * t22;
    const T t23 = t20 * (ab_ap * J1 + r1 - r0);
    G_ab = in.w[2] * t20 * (t20 * t21 * ap_ap + t23 - T(2) * t20 * ab_ap * t22) - t20 * in.w[0] * t21 - t20 * in.w[1] * t22;
  }
  const T g_factor = -length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 49 +, 88 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 278 +, 1000 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i1_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r0 * a_minus_b) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = r0 - r1 - J1 * ab_ap;
    const T t9 = T(1) / ab_ab;
    const T t10 = J1 * in.w[0] - t8 * in.w[1] * t9 - (T(1) / T(2)) * (T(2) * ap_ap * J1 + T(4) * t8 * t9 * ab_ap - (r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross) * t9) * in.w[2] * t9;
    F = t10;
    const T t11 = T(1) / r0;
    const T t12 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t13 = T(1) / r1;
    const T t14 = t11 + t12 * ab_ap - t13;
    const T t15 = J1 + T(2) * t14 * t9 * ab_ap - ap_ap * t12;
    G_ap = in.w[1] * t14 * t9 + in.w[2] * t9 * t15 + t12 * in.w[0];
    G_ab = in.w[1] * t9 * t15 + in.w[2] * t9 * (T(2) * t9 * t15 * ab_ap - ap_ap * t14 * t9 - t8 * t9) + t14 * t9 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = r0 - r1 - J1 * ab_ap;
    const T t17 = T(1) / ab_ab;
    const T t18 = J1 * in.w[0] - t16 * in.w[1] * t17 - (T(1) / T(2)) * (T(2) * ap_ap * J1 + T(4) * t16 * t17 * ab_ap - (r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross) * t17) * in.w[2] * t17;
    F = t18;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / r1;
    const T t22 = t19 * ab_ap + t21 * a_minus_b;
    const T t23 = t19 + t20 * t22 * ab_ap - t21;
    const T t24 = T(2) * t23 * t17 * ab_ap + J1 - ap_ap * t20 * t22;
    G_ap = in.w[2] * t17 * t24 + in.w[1] * t23 * t17 + t20 * t22 * in.w[0];
    G_ab = t23 * t17 * in.w[0] + in.w[1] * t17 * t24 - (ap_ap * t23 * t17 + t16 * t17 - T(2) * t17 * t24 * ab_ap) * in.w[2] * t17;
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Returns false where segment_inverse_i1_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 88 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i1_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / cross_cross;
    X = (t1 + ab_ap * r1) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = -(ab_ap - a_minus_b) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + in.w[2] * M_flat[6];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / ab_ab;
    const T t9 = ab_ap * J1 + r1 - r0;
    const T t10 = in.w[0] * J1 + (T(1) / T(2)) * (t8 * (J1 * cross_cross + ab_ap * r0 + a_minus_b * r1) + T(4) * t9 * ab_ap * t8 - T(2) * ap_ap * J1) * in.w[2] * t8 + t9 * in.w[1] * t8;
    F = t10;
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = a_minus_b * t11 + ab_ap * t12;
    const T t14 = T(1) / cross_cross;
    const T t15 = ab_ap * t13 * t14 + t12 - t11;
    const T t16 = J1 + T(2) * ab_ap * t15 * t8 - t13 * ap_ap * t14;
    G_ap = in.w[0] * t13 * t14 + t15 * in.w[1] * t8 + t16 * in.w[2] * t8;
    G_ab = t16 * in.w[1] * t8 + in.w[0] * t15 * t8 - (t15 * ap_ap * t8 - t9 * t8 - T(2) * ab_ap * t16 * t8) * in.w[2] * t8;
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 39 +, 65 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 174 +, 261 ×, 25 /, 23 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    X = (t1 + r1 * ab_ap) * length / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = a_minus_b * r0;
    X = (a_minus_b - ab_ap) * length / (t2 - r1 * ab_ap);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
  const T t4 = cross_cross - T(2) * ab_ab * ab_ab;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = r1 + J1 * ab_ap - r0;
    const T t6 = T(1) / ab_ab;
    const T t7 = r1 * a_minus_b + cross_cross * J1 + r0 * ab_ap;
    const T t8 = T(2) * ap_ap * J1 - t7 * t6 - T(4) * t5 * t6 * ab_ap;
    F = in.w[0] * J1 + t5 * t6 * in.w[1] - (T(1) / T(6)) * in.w[3] * (T(6) * t8 * t6 * ab_ap + T(6) * t5 * ap_ap * t6 - (T(3) * t7 * t6 * ab_ap + T(2) * r1 * bp_bp - T(2) * ap_ap * r0) * t6) * t6 - (T(1) / T(2)) * in.w[2] * t8 * t6;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 51 +, 93 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 280 +, 1005 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = a_minus_b * r0;
    X = t1 * length * (t2 + ab_ap * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2];
    G_ab = in.w[1] * M_flat[2] + in.w[2] * M_flat[3] + M_flat[4] * in.w[3] + M_flat[1] * in.w[0];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = -ab_ap;
    const T t9 = J_downward<T>(3, ab_ab, cross_cross, t8, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / ab_ab;
    const T t11 = r0 - ab_ap * J1 - r1;
    const T t12 = T(1) / r1;
    const T t13 = T(1) / r0;
    const T t14 = t12 - t13 - ab_ap * t9;
    const T t15 = T(2) * t10 * ab_ap * t14 + ap_ap * t9 - J1;
    const T t16 = t10 * t11 + T(2) * t10 * t15 * ab_ap - t10 * ap_ap * t14;
    G_ap = in.w[0] * t9 - t10 * t16 * in.w[3] - t10 * in.w[1] * t14 - t10 * t15 * in.w[2];
    const T t17 = t10 * (t10 * (a_minus_b * r1 + ab_ap * r0 + cross_cross * J1) - T(4) * t10 * ab_ap * t11 - T(2) * J1 * ap_ap);
    G_ab = (T(1) / T(2)) * t10 * (T(2) * t10 * t15 * ap_ap + t17 - T(4) * t10 * ab_ap * t16) * in.w[3] - t10 * t16 * in.w[2] - t10 * t14 * in.w[0] - t10 * t15 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = ab_ap * t19 + a_minus_b * t20;
    const T t22 = T(1) / ab_ab;
    const T t23 = t20 - t19 - t18 * ab_ap * t21;
    const T t24 = r0 - ab_ap * J1 - r1;
    const T t25 = t18 * ap_ap * t21 + T(2) * t22 * t23 * ab_ap - J1;
    const T t26 = t22 * t23 * ap_ap - t22 * t24 - T(2) * t22 * ab_ap * t25;
    G_ap = t18 * in.w[0] * t21 + t22 * t26 * in.w[3] - t22 * in.w[1] * t23 - t22 * in.w[2] * t25;
    const T t27 = t22 * (t22 * (a_minus_b * r1 + ab_ap * r0 + cross_cross * J1) - T(4) * t22 * ab_ap * t24 - T(2) * J1 * ap_ap);
    G_ab = t22 * in.w[2] * t26 + (T(1) / T(2)) * t22 * (T(2) * t22 * ap_ap * t25 + t27 + T(4) * t22 * ab_ap * t26) * in.w[3] - t22 * in.w[1] * t25 - t22 * t23 * in.w[0];
  }
  const T g_factor = -length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 58 +, 117 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 287 +, 1029 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i1_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r0 * a_minus_b) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0];
    G_ab = in.w[0] * M_flat[6] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + M_flat[8] * in.w[2];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = T(1) / ab_ab;
    const T t9 = r0 - r1 - J1 * ab_ap;
    const T t10 = r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross;
    const T t11 = T(4) * t9 * t8 * ab_ap + T(2) * ap_ap * J1 - t10 * t8;
    const T t12 = J1 * in.w[0] + (T(1) / T(6)) * in.w[3] * t8 * (T(6) * t9 * ap_ap * t8 + t8 * (T(2) * r1 * bp_bp + T(3) * t10 * t8 * ab_ap - T(2) * ap_ap * r0) - T(6) * t11 * t8 * ab_ap) - t9 * t8 * in.w[1] - (T(1) / T(2)) * t11 * t8 * in.w[2];
    F = t12;
    const T t13 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = t14 + t13 * ab_ap - t15;
    const T t17 = J1 + T(2) * t8 * t16 * ab_ap - ap_ap * t13;
    const T t18 = ap_ap * t8 * t16 + t9 * t8 - T(2) * t8 * ab_ap * t17;
    G_ap = in.w[0] * t13 + t8 * t17 * in.w[2] + t8 * in.w[1] * t16 - in.w[3] * t8 * t18;
    G_ab = t8 * in.w[1] * t17 + in.w[0] * t8 * t16 - (T(1) / T(2)) * (T(4) * t8 * t18 * ab_ap + t11 * t8 + T(2) * ap_ap * t8 * t17) * in.w[3] * t8 - t8 * t18 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / ab_ab;
    const T t20 = r0 - r1 - J1 * ab_ap;
    const T t21 = r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross;
    const T t22 = T(4) * t20 * t19 * ab_ap + T(2) * ap_ap * J1 - t21 * t19;
    const T t23 = J1 * in.w[0] + (T(1) / T(6)) * in.w[3] * t19 * (T(6) * t20 * ap_ap * t19 + t19 * (T(2) * r1 * bp_bp + T(3) * t21 * t19 * ab_ap - T(2) * ap_ap * r0) - T(6) * t22 * t19 * ab_ap) - t20 * t19 * in.w[1] - (T(1) / T(2)) * t22 * t19 * in.w[2];
    F = t23;
    const T t24 = T(1) / r0;
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / r1;
    const T t27 = t24 * ab_ap + t26 * a_minus_b;
    const T t28 = t24 + t25 * t27 * ab_ap - t26;
    const T t29 = J1 + T(2) * t19 * ab_ap * t28 - ap_ap * t25 * t27;
    const T t30 = T(2) * t29 * t19 * ab_ap - ap_ap * t19 * t28 - t20 * t19;
    G_ap = in.w[3] * t19 * t30 + t19 * in.w[1] * t28 + t29 * t19 * in.w[2] + in.w[0] * t25 * t27;
    G_ab = t29 * t19 * in.w[1] + t19 * t30 * in.w[2] + in.w[0] * t19 * t28 + (T(1) / T(2)) * (T(4) * t19 * t30 * ab_ap - t22 * t19 - T(2) * ap_ap * t29 * t19) * in.w[3] * t19;
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Returns false where segment_inverse_i1_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 58 +, 117 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i1_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ap = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2];
    G_ab = M_flat[7] * in.w[1] + M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = ab_ap * J1 + r1 - r0;
    const T t9 = T(1) / ab_ab;
    const T t10 = a_minus_b * r1 + ab_ap * r0 + J1 * cross_cross;
    const T t11 = t10 * t9 + T(4) * ab_ap * t8 * t9 - T(2) * ap_ap * J1;
    const T t12 = in.w[1] * t8 * t9 + J1 * in.w[0] + (T(1) / T(2)) * in.w[2] * t9 * t11 - (T(1) / T(6)) * (t9 * (T(2) * ap_ap * r0 - T(2) * bp_bp * r1 - T(3) * ab_ap * t10 * t9) + T(6) * t8 * ap_ap * t9 - T(6) * ab_ap * t9 * t11) * in.w[3] * t9;
    F = t12;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = a_minus_b * t13 + ab_ap * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = t13 - ab_ap * t15 * t16 - t14;
    const T t18 = t8 * t9;
    const T t19 = ap_ap * t15 * t16 + T(2) * ab_ap * t17 * t9 - J1;
    const T t20 = ap_ap * t17 * t9 + t18 - T(2) * ab_ap * t19 * t9;
    G_ap = t15 * t16 * in.w[0] + t20 * in.w[3] * t9 - in.w[2] * t19 * t9 - in.w[1] * t17 * t9;
    const T t21 = t9 * t11;
    G_ab = (T(1) / T(2)) * (t21 + T(4) * ab_ap * t20 * t9 + T(2) * t19 * ap_ap * t9) * in.w[3] * t9 + in.w[2] * t20 * t9 - t17 * in.w[0] * t9 - in.w[1] * t19 * t9;
  }
  const T g_factor = -length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 28 +, 34 ×, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 839 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i2_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T J2 = atan2(t3, ap_bp) / t3;
    F = in.w[0] * J2;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 35 +, 53 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1542 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = T(1) / bp_bp;
    const T t7 = ab_ab * J2 + ab_ap * t5 + a_minus_b * t6;
    const T t8 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * t7 * in.w[0] * t8;
    G_ab = -(T(1) / T(2)) * (t6 - t7 * ab_ap * t8 - t5) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(2) * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 35 +, 56 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 265 +, 974 ×, 124 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i2_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * a_minus_b;
    const T t6 = T(1) / ap_ap;
    const T t7 = ab_ap * t6;
    const T t8 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -in.w[0] * t3 * (t5 + t7 - T(2) * cross_cross * t8);
    G_ap = in.w[0] * t8;
    G_ab = (T(1) / T(2)) * in.w[0] * t3 * (t6 + T(2) * t8 * ab_ap - t4);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, ap_bp);
    F = in.w[0] * J2;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * a_minus_b;
    const T t14 = T(1) / ap_ap;
    const T t15 = ab_ap * t14;
    const T t16 = t13 + t15 + ab_ab * J2;
    G_ap = (T(1) / T(2)) * in.w[0] * t11 * t16;
    const T t17 = T(1) / ab_ab;
    G_ab = (T(1) / T(2)) * in.w[0] * t17 * (t11 * t16 * ab_ap + t14 - t12);
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Returns false where segment_inverse_i2_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 35 +, 56 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i2_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    F = in.w[0] * J2;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = T(1) / ap_ap;
    const T t8 = t6 * a_minus_b + ab_ab * J2 + ab_ap * t7;
    G_ap = (T(1) / T(2)) * in.w[0] * t5 * t8;
    const T t9 = T(1) / ab_ab;
    G_ab = -(T(1) / T(2)) * in.w[0] * t9 * (t6 - t7 - t5 * t8 * ab_ap);
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 30 +, 39 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 260 +, 954 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ab_ab;
    F = (T(1) / T(2)) * (log_ratio + T(2) * ab_ap * t3) * in.w[1] * t4 + in.w[0] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(cross_cross);
    const T J2 = atan2(t5, ap_bp) / t5;
    const T t6 = T(1) / ab_ab;
    F = in.w[0] * J2 + (T(1) / T(2)) * (log_ratio + T(2) * ab_ap * J2) * in.w[1] * t6;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 39 +, 66 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2235 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = ab_ab * J2 + t5 * a_minus_b + ab_ap * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / ab_ab;
    const T t10 = t5 - t6 - t7 * ab_ap * t8;
    G_ap = (T(1) / T(2)) * t7 * in.w[0] * t8 - (T(1) / T(2)) * t9 * t10 * in.w[1];
    G_ab = -(T(1) / T(2)) * t9 * in.w[0] * t10 - (T(1) / T(2)) * t9 * (t7 * ap_ap * t8 + T(2) * t9 * ab_ap * t10 - T(2) * J2) * in.w[1];
  }
  const T g_factor = -T(2) * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 41 +, 74 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 271 +, 990 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / ab_ab;
    const T t5 = ab_ap * t0;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * a_minus_b;
    const T t8 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t5 + t7 - T(2) * cross_cross * t8;
    F = -t4 * t9 * in.w[0] - (T(1) / T(2)) * in.w[1] * t4 * (T(2) * t4 * t9 * ab_ap - log_ratio);
    const T t10 = t0 + T(2) * ab_ap * t8 - t6;
    G_ap = in.w[0] * t8 + (T(1) / T(2)) * in.w[1] * t4 * t10;
    G_ab = (T(1) / T(2)) * t4 * in.w[0] * t10 - in.w[1] * (t4 * t9 + t8 * ap_ap - t4 * ab_ap * t10) * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / ab_ab;
    F = J2 * in.w[0] + (T(1) / T(2)) * (T(2) * ab_ap * J2 + log_ratio) * in.w[1] * t13;
    const T t14 = T(1) / cross_cross;
    const T t15 = ab_ap * t0;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * a_minus_b;
    const T t18 = ab_ab * J2 + t15 + t17;
    const T t19 = t14 * ab_ap * t18 + t0 - t16;
    G_ap = (T(1) / T(2)) * t14 * in.w[0] * t18 + (T(1) / T(2)) * in.w[1] * t13 * t19;
    G_ab = (T(1) / T(2)) * in.w[1] * t13 * (T(2) * t13 * ab_ap * t19 + T(2) * J2 - t14 * t18 * ap_ap) + (T(1) / T(2)) * t13 * t19 * in.w[0];
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Returns false where segment_inverse_i2_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 74 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i2_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(1) / ab_ab;
    F = J2 * in.w[0] + (T(1) / T(2)) * in.w[1] * t6 * (T(2) * ab_ap * J2 + log_ratio);
    const T t7 = T(1) / cross_cross;
    const T t8 = ab_ap * t0;
    const T t9 = T(1) / bp_bp;
    const T t10 = a_minus_b * t9;
    const T t11 = J2 * ab_ab + t8 + t10;
    const T t12 = t9 - t0 - ab_ap * t7 * t11;
    G_ap = (T(1) / T(2)) * in.w[0] * t7 * t11 - (T(1) / T(2)) * in.w[1] * t6 * t12;
    G_ab = (T(1) / T(2)) * in.w[1] * t6 * (T(2) * J2 - ap_ap * t7 * t11 - T(2) * ab_ap * t6 * t12) - (T(1) / T(2)) * in.w[0] * t6 * t12;
  }
  const T g_factor = -T(2) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 33 +, 44 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 263 +, 959 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(2) * t3 * ab_ap + log_ratio;
    const T t5 = T(1) / ab_ab;
    F = (t4 * t5 * ab_ap + T(1) - ap_ap * t3) * in.w[2] * t5 + (T(1) / T(2)) * t4 * t5 * in.w[1] + in.w[0] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(cross_cross);
    const T J2 = atan2(t6, ap_bp) / t6;
    const T t7 = T(1) / ab_ab;
    const T t8 = T(2) * J2 * ab_ap + log_ratio;
    F = (T(1) / T(2)) * t7 * t8 * in.w[1] + J2 * in.w[0] - (ap_ap * J2 - t7 * t8 * ab_ap - T(1)) * in.w[2] * t7;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 44 +, 81 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 274 +, 995 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ab = M_flat[1] * in.w[0] + in.w[2] * M_flat[3] + M_flat[2] * in.w[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = t0 + T(2) * t4 * ab_ap - t5;
    const T t7 = T(1) / ab_ab;
    const T t8 = ab_ap * t0;
    const T t9 = a_minus_b * t5;
    const T t10 = t8 + t9 - T(2) * cross_cross * t4;
    const T t11 = t6 * t7 * ab_ap - t4 * ap_ap - t7 * t10;
    G_ap = (T(1) / T(2)) * t6 * t7 * in.w[1] + in.w[0] * t4 + in.w[2] * t7 * t11;
    G_ab = (T(1) / T(2)) * in.w[2] * t7 * (T(4) * t7 * ab_ap * t11 - t7 * (T(2) * t7 * ab_ap * t10 - log_ratio) - t6 * t7 * ap_ap) + (T(1) / T(2)) * t6 * t7 * in.w[0] + t7 * in.w[1] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / cross_cross;
    const T t16 = ab_ap * t0;
    const T t17 = T(1) / bp_bp;
    const T t18 = a_minus_b * t17;
    const T t19 = ab_ab * J2 + t16 + t18;
    const T t20 = t0 + t15 * ab_ap * t19 - t17;
    const T t21 = t15 * t19 * ap_ap - T(2) * J2 - T(2) * t14 * ab_ap * t20;
    G_ap = (T(1) / T(2)) * t14 * in.w[1] * t20 + (T(1) / T(2)) * t15 * in.w[0] * t19 - (T(1) / T(2)) * in.w[2] * t14 * t21;
    G_ab = (T(1) / T(2)) * t14 * in.w[0] * t20 - (T(1) / T(2)) * t14 * t21 * in.w[1] - (T(1) / T(2)) * in.w[2] * t14 * (t14 * ap_ap * t20 + T(2) * t14 * ab_ap * t21 - t14 * (T(2) * J2 * ab_ap + log_ratio));
  }
  const T g_factor = -T(2) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 48 +, 91 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 278 +, 1007 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[4] + in.w[1] * M_flat[5] + M_flat[6] * in.w[2];
    G_ab = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = ab_ap * t0;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * a_minus_b;
    const T t7 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = t4 + t6 - T(2) * cross_cross * t7;
    const T t9 = T(1) / ab_ab;
    const T t10 = T(2) * ab_ap * t8 * t9 - log_ratio;
    F = (t8 * ap_ap * t9 + T(1) - t10 * ab_ap * t9) * in.w[2] * t9 - in.w[0] * t8 * t9 - (T(1) / T(2)) * t10 * in.w[1] * t9;
    const T t11 = t5 - t0 - T(2) * ab_ap * t7;
    const T t12 = ab_ap * t11 * t9 + t8 * t9 + t7 * ap_ap;
    G_ap = in.w[0] * t7 - (T(1) / T(2)) * in.w[1] * t11 * t9 - t12 * in.w[2] * t9;
    G_ab = -(T(1) / T(2)) * in.w[0] * t11 * t9 - in.w[1] * t12 * t9 - (T(1) / T(2)) * (t10 * t9 + T(4) * ab_ap * t12 * t9 - ap_ap * t11 * t9) * in.w[2] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, ap_bp);
    const T t15 = T(2) * ab_ap * J2 + log_ratio;
    const T t16 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[1] * t15 * t16 + in.w[0] * J2 - (J2 * ap_ap - ab_ap * t15 * t16 - T(1)) * in.w[2] * t16;
    const T t17 = T(1) / bp_bp;
    const T t18 = T(1) / cross_cross;
    const T t19 = ab_ap * t0;
    const T t20 = t17 * a_minus_b;
    const T t21 = t19 + t20 + J2 * ab_ab;
    const T t22 = t17 - t0 - t18 * ab_ap * t21;
    const T t23 = T(2) * J2 - T(2) * ab_ap * t22 * t16 - t18 * ap_ap * t21;
    G_ap = (T(1) / T(2)) * t23 * in.w[2] * t16 + (T(1) / T(2)) * t18 * in.w[0] * t21 - (T(1) / T(2)) * in.w[1] * t22 * t16;
    G_ab = (T(1) / T(2)) * (ap_ap * t22 * t16 + t15 * t16 + T(2) * t23 * ab_ap * t16) * in.w[2] * t16 + (T(1) / T(2)) * t23 * in.w[1] * t16 - (T(1) / T(2)) * in.w[0] * t22 * t16;
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Returns false where segment_inverse_i2_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 48 +, 91 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i2_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
    G_ab = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = log_ratio + T(2) * ab_ap * J2;
    const T t7 = T(1) / ab_ab;
    F = in.w[0] * J2 + (T(1) / T(2)) * t6 * t7 * in.w[1] + (t6 * t7 * ab_ap + T(1) - ap_ap * J2) * in.w[2] * t7;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / bp_bp;
    const T t10 = ab_ab * J2 + t9 * a_minus_b + t0 * ab_ap;
    const T t11 = t0 + t8 * t10 * ab_ap - t9;
    const T t12 = T(2) * t7 * ab_ap * t11 + T(2) * J2 - ap_ap * t8 * t10;
    G_ap = (T(1) / T(2)) * t8 * in.w[0] * t10 + (T(1) / T(2)) * t7 * t11 * in.w[1] + (T(1) / T(2)) * t12 * in.w[2] * t7;
    G_ab = (T(1) / T(2)) * (T(2) * t12 * t7 * ab_ap + t6 * t7 - ap_ap * t7 * t11) * in.w[2] * t7 + (T(1) / T(2)) * t7 * in.w[0] * t11 + (T(1) / T(2)) * t12 * t7 * in.w[1];
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 38 +, 54 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 268 +, 969 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = J_downward<T>(2, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(2) * ab_ap * t4 + log_ratio;
    const T t6 = bp_bp + T(2) * ab_ap - ap_ap;
    const T t7 = t4 * ap_ap - t3 * t5 * ab_ap - T(1);
    F = (T(1) / T(2)) * t3 * in.w[1] * t5 + t4 * in.w[0] + (T(1) / T(2)) * (t3 * t6 - t3 * t5 * ap_ap - T(4) * t3 * ab_ap * t7) * t3 * in.w[3] - t3 * in.w[2] * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T J2 = atan2(t8, ap_bp) / t8;
    const T t9 = T(1) / ab_ab;
    const T t10 = T(2) * ab_ap * J2 + log_ratio;
    const T t11 = J2 * ap_ap - t9 * ab_ap * t10 - T(1);
    const T t12 = bp_bp + T(2) * ab_ap - ap_ap;
    F = (T(1) / T(2)) * t9 * in.w[1] * t10 + J2 * in.w[0] - (T(1) / T(2)) * t9 * (T(4) * t11 * t9 * ab_ap + t9 * ap_ap * t10 - t9 * t12) * in.w[3] - t11 * t9 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 50 +, 97 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 280 +, 1009 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -a_minus_b * ab_ap;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[3] * in.w[3];
    G_ab = in.w[2] * M_flat[3] + in.w[0] * M_flat[1] + M_flat[4] * in.w[3] + in.w[1] * M_flat[2];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 - t0 - T(2) * ab_ap * t4;
    const T t8 = a_minus_b * t6;
    const T t9 = ab_ap * t0;
    const T t10 = t8 + t9 - T(2) * cross_cross * t4;
    const T t11 = T(2) * t5 * ab_ap * t10 - log_ratio;
    const T t12 = t4 * ap_ap + t5 * t7 * ab_ap + t5 * t10;
    const T t13 = t5 * t11 + T(4) * t5 * ab_ap * t12 - t5 * t7 * ap_ap;
    G_ap = in.w[0] * t4 - (T(1) / T(2)) * t5 * t7 * in.w[1] - (T(1) / T(2)) * t5 * t13 * in.w[3] - t5 * in.w[2] * t12;
    G_ab = t5 * (t5 * (t5 * t10 * ap_ap + T(1) - t5 * t11 * ab_ap) + t5 * t12 * ap_ap - t5 * ab_ap * t13) * in.w[3] - (T(1) / T(2)) * t5 * in.w[2] * t13 - t5 * in.w[1] * t12 - (T(1) / T(2)) * in.w[0] * t5 * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, ap_bp) * t15;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / bp_bp;
    const T t19 = a_minus_b * t18;
    const T t20 = ab_ap * t0;
    const T t21 = t19 + t20 + ab_ab * J2;
    const T t22 = t18 - t17 * t21 * ab_ap - t0;
    const T t23 = T(2) * J2 - t17 * t21 * ap_ap - T(2) * t16 * ab_ap * t22;
    const T t24 = T(2) * J2 * ab_ap + log_ratio;
    const T t25 = T(2) * t16 * ab_ap * t23 + t16 * t22 * ap_ap + t16 * t24;
    G_ap = (T(1) / T(2)) * t16 * t25 * in.w[3] + (T(1) / T(2)) * t16 * in.w[2] * t23 + (T(1) / T(2)) * t17 * in.w[0] * t21 - (T(1) / T(2)) * t16 * in.w[1] * t22;
    G_ab = (T(1) / T(2)) * t16 * in.w[1] * t23 + (T(1) / T(2)) * t16 * (T(2) * t16 * t25 * ab_ap - T(2) * t16 * (J2 * ap_ap - t16 * ab_ap * t24 - T(1)) - t16 * ap_ap * t23) * in.w[3] + (T(1) / T(2)) * t16 * t25 * in.w[2] - (T(1) / T(2)) * in.w[0] * t16 * t22;
  }
  const T g_factor = -T(2) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 57 +, 114 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 287 +, 1027 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i2_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1];
    G_ap = M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[2] * M_flat[7];
    G_ab = M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1] + M_flat[6] * in.w[0];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / ab_ab;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * a_minus_b;
    const T t7 = t0 * ab_ap;
    const T t8 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t6 + t7 - T(2) * t8 * cross_cross;
    const T t10 = T(2) * t9 * t4 * ab_ap - log_ratio;
    const T t11 = t4 * ab_ap * t10 - ap_ap * t9 * t4 - T(1);
    const T t12 = (ap_ap - bp_bp - T(2) * ab_ap) * t4;
    F = -in.w[2] * t11 * t4 - (T(1) / T(2)) * in.w[3] * t4 * (T(4) * t11 * t4 * ab_ap + t12 - ap_ap * t4 * t10) - t9 * in.w[0] * t4 - (T(1) / T(2)) * t4 * in.w[1] * t10;
    const T t13 = t5 - t0 - T(2) * t8 * ab_ap;
    const T t14 = t8 * ap_ap + t4 * t13 * ab_ap + t9 * t4;
    const T t15 = ap_ap * t4 * t13 - t4 * t10 - T(4) * t4 * t14 * ab_ap;
    G_ap = t8 * in.w[0] + (T(1) / T(2)) * t15 * in.w[3] * t4 - in.w[2] * t4 * t14 - (T(1) / T(2)) * t4 * t13 * in.w[1];
    G_ab = (T(1) / T(2)) * in.w[2] * t15 * t4 + in.w[3] * t4 * (t15 * t4 * ab_ap + ap_ap * t4 * t14 - t11 * t4) - (T(1) / T(2)) * in.w[0] * t4 * t13 - t4 * t14 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(cross_cross);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, ap_bp);
    const T t18 = T(1) / ab_ab;
    const T t19 = T(2) * ab_ap * J2 + log_ratio;
    const T t20 = ap_ap * J2 - t18 * t19 * ab_ap - T(1);
    const T t21 = (ap_ap - bp_bp - T(2) * ab_ap) * t18;
    F = (T(1) / T(2)) * t18 * t19 * in.w[1] + in.w[0] * J2 - in.w[2] * t18 * t20 - (T(1) / T(2)) * in.w[3] * (ap_ap * t18 * t19 + t21 + T(4) * t18 * t20 * ab_ap) * t18;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * a_minus_b;
    const T t24 = t0 * ab_ap;
    const T t25 = t23 + t24 + ab_ab * J2;
    const T t26 = T(1) / cross_cross;
    const T t27 = t22 - t0 - t25 * t26 * ab_ap;
    const T t28 = ap_ap * t25 * t26 + T(2) * t27 * t18 * ab_ap - T(2) * J2;
    const T t29 = T(2) * t28 * t18 * ab_ap - t27 * ap_ap * t18 - t18 * t19;
    G_ap = (T(1) / T(2)) * t25 * t26 * in.w[0] - (T(1) / T(2)) * in.w[3] * t18 * t29 - (T(1) / T(2)) * t28 * in.w[2] * t18 - (T(1) / T(2)) * t27 * t18 * in.w[1];
    G_ab = -(T(1) / T(2)) * t27 * in.w[0] * t18 - (T(1) / T(2)) * (T(2) * t18 * t20 + T(2) * t18 * ab_ap * t29 - t28 * ap_ap * t18) * in.w[3] * t18 - (T(1) / T(2)) * in.w[2] * t18 * t29 - (T(1) / T(2)) * t28 * t18 * in.w[1];
  }
  const T g_factor = -T(2) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Returns false where segment_inverse_i2_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 57 +, 114 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i2_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[6] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
    G_ab = M_flat[9] * in.w[3] + in.w[0] * M_flat[6] + M_flat[8] * in.w[2] + M_flat[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(2) * ab_ap * J2 + log_ratio;
    const T t7 = T(1) / ab_ab;
    const T t8 = (bp_bp + T(2) * ab_ap - ap_ap) * t7;
    const T t9 = J2 * ap_ap - t6 * ab_ap * t7 - T(1);
    F = (T(1) / T(2)) * t6 * in.w[1] * t7 + J2 * in.w[0] + (T(1) / T(2)) * (t8 - t6 * ap_ap * t7 - T(4) * t9 * ab_ap * t7) * in.w[3] * t7 - t9 * in.w[2] * t7;
    const T t10 = ab_ap * t0;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * a_minus_b;
    const T t13 = t10 + J2 * ab_ab + t12;
    const T t14 = T(1) / cross_cross;
    const T t15 = t13 * ab_ap * t14 + t0 - t11;
    const T t16 = T(2) * J2 + T(2) * ab_ap * t15 * t7 - t13 * ap_ap * t14;
    const T t17 = ap_ap * t15 * t7 - t6 * t7 - T(2) * ab_ap * t16 * t7;
    G_ap = (T(1) / T(2)) * t16 * in.w[2] * t7 + (T(1) / T(2)) * in.w[1] * t15 * t7 + (T(1) / T(2)) * t13 * in.w[0] * t14 - (T(1) / T(2)) * t17 * in.w[3] * t7;
    G_ab = (T(1) / T(2)) * t15 * in.w[0] * t7 + (T(1) / T(2)) * in.w[1] * t16 * t7 - (T(1) / T(2)) * t17 * in.w[2] * t7 - (T(1) / T(2)) * (T(2) * t9 * t7 + t16 * ap_ap * t7 + T(2) * t17 * ab_ap * t7) * in.w[3] * t7;
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 27 +, 31 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 838 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i3_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = in.w[0] * (ab_ap / r0 + a_minus_b / r1) / cross_cross;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 34 +, 59 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1540 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t4 * t4;
    const T t8 = T(2) * t3 * ab_ab * (t4 * a_minus_b + ab_ap * t5) + ab_ap * t5 * t6 + t4 * a_minus_b * t7;
    G_ap = (T(1) / T(3)) * t8 * t3 * in.w[0];
    G_ab = (T(1) / T(3)) * (t8 * t3 * ab_ap + t5 * t6 - t4 * t7) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(3) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 34 +, 62 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1562 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i3_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * ab_ap + t5 * a_minus_b;
    F = in.w[0] * t3 * t6;
    const T t7 = t5 * t5;
    const T t8 = t4 * t4;
    const T t9 = t5 * t7 * a_minus_b + t4 * ab_ap * t8 + T(2) * t3 * ab_ab * t6;
    G_ap = (T(1) / T(3)) * in.w[0] * t3 * t9;
    G_ab = -(T(1) / T(3)) * in.w[0] * (t5 * t7 - t4 * t8 - t3 * t9 * ab_ap) / ab_ab;
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Returns false where segment_inverse_i3_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 34 +, 62 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i3_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = ab_ap * t3 + t4 * a_minus_b;
    const T t6 = T(1) / cross_cross;
    F = t5 * in.w[0] * t6;
    const T t7 = t4 * t4;
    const T t8 = t3 * t3;
    const T t9 = t7 * t4 * a_minus_b + T(2) * ab_ab * t5 * t6 + ab_ap * t8 * t3;
    G_ap = (T(1) / T(3)) * t9 * in.w[0] * t6;
    G_ab = (T(1) / T(3)) * (ab_ap * t9 * t6 + t8 * t3 - t7 * t4) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 30 +, 37 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1528 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i3_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * ab_ap;
    F = t3 * t6 * in.w[0] + (t5 + t3 * ab_ap * t6 - t4) * in.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 38 +, 73 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2233 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = ab_ap * t5 + a_minus_b * t3;
    const T t7 = T(1) / cross_cross;
    const T t8 = t5 * t5;
    const T t9 = a_minus_b * t4 * t3 + T(2) * t6 * t7 * ab_ab + ab_ap * t5 * t8;
    const T t10 = ab_ap * t9 * t7 + t5 * t8 - t4 * t3;
    const T t11 = T(1) / ab_ab;
    G_ap = (T(1) / T(3)) * t10 * in.w[1] * t11 + (T(1) / T(3)) * t9 * in.w[0] * t7;
    G_ab = (T(1) / T(3)) * in.w[0] * t10 * t11 + (T(1) / T(3)) * (T(3) * t6 * t7 + T(2) * ab_ap * t10 * t11 - t9 * ap_ap * t7) * in.w[1] * t11;
  }
  const T g_factor = -T(3) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 41 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 270 +, 999 ×, 124 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i3_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t4 * t5 * a_minus_b;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7 * ab_ap;
    const T t10 = J_downward<T>(5, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = t6 + t9 - T(3) * cross_cross * t10;
    F = -(T(1) / T(2)) * (t3 * t11 * ab_ap + T(2) * t4 - T(2) * t7) * in.w[1] * t3 - (T(1) / T(2)) * in.w[0] * t3 * t11;
    const T t12 = t8 * t7;
    const T t13 = t12 + T(3) * t10 * ab_ap - t4 * t5;
    G_ap = (T(1) / T(3)) * in.w[1] * t3 * t13 + in.w[0] * t10;
    G_ab = (T(1) / T(6)) * (T(4) * t3 * t13 * ab_ap - T(6) * ap_ap * t10 - T(3) * t3 * t11) * in.w[1] * t3 + (T(1) / T(3)) * in.w[0] * t3 * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = t14 * ab_ap + t15 * a_minus_b;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / ab_ab;
    F = in.w[0] * t16 * t17 + (t14 + t16 * t17 * ab_ap - t15) * in.w[1] * t18;
    const T t19 = t14 * t14;
    const T t20 = t19 * t14;
    const T t21 = t15 * t15;
    const T t22 = t15 * t21 * a_minus_b;
    const T t23 = t19 * t14 * ab_ap;
    const T t24 = t22 + t23 + T(2) * t16 * t17 * ab_ab;
    const T t25 = t20 + t17 * t24 * ab_ap - t15 * t21;
    G_ap = (T(1) / T(3)) * t25 * in.w[1] * t18 + (T(1) / T(3)) * in.w[0] * t17 * t24;
    G_ab = (T(1) / T(3)) * in.w[1] * t18 * (T(3) * t16 * t17 + T(2) * t25 * t18 * ab_ap - ap_ap * t17 * t24) + (T(1) / T(3)) * in.w[0] * t25 * t18;
  }
  const T g_factor = -T(3) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Returns false where segment_inverse_i3_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i3_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = t3 * a_minus_b + ab_ap * t4;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ab_ab;
    F = t5 * in.w[0] * t6 - (t3 - t5 * ab_ap * t6 - t4) * in.w[1] * t7;
    const T t8 = t4 * t4;
    const T t9 = ab_ap * t8 * t4;
    const T t10 = t3 * t3;
    const T t11 = t3 * t10 * a_minus_b;
    const T t12 = t9 + t11 + T(2) * t5 * t6 * ab_ab;
    const T t13 = t3 * t10;
    const T t14 = t13 - t8 * t4 - t12 * ab_ap * t6;
    G_ap = (T(1) / T(3)) * t12 * in.w[0] * t6 - (T(1) / T(3)) * t14 * in.w[1] * t7;
    G_ab = -(T(1) / T(3)) * t14 * in.w[0] * t7 - (T(1) / T(3)) * (T(2) * ab_ap * t14 * t7 + t12 * ap_ap * t6 - T(3) * t5 * t6) * in.w[1] * t7;
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 34 +, 51 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 263 +, 963 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i3_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = ab_ap * r1;
    X = t1 * length * (t2 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = T(1) / r0;
    const T t9 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / r1;
    const T t11 = t8 + t9 * ab_ap - t10;
    const T t12 = T(1) / ab_ab;
    F = in.w[1] * t11 * t12 + t9 * in.w[0] + in.w[2] * t12 * (T(2) * ab_ap * t11 * t12 + J1 - t9 * ap_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r0;
    const T t14 = T(1) / r1;
    const T t15 = ab_ap * t13 + t14 * a_minus_b;
    const T t16 = T(1) / cross_cross;
    const T t17 = t13 + t15 * ab_ap * t16 - t14;
    const T t18 = T(1) / ab_ab;
    F = t17 * in.w[1] * t18 + t15 * t16 * in.w[0] - in.w[2] * t18 * (t15 * ap_ap * t16 - T(2) * ab_ap * t17 * t18 - J1);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 44 +, 88 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2928 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ab = M_flat[3] * in.w[2] + in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / r1;
    const T t7 = t3 * ab_ap + t6 * a_minus_b;
    const T t8 = t6 * t6;
    const T t9 = T(2) * t5 * ab_ab * t7 + t6 * a_minus_b * t8 + t3 * t4 * ab_ap;
    const T t10 = t3 * t4 + t5 * t9 * ab_ap - t6 * t8;
    const T t11 = T(1) / ab_ab;
    const T t12 = T(2) * t10 * t11 * ab_ap + T(3) * t5 * t7 - ap_ap * t5 * t9;
    G_ap = (T(1) / T(3)) * in.w[1] * t10 * t11 + (T(1) / T(3)) * t5 * t9 * in.w[0] + (T(1) / T(3)) * in.w[2] * t11 * t12;
    G_ab = (T(1) / T(3)) * in.w[1] * t11 * t12 + (T(1) / T(3)) * t10 * t11 * in.w[0] - (T(1) / T(3)) * in.w[2] * t11 * (ap_ap * t10 * t11 + T(3) * t11 * (t6 - t5 * t7 * ab_ap - t3) - T(2) * t11 * t12 * ab_ap);
  }
  const T g_factor = -T(3) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 49 +, 106 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 278 +, 1028 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i3_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r0 * a_minus_b;
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
    G_ap = in.w[0] * M_flat[4] + in.w[1] * M_flat[5] + in.w[2] * M_flat[6];
    G_ab = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8 * ab_ap;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t11 * t12 * a_minus_b;
    const T t14 = J_downward<T>(5, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = t10 + t13 - T(3) * cross_cross * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(2) * t8 - t15 * t16 * ab_ap - T(2) * t11;
    F = (T(1) / T(2)) * in.w[1] * t17 * t16 + (T(1) / T(2)) * (T(2) * t17 * t16 * ab_ap + T(2) * J1 + ap_ap * t15 * t16) * in.w[2] * t16 - (T(1) / T(2)) * t15 * t16 * in.w[0];
    const T t18 = t9 * t8;
    const T t19 = t18 + T(3) * t14 * ab_ap - t11 * t12;
    const T t20 = T(6) * ap_ap * t14 + T(3) * t15 * t16 - T(4) * t19 * t16 * ab_ap;
    G_ap = in.w[0] * t14 + (T(1) / T(3)) * t19 * in.w[1] * t16 - (T(1) / T(6)) * in.w[2] * t16 * t20;
    G_ab = (T(1) / T(3)) * t19 * t16 * in.w[0] - (T(1) / T(6)) * in.w[2] * (T(2) * t16 * t20 * ab_ap + T(2) * t19 * ap_ap * t16 - T(3) * t17 * t16) * t16 - (T(1) / T(6)) * in.w[1] * t16 * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / r1;
    const T t22 = T(1) / r0;
    const T t23 = t21 * a_minus_b + t22 * ab_ap;
    const T t24 = T(1) / cross_cross;
    const T t25 = t22 + t23 * t24 * ab_ap - t21;
    const T t26 = T(1) / ab_ab;
    F = t23 * t24 * in.w[0] + in.w[1] * t25 * t26 + (T(2) * t25 * t26 * ab_ap + J1 - ap_ap * t23 * t24) * in.w[2] * t26;
    const T t27 = t22 * t22;
    const T t28 = t27 * t22;
    const T t29 = t27 * t22 * ab_ap;
    const T t30 = t21 * t21;
    const T t31 = t21 * t30 * a_minus_b;
    const T t32 = t29 + T(2) * t23 * t24 * ab_ab + t31;
    const T t33 = t28 + t32 * t24 * ab_ap - t21 * t30;
    const T t34 = T(3) * t23 * t24 + T(2) * t26 * t33 * ab_ap - t32 * ap_ap * t24;
    G_ap = (T(1) / T(3)) * in.w[1] * t26 * t33 + (T(1) / T(3)) * t32 * t24 * in.w[0] + (T(1) / T(3)) * in.w[2] * t26 * t34;
    G_ab = (T(1) / T(3)) * t26 * in.w[0] * t33 + (T(1) / T(3)) * in.w[1] * t26 * t34 - (T(1) / T(3)) * in.w[2] * t26 * (ap_ap * t26 * t33 - T(3) * t25 * t26 - T(2) * t26 * t34 * ab_ap);
  }
  const T g_factor = -T(3) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Returns false where segment_inverse_i3_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 106 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i3_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / cross_cross;
    X = length * (t1 + r1 * ab_ap) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + in.w[2] * M_flat[6];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r1;
    const T t9 = T(1) / r0;
    const T t10 = t8 * a_minus_b + ab_ap * t9;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / ab_ab;
    const T t13 = t9 + ab_ap * t10 * t11 - t8;
    F = in.w[0] * t10 * t11 + t12 * in.w[1] * t13 - t12 * (ap_ap * t10 * t11 - T(2) * t12 * ab_ap * t13 - J1) * in.w[2];
    const T t14 = t8 * t8;
    const T t15 = t8 * t14 * a_minus_b;
    const T t16 = t9 * t9;
    const T t17 = ab_ap * t16 * t9;
    const T t18 = t15 + T(2) * ab_ab * t10 * t11 + t17;
    const T t19 = t18 * ab_ap * t11 + t16 * t9 - t8 * t14;
    const T t20 = T(3) * t10 * t11 + T(2) * t12 * t19 * ab_ap - t18 * ap_ap * t11;
    G_ap = (T(1) / T(3)) * t12 * t20 * in.w[2] + (T(1) / T(3)) * t12 * t19 * in.w[1] + (T(1) / T(3)) * in.w[0] * t18 * t11;
    G_ab = (T(1) / T(3)) * t12 * in.w[1] * t20 + (T(1) / T(3)) * t12 * t19 * in.w[0] + (T(1) / T(3)) * t12 * (T(3) * t12 * t13 + T(2) * t12 * ab_ap * t20 - t12 * t19 * ap_ap) * in.w[2];
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 39 +, 60 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 268 +, 972 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i3_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = ab_ap * r1;
    X = t1 * (t2 + a_minus_b * r0) * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = length * (ab_ap - a_minus_b) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t8 = T(1) / ab_ab;
    const T t9 = (r1 + ab_ap * J1 - r0) * t8;
    const T t10 = J_downward<T>(3, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = T(1) / r0;
    const T t12 = T(1) / r1;
    const T t13 = t10 * ab_ap + t11 - t12;
    const T t14 = T(2) * ab_ap * t13 * t8 + J1 - t10 * ap_ap;
    F = in.w[3] * (t9 + T(2) * ab_ap * t8 * t14 - ap_ap * t13 * t8) * t8 + t10 * in.w[0] + in.w[2] * t8 * t14 + t13 * t8 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / ab_ab;
    const T t16 = (r1 + ab_ap * J1 - r0) * t15;
    const T t17 = T(1) / r1;
    const T t18 = T(1) / r0;
    const T t19 = t17 * a_minus_b + ab_ap * t18;
    const T t20 = T(1) / cross_cross;
    const T t21 = ab_ap * t19 * t20 + t18 - t17;
    const T t22 = T(2) * ab_ap * t21 * t15 + J1 - ap_ap * t19 * t20;
    F = in.w[3] * (t16 + T(2) * ab_ap * t22 * t15 - t21 * ap_ap * t15) * t15 + t19 * t20 * in.w[0] + t21 * t15 * in.w[1] + in.w[2] * t22 * t15;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 51 +, 112 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 280 +, 1031 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = a_minus_b * r0;
    X = t1 * length * (t2 + ab_ap * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -a_minus_b * ab_ap;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ab = in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + in.w[2] * M_flat[3];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t8 = -ab_ap;
    const T t9 = J_downward<T>(5, ab_ab, cross_cross, t8, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t11 * t12;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t13 + T(3) * t9 * ab_ap - t15 * t14;
    const T t17 = ab_ap * t11 * t12;
    const T t18 = a_minus_b * t15 * t14;
    const T t19 = t17 + t18 - T(3) * cross_cross * t9;
    const T t20 = T(3) * t10 * t19 + T(6) * t9 * ap_ap - T(4) * t10 * t16 * ab_ap;
    const T t21 = T(2) * t14 + t10 * ab_ap * t19 - T(2) * t11;
    const T t22 = T(2) * t10 * t16 * ap_ap + T(3) * t10 * t21 + T(2) * t10 * t20 * ab_ap;
    G_ap = in.w[0] * t9 + (T(1) / T(3)) * t10 * t16 * in.w[1] - (T(1) / T(6)) * t10 * t20 * in.w[2] - (T(1) / T(6)) * in.w[3] * t22 * t10;
    G_ab = (T(1) / T(3)) * in.w[0] * t10 * t16 - (T(1) / T(6)) * in.w[3] * t10 * (T(2) * t22 * t10 * ab_ap - t10 * t20 * ap_ap - T(3) * t10 * (t10 * t19 * ap_ap + T(2) * J1 - T(2) * t10 * t21 * ab_ap)) - (T(1) / T(6)) * t10 * t20 * in.w[1] - (T(1) / T(6)) * t22 * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / cross_cross;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = ab_ap * t24 * t25;
    const T t27 = T(1) / r1;
    const T t28 = t27 * t27;
    const T t29 = a_minus_b * t28 * t27;
    const T t30 = a_minus_b * t27 + ab_ap * t24;
    const T t31 = t26 + t29 + T(2) * t23 * ab_ab * t30;
    const T t32 = T(1) / ab_ab;
    const T t33 = t24 * t25;
    const T t34 = t33 + t23 * t31 * ab_ap - t28 * t27;
    const T t35 = T(2) * t32 * t34 * ab_ap + T(3) * t23 * t30 - t23 * t31 * ap_ap;
    const T t36 = t23 * ab_ap * t30 + t24 - t27;
    const T t37 = T(3) * t32 * t36 + T(2) * t32 * ab_ap * t35 - t32 * t34 * ap_ap;
    G_ap = (T(1) / T(3)) * t23 * in.w[0] * t31 + (T(1) / T(3)) * t32 * in.w[2] * t35 + (T(1) / T(3)) * t32 * t34 * in.w[1] + (T(1) / T(3)) * in.w[3] * t32 * t37;
    G_ab = (T(1) / T(3)) * t32 * t37 * in.w[2] + (T(1) / T(3)) * t32 * in.w[1] * t35 + (T(1) / T(3)) * in.w[0] * t32 * t34 + (T(1) / T(3)) * in.w[3] * t32 * (T(2) * t32 * t37 * ab_ap - T(3) * t32 * (t23 * t30 * ap_ap - J1 - T(2) * t32 * ab_ap * t36) - t32 * ap_ap * t35);
  }
  const T g_factor = -T(3) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 58 +, 128 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 287 +, 1052 ×, 126 /, 5 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i3_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r0 * a_minus_b;
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ap = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1];
    G_ab = M_flat[8] * in.w[2] + in.w[1] * M_flat[7] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3];
  } else if (t6 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t8 = T(1) / ab_ab;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 * t9;
    const T t12 = t11 * t9 * ab_ap;
    const T t13 = t10 * t10;
    const T t14 = t10 * t13 * a_minus_b;
    const T t15 = J_downward<T>(5, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t16 = t12 + t14 - T(3) * cross_cross * t15;
    const T t17 = T(2) * t9 - T(2) * t10 - t8 * ab_ap * t16;
    const T t18 = T(2) * J1 + ap_ap * t8 * t16 + T(2) * t8 * ab_ap * t17;
    const T t19 = r0 - J1 * ab_ap - r1;
    F = (T(1) / T(2)) * t8 * in.w[1] * t17 + (T(1) / T(2)) * (T(2) * t8 * t18 * ab_ap - ap_ap * t8 * t17 - T(2) * t8 * t19) * in.w[3] * t8 + (T(1) / T(2)) * in.w[2] * t8 * t18 - (T(1) / T(2)) * in.w[0] * t8 * t16;
    const T t20 = t11 * t9;
    const T t21 = t20 + T(3) * t15 * ab_ap - t10 * t13;
    const T t22 = T(3) * t8 * t16 + T(6) * ap_ap * t15 - T(4) * t21 * t8 * ab_ap;
    const T t23 = T(2) * ap_ap * t21 * t8 + T(2) * t8 * ab_ap * t22 - T(3) * t8 * t17;
    G_ap = (T(1) / T(3)) * t21 * t8 * in.w[1] + in.w[0] * t15 - (T(1) / T(6)) * in.w[2] * t8 * t22 - (T(1) / T(6)) * in.w[3] * t8 * t23;
    G_ab = (T(1) / T(6)) * (ap_ap * t8 * t22 + T(3) * t8 * t18 - T(2) * t8 * t23 * ab_ap) * in.w[3] * t8 + (T(1) / T(3)) * t21 * in.w[0] * t8 - (T(1) / T(6)) * t8 * in.w[1] * t22 - (T(1) / T(6)) * in.w[2] * t8 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = t24 * ab_ap + t25 * a_minus_b;
    const T t27 = T(1) / cross_cross;
    const T t28 = t24 + t26 * t27 * ab_ap - t25;
    const T t29 = T(1) / ab_ab;
    const T t30 = t26 * ap_ap * t27 - T(2) * t28 * t29 * ab_ap - J1;
    const T t31 = r0 - J1 * ab_ap - r1;
    F = t26 * in.w[0] * t27 + t28 * t29 * in.w[1] - in.w[2] * t29 * t30 - in.w[3] * t29 * (t29 * t31 + T(2) * t29 * t30 * ab_ap + ap_ap * t28 * t29);
    const T t32 = t24 * t24;
    const T t33 = t32 * t24;
    const T t34 = t32 * t24 * ab_ap;
    const T t35 = t25 * t25;
    const T t36 = t25 * t35 * a_minus_b;
    const T t37 = t34 + t36 + T(2) * t26 * t27 * ab_ab;
    const T t38 = t33 + t27 * t37 * ab_ap - t25 * t35;
    const T t39 = T(3) * t26 * t27 + T(2) * t29 * ab_ap * t38 - ap_ap * t27 * t37;
    const T t40 = ap_ap * t29 * t38 - T(2) * t39 * t29 * ab_ap - T(3) * t28 * t29;
    G_ap = (T(1) / T(3)) * t29 * in.w[1] * t38 + (T(1) / T(3)) * in.w[2] * t39 * t29 + (T(1) / T(3)) * in.w[0] * t27 * t37 - (T(1) / T(3)) * in.w[3] * t29 * t40;
    G_ab = (T(1) / T(3)) * in.w[0] * t29 * t38 + (T(1) / T(3)) * t39 * t29 * in.w[1] - (T(1) / T(3)) * in.w[2] * t29 * t40 - (T(1) / T(3)) * (ap_ap * t39 * t29 + T(2) * t29 * ab_ap * t40 + T(3) * t29 * t30) * in.w[3] * t29;
  }
  const T g_factor = -T(3) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Returns false where segment_inverse_i3_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 58 +, 128 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i3_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / cross_cross;
    X = (t1 + r1 * ab_ap) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t6 = -ab_ap * a_minus_b;
  const T t7 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2];
    G_ap = M_flat[8] * in.w[3] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
    G_ab = M_flat[6] * in.w[0] + in.w[1] * M_flat[7] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / r1;
    const T t11 = t10 * a_minus_b + t8 * ab_ap;
    const T t12 = t8 + t9 * t11 * ab_ap - t10;
    const T t13 = T(1) / ab_ab;
    const T t14 = J1 + T(2) * t12 * t13 * ab_ap - ap_ap * t9 * t11;
    const T t15 = J1 * ab_ap + r1 - r0;
    F = in.w[1] * t12 * t13 + in.w[2] * t13 * t14 + t9 * t11 * in.w[0] - (ap_ap * t12 * t13 - t15 * t13 - T(2) * t13 * ab_ap * t14) * t13 * in.w[3];
    const T t16 = t10 * t10;
    const T t17 = t10 * t16;
    const T t18 = t8 * t8;
    const T t19 = t10 * t16 * a_minus_b;
    const T t20 = t18 * t8 * ab_ap;
    const T t21 = t19 + t20 + T(2) * t9 * ab_ab * t11;
    const T t22 = t17 - t18 * t8 - t21 * t9 * ab_ap;
    const T t23 = T(2) * t22 * t13 * ab_ap + ap_ap * t21 * t9 - T(3) * t9 * t11;
    const T t24 = T(3) * t12 * t13 + ap_ap * t22 * t13 - T(2) * t13 * t23 * ab_ap;
    G_ap = (T(1) / T(3)) * t24 * t13 * in.w[3] + (T(1) / T(3)) * t21 * t9 * in.w[0] - (T(1) / T(3)) * in.w[2] * t13 * t23 - (T(1) / T(3)) * in.w[1] * t22 * t13;
    G_ab = (T(1) / T(3)) * t13 * in.w[3] * (T(3) * t13 * t14 + T(2) * t24 * t13 * ab_ap + ap_ap * t13 * t23) + (T(1) / T(3)) * in.w[2] * t24 * t13 - (T(1) / T(3)) * t22 * t13 * in.w[0] - (T(1) / T(3)) * in.w[1] * t13 * t23;
  }
  const T g_factor = -T(3) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t6 >= T(0) && t7 >= T(0)) && !(t5 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 30 +, 38 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 843 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    F = (T(1) / T(2)) * (J2 * ab_ab + a_minus_b / bp_bp + ab_ap / ap_ap) * in.w[0] * t5;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 37 +, 64 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1545 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(2) * ab_ap * t6 + T(2) * a_minus_b * t8 + T(3) * t9 * (ab_ab * J2 + a_minus_b * t7 + ab_ap * t5) * ab_ab;
    G_ap = (T(1) / T(8)) * in.w[0] * t10 * t9;
    G_ab = -(T(1) / T(8)) * (T(2) * t8 - ab_ap * t10 * t9 - T(2) * t6) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(4) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 37 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1568 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = t5 * a_minus_b + ab_ap * t6 + J2 * ab_ab;
    const T t8 = T(1) / cross_cross;
    F = (T(1) / T(2)) * t7 * in.w[0] * t8;
    const T t9 = t6 * t6;
    const T t10 = t5 * t5;
    const T t11 = T(3) * t7 * t8 * ab_ab + T(2) * ab_ap * t9 + T(2) * t10 * a_minus_b;
    G_ap = (T(1) / T(8)) * t11 * in.w[0] * t8;
    G_ab = (T(1) / T(8)) * (ab_ap * t11 * t8 + T(2) * t9 - T(2) * t10) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Returns false where segment_inverse_i4_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 37 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i4_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = a_minus_b * t5 + ab_ab * J2 + t6 * ab_ap;
    const T t8 = T(1) / cross_cross;
    F = (T(1) / T(2)) * t7 * in.w[0] * t8;
    const T t9 = t6 * t6;
    const T t10 = t5 * t5;
    const T t11 = T(2) * t9 * ab_ap + T(3) * t7 * t8 * ab_ab + T(2) * a_minus_b * t10;
    G_ap = (T(1) / T(8)) * t11 * in.w[0] * t8;
    G_ab = (T(1) / T(8)) * (T(2) * t9 + t11 * t8 * ab_ap - T(2) * t10) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(4) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 33 +, 44 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1533 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = T(1) / bp_bp;
    const T t7 = a_minus_b * t6 + ab_ap * t5 + J2 * ab_ab;
    const T t8 = T(1) / cross_cross;
    F = (T(1) / T(2)) * (t5 + ab_ap * t7 * t8 - t6) * in.w[1] / ab_ab + (T(1) / T(2)) * in.w[0] * t7 * t8;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 41 +, 78 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2238 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / bp_bp;
    const T t9 = ab_ab * J2 + a_minus_b * t8 + t5 * ab_ap;
    const T t10 = t8 * t8;
    const T t11 = T(2) * t6 * ab_ap + T(3) * t7 * ab_ab * t9 + T(2) * a_minus_b * t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(2) * t6 + t11 * t7 * ab_ap - T(2) * t10;
    G_ap = (T(1) / T(8)) * in.w[0] * t11 * t7 + (T(1) / T(8)) * in.w[1] * t12 * t13;
    G_ab = (T(1) / T(8)) * in.w[0] * t12 * t13 - (T(1) / T(8)) * in.w[1] * (ap_ap * t11 * t7 - T(4) * t7 * t9 - T(2) * t12 * t13 * ab_ap) * t12;
  }
  const T g_factor = -T(4) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 44 +, 87 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2275 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = in.w[1] * M_beyond[4] + in.w[0] * M_beyond[3];
    G_ab = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = J2 * ab_ab + a_minus_b * t5 + t6 * ab_ap;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[0] * t7 * t8 + (T(1) / T(2)) * (t7 * t8 * ab_ap + t6 - t5) * in.w[1] * t9;
    const T t10 = t6 * t6;
    const T t11 = t5 * t5;
    const T t12 = T(2) * t10 * ab_ap + T(3) * t7 * ab_ab * t8 + T(2) * a_minus_b * t11;
    const T t13 = T(2) * t10 + t12 * t8 * ab_ap - T(2) * t11;
    G_ap = (T(1) / T(8)) * in.w[0] * t12 * t8 + (T(1) / T(8)) * in.w[1] * t9 * t13;
    G_ab = (T(1) / T(8)) * in.w[0] * t9 * t13 - (T(1) / T(8)) * (ap_ap * t12 * t8 - T(4) * t7 * t8 - T(2) * t9 * t13 * ab_ap) * in.w[1] * t9;
  }
  const T g_factor = -T(4) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Returns false where segment_inverse_i4_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 44 +, 87 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i4_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = t5 * a_minus_b + J2 * ab_ab + ab_ap * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[0] * t7 * t8 + (T(1) / T(2)) * (t6 + ab_ap * t7 * t8 - t5) * in.w[1] * t9;
    const T t10 = t6 * t6;
    const T t11 = t5 * t5;
    const T t12 = T(2) * ab_ap * t10 + T(2) * t11 * a_minus_b + T(3) * t7 * t8 * ab_ab;
    const T t13 = T(2) * t11 - T(2) * t10 - ab_ap * t12 * t8;
    G_ap = (T(1) / T(8)) * in.w[0] * t12 * t8 - (T(1) / T(8)) * t13 * in.w[1] * t9;
    G_ab = -(T(1) / T(8)) * (T(2) * ab_ap * t13 * t9 + t12 * ap_ap * t8 - T(4) * t7 * t8) * in.w[1] * t9 - (T(1) / T(8)) * in.w[0] * t13 * t9;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 36 +, 54 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2225 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = t5 * a_minus_b + ab_ab * J2 + t6 * ab_ap;
    const T t8 = T(1) / cross_cross;
    const T t9 = t7 * t8 * ab_ap + t6 - t5;
    const T t10 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[2] * (T(2) * t9 * t10 * ab_ap + T(2) * J2 - ap_ap * t7 * t8) * t10 + (T(1) / T(2)) * t7 * t8 * in.w[0] + (T(1) / T(2)) * in.w[1] * t9 * t10;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 47 +, 93 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2933 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(1) / ap_ap;
    const T t7 = t5 * a_minus_b + ab_ap * t6 + ab_ab * J2;
    const T t8 = T(1) / cross_cross;
    const T t9 = t6 * t6;
    const T t10 = t5 * t5;
    const T t11 = T(3) * t7 * t8 * ab_ab + T(2) * ab_ap * t9 + T(2) * t10 * a_minus_b;
    const T t12 = T(2) * t10 - T(2) * t9 - ab_ap * t11 * t8;
    const T t13 = T(1) / ab_ab;
    const T t14 = T(2) * ab_ap * t12 * t13 + ap_ap * t11 * t8 - T(4) * t7 * t8;
    G_ap = (T(1) / T(8)) * in.w[0] * t11 * t8 - (T(1) / T(8)) * t14 * in.w[2] * t13 - (T(1) / T(8)) * t12 * in.w[1] * t13;
    G_ab = -(T(1) / T(8)) * in.w[0] * t12 * t13 - (T(1) / T(8)) * t14 * in.w[1] * t13 - (T(1) / T(8)) * in.w[2] * (T(2) * ab_ap * t14 * t13 - t12 * ap_ap * t13 - T(4) * (ab_ap * t7 * t8 + t6 - t5) * t13) * t13;
  }
  const T g_factor = -T(4) * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 51 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 281 +, 1030 ×, 124 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i4_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[4] + in.w[1] * M_flat[5] + in.w[2] * M_flat[6];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t3 = T(1) / ap_ap;
    const T t4 = T(1) / bp_bp;
    const T t5 = T(1) / ab_ab;
    const T t6 = t3 * t3;
    const T t7 = t4 * t4;
    const T t8 = J_downward<T>(6, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = ab_ap * t6 + t7 * a_minus_b - T(4) * t8 * cross_cross;
    const T t10 = T(3) * t3 - T(3) * t4 - T(2) * ab_ap * t5 * t9;
    F = (T(1) / T(3)) * (ab_ap * t10 * t5 + ap_ap * t5 * t9 - (T(3) * t4 * a_minus_b + T(2) * cross_cross * t5 * t9 + T(3) * ab_ap * t3) * t5) * in.w[2] * t5 + (T(1) / T(6)) * in.w[1] * t10 * t5 - (T(1) / T(3)) * in.w[0] * t5 * t9;
    const T t11 = t7 - T(4) * t8 * ab_ap - t6;
    const T t12 = T(3) * ab_ap * t11 * t5 + T(2) * t5 * t9 + T(6) * t8 * ap_ap;
    G_ap = t8 * in.w[0] - (T(1) / T(4)) * in.w[1] * t11 * t5 - (T(1) / T(6)) * in.w[2] * t12 * t5;
    G_ab = (T(1) / T(12)) * (T(3) * ap_ap * t11 * t5 + T(2) * t10 * t5 - T(4) * ab_ap * t12 * t5) * in.w[2] * t5 - (T(1) / T(6)) * in.w[1] * t12 * t5 - (T(1) / T(4)) * in.w[0] * t11 * t5;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / ap_ap;
    const T t16 = T(1) / bp_bp;
    const T t17 = J2 * ab_ab + t16 * a_minus_b + ab_ap * t15;
    const T t18 = T(1) / cross_cross;
    const T t19 = t15 + ab_ap * t17 * t18 - t16;
    const T t20 = T(1) / ab_ab;
    F = (T(1) / T(2)) * (T(2) * J2 + T(2) * ab_ap * t19 * t20 - t17 * ap_ap * t18) * in.w[2] * t20 + (T(1) / T(2)) * t19 * in.w[1] * t20 + (T(1) / T(2)) * in.w[0] * t17 * t18;
    const T t21 = t15 * t15;
    const T t22 = t16 * t16;
    const T t23 = T(2) * ab_ap * t21 + T(3) * t17 * t18 * ab_ab + T(2) * t22 * a_minus_b;
    const T t24 = T(2) * t22 - ab_ap * t18 * t23 - T(2) * t21;
    const T t25 = ap_ap * t18 * t23 + T(2) * ab_ap * t24 * t20 - T(4) * t17 * t18;
    G_ap = (T(1) / T(8)) * in.w[0] * t18 * t23 - (T(1) / T(8)) * in.w[1] * t24 * t20 - (T(1) / T(8)) * t25 * in.w[2] * t20;
    G_ab = (T(1) / T(8)) * in.w[2] * t20 * (ap_ap * t24 * t20 + T(4) * t19 * t20 - T(2) * ab_ap * t25 * t20) - (T(1) / T(8)) * in.w[1] * t25 * t20 - (T(1) / T(8)) * in.w[0] * t24 * t20;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Returns false where segment_inverse_i4_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 51 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i4_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[4] + in.w[1] * M_flat[5] + in.w[2] * M_flat[6];
    G_ab = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = T(1) / bp_bp;
    const T t8 = ab_ab * J2 + ab_ap * t6 + t7 * a_minus_b;
    const T t9 = T(1) / cross_cross;
    const T t10 = t8 * t9 * ab_ap + t6 - t7;
    F = (T(1) / T(2)) * t5 * in.w[1] * t10 + (T(1) / T(2)) * t8 * t9 * in.w[0] + (T(1) / T(2)) * in.w[2] * (T(2) * J2 + T(2) * t5 * ab_ap * t10 - t8 * t9 * ap_ap) * t5;
    const T t11 = t7 * t7;
    const T t12 = t6 * t6;
    const T t13 = T(2) * t11 * a_minus_b + T(2) * ab_ap * t12 + T(3) * t8 * t9 * ab_ab;
    const T t14 = T(2) * t11 - t9 * ab_ap * t13 - T(2) * t12;
    const T t15 = T(2) * t14 * t5 * ab_ap + t9 * ap_ap * t13 - T(4) * t8 * t9;
    G_ap = (T(1) / T(8)) * t9 * in.w[0] * t13 - (T(1) / T(8)) * in.w[2] * t5 * t15 - (T(1) / T(8)) * t14 * t5 * in.w[1];
    G_ab = (T(1) / T(8)) * in.w[2] * (T(4) * t5 * t10 + t14 * t5 * ap_ap - T(2) * t5 * t15 * ab_ap) * t5 - (T(1) / T(8)) * t14 * t5 * in.w[0] - (T(1) / T(8)) * t5 * t15 * in.w[1];
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 40 +, 66 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 270 +, 981 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i4_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[3] * in.w[3] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = J_downward<T>(4, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = T(2) * ab_ap * t4 + t0 - t5;
    const T t7 = T(1) / ab_ab;
    const T t8 = t5 * a_minus_b;
    const T t9 = ab_ap * t0;
    const T t10 = t8 + t9 - T(2) * t4 * cross_cross;
    const T t11 = t10 * t7 + t4 * ap_ap - t6 * ab_ap * t7;
    F = t4 * in.w[0] + (T(1) / T(2)) * in.w[1] * t6 * t7 - t11 * in.w[2] * t7 - (T(1) / T(2)) * ((T(2) * ab_ap * t10 * t7 - log_ratio) * t7 + t6 * ap_ap * t7 + T(4) * t11 * ab_ap * t7) * in.w[3] * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * a_minus_b;
    const T t17 = ab_ap * t0;
    const T t18 = t16 + t17 + J2 * ab_ab;
    const T t19 = T(1) / cross_cross;
    const T t20 = t0 + t18 * ab_ap * t19 - t15;
    const T t21 = t18 * ap_ap * t19 - T(2) * ab_ap * t20 * t14 - T(2) * J2;
    F = (T(1) / T(2)) * ((T(2) * ab_ap * J2 + log_ratio) * t14 - T(2) * ab_ap * t21 * t14 - ap_ap * t20 * t14) * in.w[3] * t14 + (T(1) / T(2)) * t18 * in.w[0] * t19 + (T(1) / T(2)) * in.w[1] * t20 * t14 - (T(1) / T(2)) * t21 * in.w[2] * t14;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 53 +, 112 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3630 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ab = in.w[2] * M_flat[3] + in.w[1] * M_flat[2] + in.w[3] * M_flat[4] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = ab_ab * J2 + t6 * ab_ap + a_minus_b * t8;
    const T t12 = T(2) * t7 * ab_ap + T(2) * a_minus_b * t9 + T(3) * t10 * ab_ab * t11;
    const T t13 = T(2) * t7 + t12 * t10 * ab_ap - T(2) * t9;
    const T t14 = ap_ap * t12 * t10 - T(4) * t10 * t11 - T(2) * t5 * t13 * ab_ap;
    const T t15 = t8 - t6 - t10 * t11 * ab_ap;
    const T t16 = ap_ap * t5 * t13 + T(4) * t15 * t5 + T(2) * t14 * t5 * ab_ap;
    G_ap = (T(1) / T(8)) * t5 * t13 * in.w[1] + (T(1) / T(8)) * t12 * t10 * in.w[0] - (T(1) / T(8)) * in.w[2] * t14 * t5 - (T(1) / T(8)) * in.w[3] * t5 * t16;
    G_ab = (T(1) / T(8)) * in.w[0] * t5 * t13 + (T(1) / T(8)) * (ap_ap * t14 * t5 - T(2) * t5 * t16 * ab_ap - T(4) * (ap_ap * t10 * t11 + T(2) * t15 * t5 * ab_ap - T(2) * J2) * t5) * in.w[3] * t5 - (T(1) / T(8)) * t14 * t5 * in.w[1] - (T(1) / T(8)) * in.w[2] * t5 * t16;
  }
  const T g_factor = -T(4) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 59 +, 134 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 289 +, 1056 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
template <class T>
T segment_inverse_i4_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ap = in.w[2] * M_flat[7] + M_flat[6] * in.w[1] + in.w[3] * M_flat[8] + M_flat[5] * in.w[0];
    G_ab = in.w[1] * M_flat[7] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t4 = T(1) / ab_ab;
    const T t5 = t0 * t0;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(6, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t5 * ab_ap + t7 * a_minus_b - T(4) * cross_cross * t8;
    const T t10 = T(3) * t0 - T(2) * t4 * t9 * ab_ap - T(3) * t6;
    const T t11 = T(2) * cross_cross * t4 * t9 + T(3) * t6 * a_minus_b + T(3) * t0 * ab_ap;
    const T t12 = t11 * t4 - ap_ap * t4 * t9 - t4 * t10 * ab_ap;
    F = (T(1) / T(6)) * t4 * in.w[1] * t10 + (T(1) / T(6)) * in.w[3] * t4 * (t4 * (T(3) * log_ratio - T(2) * t11 * t4 * ab_ap) - ap_ap * t4 * t10 - T(4) * t12 * t4 * ab_ap) - (T(1) / T(3)) * in.w[2] * t12 * t4 - (T(1) / T(3)) * in.w[0] * t4 * t9;
    const T t13 = t7 - T(4) * ab_ap * t8 - t5;
    const T t14 = T(3) * t4 * ab_ap * t13 + T(2) * t4 * t9 + T(6) * ap_ap * t8;
    const T t15 = T(2) * t4 * t10 + T(3) * ap_ap * t4 * t13 - T(4) * t14 * t4 * ab_ap;
    G_ap = (T(1) / T(12)) * t15 * in.w[3] * t4 + in.w[0] * t8 - (T(1) / T(6)) * in.w[2] * t14 * t4 - (T(1) / T(4)) * t4 * in.w[1] * t13;
    G_ab = (T(1) / T(6)) * in.w[3] * t4 * (ap_ap * t14 * t4 + t15 * t4 * ab_ap - T(2) * t12 * t4) + (T(1) / T(12)) * in.w[2] * t15 * t4 - (T(1) / T(4)) * in.w[0] * t4 * t13 - (T(1) / T(6)) * t14 * t4 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(cross_cross);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, ap_bp);
    const T t18 = T(1) / bp_bp;
    const T t19 = ab_ab * J2 + t18 * a_minus_b + t0 * ab_ap;
    const T t20 = T(1) / cross_cross;
    const T t21 = t19 * t20 * ab_ap + t0 - t18;
    const T t22 = T(1) / ab_ab;
    const T t23 = ap_ap * t19 * t20 - T(2) * t21 * t22 * ab_ap - T(2) * J2;
    F = (T(1) / T(2)) * t21 * t22 * in.w[1] + (T(1) / T(2)) * t19 * in.w[0] * t20 - (T(1) / T(2)) * in.w[2] * t23 * t22 - (T(1) / T(2)) * (ap_ap * t21 * t22 + T(2) * t23 * t22 * ab_ap - t22 * (log_ratio + T(2) * ab_ap * J2)) * in.w[3] * t22;
    const T t24 = t0 * t0;
    const T t25 = t18 * t18;
    const T t26 = T(2) * t24 * ab_ap + T(2) * t25 * a_minus_b + T(3) * t19 * t20 * ab_ab;
    const T t27 = T(2) * t25 - T(2) * t24 - t26 * t20 * ab_ap;
    const T t28 = T(4) * t19 * t20 - ap_ap * t26 * t20 - T(2) * t22 * t27 * ab_ap;
    const T t29 = ap_ap * t22 * t27 + T(4) * t21 * t22 + T(2) * t22 * ab_ap * t28;
    G_ap = (T(1) / T(8)) * t26 * in.w[0] * t20 + (T(1) / T(8)) * in.w[3] * t22 * t29 + (T(1) / T(8)) * in.w[2] * t22 * t28 - (T(1) / T(8)) * t22 * t27 * in.w[1];
    G_ab = (T(1) / T(8)) * in.w[2] * t22 * t29 + (T(1) / T(8)) * in.w[3] * t22 * (T(2) * t22 * t29 * ab_ap - T(4) * t23 * t22 - ap_ap * t22 * t28) + (T(1) / T(8)) * t22 * in.w[1] * t28 - (T(1) / T(8)) * in.w[0] * t22 * t27;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Returns false where segment_inverse_i4_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 134 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_inverse_i4_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t2 = -ab_ap * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1];
    G_ab = in.w[2] * M_flat[8] + in.w[3] * M_flat[9] + M_flat[7] * in.w[1] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, ap_bp) * t5;
    const T t6 = T(1) / bp_bp;
    const T t7 = a_minus_b * t6 + J2 * ab_ab + ab_ap * t0;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / ab_ab;
    const T t10 = t6 - t0 - ab_ap * t7 * t8;
    const T t11 = T(2) * ab_ap * t9 * t10 + t7 * ap_ap * t8 - T(2) * J2;
    F = (T(1) / T(2)) * t7 * in.w[0] * t8 + (T(1) / T(2)) * ((log_ratio + T(2) * ab_ap * J2) * t9 + ap_ap * t9 * t10 - T(2) * ab_ap * t11 * t9) * in.w[3] * t9 - (T(1) / T(2)) * in.w[2] * t11 * t9 - (T(1) / T(2)) * t9 * t10 * in.w[1];
    const T t12 = t0 * t0;
    const T t13 = t6 * t6;
    const T t14 = T(3) * t7 * t8 * ab_ab + T(2) * ab_ap * t12 + T(2) * a_minus_b * t13;
    const T t15 = ab_ap * t14 * t8 + T(2) * t12 - T(2) * t13;
    const T t16 = T(2) * ab_ap * t15 * t9 + T(4) * t7 * t8 - t14 * ap_ap * t8;
    const T t17 = T(4) * t9 * t10 + ap_ap * t15 * t9 - T(2) * ab_ap * t16 * t9;
    G_ap = (T(1) / T(8)) * t15 * t9 * in.w[1] + (T(1) / T(8)) * t14 * in.w[0] * t8 + (T(1) / T(8)) * in.w[2] * t16 * t9 - (T(1) / T(8)) * in.w[3] * t17 * t9;
    G_ab = (T(1) / T(8)) * t15 * in.w[0] * t9 + (T(1) / T(8)) * t16 * t9 * in.w[1] - (T(1) / T(8)) * in.w[3] * t9 * (T(4) * t11 * t9 + ap_ap * t16 * t9 + T(2) * ab_ap * t17 * t9) - (T(1) / T(8)) * in.w[2] * t17 * t9;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 29 +, 40 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 841 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    F = (T(1) / T(3)) * (T(2) * t3 * ab_ab * (t4 * ab_ap + t5 * a_minus_b) + t5 * a_minus_b / bp_bp + t4 * ab_ap / ap_ap) * t3 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 36 +, 72 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1543 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = t7 * t7;
    const T t10 = T(3) * a_minus_b * t5 * t3 + T(4) * ab_ab * (ab_ap * t6 * t7 + T(2) * ab_ab * (a_minus_b * t3 + ab_ap * t6) * t8 + a_minus_b * t4 * t3) * t8 + T(3) * ab_ap * t6 * t9;
    G_ap = (T(1) / T(15)) * t10 * in.w[0] * t8;
    G_ab = (T(1) / T(15)) * (t10 * ab_ap * t8 + T(3) * t6 * t9 - T(3) * t5 * t3) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(5) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 36 +, 76 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1566 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = ab_ap * t4 * t3 + a_minus_b * t5 * t6 + T(2) * (a_minus_b * t5 + ab_ap * t3) * t7 * ab_ab;
    F = (T(1) / T(3)) * t8 * in.w[0] * t7;
    const T t9 = t6 * t6;
    const T t10 = t4 * t4;
    const T t11 = T(4) * t8 * t7 * ab_ab + T(3) * a_minus_b * t5 * t9 + T(3) * ab_ap * t10 * t3;
    G_ap = (T(1) / T(15)) * in.w[0] * t7 * t11;
    G_ab = -(T(1) / T(15)) * in.w[0] * (T(3) * t5 * t9 - T(3) * t10 * t3 - ab_ap * t7 * t11) / ab_ab;
  }
  const T g_factor = -T(5) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Returns false where segment_inverse_i5_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 36 +, 76 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i5_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t5 * t4 * ab_ap + T(2) * t3 * ab_ab * (t6 * a_minus_b + t4 * ab_ap) + t6 * t7 * a_minus_b;
    F = (T(1) / T(3)) * in.w[0] * t3 * t8;
    const T t9 = t7 * t7;
    const T t10 = t5 * t5;
    const T t11 = T(3) * t6 * t9 * a_minus_b + T(3) * t10 * t4 * ab_ap + T(4) * t3 * ab_ab * t8;
    G_ap = (T(1) / T(15)) * t11 * in.w[0] * t3;
    G_ab = (T(1) / T(15)) * (t11 * t3 * ab_ap + T(3) * t10 * t4 - T(3) * t6 * t9) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 32 +, 50 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1531 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = t5 * a_minus_b * t6 + T(2) * (t5 * a_minus_b + t3 * ab_ap) * t7 * ab_ab + t4 * t3 * ab_ap;
    F = (T(1) / T(3)) * in.w[1] * (t4 * t3 + t8 * t7 * ab_ap - t5 * t6) / ab_ab + (T(1) / T(3)) * t8 * in.w[0] * t7;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 40 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2236 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t3 * ab_ab * (t4 * a_minus_b + ab_ap * t7) + t4 * a_minus_b * t5 + t8 * ab_ap * t7;
    const T t11 = T(3) * t4 * a_minus_b * t6 + T(3) * t9 * ab_ap * t7 + T(4) * t10 * t3 * ab_ab;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(3) * t4 * t6 - t3 * t11 * ab_ap - T(3) * t9 * t7;
    G_ap = (T(1) / T(15)) * t3 * t11 * in.w[0] - (T(1) / T(15)) * in.w[1] * t12 * t13;
    G_ab = -(T(1) / T(15)) * in.w[1] * (T(2) * t12 * ab_ap * t13 + ap_ap * t3 * t11 - T(5) * t10 * t3) * t12 - (T(1) / T(15)) * t12 * t13 * in.w[0];
  }
  const T g_factor = -T(5) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 43 +, 97 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2273 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[4] + in.w[0] * M_beyond[3];
    G_ab = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t4 * t5 * a_minus_b + t7 * t6 * ab_ap + T(2) * ab_ab * t3 * (t4 * a_minus_b + t6 * ab_ap);
    const T t9 = T(1) / ab_ab;
    F = (T(1) / T(3)) * in.w[0] * t3 * t8 - (T(1) / T(3)) * in.w[1] * t9 * (t4 * t5 - t7 * t6 - t3 * t8 * ab_ap);
    const T t10 = t7 * t7;
    const T t11 = t5 * t5;
    const T t12 = T(3) * t10 * t6 * ab_ap + T(3) * t4 * t11 * a_minus_b + T(4) * ab_ab * t3 * t8;
    const T t13 = T(3) * t10 * t6 + t12 * t3 * ab_ap - T(3) * t4 * t11;
    G_ap = (T(1) / T(15)) * in.w[1] * t9 * t13 + (T(1) / T(15)) * in.w[0] * t12 * t3;
    G_ab = (T(1) / T(15)) * (T(2) * t9 * ab_ap * t13 + T(5) * t3 * t8 - ap_ap * t12 * t3) * in.w[1] * t9 + (T(1) / T(15)) * in.w[0] * t9 * t13;
  }
  const T g_factor = -T(5) * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Returns false where segment_inverse_i5_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 97 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i5_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * t4;
    const T t7 = t5 * t5;
    const T t8 = T(2) * t3 * ab_ab * (a_minus_b * t4 + ab_ap * t5) + t6 * a_minus_b * t4 + ab_ap * t7 * t5;
    const T t9 = T(1) / ab_ab;
    F = (T(1) / T(3)) * t8 * in.w[0] * t3 + (T(1) / T(3)) * (t8 * ab_ap * t3 + t7 * t5 - t6 * t4) * in.w[1] * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * ab_ap * t10 * t5 + T(3) * t11 * a_minus_b * t4 + T(4) * t8 * t3 * ab_ab;
    const T t13 = ab_ap * t12 * t3 + T(3) * t10 * t5 - T(3) * t11 * t4;
    G_ap = (T(1) / T(15)) * t13 * in.w[1] * t9 + (T(1) / T(15)) * in.w[0] * t12 * t3;
    G_ab = (T(1) / T(15)) * (T(5) * t8 * t3 + T(2) * ab_ap * t13 * t9 - ap_ap * t12 * t3) * in.w[1] * t9 + (T(1) / T(15)) * in.w[0] * t13 * t9;
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 35 +, 61 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2223 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = a_minus_b * t3 + t4 * ab_ap;
    const T t6 = T(1) / cross_cross;
    const T t7 = t3 * t3;
    const T t8 = t4 * t4;
    const T t9 = T(2) * t5 * t6 * ab_ab + a_minus_b * t7 * t3 + t8 * t4 * ab_ap;
    const T t10 = t8 * t4 + t9 * t6 * ab_ap - t7 * t3;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(3)) * t9 * t6 * in.w[0] + (T(1) / T(3)) * t10 * t11 * in.w[1] + (T(1) / T(3)) * in.w[2] * t11 * (T(2) * t10 * t11 * ab_ap + T(3) * t5 * t6 - ap_ap * t9 * t6);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 46 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2931 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[2] * in.w[1] + M_flat[1] * in.w[0] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t8 * a_minus_b * t9 + ab_ap * t5 * t6 + T(2) * t4 * ab_ab * (t8 * a_minus_b + ab_ap * t5);
    const T t11 = t9 * t9;
    const T t12 = T(3) * ab_ap * t5 * t7 + T(4) * t4 * ab_ab * t10 + T(3) * t8 * a_minus_b * t11;
    const T t13 = t4 * t12 * ab_ap + T(3) * t5 * t7 - T(3) * t8 * t11;
    const T t14 = T(5) * t4 * t10 + T(2) * t3 * t13 * ab_ap - t4 * t12 * ap_ap;
    G_ap = (T(1) / T(15)) * t3 * t13 * in.w[1] + (T(1) / T(15)) * in.w[2] * t3 * t14 + (T(1) / T(15)) * t4 * t12 * in.w[0];
    G_ab = (T(1) / T(15)) * t3 * t13 * in.w[0] + (T(1) / T(15)) * t3 * t14 * in.w[1] - (T(1) / T(15)) * in.w[2] * t3 * (t3 * t13 * ap_ap + T(5) * t3 * (t8 * t9 - t5 * t6 - t4 * t10 * ab_ap) - T(2) * t3 * ab_ap * t14);
  }
  const T g_factor = -T(5) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 50 +, 120 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2984 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
    G_ab = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[5] * in.w[1] + in.w[2] * M_beyond[6] + M_beyond[4] * in.w[0];
    G_ab = in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = t5 * a_minus_b + t3 * ab_ap;
    const T t9 = t3 * ab_ap * t4 + t5 * t6 * a_minus_b + T(2) * t7 * ab_ab * t8;
    const T t10 = T(1) / ab_ab;
    const T t11 = t5 * t6 - t9 * t7 * ab_ap - t3 * t4;
    F = (T(1) / T(3)) * t9 * t7 * in.w[0] + (T(1) / T(3)) * in.w[2] * t10 * (T(3) * t7 * t8 - T(2) * t10 * t11 * ab_ap - t9 * t7 * ap_ap) - (T(1) / T(3)) * t10 * t11 * in.w[1];
    const T t12 = t4 * t4;
    const T t13 = t6 * t6;
    const T t14 = T(3) * t5 * t13 * a_minus_b + T(3) * t3 * ab_ap * t12 + T(4) * t9 * t7 * ab_ab;
    const T t15 = T(3) * t3 * t12 + t7 * ab_ap * t14 - T(3) * t5 * t13;
    const T t16 = T(2) * t10 * ab_ap * t15 + T(5) * t9 * t7 - t7 * t14 * ap_ap;
    G_ap = (T(1) / T(15)) * in.w[2] * t10 * t16 + (T(1) / T(15)) * t10 * t15 * in.w[1] + (T(1) / T(15)) * t7 * in.w[0] * t14;
    G_ab = (T(1) / T(15)) * t10 * t16 * in.w[1] + (T(1) / T(15)) * t10 * in.w[0] * t15 - (T(1) / T(15)) * in.w[2] * t10 * (t10 * t15 * ap_ap + T(5) * t10 * t11 - T(2) * t10 * t16 * ab_ap);
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Returns false where segment_inverse_i5_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 50 +, 120 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i5_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + M_flat[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = ab_ap * t6 + t4 * a_minus_b;
    const T t8 = t6 * t6;
    const T t9 = t4 * t5 * a_minus_b + T(2) * t3 * ab_ab * t7 + ab_ap * t8 * t6;
    const T t10 = t3 * ab_ap * t9 + t8 * t6 - t4 * t5;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(3)) * t3 * in.w[0] * t9 + (T(1) / T(3)) * t10 * t11 * in.w[1] - (T(1) / T(3)) * in.w[2] * t11 * (t3 * ap_ap * t9 - T(3) * t3 * t7 - T(2) * t10 * t11 * ab_ap);
    const T t12 = t8 * t8;
    const T t13 = t5 * t5;
    const T t14 = T(3) * ab_ap * t12 * t6 + T(3) * t4 * t13 * a_minus_b + T(4) * t3 * ab_ab * t9;
    const T t15 = T(3) * t12 * t6 + t14 * t3 * ab_ap - T(3) * t4 * t13;
    const T t16 = T(5) * t3 * t9 + T(2) * t11 * t15 * ab_ap - t14 * t3 * ap_ap;
    G_ap = (T(1) / T(15)) * t11 * t15 * in.w[1] + (T(1) / T(15)) * in.w[2] * t11 * t16 + (T(1) / T(15)) * t14 * t3 * in.w[0];
    G_ab = (T(1) / T(15)) * t11 * t16 * in.w[1] + (T(1) / T(15)) * t11 * t15 * in.w[0] - (T(1) / T(15)) * in.w[2] * t11 * (t11 * t15 * ap_ap - T(2) * t11 * t16 * ab_ap - T(5) * t10 * t11);
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 40 +, 73 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2917 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + t6 * ab_ap;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    const T t10 = T(2) * t7 * t4 * ab_ab + t8 * t6 * ab_ap + a_minus_b * t9 * t5;
    const T t11 = t4 * t10 * ab_ap + t8 * t6 - t9 * t5;
    const T t12 = T(2) * t3 * ab_ap * t11 + T(3) * t7 * t4 - ap_ap * t4 * t10;
    F = (T(1) / T(3)) * in.w[3] * t3 * (T(2) * t3 * t12 * ab_ap - T(3) * (t5 - t7 * t4 * ab_ap - t6) * t3 - ap_ap * t3 * t11) + (T(1) / T(3)) * t3 * t12 * in.w[2] + (T(1) / T(3)) * t3 * in.w[1] * t11 + (T(1) / T(3)) * in.w[0] * t4 * t10;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 52 +, 123 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3628 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ab = in.w[0] * M_flat[1] + in.w[3] * M_flat[4] + in.w[2] * M_flat[3] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3];
    G_ab = in.w[3] * M_beyond[4] + M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = a_minus_b * t8 + ab_ap * t4;
    const T t12 = ab_ap * t4 * t5 + T(2) * t11 * t7 * ab_ab + a_minus_b * t9 * t8;
    const T t13 = T(3) * a_minus_b * t10 * t8 + T(4) * t12 * t7 * ab_ab + T(3) * ab_ap * t4 * t6;
    const T t14 = T(3) * t4 * t6 + t7 * t13 * ab_ap - T(3) * t10 * t8;
    const T t15 = T(2) * t3 * t14 * ab_ap + T(5) * t12 * t7 - t7 * t13 * ap_ap;
    const T t16 = t9 * t8 - t12 * t7 * ab_ap - t4 * t5;
    const T t17 = T(2) * t3 * ab_ap * t15 - t3 * t14 * ap_ap - T(5) * t3 * t16;
    G_ap = (T(1) / T(15)) * t3 * in.w[2] * t15 + (T(1) / T(15)) * in.w[3] * t3 * t17 + (T(1) / T(15)) * t7 * t13 * in.w[0] + (T(1) / T(15)) * t3 * t14 * in.w[1];
    G_ab = (T(1) / T(15)) * in.w[0] * t3 * t14 + (T(1) / T(15)) * t3 * in.w[2] * t17 + (T(1) / T(15)) * t3 * in.w[1] * t15 - (T(1) / T(15)) * in.w[3] * t3 * (t3 * ap_ap * t15 + T(5) * (T(2) * t3 * ab_ap * t16 + t12 * t7 * ap_ap - T(3) * t11 * t7) * t3 - T(2) * t3 * ab_ap * t17);
  }
  const T g_factor = -T(5) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 59 +, 145 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 288 +, 1070 ×, 124 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i5_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
    G_ap = in.w[3] * M_flat[8] + M_flat[6] * in.w[1] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2] + in.w[3] * M_flat[9];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = J_downward<T>(7, ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(5) * cross_cross * t4 - ab_ap * t7 * t5 - t8 * t10 * a_minus_b;
    const T t12 = T(4) * t8 * t9 - T(3) * t3 * ab_ap * t11 - T(4) * t6 * t5;
    const T t13 = T(4) * t8 * t9 * a_minus_b + T(4) * ab_ap * t6 * t5 - T(3) * cross_cross * t3 * t11;
    const T t14 = T(6) * t3 * t11 * ap_ap + T(3) * t3 * t13 + T(4) * t3 * ab_ap * t12;
    F = (T(1) / T(4)) * in.w[0] * t3 * t11 - (T(1) / T(12)) * t3 * in.w[1] * t12 - (T(1) / T(24)) * in.w[3] * t3 * (T(2) * t3 * ab_ap * t14 - T(3) * t3 * (T(8) * t5 - t3 * ab_ap * t13 - T(8) * t8) - T(2) * t3 * t12 * ap_ap) - (T(1) / T(24)) * t3 * in.w[2] * t14;
    const T t15 = T(5) * t4 * ab_ap + t7 * t5 - t8 * t10;
    const T t16 = T(8) * t3 * t15 * ab_ap + T(5) * t3 * t11 - T(20) * t4 * ap_ap;
    const T t17 = T(6) * t16 * t3 * ab_ap - T(12) * t3 * t15 * ap_ap - T(5) * t3 * t12;
    G_ap = in.w[0] * t4 + (T(1) / T(60)) * in.w[3] * t3 * t17 + (T(1) / T(20)) * t16 * t3 * in.w[2] + (T(1) / T(5)) * t3 * in.w[1] * t15;
    G_ab = (T(1) / T(20)) * t16 * t3 * in.w[1] + (T(1) / T(5)) * in.w[0] * t3 * t15 + (T(1) / T(60)) * t3 * t17 * in.w[2] - (T(1) / T(120)) * in.w[3] * t3 * (T(6) * t16 * t3 * ap_ap + T(5) * t3 * t14 - T(4) * t3 * t17 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r1;
    const T t20 = T(1) / r0;
    const T t21 = t19 * a_minus_b + ab_ap * t20;
    const T t22 = t19 * t19;
    const T t23 = t20 * t20;
    const T t24 = T(2) * t18 * ab_ab * t21 + t19 * t22 * a_minus_b + ab_ap * t23 * t20;
    const T t25 = T(1) / ab_ab;
    const T t26 = t19 * t22 - t18 * ab_ap * t24 - t23 * t20;
    const T t27 = T(2) * t25 * ab_ap * t26 + t18 * ap_ap * t24 - T(3) * t18 * t21;
    F = (T(1) / T(3)) * t18 * in.w[0] * t24 + (T(1) / T(3)) * in.w[3] * t25 * (t25 * t26 * ap_ap + T(3) * t25 * (t20 + t18 * t21 * ab_ap - t19) - T(2) * t25 * ab_ap * t27) - (T(1) / T(3)) * t25 * in.w[2] * t27 - (T(1) / T(3)) * t25 * in.w[1] * t26;
    const T t28 = t23 * t23;
    const T t29 = t22 * t22;
    const T t30 = T(4) * t18 * ab_ab * t24 + T(3) * ab_ap * t28 * t20 + T(3) * t19 * t29 * a_minus_b;
    const T t31 = T(3) * t28 * t20 + t18 * ab_ap * t30 - T(3) * t19 * t29;
    const T t32 = T(5) * t18 * t24 + T(2) * t25 * t31 * ab_ap - t18 * t30 * ap_ap;
    const T t33 = T(5) * t25 * t26 + t25 * t31 * ap_ap - T(2) * t32 * t25 * ab_ap;
    G_ap = (T(1) / T(15)) * t25 * t31 * in.w[1] + (T(1) / T(15)) * t18 * in.w[0] * t30 + (T(1) / T(15)) * t32 * t25 * in.w[2] - (T(1) / T(15)) * in.w[3] * t25 * t33;
    G_ab = (T(1) / T(15)) * t32 * t25 * in.w[1] + (T(1) / T(15)) * in.w[0] * t25 * t31 - (T(1) / T(15)) * in.w[3] * t25 * (t32 * t25 * ap_ap + T(2) * t25 * t33 * ab_ap + T(5) * t25 * t27) - (T(1) / T(15)) * t25 * t33 * in.w[2];
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Returns false where segment_inverse_i5_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 145 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i5_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ap = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + M_flat[8] * in.w[3];
    G_ab = M_flat[8] * in.w[2] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * ab_ap;
    const T t7 = t5 * t5;
    const T t8 = t4 * t4;
    const T t9 = T(2) * t3 * ab_ab * t6 + t7 * t5 * ab_ap + t4 * t8 * a_minus_b;
    const T t10 = T(1) / ab_ab;
    const T t11 = t3 * t9 * ab_ap + t7 * t5 - t4 * t8;
    const T t12 = ap_ap * t3 * t9 - T(2) * t10 * t11 * ab_ap - T(3) * t3 * t6;
    F = (T(1) / T(3)) * in.w[0] * t3 * t9 + (T(1) / T(3)) * t10 * t11 * in.w[1] + (T(1) / T(3)) * in.w[3] * t10 * (T(3) * (t3 * t6 * ab_ap + t5 - t4) * t10 - ap_ap * t10 * t11 - T(2) * t10 * t12 * ab_ap) - (T(1) / T(3)) * in.w[2] * t10 * t12;
    const T t13 = t8 * t8;
    const T t14 = t7 * t7;
    const T t15 = T(3) * t4 * t13 * a_minus_b + T(3) * t14 * t5 * ab_ap + T(4) * t3 * ab_ab * t9;
    const T t16 = t3 * ab_ap * t15 + T(3) * t14 * t5 - T(3) * t4 * t13;
    const T t17 = T(5) * t3 * t9 + T(2) * t10 * t16 * ab_ap - ap_ap * t3 * t15;
    const T t18 = T(2) * t17 * t10 * ab_ap + T(5) * t10 * t11 - ap_ap * t10 * t16;
    G_ap = (T(1) / T(15)) * in.w[2] * t17 * t10 + (T(1) / T(15)) * in.w[3] * t10 * t18 + (T(1) / T(15)) * t10 * t16 * in.w[1] + (T(1) / T(15)) * in.w[0] * t3 * t15;
    G_ab = (T(1) / T(15)) * in.w[2] * t10 * t18 + (T(1) / T(15)) * t17 * t10 * in.w[1] + (T(1) / T(15)) * in.w[0] * t10 * t16 - (T(1) / T(15)) * in.w[3] * t10 * (ap_ap * t17 * t10 + T(5) * t10 * t12 - T(2) * t10 * t18 * ab_ap);
  }
  const T g_factor = -T(5) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 32 +, 49 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 846 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = T(1) / cross_cross;
    const T t9 = t7 * t7;
    F = (T(1) / T(8)) * (T(2) * t6 * a_minus_b + T(3) * (ab_ap * t7 + J2 * ab_ab + t5 * a_minus_b) * t8 * ab_ab + T(2) * ab_ap * t9) * in.w[0] * t8;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 39 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1548 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * ab_ap * t8 + T(8) * t11 * a_minus_b + T(5) * (T(2) * ab_ap * t7 + T(2) * t10 * a_minus_b + T(3) * (t9 * a_minus_b + ab_ab * J2 + ab_ap * t6) * t5 * ab_ab) * t5 * ab_ab;
    G_ap = (T(1) / T(48)) * in.w[0] * t5 * t12;
    G_ab = -(T(1) / T(48)) * (T(8) * t11 - T(8) * t8 - ab_ap * t5 * t12) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(6) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 39 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1572 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = T(1) / cross_cross;
    const T t9 = t7 * t7;
    const T t10 = T(2) * ab_ap * t6 + T(3) * (t7 * a_minus_b + J2 * ab_ab + ab_ap * t5) * t8 * ab_ab + T(2) * t9 * a_minus_b;
    F = (T(1) / T(8)) * t10 * in.w[0] * t8;
    const T t11 = t6 * t5;
    const T t12 = t9 * t7;
    const T t13 = T(8) * ab_ap * t11 + T(5) * t10 * t8 * ab_ab + T(8) * t12 * a_minus_b;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t8;
    G_ab = (T(1) / T(48)) * (T(8) * t11 + t13 * ab_ap * t8 - T(8) * t12) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Returns false where segment_inverse_i6_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 39 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i6_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = T(1) / bp_bp;
    const T t7 = T(1) / cross_cross;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    const T t10 = T(3) * (ab_ap * t5 + a_minus_b * t6 + ab_ab * J2) * t7 * ab_ab + T(2) * a_minus_b * t8 + T(2) * ab_ap * t9;
    F = (T(1) / T(8)) * t10 * in.w[0] * t7;
    const T t11 = t9 * t5;
    const T t12 = t8 * t6;
    const T t13 = T(8) * ab_ap * t11 + T(8) * a_minus_b * t12 + T(5) * t10 * t7 * ab_ab;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t7;
    G_ab = (T(1) / T(48)) * in.w[0] * (ab_ap * t13 * t7 + T(8) * t11 - T(8) * t12) / ab_ab;
  }
  const T g_factor = -T(6) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 35 +, 55 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1536 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = T(2) * ab_ap * t7 + T(3) * t5 * ab_ab * (a_minus_b * t8 + ab_ap * t6 + J2 * ab_ab) + T(2) * a_minus_b * t9;
    F = (T(1) / T(8)) * t5 * in.w[0] * t10 + (T(1) / T(8)) * in.w[1] * (t5 * ab_ap * t10 + T(2) * t7 - T(2) * t9) / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 43 +, 87 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2241 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(2) * a_minus_b * t7 + T(2) * ab_ap * t10 + T(3) * (ab_ab * J2 + ab_ap * t9 + a_minus_b * t6) * t5 * ab_ab;
    const T t13 = T(8) * a_minus_b * t8 + T(8) * ab_ap * t11 + T(5) * t5 * ab_ab * t12;
    const T t14 = T(8) * t11 + t5 * ab_ap * t13 - T(8) * t8;
    const T t15 = T(1) / ab_ab;
    G_ap = (T(1) / T(48)) * t5 * in.w[0] * t13 + (T(1) / T(48)) * in.w[1] * t14 * t15;
    G_ab = (T(1) / T(48)) * t14 * t15 * in.w[0] + (T(1) / T(48)) * in.w[1] * t15 * (T(6) * t5 * t12 + T(2) * t14 * t15 * ab_ap - t5 * ap_ap * t13);
  }
  const T g_factor = -T(6) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 46 +, 98 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2279 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = M_beyond[4] * in.w[0] + in.w[1] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t7 * a_minus_b + T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t8 + t6 * a_minus_b) + T(2) * ab_ap * t9;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(8)) * t5 * t10 * in.w[0] + (T(1) / T(8)) * in.w[1] * t11 * (t5 * ab_ap * t10 + T(2) * t9 - T(2) * t7);
    const T t12 = t7 * t6;
    const T t13 = t9 * t8;
    const T t14 = T(8) * t12 * a_minus_b + T(8) * ab_ap * t13 + T(5) * t5 * ab_ab * t10;
    const T t15 = T(8) * t12 - T(8) * t13 - t14 * t5 * ab_ap;
    G_ap = (T(1) / T(48)) * t14 * t5 * in.w[0] - (T(1) / T(48)) * t15 * in.w[1] * t11;
    G_ab = (T(1) / T(48)) * in.w[1] * (T(6) * t5 * t10 - T(2) * t15 * t11 * ab_ap - t14 * t5 * ap_ap) * t11 - (T(1) / T(48)) * t15 * t11 * in.w[0];
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Returns false where segment_inverse_i6_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 46 +, 98 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i6_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / bp_bp;
    const T t8 = T(1) / ap_ap;
    const T t9 = t7 * t7;
    const T t10 = t8 * t8;
    const T t11 = T(3) * (t7 * a_minus_b + t8 * ab_ap + ab_ab * J2) * t6 * ab_ab + T(2) * t9 * a_minus_b + T(2) * t10 * ab_ap;
    F = (T(1) / T(8)) * in.w[1] * t5 * (t6 * t11 * ab_ap + T(2) * t10 - T(2) * t9) + (T(1) / T(8)) * in.w[0] * t6 * t11;
    const T t12 = t10 * t8;
    const T t13 = t9 * t7;
    const T t14 = T(5) * t6 * ab_ab * t11 + T(8) * t12 * ab_ap + T(8) * t13 * a_minus_b;
    const T t15 = t14 * t6 * ab_ap + T(8) * t12 - T(8) * t13;
    G_ap = (T(1) / T(48)) * t14 * in.w[0] * t6 + (T(1) / T(48)) * t15 * in.w[1] * t5;
    G_ab = (T(1) / T(48)) * in.w[0] * t15 * t5 + (T(1) / T(48)) * (T(2) * t15 * t5 * ab_ap + T(6) * t6 * t11 - t14 * ap_ap * t6) * in.w[1] * t5;
  }
  const T g_factor = -T(6) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 38 +, 66 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2228 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = ab_ap * t8 + a_minus_b * t6 + ab_ab * J2;
    const T t10 = t8 * t8;
    const T t11 = T(2) * a_minus_b * t7 + T(3) * t9 * t5 * ab_ab + T(2) * ab_ap * t10;
    const T t12 = T(2) * t7 - t5 * t11 * ab_ap - T(2) * t10;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(8)) * t5 * t11 * in.w[0] - (T(1) / T(8)) * t12 * t13 * in.w[1] - (T(1) / T(8)) * in.w[2] * t13 * (T(2) * t12 * t13 * ab_ap + t5 * t11 * ap_ap - T(4) * t9 * t5);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 49 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2936 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ab = M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = T(1) / cross_cross;
    const T t10 = t8 * t8;
    const T t11 = T(2) * a_minus_b * t7 + T(3) * ab_ab * (ab_ap * t8 + ab_ab * J2 + a_minus_b * t6) * t9 + T(2) * ab_ap * t10;
    const T t12 = t10 * t8;
    const T t13 = t7 * t6;
    const T t14 = T(5) * t11 * ab_ab * t9 + T(8) * a_minus_b * t13 + T(8) * ab_ap * t12;
    const T t15 = T(8) * t12 + ab_ap * t14 * t9 - T(8) * t13;
    const T t16 = T(6) * t11 * t9 + T(2) * t15 * t5 * ab_ap - ap_ap * t14 * t9;
    G_ap = (T(1) / T(48)) * t5 * t16 * in.w[2] + (T(1) / T(48)) * t15 * t5 * in.w[1] + (T(1) / T(48)) * in.w[0] * t14 * t9;
    G_ab = (T(1) / T(48)) * t15 * t5 * in.w[0] + (T(1) / T(48)) * t5 * (T(6) * t5 * (T(2) * t10 + t11 * ab_ap * t9 - T(2) * t7) + T(2) * t5 * t16 * ab_ap - t15 * t5 * ap_ap) * in.w[2] + (T(1) / T(48)) * t5 * t16 * in.w[1];
  }
  const T g_factor = -T(6) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 53 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 2990 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[4] + M_flat[6] * in.w[2] + in.w[1] * M_flat[5];
    G_ab = in.w[0] * M_flat[5] + M_flat[6] * in.w[1] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ap = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2];
    G_ab = in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / bp_bp;
    const T t8 = T(1) / ap_ap;
    const T t9 = t7 * a_minus_b + ab_ab * J2 + ab_ap * t8;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * ab_ap * t10 + T(3) * ab_ab * t6 * t9 + T(2) * t11 * a_minus_b;
    const T t13 = T(2) * t10 + t6 * ab_ap * t12 - T(2) * t11;
    F = (T(1) / T(8)) * t5 * (T(4) * t6 * t9 + T(2) * t5 * ab_ap * t13 - t6 * ap_ap * t12) * in.w[2] + (T(1) / T(8)) * t5 * in.w[1] * t13 + (T(1) / T(8)) * t6 * in.w[0] * t12;
    const T t14 = t10 * t8;
    const T t15 = t11 * t7;
    const T t16 = T(5) * ab_ab * t6 * t12 + T(8) * ab_ap * t14 + T(8) * t15 * a_minus_b;
    const T t17 = T(8) * t14 + t6 * t16 * ab_ap - T(8) * t15;
    const T t18 = T(6) * t6 * t12 + T(2) * t5 * t17 * ab_ap - t6 * t16 * ap_ap;
    G_ap = (T(1) / T(48)) * t5 * t17 * in.w[1] + (T(1) / T(48)) * t6 * t16 * in.w[0] + (T(1) / T(48)) * t5 * t18 * in.w[2];
    G_ab = (T(1) / T(48)) * t5 * t17 * in.w[0] + (T(1) / T(48)) * t5 * (T(6) * t5 * t13 + T(2) * t5 * ab_ap * t18 - t5 * t17 * ap_ap) * in.w[2] + (T(1) / T(48)) * t5 * in.w[1] * t18;
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Returns false where segment_inverse_i6_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 53 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i6_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = in.w[0] * M_flat[5] + M_flat[7] * in.w[2] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t7 * a_minus_b + J2 * ab_ab + ab_ap * t5;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(2) * ab_ap * t6 + T(2) * t8 * a_minus_b + T(3) * t9 * t10 * ab_ab;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(2) * t8 - T(2) * t6 - ab_ap * t11 * t10;
    F = (T(1) / T(8)) * in.w[0] * t11 * t10 - (T(1) / T(8)) * in.w[1] * t12 * t13 - (T(1) / T(8)) * (ap_ap * t11 * t10 + T(2) * ab_ap * t12 * t13 - T(4) * t9 * t10) * in.w[2] * t12;
    const T t14 = t6 * t5;
    const T t15 = t8 * t7;
    const T t16 = T(8) * ab_ap * t14 + T(8) * t15 * a_minus_b + T(5) * t11 * t10 * ab_ab;
    const T t17 = T(8) * t15 - T(8) * t14 - t16 * ab_ap * t10;
    const T t18 = T(2) * ab_ap * t17 * t12 + t16 * ap_ap * t10 - T(6) * t11 * t10;
    G_ap = (T(1) / T(48)) * t16 * in.w[0] * t10 - (T(1) / T(48)) * t18 * in.w[2] * t12 - (T(1) / T(48)) * t17 * in.w[1] * t12;
    G_ab = (T(1) / T(48)) * (t17 * ap_ap * t12 - T(2) * t18 * ab_ap * t12 - T(6) * t12 * t13) * in.w[2] * t12 - (T(1) / T(48)) * in.w[0] * t17 * t12 - (T(1) / T(48)) * t18 * in.w[1] * t12;
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 43 +, 78 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2922 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = ab_ap * t8 + ab_ab * J2 + a_minus_b * t6;
    const T t11 = T(2) * a_minus_b * t7 + T(2) * ab_ap * t9 + T(3) * ab_ab * t10 * t5;
    const T t12 = T(1) / ab_ab;
    const T t13 = ab_ap * t5 * t11 + T(2) * t9 - T(2) * t7;
    const T t14 = T(2) * ab_ap * t12 * t13 + T(4) * t10 * t5 - ap_ap * t5 * t11;
    F = (T(1) / T(8)) * in.w[0] * t5 * t11 + (T(1) / T(8)) * t12 * in.w[1] * t13 + (T(1) / T(8)) * t12 * t14 * in.w[2] - (T(1) / T(8)) * in.w[3] * t12 * (t12 * ap_ap * t13 + T(4) * t12 * (t6 - t8 - ab_ap * t10 * t5) - T(2) * ab_ap * t12 * t14);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 55 +, 124 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3633 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ab = in.w[1] * M_flat[2] + in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1];
    G_ab = in.w[3] * M_beyond[4] + M_beyond[3] * in.w[2] + M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = ab_ab * J2 + t6 * ab_ap + a_minus_b * t8;
    const T t11 = T(2) * t7 * ab_ap + T(2) * a_minus_b * t9 + T(3) * t5 * ab_ab * t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = t9 * t8;
    const T t14 = t7 * t6;
    const T t15 = T(8) * a_minus_b * t13 + T(8) * t14 * ab_ap + T(5) * t5 * ab_ab * t11;
    const T t16 = t5 * ab_ap * t15 + T(8) * t14 - T(8) * t13;
    const T t17 = T(6) * t5 * t11 + T(2) * t12 * ab_ap * t16 - ap_ap * t5 * t15;
    const T t18 = t5 * ab_ap * t11 + T(2) * t7 - T(2) * t9;
    const T t19 = T(6) * t12 * t18 + T(2) * t17 * t12 * ab_ap - ap_ap * t12 * t16;
    G_ap = (T(1) / T(48)) * t17 * t12 * in.w[2] + (T(1) / T(48)) * t5 * in.w[0] * t15 + (T(1) / T(48)) * t19 * in.w[3] * t12 + (T(1) / T(48)) * t12 * in.w[1] * t16;
    G_ab = (T(1) / T(48)) * t19 * t12 * in.w[2] + (T(1) / T(48)) * t17 * t12 * in.w[1] + (T(1) / T(48)) * in.w[0] * t12 * t16 - (T(1) / T(48)) * in.w[3] * (T(6) * t12 * (ap_ap * t5 * t11 - T(2) * t12 * ab_ap * t18 - T(4) * t5 * t10) + ap_ap * t17 * t12 - T(2) * t19 * t12 * ab_ap) * t12;
  }
  const T g_factor = -T(6) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 62 +, 146 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3705 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i6_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[3] * M_flat[8] + M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0];
    G_ab = in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[3] * M_flat[9] + in.w[0] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3];
    G_ab = in.w[3] * M_beyond[9] + in.w[0] * M_beyond[6] + M_beyond[8] * in.w[2] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = T(1) / ap_ap;
    const T t8 = t6 * a_minus_b + ab_ab * J2 + t7 * ab_ap;
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(3) * t5 * ab_ab * t8 + T(2) * t9 * ab_ap + T(2) * t10 * a_minus_b;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(2) * t9 + t11 * t5 * ab_ap - T(2) * t10;
    const T t14 = ap_ap * t11 * t5 - T(2) * t12 * ab_ap * t13 - T(4) * t5 * t8;
    F = (T(1) / T(8)) * t11 * t5 * in.w[0] + (T(1) / T(8)) * t12 * in.w[1] * t13 - (T(1) / T(8)) * in.w[3] * t12 * (ap_ap * t12 * t13 + T(4) * t12 * (t6 - t5 * t8 * ab_ap - t7) + T(2) * t14 * t12 * ab_ap) - (T(1) / T(8)) * t14 * t12 * in.w[2];
    const T t15 = t9 * t7;
    const T t16 = t10 * t6;
    const T t17 = T(5) * t11 * t5 * ab_ab + T(8) * t15 * ab_ap + T(8) * t16 * a_minus_b;
    const T t18 = t5 * ab_ap * t17 + T(8) * t15 - T(8) * t16;
    const T t19 = T(2) * t12 * ab_ap * t18 + T(6) * t11 * t5 - ap_ap * t5 * t17;
    const T t20 = T(6) * t12 * t13 + T(2) * t12 * t19 * ab_ap - ap_ap * t12 * t18;
    G_ap = (T(1) / T(48)) * t12 * t19 * in.w[2] + (T(1) / T(48)) * t12 * in.w[1] * t18 + (T(1) / T(48)) * t5 * in.w[0] * t17 + (T(1) / T(48)) * in.w[3] * t12 * t20;
    G_ab = (T(1) / T(48)) * in.w[3] * t12 * (T(2) * t12 * t20 * ab_ap - T(6) * t14 * t12 - ap_ap * t12 * t19) + (T(1) / T(48)) * t12 * t19 * in.w[1] + (T(1) / T(48)) * t12 * t20 * in.w[2] + (T(1) / T(48)) * in.w[0] * t12 * t18;
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Returns false where segment_inverse_i6_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 62 +, 146 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i6_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
    G_ab = in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = T(1) / bp_bp;
    const T t8 = ab_ap * t6 + t7 * a_minus_b + J2 * ab_ab;
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t9 * a_minus_b + T(2) * ab_ap * t10 + T(3) * t5 * t8 * ab_ab;
    const T t12 = T(2) * t9 - T(2) * t10 - ab_ap * t11 * t5;
    const T t13 = T(1) / ab_ab;
    const T t14 = T(4) * t5 * t8 - T(2) * ab_ap * t12 * t13 - t11 * ap_ap * t5;
    F = (T(1) / T(8)) * (T(2) * ab_ap * t14 * t13 + ap_ap * t12 * t13 + T(4) * (t6 + ab_ap * t5 * t8 - t7) * t13) * in.w[3] * t13 + (T(1) / T(8)) * t11 * in.w[0] * t5 + (T(1) / T(8)) * in.w[2] * t14 * t13 - (T(1) / T(8)) * in.w[1] * t12 * t13;
    const T t15 = t9 * t7;
    const T t16 = t10 * t6;
    const T t17 = T(8) * t15 * a_minus_b + T(5) * t11 * t5 * ab_ab + T(8) * ab_ap * t16;
    const T t18 = T(8) * t15 - ab_ap * t17 * t5 - T(8) * t16;
    const T t19 = T(6) * t11 * t5 - t17 * ap_ap * t5 - T(2) * ab_ap * t18 * t13;
    const T t20 = ap_ap * t18 * t13 + T(2) * ab_ap * t19 * t13 - T(6) * t12 * t13;
    G_ap = (T(1) / T(48)) * in.w[2] * t19 * t13 + (T(1) / T(48)) * t17 * in.w[0] * t5 + (T(1) / T(48)) * in.w[3] * t20 * t13 - (T(1) / T(48)) * in.w[1] * t18 * t13;
    G_ab = (T(1) / T(48)) * in.w[1] * t19 * t13 + (T(1) / T(48)) * in.w[2] * t20 * t13 - (T(1) / T(48)) * t18 * in.w[0] * t13 - (T(1) / T(48)) * in.w[3] * t13 * (ap_ap * t19 * t13 - T(2) * ab_ap * t20 * t13 - T(6) * t14 * t13);
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 31 +, 55 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 844 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = t4 * t4;
    const T t9 = t6 * t6;
    F = (T(1) / T(15)) * (T(4) * (a_minus_b * t4 * t3 + t6 * t5 * ab_ap + T(2) * ab_ab * t7 * (a_minus_b * t3 + t5 * ab_ap)) * ab_ab * t7 + T(3) * a_minus_b * t8 * t3 + T(3) * t9 * t5 * ab_ap) * in.w[0] * t7;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 38 +, 83 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1545 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(5) * t3 * a_minus_b * t6 + T(5) * ab_ap * t7 * t10 + T(2) * t11 * ab_ab * (T(4) * t11 * ab_ab * (T(2) * t11 * ab_ab * (t3 * a_minus_b + ab_ap * t7) + ab_ap * t7 * t8 + t3 * a_minus_b * t4) + T(3) * t3 * a_minus_b * t5 + T(3) * ab_ap * t7 * t9);
    G_ap = (T(1) / T(35)) * t12 * in.w[0] * t11;
    G_ab = (T(1) / T(35)) * in.w[0] * (T(5) * t7 * t10 + t12 * t11 * ab_ap - T(5) * t3 * t6) / ab_ab;
  }
  const T g_factor = -T(7) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 38 +, 87 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1569 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = T(4) * t3 * ab_ab * (t4 * t5 * a_minus_b + T(2) * t3 * ab_ab * (t4 * a_minus_b + t6 * ab_ap) + t7 * t6 * ab_ap) + T(3) * t8 * t6 * ab_ap + T(3) * t4 * t9 * a_minus_b;
    F = (T(1) / T(15)) * in.w[0] * t3 * t10;
    const T t11 = t8 * t7;
    const T t12 = t9 * t5;
    const T t13 = T(5) * t11 * t6 * ab_ap + T(5) * t4 * t12 * a_minus_b + T(2) * t3 * ab_ab * t10;
    G_ap = (T(1) / T(35)) * t13 * in.w[0] * t3;
    G_ab = (T(1) / T(35)) * in.w[0] * (T(5) * t11 * t6 + t13 * t3 * ab_ap - T(5) * t4 * t12) / ab_ab;
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Returns false where segment_inverse_i7_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 38 +, 87 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i7_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t4 * t6 * a_minus_b + T(4) * t3 * ab_ab * (t7 * ab_ap * t8 + t4 * t5 * a_minus_b + T(2) * t3 * ab_ab * (t4 * a_minus_b + t7 * ab_ap)) + T(3) * t7 * ab_ap * t9;
    F = (T(1) / T(15)) * in.w[0] * t3 * t10;
    const T t11 = t6 * t5;
    const T t12 = t9 * t8;
    const T t13 = T(2) * t3 * t10 * ab_ab + T(5) * t4 * t11 * a_minus_b + T(5) * t7 * ab_ap * t12;
    G_ap = (T(1) / T(35)) * in.w[0] * t3 * t13;
    G_ab = -(T(1) / T(35)) * in.w[0] * (T(5) * t4 * t11 - T(5) * t7 * t12 - t3 * ab_ap * t13) / ab_ab;
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 34 +, 63 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1534 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = T(4) * (a_minus_b * t5 * t4 + t6 * ab_ap * t7 + T(2) * t3 * ab_ab * (a_minus_b * t4 + t6 * ab_ap)) * t3 * ab_ab + T(3) * t6 * ab_ap * t8 + T(3) * a_minus_b * t9 * t4;
    F = (T(1) / T(15)) * t3 * t10 * in.w[0] + (T(1) / T(15)) * in.w[1] * (T(3) * t6 * t8 + t3 * t10 * ab_ap - T(3) * t9 * t4) / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 42 +, 98 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2238 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(3) * ab_ap * t4 * t6 + T(3) * t8 * a_minus_b * t10 + T(4) * (T(2) * (t8 * a_minus_b + ab_ap * t4) * t3 * ab_ab + t8 * a_minus_b * t9 + ab_ap * t4 * t5) * t3 * ab_ab;
    const T t13 = T(5) * ab_ap * t4 * t7 + T(5) * t8 * a_minus_b * t11 + T(2) * t12 * t3 * ab_ab;
    const T t14 = ab_ap * t3 * t13 + T(5) * t4 * t7 - T(5) * t8 * t11;
    const T t15 = T(1) / ab_ab;
    G_ap = (T(1) / T(35)) * in.w[0] * t3 * t13 + (T(1) / T(35)) * t14 * t15 * in.w[1];
    G_ab = (T(1) / T(35)) * t14 * in.w[0] * t15 + (T(1) / T(105)) * (T(7) * t12 * t3 + T(6) * ab_ap * t14 * t15 - T(3) * ap_ap * t3 * t13) * t15 * in.w[1];
  }
  const T g_factor = -T(7) * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 45 +, 111 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2276 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(3) * t8 * a_minus_b * t6 + T(3) * ab_ap * t5 * t3 + T(4) * (ab_ap * t4 * t3 + T(2) * (a_minus_b * t6 + ab_ap * t3) * t9 * ab_ab + t7 * a_minus_b * t6) * t9 * ab_ab;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(15)) * (T(3) * t5 * t3 + ab_ap * t10 * t9 - T(3) * t8 * t6) * in.w[1] * t11 + (T(1) / T(15)) * in.w[0] * t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = t8 * t7;
    const T t14 = T(5) * ab_ap * t12 * t3 + T(2) * t10 * t9 * ab_ab + T(5) * t13 * a_minus_b * t6;
    const T t15 = T(5) * t13 * t6 - T(5) * t12 * t3 - ab_ap * t9 * t14;
    G_ap = (T(1) / T(35)) * in.w[0] * t9 * t14 - (T(1) / T(35)) * in.w[1] * t11 * t15;
    G_ab = (T(1) / T(105)) * (T(7) * t10 * t9 - T(6) * ab_ap * t11 * t15 - T(3) * ap_ap * t9 * t14) * in.w[1] * t11 - (T(1) / T(35)) * in.w[0] * t11 * t15;
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Returns false where segment_inverse_i7_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 111 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i7_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = t6 * t6;
    const T t9 = t4 * t4;
    const T t10 = T(4) * ab_ab * (ab_ap * t4 * t3 + t6 * t5 * a_minus_b + T(2) * ab_ab * (ab_ap * t3 + t5 * a_minus_b) * t7) * t7 + T(3) * t8 * t5 * a_minus_b + T(3) * ab_ap * t9 * t3;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(15)) * t10 * in.w[0] * t7 - (T(1) / T(15)) * t11 * (T(3) * t8 * t5 - t10 * ab_ap * t7 - T(3) * t9 * t3) * in.w[1];
    const T t12 = t9 * t4;
    const T t13 = t8 * t6;
    const T t14 = T(2) * ab_ab * t10 * t7 + T(5) * ab_ap * t12 * t3 + T(5) * t13 * t5 * a_minus_b;
    const T t15 = T(5) * t13 * t5 - t14 * ab_ap * t7 - T(5) * t12 * t3;
    G_ap = (T(1) / T(35)) * t14 * in.w[0] * t7 - (T(1) / T(35)) * t11 * t15 * in.w[1];
    G_ab = (T(1) / T(105)) * t11 * (T(7) * t10 * t7 - T(3) * t14 * ap_ap * t7 - T(6) * t11 * ab_ap * t15) * in.w[1] - (T(1) / T(35)) * t11 * t15 * in.w[0];
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 37 +, 74 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2226 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = ab_ap * t8 * t7 + T(2) * (ab_ap * t7 + t4 * a_minus_b) * t3 * ab_ab + t4 * a_minus_b * t5;
    const T t11 = T(3) * t4 * a_minus_b * t6 + T(3) * ab_ap * t9 * t7 + T(4) * t3 * ab_ab * t10;
    const T t12 = T(3) * t4 * t6 - T(3) * t9 * t7 - ab_ap * t3 * t11;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(15)) * in.w[0] * t3 * t11 - (T(1) / T(15)) * in.w[2] * (T(2) * ab_ap * t12 * t13 + ap_ap * t3 * t11 - T(5) * t3 * t10) * t13 - (T(1) / T(15)) * in.w[1] * t12 * t13;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 48 +, 118 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2933 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ab = M_flat[3] * in.w[2] + M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(3) * t4 * a_minus_b * t6 + T(3) * t10 * ab_ap * t8 + T(4) * t3 * ab_ab * (t9 * ab_ap * t8 + T(2) * t3 * ab_ab * (ab_ap * t8 + t4 * a_minus_b) + t4 * a_minus_b * t5);
    const T t13 = T(5) * t4 * a_minus_b * t7 + T(5) * t11 * ab_ap * t8 + T(2) * t3 * ab_ab * t12;
    const T t14 = T(5) * t4 * t7 - t3 * t13 * ab_ap - T(5) * t11 * t8;
    const T t15 = T(1) / ab_ab;
    const T t16 = T(7) * t3 * t12 - T(6) * t14 * t15 * ab_ap - T(3) * ap_ap * t3 * t13;
    G_ap = (T(1) / T(35)) * t3 * t13 * in.w[0] + (T(1) / T(105)) * in.w[2] * t16 * t15 - (T(1) / T(35)) * in.w[1] * t14 * t15;
    G_ab = (T(1) / T(105)) * in.w[2] * (T(3) * ap_ap * t14 * t15 + T(2) * t16 * t15 * ab_ap - T(7) * t15 * (T(3) * t4 * t6 - T(3) * t10 * t8 - t3 * t12 * ab_ap)) * t15 + (T(1) / T(105)) * in.w[1] * t16 * t15 - (T(1) / T(35)) * t14 * t15 * in.w[0];
  }
  const T g_factor = -T(7) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 52 +, 135 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2987 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
    G_ab = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2];
    G_ap = in.w[1] * M_beyond[5] + M_beyond[6] * in.w[2] + M_beyond[4] * in.w[0];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = a_minus_b * t7 * t8 + ab_ap * t4 * t3 + T(2) * (ab_ap * t3 + a_minus_b * t7) * t6 * ab_ab;
    const T t10 = t8 * t8;
    const T t11 = T(4) * t9 * t6 * ab_ab + T(3) * ab_ap * t5 * t3 + T(3) * a_minus_b * t7 * t10;
    const T t12 = T(3) * t5 * t3 + ab_ap * t6 * t11 - T(3) * t7 * t10;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(15)) * in.w[1] * t12 * t13 + (T(1) / T(15)) * in.w[2] * (T(5) * t9 * t6 + T(2) * ab_ap * t12 * t13 - ap_ap * t6 * t11) * t13 + (T(1) / T(15)) * t6 * t11 * in.w[0];
    const T t14 = t5 * t4;
    const T t15 = t10 * t8;
    const T t16 = T(5) * ab_ap * t14 * t3 + T(5) * a_minus_b * t7 * t15 + T(2) * t6 * ab_ab * t11;
    const T t17 = T(5) * t7 * t15 - T(5) * t14 * t3 - ab_ap * t6 * t16;
    const T t18 = T(3) * ap_ap * t6 * t16 + T(6) * ab_ap * t17 * t13 - T(7) * t6 * t11;
    G_ap = (T(1) / T(35)) * t6 * t16 * in.w[0] - (T(1) / T(105)) * t18 * in.w[2] * t13 - (T(1) / T(35)) * t17 * in.w[1] * t13;
    G_ab = -(T(1) / T(35)) * t17 * t13 * in.w[0] - (T(1) / T(105)) * in.w[2] * t13 * (T(2) * ab_ap * t18 * t13 - T(7) * t12 * t13 - T(3) * t17 * ap_ap * t13) - (T(1) / T(105)) * t18 * in.w[1] * t13;
  }
  const T g_factor = -T(7) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Returns false where segment_inverse_i7_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 135 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i7_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + in.w[2] * M_flat[6];
    G_ab = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * t4;
    const T t7 = t5 * t5;
    const T t8 = T(2) * (t4 * ab_ap + t5 * a_minus_b) * t3 * ab_ab + t6 * t4 * ab_ap + t5 * t7 * a_minus_b;
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(4) * t3 * ab_ab * t8 + T(3) * t5 * t9 * a_minus_b + T(3) * t10 * t4 * ab_ap;
    const T t12 = T(3) * t5 * t9 - T(3) * t10 * t4 - t3 * t11 * ab_ap;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(15)) * t3 * t11 * in.w[0] + (T(1) / T(15)) * (T(5) * t3 * t8 - ap_ap * t3 * t11 - T(2) * t12 * t13 * ab_ap) * in.w[2] * t13 - (T(1) / T(15)) * in.w[1] * t12 * t13;
    const T t14 = t10 * t6;
    const T t15 = t9 * t7;
    const T t16 = T(2) * t3 * ab_ab * t11 + T(5) * t14 * t4 * ab_ap + T(5) * t5 * t15 * a_minus_b;
    const T t17 = T(5) * t5 * t15 - t16 * t3 * ab_ap - T(5) * t14 * t4;
    const T t18 = T(6) * t17 * t13 * ab_ap + T(3) * t16 * ap_ap * t3 - T(7) * t3 * t11;
    G_ap = (T(1) / T(35)) * t16 * t3 * in.w[0] - (T(1) / T(105)) * t18 * in.w[2] * t13 - (T(1) / T(35)) * in.w[1] * t17 * t13;
    G_ab = (T(1) / T(105)) * in.w[2] * t13 * (T(3) * t17 * ap_ap * t13 - T(7) * t12 * t13 - T(2) * t18 * t13 * ab_ap) - (T(1) / T(105)) * in.w[1] * t18 * t13 - (T(1) / T(35)) * t17 * t13 * in.w[0];
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 42 +, 88 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2920 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t8 * a_minus_b * t9 + T(2) * (t8 * a_minus_b + ab_ap * t5) * t4 * ab_ab + ab_ap * t6 * t5;
    const T t11 = t9 * t9;
    const T t12 = T(3) * ab_ap * t7 * t5 + T(4) * t10 * t4 * ab_ab + T(3) * t8 * a_minus_b * t11;
    const T t13 = ab_ap * t4 * t12 + T(3) * t7 * t5 - T(3) * t8 * t11;
    const T t14 = T(2) * ab_ap * t13 * t3 + T(5) * t10 * t4 - ap_ap * t4 * t12;
    F = (T(1) / T(15)) * in.w[2] * t3 * t14 + (T(1) / T(15)) * t4 * in.w[0] * t12 + (T(1) / T(15)) * t13 * t3 * in.w[1] + (T(1) / T(15)) * in.w[3] * t3 * (T(5) * t3 * (t6 * t5 + ab_ap * t10 * t4 - t8 * t9) + T(2) * ab_ap * t3 * t14 - ap_ap * t13 * t3);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 54 +, 138 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3630 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ab = in.w[2] * M_flat[3] + in.w[1] * M_flat[2] + in.w[0] * M_flat[1] + in.w[3] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t8 * a_minus_b * t9 + t5 * ab_ap * t4 + T(2) * (ab_ap * t4 + t8 * a_minus_b) * t3 * ab_ab;
    const T t11 = t9 * t9;
    const T t12 = T(4) * t3 * ab_ab * t10 + T(3) * t6 * ab_ap * t4 + T(3) * t8 * a_minus_b * t11;
    const T t13 = t11 * t9;
    const T t14 = T(5) * t7 * ab_ap * t4 + T(2) * t3 * ab_ab * t12 + T(5) * t8 * a_minus_b * t13;
    const T t15 = T(1) / ab_ab;
    const T t16 = T(5) * t8 * t13 - t3 * t14 * ab_ap - T(5) * t7 * t4;
    const T t17 = T(6) * t15 * t16 * ab_ap + T(3) * ap_ap * t3 * t14 - T(7) * t3 * t12;
    const T t18 = T(3) * t8 * t11 - t3 * t12 * ab_ap - T(3) * t6 * t4;
    const T t19 = T(7) * t15 * t18 + T(2) * t15 * t17 * ab_ap - T(3) * ap_ap * t15 * t16;
    G_ap = (T(1) / T(35)) * t3 * in.w[0] * t14 - (T(1) / T(105)) * in.w[2] * t15 * t17 - (T(1) / T(35)) * t15 * in.w[1] * t16 - (T(1) / T(105)) * in.w[3] * t15 * t19;
    G_ab = (T(1) / T(105)) * in.w[3] * t15 * (ap_ap * t15 * t17 - T(7) * (ap_ap * t3 * t12 + T(2) * t15 * ab_ap * t18 - T(5) * t3 * t10) * t15 - T(2) * t15 * t19 * ab_ap) - (T(1) / T(105)) * t15 * t17 * in.w[1] - (T(1) / T(105)) * in.w[2] * t15 * t19 - (T(1) / T(35)) * in.w[0] * t15 * t16;
  }
  const T g_factor = -T(7) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 61 +, 162 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1337 +, 3702 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i7_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[6] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
    G_ab = M_flat[8] * in.w[2] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + in.w[1] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
    G_ab = in.w[1] * M_beyond[7] + in.w[2] * M_beyond[8] + M_beyond[6] * in.w[0] + M_beyond[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = T(2) * (t4 * a_minus_b + ab_ap * t7) * t3 * ab_ab + ab_ap * t8 * t7 + t4 * t5 * a_minus_b;
    const T t10 = t8 * t8;
    const T t11 = T(3) * t4 * t6 * a_minus_b + T(4) * t9 * t3 * ab_ab + T(3) * ab_ap * t10 * t7;
    const T t12 = ab_ap * t3 * t11 + T(3) * t10 * t7 - T(3) * t4 * t6;
    const T t13 = T(1) / ab_ab;
    const T t14 = T(2) * ab_ap * t12 * t13 + T(5) * t9 * t3 - ap_ap * t3 * t11;
    F = (T(1) / T(15)) * in.w[0] * t3 * t11 + (T(1) / T(15)) * in.w[1] * t12 * t13 + (T(1) / T(15)) * in.w[2] * t14 * t13 - (T(1) / T(15)) * (t12 * ap_ap * t13 - T(2) * ab_ap * t14 * t13 - T(5) * t13 * (ab_ap * t9 * t3 + t8 * t7 - t4 * t5)) * in.w[3] * t13;
    const T t15 = t6 * t5;
    const T t16 = t10 * t8;
    const T t17 = T(5) * t4 * t15 * a_minus_b + T(5) * ab_ap * t16 * t7 + T(2) * t3 * t11 * ab_ab;
    const T t18 = T(5) * t4 * t15 - T(5) * t16 * t7 - ab_ap * t17 * t3;
    const T t19 = T(6) * t18 * ab_ap * t13 + T(3) * t17 * ap_ap * t3 - T(7) * t3 * t11;
    const T t20 = T(7) * t12 * t13 + T(3) * t18 * ap_ap * t13 - T(2) * ab_ap * t19 * t13;
    G_ap = (T(1) / T(105)) * t20 * in.w[3] * t13 + (T(1) / T(35)) * t17 * in.w[0] * t3 - (T(1) / T(105)) * in.w[2] * t19 * t13 - (T(1) / T(35)) * in.w[1] * t18 * t13;
    G_ab = (T(1) / T(105)) * t20 * in.w[2] * t13 + (T(1) / T(105)) * (ap_ap * t19 * t13 + T(7) * t14 * t13 + T(2) * ab_ap * t20 * t13) * in.w[3] * t13 - (T(1) / T(35)) * t18 * in.w[0] * t13 - (T(1) / T(105)) * in.w[1] * t19 * t13;
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Returns false where segment_inverse_i7_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 162 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i7_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ap = M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2] + in.w[3] * M_flat[8];
    G_ab = M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + M_flat[6] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(2) * t10 * ab_ab * (t7 * a_minus_b + t4 * ab_ap) + t5 * t4 * ab_ap + t7 * t8 * a_minus_b;
    const T t12 = T(3) * t7 * t9 * a_minus_b + T(4) * t11 * t10 * ab_ab + T(3) * t6 * t4 * ab_ap;
    const T t13 = T(3) * t6 * t4 + t12 * t10 * ab_ap - T(3) * t7 * t9;
    const T t14 = T(2) * t3 * ab_ap * t13 + T(5) * t11 * t10 - ap_ap * t12 * t10;
    F = (T(1) / T(15)) * t14 * t3 * in.w[2] + (T(1) / T(15)) * t12 * t10 * in.w[0] + (T(1) / T(15)) * t3 * in.w[1] * t13 - (T(1) / T(15)) * (ap_ap * t3 * t13 - T(5) * t3 * (t11 * t10 * ab_ap + t5 * t4 - t7 * t8) - T(2) * t14 * t3 * ab_ap) * in.w[3] * t3;
    const T t15 = t9 * t8;
    const T t16 = t6 * t5;
    const T t17 = T(5) * t7 * t15 * a_minus_b + T(5) * t16 * t4 * ab_ap + T(2) * t12 * t10 * ab_ab;
    const T t18 = t10 * t17 * ab_ap + T(5) * t16 * t4 - T(5) * t7 * t15;
    const T t19 = T(7) * t12 * t10 + T(6) * t3 * t18 * ab_ap - T(3) * ap_ap * t10 * t17;
    const T t20 = T(2) * t19 * t3 * ab_ap + T(7) * t3 * t13 - T(3) * ap_ap * t3 * t18;
    G_ap = (T(1) / T(105)) * t19 * t3 * in.w[2] + (T(1) / T(105)) * in.w[3] * t20 * t3 + (T(1) / T(35)) * t3 * in.w[1] * t18 + (T(1) / T(35)) * t10 * in.w[0] * t17;
    G_ab = (T(1) / T(105)) * t20 * t3 * in.w[2] + (T(1) / T(35)) * in.w[0] * t3 * t18 + (T(1) / T(105)) * in.w[3] * t3 * (T(7) * t14 * t3 + T(2) * t20 * t3 * ab_ap - ap_ap * t19 * t3) + (T(1) / T(105)) * t19 * t3 * in.w[1];
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 34 +, 58 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 849 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    F = (T(1) / T(48)) * (T(8) * ab_ap * t7 + T(8) * t10 * a_minus_b + T(5) * ab_ab * (T(2) * t9 * a_minus_b + T(2) * ab_ap * t6 + T(3) * ab_ab * (ab_ab * J2 + t8 * a_minus_b + ab_ap * t5) * t11) * t11) * in.w[0] * t11;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 41 +, 82 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1550 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t7 * t6;
    const T t11 = t9 * t8;
    const T t12 = t7 * t7;
    const T t13 = t9 * t9;
    const T t14 = T(7) * t5 * ab_ab * (T(5) * (T(2) * a_minus_b * t7 + T(3) * (ab_ap * t8 + ab_ab * J2 + a_minus_b * t6) * t5 * ab_ab + T(2) * ab_ap * t9) * t5 * ab_ab + T(8) * a_minus_b * t10 + T(8) * ab_ap * t11) + T(48) * a_minus_b * t12 + T(48) * ab_ap * t13;
    G_ap = (T(1) / T(384)) * t14 * in.w[0] * t5;
    G_ab = -(T(1) / T(384)) * (T(48) * t12 - T(48) * t13 - t14 * ab_ap * t5) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(8) * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 41 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1575 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t8 * t7;
    const T t11 = t9 * t6;
    const T t12 = T(5) * ab_ab * (T(3) * ab_ab * t5 * (ab_ap * t6 + t7 * a_minus_b + ab_ab * J2) + T(2) * t8 * a_minus_b + T(2) * ab_ap * t9) * t5 + T(8) * t10 * a_minus_b + T(8) * ab_ap * t11;
    F = (T(1) / T(48)) * in.w[0] * t12 * t5;
    const T t13 = t9 * t9;
    const T t14 = t8 * t8;
    const T t15 = T(7) * ab_ab * t12 * t5 + T(48) * ab_ap * t13 + T(48) * t14 * a_minus_b;
    G_ap = (T(1) / T(384)) * t15 * in.w[0] * t5;
    G_ab = (T(1) / T(384)) * (t15 * ab_ap * t5 + T(48) * t13 - T(48) * t14) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Returns false where segment_inverse_i8_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i8_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * t8 * a_minus_b + T(8) * ab_ap * t11 + T(5) * (T(2) * t7 * a_minus_b + T(3) * (J2 * ab_ab + ab_ap * t9 + t6 * a_minus_b) * t5 * ab_ab + T(2) * ab_ap * t10) * t5 * ab_ab;
    F = (T(1) / T(48)) * in.w[0] * t5 * t12;
    const T t13 = t10 * t10;
    const T t14 = t7 * t7;
    const T t15 = T(48) * ab_ap * t13 + T(7) * t5 * ab_ab * t12 + T(48) * t14 * a_minus_b;
    G_ap = (T(1) / T(384)) * t15 * in.w[0] * t5;
    G_ab = -(T(1) / T(384)) * (T(48) * t14 - ab_ap * t15 * t5 - T(48) * t13) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(8) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 37 +, 64 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1539 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = T(5) * (T(3) * t5 * (J2 * ab_ab + ab_ap * t6 + t7 * a_minus_b) * ab_ab + T(2) * t8 * a_minus_b + T(2) * ab_ap * t9) * t5 * ab_ab + T(8) * ab_ap * t10 + T(8) * t11 * a_minus_b;
    F = (T(1) / T(48)) * in.w[0] * t5 * t12 + (T(1) / T(48)) * in.w[1] * (ab_ap * t5 * t12 + T(8) * t10 - T(8) * t11) / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 45 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2243 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = T(5) * (T(3) * t5 * ab_ab * (a_minus_b * t6 + ab_ap * t7 + ab_ab * J2) + T(2) * ab_ap * t8 + T(2) * a_minus_b * t9) * t5 * ab_ab + T(8) * a_minus_b * t10 + T(8) * ab_ap * t11;
    const T t13 = t8 * t8;
    const T t14 = t9 * t9;
    const T t15 = T(7) * t5 * ab_ab * t12 + T(48) * ab_ap * t13 + T(48) * a_minus_b * t14;
    const T t16 = ab_ap * t15 * t5 + T(48) * t13 - T(48) * t14;
    const T t17 = T(1) / ab_ab;
    G_ap = (T(1) / T(384)) * t16 * in.w[1] * t17 + (T(1) / T(384)) * in.w[0] * t15 * t5;
    G_ab = (T(1) / T(384)) * t16 * in.w[0] * t17 + (T(1) / T(384)) * (T(8) * t5 * t12 + T(2) * ab_ap * t16 * t17 - ap_ap * t15 * t5) * in.w[1] * t17;
  }
  const T g_factor = -T(8) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 48 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2282 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = t9 * t8;
    const T t12 = T(8) * a_minus_b * t7 + T(5) * (T(2) * ab_ap * t9 + T(2) * a_minus_b * t6 + T(3) * (J2 * ab_ab + ab_ap * t8 + a_minus_b * t5) * t10 * ab_ab) * t10 * ab_ab + T(8) * ab_ap * t11;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(48)) * (ab_ap * t12 * t10 + T(8) * t11 - T(8) * t7) * in.w[1] * t13 + (T(1) / T(48)) * t12 * in.w[0] * t10;
    const T t14 = t9 * t9;
    const T t15 = t6 * t6;
    const T t16 = T(7) * t12 * t10 * ab_ab + T(48) * ab_ap * t14 + T(48) * a_minus_b * t15;
    const T t17 = ab_ap * t16 * t10 + T(48) * t14 - T(48) * t15;
    G_ap = (T(1) / T(384)) * in.w[0] * t16 * t10 + (T(1) / T(384)) * t17 * in.w[1] * t13;
    G_ab = (T(1) / T(384)) * t17 * in.w[0] * t13 - (T(1) / T(384)) * (ap_ap * t16 * t10 - T(8) * t12 * t10 - T(2) * ab_ap * t17 * t13) * in.w[1] * t13;
  }
  const T g_factor = -T(8) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Returns false where segment_inverse_i8_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 48 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i8_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * t9 * ab_ap + T(5) * (T(2) * t8 * ab_ap + T(3) * (J2 * ab_ab + a_minus_b * t10 + t7 * ab_ap) * t6 * ab_ab + T(2) * a_minus_b * t11) * t6 * ab_ab + T(8) * a_minus_b * t12;
    F = (T(1) / T(48)) * in.w[1] * t5 * (t6 * t13 * ab_ap + T(8) * t9 - T(8) * t12) + (T(1) / T(48)) * in.w[0] * t6 * t13;
    const T t14 = t8 * t8;
    const T t15 = t11 * t11;
    const T t16 = T(7) * t6 * ab_ab * t13 + T(48) * t14 * ab_ap + T(48) * a_minus_b * t15;
    const T t17 = t16 * t6 * ab_ap + T(48) * t14 - T(48) * t15;
    G_ap = (T(1) / T(384)) * t17 * in.w[1] * t5 + (T(1) / T(384)) * in.w[0] * t16 * t6;
    G_ab = (T(1) / T(384)) * in.w[0] * t17 * t5 - (T(1) / T(384)) * (ap_ap * t16 * t6 - T(8) * t6 * t13 - T(2) * t17 * t5 * ab_ap) * in.w[1] * t5;
  }
  const T g_factor = -T(8) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 40 +, 75 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2231 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(3) * t5 * ab_ab * (ab_ap * t6 + J2 * ab_ab + a_minus_b * t7) + T(2) * a_minus_b * t8 + T(2) * ab_ap * t9;
    const T t11 = t8 * t7;
    const T t12 = t9 * t6;
    const T t13 = T(5) * t10 * t5 * ab_ab + T(8) * a_minus_b * t11 + T(8) * ab_ap * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = t13 * t5 * ab_ap + T(8) * t12 - T(8) * t11;
    F = (T(1) / T(48)) * t13 * t5 * in.w[0] + (T(1) / T(48)) * in.w[2] * (T(2) * t14 * ab_ap * t15 + T(6) * t10 * t5 - t13 * t5 * ap_ap) * t14 + (T(1) / T(48)) * t14 * t15 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 51 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2938 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * a_minus_b * t8 + T(8) * ab_ap * t11 + T(5) * t5 * ab_ab * (T(2) * a_minus_b * t7 + T(2) * ab_ap * t10 + T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t9 + a_minus_b * t6));
    const T t13 = t7 * t7;
    const T t14 = t10 * t10;
    const T t15 = T(7) * t5 * ab_ab * t12 + T(48) * a_minus_b * t13 + T(48) * ab_ap * t14;
    const T t16 = t5 * t15 * ab_ap + T(48) * t14 - T(48) * t13;
    const T t17 = T(1) / ab_ab;
    const T t18 = t5 * t15 * ap_ap - T(2) * t16 * t17 * ab_ap - T(8) * t5 * t12;
    G_ap = (T(1) / T(384)) * t5 * t15 * in.w[0] + (T(1) / T(384)) * t16 * t17 * in.w[1] - (T(1) / T(384)) * in.w[2] * t18 * t17;
    G_ab = (T(1) / T(384)) * t16 * t17 * in.w[0] - (T(1) / T(384)) * in.w[2] * t17 * (t16 * t17 * ap_ap + T(2) * t18 * t17 * ab_ap + T(8) * t17 * (T(8) * t8 - T(8) * t11 - t5 * ab_ap * t12)) - (T(1) / T(384)) * t18 * t17 * in.w[1];
  }
  const T g_factor = -T(8) * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 55 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 2993 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ap = in.w[2] * M_beyond[6] + M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
    G_ab = M_beyond[6] * in.w[1] + in.w[2] * M_beyond[7] + M_beyond[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = T(2) * ab_ap * t8 + T(2) * t11 * a_minus_b + T(3) * t6 * ab_ab * (t10 * a_minus_b + ab_ab * J2 + ab_ap * t7);
    const T t13 = t11 * t10;
    const T t14 = T(8) * ab_ap * t9 + T(5) * t12 * t6 * ab_ab + T(8) * t13 * a_minus_b;
    const T t15 = t6 * ab_ap * t14 + T(8) * t9 - T(8) * t13;
    F = (T(1) / T(48)) * (T(2) * t5 * ab_ap * t15 + T(6) * t12 * t6 - t6 * t14 * ap_ap) * in.w[2] * t5 + (T(1) / T(48)) * t6 * in.w[0] * t14 + (T(1) / T(48)) * t5 * in.w[1] * t15;
    const T t16 = t8 * t8;
    const T t17 = t11 * t11;
    const T t18 = T(48) * t17 * a_minus_b + T(48) * ab_ap * t16 + T(7) * t6 * ab_ab * t14;
    const T t19 = T(48) * t16 + t6 * t18 * ab_ap - T(48) * t17;
    const T t20 = T(8) * t6 * t14 + T(2) * t19 * t5 * ab_ap - t6 * t18 * ap_ap;
    G_ap = (T(1) / T(384)) * t19 * t5 * in.w[1] + (T(1) / T(384)) * t20 * in.w[2] * t5 + (T(1) / T(384)) * t6 * t18 * in.w[0];
    G_ab = (T(1) / T(384)) * t20 * t5 * in.w[1] + (T(1) / T(384)) * t19 * t5 * in.w[0] + (T(1) / T(384)) * in.w[2] * t5 * (T(2) * t20 * t5 * ab_ap + T(8) * t5 * t15 - t19 * t5 * ap_ap);
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Returns false where segment_inverse_i8_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 55 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i8_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + in.w[2] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = T(2) * ab_ap * t10 + T(2) * t7 * a_minus_b + T(3) * t5 * ab_ab * (ab_ap * t9 + t6 * a_minus_b + ab_ab * J2);
    const T t12 = t10 * t9;
    const T t13 = T(8) * t8 * a_minus_b + T(5) * t11 * t5 * ab_ab + T(8) * ab_ap * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = t5 * ab_ap * t13 + T(8) * t12 - T(8) * t8;
    F = (T(1) / T(48)) * t5 * in.w[0] * t13 + (T(1) / T(48)) * t14 * in.w[1] * t15 - (T(1) / T(48)) * in.w[2] * (t5 * t13 * ap_ap - T(6) * t11 * t5 - T(2) * t14 * ab_ap * t15) * t14;
    const T t16 = t10 * t10;
    const T t17 = t7 * t7;
    const T t18 = T(48) * t17 * a_minus_b + T(48) * ab_ap * t16 + T(7) * t5 * ab_ab * t13;
    const T t19 = T(48) * t16 + t18 * t5 * ab_ap - T(48) * t17;
    const T t20 = t18 * t5 * ap_ap - T(8) * t5 * t13 - T(2) * t14 * t19 * ab_ap;
    G_ap = (T(1) / T(384)) * t14 * t19 * in.w[1] + (T(1) / T(384)) * t18 * t5 * in.w[0] - (T(1) / T(384)) * in.w[2] * t14 * t20;
    G_ab = (T(1) / T(384)) * in.w[2] * t14 * (T(8) * t14 * t15 - t14 * t19 * ap_ap - T(2) * t14 * ab_ap * t20) + (T(1) / T(384)) * t14 * t19 * in.w[0] - (T(1) / T(384)) * t14 * in.w[1] * t20;
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 45 +, 89 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2925 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(2) * ab_ap * t6 + T(2) * a_minus_b * t9 + T(3) * t11 * ab_ab * (J2 * ab_ab + a_minus_b * t8 + ab_ap * t5);
    const T t13 = T(8) * ab_ap * t7 + T(8) * a_minus_b * t10 + T(5) * t11 * ab_ab * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(8) * t10 - T(8) * t7 - t13 * t11 * ab_ap;
    const T t16 = t13 * t11 * ap_ap + T(2) * t14 * ab_ap * t15 - T(6) * t11 * t12;
    F = (T(1) / T(48)) * t13 * t11 * in.w[0] - (T(1) / T(48)) * t14 * t16 * in.w[2] - (T(1) / T(48)) * t14 * in.w[1] * t15 - (T(1) / T(48)) * (T(6) * t14 * (T(2) * t9 - T(2) * t6 - t11 * t12 * ab_ap) + T(2) * t14 * ab_ap * t16 - t14 * t15 * ap_ap) * in.w[3] * t14;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 57 +, 133 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3635 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ab = in.w[1] * M_flat[2] + in.w[2] * M_flat[3] + M_flat[1] * in.w[0] + M_flat[4] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(1) / cross_cross;
    const T t13 = T(2) * a_minus_b * t10 + T(3) * ab_ab * (ab_ap * t6 + a_minus_b * t9 + ab_ab * J2) * t12 + T(2) * ab_ap * t7;
    const T t14 = T(8) * ab_ap * t8 + T(8) * a_minus_b * t11 + T(5) * ab_ab * t13 * t12;
    const T t15 = ab_ap * t14 * t12 + T(8) * t8 - T(8) * t11;
    const T t16 = t10 * t10;
    const T t17 = t7 * t7;
    const T t18 = T(7) * ab_ab * t14 * t12 + T(48) * a_minus_b * t16 + T(48) * ab_ap * t17;
    const T t19 = ab_ap * t18 * t12 + T(48) * t17 - T(48) * t16;
    const T t20 = T(2) * t19 * t5 * ab_ap + T(8) * t14 * t12 - t18 * ap_ap * t12;
    const T t21 = T(8) * t5 * t15 + T(2) * t5 * ab_ap * t20 - t19 * t5 * ap_ap;
    G_ap = (T(1) / T(384)) * t21 * t5 * in.w[3] + (T(1) / T(384)) * t5 * in.w[2] * t20 + (T(1) / T(384)) * t18 * in.w[0] * t12 + (T(1) / T(384)) * t19 * t5 * in.w[1];
    G_ab = (T(1) / T(384)) * t19 * t5 * in.w[0] + (T(1) / T(384)) * t5 * in.w[1] * t20 + (T(1) / T(384)) * t5 * in.w[3] * (T(2) * t21 * t5 * ab_ap - t5 * t20 * ap_ap - T(8) * t5 * (ap_ap * t14 * t12 - T(6) * t13 * t12 - T(2) * t5 * ab_ap * t15)) + (T(1) / T(384)) * t21 * t5 * in.w[2];
  }
  const T g_factor = -T(8) * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 64 +, 157 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3708 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i8_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[3] * in.w[3];
    G_ap = M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[1] * M_flat[6];
    G_ab = M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3];
    G_ab = M_beyond[6] * in.w[0] + M_beyond[9] * in.w[3] + in.w[2] * M_beyond[8] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / ap_ap;
    const T t9 = T(1) / cross_cross;
    const T t10 = t8 * t8;
    const T t11 = T(2) * t6 * a_minus_b + T(3) * ab_ab * (ab_ap * t8 + t5 * a_minus_b + ab_ab * J2) * t9 + T(2) * ab_ap * t10;
    const T t12 = t10 * t8;
    const T t13 = T(8) * t7 * a_minus_b + T(5) * ab_ab * t11 * t9 + T(8) * ab_ap * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(8) * t12 + ab_ap * t13 * t9 - T(8) * t7;
    const T t16 = T(6) * t11 * t9 + T(2) * t14 * ab_ap * t15 - t13 * ap_ap * t9;
    F = (T(1) / T(48)) * t13 * t9 * in.w[0] + (T(1) / T(48)) * (T(6) * t14 * (ab_ap * t11 * t9 + T(2) * t10 - T(2) * t6) + T(2) * t14 * ab_ap * t16 - t14 * t15 * ap_ap) * t14 * in.w[3] + (T(1) / T(48)) * t14 * in.w[2] * t16 + (T(1) / T(48)) * t14 * in.w[1] * t15;
    const T t17 = t10 * t10;
    const T t18 = t6 * t6;
    const T t19 = T(7) * ab_ab * t13 * t9 + T(48) * ab_ap * t17 + T(48) * t18 * a_minus_b;
    const T t20 = ab_ap * t19 * t9 + T(48) * t17 - T(48) * t18;
    const T t21 = t19 * ap_ap * t9 - T(2) * t14 * t20 * ab_ap - T(8) * t13 * t9;
    const T t22 = T(2) * t14 * t21 * ab_ap + t14 * t20 * ap_ap - T(8) * t14 * t15;
    G_ap = (T(1) / T(384)) * t14 * t20 * in.w[1] + (T(1) / T(384)) * t19 * t9 * in.w[0] - (T(1) / T(384)) * t14 * t21 * in.w[2] - (T(1) / T(384)) * t14 * in.w[3] * t22;
    G_ab = (T(1) / T(384)) * t14 * (T(8) * t14 * t16 + t14 * t21 * ap_ap - T(2) * t14 * ab_ap * t22) * in.w[3] + (T(1) / T(384)) * t14 * t20 * in.w[0] - (T(1) / T(384)) * t14 * t21 * in.w[1] - (T(1) / T(384)) * t14 * in.w[2] * t22;
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Returns false where segment_inverse_i8_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 64 +, 157 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i8_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2];
    G_ab = M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = T(2) * ab_ap * t8 + T(3) * t6 * ab_ab * (t10 * a_minus_b + ab_ab * J2 + ab_ap * t7) + T(2) * t11 * a_minus_b;
    const T t13 = t11 * t10;
    const T t14 = T(8) * ab_ap * t9 + T(5) * t6 * ab_ab * t12 + T(8) * t13 * a_minus_b;
    const T t15 = t6 * ab_ap * t14 + T(8) * t9 - T(8) * t13;
    const T t16 = t6 * t14 * ap_ap - T(6) * t6 * t12 - T(2) * t5 * ab_ap * t15;
    F = (T(1) / T(48)) * t5 * t15 * in.w[1] + (T(1) / T(48)) * t6 * in.w[0] * t14 - (T(1) / T(48)) * t5 * (t5 * t15 * ap_ap + T(2) * t5 * ab_ap * t16 - T(6) * t5 * (T(2) * t8 + t6 * ab_ap * t12 - T(2) * t11)) * in.w[3] - (T(1) / T(48)) * t5 * t16 * in.w[2];
    const T t17 = t8 * t8;
    const T t18 = t11 * t11;
    const T t19 = T(48) * t18 * a_minus_b + T(48) * ab_ap * t17 + T(7) * t6 * ab_ab * t14;
    const T t20 = T(48) * t17 + t6 * ab_ap * t19 - T(48) * t18;
    const T t21 = T(2) * t5 * t20 * ab_ap + T(8) * t6 * t14 - t6 * t19 * ap_ap;
    const T t22 = T(8) * t5 * t15 + T(2) * t5 * ab_ap * t21 - t5 * t20 * ap_ap;
    G_ap = (T(1) / T(384)) * t5 * t20 * in.w[1] + (T(1) / T(384)) * t5 * t21 * in.w[2] + (T(1) / T(384)) * t6 * in.w[0] * t19 + (T(1) / T(384)) * t5 * t22 * in.w[3];
    G_ab = (T(1) / T(384)) * t5 * t21 * in.w[1] + (T(1) / T(384)) * t5 * t20 * in.w[0] + (T(1) / T(384)) * t5 * t22 * in.w[2] - (T(1) / T(384)) * t5 * (t5 * t21 * ap_ap + T(8) * t5 * t16 - T(2) * t5 * ab_ap * t22) * in.w[3];
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 33 +, 66 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 846 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    F = (T(1) / T(35)) * in.w[0] * t3 * (T(5) * t7 * t4 * ab_ap + T(5) * a_minus_b * t11 * t8 + T(2) * (T(4) * (t5 * t4 * ab_ap + T(2) * t3 * ab_ab * (a_minus_b * t8 + t4 * ab_ap) + a_minus_b * t9 * t8) * t3 * ab_ab + T(3) * a_minus_b * t10 * t8 + T(3) * t6 * t4 * ab_ap) * t3 * ab_ab);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 40 +, 94 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1548 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = t9 * t5;
    const T t11 = t8 * t7;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(8) * ab_ab * t3 * (T(2) * (T(4) * ab_ab * t3 * (ab_ap * t4 * t5 + t6 * a_minus_b * t7 + T(2) * ab_ab * t3 * (t6 * a_minus_b + ab_ap * t4)) + T(3) * t6 * a_minus_b * t8 + T(3) * ab_ap * t4 * t9) * ab_ab * t3 + T(5) * ab_ap * t4 * t10 + T(5) * t6 * a_minus_b * t11) + T(35) * t6 * a_minus_b * t12 + T(35) * ab_ap * t4 * t13;
    G_ap = (T(1) / T(315)) * in.w[0] * t3 * t14;
    G_ab = (T(1) / T(315)) * in.w[0] * (t3 * ab_ap * t14 + T(35) * t4 * t13 - T(35) * t6 * t12) / ab_ab;
  }
  const T g_factor = -T(9) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 40 +, 98 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1572 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t7 * t4 * ab_ap + T(5) * a_minus_b * t8 * t11 + T(2) * (T(3) * t6 * t4 * ab_ap + T(3) * a_minus_b * t8 * t10 + T(4) * (t5 * t4 * ab_ap + a_minus_b * t8 * t9 + T(2) * (t4 * ab_ap + a_minus_b * t8) * t3 * ab_ab) * t3 * ab_ab) * t3 * ab_ab;
    F = (T(1) / T(35)) * in.w[0] * t3 * t12;
    const T t13 = t6 * t6;
    const T t14 = t10 * t10;
    const T t15 = T(8) * t3 * ab_ab * t12 + T(35) * t13 * t4 * ab_ap + T(35) * a_minus_b * t8 * t14;
    G_ap = (T(1) / T(315)) * t15 * in.w[0] * t3;
    G_ab = (T(1) / T(315)) * (T(35) * t13 * t4 + t15 * t3 * ab_ap - T(35) * t8 * t14) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Returns false where segment_inverse_i9_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 40 +, 98 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i9_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t4 * ab_ap * t7 + T(2) * t3 * ab_ab * (T(3) * t8 * t10 * a_minus_b + T(3) * t4 * ab_ap * t6 + T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (t8 * a_minus_b + t4 * ab_ap) + t8 * t9 * a_minus_b + t4 * ab_ap * t5)) + T(5) * t8 * t11 * a_minus_b;
    F = (T(1) / T(35)) * in.w[0] * t3 * t12;
    const T t13 = t10 * t10;
    const T t14 = t6 * t6;
    const T t15 = T(35) * t8 * t13 * a_minus_b + T(8) * t3 * ab_ab * t12 + T(35) * t4 * ab_ap * t14;
    G_ap = (T(1) / T(315)) * in.w[0] * t3 * t15;
    G_ab = (T(1) / T(315)) * in.w[0] * (T(35) * t4 * t14 + t3 * t15 * ab_ap - T(35) * t8 * t13) / ab_ab;
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 36 +, 74 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1536 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t6 * t3 * ab_ap + T(5) * a_minus_b * t11 * t8 + T(2) * t7 * ab_ab * (T(4) * t7 * ab_ab * (t4 * t3 * ab_ap + a_minus_b * t9 * t8 + T(2) * t7 * ab_ab * (a_minus_b * t8 + t3 * ab_ap)) + T(3) * a_minus_b * t10 * t8 + T(3) * t5 * t3 * ab_ap);
    F = (T(1) / T(35)) * in.w[1] * (T(5) * t6 * t3 + t7 * t12 * ab_ap - T(5) * t11 * t8) / ab_ab + (T(1) / T(35)) * t7 * t12 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 44 +, 108 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2241 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t6 * t5;
    const T t11 = t9 * t8;
    const T t12 = T(2) * t3 * ab_ab * (T(3) * t4 * a_minus_b * t6 + T(3) * ab_ap * t7 * t9 + T(4) * t3 * (T(2) * t3 * ab_ab * (t4 * a_minus_b + ab_ap * t7) + ab_ap * t7 * t8 + t4 * a_minus_b * t5) * ab_ab) + T(5) * t4 * a_minus_b * t10 + T(5) * ab_ap * t7 * t11;
    const T t13 = t9 * t9;
    const T t14 = t6 * t6;
    const T t15 = T(8) * t3 * ab_ab * t12 + T(35) * ab_ap * t7 * t13 + T(35) * t4 * a_minus_b * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(35) * t4 * t14 - t3 * t15 * ab_ap - T(35) * t7 * t13;
    G_ap = (T(1) / T(315)) * t3 * t15 * in.w[0] - (T(1) / T(315)) * in.w[1] * t16 * t17;
    G_ab = (T(1) / T(315)) * in.w[1] * (T(9) * t3 * t12 - t3 * t15 * ap_ap - T(2) * t16 * t17 * ab_ap) * t16 - (T(1) / T(315)) * t16 * t17 * in.w[0];
  }
  const T g_factor = -T(9) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 47 +, 121 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2279 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * t4;
    const T t7 = t5 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = T(2) * t3 * ab_ab * (T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (t4 * ab_ap + t5 * a_minus_b) + t6 * t4 * ab_ap + t5 * t7 * a_minus_b) + T(3) * t5 * t8 * a_minus_b + T(3) * t9 * t4 * ab_ap) + T(5) * t10 * t4 * ab_ap + T(5) * t5 * t11 * a_minus_b;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(35)) * t3 * t12 * in.w[0] - (T(1) / T(35)) * in.w[1] * (T(5) * t5 * t11 - T(5) * t10 * t4 - t3 * t12 * ab_ap) * t13;
    const T t14 = t8 * t8;
    const T t15 = t9 * t9;
    const T t16 = T(35) * t5 * t14 * a_minus_b + T(8) * t3 * ab_ab * t12 + T(35) * t15 * t4 * ab_ap;
    const T t17 = t3 * t16 * ab_ap + T(35) * t15 * t4 - T(35) * t5 * t14;
    G_ap = (T(1) / T(315)) * in.w[1] * t13 * t17 + (T(1) / T(315)) * t3 * t16 * in.w[0];
    G_ab = (T(1) / T(315)) * in.w[1] * t13 * (T(9) * t3 * t12 + T(2) * t13 * t17 * ab_ap - ap_ap * t3 * t16) + (T(1) / T(315)) * t13 * t17 * in.w[0];
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Returns false where segment_inverse_i9_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 47 +, 121 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i9_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(5) * ab_ap * t6 * t3 + T(5) * a_minus_b * t7 * t10 + T(2) * t11 * (T(3) * ab_ap * t5 * t3 + T(3) * a_minus_b * t7 * t9 + T(4) * (T(2) * t11 * ab_ab * (a_minus_b * t7 + ab_ap * t3) + a_minus_b * t7 * t8 + ab_ap * t4 * t3) * t11 * ab_ab) * ab_ab;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(35)) * (T(5) * t6 * t3 + ab_ap * t12 * t11 - T(5) * t7 * t10) * in.w[1] * t13 + (T(1) / T(35)) * in.w[0] * t12 * t11;
    const T t14 = t5 * t5;
    const T t15 = t9 * t9;
    const T t16 = T(35) * ab_ap * t14 * t3 + T(8) * t12 * t11 * ab_ab + T(35) * a_minus_b * t7 * t15;
    const T t17 = T(35) * t7 * t15 - ab_ap * t16 * t11 - T(35) * t14 * t3;
    G_ap = (T(1) / T(315)) * in.w[0] * t16 * t11 - (T(1) / T(315)) * in.w[1] * t13 * t17;
    G_ab = -(T(1) / T(315)) * in.w[0] * t13 * t17 - (T(1) / T(315)) * (T(2) * ab_ap * t13 * t17 + ap_ap * t16 * t11 - T(9) * t12 * t11) * in.w[1] * t13;
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 39 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2228 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(3) * t5 * t3 * a_minus_b + T(4) * (T(2) * (t7 * ab_ap + t3 * a_minus_b) * t11 * ab_ab + t7 * ab_ap * t8 + t4 * t3 * a_minus_b) * t11 * ab_ab + T(3) * t7 * ab_ap * t9;
    const T t13 = T(5) * t6 * t3 * a_minus_b + T(5) * t7 * ab_ap * t10 + T(2) * t12 * t11 * ab_ab;
    const T t14 = T(5) * t6 * t3 - T(5) * t7 * t10 - t13 * ab_ap * t11;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(35)) * t13 * in.w[0] * t11 + (T(1) / T(105)) * (T(7) * t12 * t11 - T(6) * ab_ap * t14 * t15 - T(3) * t13 * ap_ap * t11) * in.w[2] * t15 - (T(1) / T(35)) * in.w[1] * t14 * t15;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 50 +, 127 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2936 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t5 * t4;
    const T t12 = t10 * t9;
    const T t13 = T(2) * t7 * ab_ab * (T(3) * t3 * t5 * ab_ap + T(4) * t7 * ab_ab * (T(2) * (t3 * ab_ap + t8 * a_minus_b) * t7 * ab_ab + t8 * a_minus_b * t9 + t3 * t4 * ab_ap) + T(3) * t8 * a_minus_b * t10) + T(5) * t3 * t11 * ab_ap + T(5) * t8 * a_minus_b * t12;
    const T t14 = t10 * t10;
    const T t15 = T(35) * t3 * t6 * ab_ap + T(8) * t13 * t7 * ab_ab + T(35) * t8 * a_minus_b * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = t15 * t7 * ab_ap + T(35) * t3 * t6 - T(35) * t8 * t14;
    const T t18 = T(2) * t16 * t17 * ab_ap + T(9) * t13 * t7 - t15 * ap_ap * t7;
    G_ap = (T(1) / T(315)) * t15 * t7 * in.w[0] + (T(1) / T(315)) * in.w[1] * t16 * t17 + (T(1) / T(315)) * in.w[2] * t18 * t16;
    G_ab = (T(1) / T(315)) * in.w[1] * t18 * t16 + (T(1) / T(315)) * t16 * t17 * in.w[0] - (T(1) / T(315)) * in.w[2] * (ap_ap * t16 * t17 - T(9) * t16 * (t13 * t7 * ab_ap + T(5) * t3 * t11 - T(5) * t8 * t12) - T(2) * t18 * t16 * ab_ap) * t16;
  }
  const T g_factor = -T(9) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 54 +, 145 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2990 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = M_flat[5] * in.w[0] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
    G_ab = in.w[2] * M_beyond[7] + in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(3) * a_minus_b * t10 * t8 + T(4) * t7 * ab_ab * (a_minus_b * t9 * t8 + ab_ap * t4 * t3 + T(2) * (a_minus_b * t8 + ab_ap * t3) * t7 * ab_ab) + T(3) * ab_ap * t5 * t3;
    const T t12 = t10 * t9;
    const T t13 = T(2) * t7 * t11 * ab_ab + T(5) * ab_ap * t6 * t3 + T(5) * a_minus_b * t12 * t8;
    const T t14 = T(5) * t6 * t3 + ab_ap * t13 * t7 - T(5) * t12 * t8;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(35)) * in.w[1] * t14 * t15 + (T(1) / T(105)) * (T(6) * ab_ap * t14 * t15 + T(7) * t7 * t11 - T(3) * t13 * ap_ap * t7) * in.w[2] * t15 + (T(1) / T(35)) * t13 * t7 * in.w[0];
    const T t16 = t10 * t10;
    const T t17 = t5 * t5;
    const T t18 = T(8) * t13 * t7 * ab_ab + T(35) * a_minus_b * t16 * t8 + T(35) * ab_ap * t17 * t3;
    const T t19 = T(35) * t16 * t8 - T(35) * t17 * t3 - ab_ap * t18 * t7;
    const T t20 = T(2) * ab_ap * t19 * t15 + ap_ap * t18 * t7 - T(9) * t13 * t7;
    G_ap = (T(1) / T(315)) * t18 * t7 * in.w[0] - (T(1) / T(315)) * in.w[2] * t20 * t15 - (T(1) / T(315)) * in.w[1] * t19 * t15;
    G_ab = (T(1) / T(315)) * in.w[2] * (T(9) * t14 * t15 + ap_ap * t19 * t15 - T(2) * ab_ap * t20 * t15) * t15 - (T(1) / T(315)) * t19 * t15 * in.w[0] - (T(1) / T(315)) * in.w[1] * t20 * t15;
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Returns false where segment_inverse_i9_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 54 +, 145 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i9_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * ab_ap * t6 * t4 + T(3) * a_minus_b * t7 * t9 + T(4) * (a_minus_b * t7 * t8 + ab_ap * t5 * t4 + T(2) * (ab_ap * t4 + a_minus_b * t7) * t3 * ab_ab) * t3 * ab_ab;
    const T t11 = t6 * t5;
    const T t12 = t9 * t8;
    const T t13 = T(2) * t3 * ab_ab * t10 + T(5) * ab_ap * t11 * t4 + T(5) * a_minus_b * t7 * t12;
    const T t14 = T(5) * t7 * t12 - T(5) * t11 * t4 - ab_ap * t3 * t13;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(35)) * t3 * t13 * in.w[0] + (T(1) / T(105)) * (T(7) * t3 * t10 - T(3) * ap_ap * t3 * t13 - T(6) * ab_ap * t14 * t15) * in.w[2] * t15 - (T(1) / T(35)) * t14 * in.w[1] * t15;
    const T t16 = t9 * t9;
    const T t17 = t6 * t6;
    const T t18 = T(35) * a_minus_b * t7 * t16 + T(8) * t3 * ab_ab * t13 + T(35) * ab_ap * t17 * t4;
    const T t19 = ab_ap * t18 * t3 + T(35) * t17 * t4 - T(35) * t7 * t16;
    const T t20 = T(9) * t3 * t13 + T(2) * ab_ap * t19 * t15 - t18 * ap_ap * t3;
    G_ap = (T(1) / T(315)) * in.w[2] * t15 * t20 + (T(1) / T(315)) * in.w[1] * t19 * t15 + (T(1) / T(315)) * t18 * t3 * in.w[0];
    G_ab = (T(1) / T(315)) * in.w[1] * t15 * t20 + (T(1) / T(315)) * t19 * t15 * in.w[0] - (T(1) / T(315)) * in.w[2] * t15 * (ap_ap * t19 * t15 + T(9) * t14 * t15 - T(2) * ab_ap * t15 * t20);
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 44 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2922 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * t4;
    const T t7 = t5 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(4) * (T(2) * (t4 * ab_ap + t5 * a_minus_b) * t3 * ab_ab + t4 * ab_ap * t6 + t7 * t5 * a_minus_b) * t3 * ab_ab + T(3) * t8 * t5 * a_minus_b + T(3) * t4 * ab_ap * t9;
    const T t11 = t9 * t6;
    const T t12 = t8 * t7;
    const T t13 = T(2) * t3 * ab_ab * t10 + T(5) * t4 * ab_ap * t11 + T(5) * t12 * t5 * a_minus_b;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(5) * t12 * t5 - T(5) * t4 * t11 - ab_ap * t3 * t13;
    const T t16 = T(3) * ap_ap * t3 * t13 + T(6) * t15 * ab_ap * t14 - T(7) * t3 * t10;
    F = (T(1) / T(35)) * t3 * in.w[0] * t13 + (T(1) / T(105)) * (T(7) * t14 * (T(3) * t4 * t9 + ab_ap * t3 * t10 - T(3) * t8 * t5) + T(3) * t15 * ap_ap * t14 - T(2) * ab_ap * t16 * t14) * in.w[3] * t14 - (T(1) / T(35)) * in.w[1] * t15 * t14 - (T(1) / T(105)) * t16 * in.w[2] * t14;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 56 +, 148 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3633 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ab = in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + M_beyond[4] * in.w[3] + M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(3) * ab_ap * t4 * t6 + T(3) * t7 * a_minus_b * t9 + T(4) * (t7 * a_minus_b * t8 + ab_ap * t4 * t5 + T(2) * (t7 * a_minus_b + ab_ap * t4) * t10 * ab_ab) * t10 * ab_ab;
    const T t12 = t6 * t5;
    const T t13 = t9 * t8;
    const T t14 = T(2) * t11 * t10 * ab_ab + T(5) * ab_ap * t4 * t12 + T(5) * t7 * a_minus_b * t13;
    const T t15 = t6 * t6;
    const T t16 = t9 * t9;
    const T t17 = T(35) * ab_ap * t4 * t15 + T(8) * t14 * t10 * ab_ab + T(35) * t7 * a_minus_b * t16;
    const T t18 = ab_ap * t17 * t10 + T(35) * t4 * t15 - T(35) * t7 * t16;
    const T t19 = T(9) * t14 * t10 + T(2) * ab_ap * t3 * t18 - t17 * ap_ap * t10;
    const T t20 = T(5) * t4 * t12 + ab_ap * t14 * t10 - T(5) * t7 * t13;
    const T t21 = ap_ap * t3 * t18 - T(2) * ab_ap * t3 * t19 - T(9) * t20 * t3;
    G_ap = (T(1) / T(315)) * in.w[2] * t3 * t19 + (T(1) / T(315)) * t3 * t18 * in.w[1] + (T(1) / T(315)) * t17 * t10 * in.w[0] - (T(1) / T(315)) * in.w[3] * t3 * t21;
    G_ab = (T(1) / T(315)) * in.w[0] * t3 * t18 + (T(1) / T(315)) * t3 * t19 * in.w[1] - (T(1) / T(315)) * in.w[3] * t3 * (ap_ap * t3 * t19 + T(2) * ab_ap * t3 * t21 - T(3) * t3 * (T(7) * t11 * t10 + T(6) * ab_ap * t20 * t3 - T(3) * ap_ap * t14 * t10)) - (T(1) / T(315)) * in.w[2] * t3 * t21;
  }
  const T g_factor = -T(9) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 63 +, 175 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1337 +, 3705 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i9_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0];
    G_ap = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + in.w[1] * M_flat[7] + in.w[3] * M_flat[9];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0];
    G_ab = in.w[3] * M_beyond[9] + in.w[2] * M_beyond[8] + in.w[0] * M_beyond[6] + M_beyond[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(3) * t5 * t3 * ab_ap + T(4) * (a_minus_b * t7 * t8 + T(2) * (t3 * ab_ap + a_minus_b * t7) * t11 * ab_ab + t4 * t3 * ab_ap) * t11 * ab_ab + T(3) * a_minus_b * t7 * t9;
    const T t13 = T(5) * t6 * t3 * ab_ap + T(5) * a_minus_b * t7 * t10 + T(2) * t11 * ab_ab * t12;
    const T t14 = t13 * t11 * ab_ap + T(5) * t6 * t3 - T(5) * t7 * t10;
    const T t15 = T(1) / ab_ab;
    const T t16 = T(7) * t11 * t12 + T(6) * t14 * t15 * ab_ap - T(3) * ap_ap * t13 * t11;
    F = (T(1) / T(35)) * t14 * t15 * in.w[1] + (T(1) / T(35)) * t13 * in.w[0] * t11 + (T(1) / T(105)) * in.w[2] * t16 * t15 - (T(1) / T(105)) * in.w[3] * t15 * (T(3) * t14 * ap_ap * t15 - T(2) * t16 * t15 * ab_ap - T(7) * (t11 * t12 * ab_ap + T(3) * t5 * t3 - T(3) * t7 * t9) * t15);
    const T t17 = t5 * t5;
    const T t18 = t9 * t9;
    const T t19 = T(35) * t17 * t3 * ab_ap + T(35) * a_minus_b * t7 * t18 + T(8) * t13 * t11 * ab_ab;
    const T t20 = T(35) * t17 * t3 + t11 * ab_ap * t19 - T(35) * t7 * t18;
    const T t21 = T(9) * t13 * t11 + T(2) * t15 * t20 * ab_ap - ap_ap * t11 * t19;
    const T t22 = ap_ap * t15 * t20 - T(2) * t21 * t15 * ab_ap - T(9) * t14 * t15;
    G_ap = (T(1) / T(315)) * in.w[0] * t11 * t19 + (T(1) / T(315)) * t15 * t20 * in.w[1] + (T(1) / T(315)) * t21 * in.w[2] * t15 - (T(1) / T(315)) * t22 * in.w[3] * t15;
    G_ab = (T(1) / T(315)) * in.w[0] * t15 * t20 + (T(1) / T(315)) * t21 * t15 * in.w[1] - (T(1) / T(315)) * (T(2) * t22 * t15 * ab_ap + t21 * ap_ap * t15 - T(3) * t16 * t15) * in.w[3] * t15 - (T(1) / T(315)) * t22 * in.w[2] * t15;
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Returns false where segment_inverse_i9_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 175 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i9_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1];
    G_ab = M_flat[9] * in.w[3] + M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(4) * t8 * ab_ab * (ab_ap * t5 * t4 + t9 * t10 * a_minus_b + T(2) * t8 * ab_ab * (t9 * a_minus_b + ab_ap * t4)) + T(3) * t9 * t11 * a_minus_b + T(3) * ab_ap * t6 * t4;
    const T t13 = t11 * t10;
    const T t14 = T(2) * t8 * ab_ab * t12 + T(5) * ab_ap * t7 * t4 + T(5) * t9 * t13 * a_minus_b;
    const T t15 = T(5) * t7 * t4 + t14 * t8 * ab_ap - T(5) * t9 * t13;
    const T t16 = T(3) * t14 * t8 * ap_ap - T(7) * t8 * t12 - T(6) * t3 * ab_ap * t15;
    F = (T(1) / T(35)) * t3 * in.w[1] * t15 + (T(1) / T(35)) * t14 * t8 * in.w[0] - (T(1) / T(105)) * t3 * in.w[2] * t16 - (T(1) / T(105)) * t3 * (T(2) * t3 * ab_ap * t16 + T(3) * t3 * t15 * ap_ap - T(7) * t3 * (t8 * ab_ap * t12 + T(3) * t6 * t4 - T(3) * t9 * t11)) * in.w[3];
    const T t17 = t11 * t11;
    const T t18 = t6 * t6;
    const T t19 = T(35) * t9 * t17 * a_minus_b + T(35) * ab_ap * t18 * t4 + T(8) * t14 * t8 * ab_ab;
    const T t20 = T(35) * t9 * t17 - t8 * t19 * ab_ap - T(35) * t18 * t4;
    const T t21 = T(2) * t3 * t20 * ab_ap + t8 * t19 * ap_ap - T(9) * t14 * t8;
    const T t22 = T(9) * t3 * t15 + t3 * t20 * ap_ap - T(2) * t21 * t3 * ab_ap;
    G_ap = (T(1) / T(315)) * t8 * in.w[0] * t19 + (T(1) / T(315)) * t3 * t22 * in.w[3] - (T(1) / T(315)) * t21 * t3 * in.w[2] - (T(1) / T(315)) * t3 * t20 * in.w[1];
    G_ab = (T(1) / T(315)) * (T(2) * t3 * ab_ap * t22 + t21 * t3 * ap_ap - T(3) * t3 * t16) * t3 * in.w[3] + (T(1) / T(315)) * t3 * in.w[2] * t22 - (T(1) / T(315)) * t21 * t3 * in.w[1] - (T(1) / T(315)) * in.w[0] * t3 * t20;
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 36 +, 67 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 851 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / cross_cross;
    const T t12 = t9 * t8;
    const T t13 = t6 * t5;
    F = (T(1) / T(384)) * (T(48) * t7 * ab_ap + T(48) * a_minus_b * t10 + T(7) * t11 * (T(8) * a_minus_b * t12 + T(5) * t11 * ab_ab * (T(2) * a_minus_b * t9 + T(2) * t6 * ab_ap + T(3) * t11 * ab_ab * (t5 * ab_ap + a_minus_b * t8 + J2 * ab_ab)) + T(8) * t13 * ab_ap) * ab_ab) * in.w[0] * t11;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 43 +, 91 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1553 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = t12 * t9;
    const T t15 = t13 * t6;
    const T t16 = T(3) * t5 * ab_ab * (T(7) * t5 * (T(8) * t8 * ab_ap + T(5) * t5 * ab_ab * (T(2) * t7 * ab_ap + T(2) * a_minus_b * t10 + T(3) * t5 * ab_ab * (ab_ab * J2 + a_minus_b * t9 + t6 * ab_ap)) + T(8) * a_minus_b * t11) * ab_ab + T(48) * a_minus_b * t12 + T(48) * t13 * ab_ap) + T(128) * a_minus_b * t14 + T(128) * t15 * ab_ap;
    G_ap = (T(1) / T(1280)) * in.w[0] * t5 * t16;
    G_ab = (T(1) / T(1280)) * (T(128) * t15 + t5 * t16 * ab_ap - T(128) * t14) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(10) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 43 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1578 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t7 * t7;
    const T t13 = t10 * t10;
    const T t14 = T(7) * t5 * ab_ab * (T(8) * t8 * ab_ap + T(8) * a_minus_b * t11 + T(5) * t5 * (T(3) * (a_minus_b * t9 + t6 * ab_ap + ab_ab * J2) * t5 * ab_ab + T(2) * t7 * ab_ap + T(2) * a_minus_b * t10) * ab_ab) + T(48) * t12 * ab_ap + T(48) * a_minus_b * t13;
    F = (T(1) / T(384)) * in.w[0] * t5 * t14;
    const T t15 = t12 * t6;
    const T t16 = t13 * t9;
    const T t17 = T(3) * t5 * ab_ab * t14 + T(128) * t15 * ab_ap + T(128) * a_minus_b * t16;
    G_ap = (T(1) / T(1280)) * in.w[0] * t5 * t17;
    G_ab = (T(1) / T(1280)) * (T(128) * t15 + t5 * ab_ap * t17 - T(128) * t16) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Returns false where segment_inverse_i10_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i10_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = T(7) * (T(8) * t8 * a_minus_b + T(5) * (T(2) * t7 * a_minus_b + T(2) * t10 * ab_ap + T(3) * (ab_ab * J2 + t9 * ab_ap + t6 * a_minus_b) * t5 * ab_ab) * t5 * ab_ab + T(8) * t11 * ab_ap) * t5 * ab_ab + T(48) * t12 * ab_ap + T(48) * t13 * a_minus_b;
    F = (T(1) / T(384)) * in.w[0] * t5 * t14;
    const T t15 = t12 * t9;
    const T t16 = t13 * t6;
    const T t17 = T(128) * t15 * ab_ap + T(3) * t5 * t14 * ab_ab + T(128) * t16 * a_minus_b;
    G_ap = (T(1) / T(1280)) * t17 * in.w[0] * t5;
    G_ab = (T(1) / T(1280)) * in.w[0] * (T(128) * t15 + t17 * t5 * ab_ap - T(128) * t16) / ab_ab;
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 39 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1541 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = t6 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = T(7) * (T(8) * t9 * ab_ap + T(8) * a_minus_b * t12 + T(5) * t8 * ab_ab * (T(2) * t6 * ab_ap + T(3) * t8 * ab_ab * (a_minus_b * t10 + J2 * ab_ab + t5 * ab_ap) + T(2) * a_minus_b * t11)) * t8 * ab_ab + T(48) * t7 * ab_ap + T(48) * a_minus_b * t13;
    F = (T(1) / T(384)) * in.w[1] * (T(48) * t7 + t8 * t14 * ab_ap - T(48) * t13) / ab_ab + (T(1) / T(384)) * t8 * t14 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 47 +, 106 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2246 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t7 * t6;
    const T t13 = t10 * t10;
    const T t14 = T(48) * a_minus_b * t8 + T(7) * ab_ab * t5 * (T(8) * ab_ap * t11 + T(8) * a_minus_b * t12 + T(5) * ab_ab * t5 * (T(2) * a_minus_b * t7 + T(2) * ab_ap * t10 + T(3) * ab_ab * t5 * (ab_ab * J2 + ab_ap * t9 + a_minus_b * t6))) + T(48) * ab_ap * t13;
    const T t15 = t8 * t6;
    const T t16 = t13 * t9;
    const T t17 = T(3) * ab_ab * t5 * t14 + T(128) * a_minus_b * t15 + T(128) * ab_ap * t16;
    const T t18 = T(128) * t15 - t5 * ab_ap * t17 - T(128) * t16;
    const T t19 = T(1) / ab_ab;
    G_ap = (T(1) / T(1280)) * t5 * t17 * in.w[0] - (T(1) / T(1280)) * in.w[1] * t18 * t19;
    G_ab = -(T(1) / T(1280)) * t18 * t19 * in.w[0] - (T(1) / T(3840)) * in.w[1] * t19 * (T(3) * t5 * t17 * ap_ap + T(6) * t18 * t19 * ab_ap - T(10) * t5 * t14);
  }
  const T g_factor = -T(10) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 50 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2285 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[3] * in.w[0] + in.w[1] * M_beyond[4];
    G_ab = in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t7 * t6;
    const T t14 = t11 * t10;
    const T t15 = T(48) * t12 * a_minus_b + T(48) * t8 * ab_ap + T(7) * t9 * (T(8) * t13 * ab_ap + T(5) * t9 * ab_ab * (T(2) * t7 * ab_ap + T(3) * t9 * (t10 * a_minus_b + ab_ab * J2 + t6 * ab_ap) * ab_ab + T(2) * t11 * a_minus_b) + T(8) * t14 * a_minus_b) * ab_ab;
    F = (T(1) / T(384)) * in.w[1] * t5 * (T(48) * t8 + t9 * t15 * ab_ap - T(48) * t12) + (T(1) / T(384)) * t9 * t15 * in.w[0];
    const T t16 = t8 * t6;
    const T t17 = t12 * t10;
    const T t18 = T(128) * t17 * a_minus_b + T(128) * t16 * ab_ap + T(3) * t9 * ab_ab * t15;
    const T t19 = T(128) * t16 + t18 * t9 * ab_ap - T(128) * t17;
    G_ap = (T(1) / T(1280)) * in.w[1] * t5 * t19 + (T(1) / T(1280)) * t18 * t9 * in.w[0];
    G_ab = (T(1) / T(3840)) * in.w[1] * t5 * (T(6) * t5 * t19 * ab_ap + T(10) * t9 * t15 - T(3) * ap_ap * t18 * t9) + (T(1) / T(1280)) * t5 * t19 * in.w[0];
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Returns false where segment_inverse_i10_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 50 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i10_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = t6 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = T(48) * t7 * ab_ap + T(7) * t8 * ab_ab * (T(8) * t9 * ab_ap + T(5) * (T(3) * (t5 * ab_ap + a_minus_b * t10 + ab_ab * J2) * t8 * ab_ab + T(2) * t6 * ab_ap + T(2) * a_minus_b * t11) * t8 * ab_ab + T(8) * a_minus_b * t12) + T(48) * a_minus_b * t13;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(384)) * (T(48) * t7 + t8 * t14 * ab_ap - T(48) * t13) * in.w[1] * t15 + (T(1) / T(384)) * in.w[0] * t8 * t14;
    const T t16 = t7 * t5;
    const T t17 = t13 * t10;
    const T t18 = T(128) * t16 * ab_ap + T(128) * a_minus_b * t17 + T(3) * t8 * ab_ab * t14;
    const T t19 = T(128) * t16 + t18 * t8 * ab_ap - T(128) * t17;
    G_ap = (T(1) / T(1280)) * in.w[1] * t15 * t19 + (T(1) / T(1280)) * in.w[0] * t18 * t8;
    G_ab = (T(1) / T(1280)) * in.w[0] * t15 * t19 + (T(1) / T(3840)) * in.w[1] * t15 * (T(10) * t8 * t14 + T(6) * t15 * t19 * ab_ap - T(3) * ap_ap * t18 * t8);
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 42 +, 84 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2233 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t7 * t6;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * ab_ap * t9 + T(5) * (T(2) * ab_ap * t7 + T(2) * a_minus_b * t11 + T(3) * t5 * ab_ab * (a_minus_b * t10 + ab_ap * t6 + J2 * ab_ab)) * t5 * ab_ab + T(8) * a_minus_b * t12;
    const T t14 = t11 * t11;
    const T t15 = T(48) * ab_ap * t8 + T(7) * t13 * t5 * ab_ab + T(48) * a_minus_b * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(48) * t14 - t5 * t15 * ab_ap - T(48) * t8;
    F = (T(1) / T(384)) * t5 * t15 * in.w[0] - (T(1) / T(384)) * t16 * t17 * in.w[1] - (T(1) / T(384)) * in.w[2] * t16 * (T(2) * t16 * ab_ap * t17 + t5 * t15 * ap_ap - T(8) * t13 * t5);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 53 +, 124 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2941 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t7 * t6;
    const T t16 = T(48) * ab_ap * t8 + T(7) * t5 * ab_ab * (T(8) * a_minus_b * t14 + T(8) * ab_ap * t15 + T(5) * t5 * ab_ab * (T(2) * a_minus_b * t11 + T(3) * t5 * ab_ab * (ab_ap * t6 + a_minus_b * t10 + ab_ab * J2) + T(2) * ab_ap * t7)) + T(48) * a_minus_b * t12;
    const T t17 = T(128) * ab_ap * t9 + T(128) * a_minus_b * t13 + T(3) * t5 * ab_ab * t16;
    const T t18 = T(1) / ab_ab;
    const T t19 = t5 * ab_ap * t17 + T(128) * t9 - T(128) * t13;
    const T t20 = T(10) * t5 * t16 + T(6) * t18 * t19 * ab_ap - T(3) * t5 * t17 * ap_ap;
    G_ap = (T(1) / T(1280)) * t5 * in.w[0] * t17 + (T(1) / T(3840)) * t18 * t20 * in.w[2] + (T(1) / T(1280)) * t18 * t19 * in.w[1];
    G_ab = (T(1) / T(3840)) * t18 * in.w[1] * t20 + (T(1) / T(1280)) * t18 * in.w[0] * t19 - (T(1) / T(3840)) * (T(3) * t18 * t19 * ap_ap - T(2) * t18 * ab_ap * t20 - T(10) * t18 * (T(48) * t8 + t5 * t16 * ab_ap - T(48) * t12)) * t18 * in.w[2];
  }
  const T g_factor = -T(10) * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 57 +, 141 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 2996 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[4] * in.w[0] + M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5];
    G_ab = M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t7 * t6;
    const T t11 = t9 * t8;
    const T t12 = T(5) * t5 * ab_ab * (T(2) * t7 * a_minus_b + T(3) * (J2 * ab_ab + ab_ap * t8 + t6 * a_minus_b) * t5 * ab_ab + T(2) * ab_ap * t9) + T(8) * t10 * a_minus_b + T(8) * ab_ap * t11;
    const T t13 = t7 * t7;
    const T t14 = t9 * t9;
    const T t15 = T(7) * t12 * t5 * ab_ab + T(48) * t13 * a_minus_b + T(48) * ab_ap * t14;
    const T t16 = T(48) * t13 - t15 * ab_ap * t5 - T(48) * t14;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(384)) * t15 * t5 * in.w[0] - (T(1) / T(384)) * in.w[1] * t16 * t17 - (T(1) / T(384)) * (t15 * ap_ap * t5 + T(2) * ab_ap * t16 * t17 - T(8) * t12 * t5) * in.w[2] * t17;
    const T t18 = t13 * t6;
    const T t19 = t14 * t8;
    const T t20 = T(128) * t18 * a_minus_b + T(3) * t15 * t5 * ab_ab + T(128) * ab_ap * t19;
    const T t21 = T(128) * t18 - T(128) * t19 - ab_ap * t20 * t5;
    const T t22 = T(3) * t20 * ap_ap * t5 + T(6) * ab_ap * t21 * t17 - T(10) * t15 * t5;
    G_ap = (T(1) / T(1280)) * t20 * t5 * in.w[0] - (T(1) / T(1280)) * t21 * in.w[1] * t17 - (T(1) / T(3840)) * t22 * in.w[2] * t17;
    G_ab = -(T(1) / T(1280)) * t21 * t17 * in.w[0] - (T(1) / T(3840)) * in.w[1] * t22 * t17 - (T(1) / T(3840)) * (T(2) * ab_ap * t22 * t17 + T(10) * t16 * t17 - T(3) * t21 * ap_ap * t17) * in.w[2] * t17;
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Returns false where segment_inverse_i10_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 57 +, 141 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i10_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = t6 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * t9 * ab_ap + T(5) * (T(3) * t8 * ab_ab * (a_minus_b * t10 + t5 * ab_ap + ab_ab * J2) + T(2) * t6 * ab_ap + T(2) * a_minus_b * t11) * t8 * ab_ab + T(8) * a_minus_b * t12;
    const T t14 = t11 * t11;
    const T t15 = T(7) * t13 * t8 * ab_ab + T(48) * a_minus_b * t14 + T(48) * t7 * ab_ap;
    const T t16 = T(48) * t7 + t8 * t15 * ab_ap - T(48) * t14;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(384)) * in.w[1] * t16 * t17 + (T(1) / T(384)) * (T(2) * t16 * t17 * ab_ap + T(8) * t13 * t8 - ap_ap * t8 * t15) * in.w[2] * t17 + (T(1) / T(384)) * t8 * t15 * in.w[0];
    const T t18 = t14 * t10;
    const T t19 = t7 * t5;
    const T t20 = T(3) * t8 * ab_ab * t15 + T(128) * a_minus_b * t18 + T(128) * t19 * ab_ap;
    const T t21 = t20 * t8 * ab_ap + T(128) * t19 - T(128) * t18;
    const T t22 = T(3) * t20 * ap_ap * t8 - T(10) * t8 * t15 - T(6) * t21 * t17 * ab_ap;
    G_ap = (T(1) / T(1280)) * t20 * t8 * in.w[0] + (T(1) / T(1280)) * t21 * in.w[1] * t17 - (T(1) / T(3840)) * t22 * in.w[2] * t17;
    G_ab = (T(1) / T(1280)) * t21 * t17 * in.w[0] - (T(1) / T(3840)) * in.w[1] * t22 * t17 - (T(1) / T(3840)) * (T(2) * t22 * t17 * ab_ap + T(3) * t21 * ap_ap * t17 - T(10) * t16 * t17) * in.w[2] * t17;
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 47 +, 98 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2927 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = T(1) / cross_cross;
    const T t13 = t9 * t8;
    const T t14 = T(8) * ab_ap * t11 + T(5) * (T(2) * ab_ap * t6 + T(3) * (t8 * a_minus_b + J2 * ab_ab + ab_ap * t5) * t12 * ab_ab + T(2) * t9 * a_minus_b) * t12 * ab_ab + T(8) * t13 * a_minus_b;
    const T t15 = T(48) * t10 * a_minus_b + T(7) * t14 * t12 * ab_ab + T(48) * ab_ap * t7;
    const T t16 = T(48) * t7 + t15 * ab_ap * t12 - T(48) * t10;
    const T t17 = T(1) / ab_ab;
    const T t18 = T(2) * ab_ap * t16 * t17 + T(8) * t14 * t12 - t15 * ap_ap * t12;
    F = (T(1) / T(384)) * in.w[1] * t16 * t17 + (T(1) / T(384)) * t18 * in.w[2] * t17 + (T(1) / T(384)) * (T(2) * ab_ap * t18 * t17 - T(8) * (T(8) * t13 - T(8) * t11 - ab_ap * t14 * t12) * t17 - t16 * ap_ap * t17) * in.w[3] * t17 + (T(1) / T(384)) * t15 * t12 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 59 +, 144 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3638 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + in.w[2] * M_flat[3] + in.w[3] * M_flat[4] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[4] * in.w[3] + in.w[2] * M_beyond[3] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t7 * t6;
    const T t15 = T(5) * t5 * ab_ab * (T(2) * a_minus_b * t11 + T(2) * t7 * ab_ap + T(3) * (t6 * ab_ap + a_minus_b * t10 + ab_ab * J2) * t5 * ab_ab) + T(8) * a_minus_b * t13 + T(8) * t14 * ab_ap;
    const T t16 = T(48) * t8 * ab_ap + T(48) * a_minus_b * t12 + T(7) * t15 * t5 * ab_ab;
    const T t17 = t12 * t10;
    const T t18 = T(128) * t9 * ab_ap + T(3) * t16 * t5 * ab_ab + T(128) * a_minus_b * t17;
    const T t19 = T(1) / ab_ab;
    const T t20 = t5 * t18 * ab_ap + T(128) * t9 - T(128) * t17;
    const T t21 = T(10) * t16 * t5 + T(6) * t19 * t20 * ab_ap - T(3) * ap_ap * t5 * t18;
    const T t22 = T(48) * t12 - T(48) * t8 - t16 * t5 * ab_ap;
    const T t23 = T(2) * t21 * t19 * ab_ap - T(10) * t22 * t19 - T(3) * ap_ap * t19 * t20;
    G_ap = (T(1) / T(1280)) * t5 * in.w[0] * t18 + (T(1) / T(3840)) * in.w[2] * t21 * t19 + (T(1) / T(1280)) * t19 * in.w[1] * t20 + (T(1) / T(3840)) * in.w[3] * t19 * t23;
    G_ab = (T(1) / T(3840)) * (T(2) * t19 * ab_ap * t23 - ap_ap * t21 * t19 - T(10) * t19 * (T(2) * t22 * t19 * ab_ap + ap_ap * t16 * t5 - T(8) * t15 * t5)) * in.w[3] * t19 + (T(1) / T(3840)) * t21 * t19 * in.w[1] + (T(1) / T(3840)) * in.w[2] * t19 * t23 + (T(1) / T(1280)) * in.w[0] * t19 * t20;
  }
  const T g_factor = -T(10) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 66 +, 168 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3711 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i10_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1];
    G_ap = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
    G_ab = in.w[2] * M_beyond[8] + in.w[3] * M_beyond[9] + M_beyond[7] * in.w[1] + in.w[0] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t7 * t6;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * a_minus_b * t9 + T(8) * ab_ap * t12 + T(5) * t5 * ab_ab * (T(3) * t5 * (J2 * ab_ab + ab_ap * t10 + a_minus_b * t6) * ab_ab + T(2) * a_minus_b * t7 + T(2) * ab_ap * t11);
    const T t14 = t11 * t11;
    const T t15 = T(48) * a_minus_b * t8 + T(7) * t13 * t5 * ab_ab + T(48) * ab_ap * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(48) * t14 + ab_ap * t5 * t15 - T(48) * t8;
    const T t18 = ap_ap * t5 * t15 - T(8) * t13 * t5 - T(2) * ab_ap * t16 * t17;
    F = (T(1) / T(384)) * t5 * in.w[0] * t15 + (T(1) / T(384)) * t16 * in.w[1] * t17 - (T(1) / T(384)) * in.w[3] * (ap_ap * t16 * t17 + T(2) * ab_ap * t16 * t18 + T(8) * t16 * (T(8) * t9 - ab_ap * t13 * t5 - T(8) * t12)) * t16 - (T(1) / T(384)) * in.w[2] * t16 * t18;
    const T t19 = t8 * t6;
    const T t20 = t14 * t10;
    const T t21 = T(128) * a_minus_b * t19 + T(3) * t5 * ab_ab * t15 + T(128) * ab_ap * t20;
    const T t22 = ab_ap * t5 * t21 + T(128) * t20 - T(128) * t19;
    const T t23 = T(10) * t5 * t15 + T(6) * ab_ap * t16 * t22 - T(3) * ap_ap * t5 * t21;
    const T t24 = T(2) * ab_ap * t23 * t16 + T(10) * t16 * t17 - T(3) * ap_ap * t16 * t22;
    G_ap = (T(1) / T(1280)) * t5 * in.w[0] * t21 + (T(1) / T(1280)) * t16 * t22 * in.w[1] + (T(1) / T(3840)) * in.w[3] * t24 * t16 + (T(1) / T(3840)) * in.w[2] * t23 * t16;
    G_ab = (T(1) / T(3840)) * in.w[2] * t24 * t16 + (T(1) / T(1280)) * in.w[0] * t16 * t22 + (T(1) / T(3840)) * t23 * t16 * in.w[1] - (T(1) / T(3840)) * in.w[3] * t16 * (ap_ap * t23 * t16 + T(10) * t16 * t18 - T(2) * ab_ap * t24 * t16);
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Returns false where segment_inverse_i10_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 66 +, 168 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i10_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[7] * in.w[2] + in.w[3] * M_flat[8] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1];
    G_ab = in.w[2] * M_flat[8] + M_flat[6] * in.w[0] + in.w[1] * M_flat[7] + in.w[3] * M_flat[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * t9 * a_minus_b + T(5) * t6 * ab_ab * (T(3) * t6 * ab_ab * (t7 * a_minus_b + ab_ap * t10 + ab_ab * J2) + T(2) * ab_ap * t11 + T(2) * t8 * a_minus_b) + T(8) * ab_ap * t12;
    const T t14 = t11 * t11;
    const T t15 = t8 * t8;
    const T t16 = T(7) * t6 * ab_ab * t13 + T(48) * t15 * a_minus_b + T(48) * ab_ap * t14;
    const T t17 = T(48) * t14 + t6 * t16 * ab_ap - T(48) * t15;
    const T t18 = T(8) * t6 * t13 + T(2) * t5 * ab_ap * t17 - t6 * t16 * ap_ap;
    F = (T(1) / T(384)) * t5 * in.w[2] * t18 + (T(1) / T(384)) * t6 * t16 * in.w[0] + (T(1) / T(384)) * t5 * in.w[1] * t17 + (T(1) / T(384)) * in.w[3] * t5 * (T(8) * t5 * (T(8) * t12 + t6 * t13 * ab_ap - T(8) * t9) + T(2) * t5 * ab_ap * t18 - t5 * ap_ap * t17);
    const T t19 = t14 * t10;
    const T t20 = t15 * t7;
    const T t21 = T(128) * t20 * a_minus_b + T(128) * ab_ap * t19 + T(3) * t6 * t16 * ab_ab;
    const T t22 = T(128) * t19 + t6 * t21 * ab_ap - T(128) * t20;
    const T t23 = T(10) * t6 * t16 + T(6) * t22 * t5 * ab_ap - T(3) * t6 * t21 * ap_ap;
    const T t24 = T(10) * t5 * t17 + T(2) * t5 * t23 * ab_ap - T(3) * t22 * t5 * ap_ap;
    G_ap = (T(1) / T(3840)) * in.w[3] * t5 * t24 + (T(1) / T(3840)) * t5 * t23 * in.w[2] + (T(1) / T(1280)) * t6 * t21 * in.w[0] + (T(1) / T(1280)) * t22 * t5 * in.w[1];
    G_ab = (T(1) / T(3840)) * t5 * t24 * in.w[2] + (T(1) / T(1280)) * t22 * t5 * in.w[0] + (T(1) / T(3840)) * t5 * t23 * in.w[1] - (T(1) / T(3840)) * in.w[3] * t5 * (t5 * t23 * ap_ap - T(10) * t5 * t18 - T(2) * t5 * t24 * ab_ap);
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 35 +, 77 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 849 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = t9 * t8;
    const T t12 = t9 * t9;
    const T t13 = t5 * t5;
    F = (T(1) / T(315)) * (T(8) * (T(5) * t6 * t3 * ab_ap + T(2) * (T(3) * t7 * a_minus_b * t9 + T(3) * t5 * t3 * ab_ap + T(4) * t10 * (t4 * t3 * ab_ap + T(2) * t10 * (t3 * ab_ap + t7 * a_minus_b) * ab_ab + t7 * a_minus_b * t8) * ab_ab) * t10 * ab_ab + T(5) * t7 * a_minus_b * t11) * t10 * ab_ab + T(35) * t7 * a_minus_b * t12 + T(35) * t13 * t3 * ab_ap) * in.w[0] * t10;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 42 +, 105 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1550 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t5 * t4;
    const T t14 = t10 * t9;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(63) * t3 * a_minus_b * t7 + T(63) * t12 * ab_ap * t8 + T(2) * (T(35) * t3 * a_minus_b * t6 + T(8) * (T(5) * t3 * a_minus_b * t13 + T(5) * t14 * ab_ap * t8 + T(2) * (T(3) * t3 * a_minus_b * t5 + T(4) * (t9 * ab_ap * t8 + T(2) * t15 * ab_ab * (ab_ap * t8 + t3 * a_minus_b) + t3 * a_minus_b * t4) * t15 * ab_ab + T(3) * t10 * ab_ap * t8) * t15 * ab_ab) * t15 * ab_ab + T(35) * t11 * ab_ap * t8) * t15 * ab_ab;
    G_ap = (T(1) / T(693)) * t16 * in.w[0] * t15;
    G_ab = -(T(1) / T(693)) * (T(63) * t3 * t7 - T(63) * t12 * t8 - t16 * t15 * ab_ap) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(11) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 42 +, 109 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1575 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t6 * t6;
    const T t14 = T(8) * t3 * ab_ab * (T(5) * t4 * t7 * a_minus_b + T(5) * ab_ap * t11 * t8 + T(2) * t3 * ab_ab * (T(3) * ab_ap * t10 * t8 + T(3) * t4 * t6 * a_minus_b + T(4) * (T(2) * t3 * ab_ab * (ab_ap * t8 + t4 * a_minus_b) + ab_ap * t9 * t8 + t4 * t5 * a_minus_b) * t3 * ab_ab)) + T(35) * ab_ap * t12 * t8 + T(35) * t4 * t13 * a_minus_b;
    F = (T(1) / T(315)) * t3 * in.w[0] * t14;
    const T t15 = t12 * t9;
    const T t16 = t13 * t5;
    const T t17 = T(2) * t3 * ab_ab * t14 + T(63) * ab_ap * t15 * t8 + T(63) * t4 * t16 * a_minus_b;
    G_ap = (T(1) / T(693)) * t3 * in.w[0] * t17;
    G_ab = (T(1) / T(693)) * in.w[0] * (t3 * ab_ap * t17 + T(63) * t15 * t8 - T(63) * t4 * t16) / ab_ab;
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Returns false where segment_inverse_i11_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 42 +, 109 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i11_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / cross_cross;
    const T t6 = t3 * t3;
    const T t7 = t4 * t4;
    const T t8 = t6 * t6;
    const T t9 = t7 * t7;
    const T t10 = t8 * t6;
    const T t11 = t9 * t7;
    const T t12 = t9 * t9;
    const T t13 = t8 * t8;
    const T t14 = T(8) * (T(2) * (T(4) * (T(2) * (ab_ap * t3 + a_minus_b * t4) * t5 * ab_ab + ab_ap * t6 * t3 + t7 * a_minus_b * t4) * t5 * ab_ab + T(3) * ab_ap * t8 * t3 + T(3) * t9 * a_minus_b * t4) * t5 * ab_ab + T(5) * ab_ap * t10 * t3 + T(5) * t11 * a_minus_b * t4) * t5 * ab_ab + T(35) * t12 * a_minus_b * t4 + T(35) * ab_ap * t13 * t3;
    F = (T(1) / T(315)) * t14 * in.w[0] * t5;
    const T t15 = t12 * t7;
    const T t16 = t13 * t6;
    const T t17 = T(2) * t14 * t5 * ab_ab + T(63) * t15 * a_minus_b * t4 + T(63) * ab_ap * t16 * t3;
    G_ap = (T(1) / T(693)) * in.w[0] * t17 * t5;
    G_ab = (T(1) / T(693)) * (T(63) * t16 * t3 + ab_ap * t17 * t5 - T(63) * t15 * t4) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 38 +, 85 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1539 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t5 * t4;
    const T t12 = T(1) / cross_cross;
    const T t13 = t9 * t8;
    const T t14 = T(35) * t3 * ab_ap * t6 + T(35) * t10 * t7 * a_minus_b + T(8) * (T(5) * t3 * ab_ap * t11 + T(2) * (T(3) * t9 * t7 * a_minus_b + T(4) * (T(2) * (t3 * ab_ap + t7 * a_minus_b) * t12 * ab_ab + t3 * ab_ap * t4 + t8 * t7 * a_minus_b) * t12 * ab_ab + T(3) * t3 * ab_ap * t5) * t12 * ab_ab + T(5) * t13 * t7 * a_minus_b) * t12 * ab_ab;
    F = (T(1) / T(315)) * t14 * in.w[0] * t12 - (T(1) / T(315)) * (T(35) * t10 * t7 - t14 * ab_ap * t12 - T(35) * t3 * t6) * in.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 46 +, 120 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2243 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(1) / cross_cross;
    const T t13 = t5 * t4;
    const T t14 = t10 * t9;
    const T t15 = T(35) * a_minus_b * t6 * t3 + T(35) * ab_ap * t8 * t11 + T(8) * (T(2) * t12 * (T(3) * a_minus_b * t5 * t3 + T(4) * (ab_ap * t8 * t9 + T(2) * t12 * (ab_ap * t8 + a_minus_b * t3) * ab_ab + a_minus_b * t4 * t3) * t12 * ab_ab + T(3) * ab_ap * t8 * t10) * ab_ab + T(5) * a_minus_b * t13 * t3 + T(5) * ab_ap * t8 * t14) * t12 * ab_ab;
    const T t16 = t11 * t9;
    const T t17 = T(63) * a_minus_b * t7 * t3 + T(2) * t15 * t12 * ab_ab + T(63) * ab_ap * t8 * t16;
    const T t18 = T(63) * t7 * t3 - T(63) * t8 * t16 - ab_ap * t17 * t12;
    const T t19 = T(1) / ab_ab;
    G_ap = (T(1) / T(693)) * in.w[0] * t17 * t12 - (T(1) / T(693)) * in.w[1] * t18 * t19;
    G_ab = -(T(1) / T(693)) * in.w[0] * t18 * t19 - (T(1) / T(3465)) * (T(5) * t17 * ap_ap * t12 + T(10) * ab_ap * t18 * t19 - T(11) * t15 * t12) * in.w[1] * t19;
  }
  const T g_factor = -T(11) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 49 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2282 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = t9 * t9;
    const T t13 = t5 * t5;
    const T t14 = T(8) * (T(5) * t6 * a_minus_b * t3 + T(5) * ab_ap * t10 * t7 + T(2) * (T(3) * ab_ap * t9 * t7 + T(3) * t5 * a_minus_b * t3 + T(4) * (t4 * a_minus_b * t3 + T(2) * (a_minus_b * t3 + ab_ap * t7) * t11 * ab_ab + ab_ap * t8 * t7) * t11 * ab_ab) * t11 * ab_ab) * t11 * ab_ab + T(35) * ab_ap * t12 * t7 + T(35) * t13 * a_minus_b * t3;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(315)) * t14 * in.w[0] * t11 + (T(1) / T(315)) * (t14 * ab_ap * t11 + T(35) * t12 * t7 - T(35) * t13 * t3) * in.w[1] * t15;
    const T t16 = t12 * t8;
    const T t17 = t13 * t4;
    const T t18 = T(63) * ab_ap * t16 * t7 + T(63) * t17 * a_minus_b * t3 + T(2) * t14 * t11 * ab_ab;
    const T t19 = T(63) * t16 * t7 + ab_ap * t18 * t11 - T(63) * t17 * t3;
    G_ap = (T(1) / T(693)) * t19 * in.w[1] * t15 + (T(1) / T(693)) * t18 * in.w[0] * t11;
    G_ab = (T(1) / T(3465)) * (T(10) * ab_ap * t19 * t15 + T(11) * t14 * t11 - T(5) * t18 * ap_ap * t11) * in.w[1] * t15 + (T(1) / T(693)) * in.w[0] * t19 * t15;
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Returns false where segment_inverse_i11_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i11_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t6 * t6;
    const T t13 = t10 * t10;
    const T t14 = T(8) * t3 * ab_ab * (T(5) * t4 * t7 * a_minus_b + T(5) * t8 * ab_ap * t11 + T(2) * t3 * ab_ab * (T(3) * t4 * t6 * a_minus_b + T(3) * t8 * ab_ap * t10 + T(4) * (t8 * ab_ap * t9 + t4 * t5 * a_minus_b + T(2) * t3 * ab_ab * (t4 * a_minus_b + t8 * ab_ap)) * t3 * ab_ab)) + T(35) * t4 * t12 * a_minus_b + T(35) * t8 * ab_ap * t13;
    const T t15 = T(1) / ab_ab;
    F = (T(1) / T(315)) * t3 * t14 * in.w[0] + (T(1) / T(315)) * in.w[1] * t15 * (t3 * t14 * ab_ap + T(35) * t8 * t13 - T(35) * t4 * t12);
    const T t16 = t13 * t9;
    const T t17 = t12 * t5;
    const T t18 = T(2) * t3 * t14 * ab_ab + T(63) * t4 * t17 * a_minus_b + T(63) * t8 * ab_ap * t16;
    const T t19 = T(63) * t8 * t16 + t3 * t18 * ab_ap - T(63) * t4 * t17;
    G_ap = (T(1) / T(693)) * in.w[1] * t19 * t15 + (T(1) / T(693)) * t3 * t18 * in.w[0];
    G_ab = (T(1) / T(3465)) * in.w[1] * t15 * (T(10) * t19 * t15 * ab_ap + T(11) * t3 * t14 - T(5) * t3 * t18 * ap_ap) + (T(1) / T(693)) * t19 * t15 * in.w[0];
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 41 +, 96 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2231 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = t8 * t8;
    const T t11 = t10 * t8;
    const T t12 = T(5) * t6 * t3 * a_minus_b + T(2) * (T(4) * (t7 * ab_ap * t8 + t4 * t3 * a_minus_b + T(2) * (t3 * a_minus_b + t7 * ab_ap) * t9 * ab_ab) * t9 * ab_ab + T(3) * t5 * t3 * a_minus_b + T(3) * t7 * ab_ap * t10) * t9 * ab_ab + T(5) * t7 * ab_ap * t11;
    const T t13 = t10 * t10;
    const T t14 = t5 * t5;
    const T t15 = T(8) * t12 * t9 * ab_ab + T(35) * t7 * ab_ap * t13 + T(35) * t14 * t3 * a_minus_b;
    const T t16 = ab_ap * t15 * t9 + T(35) * t7 * t13 - T(35) * t14 * t3;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(315)) * t16 * in.w[1] * t17 + (T(1) / T(315)) * (T(9) * t12 * t9 + T(2) * ab_ap * t16 * t17 - t15 * ap_ap * t9) * in.w[2] * t17 + (T(1) / T(315)) * in.w[0] * t15 * t9;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 52 +, 140 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2938 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[1] * in.w[0] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2];
    G_ab = M_beyond[1] * in.w[0] + in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t6 * t5;
    const T t15 = t12 * t12;
    const T t16 = T(35) * t7 * t4 * a_minus_b + T(8) * (T(5) * ab_ap * t10 * t13 + T(2) * (T(3) * t6 * t4 * a_minus_b + T(4) * (T(2) * (ab_ap * t10 + t4 * a_minus_b) * t9 * ab_ab + ab_ap * t10 * t11 + t5 * t4 * a_minus_b) * t9 * ab_ab + T(3) * ab_ap * t10 * t12) * t9 * ab_ab + T(5) * t14 * t4 * a_minus_b) * t9 * ab_ab + T(35) * ab_ap * t10 * t15;
    const T t17 = t15 * t11;
    const T t18 = T(63) * t8 * t4 * a_minus_b + T(2) * t9 * ab_ab * t16 + T(63) * ab_ap * t10 * t17;
    const T t19 = ab_ap * t18 * t9 + T(63) * t10 * t17 - T(63) * t8 * t4;
    const T t20 = T(11) * t9 * t16 + T(10) * ab_ap * t3 * t19 - T(5) * t18 * ap_ap * t9;
    G_ap = (T(1) / T(693)) * in.w[1] * t3 * t19 + (T(1) / T(693)) * t18 * t9 * in.w[0] + (T(1) / T(3465)) * in.w[2] * t20 * t3;
    G_ab = (T(1) / T(693)) * t3 * in.w[0] * t19 + (T(1) / T(3465)) * in.w[1] * t20 * t3 - (T(1) / T(3465)) * (T(5) * ap_ap * t3 * t19 - T(11) * (ab_ap * t9 * t16 + T(35) * t10 * t15 - T(35) * t7 * t4) * t3 - T(2) * ab_ap * t20 * t3) * in.w[2] * t3;
  }
  const T g_factor = -T(11) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 56 +, 157 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2993 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + in.w[2] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[4] * in.w[0] + M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t4;
    const T t12 = T(1) / cross_cross;
    const T t13 = T(5) * a_minus_b * t7 * t10 + T(5) * ab_ap * t11 * t3 + T(2) * t12 * (T(4) * t12 * (T(2) * t12 * (ab_ap * t3 + a_minus_b * t7) * ab_ab + a_minus_b * t7 * t8 + ab_ap * t4 * t3) * ab_ab + T(3) * ab_ap * t5 * t3 + T(3) * a_minus_b * t7 * t9) * ab_ab;
    const T t14 = t9 * t9;
    const T t15 = T(35) * ab_ap * t6 * t3 + T(8) * t13 * t12 * ab_ab + T(35) * a_minus_b * t7 * t14;
    const T t16 = T(35) * t7 * t14 - ab_ap * t15 * t12 - T(35) * t6 * t3;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(315)) * t15 * t12 * in.w[0] + (T(1) / T(315)) * in.w[2] * (T(9) * t13 * t12 - t15 * ap_ap * t12 - T(2) * ab_ap * t16 * t17) * t17 - (T(1) / T(315)) * in.w[1] * t16 * t17;
    const T t18 = t6 * t4;
    const T t19 = t14 * t8;
    const T t20 = T(63) * ab_ap * t18 * t3 + T(2) * t15 * t12 * ab_ab + T(63) * a_minus_b * t7 * t19;
    const T t21 = ab_ap * t20 * t12 + T(63) * t18 * t3 - T(63) * t7 * t19;
    const T t22 = T(5) * t20 * ap_ap * t12 - T(10) * ab_ap * t21 * t17 - T(11) * t15 * t12;
    G_ap = (T(1) / T(693)) * in.w[1] * t21 * t17 + (T(1) / T(693)) * t20 * t12 * in.w[0] - (T(1) / T(3465)) * t22 * in.w[2] * t17;
    G_ab = (T(1) / T(693)) * t21 * t17 * in.w[0] - (T(1) / T(3465)) * (T(11) * t16 * t17 + T(2) * ab_ap * t22 * t17 + T(5) * ap_ap * t21 * t17) * in.w[2] * t17 - (T(1) / T(3465)) * in.w[1] * t22 * t17;
  }
  const T g_factor = -T(11) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Returns false where segment_inverse_i11_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 56 +, 157 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i11_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[6] * in.w[2] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = T(5) * t8 * t11 * a_minus_b + T(5) * t3 * ab_ap * t12 + T(2) * t7 * ab_ab * (T(4) * t7 * (t3 * ab_ap * t4 + t8 * t9 * a_minus_b + T(2) * t7 * ab_ab * (t8 * a_minus_b + t3 * ab_ap)) * ab_ab + T(3) * t8 * t10 * a_minus_b + T(3) * t3 * ab_ap * t5);
    const T t14 = t10 * t10;
    const T t15 = T(8) * t7 * ab_ab * t13 + T(35) * t8 * t14 * a_minus_b + T(35) * t3 * ab_ap * t6;
    const T t16 = T(35) * t3 * t6 + t7 * ab_ap * t15 - T(35) * t8 * t14;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(315)) * in.w[1] * t16 * t17 + (T(1) / T(315)) * t7 * in.w[0] * t15 + (T(1) / T(315)) * (T(9) * t7 * t13 + T(2) * t16 * t17 * ab_ap - t7 * t15 * ap_ap) * t17 * in.w[2];
    const T t18 = t6 * t4;
    const T t19 = t14 * t9;
    const T t20 = T(2) * t7 * ab_ab * t15 + T(63) * t8 * t19 * a_minus_b + T(63) * t3 * ab_ap * t18;
    const T t21 = T(63) * t3 * t18 + t7 * t20 * ab_ap - T(63) * t8 * t19;
    const T t22 = T(10) * t17 * t21 * ab_ap + T(11) * t7 * t15 - T(5) * t7 * t20 * ap_ap;
    G_ap = (T(1) / T(3465)) * t17 * t22 * in.w[2] + (T(1) / T(693)) * in.w[1] * t17 * t21 + (T(1) / T(693)) * t7 * t20 * in.w[0];
    G_ab = (T(1) / T(693)) * t17 * t21 * in.w[0] + (T(1) / T(3465)) * t17 * in.w[2] * (T(2) * t17 * t22 * ab_ap + T(11) * t16 * t17 - T(5) * t17 * t21 * ap_ap) + (T(1) / T(3465)) * in.w[1] * t17 * t22;
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 46 +, 112 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2925 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[3] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * a_minus_b * t7 * t4 + T(2) * t3 * ab_ab * (T(4) * (a_minus_b * t5 * t4 + t9 * t8 * ab_ap + T(2) * t3 * ab_ab * (a_minus_b * t4 + t8 * ab_ap)) * t3 * ab_ab + T(3) * t10 * t8 * ab_ap + T(3) * a_minus_b * t6 * t4) + T(5) * t11 * t8 * ab_ap;
    const T t13 = t10 * t10;
    const T t14 = t6 * t6;
    const T t15 = T(8) * t3 * ab_ab * t12 + T(35) * t13 * t8 * ab_ap + T(35) * a_minus_b * t14 * t4;
    const T t16 = T(35) * t13 * t8 + t3 * ab_ap * t15 - T(35) * t14 * t4;
    const T t17 = T(1) / ab_ab;
    const T t18 = T(2) * t16 * t17 * ab_ap + T(9) * t3 * t12 - ap_ap * t3 * t15;
    F = (T(1) / T(315)) * t3 * in.w[0] * t15 + (T(1) / T(315)) * t16 * t17 * in.w[1] + (T(1) / T(315)) * t18 * t17 * in.w[2] - (T(1) / T(315)) * in.w[3] * t17 * (ap_ap * t16 * t17 - T(9) * (t3 * t12 * ab_ap + T(5) * t11 * t8 - T(5) * t7 * t4) * t17 - T(2) * t18 * t17 * ab_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 58 +, 160 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3635 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3];
    G_ab = in.w[2] * M_flat[3] + in.w[3] * M_flat[4] + in.w[1] * M_flat[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + in.w[3] * M_beyond[4] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = t6 * t5;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = T(5) * a_minus_b * t9 * t4 + T(5) * ab_ap * t10 * t13 + T(2) * ab_ab * t3 * (T(4) * ab_ab * t3 * (ab_ap * t10 * t11 + T(2) * ab_ab * t3 * (ab_ap * t10 + a_minus_b * t4) + a_minus_b * t5 * t4) + T(3) * a_minus_b * t6 * t4 + T(3) * ab_ap * t10 * t12);
    const T t15 = t12 * t12;
    const T t16 = T(8) * ab_ab * t3 * t14 + T(35) * a_minus_b * t7 * t4 + T(35) * ab_ap * t10 * t15;
    const T t17 = t15 * t11;
    const T t18 = T(63) * a_minus_b * t8 * t4 + T(2) * ab_ab * t3 * t16 + T(63) * ab_ap * t10 * t17;
    const T t19 = T(1) / ab_ab;
    const T t20 = t3 * ab_ap * t18 + T(63) * t10 * t17 - T(63) * t8 * t4;
    const T t21 = T(10) * t19 * ab_ap * t20 + T(11) * t3 * t16 - T(5) * t3 * t18 * ap_ap;
    const T t22 = T(35) * t7 * t4 - T(35) * t10 * t15 - t3 * t16 * ab_ap;
    const T t23 = T(11) * t19 * t22 + T(5) * t19 * t20 * ap_ap - T(2) * t19 * t21 * ab_ap;
    G_ap = (T(1) / T(693)) * in.w[0] * t3 * t18 + (T(1) / T(693)) * t19 * in.w[1] * t20 + (T(1) / T(3465)) * t19 * t21 * in.w[2] - (T(1) / T(3465)) * in.w[3] * t19 * t23;
    G_ab = (T(1) / T(3465)) * t19 * in.w[1] * t21 + (T(1) / T(693)) * in.w[0] * t19 * t20 - (T(1) / T(3465)) * t19 * t23 * in.w[2] - (T(1) / T(3465)) * in.w[3] * t19 * (T(2) * t19 * t23 * ab_ap + t19 * t21 * ap_ap + T(11) * (t3 * t16 * ap_ap + T(2) * t19 * t22 * ab_ap - T(9) * t3 * t14) * t19);
  }
  const T g_factor = -T(11) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 65 +, 186 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1337 +, 3708 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i11_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
    G_ap = M_flat[6] * in.w[1] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + in.w[3] * M_flat[8];
    G_ab = in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + in.w[1] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + in.w[3] * M_beyond[8];
    G_ab = in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7] + in.w[3] * M_beyond[9] + in.w[2] * M_beyond[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t6 * t5;
    const T t13 = T(5) * t8 * t11 * a_minus_b + T(5) * ab_ap * t12 * t4 + T(2) * t3 * ab_ab * (T(3) * ab_ap * t6 * t4 + T(3) * t8 * t10 * a_minus_b + T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (t8 * a_minus_b + ab_ap * t4) + t8 * t9 * a_minus_b + ab_ap * t5 * t4));
    const T t14 = t10 * t10;
    const T t15 = T(35) * ab_ap * t7 * t4 + T(8) * t3 * ab_ab * t13 + T(35) * t8 * t14 * a_minus_b;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(35) * t8 * t14 - T(35) * t7 * t4 - t3 * t15 * ab_ap;
    const T t18 = t3 * t15 * ap_ap + T(2) * t16 * ab_ap * t17 - T(9) * t3 * t13;
    F = (T(1) / T(315)) * in.w[0] * t3 * t15 - (T(1) / T(315)) * in.w[3] * t16 * (T(2) * t16 * t18 * ab_ap - t16 * t17 * ap_ap - T(9) * t16 * (T(5) * t12 * t4 + t3 * ab_ap * t13 - T(5) * t8 * t11)) - (T(1) / T(315)) * t16 * t18 * in.w[2] - (T(1) / T(315)) * t16 * in.w[1] * t17;
    const T t19 = t7 * t5;
    const T t20 = t14 * t9;
    const T t21 = T(2) * t3 * ab_ab * t15 + T(63) * ab_ap * t19 * t4 + T(63) * t8 * t20 * a_minus_b;
    const T t22 = t21 * t3 * ab_ap + T(63) * t19 * t4 - T(63) * t8 * t20;
    const T t23 = T(11) * t3 * t15 + T(10) * t16 * ab_ap * t22 - T(5) * t21 * t3 * ap_ap;
    const T t24 = T(11) * t16 * t17 + T(5) * t16 * t22 * ap_ap - T(2) * t16 * t23 * ab_ap;
    G_ap = (T(1) / T(693)) * t16 * in.w[1] * t22 + (T(1) / T(3465)) * t16 * t23 * in.w[2] + (T(1) / T(693)) * t21 * in.w[0] * t3 - (T(1) / T(3465)) * t24 * in.w[3] * t16;
    G_ab = (T(1) / T(3465)) * t16 * in.w[1] * t23 + (T(1) / T(693)) * in.w[0] * t16 * t22 - (T(1) / T(3465)) * in.w[3] * t16 * (T(11) * t16 * t18 + T(2) * t24 * t16 * ab_ap + t16 * t23 * ap_ap) - (T(1) / T(3465)) * t24 * t16 * in.w[2];
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Returns false where segment_inverse_i11_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 65 +, 186 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i11_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1];
    G_ap = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + in.w[1] * M_flat[7] + in.w[3] * M_flat[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / cross_cross;
    const T t12 = t9 * t8;
    const T t13 = t5 * t4;
    const T t14 = T(2) * (T(3) * a_minus_b * t7 * t9 + T(3) * ab_ap * t5 * t3 + T(4) * t11 * ab_ab * (T(2) * t11 * (ab_ap * t3 + a_minus_b * t7) * ab_ab + a_minus_b * t7 * t8 + ab_ap * t4 * t3)) * t11 * ab_ab + T(5) * a_minus_b * t7 * t12 + T(5) * ab_ap * t13 * t3;
    const T t15 = T(35) * ab_ap * t6 * t3 + T(35) * a_minus_b * t7 * t10 + T(8) * t14 * t11 * ab_ab;
    const T t16 = ab_ap * t15 * t11 + T(35) * t6 * t3 - T(35) * t7 * t10;
    const T t17 = T(1) / ab_ab;
    const T t18 = T(2) * ab_ap * t16 * t17 + T(9) * t14 * t11 - ap_ap * t15 * t11;
    F = (T(1) / T(315)) * in.w[3] * (T(2) * t18 * ab_ap * t17 + T(9) * (ab_ap * t14 * t11 + T(5) * t13 * t3 - T(5) * t7 * t12) * t17 - ap_ap * t16 * t17) * t17 + (T(1) / T(315)) * t16 * t17 * in.w[1] + (T(1) / T(315)) * t15 * in.w[0] * t11 + (T(1) / T(315)) * t18 * in.w[2] * t17;
    const T t19 = t6 * t4;
    const T t20 = t10 * t8;
    const T t21 = T(63) * ab_ap * t19 * t3 + T(2) * t15 * t11 * ab_ab + T(63) * a_minus_b * t7 * t20;
    const T t22 = ab_ap * t11 * t21 + T(63) * t19 * t3 - T(63) * t7 * t20;
    const T t23 = T(5) * ap_ap * t11 * t21 - T(11) * t15 * t11 - T(10) * ab_ap * t17 * t22;
    const T t24 = T(2) * ab_ap * t23 * t17 + T(5) * ap_ap * t17 * t22 - T(11) * t16 * t17;
    G_ap = (T(1) / T(693)) * t17 * t22 * in.w[1] + (T(1) / T(693)) * in.w[0] * t11 * t21 - (T(1) / T(3465)) * t24 * in.w[3] * t17 - (T(1) / T(3465)) * in.w[2] * t23 * t17;
    G_ab = (T(1) / T(693)) * in.w[0] * t17 * t22 - (T(1) / T(3465)) * in.w[2] * t24 * t17 - (T(1) / T(3465)) * in.w[3] * t17 * (T(2) * ab_ap * t24 * t17 - T(11) * t18 * t17 - t23 * ap_ap * t17) - (T(1) / T(3465)) * t23 * t17 * in.w[1];
  }
  const T g_factor = -T(11) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 38 +, 76 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 854 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = t8 * t6;
    const T t15 = t11 * t9;
    F = (T(1) / T(1280)) * in.w[0] * t5 * (T(3) * t5 * ab_ab * (T(48) * ab_ap * t8 + T(48) * a_minus_b * t11 + T(7) * t5 * ab_ab * (T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (ab_ap * t6 + a_minus_b * t9 + J2 * ab_ab) + T(2) * a_minus_b * t10 + T(2) * ab_ap * t7) + T(8) * a_minus_b * t12 + T(8) * ab_ap * t13)) + T(128) * ab_ap * t14 + T(128) * a_minus_b * t15);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 45 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1555 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = T(1) / cross_cross;
    const T t15 = t10 * t10;
    const T t16 = t13 * t5;
    const T t17 = t15 * t9;
    const T t18 = T(1280) * t8 * a_minus_b + T(1280) * ab_ap * t12 + T(11) * ab_ab * (T(3) * ab_ab * (T(48) * t13 * a_minus_b + T(7) * ab_ab * (T(8) * t7 * a_minus_b + T(5) * ab_ab * (T(3) * ab_ab * (t5 * a_minus_b + ab_ap * t9 + ab_ab * J2) * t14 + T(2) * ab_ap * t10 + T(2) * t6 * a_minus_b) * t14 + T(8) * ab_ap * t11) * t14 + T(48) * ab_ap * t15) * t14 + T(128) * t16 * a_minus_b + T(128) * ab_ap * t17) * t14;
    G_ap = (T(1) / T(15360)) * t18 * in.w[0] * t14;
    G_ab = (T(1) / T(15360)) * (T(1280) * t12 + t18 * ab_ap * t14 - T(1280) * t8) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 45 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1581 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t6;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = T(128) * ab_ap * t9 + T(3) * t5 * (T(48) * ab_ap * t8 + T(7) * (T(8) * t12 * a_minus_b + T(8) * ab_ap * t13 + T(5) * t5 * ab_ab * (T(2) * t11 * a_minus_b + T(2) * ab_ap * t7 + T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t6 + t10 * a_minus_b))) * t5 * ab_ab + T(48) * t14 * a_minus_b) * ab_ab + T(128) * t15 * a_minus_b;
    F = (T(1) / T(1280)) * in.w[0] * t5 * t16;
    const T t17 = t13 * t13;
    const T t18 = t12 * t12;
    const T t19 = T(1280) * ab_ap * t17 + T(11) * t5 * ab_ab * t16 + T(1280) * t18 * a_minus_b;
    G_ap = (T(1) / T(15360)) * in.w[0] * t5 * t19;
    G_ab = -(T(1) / T(15360)) * in.w[0] * (T(1280) * t18 - T(1280) * t17 - t5 * t19 * ab_ap) / ab_ab;
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Returns false where segment_inverse_i12_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i12_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = t6 * t5;
    const T t13 = t9 * t9;
    const T t14 = t7 * t5;
    const T t15 = t13 * t8;
    const T t16 = T(3) * ab_ab * (T(48) * ab_ap * t7 + T(7) * ab_ab * (T(8) * t10 * a_minus_b + T(5) * ab_ab * (T(3) * ab_ab * (ab_ap * t5 + t8 * a_minus_b + ab_ab * J2) * t11 + T(2) * t9 * a_minus_b + T(2) * ab_ap * t6) * t11 + T(8) * ab_ap * t12) * t11 + T(48) * t13 * a_minus_b) * t11 + T(128) * ab_ap * t14 + T(128) * t15 * a_minus_b;
    F = (T(1) / T(1280)) * t16 * in.w[0] * t11;
    const T t17 = t10 * t10;
    const T t18 = t12 * t12;
    const T t19 = T(11) * t16 * ab_ab * t11 + T(1280) * t17 * a_minus_b + T(1280) * ab_ap * t18;
    G_ap = (T(1) / T(15360)) * t19 * in.w[0] * t11;
    G_ab = -(T(1) / T(15360)) * (T(1280) * t17 - T(1280) * t18 - t19 * ab_ap * t11) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 41 +, 82 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1544 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t7 * t6;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t8 * t6;
    const T t15 = t13 * t10;
    const T t16 = T(3) * t5 * ab_ab * (T(48) * a_minus_b * t8 + T(7) * t5 * ab_ab * (T(8) * a_minus_b * t9 + T(8) * t12 * ab_ap + T(5) * (T(2) * a_minus_b * t7 + T(2) * t11 * ab_ap + T(3) * (J2 * ab_ab + t10 * ab_ap + a_minus_b * t6) * t5 * ab_ab) * t5 * ab_ab) + T(48) * t13 * ab_ap) + T(128) * a_minus_b * t14 + T(128) * t15 * ab_ap;
    F = (T(1) / T(1280)) * in.w[0] * t16 * t5 + (T(1) / T(1280)) * in.w[1] * (t16 * t5 * ab_ap + T(128) * t15 - T(128) * t14) / ab_ab;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 49 +, 114 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2248 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t15 * t12;
    const T t17 = T(128) * ab_ap * t11 + T(3) * t5 * ab_ab * (T(48) * ab_ap * t10 + T(7) * t5 * ab_ab * (T(8) * ab_ap * t8 + T(5) * t5 * ab_ab * (T(2) * ab_ap * t7 + T(3) * t5 * ab_ab * (a_minus_b * t12 + ab_ap * t6 + ab_ab * J2) + T(2) * a_minus_b * t13) + T(8) * a_minus_b * t14) + T(48) * a_minus_b * t15) + T(128) * a_minus_b * t16;
    const T t18 = t14 * t14;
    const T t19 = T(1280) * ab_ap * t9 + T(11) * t5 * ab_ab * t17 + T(1280) * a_minus_b * t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = t5 * ab_ap * t19 + T(1280) * t9 - T(1280) * t18;
    G_ap = (T(1) / T(15360)) * t5 * t19 * in.w[0] + (T(1) / T(15360)) * in.w[1] * t20 * t21;
    G_ab = (T(1) / T(15360)) * in.w[1] * t20 * (T(2) * t20 * ab_ap * t21 + T(12) * t5 * t17 - t5 * t19 * ap_ap) + (T(1) / T(15360)) * t20 * t21 * in.w[0];
  }
  const T g_factor = -T(12) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 52 +, 125 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2288 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = M_beyond[4] * in.w[0] + in.w[1] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = t13 * t6;
    const T t15 = t12 * t9;
    const T t16 = T(3) * t5 * ab_ab * (T(7) * (T(8) * t8 * ab_ap + T(8) * t11 * a_minus_b + T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (ab_ab * J2 + t9 * a_minus_b + t6 * ab_ap) + T(2) * t7 * ab_ap + T(2) * t10 * a_minus_b)) * t5 * ab_ab + T(48) * t12 * a_minus_b + T(48) * t13 * ab_ap) + T(128) * t14 * ab_ap + T(128) * t15 * a_minus_b;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(1280)) * t5 * t16 * in.w[0] + (T(1) / T(1280)) * in.w[1] * (t5 * t16 * ab_ap + T(128) * t14 - T(128) * t15) * t17;
    const T t18 = t11 * t11;
    const T t19 = t8 * t8;
    const T t20 = T(1280) * t18 * a_minus_b + T(11) * t5 * ab_ab * t16 + T(1280) * t19 * ab_ap;
    const T t21 = T(1280) * t18 - T(1280) * t19 - t20 * t5 * ab_ap;
    G_ap = (T(1) / T(15360)) * t20 * t5 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t21 * t17;
    G_ab = (T(1) / T(15360)) * in.w[1] * t17 * (T(12) * t5 * t16 - ap_ap * t20 * t5 - T(2) * t21 * t17 * ab_ap) - (T(1) / T(15360)) * t21 * t17 * in.w[0];
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Returns false where segment_inverse_i12_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 125 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i12_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t7 * t6;
    const T t11 = t9 * t8;
    const T t12 = t7 * t7;
    const T t13 = t9 * t9;
    const T t14 = t12 * t6;
    const T t15 = t13 * t8;
    const T t16 = T(3) * t5 * ab_ab * (T(7) * t5 * ab_ab * (T(5) * (T(2) * t7 * a_minus_b + T(2) * ab_ap * t9 + T(3) * t5 * (J2 * ab_ab + ab_ap * t8 + t6 * a_minus_b) * ab_ab) * t5 * ab_ab + T(8) * t10 * a_minus_b + T(8) * ab_ap * t11) + T(48) * t12 * a_minus_b + T(48) * ab_ap * t13) + T(128) * t14 * a_minus_b + T(128) * ab_ap * t15;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(1280)) * in.w[0] * t16 * t5 - (T(1) / T(1280)) * (T(128) * t14 - ab_ap * t16 * t5 - T(128) * t15) * in.w[1] * t17;
    const T t18 = t11 * t11;
    const T t19 = t10 * t10;
    const T t20 = T(11) * t16 * t5 * ab_ab + T(1280) * ab_ap * t18 + T(1280) * t19 * a_minus_b;
    const T t21 = T(1280) * t19 - t20 * ab_ap * t5 - T(1280) * t18;
    G_ap = (T(1) / T(15360)) * t20 * in.w[0] * t5 - (T(1) / T(15360)) * in.w[1] * t17 * t21;
    G_ab = -(T(1) / T(15360)) * in.w[1] * (t20 * ap_ap * t5 + T(2) * ab_ap * t17 * t21 - T(12) * t16 * t5) * t17 - (T(1) / T(15360)) * in.w[0] * t17 * t21;
  }
  const T g_factor = -T(12) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 44 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2236 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = t7 * t6;
    const T t14 = t12 * t11;
    const T t15 = t12 * t12;
    const T t16 = T(48) * ab_ap * t8 + T(7) * ab_ab * t10 * (T(5) * (T(2) * ab_ap * t7 + T(3) * (a_minus_b * t11 + J2 * ab_ab + ab_ap * t6) * ab_ab * t10 + T(2) * a_minus_b * t12) * ab_ab * t10 + T(8) * ab_ap * t13 + T(8) * a_minus_b * t14) + T(48) * a_minus_b * t15;
    const T t17 = t15 * t11;
    const T t18 = T(128) * ab_ap * t9 + T(3) * t16 * ab_ab * t10 + T(128) * a_minus_b * t17;
    const T t19 = t18 * t10 * ab_ap + T(128) * t9 - T(128) * t17;
    F = (T(1) / T(3840)) * (T(6) * t5 * t19 * ab_ap + T(10) * t16 * t10 - T(3) * t18 * t10 * ap_ap) * in.w[2] * t5 + (T(1) / T(1280)) * t18 * t10 * in.w[0] + (T(1) / T(1280)) * t5 * t19 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 55 +, 131 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2943 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ab = in.w[2] * M_flat[3] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t8 * t8;
    const T t16 = t12 * t12;
    const T t17 = t15 * t7;
    const T t18 = t16 * t11;
    const T t19 = T(3) * t6 * ab_ab * (T(7) * t6 * ab_ab * (T(8) * a_minus_b * t13 + T(5) * t6 * ab_ab * (T(2) * ab_ap * t8 + T(2) * a_minus_b * t12 + T(3) * (ab_ap * t7 + a_minus_b * t11 + ab_ab * J2) * t6 * ab_ab) + T(8) * ab_ap * t9) + T(48) * ab_ap * t15 + T(48) * a_minus_b * t16) + T(128) * ab_ap * t17 + T(128) * a_minus_b * t18;
    const T t20 = T(1280) * ab_ap * t10 + T(1280) * a_minus_b * t14 + T(11) * t6 * ab_ab * t19;
    const T t21 = t6 * t20 * ab_ap + T(1280) * t10 - T(1280) * t14;
    const T t22 = T(2) * t21 * t5 * ab_ap + T(12) * t6 * t19 - t6 * t20 * ap_ap;
    G_ap = (T(1) / T(15360)) * in.w[2] * t5 * t22 + (T(1) / T(15360)) * t21 * t5 * in.w[1] + (T(1) / T(15360)) * t6 * in.w[0] * t20;
    G_ab = (T(1) / T(15360)) * t5 * t22 * in.w[1] + (T(1) / T(15360)) * in.w[2] * t5 * (T(2) * t5 * ab_ap * t22 + T(12) * t5 * (t6 * t19 * ab_ap + T(128) * t17 - T(128) * t18) - t21 * t5 * ap_ap) + (T(1) / T(15360)) * t21 * t5 * in.w[0];
  }
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 59 +, 149 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 2999 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
    G_ab = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
    G_ap = in.w[2] * M_beyond[6] + M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
    G_ab = M_beyond[7] * in.w[2] + in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t7 * t6;
    const T t13 = t11 * t10;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t8 * a_minus_b + T(7) * (T(5) * t9 * ab_ab * (T(2) * t7 * a_minus_b + T(3) * (ab_ap * t10 + ab_ab * J2 + t6 * a_minus_b) * t9 * ab_ab + T(2) * ab_ap * t11) + T(8) * t12 * a_minus_b + T(8) * ab_ap * t13) * t9 * ab_ab + T(48) * ab_ap * t14;
    const T t16 = t8 * t6;
    const T t17 = t14 * t10;
    const T t18 = T(3) * t15 * t9 * ab_ab + T(128) * t16 * a_minus_b + T(128) * ab_ap * t17;
    const T t19 = T(128) * t16 - t9 * t18 * ab_ap - T(128) * t17;
    F = (T(1) / T(3840)) * in.w[2] * t5 * (T(10) * t15 * t9 - T(3) * t9 * t18 * ap_ap - T(6) * t5 * t19 * ab_ap) + (T(1) / T(1280)) * t9 * t18 * in.w[0] - (T(1) / T(1280)) * t5 * t19 * in.w[1];
    const T t20 = t13 * t13;
    const T t21 = t12 * t12;
    const T t22 = T(11) * t9 * ab_ab * t18 + T(1280) * ab_ap * t20 + T(1280) * t21 * a_minus_b;
    const T t23 = T(1280) * t21 - T(1280) * t20 - t9 * t22 * ab_ap;
    const T t24 = t9 * t22 * ap_ap + T(2) * t5 * t23 * ab_ap - T(12) * t9 * t18;
    G_ap = (T(1) / T(15360)) * t9 * in.w[0] * t22 - (T(1) / T(15360)) * in.w[2] * t5 * t24 - (T(1) / T(15360)) * t5 * t23 * in.w[1];
    G_ab = (T(1) / T(15360)) * in.w[2] * t5 * (t5 * t23 * ap_ap - T(2) * t5 * ab_ap * t24 - T(12) * t5 * t19) - (T(1) / T(15360)) * t5 * in.w[0] * t23 - (T(1) / T(15360)) * t5 * t24 * in.w[1];
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Returns false where segment_inverse_i12_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 149 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i12_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + in.w[2] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t8 * t7;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t9 * a_minus_b + T(7) * t6 * ab_ab * (T(5) * t6 * ab_ab * (T(2) * ab_ap * t11 + T(3) * t6 * ab_ab * (t7 * a_minus_b + ab_ap * t10 + ab_ab * J2) + T(2) * t8 * a_minus_b) + T(8) * ab_ap * t12 + T(8) * t13 * a_minus_b) + T(48) * ab_ap * t14;
    const T t16 = t9 * t7;
    const T t17 = t14 * t10;
    const T t18 = T(3) * t6 * ab_ab * t15 + T(128) * t16 * a_minus_b + T(128) * ab_ap * t17;
    const T t19 = t6 * ab_ap * t18 + T(128) * t17 - T(128) * t16;
    F = (T(1) / T(1280)) * t5 * t19 * in.w[1] + (T(1) / T(1280)) * t6 * in.w[0] * t18 - (T(1) / T(3840)) * in.w[2] * t5 * (T(3) * t6 * t18 * ap_ap - T(6) * t5 * t19 * ab_ap - T(10) * t6 * t15);
    const T t20 = t12 * t12;
    const T t21 = t13 * t13;
    const T t22 = T(1280) * t21 * a_minus_b + T(11) * t6 * ab_ab * t18 + T(1280) * ab_ap * t20;
    const T t23 = T(1280) * t20 + t6 * t22 * ab_ap - T(1280) * t21;
    const T t24 = t6 * t22 * ap_ap - T(2) * t5 * ab_ap * t23 - T(12) * t6 * t18;
    G_ap = (T(1) / T(15360)) * t5 * in.w[1] * t23 + (T(1) / T(15360)) * t6 * t22 * in.w[0] - (T(1) / T(15360)) * in.w[2] * t5 * t24;
    G_ab = (T(1) / T(15360)) * t5 * in.w[0] * t23 - (T(1) / T(15360)) * in.w[2] * t5 * (t5 * ap_ap * t23 + T(2) * t5 * t24 * ab_ap - T(12) * t5 * t19) - (T(1) / T(15360)) * t5 * t24 * in.w[1];
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 49 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2930 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t6 * t5;
    const T t16 = T(48) * t7 * ab_ap + T(7) * (T(5) * (T(2) * t6 * ab_ap + T(3) * t9 * ab_ab * (a_minus_b * t10 + t5 * ab_ap + J2 * ab_ab) + T(2) * a_minus_b * t11) * t9 * ab_ab + T(8) * a_minus_b * t14 + T(8) * t15 * ab_ap) * t9 * ab_ab + T(48) * a_minus_b * t12;
    const T t17 = T(128) * t8 * ab_ap + T(128) * a_minus_b * t13 + T(3) * t9 * ab_ab * t16;
    const T t18 = T(128) * t8 + t9 * t17 * ab_ap - T(128) * t13;
    const T t19 = T(1) / ab_ab;
    const T t20 = T(10) * t9 * t16 + T(6) * t18 * t19 * ab_ap - T(3) * ap_ap * t9 * t17;
    F = (T(1) / T(1280)) * t18 * t19 * in.w[1] + (T(1) / T(1280)) * t9 * in.w[0] * t17 + (T(1) / T(3840)) * (T(10) * t19 * (T(48) * t7 + t9 * t16 * ab_ap - T(48) * t12) + T(2) * t20 * t19 * ab_ap - T(3) * ap_ap * t18 * t19) * in.w[3] * t19 + (T(1) / T(3840)) * t20 * t19 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 61 +, 152 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3640 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ab = in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + M_flat[2] * in.w[1] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0] + M_beyond[4] * in.w[3] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = T(1) / cross_cross;
    const T t14 = t6 * t6;
    const T t15 = t14 * t5;
    const T t16 = t10 * t10;
    const T t17 = t16 * t9;
    const T t18 = T(7) * (T(8) * a_minus_b * t7 + T(8) * ab_ap * t11 + T(5) * (T(2) * a_minus_b * t6 + T(3) * t13 * (ab_ap * t9 + ab_ab * J2 + a_minus_b * t5) * ab_ab + T(2) * ab_ap * t10) * t13 * ab_ab) * t13 * ab_ab + T(48) * a_minus_b * t14 + T(48) * ab_ap * t16;
    const T t19 = T(128) * a_minus_b * t15 + T(128) * ab_ap * t17 + T(3) * t13 * ab_ab * t18;
    const T t20 = T(1280) * a_minus_b * t8 + T(1280) * ab_ap * t12 + T(11) * t13 * ab_ab * t19;
    const T t21 = ab_ap * t13 * t19 + T(128) * t17 - T(128) * t15;
    const T t22 = T(1) / ab_ab;
    const T t23 = T(1280) * t8 - ab_ap * t20 * t13 - T(1280) * t12;
    const T t24 = ap_ap * t20 * t13 + T(2) * ab_ap * t22 * t23 - T(12) * t13 * t19;
    const T t25 = T(12) * t21 * t22 + ap_ap * t22 * t23 - T(2) * ab_ap * t24 * t22;
    G_ap = (T(1) / T(15360)) * t20 * t13 * in.w[0] + (T(1) / T(15360)) * t25 * in.w[3] * t22 - (T(1) / T(15360)) * in.w[2] * t24 * t22 - (T(1) / T(15360)) * t22 * t23 * in.w[1];
    G_ab = (T(1) / T(15360)) * t25 * in.w[2] * t22 + (T(1) / T(15360)) * in.w[3] * t22 * (T(2) * ab_ap * t25 * t22 + T(4) * (T(10) * t13 * t18 + T(6) * ab_ap * t21 * t22 - T(3) * ap_ap * t13 * t19) * t22 + t24 * ap_ap * t22) - (T(1) / T(15360)) * t24 * t22 * in.w[1] - (T(1) / T(15360)) * in.w[0] * t22 * t23;
  }
  const T g_factor = -T(12) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 68 +, 177 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3714 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i12_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[8] * in.w[3];
    G_ab = M_flat[9] * in.w[3] + M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[7] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
    G_ab = in.w[2] * M_beyond[8] + M_beyond[7] * in.w[1] + in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t7 * t6;
    const T t10 = T(1) / ap_ap;
    const T t11 = T(1) / cross_cross;
    const T t12 = t10 * t10;
    const T t13 = t12 * t10;
    const T t14 = t12 * t12;
    const T t15 = T(48) * a_minus_b * t8 + T(7) * (T(8) * a_minus_b * t9 + T(5) * (T(2) * a_minus_b * t7 + T(3) * (J2 * ab_ab + ab_ap * t10 + a_minus_b * t6) * t11 * ab_ab + T(2) * ab_ap * t12) * t11 * ab_ab + T(8) * ab_ap * t13) * t11 * ab_ab + T(48) * ab_ap * t14;
    const T t16 = t14 * t10;
    const T t17 = t8 * t6;
    const T t18 = T(128) * a_minus_b * t17 + T(128) * ab_ap * t16 + T(3) * t15 * t11 * ab_ab;
    const T t19 = T(128) * t16 + ab_ap * t11 * t18 - T(128) * t17;
    const T t20 = T(6) * ab_ap * t19 * t5 + T(10) * t15 * t11 - T(3) * ap_ap * t11 * t18;
    F = (T(1) / T(3840)) * (T(10) * t5 * (ab_ap * t15 * t11 + T(48) * t14 - T(48) * t8) + T(2) * ab_ap * t20 * t5 - T(3) * ap_ap * t19 * t5) * in.w[3] * t5 + (T(1) / T(1280)) * t19 * t5 * in.w[1] + (T(1) / T(3840)) * in.w[2] * t20 * t5 + (T(1) / T(1280)) * t11 * in.w[0] * t18;
    const T t21 = t9 * t9;
    const T t22 = t13 * t13;
    const T t23 = T(11) * t11 * ab_ab * t18 + T(1280) * a_minus_b * t21 + T(1280) * ab_ap * t22;
    const T t24 = ab_ap * t23 * t11 + T(1280) * t22 - T(1280) * t21;
    const T t25 = T(12) * t11 * t18 + T(2) * t24 * ab_ap * t5 - t23 * ap_ap * t11;
    const T t26 = T(12) * t19 * t5 + T(2) * ab_ap * t5 * t25 - t24 * ap_ap * t5;
    G_ap = (T(1) / T(15360)) * t23 * t11 * in.w[0] + (T(1) / T(15360)) * t24 * t5 * in.w[1] + (T(1) / T(15360)) * in.w[2] * t5 * t25 + (T(1) / T(15360)) * t26 * in.w[3] * t5;
    G_ab = (T(1) / T(15360)) * t26 * in.w[2] * t5 + (T(1) / T(15360)) * t5 * t25 * in.w[1] + (T(1) / T(15360)) * t24 * in.w[0] * t5 - (T(1) / T(15360)) * (ap_ap * t5 * t25 - T(2) * t26 * ab_ap * t5 - T(4) * t20 * t5) * in.w[3] * t5;
  }
  const T g_factor = -T(12) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Returns false where segment_inverse_i12_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 68 +, 177 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i12_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[6] * in.w[1] + in.w[3] * M_flat[8] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
    G_ab = in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + in.w[1] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t7 * t7;
    const T t13 = t10 * t10;
    const T t14 = T(7) * t5 * ab_ab * (T(8) * t8 * a_minus_b + T(8) * ab_ap * t11 + T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t9 + t6 * a_minus_b) + T(2) * t7 * a_minus_b + T(2) * ab_ap * t10)) + T(48) * t12 * a_minus_b + T(48) * ab_ap * t13;
    const T t15 = t12 * t6;
    const T t16 = t13 * t9;
    const T t17 = T(3) * t5 * ab_ab * t14 + T(128) * t15 * a_minus_b + T(128) * ab_ap * t16;
    const T t18 = T(1) / ab_ab;
    const T t19 = T(128) * t15 - t5 * t17 * ab_ap - T(128) * t16;
    const T t20 = T(6) * t19 * t18 * ab_ap + T(3) * t5 * t17 * ap_ap - T(10) * t5 * t14;
    F = (T(1) / T(1280)) * in.w[0] * t5 * t17 - (T(1) / T(3840)) * t18 * in.w[2] * t20 - (T(1) / T(3840)) * in.w[3] * t18 * (T(10) * (T(48) * t12 - t5 * t14 * ab_ap - T(48) * t13) * t18 + T(2) * t18 * ab_ap * t20 - T(3) * t19 * t18 * ap_ap) - (T(1) / T(1280)) * t19 * t18 * in.w[1];
    const T t21 = t11 * t11;
    const T t22 = t8 * t8;
    const T t23 = T(11) * t5 * ab_ab * t17 + T(1280) * ab_ap * t21 + T(1280) * t22 * a_minus_b;
    const T t24 = T(1280) * t22 - t5 * t23 * ab_ap - T(1280) * t21;
    const T t25 = T(12) * t5 * t17 - t5 * t23 * ap_ap - T(2) * t18 * ab_ap * t24;
    const T t26 = t18 * t24 * ap_ap + T(2) * t18 * ab_ap * t25 - T(12) * t19 * t18;
    G_ap = (T(1) / T(15360)) * t18 * in.w[2] * t25 + (T(1) / T(15360)) * in.w[0] * t5 * t23 + (T(1) / T(15360)) * in.w[3] * t26 * t18 - (T(1) / T(15360)) * t18 * in.w[1] * t24;
    G_ab = (T(1) / T(15360)) * t18 * in.w[1] * t25 + (T(1) / T(15360)) * t26 * t18 * in.w[2] - (T(1) / T(15360)) * in.w[0] * t18 * t24 - (T(1) / T(15360)) * in.w[3] * t18 * (t18 * ap_ap * t25 + T(4) * t18 * t20 - T(2) * t26 * t18 * ab_ap);
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 37 +, 88 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 851 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t5 * t4;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    F = (T(1) / T(693)) * (T(63) * ab_ap * t7 * t3 + T(2) * t8 * ab_ab * (T(35) * ab_ap * t6 * t3 + T(8) * t8 * ab_ab * (T(2) * t8 * ab_ab * (T(4) * (t9 * a_minus_b * t10 + ab_ap * t4 * t3 + T(2) * (t9 * a_minus_b + ab_ap * t3) * t8 * ab_ab) * t8 * ab_ab + T(3) * ab_ap * t5 * t3 + T(3) * t9 * a_minus_b * t11) + T(5) * t9 * a_minus_b * t12 + T(5) * ab_ap * t13 * t3) + T(35) * t9 * a_minus_b * t14) + T(63) * t9 * a_minus_b * t15) * in.w[0] * t8;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 44 +, 116 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1553 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t6 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t7 * t5;
    const T t15 = t13 * t10;
    const T t16 = t12 * t12;
    const T t17 = t8 * t8;
    const T t18 = T(4) * t3 * ab_ab * (T(2) * (T(35) * t4 * t7 * ab_ap + T(8) * (T(5) * t4 * t8 * ab_ap + T(2) * t3 * ab_ab * (T(3) * t4 * t6 * ab_ap + T(4) * t3 * ab_ab * (t9 * a_minus_b * t10 + T(2) * (t4 * ab_ap + t9 * a_minus_b) * t3 * ab_ab + t4 * t5 * ab_ap) + T(3) * t9 * a_minus_b * t11) + T(5) * t9 * a_minus_b * t12) * t3 * ab_ab + T(35) * t9 * a_minus_b * t13) * t3 * ab_ab + T(63) * t4 * t14 * ab_ap + T(63) * t9 * a_minus_b * t15) + T(231) * t9 * a_minus_b * t16 + T(231) * t4 * t17 * ab_ap;
    G_ap = (T(1) / T(3003)) * t18 * in.w[0] * t3;
    G_ab = (T(1) / T(3003)) * (T(231) * t4 * t17 + t18 * t3 * ab_ap - T(231) * t9 * t16) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(13) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 44 +, 120 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1578 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = T(63) * t8 * a_minus_b * t4 + T(2) * (T(8) * (T(5) * ab_ap * t12 * t9 + T(2) * t3 * (T(3) * t6 * a_minus_b * t4 + T(3) * ab_ap * t11 * t9 + T(4) * (T(2) * (ab_ap * t9 + a_minus_b * t4) * t3 * ab_ab + ab_ap * t10 * t9 + t5 * a_minus_b * t4) * t3 * ab_ab) * ab_ab + T(5) * t13 * a_minus_b * t4) * t3 * ab_ab + T(35) * t7 * a_minus_b * t4 + T(35) * ab_ap * t14 * t9) * t3 * ab_ab + T(63) * ab_ap * t15 * t9;
    F = (T(1) / T(693)) * in.w[0] * t3 * t16;
    const T t17 = t12 * t12;
    const T t18 = t13 * t13;
    const T t19 = T(231) * ab_ap * t17 * t9 + T(231) * t18 * a_minus_b * t4 + T(4) * t3 * ab_ab * t16;
    G_ap = (T(1) / T(3003)) * t19 * in.w[0] * t3;
    G_ab = (T(1) / T(3003)) * (T(231) * t17 * t9 + ab_ap * t19 * t3 - T(231) * t18 * t4) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Returns false where segment_inverse_i13_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 44 +, 120 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i13_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = T(1) / cross_cross;
    const T t13 = t5 * t4;
    const T t14 = t10 * t8;
    const T t15 = t6 * t4;
    const T t16 = T(2) * (T(35) * t6 * t3 * ab_ap + T(35) * a_minus_b * t7 * t10 + T(8) * (T(5) * a_minus_b * t7 * t11 + T(2) * (T(3) * a_minus_b * t7 * t9 + T(4) * t12 * ab_ab * (T(2) * (t3 * ab_ap + a_minus_b * t7) * t12 * ab_ab + t4 * t3 * ab_ap + a_minus_b * t7 * t8) + T(3) * t5 * t3 * ab_ap) * t12 * ab_ab + T(5) * t13 * t3 * ab_ap) * t12 * ab_ab) * t12 * ab_ab + T(63) * a_minus_b * t7 * t14 + T(63) * t15 * t3 * ab_ap;
    F = (T(1) / T(693)) * t16 * in.w[0] * t12;
    const T t17 = t11 * t11;
    const T t18 = t13 * t13;
    const T t19 = T(4) * t16 * t12 * ab_ab + T(231) * a_minus_b * t7 * t17 + T(231) * t18 * t3 * ab_ap;
    G_ap = (T(1) / T(3003)) * in.w[0] * t12 * t19;
    G_ab = (T(1) / T(3003)) * in.w[0] * (t12 * t19 * ab_ap + T(231) * t18 * t3 - T(231) * t7 * t17) / ab_ab;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 40 +, 96 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1541 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / cross_cross;
    const T t14 = t5 * t4;
    const T t15 = t10 * t9;
    const T t16 = T(63) * t3 * a_minus_b * t7 + T(63) * ab_ap * t12 * t8 + T(2) * t13 * (T(35) * t3 * a_minus_b * t6 + T(8) * t13 * ab_ab * (T(2) * t13 * ab_ab * (T(3) * t3 * a_minus_b * t5 + T(4) * (ab_ap * t9 * t8 + T(2) * (t3 * a_minus_b + ab_ap * t8) * t13 * ab_ab + t3 * a_minus_b * t4) * t13 * ab_ab + T(3) * ab_ap * t10 * t8) + T(5) * t3 * a_minus_b * t14 + T(5) * ab_ap * t15 * t8) + T(35) * ab_ap * t11 * t8) * ab_ab;
    F = (T(1) / T(693)) * in.w[0] * t16 * t13 + (T(1) / T(693)) * in.w[1] * (T(63) * t12 * t8 + ab_ap * t16 * t13 - T(63) * t3 * t7) / ab_ab;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 48 +, 131 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2246 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t6 * t6;
    const T t15 = t14 * t5;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = T(63) * a_minus_b * t15 * t4 + T(63) * t17 * t9 * ab_ap + T(2) * t3 * ab_ab * (T(35) * a_minus_b * t14 * t4 + T(35) * t16 * t9 * ab_ap + T(8) * t3 * (T(5) * t12 * t9 * ab_ap + T(5) * a_minus_b * t7 * t4 + T(2) * (T(3) * t11 * t9 * ab_ap + T(3) * a_minus_b * t6 * t4 + T(4) * (T(2) * t3 * ab_ab * (a_minus_b * t4 + t9 * ab_ap) + a_minus_b * t5 * t4 + t10 * t9 * ab_ap) * t3 * ab_ab) * t3 * ab_ab) * ab_ab);
    const T t19 = T(231) * a_minus_b * t8 * t4 + T(231) * t13 * t9 * ab_ap + T(4) * t3 * ab_ab * t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = T(231) * t8 * t4 - t3 * t19 * ab_ap - T(231) * t13 * t9;
    G_ap = (T(1) / T(3003)) * t3 * t19 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t20 * t21;
    G_ab = -(T(1) / T(3003)) * t20 * t21 * in.w[0] - (T(1) / T(9009)) * (T(6) * t20 * ab_ap * t21 + T(3) * ap_ap * t3 * t19 - T(13) * t3 * t18) * in.w[1] * t20;
  }
  const T g_factor = -T(13) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 51 +, 144 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2285 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = t9 * t8;
    const T t12 = t9 * t9;
    const T t13 = t5 * t5;
    const T t14 = t12 * t8;
    const T t15 = t13 * t4;
    const T t16 = T(2) * ab_ab * (T(8) * ab_ab * (T(5) * t3 * t6 * a_minus_b + T(2) * ab_ab * (T(3) * ab_ap * t9 * t7 + T(3) * t3 * t5 * a_minus_b + T(4) * ab_ab * (T(2) * ab_ab * (ab_ap * t7 + t3 * a_minus_b) * t10 + t3 * t4 * a_minus_b + ab_ap * t8 * t7) * t10) * t10 + T(5) * ab_ap * t11 * t7) * t10 + T(35) * ab_ap * t12 * t7 + T(35) * t3 * t13 * a_minus_b) * t10 + T(63) * ab_ap * t14 * t7 + T(63) * t3 * t15 * a_minus_b;
    const T t17 = T(1) / ab_ab;
    F = (T(1) / T(693)) * t16 * in.w[0] * t10 - (T(1) / T(693)) * t17 * (T(63) * t3 * t15 - T(63) * t14 * t7 - t16 * ab_ap * t10) * in.w[1];
    const T t18 = t6 * t6;
    const T t19 = t11 * t11;
    const T t20 = T(4) * t16 * ab_ab * t10 + T(231) * t3 * t18 * a_minus_b + T(231) * ab_ap * t19 * t7;
    const T t21 = T(231) * t3 * t18 - T(231) * t19 * t7 - t20 * ab_ap * t10;
    G_ap = (T(1) / T(3003)) * t20 * in.w[0] * t10 - (T(1) / T(3003)) * t17 * t21 * in.w[1];
    G_ab = (T(1) / T(9009)) * t17 * (T(13) * t16 * t10 - T(3) * t20 * ap_ap * t10 - T(6) * t17 * t21 * ab_ap) * in.w[1] - (T(1) / T(3003)) * t17 * t21 * in.w[0];
  }
  const T g_factor = -T(13) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Returns false where segment_inverse_i13_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 51 +, 144 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i13_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t7 * t6;
    const T t15 = t12 * t12;
    const T t16 = t15 * t11;
    const T t17 = T(63) * t5 * t9 * a_minus_b + T(2) * (T(35) * t5 * t8 * a_minus_b + T(8) * t4 * ab_ab * (T(5) * t10 * ab_ap * t13 + T(2) * t4 * ab_ab * (T(4) * t4 * ab_ab * (t10 * ab_ap * t11 + t5 * t6 * a_minus_b + T(2) * t4 * (t10 * ab_ap + t5 * a_minus_b) * ab_ab) + T(3) * t5 * t7 * a_minus_b + T(3) * t10 * ab_ap * t12) + T(5) * t5 * t14 * a_minus_b) + T(35) * t10 * ab_ap * t15) * t4 * ab_ab + T(63) * t10 * ab_ap * t16;
    F = (T(1) / T(693)) * in.w[1] * t3 * (t4 * t17 * ab_ap + T(63) * t10 * t16 - T(63) * t5 * t9) + (T(1) / T(693)) * t4 * t17 * in.w[0];
    const T t18 = t14 * t14;
    const T t19 = t13 * t13;
    const T t20 = T(231) * t5 * t18 * a_minus_b + T(4) * t4 * t17 * ab_ab + T(231) * t10 * ab_ap * t19;
    const T t21 = t4 * t20 * ab_ap + T(231) * t10 * t19 - T(231) * t5 * t18;
    G_ap = (T(1) / T(3003)) * t21 * in.w[1] * t3 + (T(1) / T(3003)) * t4 * t20 * in.w[0];
    G_ab = (T(1) / T(3003)) * t21 * t3 * in.w[0] + (T(1) / T(9009)) * in.w[1] * t3 * (T(13) * t4 * t17 + T(6) * t21 * t3 * ab_ap - T(3) * t4 * t20 * ap_ap);
  }
  const T g_factor = -T(13) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 43 +, 108 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2233 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = t5 * t4;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(1) / cross_cross;
    const T t14 = t11 * t11;
    const T t15 = T(8) * (T(5) * t3 * ab_ap * t8 + T(5) * t12 * t9 * a_minus_b + T(2) * ab_ab * t13 * (T(3) * t3 * ab_ap * t5 + T(4) * ab_ab * (t10 * t9 * a_minus_b + T(2) * ab_ab * (t9 * a_minus_b + t3 * ab_ap) * t13 + t3 * ab_ap * t4) * t13 + T(3) * t11 * t9 * a_minus_b)) * ab_ab * t13 + T(35) * t3 * ab_ap * t6 + T(35) * t14 * t9 * a_minus_b;
    const T t16 = t14 * t10;
    const T t17 = T(63) * t3 * ab_ap * t7 + T(2) * ab_ab * t15 * t13 + T(63) * t16 * t9 * a_minus_b;
    const T t18 = T(1) / ab_ab;
    const T t19 = T(63) * t16 * t9 - T(63) * t3 * t7 - ab_ap * t17 * t13;
    F = (T(1) / T(693)) * in.w[0] * t17 * t13 - (T(1) / T(3465)) * (T(5) * ap_ap * t17 * t13 + T(10) * t18 * t19 * ab_ap - T(11) * t15 * t13) * t18 * in.w[2] - (T(1) / T(693)) * t18 * t19 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 54 +, 151 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2941 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ab = M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = T(1) / cross_cross;
    const T t16 = t10 * t10;
    const T t17 = t16 * t9;
    const T t18 = T(63) * ab_ap * t3 * t14 + T(2) * (T(35) * ab_ap * t3 * t13 + T(8) * (T(5) * t11 * t8 * a_minus_b + T(5) * ab_ap * t3 * t6 + T(2) * (T(3) * ab_ap * t3 * t5 + T(3) * t10 * t8 * a_minus_b + T(4) * (t9 * t8 * a_minus_b + T(2) * (t8 * a_minus_b + ab_ap * t3) * t15 * ab_ab + ab_ap * t3 * t4) * t15 * ab_ab) * t15 * ab_ab) * t15 * ab_ab + T(35) * t16 * t8 * a_minus_b) * t15 * ab_ab + T(63) * t17 * t8 * a_minus_b;
    const T t19 = T(231) * ab_ap * t3 * t7 + T(231) * t12 * t8 * a_minus_b + T(4) * t18 * t15 * ab_ab;
    const T t20 = T(231) * t12 * t8 - ab_ap * t19 * t15 - T(231) * t3 * t7;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(3) * ap_ap * t19 * t15 + T(6) * ab_ap * t20 * t21 - T(13) * t18 * t15;
    G_ap = (T(1) / T(3003)) * t19 * t15 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t20 * t21 - (T(1) / T(9009)) * t22 * in.w[2] * t21;
    G_ab = -(T(1) / T(9009)) * (T(13) * (T(63) * t17 * t8 - ab_ap * t18 * t15 - T(63) * t3 * t14) * t21 + T(2) * ab_ap * t22 * t21 - T(3) * t20 * ap_ap * t21) * in.w[2] * t21 - (T(1) / T(3003)) * t20 * t21 * in.w[0] - (T(1) / T(9009)) * in.w[1] * t22 * t21;
  }
  const T g_factor = -T(13) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 58 +, 169 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2996 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[6] * in.w[2] + in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
    G_ab = M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t5 * t4;
    const T t15 = t11 * t10;
    const T t16 = T(35) * t12 * a_minus_b * t9 + T(8) * (T(5) * ab_ap * t14 * t3 + T(2) * (T(3) * t11 * a_minus_b * t9 + T(3) * ab_ap * t5 * t3 + T(4) * t8 * (ab_ap * t4 * t3 + T(2) * (ab_ap * t3 + a_minus_b * t9) * t8 * ab_ab + t10 * a_minus_b * t9) * ab_ab) * t8 * ab_ab + T(5) * t15 * a_minus_b * t9) * t8 * ab_ab + T(35) * ab_ap * t6 * t3;
    const T t17 = T(63) * t13 * a_minus_b * t9 + T(2) * t16 * t8 * ab_ab + T(63) * ab_ap * t7 * t3;
    const T t18 = T(63) * t7 * t3 + ab_ap * t8 * t17 - T(63) * t13 * t9;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(693)) * in.w[1] * t18 * t19 + (T(1) / T(693)) * in.w[0] * t8 * t17 - (T(1) / T(3465)) * (T(5) * ap_ap * t8 * t17 - T(11) * t16 * t8 - T(10) * ab_ap * t18 * t19) * in.w[2] * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    const T t22 = T(4) * t8 * t17 * ab_ab + T(231) * ab_ap * t20 * t3 + T(231) * t21 * a_minus_b * t9;
    const T t23 = T(231) * t20 * t3 + ab_ap * t22 * t8 - T(231) * t21 * t9;
    const T t24 = T(6) * ab_ap * t23 * t19 + T(13) * t8 * t17 - T(3) * t22 * ap_ap * t8;
    G_ap = (T(1) / T(9009)) * t24 * in.w[2] * t19 + (T(1) / T(3003)) * in.w[0] * t22 * t8 + (T(1) / T(3003)) * in.w[1] * t23 * t19;
    G_ab = (T(1) / T(3003)) * in.w[0] * t23 * t19 + (T(1) / T(9009)) * (T(13) * t18 * t19 + T(2) * ab_ap * t24 * t19 - T(3) * ap_ap * t23 * t19) * in.w[2] * t19 + (T(1) / T(9009)) * in.w[1] * t24 * t19;
  }
  const T g_factor = -T(13) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Returns false where segment_inverse_i13_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 58 +, 169 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i13_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / cross_cross;
    const T t14 = t5 * t4;
    const T t15 = t10 * t9;
    const T t16 = T(35) * ab_ap * t6 * t3 + T(8) * (T(5) * ab_ap * t14 * t3 + T(2) * (T(3) * ab_ap * t5 * t3 + T(3) * a_minus_b * t8 * t10 + T(4) * (a_minus_b * t8 * t9 + T(2) * t13 * (a_minus_b * t8 + ab_ap * t3) * ab_ab + ab_ap * t4 * t3) * t13 * ab_ab) * t13 * ab_ab + T(5) * a_minus_b * t8 * t15) * t13 * ab_ab + T(35) * a_minus_b * t8 * t11;
    const T t17 = T(63) * ab_ap * t7 * t3 + T(63) * a_minus_b * t8 * t12 + T(2) * t13 * ab_ab * t16;
    const T t18 = t17 * ab_ap * t13 + T(63) * t7 * t3 - T(63) * t8 * t12;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(3465)) * (T(10) * ab_ap * t18 * t19 + T(11) * t13 * t16 - T(5) * t17 * ap_ap * t13) * in.w[2] * t19 + (T(1) / T(693)) * t17 * t13 * in.w[0] + (T(1) / T(693)) * t18 * in.w[1] * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    const T t22 = T(231) * ab_ap * t20 * t3 + T(4) * t17 * t13 * ab_ab + T(231) * a_minus_b * t8 * t21;
    const T t23 = ab_ap * t13 * t22 + T(231) * t20 * t3 - T(231) * t8 * t21;
    const T t24 = T(6) * ab_ap * t19 * t23 + T(13) * t17 * t13 - T(3) * ap_ap * t13 * t22;
    G_ap = (T(1) / T(3003)) * in.w[1] * t19 * t23 + (T(1) / T(9009)) * t24 * in.w[2] * t19 + (T(1) / T(3003)) * t13 * in.w[0] * t22;
    G_ab = (T(1) / T(9009)) * in.w[1] * t24 * t19 + (T(1) / T(3003)) * t19 * in.w[0] * t23 - (T(1) / T(9009)) * (T(3) * ap_ap * t19 * t23 - T(13) * t18 * t19 - T(2) * ab_ap * t24 * t19) * in.w[2] * t19;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 48 +, 125 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2927 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[3] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t5;
    const T t13 = T(1) / cross_cross;
    const T t14 = t10 * t9;
    const T t15 = T(35) * t4 * ab_ap * t7 + T(35) * t11 * t8 * a_minus_b + T(8) * ab_ab * (T(5) * t4 * ab_ap * t12 + T(2) * (T(3) * t4 * ab_ap * t6 + T(4) * ab_ab * (t9 * t8 * a_minus_b + T(2) * ab_ab * (t4 * ab_ap + t8 * a_minus_b) * t13 + t4 * ab_ap * t5) * t13 + T(3) * t10 * t8 * a_minus_b) * ab_ab * t13 + T(5) * t14 * t8 * a_minus_b) * t13;
    const T t16 = t7 * t5;
    const T t17 = t11 * t9;
    const T t18 = T(2) * ab_ab * t15 * t13 + T(63) * t4 * ab_ap * t16 + T(63) * t17 * t8 * a_minus_b;
    const T t19 = T(63) * t17 * t8 - T(63) * t4 * t16 - t18 * ab_ap * t13;
    const T t20 = T(11) * t15 * t13 - T(5) * t18 * ap_ap * t13 - T(10) * t3 * ab_ap * t19;
    F = (T(1) / T(3465)) * t3 * t20 * in.w[2] + (T(1) / T(693)) * t18 * t13 * in.w[0] + (T(1) / T(3465)) * t3 * (T(5) * t3 * ap_ap * t19 + T(2) * t3 * t20 * ab_ap - T(11) * t3 * (T(35) * t11 * t8 - T(35) * t4 * t7 - t15 * ab_ap * t13)) * in.w[3] - (T(1) / T(693)) * t3 * in.w[1] * t19;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 60 +, 173 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3638 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ab = in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + M_flat[2] * in.w[1] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1] + M_beyond[4] * in.w[3] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = T(1) / cross_cross;
    const T t15 = t11 * t11;
    const T t16 = T(8) * (T(5) * ab_ap * t9 * t12 + T(5) * t4 * a_minus_b * t13 + T(2) * (T(3) * ab_ap * t9 * t11 + T(4) * t14 * ab_ab * (t4 * a_minus_b * t5 + ab_ap * t9 * t10 + T(2) * t14 * (t4 * a_minus_b + ab_ap * t9) * ab_ab) + T(3) * t4 * a_minus_b * t6) * t14 * ab_ab) * t14 * ab_ab + T(35) * t4 * a_minus_b * t7 + T(35) * ab_ap * t9 * t15;
    const T t17 = t15 * t10;
    const T t18 = T(63) * t4 * a_minus_b * t8 + T(2) * t16 * t14 * ab_ab + T(63) * ab_ap * t9 * t17;
    const T t19 = t13 * t13;
    const T t20 = t12 * t12;
    const T t21 = T(4) * t18 * t14 * ab_ab + T(231) * t4 * a_minus_b * t19 + T(231) * ab_ap * t9 * t20;
    const T t22 = ab_ap * t14 * t21 + T(231) * t9 * t20 - T(231) * t4 * t19;
    const T t23 = T(13) * t18 * t14 + T(6) * ab_ap * t3 * t22 - T(3) * ap_ap * t14 * t21;
    const T t24 = T(63) * t9 * t17 + ab_ap * t18 * t14 - T(63) * t4 * t8;
    const T t25 = T(3) * ap_ap * t3 * t22 - T(2) * ab_ap * t3 * t23 - T(13) * t3 * t24;
    G_ap = (T(1) / T(9009)) * in.w[2] * t3 * t23 + (T(1) / T(3003)) * t14 * in.w[0] * t21 + (T(1) / T(3003)) * t3 * t22 * in.w[1] - (T(1) / T(9009)) * t25 * in.w[3] * t3;
    G_ab = (T(1) / T(9009)) * t3 * t23 * in.w[1] + (T(1) / T(3003)) * in.w[0] * t3 * t22 - (T(1) / T(45045)) * in.w[3] * t3 * (T(5) * ap_ap * t3 * t23 + T(10) * t25 * ab_ap * t3 + T(13) * (T(5) * ap_ap * t18 * t14 - T(10) * ab_ap * t3 * t24 - T(11) * t16 * t14) * t3) - (T(1) / T(9009)) * t25 * in.w[2] * t3;
  }
  const T g_factor = -T(13) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 67 +, 200 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1337 +, 3711 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i13_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
    G_ap = in.w[3] * M_flat[8] + M_flat[6] * in.w[1] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
    G_ab = M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[3] * M_beyond[3] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0];
    G_ab = in.w[3] * M_beyond[9] + M_beyond[7] * in.w[1] + M_beyond[6] * in.w[0] + M_beyond[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t6 * t6;
    const T t11 = t9 * t8;
    const T t12 = t10 * t6;
    const T t13 = t10 * t10;
    const T t14 = t9 * t9;
    const T t15 = T(8) * (T(2) * t4 * ab_ab * (T(4) * t4 * ab_ab * (t5 * t6 * a_minus_b + T(2) * (t5 * a_minus_b + t7 * ab_ap) * t4 * ab_ab + t7 * ab_ap * t8) + T(3) * t7 * ab_ap * t9 + T(3) * t5 * t10 * a_minus_b) + T(5) * t7 * ab_ap * t11 + T(5) * t5 * t12 * a_minus_b) * t4 * ab_ab + T(35) * t5 * t13 * a_minus_b + T(35) * t7 * ab_ap * t14;
    const T t16 = t13 * t6;
    const T t17 = t14 * t8;
    const T t18 = T(2) * t15 * t4 * ab_ab + T(63) * t5 * t16 * a_minus_b + T(63) * t7 * ab_ap * t17;
    const T t19 = T(63) * t5 * t16 - t4 * t18 * ab_ap - T(63) * t7 * t17;
    const T t20 = T(11) * t15 * t4 - T(5) * t4 * t18 * ap_ap - T(10) * t3 * t19 * ab_ap;
    F = (T(1) / T(3465)) * t3 * t20 * in.w[2] + (T(1) / T(693)) * t4 * t18 * in.w[0] + (T(1) / T(3465)) * in.w[3] * t3 * (T(11) * (T(35) * t7 * t14 + t15 * t4 * ab_ap - T(35) * t5 * t13) * t3 + T(5) * t3 * t19 * ap_ap + T(2) * t3 * ab_ap * t20) - (T(1) / T(693)) * t3 * t19 * in.w[1];
    const T t21 = t11 * t11;
    const T t22 = t12 * t12;
    const T t23 = T(231) * t5 * t22 * a_minus_b + T(4) * t4 * ab_ab * t18 + T(231) * t7 * ab_ap * t21;
    const T t24 = T(231) * t7 * t21 + t4 * t23 * ab_ap - T(231) * t5 * t22;
    const T t25 = T(3) * t4 * t23 * ap_ap - T(13) * t4 * t18 - T(6) * t24 * t3 * ab_ap;
    const T t26 = T(3) * t24 * t3 * ap_ap + T(2) * t3 * ab_ap * t25 + T(13) * t3 * t19;
    G_ap = (T(1) / T(3003)) * t24 * t3 * in.w[1] + (T(1) / T(3003)) * t4 * t23 * in.w[0] - (T(1) / T(9009)) * t26 * in.w[3] * t3 - (T(1) / T(9009)) * t3 * in.w[2] * t25;
    G_ab = (T(1) / T(45045)) * (T(13) * t3 * t20 + T(5) * t3 * t25 * ap_ap - T(10) * t26 * t3 * ab_ap) * in.w[3] * t3 + (T(1) / T(3003)) * t24 * t3 * in.w[0] - (T(1) / T(9009)) * t3 * in.w[1] * t25 - (T(1) / T(9009)) * t26 * t3 * in.w[2];
  }
  const T g_factor = -T(13) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Returns false where segment_inverse_i13_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 200 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i13_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3];
    G_ap = M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
    G_ab = M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + in.w[1] * M_flat[7] + M_flat[6] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = t10 * t9;
    const T t13 = t10 * t10;
    const T t14 = T(35) * ab_ap * t7 * t4 + T(8) * (T(2) * (T(3) * ab_ap * t6 * t4 + T(4) * (a_minus_b * t8 * t9 + T(2) * t3 * ab_ab * (a_minus_b * t8 + ab_ap * t4) + ab_ap * t5 * t4) * t3 * ab_ab + T(3) * a_minus_b * t8 * t10) * t3 * ab_ab + T(5) * ab_ap * t11 * t4 + T(5) * a_minus_b * t8 * t12) * t3 * ab_ab + T(35) * a_minus_b * t8 * t13;
    const T t15 = t7 * t5;
    const T t16 = t13 * t9;
    const T t17 = T(2) * t3 * ab_ab * t14 + T(63) * ab_ap * t15 * t4 + T(63) * a_minus_b * t8 * t16;
    const T t18 = ab_ap * t3 * t17 + T(63) * t15 * t4 - T(63) * t8 * t16;
    const T t19 = T(1) / ab_ab;
    const T t20 = T(11) * t3 * t14 + T(10) * ab_ap * t18 * t19 - T(5) * ap_ap * t3 * t17;
    F = (T(1) / T(693)) * t3 * in.w[0] * t17 + (T(1) / T(3465)) * in.w[2] * t20 * t19 + (T(1) / T(693)) * in.w[1] * t18 * t19 - (T(1) / T(3465)) * (T(5) * t18 * ap_ap * t19 + T(11) * (T(35) * t8 * t13 - ab_ap * t3 * t14 - T(35) * t7 * t4) * t19 - T(2) * ab_ap * t20 * t19) * in.w[3] * t19;
    const T t21 = t12 * t12;
    const T t22 = t11 * t11;
    const T t23 = T(4) * t3 * t17 * ab_ab + T(231) * a_minus_b * t8 * t21 + T(231) * ab_ap * t22 * t4;
    const T t24 = t23 * ab_ap * t3 + T(231) * t22 * t4 - T(231) * t8 * t21;
    const T t25 = T(13) * t3 * t17 + T(6) * ab_ap * t19 * t24 - T(3) * t23 * ap_ap * t3;
    const T t26 = T(13) * t18 * t19 + T(2) * t25 * ab_ap * t19 - T(3) * ap_ap * t19 * t24;
    G_ap = (T(1) / T(3003)) * t23 * t3 * in.w[0] + (T(1) / T(9009)) * t25 * in.w[2] * t19 + (T(1) / T(9009)) * t26 * in.w[3] * t19 + (T(1) / T(3003)) * in.w[1] * t19 * t24;
    G_ab = (T(1) / T(9009)) * in.w[1] * t25 * t19 + (T(1) / T(45045)) * (T(13) * t20 * t19 + T(10) * t26 * ab_ap * t19 - T(5) * t25 * ap_ap * t19) * in.w[3] * t19 + (T(1) / T(9009)) * t26 * in.w[2] * t19 + (T(1) / T(3003)) * in.w[0] * t19 * t24;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 40 +, 85 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 856 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t7 * t6;
    const T t16 = t15 * t15;
    const T t17 = t14 * t14;
    F = (T(1) / T(15360)) * in.w[0] * t5 * (T(11) * t5 * ab_ab * (T(128) * a_minus_b * t9 + T(128) * t13 * ab_ap + T(3) * t5 * (T(7) * t5 * ab_ab * (T(8) * t14 * ab_ap + T(8) * a_minus_b * t15 + T(5) * t5 * ab_ab * (T(2) * t11 * ab_ap + T(3) * t5 * ab_ab * (a_minus_b * t6 + J2 * ab_ab + t10 * ab_ap) + T(2) * a_minus_b * t7)) + T(48) * t12 * ab_ap + T(48) * a_minus_b * t8) * ab_ab) + T(1280) * a_minus_b * t16 + T(1280) * t17 * ab_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 47 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1558 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = t7 * t7;
    const T t12 = t11 * t6;
    const T t13 = T(1) / ap_ap;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = t14 * t14;
    const T t17 = t16 * t13;
    const T t18 = t15 * t15;
    const T t19 = t18 * t13;
    const T t20 = T(15360) * a_minus_b * t10 + T(13) * t5 * ab_ab * (T(1280) * a_minus_b * t9 + T(11) * t5 * (T(128) * a_minus_b * t12 + T(3) * t5 * ab_ab * (T(48) * a_minus_b * t11 + T(7) * t5 * ab_ab * (T(8) * a_minus_b * t8 + T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (ab_ap * t13 + ab_ab * J2 + a_minus_b * t6) + T(2) * a_minus_b * t7 + T(2) * ab_ap * t14) + T(8) * ab_ap * t15) + T(48) * ab_ap * t16) + T(128) * ab_ap * t17) * ab_ab + T(1280) * ab_ap * t18) + T(15360) * ab_ap * t19;
    G_ap = (T(1) / T(215040)) * in.w[0] * t5 * t20;
    G_ab = (T(1) / T(215040)) * (t5 * ab_ap * t20 + T(15360) * t19 - T(15360) * t10) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(14) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 47 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1584 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t7 * t7;
    const T t15 = t14 * t6;
    const T t16 = t11 * t10;
    const T t17 = t16 * t16;
    const T t18 = T(1280) * ab_ap * t9 + T(11) * (T(128) * t13 * a_minus_b + T(128) * ab_ap * t15 + T(3) * t5 * ab_ab * (T(48) * ab_ap * t14 + T(48) * t12 * a_minus_b + T(7) * t5 * ab_ab * (T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (t10 * a_minus_b + ab_ap * t6 + ab_ab * J2) + T(2) * ab_ap * t7 + T(2) * t11 * a_minus_b) + T(8) * ab_ap * t8 + T(8) * t16 * a_minus_b))) * t5 * ab_ab + T(1280) * t17 * a_minus_b;
    F = (T(1) / T(15360)) * in.w[0] * t5 * t18;
    const T t19 = t9 * t6;
    const T t20 = t17 * t10;
    const T t21 = T(15360) * ab_ap * t19 + T(15360) * t20 * a_minus_b + T(13) * t5 * ab_ab * t18;
    G_ap = (T(1) / T(215040)) * in.w[0] * t5 * t21;
    G_ab = -(T(1) / T(215040)) * in.w[0] * (T(15360) * t20 - t5 * t21 * ab_ap - T(15360) * t19) / ab_ab;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Returns false where segment_inverse_i14_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 47 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i14_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t7 * t7;
    const T t15 = t14 * t6;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = T(1280) * t9 * a_minus_b + T(1280) * ab_ap * t13 + T(11) * t5 * ab_ab * (T(128) * t15 * a_minus_b + T(3) * t5 * ab_ab * (T(48) * t14 * a_minus_b + T(7) * t5 * ab_ab * (T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (t6 * a_minus_b + ab_ap * t10 + ab_ab * J2) + T(2) * ab_ap * t11 + T(2) * t7 * a_minus_b) + T(8) * t8 * a_minus_b + T(8) * ab_ap * t12) + T(48) * ab_ap * t16) + T(128) * ab_ap * t17);
    F = (T(1) / T(15360)) * in.w[0] * t5 * t18;
    const T t19 = t9 * t6;
    const T t20 = t13 * t10;
    const T t21 = T(15360) * t19 * a_minus_b + T(13) * t5 * ab_ab * t18 + T(15360) * ab_ap * t20;
    G_ap = (T(1) / T(215040)) * in.w[0] * t5 * t21;
    G_ab = (T(1) / T(215040)) * in.w[0] * (T(15360) * t20 + t5 * t21 * ab_ap - T(15360) * t19) / ab_ab;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 43 +, 91 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1546 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t7;
    const T t14 = t11 * t11;
    const T t15 = t13 * t6;
    const T t16 = t14 * t10;
    const T t17 = t12 * t12;
    const T t18 = T(1280) * ab_ap * t9 + T(11) * t5 * (T(3) * t5 * ab_ab * (T(7) * t5 * ab_ab * (T(8) * t12 * a_minus_b + T(8) * ab_ap * t8 + T(5) * t5 * ab_ab * (T(2) * t11 * a_minus_b + T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t6 + t10 * a_minus_b) + T(2) * ab_ap * t7)) + T(48) * ab_ap * t13 + T(48) * t14 * a_minus_b) + T(128) * ab_ap * t15 + T(128) * t16 * a_minus_b) * ab_ab + T(1280) * t17 * a_minus_b;
    F = (T(1) / T(15360)) * t5 * t18 * in.w[0] + (T(1) / T(15360)) * (t5 * ab_ap * t18 + T(1280) * t9 - T(1280) * t17) * in.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 51 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2251 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t10 * t7;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t16 * t12;
    const T t18 = t8 * t8;
    const T t19 = t18 * t7;
    const T t20 = T(1280) * ab_ap * t10 + T(1280) * a_minus_b * t15 + T(11) * t6 * (T(128) * a_minus_b * t17 + T(128) * ab_ap * t19 + T(3) * t6 * ab_ab * (T(7) * t6 * ab_ab * (T(8) * ab_ap * t9 + T(5) * t6 * ab_ab * (T(2) * a_minus_b * t13 + T(2) * ab_ap * t8 + T(3) * t6 * ab_ab * (ab_ab * J2 + ab_ap * t7 + a_minus_b * t12)) + T(8) * a_minus_b * t14) + T(48) * a_minus_b * t16 + T(48) * ab_ap * t18)) * ab_ab;
    const T t21 = t15 * t12;
    const T t22 = T(15360) * ab_ap * t11 + T(13) * t6 * ab_ab * t20 + T(15360) * a_minus_b * t21;
    const T t23 = t6 * ab_ap * t22 + T(15360) * t11 - T(15360) * t21;
    G_ap = (T(1) / T(215040)) * t5 * t23 * in.w[1] + (T(1) / T(215040)) * t6 * t22 * in.w[0];
    G_ab = (T(1) / T(215040)) * t5 * t23 * in.w[0] + (T(1) / T(215040)) * t5 * (T(2) * t5 * ab_ap * t23 + T(14) * t6 * t20 - t6 * t22 * ap_ap) * in.w[1];
  }
  const T g_factor = -T(14) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 54 +, 134 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2291 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t13 * t12;
    const T t16 = t14 * t12;
    const T t17 = t15 * t15;
    const T t18 = T(1280) * ab_ap * t9 + T(11) * t5 * ab_ab * (T(128) * ab_ap * t11 + T(3) * t5 * (T(48) * ab_ap * t10 + T(48) * t14 * a_minus_b + T(7) * t5 * (T(8) * ab_ap * t8 + T(8) * t15 * a_minus_b + T(5) * t5 * ab_ab * (T(2) * t13 * a_minus_b + T(3) * t5 * ab_ab * (ab_ap * t6 + t12 * a_minus_b + ab_ab * J2) + T(2) * ab_ap * t7)) * ab_ab) * ab_ab + T(128) * t16 * a_minus_b) + T(1280) * t17 * a_minus_b;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * t5 * in.w[0] * t18 + (T(1) / T(15360)) * t19 * (t5 * ab_ap * t18 + T(1280) * t9 - T(1280) * t17) * in.w[1];
    const T t20 = t9 * t6;
    const T t21 = t17 * t12;
    const T t22 = T(15360) * ab_ap * t20 + T(13) * t5 * ab_ab * t18 + T(15360) * t21 * a_minus_b;
    const T t23 = t5 * t22 * ab_ap + T(15360) * t20 - T(15360) * t21;
    G_ap = (T(1) / T(215040)) * t19 * t23 * in.w[1] + (T(1) / T(215040)) * t5 * t22 * in.w[0];
    G_ab = (T(1) / T(215040)) * t19 * t23 * in.w[0] - (T(1) / T(215040)) * (t5 * t22 * ap_ap - T(2) * t19 * t23 * ab_ap - T(14) * t5 * t18) * t19 * in.w[1];
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Returns false where segment_inverse_i14_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 54 +, 134 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i14_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t7 * t6;
    const T t15 = t12 * t10;
    const T t16 = t14 * t14;
    const T t17 = t13 * t13;
    const T t18 = T(11) * t5 * ab_ab * (T(128) * t9 * ab_ap + T(3) * t5 * ab_ab * (T(48) * t8 * ab_ap + T(48) * t12 * a_minus_b + T(7) * t5 * ab_ab * (T(8) * t13 * a_minus_b + T(8) * t14 * ab_ap + T(5) * (T(3) * t5 * ab_ab * (ab_ab * J2 + t6 * ab_ap + t10 * a_minus_b) + T(2) * t7 * ab_ap + T(2) * t11 * a_minus_b) * t5 * ab_ab)) + T(128) * t15 * a_minus_b) + T(1280) * t16 * ab_ap + T(1280) * t17 * a_minus_b;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * in.w[0] * t18 * t5 - (T(1) / T(15360)) * in.w[1] * t19 * (T(1280) * t17 - t18 * t5 * ab_ap - T(1280) * t16);
    const T t20 = t17 * t10;
    const T t21 = t16 * t6;
    const T t22 = T(13) * t18 * t5 * ab_ab + T(15360) * t20 * a_minus_b + T(15360) * t21 * ab_ap;
    const T t23 = T(15360) * t20 - T(15360) * t21 - t5 * ab_ap * t22;
    G_ap = (T(1) / T(215040)) * in.w[0] * t5 * t22 - (T(1) / T(215040)) * in.w[1] * t19 * t23;
    G_ab = (T(1) / T(215040)) * (T(14) * t18 * t5 - ap_ap * t5 * t22 - T(2) * t19 * t23 * ab_ap) * in.w[1] * t19 - (T(1) / T(215040)) * in.w[0] * t19 * t23;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 46 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2238 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t12 * t12;
    const T t16 = t15 * t11;
    const T t17 = t7 * t7;
    const T t18 = t17 * t6;
    const T t19 = T(128) * t16 * a_minus_b + T(128) * ab_ap * t18 + T(3) * t10 * ab_ab * (T(48) * t15 * a_minus_b + T(7) * t10 * ab_ab * (T(8) * ab_ap * t8 + T(5) * t10 * ab_ab * (T(2) * ab_ap * t7 + T(2) * t12 * a_minus_b + T(3) * (t11 * a_minus_b + ab_ab * J2 + ab_ap * t6) * t10 * ab_ab) + T(8) * t13 * a_minus_b) + T(48) * ab_ap * t17);
    const T t20 = T(1280) * t14 * a_minus_b + T(1280) * ab_ap * t9 + T(11) * t10 * ab_ab * t19;
    const T t21 = T(1280) * t9 + t10 * ab_ap * t20 - T(1280) * t14;
    F = (T(1) / T(15360)) * t5 * t21 * in.w[1] + (T(1) / T(15360)) * t10 * in.w[0] * t20 - (T(1) / T(15360)) * t5 * (t10 * ap_ap * t20 - T(12) * t10 * t19 - T(2) * t5 * t21 * ab_ap) * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 57 +, 140 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2946 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ab = M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ab = in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = T(1) / cross_cross;
    const T t15 = t6 * t6;
    const T t16 = t15 * t5;
    const T t17 = t11 * t11;
    const T t18 = t17 * t10;
    const T t19 = T(1280) * a_minus_b * t8 + T(1280) * ab_ap * t13 + T(11) * t14 * (T(128) * a_minus_b * t16 + T(128) * ab_ap * t18 + T(3) * (T(48) * a_minus_b * t15 + T(48) * ab_ap * t17 + T(7) * (T(8) * ab_ap * t12 + T(8) * a_minus_b * t7 + T(5) * t14 * (T(2) * ab_ap * t11 + T(3) * (a_minus_b * t5 + ab_ap * t10 + J2 * ab_ab) * t14 * ab_ab + T(2) * a_minus_b * t6) * ab_ab) * t14 * ab_ab) * t14 * ab_ab) * ab_ab;
    const T t20 = t13 * t10;
    const T t21 = T(15360) * a_minus_b * t9 + T(13) * t19 * t14 * ab_ab + T(15360) * ab_ap * t20;
    const T t22 = T(15360) * t20 + ab_ap * t21 * t14 - T(15360) * t9;
    const T t23 = T(1) / ab_ab;
    const T t24 = t21 * ap_ap * t14 - T(2) * ab_ap * t22 * t23 - T(14) * t19 * t14;
    G_ap = (T(1) / T(215040)) * in.w[0] * t21 * t14 + (T(1) / T(215040)) * t22 * in.w[1] * t23 - (T(1) / T(215040)) * t24 * in.w[2] * t23;
    G_ab = (T(1) / T(215040)) * in.w[0] * t22 * t23 - (T(1) / T(215040)) * t24 * in.w[1] * t23 - (T(1) / T(215040)) * (T(2) * t24 * ab_ap * t23 + t22 * ap_ap * t23 - T(14) * (T(1280) * t13 + t19 * ab_ap * t14 - T(1280) * t8) * t23) * in.w[2] * t23;
  }
  const T g_factor = -T(14) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 61 +, 157 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 3002 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ap = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2];
    G_ab = M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t7 * t7;
    const T t14 = T(1) / cross_cross;
    const T t15 = t11 * t10;
    const T t16 = t13 * t6;
    const T t17 = t12 * t10;
    const T t18 = T(3) * (T(48) * t12 * a_minus_b + T(48) * ab_ap * t13 + T(7) * (T(5) * (T(3) * (ab_ap * t6 + J2 * ab_ab + t10 * a_minus_b) * t14 * ab_ab + T(2) * t11 * a_minus_b + T(2) * ab_ap * t7) * t14 * ab_ab + T(8) * t15 * a_minus_b + T(8) * ab_ap * t8) * t14 * ab_ab) * t14 * ab_ab + T(128) * ab_ap * t16 + T(128) * t17 * a_minus_b;
    const T t19 = t15 * t15;
    const T t20 = T(11) * t18 * t14 * ab_ab + T(1280) * ab_ap * t9 + T(1280) * t19 * a_minus_b;
    const T t21 = T(1280) * t9 + ab_ap * t20 * t14 - T(1280) * t19;
    F = (T(1) / T(15360)) * in.w[2] * t5 * (T(2) * ab_ap * t21 * t5 + T(12) * t18 * t14 - ap_ap * t20 * t14) + (T(1) / T(15360)) * in.w[0] * t20 * t14 + (T(1) / T(15360)) * in.w[1] * t21 * t5;
    const T t22 = t9 * t6;
    const T t23 = t19 * t10;
    const T t24 = T(13) * t20 * t14 * ab_ab + T(15360) * ab_ap * t22 + T(15360) * t23 * a_minus_b;
    const T t25 = T(15360) * t22 + ab_ap * t24 * t14 - T(15360) * t23;
    const T t26 = ap_ap * t24 * t14 - T(2) * ab_ap * t25 * t5 - T(14) * t20 * t14;
    G_ap = (T(1) / T(215040)) * t25 * in.w[1] * t5 + (T(1) / T(215040)) * in.w[0] * t24 * t14 - (T(1) / T(215040)) * t26 * in.w[2] * t5;
    G_ab = (T(1) / T(215040)) * in.w[0] * t25 * t5 - (T(1) / T(215040)) * (t25 * ap_ap * t5 + T(2) * ab_ap * t26 * t5 - T(14) * t21 * t5) * in.w[2] * t5 - (T(1) / T(215040)) * in.w[1] * t26 * t5;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Returns false where segment_inverse_i14_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 157 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i14_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + M_flat[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = t12 * t9;
    const T t15 = t13 * t6;
    const T t16 = T(3) * ab_ab * t5 * (T(7) * ab_ab * t5 * (T(8) * t8 * a_minus_b + T(8) * ab_ap * t11 + T(5) * (T(2) * t7 * a_minus_b + T(3) * (J2 * ab_ab + ab_ap * t9 + t6 * a_minus_b) * ab_ab * t5 + T(2) * ab_ap * t10) * ab_ab * t5) + T(48) * ab_ap * t12 + T(48) * t13 * a_minus_b) + T(128) * ab_ap * t14 + T(128) * t15 * a_minus_b;
    const T t17 = t8 * t8;
    const T t18 = t11 * t11;
    const T t19 = T(11) * t16 * ab_ab * t5 + T(1280) * t17 * a_minus_b + T(1280) * ab_ap * t18;
    const T t20 = ab_ap * t19 * t5 + T(1280) * t18 - T(1280) * t17;
    const T t21 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * in.w[0] * t19 * t5 + (T(1) / T(15360)) * in.w[2] * (T(2) * ab_ap * t20 * t21 + T(12) * t16 * t5 - t19 * ap_ap * t5) * t21 + (T(1) / T(15360)) * t20 * in.w[1] * t21;
    const T t22 = t17 * t6;
    const T t23 = t18 * t9;
    const T t24 = T(13) * t19 * ab_ab * t5 + T(15360) * t22 * a_minus_b + T(15360) * ab_ap * t23;
    const T t25 = T(15360) * t22 - t24 * ab_ap * t5 - T(15360) * t23;
    const T t26 = t24 * ap_ap * t5 + T(2) * ab_ap * t21 * t25 - T(14) * t19 * t5;
    G_ap = (T(1) / T(215040)) * t24 * in.w[0] * t5 - (T(1) / T(215040)) * in.w[2] * t21 * t26 - (T(1) / T(215040)) * in.w[1] * t21 * t25;
    G_ab = (T(1) / T(215040)) * in.w[2] * t21 * (T(14) * t20 * t21 + ap_ap * t21 * t25 - T(2) * ab_ap * t21 * t26) - (T(1) / T(215040)) * in.w[1] * t21 * t26 - (T(1) / T(215040)) * in.w[0] * t21 * t25;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 51 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2932 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = t13 * t5;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(128) * ab_ap * t14 + T(128) * t16 * a_minus_b + T(3) * (T(48) * ab_ap * t13 + T(48) * t15 * a_minus_b + T(7) * ab_ab * (T(5) * ab_ab * (T(2) * ab_ap * t6 + T(3) * (t9 * a_minus_b + ab_ab * J2 + ab_ap * t5) * ab_ab * t17 + T(2) * t10 * a_minus_b) * t17 + T(8) * ab_ap * t7 + T(8) * t11 * a_minus_b) * t17) * ab_ab * t17;
    const T t19 = T(1280) * ab_ap * t8 + T(1280) * t12 * a_minus_b + T(11) * ab_ab * t18 * t17;
    const T t20 = T(1) / ab_ab;
    const T t21 = T(1280) * t12 - T(1280) * t8 - ab_ap * t19 * t17;
    const T t22 = t19 * ap_ap * t17 + T(2) * t20 * ab_ap * t21 - T(12) * t18 * t17;
    F = (T(1) / T(15360)) * in.w[0] * t19 * t17 - (T(1) / T(15360)) * t20 * (T(2) * t20 * ab_ap * t22 - T(12) * t20 * (ab_ap * t18 * t17 + T(128) * t14 - T(128) * t16) - t20 * t21 * ap_ap) * in.w[3] - (T(1) / T(15360)) * t20 * in.w[2] * t22 - (T(1) / T(15360)) * t20 * in.w[1] * t21;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 63 +, 160 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3643 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[3] * in.w[3];
    G_ab = in.w[0] * M_flat[1] + M_flat[2] * in.w[1] + in.w[2] * M_flat[3] + in.w[3] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[2] + M_beyond[2] * in.w[1] + M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / cross_cross;
    const T t10 = t6 * t6;
    const T t11 = t10 * t5;
    const T t12 = T(1) / ap_ap;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t15 * t12;
    const T t17 = T(128) * a_minus_b * t11 + T(3) * (T(7) * (T(5) * (T(3) * t9 * (a_minus_b * t5 + ab_ap * t12 + ab_ab * J2) * ab_ab + T(2) * ab_ap * t13 + T(2) * a_minus_b * t6) * t9 * ab_ab + T(8) * ab_ap * t14 + T(8) * a_minus_b * t7) * t9 * ab_ab + T(48) * a_minus_b * t10 + T(48) * ab_ap * t15) * t9 * ab_ab + T(128) * ab_ap * t16;
    const T t18 = t14 * t14;
    const T t19 = T(1280) * a_minus_b * t8 + T(11) * t9 * ab_ab * t17 + T(1280) * ab_ap * t18;
    const T t20 = t8 * t5;
    const T t21 = t18 * t12;
    const T t22 = T(13) * t19 * t9 * ab_ab + T(15360) * a_minus_b * t20 + T(15360) * ab_ap * t21;
    const T t23 = ab_ap * t22 * t9 + T(15360) * t21 - T(15360) * t20;
    const T t24 = T(1) / ab_ab;
    const T t25 = t22 * ap_ap * t9 - T(2) * ab_ap * t23 * t24 - T(14) * t19 * t9;
    const T t26 = ab_ap * t19 * t9 + T(1280) * t18 - T(1280) * t8;
    const T t27 = ap_ap * t23 * t24 + T(2) * ab_ap * t25 * t24 - T(14) * t26 * t24;
    G_ap = (T(1) / T(215040)) * t22 * t9 * in.w[0] + (T(1) / T(215040)) * t23 * t24 * in.w[1] - (T(1) / T(215040)) * in.w[3] * t27 * t24 - (T(1) / T(215040)) * in.w[2] * t25 * t24;
    G_ab = (T(1) / T(215040)) * t23 * in.w[0] * t24 + (T(1) / T(215040)) * (ap_ap * t25 * t24 + T(14) * (T(2) * ab_ap * t26 * t24 + T(12) * t9 * t17 - t19 * ap_ap * t9) * t24 - T(2) * ab_ap * t27 * t24) * in.w[3] * t24 - (T(1) / T(215040)) * t25 * t24 * in.w[1] - (T(1) / T(215040)) * in.w[2] * t27 * t24;
  }
  const T g_factor = -T(14) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 70 +, 184 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3717 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i14_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ap = M_flat[8] * in.w[3] + in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
    G_ab = M_flat[7] * in.w[1] + M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[5] * in.w[0] + M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2] + in.w[1] * M_beyond[6];
    G_ab = in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9] + in.w[2] * M_beyond[8] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t6 * t5;
    const T t14 = T(1) / cross_cross;
    const T t15 = t10 * t9;
    const T t16 = T(128) * ab_ap * t8 + T(128) * t12 * a_minus_b + T(3) * (T(48) * ab_ap * t7 + T(48) * t11 * a_minus_b + T(7) * (T(8) * ab_ap * t13 + T(5) * (T(2) * ab_ap * t6 + T(3) * (J2 * ab_ab + t9 * a_minus_b + ab_ap * t5) * t14 * ab_ab + T(2) * t10 * a_minus_b) * t14 * ab_ab + T(8) * t15 * a_minus_b) * t14 * ab_ab) * t14 * ab_ab;
    const T t17 = t15 * t15;
    const T t18 = t13 * t13;
    const T t19 = T(1280) * t17 * a_minus_b + T(1280) * ab_ap * t18 + T(11) * t16 * t14 * ab_ab;
    const T t20 = T(1280) * t17 - ab_ap * t14 * t19 - T(1280) * t18;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(12) * t16 * t14 - ap_ap * t14 * t19 - T(2) * ab_ap * t20 * t21;
    F = (T(1) / T(15360)) * t22 * in.w[2] * t21 + (T(1) / T(15360)) * (t20 * ap_ap * t21 + T(2) * t22 * ab_ap * t21 - T(12) * (T(128) * t12 - ab_ap * t16 * t14 - T(128) * t8) * t21) * in.w[3] * t21 + (T(1) / T(15360)) * t14 * in.w[0] * t19 - (T(1) / T(15360)) * in.w[1] * t20 * t21;
    const T t23 = t17 * t9;
    const T t24 = t18 * t5;
    const T t25 = T(15360) * t23 * a_minus_b + T(15360) * ab_ap * t24 + T(13) * t14 * t19 * ab_ab;
    const T t26 = T(15360) * t23 - ab_ap * t25 * t14 - T(15360) * t24;
    const T t27 = ap_ap * t25 * t14 + T(2) * ab_ap * t26 * t21 - T(14) * t14 * t19;
    const T t28 = t26 * ap_ap * t21 - T(14) * t20 * t21 - T(2) * t27 * ab_ap * t21;
    G_ap = (T(1) / T(215040)) * t25 * t14 * in.w[0] + (T(1) / T(215040)) * in.w[3] * t21 * t28 - (T(1) / T(215040)) * t27 * in.w[2] * t21 - (T(1) / T(215040)) * in.w[1] * t26 * t21;
    G_ab = (T(1) / T(215040)) * in.w[2] * t21 * t28 + (T(1) / T(215040)) * (T(14) * t22 * t21 + t27 * ap_ap * t21 + T(2) * ab_ap * t21 * t28) * in.w[3] * t21 - (T(1) / T(215040)) * t26 * in.w[0] * t21 - (T(1) / T(215040)) * in.w[1] * t27 * t21;
  }
  const T g_factor = -T(14) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Returns false where segment_inverse_i14_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 70 +, 184 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i14_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
    G_ap = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + in.w[3] * M_flat[8] + in.w[0] * M_flat[5];
    G_ab = M_flat[7] * in.w[1] + in.w[3] * M_flat[9] + in.w[0] * M_flat[6] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = T(1) / cross_cross;
    const T t11 = t7 * t6;
    const T t12 = t9 * t8;
    const T t13 = t9 * t9;
    const T t14 = t7 * t7;
    const T t15 = t14 * t6;
    const T t16 = t13 * t8;
    const T t17 = T(3) * ab_ab * (T(7) * ab_ab * (T(5) * ab_ab * (T(2) * t7 * a_minus_b + T(2) * ab_ap * t9 + T(3) * ab_ab * t10 * (ab_ap * t8 + t6 * a_minus_b + ab_ab * J2)) * t10 + T(8) * t11 * a_minus_b + T(8) * ab_ap * t12) * t10 + T(48) * ab_ap * t13 + T(48) * t14 * a_minus_b) * t10 + T(128) * t15 * a_minus_b + T(128) * ab_ap * t16;
    const T t18 = t11 * t11;
    const T t19 = t12 * t12;
    const T t20 = T(11) * ab_ab * t17 * t10 + T(1280) * t18 * a_minus_b + T(1280) * ab_ap * t19;
    const T t21 = t20 * ab_ap * t10 + T(1280) * t19 - T(1280) * t18;
    const T t22 = T(12) * t17 * t10 + T(2) * t5 * ab_ap * t21 - t20 * ap_ap * t10;
    F = (T(1) / T(15360)) * t5 * in.w[2] * t22 + (T(1) / T(15360)) * t20 * in.w[0] * t10 + (T(1) / T(15360)) * t5 * in.w[1] * t21 - (T(1) / T(15360)) * in.w[3] * t5 * (t5 * t21 * ap_ap - T(12) * t5 * (t17 * ab_ap * t10 + T(128) * t16 - T(128) * t15) - T(2) * t5 * ab_ap * t22);
    const T t23 = t18 * t6;
    const T t24 = t19 * t8;
    const T t25 = T(13) * t20 * ab_ab * t10 + T(15360) * t23 * a_minus_b + T(15360) * ab_ap * t24;
    const T t26 = T(15360) * t23 - ab_ap * t25 * t10 - T(15360) * t24;
    const T t27 = t25 * ap_ap * t10 + T(2) * t5 * ab_ap * t26 - T(14) * t20 * t10;
    const T t28 = t5 * t26 * ap_ap + T(14) * t5 * t21 - T(2) * t5 * t27 * ab_ap;
    G_ap = (T(1) / T(215040)) * in.w[0] * t25 * t10 + (T(1) / T(215040)) * in.w[3] * t5 * t28 - (T(1) / T(215040)) * t5 * in.w[1] * t26 - (T(1) / T(215040)) * t5 * t27 * in.w[2];
    G_ab = (T(1) / T(215040)) * t5 * t28 * in.w[2] + (T(1) / T(215040)) * in.w[3] * t5 * (t5 * t27 * ap_ap + T(14) * t5 * t22 + T(2) * t5 * t28 * ab_ap) - (T(1) / T(215040)) * in.w[0] * t5 * t26 - (T(1) / T(215040)) * t5 * in.w[1] * t27;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 39 +, 99 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 373 +, 854 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = t13 * t13;
    const T t17 = t12 * t12;
    F = (T(1) / T(3003)) * in.w[0] * (T(4) * t3 * ab_ab * (T(63) * t8 * t4 * ab_ap + T(2) * (T(35) * t7 * t4 * ab_ap + T(8) * (T(2) * (T(4) * t3 * ab_ab * (t5 * t4 * ab_ap + a_minus_b * t10 * t9 + T(2) * t3 * ab_ab * (a_minus_b * t9 + t4 * ab_ap)) + T(3) * a_minus_b * t11 * t9 + T(3) * t6 * t4 * ab_ap) * t3 * ab_ab + T(5) * a_minus_b * t12 * t9 + T(5) * t13 * t4 * ab_ap) * t3 * ab_ab + T(35) * a_minus_b * t14 * t9) * t3 * ab_ab + T(63) * a_minus_b * t15 * t9) + T(231) * t16 * t4 * ab_ap + T(231) * a_minus_b * t17 * t9) * t3;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 46 +, 127 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1554 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = t6 * t6;
    const T t17 = t12 * t12;
    const T t18 = t16 * t5;
    const T t19 = t17 * t11;
    const T t20 = T(429) * ab_ap * t4 * t9 + T(429) * t10 * a_minus_b * t15 + T(2) * t3 * ab_ab * (T(231) * ab_ap * t4 * t8 + T(231) * t10 * a_minus_b * t14 + T(4) * (T(2) * t3 * ab_ab * (T(35) * ab_ap * t4 * t16 + T(35) * t10 * a_minus_b * t17 + T(8) * t3 * ab_ab * (T(5) * ab_ap * t4 * t7 + T(2) * t3 * ab_ab * (T(3) * ab_ap * t4 * t6 + T(4) * t3 * ab_ab * (t10 * a_minus_b * t11 + T(2) * t3 * ab_ab * (t10 * a_minus_b + ab_ap * t4) + ab_ap * t4 * t5) + T(3) * t10 * a_minus_b * t12) + T(5) * t10 * a_minus_b * t13)) + T(63) * ab_ap * t4 * t18 + T(63) * t10 * a_minus_b * t19) * t3 * ab_ab);
    G_ap = (T(1) / T(6435)) * in.w[0] * t3 * t20;
    G_ab = (T(1) / T(6435)) * in.w[0] * (t3 * ab_ap * t20 + T(429) * t4 * t9 - T(429) * t10 * t15) / ab_ab;
  }
  const T g_factor = -T(15) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 46 +, 131 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 614 +, 1580 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t6 * t5;
    const T t15 = t11 * t10;
    const T t16 = t14 * t14;
    const T t17 = t15 * t15;
    const T t18 = T(4) * t3 * ab_ab * (T(63) * t8 * t4 * ab_ap + T(63) * t9 * t13 * a_minus_b + T(2) * t3 * ab_ab * (T(35) * t9 * t12 * a_minus_b + T(35) * t7 * t4 * ab_ap + T(8) * t3 * (T(2) * t3 * ab_ab * (T(3) * t9 * t11 * a_minus_b + T(4) * t3 * ab_ab * (t5 * t4 * ab_ap + T(2) * t3 * ab_ab * (t4 * ab_ap + t9 * a_minus_b) + t9 * t10 * a_minus_b) + T(3) * t6 * t4 * ab_ap) + T(5) * t14 * t4 * ab_ap + T(5) * t9 * t15 * a_minus_b) * ab_ab)) + T(231) * t16 * t4 * ab_ap + T(231) * t9 * t17 * a_minus_b;
    F = (T(1) / T(3003)) * t18 * in.w[0] * t3;
    const T t19 = t16 * t5;
    const T t20 = t17 * t10;
    const T t21 = T(429) * t19 * t4 * ab_ap + T(2) * t18 * t3 * ab_ab + T(429) * t9 * t20 * a_minus_b;
    G_ap = (T(1) / T(6435)) * in.w[0] * t3 * t21;
    G_ab = -(T(1) / T(6435)) * in.w[0] * (T(429) * t9 * t20 - t3 * t21 * ab_ap - T(429) * t19 * t4) / ab_ab;
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Returns false where segment_inverse_i15_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 46 +, 131 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i15_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t6 * t6;
    const T t15 = t12 * t10;
    const T t16 = t14 * t5;
    const T t17 = t13 * t13;
    const T t18 = T(231) * ab_ap * t8 * t4 + T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (T(35) * t9 * t12 * a_minus_b + T(8) * t3 * ab_ab * (T(5) * ab_ap * t7 * t4 + T(5) * t9 * t13 * a_minus_b + T(2) * t3 * ab_ab * (T(4) * t3 * ab_ab * (T(2) * t3 * (ab_ap * t4 + t9 * a_minus_b) * ab_ab + ab_ap * t5 * t4 + t9 * t10 * a_minus_b) + T(3) * t9 * t11 * a_minus_b + T(3) * ab_ap * t6 * t4)) + T(35) * ab_ap * t14 * t4) + T(63) * t9 * t15 * a_minus_b + T(63) * ab_ap * t16 * t4) + T(231) * t9 * t17 * a_minus_b;
    F = (T(1) / T(3003)) * in.w[0] * t3 * t18;
    const T t19 = t8 * t5;
    const T t20 = t17 * t10;
    const T t21 = T(429) * ab_ap * t19 * t4 + T(2) * t3 * ab_ab * t18 + T(429) * t9 * t20 * a_minus_b;
    G_ap = (T(1) / T(6435)) * in.w[0] * t21 * t3;
    G_ab = -(T(1) / T(6435)) * in.w[0] * (T(429) * t9 * t20 - t21 * t3 * ab_ap - T(429) * t19 * t4) / ab_ab;
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 42 +, 107 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 604 +, 1544 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t5;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t15 * t12;
    const T t17 = t14 * t14;
    const T t18 = T(231) * t4 * ab_ap * t8 + T(4) * t3 * ab_ab * (T(63) * t4 * ab_ap * t10 + T(2) * t3 * ab_ab * (T(35) * t4 * ab_ap * t9 + T(8) * t3 * ab_ab * (T(5) * t4 * ab_ap * t7 + T(5) * a_minus_b * t14 * t11 + T(2) * t3 * ab_ab * (T(3) * t4 * ab_ap * t6 + T(3) * a_minus_b * t13 * t11 + T(4) * t3 * (T(2) * t3 * ab_ab * (t4 * ab_ap + a_minus_b * t11) + t4 * ab_ap * t5 + a_minus_b * t12 * t11) * ab_ab)) + T(35) * a_minus_b * t15 * t11) + T(63) * a_minus_b * t16 * t11) + T(231) * a_minus_b * t17 * t11;
    F = (T(1) / T(3003)) * in.w[1] * (t3 * t18 * ab_ap + T(231) * t4 * t8 - T(231) * t17 * t11) / ab_ab + (T(1) / T(3003)) * t3 * t18 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 50 +, 142 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2247 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = t6 * t6;
    const T t11 = t10 * t5;
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t13;
    const T t17 = t14 * t13;
    const T t18 = t17 * t17;
    const T t19 = T(4) * t3 * ab_ab * (T(63) * ab_ap * t4 * t11 + T(63) * a_minus_b * t16 * t12 + T(2) * t3 * ab_ab * (T(35) * a_minus_b * t15 * t12 + T(35) * ab_ap * t4 * t10 + T(8) * t3 * ab_ab * (T(2) * t3 * ab_ab * (T(3) * a_minus_b * t14 * t12 + T(4) * t3 * ab_ab * (ab_ap * t4 * t5 + T(2) * t3 * ab_ab * (a_minus_b * t12 + ab_ap * t4) + a_minus_b * t13 * t12) + T(3) * ab_ap * t4 * t6) + T(5) * a_minus_b * t17 * t12 + T(5) * ab_ap * t4 * t7))) + T(231) * ab_ap * t4 * t8 + T(231) * a_minus_b * t18 * t12;
    const T t20 = t18 * t13;
    const T t21 = T(429) * ab_ap * t4 * t9 + T(2) * t3 * ab_ab * t19 + T(429) * a_minus_b * t20 * t12;
    const T t22 = T(429) * t4 * t9 + t3 * t21 * ab_ap - T(429) * t20 * t12;
    const T t23 = T(1) / ab_ab;
    G_ap = (T(1) / T(6435)) * t3 * t21 * in.w[0] + (T(1) / T(6435)) * t22 * t23 * in.w[1];
    G_ab = (T(1) / T(6435)) * t22 * t23 * in.w[0] + (T(1) / T(45045)) * t23 * (T(14) * t22 * t23 * ab_ap + T(15) * t3 * t19 - T(7) * t3 * t21 * ap_ap) * in.w[1];
  }
  const T g_factor = -T(15) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 53 +, 155 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 853 +, 2287 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[1] + M_beyond[3] * in.w[0];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t11 * t11;
    const T t15 = t6 * t6;
    const T t16 = t14 * t10;
    const T t17 = t15 * t5;
    const T t18 = T(231) * t4 * t8 * a_minus_b + T(231) * t9 * ab_ap * t13 + T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (T(35) * t9 * ab_ap * t14 + T(35) * t4 * t15 * a_minus_b + T(8) * t3 * ab_ab * (T(5) * t9 * ab_ap * t12 + T(5) * t4 * t7 * a_minus_b + T(2) * t3 * ab_ab * (T(3) * t9 * ab_ap * t11 + T(4) * t3 * ab_ab * (t4 * t5 * a_minus_b + T(2) * t3 * (t9 * ab_ap + t4 * a_minus_b) * ab_ab + t9 * ab_ap * t10) + T(3) * t4 * t6 * a_minus_b))) + T(63) * t9 * ab_ap * t16 + T(63) * t4 * t17 * a_minus_b);
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(3003)) * t3 * t18 * in.w[0] + (T(1) / T(3003)) * (t3 * t18 * ab_ap + T(231) * t9 * t13 - T(231) * t4 * t8) * t19 * in.w[1];
    const T t20 = t8 * t5;
    const T t21 = t13 * t10;
    const T t22 = T(429) * t4 * t20 * a_minus_b + T(429) * t9 * ab_ap * t21 + T(2) * t3 * ab_ab * t18;
    const T t23 = t22 * t3 * ab_ap + T(429) * t9 * t21 - T(429) * t4 * t20;
    G_ap = (T(1) / T(6435)) * t22 * t3 * in.w[0] + (T(1) / T(6435)) * t19 * t23 * in.w[1];
    G_ab = (T(1) / T(6435)) * t19 * in.w[0] * t23 - (T(1) / T(45045)) * t19 * (T(7) * t22 * t3 * ap_ap - T(14) * t19 * ab_ap * t23 - T(15) * t3 * t18) * in.w[1];
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Returns false where segment_inverse_i15_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 53 +, 155 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i15_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t5 * t5;
    const T t15 = t13 * t10;
    const T t16 = t14 * t4;
    const T t17 = t12 * t12;
    const T t18 = T(231) * a_minus_b * t3 * t7 + T(4) * t8 * ab_ab * (T(2) * (T(8) * (T(2) * t8 * ab_ab * (T(3) * t11 * t9 * ab_ap + T(4) * (a_minus_b * t3 * t4 + t10 * t9 * ab_ap + T(2) * (t9 * ab_ap + a_minus_b * t3) * t8 * ab_ab) * t8 * ab_ab + T(3) * a_minus_b * t3 * t5) + T(5) * t12 * t9 * ab_ap + T(5) * a_minus_b * t3 * t6) * t8 * ab_ab + T(35) * t13 * t9 * ab_ap + T(35) * a_minus_b * t3 * t14) * t8 * ab_ab + T(63) * t15 * t9 * ab_ap + T(63) * a_minus_b * t3 * t16) + T(231) * t17 * t9 * ab_ap;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(3003)) * in.w[0] * t18 * t8 + (T(1) / T(3003)) * in.w[1] * t19 * (T(231) * t17 * t9 + t18 * t8 * ab_ap - T(231) * t3 * t7);
    const T t20 = t17 * t10;
    const T t21 = t7 * t4;
    const T t22 = T(2) * t18 * t8 * ab_ab + T(429) * t20 * t9 * ab_ap + T(429) * a_minus_b * t3 * t21;
    const T t23 = T(429) * t20 * t9 + t22 * t8 * ab_ap - T(429) * t3 * t21;
    G_ap = (T(1) / T(6435)) * in.w[0] * t22 * t8 + (T(1) / T(6435)) * in.w[1] * t23 * t19;
    G_ab = (T(1) / T(6435)) * in.w[0] * t23 * t19 - (T(1) / T(45045)) * (T(7) * ap_ap * t22 * t8 - T(15) * t18 * t8 - T(14) * t23 * t19 * ab_ap) * in.w[1] * t19;
  }
  const T g_factor = -T(15) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 45 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 836 +, 2236 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t6 * t6;
    const T t14 = t12 * t9;
    const T t15 = t13 * t5;
    const T t16 = T(2) * t3 * ab_ab * (T(8) * t3 * ab_ab * (T(5) * ab_ap * t7 * t4 + T(2) * t3 * ab_ab * (T(3) * t8 * t10 * a_minus_b + T(4) * t3 * ab_ab * (T(2) * t3 * (t8 * a_minus_b + ab_ap * t4) * ab_ab + ab_ap * t5 * t4 + t8 * t9 * a_minus_b) + T(3) * ab_ap * t6 * t4) + T(5) * t8 * t11 * a_minus_b) + T(35) * t8 * t12 * a_minus_b + T(35) * ab_ap * t13 * t4) + T(63) * t8 * t14 * a_minus_b + T(63) * ab_ap * t15 * t4;
    const T t17 = T(1) / ab_ab;
    const T t18 = t7 * t7;
    const T t19 = t11 * t11;
    const T t20 = T(4) * t3 * ab_ab * t16 + T(231) * ab_ap * t18 * t4 + T(231) * t8 * t19 * a_minus_b;
    const T t21 = t3 * t20 * ab_ap + T(231) * t18 * t4 - T(231) * t8 * t19;
    F = (T(1) / T(9009)) * (T(13) * t3 * t16 + T(6) * t17 * t21 * ab_ap - T(3) * t3 * t20 * ap_ap) * t17 * in.w[2] + (T(1) / T(3003)) * t3 * in.w[0] * t20 + (T(1) / T(3003)) * t17 * t21 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 56 +, 162 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1073 +, 2942 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = t6 * t6;
    const T t17 = t16 * t5;
    const T t18 = t12 * t12;
    const T t19 = t18 * t11;
    const T t20 = T(4) * t3 * (T(63) * t17 * ab_ap * t4 + T(2) * t3 * (T(35) * t16 * ab_ap * t4 + T(35) * t10 * a_minus_b * t18 + T(8) * t3 * ab_ab * (T(2) * (T(3) * t6 * ab_ap * t4 + T(4) * (t10 * a_minus_b * t11 + t5 * ab_ap * t4 + T(2) * t3 * ab_ab * (ab_ap * t4 + t10 * a_minus_b)) * t3 * ab_ab + T(3) * t10 * a_minus_b * t12) * t3 * ab_ab + T(5) * t7 * ab_ap * t4 + T(5) * t10 * a_minus_b * t13)) * ab_ab + T(63) * t10 * a_minus_b * t19) * ab_ab + T(231) * t10 * a_minus_b * t14 + T(231) * t8 * ab_ap * t4;
    const T t21 = T(429) * t9 * ab_ap * t4 + T(429) * t10 * a_minus_b * t15 + T(2) * t20 * t3 * ab_ab;
    const T t22 = T(1) / ab_ab;
    const T t23 = T(429) * t10 * t15 - t3 * t21 * ab_ap - T(429) * t9 * t4;
    const T t24 = T(14) * t22 * ab_ap * t23 + T(7) * ap_ap * t3 * t21 - T(15) * t20 * t3;
    G_ap = (T(1) / T(6435)) * t3 * t21 * in.w[0] - (T(1) / T(45045)) * t24 * in.w[2] * t22 - (T(1) / T(6435)) * t22 * in.w[1] * t23;
    G_ab = -(T(1) / T(45045)) * in.w[2] * t22 * (T(2) * t24 * t22 * ab_ap + T(15) * t22 * (T(231) * t10 * t14 - t20 * t3 * ab_ap - T(231) * t8 * t4) - T(7) * ap_ap * t22 * t23) - (T(1) / T(45045)) * t24 * t22 * in.w[1] - (T(1) / T(6435)) * t22 * in.w[0] * t23;
  }
  const T g_factor = -T(15) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 60 +, 180 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1094 +, 2998 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
    G_ab = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + M_flat[6] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2] + M_beyond[4] * in.w[0];
    G_ab = in.w[2] * M_beyond[7] + M_beyond[6] * in.w[1] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t7 * t6;
    const T t15 = t12 * t12;
    const T t16 = t15 * t11;
    const T t17 = T(63) * t9 * t5 * ab_ap + T(2) * t4 * ab_ab * (T(35) * t8 * t5 * ab_ap + T(8) * t4 * ab_ab * (T(5) * t10 * t13 * a_minus_b + T(2) * t4 * ab_ab * (T(3) * t10 * t12 * a_minus_b + T(3) * t7 * t5 * ab_ap + T(4) * (T(2) * t4 * (t5 * ab_ap + t10 * a_minus_b) * ab_ab + t6 * t5 * ab_ap + t10 * t11 * a_minus_b) * t4 * ab_ab) + T(5) * t14 * t5 * ab_ap) + T(35) * t10 * t15 * a_minus_b) + T(63) * t10 * t16 * a_minus_b;
    const T t18 = t14 * t14;
    const T t19 = t13 * t13;
    const T t20 = T(4) * t17 * t4 * ab_ab + T(231) * t18 * t5 * ab_ap + T(231) * t10 * t19 * a_minus_b;
    const T t21 = t4 * t20 * ab_ap + T(231) * t18 * t5 - T(231) * t10 * t19;
    F = (T(1) / T(3003)) * t3 * t21 * in.w[1] + (T(1) / T(3003)) * t4 * t20 * in.w[0] + (T(1) / T(9009)) * (T(13) * t17 * t4 + T(6) * t3 * ab_ap * t21 - T(3) * ap_ap * t4 * t20) * in.w[2] * t3;
    const T t22 = t19 * t11;
    const T t23 = t18 * t6;
    const T t24 = T(2) * t4 * ab_ab * t20 + T(429) * t10 * t22 * a_minus_b + T(429) * t23 * t5 * ab_ap;
    const T t25 = T(429) * t10 * t22 - T(429) * t23 * t5 - t24 * t4 * ab_ap;
    const T t26 = T(7) * ap_ap * t24 * t4 + T(14) * t3 * t25 * ab_ap - T(15) * t4 * t20;
    G_ap = (T(1) / T(6435)) * t24 * t4 * in.w[0] - (T(1) / T(6435)) * t3 * t25 * in.w[1] - (T(1) / T(45045)) * in.w[2] * t3 * t26;
    G_ab = (T(1) / T(45045)) * in.w[2] * t3 * (T(15) * t3 * t21 + T(7) * ap_ap * t3 * t25 - T(2) * t3 * ab_ap * t26) - (T(1) / T(45045)) * t3 * t26 * in.w[1] - (T(1) / T(6435)) * t3 * t25 * in.w[0];
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Returns false where segment_inverse_i15_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 60 +, 180 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i15_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = t6 * t6;
    const T t17 = t16 * t5;
    const T t18 = T(63) * t9 * t15 * a_minus_b + T(2) * (T(35) * t9 * t14 * a_minus_b + T(35) * t16 * t4 * ab_ap + T(8) * t3 * ab_ab * (T(2) * t3 * ab_ab * (T(3) * t9 * t11 * a_minus_b + T(3) * t6 * t4 * ab_ap + T(4) * t3 * ab_ab * (t5 * t4 * ab_ap + T(2) * t3 * ab_ab * (t9 * a_minus_b + t4 * ab_ap) + t9 * t10 * a_minus_b)) + T(5) * t7 * t4 * ab_ap + T(5) * t9 * t12 * a_minus_b)) * t3 * ab_ab + T(63) * t17 * t4 * ab_ap;
    const T t19 = T(231) * t8 * t4 * ab_ap + T(231) * t9 * t13 * a_minus_b + T(4) * t3 * ab_ab * t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = T(231) * t8 * t4 + t3 * ab_ap * t19 - T(231) * t9 * t13;
    F = (T(1) / T(3003)) * t3 * in.w[0] * t19 + (T(1) / T(3003)) * t20 * t21 * in.w[1] + (T(1) / T(9009)) * in.w[2] * t20 * (T(6) * t20 * t21 * ab_ap + T(13) * t3 * t18 - T(3) * ap_ap * t3 * t19);
    const T t22 = t13 * t10;
    const T t23 = t8 * t5;
    const T t24 = T(429) * t9 * t22 * a_minus_b + T(2) * t3 * ab_ab * t19 + T(429) * t23 * t4 * ab_ap;
    const T t25 = T(429) * t23 * t4 + t3 * t24 * ab_ap - T(429) * t9 * t22;
    const T t26 = T(15) * t3 * t19 + T(14) * t20 * t25 * ab_ap - T(7) * ap_ap * t3 * t24;
    G_ap = (T(1) / T(6435)) * t3 * t24 * in.w[0] + (T(1) / T(45045)) * t26 * in.w[2] * t20 + (T(1) / T(6435)) * t20 * t25 * in.w[1];
    G_ab = (T(1) / T(6435)) * t20 * in.w[0] * t25 + (T(1) / T(45045)) * t26 * t20 * in.w[1] + (T(1) / T(45045)) * in.w[2] * t20 * (T(15) * t20 * t21 + T(2) * t26 * t20 * ab_ap - T(7) * ap_ap * t20 * t25);
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 50 +, 136 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1069 +, 2930 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    const T t14 = t7 * t5;
    const T t15 = t11 * t9;
    const T t16 = T(2) * (T(35) * t4 * a_minus_b * t7 + T(35) * t11 * t8 * ab_ap + T(8) * t3 * ab_ab * (T(5) * t4 * a_minus_b * t12 + T(5) * t13 * t8 * ab_ap + T(2) * t3 * ab_ab * (T(3) * t4 * a_minus_b * t6 + T(4) * t3 * (t9 * t8 * ab_ap + T(2) * t3 * ab_ab * (t4 * a_minus_b + t8 * ab_ap) + t4 * a_minus_b * t5) * ab_ab + T(3) * t10 * t8 * ab_ap))) * t3 * ab_ab + T(63) * t4 * a_minus_b * t14 + T(63) * t15 * t8 * ab_ap;
    const T t17 = t13 * t13;
    const T t18 = t12 * t12;
    const T t19 = T(4) * t3 * ab_ab * t16 + T(231) * t17 * t8 * ab_ap + T(231) * t4 * a_minus_b * t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = t19 * t3 * ab_ap + T(231) * t17 * t8 - T(231) * t4 * t18;
    const T t22 = T(3) * ap_ap * t19 * t3 - T(6) * t21 * t20 * ab_ap - T(13) * t3 * t16;
    F = (T(1) / T(3003)) * t19 * t3 * in.w[0] + (T(1) / T(9009)) * in.w[3] * t20 * (T(13) * (t3 * t16 * ab_ap + T(63) * t15 * t8 - T(63) * t4 * t14) * t20 - T(3) * t21 * ap_ap * t20 - T(2) * t22 * t20 * ab_ap) + (T(1) / T(3003)) * t21 * t20 * in.w[1] - (T(1) / T(9009)) * in.w[2] * t22 * t20;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 62 +, 183 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1308 +, 3639 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[3] * in.w[3];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1] + in.w[3] * M_flat[4] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2] + in.w[3] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / cross_cross;
    const T t10 = t5 * t5;
    const T t11 = t10 * t4;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t13;
    const T t17 = t14 * t13;
    const T t18 = T(63) * t3 * a_minus_b * t11 + T(63) * t16 * ab_ap * t12 + T(2) * t9 * ab_ab * (T(8) * (T(5) * t3 * a_minus_b * t6 + T(2) * t9 * ab_ab * (T(3) * t3 * a_minus_b * t5 + T(4) * t9 * ab_ab * (T(2) * t9 * ab_ab * (t3 * a_minus_b + ab_ap * t12) + t13 * ab_ap * t12 + t3 * a_minus_b * t4) + T(3) * t14 * ab_ap * t12) + T(5) * t17 * ab_ap * t12) * t9 * ab_ab + T(35) * t15 * ab_ap * t12 + T(35) * t3 * a_minus_b * t10);
    const T t19 = t17 * t17;
    const T t20 = T(4) * t18 * t9 * ab_ab + T(231) * t3 * a_minus_b * t7 + T(231) * t19 * ab_ap * t12;
    const T t21 = t19 * t13;
    const T t22 = T(429) * t3 * a_minus_b * t8 + T(2) * t9 * ab_ab * t20 + T(429) * t21 * ab_ap * t12;
    const T t23 = T(1) / ab_ab;
    const T t24 = t22 * t9 * ab_ap + T(429) * t21 * t12 - T(429) * t3 * t8;
    const T t25 = T(14) * t23 * ab_ap * t24 + T(15) * t9 * t20 - T(7) * ap_ap * t22 * t9;
    const T t26 = t9 * t20 * ab_ap + T(231) * t19 * t12 - T(231) * t3 * t7;
    const T t27 = T(2) * t23 * t25 * ab_ap + T(15) * t23 * t26 - T(7) * ap_ap * t23 * t24;
    G_ap = (T(1) / T(6435)) * t22 * t9 * in.w[0] + (T(1) / T(45045)) * in.w[3] * t23 * t27 + (T(1) / T(45045)) * t23 * t25 * in.w[2] + (T(1) / T(6435)) * t23 * in.w[1] * t24;
    G_ab = (T(1) / T(45045)) * in.w[3] * t23 * (T(5) * t23 * (T(6) * t23 * t26 * ab_ap + T(13) * t18 * t9 - T(3) * ap_ap * t9 * t20) + T(2) * t23 * t27 * ab_ap - ap_ap * t23 * t25) + (T(1) / T(45045)) * t23 * t27 * in.w[2] + (T(1) / T(45045)) * t23 * in.w[1] * t25 + (T(1) / T(6435)) * in.w[0] * t23 * t24;
  }
  const T g_factor = -T(15) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 69 +, 210 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1337 +, 3713 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i15_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
    G_ap = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2] + in.w[3] * M_flat[8];
    G_ab = in.w[1] * M_flat[7] + M_flat[9] * in.w[3] + in.w[0] * M_flat[6] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3] + M_beyond[6] * in.w[1];
    G_ab = M_beyond[8] * in.w[2] + in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / cross_cross;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t5;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t15 * t12;
    const T t17 = T(63) * t4 * t10 * a_minus_b + T(2) * t3 * ab_ab * (T(8) * t3 * ab_ab * (T(5) * t11 * ab_ap * t14 + T(5) * t4 * t7 * a_minus_b + T(2) * t3 * ab_ab * (T(4) * (t4 * t5 * a_minus_b + T(2) * (t4 * a_minus_b + t11 * ab_ap) * t3 * ab_ab + t11 * ab_ap * t12) * t3 * ab_ab + T(3) * t11 * ab_ap * t13 + T(3) * t4 * t6 * a_minus_b)) + T(35) * t4 * t9 * a_minus_b + T(35) * t11 * ab_ap * t15) + T(63) * t11 * ab_ap * t16;
    const T t18 = t14 * t14;
    const T t19 = T(231) * t4 * t8 * a_minus_b + T(4) * t3 * ab_ab * t17 + T(231) * t11 * ab_ap * t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = T(231) * t11 * t18 + t3 * ab_ap * t19 - T(231) * t4 * t8;
    const T t22 = T(3) * t3 * t19 * ap_ap - T(13) * t3 * t17 - T(6) * t20 * ab_ap * t21;
    F = (T(1) / T(3003)) * in.w[0] * t3 * t19 + (T(1) / T(3003)) * t20 * in.w[1] * t21 - (T(1) / T(9009)) * in.w[3] * t20 * (T(3) * t20 * t21 * ap_ap + T(2) * t20 * ab_ap * t22 - T(13) * (t3 * ab_ap * t17 + T(63) * t11 * t16 - T(63) * t4 * t10) * t20) - (T(1) / T(9009)) * t20 * t22 * in.w[2];
    const T t23 = t8 * t5;
    const T t24 = t18 * t12;
    const T t25 = T(2) * t3 * ab_ab * t19 + T(429) * t4 * t23 * a_minus_b + T(429) * t11 * ab_ap * t24;
    const T t26 = t3 * t25 * ab_ap + T(429) * t11 * t24 - T(429) * t4 * t23;
    const T t27 = T(14) * t26 * t20 * ab_ap + T(15) * t3 * t19 - T(7) * t3 * t25 * ap_ap;
    const T t28 = T(15) * t20 * t21 + T(2) * t20 * ab_ap * t27 - T(7) * t26 * t20 * ap_ap;
    G_ap = (T(1) / T(6435)) * t26 * t20 * in.w[1] + (T(1) / T(45045)) * t20 * t27 * in.w[2] + (T(1) / T(45045)) * in.w[3] * t20 * t28 + (T(1) / T(6435)) * in.w[0] * t3 * t25;
    G_ab = (T(1) / T(45045)) * t20 * t28 * in.w[2] + (T(1) / T(45045)) * t20 * in.w[1] * t27 + (T(1) / T(6435)) * in.w[0] * t26 * t20 - (T(1) / T(45045)) * in.w[3] * t20 * (t20 * t27 * ap_ap + T(5) * t20 * t22 - T(2) * t20 * ab_ap * t28);
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Returns false where segment_inverse_i15_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 69 +, 210 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i15_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2] + M_flat[8] * in.w[3];
    G_ab = M_flat[7] * in.w[1] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + M_flat[6] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t6 * t5;
    const T t15 = T(1) / cross_cross;
    const T t16 = t11 * t10;
    const T t17 = T(63) * t9 * t13 * a_minus_b + T(63) * ab_ap * t8 * t4 + T(2) * (T(35) * t9 * t12 * a_minus_b + T(35) * ab_ap * t7 * t4 + T(8) * (T(5) * ab_ap * t14 * t4 + T(2) * (T(4) * t15 * ab_ab * (ab_ap * t5 * t4 + t9 * t10 * a_minus_b + T(2) * (t9 * a_minus_b + ab_ap * t4) * t15 * ab_ab) + T(3) * t9 * t11 * a_minus_b + T(3) * ab_ap * t6 * t4) * t15 * ab_ab + T(5) * t9 * t16 * a_minus_b) * t15 * ab_ab) * t15 * ab_ab;
    const T t18 = t14 * t14;
    const T t19 = t16 * t16;
    const T t20 = T(231) * ab_ap * t18 * t4 + T(231) * t9 * t19 * a_minus_b + T(4) * t17 * t15 * ab_ab;
    const T t21 = T(231) * t18 * t4 + ab_ap * t20 * t15 - T(231) * t9 * t19;
    const T t22 = T(6) * ab_ap * t21 * t3 + T(13) * t17 * t15 - T(3) * t20 * ap_ap * t15;
    F = (T(1) / T(9009)) * in.w[3] * t3 * (T(13) * (T(63) * t8 * t4 + t17 * ab_ap * t15 - T(63) * t9 * t13) * t3 + T(2) * ab_ap * t22 * t3 - T(3) * t21 * ap_ap * t3) + (T(1) / T(3003)) * in.w[1] * t21 * t3 + (T(1) / T(3003)) * t20 * t15 * in.w[0] + (T(1) / T(9009)) * in.w[2] * t22 * t3;
    const T t23 = t18 * t5;
    const T t24 = t19 * t10;
    const T t25 = T(429) * ab_ap * t23 * t4 + T(429) * t9 * t24 * a_minus_b + T(2) * t20 * t15 * ab_ab;
    const T t26 = ab_ap * t25 * t15 + T(429) * t23 * t4 - T(429) * t9 * t24;
    const T t27 = T(14) * t26 * ab_ap * t3 + T(15) * t20 * t15 - T(7) * t25 * ap_ap * t15;
    const T t28 = T(7) * t26 * ap_ap * t3 - T(2) * ab_ap * t27 * t3 - T(15) * t21 * t3;
    G_ap = (T(1) / T(6435)) * t25 * t15 * in.w[0] + (T(1) / T(45045)) * t27 * in.w[2] * t3 + (T(1) / T(6435)) * in.w[1] * t26 * t3 - (T(1) / T(45045)) * t28 * in.w[3] * t3;
    G_ab = (T(1) / T(6435)) * t26 * in.w[0] * t3 + (T(1) / T(45045)) * in.w[1] * t27 * t3 - (T(1) / T(45045)) * in.w[2] * t28 * t3 - (T(1) / T(45045)) * in.w[3] * (t27 * ap_ap * t3 + T(2) * ab_ap * t28 * t3 - T(5) * t22 * t3) * t3;
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 42 +, 94 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 375 +, 859 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 0, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 0, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t7 * t6;
    const T t16 = t15 * t15;
    const T t17 = t14 * t14;
    const T t18 = t16 * t6;
    const T t19 = t17 * t10;
    F = (T(1) / T(215040)) * in.w[0] * t5 * (T(13) * t5 * ab_ab * (T(11) * (T(128) * a_minus_b * t9 + T(128) * t13 * ab_ap + T(3) * t5 * (T(7) * t5 * ab_ab * (T(8) * t14 * ab_ap + T(5) * t5 * ab_ab * (T(2) * t11 * ab_ap + T(3) * t5 * ab_ab * (a_minus_b * t6 + J2 * ab_ab + t10 * ab_ap) + T(2) * a_minus_b * t7) + T(8) * a_minus_b * t15) + T(48) * t12 * ab_ap + T(48) * a_minus_b * t8) * ab_ab) * t5 * ab_ab + T(1280) * a_minus_b * t16 + T(1280) * t17 * ab_ap) + T(15360) * a_minus_b * t18 + T(15360) * t19 * ab_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 49 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 608 +, 1559 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t7 * t6;
    const T t16 = t15 * t15;
    const T t17 = t16 * t6;
    const T t18 = t11 * t11;
    const T t19 = t18 * t10;
    const T t20 = t8 * t6;
    const T t21 = t18 * t18;
    const T t22 = T(14336) * ab_ap * t9 + (T(15360) * a_minus_b * t14 + T(15360) * ab_ap * t17 + T(13) * (T(11) * (T(3) * (T(48) * a_minus_b * t18 + T(7) * (T(8) * a_minus_b * t12 + T(8) * ab_ap * t15 + T(5) * (T(3) * t5 * ab_ab * (ab_ab * J2 + ab_ap * t6 + a_minus_b * t10) + T(2) * a_minus_b * t11 + T(2) * ab_ap * t7) * t5 * ab_ab) * t5 * ab_ab + T(48) * ab_ap * t8) * t5 * ab_ab + T(128) * a_minus_b * t19 + T(128) * ab_ap * t20) * t5 * ab_ab + T(1280) * a_minus_b * t13 + T(1280) * ab_ap * t16) * t5 * ab_ab) * t5 * ab_ab + T(14336) * a_minus_b * t21;
    G_ap = (T(1) / T(229376)) * in.w[0] * t5 * t22;
    G_ab = -(T(1) / T(229376)) * in.w[0] * (T(14336) * t21 - ab_ap * t5 * t22 - T(14336) * t9) / ab_ab;
  }
  const T g_factor = -T(16) * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 49 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 616 +, 1586 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = T(1) / cross_cross;
    const T t15 = t10 * t10;
    const T t16 = t13 * t5;
    const T t17 = t15 * t9;
    const T t18 = t8 * t5;
    const T t19 = t12 * t9;
    const T t20 = T(13) * ab_ab * (T(1280) * ab_ap * t8 + T(1280) * t12 * a_minus_b + T(11) * ab_ab * (T(3) * ab_ab * (T(48) * ab_ap * t13 + T(7) * ab_ab * (T(8) * ab_ap * t7 + T(8) * t11 * a_minus_b + T(5) * ab_ab * (T(2) * ab_ap * t6 + T(2) * t10 * a_minus_b + T(3) * ab_ab * (t9 * a_minus_b + ab_ab * J2 + ab_ap * t5) * t14) * t14) * t14 + T(48) * t15 * a_minus_b) * t14 + T(128) * ab_ap * t16 + T(128) * t17 * a_minus_b) * t14) * t14 + T(15360) * ab_ap * t18 + T(15360) * t19 * a_minus_b;
    F = (T(1) / T(215040)) * t20 * in.w[0] * t14;
    const T t21 = t15 * t15;
    const T t22 = t13 * t13;
    const T t23 = ab_ab * t20 * t14 + T(14336) * t21 * a_minus_b + T(14336) * ab_ap * t22;
    G_ap = (T(1) / T(229376)) * t23 * in.w[0] * t14;
    G_ab = (T(1) / T(229376)) * (ab_ap * t23 * t14 + T(14336) * t22 - T(14336) * t21) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Returns false where segment_inverse_i16_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i16_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = T(1) / cross_cross;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = t6 * t6;
    const T t19 = t18 * t5;
    const T t20 = T(15360) * ab_ap * t9 + T(15360) * t14 * a_minus_b + T(13) * (T(1280) * ab_ap * t8 + T(11) * t15 * ab_ab * (T(128) * t17 * a_minus_b + T(128) * ab_ap * t19 + T(3) * t15 * ab_ab * (T(48) * ab_ap * t18 + T(7) * (T(5) * (T(2) * t11 * a_minus_b + T(3) * (ab_ap * t5 + t10 * a_minus_b + J2 * ab_ab) * t15 * ab_ab + T(2) * ab_ap * t6) * t15 * ab_ab + T(8) * t12 * a_minus_b + T(8) * ab_ap * t7) * t15 * ab_ab + T(48) * t16 * a_minus_b)) + T(1280) * t13 * a_minus_b) * t15 * ab_ab;
    F = (T(1) / T(215040)) * t20 * in.w[0] * t15;
    const T t21 = t18 * t18;
    const T t22 = t16 * t16;
    const T t23 = T(14336) * ab_ap * t21 + t20 * t15 * ab_ab + T(14336) * t22 * a_minus_b;
    G_ap = (T(1) / T(229376)) * t23 * in.w[0] * t15;
    G_ab = (T(1) / T(229376)) * (ab_ap * t23 * t15 + T(14336) * t21 - T(14336) * t22) * in.w[0] / ab_ab;
  }
  const T g_factor = -T(16) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 45 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 606 +, 1549 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 1, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = T(1) / cross_cross;
    const T t16 = t6 * t6;
    const T t17 = t11 * t11;
    const T t18 = t16 * t5;
    const T t19 = t17 * t10;
    const T t20 = T(15360) * ab_ap * t9 + T(15360) * t14 * a_minus_b + T(13) * (T(1280) * ab_ap * t8 + T(11) * t15 * (T(3) * (T(7) * (T(8) * t12 * a_minus_b + T(5) * t15 * (T(3) * (ab_ap * t5 + t10 * a_minus_b + J2 * ab_ab) * t15 * ab_ab + T(2) * t11 * a_minus_b + T(2) * ab_ap * t6) * ab_ab + T(8) * ab_ap * t7) * t15 * ab_ab + T(48) * ab_ap * t16 + T(48) * t17 * a_minus_b) * t15 * ab_ab + T(128) * ab_ap * t18 + T(128) * t19 * a_minus_b) * ab_ab + T(1280) * t13 * a_minus_b) * t15 * ab_ab;
    F = (T(1) / T(215040)) * t20 * in.w[0] * t15 - (T(1) / T(215040)) * in.w[1] * (T(15360) * t14 - t20 * ab_ap * t15 - T(15360) * t9) / ab_ab;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 53 +, 132 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 841 +, 2252 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t11 * t10;
    const T t15 = t14 * t14;
    const T t16 = t15 * t10;
    const T t17 = t7 * t6;
    const T t18 = t17 * t17;
    const T t19 = t18 * t6;
    const T t20 = t8 * t6;
    const T t21 = t12 * t10;
    const T t22 = T(15360) * t16 * ab_ap + T(15360) * a_minus_b * t19 + T(13) * (T(11) * (T(128) * a_minus_b * t20 + T(3) * t5 * ab_ab * (T(48) * a_minus_b * t8 + T(7) * (T(8) * t14 * ab_ap + T(5) * (T(3) * t5 * ab_ab * (a_minus_b * t6 + t10 * ab_ap + ab_ab * J2) + T(2) * t11 * ab_ap + T(2) * a_minus_b * t7) * t5 * ab_ab + T(8) * a_minus_b * t17) * t5 * ab_ab + T(48) * t12 * ab_ap) + T(128) * t21 * ab_ap) * t5 * ab_ab + T(1280) * t15 * ab_ap + T(1280) * a_minus_b * t18) * t5 * ab_ab;
    const T t23 = T(14336) * a_minus_b * t9 + T(14336) * t13 * ab_ap + t5 * ab_ab * t22;
    const T t24 = T(1) / ab_ab;
    const T t25 = T(14336) * t9 - t5 * t23 * ab_ap - T(14336) * t13;
    G_ap = (T(1) / T(229376)) * in.w[0] * t5 * t23 - (T(1) / T(229376)) * in.w[1] * t24 * t25;
    G_ab = -(T(1) / T(229376)) * in.w[0] * t24 * t25 - (T(1) / T(3440640)) * (T(30) * t24 * ab_ap * t25 + T(15) * ap_ap * t5 * t23 - T(16) * t5 * t22) * in.w[1] * t24;
  }
  const T g_factor = -T(16) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 56 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 855 +, 2293 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t7 * t7;
    const T t16 = t15 * t6;
    const T t17 = t12 * t12;
    const T t18 = t17 * t11;
    const T t19 = t14 * t11;
    const T t20 = T(15360) * ab_ap * t10 + T(13) * t5 * ab_ab * (T(1280) * ab_ap * t9 + T(1280) * t14 * a_minus_b + T(11) * (T(128) * ab_ap * t16 + T(128) * t18 * a_minus_b + T(3) * (T(48) * ab_ap * t15 + T(7) * (T(5) * (T(2) * t12 * a_minus_b + T(2) * ab_ap * t7 + T(3) * (J2 * ab_ab + ab_ap * t6 + t11 * a_minus_b) * t5 * ab_ab) * t5 * ab_ab + T(8) * ab_ap * t8 + T(8) * t13 * a_minus_b) * t5 * ab_ab + T(48) * t17 * a_minus_b) * t5 * ab_ab) * t5 * ab_ab) + T(15360) * t19 * a_minus_b;
    const T t21 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * in.w[0] * t5 * t20 - (T(1) / T(215040)) * (T(15360) * t19 - ab_ap * t5 * t20 - T(15360) * t10) * in.w[1] * t21;
    const T t22 = t15 * t15;
    const T t23 = t17 * t17;
    const T t24 = t5 * ab_ab * t20 + T(14336) * ab_ap * t22 + T(14336) * t23 * a_minus_b;
    const T t25 = t24 * ab_ap * t5 + T(14336) * t22 - T(14336) * t23;
    G_ap = (T(1) / T(229376)) * t25 * in.w[1] * t21 + (T(1) / T(229376)) * t24 * in.w[0] * t5;
    G_ab = (T(1) / T(229376)) * in.w[0] * t25 * t21 - (T(1) / T(3440640)) * (T(15) * t24 * ap_ap * t5 - T(30) * ab_ap * t25 * t21 - T(16) * t5 * t20) * in.w[1] * t21;
  }
  const T g_factor = -T(16) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Returns false where segment_inverse_i16_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 56 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i16_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / ap_ap;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t12;
    const T t16 = t13 * t12;
    const T t17 = t16 * t16;
    const T t18 = t9 * t6;
    const T t19 = t17 * t12;
    const T t20 = T(13) * t5 * ab_ab * (T(1280) * t9 * a_minus_b + T(11) * t5 * ab_ab * (T(128) * t11 * a_minus_b + T(128) * ab_ap * t15 + T(3) * t5 * ab_ab * (T(48) * t10 * a_minus_b + T(7) * t5 * ab_ab * (T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (ab_ap * t12 + t6 * a_minus_b + ab_ab * J2) + T(2) * t7 * a_minus_b + T(2) * ab_ap * t13) + T(8) * t8 * a_minus_b + T(8) * ab_ap * t16) + T(48) * ab_ap * t14)) + T(1280) * ab_ap * t17) + T(15360) * t18 * a_minus_b + T(15360) * ab_ap * t19;
    const T t21 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * t5 * in.w[0] * t20 + (T(1) / T(215040)) * t21 * (t5 * ab_ap * t20 + T(15360) * t19 - T(15360) * t18) * in.w[1];
    const T t22 = t14 * t14;
    const T t23 = t10 * t10;
    const T t24 = T(14336) * ab_ap * t22 + T(14336) * t23 * a_minus_b + t5 * ab_ab * t20;
    const T t25 = T(14336) * t23 - T(14336) * t22 - t5 * ab_ap * t24;
    G_ap = (T(1) / T(229376)) * t5 * in.w[0] * t24 - (T(1) / T(229376)) * t21 * in.w[1] * t25;
    G_ab = -(T(1) / T(3440640)) * t21 * in.w[1] * (T(15) * t5 * ap_ap * t24 + T(30) * t21 * ab_ap * t25 - T(16) * t5 * t20) - (T(1) / T(229376)) * t21 * in.w[0] * t25;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 48 +, 111 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 838 +, 2241 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 2, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / cross_cross;
    const T t12 = t9 * t9;
    const T t13 = t6 * t6;
    const T t14 = t12 * t8;
    const T t15 = t13 * t5;
    const T t16 = t7 * t7;
    const T t17 = t10 * t10;
    const T t18 = T(11) * (T(3) * (T(7) * (T(8) * t7 * a_minus_b + T(8) * ab_ap * t10 + T(5) * (T(3) * (ab_ap * t8 + t5 * a_minus_b + J2 * ab_ab) * t11 * ab_ab + T(2) * t6 * a_minus_b + T(2) * ab_ap * t9) * t11 * ab_ab) * t11 * ab_ab + T(48) * ab_ap * t12 + T(48) * t13 * a_minus_b) * t11 * ab_ab + T(128) * ab_ap * t14 + T(128) * t15 * a_minus_b) * t11 * ab_ab + T(1280) * t16 * a_minus_b + T(1280) * ab_ap * t17;
    const T t19 = t16 * t5;
    const T t20 = t17 * t8;
    const T t21 = T(13) * t18 * t11 * ab_ab + T(15360) * t19 * a_minus_b + T(15360) * ab_ap * t20;
    const T t22 = T(15360) * t19 - ab_ap * t21 * t11 - T(15360) * t20;
    const T t23 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * in.w[0] * t21 * t11 - (T(1) / T(215040)) * t22 * in.w[1] * t23 - (T(1) / T(215040)) * in.w[2] * (T(2) * t22 * ab_ap * t23 + t21 * ap_ap * t11 - T(14) * t18 * t11) * t23;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 59 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2947 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ab = M_flat[3] * in.w[2] + in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t8 * t6;
    const T t15 = t12 * t10;
    const T t16 = t11 * t10;
    const T t17 = t7 * t6;
    const T t18 = t17 * t17;
    const T t19 = t16 * t16;
    const T t20 = t18 * t6;
    const T t21 = t19 * t10;
    const T t22 = T(13) * (T(11) * t5 * ab_ab * (T(128) * a_minus_b * t14 + T(128) * t15 * ab_ap + T(3) * (T(48) * a_minus_b * t8 + T(7) * (T(8) * t16 * ab_ap + T(5) * t5 * ab_ab * (T(3) * t5 * ab_ab * (a_minus_b * t6 + ab_ab * J2 + t10 * ab_ap) + T(2) * t11 * ab_ap + T(2) * a_minus_b * t7) + T(8) * a_minus_b * t17) * t5 * ab_ab + T(48) * t12 * ab_ap) * t5 * ab_ab) + T(1280) * a_minus_b * t18 + T(1280) * t19 * ab_ap) * t5 * ab_ab + T(15360) * a_minus_b * t20 + T(15360) * t21 * ab_ap;
    const T t23 = T(14336) * a_minus_b * t9 + T(14336) * t13 * ab_ap + t22 * t5 * ab_ab;
    const T t24 = T(1) / ab_ab;
    const T t25 = T(14336) * t9 - t5 * ab_ap * t23 - T(14336) * t13;
    const T t26 = T(30) * t25 * t24 * ab_ap + T(15) * ap_ap * t5 * t23 - T(16) * t22 * t5;
    G_ap = (T(1) / T(229376)) * t5 * in.w[0] * t23 - (T(1) / T(3440640)) * in.w[2] * t24 * t26 - (T(1) / T(229376)) * in.w[1] * t25 * t24;
    G_ab = (T(1) / T(3440640)) * in.w[2] * (T(15) * t25 * ap_ap * t24 + T(16) * (T(15360) * t21 + t22 * t5 * ab_ap - T(15360) * t20) * t24 - T(2) * t24 * t26 * ab_ap) * t24 - (T(1) / T(229376)) * t25 * t24 * in.w[0] - (T(1) / T(3440640)) * in.w[1] * t24 * t26;
  }
  const T g_factor = -T(16) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 63 +, 167 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1096 +, 3004 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[5] + M_flat[6] * in.w[2] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2];
    G_ap = in.w[0] * M_beyond[4] + M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5];
    G_ab = M_beyond[5] * in.w[0] + in.w[1] * M_beyond[6] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t7 * t7;
    const T t17 = t16 * t6;
    const T t18 = t15 * t12;
    const T t19 = t14 * t14;
    const T t20 = T(11) * t11 * ab_ab * (T(3) * t11 * ab_ab * (T(7) * t11 * ab_ab * (T(5) * t11 * ab_ab * (T(2) * t13 * a_minus_b + T(3) * t11 * ab_ab * (ab_ap * t6 + ab_ab * J2 + t12 * a_minus_b) + T(2) * ab_ap * t7) + T(8) * t14 * a_minus_b + T(8) * ab_ap * t8) + T(48) * t15 * a_minus_b + T(48) * ab_ap * t16) + T(128) * ab_ap * t17 + T(128) * t18 * a_minus_b) + T(1280) * ab_ap * t9 + T(1280) * t19 * a_minus_b;
    const T t21 = t19 * t12;
    const T t22 = T(15360) * ab_ap * t10 + T(13) * t20 * t11 * ab_ab + T(15360) * t21 * a_minus_b;
    const T t23 = T(15360) * t10 + t11 * ab_ap * t22 - T(15360) * t21;
    F = (T(1) / T(215040)) * in.w[1] * t5 * t23 + (T(1) / T(215040)) * t11 * t22 * in.w[0] - (T(1) / T(215040)) * t5 * (t11 * t22 * ap_ap - T(2) * t5 * ab_ap * t23 - T(14) * t20 * t11) * in.w[2];
    const T t24 = t16 * t16;
    const T t25 = t15 * t15;
    const T t26 = T(14336) * ab_ap * t24 + t11 * ab_ab * t22 + T(14336) * t25 * a_minus_b;
    const T t27 = T(14336) * t25 - t11 * ab_ap * t26 - T(14336) * t24;
    const T t28 = T(30) * t5 * ab_ap * t27 + T(15) * t11 * t26 * ap_ap - T(16) * t11 * t22;
    G_ap = (T(1) / T(229376)) * t11 * t26 * in.w[0] - (T(1) / T(229376)) * in.w[1] * t5 * t27 - (T(1) / T(3440640)) * t5 * t28 * in.w[2];
    G_ab = (T(1) / T(3440640)) * t5 * (T(16) * t5 * t23 + T(15) * t5 * t27 * ap_ap - T(2) * t5 * t28 * ab_ap) * in.w[2] - (T(1) / T(229376)) * t5 * t27 * in.w[0] - (T(1) / T(3440640)) * in.w[1] * t5 * t28;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Returns false where segment_inverse_i16_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 167 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i16_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + in.w[2] * M_flat[6];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t12 * t12;
    const T t15 = t6 * t6;
    const T t16 = t14 * t11;
    const T t17 = t15 * t5;
    const T t18 = t13 * t13;
    const T t19 = T(1280) * ab_ap * t8 + T(11) * (T(3) * t10 * ab_ab * (T(7) * (T(5) * (T(2) * t12 * a_minus_b + T(3) * (ab_ap * t5 + J2 * ab_ab + t11 * a_minus_b) * t10 * ab_ab + T(2) * ab_ap * t6) * t10 * ab_ab + T(8) * t13 * a_minus_b + T(8) * ab_ap * t7) * t10 * ab_ab + T(48) * t14 * a_minus_b + T(48) * ab_ap * t15) + T(128) * t16 * a_minus_b + T(128) * ab_ap * t17) * t10 * ab_ab + T(1280) * t18 * a_minus_b;
    const T t20 = t18 * t11;
    const T t21 = T(15360) * ab_ap * t9 + T(13) * t19 * t10 * ab_ab + T(15360) * t20 * a_minus_b;
    const T t22 = T(15360) * t9 + ab_ap * t21 * t10 - T(15360) * t20;
    const T t23 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * t22 * in.w[1] * t23 + (T(1) / T(215040)) * in.w[0] * t21 * t10 + (T(1) / T(215040)) * (T(14) * t19 * t10 + T(2) * t22 * ab_ap * t23 - t21 * ap_ap * t10) * in.w[2] * t23;
    const T t24 = t15 * t15;
    const T t25 = t14 * t14;
    const T t26 = T(14336) * ab_ap * t24 + t21 * t10 * ab_ab + T(14336) * t25 * a_minus_b;
    const T t27 = T(14336) * t24 + ab_ap * t26 * t10 - T(14336) * t25;
    const T t28 = T(30) * ab_ap * t23 * t27 + T(16) * t21 * t10 - T(15) * t26 * ap_ap * t10;
    G_ap = (T(1) / T(3440640)) * t28 * in.w[2] * t23 + (T(1) / T(229376)) * in.w[1] * t23 * t27 + (T(1) / T(229376)) * in.w[0] * t26 * t10;
    G_ab = (T(1) / T(3440640)) * t28 * in.w[1] * t23 + (T(1) / T(229376)) * in.w[0] * t23 * t27 + (T(1) / T(3440640)) * (T(16) * t22 * t23 + T(2) * t28 * ab_ap * t23 - T(15) * ap_ap * t23 * t27) * in.w[2] * t23;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 53 +, 125 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1071 +, 2935 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 3, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / cross_cross;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t7;
    const T t14 = t11 * t11;
    const T t15 = t13 * t6;
    const T t16 = t14 * t10;
    const T t17 = t12 * t12;
    const T t18 = T(1280) * t9 * a_minus_b + T(11) * t5 * ab_ab * (T(3) * t5 * ab_ab * (T(7) * t5 * ab_ab * (T(8) * t8 * a_minus_b + T(8) * ab_ap * t12 + T(5) * (T(2) * t7 * a_minus_b + T(3) * t5 * ab_ab * (ab_ap * t10 + ab_ab * J2 + t6 * a_minus_b) + T(2) * ab_ap * t11) * t5 * ab_ab) + T(48) * t13 * a_minus_b + T(48) * ab_ap * t14) + T(128) * t15 * a_minus_b + T(128) * ab_ap * t16) + T(1280) * ab_ap * t17;
    const T t19 = t9 * t6;
    const T t20 = t17 * t10;
    const T t21 = T(13) * t5 * ab_ab * t18 + T(15360) * t19 * a_minus_b + T(15360) * ab_ap * t20;
    const T t22 = t5 * t21 * ab_ap + T(15360) * t20 - T(15360) * t19;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(14) * t5 * t18 + T(2) * t22 * t23 * ab_ap - t5 * t21 * ap_ap;
    F = (T(1) / T(215040)) * t24 * t23 * in.w[2] + (T(1) / T(215040)) * t22 * t23 * in.w[1] + (T(1) / T(215040)) * t5 * in.w[0] * t21 - (T(1) / T(215040)) * in.w[3] * t23 * (T(14) * t23 * (T(1280) * t9 - T(1280) * t17 - t5 * t18 * ab_ap) + t22 * t23 * ap_ap - T(2) * t24 * t23 * ab_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 65 +, 170 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1310 +, 3644 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(7) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = in.w[1] * M_flat[2] + in.w[3] * M_flat[4] + in.w[2] * M_flat[3] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3];
    G_ab = M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2] + M_beyond[4] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, ap_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = T(1) / cross_cross;
    const T t14 = t6 * t5;
    const T t15 = t14 * t14;
    const T t16 = t15 * t5;
    const T t17 = t10 * t9;
    const T t18 = t17 * t17;
    const T t19 = t7 * t5;
    const T t20 = t11 * t9;
    const T t21 = T(1280) * a_minus_b * t15 + T(1280) * ab_ap * t18 + T(11) * (T(3) * (T(7) * (T(8) * a_minus_b * t14 + T(5) * (T(2) * a_minus_b * t6 + T(3) * (ab_ap * t9 + ab_ab * J2 + a_minus_b * t5) * t13 * ab_ab + T(2) * ab_ap * t10) * t13 * ab_ab + T(8) * ab_ap * t17) * t13 * ab_ab + T(48) * a_minus_b * t7 + T(48) * ab_ap * t11) * t13 * ab_ab + T(128) * a_minus_b * t19 + T(128) * ab_ap * t20) * t13 * ab_ab;
    const T t22 = t18 * t9;
    const T t23 = T(15360) * a_minus_b * t16 + T(13) * t21 * t13 * ab_ab + T(15360) * ab_ap * t22;
    const T t24 = T(14336) * ab_ap * t12 + t13 * t23 * ab_ab + T(14336) * a_minus_b * t8;
    const T t25 = T(14336) * t8 - T(14336) * t12 - ab_ap * t13 * t24;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(16) * t13 * t23 - T(15) * ap_ap * t13 * t24 - T(30) * ab_ap * t25 * t26;
    const T t28 = T(15360) * t16 - T(15360) * t22 - ab_ap * t13 * t23;
    const T t29 = T(15) * ap_ap * t25 * t26 + T(2) * ab_ap * t27 * t26 - T(16) * t28 * t26;
    G_ap = (T(1) / T(3440640)) * t29 * in.w[3] * t26 + (T(1) / T(3440640)) * t27 * in.w[2] * t26 + (T(1) / T(229376)) * t13 * in.w[0] * t24 - (T(1) / T(229376)) * in.w[1] * t25 * t26;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t27 * t26 + (T(1) / T(3440640)) * in.w[2] * t29 * t26 - (T(1) / T(3440640)) * (t27 * ap_ap * t26 + T(16) * (ap_ap * t13 * t23 + T(2) * ab_ap * t28 * t26 - T(14) * t21 * t13) * t26 - T(2) * ab_ap * t29 * t26) * in.w[3] * t26 - (T(1) / T(229376)) * t25 * in.w[0] * t26;
  }
  const T g_factor = -T(16) * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 72 +, 194 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1339 +, 3719 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
template <class T>
T segment_inverse_i16_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[1] * M_flat[6];
    G_ab = in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[3] * M_flat[9] + in.w[0] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 4, ab_ab, ab_ap, cross_cross, ap_ap, bp_bp, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[8] * in.w[3];
    G_ab = in.w[3] * M_beyond[9] + M_beyond[6] * in.w[0] + in.w[1] * M_beyond[7] + in.w[2] * M_beyond[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t6 * t6;
    const T t16 = T(1) / cross_cross;
    const T t17 = t11 * t11;
    const T t18 = t15 * t5;
    const T t19 = t17 * t10;
    const T t20 = T(11) * ab_ab * (T(3) * ab_ab * (T(48) * ab_ap * t15 + T(7) * ab_ab * t16 * (T(8) * ab_ap * t7 + T(5) * ab_ab * (T(2) * t11 * a_minus_b + T(2) * ab_ap * t6 + T(3) * ab_ab * (ab_ap * t5 + t10 * a_minus_b + ab_ab * J2) * t16) * t16 + T(8) * t12 * a_minus_b) + T(48) * t17 * a_minus_b) * t16 + T(128) * ab_ap * t18 + T(128) * t19 * a_minus_b) * t16 + T(1280) * ab_ap * t8 + T(1280) * t13 * a_minus_b;
    const T t21 = T(15360) * ab_ap * t9 + T(15360) * t14 * a_minus_b + T(13) * ab_ab * t20 * t16;
    const T t22 = T(1) / ab_ab;
    const T t23 = T(15360) * t9 + ab_ap * t21 * t16 - T(15360) * t14;
    const T t24 = t21 * ap_ap * t16 - T(14) * t20 * t16 - T(2) * t22 * t23 * ab_ap;
    F = (T(1) / T(215040)) * t21 * in.w[0] * t16 + (T(1) / T(215040)) * t22 * in.w[1] * t23 - (T(1) / T(215040)) * t22 * (t22 * t23 * ap_ap + T(2) * t22 * ab_ap * t24 - T(14) * t22 * (t20 * ab_ap * t16 + T(1280) * t8 - T(1280) * t13)) * in.w[3] - (T(1) / T(215040)) * t22 * in.w[2] * t24;
    const T t25 = t17 * t17;
    const T t26 = t15 * t15;
    const T t27 = ab_ab * t21 * t16 + T(14336) * t25 * a_minus_b + T(14336) * ab_ap * t26;
    const T t28 = ab_ap * t27 * t16 + T(14336) * t26 - T(14336) * t25;
    const T t29 = T(16) * t21 * t16 + T(30) * t22 * t28 * ab_ap - T(15) * ap_ap * t27 * t16;
    const T t30 = T(2) * t22 * ab_ap * t29 + T(16) * t22 * t23 - T(15) * t22 * t28 * ap_ap;
    G_ap = (T(1) / T(229376)) * t22 * in.w[1] * t28 + (T(1) / T(3440640)) * t22 * in.w[3] * t30 + (T(1) / T(3440640)) * t22 * in.w[2] * t29 + (T(1) / T(229376)) * t27 * in.w[0] * t16;
    G_ab = (T(1) / T(3440640)) * t22 * in.w[1] * t29 + (T(1) / T(3440640)) * t22 * in.w[2] * t30 + (T(1) / T(229376)) * t22 * t28 * in.w[0] - (T(1) / T(3440640)) * t22 * in.w[3] * (t22 * t29 * ap_ap + T(16) * t22 * t24 - T(2) * t22 * ab_ap * t30);
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Returns false where segment_inverse_i16_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 72 +, 194 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_inverse_i16_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = cross_cross - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(7) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 4, ab_ab, ab_ap, ap_ap, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ap = M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + in.w[3] * M_flat[8];
    G_ab = in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + M_flat[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(cross_cross);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, ap_bp) * t4;
    const T t5 = T(1) / ab_ab;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t14 * t14;
    const T t16 = t15 * t12;
    const T t17 = t7 * t7;
    const T t18 = t13 * t13;
    const T t19 = t17 * t6;
    const T t20 = t18 * t12;
    const T t21 = T(11) * (T(3) * t11 * ab_ab * (T(7) * (T(8) * t14 * a_minus_b + T(8) * t8 * ab_ap + T(5) * t11 * ab_ab * (T(2) * t7 * ab_ap + T(3) * (ab_ab * J2 + t12 * a_minus_b + t6 * ab_ap) * t11 * ab_ab + T(2) * t13 * a_minus_b)) * t11 * ab_ab + T(48) * t17 * ab_ap + T(48) * t18 * a_minus_b) + T(128) * t19 * ab_ap + T(128) * t20 * a_minus_b) * t11 * ab_ab + T(1280) * t15 * a_minus_b + T(1280) * t9 * ab_ap;
    const T t22 = T(15360) * t16 * a_minus_b + T(13) * t11 * ab_ab * t21 + T(15360) * t10 * ab_ap;
    const T t23 = T(15360) * t10 + t11 * t22 * ab_ap - T(15360) * t16;
    const T t24 = T(2) * t5 * t23 * ab_ap + T(14) * t11 * t21 - ap_ap * t11 * t22;
    F = (T(1) / T(215040)) * t5 * in.w[1] * t23 + (T(1) / T(215040)) * t5 * t24 * in.w[2] + (T(1) / T(215040)) * in.w[3] * t5 * (T(14) * (T(1280) * t9 + t11 * ab_ap * t21 - T(1280) * t15) * t5 + T(2) * t5 * t24 * ab_ap - ap_ap * t5 * t23) + (T(1) / T(215040)) * in.w[0] * t11 * t22;
    const T t25 = t18 * t18;
    const T t26 = t17 * t17;
    const T t27 = t11 * ab_ab * t22 + T(14336) * t25 * a_minus_b + T(14336) * t26 * ab_ap;
    const T t28 = t11 * ab_ap * t27 + T(14336) * t26 - T(14336) * t25;
    const T t29 = T(30) * t28 * t5 * ab_ap + T(16) * t11 * t22 - T(15) * ap_ap * t11 * t27;
    const T t30 = T(16) * t5 * t23 + T(2) * t5 * ab_ap * t29 - T(15) * ap_ap * t28 * t5;
    G_ap = (T(1) / T(229376)) * t28 * t5 * in.w[1] + (T(1) / T(229376)) * in.w[0] * t11 * t27 + (T(1) / T(3440640)) * t30 * in.w[3] * t5 + (T(1) / T(3440640)) * t5 * t29 * in.w[2];
    G_ab = (T(1) / T(229376)) * t28 * in.w[0] * t5 + (T(1) / T(3440640)) * t30 * t5 * in.w[2] + (T(1) / T(3440640)) * (T(2) * t30 * t5 * ab_ap + T(16) * t5 * t24 - ap_ap * t5 * t29) * in.w[3] * t5 + (T(1) / T(3440640)) * t5 * in.w[1] * t29;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

}  // namespace skelconv::generated
