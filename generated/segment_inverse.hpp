// generated/segment_inverse.hpp — segment kernels of the inverse family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC §2, Hubert 2012 §3).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/stable_recurrence.hpp>
#include <skelconv/segment_input.hpp>

namespace skelconv::generated {

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 25 +, 30 ×, 2 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 26 +, 30 ×, 2 /, 3 sqrt, 0 atan, 1 log/asinh.
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
    // recurrence (1) upwards from J_1, J_2
    F = in.w[0] * J1;
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 31 +, 44 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t2 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    G_ab = -t3 * (t4 - t5 - ab_ap * t2) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = T(1) / r0;
    const T t7 = T(1) / r1;
    const T t8 = ab_ap * t6 + a_minus_b * t7;
    const T t9 = T(1) / cross_cross;
    G_ap = t8 * in.w[0] * t9;
    const T t10 = T(1) / ab_ab;
    G_ab = -t10 * (t7 - t6 - t8 * ab_ap * t9) * in.w[0];
  }
  const T g_factor = -length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 32 +, 52 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * length * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = J1 * in.w[0];
    F = t7;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t8 * in.w[0];
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = T(1) / ab_ab;
    G_ab = -(t9 - t10 - ab_ap * t8) * in.w[0] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = J1 * in.w[0];
    F = t12;
    const T t13 = T(1) / r0;
    const T t14 = T(1) / r1;
    const T t15 = ab_ap * t13 + t14 * a_minus_b;
    const T t16 = T(1) / cross_cross;
    G_ap = t15 * in.w[0] * t16;
    const T t17 = T(1) / ab_ab;
    G_ab = -(t14 - t13 - ab_ap * t15 * t16) * in.w[0] * t17;
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 28 +, 34 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 29 +, 34 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
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
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    X = (t1 + ab_ap * r1) * length / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t2 - ab_ap * r1);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / ab_ab;
    F = in.w[0] * J1 - (r0 - J1 * ab_ap - r1) * in.w[1] * t4;
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 36 +, 59 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = -ab_ap;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, t7, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / ab_ab;
    const T t10 = T(1) / r0;
    const T t11 = T(1) / r1;
    const T t12 = t10 + ab_ap * t8 - t11;
    G_ap = in.w[0] * t8 + t9 * t12 * in.w[1];
    G_ab = t9 * (J1 + T(2) * t9 * t12 * ab_ap - ap_ap * t8) * in.w[1] + t9 * t12 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = a_minus_b * t13 + ab_ap * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / ab_ab;
    const T t18 = ab_ap * t15 * t16 + t14 - t13;
    G_ap = in.w[0] * t15 * t16 + t17 * t18 * in.w[1];
    G_ab = t17 * t18 * in.w[0] + t17 * (J1 + T(2) * t17 * t18 * ab_ap - t15 * ap_ap * t16) * in.w[1];
  }
  const T g_factor = -length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 39 +, 64 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * (t2 + r0 * a_minus_b) * length;
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
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = T(1) / ab_ab;
    const T t8 = in.w[0] * J1 - t7 * (r0 - r1 - ab_ap * J1) * in.w[1];
    F = t8;
    const T t9 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t10 = T(1) / r1;
    const T t11 = T(1) / r0;
    const T t12 = t10 - t9 * ab_ap - t11;
    G_ap = t9 * in.w[0] - t12 * t7 * in.w[1];
    G_ab = -t12 * t7 * in.w[0] - t7 * (T(2) * t12 * t7 * ab_ap + t9 * ap_ap - J1) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / ab_ab;
    const T t14 = in.w[0] * J1 - t13 * (r0 - r1 - ab_ap * J1) * in.w[1];
    F = t14;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = t16 * ab_ap + t17 * a_minus_b;
    const T t19 = t17 - t15 * ab_ap * t18 - t16;
    G_ap = t15 * in.w[0] * t18 - t19 * t13 * in.w[1];
    G_ab = -t13 * (T(2) * t19 * t13 * ab_ap + t15 * t18 * ap_ap - J1) * in.w[1] - t19 * t13 * in.w[0];
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 33 +, 46 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 34 +, 46 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    X = length * (t1 + ab_ap * r1) / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t2 - ab_ap * r1);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / ab_ab;
    const T t5 = r0 - r1 - J1 * ab_ap;
    F = J1 * in.w[0] - (T(1) / T(2)) * t4 * (T(2) * J1 * ap_ap + T(4) * t4 * t5 * ab_ap - t4 * (r1 * a_minus_b + cross_cross * J1 + r0 * ab_ap)) * in.w[2] - t4 * t5 * in.w[1];
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 42 +, 70 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
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
  T X;
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = -(a_minus_b - ab_ap) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T G_ap;
  T G_ab;
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = -ab_ap;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, t7, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 + t8 * ab_ap - t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(2) * ab_ap * t11 * t12 + J1 - t8 * ap_ap;
    G_ap = in.w[0] * t8 + in.w[1] * t11 * t12 + t13 * in.w[2] * t12;
    const T t14 = ab_ap * J1 + r1 - r0;
    G_ab = t13 * in.w[1] * t12 + in.w[0] * t11 * t12 + in.w[2] * t12 * (T(2) * t13 * ab_ap * t12 + t14 * t12 - ap_ap * t11 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = a_minus_b * t15 + ab_ap * t16;
    const T t18 = T(1) / cross_cross;
    const T t19 = t16 + ab_ap * t17 * t18 - t15;
    const T t20 = T(1) / ab_ab;
    const T t21 = J1 + T(2) * ab_ap * t19 * t20 - ap_ap * t17 * t18;
    G_ap = in.w[0] * t17 * t18 + in.w[1] * t19 * t20 + t21 * in.w[2] * t20;
    const T t22 = ab_ap * J1 + r1 - r0;
    G_ab = t21 * in.w[1] * t20 + in.w[0] * t19 * t20 - in.w[2] * (ap_ap * t19 * t20 - t22 * t20 - T(2) * t21 * ab_ap * t20) * t20;
  }
  const T g_factor = -length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 48 +, 86 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * length * (t2 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = length * (ab_ap - a_minus_b) / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = J1 * ab_ap + r1 - r0;
    const T t8 = T(1) / ab_ab;
    const T t9 = in.w[1] * t7 * t8 + J1 * in.w[0] - (T(1) / T(2)) * in.w[2] * t8 * (T(2) * ap_ap * J1 - t8 * (J1 * cross_cross + r0 * ab_ap + r1 * a_minus_b) - T(4) * t7 * t8 * ab_ap);
    F = t9;
    const T t10 = T(1) / r0;
    const T t11 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = T(1) / r1;
    const T t13 = t10 + t11 * ab_ap - t12;
    const T t14 = T(2) * t13 * t8 * ab_ap + J1 - ap_ap * t11;
    G_ap = in.w[2] * t14 * t8 + in.w[1] * t13 * t8 + t11 * in.w[0];
    G_ab = in.w[1] * t14 * t8 + t13 * t8 * in.w[0] - in.w[2] * t8 * (ap_ap * t13 * t8 - t7 * t8 - T(2) * t14 * t8 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = J1 * ab_ap + r1 - r0;
    const T t16 = T(1) / ab_ab;
    const T t17 = in.w[1] * t15 * t16 + J1 * in.w[0] - (T(1) / T(2)) * in.w[2] * t16 * (T(2) * ap_ap * J1 - t16 * (J1 * cross_cross + r0 * ab_ap + r1 * a_minus_b) - T(4) * t15 * t16 * ab_ap);
    F = t17;
    const T t18 = T(1) / r0;
    const T t19 = T(1) / r1;
    const T t20 = t18 * ab_ap + t19 * a_minus_b;
    const T t21 = T(1) / cross_cross;
    const T t22 = t20 * t21 * ab_ap + t18 - t19;
    const T t23 = J1 + T(2) * t22 * t16 * ab_ap - ap_ap * t20 * t21;
    G_ap = in.w[2] * t16 * t23 + in.w[1] * t22 * t16 + t20 * t21 * in.w[0];
    G_ab = t22 * t16 * in.w[0] + (t15 * t16 + T(2) * t16 * ab_ap * t23 - ap_ap * t22 * t16) * in.w[2] * t16 + in.w[1] * t16 * t23;
  }
  const T g_factor = -length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 38 +, 63 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 39 +, 63 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
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
  const T t0 = a_minus_b * ab_ap;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * ab_ap;
    X = (t1 + a_minus_b * r0) * length / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = r1 * ab_ap;
    X = -(a_minus_b - ab_ap) * length / (t2 - a_minus_b * r0);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / ab_ab;
    const T t5 = r0 * ab_ap + cross_cross * J1 + r1 * a_minus_b;
    const T t6 = r1 + J1 * ab_ap - r0;
    const T t7 = t4 * t5 + T(4) * t4 * t6 * ab_ap - T(2) * ap_ap * J1;
    F = in.w[0] * J1 + (T(1) / T(2)) * t7 * in.w[2] * t4 + t4 * t6 * in.w[1] - (T(1) / T(6)) * in.w[3] * t4 * (t4 * (T(2) * ap_ap * r0 - T(2) * r1 * bp_bp - T(3) * t4 * t5 * ab_ap) + T(6) * ap_ap * t4 * t6 - T(6) * t7 * t4 * ab_ap);
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 50 +, 91 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
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
    const T t1 = T(1) / cross_cross;
    const T t2 = ab_ap * r1;
    X = t1 * length * (t2 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = T(1) / r0;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r1;
    const T t10 = t7 + ab_ap * t8 - t9;
    const T t11 = T(1) / ab_ab;
    const T t12 = r1 + ab_ap * J1 - r0;
    const T t13 = t11 * t12;
    const T t14 = ap_ap * t8 - J1 - T(2) * ab_ap * t10 * t11;
    const T t15 = t13 - t10 * ap_ap * t11 - T(2) * ab_ap * t14 * t11;
    G_ap = in.w[1] * t10 * t11 + in.w[0] * t8 + t15 * in.w[3] * t11 - in.w[2] * t14 * t11;
    const T t16 = T(2) * ap_ap * J1 - t11 * (cross_cross * J1 + ab_ap * r0 + r1 * a_minus_b) - T(4) * ab_ap * t11 * t12;
    G_ab = t10 * in.w[0] * t11 + (T(1) / T(2)) * in.w[3] * t11 * (T(4) * ab_ap * t15 * t11 + T(2) * ap_ap * t14 * t11 - t11 * t16) + in.w[2] * t15 * t11 - in.w[1] * t14 * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / r0;
    const T t19 = T(1) / r1;
    const T t20 = t19 * a_minus_b + ab_ap * t18;
    const T t21 = T(1) / cross_cross;
    const T t22 = t18 + ab_ap * t20 * t21 - t19;
    const T t23 = r1 + ab_ap * J1 - r0;
    const T t24 = t17 * t23;
    const T t25 = ap_ap * t20 * t21 - T(2) * ab_ap * t17 * t22 - J1;
    const T t26 = t24 - ap_ap * t17 * t22 - T(2) * ab_ap * t25 * t17;
    G_ap = in.w[1] * t17 * t22 + t26 * in.w[3] * t17 + t20 * t21 * in.w[0] - in.w[2] * t25 * t17;
    const T t27 = T(2) * ap_ap * J1 - t17 * (cross_cross * J1 + ab_ap * r0 + r1 * a_minus_b) - T(4) * ab_ap * t17 * t23;
    G_ab = in.w[2] * t26 * t17 + in.w[0] * t17 * t22 - (T(1) / T(2)) * (t17 * t27 - T(4) * ab_ap * t26 * t17 - T(2) * ap_ap * t25 * t17) * in.w[3] * t17 - in.w[1] * t25 * t17;
  }
  const T g_factor = -length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 57 +, 115 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = a_minus_b * r0;
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = -length * (ab_ap - a_minus_b) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T F;
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = T(1) / ab_ab;
    const T t8 = r1 + J1 * ab_ap - r0;
    const T t9 = J1 * cross_cross + ab_ap * r0 + r1 * a_minus_b;
    const T t10 = T(4) * t7 * t8 * ab_ap + t7 * t9 - T(2) * J1 * ap_ap;
    const T t11 = J1 * in.w[0] + t7 * t8 * in.w[1] + (T(1) / T(2)) * t10 * t7 * in.w[2] - (T(1) / T(6)) * in.w[3] * t7 * (t7 * (T(2) * ap_ap * r0 - T(3) * t7 * t9 * ab_ap - T(2) * r1 * bp_bp) + T(6) * t7 * t8 * ap_ap - T(6) * t10 * t7 * ab_ap);
    F = t11;
    const T t12 = T(1) / r0;
    const T t13 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t14 = T(1) / r1;
    const T t15 = t12 + t13 * ab_ap - t14;
    const T t16 = J1 + T(2) * t15 * t7 * ab_ap - t13 * ap_ap;
    const T t17 = t15 * t7 * ap_ap - t7 * t8 - T(2) * t7 * t16 * ab_ap;
    G_ap = t7 * t16 * in.w[2] + in.w[0] * t13 + t15 * t7 * in.w[1] - in.w[3] * t7 * t17;
    const T t18 = t10 * t7;
    G_ab = t15 * in.w[0] * t7 + t7 * in.w[1] * t16 + (T(1) / T(2)) * in.w[3] * t7 * (t18 - T(2) * t7 * t16 * ap_ap - T(4) * t7 * t17 * ab_ap) - t7 * t17 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / ab_ab;
    const T t20 = r1 + J1 * ab_ap - r0;
    const T t21 = J1 * cross_cross + ab_ap * r0 + r1 * a_minus_b;
    const T t22 = T(4) * t19 * t20 * ab_ap + t19 * t21 - T(2) * J1 * ap_ap;
    const T t23 = J1 * in.w[0] + t19 * t20 * in.w[1] + (T(1) / T(2)) * t22 * t19 * in.w[2] - (T(1) / T(6)) * in.w[3] * t19 * (t19 * (T(2) * ap_ap * r0 - T(3) * t19 * t21 * ab_ap - T(2) * r1 * bp_bp) + T(6) * t19 * t20 * ap_ap - T(6) * t22 * t19 * ab_ap);
    F = t23;
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = t25 * a_minus_b + ab_ap * t24;
    const T t27 = T(1) / cross_cross;
    const T t28 = t24 + t26 * t27 * ab_ap - t25;
    const T t29 = J1 + T(2) * t28 * t19 * ab_ap - t26 * t27 * ap_ap;
    const T t30 = t19 * t20 + T(2) * t29 * t19 * ab_ap - t28 * t19 * ap_ap;
    G_ap = t28 * t19 * in.w[1] + t26 * t27 * in.w[0] + in.w[3] * t19 * t30 + t29 * t19 * in.w[2];
    const T t31 = t22 * t19;
    G_ab = t29 * t19 * in.w[1] + t19 * in.w[2] * t30 + (T(1) / T(2)) * in.w[3] * t19 * (t31 + T(4) * t19 * ab_ap * t30 - T(2) * t29 * t19 * ap_ap) + t28 * in.w[0] * t19;
  }
  const T g_factor = -length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 27 +, 32 ×, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(2), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T J2 = atan2(t2, ap_bp) / t2;
    F = J2 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 34 +, 52 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ap_ap;
    const T t4 = T(1) / bp_bp;
    const T t5 = T(1) / ab_ab;
    G_ab = (T(1) / T(2)) * (t3 + T(2) * ab_ap * t2 - t4) * in.w[0] * t5;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(cross_cross);
    const T t7 = T(1) / t6;
    const T J2 = atan2(t6, ap_bp) * t7;
    const T t8 = T(1) / cross_cross;
    const T t9 = T(1) / bp_bp;
    const T t10 = T(1) / ap_ap;
    const T t11 = t9 * a_minus_b + ab_ab * J2 + ab_ap * t10;
    G_ap = (T(1) / T(2)) * in.w[0] * t8 * t11;
    const T t12 = T(1) / ab_ab;
    G_ab = (T(1) / T(2)) * (t10 + ab_ap * t8 * t11 - t9) * in.w[0] * t12;
  }
  const T g_factor = -T(2) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 34 +, 54 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / bp_bp;
    const T t5 = T(1) / ap_ap;
    F = in.w[0] * t2 * (T(2) * t3 * cross_cross - a_minus_b * t4 - t5 * ab_ap);
    G_ap = t3 * in.w[0];
    G_ab = -(T(1) / T(2)) * (t4 - T(2) * t3 * ab_ap - t5) * in.w[0] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(cross_cross);
    const T t7 = T(1) / t6;
    const T J2 = atan2(t6, ap_bp) * t7;
    F = in.w[0] * J2;
    const T t8 = T(1) / bp_bp;
    const T t9 = T(1) / ap_ap;
    const T t10 = a_minus_b * t8 + t9 * ab_ap + ab_ab * J2;
    const T t11 = T(1) / cross_cross;
    G_ap = (T(1) / T(2)) * t10 * in.w[0] * t11;
    const T t12 = T(1) / ab_ab;
    G_ab = -(T(1) / T(2)) * in.w[0] * t12 * (t8 - t10 * t11 * ab_ap - t9);
  }
  const T g_factor = -T(2) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 29 +, 37 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    F = t2 * in.w[0] + (T(1) / T(2)) * t3 * (log_ratio + T(2) * t2 * ab_ap) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(cross_cross);
    const T J2 = atan2(t4, ap_bp) / t4;
    const T t5 = T(1) / ab_ab;
    F = in.w[0] * J2 + (T(1) / T(2)) * t5 * (T(2) * ab_ap * J2 + log_ratio) * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 38 +, 64 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / bp_bp;
    const T t5 = t2 + T(2) * ab_ap * t3 - t4;
    const T t6 = T(1) / ab_ab;
    G_ap = (T(1) / T(2)) * t5 * in.w[1] * t6 + in.w[0] * t3;
    const T t7 = t4 * a_minus_b;
    const T t8 = ab_ap * t2;
    G_ab = (T(1) / T(2)) * t5 * in.w[0] * t6 - in.w[1] * t6 * ((t7 + t8 - T(2) * cross_cross * t3) * t6 + ap_ap * t3 - ab_ap * t5 * t6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, ap_bp) * t10;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * a_minus_b;
    const T t13 = T(1) / ap_ap;
    const T t14 = ab_ap * t13;
    const T t15 = t12 + ab_ab * J2 + t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / ab_ab;
    const T t18 = t13 + ab_ap * t15 * t16 - t11;
    G_ap = (T(1) / T(2)) * t15 * in.w[0] * t16 + (T(1) / T(2)) * in.w[1] * t17 * t18;
    G_ab = (T(1) / T(2)) * in.w[0] * t17 * t18 + (T(1) / T(2)) * (T(2) * ab_ap * t17 * t18 + T(2) * J2 - t15 * ap_ap * t16) * in.w[1] * t17;
  }
  const T g_factor = -T(2) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 40 +, 72 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = ab_ap * t0;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * a_minus_b;
    const T t7 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = t4 + t6 - T(2) * t7 * cross_cross;
    F = -(T(1) / T(2)) * in.w[1] * t3 * (T(2) * ab_ap * t8 * t3 - log_ratio) - in.w[0] * t8 * t3;
    const T t9 = T(2) * t7 * ab_ap + t0 - t5;
    G_ap = (T(1) / T(2)) * t9 * in.w[1] * t3 + t7 * in.w[0];
    G_ab = (T(1) / T(2)) * t9 * in.w[0] * t3 - (t8 * t3 + t7 * ap_ap - t9 * ab_ap * t3) * in.w[1] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, ap_bp) * t11;
    const T t12 = T(1) / ab_ab;
    F = J2 * in.w[0] + (T(1) / T(2)) * (T(2) * ab_ap * J2 + log_ratio) * in.w[1] * t12;
    const T t13 = T(1) / cross_cross;
    const T t14 = ab_ap * t0;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * a_minus_b;
    const T t17 = t14 + t16 + J2 * ab_ab;
    const T t18 = t0 + ab_ap * t13 * t17 - t15;
    G_ap = (T(1) / T(2)) * t18 * in.w[1] * t12 + (T(1) / T(2)) * in.w[0] * t13 * t17;
    G_ab = (T(1) / T(2)) * in.w[1] * (T(2) * J2 + T(2) * ab_ap * t18 * t12 - ap_ap * t13 * t17) * t12 + (T(1) / T(2)) * in.w[0] * t18 * t12;
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 32 +, 42 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(2) * t2 * ab_ap + log_ratio;
    const T t4 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[1] * t3 * t4 + t2 * in.w[0] - in.w[2] * (ap_ap * t2 - t3 * t4 * ab_ap - T(1)) * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(cross_cross);
    const T J2 = atan2(t5, ap_bp) / t5;
    const T t6 = log_ratio + T(2) * J2 * ab_ap;
    const T t7 = T(1) / ab_ab;
    F = (T(1) / T(2)) * t6 * in.w[1] * t7 + J2 * in.w[0] - (ap_ap * J2 - t6 * t7 * ab_ap - T(1)) * in.w[2] * t7;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 43 +, 79 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ab_ab;
    const T t5 = T(1) / bp_bp;
    const T t6 = t0 + T(2) * t3 * ab_ap - t5;
    const T t7 = a_minus_b * t5;
    const T t8 = t0 * ab_ap;
    const T t9 = t7 + t8 - T(2) * cross_cross * t3;
    const T t10 = t4 * ab_ap * t6 - t9 * t4 - ap_ap * t3;
    G_ap = t3 * in.w[0] + (T(1) / T(2)) * in.w[1] * t4 * t6 + in.w[2] * t4 * t10;
    G_ab = (T(1) / T(2)) * t4 * in.w[0] * t6 + (T(1) / T(2)) * in.w[2] * t4 * (T(4) * t4 * t10 * ab_ap + t4 * (log_ratio - T(2) * t9 * t4 * ab_ap) - ap_ap * t4 * t6) + in.w[1] * t4 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / bp_bp;
    const T t15 = a_minus_b * t14;
    const T t16 = t0 * ab_ap;
    const T t17 = t15 + t16 + ab_ab * J2;
    const T t18 = t13 * t17 * ab_ap + t0 - t14;
    const T t19 = T(1) / ab_ab;
    const T t20 = ap_ap * t13 * t17 - T(2) * J2 - T(2) * t18 * t19 * ab_ap;
    G_ap = (T(1) / T(2)) * t13 * t17 * in.w[0] + (T(1) / T(2)) * t18 * in.w[1] * t19 - (T(1) / T(2)) * t20 * in.w[2] * t19;
    G_ab = (T(1) / T(2)) * t18 * t19 * in.w[0] + (T(1) / T(2)) * ((log_ratio + T(2) * J2 * ab_ap) * t19 - t18 * ap_ap * t19 - T(2) * t20 * t19 * ab_ap) * in.w[2] * t19 - (T(1) / T(2)) * in.w[1] * t20 * t19;
  }
  const T g_factor = -T(2) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 47 +, 89 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(1) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * a_minus_b;
    const T t6 = ab_ap * t0;
    const T t7 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = t5 + t6 - T(2) * cross_cross * t7;
    const T t9 = log_ratio - T(2) * t3 * t8 * ab_ap;
    F = (T(1) / T(2)) * t3 * t9 * in.w[1] + in.w[2] * (t3 * t9 * ab_ap + t3 * t8 * ap_ap + T(1)) * t3 - t3 * t8 * in.w[0];
    const T t10 = T(2) * ab_ap * t7 + t0 - t4;
    const T t11 = t3 * t10 * ab_ap - ap_ap * t7 - t3 * t8;
    G_ap = in.w[0] * t7 + (T(1) / T(2)) * t3 * t10 * in.w[1] + in.w[2] * t11 * t3;
    G_ab = (T(1) / T(2)) * t3 * t10 * in.w[0] + (T(1) / T(2)) * in.w[2] * t3 * (t3 * t9 + T(4) * t11 * t3 * ab_ap - t3 * t10 * ap_ap) + t11 * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / ab_ab;
    const T t15 = T(2) * ab_ap * J2 + log_ratio;
    F = in.w[0] * J2 + (T(1) / T(2)) * t14 * t15 * in.w[1] - in.w[2] * t14 * (J2 * ap_ap - t14 * ab_ap * t15 - T(1));
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * a_minus_b;
    const T t18 = ab_ap * t0;
    const T t19 = t17 + t18 + ab_ab * J2;
    const T t20 = T(1) / cross_cross;
    const T t21 = t16 - t19 * t20 * ab_ap - t0;
    const T t22 = t19 * t20 * ap_ap + T(2) * t14 * ab_ap * t21 - T(2) * J2;
    G_ap = (T(1) / T(2)) * t19 * t20 * in.w[0] - (T(1) / T(2)) * in.w[2] * t14 * t22 - (T(1) / T(2)) * t14 * t21 * in.w[1];
    G_ab = -(T(1) / T(2)) * in.w[2] * t14 * (T(2) * t14 * t22 * ab_ap - t14 * t15 - t14 * t21 * ap_ap) - (T(1) / T(2)) * t14 * t22 * in.w[1] - (T(1) / T(2)) * t14 * in.w[0] * t21;
  }
  const T g_factor = -T(2) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 37 +, 52 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T log_ratio = log(bp_bp / ap_ap);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = log_ratio + T(2) * t2 * ab_ap;
    const T t5 = t2 * ap_ap - ab_ap * t3 * t4 - T(1);
    F = t2 * in.w[0] + (T(1) / T(2)) * in.w[1] * t3 * t4 - in.w[2] * t5 * t3 - (T(1) / T(2)) * (ap_ap * t3 * t4 + T(4) * ab_ap * t5 * t3 - (bp_bp + T(2) * ab_ap - ap_ap) * t3) * in.w[3] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(cross_cross);
    const T J2 = atan2(t6, ap_bp) / t6;
    const T t7 = T(1) / ab_ab;
    const T t8 = T(2) * ab_ap * J2 + log_ratio;
    const T t9 = ap_ap * J2 - ab_ap * t7 * t8 - T(1);
    F = J2 * in.w[0] + (T(1) / T(2)) * in.w[1] * t7 * t8 - (T(1) / T(2)) * (ap_ap * t7 * t8 + T(4) * ab_ap * t9 * t7 - (bp_bp + T(2) * ab_ap - ap_ap) * t7) * in.w[3] * t7 - t9 * in.w[2] * t7;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 49 +, 95 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = (T(1) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = T(2) * ab_ap * t4 + t0 - t5;
    const T t7 = T(2) * t4 * cross_cross - a_minus_b * t5 - ab_ap * t0;
    const T t8 = ap_ap * t4 - t3 * t7 - t3 * ab_ap * t6;
    const T t9 = log_ratio + T(2) * t3 * ab_ap * t7;
    const T t10 = t3 * ap_ap * t6 + T(4) * t3 * ab_ap * t8 - t3 * t9;
    G_ap = (T(1) / T(2)) * t3 * in.w[1] * t6 + t4 * in.w[0] - (T(1) / T(2)) * t3 * t10 * in.w[3] - t3 * in.w[2] * t8;
    G_ab = (T(1) / T(2)) * t3 * t6 * in.w[0] + t3 * (t3 * ap_ap * t8 + t3 * (t3 * t9 * ab_ap + T(1) - t3 * ap_ap * t7) - t3 * t10 * ab_ap) * in.w[3] - t3 * in.w[1] * t8 - (T(1) / T(2)) * t3 * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / bp_bp;
    const T t15 = ab_ab * J2 + a_minus_b * t14 + ab_ap * t0;
    const T t16 = T(1) / cross_cross;
    const T t17 = ab_ap * t15 * t16 + t0 - t14;
    const T t18 = T(2) * t17 * t13 * ab_ap + T(2) * J2 - ap_ap * t15 * t16;
    const T t19 = log_ratio + T(2) * J2 * ab_ap;
    const T t20 = t13 * t19 + T(2) * t13 * ab_ap * t18 - t17 * t13 * ap_ap;
    G_ap = (T(1) / T(2)) * t13 * t18 * in.w[2] + (T(1) / T(2)) * t17 * t13 * in.w[1] + (T(1) / T(2)) * t13 * t20 * in.w[3] + (T(1) / T(2)) * t15 * t16 * in.w[0];
    G_ab = (T(1) / T(2)) * t13 * in.w[1] * t18 + (T(1) / T(2)) * t13 * t20 * in.w[2] + (T(1) / T(2)) * t17 * t13 * in.w[0] - (T(1) / T(2)) * t13 * (t13 * t18 * ap_ap + T(2) * t13 * (J2 * ap_ap - t13 * ab_ap * t19 - T(1)) - T(2) * t13 * ab_ap * t20) * in.w[3];
  }
  const T g_factor = -T(2) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 56 +, 112 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(t0 * bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = t3 * (T(2) * ab_ap + bp_bp - ap_ap);
    const T t5 = T(1) / bp_bp;
    const T t6 = a_minus_b * t5;
    const T t7 = ab_ap * t0;
    const T t8 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t6 + t7 - T(2) * t8 * cross_cross;
    const T t10 = T(2) * ab_ap * t3 * t9 - log_ratio;
    const T t11 = ab_ap * t10 * t3 - ap_ap * t3 * t9 - T(1);
    F = (T(1) / T(2)) * (t4 + t10 * ap_ap * t3 - T(4) * ab_ap * t11 * t3) * in.w[3] * t3 - (T(1) / T(2)) * in.w[1] * t10 * t3 - in.w[0] * t3 * t9 - in.w[2] * t11 * t3;
    const T t12 = t5 - t0 - T(2) * t8 * ab_ap;
    const T t13 = t3 * t9 + t8 * ap_ap + ab_ap * t12 * t3;
    const T t14 = T(4) * ab_ap * t3 * t13 + t10 * t3 - ap_ap * t12 * t3;
    G_ap = t8 * in.w[0] - (T(1) / T(2)) * in.w[3] * t3 * t14 - (T(1) / T(2)) * in.w[1] * t12 * t3 - in.w[2] * t3 * t13;
    G_ab = -(t11 * t3 + ab_ap * t3 * t14 - ap_ap * t3 * t13) * in.w[3] * t3 - in.w[1] * t3 * t13 - (T(1) / T(2)) * in.w[2] * t3 * t14 - (T(1) / T(2)) * in.w[0] * t12 * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, ap_bp) * t16;
    const T t17 = T(2) * ab_ap * J2 + log_ratio;
    const T t18 = T(1) / ab_ab;
    const T t19 = ab_ap * t17 * t18 + T(1) - J2 * ap_ap;
    const T t20 = t18 * (T(2) * ab_ap + bp_bp - ap_ap);
    F = in.w[2] * t19 * t18 + (T(1) / T(2)) * in.w[3] * (t20 + T(4) * ab_ap * t19 * t18 - ap_ap * t17 * t18) * t18 + J2 * in.w[0] + (T(1) / T(2)) * in.w[1] * t17 * t18;
    const T t21 = T(1) / bp_bp;
    const T t22 = a_minus_b * t21;
    const T t23 = ab_ap * t0;
    const T t24 = t22 + t23 + J2 * ab_ab;
    const T t25 = T(1) / cross_cross;
    const T t26 = t21 - t0 - ab_ap * t24 * t25;
    const T t27 = t24 * ap_ap * t25 + T(2) * ab_ap * t26 * t18 - T(2) * J2;
    const T t28 = t26 * ap_ap * t18 + t17 * t18 - T(2) * ab_ap * t27 * t18;
    G_ap = (T(1) / T(2)) * t24 * t25 * in.w[0] + (T(1) / T(2)) * t28 * in.w[3] * t18 - (T(1) / T(2)) * in.w[1] * t26 * t18 - (T(1) / T(2)) * in.w[2] * t27 * t18;
    G_ab = (T(1) / T(2)) * in.w[3] * (T(2) * ab_ap * t28 * t18 + ap_ap * t27 * t18 + T(2) * t19 * t18) * t18 + (T(1) / T(2)) * t28 * in.w[2] * t18 - (T(1) / T(2)) * t26 * in.w[0] * t18 - (T(1) / T(2)) * in.w[1] * t27 * t18;
  }
  const T g_factor = -T(2) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 26 +, 29 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    F = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = (a_minus_b / r1 + ab_ap / r0) * in.w[0] / cross_cross;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 33 +, 58 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t4 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    G_ab = (T(1) / T(3)) * in.w[0] * t3 * (T(3) * t2 * ab_ap + t6 - t8 * t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = T(1) / cross_cross;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = a_minus_b * t11 * t10 + ab_ap * t12 * t13 + T(2) * t9 * ab_ab * (ab_ap * t12 + a_minus_b * t10);
    G_ap = (T(1) / T(3)) * in.w[0] * t9 * t14;
    const T t15 = T(1) / ab_ab;
    const T t16 = t12 * t13;
    G_ab = (T(1) / T(3)) * in.w[0] * t15 * (t16 + t9 * t14 * ab_ap - t11 * t10);
  }
  const T g_factor = -T(3) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 33 +, 61 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = ab_ap * t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t6 * t7 * a_minus_b;
    const T t9 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -(T(1) / T(2)) * in.w[0] * t2 * (t5 + t8 - T(3) * cross_cross * t9);
    G_ap = in.w[0] * t9;
    const T t10 = t4 * t3;
    G_ab = (T(1) / T(3)) * in.w[0] * t2 * (T(3) * t9 * ab_ap + t10 - t6 * t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / r0;
    const T t13 = T(1) / r1;
    const T t14 = ab_ap * t12 + t13 * a_minus_b;
    F = in.w[0] * t11 * t14;
    const T t15 = t12 * t12;
    const T t16 = ab_ap * t15 * t12;
    const T t17 = t13 * t13;
    const T t18 = t13 * t17 * a_minus_b;
    const T t19 = t16 + t18 + T(2) * ab_ab * t11 * t14;
    G_ap = (T(1) / T(3)) * in.w[0] * t11 * t19;
    const T t20 = T(1) / ab_ab;
    const T t21 = t15 * t12;
    G_ab = (T(1) / T(3)) * in.w[0] * t20 * (t21 + t11 * ab_ap * t19 - t13 * t17);
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 29 +, 36 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t2 = J_downward<T>(T(3), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / ab_ab;
    F = (t2 * ab_ap + t3 - t4) * in.w[1] * t5 + t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = T(1) / cross_cross;
    const T t7 = T(1) / r0;
    const T t8 = T(1) / r1;
    const T t9 = ab_ap * t7 + t8 * a_minus_b;
    const T t10 = T(1) / ab_ab;
    F = in.w[0] * t6 * t9 + in.w[1] * (t7 + ab_ap * t6 * t9 - t8) * t10;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 37 +, 71 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = T(3) * ab_ap * t2 + t4 * t5 - t7 * t6;
    G_ap = t2 * in.w[0] + (T(1) / T(3)) * in.w[1] * t3 * t8;
    const T t9 = ab_ap * t4 * t5;
    const T t10 = a_minus_b * t7 * t6;
    G_ab = (T(1) / T(3)) * t3 * t8 * in.w[0] - (T(1) / T(6)) * in.w[1] * t3 * (T(6) * t2 * ap_ap + T(3) * t3 * (t9 + t10 - T(3) * cross_cross * t2) - T(4) * t3 * ab_ap * t8);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = ab_ap * t12 * t13;
    const T t15 = T(1) / r1;
    const T t16 = a_minus_b * t15 + ab_ap * t12;
    const T t17 = t15 * t15;
    const T t18 = a_minus_b * t17 * t15;
    const T t19 = t14 + T(2) * t11 * ab_ab * t16 + t18;
    const T t20 = T(1) / ab_ab;
    const T t21 = t17 * t15 - t12 * t13 - t11 * ab_ap * t19;
    G_ap = (T(1) / T(3)) * t11 * t19 * in.w[0] - (T(1) / T(3)) * in.w[1] * t20 * t21;
    G_ab = -(T(1) / T(3)) * t20 * t21 * in.w[0] - (T(1) / T(3)) * in.w[1] * t20 * (t11 * t19 * ap_ap + T(2) * t20 * t21 * ab_ap - T(3) * t11 * t16);
  }
  const T g_factor = -T(3) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 40 +, 78 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2 * ab_ap;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t5 * t6 * a_minus_b;
    const T t8 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t4 + t7 - T(3) * t8 * cross_cross;
    const T t10 = T(1) / ab_ab;
    F = -(T(1) / T(2)) * in.w[0] * t9 * t10 - (T(1) / T(2)) * in.w[1] * t10 * (t9 * t10 * ab_ap + T(2) * t5 - T(2) * t2);
    const T t11 = t3 * t2;
    const T t12 = t11 + T(3) * t8 * ab_ap - t5 * t6;
    G_ap = (T(1) / T(3)) * t12 * in.w[1] * t10 + in.w[0] * t8;
    G_ab = (T(1) / T(6)) * (T(4) * t12 * t10 * ab_ap - T(3) * t9 * t10 - T(6) * ap_ap * t8) * in.w[1] * t10 + (T(1) / T(3)) * in.w[0] * t12 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + t15 * ab_ap;
    const T t17 = T(1) / ab_ab;
    F = in.w[0] * t13 * t16 + (t13 * ab_ap * t16 + t15 - t14) * in.w[1] * t17;
    const T t18 = t15 * t15;
    const T t19 = t18 * t15 * ab_ap;
    const T t20 = t14 * t14;
    const T t21 = t14 * t20 * a_minus_b;
    const T t22 = T(2) * t13 * ab_ab * t16 + t19 + t21;
    const T t23 = t18 * t15;
    const T t24 = t22 * t13 * ab_ap + t23 - t14 * t20;
    G_ap = (T(1) / T(3)) * t22 * in.w[0] * t13 + (T(1) / T(3)) * t24 * in.w[1] * t17;
    G_ab = (T(1) / T(3)) * in.w[0] * t24 * t17 - (T(1) / T(3)) * in.w[1] * t17 * (t22 * ap_ap * t13 - T(3) * t13 * t16 - T(2) * t24 * t17 * ab_ap);
  }
  const T g_factor = -T(3) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 33 +, 49 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
    X = (a_minus_b - ab_ap) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = -ab_ap;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, t7, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / ab_ab;
    const T t10 = T(1) / r0;
    const T t11 = T(1) / r1;
    const T t12 = t8 * ab_ap + t10 - t11;
    F = t8 * in.w[0] + t9 * t12 * in.w[1] + in.w[2] * t9 * (T(2) * t9 * t12 * ab_ap + J1 - ap_ap * t8);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = t15 * ab_ap + a_minus_b * t16;
    const T t18 = t14 * ab_ap * t17 + t15 - t16;
    F = t13 * t18 * in.w[1] + t14 * in.w[0] * t17 - (ap_ap * t14 * t17 - J1 - T(2) * t13 * t18 * ab_ap) * in.w[2] * t13;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 43 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t6 - t7 * t8 - T(3) * t2 * ab_ap;
    const T t10 = T(3) * t2 * cross_cross - a_minus_b * t5 * t4 - ab_ap * t7 * t8;
    const T t11 = T(4) * t3 * ab_ap * t9 + T(6) * t2 * ap_ap - T(3) * t3 * t10;
    G_ap = t2 * in.w[0] - (T(1) / T(3)) * t3 * in.w[1] * t9 - (T(1) / T(6)) * in.w[2] * t3 * t11;
    G_ab = -(T(1) / T(6)) * t3 * t11 * in.w[1] - (T(1) / T(6)) * in.w[2] * t3 * (T(2) * t3 * t11 * ab_ap - T(3) * t3 * (t3 * t10 * ab_ap + T(2) * t7 - T(2) * t4) - T(2) * t3 * t9 * ap_ap) - (T(1) / T(3)) * t3 * in.w[0] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = ab_ap * t15 + a_minus_b * t13;
    const T t18 = a_minus_b * t14 * t13 + ab_ap * t15 * t16 + T(2) * t12 * ab_ab * t17;
    const T t19 = t14 * t13;
    const T t20 = t19 - t15 * t16 - t12 * t18 * ab_ap;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(3) * t12 * t17 - T(2) * t20 * t21 * ab_ap - t12 * t18 * ap_ap;
    G_ap = (T(1) / T(3)) * t12 * t18 * in.w[0] + (T(1) / T(3)) * t22 * in.w[2] * t21 - (T(1) / T(3)) * t20 * t21 * in.w[1];
    G_ab = (T(1) / T(3)) * t22 * t21 * in.w[1] - (T(1) / T(3)) * in.w[2] * t21 * (T(3) * t21 * (t13 - t15 - t12 * ab_ap * t17) - t20 * t21 * ap_ap - T(2) * t22 * t21 * ab_ap) - (T(1) / T(3)) * t20 * t21 * in.w[0];
  }
  const T g_factor = -T(3) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 48 +, 104 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 47 +, 106 ×, 5 /, 3 sqrt, 0 atan, 1 log/asinh, 1 other.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * length * (t2 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = length * (ab_ap - a_minus_b) / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t7 = T(1) / ab_ab;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t8 * t9 * a_minus_b;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11 * ab_ap;
    const T t14 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = t10 + t13 - T(3) * cross_cross * t14;
    const T t16 = T(2) * t8 + t7 * ab_ap * t15 - T(2) * t11;
    F = -(T(1) / T(2)) * t7 * t16 * in.w[1] - (T(1) / T(2)) * in.w[2] * t7 * (T(2) * t7 * ab_ap * t16 - T(2) * J1 - ap_ap * t7 * t15) - (T(1) / T(2)) * t7 * in.w[0] * t15;
    const T t17 = T(3) * t14 * ab_ap + t12 * t11 - t8 * t9;
    const T t18 = T(4) * t7 * t17 * ab_ap - T(3) * t7 * t15 - T(6) * ap_ap * t14;
    G_ap = t14 * in.w[0] + (T(1) / T(3)) * t7 * t17 * in.w[1] + (T(1) / T(6)) * in.w[2] * t7 * t18;
    G_ab = (T(1) / T(6)) * (T(2) * t7 * t18 * ab_ap - T(3) * t7 * t16 - T(2) * ap_ap * t7 * t17) * in.w[2] * t7 + (T(1) / T(3)) * t7 * in.w[0] * t17 + (T(1) / T(6)) * t7 * t18 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = t20 * a_minus_b + t21 * ab_ap;
    const T t23 = t20 - t19 * t22 * ab_ap - t21;
    const T t24 = T(1) / ab_ab;
    F = t19 * t22 * in.w[0] - in.w[2] * (T(2) * t23 * t24 * ab_ap + ap_ap * t19 * t22 - J1) * t24 - t23 * t24 * in.w[1];
    const T t25 = t20 * t20;
    const T t26 = t20 * t25 * a_minus_b;
    const T t27 = t21 * t21;
    const T t28 = t27 * t21 * ab_ap;
    const T t29 = t26 + T(2) * t19 * ab_ab * t22 + t28;
    const T t30 = t20 * t25 - t19 * ab_ap * t29 - t27 * t21;
    const T t31 = ap_ap * t19 * t29 + T(2) * t30 * t24 * ab_ap - T(3) * t19 * t22;
    G_ap = (T(1) / T(3)) * t19 * in.w[0] * t29 - (T(1) / T(3)) * t30 * t24 * in.w[1] - (T(1) / T(3)) * in.w[2] * t24 * t31;
    G_ab = -(T(1) / T(3)) * in.w[2] * t24 * (T(3) * t23 * t24 + T(2) * t24 * ab_ap * t31 - ap_ap * t30 * t24) - (T(1) / T(3)) * t30 * t24 * in.w[0] - (T(1) / T(3)) * t24 * t31 * in.w[1];
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 38 +, 58 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
    X = -(a_minus_b - ab_ap) * length / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  T F;
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = (T(1) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t7 = -ab_ap;
    const T t8 = J_downward<T>(T(3), ab_ab, cross_cross, t7, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t8 * ab_ap + t9 - t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = ap_ap * t8 - T(2) * t11 * t12 * ab_ap - J1;
    const T t14 = r0 - J1 * ab_ap - r1;
    F = t8 * in.w[0] + t11 * t12 * in.w[1] - t13 * t12 * in.w[2] - in.w[3] * t12 * (t14 * t12 + T(2) * t13 * t12 * ab_ap + t11 * ap_ap * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = t16 * ab_ap + a_minus_b * t17;
    const T t19 = T(1) / ab_ab;
    const T t20 = t17 - t15 * t18 * ab_ap - t16;
    const T t21 = r0 - J1 * ab_ap - r1;
    const T t22 = ap_ap * t15 * t18 + T(2) * t20 * t19 * ab_ap - J1;
    F = t15 * in.w[0] * t18 + in.w[3] * t19 * (ap_ap * t20 * t19 - t21 * t19 - T(2) * t19 * t22 * ab_ap) - t20 * t19 * in.w[1] - t19 * t22 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 50 +, 110 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
    X = t1 * (t2 + r0 * a_minus_b) * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = length * (ab_ap - a_minus_b) / (t3 - r0 * a_minus_b);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  T G_ap;
  T G_ab;
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(3) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t7 * t8;
    const T t10 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t9 + T(3) * ab_ap * t10 - t11 * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(3) * cross_cross * t10 - t11 * a_minus_b * t12 - ab_ap * t7 * t8;
    const T t16 = T(3) * t15 * t14 + T(4) * ab_ap * t13 * t14 - T(6) * ap_ap * t10;
    const T t17 = ab_ap * t15 * t14 + T(2) * t7 - T(2) * t11;
    const T t18 = T(3) * t14 * t17 + T(2) * t16 * ab_ap * t14 - T(2) * ap_ap * t13 * t14;
    G_ap = (T(1) / T(3)) * t13 * t14 * in.w[1] + (T(1) / T(6)) * t16 * in.w[2] * t14 + (T(1) / T(6)) * in.w[3] * t18 * t14 + in.w[0] * t10;
    G_ab = (T(1) / T(6)) * t16 * t14 * in.w[1] + (T(1) / T(3)) * in.w[0] * t13 * t14 + (T(1) / T(6)) * in.w[2] * t18 * t14 - (T(1) / T(6)) * (T(3) * (ap_ap * t15 * t14 - T(2) * J1 - T(2) * ab_ap * t14 * t17) * t14 + t16 * ap_ap * t14 - T(2) * ab_ap * t18 * t14) * in.w[3] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t19 * t20;
    const T t22 = T(1) / cross_cross;
    const T t23 = T(1) / r1;
    const T t24 = t23 * a_minus_b + ab_ap * t19;
    const T t25 = t23 * t23;
    const T t26 = T(2) * t22 * t24 * ab_ab + t23 * a_minus_b * t25 + ab_ap * t19 * t20;
    const T t27 = t21 + ab_ap * t26 * t22 - t23 * t25;
    const T t28 = T(1) / ab_ab;
    const T t29 = T(2) * ab_ap * t27 * t28 + T(3) * t22 * t24 - ap_ap * t26 * t22;
    const T t30 = ab_ap * t22 * t24 + t19 - t23;
    const T t31 = T(3) * t30 * t28 + T(2) * ab_ap * t29 * t28 - ap_ap * t27 * t28;
    G_ap = (T(1) / T(3)) * t27 * t28 * in.w[1] + (T(1) / T(3)) * t26 * in.w[0] * t22 + (T(1) / T(3)) * in.w[2] * t29 * t28 + (T(1) / T(3)) * in.w[3] * t28 * t31;
    G_ab = (T(1) / T(3)) * in.w[2] * t28 * t31 + (T(1) / T(3)) * t27 * in.w[0] * t28 + (T(1) / T(3)) * t29 * t28 * in.w[1] - (T(1) / T(3)) * (T(3) * (ap_ap * t22 * t24 - J1 - T(2) * t30 * ab_ap * t28) * t28 + ap_ap * t29 * t28 - T(2) * ab_ap * t28 * t31) * in.w[3] * t28;
  }
  const T g_factor = -T(3) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 57 +, 126 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 56 +, 130 ×, 5 /, 3 sqrt, 0 atan, 1 log/asinh, 1 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / cross_cross;
    const T t2 = r1 * ab_ap;
    X = t1 * length * (t2 + r0 * a_minus_b);
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
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t5 >= T(0) && t6 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t7 * t8 * a_minus_b;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10 * ab_ap;
    const T t13 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t14 = t9 + t12 - T(3) * cross_cross * t13;
    const T t15 = T(1) / ab_ab;
    const T t16 = t14 * t15 * ab_ap + T(2) * t7 - T(2) * t10;
    const T t17 = T(2) * J1 + t14 * ap_ap * t15 - T(2) * t16 * t15 * ab_ap;
    const T t18 = r0 - J1 * ab_ap - r1;
    F = (T(1) / T(2)) * in.w[2] * t17 * t15 + (T(1) / T(2)) * (ap_ap * t16 * t15 + T(2) * t17 * t15 * ab_ap - T(2) * t18 * t15) * in.w[3] * t15 - (T(1) / T(2)) * t16 * t15 * in.w[1] - (T(1) / T(2)) * t14 * in.w[0] * t15;
    const T t19 = t11 * t10;
    const T t20 = t19 + T(3) * t13 * ab_ap - t7 * t8;
    const T t21 = T(6) * ap_ap * t13 + T(3) * t14 * t15 - T(4) * t15 * t20 * ab_ap;
    const T t22 = T(3) * t16 * t15 + T(2) * t15 * t21 * ab_ap + T(2) * ap_ap * t15 * t20;
    G_ap = in.w[0] * t13 + (T(1) / T(3)) * t15 * in.w[1] * t20 - (T(1) / T(6)) * in.w[2] * t15 * t21 - (T(1) / T(6)) * in.w[3] * t15 * t22;
    G_ab = (T(1) / T(6)) * in.w[3] * (T(3) * t17 * t15 + ap_ap * t15 * t21 - T(2) * t15 * ab_ap * t22) * t15 + (T(1) / T(3)) * in.w[0] * t15 * t20 - (T(1) / T(6)) * in.w[2] * t15 * t22 - (T(1) / T(6)) * t15 * t21 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / r0;
    const T t24 = T(1) / r1;
    const T t25 = t24 * a_minus_b + t23 * ab_ap;
    const T t26 = T(1) / cross_cross;
    const T t27 = t23 + t25 * t26 * ab_ap - t24;
    const T t28 = T(1) / ab_ab;
    const T t29 = T(2) * t27 * t28 * ab_ap + J1 - ap_ap * t25 * t26;
    const T t30 = r0 - J1 * ab_ap - r1;
    F = in.w[2] * t29 * t28 + t25 * t26 * in.w[0] + (T(2) * t29 * t28 * ab_ap - ap_ap * t27 * t28 - t30 * t28) * in.w[3] * t28 + t27 * t28 * in.w[1];
    const T t31 = t24 * t24;
    const T t32 = t24 * t31 * a_minus_b;
    const T t33 = t23 * t23;
    const T t34 = t33 * t23 * ab_ap;
    const T t35 = t32 + t34 + T(2) * t25 * t26 * ab_ab;
    const T t36 = t33 * t23;
    const T t37 = t26 * t35 * ab_ap + t36 - t24 * t31;
    const T t38 = T(2) * t28 * t37 * ab_ap + T(3) * t25 * t26 - ap_ap * t26 * t35;
    const T t39 = T(3) * t27 * t28 + T(2) * t28 * t38 * ab_ap - ap_ap * t28 * t37;
    G_ap = (T(1) / T(3)) * t39 * in.w[3] * t28 + (T(1) / T(3)) * in.w[2] * t28 * t38 + (T(1) / T(3)) * t28 * t37 * in.w[1] + (T(1) / T(3)) * t26 * in.w[0] * t35;
    G_ab = (T(1) / T(3)) * in.w[2] * t39 * t28 + (T(1) / T(3)) * t28 * in.w[1] * t38 + (T(1) / T(3)) * in.w[0] * t28 * t37 - (T(1) / T(3)) * in.w[3] * (ap_ap * t28 * t38 - T(3) * t29 * t28 - T(2) * t39 * t28 * ab_ap) * t28;
  }
  const T g_factor = -T(3) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 29 +, 36 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, ap_bp);
    const T t4 = T(1) / cross_cross;
    F = (T(1) / T(2)) * (a_minus_b / bp_bp + ab_ap / ap_ap + J2 * ab_ab) * in.w[0] * t4;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 36 +, 63 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    G_ab = (T(1) / T(4)) * t3 * (t5 + T(4) * ab_ap * t2 - t7) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, ap_bp) * t9;
    const T t10 = T(1) / bp_bp;
    const T t11 = t10 * t10;
    const T t12 = T(1) / ap_ap;
    const T t13 = T(1) / cross_cross;
    const T t14 = t12 * t12;
    const T t15 = T(2) * a_minus_b * t11 + T(3) * ab_ab * (ab_ap * t12 + ab_ab * J2 + a_minus_b * t10) * t13 + T(2) * ab_ap * t14;
    G_ap = (T(1) / T(8)) * t15 * in.w[0] * t13;
    const T t16 = T(1) / ab_ab;
    G_ab = (T(1) / T(8)) * (t15 * ab_ap * t13 + T(2) * t14 - T(2) * t11) * t16 * in.w[0];
  }
  const T g_factor = -T(4) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 36 +, 67 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ab_ab;
    F = (T(1) / T(3)) * (T(4) * t2 * cross_cross - t4 * a_minus_b - ab_ap * t6) * in.w[0] * t7;
    G_ap = t2 * in.w[0];
    G_ab = (T(1) / T(4)) * in.w[0] * (t6 + T(4) * t2 * ab_ap - t4) * t7;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, ap_bp) * t9;
    const T t10 = T(1) / ap_ap;
    const T t11 = T(1) / bp_bp;
    const T t12 = ab_ap * t10 + t11 * a_minus_b + J2 * ab_ab;
    const T t13 = T(1) / cross_cross;
    F = (T(1) / T(2)) * t12 * in.w[0] * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(3) * t12 * t13 * ab_ab + T(2) * t14 * a_minus_b + T(2) * ab_ap * t15;
    G_ap = (T(1) / T(8)) * t16 * in.w[0] * t13;
    const T t17 = T(1) / ab_ab;
    G_ab = (T(1) / T(8)) * in.w[0] * (T(2) * t15 + ab_ap * t16 * t13 - T(2) * t14) * t17;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 32 +, 43 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = T(1) / bp_bp;
    F = (T(1) / T(2)) * in.w[1] * t2 * (T(2) * ab_ap * t3 + t4 - t5) + t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(cross_cross);
    const T t7 = T(1) / t6;
    const T J2 = atan2(t6, ap_bp) * t7;
    const T t8 = T(1) / bp_bp;
    const T t9 = T(1) / ap_ap;
    const T t10 = a_minus_b * t8 + t9 * ab_ap + J2 * ab_ab;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / ab_ab;
    F = (T(1) / T(2)) * t10 * t11 * in.w[0] - (T(1) / T(2)) * (t8 - t9 - t10 * t11 * ab_ap) * in.w[1] * t12;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 40 +, 76 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t4 + T(4) * ab_ap * t2 - t6;
    const T t8 = T(1) / ab_ab;
    G_ap = in.w[0] * t2 + (T(1) / T(4)) * t7 * in.w[1] * t8;
    G_ab = (T(1) / T(4)) * t7 * in.w[0] * t8 + (T(1) / T(6)) * (T(3) * t7 * ab_ap * t8 - T(6) * ap_ap * t2 - T(2) * (a_minus_b * t6 + ab_ap * t4 - T(4) * t2 * cross_cross) * t8) * in.w[1] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, ap_bp) * t10;
    const T t11 = T(1) / bp_bp;
    const T t12 = t11 * t11;
    const T t13 = T(1) / ap_ap;
    const T t14 = t13 * t13;
    const T t15 = ab_ap * t13 + J2 * ab_ab + a_minus_b * t11;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(2) * a_minus_b * t12 + T(2) * ab_ap * t14 + T(3) * t15 * t16 * ab_ab;
    const T t18 = T(2) * t14 + ab_ap * t17 * t16 - T(2) * t12;
    const T t19 = T(1) / ab_ab;
    G_ap = (T(1) / T(8)) * t17 * in.w[0] * t16 + (T(1) / T(8)) * in.w[1] * t18 * t19;
    G_ab = (T(1) / T(8)) * (T(4) * t15 * t16 + T(2) * ab_ap * t18 * t19 - t17 * ap_ap * t16) * in.w[1] * t19 + (T(1) / T(8)) * in.w[0] * t18 * t19;
  }
  const T g_factor = -T(4) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 43 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = t3 * t3;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(4) * cross_cross * t4 - ab_ap * t5 - t7 * a_minus_b;
    F = (T(1) / T(6)) * in.w[1] * t2 * (T(3) * t3 + T(2) * t2 * ab_ap * t8 - T(3) * t6) + (T(1) / T(3)) * t2 * in.w[0] * t8;
    const T t9 = t7 - T(4) * t4 * ab_ap - t5;
    G_ap = t4 * in.w[0] - (T(1) / T(4)) * in.w[1] * t2 * t9;
    G_ab = -(T(1) / T(6)) * in.w[1] * t2 * (T(6) * t4 * ap_ap + T(3) * t2 * ab_ap * t9 - T(2) * t2 * t8) - (T(1) / T(4)) * t2 * in.w[0] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / bp_bp;
    const T t14 = T(1) / ap_ap;
    const T t15 = t13 * a_minus_b + ab_ap * t14 + ab_ab * J2;
    const T t16 = T(1) / ab_ab;
    F = (T(1) / T(2)) * t12 * t15 * in.w[0] + (T(1) / T(2)) * in.w[1] * t16 * (t14 + t12 * t15 * ab_ap - t13);
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = T(2) * ab_ap * t17 + T(2) * t18 * a_minus_b + T(3) * t12 * ab_ab * t15;
    const T t20 = t12 * ab_ap * t19 + T(2) * t17 - T(2) * t18;
    G_ap = (T(1) / T(8)) * in.w[1] * t16 * t20 + (T(1) / T(8)) * t12 * in.w[0] * t19;
    G_ab = (T(1) / T(8)) * t16 * t20 * in.w[0] - (T(1) / T(8)) * in.w[1] * t16 * (t12 * ap_ap * t19 - T(4) * t12 * t15 - T(2) * t16 * t20 * ab_ap);
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 35 +, 52 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = T(1) / bp_bp;
    const T t6 = T(2) * t3 * ab_ap + t4 - t5;
    F = (T(1) / T(2)) * in.w[1] * t2 * t6 + t2 * in.w[2] * (t2 * t6 * ab_ap + t2 * (T(2) * t3 * cross_cross - a_minus_b * t5 - t4 * ab_ap) - t3 * ap_ap) + t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = sqrt(cross_cross);
    const T t8 = T(1) / t7;
    const T J2 = t8 * atan2(t7, ap_bp);
    const T t9 = T(1) / ab_ab;
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / bp_bp;
    const T t12 = T(1) / ap_ap;
    const T t13 = J2 * ab_ab + a_minus_b * t11 + t12 * ab_ap;
    const T t14 = t10 * t13 * ab_ap + t12 - t11;
    F = (T(1) / T(2)) * in.w[1] * t9 * t14 + (T(1) / T(2)) * in.w[0] * t10 * t13 - (T(1) / T(2)) * (ap_ap * t10 * t13 - T(2) * J2 - T(2) * t9 * t14 * ab_ap) * t9 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 46 +, 91 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = T(4) * ab_ap * t2 + t4 - t6;
    const T t8 = T(1) / ab_ab;
    const T t9 = t4 * ab_ap + a_minus_b * t6 - T(4) * cross_cross * t2;
    const T t10 = T(2) * t8 * t9 + T(6) * ap_ap * t2 - T(3) * t7 * t8 * ab_ap;
    G_ap = (T(1) / T(4)) * t7 * t8 * in.w[1] + in.w[0] * t2 - (T(1) / T(6)) * in.w[2] * t8 * t10;
    G_ab = (T(1) / T(4)) * t7 * t8 * in.w[0] - (T(1) / T(6)) * t8 * t10 * in.w[1] - (T(1) / T(12)) * in.w[2] * (T(2) * t8 * (T(2) * t8 * ab_ap * t9 + T(3) * t5 - T(3) * t3) + T(3) * ap_ap * t7 * t8 + T(4) * t8 * t10 * ab_ap) * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = T(1) / bp_bp;
    const T t17 = a_minus_b * t16 + ab_ab * J2 + t14 * ab_ap;
    const T t18 = t16 * t16;
    const T t19 = T(2) * t15 * ab_ap + T(3) * t13 * t17 * ab_ab + T(2) * a_minus_b * t18;
    const T t20 = t13 * t19 * ab_ap + T(2) * t15 - T(2) * t18;
    const T t21 = T(1) / ab_ab;
    const T t22 = ap_ap * t13 * t19 - T(4) * t13 * t17 - T(2) * t20 * t21 * ab_ap;
    G_ap = (T(1) / T(8)) * t20 * t21 * in.w[1] + (T(1) / T(8)) * t13 * t19 * in.w[0] - (T(1) / T(8)) * in.w[2] * t21 * t22;
    G_ab = (T(1) / T(8)) * t20 * t21 * in.w[0] - (T(1) / T(8)) * t21 * t22 * in.w[1] - (T(1) / T(8)) * in.w[2] * t21 * (ap_ap * t20 * t21 + T(2) * t21 * t22 * ab_ap + T(4) * t21 * (t16 - t14 - t13 * t17 * ab_ap));
  }
  const T g_factor = -T(4) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 50 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / bp_bp;
    const T t3 = t2 * t2;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t7 = t3 * a_minus_b + ab_ap * t5 - T(4) * t6 * cross_cross;
    const T t8 = T(1) / ab_ab;
    const T t9 = T(2) * ab_ap * t7 * t8 + T(3) * t2 - T(3) * t4;
    F = -(T(1) / T(6)) * t9 * in.w[1] * t8 - (T(1) / T(3)) * in.w[2] * (t9 * ab_ap * t8 + (T(2) * cross_cross * t7 * t8 + T(3) * ab_ap * t4 + T(3) * t2 * a_minus_b) * t8 - ap_ap * t7 * t8) * t8 - (T(1) / T(3)) * in.w[0] * t7 * t8;
    const T t10 = t5 + T(4) * ab_ap * t6 - t3;
    const T t11 = T(6) * ap_ap * t6 + T(2) * t7 * t8 - T(3) * t10 * ab_ap * t8;
    G_ap = in.w[0] * t6 + (T(1) / T(4)) * t10 * in.w[1] * t8 - (T(1) / T(6)) * t11 * in.w[2] * t8;
    G_ab = (T(1) / T(4)) * in.w[0] * t10 * t8 - (T(1) / T(12)) * (T(3) * t10 * ap_ap * t8 + T(2) * t9 * t8 + T(4) * ab_ap * t11 * t8) * in.w[2] * t8 - (T(1) / T(6)) * in.w[1] * t11 * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / ap_ap;
    const T t16 = T(1) / bp_bp;
    const T t17 = ab_ap * t15 + t16 * a_minus_b + J2 * ab_ab;
    const T t18 = ab_ap * t14 * t17 + t15 - t16;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(2)) * in.w[1] * t18 * t19 + (T(1) / T(2)) * in.w[0] * t14 * t17 - (T(1) / T(2)) * (ap_ap * t14 * t17 - T(2) * J2 - T(2) * ab_ap * t18 * t19) * in.w[2] * t19;
    const T t20 = t16 * t16;
    const T t21 = t15 * t15;
    const T t22 = T(3) * t14 * ab_ab * t17 + T(2) * t20 * a_minus_b + T(2) * ab_ap * t21;
    const T t23 = t22 * ab_ap * t14 + T(2) * t21 - T(2) * t20;
    const T t24 = T(2) * ab_ap * t23 * t19 + T(4) * t14 * t17 - t22 * ap_ap * t14;
    G_ap = (T(1) / T(8)) * t23 * in.w[1] * t19 + (T(1) / T(8)) * t24 * in.w[2] * t19 + (T(1) / T(8)) * in.w[0] * t22 * t14;
    G_ab = (T(1) / T(8)) * in.w[0] * t23 * t19 + (T(1) / T(8)) * (T(4) * t18 * t19 + T(2) * t24 * ab_ap * t19 - t23 * ap_ap * t19) * in.w[2] * t19 + (T(1) / T(8)) * t24 * in.w[1] * t19;
  }
  const T g_factor = -T(4) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 39 +, 64 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(1) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(T(4), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ab_ab;
    const T t5 = ab_ap * t0;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * a_minus_b;
    const T t8 = t5 + t7 - T(2) * t3 * cross_cross;
    const T t9 = t6 - t0 - T(2) * t3 * ab_ap;
    const T t10 = t3 * ap_ap + t4 * t8 + t9 * t4 * ab_ap;
    F = t3 * in.w[0] - (T(1) / T(2)) * t4 * (T(4) * t4 * ab_ap * t10 - t9 * t4 * ap_ap - t4 * (log_ratio - T(2) * t4 * t8 * ab_ap)) * in.w[3] - t4 * in.w[2] * t10 - (T(1) / T(2)) * t9 * t4 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / bp_bp;
    const T t15 = ab_ap * t0;
    const T t16 = t14 * a_minus_b;
    const T t17 = t15 + t16 + ab_ab * J2;
    const T t18 = T(1) / cross_cross;
    const T t19 = t14 - t17 * ab_ap * t18 - t0;
    const T t20 = t17 * ap_ap * t18 + T(2) * t13 * t19 * ab_ap - T(2) * J2;
    F = (T(1) / T(2)) * t13 * (t13 * (log_ratio + T(2) * ab_ap * J2) + t13 * t19 * ap_ap - T(2) * t20 * t13 * ab_ap) * in.w[3] + (T(1) / T(2)) * t17 * t18 * in.w[0] - (T(1) / T(2)) * t13 * t19 * in.w[1] - (T(1) / T(2)) * t20 * t13 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 52 +, 110 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t4 + T(4) * t5 * ab_ap - t7;
    const T t9 = a_minus_b * t7 + ab_ap * t4 - T(4) * cross_cross * t5;
    const T t10 = T(6) * t5 * ap_ap + T(2) * t2 * t9 - T(3) * t2 * t8 * ab_ap;
    const T t11 = T(2) * t2 * t9 * ab_ap + T(3) * t6 - T(3) * t3;
    const T t12 = T(3) * t2 * t8 * ap_ap + T(2) * t2 * t11 + T(4) * t2 * t10 * ab_ap;
    G_ap = (T(1) / T(4)) * t2 * t8 * in.w[1] + in.w[0] * t5 - (T(1) / T(6)) * t2 * t10 * in.w[2] - (T(1) / T(12)) * t12 * in.w[3] * t2;
    G_ab = (T(1) / T(4)) * in.w[0] * t2 * t8 + (T(1) / T(6)) * in.w[3] * t2 * (t2 * t10 * ap_ap - T(2) * t2 * (t2 * (T(2) * cross_cross * t2 * t9 + T(3) * ab_ap * t3 + T(3) * a_minus_b * t6) + t2 * ab_ap * t11 - t2 * t9 * ap_ap) - t12 * t2 * ab_ap) - (T(1) / T(6)) * t2 * in.w[1] * t10 - (T(1) / T(12)) * t12 * t2 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, ap_bp);
    const T t15 = T(1) / ap_ap;
    const T t16 = t15 * t15;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / bp_bp;
    const T t19 = t18 * t18;
    const T t20 = ab_ap * t15 + ab_ab * J2 + a_minus_b * t18;
    const T t21 = T(2) * a_minus_b * t19 + T(3) * t17 * ab_ab * t20 + T(2) * ab_ap * t16;
    const T t22 = T(2) * t16 + t17 * ab_ap * t21 - T(2) * t19;
    const T t23 = T(1) / ab_ab;
    const T t24 = t17 * t20 * ab_ap + t15 - t18;
    const T t25 = T(4) * t17 * t20 + T(2) * t22 * t23 * ab_ap - t17 * t21 * ap_ap;
    const T t26 = T(4) * t23 * t24 + T(2) * t23 * ab_ap * t25 - t22 * t23 * ap_ap;
    G_ap = (T(1) / T(8)) * t22 * t23 * in.w[1] + (T(1) / T(8)) * t17 * in.w[0] * t21 + (T(1) / T(8)) * in.w[3] * t26 * t23 + (T(1) / T(8)) * t23 * in.w[2] * t25;
    G_ab = (T(1) / T(8)) * in.w[3] * t23 * (T(4) * t23 * (T(2) * t23 * t24 * ab_ap + T(2) * J2 - t17 * t20 * ap_ap) + T(2) * t26 * t23 * ab_ap - t23 * ap_ap * t25) + (T(1) / T(8)) * t26 * t23 * in.w[2] + (T(1) / T(8)) * t23 * in.w[1] * t25 + (T(1) / T(8)) * t22 * in.w[0] * t23;
  }
  const T g_factor = -T(4) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 58 +, 132 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = T(1) / ap_ap;
  const T log_ratio = log(bp_bp * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t3 = T(1) / ab_ab;
    const T t4 = t0 * t0;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = ab_ap * t4 + t6 * a_minus_b - T(4) * t7 * cross_cross;
    const T t9 = T(2) * t3 * ab_ap * t8 + T(3) * t5 - T(3) * t0;
    const T t10 = T(3) * t5 * a_minus_b + T(2) * t3 * t8 * cross_cross + T(3) * ab_ap * t0;
    const T t11 = t3 * ap_ap * t8 - t3 * ab_ap * t9 - t3 * t10;
    F = (T(1) / T(3)) * t3 * t11 * in.w[2] + (T(1) / T(6)) * t3 * (t3 * ap_ap * t9 + T(4) * t3 * t11 * ab_ap - t3 * (T(2) * t3 * t10 * ab_ap - T(3) * log_ratio)) * in.w[3] - (T(1) / T(6)) * t3 * in.w[1] * t9 - (T(1) / T(3)) * t3 * t8 * in.w[0];
    const T t12 = t4 + T(4) * t7 * ab_ap - t6;
    const T t13 = T(2) * t3 * t8 + T(6) * t7 * ap_ap - T(3) * t3 * ab_ap * t12;
    const T t14 = T(3) * t3 * ap_ap * t12 + T(2) * t3 * t9 + T(4) * t3 * ab_ap * t13;
    G_ap = (T(1) / T(4)) * t3 * in.w[1] * t12 + t7 * in.w[0] - (T(1) / T(12)) * t3 * t14 * in.w[3] - (T(1) / T(6)) * t3 * t13 * in.w[2];
    G_ab = (T(1) / T(4)) * t3 * t12 * in.w[0] - (T(1) / T(6)) * t3 * (t3 * ab_ap * t14 - t3 * t13 * ap_ap - T(2) * t3 * t11) * in.w[3] - (T(1) / T(6)) * t3 * in.w[1] * t13 - (T(1) / T(12)) * t3 * t14 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, ap_bp) * t16;
    const T t17 = T(1) / bp_bp;
    const T t18 = ab_ab * J2 + t17 * a_minus_b + ab_ap * t0;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / ab_ab;
    const T t21 = t18 * ab_ap * t19 + t0 - t17;
    const T t22 = T(2) * t20 * t21 * ab_ap + T(2) * J2 - t18 * ap_ap * t19;
    F = (T(1) / T(2)) * t18 * t19 * in.w[0] + (T(1) / T(2)) * t20 * t21 * in.w[1] + (T(1) / T(2)) * t20 * in.w[2] * t22 - (T(1) / T(2)) * t20 * in.w[3] * (t20 * t21 * ap_ap - t20 * (T(2) * ab_ap * J2 + log_ratio) - T(2) * t20 * ab_ap * t22);
    const T t23 = t0 * t0;
    const T t24 = t17 * t17;
    const T t25 = T(2) * ab_ap * t23 + T(3) * ab_ab * t18 * t19 + T(2) * t24 * a_minus_b;
    const T t26 = T(2) * t23 + t25 * ab_ap * t19 - T(2) * t24;
    const T t27 = T(4) * t18 * t19 + T(2) * t20 * t26 * ab_ap - t25 * ap_ap * t19;
    const T t28 = t20 * t26 * ap_ap - T(2) * t20 * ab_ap * t27 - T(4) * t20 * t21;
    G_ap = (T(1) / T(8)) * t25 * t19 * in.w[0] + (T(1) / T(8)) * t20 * t26 * in.w[1] + (T(1) / T(8)) * t20 * in.w[2] * t27 - (T(1) / T(8)) * t20 * t28 * in.w[3];
    G_ab = (T(1) / T(8)) * t20 * in.w[1] * t27 + (T(1) / T(8)) * t20 * t26 * in.w[0] - (T(1) / T(8)) * t20 * (T(2) * t20 * ab_ap * t28 + t20 * ap_ap * t27 - T(4) * t20 * t22) * in.w[3] - (T(1) / T(8)) * t20 * in.w[2] * t28;
  }
  const T g_factor = -T(4) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 28 +, 38 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / cross_cross;
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    F = (T(1) / T(3)) * in.w[0] * t2 * (T(2) * t2 * ab_ab * (t3 * ab_ap + a_minus_b * t4) + a_minus_b * t4 / bp_bp + t3 * ab_ap / ap_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 35 +, 71 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    G_ab = (T(1) / T(5)) * in.w[0] * t3 * (T(5) * t2 * ab_ap + t4 * t6 - t7 * t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(3) * t11 * t13 * ab_ap + T(3) * t14 * a_minus_b * t16 + T(4) * t10 * ab_ab * (t11 * t12 * ab_ap + t14 * a_minus_b * t15 + T(2) * (t11 * ab_ap + t14 * a_minus_b) * t10 * ab_ab);
    G_ap = (T(1) / T(15)) * in.w[0] * t10 * t17;
    const T t18 = T(1) / ab_ab;
    G_ab = (T(1) / T(15)) * (t10 * t17 * ab_ap + T(3) * t11 * t13 - T(3) * t14 * t16) * in.w[0] * t18;
  }
  const T g_factor = -T(5) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 35 +, 75 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ab_ab;
    F = (T(1) / T(4)) * in.w[0] * (T(5) * t2 * cross_cross - t5 * t3 * ab_ap - t6 * t8 * a_minus_b) * t9;
    G_ap = t2 * in.w[0];
    G_ab = (T(1) / T(5)) * in.w[0] * t9 * (T(5) * t2 * ab_ap + t5 * t3 - t6 * t8);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t11 * t12 * a_minus_b + t14 * t13 * ab_ap + T(2) * t10 * ab_ab * (t13 * ab_ap + t11 * a_minus_b);
    F = (T(1) / T(3)) * in.w[0] * t10 * t15;
    const T t16 = t14 * t14;
    const T t17 = t12 * t12;
    const T t18 = T(4) * t10 * ab_ab * t15 + T(3) * t16 * t13 * ab_ap + T(3) * t11 * t17 * a_minus_b;
    G_ap = (T(1) / T(15)) * t18 * in.w[0] * t10;
    const T t19 = T(1) / ab_ab;
    G_ab = (T(1) / T(15)) * in.w[0] * t19 * (t18 * t10 * ab_ap + T(3) * t16 * t13 - T(3) * t11 * t17);
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 31 +, 49 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    F = in.w[0] * t2 - (T(1) / T(3)) * t3 * (t6 - t7 * t8 - T(3) * ab_ap * t2) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t10 * t9 * a_minus_b + T(2) * ab_ab * t11 * (t9 * a_minus_b + t12 * ab_ap) + t12 * ab_ap * t13;
    const T t15 = T(1) / ab_ab;
    const T t16 = t10 * t9;
    F = (T(1) / T(3)) * t14 * in.w[0] * t11 - (T(1) / T(3)) * t15 * (t16 - t12 * t13 - t14 * ab_ap * t11) * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 39 +, 84 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(5) * t2 * ab_ap + t5 * t3 - t6 * t8;
    const T t10 = T(1) / ab_ab;
    G_ap = t2 * in.w[0] + (T(1) / T(5)) * t9 * in.w[1] * t10;
    G_ab = (T(1) / T(5)) * in.w[0] * t9 * t10 - (T(1) / T(20)) * (T(5) * (t6 * a_minus_b * t8 + t5 * ab_ap * t3 - T(5) * t2 * cross_cross) * t10 + T(20) * t2 * ap_ap - T(8) * t9 * t10 * ab_ap) * in.w[1] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / ab_ab;
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(2) * t12 * (ab_ap * t16 + t13 * a_minus_b) * ab_ab + t17 * ab_ap * t16 + t13 * a_minus_b * t14;
    const T t20 = T(3) * t13 * a_minus_b * t15 + T(3) * t18 * ab_ap * t16 + T(4) * t19 * t12 * ab_ab;
    const T t21 = t12 * t20 * ab_ap + T(3) * t18 * t16 - T(3) * t13 * t15;
    G_ap = (T(1) / T(15)) * in.w[1] * t11 * t21 + (T(1) / T(15)) * in.w[0] * t12 * t20;
    G_ab = (T(1) / T(15)) * in.w[0] * t11 * t21 - (T(1) / T(15)) * (ap_ap * t12 * t20 - T(5) * t19 * t12 - T(2) * t11 * t21 * ab_ap) * in.w[1] * t11;
  }
  const T g_factor = -T(5) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 42 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = T(1) / ab_ab;
    const T t5 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t3 * t3;
    const T t10 = T(5) * cross_cross * t5 - t6 * t8 * a_minus_b - t9 * t2 * ab_ap;
    F = (T(1) / T(12)) * in.w[1] * (T(4) * t3 * t2 + T(3) * t4 * t10 * ab_ap - T(4) * t6 * t7) * t4 + (T(1) / T(4)) * t4 * t10 * in.w[0];
    const T t11 = T(5) * ab_ap * t5 + t9 * t2 - t6 * t8;
    G_ap = t5 * in.w[0] + (T(1) / T(5)) * in.w[1] * t4 * t11;
    G_ab = (T(1) / T(20)) * in.w[1] * t4 * (T(5) * t4 * t10 + T(8) * t4 * t11 * ab_ap - T(20) * ap_ap * t5) + (T(1) / T(5)) * t4 * t11 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t14 * t13 * ab_ap + t15 * t16 * a_minus_b + T(2) * (t15 * a_minus_b + t13 * ab_ap) * t12 * ab_ab;
    const T t18 = T(1) / ab_ab;
    F = (T(1) / T(3)) * t12 * t17 * in.w[0] + (T(1) / T(3)) * in.w[1] * t18 * (t14 * t13 + t12 * t17 * ab_ap - t15 * t16);
    const T t19 = t16 * t16;
    const T t20 = t14 * t14;
    const T t21 = T(4) * t12 * ab_ab * t17 + T(3) * t15 * t19 * a_minus_b + T(3) * t20 * t13 * ab_ap;
    const T t22 = T(3) * t15 * t19 - t21 * t12 * ab_ap - T(3) * t20 * t13;
    G_ap = (T(1) / T(15)) * t21 * t12 * in.w[0] - (T(1) / T(15)) * in.w[1] * t18 * t22;
    G_ab = -(T(1) / T(15)) * in.w[1] * t18 * (T(2) * t18 * t22 * ab_ap + ap_ap * t21 * t12 - T(5) * t12 * t17) - (T(1) / T(15)) * t18 * t22 * in.w[0];
  }
  const T g_factor = -T(5) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 34 +, 59 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t5 - t6 * t7 - T(3) * ab_ap * t2;
    const T t9 = T(1) / ab_ab;
    F = in.w[0] * t2 - (T(1) / T(3)) * t8 * t9 * in.w[1] - (T(1) / T(6)) * t9 * (T(6) * t2 * ap_ap + T(4) * t8 * t9 * ab_ap - T(3) * (T(3) * cross_cross * t2 - t6 * ab_ap * t7 - t4 * t3 * a_minus_b) * t9) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / r0;
    const T t12 = T(1) / r1;
    const T t13 = t11 * ab_ap + t12 * a_minus_b;
    const T t14 = t11 * t11;
    const T t15 = t12 * t12;
    const T t16 = T(2) * t10 * ab_ab * t13 + t11 * ab_ap * t14 + t15 * t12 * a_minus_b;
    const T t17 = T(1) / ab_ab;
    const T t18 = t15 * t12;
    const T t19 = t18 - t11 * t14 - t10 * ab_ap * t16;
    F = (T(1) / T(3)) * t10 * in.w[0] * t16 - (T(1) / T(3)) * t17 * (t10 * t16 * ap_ap + T(2) * t19 * t17 * ab_ap - T(3) * t10 * t13) * in.w[2] - (T(1) / T(3)) * t19 * t17 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 45 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(5) * ab_ap * t3 + t4 * t6 - t9 * t7;
    const T t11 = ab_ap * t4 * t6 + a_minus_b * t9 * t7 - T(5) * t3 * cross_cross;
    const T t12 = T(8) * t2 * ab_ap * t10 - T(20) * t3 * ap_ap - T(5) * t2 * t11;
    G_ap = (T(1) / T(5)) * t2 * in.w[1] * t10 + (T(1) / T(20)) * t2 * t12 * in.w[2] + in.w[0] * t3;
    G_ab = (T(1) / T(20)) * t2 * t12 * in.w[1] + (T(1) / T(5)) * t2 * in.w[0] * t10 - (T(1) / T(60)) * t2 * in.w[2] * (T(5) * t2 * (T(4) * t8 * t7 + T(3) * t2 * ab_ap * t11 - T(4) * t4 * t5) + T(12) * t2 * ap_ap * t10 - T(6) * t2 * ab_ap * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(2) * ab_ab * (a_minus_b * t18 + ab_ap * t15) * t14 + a_minus_b * t19 * t18 + ab_ap * t15 * t16;
    const T t22 = T(3) * ab_ap * t15 * t17 + T(3) * a_minus_b * t20 * t18 + T(4) * ab_ab * t14 * t21;
    const T t23 = ab_ap * t14 * t22 + T(3) * t15 * t17 - T(3) * t20 * t18;
    const T t24 = T(2) * t13 * t23 * ab_ap + T(5) * t14 * t21 - ap_ap * t14 * t22;
    G_ap = (T(1) / T(15)) * t13 * t24 * in.w[2] + (T(1) / T(15)) * in.w[0] * t14 * t22 + (T(1) / T(15)) * t13 * t23 * in.w[1];
    G_ab = (T(1) / T(15)) * t13 * in.w[1] * t24 + (T(1) / T(15)) * t13 * t23 * in.w[0] + (T(1) / T(15)) * t13 * (T(2) * t13 * ab_ap * t24 + T(5) * t13 * (ab_ap * t14 * t21 + t15 * t16 - t19 * t18) - t13 * t23 * ap_ap) * in.w[2];
  }
  const T g_factor = -T(5) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 49 +, 118 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t4 * t4;
    const T t10 = T(5) * t5 * cross_cross - a_minus_b * t6 * t8 - t9 * t3 * ab_ap;
    const T t11 = T(4) * t4 * t3 + T(3) * t10 * t2 * ab_ap - T(4) * t6 * t7;
    F = (T(1) / T(12)) * in.w[1] * t2 * t11 + (T(1) / T(24)) * in.w[2] * t2 * (T(3) * (T(3) * t10 * cross_cross * t2 - T(4) * t4 * t3 * ab_ap - T(4) * a_minus_b * t6 * t7) * t2 + T(4) * t2 * t11 * ab_ap - T(6) * ap_ap * t10 * t2) + (T(1) / T(4)) * t10 * t2 * in.w[0];
    const T t12 = T(5) * t5 * ab_ap + t9 * t3 - t6 * t8;
    const T t13 = T(5) * t10 * t2 + T(8) * t12 * t2 * ab_ap - T(20) * t5 * ap_ap;
    G_ap = (T(1) / T(5)) * in.w[1] * t12 * t2 + t5 * in.w[0] + (T(1) / T(20)) * in.w[2] * t2 * t13;
    G_ab = (T(1) / T(60)) * (T(6) * t2 * t13 * ab_ap + T(5) * t2 * t11 - T(12) * ap_ap * t12 * t2) * in.w[2] * t2 + (T(1) / T(20)) * in.w[1] * t2 * t13 + (T(1) / T(5)) * t12 * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / ab_ab;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t15 * ab_ap + a_minus_b * t17;
    const T t20 = T(1) / cross_cross;
    const T t21 = t16 * t15 * ab_ap + a_minus_b * t17 * t18 + T(2) * t19 * t20 * ab_ab;
    const T t22 = t16 * t15 + t21 * t20 * ab_ap - t17 * t18;
    F = (T(1) / T(3)) * in.w[1] * t14 * t22 + (T(1) / T(3)) * t21 * t20 * in.w[0] - (T(1) / T(3)) * in.w[2] * (t21 * ap_ap * t20 - T(2) * t14 * t22 * ab_ap - T(3) * t19 * t20) * t14;
    const T t23 = t18 * t18;
    const T t24 = t16 * t16;
    const T t25 = T(3) * a_minus_b * t17 * t23 + T(3) * t24 * t15 * ab_ap + T(4) * t21 * t20 * ab_ab;
    const T t26 = t25 * t20 * ab_ap + T(3) * t24 * t15 - T(3) * t17 * t23;
    const T t27 = T(5) * t21 * t20 + T(2) * t26 * t14 * ab_ap - t25 * ap_ap * t20;
    G_ap = (T(1) / T(15)) * in.w[1] * t26 * t14 + (T(1) / T(15)) * t27 * in.w[2] * t14 + (T(1) / T(15)) * t25 * t20 * in.w[0];
    G_ab = (T(1) / T(15)) * t26 * t14 * in.w[0] + (T(1) / T(15)) * (T(2) * t27 * t14 * ab_ap + T(5) * t14 * t22 - ap_ap * t26 * t14) * in.w[2] * t14 + (T(1) / T(15)) * in.w[1] * t27 * t14;
  }
  const T g_factor = -T(5) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 39 +, 71 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t4 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t6 - T(3) * ab_ap * t2 - t8 * t7;
    const T t10 = t4 * a_minus_b * t5;
    const T t11 = ab_ap * t8 * t7;
    const T t12 = t10 + t11 - T(3) * cross_cross * t2;
    const T t13 = T(6) * ap_ap * t2 + T(3) * t12 * t3 + T(4) * ab_ap * t3 * t9;
    F = in.w[0] * t2 + (T(1) / T(6)) * in.w[3] * t3 * (T(2) * ap_ap * t3 * t9 + T(3) * (T(2) * t7 - ab_ap * t12 * t3 - T(2) * t4) * t3 - T(2) * ab_ap * t13 * t3) - (T(1) / T(6)) * in.w[2] * t13 * t3 - (T(1) / T(3)) * t3 * t9 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    const T t16 = t14 * a_minus_b + ab_ap * t15;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / ab_ab;
    const T t19 = t14 * t14;
    const T t20 = t14 * t19;
    const T t21 = t14 * a_minus_b * t19;
    const T t22 = t15 * t15;
    const T t23 = ab_ap * t22 * t15;
    const T t24 = t21 + T(2) * t16 * t17 * ab_ab + t23;
    const T t25 = t20 - ab_ap * t17 * t24 - t22 * t15;
    const T t26 = T(3) * t16 * t17 - T(2) * ab_ap * t18 * t25 - ap_ap * t17 * t24;
    F = (T(1) / T(3)) * (T(2) * ab_ap * t26 * t18 + ap_ap * t18 * t25 + T(3) * (t15 + ab_ap * t16 * t17 - t14) * t18) * in.w[3] * t18 + (T(1) / T(3)) * t17 * in.w[0] * t24 + (T(1) / T(3)) * in.w[2] * t26 * t18 - (T(1) / T(3)) * t18 * in.w[1] * t25;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 51 +, 121 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t2 * t4 + T(5) * t5 * ab_ap - t8 * t6;
    const T t10 = T(1) / ab_ab;
    const T t11 = ab_ap * t2 * t4 + a_minus_b * t8 * t6 - T(5) * t5 * cross_cross;
    const T t12 = T(8) * t9 * ab_ap * t10 - T(20) * t5 * ap_ap - T(5) * t11 * t10;
    const T t13 = T(4) * t7 * t6 + T(3) * ab_ap * t11 * t10 - T(4) * t2 * t3;
    const T t14 = T(6) * ab_ap * t12 * t10 - T(12) * t9 * ap_ap * t10 - T(5) * t13 * t10;
    G_ap = (T(1) / T(20)) * in.w[2] * t12 * t10 + (T(1) / T(5)) * t9 * in.w[1] * t10 + (T(1) / T(60)) * t14 * in.w[3] * t10 + t5 * in.w[0];
    G_ab = (T(1) / T(5)) * t9 * in.w[0] * t10 + (T(1) / T(120)) * in.w[3] * (T(4) * t14 * ab_ap * t10 - T(6) * ap_ap * t12 * t10 - T(5) * (T(3) * (T(3) * t11 * cross_cross * t10 + T(4) * a_minus_b * t7 * t6 + T(4) * ab_ap * t2 * t3) * t10 + T(4) * ab_ap * t13 * t10 - T(6) * t11 * ap_ap * t10) * t10) * t10 + (T(1) / T(60)) * t14 * in.w[2] * t10 + (T(1) / T(20)) * in.w[1] * t12 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r1;
    const T t20 = a_minus_b * t19 + ab_ap * t15;
    const T t21 = t19 * t19;
    const T t22 = T(2) * t18 * t20 * ab_ab + a_minus_b * t21 * t19 + ab_ap * t15 * t16;
    const T t23 = t21 * t21;
    const T t24 = T(3) * ab_ap * t15 * t17 + T(4) * t22 * t18 * ab_ab + T(3) * a_minus_b * t23 * t19;
    const T t25 = T(3) * t15 * t17 + ab_ap * t24 * t18 - T(3) * t23 * t19;
    const T t26 = T(1) / ab_ab;
    const T t27 = t24 * ap_ap * t18 - T(2) * t25 * ab_ap * t26 - T(5) * t22 * t18;
    const T t28 = t21 * t19 - ab_ap * t22 * t18 - t15 * t16;
    const T t29 = T(5) * t28 * t26 + t25 * ap_ap * t26 + T(2) * ab_ap * t27 * t26;
    G_ap = (T(1) / T(15)) * t24 * in.w[0] * t18 + (T(1) / T(15)) * in.w[1] * t25 * t26 - (T(1) / T(15)) * in.w[2] * t27 * t26 - (T(1) / T(15)) * t29 * in.w[3] * t26;
    G_ab = (T(1) / T(15)) * t25 * in.w[0] * t26 - (T(1) / T(15)) * in.w[1] * t27 * t26 - (T(1) / T(15)) * (T(2) * t29 * ab_ap * t26 + T(5) * (T(2) * ab_ap * t28 * t26 + ap_ap * t22 * t18 - T(3) * t18 * t20) * t26 - ap_ap * t27 * t26) * in.w[3] * t26 - (T(1) / T(15)) * t29 * in.w[2] * t26;
  }
  const T g_factor = -T(5) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 58 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 57 +, 145 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh, 1 other.
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(5) * t3 * cross_cross - a_minus_b * t4 * t6 - ab_ap * t9 * t7;
    const T t11 = T(3) * ab_ap * t2 * t10 + T(4) * t8 * t7 - T(4) * t4 * t5;
    const T t12 = T(4) * ab_ap * t8 * t7 + T(4) * a_minus_b * t4 * t5 - T(3) * cross_cross * t2 * t10;
    const T t13 = T(4) * ab_ap * t11 * t2 - T(6) * ap_ap * t2 * t10 - T(3) * t2 * t12;
    F = (T(1) / T(24)) * in.w[2] * t13 * t2 + (T(1) / T(4)) * in.w[0] * t2 * t10 + (T(1) / T(12)) * t11 * t2 * in.w[1] - (T(1) / T(24)) * (T(3) * t2 * (T(8) * t4 + ab_ap * t2 * t12 - T(8) * t7) + T(2) * t11 * ap_ap * t2 - T(2) * ab_ap * t13 * t2) * in.w[3] * t2;
    const T t14 = T(5) * t3 * ab_ap + t9 * t7 - t4 * t6;
    const T t15 = T(5) * t2 * t10 + T(8) * ab_ap * t2 * t14 - T(20) * t3 * ap_ap;
    const T t16 = T(12) * ap_ap * t2 * t14 - T(6) * ab_ap * t15 * t2 - T(5) * t11 * t2;
    G_ap = (T(1) / T(20)) * t15 * in.w[2] * t2 + t3 * in.w[0] + (T(1) / T(5)) * t2 * t14 * in.w[1] - (T(1) / T(60)) * t16 * in.w[3] * t2;
    G_ab = (T(1) / T(5)) * in.w[0] * t2 * t14 + (T(1) / T(20)) * t15 * t2 * in.w[1] + (T(1) / T(120)) * (T(5) * t13 * t2 - T(6) * t15 * ap_ap * t2 - T(4) * ab_ap * t16 * t2) * in.w[3] * t2 - (T(1) / T(60)) * in.w[2] * t16 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = ab_ap * t17 + a_minus_b * t18;
    const T t20 = T(1) / cross_cross;
    const T t21 = t17 * t17;
    const T t22 = t18 * t18;
    const T t23 = T(2) * t19 * t20 * ab_ab + ab_ap * t21 * t17 + a_minus_b * t18 * t22;
    const T t24 = ab_ap * t23 * t20 + t21 * t17 - t18 * t22;
    const T t25 = T(1) / ab_ab;
    const T t26 = ap_ap * t23 * t20 - T(2) * ab_ap * t24 * t25 - T(3) * t19 * t20;
    F = (T(1) / T(3)) * t24 * t25 * in.w[1] + (T(1) / T(3)) * t23 * t20 * in.w[0] - (T(1) / T(3)) * in.w[3] * t25 * (T(2) * ab_ap * t26 * t25 + ap_ap * t24 * t25 + T(3) * (t18 - ab_ap * t19 * t20 - t17) * t25) - (T(1) / T(3)) * in.w[2] * t26 * t25;
    const T t27 = t21 * t21;
    const T t28 = t22 * t22;
    const T t29 = T(4) * t23 * t20 * ab_ab + T(3) * a_minus_b * t18 * t28 + T(3) * ab_ap * t27 * t17;
    const T t30 = T(3) * t27 * t17 + ab_ap * t29 * t20 - T(3) * t18 * t28;
    const T t31 = T(2) * ab_ap * t30 * t25 + T(5) * t23 * t20 - ap_ap * t29 * t20;
    const T t32 = T(2) * ab_ap * t31 * t25 + T(5) * t24 * t25 - ap_ap * t30 * t25;
    G_ap = (T(1) / T(15)) * t32 * in.w[3] * t25 + (T(1) / T(15)) * t30 * t25 * in.w[1] + (T(1) / T(15)) * in.w[2] * t31 * t25 + (T(1) / T(15)) * t29 * t20 * in.w[0];
    G_ab = (T(1) / T(15)) * t32 * in.w[2] * t25 + (T(1) / T(15)) * t30 * in.w[0] * t25 + (T(1) / T(15)) * t31 * t25 * in.w[1] + (T(1) / T(15)) * in.w[3] * t25 * (T(2) * ab_ap * t32 * t25 - T(5) * t26 * t25 - ap_ap * t31 * t25);
  }
  const T g_factor = -T(5) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 31 +, 47 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    F = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, ap_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = T(1) / cross_cross;
    F = (T(1) / T(8)) * (T(2) * ab_ap * t5 + T(2) * t7 * a_minus_b + T(3) * (J2 * ab_ab + t6 * a_minus_b + ab_ap * t4) * t8 * ab_ab) * in.w[0] * t8;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 38 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    G_ab = (T(1) / T(6)) * in.w[0] * t3 * (T(6) * t2 * ab_ap + t6 - t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(8) * a_minus_b * t15 + T(8) * ab_ap * t18 + T(5) * t12 * ab_ab * (T(3) * t12 * ab_ab * (ab_ap * t16 + a_minus_b * t13 + ab_ab * J2) + T(2) * a_minus_b * t14 + T(2) * ab_ap * t17);
    G_ap = (T(1) / T(48)) * in.w[0] * t12 * t19;
    const T t20 = T(1) / ab_ab;
    G_ab = -(T(1) / T(48)) * in.w[0] * t20 * (T(8) * t15 - t12 * t19 * ab_ap - T(8) * t18);
  }
  const T g_factor = -T(6) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 38 +, 76 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    F = (T(1) / T(5)) * t2 * (T(6) * cross_cross * t3 - ab_ap * t6 - t9 * a_minus_b) * in.w[0];
    G_ap = t3 * in.w[0];
    G_ab = (T(1) / T(6)) * t2 * (T(6) * t3 * ab_ap + t6 - t9) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = T(1) / ap_ap;
    const T t16 = t15 * t15;
    const T t17 = T(2) * t14 * a_minus_b + T(3) * t12 * (ab_ab * J2 + ab_ap * t15 + t13 * a_minus_b) * ab_ab + T(2) * ab_ap * t16;
    F = (T(1) / T(8)) * t12 * t17 * in.w[0];
    const T t18 = t16 * t15;
    const T t19 = t14 * t13;
    const T t20 = T(8) * ab_ap * t18 + T(8) * t19 * a_minus_b + T(5) * t12 * ab_ab * t17;
    G_ap = (T(1) / T(48)) * t12 * t20 * in.w[0];
    const T t21 = T(1) / ab_ab;
    G_ab = (T(1) / T(48)) * (t12 * ab_ap * t20 + T(8) * t18 - T(8) * t19) * t21 * in.w[0];
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 34 +, 54 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    F = in.w[0] * t2 + (T(1) / T(4)) * in.w[1] * t3 * (T(4) * t2 * ab_ap + t5 - t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(cross_cross);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, ap_bp);
    const T t10 = T(1) / ab_ab;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / ap_ap;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = t12 * t12;
    const T t16 = T(3) * (t12 * ab_ap + ab_ab * J2 + t13 * a_minus_b) * t11 * ab_ab + T(2) * t14 * a_minus_b + T(2) * t15 * ab_ap;
    F = (T(1) / T(8)) * in.w[1] * t10 * (t11 * t16 * ab_ap + T(2) * t15 - T(2) * t14) + (T(1) / T(8)) * in.w[0] * t11 * t16;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 42 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(6) * ab_ap * t2 + t5 - t8;
    const T t10 = T(1) / ab_ab;
    G_ap = in.w[0] * t2 + (T(1) / T(6)) * t9 * in.w[1] * t10;
    G_ab = (T(1) / T(6)) * in.w[0] * t9 * t10 - (T(1) / T(15)) * (T(3) * t10 * (a_minus_b * t8 + ab_ap * t5 - T(6) * cross_cross * t2) + T(15) * ap_ap * t2 - T(5) * ab_ap * t9 * t10) * in.w[1] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * t16;
    const T t18 = T(2) * ab_ap * t15 + T(2) * a_minus_b * t17 + T(3) * (ab_ab * J2 + a_minus_b * t16 + ab_ap * t14) * t13 * ab_ab;
    const T t19 = t17 * t16;
    const T t20 = t15 * t14;
    const T t21 = T(5) * t18 * t13 * ab_ab + T(8) * a_minus_b * t19 + T(8) * ab_ap * t20;
    const T t22 = T(8) * t19 - T(8) * t20 - ab_ap * t13 * t21;
    const T t23 = T(1) / ab_ab;
    G_ap = (T(1) / T(48)) * in.w[0] * t13 * t21 - (T(1) / T(48)) * t22 * in.w[1] * t23;
    G_ab = -(T(1) / T(48)) * t22 * in.w[0] * t23 - (T(1) / T(48)) * in.w[1] * (ap_ap * t13 * t21 + T(2) * ab_ap * t22 * t23 - T(6) * t18 * t13) * t23;
  }
  const T g_factor = -T(6) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 45 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t3 * t2;
    const T t9 = T(6) * cross_cross * t4 - t7 * a_minus_b - ab_ap * t8;
    const T t10 = T(1) / ab_ab;
    F = (T(1) / T(20)) * (T(5) * t3 + T(4) * t9 * ab_ap * t10 - T(5) * t6) * in.w[1] * t10 + (T(1) / T(5)) * t9 * in.w[0] * t10;
    const T t11 = t8 + T(6) * ab_ap * t4 - t7;
    G_ap = (T(1) / T(6)) * in.w[1] * t10 * t11 + in.w[0] * t4;
    G_ab = (T(1) / T(6)) * in.w[0] * t10 * t11 + (T(1) / T(15)) * in.w[1] * (T(5) * ab_ap * t10 * t11 + T(3) * t9 * t10 - T(15) * ap_ap * t4) * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t15 * t15;
    const T t19 = T(3) * t14 * (t15 * a_minus_b + ab_ap * t16 + J2 * ab_ab) * ab_ab + T(2) * ab_ap * t17 + T(2) * t18 * a_minus_b;
    const T t20 = T(1) / ab_ab;
    F = (T(1) / T(8)) * in.w[0] * t19 * t14 + (T(1) / T(8)) * (T(2) * t17 + ab_ap * t19 * t14 - T(2) * t18) * in.w[1] * t20;
    const T t21 = t18 * t15;
    const T t22 = t17 * t16;
    const T t23 = T(5) * t19 * t14 * ab_ab + T(8) * t21 * a_minus_b + T(8) * ab_ap * t22;
    const T t24 = T(8) * t22 + ab_ap * t23 * t14 - T(8) * t21;
    G_ap = (T(1) / T(48)) * in.w[0] * t23 * t14 + (T(1) / T(48)) * t24 * in.w[1] * t20;
    G_ab = (T(1) / T(48)) * (T(6) * t19 * t14 + T(2) * t24 * ab_ap * t20 - t23 * ap_ap * t14) * in.w[1] * t20 + (T(1) / T(48)) * t24 * in.w[0] * t20;
  }
  const T g_factor = -T(6) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 37 +, 64 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t4 + T(4) * ab_ap * t5 - t7;
    F = (T(1) / T(4)) * in.w[1] * t2 * t8 + t5 * in.w[0] - (T(1) / T(6)) * (T(6) * ap_ap * t5 - T(2) * (T(4) * cross_cross * t5 - a_minus_b * t7 - ab_ap * t4) * t2 - T(3) * ab_ap * t2 * t8) * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(cross_cross);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, ap_bp) * t10;
    const T t11 = T(1) / cross_cross;
    const T t12 = T(1) / bp_bp;
    const T t13 = t12 * t12;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = ab_ap * t14 + a_minus_b * t12 + J2 * ab_ab;
    const T t17 = T(2) * a_minus_b * t13 + T(2) * ab_ap * t15 + T(3) * t11 * t16 * ab_ab;
    const T t18 = ab_ap * t11 * t17 + T(2) * t15 - T(2) * t13;
    const T t19 = T(1) / ab_ab;
    F = (T(1) / T(8)) * t11 * t17 * in.w[0] + (T(1) / T(8)) * t18 * in.w[1] * t19 + (T(1) / T(8)) * (T(2) * t18 * ab_ap * t19 + T(4) * t11 * t16 - ap_ap * t11 * t17) * in.w[2] * t19;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 48 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(5)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(6) * t2 * ab_ap + t6 - t9;
    const T t11 = T(6) * t2 * cross_cross - a_minus_b * t9 - t6 * ab_ap;
    const T t12 = T(5) * t3 * t10 * ab_ap + T(3) * t3 * t11 - T(15) * ap_ap * t2;
    G_ap = t2 * in.w[0] + (T(1) / T(15)) * in.w[2] * t3 * t12 + (T(1) / T(6)) * in.w[1] * t3 * t10;
    G_ab = (T(1) / T(6)) * t3 * t10 * in.w[0] + (T(1) / T(15)) * in.w[1] * t3 * t12 - (T(1) / T(60)) * (T(10) * ap_ap * t3 * t10 - T(8) * t3 * ab_ap * t12 - T(3) * (T(4) * t3 * t11 * ab_ap + T(5) * t5 - T(5) * t8) * t3) * in.w[2] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, ap_bp);
    const T t15 = T(1) / ab_ab;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    const T t22 = T(2) * a_minus_b * t21 + T(2) * t17 * ab_ap + T(3) * (t16 * ab_ap + a_minus_b * t20 + ab_ab * J2) * t19 * ab_ab;
    const T t23 = t21 * t20;
    const T t24 = T(5) * t19 * ab_ab * t22 + T(8) * a_minus_b * t23 + T(8) * t18 * ab_ap;
    const T t25 = T(8) * t18 + t19 * t24 * ab_ap - T(8) * t23;
    const T t26 = T(2) * t25 * t15 * ab_ap + T(6) * t19 * t22 - ap_ap * t19 * t24;
    G_ap = (T(1) / T(48)) * in.w[2] * t15 * t26 + (T(1) / T(48)) * t19 * t24 * in.w[0] + (T(1) / T(48)) * t25 * in.w[1] * t15;
    G_ab = (T(1) / T(48)) * in.w[2] * t15 * (T(2) * t15 * t26 * ab_ap + T(6) * (t19 * t22 * ab_ap + T(2) * t17 - T(2) * t21) * t15 - t25 * ap_ap * t15) + (T(1) / T(48)) * t25 * t15 * in.w[0] + (T(1) / T(48)) * in.w[1] * t15 * t26;
  }
  const T g_factor = -T(6) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 52 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t4 * t3;
    const T t10 = T(6) * t5 * cross_cross - t8 * a_minus_b - ab_ap * t9;
    const T t11 = T(5) * t4 + T(4) * t10 * t2 * ab_ap - T(5) * t7;
    F = (T(1) / T(30)) * t2 * (T(3) * t2 * t11 * ab_ap - T(6) * t10 * t2 * ap_ap - T(2) * t2 * (T(5) * t7 * a_minus_b + T(5) * ab_ap * t4 - T(4) * t10 * t2 * cross_cross)) * in.w[2] + (T(1) / T(5)) * t10 * t2 * in.w[0] + (T(1) / T(20)) * t2 * t11 * in.w[1];
    const T t12 = t9 + T(6) * t5 * ab_ap - t8;
    const T t13 = T(5) * t2 * ab_ap * t12 + T(3) * t10 * t2 - T(15) * t5 * ap_ap;
    G_ap = (T(1) / T(6)) * t2 * in.w[1] * t12 + (T(1) / T(15)) * t2 * t13 * in.w[2] + t5 * in.w[0];
    G_ab = (T(1) / T(6)) * t2 * in.w[0] * t12 + (T(1) / T(15)) * t2 * in.w[1] * t13 + (T(1) / T(60)) * t2 * (T(3) * t2 * t11 + T(8) * t2 * ab_ap * t13 - T(10) * t2 * ap_ap * t12) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, ap_bp) * t15;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(1) / ap_ap;
    const T t18 = T(1) / bp_bp;
    const T t19 = ab_ap * t17 + t18 * a_minus_b + ab_ab * J2;
    const T t20 = T(1) / cross_cross;
    const T t21 = t17 * t17;
    const T t22 = t18 * t18;
    const T t23 = T(2) * t22 * a_minus_b + T(3) * t19 * ab_ab * t20 + T(2) * ab_ap * t21;
    const T t24 = T(2) * t21 + ab_ap * t23 * t20 - T(2) * t22;
    F = (T(1) / T(8)) * t16 * (T(4) * t19 * t20 + T(2) * t16 * ab_ap * t24 - ap_ap * t23 * t20) * in.w[2] + (T(1) / T(8)) * t16 * in.w[1] * t24 + (T(1) / T(8)) * in.w[0] * t23 * t20;
    const T t25 = t21 * t17;
    const T t26 = t22 * t18;
    const T t27 = T(8) * t26 * a_minus_b + T(8) * ab_ap * t25 + T(5) * ab_ab * t23 * t20;
    const T t28 = T(8) * t25 + ab_ap * t27 * t20 - T(8) * t26;
    const T t29 = T(2) * t16 * ab_ap * t28 + T(6) * t23 * t20 - ap_ap * t27 * t20;
    G_ap = (T(1) / T(48)) * t16 * t29 * in.w[2] + (T(1) / T(48)) * in.w[0] * t27 * t20 + (T(1) / T(48)) * t16 * t28 * in.w[1];
    G_ab = (T(1) / T(48)) * t16 * in.w[0] * t28 + (T(1) / T(48)) * t16 * t29 * in.w[1] + (T(1) / T(48)) * t16 * (T(2) * t16 * t29 * ab_ap + T(6) * t16 * t24 - t16 * t28 * ap_ap) * in.w[2];
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 42 +, 76 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(10)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(6), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t4 + T(4) * t5 * ab_ap - t7;
    const T t9 = T(4) * cross_cross * t5 - a_minus_b * t7 - ab_ap * t4;
    const T t10 = T(6) * t5 * ap_ap - T(2) * t2 * t9 - T(3) * t2 * ab_ap * t8;
    F = (T(1) / T(4)) * t2 * in.w[1] * t8 + in.w[0] * t5 - (T(1) / T(12)) * in.w[3] * t2 * (T(2) * t2 * (T(3) * t6 - T(3) * t3 - T(2) * t2 * ab_ap * t9) + T(3) * t2 * t8 * ap_ap + T(4) * t2 * ab_ap * t10) - (T(1) / T(6)) * t2 * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = a_minus_b * t15 + ab_ap * t17 + J2 * ab_ab;
    const T t20 = T(2) * a_minus_b * t16 + T(2) * ab_ap * t18 + T(3) * t14 * ab_ab * t19;
    const T t21 = t14 * t20 * ab_ap + T(2) * t18 - T(2) * t16;
    const T t22 = T(2) * t13 * ab_ap * t21 + T(4) * t14 * t19 - t14 * t20 * ap_ap;
    F = (T(1) / T(8)) * t13 * in.w[1] * t21 + (T(1) / T(8)) * t13 * t22 * in.w[2] + (T(1) / T(8)) * t14 * in.w[0] * t20 - (T(1) / T(8)) * in.w[3] * t13 * (t13 * t21 * ap_ap + T(4) * t13 * (t15 - t17 - t14 * ab_ap * t19) - T(2) * t13 * t22 * ab_ap);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 54 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t6 - t9 - T(6) * t2 * ab_ap;
    const T t11 = a_minus_b * t6 + t9 * ab_ap - T(6) * t2 * cross_cross;
    const T t12 = T(5) * t3 * t10 * ab_ap + T(15) * ap_ap * t2 + T(3) * t3 * t11;
    const T t13 = T(5) * t5 + T(4) * t3 * t11 * ab_ap - T(5) * t8;
    const T t14 = T(3) * t13 * t3 + T(8) * t12 * t3 * ab_ap - T(10) * ap_ap * t3 * t10;
    G_ap = t2 * in.w[0] - (T(1) / T(15)) * t12 * t3 * in.w[2] - (T(1) / T(60)) * in.w[3] * t3 * t14 - (T(1) / T(6)) * t3 * t10 * in.w[1];
    G_ab = -(T(1) / T(30)) * (t3 * (T(2) * (T(5) * a_minus_b * t5 + T(5) * t8 * ab_ap + T(4) * cross_cross * t3 * t11) * t3 + T(3) * t13 * t3 * ab_ap - T(6) * ap_ap * t3 * t11) + t3 * t14 * ab_ap - T(2) * ap_ap * t12 * t3) * in.w[3] * t3 - (T(1) / T(15)) * t12 * t3 * in.w[1] - (T(1) / T(60)) * t3 * t14 * in.w[2] - (T(1) / T(6)) * in.w[0] * t3 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, ap_bp) * t16;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / bp_bp;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(1) / ap_ap;
    const T t22 = t21 * ab_ap + a_minus_b * t18 + ab_ab * J2;
    const T t23 = t21 * t21;
    const T t24 = T(3) * t17 * t22 * ab_ab + T(2) * a_minus_b * t19 + T(2) * t23 * ab_ap;
    const T t25 = t23 * t21;
    const T t26 = T(8) * a_minus_b * t20 + T(5) * t24 * t17 * ab_ab + T(8) * t25 * ab_ap;
    const T t27 = T(1) / ab_ab;
    const T t28 = T(8) * t20 - T(8) * t25 - t17 * t26 * ab_ap;
    const T t29 = ap_ap * t17 * t26 + T(2) * t28 * t27 * ab_ap - T(6) * t24 * t17;
    const T t30 = T(2) * t19 - t24 * t17 * ab_ap - T(2) * t23;
    const T t31 = T(6) * t27 * t30 + T(2) * t27 * ab_ap * t29 - t28 * ap_ap * t27;
    G_ap = (T(1) / T(48)) * t17 * in.w[0] * t26 - (T(1) / T(48)) * t27 * t29 * in.w[2] - (T(1) / T(48)) * t31 * in.w[3] * t27 - (T(1) / T(48)) * t28 * t27 * in.w[1];
    G_ab = -(T(1) / T(48)) * t31 * t27 * in.w[2] - (T(1) / T(48)) * t28 * in.w[0] * t27 - (T(1) / T(48)) * t27 * in.w[1] * t29 - (T(1) / T(48)) * (T(2) * t31 * t27 * ab_ap - ap_ap * t27 * t29 - T(6) * (T(4) * t17 * t22 - ap_ap * t24 * t17 - T(2) * t27 * t30 * ab_ap) * t27) * in.w[3] * t27;
  }
  const T g_factor = -T(6) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 61 +, 144 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t4 * t3;
    const T t8 = t6 * t5;
    const T t9 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t10 = t7 * a_minus_b + ab_ap * t8 - T(6) * cross_cross * t9;
    const T t11 = T(5) * t4 * a_minus_b + T(5) * ab_ap * t6 + T(4) * t2 * cross_cross * t10;
    const T t12 = T(5) * t4 + T(4) * t2 * ab_ap * t10 - T(5) * t6;
    const T t13 = T(2) * t11 * t2 + T(3) * t2 * ab_ap * t12 - T(6) * t2 * t10 * ap_ap;
    F = -(T(1) / T(60)) * in.w[3] * t2 * (T(4) * t2 * t13 * ab_ap + T(2) * t2 * (T(2) * t11 * t2 * ab_ap + T(15) * t3 - T(15) * t5) - T(3) * t2 * ap_ap * t12) - (T(1) / T(20)) * t2 * in.w[1] * t12 - (T(1) / T(5)) * in.w[0] * t2 * t10 - (T(1) / T(30)) * t2 * t13 * in.w[2];
    const T t14 = T(6) * ab_ap * t9 + t8 - t7;
    const T t15 = T(15) * t9 * ap_ap + T(3) * t2 * t10 - T(5) * t14 * t2 * ab_ap;
    const T t16 = T(8) * t2 * t15 * ab_ap + T(3) * t2 * t12 + T(10) * t14 * t2 * ap_ap;
    G_ap = in.w[0] * t9 + (T(1) / T(6)) * t14 * t2 * in.w[1] - (T(1) / T(15)) * t2 * t15 * in.w[2] - (T(1) / T(60)) * in.w[3] * t2 * t16;
    G_ab = (T(1) / T(6)) * t14 * in.w[0] * t2 - (T(1) / T(60)) * t2 * t16 * in.w[2] - (T(1) / T(30)) * (t2 * ab_ap * t16 + t2 * t13 - T(2) * t2 * t15 * ap_ap) * in.w[3] * t2 - (T(1) / T(15)) * t2 * t15 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(cross_cross);
    const T t18 = T(1) / t17;
    const T J2 = atan2(t17, ap_bp) * t18;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    const T t22 = T(1) / ap_ap;
    const T t23 = t22 * t22;
    const T t24 = ab_ab * J2 + ab_ap * t22 + t20 * a_minus_b;
    const T t25 = T(2) * t21 * a_minus_b + T(2) * ab_ap * t23 + T(3) * ab_ab * t19 * t24;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(2) * t21 - t19 * ab_ap * t25 - T(2) * t23;
    const T t28 = t19 * t25 * ap_ap + T(2) * t26 * ab_ap * t27 - T(4) * t19 * t24;
    F = (T(1) / T(8)) * in.w[0] * t19 * t25 - (T(1) / T(8)) * t26 * in.w[1] * t27 - (T(1) / T(8)) * in.w[3] * t26 * (T(2) * t26 * ab_ap * t28 - T(4) * t26 * (t22 + t19 * ab_ap * t24 - t20) - t26 * t27 * ap_ap) - (T(1) / T(8)) * t26 * t28 * in.w[2];
    const T t29 = t21 * t20;
    const T t30 = t23 * t22;
    const T t31 = T(8) * t29 * a_minus_b + T(5) * ab_ab * t19 * t25 + T(8) * ab_ap * t30;
    const T t32 = T(8) * t29 - t19 * t31 * ab_ap - T(8) * t30;
    const T t33 = T(2) * t32 * t26 * ab_ap + t19 * t31 * ap_ap - T(6) * t19 * t25;
    const T t34 = T(6) * t26 * t27 + T(2) * t26 * ab_ap * t33 - t32 * t26 * ap_ap;
    G_ap = (T(1) / T(48)) * in.w[0] * t19 * t31 - (T(1) / T(48)) * t26 * t33 * in.w[2] - (T(1) / T(48)) * in.w[3] * t26 * t34 - (T(1) / T(48)) * t32 * t26 * in.w[1];
    G_ab = (T(1) / T(48)) * in.w[3] * t26 * (t26 * t33 * ap_ap - T(6) * t26 * t28 - T(2) * t26 * ab_ap * t34) - (T(1) / T(48)) * t32 * in.w[0] * t26 - (T(1) / T(48)) * t26 * in.w[2] * t34 - (T(1) / T(48)) * t26 * in.w[1] * t33;
  }
  const T g_factor = -T(6) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 30 +, 53 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    F = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / cross_cross;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    F = (T(1) / T(15)) * in.w[0] * t2 * (T(3) * t5 * t3 * ab_ap + T(3) * a_minus_b * t8 * t6 + T(4) * (a_minus_b * t7 * t6 + t4 * t3 * ab_ap + T(2) * (a_minus_b * t6 + t3 * ab_ap) * t2 * ab_ab) * t2 * ab_ab);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 37 +, 82 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / ab_ab;
    G_ab = -(T(1) / T(7)) * (t3 * t6 - t7 * t10 - T(7) * ab_ap * t2) * in.w[0] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(5) * ab_ap * t12 * t15 + T(5) * t16 * a_minus_b * t19 + T(2) * (T(3) * ab_ap * t12 * t14 + T(4) * t20 * (t16 * a_minus_b * t17 + T(2) * (t16 * a_minus_b + ab_ap * t12) * t20 * ab_ab + ab_ap * t12 * t13) * ab_ab + T(3) * t16 * a_minus_b * t18) * t20 * ab_ab;
    G_ap = (T(1) / T(35)) * t21 * in.w[0] * t20;
    const T t22 = T(1) / ab_ab;
    G_ab = (T(1) / T(35)) * (ab_ap * t21 * t20 + T(5) * t12 * t15 - T(5) * t16 * t19) * in.w[0] * t22;
  }
  const T g_factor = -T(7) * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 37 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / ab_ab;
    F = (T(1) / T(6)) * (T(7) * cross_cross * t2 - t3 * t6 * a_minus_b - t7 * ab_ap * t10) * t11 * in.w[0];
    G_ap = t2 * in.w[0];
    G_ab = (T(1) / T(7)) * t11 * in.w[0] * (t7 * t10 + T(7) * t2 * ab_ap - t3 * t6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(3) * t13 * t15 * a_minus_b + T(4) * t12 * ab_ab * (t16 * ab_ap * t17 + T(2) * t12 * ab_ab * (t16 * ab_ap + t13 * a_minus_b) + t13 * t14 * a_minus_b) + T(3) * t16 * ab_ap * t18;
    F = (T(1) / T(15)) * t12 * in.w[0] * t19;
    const T t20 = t15 * t14;
    const T t21 = t18 * t17;
    const T t22 = T(5) * t13 * t20 * a_minus_b + T(2) * t12 * ab_ab * t19 + T(5) * t16 * ab_ap * t21;
    G_ap = (T(1) / T(35)) * t22 * t12 * in.w[0];
    const T t23 = T(1) / ab_ab;
    G_ab = (T(1) / T(35)) * t23 * (t22 * t12 * ab_ap + T(5) * t16 * t21 - T(5) * t13 * t20) * in.w[0];
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 33 +, 62 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    F = in.w[0] * t2 - (T(1) / T(5)) * in.w[1] * t3 * (t4 * t6 - T(5) * ab_ap * t2 - t9 * t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / cross_cross;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(3) * t11 * a_minus_b * t13 + T(4) * t10 * (T(2) * (ab_ap * t14 + t11 * a_minus_b) * t10 * ab_ab + ab_ap * t15 * t14 + t11 * a_minus_b * t12) * ab_ab + T(3) * ab_ap * t16 * t14;
    const T t18 = T(1) / ab_ab;
    F = (T(1) / T(15)) * (ab_ap * t10 * t17 + T(3) * t16 * t14 - T(3) * t11 * t13) * in.w[1] * t18 + (T(1) / T(15)) * in.w[0] * t10 * t17;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 41 +, 96 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t2 * t5 + T(7) * ab_ap * t6 - t7 * t10;
    const T t12 = T(1) / ab_ab;
    G_ap = (T(1) / T(7)) * t11 * in.w[1] * t12 + t6 * in.w[0];
    G_ab = (T(1) / T(7)) * t11 * t12 * in.w[0] - (T(1) / T(42)) * in.w[1] * t12 * (T(7) * t12 * (ab_ap * t2 * t5 + t7 * a_minus_b * t10 - T(7) * cross_cross * t6) + T(42) * t6 * ap_ap - T(12) * t11 * t12 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / ab_ab;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(3) * t14 * a_minus_b * t16 + T(3) * ab_ap * t17 * t19 + T(4) * t20 * ab_ab * (T(2) * t20 * ab_ab * (t14 * a_minus_b + ab_ap * t17) + ab_ap * t17 * t18 + t14 * a_minus_b * t15);
    const T t22 = t19 * t18;
    const T t23 = t16 * t15;
    const T t24 = T(2) * t21 * t20 * ab_ab + T(5) * ab_ap * t17 * t22 + T(5) * t14 * a_minus_b * t23;
    const T t25 = t24 * t20 * ab_ap + T(5) * t17 * t22 - T(5) * t14 * t23;
    G_ap = (T(1) / T(35)) * in.w[1] * t13 * t25 + (T(1) / T(35)) * t24 * t20 * in.w[0];
    G_ab = (T(1) / T(105)) * in.w[1] * t13 * (T(6) * t13 * t25 * ab_ap + T(7) * t21 * t20 - T(3) * t24 * t20 * ap_ap) + (T(1) / T(35)) * t13 * t25 * in.w[0];
  }
  const T g_factor = -T(7) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 44 +, 109 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = a_minus_b * t2 * t5 + t9 * t6 * ab_ap - T(7) * cross_cross * t10;
    const T t12 = T(1) / ab_ab;
    F = -(T(1) / T(6)) * in.w[0] * t11 * t12 - (T(1) / T(30)) * in.w[1] * (T(5) * t11 * t12 * ab_ap + T(6) * t2 * t4 - T(6) * t8 * t6) * t12;
    const T t13 = T(7) * t10 * ab_ap + t9 * t6 - t2 * t5;
    G_ap = in.w[0] * t10 + (T(1) / T(7)) * in.w[1] * t13 * t12;
    G_ab = (T(1) / T(7)) * in.w[0] * t13 * t12 - (T(1) / T(42)) * (T(42) * ap_ap * t10 + T(7) * t11 * t12 - T(12) * t13 * t12 * ab_ap) * in.w[1] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(3) * a_minus_b * t15 * t17 + T(3) * t20 * t18 * ab_ap + T(4) * t14 * ab_ab * (T(2) * t14 * (t18 * ab_ap + a_minus_b * t15) * ab_ab + t19 * t18 * ab_ap + a_minus_b * t15 * t16);
    const T t22 = T(1) / ab_ab;
    F = (T(1) / T(15)) * in.w[0] * t14 * t21 + (T(1) / T(15)) * in.w[1] * t22 * (t14 * t21 * ab_ap + T(3) * t20 * t18 - T(3) * t15 * t17);
    const T t23 = t17 * t16;
    const T t24 = t20 * t19;
    const T t25 = T(5) * a_minus_b * t15 * t23 + T(2) * t14 * ab_ab * t21 + T(5) * t24 * t18 * ab_ap;
    const T t26 = T(5) * t24 * t18 + t25 * t14 * ab_ap - T(5) * t15 * t23;
    G_ap = (T(1) / T(35)) * in.w[0] * t25 * t14 + (T(1) / T(35)) * t26 * in.w[1] * t22;
    G_ab = (T(1) / T(35)) * t26 * in.w[0] * t22 - (T(1) / T(105)) * in.w[1] * t22 * (T(3) * t25 * ap_ap * t14 - T(6) * t26 * t22 * ab_ap - T(7) * t14 * t21);
  }
  const T g_factor = -T(7) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 36 +, 72 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(3) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t3 - T(5) * ab_ap * t2 - t8 * t6;
    const T t10 = T(1) / ab_ab;
    F = in.w[0] * t2 - (T(1) / T(20)) * in.w[2] * (T(8) * t9 * t10 * ab_ap + T(20) * ap_ap * t2 + T(5) * (t8 * t6 * ab_ap + a_minus_b * t5 * t3 - T(5) * cross_cross * t2) * t10) * t10 - (T(1) / T(5)) * t9 * t10 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / ab_ab;
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = a_minus_b * t14 * t13 + t16 * t15 * ab_ap + T(2) * t12 * ab_ab * (a_minus_b * t13 + t15 * ab_ap);
    const T t18 = t16 * t16;
    const T t19 = t14 * t14;
    const T t20 = T(4) * t12 * ab_ab * t17 + T(3) * t18 * t15 * ab_ap + T(3) * a_minus_b * t19 * t13;
    const T t21 = t20 * t12 * ab_ap + T(3) * t18 * t15 - T(3) * t19 * t13;
    F = (T(1) / T(15)) * t11 * t21 * in.w[1] + (T(1) / T(15)) * t20 * t12 * in.w[0] - (T(1) / T(15)) * in.w[2] * (ap_ap * t20 * t12 - T(5) * t12 * t17 - T(2) * t11 * t21 * ab_ap) * t11;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 47 +, 116 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t4 * t7 - t8 * t11 - T(7) * t2 * ab_ap;
    const T t13 = t4 * t7 * a_minus_b + ab_ap * t8 * t11 - T(7) * cross_cross * t2;
    const T t14 = T(12) * t12 * t3 * ab_ap + T(42) * t2 * ap_ap + T(7) * t13 * t3;
    G_ap = t2 * in.w[0] - (T(1) / T(42)) * in.w[2] * t3 * t14 - (T(1) / T(7)) * t12 * t3 * in.w[1];
    G_ab = (T(1) / T(210)) * in.w[2] * t3 * (T(7) * t3 * (T(6) * t8 * t10 - T(6) * t4 * t6 - T(5) * t13 * t3 * ab_ap) + T(30) * t12 * t3 * ap_ap - T(10) * t3 * t14 * ab_ap) - (T(1) / T(42)) * t3 * t14 * in.w[1] - (T(1) / T(7)) * t12 * t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(4) * t15 * ab_ab * (ab_ap * t20 * t21 + T(2) * (ab_ap * t20 + t16 * a_minus_b) * t15 * ab_ab + t16 * t17 * a_minus_b) + T(3) * t16 * t18 * a_minus_b + T(3) * ab_ap * t20 * t22;
    const T t24 = t22 * t21;
    const T t25 = T(5) * t16 * t19 * a_minus_b + T(2) * t15 * ab_ab * t23 + T(5) * ab_ap * t20 * t24;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(5) * t16 * t19 - T(5) * t20 * t24 - t15 * t25 * ab_ap;
    const T t28 = T(3) * t15 * t25 * ap_ap + T(6) * t26 * ab_ap * t27 - T(7) * t15 * t23;
    G_ap = (T(1) / T(35)) * t15 * t25 * in.w[0] - (T(1) / T(35)) * t26 * t27 * in.w[1] - (T(1) / T(105)) * in.w[2] * t26 * t28;
    G_ab = (T(1) / T(105)) * in.w[2] * (T(7) * t26 * (T(3) * t20 * t22 + t15 * ab_ap * t23 - T(3) * t16 * t18) + T(3) * t26 * t27 * ap_ap - T(2) * t26 * t28 * ab_ap) * t26 - (T(1) / T(105)) * t26 * t28 * in.w[1] - (T(1) / T(35)) * t26 * in.w[0] * t27;
  }
  const T g_factor = -T(7) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 51 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t4 * t3;
    const T t11 = T(7) * t5 * cross_cross - t9 * a_minus_b * t6 - ab_ap * t10 * t2;
    const T t12 = T(1) / ab_ab;
    const T t13 = T(6) * t4 * t2 + T(5) * ab_ap * t11 * t12 - T(6) * t8 * t6;
    F = (T(1) / T(120)) * (T(8) * ab_ap * t13 * t12 - T(20) * t11 * ap_ap * t12 - T(5) * (T(6) * ab_ap * t4 * t2 + T(6) * t8 * a_minus_b * t6 - T(5) * t11 * cross_cross * t12) * t12) * in.w[2] * t12 + (T(1) / T(30)) * t13 * in.w[1] * t12 + (T(1) / T(6)) * in.w[0] * t11 * t12;
    const T t14 = t9 * t6 - t10 * t2 - T(7) * t5 * ab_ap;
    const T t15 = T(12) * t14 * ab_ap * t12 + T(42) * t5 * ap_ap - T(7) * t11 * t12;
    G_ap = in.w[0] * t5 - (T(1) / T(42)) * t15 * in.w[2] * t12 - (T(1) / T(7)) * t14 * in.w[1] * t12;
    G_ab = -(T(1) / T(42)) * in.w[1] * t15 * t12 - (T(1) / T(7)) * in.w[0] * t14 * t12 - (T(1) / T(210)) * (T(10) * ab_ap * t15 * t12 - T(7) * t13 * t12 - T(30) * t14 * ap_ap * t12) * in.w[2] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = T(1) / cross_cross;
    const T t22 = t20 * a_minus_b * t19 + ab_ap * t17 * t16 + T(2) * (a_minus_b * t19 + ab_ap * t16) * t21 * ab_ab;
    const T t23 = t20 * t20;
    const T t24 = T(3) * ab_ap * t18 * t16 + T(4) * t22 * t21 * ab_ab + T(3) * t23 * a_minus_b * t19;
    const T t25 = ab_ap * t24 * t21 + T(3) * t18 * t16 - T(3) * t23 * t19;
    const T t26 = T(1) / ab_ab;
    F = (T(1) / T(15)) * in.w[2] * (T(2) * ab_ap * t25 * t26 + T(5) * t22 * t21 - ap_ap * t24 * t21) * t26 + (T(1) / T(15)) * in.w[0] * t24 * t21 + (T(1) / T(15)) * in.w[1] * t25 * t26;
    const T t27 = t23 * t20;
    const T t28 = t18 * t17;
    const T t29 = T(5) * t27 * a_minus_b * t19 + T(5) * ab_ap * t28 * t16 + T(2) * t24 * t21 * ab_ab;
    const T t30 = T(5) * t27 * t19 - T(5) * t28 * t16 - ab_ap * t21 * t29;
    const T t31 = T(6) * ab_ap * t30 * t26 + T(3) * ap_ap * t21 * t29 - T(7) * t24 * t21;
    G_ap = (T(1) / T(35)) * in.w[0] * t21 * t29 - (T(1) / T(105)) * t31 * in.w[2] * t26 - (T(1) / T(35)) * t30 * in.w[1] * t26;
    G_ab = (T(1) / T(105)) * in.w[2] * t26 * (T(3) * t30 * ap_ap * t26 + T(7) * t25 * t26 - T(2) * ab_ap * t31 * t26) - (T(1) / T(105)) * in.w[1] * t31 * t26 - (T(1) / T(35)) * in.w[0] * t30 * t26;
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 41 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(5) * ab_ap * t2 + t4 * t6 - t9 * t7;
    const T t11 = T(5) * t2 * cross_cross - t9 * t7 * a_minus_b - t4 * ab_ap * t6;
    const T t12 = T(20) * ap_ap * t2 - T(5) * t11 * t3 - T(8) * ab_ap * t3 * t10;
    F = t2 * in.w[0] + (T(1) / T(5)) * in.w[1] * t3 * t10 - (T(1) / T(20)) * in.w[2] * t12 * t3 - (T(1) / T(60)) * (T(6) * ab_ap * t12 * t3 + T(12) * ap_ap * t3 * t10 - T(5) * (T(4) * t4 * t5 + T(3) * t11 * ab_ap * t3 - T(4) * t8 * t7) * t3) * in.w[3] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = T(1) / cross_cross;
    const T t18 = t14 * t13 * a_minus_b + t15 * ab_ap * t16 + T(2) * (t15 * ab_ap + t13 * a_minus_b) * t17 * ab_ab;
    const T t19 = t14 * t14;
    const T t20 = t16 * t16;
    const T t21 = T(4) * t18 * t17 * ab_ab + T(3) * t19 * t13 * a_minus_b + T(3) * t15 * ab_ap * t20;
    const T t22 = ab_ap * t21 * t17 + T(3) * t15 * t20 - T(3) * t19 * t13;
    const T t23 = T(1) / ab_ab;
    const T t24 = ap_ap * t21 * t17 - T(2) * ab_ap * t22 * t23 - T(5) * t18 * t17;
    F = (T(1) / T(15)) * in.w[1] * t22 * t23 + (T(1) / T(15)) * t21 * in.w[0] * t17 - (T(1) / T(15)) * t24 * in.w[2] * t23 - (T(1) / T(15)) * (T(2) * ab_ap * t24 * t23 + t22 * ap_ap * t23 - T(5) * (t15 * t16 + ab_ap * t18 * t17 - t14 * t13) * t23) * in.w[3] * t23;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 53 +, 136 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(7) * ab_ap * t3 + t4 * t7 - t11 * t8;
    const T t13 = T(7) * cross_cross * t3 - a_minus_b * t11 * t8 - ab_ap * t4 * t7;
    const T t14 = T(12) * t12 * t2 * ab_ap + T(7) * t2 * t13 - T(42) * ap_ap * t3;
    const T t15 = T(6) * t4 * t6 + T(5) * t2 * t13 * ab_ap - T(6) * t10 * t8;
    const T t16 = T(10) * t2 * ab_ap * t14 + T(7) * t2 * t15 - T(30) * t12 * t2 * ap_ap;
    G_ap = (T(1) / T(42)) * t2 * in.w[2] * t14 + (T(1) / T(210)) * in.w[3] * t2 * t16 + t3 * in.w[0] + (T(1) / T(7)) * t12 * t2 * in.w[1];
    G_ab = (T(1) / T(42)) * t2 * in.w[1] * t14 + (T(1) / T(210)) * t2 * t16 * in.w[2] + (T(1) / T(7)) * t12 * t2 * in.w[0] - (T(1) / T(840)) * in.w[3] * t2 * (T(20) * t2 * t14 * ap_ap + T(7) * (T(20) * t2 * t13 * ap_ap - T(5) * (T(5) * cross_cross * t2 * t13 - T(6) * a_minus_b * t10 * t8 - T(6) * ab_ap * t4 * t6) * t2 - T(8) * t2 * t15 * ab_ap) * t2 - T(8) * t2 * t16 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = ab_ap * t19 * t20 + T(2) * t18 * ab_ab * (a_minus_b * t21 + ab_ap * t19) + a_minus_b * t22 * t21;
    const T t24 = t22 * t22;
    const T t25 = t20 * t20;
    const T t26 = T(4) * t18 * ab_ab * t23 + T(3) * a_minus_b * t24 * t21 + T(3) * ab_ap * t19 * t25;
    const T t27 = t18 * ab_ap * t26 + T(3) * t19 * t25 - T(3) * t24 * t21;
    const T t28 = t25 * t20;
    const T t29 = t24 * t22;
    const T t30 = T(5) * a_minus_b * t29 * t21 + T(5) * ab_ap * t19 * t28 + T(2) * t18 * ab_ab * t26;
    const T t31 = T(5) * t19 * t28 + t18 * ab_ap * t30 - T(5) * t29 * t21;
    const T t32 = T(3) * t18 * t30 * ap_ap - T(6) * t31 * t17 * ab_ap - T(7) * t18 * t26;
    const T t33 = T(7) * t27 * t17 - T(3) * t31 * t17 * ap_ap - T(2) * t17 * t32 * ab_ap;
    G_ap = (T(1) / T(105)) * in.w[3] * t17 * t33 + (T(1) / T(35)) * t18 * t30 * in.w[0] + (T(1) / T(35)) * t31 * t17 * in.w[1] - (T(1) / T(105)) * t17 * t32 * in.w[2];
    G_ab = (T(1) / T(105)) * in.w[3] * t17 * (T(7) * t17 * (T(2) * t27 * t17 * ab_ap + T(5) * t18 * t23 - t18 * t26 * ap_ap) + t17 * t32 * ap_ap + T(2) * t17 * ab_ap * t33) + (T(1) / T(35)) * t31 * t17 * in.w[0] + (T(1) / T(105)) * t17 * t33 * in.w[2] - (T(1) / T(105)) * t17 * in.w[1] * t32;
  }
  const T g_factor = -T(7) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 60 +, 160 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = ab_ap * t6 * t3 + t7 * t10 * a_minus_b - T(7) * t11 * cross_cross;
    const T t13 = T(6) * t7 * t9 * a_minus_b + T(6) * ab_ap * t5 * t3 + T(5) * t2 * t12 * cross_cross;
    const T t14 = T(6) * t7 * t9 + T(5) * t2 * ab_ap * t12 - T(6) * t5 * t3;
    const T t15 = T(20) * t2 * ap_ap * t12 - T(5) * t2 * t13 - T(8) * t2 * ab_ap * t14;
    F = (T(1) / T(120)) * t2 * t15 * in.w[2] + (T(1) / T(120)) * t2 * (T(2) * t2 * ab_ap * t15 + T(4) * t2 * t14 * ap_ap + T(5) * t2 * (T(8) * t4 * t3 - t2 * t13 * ab_ap - T(8) * t7 * t8)) * in.w[3] - (T(1) / T(6)) * t2 * t12 * in.w[0] - (T(1) / T(30)) * t2 * in.w[1] * t14;
    const T t16 = t7 * t10 - T(7) * t11 * ab_ap - t6 * t3;
    const T t17 = T(12) * t2 * ab_ap * t16 + T(7) * t2 * t12 + T(42) * t11 * ap_ap;
    const T t18 = T(7) * t2 * t14 + T(10) * t2 * ab_ap * t17 - T(30) * t2 * t16 * ap_ap;
    G_ap = t11 * in.w[0] - (T(1) / T(210)) * t2 * in.w[3] * t18 - (T(1) / T(42)) * t2 * in.w[2] * t17 - (T(1) / T(7)) * t2 * in.w[1] * t16;
    G_ab = (T(1) / T(840)) * t2 * (T(20) * t2 * ap_ap * t17 + T(7) * t2 * t15 - T(8) * t2 * ab_ap * t18) * in.w[3] - (T(1) / T(42)) * t2 * in.w[1] * t17 - (T(1) / T(7)) * t2 * t16 * in.w[0] - (T(1) / T(210)) * t2 * in.w[2] * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / ab_ab;
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = T(1) / cross_cross;
    const T t23 = t20 * t20;
    const T t24 = t21 * t21;
    const T t25 = T(2) * ab_ab * (t20 * a_minus_b + ab_ap * t21) * t22 + t20 * t23 * a_minus_b + ab_ap * t24 * t21;
    const T t26 = t23 * t23;
    const T t27 = t24 * t24;
    const T t28 = T(4) * ab_ab * t25 * t22 + T(3) * t20 * t26 * a_minus_b + T(3) * ab_ap * t27 * t21;
    const T t29 = t28 * ab_ap * t22 + T(3) * t27 * t21 - T(3) * t20 * t26;
    const T t30 = T(2) * t19 * t29 * ab_ap + T(5) * t25 * t22 - t28 * ap_ap * t22;
    F = (T(1) / T(15)) * t19 * t29 * in.w[1] + (T(1) / T(15)) * t19 * (T(5) * t19 * (t24 * t21 + ab_ap * t25 * t22 - t20 * t23) + T(2) * t19 * ab_ap * t30 - t19 * t29 * ap_ap) * in.w[3] + (T(1) / T(15)) * t19 * in.w[2] * t30 + (T(1) / T(15)) * t28 * in.w[0] * t22;
    const T t31 = t27 * t24;
    const T t32 = t26 * t23;
    const T t33 = T(5) * ab_ap * t31 * t21 + T(5) * t20 * t32 * a_minus_b + T(2) * ab_ab * t28 * t22;
    const T t34 = t33 * ab_ap * t22 + T(5) * t31 * t21 - T(5) * t20 * t32;
    const T t35 = T(7) * t28 * t22 + T(6) * t19 * t34 * ab_ap - T(3) * t33 * ap_ap * t22;
    const T t36 = T(2) * t19 * ab_ap * t35 + T(7) * t19 * t29 - T(3) * t19 * t34 * ap_ap;
    G_ap = (T(1) / T(35)) * t19 * t34 * in.w[1] + (T(1) / T(105)) * t19 * t36 * in.w[3] + (T(1) / T(105)) * t19 * t35 * in.w[2] + (T(1) / T(35)) * t33 * in.w[0] * t22;
    G_ab = (T(1) / T(35)) * t19 * t34 * in.w[0] + (T(1) / T(105)) * t19 * in.w[1] * t35 + (T(1) / T(105)) * t19 * (T(7) * t19 * t30 + T(2) * t19 * ab_ap * t36 - t19 * t35 * ap_ap) * in.w[3] + (T(1) / T(105)) * t19 * t36 * in.w[2];
  }
  const T g_factor = -T(7) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 33 +, 56 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, ap_bp);
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    F = (T(1) / T(48)) * in.w[0] * t4 * (T(8) * t7 * a_minus_b + T(8) * ab_ap * t10 + T(5) * (T(2) * t6 * a_minus_b + T(2) * ab_ap * t9 + T(3) * t4 * (ab_ab * J2 + t5 * a_minus_b + ab_ap * t8) * ab_ab) * t4 * ab_ab);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 40 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ab_ab;
    G_ab = (T(1) / T(8)) * (t5 + T(8) * t2 * ab_ap - t8) * in.w[0] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, ap_bp) * t11;
    const T t12 = T(1) / ap_ap;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / cross_cross;
    const T t19 = t16 * t15;
    const T t20 = t13 * t12;
    const T t21 = T(48) * t14 * ab_ap + T(48) * a_minus_b * t17 + T(7) * t18 * ab_ab * (T(5) * (T(2) * t13 * ab_ap + T(3) * (a_minus_b * t15 + t12 * ab_ap + ab_ab * J2) * t18 * ab_ab + T(2) * a_minus_b * t16) * t18 * ab_ab + T(8) * a_minus_b * t19 + T(8) * t20 * ab_ap);
    G_ap = (T(1) / T(384)) * t21 * in.w[0] * t18;
    const T t22 = T(1) / ab_ab;
    G_ab = (T(1) / T(384)) * in.w[0] * t22 * (t21 * t18 * ab_ap + T(48) * t14 - T(48) * t17);
  }
  const T g_factor = -T(8) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 40 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / ab_ab;
    F = -(T(1) / T(7)) * in.w[0] * (ab_ap * t4 + t7 * a_minus_b - T(8) * cross_cross * t8) * t9;
    G_ap = in.w[0] * t8;
    G_ab = -(T(1) / T(8)) * in.w[0] * t9 * (t7 - T(8) * ab_ap * t8 - t4);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / ap_ap;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(8) * ab_ap * t14 + T(8) * t17 * a_minus_b + T(5) * t18 * (T(2) * ab_ap * t13 + T(2) * t16 * a_minus_b + T(3) * (t15 * a_minus_b + ab_ab * J2 + ab_ap * t12) * t18 * ab_ab) * ab_ab;
    F = (T(1) / T(48)) * t19 * in.w[0] * t18;
    const T t20 = t13 * t13;
    const T t21 = t16 * t16;
    const T t22 = T(48) * ab_ap * t20 + T(48) * t21 * a_minus_b + T(7) * t19 * t18 * ab_ab;
    G_ap = (T(1) / T(384)) * in.w[0] * t18 * t22;
    const T t23 = T(1) / ab_ab;
    G_ab = -(T(1) / T(384)) * in.w[0] * t23 * (T(48) * t21 - t18 * ab_ap * t22 - T(48) * t20);
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 36 +, 63 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    F = in.w[0] * t2 - (T(1) / T(6)) * in.w[1] * t3 * (t6 - T(6) * ab_ap * t2 - t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, ap_bp) * t11;
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / ap_ap;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(8) * ab_ap * t15 + T(8) * t18 * a_minus_b + T(5) * (T(2) * t17 * a_minus_b + T(2) * ab_ap * t14 + T(3) * (J2 * ab_ab + ab_ap * t13 + t16 * a_minus_b) * t12 * ab_ab) * t12 * ab_ab;
    const T t20 = T(1) / ab_ab;
    F = (T(1) / T(48)) * in.w[0] * t12 * t19 - (T(1) / T(48)) * in.w[1] * (T(8) * t18 - T(8) * t15 - ab_ap * t12 * t19) * t20;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 44 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t6 + T(8) * ab_ap * t2 - t9;
    G_ap = in.w[0] * t2 + (T(1) / T(8)) * in.w[1] * t3 * t10;
    G_ab = (T(1) / T(8)) * t3 * t10 * in.w[0] - (T(1) / T(28)) * (T(4) * t3 * (t6 * ab_ap + a_minus_b * t9 - T(8) * cross_cross * t2) + T(28) * ap_ap * t2 - T(7) * t3 * t10 * ab_ap) * in.w[1] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t15 * t14;
    const T t21 = T(8) * a_minus_b * t19 + T(5) * t13 * ab_ab * (T(2) * a_minus_b * t18 + T(3) * t13 * (t14 * ab_ap + ab_ab * J2 + a_minus_b * t17) * ab_ab + T(2) * t15 * ab_ap) + T(8) * t20 * ab_ap;
    const T t22 = t18 * t18;
    const T t23 = T(48) * t16 * ab_ap + T(7) * t21 * t13 * ab_ab + T(48) * a_minus_b * t22;
    const T t24 = T(1) / ab_ab;
    const T t25 = T(48) * t16 + t13 * ab_ap * t23 - T(48) * t22;
    G_ap = (T(1) / T(384)) * t13 * t23 * in.w[0] + (T(1) / T(384)) * in.w[1] * t24 * t25;
    G_ab = (T(1) / T(384)) * t24 * t25 * in.w[0] + (T(1) / T(384)) * in.w[1] * t24 * (T(2) * t24 * ab_ap * t25 + T(8) * t21 * t13 - ap_ap * t13 * t23);
  }
  const T g_factor = -T(8) * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 47 +, 105 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = t4 * ab_ap + a_minus_b * t7 - T(8) * cross_cross * t8;
    const T t10 = T(1) / ab_ab;
    const T t11 = t6 * t5;
    const T t12 = t3 * t2;
    F = -(T(1) / T(7)) * in.w[0] * t9 * t10 - (T(1) / T(42)) * (T(6) * t9 * t10 * ab_ap + T(7) * t11 - T(7) * t12) * in.w[1] * t10;
    const T t13 = t7 - t4 - T(8) * t8 * ab_ap;
    G_ap = in.w[0] * t8 - (T(1) / T(8)) * t13 * in.w[1] * t10;
    G_ab = -(T(1) / T(8)) * t13 * in.w[0] * t10 - (T(1) / T(28)) * in.w[1] * t10 * (T(4) * t9 * t10 + T(7) * t13 * t10 * ab_ap + T(28) * ap_ap * t8);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, ap_bp);
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = T(1) / ap_ap;
    const T t19 = t18 * t18;
    const T t20 = t17 * t17;
    const T t21 = t20 * t17;
    const T t22 = t19 * t18;
    const T t23 = T(5) * t16 * ab_ab * (T(3) * t16 * (a_minus_b * t17 + t18 * ab_ap + J2 * ab_ab) * ab_ab + T(2) * t19 * ab_ap + T(2) * a_minus_b * t20) + T(8) * a_minus_b * t21 + T(8) * t22 * ab_ap;
    const T t24 = T(1) / ab_ab;
    F = (T(1) / T(48)) * (t16 * t23 * ab_ap + T(8) * t22 - T(8) * t21) * in.w[1] * t24 + (T(1) / T(48)) * in.w[0] * t16 * t23;
    const T t25 = t19 * t19;
    const T t26 = t20 * t20;
    const T t27 = T(48) * t25 * ab_ap + T(7) * t16 * t23 * ab_ab + T(48) * a_minus_b * t26;
    const T t28 = T(48) * t26 - T(48) * t25 - t16 * t27 * ab_ap;
    G_ap = (T(1) / T(384)) * in.w[0] * t16 * t27 - (T(1) / T(384)) * t28 * in.w[1] * t24;
    G_ab = -(T(1) / T(384)) * in.w[1] * (T(2) * t28 * t24 * ab_ap + ap_ap * t16 * t27 - T(8) * t16 * t23) * t24 - (T(1) / T(384)) * in.w[0] * t28 * t24;
  }
  const T g_factor = -T(8) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 39 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t6 + T(6) * t2 * ab_ap - t9;
    F = t2 * in.w[0] + (T(1) / T(6)) * t3 * t10 * in.w[1] - (T(1) / T(15)) * in.w[2] * t3 * (T(3) * (t6 * ab_ap + a_minus_b * t9 - T(6) * t2 * cross_cross) * t3 + T(15) * ap_ap * t2 - T(5) * t3 * t10 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, ap_bp);
    const T t13 = T(1) / ap_ap;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = T(2) * t14 * ab_ap + T(3) * t16 * (J2 * ab_ab + a_minus_b * t17 + t13 * ab_ap) * ab_ab + T(2) * a_minus_b * t18;
    const T t20 = t18 * t17;
    const T t21 = T(8) * t15 * ab_ap + T(5) * t16 * ab_ab * t19 + T(8) * a_minus_b * t20;
    const T t22 = T(8) * t15 + t16 * ab_ap * t21 - T(8) * t20;
    const T t23 = T(1) / ab_ab;
    F = (T(1) / T(48)) * t22 * t23 * in.w[1] + (T(1) / T(48)) * in.w[2] * t23 * (T(2) * t22 * t23 * ab_ap + T(6) * t16 * t19 - ap_ap * t16 * t21) + (T(1) / T(48)) * t16 * in.w[0] * t21;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 50 +, 111 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 + T(8) * t2 * ab_ap - t8;
    const T t10 = T(1) / ab_ab;
    const T t11 = T(8) * cross_cross * t2 - a_minus_b * t8 - t5 * ab_ap;
    const T t12 = T(28) * ap_ap * t2 - T(4) * t10 * t11 - T(7) * t9 * t10 * ab_ap;
    G_ap = in.w[0] * t2 + (T(1) / T(8)) * t9 * t10 * in.w[1] - (T(1) / T(28)) * in.w[2] * t10 * t12;
    const T t13 = t4 * t3;
    const T t14 = t7 * t6;
    G_ab = (T(1) / T(8)) * t9 * t10 * in.w[0] + (T(1) / T(168)) * in.w[2] * (T(4) * t10 * (T(6) * t10 * ab_ap * t11 + T(7) * t13 - T(7) * t14) - T(12) * t10 * t12 * ab_ap - T(21) * ap_ap * t9 * t10) * t10 - (T(1) / T(28)) * t10 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, ap_bp);
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / ap_ap;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / cross_cross;
    const T t24 = T(8) * a_minus_b * t19 + T(8) * t22 * ab_ap + T(5) * t23 * (T(3) * t23 * ab_ab * (ab_ab * J2 + a_minus_b * t17 + t20 * ab_ap) + T(2) * t21 * ab_ap + T(2) * a_minus_b * t18) * ab_ab;
    const T t25 = t18 * t18;
    const T t26 = t21 * t21;
    const T t27 = T(7) * t24 * t23 * ab_ab + T(48) * a_minus_b * t25 + T(48) * t26 * ab_ap;
    const T t28 = T(1) / ab_ab;
    const T t29 = T(48) * t26 + t27 * t23 * ab_ap - T(48) * t25;
    const T t30 = ap_ap * t27 * t23 - T(2) * t28 * ab_ap * t29 - T(8) * t24 * t23;
    G_ap = (T(1) / T(384)) * t27 * t23 * in.w[0] + (T(1) / T(384)) * t28 * in.w[1] * t29 - (T(1) / T(384)) * in.w[2] * t30 * t28;
    G_ab = (T(1) / T(384)) * t28 * in.w[0] * t29 - (T(1) / T(384)) * (T(2) * t30 * t28 * ab_ap + T(8) * t28 * (T(8) * t19 - T(8) * t22 - t24 * t23 * ab_ap) + ap_ap * t28 * t29) * in.w[2] * t28 - (T(1) / T(384)) * t30 * t28 * in.w[1];
  }
  const T g_factor = -T(8) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 54 +, 128 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / bp_bp;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t3 * t3;
    const T t9 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t10 = ab_ap * t7 + t8 * a_minus_b - T(8) * t9 * cross_cross;
    const T t11 = T(1) / ab_ab;
    const T t12 = t6 * t5;
    const T t13 = T(7) * t4 + T(6) * t10 * ab_ap * t11 - T(7) * t12;
    F = -(T(1) / T(42)) * in.w[1] * t13 * t11 - (T(1) / T(7)) * t10 * in.w[0] * t11 - (T(1) / T(105)) * in.w[2] * t11 * (T(3) * (T(7) * t4 * a_minus_b + T(7) * ab_ap * t12 + T(6) * t10 * cross_cross * t11) * t11 + T(5) * ab_ap * t13 * t11 - T(15) * t10 * ap_ap * t11);
    const T t14 = t8 - T(8) * ab_ap * t9 - t7;
    const T t15 = T(4) * t10 * t11 + T(28) * ap_ap * t9 + T(7) * ab_ap * t11 * t14;
    G_ap = in.w[0] * t9 - (T(1) / T(28)) * t15 * in.w[2] * t11 - (T(1) / T(8)) * in.w[1] * t11 * t14;
    G_ab = (T(1) / T(168)) * (T(21) * ap_ap * t11 * t14 - T(12) * ab_ap * t15 * t11 - T(4) * t13 * t11) * in.w[2] * t11 - (T(1) / T(28)) * in.w[1] * t15 * t11 - (T(1) / T(8)) * in.w[0] * t11 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(cross_cross);
    const T t17 = T(1) / t16;
    const T J2 = atan2(t16, ap_bp) * t17;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(1) / ap_ap;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = T(2) * ab_ap * t23 + T(2) * t20 * a_minus_b + T(3) * (J2 * ab_ab + t19 * a_minus_b + ab_ap * t22) * t18 * ab_ab;
    const T t26 = T(8) * t21 * a_minus_b + T(8) * ab_ap * t24 + T(5) * t25 * t18 * ab_ab;
    const T t27 = T(8) * t21 - T(8) * t24 - ab_ap * t18 * t26;
    const T t28 = T(1) / ab_ab;
    F = (T(1) / T(48)) * in.w[0] * t18 * t26 + (T(1) / T(48)) * (T(6) * t25 * t18 - T(2) * ab_ap * t27 * t28 - ap_ap * t18 * t26) * in.w[2] * t28 - (T(1) / T(48)) * t27 * in.w[1] * t28;
    const T t29 = t23 * t23;
    const T t30 = t20 * t20;
    const T t31 = T(48) * ab_ap * t29 + T(7) * t18 * t26 * ab_ab + T(48) * t30 * a_minus_b;
    const T t32 = ab_ap * t18 * t31 + T(48) * t29 - T(48) * t30;
    const T t33 = T(2) * ab_ap * t32 * t28 + T(8) * t18 * t26 - ap_ap * t18 * t31;
    G_ap = (T(1) / T(384)) * in.w[0] * t18 * t31 + (T(1) / T(384)) * in.w[1] * t32 * t28 + (T(1) / T(384)) * t33 * in.w[2] * t28;
    G_ab = (T(1) / T(384)) * t33 * in.w[1] * t28 + (T(1) / T(384)) * in.w[0] * t32 * t28 - (T(1) / T(384)) * (T(8) * t27 * t28 + ap_ap * t32 * t28 - T(2) * t33 * ab_ap * t28) * in.w[2] * t28;
  }
  const T g_factor = -T(8) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 44 +, 87 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(1) / T(5)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t5 * t4;
    const T t10 = t8 * a_minus_b + ab_ap * t9 - T(6) * cross_cross * t2;
    const T t11 = t9 + T(6) * t2 * ab_ap - t8;
    const T t12 = T(3) * t3 * t10 + T(15) * t2 * ap_ap - T(5) * t3 * ab_ap * t11;
    F = t2 * in.w[0] + (T(1) / T(60)) * t3 * (T(3) * t3 * (T(5) * t5 - T(4) * t3 * ab_ap * t10 - T(5) * t7) - T(8) * t3 * ab_ap * t12 - T(10) * t3 * t11 * ap_ap) * in.w[3] + (T(1) / T(6)) * t3 * in.w[1] * t11 - (T(1) / T(15)) * t3 * t12 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, ap_bp);
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = T(1) / bp_bp;
    const T t19 = t18 * t18;
    const T t20 = T(2) * ab_ap * t17 + T(3) * t15 * ab_ab * (ab_ap * t16 + t18 * a_minus_b + ab_ab * J2) + T(2) * t19 * a_minus_b;
    const T t21 = t19 * t18;
    const T t22 = t17 * t16;
    const T t23 = T(5) * t15 * ab_ab * t20 + T(8) * t21 * a_minus_b + T(8) * ab_ap * t22;
    const T t24 = T(1) / ab_ab;
    const T t25 = T(8) * t22 + t15 * ab_ap * t23 - T(8) * t21;
    const T t26 = t15 * ap_ap * t23 - T(2) * t24 * ab_ap * t25 - T(6) * t15 * t20;
    F = (T(1) / T(48)) * t15 * t23 * in.w[0] + (T(1) / T(48)) * t24 * in.w[1] * t25 - (T(1) / T(48)) * t24 * (t24 * t25 * ap_ap + T(2) * t24 * ab_ap * t26 - T(6) * t24 * (T(2) * t17 + t15 * ab_ap * t20 - T(2) * t19)) * in.w[3] - (T(1) / T(48)) * t24 * t26 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 56 +, 131 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t6 - t9 - T(8) * ab_ap * t2;
    const T t11 = T(8) * cross_cross * t2 - a_minus_b * t6 - ab_ap * t9;
    const T t12 = T(7) * t3 * t10 * ab_ap + T(28) * ap_ap * t2 - T(4) * t11 * t3;
    const T t13 = t5 * t4;
    const T t14 = t8 * t7;
    const T t15 = T(7) * t13 - T(6) * t11 * t3 * ab_ap - T(7) * t14;
    const T t16 = T(12) * t3 * ab_ap * t12 + T(4) * t15 * t3 - T(21) * t3 * t10 * ap_ap;
    G_ap = in.w[0] * t2 - (T(1) / T(168)) * t16 * in.w[3] * t3 - (T(1) / T(28)) * t3 * t12 * in.w[2] - (T(1) / T(8)) * t3 * t10 * in.w[1];
    G_ab = -(T(1) / T(420)) * in.w[3] * t3 * (T(4) * t3 * (T(5) * t15 * t3 * ab_ap + T(15) * t11 * t3 * ap_ap - T(3) * t3 * (T(6) * t11 * cross_cross * t3 - T(7) * ab_ap * t14 - T(7) * a_minus_b * t13)) + T(5) * t16 * t3 * ab_ap - T(15) * t3 * t12 * ap_ap) - (T(1) / T(28)) * t3 * in.w[1] * t12 - (T(1) / T(8)) * in.w[0] * t3 * t10 - (T(1) / T(168)) * t16 * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(cross_cross);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, ap_bp);
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / ap_ap;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / bp_bp;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(2) * a_minus_b * t24 + T(2) * ab_ap * t21 + T(3) * t19 * ab_ab * (ab_ab * J2 + a_minus_b * t23 + ab_ap * t20);
    const T t27 = T(8) * ab_ap * t22 + T(8) * a_minus_b * t25 + T(5) * t19 * ab_ab * t26;
    const T t28 = t24 * t24;
    const T t29 = t21 * t21;
    const T t30 = T(7) * t19 * ab_ab * t27 + T(48) * a_minus_b * t28 + T(48) * ab_ap * t29;
    const T t31 = T(1) / ab_ab;
    const T t32 = T(48) * t28 - t19 * t30 * ab_ap - T(48) * t29;
    const T t33 = T(8) * t25 - T(8) * t22 - t19 * t27 * ab_ap;
    const T t34 = T(2) * t31 * ab_ap * t32 + t19 * t30 * ap_ap - T(8) * t19 * t27;
    const T t35 = t31 * t32 * ap_ap - T(8) * t33 * t31 - T(2) * t31 * t34 * ab_ap;
    G_ap = (T(1) / T(384)) * in.w[0] * t19 * t30 + (T(1) / T(384)) * in.w[3] * t31 * t35 - (T(1) / T(384)) * t31 * in.w[1] * t32 - (T(1) / T(384)) * t31 * t34 * in.w[2];
    G_ab = (T(1) / T(384)) * t31 * in.w[2] * t35 + (T(1) / T(384)) * in.w[3] * t31 * (t31 * t34 * ap_ap + T(2) * t31 * ab_ap * t35 - T(8) * (t19 * t27 * ap_ap + T(2) * t33 * t31 * ab_ap - T(6) * t19 * t26) * t31) - (T(1) / T(384)) * in.w[0] * t31 * t32 - (T(1) / T(384)) * t31 * t34 * in.w[1];
  }
  const T g_factor = -T(8) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 63 +, 155 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(8) * t3 * cross_cross - a_minus_b * t6 - ab_ap * t9;
    const T t11 = t8 * t7;
    const T t12 = t5 * t4;
    const T t13 = T(6) * t2 * ab_ap * t10 + T(7) * t11 - T(7) * t12;
    const T t14 = T(7) * a_minus_b * t12 + T(7) * ab_ap * t11 - T(6) * t2 * cross_cross * t10;
    const T t15 = T(3) * t2 * t14 + T(15) * t2 * ap_ap * t10 - T(5) * t2 * ab_ap * t13;
    F = (T(1) / T(7)) * in.w[0] * t2 * t10 + (T(1) / T(42)) * t2 * in.w[1] * t13 - (T(1) / T(105)) * t2 * in.w[2] * t15 - (T(1) / T(420)) * (T(10) * t2 * t13 * ap_ap + T(8) * t2 * ab_ap * t15 + T(3) * t2 * (T(4) * t2 * ab_ap * t14 + T(35) * t5 - T(35) * t8)) * t2 * in.w[3];
    const T t16 = t9 + T(8) * t3 * ab_ap - t6;
    const T t17 = T(4) * t2 * t10 + T(7) * t2 * ab_ap * t16 - T(28) * t3 * ap_ap;
    const T t18 = T(4) * t2 * t13 + T(12) * t2 * ab_ap * t17 - T(21) * t2 * ap_ap * t16;
    G_ap = in.w[0] * t3 + (T(1) / T(168)) * t18 * t2 * in.w[3] + (T(1) / T(8)) * t2 * in.w[1] * t16 + (T(1) / T(28)) * t2 * t17 * in.w[2];
    G_ab = (T(1) / T(168)) * t18 * t2 * in.w[2] + (T(1) / T(28)) * t2 * in.w[1] * t17 + (T(1) / T(8)) * in.w[0] * t2 * t16 - (T(1) / T(420)) * t2 * in.w[3] * (T(4) * t2 * t15 + T(15) * t2 * ap_ap * t17 - T(5) * t18 * t2 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, ap_bp) * t20;
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * t22;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = T(1) / cross_cross;
    const T t27 = T(2) * a_minus_b * t23 + T(2) * ab_ap * t25 + T(3) * ab_ab * (ab_ab * J2 + ab_ap * t24 + a_minus_b * t22) * t26;
    const T t28 = t23 * t22;
    const T t29 = t25 * t24;
    const T t30 = T(8) * a_minus_b * t28 + T(5) * ab_ab * t27 * t26 + T(8) * ab_ap * t29;
    const T t31 = ab_ap * t30 * t26 + T(8) * t29 - T(8) * t28;
    const T t32 = T(6) * t27 * t26 + T(2) * t21 * t31 * ab_ap - ap_ap * t30 * t26;
    F = (T(1) / T(48)) * t21 * (T(2) * t21 * ab_ap * t32 + T(6) * t21 * (T(2) * t25 + t27 * ab_ap * t26 - T(2) * t23) - t21 * t31 * ap_ap) * in.w[3] + (T(1) / T(48)) * t21 * in.w[2] * t32 + (T(1) / T(48)) * in.w[0] * t30 * t26 + (T(1) / T(48)) * t21 * t31 * in.w[1];
    const T t33 = t23 * t23;
    const T t34 = t25 * t25;
    const T t35 = T(48) * a_minus_b * t33 + T(7) * ab_ab * t30 * t26 + T(48) * ab_ap * t34;
    const T t36 = t35 * ab_ap * t26 + T(48) * t34 - T(48) * t33;
    const T t37 = T(2) * t21 * ab_ap * t36 + T(8) * t30 * t26 - t35 * ap_ap * t26;
    const T t38 = t21 * ap_ap * t36 - T(2) * t21 * ab_ap * t37 - T(8) * t21 * t31;
    G_ap = (T(1) / T(384)) * t21 * t37 * in.w[2] + (T(1) / T(384)) * in.w[0] * t35 * t26 + (T(1) / T(384)) * t21 * in.w[1] * t36 - (T(1) / T(384)) * t21 * t38 * in.w[3];
    G_ab = (T(1) / T(384)) * in.w[0] * t21 * t36 + (T(1) / T(384)) * t21 * in.w[1] * t37 + (T(1) / T(384)) * t21 * (T(8) * t21 * t32 - T(2) * t21 * ab_ap * t38 - t21 * ap_ap * t37) * in.w[3] - (T(1) / T(384)) * t21 * t38 * in.w[2];
  }
  const T g_factor = -T(8) * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 32 +, 64 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    F = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = t6 * t6;
    const T t9 = t4 * t3;
    const T t10 = t8 * t6;
    F = (T(1) / T(35)) * (T(2) * (T(3) * t4 * t2 * a_minus_b + T(4) * (t5 * ab_ap * t6 + T(2) * (t5 * ab_ap + t2 * a_minus_b) * t7 * ab_ab + t3 * t2 * a_minus_b) * t7 * ab_ab + T(3) * t5 * ab_ap * t8) * t7 * ab_ab + T(5) * t9 * t2 * a_minus_b + T(5) * t5 * ab_ap * t10) * in.w[0] * t7;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 39 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    G_ab = -(T(1) / T(9)) * in.w[0] * t3 * (t7 * t4 - t8 * t11 - T(9) * t2 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t15 * t14;
    const T t22 = t19 * t18;
    const T t23 = T(35) * a_minus_b * t16 * t13 + T(35) * ab_ap * t17 * t20 + T(8) * t12 * ab_ab * (T(5) * a_minus_b * t21 * t13 + T(2) * (T(3) * a_minus_b * t15 * t13 + T(4) * t12 * ab_ab * (ab_ap * t17 * t18 + T(2) * t12 * ab_ab * (ab_ap * t17 + a_minus_b * t13) + a_minus_b * t14 * t13) + T(3) * ab_ap * t17 * t19) * t12 * ab_ab + T(5) * ab_ap * t17 * t22);
    G_ap = (T(1) / T(315)) * in.w[0] * t12 * t23;
    const T t24 = T(1) / ab_ab;
    G_ab = -(T(1) / T(315)) * in.w[0] * t24 * (T(35) * t16 * t13 - t12 * t23 * ab_ap - T(35) * t17 * t20);
  }
  const T g_factor = -T(9) * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 39 +, 97 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -(T(1) / T(8)) * t2 * (ab_ap * t6 * t3 + t7 * t10 * a_minus_b - T(9) * cross_cross * t11) * in.w[0];
    G_ap = t11 * in.w[0];
    G_ab = (T(1) / T(9)) * t2 * (t6 * t3 + T(9) * t11 * ab_ap - t7 * t10) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / cross_cross;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(5) * t13 * t16 * a_minus_b + T(2) * (T(4) * t12 * ab_ab * (T(2) * t12 * ab_ab * (t13 * a_minus_b + ab_ap * t17) + ab_ap * t18 * t17 + t13 * t14 * a_minus_b) + T(3) * t13 * t15 * a_minus_b + T(3) * ab_ap * t19 * t17) * t12 * ab_ab + T(5) * ab_ap * t20 * t17;
    F = (T(1) / T(35)) * t12 * t21 * in.w[0];
    const T t22 = t19 * t19;
    const T t23 = t15 * t15;
    const T t24 = T(8) * t12 * ab_ab * t21 + T(35) * ab_ap * t22 * t17 + T(35) * t13 * t23 * a_minus_b;
    G_ap = (T(1) / T(315)) * t12 * t24 * in.w[0];
    const T t25 = T(1) / ab_ab;
    G_ab = (T(1) / T(315)) * t25 * (T(35) * t22 * t17 + t12 * t24 * ab_ap - T(35) * t13 * t23) * in.w[0];
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 35 +, 73 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / ab_ab;
    F = t2 * in.w[0] + (T(1) / T(7)) * in.w[1] * (t6 * t3 + T(7) * t2 * ab_ap - t10 * t7) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / ab_ab;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(5) * a_minus_b * t16 * t13 + T(2) * t17 * (T(3) * a_minus_b * t15 * t13 + T(3) * t20 * t18 * ab_ap + T(4) * t17 * ab_ab * (T(2) * t17 * ab_ab * (a_minus_b * t13 + t18 * ab_ap) + t19 * t18 * ab_ap + a_minus_b * t14 * t13)) * ab_ab + T(5) * t21 * t18 * ab_ap;
    F = (T(1) / T(35)) * in.w[1] * t12 * (t22 * t17 * ab_ap + T(5) * t21 * t18 - T(5) * t16 * t13) + (T(1) / T(35)) * in.w[0] * t22 * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 43 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t4 - T(9) * ab_ap * t2 - t8 * t11;
    G_ap = in.w[0] * t2 - (T(1) / T(9)) * t3 * t12 * in.w[1];
    G_ab = -(T(1) / T(9)) * t3 * in.w[0] * t12 - (T(1) / T(72)) * t3 * in.w[1] * (T(72) * ap_ap * t2 + T(16) * t3 * ab_ap * t12 - T(9) * t3 * (T(9) * cross_cross * t2 - a_minus_b * t7 * t4 - ab_ap * t8 * t11));
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = T(1) / cross_cross;
    const T t19 = t17 * t17;
    const T t20 = t15 * t14;
    const T t21 = t19 * t17;
    const T t22 = T(2) * ab_ab * (T(3) * a_minus_b * t15 * t13 + T(4) * ab_ab * (ab_ap * t16 * t17 + T(2) * ab_ab * (ab_ap * t16 + a_minus_b * t13) * t18 + a_minus_b * t14 * t13) * t18 + T(3) * ab_ap * t16 * t19) * t18 + T(5) * a_minus_b * t20 * t13 + T(5) * ab_ap * t16 * t21;
    const T t23 = t15 * t15;
    const T t24 = t19 * t19;
    const T t25 = T(8) * t22 * ab_ab * t18 + T(35) * a_minus_b * t23 * t13 + T(35) * ab_ap * t16 * t24;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(35) * t23 * t13 - T(35) * t16 * t24 - t25 * ab_ap * t18;
    G_ap = (T(1) / T(315)) * t25 * in.w[0] * t18 - (T(1) / T(315)) * t26 * t27 * in.w[1];
    G_ab = (T(1) / T(315)) * t26 * (T(9) * t22 * t18 - T(2) * t26 * ab_ap * t27 - t25 * ap_ap * t18) * in.w[1] - (T(1) / T(315)) * t26 * in.w[0] * t27;
  }
  const T g_factor = -T(9) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 46 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = t2 * ab_ap * t5 + t6 * t9 * a_minus_b - T(9) * cross_cross * t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = t8 * t7;
    const T t14 = t4 * t3;
    F = -(T(1) / T(8)) * t11 * t12 * in.w[0] - (T(1) / T(56)) * in.w[1] * t12 * (T(8) * t6 * t13 + T(7) * t11 * t12 * ab_ap - T(8) * t2 * t14);
    const T t15 = T(9) * t10 * ab_ap + t2 * t5 - t6 * t9;
    G_ap = (T(1) / T(9)) * in.w[1] * t12 * t15 + t10 * in.w[0];
    G_ab = (T(1) / T(72)) * (T(16) * t12 * ab_ap * t15 - T(9) * t11 * t12 - T(72) * t10 * ap_ap) * in.w[1] * t12 + (T(1) / T(9)) * t12 * t15 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = T(5) * t17 * ab_ap * t20 + T(5) * t21 * t24 * a_minus_b + T(2) * t16 * ab_ab * (T(4) * t16 * (t21 * t22 * a_minus_b + t17 * ab_ap * t18 + T(2) * (t17 * ab_ap + t21 * a_minus_b) * t16 * ab_ab) * ab_ab + T(3) * t17 * ab_ap * t19 + T(3) * t21 * t23 * a_minus_b);
    const T t26 = T(1) / ab_ab;
    F = (T(1) / T(35)) * (t16 * t25 * ab_ap + T(5) * t17 * t20 - T(5) * t21 * t24) * in.w[1] * t26 + (T(1) / T(35)) * t16 * t25 * in.w[0];
    const T t27 = t19 * t19;
    const T t28 = t23 * t23;
    const T t29 = T(35) * t17 * ab_ap * t27 + T(35) * t21 * t28 * a_minus_b + T(8) * t16 * ab_ab * t25;
    const T t30 = T(35) * t21 * t28 - t16 * t29 * ab_ap - T(35) * t17 * t27;
    G_ap = (T(1) / T(315)) * t16 * t29 * in.w[0] - (T(1) / T(315)) * in.w[1] * t26 * t30;
    G_ab = -(T(1) / T(315)) * in.w[1] * (t16 * t29 * ap_ap + T(2) * t26 * ab_ap * t30 - T(9) * t16 * t25) * t26 - (T(1) / T(315)) * t26 * t30 * in.w[0];
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 38 +, 84 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t3 * t6 + T(7) * ab_ap * t7 - t11 * t8;
    F = (T(1) / T(42)) * in.w[2] * t2 * (T(12) * t2 * t12 * ab_ap - T(42) * t7 * ap_ap - T(7) * t2 * (t3 * ab_ap * t6 + t11 * t8 * a_minus_b - T(7) * cross_cross * t7)) + in.w[0] * t7 + (T(1) / T(7)) * t2 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(3) * t20 * t18 * a_minus_b + T(3) * t14 * ab_ap * t16 + T(4) * (T(2) * t13 * ab_ab * (t18 * a_minus_b + t14 * ab_ap) + t14 * ab_ap * t15 + t19 * t18 * a_minus_b) * t13 * ab_ab;
    const T t22 = t20 * t19;
    const T t23 = T(5) * t14 * ab_ap * t17 + T(2) * t13 * ab_ab * t21 + T(5) * t22 * t18 * a_minus_b;
    const T t24 = T(5) * t14 * t17 + t13 * ab_ap * t23 - T(5) * t22 * t18;
    const T t25 = T(1) / ab_ab;
    F = (T(1) / T(35)) * t13 * in.w[0] * t23 + (T(1) / T(35)) * t24 * t25 * in.w[1] - (T(1) / T(105)) * in.w[2] * t25 * (T(3) * t13 * t23 * ap_ap - T(6) * t24 * t25 * ab_ap - T(7) * t13 * t21);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 49 +, 125 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t4 - T(9) * ab_ap * t2 - t8 * t11;
    const T t13 = ab_ap * t8 * t11 + a_minus_b * t7 * t4 - T(9) * cross_cross * t2;
    const T t14 = T(9) * t3 * t13 + T(72) * ap_ap * t2 + T(16) * t3 * ab_ap * t12;
    G_ap = in.w[0] * t2 - (T(1) / T(9)) * t3 * in.w[1] * t12 - (T(1) / T(72)) * t3 * t14 * in.w[2];
    const T t15 = t10 * t9;
    const T t16 = t6 * t5;
    G_ab = -(T(1) / T(504)) * t3 * (T(14) * t3 * ab_ap * t14 - T(9) * t3 * (T(8) * t8 * t15 - T(8) * t16 * t4 - T(7) * t3 * ab_ap * t13) - T(56) * t3 * ap_ap * t12) * in.w[2] - (T(1) / T(72)) * t3 * in.w[1] * t14 - (T(1) / T(9)) * t3 * in.w[0] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t20 * t20;
    const T t25 = t23 * t22;
    const T t26 = t24 * t20;
    const T t27 = T(2) * ab_ab * t18 * (T(4) * ab_ab * t18 * (a_minus_b * t20 * t19 + ab_ap * t21 * t22 + T(2) * ab_ab * (a_minus_b * t19 + ab_ap * t21) * t18) + T(3) * ab_ap * t21 * t23 + T(3) * a_minus_b * t24 * t19) + T(5) * ab_ap * t21 * t25 + T(5) * a_minus_b * t26 * t19;
    const T t28 = t23 * t23;
    const T t29 = t24 * t24;
    const T t30 = T(35) * ab_ap * t21 * t28 + T(35) * a_minus_b * t29 * t19 + T(8) * ab_ab * t18 * t27;
    const T t31 = t18 * t30 * ab_ap + T(35) * t21 * t28 - T(35) * t29 * t19;
    const T t32 = T(9) * t18 * t27 + T(2) * t17 * t31 * ab_ap - t18 * t30 * ap_ap;
    G_ap = (T(1) / T(315)) * t17 * t32 * in.w[2] + (T(1) / T(315)) * t17 * t31 * in.w[1] + (T(1) / T(315)) * t18 * t30 * in.w[0];
    G_ab = (T(1) / T(315)) * t17 * in.w[0] * t31 + (T(1) / T(315)) * t17 * in.w[1] * t32 + (T(1) / T(315)) * t17 * (T(9) * t17 * (t18 * ab_ap * t27 + T(5) * t21 * t25 - T(5) * t26 * t19) + T(2) * t17 * ab_ap * t32 - t17 * t31 * ap_ap) * in.w[2];
  }
  const T g_factor = -T(9) * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 53 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t7 = t4 * t4;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(9) * t6 * cross_cross - t7 * t2 * ab_ap - a_minus_b * t8 * t11;
    const T t13 = T(1) / ab_ab;
    const T t14 = t10 * t9;
    const T t15 = T(8) * t5 * t2 + T(7) * t12 * t13 * ab_ap - T(8) * t8 * t14;
    F = (T(1) / T(56)) * in.w[1] * t15 * t13 + (T(1) / T(8)) * t12 * t13 * in.w[0] + (T(1) / T(336)) * in.w[2] * t13 * (T(7) * (T(7) * cross_cross * t12 * t13 - T(8) * t5 * t2 * ab_ap - T(8) * a_minus_b * t8 * t14) * t13 + T(12) * t15 * t13 * ab_ap - T(42) * ap_ap * t12 * t13);
    const T t16 = t7 * t2 + T(9) * t6 * ab_ap - t8 * t11;
    const T t17 = T(16) * t16 * t13 * ab_ap + T(9) * t12 * t13 - T(72) * ap_ap * t6;
    G_ap = (T(1) / T(72)) * in.w[2] * t13 * t17 + t6 * in.w[0] + (T(1) / T(9)) * in.w[1] * t16 * t13;
    G_ab = (T(1) / T(9)) * t16 * t13 * in.w[0] + (T(1) / T(72)) * in.w[1] * t13 * t17 - (T(1) / T(504)) * in.w[2] * (T(56) * ap_ap * t16 * t13 - T(14) * t13 * ab_ap * t17 - T(9) * t15 * t13) * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(3) * t21 * t19 * ab_ap + T(3) * a_minus_b * t23 * t25 + T(4) * (a_minus_b * t23 * t24 + T(2) * t18 * ab_ab * (t19 * ab_ap + a_minus_b * t23) + t20 * t19 * ab_ap) * t18 * ab_ab;
    const T t28 = T(5) * t22 * t19 * ab_ap + T(5) * a_minus_b * t23 * t26 + T(2) * t27 * t18 * ab_ab;
    const T t29 = T(1) / ab_ab;
    const T t30 = T(5) * t22 * t19 + t18 * ab_ap * t28 - T(5) * t23 * t26;
    F = (T(1) / T(35)) * t18 * in.w[0] * t28 + (T(1) / T(35)) * in.w[1] * t29 * t30 - (T(1) / T(105)) * (T(3) * ap_ap * t18 * t28 - T(6) * t29 * t30 * ab_ap - T(7) * t27 * t18) * in.w[2] * t29;
    const T t31 = t21 * t21;
    const T t32 = t25 * t25;
    const T t33 = T(35) * t31 * t19 * ab_ap + T(8) * t18 * ab_ab * t28 + T(35) * a_minus_b * t23 * t32;
    const T t34 = T(35) * t31 * t19 + t33 * t18 * ab_ap - T(35) * t23 * t32;
    const T t35 = T(9) * t18 * t28 + T(2) * t34 * t29 * ab_ap - t33 * ap_ap * t18;
    G_ap = (T(1) / T(315)) * in.w[1] * t34 * t29 + (T(1) / T(315)) * t33 * t18 * in.w[0] + (T(1) / T(315)) * in.w[2] * t35 * t29;
    G_ab = (T(1) / T(315)) * in.w[1] * t35 * t29 + (T(1) / T(315)) * t34 * t29 * in.w[0] - (T(1) / T(315)) * (ap_ap * t34 * t29 - T(2) * t35 * t29 * ab_ap - T(9) * t29 * t30) * in.w[2] * t29;
  }
  const T g_factor = -T(9) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 43 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(9), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(7) * ab_ap * t3 + t7 * t4 - t8 * t11;
    const T t13 = t8 * a_minus_b * t11 + ab_ap * t7 * t4 - T(7) * t3 * cross_cross;
    const T t14 = T(12) * ab_ap * t12 * t2 - T(42) * ap_ap * t3 - T(7) * t13 * t2;
    F = (T(1) / T(210)) * (T(10) * ab_ap * t2 * t14 + T(7) * (T(6) * t6 * t4 - T(5) * ab_ap * t13 * t2 - T(6) * t8 * t10) * t2 - T(30) * t12 * ap_ap * t2) * in.w[3] * t2 + (T(1) / T(7)) * t12 * t2 * in.w[1] + t3 * in.w[0] + (T(1) / T(42)) * in.w[2] * t2 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(4) * t19 * ab_ab * (ab_ap * t21 * t20 + T(2) * t19 * ab_ab * (t15 * a_minus_b + ab_ap * t20) + t15 * a_minus_b * t16) + T(3) * t15 * a_minus_b * t17 + T(3) * ab_ap * t22 * t20;
    const T t24 = t22 * t21;
    const T t25 = T(5) * t15 * a_minus_b * t18 + T(2) * t23 * t19 * ab_ab + T(5) * ab_ap * t24 * t20;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(5) * t15 * t18 - T(5) * t24 * t20 - ab_ap * t25 * t19;
    const T t28 = T(3) * t25 * ap_ap * t19 + T(6) * ab_ap * t26 * t27 - T(7) * t23 * t19;
    F = (T(1) / T(35)) * t25 * t19 * in.w[0] + (T(1) / T(105)) * (T(7) * (T(3) * t22 * t20 + ab_ap * t23 * t19 - T(3) * t15 * t17) * t26 + T(3) * ap_ap * t26 * t27 - T(2) * ab_ap * t28 * t26) * in.w[3] * t26 - (T(1) / T(35)) * t26 * t27 * in.w[1] - (T(1) / T(105)) * in.w[2] * t28 * t26;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 55 +, 146 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t3 + T(9) * t7 * ab_ap - t8 * t11;
    const T t13 = t8 * a_minus_b * t11 + t6 * ab_ap * t3 - T(9) * t7 * cross_cross;
    const T t14 = T(16) * t2 * t12 * ab_ap - T(72) * t7 * ap_ap - T(9) * t2 * t13;
    const T t15 = t10 * t9;
    const T t16 = t5 * t4;
    const T t17 = T(7) * t2 * ab_ap * t13 + T(8) * t8 * t15 - T(8) * t16 * t3;
    const T t18 = T(9) * t17 * t2 + T(56) * ap_ap * t2 * t12 - T(14) * t2 * t14 * ab_ap;
    G_ap = (T(1) / T(9)) * t2 * t12 * in.w[1] + (T(1) / T(72)) * in.w[2] * t2 * t14 + t7 * in.w[0] - (T(1) / T(504)) * in.w[3] * t2 * t18;
    G_ab = (T(1) / T(9)) * in.w[0] * t2 * t12 + (T(1) / T(72)) * t2 * t14 * in.w[1] - (T(1) / T(1008)) * in.w[3] * t2 * (T(14) * ap_ap * t2 * t14 + T(4) * t2 * t18 * ab_ap + T(3) * t2 * (T(7) * t2 * (T(8) * t8 * a_minus_b * t15 + T(8) * t16 * ab_ap * t3 + T(7) * cross_cross * t2 * t13) + T(12) * t17 * t2 * ab_ap - T(42) * ap_ap * t2 * t13)) - (T(1) / T(504)) * in.w[2] * t2 * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = T(4) * t19 * ab_ab * (T(2) * t19 * ab_ab * (t20 * a_minus_b + ab_ap * t24) + t20 * a_minus_b * t21 + t25 * ab_ap * t24) + T(3) * t26 * ab_ap * t24 + T(3) * t20 * a_minus_b * t22;
    const T t29 = T(5) * t20 * a_minus_b * t23 + T(5) * t27 * ab_ap * t24 + T(2) * t19 * ab_ab * t28;
    const T t30 = t22 * t22;
    const T t31 = t26 * t26;
    const T t32 = T(8) * t19 * t29 * ab_ab + T(35) * t20 * a_minus_b * t30 + T(35) * t31 * ab_ap * t24;
    const T t33 = T(35) * t31 * t24 + t19 * ab_ap * t32 - T(35) * t20 * t30;
    const T t34 = T(1) / ab_ab;
    const T t35 = ap_ap * t19 * t32 - T(2) * t33 * t34 * ab_ap - T(9) * t19 * t29;
    const T t36 = T(5) * t20 * t23 - t19 * t29 * ab_ap - T(5) * t27 * t24;
    const T t37 = ap_ap * t33 * t34 + T(2) * t35 * t34 * ab_ap + T(9) * t34 * t36;
    G_ap = (T(1) / T(315)) * t19 * in.w[0] * t32 + (T(1) / T(315)) * t33 * t34 * in.w[1] - (T(1) / T(315)) * in.w[3] * t34 * t37 - (T(1) / T(315)) * in.w[2] * t35 * t34;
    G_ab = (T(1) / T(315)) * t33 * in.w[0] * t34 - (T(1) / T(315)) * in.w[3] * t34 * (T(2) * t34 * t37 * ab_ap - ap_ap * t35 * t34 - T(3) * t34 * (T(7) * t19 * t28 - T(6) * t34 * ab_ap * t36 - T(3) * ap_ap * t19 * t29)) - (T(1) / T(315)) * t35 * t34 * in.w[1] - (T(1) / T(315)) * in.w[2] * t34 * t37;
  }
  const T g_factor = -T(9) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 62 +, 173 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(9) * cross_cross * t2 - t3 * t6 * a_minus_b - ab_ap * t10 * t7;
    const T t12 = T(1) / ab_ab;
    const T t13 = t9 * t8;
    const T t14 = t5 * t4;
    const T t15 = T(8) * ab_ap * t13 * t7 + T(8) * t3 * t14 * a_minus_b - T(7) * t11 * cross_cross * t12;
    const T t16 = T(8) * t3 * t14 - T(7) * t11 * t12 * ab_ap - T(8) * t13 * t7;
    const T t17 = T(7) * t12 * t15 + T(12) * t16 * t12 * ab_ap + T(42) * t11 * t12 * ap_ap;
    F = (T(1) / T(8)) * t11 * in.w[0] * t12 - (T(1) / T(1680)) * in.w[3] * t12 * (T(7) * (T(48) * t3 * t5 + T(5) * t12 * ab_ap * t15 - T(48) * t9 * t7) * t12 + T(10) * t12 * ab_ap * t17 - T(30) * t16 * t12 * ap_ap) - (T(1) / T(336)) * t12 * in.w[2] * t17 - (T(1) / T(56)) * t16 * t12 * in.w[1];
    const T t18 = T(9) * t2 * ab_ap + t10 * t7 - t3 * t6;
    const T t19 = T(9) * t11 * t12 + T(16) * t12 * t18 * ab_ap - T(72) * t2 * ap_ap;
    const T t20 = T(9) * t16 * t12 + T(56) * t12 * t18 * ap_ap - T(14) * t12 * t19 * ab_ap;
    G_ap = (T(1) / T(9)) * t12 * t18 * in.w[1] + (T(1) / T(72)) * t12 * t19 * in.w[2] + in.w[0] * t2 - (T(1) / T(504)) * in.w[3] * t20 * t12;
    G_ab = (T(1) / T(72)) * t12 * t19 * in.w[1] + (T(1) / T(9)) * in.w[0] * t12 * t18 - (T(1) / T(504)) * t20 * t12 * in.w[2] - (T(1) / T(1008)) * in.w[3] * t12 * (T(14) * t12 * t19 * ap_ap + T(3) * t12 * t17 + T(4) * t20 * t12 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = T(1) / cross_cross;
    const T t30 = T(3) * ab_ap * t23 * t21 + T(3) * t25 * t27 * a_minus_b + T(4) * t29 * ab_ab * (T(2) * t29 * (ab_ap * t21 + t25 * a_minus_b) * ab_ab + t25 * t26 * a_minus_b + ab_ap * t22 * t21);
    const T t31 = T(5) * ab_ap * t24 * t21 + T(5) * t25 * t28 * a_minus_b + T(2) * t30 * t29 * ab_ab;
    const T t32 = T(1) / ab_ab;
    const T t33 = T(5) * t25 * t28 - T(5) * t24 * t21 - t31 * t29 * ab_ap;
    const T t34 = T(3) * t31 * t29 * ap_ap + T(6) * t32 * ab_ap * t33 - T(7) * t30 * t29;
    F = (T(1) / T(35)) * t31 * t29 * in.w[0] - (T(1) / T(105)) * t32 * t34 * in.w[2] - (T(1) / T(35)) * t32 * in.w[1] * t33 - (T(1) / T(105)) * in.w[3] * t32 * (T(2) * t32 * ab_ap * t34 + T(7) * t32 * (T(3) * t25 * t27 - T(3) * t23 * t21 - t30 * t29 * ab_ap) - T(3) * t32 * t33 * ap_ap);
    const T t35 = t27 * t27;
    const T t36 = t23 * t23;
    const T t37 = T(8) * t31 * t29 * ab_ab + T(35) * t25 * t35 * a_minus_b + T(35) * ab_ap * t36 * t21;
    const T t38 = T(35) * t25 * t35 - T(35) * t36 * t21 - t29 * ab_ap * t37;
    const T t39 = t29 * ap_ap * t37 + T(2) * t32 * ab_ap * t38 - T(9) * t31 * t29;
    const T t40 = T(2) * t32 * t39 * ab_ap + T(9) * t32 * t33 - t32 * t38 * ap_ap;
    G_ap = (T(1) / T(315)) * t29 * in.w[0] * t37 - (T(1) / T(315)) * t32 * in.w[1] * t38 - (T(1) / T(315)) * in.w[3] * t32 * t40 - (T(1) / T(315)) * t32 * t39 * in.w[2];
    G_ab = -(T(1) / T(315)) * t32 * t40 * in.w[2] - (T(1) / T(315)) * in.w[0] * t32 * t38 - (T(1) / T(315)) * in.w[3] * t32 * (T(2) * t32 * ab_ap * t40 + T(3) * t32 * t34 - t32 * t39 * ap_ap) - (T(1) / T(315)) * t32 * in.w[1] * t39;
  }
  const T g_factor = -T(9) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 35 +, 65 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, ap_bp) * t3;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / ap_ap;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t6 * t5;
    const T t12 = t9 * t9;
    F = (T(1) / T(384)) * in.w[0] * t4 * (T(48) * t7 * ab_ap + T(7) * t4 * (T(5) * (T(2) * t6 * ab_ap + T(3) * t4 * ab_ab * (a_minus_b * t8 + t5 * ab_ap + J2 * ab_ab) + T(2) * a_minus_b * t9) * t4 * ab_ab + T(8) * a_minus_b * t10 + T(8) * t11 * ab_ap) * ab_ab + T(48) * a_minus_b * t12);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 42 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(1) / ab_ab;
    G_ab = (T(1) / T(10)) * (T(10) * ab_ap * t2 + t6 - t10) * in.w[0] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = t16 * t15;
    const T t20 = t18 * t17;
    const T t21 = t18 * t18;
    const T t22 = t16 * t16;
    const T t23 = t22 * t15;
    const T t24 = t21 * t17;
    const T t25 = T(3) * (T(7) * t14 * ab_ab * (T(5) * t14 * ab_ab * (T(2) * a_minus_b * t16 + T(2) * ab_ap * t18 + T(3) * (ab_ap * t17 + a_minus_b * t15 + ab_ab * J2) * t14 * ab_ab) + T(8) * a_minus_b * t19 + T(8) * ab_ap * t20) + T(48) * ab_ap * t21 + T(48) * a_minus_b * t22) * t14 * ab_ab + T(128) * a_minus_b * t23 + T(128) * ab_ap * t24;
    G_ap = (T(1) / T(1280)) * in.w[0] * t14 * t25;
    const T t26 = T(1) / ab_ab;
    G_ab = (T(1) / T(1280)) * in.w[0] * t26 * (ab_ap * t14 * t25 + T(128) * t24 - T(128) * t23);
  }
  const T g_factor = -T(10) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 42 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    F = (T(1) / T(9)) * in.w[0] * t2 * (T(10) * t3 * cross_cross - t7 * ab_ap - a_minus_b * t11);
    G_ap = in.w[0] * t3;
    G_ab = (T(1) / T(10)) * in.w[0] * t2 * (t7 + T(10) * t3 * ab_ap - t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / cross_cross;
    const T t21 = t18 * t18;
    const T t22 = t15 * t15;
    const T t23 = T(7) * (T(8) * t16 * ab_ap + T(8) * a_minus_b * t19 + T(5) * t20 * ab_ab * (T(3) * (a_minus_b * t17 + ab_ab * J2 + t14 * ab_ap) * t20 * ab_ab + T(2) * t15 * ab_ap + T(2) * a_minus_b * t18)) * t20 * ab_ab + T(48) * a_minus_b * t21 + T(48) * t22 * ab_ap;
    F = (T(1) / T(384)) * t23 * in.w[0] * t20;
    const T t24 = t22 * t14;
    const T t25 = t21 * t17;
    const T t26 = T(3) * t23 * t20 * ab_ab + T(128) * t24 * ab_ap + T(128) * a_minus_b * t25;
    G_ap = (T(1) / T(1280)) * t26 * in.w[0] * t20;
    const T t27 = T(1) / ab_ab;
    G_ab = (T(1) / T(1280)) * (t26 * t20 * ab_ap + T(128) * t24 - T(128) * t25) * in.w[0] * t27;
  }
  const T g_factor = -T(10) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 38 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    F = t2 * in.w[0] + (T(1) / T(8)) * t3 * (t6 + T(8) * ab_ap * t2 - t9) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(cross_cross);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, ap_bp);
    const T t12 = T(1) / ab_ab;
    const T t13 = T(1) / ap_ap;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t14 * t13;
    const T t20 = t18 * t17;
    const T t21 = t18 * t18;
    const T t22 = T(48) * ab_ap * t15 + T(7) * ab_ab * t16 * (T(5) * ab_ab * t16 * (T(2) * t18 * a_minus_b + T(3) * ab_ab * t16 * (ab_ab * J2 + ab_ap * t13 + t17 * a_minus_b) + T(2) * ab_ap * t14) + T(8) * ab_ap * t19 + T(8) * t20 * a_minus_b) + T(48) * t21 * a_minus_b;
    F = (T(1) / T(384)) * t12 * (T(48) * t15 + t16 * ab_ap * t22 - T(48) * t21) * in.w[1] + (T(1) / T(384)) * t16 * in.w[0] * t22;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 46 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * ab_ap * t3 + t7 - t11;
    G_ap = (T(1) / T(10)) * in.w[1] * t2 * t12 + in.w[0] * t3;
    G_ab = (T(1) / T(45)) * in.w[1] * t2 * (T(5) * t2 * (T(10) * t3 * cross_cross - ab_ap * t7 - a_minus_b * t11) + T(9) * ab_ap * t2 * t12 - T(45) * ap_ap * t3) + (T(1) / T(10)) * in.w[0] * t2 * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / ap_ap;
    const T t17 = T(1) / bp_bp;
    const T t18 = t16 * t16;
    const T t19 = t17 * t17;
    const T t20 = t19 * t17;
    const T t21 = t18 * t16;
    const T t22 = t18 * t18;
    const T t23 = t19 * t19;
    const T t24 = T(7) * (T(5) * (T(3) * (ab_ap * t16 + a_minus_b * t17 + ab_ab * J2) * t15 * ab_ab + T(2) * ab_ap * t18 + T(2) * a_minus_b * t19) * t15 * ab_ab + T(8) * a_minus_b * t20 + T(8) * ab_ap * t21) * t15 * ab_ab + T(48) * ab_ap * t22 + T(48) * a_minus_b * t23;
    const T t25 = t22 * t16;
    const T t26 = t23 * t17;
    const T t27 = T(3) * t15 * ab_ab * t24 + T(128) * ab_ap * t25 + T(128) * a_minus_b * t26;
    const T t28 = ab_ap * t27 * t15 + T(128) * t25 - T(128) * t26;
    const T t29 = T(1) / ab_ab;
    G_ap = (T(1) / T(1280)) * t27 * in.w[0] * t15 + (T(1) / T(1280)) * t28 * in.w[1] * t29;
    G_ab = (T(1) / T(1280)) * t28 * in.w[0] * t29 - (T(1) / T(3840)) * in.w[1] * (T(3) * t27 * ap_ap * t15 - T(10) * t15 * t24 - T(6) * ab_ap * t28 * t29) * t29;
  }
  const T g_factor = -T(10) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 49 +, 115 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t2;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = ab_ap * t5 + t9 * a_minus_b - T(10) * t10 * cross_cross;
    const T t12 = T(1) / ab_ab;
    F = -(T(1) / T(9)) * in.w[0] * t11 * t12 - (T(1) / T(72)) * (T(9) * t8 + T(8) * ab_ap * t11 * t12 - T(9) * t4) * in.w[1] * t12;
    const T t13 = t9 - T(10) * ab_ap * t10 - t5;
    G_ap = t10 * in.w[0] - (T(1) / T(10)) * t13 * in.w[1] * t12;
    G_ab = -(T(1) / T(45)) * (T(45) * t10 * ap_ap + T(9) * t13 * ab_ap * t12 + T(5) * t11 * t12) * in.w[1] * t12 - (T(1) / T(10)) * t13 * in.w[0] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, ap_bp) * t15;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t17 * t16;
    const T t23 = T(1) / cross_cross;
    const T t24 = t20 * t20;
    const T t25 = T(48) * ab_ap * t18 + T(7) * (T(8) * t21 * a_minus_b + T(8) * ab_ap * t22 + T(5) * (T(2) * ab_ap * t17 + T(2) * t20 * a_minus_b + T(3) * (J2 * ab_ab + t19 * a_minus_b + ab_ap * t16) * t23 * ab_ab) * t23 * ab_ab) * t23 * ab_ab + T(48) * t24 * a_minus_b;
    const T t26 = T(1) / ab_ab;
    F = (T(1) / T(384)) * t25 * in.w[0] * t23 - (T(1) / T(384)) * (T(48) * t24 - ab_ap * t25 * t23 - T(48) * t18) * in.w[1] * t26;
    const T t27 = t18 * t16;
    const T t28 = t24 * t19;
    const T t29 = T(128) * ab_ap * t27 + T(128) * t28 * a_minus_b + T(3) * t25 * t23 * ab_ab;
    const T t30 = T(128) * t28 - ab_ap * t29 * t23 - T(128) * t27;
    G_ap = (T(1) / T(1280)) * in.w[0] * t29 * t23 - (T(1) / T(1280)) * t30 * in.w[1] * t26;
    G_ab = -(T(1) / T(1280)) * in.w[0] * t30 * t26 - (T(1) / T(3840)) * in.w[1] * t26 * (T(6) * ab_ap * t30 * t26 + T(3) * ap_ap * t29 * t23 - T(10) * t25 * t23);
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 41 +, 82 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / ab_ab;
    const T t10 = t8 - T(8) * t2 * ab_ap - t5;
    F = t2 * in.w[0] + (T(1) / T(28)) * (T(4) * (T(8) * t2 * cross_cross - ab_ap * t5 - t8 * a_minus_b) * t9 - T(7) * ab_ap * t10 * t9 - T(28) * t2 * ap_ap) * in.w[2] * t9 - (T(1) / T(8)) * in.w[1] * t10 * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(cross_cross);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, ap_bp) * t12;
    const T t13 = T(1) / bp_bp;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(8) * t15 * a_minus_b + T(8) * ab_ap * t18 + T(5) * (T(2) * t14 * a_minus_b + T(2) * ab_ap * t17 + T(3) * (ab_ap * t16 + t13 * a_minus_b + J2 * ab_ab) * t19 * ab_ab) * t19 * ab_ab;
    const T t21 = t17 * t17;
    const T t22 = t14 * t14;
    const T t23 = T(7) * t20 * t19 * ab_ab + T(48) * ab_ap * t21 + T(48) * t22 * a_minus_b;
    const T t24 = T(1) / ab_ab;
    const T t25 = T(48) * t22 - ab_ap * t23 * t19 - T(48) * t21;
    F = (T(1) / T(384)) * in.w[0] * t23 * t19 + (T(1) / T(384)) * (T(8) * t20 * t19 - ap_ap * t23 * t19 - T(2) * ab_ap * t24 * t25) * in.w[2] * t24 - (T(1) / T(384)) * in.w[1] * t24 * t25;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 52 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * t3 * ab_ap + t7 - t11;
    const T t13 = T(10) * cross_cross * t3 - a_minus_b * t11 - t7 * ab_ap;
    const T t14 = T(5) * t2 * t13 + T(9) * t2 * t12 * ab_ap - T(45) * ap_ap * t3;
    G_ap = (T(1) / T(10)) * in.w[1] * t2 * t12 + t3 * in.w[0] + (T(1) / T(45)) * in.w[2] * t2 * t14;
    G_ab = (T(1) / T(45)) * in.w[1] * t2 * t14 + (T(1) / T(360)) * (T(16) * t2 * t14 * ab_ap + T(5) * t2 * (T(9) * t6 + T(8) * t2 * t13 * ab_ap - T(9) * t10) - T(36) * ap_ap * t2 * t12) * in.w[2] * t2 + (T(1) / T(10)) * t2 * t12 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, ap_bp);
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / ap_ap;
    const T t22 = T(1) / cross_cross;
    const T t23 = t21 * t21;
    const T t24 = t23 * t21;
    const T t25 = t18 * t17;
    const T t26 = t23 * t23;
    const T t27 = T(48) * a_minus_b * t19 + T(7) * (T(5) * (T(3) * (ab_ab * J2 + a_minus_b * t17 + t21 * ab_ap) * t22 * ab_ab + T(2) * t23 * ab_ap + T(2) * a_minus_b * t18) * t22 * ab_ab + T(8) * t24 * ab_ap + T(8) * a_minus_b * t25) * t22 * ab_ab + T(48) * t26 * ab_ap;
    const T t28 = t26 * t21;
    const T t29 = T(128) * a_minus_b * t20 + T(3) * t27 * t22 * ab_ab + T(128) * t28 * ab_ap;
    const T t30 = t29 * t22 * ab_ap + T(128) * t28 - T(128) * t20;
    const T t31 = T(1) / ab_ab;
    const T t32 = T(6) * t30 * t31 * ab_ap + T(10) * t27 * t22 - T(3) * ap_ap * t29 * t22;
    G_ap = (T(1) / T(1280)) * t30 * in.w[1] * t31 + (T(1) / T(1280)) * t29 * t22 * in.w[0] + (T(1) / T(3840)) * in.w[2] * t31 * t32;
    G_ab = (T(1) / T(1280)) * t30 * t31 * in.w[0] + (T(1) / T(3840)) * in.w[1] * t31 * t32 - (T(1) / T(3840)) * in.w[2] * t31 * (T(3) * t30 * ap_ap * t31 - T(2) * t31 * t32 * ab_ap - T(10) * (t27 * t22 * ab_ap + T(48) * t26 - T(48) * t19) * t31);
  }
  const T g_factor = -T(10) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 56 +, 139 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = t5 * t3;
    const T t11 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = t9 * a_minus_b + ab_ap * t10 - T(10) * cross_cross * t11;
    const T t13 = T(9) * t5 - T(8) * t2 * t12 * ab_ap - T(9) * t8;
    F = (T(1) / T(72)) * t2 * t13 * in.w[1] - (T(1) / T(252)) * in.w[2] * t2 * (T(4) * t2 * (T(9) * t8 * a_minus_b + T(9) * ab_ap * t5 + T(8) * cross_cross * t2 * t12) - T(28) * t2 * t12 * ap_ap - T(7) * t2 * t13 * ab_ap) - (T(1) / T(9)) * t2 * t12 * in.w[0];
    const T t14 = t10 + T(10) * t11 * ab_ap - t9;
    const T t15 = T(5) * t2 * t12 + T(45) * t11 * ap_ap - T(9) * t2 * ab_ap * t14;
    G_ap = (T(1) / T(10)) * t2 * t14 * in.w[1] + in.w[0] * t11 - (T(1) / T(45)) * in.w[2] * t2 * t15;
    G_ab = (T(1) / T(10)) * t2 * in.w[0] * t14 - (T(1) / T(45)) * t2 * t15 * in.w[1] - (T(1) / T(360)) * in.w[2] * t2 * (T(36) * t2 * t14 * ap_ap + T(16) * t2 * ab_ap * t15 - T(5) * t2 * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(cross_cross);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, ap_bp);
    const T t18 = T(1) / ab_ab;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / ap_ap;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t20 * t20;
    const T t24 = t22 * t21;
    const T t25 = t23 * t20;
    const T t26 = T(5) * t19 * ab_ab * (T(3) * t19 * ab_ab * (ab_ap * t20 + t21 * a_minus_b + ab_ab * J2) + T(2) * t22 * a_minus_b + T(2) * ab_ap * t23) + T(8) * t24 * a_minus_b + T(8) * ab_ap * t25;
    const T t27 = t23 * t23;
    const T t28 = t22 * t22;
    const T t29 = T(7) * t19 * ab_ab * t26 + T(48) * t28 * a_minus_b + T(48) * ab_ap * t27;
    const T t30 = T(48) * t27 + t19 * ab_ap * t29 - T(48) * t28;
    F = (T(1) / T(384)) * in.w[2] * t18 * (T(8) * t19 * t26 + T(2) * t18 * ab_ap * t30 - t19 * ap_ap * t29) + (T(1) / T(384)) * t18 * t30 * in.w[1] + (T(1) / T(384)) * t19 * in.w[0] * t29;
    const T t31 = t28 * t21;
    const T t32 = t27 * t20;
    const T t33 = T(3) * t19 * ab_ab * t29 + T(128) * t31 * a_minus_b + T(128) * ab_ap * t32;
    const T t34 = t19 * t33 * ab_ap + T(128) * t32 - T(128) * t31;
    const T t35 = T(10) * t19 * t29 + T(6) * t18 * ab_ap * t34 - T(3) * t19 * t33 * ap_ap;
    G_ap = (T(1) / T(1280)) * t19 * t33 * in.w[0] + (T(1) / T(1280)) * t18 * in.w[1] * t34 + (T(1) / T(3840)) * in.w[2] * t18 * t35;
    G_ab = (T(1) / T(3840)) * in.w[2] * t18 * (T(2) * t18 * ab_ap * t35 + T(10) * t18 * t30 - T(3) * t18 * ap_ap * t34) + (T(1) / T(3840)) * t18 * t35 * in.w[1] + (T(1) / T(1280)) * t18 * in.w[0] * t34;
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 46 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(10), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t4 + T(8) * t5 * ab_ap - t8;
    const T t10 = T(1) / ab_ab;
    const T t11 = t7 * t6;
    const T t12 = t8 * a_minus_b + ab_ap * t4 - T(8) * t5 * cross_cross;
    const T t13 = t3 * t2;
    const T t14 = T(28) * t5 * ap_ap + T(4) * t12 * t10 - T(7) * ab_ap * t9 * t10;
    F = (T(1) / T(8)) * in.w[1] * t9 * t10 + t5 * in.w[0] - (T(1) / T(168)) * in.w[3] * (T(4) * (T(7) * t11 + T(6) * ab_ap * t12 * t10 - T(7) * t13) * t10 + T(21) * ap_ap * t9 * t10 + T(12) * t14 * ab_ap * t10) * t10 - (T(1) / T(28)) * t14 * in.w[2] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, ap_bp) * t16;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / ap_ap;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t21 * t20;
    const T t24 = T(1) / cross_cross;
    const T t25 = t18 * t17;
    const T t26 = T(8) * ab_ap * t23 + T(5) * (T(2) * ab_ap * t21 + T(3) * t24 * (t17 * a_minus_b + J2 * ab_ab + ab_ap * t20) * ab_ab + T(2) * t18 * a_minus_b) * t24 * ab_ab + T(8) * t25 * a_minus_b;
    const T t27 = T(48) * t19 * a_minus_b + T(48) * ab_ap * t22 + T(7) * t26 * t24 * ab_ab;
    const T t28 = T(48) * t22 + ab_ap * t27 * t24 - T(48) * t19;
    const T t29 = T(1) / ab_ab;
    const T t30 = t27 * ap_ap * t24 - T(2) * ab_ap * t28 * t29 - T(8) * t26 * t24;
    F = (T(1) / T(384)) * t27 * t24 * in.w[0] + (T(1) / T(384)) * in.w[1] * t28 * t29 - (T(1) / T(384)) * in.w[3] * (ap_ap * t28 * t29 + T(2) * ab_ap * t30 * t29 + T(8) * (T(8) * t25 - T(8) * t23 - ab_ap * t26 * t24) * t29) * t29 - (T(1) / T(384)) * in.w[2] * t30 * t29;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 58 +, 142 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * ab_ap * t3 + t7 - t11;
    const T t13 = ab_ap * t7 + a_minus_b * t11 - T(10) * cross_cross * t3;
    const T t14 = T(5) * t2 * t13 + T(45) * t3 * ap_ap - T(9) * t2 * ab_ap * t12;
    const T t15 = T(8) * t2 * t13 * ab_ap + T(9) * t10 - T(9) * t6;
    const T t16 = T(36) * t2 * t12 * ap_ap + T(16) * t2 * ab_ap * t14 + T(5) * t15 * t2;
    G_ap = (T(1) / T(10)) * t2 * in.w[1] * t12 + in.w[0] * t3 - (T(1) / T(45)) * t2 * in.w[2] * t14 - (T(1) / T(360)) * t2 * t16 * in.w[3];
    G_ab = (T(1) / T(10)) * in.w[0] * t2 * t12 - (T(1) / T(360)) * t2 * in.w[2] * t16 - (T(1) / T(45)) * t2 * in.w[1] * t14 - (T(1) / T(1260)) * t2 * (T(7) * t2 * ab_ap * t16 - T(28) * t2 * t14 * ap_ap - T(5) * t2 * (T(28) * t2 * t13 * ap_ap - T(7) * t15 * t2 * ab_ap - T(4) * t2 * (T(9) * ab_ap * t6 + T(8) * cross_cross * t2 * t13 + T(9) * a_minus_b * t10))) * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(cross_cross);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, ap_bp);
    const T t19 = T(1) / ab_ab;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / ap_ap;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t22 * t21;
    const T t28 = T(8) * a_minus_b * t26 + T(5) * t20 * ab_ab * (T(2) * a_minus_b * t25 + T(2) * ab_ap * t22 + T(3) * t20 * (ab_ap * t21 + a_minus_b * t24 + ab_ab * J2) * ab_ab) + T(8) * ab_ap * t27;
    const T t29 = t25 * t25;
    const T t30 = T(48) * ab_ap * t23 + T(7) * t20 * ab_ab * t28 + T(48) * a_minus_b * t29;
    const T t31 = t23 * t21;
    const T t32 = t29 * t24;
    const T t33 = T(128) * ab_ap * t31 + T(128) * a_minus_b * t32 + T(3) * t20 * ab_ab * t30;
    const T t34 = T(128) * t31 + t20 * ab_ap * t33 - T(128) * t32;
    const T t35 = T(10) * t20 * t30 + T(6) * t19 * ab_ap * t34 - T(3) * t20 * t33 * ap_ap;
    const T t36 = T(48) * t29 - T(48) * t23 - t20 * ab_ap * t30;
    const T t37 = T(2) * t19 * t35 * ab_ap - T(3) * t19 * t34 * ap_ap - T(10) * t19 * t36;
    G_ap = (T(1) / T(3840)) * t19 * t37 * in.w[3] + (T(1) / T(1280)) * t20 * in.w[0] * t33 + (T(1) / T(1280)) * t19 * in.w[1] * t34 + (T(1) / T(3840)) * t19 * t35 * in.w[2];
    G_ab = (T(1) / T(1280)) * in.w[0] * t19 * t34 + (T(1) / T(3840)) * t19 * in.w[2] * t37 + (T(1) / T(3840)) * t19 * in.w[1] * t35 - (T(1) / T(3840)) * t19 * (t19 * t35 * ap_ap + T(10) * t19 * (T(2) * t19 * ab_ap * t36 + t20 * t30 * ap_ap - T(8) * t20 * t28) - T(2) * t19 * ab_ap * t37) * in.w[3];
  }
  const T g_factor = -T(10) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 65 +, 166 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t7 = t5 * t3;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * t6 * cross_cross - ab_ap * t7 - t11 * a_minus_b;
    const T t13 = T(9) * t5 + T(8) * t2 * t12 * ab_ap - T(9) * t10;
    const T t14 = T(9) * ab_ap * t5 + T(9) * t10 * a_minus_b - T(8) * t2 * t12 * cross_cross;
    const T t15 = T(28) * t2 * t12 * ap_ap + T(4) * t2 * t14 - T(7) * t2 * ab_ap * t13;
    const T t16 = t9 * t8;
    const T t17 = t4 * t3;
    F = (T(1) / T(72)) * t2 * in.w[1] * t13 + (T(1) / T(9)) * t2 * t12 * in.w[0] - (T(1) / T(252)) * t2 * t15 * in.w[2] - (T(1) / T(504)) * t2 * (T(4) * t2 * t15 * ab_ap + T(7) * t2 * t13 * ap_ap + T(4) * (T(21) * t16 + T(2) * t2 * t14 * ab_ap - T(21) * t17) * t2) * in.w[3];
    const T t18 = T(10) * ab_ap * t6 + t7 - t11;
    const T t19 = T(5) * t2 * t12 + T(9) * t2 * ab_ap * t18 - T(45) * t6 * ap_ap;
    const T t20 = T(36) * t2 * ap_ap * t18 - T(16) * t2 * t19 * ab_ap - T(5) * t2 * t13;
    G_ap = (T(1) / T(45)) * t2 * t19 * in.w[2] + t6 * in.w[0] + (T(1) / T(10)) * t2 * in.w[1] * t18 - (T(1) / T(360)) * t2 * t20 * in.w[3];
    G_ab = (T(1) / T(45)) * t2 * in.w[1] * t19 + (T(1) / T(10)) * t2 * t18 * in.w[0] - (T(1) / T(1260)) * t2 * in.w[3] * (T(7) * t2 * ab_ap * t20 + T(28) * t2 * t19 * ap_ap + T(5) * t2 * t15) - (T(1) / T(360)) * t2 * t20 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(cross_cross);
    const T t22 = T(1) / t21;
    const T J2 = atan2(t21, ap_bp) * t22;
    const T t23 = T(1) / ab_ab;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(1) / cross_cross;
    const T t28 = t25 * t24;
    const T t29 = T(1) / bp_bp;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = T(8) * ab_ap * t28 + T(8) * t31 * a_minus_b + T(5) * ab_ab * (T(3) * ab_ab * (t29 * a_minus_b + ab_ab * J2 + ab_ap * t24) * t27 + T(2) * ab_ap * t25 + T(2) * t30 * a_minus_b) * t27;
    const T t33 = t30 * t30;
    const T t34 = T(48) * ab_ap * t26 + T(7) * ab_ab * t32 * t27 + T(48) * t33 * a_minus_b;
    const T t35 = T(48) * t26 + ab_ap * t27 * t34 - T(48) * t33;
    const T t36 = T(2) * t35 * t23 * ab_ap + T(8) * t32 * t27 - ap_ap * t27 * t34;
    F = (T(1) / T(384)) * t23 * in.w[2] * t36 + (T(1) / T(384)) * t23 * (T(8) * t23 * (ab_ap * t32 * t27 + T(8) * t28 - T(8) * t31) + T(2) * t23 * ab_ap * t36 - t35 * t23 * ap_ap) * in.w[3] + (T(1) / T(384)) * t35 * t23 * in.w[1] + (T(1) / T(384)) * in.w[0] * t27 * t34;
    const T t37 = t26 * t24;
    const T t38 = t33 * t29;
    const T t39 = T(128) * ab_ap * t37 + T(3) * ab_ab * t27 * t34 + T(128) * t38 * a_minus_b;
    const T t40 = T(128) * t37 + ab_ap * t39 * t27 - T(128) * t38;
    const T t41 = T(3) * t39 * ap_ap * t27 - T(6) * t23 * ab_ap * t40 - T(10) * t27 * t34;
    const T t42 = T(3) * t23 * t40 * ap_ap + T(2) * t41 * t23 * ab_ap - T(10) * t35 * t23;
    G_ap = (T(1) / T(1280)) * t23 * in.w[1] * t40 + (T(1) / T(1280)) * t39 * in.w[0] * t27 - (T(1) / T(3840)) * t41 * t23 * in.w[2] - (T(1) / T(3840)) * t42 * t23 * in.w[3];
    G_ab = (T(1) / T(1280)) * t23 * t40 * in.w[0] + (T(1) / T(3840)) * t23 * (T(10) * t23 * t36 + t41 * t23 * ap_ap - T(2) * t42 * t23 * ab_ap) * in.w[3] - (T(1) / T(3840)) * t42 * t23 * in.w[2] - (T(1) / T(3840)) * t41 * t23 * in.w[1];
  }
  const T g_factor = -T(10) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 34 +, 75 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / cross_cross;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t4;
    const T t12 = t9 * t9;
    F = (T(1) / T(315)) * in.w[0] * t2 * (T(35) * t3 * ab_ap * t6 + T(8) * t2 * ab_ab * (T(5) * t10 * t7 * a_minus_b + T(5) * t3 * ab_ap * t11 + T(2) * t2 * ab_ab * (T(3) * t3 * ab_ap * t5 + T(4) * t2 * ab_ab * (t8 * t7 * a_minus_b + T(2) * t2 * ab_ab * (t3 * ab_ap + t7 * a_minus_b) + t3 * ab_ap * t4) + T(3) * t9 * t7 * a_minus_b)) + T(35) * t12 * t7 * a_minus_b);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 41 +, 104 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    G_ab = -(T(1) / T(11)) * in.w[0] * t3 * (t4 * t8 - t13 * t9 - T(11) * t2 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t16;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = t22 * t21;
    const T t26 = t17 * t16;
    const T t27 = T(63) * t19 * ab_ap * t15 + T(63) * t20 * a_minus_b * t24 + T(2) * (T(35) * t18 * ab_ap * t15 + T(35) * t20 * a_minus_b * t23 + T(8) * (T(5) * t20 * a_minus_b * t25 + T(2) * t14 * ab_ab * (T(3) * t20 * a_minus_b * t22 + T(3) * t17 * ab_ap * t15 + T(4) * (T(2) * (t20 * a_minus_b + ab_ap * t15) * t14 * ab_ab + t16 * ab_ap * t15 + t20 * a_minus_b * t21) * t14 * ab_ab) + T(5) * t26 * ab_ap * t15) * t14 * ab_ab) * t14 * ab_ab;
    G_ap = (T(1) / T(693)) * in.w[0] * t14 * t27;
    const T t28 = T(1) / ab_ab;
    G_ab = (T(1) / T(693)) * in.w[0] * t28 * (t14 * ab_ap * t27 + T(63) * t19 * t15 - T(63) * t20 * t24);
  }
  const T g_factor = -T(11) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 41 +, 108 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / ab_ab;
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
    const T t13 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -(T(1) / T(10)) * in.w[0] * t2 * (t7 * t3 * ab_ap + t8 * t12 * a_minus_b - T(11) * cross_cross * t13);
    G_ap = in.w[0] * t13;
    G_ab = (T(1) / T(11)) * in.w[0] * t2 * (t7 * t3 + T(11) * ab_ap * t13 - t8 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / cross_cross;
    const T t23 = t20 * t19;
    const T t24 = t16 * t15;
    const T t25 = T(35) * t17 * t14 * ab_ap + T(35) * t18 * t21 * a_minus_b + T(8) * t22 * ab_ab * (T(5) * t18 * t23 * a_minus_b + T(2) * t22 * ab_ab * (T(3) * t16 * t14 * ab_ap + T(4) * t22 * ab_ab * (t18 * t19 * a_minus_b + T(2) * t22 * ab_ab * (t14 * ab_ap + t18 * a_minus_b) + t15 * t14 * ab_ap) + T(3) * t18 * t20 * a_minus_b) + T(5) * t24 * t14 * ab_ap);
    F = (T(1) / T(315)) * t25 * in.w[0] * t22;
    const T t26 = t17 * t15;
    const T t27 = t21 * t19;
    const T t28 = T(63) * t26 * t14 * ab_ap + T(2) * t25 * t22 * ab_ab + T(63) * t18 * t27 * a_minus_b;
    G_ap = (T(1) / T(693)) * in.w[0] * t22 * t28;
    const T t29 = T(1) / ab_ab;
    G_ab = (T(1) / T(693)) * in.w[0] * t29 * (T(63) * t26 * t14 + t22 * t28 * ab_ap - T(63) * t18 * t27);
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 37 +, 84 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(8) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / ab_ab;
    F = in.w[0] * t2 - (T(1) / T(9)) * in.w[1] * (t6 * t3 - T(9) * ab_ap * t2 - t10 * t7) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t14 * t13;
    const T t22 = t19 * t19;
    const T t23 = T(35) * ab_ap * t15 * t12 + T(8) * (T(2) * t16 * ab_ab * (T(4) * t16 * ab_ab * (t18 * t17 * a_minus_b + ab_ap * t13 * t12 + T(2) * (t17 * a_minus_b + ab_ap * t12) * t16 * ab_ab) + T(3) * t19 * t17 * a_minus_b + T(3) * ab_ap * t14 * t12) + T(5) * t20 * t17 * a_minus_b + T(5) * ab_ap * t21 * t12) * t16 * ab_ab + T(35) * t22 * t17 * a_minus_b;
    const T t24 = T(1) / ab_ab;
    F = (T(1) / T(315)) * in.w[0] * t23 * t16 - (T(1) / T(315)) * (T(35) * t22 * t17 - ab_ap * t23 * t16 - T(35) * t15 * t12) * in.w[1] * t24;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 45 +, 118 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t14 = t4 * t8 + T(11) * ab_ap * t2 - t9 * t13;
    G_ap = t2 * in.w[0] + (T(1) / T(11)) * in.w[1] * t3 * t14;
    G_ab = (T(1) / T(11)) * t3 * t14 * in.w[0] - (T(1) / T(110)) * in.w[1] * t3 * (T(110) * t2 * ap_ap + T(11) * t3 * (ab_ap * t4 * t8 + t9 * a_minus_b * t13 - T(11) * cross_cross * t2) - T(20) * t3 * ab_ap * t14);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t22;
    const T t26 = t18 * t17;
    const T t27 = t23 * t22;
    const T t28 = T(35) * t21 * a_minus_b * t24 + T(8) * t15 * ab_ab * (T(2) * t15 * ab_ab * (T(3) * ab_ap * t16 * t18 + T(4) * (t21 * a_minus_b * t22 + T(2) * t15 * ab_ab * (t21 * a_minus_b + ab_ap * t16) + ab_ap * t16 * t17) * t15 * ab_ab + T(3) * t21 * a_minus_b * t23) + T(5) * ab_ap * t16 * t26 + T(5) * t21 * a_minus_b * t27) + T(35) * ab_ap * t16 * t19;
    const T t29 = T(63) * ab_ap * t16 * t20 + T(63) * t21 * a_minus_b * t25 + T(2) * t15 * ab_ab * t28;
    const T t30 = t15 * ab_ap * t29 + T(63) * t16 * t20 - T(63) * t21 * t25;
    const T t31 = T(1) / ab_ab;
    G_ap = (T(1) / T(693)) * t30 * in.w[1] * t31 + (T(1) / T(693)) * t15 * t29 * in.w[0];
    G_ab = (T(1) / T(693)) * t30 * t31 * in.w[0] + (T(1) / T(3465)) * in.w[1] * t31 * (T(10) * t30 * t31 * ab_ap + T(11) * t15 * t28 - T(5) * t15 * t29 * ap_ap);
  }
  const T g_factor = -T(11) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 48 +, 131 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t13 = t6 * t2 * ab_ap + a_minus_b * t7 * t11 - T(11) * cross_cross * t12;
    const T t14 = T(1) / ab_ab;
    F = -(T(1) / T(10)) * in.w[0] * t13 * t14 - (T(1) / T(90)) * (T(9) * t13 * t14 * ab_ap + T(10) * t7 * t10 - T(10) * t5 * t2) * in.w[1] * t14;
    const T t15 = t6 * t2 + T(11) * ab_ap * t12 - t7 * t11;
    G_ap = in.w[0] * t12 + (T(1) / T(11)) * t15 * in.w[1] * t14;
    G_ab = (T(1) / T(11)) * in.w[0] * t15 * t14 - (T(1) / T(110)) * in.w[1] * t14 * (T(110) * ap_ap * t12 + T(11) * t13 * t14 - T(20) * t15 * t14 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t18 * t17;
    const T t25 = t23 * t22;
    const T t26 = t23 * t23;
    const T t27 = T(8) * (T(2) * t20 * ab_ab * (T(3) * t18 * t16 * ab_ap + T(4) * (T(2) * t20 * ab_ab * (t16 * ab_ap + a_minus_b * t21) + a_minus_b * t21 * t22 + t17 * t16 * ab_ap) * t20 * ab_ab + T(3) * a_minus_b * t21 * t23) + T(5) * t24 * t16 * ab_ap + T(5) * a_minus_b * t21 * t25) * t20 * ab_ab + T(35) * t19 * t16 * ab_ap + T(35) * a_minus_b * t21 * t26;
    const T t28 = T(1) / ab_ab;
    F = (T(1) / T(315)) * (T(35) * t19 * t16 + t20 * t27 * ab_ap - T(35) * t21 * t26) * in.w[1] * t28 + (T(1) / T(315)) * in.w[0] * t20 * t27;
    const T t29 = t19 * t17;
    const T t30 = t26 * t22;
    const T t31 = T(2) * t20 * ab_ab * t27 + T(63) * t29 * t16 * ab_ap + T(63) * a_minus_b * t21 * t30;
    const T t32 = T(63) * t29 * t16 + t31 * t20 * ab_ap - T(63) * t21 * t30;
    G_ap = (T(1) / T(693)) * in.w[0] * t31 * t20 + (T(1) / T(693)) * t32 * in.w[1] * t28;
    G_ab = (T(1) / T(693)) * t32 * in.w[0] * t28 + (T(1) / T(3465)) * (T(10) * t32 * t28 * ab_ap + T(11) * t20 * t27 - T(5) * ap_ap * t31 * t20) * in.w[1] * t28;
  }
  const T g_factor = -T(11) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 40 +, 94 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t4 - t11 * t8 - T(9) * ab_ap * t2;
    F = in.w[0] * t2 - (T(1) / T(72)) * in.w[2] * t3 * (T(16) * t3 * t12 * ab_ap + T(72) * ap_ap * t2 + T(9) * (t11 * t8 * ab_ap + a_minus_b * t7 * t4 - T(9) * cross_cross * t2) * t3) - (T(1) / T(9)) * t3 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / cross_cross;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t16 * t15;
    const T t23 = T(5) * a_minus_b * t21 * t18 + T(2) * t13 * ab_ab * (T(3) * a_minus_b * t20 * t18 + T(3) * t16 * t14 * ab_ap + T(4) * t13 * ab_ab * (T(2) * (t14 * ab_ap + a_minus_b * t18) * t13 * ab_ab + t15 * t14 * ab_ap + a_minus_b * t19 * t18)) + T(5) * t22 * t14 * ab_ap;
    const T t24 = t20 * t20;
    const T t25 = T(35) * t17 * t14 * ab_ap + T(8) * t13 * ab_ab * t23 + T(35) * a_minus_b * t24 * t18;
    const T t26 = T(1) / ab_ab;
    const T t27 = T(35) * t24 * t18 - T(35) * t17 * t14 - t13 * t25 * ab_ap;
    F = (T(1) / T(315)) * t13 * t25 * in.w[0] - (T(1) / T(315)) * t26 * t27 * in.w[1] - (T(1) / T(315)) * (T(2) * t26 * t27 * ab_ap + ap_ap * t13 * t25 - T(9) * t13 * t23) * in.w[2] * t26;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 51 +, 138 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t3 * t7 + T(11) * ab_ap * t8 - t13 * t9;
    const T t15 = t13 * t9 * a_minus_b + t3 * t7 * ab_ap - T(11) * cross_cross * t8;
    const T t16 = T(110) * ap_ap * t8 + T(11) * t2 * t15 - T(20) * t2 * t14 * ab_ap;
    G_ap = (T(1) / T(11)) * t2 * t14 * in.w[1] + in.w[0] * t8 - (T(1) / T(110)) * in.w[2] * t2 * t16;
    G_ab = (T(1) / T(11)) * t2 * t14 * in.w[0] - (T(1) / T(990)) * in.w[2] * t2 * (T(18) * t2 * ab_ap * t16 + T(90) * t2 * t14 * ap_ap - T(11) * t2 * (T(10) * t3 * t6 - T(10) * t12 * t9 - T(9) * t2 * t15 * ab_ap)) - (T(1) / T(110)) * t2 * in.w[1] * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t24;
    const T t28 = T(1) / cross_cross;
    const T t29 = t20 * t19;
    const T t30 = t25 * t24;
    const T t31 = T(35) * t26 * t23 * a_minus_b + T(35) * t18 * t21 * ab_ap + T(8) * ab_ab * t28 * (T(2) * ab_ab * (T(4) * (T(2) * ab_ab * (t18 * ab_ap + t23 * a_minus_b) * t28 + t18 * t19 * ab_ap + t24 * t23 * a_minus_b) * ab_ab * t28 + T(3) * t25 * t23 * a_minus_b + T(3) * t18 * t20 * ab_ap) * t28 + T(5) * t18 * t29 * ab_ap + T(5) * t30 * t23 * a_minus_b);
    const T t32 = T(63) * t27 * t23 * a_minus_b + T(63) * t18 * t22 * ab_ap + T(2) * t31 * ab_ab * t28;
    const T t33 = T(63) * t18 * t22 + ab_ap * t32 * t28 - T(63) * t27 * t23;
    const T t34 = T(5) * ap_ap * t32 * t28 - T(11) * t31 * t28 - T(10) * t17 * ab_ap * t33;
    G_ap = (T(1) / T(693)) * t17 * t33 * in.w[1] + (T(1) / T(693)) * in.w[0] * t32 * t28 - (T(1) / T(3465)) * in.w[2] * t17 * t34;
    G_ab = (T(1) / T(693)) * t17 * in.w[0] * t33 - (T(1) / T(3465)) * t17 * t34 * in.w[1] - (T(1) / T(3465)) * in.w[2] * t17 * (T(2) * t17 * t34 * ab_ap + T(5) * t17 * ap_ap * t33 - T(11) * t17 * (T(35) * t18 * t21 + t31 * ab_ap * t28 - T(35) * t26 * t23));
  }
  const T g_factor = -T(11) * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 55 +, 155 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = t6 * t4;
    const T t13 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t14 = t7 * t11 * a_minus_b + t3 * ab_ap * t12 - T(11) * cross_cross * t13;
    const T t15 = T(10) * t3 * t6 - T(9) * t2 * t14 * ab_ap - T(10) * t7 * t10;
    F = (T(1) / T(90)) * t2 * t15 * in.w[1] - (T(1) / T(720)) * (T(9) * t2 * (T(9) * cross_cross * t2 * t14 + T(10) * t7 * t10 * a_minus_b + T(10) * t3 * ab_ap * t6) - T(72) * t2 * t14 * ap_ap - T(16) * t2 * t15 * ab_ap) * in.w[2] * t2 - (T(1) / T(10)) * t2 * t14 * in.w[0];
    const T t16 = T(11) * ab_ap * t13 + t3 * t12 - t7 * t11;
    const T t17 = T(20) * t2 * ab_ap * t16 - T(11) * t2 * t14 - T(110) * t13 * ap_ap;
    G_ap = (T(1) / T(110)) * in.w[2] * t2 * t17 + in.w[0] * t13 + (T(1) / T(11)) * t2 * in.w[1] * t16;
    G_ab = (T(1) / T(110)) * t2 * t17 * in.w[1] + (T(1) / T(11)) * t2 * in.w[0] * t16 - (T(1) / T(990)) * in.w[2] * t2 * (T(90) * t2 * t16 * ap_ap - T(11) * t2 * t15 - T(18) * t2 * t17 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / ab_ab;
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t22 * t21;
    const T t27 = t25 * t24;
    const T t28 = T(2) * (T(3) * t20 * ab_ap * t22 + T(4) * t19 * ab_ab * (t23 * t24 * a_minus_b + T(2) * t19 * ab_ab * (t23 * a_minus_b + t20 * ab_ap) + t20 * ab_ap * t21) + T(3) * t23 * t25 * a_minus_b) * t19 * ab_ab + T(5) * t20 * ab_ap * t26 + T(5) * t23 * t27 * a_minus_b;
    const T t29 = t25 * t25;
    const T t30 = t22 * t22;
    const T t31 = T(8) * t19 * ab_ab * t28 + T(35) * t23 * t29 * a_minus_b + T(35) * t20 * ab_ap * t30;
    const T t32 = t19 * t31 * ab_ap + T(35) * t20 * t30 - T(35) * t23 * t29;
    F = (T(1) / T(315)) * in.w[2] * t18 * (T(2) * t18 * ab_ap * t32 + T(9) * t19 * t28 - t19 * t31 * ap_ap) + (T(1) / T(315)) * t19 * t31 * in.w[0] + (T(1) / T(315)) * t18 * in.w[1] * t32;
    const T t33 = t30 * t21;
    const T t34 = t29 * t24;
    const T t35 = T(63) * t23 * t34 * a_minus_b + T(2) * t19 * ab_ab * t31 + T(63) * t20 * ab_ap * t33;
    const T t36 = T(63) * t20 * t33 + t19 * t35 * ab_ap - T(63) * t23 * t34;
    const T t37 = T(10) * t18 * t36 * ab_ap + T(11) * t19 * t31 - T(5) * t19 * t35 * ap_ap;
    G_ap = (T(1) / T(3465)) * in.w[2] * t18 * t37 + (T(1) / T(693)) * t18 * t36 * in.w[1] + (T(1) / T(693)) * t19 * in.w[0] * t35;
    G_ab = (T(1) / T(693)) * t18 * t36 * in.w[0] + (T(1) / T(3465)) * t18 * t37 * in.w[1] + (T(1) / T(3465)) * in.w[2] * t18 * (T(11) * t18 * t32 + T(2) * t18 * t37 * ab_ap - T(5) * t18 * t36 * ap_ap);
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 45 +, 110 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(8) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t4 - t11 * t8 - T(9) * t2 * ab_ap;
    const T t13 = T(9) * cross_cross * t2 - a_minus_b * t7 * t4 - t11 * t8 * ab_ap;
    const T t14 = T(72) * ap_ap * t2 + T(16) * t3 * ab_ap * t12 - T(9) * t3 * t13;
    const T t15 = t10 * t9;
    const T t16 = t6 * t5;
    F = in.w[0] * t2 - (T(1) / T(72)) * t3 * t14 * in.w[2] - (T(1) / T(504)) * in.w[3] * t3 * (T(14) * t3 * t14 * ab_ap - T(56) * ap_ap * t3 * t12 - T(9) * (T(7) * t3 * t13 * ab_ap + T(8) * t15 * t8 - T(8) * t16 * t4) * t3) - (T(1) / T(9)) * t3 * in.w[1] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(5) * t21 * t18 * ab_ap + T(5) * a_minus_b * t25 * t22 + T(2) * t17 * ab_ab * (T(4) * (T(2) * (a_minus_b * t22 + t18 * ab_ap) * t17 * ab_ab + t19 * t18 * ab_ap + a_minus_b * t23 * t22) * t17 * ab_ab + T(3) * t20 * t18 * ab_ap + T(3) * a_minus_b * t24 * t22);
    const T t27 = t24 * t24;
    const T t28 = t20 * t20;
    const T t29 = T(8) * t17 * ab_ab * t26 + T(35) * a_minus_b * t27 * t22 + T(35) * t28 * t18 * ab_ap;
    const T t30 = t17 * t29 * ab_ap + T(35) * t28 * t18 - T(35) * t27 * t22;
    const T t31 = T(1) / ab_ab;
    const T t32 = ap_ap * t17 * t29 - T(2) * t30 * t31 * ab_ap - T(9) * t17 * t26;
    F = (T(1) / T(315)) * t17 * in.w[0] * t29 + (T(1) / T(315)) * t30 * t31 * in.w[1] - (T(1) / T(315)) * t31 * t32 * in.w[2] - (T(1) / T(315)) * in.w[3] * t31 * (ap_ap * t30 * t31 + T(2) * t31 * t32 * ab_ap - T(9) * (T(5) * t21 * t18 + t17 * t26 * ab_ap - T(5) * t25 * t22) * t31);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 57 +, 158 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t14 = T(11) * ab_ap * t2 + t4 * t8 - t9 * t13;
    const T t15 = T(11) * cross_cross * t2 - t9 * a_minus_b * t13 - ab_ap * t4 * t8;
    const T t16 = T(110) * ap_ap * t2 - T(11) * t15 * t3 - T(20) * ab_ap * t3 * t14;
    const T t17 = T(9) * ab_ap * t15 * t3 + T(10) * t4 * t7 - T(10) * t9 * t12;
    const T t18 = T(90) * ap_ap * t3 * t14 + T(18) * ab_ap * t16 * t3 - T(11) * t17 * t3;
    G_ap = in.w[0] * t2 + (T(1) / T(11)) * t3 * t14 * in.w[1] - (T(1) / T(990)) * t18 * in.w[3] * t3 - (T(1) / T(110)) * in.w[2] * t16 * t3;
    G_ab = (T(1) / T(11)) * in.w[0] * t3 * t14 - (T(1) / T(110)) * t16 * t3 * in.w[1] - (T(1) / T(990)) * in.w[2] * t18 * t3 - (T(1) / T(7920)) * (T(16) * ab_ap * t18 * t3 - T(11) * (T(16) * ab_ap * t17 * t3 - T(72) * ap_ap * t15 * t3 - T(9) * t3 * (T(10) * t9 * a_minus_b * t12 + T(10) * ab_ap * t4 * t7 - T(9) * cross_cross * t15 * t3)) * t3 - T(72) * ap_ap * t16 * t3) * in.w[3] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / ab_ab;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t26;
    const T t30 = T(1) / cross_cross;
    const T t31 = t27 * t26;
    const T t32 = t22 * t21;
    const T t33 = T(2) * t30 * (T(3) * t25 * a_minus_b * t27 + T(3) * ab_ap * t20 * t22 + T(4) * t30 * ab_ab * (ab_ap * t20 * t21 + t25 * a_minus_b * t26 + T(2) * (ab_ap * t20 + t25 * a_minus_b) * t30 * ab_ab)) * ab_ab + T(5) * t25 * a_minus_b * t31 + T(5) * ab_ap * t20 * t32;
    const T t34 = T(35) * t25 * a_minus_b * t28 + T(8) * t33 * t30 * ab_ab + T(35) * ab_ap * t20 * t23;
    const T t35 = T(63) * t25 * a_minus_b * t29 + T(2) * t30 * t34 * ab_ab + T(63) * ab_ap * t20 * t24;
    const T t36 = T(63) * t20 * t24 + ab_ap * t35 * t30 - T(63) * t25 * t29;
    const T t37 = T(5) * ap_ap * t35 * t30 - T(11) * t30 * t34 - T(10) * ab_ap * t19 * t36;
    const T t38 = ab_ap * t30 * t34 + T(35) * t20 * t23 - T(35) * t25 * t28;
    const T t39 = T(2) * ab_ap * t37 * t19 + T(5) * ap_ap * t19 * t36 - T(11) * t19 * t38;
    G_ap = (T(1) / T(693)) * t19 * t36 * in.w[1] + (T(1) / T(693)) * t35 * t30 * in.w[0] - (T(1) / T(3465)) * in.w[2] * t37 * t19 - (T(1) / T(3465)) * in.w[3] * t39 * t19;
    G_ab = (T(1) / T(693)) * in.w[0] * t19 * t36 - (T(1) / T(3465)) * (T(11) * (ap_ap * t30 * t34 - T(2) * ab_ap * t19 * t38 - T(9) * t33 * t30) * t19 + T(2) * ab_ap * t39 * t19 - ap_ap * t37 * t19) * in.w[3] * t19 - (T(1) / T(3465)) * t37 * t19 * in.w[1] - (T(1) / T(3465)) * in.w[2] * t39 * t19;
  }
  const T g_factor = -T(11) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 64 +, 184 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = t5 * t3;
    const T t12 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t13 = t6 * t10 * a_minus_b + t11 * t2 * ab_ap - T(11) * cross_cross * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(10) * t5 * t2 - T(9) * t13 * t14 * ab_ap - T(10) * t6 * t9;
    const T t16 = T(10) * t6 * t9 * a_minus_b + T(9) * t13 * cross_cross * t14 + T(10) * t5 * t2 * ab_ap;
    const T t17 = T(9) * t16 * t14 - T(16) * t15 * t14 * ab_ap - T(72) * ap_ap * t13 * t14;
    const T t18 = t8 * t7;
    const T t19 = t4 * t3;
    F = (T(1) / T(90)) * t15 * t14 * in.w[1] - (T(1) / T(720)) * in.w[2] * t14 * t17 - (T(1) / T(5040)) * (T(56) * ap_ap * t15 * t14 + T(9) * (T(7) * t16 * t14 * ab_ap + T(80) * t6 * t18 - T(80) * t19 * t2) * t14 + T(14) * t14 * ab_ap * t17) * in.w[3] * t14 - (T(1) / T(10)) * t13 * in.w[0] * t14;
    const T t20 = t11 * t2 + T(11) * t12 * ab_ap - t6 * t10;
    const T t21 = T(11) * t13 * t14 + T(110) * ap_ap * t12 - T(20) * t14 * t20 * ab_ap;
    const T t22 = T(90) * ap_ap * t14 * t20 + T(18) * t14 * t21 * ab_ap - T(11) * t15 * t14;
    G_ap = (T(1) / T(11)) * t14 * in.w[1] * t20 + in.w[0] * t12 - (T(1) / T(990)) * t22 * in.w[3] * t14 - (T(1) / T(110)) * in.w[2] * t14 * t21;
    G_ab = (T(1) / T(11)) * in.w[0] * t14 * t20 - (T(1) / T(990)) * in.w[2] * t22 * t14 - (T(1) / T(110)) * t14 * t21 * in.w[1] - (T(1) / T(7920)) * in.w[3] * (T(16) * t22 * t14 * ab_ap + T(11) * t14 * t17 - T(72) * ap_ap * t14 * t21) * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / cross_cross;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t30 * t29;
    const T t33 = t26 * t25;
    const T t34 = T(5) * t32 * t28 * ab_ap + T(2) * (T(4) * t23 * (t29 * t28 * ab_ap + t24 * t25 * a_minus_b + T(2) * t23 * ab_ab * (t28 * ab_ap + t24 * a_minus_b)) * ab_ab + T(3) * t30 * t28 * ab_ap + T(3) * t24 * t26 * a_minus_b) * t23 * ab_ab + T(5) * t24 * t33 * a_minus_b;
    const T t35 = T(35) * t24 * t27 * a_minus_b + T(35) * t31 * t28 * ab_ap + T(8) * t23 * t34 * ab_ab;
    const T t36 = t23 * t35 * ab_ap + T(35) * t31 * t28 - T(35) * t24 * t27;
    const T t37 = T(1) / ab_ab;
    const T t38 = ap_ap * t23 * t35 - T(2) * t36 * t37 * ab_ap - T(9) * t23 * t34;
    F = (T(1) / T(315)) * t36 * t37 * in.w[1] + (T(1) / T(315)) * t23 * in.w[0] * t35 - (T(1) / T(315)) * in.w[3] * t37 * (ap_ap * t36 * t37 + T(2) * t38 * t37 * ab_ap - T(9) * (t23 * t34 * ab_ap + T(5) * t32 * t28 - T(5) * t24 * t33) * t37) - (T(1) / T(315)) * in.w[2] * t38 * t37;
    const T t39 = t27 * t25;
    const T t40 = t31 * t29;
    const T t41 = T(2) * t23 * ab_ab * t35 + T(63) * t24 * t39 * a_minus_b + T(63) * t40 * t28 * ab_ap;
    const T t42 = T(63) * t40 * t28 + t41 * t23 * ab_ap - T(63) * t24 * t39;
    const T t43 = T(10) * t42 * t37 * ab_ap + T(11) * t23 * t35 - T(5) * ap_ap * t41 * t23;
    const T t44 = T(5) * ap_ap * t42 * t37 - T(11) * t36 * t37 - T(2) * t43 * t37 * ab_ap;
    G_ap = (T(1) / T(693)) * t41 * t23 * in.w[0] + (T(1) / T(3465)) * in.w[2] * t43 * t37 + (T(1) / T(693)) * t42 * t37 * in.w[1] - (T(1) / T(3465)) * t44 * in.w[3] * t37;
    G_ab = (T(1) / T(3465)) * t43 * t37 * in.w[1] + (T(1) / T(693)) * t42 * in.w[0] * t37 - (T(1) / T(3465)) * in.w[3] * t37 * (T(11) * t38 * t37 + T(2) * t44 * t37 * ab_ap + ap_ap * t43 * t37) - (T(1) / T(3465)) * in.w[2] * t44 * t37;
  }
  const T g_factor = -T(11) * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 37 +, 74 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    F = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, ap_bp) * t3;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / ap_ap;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t6 * t5;
    const T t14 = t10 * t9;
    F = (T(1) / T(1280)) * in.w[0] * t4 * (T(128) * a_minus_b * t8 + T(128) * ab_ap * t12 + T(3) * (T(48) * a_minus_b * t7 + T(7) * (T(5) * (T(2) * a_minus_b * t6 + T(3) * (ab_ap * t9 + J2 * ab_ab + a_minus_b * t5) * t4 * ab_ab + T(2) * ab_ap * t10) * t4 * ab_ab + T(8) * a_minus_b * t13 + T(8) * ab_ap * t14) * t4 * ab_ab + T(48) * ab_ap * t11) * t4 * ab_ab);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 44 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    G_ab = (T(1) / T(12)) * t3 * in.w[0] * (T(12) * t2 * ab_ap + t7 - t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = t16 * t16;
    const T t18 = T(1) / bp_bp;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t22 * t18;
    const T t24 = t15 * t15;
    const T t25 = t24 * t14;
    const T t26 = T(1) / cross_cross;
    const T t27 = T(1280) * ab_ap * t17 + T(1280) * a_minus_b * t21 + T(11) * ab_ab * (T(128) * a_minus_b * t23 + T(128) * ab_ap * t25 + T(3) * ab_ab * (T(7) * ab_ab * (T(8) * a_minus_b * t20 + T(8) * ab_ap * t16 + T(5) * ab_ab * (T(2) * a_minus_b * t19 + T(2) * ab_ap * t15 + T(3) * ab_ab * t26 * (ab_ab * J2 + ab_ap * t14 + a_minus_b * t18)) * t26) * t26 + T(48) * ab_ap * t24 + T(48) * a_minus_b * t22) * t26) * t26;
    G_ap = (T(1) / T(15360)) * t27 * in.w[0] * t26;
    const T t28 = T(1) / ab_ab;
    G_ab = -(T(1) / T(15360)) * t28 * (T(1280) * t21 - T(1280) * t17 - t27 * ab_ap * t26) * in.w[0];
  }
  const T g_factor = -T(12) * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 44 +, 103 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / bp_bp;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = T(1) / ap_ap;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = T(1) / ab_ab;
    F = -(T(1) / T(11)) * (t5 * a_minus_b + ab_ap * t9 - T(12) * cross_cross * t10) * in.w[0] * t11;
    G_ap = in.w[0] * t10;
    G_ab = -(T(1) / T(12)) * (t5 - T(12) * ab_ap * t10 - t9) * in.w[0] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / ap_ap;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t14;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t15 * t14;
    const T t23 = t20 * t20;
    const T t24 = t23 * t19;
    const T t25 = T(128) * ab_ap * t17 + T(3) * (T(7) * t18 * ab_ab * (T(8) * t21 * a_minus_b + T(5) * (T(2) * t20 * a_minus_b + T(2) * ab_ap * t15 + T(3) * (ab_ap * t14 + t19 * a_minus_b + J2 * ab_ab) * t18 * ab_ab) * t18 * ab_ab + T(8) * ab_ap * t22) + T(48) * ab_ap * t16 + T(48) * t23 * a_minus_b) * t18 * ab_ab + T(128) * t24 * a_minus_b;
    F = (T(1) / T(1280)) * t25 * in.w[0] * t18;
    const T t26 = t21 * t21;
    const T t27 = t22 * t22;
    const T t28 = T(11) * t25 * t18 * ab_ab + T(1280) * t26 * a_minus_b + T(1280) * ab_ap * t27;
    G_ap = (T(1) / T(15360)) * t28 * in.w[0] * t18;
    const T t29 = T(1) / ab_ab;
    G_ab = -(T(1) / T(15360)) * (T(1280) * t26 - T(1280) * t27 - t28 * ab_ap * t18) * in.w[0] * t29;
  }
  const T g_factor = -T(12) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 40 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    F = (T(1) / T(10)) * in.w[1] * t2 * (t6 + T(10) * t7 * ab_ap - t11) + t7 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, ap_bp) * t13;
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / ap_ap;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t20 * t19;
    const T t23 = t16 * t15;
    const T t24 = t21 * t19;
    const T t25 = T(128) * t18 * ab_ap + T(3) * (T(48) * t17 * ab_ap + T(48) * a_minus_b * t21 + T(7) * t14 * ab_ab * (T(8) * a_minus_b * t22 + T(5) * (T(3) * t14 * ab_ab * (J2 * ab_ab + t15 * ab_ap + a_minus_b * t19) + T(2) * a_minus_b * t20 + T(2) * t16 * ab_ap) * t14 * ab_ab + T(8) * t23 * ab_ap)) * t14 * ab_ab + T(128) * a_minus_b * t24;
    const T t26 = T(1) / ab_ab;
    F = (T(1) / T(1280)) * t14 * t25 * in.w[0] + (T(1) / T(1280)) * in.w[1] * t26 * (T(128) * t18 + t14 * ab_ap * t25 - T(128) * t24);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 48 +, 112 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t6 - t10 - T(12) * t2 * ab_ap;
    const T t12 = T(1) / ab_ab;
    G_ap = t2 * in.w[0] - (T(1) / T(12)) * t11 * in.w[1] * t12;
    G_ab = (T(1) / T(66)) * (T(6) * (T(12) * t2 * cross_cross - a_minus_b * t6 - ab_ap * t10) * t12 - T(11) * t11 * ab_ap * t12 - T(66) * t2 * ap_ap) * in.w[1] * t12 - (T(1) / T(12)) * t11 * in.w[0] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = t17 * t17;
    const T t19 = T(1) / ap_ap;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t21 * t21;
    const T t23 = T(1) / cross_cross;
    const T t24 = t16 * t16;
    const T t25 = t20 * t20;
    const T t26 = t24 * t15;
    const T t27 = t25 * t19;
    const T t28 = T(3) * t23 * (T(48) * a_minus_b * t24 + T(7) * (T(8) * ab_ap * t21 + T(5) * (T(2) * ab_ap * t20 + T(2) * a_minus_b * t16 + T(3) * (ab_ab * J2 + a_minus_b * t15 + ab_ap * t19) * t23 * ab_ab) * t23 * ab_ab + T(8) * a_minus_b * t17) * t23 * ab_ab + T(48) * ab_ap * t25) * ab_ab + T(128) * a_minus_b * t26 + T(128) * ab_ap * t27;
    const T t29 = T(1280) * a_minus_b * t18 + T(1280) * ab_ap * t22 + T(11) * t28 * t23 * ab_ab;
    const T t30 = T(1280) * t18 - T(1280) * t22 - ab_ap * t29 * t23;
    const T t31 = T(1) / ab_ab;
    G_ap = (T(1) / T(15360)) * t29 * in.w[0] * t23 - (T(1) / T(15360)) * t30 * in.w[1] * t31;
    G_ab = -(T(1) / T(15360)) * t30 * in.w[0] * t31 - (T(1) / T(15360)) * (t29 * ap_ap * t23 + T(2) * t30 * ab_ap * t31 - T(12) * t28 * t23) * in.w[1] * t31;
  }
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 51 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t12 = ab_ap * t6 + t10 * a_minus_b - T(12) * cross_cross * t11;
    const T t13 = t8 * t8;
    const T t14 = t13 * t7;
    const T t15 = t4 * t4;
    const T t16 = t15 * t3;
    F = -(T(1) / T(11)) * t2 * t12 * in.w[0] - (T(1) / T(110)) * in.w[1] * (T(10) * t2 * ab_ap * t12 + T(11) * t14 - T(11) * t16) * t2;
    const T t17 = T(12) * t11 * ab_ap + t6 - t10;
    G_ap = (T(1) / T(12)) * in.w[1] * t2 * t17 + t11 * in.w[0];
    G_ab = (T(1) / T(66)) * in.w[1] * t2 * (T(11) * t2 * ab_ap * t17 - T(66) * t11 * ap_ap - T(6) * t2 * t12) + (T(1) / T(12)) * t2 * in.w[0] * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(cross_cross);
    const T t19 = T(1) / t18;
    const T J2 = t19 * atan2(t18, ap_bp);
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t22 * t22;
    const T t28 = t25 * t25;
    const T t29 = t27 * t21;
    const T t30 = t28 * t24;
    const T t31 = T(3) * t20 * ab_ab * (T(7) * t20 * ab_ab * (T(8) * t23 * a_minus_b + T(8) * ab_ap * t26 + T(5) * t20 * ab_ab * (T(2) * t22 * a_minus_b + T(3) * t20 * ab_ab * (ab_ap * t24 + ab_ab * J2 + t21 * a_minus_b) + T(2) * ab_ap * t25)) + T(48) * t27 * a_minus_b + T(48) * ab_ap * t28) + T(128) * t29 * a_minus_b + T(128) * ab_ap * t30;
    const T t32 = T(1) / ab_ab;
    F = (T(1) / T(1280)) * t20 * t31 * in.w[0] + (T(1) / T(1280)) * in.w[1] * t32 * (T(128) * t30 + t20 * t31 * ab_ap - T(128) * t29);
    const T t33 = t26 * t26;
    const T t34 = t23 * t23;
    const T t35 = T(11) * t20 * ab_ab * t31 + T(1280) * ab_ap * t33 + T(1280) * t34 * a_minus_b;
    const T t36 = T(1280) * t34 - T(1280) * t33 - t20 * t35 * ab_ap;
    G_ap = (T(1) / T(15360)) * t20 * t35 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t32 * t36;
    G_ab = -(T(1) / T(15360)) * in.w[1] * t32 * (t20 * t35 * ap_ap + T(2) * t32 * t36 * ab_ap - T(12) * t20 * t31) - (T(1) / T(15360)) * t32 * t36 * in.w[0];
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 43 +, 92 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * t3 * ab_ap + t7 - t11;
    F = (T(1) / T(10)) * in.w[1] * t2 * t12 + in.w[0] * t3 + (T(1) / T(45)) * (T(9) * t2 * t12 * ab_ap - T(5) * (t7 * ab_ap + a_minus_b * t11 - T(10) * cross_cross * t3) * t2 - T(45) * ap_ap * t3) * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t16;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t20;
    const T t24 = t21 * t20;
    const T t25 = t17 * t16;
    const T t26 = T(48) * t18 * ab_ap + T(7) * t15 * ab_ab * (T(8) * a_minus_b * t24 + T(5) * (T(2) * a_minus_b * t21 + T(3) * (t16 * ab_ap + J2 * ab_ab + a_minus_b * t20) * t15 * ab_ab + T(2) * t17 * ab_ap) * t15 * ab_ab + T(8) * t25 * ab_ap) + T(48) * a_minus_b * t22;
    const T t27 = T(128) * t19 * ab_ap + T(128) * a_minus_b * t23 + T(3) * t26 * t15 * ab_ab;
    const T t28 = t15 * t27 * ab_ap + T(128) * t19 - T(128) * t23;
    const T t29 = T(1) / ab_ab;
    F = (T(1) / T(1280)) * t15 * t27 * in.w[0] + (T(1) / T(3840)) * (T(6) * t28 * t29 * ab_ap + T(10) * t26 * t15 - T(3) * ap_ap * t15 * t27) * in.w[2] * t29 + (T(1) / T(1280)) * in.w[1] * t28 * t29;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 54 +, 129 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = T(12) * t2 * ab_ap + t6 - t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = a_minus_b * t10 + t6 * ab_ap - T(12) * cross_cross * t2;
    const T t14 = T(66) * ap_ap * t2 + T(6) * t12 * t13 - T(11) * t11 * t12 * ab_ap;
    G_ap = t2 * in.w[0] + (T(1) / T(12)) * in.w[1] * t11 * t12 - (T(1) / T(66)) * in.w[2] * t14 * t12;
    const T t15 = t8 * t8;
    const T t16 = t15 * t7;
    const T t17 = t4 * t4;
    const T t18 = t17 * t3;
    G_ab = (T(1) / T(12)) * t11 * t12 * in.w[0] - (T(1) / T(660)) * in.w[2] * t12 * (T(6) * (T(10) * t12 * t13 * ab_ap + T(11) * t16 - T(11) * t18) * t12 + T(20) * t14 * t12 * ab_ap + T(55) * ap_ap * t11 * t12) - (T(1) / T(66)) * in.w[1] * t14 * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, ap_bp);
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t23 * t23;
    const T t25 = T(1) / ap_ap;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = t27 * t27;
    const T t29 = T(1) / cross_cross;
    const T t30 = t22 * t22;
    const T t31 = t30 * t21;
    const T t32 = t26 * t26;
    const T t33 = t32 * t25;
    const T t34 = T(128) * a_minus_b * t31 + T(128) * t33 * ab_ap + T(3) * (T(48) * a_minus_b * t30 + T(7) * t29 * (T(8) * t27 * ab_ap + T(8) * a_minus_b * t23 + T(5) * (T(2) * a_minus_b * t22 + T(3) * t29 * ab_ab * (ab_ab * J2 + t25 * ab_ap + a_minus_b * t21) + T(2) * t26 * ab_ap) * t29 * ab_ab) * ab_ab + T(48) * t32 * ab_ap) * t29 * ab_ab;
    const T t35 = T(1280) * a_minus_b * t24 + T(1280) * t28 * ab_ap + T(11) * t29 * t34 * ab_ab;
    const T t36 = T(1280) * t24 - t35 * t29 * ab_ap - T(1280) * t28;
    const T t37 = T(1) / ab_ab;
    const T t38 = t35 * ap_ap * t29 + T(2) * t36 * t37 * ab_ap - T(12) * t29 * t34;
    G_ap = (T(1) / T(15360)) * t35 * t29 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t36 * t37 - (T(1) / T(15360)) * in.w[2] * t37 * t38;
    G_ab = (T(1) / T(15360)) * in.w[2] * t37 * (ap_ap * t36 * t37 + T(12) * t37 * (t29 * t34 * ab_ap + T(128) * t33 - T(128) * t31) - T(2) * t37 * t38 * ab_ap) - (T(1) / T(15360)) * t36 * t37 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t37 * t38;
  }
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 58 +, 147 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(12) * t3 * cross_cross - ab_ap * t7 - t11 * a_minus_b;
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t9 * t9;
    const T t16 = t15 * t8;
    const T t17 = T(10) * t2 * t12 * ab_ap + T(11) * t14 - T(11) * t16;
    F = (T(1) / T(110)) * t2 * t17 * in.w[1] + (T(1) / T(11)) * t2 * in.w[0] * t12 + (T(1) / T(495)) * t2 * (T(5) * t2 * (T(10) * t2 * t12 * cross_cross - T(11) * ab_ap * t14 - T(11) * t16 * a_minus_b) + T(9) * t2 * ab_ap * t17 - T(45) * t2 * t12 * ap_ap) * in.w[2];
    const T t18 = t7 + T(12) * ab_ap * t3 - t11;
    const T t19 = T(11) * t2 * ab_ap * t18 + T(6) * t2 * t12 - T(66) * t3 * ap_ap;
    G_ap = in.w[0] * t3 + (T(1) / T(12)) * t2 * in.w[1] * t18 + (T(1) / T(66)) * t2 * t19 * in.w[2];
    G_ab = (T(1) / T(66)) * t2 * t19 * in.w[1] + (T(1) / T(12)) * t2 * in.w[0] * t18 - (T(1) / T(660)) * t2 * (T(55) * t2 * t18 * ap_ap - T(6) * t2 * t17 - T(20) * t2 * t19 * ab_ap) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = atan2(t20, ap_bp) * t21;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = T(1) / ap_ap;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = T(1) / cross_cross;
    const T t29 = t26 * t26;
    const T t30 = t23 * t23;
    const T t31 = T(7) * ab_ab * (T(8) * t24 * a_minus_b + T(8) * ab_ap * t27 + T(5) * ab_ab * (T(2) * ab_ap * t26 + T(2) * t23 * a_minus_b + T(3) * ab_ab * (t22 * a_minus_b + ab_ab * J2 + ab_ap * t25) * t28) * t28) * t28 + T(48) * ab_ap * t29 + T(48) * t30 * a_minus_b;
    const T t32 = t29 * t25;
    const T t33 = t30 * t22;
    const T t34 = T(3) * ab_ab * t31 * t28 + T(128) * ab_ap * t32 + T(128) * t33 * a_minus_b;
    const T t35 = T(1) / ab_ab;
    const T t36 = T(128) * t32 + ab_ap * t34 * t28 - T(128) * t33;
    F = (T(1) / T(1280)) * in.w[0] * t34 * t28 + (T(1) / T(1280)) * t35 * in.w[1] * t36 - (T(1) / T(3840)) * t35 * in.w[2] * (T(3) * t34 * ap_ap * t28 - T(6) * t35 * ab_ap * t36 - T(10) * t31 * t28);
    const T t37 = t27 * t27;
    const T t38 = t24 * t24;
    const T t39 = T(1280) * ab_ap * t37 + T(11) * ab_ab * t34 * t28 + T(1280) * t38 * a_minus_b;
    const T t40 = ab_ap * t28 * t39 + T(1280) * t37 - T(1280) * t38;
    const T t41 = T(2) * t35 * ab_ap * t40 + T(12) * t34 * t28 - ap_ap * t28 * t39;
    G_ap = (T(1) / T(15360)) * in.w[0] * t28 * t39 + (T(1) / T(15360)) * t35 * in.w[2] * t41 + (T(1) / T(15360)) * t35 * in.w[1] * t40;
    G_ab = (T(1) / T(15360)) * t35 * in.w[1] * t41 + (T(1) / T(15360)) * t35 * in.w[0] * t40 - (T(1) / T(15360)) * t35 * in.w[2] * (t35 * ap_ap * t40 - T(2) * t35 * ab_ap * t41 - T(12) * t35 * t36);
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 48 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(7) / T(20)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * t2 * ab_ap + t7 - t11;
    const T t13 = T(10) * cross_cross * t2 - ab_ap * t7 - a_minus_b * t11;
    const T t14 = T(5) * t13 * t3 + T(9) * t3 * ab_ap * t12 - T(45) * t2 * ap_ap;
    F = t2 * in.w[0] + (T(1) / T(10)) * t3 * in.w[1] * t12 + (T(1) / T(45)) * t3 * t14 * in.w[2] - (T(1) / T(360)) * in.w[3] * t3 * (T(36) * t3 * t12 * ap_ap - T(5) * t3 * (T(8) * t13 * t3 * ab_ap + T(9) * t6 - T(9) * t10) - T(16) * t3 * ab_ap * t14);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, ap_bp);
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / cross_cross;
    const T t19 = T(1) / ap_ap;
    const T t20 = T(1) / bp_bp;
    const T t21 = t19 * t19;
    const T t22 = t20 * t20;
    const T t23 = t22 * t20;
    const T t24 = t21 * t19;
    const T t25 = t21 * t21;
    const T t26 = t22 * t22;
    const T t27 = T(7) * t18 * ab_ab * (T(5) * t18 * ab_ab * (T(3) * t18 * (ab_ab * J2 + ab_ap * t19 + a_minus_b * t20) * ab_ab + T(2) * ab_ap * t21 + T(2) * a_minus_b * t22) + T(8) * a_minus_b * t23 + T(8) * ab_ap * t24) + T(48) * ab_ap * t25 + T(48) * a_minus_b * t26;
    const T t28 = t25 * t19;
    const T t29 = t26 * t20;
    const T t30 = T(3) * t18 * ab_ab * t27 + T(128) * ab_ap * t28 + T(128) * a_minus_b * t29;
    const T t31 = T(128) * t28 + t18 * ab_ap * t30 - T(128) * t29;
    const T t32 = T(10) * t18 * t27 + T(6) * t17 * t31 * ab_ap - T(3) * t18 * t30 * ap_ap;
    F = (T(1) / T(3840)) * t17 * in.w[2] * t32 + (T(1) / T(1280)) * t17 * t31 * in.w[1] + (T(1) / T(1280)) * t18 * in.w[0] * t30 - (T(1) / T(3840)) * in.w[3] * t17 * (T(3) * t17 * t31 * ap_ap - T(10) * t17 * (t18 * ab_ap * t27 + T(48) * t25 - T(48) * t26) - T(2) * t17 * ab_ap * t32);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 60 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t5 * t4;
    const T t13 = t12 * t12;
    const T t14 = ab_ap * t11 + a_minus_b * t13 - T(12) * t2 * cross_cross;
    const T t15 = t9 * t9;
    const T t16 = t15 * t8;
    const T t17 = T(11) * t7 + T(10) * t3 * t14 * ab_ap - T(11) * t16;
    const T t18 = t13 - t11 - T(12) * t2 * ab_ap;
    const T t19 = T(66) * t2 * ap_ap + T(6) * t3 * t14 + T(11) * t18 * t3 * ab_ap;
    const T t20 = T(6) * t3 * t17 + T(20) * t3 * ab_ap * t19 - T(55) * t18 * t3 * ap_ap;
    G_ap = t2 * in.w[0] - (T(1) / T(660)) * in.w[3] * t3 * t20 - (T(1) / T(12)) * t18 * t3 * in.w[1] - (T(1) / T(66)) * t3 * t19 * in.w[2];
    G_ab = (T(1) / T(990)) * in.w[3] * (T(2) * t3 * (T(45) * t3 * t14 * ap_ap - T(5) * t3 * (T(11) * ab_ap * t16 + T(11) * a_minus_b * t7 + T(10) * cross_cross * t3 * t14) - T(9) * t3 * ab_ap * t17) + T(15) * t3 * t19 * ap_ap - T(3) * t3 * ab_ap * t20) * t3 - (T(1) / T(660)) * t3 * t20 * in.w[2] - (T(1) / T(66)) * t3 * in.w[1] * t19 - (T(1) / T(12)) * t18 * in.w[0] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(cross_cross);
    const T t22 = T(1) / t21;
    const T J2 = t22 * atan2(t21, ap_bp);
    const T t23 = T(1) / ap_ap;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t25 * t25;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = T(1) / cross_cross;
    const T t32 = t24 * t24;
    const T t33 = t28 * t28;
    const T t34 = T(48) * ab_ap * t32 + T(48) * a_minus_b * t33 + T(7) * t31 * ab_ab * (T(5) * t31 * ab_ab * (T(2) * a_minus_b * t28 + T(3) * t31 * ab_ab * (ab_ab * J2 + ab_ap * t23 + a_minus_b * t27) + T(2) * ab_ap * t24) + T(8) * a_minus_b * t29 + T(8) * ab_ap * t25);
    const T t35 = t32 * t23;
    const T t36 = t33 * t27;
    const T t37 = T(3) * t31 * ab_ab * t34 + T(128) * ab_ap * t35 + T(128) * a_minus_b * t36;
    const T t38 = T(1280) * ab_ap * t26 + T(1280) * a_minus_b * t30 + T(11) * t31 * t37 * ab_ab;
    const T t39 = T(1) / ab_ab;
    const T t40 = T(1280) * t30 - t38 * t31 * ab_ap - T(1280) * t26;
    const T t41 = T(12) * t31 * t37 - T(2) * t39 * t40 * ab_ap - t38 * t31 * ap_ap;
    const T t42 = T(128) * t36 - t31 * t37 * ab_ap - T(128) * t35;
    const T t43 = T(2) * t39 * t41 * ab_ap + t39 * t40 * ap_ap - T(12) * t39 * t42;
    G_ap = (T(1) / T(15360)) * t38 * t31 * in.w[0] + (T(1) / T(15360)) * in.w[3] * t39 * t43 + (T(1) / T(15360)) * t39 * t41 * in.w[2] - (T(1) / T(15360)) * t39 * in.w[1] * t40;
    G_ab = (T(1) / T(15360)) * t39 * t43 * in.w[2] + (T(1) / T(15360)) * t39 * in.w[1] * t41 - (T(1) / T(15360)) * in.w[0] * t39 * t40 - (T(1) / T(15360)) * in.w[3] * t39 * (T(4) * t39 * (T(3) * t31 * t37 * ap_ap + T(6) * t39 * t42 * ab_ap - T(10) * t31 * t34) + t39 * t41 * ap_ap - T(2) * t39 * ab_ap * t43);
  }
  const T g_factor = -T(12) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 67 +, 175 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(12) * t3 * cross_cross - t7 * a_minus_b - ab_ap * t11;
    const T t13 = t9 * t9;
    const T t14 = t13 * t8;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = T(11) * t14 + T(10) * t2 * ab_ap * t12 - T(11) * t16;
    const T t18 = T(11) * t16 * a_minus_b + T(11) * ab_ap * t14 - T(10) * cross_cross * t2 * t12;
    const T t19 = T(9) * t2 * t17 * ab_ap - T(45) * t2 * ap_ap * t12 - T(5) * t2 * t18;
    F = (T(1) / T(11)) * in.w[0] * t2 * t12 + (T(1) / T(110)) * t2 * t17 * in.w[1] + (T(1) / T(495)) * t2 * t19 * in.w[2] - (T(1) / T(3960)) * t2 * (T(5) * (T(99) * t15 + T(8) * t2 * ab_ap * t18 - T(99) * t13) * t2 + T(36) * t2 * t17 * ap_ap - T(16) * t2 * t19 * ab_ap) * in.w[3];
    const T t20 = T(12) * t3 * ab_ap + t11 - t7;
    const T t21 = T(6) * t2 * t12 + T(11) * t2 * ab_ap * t20 - T(66) * t3 * ap_ap;
    const T t22 = T(6) * t2 * t17 + T(20) * t21 * t2 * ab_ap - T(55) * t2 * t20 * ap_ap;
    G_ap = in.w[0] * t3 + (T(1) / T(12)) * t2 * in.w[1] * t20 + (T(1) / T(660)) * t2 * t22 * in.w[3] + (T(1) / T(66)) * t21 * t2 * in.w[2];
    G_ab = (T(1) / T(12)) * in.w[0] * t2 * t20 + (T(1) / T(660)) * t2 * in.w[2] * t22 + (T(1) / T(66)) * t21 * t2 * in.w[1] - (T(1) / T(990)) * (T(15) * t21 * t2 * ap_ap - T(2) * t2 * t19 - T(3) * t2 * ab_ap * t22) * t2 * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(cross_cross);
    const T t24 = T(1) / t23;
    const T J2 = t24 * atan2(t23, ap_bp);
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / bp_bp;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = T(1) / ap_ap;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t27 * t26;
    const T t33 = t30 * t30;
    const T t34 = T(48) * t28 * a_minus_b + T(7) * t25 * ab_ab * (T(8) * ab_ap * t31 + T(5) * t25 * (T(3) * t25 * ab_ab * (t26 * a_minus_b + ab_ab * J2 + ab_ap * t29) + T(2) * ab_ap * t30 + T(2) * t27 * a_minus_b) * ab_ab + T(8) * t32 * a_minus_b) + T(48) * ab_ap * t33;
    const T t35 = T(1) / ab_ab;
    const T t36 = t28 * t26;
    const T t37 = t33 * t29;
    const T t38 = T(128) * t36 * a_minus_b + T(3) * t25 * ab_ab * t34 + T(128) * ab_ap * t37;
    const T t39 = t25 * ab_ap * t38 + T(128) * t37 - T(128) * t36;
    const T t40 = T(10) * t25 * t34 + T(6) * t35 * t39 * ab_ap - T(3) * t25 * t38 * ap_ap;
    F = (T(1) / T(3840)) * t40 * t35 * in.w[2] + (T(1) / T(1280)) * t35 * in.w[1] * t39 + (T(1) / T(1280)) * in.w[0] * t25 * t38 - (T(1) / T(3840)) * t35 * (T(3) * t35 * t39 * ap_ap - T(2) * t40 * t35 * ab_ap - T(10) * t35 * (t25 * ab_ap * t34 + T(48) * t33 - T(48) * t28)) * in.w[3];
    const T t41 = t32 * t32;
    const T t42 = t31 * t31;
    const T t43 = T(1280) * t41 * a_minus_b + T(11) * t25 * ab_ab * t38 + T(1280) * ab_ap * t42;
    const T t44 = t25 * ab_ap * t43 + T(1280) * t42 - T(1280) * t41;
    const T t45 = T(12) * t25 * t38 + T(2) * t35 * ab_ap * t44 - t25 * t43 * ap_ap;
    const T t46 = t35 * ap_ap * t44 - T(12) * t35 * t39 - T(2) * t35 * t45 * ab_ap;
    G_ap = (T(1) / T(15360)) * in.w[0] * t25 * t43 + (T(1) / T(15360)) * t35 * t45 * in.w[2] + (T(1) / T(15360)) * t35 * in.w[1] * t44 - (T(1) / T(15360)) * t35 * t46 * in.w[3];
    G_ab = (T(1) / T(15360)) * in.w[0] * t35 * t44 + (T(1) / T(15360)) * t35 * in.w[1] * t45 - (T(1) / T(15360)) * t35 * (T(2) * t35 * ab_ap * t46 + t35 * t45 * ap_ap - T(4) * t40 * t35) * in.w[3] - (T(1) / T(15360)) * t35 * in.w[2] * t46;
  }
  const T g_factor = -T(12) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 36 +, 86 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / cross_cross;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = t5 * t4;
    const T t13 = t6 * t4;
    const T t14 = t10 * t8;
    F = (T(1) / T(693)) * in.w[0] * t2 * (T(2) * t2 * ab_ab * (T(35) * t6 * t3 * ab_ap + T(35) * a_minus_b * t10 * t7 + T(8) * t2 * ab_ab * (T(5) * a_minus_b * t11 * t7 + T(5) * t12 * t3 * ab_ap + T(2) * t2 * ab_ab * (T(3) * a_minus_b * t9 * t7 + T(3) * t5 * t3 * ab_ap + T(4) * t2 * ab_ab * (a_minus_b * t8 * t7 + T(2) * (a_minus_b * t7 + t3 * ab_ap) * t2 * ab_ab + t4 * t3 * ab_ap)))) + T(63) * t13 * t3 * ab_ap + T(63) * a_minus_b * t14 * t7);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 43 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / ab_ab;
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
    G_ab = (T(1) / T(13)) * in.w[0] * t3 * (t4 * t8 + T(13) * t2 * ab_ap - t9 * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t17 * t17;
    const T t24 = t21 * t21;
    const T t25 = t23 * t16;
    const T t26 = t24 * t20;
    const T t27 = t22 * t22;
    const T t28 = t18 * t18;
    const T t29 = T(4) * t14 * ab_ab * (T(2) * (T(8) * (T(5) * t15 * t18 * ab_ap + T(2) * (T(3) * t15 * t17 * ab_ap + T(3) * t19 * a_minus_b * t21 + T(4) * t14 * ab_ab * (t19 * a_minus_b * t20 + T(2) * (t15 * ab_ap + t19 * a_minus_b) * t14 * ab_ab + t15 * t16 * ab_ap)) * t14 * ab_ab + T(5) * t19 * a_minus_b * t22) * t14 * ab_ab + T(35) * t15 * t23 * ab_ap + T(35) * t19 * a_minus_b * t24) * t14 * ab_ab + T(63) * t15 * t25 * ab_ap + T(63) * t19 * a_minus_b * t26) + T(231) * t19 * a_minus_b * t27 + T(231) * t15 * t28 * ab_ap;
    G_ap = (T(1) / T(3003)) * in.w[0] * t14 * t29;
    const T t30 = T(1) / ab_ab;
    G_ab = (T(1) / T(3003)) * (t14 * t29 * ab_ap + T(231) * t15 * t28 - T(231) * t19 * t27) * in.w[0] * t30;
  }
  const T g_factor = -T(13) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 43 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    F = (T(1) / T(12)) * in.w[0] * t2 * (T(13) * cross_cross * t3 - a_minus_b * t4 * t8 - t13 * t9 * ab_ap);
    G_ap = in.w[0] * t3;
    G_ab = (T(1) / T(13)) * (T(13) * t3 * ab_ap + t13 * t9 - t4 * t8) * in.w[0] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t21 * t21;
    const T t24 = t17 * t17;
    const T t25 = t24 * t16;
    const T t26 = t23 * t20;
    const T t27 = T(2) * t14 * (T(8) * (T(5) * a_minus_b * t15 * t18 + T(2) * (T(3) * a_minus_b * t15 * t17 + T(3) * t21 * t19 * ab_ap + T(4) * (T(2) * (t19 * ab_ap + a_minus_b * t15) * t14 * ab_ab + t20 * t19 * ab_ap + a_minus_b * t15 * t16) * t14 * ab_ab) * t14 * ab_ab + T(5) * t22 * t19 * ab_ap) * t14 * ab_ab + T(35) * t23 * t19 * ab_ap + T(35) * a_minus_b * t15 * t24) * ab_ab + T(63) * a_minus_b * t15 * t25 + T(63) * t26 * t19 * ab_ap;
    F = (T(1) / T(693)) * t27 * in.w[0] * t14;
    const T t28 = t18 * t18;
    const T t29 = t22 * t22;
    const T t30 = T(231) * a_minus_b * t15 * t28 + T(4) * t27 * t14 * ab_ab + T(231) * t29 * t19 * ab_ap;
    G_ap = (T(1) / T(3003)) * in.w[0] * t14 * t30;
    const T t31 = T(1) / ab_ab;
    G_ab = (T(1) / T(3003)) * (t14 * ab_ap * t30 + T(231) * t29 * t19 - T(231) * t15 * t28) * in.w[0] * t31;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 39 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    F = in.w[0] * t2 - (T(1) / T(11)) * t3 * (t8 * t4 - t9 * t13 - T(11) * ab_ap * t2) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / cross_cross;
    const T t24 = t16 * t15;
    const T t25 = t21 * t21;
    const T t26 = t25 * t20;
    const T t27 = T(63) * t14 * ab_ap * t18 + T(2) * ab_ab * (T(35) * t14 * ab_ap * t17 + T(8) * ab_ab * (T(5) * t22 * t19 * a_minus_b + T(2) * ab_ab * (T(3) * t14 * ab_ap * t16 + T(4) * ab_ab * (t20 * t19 * a_minus_b + T(2) * ab_ab * (t19 * a_minus_b + t14 * ab_ap) * t23 + t14 * ab_ap * t15) * t23 + T(3) * t21 * t19 * a_minus_b) * t23 + T(5) * t14 * ab_ap * t24) * t23 + T(35) * t25 * t19 * a_minus_b) * t23 + T(63) * t26 * t19 * a_minus_b;
    const T t28 = T(1) / ab_ab;
    F = (T(1) / T(693)) * t27 * in.w[0] * t23 - (T(1) / T(693)) * (T(63) * t26 * t19 - T(63) * t14 * t18 - t27 * ab_ap * t23) * t28 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 47 +, 129 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t7 * t3 + T(13) * t8 * ab_ap - t13 * t9;
    G_ap = (T(1) / T(13)) * in.w[1] * t2 * t14 + in.w[0] * t8;
    G_ab = (T(1) / T(13)) * in.w[0] * t2 * t14 - (T(1) / T(156)) * in.w[1] * (T(156) * ap_ap * t8 - T(24) * t2 * t14 * ab_ap - T(13) * (T(13) * cross_cross * t8 - t7 * ab_ap * t3 - a_minus_b * t13 * t9) * t2) * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t16;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t23 * t22;
    const T t26 = t17 * t16;
    const T t27 = t24 * t22;
    const T t28 = T(63) * t19 * ab_ap * t15 + T(2) * t20 * ab_ab * (T(35) * t18 * ab_ap * t15 + T(35) * a_minus_b * t24 * t21 + T(8) * t20 * (T(2) * t20 * ab_ab * (T(3) * t17 * ab_ap * t15 + T(4) * t20 * ab_ab * (T(2) * t20 * ab_ab * (a_minus_b * t21 + ab_ap * t15) + t16 * ab_ap * t15 + a_minus_b * t22 * t21) + T(3) * a_minus_b * t23 * t21) + T(5) * a_minus_b * t25 * t21 + T(5) * t26 * ab_ap * t15) * ab_ab) + T(63) * a_minus_b * t27 * t21;
    const T t29 = t26 * t26;
    const T t30 = t25 * t25;
    const T t31 = T(4) * t28 * t20 * ab_ab + T(231) * t29 * ab_ap * t15 + T(231) * a_minus_b * t30 * t21;
    const T t32 = t31 * t20 * ab_ap + T(231) * t29 * t15 - T(231) * t30 * t21;
    const T t33 = T(1) / ab_ab;
    G_ap = (T(1) / T(3003)) * in.w[0] * t31 * t20 + (T(1) / T(3003)) * t32 * in.w[1] * t33;
    G_ab = (T(1) / T(3003)) * t32 * in.w[0] * t33 - (T(1) / T(9009)) * in.w[1] * t33 * (T(3) * ap_ap * t31 * t20 - T(13) * t28 * t20 - T(6) * t32 * t33 * ab_ap);
  }
  const T g_factor = -T(13) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 50 +, 142 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t13 = T(13) * t2 * cross_cross - t3 * ab_ap * t7 - t8 * t12 * a_minus_b;
    const T t14 = T(1) / ab_ab;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = t10 * t10;
    const T t18 = t17 * t9;
    F = (T(1) / T(12)) * t13 * t14 * in.w[0] + (T(1) / T(132)) * in.w[1] * t14 * (T(12) * t3 * t16 + T(11) * t13 * t14 * ab_ap - T(12) * t8 * t18);
    const T t19 = T(13) * t2 * ab_ap + t3 * t7 - t8 * t12;
    G_ap = (T(1) / T(13)) * in.w[1] * t19 * t14 + t2 * in.w[0];
    G_ab = (T(1) / T(13)) * t19 * t14 * in.w[0] + (T(1) / T(156)) * (T(24) * t19 * t14 * ab_ap + T(13) * t13 * t14 - T(156) * t2 * ap_ap) * in.w[1] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t22 * t21;
    const T t31 = t28 * t28;
    const T t32 = t31 * t27;
    const T t33 = T(2) * t25 * ab_ab * (T(8) * t25 * ab_ab * (T(5) * t26 * t29 * a_minus_b + T(2) * t25 * ab_ab * (T(3) * t26 * t28 * a_minus_b + T(4) * (T(2) * t25 * ab_ab * (t26 * a_minus_b + t20 * ab_ap) + t20 * ab_ap * t21 + t26 * t27 * a_minus_b) * t25 * ab_ab + T(3) * t20 * ab_ap * t22) + T(5) * t20 * ab_ap * t30) + T(35) * t20 * ab_ap * t23 + T(35) * t26 * t31 * a_minus_b) + T(63) * t26 * t32 * a_minus_b + T(63) * t20 * ab_ap * t24;
    const T t34 = T(1) / ab_ab;
    F = (T(1) / T(693)) * in.w[1] * (T(63) * t20 * t24 + t25 * t33 * ab_ap - T(63) * t26 * t32) * t34 + (T(1) / T(693)) * t25 * t33 * in.w[0];
    const T t35 = t30 * t30;
    const T t36 = t29 * t29;
    const T t37 = T(231) * t20 * ab_ap * t35 + T(4) * t25 * ab_ab * t33 + T(231) * t26 * t36 * a_minus_b;
    const T t38 = T(231) * t26 * t36 - T(231) * t20 * t35 - t25 * ab_ap * t37;
    G_ap = (T(1) / T(3003)) * t25 * t37 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t34 * t38;
    G_ab = -(T(1) / T(3003)) * t34 * t38 * in.w[0] - (T(1) / T(9009)) * in.w[1] * t34 * (T(3) * t25 * t37 * ap_ap + T(6) * t34 * ab_ap * t38 - T(13) * t25 * t33);
  }
  const T g_factor = -T(13) * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 42 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t8 * t4 - t9 * t13 - T(11) * ab_ap * t2;
    F = in.w[0] * t2 - (T(1) / T(11)) * t3 * in.w[1] * t14 - (T(1) / T(110)) * t3 * (T(110) * t2 * ap_ap + T(20) * t3 * ab_ap * t14 + T(11) * t3 * (t9 * ab_ap * t13 + t8 * t4 * a_minus_b - T(11) * cross_cross * t2)) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t22;
    const T t26 = t18 * t17;
    const T t27 = t23 * t22;
    const T t28 = T(35) * t24 * t21 * a_minus_b + T(35) * t16 * ab_ap * t19 + T(8) * t15 * ab_ab * (T(2) * t15 * ab_ab * (T(3) * t23 * t21 * a_minus_b + T(3) * t16 * ab_ap * t18 + T(4) * t15 * ab_ab * (t16 * ab_ap * t17 + t22 * t21 * a_minus_b + T(2) * t15 * ab_ab * (t21 * a_minus_b + t16 * ab_ap))) + T(5) * t16 * ab_ap * t26 + T(5) * t27 * t21 * a_minus_b);
    const T t29 = T(63) * t16 * ab_ap * t20 + T(63) * t25 * t21 * a_minus_b + T(2) * t15 * ab_ab * t28;
    const T t30 = T(1) / ab_ab;
    const T t31 = T(63) * t25 * t21 - T(63) * t16 * t20 - t15 * t29 * ab_ap;
    F = (T(1) / T(693)) * t15 * t29 * in.w[0] - (T(1) / T(3465)) * t30 * (T(10) * t30 * ab_ap * t31 + T(5) * t15 * t29 * ap_ap - T(11) * t15 * t28) * in.w[2] - (T(1) / T(693)) * t30 * t31 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 53 +, 149 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
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
    const T t14 = T(13) * t2 * ab_ap + t4 * t8 - t13 * t9;
    const T t15 = T(13) * t2 * cross_cross - a_minus_b * t13 * t9 - ab_ap * t4 * t8;
    const T t16 = T(156) * t2 * ap_ap - T(24) * t3 * ab_ap * t14 - T(13) * t3 * t15;
    G_ap = t2 * in.w[0] + (T(1) / T(13)) * t3 * in.w[1] * t14 - (T(1) / T(156)) * t3 * t16 * in.w[2];
    const T t17 = t6 * t6;
    const T t18 = t17 * t5;
    const T t19 = t11 * t11;
    const T t20 = t19 * t10;
    G_ab = (T(1) / T(13)) * t3 * in.w[0] * t14 - (T(1) / T(156)) * t3 * in.w[1] * t16 - (T(1) / T(1716)) * (T(132) * t3 * ap_ap * t14 + T(22) * t3 * ab_ap * t16 - T(13) * t3 * (T(11) * t3 * ab_ap * t15 + T(12) * t4 * t18 - T(12) * t20 * t9)) * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t25 * t25;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = T(1) / cross_cross;
    const T t32 = t24 * t24;
    const T t33 = t29 * t29;
    const T t34 = t32 * t23;
    const T t35 = t33 * t28;
    const T t36 = T(2) * ab_ab * (T(8) * (T(5) * a_minus_b * t25 * t22 + T(5) * ab_ap * t27 * t30 + T(2) * ab_ab * (T(3) * a_minus_b * t24 * t22 + T(4) * (ab_ap * t27 * t28 + a_minus_b * t23 * t22 + T(2) * ab_ab * (ab_ap * t27 + a_minus_b * t22) * t31) * ab_ab * t31 + T(3) * ab_ap * t27 * t29) * t31) * ab_ab * t31 + T(35) * a_minus_b * t32 * t22 + T(35) * ab_ap * t27 * t33) * t31 + T(63) * a_minus_b * t34 * t22 + T(63) * ab_ap * t27 * t35;
    const T t37 = t30 * t30;
    const T t38 = T(231) * a_minus_b * t26 * t22 + T(4) * ab_ab * t36 * t31 + T(231) * ab_ap * t27 * t37;
    const T t39 = ab_ap * t38 * t31 + T(231) * t27 * t37 - T(231) * t26 * t22;
    const T t40 = T(6) * t21 * ab_ap * t39 + T(13) * t36 * t31 - T(3) * t38 * ap_ap * t31;
    G_ap = (T(1) / T(3003)) * t21 * in.w[1] * t39 + (T(1) / T(9009)) * t21 * in.w[2] * t40 + (T(1) / T(3003)) * in.w[0] * t38 * t31;
    G_ab = (T(1) / T(9009)) * t21 * (T(2) * t21 * ab_ap * t40 - T(3) * t21 * ap_ap * t39 - T(13) * t21 * (T(63) * t34 * t22 - ab_ap * t36 * t31 - T(63) * t27 * t35)) * in.w[2] + (T(1) / T(3003)) * t21 * in.w[0] * t39 + (T(1) / T(9009)) * t21 * in.w[1] * t40;
  }
  const T g_factor = -T(13) * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 57 +, 167 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t14 = T(13) * t3 * cross_cross - t8 * t4 * ab_ap - a_minus_b * t9 * t13;
    const T t15 = t6 * t6;
    const T t16 = t15 * t5;
    const T t17 = t11 * t11;
    const T t18 = t17 * t10;
    const T t19 = T(12) * t16 * t4 + T(11) * t2 * ab_ap * t14 - T(12) * t9 * t18;
    F = (T(1) / T(12)) * t2 * in.w[0] * t14 + (T(1) / T(132)) * in.w[1] * t2 * t19 - (T(1) / T(1320)) * in.w[2] * (T(110) * ap_ap * t2 * t14 + T(11) * (T(12) * t16 * t4 * ab_ap + T(12) * a_minus_b * t9 * t18 - T(11) * cross_cross * t2 * t14) * t2 - T(20) * t2 * ab_ap * t19) * t2;
    const T t20 = t8 * t4 + T(13) * t3 * ab_ap - t9 * t13;
    const T t21 = T(156) * t3 * ap_ap - T(13) * t2 * t14 - T(24) * t2 * t20 * ab_ap;
    G_ap = (T(1) / T(13)) * in.w[1] * t2 * t20 + t3 * in.w[0] - (T(1) / T(156)) * t21 * in.w[2] * t2;
    G_ab = (T(1) / T(13)) * t2 * in.w[0] * t20 - (T(1) / T(1716)) * in.w[2] * t2 * (T(22) * t21 * t2 * ab_ap + T(132) * ap_ap * t2 * t20 - T(13) * t2 * t19) - (T(1) / T(156)) * in.w[1] * t21 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / cross_cross;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(1) / r1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t25 * t24;
    const T t32 = t29 * t29;
    const T t33 = T(35) * t26 * t23 * ab_ap + T(8) * (T(5) * a_minus_b * t27 * t30 + T(5) * t31 * t23 * ab_ap + T(2) * t22 * ab_ab * (T(4) * (T(2) * t22 * ab_ab * (t23 * ab_ap + a_minus_b * t27) + a_minus_b * t27 * t28 + t24 * t23 * ab_ap) * t22 * ab_ab + T(3) * t25 * t23 * ab_ap + T(3) * a_minus_b * t27 * t29)) * t22 * ab_ab + T(35) * a_minus_b * t27 * t32;
    const T t34 = t26 * t24;
    const T t35 = t32 * t28;
    const T t36 = T(2) * t22 * ab_ab * t33 + T(63) * t34 * t23 * ab_ap + T(63) * a_minus_b * t27 * t35;
    const T t37 = T(63) * t34 * t23 + t22 * ab_ap * t36 - T(63) * t27 * t35;
    const T t38 = T(1) / ab_ab;
    F = (T(1) / T(693)) * t22 * in.w[0] * t36 + (T(1) / T(693)) * in.w[1] * t37 * t38 + (T(1) / T(3465)) * in.w[2] * t38 * (T(10) * t37 * t38 * ab_ap + T(11) * t22 * t33 - T(5) * ap_ap * t22 * t36);
    const T t39 = t31 * t31;
    const T t40 = t30 * t30;
    const T t41 = T(4) * t22 * ab_ab * t36 + T(231) * t39 * t23 * ab_ap + T(231) * a_minus_b * t27 * t40;
    const T t42 = t22 * t41 * ab_ap + T(231) * t39 * t23 - T(231) * t27 * t40;
    const T t43 = T(3) * ap_ap * t22 * t41 - T(6) * t42 * t38 * ab_ap - T(13) * t22 * t36;
    G_ap = (T(1) / T(3003)) * t22 * in.w[0] * t41 + (T(1) / T(3003)) * in.w[1] * t42 * t38 - (T(1) / T(9009)) * t43 * in.w[2] * t38;
    G_ab = (T(1) / T(3003)) * t42 * t38 * in.w[0] - (T(1) / T(9009)) * in.w[2] * (T(2) * t43 * t38 * ab_ap + T(3) * ap_ap * t42 * t38 - T(13) * t37 * t38) * t38 - (T(1) / T(9009)) * in.w[1] * t43 * t38;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 47 +, 123 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = T(11) * t2 * cross_cross - t4 * a_minus_b * t8 - ab_ap * t13 * t9;
    const T t15 = T(11) * ab_ap * t2 + t13 * t9 - t4 * t8;
    const T t16 = T(11) * t3 * t14 + T(20) * ab_ap * t15 * t3 - T(110) * t2 * ap_ap;
    F = t2 * in.w[0] + (T(1) / T(110)) * in.w[2] * t16 * t3 + (T(1) / T(990)) * in.w[3] * (T(18) * ab_ap * t16 * t3 + T(11) * (T(10) * t12 * t9 + T(9) * ab_ap * t3 * t14 - T(10) * t4 * t7) * t3 - T(90) * t15 * ap_ap * t3) * t3 + (T(1) / T(11)) * t15 * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = T(1) / cross_cross;
    const T t24 = t22 * t22;
    const T t25 = t24 * t22;
    const T t26 = t24 * t24;
    const T t27 = t19 * t19;
    const T t28 = T(8) * (T(5) * ab_ap * t20 * t17 + T(2) * (T(3) * ab_ap * t19 * t17 + T(4) * (t21 * a_minus_b * t22 + T(2) * (t21 * a_minus_b + ab_ap * t17) * t23 * ab_ab + ab_ap * t18 * t17) * t23 * ab_ab + T(3) * t21 * a_minus_b * t24) * t23 * ab_ab + T(5) * t21 * a_minus_b * t25) * t23 * ab_ab + T(35) * t21 * a_minus_b * t26 + T(35) * ab_ap * t27 * t17;
    const T t29 = t26 * t22;
    const T t30 = t27 * t18;
    const T t31 = T(2) * t28 * t23 * ab_ab + T(63) * t21 * a_minus_b * t29 + T(63) * ab_ap * t30 * t17;
    const T t32 = ab_ap * t31 * t23 + T(63) * t30 * t17 - T(63) * t21 * t29;
    const T t33 = T(1) / ab_ab;
    const T t34 = T(10) * ab_ap * t32 * t33 + T(11) * t28 * t23 - T(5) * ap_ap * t31 * t23;
    F = (T(1) / T(3465)) * in.w[2] * t34 * t33 + (T(1) / T(3465)) * in.w[3] * (T(2) * ab_ap * t34 * t33 + T(11) * t33 * (T(35) * t27 * t17 + ab_ap * t28 * t23 - T(35) * t21 * t26) - T(5) * ap_ap * t32 * t33) * t33 + (T(1) / T(693)) * t31 * t23 * in.w[0] + (T(1) / T(693)) * t32 * t33 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 59 +, 171 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t13 = T(13) * ab_ap * t2 + t3 * t7 - t12 * t8;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(13) * t2 * cross_cross - ab_ap * t3 * t7 - a_minus_b * t12 * t8;
    const T t16 = T(156) * ap_ap * t2 - T(13) * t15 * t14 - T(24) * ab_ap * t13 * t14;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = t10 * t10;
    const T t20 = t19 * t9;
    const T t21 = T(12) * t3 * t18 + T(11) * t15 * ab_ap * t14 - T(12) * t20 * t8;
    const T t22 = T(22) * ab_ap * t16 * t14 + T(132) * ap_ap * t13 * t14 - T(13) * t21 * t14;
    G_ap = t2 * in.w[0] + (T(1) / T(13)) * in.w[1] * t13 * t14 - (T(1) / T(156)) * in.w[2] * t16 * t14 - (T(1) / T(1716)) * t22 * in.w[3] * t14;
    G_ab = (T(1) / T(13)) * in.w[0] * t13 * t14 - (T(1) / T(1716)) * t22 * in.w[2] * t14 - (T(1) / T(156)) * in.w[1] * t16 * t14 - (T(1) / T(17160)) * (T(13) * (T(110) * t15 * ap_ap * t14 + T(11) * (T(12) * ab_ap * t3 * t18 + T(12) * a_minus_b * t20 * t8 - T(11) * t15 * cross_cross * t14) * t14 - T(20) * ab_ap * t21 * t14) * t14 + T(20) * t22 * ab_ap * t14 - T(110) * ap_ap * t16 * t14) * in.w[3] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t31 * t31;
    const T t33 = t25 * t25;
    const T t34 = t33 * t24;
    const T t35 = t30 * t30;
    const T t36 = t35 * t29;
    const T t37 = T(1) / cross_cross;
    const T t38 = T(35) * ab_ap * t23 * t33 + T(8) * t37 * (T(2) * (T(4) * (a_minus_b * t29 * t28 + ab_ap * t23 * t24 + T(2) * t37 * (ab_ap * t23 + a_minus_b * t28) * ab_ab) * t37 * ab_ab + T(3) * ab_ap * t23 * t25 + T(3) * a_minus_b * t30 * t28) * t37 * ab_ab + T(5) * ab_ap * t23 * t26 + T(5) * a_minus_b * t31 * t28) * ab_ab + T(35) * a_minus_b * t35 * t28;
    const T t39 = T(63) * ab_ap * t23 * t34 + T(63) * a_minus_b * t36 * t28 + T(2) * t37 * t38 * ab_ab;
    const T t40 = T(231) * ab_ap * t23 * t27 + T(231) * a_minus_b * t32 * t28 + T(4) * t39 * t37 * ab_ab;
    const T t41 = T(231) * t23 * t27 + ab_ap * t40 * t37 - T(231) * t32 * t28;
    const T t42 = T(1) / ab_ab;
    const T t43 = T(6) * t41 * ab_ap * t42 + T(13) * t39 * t37 - T(3) * t40 * ap_ap * t37;
    const T t44 = t39 * ab_ap * t37 + T(63) * t23 * t34 - T(63) * t36 * t28;
    const T t45 = T(2) * ab_ap * t43 * t42 + T(13) * t44 * t42 - T(3) * t41 * ap_ap * t42;
    G_ap = (T(1) / T(9009)) * t45 * in.w[3] * t42 + (T(1) / T(3003)) * t40 * t37 * in.w[0] + (T(1) / T(3003)) * in.w[1] * t41 * t42 + (T(1) / T(9009)) * in.w[2] * t43 * t42;
    G_ab = (T(1) / T(9009)) * in.w[1] * t43 * t42 + (T(1) / T(9009)) * t45 * in.w[2] * t42 + (T(1) / T(45045)) * (T(10) * t45 * ab_ap * t42 + T(13) * (T(11) * t37 * t38 + T(10) * ab_ap * t44 * t42 - T(5) * t39 * ap_ap * t37) * t42 - T(5) * ap_ap * t43 * t42) * in.w[3] * t42 + (T(1) / T(3003)) * t41 * in.w[0] * t42;
  }
  const T g_factor = -T(13) * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 66 +, 198 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t13 = T(13) * t2 * cross_cross - ab_ap * t7 * t3 - a_minus_b * t8 * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = t10 * t10;
    const T t18 = t17 * t9;
    const T t19 = T(11) * ab_ap * t13 * t14 + T(12) * t16 * t3 - T(12) * t8 * t18;
    const T t20 = T(11) * t13 * cross_cross * t14 - T(12) * ab_ap * t16 * t3 - T(12) * a_minus_b * t8 * t18;
    const T t21 = T(20) * ab_ap * t19 * t14 + T(11) * t20 * t14 - T(110) * t13 * ap_ap * t14;
    F = (T(1) / T(132)) * t19 * t14 * in.w[1] + (T(1) / T(1320)) * in.w[2] * t21 * t14 + (T(1) / T(12)) * t13 * in.w[0] * t14 - (T(1) / T(3960)) * (T(11) * (T(40) * t8 * t17 - T(3) * ab_ap * t20 * t14 - T(40) * t15 * t3) * t14 + T(30) * ap_ap * t19 * t14 - T(6) * ab_ap * t21 * t14) * in.w[3] * t14;
    const T t22 = t8 * t12 - T(13) * ab_ap * t2 - t7 * t3;
    const T t23 = T(24) * ab_ap * t22 * t14 + T(156) * t2 * ap_ap - T(13) * t13 * t14;
    const T t24 = T(132) * t22 * ap_ap * t14 + T(13) * t19 * t14 - T(22) * ab_ap * t23 * t14;
    G_ap = (T(1) / T(1716)) * in.w[3] * t24 * t14 + t2 * in.w[0] - (T(1) / T(156)) * in.w[2] * t23 * t14 - (T(1) / T(13)) * t22 * t14 * in.w[1];
    G_ab = (T(1) / T(17160)) * in.w[3] * t14 * (T(13) * t21 * t14 + T(110) * ap_ap * t23 * t14 + T(20) * ab_ap * t24 * t14) + (T(1) / T(1716)) * in.w[2] * t24 * t14 - (T(1) / T(13)) * t22 * in.w[0] * t14 - (T(1) / T(156)) * t23 * t14 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = T(1) / cross_cross;
    const T t26 = T(1) / r0;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = T(1) / r1;
    const T t31 = t30 * t30;
    const T t32 = t31 * t31;
    const T t33 = t28 * t27;
    const T t34 = t32 * t31;
    const T t35 = t32 * t32;
    const T t36 = T(35) * ab_ap * t29 * t26 + T(8) * (T(2) * (T(4) * (a_minus_b * t30 * t31 + T(2) * t25 * ab_ab * (a_minus_b * t30 + ab_ap * t26) + ab_ap * t27 * t26) * t25 * ab_ab + T(3) * ab_ap * t28 * t26 + T(3) * a_minus_b * t30 * t32) * t25 * ab_ab + T(5) * ab_ap * t33 * t26 + T(5) * a_minus_b * t30 * t34) * t25 * ab_ab + T(35) * a_minus_b * t30 * t35;
    const T t37 = T(1) / ab_ab;
    const T t38 = t35 * t31;
    const T t39 = t29 * t27;
    const T t40 = T(2) * t25 * ab_ab * t36 + T(63) * ab_ap * t39 * t26 + T(63) * a_minus_b * t30 * t38;
    const T t41 = T(63) * t30 * t38 - ab_ap * t25 * t40 - T(63) * t39 * t26;
    const T t42 = T(11) * t25 * t36 - T(10) * ab_ap * t37 * t41 - T(5) * ap_ap * t25 * t40;
    F = (T(1) / T(3465)) * t42 * in.w[2] * t37 + (T(1) / T(3465)) * in.w[3] * (T(5) * ap_ap * t37 * t41 + T(2) * ab_ap * t42 * t37 - T(11) * (T(35) * t30 * t35 - ab_ap * t25 * t36 - T(35) * t29 * t26) * t37) * t37 + (T(1) / T(693)) * t25 * in.w[0] * t40 - (T(1) / T(693)) * t37 * t41 * in.w[1];
    const T t43 = t33 * t33;
    const T t44 = t34 * t34;
    const T t45 = T(231) * ab_ap * t43 * t26 + T(231) * a_minus_b * t30 * t44 + T(4) * t25 * t40 * ab_ab;
    const T t46 = T(231) * t30 * t44 - ab_ap * t25 * t45 - T(231) * t43 * t26;
    const T t47 = T(6) * ab_ap * t46 * t37 + T(3) * ap_ap * t25 * t45 - T(13) * t25 * t40;
    const T t48 = T(13) * t37 * t41 + T(2) * ab_ap * t47 * t37 - T(3) * ap_ap * t46 * t37;
    G_ap = (T(1) / T(3003)) * t25 * in.w[0] * t45 - (T(1) / T(9009)) * in.w[2] * t47 * t37 - (T(1) / T(3003)) * t46 * t37 * in.w[1] - (T(1) / T(9009)) * t48 * in.w[3] * t37;
    G_ab = (T(1) / T(45045)) * (T(13) * t42 * t37 + T(5) * ap_ap * t47 * t37 - T(10) * ab_ap * t48 * t37) * in.w[3] * t37 - (T(1) / T(9009)) * t47 * t37 * in.w[1] - (T(1) / T(9009)) * in.w[2] * t48 * t37 - (T(1) / T(3003)) * t46 * in.w[0] * t37;
  }
  const T g_factor = -T(13) * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 39 +, 83 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    F = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, ap_bp);
    const T t4 = T(1) / bp_bp;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(1) / cross_cross;
    const T t13 = t9 * t8;
    const T t14 = t5 * t4;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    F = (T(1) / T(15360)) * (T(11) * (T(128) * t7 * a_minus_b + T(128) * ab_ap * t11 + T(3) * (T(48) * t6 * a_minus_b + T(48) * ab_ap * t10 + T(7) * (T(5) * (T(2) * t5 * a_minus_b + T(3) * (ab_ap * t8 + t4 * a_minus_b + J2 * ab_ab) * t12 * ab_ab + T(2) * ab_ap * t9) * t12 * ab_ab + T(8) * ab_ap * t13 + T(8) * t14 * a_minus_b) * t12 * ab_ab) * t12 * ab_ab) * t12 * ab_ab + T(1280) * t15 * a_minus_b + T(1280) * ab_ap * t16) * in.w[0] * t12;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 46 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    G_ab = (T(1) / T(14)) * in.w[0] * t3 * (T(14) * ab_ap * t2 + t8 - t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, ap_bp);
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / bp_bp;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = t20 * t17;
    const T t22 = t18 * t18;
    const T t23 = t22 * t17;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t25 * t25;
    const T t28 = t27 * t24;
    const T t29 = t26 * t26;
    const T t30 = t29 * t24;
    const T t31 = T(15360) * a_minus_b * t21 + T(13) * t16 * ab_ab * (T(11) * t16 * (T(128) * a_minus_b * t23 + T(3) * t16 * ab_ab * (T(48) * a_minus_b * t22 + T(7) * t16 * ab_ab * (T(5) * t16 * (T(2) * a_minus_b * t18 + T(2) * ab_ap * t25 + T(3) * t16 * ab_ab * (ab_ap * t24 + ab_ab * J2 + a_minus_b * t17)) * ab_ab + T(8) * a_minus_b * t19 + T(8) * ab_ap * t26) + T(48) * ab_ap * t27) + T(128) * ab_ap * t28) * ab_ab + T(1280) * a_minus_b * t20 + T(1280) * ab_ap * t29) + T(15360) * ab_ap * t30;
    G_ap = (T(1) / T(215040)) * in.w[0] * t16 * t31;
    const T t32 = T(1) / ab_ab;
    G_ab = (T(1) / T(215040)) * in.w[0] * t32 * (t16 * ab_ap * t31 + T(15360) * t30 - T(15360) * t21);
  }
  const T g_factor = -T(14) * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 46 +, 112 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -(T(1) / T(13)) * t2 * (t7 * a_minus_b + ab_ap * t12 - T(14) * t13 * cross_cross) * in.w[0];
    G_ap = t13 * in.w[0];
    G_ab = (T(1) / T(14)) * t2 * (t12 + T(14) * t13 * ab_ap - t7) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, ap_bp) * t15;
    const T t16 = T(1) / bp_bp;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / ap_ap;
    const T t20 = t19 * t19;
    const T t21 = T(1) / cross_cross;
    const T t22 = t20 * t19;
    const T t23 = t20 * t20;
    const T t24 = t17 * t17;
    const T t25 = t24 * t16;
    const T t26 = t23 * t19;
    const T t27 = t18 * t18;
    const T t28 = t22 * t22;
    const T t29 = T(11) * (T(3) * ab_ab * (T(7) * ab_ab * (T(8) * t18 * a_minus_b + T(5) * (T(2) * t17 * a_minus_b + T(2) * ab_ap * t20 + T(3) * ab_ab * (ab_ap * t19 + ab_ab * J2 + t16 * a_minus_b) * t21) * ab_ab * t21 + T(8) * ab_ap * t22) * t21 + T(48) * ab_ap * t23 + T(48) * t24 * a_minus_b) * t21 + T(128) * t25 * a_minus_b + T(128) * ab_ap * t26) * ab_ab * t21 + T(1280) * t27 * a_minus_b + T(1280) * ab_ap * t28;
    F = (T(1) / T(15360)) * t29 * in.w[0] * t21;
    const T t30 = t27 * t16;
    const T t31 = t28 * t19;
    const T t32 = T(15360) * t30 * a_minus_b + T(13) * ab_ab * t29 * t21 + T(15360) * ab_ap * t31;
    G_ap = (T(1) / T(215040)) * t32 * in.w[0] * t21;
    const T t33 = T(1) / ab_ab;
    G_ab = (T(1) / T(215040)) * t33 * (T(15360) * t31 + t32 * ab_ap * t21 - T(15360) * t30) * in.w[0];
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 42 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    F = in.w[0] * t2 + (T(1) / T(12)) * t3 * in.w[1] * (T(12) * t2 * ab_ap + t7 - t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / ap_ap;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = t16 * t15;
    const T t24 = t20 * t19;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = T(11) * t14 * ab_ab * (T(128) * a_minus_b * t18 + T(128) * ab_ap * t22 + T(3) * t14 * ab_ab * (T(7) * (T(5) * t14 * (T(2) * a_minus_b * t16 + T(2) * ab_ap * t20 + T(3) * t14 * (ab_ap * t19 + a_minus_b * t15 + J2 * ab_ab) * ab_ab) * ab_ab + T(8) * a_minus_b * t23 + T(8) * ab_ap * t24) * t14 * ab_ab + T(48) * ab_ap * t21 + T(48) * a_minus_b * t17)) + T(1280) * ab_ap * t25 + T(1280) * a_minus_b * t26;
    const T t28 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * in.w[0] * t14 * t27 - (T(1) / T(15360)) * t28 * in.w[1] * (T(1280) * t26 - t14 * ab_ap * t27 - T(1280) * t25);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 50 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = T(14) * ab_ap * t2 + t7 - t12;
    const T t14 = T(1) / ab_ab;
    G_ap = (T(1) / T(14)) * t13 * in.w[1] * t14 + in.w[0] * t2;
    G_ab = (T(1) / T(14)) * t13 * in.w[0] * t14 - (T(1) / T(91)) * (T(91) * ap_ap * t2 + T(7) * (ab_ap * t7 + a_minus_b * t12 - T(14) * cross_cross * t2) * t14 - T(13) * t13 * ab_ap * t14) * in.w[1] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, ap_bp) * t16;
    const T t17 = T(1) / ap_ap;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = t20 * t17;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = T(1) / cross_cross;
    const T t28 = t18 * t18;
    const T t29 = t28 * t17;
    const T t30 = t23 * t23;
    const T t31 = t30 * t22;
    const T t32 = T(1280) * ab_ap * t20 + T(1280) * a_minus_b * t25 + T(11) * t27 * ab_ab * (T(128) * ab_ap * t29 + T(3) * (T(48) * ab_ap * t28 + T(48) * a_minus_b * t30 + T(7) * (T(8) * a_minus_b * t24 + T(8) * ab_ap * t19 + T(5) * (T(2) * a_minus_b * t23 + T(2) * ab_ap * t18 + T(3) * (ab_ap * t17 + ab_ab * J2 + a_minus_b * t22) * t27 * ab_ab) * t27 * ab_ab) * t27 * ab_ab) * t27 * ab_ab + T(128) * a_minus_b * t31);
    const T t33 = T(15360) * ab_ap * t21 + T(15360) * a_minus_b * t26 + T(13) * t32 * t27 * ab_ab;
    const T t34 = T(15360) * t21 + t33 * ab_ap * t27 - T(15360) * t26;
    const T t35 = T(1) / ab_ab;
    G_ap = (T(1) / T(215040)) * t33 * in.w[0] * t27 + (T(1) / T(215040)) * in.w[1] * t34 * t35;
    G_ab = (T(1) / T(215040)) * in.w[0] * t34 * t35 + (T(1) / T(215040)) * in.w[1] * (T(14) * t32 * t27 + T(2) * ab_ap * t34 * t35 - t33 * ap_ap * t27) * t35;
  }
  const T g_factor = -T(14) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 53 +, 132 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t5 * t2;
    const T t11 = t9 * t6;
    const T t12 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t13 = ab_ap * t10 + t11 * a_minus_b - T(14) * t12 * cross_cross;
    const T t14 = T(1) / ab_ab;
    F = (T(1) / T(156)) * in.w[1] * (T(13) * t5 - T(13) * t9 - T(12) * ab_ap * t13 * t14) * t14 - (T(1) / T(13)) * t13 * in.w[0] * t14;
    const T t15 = t10 + T(14) * t12 * ab_ap - t11;
    G_ap = (T(1) / T(14)) * in.w[1] * t15 * t14 + t12 * in.w[0];
    G_ab = (T(1) / T(14)) * in.w[0] * t15 * t14 - (T(1) / T(91)) * (T(91) * t12 * ap_ap + T(7) * t13 * t14 - T(13) * ab_ap * t15 * t14) * in.w[1] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(cross_cross);
    const T t17 = T(1) / t16;
    const T J2 = atan2(t16, ap_bp) * t17;
    const T t18 = T(1) / ap_ap;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t22 * t18;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t24;
    const T t28 = T(1) / cross_cross;
    const T t29 = t25 * t24;
    const T t30 = t29 * t29;
    const T t31 = T(1280) * ab_ap * t21 + T(11) * (T(128) * ab_ap * t23 + T(128) * t27 * a_minus_b + T(3) * (T(48) * ab_ap * t22 + T(48) * t26 * a_minus_b + T(7) * (T(8) * ab_ap * t20 + T(5) * (T(2) * ab_ap * t19 + T(2) * t25 * a_minus_b + T(3) * t28 * (J2 * ab_ab + t24 * a_minus_b + ab_ap * t18) * ab_ab) * t28 * ab_ab + T(8) * t29 * a_minus_b) * t28 * ab_ab) * t28 * ab_ab) * t28 * ab_ab + T(1280) * t30 * a_minus_b;
    const T t32 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * t31 * in.w[0] * t28 + (T(1) / T(15360)) * (T(1280) * t21 + ab_ap * t31 * t28 - T(1280) * t30) * in.w[1] * t32;
    const T t33 = t21 * t18;
    const T t34 = t30 * t24;
    const T t35 = T(15360) * ab_ap * t33 + T(13) * t31 * t28 * ab_ab + T(15360) * t34 * a_minus_b;
    const T t36 = T(15360) * t33 + t35 * ab_ap * t28 - T(15360) * t34;
    G_ap = (T(1) / T(215040)) * t36 * in.w[1] * t32 + (T(1) / T(215040)) * t35 * in.w[0] * t28;
    G_ab = (T(1) / T(215040)) * t36 * in.w[0] * t32 + (T(1) / T(215040)) * (T(14) * t31 * t28 + T(2) * ab_ap * t36 * t32 - t35 * ap_ap * t28) * in.w[1] * t32;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 45 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(21) / T(50)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = T(12) * ab_ap * t2 + t6 - t10;
    const T t12 = T(1) / ab_ab;
    F = (T(1) / T(66)) * (T(11) * t11 * ab_ap * t12 + T(6) * (T(12) * cross_cross * t2 - ab_ap * t6 - t10 * a_minus_b) * t12 - T(66) * ap_ap * t2) * in.w[2] * t12 + (T(1) / T(12)) * t11 * in.w[1] * t12 + in.w[0] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, ap_bp) * t14;
    const T t15 = T(1) / cross_cross;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t16;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t20;
    const T t24 = t21 * t20;
    const T t25 = t17 * t16;
    const T t26 = T(128) * ab_ap * t19 + T(128) * t23 * a_minus_b + T(3) * t15 * ab_ab * (T(48) * ab_ap * t18 + T(48) * t22 * a_minus_b + T(7) * (T(5) * (T(2) * t21 * a_minus_b + T(2) * ab_ap * t17 + T(3) * (ab_ap * t16 + J2 * ab_ab + t20 * a_minus_b) * t15 * ab_ab) * t15 * ab_ab + T(8) * t24 * a_minus_b + T(8) * ab_ap * t25) * t15 * ab_ab);
    const T t27 = t25 * t25;
    const T t28 = t24 * t24;
    const T t29 = T(11) * t15 * t26 * ab_ab + T(1280) * ab_ap * t27 + T(1280) * t28 * a_minus_b;
    const T t30 = T(1280) * t28 - T(1280) * t27 - ab_ap * t29 * t15;
    const T t31 = T(1) / ab_ab;
    F = (T(1) / T(15360)) * in.w[0] * t29 * t15 - (T(1) / T(15360)) * (T(2) * ab_ap * t30 * t31 + ap_ap * t29 * t15 - T(12) * t15 * t26) * in.w[2] * t31 - (T(1) / T(15360)) * in.w[1] * t30 * t31;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 56 +, 138 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = t7 + T(14) * ab_ap * t2 - t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = a_minus_b * t12 + ab_ap * t7 - T(14) * t2 * cross_cross;
    const T t16 = T(7) * t14 * t15 + T(91) * ap_ap * t2 - T(13) * ab_ap * t13 * t14;
    G_ap = t2 * in.w[0] + (T(1) / T(14)) * t13 * in.w[1] * t14 - (T(1) / T(91)) * t16 * in.w[2] * t14;
    G_ab = (T(1) / T(14)) * t13 * t14 * in.w[0] - (T(1) / T(1092)) * in.w[2] * (T(24) * ab_ap * t16 * t14 + T(78) * t13 * ap_ap * t14 + T(7) * (T(12) * ab_ap * t14 * t15 + T(13) * t11 - T(13) * t6) * t14) * t14 - (T(1) / T(91)) * in.w[1] * t16 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(cross_cross);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, ap_bp);
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / bp_bp;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t22 * t22;
    const T t24 = t23 * t20;
    const T t25 = t21 * t21;
    const T t26 = t25 * t20;
    const T t27 = T(1) / ap_ap;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t28 * t28;
    const T t31 = t30 * t27;
    const T t32 = t29 * t29;
    const T t33 = T(1280) * a_minus_b * t23 + T(11) * (T(128) * a_minus_b * t26 + T(3) * (T(48) * a_minus_b * t25 + T(7) * (T(8) * a_minus_b * t22 + T(5) * (T(2) * a_minus_b * t21 + T(2) * ab_ap * t28 + T(3) * t19 * (ab_ap * t27 + ab_ab * J2 + a_minus_b * t20) * ab_ab) * t19 * ab_ab + T(8) * ab_ap * t29) * t19 * ab_ab + T(48) * ab_ap * t30) * t19 * ab_ab + T(128) * ab_ap * t31) * t19 * ab_ab + T(1280) * ab_ap * t32;
    const T t34 = t32 * t27;
    const T t35 = T(15360) * a_minus_b * t24 + T(13) * t33 * t19 * ab_ab + T(15360) * ab_ap * t34;
    const T t36 = T(1) / ab_ab;
    const T t37 = ab_ap * t19 * t35 + T(15360) * t34 - T(15360) * t24;
    const T t38 = T(2) * ab_ap * t36 * t37 + T(14) * t33 * t19 - ap_ap * t19 * t35;
    G_ap = (T(1) / T(215040)) * t19 * t35 * in.w[0] + (T(1) / T(215040)) * in.w[2] * t38 * t36 + (T(1) / T(215040)) * in.w[1] * t36 * t37;
    G_ab = (T(1) / T(215040)) * (T(2) * ab_ap * t38 * t36 + T(14) * (ab_ap * t33 * t19 + T(1280) * t32 - T(1280) * t23) * t36 - ap_ap * t36 * t37) * in.w[2] * t36 + (T(1) / T(215040)) * in.w[1] * t38 * t36 + (T(1) / T(215040)) * t36 * t37 * in.w[0];
  }
  const T g_factor = -T(14) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 60 +, 155 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / ap_ap;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = T(14) * t2 * cross_cross - t7 * a_minus_b - ab_ap * t12;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(13) * t11 + T(12) * t13 * t14 * ab_ap - T(13) * t6;
    F = (T(1) / T(13)) * t13 * t14 * in.w[0] + (T(1) / T(156)) * t15 * t14 * in.w[1] - (T(1) / T(858)) * in.w[2] * t14 * (T(66) * t13 * t14 * ap_ap - T(11) * t15 * t14 * ab_ap - T(6) * t14 * (T(12) * cross_cross * t13 * t14 - T(13) * t6 * a_minus_b - T(13) * ab_ap * t11));
    const T t16 = T(14) * t2 * ab_ap + t12 - t7;
    const T t17 = T(7) * t13 * t14 + T(13) * t14 * t16 * ab_ap - T(91) * t2 * ap_ap;
    G_ap = (T(1) / T(14)) * t14 * t16 * in.w[1] + t2 * in.w[0] + (T(1) / T(91)) * in.w[2] * t14 * t17;
    G_ab = (T(1) / T(1092)) * in.w[2] * t14 * (T(7) * t15 * t14 + T(24) * t14 * t17 * ab_ap - T(78) * t14 * t16 * ap_ap) + (T(1) / T(91)) * t14 * t17 * in.w[1] + (T(1) / T(14)) * t14 * t16 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(cross_cross);
    const T t19 = T(1) / t18;
    const T J2 = t19 * atan2(t18, ap_bp);
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / bp_bp;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / ap_ap;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t25 * t25;
    const T t28 = t22 * t22;
    const T t29 = t27 * t24;
    const T t30 = t28 * t21;
    const T t31 = T(3) * t20 * (T(7) * t20 * ab_ab * (T(8) * t23 * a_minus_b + T(5) * t20 * ab_ab * (T(2) * t22 * a_minus_b + T(3) * t20 * ab_ab * (ab_ap * t24 + t21 * a_minus_b + ab_ab * J2) + T(2) * ab_ap * t25) + T(8) * ab_ap * t26) + T(48) * ab_ap * t27 + T(48) * t28 * a_minus_b) * ab_ab + T(128) * ab_ap * t29 + T(128) * t30 * a_minus_b;
    const T t32 = t23 * t23;
    const T t33 = t26 * t26;
    const T t34 = T(11) * t20 * ab_ab * t31 + T(1280) * t32 * a_minus_b + T(1280) * ab_ap * t33;
    const T t35 = T(1) / ab_ab;
    const T t36 = T(1280) * t33 + t20 * t34 * ab_ap - T(1280) * t32;
    F = (T(1) / T(15360)) * t20 * t34 * in.w[0] + (T(1) / T(15360)) * t35 * t36 * in.w[1] - (T(1) / T(15360)) * in.w[2] * t35 * (t20 * t34 * ap_ap - T(12) * t20 * t31 - T(2) * t35 * t36 * ab_ap);
    const T t37 = t32 * t21;
    const T t38 = t33 * t24;
    const T t39 = T(15360) * t37 * a_minus_b + T(13) * t20 * ab_ab * t34 + T(15360) * ab_ap * t38;
    const T t40 = t20 * t39 * ab_ap + T(15360) * t38 - T(15360) * t37;
    const T t41 = T(2) * t35 * t40 * ab_ap + T(14) * t20 * t34 - t20 * t39 * ap_ap;
    G_ap = (T(1) / T(215040)) * t35 * t40 * in.w[1] + (T(1) / T(215040)) * t20 * t39 * in.w[0] + (T(1) / T(215040)) * in.w[2] * t41 * t35;
    G_ab = (T(1) / T(215040)) * t41 * t35 * in.w[1] + (T(1) / T(215040)) * in.w[2] * (T(2) * t41 * t35 * ab_ap + T(14) * t35 * t36 - t35 * t40 * ap_ap) * t35 + (T(1) / T(215040)) * t35 * in.w[0] * t40;
  }
  const T g_factor = -T(14) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 50 +, 114 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(21) / T(50)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t2;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = t7 * t6;
    const T t11 = t10 * t10;
    const T t12 = t3 * t2;
    const T t13 = t12 * t12;
    const T t14 = J_downward<T>(T(14), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = a_minus_b * t11 + t13 * ab_ap - T(12) * cross_cross * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = t11 - t13 - T(12) * ab_ap * t14;
    const T t18 = T(6) * t15 * t16 + T(11) * t16 * t17 * ab_ap + T(66) * ap_ap * t14;
    F = (T(1) / T(660)) * in.w[3] * (T(6) * (T(11) * t5 - T(11) * t9 - T(10) * t15 * t16 * ab_ap) * t16 + T(55) * ap_ap * t16 * t17 - T(20) * t18 * t16 * ab_ap) * t16 + in.w[0] * t14 - (T(1) / T(12)) * t16 * t17 * in.w[1] - (T(1) / T(66)) * t18 * t16 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, ap_bp);
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / cross_cross;
    const T t23 = T(1) / ap_ap;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t23;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t27;
    const T t31 = t24 * t23;
    const T t32 = t28 * t27;
    const T t33 = T(128) * t26 * ab_ap + T(128) * a_minus_b * t30 + T(3) * (T(48) * a_minus_b * t29 + T(7) * t22 * (T(5) * (T(2) * t24 * ab_ap + T(3) * t22 * ab_ab * (a_minus_b * t27 + J2 * ab_ab + t23 * ab_ap) + T(2) * a_minus_b * t28) * t22 * ab_ab + T(8) * t31 * ab_ap + T(8) * a_minus_b * t32) * ab_ab + T(48) * t25 * ab_ap) * t22 * ab_ab;
    const T t34 = t32 * t32;
    const T t35 = t31 * t31;
    const T t36 = T(11) * t22 * ab_ab * t33 + T(1280) * a_minus_b * t34 + T(1280) * t35 * ab_ap;
    const T t37 = t36 * t22 * ab_ap + T(1280) * t35 - T(1280) * t34;
    const T t38 = ap_ap * t36 * t22 - T(2) * t21 * t37 * ab_ap - T(12) * t22 * t33;
    F = (T(1) / T(15360)) * t21 * in.w[1] * t37 + (T(1) / T(15360)) * t36 * t22 * in.w[0] - (T(1) / T(15360)) * t21 * t38 * in.w[2] - (T(1) / T(15360)) * (T(2) * t21 * t38 * ab_ap + ap_ap * t21 * t37 - T(12) * (T(128) * t26 + t22 * t33 * ab_ap - T(128) * t30) * t21) * in.w[3] * t21;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 62 +, 158 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = t7 + T(14) * t8 * ab_ap - t13;
    const T t15 = a_minus_b * t13 + t7 * ab_ap - T(14) * t8 * cross_cross;
    const T t16 = T(13) * t6 - T(12) * t2 * t15 * ab_ap - T(13) * t12;
    const T t17 = T(13) * t2 * t14 * ab_ap - T(91) * ap_ap * t8 - T(7) * t2 * t15;
    const T t18 = T(7) * t16 * t2 + T(24) * t2 * ab_ap * t17 - T(78) * ap_ap * t2 * t14;
    G_ap = (T(1) / T(14)) * t2 * in.w[1] * t14 + (T(1) / T(1092)) * t18 * in.w[3] * t2 + (T(1) / T(91)) * in.w[2] * t2 * t17 + t8 * in.w[0];
    G_ab = (T(1) / T(91)) * t2 * in.w[1] * t17 + (T(1) / T(14)) * in.w[0] * t2 * t14 + (T(1) / T(6006)) * in.w[3] * t2 * (T(7) * t2 * (T(66) * ap_ap * t2 * t15 + T(11) * t16 * t2 * ab_ap - T(6) * t2 * (T(13) * a_minus_b * t12 + T(12) * cross_cross * t2 * t15 + T(13) * t6 * ab_ap)) + T(11) * t18 * t2 * ab_ap - T(66) * ap_ap * t2 * t17) + (T(1) / T(1092)) * t18 * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(cross_cross);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, ap_bp);
    const T t21 = T(1) / cross_cross;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = T(1) / ap_ap;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = t23 * t23;
    const T t32 = t31 * t22;
    const T t33 = t28 * t28;
    const T t34 = t33 * t27;
    const T t35 = T(128) * a_minus_b * t32 + T(3) * t21 * ab_ab * (T(48) * a_minus_b * t31 + T(48) * t33 * ab_ap + T(7) * (T(8) * t29 * ab_ap + T(8) * a_minus_b * t24 + T(5) * t21 * ab_ab * (T(3) * (ab_ab * J2 + a_minus_b * t22 + t27 * ab_ap) * t21 * ab_ab + T(2) * t28 * ab_ap + T(2) * a_minus_b * t23)) * t21 * ab_ab) + T(128) * t34 * ab_ap;
    const T t36 = T(1280) * a_minus_b * t25 + T(1280) * t30 * ab_ap + T(11) * t21 * ab_ab * t35;
    const T t37 = t30 * t27;
    const T t38 = T(15360) * a_minus_b * t26 + T(13) * t36 * t21 * ab_ab + T(15360) * t37 * ab_ap;
    const T t39 = t21 * t38 * ab_ap + T(15360) * t37 - T(15360) * t26;
    const T t40 = T(1) / ab_ab;
    const T t41 = T(2) * t39 * t40 * ab_ap + T(14) * t36 * t21 - ap_ap * t21 * t38;
    const T t42 = T(1280) * t30 + t36 * t21 * ab_ap - T(1280) * t25;
    const T t43 = t39 * ap_ap * t40 - T(14) * t42 * t40 - T(2) * t40 * t41 * ab_ap;
    G_ap = (T(1) / T(215040)) * t39 * t40 * in.w[1] + (T(1) / T(215040)) * in.w[2] * t40 * t41 + (T(1) / T(215040)) * t21 * in.w[0] * t38 - (T(1) / T(215040)) * in.w[3] * t43 * t40;
    G_ab = (T(1) / T(215040)) * t40 * in.w[1] * t41 + (T(1) / T(215040)) * t39 * in.w[0] * t40 + (T(1) / T(215040)) * in.w[3] * (T(14) * t40 * (T(12) * t21 * t35 + T(2) * t42 * t40 * ab_ap - ap_ap * t36 * t21) - T(2) * t43 * t40 * ab_ap - ap_ap * t40 * t41) * t40 - (T(1) / T(215040)) * in.w[2] * t43 * t40;
  }
  const T g_factor = -T(14) * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 69 +, 182 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = T(1) / ab_ab;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t10 * t7;
    const T t12 = t5 * t2;
    const T t13 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t14 = t11 * a_minus_b + t12 * ab_ap - T(14) * t13 * cross_cross;
    const T t15 = T(13) * t5 - T(12) * t6 * t14 * ab_ap - T(13) * t10;
    const T t16 = T(13) * t5 * ab_ap + T(13) * t10 * a_minus_b + T(12) * cross_cross * t6 * t14;
    const T t17 = T(6) * t16 * t6 - T(11) * t15 * t6 * ab_ap - T(66) * ap_ap * t6 * t14;
    const T t18 = t3 * t3;
    const T t19 = t18 * t2;
    const T t20 = t8 * t8;
    const T t21 = t20 * t7;
    F = (T(1) / T(156)) * t15 * t6 * in.w[1] - (T(1) / T(858)) * t6 * in.w[2] * t17 - (T(1) / T(13)) * in.w[0] * t6 * t14 - (T(1) / T(8580)) * (T(20) * t6 * ab_ap * t17 + T(55) * ap_ap * t15 * t6 - T(6) * (T(143) * t19 - T(143) * t21 - T(10) * t16 * t6 * ab_ap) * t6) * in.w[3] * t6;
    const T t22 = T(14) * t13 * ab_ap + t12 - t11;
    const T t23 = T(91) * ap_ap * t13 + T(7) * t6 * t14 - T(13) * t22 * t6 * ab_ap;
    const T t24 = T(78) * ap_ap * t22 * t6 + T(24) * t6 * ab_ap * t23 - T(7) * t15 * t6;
    G_ap = (T(1) / T(14)) * t22 * t6 * in.w[1] + t13 * in.w[0] - (T(1) / T(91)) * t6 * in.w[2] * t23 - (T(1) / T(1092)) * t24 * in.w[3] * t6;
    G_ab = (T(1) / T(6006)) * (T(66) * ap_ap * t6 * t23 - T(11) * t24 * t6 * ab_ap - T(7) * t6 * t17) * in.w[3] * t6 + (T(1) / T(14)) * t22 * in.w[0] * t6 - (T(1) / T(1092)) * t24 * t6 * in.w[2] - (T(1) / T(91)) * t6 * in.w[1] * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(cross_cross);
    const T t26 = T(1) / t25;
    const T J2 = t26 * atan2(t25, ap_bp);
    const T t27 = T(1) / ap_ap;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = T(1) / cross_cross;
    const T t32 = T(1) / bp_bp;
    const T t33 = t32 * t32;
    const T t34 = t33 * t32;
    const T t35 = t34 * t34;
    const T t36 = t33 * t33;
    const T t37 = t36 * t32;
    const T t38 = t28 * t28;
    const T t39 = t38 * t27;
    const T t40 = T(128) * t37 * a_minus_b + T(128) * t39 * ab_ap + T(3) * t31 * ab_ab * (T(48) * t38 * ab_ap + T(48) * t36 * a_minus_b + T(7) * (T(5) * t31 * ab_ab * (T(3) * t31 * ab_ab * (t27 * ab_ap + t32 * a_minus_b + ab_ab * J2) + T(2) * t33 * a_minus_b + T(2) * t28 * ab_ap) + T(8) * t34 * a_minus_b + T(8) * t29 * ab_ap) * t31 * ab_ab);
    const T t41 = T(1280) * t30 * ab_ap + T(1280) * t35 * a_minus_b + T(11) * t40 * t31 * ab_ab;
    const T t42 = T(1280) * t30 + t31 * ab_ap * t41 - T(1280) * t35;
    const T t43 = T(1) / ab_ab;
    const T t44 = ap_ap * t31 * t41 - T(12) * t40 * t31 - T(2) * t42 * t43 * ab_ap;
    F = (T(1) / T(15360)) * t42 * t43 * in.w[1] + (T(1) / T(15360)) * in.w[3] * t43 * (T(12) * (T(128) * t39 + t40 * t31 * ab_ap - T(128) * t37) * t43 - T(2) * t43 * ab_ap * t44 - t42 * ap_ap * t43) + (T(1) / T(15360)) * in.w[0] * t31 * t41 - (T(1) / T(15360)) * t43 * t44 * in.w[2];
    const T t45 = t30 * t27;
    const T t46 = t35 * t32;
    const T t47 = T(15360) * t46 * a_minus_b + T(15360) * t45 * ab_ap + T(13) * t31 * ab_ab * t41;
    const T t48 = T(15360) * t45 + t47 * t31 * ab_ap - T(15360) * t46;
    const T t49 = ap_ap * t47 * t31 - T(14) * t31 * t41 - T(2) * t48 * t43 * ab_ap;
    const T t50 = T(14) * t42 * t43 - ap_ap * t48 * t43 - T(2) * t43 * t49 * ab_ap;
    G_ap = (T(1) / T(215040)) * t48 * t43 * in.w[1] + (T(1) / T(215040)) * t47 * in.w[0] * t31 + (T(1) / T(215040)) * in.w[3] * t50 * t43 - (T(1) / T(215040)) * t43 * t49 * in.w[2];
    G_ab = (T(1) / T(215040)) * t50 * t43 * in.w[2] + (T(1) / T(215040)) * t48 * in.w[0] * t43 + (T(1) / T(215040)) * (T(2) * t50 * t43 * ab_ap + ap_ap * t43 * t49 - T(14) * t43 * t44) * in.w[3] * t43 - (T(1) / T(215040)) * t43 * in.w[1] * t49;
  }
  const T g_factor = -T(14) * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 38 +, 97 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    F = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / cross_cross;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t4 * t4;
    const T t13 = t10 * t10;
    const T t14 = t13 * t9;
    const T t15 = t12 * t3;
    const T t16 = t11 * t11;
    F = (T(1) / T(3003)) * (T(231) * t6 * t2 * ab_ap + T(4) * t7 * ab_ab * (T(2) * (T(8) * t7 * ab_ab * (T(2) * (T(4) * t7 * ab_ab * (t3 * t2 * ab_ap + t8 * a_minus_b * t9 + T(2) * (t8 * a_minus_b + t2 * ab_ap) * t7 * ab_ab) + T(3) * t8 * a_minus_b * t10 + T(3) * t4 * t2 * ab_ap) * t7 * ab_ab + T(5) * t5 * t2 * ab_ap + T(5) * t8 * a_minus_b * t11) + T(35) * t12 * t2 * ab_ap + T(35) * t8 * a_minus_b * t13) * t7 * ab_ab + T(63) * t8 * a_minus_b * t14 + T(63) * t15 * t2 * ab_ap) + T(231) * t8 * a_minus_b * t16) * in.w[0] * t7;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 45 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(49) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = T(1) / ab_ab;
    G_ab = -(T(1) / T(15)) * (t8 * t3 - t9 * t14 - T(15) * ab_ap * t2) * in.w[0] * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t23 * t22;
    const T t26 = t19 * t18;
    const T t27 = t20 * t18;
    const T t28 = t24 * t22;
    const T t29 = t26 * t26;
    const T t30 = t25 * t25;
    const T t31 = t29 * t18;
    const T t32 = t30 * t22;
    const T t33 = T(2) * (T(4) * t16 * ab_ab * (T(2) * t16 * ab_ab * (T(35) * a_minus_b * t20 * t17 + T(35) * ab_ap * t21 * t24 + T(8) * (T(5) * ab_ap * t21 * t25 + T(2) * (T(3) * ab_ap * t21 * t23 + T(4) * (T(2) * (ab_ap * t21 + a_minus_b * t17) * t16 * ab_ab + a_minus_b * t18 * t17 + ab_ap * t21 * t22) * t16 * ab_ab + T(3) * a_minus_b * t19 * t17) * t16 * ab_ab + T(5) * a_minus_b * t26 * t17) * t16 * ab_ab) + T(63) * a_minus_b * t27 * t17 + T(63) * ab_ap * t21 * t28) + T(231) * a_minus_b * t29 * t17 + T(231) * ab_ap * t21 * t30) * t16 * ab_ab + T(429) * a_minus_b * t31 * t17 + T(429) * ab_ap * t21 * t32;
    G_ap = (T(1) / T(6435)) * t33 * in.w[0] * t16;
    const T t34 = T(1) / ab_ab;
    G_ab = -(T(1) / T(6435)) * (T(429) * t31 * t17 - ab_ap * t33 * t16 - T(429) * t21 * t32) * in.w[0] * t34;
  }
  const T g_factor = -T(15) * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 45 +, 130 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(49) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = T(1) / ab_ab;
    F = -(T(1) / T(14)) * (ab_ap * t7 * t2 + a_minus_b * t8 * t13 - T(15) * cross_cross * t14) * in.w[0] * t15;
    G_ap = in.w[0] * t14;
    G_ab = -(T(1) / T(15)) * in.w[0] * (t8 * t13 - T(15) * ab_ap * t14 - t7 * t2) * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / cross_cross;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t22 * t18;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t25;
    const T t29 = t26 * t25;
    const T t30 = t29 * t29;
    const T t31 = T(231) * ab_ap * t21 * t17 + T(4) * t16 * ab_ab * (T(63) * ab_ap * t23 * t17 + T(63) * a_minus_b * t24 * t28 + T(2) * (T(8) * (T(5) * ab_ap * t20 * t17 + T(2) * t16 * (T(4) * (ab_ap * t18 * t17 + a_minus_b * t24 * t25 + T(2) * t16 * ab_ab * (a_minus_b * t24 + ab_ap * t17)) * t16 * ab_ab + T(3) * ab_ap * t19 * t17 + T(3) * a_minus_b * t24 * t26) * ab_ab + T(5) * a_minus_b * t24 * t29) * t16 * ab_ab + T(35) * ab_ap * t22 * t17 + T(35) * a_minus_b * t24 * t27) * t16 * ab_ab) + T(231) * a_minus_b * t24 * t30;
    F = (T(1) / T(3003)) * in.w[0] * t16 * t31;
    const T t32 = t21 * t18;
    const T t33 = t30 * t25;
    const T t34 = T(429) * ab_ap * t32 * t17 + T(429) * a_minus_b * t24 * t33 + T(2) * t16 * t31 * ab_ab;
    G_ap = (T(1) / T(6435)) * in.w[0] * t16 * t34;
    const T t35 = T(1) / ab_ab;
    G_ab = -(T(1) / T(6435)) * in.w[0] * t35 * (T(429) * t24 * t33 - ab_ap * t16 * t34 - T(429) * t32 * t17);
  }
  const T g_factor = -T(15) * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 41 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
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
    F = t2 * in.w[0] + (T(1) / T(13)) * in.w[1] * t3 * (t4 * t8 + T(13) * t2 * ab_ap - t13 * t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = t18 * t18;
    const T t20 = t17 * t17;
    const T t21 = t20 * t16;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t24 * t24;
    const T t27 = t26 * t23;
    const T t28 = t25 * t25;
    const T t29 = T(231) * t15 * ab_ap * t19 + T(4) * t14 * ab_ab * (T(63) * t15 * ab_ap * t21 + T(2) * (T(35) * t15 * ab_ap * t20 + T(8) * t14 * ab_ab * (T(5) * a_minus_b * t25 * t22 + T(2) * t14 * ab_ab * (T(3) * t15 * ab_ap * t17 + T(3) * a_minus_b * t24 * t22 + T(4) * t14 * ab_ab * (T(2) * (a_minus_b * t22 + t15 * ab_ap) * t14 * ab_ab + a_minus_b * t23 * t22 + t15 * ab_ap * t16)) + T(5) * t15 * ab_ap * t18) + T(35) * a_minus_b * t26 * t22) * t14 * ab_ab + T(63) * a_minus_b * t27 * t22) + T(231) * a_minus_b * t28 * t22;
    const T t30 = T(1) / ab_ab;
    F = (T(1) / T(3003)) * t14 * in.w[0] * t29 + (T(1) / T(3003)) * in.w[1] * t30 * (T(231) * t15 * t19 + t14 * ab_ap * t29 - T(231) * t28 * t22);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 49 +, 140 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(49) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t3 * t8 + T(15) * ab_ap * t2 - t9 * t14;
    const T t16 = T(1) / ab_ab;
    G_ap = in.w[0] * t2 + (T(1) / T(15)) * t15 * in.w[1] * t16;
    G_ab = (T(1) / T(210)) * in.w[1] * t16 * (T(28) * ab_ap * t15 * t16 + T(15) * t16 * (T(15) * t2 * cross_cross - ab_ap * t3 * t8 - a_minus_b * t9 * t14) - T(210) * ap_ap * t2) + (T(1) / T(15)) * in.w[0] * t15 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / cross_cross;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t20 * t19;
    const T t26 = t20 * t20;
    const T t27 = t23 * t23;
    const T t28 = t26 * t19;
    const T t29 = t27 * t22;
    const T t30 = t25 * t25;
    const T t31 = t24 * t24;
    const T t32 = T(4) * (T(2) * (T(8) * t17 * ab_ab * (T(2) * t17 * (T(3) * a_minus_b * t18 * t20 + T(3) * ab_ap * t21 * t23 + T(4) * t17 * ab_ab * (T(2) * (ab_ap * t21 + a_minus_b * t18) * t17 * ab_ab + a_minus_b * t18 * t19 + ab_ap * t21 * t22)) * ab_ab + T(5) * ab_ap * t21 * t24 + T(5) * a_minus_b * t18 * t25) + T(35) * a_minus_b * t18 * t26 + T(35) * ab_ap * t21 * t27) * t17 * ab_ab + T(63) * a_minus_b * t18 * t28 + T(63) * ab_ap * t21 * t29) * t17 * ab_ab + T(231) * a_minus_b * t18 * t30 + T(231) * ab_ap * t21 * t31;
    const T t33 = t31 * t22;
    const T t34 = t30 * t19;
    const T t35 = T(2) * t17 * ab_ab * t32 + T(429) * ab_ap * t21 * t33 + T(429) * a_minus_b * t18 * t34;
    const T t36 = ab_ap * t35 * t17 + T(429) * t21 * t33 - T(429) * t18 * t34;
    const T t37 = T(1) / ab_ab;
    G_ap = (T(1) / T(6435)) * t36 * in.w[1] * t37 + (T(1) / T(6435)) * in.w[0] * t35 * t17;
    G_ab = (T(1) / T(45045)) * (T(14) * ab_ap * t36 * t37 + T(15) * t17 * t32 - T(7) * ap_ap * t35 * t17) * in.w[1] * t37 + (T(1) / T(6435)) * t36 * in.w[0] * t37;
  }
  const T g_factor = -T(15) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 52 +, 153 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(49) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t7 * t4;
    const T t16 = T(15) * t8 * cross_cross - t9 * t14 * a_minus_b - ab_ap * t15 * t3;
    F = (T(1) / T(182)) * t2 * (T(14) * t7 * t3 + T(13) * t2 * ab_ap * t16 - T(14) * t9 * t13) * in.w[1] + (T(1) / T(14)) * t2 * in.w[0] * t16;
    const T t17 = T(15) * ab_ap * t8 + t15 * t3 - t9 * t14;
    G_ap = (T(1) / T(15)) * t2 * t17 * in.w[1] + t8 * in.w[0];
    G_ab = (T(1) / T(210)) * t2 * (T(28) * t2 * t17 * ab_ap + T(15) * t2 * t16 - T(210) * t8 * ap_ap) * in.w[1] + (T(1) / T(15)) * t2 * t17 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / ab_ab;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t22 * t22;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = t27 * t27;
    const T t29 = T(1) / cross_cross;
    const T t30 = t26 * t26;
    const T t31 = t21 * t21;
    const T t32 = t30 * t25;
    const T t33 = t31 * t20;
    const T t34 = T(231) * ab_ap * t23 * t19 + T(231) * t24 * t28 * a_minus_b + T(4) * ab_ab * (T(2) * ab_ab * t29 * (T(35) * t24 * t30 * a_minus_b + T(35) * ab_ap * t31 * t19 + T(8) * ab_ab * (T(5) * t24 * t27 * a_minus_b + T(5) * ab_ap * t22 * t19 + T(2) * ab_ab * (T(3) * t24 * t26 * a_minus_b + T(3) * ab_ap * t21 * t19 + T(4) * ab_ab * (T(2) * ab_ab * (ab_ap * t19 + t24 * a_minus_b) * t29 + ab_ap * t20 * t19 + t24 * t25 * a_minus_b) * t29) * t29) * t29) + T(63) * t24 * t32 * a_minus_b + T(63) * ab_ap * t33 * t19) * t29;
    F = (T(1) / T(3003)) * t18 * (T(231) * t23 * t19 + ab_ap * t34 * t29 - T(231) * t24 * t28) * in.w[1] + (T(1) / T(3003)) * t34 * in.w[0] * t29;
    const T t35 = t28 * t25;
    const T t36 = t23 * t20;
    const T t37 = T(2) * ab_ab * t34 * t29 + T(429) * t24 * t35 * a_minus_b + T(429) * ab_ap * t36 * t19;
    const T t38 = ab_ap * t37 * t29 + T(429) * t36 * t19 - T(429) * t24 * t35;
    G_ap = (T(1) / T(6435)) * t37 * in.w[0] * t29 + (T(1) / T(6435)) * t18 * t38 * in.w[1];
    G_ab = (T(1) / T(45045)) * t18 * (T(15) * t34 * t29 + T(14) * t18 * ab_ap * t38 - T(7) * t37 * ap_ap * t29) * in.w[1] + (T(1) / T(6435)) * t18 * in.w[0] * t38;
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 44 +, 117 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t13 = T(13) * ab_ap * t2 + t7 * t3 - t12 * t8;
    const T t14 = T(1) / ab_ab;
    F = (T(1) / T(156)) * (T(24) * ab_ap * t13 * t14 + T(13) * t14 * (T(13) * cross_cross * t2 - ab_ap * t7 * t3 - t12 * t8 * a_minus_b) - T(156) * ap_ap * t2) * in.w[2] * t14 + in.w[0] * t2 + (T(1) / T(13)) * in.w[1] * t13 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = t18 * t18;
    const T t20 = T(1) / cross_cross;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t17 * t17;
    const T t28 = t27 * t16;
    const T t29 = t26 * t22;
    const T t30 = T(2) * (T(35) * t26 * t21 * a_minus_b + T(35) * ab_ap * t27 * t15 + T(8) * t20 * (T(2) * (T(3) * t23 * t21 * a_minus_b + T(3) * ab_ap * t17 * t15 + T(4) * (T(2) * t20 * ab_ab * (ab_ap * t15 + t21 * a_minus_b) + ab_ap * t16 * t15 + t22 * t21 * a_minus_b) * t20 * ab_ab) * t20 * ab_ab + T(5) * t24 * t21 * a_minus_b + T(5) * ab_ap * t18 * t15) * ab_ab) * t20 * ab_ab + T(63) * ab_ap * t28 * t15 + T(63) * t29 * t21 * a_minus_b;
    const T t31 = T(231) * ab_ap * t19 * t15 + T(231) * t25 * t21 * a_minus_b + T(4) * t30 * t20 * ab_ab;
    const T t32 = T(231) * t19 * t15 + ab_ap * t20 * t31 - T(231) * t25 * t21;
    const T t33 = T(1) / ab_ab;
    F = (T(1) / T(3003)) * in.w[1] * t32 * t33 + (T(1) / T(3003)) * in.w[0] * t20 * t31 - (T(1) / T(9009)) * in.w[2] * t33 * (T(3) * ap_ap * t20 * t31 - T(6) * ab_ap * t32 * t33 - T(13) * t30 * t20);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 55 +, 160 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(49) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t3 * t8 + T(15) * ab_ap * t2 - t9 * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = ab_ap * t3 * t8 + t9 * a_minus_b * t14 - T(15) * t2 * cross_cross;
    const T t18 = T(15) * t17 * t16 + T(210) * t2 * ap_ap - T(28) * ab_ap * t15 * t16;
    G_ap = t2 * in.w[0] + (T(1) / T(15)) * t15 * in.w[1] * t16 - (T(1) / T(210)) * in.w[2] * t16 * t18;
    G_ab = (T(1) / T(15)) * t15 * t16 * in.w[0] - (T(1) / T(2730)) * in.w[2] * (T(26) * ab_ap * t16 * t18 + T(182) * t15 * ap_ap * t16 - T(15) * (T(14) * t3 * t7 - T(14) * t9 * t13 - T(13) * t17 * ab_ap * t16) * t16) * t16 - (T(1) / T(210)) * in.w[1] * t16 * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / cross_cross;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t23 * t23;
    const T t25 = t24 * t21;
    const T t26 = T(1) / r1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = t22 * t22;
    const T t32 = t28 * t28;
    const T t33 = t31 * t21;
    const T t34 = t32 * t27;
    const T t35 = T(231) * ab_ap * t20 * t24 + T(231) * t26 * a_minus_b * t30 + T(4) * t19 * (T(2) * (T(35) * ab_ap * t20 * t31 + T(8) * t19 * ab_ab * (T(5) * ab_ap * t20 * t23 + T(2) * t19 * ab_ab * (T(4) * (t26 * a_minus_b * t27 + T(2) * (t26 * a_minus_b + ab_ap * t20) * t19 * ab_ab + ab_ap * t20 * t21) * t19 * ab_ab + T(3) * ab_ap * t20 * t22 + T(3) * t26 * a_minus_b * t28) + T(5) * t26 * a_minus_b * t29) + T(35) * t26 * a_minus_b * t32) * t19 * ab_ab + T(63) * ab_ap * t20 * t33 + T(63) * t26 * a_minus_b * t34) * ab_ab;
    const T t36 = t30 * t27;
    const T t37 = T(429) * ab_ap * t20 * t25 + T(2) * t19 * ab_ab * t35 + T(429) * t26 * a_minus_b * t36;
    const T t38 = T(1) / ab_ab;
    const T t39 = ab_ap * t19 * t37 + T(429) * t20 * t25 - T(429) * t26 * t36;
    const T t40 = T(14) * ab_ap * t38 * t39 + T(15) * t19 * t35 - T(7) * ap_ap * t19 * t37;
    G_ap = (T(1) / T(6435)) * t19 * t37 * in.w[0] + (T(1) / T(45045)) * t40 * in.w[2] * t38 + (T(1) / T(6435)) * in.w[1] * t38 * t39;
    G_ab = (T(1) / T(45045)) * t40 * in.w[1] * t38 + (T(1) / T(6435)) * t38 * in.w[0] * t39 - (T(1) / T(45045)) * (T(7) * ap_ap * t38 * t39 - T(2) * t40 * ab_ap * t38 - T(15) * (T(231) * t20 * t24 + ab_ap * t19 * t35 - T(231) * t26 * t30) * t38) * in.w[2] * t38;
  }
  const T g_factor = -T(15) * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 59 +, 178 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(49) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t7 * t4;
    const T t16 = T(15) * cross_cross * t8 - t9 * t14 * a_minus_b - t3 * ab_ap * t15;
    const T t17 = T(14) * t3 * t7 + T(13) * t2 * t16 * ab_ap - T(14) * t9 * t13;
    F = (T(1) / T(2184)) * in.w[2] * (T(24) * t2 * t17 * ab_ap - T(13) * (T(14) * t9 * t13 * a_minus_b + T(14) * t3 * ab_ap * t7 - T(13) * cross_cross * t2 * t16) * t2 - T(156) * t2 * t16 * ap_ap) * t2 + (T(1) / T(182)) * t2 * t17 * in.w[1] + (T(1) / T(14)) * t2 * in.w[0] * t16;
    const T t18 = t3 * t15 + T(15) * t8 * ab_ap - t9 * t14;
    const T t19 = T(15) * t2 * t16 + T(28) * t2 * ab_ap * t18 - T(210) * t8 * ap_ap;
    G_ap = (T(1) / T(15)) * t2 * in.w[1] * t18 + t8 * in.w[0] + (T(1) / T(210)) * in.w[2] * t2 * t19;
    G_ab = (T(1) / T(2730)) * in.w[2] * (T(15) * t2 * t17 + T(26) * t2 * t19 * ab_ap - T(182) * t2 * t18 * ap_ap) * t2 + (T(1) / T(15)) * t2 * in.w[0] * t18 + (T(1) / T(210)) * t2 * t19 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / ab_ab;
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = T(1) / cross_cross;
    const T t27 = T(1) / r1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t30 * t30;
    const T t32 = t23 * t23;
    const T t33 = t32 * t22;
    const T t34 = t29 * t29;
    const T t35 = t34 * t28;
    const T t36 = T(63) * t21 * ab_ap * t33 + T(63) * t27 * t35 * a_minus_b + T(2) * t26 * ab_ab * (T(8) * t26 * ab_ab * (T(5) * t27 * t30 * a_minus_b + T(2) * t26 * ab_ab * (T(3) * t27 * t29 * a_minus_b + T(3) * t21 * ab_ap * t23 + T(4) * t26 * (T(2) * (t21 * ab_ap + t27 * a_minus_b) * t26 * ab_ab + t21 * ab_ap * t22 + t27 * t28 * a_minus_b) * ab_ab) + T(5) * t21 * ab_ap * t24) + T(35) * t21 * ab_ap * t32 + T(35) * t27 * t34 * a_minus_b);
    const T t37 = T(231) * t27 * t31 * a_minus_b + T(4) * t26 * ab_ab * t36 + T(231) * t21 * ab_ap * t25;
    const T t38 = T(231) * t21 * t25 + t26 * t37 * ab_ap - T(231) * t27 * t31;
    F = (T(1) / T(3003)) * t20 * t38 * in.w[1] + (T(1) / T(3003)) * t26 * t37 * in.w[0] - (T(1) / T(9009)) * in.w[2] * t20 * (T(3) * t26 * t37 * ap_ap - T(6) * t20 * t38 * ab_ap - T(13) * t26 * t36);
    const T t39 = t25 * t22;
    const T t40 = t31 * t28;
    const T t41 = T(429) * t27 * t40 * a_minus_b + T(2) * t26 * ab_ab * t37 + T(429) * t21 * ab_ap * t39;
    const T t42 = T(429) * t21 * t39 + t26 * ab_ap * t41 - T(429) * t27 * t40;
    const T t43 = T(14) * t20 * ab_ap * t42 + T(15) * t26 * t37 - T(7) * t26 * t41 * ap_ap;
    G_ap = (T(1) / T(6435)) * t20 * t42 * in.w[1] + (T(1) / T(45045)) * in.w[2] * t20 * t43 + (T(1) / T(6435)) * t26 * in.w[0] * t41;
    G_ab = (T(1) / T(6435)) * t20 * in.w[0] * t42 + (T(1) / T(45045)) * t20 * in.w[1] * t43 + (T(1) / T(45045)) * in.w[2] * t20 * (T(15) * t20 * t38 + T(2) * t20 * ab_ap * t43 - T(7) * t20 * t42 * ap_ap);
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 49 +, 134 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(11) / T(25)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
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
    const T t13 = T(13) * t2 * ab_ap + t7 * t3 - t12 * t8;
    const T t14 = T(1) / ab_ab;
    const T t15 = T(13) * cross_cross * t2 - t7 * t3 * ab_ap - a_minus_b * t12 * t8;
    const T t16 = T(156) * ap_ap * t2 - T(24) * t13 * t14 * ab_ap - T(13) * t15 * t14;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = t10 * t10;
    const T t20 = t19 * t9;
    F = (T(1) / T(13)) * t13 * t14 * in.w[1] + in.w[0] * t2 - (T(1) / T(1716)) * in.w[3] * (T(22) * t14 * ab_ap * t16 + T(132) * ap_ap * t13 * t14 - T(13) * t14 * (T(12) * t18 * t3 + T(11) * t15 * t14 * ab_ap - T(12) * t20 * t8)) * t14 - (T(1) / T(156)) * t14 * t16 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / ab_ab;
    const T t22 = T(1) / r0;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t23;
    const T t27 = T(1) / cross_cross;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t30 * t29;
    const T t33 = t24 * t23;
    const T t34 = t31 * t29;
    const T t35 = T(63) * t26 * t22 * ab_ap + T(2) * t27 * ab_ab * (T(35) * t25 * t22 * ab_ap + T(35) * a_minus_b * t31 * t28 + T(8) * t27 * ab_ab * (T(5) * a_minus_b * t32 * t28 + T(2) * t27 * ab_ab * (T(4) * t27 * ab_ab * (t23 * t22 * ab_ap + a_minus_b * t29 * t28 + T(2) * t27 * ab_ab * (a_minus_b * t28 + t22 * ab_ap)) + T(3) * a_minus_b * t30 * t28 + T(3) * t24 * t22 * ab_ap) + T(5) * t33 * t22 * ab_ap)) + T(63) * a_minus_b * t34 * t28;
    const T t36 = t33 * t33;
    const T t37 = t32 * t32;
    const T t38 = T(231) * t36 * t22 * ab_ap + T(231) * a_minus_b * t37 * t28 + T(4) * t27 * ab_ab * t35;
    const T t39 = t27 * t38 * ab_ap + T(231) * t36 * t22 - T(231) * t37 * t28;
    const T t40 = T(6) * t21 * ab_ap * t39 + T(13) * t27 * t35 - T(3) * ap_ap * t27 * t38;
    F = (T(1) / T(9009)) * in.w[3] * (T(13) * t21 * (T(63) * t26 * t22 + t27 * t35 * ab_ap - T(63) * t34 * t28) + T(2) * t21 * t40 * ab_ap - T(3) * ap_ap * t21 * t39) * t21 + (T(1) / T(3003)) * in.w[0] * t27 * t38 + (T(1) / T(3003)) * t21 * in.w[1] * t39 + (T(1) / T(9009)) * t21 * t40 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 61 +, 181 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(49) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = T(15) * t3 * cross_cross - t4 * a_minus_b * t9 - t10 * t15 * ab_ap;
    const T t17 = t10 * t15 + T(15) * t3 * ab_ap - t4 * t9;
    const T t18 = T(15) * t16 * t2 + T(28) * t2 * t17 * ab_ap - T(210) * ap_ap * t3;
    const T t19 = T(14) * t10 * t14 + T(13) * t16 * t2 * ab_ap - T(14) * t4 * t8;
    const T t20 = T(26) * t18 * t2 * ab_ap + T(15) * t2 * t19 - T(182) * ap_ap * t2 * t17;
    G_ap = (T(1) / T(2730)) * in.w[3] * t2 * t20 + in.w[0] * t3 + (T(1) / T(210)) * in.w[2] * t18 * t2 + (T(1) / T(15)) * t2 * t17 * in.w[1];
    G_ab = (T(1) / T(210)) * t18 * t2 * in.w[1] + (T(1) / T(15)) * in.w[0] * t2 * t17 + (T(1) / T(2730)) * in.w[2] * t2 * t20 + (T(1) / T(10920)) * (T(8) * t2 * t20 * ab_ap - T(52) * t18 * ap_ap * t2 - T(5) * t2 * (T(156) * t16 * ap_ap * t2 - T(24) * t2 * t19 * ab_ap - T(13) * (T(13) * t16 * cross_cross * t2 - T(14) * t4 * a_minus_b * t8 - T(14) * t10 * t14 * ab_ap) * t2)) * in.w[3] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / r0;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = T(1) / cross_cross;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t30 * t30;
    const T t33 = t23 * t23;
    const T t34 = t32 * t29;
    const T t35 = t33 * t22;
    const T t36 = T(2) * t27 * ab_ab * (T(8) * t27 * ab_ab * (T(5) * t21 * t24 * ab_ap + T(2) * (T(3) * t21 * t23 * ab_ap + T(4) * (t28 * a_minus_b * t29 + T(2) * (t21 * ab_ap + t28 * a_minus_b) * t27 * ab_ab + t21 * t22 * ab_ap) * t27 * ab_ab + T(3) * t28 * a_minus_b * t30) * t27 * ab_ab + T(5) * t28 * a_minus_b * t31) + T(35) * t28 * a_minus_b * t32 + T(35) * t21 * t33 * ab_ap) + T(63) * t28 * a_minus_b * t34 + T(63) * t21 * t35 * ab_ap;
    const T t37 = t31 * t31;
    const T t38 = T(4) * t27 * ab_ab * t36 + T(231) * t28 * a_minus_b * t37 + T(231) * t21 * t25 * ab_ap;
    const T t39 = t37 * t29;
    const T t40 = T(2) * t38 * t27 * ab_ab + T(429) * t28 * a_minus_b * t39 + T(429) * t21 * t26 * ab_ap;
    const T t41 = T(429) * t21 * t26 + t40 * t27 * ab_ap - T(429) * t28 * t39;
    const T t42 = T(1) / ab_ab;
    const T t43 = T(15) * t38 * t27 + T(14) * t41 * t42 * ab_ap - T(7) * t40 * ap_ap * t27;
    const T t44 = T(231) * t21 * t25 + t38 * t27 * ab_ap - T(231) * t28 * t37;
    const T t45 = T(2) * t43 * t42 * ab_ap + T(15) * t44 * t42 - T(7) * ap_ap * t41 * t42;
    G_ap = (T(1) / T(6435)) * t41 * t42 * in.w[1] + (T(1) / T(45045)) * in.w[2] * t43 * t42 + (T(1) / T(45045)) * t45 * in.w[3] * t42 + (T(1) / T(6435)) * t40 * in.w[0] * t27;
    G_ab = (T(1) / T(45045)) * t43 * t42 * in.w[1] + (T(1) / T(45045)) * t45 * in.w[2] * t42 + (T(1) / T(6435)) * t41 * in.w[0] * t42 + (T(1) / T(45045)) * (T(5) * (T(6) * t44 * t42 * ab_ap + T(13) * t27 * t36 - T(3) * ap_ap * t38 * t27) * t42 + T(2) * t45 * t42 * ab_ap - ap_ap * t43 * t42) * in.w[3] * t42;
  }
  const T g_factor = -T(15) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 68 +, 208 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(49) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = J_downward<T>(T(17), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t15 = t7 * t2 * ab_ap + t8 * t13 * a_minus_b - T(15) * cross_cross * t14;
    const T t16 = T(1) / ab_ab;
    const T t17 = T(14) * t6 * t2 - T(14) * t8 * t12 - T(13) * t15 * t16 * ab_ap;
    const T t18 = T(14) * t6 * t2 * ab_ap + T(13) * t15 * cross_cross * t16 + T(14) * t8 * t12 * a_minus_b;
    const T t19 = T(156) * ap_ap * t15 * t16 + T(24) * t16 * t17 * ab_ap - T(13) * t18 * t16;
    const T t20 = t4 * t4;
    const T t21 = t20 * t3;
    const T t22 = t10 * t10;
    const T t23 = t22 * t9;
    F = (T(1) / T(2184)) * in.w[2] * t19 * t16 + (T(1) / T(182)) * t16 * t17 * in.w[1] - (T(1) / T(14)) * t15 * in.w[0] * t16 - (T(1) / T(24024)) * in.w[3] * (T(132) * ap_ap * t16 * t17 - T(22) * t19 * t16 * ab_ap - T(13) * (T(168) * t21 * t2 - T(11) * t18 * t16 * ab_ap - T(168) * t8 * t23) * t16) * t16;
    const T t24 = t7 * t2 + T(15) * t14 * ab_ap - t8 * t13;
    const T t25 = T(210) * ap_ap * t14 + T(15) * t15 * t16 - T(28) * t24 * t16 * ab_ap;
    const T t26 = T(15) * t16 * t17 - T(182) * ap_ap * t24 * t16 - T(26) * t25 * t16 * ab_ap;
    G_ap = in.w[0] * t14 + (T(1) / T(15)) * t24 * t16 * in.w[1] + (T(1) / T(2730)) * t26 * in.w[3] * t16 - (T(1) / T(210)) * in.w[2] * t25 * t16;
    G_ab = (T(1) / T(10920)) * in.w[3] * t16 * (T(8) * t26 * t16 * ab_ap + T(52) * ap_ap * t25 * t16 + T(5) * t19 * t16) + (T(1) / T(15)) * in.w[0] * t24 * t16 + (T(1) / T(2730)) * in.w[2] * t26 * t16 - (T(1) / T(210)) * t25 * t16 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = T(1) / cross_cross;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t31 * t31;
    const T t33 = T(1) / r1;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = t30 * t30;
    const T t38 = t35 * t35;
    const T t39 = t38 * t34;
    const T t40 = t37 * t29;
    const T t41 = T(2) * t27 * ab_ab * (T(8) * t27 * ab_ab * (T(2) * t27 * ab_ab * (T(3) * t33 * t35 * a_minus_b + T(4) * t27 * ab_ab * (t29 * t28 * ab_ap + T(2) * t27 * ab_ab * (t33 * a_minus_b + t28 * ab_ap) + t33 * t34 * a_minus_b) + T(3) * t30 * t28 * ab_ap) + T(5) * t33 * t36 * a_minus_b + T(5) * t31 * t28 * ab_ap) + T(35) * t37 * t28 * ab_ap + T(35) * t33 * t38 * a_minus_b) + T(63) * t33 * t39 * a_minus_b + T(63) * t40 * t28 * ab_ap;
    const T t42 = t36 * t36;
    const T t43 = T(231) * t32 * t28 * ab_ap + T(4) * t41 * t27 * ab_ab + T(231) * t33 * t42 * a_minus_b;
    const T t44 = T(1) / ab_ab;
    const T t45 = t27 * t43 * ab_ap + T(231) * t32 * t28 - T(231) * t33 * t42;
    const T t46 = T(13) * t41 * t27 + T(6) * t44 * ab_ap * t45 - T(3) * ap_ap * t27 * t43;
    F = (T(1) / T(3003)) * in.w[0] * t27 * t43 + (T(1) / T(9009)) * in.w[2] * t44 * t46 + (T(1) / T(9009)) * in.w[3] * t44 * (T(2) * t44 * ab_ap * t46 + T(13) * (T(63) * t40 * t28 + t41 * t27 * ab_ap - T(63) * t33 * t39) * t44 - T(3) * ap_ap * t44 * t45) + (T(1) / T(3003)) * t44 * in.w[1] * t45;
    const T t47 = t32 * t29;
    const T t48 = t42 * t34;
    const T t49 = T(429) * t47 * t28 * ab_ap + T(2) * t27 * ab_ab * t43 + T(429) * t33 * t48 * a_minus_b;
    const T t50 = T(429) * t47 * t28 + t27 * ab_ap * t49 - T(429) * t33 * t48;
    const T t51 = T(15) * t27 * t43 + T(14) * t50 * t44 * ab_ap - T(7) * ap_ap * t27 * t49;
    const T t52 = T(15) * t44 * t45 + T(2) * t51 * t44 * ab_ap - T(7) * ap_ap * t50 * t44;
    G_ap = (T(1) / T(45045)) * t52 * in.w[3] * t44 + (T(1) / T(6435)) * t50 * t44 * in.w[1] + (T(1) / T(45045)) * t51 * in.w[2] * t44 + (T(1) / T(6435)) * in.w[0] * t27 * t49;
    G_ab = (T(1) / T(45045)) * in.w[2] * t52 * t44 + (T(1) / T(45045)) * t51 * t44 * in.w[1] + (T(1) / T(6435)) * t50 * in.w[0] * t44 - (T(1) / T(45045)) * in.w[3] * (t51 * ap_ap * t44 - T(2) * t52 * t44 * ab_ap - T(5) * t44 * t46) * t44;
  }
  const T g_factor = -T(15) * length;
  f = length * F;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 41 +, 92 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    F = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(cross_cross);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, ap_bp) * t3;
    const T t4 = T(1) / cross_cross;
    const T t5 = T(1) / bp_bp;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / ap_ap;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t6 * t6;
    const T t16 = t11 * t11;
    const T t17 = t15 * t5;
    const T t18 = t16 * t10;
    F = (T(1) / T(215040)) * t4 * (T(15360) * a_minus_b * t9 + T(15360) * t14 * ab_ap + T(13) * t4 * ab_ab * (T(1280) * a_minus_b * t8 + T(1280) * t13 * ab_ap + T(11) * t4 * (T(3) * t4 * (T(48) * a_minus_b * t15 + T(48) * t16 * ab_ap + T(7) * t4 * ab_ab * (T(8) * t12 * ab_ap + T(5) * (T(2) * a_minus_b * t6 + T(2) * t11 * ab_ap + T(3) * t4 * ab_ab * (J2 * ab_ab + t10 * ab_ap + a_minus_b * t5)) * t4 * ab_ab + T(8) * a_minus_b * t7)) * ab_ab + T(128) * a_minus_b * t17 + T(128) * t18 * ab_ap) * ab_ab)) * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 48 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / ab_ab;
    G_ab = -(T(1) / T(16)) * in.w[0] * (t6 - T(16) * t2 * ab_ap - t10) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / cross_cross;
    const T t15 = T(1) / ap_ap;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / bp_bp;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t20 * t19;
    const T t24 = t23 * t23;
    const T t25 = t24 * t19;
    const T t26 = t16 * t15;
    const T t27 = t26 * t26;
    const T t28 = t21 * t19;
    const T t29 = t17 * t15;
    const T t30 = t27 * t15;
    const T t31 = T(14336) * t18 * ab_ap + T(14336) * a_minus_b * t22 + t14 * (T(15360) * a_minus_b * t25 + T(13) * (T(1280) * a_minus_b * t24 + T(1280) * t27 * ab_ap + T(11) * (T(128) * a_minus_b * t28 + T(3) * t14 * (T(48) * a_minus_b * t21 + T(7) * t14 * ab_ab * (T(5) * t14 * ab_ab * (T(2) * a_minus_b * t20 + T(3) * (ab_ab * J2 + t15 * ab_ap + a_minus_b * t19) * t14 * ab_ab + T(2) * t16 * ab_ap) + T(8) * a_minus_b * t23 + T(8) * t26 * ab_ap) + T(48) * t17 * ab_ap) * ab_ab + T(128) * t29 * ab_ap) * t14 * ab_ab) * t14 * ab_ab + T(15360) * t30 * ab_ap) * ab_ab;
    G_ap = (T(1) / T(229376)) * in.w[0] * t14 * t31;
    const T t32 = T(1) / ab_ab;
    G_ab = (T(1) / T(229376)) * in.w[0] * t32 * (t14 * t31 * ab_ap + T(14336) * t18 - T(14336) * t22);
  }
  const T g_factor = -T(16) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 48 +, 120 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(51) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = T(1) / bp_bp;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / ap_ap;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    F = -(T(1) / T(15)) * in.w[0] * t2 * (t6 * a_minus_b + t10 * ab_ap - T(16) * cross_cross * t11);
    G_ap = in.w[0] * t11;
    G_ab = (T(1) / T(16)) * in.w[0] * t2 * (T(16) * ab_ap * t11 + t10 - t6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(cross_cross);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, ap_bp);
    const T t14 = T(1) / bp_bp;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = t16 * t16;
    const T t18 = t17 * t14;
    const T t19 = T(1) / ap_ap;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t21 * t21;
    const T t23 = t22 * t19;
    const T t24 = T(1) / cross_cross;
    const T t25 = t15 * t15;
    const T t26 = t25 * t14;
    const T t27 = t20 * t20;
    const T t28 = t27 * t19;
    const T t29 = T(15360) * t18 * a_minus_b + T(15360) * t23 * ab_ap + T(13) * (T(1280) * t17 * a_minus_b + T(1280) * t22 * ab_ap + T(11) * t24 * ab_ab * (T(128) * t26 * a_minus_b + T(3) * t24 * (T(48) * t25 * a_minus_b + T(7) * t24 * ab_ab * (T(8) * t21 * ab_ap + T(8) * t16 * a_minus_b + T(5) * t24 * ab_ab * (T(3) * t24 * ab_ab * (t14 * a_minus_b + ab_ab * J2 + t19 * ab_ap) + T(2) * t20 * ab_ap + T(2) * t15 * a_minus_b)) + T(48) * t27 * ab_ap) * ab_ab + T(128) * t28 * ab_ap)) * t24 * ab_ab;
    F = (T(1) / T(215040)) * t29 * in.w[0] * t24;
    const T t30 = t25 * t25;
    const T t31 = t27 * t27;
    const T t32 = T(14336) * t30 * a_minus_b + t29 * t24 * ab_ab + T(14336) * t31 * ab_ap;
    G_ap = (T(1) / T(229376)) * in.w[0] * t24 * t32;
    const T t33 = T(1) / ab_ab;
    G_ab = (T(1) / T(229376)) * in.w[0] * (T(14336) * t31 + t24 * t32 * ab_ap - T(14336) * t30) * t33;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 44 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = t5 * t2;
    const T t7 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = T(1) / ab_ab;
    F = (T(1) / T(14)) * (t6 + T(14) * t7 * ab_ap - t12) * in.w[1] * t13 + t7 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(cross_cross);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, ap_bp) * t15;
    const T t16 = T(1) / ap_ap;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = t18 * t18;
    const T t20 = t17 * t17;
    const T t21 = t20 * t16;
    const T t22 = T(1) / bp_bp;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t22;
    const T t26 = T(1) / cross_cross;
    const T t27 = t23 * t22;
    const T t28 = t27 * t27;
    const T t29 = t19 * t16;
    const T t30 = t28 * t22;
    const T t31 = T(13) * (T(1280) * ab_ap * t19 + T(11) * (T(128) * ab_ap * t21 + T(128) * t25 * a_minus_b + T(3) * (T(48) * ab_ap * t20 + T(48) * t24 * a_minus_b + T(7) * t26 * (T(8) * ab_ap * t18 + T(5) * (T(2) * ab_ap * t17 + T(2) * t23 * a_minus_b + T(3) * (J2 * ab_ab + t22 * a_minus_b + ab_ap * t16) * t26 * ab_ab) * t26 * ab_ab + T(8) * t27 * a_minus_b) * ab_ab) * t26 * ab_ab) * t26 * ab_ab + T(1280) * t28 * a_minus_b) * t26 * ab_ab + T(15360) * ab_ap * t29 + T(15360) * t30 * a_minus_b;
    const T t32 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * in.w[0] * t31 * t26 + (T(1) / T(215040)) * (T(15360) * t29 + ab_ap * t31 * t26 - T(15360) * t30) * in.w[1] * t32;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 52 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / bp_bp;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(16) * t2 * ab_ap + t6 - t10;
    const T t12 = T(1) / ab_ab;
    G_ap = (T(1) / T(16)) * t11 * in.w[1] * t12 + in.w[0] * t2;
    G_ab = (T(1) / T(16)) * in.w[0] * t11 * t12 - (T(1) / T(120)) * in.w[1] * t12 * (T(8) * t12 * (a_minus_b * t10 + t6 * ab_ap - T(16) * cross_cross * t2) + T(120) * ap_ap * t2 - T(15) * t11 * t12 * ab_ap);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(cross_cross);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, ap_bp);
    const T t15 = T(1) / bp_bp;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / cross_cross;
    const T t20 = t16 * t15;
    const T t21 = t20 * t20;
    const T t22 = t21 * t15;
    const T t23 = T(1) / ap_ap;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t25 * t25;
    const T t27 = t26 * t23;
    const T t28 = t24 * t24;
    const T t29 = t17 * t15;
    const T t30 = t28 * t23;
    const T t31 = T(15360) * a_minus_b * t22 + T(15360) * t27 * ab_ap + T(13) * (T(11) * t19 * ab_ab * (T(3) * t19 * ab_ab * (T(7) * (T(8) * t25 * ab_ap + T(5) * t19 * ab_ab * (T(3) * (ab_ab * J2 + a_minus_b * t15 + t23 * ab_ap) * t19 * ab_ab + T(2) * t24 * ab_ap + T(2) * a_minus_b * t16) + T(8) * a_minus_b * t20) * t19 * ab_ab + T(48) * a_minus_b * t17 + T(48) * t28 * ab_ap) + T(128) * a_minus_b * t29 + T(128) * t30 * ab_ap) + T(1280) * t26 * ab_ap + T(1280) * a_minus_b * t21) * t19 * ab_ab;
    const T t32 = t28 * t28;
    const T t33 = T(14336) * a_minus_b * t18 + t19 * ab_ab * t31 + T(14336) * t32 * ab_ap;
    const T t34 = T(1) / ab_ab;
    const T t35 = T(14336) * t32 + t33 * t19 * ab_ap - T(14336) * t18;
    G_ap = (T(1) / T(229376)) * in.w[0] * t33 * t19 + (T(1) / T(229376)) * in.w[1] * t34 * t35;
    G_ab = (T(1) / T(229376)) * in.w[0] * t34 * t35 - (T(1) / T(3440640)) * (T(15) * ap_ap * t33 * t19 - T(16) * t19 * t31 - T(30) * t34 * ab_ap * t35) * in.w[1] * t34;
  }
  const T g_factor = -T(16) * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 55 +, 141 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = t5 * ab_ap + a_minus_b * t9 - T(16) * cross_cross * t10;
    const T t12 = T(1) / ab_ab;
    const T t13 = t7 * t6;
    const T t14 = t13 * t13;
    const T t15 = t14 * t6;
    const T t16 = t3 * t2;
    const T t17 = t16 * t16;
    const T t18 = t17 * t2;
    F = -(T(1) / T(15)) * in.w[0] * t11 * t12 - (T(1) / T(210)) * in.w[1] * (T(15) * t15 + T(14) * t11 * t12 * ab_ap - T(15) * t18) * t12;
    const T t19 = t9 - t5 - T(16) * t10 * ab_ap;
    G_ap = in.w[0] * t10 - (T(1) / T(16)) * t19 * in.w[1] * t12;
    G_ab = -(T(1) / T(16)) * in.w[0] * t19 * t12 - (T(1) / T(120)) * (T(8) * t11 * t12 + T(120) * ap_ap * t10 + T(15) * t19 * t12 * ab_ap) * in.w[1] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(cross_cross);
    const T t21 = T(1) / t20;
    const T J2 = atan2(t20, ap_bp) * t21;
    const T t22 = T(1) / ap_ap;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = t30 * t27;
    const T t32 = t23 * t23;
    const T t33 = t32 * t22;
    const T t34 = t28 * t28;
    const T t35 = t34 * t27;
    const T t36 = T(1) / cross_cross;
    const T t37 = T(15360) * t26 * ab_ap + T(15360) * a_minus_b * t31 + T(13) * (T(1280) * a_minus_b * t30 + T(11) * (T(128) * t33 * ab_ap + T(128) * a_minus_b * t35 + T(3) * t36 * ab_ab * (T(48) * t32 * ab_ap + T(48) * a_minus_b * t34 + T(7) * t36 * (T(8) * a_minus_b * t29 + T(5) * (T(2) * a_minus_b * t28 + T(2) * t23 * ab_ap + T(3) * t36 * ab_ab * (J2 * ab_ab + t22 * ab_ap + a_minus_b * t27)) * t36 * ab_ab + T(8) * t24 * ab_ap) * ab_ab)) * t36 * ab_ab + T(1280) * t25 * ab_ap) * t36 * ab_ab;
    const T t38 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * in.w[0] * t37 * t36 - (T(1) / T(215040)) * in.w[1] * t38 * (T(15360) * t31 - t37 * t36 * ab_ap - T(15360) * t26);
    const T t39 = t32 * t32;
    const T t40 = t34 * t34;
    const T t41 = t37 * t36 * ab_ab + T(14336) * t39 * ab_ap + T(14336) * a_minus_b * t40;
    const T t42 = T(14336) * t40 - T(14336) * t39 - t36 * t41 * ab_ap;
    G_ap = (T(1) / T(229376)) * in.w[0] * t36 * t41 - (T(1) / T(229376)) * in.w[1] * t38 * t42;
    G_ab = -(T(1) / T(3440640)) * (T(15) * ap_ap * t36 * t41 + T(30) * t38 * t42 * ab_ap - T(16) * t37 * t36) * in.w[1] * t38 - (T(1) / T(229376)) * in.w[0] * t38 * t42;
  }
  const T g_factor = -T(16) * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 47 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ap_ap;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = T(14) * t2 * ab_ap + t7 - t12;
    const T t14 = T(1) / ab_ab;
    F = (T(1) / T(14)) * in.w[1] * t13 * t14 + t2 * in.w[0] + (T(1) / T(91)) * in.w[2] * (T(13) * t13 * t14 * ab_ap - T(91) * ap_ap * t2 - T(7) * t14 * (a_minus_b * t12 + t7 * ab_ap - T(14) * cross_cross * t2)) * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(cross_cross);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, ap_bp);
    const T t17 = T(1) / ab_ab;
    const T t18 = T(1) / ap_ap;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t21 * t18;
    const T t23 = T(1) / cross_cross;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = t27 * t24;
    const T t29 = t25 * t25;
    const T t30 = t29 * t24;
    const T t31 = t19 * t19;
    const T t32 = t31 * t18;
    const T t33 = T(11) * t23 * (T(128) * a_minus_b * t30 + T(3) * t23 * ab_ab * (T(48) * a_minus_b * t29 + T(7) * t23 * ab_ab * (T(8) * t20 * ab_ap + T(8) * a_minus_b * t26 + T(5) * t23 * ab_ab * (T(2) * a_minus_b * t25 + T(2) * t19 * ab_ap + T(3) * t23 * ab_ab * (J2 * ab_ab + t18 * ab_ap + a_minus_b * t24))) + T(48) * t31 * ab_ap) + T(128) * t32 * ab_ap) * ab_ab + T(1280) * a_minus_b * t27 + T(1280) * t21 * ab_ap;
    const T t34 = T(15360) * a_minus_b * t28 + T(13) * t33 * t23 * ab_ab + T(15360) * t22 * ab_ap;
    const T t35 = T(15360) * t22 + t23 * t34 * ab_ap - T(15360) * t28;
    F = (T(1) / T(215040)) * in.w[1] * t17 * t35 + (T(1) / T(215040)) * t23 * in.w[0] * t34 - (T(1) / T(215040)) * (ap_ap * t23 * t34 - T(2) * t17 * t35 * ab_ap - T(14) * t33 * t23) * in.w[2] * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 58 +, 148 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(16) * ab_ap * t3 + t7 - t11;
    const T t13 = a_minus_b * t11 + t7 * ab_ap - T(16) * cross_cross * t3;
    const T t14 = T(8) * t2 * t13 + T(120) * ap_ap * t3 - T(15) * t2 * t12 * ab_ap;
    G_ap = (T(1) / T(16)) * t2 * t12 * in.w[1] + in.w[0] * t3 - (T(1) / T(120)) * t14 * in.w[2] * t2;
    const T t15 = t9 * t8;
    const T t16 = t15 * t15;
    const T t17 = t16 * t8;
    const T t18 = t5 * t4;
    const T t19 = t18 * t18;
    const T t20 = t19 * t4;
    G_ab = (T(1) / T(16)) * t2 * t12 * in.w[0] - (T(1) / T(1680)) * in.w[2] * (T(28) * t14 * t2 * ab_ap + T(105) * ap_ap * t2 * t12 + T(8) * t2 * (T(15) * t17 + T(14) * t2 * ab_ap * t13 - T(15) * t20)) * t2 - (T(1) / T(120)) * t14 * t2 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(cross_cross);
    const T t22 = T(1) / t21;
    const T J2 = atan2(t21, ap_bp) * t22;
    const T t23 = T(1) / cross_cross;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = t27 * t24;
    const T t29 = t25 * t25;
    const T t30 = t29 * t24;
    const T t31 = T(1) / ap_ap;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t31;
    const T t35 = t32 * t31;
    const T t36 = t35 * t35;
    const T t37 = t36 * t31;
    const T t38 = T(15360) * a_minus_b * t28 + T(13) * t23 * ab_ab * (T(11) * (T(128) * a_minus_b * t30 + T(128) * t34 * ab_ap + T(3) * t23 * ab_ab * (T(48) * a_minus_b * t29 + T(7) * t23 * ab_ab * (T(8) * t35 * ab_ap + T(8) * a_minus_b * t26 + T(5) * t23 * ab_ab * (T(2) * t32 * ab_ap + T(2) * a_minus_b * t25 + T(3) * t23 * (ab_ab * J2 + a_minus_b * t24 + t31 * ab_ap) * ab_ab)) + T(48) * t33 * ab_ap)) * t23 * ab_ab + T(1280) * a_minus_b * t27 + T(1280) * t36 * ab_ap) + T(15360) * t37 * ab_ap;
    const T t39 = t29 * t29;
    const T t40 = t33 * t33;
    const T t41 = t23 * t38 * ab_ab + T(14336) * a_minus_b * t39 + T(14336) * t40 * ab_ap;
    const T t42 = T(1) / ab_ab;
    const T t43 = T(14336) * t39 - t41 * t23 * ab_ap - T(14336) * t40;
    const T t44 = T(15) * t41 * ap_ap * t23 + T(30) * t43 * t42 * ab_ap - T(16) * t23 * t38;
    G_ap = (T(1) / T(229376)) * t41 * t23 * in.w[0] - (T(1) / T(3440640)) * in.w[2] * t42 * t44 - (T(1) / T(229376)) * t43 * t42 * in.w[1];
    G_ab = -(T(1) / T(3440640)) * (T(2) * t42 * t44 * ab_ap + T(16) * (T(15360) * t28 - T(15360) * t37 - t23 * t38 * ab_ap) * t42 - T(15) * ap_ap * t43 * t42) * in.w[2] * t42 - (T(1) / T(229376)) * t43 * t42 * in.w[0] - (T(1) / T(3440640)) * t42 * t44 * in.w[1];
  }
  const T g_factor = -T(16) * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 62 +, 165 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(51) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / ap_ap;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / bp_bp;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t11 = ab_ap * t5 + t9 * a_minus_b - T(16) * t10 * cross_cross;
    const T t12 = T(1) / ab_ab;
    const T t13 = t7 * t6;
    const T t14 = t13 * t13;
    const T t15 = t14 * t6;
    const T t16 = t3 * t2;
    const T t17 = t16 * t16;
    const T t18 = t17 * t2;
    const T t19 = T(14) * t11 * ab_ap * t12 + T(15) * t15 - T(15) * t18;
    F = -(T(1) / T(15)) * in.w[0] * t11 * t12 - (T(1) / T(210)) * in.w[1] * t19 * t12 - (T(1) / T(1365)) * in.w[2] * (T(7) * (T(15) * t15 * a_minus_b + T(15) * ab_ap * t18 + T(14) * t11 * cross_cross * t12) * t12 + T(13) * ab_ap * t19 * t12 - T(91) * t11 * ap_ap * t12) * t12;
    const T t20 = t9 - t5 - T(16) * t10 * ab_ap;
    const T t21 = T(15) * ab_ap * t20 * t12 + T(120) * t10 * ap_ap + T(8) * t11 * t12;
    G_ap = in.w[0] * t10 - (T(1) / T(120)) * t21 * in.w[2] * t12 - (T(1) / T(16)) * in.w[1] * t20 * t12;
    G_ab = -(T(1) / T(16)) * in.w[0] * t20 * t12 - (T(1) / T(120)) * t21 * in.w[1] * t12 - (T(1) / T(1680)) * (T(8) * t19 * t12 + T(28) * ab_ap * t21 * t12 - T(105) * ap_ap * t20 * t12) * in.w[2] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(cross_cross);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, ap_bp) * t23;
    const T t24 = T(1) / bp_bp;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t24;
    const T t28 = T(1) / ap_ap;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t28;
    const T t32 = T(1) / cross_cross;
    const T t33 = t29 * t28;
    const T t34 = t25 * t24;
    const T t35 = t34 * t34;
    const T t36 = t33 * t33;
    const T t37 = T(11) * (T(128) * t27 * a_minus_b + T(128) * ab_ap * t31 + T(3) * (T(48) * t26 * a_minus_b + T(48) * ab_ap * t30 + T(7) * (T(5) * (T(3) * (ab_ap * t28 + t24 * a_minus_b + J2 * ab_ab) * t32 * ab_ab + T(2) * t25 * a_minus_b + T(2) * ab_ap * t29) * t32 * ab_ab + T(8) * ab_ap * t33 + T(8) * t34 * a_minus_b) * t32 * ab_ab) * t32 * ab_ab) * t32 * ab_ab + T(1280) * t35 * a_minus_b + T(1280) * ab_ap * t36;
    const T t38 = t35 * t24;
    const T t39 = t36 * t28;
    const T t40 = T(13) * t37 * t32 * ab_ab + T(15360) * t38 * a_minus_b + T(15360) * ab_ap * t39;
    const T t41 = ab_ap * t40 * t32 + T(15360) * t39 - T(15360) * t38;
    const T t42 = T(1) / ab_ab;
    F = (T(1) / T(215040)) * in.w[2] * (T(2) * ab_ap * t41 * t42 + T(14) * t37 * t32 - ap_ap * t40 * t32) * t42 + (T(1) / T(215040)) * in.w[0] * t40 * t32 + (T(1) / T(215040)) * t41 * in.w[1] * t42;
    const T t43 = t30 * t30;
    const T t44 = t26 * t26;
    const T t45 = T(14336) * ab_ap * t43 + T(14336) * t44 * a_minus_b + t40 * t32 * ab_ab;
    const T t46 = T(14336) * t44 - T(14336) * t43 - ab_ap * t32 * t45;
    const T t47 = T(30) * t46 * ab_ap * t42 + T(15) * ap_ap * t32 * t45 - T(16) * t40 * t32;
    G_ap = (T(1) / T(229376)) * in.w[0] * t32 * t45 - (T(1) / T(229376)) * t46 * in.w[1] * t42 - (T(1) / T(3440640)) * t47 * in.w[2] * t42;
    G_ab = -(T(1) / T(229376)) * in.w[0] * t46 * t42 - (T(1) / T(3440640)) * in.w[1] * t47 * t42 - (T(1) / T(3440640)) * in.w[2] * (T(2) * ab_ap * t47 * t42 - T(16) * t41 * t42 - T(15) * t46 * ap_ap * t42) * t42;
  }
  const T g_factor = -T(16) * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 52 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  const T t0 = -ab_ap * a_minus_b;
  const T t1 = (T(47) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / bp_bp;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = t8 + T(14) * t2 * ab_ap - t13;
    const T t15 = ab_ap * t8 + t13 * a_minus_b - T(14) * cross_cross * t2;
    const T t16 = T(91) * t2 * ap_ap + T(7) * t3 * t15 - T(13) * t3 * ab_ap * t14;
    F = t2 * in.w[0] + (T(1) / T(14)) * t3 * in.w[1] * t14 - (T(1) / T(91)) * t3 * in.w[2] * t16 - (T(1) / T(1092)) * in.w[3] * (T(7) * t3 * (T(12) * t3 * t15 * ab_ap + T(13) * t12 - T(13) * t7) + T(78) * t3 * ap_ap * t14 + T(24) * t3 * ab_ap * t16) * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(cross_cross);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, ap_bp);
    const T t19 = T(1) / ab_ab;
    const T t20 = T(1) / ap_ap;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t22 * t22;
    const T t24 = T(1) / cross_cross;
    const T t25 = t21 * t21;
    const T t26 = t25 * t20;
    const T t27 = T(1) / bp_bp;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t27;
    const T t31 = t28 * t27;
    const T t32 = t31 * t31;
    const T t33 = T(11) * t24 * ab_ab * (T(128) * ab_ap * t26 + T(128) * t30 * a_minus_b + T(3) * t24 * ab_ab * (T(7) * t24 * ab_ab * (T(5) * t24 * ab_ab * (T(3) * t24 * ab_ab * (ab_ap * t20 + t27 * a_minus_b + ab_ab * J2) + T(2) * t28 * a_minus_b + T(2) * ab_ap * t21) + T(8) * t31 * a_minus_b + T(8) * ab_ap * t22) + T(48) * t29 * a_minus_b + T(48) * ab_ap * t25)) + T(1280) * ab_ap * t23 + T(1280) * t32 * a_minus_b;
    const T t34 = t23 * t20;
    const T t35 = t32 * t27;
    const T t36 = T(13) * t24 * ab_ab * t33 + T(15360) * ab_ap * t34 + T(15360) * t35 * a_minus_b;
    const T t37 = T(15360) * t34 + t24 * t36 * ab_ap - T(15360) * t35;
    const T t38 = t24 * t36 * ap_ap - T(14) * t24 * t33 - T(2) * t19 * ab_ap * t37;
    F = (T(1) / T(215040)) * in.w[3] * t19 * (T(14) * t19 * (T(1280) * t23 + t24 * ab_ap * t33 - T(1280) * t32) - t19 * ap_ap * t37 - T(2) * t19 * t38 * ab_ap) + (T(1) / T(215040)) * t24 * t36 * in.w[0] + (T(1) / T(215040)) * t19 * in.w[1] * t37 - (T(1) / T(215040)) * t19 * t38 * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 64 +, 168 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * ab_ab * min(T(ap_ap), T(bp_bp)) - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t3 = T(1) / ab_ab;
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 + T(16) * t2 * ab_ap - t11;
    const T t13 = ab_ap * t7 + a_minus_b * t11 - T(16) * cross_cross * t2;
    const T t14 = T(8) * t3 * t13 + T(120) * t2 * ap_ap - T(15) * t3 * t12 * ab_ap;
    const T t15 = t9 * t8;
    const T t16 = t15 * t15;
    const T t17 = t16 * t8;
    const T t18 = t5 * t4;
    const T t19 = t18 * t18;
    const T t20 = t19 * t4;
    const T t21 = T(15) * t17 + T(14) * t3 * ab_ap * t13 - T(15) * t20;
    const T t22 = T(8) * t21 * t3 + T(28) * t14 * t3 * ab_ap + T(105) * t3 * t12 * ap_ap;
    G_ap = in.w[0] * t2 + (T(1) / T(16)) * t3 * t12 * in.w[1] - (T(1) / T(120)) * t14 * t3 * in.w[2] - (T(1) / T(1680)) * t22 * in.w[3] * t3;
    G_ab = (T(1) / T(16)) * in.w[0] * t3 * t12 + (T(1) / T(10920)) * in.w[3] * t3 * (T(91) * t14 * t3 * ap_ap - T(8) * (T(7) * (T(14) * cross_cross * t3 * t13 + T(15) * ab_ap * t20 + T(15) * a_minus_b * t17) * t3 + T(13) * t21 * t3 * ab_ap - T(91) * t3 * t13 * ap_ap) * t3 - T(13) * t22 * t3 * ab_ap) - (T(1) / T(1680)) * t22 * t3 * in.w[2] - (T(1) / T(120)) * t14 * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(cross_cross);
    const T t24 = T(1) / t23;
    const T J2 = atan2(t23, ap_bp) * t24;
    const T t25 = T(1) / ap_ap;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = T(1) / cross_cross;
    const T t30 = t26 * t25;
    const T t31 = T(1) / bp_bp;
    const T t32 = t31 * t31;
    const T t33 = t32 * t31;
    const T t34 = t32 * t32;
    const T t35 = t27 * t25;
    const T t36 = t34 * t31;
    const T t37 = t33 * t33;
    const T t38 = t30 * t30;
    const T t39 = T(11) * t29 * ab_ab * (T(3) * (T(7) * (T(8) * ab_ap * t30 + T(8) * a_minus_b * t33 + T(5) * t29 * ab_ab * (T(2) * ab_ap * t26 + T(3) * t29 * ab_ab * (a_minus_b * t31 + ab_ap * t25 + ab_ab * J2) + T(2) * a_minus_b * t32)) * t29 * ab_ab + T(48) * a_minus_b * t34 + T(48) * ab_ap * t27) * t29 * ab_ab + T(128) * ab_ap * t35 + T(128) * a_minus_b * t36) + T(1280) * a_minus_b * t37 + T(1280) * ab_ap * t38;
    const T t40 = t38 * t25;
    const T t41 = t37 * t31;
    const T t42 = T(13) * t39 * t29 * ab_ab + T(15360) * ab_ap * t40 + T(15360) * a_minus_b * t41;
    const T t43 = t34 * t34;
    const T t44 = t29 * ab_ab * t42 + T(14336) * ab_ap * t28 + T(14336) * a_minus_b * t43;
    const T t45 = T(14336) * t28 + t29 * ab_ap * t44 - T(14336) * t43;
    const T t46 = T(1) / ab_ab;
    const T t47 = T(15) * t29 * ap_ap * t44 - T(30) * t45 * t46 * ab_ap - T(16) * t29 * t42;
    const T t48 = T(15360) * t41 - t29 * ab_ap * t42 - T(15360) * t40;
    const T t49 = T(16) * t46 * t48 + T(2) * t46 * t47 * ab_ap + T(15) * t45 * t46 * ap_ap;
    G_ap = (T(1) / T(229376)) * t45 * t46 * in.w[1] + (T(1) / T(229376)) * in.w[0] * t29 * t44 - (T(1) / T(3440640)) * t46 * t47 * in.w[2] - (T(1) / T(3440640)) * in.w[3] * t46 * t49;
    G_ab = (T(1) / T(229376)) * in.w[0] * t45 * t46 + (T(1) / T(3440640)) * (t46 * t47 * ap_ap - T(2) * t46 * ab_ap * t49 - T(16) * (t29 * t42 * ap_ap + T(2) * t46 * t48 * ab_ap - T(14) * t39 * t29) * t46) * in.w[3] * t46 - (T(1) / T(3440640)) * t46 * t47 * in.w[1] - (T(1) / T(3440640)) * t46 * t49 * in.w[2];
  }
  const T g_factor = -T(16) * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 71 +, 192 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * ab_ap;
  const T t1 = (T(51) / T(100)) * min(T(ap_ap), T(bp_bp)) * ab_ab - cross_cross;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / ab_ab;
    const T t3 = J_downward<T>(T(18), ab_ab, cross_cross, -ab_ap, ap_ap, a_minus_b, bp_bp);
    const T t4 = T(1) / ap_ap;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / bp_bp;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(16) * cross_cross * t3 - t7 * ab_ap - a_minus_b * t11;
    const T t13 = t5 * t4;
    const T t14 = t13 * t13;
    const T t15 = t14 * t4;
    const T t16 = t9 * t8;
    const T t17 = t16 * t16;
    const T t18 = t17 * t8;
    const T t19 = T(14) * t2 * t12 * ab_ap + T(15) * t15 - T(15) * t18;
    const T t20 = T(15) * t15 * ab_ap + T(15) * a_minus_b * t18 - T(14) * cross_cross * t2 * t12;
    const T t21 = T(13) * t19 * t2 * ab_ap - T(7) * t2 * t20 - T(91) * ap_ap * t2 * t12;
    F = (T(1) / T(5460)) * (T(8) * t2 * t21 * ab_ap + T(7) * (T(65) * t14 - T(4) * t2 * t20 * ab_ap - T(65) * t17) * t2 - T(26) * t19 * ap_ap * t2) * in.w[3] * t2 + (T(1) / T(210)) * t19 * t2 * in.w[1] + (T(1) / T(1365)) * in.w[2] * t2 * t21 + (T(1) / T(15)) * in.w[0] * t2 * t12;
    const T t22 = t7 + T(16) * t3 * ab_ap - t11;
    const T t23 = T(120) * ap_ap * t3 - T(15) * t2 * t22 * ab_ap - T(8) * t2 * t12;
    const T t24 = T(8) * t19 * t2 - T(28) * t2 * t23 * ab_ap - T(105) * ap_ap * t2 * t22;
    G_ap = (T(1) / T(16)) * t2 * t22 * in.w[1] + in.w[0] * t3 + (T(1) / T(1680)) * in.w[3] * t2 * t24 - (T(1) / T(120)) * in.w[2] * t2 * t23;
    G_ab = (T(1) / T(10920)) * (T(8) * t2 * t21 + T(91) * ap_ap * t2 * t23 + T(13) * t2 * t24 * ab_ap) * in.w[3] * t2 + (T(1) / T(1680)) * in.w[2] * t2 * t24 + (T(1) / T(16)) * in.w[0] * t2 * t22 - (T(1) / T(120)) * t2 * t23 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(cross_cross);
    const T t26 = T(1) / t25;
    const T J2 = t26 * atan2(t25, ap_bp);
    const T t27 = T(1) / ab_ab;
    const T t28 = T(1) / ap_ap;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t30 * t30;
    const T t32 = t29 * t29;
    const T t33 = t32 * t28;
    const T t34 = T(1) / cross_cross;
    const T t35 = T(1) / bp_bp;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = t36 * t36;
    const T t39 = t38 * t35;
    const T t40 = t37 * t37;
    const T t41 = T(1280) * t31 * ab_ap + T(11) * (T(128) * t33 * ab_ap + T(3) * t34 * (T(48) * t32 * ab_ap + T(7) * t34 * (T(8) * t30 * ab_ap + T(5) * t34 * (T(3) * (a_minus_b * t35 + t28 * ab_ap + ab_ab * J2) * t34 * ab_ab + T(2) * t29 * ab_ap + T(2) * a_minus_b * t36) * ab_ab + T(8) * a_minus_b * t37) * ab_ab + T(48) * a_minus_b * t38) * ab_ab + T(128) * a_minus_b * t39) * t34 * ab_ab + T(1280) * a_minus_b * t40;
    const T t42 = t31 * t28;
    const T t43 = t40 * t35;
    const T t44 = T(15360) * t42 * ab_ap + T(13) * t41 * t34 * ab_ab + T(15360) * a_minus_b * t43;
    const T t45 = T(15360) * t42 + t34 * ab_ap * t44 - T(15360) * t43;
    const T t46 = T(2) * t45 * t27 * ab_ap + T(14) * t41 * t34 - ap_ap * t34 * t44;
    F = (T(1) / T(215040)) * (T(14) * t27 * (T(1280) * t31 + t41 * t34 * ab_ap - T(1280) * t40) + T(2) * t27 * t46 * ab_ap - t45 * ap_ap * t27) * in.w[3] * t27 + (T(1) / T(215040)) * t34 * in.w[0] * t44 + (T(1) / T(215040)) * t45 * t27 * in.w[1] + (T(1) / T(215040)) * in.w[2] * t27 * t46;
    const T t47 = t32 * t32;
    const T t48 = t38 * t38;
    const T t49 = T(14336) * t47 * ab_ap + T(14336) * a_minus_b * t48 + t34 * ab_ab * t44;
    const T t50 = T(14336) * t47 + t34 * t49 * ab_ap - T(14336) * t48;
    const T t51 = T(16) * t34 * t44 + T(30) * t27 * t50 * ab_ap - T(15) * ap_ap * t34 * t49;
    const T t52 = T(2) * t51 * t27 * ab_ap + T(16) * t45 * t27 - T(15) * ap_ap * t27 * t50;
    G_ap = (T(1) / T(229376)) * t27 * t50 * in.w[1] + (T(1) / T(3440640)) * in.w[2] * t51 * t27 + (T(1) / T(3440640)) * t52 * in.w[3] * t27 + (T(1) / T(229376)) * t34 * in.w[0] * t49;
    G_ab = (T(1) / T(3440640)) * t51 * t27 * in.w[1] + (T(1) / T(3440640)) * t52 * in.w[2] * t27 + (T(1) / T(3440640)) * in.w[3] * (T(16) * t27 * t46 + T(2) * t52 * t27 * ab_ap - ap_ap * t51 * t27) * t27 + (T(1) / T(229376)) * in.w[0] * t27 * t50;
  }
  const T g_factor = -T(16) * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

}  // namespace skelconv::generated
