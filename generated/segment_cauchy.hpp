// generated/segment_cauchy.hpp — segment kernels of the cauchy family.
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
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 28 +, 37 ×, 2 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 29 +, 37 ×, 2 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_cauchy_i1_w0_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * b;
    const T t2 = sqrt(a);
    X = (t1 + a_minus_b * r0) * t2 / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = r1 * b;
    X = -(a_minus_b - b) * t3 / (t4 - a_minus_b * r0);
  }
  const T t5 = sqrt(a);
  const T J1 = asinh(X) / t5;
  T F;
    // recurrence (1) upwards from J_1, J_2
    F = in.w[0] * J1;
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 34 +, 52 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i1_w0_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t2 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / a;
    G_ab = (t3 + b * t2 - t4) * t5 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = T(1) / r0;
    const T t7 = T(1) / r1;
    const T t8 = b * t6 + t7 * a_minus_b;
    const T t9 = T(1) / D;
    G_ap = t8 * in.w[0] * t9;
    const T t10 = T(1) / a;
    G_ab = (b * t8 * t9 + t6 - t7) * t10 * in.w[0];
  }
  const T g_factor = -length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 35 +, 60 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i1_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = r0 * a_minus_b;
    const T t3 = sqrt(a);
    X = t1 * (t2 + r1 * b) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = t4 * (a_minus_b - b) / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = J1 * in.w[0];
    F = t10;
    const T t11 = -b;
    const T t12 = J_downward<T>(T(3), a, D, t11, c, a_minus_b, q1);
    G_ap = t12 * in.w[0];
    const T t13 = T(1) / a;
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    G_ab = in.w[0] * t13 * (t14 + t12 * b - t15);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = J1 * in.w[0];
    F = t16;
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = t17 * b + t18 * a_minus_b;
    const T t20 = T(1) / D;
    G_ap = t19 * t20 * in.w[0];
    const T t21 = T(1) / a;
    G_ab = in.w[0] * t21 * (t19 * t20 * b + t17 - t18);
  }
  const T g_factor = -length * in.s;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 31 +, 41 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 32 +, 41 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_cauchy_i1_w1_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = b * r1;
    const T t2 = sqrt(a);
    X = (t1 + r0 * a_minus_b) * t2 / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = b * r1;
    X = (b - a_minus_b) * t3 / (t4 - r0 * a_minus_b);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = asinh(X) * t6;
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / a;
    F = in.w[1] * (J1 * b + r1 - r0) * t7 + J1 * in.w[0];
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 39 +, 67 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i1_w1_grad(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * b;
    const T t2 = sqrt(a);
    const T t3 = T(1) / D;
    X = (t1 + r0 * a_minus_b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -(a_minus_b - b) * t4 / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = -b;
    const T t11 = J_downward<T>(T(3), a, D, t10, c, a_minus_b, q1);
    const T t12 = T(1) / a;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t13 - t14 - t11 * b;
    G_ap = in.w[0] * t11 - t12 * in.w[1] * t15;
    G_ab = -t12 * in.w[1] * (c * t11 + T(2) * t12 * b * t15 - J1) - in.w[0] * t12 * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = t17 * b + t18 * a_minus_b;
    const T t20 = t18 - t17 - t16 * b * t19;
    const T t21 = T(1) / a;
    G_ap = in.w[0] * t16 * t19 - t20 * t21 * in.w[1];
    G_ab = -in.w[0] * t20 * t21 - (c * t16 * t19 + T(2) * t20 * t21 * b - J1) * t21 * in.w[1];
  }
  const T g_factor = -in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 42 +, 72 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i1_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * b;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + r0 * a_minus_b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -t4 * (a_minus_b - b) / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = in.w[0] * J1 - in.w[1] * t10 * (r0 - r1 - J1 * b);
    F = t11;
    const T t12 = T(1) / r0;
    const T t13 = -b;
    const T t14 = J_downward<T>(T(3), a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / r1;
    const T t16 = t12 + t14 * b - t15;
    G_ap = in.w[1] * t10 * t16 + t14 * in.w[0];
    G_ab = in.w[0] * t10 * t16 - in.w[1] * t10 * (t14 * c - J1 - T(2) * t10 * t16 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = in.w[0] * J1 - in.w[1] * t17 * (r0 - r1 - J1 * b);
    F = t18;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / D;
    const T t21 = T(1) / r1;
    const T t22 = t19 * b + t21 * a_minus_b;
    const T t23 = t19 + t20 * t22 * b - t21;
    G_ap = t23 * in.w[1] * t17 + in.w[0] * t20 * t22;
    G_ab = t23 * in.w[0] * t17 - (c * t20 * t22 - J1 - T(2) * t23 * t17 * b) * in.w[1] * t17;
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 36 +, 53 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 37 +, 53 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_cauchy_i1_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = sqrt(a);
    X = (t1 + b * r1) * t2 / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = a_minus_b * r0;
    X = t3 * (a_minus_b - b) / (t4 - b * r1);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = t6 * asinh(X);
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / a;
    const T t8 = J1 * b + r1 - r0;
    F = (T(1) / T(2)) * in.w[2] * t7 * (T(4) * t7 * t8 * b + (r0 * b + D * J1 + a_minus_b * r1) * t7 - T(2) * J1 * c) + J1 * in.w[0] + in.w[1] * t7 * t8;
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 45 +, 78 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i1_w2_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = b * r1;
    X = t1 * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = b * r1;
    X = -t4 * (a_minus_b - b) / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = -b;
    const T t11 = J_downward<T>(T(3), a, D, t10, c, a_minus_b, q1);
    const T t12 = T(1) / a;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t13 - t11 * b - t14;
    const T t16 = J1 - T(2) * t12 * b * t15 - t11 * c;
    G_ap = t11 * in.w[0] + in.w[2] * t12 * t16 - t12 * t15 * in.w[1];
    const T t17 = r0 - r1 - b * J1;
    G_ab = t12 * t16 * in.w[1] + (T(2) * t12 * b * t16 + t12 * t15 * c - t12 * t17) * in.w[2] * t12 - t12 * in.w[0] * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / D;
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = a_minus_b * t20 + b * t21;
    const T t23 = t19 * t22 * b + t21 - t20;
    const T t24 = t19 * t22 * c - T(2) * t18 * b * t23 - J1;
    G_ap = t18 * in.w[1] * t23 + t19 * t22 * in.w[0] - in.w[2] * t18 * t24;
    const T t25 = r0 - r1 - b * J1;
    G_ab = t18 * in.w[0] * t23 - t18 * t24 * in.w[1] - (T(2) * t18 * b * t24 + t18 * t25 + t18 * c * t23) * in.w[2] * t18;
  }
  const T g_factor = -length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 51 +, 94 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i1_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + r1 * b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = (a_minus_b - b) * t4 / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = r0 - r1 - b * J1;
    const T t12 = (T(1) / T(2)) * ((D * J1 + r0 * b + r1 * a_minus_b) * t10 - T(4) * t11 * t10 * b - T(2) * c * J1) * t10 * in.w[2] + in.w[0] * J1 - t11 * in.w[1] * t10;
    F = t12;
    const T t13 = -b;
    const T t14 = J_downward<T>(T(3), a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 - t16 - t14 * b;
    const T t18 = t14 * c + T(2) * t10 * b * t17 - J1;
    G_ap = t14 * in.w[0] - in.w[1] * t10 * t17 - t18 * t10 * in.w[2];
    const T t19 = t11 * t10;
    G_ab = -t10 * in.w[2] * (t19 + T(2) * t18 * t10 * b - c * t10 * t17) - in.w[1] * t18 * t10 - t10 * in.w[0] * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / a;
    const T t21 = r0 - r1 - b * J1;
    const T t22 = (T(1) / T(2)) * ((D * J1 + r0 * b + r1 * a_minus_b) * t20 - T(4) * t21 * t20 * b - T(2) * c * J1) * t20 * in.w[2] + in.w[0] * J1 - t21 * in.w[1] * t20;
    F = t22;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = t24 * b + t25 * a_minus_b;
    const T t27 = t23 * t26 * b + t24 - t25;
    const T t28 = T(2) * t20 * t27 * b + J1 - c * t23 * t26;
    G_ap = in.w[1] * t20 * t27 + t23 * t26 * in.w[0] + t20 * in.w[2] * t28;
    const T t29 = t21 * t20;
    G_ab = in.w[1] * t20 * t28 + t20 * t27 * in.w[0] - t20 * in.w[2] * (t29 + c * t20 * t27 - T(2) * t20 * t28 * b);
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 41 +, 70 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 42 +, 70 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_cauchy_i1_w3_f(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = sqrt(a);
    const T t2 = r0 * a_minus_b;
    X = t1 * (t2 + b * r1) / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = r0 * a_minus_b;
    X = -t3 * (b - a_minus_b) / (t4 - b * r1);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = t6 * asinh(X);
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / a;
    const T t8 = r0 - J1 * b - r1;
    const T t9 = D * J1 + r1 * a_minus_b + r0 * b;
    const T t10 = T(4) * t7 * t8 * b + T(2) * J1 * c - t7 * t9;
    F = (T(1) / T(6)) * (T(6) * t7 * t8 * c + t7 * (T(2) * q1 * r1 + T(3) * t7 * b * t9 - T(2) * r0 * c) - T(6) * t7 * t10 * b) * in.w[3] * t7 + in.w[0] * J1 - (T(1) / T(2)) * t7 * t10 * in.w[2] - t7 * t8 * in.w[1];
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 53 +, 99 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i1_w3_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = r1 * b;
    X = t1 * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -t4 * (a_minus_b - b) / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = r1 + b * J1 - r0;
    const T t12 = t10 * t11;
    const T t13 = -b;
    const T t14 = J_downward<T>(T(3), a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = b * t14 + t15 - t16;
    const T t18 = t14 * c - T(2) * t10 * t17 * b - J1;
    const T t19 = t12 - t10 * t17 * c - T(2) * t10 * b * t18;
    G_ap = t19 * t10 * in.w[3] + in.w[0] * t14 + t10 * t17 * in.w[1] - t10 * t18 * in.w[2];
    const T t20 = (T(4) * t10 * t11 * b + t10 * (D * J1 + b * r0 + r1 * a_minus_b) - T(2) * J1 * c) * t10;
    G_ab = t19 * t10 * in.w[2] + t10 * in.w[0] * t17 + (T(1) / T(2)) * t10 * in.w[3] * (T(2) * t10 * c * t18 + t20 + T(4) * t19 * t10 * b) - t10 * in.w[1] * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / D;
    const T t22 = T(1) / r1;
    const T t23 = T(1) / r0;
    const T t24 = t22 * a_minus_b + b * t23;
    const T t25 = t21 * b * t24 + t23 - t22;
    const T t26 = T(1) / a;
    const T t27 = r1 + b * J1 - r0;
    const T t28 = t26 * t27;
    const T t29 = t21 * c * t24 - T(2) * t25 * t26 * b - J1;
    const T t30 = t28 - t25 * t26 * c - T(2) * t26 * b * t29;
    G_ap = t25 * t26 * in.w[1] + t21 * in.w[0] * t24 + t26 * t30 * in.w[3] - t26 * t29 * in.w[2];
    const T t31 = (T(4) * t26 * t27 * b + t26 * (D * J1 + b * r0 + r1 * a_minus_b) - T(2) * J1 * c) * t26;
    G_ab = (T(1) / T(2)) * t26 * in.w[3] * (T(4) * t26 * t30 * b + t31 + T(2) * t26 * t29 * c) + t25 * t26 * in.w[0] + t26 * t30 * in.w[2] - t26 * in.w[1] * t29;
  }
  const T g_factor = -length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 60 +, 123 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i1_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = sqrt(a);
    const T t2 = T(1) / D;
    const T t3 = r1 * b;
    X = t1 * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -t4 * (a_minus_b - b) / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = r1 * a_minus_b + b * r0 + D * J1;
    const T t12 = r1 + b * J1 - r0;
    const T t13 = t10 * t11 + T(4) * t10 * t12 * b - T(2) * c * J1;
    const T t14 = in.w[0] * J1 + (T(1) / T(2)) * t10 * t13 * in.w[2] + t10 * t12 * in.w[1] - (T(1) / T(6)) * t10 * in.w[3] * (T(6) * t10 * t12 * c + t10 * (T(2) * c * r0 - T(2) * r1 * q1 - T(3) * t10 * b * t11) - T(6) * t10 * t13 * b);
    F = t14;
    const T t15 = -b;
    const T t16 = J_downward<T>(T(3), a, D, t15, c, a_minus_b, q1);
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = b * t16 + t17 - t18;
    const T t20 = t16 * c - J1 - T(2) * t10 * b * t19;
    const T t21 = t10 * t12 - T(2) * t10 * b * t20 - t10 * t19 * c;
    G_ap = t10 * t19 * in.w[1] + in.w[0] * t16 + t10 * in.w[3] * t21 - t10 * t20 * in.w[2];
    G_ab = t10 * in.w[0] * t19 + (T(1) / T(2)) * t10 * in.w[3] * (T(2) * t10 * t20 * c + T(4) * t10 * b * t21 + t10 * t13) + t10 * in.w[2] * t21 - t10 * in.w[1] * t20;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / a;
    const T t23 = r1 * a_minus_b + b * r0 + D * J1;
    const T t24 = r1 + b * J1 - r0;
    const T t25 = t22 * t23 + T(4) * t22 * t24 * b - T(2) * c * J1;
    const T t26 = in.w[0] * J1 + (T(1) / T(2)) * t22 * t25 * in.w[2] + t22 * t24 * in.w[1] - (T(1) / T(6)) * t22 * in.w[3] * (T(6) * t22 * t24 * c + t22 * (T(2) * c * r0 - T(2) * r1 * q1 - T(3) * t22 * b * t23) - T(6) * t22 * t25 * b);
    F = t26;
    const T t27 = T(1) / r0;
    const T t28 = T(1) / D;
    const T t29 = T(1) / r1;
    const T t30 = b * t27 + t29 * a_minus_b;
    const T t31 = t27 + t28 * b * t30 - t29;
    const T t32 = t28 * c * t30 - T(2) * t22 * b * t31 - J1;
    const T t33 = t22 * c * t31 + T(2) * t22 * b * t32 - t22 * t24;
    G_ap = t22 * in.w[1] * t31 + t28 * in.w[0] * t30 - t22 * in.w[3] * t33 - t22 * t32 * in.w[2];
    G_ab = t22 * in.w[0] * t31 - t22 * t33 * in.w[2] - (T(1) / T(2)) * t22 * in.w[3] * (T(4) * t22 * b * t33 - T(2) * t22 * t32 * c - t22 * t25) - t22 * t32 * in.w[1];
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 31 +, 40 ×, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w0_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T J2 = atan2(t2, c_minus_b) / t2;
    F = in.w[0] * J2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 38 +, 61 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i2_w0_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = T(1) / c;
    G_ab = -(T(1) / T(2)) * in.w[0] * t3 * (t4 - T(2) * t2 * b - t5);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T t7 = T(1) / t6;
    const T J2 = t7 * atan2(t6, c_minus_b);
    const T t8 = T(1) / c;
    const T t9 = T(1) / q1;
    const T t10 = t8 * b + a_minus_b * t9 + J2 * a;
    const T t11 = T(1) / D;
    G_ap = (T(1) / T(2)) * t10 * t11 * in.w[0];
    const T t12 = T(1) / a;
    G_ab = -(T(1) / T(2)) * in.w[0] * t12 * (t9 - t8 - t10 * t11 * b);
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 38 +, 63 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = T(1) / c;
    const T t5 = T(1) / a;
    F = (T(2) * t2 * D - t3 * a_minus_b - t4 * b) * t5 * in.w[0];
    G_ap = t2 * in.w[0];
    G_ab = -(T(1) / T(2)) * (t3 - t4 - T(2) * t2 * b) * t5 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T t7 = T(1) / t6;
    const T J2 = t7 * atan2(t6, c_minus_b);
    F = J2 * in.w[0];
    const T t8 = T(1) / q1;
    const T t9 = T(1) / c;
    const T t10 = t8 * a_minus_b + J2 * a + t9 * b;
    const T t11 = T(1) / D;
    G_ap = (T(1) / T(2)) * t10 * t11 * in.w[0];
    const T t12 = T(1) / a;
    G_ab = -(T(1) / T(2)) * (t8 - t10 * t11 * b - t9) * t12 * in.w[0];
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 33 +, 45 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w1_f(const SegmentInput<T>& in) {
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    F = in.w[0] * t2 + (T(1) / T(2)) * (log_ratio + T(2) * t2 * b) * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    const T t5 = T(1) / a;
    F = in.w[0] * J2 + (T(1) / T(2)) * t5 * in.w[1] * (log_ratio + T(2) * b * J2);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 42 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i2_w1_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = t3 + T(2) * b * t4 - t5;
    G_ap = (T(1) / T(2)) * t2 * in.w[1] * t6 + in.w[0] * t4;
    G_ab = (T(1) / T(2)) * in.w[0] * t2 * t6 - t2 * in.w[1] * (t4 * c - t2 * (T(2) * D * t4 - a_minus_b * t5 - b * t3) - t2 * b * t6);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = sqrt(D);
    const T t8 = T(1) / t7;
    const T J2 = t8 * atan2(t7, c_minus_b);
    const T t9 = T(1) / c;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = a_minus_b * t11 + a * J2 + b * t9;
    const T t13 = t9 + t10 * t12 * b - t11;
    const T t14 = T(1) / a;
    G_ap = (T(1) / T(2)) * t13 * t14 * in.w[1] + (T(1) / T(2)) * in.w[0] * t10 * t12;
    G_ab = (T(1) / T(2)) * in.w[0] * t13 * t14 - (T(1) / T(2)) * (t10 * t12 * c - T(2) * t13 * t14 * b - T(2) * J2) * t14 * in.w[1];
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 44 +, 81 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = T(2) * t4 * D - t0 * b - t5 * a_minus_b;
    F = (T(1) / T(2)) * in.w[1] * t3 * (log_ratio + T(2) * t6 * t3 * b) + t6 * in.w[0] * t3;
    const T t7 = t0 + T(2) * t4 * b - t5;
    G_ap = in.w[0] * t4 + (T(1) / T(2)) * t7 * in.w[1] * t3;
    G_ab = (T(1) / T(2)) * t7 * in.w[0] * t3 - in.w[1] * t3 * (c * t4 - t7 * t3 * b - t6 * t3);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / a;
    F = (T(1) / T(2)) * (T(2) * J2 * b + log_ratio) * in.w[1] * t10 + in.w[0] * J2;
    const T t11 = T(1) / q1;
    const T t12 = t0 * b + t11 * a_minus_b + J2 * a;
    const T t13 = T(1) / D;
    const T t14 = t0 + t12 * t13 * b - t11;
    G_ap = (T(1) / T(2)) * in.w[0] * t12 * t13 + (T(1) / T(2)) * in.w[1] * t10 * t14;
    G_ab = (T(1) / T(2)) * in.w[0] * t10 * t14 - (T(1) / T(2)) * in.w[1] * t10 * (c * t12 * t13 - T(2) * J2 - T(2) * t10 * t14 * b);
  }
  const T g_factor = -T(2) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 36 +, 50 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(2) * b * t2 + log_ratio;
    F = in.w[0] * t2 + t3 * in.w[2] * (t4 * t3 * b + T(1) - t2 * c) + (T(1) / T(2)) * t4 * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    const T t6 = T(1) / a;
    const T t7 = T(2) * J2 * b + log_ratio;
    F = (T(1) / T(2)) * t6 * t7 * in.w[1] + J2 * in.w[0] - t6 * in.w[2] * (J2 * c - t6 * t7 * b - T(1));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 47 +, 88 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i2_w2_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(1) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = T(2) * b * t4 + t0 - t5;
    const T t7 = b * t0;
    const T t8 = a_minus_b * t5;
    const T t9 = t7 + t8 - T(2) * D * t4;
    const T t10 = t9 * t3 + t4 * c - t3 * b * t6;
    G_ap = (T(1) / T(2)) * t3 * t6 * in.w[1] + in.w[0] * t4 - in.w[2] * t3 * t10;
    G_ab = (T(1) / T(2)) * t3 * in.w[0] * t6 + (T(1) / T(2)) * in.w[2] * t3 * (t3 * (log_ratio - T(2) * t9 * t3 * b) - T(4) * t3 * b * t10 - t3 * t6 * c) - t3 * in.w[1] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / D;
    const T t14 = b * t0;
    const T t15 = T(1) / q1;
    const T t16 = a_minus_b * t15;
    const T t17 = t14 + a * J2 + t16;
    const T t18 = T(1) / a;
    const T t19 = t15 - t0 - t13 * t17 * b;
    const T t20 = t13 * t17 * c + T(2) * t18 * t19 * b - T(2) * J2;
    G_ap = (T(1) / T(2)) * t13 * t17 * in.w[0] - (T(1) / T(2)) * t18 * t19 * in.w[1] - (T(1) / T(2)) * in.w[2] * t18 * t20;
    G_ab = -(T(1) / T(2)) * t18 * t19 * in.w[0] - (T(1) / T(2)) * in.w[2] * (T(2) * t18 * b * t20 - t18 * (log_ratio + T(2) * b * J2) - t18 * t19 * c) * t18 - (T(1) / T(2)) * t18 * t20 * in.w[1];
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 51 +, 98 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(1) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = T(2) * t4 * D - b * t0 - a_minus_b * t5;
    const T t7 = log_ratio + T(2) * t3 * b * t6;
    F = t3 * in.w[0] * t6 + (T(1) / T(2)) * t3 * in.w[1] * t7 - in.w[2] * t3 * (t3 * c * t6 - t3 * b * t7 - T(1));
    const T t8 = T(2) * b * t4 + t0 - t5;
    const T t9 = t3 * t6 + t3 * b * t8 - c * t4;
    G_ap = in.w[0] * t4 + (T(1) / T(2)) * t3 * t8 * in.w[1] + in.w[2] * t3 * t9;
    G_ab = (T(1) / T(2)) * in.w[2] * t3 * (t3 * t7 + T(4) * t3 * t9 * b - t3 * t8 * c) + (T(1) / T(2)) * t3 * in.w[0] * t8 + t3 * t9 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / a;
    const T t13 = log_ratio + T(2) * b * J2;
    F = (T(1) / T(2)) * t12 * t13 * in.w[1] + in.w[0] * J2 - in.w[2] * t12 * (c * J2 - t12 * t13 * b - T(1));
    const T t14 = T(1) / q1;
    const T t15 = a * J2 + b * t0 + a_minus_b * t14;
    const T t16 = T(1) / D;
    const T t17 = t15 * b * t16 + t0 - t14;
    const T t18 = T(2) * t12 * b * t17 + T(2) * J2 - t15 * c * t16;
    G_ap = (T(1) / T(2)) * in.w[2] * t12 * t18 + (T(1) / T(2)) * t12 * t17 * in.w[1] + (T(1) / T(2)) * t15 * in.w[0] * t16;
    G_ab = (T(1) / T(2)) * in.w[2] * t12 * (T(2) * t12 * b * t18 + t12 * t13 - t12 * t17 * c) + (T(1) / T(2)) * t12 * in.w[1] * t18 + (T(1) / T(2)) * t12 * in.w[0] * t17;
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 41 +, 60 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w3_f(const SegmentInput<T>& in) {
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
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(2) * t2 * b + log_ratio;
    const T t5 = t3 * t4 * b + T(1) - c * t2;
    const T t6 = (c - q1 - T(2) * b) * t3;
    F = in.w[0] * t2 + (T(1) / T(2)) * t3 * t4 * in.w[1] + in.w[2] * t5 * t3 - (T(1) / T(2)) * in.w[3] * t3 * (c * t3 * t4 + t6 - T(4) * t5 * t3 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = sqrt(D);
    const T J2 = atan2(t7, c_minus_b) / t7;
    const T t8 = T(1) / a;
    const T t9 = T(2) * J2 * b + log_ratio;
    const T t10 = (c - q1 - T(2) * b) * t8;
    const T t11 = c * J2 - t8 * t9 * b - T(1);
    F = in.w[0] * J2 + (T(1) / T(2)) * t8 * t9 * in.w[1] - (T(1) / T(2)) * in.w[3] * t8 * (t10 + c * t8 * t9 + T(4) * t8 * t11 * b) - in.w[2] * t8 * t11;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 53 +, 104 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i2_w3_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T G_ap;
  T G_ab;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = t0 + T(2) * b * t4 - t5;
    const T t7 = b * t0;
    const T t8 = t5 * a_minus_b;
    const T t9 = t7 + t8 - T(2) * D * t4;
    const T t10 = b * t6 * t3 - t9 * t3 - c * t4;
    const T t11 = T(2) * b * t9 * t3 - log_ratio;
    const T t12 = c * t6 * t3 + t3 * t11 - T(4) * b * t3 * t10;
    G_ap = in.w[2] * t3 * t10 + (T(1) / T(2)) * in.w[1] * t6 * t3 + t4 * in.w[0] - (T(1) / T(2)) * t12 * t3 * in.w[3];
    G_ab = in.w[1] * t3 * t10 + (T(1) / T(2)) * t6 * t3 * in.w[0] - (T(1) / T(2)) * t12 * in.w[2] * t3 - t3 * in.w[3] * (b * t12 * t3 + c * t3 * t10 - (c * t9 * t3 + T(1) - b * t3 * t11) * t3);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = b * t0;
    const T t16 = T(1) / q1;
    const T t17 = t16 * a_minus_b;
    const T t18 = t15 + t17 + J2 * a;
    const T t19 = T(1) / D;
    const T t20 = t0 + b * t18 * t19 - t16;
    const T t21 = T(1) / a;
    const T t22 = T(2) * J2 + T(2) * b * t20 * t21 - c * t18 * t19;
    const T t23 = log_ratio + T(2) * b * J2;
    const T t24 = T(2) * b * t22 * t21 + t23 * t21 - t20 * c * t21;
    G_ap = (T(1) / T(2)) * t22 * in.w[2] * t21 + (T(1) / T(2)) * t18 * t19 * in.w[0] + (T(1) / T(2)) * in.w[1] * t20 * t21 + (T(1) / T(2)) * t21 * t24 * in.w[3];
    G_ab = (T(1) / T(2)) * in.w[2] * t21 * t24 + (T(1) / T(2)) * t22 * in.w[1] * t21 + (T(1) / T(2)) * t20 * t21 * in.w[0] - (T(1) / T(2)) * (t22 * c * t21 - T(2) * (b * t23 * t21 + T(1) - c * J2) * t21 - T(2) * b * t21 * t24) * t21 * in.w[3];
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 60 +, 121 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i2_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = b * t0;
    const T t4 = T(1) / q1;
    const T t5 = a_minus_b * t4;
    const T t6 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t7 = t3 + t5 - T(2) * t6 * D;
    const T t8 = T(1) / a;
    const T t9 = log_ratio - T(2) * b * t7 * t8;
    const T t10 = c * t7 * t8 + b * t9 * t8 + T(1);
    const T t11 = T(2) * b + q1 - c;
    F = (T(1) / T(2)) * in.w[1] * t9 * t8 + in.w[2] * t8 * t10 - (T(1) / T(2)) * (c * t9 * t8 - T(4) * b * t8 * t10 - t11 * t8) * in.w[3] * t8 - t7 * t8 * in.w[0];
    const T t12 = t4 - t0 - T(2) * b * t6;
    const T t13 = t7 * t8 + b * t12 * t8 + t6 * c;
    const T t14 = t9 * t8 + t12 * c * t8 - T(4) * b * t13 * t8;
    G_ap = (T(1) / T(2)) * t14 * in.w[3] * t8 + t6 * in.w[0] - (T(1) / T(2)) * t12 * in.w[1] * t8 - t13 * in.w[2] * t8;
    G_ab = (b * t14 * t8 + t13 * c * t8 + t8 * t10) * in.w[3] * t8 + (T(1) / T(2)) * t14 * in.w[2] * t8 - (T(1) / T(2)) * t12 * t8 * in.w[0] - t13 * in.w[1] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = log_ratio + T(2) * b * J2;
    const T t18 = T(1) / a;
    const T t19 = b * t17 * t18 + T(1) - c * J2;
    const T t20 = T(2) * b + q1 - c;
    F = J2 * in.w[0] + t19 * in.w[2] * t18 + (T(1) / T(2)) * (t20 * t18 + T(4) * t19 * b * t18 - c * t17 * t18) * in.w[3] * t18 + (T(1) / T(2)) * in.w[1] * t17 * t18;
    const T t21 = T(1) / D;
    const T t22 = b * t0;
    const T t23 = T(1) / q1;
    const T t24 = a_minus_b * t23;
    const T t25 = t22 + J2 * a + t24;
    const T t26 = t23 - b * t21 * t25 - t0;
    const T t27 = c * t21 * t25 + T(2) * b * t26 * t18 - T(2) * J2;
    const T t28 = T(2) * t27 * b * t18 - t26 * c * t18 - t17 * t18;
    G_ap = (T(1) / T(2)) * t21 * in.w[0] * t25 - (T(1) / T(2)) * t28 * in.w[3] * t18 - (T(1) / T(2)) * t26 * in.w[1] * t18 - (T(1) / T(2)) * t27 * in.w[2] * t18;
    G_ab = (T(1) / T(2)) * (t27 * c * t18 + T(2) * t19 * t18 - T(2) * b * t28 * t18) * in.w[3] * t18 - (T(1) / T(2)) * t26 * t18 * in.w[0] - (T(1) / T(2)) * t27 * in.w[1] * t18 - (T(1) / T(2)) * t28 * in.w[2] * t18;
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 29 +, 36 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w0_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = (a_minus_b / r1 + b / r0) * in.w[0] / D;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 36 +, 66 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i3_w0_grad(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / a;
    G_ab = -(T(1) / T(3)) * (t3 * t4 - t5 * t6 - T(3) * b * t2) * t7 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t8 * t9 * b + T(2) * a * t10 * (t11 * a_minus_b + t8 * b) + t11 * a_minus_b * t12;
    G_ap = (T(1) / T(3)) * t13 * t10 * in.w[0];
    const T t14 = T(1) / a;
    G_ab = (T(1) / T(3)) * (t13 * t10 * b + t8 * t9 - t11 * t12) * t14 * in.w[0];
  }
  const T g_factor = -T(3) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 36 +, 69 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t3 * a_minus_b * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t6 * b * t7;
    const T t9 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    F = -(T(1) / T(2)) * in.w[0] * t2 * (t5 + t8 - T(3) * D * t9);
    G_ap = in.w[0] * t9;
    const T t10 = t3 * t4;
    G_ab = -(T(1) / T(3)) * in.w[0] * t2 * (t10 - t6 * t7 - T(3) * b * t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 * a_minus_b + t12 * b;
    const T t14 = T(1) / D;
    F = t13 * t14 * in.w[0];
    const T t15 = t11 * t11;
    const T t16 = t11 * a_minus_b * t15;
    const T t17 = t12 * t12;
    const T t18 = t12 * b * t17;
    const T t19 = t16 + t18 + T(2) * t13 * t14 * a;
    G_ap = (T(1) / T(3)) * t14 * in.w[0] * t19;
    const T t20 = T(1) / a;
    const T t21 = t11 * t15;
    G_ab = -(T(1) / T(3)) * in.w[0] * t20 * (t21 - t12 * t17 - t14 * b * t19);
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 32 +, 43 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w1_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t2 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    F = t2 * in.w[0] - t3 * in.w[1] * (t4 - t2 * b - t5);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = T(1) / r0;
    const T t9 = a_minus_b * t7 + t8 * b;
    const T t10 = T(1) / a;
    F = t6 * in.w[0] * t9 - t10 * in.w[1] * (t7 - t6 * b * t9 - t8);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 40 +, 79 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i3_w1_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t4 * t5 - T(3) * t2 * b - t6 * t7;
    G_ap = t2 * in.w[0] - (T(1) / T(3)) * t3 * in.w[1] * t8;
    const T t9 = t6 * t7 * b;
    const T t10 = t4 * a_minus_b * t5;
    G_ab = -(T(1) / T(3)) * in.w[0] * t3 * t8 - (T(1) / T(6)) * (T(3) * t3 * (t9 + t10 - T(3) * t2 * D) + T(6) * t2 * c + T(4) * t3 * t8 * b) * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / D;
    const T t12 = T(1) / r0;
    const T t13 = T(1) / r1;
    const T t14 = t12 * b + t13 * a_minus_b;
    const T t15 = t12 * t12;
    const T t16 = t12 * t15 * b;
    const T t17 = t13 * t13;
    const T t18 = t13 * a_minus_b * t17;
    const T t19 = T(2) * a * t11 * t14 + t16 + t18;
    const T t20 = t11 * t19 * b + t12 * t15 - t13 * t17;
    const T t21 = T(1) / a;
    G_ap = (T(1) / T(3)) * in.w[0] * t11 * t19 + (T(1) / T(3)) * t20 * t21 * in.w[1];
    G_ab = (T(1) / T(3)) * in.w[0] * t20 * t21 + (T(1) / T(3)) * (T(2) * t20 * t21 * b + T(3) * t11 * t14 - c * t11 * t19) * t21 * in.w[1];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 43 +, 86 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = T(3) * t3 * D - t5 * t4 * a_minus_b - b * t7 * t6;
    F = (T(1) / T(2)) * in.w[0] * t2 * t8 - (T(1) / T(2)) * (T(2) * t4 - b * t2 * t8 - T(2) * t6) * in.w[1] * t2;
    const T t9 = T(3) * b * t3 + t7 * t6 - t5 * t4;
    G_ap = (T(1) / T(3)) * t9 * in.w[1] * t2 + t3 * in.w[0];
    G_ab = (T(1) / T(3)) * t9 * in.w[0] * t2 + (T(1) / T(6)) * (T(3) * t2 * t8 + T(4) * b * t9 * t2 - T(6) * t3 * c) * in.w[1] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / r0;
    const T t11 = T(1) / r1;
    const T t12 = b * t10 + t11 * a_minus_b;
    const T t13 = T(1) / D;
    const T t14 = T(1) / a;
    F = (b * t12 * t13 + t10 - t11) * in.w[1] * t14 + t12 * in.w[0] * t13;
    const T t15 = t11 * t11;
    const T t16 = t10 * t10;
    const T t17 = T(2) * t12 * t13 * a + t15 * t11 * a_minus_b + b * t16 * t10;
    const T t18 = t15 * t11 - t16 * t10 - b * t17 * t13;
    G_ap = (T(1) / T(3)) * in.w[0] * t17 * t13 - (T(1) / T(3)) * t18 * in.w[1] * t14;
    G_ab = -(T(1) / T(3)) * in.w[0] * t18 * t14 - (T(1) / T(3)) * (c * t17 * t13 + T(2) * b * t18 * t14 - T(3) * t12 * t13) * in.w[1] * t14;
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 36 +, 56 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w2_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = r1 * b;
    X = t1 * t2 * (t3 + a_minus_b * r0);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -(a_minus_b - b) * t4 / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(1) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / r0;
    const T t11 = -b;
    const T t12 = J_downward<T>(T(3), a, D, t11, c, a_minus_b, q1);
    const T t13 = T(1) / r1;
    const T t14 = t10 + t12 * b - t13;
    const T t15 = T(1) / a;
    F = in.w[1] * t14 * t15 + in.w[0] * t12 - t15 * in.w[2] * (c * t12 - T(2) * t14 * t15 * b - J1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / a;
    const T t17 = T(1) / r0;
    const T t18 = T(1) / D;
    const T t19 = T(1) / r1;
    const T t20 = t17 * b + t19 * a_minus_b;
    const T t21 = t17 + t18 * b * t20 - t19;
    F = in.w[1] * t16 * t21 + (T(2) * t16 * t21 * b + J1 - c * t18 * t20) * t16 * in.w[2] + in.w[0] * t18 * t20;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 46 +, 94 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i3_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = T(3) * b * t3 + t6 - t7 * t8;
    const T t10 = t7 * a_minus_b * t8;
    const T t11 = t5 * b * t4;
    const T t12 = t10 + t11 - T(3) * D * t3;
    const T t13 = T(3) * t2 * t12 + T(6) * c * t3 - T(4) * t2 * t9 * b;
    G_ap = (T(1) / T(3)) * in.w[1] * t2 * t9 + in.w[0] * t3 - (T(1) / T(6)) * t13 * in.w[2] * t2;
    G_ab = (T(1) / T(3)) * t2 * t9 * in.w[0] - (T(1) / T(6)) * (T(2) * t13 * t2 * b + T(2) * c * t2 * t9 - T(3) * t2 * (T(2) * t4 - t2 * b * t12 - T(2) * t7)) * in.w[2] * t2 - (T(1) / T(6)) * in.w[1] * t13 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t14 * a_minus_b * t15;
    const T t17 = T(1) / r0;
    const T t18 = t14 * a_minus_b + b * t17;
    const T t19 = T(1) / D;
    const T t20 = t17 * t17;
    const T t21 = t20 * b * t17;
    const T t22 = t16 + T(2) * t18 * t19 * a + t21;
    const T t23 = T(1) / a;
    const T t24 = t20 * t17;
    const T t25 = t22 * t19 * b + t24 - t14 * t15;
    const T t26 = T(3) * t18 * t19 + T(2) * t23 * t25 * b - c * t22 * t19;
    G_ap = (T(1) / T(3)) * t22 * t19 * in.w[0] + (T(1) / T(3)) * in.w[2] * t23 * t26 + (T(1) / T(3)) * in.w[1] * t23 * t25;
    G_ab = (T(1) / T(3)) * in.w[1] * t23 * t26 + (T(1) / T(3)) * (T(3) * (t17 + t18 * t19 * b - t14) * t23 + T(2) * t23 * b * t26 - c * t23 * t25) * in.w[2] * t23 + (T(1) / T(3)) * t23 * t25 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 51 +, 112 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 50 +, 114 ×, 5 /, 5 sqrt, 0 atan, 1 log/asinh, 1 other.
template <class T>
T segment_cauchy_i3_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = r0 * a_minus_b;
    X = t1 * t2 * (t3 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = -(b - a_minus_b) * t4 / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -b * a_minus_b;
  const T t9 = (T(3) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = T(3) * t10 * D - t11 * t12 * a_minus_b - b * t14 * t13;
    const T t16 = T(1) / a;
    const T t17 = T(2) * t11 - b * t15 * t16 - T(2) * t13;
    F = (T(1) / T(2)) * in.w[0] * t15 * t16 + (T(1) / T(2)) * (T(2) * J1 - t15 * c * t16 - T(2) * b * t17 * t16) * t16 * in.w[2] - (T(1) / T(2)) * in.w[1] * t17 * t16;
    const T t18 = t14 * t13;
    const T t19 = T(3) * b * t10 + t18 - t11 * t12;
    const T t20 = T(4) * t19 * b * t16 + T(3) * t15 * t16 - T(6) * t10 * c;
    G_ap = in.w[0] * t10 + (T(1) / T(6)) * t20 * t16 * in.w[2] + (T(1) / T(3)) * t19 * in.w[1] * t16;
    G_ab = (T(1) / T(6)) * t16 * in.w[2] * (T(2) * t20 * b * t16 - T(2) * t19 * c * t16 - T(3) * t17 * t16) + (T(1) / T(3)) * in.w[0] * t19 * t16 + (T(1) / T(6)) * t20 * in.w[1] * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / r0;
    const T t22 = T(1) / r1;
    const T t23 = b * t21 + t22 * a_minus_b;
    const T t24 = T(1) / D;
    const T t25 = t22 - t23 * b * t24 - t21;
    const T t26 = T(1) / a;
    F = t23 * in.w[0] * t24 - (T(2) * b * t25 * t26 + t23 * c * t24 - J1) * t26 * in.w[2] - in.w[1] * t25 * t26;
    const T t27 = t22 * t22;
    const T t28 = t21 * t21;
    const T t29 = T(2) * t23 * t24 * a + t22 * t27 * a_minus_b + b * t28 * t21;
    const T t30 = t28 * t21;
    const T t31 = b * t29 * t24 + t30 - t22 * t27;
    const T t32 = T(3) * t23 * t24 + T(2) * b * t31 * t26 - t29 * c * t24;
    G_ap = (T(1) / T(3)) * in.w[0] * t29 * t24 + (T(1) / T(3)) * in.w[1] * t31 * t26 + (T(1) / T(3)) * t32 * t26 * in.w[2];
    G_ab = (T(1) / T(3)) * in.w[0] * t31 * t26 + (T(1) / T(3)) * in.w[1] * t32 * t26 - (T(1) / T(3)) * (c * t31 * t26 + T(3) * t25 * t26 - T(2) * b * t32 * t26) * t26 * in.w[2];
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 41 +, 65 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i3_w3_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = b * r1;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + r0 * a_minus_b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = b * r1;
    X = (b - a_minus_b) * t4 / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  const T t8 = -b * a_minus_b;
  const T t9 = (T(1) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.01 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = T(1) / r1;
    const T t12 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t13 = T(1) / r0;
    const T t14 = t11 - t12 * b - t13;
    const T t15 = b * J1 + r1 - r0;
    const T t16 = t12 * c + T(2) * b * t14 * t10 - J1;
    F = in.w[3] * t10 * (t14 * c * t10 + t15 * t10 - T(2) * b * t10 * t16) + t12 * in.w[0] - in.w[1] * t14 * t10 - in.w[2] * t10 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r1;
    const T t18 = T(1) / r0;
    const T t19 = t17 * a_minus_b + t18 * b;
    const T t20 = T(1) / D;
    const T t21 = t17 - t18 - b * t19 * t20;
    const T t22 = T(1) / a;
    const T t23 = t19 * c * t20 + T(2) * b * t21 * t22 - J1;
    const T t24 = b * J1 + r1 - r0;
    F = t19 * t20 * in.w[0] - in.w[1] * t21 * t22 - t23 * in.w[2] * t22 - (T(2) * b * t23 * t22 - t24 * t22 - t21 * c * t22) * in.w[3] * t22;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 53 +, 118 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i3_w3_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = sqrt(a);
    const T t2 = r0 * a_minus_b;
    const T t3 = T(1) / D;
    X = t1 * (t2 + b * r1) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = -t4 * (b - a_minus_b) / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = -b * a_minus_b;
  const T t9 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t11 = T(1) / a;
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t14 - T(3) * t10 * b - t15 * t16;
    const T t18 = b * t15 * t16;
    const T t19 = t13 * t12 * a_minus_b;
    const T t20 = t18 + t19 - T(3) * t10 * D;
    const T t21 = T(2) * t12 + t11 * b * t20 - T(2) * t15;
    const T t22 = T(4) * t11 * b * t17 + T(3) * t11 * t20 + T(6) * t10 * c;
    const T t23 = T(2) * t11 * t17 * c - T(3) * t11 * t21 - T(2) * t11 * b * t22;
    G_ap = t10 * in.w[0] + (T(1) / T(6)) * in.w[3] * t11 * t23 - (T(1) / T(3)) * t11 * in.w[1] * t17 - (T(1) / T(6)) * t11 * in.w[2] * t22;
    G_ab = (T(1) / T(6)) * in.w[3] * t11 * (T(3) * t11 * (t11 * c * t20 + T(2) * J1 - T(2) * t11 * b * t21) + t11 * c * t22 + T(2) * t11 * t23 * b) + (T(1) / T(6)) * t11 * t23 * in.w[2] - (T(1) / T(3)) * t11 * t17 * in.w[0] - (T(1) / T(6)) * t11 * in.w[1] * t22;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = T(1) / r0;
    const T t25 = t24 * t24;
    const T t26 = b * t24 * t25;
    const T t27 = T(1) / r1;
    const T t28 = t27 * a_minus_b + b * t24;
    const T t29 = T(1) / D;
    const T t30 = t27 * t27;
    const T t31 = t30 * t27 * a_minus_b;
    const T t32 = t26 + T(2) * a * t28 * t29 + t31;
    const T t33 = T(1) / a;
    const T t34 = t30 * t27;
    const T t35 = t34 - b * t32 * t29 - t24 * t25;
    const T t36 = T(3) * t28 * t29 - t32 * c * t29 - T(2) * t33 * b * t35;
    const T t37 = t28 * b * t29 + t24 - t27;
    const T t38 = T(3) * t33 * t37 + T(2) * t33 * b * t36 + t33 * c * t35;
    G_ap = (T(1) / T(3)) * t32 * t29 * in.w[0] + (T(1) / T(3)) * t33 * t36 * in.w[2] + (T(1) / T(3)) * in.w[3] * t33 * t38 - (T(1) / T(3)) * t33 * in.w[1] * t35;
    G_ab = (T(1) / T(3)) * in.w[3] * t33 * (T(3) * t33 * (J1 + T(2) * t33 * t37 * b - t28 * c * t29) + T(2) * t33 * t38 * b - t33 * t36 * c) + (T(1) / T(3)) * t33 * in.w[1] * t36 + (T(1) / T(3)) * t33 * t38 * in.w[2] - (T(1) / T(3)) * t33 * t35 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 60 +, 134 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 59 +, 138 ×, 5 /, 5 sqrt, 0 atan, 1 log/asinh, 1 other.
template <class T>
T segment_cauchy_i3_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r1 * b;
    const T t2 = sqrt(a);
    const T t3 = T(1) / D;
    X = (t1 + r0 * a_minus_b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -(a_minus_b - b) * t4 / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10 * b;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13 * a_minus_b;
    const T t16 = -b;
    const T t17 = J_downward<T>(T(5), a, D, t16, c, a_minus_b, q1);
    const T t18 = t12 + t15 - T(3) * t17 * D;
    const T t19 = T(1) / a;
    const T t20 = T(2) * t13 + t18 * t19 * b - T(2) * t10;
    const T t21 = T(2) * J1 + c * t18 * t19 - T(2) * t20 * t19 * b;
    const T t22 = J1 * b + r1 - r0;
    F = (T(1) / T(2)) * t21 * in.w[2] * t19 + (T(1) / T(2)) * t19 * in.w[3] * (T(2) * t21 * t19 * b + T(2) * t19 * t22 + c * t20 * t19) - (T(1) / T(2)) * in.w[1] * t20 * t19 - (T(1) / T(2)) * t18 * t19 * in.w[0];
    const T t23 = t11 * t10;
    const T t24 = T(3) * t17 * b + t23 - t14 * t13;
    const T t25 = T(4) * t24 * t19 * b - T(6) * c * t17 - T(3) * t18 * t19;
    const T t26 = T(2) * c * t24 * t19 + T(3) * t20 * t19 - T(2) * t25 * t19 * b;
    G_ap = (T(1) / T(3)) * in.w[1] * t24 * t19 + (T(1) / T(6)) * in.w[2] * t25 * t19 + t17 * in.w[0] - (T(1) / T(6)) * t19 * t26 * in.w[3];
    G_ab = (T(1) / T(3)) * t24 * t19 * in.w[0] + (T(1) / T(6)) * in.w[1] * t25 * t19 - (T(1) / T(6)) * in.w[2] * t19 * t26 - (T(1) / T(6)) * t19 * in.w[3] * (T(2) * t19 * t26 * b + c * t25 * t19 - T(3) * t21 * t19);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = T(1) / r1;
    const T t28 = T(1) / r0;
    const T t29 = t27 * a_minus_b + t28 * b;
    const T t30 = T(1) / D;
    const T t31 = t27 - t29 * t30 * b - t28;
    const T t32 = T(1) / a;
    const T t33 = c * t29 * t30 + T(2) * t31 * t32 * b - J1;
    const T t34 = J1 * b + r1 - r0;
    F = t29 * t30 * in.w[0] - in.w[2] * t33 * t32 - (T(2) * t33 * t32 * b - t32 * t34 - c * t31 * t32) * t32 * in.w[3] - in.w[1] * t31 * t32;
    const T t35 = t28 * t28;
    const T t36 = t35 * t28 * b;
    const T t37 = t27 * t27;
    const T t38 = t37 * t27 * a_minus_b;
    const T t39 = t36 + t38 + T(2) * t29 * a * t30;
    const T t40 = t35 * t28;
    const T t41 = t39 * t30 * b + t40 - t37 * t27;
    const T t42 = T(2) * t32 * t41 * b + T(3) * t29 * t30 - t39 * c * t30;
    const T t43 = c * t32 * t41 + T(3) * t31 * t32 - T(2) * t42 * t32 * b;
    G_ap = (T(1) / T(3)) * in.w[1] * t32 * t41 + (T(1) / T(3)) * t39 * t30 * in.w[0] + (T(1) / T(3)) * in.w[2] * t42 * t32 - (T(1) / T(3)) * t32 * t43 * in.w[3];
    G_ab = (T(1) / T(3)) * in.w[1] * t42 * t32 + (T(1) / T(3)) * t32 * t41 * in.w[0] - (T(1) / T(3)) * in.w[2] * t32 * t43 - (T(1) / T(3)) * t32 * in.w[3] * (c * t42 * t32 + T(2) * t32 * t43 * b + T(3) * t33 * t32);
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 33 +, 44 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w0_f(const SegmentInput<T>& in) {
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    F = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    F = (T(1) / T(2)) * (b / c + a * J2 + a_minus_b / q1) * t4 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 40 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i4_w0_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / a;
    G_ab = -(T(1) / T(4)) * (t4 - T(4) * b * t2 - t6) * t7 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = T(1) / q1;
    const T t13 = T(1) / D;
    const T t14 = t12 * t12;
    const T t15 = T(2) * b * t11 + T(3) * (a_minus_b * t12 + b * t10 + J2 * a) * t13 * a + T(2) * a_minus_b * t14;
    G_ap = (T(1) / T(8)) * t15 * t13 * in.w[0];
    const T t16 = T(1) / a;
    G_ab = -(T(1) / T(8)) * (T(2) * t14 - b * t15 * t13 - T(2) * t11) * t16 * in.w[0];
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 40 +, 76 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / a;
    F = (T(1) / T(3)) * (T(4) * t2 * D - a_minus_b * t4 - b * t6) * t7 * in.w[0];
    G_ap = t2 * in.w[0];
    G_ab = (T(1) / T(4)) * (T(4) * b * t2 + t6 - t4) * t7 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / c;
    const T t11 = T(1) / q1;
    const T t12 = b * t10 + a_minus_b * t11 + J2 * a;
    const T t13 = T(1) / D;
    F = (T(1) / T(2)) * t12 * t13 * in.w[0];
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * a_minus_b * t14 + T(2) * b * t15 + T(3) * t12 * a * t13;
    G_ap = (T(1) / T(8)) * t13 * in.w[0] * t16;
    const T t17 = T(1) / a;
    G_ab = (T(1) / T(8)) * (b * t13 * t16 + T(2) * t15 - T(2) * t14) * t17 * in.w[0];
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 36 +, 51 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w1_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = T(1) / c;
    F = in.w[0] * t2 - (T(1) / T(2)) * t3 * (t4 - T(2) * t2 * b - t5) * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T t7 = T(1) / t6;
    const T J2 = atan2(t6, c_minus_b) * t7;
    const T t8 = T(1) / c;
    const T t9 = T(1) / q1;
    const T t10 = t8 * b + a_minus_b * t9 + a * J2;
    const T t11 = T(1) / D;
    const T t12 = T(1) / a;
    F = (T(1) / T(2)) * in.w[0] * t10 * t11 - (T(1) / T(2)) * (t9 - t10 * t11 * b - t8) * t12 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 44 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i4_w1_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t4 - T(4) * t2 * b - t6;
    const T t8 = T(1) / a;
    G_ap = in.w[0] * t2 - (T(1) / T(4)) * t7 * t8 * in.w[1];
    G_ab = -(T(1) / T(6)) * t8 * in.w[1] * (T(3) * t7 * t8 * b + T(6) * t2 * c + T(2) * t8 * (a_minus_b * t4 + b * t6 - T(4) * D * t2)) - (T(1) / T(4)) * in.w[0] * t7 * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = t10 * atan2(t9, c_minus_b);
    const T t11 = T(1) / D;
    const T t12 = T(1) / q1;
    const T t13 = t12 * t12;
    const T t14 = T(1) / c;
    const T t15 = t14 * t14;
    const T t16 = b * t14 + a * J2 + a_minus_b * t12;
    const T t17 = T(2) * a_minus_b * t13 + T(2) * b * t15 + T(3) * t11 * a * t16;
    const T t18 = T(2) * t13 - T(2) * t15 - t11 * t17 * b;
    const T t19 = T(1) / a;
    G_ap = (T(1) / T(8)) * in.w[0] * t11 * t17 - (T(1) / T(8)) * t18 * t19 * in.w[1];
    G_ab = (T(1) / T(8)) * t19 * (T(4) * t11 * t16 - t11 * t17 * c - T(2) * t18 * t19 * b) * in.w[1] - (T(1) / T(8)) * in.w[0] * t18 * t19;
  }
  const T g_factor = -T(4) * in.s * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 47 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / q1;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t2 * t2;
    const T t6 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t7 = b * t4 + a_minus_b * t5 - T(4) * t6 * D;
    const T t8 = T(1) / a;
    F = -(T(1) / T(6)) * (T(3) * t2 + T(2) * b * t7 * t8 - T(3) * t3) * in.w[1] * t8 - (T(1) / T(3)) * t7 * in.w[0] * t8;
    const T t9 = T(4) * b * t6 + t4 - t5;
    G_ap = t6 * in.w[0] + (T(1) / T(4)) * t9 * in.w[1] * t8;
    G_ab = (T(1) / T(4)) * t9 * in.w[0] * t8 - (T(1) / T(6)) * (T(6) * t6 * c + T(2) * t7 * t8 - T(3) * b * t9 * t8) * in.w[1] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / q1;
    const T t13 = T(1) / c;
    const T t14 = a_minus_b * t12 + J2 * a + b * t13;
    const T t15 = T(1) / D;
    const T t16 = T(1) / a;
    F = (T(1) / T(2)) * in.w[0] * t14 * t15 + (T(1) / T(2)) * (b * t14 * t15 + t13 - t12) * in.w[1] * t16;
    const T t17 = t13 * t13;
    const T t18 = t12 * t12;
    const T t19 = T(2) * b * t17 + T(3) * t14 * t15 * a + T(2) * a_minus_b * t18;
    const T t20 = b * t19 * t15 + T(2) * t17 - T(2) * t18;
    G_ap = (T(1) / T(8)) * t20 * in.w[1] * t16 + (T(1) / T(8)) * in.w[0] * t19 * t15;
    G_ab = (T(1) / T(8)) * in.w[0] * t20 * t16 + (T(1) / T(8)) * (T(2) * b * t20 * t16 + T(4) * t14 * t15 - c * t19 * t15) * in.w[1] * t16;
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 39 +, 60 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = T(1) / c;
    const T t5 = t3 - t4 - T(2) * b * t2;
    const T t6 = T(1) / a;
    F = in.w[0] * t2 - (b * t5 * t6 + c * t2 - (T(2) * t2 * D - b * t4 - a_minus_b * t3) * t6) * t6 * in.w[2] - (T(1) / T(2)) * t5 * in.w[1] * t6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = sqrt(D);
    const T t8 = T(1) / t7;
    const T J2 = atan2(t7, c_minus_b) * t8;
    const T t9 = T(1) / c;
    const T t10 = T(1) / q1;
    const T t11 = J2 * a + b * t9 + a_minus_b * t10;
    const T t12 = T(1) / D;
    const T t13 = T(1) / a;
    const T t14 = t10 - t9 - b * t11 * t12;
    F = (T(1) / T(2)) * (T(2) * J2 - c * t11 * t12 - T(2) * b * t13 * t14) * t13 * in.w[2] + (T(1) / T(2)) * in.w[0] * t11 * t12 - (T(1) / T(2)) * in.w[1] * t13 * t14;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 50 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i4_w2_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = t2 * t2;
    const T t4 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t3 + T(4) * b * t4 - t6;
    const T t8 = T(1) / a;
    const T t9 = b * t3 + t6 * a_minus_b - T(4) * t4 * D;
    const T t10 = T(6) * t4 * c + T(2) * t9 * t8 - T(3) * b * t7 * t8;
    G_ap = (T(1) / T(4)) * t7 * in.w[1] * t8 + t4 * in.w[0] - (T(1) / T(6)) * t10 * in.w[2] * t8;
    G_ab = (T(1) / T(4)) * in.w[0] * t7 * t8 - (T(1) / T(12)) * (T(2) * (T(3) * t5 + T(2) * b * t9 * t8 - T(3) * t2) * t8 + T(4) * t10 * b * t8 + T(3) * t7 * c * t8) * in.w[2] * t8 - (T(1) / T(6)) * t10 * in.w[1] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / q1;
    const T t14 = T(1) / c;
    const T t15 = t13 * a_minus_b + J2 * a + b * t14;
    const T t16 = T(1) / D;
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = T(2) * b * t17 + T(2) * t18 * a_minus_b + T(3) * t15 * t16 * a;
    const T t20 = t19 * b * t16 + T(2) * t17 - T(2) * t18;
    const T t21 = T(1) / a;
    const T t22 = T(4) * t15 * t16 + T(2) * b * t20 * t21 - t19 * c * t16;
    G_ap = (T(1) / T(8)) * t22 * in.w[2] * t21 + (T(1) / T(8)) * t19 * in.w[0] * t16 + (T(1) / T(8)) * t20 * in.w[1] * t21;
    G_ab = (T(1) / T(8)) * t22 * in.w[1] * t21 + (T(1) / T(8)) * in.w[0] * t20 * t21 - (T(1) / T(8)) * (t20 * c * t21 - T(4) * t21 * (b * t15 * t16 + t14 - t13) - T(2) * t22 * b * t21) * in.w[2] * t21;
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 54 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t2 * t2;
    const T t6 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t7 = t4 * a_minus_b + b * t5 - T(4) * t6 * D;
    const T t8 = T(1) / a;
    const T t9 = T(3) * t2 - T(3) * t3 - T(2) * b * t7 * t8;
    F = (T(1) / T(6)) * t9 * in.w[1] * t8 - (T(1) / T(3)) * ((T(3) * b * t2 + T(2) * t7 * D * t8 + T(3) * t3 * a_minus_b) * t8 - c * t7 * t8 - b * t9 * t8) * t8 * in.w[2] - (T(1) / T(3)) * in.w[0] * t7 * t8;
    const T t10 = T(4) * b * t6 + t5 - t4;
    const T t11 = T(6) * t6 * c + T(2) * t7 * t8 - T(3) * b * t8 * t10;
    G_ap = (T(1) / T(4)) * in.w[1] * t8 * t10 + t6 * in.w[0] - (T(1) / T(6)) * t8 * in.w[2] * t11;
    G_ab = (T(1) / T(4)) * in.w[0] * t8 * t10 + (T(1) / T(12)) * (T(2) * t9 * t8 - T(3) * c * t8 * t10 - T(4) * b * t8 * t11) * t8 * in.w[2] - (T(1) / T(6)) * in.w[1] * t8 * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / c;
    const T t15 = T(1) / q1;
    const T t16 = J2 * a + b * t14 + t15 * a_minus_b;
    const T t17 = T(1) / D;
    const T t18 = T(1) / a;
    const T t19 = t14 + b * t16 * t17 - t15;
    F = (T(1) / T(2)) * t16 * in.w[0] * t17 + (T(1) / T(2)) * in.w[1] * t18 * t19 + (T(1) / T(2)) * (T(2) * b * t18 * t19 + T(2) * J2 - t16 * c * t17) * t18 * in.w[2];
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    const T t22 = T(3) * t16 * t17 * a + T(2) * t20 * a_minus_b + T(2) * b * t21;
    const T t23 = b * t17 * t22 + T(2) * t21 - T(2) * t20;
    const T t24 = T(4) * t16 * t17 + T(2) * b * t23 * t18 - c * t17 * t22;
    G_ap = (T(1) / T(8)) * in.w[1] * t23 * t18 + (T(1) / T(8)) * t24 * t18 * in.w[2] + (T(1) / T(8)) * in.w[0] * t17 * t22;
    G_ab = (T(1) / T(8)) * in.w[1] * t24 * t18 + (T(1) / T(8)) * in.w[0] * t23 * t18 + (T(1) / T(8)) * (T(4) * t18 * t19 + T(2) * b * t24 * t18 - c * t23 * t18) * t18 * in.w[2];
  }
  const T g_factor = -T(4) * length * in.s;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 43 +, 72 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w3_f(const SegmentInput<T>& in) {
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
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(t0 * q1);
  T F;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(1) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.02 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 - T(2) * t3 * b - t0;
    const T t7 = b * t0;
    const T t8 = a_minus_b * t5;
    const T t9 = t7 + t8 - T(2) * D * t3;
    const T t10 = t4 * b * t6 + t3 * c + t4 * t9;
    F = in.w[0] * t3 - (T(1) / T(2)) * in.w[3] * t4 * (T(4) * t4 * t10 * b - t4 * t6 * c - t4 * (log_ratio - T(2) * t4 * t9 * b)) - (T(1) / T(2)) * t4 * in.w[1] * t6 - t4 * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = b * t0;
    const T t16 = T(1) / q1;
    const T t17 = a_minus_b * t16;
    const T t18 = t15 + a * J2 + t17;
    const T t19 = t14 * b * t18 + t0 - t16;
    const T t20 = T(2) * J2 + T(2) * t13 * b * t19 - t14 * t18 * c;
    F = (T(1) / T(2)) * t13 * t20 * in.w[2] + (T(1) / T(2)) * t13 * in.w[1] * t19 + (T(1) / T(2)) * t14 * in.w[0] * t18 + (T(1) / T(2)) * in.w[3] * t13 * (T(2) * t13 * t20 * b + t13 * (T(2) * J2 * b + log_ratio) - t13 * t19 * c);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 56 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i4_w3_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t5 + T(4) * t2 * b - t7;
    const T t9 = a_minus_b * t7 + b * t5 - T(4) * D * t2;
    const T t10 = T(2) * t3 * t9 + T(6) * t2 * c - T(3) * t3 * b * t8;
    const T t11 = T(3) * t6 + T(2) * t3 * b * t9 - T(3) * t4;
    const T t12 = T(3) * t3 * c * t8 + T(4) * t3 * b * t10 + T(2) * t3 * t11;
    G_ap = in.w[0] * t2 + (T(1) / T(4)) * t3 * in.w[1] * t8 - (T(1) / T(6)) * t3 * t10 * in.w[2] - (T(1) / T(12)) * t12 * t3 * in.w[3];
    G_ab = (T(1) / T(4)) * t3 * in.w[0] * t8 - (T(1) / T(6)) * t3 * t10 * in.w[1] - (T(1) / T(12)) * t12 * t3 * in.w[2] - (T(1) / T(6)) * t3 * in.w[3] * (t12 * t3 * b - T(2) * t3 * (t3 * t9 * c - t3 * b * t11 - (T(3) * b * t4 + T(2) * D * t3 * t9 + T(3) * a_minus_b * t6) * t3) - t3 * t10 * c);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / a;
    const T t16 = T(1) / c;
    const T t17 = t16 * t16;
    const T t18 = T(1) / D;
    const T t19 = T(1) / q1;
    const T t20 = b * t16 + a * J2 + a_minus_b * t19;
    const T t21 = t19 * t19;
    const T t22 = T(3) * t18 * a * t20 + T(2) * a_minus_b * t21 + T(2) * b * t17;
    const T t23 = T(2) * t17 + t18 * b * t22 - T(2) * t21;
    const T t24 = T(4) * t18 * t20 + T(2) * t15 * b * t23 - t18 * t22 * c;
    const T t25 = t19 - t18 * t20 * b - t16;
    const T t26 = T(2) * t15 * b * t24 - T(4) * t15 * t25 - t15 * c * t23;
    G_ap = (T(1) / T(8)) * t15 * in.w[1] * t23 + (T(1) / T(8)) * t15 * in.w[3] * t26 + (T(1) / T(8)) * t15 * t24 * in.w[2] + (T(1) / T(8)) * t18 * in.w[0] * t22;
    G_ab = (T(1) / T(8)) * t15 * t26 * in.w[2] + (T(1) / T(8)) * t15 * in.w[1] * t24 + (T(1) / T(8)) * t15 * in.w[0] * t23 - (T(1) / T(8)) * t15 * in.w[3] * (t15 * t24 * c + T(4) * t15 * (t18 * t20 * c + T(2) * t15 * b * t25 - T(2) * J2) - T(2) * t15 * b * t26);
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 62 +, 141 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
template <class T>
T segment_cauchy_i4_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t0 * t0;
    const T t7 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t8 = a_minus_b * t5 + b * t6 - T(4) * D * t7;
    const T t9 = T(3) * t0 - T(3) * t4 - T(2) * t3 * t8 * b;
    const T t10 = T(2) * D * t3 * t8 + T(3) * b * t0 + T(3) * a_minus_b * t4;
    const T t11 = t10 * t3 - t3 * t9 * b - t3 * t8 * c;
    F = (T(1) / T(6)) * t3 * t9 * in.w[1] - (T(1) / T(6)) * in.w[3] * t3 * (T(4) * t3 * b * t11 + t3 * t9 * c - t3 * (T(3) * log_ratio - T(2) * t10 * t3 * b)) - (T(1) / T(3)) * t3 * in.w[0] * t8 - (T(1) / T(3)) * t3 * t11 * in.w[2];
    const T t12 = t5 - t6 - T(4) * b * t7;
    const T t13 = T(3) * t3 * t12 * b + T(6) * t7 * c + T(2) * t3 * t8;
    const T t14 = T(3) * t3 * t12 * c + T(2) * t3 * t9 - T(4) * t3 * b * t13;
    G_ap = (T(1) / T(12)) * in.w[3] * t3 * t14 + in.w[0] * t7 - (T(1) / T(4)) * t3 * t12 * in.w[1] - (T(1) / T(6)) * t3 * t13 * in.w[2];
    G_ab = (T(1) / T(12)) * t3 * t14 * in.w[2] - (T(1) / T(6)) * in.w[3] * t3 * (T(2) * t3 * t11 - t3 * t14 * b - t3 * t13 * c) - (T(1) / T(4)) * t3 * in.w[0] * t12 - (T(1) / T(6)) * t3 * in.w[1] * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / a;
    const T t18 = T(1) / D;
    const T t19 = T(1) / q1;
    const T t20 = a * J2 + b * t0 + a_minus_b * t19;
    const T t21 = t0 + t18 * t20 * b - t19;
    const T t22 = T(2) * t17 * b * t21 + T(2) * J2 - t18 * t20 * c;
    F = (T(1) / T(2)) * t17 * in.w[1] * t21 + (T(1) / T(2)) * in.w[3] * t17 * (t17 * (T(2) * b * J2 + log_ratio) + T(2) * t17 * t22 * b - t17 * c * t21) + (T(1) / T(2)) * t17 * t22 * in.w[2] + (T(1) / T(2)) * t18 * in.w[0] * t20;
    const T t23 = t19 * t19;
    const T t24 = t0 * t0;
    const T t25 = T(2) * a_minus_b * t23 + T(2) * b * t24 + T(3) * t18 * a * t20;
    const T t26 = t18 * b * t25 + T(2) * t24 - T(2) * t23;
    const T t27 = T(4) * t18 * t20 + T(2) * t17 * t26 * b - t18 * t25 * c;
    const T t28 = t17 * t26 * c - T(2) * t17 * t27 * b - T(4) * t17 * t21;
    G_ap = (T(1) / T(8)) * t17 * t27 * in.w[2] + (T(1) / T(8)) * t18 * in.w[0] * t25 + (T(1) / T(8)) * t17 * t26 * in.w[1] - (T(1) / T(8)) * in.w[3] * t17 * t28;
    G_ab = (T(1) / T(8)) * t17 * t27 * in.w[1] + (T(1) / T(8)) * t17 * in.w[0] * t26 - (T(1) / T(8)) * t17 * t28 * in.w[2] - (T(1) / T(8)) * in.w[3] * t17 * (t17 * t27 * c + T(2) * t17 * b * t28 - T(4) * t17 * t22);
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 31 +, 45 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w0_f(const SegmentInput<T>& in) {
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    F = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    F = (T(1) / T(3)) * t2 * (a_minus_b * t3 / q1 + t4 * b / c + T(2) * t2 * a * (t4 * b + a_minus_b * t3)) * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 38 +, 79 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i5_w0_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / a;
    G_ab = (T(1) / T(5)) * (t3 * t5 + T(5) * t2 * b - t6 * t8) * t9 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / r0;
    const T t11 = t10 * t10;
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = T(1) / D;
    const T t15 = t13 * t13;
    const T t16 = t11 * t11;
    const T t17 = T(4) * a * (t10 * t11 * b + t12 * a_minus_b * t13 + T(2) * (t10 * b + t12 * a_minus_b) * a * t14) * t14 + T(3) * t12 * a_minus_b * t15 + T(3) * t10 * t16 * b;
    G_ap = (T(1) / T(15)) * t17 * t14 * in.w[0];
    const T t18 = T(1) / a;
    G_ab = (T(1) / T(15)) * (T(3) * t10 * t16 + t17 * t14 * b - T(3) * t12 * t15) * t18 * in.w[0];
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 38 +, 83 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / a;
    F = -(T(1) / T(4)) * (t4 * t2 * b + t5 * a_minus_b * t7 - T(5) * t8 * D) * in.w[0] * t9;
    G_ap = t8 * in.w[0];
    G_ab = -(T(1) / T(5)) * in.w[0] * t9 * (t5 * t7 - t4 * t2 - T(5) * t8 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / D;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t11 * a_minus_b * t12 + t14 * t13 * b + T(2) * (t13 * b + t11 * a_minus_b) * t10 * a;
    F = (T(1) / T(3)) * t10 * t15 * in.w[0];
    const T t16 = t14 * t14;
    const T t17 = t12 * t12;
    const T t18 = T(3) * t16 * t13 * b + T(3) * t11 * a_minus_b * t17 + T(4) * t10 * t15 * a;
    G_ap = (T(1) / T(15)) * t10 * t18 * in.w[0];
    const T t19 = T(1) / a;
    G_ab = -(T(1) / T(15)) * (T(3) * t11 * t17 - t10 * t18 * b - T(3) * t16 * t13) * in.w[0] * t19;
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 34 +, 56 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w1_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t3 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / a;
    F = (T(1) / T(3)) * in.w[1] * (T(3) * b * t2 + t5 - t6 * t7) * t8 + in.w[0] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = T(1) / D;
    const T t14 = a_minus_b * t9 * t10 + t11 * b * t12 + T(2) * (t11 * b + a_minus_b * t9) * t13 * a;
    const T t15 = t11 * t12;
    const T t16 = T(1) / a;
    F = (T(1) / T(3)) * t14 * in.w[0] * t13 + (T(1) / T(3)) * in.w[1] * (t14 * b * t13 + t15 - t9 * t10) * t16;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 42 +, 92 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i5_w1_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t4 * t6 - T(5) * b * t2 - t7 * t9;
    G_ap = in.w[0] * t2 - (T(1) / T(5)) * t3 * in.w[1] * t10;
    G_ab = -(T(1) / T(5)) * in.w[0] * t3 * t10 - (T(1) / T(20)) * t3 * in.w[1] * (T(8) * t3 * t10 * b + T(20) * t2 * c - T(5) * t3 * (T(5) * D * t2 - t4 * a_minus_b * t6 - b * t7 * t9));
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = T(1) / D;
    const T t16 = t11 * a_minus_b * t12 + b * t13 * t14 + T(2) * a * t15 * (b * t13 + t11 * a_minus_b);
    const T t17 = t12 * t12;
    const T t18 = t14 * t14;
    const T t19 = T(4) * t16 * a * t15 + T(3) * t11 * a_minus_b * t17 + T(3) * b * t13 * t18;
    const T t20 = T(1) / a;
    const T t21 = T(3) * t11 * t17 - t19 * t15 * b - T(3) * t13 * t18;
    G_ap = (T(1) / T(15)) * in.w[0] * t19 * t15 - (T(1) / T(15)) * t20 * in.w[1] * t21;
    G_ab = -(T(1) / T(15)) * t20 * (t19 * t15 * c + T(2) * t20 * b * t21 - T(5) * t16 * t15) * in.w[1] - (T(1) / T(15)) * in.w[0] * t20 * t21;
  }
  const T g_factor = -T(5) * in.s * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 45 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t4 * t4;
    const T t8 = t6 * t6;
    const T t9 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t10 = t7 * t3 * b + t8 * t5 * a_minus_b - T(5) * D * t9;
    F = (T(1) / T(12)) * in.w[1] * t2 * (T(4) * t4 * t3 - T(4) * t6 * t5 - T(3) * t2 * t10 * b) - (T(1) / T(4)) * in.w[0] * t2 * t10;
    const T t11 = t7 * t3 + T(5) * t9 * b - t8 * t5;
    G_ap = in.w[0] * t9 + (T(1) / T(5)) * in.w[1] * t2 * t11;
    G_ab = (T(1) / T(5)) * in.w[0] * t2 * t11 + (T(1) / T(20)) * in.w[1] * (T(8) * t2 * t11 * b - T(5) * t2 * t10 - T(20) * c * t9) * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / D;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t14 * t13 * a_minus_b + T(2) * (t15 * b + t13 * a_minus_b) * t12 * a + t16 * t15 * b;
    const T t18 = T(1) / a;
    F = (T(1) / T(3)) * in.w[0] * t12 * t17 + (T(1) / T(3)) * in.w[1] * (t12 * t17 * b + t16 * t15 - t14 * t13) * t18;
    const T t19 = t16 * t16;
    const T t20 = t14 * t14;
    const T t21 = T(3) * t19 * t15 * b + T(4) * t12 * a * t17 + T(3) * t20 * t13 * a_minus_b;
    const T t22 = t21 * t12 * b + T(3) * t19 * t15 - T(3) * t20 * t13;
    G_ap = (T(1) / T(15)) * in.w[0] * t21 * t12 + (T(1) / T(15)) * in.w[1] * t22 * t18;
    G_ab = (T(1) / T(15)) * in.w[0] * t22 * t18 - (T(1) / T(15)) * in.w[1] * (t21 * c * t12 - T(2) * t22 * t18 * b - T(5) * t12 * t17) * t18;
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 37 +, 66 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w2_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t6 - t7 * t8 - T(3) * b * t2;
    F = in.w[0] * t2 - (T(1) / T(3)) * in.w[1] * t3 * t9 - (T(1) / T(6)) * (T(6) * t2 * c + T(4) * t3 * b * t9 - T(3) * t3 * (T(3) * D * t2 - t5 * t4 * a_minus_b - t7 * b * t8)) * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / D;
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 * a_minus_b + t12 * b;
    const T t14 = t11 * t11;
    const T t15 = t12 * t12;
    const T t16 = T(2) * t10 * a * t13 + t14 * t11 * a_minus_b + t12 * b * t15;
    const T t17 = T(1) / a;
    const T t18 = t14 * t11;
    const T t19 = t18 - t12 * t15 - t10 * t16 * b;
    F = (T(1) / T(3)) * t10 * t16 * in.w[0] - (T(1) / T(3)) * t17 * in.w[2] * (T(2) * t19 * t17 * b + t10 * t16 * c - T(3) * t10 * t13) - (T(1) / T(3)) * in.w[1] * t19 * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 48 +, 109 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i5_w2_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(5) * t2 * b + t3 * t5 - t8 * t6;
    const T t10 = T(1) / a;
    const T t11 = t8 * t6 * a_minus_b + b * t3 * t5 - T(5) * D * t2;
    const T t12 = T(20) * t2 * c + T(5) * t11 * t10 - T(8) * t9 * t10 * b;
    G_ap = t2 * in.w[0] + (T(1) / T(5)) * t9 * t10 * in.w[1] - (T(1) / T(20)) * in.w[2] * t10 * t12;
    G_ab = (T(1) / T(60)) * in.w[2] * t10 * (T(5) * t10 * (T(4) * t3 * t4 - T(4) * t7 * t6 - T(3) * t11 * t10 * b) - T(12) * t9 * t10 * c - T(6) * t10 * b * t12) + (T(1) / T(5)) * t9 * t10 * in.w[0] - (T(1) / T(20)) * t10 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / D;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = b * t14 * t15 + T(2) * t13 * a * (b * t14 + t16 * a_minus_b) + t17 * t16 * a_minus_b;
    const T t19 = t17 * t17;
    const T t20 = t15 * t15;
    const T t21 = T(4) * t13 * a * t18 + T(3) * t19 * t16 * a_minus_b + T(3) * b * t14 * t20;
    const T t22 = T(1) / a;
    const T t23 = T(3) * t19 * t16 - T(3) * t14 * t20 - t13 * t21 * b;
    const T t24 = T(2) * t22 * b * t23 + t13 * t21 * c - T(5) * t13 * t18;
    G_ap = (T(1) / T(15)) * t13 * t21 * in.w[0] - (T(1) / T(15)) * t22 * in.w[1] * t23 - (T(1) / T(15)) * in.w[2] * t22 * t24;
    G_ab = (T(1) / T(15)) * in.w[2] * t22 * (t22 * t23 * c + T(5) * (t14 * t15 + t13 * b * t18 - t17 * t16) * t22 - T(2) * t22 * t24 * b) - (T(1) / T(15)) * t22 * in.w[0] * t23 - (T(1) / T(15)) * t22 * t24 * in.w[1];
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 52 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t3 * t3;
    const T t8 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t9 = t6 * t4 * b + a_minus_b * t2 * t7 - T(5) * D * t8;
    const T t10 = T(1) / a;
    const T t11 = T(4) * t2 * t3 + T(3) * t9 * t10 * b - T(4) * t5 * t4;
    F = -(T(1) / T(12)) * in.w[1] * t11 * t10 - (T(1) / T(24)) * (T(3) * (T(4) * t5 * t4 * b + T(4) * a_minus_b * t2 * t3 + T(3) * D * t9 * t10) * t10 + T(4) * t11 * t10 * b - T(6) * c * t9 * t10) * t10 * in.w[2] - (T(1) / T(4)) * t9 * t10 * in.w[0];
    const T t12 = T(5) * t8 * b + t6 * t4 - t2 * t7;
    const T t13 = T(8) * t12 * t10 * b - T(5) * t9 * t10 - T(20) * c * t8;
    G_ap = (T(1) / T(20)) * t13 * t10 * in.w[2] + t8 * in.w[0] + (T(1) / T(5)) * in.w[1] * t12 * t10;
    G_ab = (T(1) / T(5)) * t12 * t10 * in.w[0] + (T(1) / T(20)) * in.w[1] * t13 * t10 + (T(1) / T(60)) * t10 * (T(6) * t13 * t10 * b - T(5) * t11 * t10 - T(12) * c * t12 * t10) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = t15 * b + a_minus_b * t16;
    const T t18 = t15 * t15;
    const T t19 = t16 * t16;
    const T t20 = T(2) * t14 * a * t17 + t18 * t15 * b + a_minus_b * t16 * t19;
    const T t21 = T(1) / a;
    const T t22 = t16 * t19 - t14 * t20 * b - t18 * t15;
    F = (T(1) / T(3)) * t14 * t20 * in.w[0] - (T(1) / T(3)) * in.w[1] * t21 * t22 - (T(1) / T(3)) * t21 * in.w[2] * (T(2) * t21 * b * t22 + c * t14 * t20 - T(3) * t14 * t17);
    const T t23 = t18 * t18;
    const T t24 = t19 * t19;
    const T t25 = T(3) * t23 * t15 * b + T(3) * a_minus_b * t16 * t24 + T(4) * t14 * a * t20;
    const T t26 = t25 * t14 * b + T(3) * t23 * t15 - T(3) * t16 * t24;
    const T t27 = T(2) * t26 * t21 * b + T(5) * t14 * t20 - c * t25 * t14;
    G_ap = (T(1) / T(15)) * t25 * t14 * in.w[0] + (T(1) / T(15)) * t26 * in.w[1] * t21 + (T(1) / T(15)) * t21 * t27 * in.w[2];
    G_ab = (T(1) / T(15)) * t26 * t21 * in.w[0] + (T(1) / T(15)) * (T(2) * t21 * t27 * b - c * t26 * t21 - T(5) * t21 * t22) * t21 * in.w[2] + (T(1) / T(15)) * in.w[1] * t21 * t27;
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 42 +, 78 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i5_w3_f(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.06 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t5 + T(3) * t2 * b - t7 * t6;
    const T t9 = T(1) / a;
    const T t10 = T(3) * t2 * D - t4 * t3 * b - a_minus_b * t7 * t6;
    const T t11 = T(6) * t2 * c - T(4) * t8 * t9 * b - T(3) * t9 * t10;
    F = t2 * in.w[0] + (T(1) / T(3)) * t8 * t9 * in.w[1] - (T(1) / T(6)) * in.w[2] * t9 * t11 - (T(1) / T(6)) * (T(3) * (T(2) * t6 - t9 * t10 * b - T(2) * t3) * t9 + T(2) * t9 * b * t11 + T(2) * c * t8 * t9) * in.w[3] * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / D;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = a_minus_b * t13 + t14 * b;
    const T t16 = t14 * t14;
    const T t17 = t13 * t13;
    const T t18 = T(2) * t15 * t12 * a + t16 * t14 * b + a_minus_b * t17 * t13;
    const T t19 = T(1) / a;
    const T t20 = t16 * t14;
    const T t21 = t12 * b * t18 + t20 - t17 * t13;
    const T t22 = T(3) * t15 * t12 + T(2) * t19 * t21 * b - c * t12 * t18;
    F = (T(1) / T(3)) * t12 * in.w[0] * t18 + (T(1) / T(3)) * in.w[2] * t22 * t19 + (T(1) / T(3)) * in.w[3] * t19 * (T(3) * t19 * (t15 * t12 * b + t14 - t13) + T(2) * t22 * t19 * b - c * t19 * t21) + (T(1) / T(3)) * t19 * t21 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 54 +, 129 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i5_w3_grad(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t2 * t4 + T(5) * t5 * b - t6 * t8;
    const T t10 = T(1) / a;
    const T t11 = t2 * t4 * b + t6 * a_minus_b * t8 - T(5) * D * t5;
    const T t12 = T(8) * t9 * t10 * b - T(20) * c * t5 - T(5) * t10 * t11;
    const T t13 = T(4) * t6 * t7 + T(3) * t10 * b * t11 - T(4) * t2 * t3;
    const T t14 = T(5) * t13 * t10 + T(12) * t9 * c * t10 - T(6) * t10 * t12 * b;
    G_ap = (T(1) / T(5)) * in.w[1] * t9 * t10 + in.w[0] * t5 + (T(1) / T(20)) * in.w[2] * t10 * t12 - (T(1) / T(60)) * t14 * t10 * in.w[3];
    G_ab = (T(1) / T(5)) * t9 * t10 * in.w[0] + (T(1) / T(20)) * in.w[1] * t10 * t12 - (T(1) / T(120)) * (T(4) * t14 * t10 * b + T(5) * (T(4) * t13 * t10 * b + T(3) * t10 * (T(3) * D * t10 * t11 + T(4) * t6 * a_minus_b * t7 + T(4) * t2 * t3 * b) - T(6) * c * t10 * t11) * t10 + T(6) * c * t10 * t12) * t10 * in.w[3] - (T(1) / T(60)) * in.w[2] * t14 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / a;
    const T t16 = T(1) / D;
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = t17 * b + t18 * a_minus_b;
    const T t20 = t18 * t18;
    const T t21 = t17 * t17;
    const T t22 = T(2) * t16 * a * t19 + t18 * a_minus_b * t20 + t17 * t21 * b;
    const T t23 = t21 * t21;
    const T t24 = t20 * t20;
    const T t25 = T(4) * t22 * t16 * a + T(3) * t17 * t23 * b + T(3) * t18 * a_minus_b * t24;
    const T t26 = t25 * t16 * b + T(3) * t17 * t23 - T(3) * t18 * t24;
    const T t27 = T(2) * t15 * b * t26 + T(5) * t22 * t16 - c * t25 * t16;
    const T t28 = t18 * t20 - t22 * t16 * b - t17 * t21;
    const T t29 = c * t15 * t26 + T(5) * t28 * t15 - T(2) * t27 * t15 * b;
    G_ap = (T(1) / T(15)) * t27 * in.w[2] * t15 + (T(1) / T(15)) * in.w[1] * t15 * t26 + (T(1) / T(15)) * t25 * t16 * in.w[0] - (T(1) / T(15)) * t29 * t15 * in.w[3];
    G_ab = (T(1) / T(15)) * t15 * in.w[0] * t26 + (T(1) / T(15)) * in.w[1] * t27 * t15 - (T(1) / T(15)) * in.w[2] * t29 * t15 - (T(1) / T(15)) * (T(2) * t29 * t15 * b + T(5) * (T(2) * t28 * t15 * b + c * t22 * t16 - T(3) * t16 * t19) * t15 + t27 * c * t15) * t15 * in.w[3];
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 61 +, 151 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 60 +, 153 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh, 1 other.
template <class T>
T segment_cauchy_i5_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t10 = t3 * a_minus_b * t5 + t8 * t6 * b - T(5) * D * t9;
    const T t11 = T(4) * t7 * t6 * b + T(3) * t2 * D * t10 + T(4) * t3 * a_minus_b * t4;
    const T t12 = T(4) * t3 * t4 + T(3) * t2 * b * t10 - T(4) * t7 * t6;
    const T t13 = T(3) * t2 * t11 + T(4) * t2 * t12 * b - T(6) * c * t2 * t10;
    F = -(T(1) / T(4)) * t2 * in.w[0] * t10 - (T(1) / T(24)) * t2 * in.w[3] * (T(3) * t2 * (T(8) * t3 + t2 * t11 * b - T(8) * t6) + T(2) * t2 * t13 * b - T(2) * c * t2 * t12) - (T(1) / T(24)) * in.w[2] * t2 * t13 - (T(1) / T(12)) * t2 * t12 * in.w[1];
    const T t14 = T(5) * b * t9 + t8 * t6 - t3 * t5;
    const T t15 = T(5) * t2 * t10 + T(20) * c * t9 - T(8) * t2 * t14 * b;
    const T t16 = T(5) * t2 * t12 + T(6) * t2 * t15 * b + T(12) * c * t2 * t14;
    G_ap = in.w[0] * t9 + (T(1) / T(5)) * t2 * t14 * in.w[1] - (T(1) / T(20)) * in.w[2] * t2 * t15 - (T(1) / T(60)) * t2 * in.w[3] * t16;
    G_ab = (T(1) / T(5)) * t2 * in.w[0] * t14 - (T(1) / T(60)) * in.w[2] * t2 * t16 - (T(1) / T(120)) * t2 * in.w[3] * (T(5) * t2 * t13 + T(4) * t2 * b * t16 - T(6) * c * t2 * t15) - (T(1) / T(20)) * t2 * t15 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = T(1) / D;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = t19 * b + t20 * a_minus_b;
    const T t22 = t20 * t20;
    const T t23 = t19 * t19;
    const T t24 = T(2) * a * t18 * t21 + t23 * t19 * b + t20 * a_minus_b * t22;
    const T t25 = t20 * t22 - t23 * t19 - t18 * b * t24;
    const T t26 = T(2) * t17 * b * t25 + c * t18 * t24 - T(3) * t18 * t21;
    F = (T(1) / T(3)) * t17 * (T(3) * t17 * (t18 * b * t21 + t19 - t20) + c * t17 * t25 - T(2) * t17 * b * t26) * in.w[3] + (T(1) / T(3)) * t18 * in.w[0] * t24 - (T(1) / T(3)) * t17 * t25 * in.w[1] - (T(1) / T(3)) * in.w[2] * t17 * t26;
    const T t27 = t22 * t22;
    const T t28 = t23 * t23;
    const T t29 = T(3) * t20 * a_minus_b * t27 + T(4) * a * t18 * t24 + T(3) * t28 * t19 * b;
    const T t30 = t18 * b * t29 + T(3) * t28 * t19 - T(3) * t20 * t27;
    const T t31 = T(2) * t17 * t30 * b + T(5) * t18 * t24 - c * t18 * t29;
    const T t32 = T(2) * t17 * b * t31 - T(5) * t17 * t25 - c * t17 * t30;
    G_ap = (T(1) / T(15)) * t17 * t32 * in.w[3] + (T(1) / T(15)) * t17 * t30 * in.w[1] + (T(1) / T(15)) * t18 * in.w[0] * t29 + (T(1) / T(15)) * in.w[2] * t17 * t31;
    G_ab = (T(1) / T(15)) * in.w[2] * t17 * t32 + (T(1) / T(15)) * t17 * t31 * in.w[1] + (T(1) / T(15)) * t17 * in.w[0] * t30 + (T(1) / T(15)) * t17 * in.w[3] * (T(2) * t17 * t32 * b - c * t17 * t31 - T(5) * t17 * t26);
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 35 +, 55 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w0_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    F = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    F = (T(1) / T(8)) * in.w[0] * t4 * (T(3) * t4 * a * (a_minus_b * t5 + a * J2 + t6 * b) + T(2) * t7 * b + T(2) * a_minus_b * t8);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 42 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i6_w0_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / a;
    G_ab = -(T(1) / T(6)) * in.w[0] * (t5 - t8 - T(6) * t2 * b) * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / q1;
    const T t13 = t12 * t12;
    const T t14 = T(1) / c;
    const T t15 = T(1) / D;
    const T t16 = t14 * t14;
    const T t17 = t13 * t12;
    const T t18 = t16 * t14;
    const T t19 = T(5) * (T(2) * t13 * a_minus_b + T(3) * (b * t14 + J2 * a + t12 * a_minus_b) * t15 * a + T(2) * b * t16) * t15 * a + T(8) * t17 * a_minus_b + T(8) * b * t18;
    G_ap = (T(1) / T(48)) * in.w[0] * t19 * t15;
    const T t20 = T(1) / a;
    G_ab = -(T(1) / T(48)) * in.w[0] * (T(8) * t17 - T(8) * t18 - t19 * b * t15) * t20;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 42 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / q1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / a;
    F = -(T(1) / T(5)) * in.w[0] * (a_minus_b * t4 + b * t7 - T(6) * D * t8) * t9;
    G_ap = in.w[0] * t8;
    G_ab = -(T(1) / T(6)) * in.w[0] * (t4 - T(6) * b * t8 - t7) * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, c_minus_b);
    const T t12 = T(1) / D;
    const T t13 = T(1) / c;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = T(3) * t12 * (b * t13 + J2 * a + a_minus_b * t14) * a + T(2) * a_minus_b * t15 + T(2) * b * t16;
    F = (T(1) / T(8)) * in.w[0] * t12 * t17;
    const T t18 = t15 * t14;
    const T t19 = t16 * t13;
    const T t20 = T(8) * a_minus_b * t18 + T(8) * b * t19 + T(5) * t12 * t17 * a;
    G_ap = (T(1) / T(48)) * in.w[0] * t12 * t20;
    const T t21 = T(1) / a;
    G_ab = -(T(1) / T(48)) * in.w[0] * t21 * (T(8) * t18 - t12 * b * t20 - T(8) * t19);
  }
  const T g_factor = -T(6) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 38 +, 62 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w1_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    F = in.w[0] * t2 - (T(1) / T(4)) * t3 * in.w[1] * (t5 - t7 - T(4) * b * t2);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = T(2) * a_minus_b * t12 + T(2) * b * t14 + T(3) * (b * t13 + J2 * a + a_minus_b * t11) * t10 * a;
    const T t16 = T(1) / a;
    F = (T(1) / T(8)) * in.w[0] * t10 * t15 - (T(1) / T(8)) * (T(2) * t12 - b * t10 * t15 - T(2) * t14) * t16 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 46 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i6_w1_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(6) * t2 * b + t6 - t9;
    G_ap = t2 * in.w[0] + (T(1) / T(6)) * t3 * in.w[1] * t10;
    G_ab = (T(1) / T(15)) * (T(5) * t3 * t10 * b - T(3) * t3 * (t6 * b + a_minus_b * t9 - T(6) * t2 * D) - T(15) * c * t2) * t3 * in.w[1] + (T(1) / T(6)) * in.w[0] * t3 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / D;
    const T t14 = T(1) / c;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = T(2) * a_minus_b * t18 + T(2) * t15 * b + T(3) * t13 * a * (J2 * a + a_minus_b * t17 + t14 * b);
    const T t20 = t18 * t17;
    const T t21 = T(8) * t16 * b + T(5) * t13 * t19 * a + T(8) * a_minus_b * t20;
    const T t22 = T(1) / a;
    const T t23 = T(8) * t16 + t13 * t21 * b - T(8) * t20;
    G_ap = (T(1) / T(48)) * in.w[0] * t13 * t21 + (T(1) / T(48)) * t22 * t23 * in.w[1];
    G_ab = (T(1) / T(48)) * in.w[0] * t22 * t23 - (T(1) / T(48)) * (c * t13 * t21 - T(6) * t13 * t19 - T(2) * t22 * t23 * b) * t22 * in.w[1];
  }
  const T g_factor = -T(6) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 49 +, 105 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(6) * t3 * D - t6 * b - t9 * a_minus_b;
    F = (T(1) / T(5)) * in.w[0] * t2 * t10 - (T(1) / T(20)) * (T(5) * t8 - T(5) * t5 - T(4) * t2 * t10 * b) * in.w[1] * t2;
    const T t11 = t9 - T(6) * t3 * b - t6;
    G_ap = t3 * in.w[0] - (T(1) / T(6)) * t11 * in.w[1] * t2;
    G_ab = (T(1) / T(15)) * in.w[1] * t2 * (T(3) * t2 * t10 - T(5) * t11 * t2 * b - T(15) * t3 * c) - (T(1) / T(6)) * t11 * in.w[0] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = T(1) / c;
    const T t17 = t15 * t15;
    const T t18 = t16 * t16;
    const T t19 = T(3) * (J2 * a + t15 * a_minus_b + t16 * b) * t14 * a + T(2) * t17 * a_minus_b + T(2) * t18 * b;
    const T t20 = T(1) / a;
    F = (T(1) / T(8)) * in.w[0] * t14 * t19 + (T(1) / T(8)) * (t14 * t19 * b + T(2) * t18 - T(2) * t17) * in.w[1] * t20;
    const T t21 = t18 * t16;
    const T t22 = t17 * t15;
    const T t23 = T(8) * t21 * b + T(5) * t14 * a * t19 + T(8) * t22 * a_minus_b;
    const T t24 = t14 * b * t23 + T(8) * t21 - T(8) * t22;
    G_ap = (T(1) / T(48)) * in.w[1] * t20 * t24 + (T(1) / T(48)) * in.w[0] * t14 * t23;
    G_ab = (T(1) / T(48)) * in.w[0] * t20 * t24 - (T(1) / T(48)) * (c * t14 * t23 - T(6) * t14 * t19 - T(2) * t20 * t24 * b) * in.w[1] * t20;
  }
  const T g_factor = -T(6) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 41 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w2_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = t2 * t2;
    const T t4 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t3 + T(4) * t4 * b - t6;
    const T t8 = T(1) / a;
    F = (T(1) / T(6)) * (T(3) * t7 * t8 * b - T(2) * t8 * (t3 * b + a_minus_b * t6 - T(4) * D * t4) - T(6) * c * t4) * t8 * in.w[2] + in.w[0] * t4 + (T(1) / T(4)) * in.w[1] * t7 * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / a;
    const T t12 = T(1) / c;
    const T t13 = t12 * t12;
    const T t14 = T(1) / q1;
    const T t15 = a_minus_b * t14 + t12 * b + a * J2;
    const T t16 = T(1) / D;
    const T t17 = t14 * t14;
    const T t18 = T(3) * t15 * t16 * a + T(2) * t13 * b + T(2) * a_minus_b * t17;
    const T t19 = T(2) * t13 + t18 * t16 * b - T(2) * t17;
    F = (T(1) / T(8)) * t11 * in.w[2] * (T(2) * t11 * t19 * b + T(4) * t15 * t16 - c * t18 * t16) + (T(1) / T(8)) * in.w[0] * t18 * t16 + (T(1) / T(8)) * in.w[1] * t11 * t19;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 52 +, 111 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i6_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(6) * b * t3 + t6 - t9;
    const T t11 = T(6) * D * t3 - b * t6 - a_minus_b * t9;
    const T t12 = T(5) * b * t2 * t10 + T(3) * t11 * t2 - T(15) * c * t3;
    G_ap = (T(1) / T(6)) * in.w[1] * t2 * t10 + in.w[0] * t3 + (T(1) / T(15)) * in.w[2] * t2 * t12;
    G_ab = (T(1) / T(15)) * in.w[1] * t2 * t12 + (T(1) / T(6)) * in.w[0] * t2 * t10 + (T(1) / T(60)) * (T(8) * b * t2 * t12 + T(3) * (T(4) * b * t11 * t2 + T(5) * t5 - T(5) * t8) * t2 - T(10) * c * t2 * t10) * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / D;
    const T t16 = T(1) / q1;
    const T t17 = t16 * t16;
    const T t18 = T(1) / c;
    const T t19 = t18 * t18;
    const T t20 = T(2) * a_minus_b * t17 + T(2) * b * t19 + T(3) * (J2 * a + b * t18 + a_minus_b * t16) * t15 * a;
    const T t21 = t19 * t18;
    const T t22 = t17 * t16;
    const T t23 = T(5) * t15 * a * t20 + T(8) * b * t21 + T(8) * a_minus_b * t22;
    const T t24 = T(8) * t21 + b * t15 * t23 - T(8) * t22;
    const T t25 = T(1) / a;
    const T t26 = c * t15 * t23 - T(6) * t15 * t20 - T(2) * t24 * b * t25;
    G_ap = (T(1) / T(48)) * in.w[0] * t15 * t23 + (T(1) / T(48)) * t24 * in.w[1] * t25 - (T(1) / T(48)) * t26 * in.w[2] * t25;
    G_ab = (T(1) / T(48)) * (T(6) * (T(2) * t19 + b * t15 * t20 - T(2) * t17) * t25 - T(2) * t26 * b * t25 - t24 * c * t25) * in.w[2] * t25 + (T(1) / T(48)) * in.w[0] * t24 * t25 - (T(1) / T(48)) * t26 * in.w[1] * t25;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 56 +, 128 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t10 = t5 * a_minus_b + t8 * b - T(6) * D * t9;
    const T t11 = T(5) * t4 + T(4) * t2 * t10 * b - T(5) * t7;
    F = (T(1) / T(30)) * t2 * (T(6) * c * t2 * t10 - T(2) * (T(5) * t4 * a_minus_b + T(5) * t7 * b + T(4) * D * t2 * t10) * t2 - T(3) * t11 * t2 * b) * in.w[2] - (T(1) / T(5)) * t2 * t10 * in.w[0] - (T(1) / T(20)) * t11 * in.w[1] * t2;
    const T t12 = t8 + T(6) * t9 * b - t5;
    const T t13 = T(15) * c * t9 + T(3) * t2 * t10 - T(5) * t12 * t2 * b;
    G_ap = t9 * in.w[0] + (T(1) / T(6)) * t12 * in.w[1] * t2 - (T(1) / T(15)) * t13 * t2 * in.w[2];
    G_ab = (T(1) / T(6)) * t12 * t2 * in.w[0] - (T(1) / T(15)) * t13 * in.w[1] * t2 - (T(1) / T(60)) * (T(8) * t13 * t2 * b + T(3) * t11 * t2 + T(10) * t12 * c * t2) * t2 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, c_minus_b) * t15;
    const T t16 = T(1) / q1;
    const T t17 = t16 * t16;
    const T t18 = T(1) / D;
    const T t19 = T(1) / c;
    const T t20 = t19 * b + t16 * a_minus_b + J2 * a;
    const T t21 = t19 * t19;
    const T t22 = T(2) * t17 * a_minus_b + T(3) * t18 * a * t20 + T(2) * t21 * b;
    const T t23 = T(1) / a;
    const T t24 = T(2) * t17 - T(2) * t21 - t22 * t18 * b;
    F = (T(1) / T(8)) * t22 * t18 * in.w[0] + (T(1) / T(8)) * t23 * in.w[2] * (T(4) * t18 * t20 - c * t22 * t18 - T(2) * t24 * t23 * b) - (T(1) / T(8)) * t24 * in.w[1] * t23;
    const T t25 = t21 * t19;
    const T t26 = t17 * t16;
    const T t27 = T(8) * t26 * a_minus_b + T(5) * t22 * t18 * a + T(8) * t25 * b;
    const T t28 = T(8) * t25 + t18 * b * t27 - T(8) * t26;
    const T t29 = T(6) * t22 * t18 + T(2) * t23 * t28 * b - c * t18 * t27;
    G_ap = (T(1) / T(48)) * in.w[1] * t23 * t28 + (T(1) / T(48)) * t29 * t23 * in.w[2] + (T(1) / T(48)) * t18 * t27 * in.w[0];
    G_ab = (T(1) / T(48)) * t29 * in.w[1] * t23 + (T(1) / T(48)) * t23 * t28 * in.w[0] - (T(1) / T(48)) * (T(6) * t24 * t23 + c * t23 * t28 - T(2) * t29 * t23 * b) * t23 * in.w[2];
  }
  const T g_factor = -T(6) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 46 +, 84 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w3_f(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(4) * t2 * D - a_minus_b * t4 - b * t6;
    const T t8 = T(1) / a;
    const T t9 = t6 + T(4) * t2 * b - t4;
    const T t10 = T(2) * t7 * t8 + T(3) * b * t9 * t8 - T(6) * t2 * c;
    F = t2 * in.w[0] + (T(1) / T(6)) * t10 * in.w[2] * t8 + (T(1) / T(4)) * in.w[1] * t9 * t8 - (T(1) / T(12)) * (T(3) * c * t9 * t8 + T(2) * t8 * (T(3) * t3 - T(3) * t5 - T(2) * b * t7 * t8) - T(4) * b * t10 * t8) * in.w[3] * t8;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / c;
    const T t14 = T(1) / q1;
    const T t15 = b * t13 + a_minus_b * t14 + J2 * a;
    const T t16 = T(1) / D;
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = T(3) * t15 * t16 * a + T(2) * a_minus_b * t17 + T(2) * b * t18;
    const T t20 = T(2) * t18 + t19 * b * t16 - T(2) * t17;
    const T t21 = T(1) / a;
    const T t22 = t19 * c * t16 - T(4) * t15 * t16 - T(2) * t20 * b * t21;
    F = (T(1) / T(8)) * t19 * t16 * in.w[0] + (T(1) / T(8)) * t20 * in.w[1] * t21 - (T(1) / T(8)) * t22 * in.w[2] * t21 - (T(1) / T(8)) * (t20 * c * t21 + T(4) * t21 * (t14 - t13 - b * t15 * t16) + T(2) * b * t22 * t21) * in.w[3] * t21;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 58 +, 131 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i6_w3_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(6) * t2 * b + t5 - t8;
    const T t10 = T(1) / a;
    const T t11 = b * t5 + a_minus_b * t8 - T(6) * D * t2;
    const T t12 = T(5) * t9 * t10 * b - T(15) * t2 * c - T(3) * t10 * t11;
    const T t13 = T(5) * t7 + T(4) * t10 * b * t11 - T(5) * t4;
    const T t14 = T(8) * t10 * b * t12 - T(3) * t13 * t10 - T(10) * t9 * t10 * c;
    G_ap = (T(1) / T(6)) * t9 * t10 * in.w[1] + in.w[0] * t2 + (T(1) / T(15)) * in.w[2] * t10 * t12 + (T(1) / T(60)) * t10 * t14 * in.w[3];
    G_ab = (T(1) / T(60)) * in.w[2] * t10 * t14 + (T(1) / T(6)) * t9 * t10 * in.w[0] + (T(1) / T(15)) * t10 * t12 * in.w[1] - (T(1) / T(30)) * (T(2) * t10 * t12 * c - t10 * t14 * b - t10 * (T(6) * t10 * t11 * c - T(2) * (T(4) * D * t10 * t11 + T(5) * b * t4 + T(5) * a_minus_b * t7) * t10 - T(3) * t13 * t10 * b)) * t10 * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / a;
    const T t18 = T(1) / D;
    const T t19 = T(1) / q1;
    const T t20 = T(1) / c;
    const T t21 = a_minus_b * t19 + b * t20 + a * J2;
    const T t22 = t20 * t20;
    const T t23 = t19 * t19;
    const T t24 = T(3) * t18 * a * t21 + T(2) * b * t22 + T(2) * a_minus_b * t23;
    const T t25 = t22 * t20;
    const T t26 = t23 * t19;
    const T t27 = T(5) * t18 * a * t24 + T(8) * b * t25 + T(8) * a_minus_b * t26;
    const T t28 = t27 * t18 * b + T(8) * t25 - T(8) * t26;
    const T t29 = T(2) * t17 * t28 * b + T(6) * t18 * t24 - t27 * t18 * c;
    const T t30 = T(2) * t23 - T(2) * t22 - t18 * t24 * b;
    const T t31 = T(6) * t17 * t30 + t17 * t28 * c - T(2) * t17 * b * t29;
    G_ap = (T(1) / T(48)) * t17 * t28 * in.w[1] + (T(1) / T(48)) * in.w[2] * t17 * t29 + (T(1) / T(48)) * t27 * t18 * in.w[0] - (T(1) / T(48)) * t31 * t17 * in.w[3];
    G_ab = (T(1) / T(48)) * t17 * t28 * in.w[0] + (T(1) / T(48)) * t17 * t29 * in.w[1] - (T(1) / T(48)) * in.w[2] * t31 * t17 - (T(1) / T(48)) * t17 * in.w[3] * (T(6) * t17 * (t18 * t24 * c + T(2) * t17 * b * t30 - T(4) * t18 * t21) + T(2) * t31 * t17 * b + t17 * t29 * c);
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 65 +, 153 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i6_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t3 * t3;
    const T t7 = t6 * t3;
    const T t8 = t5 * t4;
    const T t9 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t10 = a_minus_b * t7 + b * t8 - T(6) * D * t9;
    const T t11 = T(5) * b * t5 + T(5) * a_minus_b * t6 + T(4) * t10 * D * t2;
    const T t12 = T(4) * t10 * t2 * b + T(5) * t6 - T(5) * t5;
    const T t13 = T(3) * t2 * t12 * b + T(2) * t2 * t11 - T(6) * t10 * t2 * c;
    F = -(T(1) / T(60)) * in.w[3] * t2 * (T(2) * t2 * (T(15) * t3 + T(2) * t2 * t11 * b - T(15) * t4) + T(4) * t13 * t2 * b - T(3) * t2 * t12 * c) - (T(1) / T(30)) * t13 * t2 * in.w[2] - (T(1) / T(20)) * t2 * t12 * in.w[1] - (T(1) / T(5)) * t10 * t2 * in.w[0];
    const T t14 = t8 + T(6) * t9 * b - t7;
    const T t15 = T(15) * t9 * c + T(3) * t10 * t2 - T(5) * t2 * b * t14;
    const T t16 = T(3) * t2 * t12 + T(10) * t2 * t14 * c + T(8) * t15 * t2 * b;
    G_ap = in.w[0] * t9 + (T(1) / T(6)) * t2 * in.w[1] * t14 - (T(1) / T(60)) * in.w[3] * t2 * t16 - (T(1) / T(15)) * t15 * t2 * in.w[2];
    G_ab = (T(1) / T(6)) * t2 * in.w[0] * t14 - (T(1) / T(30)) * in.w[3] * t2 * (t2 * t16 * b + t13 * t2 - T(2) * t15 * t2 * c) - (T(1) / T(15)) * t15 * t2 * in.w[1] - (T(1) / T(60)) * t2 * t16 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, c_minus_b);
    const T t19 = T(1) / D;
    const T t20 = T(1) / c;
    const T t21 = T(1) / q1;
    const T t22 = b * t20 + a_minus_b * t21 + J2 * a;
    const T t23 = t20 * t20;
    const T t24 = t21 * t21;
    const T t25 = T(3) * t22 * t19 * a + T(2) * b * t23 + T(2) * a_minus_b * t24;
    const T t26 = t19 * b * t25 + T(2) * t23 - T(2) * t24;
    const T t27 = T(1) / a;
    const T t28 = t19 * t25 * c - T(2) * t26 * t27 * b - T(4) * t22 * t19;
    F = (T(1) / T(8)) * t19 * in.w[0] * t25 + (T(1) / T(8)) * t26 * t27 * in.w[1] - (T(1) / T(8)) * t28 * t27 * in.w[2] - (T(1) / T(8)) * (t26 * t27 * c + T(2) * t28 * t27 * b + T(4) * (t21 - t20 - t22 * t19 * b) * t27) * in.w[3] * t27;
    const T t29 = t24 * t21;
    const T t30 = t23 * t20;
    const T t31 = T(8) * a_minus_b * t29 + T(8) * b * t30 + T(5) * t19 * a * t25;
    const T t32 = t19 * b * t31 + T(8) * t30 - T(8) * t29;
    const T t33 = T(2) * t27 * t32 * b + T(6) * t19 * t25 - t19 * t31 * c;
    const T t34 = T(2) * t27 * b * t33 + T(6) * t26 * t27 - t27 * t32 * c;
    G_ap = (T(1) / T(48)) * t27 * t32 * in.w[1] + (T(1) / T(48)) * in.w[3] * t27 * t34 + (T(1) / T(48)) * t19 * in.w[0] * t31 + (T(1) / T(48)) * t27 * t33 * in.w[2];
    G_ab = (T(1) / T(48)) * t27 * in.w[1] * t33 + (T(1) / T(48)) * t27 * t34 * in.w[2] + (T(1) / T(48)) * t27 * in.w[0] * t32 + (T(1) / T(48)) * (T(2) * t27 * b * t34 - t27 * t33 * c - T(6) * t28 * t27) * in.w[3] * t27;
  }
  const T g_factor = -T(6) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 33 +, 60 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w0_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    F = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = t5 * t5;
    const T t8 = t3 * t3;
    F = (T(1) / T(15)) * (T(4) * (t2 * b * t3 + a_minus_b * t4 * t5 + T(2) * (a_minus_b * t4 + t2 * b) * t6 * a) * t6 * a + T(3) * a_minus_b * t4 * t7 + T(3) * t2 * b * t8) * t6 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 40 +, 90 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i7_w0_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / a;
    G_ab = (T(1) / T(7)) * (T(7) * b * t2 + t3 * t6 - t10 * t7) * t11 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / D;
    const T t20 = t18 * t17;
    const T t21 = T(5) * t15 * t12 * a_minus_b + T(2) * (T(3) * b * t16 * t18 + T(4) * (t13 * t12 * a_minus_b + b * t16 * t17 + T(2) * (t12 * a_minus_b + b * t16) * a * t19) * a * t19 + T(3) * t14 * t12 * a_minus_b) * a * t19 + T(5) * b * t16 * t20;
    G_ap = (T(1) / T(35)) * t21 * t19 * in.w[0];
    const T t22 = T(1) / a;
    G_ab = (T(1) / T(35)) * (t21 * b * t19 + T(5) * t16 * t20 - T(5) * t15 * t12) * t22 * in.w[0];
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 40 +, 94 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    F = (T(1) / T(6)) * t2 * in.w[0] * (T(7) * D * t3 - t4 * a_minus_b * t7 - t8 * b * t11);
    G_ap = t3 * in.w[0];
    G_ab = (T(1) / T(7)) * t2 * (t8 * t11 + T(7) * t3 * b - t4 * t7) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / D;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t16 * t16;
    const T t18 = t15 * t15;
    const T t19 = T(4) * t12 * a * (T(2) * t12 * a * (t13 * a_minus_b + t14 * b) + t14 * b * t15 + t13 * a_minus_b * t16) + T(3) * t13 * a_minus_b * t17 + T(3) * t14 * b * t18;
    F = (T(1) / T(15)) * t12 * in.w[0] * t19;
    const T t20 = t17 * t16;
    const T t21 = t18 * t15;
    const T t22 = T(5) * t13 * a_minus_b * t20 + T(2) * t12 * a * t19 + T(5) * t14 * b * t21;
    G_ap = (T(1) / T(35)) * t22 * t12 * in.w[0];
    const T t23 = T(1) / a;
    G_ab = (T(1) / T(35)) * t23 * in.w[0] * (T(5) * t14 * t21 + t22 * t12 * b - T(5) * t13 * t20);
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 36 +, 69 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w1_f(const SegmentInput<T>& in) {
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / a;
    F = (T(1) / T(5)) * (t4 * t2 + T(5) * t5 * b - t6 * t8) * t9 * in.w[1] + in.w[0] * t5;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / D;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t12 * t12;
    const T t17 = T(4) * t10 * (t12 * t11 * b + a_minus_b * t13 * t14 + T(2) * (t11 * b + a_minus_b * t13) * t10 * a) * a + T(3) * a_minus_b * t13 * t15 + T(3) * t16 * t11 * b;
    const T t18 = T(1) / a;
    F = (T(1) / T(15)) * (t10 * t17 * b + T(3) * t16 * t11 - T(3) * t13 * t15) * t18 * in.w[1] + (T(1) / T(15)) * in.w[0] * t10 * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 44 +, 104 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i7_w1_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t6 * t3 - T(7) * b * t2 - t10 * t7;
    const T t12 = T(1) / a;
    G_ap = in.w[0] * t2 - (T(1) / T(7)) * in.w[1] * t11 * t12;
    G_ab = -(T(1) / T(7)) * t11 * in.w[0] * t12 - (T(1) / T(42)) * in.w[1] * (T(12) * b * t11 * t12 + T(42) * c * t2 + T(7) * (a_minus_b * t6 * t3 + b * t10 * t7 - T(7) * D * t2) * t12) * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / D;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(3) * a_minus_b * t16 * t14 + T(3) * b * t19 * t17 + T(4) * t13 * (T(2) * t13 * (a_minus_b * t14 + b * t17) * a + b * t18 * t17 + a_minus_b * t15 * t14) * a;
    const T t21 = t16 * t15;
    const T t22 = t19 * t18;
    const T t23 = T(2) * t13 * t20 * a + T(5) * a_minus_b * t21 * t14 + T(5) * b * t22 * t17;
    const T t24 = T(5) * t21 * t14 - t13 * b * t23 - T(5) * t22 * t17;
    const T t25 = T(1) / a;
    G_ap = (T(1) / T(35)) * t13 * in.w[0] * t23 - (T(1) / T(35)) * t24 * in.w[1] * t25;
    G_ab = -(T(1) / T(35)) * t24 * in.w[0] * t25 - (T(1) / T(105)) * in.w[1] * (T(3) * t13 * c * t23 + T(6) * t24 * b * t25 - T(7) * t13 * t20) * t25;
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 47 +, 117 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / a;
    const T t6 = t4 * t3;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t12 = b * t6 * t2 + t7 * a_minus_b * t10 - T(7) * D * t11;
    F = (T(1) / T(30)) * (T(6) * t4 * t2 - T(5) * t5 * b * t12 - T(6) * t7 * t9) * in.w[1] * t5 - (T(1) / T(6)) * t5 * t12 * in.w[0];
    const T t13 = t6 * t2 + T(7) * b * t11 - t7 * t10;
    G_ap = (T(1) / T(7)) * in.w[1] * t5 * t13 + in.w[0] * t11;
    G_ab = (T(1) / T(7)) * t5 * t13 * in.w[0] - (T(1) / T(42)) * in.w[1] * t5 * (T(7) * t5 * t12 + T(42) * c * t11 - T(12) * t5 * b * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / D;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(3) * t18 * a_minus_b * t20 + T(4) * t17 * a * (T(2) * t17 * a * (b * t14 + t18 * a_minus_b) + b * t15 * t14 + t18 * a_minus_b * t19) + T(3) * b * t16 * t14;
    const T t22 = T(1) / a;
    F = (T(1) / T(15)) * (T(3) * t16 * t14 + t17 * b * t21 - T(3) * t18 * t20) * in.w[1] * t22 + (T(1) / T(15)) * t17 * t21 * in.w[0];
    const T t23 = t16 * t15;
    const T t24 = t20 * t19;
    const T t25 = T(5) * b * t23 * t14 + T(2) * t17 * a * t21 + T(5) * t18 * a_minus_b * t24;
    const T t26 = T(5) * t23 * t14 + t17 * t25 * b - T(5) * t18 * t24;
    G_ap = (T(1) / T(35)) * in.w[1] * t22 * t26 + (T(1) / T(35)) * t17 * t25 * in.w[0];
    G_ab = (T(1) / T(35)) * t22 * t26 * in.w[0] - (T(1) / T(105)) * in.w[1] * t22 * (T(3) * t17 * t25 * c - T(7) * t17 * t21 - T(6) * t22 * b * t26);
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 39 +, 79 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t3 * t5 + T(5) * b * t2 - t6 * t8;
    const T t10 = T(1) / a;
    F = in.w[0] * t2 + (T(1) / T(5)) * in.w[1] * t9 * t10 - (T(1) / T(20)) * t10 * in.w[2] * (T(5) * (t6 * a_minus_b * t8 + t3 * b * t5 - T(5) * t2 * D) * t10 + T(20) * c * t2 - T(8) * b * t9 * t10);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = T(1) / D;
    const T t17 = t11 * b * t12 + t14 * a_minus_b * t15 + T(2) * (t11 * b + t14 * a_minus_b) * t16 * a;
    const T t18 = t15 * t15;
    const T t19 = T(4) * t17 * t16 * a + T(3) * t14 * a_minus_b * t18 + T(3) * t11 * b * t13;
    const T t20 = T(3) * t11 * t13 + t19 * b * t16 - T(3) * t14 * t18;
    const T t21 = T(1) / a;
    F = (T(1) / T(15)) * t20 * in.w[1] * t21 + (T(1) / T(15)) * t19 * in.w[0] * t16 - (T(1) / T(15)) * (t19 * c * t16 - T(2) * b * t20 * t21 - T(5) * t17 * t16) * t21 * in.w[2];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 50 +, 124 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i7_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = b * t4 * t7 + t8 * a_minus_b * t11 - T(7) * t2 * D;
    const T t13 = t8 * t11 - T(7) * b * t2 - t4 * t7;
    const T t14 = T(7) * t3 * t12 + T(42) * c * t2 + T(12) * b * t13 * t3;
    G_ap = in.w[0] * t2 - (T(1) / T(42)) * t14 * in.w[2] * t3 - (T(1) / T(7)) * in.w[1] * t13 * t3;
    G_ab = -(T(1) / T(7)) * in.w[0] * t13 * t3 - (T(1) / T(42)) * in.w[1] * t14 * t3 - (T(1) / T(210)) * in.w[2] * t3 * (T(7) * t3 * (T(6) * t8 * t10 + T(5) * b * t3 * t12 - T(6) * t4 * t6) + T(10) * b * t14 * t3 - T(30) * c * t13 * t3);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / D;
    const T t16 = T(1) / r1;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t16 * t16;
    const T t20 = t19 * t19;
    const T t21 = t18 * t18;
    const T t22 = T(4) * t15 * a * (T(2) * (t16 * a_minus_b + b * t17) * t15 * a + b * t17 * t18 + t16 * a_minus_b * t19) + T(3) * t16 * a_minus_b * t20 + T(3) * b * t17 * t21;
    const T t23 = t21 * t18;
    const T t24 = t20 * t19;
    const T t25 = T(2) * t15 * a * t22 + T(5) * b * t17 * t23 + T(5) * t16 * a_minus_b * t24;
    const T t26 = b * t25 * t15 + T(5) * t17 * t23 - T(5) * t16 * t24;
    const T t27 = T(1) / a;
    const T t28 = T(6) * b * t26 * t27 + T(7) * t15 * t22 - T(3) * t25 * c * t15;
    G_ap = (T(1) / T(105)) * t28 * in.w[2] * t27 + (T(1) / T(35)) * t26 * in.w[1] * t27 + (T(1) / T(35)) * in.w[0] * t25 * t15;
    G_ab = (T(1) / T(105)) * (T(7) * (b * t15 * t22 + T(3) * t17 * t21 - T(3) * t16 * t20) * t27 + T(2) * b * t28 * t27 - T(3) * t26 * c * t27) * in.w[2] * t27 + (T(1) / T(105)) * t28 * in.w[1] * t27 + (T(1) / T(35)) * in.w[0] * t26 * t27;
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 54 +, 141 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(7) * D * t3 - a_minus_b * t4 * t7 - b * t11 * t8;
    const T t13 = T(6) * t10 * t8 + T(5) * t2 * b * t12 - T(6) * t4 * t6;
    F = (T(1) / T(6)) * t2 * in.w[0] * t12 + (T(1) / T(30)) * t2 * t13 * in.w[1] + (T(1) / T(120)) * t2 * in.w[2] * (T(5) * t2 * (T(5) * D * t2 * t12 - T(6) * b * t10 * t8 - T(6) * a_minus_b * t4 * t6) + T(8) * t2 * t13 * b - T(20) * t2 * c * t12);
    const T t14 = t4 * t7 - T(7) * b * t3 - t11 * t8;
    const T t15 = T(7) * t2 * t12 - T(42) * t3 * c - T(12) * t2 * b * t14;
    G_ap = (T(1) / T(42)) * t2 * in.w[2] * t15 + in.w[0] * t3 - (T(1) / T(7)) * t2 * in.w[1] * t14;
    G_ab = (T(1) / T(42)) * t2 * t15 * in.w[1] + (T(1) / T(210)) * t2 * (T(10) * t2 * b * t15 + T(7) * t2 * t13 + T(30) * t2 * c * t14) * in.w[2] - (T(1) / T(7)) * t2 * in.w[0] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = a_minus_b * t17 * t18 + b * t20 * t19 + T(2) * t16 * a * (a_minus_b * t17 + b * t19);
    const T t22 = t20 * t20;
    const T t23 = t18 * t18;
    const T t24 = T(4) * t16 * a * t21 + T(3) * b * t22 * t19 + T(3) * a_minus_b * t17 * t23;
    const T t25 = T(1) / a;
    const T t26 = t16 * t24 * b + T(3) * t22 * t19 - T(3) * t17 * t23;
    F = (T(1) / T(15)) * t16 * t24 * in.w[0] + (T(1) / T(15)) * t25 * t26 * in.w[1] + (T(1) / T(15)) * (T(2) * t25 * b * t26 + T(5) * t16 * t21 - t16 * t24 * c) * t25 * in.w[2];
    const T t27 = t23 * t18;
    const T t28 = t22 * t20;
    const T t29 = T(2) * t16 * a * t24 + T(5) * a_minus_b * t17 * t27 + T(5) * b * t28 * t19;
    const T t30 = t16 * t29 * b + T(5) * t28 * t19 - T(5) * t17 * t27;
    const T t31 = T(3) * t16 * t29 * c - T(6) * t25 * b * t30 - T(7) * t16 * t24;
    G_ap = (T(1) / T(35)) * t16 * t29 * in.w[0] + (T(1) / T(35)) * t25 * in.w[1] * t30 - (T(1) / T(105)) * t31 * t25 * in.w[2];
    G_ab = (T(1) / T(35)) * t25 * in.w[0] * t30 - (T(1) / T(105)) * t31 * t25 * in.w[1] - (T(1) / T(105)) * (T(2) * t31 * t25 * b + T(3) * t25 * c * t30 - T(7) * t25 * t26) * t25 * in.w[2];
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 44 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w3_f(const SegmentInput<T>& in) {
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(3) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.15 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(5) * D * t3 - t6 * t4 * a_minus_b - t7 * b * t9;
    const T t11 = t6 * t4 - T(5) * t3 * b - t7 * t9;
    const T t12 = T(5) * t2 * t10 - T(20) * t3 * c - T(8) * t2 * b * t11;
    F = (T(1) / T(20)) * t12 * t2 * in.w[2] + in.w[0] * t3 + (T(1) / T(60)) * in.w[3] * t2 * (T(12) * t2 * c * t11 + T(5) * t2 * (T(4) * t7 * t8 + T(3) * t2 * t10 * b - T(4) * t5 * t4) + T(6) * t12 * t2 * b) - (T(1) / T(5)) * t2 * in.w[1] * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = T(1) / D;
    const T t18 = t13 * b * t14 + t16 * t15 * a_minus_b + T(2) * t17 * a * (t13 * b + t15 * a_minus_b);
    const T t19 = t16 * t16;
    const T t20 = t14 * t14;
    const T t21 = T(4) * t18 * t17 * a + T(3) * t19 * t15 * a_minus_b + T(3) * t13 * b * t20;
    const T t22 = t21 * t17 * b + T(3) * t13 * t20 - T(3) * t19 * t15;
    const T t23 = T(1) / a;
    const T t24 = T(5) * t18 * t17 + T(2) * t22 * t23 * b - t21 * t17 * c;
    F = (T(1) / T(15)) * t21 * t17 * in.w[0] + (T(1) / T(15)) * t24 * t23 * in.w[2] + (T(1) / T(15)) * in.w[3] * t23 * (T(5) * t23 * (t13 * t14 + t18 * t17 * b - t16 * t15) + T(2) * t24 * t23 * b - t22 * t23 * c) + (T(1) / T(15)) * t22 * t23 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 56 +, 144 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i7_w3_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(7) * t3 * D - t4 * a_minus_b * t7 - b * t8 * t11;
    const T t13 = t4 * t7 - t8 * t11 - T(7) * t3 * b;
    const T t14 = T(7) * t2 * t12 - T(42) * t3 * c - T(12) * t13 * t2 * b;
    const T t15 = T(6) * t4 * t6 - T(6) * t8 * t10 - T(5) * t2 * t12 * b;
    const T t16 = T(10) * t2 * b * t14 + T(30) * t13 * t2 * c - T(7) * t2 * t15;
    G_ap = (T(1) / T(210)) * t16 * t2 * in.w[3] + (T(1) / T(42)) * t2 * t14 * in.w[2] + t3 * in.w[0] - (T(1) / T(7)) * t13 * t2 * in.w[1];
    G_ab = (T(1) / T(210)) * t16 * t2 * in.w[2] + (T(1) / T(42)) * t2 * in.w[1] * t14 - (T(1) / T(7)) * t13 * t2 * in.w[0] - (T(1) / T(840)) * t2 * (T(20) * t2 * t14 * c + T(7) * t2 * (T(5) * (T(6) * t4 * a_minus_b * t6 + T(6) * b * t8 * t10 - T(5) * D * t2 * t12) * t2 + T(20) * t2 * t12 * c + T(8) * t2 * b * t15) - T(8) * t16 * t2 * b) * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / D;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = b * t18 * t19 + T(2) * t17 * a * (b * t18 + t20 * a_minus_b) + t20 * a_minus_b * t21;
    const T t23 = t21 * t21;
    const T t24 = t19 * t19;
    const T t25 = T(4) * t17 * a * t22 + T(3) * t20 * a_minus_b * t23 + T(3) * b * t18 * t24;
    const T t26 = t23 * t21;
    const T t27 = t24 * t19;
    const T t28 = T(2) * t17 * a * t25 + T(5) * t20 * a_minus_b * t26 + T(5) * b * t18 * t27;
    const T t29 = T(1) / a;
    const T t30 = T(5) * t20 * t26 - t28 * t17 * b - T(5) * t18 * t27;
    const T t31 = t17 * b * t25 + T(3) * t18 * t24 - T(3) * t20 * t23;
    const T t32 = T(6) * t29 * b * t30 + T(3) * t28 * t17 * c - T(7) * t17 * t25;
    const T t33 = T(3) * t29 * t30 * c + T(7) * t29 * t31 - T(2) * t32 * t29 * b;
    G_ap = (T(1) / T(35)) * t28 * t17 * in.w[0] + (T(1) / T(105)) * t29 * in.w[3] * t33 - (T(1) / T(105)) * t32 * t29 * in.w[2] - (T(1) / T(35)) * t29 * in.w[1] * t30;
    G_ab = (T(1) / T(105)) * (t32 * t29 * c + T(2) * t29 * b * t33 + T(7) * t29 * (T(2) * t29 * t31 * b + T(5) * t17 * t22 - t17 * c * t25)) * t29 * in.w[3] + (T(1) / T(105)) * t29 * t33 * in.w[2] - (T(1) / T(35)) * t29 * in.w[0] * t30 - (T(1) / T(105)) * t32 * t29 * in.w[1];
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 63 +, 168 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i7_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t11 = b * t5 * t2 + t9 * t6 * a_minus_b - T(7) * t10 * D;
    const T t12 = T(1) / a;
    const T t13 = T(5) * b * t11 * t12 + T(6) * t8 * t6 - T(6) * t4 * t2;
    const T t14 = T(6) * b * t4 * t2 + T(6) * t8 * t6 * a_minus_b + T(5) * t11 * D * t12;
    const T t15 = T(8) * b * t13 * t12 + T(5) * t14 * t12 - T(20) * c * t11 * t12;
    F = (T(1) / T(120)) * in.w[3] * (T(4) * c * t13 * t12 - T(2) * b * t15 * t12 - T(5) * (T(8) * t7 * t6 + t14 * b * t12 - T(8) * t3 * t2) * t12) * t12 - (T(1) / T(6)) * in.w[0] * t11 * t12 - (T(1) / T(120)) * t15 * in.w[2] * t12 - (T(1) / T(30)) * in.w[1] * t13 * t12;
    const T t16 = T(7) * t10 * b + t5 * t2 - t9 * t6;
    const T t17 = T(7) * t11 * t12 + T(42) * t10 * c - T(12) * t16 * b * t12;
    const T t18 = T(30) * t16 * c * t12 + T(10) * b * t17 * t12 + T(7) * t13 * t12;
    G_ap = t10 * in.w[0] + (T(1) / T(7)) * t16 * in.w[1] * t12 - (T(1) / T(42)) * t17 * in.w[2] * t12 - (T(1) / T(210)) * in.w[3] * t18 * t12;
    G_ab = (T(1) / T(7)) * in.w[0] * t16 * t12 - (T(1) / T(840)) * in.w[3] * (T(8) * b * t18 * t12 + T(7) * t15 * t12 - T(20) * c * t17 * t12) * t12 - (T(1) / T(42)) * in.w[1] * t17 * t12 - (T(1) / T(210)) * t18 * in.w[2] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = b * t20 * t19 + t24 * t23 * a_minus_b + T(2) * (b * t19 + t23 * a_minus_b) * t22 * a;
    const T t26 = t24 * t24;
    const T t27 = T(4) * t22 * t25 * a + T(3) * b * t21 * t19 + T(3) * t26 * t23 * a_minus_b;
    const T t28 = T(3) * t21 * t19 + b * t22 * t27 - T(3) * t26 * t23;
    const T t29 = T(1) / a;
    const T t30 = T(2) * b * t28 * t29 + T(5) * t22 * t25 - c * t22 * t27;
    F = (T(1) / T(15)) * in.w[2] * t30 * t29 + (T(1) / T(15)) * in.w[1] * t28 * t29 + (T(1) / T(15)) * in.w[0] * t22 * t27 - (T(1) / T(15)) * in.w[3] * (T(5) * (t24 * t23 - t20 * t19 - b * t22 * t25) * t29 + c * t28 * t29 - T(2) * b * t30 * t29) * t29;
    const T t31 = t21 * t20;
    const T t32 = t26 * t24;
    const T t33 = T(5) * b * t31 * t19 + T(2) * t22 * t27 * a + T(5) * t32 * t23 * a_minus_b;
    const T t34 = b * t33 * t22 + T(5) * t31 * t19 - T(5) * t32 * t23;
    const T t35 = T(7) * t22 * t27 + T(6) * b * t34 * t29 - T(3) * t33 * c * t22;
    const T t36 = T(7) * t28 * t29 + T(2) * b * t35 * t29 - T(3) * c * t34 * t29;
    G_ap = (T(1) / T(35)) * in.w[1] * t34 * t29 + (T(1) / T(35)) * in.w[0] * t33 * t22 + (T(1) / T(105)) * in.w[3] * t36 * t29 + (T(1) / T(105)) * in.w[2] * t35 * t29;
    G_ab = (T(1) / T(105)) * (T(2) * b * t36 * t29 + T(7) * t30 * t29 - c * t35 * t29) * in.w[3] * t29 + (T(1) / T(105)) * in.w[2] * t36 * t29 + (T(1) / T(105)) * in.w[1] * t35 * t29 + (T(1) / T(35)) * in.w[0] * t34 * t29;
  }
  const T g_factor = -T(7) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 37 +, 64 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w0_f(const SegmentInput<T>& in) {
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    F = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    F = (T(1) / T(48)) * t4 * in.w[0] * (T(8) * a_minus_b * t7 + T(5) * (T(2) * a_minus_b * t6 + T(2) * b * t9 + T(3) * t4 * (a * J2 + b * t8 + a_minus_b * t5) * a) * t4 * a + T(8) * b * t10);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 44 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i8_w0_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    G_ab = -(T(1) / T(8)) * t3 * in.w[0] * (t6 - t9 - T(8) * b * t2);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, c_minus_b);
    const T t12 = T(1) / D;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / q1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = t14 * t14;
    const T t20 = t17 * t17;
    const T t21 = T(7) * t12 * a * (T(8) * b * t15 + T(8) * t18 * a_minus_b + T(5) * t12 * (T(2) * b * t14 + T(2) * t17 * a_minus_b + T(3) * t12 * a * (t16 * a_minus_b + b * t13 + a * J2)) * a) + T(48) * b * t19 + T(48) * t20 * a_minus_b;
    G_ap = (T(1) / T(384)) * t12 * in.w[0] * t21;
    const T t22 = T(1) / a;
    G_ab = -(T(1) / T(384)) * t22 * in.w[0] * (T(48) * t20 - T(48) * t19 - t12 * b * t21);
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 44 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    F = (T(1) / T(7)) * t2 * in.w[0] * (T(8) * t3 * D - t6 * b - a_minus_b * t9);
    G_ap = t3 * in.w[0];
    G_ab = (T(1) / T(8)) * (t6 + T(8) * t3 * b - t9) * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = t11 * atan2(t10, c_minus_b);
    const T t12 = T(1) / D;
    const T t13 = T(1) / q1;
    const T t14 = T(1) / c;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t15 * t14;
    const T t18 = t16 * t13;
    const T t19 = T(5) * (T(3) * a * t12 * (a_minus_b * t13 + t14 * b + J2 * a) + T(2) * t15 * b + T(2) * a_minus_b * t16) * a * t12 + T(8) * t17 * b + T(8) * a_minus_b * t18;
    F = (T(1) / T(48)) * t19 * t12 * in.w[0];
    const T t20 = t15 * t15;
    const T t21 = t16 * t16;
    const T t22 = T(7) * t19 * a * t12 + T(48) * t20 * b + T(48) * a_minus_b * t21;
    G_ap = (T(1) / T(384)) * t12 * in.w[0] * t22;
    const T t23 = T(1) / a;
    G_ab = (T(1) / T(384)) * (T(48) * t20 + t12 * b * t22 - T(48) * t21) * t23 * in.w[0];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 40 +, 71 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w1_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    F = in.w[0] * t2 + (T(1) / T(6)) * t3 * in.w[1] * (t6 + T(6) * b * t2 - t9);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / a;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / q1;
    const T t17 = T(1) / D;
    const T t18 = t16 * t16;
    const T t19 = t18 * t16;
    const T t20 = T(8) * b * t15 + T(5) * a * (T(2) * b * t14 + T(3) * (a * J2 + a_minus_b * t16 + b * t13) * a * t17 + T(2) * a_minus_b * t18) * t17 + T(8) * a_minus_b * t19;
    F = (T(1) / T(48)) * t12 * in.w[1] * (T(8) * t15 + b * t20 * t17 - T(8) * t19) + (T(1) / T(48)) * t20 * in.w[0] * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 48 +, 103 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i8_w1_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(8) * b * t2 + t6 - t9;
    G_ap = in.w[0] * t2 + (T(1) / T(8)) * in.w[1] * t3 * t10;
    G_ab = (T(1) / T(8)) * in.w[0] * t3 * t10 + (T(1) / T(28)) * (T(7) * b * t3 * t10 - T(28) * c * t2 - T(4) * (t9 * a_minus_b + b * t6 - T(8) * D * t2) * t3) * in.w[1] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / D;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t18 * t17;
    const T t21 = t15 * t14;
    const T t22 = T(8) * b * t20 + T(5) * (T(3) * (t14 * a_minus_b + b * t17 + J2 * a) * t13 * a + T(2) * b * t18 + T(2) * t15 * a_minus_b) * t13 * a + T(8) * t21 * a_minus_b;
    const T t23 = T(48) * t16 * a_minus_b + T(48) * b * t19 + T(7) * t22 * t13 * a;
    const T t24 = T(48) * t16 - b * t13 * t23 - T(48) * t19;
    const T t25 = T(1) / a;
    G_ap = (T(1) / T(384)) * in.w[0] * t13 * t23 - (T(1) / T(384)) * t24 * in.w[1] * t25;
    G_ab = (T(1) / T(384)) * (T(8) * t22 * t13 - c * t13 * t23 - T(2) * b * t24 * t25) * in.w[1] * t25 - (T(1) / T(384)) * in.w[0] * t24 * t25;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 51 +, 114 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t10 = a_minus_b * t5 + b * t8 - T(8) * D * t9;
    const T t11 = t4 * t3;
    const T t12 = t7 * t6;
    F = -(T(1) / T(42)) * in.w[1] * t2 * (T(6) * t10 * t2 * b + T(7) * t11 - T(7) * t12) - (T(1) / T(7)) * t10 * t2 * in.w[0];
    const T t13 = t5 - t8 - T(8) * b * t9;
    G_ap = t9 * in.w[0] - (T(1) / T(8)) * in.w[1] * t2 * t13;
    G_ab = -(T(1) / T(28)) * (T(4) * t10 * t2 + T(28) * t9 * c + T(7) * t2 * b * t13) * in.w[1] * t2 - (T(1) / T(8)) * t2 * t13 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(8) * a_minus_b * t19 + T(8) * b * t22 + T(5) * t16 * a * (T(2) * a_minus_b * t18 + T(3) * (b * t20 + a_minus_b * t17 + a * J2) * t16 * a + T(2) * b * t21);
    const T t24 = T(1) / a;
    F = (T(1) / T(48)) * t16 * t23 * in.w[0] + (T(1) / T(48)) * (t16 * b * t23 + T(8) * t22 - T(8) * t19) * in.w[1] * t24;
    const T t25 = t18 * t18;
    const T t26 = t21 * t21;
    const T t27 = T(48) * a_minus_b * t25 + T(7) * t16 * a * t23 + T(48) * b * t26;
    const T t28 = T(48) * t25 - t16 * b * t27 - T(48) * t26;
    G_ap = (T(1) / T(384)) * t16 * t27 * in.w[0] - (T(1) / T(384)) * t28 * in.w[1] * t24;
    G_ab = -(T(1) / T(384)) * in.w[1] * t24 * (T(2) * t28 * t24 * b + t16 * t27 * c - T(8) * t16 * t23) - (T(1) / T(384)) * t28 * t24 * in.w[0];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 43 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w2_f(const SegmentInput<T>& in) {
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
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(6) * t2 * b + t6 - t9;
    F = t2 * in.w[0] + (T(1) / T(15)) * (T(3) * t3 * (T(6) * D * t2 - b * t6 - t9 * a_minus_b) + T(5) * t3 * t10 * b - T(15) * t2 * c) * t3 * in.w[2] + (T(1) / T(6)) * in.w[1] * t3 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = t12 * atan2(t11, c_minus_b);
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = T(1) / c;
    const T t16 = T(1) / q1;
    const T t17 = t15 * t15;
    const T t18 = t16 * t16;
    const T t19 = T(3) * t14 * a * (b * t15 + t16 * a_minus_b + a * J2) + T(2) * b * t17 + T(2) * t18 * a_minus_b;
    const T t20 = t17 * t15;
    const T t21 = t18 * t16;
    const T t22 = T(5) * t14 * a * t19 + T(8) * b * t20 + T(8) * t21 * a_minus_b;
    const T t23 = t14 * b * t22 + T(8) * t20 - T(8) * t21;
    F = (T(1) / T(48)) * t13 * in.w[2] * (T(2) * t13 * b * t23 + T(6) * t14 * t19 - t14 * t22 * c) + (T(1) / T(48)) * in.w[1] * t13 * t23 + (T(1) / T(48)) * t14 * in.w[0] * t22;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 54 +, 120 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i8_w2_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t4 + T(8) * t5 * b - t8;
    const T t10 = T(1) / a;
    const T t11 = t4 * b + a_minus_b * t8 - T(8) * t5 * D;
    const T t12 = T(4) * t10 * t11 + T(28) * t5 * c - T(7) * t9 * t10 * b;
    G_ap = (T(1) / T(8)) * in.w[1] * t9 * t10 + t5 * in.w[0] - (T(1) / T(28)) * in.w[2] * t12 * t10;
    const T t13 = t7 * t6;
    const T t14 = t3 * t2;
    G_ab = (T(1) / T(8)) * t9 * t10 * in.w[0] - (T(1) / T(28)) * in.w[1] * t12 * t10 - (T(1) / T(168)) * (T(12) * t12 * t10 * b + T(4) * t10 * (T(7) * t13 + T(6) * t10 * t11 * b - T(7) * t14) + T(21) * c * t9 * t10) * in.w[2] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / D;
    const T t18 = T(1) / c;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t22 * t21;
    const T t25 = t19 * t18;
    const T t26 = T(8) * a_minus_b * t24 + T(5) * (T(2) * a_minus_b * t22 + T(2) * t19 * b + T(3) * t17 * a * (a * J2 + t18 * b + a_minus_b * t21)) * t17 * a + T(8) * t25 * b;
    const T t27 = T(48) * t20 * b + T(48) * a_minus_b * t23 + T(7) * t17 * a * t26;
    const T t28 = T(1) / a;
    const T t29 = T(48) * t20 + t17 * b * t27 - T(48) * t23;
    const T t30 = c * t17 * t27 - T(2) * t28 * b * t29 - T(8) * t17 * t26;
    G_ap = (T(1) / T(384)) * t17 * t27 * in.w[0] + (T(1) / T(384)) * in.w[1] * t28 * t29 - (T(1) / T(384)) * in.w[2] * t28 * t30;
    G_ab = (T(1) / T(384)) * t28 * in.w[0] * t29 - (T(1) / T(384)) * in.w[2] * t28 * (T(2) * t28 * t30 * b + c * t28 * t29 + T(8) * t28 * (T(8) * t24 - T(8) * t25 - t17 * b * t26)) - (T(1) / T(384)) * in.w[1] * t28 * t30;
  }
  const T g_factor = -T(8) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 58 +, 137 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t10 = b * t5 + a_minus_b * t8 - T(8) * D * t9;
    const T t11 = t7 * t6;
    const T t12 = t4 * t3;
    const T t13 = T(7) * t11 + T(6) * t2 * b * t10 - T(7) * t12;
    F = -(T(1) / T(7)) * t2 * in.w[0] * t10 - (T(1) / T(42)) * t2 * t13 * in.w[1] - (T(1) / T(105)) * t2 * in.w[2] * (T(3) * t2 * (T(6) * D * t2 * t10 + T(7) * a_minus_b * t11 + T(7) * b * t12) + T(5) * t2 * b * t13 - T(15) * t2 * c * t10);
    const T t14 = T(8) * b * t9 + t5 - t8;
    const T t15 = T(28) * c * t9 + T(4) * t2 * t10 - T(7) * t2 * b * t14;
    G_ap = (T(1) / T(8)) * t2 * t14 * in.w[1] + in.w[0] * t9 - (T(1) / T(28)) * t2 * in.w[2] * t15;
    G_ab = (T(1) / T(8)) * t2 * in.w[0] * t14 - (T(1) / T(168)) * t2 * in.w[2] * (T(12) * t2 * b * t15 + T(4) * t2 * t13 + T(21) * t2 * c * t14) - (T(1) / T(28)) * t2 * t15 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, c_minus_b);
    const T t18 = T(1) / D;
    const T t19 = T(1) / q1;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = T(3) * t18 * a * (a_minus_b * t19 + b * t20 + a * J2) + T(2) * b * t21 + T(2) * a_minus_b * t22;
    const T t24 = t22 * t19;
    const T t25 = t21 * t20;
    const T t26 = T(5) * t18 * a * t23 + T(8) * a_minus_b * t24 + T(8) * b * t25;
    const T t27 = T(1) / a;
    const T t28 = T(8) * t24 - T(8) * t25 - t18 * t26 * b;
    F = (T(1) / T(48)) * t18 * t26 * in.w[0] - (T(1) / T(48)) * t27 * t28 * in.w[1] - (T(1) / T(48)) * t27 * (T(2) * t27 * t28 * b + t18 * t26 * c - T(6) * t18 * t23) * in.w[2];
    const T t29 = t21 * t21;
    const T t30 = t22 * t22;
    const T t31 = T(7) * t18 * a * t26 + T(48) * b * t29 + T(48) * a_minus_b * t30;
    const T t32 = T(48) * t29 + t18 * b * t31 - T(48) * t30;
    const T t33 = T(8) * t18 * t26 + T(2) * t27 * t32 * b - t18 * t31 * c;
    G_ap = (T(1) / T(384)) * t18 * in.w[0] * t31 + (T(1) / T(384)) * t27 * in.w[2] * t33 + (T(1) / T(384)) * t27 * t32 * in.w[1];
    G_ab = (T(1) / T(384)) * t27 * t32 * in.w[0] + (T(1) / T(384)) * t27 * t33 * in.w[1] - (T(1) / T(384)) * (t27 * t32 * c + T(8) * t27 * t28 - T(2) * t27 * b * t33) * t27 * in.w[2];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 48 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w3_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(1) / T(5)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.20 a min(q(0), q(1)): recurrence (1) downwards from J_8 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = J_downward<T>(T(8), a, D, -b, c, a_minus_b, q1);
    const T t10 = b * t5 + a_minus_b * t8 - T(6) * t9 * D;
    const T t11 = t5 + T(6) * b * t9 - t8;
    const T t12 = T(15) * c * t9 + T(3) * t2 * t10 - T(5) * t2 * b * t11;
    F = (T(1) / T(60)) * in.w[3] * t2 * (T(3) * t2 * (T(5) * t4 - T(4) * t2 * b * t10 - T(5) * t7) - T(10) * t2 * t11 * c - T(8) * t2 * b * t12) + (T(1) / T(6)) * t2 * in.w[1] * t11 + in.w[0] * t9 - (T(1) / T(15)) * t2 * in.w[2] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / D;
    const T t20 = T(2) * b * t16 + T(2) * a_minus_b * t18 + T(3) * a * (a * J2 + a_minus_b * t17 + b * t15) * t19;
    const T t21 = t16 * t15;
    const T t22 = t18 * t17;
    const T t23 = T(5) * a * t20 * t19 + T(8) * b * t21 + T(8) * a_minus_b * t22;
    const T t24 = T(1) / a;
    const T t25 = T(8) * t21 + t23 * b * t19 - T(8) * t22;
    const T t26 = T(6) * t20 * t19 + T(2) * t24 * b * t25 - t23 * c * t19;
    F = (T(1) / T(48)) * in.w[0] * t23 * t19 + (T(1) / T(48)) * t24 * in.w[2] * t26 + (T(1) / T(48)) * t24 * in.w[1] * t25 - (T(1) / T(48)) * in.w[3] * t24 * (t24 * c * t25 - T(6) * t24 * (T(2) * t16 + b * t20 * t19 - T(2) * t18) - T(2) * t24 * b * t26);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 60 +, 140 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i8_w3_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(8) * t2 * b + t6 - t9;
    const T t11 = b * t6 + a_minus_b * t9 - T(8) * t2 * D;
    const T t12 = T(7) * t3 * b * t10 - T(4) * t11 * t3 - T(28) * t2 * c;
    const T t13 = t8 * t7;
    const T t14 = t5 * t4;
    const T t15 = T(7) * t13 + T(6) * t11 * t3 * b - T(7) * t14;
    const T t16 = T(21) * t3 * t10 * c + T(4) * t3 * t15 - T(12) * t12 * t3 * b;
    G_ap = t2 * in.w[0] + (T(1) / T(8)) * t3 * in.w[1] * t10 + (T(1) / T(28)) * t12 * in.w[2] * t3 - (T(1) / T(168)) * t16 * t3 * in.w[3];
    G_ab = (T(1) / T(8)) * t3 * in.w[0] * t10 + (T(1) / T(28)) * t12 * t3 * in.w[1] - (T(1) / T(168)) * in.w[2] * t16 * t3 - (T(1) / T(420)) * (T(15) * t12 * t3 * c + T(4) * t3 * (T(5) * t3 * b * t15 + T(3) * t3 * (T(7) * a_minus_b * t13 + T(7) * b * t14 + T(6) * t11 * D * t3) - T(15) * t11 * t3 * c) + T(5) * t16 * t3 * b) * t3 * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, c_minus_b);
    const T t19 = T(1) / a;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / c;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(1) / D;
    const T t27 = T(2) * a_minus_b * t21 + T(2) * b * t24 + T(3) * t26 * a * (b * t23 + a * J2 + a_minus_b * t20);
    const T t28 = T(8) * a_minus_b * t22 + T(8) * b * t25 + T(5) * t26 * a * t27;
    const T t29 = t24 * t24;
    const T t30 = t21 * t21;
    const T t31 = T(48) * b * t29 + T(48) * a_minus_b * t30 + T(7) * t28 * t26 * a;
    const T t32 = t26 * b * t31 + T(48) * t29 - T(48) * t30;
    const T t33 = T(8) * t28 * t26 + T(2) * t19 * b * t32 - t26 * t31 * c;
    const T t34 = t28 * t26 * b + T(8) * t25 - T(8) * t22;
    const T t35 = T(8) * t19 * t34 + T(2) * t19 * b * t33 - t19 * t32 * c;
    G_ap = (T(1) / T(384)) * in.w[2] * t19 * t33 + (T(1) / T(384)) * t19 * in.w[1] * t32 + (T(1) / T(384)) * t26 * in.w[0] * t31 + (T(1) / T(384)) * t19 * t35 * in.w[3];
    G_ab = (T(1) / T(384)) * t19 * in.w[3] * (T(8) * t19 * (T(6) * t26 * t27 + T(2) * t19 * b * t34 - t28 * t26 * c) + T(2) * t19 * t35 * b - t19 * t33 * c) + (T(1) / T(384)) * t19 * t33 * in.w[1] + (T(1) / T(384)) * t19 * in.w[0] * t32 + (T(1) / T(384)) * in.w[2] * t19 * t35;
  }
  const T g_factor = -T(8) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 67 +, 164 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i8_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / a;
    const T t9 = t6 * t6;
    const T t10 = t3 * t3;
    const T t11 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t12 = a_minus_b * t9 + t10 * b - T(8) * t11 * D;
    const T t13 = T(7) * t4 - T(7) * t7 - T(6) * t8 * t12 * b;
    const T t14 = T(7) * t4 * b + T(6) * D * t8 * t12 + T(7) * a_minus_b * t7;
    const T t15 = T(5) * t13 * t8 * b + T(15) * c * t8 * t12 - T(3) * t8 * t14;
    F = (T(1) / T(42)) * t13 * t8 * in.w[1] + (T(1) / T(105)) * in.w[2] * t15 * t8 - (T(1) / T(7)) * in.w[0] * t8 * t12 - (T(1) / T(420)) * in.w[3] * t8 * (T(10) * t13 * c * t8 - T(3) * (T(35) * t3 - T(35) * t6 - T(4) * t8 * b * t14) * t8 - T(8) * t15 * t8 * b);
    const T t16 = t10 + T(8) * t11 * b - t9;
    const T t17 = T(4) * t8 * t12 + T(28) * c * t11 - T(7) * t8 * t16 * b;
    const T t18 = T(4) * t13 * t8 - T(12) * t17 * t8 * b - T(21) * c * t8 * t16;
    G_ap = t11 * in.w[0] + (T(1) / T(168)) * in.w[3] * t8 * t18 + (T(1) / T(8)) * t8 * t16 * in.w[1] - (T(1) / T(28)) * in.w[2] * t17 * t8;
    G_ab = (T(1) / T(8)) * in.w[0] * t8 * t16 + (T(1) / T(420)) * in.w[3] * t8 * (T(5) * t8 * b * t18 + T(4) * t15 * t8 + T(15) * t17 * c * t8) + (T(1) / T(168)) * in.w[2] * t8 * t18 - (T(1) / T(28)) * t17 * t8 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, c_minus_b) * t20;
    const T t21 = T(1) / D;
    const T t22 = T(1) / c;
    const T t23 = T(1) / q1;
    const T t24 = t23 * t23;
    const T t25 = t22 * t22;
    const T t26 = T(3) * t21 * a * (t22 * b + a_minus_b * t23 + J2 * a) + T(2) * a_minus_b * t24 + T(2) * t25 * b;
    const T t27 = t25 * t22;
    const T t28 = t24 * t23;
    const T t29 = T(5) * t26 * t21 * a + T(8) * t27 * b + T(8) * a_minus_b * t28;
    const T t30 = T(8) * t27 + t29 * t21 * b - T(8) * t28;
    const T t31 = T(1) / a;
    const T t32 = c * t29 * t21 - T(6) * t26 * t21 - T(2) * t30 * t31 * b;
    F = (T(1) / T(48)) * t29 * t21 * in.w[0] + (T(1) / T(48)) * t30 * t31 * in.w[1] - (T(1) / T(48)) * in.w[3] * t31 * (T(2) * t32 * t31 * b + c * t30 * t31 - T(6) * (T(2) * t25 + t26 * t21 * b - T(2) * t24) * t31) - (T(1) / T(48)) * in.w[2] * t32 * t31;
    const T t33 = t25 * t25;
    const T t34 = t24 * t24;
    const T t35 = T(48) * a_minus_b * t34 + T(48) * t33 * b + T(7) * t29 * t21 * a;
    const T t36 = T(48) * t33 + t21 * t35 * b - T(48) * t34;
    const T t37 = T(2) * t36 * t31 * b + T(8) * t29 * t21 - c * t21 * t35;
    const T t38 = c * t36 * t31 - T(2) * t31 * t37 * b - T(8) * t30 * t31;
    G_ap = (T(1) / T(384)) * t36 * t31 * in.w[1] + (T(1) / T(384)) * in.w[2] * t31 * t37 + (T(1) / T(384)) * t21 * t35 * in.w[0] - (T(1) / T(384)) * t38 * in.w[3] * t31;
    G_ab = (T(1) / T(384)) * t36 * in.w[0] * t31 + (T(1) / T(384)) * t31 * t37 * in.w[1] - (T(1) / T(384)) * in.w[2] * t38 * t31 - (T(1) / T(384)) * in.w[3] * (T(8) * t32 * t31 + c * t31 * t37 + T(2) * t38 * t31 * b) * t31;
  }
  const T g_factor = -T(8) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 35 +, 71 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w0_f(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    F = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = t7 * t7;
    const T t10 = t9 * t7;
    F = (T(1) / T(35)) * (T(5) * t2 * b * t5 + T(2) * (T(4) * (a_minus_b * t6 * t7 + T(2) * (t2 * b + a_minus_b * t6) * t8 * a + t2 * b * t3) * t8 * a + T(3) * t2 * b * t4 + T(3) * a_minus_b * t6 * t9) * t8 * a + T(5) * a_minus_b * t6 * t10) * t8 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 42 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i9_w0_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / a;
    G_ab = (T(1) / T(9)) * in.w[0] * (t6 * t3 + T(9) * b * t2 - t10 * t7) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / D;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t19 * t18;
    const T t22 = t15 * t14;
    const T t23 = T(35) * b * t16 * t13 + T(35) * a_minus_b * t20 * t17 + T(8) * t12 * (T(5) * a_minus_b * t21 * t17 + T(2) * t12 * (T(3) * a_minus_b * t19 * t17 + T(3) * b * t15 * t13 + T(4) * t12 * (b * t14 * t13 + T(2) * t12 * (a_minus_b * t17 + b * t13) * a + a_minus_b * t18 * t17) * a) * a + T(5) * b * t22 * t13) * a;
    G_ap = (T(1) / T(315)) * in.w[0] * t12 * t23;
    const T t24 = T(1) / a;
    G_ab = (T(1) / T(315)) * in.w[0] * (T(35) * t16 * t13 + t12 * b * t23 - T(35) * t20 * t17) * t24;
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 42 +, 105 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    F = -(T(1) / T(8)) * in.w[0] * t2 * (b * t6 * t3 + a_minus_b * t10 * t7 - T(9) * D * t11);
    G_ap = in.w[0] * t11;
    G_ab = (T(1) / T(9)) * in.w[0] * t2 * (T(9) * b * t11 + t6 * t3 - t10 * t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = T(1) / D;
    const T t19 = t17 * t17;
    const T t20 = t19 * t17;
    const T t21 = T(5) * a_minus_b * t15 * t12 + T(2) * (T(3) * a_minus_b * t14 * t12 + T(4) * (b * t17 * t16 + a_minus_b * t13 * t12 + T(2) * (a_minus_b * t12 + b * t16) * t18 * a) * t18 * a + T(3) * b * t19 * t16) * t18 * a + T(5) * b * t20 * t16;
    F = (T(1) / T(35)) * t21 * t18 * in.w[0];
    const T t22 = t19 * t19;
    const T t23 = t14 * t14;
    const T t24 = T(8) * t21 * t18 * a + T(35) * b * t22 * t16 + T(35) * a_minus_b * t23 * t12;
    G_ap = (T(1) / T(315)) * t24 * t18 * in.w[0];
    const T t25 = T(1) / a;
    G_ab = (T(1) / T(315)) * (T(35) * t22 * t16 + b * t24 * t18 - T(35) * t23 * t12) * in.w[0] * t25;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 38 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w1_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    F = t2 * in.w[0] - (T(1) / T(7)) * t3 * in.w[1] * (t7 * t4 - T(7) * b * t2 - t8 * t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(5) * t12 * b * t15 + T(2) * t16 * a * (T(4) * t16 * a * (T(2) * (t12 * b + a_minus_b * t17) * t16 * a + t18 * a_minus_b * t17 + t12 * b * t13) + T(3) * t12 * b * t14 + T(3) * t19 * a_minus_b * t17) + T(5) * t20 * a_minus_b * t17;
    const T t22 = T(1) / a;
    F = (T(1) / T(35)) * t21 * t16 * in.w[0] - (T(1) / T(35)) * (T(5) * t20 * t17 - t21 * t16 * b - T(5) * t12 * t15) * t22 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 46 +, 114 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i9_w1_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t3 * t6 + T(9) * b * t2 - t7 * t10;
    const T t12 = T(1) / a;
    G_ap = in.w[0] * t2 + (T(1) / T(9)) * t11 * t12 * in.w[1];
    G_ab = (T(1) / T(9)) * t11 * in.w[0] * t12 - (T(1) / T(72)) * (T(9) * (b * t3 * t6 + t7 * a_minus_b * t10 - T(9) * D * t2) * t12 + T(72) * c * t2 - T(16) * t11 * b * t12) * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / D;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(5) * b * t14 * t17 + T(2) * (T(3) * b * t14 * t16 + T(4) * a * t13 * (T(2) * (b * t14 + t18 * a_minus_b) * a * t13 + t18 * a_minus_b * t19 + b * t14 * t15) + T(3) * t18 * a_minus_b * t20) * a * t13 + T(5) * t18 * a_minus_b * t21;
    const T t23 = t16 * t16;
    const T t24 = t20 * t20;
    const T t25 = T(8) * t22 * a * t13 + T(35) * b * t14 * t23 + T(35) * t18 * a_minus_b * t24;
    const T t26 = T(1) / a;
    const T t27 = b * t13 * t25 + T(35) * t14 * t23 - T(35) * t18 * t24;
    G_ap = (T(1) / T(315)) * in.w[0] * t13 * t25 + (T(1) / T(315)) * t26 * in.w[1] * t27;
    G_ab = (T(1) / T(315)) * t26 * in.w[1] * (T(9) * t22 * t13 + T(2) * b * t26 * t27 - c * t13 * t25) + (T(1) / T(315)) * in.w[0] * t26 * t27;
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 49 +, 127 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t7 = t4 * t4;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(9) * t6 * D - b * t7 * t2 - a_minus_b * t11 * t8;
    const T t13 = T(1) / a;
    const T t14 = t10 * t9;
    F = (T(1) / T(56)) * (T(8) * t5 * t2 + T(7) * b * t12 * t13 - T(8) * t14 * t8) * in.w[1] * t13 + (T(1) / T(8)) * t12 * in.w[0] * t13;
    const T t15 = T(9) * b * t6 + t7 * t2 - t11 * t8;
    G_ap = (T(1) / T(9)) * t15 * in.w[1] * t13 + t6 * in.w[0];
    G_ab = (T(1) / T(9)) * t15 * in.w[0] * t13 - (T(1) / T(72)) * (T(72) * t6 * c - T(16) * b * t15 * t13 - T(9) * t12 * t13) * in.w[1] * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = T(1) / D;
    const T t25 = T(5) * a_minus_b * t19 * t16 + T(5) * b * t23 * t20 + T(2) * (T(3) * b * t22 * t20 + T(3) * a_minus_b * t18 * t16 + T(4) * (T(2) * t24 * (a_minus_b * t16 + b * t20) * a + a_minus_b * t17 * t16 + b * t21 * t20) * t24 * a) * t24 * a;
    const T t26 = T(1) / a;
    F = (T(1) / T(35)) * t25 * in.w[0] * t24 + (T(1) / T(35)) * in.w[1] * t26 * (T(5) * t23 * t20 + t25 * b * t24 - T(5) * t19 * t16);
    const T t27 = t22 * t22;
    const T t28 = t18 * t18;
    const T t29 = T(8) * t25 * t24 * a + T(35) * b * t27 * t20 + T(35) * a_minus_b * t28 * t16;
    const T t30 = T(35) * t28 * t16 - T(35) * t27 * t20 - b * t29 * t24;
    G_ap = (T(1) / T(315)) * in.w[0] * t29 * t24 - (T(1) / T(315)) * t30 * in.w[1] * t26;
    G_ab = (T(1) / T(315)) * in.w[1] * t26 * (T(9) * t25 * t24 - c * t29 * t24 - T(2) * b * t30 * t26) - (T(1) / T(315)) * in.w[0] * t30 * t26;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 41 +, 91 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(6) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t7 * t4 - T(7) * t2 * b - t8 * t11;
    F = t2 * in.w[0] - (T(1) / T(7)) * t3 * in.w[1] * t12 - (T(1) / T(42)) * (T(12) * t3 * t12 * b + T(42) * t2 * c - T(7) * t3 * (T(7) * t2 * D - t7 * t4 * a_minus_b - t8 * b * t11)) * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / a;
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t16;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(3) * t19 * b * t21 + T(3) * t17 * t15 * a_minus_b + T(4) * (T(2) * t14 * a * (t15 * a_minus_b + t19 * b) + t16 * t15 * a_minus_b + t19 * b * t20) * t14 * a;
    const T t23 = t21 * t20;
    const T t24 = T(5) * t18 * t15 * a_minus_b + T(2) * t14 * a * t22 + T(5) * t19 * b * t23;
    const T t25 = t14 * b * t24 + T(5) * t19 * t23 - T(5) * t18 * t15;
    F = (T(1) / T(105)) * t13 * (T(6) * t13 * b * t25 + T(7) * t14 * t22 - T(3) * t14 * c * t24) * in.w[2] + (T(1) / T(35)) * t13 * in.w[1] * t25 + (T(1) / T(35)) * t14 * t24 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 52 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i9_w2_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t3 - t7 * t10 - T(9) * b * t2;
    const T t12 = T(1) / a;
    const T t13 = b * t7 * t10 + t6 * t3 * a_minus_b - T(9) * t2 * D;
    const T t14 = T(16) * t11 * b * t12 + T(9) * t13 * t12 + T(72) * c * t2;
    G_ap = in.w[0] * t2 - (T(1) / T(9)) * t11 * in.w[1] * t12 - (T(1) / T(72)) * t14 * in.w[2] * t12;
    const T t15 = t9 * t8;
    const T t16 = t5 * t4;
    G_ab = -(T(1) / T(72)) * in.w[1] * t14 * t12 - (T(1) / T(9)) * t11 * in.w[0] * t12 - (T(1) / T(504)) * (T(14) * b * t14 * t12 - T(56) * t11 * c * t12 - T(9) * (T(8) * t7 * t15 - T(7) * b * t13 * t12 - T(8) * t16 * t3) * t12) * in.w[2] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t23 * t22;
    const T t26 = t19 * t18;
    const T t27 = T(1) / D;
    const T t28 = T(5) * t25 * t21 * a_minus_b + T(5) * b * t17 * t26 + T(2) * (T(3) * b * t17 * t19 + T(4) * (T(2) * (t21 * a_minus_b + b * t17) * t27 * a + t22 * t21 * a_minus_b + b * t17 * t18) * t27 * a + T(3) * t23 * t21 * a_minus_b) * t27 * a;
    const T t29 = T(35) * b * t17 * t20 + T(35) * t24 * t21 * a_minus_b + T(8) * t28 * t27 * a;
    const T t30 = T(35) * t24 * t21 - T(35) * t17 * t20 - b * t29 * t27;
    const T t31 = T(1) / a;
    const T t32 = c * t29 * t27 + T(2) * b * t30 * t31 - T(9) * t28 * t27;
    G_ap = (T(1) / T(315)) * in.w[0] * t29 * t27 - (T(1) / T(315)) * t32 * in.w[2] * t31 - (T(1) / T(315)) * in.w[1] * t30 * t31;
    G_ab = (T(1) / T(315)) * (c * t30 * t31 + T(9) * (b * t28 * t27 + T(5) * t17 * t26 - T(5) * t25 * t21) * t31 - T(2) * b * t32 * t31) * in.w[2] * t31 - (T(1) / T(315)) * t32 * in.w[1] * t31 - (T(1) / T(315)) * in.w[0] * t30 * t31;
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 56 +, 151 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t5 * t5;
    const T t13 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t14 = a_minus_b * t7 * t11 + t3 * b * t12 - T(9) * t13 * D;
    const T t15 = T(8) * t3 * t6 - T(8) * t7 * t10 - T(7) * t14 * t2 * b;
    F = (T(1) / T(56)) * in.w[1] * t2 * t15 - (T(1) / T(336)) * t2 * in.w[2] * (T(7) * t2 * (T(7) * t14 * D * t2 + T(8) * a_minus_b * t7 * t10 + T(8) * t3 * b * t6) - T(42) * t14 * t2 * c - T(12) * t2 * t15 * b) - (T(1) / T(8)) * t14 * t2 * in.w[0];
    const T t16 = T(9) * t13 * b + t3 * t12 - t7 * t11;
    const T t17 = T(9) * t14 * t2 + T(72) * t13 * c - T(16) * t16 * t2 * b;
    G_ap = t13 * in.w[0] + (T(1) / T(9)) * t16 * in.w[1] * t2 - (T(1) / T(72)) * t2 * in.w[2] * t17;
    G_ab = (T(1) / T(9)) * t16 * t2 * in.w[0] - (T(1) / T(504)) * (T(56) * t16 * t2 * c + T(14) * t2 * b * t17 - T(9) * t2 * t15) * t2 * in.w[2] - (T(1) / T(72)) * in.w[1] * t2 * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / D;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = T(3) * a_minus_b * t19 * t21 + T(3) * t23 * b * t25 + T(4) * t18 * a * (T(2) * t18 * a * (a_minus_b * t19 + t23 * b) + t23 * b * t24 + a_minus_b * t19 * t20);
    const T t28 = T(5) * a_minus_b * t19 * t22 + T(5) * t23 * b * t26 + T(2) * t18 * a * t27;
    const T t29 = T(1) / a;
    const T t30 = T(5) * t23 * t26 + t18 * b * t28 - T(5) * t19 * t22;
    F = (T(1) / T(35)) * t18 * in.w[0] * t28 + (T(1) / T(35)) * in.w[1] * t29 * t30 - (T(1) / T(105)) * t29 * in.w[2] * (T(3) * t18 * t28 * c - T(7) * t18 * t27 - T(6) * t29 * b * t30);
    const T t31 = t21 * t21;
    const T t32 = t25 * t25;
    const T t33 = T(35) * a_minus_b * t19 * t31 + T(8) * t18 * a * t28 + T(35) * t23 * b * t32;
    const T t34 = T(35) * t23 * t32 + t18 * t33 * b - T(35) * t19 * t31;
    const T t35 = t18 * t33 * c - T(9) * t18 * t28 - T(2) * t29 * b * t34;
    G_ap = (T(1) / T(315)) * t18 * t33 * in.w[0] + (T(1) / T(315)) * in.w[1] * t29 * t34 - (T(1) / T(315)) * t29 * in.w[2] * t35;
    G_ab = (T(1) / T(315)) * t29 * in.w[0] * t34 - (T(1) / T(315)) * in.w[1] * t29 * t35 - (T(1) / T(315)) * t29 * in.w[2] * (t29 * t34 * c + T(2) * t29 * b * t35 - T(9) * t29 * t30);
  }
  const T g_factor = -T(9) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 46 +, 108 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w3_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(6) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.24 a min(q(0), q(1)): recurrence (1) downwards from J_9 = J_downward(…)
    const T t2 = J_downward<T>(T(9), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t6 * t3 - T(7) * t2 * b - t10 * t7;
    const T t12 = T(1) / a;
    const T t13 = t10 * t7 * b + a_minus_b * t6 * t3 - T(7) * t2 * D;
    const T t14 = T(42) * t2 * c + T(7) * t12 * t13 + T(12) * t11 * t12 * b;
    F = t2 * in.w[0] + (T(1) / T(210)) * (T(30) * c * t11 * t12 - T(7) * t12 * (T(6) * t5 * t3 + T(5) * t12 * t13 * b - T(6) * t9 * t7) - T(10) * t12 * b * t14) * in.w[3] * t12 - (T(1) / T(42)) * in.w[2] * t12 * t14 - (T(1) / T(7)) * t11 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / a;
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(3) * a_minus_b * t19 * t17 + T(4) * (t21 * t20 * b + T(2) * t16 * (a_minus_b * t17 + t20 * b) * a + a_minus_b * t18 * t17) * t16 * a + T(3) * t22 * t20 * b;
    const T t24 = t22 * t21;
    const T t25 = t19 * t18;
    const T t26 = T(2) * t16 * a * t23 + T(5) * t24 * t20 * b + T(5) * a_minus_b * t25 * t17;
    const T t27 = t16 * t26 * b + T(5) * t24 * t20 - T(5) * t25 * t17;
    const T t28 = T(6) * t27 * t15 * b + T(7) * t16 * t23 - T(3) * c * t16 * t26;
    F = (T(1) / T(105)) * in.w[2] * t15 * t28 + (T(1) / T(35)) * t16 * in.w[0] * t26 + (T(1) / T(35)) * t27 * t15 * in.w[1] - (T(1) / T(105)) * in.w[3] * t15 * (T(3) * c * t27 * t15 + T(7) * t15 * (T(3) * t19 * t17 - T(3) * t22 * t20 - t16 * b * t23) - T(2) * t15 * t28 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 58 +, 154 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i9_w3_grad(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t4 + T(9) * t2 * b - t8 * t11;
    const T t13 = t8 * a_minus_b * t11 + t7 * b * t4 - T(9) * t2 * D;
    const T t14 = T(72) * c * t2 + T(9) * t3 * t13 - T(16) * t3 * t12 * b;
    const T t15 = t6 * t5;
    const T t16 = t10 * t9;
    const T t17 = T(8) * t15 * t4 - T(8) * t8 * t16 - T(7) * t3 * t13 * b;
    const T t18 = T(14) * t14 * t3 * b + T(56) * c * t3 * t12 - T(9) * t17 * t3;
    G_ap = t2 * in.w[0] + (T(1) / T(9)) * t3 * t12 * in.w[1] - (T(1) / T(72)) * t14 * in.w[2] * t3 - (T(1) / T(504)) * t18 * t3 * in.w[3];
    G_ab = (T(1) / T(9)) * t3 * in.w[0] * t12 - (T(1) / T(72)) * t14 * t3 * in.w[1] - (T(1) / T(504)) * in.w[2] * t18 * t3 - (T(1) / T(1008)) * t3 * in.w[3] * (T(4) * t18 * t3 * b - T(14) * t14 * c * t3 - T(3) * (T(42) * c * t3 * t13 + T(12) * t17 * t3 * b - T(7) * (T(8) * t8 * a_minus_b * t16 + T(8) * t15 * b * t4 + T(7) * D * t3 * t13) * t3) * t3);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(3) * t24 * a_minus_b * t26 + T(4) * (T(2) * t23 * a * (t24 * a_minus_b + b * t19) + t20 * b * t19 + t24 * a_minus_b * t25) * t23 * a + T(3) * t21 * b * t19;
    const T t28 = t26 * t25;
    const T t29 = t21 * t20;
    const T t30 = T(2) * t27 * t23 * a + T(5) * t24 * a_minus_b * t28 + T(5) * t29 * b * t19;
    const T t31 = t26 * t26;
    const T t32 = T(8) * t23 * a * t30 + T(35) * t24 * a_minus_b * t31 + T(35) * t22 * b * t19;
    const T t33 = T(35) * t22 * t19 + t32 * t23 * b - T(35) * t24 * t31;
    const T t34 = T(1) / a;
    const T t35 = c * t32 * t23 - T(2) * t33 * t34 * b - T(9) * t23 * t30;
    const T t36 = t23 * b * t30 + T(5) * t29 * t19 - T(5) * t24 * t28;
    const T t37 = c * t33 * t34 + T(2) * t34 * t35 * b - T(9) * t34 * t36;
    G_ap = (T(1) / T(315)) * t33 * t34 * in.w[1] + (T(1) / T(315)) * t32 * t23 * in.w[0] - (T(1) / T(315)) * in.w[2] * t34 * t35 - (T(1) / T(315)) * t37 * t34 * in.w[3];
    G_ab = (T(1) / T(315)) * t33 * t34 * in.w[0] - (T(1) / T(315)) * in.w[2] * t37 * t34 - (T(1) / T(315)) * t34 * in.w[3] * (T(2) * t37 * t34 * b - T(3) * (T(7) * t27 * t23 + T(6) * t34 * t36 * b - T(3) * c * t23 * t30) * t34 - c * t34 * t35) - (T(1) / T(315)) * t34 * t35 * in.w[1];
  }
  const T g_factor = -T(9) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 65 +, 181 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i9_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(9) * t3 * D - t4 * a_minus_b * t7 - t8 * b * t11;
    const T t13 = t10 * t9;
    const T t14 = t6 * t5;
    const T t15 = T(7) * t2 * t12 * b + T(8) * t8 * t13 - T(8) * t4 * t14;
    const T t16 = T(8) * t4 * a_minus_b * t14 + T(8) * t8 * b * t13 - T(7) * t2 * D * t12;
    const T t17 = T(12) * t2 * t15 * b - T(7) * t2 * t16 - T(42) * t2 * t12 * c;
    F = (T(1) / T(56)) * t2 * t15 * in.w[1] + (T(1) / T(336)) * in.w[2] * t2 * t17 + (T(1) / T(1680)) * t2 * in.w[3] * (T(10) * t2 * t17 * b - T(30) * t2 * t15 * c - T(7) * t2 * (T(48) * t4 * t6 + T(5) * t2 * t16 * b - T(48) * t8 * t10)) + (T(1) / T(8)) * t2 * t12 * in.w[0];
    const T t18 = t4 * t7 - t8 * t11 - T(9) * t3 * b;
    const T t19 = T(9) * t2 * t12 - T(72) * t3 * c - T(16) * t18 * t2 * b;
    const T t20 = T(14) * t2 * b * t19 + T(56) * t18 * t2 * c + T(9) * t2 * t15;
    G_ap = t3 * in.w[0] + (T(1) / T(504)) * t20 * t2 * in.w[3] + (T(1) / T(72)) * in.w[2] * t2 * t19 - (T(1) / T(9)) * t18 * t2 * in.w[1];
    G_ab = (T(1) / T(504)) * t20 * in.w[2] * t2 + (T(1) / T(72)) * t2 * t19 * in.w[1] + (T(1) / T(1008)) * t2 * (T(3) * t2 * t17 + T(4) * t20 * t2 * b - T(14) * t2 * t19 * c) * in.w[3] - (T(1) / T(9)) * t18 * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = T(1) / D;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t24 * t24;
    const T t29 = T(4) * a * t22 * (t23 * b * t24 + T(2) * (t23 * b + t25 * a_minus_b) * a * t22 + t25 * a_minus_b * t26) + T(3) * t25 * a_minus_b * t27 + T(3) * t23 * b * t28;
    const T t30 = t28 * t24;
    const T t31 = t27 * t26;
    const T t32 = T(2) * a * t22 * t29 + T(5) * t25 * a_minus_b * t31 + T(5) * t23 * b * t30;
    const T t33 = T(5) * t23 * t30 + t22 * b * t32 - T(5) * t25 * t31;
    const T t34 = T(7) * t22 * t29 + T(6) * t21 * t33 * b - T(3) * t22 * t32 * c;
    F = (T(1) / T(105)) * in.w[2] * t21 * t34 + (T(1) / T(35)) * t22 * in.w[0] * t32 + (T(1) / T(35)) * t21 * t33 * in.w[1] - (T(1) / T(105)) * t21 * in.w[3] * (T(3) * t21 * t33 * c - T(2) * t21 * b * t34 - T(7) * t21 * (t22 * t29 * b + T(3) * t23 * t28 - T(3) * t25 * t27));
    const T t35 = t27 * t27;
    const T t36 = t28 * t28;
    const T t37 = T(35) * t25 * a_minus_b * t35 + T(8) * a * t22 * t32 + T(35) * t23 * b * t36;
    const T t38 = t37 * t22 * b + T(35) * t23 * t36 - T(35) * t25 * t35;
    const T t39 = T(9) * t22 * t32 + T(2) * t38 * t21 * b - t37 * t22 * c;
    const T t40 = t38 * t21 * c - T(9) * t21 * t33 - T(2) * t39 * t21 * b;
    G_ap = (T(1) / T(315)) * t37 * t22 * in.w[0] + (T(1) / T(315)) * t39 * in.w[2] * t21 + (T(1) / T(315)) * t38 * t21 * in.w[1] - (T(1) / T(315)) * t21 * in.w[3] * t40;
    G_ab = (T(1) / T(315)) * t38 * t21 * in.w[0] + (T(1) / T(315)) * (T(3) * t21 * t34 - t39 * t21 * c - T(2) * t21 * b * t40) * t21 * in.w[3] + (T(1) / T(315)) * t39 * t21 * in.w[1] - (T(1) / T(315)) * in.w[2] * t21 * t40;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 39 +, 73 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w0_f(const SegmentInput<T>& in) {
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t6 * t6;
    F = (T(1) / T(384)) * t4 * in.w[0] * (T(7) * t4 * a * (T(8) * t7 * a_minus_b + T(8) * t10 * b + T(5) * (T(2) * t9 * b + T(2) * t6 * a_minus_b + T(3) * t4 * a * (a * J2 + t5 * a_minus_b + t8 * b)) * t4 * a) + T(48) * t11 * b + T(48) * t12 * a_minus_b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 46 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i10_w0_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(1) / a;
    G_ab = (T(1) / T(10)) * in.w[0] * (T(10) * t2 * b + t6 - t10) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / q1;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t14;
    const T t18 = T(1) / D;
    const T t19 = t15 * t14;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t21 * t21;
    const T t24 = t23 * t20;
    const T t25 = T(128) * t17 * a_minus_b + T(3) * t18 * a * (T(48) * t16 * a_minus_b + T(7) * (T(8) * t19 * a_minus_b + T(5) * (T(3) * (b * t20 + J2 * a + t14 * a_minus_b) * t18 * a + T(2) * t15 * a_minus_b + T(2) * b * t21) * t18 * a + T(8) * b * t22) * t18 * a + T(48) * b * t23) + T(128) * b * t24;
    G_ap = (T(1) / T(1280)) * t25 * t18 * in.w[0];
    const T t26 = T(1) / a;
    G_ab = (T(1) / T(1280)) * (T(128) * t24 + b * t25 * t18 - T(128) * t17) * in.w[0] * t26;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 46 +, 103 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(1) / a;
    F = (T(1) / T(9)) * in.w[0] * (T(10) * t2 * D - a_minus_b * t6 - b * t10) * t11;
    G_ap = in.w[0] * t2;
    G_ab = -(T(1) / T(10)) * in.w[0] * (t6 - t10 - T(10) * t2 * b) * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / q1;
    const T t15 = T(1) / c;
    const T t16 = T(1) / D;
    const T t17 = t15 * t15;
    const T t18 = t14 * t14;
    const T t19 = t17 * t15;
    const T t20 = t18 * t14;
    const T t21 = t18 * t18;
    const T t22 = t17 * t17;
    const T t23 = T(7) * (T(5) * (T(3) * (J2 * a + a_minus_b * t14 + b * t15) * a * t16 + T(2) * b * t17 + T(2) * a_minus_b * t18) * a * t16 + T(8) * b * t19 + T(8) * a_minus_b * t20) * a * t16 + T(48) * a_minus_b * t21 + T(48) * b * t22;
    F = (T(1) / T(384)) * in.w[0] * t23 * t16;
    const T t24 = t21 * t14;
    const T t25 = t22 * t15;
    const T t26 = T(128) * a_minus_b * t24 + T(3) * t23 * a * t16 + T(128) * b * t25;
    G_ap = (T(1) / T(1280)) * in.w[0] * t26 * t16;
    const T t27 = T(1) / a;
    G_ab = -(T(1) / T(1280)) * in.w[0] * (T(128) * t24 - T(128) * t25 - b * t26 * t16) * t27;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 42 +, 80 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w1_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / a;
    F = in.w[0] * t2 - (T(1) / T(8)) * (t5 - T(8) * t2 * b - t8) * t9 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / D;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / q1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t17 * t16;
    const T t20 = t14 * t13;
    const T t21 = T(48) * t15 * b + T(48) * a_minus_b * t18 + T(7) * t12 * a * (T(5) * (T(2) * t14 * b + T(3) * t12 * a * (a_minus_b * t16 + t13 * b + J2 * a) + T(2) * a_minus_b * t17) * t12 * a + T(8) * a_minus_b * t19 + T(8) * t20 * b);
    const T t22 = T(1) / a;
    F = (T(1) / T(384)) * in.w[0] * t12 * t21 - (T(1) / T(384)) * (T(48) * t18 - t12 * t21 * b - T(48) * t15) * t22 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 50 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i10_w1_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = t6 + T(10) * t2 * b - t10;
    const T t12 = T(1) / a;
    G_ap = t2 * in.w[0] + (T(1) / T(10)) * in.w[1] * t11 * t12;
    G_ab = (T(1) / T(10)) * t11 * in.w[0] * t12 + (T(1) / T(45)) * in.w[1] * (T(9) * b * t11 * t12 + T(5) * (T(10) * t2 * D - b * t6 - t10 * a_minus_b) * t12 - T(45) * t2 * c) * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / D;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t16 * t15;
    const T t24 = t21 * t21;
    const T t25 = T(48) * b * t17 + T(7) * t19 * a * (T(8) * t22 * a_minus_b + T(5) * (T(2) * t21 * a_minus_b + T(3) * (b * t15 + J2 * a + t20 * a_minus_b) * t19 * a + T(2) * b * t16) * t19 * a + T(8) * b * t23) + T(48) * t24 * a_minus_b;
    const T t26 = t24 * t20;
    const T t27 = T(3) * t25 * t19 * a + T(128) * b * t18 + T(128) * t26 * a_minus_b;
    const T t28 = T(128) * t18 + b * t27 * t19 - T(128) * t26;
    const T t29 = T(1) / a;
    G_ap = (T(1) / T(1280)) * in.w[1] * t28 * t29 + (T(1) / T(1280)) * t27 * in.w[0] * t19;
    G_ab = (T(1) / T(1280)) * t28 * in.w[0] * t29 + (T(1) / T(3840)) * in.w[1] * (T(10) * t25 * t19 + T(6) * b * t28 * t29 - T(3) * t27 * c * t19) * t29;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 53 +, 124 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t12 = b * t6 + a_minus_b * t10 - T(10) * D * t11;
    F = -(T(1) / T(9)) * in.w[0] * t2 * t12 - (T(1) / T(72)) * in.w[1] * t2 * (T(9) * t9 + T(8) * t2 * b * t12 - T(9) * t5);
    const T t13 = t10 - T(10) * b * t11 - t6;
    G_ap = in.w[0] * t11 - (T(1) / T(10)) * in.w[1] * t2 * t13;
    G_ab = -(T(1) / T(45)) * in.w[1] * t2 * (T(5) * t2 * t12 + T(45) * t11 * c + T(9) * t2 * t13 * b) - (T(1) / T(10)) * in.w[0] * t2 * t13;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / D;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t18 * t17;
    const T t23 = t21 * t20;
    const T t24 = t21 * t21;
    const T t25 = T(48) * b * t19 + T(7) * t16 * a * (T(5) * t16 * a * (T(2) * b * t18 + T(3) * t16 * a * (a_minus_b * t20 + b * t17 + J2 * a) + T(2) * a_minus_b * t21) + T(8) * b * t22 + T(8) * a_minus_b * t23) + T(48) * a_minus_b * t24;
    const T t26 = T(1) / a;
    F = (T(1) / T(384)) * in.w[0] * t16 * t25 - (T(1) / T(384)) * (T(48) * t24 - t16 * t25 * b - T(48) * t19) * in.w[1] * t26;
    const T t27 = t19 * t17;
    const T t28 = t24 * t20;
    const T t29 = T(128) * b * t27 + T(3) * t16 * a * t25 + T(128) * a_minus_b * t28;
    const T t30 = t16 * b * t29 + T(128) * t27 - T(128) * t28;
    G_ap = (T(1) / T(1280)) * in.w[0] * t16 * t29 + (T(1) / T(1280)) * t30 * in.w[1] * t26;
    G_ab = (T(1) / T(1280)) * in.w[0] * t30 * t26 - (T(1) / T(3840)) * in.w[1] * t26 * (T(3) * t16 * t29 * c - T(10) * t16 * t25 - T(6) * t30 * t26 * b);
  }
  const T g_factor = -T(10) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 45 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w2_f(const SegmentInput<T>& in) {
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
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 + T(8) * t2 * b - t8;
    const T t10 = T(1) / a;
    F = t2 * in.w[0] + (T(1) / T(8)) * in.w[1] * t9 * t10 + (T(1) / T(28)) * (T(4) * t10 * (T(8) * D * t2 - t5 * b - a_minus_b * t8) + T(7) * t9 * t10 * b - T(28) * c * t2) * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = T(1) / D;
    const T t17 = t14 * t13;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = T(8) * t17 * b + T(8) * a_minus_b * t20 + T(5) * t16 * a * (T(2) * t14 * b + T(2) * a_minus_b * t19 + T(3) * (a_minus_b * t18 + a * J2 + t13 * b) * t16 * a);
    const T t22 = t19 * t19;
    const T t23 = T(7) * t16 * a * t21 + T(48) * t15 * b + T(48) * a_minus_b * t22;
    const T t24 = T(48) * t15 + t16 * t23 * b - T(48) * t22;
    const T t25 = T(1) / a;
    F = (T(1) / T(384)) * in.w[1] * t24 * t25 + (T(1) / T(384)) * t25 * in.w[2] * (T(2) * t24 * t25 * b + T(8) * t16 * t21 - c * t16 * t23) + (T(1) / T(384)) * t16 * t23 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 56 +, 131 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i10_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(10) * t2 * b + t6 - t10;
    const T t12 = T(1) / a;
    const T t13 = T(10) * D * t2 - a_minus_b * t10 - t6 * b;
    const T t14 = T(5) * t12 * t13 + T(9) * t11 * t12 * b - T(45) * c * t2;
    G_ap = (T(1) / T(10)) * in.w[1] * t11 * t12 + (T(1) / T(45)) * in.w[2] * t12 * t14 + t2 * in.w[0];
    G_ab = (T(1) / T(360)) * (T(16) * t12 * t14 * b + T(5) * t12 * (T(9) * t5 + T(8) * t12 * b * t13 - T(9) * t9) - T(36) * c * t11 * t12) * in.w[2] * t12 + (T(1) / T(45)) * in.w[1] * t12 * t14 + (T(1) / T(10)) * t11 * t12 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / D;
    const T t26 = t18 * t17;
    const T t27 = t22 * t21;
    const T t28 = T(7) * t25 * a * (T(8) * t26 * b + T(5) * (T(2) * t18 * b + T(3) * t25 * (a_minus_b * t21 + a * J2 + t17 * b) * a + T(2) * a_minus_b * t22) * t25 * a + T(8) * a_minus_b * t27) + T(48) * a_minus_b * t23 + T(48) * t19 * b;
    const T t29 = T(128) * a_minus_b * t24 + T(3) * t25 * t28 * a + T(128) * t20 * b;
    const T t30 = T(128) * t20 + t29 * t25 * b - T(128) * t24;
    const T t31 = T(1) / a;
    const T t32 = T(6) * t30 * t31 * b + T(10) * t25 * t28 - T(3) * t29 * c * t25;
    G_ap = (T(1) / T(1280)) * in.w[1] * t30 * t31 + (T(1) / T(1280)) * t29 * t25 * in.w[0] + (T(1) / T(3840)) * in.w[2] * t31 * t32;
    G_ab = (T(1) / T(1280)) * t30 * t31 * in.w[0] + (T(1) / T(3840)) * in.w[1] * t31 * t32 + (T(1) / T(3840)) * (T(2) * t31 * t32 * b + T(10) * t31 * (t25 * t28 * b + T(48) * t19 - T(48) * t23) - T(3) * c * t30 * t31) * in.w[2] * t31;
  }
  const T g_factor = -T(10) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 60 +, 148 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = T(10) * D * t3 - a_minus_b * t7 - b * t11;
    const T t13 = T(8) * t2 * b * t12 + T(9) * t10 - T(9) * t6;
    F = (T(1) / T(252)) * (T(7) * t13 * t2 * b + T(4) * (T(8) * D * t2 * t12 - T(9) * a_minus_b * t6 - T(9) * b * t10) * t2 - T(28) * t2 * t12 * c) * in.w[2] * t2 + (T(1) / T(72)) * t13 * t2 * in.w[1] + (T(1) / T(9)) * t2 * in.w[0] * t12;
    const T t14 = T(10) * b * t3 + t11 - t7;
    const T t15 = T(9) * t14 * t2 * b + T(5) * t2 * t12 - T(45) * t3 * c;
    G_ap = (T(1) / T(45)) * in.w[2] * t2 * t15 + in.w[0] * t3 + (T(1) / T(10)) * t14 * t2 * in.w[1];
    G_ab = (T(1) / T(45)) * t2 * in.w[1] * t15 + (T(1) / T(10)) * t14 * t2 * in.w[0] + (T(1) / T(360)) * (T(5) * t13 * t2 + T(16) * t2 * b * t15 - T(36) * t14 * t2 * c) * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = atan2(t16, c_minus_b) * t17;
    const T t18 = T(1) / D;
    const T t19 = T(1) / c;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t19 * t19;
    const T t23 = t22 * t19;
    const T t24 = t21 * t20;
    const T t25 = T(5) * t18 * a * (T(3) * (J2 * a + b * t19 + a_minus_b * t20) * t18 * a + T(2) * a_minus_b * t21 + T(2) * b * t22) + T(8) * b * t23 + T(8) * a_minus_b * t24;
    const T t26 = t21 * t21;
    const T t27 = t22 * t22;
    const T t28 = T(7) * t18 * a * t25 + T(48) * a_minus_b * t26 + T(48) * b * t27;
    const T t29 = t18 * b * t28 + T(48) * t27 - T(48) * t26;
    const T t30 = T(1) / a;
    F = (T(1) / T(384)) * (T(2) * t29 * t30 * b + T(8) * t18 * t25 - t18 * c * t28) * in.w[2] * t30 + (T(1) / T(384)) * t29 * t30 * in.w[1] + (T(1) / T(384)) * t18 * in.w[0] * t28;
    const T t31 = t26 * t20;
    const T t32 = t27 * t19;
    const T t33 = T(3) * t18 * a * t28 + T(128) * a_minus_b * t31 + T(128) * b * t32;
    const T t34 = T(128) * t31 - T(128) * t32 - t18 * t33 * b;
    const T t35 = T(3) * t18 * t33 * c + T(6) * t30 * b * t34 - T(10) * t18 * t28;
    G_ap = (T(1) / T(1280)) * t18 * t33 * in.w[0] - (T(1) / T(3840)) * t35 * in.w[2] * t30 - (T(1) / T(1280)) * t30 * in.w[1] * t34;
    G_ab = (T(1) / T(3840)) * in.w[2] * t30 * (T(10) * t29 * t30 + T(3) * t30 * c * t34 - T(2) * t35 * t30 * b) - (T(1) / T(3840)) * t35 * t30 * in.w[1] - (T(1) / T(1280)) * t30 * in.w[0] * t34;
  }
  const T g_factor = -T(10) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 50 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w3_f(const SegmentInput<T>& in) {
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
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.28 a min(q(0), q(1)): recurrence (1) downwards from J_10 = J_downward(…)
    const T t2 = J_downward<T>(T(10), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 - T(8) * t2 * b - t8;
    const T t10 = T(1) / a;
    const T t11 = T(8) * D * t2 - t8 * b - a_minus_b * t5;
    const T t12 = T(28) * c * t2 + T(7) * t9 * t10 * b - T(4) * t11 * t10;
    const T t13 = t7 * t6;
    const T t14 = t4 * t3;
    F = t2 * in.w[0] - (T(1) / T(8)) * in.w[1] * t9 * t10 - (T(1) / T(28)) * t12 * in.w[2] * t10 - (T(1) / T(168)) * in.w[3] * t10 * (T(12) * t12 * t10 * b - T(21) * t9 * c * t10 - T(4) * t10 * (T(6) * t11 * t10 * b + T(7) * t13 - T(7) * t14));
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / D;
    const T t18 = T(1) / c;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t19 * t18;
    const T t25 = t22 * t21;
    const T t26 = T(8) * t24 * b + T(8) * a_minus_b * t25 + T(5) * (T(2) * t19 * b + T(3) * (a * J2 + a_minus_b * t21 + t18 * b) * t17 * a + T(2) * a_minus_b * t22) * t17 * a;
    const T t27 = T(48) * t20 * b + T(48) * a_minus_b * t23 + T(7) * t17 * a * t26;
    const T t28 = T(48) * t23 - T(48) * t20 - t17 * t27 * b;
    const T t29 = T(1) / a;
    const T t30 = c * t17 * t27 + T(2) * t28 * t29 * b - T(8) * t17 * t26;
    F = (T(1) / T(384)) * t17 * in.w[0] * t27 - (T(1) / T(384)) * in.w[1] * t28 * t29 - (T(1) / T(384)) * (T(2) * t30 * t29 * b + T(8) * (T(8) * t25 - t17 * t26 * b - T(8) * t24) * t29 - t28 * c * t29) * in.w[3] * t29 - (T(1) / T(384)) * in.w[2] * t30 * t29;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 62 +, 151 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i10_w3_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = t6 + T(10) * t7 * b - t11;
    const T t13 = T(10) * t7 * D - b * t6 - a_minus_b * t11;
    const T t14 = T(5) * t2 * t13 + T(9) * t2 * b * t12 - T(45) * t7 * c;
    const T t15 = T(9) * t5 + T(8) * t2 * b * t13 - T(9) * t10;
    const T t16 = T(5) * t2 * t15 + T(16) * t2 * b * t14 - T(36) * t2 * t12 * c;
    G_ap = (T(1) / T(10)) * t2 * t12 * in.w[1] + (T(1) / T(45)) * t2 * in.w[2] * t14 + (T(1) / T(360)) * t2 * in.w[3] * t16 + in.w[0] * t7;
    G_ab = (T(1) / T(45)) * t2 * in.w[1] * t14 + (T(1) / T(10)) * t2 * in.w[0] * t12 + (T(1) / T(360)) * t2 * in.w[2] * t16 - (T(1) / T(1260)) * t2 * in.w[3] * (T(5) * t2 * (T(28) * t2 * c * t13 - T(4) * t2 * (T(8) * t2 * D * t13 - T(9) * b * t5 - T(9) * a_minus_b * t10) - T(7) * t2 * b * t15) + T(28) * t2 * c * t14 - T(7) * t2 * b * t16);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = atan2(t17, c_minus_b) * t18;
    const T t19 = T(1) / a;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = T(1) / q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = T(1) / D;
    const T t27 = T(8) * b * t22 + T(8) * a_minus_b * t25 + T(5) * a * (T(2) * b * t21 + T(2) * a_minus_b * t24 + T(3) * a * (a_minus_b * t23 + a * J2 + b * t20) * t26) * t26;
    const T t28 = t21 * t21;
    const T t29 = t24 * t24;
    const T t30 = T(7) * a * t27 * t26 + T(48) * b * t28 + T(48) * a_minus_b * t29;
    const T t31 = t28 * t20;
    const T t32 = t29 * t23;
    const T t33 = T(128) * b * t31 + T(3) * a * t30 * t26 + T(128) * a_minus_b * t32;
    const T t34 = T(128) * t31 + b * t33 * t26 - T(128) * t32;
    const T t35 = T(10) * t30 * t26 + T(6) * t19 * t34 * b - T(3) * t33 * c * t26;
    const T t36 = T(48) * t28 + b * t30 * t26 - T(48) * t29;
    const T t37 = T(3) * t19 * t34 * c - T(10) * t19 * t36 - T(2) * t19 * b * t35;
    G_ap = (T(1) / T(3840)) * t19 * t35 * in.w[2] + (T(1) / T(1280)) * t19 * t34 * in.w[1] + (T(1) / T(1280)) * in.w[0] * t33 * t26 - (T(1) / T(3840)) * t19 * in.w[3] * t37;
    G_ab = (T(1) / T(1280)) * t19 * t34 * in.w[0] + (T(1) / T(3840)) * t19 * t35 * in.w[1] - (T(1) / T(3840)) * t19 * in.w[3] * (T(2) * t19 * b * t37 + t19 * t35 * c - T(10) * t19 * (T(8) * t27 * t26 + T(2) * t19 * b * t36 - t30 * c * t26)) - (T(1) / T(3840)) * t19 * t37 * in.w[2];
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 69 +, 175 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i10_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = t5 * t3;
    const T t11 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t12 = b * t9 + a_minus_b * t10 - T(10) * D * t11;
    const T t13 = T(9) * t5 + T(8) * t2 * b * t12 - T(9) * t8;
    const T t14 = T(9) * b * t8 + T(9) * a_minus_b * t5 + T(8) * D * t2 * t12;
    const T t15 = t4 * t3;
    const T t16 = t7 * t6;
    const T t17 = T(4) * t2 * t14 + T(7) * t2 * t13 * b - T(28) * t2 * t12 * c;
    F = -(T(1) / T(72)) * t2 * t13 * in.w[1] - (T(1) / T(504)) * in.w[3] * t2 * (T(4) * (T(2) * t2 * t14 * b + T(21) * t15 - T(21) * t16) * t2 + T(4) * t17 * t2 * b - T(7) * t2 * t13 * c) - (T(1) / T(9)) * t2 * in.w[0] * t12 - (T(1) / T(252)) * t17 * t2 * in.w[2];
    const T t18 = t10 - t9 - T(10) * b * t11;
    const T t19 = T(5) * t2 * t12 + T(9) * t2 * b * t18 + T(45) * t11 * c;
    const T t20 = T(16) * t19 * t2 * b + T(5) * t2 * t13 - T(36) * t2 * c * t18;
    G_ap = in.w[0] * t11 - (T(1) / T(45)) * t19 * t2 * in.w[2] - (T(1) / T(360)) * in.w[3] * t2 * t20 - (T(1) / T(10)) * t2 * in.w[1] * t18;
    G_ab = -(T(1) / T(10)) * t2 * in.w[0] * t18 - (T(1) / T(1260)) * in.w[3] * t2 * (T(5) * t17 * t2 + T(7) * t2 * b * t20 - T(28) * t19 * t2 * c) - (T(1) / T(360)) * t2 * t20 * in.w[2] - (T(1) / T(45)) * t19 * t2 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(D);
    const T t22 = T(1) / t21;
    const T J2 = t22 * atan2(t21, c_minus_b);
    const T t23 = T(1) / a;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(1) / c;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = T(1) / D;
    const T t31 = t25 * t24;
    const T t32 = t28 * t27;
    const T t33 = T(8) * a_minus_b * t31 + T(8) * b * t32 + T(5) * t30 * a * (T(2) * a_minus_b * t25 + T(2) * b * t28 + T(3) * t30 * a * (a * J2 + b * t27 + a_minus_b * t24));
    const T t34 = T(48) * b * t29 + T(48) * a_minus_b * t26 + T(7) * t30 * a * t33;
    const T t35 = T(48) * t26 - T(48) * t29 - t30 * b * t34;
    const T t36 = t30 * t34 * c + T(2) * t23 * b * t35 - T(8) * t30 * t33;
    F = (T(1) / T(384)) * in.w[3] * t23 * (t23 * t35 * c - T(2) * t23 * t36 * b - T(8) * (T(8) * t31 - t30 * t33 * b - T(8) * t32) * t23) + (T(1) / T(384)) * t30 * in.w[0] * t34 - (T(1) / T(384)) * t23 * t36 * in.w[2] - (T(1) / T(384)) * t23 * in.w[1] * t35;
    const T t37 = t29 * t27;
    const T t38 = t26 * t24;
    const T t39 = T(128) * b * t37 + T(128) * a_minus_b * t38 + T(3) * t30 * a * t34;
    const T t40 = T(128) * t38 - T(128) * t37 - t30 * t39 * b;
    const T t41 = T(6) * t23 * b * t40 + T(3) * t30 * t39 * c - T(10) * t30 * t34;
    const T t42 = T(2) * t23 * b * t41 + T(10) * t23 * t35 - T(3) * t23 * c * t40;
    G_ap = (T(1) / T(1280)) * t30 * in.w[0] * t39 - (T(1) / T(3840)) * in.w[3] * t23 * t42 - (T(1) / T(3840)) * t23 * in.w[2] * t41 - (T(1) / T(1280)) * t23 * in.w[1] * t40;
    G_ab = -(T(1) / T(1280)) * t23 * in.w[0] * t40 - (T(1) / T(3840)) * t23 * t42 * in.w[2] - (T(1) / T(3840)) * (T(2) * t23 * b * t42 + T(10) * t23 * t36 - t23 * c * t41) * in.w[3] * t23 - (T(1) / T(3840)) * t23 * in.w[1] * t41;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 37 +, 82 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w0_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t5 * t4;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    F = (T(1) / T(315)) * t2 * in.w[0] * (T(35) * a_minus_b * t3 * t6 + T(8) * t2 * a * (T(5) * a_minus_b * t3 * t7 + T(5) * t11 * t8 * b + T(2) * t2 * a * (T(4) * (t9 * t8 * b + T(2) * t2 * a * (t8 * b + a_minus_b * t3) + a_minus_b * t3 * t4) * t2 * a + T(3) * a_minus_b * t3 * t5 + T(3) * t10 * t8 * b)) + T(35) * t12 * t8 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 44 +, 112 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i11_w0_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / a;
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
    G_ab = (T(1) / T(11)) * t3 * in.w[0] * (t4 * t8 + T(11) * b * t2 - t9 * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t16 * t16;
    const T t21 = t20 * t16;
    const T t22 = t19 * t18;
    const T t23 = t19 * t19;
    const T t24 = t20 * t20;
    const T t25 = t23 * t18;
    const T t26 = t24 * t16;
    const T t27 = T(2) * a * t14 * (T(8) * a * t14 * (T(2) * a * t14 * (T(4) * a * t14 * (b * t15 * t16 + t17 * a_minus_b * t18 + T(2) * a * t14 * (b * t15 + t17 * a_minus_b)) + T(3) * t17 * a_minus_b * t19 + T(3) * b * t15 * t20) + T(5) * b * t15 * t21 + T(5) * t17 * a_minus_b * t22) + T(35) * t17 * a_minus_b * t23 + T(35) * b * t15 * t24) + T(63) * t17 * a_minus_b * t25 + T(63) * b * t15 * t26;
    G_ap = (T(1) / T(693)) * t27 * t14 * in.w[0];
    const T t28 = T(1) / a;
    G_ab = (T(1) / T(693)) * t28 * in.w[0] * (t27 * t14 * b + T(63) * t15 * t26 - T(63) * t17 * t25);
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 44 +, 116 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
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
    const T t13 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    F = -(T(1) / T(10)) * in.w[0] * t2 * (b * t7 * t3 + t8 * a_minus_b * t12 - T(11) * D * t13);
    G_ap = in.w[0] * t13;
    G_ab = (T(1) / T(11)) * in.w[0] * t2 * (T(11) * t13 * b + t7 * t3 - t8 * t12);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t17 * t16;
    const T t23 = t21 * t20;
    const T t24 = t21 * t21;
    const T t25 = T(35) * b * t18 * t15 + T(8) * t14 * a * (T(2) * t14 * a * (T(3) * b * t17 * t15 + T(4) * t14 * a * (t19 * a_minus_b * t20 + b * t16 * t15 + T(2) * t14 * a * (b * t15 + t19 * a_minus_b)) + T(3) * t19 * a_minus_b * t21) + T(5) * b * t22 * t15 + T(5) * t19 * a_minus_b * t23) + T(35) * t19 * a_minus_b * t24;
    F = (T(1) / T(315)) * t14 * in.w[0] * t25;
    const T t26 = t18 * t16;
    const T t27 = t24 * t20;
    const T t28 = T(63) * b * t26 * t15 + T(2) * t14 * a * t25 + T(63) * t19 * a_minus_b * t27;
    G_ap = (T(1) / T(693)) * t14 * in.w[0] * t28;
    const T t29 = T(1) / a;
    G_ab = -(T(1) / T(693)) * in.w[0] * t29 * (T(63) * t19 * t27 - T(63) * t26 * t15 - t14 * b * t28);
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 40 +, 91 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w1_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    F = in.w[0] * t2 + (T(1) / T(9)) * in.w[1] * t3 * (t7 * t4 + T(9) * t2 * b - t8 * t11);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = T(1) / a;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / D;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t15 * t14;
    const T t22 = t20 * t19;
    const T t23 = t20 * t20;
    const T t24 = T(8) * (T(2) * (T(4) * t17 * a * (a_minus_b * t18 * t19 + t14 * t13 * b + T(2) * t17 * a * (t13 * b + a_minus_b * t18)) + T(3) * t15 * t13 * b + T(3) * a_minus_b * t18 * t20) * t17 * a + T(5) * t21 * t13 * b + T(5) * a_minus_b * t18 * t22) * t17 * a + T(35) * a_minus_b * t18 * t23 + T(35) * t16 * t13 * b;
    F = (T(1) / T(315)) * in.w[1] * t12 * (T(35) * t16 * t13 + t24 * t17 * b - T(35) * t18 * t23) + (T(1) / T(315)) * t24 * in.w[0] * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 48 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i11_w1_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
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
    const T t13 = t7 * t3 - T(11) * b * t2 - t8 * t12;
    const T t14 = T(1) / a;
    G_ap = t2 * in.w[0] - (T(1) / T(11)) * in.w[1] * t13 * t14;
    G_ab = -(T(1) / T(11)) * t13 * in.w[0] * t14 - (T(1) / T(110)) * in.w[1] * (T(110) * t2 * c + T(20) * b * t13 * t14 + T(11) * t14 * (t7 * t3 * a_minus_b + b * t8 * t12 - T(11) * t2 * D)) * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t16;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = t21 * t21;
    const T t24 = t17 * t16;
    const T t25 = t23 * t21;
    const T t26 = t23 * t23;
    const T t27 = T(35) * t18 * t15 * a_minus_b + T(8) * (T(2) * (T(4) * (b * t20 * t21 + t16 * t15 * a_minus_b + T(2) * (t15 * a_minus_b + b * t20) * a * t22) * a * t22 + T(3) * t17 * t15 * a_minus_b + T(3) * b * t20 * t23) * a * t22 + T(5) * t24 * t15 * a_minus_b + T(5) * b * t20 * t25) * a * t22 + T(35) * b * t20 * t26;
    const T t28 = t26 * t21;
    const T t29 = T(63) * t19 * t15 * a_minus_b + T(2) * t27 * a * t22 + T(63) * b * t20 * t28;
    const T t30 = T(63) * t19 * t15 - b * t29 * t22 - T(63) * t20 * t28;
    const T t31 = T(1) / a;
    G_ap = (T(1) / T(693)) * t29 * in.w[0] * t22 - (T(1) / T(693)) * in.w[1] * t30 * t31;
    G_ab = -(T(1) / T(3465)) * in.w[1] * (T(5) * t29 * c * t22 + T(10) * b * t30 * t31 - T(11) * t27 * t22) * t31 - (T(1) / T(693)) * t30 * in.w[0] * t31;
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 51 +, 139 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t4;
    const T t12 = t10 * t8;
    const T t13 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    const T t14 = b * t11 * t3 + t7 * a_minus_b * t12 - T(11) * D * t13;
    F = (T(1) / T(90)) * in.w[1] * t2 * (T(10) * t6 * t3 - T(10) * t7 * t10 - T(9) * t2 * b * t14) - (T(1) / T(10)) * t2 * in.w[0] * t14;
    const T t15 = T(11) * b * t13 + t11 * t3 - t7 * t12;
    G_ap = (T(1) / T(11)) * in.w[1] * t2 * t15 + t13 * in.w[0];
    G_ab = (T(1) / T(11)) * t2 * t15 * in.w[0] - (T(1) / T(110)) * in.w[1] * t2 * (T(11) * t2 * t14 + T(110) * t13 * c - T(20) * t2 * b * t15);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / a;
    const T t17 = T(1) / D;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t20 * t19;
    const T t26 = t24 * t23;
    const T t27 = t24 * t24;
    const T t28 = T(35) * b * t21 * t18 + T(8) * t17 * a * (T(2) * t17 * (T(4) * t17 * a * (t22 * a_minus_b * t23 + b * t19 * t18 + T(2) * t17 * a * (t22 * a_minus_b + b * t18)) + T(3) * b * t20 * t18 + T(3) * t22 * a_minus_b * t24) * a + T(5) * b * t25 * t18 + T(5) * t22 * a_minus_b * t26) + T(35) * t22 * a_minus_b * t27;
    F = (T(1) / T(315)) * in.w[1] * t16 * (t17 * t28 * b + T(35) * t21 * t18 - T(35) * t22 * t27) + (T(1) / T(315)) * t17 * t28 * in.w[0];
    const T t29 = t21 * t19;
    const T t30 = t27 * t23;
    const T t31 = T(63) * b * t29 * t18 + T(2) * t17 * a * t28 + T(63) * t22 * a_minus_b * t30;
    const T t32 = T(63) * t29 * t18 + t17 * t31 * b - T(63) * t22 * t30;
    G_ap = (T(1) / T(693)) * in.w[1] * t16 * t32 + (T(1) / T(693)) * t17 * t31 * in.w[0];
    G_ab = (T(1) / T(693)) * t16 * t32 * in.w[0] - (T(1) / T(3465)) * in.w[1] * t16 * (T(5) * t17 * t31 * c - T(10) * t16 * b * t32 - T(11) * t17 * t28);
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 43 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w2_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(8) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t3 * t6 + T(9) * b * t2 - t7 * t10;
    const T t12 = T(1) / a;
    F = t2 * in.w[0] + (T(1) / T(72)) * (T(16) * t11 * b * t12 + T(9) * (T(9) * t2 * D - t7 * a_minus_b * t10 - t3 * b * t6) * t12 - T(72) * t2 * c) * t12 * in.w[2] + (T(1) / T(9)) * t11 * in.w[1] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = T(1) / D;
    const T t22 = t15 * t14;
    const T t23 = t19 * t18;
    const T t24 = T(2) * (T(3) * t13 * a_minus_b * t15 + T(4) * t21 * a * (t17 * b * t18 + T(2) * (t17 * b + t13 * a_minus_b) * t21 * a + t13 * a_minus_b * t14) + T(3) * t17 * b * t19) * t21 * a + T(5) * t13 * a_minus_b * t22 + T(5) * t17 * b * t23;
    const T t25 = T(35) * t13 * a_minus_b * t16 + T(35) * t17 * b * t20 + T(8) * t24 * t21 * a;
    const T t26 = T(1) / a;
    const T t27 = T(35) * t17 * t20 + b * t25 * t21 - T(35) * t13 * t16;
    F = (T(1) / T(315)) * t25 * in.w[0] * t21 + (T(1) / T(315)) * t26 * (T(2) * b * t26 * t27 + T(9) * t24 * t21 - t25 * c * t21) * in.w[2] + (T(1) / T(315)) * in.w[1] * t26 * t27;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 54 +, 146 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i11_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
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
    const T t13 = t3 * t7 + T(11) * t2 * b - t8 * t12;
    const T t14 = T(1) / a;
    const T t15 = T(11) * t2 * D - t3 * t7 * b - t8 * a_minus_b * t12;
    const T t16 = T(11) * t15 * t14 + T(20) * t13 * t14 * b - T(110) * t2 * c;
    G_ap = in.w[0] * t2 + (T(1) / T(11)) * in.w[1] * t13 * t14 + (T(1) / T(110)) * t16 * in.w[2] * t14;
    G_ab = (T(1) / T(110)) * t16 * in.w[1] * t14 + (T(1) / T(990)) * (T(18) * t16 * t14 * b + T(11) * (T(10) * t3 * t6 + T(9) * t15 * t14 * b - T(10) * t8 * t11) * t14 - T(90) * c * t13 * t14) * in.w[2] * t14 + (T(1) / T(11)) * in.w[0] * t13 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = T(1) / D;
    const T t24 = t20 * t19;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t27 * t27;
    const T t30 = T(8) * t23 * (T(5) * t18 * t24 * b + T(5) * t25 * a_minus_b * t28 + T(2) * t23 * a * (T(3) * t18 * t20 * b + T(3) * t25 * a_minus_b * t27 + T(4) * t23 * a * (T(2) * t23 * a * (t25 * a_minus_b + t18 * b) + t25 * a_minus_b * t26 + t18 * t19 * b))) * a + T(35) * t18 * t21 * b + T(35) * t25 * a_minus_b * t29;
    const T t31 = t29 * t26;
    const T t32 = T(63) * t18 * t22 * b + T(2) * t23 * a * t30 + T(63) * t25 * a_minus_b * t31;
    const T t33 = T(63) * t18 * t22 + t32 * t23 * b - T(63) * t25 * t31;
    const T t34 = T(5) * c * t32 * t23 - T(10) * t17 * t33 * b - T(11) * t23 * t30;
    G_ap = (T(1) / T(693)) * in.w[1] * t17 * t33 + (T(1) / T(693)) * in.w[0] * t32 * t23 - (T(1) / T(3465)) * t34 * in.w[2] * t17;
    G_ab = (T(1) / T(3465)) * (T(11) * (t23 * t30 * b + T(35) * t18 * t21 - T(35) * t25 * t29) * t17 - T(5) * c * t17 * t33 - T(2) * t34 * t17 * b) * in.w[2] * t17 + (T(1) / T(693)) * in.w[0] * t17 * t33 - (T(1) / T(3465)) * in.w[1] * t34 * t17;
  }
  const T g_factor = -T(11) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 58 +, 163 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
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
    const T t13 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    const T t14 = a_minus_b * t7 * t11 + b * t12 * t3 - T(11) * D * t13;
    const T t15 = T(10) * t6 * t3 - T(9) * t2 * b * t14 - T(10) * t7 * t10;
    F = (T(1) / T(90)) * t2 * t15 * in.w[1] - (T(1) / T(720)) * t2 * in.w[2] * (T(9) * t2 * (T(10) * b * t6 * t3 + T(10) * a_minus_b * t7 * t10 + T(9) * D * t2 * t14) - T(16) * t2 * b * t15 - T(72) * t2 * t14 * c) - (T(1) / T(10)) * t2 * in.w[0] * t14;
    const T t16 = t12 * t3 + T(11) * b * t13 - t7 * t11;
    const T t17 = T(110) * c * t13 + T(11) * t2 * t14 - T(20) * t2 * t16 * b;
    G_ap = (T(1) / T(11)) * t2 * t16 * in.w[1] + in.w[0] * t13 - (T(1) / T(110)) * t2 * in.w[2] * t17;
    G_ab = (T(1) / T(11)) * t2 * t16 * in.w[0] + (T(1) / T(990)) * t2 * in.w[2] * (T(11) * t2 * t15 - T(90) * t2 * t16 * c - T(18) * t2 * b * t17) - (T(1) / T(110)) * t2 * t17 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t26 * t25;
    const T t29 = t21 * t20;
    const T t30 = T(5) * a_minus_b * t24 * t28 + T(2) * t23 * a * (T(4) * t23 * a * (b * t20 * t19 + T(2) * t23 * a * (a_minus_b * t24 + b * t19) + a_minus_b * t24 * t25) + T(3) * a_minus_b * t24 * t26 + T(3) * b * t21 * t19) + T(5) * b * t29 * t19;
    const T t31 = T(35) * b * t22 * t19 + T(35) * a_minus_b * t24 * t27 + T(8) * t23 * a * t30;
    const T t32 = T(35) * t22 * t19 + t23 * b * t31 - T(35) * t24 * t27;
    F = (T(1) / T(315)) * t18 * t32 * in.w[1] + (T(1) / T(315)) * t23 * in.w[0] * t31 - (T(1) / T(315)) * t18 * (t23 * c * t31 - T(9) * t23 * t30 - T(2) * t18 * t32 * b) * in.w[2];
    const T t33 = t22 * t20;
    const T t34 = t27 * t25;
    const T t35 = T(63) * a_minus_b * t24 * t34 + T(63) * b * t33 * t19 + T(2) * t23 * a * t31;
    const T t36 = T(63) * t33 * t19 + t23 * b * t35 - T(63) * t24 * t34;
    const T t37 = T(5) * t23 * c * t35 - T(11) * t23 * t31 - T(10) * t36 * t18 * b;
    G_ap = (T(1) / T(693)) * t36 * t18 * in.w[1] + (T(1) / T(693)) * t23 * in.w[0] * t35 - (T(1) / T(3465)) * t18 * in.w[2] * t37;
    G_ab = (T(1) / T(693)) * t36 * t18 * in.w[0] - (T(1) / T(3465)) * t18 * t37 * in.w[1] - (T(1) / T(3465)) * t18 * (T(2) * t18 * b * t37 + T(5) * t36 * t18 * c - T(11) * t18 * t32) * in.w[2];
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 48 +, 117 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w3_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(8) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.32 a min(q(0), q(1)): recurrence (1) downwards from J_11 = J_downward(…)
    const T t2 = J_downward<T>(T(11), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t4 * t7 - t8 * t11 - T(9) * b * t2;
    const T t13 = t10 * t9;
    const T t14 = t6 * t5;
    const T t15 = t8 * b * t11 + t4 * a_minus_b * t7 - T(9) * D * t2;
    const T t16 = T(72) * t2 * c + T(9) * t3 * t15 + T(16) * t3 * b * t12;
    F = in.w[0] * t2 + (T(1) / T(504)) * in.w[3] * t3 * (T(56) * t3 * t12 * c + T(9) * t3 * (T(8) * t8 * t13 - T(8) * t4 * t14 - T(7) * t3 * b * t15) - T(14) * t3 * b * t16) - (T(1) / T(9)) * t3 * in.w[1] * t12 - (T(1) / T(72)) * t3 * in.w[2] * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = T(1) / r0;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = T(1) / D;
    const T t27 = t24 * t23;
    const T t28 = t20 * t19;
    const T t29 = T(5) * t22 * b * t27 + T(5) * t18 * a_minus_b * t28 + T(2) * t26 * a * (T(3) * t22 * b * t24 + T(4) * t26 * a * (T(2) * t26 * a * (t22 * b + t18 * a_minus_b) + t18 * a_minus_b * t19 + t22 * b * t23) + T(3) * t18 * a_minus_b * t20);
    const T t30 = T(35) * t22 * b * t25 + T(8) * t26 * a * t29 + T(35) * t18 * a_minus_b * t21;
    const T t31 = T(35) * t18 * t21 - T(35) * t22 * t25 - t26 * t30 * b;
    const T t32 = T(2) * t17 * t31 * b + t26 * t30 * c - T(9) * t26 * t29;
    F = (T(1) / T(315)) * in.w[3] * t17 * (t17 * t31 * c + T(9) * t17 * (T(5) * t22 * t27 + t26 * t29 * b - T(5) * t18 * t28) - T(2) * t17 * b * t32) + (T(1) / T(315)) * t26 * in.w[0] * t30 - (T(1) / T(315)) * t17 * t32 * in.w[2] - (T(1) / T(315)) * t17 * t31 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 60 +, 166 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i11_w3_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
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
    const T t14 = b * t4 * t8 + a_minus_b * t13 * t9 - T(11) * D * t2;
    const T t15 = T(9) * t3 * t14 * b + T(10) * t12 * t9 - T(10) * t4 * t7;
    const T t16 = t13 * t9 - T(11) * b * t2 - t4 * t8;
    const T t17 = T(20) * t3 * b * t16 + T(110) * t2 * c + T(11) * t3 * t14;
    const T t18 = T(11) * t3 * t15 + T(18) * t17 * t3 * b - T(90) * t3 * c * t16;
    G_ap = in.w[0] * t2 - (T(1) / T(990)) * t3 * in.w[3] * t18 - (T(1) / T(110)) * t17 * t3 * in.w[2] - (T(1) / T(11)) * t3 * in.w[1] * t16;
    G_ab = (T(1) / T(7920)) * t3 * in.w[3] * (T(11) * t3 * (T(72) * t3 * t14 * c - T(16) * t3 * b * t15 - T(9) * t3 * (T(9) * D * t3 * t14 + T(10) * b * t4 * t7 + T(10) * a_minus_b * t12 * t9)) + T(72) * t17 * t3 * c - T(16) * t3 * b * t18) - (T(1) / T(11)) * t3 * in.w[0] * t16 - (T(1) / T(110)) * t17 * t3 * in.w[1] - (T(1) / T(990)) * t3 * t18 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / D;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t22 * t21;
    const T t30 = T(5) * a_minus_b * t28 * t25 + T(5) * b * t20 * t29 + T(2) * t19 * (T(3) * b * t20 * t22 + T(4) * t19 * (a_minus_b * t26 * t25 + b * t20 * t21 + T(2) * t19 * a * (a_minus_b * t25 + b * t20)) * a + T(3) * a_minus_b * t27 * t25) * a;
    const T t31 = t27 * t27;
    const T t32 = T(35) * b * t20 * t23 + T(8) * t19 * a * t30 + T(35) * a_minus_b * t31 * t25;
    const T t33 = t31 * t26;
    const T t34 = T(63) * b * t20 * t24 + T(2) * t19 * a * t32 + T(63) * a_minus_b * t33 * t25;
    const T t35 = T(1) / a;
    const T t36 = T(63) * t33 * t25 - t19 * t34 * b - T(63) * t20 * t24;
    const T t37 = T(10) * t35 * b * t36 + T(5) * t19 * t34 * c - T(11) * t19 * t32;
    const T t38 = t19 * b * t32 + T(35) * t20 * t23 - T(35) * t31 * t25;
    const T t39 = T(2) * t37 * t35 * b - T(11) * t38 * t35 - T(5) * t35 * c * t36;
    G_ap = (T(1) / T(693)) * t19 * t34 * in.w[0] - (T(1) / T(3465)) * t37 * t35 * in.w[2] - (T(1) / T(693)) * t35 * in.w[1] * t36 - (T(1) / T(3465)) * t35 * in.w[3] * t39;
    G_ab = -(T(1) / T(693)) * t35 * in.w[0] * t36 - (T(1) / T(3465)) * t35 * in.w[2] * t39 - (T(1) / T(3465)) * t37 * t35 * in.w[1] - (T(1) / T(3465)) * t35 * in.w[3] * (T(2) * t35 * b * t39 - t37 * t35 * c - T(11) * t35 * (T(9) * t19 * t30 + T(2) * t38 * t35 * b - t19 * t32 * c));
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 67 +, 192 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i11_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
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
    const T t14 = T(11) * t3 * D - t4 * a_minus_b * t8 - b * t13 * t9;
    const T t15 = T(9) * t2 * t14 * D - T(10) * t4 * a_minus_b * t7 - T(10) * b * t12 * t9;
    const T t16 = T(10) * t4 * t7 - T(10) * t12 * t9 - T(9) * b * t2 * t14;
    const T t17 = T(9) * t15 * t2 - T(16) * b * t16 * t2 - T(72) * c * t2 * t14;
    const T t18 = t6 * t5;
    const T t19 = t11 * t10;
    F = (T(1) / T(10)) * t2 * t14 * in.w[0] + (T(1) / T(720)) * in.w[2] * t17 * t2 - (T(1) / T(5040)) * (T(9) * (T(80) * t4 * t18 - T(80) * t19 * t9 - T(7) * b * t15 * t2) * t2 - T(14) * b * t17 * t2 - T(56) * t16 * c * t2) * t2 * in.w[3] - (T(1) / T(90)) * t16 * in.w[1] * t2;
    const T t20 = T(11) * b * t3 + t13 * t9 - t4 * t8;
    const T t21 = T(11) * t2 * t14 + T(20) * b * t20 * t2 - T(110) * t3 * c;
    const T t22 = T(90) * t20 * c * t2 + T(11) * t16 * t2 - T(18) * b * t21 * t2;
    G_ap = t3 * in.w[0] + (T(1) / T(11)) * t20 * in.w[1] * t2 + (T(1) / T(110)) * t21 * in.w[2] * t2 - (T(1) / T(990)) * t22 * t2 * in.w[3];
    G_ab = (T(1) / T(11)) * t20 * t2 * in.w[0] + (T(1) / T(110)) * in.w[1] * t21 * t2 - (T(1) / T(7920)) * (T(72) * c * t21 * t2 + T(16) * t22 * b * t2 - T(11) * t17 * t2) * t2 * in.w[3] - (T(1) / T(990)) * t22 * in.w[2] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / r1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = T(1) / D;
    const T t32 = t29 * t28;
    const T t33 = t25 * t24;
    const T t34 = T(5) * b * t32 * t27 + T(2) * (T(4) * (t23 * a_minus_b * t24 + b * t28 * t27 + T(2) * (t23 * a_minus_b + b * t27) * a * t31) * a * t31 + T(3) * b * t29 * t27 + T(3) * t23 * a_minus_b * t25) * a * t31 + T(5) * t23 * a_minus_b * t33;
    const T t35 = T(35) * t23 * a_minus_b * t26 + T(35) * b * t30 * t27 + T(8) * a * t31 * t34;
    const T t36 = T(35) * t23 * t26 - T(35) * t30 * t27 - b * t35 * t31;
    const T t37 = T(1) / a;
    const T t38 = T(2) * b * t36 * t37 + c * t35 * t31 - T(9) * t31 * t34;
    F = (T(1) / T(315)) * t35 * t31 * in.w[0] - (T(1) / T(315)) * t38 * in.w[2] * t37 - (T(1) / T(315)) * in.w[1] * t36 * t37 - (T(1) / T(315)) * (T(9) * (T(5) * t23 * t33 - T(5) * t32 * t27 - b * t31 * t34) * t37 + T(2) * b * t38 * t37 - t36 * c * t37) * t37 * in.w[3];
    const T t39 = t26 * t24;
    const T t40 = t30 * t28;
    const T t41 = T(63) * t23 * a_minus_b * t39 + T(63) * b * t40 * t27 + T(2) * t35 * a * t31;
    const T t42 = T(63) * t23 * t39 - b * t41 * t31 - T(63) * t40 * t27;
    const T t43 = T(11) * t35 * t31 - T(5) * t41 * c * t31 - T(10) * b * t42 * t37;
    const T t44 = T(5) * c * t42 * t37 + T(2) * t43 * b * t37 - T(11) * t36 * t37;
    G_ap = (T(1) / T(693)) * t41 * t31 * in.w[0] + (T(1) / T(3465)) * t44 * t37 * in.w[3] + (T(1) / T(3465)) * t43 * in.w[2] * t37 - (T(1) / T(693)) * in.w[1] * t42 * t37;
    G_ab = (T(1) / T(3465)) * t37 * (T(2) * b * t44 * t37 - t43 * c * t37 - T(11) * t38 * t37) * in.w[3] + (T(1) / T(3465)) * t44 * in.w[2] * t37 + (T(1) / T(3465)) * t43 * in.w[1] * t37 - (T(1) / T(693)) * t42 * t37 * in.w[0];
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 41 +, 82 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w0_f(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(20)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    F = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = t9 * t8;
    const T t13 = t5 * t4;
    const T t14 = T(1) / D;
    F = (T(1) / T(1280)) * (T(128) * a_minus_b * t7 + T(128) * b * t11 + T(3) * (T(7) * (T(8) * b * t12 + T(8) * a_minus_b * t13 + T(5) * (T(2) * b * t9 + T(2) * a_minus_b * t5 + T(3) * t14 * a * (a_minus_b * t4 + b * t8 + J2 * a)) * t14 * a) * t14 * a + T(48) * a_minus_b * t6 + T(48) * b * t10) * t14 * a) * t14 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 48 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i12_w0_grad(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    G_ab = -(T(1) / T(12)) * t3 * in.w[0] * (t7 - t11 - T(12) * t2 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = t17 * t17;
    const T t19 = T(1) / c;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = t16 * t16;
    const T t24 = t23 * t15;
    const T t25 = t20 * t19;
    const T t26 = t25 * t25;
    const T t27 = T(1280) * a_minus_b * t18 + T(11) * t14 * (T(128) * t22 * b + T(128) * a_minus_b * t24 + T(3) * t14 * a * (T(7) * t14 * a * (T(8) * a_minus_b * t17 + T(5) * t14 * a * (T(2) * a_minus_b * t16 + T(2) * t20 * b + T(3) * t14 * a * (a * J2 + t19 * b + a_minus_b * t15)) + T(8) * t25 * b) + T(48) * a_minus_b * t23 + T(48) * t21 * b)) * a + T(1280) * t26 * b;
    G_ap = (T(1) / T(15360)) * t14 * in.w[0] * t27;
    const T t28 = T(1) / a;
    G_ab = -(T(1) / T(15360)) * (T(1280) * t18 - T(1280) * t26 - t14 * t27 * b) * t28 * in.w[0];
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 48 +, 112 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    F = (T(1) / T(11)) * t2 * in.w[0] * (T(12) * t3 * D - t7 * a_minus_b - t11 * b);
    G_ap = t3 * in.w[0];
    G_ab = -(T(1) / T(12)) * (t7 - t11 - T(12) * t3 * b) * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / D;
    const T t15 = T(1) / q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / c;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = t20 * t19;
    const T t24 = t16 * t15;
    const T t25 = T(128) * t18 * a_minus_b + T(128) * t22 * b + T(3) * a * t14 * (T(48) * t17 * a_minus_b + T(48) * t21 * b + T(7) * (T(8) * t23 * b + T(5) * a * t14 * (T(2) * t20 * b + T(2) * t16 * a_minus_b + T(3) * (t15 * a_minus_b + J2 * a + t19 * b) * a * t14) + T(8) * t24 * a_minus_b) * a * t14);
    F = (T(1) / T(1280)) * t14 * in.w[0] * t25;
    const T t26 = t24 * t24;
    const T t27 = t23 * t23;
    const T t28 = T(1280) * t26 * a_minus_b + T(11) * a * t14 * t25 + T(1280) * t27 * b;
    G_ap = (T(1) / T(15360)) * t14 * in.w[0] * t28;
    const T t29 = T(1) / a;
    G_ab = -(T(1) / T(15360)) * t29 * (T(1280) * t26 - T(1280) * t27 - t14 * b * t28) * in.w[0];
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 44 +, 89 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w1_f(const SegmentInput<T>& in) {
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
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(1) / a;
    F = (T(1) / T(10)) * (T(10) * t2 * b + t6 - t10) * t11 * in.w[1] + t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / D;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / q1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t19;
    const T t23 = t20 * t19;
    const T t24 = t16 * t15;
    const T t25 = T(128) * b * t18 + T(128) * t22 * a_minus_b + T(3) * t14 * a * (T(48) * b * t17 + T(7) * (T(8) * t23 * a_minus_b + T(8) * b * t24 + T(5) * t14 * (T(2) * t20 * a_minus_b + T(2) * b * t16 + T(3) * t14 * (a * J2 + b * t15 + t19 * a_minus_b) * a) * a) * t14 * a + T(48) * t21 * a_minus_b);
    const T t26 = T(1) / a;
    F = (T(1) / T(1280)) * t14 * t25 * in.w[0] - (T(1) / T(1280)) * (T(128) * t22 - t14 * t25 * b - T(128) * t18) * t26 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 52 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i12_w1_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t6 + T(12) * b * t7 - t11;
    G_ap = (T(1) / T(12)) * t2 * in.w[1] * t12 + in.w[0] * t7;
    G_ab = (T(1) / T(66)) * t2 * in.w[1] * (T(6) * t2 * (T(12) * t7 * D - b * t6 - a_minus_b * t11) + T(11) * t2 * b * t12 - T(66) * c * t7) + (T(1) / T(12)) * t2 * t12 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = t17 * t17;
    const T t19 = T(1) / q1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t21 * t21;
    const T t23 = t16 * t16;
    const T t24 = T(1) / D;
    const T t25 = t20 * t20;
    const T t26 = t23 * t15;
    const T t27 = t25 * t19;
    const T t28 = T(3) * a * (T(48) * b * t23 + T(7) * a * t24 * (T(8) * b * t17 + T(5) * a * (T(3) * a * (a * J2 + a_minus_b * t19 + b * t15) * t24 + T(2) * b * t16 + T(2) * a_minus_b * t20) * t24 + T(8) * a_minus_b * t21) + T(48) * a_minus_b * t25) * t24 + T(128) * b * t26 + T(128) * a_minus_b * t27;
    const T t29 = T(1280) * b * t18 + T(1280) * a_minus_b * t22 + T(11) * a * t28 * t24;
    const T t30 = T(1) / a;
    const T t31 = T(1280) * t18 + b * t29 * t24 - T(1280) * t22;
    G_ap = (T(1) / T(15360)) * t29 * in.w[0] * t24 + (T(1) / T(15360)) * t30 * in.w[1] * t31;
    G_ab = (T(1) / T(15360)) * t30 * t31 * in.w[0] - (T(1) / T(15360)) * (c * t29 * t24 - T(2) * t30 * b * t31 - T(12) * t28 * t24) * t30 * in.w[1];
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 55 +, 132 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t12 = t6 * a_minus_b + t10 * b - T(12) * t11 * D;
    const T t13 = t4 * t4;
    const T t14 = t13 * t3;
    const T t15 = t8 * t8;
    const T t16 = t15 * t7;
    F = -(T(1) / T(11)) * in.w[0] * t2 * t12 - (T(1) / T(110)) * (T(11) * t14 + T(10) * t2 * t12 * b - T(11) * t16) * in.w[1] * t2;
    const T t17 = t6 - t10 - T(12) * t11 * b;
    G_ap = t11 * in.w[0] - (T(1) / T(12)) * t17 * in.w[1] * t2;
    G_ab = -(T(1) / T(12)) * in.w[0] * t17 * t2 - (T(1) / T(66)) * (T(66) * t11 * c + T(6) * t2 * t12 + T(11) * t17 * t2 * b) * in.w[1] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = atan2(t18, c_minus_b) * t19;
    const T t20 = T(1) / D;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / c;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t25;
    const T t29 = t26 * t25;
    const T t30 = t22 * t21;
    const T t31 = T(128) * t24 * a_minus_b + T(128) * t28 * b + T(3) * (T(48) * t23 * a_minus_b + T(48) * t27 * b + T(7) * (T(8) * t29 * b + T(5) * (T(2) * t26 * b + T(2) * t22 * a_minus_b + T(3) * t20 * a * (J2 * a + t21 * a_minus_b + t25 * b)) * t20 * a + T(8) * t30 * a_minus_b) * t20 * a) * t20 * a;
    const T t32 = T(1) / a;
    F = (T(1) / T(1280)) * in.w[0] * t20 * t31 - (T(1) / T(1280)) * in.w[1] * t32 * (T(128) * t24 - T(128) * t28 - t20 * t31 * b);
    const T t33 = t30 * t30;
    const T t34 = t29 * t29;
    const T t35 = T(1280) * t33 * a_minus_b + T(1280) * t34 * b + T(11) * t20 * a * t31;
    const T t36 = T(1280) * t33 - T(1280) * t34 - t35 * t20 * b;
    G_ap = (T(1) / T(15360)) * in.w[0] * t35 * t20 - (T(1) / T(15360)) * in.w[1] * t36 * t32;
    G_ab = -(T(1) / T(15360)) * in.w[1] * (c * t35 * t20 + T(2) * t36 * t32 * b - T(12) * t20 * t31) * t32 - (T(1) / T(15360)) * in.w[0] * t36 * t32;
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 47 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w2_f(const SegmentInput<T>& in) {
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
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = t6 - t10 - T(10) * t2 * b;
    const T t12 = T(1) / a;
    F = in.w[0] * t2 - (T(1) / T(10)) * t11 * in.w[1] * t12 - (T(1) / T(45)) * t12 * (T(5) * (a_minus_b * t6 + t10 * b - T(10) * D * t2) * t12 + T(9) * t11 * t12 * b + T(45) * c * t2) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / a;
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = T(1) / c;
    const T t19 = t18 * t18;
    const T t20 = t17 * t17;
    const T t21 = t19 * t18;
    const T t22 = t20 * t17;
    const T t23 = t20 * t20;
    const T t24 = t19 * t19;
    const T t25 = T(7) * t16 * a * (T(5) * t16 * a * (T(3) * t16 * a * (a_minus_b * t17 + a * J2 + t18 * b) + T(2) * t19 * b + T(2) * a_minus_b * t20) + T(8) * t21 * b + T(8) * a_minus_b * t22) + T(48) * a_minus_b * t23 + T(48) * t24 * b;
    const T t26 = t23 * t17;
    const T t27 = t24 * t18;
    const T t28 = T(3) * t16 * a * t25 + T(128) * a_minus_b * t26 + T(128) * t27 * b;
    const T t29 = T(128) * t26 - t16 * b * t28 - T(128) * t27;
    F = (T(1) / T(3840)) * t15 * in.w[2] * (T(10) * t16 * t25 - T(3) * c * t16 * t28 - T(6) * t29 * t15 * b) + (T(1) / T(1280)) * in.w[0] * t16 * t28 - (T(1) / T(1280)) * t29 * in.w[1] * t15;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 58 +, 138 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i12_w2_grad(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(12) * t3 * b + t7 - t11;
    const T t13 = t7 * b + a_minus_b * t11 - T(12) * D * t3;
    const T t14 = T(11) * t2 * t12 * b - T(6) * t13 * t2 - T(66) * c * t3;
    G_ap = (T(1) / T(12)) * in.w[1] * t2 * t12 + (T(1) / T(66)) * t14 * in.w[2] * t2 + in.w[0] * t3;
    const T t15 = t9 * t9;
    const T t16 = t15 * t8;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    G_ab = (T(1) / T(66)) * t14 * in.w[1] * t2 + (T(1) / T(12)) * in.w[0] * t2 * t12 - (T(1) / T(660)) * in.w[2] * t2 * (T(6) * (T(10) * t13 * t2 * b + T(11) * t16 - T(11) * t18) * t2 + T(55) * c * t2 * t12 - T(20) * t14 * t2 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, c_minus_b) * t20;
    const T t21 = T(1) / D;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t26 * t22;
    const T t28 = T(1) / q1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t29 * t29;
    const T t32 = t31 * t28;
    const T t33 = T(128) * t27 * b + T(3) * (T(48) * t26 * b + T(7) * t21 * (T(5) * (T(3) * (J2 * a + a_minus_b * t28 + t22 * b) * t21 * a + T(2) * t23 * b + T(2) * a_minus_b * t29) * t21 * a + T(8) * a_minus_b * t30 + T(8) * t24 * b) * a + T(48) * a_minus_b * t31) * t21 * a + T(128) * a_minus_b * t32;
    const T t34 = t30 * t30;
    const T t35 = T(1280) * t25 * b + T(11) * t21 * a * t33 + T(1280) * a_minus_b * t34;
    const T t36 = t21 * t35 * b + T(1280) * t25 - T(1280) * t34;
    const T t37 = T(1) / a;
    const T t38 = c * t21 * t35 - T(2) * t36 * t37 * b - T(12) * t21 * t33;
    G_ap = (T(1) / T(15360)) * in.w[0] * t21 * t35 + (T(1) / T(15360)) * in.w[1] * t36 * t37 - (T(1) / T(15360)) * in.w[2] * t37 * t38;
    G_ab = (T(1) / T(15360)) * in.w[0] * t36 * t37 - (T(1) / T(15360)) * in.w[2] * (T(2) * t37 * t38 * b + c * t36 * t37 - T(12) * t37 * (t21 * t33 * b + T(128) * t27 - T(128) * t32)) * t37 - (T(1) / T(15360)) * in.w[1] * t37 * t38;
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 62 +, 156 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / q1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t11 = a_minus_b * t5 + b * t9 - T(12) * t10 * D;
    const T t12 = T(1) / a;
    const T t13 = t7 * t7;
    const T t14 = t13 * t6;
    const T t15 = t3 * t3;
    const T t16 = t15 * t2;
    const T t17 = T(11) * t16 + T(10) * b * t11 * t12 - T(11) * t14;
    F = -(T(1) / T(495)) * in.w[2] * (T(5) * (T(10) * t11 * D * t12 + T(11) * b * t14 + T(11) * a_minus_b * t16) * t12 + T(9) * b * t17 * t12 - T(45) * t11 * c * t12) * t12 - (T(1) / T(11)) * t11 * in.w[0] * t12 - (T(1) / T(110)) * t17 * in.w[1] * t12;
    const T t18 = t9 + T(12) * b * t10 - t5;
    const T t19 = T(6) * t11 * t12 + T(66) * t10 * c - T(11) * b * t18 * t12;
    G_ap = (T(1) / T(12)) * t18 * in.w[1] * t12 + t10 * in.w[0] - (T(1) / T(66)) * in.w[2] * t19 * t12;
    G_ab = (T(1) / T(12)) * t18 * in.w[0] * t12 - (T(1) / T(660)) * in.w[2] * (T(55) * t18 * c * t12 + T(20) * b * t19 * t12 + T(6) * t17 * t12) * t12 - (T(1) / T(66)) * in.w[1] * t19 * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(D);
    const T t21 = T(1) / t20;
    const T J2 = atan2(t20, c_minus_b) * t21;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = T(1) / q1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t26 * t25;
    const T t29 = t23 * t22;
    const T t30 = T(1) / D;
    const T t31 = T(48) * b * t24 + T(48) * a_minus_b * t27 + T(7) * (T(8) * a_minus_b * t28 + T(8) * b * t29 + T(5) * (T(2) * b * t23 + T(3) * (J2 * a + a_minus_b * t25 + b * t22) * t30 * a + T(2) * a_minus_b * t26) * t30 * a) * t30 * a;
    const T t32 = t24 * t22;
    const T t33 = t27 * t25;
    const T t34 = T(3) * t31 * t30 * a + T(128) * b * t32 + T(128) * a_minus_b * t33;
    const T t35 = T(128) * t33 - T(128) * t32 - b * t34 * t30;
    const T t36 = T(1) / a;
    F = (T(1) / T(1280)) * t34 * in.w[0] * t30 - (T(1) / T(3840)) * in.w[2] * (T(3) * t34 * c * t30 + T(6) * b * t35 * t36 - T(10) * t31 * t30) * t36 - (T(1) / T(1280)) * t35 * in.w[1] * t36;
    const T t37 = t29 * t29;
    const T t38 = t28 * t28;
    const T t39 = T(11) * t34 * t30 * a + T(1280) * a_minus_b * t38 + T(1280) * b * t37;
    const T t40 = T(1280) * t37 + b * t30 * t39 - T(1280) * t38;
    const T t41 = T(2) * b * t40 * t36 + T(12) * t34 * t30 - c * t30 * t39;
    G_ap = (T(1) / T(15360)) * t40 * in.w[1] * t36 + (T(1) / T(15360)) * in.w[0] * t30 * t39 + (T(1) / T(15360)) * in.w[2] * t41 * t36;
    G_ab = (T(1) / T(15360)) * t41 * in.w[1] * t36 + (T(1) / T(15360)) * in.w[0] * t40 * t36 + (T(1) / T(15360)) * in.w[2] * (T(2) * t41 * b * t36 - c * t40 * t36 - T(12) * t35 * t36) * t36;
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 52 +, 115 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w3_f(const SegmentInput<T>& in) {
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
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(20)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.35 a min(q(0), q(1)): recurrence (1) downwards from J_12 = J_downward(…)
    const T t2 = J_downward<T>(T(12), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t7;
    const T t11 = T(10) * t2 * b + t6 - t10;
    const T t12 = T(1) / a;
    const T t13 = b * t6 + t10 * a_minus_b - T(10) * D * t2;
    const T t14 = T(5) * t12 * t13 + T(45) * t2 * c - T(9) * t11 * t12 * b;
    F = (T(1) / T(10)) * t11 * t12 * in.w[1] + in.w[0] * t2 - (T(1) / T(360)) * in.w[3] * t12 * (T(36) * t11 * t12 * c + T(5) * (T(9) * t9 + T(8) * t12 * b * t13 - T(9) * t5) * t12 + T(16) * t12 * t14 * b) - (T(1) / T(45)) * in.w[2] * t12 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / D;
    const T t22 = T(1) / q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t18 * t17;
    const T t26 = t23 * t23;
    const T t27 = T(48) * b * t19 + T(7) * t21 * a * (T(8) * t24 * a_minus_b + T(8) * b * t25 + T(5) * t21 * a * (T(2) * b * t18 + T(2) * t23 * a_minus_b + T(3) * (t22 * a_minus_b + a * J2 + b * t17) * t21 * a)) + T(48) * t26 * a_minus_b;
    const T t28 = t26 * t22;
    const T t29 = T(128) * b * t20 + T(3) * t27 * t21 * a + T(128) * t28 * a_minus_b;
    const T t30 = T(1) / a;
    const T t31 = T(128) * t28 - t29 * t21 * b - T(128) * t20;
    const T t32 = T(3) * t29 * t21 * c + T(6) * t30 * t31 * b - T(10) * t27 * t21;
    F = (T(1) / T(1280)) * t29 * t21 * in.w[0] - (T(1) / T(3840)) * (T(10) * t30 * (T(48) * t26 - T(48) * t19 - t27 * t21 * b) + T(2) * t30 * t32 * b - T(3) * t30 * t31 * c) * in.w[3] * t30 - (T(1) / T(3840)) * in.w[2] * t30 * t32 - (T(1) / T(1280)) * t30 * t31 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 64 +, 159 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i12_w3_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(21) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = T(12) * t2 * D - t6 * a_minus_b - b * t10;
    const T t12 = T(1) / a;
    const T t13 = t6 - T(12) * b * t2 - t10;
    const T t14 = T(6) * t11 * t12 - T(11) * b * t13 * t12 - T(66) * t2 * c;
    const T t15 = t4 * t4;
    const T t16 = t15 * t3;
    const T t17 = t8 * t8;
    const T t18 = t17 * t7;
    const T t19 = T(11) * t16 - T(10) * t11 * b * t12 - T(11) * t18;
    const T t20 = T(20) * b * t14 * t12 + T(55) * t13 * c * t12 - T(6) * t12 * t19;
    G_ap = (T(1) / T(66)) * t14 * in.w[2] * t12 + (T(1) / T(660)) * t20 * t12 * in.w[3] + t2 * in.w[0] - (T(1) / T(12)) * in.w[1] * t13 * t12;
    G_ab = (T(1) / T(990)) * (T(3) * b * t20 * t12 - T(2) * (T(5) * t12 * (T(11) * t16 * a_minus_b + T(11) * b * t18 - T(10) * t11 * D * t12) + T(45) * t11 * c * t12 + T(9) * b * t12 * t19) * t12 - T(15) * c * t14 * t12) * t12 * in.w[3] + (T(1) / T(660)) * t20 * in.w[2] * t12 + (T(1) / T(66)) * in.w[1] * t14 * t12 - (T(1) / T(12)) * t13 * t12 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(D);
    const T t22 = T(1) / t21;
    const T J2 = t22 * atan2(t21, c_minus_b);
    const T t23 = T(1) / D;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t24;
    const T t28 = T(1) / c;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t25 * t24;
    const T t32 = t29 * t29;
    const T t33 = T(7) * t23 * a * (T(8) * b * t30 + T(5) * (T(2) * t25 * a_minus_b + T(2) * b * t29 + T(3) * (b * t28 + t24 * a_minus_b + J2 * a) * t23 * a) * t23 * a + T(8) * t31 * a_minus_b) + T(48) * t26 * a_minus_b + T(48) * b * t32;
    const T t34 = t32 * t28;
    const T t35 = T(128) * t27 * a_minus_b + T(3) * t33 * t23 * a + T(128) * b * t34;
    const T t36 = t31 * t31;
    const T t37 = t30 * t30;
    const T t38 = T(11) * t35 * t23 * a + T(1280) * t36 * a_minus_b + T(1280) * b * t37;
    const T t39 = T(1) / a;
    const T t40 = T(1280) * t36 - b * t23 * t38 - T(1280) * t37;
    const T t41 = T(12) * t35 * t23 - c * t23 * t38 - T(2) * b * t40 * t39;
    const T t42 = T(128) * t27 - b * t35 * t23 - T(128) * t34;
    const T t43 = c * t40 * t39 + T(2) * b * t41 * t39 - T(12) * t42 * t39;
    G_ap = (T(1) / T(15360)) * t23 * t38 * in.w[0] + (T(1) / T(15360)) * t39 * t43 * in.w[3] + (T(1) / T(15360)) * t41 * in.w[2] * t39 - (T(1) / T(15360)) * in.w[1] * t40 * t39;
    G_ab = (T(1) / T(15360)) * in.w[1] * t41 * t39 + (T(1) / T(15360)) * in.w[2] * t39 * t43 - (T(1) / T(15360)) * t40 * t39 * in.w[0] - (T(1) / T(15360)) * t39 * in.w[3] * (t41 * c * t39 + T(4) * (T(6) * b * t42 * t39 + T(3) * t35 * c * t23 - T(10) * t33 * t23) * t39 - T(2) * b * t39 * t43);
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 71 +, 184 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i12_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t12 = b * t6 + a_minus_b * t10 - T(12) * t11 * D;
    const T t13 = t8 * t8;
    const T t14 = t13 * t7;
    const T t15 = t4 * t4;
    const T t16 = t15 * t3;
    const T t17 = T(10) * t12 * b * t2 + T(11) * t14 - T(11) * t16;
    const T t18 = T(10) * t12 * D * t2 + T(11) * b * t16 + T(11) * a_minus_b * t14;
    const T t19 = T(9) * t17 * b * t2 + T(5) * t18 * t2 - T(45) * t12 * c * t2;
    F = (T(1) / T(3960)) * in.w[3] * t2 * (T(36) * t17 * c * t2 - T(5) * (T(99) * t13 + T(8) * t18 * b * t2 - T(99) * t15) * t2 - T(16) * b * t19 * t2) - (T(1) / T(110)) * t17 * in.w[1] * t2 - (T(1) / T(495)) * t19 * in.w[2] * t2 - (T(1) / T(11)) * t12 * t2 * in.w[0];
    const T t20 = t10 - t6 - T(12) * b * t11;
    const T t21 = T(11) * b * t20 * t2 + T(66) * c * t11 + T(6) * t12 * t2;
    const T t22 = T(6) * t17 * t2 + T(20) * b * t21 * t2 - T(55) * c * t20 * t2;
    G_ap = t11 * in.w[0] - (T(1) / T(66)) * t21 * in.w[2] * t2 - (T(1) / T(660)) * t22 * in.w[3] * t2 - (T(1) / T(12)) * in.w[1] * t20 * t2;
    G_ab = -(T(1) / T(12)) * t20 * t2 * in.w[0] - (T(1) / T(660)) * t22 * in.w[2] * t2 - (T(1) / T(990)) * (T(3) * t22 * b * t2 + T(2) * t19 * t2 - T(15) * t21 * c * t2) * in.w[3] * t2 - (T(1) / T(66)) * in.w[1] * t21 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = atan2(t23, c_minus_b) * t24;
    const T t25 = T(1) / c;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t25;
    const T t29 = T(1) / D;
    const T t30 = t26 * t25;
    const T t31 = T(1) / q1;
    const T t32 = t31 * t31;
    const T t33 = t32 * t31;
    const T t34 = t32 * t32;
    const T t35 = T(48) * b * t27 + T(7) * t29 * a * (T(8) * b * t30 + T(8) * a_minus_b * t33 + T(5) * (T(2) * b * t26 + T(3) * (a_minus_b * t31 + b * t25 + J2 * a) * t29 * a + T(2) * a_minus_b * t32) * t29 * a) + T(48) * a_minus_b * t34;
    const T t36 = t34 * t31;
    const T t37 = T(128) * b * t28 + T(3) * t35 * t29 * a + T(128) * a_minus_b * t36;
    const T t38 = T(128) * t36 - T(128) * t28 - b * t37 * t29;
    const T t39 = T(1) / a;
    const T t40 = T(10) * t35 * t29 - T(6) * b * t38 * t39 - T(3) * t37 * c * t29;
    F = (T(1) / T(1280)) * t37 * t29 * in.w[0] + (T(1) / T(3840)) * in.w[2] * t40 * t39 + (T(1) / T(3840)) * (T(3) * c * t38 * t39 + T(10) * (t35 * b * t29 + T(48) * t27 - T(48) * t34) * t39 + T(2) * b * t40 * t39) * in.w[3] * t39 - (T(1) / T(1280)) * in.w[1] * t38 * t39;
    const T t41 = t30 * t30;
    const T t42 = t33 * t33;
    const T t43 = T(1280) * b * t41 + T(11) * t37 * t29 * a + T(1280) * a_minus_b * t42;
    const T t44 = b * t29 * t43 + T(1280) * t41 - T(1280) * t42;
    const T t45 = T(2) * b * t44 * t39 + T(12) * t37 * t29 - c * t29 * t43;
    const T t46 = t44 * c * t39 + T(12) * t38 * t39 - T(2) * t45 * b * t39;
    G_ap = (T(1) / T(15360)) * t45 * in.w[2] * t39 + (T(1) / T(15360)) * t29 * t43 * in.w[0] + (T(1) / T(15360)) * in.w[1] * t44 * t39 - (T(1) / T(15360)) * t46 * in.w[3] * t39;
    G_ab = (T(1) / T(15360)) * t45 * in.w[1] * t39 + (T(1) / T(15360)) * in.w[3] * t39 * (T(4) * t40 * t39 - T(2) * b * t46 * t39 - t45 * c * t39) + (T(1) / T(15360)) * t44 * t39 * in.w[0] - (T(1) / T(15360)) * t46 * in.w[2] * t39;
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 39 +, 93 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w0_f(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    F = in.w[0] * J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t13 = t10 * t9;
    const T t14 = t5 * t4;
    F = (T(1) / T(693)) * t2 * in.w[0] * (T(63) * t3 * b * t7 + T(63) * t12 * a_minus_b * t8 + T(2) * t2 * (T(35) * t3 * b * t6 + T(8) * t2 * a * (T(2) * t2 * a * (T(4) * t2 * a * (t9 * a_minus_b * t8 + t3 * b * t4 + T(2) * (a_minus_b * t8 + t3 * b) * t2 * a) + T(3) * t3 * b * t5 + T(3) * t10 * a_minus_b * t8) + T(5) * t13 * a_minus_b * t8 + T(5) * t3 * b * t14) + T(35) * t11 * a_minus_b * t8) * a);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 46 +, 123 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i13_w0_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / a;
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
    G_ab = (T(1) / T(13)) * t3 * in.w[0] * (t8 * t4 + T(13) * t2 * b - t9 * t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r1;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t21 * t20;
    const T t24 = t17 * t16;
    const T t25 = t22 * t20;
    const T t26 = t18 * t16;
    const T t27 = t23 * t23;
    const T t28 = t24 * t24;
    const T t29 = T(4) * a * t14 * (T(2) * a * t14 * (T(35) * t18 * b * t15 + T(35) * t19 * a_minus_b * t22 + T(8) * a * t14 * (T(5) * t19 * a_minus_b * t23 + T(2) * a * t14 * (T(3) * t19 * a_minus_b * t21 + T(3) * t17 * b * t15 + T(4) * a * t14 * (t16 * b * t15 + T(2) * a * t14 * (t19 * a_minus_b + b * t15) + t19 * a_minus_b * t20)) + T(5) * t24 * b * t15)) + T(63) * t19 * a_minus_b * t25 + T(63) * t26 * b * t15) + T(231) * t19 * a_minus_b * t27 + T(231) * t28 * b * t15;
    G_ap = (T(1) / T(3003)) * t29 * t14 * in.w[0];
    const T t30 = T(1) / a;
    G_ab = (T(1) / T(3003)) * (t29 * t14 * b + T(231) * t28 * t15 - T(231) * t19 * t27) * t30 * in.w[0];
  }
  const T g_factor = -T(13) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 46 +, 127 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    F = -(T(1) / T(12)) * in.w[0] * t2 * (t3 * a_minus_b * t7 + t8 * b * t12 - T(13) * D * t13);
    G_ap = in.w[0] * t13;
    G_ab = (T(1) / T(13)) * in.w[0] * t2 * (t8 * t12 + T(13) * b * t13 - t3 * t7);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t16 * t16;
    const T t21 = t20 * t16;
    const T t22 = t19 * t18;
    const T t23 = t19 * t19;
    const T t24 = t20 * t20;
    const T t25 = t23 * t18;
    const T t26 = t24 * t16;
    const T t27 = T(2) * t14 * a * (T(8) * t14 * a * (T(2) * t14 * a * (T(4) * t14 * a * (t15 * a_minus_b * t16 + t17 * b * t18 + T(2) * t14 * a * (t15 * a_minus_b + t17 * b)) + T(3) * t17 * b * t19 + T(3) * t15 * a_minus_b * t20) + T(5) * t15 * a_minus_b * t21 + T(5) * t17 * b * t22) + T(35) * t17 * b * t23 + T(35) * t15 * a_minus_b * t24) + T(63) * t17 * b * t25 + T(63) * t15 * a_minus_b * t26;
    F = (T(1) / T(693)) * t14 * in.w[0] * t27;
    const T t28 = t21 * t21;
    const T t29 = t22 * t22;
    const T t30 = T(231) * t15 * a_minus_b * t28 + T(231) * t17 * b * t29 + T(4) * t14 * a * t27;
    G_ap = (T(1) / T(3003)) * t14 * t30 * in.w[0];
    const T t31 = T(1) / a;
    G_ab = (T(1) / T(3003)) * (T(231) * t17 * t29 + t14 * t30 * b - T(231) * t15 * t28) * in.w[0] * t31;
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 42 +, 102 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w1_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
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
    const T t13 = T(1) / a;
    F = t2 * in.w[0] - (T(1) / T(11)) * (t3 * t7 - T(11) * t2 * b - t12 * t8) * t13 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t15;
    const T t19 = T(1) / D;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t16 * t15;
    const T t25 = t22 * t22;
    const T t26 = t25 * t21;
    const T t27 = T(63) * t18 * t14 * b + T(2) * t19 * a * (T(35) * t17 * t14 * b + T(8) * (T(5) * a_minus_b * t20 * t23 + T(2) * t19 * a * (T(3) * t16 * t14 * b + T(3) * a_minus_b * t20 * t22 + T(4) * t19 * a * (a_minus_b * t20 * t21 + t15 * t14 * b + T(2) * (a_minus_b * t20 + t14 * b) * t19 * a)) + T(5) * t24 * t14 * b) * t19 * a + T(35) * a_minus_b * t20 * t25) + T(63) * a_minus_b * t20 * t26;
    const T t28 = T(1) / a;
    F = (T(1) / T(693)) * t27 * in.w[0] * t19 + (T(1) / T(693)) * (t27 * t19 * b + T(63) * t18 * t14 - T(63) * t20 * t26) * t28 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 50 +, 137 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i13_w1_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t3 * t7 + T(13) * t8 * b - t13 * t9;
    G_ap = (T(1) / T(13)) * t2 * in.w[1] * t14 + t8 * in.w[0];
    G_ab = (T(1) / T(13)) * t2 * t14 * in.w[0] - (T(1) / T(156)) * t2 * in.w[1] * (T(156) * t8 * c - T(13) * t2 * (T(13) * t8 * D - a_minus_b * t13 * t9 - b * t3 * t7) - T(24) * t2 * t14 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / a;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = T(1) / D;
    const T t22 = t18 * t18;
    const T t23 = t22 * t17;
    const T t24 = T(1) / r1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = t26 * t26;
    const T t29 = t28 * t25;
    const T t30 = T(63) * b * t16 * t23 + T(2) * a * t21 * (T(35) * b * t16 * t22 + T(8) * a * t21 * (T(5) * a_minus_b * t27 * t24 + T(2) * a * (T(4) * a * t21 * (b * t16 * t17 + a_minus_b * t25 * t24 + T(2) * a * t21 * (a_minus_b * t24 + b * t16)) + T(3) * a_minus_b * t26 * t24 + T(3) * b * t16 * t18) * t21 + T(5) * b * t16 * t19) + T(35) * a_minus_b * t28 * t24) + T(63) * a_minus_b * t29 * t24;
    const T t31 = t27 * t27;
    const T t32 = T(4) * a * t21 * t30 + T(231) * a_minus_b * t31 * t24 + T(231) * b * t16 * t20;
    const T t33 = T(231) * t16 * t20 + t21 * t32 * b - T(231) * t31 * t24;
    G_ap = (T(1) / T(3003)) * t15 * in.w[1] * t33 + (T(1) / T(3003)) * t21 * t32 * in.w[0];
    G_ab = (T(1) / T(3003)) * t15 * t33 * in.w[0] - (T(1) / T(9009)) * t15 * in.w[1] * (T(3) * t21 * t32 * c - T(13) * t21 * t30 - T(6) * t15 * b * t33);
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 53 +, 150 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t5 * t4;
    const T t14 = t13 * t13;
    const T t15 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t16 = b * t12 * t8 + t14 * t3 * a_minus_b - T(13) * D * t15;
    const T t17 = t10 * t10;
    const T t18 = t17 * t9;
    F = -(T(1) / T(132)) * in.w[1] * t2 * (T(12) * t7 * t3 + T(11) * t16 * b * t2 - T(12) * t18 * t8) - (T(1) / T(12)) * t16 * t2 * in.w[0];
    const T t19 = t14 * t3 - t12 * t8 - T(13) * b * t15;
    G_ap = t15 * in.w[0] - (T(1) / T(13)) * in.w[1] * t19 * t2;
    G_ab = -(T(1) / T(156)) * in.w[1] * (T(156) * c * t15 + T(13) * t16 * t2 + T(24) * b * t19 * t2) * t2 - (T(1) / T(13)) * t19 * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t26;
    const T t30 = T(1) / D;
    const T t31 = t22 * t21;
    const T t32 = t27 * t26;
    const T t33 = T(63) * t24 * t20 * a_minus_b + T(63) * b * t29 * t25 + T(2) * (T(35) * b * t28 * t25 + T(35) * t23 * t20 * a_minus_b + T(8) * t30 * (T(5) * t31 * t20 * a_minus_b + T(5) * b * t32 * t25 + T(2) * (T(3) * t22 * t20 * a_minus_b + T(4) * (b * t26 * t25 + T(2) * (t20 * a_minus_b + b * t25) * t30 * a + t21 * t20 * a_minus_b) * t30 * a + T(3) * b * t27 * t25) * t30 * a) * a) * t30 * a;
    const T t34 = T(1) / a;
    F = (T(1) / T(693)) * t33 * t30 * in.w[0] - (T(1) / T(693)) * in.w[1] * t34 * (T(63) * t24 * t20 - T(63) * t29 * t25 - t33 * b * t30);
    const T t35 = t32 * t32;
    const T t36 = t31 * t31;
    const T t37 = T(231) * b * t35 * t25 + T(4) * t33 * t30 * a + T(231) * t36 * t20 * a_minus_b;
    const T t38 = T(231) * t36 * t20 - T(231) * t35 * t25 - b * t30 * t37;
    G_ap = (T(1) / T(3003)) * t30 * t37 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t38 * t34;
    G_ab = (T(1) / T(9009)) * in.w[1] * (T(13) * t33 * t30 - T(6) * b * t38 * t34 - T(3) * c * t30 * t37) * t34 - (T(1) / T(3003)) * t38 * t34 * in.w[0];
  }
  const T g_factor = -T(13) * length * in.s;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 45 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w2_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(39) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
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
    const T t14 = T(11) * t3 * b + t4 * t8 - t13 * t9;
    F = (T(1) / T(110)) * t2 * in.w[2] * (T(20) * t2 * b * t14 + T(11) * t2 * (T(11) * D * t3 - t4 * b * t8 - a_minus_b * t13 * t9) - T(110) * t3 * c) + (T(1) / T(11)) * in.w[1] * t2 * t14 + t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / D;
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t18 * t17;
    const T t25 = t22 * t21;
    const T t26 = T(35) * t16 * b * t19 + T(35) * a_minus_b * t23 * t20 + T(8) * t15 * a * (T(5) * t16 * b * t24 + T(5) * a_minus_b * t25 * t20 + T(2) * t15 * (T(3) * a_minus_b * t22 * t20 + T(3) * t16 * b * t18 + T(4) * t15 * a * (T(2) * t15 * a * (a_minus_b * t20 + t16 * b) + a_minus_b * t21 * t20 + t16 * b * t17)) * a);
    const T t27 = t19 * t17;
    const T t28 = t23 * t21;
    const T t29 = T(2) * t15 * a * t26 + T(63) * t16 * b * t27 + T(63) * a_minus_b * t28 * t20;
    const T t30 = T(1) / a;
    const T t31 = t15 * b * t29 + T(63) * t16 * t27 - T(63) * t28 * t20;
    F = (T(1) / T(693)) * t15 * in.w[0] * t29 + (T(1) / T(3465)) * t30 * in.w[2] * (T(11) * t15 * t26 + T(10) * t30 * t31 * b - T(5) * t15 * t29 * c) + (T(1) / T(693)) * in.w[1] * t30 * t31;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 56 +, 157 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i13_w2_grad(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t3 * t7 + T(13) * b * t8 - t9 * t13;
    const T t15 = T(13) * D * t8 - b * t3 * t7 - t9 * a_minus_b * t13;
    const T t16 = T(156) * t8 * c - T(13) * t2 * t15 - T(24) * t2 * b * t14;
    G_ap = (T(1) / T(13)) * t2 * t14 * in.w[1] + in.w[0] * t8 - (T(1) / T(156)) * t16 * in.w[2] * t2;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = t11 * t11;
    const T t20 = t19 * t10;
    G_ab = (T(1) / T(1716)) * in.w[2] * t2 * (T(13) * t2 * (T(11) * t2 * b * t15 + T(12) * t3 * t18 - T(12) * t9 * t20) - T(22) * t16 * t2 * b - T(132) * t2 * t14 * c) + (T(1) / T(13)) * t2 * in.w[0] * t14 - (T(1) / T(156)) * t16 * t2 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = T(1) / D;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t24 * t24;
    const T t29 = t27 * t26;
    const T t30 = t28 * t24;
    const T t31 = t28 * t28;
    const T t32 = t27 * t27;
    const T t33 = t31 * t24;
    const T t34 = t32 * t26;
    const T t35 = T(2) * t22 * a * (T(8) * t22 * a * (T(2) * t22 * a * (T(4) * (b * t23 * t24 + t25 * a_minus_b * t26 + T(2) * t22 * a * (b * t23 + t25 * a_minus_b)) * t22 * a + T(3) * t25 * a_minus_b * t27 + T(3) * b * t23 * t28) + T(5) * t25 * a_minus_b * t29 + T(5) * b * t23 * t30) + T(35) * b * t23 * t31 + T(35) * t25 * a_minus_b * t32) + T(63) * b * t23 * t33 + T(63) * t25 * a_minus_b * t34;
    const T t36 = t30 * t30;
    const T t37 = t29 * t29;
    const T t38 = T(231) * b * t23 * t36 + T(4) * t35 * t22 * a + T(231) * t25 * a_minus_b * t37;
    const T t39 = t22 * b * t38 + T(231) * t23 * t36 - T(231) * t25 * t37;
    const T t40 = T(13) * t35 * t22 + T(6) * t21 * b * t39 - T(3) * t22 * c * t38;
    G_ap = (T(1) / T(9009)) * in.w[2] * t21 * t40 + (T(1) / T(3003)) * t22 * in.w[0] * t38 + (T(1) / T(3003)) * t21 * in.w[1] * t39;
    G_ab = (T(1) / T(9009)) * t21 * t40 * in.w[1] + (T(1) / T(9009)) * in.w[2] * t21 * (T(13) * t21 * (T(63) * t23 * t33 + t35 * t22 * b - T(63) * t25 * t34) + T(2) * t21 * t40 * b - T(3) * t21 * c * t39) + (T(1) / T(3003)) * t21 * in.w[0] * t39;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 60 +, 175 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t13 = t6 * t2 * b + t11 * a_minus_b * t7 - T(13) * t12 * D;
    const T t14 = T(1) / a;
    const T t15 = t9 * t9;
    const T t16 = t15 * t8;
    const T t17 = t4 * t4;
    const T t18 = t17 * t3;
    const T t19 = T(11) * t13 * t14 * b + T(12) * t16 * t7 - T(12) * t18 * t2;
    F = (T(1) / T(1320)) * (T(110) * c * t13 * t14 - T(20) * t19 * t14 * b - T(11) * (T(12) * t16 * a_minus_b * t7 + T(11) * t13 * D * t14 + T(12) * t18 * t2 * b) * t14) * t14 * in.w[2] - (T(1) / T(12)) * t13 * t14 * in.w[0] - (T(1) / T(132)) * in.w[1] * t19 * t14;
    const T t20 = t6 * t2 + T(13) * t12 * b - t11 * t7;
    const T t21 = T(13) * t13 * t14 + T(156) * c * t12 - T(24) * t20 * t14 * b;
    G_ap = (T(1) / T(13)) * t20 * in.w[1] * t14 + t12 * in.w[0] - (T(1) / T(156)) * t21 * t14 * in.w[2];
    G_ab = (T(1) / T(13)) * t20 * t14 * in.w[0] - (T(1) / T(1716)) * (T(13) * t19 * t14 + T(132) * t20 * c * t14 + T(22) * t21 * t14 * b) * t14 * in.w[2] - (T(1) / T(156)) * t21 * in.w[1] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = T(1) / r0;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t23;
    const T t27 = T(1) / D;
    const T t28 = T(1) / r1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t31 * t29;
    const T t33 = t24 * t23;
    const T t34 = t30 * t29;
    const T t35 = T(35) * t31 * a_minus_b * t28 + T(8) * t27 * a * (T(5) * t33 * t22 * b + T(2) * (T(3) * t30 * a_minus_b * t28 + T(4) * t27 * a * (T(2) * t27 * a * (a_minus_b * t28 + t22 * b) + t23 * t22 * b + t29 * a_minus_b * t28) + T(3) * t24 * t22 * b) * t27 * a + T(5) * t34 * a_minus_b * t28) + T(35) * t25 * t22 * b;
    const T t36 = T(63) * t32 * a_minus_b * t28 + T(2) * t35 * t27 * a + T(63) * t26 * t22 * b;
    const T t37 = T(63) * t26 * t22 + t27 * t36 * b - T(63) * t32 * t28;
    const T t38 = T(1) / a;
    F = (T(1) / T(3465)) * (T(10) * t37 * t38 * b + T(11) * t35 * t27 - T(5) * c * t27 * t36) * t38 * in.w[2] + (T(1) / T(693)) * t37 * in.w[1] * t38 + (T(1) / T(693)) * t27 * t36 * in.w[0];
    const T t39 = t33 * t33;
    const T t40 = t34 * t34;
    const T t41 = T(231) * t39 * t22 * b + T(4) * t27 * a * t36 + T(231) * t40 * a_minus_b * t28;
    const T t42 = T(231) * t39 * t22 + t27 * t41 * b - T(231) * t40 * t28;
    const T t43 = T(13) * t27 * t36 + T(6) * t38 * t42 * b - T(3) * c * t27 * t41;
    G_ap = (T(1) / T(3003)) * in.w[1] * t38 * t42 + (T(1) / T(3003)) * t27 * t41 * in.w[0] + (T(1) / T(9009)) * t38 * t43 * in.w[2];
    G_ab = (T(1) / T(9009)) * in.w[1] * t38 * t43 + (T(1) / T(9009)) * (T(2) * t38 * t43 * b + T(13) * t37 * t38 - T(3) * c * t38 * t42) * t38 * in.w[2] + (T(1) / T(3003)) * t38 * t42 * in.w[0];
  }
  const T g_factor = -T(13) * length * in.s;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 50 +, 130 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w3_f(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(39) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.39 a min(q(0), q(1)): recurrence (1) downwards from J_13 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = J_downward<T>(T(13), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t3 * t7 - T(11) * b * t8 - t13 * t9;
    const T t15 = T(11) * D * t8 - b * t13 * t9 - t3 * a_minus_b * t7;
    const T t16 = T(20) * b * t2 * t14 + T(110) * c * t8 - T(11) * t2 * t15;
    F = (T(1) / T(990)) * in.w[3] * t2 * (T(90) * c * t2 * t14 - T(11) * (T(10) * t3 * t6 - T(9) * b * t2 * t15 - T(10) * t12 * t9) * t2 - T(18) * b * t16 * t2) + in.w[0] * t8 - (T(1) / T(110)) * in.w[2] * t16 * t2 - (T(1) / T(11)) * in.w[1] * t2 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / D;
    const T t18 = T(1) / r0;
    const T t19 = t18 * t18;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t24 * t24;
    const T t27 = t20 * t20;
    const T t28 = T(8) * t17 * a * (T(5) * b * t21 * t18 + T(2) * (T(3) * b * t20 * t18 + T(4) * (t22 * a_minus_b * t23 + T(2) * (b * t18 + t22 * a_minus_b) * t17 * a + b * t19 * t18) * t17 * a + T(3) * t22 * a_minus_b * t24) * t17 * a + T(5) * t22 * a_minus_b * t25) + T(35) * t22 * a_minus_b * t26 + T(35) * b * t27 * t18;
    const T t29 = t27 * t19;
    const T t30 = t26 * t23;
    const T t31 = T(2) * t17 * a * t28 + T(63) * b * t29 * t18 + T(63) * t22 * a_minus_b * t30;
    const T t32 = T(1) / a;
    const T t33 = T(63) * t22 * t30 - b * t31 * t17 - T(63) * t29 * t18;
    const T t34 = T(5) * c * t31 * t17 + T(10) * b * t32 * t33 - T(11) * t17 * t28;
    F = (T(1) / T(693)) * t31 * t17 * in.w[0] + (T(1) / T(3465)) * (T(5) * c * t32 * t33 - T(11) * t32 * (T(35) * t22 * t26 - b * t17 * t28 - T(35) * t27 * t18) - T(2) * b * t34 * t32) * in.w[3] * t32 - (T(1) / T(3465)) * in.w[2] * t34 * t32 - (T(1) / T(693)) * in.w[1] * t32 * t33;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 62 +, 179 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i13_w3_grad(const SegmentInput<T>& in) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
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
    const T t13 = t3 * t7 + T(13) * b * t2 - t8 * t12;
    const T t14 = T(1) / a;
    const T t15 = b * t3 * t7 + t8 * a_minus_b * t12 - T(13) * t2 * D;
    const T t16 = T(24) * t13 * b * t14 - T(156) * t2 * c - T(13) * t14 * t15;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = t10 * t10;
    const T t20 = t19 * t9;
    const T t21 = T(12) * t3 * t18 - T(12) * t8 * t20 - T(11) * b * t14 * t15;
    const T t22 = T(22) * b * t14 * t16 + T(13) * t21 * t14 - T(132) * t13 * c * t14;
    G_ap = t2 * in.w[0] + (T(1) / T(13)) * t13 * in.w[1] * t14 + (T(1) / T(1716)) * t22 * t14 * in.w[3] + (T(1) / T(156)) * in.w[2] * t14 * t16;
    G_ab = (T(1) / T(17160)) * (T(20) * b * t22 * t14 - T(13) * (T(11) * t14 * (T(12) * b * t3 * t18 + T(11) * D * t14 * t15 + T(12) * t8 * a_minus_b * t20) - T(110) * c * t14 * t15 - T(20) * b * t21 * t14) * t14 - T(110) * c * t14 * t16) * t14 * in.w[3] + (T(1) / T(156)) * in.w[1] * t14 * t16 + (T(1) / T(13)) * t13 * t14 * in.w[0] + (T(1) / T(1716)) * t22 * in.w[2] * t14;
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
    const T t37 = T(1) / D;
    const T t38 = T(35) * b * t23 * t33 + T(35) * t28 * a_minus_b * t35 + T(8) * (T(5) * b * t23 * t26 + T(2) * (T(3) * b * t23 * t25 + T(3) * t28 * a_minus_b * t30 + T(4) * t37 * a * (t28 * a_minus_b * t29 + b * t23 * t24 + T(2) * (t28 * a_minus_b + b * t23) * t37 * a)) * t37 * a + T(5) * t28 * a_minus_b * t31) * t37 * a;
    const T t39 = T(63) * b * t23 * t34 + T(63) * t28 * a_minus_b * t36 + T(2) * t38 * t37 * a;
    const T t40 = T(231) * b * t23 * t27 + T(231) * t28 * a_minus_b * t32 + T(4) * t39 * t37 * a;
    const T t41 = T(231) * t23 * t27 + b * t40 * t37 - T(231) * t28 * t32;
    const T t42 = T(1) / a;
    const T t43 = T(3) * c * t40 * t37 - T(6) * b * t41 * t42 - T(13) * t39 * t37;
    const T t44 = T(63) * t23 * t34 + b * t39 * t37 - T(63) * t28 * t36;
    const T t45 = T(3) * t41 * c * t42 + T(2) * b * t43 * t42 - T(13) * t44 * t42;
    G_ap = (T(1) / T(3003)) * t40 * t37 * in.w[0] + (T(1) / T(3003)) * in.w[1] * t41 * t42 - (T(1) / T(9009)) * t43 * in.w[2] * t42 - (T(1) / T(9009)) * t45 * t42 * in.w[3];
    G_ab = (T(1) / T(3003)) * t41 * t42 * in.w[0] + (T(1) / T(45045)) * t42 * in.w[3] * (T(5) * t43 * c * t42 - T(10) * b * t45 * t42 - T(13) * (T(5) * c * t39 * t37 - T(11) * t38 * t37 - T(10) * b * t44 * t42) * t42) - (T(1) / T(9009)) * t45 * in.w[2] * t42 - (T(1) / T(9009)) * t43 * in.w[1] * t42;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 69 +, 206 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i13_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(11) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = T(13) * D * t2 - t7 * t3 * a_minus_b - t12 * t8 * b;
    const T t14 = T(1) / a;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = T(12) * t16 * t8 + T(11) * t13 * t14 * b - T(12) * t18 * t3;
    const T t20 = T(11) * t13 * t14 * D - T(12) * t16 * t8 * b - T(12) * t18 * t3 * a_minus_b;
    const T t21 = T(20) * t14 * b * t19 + T(11) * t20 * t14 - T(110) * c * t13 * t14;
    F = (T(1) / T(12)) * t13 * t14 * in.w[0] + (T(1) / T(1320)) * t21 * in.w[2] * t14 + (T(1) / T(3960)) * t14 * in.w[3] * (T(6) * t21 * t14 * b + T(11) * (T(3) * t20 * t14 * b + T(40) * t15 * t8 - T(40) * t17 * t3) * t14 - T(30) * c * t14 * t19) + (T(1) / T(132)) * t14 * in.w[1] * t19;
    const T t22 = t12 * t8 + T(13) * t2 * b - t7 * t3;
    const T t23 = T(13) * t13 * t14 + T(24) * t22 * t14 * b - T(156) * c * t2;
    const T t24 = T(132) * c * t22 * t14 - T(22) * t14 * t23 * b - T(13) * t14 * t19;
    G_ap = t2 * in.w[0] + (T(1) / T(156)) * in.w[2] * t14 * t23 + (T(1) / T(13)) * t22 * t14 * in.w[1] - (T(1) / T(1716)) * t14 * t24 * in.w[3];
    G_ab = (T(1) / T(13)) * t22 * t14 * in.w[0] + (T(1) / T(156)) * t14 * t23 * in.w[1] - (T(1) / T(1716)) * in.w[2] * t14 * t24 - (T(1) / T(17160)) * (T(20) * t14 * t24 * b + T(110) * c * t14 * t23 - T(13) * t21 * t14) * t14 * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t26;
    const T t30 = T(1) / r1;
    const T t31 = t30 * t30;
    const T t32 = t31 * t31;
    const T t33 = t32 * t32;
    const T t34 = t33 * t31;
    const T t35 = T(1) / D;
    const T t36 = t32 * t31;
    const T t37 = t27 * t26;
    const T t38 = T(35) * t28 * t25 * b + T(8) * (T(5) * t36 * t30 * a_minus_b + T(2) * (T(3) * t27 * t25 * b + T(3) * t32 * t30 * a_minus_b + T(4) * (t31 * t30 * a_minus_b + T(2) * (t25 * b + t30 * a_minus_b) * a * t35 + t26 * t25 * b) * a * t35) * a * t35 + T(5) * t37 * t25 * b) * a * t35 + T(35) * t33 * t30 * a_minus_b;
    const T t39 = T(63) * t29 * t25 * b + T(63) * t34 * t30 * a_minus_b + T(2) * a * t35 * t38;
    const T t40 = T(1) / a;
    const T t41 = T(63) * t29 * t25 + t39 * t35 * b - T(63) * t34 * t30;
    const T t42 = T(10) * t40 * b * t41 + T(11) * t35 * t38 - T(5) * c * t39 * t35;
    F = (T(1) / T(693)) * t39 * t35 * in.w[0] + (T(1) / T(3465)) * t40 * (T(2) * t42 * t40 * b + T(11) * (T(35) * t28 * t25 + t35 * b * t38 - T(35) * t33 * t30) * t40 - T(5) * c * t40 * t41) * in.w[3] + (T(1) / T(693)) * t40 * in.w[1] * t41 + (T(1) / T(3465)) * in.w[2] * t42 * t40;
    const T t43 = t37 * t37;
    const T t44 = t36 * t36;
    const T t45 = T(231) * t44 * t30 * a_minus_b + T(231) * t43 * t25 * b + T(4) * t39 * a * t35;
    const T t46 = T(231) * t43 * t25 + t45 * t35 * b - T(231) * t44 * t30;
    const T t47 = T(6) * t46 * t40 * b + T(13) * t39 * t35 - T(3) * c * t45 * t35;
    const T t48 = T(3) * t46 * c * t40 - T(13) * t40 * t41 - T(2) * t47 * t40 * b;
    G_ap = (T(1) / T(3003)) * t46 * t40 * in.w[1] + (T(1) / T(3003)) * t45 * t35 * in.w[0] + (T(1) / T(9009)) * t47 * in.w[2] * t40 - (T(1) / T(9009)) * t40 * in.w[3] * t48;
    G_ab = (T(1) / T(9009)) * t47 * t40 * in.w[1] + (T(1) / T(3003)) * t46 * t40 * in.w[0] - (T(1) / T(45045)) * t40 * in.w[3] * (T(10) * t40 * b * t48 + T(5) * t47 * c * t40 - T(13) * t42 * t40) - (T(1) / T(9009)) * in.w[2] * t40 * t48;
  }
  const T g_factor = -T(13) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 43 +, 91 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w0_f(const SegmentInput<T>& in) {
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    F = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t5 * t5;
    const T t13 = t12 * t4;
    const T t14 = t9 * t9;
    const T t15 = t14 * t8;
    const T t16 = T(1) / D;
    F = (T(1) / T(15360)) * (T(1280) * a_minus_b * t7 + T(1280) * b * t11 + T(11) * (T(128) * a_minus_b * t13 + T(128) * b * t15 + T(3) * (T(48) * a_minus_b * t12 + T(7) * (T(8) * a_minus_b * t6 + T(8) * b * t10 + T(5) * (T(2) * a_minus_b * t5 + T(3) * (b * t8 + a * J2 + a_minus_b * t4) * t16 * a + T(2) * b * t9) * t16 * a) * t16 * a + T(48) * b * t14) * t16 * a) * t16 * a) * in.w[0] * t16;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 50 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i14_w0_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    G_ap = in.w[0] * t2;
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    G_ab = (T(1) / T(14)) * t3 * in.w[0] * (t8 + T(14) * b * t2 - t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = t20 * t17;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t18 * t18;
    const T t27 = t26 * t17;
    const T t28 = t23 * t23;
    const T t29 = t28 * t22;
    const T t30 = t25 * t22;
    const T t31 = T(15360) * t21 * a_minus_b + T(13) * t16 * a * (T(1280) * t20 * a_minus_b + T(1280) * b * t25 + T(11) * t16 * a * (T(128) * t27 * a_minus_b + T(128) * b * t29 + T(3) * t16 * a * (T(48) * t26 * a_minus_b + T(7) * t16 * a * (T(5) * t16 * a * (T(2) * t18 * a_minus_b + T(3) * t16 * a * (b * t22 + t17 * a_minus_b + a * J2) + T(2) * b * t23) + T(8) * t19 * a_minus_b + T(8) * b * t24) + T(48) * b * t28))) + T(15360) * b * t30;
    G_ap = (T(1) / T(215040)) * t16 * in.w[0] * t31;
    const T t32 = T(1) / a;
    G_ab = (T(1) / T(215040)) * t32 * in.w[0] * (T(15360) * t30 + t16 * t31 * b - T(15360) * t21);
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 50 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    F = (T(1) / T(13)) * t2 * in.w[0] * (T(14) * t3 * D - b * t8 - a_minus_b * t13);
    G_ap = in.w[0] * t3;
    G_ab = (T(1) / T(14)) * t2 * in.w[0] * (t8 + T(14) * b * t3 - t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = atan2(t14, c_minus_b) * t15;
    const T t16 = T(1) / D;
    const T t17 = T(1) / c;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t17;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = t22 * t21;
    const T t26 = t18 * t17;
    const T t27 = t26 * t26;
    const T t28 = t25 * t25;
    const T t29 = T(11) * a * (T(128) * b * t20 + T(128) * a_minus_b * t24 + T(3) * a * (T(48) * b * t19 + T(7) * (T(5) * a * (T(3) * a * (b * t17 + a_minus_b * t21 + a * J2) * t16 + T(2) * a_minus_b * t22 + T(2) * b * t18) * t16 + T(8) * a_minus_b * t25 + T(8) * b * t26) * a * t16 + T(48) * a_minus_b * t23) * t16) * t16 + T(1280) * b * t27 + T(1280) * a_minus_b * t28;
    F = (T(1) / T(15360)) * in.w[0] * t16 * t29;
    const T t30 = t27 * t17;
    const T t31 = t28 * t21;
    const T t32 = T(13) * a * t16 * t29 + T(15360) * b * t30 + T(15360) * a_minus_b * t31;
    G_ap = (T(1) / T(215040)) * in.w[0] * t32 * t16;
    const T t33 = T(1) / a;
    G_ab = (T(1) / T(215040)) * t33 * in.w[0] * (T(15360) * t30 + b * t32 * t16 - T(15360) * t31);
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 46 +, 98 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w1_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = T(1) / a;
    F = in.w[0] * t2 + (T(1) / T(12)) * (t6 + T(12) * b * t2 - t10) * t11 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / a;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15;
    const T t18 = t17 * t17;
    const T t19 = T(1) / D;
    const T t20 = t16 * t16;
    const T t21 = t20 * t15;
    const T t22 = T(1) / q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t23 * t23;
    const T t26 = t25 * t22;
    const T t27 = t24 * t24;
    const T t28 = T(11) * t19 * a * (T(128) * t21 * b + T(3) * (T(7) * (T(8) * t17 * b + T(5) * t19 * a * (T(3) * t19 * a * (a_minus_b * t22 + a * J2 + t15 * b) + T(2) * t16 * b + T(2) * a_minus_b * t23) + T(8) * a_minus_b * t24) * t19 * a + T(48) * a_minus_b * t25 + T(48) * t20 * b) * t19 * a + T(128) * a_minus_b * t26) + T(1280) * t18 * b + T(1280) * a_minus_b * t27;
    F = (T(1) / T(15360)) * t14 * in.w[1] * (T(1280) * t18 + t28 * t19 * b - T(1280) * t27) + (T(1) / T(15360)) * in.w[0] * t28 * t19;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 54 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i14_w1_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = t8 - T(14) * b * t2 - t13;
    G_ap = in.w[0] * t2 - (T(1) / T(14)) * t3 * in.w[1] * t14;
    G_ab = -(T(1) / T(14)) * in.w[0] * t3 * t14 - (T(1) / T(91)) * t3 * in.w[1] * (T(91) * t2 * c + T(13) * t3 * t14 * b - T(7) * t3 * (T(14) * D * t2 - a_minus_b * t8 - b * t13));
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = t20 * t17;
    const T t22 = T(1) / D;
    const T t23 = T(1) / c;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t18 * t18;
    const T t27 = t24 * t24;
    const T t28 = t26 * t17;
    const T t29 = t27 * t23;
    const T t30 = t25 * t25;
    const T t31 = T(11) * t22 * a * (T(3) * t22 * a * (T(7) * t22 * a * (T(5) * t22 * a * (T(2) * b * t24 + T(3) * t22 * a * (a_minus_b * t17 + b * t23 + a * J2) + T(2) * a_minus_b * t18) + T(8) * b * t25 + T(8) * a_minus_b * t19) + T(48) * a_minus_b * t26 + T(48) * b * t27) + T(128) * a_minus_b * t28 + T(128) * b * t29) + T(1280) * a_minus_b * t20 + T(1280) * b * t30;
    const T t32 = t30 * t23;
    const T t33 = T(15360) * a_minus_b * t21 + T(13) * t22 * t31 * a + T(15360) * b * t32;
    const T t34 = T(15360) * t21 - t33 * t22 * b - T(15360) * t32;
    const T t35 = T(1) / a;
    G_ap = (T(1) / T(215040)) * in.w[0] * t33 * t22 - (T(1) / T(215040)) * t34 * t35 * in.w[1];
    G_ab = -(T(1) / T(215040)) * (t33 * t22 * c + T(2) * t34 * t35 * b - T(14) * t22 * t31) * t35 * in.w[1] - (T(1) / T(215040)) * in.w[0] * t34 * t35;
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 57 +, 141 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t10 * t7;
    const T t12 = t6 * t3;
    const T t13 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t14 = b * t11 + t12 * a_minus_b - T(14) * t13 * D;
    F = -(T(1) / T(156)) * in.w[1] * t2 * (T(13) * t6 + T(12) * b * t14 * t2 - T(13) * t10) - (T(1) / T(13)) * in.w[0] * t14 * t2;
    const T t15 = t12 - t11 - T(14) * b * t13;
    G_ap = in.w[0] * t13 - (T(1) / T(14)) * t15 * in.w[1] * t2;
    G_ab = -(T(1) / T(14)) * in.w[0] * t15 * t2 - (T(1) / T(91)) * (T(7) * t14 * t2 + T(91) * c * t13 + T(13) * b * t15 * t2) * in.w[1] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, c_minus_b);
    const T t18 = T(1) / c;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = T(1) / q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t23;
    const T t27 = t19 * t19;
    const T t28 = t24 * t23;
    const T t29 = t27 * t18;
    const T t30 = t28 * t28;
    const T t31 = T(1280) * b * t21 + T(11) * t22 * a * (T(128) * t26 * a_minus_b + T(3) * (T(48) * t25 * a_minus_b + T(48) * b * t27 + T(7) * (T(8) * b * t20 + T(5) * (T(3) * t22 * a * (t23 * a_minus_b + J2 * a + b * t18) + T(2) * b * t19 + T(2) * t24 * a_minus_b) * t22 * a + T(8) * t28 * a_minus_b) * t22 * a) * t22 * a + T(128) * b * t29) + T(1280) * t30 * a_minus_b;
    const T t32 = T(1) / a;
    F = (T(1) / T(15360)) * t31 * in.w[0] * t22 + (T(1) / T(15360)) * (b * t31 * t22 + T(1280) * t21 - T(1280) * t30) * in.w[1] * t32;
    const T t33 = t21 * t18;
    const T t34 = t30 * t23;
    const T t35 = T(15360) * b * t33 + T(15360) * t34 * a_minus_b + T(13) * t31 * t22 * a;
    const T t36 = b * t35 * t22 + T(15360) * t33 - T(15360) * t34;
    G_ap = (T(1) / T(215040)) * t36 * in.w[1] * t32 + (T(1) / T(215040)) * in.w[0] * t35 * t22;
    G_ab = (T(1) / T(215040)) * (T(14) * t31 * t22 + T(2) * b * t36 * t32 - c * t35 * t22) * in.w[1] * t32 + (T(1) / T(215040)) * in.w[0] * t36 * t32;
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 49 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w2_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(21) / T(50)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t7 - T(12) * b * t2 - t11;
    F = in.w[0] * t2 + (T(1) / T(66)) * t3 * (T(6) * (T(12) * D * t2 - a_minus_b * t7 - b * t11) * t3 - T(66) * c * t2 - T(11) * b * t12 * t3) * in.w[2] - (T(1) / T(12)) * t12 * in.w[1] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / D;
    const T t16 = T(1) / c;
    const T t17 = t16 * t16;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t17 * t16;
    const T t21 = t19 * t18;
    const T t22 = t19 * t19;
    const T t23 = t17 * t17;
    const T t24 = t22 * t18;
    const T t25 = t23 * t16;
    const T t26 = T(3) * (T(7) * t15 * a * (T(5) * t15 * (T(2) * b * t17 + T(2) * a_minus_b * t19 + T(3) * (a_minus_b * t18 + b * t16 + a * J2) * t15 * a) * a + T(8) * b * t20 + T(8) * a_minus_b * t21) + T(48) * a_minus_b * t22 + T(48) * b * t23) * t15 * a + T(128) * a_minus_b * t24 + T(128) * b * t25;
    const T t27 = t21 * t21;
    const T t28 = t20 * t20;
    const T t29 = T(11) * t26 * t15 * a + T(1280) * a_minus_b * t27 + T(1280) * b * t28;
    const T t30 = b * t29 * t15 + T(1280) * t28 - T(1280) * t27;
    const T t31 = T(1) / a;
    F = (T(1) / T(15360)) * in.w[1] * t30 * t31 + (T(1) / T(15360)) * t29 * in.w[0] * t15 - (T(1) / T(15360)) * t31 * (t29 * c * t15 - T(12) * t26 * t15 - T(2) * b * t30 * t31) * in.w[2];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 60 +, 147 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i14_w2_grad(const SegmentInput<T>& in) {
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = T(14) * t3 * b + t8 - t13;
    const T t15 = b * t8 + t13 * a_minus_b - T(14) * t3 * D;
    const T t16 = T(7) * t2 * t15 + T(91) * t3 * c - T(13) * t2 * b * t14;
    G_ap = (T(1) / T(14)) * t2 * t14 * in.w[1] + t3 * in.w[0] - (T(1) / T(91)) * t2 * t16 * in.w[2];
    G_ab = (T(1) / T(14)) * t2 * in.w[0] * t14 - (T(1) / T(1092)) * t2 * (T(78) * t2 * t14 * c + T(7) * t2 * (T(13) * t12 + T(12) * t2 * t15 * b - T(13) * t7) + T(24) * t2 * b * t16) * in.w[2] - (T(1) / T(91)) * t2 * t16 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = atan2(t17, c_minus_b) * t18;
    const T t19 = T(1) / c;
    const T t20 = t19 * t19;
    const T t21 = t20 * t19;
    const T t22 = t21 * t21;
    const T t23 = t22 * t19;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = t27 * t24;
    const T t29 = t20 * t20;
    const T t30 = t29 * t19;
    const T t31 = T(1) / D;
    const T t32 = t25 * t25;
    const T t33 = t32 * t24;
    const T t34 = T(1280) * b * t22 + T(1280) * t27 * a_minus_b + T(11) * a * (T(128) * b * t30 + T(3) * a * (T(7) * a * (T(8) * t26 * a_minus_b + T(8) * b * t21 + T(5) * a * (T(2) * b * t20 + T(3) * a * (t24 * a_minus_b + a * J2 + b * t19) * t31 + T(2) * t25 * a_minus_b) * t31) * t31 + T(48) * b * t29 + T(48) * t32 * a_minus_b) * t31 + T(128) * t33 * a_minus_b) * t31;
    const T t35 = T(15360) * b * t23 + T(15360) * t28 * a_minus_b + T(13) * a * t34 * t31;
    const T t36 = T(1) / a;
    const T t37 = t35 * b * t31 + T(15360) * t23 - T(15360) * t28;
    const T t38 = T(2) * t36 * b * t37 + T(14) * t34 * t31 - t35 * c * t31;
    G_ap = (T(1) / T(215040)) * t35 * in.w[0] * t31 + (T(1) / T(215040)) * t36 * t37 * in.w[1] + (T(1) / T(215040)) * t36 * t38 * in.w[2];
    G_ab = (T(1) / T(215040)) * t36 * in.w[0] * t37 + (T(1) / T(215040)) * t36 * in.w[1] * t38 - (T(1) / T(215040)) * t36 * (t36 * t37 * c + T(14) * t36 * (T(1280) * t27 - b * t34 * t31 - T(1280) * t22) - T(2) * t36 * b * t38) * in.w[2];
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 64 +, 164 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t11 * t8;
    const T t13 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t14 = t7 * b + t12 * a_minus_b - T(14) * t13 * D;
    const T t15 = T(13) * t11 + T(12) * t2 * t14 * b - T(13) * t6;
    F = -(T(1) / T(13)) * in.w[0] * t2 * t14 - (T(1) / T(858)) * (T(11) * t15 * t2 * b + T(6) * t2 * (T(13) * t6 * b + T(12) * D * t2 * t14 + T(13) * t11 * a_minus_b) - T(66) * c * t2 * t14) * t2 * in.w[2] - (T(1) / T(156)) * t15 * in.w[1] * t2;
    const T t16 = T(14) * t13 * b + t7 - t12;
    const T t17 = T(91) * t13 * c + T(7) * t2 * t14 - T(13) * t16 * t2 * b;
    G_ap = in.w[0] * t13 + (T(1) / T(14)) * t16 * in.w[1] * t2 - (T(1) / T(91)) * t17 * t2 * in.w[2];
    G_ab = (T(1) / T(14)) * in.w[0] * t16 * t2 - (T(1) / T(91)) * in.w[1] * t17 * t2 - (T(1) / T(1092)) * t2 * (T(7) * t15 * t2 + T(24) * t17 * t2 * b + T(78) * c * t16 * t2) * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = sqrt(D);
    const T t19 = T(1) / t18;
    const T J2 = atan2(t18, c_minus_b) * t19;
    const T t20 = T(1) / c;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t22 * t22;
    const T t24 = T(1) / q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = T(1) / D;
    const T t29 = t21 * t21;
    const T t30 = t29 * t20;
    const T t31 = t25 * t25;
    const T t32 = t31 * t24;
    const T t33 = T(128) * t30 * b + T(3) * t28 * a * (T(48) * t29 * b + T(7) * (T(8) * t26 * a_minus_b + T(5) * t28 * a * (T(3) * t28 * a * (t20 * b + t24 * a_minus_b + J2 * a) + T(2) * t25 * a_minus_b + T(2) * t21 * b) + T(8) * t22 * b) * t28 * a + T(48) * t31 * a_minus_b) + T(128) * t32 * a_minus_b;
    const T t34 = T(1280) * t23 * b + T(1280) * t27 * a_minus_b + T(11) * t28 * a * t33;
    const T t35 = T(1) / a;
    const T t36 = T(1280) * t27 - T(1280) * t23 - t34 * t28 * b;
    F = (T(1) / T(15360)) * in.w[0] * t34 * t28 - (T(1) / T(15360)) * t35 * in.w[2] * (t34 * c * t28 + T(2) * t35 * t36 * b - T(12) * t28 * t33) - (T(1) / T(15360)) * in.w[1] * t35 * t36;
    const T t37 = t23 * t20;
    const T t38 = t27 * t24;
    const T t39 = T(13) * t34 * t28 * a + T(15360) * t37 * b + T(15360) * t38 * a_minus_b;
    const T t40 = t39 * t28 * b + T(15360) * t37 - T(15360) * t38;
    const T t41 = T(14) * t34 * t28 + T(2) * t35 * t40 * b - c * t39 * t28;
    G_ap = (T(1) / T(215040)) * in.w[1] * t35 * t40 + (T(1) / T(215040)) * t41 * t35 * in.w[2] + (T(1) / T(215040)) * in.w[0] * t39 * t28;
    G_ab = (T(1) / T(215040)) * in.w[0] * t35 * t40 + (T(1) / T(215040)) * (T(2) * t41 * t35 * b - T(14) * t35 * t36 - c * t35 * t40) * t35 * in.w[2] + (T(1) / T(215040)) * in.w[1] * t41 * t35;
  }
  const T g_factor = -T(14) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 54 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w3_f(const SegmentInput<T>& in) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(21) / T(50)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.42 a min(q(0), q(1)): recurrence (1) downwards from J_14 = J_downward(…)
    const T t2 = J_downward<T>(T(14), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = t7 + T(12) * b * t2 - t11;
    const T t13 = T(12) * D * t2 - a_minus_b * t11 - b * t7;
    const T t14 = T(66) * t2 * c - T(11) * t3 * b * t12 - T(6) * t3 * t13;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = t9 * t9;
    const T t18 = t17 * t8;
    F = in.w[0] * t2 + (T(1) / T(12)) * t3 * in.w[1] * t12 - (T(1) / T(660)) * t3 * (T(55) * t3 * c * t12 + T(20) * t3 * t14 * b - T(6) * (T(11) * t16 + T(10) * t3 * b * t13 - T(11) * t18) * t3) * in.w[3] - (T(1) / T(66)) * t3 * t14 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = t20 * atan2(t19, c_minus_b);
    const T t21 = T(1) / D;
    const T t22 = T(1) / q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t22;
    const T t26 = T(1) / c;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t23 * t22;
    const T t30 = t27 * t26;
    const T t31 = t28 * t26;
    const T t32 = T(128) * a_minus_b * t25 + T(3) * t21 * a * (T(48) * a_minus_b * t24 + T(48) * b * t28 + T(7) * t21 * a * (T(5) * t21 * a * (T(2) * a_minus_b * t23 + T(2) * b * t27 + T(3) * t21 * a * (b * t26 + a_minus_b * t22 + a * J2)) + T(8) * a_minus_b * t29 + T(8) * b * t30)) + T(128) * b * t31;
    const T t33 = t30 * t30;
    const T t34 = t29 * t29;
    const T t35 = T(11) * t21 * a * t32 + T(1280) * a_minus_b * t34 + T(1280) * b * t33;
    const T t36 = T(1280) * t33 + t21 * b * t35 - T(1280) * t34;
    const T t37 = T(1) / a;
    const T t38 = T(12) * t21 * t32 + T(2) * t36 * t37 * b - t21 * t35 * c;
    F = (T(1) / T(15360)) * t38 * t37 * in.w[2] + (T(1) / T(15360)) * t21 * in.w[0] * t35 + (T(1) / T(15360)) * t36 * t37 * in.w[1] - (T(1) / T(15360)) * t37 * (t36 * t37 * c - T(12) * t37 * (t21 * b * t32 + T(128) * t31 - T(128) * t25) - T(2) * t38 * t37 * b) * in.w[3];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 66 +, 167 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i14_w3_grad(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / c;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t6 * t3;
    const T t12 = t10 * t7;
    const T t13 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t14 = t11 * b + a_minus_b * t12 - T(14) * D * t13;
    const T t15 = T(13) * t6 - T(13) * t10 - T(12) * t2 * b * t14;
    const T t16 = t11 + T(14) * t13 * b - t12;
    const T t17 = T(13) * t16 * t2 * b - T(91) * c * t13 - T(7) * t2 * t14;
    const T t18 = T(7) * t15 * t2 + T(24) * t2 * b * t17 - T(78) * c * t16 * t2;
    G_ap = (T(1) / T(1092)) * t2 * in.w[3] * t18 + (T(1) / T(91)) * in.w[2] * t2 * t17 + (T(1) / T(14)) * t16 * t2 * in.w[1] + t13 * in.w[0];
    G_ab = (T(1) / T(1092)) * in.w[2] * t2 * t18 + (T(1) / T(6006)) * t2 * in.w[3] * (T(11) * t2 * b * t18 + T(7) * (T(66) * c * t2 * t14 + T(11) * t15 * t2 * b - T(6) * t2 * (T(13) * t6 * b + T(12) * D * t2 * t14 + T(13) * a_minus_b * t10)) * t2 - T(66) * c * t2 * t17) + (T(1) / T(91)) * t2 * t17 * in.w[1] + (T(1) / T(14)) * t16 * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = sqrt(D);
    const T t20 = T(1) / t19;
    const T J2 = atan2(t19, c_minus_b) * t20;
    const T t21 = T(1) / c;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t23 * t23;
    const T t25 = t24 * t21;
    const T t26 = T(1) / D;
    const T t27 = T(1) / q1;
    const T t28 = t27 * t27;
    const T t29 = t28 * t27;
    const T t30 = t29 * t29;
    const T t31 = t30 * t27;
    const T t32 = t22 * t22;
    const T t33 = t32 * t21;
    const T t34 = t28 * t28;
    const T t35 = t34 * t27;
    const T t36 = T(128) * t33 * b + T(3) * t26 * a * (T(48) * t32 * b + T(7) * t26 * a * (T(5) * t26 * a * (T(2) * t22 * b + T(2) * a_minus_b * t28 + T(3) * t26 * a * (a * J2 + a_minus_b * t27 + t21 * b)) + T(8) * t23 * b + T(8) * a_minus_b * t29) + T(48) * a_minus_b * t34) + T(128) * a_minus_b * t35;
    const T t37 = T(11) * t26 * a * t36 + T(1280) * t24 * b + T(1280) * a_minus_b * t30;
    const T t38 = T(15360) * t25 * b + T(15360) * a_minus_b * t31 + T(13) * t26 * a * t37;
    const T t39 = T(15360) * t25 + t26 * t38 * b - T(15360) * t31;
    const T t40 = T(1) / a;
    const T t41 = T(2) * t39 * t40 * b + T(14) * t26 * t37 - c * t26 * t38;
    const T t42 = t26 * t37 * b + T(1280) * t24 - T(1280) * t30;
    const T t43 = c * t39 * t40 - T(14) * t40 * t42 - T(2) * t40 * t41 * b;
    G_ap = (T(1) / T(215040)) * t39 * t40 * in.w[1] + (T(1) / T(215040)) * t26 * t38 * in.w[0] + (T(1) / T(215040)) * in.w[2] * t40 * t41 - (T(1) / T(215040)) * t40 * in.w[3] * t43;
    G_ab = (T(1) / T(215040)) * t40 * t41 * in.w[1] + (T(1) / T(215040)) * t39 * t40 * in.w[0] - (T(1) / T(215040)) * t40 * in.w[3] * (T(2) * t40 * t43 * b + c * t40 * t41 - T(14) * (T(2) * t40 * b * t42 + T(12) * t26 * t36 - c * t26 * t37) * t40) - (T(1) / T(215040)) * in.w[2] * t40 * t43;
  }
  const T g_factor = -T(14) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 73 +, 191 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i14_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / q1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = t5 * t2;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t9 * t9;
    const T t11 = t10 * t7;
    const T t12 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t13 = a_minus_b * t6 + t11 * b - T(14) * D * t12;
    const T t14 = T(1) / a;
    const T t15 = T(12) * t13 * t14 * b + T(13) * t5 - T(13) * t10;
    const T t16 = T(13) * a_minus_b * t5 + T(12) * t13 * D * t14 + T(13) * t10 * b;
    const T t17 = T(66) * t13 * c * t14 - T(11) * t15 * t14 * b - T(6) * t14 * t16;
    const T t18 = t8 * t8;
    const T t19 = t18 * t7;
    const T t20 = t3 * t3;
    const T t21 = t20 * t2;
    F = (T(1) / T(8580)) * (T(20) * t17 * t14 * b + T(6) * t14 * (T(143) * t19 - T(10) * t14 * t16 * b - T(143) * t21) + T(55) * t15 * c * t14) * in.w[3] * t14 + (T(1) / T(858)) * t17 * in.w[2] * t14 - (T(1) / T(13)) * t13 * t14 * in.w[0] - (T(1) / T(156)) * t15 * t14 * in.w[1];
    const T t22 = t11 + T(14) * b * t12 - t6;
    const T t23 = T(91) * c * t12 + T(7) * t13 * t14 - T(13) * t14 * t22 * b;
    const T t24 = T(24) * t23 * t14 * b + T(78) * c * t14 * t22 + T(7) * t15 * t14;
    G_ap = (T(1) / T(14)) * t14 * t22 * in.w[1] + in.w[0] * t12 - (T(1) / T(91)) * t23 * in.w[2] * t14 - (T(1) / T(1092)) * in.w[3] * t14 * t24;
    G_ab = (T(1) / T(14)) * t14 * in.w[0] * t22 - (T(1) / T(91)) * t23 * t14 * in.w[1] - (T(1) / T(6006)) * in.w[3] * t14 * (T(11) * t14 * t24 * b - T(66) * t23 * c * t14 - T(7) * t17 * t14) - (T(1) / T(1092)) * in.w[2] * t14 * t24;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(D);
    const T t26 = T(1) / t25;
    const T J2 = atan2(t25, c_minus_b) * t26;
    const T t27 = T(1) / a;
    const T t28 = T(1) / D;
    const T t29 = T(1) / q1;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t31 * t31;
    const T t33 = t30 * t30;
    const T t34 = t33 * t29;
    const T t35 = T(1) / c;
    const T t36 = t35 * t35;
    const T t37 = t36 * t35;
    const T t38 = t36 * t36;
    const T t39 = t38 * t35;
    const T t40 = T(128) * a_minus_b * t34 + T(3) * (T(7) * (T(8) * t37 * b + T(8) * a_minus_b * t31 + T(5) * t28 * a * (T(2) * a_minus_b * t30 + T(3) * (t35 * b + a_minus_b * t29 + J2 * a) * t28 * a + T(2) * t36 * b)) * t28 * a + T(48) * a_minus_b * t33 + T(48) * t38 * b) * t28 * a + T(128) * t39 * b;
    const T t41 = t37 * t37;
    const T t42 = T(1280) * a_minus_b * t32 + T(11) * t40 * t28 * a + T(1280) * t41 * b;
    const T t43 = t28 * t42 * b + T(1280) * t41 - T(1280) * t32;
    const T t44 = c * t28 * t42 - T(12) * t40 * t28 - T(2) * t27 * b * t43;
    F = (T(1) / T(15360)) * t27 * in.w[1] * t43 + (T(1) / T(15360)) * t28 * t42 * in.w[0] - (T(1) / T(15360)) * in.w[2] * t44 * t27 - (T(1) / T(15360)) * in.w[3] * t27 * (c * t27 * t43 + T(2) * t44 * t27 * b - T(12) * t27 * (T(128) * t39 + t40 * t28 * b - T(128) * t34));
    const T t45 = t32 * t29;
    const T t46 = t41 * t35;
    const T t47 = T(15360) * a_minus_b * t45 + T(15360) * t46 * b + T(13) * t28 * a * t42;
    const T t48 = t28 * b * t47 + T(15360) * t46 - T(15360) * t45;
    const T t49 = T(2) * t48 * t27 * b + T(14) * t28 * t42 - c * t28 * t47;
    const T t50 = T(2) * t27 * t49 * b + T(14) * t27 * t43 - t48 * c * t27;
    G_ap = (T(1) / T(215040)) * t28 * in.w[0] * t47 + (T(1) / T(215040)) * t48 * t27 * in.w[1] + (T(1) / T(215040)) * t50 * in.w[3] * t27 + (T(1) / T(215040)) * in.w[2] * t27 * t49;
    G_ab = (T(1) / T(215040)) * t50 * in.w[2] * t27 + (T(1) / T(215040)) * t27 * t49 * in.w[1] + (T(1) / T(215040)) * t48 * t27 * in.w[0] - (T(1) / T(215040)) * in.w[3] * t27 * (T(14) * t44 * t27 + c * t27 * t49 - T(2) * t50 * t27 * b);
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 41 +, 104 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w0_f(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    F = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t13 = t10 * t10;
    const T t14 = t5 * t5;
    const T t15 = t14 * t4;
    const T t16 = t13 * t9;
    F = (T(1) / T(3003)) * t2 * (T(231) * t7 * t3 * b + T(231) * t12 * a_minus_b * t8 + T(4) * (T(2) * t2 * a * (T(35) * t13 * a_minus_b * t8 + T(35) * t14 * t3 * b + T(8) * t2 * a * (T(5) * t11 * a_minus_b * t8 + T(5) * t6 * t3 * b + T(2) * t2 * a * (T(4) * t2 * a * (t9 * a_minus_b * t8 + t4 * t3 * b + T(2) * t2 * (t3 * b + a_minus_b * t8) * a) + T(3) * t5 * t3 * b + T(3) * t10 * a_minus_b * t8))) + T(63) * t15 * t3 * b + T(63) * t16 * a_minus_b * t8) * t2 * a) * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 48 +, 134 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i15_w0_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
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
    const T t15 = T(1) / a;
    G_ab = (T(1) / T(15)) * (t3 * t8 + T(15) * t2 * b - t9 * t14) * t15 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t21 * t18;
    const T t23 = T(1) / r0;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t26 * t26;
    const T t28 = t27 * t24;
    const T t29 = t19 * t19;
    const T t30 = t25 * t25;
    const T t31 = t29 * t18;
    const T t32 = t30 * t24;
    const T t33 = T(429) * t17 * a_minus_b * t22 + T(429) * t23 * t28 * b + T(2) * a * t16 * (T(231) * t17 * a_minus_b * t21 + T(231) * t23 * t27 * b + T(4) * a * t16 * (T(2) * (T(35) * t17 * a_minus_b * t29 + T(8) * a * t16 * (T(5) * t17 * a_minus_b * t20 + T(5) * t23 * t26 * b + T(2) * a * t16 * (T(3) * t17 * a_minus_b * t19 + T(3) * t23 * t25 * b + T(4) * (T(2) * a * t16 * (t23 * b + t17 * a_minus_b) + t23 * t24 * b + t17 * a_minus_b * t18) * a * t16)) + T(35) * t23 * t30 * b) * a * t16 + T(63) * t17 * a_minus_b * t31 + T(63) * t23 * t32 * b));
    G_ap = (T(1) / T(6435)) * t16 * in.w[0] * t33;
    const T t34 = T(1) / a;
    G_ab = (T(1) / T(6435)) * t34 * in.w[0] * (t16 * t33 * b + T(429) * t23 * t28 - T(429) * t17 * t22);
  }
  const T g_factor = -T(15) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 48 +, 138 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / a;
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
    const T t15 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
    F = -(T(1) / T(14)) * in.w[0] * t2 * (t8 * t3 * b + t9 * a_minus_b * t14 - T(15) * t15 * D);
    G_ap = t15 * in.w[0];
    G_ab = (T(1) / T(15)) * in.w[0] * t2 * (t8 * t3 + T(15) * t15 * b - t9 * t14);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / r0;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = T(1) / D;
    const T t27 = t18 * t18;
    const T t28 = t23 * t23;
    const T t29 = t28 * t22;
    const T t30 = t27 * t17;
    const T t31 = T(231) * t20 * t16 * b + T(231) * t21 * a_minus_b * t25 + T(4) * t26 * a * (T(2) * t26 * a * (T(8) * t26 * a * (T(5) * t19 * t16 * b + T(2) * t26 * a * (T(4) * (t21 * a_minus_b * t22 + t17 * t16 * b + T(2) * t26 * a * (t16 * b + t21 * a_minus_b)) * t26 * a + T(3) * t18 * t16 * b + T(3) * t21 * a_minus_b * t23) + T(5) * t21 * a_minus_b * t24) + T(35) * t27 * t16 * b + T(35) * t21 * a_minus_b * t28) + T(63) * t21 * a_minus_b * t29 + T(63) * t30 * t16 * b);
    F = (T(1) / T(3003)) * in.w[0] * t31 * t26;
    const T t32 = t20 * t17;
    const T t33 = t25 * t22;
    const T t34 = T(429) * t32 * t16 * b + T(429) * t21 * a_minus_b * t33 + T(2) * t31 * t26 * a;
    G_ap = (T(1) / T(6435)) * in.w[0] * t26 * t34;
    const T t35 = T(1) / a;
    G_ab = (T(1) / T(6435)) * (T(429) * t32 * t16 + t26 * b * t34 - T(429) * t21 * t33) * in.w[0] * t35;
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 44 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w1_f(const SegmentInput<T>& in) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
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
    const T t13 = T(1) / a;
    F = t2 * in.w[0] + (T(1) / T(13)) * (T(13) * t2 * b + t3 * t7 - t8 * t12) * t13 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / a;
    const T t15 = T(1) / D;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t22 * t21;
    const T t25 = t18 * t17;
    const T t26 = t23 * t21;
    const T t27 = t19 * t17;
    const T t28 = t25 * t25;
    const T t29 = t24 * t24;
    const T t30 = T(4) * (T(2) * t15 * a * (T(35) * a_minus_b * t16 * t19 + T(35) * t20 * b * t23 + T(8) * (T(2) * t15 * a * (T(4) * (a_minus_b * t16 * t17 + t20 * b * t21 + T(2) * (a_minus_b * t16 + t20 * b) * t15 * a) * t15 * a + T(3) * t20 * b * t22 + T(3) * a_minus_b * t16 * t18) + T(5) * t20 * b * t24 + T(5) * a_minus_b * t16 * t25) * t15 * a) + T(63) * t20 * b * t26 + T(63) * a_minus_b * t16 * t27) * t15 * a + T(231) * a_minus_b * t16 * t28 + T(231) * t20 * b * t29;
    F = (T(1) / T(3003)) * t14 * in.w[1] * (b * t30 * t15 + T(231) * t20 * t29 - T(231) * t16 * t28) + (T(1) / T(3003)) * t30 * in.w[0] * t15;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 52 +, 148 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i15_w1_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
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
    const T t16 = t4 * t9 - T(15) * b * t2 - t15 * t10;
    G_ap = t2 * in.w[0] - (T(1) / T(15)) * t3 * in.w[1] * t16;
    G_ab = -(T(1) / T(15)) * t3 * in.w[0] * t16 - (T(1) / T(210)) * (T(28) * t3 * b * t16 + T(15) * t3 * (b * t15 * t10 + t4 * a_minus_b * t9 - T(15) * D * t2) + T(210) * t2 * c) * t3 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r0;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = t21 * t18;
    const T t23 = T(1) / D;
    const T t24 = t19 * t19;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t27 * t27;
    const T t30 = t24 * t18;
    const T t31 = t29 * t26;
    const T t32 = t28 * t28;
    const T t33 = T(231) * b * t21 * t17 + T(4) * a * (T(2) * a * t23 * (T(35) * b * t24 * t17 + T(8) * (T(5) * t25 * a_minus_b * t28 + T(5) * b * t20 * t17 + T(2) * a * t23 * (T(4) * a * t23 * (b * t18 * t17 + t25 * a_minus_b * t26 + T(2) * a * t23 * (t25 * a_minus_b + b * t17)) + T(3) * t25 * a_minus_b * t27 + T(3) * b * t19 * t17)) * a * t23 + T(35) * t25 * a_minus_b * t29) + T(63) * b * t30 * t17 + T(63) * t25 * a_minus_b * t31) * t23 + T(231) * t25 * a_minus_b * t32;
    const T t34 = t32 * t26;
    const T t35 = T(429) * b * t22 * t17 + T(2) * a * t23 * t33 + T(429) * t25 * a_minus_b * t34;
    const T t36 = T(1) / a;
    const T t37 = T(429) * t25 * t34 - t35 * t23 * b - T(429) * t22 * t17;
    G_ap = (T(1) / T(6435)) * t35 * t23 * in.w[0] - (T(1) / T(6435)) * t36 * in.w[1] * t37;
    G_ab = -(T(1) / T(6435)) * t36 * t37 * in.w[0] - (T(1) / T(45045)) * t36 * in.w[1] * (T(7) * t35 * t23 * c + T(14) * t36 * t37 * b - T(15) * t23 * t33);
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 55 +, 161 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
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
    const T t15 = T(15) * t2 * D - t3 * a_minus_b * t8 - t14 * t9 * b;
    const T t16 = T(1) / a;
    F = (T(1) / T(14)) * in.w[0] * t15 * t16 + (T(1) / T(182)) * in.w[1] * t16 * (T(14) * t13 * t9 + T(13) * t15 * t16 * b - T(14) * t3 * t7);
    const T t17 = t14 * t9 + T(15) * t2 * b - t3 * t8;
    G_ap = (T(1) / T(15)) * t17 * in.w[1] * t16 + in.w[0] * t2;
    G_ab = (T(1) / T(15)) * t17 * in.w[0] * t16 + (T(1) / T(210)) * in.w[1] * t16 * (T(15) * t15 * t16 + T(28) * t17 * t16 * b - T(210) * c * t2);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
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
    const T t29 = T(1) / D;
    const T t30 = t26 * t26;
    const T t31 = t30 * t25;
    const T t32 = t21 * t21;
    const T t33 = t32 * t20;
    const T t34 = T(231) * t23 * t19 * b + T(231) * t24 * a_minus_b * t28 + T(4) * t29 * a * (T(63) * t24 * a_minus_b * t31 + T(2) * t29 * a * (T(35) * t24 * a_minus_b * t30 + T(35) * t32 * t19 * b + T(8) * (T(2) * t29 * a * (T(4) * (t20 * t19 * b + T(2) * (t24 * a_minus_b + t19 * b) * t29 * a + t24 * a_minus_b * t25) * t29 * a + T(3) * t24 * a_minus_b * t26 + T(3) * t21 * t19 * b) + T(5) * t24 * a_minus_b * t27 + T(5) * t22 * t19 * b) * t29 * a) + T(63) * t33 * t19 * b);
    F = (T(1) / T(3003)) * in.w[1] * t18 * (T(231) * t23 * t19 + t34 * t29 * b - T(231) * t24 * t28) + (T(1) / T(3003)) * in.w[0] * t34 * t29;
    const T t35 = t23 * t20;
    const T t36 = t28 * t25;
    const T t37 = T(2) * t34 * t29 * a + T(429) * t24 * a_minus_b * t36 + T(429) * t35 * t19 * b;
    const T t38 = T(429) * t35 * t19 + t37 * t29 * b - T(429) * t24 * t36;
    G_ap = (T(1) / T(6435)) * t38 * in.w[1] * t18 + (T(1) / T(6435)) * in.w[0] * t37 * t29;
    G_ab = (T(1) / T(6435)) * t38 * in.w[0] * t18 + (T(1) / T(45045)) * in.w[1] * t18 * (T(14) * t38 * t18 * b + T(15) * t34 * t29 - T(7) * c * t37 * t29);
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 47 +, 124 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w2_f(const SegmentInput<T>& in) {
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
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
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
    const T t14 = t9 * t13 - t4 * t8 - T(13) * t2 * b;
    F = t2 * in.w[0] - (T(1) / T(156)) * t3 * in.w[2] * (T(13) * t3 * (t4 * b * t8 + t9 * a_minus_b * t13 - T(13) * t2 * D) + T(156) * t2 * c + T(24) * t3 * b * t14) - (T(1) / T(13)) * t3 * t14 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t25 = T(1) / D;
    const T t26 = t17 * t16;
    const T t27 = t22 * t21;
    const T t28 = T(63) * t15 * b * t19 + T(63) * t20 * a_minus_b * t24 + T(2) * a * t25 * (T(35) * t15 * b * t18 + T(35) * t20 * a_minus_b * t23 + T(8) * a * (T(5) * t15 * b * t26 + T(2) * a * (T(3) * t15 * b * t17 + T(3) * t20 * a_minus_b * t22 + T(4) * a * (t20 * a_minus_b * t21 + T(2) * a * (t15 * b + t20 * a_minus_b) * t25 + t15 * b * t16) * t25) * t25 + T(5) * t20 * a_minus_b * t27) * t25);
    const T t29 = t26 * t26;
    const T t30 = t27 * t27;
    const T t31 = T(4) * a * t28 * t25 + T(231) * t15 * b * t29 + T(231) * t20 * a_minus_b * t30;
    const T t32 = T(1) / a;
    const T t33 = t31 * b * t25 + T(231) * t15 * t29 - T(231) * t20 * t30;
    F = (T(1) / T(3003)) * t31 * in.w[0] * t25 + (T(1) / T(9009)) * t32 * in.w[2] * (T(6) * t32 * t33 * b + T(13) * t28 * t25 - T(3) * t31 * c * t25) + (T(1) / T(3003)) * t32 * t33 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 58 +, 168 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i15_w2_grad(const SegmentInput<T>& in) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(49) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
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
    const T t15 = T(15) * t2 * b + t3 * t8 - t14 * t9;
    const T t16 = T(1) / a;
    const T t17 = b * t3 * t8 + t14 * t9 * a_minus_b - T(15) * t2 * D;
    const T t18 = T(15) * t17 * t16 + T(210) * t2 * c - T(28) * b * t15 * t16;
    G_ap = t2 * in.w[0] + (T(1) / T(15)) * t15 * in.w[1] * t16 - (T(1) / T(210)) * t18 * in.w[2] * t16;
    G_ab = (T(1) / T(15)) * in.w[0] * t15 * t16 - (T(1) / T(210)) * t18 * in.w[1] * t16 - (T(1) / T(2730)) * (T(182) * t15 * c * t16 + T(26) * t18 * b * t16 + T(15) * (T(13) * b * t17 * t16 + T(14) * t13 * t9 - T(14) * t3 * t7) * t16) * in.w[2] * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = t20 * t20;
    const T t22 = t21 * t20;
    const T t23 = t22 * t22;
    const T t24 = t23 * t20;
    const T t25 = T(1) / r1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t28 * t28;
    const T t30 = t29 * t26;
    const T t31 = t21 * t21;
    const T t32 = t31 * t20;
    const T t33 = t27 * t27;
    const T t34 = t33 * t26;
    const T t35 = T(1) / D;
    const T t36 = T(231) * b * t19 * t23 + T(4) * (T(63) * b * t19 * t32 + T(63) * t34 * t25 * a_minus_b + T(2) * (T(35) * t33 * t25 * a_minus_b + T(35) * b * t19 * t31 + T(8) * (T(2) * t35 * (T(3) * t27 * t25 * a_minus_b + T(3) * b * t19 * t21 + T(4) * (T(2) * (b * t19 + t25 * a_minus_b) * t35 * a + t26 * t25 * a_minus_b + b * t19 * t20) * t35 * a) * a + T(5) * b * t19 * t22 + T(5) * t28 * t25 * a_minus_b) * t35 * a) * t35 * a) * t35 * a + T(231) * t29 * t25 * a_minus_b;
    const T t37 = T(429) * b * t19 * t24 + T(429) * t30 * t25 * a_minus_b + T(2) * t36 * t35 * a;
    const T t38 = T(429) * t19 * t24 + b * t37 * t35 - T(429) * t30 * t25;
    const T t39 = T(1) / a;
    const T t40 = T(15) * t36 * t35 + T(14) * t38 * b * t39 - T(7) * t37 * c * t35;
    G_ap = (T(1) / T(6435)) * in.w[0] * t37 * t35 + (T(1) / T(6435)) * t38 * in.w[1] * t39 + (T(1) / T(45045)) * t40 * in.w[2] * t39;
    G_ab = (T(1) / T(45045)) * (T(2) * t40 * b * t39 + T(15) * (b * t36 * t35 + T(231) * t19 * t23 - T(231) * t29 * t25) * t39 - T(7) * t38 * c * t39) * in.w[2] * t39 + (T(1) / T(6435)) * t38 * in.w[0] * t39 + (T(1) / T(45045)) * t40 * in.w[1] * t39;
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 62 +, 186 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = T(1) / a;
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
    const T t15 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
    const T t16 = a_minus_b * t3 * t8 + t9 * b * t14 - T(15) * D * t15;
    const T t17 = T(14) * t3 * t7 + T(13) * t2 * b * t16 - T(14) * t9 * t13;
    F = -(T(1) / T(14)) * t2 * in.w[0] * t16 - (T(1) / T(2184)) * (T(24) * t17 * t2 * b + T(13) * t2 * (T(14) * a_minus_b * t3 * t7 + T(13) * D * t2 * t16 + T(14) * t9 * b * t13) - T(156) * t2 * t16 * c) * t2 * in.w[2] - (T(1) / T(182)) * in.w[1] * t17 * t2;
    const T t18 = T(15) * t15 * b + t9 * t14 - t3 * t8;
    const T t19 = T(15) * t2 * t16 + T(210) * t15 * c - T(28) * t2 * t18 * b;
    G_ap = t15 * in.w[0] + (T(1) / T(15)) * in.w[1] * t2 * t18 - (T(1) / T(210)) * t2 * in.w[2] * t19;
    G_ab = (T(1) / T(15)) * t2 * t18 * in.w[0] - (T(1) / T(210)) * in.w[1] * t2 * t19 - (T(1) / T(2730)) * t2 * in.w[2] * (T(182) * t2 * t18 * c + T(26) * t2 * b * t19 + T(15) * t17 * t2);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / D;
    const T t21 = T(1) / r1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = T(1) / r0;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = t27 * t26;
    const T t29 = t23 * t23;
    const T t30 = t27 * t27;
    const T t31 = t29 * t22;
    const T t32 = t30 * t26;
    const T t33 = T(2) * t20 * a * (T(8) * t20 * a * (T(5) * a_minus_b * t21 * t24 + T(5) * t25 * b * t28 + T(2) * t20 * a * (T(3) * a_minus_b * t21 * t23 + T(4) * t20 * a * (t25 * b * t26 + a_minus_b * t21 * t22 + T(2) * t20 * a * (t25 * b + a_minus_b * t21)) + T(3) * t25 * b * t27)) + T(35) * a_minus_b * t21 * t29 + T(35) * t25 * b * t30) + T(63) * a_minus_b * t21 * t31 + T(63) * t25 * b * t32;
    const T t34 = t24 * t24;
    const T t35 = t28 * t28;
    const T t36 = T(4) * t20 * a * t33 + T(231) * a_minus_b * t21 * t34 + T(231) * t25 * b * t35;
    const T t37 = T(231) * t21 * t34 - t20 * t36 * b - T(231) * t25 * t35;
    const T t38 = T(1) / a;
    F = (T(1) / T(3003)) * t20 * t36 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t37 * t38 - (T(1) / T(9009)) * t38 * in.w[2] * (T(3) * t20 * t36 * c + T(6) * t37 * t38 * b - T(13) * t20 * t33);
    const T t39 = t35 * t26;
    const T t40 = t34 * t22;
    const T t41 = T(2) * t20 * t36 * a + T(429) * a_minus_b * t21 * t40 + T(429) * t25 * b * t39;
    const T t42 = T(429) * t25 * t39 + t20 * b * t41 - T(429) * t21 * t40;
    const T t43 = T(15) * t20 * t36 + T(14) * t38 * t42 * b - T(7) * t20 * t41 * c;
    G_ap = (T(1) / T(45045)) * t38 * in.w[2] * t43 + (T(1) / T(6435)) * t20 * in.w[0] * t41 + (T(1) / T(6435)) * in.w[1] * t38 * t42;
    G_ab = (T(1) / T(6435)) * t38 * t42 * in.w[0] + (T(1) / T(45045)) * in.w[1] * t38 * t43 - (T(1) / T(45045)) * t38 * in.w[2] * (T(7) * t38 * t42 * c + T(15) * t37 * t38 - T(2) * t38 * t43 * b);
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 52 +, 141 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w3_f(const SegmentInput<T>& in) {
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
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(11) / T(25)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.44 a min(q(0), q(1)): recurrence (1) downwards from J_15 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = J_downward<T>(T(15), a, D, -b, c, a_minus_b, q1);
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t3 * t7 + T(13) * t8 * b - t9 * t13;
    const T t15 = t9 * a_minus_b * t13 + t3 * b * t7 - T(13) * t8 * D;
    const T t16 = T(156) * t8 * c + T(13) * t2 * t15 - T(24) * t2 * b * t14;
    const T t17 = t5 * t5;
    const T t18 = t17 * t4;
    const T t19 = t11 * t11;
    const T t20 = t19 * t10;
    F = (T(1) / T(13)) * t2 * t14 * in.w[1] + t8 * in.w[0] - (T(1) / T(156)) * in.w[2] * t2 * t16 - (T(1) / T(1716)) * t2 * in.w[3] * (T(132) * t2 * t14 * c + T(22) * t2 * b * t16 - T(13) * t2 * (T(12) * t3 * t18 - T(11) * t2 * b * t15 - T(12) * t9 * t20));
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t24;
    const T t26 = t24 * t23;
    const T t27 = T(1) / r0;
    const T t28 = t27 * t27;
    const T t29 = T(1) / D;
    const T t30 = t28 * t28;
    const T t31 = t30 * t28;
    const T t32 = t30 * t30;
    const T t33 = t25 * t23;
    const T t34 = t32 * t28;
    const T t35 = T(2) * a * (T(35) * t22 * a_minus_b * t25 + T(8) * a * (T(5) * t22 * a_minus_b * t26 + T(2) * a * (T(3) * t22 * a_minus_b * t24 + T(4) * a * (t27 * b * t28 + T(2) * a * t29 * (t22 * a_minus_b + t27 * b) + t22 * a_minus_b * t23) * t29 + T(3) * t27 * b * t30) * t29 + T(5) * t27 * b * t31) * t29 + T(35) * t27 * b * t32) * t29 + T(63) * t22 * a_minus_b * t33 + T(63) * t27 * b * t34;
    const T t36 = t26 * t26;
    const T t37 = t31 * t31;
    const T t38 = T(231) * t22 * a_minus_b * t36 + T(231) * t27 * b * t37 + T(4) * a * t35 * t29;
    const T t39 = t38 * b * t29 + T(231) * t27 * t37 - T(231) * t22 * t36;
    const T t40 = T(13) * t35 * t29 + T(6) * t21 * b * t39 - T(3) * t38 * c * t29;
    F = (T(1) / T(9009)) * in.w[2] * t21 * t40 + (T(1) / T(3003)) * t21 * t39 * in.w[1] + (T(1) / T(3003)) * t38 * in.w[0] * t29 - (T(1) / T(9009)) * t21 * (T(3) * t21 * t39 * c - T(13) * t21 * (b * t35 * t29 + T(63) * t27 * t34 - T(63) * t22 * t33) - T(2) * t21 * b * t40) * in.w[3];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 64 +, 189 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i15_w3_grad(const SegmentInput<T>& in) {
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
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(49) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
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
    const T t16 = T(15) * b * t2 + t4 * t9 - t15 * t10;
    const T t17 = b * t4 * t9 + t15 * t10 * a_minus_b - T(15) * t2 * D;
    const T t18 = T(15) * t3 * t17 + T(210) * t2 * c - T(28) * t3 * b * t16;
    const T t19 = T(14) * t14 * t10 + T(13) * t3 * t17 * b - T(14) * t4 * t8;
    const T t20 = T(26) * t3 * b * t18 + T(182) * t3 * t16 * c + T(15) * t3 * t19;
    G_ap = in.w[0] * t2 + (T(1) / T(15)) * t3 * in.w[1] * t16 - (T(1) / T(2730)) * t3 * in.w[3] * t20 - (T(1) / T(210)) * t3 * t18 * in.w[2];
    G_ab = (T(1) / T(15)) * t3 * in.w[0] * t16 - (T(1) / T(10920)) * t3 * in.w[3] * (T(8) * t3 * b * t20 - T(5) * t3 * (T(156) * t3 * t17 * c - T(24) * t3 * b * t19 - T(13) * t3 * (T(14) * b * t4 * t8 + T(13) * t3 * t17 * D + T(14) * t14 * t10 * a_minus_b)) - T(52) * t3 * c * t18) - (T(1) / T(2730)) * t3 * t20 * in.w[2] - (T(1) / T(210)) * t3 * in.w[1] * t18;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = T(1) / a;
    const T t22 = T(1) / r1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * t23;
    const T t26 = t25 * t25;
    const T t27 = t26 * t23;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t29;
    const T t32 = t31 * t31;
    const T t33 = t32 * t29;
    const T t34 = T(1) / D;
    const T t35 = t30 * t30;
    const T t36 = t24 * t24;
    const T t37 = t36 * t23;
    const T t38 = t35 * t29;
    const T t39 = T(2) * a * (T(8) * a * (T(2) * (T(3) * t24 * t22 * a_minus_b + T(3) * b * t28 * t30 + T(4) * a * (b * t28 * t29 + T(2) * a * (t22 * a_minus_b + b * t28) * t34 + t23 * t22 * a_minus_b) * t34) * a * t34 + T(5) * b * t28 * t31 + T(5) * t25 * t22 * a_minus_b) * t34 + T(35) * b * t28 * t35 + T(35) * t36 * t22 * a_minus_b) * t34 + T(63) * t37 * t22 * a_minus_b + T(63) * b * t28 * t38;
    const T t40 = T(231) * b * t28 * t32 + T(4) * a * t39 * t34 + T(231) * t26 * t22 * a_minus_b;
    const T t41 = T(429) * b * t28 * t33 + T(429) * t27 * t22 * a_minus_b + T(2) * a * t40 * t34;
    const T t42 = T(429) * t27 * t22 - T(429) * t28 * t33 - b * t41 * t34;
    const T t43 = T(231) * t26 * t22 - b * t40 * t34 - T(231) * t28 * t32;
    const T t44 = T(7) * c * t41 * t34 + T(14) * t21 * b * t42 - T(15) * t40 * t34;
    const T t45 = T(7) * t21 * t42 * c - T(15) * t21 * t43 - T(2) * t21 * b * t44;
    G_ap = (T(1) / T(45045)) * t21 * in.w[3] * t45 + (T(1) / T(6435)) * in.w[0] * t41 * t34 - (T(1) / T(6435)) * t21 * t42 * in.w[1] - (T(1) / T(45045)) * t21 * t44 * in.w[2];
    G_ab = (T(1) / T(45045)) * t21 * in.w[3] * (T(5) * t21 * (T(13) * t39 * t34 - T(6) * t21 * b * t43 - T(3) * c * t40 * t34) + T(2) * t21 * b * t45 + t21 * t44 * c) + (T(1) / T(45045)) * t21 * t45 * in.w[2] - (T(1) / T(45045)) * t21 * in.w[1] * t44 - (T(1) / T(6435)) * t21 * in.w[0] * t42;
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 71 +, 216 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i15_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(49) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.49 a min(q(0), q(1)): recurrence (1) downwards from J_17 = J_downward(…)
    const T t2 = J_downward<T>(T(17), a, D, -b, c, a_minus_b, q1);
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
    const T t15 = T(15) * t2 * D - t8 * t3 * b - a_minus_b * t14 * t9;
    const T t16 = T(1) / a;
    const T t17 = T(14) * t7 * t3 + T(13) * t15 * t16 * b - T(14) * t13 * t9;
    const T t18 = T(13) * t15 * t16 * D - T(14) * t7 * t3 * b - T(14) * a_minus_b * t13 * t9;
    const T t19 = T(24) * t17 * t16 * b + T(13) * t16 * t18 - T(156) * t15 * c * t16;
    const T t20 = t11 * t11;
    const T t21 = t20 * t10;
    const T t22 = t5 * t5;
    const T t23 = t22 * t4;
    F = (T(1) / T(14)) * t15 * t16 * in.w[0] + (T(1) / T(182)) * in.w[1] * t17 * t16 + (T(1) / T(2184)) * t19 * in.w[2] * t16 - (T(1) / T(24024)) * t16 * in.w[3] * (T(132) * t17 * c * t16 + T(13) * (T(168) * t21 * t9 - T(168) * t23 * t3 - T(11) * t16 * t18 * b) * t16 - T(22) * t19 * t16 * b);
    const T t24 = t14 * t9 - t8 * t3 - T(15) * t2 * b;
    const T t25 = T(210) * c * t2 + T(28) * t16 * b * t24 - T(15) * t15 * t16;
    const T t26 = T(15) * t17 * t16 + T(182) * c * t16 * t24 - T(26) * t25 * t16 * b;
    G_ap = t2 * in.w[0] + (T(1) / T(2730)) * t26 * t16 * in.w[3] - (T(1) / T(210)) * t25 * in.w[2] * t16 - (T(1) / T(15)) * in.w[1] * t16 * t24;
    G_ab = (T(1) / T(2730)) * in.w[2] * t26 * t16 + (T(1) / T(10920)) * (T(5) * t19 * t16 + T(8) * t26 * t16 * b + T(52) * t25 * c * t16) * t16 * in.w[3] - (T(1) / T(15)) * t16 * in.w[0] * t24 - (T(1) / T(210)) * in.w[1] * t25 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = T(1) / a;
    const T t28 = T(1) / r0;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t31 * t29;
    const T t33 = T(1) / r1;
    const T t34 = t33 * t33;
    const T t35 = t34 * t34;
    const T t36 = t35 * t34;
    const T t37 = T(1) / D;
    const T t38 = t30 * t29;
    const T t39 = t35 * t35;
    const T t40 = t39 * t34;
    const T t41 = T(63) * t32 * t28 * b + T(2) * (T(8) * (T(5) * a_minus_b * t36 * t33 + T(2) * (T(3) * t30 * t28 * b + T(3) * a_minus_b * t35 * t33 + T(4) * (T(2) * a * t37 * (a_minus_b * t33 + t28 * b) + t29 * t28 * b + a_minus_b * t34 * t33) * a * t37) * a * t37 + T(5) * t38 * t28 * b) * a * t37 + T(35) * t31 * t28 * b + T(35) * a_minus_b * t39 * t33) * a * t37 + T(63) * a_minus_b * t40 * t33;
    const T t42 = t38 * t38;
    const T t43 = t36 * t36;
    const T t44 = T(4) * t41 * a * t37 + T(231) * t42 * t28 * b + T(231) * a_minus_b * t43 * t33;
    const T t45 = T(231) * t42 * t28 + t37 * t44 * b - T(231) * t43 * t33;
    const T t46 = T(13) * t41 * t37 + T(6) * t45 * t27 * b - T(3) * c * t37 * t44;
    F = (T(1) / T(9009)) * in.w[2] * t27 * t46 + (T(1) / T(3003)) * t37 * in.w[0] * t44 + (T(1) / T(3003)) * t45 * in.w[1] * t27 - (T(1) / T(9009)) * (T(13) * (T(63) * t40 * t33 - T(63) * t32 * t28 - t41 * t37 * b) * t27 + T(3) * t45 * c * t27 - T(2) * t27 * t46 * b) * t27 * in.w[3];
    const T t47 = t43 * t34;
    const T t48 = t42 * t29;
    const T t49 = T(429) * t48 * t28 * b + T(429) * a_minus_b * t47 * t33 + T(2) * a * t37 * t44;
    const T t50 = T(429) * t47 * t33 - T(429) * t48 * t28 - t49 * t37 * b;
    const T t51 = T(15) * t37 * t44 - T(14) * t27 * t50 * b - T(7) * t49 * c * t37;
    const T t52 = T(2) * t51 * t27 * b + T(15) * t45 * t27 + T(7) * c * t27 * t50;
    G_ap = (T(1) / T(45045)) * in.w[2] * t51 * t27 + (T(1) / T(45045)) * t52 * t27 * in.w[3] + (T(1) / T(6435)) * t49 * t37 * in.w[0] - (T(1) / T(6435)) * in.w[1] * t27 * t50;
    G_ab = (T(1) / T(45045)) * t52 * in.w[2] * t27 + (T(1) / T(45045)) * in.w[1] * t51 * t27 - (T(1) / T(6435)) * t27 * in.w[0] * t50 - (T(1) / T(45045)) * (c * t51 * t27 - T(2) * t52 * t27 * b - T(5) * t27 * t46) * t27 * in.w[3];
  }
  const T g_factor = -T(15) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 45 +, 100 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w0_f(const SegmentInput<T>& in) {
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    F = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = T(1) / D;
    const T t16 = t10 * t10;
    const T t17 = t16 * t9;
    const T t18 = t12 * t9;
    F = (T(1) / T(215040)) * (T(15360) * a_minus_b * t8 + T(13) * (T(1280) * a_minus_b * t7 + T(1280) * b * t12 + T(11) * (T(128) * a_minus_b * t14 + T(3) * (T(48) * a_minus_b * t13 + T(7) * (T(5) * (T(2) * a_minus_b * t5 + T(3) * t15 * (b * t9 + a_minus_b * t4 + J2 * a) * a + T(2) * b * t10) * t15 * a + T(8) * a_minus_b * t6 + T(8) * b * t11) * t15 * a + T(48) * b * t16) * t15 * a + T(128) * b * t17) * t15 * a) * t15 * a + T(15360) * b * t18) * t15 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 52 +, 125 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i16_w0_grad(const SegmentInput<T>& in) {
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(51) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    G_ap = t2 * in.w[0];
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    G_ab = (T(1) / T(16)) * t3 * (T(16) * t2 * b + t7 - t11) * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / D;
    const T t15 = T(1) / c;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t16 * t15;
    const T t20 = t19 * t19;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t21;
    const T t24 = t23 * t23;
    const T t25 = t22 * t22;
    const T t26 = t25 * t21;
    const T t27 = t17 * t15;
    const T t28 = t20 * t15;
    const T t29 = t24 * t21;
    const T t30 = t25 * t25;
    const T t31 = T(14336) * b * t18 + t14 * a * (T(13) * (T(1280) * b * t20 + T(1280) * a_minus_b * t24 + T(11) * t14 * a * (T(128) * a_minus_b * t26 + T(128) * b * t27 + T(3) * t14 * a * (T(48) * a_minus_b * t25 + T(48) * b * t17 + T(7) * t14 * a * (T(8) * b * t19 + T(8) * a_minus_b * t23 + T(5) * t14 * a * (T(2) * a_minus_b * t22 + T(3) * t14 * a * (b * t15 + a_minus_b * t21 + a * J2) + T(2) * b * t16))))) * t14 * a + T(15360) * b * t28 + T(15360) * a_minus_b * t29) + T(14336) * a_minus_b * t30;
    G_ap = (T(1) / T(229376)) * t14 * in.w[0] * t31;
    const T t32 = T(1) / a;
    G_ab = (T(1) / T(229376)) * t32 * in.w[0] * (t14 * t31 * b + T(14336) * t18 - T(14336) * t30);
  }
  const T g_factor = -T(16) * in.s * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 52 +, 129 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(51) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    F = (T(1) / T(15)) * t2 * in.w[0] * (T(16) * t3 * D - t7 * a_minus_b - t11 * b);
    G_ap = t3 * in.w[0];
    G_ab = -(T(1) / T(16)) * (t7 - t11 - T(16) * t3 * b) * t2 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / c;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14;
    const T t17 = t16 * t16;
    const T t18 = t17 * t14;
    const T t19 = T(1) / D;
    const T t20 = T(1) / q1;
    const T t21 = t20 * t20;
    const T t22 = t21 * t21;
    const T t23 = t22 * t20;
    const T t24 = t15 * t15;
    const T t25 = t24 * t14;
    const T t26 = t21 * t20;
    const T t27 = t26 * t26;
    const T t28 = t27 * t20;
    const T t29 = T(15360) * t18 * b + T(13) * a * t19 * (T(11) * a * t19 * (T(128) * t23 * a_minus_b + T(128) * t25 * b + T(3) * a * (T(7) * a * t19 * (T(8) * t16 * b + T(8) * t26 * a_minus_b + T(5) * a * t19 * (T(2) * t21 * a_minus_b + T(2) * t15 * b + T(3) * a * t19 * (t20 * a_minus_b + J2 * a + t14 * b))) + T(48) * t22 * a_minus_b + T(48) * t24 * b) * t19) + T(1280) * t27 * a_minus_b + T(1280) * t17 * b) + T(15360) * t28 * a_minus_b;
    F = (T(1) / T(215040)) * t29 * t19 * in.w[0];
    const T t30 = t22 * t22;
    const T t31 = t24 * t24;
    const T t32 = t29 * a * t19 + T(14336) * t30 * a_minus_b + T(14336) * t31 * b;
    G_ap = (T(1) / T(229376)) * t32 * t19 * in.w[0];
    const T t33 = T(1) / a;
    G_ab = (T(1) / T(229376)) * (t32 * t19 * b + T(14336) * t31 - T(14336) * t30) * t33 * in.w[0];
  }
  const T g_factor = -T(16) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 48 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w1_f(const SegmentInput<T>& in) {
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
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    F = t2 * in.w[0] - (T(1) / T(14)) * t3 * in.w[1] * (t8 - T(14) * t2 * b - t13);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t17;
    const T t20 = t19 * t19;
    const T t21 = t20 * t17;
    const T t22 = t18 * t18;
    const T t23 = t22 * t17;
    const T t24 = T(1) / c;
    const T t25 = t24 * t24;
    const T t26 = t25 * t24;
    const T t27 = t25 * t25;
    const T t28 = t27 * t24;
    const T t29 = t26 * t26;
    const T t30 = t29 * t24;
    const T t31 = T(15360) * t21 * a_minus_b + T(13) * t16 * a * (T(11) * t16 * a * (T(128) * t23 * a_minus_b + T(3) * t16 * a * (T(48) * t22 * a_minus_b + T(7) * t16 * a * (T(5) * t16 * a * (T(3) * t16 * a * (a * J2 + b * t24 + t17 * a_minus_b) + T(2) * t18 * a_minus_b + T(2) * b * t25) + T(8) * b * t26 + T(8) * t19 * a_minus_b) + T(48) * b * t27) + T(128) * b * t28) + T(1280) * t20 * a_minus_b + T(1280) * b * t29) + T(15360) * b * t30;
    const T t32 = T(1) / a;
    F = (T(1) / T(215040)) * t16 * t31 * in.w[0] - (T(1) / T(215040)) * (T(15360) * t21 - T(15360) * t30 - t16 * t31 * b) * t32 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 56 +, 139 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i16_w1_grad(const SegmentInput<T>& in) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(51) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(16) * t3 * b + t7 - t11;
    G_ap = (T(1) / T(16)) * in.w[1] * t2 * t12 + t3 * in.w[0];
    G_ab = (T(1) / T(16)) * t2 * t12 * in.w[0] + (T(1) / T(120)) * in.w[1] * t2 * (T(15) * t2 * t12 * b - T(8) * t2 * (t11 * a_minus_b + b * t7 - T(16) * t3 * D) - T(120) * t3 * c);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = atan2(t13, c_minus_b) * t14;
    const T t15 = T(1) / q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t17 * t17;
    const T t19 = t16 * t15;
    const T t20 = t19 * t19;
    const T t21 = t20 * t15;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = t17 * t15;
    const T t28 = t23 * t23;
    const T t29 = t28 * t22;
    const T t30 = T(1) / D;
    const T t31 = T(15360) * t21 * a_minus_b + T(15360) * b * t26 + T(13) * a * (T(11) * a * (T(128) * t27 * a_minus_b + T(128) * b * t29 + T(3) * a * (T(48) * t17 * a_minus_b + T(48) * b * t28 + T(7) * a * (T(8) * b * t24 + T(5) * a * (T(2) * b * t23 + T(3) * a * (a * J2 + t15 * a_minus_b + b * t22) * t30 + T(2) * t16 * a_minus_b) * t30 + T(8) * t19 * a_minus_b) * t30) * t30) * t30 + T(1280) * b * t25 + T(1280) * t20 * a_minus_b) * t30;
    const T t32 = t28 * t28;
    const T t33 = T(14336) * t18 * a_minus_b + a * t31 * t30 + T(14336) * b * t32;
    const T t34 = T(1) / a;
    const T t35 = T(14336) * t18 - t33 * b * t30 - T(14336) * t32;
    G_ap = (T(1) / T(229376)) * t33 * in.w[0] * t30 - (T(1) / T(229376)) * in.w[1] * t34 * t35;
    G_ab = -(T(1) / T(3440640)) * in.w[1] * t34 * (T(30) * t34 * t35 * b + T(15) * t33 * c * t30 - T(16) * t31 * t30) - (T(1) / T(229376)) * t34 * t35 * in.w[0];
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 59 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(51) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / c;
    const T t3 = t2 * t2;
    const T t4 = t3 * t2;
    const T t5 = t4 * t4;
    const T t6 = t5 * t2;
    const T t7 = T(1) / a;
    const T t8 = t3 * t3;
    const T t9 = t8 * t8;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t15 = t9 * b + a_minus_b * t13 - T(16) * t14 * D;
    const T t16 = t11 * t10;
    const T t17 = t16 * t16;
    const T t18 = t17 * t10;
    F = (T(1) / T(210)) * (T(15) * t6 - T(14) * t7 * t15 * b - T(15) * t18) * in.w[1] * t7 - (T(1) / T(15)) * in.w[0] * t7 * t15;
    const T t19 = t13 - t9 - T(16) * t14 * b;
    G_ap = t14 * in.w[0] - (T(1) / T(16)) * t19 * in.w[1] * t7;
    G_ab = -(T(1) / T(16)) * t19 * in.w[0] * t7 - (T(1) / T(120)) * in.w[1] * t7 * (T(120) * t14 * c + T(15) * t19 * t7 * b + T(8) * t7 * t15);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = sqrt(D);
    const T t21 = T(1) / t20;
    const T J2 = t21 * atan2(t20, c_minus_b);
    const T t22 = T(1) / q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t25 * t22;
    const T t27 = T(1) / D;
    const T t28 = T(1) / c;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t30 * t30;
    const T t32 = t29 * t29;
    const T t33 = t32 * t28;
    const T t34 = t23 * t23;
    const T t35 = t34 * t22;
    const T t36 = t31 * t28;
    const T t37 = T(15360) * a_minus_b * t26 + T(13) * t27 * a * (T(1280) * a_minus_b * t25 + T(1280) * t31 * b + T(11) * (T(128) * t33 * b + T(128) * a_minus_b * t35 + T(3) * t27 * a * (T(48) * t32 * b + T(48) * a_minus_b * t34 + T(7) * t27 * a * (T(5) * t27 * (T(2) * a_minus_b * t23 + T(3) * t27 * a * (t28 * b + J2 * a + a_minus_b * t22) + T(2) * t29 * b) * a + T(8) * a_minus_b * t24 + T(8) * t30 * b))) * t27 * a) + T(15360) * t36 * b;
    const T t38 = T(1) / a;
    F = (T(1) / T(215040)) * in.w[0] * t37 * t27 + (T(1) / T(215040)) * in.w[1] * t38 * (T(15360) * t36 + t37 * t27 * b - T(15360) * t26);
    const T t39 = t32 * t32;
    const T t40 = t34 * t34;
    const T t41 = T(14336) * t39 * b + T(14336) * a_minus_b * t40 + t37 * t27 * a;
    const T t42 = t27 * t41 * b + T(14336) * t39 - T(14336) * t40;
    G_ap = (T(1) / T(229376)) * in.w[0] * t27 * t41 + (T(1) / T(229376)) * in.w[1] * t38 * t42;
    G_ab = (T(1) / T(3440640)) * (T(16) * t37 * t27 + T(30) * t38 * b * t42 - T(15) * c * t27 * t41) * in.w[1] * t38 + (T(1) / T(229376)) * in.w[0] * t38 * t42;
  }
  const T g_factor = -T(16) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 51 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w2_f(const SegmentInput<T>& in) {
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = t13 + T(14) * t3 * b - t8;
    F = (T(1) / T(91)) * (T(7) * t2 * (T(14) * t3 * D - a_minus_b * t8 - t13 * b) + T(13) * t2 * t14 * b - T(91) * c * t3) * t2 * in.w[2] + t3 * in.w[0] + (T(1) / T(14)) * in.w[1] * t2 * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = t16 * atan2(t15, c_minus_b);
    const T t17 = T(1) / D;
    const T t18 = T(1) / q1;
    const T t19 = t18 * t18;
    const T t20 = t19 * t18;
    const T t21 = t20 * t20;
    const T t22 = T(1) / c;
    const T t23 = t22 * t22;
    const T t24 = t23 * t22;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t26 * t22;
    const T t28 = t19 * t19;
    const T t29 = t28 * t18;
    const T t30 = T(1280) * a_minus_b * t21 + T(1280) * t25 * b + T(11) * (T(128) * t27 * b + T(3) * t17 * a * (T(7) * t17 * a * (T(8) * t24 * b + T(8) * a_minus_b * t20 + T(5) * t17 * a * (T(2) * t23 * b + T(2) * a_minus_b * t19 + T(3) * (J2 * a + a_minus_b * t18 + t22 * b) * t17 * a)) + T(48) * t26 * b + T(48) * a_minus_b * t28) + T(128) * a_minus_b * t29) * t17 * a;
    const T t31 = t25 * t22;
    const T t32 = t21 * t18;
    const T t33 = T(15360) * a_minus_b * t32 + T(13) * t17 * a * t30 + T(15360) * t31 * b;
    const T t34 = T(15360) * t31 + t33 * t17 * b - T(15360) * t32;
    const T t35 = T(1) / a;
    F = (T(1) / T(215040)) * (T(14) * t17 * t30 + T(2) * t34 * t35 * b - c * t33 * t17) * t35 * in.w[2] + (T(1) / T(215040)) * t33 * t17 * in.w[0] + (T(1) / T(215040)) * t34 * in.w[1] * t35;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 62 +, 157 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i16_w2_grad(const SegmentInput<T>& in) {
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
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(51) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 - T(16) * b * t2 - t11;
    const T t13 = b * t11 + t7 * a_minus_b - T(16) * D * t2;
    const T t14 = T(120) * t2 * c + T(8) * t3 * t13 + T(15) * t3 * b * t12;
    G_ap = in.w[0] * t2 - (T(1) / T(16)) * t3 * in.w[1] * t12 - (T(1) / T(120)) * in.w[2] * t3 * t14;
    const T t15 = t9 * t8;
    const T t16 = t15 * t15;
    const T t17 = t16 * t8;
    const T t18 = t5 * t4;
    const T t19 = t18 * t18;
    const T t20 = t19 * t4;
    G_ab = (T(1) / T(1680)) * in.w[2] * t3 * (T(8) * t3 * (T(15) * t17 - T(14) * t3 * b * t13 - T(15) * t20) + T(105) * t3 * c * t12 - T(28) * t3 * t14 * b) - (T(1) / T(120)) * t3 * t14 * in.w[1] - (T(1) / T(16)) * t3 * in.w[0] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t21 = sqrt(D);
    const T t22 = T(1) / t21;
    const T J2 = t22 * atan2(t21, c_minus_b);
    const T t23 = T(1) / D;
    const T t24 = T(1) / c;
    const T t25 = t24 * t24;
    const T t26 = t25 * t25;
    const T t27 = t26 * t26;
    const T t28 = T(1) / q1;
    const T t29 = t28 * t28;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t30 * t28;
    const T t33 = t25 * t24;
    const T t34 = t29 * t28;
    const T t35 = t26 * t24;
    const T t36 = t34 * t34;
    const T t37 = t33 * t33;
    const T t38 = t36 * t28;
    const T t39 = t37 * t24;
    const T t40 = T(13) * t23 * a * (T(11) * t23 * a * (T(128) * t32 * a_minus_b + T(3) * t23 * a * (T(48) * t30 * a_minus_b + T(7) * t23 * a * (T(5) * t23 * a * (T(3) * t23 * (b * t24 + t28 * a_minus_b + a * J2) * a + T(2) * t29 * a_minus_b + T(2) * b * t25) + T(8) * b * t33 + T(8) * t34 * a_minus_b) + T(48) * b * t26) + T(128) * b * t35) + T(1280) * t36 * a_minus_b + T(1280) * b * t37) + T(15360) * t38 * a_minus_b + T(15360) * b * t39;
    const T t41 = T(14336) * b * t27 + T(14336) * t31 * a_minus_b + t40 * t23 * a;
    const T t42 = T(1) / a;
    const T t43 = T(14336) * t31 - T(14336) * t27 - t23 * b * t41;
    const T t44 = T(30) * t42 * t43 * b + T(15) * t23 * t41 * c - T(16) * t40 * t23;
    G_ap = (T(1) / T(229376)) * t23 * in.w[0] * t41 - (T(1) / T(3440640)) * in.w[2] * t42 * t44 - (T(1) / T(229376)) * t42 * t43 * in.w[1];
    G_ab = (T(1) / T(3440640)) * in.w[2] * t42 * (T(16) * t42 * (t40 * t23 * b + T(15360) * t39 - T(15360) * t38) + T(15) * t42 * t43 * c - T(2) * t42 * b * t44) - (T(1) / T(3440640)) * t42 * t44 * in.w[1] - (T(1) / T(229376)) * t42 * t43 * in.w[0];
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 66 +, 174 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(51) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t12 = a_minus_b * t6 + b * t10 - T(16) * t11 * D;
    const T t13 = t4 * t3;
    const T t14 = t13 * t13;
    const T t15 = t14 * t3;
    const T t16 = t8 * t7;
    const T t17 = t16 * t16;
    const T t18 = t17 * t7;
    const T t19 = T(14) * b * t2 * t12 + T(15) * t15 - T(15) * t18;
    F = -(T(1) / T(1365)) * t2 * in.w[2] * (T(13) * b * t19 * t2 + T(7) * t2 * (T(14) * D * t2 * t12 + T(15) * a_minus_b * t15 + T(15) * b * t18) - T(91) * c * t2 * t12) - (T(1) / T(210)) * t19 * in.w[1] * t2 - (T(1) / T(15)) * in.w[0] * t2 * t12;
    const T t20 = t6 - t10 - T(16) * b * t11;
    const T t21 = T(8) * t2 * t12 + T(15) * b * t20 * t2 + T(120) * c * t11;
    G_ap = in.w[0] * t11 - (T(1) / T(120)) * t21 * t2 * in.w[2] - (T(1) / T(16)) * t20 * in.w[1] * t2;
    G_ab = -(T(1) / T(1680)) * (T(8) * t19 * t2 + T(28) * b * t21 * t2 - T(105) * c * t20 * t2) * t2 * in.w[2] - (T(1) / T(16)) * in.w[0] * t20 * t2 - (T(1) / T(120)) * t21 * in.w[1] * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = sqrt(D);
    const T t23 = T(1) / t22;
    const T J2 = atan2(t22, c_minus_b) * t23;
    const T t24 = T(1) / D;
    const T t25 = T(1) / q1;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = T(1) / c;
    const T t29 = t28 * t28;
    const T t30 = t29 * t28;
    const T t31 = t29 * t29;
    const T t32 = t26 * t26;
    const T t33 = t31 * t28;
    const T t34 = t32 * t25;
    const T t35 = t27 * t27;
    const T t36 = t30 * t30;
    const T t37 = T(11) * t24 * (T(3) * (T(7) * (T(8) * a_minus_b * t27 + T(8) * b * t30 + T(5) * (T(3) * (a_minus_b * t25 + b * t28 + J2 * a) * t24 * a + T(2) * b * t29 + T(2) * a_minus_b * t26) * t24 * a) * t24 * a + T(48) * b * t31 + T(48) * a_minus_b * t32) * t24 * a + T(128) * b * t33 + T(128) * a_minus_b * t34) * a + T(1280) * a_minus_b * t35 + T(1280) * b * t36;
    const T t38 = t35 * t25;
    const T t39 = t36 * t28;
    const T t40 = T(13) * t24 * a * t37 + T(15360) * a_minus_b * t38 + T(15360) * b * t39;
    const T t41 = b * t24 * t40 + T(15360) * t39 - T(15360) * t38;
    const T t42 = T(1) / a;
    F = (T(1) / T(215040)) * in.w[1] * t41 * t42 + (T(1) / T(215040)) * in.w[0] * t24 * t40 - (T(1) / T(215040)) * (c * t24 * t40 - T(2) * b * t41 * t42 - T(14) * t24 * t37) * t42 * in.w[2];
    const T t43 = t32 * t32;
    const T t44 = t31 * t31;
    const T t45 = T(14336) * a_minus_b * t43 + t24 * a * t40 + T(14336) * b * t44;
    const T t46 = T(14336) * t43 - T(14336) * t44 - b * t45 * t24;
    const T t47 = T(16) * t24 * t40 - T(30) * b * t42 * t46 - T(15) * t45 * c * t24;
    G_ap = (T(1) / T(3440640)) * t42 * in.w[2] * t47 + (T(1) / T(229376)) * t45 * in.w[0] * t24 - (T(1) / T(229376)) * in.w[1] * t42 * t46;
    G_ab = (T(1) / T(3440640)) * (T(15) * c * t42 * t46 + T(16) * t41 * t42 + T(2) * b * t42 * t47) * t42 * in.w[2] + (T(1) / T(3440640)) * in.w[1] * t42 * t47 - (T(1) / T(229376)) * in.w[0] * t42 * t46;
  }
  const T g_factor = -T(16) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 56 +, 131 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w3_f(const SegmentInput<T>& in) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(47) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.47 a min(q(0), q(1)): recurrence (1) downwards from J_16 = J_downward(…)
    const T t2 = J_downward<T>(T(16), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t12 * t9;
    const T t14 = t8 - t13 - T(14) * t2 * b;
    const T t15 = t8 * a_minus_b + b * t13 - T(14) * D * t2;
    const T t16 = T(13) * t3 * t14 * b + T(91) * t2 * c + T(7) * t3 * t15;
    F = in.w[0] * t2 - (T(1) / T(14)) * t3 * t14 * in.w[1] - (T(1) / T(1092)) * in.w[3] * t3 * (T(7) * (T(13) * t7 + T(12) * t3 * t15 * b - T(13) * t12) * t3 + T(24) * t3 * t16 * b - T(78) * t3 * t14 * c) - (T(1) / T(91)) * t3 * t16 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = sqrt(D);
    const T t18 = T(1) / t17;
    const T J2 = t18 * atan2(t17, c_minus_b);
    const T t19 = T(1) / a;
    const T t20 = T(1) / D;
    const T t21 = T(1) / q1;
    const T t22 = t21 * t21;
    const T t23 = t22 * t22;
    const T t24 = t23 * t21;
    const T t25 = T(1) / c;
    const T t26 = t25 * t25;
    const T t27 = t26 * t25;
    const T t28 = t22 * t21;
    const T t29 = t26 * t26;
    const T t30 = t29 * t25;
    const T t31 = t28 * t28;
    const T t32 = t27 * t27;
    const T t33 = T(11) * t20 * a * (T(128) * t24 * a_minus_b + T(3) * t20 * (T(48) * t23 * a_minus_b + T(7) * t20 * a * (T(8) * b * t27 + T(8) * t28 * a_minus_b + T(5) * t20 * a * (T(3) * t20 * a * (b * t25 + t21 * a_minus_b + a * J2) + T(2) * t22 * a_minus_b + T(2) * b * t26)) + T(48) * b * t29) * a + T(128) * b * t30) + T(1280) * t31 * a_minus_b + T(1280) * b * t32;
    const T t34 = t31 * t21;
    const T t35 = t32 * t25;
    const T t36 = T(15360) * t34 * a_minus_b + T(13) * t20 * a * t33 + T(15360) * b * t35;
    const T t37 = t20 * t36 * b + T(15360) * t35 - T(15360) * t34;
    const T t38 = T(14) * t20 * t33 + T(2) * t19 * b * t37 - t20 * t36 * c;
    F = (T(1) / T(215040)) * t19 * t38 * in.w[2] + (T(1) / T(215040)) * t20 * in.w[0] * t36 + (T(1) / T(215040)) * t19 * in.w[1] * t37 - (T(1) / T(215040)) * in.w[3] * t19 * (T(14) * (T(1280) * t31 - t20 * t33 * b - T(1280) * t32) * t19 + t19 * t37 * c - T(2) * t19 * t38 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 68 +, 177 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_cauchy_i16_w3_grad(const SegmentInput<T>& in) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(51) / T(100)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = a_minus_b * t6 + t10 * b - T(16) * t2 * D;
    const T t12 = T(1) / a;
    const T t13 = t6 - T(16) * t2 * b - t10;
    const T t14 = T(120) * t2 * c + T(8) * t11 * t12 + T(15) * t13 * t12 * b;
    const T t15 = t4 * t3;
    const T t16 = t15 * t15;
    const T t17 = t16 * t3;
    const T t18 = t8 * t7;
    const T t19 = t18 * t18;
    const T t20 = t19 * t7;
    const T t21 = T(14) * t11 * t12 * b + T(15) * t17 - T(15) * t20;
    const T t22 = T(8) * t21 * t12 + T(28) * t14 * t12 * b - T(105) * c * t13 * t12;
    G_ap = t2 * in.w[0] - (T(1) / T(120)) * t14 * in.w[2] * t12 - (T(1) / T(16)) * in.w[1] * t13 * t12 - (T(1) / T(1680)) * t22 * t12 * in.w[3];
    G_ab = -(T(1) / T(10920)) * t12 * in.w[3] * (T(13) * t22 * t12 * b + T(8) * (T(7) * t12 * (T(14) * t11 * D * t12 + T(15) * t20 * b + T(15) * a_minus_b * t17) + T(13) * t21 * t12 * b - T(91) * c * t11 * t12) * t12 - T(91) * t14 * c * t12) - (T(1) / T(16)) * t13 * t12 * in.w[0] - (T(1) / T(1680)) * t22 * in.w[2] * t12 - (T(1) / T(120)) * t14 * in.w[1] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = sqrt(D);
    const T t24 = T(1) / t23;
    const T J2 = atan2(t23, c_minus_b) * t24;
    const T t25 = T(1) / a;
    const T t26 = T(1) / q1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * t28;
    const T t30 = T(1) / D;
    const T t31 = T(1) / c;
    const T t32 = t31 * t31;
    const T t33 = t32 * t31;
    const T t34 = t27 * t26;
    const T t35 = t32 * t32;
    const T t36 = t35 * t31;
    const T t37 = t28 * t26;
    const T t38 = t33 * t33;
    const T t39 = t34 * t34;
    const T t40 = T(11) * (T(3) * t30 * a * (T(7) * t30 * a * (T(8) * t33 * b + T(8) * a_minus_b * t34 + T(5) * (T(3) * (J2 * a + a_minus_b * t26 + t31 * b) * t30 * a + T(2) * t32 * b + T(2) * a_minus_b * t27) * t30 * a) + T(48) * t35 * b + T(48) * a_minus_b * t28) + T(128) * t36 * b + T(128) * a_minus_b * t37) * t30 * a + T(1280) * t38 * b + T(1280) * a_minus_b * t39;
    const T t41 = t38 * t31;
    const T t42 = t39 * t26;
    const T t43 = T(13) * t40 * t30 * a + T(15360) * t41 * b + T(15360) * a_minus_b * t42;
    const T t44 = t35 * t35;
    const T t45 = T(14336) * a_minus_b * t29 + t30 * a * t43 + T(14336) * t44 * b;
    const T t46 = T(14336) * t29 - t30 * t45 * b - T(14336) * t44;
    const T t47 = t30 * t43 * b + T(15360) * t41 - T(15360) * t42;
    const T t48 = T(16) * t30 * t43 - T(15) * c * t30 * t45 - T(30) * t25 * b * t46;
    const T t49 = T(15) * c * t25 * t46 + T(16) * t47 * t25 + T(2) * t25 * b * t48;
    G_ap = (T(1) / T(3440640)) * t49 * t25 * in.w[3] + (T(1) / T(3440640)) * in.w[2] * t25 * t48 + (T(1) / T(229376)) * t30 * t45 * in.w[0] - (T(1) / T(229376)) * in.w[1] * t25 * t46;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t25 * t48 + (T(1) / T(3440640)) * (T(16) * (T(2) * t47 * t25 * b + T(14) * t40 * t30 - c * t30 * t43) * t25 + T(2) * t49 * t25 * b - c * t25 * t48) * t25 * in.w[3] + (T(1) / T(3440640)) * t49 * in.w[2] * t25 - (T(1) / T(229376)) * t25 * in.w[0] * t46;
  }
  const T g_factor = -T(16) * in.s * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 75 +, 201 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
template <class T>
T segment_cauchy_i16_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(51) / T(100)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D ≤ 0.51 a min(q(0), q(1)): recurrence (1) downwards from J_18 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = T(1) / q1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t4 * t4;
    const T t13 = t12 * t12;
    const T t14 = J_downward<T>(T(18), a, D, -b, c, a_minus_b, q1);
    const T t15 = b * t11 + t13 * a_minus_b - T(16) * t14 * D;
    const T t16 = t9 * t8;
    const T t17 = t16 * t16;
    const T t18 = t17 * t8;
    const T t19 = T(15) * t7 + T(14) * b * t15 * t2 - T(15) * t18;
    const T t20 = T(15) * b * t18 + T(14) * t15 * D * t2 + T(15) * t7 * a_minus_b;
    const T t21 = T(91) * t15 * c * t2 - T(7) * t20 * t2 - T(13) * b * t2 * t19;
    F = (T(1) / T(5460)) * (T(26) * c * t2 * t19 + T(8) * b * t2 * t21 - T(7) * (T(4) * b * t20 * t2 + T(65) * t6 - T(65) * t17) * t2) * in.w[3] * t2 + (T(1) / T(1365)) * in.w[2] * t2 * t21 - (T(1) / T(210)) * t2 * t19 * in.w[1] - (T(1) / T(15)) * t15 * in.w[0] * t2;
    const T t22 = t11 + T(16) * b * t14 - t13;
    const T t23 = T(120) * t14 * c + T(8) * t15 * t2 - T(15) * b * t2 * t22;
    const T t24 = T(105) * c * t2 * t22 + T(8) * t2 * t19 + T(28) * b * t23 * t2;
    G_ap = (T(1) / T(16)) * t2 * t22 * in.w[1] + t14 * in.w[0] - (T(1) / T(1680)) * in.w[3] * t2 * t24 - (T(1) / T(120)) * t23 * in.w[2] * t2;
    G_ab = (T(1) / T(10920)) * in.w[3] * t2 * (T(8) * t2 * t21 + T(91) * t23 * c * t2 - T(13) * b * t2 * t24) + (T(1) / T(16)) * in.w[0] * t2 * t22 - (T(1) / T(1680)) * in.w[2] * t2 * t24 - (T(1) / T(120)) * t23 * t2 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = sqrt(D);
    const T t26 = T(1) / t25;
    const T J2 = t26 * atan2(t25, c_minus_b);
    const T t27 = T(1) / a;
    const T t28 = T(1) / D;
    const T t29 = T(1) / q1;
    const T t30 = t29 * t29;
    const T t31 = T(1) / c;
    const T t32 = t31 * t31;
    const T t33 = t30 * t29;
    const T t34 = t32 * t31;
    const T t35 = t30 * t30;
    const T t36 = t32 * t32;
    const T t37 = t35 * t29;
    const T t38 = t36 * t31;
    const T t39 = t34 * t34;
    const T t40 = t33 * t33;
    const T t41 = T(11) * (T(3) * (T(7) * (T(5) * t28 * a * (T(2) * t30 * a_minus_b + T(3) * (b * t31 + t29 * a_minus_b + J2 * a) * t28 * a + T(2) * b * t32) + T(8) * t33 * a_minus_b + T(8) * b * t34) * t28 * a + T(48) * t35 * a_minus_b + T(48) * b * t36) * t28 * a + T(128) * t37 * a_minus_b + T(128) * b * t38) * t28 * a + T(1280) * b * t39 + T(1280) * t40 * a_minus_b;
    const T t42 = t40 * t29;
    const T t43 = t39 * t31;
    const T t44 = T(13) * t41 * t28 * a + T(15360) * b * t43 + T(15360) * t42 * a_minus_b;
    const T t45 = T(15360) * t42 - T(15360) * t43 - b * t44 * t28;
    const T t46 = T(14) * t41 * t28 - c * t44 * t28 - T(2) * b * t45 * t27;
    F = (T(1) / T(215040)) * in.w[3] * t27 * (T(14) * (b * t41 * t28 + T(1280) * t39 - T(1280) * t40) * t27 + t45 * c * t27 + T(2) * b * t46 * t27) + (T(1) / T(215040)) * t46 * in.w[2] * t27 + (T(1) / T(215040)) * t44 * t28 * in.w[0] - (T(1) / T(215040)) * t45 * t27 * in.w[1];
    const T t47 = t36 * t36;
    const T t48 = t35 * t35;
    const T t49 = T(14336) * b * t47 + t44 * t28 * a + T(14336) * t48 * a_minus_b;
    const T t50 = T(14336) * t47 + b * t49 * t28 - T(14336) * t48;
    const T t51 = T(15) * c * t49 * t28 - T(16) * t44 * t28 - T(30) * b * t27 * t50;
    const T t52 = T(15) * c * t27 * t50 + T(2) * b * t51 * t27 + T(16) * t45 * t27;
    G_ap = (T(1) / T(229376)) * t49 * t28 * in.w[0] + (T(1) / T(229376)) * t27 * t50 * in.w[1] - (T(1) / T(3440640)) * in.w[2] * t51 * t27 - (T(1) / T(3440640)) * t52 * in.w[3] * t27;
    G_ab = (T(1) / T(3440640)) * (c * t51 * t27 + T(16) * t46 * t27 - T(2) * b * t52 * t27) * in.w[3] * t27 + (T(1) / T(229376)) * in.w[0] * t27 * t50 - (T(1) / T(3440640)) * t51 * t27 * in.w[1] - (T(1) / T(3440640)) * in.w[2] * t52 * t27;
  }
  const T g_factor = -T(16) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

}  // namespace skelconv::generated
