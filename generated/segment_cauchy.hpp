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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
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
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = sqrt(a);
    const T t2 = a_minus_b * r0;
    X = t1 * (t2 + b * r1) / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = a_minus_b * r0;
    X = -(b - a_minus_b) * t3 / (t4 - b * r1);
  }
  const T t5 = sqrt(a);
  const T J1 = asinh(X) / t5;
  T F;
    // recurrence (1) upwards from J_1, J_2
    F = J1 * in.w[0];
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 34 +, 51 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = T(1) / r0;
    const T t4 = a_minus_b * t2 + b * t3;
    const T t5 = T(1) / D;
    G_ap = in.w[0] * t4 * t5;
    G_ab = -in.w[0] * (t2 - t3 - b * t4 * t5) / a;
  }
  const T g_factor = -length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
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
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = J1 * in.w[0];
    F = t10;
    const T t11 = -b;
    const T t12 = J_downward<T>(T(3), a, D, t11, c, a_minus_b, q1);
    G_ap = in.w[0] * t12;
    const T t13 = T(1) / a;
    const T t14 = T(1) / r1;
    const T t15 = T(1) / r0;
    G_ab = -in.w[0] * t13 * (t14 - t15 - t12 * b);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = J1 * in.w[0];
    F = t16;
    const T t17 = T(1) / D;
    const T t18 = T(1) / r1;
    const T t19 = T(1) / r0;
    const T t20 = t18 * a_minus_b + t19 * b;
    G_ap = t17 * in.w[0] * t20;
    const T t21 = T(1) / a;
    G_ab = -(t18 - t19 - t17 * t20 * b) * in.w[0] * t21;
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
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
    F = J1 * in.w[0] - (r0 - J1 * b - r1) * in.w[1] * t7;
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
    const T t1 = r1 * b;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + a_minus_b * r0) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r1 * b;
    X = -(a_minus_b - b) * t4 / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = T(1) / r0;
    const T t12 = -b;
    const T t13 = J_downward<T>(T(3), a, D, t12, c, a_minus_b, q1);
    const T t14 = T(1) / r1;
    const T t15 = t11 + b * t13 - t14;
    G_ap = t10 * in.w[1] * t15 + in.w[0] * t13;
    G_ab = in.w[0] * t10 * t15 - t10 * in.w[1] * (c * t13 - T(2) * t10 * b * t15 - J1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / a;
    const T t17 = T(1) / D;
    const T t18 = T(1) / r0;
    const T t19 = T(1) / r1;
    const T t20 = b * t18 + t19 * a_minus_b;
    const T t21 = t17 * t20 * b + t18 - t19;
    G_ap = t16 * in.w[1] * t21 + in.w[0] * t17 * t20;
    G_ab = t16 * (T(2) * t16 * b * t21 + J1 - t17 * t20 * c) * in.w[1] + in.w[0] * t16 * t21;
  }
  const T g_factor = -length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
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
    X = -(a_minus_b - b) * t4 / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = in.w[0] * J1 - in.w[1] * t10 * (r0 - r1 - J1 * b);
    F = t11;
    const T t12 = -b;
    const T t13 = J_downward<T>(T(3), a, D, t12, c, a_minus_b, q1);
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = b * t13 + t14 - t15;
    G_ap = in.w[0] * t13 + in.w[1] * t10 * t16;
    G_ab = (T(2) * t10 * b * t16 + J1 - c * t13) * in.w[1] * t10 + in.w[0] * t10 * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = in.w[0] * J1 - in.w[1] * t17 * (r0 - r1 - J1 * b);
    F = t18;
    const T t19 = T(1) / D;
    const T t20 = T(1) / r0;
    const T t21 = T(1) / r1;
    const T t22 = t20 * b + t21 * a_minus_b;
    const T t23 = t21 - t19 * t22 * b - t20;
    G_ap = in.w[0] * t19 * t22 - in.w[1] * t17 * t23;
    G_ab = (J1 - T(2) * t17 * t23 * b - c * t19 * t22) * in.w[1] * t17 - in.w[0] * t17 * t23;
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
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
    const T t1 = sqrt(a);
    const T t2 = r1 * b;
    X = t1 * (t2 + a_minus_b * r0) / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = r1 * b;
    X = -(a_minus_b - b) * t3 / (t4 - a_minus_b * r0);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = asinh(X) * t6;
  T F;
    // recurrence (1) upwards from J_1, J_2
    const T t7 = T(1) / a;
    const T t8 = r1 + J1 * b - r0;
    F = (T(1) / T(2)) * (t7 * (r0 * b + D * J1 + a_minus_b * r1) + T(4) * t8 * t7 * b - T(2) * c * J1) * t7 * in.w[2] + in.w[1] * t8 * t7 + in.w[0] * J1;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
  const T J1 = asinh(X) * t7;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = T(1) / r0;
    const T t12 = -b;
    const T t13 = J_downward<T>(T(3), a, D, t12, c, a_minus_b, q1);
    const T t14 = T(1) / r1;
    const T t15 = t11 + t13 * b - t14;
    const T t16 = T(2) * t10 * b * t15 + J1 - c * t13;
    G_ap = in.w[1] * t10 * t15 + t13 * in.w[0] + t16 * t10 * in.w[2];
    const T t17 = b * J1 + r1 - r0;
    G_ab = (T(2) * t16 * t10 * b + t10 * t17 - c * t10 * t15) * t10 * in.w[2] + t10 * t15 * in.w[0] + t16 * in.w[1] * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / D;
    const T t20 = T(1) / r0;
    const T t21 = T(1) / r1;
    const T t22 = b * t20 + t21 * a_minus_b;
    const T t23 = t19 * b * t22 + t20 - t21;
    const T t24 = T(2) * t18 * b * t23 + J1 - c * t19 * t22;
    G_ap = t18 * in.w[2] * t24 + in.w[1] * t18 * t23 + t19 * t22 * in.w[0];
    const T t25 = b * J1 + r1 - r0;
    G_ab = in.w[1] * t18 * t24 + t18 * in.w[0] * t23 - t18 * in.w[2] * (c * t18 * t23 - T(2) * t18 * b * t24 - t18 * t25);
  }
  const T g_factor = -in.s * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + b * r1) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = (a_minus_b - b) * t4 / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = r0 - b * J1 - r1;
    const T t12 = (T(1) / T(2)) * ((J1 * D + b * r0 + a_minus_b * r1) * t10 - T(2) * c * J1 - T(4) * b * t10 * t11) * in.w[2] * t10 + in.w[0] * J1 - in.w[1] * t10 * t11;
    F = t12;
    const T t13 = -b;
    const T t14 = J_downward<T>(T(3), a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = b * t14 + t15 - t16;
    const T t18 = t14 * c - J1 - T(2) * b * t17 * t10;
    G_ap = in.w[0] * t14 + in.w[1] * t17 * t10 - t18 * in.w[2] * t10;
    const T t19 = t10 * t11;
    G_ab = in.w[0] * t17 * t10 - in.w[2] * t10 * (c * t17 * t10 + t19 + T(2) * b * t18 * t10) - in.w[1] * t18 * t10;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / a;
    const T t21 = r0 - b * J1 - r1;
    const T t22 = (T(1) / T(2)) * ((J1 * D + b * r0 + a_minus_b * r1) * t20 - T(2) * c * J1 - T(4) * b * t20 * t21) * in.w[2] * t20 + in.w[0] * J1 - in.w[1] * t20 * t21;
    F = t22;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = b * t24 + a_minus_b * t25;
    const T t27 = t25 - b * t23 * t26 - t24;
    const T t28 = T(2) * t27 * b * t20 + c * t23 * t26 - J1;
    G_ap = in.w[0] * t23 * t26 - t28 * in.w[2] * t20 - t27 * in.w[1] * t20;
    const T t29 = t20 * t21;
    G_ab = -(t29 + T(2) * b * t28 * t20 - t27 * c * t20) * in.w[2] * t20 - t27 * in.w[0] * t20 - in.w[1] * t28 * t20;
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
    const T t8 = r0 * b + r1 * a_minus_b + J1 * D;
    const T t9 = r0 - J1 * b - r1;
    const T t10 = t7 * t8 - T(2) * J1 * c - T(4) * b * t9 * t7;
    F = (T(1) / T(6)) * (T(6) * b * t10 * t7 + (T(2) * r1 * q1 + T(3) * b * t7 * t8 - T(2) * r0 * c) * t7 + T(6) * t9 * c * t7) * t7 * in.w[3] + J1 * in.w[0] + (T(1) / T(2)) * in.w[2] * t10 * t7 - in.w[1] * t9 * t7;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
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
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 - b * t10 - t12;
    const T t14 = T(1) / a;
    const T t15 = T(2) * t13 * t14 * b + t10 * c - J1;
    const T t16 = r0 - b * J1 - r1;
    const T t17 = t14 * t16;
    const T t18 = T(2) * t14 * b * t15 + t17 - t13 * t14 * c;
    G_ap = in.w[0] * t10 - t13 * t14 * in.w[1] - t14 * t18 * in.w[3] - t14 * in.w[2] * t15;
    const T t19 = T(4) * t14 * b * t16 + T(2) * J1 * c - t14 * (J1 * D + b * r0 + r1 * a_minus_b);
    G_ab = -t14 * in.w[1] * t15 - t14 * in.w[2] * t18 - (T(1) / T(2)) * (t14 * t19 + T(4) * t14 * b * t18 - T(2) * t14 * c * t15) * t14 * in.w[3] - t13 * in.w[0] * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = t20 * a_minus_b + b * t21;
    const T t23 = T(1) / D;
    const T t24 = T(1) / a;
    const T t25 = t20 - b * t22 * t23 - t21;
    const T t26 = c * t22 * t23 + T(2) * t24 * b * t25 - J1;
    const T t27 = r0 - b * J1 - r1;
    const T t28 = t24 * t27;
    const T t29 = T(2) * t24 * b * t26 + t28 - t24 * c * t25;
    G_ap = in.w[0] * t22 * t23 - t24 * t29 * in.w[3] - t24 * in.w[1] * t25 - t24 * in.w[2] * t26;
    const T t30 = T(4) * t24 * b * t27 + T(2) * J1 * c - t24 * (J1 * D + b * r0 + r1 * a_minus_b);
    G_ab = (T(1) / T(2)) * t24 * (T(2) * t24 * c * t26 - T(4) * t24 * b * t29 - t24 * t30) * in.w[3] - t24 * in.w[1] * t26 - in.w[0] * t24 * t25 - t24 * t29 * in.w[2];
  }
  const T g_factor = -length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = r0 * a_minus_b;
    const T t3 = sqrt(a);
    X = t1 * (t2 + b * r1) * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = -t4 * (b - a_minus_b) / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -b * a_minus_b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = b * J1 + r1 - r0;
    const T t11 = T(1) / a;
    const T t12 = b * r0 + J1 * D + r1 * a_minus_b;
    const T t13 = T(2) * c * J1 - T(4) * b * t10 * t11 - t11 * t12;
    const T t14 = J1 * in.w[0] + in.w[1] * t10 * t11 - (T(1) / T(6)) * t11 * in.w[3] * (T(6) * c * t10 * t11 + t11 * (T(2) * c * r0 - T(3) * b * t11 * t12 - T(2) * q1 * r1) + T(6) * b * t13 * t11) - (T(1) / T(2)) * t13 * in.w[2] * t11;
    F = t14;
    const T t15 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = b * t15 + t16 - t17;
    const T t19 = c * t15 - J1 - T(2) * b * t18 * t11;
    const T t20 = T(2) * b * t19 * t11 + c * t18 * t11 - t10 * t11;
    G_ap = in.w[1] * t18 * t11 + t15 * in.w[0] - t20 * t11 * in.w[3] - in.w[2] * t19 * t11;
    const T t21 = t13 * t11;
    G_ab = t18 * t11 * in.w[0] - (T(1) / T(2)) * t11 * in.w[3] * (t21 + T(4) * b * t20 * t11 - T(2) * c * t19 * t11) - t20 * in.w[2] * t11 - in.w[1] * t19 * t11;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t22 = b * J1 + r1 - r0;
    const T t23 = T(1) / a;
    const T t24 = b * r0 + J1 * D + r1 * a_minus_b;
    const T t25 = T(2) * c * J1 - T(4) * b * t22 * t23 - t23 * t24;
    const T t26 = J1 * in.w[0] + in.w[1] * t22 * t23 - (T(1) / T(6)) * t23 * in.w[3] * (T(6) * c * t22 * t23 + t23 * (T(2) * c * r0 - T(3) * b * t23 * t24 - T(2) * q1 * r1) + T(6) * b * t25 * t23) - (T(1) / T(2)) * t25 * in.w[2] * t23;
    F = t26;
    const T t27 = T(1) / r0;
    const T t28 = T(1) / r1;
    const T t29 = b * t27 + t28 * a_minus_b;
    const T t30 = T(1) / D;
    const T t31 = t28 - t27 - b * t29 * t30;
    const T t32 = T(2) * b * t23 * t31 + t29 * c * t30 - J1;
    const T t33 = T(2) * b * t32 * t23 - c * t23 * t31 - t22 * t23;
    G_ap = t29 * t30 * in.w[0] - in.w[1] * t23 * t31 - t32 * in.w[2] * t23 - t33 * t23 * in.w[3];
    const T t34 = t25 * t23;
    G_ab = -t32 * in.w[1] * t23 - (T(1) / T(2)) * (t34 + T(4) * b * t33 * t23 - T(2) * t32 * c * t23) * t23 * in.w[3] - t23 * t31 * in.w[0] - t33 * in.w[2] * t23;
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
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
/// Operations: 38 +, 60 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = T(1) / q1;
    const T t6 = t4 * b + a_minus_b * t5 + J2 * a;
    const T t7 = T(1) / D;
    G_ap = (T(1) / T(2)) * t6 * t7 * in.w[0];
    G_ab = -(T(1) / T(2)) * (t5 - t6 * t7 * b - t4) * in.w[0] / a;
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = T(1) / c;
    F = t2 * in.w[0] * (T(2) * D * t3 - a_minus_b * t4 - t5 * b);
    G_ap = in.w[0] * t3;
    G_ab = -(T(1) / T(2)) * t2 * in.w[0] * (t4 - T(2) * t3 * b - t5);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T t7 = T(1) / t6;
    const T J2 = t7 * atan2(t6, c_minus_b);
    F = J2 * in.w[0];
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = T(1) / c;
    const T t11 = a_minus_b * t9 + t10 * b + J2 * a;
    G_ap = (T(1) / T(2)) * t8 * in.w[0] * t11;
    const T t12 = T(1) / a;
    G_ab = (T(1) / T(2)) * (t8 * t11 * b + t10 - t9) * t12 * in.w[0];
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    F = (T(1) / T(2)) * t2 * (log_ratio + T(2) * b * t3) * in.w[1] + t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    const T t5 = T(1) / a;
    F = (T(1) / T(2)) * t5 * in.w[1] * (log_ratio + T(2) * b * J2) + in.w[0] * J2;
  }
  f = length * F;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = a_minus_b * t5 + a * J2 + t6 * b;
    const T t8 = T(1) / a;
    const T t9 = t6 + t4 * t7 * b - t5;
    G_ap = (T(1) / T(2)) * in.w[0] * t4 * t7 + (T(1) / T(2)) * t8 * in.w[1] * t9;
    G_ab = (T(1) / T(2)) * (T(2) * t8 * t9 * b + T(2) * J2 - c * t4 * t7) * t8 * in.w[1] + (T(1) / T(2)) * in.w[0] * t8 * t9;
  }
  const T g_factor = -T(2) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
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
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = b * t0;
    const T t4 = T(1) / q1;
    const T t5 = a_minus_b * t4;
    const T t6 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t7 = t3 + t5 - T(2) * t6 * D;
    const T t8 = T(1) / a;
    F = (T(1) / T(2)) * (log_ratio - T(2) * t7 * b * t8) * in.w[1] * t8 - t7 * in.w[0] * t8;
    const T t9 = T(2) * b * t6 + t0 - t4;
    G_ap = in.w[0] * t6 + (T(1) / T(2)) * t9 * in.w[1] * t8;
    G_ab = (T(1) / T(2)) * t9 * in.w[0] * t8 - in.w[1] * t8 * (t7 * t8 + t6 * c - t9 * b * t8);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = sqrt(D);
    const T t11 = T(1) / t10;
    const T J2 = atan2(t10, c_minus_b) * t11;
    const T t12 = T(1) / a;
    F = in.w[0] * J2 + (T(1) / T(2)) * (log_ratio + T(2) * b * J2) * in.w[1] * t12;
    const T t13 = b * t0;
    const T t14 = T(1) / q1;
    const T t15 = a_minus_b * t14;
    const T t16 = J2 * a + t13 + t15;
    const T t17 = T(1) / D;
    const T t18 = t14 - t16 * b * t17 - t0;
    G_ap = (T(1) / T(2)) * t16 * in.w[0] * t17 - (T(1) / T(2)) * t18 * in.w[1] * t12;
    G_ab = -(T(1) / T(2)) * (t16 * c * t17 + T(2) * b * t18 * t12 - T(2) * J2) * in.w[1] * t12 - (T(1) / T(2)) * in.w[0] * t18 * t12;
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    const T t3 = log_ratio + T(2) * t2 * b;
    const T t4 = T(1) / a;
    F = (T(1) / T(2)) * t3 * in.w[1] * t4 + t2 * in.w[0] - (t2 * c - b * t3 * t4 - T(1)) * t4 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    const T t6 = log_ratio + T(2) * J2 * b;
    const T t7 = T(1) / a;
    F = (T(1) / T(2)) * t6 * in.w[1] * t7 + J2 * in.w[0] - (J2 * c - t6 * b * t7 - T(1)) * t7 * in.w[2];
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T G_ap;
  T G_ab;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / q1;
    const T t5 = T(2) * b * t3 + t0 - t4;
    const T t6 = T(1) / a;
    const T t7 = T(2) * t3 * D - t4 * a_minus_b - b * t0;
    const T t8 = c * t3 - b * t5 * t6 - t7 * t6;
    G_ap = in.w[0] * t3 + (T(1) / T(2)) * in.w[1] * t5 * t6 - t8 * in.w[2] * t6;
    G_ab = (T(1) / T(2)) * ((T(2) * b * t7 * t6 + log_ratio) * t6 - T(4) * b * t8 * t6 - c * t5 * t6) * in.w[2] * t6 + (T(1) / T(2)) * in.w[0] * t5 * t6 - in.w[1] * t8 * t6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t9 = sqrt(D);
    const T t10 = T(1) / t9;
    const T J2 = atan2(t9, c_minus_b) * t10;
    const T t11 = T(1) / q1;
    const T t12 = t11 * a_minus_b + J2 * a + b * t0;
    const T t13 = T(1) / D;
    const T t14 = b * t12 * t13 + t0 - t11;
    const T t15 = T(1) / a;
    const T t16 = c * t12 * t13 - T(2) * J2 - T(2) * t14 * b * t15;
    G_ap = (T(1) / T(2)) * t14 * in.w[1] * t15 + (T(1) / T(2)) * in.w[0] * t12 * t13 - (T(1) / T(2)) * t16 * in.w[2] * t15;
    G_ab = (T(1) / T(2)) * t14 * in.w[0] * t15 - (T(1) / T(2)) * (T(2) * b * t16 * t15 + t14 * c * t15 - (T(2) * b * J2 + log_ratio) * t15) * in.w[2] * t15 - (T(1) / T(2)) * in.w[1] * t16 * t15;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = a_minus_b * t4;
    const T t6 = b * t0;
    const T t7 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t8 = t5 + t6 - T(2) * D * t7;
    const T t9 = T(2) * b * t8 * t3 - log_ratio;
    F = t3 * in.w[2] * (c * t8 * t3 + T(1) - b * t9 * t3) - (T(1) / T(2)) * in.w[1] * t9 * t3 - in.w[0] * t8 * t3;
    const T t10 = t0 + T(2) * b * t7 - t4;
    const T t11 = b * t10 * t3 - t8 * t3 - c * t7;
    G_ap = t3 * t11 * in.w[2] + in.w[0] * t7 + (T(1) / T(2)) * t10 * in.w[1] * t3;
    G_ab = (T(1) / T(2)) * t10 * in.w[0] * t3 + in.w[1] * t3 * t11 - (T(1) / T(2)) * (t10 * c * t3 + t9 * t3 - T(4) * b * t3 * t11) * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / a;
    const T t15 = T(2) * b * J2 + log_ratio;
    F = (T(1) / T(2)) * in.w[1] * t14 * t15 + in.w[0] * J2 - (c * J2 - b * t14 * t15 - T(1)) * t14 * in.w[2];
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = a_minus_b * t17;
    const T t19 = b * t0;
    const T t20 = t18 + t19 + J2 * a;
    const T t21 = t0 + b * t16 * t20 - t17;
    const T t22 = T(2) * J2 + T(2) * b * t21 * t14 - c * t16 * t20;
    G_ap = (T(1) / T(2)) * t21 * in.w[1] * t14 + (T(1) / T(2)) * t22 * t14 * in.w[2] + (T(1) / T(2)) * in.w[0] * t16 * t20;
    G_ab = (T(1) / T(2)) * in.w[0] * t21 * t14 + (T(1) / T(2)) * in.w[1] * t22 * t14 - (T(1) / T(2)) * (t21 * c * t14 - T(2) * b * t22 * t14 - t14 * t15) * t14 * in.w[2];
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(2), a, D, -b, c, a_minus_b, q1);
    const T t4 = log_ratio + T(2) * t3 * b;
    const T t5 = t3 * c - t2 * b * t4 - T(1);
    F = (T(1) / T(2)) * t2 * in.w[1] * t4 + in.w[0] * t3 - (T(1) / T(2)) * t2 * in.w[3] * (t2 * c * t4 + T(4) * t2 * t5 * b - t2 * (T(2) * b + q1 - c)) - t2 * t5 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T J2 = atan2(t6, c_minus_b) / t6;
    const T t7 = T(1) / a;
    const T t8 = log_ratio + T(2) * J2 * b;
    const T t9 = J2 * c - t7 * b * t8 - T(1);
    F = in.w[0] * J2 + (T(1) / T(2)) * t7 * t8 * in.w[1] - t7 * t9 * in.w[2] - (T(1) / T(2)) * t7 * in.w[3] * (T(4) * t7 * b * t9 + t7 * t8 * c - t7 * (T(2) * b + q1 - c));
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(t0 * q1);
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 - T(2) * t3 * b - t0;
    const T t7 = t0 * b;
    const T t8 = a_minus_b * t5;
    const T t9 = t7 + t8 - T(2) * t3 * D;
    const T t10 = t6 * t4 * b + c * t3 + t9 * t4;
    const T t11 = log_ratio - T(2) * t9 * t4 * b;
    const T t12 = T(4) * t4 * t10 * b - t11 * t4 - t6 * c * t4;
    G_ap = t3 * in.w[0] - (T(1) / T(2)) * t12 * t4 * in.w[3] - (T(1) / T(2)) * in.w[1] * t6 * t4 - in.w[2] * t4 * t10;
    G_ab = t4 * in.w[3] * (c * t4 * t10 + t4 * (t11 * t4 * b + t9 * c * t4 + T(1)) - t12 * t4 * b) - in.w[1] * t4 * t10 - (T(1) / T(2)) * t12 * in.w[2] * t4 - (T(1) / T(2)) * t6 * t4 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / D;
    const T t16 = t0 * b;
    const T t17 = T(1) / q1;
    const T t18 = a_minus_b * t17;
    const T t19 = t16 + J2 * a + t18;
    const T t20 = T(1) / a;
    const T t21 = t17 - t0 - t15 * b * t19;
    const T t22 = T(2) * t21 * t20 * b + c * t15 * t19 - T(2) * J2;
    const T t23 = log_ratio + T(2) * J2 * b;
    const T t24 = T(2) * t20 * t22 * b - t21 * c * t20 - t20 * t23;
    G_ap = (T(1) / T(2)) * t15 * in.w[0] * t19 - (T(1) / T(2)) * in.w[2] * t20 * t22 - (T(1) / T(2)) * in.w[1] * t21 * t20 - (T(1) / T(2)) * t24 * t20 * in.w[3];
    G_ab = (T(1) / T(2)) * (T(2) * t20 * (t20 * t23 * b + T(1) - J2 * c) + c * t20 * t22 - T(2) * t24 * t20 * b) * t20 * in.w[3] - (T(1) / T(2)) * in.w[2] * t24 * t20 - (T(1) / T(2)) * in.w[1] * t20 * t22 - (T(1) / T(2)) * t21 * t20 * in.w[0];
  }
  const T g_factor = -T(2) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * a_minus_b;
    const T t6 = t0 * b;
    const T t7 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t8 = t5 + t6 - T(2) * D * t7;
    const T t9 = log_ratio - T(2) * t3 * t8 * b;
    const T t10 = t3 * t9 * b + c * t3 * t8 + T(1);
    const T t11 = t3 * (q1 + T(2) * b - c);
    F = (T(1) / T(2)) * t3 * t9 * in.w[1] + t10 * in.w[2] * t3 + (T(1) / T(2)) * (T(4) * t10 * t3 * b + t11 - c * t3 * t9) * t3 * in.w[3] - t3 * in.w[0] * t8;
    const T t12 = t4 - t0 - T(2) * t7 * b;
    const T t13 = t12 * t3 * b + c * t7 + t3 * t8;
    const T t14 = T(4) * t13 * t3 * b - t12 * c * t3 - t3 * t9;
    G_ap = in.w[0] * t7 - (T(1) / T(2)) * t12 * t3 * in.w[1] - t13 * in.w[2] * t3 - (T(1) / T(2)) * t3 * in.w[3] * t14;
    G_ab = (c * t13 * t3 + t10 * t3 - t3 * b * t14) * t3 * in.w[3] - t13 * t3 * in.w[1] - (T(1) / T(2)) * in.w[2] * t3 * t14 - (T(1) / T(2)) * t12 * t3 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / a;
    const T t18 = t17 * (q1 + T(2) * b - c);
    const T t19 = T(2) * J2 * b + log_ratio;
    const T t20 = c * J2 - t19 * t17 * b - T(1);
    F = (T(1) / T(2)) * t17 * in.w[3] * (t18 - t19 * c * t17 - T(4) * t20 * t17 * b) + (T(1) / T(2)) * t19 * t17 * in.w[1] + J2 * in.w[0] - in.w[2] * t20 * t17;
    const T t21 = T(1) / q1;
    const T t22 = T(1) / D;
    const T t23 = t21 * a_minus_b;
    const T t24 = t0 * b;
    const T t25 = t23 + t24 + J2 * a;
    const T t26 = t21 - t0 - t22 * t25 * b;
    const T t27 = T(2) * J2 - T(2) * t17 * t26 * b - c * t22 * t25;
    const T t28 = c * t17 * t26 + t19 * t17 + T(2) * t27 * t17 * b;
    G_ap = (T(1) / T(2)) * t28 * t17 * in.w[3] + (T(1) / T(2)) * t22 * in.w[0] * t25 + (T(1) / T(2)) * t27 * in.w[2] * t17 - (T(1) / T(2)) * t17 * t26 * in.w[1];
    G_ab = (T(1) / T(2)) * t27 * t17 * in.w[1] + (T(1) / T(2)) * t28 * in.w[2] * t17 - (T(1) / T(2)) * t17 * in.w[0] * t26 - (T(1) / T(2)) * (c * t27 * t17 + T(2) * t20 * t17 - T(2) * t28 * t17 * b) * t17 * in.w[3];
  }
  const T g_factor = -T(2) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = (b / r0 + a_minus_b / r1) * in.w[0] / D;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 36 +, 65 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / D;
    const T t6 = t4 * t4;
    const T t7 = t3 * t2 * a_minus_b + T(2) * (t2 * a_minus_b + b * t4) * t5 * a + b * t4 * t6;
    G_ap = (T(1) / T(3)) * t7 * t5 * in.w[0];
    G_ab = -(T(1) / T(3)) * (t3 * t2 - t4 * t6 - b * t7 * t5) * in.w[0] / a;
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 36 +, 68 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = t3 * a_minus_b + t4 * b;
    F = t2 * in.w[0] * t5;
    const T t6 = t3 * t3;
    const T t7 = t4 * t4;
    const T t8 = t6 * t3 * a_minus_b + t4 * b * t7 + T(2) * t2 * a * t5;
    G_ap = (T(1) / T(3)) * t2 * in.w[0] * t8;
    G_ab = (T(1) / T(3)) * (t2 * t8 * b + t4 * t7 - t6 * t3) * in.w[0] / a;
  }
  const T g_factor = -T(3) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 32 +, 42 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t2 * b + t4 * a_minus_b;
    F = in.w[1] * (t2 + t3 * b * t5 - t4) / a + t3 * t5 * in.w[0];
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = b * t5 + t3 * a_minus_b;
    const T t8 = t3 * a_minus_b * t4 + b * t5 * t6 + T(2) * t2 * a * t7;
    const T t9 = T(1) / a;
    const T t10 = t5 * t6 + t2 * b * t8 - t3 * t4;
    G_ap = (T(1) / T(3)) * t2 * t8 * in.w[0] + (T(1) / T(3)) * t9 * in.w[1] * t10;
    G_ab = (T(1) / T(3)) * t9 * in.w[1] * (T(2) * t9 * b * t10 + T(3) * t2 * t7 - t2 * c * t8) + (T(1) / T(3)) * t9 * t10 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(5), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = T(3) * D * t3 - t4 * b * t5 - t6 * a_minus_b * t7;
    F = (T(1) / T(2)) * t2 * t8 * in.w[0] - (T(1) / T(2)) * in.w[1] * t2 * (T(2) * t6 - T(2) * t4 - t2 * t8 * b);
    const T t9 = t6 * t7 - T(3) * b * t3 - t4 * t5;
    G_ap = t3 * in.w[0] - (T(1) / T(3)) * in.w[1] * t2 * t9;
    G_ab = (T(1) / T(6)) * in.w[1] * t2 * (T(3) * t2 * t8 - T(6) * t3 * c - T(4) * t2 * t9 * b) - (T(1) / T(3)) * t2 * t9 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t10 = T(1) / a;
    const T t11 = T(1) / D;
    const T t12 = T(1) / r1;
    const T t13 = T(1) / r0;
    const T t14 = t12 * a_minus_b + t13 * b;
    F = in.w[1] * t10 * (t11 * t14 * b + t13 - t12) + t11 * t14 * in.w[0];
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(2) * t11 * a * t14 + t13 * b * t15 + t12 * a_minus_b * t16;
    const T t18 = t11 * t17 * b + t13 * t15 - t12 * t16;
    G_ap = (T(1) / T(3)) * in.w[1] * t10 * t18 + (T(1) / T(3)) * t11 * t17 * in.w[0];
    G_ab = (T(1) / T(3)) * in.w[1] * t10 * (T(3) * t11 * t14 + T(2) * t10 * b * t18 - t11 * t17 * c) + (T(1) / T(3)) * t10 * t18 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
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
  const T t9 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t11 = T(1) / r1;
    const T t12 = T(1) / r0;
    const T t13 = t11 - t12 - t10 * b;
    const T t14 = T(1) / a;
    F = t10 * in.w[0] - t13 * in.w[1] * t14 - in.w[2] * (T(2) * b * t13 * t14 + t10 * c - J1) * t14;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = T(1) / r0;
    const T t16 = T(1) / r1;
    const T t17 = t15 * b + t16 * a_minus_b;
    const T t18 = T(1) / D;
    const T t19 = b * t17 * t18 + t15 - t16;
    const T t20 = T(1) / a;
    F = in.w[0] * t17 * t18 + t19 * in.w[1] * t20 - in.w[2] * (c * t17 * t18 - J1 - T(2) * t19 * b * t20) * t20;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = T(1) / r0;
    const T t5 = t2 * a_minus_b + b * t4;
    const T t6 = T(1) / D;
    const T t7 = t4 * t4;
    const T t8 = t3 * t2 * a_minus_b + T(2) * t5 * t6 * a + b * t4 * t7;
    const T t9 = T(1) / a;
    const T t10 = t3 * t2 - b * t8 * t6 - t4 * t7;
    const T t11 = T(2) * b * t9 * t10 + t8 * c * t6 - T(3) * t5 * t6;
    G_ap = (T(1) / T(3)) * in.w[0] * t8 * t6 - (T(1) / T(3)) * in.w[1] * t9 * t10 - (T(1) / T(3)) * t11 * in.w[2] * t9;
    G_ab = -(T(1) / T(3)) * (T(2) * t11 * b * t9 - T(3) * (t4 + b * t5 * t6 - t2) * t9 - c * t9 * t10) * in.w[2] * t9 - (T(1) / T(3)) * t11 * in.w[1] * t9 - (T(1) / T(3)) * in.w[0] * t9 * t10;
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11 * a_minus_b;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t14 * b;
    const T t17 = -b;
    const T t18 = J_downward<T>(T(5), a, D, t17, c, a_minus_b, q1);
    const T t19 = t13 + t16 - T(3) * D * t18;
    const T t20 = T(2) * t14 - t10 * t19 * b - T(2) * t11;
    F = (T(1) / T(2)) * t10 * in.w[2] * (c * t10 * t19 + T(2) * J1 + T(2) * t20 * t10 * b) + (T(1) / T(2)) * t20 * in.w[1] * t10 - (T(1) / T(2)) * t10 * t19 * in.w[0];
    const T t21 = T(3) * b * t18 + t15 * t14 - t12 * t11;
    const T t22 = T(4) * t21 * t10 * b - T(3) * t10 * t19 - T(6) * c * t18;
    G_ap = (T(1) / T(3)) * in.w[1] * t21 * t10 + (T(1) / T(6)) * t10 * in.w[2] * t22 + t18 * in.w[0];
    G_ab = (T(1) / T(6)) * in.w[1] * t10 * t22 + (T(1) / T(3)) * t21 * t10 * in.w[0] + (T(1) / T(6)) * (T(3) * t20 * t10 + T(2) * t10 * b * t22 - T(2) * c * t21 * t10) * t10 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / D;
    const T t24 = T(1) / r1;
    const T t25 = T(1) / r0;
    const T t26 = t24 * a_minus_b + t25 * b;
    const T t27 = t25 + t23 * b * t26 - t24;
    const T t28 = T(1) / a;
    F = t23 * t26 * in.w[0] + in.w[1] * t27 * t28 - (c * t23 * t26 - J1 - T(2) * t27 * t28 * b) * t28 * in.w[2];
    const T t29 = t24 * t24;
    const T t30 = t29 * t24 * a_minus_b;
    const T t31 = t25 * t25;
    const T t32 = t31 * t25 * b;
    const T t33 = t30 + t32 + T(2) * t23 * a * t26;
    const T t34 = t29 * t24 - t23 * t33 * b - t31 * t25;
    const T t35 = T(3) * t23 * t26 - c * t23 * t33 - T(2) * t28 * t34 * b;
    G_ap = (T(1) / T(3)) * t23 * t33 * in.w[0] + (T(1) / T(3)) * t28 * in.w[2] * t35 - (T(1) / T(3)) * in.w[1] * t28 * t34;
    G_ab = (T(1) / T(3)) * in.w[1] * t28 * t35 + (T(1) / T(3)) * (c * t28 * t34 + T(3) * t27 * t28 + T(2) * t28 * t35 * b) * t28 * in.w[2] - (T(1) / T(3)) * t28 * t34 * in.w[0];
  }
  const T g_factor = -T(3) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
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
    X = t1 * t2 * (t3 + b * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = -t4 * (b - a_minus_b) / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  const T t8 = -b * a_minus_b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t10 = T(1) / a;
    const T t11 = J_downward<T>(T(3), a, D, -b, c, a_minus_b, q1);
    const T t12 = T(1) / r0;
    const T t13 = T(1) / r1;
    const T t14 = t11 * b + t12 - t13;
    const T t15 = J1 + T(2) * t10 * t14 * b - t11 * c;
    const T t16 = r0 - r1 - J1 * b;
    F = t10 * t14 * in.w[1] + in.w[2] * t10 * t15 + t11 * in.w[0] - t10 * (t10 * t14 * c + t10 * t16 - T(2) * t10 * b * t15) * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / D;
    const T t18 = T(1) / r0;
    const T t19 = T(1) / r1;
    const T t20 = t18 * b + t19 * a_minus_b;
    const T t21 = T(1) / a;
    const T t22 = t18 + t17 * t20 * b - t19;
    const T t23 = J1 + T(2) * t22 * t21 * b - t17 * t20 * c;
    const T t24 = r0 - r1 - J1 * b;
    F = t17 * t20 * in.w[0] + t21 * in.w[3] * (T(2) * t21 * t23 * b - t21 * t24 - t22 * t21 * c) + t22 * t21 * in.w[1] + in.w[2] * t21 * t23;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = a_minus_b * r0;
    X = t1 * t2 * (t3 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = t4 * (a_minus_b - b) / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = -b;
    const T t11 = J_downward<T>(T(5), a, D, t10, c, a_minus_b, q1);
    const T t12 = T(1) / a;
    const T t13 = T(1) / r0;
    const T t14 = t13 * t13;
    const T t15 = t13 * t14;
    const T t16 = T(1) / r1;
    const T t17 = t16 * t16;
    const T t18 = T(3) * t11 * b + t15 - t16 * t17;
    const T t19 = T(3) * D * t11 - t16 * a_minus_b * t17 - b * t13 * t14;
    const T t20 = T(4) * t12 * t18 * b + T(3) * t12 * t19 - T(6) * t11 * c;
    const T t21 = T(2) * t13 + t12 * b * t19 - T(2) * t16;
    const T t22 = T(2) * t20 * t12 * b + T(3) * t12 * t21 - T(2) * t12 * t18 * c;
    G_ap = t11 * in.w[0] + (T(1) / T(3)) * t12 * t18 * in.w[1] + (T(1) / T(6)) * t22 * t12 * in.w[3] + (T(1) / T(6)) * t20 * t12 * in.w[2];
    G_ab = (T(1) / T(6)) * t22 * t12 * in.w[2] + (T(1) / T(6)) * t20 * t12 * in.w[1] + (T(1) / T(3)) * t12 * t18 * in.w[0] - (T(1) / T(6)) * (T(3) * t12 * (t12 * t19 * c - T(2) * t12 * t21 * b - T(2) * J1) + t20 * t12 * c - T(2) * t22 * t12 * b) * t12 * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t23 = T(1) / a;
    const T t24 = T(1) / D;
    const T t25 = T(1) / r0;
    const T t26 = T(1) / r1;
    const T t27 = b * t25 + t26 * a_minus_b;
    const T t28 = t26 * t26;
    const T t29 = t25 * t25;
    const T t30 = t26 * a_minus_b * t28 + T(2) * t24 * a * t27 + b * t25 * t29;
    const T t31 = t25 * t29;
    const T t32 = t24 * b * t30 + t31 - t26 * t28;
    const T t33 = T(3) * t24 * t27 + T(2) * t23 * b * t32 - t24 * t30 * c;
    const T t34 = t25 + t24 * t27 * b - t26;
    const T t35 = t23 * c * t32 - T(2) * t23 * b * t33 - T(3) * t23 * t34;
    G_ap = (T(1) / T(3)) * t23 * t33 * in.w[2] + (T(1) / T(3)) * t23 * in.w[1] * t32 + (T(1) / T(3)) * t24 * in.w[0] * t30 - (T(1) / T(3)) * t23 * t35 * in.w[3];
    G_ab = (T(1) / T(3)) * t23 * in.w[0] * t32 + (T(1) / T(3)) * t23 * in.w[1] * t33 - (T(1) / T(3)) * t23 * in.w[3] * (T(2) * t23 * t35 * b + t23 * t33 * c - T(3) * t23 * (T(2) * t23 * t34 * b + J1 - t24 * t27 * c)) - (T(1) / T(3)) * t23 * t35 * in.w[2];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = a_minus_b * r0;
    const T t2 = T(1) / D;
    const T t3 = sqrt(a);
    X = (t1 + r1 * b) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = (a_minus_b - b) * t4 / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = -a_minus_b * b;
  const T t9 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0) && t9 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t10 = -b;
    const T t11 = J_downward<T>(T(5), a, D, t10, c, a_minus_b, q1);
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = T(1) / r1;
    const T t15 = t14 * t14;
    const T t16 = T(3) * t11 * D - b * t13 * t12 - t14 * a_minus_b * t15;
    const T t17 = T(1) / a;
    const T t18 = b * t16 * t17 + T(2) * t12 - T(2) * t14;
    const T t19 = t16 * c * t17 - T(2) * J1 - T(2) * b * t18 * t17;
    const T t20 = r1 + b * J1 - r0;
    F = (T(1) / T(2)) * t16 * t17 * in.w[0] + (T(1) / T(2)) * in.w[1] * t18 * t17 - (T(1) / T(2)) * (T(2) * b * t19 * t17 + c * t18 * t17 - T(2) * t20 * t17) * in.w[3] * t17 - (T(1) / T(2)) * t19 * in.w[2] * t17;
    const T t21 = t13 * t12;
    const T t22 = T(3) * t11 * b + t21 - t14 * t15;
    const T t23 = T(3) * t16 * t17 + T(4) * b * t22 * t17 - T(6) * t11 * c;
    const T t24 = T(2) * b * t23 * t17 + T(3) * t18 * t17 - T(2) * t22 * c * t17;
    G_ap = (T(1) / T(6)) * t24 * in.w[3] * t17 + (T(1) / T(6)) * t23 * in.w[2] * t17 + t11 * in.w[0] + (T(1) / T(3)) * in.w[1] * t22 * t17;
    G_ab = (T(1) / T(6)) * in.w[1] * t23 * t17 + (T(1) / T(3)) * t22 * t17 * in.w[0] + (T(1) / T(6)) * (T(2) * b * t24 * t17 - T(3) * t19 * t17 - t23 * c * t17) * in.w[3] * t17 + (T(1) / T(6)) * t24 * in.w[2] * t17;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t25 = T(1) / r0;
    const T t26 = T(1) / r1;
    const T t27 = b * t25 + t26 * a_minus_b;
    const T t28 = T(1) / D;
    const T t29 = T(1) / a;
    const T t30 = b * t27 * t28 + t25 - t26;
    const T t31 = c * t27 * t28 - J1 - T(2) * b * t29 * t30;
    const T t32 = r1 + b * J1 - r0;
    F = t27 * t28 * in.w[0] + in.w[1] * t29 * t30 - in.w[2] * t31 * t29 - (c * t29 * t30 + T(2) * b * t31 * t29 - t32 * t29) * in.w[3] * t29;
    const T t33 = t25 * t25;
    const T t34 = t26 * t26;
    const T t35 = b * t33 * t25 + T(2) * t27 * t28 * a + t26 * a_minus_b * t34;
    const T t36 = t33 * t25;
    const T t37 = t35 * b * t28 + t36 - t26 * t34;
    const T t38 = T(2) * t37 * b * t29 + T(3) * t27 * t28 - t35 * c * t28;
    const T t39 = T(2) * b * t38 * t29 + T(3) * t29 * t30 - t37 * c * t29;
    G_ap = (T(1) / T(3)) * t37 * in.w[1] * t29 + (T(1) / T(3)) * t38 * in.w[2] * t29 + (T(1) / T(3)) * t35 * t28 * in.w[0] + (T(1) / T(3)) * t39 * in.w[3] * t29;
    G_ab = (T(1) / T(3)) * in.w[1] * t38 * t29 + (T(1) / T(3)) * (T(2) * t39 * b * t29 - t38 * c * t29 - T(3) * t31 * t29) * in.w[3] * t29 + (T(1) / T(3)) * t39 * in.w[2] * t29 + (T(1) / T(3)) * t37 * t29 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    F = (T(1) / T(2)) * t4 * in.w[0] * (b / c + a_minus_b / q1 + a * J2);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 40 +, 71 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    const T t9 = T(3) * a * t4 * (t5 * a_minus_b + b * t6 + J2 * a) + T(2) * b * t7 + T(2) * t8 * a_minus_b;
    G_ap = (T(1) / T(8)) * t9 * t4 * in.w[0];
    G_ab = (T(1) / T(8)) * (b * t9 * t4 + T(2) * t7 - T(2) * t8) * in.w[0] / a;
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 40 +, 75 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = T(1) / q1;
    const T t6 = t4 * b + t5 * a_minus_b + J2 * a;
    const T t7 = T(1) / D;
    F = (T(1) / T(2)) * t6 * in.w[0] * t7;
    const T t8 = t4 * t4;
    const T t9 = t5 * t5;
    const T t10 = T(3) * t6 * t7 * a + T(2) * t8 * b + T(2) * t9 * a_minus_b;
    G_ap = (T(1) / T(8)) * t10 * in.w[0] * t7;
    G_ab = -(T(1) / T(8)) * in.w[0] * (T(2) * t9 - t10 * t7 * b - T(2) * t8) / a;
  }
  const T g_factor = -T(4) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 36 +, 50 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = T(1) / q1;
    const T t6 = t4 * b + a_minus_b * t5 + a * J2;
    const T t7 = T(1) / D;
    F = (T(1) / T(2)) * (t4 + t6 * t7 * b - t5) * in.w[1] / a + (T(1) / T(2)) * t6 * in.w[0] * t7;
  }
  f = F * length;
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = b * t5 + a * J2 + t7 * a_minus_b;
    const T t10 = T(1) / D;
    const T t11 = T(2) * t8 * a_minus_b + T(3) * a * t9 * t10 + T(2) * b * t6;
    const T t12 = T(2) * t6 + t11 * b * t10 - T(2) * t8;
    G_ap = (T(1) / T(8)) * in.w[1] * t4 * t12 + (T(1) / T(8)) * t11 * in.w[0] * t10;
    G_ab = (T(1) / T(8)) * in.w[1] * t4 * (T(4) * t9 * t10 + T(2) * t4 * b * t12 - t11 * c * t10) + (T(1) / T(8)) * t4 * in.w[0] * t12;
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = T(1) / q1;
    const T t6 = t4 * b + a_minus_b * t5 + J2 * a;
    const T t7 = T(1) / D;
    const T t8 = T(1) / a;
    F = (T(1) / T(2)) * t6 * in.w[0] * t7 + (T(1) / T(2)) * in.w[1] * t8 * (t6 * t7 * b + t4 - t5);
    const T t9 = t5 * t5;
    const T t10 = t4 * t4;
    const T t11 = T(3) * t6 * t7 * a + T(2) * a_minus_b * t9 + T(2) * t10 * b;
    const T t12 = t7 * b * t11 + T(2) * t10 - T(2) * t9;
    G_ap = (T(1) / T(8)) * in.w[1] * t8 * t12 + (T(1) / T(8)) * in.w[0] * t7 * t11;
    G_ab = (T(1) / T(8)) * in.w[0] * t8 * t12 + (T(1) / T(8)) * (T(2) * t8 * b * t12 + T(4) * t6 * t7 - c * t7 * t11) * in.w[1] * t8;
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / q1;
    const T t5 = T(1) / c;
    const T t6 = t4 * a_minus_b + a * J2 + t5 * b;
    const T t7 = T(1) / D;
    const T t8 = T(1) / a;
    const T t9 = t4 - t6 * t7 * b - t5;
    F = (T(1) / T(2)) * t6 * t7 * in.w[0] - (T(1) / T(2)) * (c * t6 * t7 + T(2) * t8 * b * t9 - T(2) * J2) * in.w[2] * t8 - (T(1) / T(2)) * in.w[1] * t8 * t9;
  }
  f = length * F;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = a * J2 + b * t7 + a_minus_b * t5;
    const T t10 = T(2) * a_minus_b * t6 + T(2) * b * t8 + T(3) * t4 * a * t9;
    const T t11 = T(1) / a;
    const T t12 = T(2) * t6 - t4 * t10 * b - T(2) * t8;
    const T t13 = T(2) * t11 * b * t12 + t4 * t10 * c - T(4) * t4 * t9;
    G_ap = (T(1) / T(8)) * t4 * t10 * in.w[0] - (T(1) / T(8)) * t11 * in.w[2] * t13 - (T(1) / T(8)) * in.w[1] * t11 * t12;
    G_ab = (T(1) / T(8)) * t11 * in.w[2] * (T(4) * t11 * (t7 + t4 * t9 * b - t5) + t11 * t12 * c - T(2) * t11 * b * t13) - (T(1) / T(8)) * in.w[1] * t11 * t13 - (T(1) / T(8)) * t11 * t12 * in.w[0];
  }
  const T g_factor = -T(4) * in.s * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t2 = T(1) / q1;
    const T t3 = T(1) / a;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t2 * t2;
    const T t7 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t8 = b * t5 + a_minus_b * t6 - T(4) * D * t7;
    const T t9 = T(3) * t2 + T(2) * t3 * t8 * b - T(3) * t4;
    F = -(T(1) / T(6)) * in.w[1] * t9 * t3 - (T(1) / T(3)) * t3 * in.w[2] * (t9 * t3 * b + (T(3) * a_minus_b * t2 + T(3) * b * t4 + T(2) * D * t3 * t8) * t3 - t3 * t8 * c) - (T(1) / T(3)) * t3 * t8 * in.w[0];
    const T t10 = T(4) * b * t7 + t5 - t6;
    const T t11 = T(3) * t10 * t3 * b - T(6) * c * t7 - T(2) * t3 * t8;
    G_ap = (T(1) / T(4)) * in.w[1] * t10 * t3 + in.w[0] * t7 + (T(1) / T(6)) * t11 * t3 * in.w[2];
    G_ab = (T(1) / T(4)) * t10 * t3 * in.w[0] + (T(1) / T(6)) * in.w[1] * t11 * t3 - (T(1) / T(12)) * (T(2) * t9 * t3 + T(3) * t10 * t3 * c - T(4) * t11 * t3 * b) * t3 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = t13 * atan2(t12, c_minus_b);
    const T t14 = T(1) / a;
    const T t15 = T(1) / q1;
    const T t16 = T(1) / c;
    const T t17 = a_minus_b * t15 + J2 * a + b * t16;
    const T t18 = T(1) / D;
    const T t19 = t17 * t18 * b + t16 - t15;
    F = (T(1) / T(2)) * in.w[1] * t14 * t19 + (T(1) / T(2)) * t17 * t18 * in.w[0] + (T(1) / T(2)) * t14 * in.w[2] * (T(2) * J2 + T(2) * t14 * b * t19 - t17 * t18 * c);
    const T t20 = t16 * t16;
    const T t21 = t15 * t15;
    const T t22 = T(2) * b * t20 + T(2) * a_minus_b * t21 + T(3) * t17 * t18 * a;
    const T t23 = t18 * t22 * b + T(2) * t20 - T(2) * t21;
    const T t24 = t18 * t22 * c - T(4) * t17 * t18 - T(2) * t14 * b * t23;
    G_ap = (T(1) / T(8)) * in.w[1] * t14 * t23 + (T(1) / T(8)) * t18 * t22 * in.w[0] - (T(1) / T(8)) * t14 * in.w[2] * t24;
    G_ab = (T(1) / T(8)) * t14 * in.w[0] * t23 + (T(1) / T(8)) * t14 * in.w[2] * (T(4) * t14 * t19 - T(2) * t14 * b * t24 - t14 * t23 * c) - (T(1) / T(8)) * in.w[1] * t14 * t24;
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(t0 * q1);
  T F;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(T(4), a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = t0 + T(2) * b * t4 - t5;
    const T t7 = a_minus_b * t5;
    const T t8 = b * t0;
    const T t9 = t7 + t8 - T(2) * t4 * D;
    const T t10 = b * t6 * t3 - t9 * t3 - c * t4;
    F = in.w[2] * t3 * t10 + (T(1) / T(2)) * in.w[1] * t6 * t3 + (T(1) / T(2)) * in.w[3] * t3 * (T(4) * b * t3 * t10 - (T(2) * b * t9 * t3 - log_ratio) * t3 - t6 * c * t3) + t4 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / q1;
    const T t14 = a_minus_b * t13;
    const T t15 = b * t0;
    const T t16 = t14 + t15 + a * J2;
    const T t17 = T(1) / D;
    const T t18 = t0 + b * t16 * t17 - t13;
    const T t19 = T(1) / a;
    const T t20 = c * t16 * t17 - T(2) * b * t18 * t19 - T(2) * J2;
    F = (T(1) / T(2)) * in.w[1] * t18 * t19 + (T(1) / T(2)) * t16 * t17 * in.w[0] - (T(1) / T(2)) * t20 * in.w[2] * t19 - (T(1) / T(2)) * (t18 * c * t19 + T(2) * b * t20 * t19 - (log_ratio + T(2) * b * J2) * t19) * in.w[3] * t19;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2];
    G_ab = in.w[3] * M_beyond[4] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = a_minus_b * t7 + b * t5 + a * J2;
    const T t9 = t7 * t7;
    const T t10 = T(2) * b * t6 + T(3) * t4 * a * t8 + T(2) * a_minus_b * t9;
    const T t11 = T(1) / a;
    const T t12 = t4 * b * t10 + T(2) * t6 - T(2) * t9;
    const T t13 = T(2) * t11 * b * t12 + T(4) * t4 * t8 - t4 * t10 * c;
    const T t14 = t7 - t5 - t4 * t8 * b;
    const T t15 = T(4) * t11 * t14 + t11 * c * t12 - T(2) * t11 * t13 * b;
    G_ap = (T(1) / T(8)) * t4 * in.w[0] * t10 + (T(1) / T(8)) * t11 * t13 * in.w[2] + (T(1) / T(8)) * t11 * in.w[1] * t12 - (T(1) / T(8)) * t11 * t15 * in.w[3];
    G_ab = (T(1) / T(8)) * t11 * in.w[0] * t12 + (T(1) / T(8)) * t11 * t13 * in.w[1] - (T(1) / T(8)) * t11 * t15 * in.w[2] - (T(1) / T(8)) * t11 * in.w[3] * (T(2) * t11 * t15 * b + T(4) * (t4 * t8 * c + T(2) * t11 * t14 * b - T(2) * J2) * t11 + t11 * t13 * c);
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t0 * t0;
    const T t7 = J_downward<T>(T(6), a, D, -b, c, a_minus_b, q1);
    const T t8 = a_minus_b * t5 + b * t6 - T(4) * t7 * D;
    const T t9 = T(2) * b * t3 * t8 + T(3) * t4 - T(3) * t0;
    const T t10 = T(2) * D * t3 * t8 + T(3) * b * t0 + T(3) * a_minus_b * t4;
    const T t11 = t10 * t3 + b * t9 * t3 - c * t3 * t8;
    F = (T(1) / T(6)) * (c * t9 * t3 + t3 * (T(3) * log_ratio - T(2) * b * t10 * t3) - T(4) * b * t11 * t3) * in.w[3] * t3 - (T(1) / T(3)) * t3 * t8 * in.w[0] - (T(1) / T(3)) * in.w[2] * t11 * t3 - (T(1) / T(6)) * in.w[1] * t9 * t3;
    const T t12 = t6 + T(4) * t7 * b - t5;
    const T t13 = T(6) * t7 * c + T(2) * t3 * t8 - T(3) * b * t12 * t3;
    const T t14 = T(4) * b * t3 * t13 + T(3) * c * t12 * t3 + T(2) * t9 * t3;
    G_ap = (T(1) / T(4)) * in.w[1] * t12 * t3 + t7 * in.w[0] - (T(1) / T(6)) * in.w[2] * t3 * t13 - (T(1) / T(12)) * t14 * in.w[3] * t3;
    G_ab = (T(1) / T(4)) * t12 * t3 * in.w[0] - (T(1) / T(6)) * (b * t14 * t3 + T(2) * t11 * t3 - c * t3 * t13) * in.w[3] * t3 - (T(1) / T(6)) * in.w[1] * t3 * t13 - (T(1) / T(12)) * in.w[2] * t14 * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t15 = sqrt(D);
    const T t16 = T(1) / t15;
    const T J2 = atan2(t15, c_minus_b) * t16;
    const T t17 = T(1) / D;
    const T t18 = T(1) / q1;
    const T t19 = J2 * a + b * t0 + a_minus_b * t18;
    const T t20 = T(1) / a;
    const T t21 = t18 - t0 - b * t17 * t19;
    const T t22 = c * t17 * t19 + T(2) * b * t21 * t20 - T(2) * J2;
    F = (T(1) / T(2)) * t17 * t19 * in.w[0] + (T(1) / T(2)) * ((log_ratio + T(2) * b * J2) * t20 + t21 * c * t20 - T(2) * b * t22 * t20) * in.w[3] * t20 - (T(1) / T(2)) * t22 * in.w[2] * t20 - (T(1) / T(2)) * in.w[1] * t21 * t20;
    const T t23 = t0 * t0;
    const T t24 = t18 * t18;
    const T t25 = T(3) * t17 * t19 * a + T(2) * a_minus_b * t24 + T(2) * b * t23;
    const T t26 = T(2) * t23 + b * t25 * t17 - T(2) * t24;
    const T t27 = T(4) * t17 * t19 + T(2) * t26 * b * t20 - t25 * c * t17;
    const T t28 = t26 * c * t20 + T(4) * t21 * t20 - T(2) * t27 * b * t20;
    G_ap = (T(1) / T(8)) * t27 * in.w[2] * t20 + (T(1) / T(8)) * t26 * in.w[1] * t20 + (T(1) / T(8)) * t25 * t17 * in.w[0] - (T(1) / T(8)) * in.w[3] * t20 * t28;
    G_ab = (T(1) / T(8)) * t26 * t20 * in.w[0] + (T(1) / T(8)) * t27 * in.w[1] * t20 - (T(1) / T(8)) * (T(2) * b * t20 * t28 + T(4) * t22 * t20 + t27 * c * t20) * in.w[3] * t20 - (T(1) / T(8)) * in.w[2] * t20 * t28;
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    F = (T(1) / T(3)) * t2 * in.w[0] * (t3 * a_minus_b / q1 + T(2) * t2 * a * (t3 * a_minus_b + t4 * b) + t4 * b / c);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 38 +, 78 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(3) * t5 * t3 * a_minus_b + T(3) * b * t6 * t8 + T(4) * (T(2) * (t3 * a_minus_b + b * t6) * t2 * a + t4 * t3 * a_minus_b + b * t6 * t7) * t2 * a;
    G_ap = (T(1) / T(15)) * in.w[0] * t2 * t9;
    G_ab = (T(1) / T(15)) * in.w[0] * (T(3) * t6 * t8 + b * t2 * t9 - T(3) * t5 * t3) / a;
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 38 +, 82 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = a_minus_b * t3 * t4 + t5 * b * t6 + T(2) * t2 * a * (a_minus_b * t3 + t5 * b);
    F = (T(1) / T(3)) * t2 * in.w[0] * t7;
    const T t8 = t6 * t6;
    const T t9 = t4 * t4;
    const T t10 = T(3) * t5 * b * t8 + T(3) * a_minus_b * t3 * t9 + T(4) * t2 * a * t7;
    G_ap = (T(1) / T(15)) * t2 * in.w[0] * t10;
    G_ab = (T(1) / T(15)) * in.w[0] * (T(3) * t5 * t8 + t2 * b * t10 - T(3) * t3 * t9) / a;
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 34 +, 55 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t3 * t3;
    const T t7 = T(2) * t2 * (a_minus_b * t3 + t4 * b) * a + t5 * t4 * b + a_minus_b * t6 * t3;
    F = (T(1) / T(3)) * t2 * in.w[0] * t7 - (T(1) / T(3)) * (t6 * t3 - t2 * b * t7 - t5 * t4) * in.w[1] / a;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(2) * t2 * a * (t6 * b + a_minus_b * t3) + t6 * t7 * b + a_minus_b * t3 * t4;
    const T t10 = T(3) * a_minus_b * t3 * t5 + T(3) * t6 * t8 * b + T(4) * t2 * t9 * a;
    const T t11 = T(3) * t3 * t5 - T(3) * t6 * t8 - t2 * t10 * b;
    const T t12 = T(1) / a;
    G_ap = (T(1) / T(15)) * in.w[0] * t2 * t10 - (T(1) / T(15)) * t11 * t12 * in.w[1];
    G_ab = -(T(1) / T(15)) * (c * t2 * t10 + T(2) * t11 * t12 * b - T(5) * t2 * t9) * t12 * in.w[1] - (T(1) / T(15)) * t11 * in.w[0] * t12;
  }
  const T g_factor = -T(5) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = t3 * t2 * a_minus_b + t5 * t4 * b + T(2) * t6 * a * (t4 * b + t2 * a_minus_b);
    const T t8 = T(1) / a;
    F = (T(1) / T(3)) * t7 * in.w[0] * t6 - (T(1) / T(3)) * in.w[1] * t8 * (t3 * t2 - t5 * t4 - t7 * t6 * b);
    const T t9 = t5 * t5;
    const T t10 = t3 * t3;
    const T t11 = T(4) * t7 * t6 * a + T(3) * t9 * t4 * b + T(3) * t10 * t2 * a_minus_b;
    const T t12 = t11 * t6 * b + T(3) * t9 * t4 - T(3) * t10 * t2;
    G_ap = (T(1) / T(15)) * in.w[0] * t11 * t6 + (T(1) / T(15)) * in.w[1] * t8 * t12;
    G_ab = (T(1) / T(15)) * (T(2) * t8 * t12 * b + T(5) * t7 * t6 - c * t11 * t6) * in.w[1] * t8 + (T(1) / T(15)) * in.w[0] * t8 * t12;
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t5 * b + t3 * a_minus_b;
    const T t8 = t4 * t3 * a_minus_b + t5 * b * t6 + T(2) * a * t2 * t7;
    const T t9 = T(1) / a;
    const T t10 = t4 * t3 - t5 * t6 - t2 * t8 * b;
    F = (T(1) / T(3)) * t2 * t8 * in.w[0] - (T(1) / T(3)) * t9 * t10 * in.w[1] - (T(1) / T(3)) * t9 * in.w[2] * (T(2) * t9 * t10 * b + t2 * t8 * c - T(3) * t2 * t7);
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
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
    G_ab = in.w[2] * M_beyond[3] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = T(1) / r1;
    const T t4 = T(1) / D;
    const T t5 = t2 * t2;
    const T t6 = t3 * t3;
    const T t7 = T(2) * (b * t2 + a_minus_b * t3) * t4 * a + b * t2 * t5 + t6 * a_minus_b * t3;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    const T t10 = T(4) * t7 * t4 * a + T(3) * t8 * a_minus_b * t3 + T(3) * b * t2 * t9;
    const T t11 = T(3) * t2 * t9 + b * t10 * t4 - T(3) * t8 * t3;
    const T t12 = T(1) / a;
    const T t13 = T(2) * b * t11 * t12 + T(5) * t7 * t4 - t10 * c * t4;
    G_ap = (T(1) / T(15)) * in.w[0] * t10 * t4 + (T(1) / T(15)) * in.w[2] * t13 * t12 + (T(1) / T(15)) * in.w[1] * t11 * t12;
    G_ab = (T(1) / T(15)) * t13 * in.w[1] * t12 + (T(1) / T(15)) * in.w[2] * (T(5) * (b * t7 * t4 + t2 * t5 - t6 * t3) * t12 + T(2) * b * t13 * t12 - c * t11 * t12) * t12 + (T(1) / T(15)) * in.w[0] * t11 * t12;
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ap = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4] + in.w[2] * M_beyond[6];
    G_ab = M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = t5 * a_minus_b + b * t2;
    const T t7 = t5 * t5;
    const T t8 = b * t3 * t2 + T(2) * t4 * a * t6 + t7 * t5 * a_minus_b;
    const T t9 = t3 * t2 + b * t8 * t4 - t7 * t5;
    const T t10 = T(1) / a;
    F = (T(1) / T(3)) * in.w[0] * t8 * t4 + (T(1) / T(3)) * (T(3) * t4 * t6 + T(2) * b * t9 * t10 - t8 * c * t4) * in.w[2] * t10 + (T(1) / T(3)) * t9 * in.w[1] * t10;
    const T t11 = t7 * t7;
    const T t12 = t3 * t3;
    const T t13 = T(4) * t8 * t4 * a + T(3) * t11 * t5 * a_minus_b + T(3) * b * t12 * t2;
    const T t14 = b * t13 * t4 + T(3) * t12 * t2 - T(3) * t11 * t5;
    const T t15 = T(2) * b * t14 * t10 + T(5) * t8 * t4 - c * t13 * t4;
    G_ap = (T(1) / T(15)) * in.w[0] * t13 * t4 + (T(1) / T(15)) * in.w[2] * t10 * t15 + (T(1) / T(15)) * t14 * in.w[1] * t10;
    G_ab = (T(1) / T(15)) * in.w[1] * t10 * t15 + (T(1) / T(15)) * in.w[0] * t14 * t10 - (T(1) / T(15)) * in.w[2] * t10 * (c * t14 * t10 - T(2) * b * t10 * t15 - T(5) * t9 * t10);
  }
  const T g_factor = -T(5) * length * in.s;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t3 * b + t5 * a_minus_b;
    const T t8 = t3 * b * t4 + t6 * t5 * a_minus_b + T(2) * t2 * a * t7;
    const T t9 = T(1) / a;
    const T t10 = t3 * t4 + t2 * t8 * b - t6 * t5;
    const T t11 = t2 * t8 * c - T(3) * t2 * t7 - T(2) * t9 * b * t10;
    F = (T(1) / T(3)) * t2 * t8 * in.w[0] + (T(1) / T(3)) * t9 * in.w[1] * t10 - (T(1) / T(3)) * in.w[3] * t9 * (T(2) * t9 * t11 * b + t9 * t10 * c - T(3) * t9 * (t3 + t2 * b * t7 - t5)) - (T(1) / T(3)) * t9 * t11 * in.w[2];
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t3 * a_minus_b + t7 * b;
    const T t11 = t3 * a_minus_b * t4 + T(2) * t10 * a * t6 + t7 * t8 * b;
    const T t12 = T(3) * t7 * t9 * b + T(3) * t3 * a_minus_b * t5 + T(4) * t11 * a * t6;
    const T t13 = T(3) * t3 * t5 - t6 * t12 * b - T(3) * t7 * t9;
    const T t14 = t7 * t8 + t11 * t6 * b - t3 * t4;
    const T t15 = c * t6 * t12 + T(2) * t13 * t2 * b - T(5) * t11 * t6;
    const T t16 = c * t13 * t2 + T(5) * t2 * t14 - T(2) * t15 * t2 * b;
    G_ap = (T(1) / T(15)) * t2 * in.w[3] * t16 + (T(1) / T(15)) * t6 * in.w[0] * t12 - (T(1) / T(15)) * t15 * in.w[2] * t2 - (T(1) / T(15)) * in.w[1] * t13 * t2;
    G_ab = (T(1) / T(15)) * (T(5) * (T(2) * t2 * b * t14 + T(3) * t10 * t6 - c * t11 * t6) * t2 + T(2) * t2 * t16 * b + t15 * c * t2) * t2 * in.w[3] + (T(1) / T(15)) * in.w[2] * t2 * t16 - (T(1) / T(15)) * in.w[1] * t15 * t2 - (T(1) / T(15)) * t13 * t2 * in.w[0];
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t2 = T(1) / a;
    const T t3 = J_downward<T>(T(7), a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(5) * t3 * D - b * t6 * t4 - t7 * a_minus_b * t9;
    const T t11 = T(3) * t10 * D * t2 - T(4) * t7 * a_minus_b * t8 - T(4) * b * t5 * t4;
    const T t12 = T(3) * b * t10 * t2 + T(4) * t5 * t4 - T(4) * t7 * t8;
    const T t13 = T(3) * t11 * t2 + T(4) * b * t12 * t2 - T(6) * c * t10 * t2;
    F = (T(1) / T(24)) * in.w[3] * (T(2) * b * t2 * t13 + T(3) * (T(8) * t4 + b * t11 * t2 - T(8) * t7) * t2 - T(2) * c * t12 * t2) * t2 + (T(1) / T(4)) * in.w[0] * t10 * t2 + (T(1) / T(24)) * in.w[2] * t2 * t13 + (T(1) / T(12)) * in.w[1] * t12 * t2;
    const T t14 = t7 * t9 - t6 * t4 - T(5) * b * t3;
    const T t15 = T(20) * c * t3 + T(8) * t14 * b * t2 - T(5) * t10 * t2;
    const T t16 = T(6) * b * t15 * t2 - T(12) * t14 * c * t2 - T(5) * t12 * t2;
    G_ap = in.w[0] * t3 - (T(1) / T(60)) * in.w[3] * t16 * t2 - (T(1) / T(20)) * t15 * in.w[2] * t2 - (T(1) / T(5)) * t14 * in.w[1] * t2;
    G_ab = (T(1) / T(120)) * in.w[3] * (T(6) * c * t15 * t2 + T(5) * t2 * t13 - T(4) * b * t16 * t2) * t2 - (T(1) / T(5)) * in.w[0] * t14 * t2 - (T(1) / T(20)) * in.w[1] * t15 * t2 - (T(1) / T(60)) * in.w[2] * t16 * t2;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / r0;
    const T t20 = t19 * t19;
    const T t21 = T(1) / D;
    const T t22 = t17 * a_minus_b + b * t19;
    const T t23 = t17 * a_minus_b * t18 + b * t20 * t19 + T(2) * t21 * t22 * a;
    const T t24 = T(1) / a;
    const T t25 = t23 * b * t21 + t20 * t19 - t17 * t18;
    const T t26 = t23 * c * t21 - T(3) * t21 * t22 - T(2) * b * t24 * t25;
    F = (T(1) / T(3)) * in.w[0] * t23 * t21 + (T(1) / T(3)) * in.w[1] * t24 * t25 - (T(1) / T(3)) * in.w[3] * (T(2) * b * t26 * t24 + c * t24 * t25 - T(3) * (t19 + b * t21 * t22 - t17) * t24) * t24 - (T(1) / T(3)) * t26 * in.w[2] * t24;
    const T t27 = t20 * t20;
    const T t28 = t18 * t18;
    const T t29 = T(4) * t23 * t21 * a + T(3) * b * t27 * t19 + T(3) * t17 * a_minus_b * t28;
    const T t30 = T(3) * t17 * t28 - T(3) * t27 * t19 - b * t29 * t21;
    const T t31 = T(2) * b * t30 * t24 + t29 * c * t21 - T(5) * t23 * t21;
    const T t32 = T(2) * b * t31 * t24 - c * t30 * t24 - T(5) * t24 * t25;
    G_ap = (T(1) / T(15)) * in.w[0] * t29 * t21 - (T(1) / T(15)) * in.w[3] * t32 * t24 - (T(1) / T(15)) * t31 * in.w[2] * t24 - (T(1) / T(15)) * in.w[1] * t30 * t24;
    G_ab = -(T(1) / T(15)) * t32 * in.w[2] * t24 - (T(1) / T(15)) * in.w[3] * (T(2) * b * t32 * t24 + T(5) * t26 * t24 - c * t31 * t24) * t24 - (T(1) / T(15)) * in.w[0] * t30 * t24 - (T(1) / T(15)) * in.w[1] * t31 * t24;
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    F = (T(1) / T(8)) * in.w[0] * t4 * (T(2) * t6 * b + T(2) * a_minus_b * t8 + T(3) * t4 * a * (a * J2 + t5 * b + a_minus_b * t7));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 42 +, 80 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(8) * b * t7 + T(8) * a_minus_b * t10 + T(5) * t4 * a * (T(3) * (b * t5 + a_minus_b * t8 + a * J2) * t4 * a + T(2) * a_minus_b * t9 + T(2) * b * t6);
    G_ap = (T(1) / T(48)) * t4 * in.w[0] * t11;
    G_ab = (T(1) / T(48)) * in.w[0] * (t4 * b * t11 + T(8) * t7 - T(8) * t10) / a;
  }
  const T g_factor = -T(6) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 42 +, 84 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = T(2) * a_minus_b * t6 + T(2) * b * t8 + T(3) * t4 * (J2 * a + b * t7 + a_minus_b * t5) * a;
    F = (T(1) / T(8)) * in.w[0] * t4 * t9;
    const T t10 = t6 * t5;
    const T t11 = t8 * t7;
    const T t12 = T(8) * a_minus_b * t10 + T(8) * b * t11 + T(5) * t4 * t9 * a;
    G_ap = (T(1) / T(48)) * in.w[0] * t4 * t12;
    G_ab = (T(1) / T(48)) * in.w[0] * (t4 * b * t12 + T(8) * t11 - T(8) * t10) / a;
  }
  const T g_factor = -T(6) * length * in.s;
  f = length * F;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 38 +, 61 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = T(2) * b * t5 + T(3) * (a_minus_b * t6 + a * J2 + b * t4) * a * t7 + T(2) * a_minus_b * t8;
    F = (T(1) / T(8)) * t9 * in.w[0] * t7 + (T(1) / T(8)) * (t9 * b * t7 + T(2) * t5 - T(2) * t8) * in.w[1] / a;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
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
    const T t10 = T(2) * a_minus_b * t6 + T(2) * t9 * b + T(3) * (a * J2 + t8 * b + a_minus_b * t5) * t4 * a;
    const T t11 = t9 * t8;
    const T t12 = T(8) * a_minus_b * t7 + T(5) * t10 * t4 * a + T(8) * t11 * b;
    const T t13 = T(1) / a;
    const T t14 = t4 * t12 * b + T(8) * t11 - T(8) * t7;
    G_ap = (T(1) / T(48)) * in.w[0] * t4 * t12 + (T(1) / T(48)) * in.w[1] * t13 * t14;
    G_ab = (T(1) / T(48)) * in.w[0] * t13 * t14 + (T(1) / T(48)) * in.w[1] * t13 * (T(2) * t13 * t14 * b + T(6) * t10 * t4 - c * t4 * t12);
  }
  const T g_factor = -T(6) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[3] * in.w[0] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = T(2) * b * t5 + T(3) * (J2 * a + a_minus_b * t6 + b * t4) * t7 * a + T(2) * a_minus_b * t8;
    const T t10 = T(1) / a;
    F = (T(1) / T(8)) * (b * t9 * t7 + T(2) * t5 - T(2) * t8) * t10 * in.w[1] + (T(1) / T(8)) * t9 * in.w[0] * t7;
    const T t11 = t8 * t6;
    const T t12 = t5 * t4;
    const T t13 = T(8) * a_minus_b * t11 + T(8) * b * t12 + T(5) * t9 * t7 * a;
    const T t14 = T(8) * t11 - T(8) * t12 - b * t13 * t7;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t7 - (T(1) / T(48)) * t14 * t10 * in.w[1];
    G_ab = -(T(1) / T(48)) * (T(2) * b * t14 * t10 + c * t13 * t7 - T(6) * t9 * t7) * t10 * in.w[1] - (T(1) / T(48)) * t14 * in.w[0] * t10;
  }
  const T g_factor = -T(6) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / c;
    const T t7 = b * t6 + a * J2 + a_minus_b * t4;
    const T t8 = T(1) / D;
    const T t9 = t6 * t6;
    const T t10 = T(2) * a_minus_b * t5 + T(3) * t7 * t8 * a + T(2) * b * t9;
    const T t11 = T(2) * t5 - b * t10 * t8 - T(2) * t9;
    const T t12 = T(1) / a;
    F = (T(1) / T(8)) * in.w[0] * t10 * t8 - (T(1) / T(8)) * (T(2) * b * t11 * t12 + c * t10 * t8 - T(4) * t7 * t8) * t12 * in.w[2] - (T(1) / T(8)) * t11 * in.w[1] * t12;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = T(2) * b * t6 + T(2) * t9 * a_minus_b + T(3) * (t8 * a_minus_b + J2 * a + b * t5) * t4 * a;
    const T t11 = t9 * t8;
    const T t12 = T(8) * b * t7 + T(5) * t10 * t4 * a + T(8) * t11 * a_minus_b;
    const T t13 = b * t4 * t12 + T(8) * t7 - T(8) * t11;
    const T t14 = T(1) / a;
    const T t15 = T(2) * t13 * b * t14 + T(6) * t10 * t4 - c * t4 * t12;
    G_ap = (T(1) / T(48)) * t13 * in.w[1] * t14 + (T(1) / T(48)) * in.w[0] * t4 * t12 + (T(1) / T(48)) * t15 * in.w[2] * t14;
    G_ab = (T(1) / T(48)) * in.w[1] * t15 * t14 + (T(1) / T(48)) * t13 * in.w[0] * t14 - (T(1) / T(48)) * (t13 * c * t14 - T(6) * (b * t10 * t4 + T(2) * t6 - T(2) * t9) * t14 - T(2) * b * t15 * t14) * in.w[2] * t14;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[6] * in.w[2] + in.w[0] * M_beyond[4] + in.w[1] * M_beyond[5];
    G_ab = in.w[0] * M_beyond[5] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = J2 * a + a_minus_b * t5 + b * t6;
    const T t8 = T(1) / D;
    const T t9 = t6 * t6;
    const T t10 = t5 * t5;
    const T t11 = T(2) * b * t9 + T(2) * a_minus_b * t10 + T(3) * t7 * a * t8;
    const T t12 = T(2) * t9 + b * t11 * t8 - T(2) * t10;
    F = (T(1) / T(8)) * t4 * (T(4) * t7 * t8 + T(2) * t12 * b * t4 - t11 * c * t8) * in.w[2] + (T(1) / T(8)) * t11 * in.w[0] * t8 + (T(1) / T(8)) * t12 * in.w[1] * t4;
    const T t13 = t9 * t6;
    const T t14 = t10 * t5;
    const T t15 = T(8) * a_minus_b * t14 + T(8) * b * t13 + T(5) * t11 * a * t8;
    const T t16 = T(8) * t13 + b * t15 * t8 - T(8) * t14;
    const T t17 = T(2) * b * t4 * t16 + T(6) * t11 * t8 - t15 * c * t8;
    G_ap = (T(1) / T(48)) * t17 * t4 * in.w[2] + (T(1) / T(48)) * in.w[1] * t4 * t16 + (T(1) / T(48)) * t15 * in.w[0] * t8;
    G_ab = (T(1) / T(48)) * in.w[0] * t4 * t16 + (T(1) / T(48)) * (T(6) * t12 * t4 + T(2) * b * t17 * t4 - c * t4 * t16) * t4 * in.w[2] + (T(1) / T(48)) * t17 * in.w[1] * t4;
  }
  const T g_factor = -T(6) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t5 * a_minus_b + t7 * b + a * J2;
    const T t9 = t7 * t7;
    const T t10 = T(2) * t6 * a_minus_b + T(3) * t8 * t4 * a + T(2) * t9 * b;
    const T t11 = t4 * t10 * b + T(2) * t9 - T(2) * t6;
    const T t12 = T(1) / a;
    const T t13 = c * t4 * t10 - T(4) * t8 * t4 - T(2) * t11 * t12 * b;
    F = (T(1) / T(8)) * t4 * t10 * in.w[0] + (T(1) / T(8)) * t11 * t12 * in.w[1] - (T(1) / T(8)) * (T(2) * t12 * t13 * b + c * t11 * t12 + T(4) * (t5 - t7 - t8 * t4 * b) * t12) * in.w[3] * t12 - (T(1) / T(8)) * in.w[2] * t12 * t13;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1] + in.w[3] * M_beyond[4] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = a * J2 + t7 * a_minus_b + b * t5;
    const T t9 = T(1) / D;
    const T t10 = t7 * t7;
    const T t11 = T(2) * b * t6 + T(3) * a * t8 * t9 + T(2) * t10 * a_minus_b;
    const T t12 = t6 * t5;
    const T t13 = t10 * t7;
    const T t14 = T(8) * b * t12 + T(5) * a * t11 * t9 + T(8) * t13 * a_minus_b;
    const T t15 = T(8) * t12 + b * t14 * t9 - T(8) * t13;
    const T t16 = T(6) * t11 * t9 + T(2) * t4 * b * t15 - c * t14 * t9;
    const T t17 = T(2) * t6 + b * t11 * t9 - T(2) * t10;
    const T t18 = t4 * t15 * c - T(2) * t4 * b * t16 - T(6) * t4 * t17;
    G_ap = (T(1) / T(48)) * t4 * t16 * in.w[2] + (T(1) / T(48)) * t4 * in.w[1] * t15 + (T(1) / T(48)) * in.w[0] * t14 * t9 - (T(1) / T(48)) * t4 * in.w[3] * t18;
    G_ab = (T(1) / T(48)) * t4 * t16 * in.w[1] + (T(1) / T(48)) * t4 * in.w[3] * (T(6) * t4 * (T(4) * t8 * t9 + T(2) * t4 * b * t17 - t11 * c * t9) - T(2) * t4 * b * t18 - t4 * t16 * c) + (T(1) / T(48)) * t4 * in.w[0] * t15 - (T(1) / T(48)) * t4 * t18 * in.w[2];
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3];
    G_ap = M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2];
    G_ab = in.w[1] * M_beyond[7] + in.w[2] * M_beyond[8] + M_beyond[9] * in.w[3] + M_beyond[6] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = a_minus_b * t5 + b * t6 + J2 * a;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = T(3) * t4 * a * t7 + T(2) * a_minus_b * t8 + T(2) * b * t9;
    const T t11 = b * t4 * t10 + T(2) * t9 - T(2) * t8;
    const T t12 = T(1) / a;
    const T t13 = c * t4 * t10 - T(2) * b * t11 * t12 - T(4) * t4 * t7;
    F = (T(1) / T(8)) * in.w[1] * t11 * t12 + (T(1) / T(8)) * t4 * t10 * in.w[0] - (T(1) / T(8)) * in.w[2] * t12 * t13 - (T(1) / T(8)) * (t11 * c * t12 + T(2) * b * t12 * t13 - T(4) * (t6 + b * t4 * t7 - t5) * t12) * t12 * in.w[3];
    const T t14 = t9 * t6;
    const T t15 = t8 * t5;
    const T t16 = T(5) * t4 * a * t10 + T(8) * b * t14 + T(8) * a_minus_b * t15;
    const T t17 = b * t4 * t16 + T(8) * t14 - T(8) * t15;
    const T t18 = T(6) * t4 * t10 + T(2) * b * t12 * t17 - c * t4 * t16;
    const T t19 = c * t12 * t17 - T(6) * t11 * t12 - T(2) * b * t12 * t18;
    G_ap = (T(1) / T(48)) * t4 * t16 * in.w[0] + (T(1) / T(48)) * in.w[1] * t12 * t17 + (T(1) / T(48)) * in.w[2] * t12 * t18 - (T(1) / T(48)) * t12 * in.w[3] * t19;
    G_ab = (T(1) / T(48)) * in.w[1] * t12 * t18 + (T(1) / T(48)) * t12 * in.w[0] * t17 - (T(1) / T(48)) * t12 * in.w[3] * (c * t12 * t18 + T(2) * b * t12 * t19 + T(6) * t12 * t13) - (T(1) / T(48)) * in.w[2] * t12 * t19;
  }
  const T g_factor = -T(6) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    F = (T(1) / T(15)) * t2 * in.w[0] * (T(3) * t5 * a_minus_b * t3 + T(3) * t6 * b * t8 + T(4) * t2 * a * (t6 * b * t7 + t4 * a_minus_b * t3 + T(2) * t2 * a * (a_minus_b * t3 + t6 * b)));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 40 +, 89 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = T(5) * b * t2 * t5 + T(5) * t9 * t6 * a_minus_b + T(2) * (T(3) * b * t2 * t4 + T(3) * t8 * t6 * a_minus_b + T(4) * (t7 * t6 * a_minus_b + T(2) * (b * t2 + t6 * a_minus_b) * a * t10 + b * t2 * t3) * a * t10) * a * t10;
    G_ap = (T(1) / T(35)) * t11 * in.w[0] * t10;
    G_ab = -(T(1) / T(35)) * (T(5) * t9 * t6 - T(5) * t2 * t5 - b * t11 * t10) * in.w[0] / a;
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 40 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t4 * t4;
    const T t9 = T(4) * t2 * a * (t3 * a_minus_b * t4 + T(2) * (b * t5 + t3 * a_minus_b) * t2 * a + b * t6 * t5) + T(3) * b * t7 * t5 + T(3) * t3 * a_minus_b * t8;
    F = (T(1) / T(15)) * t2 * in.w[0] * t9;
    const T t10 = t7 * t6;
    const T t11 = t8 * t4;
    const T t12 = T(2) * t2 * a * t9 + T(5) * b * t10 * t5 + T(5) * t3 * a_minus_b * t11;
    G_ap = (T(1) / T(35)) * t2 * in.w[0] * t12;
    G_ab = (T(1) / T(35)) * in.w[0] * (T(5) * t10 * t5 + t2 * t12 * b - T(5) * t3 * t11) / a;
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 36 +, 68 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(3) * t2 * b * t4 + T(3) * t5 * a_minus_b * t7 + T(4) * (t5 * a_minus_b * t6 + t2 * b * t3 + T(2) * (t5 * a_minus_b + t2 * b) * t8 * a) * t8 * a;
    F = (T(1) / T(15)) * (T(3) * t2 * t4 + b * t9 * t8 - T(3) * t5 * t7) * in.w[1] / a + (T(1) / T(15)) * t9 * in.w[0] * t8;
  }
  f = length * F;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = T(3) * t4 * t2 * a_minus_b + T(4) * a * (b * t5 * t6 + t3 * t2 * a_minus_b + T(2) * a * (t2 * a_minus_b + b * t5) * t7) * t7 + T(3) * b * t5 * t8;
    const T t10 = t4 * t3;
    const T t11 = t8 * t6;
    const T t12 = T(2) * a * t9 * t7 + T(5) * t10 * t2 * a_minus_b + T(5) * b * t5 * t11;
    const T t13 = T(5) * t5 * t11 + t12 * b * t7 - T(5) * t10 * t2;
    const T t14 = T(1) / a;
    G_ap = (T(1) / T(35)) * t12 * in.w[0] * t7 + (T(1) / T(35)) * t13 * t14 * in.w[1];
    G_ab = (T(1) / T(35)) * t13 * t14 * in.w[0] + (T(1) / T(105)) * t14 * in.w[1] * (T(7) * t9 * t7 + T(6) * t13 * t14 * b - T(3) * t12 * c * t7);
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[3] * in.w[0] + in.w[1] * M_beyond[4];
    G_ab = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(3) * b * t5 * t3 + T(4) * t2 * (T(2) * t2 * (t6 * a_minus_b + b * t3) * a + t6 * a_minus_b * t7 + b * t4 * t3) * a + T(3) * t6 * a_minus_b * t8;
    const T t10 = T(1) / a;
    F = (T(1) / T(15)) * t2 * t9 * in.w[0] - (T(1) / T(15)) * in.w[1] * (T(3) * t6 * t8 - T(3) * t5 * t3 - t2 * t9 * b) * t10;
    const T t11 = t5 * t4;
    const T t12 = t8 * t7;
    const T t13 = T(5) * b * t11 * t3 + T(2) * t2 * t9 * a + T(5) * t6 * a_minus_b * t12;
    const T t14 = T(5) * t6 * t12 - t2 * b * t13 - T(5) * t11 * t3;
    G_ap = (T(1) / T(35)) * t2 * in.w[0] * t13 - (T(1) / T(35)) * in.w[1] * t14 * t10;
    G_ab = -(T(1) / T(105)) * in.w[1] * (T(3) * t2 * c * t13 + T(6) * b * t14 * t10 - T(7) * t2 * t9) * t10 - (T(1) / T(35)) * in.w[0] * t14 * t10;
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t4 * t3 * a_minus_b + T(2) * a * t2 * (t5 * b + t3 * a_minus_b) + t5 * b * t6;
    const T t8 = t6 * t6;
    const T t9 = t4 * t4;
    const T t10 = T(4) * a * t2 * t7 + T(3) * t5 * b * t8 + T(3) * t9 * t3 * a_minus_b;
    const T t11 = T(1) / a;
    const T t12 = T(3) * t5 * t8 + t10 * t2 * b - T(3) * t9 * t3;
    F = (T(1) / T(15)) * t10 * t2 * in.w[0] + (T(1) / T(15)) * t11 * (T(5) * t2 * t7 + T(2) * t11 * t12 * b - t10 * t2 * c) * in.w[2] + (T(1) / T(15)) * t11 * t12 * in.w[1];
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(3) * b * t3 * t5 + T(4) * t7 * (t9 * t8 * a_minus_b + T(2) * (t8 * a_minus_b + b * t3) * t7 * a + b * t3 * t4) * a + T(3) * t10 * t8 * a_minus_b;
    const T t12 = t10 * t9;
    const T t13 = T(5) * b * t3 * t6 + T(2) * t11 * t7 * a + T(5) * t12 * t8 * a_minus_b;
    const T t14 = T(5) * t3 * t6 + b * t13 * t7 - T(5) * t12 * t8;
    const T t15 = T(7) * t11 * t7 + T(6) * b * t2 * t14 - T(3) * c * t13 * t7;
    G_ap = (T(1) / T(35)) * in.w[1] * t2 * t14 + (T(1) / T(35)) * in.w[0] * t13 * t7 + (T(1) / T(105)) * t15 * in.w[2] * t2;
    G_ab = (T(1) / T(105)) * in.w[1] * t15 * t2 + (T(1) / T(105)) * in.w[2] * t2 * (T(2) * b * t15 * t2 + T(7) * (T(3) * t3 * t5 + t11 * b * t7 - T(3) * t10 * t8) * t2 - T(3) * c * t2 * t14) + (T(1) / T(35)) * in.w[0] * t2 * t14;
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[4] + in.w[1] * M_beyond[5] + in.w[2] * M_beyond[6];
    G_ab = in.w[1] * M_beyond[6] + in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t8 * t7 * a_minus_b + T(2) * (t7 * a_minus_b + t3 * b) * t6 * a + t4 * t3 * b;
    const T t11 = T(3) * t9 * t7 * a_minus_b + T(3) * t5 * t3 * b + T(4) * t10 * t6 * a;
    const T t12 = T(3) * t5 * t3 + t6 * t11 * b - T(3) * t9 * t7;
    F = (T(1) / T(15)) * in.w[2] * t2 * (T(2) * t12 * t2 * b + T(5) * t10 * t6 - c * t6 * t11) + (T(1) / T(15)) * in.w[1] * t12 * t2 + (T(1) / T(15)) * in.w[0] * t6 * t11;
    const T t13 = t5 * t4;
    const T t14 = t9 * t8;
    const T t15 = T(2) * t6 * a * t11 + T(5) * t13 * t3 * b + T(5) * t14 * t7 * a_minus_b;
    const T t16 = T(5) * t13 * t3 + t15 * t6 * b - T(5) * t14 * t7;
    const T t17 = T(6) * t16 * t2 * b + T(7) * t6 * t11 - T(3) * c * t15 * t6;
    G_ap = (T(1) / T(35)) * t16 * in.w[1] * t2 + (T(1) / T(105)) * t17 * in.w[2] * t2 + (T(1) / T(35)) * in.w[0] * t15 * t6;
    G_ab = (T(1) / T(105)) * (T(7) * t12 * t2 + T(2) * t17 * t2 * b - T(3) * t16 * c * t2) * in.w[2] * t2 + (T(1) / T(105)) * t17 * in.w[1] * t2 + (T(1) / T(35)) * in.w[0] * t16 * t2;
  }
  const T g_factor = -T(7) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t6 * a * (t3 * b + t7 * a_minus_b) + t3 * b * t4 + t8 * t7 * a_minus_b;
    const T t11 = T(3) * t9 * t7 * a_minus_b + T(3) * t3 * b * t5 + T(4) * t6 * a * t10;
    const T t12 = T(3) * t3 * t5 + t6 * b * t11 - T(3) * t9 * t7;
    const T t13 = T(2) * t2 * b * t12 + T(5) * t6 * t10 - t6 * c * t11;
    F = (T(1) / T(15)) * t2 * t13 * in.w[2] + (T(1) / T(15)) * t6 * in.w[0] * t11 + (T(1) / T(15)) * t2 * in.w[1] * t12 - (T(1) / T(15)) * in.w[3] * t2 * (T(5) * t2 * (t8 * t7 - t3 * t4 - t6 * t10 * b) + t2 * c * t12 - T(2) * t2 * t13 * b);
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[4] * in.w[3] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = t5 * a_minus_b * t6 + t2 * t3 * b + T(2) * (t5 * a_minus_b + t2 * b) * t8 * a;
    const T t10 = T(3) * t2 * t4 * b + T(3) * t5 * a_minus_b * t7 + T(4) * t9 * t8 * a;
    const T t11 = t4 * t3;
    const T t12 = t7 * t6;
    const T t13 = T(2) * t10 * t8 * a + T(5) * t2 * t11 * b + T(5) * t5 * a_minus_b * t12;
    const T t14 = t13 * t8 * b + T(5) * t2 * t11 - T(5) * t5 * t12;
    const T t15 = T(1) / a;
    const T t16 = T(3) * c * t13 * t8 - T(7) * t10 * t8 - T(6) * t14 * t15 * b;
    const T t17 = T(3) * t2 * t4 + t10 * t8 * b - T(3) * t5 * t7;
    const T t18 = T(3) * c * t14 * t15 + T(2) * t16 * t15 * b - T(7) * t15 * t17;
    G_ap = (T(1) / T(35)) * in.w[1] * t14 * t15 + (T(1) / T(35)) * t13 * t8 * in.w[0] - (T(1) / T(105)) * t15 * in.w[3] * t18 - (T(1) / T(105)) * t16 * in.w[2] * t15;
    G_ab = (T(1) / T(105)) * t15 * in.w[3] * (c * t16 * t15 + T(7) * (T(2) * t15 * b * t17 + T(5) * t9 * t8 - t10 * c * t8) * t15 - T(2) * t15 * t18 * b) + (T(1) / T(35)) * t14 * t15 * in.w[0] - (T(1) / T(105)) * in.w[2] * t15 * t18 - (T(1) / T(105)) * in.w[1] * t16 * t15;
  }
  const T g_factor = -T(7) * in.s * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[8] * in.w[3] + in.w[1] * M_beyond[6] + M_beyond[5] * in.w[0] + M_beyond[7] * in.w[2];
    G_ab = M_beyond[7] * in.w[1] + M_beyond[6] * in.w[0] + M_beyond[8] * in.w[2] + M_beyond[9] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = b * t6 * t5 + T(2) * (b * t5 + a_minus_b * t2) * t7 * a + a_minus_b * t2 * t3;
    const T t9 = t6 * t6;
    const T t10 = T(3) * a_minus_b * t2 * t4 + T(4) * t8 * t7 * a + T(3) * b * t9 * t5;
    const T t11 = T(3) * t9 * t5 + b * t10 * t7 - T(3) * t2 * t4;
    const T t12 = T(1) / a;
    const T t13 = c * t10 * t7 - T(2) * b * t11 * t12 - T(5) * t8 * t7;
    F = (T(1) / T(15)) * t10 * t7 * in.w[0] + (T(1) / T(15)) * in.w[1] * t11 * t12 - (T(1) / T(15)) * in.w[2] * t13 * t12 - (T(1) / T(15)) * (T(2) * b * t13 * t12 + c * t11 * t12 - T(5) * (b * t8 * t7 + t6 * t5 - t2 * t3) * t12) * t12 * in.w[3];
    const T t14 = t4 * t3;
    const T t15 = t9 * t6;
    const T t16 = T(5) * a_minus_b * t2 * t14 + T(5) * b * t15 * t5 + T(2) * t10 * t7 * a;
    const T t17 = b * t7 * t16 + T(5) * t15 * t5 - T(5) * t2 * t14;
    const T t18 = T(3) * c * t7 * t16 - T(7) * t10 * t7 - T(6) * b * t17 * t12;
    const T t19 = T(7) * t11 * t12 - T(3) * c * t17 * t12 - T(2) * b * t18 * t12;
    G_ap = (T(1) / T(35)) * t7 * in.w[0] * t16 + (T(1) / T(35)) * in.w[1] * t17 * t12 + (T(1) / T(105)) * t12 * t19 * in.w[3] - (T(1) / T(105)) * t18 * in.w[2] * t12;
    G_ab = (T(1) / T(105)) * in.w[2] * t12 * t19 + (T(1) / T(35)) * t17 * t12 * in.w[0] - (T(1) / T(105)) * (T(7) * t13 * t12 - T(2) * b * t12 * t19 - t18 * c * t12) * t12 * in.w[3] - (T(1) / T(105)) * t18 * in.w[1] * t12;
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    F = (T(1) / T(48)) * (T(8) * b * t6 + T(8) * t9 * a_minus_b + T(5) * t10 * a * (T(2) * t8 * a_minus_b + T(2) * b * t5 + T(3) * t10 * a * (a * J2 + b * t4 + t7 * a_minus_b))) * t10 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 44 +, 89 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = t5 * t4;
    const T t12 = t8 * t8;
    const T t13 = T(48) * b * t6 + T(7) * (T(8) * t9 * a_minus_b + T(5) * (T(2) * t8 * a_minus_b + T(3) * (b * t4 + J2 * a + t7 * a_minus_b) * a * t10 + T(2) * b * t5) * a * t10 + T(8) * b * t11) * a * t10 + T(48) * t12 * a_minus_b;
    G_ap = (T(1) / T(384)) * t13 * t10 * in.w[0];
    G_ab = (T(1) / T(384)) * (T(48) * t6 + b * t13 * t10 - T(48) * t12) * in.w[0] / a;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 44 +, 93 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    const T t9 = t7 * t6;
    const T t10 = t8 * t5;
    const T t11 = T(5) * t4 * a * (T(3) * t4 * (J2 * a + b * t5 + a_minus_b * t6) * a + T(2) * a_minus_b * t7 + T(2) * b * t8) + T(8) * a_minus_b * t9 + T(8) * b * t10;
    F = (T(1) / T(48)) * t4 * t11 * in.w[0];
    const T t12 = t7 * t7;
    const T t13 = t8 * t8;
    const T t14 = T(7) * t4 * a * t11 + T(48) * a_minus_b * t12 + T(48) * b * t13;
    G_ap = (T(1) / T(384)) * t14 * t4 * in.w[0];
    G_ab = (T(1) / T(384)) * (t14 * t4 * b + T(48) * t13 - T(48) * t12) * in.w[0] / a;
  }
  const T g_factor = -T(8) * in.s * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 40 +, 70 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
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
    const T t11 = T(8) * t7 * a_minus_b + T(5) * t4 * a * (T(2) * t6 * a_minus_b + T(3) * t4 * a * (b * t8 + t5 * a_minus_b + a * J2) + T(2) * b * t9) + T(8) * b * t10;
    F = (T(1) / T(48)) * t4 * t11 * in.w[0] - (T(1) / T(48)) * in.w[1] * (T(8) * t7 - t4 * b * t11 - T(8) * t10) / a;
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = t6 * t5;
    const T t13 = T(5) * t4 * a * (T(2) * a_minus_b * t9 + T(2) * t6 * b + T(3) * t4 * a * (t5 * b + J2 * a + a_minus_b * t8)) + T(8) * a_minus_b * t11 + T(8) * t12 * b;
    const T t14 = T(48) * t7 * b + T(48) * a_minus_b * t10 + T(7) * t4 * a * t13;
    const T t15 = T(48) * t10 - T(48) * t7 - t4 * t14 * b;
    const T t16 = T(1) / a;
    G_ap = (T(1) / T(384)) * in.w[0] * t4 * t14 - (T(1) / T(384)) * t15 * t16 * in.w[1];
    G_ab = (T(1) / T(384)) * t16 * (T(8) * t4 * t13 - c * t4 * t14 - T(2) * t15 * t16 * b) * in.w[1] - (T(1) / T(384)) * t15 * in.w[0] * t16;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[3] * in.w[0] + in.w[1] * M_beyond[4];
    G_ab = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
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
    const T t11 = T(8) * a_minus_b * t7 + T(5) * t4 * a * (T(2) * a_minus_b * t6 + T(3) * t4 * a * (b * t8 + a_minus_b * t5 + a * J2) + T(2) * b * t9) + T(8) * b * t10;
    const T t12 = T(1) / a;
    F = (T(1) / T(48)) * t4 * in.w[0] * t11 + (T(1) / T(48)) * in.w[1] * t12 * (T(8) * t10 + t4 * b * t11 - T(8) * t7);
    const T t13 = t6 * t6;
    const T t14 = t9 * t9;
    const T t15 = T(48) * a_minus_b * t13 + T(48) * b * t14 + T(7) * t4 * a * t11;
    const T t16 = t15 * t4 * b + T(48) * t14 - T(48) * t13;
    G_ap = (T(1) / T(384)) * in.w[1] * t12 * t16 + (T(1) / T(384)) * t15 * t4 * in.w[0];
    G_ab = (T(1) / T(384)) * t12 * t16 * in.w[0] + (T(1) / T(384)) * in.w[1] * t12 * (T(8) * t4 * t11 + T(2) * t12 * t16 * b - t15 * t4 * c);
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = T(2) * b * t5 + T(3) * a * (a * J2 + a_minus_b * t7 + b * t4) * t10 + T(2) * a_minus_b * t8;
    const T t12 = T(8) * b * t6 + T(8) * a_minus_b * t9 + T(5) * a * t11 * t10;
    const T t13 = T(1) / a;
    const T t14 = T(8) * t6 + b * t12 * t10 - T(8) * t9;
    F = (T(1) / T(48)) * in.w[0] * t12 * t10 + (T(1) / T(48)) * t13 * t14 * in.w[1] - (T(1) / T(48)) * in.w[2] * t13 * (c * t12 * t10 - T(6) * t11 * t10 - T(2) * t13 * t14 * b);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t6 * t5;
    const T t10 = t8 * t7;
    const T t11 = T(5) * t4 * a * (T(2) * a_minus_b * t6 + T(3) * t4 * a * (b * t7 + a * J2 + a_minus_b * t5) + T(2) * b * t8) + T(8) * a_minus_b * t9 + T(8) * b * t10;
    const T t12 = t8 * t8;
    const T t13 = t6 * t6;
    const T t14 = T(7) * t4 * a * t11 + T(48) * b * t12 + T(48) * a_minus_b * t13;
    const T t15 = T(1) / a;
    const T t16 = T(48) * t12 + t4 * b * t14 - T(48) * t13;
    const T t17 = t4 * t14 * c - T(2) * t15 * b * t16 - T(8) * t4 * t11;
    G_ap = (T(1) / T(384)) * t4 * t14 * in.w[0] + (T(1) / T(384)) * t15 * in.w[1] * t16 - (T(1) / T(384)) * t15 * in.w[2] * t17;
    G_ab = (T(1) / T(384)) * t15 * in.w[0] * t16 - (T(1) / T(384)) * t15 * t17 * in.w[1] - (T(1) / T(384)) * t15 * in.w[2] * (T(2) * t15 * t17 * b + t15 * c * t16 - T(8) * t15 * (T(8) * t10 + t4 * b * t11 - T(8) * t9));
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = in.w[2] * M_beyond[6] + M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
    G_ab = M_beyond[6] * in.w[1] + in.w[2] * M_beyond[7] + M_beyond[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = T(2) * b * t8 + T(3) * a * (a_minus_b * t4 + b * t7 + a * J2) * t9 + T(2) * a_minus_b * t5;
    const T t11 = t8 * t7;
    const T t12 = T(8) * a_minus_b * t6 + T(5) * a * t10 * t9 + T(8) * b * t11;
    const T t13 = T(1) / a;
    const T t14 = T(8) * t11 + t12 * b * t9 - T(8) * t6;
    F = (T(1) / T(48)) * t12 * in.w[0] * t9 + (T(1) / T(48)) * t13 * in.w[2] * (T(6) * t10 * t9 + T(2) * t13 * b * t14 - t12 * c * t9) + (T(1) / T(48)) * t13 * in.w[1] * t14;
    const T t15 = t8 * t8;
    const T t16 = t5 * t5;
    const T t17 = T(7) * a * t12 * t9 + T(48) * b * t15 + T(48) * a_minus_b * t16;
    const T t18 = T(48) * t16 - T(48) * t15 - b * t17 * t9;
    const T t19 = T(2) * t13 * b * t18 + t17 * c * t9 - T(8) * t12 * t9;
    G_ap = (T(1) / T(384)) * t17 * in.w[0] * t9 - (T(1) / T(384)) * t13 * t18 * in.w[1] - (T(1) / T(384)) * t13 * in.w[2] * t19;
    G_ab = (T(1) / T(384)) * t13 * in.w[2] * (T(8) * t13 * t14 + t13 * t18 * c - T(2) * t13 * t19 * b) - (T(1) / T(384)) * t13 * in.w[0] * t18 - (T(1) / T(384)) * t13 * t19 * in.w[1];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = T(2) * b * t5 + T(3) * a * (a * J2 + a_minus_b * t7 + b * t4) * t10 + T(2) * a_minus_b * t8;
    const T t12 = T(8) * b * t6 + T(8) * a_minus_b * t9 + T(5) * a * t11 * t10;
    const T t13 = T(8) * t6 + t12 * b * t10 - T(8) * t9;
    const T t14 = T(1) / a;
    const T t15 = T(2) * t13 * t14 * b + T(6) * t11 * t10 - t12 * c * t10;
    F = (T(1) / T(48)) * t13 * t14 * in.w[1] + (T(1) / T(48)) * in.w[0] * t12 * t10 + (T(1) / T(48)) * t14 * in.w[3] * (T(6) * t14 * (T(2) * t5 + b * t11 * t10 - T(2) * t8) + T(2) * t14 * b * t15 - t13 * t14 * c) + (T(1) / T(48)) * t14 * t15 * in.w[2];
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0] + in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = T(2) * a_minus_b * t8 + T(3) * t10 * a * (J2 * a + b * t4 + a_minus_b * t7) + T(2) * b * t5;
    const T t12 = T(8) * b * t6 + T(8) * a_minus_b * t9 + T(5) * t11 * t10 * a;
    const T t13 = t12 * b * t10 + T(8) * t6 - T(8) * t9;
    const T t14 = T(1) / a;
    const T t15 = t8 * t8;
    const T t16 = t5 * t5;
    const T t17 = T(7) * t12 * t10 * a + T(48) * a_minus_b * t15 + T(48) * b * t16;
    const T t18 = T(48) * t15 - T(48) * t16 - b * t17 * t10;
    const T t19 = c * t17 * t10 + T(2) * b * t18 * t14 - T(8) * t12 * t10;
    const T t20 = T(8) * t13 * t14 + c * t18 * t14 - T(2) * b * t14 * t19;
    G_ap = (T(1) / T(384)) * t20 * in.w[3] * t14 + (T(1) / T(384)) * t17 * t10 * in.w[0] - (T(1) / T(384)) * in.w[2] * t14 * t19 - (T(1) / T(384)) * in.w[1] * t18 * t14;
    G_ab = (T(1) / T(384)) * (c * t14 * t19 + T(8) * (T(6) * t11 * t10 + T(2) * b * t13 * t14 - t12 * c * t10) * t14 + T(2) * b * t20 * t14) * in.w[3] * t14 + (T(1) / T(384)) * t20 * in.w[2] * t14 - (T(1) / T(384)) * in.w[1] * t14 * t19 - (T(1) / T(384)) * t18 * t14 * in.w[0];
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ap = M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2];
    G_ab = in.w[1] * M_beyond[7] + M_beyond[6] * in.w[0] + M_beyond[9] * in.w[3] + in.w[2] * M_beyond[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    const T t9 = T(3) * (a_minus_b * t5 + b * t6 + J2 * a) * t4 * a + T(2) * b * t7 + T(2) * a_minus_b * t8;
    const T t10 = T(1) / a;
    const T t11 = t7 * t6;
    const T t12 = t8 * t5;
    const T t13 = T(8) * b * t11 + T(8) * a_minus_b * t12 + T(5) * t4 * t9 * a;
    const T t14 = T(8) * t11 + b * t13 * t4 - T(8) * t12;
    const T t15 = T(6) * t4 * t9 + T(2) * b * t14 * t10 - t13 * c * t4;
    F = (T(1) / T(48)) * (T(6) * (b * t4 * t9 + T(2) * t7 - T(2) * t8) * t10 + T(2) * b * t10 * t15 - c * t14 * t10) * in.w[3] * t10 + (T(1) / T(48)) * t13 * t4 * in.w[0] + (T(1) / T(48)) * in.w[2] * t10 * t15 + (T(1) / T(48)) * in.w[1] * t14 * t10;
    const T t16 = t7 * t7;
    const T t17 = t8 * t8;
    const T t18 = T(48) * b * t16 + T(7) * t13 * t4 * a + T(48) * a_minus_b * t17;
    const T t19 = T(48) * t17 - b * t18 * t4 - T(48) * t16;
    const T t20 = T(2) * b * t10 * t19 + c * t18 * t4 - T(8) * t13 * t4;
    const T t21 = T(2) * b * t10 * t20 - T(8) * t14 * t10 - c * t10 * t19;
    G_ap = (T(1) / T(384)) * t18 * t4 * in.w[0] - (T(1) / T(384)) * in.w[2] * t10 * t20 - (T(1) / T(384)) * t21 * in.w[3] * t10 - (T(1) / T(384)) * in.w[1] * t10 * t19;
    G_ab = (T(1) / T(384)) * in.w[3] * t10 * (T(8) * t10 * t15 + c * t10 * t20 - T(2) * b * t21 * t10) - (T(1) / T(384)) * t10 * in.w[0] * t19 - (T(1) / T(384)) * in.w[1] * t10 * t20 - (T(1) / T(384)) * t21 * in.w[2] * t10;
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    F = (T(1) / T(35)) * t2 * in.w[0] * (T(5) * t3 * b * t6 + T(2) * t2 * a * (T(3) * t3 * b * t5 + T(3) * t9 * t7 * a_minus_b + T(4) * t2 * (T(2) * t2 * a * (t7 * a_minus_b + t3 * b) + t3 * b * t4 + t8 * t7 * a_minus_b) * a) + T(5) * t10 * t7 * a_minus_b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 42 +, 100 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t4 * t3;
    const T t11 = T(1) / D;
    const T t12 = t8 * t8;
    const T t13 = T(35) * b * t2 * t5 + T(8) * (T(5) * t9 * t6 * a_minus_b + T(5) * b * t2 * t10 + T(2) * (T(3) * b * t2 * t4 + T(3) * t8 * t6 * a_minus_b + T(4) * (T(2) * (t6 * a_minus_b + b * t2) * t11 * a + t7 * t6 * a_minus_b + b * t2 * t3) * t11 * a) * t11 * a) * t11 * a + T(35) * t12 * t6 * a_minus_b;
    G_ap = (T(1) / T(315)) * t13 * t11 * in.w[0];
    G_ab = -(T(1) / T(315)) * (T(35) * t12 * t6 - b * t13 * t11 - T(35) * t2 * t5) * in.w[0] / a;
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 42 +, 104 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(5) * t3 * b * t6 + T(5) * t7 * a_minus_b * t10 + T(2) * a * t2 * (T(3) * t3 * b * t5 + T(3) * t7 * a_minus_b * t9 + T(4) * a * t2 * (t7 * a_minus_b * t8 + T(2) * a * t2 * (t3 * b + t7 * a_minus_b) + t3 * b * t4));
    F = (T(1) / T(35)) * t2 * in.w[0] * t11;
    const T t12 = t9 * t9;
    const T t13 = t5 * t5;
    const T t14 = T(35) * t7 * a_minus_b * t12 + T(35) * t3 * b * t13 + T(8) * a * t2 * t11;
    G_ap = (T(1) / T(315)) * t2 * in.w[0] * t14;
    G_ab = (T(1) / T(315)) * in.w[0] * (T(35) * t3 * t13 + t2 * b * t14 - T(35) * t7 * t12) / a;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 38 +, 79 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
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
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = T(5) * t2 * b * t5 + T(5) * a_minus_b * t6 * t9 + T(2) * a * t10 * (T(3) * t2 * b * t4 + T(4) * a * (T(2) * a * (t2 * b + a_minus_b * t6) * t10 + a_minus_b * t6 * t7 + t2 * b * t3) * t10 + T(3) * a_minus_b * t6 * t8);
    F = (T(1) / T(35)) * (T(5) * t2 * t5 + t11 * b * t10 - T(5) * t6 * t9) * in.w[1] / a + (T(1) / T(35)) * t11 * in.w[0] * t10;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t5 * t4;
    const T t11 = T(2) * a * t2 * (T(3) * t5 * t3 * a_minus_b + T(3) * b * t6 * t8 + T(4) * a * t2 * (T(2) * a * t2 * (b * t6 + t3 * a_minus_b) + b * t6 * t7 + t4 * t3 * a_minus_b)) + T(5) * b * t6 * t9 + T(5) * t10 * t3 * a_minus_b;
    const T t12 = t5 * t5;
    const T t13 = t8 * t8;
    const T t14 = T(8) * a * t2 * t11 + T(35) * t12 * t3 * a_minus_b + T(35) * b * t6 * t13;
    const T t15 = T(1) / a;
    const T t16 = T(35) * t6 * t13 + t2 * t14 * b - T(35) * t12 * t3;
    G_ap = (T(1) / T(315)) * t2 * t14 * in.w[0] + (T(1) / T(315)) * t15 * in.w[1] * t16;
    G_ab = (T(1) / T(315)) * t15 * t16 * in.w[0] + (T(1) / T(315)) * t15 * in.w[1] * (T(9) * t2 * t11 + T(2) * t15 * b * t16 - t2 * t14 * c);
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[3] * in.w[0] + in.w[1] * M_beyond[4];
    G_ab = in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(5) * t3 * b * t6 + T(5) * a_minus_b * t7 * t10 + T(2) * t2 * a * (T(3) * t3 * b * t5 + T(4) * t2 * (a_minus_b * t7 * t8 + T(2) * t2 * a * (t3 * b + a_minus_b * t7) + t3 * b * t4) * a + T(3) * a_minus_b * t7 * t9);
    const T t12 = T(1) / a;
    F = (T(1) / T(35)) * t2 * in.w[0] * t11 + (T(1) / T(35)) * t12 * in.w[1] * (t2 * b * t11 + T(5) * t3 * t6 - T(5) * t7 * t10);
    const T t13 = t5 * t5;
    const T t14 = t9 * t9;
    const T t15 = T(35) * t3 * b * t13 + T(35) * a_minus_b * t7 * t14 + T(8) * t2 * a * t11;
    const T t16 = t2 * b * t15 + T(35) * t3 * t13 - T(35) * t7 * t14;
    G_ap = (T(1) / T(315)) * t12 * t16 * in.w[1] + (T(1) / T(315)) * t2 * t15 * in.w[0];
    G_ab = (T(1) / T(315)) * t12 * in.w[1] * (T(9) * t2 * t11 + T(2) * t12 * t16 * b - t2 * t15 * c) + (T(1) / T(315)) * t12 * t16 * in.w[0];
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(3) * t2 * a_minus_b * t4 + T(3) * b * t7 * t5 + T(4) * (T(2) * (t2 * a_minus_b + b * t5) * t8 * a + b * t6 * t5 + t2 * a_minus_b * t3) * t8 * a;
    const T t10 = t7 * t6;
    const T t11 = t4 * t3;
    const T t12 = T(2) * t9 * t8 * a + T(5) * b * t10 * t5 + T(5) * t2 * a_minus_b * t11;
    const T t13 = T(1) / a;
    const T t14 = T(5) * t10 * t5 + b * t12 * t8 - T(5) * t2 * t11;
    F = (T(1) / T(35)) * in.w[0] * t12 * t8 + (T(1) / T(35)) * in.w[1] * t13 * t14 - (T(1) / T(105)) * (T(3) * t12 * c * t8 - T(6) * b * t13 * t14 - T(7) * t9 * t8) * in.w[2] * t13;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t4 * t7 * b + T(5) * t8 * a_minus_b * t11 + T(2) * (T(3) * t8 * a_minus_b * t10 + T(3) * t4 * t6 * b + T(4) * a * t3 * (T(2) * a * t3 * (t8 * a_minus_b + t4 * b) + t4 * t5 * b + t8 * a_minus_b * t9)) * a * t3;
    const T t13 = t10 * t10;
    const T t14 = t6 * t6;
    const T t15 = T(8) * a * t3 * t12 + T(35) * t8 * a_minus_b * t13 + T(35) * t4 * t14 * b;
    const T t16 = t3 * t15 * b + T(35) * t4 * t14 - T(35) * t8 * t13;
    const T t17 = c * t3 * t15 - T(9) * t3 * t12 - T(2) * t2 * t16 * b;
    G_ap = (T(1) / T(315)) * in.w[1] * t2 * t16 + (T(1) / T(315)) * t3 * t15 * in.w[0] - (T(1) / T(315)) * t2 * in.w[2] * t17;
    G_ab = (T(1) / T(315)) * t2 * t16 * in.w[0] - (T(1) / T(315)) * (T(2) * t2 * t17 * b + c * t2 * t16 - T(9) * t2 * (t3 * t12 * b + T(5) * t4 * t7 - T(5) * t8 * t11)) * t2 * in.w[2] - (T(1) / T(315)) * in.w[1] * t2 * t17;
  }
  const T g_factor = -T(9) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2];
    G_ab = M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(4) * (b * t3 * t2 + T(2) * (b * t2 + a_minus_b * t7) * t6 * a + t8 * a_minus_b * t7) * t6 * a + T(3) * t9 * a_minus_b * t7 + T(3) * b * t4 * t2;
    const T t12 = T(5) * t10 * a_minus_b * t7 + T(2) * t11 * t6 * a + T(5) * b * t5 * t2;
    const T t13 = T(5) * t5 * t2 + b * t6 * t12 - T(5) * t10 * t7;
    const T t14 = T(1) / a;
    F = (T(1) / T(35)) * in.w[1] * t13 * t14 + (T(1) / T(105)) * (T(6) * b * t13 * t14 + T(7) * t11 * t6 - T(3) * c * t6 * t12) * t14 * in.w[2] + (T(1) / T(35)) * in.w[0] * t6 * t12;
    const T t15 = t4 * t4;
    const T t16 = t9 * t9;
    const T t17 = T(8) * t6 * a * t12 + T(35) * b * t15 * t2 + T(35) * t16 * a_minus_b * t7;
    const T t18 = b * t6 * t17 + T(35) * t15 * t2 - T(35) * t16 * t7;
    const T t19 = c * t6 * t17 - T(9) * t6 * t12 - T(2) * b * t14 * t18;
    G_ap = (T(1) / T(315)) * in.w[1] * t14 * t18 + (T(1) / T(315)) * in.w[0] * t6 * t17 - (T(1) / T(315)) * t19 * t14 * in.w[2];
    G_ab = (T(1) / T(315)) * in.w[0] * t14 * t18 - (T(1) / T(315)) * t19 * in.w[1] * t14 - (T(1) / T(315)) * t14 * (c * t14 * t18 + T(2) * b * t19 * t14 - T(9) * t13 * t14) * in.w[2];
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(3) * t5 * a_minus_b * t3 + T(4) * (T(2) * t2 * a * (a_minus_b * t3 + t7 * b) + t7 * b * t8 + t4 * a_minus_b * t3) * t2 * a + T(3) * t7 * b * t9;
    const T t12 = T(5) * t6 * a_minus_b * t3 + T(5) * t7 * b * t10 + T(2) * t2 * a * t11;
    const T t13 = T(1) / a;
    const T t14 = T(5) * t7 * t10 + t2 * t12 * b - T(5) * t6 * t3;
    const T t15 = T(3) * t2 * t12 * c - T(6) * t13 * b * t14 - T(7) * t2 * t11;
    F = (T(1) / T(35)) * t2 * in.w[0] * t12 + (T(1) / T(35)) * t13 * t14 * in.w[1] + (T(1) / T(105)) * t13 * in.w[3] * (T(7) * (T(3) * t7 * t9 + t2 * t11 * b - T(3) * t5 * t3) * t13 - T(2) * t13 * b * t15 - T(3) * t13 * t14 * c) - (T(1) / T(105)) * in.w[2] * t13 * t15;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3];
    G_ab = in.w[0] * M_beyond[1] + in.w[3] * M_beyond[4] + in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t7 * a_minus_b * t9 + T(4) * t6 * (T(2) * t6 * a * (b * t2 + t7 * a_minus_b) + b * t2 * t3 + t7 * a_minus_b * t8) * a + T(3) * b * t2 * t4;
    const T t11 = t9 * t8;
    const T t12 = t4 * t3;
    const T t13 = T(2) * t6 * a * t10 + T(5) * t7 * a_minus_b * t11 + T(5) * b * t2 * t12;
    const T t14 = t9 * t9;
    const T t15 = T(35) * b * t2 * t5 + T(8) * t13 * t6 * a + T(35) * t7 * a_minus_b * t14;
    const T t16 = T(35) * t2 * t5 + b * t15 * t6 - T(35) * t7 * t14;
    const T t17 = T(1) / a;
    const T t18 = T(5) * t7 * t11 - b * t13 * t6 - T(5) * t2 * t12;
    const T t19 = t15 * c * t6 - T(9) * t13 * t6 - T(2) * b * t16 * t17;
    const T t20 = t16 * c * t17 + T(9) * t18 * t17 + T(2) * b * t17 * t19;
    G_ap = (T(1) / T(315)) * in.w[1] * t16 * t17 + (T(1) / T(315)) * t15 * t6 * in.w[0] - (T(1) / T(315)) * t20 * in.w[3] * t17 - (T(1) / T(315)) * in.w[2] * t17 * t19;
    G_ab = (T(1) / T(315)) * (T(3) * t17 * (T(7) * t6 * t10 - T(3) * c * t13 * t6 - T(6) * b * t18 * t17) + c * t17 * t19 - T(2) * b * t20 * t17) * in.w[3] * t17 + (T(1) / T(315)) * t16 * t17 * in.w[0] - (T(1) / T(315)) * in.w[1] * t17 * t19 - (T(1) / T(315)) * t20 * in.w[2] * t17;
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[3] * M_beyond[3] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ap = in.w[3] * M_beyond[8] + in.w[0] * M_beyond[5] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
    G_ab = M_beyond[9] * in.w[3] + M_beyond[6] * in.w[0] + M_beyond[7] * in.w[1] + M_beyond[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t3 * a_minus_b * t5 + T(4) * t2 * a * (b * t8 * t7 + t3 * a_minus_b * t4 + T(2) * t2 * a * (t3 * a_minus_b + b * t7)) + T(3) * b * t9 * t7;
    const T t11 = t9 * t8;
    const T t12 = T(5) * t3 * a_minus_b * t6 + T(2) * t2 * a * t10 + T(5) * b * t11 * t7;
    const T t13 = T(1) / a;
    const T t14 = T(5) * t3 * t6 - T(5) * t11 * t7 - t2 * b * t12;
    const T t15 = T(3) * t2 * t12 * c + T(6) * t13 * b * t14 - T(7) * t2 * t10;
    F = (T(1) / T(35)) * t2 * in.w[0] * t12 - (T(1) / T(105)) * t13 * in.w[2] * t15 - (T(1) / T(105)) * (T(7) * t13 * (T(3) * t3 * t5 - t2 * t10 * b - T(3) * t9 * t7) + T(2) * t13 * b * t15 - T(3) * t13 * c * t14) * in.w[3] * t13 - (T(1) / T(35)) * t13 * in.w[1] * t14;
    const T t16 = t9 * t9;
    const T t17 = t5 * t5;
    const T t18 = T(35) * b * t16 * t7 + T(8) * t2 * a * t12 + T(35) * t3 * a_minus_b * t17;
    const T t19 = t2 * b * t18 + T(35) * t16 * t7 - T(35) * t3 * t17;
    const T t20 = T(2) * t13 * b * t19 + T(9) * t2 * t12 - t2 * t18 * c;
    const T t21 = T(9) * t13 * t14 + t13 * t19 * c - T(2) * t13 * b * t20;
    G_ap = (T(1) / T(315)) * t13 * in.w[1] * t19 + (T(1) / T(315)) * t2 * in.w[0] * t18 + (T(1) / T(315)) * t13 * in.w[2] * t20 - (T(1) / T(315)) * in.w[3] * t13 * t21;
    G_ab = (T(1) / T(315)) * t13 * in.w[0] * t19 + (T(1) / T(315)) * t13 * in.w[1] * t20 - (T(1) / T(315)) * in.w[3] * t13 * (T(3) * t13 * t15 + T(2) * t13 * b * t21 + t13 * c * t20) - (T(1) / T(315)) * t13 * t21 * in.w[2];
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + bp2 * ap2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t6 * t5;
    const T t12 = t9 * t9;
    F = (T(1) / T(384)) * t4 * in.w[0] * (T(48) * t7 * a_minus_b + T(7) * t4 * a * (T(5) * t4 * a * (T(2) * t9 * b + T(2) * t6 * a_minus_b + T(3) * t4 * a * (t5 * a_minus_b + a * J2 + t8 * b)) + T(8) * t10 * b + T(8) * t11 * a_minus_b) + T(48) * t12 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 46 +, 98 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t6 * t5;
    const T t14 = t10 * t9;
    const T t15 = T(128) * b * t8 + T(128) * t12 * a_minus_b + T(3) * t4 * a * (T(48) * b * t7 + T(48) * t11 * a_minus_b + T(7) * t4 * a * (T(8) * b * t13 + T(5) * t4 * a * (T(3) * t4 * (t9 * a_minus_b + b * t5 + a * J2) * a + T(2) * b * t6 + T(2) * t10 * a_minus_b) + T(8) * t14 * a_minus_b));
    G_ap = (T(1) / T(1280)) * t4 * in.w[0] * t15;
    G_ab = (T(1) / T(1280)) * in.w[0] * (t4 * t15 * b + T(128) * t8 - T(128) * t12) / a;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 46 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = t9 * t8;
    const T t13 = T(48) * a_minus_b * t7 + T(48) * b * t10 + T(7) * (T(8) * a_minus_b * t11 + T(5) * (T(2) * a_minus_b * t6 + T(3) * (J2 * a + b * t8 + a_minus_b * t5) * a * t4 + T(2) * b * t9) * a * t4 + T(8) * b * t12) * a * t4;
    F = (T(1) / T(384)) * in.w[0] * t4 * t13;
    const T t14 = t7 * t5;
    const T t15 = t10 * t8;
    const T t16 = T(128) * a_minus_b * t14 + T(128) * b * t15 + T(3) * a * t4 * t13;
    G_ap = (T(1) / T(1280)) * t16 * in.w[0] * t4;
    G_ab = (T(1) / T(1280)) * (T(128) * t15 + b * t16 * t4 - T(128) * t14) * in.w[0] / a;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 42 +, 79 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t5 * t4;
    const T t12 = t8 * t7;
    const T t13 = T(48) * b * t6 + T(48) * a_minus_b * t9 + T(7) * (T(5) * (T(2) * b * t5 + T(3) * t10 * (a_minus_b * t7 + b * t4 + J2 * a) * a + T(2) * a_minus_b * t8) * t10 * a + T(8) * b * t11 + T(8) * a_minus_b * t12) * t10 * a;
    F = (T(1) / T(384)) * in.w[0] * t13 * t10 - (T(1) / T(384)) * (T(48) * t9 - b * t13 * t10 - T(48) * t6) * in.w[1] / a;
  }
  f = F * length;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t10 * t9;
    const T t14 = t6 * t5;
    const T t15 = T(48) * a_minus_b * t7 + T(48) * b * t11 + T(7) * t4 * a * (T(5) * t4 * a * (T(2) * a_minus_b * t6 + T(2) * b * t10 + T(3) * t4 * a * (a * J2 + b * t9 + a_minus_b * t5)) + T(8) * b * t13 + T(8) * a_minus_b * t14);
    const T t16 = T(128) * a_minus_b * t8 + T(128) * b * t12 + T(3) * t4 * a * t15;
    const T t17 = T(1) / a;
    const T t18 = T(128) * t12 + t4 * t16 * b - T(128) * t8;
    G_ap = (T(1) / T(1280)) * t4 * t16 * in.w[0] + (T(1) / T(1280)) * in.w[1] * t17 * t18;
    G_ab = (T(1) / T(3840)) * in.w[1] * t17 * (T(10) * t4 * t15 + T(6) * t17 * t18 * b - T(3) * t4 * t16 * c) + (T(1) / T(1280)) * t17 * t18 * in.w[0];
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t6 * t6;
    const T t13 = T(7) * t4 * (T(8) * t7 * b + T(8) * t10 * a_minus_b + T(5) * t4 * a * (T(2) * t9 * a_minus_b + T(2) * t6 * b + T(3) * (J2 * a + t8 * a_minus_b + t5 * b) * t4 * a)) * a + T(48) * t11 * a_minus_b + T(48) * t12 * b;
    const T t14 = T(1) / a;
    F = (T(1) / T(384)) * in.w[0] * t4 * t13 - (T(1) / T(384)) * (T(48) * t11 - T(48) * t12 - t4 * t13 * b) * t14 * in.w[1];
    const T t15 = t11 * t8;
    const T t16 = t12 * t5;
    const T t17 = T(3) * t4 * a * t13 + T(128) * t15 * a_minus_b + T(128) * t16 * b;
    const T t18 = T(128) * t15 - T(128) * t16 - t4 * t17 * b;
    G_ap = (T(1) / T(1280)) * in.w[0] * t4 * t17 - (T(1) / T(1280)) * t14 * in.w[1] * t18;
    G_ab = (T(1) / T(3840)) * (T(10) * t4 * t13 - T(3) * c * t4 * t17 - T(6) * t14 * t18 * b) * t14 * in.w[1] - (T(1) / T(1280)) * in.w[0] * t14 * t18;
  }
  const T g_factor = -T(10) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / a;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t9 * t8;
    const T t12 = t6 * t5;
    const T t13 = T(5) * (T(2) * a_minus_b * t9 + T(2) * t6 * b + T(3) * t10 * a * (t5 * b + a * J2 + a_minus_b * t8)) * t10 * a + T(8) * a_minus_b * t11 + T(8) * t12 * b;
    const T t14 = t9 * t9;
    const T t15 = T(48) * t7 * b + T(7) * t13 * t10 * a + T(48) * a_minus_b * t14;
    const T t16 = T(48) * t7 + t15 * t10 * b - T(48) * t14;
    F = (T(1) / T(384)) * in.w[1] * t4 * t16 + (T(1) / T(384)) * t15 * t10 * in.w[0] - (T(1) / T(384)) * t4 * in.w[2] * (c * t15 * t10 - T(8) * t13 * t10 - T(2) * t4 * t16 * b);
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t6 * t5;
    const T t13 = t10 * t10;
    const T t14 = T(48) * t7 * b + T(7) * t4 * a * (T(8) * a_minus_b * t11 + T(5) * t4 * a * (T(3) * t4 * a * (J2 * a + t5 * b + a_minus_b * t9) + T(2) * a_minus_b * t10 + T(2) * t6 * b) + T(8) * t12 * b) + T(48) * a_minus_b * t13;
    const T t15 = t13 * t9;
    const T t16 = T(128) * t8 * b + T(3) * t4 * t14 * a + T(128) * a_minus_b * t15;
    const T t17 = t4 * t16 * b + T(128) * t8 - T(128) * t15;
    const T t18 = T(1) / a;
    const T t19 = T(3) * c * t4 * t16 - T(6) * t17 * t18 * b - T(10) * t4 * t14;
    G_ap = (T(1) / T(1280)) * in.w[0] * t4 * t16 + (T(1) / T(1280)) * in.w[1] * t17 * t18 - (T(1) / T(3840)) * in.w[2] * t18 * t19;
    G_ab = (T(1) / T(1280)) * in.w[0] * t17 * t18 - (T(1) / T(3840)) * in.w[1] * t18 * t19 - (T(1) / T(3840)) * (T(2) * t18 * t19 * b + T(3) * c * t17 * t18 - T(10) * t18 * (t4 * t14 * b + T(48) * t7 - T(48) * t13)) * in.w[2] * t18;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = in.w[1] * M_beyond[5] + M_beyond[6] * in.w[2] + in.w[0] * M_beyond[4];
    G_ab = M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t8 * t7;
    const T t11 = T(1) / D;
    const T t12 = t5 * t4;
    const T t13 = T(8) * t10 * b + T(5) * (T(3) * a * t11 * (t7 * b + J2 * a + t4 * a_minus_b) + T(2) * t5 * a_minus_b + T(2) * t8 * b) * a * t11 + T(8) * t12 * a_minus_b;
    const T t14 = T(48) * t6 * a_minus_b + T(48) * t9 * b + T(7) * t13 * a * t11;
    const T t15 = T(48) * t6 - T(48) * t9 - t14 * t11 * b;
    const T t16 = T(1) / a;
    F = (T(1) / T(384)) * in.w[0] * t14 * t11 - (T(1) / T(384)) * (T(2) * t15 * t16 * b + c * t14 * t11 - T(8) * t13 * t11) * t16 * in.w[2] - (T(1) / T(384)) * in.w[1] * t15 * t16;
    const T t17 = t6 * t4;
    const T t18 = t9 * t7;
    const T t19 = T(128) * t17 * a_minus_b + T(3) * t14 * a * t11 + T(128) * t18 * b;
    const T t20 = T(128) * t17 - t11 * b * t19 - T(128) * t18;
    const T t21 = T(6) * t20 * t16 * b + T(3) * c * t11 * t19 - T(10) * t14 * t11;
    G_ap = (T(1) / T(1280)) * in.w[0] * t11 * t19 - (T(1) / T(1280)) * t20 * in.w[1] * t16 - (T(1) / T(3840)) * t21 * t16 * in.w[2];
    G_ab = -(T(1) / T(3840)) * t21 * in.w[1] * t16 - (T(1) / T(3840)) * (T(2) * t21 * t16 * b + T(10) * t15 * t16 - T(3) * t20 * c * t16) * t16 * in.w[2] - (T(1) / T(1280)) * in.w[0] * t20 * t16;
  }
  const T g_factor = -T(10) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t5 * t4;
    const T t12 = t9 * t8;
    const T t13 = T(8) * t11 * b + T(8) * a_minus_b * t12 + T(5) * t7 * a * (T(2) * t5 * b + T(2) * a_minus_b * t9 + T(3) * t7 * a * (a * J2 + a_minus_b * t8 + t4 * b));
    const T t14 = T(48) * a_minus_b * t10 + T(7) * t7 * a * t13 + T(48) * t6 * b;
    const T t15 = T(48) * t6 + t7 * t14 * b - T(48) * t10;
    const T t16 = T(1) / a;
    const T t17 = T(2) * t15 * t16 * b + T(8) * t7 * t13 - c * t7 * t14;
    F = (T(1) / T(384)) * t15 * t16 * in.w[1] + (T(1) / T(384)) * in.w[2] * t16 * t17 + (T(1) / T(384)) * t7 * in.w[0] * t14 + (T(1) / T(384)) * (T(8) * t16 * (T(8) * t11 + t7 * t13 * b - T(8) * t12) + T(2) * t16 * t17 * b - c * t15 * t16) * in.w[3] * t16;
  }
  f = F * length;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ab = in.w[3] * M_beyond[4] + M_beyond[3] * in.w[2] + in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / a;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = T(5) * t5 * a * (T(3) * (b * t6 + a_minus_b * t9 + a * J2) * t5 * a + T(2) * a_minus_b * t10 + T(2) * b * t7) + T(8) * a_minus_b * t12 + T(8) * b * t13;
    const T t15 = T(48) * b * t8 + T(48) * a_minus_b * t11 + T(7) * t5 * a * t14;
    const T t16 = t11 * t9;
    const T t17 = t8 * t6;
    const T t18 = T(3) * t5 * a * t15 + T(128) * a_minus_b * t16 + T(128) * b * t17;
    const T t19 = t5 * b * t18 + T(128) * t17 - T(128) * t16;
    const T t20 = T(6) * t4 * t19 * b + T(10) * t5 * t15 - T(3) * t5 * t18 * c;
    const T t21 = T(48) * t8 + t5 * t15 * b - T(48) * t11;
    const T t22 = T(3) * t4 * t19 * c - T(10) * t4 * t21 - T(2) * t4 * t20 * b;
    G_ap = (T(1) / T(1280)) * t4 * t19 * in.w[1] + (T(1) / T(1280)) * t5 * in.w[0] * t18 + (T(1) / T(3840)) * t4 * t20 * in.w[2] - (T(1) / T(3840)) * t4 * t22 * in.w[3];
    G_ab = (T(1) / T(3840)) * t4 * t20 * in.w[1] + (T(1) / T(1280)) * t4 * in.w[0] * t19 - (T(1) / T(3840)) * t4 * in.w[3] * (T(2) * t4 * t22 * b + t4 * t20 * c - T(10) * t4 * (T(8) * t5 * t14 + T(2) * t4 * b * t21 - t5 * t15 * c)) - (T(1) / T(3840)) * t4 * t22 * in.w[2];
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + M_beyond[8] * in.w[3];
    G_ab = M_beyond[9] * in.w[3] + in.w[2] * M_beyond[8] + in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(1) / D;
    const T t12 = t9 * t8;
    const T t13 = t6 * t5;
    const T t14 = T(5) * (T(2) * b * t6 + T(2) * a_minus_b * t9 + T(3) * (J2 * a + a_minus_b * t8 + b * t5) * t11 * a) * t11 * a + T(8) * a_minus_b * t12 + T(8) * b * t13;
    const T t15 = T(48) * b * t7 + T(48) * a_minus_b * t10 + T(7) * t14 * t11 * a;
    const T t16 = b * t15 * t11 + T(48) * t7 - T(48) * t10;
    const T t17 = T(2) * b * t16 * t4 + T(8) * t14 * t11 - c * t15 * t11;
    F = (T(1) / T(384)) * t4 * (T(2) * b * t17 * t4 - T(8) * (T(8) * t12 - b * t14 * t11 - T(8) * t13) * t4 - c * t16 * t4) * in.w[3] + (T(1) / T(384)) * in.w[0] * t15 * t11 + (T(1) / T(384)) * in.w[2] * t17 * t4 + (T(1) / T(384)) * in.w[1] * t16 * t4;
    const T t18 = t7 * t5;
    const T t19 = t10 * t8;
    const T t20 = T(128) * b * t18 + T(128) * a_minus_b * t19 + T(3) * t15 * t11 * a;
    const T t21 = t20 * b * t11 + T(128) * t18 - T(128) * t19;
    const T t22 = T(10) * t15 * t11 + T(6) * b * t21 * t4 - T(3) * t20 * c * t11;
    const T t23 = T(3) * c * t21 * t4 - T(10) * t16 * t4 - T(2) * b * t22 * t4;
    G_ap = (T(1) / T(1280)) * in.w[1] * t21 * t4 + (T(1) / T(1280)) * t20 * in.w[0] * t11 + (T(1) / T(3840)) * in.w[2] * t22 * t4 - (T(1) / T(3840)) * t23 * t4 * in.w[3];
    G_ab = (T(1) / T(3840)) * in.w[1] * t22 * t4 + (T(1) / T(1280)) * in.w[0] * t21 * t4 - (T(1) / T(3840)) * (T(2) * b * t23 * t4 + c * t22 * t4 - T(10) * t17 * t4) * t4 * in.w[3] - (T(1) / T(3840)) * t23 * in.w[2] * t4;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t5 * t5;
    F = (T(1) / T(315)) * t2 * in.w[0] * (T(8) * t2 * a * (T(5) * t6 * a_minus_b * t3 + T(5) * t10 * t7 * b + T(2) * t2 * a * (T(3) * t5 * a_minus_b * t3 + T(4) * t2 * a * (t8 * t7 * b + t4 * a_minus_b * t3 + T(2) * t2 * a * (t7 * b + a_minus_b * t3)) + T(3) * t9 * t7 * b)) + T(35) * t11 * t7 * b + T(35) * t12 * a_minus_b * t3);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 44 +, 111 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t13 = t12 * t8;
    const T t14 = t6 * t4;
    const T t15 = T(2) * a * t2 * (T(35) * t3 * t6 * b + T(8) * (T(5) * t7 * a_minus_b * t10 + T(5) * t3 * t11 * b + T(2) * a * t2 * (T(3) * t7 * a_minus_b * t9 + T(4) * a * t2 * (t3 * t4 * b + T(2) * a * t2 * (t3 * b + t7 * a_minus_b) + t7 * a_minus_b * t8) + T(3) * t3 * t5 * b)) * a * t2 + T(35) * t7 * a_minus_b * t12) + T(63) * t7 * a_minus_b * t13 + T(63) * t3 * t14 * b;
    G_ap = (T(1) / T(693)) * t2 * in.w[0] * t15;
    G_ab = -(T(1) / T(693)) * (T(63) * t7 * t13 - T(63) * t3 * t14 - t2 * b * t15) * in.w[0] / a;
  }
  const T g_factor = -T(11) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 44 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T a = ab_ab * in.s;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t4 * t3;
    const T t12 = t9 * t9;
    const T t13 = T(35) * t2 * a_minus_b * t5 + T(8) * t6 * a * (T(5) * b * t10 * t7 + T(2) * (T(3) * b * t9 * t7 + T(3) * t2 * a_minus_b * t4 + T(4) * (t2 * a_minus_b * t3 + b * t8 * t7 + T(2) * (b * t7 + t2 * a_minus_b) * t6 * a) * t6 * a) * t6 * a + T(5) * t2 * a_minus_b * t11) + T(35) * b * t12 * t7;
    F = (T(1) / T(315)) * t13 * t6 * in.w[0];
    const T t14 = t5 * t3;
    const T t15 = t12 * t8;
    const T t16 = T(63) * t2 * a_minus_b * t14 + T(63) * b * t15 * t7 + T(2) * t13 * t6 * a;
    G_ap = (T(1) / T(693)) * t16 * t6 * in.w[0];
    G_ab = -(T(1) / T(693)) * (T(63) * t2 * t14 - T(63) * t15 * t7 - t16 * b * t6) * in.w[0] / a;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 40 +, 90 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = t5 * t4;
    const T t11 = t5 * t5;
    const T t12 = t8 * t8;
    const T t13 = T(8) * t2 * a * (T(2) * t2 * a * (T(3) * t3 * a_minus_b * t5 + T(3) * b * t8 * t6 + T(4) * (b * t7 * t6 + t3 * a_minus_b * t4 + T(2) * (b * t6 + t3 * a_minus_b) * t2 * a) * t2 * a) + T(5) * b * t9 * t6 + T(5) * t3 * a_minus_b * t10) + T(35) * t3 * a_minus_b * t11 + T(35) * b * t12 * t6;
    F = (T(1) / T(315)) * in.w[0] * t13 * t2 - (T(1) / T(315)) * in.w[1] * (T(35) * t3 * t11 - T(35) * t12 * t6 - b * t13 * t2) / a;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t8 * t7;
    const T t12 = t4 * t3;
    const T t13 = T(35) * t2 * a_minus_b * t5 + T(35) * b * t6 * t9 + T(8) * t10 * (T(2) * t10 * a * (T(4) * (t2 * a_minus_b * t3 + b * t6 * t7 + T(2) * t10 * a * (t2 * a_minus_b + b * t6)) * t10 * a + T(3) * t2 * a_minus_b * t4 + T(3) * b * t6 * t8) + T(5) * b * t6 * t11 + T(5) * t2 * a_minus_b * t12) * a;
    const T t14 = t5 * t3;
    const T t15 = t9 * t7;
    const T t16 = T(2) * t13 * t10 * a + T(63) * t2 * a_minus_b * t14 + T(63) * b * t6 * t15;
    const T t17 = T(63) * t2 * t14 - T(63) * t6 * t15 - t16 * b * t10;
    const T t18 = T(1) / a;
    G_ap = (T(1) / T(693)) * t16 * in.w[0] * t10 - (T(1) / T(693)) * t17 * t18 * in.w[1];
    G_ab = -(T(1) / T(3465)) * (T(10) * b * t17 * t18 + T(5) * t16 * c * t10 - T(11) * t13 * t10) * t18 * in.w[1] - (T(1) / T(693)) * in.w[0] * t17 * t18;
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = t5 * t4;
    const T t13 = T(35) * a_minus_b * t6 * t3 + T(35) * b * t10 * t7 + T(8) * (T(5) * b * t11 * t7 + T(5) * a_minus_b * t12 * t3 + T(2) * (T(3) * a_minus_b * t5 * t3 + T(3) * b * t9 * t7 + T(4) * (T(2) * (a_minus_b * t3 + b * t7) * a * t2 + a_minus_b * t4 * t3 + b * t8 * t7) * a * t2) * a * t2) * a * t2;
    const T t14 = T(1) / a;
    F = (T(1) / T(315)) * in.w[0] * t2 * t13 - (T(1) / T(315)) * (T(35) * t6 * t3 - T(35) * t10 * t7 - b * t2 * t13) * t14 * in.w[1];
    const T t15 = t10 * t8;
    const T t16 = t6 * t4;
    const T t17 = T(2) * a * t2 * t13 + T(63) * a_minus_b * t16 * t3 + T(63) * b * t15 * t7;
    const T t18 = T(63) * t15 * t7 + b * t17 * t2 - T(63) * t16 * t3;
    G_ap = (T(1) / T(693)) * t18 * t14 * in.w[1] + (T(1) / T(693)) * in.w[0] * t17 * t2;
    G_ab = (T(1) / T(693)) * t18 * in.w[0] * t14 + (T(1) / T(3465)) * (T(10) * t18 * b * t14 + T(11) * t2 * t13 - T(5) * c * t17 * t2) * t14 * in.w[1];
  }
  const T g_factor = -T(11) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
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
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
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
    const T t13 = T(1) / D;
    const T t14 = T(5) * a_minus_b * t11 * t7 + T(5) * t12 * t3 * b + T(2) * a * t13 * (T(3) * a_minus_b * t9 * t7 + T(4) * a * t13 * (t4 * t3 * b + T(2) * a * t13 * (a_minus_b * t7 + t3 * b) + a_minus_b * t8 * t7) + T(3) * t5 * t3 * b);
    const T t15 = T(35) * t6 * t3 * b + T(35) * a_minus_b * t10 * t7 + T(8) * t14 * a * t13;
    const T t16 = T(35) * t6 * t3 + t15 * t13 * b - T(35) * t10 * t7;
    F = (T(1) / T(315)) * t2 * in.w[2] * (T(2) * t2 * b * t16 + T(9) * t14 * t13 - c * t15 * t13) + (T(1) / T(315)) * t15 * t13 * in.w[0] + (T(1) / T(315)) * in.w[1] * t2 * t16;
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / D;
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
    const T t14 = t12 * t12;
    const T t15 = T(35) * a_minus_b * t7 * t4 + T(8) * (T(5) * a_minus_b * t9 * t4 + T(5) * b * t10 * t13 + T(2) * t3 * a * (T(3) * a_minus_b * t6 * t4 + T(3) * b * t10 * t12 + T(4) * t3 * a * (b * t10 * t11 + T(2) * t3 * a * (b * t10 + a_minus_b * t4) + a_minus_b * t5 * t4))) * t3 * a + T(35) * b * t10 * t14;
    const T t16 = t14 * t11;
    const T t17 = T(63) * a_minus_b * t8 * t4 + T(2) * t3 * a * t15 + T(63) * b * t10 * t16;
    const T t18 = t3 * t17 * b + T(63) * t10 * t16 - T(63) * t8 * t4;
    const T t19 = T(11) * t3 * t15 + T(10) * t2 * t18 * b - T(5) * t3 * t17 * c;
    G_ap = (T(1) / T(693)) * t2 * t18 * in.w[1] + (T(1) / T(3465)) * in.w[2] * t2 * t19 + (T(1) / T(693)) * t3 * t17 * in.w[0];
    G_ab = (T(1) / T(3465)) * in.w[2] * t2 * (T(11) * t2 * (T(35) * t10 * t14 + t3 * b * t15 - T(35) * t7 * t4) + T(2) * t2 * b * t19 - T(5) * t2 * t18 * c) + (T(1) / T(693)) * t2 * t18 * in.w[0] + (T(1) / T(3465)) * t2 * in.w[1] * t19;
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ap = in.w[2] * M_beyond[6] + in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
    G_ab = M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / D;
    const T t11 = t4 * t3;
    const T t12 = T(5) * b * t9 * t6 + T(2) * (T(4) * (t2 * a_minus_b * t3 + T(2) * (b * t6 + t2 * a_minus_b) * t10 * a + b * t7 * t6) * t10 * a + T(3) * b * t8 * t6 + T(3) * t2 * a_minus_b * t4) * t10 * a + T(5) * t2 * a_minus_b * t11;
    const T t13 = t8 * t8;
    const T t14 = T(35) * t2 * a_minus_b * t5 + T(8) * t12 * t10 * a + T(35) * b * t13 * t6;
    const T t15 = T(35) * t2 * t5 - T(35) * t13 * t6 - b * t14 * t10;
    const T t16 = T(1) / a;
    F = (T(1) / T(315)) * in.w[0] * t14 * t10 - (T(1) / T(315)) * t15 * in.w[1] * t16 - (T(1) / T(315)) * (c * t14 * t10 + T(2) * b * t15 * t16 - T(9) * t12 * t10) * in.w[2] * t16;
    const T t17 = t5 * t3;
    const T t18 = t13 * t7;
    const T t19 = T(2) * t14 * t10 * a + T(63) * t2 * a_minus_b * t17 + T(63) * b * t18 * t6;
    const T t20 = T(63) * t2 * t17 - T(63) * t18 * t6 - b * t19 * t10;
    const T t21 = T(10) * b * t20 * t16 + T(5) * t19 * c * t10 - T(11) * t14 * t10;
    G_ap = (T(1) / T(693)) * in.w[0] * t19 * t10 - (T(1) / T(3465)) * t21 * in.w[2] * t16 - (T(1) / T(693)) * in.w[1] * t20 * t16;
    G_ab = -(T(1) / T(3465)) * (T(11) * t15 * t16 + T(2) * b * t21 * t16 - T(5) * c * t20 * t16) * in.w[2] * t16 - (T(1) / T(693)) * in.w[0] * t20 * t16 - (T(1) / T(3465)) * in.w[1] * t21 * t16;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t4 * t3;
    const T t12 = T(5) * t10 * t7 * b + T(5) * a_minus_b * t11 * t2 + T(2) * t6 * a * (T(3) * a_minus_b * t4 * t2 + T(4) * t6 * a * (T(2) * t6 * a * (a_minus_b * t2 + t7 * b) + t8 * t7 * b + a_minus_b * t3 * t2) + T(3) * t9 * t7 * b);
    const T t13 = t9 * t9;
    const T t14 = T(35) * a_minus_b * t5 * t2 + T(8) * t6 * a * t12 + T(35) * t13 * t7 * b;
    const T t15 = T(35) * t13 * t7 + t14 * t6 * b - T(35) * t5 * t2;
    const T t16 = T(1) / a;
    const T t17 = T(2) * t15 * t16 * b + T(9) * t6 * t12 - c * t14 * t6;
    F = (T(1) / T(315)) * t14 * t6 * in.w[0] + (T(1) / T(315)) * t15 * t16 * in.w[1] + (T(1) / T(315)) * in.w[2] * t16 * t17 + (T(1) / T(315)) * in.w[3] * t16 * (T(9) * (t6 * t12 * b + T(5) * t10 * t7 - T(5) * t11 * t2) * t16 + T(2) * t16 * b * t17 - c * t15 * t16);
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1] + M_beyond[4] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / D;
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
    const T t14 = t6 * t5;
    const T t15 = t11 * t10;
    const T t16 = T(2) * (T(4) * t3 * a * (b * t9 * t10 + t4 * a_minus_b * t5 + T(2) * (b * t9 + t4 * a_minus_b) * t3 * a) + T(3) * t4 * a_minus_b * t6 + T(3) * b * t9 * t11) * t3 * a + T(5) * t4 * a_minus_b * t14 + T(5) * b * t9 * t15;
    const T t17 = T(35) * t4 * a_minus_b * t7 + T(35) * b * t9 * t12 + T(8) * t16 * t3 * a;
    const T t18 = T(63) * t4 * a_minus_b * t8 + T(63) * b * t9 * t13 + T(2) * t17 * t3 * a;
    const T t19 = t3 * b * t18 + T(63) * t9 * t13 - T(63) * t4 * t8;
    const T t20 = T(11) * t17 * t3 + T(10) * t2 * b * t19 - T(5) * t3 * c * t18;
    const T t21 = t17 * t3 * b + T(35) * t9 * t12 - T(35) * t4 * t7;
    const T t22 = T(11) * t2 * t21 + T(2) * t2 * t20 * b - T(5) * t2 * t19 * c;
    G_ap = (T(1) / T(693)) * t2 * in.w[1] * t19 + (T(1) / T(3465)) * in.w[2] * t2 * t20 + (T(1) / T(693)) * t3 * in.w[0] * t18 + (T(1) / T(3465)) * t2 * in.w[3] * t22;
    G_ab = (T(1) / T(3465)) * t2 * t20 * in.w[1] + (T(1) / T(693)) * t2 * in.w[0] * t19 + (T(1) / T(3465)) * in.w[2] * t2 * t22 + (T(1) / T(3465)) * (T(2) * t2 * t22 * b + T(11) * t2 * (T(2) * t2 * t21 * b + T(9) * t16 * t3 - t17 * t3 * c) - t2 * t20 * c) * t2 * in.w[3];
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[3] * in.w[3] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[6] + in.w[2] * M_beyond[7] + M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0];
    G_ab = M_beyond[6] * in.w[0] + M_beyond[8] * in.w[2] + M_beyond[9] * in.w[3] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t4;
    const T t10 = t8 * t7;
    const T t11 = T(2) * t2 * a * (T(3) * t5 * a_minus_b * t3 + T(3) * t8 * t6 * b + T(4) * t2 * a * (t7 * t6 * b + t4 * a_minus_b * t3 + T(2) * (a_minus_b * t3 + t6 * b) * t2 * a)) + T(5) * t9 * a_minus_b * t3 + T(5) * t10 * t6 * b;
    const T t12 = t5 * t5;
    const T t13 = t8 * t8;
    const T t14 = T(8) * t11 * t2 * a + T(35) * t12 * a_minus_b * t3 + T(35) * t13 * t6 * b;
    const T t15 = T(1) / a;
    const T t16 = T(35) * t12 * t3 - T(35) * t13 * t6 - t2 * t14 * b;
    const T t17 = c * t2 * t14 + T(2) * t16 * t15 * b - T(9) * t11 * t2;
    F = (T(1) / T(315)) * t2 * in.w[0] * t14 + (T(1) / T(315)) * (T(9) * (t11 * t2 * b + T(5) * t10 * t6 - T(5) * t9 * t3) * t15 + c * t16 * t15 - T(2) * t17 * t15 * b) * t15 * in.w[3] - (T(1) / T(315)) * in.w[2] * t17 * t15 - (T(1) / T(315)) * in.w[1] * t16 * t15;
    const T t18 = t12 * t4;
    const T t19 = t13 * t7;
    const T t20 = T(63) * t18 * a_minus_b * t3 + T(63) * t19 * t6 * b + T(2) * t2 * a * t14;
    const T t21 = t20 * t2 * b + T(63) * t19 * t6 - T(63) * t18 * t3;
    const T t22 = T(11) * t2 * t14 + T(10) * t21 * t15 * b - T(5) * c * t20 * t2;
    const T t23 = T(2) * t22 * t15 * b - T(5) * c * t21 * t15 - T(11) * t16 * t15;
    G_ap = (T(1) / T(693)) * t20 * t2 * in.w[0] + (T(1) / T(693)) * in.w[1] * t21 * t15 + (T(1) / T(3465)) * in.w[2] * t22 * t15 + (T(1) / T(3465)) * t23 * t15 * in.w[3];
    G_ab = (T(1) / T(3465)) * in.w[1] * t22 * t15 + (T(1) / T(3465)) * t23 * in.w[2] * t15 + (T(1) / T(693)) * t21 * t15 * in.w[0] - (T(1) / T(3465)) * (c * t22 * t15 + T(11) * t17 * t15 - T(2) * t23 * t15 * b) * t15 * in.w[3];
  }
  const T g_factor = -T(11) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t8 * t7;
    const T t12 = t5 * t4;
    const T t13 = t6 * t4;
    const T t14 = t9 * t7;
    F = (T(1) / T(1280)) * (T(3) * (T(48) * b * t6 + T(48) * a_minus_b * t9 + T(7) * (T(5) * (T(3) * (b * t4 + a_minus_b * t7 + J2 * a) * t10 * a + T(2) * a_minus_b * t8 + T(2) * b * t5) * t10 * a + T(8) * a_minus_b * t11 + T(8) * b * t12) * t10 * a) * t10 * a + T(128) * b * t13 + T(128) * a_minus_b * t14) * t10 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 48 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
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
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t5;
    const T t12 = t9 * t9;
    const T t13 = t12 * t8;
    const T t14 = t11 * t4;
    const T t15 = t6 * t6;
    const T t16 = t10 * t10;
    const T t17 = T(11) * (T(3) * (T(7) * (T(8) * t6 * b + T(5) * (T(3) * a * t7 * (a_minus_b * t8 + J2 * a + t4 * b) + T(2) * t5 * b + T(2) * a_minus_b * t9) * a * t7 + T(8) * a_minus_b * t10) * a * t7 + T(48) * t11 * b + T(48) * a_minus_b * t12) * a * t7 + T(128) * a_minus_b * t13 + T(128) * t14 * b) * a * t7 + T(1280) * t15 * b + T(1280) * a_minus_b * t16;
    G_ap = (T(1) / T(15360)) * t17 * t7 * in.w[0];
    G_ab = (T(1) / T(15360)) * (T(1280) * t15 + t17 * t7 * b - T(1280) * t16) * in.w[0] / a;
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 48 +, 111 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t10 * t9;
    const T t14 = t6 * t5;
    const T t15 = T(128) * t8 * b + T(128) * a_minus_b * t12 + T(3) * (T(48) * a_minus_b * t11 + T(48) * t7 * b + T(7) * t4 * a * (T(5) * (T(3) * t4 * a * (t5 * b + a_minus_b * t9 + J2 * a) + T(2) * a_minus_b * t10 + T(2) * t6 * b) * t4 * a + T(8) * a_minus_b * t13 + T(8) * t14 * b)) * t4 * a;
    F = (T(1) / T(1280)) * in.w[0] * t4 * t15;
    const T t16 = t13 * t13;
    const T t17 = t14 * t14;
    const T t18 = T(1280) * a_minus_b * t16 + T(1280) * t17 * b + T(11) * t4 * a * t15;
    G_ap = (T(1) / T(15360)) * in.w[0] * t4 * t18;
    G_ab = (T(1) / T(15360)) * in.w[0] * (t4 * t18 * b + T(1280) * t17 - T(1280) * t16) / a;
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 44 +, 88 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t6 * t5;
    const T t14 = t10 * t9;
    const T t15 = T(128) * t8 * b + T(128) * t12 * a_minus_b + T(3) * t4 * (T(48) * t7 * b + T(48) * t11 * a_minus_b + T(7) * t4 * a * (T(5) * (T(3) * t4 * (t9 * a_minus_b + t5 * b + a * J2) * a + T(2) * t6 * b + T(2) * t10 * a_minus_b) * t4 * a + T(8) * t13 * b + T(8) * t14 * a_minus_b)) * a;
    F = (T(1) / T(1280)) * in.w[0] * t4 * t15 + (T(1) / T(1280)) * in.w[1] * (T(128) * t8 + t4 * b * t15 - T(128) * t12) / a;
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = t6 * t5;
    const T t13 = t7 * t5;
    const T t14 = t10 * t8;
    const T t15 = T(3) * (T(48) * b * t7 + T(48) * t10 * a_minus_b + T(7) * (T(8) * t11 * a_minus_b + T(5) * (T(2) * t9 * a_minus_b + T(2) * b * t6 + T(3) * (b * t5 + J2 * a + t8 * a_minus_b) * t4 * a) * t4 * a + T(8) * b * t12) * t4 * a) * t4 * a + T(128) * b * t13 + T(128) * t14 * a_minus_b;
    const T t16 = t12 * t12;
    const T t17 = t11 * t11;
    const T t18 = T(11) * t15 * t4 * a + T(1280) * b * t16 + T(1280) * t17 * a_minus_b;
    const T t19 = T(1) / a;
    const T t20 = T(1280) * t17 - T(1280) * t16 - b * t4 * t18;
    G_ap = (T(1) / T(15360)) * in.w[0] * t4 * t18 - (T(1) / T(15360)) * in.w[1] * t19 * t20;
    G_ab = -(T(1) / T(15360)) * in.w[1] * t19 * (T(2) * b * t19 * t20 + c * t4 * t18 - T(12) * t15 * t4) - (T(1) / T(15360)) * in.w[0] * t19 * t20;
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = in.w[0] * M_beyond[4] + in.w[1] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t6 * t5;
    const T t15 = t12 * t10;
    const T t16 = T(128) * a_minus_b * t8 + T(3) * t9 * a * (T(48) * a_minus_b * t7 + T(48) * b * t12 + T(7) * t9 * a * (T(8) * b * t13 + T(5) * t9 * a * (T(2) * b * t11 + T(3) * t9 * a * (a_minus_b * t5 + b * t10 + a * J2) + T(2) * a_minus_b * t6) + T(8) * a_minus_b * t14)) + T(128) * b * t15;
    F = (T(1) / T(1280)) * in.w[1] * t4 * (t16 * t9 * b + T(128) * t15 - T(128) * t8) + (T(1) / T(1280)) * t16 * t9 * in.w[0];
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = T(1280) * a_minus_b * t17 + T(11) * t16 * t9 * a + T(1280) * b * t18;
    const T t20 = t9 * t19 * b + T(1280) * t18 - T(1280) * t17;
    G_ap = (T(1) / T(15360)) * t20 * in.w[1] * t4 + (T(1) / T(15360)) * t9 * t19 * in.w[0];
    G_ab = (T(1) / T(15360)) * in.w[1] * t4 * (T(12) * t16 * t9 + T(2) * t20 * t4 * b - t9 * t19 * c) + (T(1) / T(15360)) * t20 * t4 * in.w[0];
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t6 * t5;
    const T t14 = t10 * t9;
    const T t15 = T(48) * b * t7 + T(7) * (T(8) * b * t13 + T(5) * (T(2) * b * t6 + T(3) * t4 * a * (a_minus_b * t9 + a * J2 + b * t5) + T(2) * a_minus_b * t10) * t4 * a + T(8) * a_minus_b * t14) * t4 * a + T(48) * a_minus_b * t11;
    const T t16 = T(128) * b * t8 + T(128) * a_minus_b * t12 + T(3) * t4 * a * t15;
    const T t17 = b * t4 * t16 + T(128) * t8 - T(128) * t12;
    const T t18 = T(1) / a;
    F = (T(1) / T(1280)) * t17 * in.w[1] * t18 + (T(1) / T(3840)) * in.w[2] * (T(10) * t4 * t15 + T(6) * b * t17 * t18 - T(3) * c * t4 * t16) * t18 + (T(1) / T(1280)) * in.w[0] * t4 * t16;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    const T t9 = t8 * t4;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t11 * t10;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = T(128) * t9 * a_minus_b + T(3) * (T(48) * t8 * a_minus_b + T(7) * (T(5) * (T(2) * t5 * a_minus_b + T(2) * b * t11 + T(3) * (b * t10 + t4 * a_minus_b + J2 * a) * t12 * a) * t12 * a + T(8) * b * t13 + T(8) * t6 * a_minus_b) * t12 * a + T(48) * b * t14) * t12 * a + T(128) * b * t15;
    const T t17 = t13 * t13;
    const T t18 = T(1280) * t7 * a_minus_b + T(11) * t16 * t12 * a + T(1280) * b * t17;
    const T t19 = T(1280) * t7 - b * t18 * t12 - T(1280) * t17;
    const T t20 = T(1) / a;
    const T t21 = T(12) * t16 * t12 - T(2) * b * t19 * t20 - t18 * c * t12;
    G_ap = (T(1) / T(15360)) * t18 * in.w[0] * t12 + (T(1) / T(15360)) * t21 * t20 * in.w[2] - (T(1) / T(15360)) * in.w[1] * t19 * t20;
    G_ab = (T(1) / T(15360)) * t20 * (c * t19 * t20 + T(2) * b * t21 * t20 - T(12) * (T(128) * t9 - b * t16 * t12 - T(128) * t15) * t20) * in.w[2] + (T(1) / T(15360)) * in.w[1] * t21 * t20 - (T(1) / T(15360)) * in.w[0] * t19 * t20;
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
    G_ab = in.w[0] * M_beyond[5] + M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t6 * t5;
    const T t12 = t9 * t9;
    const T t13 = T(48) * t7 * a_minus_b + T(7) * t4 * a * (T(5) * (T(3) * (t5 * a_minus_b + b * t8 + J2 * a) * t4 * a + T(2) * b * t9 + T(2) * t6 * a_minus_b) * t4 * a + T(8) * b * t10 + T(8) * t11 * a_minus_b) + T(48) * b * t12;
    const T t14 = t7 * t5;
    const T t15 = t12 * t8;
    const T t16 = T(3) * t4 * a * t13 + T(128) * t14 * a_minus_b + T(128) * b * t15;
    const T t17 = T(1) / a;
    const T t18 = b * t16 * t4 + T(128) * t15 - T(128) * t14;
    F = (T(1) / T(1280)) * in.w[0] * t16 * t4 + (T(1) / T(1280)) * in.w[1] * t17 * t18 - (T(1) / T(3840)) * (T(3) * t16 * c * t4 - T(10) * t4 * t13 - T(6) * b * t17 * t18) * t17 * in.w[2];
    const T t19 = t11 * t11;
    const T t20 = t10 * t10;
    const T t21 = T(1280) * t19 * a_minus_b + T(11) * t16 * t4 * a + T(1280) * b * t20;
    const T t22 = T(1280) * t19 - t21 * b * t4 - T(1280) * t20;
    const T t23 = t21 * c * t4 + T(2) * b * t17 * t22 - T(12) * t16 * t4;
    G_ap = (T(1) / T(15360)) * t21 * in.w[0] * t4 - (T(1) / T(15360)) * in.w[1] * t17 * t22 - (T(1) / T(15360)) * t23 * t17 * in.w[2];
    G_ab = (T(1) / T(15360)) * (c * t17 * t22 + T(12) * t17 * t18 - T(2) * b * t23 * t17) * t17 * in.w[2] - (T(1) / T(15360)) * in.w[0] * t17 * t22 - (T(1) / T(15360)) * t23 * in.w[1] * t17;
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
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
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / D;
    const T t14 = t6 * t5;
    const T t15 = t10 * t9;
    const T t16 = T(48) * a_minus_b * t7 + T(7) * t13 * (T(8) * a_minus_b * t14 + T(5) * (T(3) * t13 * a * (a * J2 + b * t9 + a_minus_b * t5) + T(2) * a_minus_b * t6 + T(2) * b * t10) * t13 * a + T(8) * b * t15) * a + T(48) * b * t11;
    const T t17 = T(128) * a_minus_b * t8 + T(128) * b * t12 + T(3) * t16 * t13 * a;
    const T t18 = b * t17 * t13 + T(128) * t12 - T(128) * t8;
    const T t19 = T(3) * c * t17 * t13 - T(6) * b * t4 * t18 - T(10) * t16 * t13;
    F = (T(1) / T(1280)) * in.w[1] * t4 * t18 + (T(1) / T(1280)) * t17 * t13 * in.w[0] - (T(1) / T(3840)) * t19 * in.w[2] * t4 - (T(1) / T(3840)) * (T(3) * c * t4 * t18 + T(10) * (T(48) * t7 - T(48) * t11 - b * t16 * t13) * t4 + T(2) * b * t19 * t4) * t4 * in.w[3];
  }
  f = length * F;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + M_beyond[2] * in.w[1];
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
    const T t11 = t6 * t6;
    const T t12 = t9 * t9;
    const T t13 = T(7) * t4 * a * (T(8) * a_minus_b * t7 + T(8) * t10 * b + T(5) * (T(3) * (a * J2 + t8 * b + a_minus_b * t5) * t4 * a + T(2) * a_minus_b * t6 + T(2) * t9 * b) * t4 * a) + T(48) * a_minus_b * t11 + T(48) * t12 * b;
    const T t14 = t11 * t5;
    const T t15 = t12 * t8;
    const T t16 = T(3) * t13 * t4 * a + T(128) * a_minus_b * t14 + T(128) * t15 * b;
    const T t17 = t7 * t7;
    const T t18 = t10 * t10;
    const T t19 = T(11) * t4 * a * t16 + T(1280) * a_minus_b * t17 + T(1280) * t18 * b;
    const T t20 = T(1) / a;
    const T t21 = T(128) * t15 + t4 * b * t16 - T(128) * t14;
    const T t22 = T(1280) * t17 - T(1280) * t18 - t19 * t4 * b;
    const T t23 = c * t19 * t4 + T(2) * t22 * t20 * b - T(12) * t4 * t16;
    const T t24 = T(12) * t20 * t21 + c * t22 * t20 - T(2) * t23 * t20 * b;
    G_ap = (T(1) / T(15360)) * t19 * t4 * in.w[0] + (T(1) / T(15360)) * t24 * in.w[3] * t20 - (T(1) / T(15360)) * t22 * t20 * in.w[1] - (T(1) / T(15360)) * in.w[2] * t23 * t20;
    G_ab = (T(1) / T(15360)) * in.w[2] * t24 * t20 + (T(1) / T(15360)) * (T(2) * t24 * t20 * b + T(4) * t20 * (T(6) * t20 * t21 * b + T(10) * t13 * t4 - T(3) * c * t4 * t16) + c * t23 * t20) * in.w[3] * t20 - (T(1) / T(15360)) * t22 * t20 * in.w[0] - (T(1) / T(15360)) * t23 * t20 * in.w[1];
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[3] * M_beyond[3];
    G_ap = M_beyond[5] * in.w[0] + M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1];
    G_ab = in.w[0] * M_beyond[6] + M_beyond[8] * in.w[2] + in.w[1] * M_beyond[7] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    const T t14 = T(48) * a_minus_b * t7 + T(48) * b * t11 + T(7) * t4 * a * (T(8) * a_minus_b * t12 + T(5) * (T(2) * a_minus_b * t6 + T(3) * t4 * (b * t9 + a * J2 + a_minus_b * t5) * a + T(2) * b * t10) * t4 * a + T(8) * b * t13);
    const T t15 = t11 * t9;
    const T t16 = T(128) * a_minus_b * t8 + T(3) * t4 * a * t14 + T(128) * b * t15;
    const T t17 = T(1) / a;
    const T t18 = T(128) * t8 - T(128) * t15 - t4 * t16 * b;
    const T t19 = T(3) * t4 * t16 * c + T(6) * t18 * t17 * b - T(10) * t4 * t14;
    F = (T(1) / T(1280)) * t4 * t16 * in.w[0] - (T(1) / T(3840)) * t17 * t19 * in.w[2] - (T(1) / T(3840)) * in.w[3] * t17 * (T(2) * t17 * b * t19 + T(10) * t17 * (T(48) * t7 - T(48) * t11 - t4 * b * t14) - T(3) * t18 * t17 * c) - (T(1) / T(1280)) * t18 * t17 * in.w[1];
    const T t20 = t12 * t12;
    const T t21 = t13 * t13;
    const T t22 = T(11) * t4 * t16 * a + T(1280) * a_minus_b * t20 + T(1280) * b * t21;
    const T t23 = T(1280) * t20 - T(1280) * t21 - t4 * b * t22;
    const T t24 = t4 * t22 * c + T(2) * t17 * b * t23 - T(12) * t4 * t16;
    const T t25 = T(12) * t18 * t17 + T(2) * t24 * t17 * b - t17 * c * t23;
    G_ap = (T(1) / T(15360)) * t4 * in.w[0] * t22 - (T(1) / T(15360)) * in.w[3] * t17 * t25 - (T(1) / T(15360)) * t24 * t17 * in.w[2] - (T(1) / T(15360)) * t17 * in.w[1] * t23;
    G_ab = (T(1) / T(15360)) * in.w[3] * t17 * (t24 * t17 * c - T(2) * t17 * b * t25 - T(4) * t17 * t19) - (T(1) / T(15360)) * t17 * t25 * in.w[2] - (T(1) / T(15360)) * t17 * in.w[0] * t23 - (T(1) / T(15360)) * t24 * t17 * in.w[1];
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t5;
    const T t12 = t9 * t9;
    const T t13 = t11 * t4;
    const T t14 = t12 * t8;
    F = (T(1) / T(693)) * t2 * in.w[0] * (T(2) * (T(8) * (T(5) * t6 * t3 * b + T(5) * t7 * a_minus_b * t10 + T(2) * t2 * a * (T(4) * t2 * a * (t4 * t3 * b + t7 * a_minus_b * t8 + T(2) * (t3 * b + t7 * a_minus_b) * t2 * a) + T(3) * t5 * t3 * b + T(3) * t7 * a_minus_b * t9)) * t2 * a + T(35) * t11 * t3 * b + T(35) * t7 * a_minus_b * t12) * t2 * a + T(63) * t13 * t3 * b + T(63) * t7 * a_minus_b * t14);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 46 +, 122 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
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
    const T t13 = t5 * t5;
    const T t14 = t10 * t10;
    const T t15 = t13 * t4;
    const T t16 = t14 * t9;
    const T t17 = T(231) * b * t3 * t7 + T(231) * a_minus_b * t12 * t8 + T(4) * t2 * a * (T(2) * t2 * a * (T(35) * b * t3 * t13 + T(8) * t2 * a * (T(5) * b * t3 * t6 + T(5) * a_minus_b * t11 * t8 + T(2) * t2 * a * (T(4) * t2 * (a_minus_b * t9 * t8 + b * t3 * t4 + T(2) * t2 * a * (a_minus_b * t8 + b * t3)) * a + T(3) * b * t3 * t5 + T(3) * a_minus_b * t10 * t8)) + T(35) * a_minus_b * t14 * t8) + T(63) * b * t3 * t15 + T(63) * a_minus_b * t16 * t8);
    G_ap = (T(1) / T(3003)) * t2 * in.w[0] * t17;
    G_ab = -(T(1) / T(3003)) * in.w[0] * (T(231) * t12 * t8 - T(231) * t3 * t7 - t2 * b * t17) / a;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 46 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t5 * t5;
    const T t13 = t11 * t8;
    const T t14 = t12 * t4;
    const T t15 = T(2) * a * t2 * (T(8) * a * t2 * (T(5) * t6 * t3 * a_minus_b + T(5) * t10 * t7 * b + T(2) * (T(4) * a * t2 * (t8 * t7 * b + t4 * t3 * a_minus_b + T(2) * a * (t7 * b + t3 * a_minus_b) * t2) + T(3) * t9 * t7 * b + T(3) * t5 * t3 * a_minus_b) * a * t2) + T(35) * t11 * t7 * b + T(35) * t12 * t3 * a_minus_b) + T(63) * t13 * t7 * b + T(63) * t14 * t3 * a_minus_b;
    F = (T(1) / T(693)) * t15 * t2 * in.w[0];
    const T t16 = t10 * t10;
    const T t17 = t6 * t6;
    const T t18 = T(4) * t15 * a * t2 + T(231) * t16 * t7 * b + T(231) * t17 * t3 * a_minus_b;
    G_ap = (T(1) / T(3003)) * t2 * in.w[0] * t18;
    G_ab = -(T(1) / T(3003)) * (T(231) * t17 * t3 - t2 * b * t18 - T(231) * t16 * t7) * in.w[0] / a;
  }
  const T g_factor = -T(13) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 42 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t4 * t4;
    const T t13 = t11 * t8;
    const T t14 = t12 * t3;
    const T t15 = T(2) * (T(8) * (T(5) * b * t5 * t2 + T(2) * t6 * (T(4) * (a_minus_b * t7 * t8 + T(2) * (b * t2 + a_minus_b * t7) * t6 * a + b * t3 * t2) * t6 * a + T(3) * b * t4 * t2 + T(3) * a_minus_b * t7 * t9) * a + T(5) * a_minus_b * t7 * t10) * t6 * a + T(35) * a_minus_b * t7 * t11 + T(35) * b * t12 * t2) * t6 * a + T(63) * a_minus_b * t7 * t13 + T(63) * b * t14 * t2;
    F = (T(1) / T(693)) * (b * t15 * t6 + T(63) * t14 * t2 - T(63) * t7 * t13) * in.w[1] / a + (T(1) / T(693)) * t15 * in.w[0] * t6;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t9 * t9;
    const T t14 = t4 * t4;
    const T t15 = t13 * t8;
    const T t16 = t14 * t3;
    const T t17 = T(2) * (T(8) * (T(5) * b * t7 * t10 + T(5) * t5 * t2 * a_minus_b + T(2) * (T(3) * b * t7 * t9 + T(4) * (t3 * t2 * a_minus_b + T(2) * (t2 * a_minus_b + b * t7) * a * t12 + b * t7 * t8) * a * t12 + T(3) * t4 * t2 * a_minus_b) * a * t12) * a * t12 + T(35) * b * t7 * t13 + T(35) * t14 * t2 * a_minus_b) * a * t12 + T(63) * b * t7 * t15 + T(63) * t16 * t2 * a_minus_b;
    const T t18 = T(231) * t6 * t2 * a_minus_b + T(231) * b * t7 * t11 + T(4) * a * t12 * t17;
    const T t19 = T(231) * t6 * t2 - b * t18 * t12 - T(231) * t7 * t11;
    const T t20 = T(1) / a;
    G_ap = (T(1) / T(3003)) * t18 * in.w[0] * t12 - (T(1) / T(3003)) * t19 * t20 * in.w[1];
    G_ab = -(T(1) / T(9009)) * t20 * (T(6) * b * t19 * t20 + T(3) * t18 * c * t12 - T(13) * t12 * t17) * in.w[1] - (T(1) / T(3003)) * t19 * in.w[0] * t20;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t3;
    const T t7 = T(1) / D;
    const T t8 = t4 * t3;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t13 * t10;
    const T t15 = T(63) * b * t6 * t2 + T(2) * t7 * (T(8) * (T(5) * b * t8 * t2 + T(2) * (T(4) * (b * t3 * t2 + a_minus_b * t9 * t10 + T(2) * (a_minus_b * t9 + b * t2) * t7 * a) * t7 * a + T(3) * b * t4 * t2 + T(3) * a_minus_b * t9 * t11) * t7 * a + T(5) * a_minus_b * t9 * t12) * t7 * a + T(35) * b * t5 * t2 + T(35) * a_minus_b * t9 * t13) * a + T(63) * a_minus_b * t9 * t14;
    const T t16 = T(1) / a;
    F = (T(1) / T(693)) * (b * t15 * t7 + T(63) * t6 * t2 - T(63) * t9 * t14) * in.w[1] * t16 + (T(1) / T(693)) * in.w[0] * t15 * t7;
    const T t17 = t8 * t8;
    const T t18 = t12 * t12;
    const T t19 = T(4) * t15 * t7 * a + T(231) * b * t17 * t2 + T(231) * a_minus_b * t9 * t18;
    const T t20 = t19 * b * t7 + T(231) * t17 * t2 - T(231) * t9 * t18;
    G_ap = (T(1) / T(3003)) * t20 * in.w[1] * t16 + (T(1) / T(3003)) * t19 * in.w[0] * t7;
    G_ab = (T(1) / T(9009)) * (T(6) * t20 * b * t16 + T(13) * t15 * t7 - T(3) * t19 * c * t7) * in.w[1] * t16 + (T(1) / T(3003)) * t20 * in.w[0] * t16;
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
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
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
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
    const T t15 = T(8) * (T(5) * a_minus_b * t13 * t8 + T(2) * t2 * a * (T(3) * a_minus_b * t10 * t8 + T(3) * t5 * t3 * b + T(4) * t2 * a * (t4 * t3 * b + a_minus_b * t9 * t8 + T(2) * (a_minus_b * t8 + t3 * b) * t2 * a)) + T(5) * t14 * t3 * b) * t2 * a + T(35) * t6 * t3 * b + T(35) * a_minus_b * t11 * t8;
    const T t16 = T(63) * t7 * t3 * b + T(63) * a_minus_b * t12 * t8 + T(2) * t2 * t15 * a;
    const T t17 = T(1) / a;
    const T t18 = t2 * t16 * b + T(63) * t7 * t3 - T(63) * t12 * t8;
    F = (T(1) / T(693)) * t2 * t16 * in.w[0] + (T(1) / T(693)) * in.w[1] * t17 * t18 - (T(1) / T(3465)) * in.w[2] * t17 * (T(5) * c * t2 * t16 - T(11) * t2 * t15 - T(10) * t17 * b * t18);
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t5 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t8 * t4;
    const T t15 = t13 * t10;
    const T t16 = T(2) * a * t2 * (T(35) * b * t8 * t3 + T(8) * (T(5) * t9 * a_minus_b * t12 + T(5) * b * t6 * t3 + T(2) * a * t2 * (T(4) * a * t2 * (b * t4 * t3 + t9 * a_minus_b * t10 + T(2) * a * t2 * (t9 * a_minus_b + b * t3)) + T(3) * t9 * a_minus_b * t11 + T(3) * b * t5 * t3)) * a * t2 + T(35) * t9 * a_minus_b * t13) + T(63) * b * t14 * t3 + T(63) * t9 * a_minus_b * t15;
    const T t17 = t12 * t12;
    const T t18 = T(231) * b * t7 * t3 + T(4) * a * t16 * t2 + T(231) * t9 * a_minus_b * t17;
    const T t19 = T(1) / a;
    const T t20 = T(231) * t9 * t17 - t2 * b * t18 - T(231) * t7 * t3;
    const T t21 = T(6) * t19 * t20 * b + T(3) * t2 * t18 * c - T(13) * t16 * t2;
    G_ap = (T(1) / T(3003)) * t2 * in.w[0] * t18 - (T(1) / T(3003)) * t19 * t20 * in.w[1] - (T(1) / T(9009)) * t19 * in.w[2] * t21;
    G_ab = -(T(1) / T(9009)) * (T(13) * (T(63) * t9 * t15 - t16 * t2 * b - T(63) * t14 * t3) * t19 + T(2) * t19 * b * t21 - T(3) * t19 * t20 * c) * t19 * in.w[2] - (T(1) / T(9009)) * t19 * t21 * in.w[1] - (T(1) / T(3003)) * t19 * t20 * in.w[0];
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0] + in.w[2] * M_beyond[6];
    G_ab = in.w[1] * M_beyond[6] + in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r0;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t4 * t3;
    const T t12 = t9 * t9;
    const T t13 = T(35) * b * t5 * t2 + T(8) * (T(2) * (T(4) * (T(2) * (b * t2 + a_minus_b * t6) * t7 * a + a_minus_b * t6 * t8 + b * t3 * t2) * t7 * a + T(3) * b * t4 * t2 + T(3) * a_minus_b * t6 * t9) * t7 * a + T(5) * a_minus_b * t6 * t10 + T(5) * b * t11 * t2) * t7 * a + T(35) * a_minus_b * t6 * t12;
    const T t14 = t5 * t3;
    const T t15 = t12 * t8;
    const T t16 = T(2) * t13 * t7 * a + T(63) * b * t14 * t2 + T(63) * a_minus_b * t6 * t15;
    const T t17 = T(63) * t6 * t15 - T(63) * t14 * t2 - b * t16 * t7;
    const T t18 = T(1) / a;
    F = (T(1) / T(693)) * in.w[0] * t16 * t7 + (T(1) / T(3465)) * in.w[2] * (T(11) * t13 * t7 - T(5) * c * t16 * t7 - T(10) * b * t17 * t18) * t18 - (T(1) / T(693)) * t17 * in.w[1] * t18;
    const T t19 = t11 * t11;
    const T t20 = t10 * t10;
    const T t21 = T(4) * t16 * t7 * a + T(231) * b * t19 * t2 + T(231) * a_minus_b * t6 * t20;
    const T t22 = T(231) * t6 * t20 - b * t21 * t7 - T(231) * t19 * t2;
    const T t23 = T(3) * c * t21 * t7 + T(6) * b * t22 * t18 - T(13) * t16 * t7;
    G_ap = (T(1) / T(3003)) * in.w[0] * t21 * t7 - (T(1) / T(9009)) * in.w[2] * t23 * t18 - (T(1) / T(3003)) * t22 * in.w[1] * t18;
    G_ab = (T(1) / T(9009)) * in.w[2] * (T(3) * c * t22 * t18 - T(13) * t17 * t18 - T(2) * b * t23 * t18) * t18 - (T(1) / T(3003)) * in.w[0] * t22 * t18 - (T(1) / T(9009)) * in.w[1] * t23 * t18;
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t9 * t9;
    const T t12 = t5 * t5;
    const T t13 = T(8) * (T(5) * a_minus_b * t3 * t6 + T(2) * t2 * a * (T(4) * t2 * a * (T(2) * t2 * a * (b * t7 + a_minus_b * t3) + a_minus_b * t3 * t4 + t8 * b * t7) + T(3) * t9 * b * t7 + T(3) * a_minus_b * t3 * t5) + T(5) * t10 * b * t7) * t2 * a + T(35) * t11 * b * t7 + T(35) * a_minus_b * t3 * t12;
    const T t14 = t11 * t8;
    const T t15 = t12 * t4;
    const T t16 = T(2) * t2 * t13 * a + T(63) * t14 * b * t7 + T(63) * a_minus_b * t3 * t15;
    const T t17 = T(1) / a;
    const T t18 = t2 * b * t16 + T(63) * t14 * t7 - T(63) * t3 * t15;
    const T t19 = T(5) * c * t2 * t16 - T(10) * t17 * t18 * b - T(11) * t2 * t13;
    F = (T(1) / T(693)) * t2 * in.w[0] * t16 + (T(1) / T(693)) * t17 * t18 * in.w[1] + (T(1) / T(3465)) * (T(11) * t17 * (t2 * t13 * b + T(35) * t11 * t7 - T(35) * t3 * t12) - T(2) * t19 * t17 * b - T(5) * c * t17 * t18) * t17 * in.w[3] - (T(1) / T(3465)) * in.w[2] * t19 * t17;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2] + M_beyond[4] * in.w[3];
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
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(8) * (T(5) * t11 * t8 * a_minus_b + T(5) * b * t3 * t6 + T(2) * (T(3) * b * t3 * t5 + T(4) * t2 * a * (t9 * t8 * a_minus_b + T(2) * t2 * (b * t3 + t8 * a_minus_b) * a + b * t3 * t4) + T(3) * t10 * t8 * a_minus_b) * t2 * a) * t2 * a + T(35) * b * t3 * t13 + T(35) * t15 * t8 * a_minus_b;
    const T t18 = T(63) * b * t3 * t14 + T(63) * t16 * t8 * a_minus_b + T(2) * t2 * t17 * a;
    const T t19 = T(231) * b * t3 * t7 + T(231) * t12 * t8 * a_minus_b + T(4) * t18 * t2 * a;
    const T t20 = T(63) * t16 * t8 - T(63) * t3 * t14 - t18 * b * t2;
    const T t21 = T(1) / a;
    const T t22 = T(231) * t12 * t8 - T(231) * t3 * t7 - b * t2 * t19;
    const T t23 = T(6) * b * t22 * t21 + T(3) * c * t2 * t19 - T(13) * t18 * t2;
    const T t24 = T(13) * t20 * t21 + T(2) * b * t23 * t21 - T(3) * t22 * c * t21;
    G_ap = (T(1) / T(3003)) * t2 * t19 * in.w[0] - (T(1) / T(9009)) * t24 * in.w[3] * t21 - (T(1) / T(3003)) * in.w[1] * t22 * t21 - (T(1) / T(9009)) * in.w[2] * t23 * t21;
    G_ab = (T(1) / T(45045)) * (T(13) * (T(11) * t2 * t17 - T(10) * t20 * b * t21 - T(5) * t18 * c * t2) * t21 + T(5) * c * t23 * t21 - T(10) * b * t24 * t21) * in.w[3] * t21 - (T(1) / T(9009)) * in.w[1] * t23 * t21 - (T(1) / T(3003)) * t22 * t21 * in.w[0] - (T(1) / T(9009)) * t24 * in.w[2] * t21;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6] + in.w[3] * M_beyond[8];
    G_ab = in.w[3] * M_beyond[9] + in.w[0] * M_beyond[6] + M_beyond[7] * in.w[1] + M_beyond[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / D;
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
    const T t14 = T(8) * t3 * a * (T(5) * t4 * a_minus_b * t7 + T(2) * t3 * a * (T(3) * t4 * a_minus_b * t6 + T(4) * t3 * a * (T(2) * (t4 * a_minus_b + t8 * b) * t3 * a + t8 * b * t9 + t4 * a_minus_b * t5) + T(3) * t8 * b * t10) + T(5) * t8 * b * t11) + T(35) * t4 * a_minus_b * t12 + T(35) * t8 * b * t13;
    const T t15 = t13 * t9;
    const T t16 = t12 * t5;
    const T t17 = T(2) * t3 * a * t14 + T(63) * t4 * a_minus_b * t16 + T(63) * t8 * b * t15;
    const T t18 = T(63) * t8 * t15 + t3 * b * t17 - T(63) * t4 * t16;
    const T t19 = T(11) * t3 * t14 + T(10) * t2 * t18 * b - T(5) * t3 * c * t17;
    F = (T(1) / T(3465)) * t2 * t19 * in.w[2] + (T(1) / T(693)) * t2 * t18 * in.w[1] + (T(1) / T(693)) * t3 * in.w[0] * t17 - (T(1) / T(3465)) * in.w[3] * t2 * (T(5) * t2 * t18 * c - T(11) * t2 * (T(35) * t8 * t13 + t3 * b * t14 - T(35) * t4 * t12) - T(2) * t2 * t19 * b);
    const T t20 = t11 * t11;
    const T t21 = t7 * t7;
    const T t22 = T(4) * t3 * a * t17 + T(231) * t4 * a_minus_b * t21 + T(231) * t8 * b * t20;
    const T t23 = T(231) * t8 * t20 + t3 * b * t22 - T(231) * t4 * t21;
    const T t24 = T(6) * t2 * t23 * b + T(13) * t3 * t17 - T(3) * t3 * t22 * c;
    const T t25 = T(2) * t24 * t2 * b + T(13) * t2 * t18 - T(3) * t2 * t23 * c;
    G_ap = (T(1) / T(9009)) * in.w[3] * t2 * t25 + (T(1) / T(3003)) * t2 * t23 * in.w[1] + (T(1) / T(3003)) * t3 * in.w[0] * t22 + (T(1) / T(9009)) * t24 * t2 * in.w[2];
    G_ab = (T(1) / T(9009)) * t24 * t2 * in.w[1] + (T(1) / T(3003)) * t2 * in.w[0] * t23 + (T(1) / T(45045)) * in.w[3] * t2 * (T(10) * t2 * b * t25 + T(13) * t2 * t19 - T(5) * t24 * t2 * c) + (T(1) / T(9009)) * t2 * t25 * in.w[2];
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = t13 * t5;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    F = (T(1) / T(15360)) * t4 * in.w[0] * (T(1280) * b * t8 + T(1280) * a_minus_b * t12 + T(11) * t4 * a * (T(128) * b * t14 + T(128) * a_minus_b * t16 + T(3) * t4 * a * (T(48) * b * t13 + T(48) * a_minus_b * t15 + T(7) * t4 * (T(8) * a_minus_b * t11 + T(8) * b * t7 + T(5) * t4 * a * (T(2) * b * t6 + T(2) * a_minus_b * t10 + T(3) * t4 * a * (b * t5 + a_minus_b * t9 + a * J2))) * a)));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 50 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = t5 * t5;
    const T t10 = t9 * t4;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t11;
    const T t15 = T(1) / D;
    const T t16 = t12 * t11;
    const T t17 = t16 * t16;
    const T t18 = t17 * t11;
    const T t19 = T(15360) * b * t8 + T(13) * (T(1280) * b * t7 + T(11) * (T(128) * b * t10 + T(128) * t14 * a_minus_b + T(3) * t15 * a * (T(48) * b * t9 + T(7) * (T(5) * (T(2) * t12 * a_minus_b + T(2) * b * t5 + T(3) * (b * t4 + t11 * a_minus_b + J2 * a) * t15 * a) * t15 * a + T(8) * t16 * a_minus_b + T(8) * b * t6) * t15 * a + T(48) * t13 * a_minus_b)) * t15 * a + T(1280) * t17 * a_minus_b) * t15 * a + T(15360) * t18 * a_minus_b;
    G_ap = (T(1) / T(215040)) * t19 * t15 * in.w[0];
    G_ab = (T(1) / T(215040)) * (b * t19 * t15 + T(15360) * t8 - T(15360) * t18) * in.w[0] / a;
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 50 +, 120 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t5 * t5;
    const T t14 = t9 * t9;
    const T t15 = t13 * t4;
    const T t16 = t14 * t8;
    const T t17 = T(1280) * t7 * b + T(1280) * t11 * a_minus_b + T(11) * (T(3) * a * t12 * (T(7) * (T(8) * t10 * a_minus_b + T(8) * t6 * b + T(5) * (T(3) * (J2 * a + t4 * b + t8 * a_minus_b) * a * t12 + T(2) * t5 * b + T(2) * t9 * a_minus_b) * a * t12) * a * t12 + T(48) * t13 * b + T(48) * t14 * a_minus_b) + T(128) * t15 * b + T(128) * t16 * a_minus_b) * a * t12;
    F = (T(1) / T(15360)) * t17 * t12 * in.w[0];
    const T t18 = t11 * t8;
    const T t19 = t7 * t4;
    const T t20 = T(15360) * t18 * a_minus_b + T(13) * t17 * a * t12 + T(15360) * t19 * b;
    G_ap = (T(1) / T(215040)) * t20 * t12 * in.w[0];
    G_ab = (T(1) / T(215040)) * (T(15360) * t19 + t20 * t12 * b - T(15360) * t18) * in.w[0] / a;
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 46 +, 97 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = t5 * t5;
    const T t10 = t9 * t4;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t11;
    const T t15 = t12 * t11;
    const T t16 = t15 * t15;
    const T t17 = T(1280) * a_minus_b * t7 + T(11) * t8 * a * (T(128) * a_minus_b * t10 + T(128) * t14 * b + T(3) * t8 * a * (T(48) * a_minus_b * t9 + T(48) * t13 * b + T(7) * (T(8) * t15 * b + T(8) * a_minus_b * t6 + T(5) * (T(2) * t12 * b + T(3) * (a_minus_b * t4 + t11 * b + a * J2) * t8 * a + T(2) * a_minus_b * t5) * t8 * a) * t8 * a)) + T(1280) * t16 * b;
    F = (T(1) / T(15360)) * (t17 * t8 * b + T(1280) * t16 - T(1280) * t7) * in.w[1] / a + (T(1) / T(15360)) * t17 * in.w[0] * t8;
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + ap0 * bp0;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t6 * t6;
    const T t16 = t15 * t5;
    const T t17 = t11 * t11;
    const T t18 = t17 * t10;
    const T t19 = T(1280) * b * t8 + T(1280) * t13 * a_minus_b + T(11) * t4 * a * (T(128) * b * t16 + T(128) * t18 * a_minus_b + T(3) * t4 * a * (T(48) * b * t15 + T(48) * t17 * a_minus_b + T(7) * t4 * a * (T(8) * b * t7 + T(8) * t12 * a_minus_b + T(5) * t4 * a * (T(2) * b * t6 + T(2) * t11 * a_minus_b + T(3) * t4 * a * (t10 * a_minus_b + a * J2 + b * t5)))));
    const T t20 = T(15360) * b * t9 + T(15360) * t14 * a_minus_b + T(13) * t4 * a * t19;
    const T t21 = T(1) / a;
    const T t22 = T(15360) * t9 + t4 * t20 * b - T(15360) * t14;
    G_ap = (T(1) / T(215040)) * t4 * t20 * in.w[0] + (T(1) / T(215040)) * in.w[1] * t21 * t22;
    G_ab = (T(1) / T(215040)) * t21 * t22 * in.w[0] + (T(1) / T(215040)) * in.w[1] * t21 * (T(14) * t4 * t19 + T(2) * t21 * b * t22 - t4 * t20 * c);
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t9 * t5;
    const T t15 = t13 * t10;
    const T t16 = t12 * t12;
    const T t17 = T(1280) * a_minus_b * t8 + T(11) * t4 * a * (T(3) * t4 * a * (T(48) * a_minus_b * t9 + T(7) * t4 * (T(5) * t4 * a * (T(2) * t11 * b + T(2) * a_minus_b * t6 + T(3) * t4 * a * (J2 * a + a_minus_b * t5 + t10 * b)) + T(8) * t12 * b + T(8) * a_minus_b * t7) * a + T(48) * t13 * b) + T(128) * a_minus_b * t14 + T(128) * t15 * b) + T(1280) * t16 * b;
    const T t18 = T(1) / a;
    F = (T(1) / T(15360)) * in.w[0] * t4 * t17 + (T(1) / T(15360)) * t18 * (T(1280) * t16 + t4 * b * t17 - T(1280) * t8) * in.w[1];
    const T t19 = t16 * t10;
    const T t20 = t8 * t5;
    const T t21 = T(15360) * a_minus_b * t20 + T(13) * t4 * a * t17 + T(15360) * t19 * b;
    const T t22 = T(15360) * t19 + t21 * t4 * b - T(15360) * t20;
    G_ap = (T(1) / T(215040)) * t18 * in.w[1] * t22 + (T(1) / T(215040)) * t21 * in.w[0] * t4;
    G_ab = (T(1) / T(215040)) * t18 * (T(2) * t18 * b * t22 + T(14) * t4 * t17 - c * t21 * t4) * in.w[1] + (T(1) / T(215040)) * in.w[0] * t18 * t22;
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t10 * t10;
    const T t14 = t13 * t9;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = T(128) * t14 * a_minus_b + T(3) * (T(48) * t13 * a_minus_b + T(48) * t15 * b + T(7) * t8 * a * (T(8) * t6 * b + T(5) * t8 * a * (T(2) * t5 * b + T(2) * t10 * a_minus_b + T(3) * t8 * a * (t9 * a_minus_b + a * J2 + t4 * b)) + T(8) * t11 * a_minus_b)) * t8 * a + T(128) * t16 * b;
    const T t18 = T(1280) * t12 * a_minus_b + T(11) * t17 * t8 * a + T(1280) * t7 * b;
    const T t19 = T(1280) * t7 + t8 * t18 * b - T(1280) * t12;
    const T t20 = T(1) / a;
    F = (T(1) / T(15360)) * t19 * in.w[1] * t20 + (T(1) / T(15360)) * in.w[2] * t20 * (T(2) * t19 * t20 * b + T(12) * t17 * t8 - c * t8 * t18) + (T(1) / T(15360)) * t8 * t18 * in.w[0];
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / D;
    const T t10 = t5 * t5;
    const T t11 = t10 * t4;
    const T t12 = T(1) / q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t12;
    const T t16 = t13 * t12;
    const T t17 = t16 * t16;
    const T t18 = T(11) * t9 * a * (T(128) * t11 * b + T(128) * a_minus_b * t15 + T(3) * (T(48) * t10 * b + T(48) * a_minus_b * t14 + T(7) * t9 * a * (T(8) * a_minus_b * t16 + T(5) * t9 * a * (T(2) * a_minus_b * t13 + T(2) * t5 * b + T(3) * t9 * a * (a * J2 + t4 * b + a_minus_b * t12)) + T(8) * t6 * b)) * t9 * a) + T(1280) * a_minus_b * t17 + T(1280) * t7 * b;
    const T t19 = t17 * t12;
    const T t20 = T(15360) * t8 * b + T(13) * t18 * t9 * a + T(15360) * a_minus_b * t19;
    const T t21 = T(1) / a;
    const T t22 = T(15360) * t8 + t20 * t9 * b - T(15360) * t19;
    const T t23 = T(2) * t21 * b * t22 + T(14) * t18 * t9 - c * t20 * t9;
    G_ap = (T(1) / T(215040)) * t20 * t9 * in.w[0] + (T(1) / T(215040)) * t23 * in.w[2] * t21 + (T(1) / T(215040)) * in.w[1] * t21 * t22;
    G_ab = (T(1) / T(215040)) * t21 * in.w[0] * t22 + (T(1) / T(215040)) * in.w[2] * t21 * (T(14) * t21 * (T(1280) * t7 + t18 * t9 * b - T(1280) * t17) + T(2) * t23 * t21 * b - c * t21 * t22) + (T(1) / T(215040)) * in.w[1] * t23 * t21;
  }
  const T g_factor = -T(14) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + bp1 * ap1;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[4] * in.w[0] + in.w[1] * M_beyond[5] + M_beyond[6] * in.w[2];
    G_ab = in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + in.w[2] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = t13 * t5;
    const T t15 = t10 * t10;
    const T t16 = T(1) / D;
    const T t17 = t15 * t9;
    const T t18 = T(128) * a_minus_b * t14 + T(3) * a * (T(48) * a_minus_b * t13 + T(48) * t15 * b + T(7) * (T(8) * t11 * b + T(5) * a * (T(2) * a_minus_b * t6 + T(3) * (a * J2 + t9 * b + a_minus_b * t5) * a * t16 + T(2) * t10 * b) * t16 + T(8) * a_minus_b * t7) * a * t16) * t16 + T(128) * t17 * b;
    const T t19 = T(1280) * a_minus_b * t8 + T(1280) * t12 * b + T(11) * t18 * a * t16;
    const T t20 = t19 * b * t16 + T(1280) * t12 - T(1280) * t8;
    F = (T(1) / T(15360)) * t4 * in.w[2] * (T(2) * t4 * b * t20 + T(12) * t18 * t16 - t19 * c * t16) + (T(1) / T(15360)) * in.w[1] * t4 * t20 + (T(1) / T(15360)) * t19 * in.w[0] * t16;
    const T t21 = t8 * t5;
    const T t22 = t12 * t9;
    const T t23 = T(15360) * a_minus_b * t21 + T(15360) * t22 * b + T(13) * a * t19 * t16;
    const T t24 = T(15360) * t22 + t23 * b * t16 - T(15360) * t21;
    const T t25 = T(2) * t24 * t4 * b + T(14) * t19 * t16 - t23 * c * t16;
    G_ap = (T(1) / T(215040)) * t23 * in.w[0] * t16 + (T(1) / T(215040)) * t25 * t4 * in.w[2] + (T(1) / T(215040)) * in.w[1] * t24 * t4;
    G_ab = (T(1) / T(215040)) * in.w[1] * t25 * t4 + (T(1) / T(215040)) * t4 * in.w[2] * (T(2) * t25 * t4 * b + T(14) * t4 * t20 - t24 * t4 * c) + (T(1) / T(215040)) * t24 * t4 * in.w[0];
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t8;
    const T t12 = t5 * t4;
    const T t13 = t9 * t8;
    const T t14 = T(1) / D;
    const T t15 = T(128) * b * t7 + T(128) * a_minus_b * t11 + T(3) * (T(48) * b * t6 + T(48) * a_minus_b * t10 + T(7) * (T(8) * b * t12 + T(8) * a_minus_b * t13 + T(5) * t14 * (T(2) * b * t5 + T(3) * (a_minus_b * t8 + a * J2 + b * t4) * t14 * a + T(2) * a_minus_b * t9) * a) * t14 * a) * t14 * a;
    const T t16 = T(1) / a;
    const T t17 = t12 * t12;
    const T t18 = t13 * t13;
    const T t19 = T(1280) * b * t17 + T(1280) * a_minus_b * t18 + T(11) * t15 * t14 * a;
    const T t20 = t19 * b * t14 + T(1280) * t17 - T(1280) * t18;
    const T t21 = T(12) * t15 * t14 + T(2) * b * t16 * t20 - t19 * c * t14;
    F = (T(1) / T(15360)) * (T(2) * b * t21 * t16 - T(12) * (T(128) * t11 - b * t15 * t14 - T(128) * t7) * t16 - c * t16 * t20) * in.w[3] * t16 + (T(1) / T(15360)) * t19 * t14 * in.w[0] + (T(1) / T(15360)) * t21 * in.w[2] * t16 + (T(1) / T(15360)) * in.w[1] * t16 * t20;
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + M_beyond[2] * in.w[1] + in.w[3] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = t6 * t6;
    const T t14 = t13 * t5;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(128) * a_minus_b * t14 + T(3) * (T(7) * t4 * a * (T(8) * a_minus_b * t7 + T(8) * t11 * b + T(5) * t4 * a * (T(2) * t10 * b + T(2) * a_minus_b * t6 + T(3) * t4 * a * (a_minus_b * t5 + t9 * b + J2 * a))) + T(48) * a_minus_b * t13 + T(48) * t15 * b) * t4 * a + T(128) * t16 * b;
    const T t18 = T(1280) * a_minus_b * t8 + T(1280) * t12 * b + T(11) * t4 * a * t17;
    const T t19 = t12 * t9;
    const T t20 = t8 * t5;
    const T t21 = T(15360) * a_minus_b * t20 + T(13) * t4 * a * t18 + T(15360) * t19 * b;
    const T t22 = T(15360) * t19 + t4 * b * t21 - T(15360) * t20;
    const T t23 = T(1) / a;
    const T t24 = T(14) * t4 * t18 + T(2) * t22 * t23 * b - c * t4 * t21;
    const T t25 = T(1280) * t12 + t4 * b * t18 - T(1280) * t8;
    const T t26 = c * t22 * t23 - T(14) * t23 * t25 - T(2) * t24 * t23 * b;
    G_ap = (T(1) / T(215040)) * in.w[2] * t24 * t23 + (T(1) / T(215040)) * t22 * t23 * in.w[1] + (T(1) / T(215040)) * t4 * in.w[0] * t21 - (T(1) / T(215040)) * t23 * in.w[3] * t26;
    G_ab = (T(1) / T(215040)) * t24 * t23 * in.w[1] + (T(1) / T(215040)) * t22 * t23 * in.w[0] - (T(1) / T(215040)) * in.w[2] * t23 * t26 - (T(1) / T(215040)) * t23 * in.w[3] * (T(2) * t23 * b * t26 + c * t24 * t23 + T(14) * t23 * (c * t4 * t18 - T(2) * t23 * t25 * b - T(12) * t4 * t17));
  }
  const T g_factor = -T(14) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3] + M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0];
    G_ab = in.w[3] * M_beyond[9] + in.w[1] * M_beyond[7] + in.w[0] * M_beyond[6] + M_beyond[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / a;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = t7 * t7;
    const T t17 = t16 * t6;
    const T t18 = T(128) * b * t15 + T(128) * a_minus_b * t17 + T(3) * t5 * a * (T(7) * t5 * a * (T(5) * t5 * a * (T(2) * b * t11 + T(3) * t5 * a * (a_minus_b * t6 + b * t10 + a * J2) + T(2) * a_minus_b * t7) + T(8) * a_minus_b * t8 + T(8) * b * t12) + T(48) * b * t14 + T(48) * a_minus_b * t16);
    const T t19 = T(1280) * a_minus_b * t9 + T(1280) * b * t13 + T(11) * t18 * t5 * a;
    const T t20 = t5 * b * t19 + T(1280) * t13 - T(1280) * t9;
    const T t21 = t5 * c * t19 - T(2) * t4 * t20 * b - T(12) * t18 * t5;
    F = (T(1) / T(15360)) * t4 * t20 * in.w[1] + (T(1) / T(15360)) * t4 * in.w[3] * (T(12) * t4 * (t18 * t5 * b + T(128) * t15 - T(128) * t17) - t4 * t20 * c - T(2) * t4 * t21 * b) + (T(1) / T(15360)) * t5 * in.w[0] * t19 - (T(1) / T(15360)) * t4 * t21 * in.w[2];
    const T t22 = t9 * t6;
    const T t23 = t13 * t10;
    const T t24 = T(15360) * a_minus_b * t22 + T(15360) * b * t23 + T(13) * t5 * a * t19;
    const T t25 = T(15360) * t22 - T(15360) * t23 - t5 * b * t24;
    const T t26 = T(14) * t5 * t19 - T(2) * t4 * t25 * b - t5 * t24 * c;
    const T t27 = T(14) * t4 * t20 + t4 * t25 * c + T(2) * t4 * t26 * b;
    G_ap = (T(1) / T(215040)) * t4 * t26 * in.w[2] + (T(1) / T(215040)) * t5 * in.w[0] * t24 + (T(1) / T(215040)) * t4 * in.w[3] * t27 - (T(1) / T(215040)) * t4 * t25 * in.w[1];
    G_ab = (T(1) / T(215040)) * t4 * t26 * in.w[1] + (T(1) / T(215040)) * t4 * t27 * in.w[2] - (T(1) / T(215040)) * t4 * in.w[3] * (t4 * t26 * c + T(14) * t4 * t21 - T(2) * t4 * b * t27) - (T(1) / T(215040)) * t4 * t25 * in.w[0];
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t9 * t9;
    const T t14 = t13 * t8;
    const T t15 = t4 * t4;
    const T t16 = t15 * t3;
    F = (T(1) / T(3003)) * (T(231) * a_minus_b * t2 * t6 + T(231) * t7 * t11 * b + T(4) * t12 * a * (T(63) * t7 * t14 * b + T(63) * a_minus_b * t2 * t16 + T(2) * t12 * a * (T(8) * (T(5) * a_minus_b * t2 * t5 + T(2) * t12 * a * (T(4) * (T(2) * (t7 * b + a_minus_b * t2) * t12 * a + t7 * t8 * b + a_minus_b * t2 * t3) * t12 * a + T(3) * a_minus_b * t2 * t4 + T(3) * t7 * t9 * b) + T(5) * t7 * t10 * b) * t12 * a + T(35) * t7 * t13 * b + T(35) * a_minus_b * t2 * t15))) * t12 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 48 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = t6 * t3;
    const T t8 = T(1) / D;
    const T t9 = t4 * t4;
    const T t10 = t9 * t3;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t12;
    const T t16 = t13 * t12;
    const T t17 = t16 * t16;
    const T t18 = t17 * t12;
    const T t19 = T(429) * t2 * a_minus_b * t7 + T(2) * a * t8 * (T(231) * t2 * a_minus_b * t6 + T(4) * a * (T(63) * t2 * a_minus_b * t10 + T(63) * b * t11 * t15 + T(2) * a * t8 * (T(35) * t2 * a_minus_b * t9 + T(8) * a * t8 * (T(5) * t2 * a_minus_b * t5 + T(2) * (T(4) * a * t8 * (b * t11 * t12 + T(2) * (b * t11 + t2 * a_minus_b) * a * t8 + t2 * a_minus_b * t3) + T(3) * t2 * a_minus_b * t4 + T(3) * b * t11 * t13) * a * t8 + T(5) * b * t11 * t16) + T(35) * b * t11 * t14)) * t8 + T(231) * b * t11 * t17) + T(429) * b * t11 * t18;
    G_ap = (T(1) / T(6435)) * t19 * t8 * in.w[0];
    G_ab = (T(1) / T(6435)) * in.w[0] * (T(429) * t11 * t18 + t19 * t8 * b - T(429) * t2 * t7) / a;
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 48 +, 137 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / r1;
    const T t3 = t2 * t2;
    const T t4 = t3 * t3;
    const T t5 = t4 * t3;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t9 * t9;
    const T t14 = t13 * t8;
    const T t15 = t4 * t4;
    const T t16 = t15 * t3;
    const T t17 = T(231) * t6 * t2 * a_minus_b + T(231) * t11 * t7 * b + T(4) * t12 * a * (T(63) * t14 * t7 * b + T(2) * (T(8) * (T(2) * (T(4) * (T(2) * t12 * a * (t7 * b + t2 * a_minus_b) + t3 * t2 * a_minus_b + t8 * t7 * b) * t12 * a + T(3) * t9 * t7 * b + T(3) * t4 * t2 * a_minus_b) * t12 * a + T(5) * t10 * t7 * b + T(5) * t5 * t2 * a_minus_b) * t12 * a + T(35) * t15 * t2 * a_minus_b + T(35) * t13 * t7 * b) * t12 * a + T(63) * t16 * t2 * a_minus_b);
    F = (T(1) / T(3003)) * t17 * t12 * in.w[0];
    const T t18 = t11 * t8;
    const T t19 = t6 * t3;
    const T t20 = T(429) * t18 * t7 * b + T(2) * t17 * t12 * a + T(429) * t19 * t2 * a_minus_b;
    G_ap = (T(1) / T(6435)) * t12 * in.w[0] * t20;
    G_ab = (T(1) / T(6435)) * (T(429) * t18 * t7 + t12 * t20 * b - T(429) * t19 * t2) * in.w[0] / a;
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 44 +, 112 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t15 = t12 * t12;
    const T t16 = t11 * t11;
    const T t17 = T(4) * t2 * a * (T(2) * (T(35) * t6 * t3 * b + T(35) * t10 * t7 * a_minus_b + T(8) * (T(2) * t2 * a * (T(4) * t2 * a * (T(2) * t2 * a * (t7 * a_minus_b + t3 * b) + t4 * t3 * b + t8 * t7 * a_minus_b) + T(3) * t5 * t3 * b + T(3) * t9 * t7 * a_minus_b) + T(5) * t11 * t7 * a_minus_b + T(5) * t12 * t3 * b) * t2 * a) * t2 * a + T(63) * t13 * t3 * b + T(63) * t14 * t7 * a_minus_b) + T(231) * t15 * t3 * b + T(231) * t16 * t7 * a_minus_b;
    F = (T(1) / T(3003)) * in.w[0] * t2 * t17 - (T(1) / T(3003)) * (T(231) * t16 * t7 - T(231) * t15 * t3 - t2 * b * t17) * in.w[1] / a;
  }
  f = F * length;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = t11 * t11;
    const T t18 = t17 * t10;
    const T t19 = T(231) * t9 * a_minus_b * t13 + T(4) * t2 * (T(63) * t16 * b * t3 + T(63) * t9 * a_minus_b * t18 + T(2) * t2 * a * (T(35) * t15 * b * t3 + T(35) * t9 * a_minus_b * t17 + T(8) * t2 * (T(2) * (T(3) * t5 * b * t3 + T(4) * t2 * a * (T(2) * (b * t3 + t9 * a_minus_b) * t2 * a + t9 * a_minus_b * t10 + t4 * b * t3) + T(3) * t9 * a_minus_b * t11) * t2 * a + T(5) * t6 * b * t3 + T(5) * t9 * a_minus_b * t12) * a)) * a + T(231) * t7 * b * t3;
    const T t20 = T(429) * t8 * b * t3 + T(429) * t9 * a_minus_b * t14 + T(2) * t2 * a * t19;
    const T t21 = T(429) * t9 * t14 - t2 * b * t20 - T(429) * t8 * t3;
    const T t22 = T(1) / a;
    G_ap = (T(1) / T(6435)) * in.w[0] * t2 * t20 - (T(1) / T(6435)) * t21 * t22 * in.w[1];
    G_ab = -(T(1) / T(6435)) * t21 * in.w[0] * t22 - (T(1) / T(45045)) * t22 * in.w[1] * (T(14) * t21 * t22 * b + T(7) * c * t2 * t20 - T(15) * t2 * t19);
  }
  const T g_factor = -T(15) * in.s * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[3] * in.w[0] + in.w[1] * M_beyond[4];
    G_ab = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
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
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(231) * b * t7 * t3 + T(231) * t8 * a_minus_b * t12 + T(4) * a * t2 * (T(63) * b * t14 * t3 + T(2) * a * t2 * (T(8) * a * t2 * (T(2) * a * t2 * (T(3) * b * t5 * t3 + T(4) * a * t2 * (t8 * a_minus_b * t9 + b * t4 * t3 + T(2) * a * t2 * (t8 * a_minus_b + b * t3)) + T(3) * t8 * a_minus_b * t10) + T(5) * b * t6 * t3 + T(5) * t8 * a_minus_b * t11) + T(35) * b * t13 * t3 + T(35) * t8 * a_minus_b * t15) + T(63) * t8 * a_minus_b * t16);
    const T t18 = T(1) / a;
    F = (T(1) / T(3003)) * t2 * in.w[0] * t17 - (T(1) / T(3003)) * t18 * in.w[1] * (T(231) * t8 * t12 - T(231) * t7 * t3 - t2 * b * t17);
    const T t19 = t7 * t4;
    const T t20 = t12 * t9;
    const T t21 = T(2) * a * t2 * t17 + T(429) * b * t19 * t3 + T(429) * t8 * a_minus_b * t20;
    const T t22 = T(429) * t8 * t20 - t2 * t21 * b - T(429) * t19 * t3;
    G_ap = (T(1) / T(6435)) * t2 * in.w[0] * t21 - (T(1) / T(6435)) * t18 * t22 * in.w[1];
    G_ab = (T(1) / T(45045)) * t18 * (T(15) * t2 * t17 - T(7) * t2 * t21 * c - T(14) * t18 * t22 * b) * in.w[1] - (T(1) / T(6435)) * t18 * t22 * in.w[0];
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1];
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
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(63) * t14 * t3 * b + T(2) * (T(35) * t13 * t3 * b + T(8) * a * t2 * (T(5) * t8 * a_minus_b * t11 + T(2) * a * t2 * (T(3) * t5 * t3 * b + T(4) * (t8 * a_minus_b * t9 + T(2) * (t8 * a_minus_b + t3 * b) * a * t2 + t4 * t3 * b) * a * t2 + T(3) * t8 * a_minus_b * t10) + T(5) * t6 * t3 * b) + T(35) * t8 * a_minus_b * t15) * a * t2 + T(63) * t8 * a_minus_b * t16;
    const T t18 = T(231) * t7 * t3 * b + T(231) * t8 * a_minus_b * t12 + T(4) * a * t2 * t17;
    const T t19 = T(1) / a;
    const T t20 = T(231) * t8 * t12 - T(231) * t7 * t3 - t2 * t18 * b;
    F = (T(1) / T(3003)) * in.w[0] * t2 * t18 - (T(1) / T(3003)) * in.w[1] * t19 * t20 - (T(1) / T(9009)) * (T(6) * t19 * t20 * b + T(3) * c * t2 * t18 - T(13) * t2 * t17) * t19 * in.w[2];
  }
  f = length * F;
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
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t6 * t5;
    const T t15 = t12 * t10;
    const T t16 = t13 * t13;
    const T t17 = t14 * t14;
    const T t18 = T(4) * t3 * a * (T(63) * t8 * b * t4 + T(2) * t3 * a * (T(35) * t9 * a_minus_b * t12 + T(35) * t7 * b * t4 + T(8) * (T(2) * t3 * a * (T(3) * t9 * a_minus_b * t11 + T(3) * t6 * b * t4 + T(4) * t3 * (t5 * b * t4 + t9 * a_minus_b * t10 + T(2) * t3 * a * (t9 * a_minus_b + b * t4)) * a) + T(5) * t9 * a_minus_b * t13 + T(5) * t14 * b * t4) * t3 * a) + T(63) * t9 * a_minus_b * t15) + T(231) * t9 * a_minus_b * t16 + T(231) * t17 * b * t4;
    const T t19 = t16 * t10;
    const T t20 = t17 * t5;
    const T t21 = T(2) * t18 * t3 * a + T(429) * t9 * a_minus_b * t19 + T(429) * t20 * b * t4;
    const T t22 = t3 * b * t21 + T(429) * t20 * t4 - T(429) * t9 * t19;
    const T t23 = T(7) * c * t3 * t21 - T(15) * t18 * t3 - T(14) * t2 * t22 * b;
    G_ap = (T(1) / T(6435)) * in.w[1] * t2 * t22 + (T(1) / T(6435)) * t3 * in.w[0] * t21 - (T(1) / T(45045)) * in.w[2] * t2 * t23;
    G_ab = (T(1) / T(6435)) * t2 * t22 * in.w[0] - (T(1) / T(45045)) * in.w[2] * t2 * (T(7) * c * t2 * t22 + T(15) * t2 * (T(231) * t9 * t16 - t18 * t3 * b - T(231) * t17 * t4) + T(2) * t2 * t23 * b) - (T(1) / T(45045)) * in.w[1] * t2 * t23;
  }
  const T g_factor = -T(15) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[4] + in.w[2] * M_beyond[6] + in.w[1] * M_beyond[5];
    G_ab = M_beyond[6] * in.w[1] + in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
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
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(63) * t3 * a_minus_b * t14 + T(63) * b * t16 * t8 + T(2) * t2 * a * (T(35) * t3 * a_minus_b * t13 + T(35) * b * t15 * t8 + T(8) * t2 * a * (T(5) * t3 * a_minus_b * t6 + T(5) * b * t11 * t8 + T(2) * t2 * a * (T(3) * t3 * a_minus_b * t5 + T(4) * t2 * a * (b * t9 * t8 + t3 * a_minus_b * t4 + T(2) * t2 * a * (t3 * a_minus_b + b * t8)) + T(3) * b * t10 * t8)));
    const T t18 = T(231) * t3 * a_minus_b * t7 + T(231) * b * t12 * t8 + T(4) * t2 * a * t17;
    const T t19 = t2 * t18 * b + T(231) * t12 * t8 - T(231) * t3 * t7;
    const T t20 = T(1) / a;
    F = (T(1) / T(3003)) * t2 * t18 * in.w[0] + (T(1) / T(3003)) * t19 * t20 * in.w[1] + (T(1) / T(9009)) * in.w[2] * t20 * (T(13) * t2 * t17 + T(6) * t19 * t20 * b - T(3) * t2 * t18 * c);
    const T t21 = t7 * t4;
    const T t22 = t12 * t9;
    const T t23 = T(429) * t3 * a_minus_b * t21 + T(429) * b * t22 * t8 + T(2) * t2 * a * t18;
    const T t24 = t2 * t23 * b + T(429) * t22 * t8 - T(429) * t3 * t21;
    const T t25 = T(14) * t20 * t24 * b + T(15) * t2 * t18 - T(7) * t2 * t23 * c;
    G_ap = (T(1) / T(6435)) * t20 * t24 * in.w[1] + (T(1) / T(45045)) * in.w[2] * t20 * t25 + (T(1) / T(6435)) * t2 * t23 * in.w[0];
    G_ab = (T(1) / T(45045)) * t20 * t25 * in.w[1] + (T(1) / T(6435)) * t20 * t24 * in.w[0] - (T(1) / T(45045)) * in.w[2] * t20 * (T(7) * t20 * t24 * c - T(15) * t19 * t20 - T(2) * t20 * t25 * b);
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3];
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
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(63) * b * t14 * t3 + T(63) * t8 * a_minus_b * t16 + T(2) * (T(8) * t2 * (T(5) * t8 * a_minus_b * t11 + T(2) * t2 * a * (T(3) * t8 * a_minus_b * t10 + T(3) * b * t5 * t3 + T(4) * (T(2) * (t8 * a_minus_b + b * t3) * t2 * a + b * t4 * t3 + t8 * a_minus_b * t9) * t2 * a) + T(5) * b * t6 * t3) * a + T(35) * t8 * a_minus_b * t15 + T(35) * b * t13 * t3) * t2 * a;
    const T t18 = T(231) * b * t7 * t3 + T(231) * t8 * a_minus_b * t12 + T(4) * t17 * t2 * a;
    const T t19 = T(231) * t7 * t3 + b * t2 * t18 - T(231) * t8 * t12;
    const T t20 = T(1) / a;
    const T t21 = T(3) * c * t2 * t18 - T(13) * t17 * t2 - T(6) * b * t19 * t20;
    F = (T(1) / T(3003)) * t2 * in.w[0] * t18 + (T(1) / T(3003)) * in.w[1] * t19 * t20 + (T(1) / T(9009)) * (T(13) * t20 * (T(63) * t14 * t3 + b * t17 * t2 - T(63) * t8 * t16) - T(3) * c * t19 * t20 - T(2) * b * t21 * t20) * in.w[3] * t20 - (T(1) / T(9009)) * t21 * in.w[2] * t20;
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
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2] + M_beyond[4] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / a;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = t7 * t4;
    const T t9 = T(1) / D;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t5 * t5;
    const T t16 = t15 * t4;
    const T t17 = t12 * t12;
    const T t18 = t17 * t11;
    const T t19 = T(63) * b * t3 * t16 + T(2) * t9 * a * (T(35) * b * t3 * t15 + T(8) * t9 * a * (T(5) * b * t3 * t6 + T(5) * a_minus_b * t13 * t10 + T(2) * t9 * a * (T(3) * a_minus_b * t12 * t10 + T(3) * b * t3 * t5 + T(4) * t9 * a * (T(2) * t9 * (b * t3 + a_minus_b * t10) * a + b * t3 * t4 + a_minus_b * t11 * t10))) + T(35) * a_minus_b * t17 * t10) + T(63) * a_minus_b * t18 * t10;
    const T t20 = T(231) * b * t3 * t7 + T(231) * a_minus_b * t14 * t10 + T(4) * t9 * a * t19;
    const T t21 = t14 * t11;
    const T t22 = T(429) * b * t3 * t8 + T(2) * t9 * a * t20 + T(429) * a_minus_b * t21 * t10;
    const T t23 = T(429) * t3 * t8 + t9 * b * t22 - T(429) * t21 * t10;
    const T t24 = T(7) * t9 * t22 * c - T(15) * t9 * t20 - T(14) * t2 * t23 * b;
    const T t25 = T(231) * t3 * t7 + t9 * b * t20 - T(231) * t14 * t10;
    const T t26 = T(7) * t2 * t23 * c + T(2) * t2 * b * t24 - T(15) * t2 * t25;
    G_ap = (T(1) / T(6435)) * t2 * t23 * in.w[1] + (T(1) / T(6435)) * t9 * in.w[0] * t22 - (T(1) / T(45045)) * t2 * t24 * in.w[2] - (T(1) / T(45045)) * t2 * t26 * in.w[3];
    G_ab = (T(1) / T(6435)) * t2 * t23 * in.w[0] - (T(1) / T(45045)) * t2 * in.w[3] * (T(2) * t2 * t26 * b - t2 * t24 * c - T(5) * t2 * (T(6) * t2 * t25 * b + T(13) * t9 * t19 - T(3) * t9 * c * t20)) - (T(1) / T(45045)) * t2 * t26 * in.w[2] - (T(1) / T(45045)) * t2 * t24 * in.w[1];
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3];
    G_ap = in.w[2] * M_beyond[7] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[8] * in.w[3];
    G_ab = M_beyond[8] * in.w[2] + M_beyond[9] * in.w[3] + in.w[0] * M_beyond[6] + M_beyond[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = T(1) / D;
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t5;
    const T t12 = t9 * t9;
    const T t13 = t11 * t4;
    const T t14 = t12 * t8;
    const T t15 = T(2) * t2 * a * (T(8) * t2 * a * (T(5) * t3 * b * t6 + T(5) * t10 * a_minus_b * t7 + T(2) * t2 * a * (T(4) * t2 * a * (T(2) * (t3 * b + a_minus_b * t7) * t2 * a + t8 * a_minus_b * t7 + t3 * b * t4) + T(3) * t3 * b * t5 + T(3) * t9 * a_minus_b * t7)) + T(35) * t3 * b * t11 + T(35) * t12 * a_minus_b * t7) + T(63) * t3 * b * t13 + T(63) * t14 * a_minus_b * t7;
    const T t16 = t6 * t6;
    const T t17 = t10 * t10;
    const T t18 = T(4) * t2 * a * t15 + T(231) * t3 * b * t16 + T(231) * t17 * a_minus_b * t7;
    const T t19 = t2 * t18 * b + T(231) * t3 * t16 - T(231) * t17 * t7;
    const T t20 = T(1) / a;
    const T t21 = T(6) * t19 * t20 * b + T(13) * t2 * t15 - T(3) * t2 * t18 * c;
    F = (T(1) / T(3003)) * t2 * t18 * in.w[0] + (T(1) / T(9009)) * in.w[2] * t21 * t20 + (T(1) / T(3003)) * t19 * t20 * in.w[1] - (T(1) / T(9009)) * (T(13) * (T(63) * t14 * t7 - t2 * b * t15 - T(63) * t3 * t13) * t20 + T(3) * t19 * t20 * c - T(2) * t21 * t20 * b) * t20 * in.w[3];
    const T t22 = t17 * t8;
    const T t23 = t16 * t4;
    const T t24 = T(429) * t22 * a_minus_b * t7 + T(429) * t3 * b * t23 + T(2) * t2 * t18 * a;
    const T t25 = T(429) * t22 * t7 - T(429) * t3 * t23 - t24 * t2 * b;
    const T t26 = T(7) * t24 * t2 * c + T(14) * t25 * t20 * b - T(15) * t2 * t18;
    const T t27 = T(15) * t19 * t20 + T(7) * t25 * t20 * c - T(2) * t26 * t20 * b;
    G_ap = (T(1) / T(45045)) * t27 * t20 * in.w[3] + (T(1) / T(6435)) * t24 * t2 * in.w[0] - (T(1) / T(6435)) * t25 * t20 * in.w[1] - (T(1) / T(45045)) * in.w[2] * t26 * t20;
    G_ab = (T(1) / T(45045)) * t20 * in.w[3] * (T(2) * t27 * t20 * b + t26 * t20 * c + T(5) * t21 * t20) + (T(1) / T(45045)) * in.w[2] * t27 * t20 - (T(1) / T(6435)) * t25 * t20 * in.w[0] - (T(1) / T(45045)) * t26 * t20 * in.w[1];
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t6 * t6;
    const T t15 = t11 * t11;
    const T t16 = t14 * t5;
    const T t17 = t15 * t10;
    const T t18 = t13 * t10;
    F = (T(1) / T(215040)) * t4 * in.w[0] * (T(15360) * a_minus_b * t9 + T(13) * (T(1280) * a_minus_b * t8 + T(1280) * b * t13 + T(11) * t4 * a * (T(3) * (T(48) * a_minus_b * t14 + T(7) * (T(5) * (T(2) * a_minus_b * t6 + T(3) * (a * J2 + b * t10 + a_minus_b * t5) * t4 * a + T(2) * b * t11) * t4 * a + T(8) * a_minus_b * t7 + T(8) * b * t12) * t4 * a + T(48) * b * t15) * t4 * a + T(128) * a_minus_b * t16 + T(128) * b * t17)) * t4 * a + T(15360) * b * t18);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 52 +, 124 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + ap1 * bp1;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t6 * t5;
    const T t10 = t9 * t9;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t12 * t12;
    const T t15 = t14 * t11;
    const T t16 = t7 * t5;
    const T t17 = t13 * t13;
    const T t18 = t10 * t5;
    const T t19 = t17 * t11;
    const T t20 = t14 * t14;
    const T t21 = T(14336) * a_minus_b * t8 + (T(13) * a * t4 * (T(1280) * a_minus_b * t10 + T(11) * a * t4 * (T(3) * a * t4 * (T(7) * a * t4 * (T(8) * t13 * b + T(5) * (T(2) * t12 * b + T(3) * a * t4 * (a_minus_b * t5 + a * J2 + t11 * b) + T(2) * a_minus_b * t6) * a * t4 + T(8) * a_minus_b * t9) + T(48) * t14 * b + T(48) * a_minus_b * t7) + T(128) * t15 * b + T(128) * a_minus_b * t16) + T(1280) * t17 * b) + T(15360) * a_minus_b * t18 + T(15360) * t19 * b) * a * t4 + T(14336) * t20 * b;
    G_ap = (T(1) / T(229376)) * t4 * t21 * in.w[0];
    G_ab = (T(1) / T(229376)) * in.w[0] * (t4 * t21 * b + T(14336) * t20 - T(14336) * t8) / a;
  }
  const T g_factor = -T(16) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 52 +, 128 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
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
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t5;
    const T t10 = t8 * t7;
    const T t11 = t8 * t8;
    const T t12 = t6 * t6;
    const T t13 = t11 * t7;
    const T t14 = t12 * t5;
    const T t15 = t10 * t10;
    const T t16 = t9 * t9;
    const T t17 = t15 * t7;
    const T t18 = t16 * t5;
    const T t19 = T(13) * t4 * a * (T(11) * t4 * a * (T(3) * t4 * a * (T(7) * t4 * a * (T(5) * (T(2) * b * t6 + T(3) * t4 * a * (J2 * a + a_minus_b * t7 + b * t5) + T(2) * a_minus_b * t8) * t4 * a + T(8) * b * t9 + T(8) * a_minus_b * t10) + T(48) * a_minus_b * t11 + T(48) * b * t12) + T(128) * a_minus_b * t13 + T(128) * b * t14) + T(1280) * a_minus_b * t15 + T(1280) * b * t16) + T(15360) * a_minus_b * t17 + T(15360) * b * t18;
    F = (T(1) / T(215040)) * t19 * t4 * in.w[0];
    const T t20 = t11 * t11;
    const T t21 = t12 * t12;
    const T t22 = T(14336) * a_minus_b * t20 + t19 * t4 * a + T(14336) * b * t21;
    G_ap = (T(1) / T(229376)) * t4 * in.w[0] * t22;
    G_ab = (T(1) / T(229376)) * in.w[0] * (t4 * t22 * b + T(14336) * t21 - T(14336) * t20) / a;
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 48 +, 106 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t5;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t12 * t12;
    const T t15 = t14 * t11;
    const T t16 = t13 * t13;
    const T t17 = t8 * t5;
    const T t18 = t16 * t11;
    const T t19 = T(13) * t4 * a * (T(1280) * t8 * a_minus_b + T(11) * t4 * a * (T(128) * t10 * a_minus_b + T(3) * t4 * a * (T(48) * t9 * a_minus_b + T(7) * t4 * a * (T(5) * t4 * a * (T(3) * t4 * a * (t5 * a_minus_b + b * t11 + a * J2) + T(2) * t6 * a_minus_b + T(2) * b * t12) + T(8) * b * t13 + T(8) * t7 * a_minus_b) + T(48) * b * t14) + T(128) * b * t15) + T(1280) * b * t16) + T(15360) * t17 * a_minus_b + T(15360) * b * t18;
    F = (T(1) / T(215040)) * t4 * t19 * in.w[0] + (T(1) / T(215040)) * in.w[1] * (t4 * b * t19 + T(15360) * t18 - T(15360) * t17) / a;
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / D;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t6 * t5;
    const T t14 = t13 * t13;
    const T t15 = t14 * t5;
    const T t16 = t7 * t5;
    const T t17 = t10 * t9;
    const T t18 = t11 * t9;
    const T t19 = t17 * t17;
    const T t20 = t19 * t9;
    const T t21 = T(15360) * t15 * b + T(13) * t4 * a * (T(11) * t4 * (T(128) * t16 * b + T(3) * (T(48) * t7 * b + T(7) * (T(8) * a_minus_b * t17 + T(5) * t4 * a * (T(2) * t6 * b + T(2) * a_minus_b * t10 + T(3) * t4 * a * (a_minus_b * t9 + t5 * b + J2 * a)) + T(8) * t13 * b) * t4 * a + T(48) * a_minus_b * t11) * t4 * a + T(128) * a_minus_b * t18) * a + T(1280) * t14 * b + T(1280) * a_minus_b * t19) + T(15360) * a_minus_b * t20;
    const T t22 = T(14336) * t8 * b + T(14336) * a_minus_b * t12 + t4 * a * t21;
    const T t23 = T(14336) * t12 - T(14336) * t8 - t4 * t22 * b;
    const T t24 = T(1) / a;
    G_ap = (T(1) / T(229376)) * in.w[0] * t4 * t22 - (T(1) / T(229376)) * t23 * t24 * in.w[1];
    G_ab = -(T(1) / T(229376)) * t23 * in.w[0] * t24 - (T(1) / T(3440640)) * (T(30) * t23 * t24 * b + T(15) * c * t4 * t22 - T(16) * t4 * t21) * t24 * in.w[1];
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = in.w[1] * M_beyond[5] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
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
    const T t14 = t5 * t5;
    const T t15 = t14 * t4;
    const T t16 = t10 * t10;
    const T t17 = t16 * t9;
    const T t18 = T(1) / D;
    const T t19 = T(15360) * b * t8 + T(15360) * a_minus_b * t13 + T(13) * a * (T(1280) * b * t7 + T(11) * a * (T(128) * b * t15 + T(128) * a_minus_b * t17 + T(3) * a * (T(48) * b * t14 + T(48) * a_minus_b * t16 + T(7) * a * (T(8) * b * t6 + T(5) * a * (T(2) * b * t5 + T(3) * a * (a_minus_b * t9 + a * J2 + b * t4) * t18 + T(2) * a_minus_b * t10) * t18 + T(8) * a_minus_b * t11) * t18) * t18) * t18 + T(1280) * a_minus_b * t12) * t18;
    const T t20 = T(1) / a;
    F = (T(1) / T(215040)) * t19 * in.w[0] * t18 - (T(1) / T(215040)) * in.w[1] * t20 * (T(15360) * t13 - T(15360) * t8 - t19 * b * t18);
    const T t21 = t16 * t16;
    const T t22 = t14 * t14;
    const T t23 = T(14336) * a_minus_b * t21 + a * t19 * t18 + T(14336) * b * t22;
    const T t24 = b * t23 * t18 + T(14336) * t22 - T(14336) * t21;
    G_ap = (T(1) / T(229376)) * in.w[1] * t20 * t24 + (T(1) / T(229376)) * t23 * in.w[0] * t18;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t20 * (T(16) * t19 * t18 + T(30) * t20 * b * t24 - T(15) * t23 * c * t18) + (T(1) / T(229376)) * t20 * t24 * in.w[0];
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = t5 * t4;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = T(1) / D;
    const T t12 = t10 * t9;
    const T t13 = t10 * t10;
    const T t14 = t13 * t9;
    const T t15 = t8 * t8;
    const T t16 = t12 * t12;
    const T t17 = T(11) * a * (T(128) * b * t7 + T(3) * a * (T(7) * a * (T(8) * b * t8 + T(5) * a * (T(2) * b * t5 + T(2) * a_minus_b * t10 + T(3) * a * (a_minus_b * t9 + a * J2 + b * t4) * t11) * t11 + T(8) * a_minus_b * t12) * t11 + T(48) * b * t6 + T(48) * a_minus_b * t13) * t11 + T(128) * a_minus_b * t14) * t11 + T(1280) * b * t15 + T(1280) * a_minus_b * t16;
    const T t18 = t15 * t4;
    const T t19 = t16 * t9;
    const T t20 = T(13) * a * t17 * t11 + T(15360) * b * t18 + T(15360) * a_minus_b * t19;
    const T t21 = T(1) / a;
    const T t22 = t20 * b * t11 + T(15360) * t18 - T(15360) * t19;
    F = (T(1) / T(215040)) * t20 * in.w[0] * t11 + (T(1) / T(215040)) * t21 * (T(14) * t17 * t11 + T(2) * t21 * t22 * b - t20 * c * t11) * in.w[2] + (T(1) / T(215040)) * t21 * t22 * in.w[1];
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
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / q1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t5 * t4;
    const T t9 = t8 * t8;
    const T t10 = t9 * t4;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = T(1) / D;
    const T t17 = t6 * t4;
    const T t18 = t12 * t12;
    const T t19 = t18 * t11;
    const T t20 = T(15360) * t10 * a_minus_b + T(15360) * b * t15 + T(13) * a * (T(1280) * t9 * a_minus_b + T(1280) * b * t14 + T(11) * a * t16 * (T(128) * t17 * a_minus_b + T(128) * b * t19 + T(3) * a * (T(48) * t6 * a_minus_b + T(7) * a * (T(8) * b * t13 + T(8) * t8 * a_minus_b + T(5) * a * (T(2) * b * t12 + T(2) * t5 * a_minus_b + T(3) * a * (a * J2 + t4 * a_minus_b + b * t11) * t16) * t16) * t16 + T(48) * b * t18) * t16)) * t16;
    const T t21 = t18 * t18;
    const T t22 = T(14336) * t7 * a_minus_b + a * t20 * t16 + T(14336) * b * t21;
    const T t23 = T(1) / a;
    const T t24 = T(14336) * t7 - b * t22 * t16 - T(14336) * t21;
    const T t25 = T(15) * c * t22 * t16 + T(30) * t23 * b * t24 - T(16) * t20 * t16;
    G_ap = (T(1) / T(229376)) * in.w[0] * t22 * t16 - (T(1) / T(229376)) * t23 * t24 * in.w[1] - (T(1) / T(3440640)) * t23 * in.w[2] * t25;
    G_ab = (T(1) / T(3440640)) * t23 * (T(16) * t23 * (T(15360) * t15 + b * t20 * t16 - T(15360) * t10) + T(15) * t23 * c * t24 - T(2) * t23 * t25 * b) * in.w[2] - (T(1) / T(3440640)) * t23 * t25 * in.w[1] - (T(1) / T(229376)) * t23 * in.w[0] * t24;
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
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
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[5] * in.w[1] + in.w[2] * M_beyond[6] + in.w[0] * M_beyond[4];
    G_ab = in.w[2] * M_beyond[7] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / a;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t7 * t6;
    const T t15 = t11 * t10;
    const T t16 = t14 * t14;
    const T t17 = t15 * t15;
    const T t18 = T(11) * t5 * (T(128) * a_minus_b * t9 + T(128) * b * t13 + T(3) * t5 * a * (T(7) * t5 * a * (T(8) * a_minus_b * t14 + T(5) * t5 * a * (T(2) * a_minus_b * t7 + T(3) * t5 * a * (b * t10 + a * J2 + a_minus_b * t6) + T(2) * b * t11) + T(8) * b * t15) + T(48) * a_minus_b * t8 + T(48) * b * t12)) * a + T(1280) * a_minus_b * t16 + T(1280) * b * t17;
    const T t19 = t16 * t6;
    const T t20 = t17 * t10;
    const T t21 = T(15360) * a_minus_b * t19 + T(15360) * b * t20 + T(13) * t5 * a * t18;
    const T t22 = T(15360) * t19 - T(15360) * t20 - t5 * t21 * b;
    F = (T(1) / T(215040)) * in.w[2] * t4 * (T(14) * t5 * t18 - t5 * t21 * c - T(2) * t22 * t4 * b) + (T(1) / T(215040)) * t5 * t21 * in.w[0] - (T(1) / T(215040)) * t22 * t4 * in.w[1];
    const T t23 = t12 * t12;
    const T t24 = t8 * t8;
    const T t25 = T(14336) * b * t23 + T(14336) * a_minus_b * t24 + t5 * a * t21;
    const T t26 = t5 * b * t25 + T(14336) * t23 - T(14336) * t24;
    const T t27 = T(16) * t5 * t21 + T(30) * t4 * b * t26 - T(15) * t5 * c * t25;
    G_ap = (T(1) / T(229376)) * t4 * in.w[1] * t26 + (T(1) / T(3440640)) * in.w[2] * t4 * t27 + (T(1) / T(229376)) * t5 * in.w[0] * t25;
    G_ab = (T(1) / T(229376)) * t4 * in.w[0] * t26 + (T(1) / T(3440640)) * t4 * in.w[1] * t27 + (T(1) / T(3440640)) * in.w[2] * t4 * (T(2) * t4 * b * t27 - T(16) * t22 * t4 - T(15) * t4 * c * t26);
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = -b * a_minus_b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
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
    const T t17 = T(1280) * a_minus_b * t7 + T(1280) * b * t11 + T(11) * (T(128) * a_minus_b * t13 + T(128) * b * t15 + T(3) * (T(48) * a_minus_b * t12 + T(48) * b * t14 + T(7) * (T(8) * b * t10 + T(8) * a_minus_b * t6 + T(5) * (T(2) * b * t9 + T(2) * a_minus_b * t5 + T(3) * (J2 * a + a_minus_b * t4 + b * t8) * t16 * a) * t16 * a) * t16 * a) * t16 * a) * t16 * a;
    const T t18 = t11 * t8;
    const T t19 = t7 * t4;
    const T t20 = T(15360) * a_minus_b * t19 + T(15360) * b * t18 + T(13) * t17 * t16 * a;
    const T t21 = T(15360) * t18 + t20 * b * t16 - T(15360) * t19;
    const T t22 = T(1) / a;
    const T t23 = T(14) * t17 * t16 + T(2) * b * t21 * t22 - t20 * c * t16;
    F = (T(1) / T(215040)) * t23 * in.w[2] * t22 + (T(1) / T(215040)) * in.w[1] * t21 * t22 + (T(1) / T(215040)) * t20 * t16 * in.w[0] + (T(1) / T(215040)) * in.w[3] * (T(2) * b * t23 * t22 + T(14) * (T(1280) * t11 + b * t17 * t16 - T(1280) * t7) * t22 - c * t21 * t22) * t22;
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[3] * in.w[3] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ab = in.w[3] * M_beyond[4] + in.w[2] * M_beyond[3] + M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = t3 * atan2(t2, c_minus_b);
    const T t4 = T(1) / D;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = t6 * t6;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t12 * t12;
    const T t15 = t10 * t5;
    const T t16 = t14 * t11;
    const T t17 = t13 * t13;
    const T t18 = T(1280) * a_minus_b * t8 + T(11) * t4 * a * (T(3) * t4 * a * (T(48) * a_minus_b * t10 + T(7) * (T(8) * a_minus_b * t7 + T(8) * b * t13 + T(5) * (T(2) * a_minus_b * t6 + T(3) * (b * t11 + a * J2 + a_minus_b * t5) * t4 * a + T(2) * b * t12) * t4 * a) * t4 * a + T(48) * b * t14) + T(128) * a_minus_b * t15 + T(128) * b * t16) + T(1280) * b * t17;
    const T t19 = t17 * t11;
    const T t20 = T(15360) * a_minus_b * t9 + T(13) * t4 * a * t18 + T(15360) * b * t19;
    const T t21 = t14 * t14;
    const T t22 = t10 * t10;
    const T t23 = t4 * a * t20 + T(14336) * b * t21 + T(14336) * a_minus_b * t22;
    const T t24 = T(1) / a;
    const T t25 = T(14336) * t22 - T(14336) * t21 - t4 * t23 * b;
    const T t26 = T(15360) * t9 - t4 * t20 * b - T(15360) * t19;
    const T t27 = T(15) * t4 * t23 * c + T(30) * t25 * t24 * b - T(16) * t4 * t20;
    const T t28 = T(15) * t25 * t24 * c - T(16) * t24 * t26 - T(2) * t27 * t24 * b;
    G_ap = (T(1) / T(229376)) * t4 * t23 * in.w[0] + (T(1) / T(3440640)) * t24 * in.w[3] * t28 - (T(1) / T(3440640)) * t27 * in.w[2] * t24 - (T(1) / T(229376)) * t25 * t24 * in.w[1];
    G_ab = (T(1) / T(3440640)) * in.w[2] * t24 * t28 + (T(1) / T(3440640)) * t24 * in.w[3] * (t27 * t24 * c + T(2) * t24 * b * t28 - T(16) * t24 * (t4 * t20 * c + T(2) * t24 * t26 * b - T(14) * t4 * t18)) - (T(1) / T(3440640)) * t27 * t24 * in.w[1] - (T(1) / T(229376)) * t25 * t24 * in.w[0];
  }
  const T g_factor = -T(16) * length * in.s;
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
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
  const T t0 = -a_minus_b * b;
  const T t1 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0) && t1 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3];
    G_ap = M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[8] * in.w[3];
    G_ab = M_beyond[6] * in.w[0] + in.w[1] * M_beyond[7] + M_beyond[9] * in.w[3] + in.w[2] * M_beyond[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t2 = sqrt(D);
    const T t3 = T(1) / t2;
    const T J2 = atan2(t2, c_minus_b) * t3;
    const T t4 = T(1) / c;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = t10 * t10;
    const T t14 = t13 * t9;
    const T t15 = t12 * t12;
    const T t16 = t11 * t11;
    const T t17 = T(11) * (T(128) * b * t7 + T(3) * (T(7) * t8 * (T(5) * (T(2) * a_minus_b * t10 + T(2) * b * t5 + T(3) * (b * t4 + a_minus_b * t9 + J2 * a) * t8 * a) * t8 * a + T(8) * a_minus_b * t11 + T(8) * b * t12) * a + T(48) * b * t6 + T(48) * a_minus_b * t13) * t8 * a + T(128) * a_minus_b * t14) * t8 * a + T(1280) * b * t15 + T(1280) * a_minus_b * t16;
    const T t18 = t15 * t4;
    const T t19 = t16 * t9;
    const T t20 = T(13) * t17 * t8 * a + T(15360) * b * t18 + T(15360) * a_minus_b * t19;
    const T t21 = T(15360) * t18 + t20 * b * t8 - T(15360) * t19;
    const T t22 = T(1) / a;
    const T t23 = T(14) * t17 * t8 + T(2) * b * t21 * t22 - t20 * c * t8;
    F = (T(1) / T(215040)) * t20 * t8 * in.w[0] + (T(1) / T(215040)) * in.w[1] * t21 * t22 + (T(1) / T(215040)) * t23 * in.w[2] * t22 - (T(1) / T(215040)) * (c * t21 * t22 - T(2) * b * t23 * t22 - T(14) * (T(1280) * t15 + b * t17 * t8 - T(1280) * t16) * t22) * in.w[3] * t22;
    const T t24 = t6 * t6;
    const T t25 = t13 * t13;
    const T t26 = t20 * t8 * a + T(14336) * b * t24 + T(14336) * a_minus_b * t25;
    const T t27 = t26 * b * t8 + T(14336) * t24 - T(14336) * t25;
    const T t28 = T(30) * b * t22 * t27 + T(16) * t20 * t8 - T(15) * t26 * c * t8;
    const T t29 = T(16) * t21 * t22 + T(2) * b * t28 * t22 - T(15) * c * t22 * t27;
    G_ap = (T(1) / T(229376)) * in.w[1] * t22 * t27 + (T(1) / T(3440640)) * in.w[3] * t29 * t22 + (T(1) / T(229376)) * t26 * t8 * in.w[0] + (T(1) / T(3440640)) * t28 * in.w[2] * t22;
    G_ab = (T(1) / T(229376)) * t22 * t27 * in.w[0] + (T(1) / T(3440640)) * in.w[1] * t28 * t22 + (T(1) / T(3440640)) * in.w[2] * t29 * t22 + (T(1) / T(3440640)) * (T(16) * t23 * t22 + T(2) * b * t29 * t22 - t28 * c * t22) * in.w[3] * t22;
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

}  // namespace skelconv::generated
