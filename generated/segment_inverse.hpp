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

#include <skelconv/segment_input.hpp>

namespace skelconv::generated {

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 26 +, 30 ×, 2 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    X = (t1 + r0 * a_minus_b) * length / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = ab_ap * r1;
    X = (ab_ap - a_minus_b) * length / (t2 - r0 * a_minus_b);
  }
  const T J1 = asinh(X) / length;
  f = in.w[0] * J1 * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 30 +, 40 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = T(1) / r0;
  const T t2 = t0 * a_minus_b + ab_ap * t1;
  const T t3 = T(1) / cross_cross;
  const T g_ap = in.w[0] * t2 * t3;
  const T g_ab = (t1 + t2 * ab_ap * t3 - t0) * in.w[0] / ab_ab;
  const T g_factor = -length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−1) dt
/// Operations: 31 +, 49 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
    X = t1 * length * (t2 + ab_ap * r1);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  const T t5 = T(1) / r1;
  const T t6 = T(1) / r0;
  const T t7 = t5 * a_minus_b + t6 * ab_ap;
  const T t8 = T(1) / cross_cross;
  const T g_ap = t7 * t8 * in.w[0];
  const T t9 = T(1) / ab_ab;
  const T g_ab = -(t5 - ab_ap * t7 * t8 - t6) * t9 * in.w[0];
  const T g_factor = -length;
  f = in.w[0] * J1 * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 29 +, 34 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  T X;
  const T t0 = ab_ap * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = ab_ap * r1;
    X = length * (t1 + r0 * a_minus_b) / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = ab_ap * r1;
    X = length * (ab_ap - a_minus_b) / (t2 - r0 * a_minus_b);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  const T t4 = T(1) / ab_ab;
  f = (J1 * in.w[0] - in.w[1] * (r0 - r1 - ab_ap * J1) * t4) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 35 +, 56 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
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
    const T t2 = a_minus_b * r0;
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r0;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(1) / r1;
  const T t9 = t6 * ab_ap + t8 * a_minus_b;
  const T t10 = t6 + t7 * t9 * ab_ap - t8;
  const T g_ap = t5 * in.w[1] * t10 + t7 * t9 * in.w[0];
  const T g_ab = t5 * t10 * in.w[0] - t5 * in.w[1] * (t7 * ap_ap * t9 - T(2) * t5 * t10 * ab_ap - J1);
  const T g_factor = -length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−1) dt
/// Operations: 38 +, 61 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
    X = length * (t1 + a_minus_b * r0) * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = ab_ap * r1;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / r1;
  const T t6 = T(1) / r0;
  const T t7 = a_minus_b * t5 + t6 * ab_ap;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(1) / ab_ab;
  const T t10 = t5 - t7 * ab_ap * t8 - t6;
  const T g_ap = t7 * in.w[0] * t8 - t9 * t10 * in.w[1];
  const T g_ab = t9 * (J1 - t7 * ap_ap * t8 - T(2) * t9 * t10 * ab_ap) * in.w[1] - t9 * t10 * in.w[0];
  const T g_factor = -length;
  f = (J1 * in.w[0] - t9 * in.w[1] * (r0 - r1 - J1 * ab_ap)) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 34 +, 48 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
  const T t4 = T(1) / ab_ab;
  const T t5 = J1 * ab_ap + r1 - r0;
  f = (T(1) / T(2)) * (T(2) * J1 * in.w[0] + T(2) * t4 * in.w[1] * t5 + t4 * in.w[2] * (t4 * (J1 * cross_cross + ab_ap * r0 + a_minus_b * r1) + T(4) * t4 * ab_ap * t5 - T(2) * J1 * ap_ap)) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 41 +, 67 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
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
    X = (t1 + ab_ap * r1) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  const T t5 = T(1) / r0;
  const T t6 = T(1) / r1;
  const T t7 = t5 * ab_ap + t6 * a_minus_b;
  const T t8 = T(1) / cross_cross;
  const T t9 = t5 + t7 * ab_ap * t8 - t6;
  const T t10 = T(1) / ab_ab;
  const T t11 = ap_ap * t7 * t8 - T(2) * t9 * ab_ap * t10 - J1;
  const T g_ap = in.w[0] * t7 * t8 + t9 * in.w[1] * t10 - t11 * in.w[2] * t10;
  const T g_ab = in.w[0] * t9 * t10 - (T(2) * ab_ap * t11 * t10 + ap_ap * t9 * t10 + t10 * (r0 - r1 - ab_ap * J1)) * in.w[2] * t10 - in.w[1] * t11 * t10;
  const T g_factor = -length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−1) dt
/// Operations: 47 +, 85 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
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
    X = (t1 + ab_ap * r1) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -length * (ab_ap - a_minus_b) / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r1;
  const T t7 = T(1) / r0;
  const T t8 = t6 * a_minus_b + ab_ap * t7;
  const T t9 = T(1) / cross_cross;
  const T t10 = t8 * ab_ap * t9 + t7 - t6;
  const T t11 = J1 + T(2) * ab_ap * t5 * t10 - ap_ap * t8 * t9;
  const T g_ap = in.w[1] * t5 * t10 + in.w[0] * t8 * t9 + t11 * t5 * in.w[2];
  const T t12 = J1 * ab_ap + r1 - r0;
  const T g_ab = in.w[0] * t5 * t10 + t11 * in.w[1] * t5 - t5 * in.w[2] * (ap_ap * t5 * t10 - T(2) * t11 * ab_ap * t5 - t12 * t5);
  const T g_factor = -length;
  f = (T(1) / T(2)) * length * (T(2) * J1 * in.w[0] + T(2) * t12 * in.w[1] * t5 - t5 * in.w[2] * (T(2) * J1 * ap_ap - t5 * (J1 * cross_cross + ab_ap * r0 + r1 * a_minus_b) - T(4) * t12 * ab_ap * t5));
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 39 +, 65 ×, 3 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
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
    const T t1 = r1 * ab_ap;
    X = (t1 + a_minus_b * r0) * length / cross_cross;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t2 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t2 - a_minus_b * r0);
  }
  const T t3 = T(1) / length;
  const T J1 = t3 * asinh(X);
  const T t4 = T(1) / ab_ab;
  const T t5 = ab_ap * r0 + r1 * a_minus_b + cross_cross * J1;
  const T t6 = J1 * ab_ap + r1 - r0;
  const T t7 = T(4) * t6 * t4 * ab_ap + t4 * t5 - T(2) * J1 * ap_ap;
  f = (T(1) / T(6)) * (T(6) * in.w[0] * J1 + t4 * in.w[3] * (t4 * (T(3) * t4 * t5 * ab_ap + T(2) * r1 * bp_bp - T(2) * ap_ap * r0) + T(6) * t4 * t7 * ab_ap - T(6) * t6 * t4 * ap_ap) + T(3) * t4 * t7 * in.w[2] + T(6) * t6 * t4 * in.w[1]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 49 +, 88 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i1_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + ab0 * bp0;
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
    X = (t1 + ab_ap * r1) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  const T t5 = T(1) / r0;
  const T t6 = T(1) / r1;
  const T t7 = t5 * ab_ap + t6 * a_minus_b;
  const T t8 = T(1) / cross_cross;
  const T t9 = t5 + t7 * ab_ap * t8 - t6;
  const T t10 = T(1) / ab_ab;
  const T t11 = ap_ap * t7 * t8 - T(2) * t9 * ab_ap * t10 - J1;
  const T t12 = r0 - r1 - ab_ap * J1;
  const T t13 = t12 * t10 + ap_ap * t9 * t10 + T(2) * t11 * ab_ap * t10;
  const T g_ap = in.w[1] * t9 * t10 + t7 * t8 * in.w[0] - t11 * in.w[2] * t10 - t13 * in.w[3] * t10;
  const T g_ab = (T(1) / T(2)) * (((r1 * a_minus_b + r0 * ab_ap + cross_cross * J1) * t10 - T(2) * ap_ap * J1 - T(4) * ab_ap * t12 * t10) * t10 + T(2) * ap_ap * t11 * t10 - T(4) * t13 * ab_ap * t10) * in.w[3] * t10 + t9 * in.w[0] * t10 - in.w[1] * t11 * t10 - t13 * in.w[2] * t10;
  const T g_factor = -length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−1) dt
/// Operations: 56 +, 114 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i1_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
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
    X = (t1 + r1 * ab_ap) * length * t2;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = (a_minus_b - ab_ap) * length / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r0;
  const T t7 = T(1) / r1;
  const T t8 = t6 * ab_ap + t7 * a_minus_b;
  const T t9 = T(1) / cross_cross;
  const T t10 = t8 * ab_ap * t9 + t6 - t7;
  const T t11 = J1 + T(2) * t5 * t10 * ab_ap - ap_ap * t8 * t9;
  const T t12 = r1 + J1 * ab_ap - r0;
  const T t13 = T(2) * t5 * t11 * ab_ap + t5 * t12 - t5 * ap_ap * t10;
  const T g_ap = t5 * t11 * in.w[2] + t5 * t10 * in.w[1] + in.w[0] * t8 * t9 + t13 * t5 * in.w[3];
  const T t14 = r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross;
  const T t15 = T(4) * t5 * t12 * ab_ap + t14 * t5 - T(2) * J1 * ap_ap;
  const T g_ab = t5 * in.w[1] * t11 + (T(1) / T(2)) * t5 * in.w[3] * (T(4) * t13 * t5 * ab_ap + t5 * t15 - T(2) * t5 * ap_ap * t11) + t13 * t5 * in.w[2] + t5 * in.w[0] * t10;
  const T g_factor = -length;
  f = -(T(1) / T(6)) * (t5 * in.w[3] * (T(6) * t5 * t12 * ap_ap - T(6) * t5 * ab_ap * t15 - t5 * (T(2) * r1 * bp_bp + T(3) * t14 * t5 * ab_ap - T(2) * ap_ap * r0)) - T(6) * in.w[0] * J1 - T(3) * t5 * in.w[2] * t15 - T(6) * t5 * t12 * in.w[1]) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 18 +, 17 ×, 1 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i2_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t0 = sqrt(cross_cross);
  const T J2 = atan2(t0, ap_bp) / t0;
  f = in.w[0] * J2 * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 33 +, 48 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = T(1) / ap_ap;
  const T t4 = t2 * a_minus_b + J2 * ab_ab + t3 * ab_ap;
  const T t5 = T(1) / cross_cross;
  const T g_ap = (T(1) / T(2)) * t4 * t5 * in.w[0];
  const T g_ab = (T(1) / T(2)) * (ab_ap * t4 * t5 + t3 - t2) * in.w[0] / ab_ab;
  const T g_factor = -T(2) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−2) dt
/// Operations: 33 +, 50 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i2_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = T(1) / ap_ap;
  const T t5 = a_minus_b * t3 + ab_ab * J2 + ab_ap * t4;
  const T g_ap = (T(1) / T(2)) * t2 * in.w[0] * t5;
  const T g_ab = -(T(1) / T(2)) * (t3 - ab_ap * t2 * t5 - t4) * in.w[0] / ab_ab;
  const T g_factor = -T(2) * length;
  f = in.w[0] * J2 * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 26 +, 31 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = sqrt(cross_cross);
  const T J2 = atan2(t0, ap_bp) / t0;
  const T log_ratio = log(bp_bp / ap_ap);
  f = (T(1) / T(2)) * ((T(2) * J2 * ab_ap + log_ratio) * in.w[1] / ab_ab + T(2) * J2 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 37 +, 61 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = T(1) / ap_ap;
  const T t4 = a_minus_b * t2 + ab_ap * t3 + ab_ab * J2;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / ab_ab;
  const T t7 = t4 * ab_ap * t5 + t3 - t2;
  const T g_ap = (T(1) / T(2)) * in.w[0] * t4 * t5 + (T(1) / T(2)) * t6 * in.w[1] * t7;
  const T g_ab = (T(1) / T(2)) * t6 * (T(2) * J2 + T(2) * ab_ap * t6 * t7 - t4 * t5 * ap_ap) * in.w[1] + (T(1) / T(2)) * in.w[0] * t6 * t7;
  const T g_factor = -T(2) * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−2) dt
/// Operations: 39 +, 70 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * a_minus_b + J2 * ab_ab + t2 * ab_ap;
  const T t5 = T(1) / cross_cross;
  const T t6 = t3 - ab_ap * t4 * t5 - t2;
  const T t7 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(2)) * t4 * in.w[0] * t5 - (T(1) / T(2)) * t6 * t7 * in.w[1];
  const T g_ab = (T(1) / T(2)) * (T(2) * J2 - T(2) * ab_ap * t6 * t7 - ap_ap * t4 * t5) * t7 * in.w[1] - (T(1) / T(2)) * in.w[0] * t6 * t7;
  const T g_factor = -T(2) * length;
  f = (T(1) / T(2)) * (T(2) * J2 * in.w[0] + (T(2) * J2 * ab_ap + log_ratio) * t7 * in.w[1]) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 29 +, 38 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T t0 = sqrt(cross_cross);
  const T J2 = atan2(t0, ap_bp) / t0;
  const T log_ratio = log(bp_bp / ap_ap);
  const T t1 = T(1) / ab_ab;
  const T t2 = T(2) * ab_ap * J2 + log_ratio;
  f = -(T(1) / T(2)) * (T(2) * (ap_ap * J2 - ab_ap * t1 * t2 - T(1)) * t1 * in.w[2] - T(2) * in.w[0] * J2 - in.w[1] * t1 * t2) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 42 +, 76 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / bp_bp;
  const T t5 = a_minus_b * t4 + ab_ap * t2 + ab_ab * J2;
  const T t6 = t2 + ab_ap * t3 * t5 - t4;
  const T t7 = T(1) / ab_ab;
  const T t8 = t3 * t5 * ap_ap - T(2) * J2 - T(2) * ab_ap * t6 * t7;
  const T g_ap = (T(1) / T(2)) * t3 * t5 * in.w[0] + (T(1) / T(2)) * in.w[1] * t6 * t7 - (T(1) / T(2)) * t8 * in.w[2] * t7;
  const T g_ab = (T(1) / T(2)) * t6 * t7 * in.w[0] - (T(1) / T(2)) * in.w[2] * t7 * (t6 * t7 * ap_ap + T(2) * ab_ap * t8 * t7 - t7 * (log_ratio + T(2) * ab_ap * J2)) - (T(1) / T(2)) * in.w[1] * t8 * t7;
  const T g_factor = -T(2) * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−2) dt
/// Operations: 46 +, 88 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / ab_ab;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / bp_bp;
  const T t6 = ab_ab * J2 + a_minus_b * t5 + t2 * ab_ap;
  const T t7 = t2 + t4 * ab_ap * t6 - t5;
  const T t8 = t4 * ap_ap * t6 - T(2) * t3 * t7 * ab_ap - T(2) * J2;
  const T g_ap = (T(1) / T(2)) * t3 * t7 * in.w[1] + (T(1) / T(2)) * t4 * in.w[0] * t6 - (T(1) / T(2)) * t8 * t3 * in.w[2];
  const T t9 = log_ratio + T(2) * J2 * ab_ap;
  const T g_ab = (T(1) / T(2)) * t3 * in.w[2] * (t9 * t3 - t3 * ap_ap * t7 - T(2) * t8 * t3 * ab_ap) + (T(1) / T(2)) * t3 * in.w[0] * t7 - (T(1) / T(2)) * t8 * t3 * in.w[1];
  const T g_factor = -T(2) * length;
  f = -(T(1) / T(2)) * length * (T(2) * t3 * in.w[2] * (ap_ap * J2 - t9 * t3 * ab_ap - T(1)) - T(2) * J2 * in.w[0] - t9 * t3 * in.w[1]);
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 34 +, 47 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T t0 = sqrt(cross_cross);
  const T J2 = atan2(t0, ap_bp) / t0;
  const T log_ratio = log(bp_bp / ap_ap);
  const T t1 = T(2) * J2 * ab_ap + log_ratio;
  const T t2 = T(1) / ab_ab;
  const T t3 = J2 * ap_ap - t1 * ab_ap * t2 - T(1);
  f = -(T(1) / T(2)) * length * (T(2) * in.w[2] * t3 * t2 + ((ap_ap - bp_bp - T(2) * ab_ap) * t2 + T(4) * ab_ap * t3 * t2 + ap_ap * t1 * t2) * t2 * in.w[3] - in.w[1] * t1 * t2 - T(2) * J2 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 48 +, 92 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i2_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / ab_ab;
  const T t4 = T(1) / bp_bp;
  const T t5 = a_minus_b * t4 + ab_ab * J2 + t2 * ab_ap;
  const T t6 = T(1) / cross_cross;
  const T t7 = t2 + t5 * ab_ap * t6 - t4;
  const T t8 = ap_ap * t5 * t6 - T(2) * J2 - T(2) * t3 * t7 * ab_ap;
  const T t9 = log_ratio + T(2) * J2 * ab_ap;
  const T t10 = T(2) * t3 * ab_ap * t8 + t3 * t7 * ap_ap - t3 * t9;
  const T g_ap = (T(1) / T(2)) * t3 * t7 * in.w[1] + (T(1) / T(2)) * in.w[0] * t5 * t6 - (T(1) / T(2)) * t3 * in.w[2] * t8 - (T(1) / T(2)) * t3 * in.w[3] * t10;
  const T g_ab = (T(1) / T(2)) * t3 * in.w[0] * t7 + (T(1) / T(2)) * t3 * in.w[3] * (t3 * ap_ap * t8 + T(2) * t3 * (t3 * t9 * ab_ap + T(1) - ap_ap * J2) - T(2) * t3 * t10 * ab_ap) - (T(1) / T(2)) * t3 * in.w[1] * t8 - (T(1) / T(2)) * t3 * t10 * in.w[2];
  const T g_factor = -T(2) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−2) dt
/// Operations: 55 +, 110 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i2_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / bp_bp;
  const T t4 = ab_ab * J2 + t2 * ab_ap + a_minus_b * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = t2 + t4 * ab_ap * t5 - t3;
  const T t7 = T(1) / ab_ab;
  const T t8 = log_ratio + T(2) * J2 * ab_ap;
  const T t9 = t4 * ap_ap * t5 - T(2) * J2 - T(2) * t6 * t7 * ab_ap;
  const T t10 = t7 * t8 - T(2) * t9 * t7 * ab_ap - t6 * t7 * ap_ap;
  const T g_ap = (T(1) / T(2)) * t6 * t7 * in.w[1] + (T(1) / T(2)) * t4 * in.w[0] * t5 + (T(1) / T(2)) * t7 * in.w[3] * t10 - (T(1) / T(2)) * t9 * t7 * in.w[2];
  const T t11 = t7 * t8 * ab_ap + T(1) - ap_ap * J2;
  const T g_ab = (T(1) / T(2)) * t7 * in.w[3] * (T(2) * t7 * t11 + t9 * t7 * ap_ap + T(2) * t7 * t10 * ab_ap) + (T(1) / T(2)) * t6 * t7 * in.w[0] + (T(1) / T(2)) * t7 * t10 * in.w[2] - (T(1) / T(2)) * t9 * t7 * in.w[1];
  const T g_factor = -T(2) * length;
  f = (T(1) / T(2)) * length * (t7 * in.w[1] * t8 + T(2) * t7 * t11 * in.w[2] + T(2) * in.w[0] * J2 - t7 * in.w[3] * (t7 * (ap_ap - bp_bp - T(2) * ab_ap) + t7 * ap_ap * t8 - T(4) * t7 * t11 * ab_ap));
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 25 +, 26 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i3_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  f = in.w[0] * length * (ab_ap / r0 + a_minus_b / r1) / cross_cross;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 32 +, 54 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = T(1) / r1;
  const T t2 = T(1) / cross_cross;
  const T t3 = t0 * t0;
  const T t4 = t1 * t1;
  const T t5 = T(2) * (t0 * ab_ap + t1 * a_minus_b) * t2 * ab_ab + t3 * t0 * ab_ap + t4 * t1 * a_minus_b;
  const T g_ap = (T(1) / T(3)) * t5 * t2 * in.w[0];
  const T g_ab = -(T(1) / T(3)) * (t4 * t1 - t5 * ab_ap * t2 - t3 * t0) * in.w[0] / ab_ab;
  const T g_factor = -T(3) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−3) dt
/// Operations: 32 +, 57 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i3_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r0;
  const T t4 = t3 * t3;
  const T t5 = ab_ap * t3 + t1 * a_minus_b;
  const T t6 = t1 * a_minus_b * t2 + t4 * ab_ap * t3 + T(2) * t0 * ab_ab * t5;
  const T g_ap = (T(1) / T(3)) * t0 * in.w[0] * t6;
  const T g_ab = (T(1) / T(3)) * in.w[0] * (t4 * t3 + t0 * t6 * ab_ap - t1 * t2) / ab_ab;
  const T g_factor = -T(3) * length;
  f = t0 * in.w[0] * t5 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 28 +, 32 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i3_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = T(1) / r1;
  const T t2 = ab_ap * t0 + a_minus_b * t1;
  const T t3 = T(1) / cross_cross;
  f = length * (t2 * in.w[0] * t3 + (t2 * ab_ap * t3 + t0 - t1) * in.w[1] / ab_ab);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 36 +, 68 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / r1;
  const T t4 = t3 * a_minus_b + ab_ap * t0;
  const T t5 = t3 * t3;
  const T t6 = T(2) * t2 * t4 * ab_ab + t3 * a_minus_b * t5 + t1 * ab_ap * t0;
  const T t7 = t1 * t0 + t2 * t6 * ab_ap - t3 * t5;
  const T t8 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(3)) * t7 * t8 * in.w[1] + (T(1) / T(3)) * in.w[0] * t2 * t6;
  const T g_ab = (T(1) / T(3)) * t8 * in.w[1] * (T(3) * t2 * t4 + T(2) * t7 * t8 * ab_ap - t2 * ap_ap * t6) + (T(1) / T(3)) * in.w[0] * t7 * t8;
  const T g_factor = -T(3) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−3) dt
/// Operations: 39 +, 75 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i3_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = T(1) / r0;
  const T t2 = t0 * a_minus_b + ab_ap * t1;
  const T t3 = T(1) / cross_cross;
  const T t4 = t0 * t0;
  const T t5 = t1 * t1;
  const T t6 = T(2) * ab_ab * t2 * t3 + t0 * t4 * a_minus_b + t5 * ab_ap * t1;
  const T t7 = t6 * ab_ap * t3 + t5 * t1 - t0 * t4;
  const T t8 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(3)) * t6 * in.w[0] * t3 + (T(1) / T(3)) * t7 * t8 * in.w[1];
  const T g_ab = (T(1) / T(3)) * t7 * t8 * in.w[0] + (T(1) / T(3)) * t8 * in.w[1] * (T(3) * t2 * t3 + T(2) * t7 * t8 * ab_ap - t6 * ap_ap * t3);
  const T g_factor = -T(3) * length;
  f = (t2 * in.w[0] * t3 + t8 * in.w[1] * (t1 + t2 * ab_ap * t3 - t0)) * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 32 +, 46 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i3_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
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
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = length * (a_minus_b - ab_ap) / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / r1;
  const T t7 = T(1) / r0;
  const T t8 = t6 * a_minus_b + t7 * ab_ap;
  const T t9 = T(1) / ab_ab;
  const T t10 = t6 - t5 * t8 * ab_ap - t7;
  f = length * (t5 * in.w[0] * t8 - t9 * in.w[2] * (t5 * ap_ap * t8 + T(2) * t10 * t9 * ab_ap - J1) - t10 * t9 * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 42 +, 83 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / r1;
  const T t5 = t4 * a_minus_b + t1 * ab_ap;
  const T t6 = t4 * t4;
  const T t7 = T(2) * t3 * ab_ab * t5 + t1 * t2 * ab_ap + t4 * a_minus_b * t6;
  const T t8 = t1 * t2 + t3 * t7 * ab_ap - t4 * t6;
  const T t9 = t3 * ap_ap * t7 - T(3) * t3 * t5 - T(2) * t0 * t8 * ab_ap;
  const T g_ap = (T(1) / T(3)) * t0 * t8 * in.w[1] + (T(1) / T(3)) * t3 * in.w[0] * t7 - (T(1) / T(3)) * t0 * in.w[2] * t9;
  const T g_ab = (T(1) / T(3)) * t0 * in.w[0] * t8 - (T(1) / T(3)) * t0 * t9 * in.w[1] - (T(1) / T(3)) * t0 * in.w[2] * (T(2) * t0 * t9 * ab_ap + t0 * ap_ap * t8 + T(3) * t0 * (t4 - t1 - t3 * t5 * ab_ap));
  const T g_factor = -T(3) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−3) dt
/// Operations: 47 +, 101 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i3_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + ab1 * bp1;
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
    X = length * (ab_ap - a_minus_b) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(1) / r0;
  const T t10 = t6 * a_minus_b + ab_ap * t9;
  const T t11 = t9 * t9;
  const T t12 = t6 * a_minus_b * t7 + T(2) * t8 * ab_ab * t10 + ab_ap * t11 * t9;
  const T t13 = ab_ap * t12 * t8 + t11 * t9 - t6 * t7;
  const T t14 = T(3) * t8 * t10 + T(2) * ab_ap * t5 * t13 - t12 * t8 * ap_ap;
  const T g_ap = (T(1) / T(3)) * in.w[1] * t5 * t13 + (T(1) / T(3)) * t14 * t5 * in.w[2] + (T(1) / T(3)) * t12 * t8 * in.w[0];
  const T t15 = ab_ap * t8 * t10 + t9 - t6;
  const T g_ab = (T(1) / T(3)) * t5 * t13 * in.w[0] + (T(1) / T(3)) * (T(3) * t15 * t5 + T(2) * ab_ap * t14 * t5 - t5 * t13 * ap_ap) * t5 * in.w[2] + (T(1) / T(3)) * in.w[1] * t14 * t5;
  const T g_factor = -T(3) * length;
  f = -(t5 * in.w[2] * (t8 * ap_ap * t10 - T(2) * ab_ap * t15 * t5 - J1) - t15 * in.w[1] * t5 - t8 * t10 * in.w[0]) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 37 +, 55 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i3_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
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
    const T t1 = r0 * a_minus_b;
    const T t2 = T(1) / cross_cross;
    X = (t1 + ab_ap * r1) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r0 * a_minus_b;
    X = -(ab_ap - a_minus_b) * length / (t3 - ab_ap * r1);
  }
  const T t4 = T(1) / length;
  const T J1 = asinh(X) * t4;
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r0;
  const T t7 = T(1) / r1;
  const T t8 = t6 * ab_ap + t7 * a_minus_b;
  const T t9 = T(1) / cross_cross;
  const T t10 = t6 + t8 * ab_ap * t9 - t7;
  const T t11 = J1 + T(2) * t10 * ab_ap * t5 - ap_ap * t8 * t9;
  f = length * (((J1 * ab_ap + r1 - r0) * t5 + T(2) * ab_ap * t5 * t11 - ap_ap * t10 * t5) * t5 * in.w[3] + t8 * t9 * in.w[0] + in.w[1] * t10 * t5 + in.w[2] * t5 * t11);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 49 +, 107 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i3_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
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
    const T t1 = r1 * ab_ap;
    const T t2 = T(1) / cross_cross;
    X = (t1 + a_minus_b * r0) * t2 * length;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = r1 * ab_ap;
    X = -length * (a_minus_b - ab_ap) / (t3 - a_minus_b * r0);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / ab_ab;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(1) / r1;
  const T t10 = t9 * t9;
  const T t11 = ab_ap * t6 + t9 * a_minus_b;
  const T t12 = t9 * a_minus_b * t10 + T(2) * t8 * ab_ab * t11 + t7 * ab_ap * t6;
  const T t13 = t7 * t6 + t8 * ab_ap * t12 - t9 * t10;
  const T t14 = t6 + t8 * t11 * ab_ap - t9;
  const T t15 = T(2) * t5 * ab_ap * t13 + T(3) * t8 * t11 - t8 * ap_ap * t12;
  const T t16 = T(3) * t14 * t5 + T(2) * t5 * t15 * ab_ap - t5 * ap_ap * t13;
  const T g_ap = (T(1) / T(3)) * t5 * in.w[1] * t13 + (T(1) / T(3)) * t5 * in.w[3] * t16 + (T(1) / T(3)) * t5 * t15 * in.w[2] + (T(1) / T(3)) * t8 * in.w[0] * t12;
  const T g_ab = (T(1) / T(3)) * t5 * in.w[1] * t15 + (T(1) / T(3)) * t5 * in.w[0] * t13 + (T(1) / T(3)) * t5 * in.w[3] * (T(3) * t5 * (J1 + T(2) * t14 * t5 * ab_ap - t8 * ap_ap * t11) + T(2) * t5 * t16 * ab_ap - t5 * ap_ap * t15) + (T(1) / T(3)) * t5 * t16 * in.w[2];
  const T g_factor = -T(3) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−3) dt
/// Operations: 56 +, 123 ×, 6 /, 3 sqrt, 0 atan, 1 log/asinh.
template <class T>
T segment_inverse_i3_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
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
    X = t1 * length * (t2 + r1 * ab_ap);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = a_minus_b * r0;
    X = (a_minus_b - ab_ap) * length / (t3 - r1 * ab_ap);
  }
  const T t4 = T(1) / length;
  const T J1 = t4 * asinh(X);
  const T t5 = T(1) / r0;
  const T t6 = T(1) / r1;
  const T t7 = t5 * ab_ap + a_minus_b * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t5 * t5;
  const T t10 = t6 * t6;
  const T t11 = T(2) * t7 * t8 * ab_ab + t9 * t5 * ab_ap + a_minus_b * t6 * t10;
  const T t12 = T(1) / ab_ab;
  const T t13 = t6 * t10 - t11 * t8 * ab_ap - t9 * t5;
  const T t14 = t11 * t8 * ap_ap + T(2) * t12 * t13 * ab_ap - T(3) * t7 * t8;
  const T t15 = t5 + t7 * t8 * ab_ap - t6;
  const T t16 = T(2) * t12 * t14 * ab_ap - t12 * ap_ap * t13 - T(3) * t12 * t15;
  const T g_ap = (T(1) / T(3)) * t11 * t8 * in.w[0] - (T(1) / T(3)) * in.w[2] * t12 * t14 - (T(1) / T(3)) * t12 * in.w[3] * t16 - (T(1) / T(3)) * t12 * in.w[1] * t13;
  const T t17 = J1 + T(2) * t12 * t15 * ab_ap - t7 * t8 * ap_ap;
  const T g_ab = (T(1) / T(3)) * t12 * in.w[3] * (T(3) * t12 * t17 + t12 * t14 * ap_ap - T(2) * t12 * t16 * ab_ap) - (T(1) / T(3)) * t12 * in.w[0] * t13 - (T(1) / T(3)) * t12 * t14 * in.w[1] - (T(1) / T(3)) * in.w[2] * t12 * t16;
  const T g_factor = -T(3) * length;
  f = (t12 * t15 * in.w[1] + in.w[2] * t12 * t17 + t7 * t8 * in.w[0] - (t12 * ap_ap * t15 - (J1 * ab_ap + r1 - r0) * t12 - T(2) * t12 * t17 * ab_ap) * t12 * in.w[3]) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 28 +, 33 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  f = (T(1) / T(2)) * length * t2 * (a_minus_b / bp_bp + ab_ab * J2 + ab_ap / ap_ap) * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 35 +, 59 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = T(2) * t3 * a_minus_b + T(3) * t4 * (J2 * ab_ab + t5 * ab_ap + t2 * a_minus_b) * ab_ab + T(2) * t6 * ab_ap;
  const T g_ap = (T(1) / T(8)) * in.w[0] * t7 * t4;
  const T g_ab = (T(1) / T(8)) * in.w[0] * (T(2) * t6 + t7 * ab_ap * t4 - T(2) * t3) / ab_ab;
  const T g_factor = -T(4) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−4) dt
/// Operations: 35 +, 63 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = T(1) / ap_ap;
  const T t5 = t4 * t4;
  const T t6 = t4 * ab_ap + a_minus_b * t2 + J2 * ab_ab;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(2) * a_minus_b * t3 + T(2) * t5 * ab_ap + T(3) * t6 * t7 * ab_ab;
  const T g_ap = (T(1) / T(8)) * in.w[0] * t8 * t7;
  const T g_ab = (T(1) / T(8)) * in.w[0] * (t8 * ab_ap * t7 + T(2) * t5 - T(2) * t3) / ab_ab;
  const T g_factor = -T(4) * length;
  f = (T(1) / T(2)) * in.w[0] * length * t6 * t7;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 31 +, 38 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = T(1) / bp_bp;
  const T t4 = ab_ab * J2 + a_minus_b * t3 + ab_ap * t2;
  const T t5 = T(1) / cross_cross;
  f = (T(1) / T(2)) * length * ((t2 + t4 * ab_ap * t5 - t3) * in.w[1] / ab_ab + t4 * in.w[0] * t5);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 39 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = T(1) / bp_bp;
  const T t5 = t3 * ab_ap + a_minus_b * t4 + ab_ab * J2;
  const T t6 = t3 * t3;
  const T t7 = t4 * t4;
  const T t8 = T(3) * ab_ab * t5 * t2 + T(2) * t6 * ab_ap + T(2) * a_minus_b * t7;
  const T t9 = T(1) / ab_ab;
  const T t10 = ab_ap * t2 * t8 + T(2) * t6 - T(2) * t7;
  const T g_ap = (T(1) / T(8)) * in.w[0] * t2 * t8 + (T(1) / T(8)) * in.w[1] * t9 * t10;
  const T g_ab = (T(1) / T(8)) * t9 * t10 * in.w[0] - (T(1) / T(8)) * (ap_ap * t2 * t8 - T(2) * t9 * t10 * ab_ap - T(4) * t5 * t2) * in.w[1] * t9;
  const T g_factor = -T(4) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−4) dt
/// Operations: 42 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = T(1) / bp_bp;
  const T t5 = t4 * t4;
  const T t6 = ab_ab * J2 + a_minus_b * t4 + ab_ap * t2;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(2) * ab_ap * t3 + T(2) * a_minus_b * t5 + T(3) * t6 * t7 * ab_ab;
  const T t9 = ab_ap * t8 * t7 + T(2) * t3 - T(2) * t5;
  const T t10 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(8)) * in.w[0] * t8 * t7 + (T(1) / T(8)) * t9 * t10 * in.w[1];
  const T g_ab = (T(1) / T(8)) * in.w[0] * t9 * t10 - (T(1) / T(8)) * (t8 * t7 * ap_ap - T(4) * t6 * t7 - T(2) * ab_ap * t9 * t10) * t10 * in.w[1];
  const T g_factor = -T(4) * length;
  f = (T(1) / T(2)) * (t10 * in.w[1] * (t2 + t6 * ab_ap * t7 - t4) + t6 * in.w[0] * t7) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = g_factor * (g_ap * ap1 - g_ab * ab1);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 34 +, 47 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = T(1) / bp_bp;
  const T t5 = t3 * ab_ap + t4 * a_minus_b + ab_ab * J2;
  const T t6 = t4 - t3 - ab_ap * t2 * t5;
  const T t7 = T(1) / ab_ab;
  f = (T(1) / T(2)) * length * (in.w[0] * t2 * t5 - in.w[1] * t6 * t7 - (T(2) * ab_ap * t6 * t7 + ap_ap * t2 * t5 - T(2) * J2) * in.w[2] * t7);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 45 +, 88 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = T(1) / bp_bp;
  const T t6 = ab_ab * J2 + t5 * a_minus_b + ab_ap * t3;
  const T t7 = t5 * t5;
  const T t8 = T(2) * ab_ap * t4 + T(3) * t2 * ab_ab * t6 + T(2) * t7 * a_minus_b;
  const T t9 = T(2) * t7 - ab_ap * t2 * t8 - T(2) * t4;
  const T t10 = T(1) / ab_ab;
  const T t11 = T(2) * ab_ap * t9 * t10 + t2 * ap_ap * t8 - T(4) * t2 * t6;
  const T g_ap = (T(1) / T(8)) * t2 * t8 * in.w[0] - (T(1) / T(8)) * in.w[1] * t9 * t10 - (T(1) / T(8)) * t10 * in.w[2] * t11;
  const T g_ab = (T(1) / T(8)) * (t9 * t10 * ap_ap + T(4) * t10 * (t3 + ab_ap * t2 * t6 - t5) - T(2) * ab_ap * t10 * t11) * t10 * in.w[2] - (T(1) / T(8)) * t9 * t10 * in.w[0] - (T(1) / T(8)) * in.w[1] * t10 * t11;
  const T g_factor = -T(4) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−4) dt
/// Operations: 49 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i4_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = T(1) / bp_bp;
  const T t5 = ab_ab * J2 + ab_ap * t3 + a_minus_b * t4;
  const T t6 = t4 * t4;
  const T t7 = t3 * t3;
  const T t8 = T(3) * t2 * ab_ab * t5 + T(2) * a_minus_b * t6 + T(2) * ab_ap * t7;
  const T t9 = T(1) / ab_ab;
  const T t10 = T(2) * t7 + ab_ap * t2 * t8 - T(2) * t6;
  const T t11 = t2 * t8 * ap_ap - T(2) * ab_ap * t9 * t10 - T(4) * t2 * t5;
  const T g_ap = (T(1) / T(8)) * t2 * t8 * in.w[0] + (T(1) / T(8)) * in.w[1] * t9 * t10 - (T(1) / T(8)) * in.w[2] * t11 * t9;
  const T t12 = ab_ap * t2 * t5 + t3 - t4;
  const T g_ab = (T(1) / T(8)) * in.w[2] * t9 * (T(4) * t9 * t12 - t9 * t10 * ap_ap - T(2) * ab_ap * t11 * t9) + (T(1) / T(8)) * t9 * t10 * in.w[0] - (T(1) / T(8)) * in.w[1] * t11 * t9;
  const T g_factor = -T(4) * length;
  f = (T(1) / T(2)) * ((T(2) * J2 + T(2) * ab_ap * t9 * t12 - t2 * t5 * ap_ap) * in.w[2] * t9 + in.w[1] * t9 * t12 + t2 * t5 * in.w[0]) * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 38 +, 58 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i4_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = T(1) / ab_ab;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / bp_bp;
  const T t6 = ab_ab * J2 + t2 * ab_ap + a_minus_b * t5;
  const T t7 = t2 + t4 * t6 * ab_ap - t5;
  const T t8 = t4 * t6 * ap_ap - T(2) * t3 * t7 * ab_ap - T(2) * J2;
  f = -(T(1) / T(2)) * length * (in.w[2] * t3 * t8 + (t3 * ap_ap * t7 + T(2) * t3 * t8 * ab_ap - t3 * (T(2) * J2 * ab_ap + log_ratio)) * t3 * in.w[3] - t3 * in.w[1] * t7 - t4 * in.w[0] * t6);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 51 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i4_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / bp_bp;
  const T t5 = t4 * t4;
  const T t6 = T(1) / ap_ap;
  const T t7 = ab_ab * J2 + ab_ap * t6 + t4 * a_minus_b;
  const T t8 = t6 * t6;
  const T t9 = T(2) * t5 * a_minus_b + T(3) * t3 * t7 * ab_ab + T(2) * ab_ap * t8;
  const T t10 = ab_ap * t3 * t9 + T(2) * t8 - T(2) * t5;
  const T t11 = T(2) * ab_ap * t2 * t10 + T(4) * t3 * t7 - t3 * ap_ap * t9;
  const T t12 = t6 + ab_ap * t3 * t7 - t4;
  const T t13 = t2 * t10 * ap_ap - T(2) * ab_ap * t11 * t2 - T(4) * t12 * t2;
  const T g_ap = (T(1) / T(8)) * t2 * t10 * in.w[1] + (T(1) / T(8)) * t3 * in.w[0] * t9 + (T(1) / T(8)) * in.w[2] * t11 * t2 - (T(1) / T(8)) * in.w[3] * t2 * t13;
  const T g_ab = (T(1) / T(8)) * t11 * t2 * in.w[1] + (T(1) / T(8)) * in.w[0] * t2 * t10 - (T(1) / T(8)) * in.w[2] * t2 * t13 - (T(1) / T(8)) * in.w[3] * t2 * (T(2) * ab_ap * t2 * t13 + t11 * t2 * ap_ap - T(4) * t2 * (T(2) * ab_ap * t12 * t2 + T(2) * J2 - t3 * t7 * ap_ap));
  const T g_factor = -T(4) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−4) dt
/// Operations: 57 +, 126 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
T segment_inverse_i4_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T log_ratio = log(t2 * bp_bp);
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = ab_ab * J2 + t2 * ab_ap + t5 * a_minus_b;
  const T t8 = T(2) * t6 * a_minus_b + T(3) * t4 * ab_ab * t7 + T(2) * t3 * ab_ap;
  const T t9 = T(2) * t3 + ab_ap * t4 * t8 - T(2) * t6;
  const T t10 = T(1) / ab_ab;
  const T t11 = T(2) * t9 * ab_ap * t10 + T(4) * t4 * t7 - ap_ap * t4 * t8;
  const T t12 = t5 - ab_ap * t4 * t7 - t2;
  const T t13 = ap_ap * t9 * t10 + T(4) * t10 * t12 - T(2) * ab_ap * t10 * t11;
  const T g_ap = (T(1) / T(8)) * t9 * t10 * in.w[1] + (T(1) / T(8)) * in.w[2] * t10 * t11 + (T(1) / T(8)) * t4 * in.w[0] * t8 - (T(1) / T(8)) * t13 * in.w[3] * t10;
  const T t14 = ap_ap * t4 * t7 + T(2) * ab_ap * t10 * t12 - T(2) * J2;
  const T g_ab = (T(1) / T(8)) * t10 * in.w[1] * t11 + (T(1) / T(8)) * t9 * in.w[0] * t10 - (T(1) / T(8)) * t13 * in.w[2] * t10 - (T(1) / T(8)) * in.w[3] * (T(4) * t10 * t14 + ap_ap * t10 * t11 + T(2) * t13 * ab_ap * t10) * t10;
  const T g_factor = -T(4) * length;
  f = -(T(1) / T(2)) * length * (in.w[3] * (T(2) * ab_ap * t10 * t14 - t10 * (T(2) * ab_ap * J2 + log_ratio) - ap_ap * t10 * t12) * t10 + in.w[2] * t10 * t14 + t10 * t12 * in.w[1] - t4 * in.w[0] * t7);
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 27 +, 35 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = T(1) / r1;
  f = (T(1) / T(3)) * length * (T(2) * t0 * ab_ab * (t1 * ab_ap + a_minus_b * t2) + t1 * ab_ap / ap_ap + a_minus_b * t2 / bp_bp) * t0 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 34 +, 67 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r1;
  const T t4 = T(1) / cross_cross;
  const T t5 = t3 * t3;
  const T t6 = t5 * t5;
  const T t7 = T(3) * t2 * ab_ap * t0 + T(4) * (T(2) * (t3 * a_minus_b + ab_ap * t0) * t4 * ab_ab + t5 * t3 * a_minus_b + t1 * ab_ap * t0) * t4 * ab_ab + T(3) * t6 * t3 * a_minus_b;
  const T g_ap = (T(1) / T(15)) * t7 * t4 * in.w[0];
  const T g_ab = (T(1) / T(15)) * (T(3) * t2 * t0 + ab_ap * t7 * t4 - T(3) * t6 * t3) * in.w[0] / ab_ab;
  const T g_factor = -T(5) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−5) dt
/// Operations: 34 +, 71 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t4 * ab_ap + t1 * a_minus_b * t2 + T(2) * t0 * ab_ab * (t1 * a_minus_b + t4 * ab_ap);
  const T t7 = t5 * t5;
  const T t8 = T(3) * t1 * a_minus_b * t3 + T(4) * t0 * ab_ab * t6 + T(3) * t7 * t4 * ab_ap;
  const T g_ap = (T(1) / T(15)) * t0 * t8 * in.w[0];
  const T g_ab = (T(1) / T(15)) * in.w[0] * (T(3) * t7 * t4 + t0 * t8 * ab_ap - T(3) * t1 * t3) / ab_ab;
  const T g_factor = -T(5) * length;
  f = (T(1) / T(3)) * t0 * in.w[0] * t6 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 30 +, 44 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = T(1) / r0;
  const T t2 = T(1) / cross_cross;
  const T t3 = t1 * t1;
  const T t4 = t0 * t0;
  const T t5 = T(2) * (t0 * a_minus_b + t1 * ab_ap) * ab_ab * t2 + t3 * t1 * ab_ap + t0 * a_minus_b * t4;
  f = (T(1) / T(3)) * length * (in.w[1] * (t5 * ab_ap * t2 + t3 * t1 - t0 * t4) / ab_ab + t5 * in.w[0] * t2);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 38 +, 81 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = T(1) / r1;
  const T t3 = T(1) / cross_cross;
  const T t4 = t2 * t2;
  const T t5 = t1 * ab_ap * t0 + T(2) * (ab_ap * t0 + t2 * a_minus_b) * t3 * ab_ab + t4 * t2 * a_minus_b;
  const T t6 = t4 * t4;
  const T t7 = t1 * t1;
  const T t8 = T(4) * t5 * t3 * ab_ab + T(3) * t6 * t2 * a_minus_b + T(3) * t7 * ab_ap * t0;
  const T t9 = T(3) * t6 * t2 - T(3) * t7 * t0 - t8 * ab_ap * t3;
  const T t10 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(15)) * t8 * in.w[0] * t3 - (T(1) / T(15)) * t9 * t10 * in.w[1];
  const T g_ab = -(T(1) / T(15)) * t10 * in.w[1] * (T(2) * t9 * ab_ap * t10 + t8 * ap_ap * t3 - T(5) * t5 * t3) - (T(1) / T(15)) * t9 * in.w[0] * t10;
  const T g_factor = -T(5) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−5) dt
/// Operations: 41 +, 91 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r1;
  const T t4 = t3 * t3;
  const T t5 = t2 * t1 * ab_ap + t4 * t3 * a_minus_b + T(2) * t0 * (t1 * ab_ap + t3 * a_minus_b) * ab_ab;
  const T t6 = t2 * t2;
  const T t7 = t4 * t4;
  const T t8 = T(4) * t0 * ab_ab * t5 + T(3) * t6 * t1 * ab_ap + T(3) * t7 * t3 * a_minus_b;
  const T t9 = T(3) * t6 * t1 + t8 * ab_ap * t0 - T(3) * t7 * t3;
  const T t10 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(15)) * t8 * in.w[0] * t0 + (T(1) / T(15)) * t9 * in.w[1] * t10;
  const T g_ab = (T(1) / T(15)) * (T(2) * t9 * ab_ap * t10 + T(5) * t0 * t5 - ap_ap * t8 * t0) * in.w[1] * t10 + (T(1) / T(15)) * t9 * in.w[0] * t10;
  const T g_factor = -T(5) * length;
  f = (T(1) / T(3)) * length * (in.w[0] * t0 * t5 + (ab_ap * t0 * t5 + t2 * t1 - t4 * t3) * in.w[1] * t10);
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 33 +, 54 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = T(1) / r1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = t2 * a_minus_b + ab_ap * t0;
  const T t6 = t1 * ab_ap * t0 + t3 * t2 * a_minus_b + T(2) * t4 * t5 * ab_ab;
  const T t7 = T(1) / ab_ab;
  const T t8 = ab_ap * t6 * t4 + t1 * t0 - t3 * t2;
  f = -(T(1) / T(3)) * length * ((ap_ap * t6 * t4 - T(3) * t4 * t5 - T(2) * ab_ap * t7 * t8) * in.w[2] * t7 - in.w[0] * t6 * t4 - in.w[1] * t7 * t8);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 44 +, 98 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t5 * t4 * ab_ap + t2 * t1 * a_minus_b + T(2) * ab_ab * t0 * (t1 * a_minus_b + t4 * ab_ap);
  const T t8 = T(3) * t3 * t1 * a_minus_b + T(3) * t6 * t4 * ab_ap + T(4) * ab_ab * t0 * t7;
  const T t9 = T(1) / ab_ab;
  const T t10 = T(3) * t6 * t4 + ab_ap * t0 * t8 - T(3) * t3 * t1;
  const T t11 = T(5) * t0 * t7 + T(2) * t9 * ab_ap * t10 - ap_ap * t0 * t8;
  const T g_ap = (T(1) / T(15)) * in.w[0] * t0 * t8 + (T(1) / T(15)) * t9 * t11 * in.w[2] + (T(1) / T(15)) * t9 * in.w[1] * t10;
  const T g_ab = (T(1) / T(15)) * t9 * in.w[0] * t10 + (T(1) / T(15)) * t9 * t11 * in.w[1] - (T(1) / T(15)) * t9 * (t9 * ap_ap * t10 + T(5) * t9 * (t2 * t1 - t5 * t4 - ab_ap * t0 * t7) - T(2) * t9 * t11 * ab_ap) * in.w[2];
  const T g_factor = -T(5) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−5) dt
/// Operations: 48 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r1;
  const T t2 = T(1) / r0;
  const T t3 = a_minus_b * t1 + t2 * ab_ap;
  const T t4 = T(1) / cross_cross;
  const T t5 = t1 * t1;
  const T t6 = t2 * t2;
  const T t7 = T(2) * ab_ab * t3 * t4 + a_minus_b * t5 * t1 + t6 * t2 * ab_ap;
  const T t8 = t6 * t6;
  const T t9 = t5 * t5;
  const T t10 = T(4) * ab_ab * t7 * t4 + T(3) * t8 * t2 * ab_ap + T(3) * a_minus_b * t9 * t1;
  const T t11 = T(3) * t8 * t2 + ab_ap * t4 * t10 - T(3) * t9 * t1;
  const T t12 = T(5) * t7 * t4 + T(2) * t0 * t11 * ab_ap - ap_ap * t4 * t10;
  const T g_ap = (T(1) / T(15)) * t0 * in.w[2] * t12 + (T(1) / T(15)) * t0 * t11 * in.w[1] + (T(1) / T(15)) * in.w[0] * t4 * t10;
  const T t13 = t5 * t1 - t6 * t2 - t7 * ab_ap * t4;
  const T g_ab = (T(1) / T(15)) * t0 * t12 * in.w[1] + (T(1) / T(15)) * t0 * in.w[0] * t11 - (T(1) / T(15)) * t0 * in.w[2] * (t0 * ap_ap * t11 + T(5) * t0 * t13 - T(2) * t0 * t12 * ab_ap);
  const T g_factor = -T(5) * length;
  f = -(T(1) / T(3)) * length * (t0 * t13 * in.w[1] - t0 * in.w[2] * (T(3) * t3 * t4 - t7 * ap_ap * t4 - T(2) * t0 * t13 * ab_ap) - t7 * in.w[0] * t4);
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 38 +, 65 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / r0;
  const T t5 = t1 * a_minus_b + ab_ap * t4;
  const T t6 = t4 * t4;
  const T t7 = T(2) * t3 * ab_ab * t5 + t1 * a_minus_b * t2 + ab_ap * t4 * t6;
  const T t8 = t1 * t2 - ab_ap * t3 * t7 - t4 * t6;
  const T t9 = T(2) * ab_ap * t0 * t8 + t3 * t7 * ap_ap - T(3) * t3 * t5;
  f = -(T(1) / T(3)) * (t0 * t8 * in.w[1] + (T(3) * (t1 - ab_ap * t3 * t5 - t4) * t0 + T(2) * ab_ap * t0 * t9 - t0 * ap_ap * t8) * t0 * in.w[3] + in.w[2] * t0 * t9 - t3 * t7 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 50 +, 118 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i5_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r1;
  const T t4 = t3 * t3;
  const T t5 = t3 * a_minus_b + t0 * ab_ap;
  const T t6 = T(1) / cross_cross;
  const T t7 = t1 * t0 * ab_ap + t4 * t3 * a_minus_b + T(2) * t5 * t6 * ab_ab;
  const T t8 = t4 * t4;
  const T t9 = T(4) * t7 * t6 * ab_ab + T(3) * t2 * t0 * ab_ap + T(3) * t8 * t3 * a_minus_b;
  const T t10 = T(3) * t2 * t0 + t9 * ab_ap * t6 - T(3) * t8 * t3;
  const T t11 = T(1) / ab_ab;
  const T t12 = t9 * ap_ap * t6 - T(5) * t7 * t6 - T(2) * t10 * ab_ap * t11;
  const T t13 = t4 * t3 - t1 * t0 - t7 * ab_ap * t6;
  const T t14 = T(2) * t12 * ab_ap * t11 + t10 * ap_ap * t11 + T(5) * t13 * t11;
  const T g_ap = (T(1) / T(15)) * t10 * in.w[1] * t11 + (T(1) / T(15)) * t9 * t6 * in.w[0] - (T(1) / T(15)) * t12 * in.w[2] * t11 - (T(1) / T(15)) * in.w[3] * t14 * t11;
  const T g_ab = (T(1) / T(15)) * t10 * in.w[0] * t11 - (T(1) / T(15)) * t12 * in.w[1] * t11 - (T(1) / T(15)) * in.w[2] * t14 * t11 - (T(1) / T(15)) * (T(2) * ab_ap * t14 * t11 - t12 * ap_ap * t11 - T(5) * (T(3) * t5 * t6 - T(2) * t13 * ab_ap * t11 - ap_ap * t7 * t6) * t11) * in.w[3] * t11;
  const T g_factor = -T(5) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−5) dt
/// Operations: 57 +, 137 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i5_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r1;
  const T t5 = t4 * a_minus_b + ab_ap * t1;
  const T t6 = t4 * t4;
  const T t7 = T(2) * t0 * ab_ab * t5 + t4 * a_minus_b * t6 + ab_ap * t2 * t1;
  const T t8 = t6 * t6;
  const T t9 = T(3) * ab_ap * t3 * t1 + T(4) * t0 * ab_ab * t7 + T(3) * t4 * a_minus_b * t8;
  const T t10 = T(1) / ab_ab;
  const T t11 = t2 * t1 + ab_ap * t0 * t7 - t4 * t6;
  const T t12 = T(3) * t4 * t8 - T(3) * t3 * t1 - ab_ap * t0 * t9;
  const T t13 = t0 * t9 * ap_ap + T(2) * ab_ap * t12 * t10 - T(5) * t0 * t7;
  const T t14 = T(5) * t10 * t11 + t12 * t10 * ap_ap - T(2) * ab_ap * t10 * t13;
  const T g_ap = (T(1) / T(15)) * t0 * in.w[0] * t9 + (T(1) / T(15)) * t10 * in.w[3] * t14 - (T(1) / T(15)) * t12 * t10 * in.w[1] - (T(1) / T(15)) * t10 * t13 * in.w[2];
  const T t15 = t0 * t7 * ap_ap - T(2) * ab_ap * t10 * t11 - T(3) * t0 * t5;
  const T g_ab = (T(1) / T(15)) * t10 * t14 * in.w[2] - (T(1) / T(15)) * t10 * in.w[3] * (T(5) * t10 * t15 - t10 * ap_ap * t13 - T(2) * ab_ap * t10 * t14) - (T(1) / T(15)) * t12 * t10 * in.w[0] - (T(1) / T(15)) * t10 * in.w[1] * t13;
  const T g_factor = -T(5) * length;
  f = (T(1) / T(3)) * ((T(3) * (ab_ap * t0 * t5 + t1 - t4) * t10 - t10 * t11 * ap_ap - T(2) * ab_ap * t10 * t15) * t10 * in.w[3] + t10 * t11 * in.w[1] + t0 * in.w[0] * t7 - t10 * t15 * in.w[2]) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 30 +, 44 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = T(1) / ap_ap;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  f = (T(1) / T(8)) * length * (T(3) * t2 * (t3 * a_minus_b + t4 * ab_ap + J2 * ab_ab) * ab_ab + T(2) * t5 * ab_ap + T(2) * t6 * a_minus_b) * t2 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 37 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(8) * t5 * ab_ap + T(5) * ab_ab * t2 * (T(2) * t4 * ab_ap + T(3) * ab_ab * (a_minus_b * t6 + t3 * ab_ap + ab_ab * J2) * t2 + T(2) * a_minus_b * t7) + T(8) * a_minus_b * t8;
  const T g_ap = (T(1) / T(48)) * t2 * in.w[0] * t9;
  const T g_ab = (T(1) / T(48)) * (ab_ap * t2 * t9 + T(8) * t5 - T(8) * t8) * in.w[0] / ab_ab;
  const T g_factor = -T(6) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−6) dt
/// Operations: 37 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(2) * a_minus_b * t6 + T(2) * t3 * ab_ap + T(3) * ab_ab * (ab_ab * J2 + t2 * ab_ap + a_minus_b * t5) * t8;
  const T t10 = T(8) * t4 * ab_ap + T(8) * a_minus_b * t7 + T(5) * ab_ab * t9 * t8;
  const T g_ap = (T(1) / T(48)) * in.w[0] * t10 * t8;
  const T g_ab = -(T(1) / T(48)) * (T(8) * t7 - T(8) * t4 - t10 * ab_ap * t8) * in.w[0] / ab_ab;
  const T g_factor = -T(6) * length;
  f = (T(1) / T(8)) * in.w[0] * length * t9 * t8;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 33 +, 49 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = T(1) / bp_bp;
  const T t5 = T(1) / cross_cross;
  const T t6 = t4 * t4;
  const T t7 = T(2) * t3 * ab_ap + T(3) * ab_ab * (a_minus_b * t4 + ab_ab * J2 + t2 * ab_ap) * t5 + T(2) * a_minus_b * t6;
  f = (T(1) / T(8)) * length * (in.w[1] * (t7 * ab_ap * t5 + T(2) * t3 - T(2) * t6) / ab_ab + t7 * in.w[0] * t5);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 41 +, 82 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + ab0 * bp0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = T(1) / ap_ap;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = T(3) * (t3 * a_minus_b + ab_ab * J2 + ab_ap * t4) * t2 * ab_ab + T(2) * ab_ap * t5 + T(2) * t6 * a_minus_b;
  const T t8 = t5 * t4;
  const T t9 = t6 * t3;
  const T t10 = T(5) * t2 * t7 * ab_ab + T(8) * ab_ap * t8 + T(8) * t9 * a_minus_b;
  const T t11 = T(1) / ab_ab;
  const T t12 = T(8) * t9 - T(8) * t8 - ab_ap * t2 * t10;
  const T g_ap = (T(1) / T(48)) * in.w[0] * t2 * t10 - (T(1) / T(48)) * t11 * in.w[1] * t12;
  const T g_ab = (T(1) / T(48)) * t11 * in.w[1] * (T(6) * t2 * t7 - T(2) * ab_ap * t11 * t12 - t2 * t10 * ap_ap) - (T(1) / T(48)) * in.w[0] * t11 * t12;
  const T g_factor = -T(6) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−6) dt
/// Operations: 44 +, 92 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(2) * a_minus_b * t6 + T(3) * ab_ab * (t2 * ab_ap + a_minus_b * t5 + ab_ab * J2) * t8 + T(2) * t3 * ab_ap;
  const T t10 = T(8) * t4 * ab_ap + T(8) * a_minus_b * t7 + T(5) * ab_ab * t9 * t8;
  const T t11 = T(8) * t7 - T(8) * t4 - t10 * ab_ap * t8;
  const T t12 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(48)) * t10 * in.w[0] * t8 - (T(1) / T(48)) * t11 * t12 * in.w[1];
  const T g_ab = (T(1) / T(48)) * t12 * in.w[1] * (T(6) * t9 * t8 - ap_ap * t10 * t8 - T(2) * t11 * t12 * ab_ap) - (T(1) / T(48)) * t11 * t12 * in.w[0];
  const T g_factor = -T(6) * length;
  f = (T(1) / T(8)) * (t9 * in.w[0] * t8 - t12 * in.w[1] * (T(2) * t6 - T(2) * t3 - t9 * ab_ap * t8)) * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 36 +, 59 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t5 * ab_ap + J2 * ab_ab + t3 * a_minus_b;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(2) * t4 * a_minus_b + T(2) * t6 * ab_ap + T(3) * t7 * t8 * ab_ab;
  const T t10 = t9 * ab_ap * t8 + T(2) * t6 - T(2) * t4;
  f = (T(1) / T(8)) * length * (in.w[1] * t2 * t10 + t9 * in.w[0] * t8 - (ap_ap * t9 * t8 - T(2) * ab_ap * t2 * t10 - T(4) * t7 * t8) * t2 * in.w[2]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 47 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = T(3) * t2 * ab_ab * (ab_ab * J2 + t6 * ab_ap + t3 * a_minus_b) + T(2) * t4 * a_minus_b + T(2) * t7 * ab_ap;
  const T t9 = t7 * t6;
  const T t10 = T(8) * t5 * a_minus_b + T(5) * t2 * t8 * ab_ab + T(8) * t9 * ab_ap;
  const T t11 = T(1) / ab_ab;
  const T t12 = T(8) * t5 - T(8) * t9 - ab_ap * t2 * t10;
  const T t13 = T(6) * t2 * t8 - T(2) * t12 * ab_ap * t11 - ap_ap * t2 * t10;
  const T g_ap = (T(1) / T(48)) * in.w[0] * t2 * t10 + (T(1) / T(48)) * t11 * in.w[2] * t13 - (T(1) / T(48)) * t12 * in.w[1] * t11;
  const T g_ab = (T(1) / T(48)) * in.w[1] * t11 * t13 - (T(1) / T(48)) * (T(6) * (T(2) * t4 - ab_ap * t2 * t8 - T(2) * t7) * t11 - T(2) * ab_ap * t11 * t13 - ap_ap * t12 * t11) * t11 * in.w[2] - (T(1) / T(48)) * in.w[0] * t12 * t11;
  const T g_factor = -T(6) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−6) dt
/// Operations: 51 +, 114 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * a_minus_b + ab_ap * t3 + ab_ab * J2;
  const T t7 = t5 * t5;
  const T t8 = T(2) * ab_ap * t4 + T(3) * t2 * ab_ab * t6 + T(2) * t7 * a_minus_b;
  const T t9 = t4 * t3;
  const T t10 = t7 * t5;
  const T t11 = T(5) * t8 * t2 * ab_ab + T(8) * ab_ap * t9 + T(8) * t10 * a_minus_b;
  const T t12 = ab_ap * t2 * t11 + T(8) * t9 - T(8) * t10;
  const T t13 = T(1) / ab_ab;
  const T t14 = t2 * t11 * ap_ap - T(6) * t8 * t2 - T(2) * ab_ap * t12 * t13;
  const T g_ap = (T(1) / T(48)) * t2 * t11 * in.w[0] + (T(1) / T(48)) * in.w[1] * t12 * t13 - (T(1) / T(48)) * in.w[2] * t13 * t14;
  const T t15 = T(2) * t7 - t8 * ab_ap * t2 - T(2) * t4;
  const T g_ab = (T(1) / T(48)) * t12 * t13 * in.w[0] - (T(1) / T(48)) * in.w[1] * t13 * t14 - (T(1) / T(48)) * in.w[2] * t13 * (t12 * t13 * ap_ap + T(6) * t15 * t13 + T(2) * ab_ap * t13 * t14);
  const T g_factor = -T(6) * length;
  f = (T(1) / T(8)) * ((T(4) * t2 * t6 - t8 * t2 * ap_ap - T(2) * t15 * ab_ap * t13) * in.w[2] * t13 + t8 * t2 * in.w[0] - t15 * in.w[1] * t13) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 41 +, 70 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = T(1) / ap_ap;
  const T t5 = t3 * a_minus_b + ab_ap * t4 + ab_ab * J2;
  const T t6 = t4 * t4;
  const T t7 = t3 * t3;
  const T t8 = T(3) * t2 * ab_ab * t5 + T(2) * ab_ap * t6 + T(2) * t7 * a_minus_b;
  const T t9 = T(2) * t7 - ab_ap * t8 * t2 - T(2) * t6;
  const T t10 = T(1) / ab_ab;
  const T t11 = T(4) * t2 * t5 - T(2) * ab_ap * t9 * t10 - t8 * t2 * ap_ap;
  f = (T(1) / T(8)) * (t8 * t2 * in.w[0] + in.w[2] * t11 * t10 + (t9 * t10 * ap_ap + T(2) * ab_ap * t11 * t10 + T(4) * (t4 + ab_ap * t2 * t5 - t3) * t10) * t10 * in.w[3] - t9 * t10 * in.w[1]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 53 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i6_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / cross_cross;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = ab_ab * J2 + a_minus_b * t3 + t7 * ab_ap;
  const T t11 = T(2) * t8 * ab_ap + T(3) * t6 * ab_ab * t10 + T(2) * a_minus_b * t4;
  const T t12 = T(8) * t9 * ab_ap + T(8) * a_minus_b * t5 + T(5) * t6 * ab_ab * t11;
  const T t13 = T(8) * t5 - t6 * t12 * ab_ap - T(8) * t9;
  const T t14 = t6 * t11 * ab_ap + T(2) * t8 - T(2) * t4;
  const T t15 = t6 * ap_ap * t12 + T(2) * t2 * t13 * ab_ap - T(6) * t6 * t11;
  const T t16 = t2 * t13 * ap_ap + T(6) * t14 * t2 - T(2) * t2 * t15 * ab_ap;
  const T g_ap = (T(1) / T(48)) * t2 * in.w[3] * t16 + (T(1) / T(48)) * t6 * in.w[0] * t12 - (T(1) / T(48)) * t2 * t13 * in.w[1] - (T(1) / T(48)) * t2 * t15 * in.w[2];
  const T g_ab = (T(1) / T(48)) * (T(6) * (T(4) * t6 * t10 + T(2) * t14 * t2 * ab_ap - t6 * ap_ap * t11) * t2 + T(2) * t2 * ab_ap * t16 + t2 * t15 * ap_ap) * t2 * in.w[3] + (T(1) / T(48)) * t2 * t16 * in.w[2] - (T(1) / T(48)) * t2 * t15 * in.w[1] - (T(1) / T(48)) * t2 * in.w[0] * t13;
  const T g_factor = -T(6) * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−6) dt
/// Operations: 60 +, 138 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i6_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = a_minus_b * t5 + ab_ab * J2 + t3 * ab_ap;
  const T t8 = T(2) * t4 * ab_ap + T(2) * a_minus_b * t6 + T(3) * t2 * ab_ab * t7;
  const T t9 = t4 * t3;
  const T t10 = t6 * t5;
  const T t11 = T(8) * t9 * ab_ap + T(5) * t2 * ab_ab * t8 + T(8) * a_minus_b * t10;
  const T t12 = T(8) * t10 - t2 * t11 * ab_ap - T(8) * t9;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(6) * t2 * t8 - t2 * t11 * ap_ap - T(2) * t12 * t13 * ab_ap;
  const T t15 = T(2) * t6 - T(2) * t4 - t2 * t8 * ab_ap;
  const T t16 = T(6) * t15 * t13 - t12 * t13 * ap_ap - T(2) * t14 * t13 * ab_ap;
  const T g_ap = (T(1) / T(48)) * t14 * t13 * in.w[2] + (T(1) / T(48)) * t2 * t11 * in.w[0] - (T(1) / T(48)) * t12 * t13 * in.w[1] - (T(1) / T(48)) * t16 * t13 * in.w[3];
  const T t17 = T(4) * t2 * t7 - t2 * ap_ap * t8 - T(2) * t15 * t13 * ab_ap;
  const T g_ab = (T(1) / T(48)) * t13 * in.w[3] * (T(6) * t13 * t17 - T(2) * t16 * t13 * ab_ap - t14 * t13 * ap_ap) + (T(1) / T(48)) * t14 * t13 * in.w[1] - (T(1) / T(48)) * t12 * t13 * in.w[0] - (T(1) / T(48)) * t16 * t13 * in.w[2];
  const T g_factor = -T(6) * length;
  f = -(T(1) / T(8)) * length * (t15 * t13 * in.w[1] - t2 * in.w[0] * t8 - (t15 * t13 * ap_ap + T(2) * t13 * t17 * ab_ap + T(4) * t13 * (t3 + t2 * t7 * ab_ap - t5)) * t13 * in.w[3] - t13 * t17 * in.w[2]);
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 29 +, 50 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = T(1) / r0;
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = t3 * t3;
  const T t6 = t1 * t1;
  f = (T(1) / T(15)) * (T(4) * (t0 * a_minus_b * t1 + t2 * ab_ap * t3 + T(2) * (t0 * a_minus_b + t2 * ab_ap) * t4 * ab_ab) * t4 * ab_ab + T(3) * t2 * ab_ap * t5 + T(3) * t0 * a_minus_b * t6) * t4 * in.w[0] * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 36 +, 78 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = t3 * t2;
  const T t9 = T(2) * (T(3) * t3 * t1 * a_minus_b + T(3) * t6 * ab_ap * t4 + T(4) * (t5 * ab_ap * t4 + T(2) * (ab_ap * t4 + t1 * a_minus_b) * t0 * ab_ab + t2 * t1 * a_minus_b) * t0 * ab_ab) * t0 * ab_ab + T(5) * t7 * ab_ap * t4 + T(5) * t8 * t1 * a_minus_b;
  const T g_ap = (T(1) / T(35)) * t0 * t9 * in.w[0];
  const T g_ab = -(T(1) / T(35)) * (T(5) * t8 * t1 - ab_ap * t0 * t9 - T(5) * t7 * t4) * in.w[0] / ab_ab;
  const T g_factor = -T(7) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−7) dt
/// Operations: 36 +, 82 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(3) * t1 * t3 * ab_ap + T(3) * t4 * a_minus_b * t6 + T(4) * t0 * ab_ab * (t4 * a_minus_b * t5 + T(2) * t0 * ab_ab * (t4 * a_minus_b + t1 * ab_ap) + t1 * t2 * ab_ap);
  const T t8 = t3 * t2;
  const T t9 = t6 * t5;
  const T t10 = T(2) * t0 * t7 * ab_ab + T(5) * t1 * t8 * ab_ap + T(5) * t4 * a_minus_b * t9;
  const T g_ap = (T(1) / T(35)) * t0 * t10 * in.w[0];
  const T g_ab = -(T(1) / T(35)) * in.w[0] * (T(5) * t4 * t9 - t0 * t10 * ab_ap - T(5) * t1 * t8) / ab_ab;
  const T g_factor = -T(7) * length;
  f = (T(1) / T(15)) * t0 * t7 * in.w[0] * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 32 +, 57 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(3) * a_minus_b * t0 * t2 + T(3) * t6 * ab_ap * t4 + T(4) * t3 * ab_ab * (T(2) * t3 * ab_ab * (ab_ap * t4 + a_minus_b * t0) + t5 * ab_ap * t4 + a_minus_b * t0 * t1);
  f = -(T(1) / T(15)) * length * (in.w[1] * (T(3) * t0 * t2 - t3 * t7 * ab_ap - T(3) * t6 * t4) / ab_ab - t3 * t7 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 40 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r1;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t2 * t2;
  const T t7 = T(4) * (t2 * ab_ap * t1 + a_minus_b * t4 * t3 + T(2) * (a_minus_b * t3 + ab_ap * t1) * t0 * ab_ab) * t0 * ab_ab + T(3) * a_minus_b * t5 * t3 + T(3) * t6 * ab_ap * t1;
  const T t8 = t6 * t2;
  const T t9 = t5 * t4;
  const T t10 = T(2) * t7 * t0 * ab_ab + T(5) * t8 * ab_ap * t1 + T(5) * a_minus_b * t9 * t3;
  const T t11 = T(5) * t9 * t3 - T(5) * t8 * t1 - ab_ap * t0 * t10;
  const T t12 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(35)) * in.w[0] * t0 * t10 - (T(1) / T(35)) * in.w[1] * t11 * t12;
  const T g_ab = -(T(1) / T(35)) * t11 * in.w[0] * t12 - (T(1) / T(105)) * in.w[1] * (T(6) * t11 * ab_ap * t12 + T(3) * ap_ap * t0 * t10 - T(7) * t7 * t0) * t12;
  const T g_factor = -T(7) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−7) dt
/// Operations: 43 +, 105 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(4) * t0 * ab_ab * (ab_ap * t5 * t6 + a_minus_b * t1 * t2 + T(2) * t0 * ab_ab * (a_minus_b * t1 + ab_ap * t5)) + T(3) * a_minus_b * t1 * t3 + T(3) * ab_ap * t5 * t7;
  const T t10 = T(5) * a_minus_b * t1 * t4 + T(5) * ab_ap * t5 * t8 + T(2) * t0 * ab_ab * t9;
  const T t11 = T(1) / ab_ab;
  const T t12 = T(5) * t1 * t4 - T(5) * t5 * t8 - ab_ap * t0 * t10;
  const T g_ap = (T(1) / T(35)) * in.w[0] * t0 * t10 - (T(1) / T(35)) * t11 * in.w[1] * t12;
  const T g_ab = -(T(1) / T(35)) * in.w[0] * t11 * t12 - (T(1) / T(105)) * t11 * in.w[1] * (T(3) * t0 * t10 * ap_ap + T(6) * ab_ap * t11 * t12 - T(7) * t0 * t9);
  const T g_factor = -T(7) * length;
  f = (T(1) / T(15)) * (in.w[0] * t0 * t9 - t11 * in.w[1] * (T(3) * t1 * t3 - ab_ap * t0 * t9 - T(3) * t5 * t7)) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 35 +, 67 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r0;
  const T t4 = t3 * t3;
  const T t5 = t1 * a_minus_b * t2 + T(2) * t0 * ab_ab * (t1 * a_minus_b + ab_ap * t3) + ab_ap * t4 * t3;
  const T t6 = t4 * t4;
  const T t7 = t2 * t2;
  const T t8 = T(4) * t0 * ab_ab * t5 + T(3) * ab_ap * t6 * t3 + T(3) * t1 * a_minus_b * t7;
  const T t9 = ab_ap * t0 * t8 + T(3) * t6 * t3 - T(3) * t1 * t7;
  const T t10 = T(1) / ab_ab;
  f = (T(1) / T(15)) * length * (t0 * in.w[0] * t8 + in.w[1] * t9 * t10 - (t0 * ap_ap * t8 - T(2) * ab_ap * t9 * t10 - T(5) * t0 * t5) * t10 * in.w[2]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 46 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(1) / cross_cross;
  const T t10 = T(4) * (T(2) * t9 * ab_ab * (ab_ap * t1 + t5 * a_minus_b) + ab_ap * t1 * t2 + t6 * t5 * a_minus_b) * t9 * ab_ab + T(3) * t7 * t5 * a_minus_b + T(3) * ab_ap * t1 * t3;
  const T t11 = T(5) * t8 * t5 * a_minus_b + T(5) * ab_ap * t1 * t4 + T(2) * t9 * ab_ab * t10;
  const T t12 = T(5) * t1 * t4 + t11 * ab_ap * t9 - T(5) * t8 * t5;
  const T t13 = T(6) * ab_ap * t12 * t0 + T(7) * t9 * t10 - T(3) * t11 * t9 * ap_ap;
  const T g_ap = (T(1) / T(105)) * t0 * in.w[2] * t13 + (T(1) / T(35)) * t12 * in.w[1] * t0 + (T(1) / T(35)) * in.w[0] * t11 * t9;
  const T g_ab = (T(1) / T(105)) * in.w[1] * t0 * t13 + (T(1) / T(105)) * (T(2) * ab_ap * t0 * t13 + T(7) * t0 * (ab_ap * t9 * t10 + T(3) * t1 * t3 - T(3) * t7 * t5) - T(3) * t12 * t0 * ap_ap) * t0 * in.w[2] + (T(1) / T(35)) * in.w[0] * t12 * t0;
  const T g_factor = -T(7) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−7) dt
/// Operations: 50 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = t1 * t0 * a_minus_b + ab_ap * t4 * t5 + T(2) * t8 * ab_ab * (ab_ap * t4 + t0 * a_minus_b);
  const T t10 = T(3) * ab_ap * t4 * t6 + T(3) * t2 * t0 * a_minus_b + T(4) * t8 * ab_ab * t9;
  const T t11 = T(5) * t3 * t0 * a_minus_b + T(5) * ab_ap * t4 * t7 + T(2) * t8 * ab_ab * t10;
  const T t12 = T(1) / ab_ab;
  const T t13 = T(5) * t3 * t0 - T(5) * t4 * t7 - t11 * ab_ap * t8;
  const T t14 = T(6) * t13 * ab_ap * t12 + T(3) * t11 * t8 * ap_ap - T(7) * t8 * t10;
  const T g_ap = (T(1) / T(35)) * in.w[0] * t11 * t8 - (T(1) / T(105)) * t12 * in.w[2] * t14 - (T(1) / T(35)) * t13 * in.w[1] * t12;
  const T t15 = ab_ap * t8 * t10 + T(3) * t4 * t6 - T(3) * t2 * t0;
  const T g_ab = (T(1) / T(105)) * (T(3) * t13 * t12 * ap_ap + T(7) * t12 * t15 - T(2) * ab_ap * t12 * t14) * t12 * in.w[2] - (T(1) / T(35)) * in.w[0] * t13 * t12 - (T(1) / T(105)) * in.w[1] * t12 * t14;
  const T g_factor = -T(7) * length;
  f = -(T(1) / T(15)) * length * (t12 * in.w[2] * (t8 * t10 * ap_ap - T(5) * t8 * t9 - T(2) * ab_ap * t12 * t15) - in.w[0] * t8 * t10 - in.w[1] * t12 * t15);
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 40 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(2) * ab_ab * (a_minus_b * t1 + t4 * ab_ap) * t7 + t5 * t4 * ab_ap + a_minus_b * t2 * t1;
  const T t9 = T(3) * a_minus_b * t3 * t1 + T(3) * t6 * t4 * ab_ap + T(4) * ab_ab * t8 * t7;
  const T t10 = T(3) * t3 * t1 - t9 * ab_ap * t7 - T(3) * t6 * t4;
  const T t11 = T(5) * t8 * t7 - ap_ap * t9 * t7 - T(2) * t0 * t10 * ab_ap;
  f = -(T(1) / T(15)) * length * (t0 * t10 * in.w[1] - t11 * t0 * in.w[2] - in.w[0] * t9 * t7 - t0 * in.w[3] * (T(2) * t11 * t0 * ab_ap + t0 * t10 * ap_ap + T(5) * (t5 * t4 + t8 * ab_ap * t7 - t2 * t1) * t0));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 52 +, 133 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i7_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = ab_ap * t1 * t2 + t6 * t5 * a_minus_b + T(2) * t4 * (ab_ap * t1 + t5 * a_minus_b) * ab_ab;
  const T t8 = t6 * t6;
  const T t9 = T(4) * t4 * ab_ab * t7 + T(3) * t8 * t5 * a_minus_b + T(3) * ab_ap * t1 * t3;
  const T t10 = T(3) * t1 * t3 + ab_ap * t4 * t9 - T(3) * t8 * t5;
  const T t11 = t3 * t2;
  const T t12 = t8 * t6;
  const T t13 = T(2) * t4 * ab_ab * t9 + T(5) * ab_ap * t1 * t11 + T(5) * t12 * t5 * a_minus_b;
  const T t14 = T(5) * t1 * t11 + ab_ap * t4 * t13 - T(5) * t12 * t5;
  const T t15 = T(3) * t4 * t13 * ap_ap - T(6) * ab_ap * t14 * t0 - T(7) * t4 * t9;
  const T t16 = T(7) * t0 * t10 - T(3) * t14 * t0 * ap_ap - T(2) * ab_ap * t0 * t15;
  const T g_ap = (T(1) / T(105)) * in.w[3] * t0 * t16 + (T(1) / T(35)) * t4 * in.w[0] * t13 + (T(1) / T(35)) * t14 * t0 * in.w[1] - (T(1) / T(105)) * in.w[2] * t0 * t15;
  const T g_ab = (T(1) / T(35)) * t14 * in.w[0] * t0 + (T(1) / T(105)) * in.w[3] * t0 * (t0 * t15 * ap_ap + T(2) * ab_ap * t0 * t16 - T(7) * (t4 * t9 * ap_ap - T(5) * t4 * t7 - T(2) * ab_ap * t0 * t10) * t0) + (T(1) / T(105)) * in.w[2] * t0 * t16 - (T(1) / T(105)) * t0 * t15 * in.w[1];
  const T g_factor = -T(7) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−7) dt
/// Operations: 59 +, 154 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i7_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(1) / cross_cross;
  const T t8 = t1 * t0 * ab_ap + t5 * a_minus_b * t4 + T(2) * t7 * (t0 * ab_ap + a_minus_b * t4) * ab_ab;
  const T t9 = T(3) * t6 * a_minus_b * t4 + T(3) * t2 * t0 * ab_ap + T(4) * t8 * t7 * ab_ab;
  const T t10 = t6 * t5;
  const T t11 = T(2) * t9 * t7 * ab_ab + T(5) * t3 * t0 * ab_ap + T(5) * t10 * a_minus_b * t4;
  const T t12 = T(5) * t3 * t0 + ab_ap * t11 * t7 - T(5) * t10 * t4;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(6) * t12 * ab_ap * t13 + T(7) * t9 * t7 - T(3) * ap_ap * t11 * t7;
  const T t15 = T(3) * t2 * t0 + t9 * ab_ap * t7 - T(3) * t6 * t4;
  const T t16 = T(2) * ab_ap * t14 * t13 + T(7) * t15 * t13 - T(3) * ap_ap * t12 * t13;
  const T g_ap = (T(1) / T(35)) * in.w[1] * t12 * t13 + (T(1) / T(105)) * t16 * t13 * in.w[3] + (T(1) / T(105)) * t14 * in.w[2] * t13 + (T(1) / T(35)) * in.w[0] * t11 * t7;
  const T t17 = T(5) * t8 * t7 + T(2) * t15 * ab_ap * t13 - t9 * ap_ap * t7;
  const T g_ab = (T(1) / T(105)) * in.w[1] * t14 * t13 + (T(1) / T(105)) * t16 * in.w[2] * t13 + (T(1) / T(35)) * in.w[0] * t12 * t13 - (T(1) / T(105)) * (ap_ap * t14 * t13 - T(2) * t16 * ab_ap * t13 - T(7) * t17 * t13) * t13 * in.w[3];
  const T g_factor = -T(7) * length;
  f = (T(1) / T(15)) * (t9 * in.w[0] * t7 + (T(2) * ab_ap * t17 * t13 - T(5) * (t5 * t4 - t8 * ab_ap * t7 - t1 * t0) * t13 - t15 * ap_ap * t13) * t13 * in.w[3] + t15 * in.w[1] * t13 + in.w[2] * t17 * t13) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 32 +, 53 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  f = (T(1) / T(48)) * (T(8) * t4 * a_minus_b + T(8) * t7 * ab_ap + T(5) * (T(3) * (t5 * ab_ap + t2 * a_minus_b + J2 * ab_ab) * t8 * ab_ab + T(2) * t6 * ab_ap + T(2) * t3 * a_minus_b) * t8 * ab_ab) * length * t8 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 39 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = t3 * t2;
  const T t9 = T(1) / cross_cross;
  const T t10 = t6 * t6;
  const T t11 = T(48) * a_minus_b * t4 + T(7) * ab_ab * (T(8) * t7 * ab_ap + T(8) * a_minus_b * t8 + T(5) * ab_ab * (T(2) * a_minus_b * t3 + T(2) * t6 * ab_ap + T(3) * ab_ab * (ab_ab * J2 + t5 * ab_ap + a_minus_b * t2) * t9) * t9) * t9 + T(48) * t10 * ab_ap;
  const T g_ap = (T(1) / T(384)) * in.w[0] * t11 * t9;
  const T g_ab = -(T(1) / T(384)) * (T(48) * t4 - T(48) * t10 - t11 * ab_ap * t9) * in.w[0] / ab_ab;
  const T g_factor = -T(8) * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−8) dt
/// Operations: 39 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = T(1) / bp_bp;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = t5 * t4;
  const T t8 = t6 * t3;
  const T t9 = T(5) * t2 * ab_ab * (T(3) * t2 * ab_ab * (ab_ab * J2 + t3 * ab_ap + a_minus_b * t4) + T(2) * a_minus_b * t5 + T(2) * t6 * ab_ap) + T(8) * a_minus_b * t7 + T(8) * t8 * ab_ap;
  const T t10 = t6 * t6;
  const T t11 = t5 * t5;
  const T t12 = T(7) * t2 * ab_ab * t9 + T(48) * t10 * ab_ap + T(48) * a_minus_b * t11;
  const T g_ap = (T(1) / T(384)) * t2 * t12 * in.w[0];
  const T g_ab = (T(1) / T(384)) * in.w[0] * (T(48) * t10 + t2 * t12 * ab_ap - T(48) * t11) / ab_ab;
  const T g_factor = -T(8) * length;
  f = (T(1) / T(48)) * t2 * in.w[0] * t9 * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 35 +, 58 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = T(1) / cross_cross;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = t3 * t2;
  const T t8 = t6 * t5;
  const T t9 = T(5) * (T(2) * ab_ap * t3 + T(3) * t4 * ab_ab * (ab_ab * J2 + t5 * a_minus_b + ab_ap * t2) + T(2) * t6 * a_minus_b) * t4 * ab_ab + T(8) * ab_ap * t7 + T(8) * t8 * a_minus_b;
  f = (T(1) / T(48)) * length * (t9 * in.w[0] * t4 + (ab_ap * t9 * t4 + T(8) * t7 - T(8) * t8) * in.w[1] / ab_ab);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 43 +, 91 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(8) * t5 * ab_ap + T(5) * t2 * ab_ab * (T(2) * t4 * ab_ap + T(2) * a_minus_b * t7 + T(3) * t2 * ab_ab * (ab_ab * J2 + a_minus_b * t6 + t3 * ab_ap)) + T(8) * a_minus_b * t8;
  const T t10 = t7 * t7;
  const T t11 = t4 * t4;
  const T t12 = T(7) * t2 * ab_ab * t9 + T(48) * a_minus_b * t10 + T(48) * t11 * ab_ap;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(48) * t10 - t2 * t12 * ab_ap - T(48) * t11;
  const T g_ap = (T(1) / T(384)) * t2 * t12 * in.w[0] - (T(1) / T(384)) * t13 * in.w[1] * t14;
  const T g_ab = -(T(1) / T(384)) * t13 * in.w[1] * (t2 * t12 * ap_ap + T(2) * t13 * t14 * ab_ap - T(8) * t2 * t9) - (T(1) / T(384)) * t13 * t14 * in.w[0];
  const T g_factor = -T(8) * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−8) dt
/// Operations: 46 +, 101 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t3 * t2;
  const T t10 = T(5) * t5 * ab_ab * (T(2) * ab_ap * t7 + T(3) * (t2 * a_minus_b + ab_ab * J2 + ab_ap * t6) * t5 * ab_ab + T(2) * t3 * a_minus_b) + T(8) * ab_ap * t8 + T(8) * t9 * a_minus_b;
  const T t11 = t7 * t7;
  const T t12 = T(48) * t4 * a_minus_b + T(7) * t10 * t5 * ab_ab + T(48) * ab_ap * t11;
  const T t13 = T(48) * t4 - t12 * ab_ap * t5 - T(48) * t11;
  const T t14 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(384)) * t12 * in.w[0] * t5 - (T(1) / T(384)) * t13 * in.w[1] * t14;
  const T g_ab = -(T(1) / T(384)) * (t12 * t5 * ap_ap + T(2) * t13 * ab_ap * t14 - T(8) * t10 * t5) * in.w[1] * t14 - (T(1) / T(384)) * t13 * in.w[0] * t14;
  const T g_factor = -T(8) * length;
  f = -(T(1) / T(48)) * length * (in.w[1] * (T(8) * t9 - T(8) * t8 - t10 * ab_ap * t5) * t14 - t10 * in.w[0] * t5);
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 38 +, 68 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = T(2) * ab_ap * t3 + T(3) * t5 * ab_ab * (a_minus_b * t6 + ab_ap * t2 + ab_ab * J2) + T(2) * a_minus_b * t7;
  const T t9 = t7 * t6;
  const T t10 = T(8) * ab_ap * t4 + T(5) * t5 * ab_ab * t8 + T(8) * a_minus_b * t9;
  const T t11 = T(8) * t4 + ab_ap * t5 * t10 - T(8) * t9;
  const T t12 = T(1) / ab_ab;
  f = (T(1) / T(48)) * length * (t11 * in.w[1] * t12 + t5 * t10 * in.w[0] + in.w[2] * t12 * (T(6) * t5 * t8 + T(2) * t11 * ab_ap * t12 - t5 * ap_ap * t10));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 49 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t3 * t2;
  const T t10 = t7 * t6;
  const T t11 = T(8) * t9 * ab_ap + T(5) * (T(3) * t5 * (t2 * ab_ap + t6 * a_minus_b + J2 * ab_ab) * ab_ab + T(2) * t7 * a_minus_b + T(2) * t3 * ab_ap) * t5 * ab_ab + T(8) * t10 * a_minus_b;
  const T t12 = T(48) * t8 * a_minus_b + T(48) * t4 * ab_ap + T(7) * t11 * t5 * ab_ab;
  const T t13 = T(48) * t4 + ab_ap * t5 * t12 - T(48) * t8;
  const T t14 = T(1) / ab_ab;
  const T t15 = T(2) * ab_ap * t13 * t14 + T(8) * t11 * t5 - ap_ap * t5 * t12;
  const T g_ap = (T(1) / T(384)) * t13 * in.w[1] * t14 + (T(1) / T(384)) * in.w[0] * t5 * t12 + (T(1) / T(384)) * t15 * t14 * in.w[2];
  const T g_ab = (T(1) / T(384)) * in.w[0] * t13 * t14 + (T(1) / T(384)) * t15 * in.w[1] * t14 + (T(1) / T(384)) * (T(2) * ab_ap * t15 * t14 + T(8) * (T(8) * t9 + t11 * ab_ap * t5 - T(8) * t10) * t14 - ap_ap * t13 * t14) * t14 * in.w[2];
  const T g_factor = -T(8) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−8) dt
/// Operations: 53 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t6 * t5;
  const T t9 = T(1) / cross_cross;
  const T t10 = T(2) * ab_ap * t6 + T(3) * t9 * (ab_ab * J2 + a_minus_b * t2 + ab_ap * t5) * ab_ab + T(2) * a_minus_b * t3;
  const T t11 = t3 * t2;
  const T t12 = T(8) * ab_ap * t8 + T(5) * t9 * t10 * ab_ab + T(8) * a_minus_b * t11;
  const T t13 = T(48) * a_minus_b * t4 + T(48) * ab_ap * t7 + T(7) * t12 * t9 * ab_ab;
  const T t14 = T(1) / ab_ab;
  const T t15 = t13 * ab_ap * t9 + T(48) * t7 - T(48) * t4;
  const T t16 = t13 * t9 * ap_ap - T(8) * t12 * t9 - T(2) * ab_ap * t14 * t15;
  const T g_ap = (T(1) / T(384)) * t13 * t9 * in.w[0] + (T(1) / T(384)) * in.w[1] * t14 * t15 - (T(1) / T(384)) * in.w[2] * t16 * t14;
  const T t17 = t12 * ab_ap * t9 + T(8) * t8 - T(8) * t11;
  const T g_ab = (T(1) / T(384)) * t14 * t15 * in.w[0] + (T(1) / T(384)) * in.w[2] * t14 * (T(8) * t17 * t14 - T(2) * ab_ap * t16 * t14 - t14 * t15 * ap_ap) - (T(1) / T(384)) * in.w[1] * t16 * t14;
  const T g_factor = -T(8) * length;
  f = -(T(1) / T(48)) * ((t12 * t9 * ap_ap - T(2) * t17 * ab_ap * t14 - T(6) * t9 * t10) * in.w[2] * t14 - t12 * t9 * in.w[0] - in.w[1] * t17 * t14) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 43 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(2) * t3 * a_minus_b + T(3) * (t5 * ab_ap + ab_ab * J2 + t2 * a_minus_b) * t8 * ab_ab + T(2) * t6 * ab_ap;
  const T t10 = T(8) * t4 * a_minus_b + T(8) * t7 * ab_ap + T(5) * t8 * ab_ab * t9;
  const T t11 = T(8) * t4 - T(8) * t7 - ab_ap * t8 * t10;
  const T t12 = T(1) / ab_ab;
  const T t13 = ap_ap * t8 * t10 + T(2) * ab_ap * t11 * t12 - T(6) * t8 * t9;
  f = -(T(1) / T(48)) * length * (in.w[1] * t11 * t12 + in.w[2] * t13 * t12 - t8 * in.w[0] * t10 - t12 * in.w[3] * (ap_ap * t11 * t12 + T(6) * (T(2) * t6 + ab_ap * t8 * t9 - T(2) * t3) * t12 - T(2) * ab_ap * t13 * t12));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 55 +, 128 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i8_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = T(3) * (t2 * ab_ap + t6 * a_minus_b + J2 * ab_ab) * t5 * ab_ab + T(2) * t7 * a_minus_b + T(2) * t3 * ab_ap;
  const T t9 = t7 * t6;
  const T t10 = t3 * t2;
  const T t11 = T(5) * t8 * t5 * ab_ab + T(8) * t9 * a_minus_b + T(8) * t10 * ab_ap;
  const T t12 = t7 * t7;
  const T t13 = T(7) * t5 * t11 * ab_ab + T(48) * t4 * ab_ap + T(48) * t12 * a_minus_b;
  const T t14 = T(48) * t4 + ab_ap * t13 * t5 - T(48) * t12;
  const T t15 = T(1) / ab_ab;
  const T t16 = T(2) * t14 * ab_ap * t15 + T(8) * t5 * t11 - ap_ap * t13 * t5;
  const T t17 = T(8) * t10 + ab_ap * t5 * t11 - T(8) * t9;
  const T t18 = T(2) * t16 * ab_ap * t15 + T(8) * t17 * t15 - ap_ap * t14 * t15;
  const T g_ap = (T(1) / T(384)) * t16 * in.w[2] * t15 + (T(1) / T(384)) * in.w[1] * t14 * t15 + (T(1) / T(384)) * t13 * t5 * in.w[0] + (T(1) / T(384)) * t18 * in.w[3] * t15;
  const T g_ab = (T(1) / T(384)) * in.w[1] * t16 * t15 + (T(1) / T(384)) * in.w[3] * t15 * (T(2) * ab_ap * t18 * t15 + T(8) * (T(2) * t17 * ab_ap * t15 + T(6) * t8 * t5 - ap_ap * t5 * t11) * t15 - ap_ap * t16 * t15) + (T(1) / T(384)) * in.w[2] * t18 * t15 + (T(1) / T(384)) * t14 * in.w[0] * t15;
  const T g_factor = -T(8) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−8) dt
/// Operations: 62 +, 149 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i8_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(2) * t3 * ab_ap + T(2) * t6 * a_minus_b + T(3) * t7 * ab_ab * (t5 * a_minus_b + J2 * ab_ab + t2 * ab_ap);
  const T t9 = t6 * t5;
  const T t10 = T(8) * t4 * ab_ap + T(5) * t8 * t7 * ab_ab + T(8) * t9 * a_minus_b;
  const T t11 = T(1) / ab_ab;
  const T t12 = t3 * t3;
  const T t13 = t6 * t6;
  const T t14 = T(48) * t13 * a_minus_b + T(48) * t12 * ab_ap + T(7) * t10 * t7 * ab_ab;
  const T t15 = T(48) * t12 + ab_ap * t7 * t14 - T(48) * t13;
  const T t16 = T(8) * t10 * t7 + T(2) * ab_ap * t11 * t15 - ap_ap * t7 * t14;
  const T t17 = t10 * ab_ap * t7 + T(8) * t4 - T(8) * t9;
  const T t18 = T(2) * t16 * ab_ap * t11 + T(8) * t17 * t11 - ap_ap * t11 * t15;
  const T g_ap = (T(1) / T(384)) * t18 * t11 * in.w[3] + (T(1) / T(384)) * t7 * t14 * in.w[0] + (T(1) / T(384)) * in.w[1] * t11 * t15 + (T(1) / T(384)) * t16 * in.w[2] * t11;
  const T t19 = T(2) * t17 * ab_ap * t11 + T(6) * t8 * t7 - ap_ap * t10 * t7;
  const T g_ab = (T(1) / T(384)) * t11 * t15 * in.w[0] + (T(1) / T(384)) * (T(2) * t18 * ab_ap * t11 + T(8) * t19 * t11 - t16 * ap_ap * t11) * t11 * in.w[3] + (T(1) / T(384)) * t16 * in.w[1] * t11 + (T(1) / T(384)) * t18 * in.w[2] * t11;
  const T g_factor = -T(8) * length;
  f = (T(1) / T(48)) * length * (t19 * in.w[2] * t11 + t17 * in.w[1] * t11 + (T(6) * (t8 * ab_ap * t7 + T(2) * t3 - T(2) * t6) * t11 + T(2) * t19 * ab_ap * t11 - t17 * ap_ap * t11) * t11 * in.w[3] + t10 * t7 * in.w[0]);
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 31 +, 61 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / r1;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = T(1) / cross_cross;
  const T t7 = t2 * t1;
  const T t8 = t5 * t4;
  f = (T(1) / T(35)) * in.w[0] * (T(2) * ab_ab * (T(3) * t2 * t0 * ab_ap + T(3) * a_minus_b * t3 * t5 + T(4) * ab_ab * (a_minus_b * t3 * t4 + T(2) * ab_ab * (t0 * ab_ap + a_minus_b * t3) * t6 + t1 * t0 * ab_ap) * t6) * t6 + T(5) * t7 * t0 * ab_ap + T(5) * a_minus_b * t3 * t8) * length * t6;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 38 +, 89 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t3 * t2;
  const T t10 = t7 * t6;
  const T t11 = T(35) * ab_ap * t1 * t4 + T(35) * t8 * t5 * a_minus_b + T(8) * t0 * ab_ab * (T(5) * ab_ap * t1 * t9 + T(2) * t0 * ab_ab * (T(3) * ab_ap * t1 * t3 + T(3) * t7 * t5 * a_minus_b + T(4) * t0 * ab_ab * (T(2) * t0 * ab_ab * (ab_ap * t1 + t5 * a_minus_b) + t6 * t5 * a_minus_b + ab_ap * t1 * t2)) + T(5) * t10 * t5 * a_minus_b);
  const T g_ap = (T(1) / T(315)) * t0 * in.w[0] * t11;
  const T g_ab = -(T(1) / T(315)) * in.w[0] * (T(35) * t8 * t5 - T(35) * t1 * t4 - ab_ap * t0 * t11) / ab_ab;
  const T g_factor = -T(9) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−9) dt
/// Operations: 38 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t3 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = T(5) * t1 * a_minus_b * t5 + T(2) * t0 * ab_ab * (T(4) * (t6 * ab_ap * t7 + t1 * a_minus_b * t2 + T(2) * t0 * (t6 * ab_ap + t1 * a_minus_b) * ab_ab) * t0 * ab_ab + T(3) * t1 * a_minus_b * t3 + T(3) * t6 * ab_ap * t8) + T(5) * t6 * ab_ap * t9;
  const T t11 = t8 * t8;
  const T t12 = T(35) * t1 * a_minus_b * t4 + T(8) * t0 * t10 * ab_ab + T(35) * t6 * ab_ap * t11;
  const T g_ap = (T(1) / T(315)) * t0 * in.w[0] * t12;
  const T g_ab = (T(1) / T(315)) * (ab_ap * t0 * t12 + T(35) * t6 * t11 - T(35) * t1 * t4) * in.w[0] / ab_ab;
  const T g_factor = -T(9) * length;
  f = (T(1) / T(35)) * t0 * t10 * in.w[0] * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 34 +, 68 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(5) * t3 * t0 * ab_ap + T(5) * t4 * a_minus_b * t7 + T(2) * ab_ab * (T(4) * ab_ab * (T(2) * ab_ab * (t0 * ab_ap + t4 * a_minus_b) * t8 + t1 * t0 * ab_ap + t4 * a_minus_b * t5) * t8 + T(3) * t4 * a_minus_b * t6 + T(3) * t2 * t0 * ab_ap) * t8;
  f = (T(1) / T(35)) * (in.w[1] * (t9 * ab_ap * t8 + T(5) * t3 * t0 - T(5) * t4 * t7) / ab_ab + t9 * in.w[0] * t8) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 42 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t6 * t5;
  const T t10 = t2 * t1;
  const T t11 = T(5) * t4 * a_minus_b * t9 + T(2) * (T(3) * t4 * a_minus_b * t6 + T(3) * t2 * t0 * ab_ap + T(4) * (t1 * t0 * ab_ap + t4 * a_minus_b * t5 + T(2) * ab_ab * (t4 * a_minus_b + t0 * ab_ap) * t8) * ab_ab * t8) * ab_ab * t8 + T(5) * t10 * t0 * ab_ap;
  const T t12 = T(35) * t3 * t0 * ab_ap + T(35) * t4 * a_minus_b * t7 + T(8) * ab_ab * t8 * t11;
  const T t13 = T(1) / ab_ab;
  const T t14 = t12 * ab_ap * t8 + T(35) * t3 * t0 - T(35) * t4 * t7;
  const T g_ap = (T(1) / T(315)) * t12 * in.w[0] * t8 + (T(1) / T(315)) * t13 * in.w[1] * t14;
  const T g_ab = (T(1) / T(315)) * t13 * in.w[1] * (T(2) * t13 * t14 * ab_ap + T(9) * t8 * t11 - t12 * ap_ap * t8) + (T(1) / T(315)) * t13 * t14 * in.w[0];
  const T g_factor = -T(9) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−9) dt
/// Operations: 45 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t6 * t5;
  const T t10 = t2 * t1;
  const T t11 = T(2) * (T(4) * (t1 * ab_ap * t0 + t5 * t4 * a_minus_b + T(2) * t8 * (t4 * a_minus_b + ab_ap * t0) * ab_ab) * t8 * ab_ab + T(3) * t2 * ab_ap * t0 + T(3) * t6 * t4 * a_minus_b) * t8 * ab_ab + T(5) * t9 * t4 * a_minus_b + T(5) * t10 * ab_ap * t0;
  const T t12 = T(35) * t3 * ab_ap * t0 + T(35) * t7 * t4 * a_minus_b + T(8) * t11 * t8 * ab_ab;
  const T t13 = T(35) * t7 * t4 - T(35) * t3 * t0 - t12 * ab_ap * t8;
  const T t14 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(315)) * t12 * in.w[0] * t8 - (T(1) / T(315)) * t13 * in.w[1] * t14;
  const T g_ab = -(T(1) / T(315)) * (T(2) * t13 * ab_ap * t14 + ap_ap * t12 * t8 - T(9) * t11 * t8) * in.w[1] * t14 - (T(1) / T(315)) * t13 * in.w[0] * t14;
  const T g_factor = -T(9) * length;
  f = (T(1) / T(35)) * length * ((T(5) * t10 * t0 + t11 * ab_ap * t8 - T(5) * t9 * t4) * in.w[1] * t14 + t11 * in.w[0] * t8);
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 37 +, 81 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(1) / cross_cross;
  const T t8 = T(3) * t6 * ab_ap * t4 + T(4) * (T(2) * (t0 * a_minus_b + ab_ap * t4) * t7 * ab_ab + t1 * t0 * a_minus_b + t5 * ab_ap * t4) * t7 * ab_ab + T(3) * t2 * t0 * a_minus_b;
  const T t9 = t6 * t5;
  const T t10 = T(2) * t8 * t7 * ab_ab + T(5) * t9 * ab_ap * t4 + T(5) * t3 * t0 * a_minus_b;
  const T t11 = T(5) * t3 * t0 - t10 * ab_ap * t7 - T(5) * t9 * t4;
  const T t12 = T(1) / ab_ab;
  f = -(T(1) / T(105)) * ((T(6) * t11 * ab_ap * t12 + T(3) * t10 * ap_ap * t7 - T(7) * t8 * t7) * t12 * in.w[2] + T(3) * t11 * in.w[1] * t12 - T(3) * t10 * in.w[0] * t7) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 48 +, 122 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r1;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = t2 * t1;
  const T t10 = T(5) * t4 * a_minus_b * t7 + T(2) * ab_ab * (T(3) * t4 * a_minus_b * t6 + T(3) * t2 * t0 * ab_ap + T(4) * (T(2) * ab_ab * (t0 * ab_ap + t4 * a_minus_b) * t8 + t1 * t0 * ab_ap + t4 * a_minus_b * t5) * ab_ab * t8) * t8 + T(5) * t9 * t0 * ab_ap;
  const T t11 = t6 * t6;
  const T t12 = T(35) * t3 * t0 * ab_ap + T(8) * ab_ab * t10 * t8 + T(35) * t4 * a_minus_b * t11;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(35) * t3 * t0 + t12 * ab_ap * t8 - T(35) * t4 * t11;
  const T t15 = T(2) * t13 * ab_ap * t14 + T(9) * t10 * t8 - t12 * ap_ap * t8;
  const T g_ap = (T(1) / T(315)) * t12 * in.w[0] * t8 + (T(1) / T(315)) * t13 * in.w[1] * t14 + (T(1) / T(315)) * in.w[2] * t13 * t15;
  const T g_ab = (T(1) / T(315)) * t13 * t15 * in.w[1] + (T(1) / T(315)) * t13 * in.w[0] * t14 - (T(1) / T(315)) * in.w[2] * t13 * (t13 * ap_ap * t14 - T(2) * t13 * t15 * ab_ap - T(9) * t13 * (t10 * ab_ap * t8 + T(5) * t9 * t0 - T(5) * t4 * t7));
  const T g_factor = -T(9) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−9) dt
/// Operations: 52 +, 140 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t3 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t7 * t7;
  const T t10 = T(3) * t1 * a_minus_b * t3 + T(4) * ab_ab * (t7 * t6 * ab_ap + T(2) * ab_ab * (t6 * ab_ap + t1 * a_minus_b) * t8 + t1 * a_minus_b * t2) * t8 + T(3) * t9 * t6 * ab_ap;
  const T t11 = t9 * t7;
  const T t12 = T(5) * t1 * a_minus_b * t5 + T(2) * ab_ab * t10 * t8 + T(5) * t11 * t6 * ab_ap;
  const T t13 = t9 * t9;
  const T t14 = T(35) * t1 * a_minus_b * t4 + T(8) * ab_ab * t12 * t8 + T(35) * t13 * t6 * ab_ap;
  const T t15 = t14 * ab_ap * t8 + T(35) * t13 * t6 - T(35) * t1 * t4;
  const T t16 = T(2) * t0 * ab_ap * t15 + T(9) * t12 * t8 - t14 * ap_ap * t8;
  const T g_ap = (T(1) / T(315)) * t16 * t0 * in.w[2] + (T(1) / T(315)) * t0 * in.w[1] * t15 + (T(1) / T(315)) * t14 * in.w[0] * t8;
  const T t17 = T(5) * t11 * t6 + t12 * ab_ap * t8 - T(5) * t1 * t5;
  const T g_ab = (T(1) / T(315)) * t0 * in.w[2] * (T(9) * t0 * t17 + T(2) * t16 * t0 * ab_ap - t0 * ap_ap * t15) + (T(1) / T(315)) * t0 * in.w[0] * t15 + (T(1) / T(315)) * t16 * t0 * in.w[1];
  const T g_factor = -T(9) * length;
  f = (T(1) / T(105)) * (t0 * in.w[2] * (T(6) * t0 * t17 * ab_ap + T(7) * t10 * t8 - T(3) * ap_ap * t12 * t8) + T(3) * in.w[0] * t12 * t8 + T(3) * t0 * t17 * in.w[1]) * length;
  grad[0] = (ap0 * g_ap - ab0 * g_ab) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 42 +, 97 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / cross_cross;
  const T t2 = T(1) / r0;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = T(4) * t1 * ab_ab * (t6 * a_minus_b * t7 + T(2) * t1 * ab_ab * (t6 * a_minus_b + ab_ap * t2) + t3 * ab_ap * t2) + T(3) * t4 * ab_ap * t2 + T(3) * t6 * a_minus_b * t8;
  const T t10 = t8 * t7;
  const T t11 = T(5) * t5 * ab_ap * t2 + T(2) * t1 * ab_ab * t9 + T(5) * t6 * a_minus_b * t10;
  const T t12 = t1 * t11 * ab_ap + T(5) * t5 * t2 - T(5) * t6 * t10;
  const T t13 = T(3) * t1 * ap_ap * t11 - T(7) * t1 * t9 - T(6) * t0 * t12 * ab_ap;
  f = -(T(1) / T(105)) * length * (t0 * in.w[3] * (T(3) * t0 * ap_ap * t12 + T(2) * t0 * t13 * ab_ap + T(7) * t0 * (T(3) * t6 * t8 - T(3) * t4 * t2 - t1 * t9 * ab_ap)) + t0 * t13 * in.w[2] - T(3) * t1 * in.w[0] * t11 - T(3) * t0 * in.w[1] * t12);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 54 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i9_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t3 * t2;
  const T t10 = t7 * t6;
  const T t11 = T(3) * t7 * t5 * a_minus_b + T(3) * t1 * ab_ap * t3 + T(4) * t0 * ab_ab * (T(2) * t0 * (t5 * a_minus_b + t1 * ab_ap) * ab_ab + t1 * ab_ap * t2 + t6 * t5 * a_minus_b);
  const T t12 = T(5) * t1 * ab_ap * t9 + T(5) * t10 * t5 * a_minus_b + T(2) * t11 * t0 * ab_ab;
  const T t13 = T(35) * t1 * ab_ap * t4 + T(35) * t8 * t5 * a_minus_b + T(8) * t0 * t12 * ab_ab;
  const T t14 = ab_ap * t0 * t13 + T(35) * t1 * t4 - T(35) * t8 * t5;
  const T t15 = T(1) / ab_ab;
  const T t16 = T(5) * t10 * t5 - T(5) * t1 * t9 - ab_ap * t0 * t12;
  const T t17 = t0 * t13 * ap_ap - T(2) * ab_ap * t14 * t15 - T(9) * t0 * t12;
  const T t18 = t14 * t15 * ap_ap + T(9) * t16 * t15 + T(2) * ab_ap * t15 * t17;
  const T g_ap = (T(1) / T(315)) * t14 * t15 * in.w[1] + (T(1) / T(315)) * t0 * t13 * in.w[0] - (T(1) / T(315)) * t18 * in.w[3] * t15 - (T(1) / T(315)) * in.w[2] * t15 * t17;
  const T g_ab = (T(1) / T(315)) * t14 * in.w[0] * t15 + (T(1) / T(315)) * in.w[3] * t15 * (t15 * t17 * ap_ap - T(3) * t15 * (T(6) * t16 * ab_ap * t15 + T(3) * t0 * t12 * ap_ap - T(7) * t11 * t0) - T(2) * ab_ap * t18 * t15) - (T(1) / T(315)) * t15 * t17 * in.w[1] - (T(1) / T(315)) * in.w[2] * t18 * t15;
  const T g_factor = -T(9) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−9) dt
/// Operations: 61 +, 169 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i9_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(1) / cross_cross;
  const T t10 = T(3) * t3 * t1 * ab_ap + T(3) * a_minus_b * t7 * t5 + T(4) * ab_ab * (a_minus_b * t6 * t5 + T(2) * ab_ab * (a_minus_b * t5 + t1 * ab_ap) * t9 + t2 * t1 * ab_ap) * t9;
  const T t11 = T(5) * t4 * t1 * ab_ap + T(5) * a_minus_b * t8 * t5 + T(2) * ab_ab * t10 * t9;
  const T t12 = t7 * t7;
  const T t13 = t3 * t3;
  const T t14 = T(35) * a_minus_b * t12 * t5 + T(8) * ab_ab * t11 * t9 + T(35) * t13 * t1 * ab_ap;
  const T t15 = T(35) * t12 * t5 - t14 * ab_ap * t9 - T(35) * t13 * t1;
  const T t16 = T(9) * t11 * t9 - ap_ap * t14 * t9 - T(2) * t0 * t15 * ab_ap;
  const T t17 = T(5) * t4 * t1 + t11 * ab_ap * t9 - T(5) * t8 * t5;
  const T t18 = T(9) * t0 * t17 + T(2) * t0 * ab_ap * t16 + t0 * t15 * ap_ap;
  const T g_ap = (T(1) / T(315)) * t0 * in.w[2] * t16 + (T(1) / T(315)) * in.w[0] * t14 * t9 + (T(1) / T(315)) * t0 * in.w[3] * t18 - (T(1) / T(315)) * t0 * t15 * in.w[1];
  const T t19 = T(3) * ap_ap * t11 * t9 - T(7) * t10 * t9 - T(6) * t0 * t17 * ab_ap;
  const T g_ab = (T(1) / T(315)) * t0 * in.w[2] * t18 + (T(1) / T(315)) * t0 * in.w[1] * t16 - (T(1) / T(315)) * t0 * in.w[0] * t15 - (T(1) / T(315)) * t0 * in.w[3] * (T(3) * t0 * t19 + t0 * ap_ap * t16 - T(2) * t0 * ab_ap * t18);
  const T g_factor = -T(9) * length;
  f = -(T(1) / T(105)) * (t0 * in.w[2] * t19 + t0 * in.w[3] * (T(3) * t0 * ap_ap * t17 + T(2) * t0 * ab_ap * t19 - T(7) * t0 * (t10 * ab_ap * t9 + T(3) * t3 * t1 - T(3) * t7 * t5)) - T(3) * in.w[0] * t11 * t9 - T(3) * t0 * in.w[1] * t17) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 34 +, 62 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = t3 * t2;
  const T t10 = t6 * t6;
  f = (T(1) / T(384)) * (T(48) * t4 * a_minus_b + T(7) * (T(8) * ab_ap * t7 + T(5) * (T(2) * ab_ap * t6 + T(3) * (t2 * a_minus_b + ab_ab * J2 + ab_ap * t5) * t8 * ab_ab + T(2) * t3 * a_minus_b) * t8 * ab_ab + T(8) * t9 * a_minus_b) * t8 * ab_ab + T(48) * ab_ap * t10) * t8 * in.w[0] * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 41 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = T(1) / cross_cross;
  const T t11 = t3 * t2;
  const T t12 = t7 * t6;
  const T t13 = T(128) * t5 * a_minus_b + T(128) * t9 * ab_ap + T(3) * (T(48) * t8 * ab_ap + T(48) * t4 * a_minus_b + T(7) * t10 * ab_ab * (T(5) * (T(2) * t3 * a_minus_b + T(2) * t7 * ab_ap + T(3) * (ab_ab * J2 + t6 * ab_ap + t2 * a_minus_b) * t10 * ab_ab) * t10 * ab_ab + T(8) * t11 * a_minus_b + T(8) * t12 * ab_ap)) * t10 * ab_ab;
  const T g_ap = (T(1) / T(1280)) * t13 * t10 * in.w[0];
  const T g_ab = (T(1) / T(1280)) * (T(128) * t9 + t13 * ab_ap * t10 - T(128) * t5) * in.w[0] / ab_ab;
  const T g_factor = -T(10) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−10) dt
/// Operations: 41 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / ap_ap;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = t6 * t6;
  const T t10 = t3 * t3;
  const T t11 = T(7) * (T(8) * t4 * a_minus_b + T(8) * t7 * ab_ap + T(5) * (T(3) * (t5 * ab_ap + J2 * ab_ab + t2 * a_minus_b) * t8 * ab_ab + T(2) * t3 * a_minus_b + T(2) * t6 * ab_ap) * t8 * ab_ab) * t8 * ab_ab + T(48) * t9 * ab_ap + T(48) * t10 * a_minus_b;
  const T t12 = t9 * t5;
  const T t13 = t10 * t2;
  const T t14 = T(3) * t11 * t8 * ab_ab + T(128) * t12 * ab_ap + T(128) * t13 * a_minus_b;
  const T g_ap = (T(1) / T(1280)) * t14 * t8 * in.w[0];
  const T g_ab = (T(1) / T(1280)) * (T(128) * t12 + ab_ap * t14 * t8 - T(128) * t13) * in.w[0] / ab_ab;
  const T g_factor = -T(10) * length;
  f = (T(1) / T(384)) * t11 * length * t8 * in.w[0];
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 37 +, 67 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t7 * t6;
  const T t10 = t3 * t2;
  const T t11 = T(48) * a_minus_b * t8 + T(7) * t5 * ab_ab * (T(8) * a_minus_b * t9 + T(8) * t10 * ab_ap + T(5) * t5 * ab_ab * (T(3) * t5 * (t2 * ab_ap + ab_ab * J2 + a_minus_b * t6) * ab_ab + T(2) * a_minus_b * t7 + T(2) * t3 * ab_ap)) + T(48) * t4 * ab_ap;
  f = (T(1) / T(384)) * length * (in.w[1] * (T(48) * t4 + t5 * t11 * ab_ap - T(48) * t8) / ab_ab + t5 * t11 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 45 +, 101 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / cross_cross;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t3 * t2;
  const T t11 = t8 * t8;
  const T t12 = T(48) * t4 * ab_ap + T(7) * t6 * ab_ab * (T(5) * t6 * (T(2) * t8 * a_minus_b + T(3) * t6 * (t2 * ab_ap + ab_ab * J2 + t7 * a_minus_b) * ab_ab + T(2) * t3 * ab_ap) * ab_ab + T(8) * t9 * a_minus_b + T(8) * t10 * ab_ap) + T(48) * t11 * a_minus_b;
  const T t13 = t11 * t7;
  const T t14 = T(128) * t5 * ab_ap + T(3) * t6 * t12 * ab_ab + T(128) * t13 * a_minus_b;
  const T t15 = T(1) / ab_ab;
  const T t16 = T(128) * t5 + t14 * ab_ap * t6 - T(128) * t13;
  const T g_ap = (T(1) / T(1280)) * t14 * in.w[0] * t6 + (T(1) / T(1280)) * t15 * in.w[1] * t16;
  const T g_ab = (T(1) / T(1280)) * in.w[0] * t15 * t16 + (T(1) / T(3840)) * (T(10) * t6 * t12 + T(6) * ab_ap * t15 * t16 - T(3) * ap_ap * t14 * t6) * t15 * in.w[1];
  const T g_factor = -T(10) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−10) dt
/// Operations: 48 +, 111 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = t3 * t2;
  const T t11 = T(1) / cross_cross;
  const T t12 = t7 * t6;
  const T t13 = T(48) * t4 * ab_ap + T(48) * a_minus_b * t8 + T(7) * (T(8) * t10 * ab_ap + T(5) * ab_ab * (T(3) * ab_ab * (ab_ab * J2 + a_minus_b * t6 + t2 * ab_ap) * t11 + T(2) * t3 * ab_ap + T(2) * a_minus_b * t7) * t11 + T(8) * a_minus_b * t12) * ab_ab * t11;
  const T t14 = T(128) * t5 * ab_ap + T(128) * a_minus_b * t9 + T(3) * ab_ab * t13 * t11;
  const T t15 = T(1) / ab_ab;
  const T t16 = T(128) * t9 - ab_ap * t14 * t11 - T(128) * t5;
  const T g_ap = (T(1) / T(1280)) * t14 * in.w[0] * t11 - (T(1) / T(1280)) * t15 * in.w[1] * t16;
  const T g_ab = -(T(1) / T(3840)) * t15 * in.w[1] * (T(6) * t15 * t16 * ab_ap + T(3) * ap_ap * t14 * t11 - T(10) * t13 * t11) - (T(1) / T(1280)) * t15 * t16 * in.w[0];
  const T g_factor = -T(10) * length;
  f = (T(1) / T(384)) * (t13 * in.w[0] * t11 - t15 * in.w[1] * (T(48) * t8 - t13 * ab_ap * t11 - T(48) * t4)) * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 40 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / bp_bp;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t6 * t5;
  const T t10 = t3 * t2;
  const T t11 = T(5) * (T(2) * t6 * a_minus_b + T(3) * (J2 * ab_ab + t2 * ab_ap + t5 * a_minus_b) * t8 * ab_ab + T(2) * t3 * ab_ap) * t8 * ab_ab + T(8) * t9 * a_minus_b + T(8) * t10 * ab_ap;
  const T t12 = T(48) * t4 * ab_ap + T(48) * t7 * a_minus_b + T(7) * t11 * t8 * ab_ab;
  const T t13 = T(48) * t4 + ab_ap * t12 * t8 - T(48) * t7;
  const T t14 = T(1) / ab_ab;
  f = (T(1) / T(384)) * length * (in.w[0] * t12 * t8 + t13 * in.w[1] * t14 + in.w[2] * (T(2) * t13 * ab_ap * t14 + T(8) * t11 * t8 - ap_ap * t12 * t8) * t14);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 51 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t7 * t7;
  const T t10 = t4 * t4;
  const T t11 = T(7) * t2 * ab_ab * (T(8) * t5 * a_minus_b + T(5) * (T(2) * t4 * a_minus_b + T(3) * (t6 * ab_ap + J2 * ab_ab + t3 * a_minus_b) * t2 * ab_ab + T(2) * t7 * ab_ap) * t2 * ab_ab + T(8) * t8 * ab_ap) + T(48) * t9 * ab_ap + T(48) * t10 * a_minus_b;
  const T t12 = t9 * t6;
  const T t13 = t10 * t3;
  const T t14 = T(3) * t2 * ab_ab * t11 + T(128) * t12 * ab_ap + T(128) * t13 * a_minus_b;
  const T t15 = T(128) * t12 + ab_ap * t2 * t14 - T(128) * t13;
  const T t16 = T(1) / ab_ab;
  const T t17 = T(10) * t2 * t11 + T(6) * ab_ap * t15 * t16 - T(3) * ap_ap * t2 * t14;
  const T g_ap = (T(1) / T(1280)) * in.w[0] * t2 * t14 + (T(1) / T(3840)) * t17 * t16 * in.w[2] + (T(1) / T(1280)) * in.w[1] * t15 * t16;
  const T g_ab = (T(1) / T(3840)) * t17 * in.w[1] * t16 + (T(1) / T(1280)) * in.w[0] * t15 * t16 - (T(1) / T(3840)) * (T(3) * ap_ap * t15 * t16 - T(10) * (T(48) * t9 + ab_ap * t2 * t11 - T(48) * t10) * t16 - T(2) * t17 * ab_ap * t16) * t16 * in.w[2];
  const T g_factor = -T(10) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−10) dt
/// Operations: 55 +, 134 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t6;
  const T t12 = t3 * t2;
  const T t13 = T(8) * t11 * a_minus_b + T(5) * (T(2) * ab_ap * t3 + T(2) * t7 * a_minus_b + T(3) * (t6 * a_minus_b + ab_ap * t2 + ab_ab * J2) * t10 * ab_ab) * t10 * ab_ab + T(8) * ab_ap * t12;
  const T t14 = T(48) * ab_ap * t4 + T(7) * t13 * t10 * ab_ab + T(48) * t8 * a_minus_b;
  const T t15 = T(128) * ab_ap * t5 + T(128) * t9 * a_minus_b + T(3) * t10 * t14 * ab_ab;
  const T t16 = T(1) / ab_ab;
  const T t17 = T(128) * t9 - T(128) * t5 - t15 * ab_ap * t10;
  const T t18 = T(3) * t15 * t10 * ap_ap + T(6) * ab_ap * t16 * t17 - T(10) * t10 * t14;
  const T g_ap = (T(1) / T(1280)) * in.w[0] * t15 * t10 - (T(1) / T(1280)) * in.w[1] * t16 * t17 - (T(1) / T(3840)) * t16 * in.w[2] * t18;
  const T t19 = T(48) * t8 - ab_ap * t10 * t14 - T(48) * t4;
  const T g_ab = (T(1) / T(3840)) * (T(3) * t16 * ap_ap * t17 - T(10) * t19 * t16 - T(2) * ab_ap * t16 * t18) * t16 * in.w[2] - (T(1) / T(3840)) * in.w[1] * t16 * t18 - (T(1) / T(1280)) * in.w[0] * t16 * t17;
  const T g_factor = -T(10) * length;
  f = -(T(1) / T(384)) * (t19 * in.w[1] * t16 - (T(8) * t13 * t10 - t10 * t14 * ap_ap - T(2) * ab_ap * t19 * t16) * t16 * in.w[2] - in.w[0] * t10 * t14) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = -g_factor * (g_ab * ab2 - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 45 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / bp_bp;
  const T t5 = t4 * t4;
  const T t6 = t5 * t4;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = T(8) * t6 * a_minus_b + T(8) * ab_ap * t9 + T(5) * t3 * (T(3) * t3 * ab_ab * (t4 * a_minus_b + ab_ap * t7 + ab_ab * J2) + T(2) * ab_ap * t8 + T(2) * t5 * a_minus_b) * ab_ab;
  const T t11 = t5 * t5;
  const T t12 = t8 * t8;
  const T t13 = T(7) * t3 * ab_ab * t10 + T(48) * t11 * a_minus_b + T(48) * ab_ap * t12;
  const T t14 = t13 * ab_ap * t3 + T(48) * t12 - T(48) * t11;
  const T t15 = T(8) * t3 * t10 + T(2) * ab_ap * t2 * t14 - t13 * t3 * ap_ap;
  f = (T(1) / T(384)) * length * (t2 * t14 * in.w[1] + t13 * t3 * in.w[0] + in.w[2] * t15 * t2 - in.w[3] * (t2 * t14 * ap_ap + T(8) * (T(8) * t6 - T(8) * t9 - ab_ap * t3 * t10) * t2 - T(2) * ab_ap * t15 * t2) * t2);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 57 +, 139 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i10_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t4 * t3;
  const T t12 = t8 * t7;
  const T t13 = T(8) * t11 * a_minus_b + T(8) * t12 * ab_ap + T(5) * t2 * (T(3) * t2 * (t7 * ab_ap + t3 * a_minus_b + J2 * ab_ab) * ab_ab + T(2) * t4 * a_minus_b + T(2) * t8 * ab_ap) * ab_ab;
  const T t14 = T(7) * t13 * t2 * ab_ab + T(48) * t5 * a_minus_b + T(48) * t9 * ab_ap;
  const T t15 = T(128) * t6 * a_minus_b + T(128) * t10 * ab_ap + T(3) * t14 * t2 * ab_ab;
  const T t16 = T(48) * t9 + t14 * ab_ap * t2 - T(48) * t5;
  const T t17 = T(1) / ab_ab;
  const T t18 = T(128) * t10 + ab_ap * t2 * t15 - T(128) * t6;
  const T t19 = T(3) * ap_ap * t2 * t15 - T(6) * t18 * ab_ap * t17 - T(10) * t14 * t2;
  const T t20 = T(10) * t16 * t17 - T(3) * ap_ap * t18 * t17 - T(2) * ab_ap * t17 * t19;
  const T g_ap = (T(1) / T(1280)) * t2 * in.w[0] * t15 + (T(1) / T(3840)) * t20 * t17 * in.w[3] + (T(1) / T(1280)) * in.w[1] * t18 * t17 - (T(1) / T(3840)) * in.w[2] * t17 * t19;
  const T g_ab = (T(1) / T(3840)) * (T(2) * ab_ap * t20 * t17 + ap_ap * t17 * t19 - T(10) * (ap_ap * t14 * t2 - T(8) * t13 * t2 - T(2) * t16 * ab_ap * t17) * t17) * t17 * in.w[3] + (T(1) / T(3840)) * in.w[2] * t20 * t17 + (T(1) / T(1280)) * t18 * t17 * in.w[0] - (T(1) / T(3840)) * in.w[1] * t17 * t19;
  const T g_factor = -T(10) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−10) dt
/// Operations: 64 +, 160 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i10_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = t4 * t3;
  const T t8 = T(1) / ap_ap;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = T(8) * a_minus_b * t7 + T(8) * ab_ap * t10 + T(5) * t2 * ab_ab * (T(2) * a_minus_b * t4 + T(2) * ab_ap * t9 + T(3) * t2 * ab_ab * (ab_ab * J2 + ab_ap * t8 + a_minus_b * t3));
  const T t12 = t9 * t9;
  const T t13 = T(7) * t2 * ab_ab * t11 + T(48) * ab_ap * t12 + T(48) * a_minus_b * t5;
  const T t14 = t12 * t8;
  const T t15 = T(128) * a_minus_b * t6 + T(3) * t2 * t13 * ab_ab + T(128) * ab_ap * t14;
  const T t16 = ab_ap * t2 * t15 + T(128) * t14 - T(128) * t6;
  const T t17 = T(1) / ab_ab;
  const T t18 = T(6) * ab_ap * t16 * t17 + T(10) * t2 * t13 - T(3) * t2 * ap_ap * t15;
  const T t19 = ab_ap * t2 * t13 + T(48) * t12 - T(48) * t5;
  const T t20 = T(3) * t16 * t17 * ap_ap - T(2) * ab_ap * t18 * t17 - T(10) * t17 * t19;
  const T g_ap = (T(1) / T(3840)) * in.w[2] * t18 * t17 + (T(1) / T(1280)) * t2 * in.w[0] * t15 + (T(1) / T(1280)) * t16 * t17 * in.w[1] - (T(1) / T(3840)) * t17 * in.w[3] * t20;
  const T t21 = T(8) * t2 * t11 + T(2) * ab_ap * t17 * t19 - t2 * t13 * ap_ap;
  const T g_ab = (T(1) / T(1280)) * t16 * t17 * in.w[0] + (T(1) / T(3840)) * t18 * t17 * in.w[1] - (T(1) / T(3840)) * in.w[2] * t17 * t20 - (T(1) / T(3840)) * t17 * in.w[3] * (T(2) * ab_ap * t17 * t20 + t18 * t17 * ap_ap - T(10) * t21 * t17);
  const T g_factor = -T(10) * length;
  f = (T(1) / T(384)) * (t2 * t13 * in.w[0] + t21 * in.w[2] * t17 + t17 * t19 * in.w[1] - (t17 * t19 * ap_ap - T(8) * (ab_ap * t2 * t11 + T(8) * t10 - T(8) * t7) * t17 - T(2) * t21 * ab_ap * t17) * t17 * in.w[3]) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 33 +, 72 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t5;
  const T t8 = T(1) / cross_cross;
  const T t9 = t6 * t6;
  const T t10 = t2 * t2;
  f = (T(1) / T(315)) * (T(8) * (T(5) * t0 * a_minus_b * t3 + T(5) * t4 * ab_ap * t7 + T(2) * (T(4) * t8 * (t4 * ab_ap * t5 + t0 * a_minus_b * t1 + T(2) * t8 * ab_ab * (t0 * a_minus_b + t4 * ab_ap)) * ab_ab + T(3) * t0 * a_minus_b * t2 + T(3) * t4 * ab_ap * t6) * t8 * ab_ab) * t8 * ab_ab + T(35) * t4 * ab_ap * t9 + T(35) * t0 * a_minus_b * t10) * t8 * in.w[0] * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 40 +, 100 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t2 * t1;
  const T t11 = t8 * t8;
  const T t12 = t11 * t7;
  const T t13 = T(63) * t4 * t0 * ab_ap + T(2) * ab_ab * t5 * (T(8) * (T(5) * t6 * a_minus_b * t9 + T(2) * ab_ab * (T(3) * t2 * t0 * ab_ap + T(3) * t6 * a_minus_b * t8 + T(4) * ab_ab * (T(2) * ab_ab * (t0 * ab_ap + t6 * a_minus_b) * t5 + t6 * a_minus_b * t7 + t1 * t0 * ab_ap) * t5) * t5 + T(5) * t10 * t0 * ab_ap) * ab_ab * t5 + T(35) * t3 * t0 * ab_ap + T(35) * t6 * a_minus_b * t11) + T(63) * t6 * a_minus_b * t12;
  const T g_ap = (T(1) / T(693)) * t13 * in.w[0] * t5;
  const T g_ab = (T(1) / T(693)) * in.w[0] * (t13 * ab_ap * t5 + T(63) * t4 * t0 - T(63) * t6 * t12) / ab_ab;
  const T g_factor = -T(11) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−11) dt
/// Operations: 40 +, 104 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / cross_cross;
  const T t6 = t2 * t1;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = t9 * t9;
  const T t12 = T(35) * ab_ap * t0 * t3 + T(8) * t5 * ab_ab * (T(5) * ab_ap * t0 * t6 + T(5) * t7 * a_minus_b * t10 + T(2) * (T(4) * t5 * (t7 * a_minus_b * t8 + T(2) * (t7 * a_minus_b + ab_ap * t0) * t5 * ab_ab + ab_ap * t0 * t1) * ab_ab + T(3) * ab_ap * t0 * t2 + T(3) * t7 * a_minus_b * t9) * t5 * ab_ab) + T(35) * t7 * a_minus_b * t11;
  const T t13 = t11 * t8;
  const T t14 = T(63) * ab_ap * t0 * t4 + T(2) * t5 * t12 * ab_ab + T(63) * t7 * a_minus_b * t13;
  const T g_ap = (T(1) / T(693)) * t14 * t5 * in.w[0];
  const T g_ab = (T(1) / T(693)) * in.w[0] * (T(63) * t0 * t4 + t14 * ab_ap * t5 - T(63) * t7 * t13) / ab_ab;
  const T g_factor = -T(11) * length;
  f = (T(1) / T(315)) * length * t5 * t12 * in.w[0];
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 36 +, 79 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t3 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t8 * t8;
  const T t11 = T(35) * a_minus_b * t1 * t4 + T(8) * (T(5) * a_minus_b * t1 * t5 + T(5) * ab_ap * t6 * t9 + T(2) * t0 * ab_ab * (T(3) * a_minus_b * t1 * t3 + T(4) * t0 * ab_ab * (ab_ap * t6 * t7 + a_minus_b * t1 * t2 + T(2) * t0 * ab_ab * (a_minus_b * t1 + ab_ap * t6)) + T(3) * ab_ap * t6 * t8)) * t0 * ab_ab + T(35) * ab_ap * t6 * t10;
  f = (T(1) / T(315)) * length * (in.w[1] * (ab_ap * t0 * t11 + T(35) * t6 * t10 - T(35) * t1 * t4) / ab_ab + in.w[0] * t0 * t11);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 44 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t3 * t2;
  const T t11 = t8 * t8;
  const T t12 = T(35) * t4 * ab_ap * t1 + T(8) * t0 * (T(2) * t0 * ab_ab * (T(3) * t3 * ab_ap * t1 + T(4) * t0 * ab_ab * (T(2) * t0 * ab_ab * (ab_ap * t1 + t6 * a_minus_b) + t6 * a_minus_b * t7 + t2 * ab_ap * t1) + T(3) * t6 * a_minus_b * t8) + T(5) * t6 * a_minus_b * t9 + T(5) * t10 * ab_ap * t1) * ab_ab + T(35) * t6 * a_minus_b * t11;
  const T t13 = t11 * t7;
  const T t14 = T(63) * t5 * ab_ap * t1 + T(2) * t0 * ab_ab * t12 + T(63) * t6 * a_minus_b * t13;
  const T t15 = t0 * ab_ap * t14 + T(63) * t5 * t1 - T(63) * t6 * t13;
  const T t16 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(693)) * t0 * in.w[0] * t14 + (T(1) / T(693)) * t15 * t16 * in.w[1];
  const T g_ab = (T(1) / T(693)) * t15 * t16 * in.w[0] + (T(1) / T(3465)) * t16 * in.w[1] * (T(11) * t0 * t12 + T(10) * t15 * t16 * ab_ap - T(5) * t0 * ap_ap * t14);
  const T g_factor = -T(11) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−11) dt
/// Operations: 47 +, 127 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t6;
  const T t12 = t2 * t1;
  const T t13 = T(35) * t3 * a_minus_b * t0 + T(8) * (T(5) * t11 * ab_ap * t5 + T(2) * (T(4) * (t6 * ab_ap * t5 + t1 * a_minus_b * t0 + T(2) * (a_minus_b * t0 + ab_ap * t5) * t10 * ab_ab) * t10 * ab_ab + T(3) * t2 * a_minus_b * t0 + T(3) * t7 * ab_ap * t5) * t10 * ab_ab + T(5) * t12 * a_minus_b * t0) * t10 * ab_ab + T(35) * t8 * ab_ap * t5;
  const T t14 = T(63) * t4 * a_minus_b * t0 + T(63) * t9 * ab_ap * t5 + T(2) * t10 * t13 * ab_ab;
  const T t15 = T(63) * t4 * t0 - T(63) * t9 * t5 - t14 * ab_ap * t10;
  const T t16 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(693)) * t14 * in.w[0] * t10 - (T(1) / T(693)) * in.w[1] * t15 * t16;
  const T g_ab = -(T(1) / T(3465)) * in.w[1] * (T(10) * t15 * ab_ap * t16 + T(5) * t14 * ap_ap * t10 - T(11) * t10 * t13) * t16 - (T(1) / T(693)) * t15 * in.w[0] * t16;
  const T g_factor = -T(11) * length;
  f = -(T(1) / T(315)) * length * (in.w[1] * (T(35) * t3 * t0 - T(35) * t8 * t5 - ab_ap * t10 * t13) * t16 - in.w[0] * t10 * t13);
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 39 +, 89 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / r0;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = T(1) / cross_cross;
  const T t9 = t2 * t1;
  const T t10 = t6 * t5;
  const T t11 = T(2) * t8 * ab_ab * (T(3) * t2 * t0 * a_minus_b + T(4) * t8 * ab_ab * (t4 * ab_ap * t5 + T(2) * t8 * ab_ab * (t4 * ab_ap + t0 * a_minus_b) + t1 * t0 * a_minus_b) + T(3) * t4 * ab_ap * t6) + T(5) * t9 * t0 * a_minus_b + T(5) * t4 * ab_ap * t10;
  const T t12 = T(35) * t3 * t0 * a_minus_b + T(35) * t4 * ab_ap * t7 + T(8) * t11 * t8 * ab_ab;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(35) * t4 * t7 + t12 * ab_ap * t8 - T(35) * t3 * t0;
  f = (T(1) / T(315)) * (t12 * in.w[0] * t8 + in.w[1] * t13 * t14 + t13 * in.w[2] * (T(2) * ab_ap * t13 * t14 + T(9) * t11 * t8 - t12 * t8 * ap_ap)) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 50 +, 135 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / cross_cross;
  const T t7 = t3 * t2;
  const T t8 = T(1) / r1;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t10 * t10;
  const T t13 = T(8) * (T(5) * ab_ap * t1 * t7 + T(5) * t11 * t8 * a_minus_b + T(2) * (T(3) * ab_ap * t1 * t3 + T(4) * (t9 * t8 * a_minus_b + ab_ap * t1 * t2 + T(2) * (ab_ap * t1 + t8 * a_minus_b) * t6 * ab_ab) * t6 * ab_ab + T(3) * t10 * t8 * a_minus_b) * t6 * ab_ab) * t6 * ab_ab + T(35) * ab_ap * t1 * t4 + T(35) * t12 * t8 * a_minus_b;
  const T t14 = t12 * t9;
  const T t15 = T(2) * t6 * ab_ab * t13 + T(63) * ab_ap * t1 * t5 + T(63) * t14 * t8 * a_minus_b;
  const T t16 = T(63) * t1 * t5 + ab_ap * t6 * t15 - T(63) * t14 * t8;
  const T t17 = T(5) * t6 * t15 * ap_ap - T(11) * t6 * t13 - T(10) * ab_ap * t0 * t16;
  const T g_ap = (T(1) / T(693)) * in.w[1] * t0 * t16 + (T(1) / T(693)) * in.w[0] * t6 * t15 - (T(1) / T(3465)) * t0 * in.w[2] * t17;
  const T g_ab = (T(1) / T(693)) * in.w[0] * t0 * t16 - (T(1) / T(3465)) * (T(5) * t0 * t16 * ap_ap + T(2) * ab_ap * t0 * t17 - T(11) * (T(35) * t1 * t4 + ab_ap * t6 * t13 - T(35) * t12 * t8) * t0) * t0 * in.w[2] - (T(1) / T(3465)) * in.w[1] * t0 * t17;
  const T g_factor = -T(11) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−11) dt
/// Operations: 54 +, 150 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t2 * t1;
  const T t12 = t8 * t7;
  const T t13 = T(5) * t11 * t0 * ab_ap + T(2) * t5 * ab_ab * (T(3) * t8 * t6 * a_minus_b + T(4) * t5 * ab_ab * (t1 * t0 * ab_ap + T(2) * (t0 * ab_ap + t6 * a_minus_b) * t5 * ab_ab + t7 * t6 * a_minus_b) + T(3) * t2 * t0 * ab_ap) + T(5) * t12 * t6 * a_minus_b;
  const T t14 = T(8) * t13 * t5 * ab_ab + T(35) * t9 * t6 * a_minus_b + T(35) * t3 * t0 * ab_ap;
  const T t15 = T(63) * t10 * t6 * a_minus_b + T(2) * t14 * t5 * ab_ab + T(63) * t4 * t0 * ab_ap;
  const T t16 = T(63) * t4 * t0 + ab_ap * t5 * t15 - T(63) * t10 * t6;
  const T t17 = T(1) / ab_ab;
  const T t18 = T(10) * t16 * ab_ap * t17 + T(11) * t14 * t5 - T(5) * ap_ap * t5 * t15;
  const T g_ap = (T(1) / T(693)) * t16 * in.w[1] * t17 + (T(1) / T(693)) * in.w[0] * t5 * t15 + (T(1) / T(3465)) * t17 * in.w[2] * t18;
  const T t19 = T(35) * t9 * t6 - ab_ap * t14 * t5 - T(35) * t3 * t0;
  const T g_ab = (T(1) / T(3465)) * in.w[1] * t17 * t18 + (T(1) / T(693)) * in.w[0] * t16 * t17 + (T(1) / T(3465)) * (T(2) * ab_ap * t17 * t18 - T(11) * t19 * t17 - T(5) * ap_ap * t16 * t17) * t17 * in.w[2];
  const T g_factor = -T(11) * length;
  f = -(T(1) / T(315)) * length * ((ap_ap * t14 * t5 + T(2) * ab_ap * t19 * t17 - T(9) * t13 * t5) * t17 * in.w[2] + t19 * in.w[1] * t17 - in.w[0] * t14 * t5);
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 44 +, 104 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t3 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = T(5) * t1 * a_minus_b * t5 + T(5) * t9 * ab_ap * t6 + T(2) * (T(4) * ab_ab * t0 * (t7 * ab_ap * t6 + T(2) * (ab_ap * t6 + t1 * a_minus_b) * ab_ab * t0 + t1 * a_minus_b * t2) + T(3) * t1 * a_minus_b * t3 + T(3) * t8 * ab_ap * t6) * ab_ab * t0;
  const T t11 = t8 * t8;
  const T t12 = T(35) * t1 * a_minus_b * t4 + T(8) * ab_ab * t10 * t0 + T(35) * t11 * ab_ap * t6;
  const T t13 = T(1) / ab_ab;
  const T t14 = T(35) * t11 * t6 + ab_ap * t0 * t12 - T(35) * t1 * t4;
  const T t15 = ap_ap * t0 * t12 - T(9) * t10 * t0 - T(2) * t13 * t14 * ab_ap;
  f = (T(1) / T(315)) * length * (in.w[0] * t0 * t12 + t13 * in.w[1] * t14 - (t13 * ap_ap * t14 + T(2) * t13 * ab_ap * t15 - T(9) * t13 * (t10 * ab_ap * t0 + T(5) * t9 * t6 - T(5) * t1 * t5)) * t13 * in.w[3] - t13 * in.w[2] * t15);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 56 +, 155 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i11_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t3 * t2;
  const T t10 = t7 * t6;
  const T t11 = T(5) * ab_ap * t1 * t9 + T(5) * t10 * t5 * a_minus_b + T(2) * t0 * (T(3) * ab_ap * t1 * t3 + T(3) * t7 * t5 * a_minus_b + T(4) * (T(2) * (ab_ap * t1 + t5 * a_minus_b) * t0 * ab_ab + t6 * t5 * a_minus_b + ab_ap * t1 * t2) * t0 * ab_ab) * ab_ab;
  const T t12 = T(35) * ab_ap * t1 * t4 + T(35) * t8 * t5 * a_minus_b + T(8) * t0 * ab_ab * t11;
  const T t13 = t4 * t2;
  const T t14 = t8 * t6;
  const T t15 = T(2) * t0 * ab_ab * t12 + T(63) * ab_ap * t1 * t13 + T(63) * t14 * t5 * a_minus_b;
  const T t16 = T(1) / ab_ab;
  const T t17 = ab_ap * t0 * t15 + T(63) * t1 * t13 - T(63) * t14 * t5;
  const T t18 = T(11) * t0 * t12 + T(10) * ab_ap * t16 * t17 - T(5) * t0 * t15 * ap_ap;
  const T t19 = T(35) * t1 * t4 + ab_ap * t0 * t12 - T(35) * t8 * t5;
  const T t20 = T(5) * t16 * ap_ap * t17 - T(11) * t19 * t16 - T(2) * t18 * ab_ap * t16;
  const T g_ap = (T(1) / T(693)) * t0 * t15 * in.w[0] + (T(1) / T(3465)) * t18 * in.w[2] * t16 + (T(1) / T(693)) * in.w[1] * t16 * t17 - (T(1) / T(3465)) * t20 * t16 * in.w[3];
  const T g_ab = (T(1) / T(693)) * t16 * in.w[0] * t17 + (T(1) / T(3465)) * in.w[1] * t18 * t16 - (T(1) / T(3465)) * t16 * in.w[3] * (T(2) * ab_ap * t20 * t16 + t18 * t16 * ap_ap - T(11) * (T(9) * t0 * t11 + T(2) * ab_ap * t19 * t16 - t0 * t12 * ap_ap) * t16) - (T(1) / T(3465)) * in.w[2] * t20 * t16;
  const T g_factor = -T(11) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−11) dt
/// Operations: 63 +, 178 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i11_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = t3 * t2;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = T(1) / cross_cross;
  const T t12 = T(5) * t6 * t1 * ab_ap + T(5) * a_minus_b * t7 * t10 + T(2) * ab_ab * (T(4) * ab_ab * (a_minus_b * t7 * t8 + T(2) * ab_ab * (t1 * ab_ap + a_minus_b * t7) * t11 + t2 * t1 * ab_ap) * t11 + T(3) * t3 * t1 * ab_ap + T(3) * a_minus_b * t7 * t9) * t11;
  const T t13 = t9 * t9;
  const T t14 = T(35) * t4 * t1 * ab_ap + T(8) * ab_ab * t12 * t11 + T(35) * a_minus_b * t7 * t13;
  const T t15 = t13 * t8;
  const T t16 = T(63) * t5 * t1 * ab_ap + T(2) * t14 * ab_ab * t11 + T(63) * a_minus_b * t7 * t15;
  const T t17 = T(63) * t5 * t1 + ab_ap * t16 * t11 - T(63) * t7 * t15;
  const T t18 = T(35) * t4 * t1 + t14 * ab_ap * t11 - T(35) * t7 * t13;
  const T t19 = T(11) * t14 * t11 + T(10) * t0 * t17 * ab_ap - T(5) * ap_ap * t16 * t11;
  const T t20 = T(11) * t0 * t18 + T(2) * t0 * t19 * ab_ap - T(5) * t0 * t17 * ap_ap;
  const T g_ap = (T(1) / T(693)) * t0 * t17 * in.w[1] + (T(1) / T(3465)) * in.w[3] * t0 * t20 + (T(1) / T(693)) * in.w[0] * t16 * t11 + (T(1) / T(3465)) * t0 * t19 * in.w[2];
  const T t21 = T(9) * t12 * t11 + T(2) * t0 * ab_ap * t18 - t14 * ap_ap * t11;
  const T g_ab = (T(1) / T(693)) * in.w[0] * t0 * t17 + (T(1) / T(3465)) * t0 * in.w[1] * t19 + (T(1) / T(3465)) * in.w[3] * t0 * (T(11) * t0 * t21 + T(2) * t0 * t20 * ab_ap - t0 * ap_ap * t19) + (T(1) / T(3465)) * t0 * t20 * in.w[2];
  const T g_factor = -T(11) * length;
  f = -(T(1) / T(315)) * (in.w[3] * t0 * (t0 * ap_ap * t18 + T(9) * (T(5) * t7 * t10 - ab_ap * t12 * t11 - T(5) * t6 * t1) * t0 - T(2) * t0 * t21 * ab_ap) - t0 * t21 * in.w[2] - t14 * in.w[0] * t11 - t0 * in.w[1] * t18) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 36 +, 71 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t7 * t6;
  const T t10 = t4 * t3;
  const T t11 = t5 * t3;
  const T t12 = t8 * t6;
  f = (T(1) / T(1280)) * t2 * (T(3) * t2 * (T(48) * a_minus_b * t5 + T(48) * ab_ap * t8 + T(7) * (T(5) * t2 * (T(2) * ab_ap * t7 + T(2) * a_minus_b * t4 + T(3) * t2 * (ab_ab * J2 + a_minus_b * t3 + ab_ap * t6) * ab_ab) * ab_ab + T(8) * ab_ap * t9 + T(8) * a_minus_b * t10) * t2 * ab_ab) * ab_ab + T(128) * a_minus_b * t11 + T(128) * ab_ap * t12) * in.w[0] * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 43 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = T(1) / bp_bp;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t9 * t8;
  const T t12 = t7 * t3;
  const T t13 = t10 * t8;
  const T t14 = t11 * t11;
  const T t15 = T(1280) * t6 * ab_ap + T(11) * (T(3) * t2 * ab_ab * (T(48) * t7 * ab_ap + T(48) * a_minus_b * t10 + T(7) * t2 * ab_ab * (T(8) * t5 * ab_ap + T(8) * a_minus_b * t11 + T(5) * (T(2) * a_minus_b * t9 + T(2) * t4 * ab_ap + T(3) * (t3 * ab_ap + ab_ab * J2 + a_minus_b * t8) * t2 * ab_ab) * t2 * ab_ab)) + T(128) * t12 * ab_ap + T(128) * a_minus_b * t13) * t2 * ab_ab + T(1280) * a_minus_b * t14;
  const T g_ap = (T(1) / T(15360)) * t2 * in.w[0] * t15;
  const T g_ab = (T(1) / T(15360)) * (T(1280) * t6 + t2 * t15 * ab_ap - T(1280) * t14) * in.w[0] / ab_ab;
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−12) dt
/// Operations: 43 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t4 * t3;
  const T t11 = t8 * t8;
  const T t12 = t11 * t7;
  const T t13 = T(128) * a_minus_b * t6 + T(3) * t2 * ab_ab * (T(48) * a_minus_b * t5 + T(7) * (T(8) * t9 * ab_ap + T(8) * a_minus_b * t10 + T(5) * (T(2) * a_minus_b * t4 + T(3) * t2 * ab_ab * (ab_ab * J2 + t7 * ab_ap + a_minus_b * t3) + T(2) * t8 * ab_ap) * t2 * ab_ab) * t2 * ab_ab + T(48) * t11 * ab_ap) + T(128) * t12 * ab_ap;
  const T t14 = t10 * t10;
  const T t15 = t9 * t9;
  const T t16 = T(11) * t2 * ab_ab * t13 + T(1280) * a_minus_b * t14 + T(1280) * t15 * ab_ap;
  const T g_ap = (T(1) / T(15360)) * t2 * t16 * in.w[0];
  const T g_ab = (T(1) / T(15360)) * in.w[0] * (T(1280) * t15 + t2 * t16 * ab_ap - T(1280) * t14) / ab_ab;
  const T g_factor = -T(12) * length;
  f = (T(1) / T(1280)) * t2 * in.w[0] * t13 * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 39 +, 76 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t8 * t7;
  const T t12 = t4 * t3;
  const T t13 = T(128) * t6 * a_minus_b + T(128) * t10 * ab_ap + T(3) * (T(48) * t5 * a_minus_b + T(48) * t9 * ab_ap + T(7) * t2 * ab_ab * (T(8) * t11 * ab_ap + T(8) * t12 * a_minus_b + T(5) * t2 * ab_ab * (T(3) * t2 * (t7 * ab_ap + J2 * ab_ab + t3 * a_minus_b) * ab_ab + T(2) * t4 * a_minus_b + T(2) * t8 * ab_ap))) * t2 * ab_ab;
  f = (T(1) / T(1280)) * (in.w[0] * t2 * t13 + (T(128) * t10 + ab_ap * t2 * t13 - T(128) * t6) * in.w[1] / ab_ab) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 47 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t4 * t4;
  const T t12 = t11 * t3;
  const T t13 = t8 * t8;
  const T t14 = t13 * t7;
  const T t15 = T(128) * a_minus_b * t12 + T(128) * t14 * ab_ap + T(3) * t2 * ab_ab * (T(48) * a_minus_b * t11 + T(7) * t2 * ab_ab * (T(8) * a_minus_b * t5 + T(5) * t2 * (T(2) * a_minus_b * t4 + T(3) * (ab_ab * J2 + t7 * ab_ap + a_minus_b * t3) * t2 * ab_ab + T(2) * t8 * ab_ap) * ab_ab + T(8) * t9 * ab_ap) + T(48) * t13 * ab_ap);
  const T t16 = T(1280) * a_minus_b * t6 + T(1280) * t10 * ab_ap + T(11) * t2 * t15 * ab_ab;
  const T t17 = T(1280) * t10 + t2 * t16 * ab_ap - T(1280) * t6;
  const T t18 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(15360)) * in.w[0] * t2 * t16 + (T(1) / T(15360)) * t17 * t18 * in.w[1];
  const T g_ab = (T(1) / T(15360)) * t18 * in.w[1] * (T(12) * t2 * t15 + T(2) * t17 * t18 * ab_ap - t2 * ap_ap * t16) + (T(1) / T(15360)) * in.w[0] * t17 * t18;
  const T g_factor = -T(12) * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−12) dt
/// Operations: 50 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = t3 * t3;
  const T t11 = t10 * t2;
  const T t12 = T(1) / cross_cross;
  const T t13 = t7 * t6;
  const T t14 = T(128) * t9 * a_minus_b + T(128) * t11 * ab_ap + T(3) * (T(48) * t8 * a_minus_b + T(48) * t10 * ab_ap + T(7) * t12 * (T(8) * t4 * ab_ap + T(8) * t13 * a_minus_b + T(5) * (T(3) * (t2 * ab_ap + t6 * a_minus_b + J2 * ab_ab) * t12 * ab_ab + T(2) * t7 * a_minus_b + T(2) * t3 * ab_ap) * t12 * ab_ab) * ab_ab) * t12 * ab_ab;
  const T t15 = t13 * t13;
  const T t16 = T(1280) * t5 * ab_ap + T(11) * t14 * t12 * ab_ab + T(1280) * t15 * a_minus_b;
  const T t17 = T(1280) * t5 + ab_ap * t16 * t12 - T(1280) * t15;
  const T t18 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(15360)) * in.w[0] * t16 * t12 + (T(1) / T(15360)) * t17 * t18 * in.w[1];
  const T g_ab = (T(1) / T(15360)) * t17 * in.w[0] * t18 + (T(1) / T(15360)) * (T(2) * t17 * ab_ap * t18 + T(12) * t14 * t12 - ap_ap * t16 * t12) * t18 * in.w[1];
  const T g_factor = -T(12) * length;
  f = (T(1) / T(1280)) * length * ((T(128) * t11 + ab_ap * t14 * t12 - T(128) * t9) * t18 * in.w[1] + t14 * in.w[0] * t12);
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 42 +, 89 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / cross_cross;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t3 * t2;
  const T t11 = t8 * t7;
  const T t12 = T(48) * t4 * a_minus_b + T(48) * ab_ap * t9 + T(7) * t6 * ab_ab * (T(8) * t10 * a_minus_b + T(5) * (T(2) * t3 * a_minus_b + T(3) * (ab_ab * J2 + ab_ap * t7 + t2 * a_minus_b) * t6 * ab_ab + T(2) * ab_ap * t8) * t6 * ab_ab + T(8) * ab_ap * t11);
  const T t13 = t9 * t7;
  const T t14 = T(128) * t5 * a_minus_b + T(3) * t6 * ab_ab * t12 + T(128) * ab_ap * t13;
  const T t15 = t14 * ab_ap * t6 + T(128) * t13 - T(128) * t5;
  const T t16 = T(1) / ab_ab;
  f = (T(1) / T(3840)) * length * (T(3) * in.w[1] * t15 * t16 + T(3) * t14 * t6 * in.w[0] + in.w[2] * t16 * (T(10) * t6 * t12 + T(6) * ab_ap * t15 * t16 - T(3) * t14 * t6 * ap_ap));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 53 +, 126 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t4 * t4;
  const T t12 = t11 * t3;
  const T t13 = t8 * t8;
  const T t14 = t13 * t7;
  const T t15 = T(128) * a_minus_b * t12 + T(128) * ab_ap * t14 + T(3) * (T(48) * a_minus_b * t11 + T(7) * t2 * ab_ab * (T(8) * ab_ap * t9 + T(8) * a_minus_b * t5 + T(5) * (T(2) * ab_ap * t8 + T(2) * a_minus_b * t4 + T(3) * (ab_ab * J2 + a_minus_b * t3 + ab_ap * t7) * t2 * ab_ab) * t2 * ab_ab) + T(48) * ab_ap * t13) * t2 * ab_ab;
  const T t16 = T(1280) * a_minus_b * t6 + T(1280) * ab_ap * t10 + T(11) * t2 * ab_ab * t15;
  const T t17 = T(1280) * t10 + ab_ap * t2 * t16 - T(1280) * t6;
  const T t18 = T(1) / ab_ab;
  const T t19 = T(12) * t2 * t15 + T(2) * ab_ap * t17 * t18 - t2 * t16 * ap_ap;
  const T g_ap = (T(1) / T(15360)) * t2 * t16 * in.w[0] + (T(1) / T(15360)) * t17 * in.w[1] * t18 + (T(1) / T(15360)) * t19 * t18 * in.w[2];
  const T g_ab = (T(1) / T(15360)) * t19 * in.w[1] * t18 + (T(1) / T(15360)) * t17 * t18 * in.w[0] - (T(1) / T(15360)) * (t17 * t18 * ap_ap - T(12) * t18 * (ab_ap * t2 * t15 + T(128) * t14 - T(128) * t12) - T(2) * ab_ap * t19 * t18) * t18 * in.w[2];
  const T g_factor = -T(12) * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−12) dt
/// Operations: 57 +, 144 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = T(1) / bp_bp;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = t5 * t4;
  const T t8 = t6 * t3;
  const T t9 = t6 * t6;
  const T t10 = t5 * t5;
  const T t11 = T(7) * t2 * (T(5) * (T(3) * t2 * (t3 * ab_ap + t4 * a_minus_b + ab_ab * J2) * ab_ab + T(2) * t5 * a_minus_b + T(2) * t6 * ab_ap) * t2 * ab_ab + T(8) * t7 * a_minus_b + T(8) * t8 * ab_ap) * ab_ab + T(48) * t9 * ab_ap + T(48) * t10 * a_minus_b;
  const T t12 = t9 * t3;
  const T t13 = t10 * t4;
  const T t14 = T(3) * t11 * t2 * ab_ab + T(128) * t12 * ab_ap + T(128) * t13 * a_minus_b;
  const T t15 = T(1) / ab_ab;
  const T t16 = t7 * t7;
  const T t17 = t8 * t8;
  const T t18 = T(1280) * t17 * ab_ap + T(1280) * t16 * a_minus_b + T(11) * t14 * t2 * ab_ab;
  const T t19 = T(1280) * t16 - T(1280) * t17 - ab_ap * t2 * t18;
  const T t20 = T(12) * t14 * t2 - T(2) * ab_ap * t15 * t19 - ap_ap * t2 * t18;
  const T g_ap = (T(1) / T(15360)) * in.w[2] * t20 * t15 + (T(1) / T(15360)) * t2 * in.w[0] * t18 - (T(1) / T(15360)) * t15 * in.w[1] * t19;
  const T t21 = T(128) * t12 + t14 * ab_ap * t2 - T(128) * t13;
  const T g_ab = (T(1) / T(15360)) * in.w[2] * t15 * (ap_ap * t15 * t19 + T(2) * ab_ap * t20 * t15 + T(12) * t21 * t15) + (T(1) / T(15360)) * t20 * t15 * in.w[1] - (T(1) / T(15360)) * in.w[0] * t15 * t19;
  const T g_factor = -T(12) * length;
  f = -(T(1) / T(3840)) * (in.w[2] * (T(3) * ap_ap * t14 * t2 - T(10) * t11 * t2 - T(6) * ab_ap * t21 * t15) * t15 - T(3) * t14 * t2 * in.w[0] - T(3) * t21 * t15 * in.w[1]) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 47 +, 103 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = T(1) / cross_cross;
  const T t12 = t4 * t3;
  const T t13 = t8 * t7;
  const T t14 = T(7) * t11 * ab_ab * (T(5) * (T(3) * t11 * (ab_ab * J2 + t3 * ab_ap + t7 * a_minus_b) * ab_ab + T(2) * t8 * a_minus_b + T(2) * t4 * ab_ap) * t11 * ab_ab + T(8) * t12 * ab_ap + T(8) * t13 * a_minus_b) + T(48) * t9 * a_minus_b + T(48) * t5 * ab_ap;
  const T t15 = T(128) * t10 * a_minus_b + T(128) * t6 * ab_ap + T(3) * t11 * ab_ab * t14;
  const T t16 = T(128) * t6 + t15 * ab_ap * t11 - T(128) * t10;
  const T t17 = T(10) * t11 * t14 + T(6) * ab_ap * t2 * t16 - T(3) * ap_ap * t15 * t11;
  f = (T(1) / T(3840)) * length * (T(3) * in.w[1] * t2 * t16 + (T(2) * ab_ap * t2 * t17 + T(10) * (T(48) * t5 + ab_ap * t11 * t14 - T(48) * t9) * t2 - T(3) * ap_ap * t2 * t16) * t2 * in.w[3] + T(3) * t15 * t11 * in.w[0] + in.w[2] * t2 * t17);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 59 +, 147 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i12_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t4 * t3;
  const T t11 = t8 * t8;
  const T t12 = T(48) * t5 * ab_ap + T(7) * ab_ab * (T(8) * t9 * a_minus_b + T(5) * ab_ab * (T(2) * t8 * a_minus_b + T(3) * ab_ab * t2 * (t3 * ab_ap + ab_ab * J2 + t7 * a_minus_b) + T(2) * t4 * ab_ap) * t2 + T(8) * t10 * ab_ap) * t2 + T(48) * t11 * a_minus_b;
  const T t13 = t11 * t7;
  const T t14 = T(128) * t6 * ab_ap + T(3) * ab_ab * t12 * t2 + T(128) * t13 * a_minus_b;
  const T t15 = t10 * t10;
  const T t16 = t9 * t9;
  const T t17 = T(11) * ab_ab * t14 * t2 + T(1280) * t15 * ab_ap + T(1280) * t16 * a_minus_b;
  const T t18 = T(1) / ab_ab;
  const T t19 = T(1280) * t15 + ab_ap * t2 * t17 - T(1280) * t16;
  const T t20 = T(12) * t14 * t2 + T(2) * t18 * t19 * ab_ap - ap_ap * t2 * t17;
  const T t21 = T(128) * t6 + ab_ap * t14 * t2 - T(128) * t13;
  const T t22 = t18 * ap_ap * t19 - T(12) * t18 * t21 - T(2) * t18 * t20 * ab_ap;
  const T g_ap = (T(1) / T(15360)) * t2 * t17 * in.w[0] + (T(1) / T(15360)) * t18 * in.w[1] * t19 + (T(1) / T(15360)) * t18 * t20 * in.w[2] - (T(1) / T(15360)) * t18 * t22 * in.w[3];
  const T g_ab = (T(1) / T(15360)) * t18 * in.w[3] * (T(4) * t18 * (T(10) * t12 * t2 + T(6) * t18 * t21 * ab_ap - T(3) * ap_ap * t14 * t2) - t18 * t20 * ap_ap - T(2) * t18 * t22 * ab_ap) + (T(1) / T(15360)) * t18 * t19 * in.w[0] + (T(1) / T(15360)) * t18 * t20 * in.w[1] - (T(1) / T(15360)) * t18 * t22 * in.w[2];
  const T g_factor = -T(12) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−12) dt
/// Operations: 66 +, 171 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i12_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / ap_ap;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t8 * t8;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t7;
  const T t12 = t3 * t3;
  const T t13 = T(48) * t11 * ab_ap + T(48) * a_minus_b * t12 + T(7) * (T(8) * t8 * ab_ap + T(5) * (T(2) * t7 * ab_ap + T(3) * (a_minus_b * t2 + t6 * ab_ap + J2 * ab_ab) * t10 * ab_ab + T(2) * a_minus_b * t3) * t10 * ab_ab + T(8) * a_minus_b * t4) * t10 * ab_ab;
  const T t14 = t11 * t6;
  const T t15 = t12 * t2;
  const T t16 = T(3) * t13 * t10 * ab_ab + T(128) * t14 * ab_ap + T(128) * a_minus_b * t15;
  const T t17 = T(1280) * a_minus_b * t5 + T(1280) * t9 * ab_ap + T(11) * t10 * t16 * ab_ab;
  const T t18 = T(1280) * t5 - t17 * ab_ap * t10 - T(1280) * t9;
  const T t19 = T(1) / ab_ab;
  const T t20 = T(12) * t10 * t16 - t17 * ap_ap * t10 - T(2) * ab_ap * t18 * t19;
  const T t21 = ab_ap * t10 * t16 + T(128) * t14 - T(128) * t15;
  const T t22 = T(2) * t20 * ab_ap * t19 + T(12) * t21 * t19 + ap_ap * t18 * t19;
  const T g_ap = (T(1) / T(15360)) * t17 * in.w[0] * t10 + (T(1) / T(15360)) * t20 * in.w[2] * t19 + (T(1) / T(15360)) * t22 * t19 * in.w[3] - (T(1) / T(15360)) * in.w[1] * t18 * t19;
  const T t23 = T(6) * ab_ap * t21 * t19 + T(10) * t13 * t10 - T(3) * ap_ap * t10 * t16;
  const T g_ab = (T(1) / T(15360)) * t22 * in.w[2] * t19 + (T(1) / T(15360)) * in.w[1] * t20 * t19 - (T(1) / T(15360)) * in.w[0] * t18 * t19 - (T(1) / T(15360)) * (ap_ap * t20 * t19 - T(2) * t22 * ab_ap * t19 - T(4) * t23 * t19) * t19 * in.w[3];
  const T g_factor = -T(12) * length;
  f = -(T(1) / T(3840)) * ((T(3) * ap_ap * t21 * t19 - T(10) * (t13 * ab_ap * t10 + T(48) * t11 - T(48) * t12) * t19 - T(2) * ab_ap * t23 * t19) * t19 * in.w[3] - T(3) * in.w[0] * t10 * t16 - in.w[2] * t23 * t19 - T(3) * in.w[1] * t21 * t19) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 35 +, 83 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t2 * t1;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t6;
  const T t12 = t8 * t6;
  f = (T(1) / T(693)) * in.w[0] * (T(63) * a_minus_b * t0 * t4 + T(2) * ab_ab * (T(35) * t8 * t5 * ab_ap + T(35) * a_minus_b * t0 * t3 + T(8) * ab_ab * (T(5) * a_minus_b * t0 * t9 + T(2) * ab_ab * (T(4) * ab_ab * (T(2) * (a_minus_b * t0 + t5 * ab_ap) * ab_ab * t10 + t6 * t5 * ab_ap + a_minus_b * t0 * t1) * t10 + T(3) * a_minus_b * t0 * t2 + T(3) * t7 * t5 * ab_ap) * t10 + T(5) * t11 * t5 * ab_ap) * t10) * t10 + T(63) * t12 * t5 * ab_ap) * length * t10;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 42 +, 111 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t8 * t8;
  const T t11 = t3 * t3;
  const T t12 = t11 * t2;
  const T t13 = t10 * t7;
  const T t14 = t9 * t9;
  const T t15 = T(231) * t5 * t1 * a_minus_b + T(4) * (T(2) * (T(8) * (T(5) * t4 * t1 * a_minus_b + T(2) * (T(4) * (ab_ap * t6 * t7 + t2 * t1 * a_minus_b + T(2) * (t1 * a_minus_b + ab_ap * t6) * t0 * ab_ab) * t0 * ab_ab + T(3) * t3 * t1 * a_minus_b + T(3) * ab_ap * t6 * t8) * t0 * ab_ab + T(5) * ab_ap * t6 * t9) * t0 * ab_ab + T(35) * ab_ap * t6 * t10 + T(35) * t11 * t1 * a_minus_b) * t0 * ab_ab + T(63) * t12 * t1 * a_minus_b + T(63) * ab_ap * t6 * t13) * t0 * ab_ab + T(231) * ab_ap * t6 * t14;
  const T g_ap = (T(1) / T(3003)) * t0 * in.w[0] * t15;
  const T g_ab = (T(1) / T(3003)) * in.w[0] * (T(231) * t6 * t14 + ab_ap * t0 * t15 - T(231) * t5 * t1) / ab_ab;
  const T g_factor = -T(13) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−13) dt
/// Operations: 42 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t6;
  const T t12 = t2 * t2;
  const T t13 = t12 * t1;
  const T t14 = T(63) * t9 * t5 * ab_ap + T(2) * (T(8) * ab_ab * (T(2) * ab_ab * (T(3) * a_minus_b * t2 * t0 + T(3) * t7 * t5 * ab_ap + T(4) * ab_ab * (a_minus_b * t1 * t0 + T(2) * (a_minus_b * t0 + t5 * ab_ap) * ab_ab * t10 + t6 * t5 * ab_ap) * t10) * t10 + T(5) * a_minus_b * t3 * t0 + T(5) * t11 * t5 * ab_ap) * t10 + T(35) * t8 * t5 * ab_ap + T(35) * a_minus_b * t12 * t0) * ab_ab * t10 + T(63) * a_minus_b * t13 * t0;
  const T t15 = t11 * t11;
  const T t16 = T(231) * a_minus_b * t4 * t0 + T(4) * ab_ab * t14 * t10 + T(231) * t15 * t5 * ab_ap;
  const T g_ap = (T(1) / T(3003)) * in.w[0] * t16 * t10;
  const T g_ab = (T(1) / T(3003)) * in.w[0] * (T(231) * t15 * t5 + t16 * ab_ap * t10 - T(231) * t4 * t0) / ab_ab;
  const T g_factor = -T(13) * length;
  f = (T(1) / T(693)) * in.w[0] * t14 * length * t10;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 38 +, 90 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t3 * t2;
  const T t12 = t8 * t7;
  const T t13 = T(63) * t1 * a_minus_b * t5 + T(63) * t6 * ab_ap * t10 + T(2) * (T(35) * t1 * a_minus_b * t4 + T(8) * (T(5) * t1 * a_minus_b * t11 + T(2) * t0 * ab_ab * (T(3) * t1 * a_minus_b * t3 + T(4) * t0 * ab_ab * (t6 * ab_ap * t7 + T(2) * t0 * (t6 * ab_ap + t1 * a_minus_b) * ab_ab + t1 * a_minus_b * t2) + T(3) * t6 * ab_ap * t8) + T(5) * t6 * ab_ap * t12) * t0 * ab_ab + T(35) * t6 * ab_ap * t9) * t0 * ab_ab;
  f = (T(1) / T(693)) * length * (t0 * t13 * in.w[0] + in.w[1] * (T(63) * t6 * t10 + ab_ap * t0 * t13 - T(63) * t1 * t5) / ab_ab);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 46 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = T(1) / cross_cross;
  const T t12 = t8 * t8;
  const T t13 = t12 * t7;
  const T t14 = t3 * t3;
  const T t15 = t14 * t2;
  const T t16 = T(63) * t6 * a_minus_b * t13 + T(2) * t11 * ab_ab * (T(35) * t6 * a_minus_b * t12 + T(35) * t14 * t1 * ab_ap + T(8) * t11 * (T(2) * t11 * (T(3) * t3 * t1 * ab_ap + T(3) * t6 * a_minus_b * t8 + T(4) * (T(2) * t11 * ab_ab * (t1 * ab_ap + t6 * a_minus_b) + t6 * a_minus_b * t7 + t2 * t1 * ab_ap) * t11 * ab_ab) * ab_ab + T(5) * t6 * a_minus_b * t9 + T(5) * t4 * t1 * ab_ap) * ab_ab) + T(63) * t15 * t1 * ab_ap;
  const T t17 = T(231) * t6 * a_minus_b * t10 + T(231) * t5 * t1 * ab_ap + T(4) * t11 * ab_ab * t16;
  const T t18 = T(231) * t5 * t1 + t17 * t11 * ab_ap - T(231) * t6 * t10;
  const T g_ap = (T(1) / T(3003)) * t0 * in.w[1] * t18 + (T(1) / T(3003)) * t17 * in.w[0] * t11;
  const T g_ab = (T(1) / T(3003)) * in.w[0] * t0 * t18 - (T(1) / T(9009)) * (T(3) * t17 * t11 * ap_ap - T(6) * t0 * ab_ap * t18 - T(13) * t11 * t16) * t0 * in.w[1];
  const T g_factor = -T(13) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−13) dt
/// Operations: 49 +, 138 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t8 * t8;
  const T t10 = T(1) / cross_cross;
  const T t11 = t2 * t2;
  const T t12 = t7 * t7;
  const T t13 = t11 * t1;
  const T t14 = t12 * t6;
  const T t15 = T(2) * ab_ab * (T(35) * t11 * t0 * ab_ap + T(8) * ab_ab * (T(2) * ab_ab * (T(4) * ab_ab * (T(2) * ab_ab * (t5 * a_minus_b + t0 * ab_ap) * t10 + t5 * a_minus_b * t6 + t1 * t0 * ab_ap) * t10 + T(3) * t2 * t0 * ab_ap + T(3) * t5 * a_minus_b * t7) * t10 + T(5) * t3 * t0 * ab_ap + T(5) * t5 * a_minus_b * t8) * t10 + T(35) * t5 * a_minus_b * t12) * t10 + T(63) * t13 * t0 * ab_ap + T(63) * t5 * a_minus_b * t14;
  const T t16 = T(231) * t4 * t0 * ab_ap + T(231) * t5 * a_minus_b * t9 + T(4) * ab_ab * t10 * t15;
  const T t17 = T(1) / ab_ab;
  const T t18 = T(231) * t5 * t9 - t16 * ab_ap * t10 - T(231) * t4 * t0;
  const T g_ap = (T(1) / T(3003)) * t16 * in.w[0] * t10 - (T(1) / T(3003)) * in.w[1] * t17 * t18;
  const T g_ab = -(T(1) / T(9009)) * in.w[1] * t17 * (T(3) * ap_ap * t16 * t10 + T(6) * t17 * t18 * ab_ap - T(13) * t10 * t15) - (T(1) / T(3003)) * t17 * t18 * in.w[0];
  const T g_factor = -T(13) * length;
  f = -(T(1) / T(693)) * (in.w[1] * t17 * (T(63) * t5 * t14 - ab_ap * t10 * t15 - T(63) * t13 * t0) - in.w[0] * t10 * t15) * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 41 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = T(1) / cross_cross;
  const T t10 = t3 * t2;
  const T t11 = t7 * t7;
  const T t12 = T(35) * t1 * a_minus_b * t4 + T(8) * ab_ab * (T(5) * t8 * ab_ap * t5 + T(2) * ab_ab * (T(4) * ab_ab * (t1 * a_minus_b * t2 + T(2) * ab_ab * (t1 * a_minus_b + ab_ap * t5) * t9 + t6 * ab_ap * t5) * t9 + T(3) * t7 * ab_ap * t5 + T(3) * t1 * a_minus_b * t3) * t9 + T(5) * t1 * a_minus_b * t10) * t9 + T(35) * t11 * ab_ap * t5;
  const T t13 = t11 * t6;
  const T t14 = t4 * t2;
  const T t15 = T(2) * ab_ab * t12 * t9 + T(63) * t13 * ab_ap * t5 + T(63) * t1 * a_minus_b * t14;
  const T t16 = t15 * ab_ap * t9 + T(63) * t13 * t5 - T(63) * t1 * t14;
  f = -(T(1) / T(3465)) * length * (t0 * in.w[2] * (T(5) * t15 * ap_ap * t9 - T(10) * t16 * t0 * ab_ap - T(11) * t12 * t9) - T(5) * t16 * t0 * in.w[1] - T(5) * t15 * in.w[0] * t9);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 52 +, 146 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t8 * t8;
  const T t10 = T(1) / cross_cross;
  const T t11 = t7 * t7;
  const T t12 = t11 * t6;
  const T t13 = t2 * t2;
  const T t14 = t13 * t1;
  const T t15 = T(63) * ab_ap * t12 * t5 + T(2) * t10 * ab_ab * (T(8) * (T(5) * t0 * a_minus_b * t3 + T(5) * ab_ap * t8 * t5 + T(2) * t10 * ab_ab * (T(3) * t0 * a_minus_b * t2 + T(3) * ab_ap * t7 * t5 + T(4) * t10 * ab_ab * (ab_ap * t6 * t5 + T(2) * t10 * ab_ab * (ab_ap * t5 + t0 * a_minus_b) + t0 * a_minus_b * t1))) * t10 * ab_ab + T(35) * ab_ap * t11 * t5 + T(35) * t0 * a_minus_b * t13) + T(63) * t0 * a_minus_b * t14;
  const T t16 = T(231) * t0 * a_minus_b * t4 + T(231) * ab_ap * t9 * t5 + T(4) * t10 * ab_ab * t15;
  const T t17 = T(231) * t9 * t5 + ab_ap * t16 * t10 - T(231) * t0 * t4;
  const T t18 = T(1) / ab_ab;
  const T t19 = T(3) * t16 * t10 * ap_ap - T(6) * ab_ap * t17 * t18 - T(13) * t10 * t15;
  const T g_ap = (T(1) / T(3003)) * t16 * t10 * in.w[0] + (T(1) / T(3003)) * t17 * t18 * in.w[1] - (T(1) / T(9009)) * in.w[2] * t18 * t19;
  const T g_ab = (T(1) / T(3003)) * t17 * t18 * in.w[0] - (T(1) / T(9009)) * t18 * t19 * in.w[1] - (T(1) / T(9009)) * in.w[2] * t18 * (T(3) * t17 * t18 * ap_ap + T(2) * ab_ap * t18 * t19 - T(13) * (T(63) * t12 * t5 + ab_ap * t10 * t15 - T(63) * t0 * t14) * t18);
  const T g_factor = -T(13) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−13) dt
/// Operations: 56 +, 164 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t3 * t3;
  const T t12 = t11 * t2;
  const T t13 = t8 * t8;
  const T t14 = t13 * t7;
  const T t15 = T(35) * t1 * a_minus_b * t11 + T(8) * (T(2) * (T(4) * t0 * ab_ab * (t6 * ab_ap * t7 + t1 * a_minus_b * t2 + T(2) * t0 * ab_ab * (t6 * ab_ap + t1 * a_minus_b)) + T(3) * t1 * a_minus_b * t3 + T(3) * t6 * ab_ap * t8) * t0 * ab_ab + T(5) * t1 * a_minus_b * t4 + T(5) * t6 * ab_ap * t9) * t0 * ab_ab + T(35) * t6 * ab_ap * t13;
  const T t16 = T(63) * t1 * a_minus_b * t12 + T(63) * t6 * ab_ap * t14 + T(2) * t15 * t0 * ab_ab;
  const T t17 = T(231) * t1 * a_minus_b * t5 + T(231) * t6 * ab_ap * t10 + T(4) * t0 * ab_ab * t16;
  const T t18 = T(1) / ab_ab;
  const T t19 = ab_ap * t0 * t17 + T(231) * t6 * t10 - T(231) * t1 * t5;
  const T t20 = T(13) * t0 * t16 + T(6) * ab_ap * t18 * t19 - T(3) * t0 * ap_ap * t17;
  const T g_ap = (T(1) / T(3003)) * t0 * in.w[0] * t17 + (T(1) / T(9009)) * t18 * in.w[2] * t20 + (T(1) / T(3003)) * in.w[1] * t18 * t19;
  const T t21 = T(63) * t6 * t14 + ab_ap * t0 * t16 - T(63) * t1 * t12;
  const T g_ab = (T(1) / T(9009)) * (T(2) * ab_ap * t18 * t20 + T(13) * t21 * t18 - T(3) * t18 * t19 * ap_ap) * t18 * in.w[2] + (T(1) / T(9009)) * in.w[1] * t18 * t20 + (T(1) / T(3003)) * t18 * t19 * in.w[0];
  const T g_factor = -T(13) * length;
  f = (T(1) / T(3465)) * (t18 * in.w[2] * (T(11) * t15 * t0 + T(10) * ab_ap * t21 * t18 - T(5) * t0 * t16 * ap_ap) + T(5) * in.w[1] * t21 * t18 + T(5) * t0 * t16 * in.w[0]) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 46 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / r0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t6;
  const T t9 = t7 * t7;
  const T t10 = t3 * t3;
  const T t11 = T(8) * t0 * ab_ab * (T(5) * t4 * t1 * a_minus_b + T(2) * (T(3) * t7 * ab_ap * t5 + T(3) * t3 * t1 * a_minus_b + T(4) * (t2 * t1 * a_minus_b + T(2) * (ab_ap * t5 + t1 * a_minus_b) * t0 * ab_ab + t6 * ab_ap * t5) * t0 * ab_ab) * t0 * ab_ab + T(5) * t8 * ab_ap * t5) + T(35) * t9 * ab_ap * t5 + T(35) * t10 * t1 * a_minus_b;
  const T t12 = t9 * t6;
  const T t13 = t10 * t2;
  const T t14 = T(2) * t0 * t11 * ab_ab + T(63) * t12 * ab_ap * t5 + T(63) * t13 * t1 * a_minus_b;
  const T t15 = T(1) / ab_ab;
  const T t16 = T(63) * t13 * t1 - T(63) * t12 * t5 - t14 * ab_ap * t0;
  const T t17 = T(10) * ab_ap * t15 * t16 + T(5) * ap_ap * t14 * t0 - T(11) * t0 * t11;
  f = (T(1) / T(3465)) * length * (T(5) * t14 * t0 * in.w[0] + (T(5) * ap_ap * t15 * t16 + T(11) * (ab_ap * t0 * t11 + T(35) * t9 * t5 - T(35) * t10 * t1) * t15 - T(2) * t17 * ab_ap * t15) * t15 * in.w[3] - T(5) * in.w[1] * t15 * t16 - t17 * in.w[2] * t15);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 58 +, 168 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i13_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t8 * t8;
  const T t12 = t11 * t7;
  const T t13 = t3 * t3;
  const T t14 = T(8) * (T(5) * t4 * t1 * a_minus_b + T(2) * t0 * ab_ab * (T(3) * t8 * t6 * ab_ap + T(4) * t0 * (t2 * t1 * a_minus_b + T(2) * t0 * (t6 * ab_ap + t1 * a_minus_b) * ab_ab + t7 * t6 * ab_ap) * ab_ab + T(3) * t3 * t1 * a_minus_b) + T(5) * t9 * t6 * ab_ap) * t0 * ab_ab + T(35) * t11 * t6 * ab_ap + T(35) * t13 * t1 * a_minus_b;
  const T t15 = t13 * t2;
  const T t16 = T(63) * t12 * t6 * ab_ap + T(2) * t14 * t0 * ab_ab + T(63) * t15 * t1 * a_minus_b;
  const T t17 = T(231) * t5 * t1 * a_minus_b + T(231) * t10 * t6 * ab_ap + T(4) * t0 * ab_ab * t16;
  const T t18 = T(1) / ab_ab;
  const T t19 = T(231) * t5 * t1 - T(231) * t10 * t6 - ab_ap * t0 * t17;
  const T t20 = T(13) * t0 * t16 - T(6) * ab_ap * t18 * t19 - T(3) * ap_ap * t0 * t17;
  const T t21 = T(63) * t15 * t1 - ab_ap * t0 * t16 - T(63) * t12 * t6;
  const T t22 = T(13) * t18 * t21 - T(3) * ap_ap * t18 * t19 - T(2) * ab_ap * t20 * t18;
  const T g_ap = (T(1) / T(3003)) * in.w[0] * t0 * t17 + (T(1) / T(9009)) * t20 * t18 * in.w[2] - (T(1) / T(9009)) * in.w[3] * t22 * t18 - (T(1) / T(3003)) * in.w[1] * t18 * t19;
  const T g_ab = (T(1) / T(9009)) * in.w[1] * t20 * t18 - (T(1) / T(3003)) * in.w[0] * t18 * t19 - (T(1) / T(9009)) * t22 * t18 * in.w[2] - (T(1) / T(45045)) * in.w[3] * (T(13) * (T(5) * ap_ap * t0 * t16 + T(10) * ab_ap * t18 * t21 - T(11) * t14 * t0) * t18 + T(10) * ab_ap * t22 * t18 + T(5) * ap_ap * t20 * t18) * t18;
  const T g_factor = -T(13) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−13) dt
/// Operations: 65 +, 194 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i13_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / cross_cross;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t9 * t8;
  const T t12 = t3 * t2;
  const T t13 = T(35) * t4 * t1 * ab_ap + T(35) * t7 * a_minus_b * t10 + T(8) * ab_ab * (T(5) * t7 * a_minus_b * t11 + T(2) * ab_ab * (T(4) * ab_ab * (T(2) * ab_ab * (t7 * a_minus_b + t1 * ab_ap) * t6 + t2 * t1 * ab_ap + t7 * a_minus_b * t8) * t6 + T(3) * t3 * t1 * ab_ap + T(3) * t7 * a_minus_b * t9) * t6 + T(5) * t12 * t1 * ab_ap) * t6;
  const T t14 = t10 * t8;
  const T t15 = T(63) * t5 * t1 * ab_ap + T(2) * ab_ab * t6 * t13 + T(63) * t7 * a_minus_b * t14;
  const T t16 = t12 * t12;
  const T t17 = t11 * t11;
  const T t18 = T(231) * t7 * a_minus_b * t17 + T(231) * t16 * t1 * ab_ap + T(4) * ab_ab * t15 * t6;
  const T t19 = T(231) * t16 * t1 + ab_ap * t6 * t18 - T(231) * t7 * t17;
  const T t20 = T(13) * t15 * t6 + T(6) * t0 * t19 * ab_ap - T(3) * ap_ap * t6 * t18;
  const T t21 = t15 * ab_ap * t6 + T(63) * t5 * t1 - T(63) * t7 * t14;
  const T t22 = T(2) * t0 * ab_ap * t20 + T(13) * t0 * t21 - T(3) * t0 * t19 * ap_ap;
  const T g_ap = (T(1) / T(9009)) * t0 * in.w[2] * t20 + (T(1) / T(3003)) * t0 * t19 * in.w[1] + (T(1) / T(3003)) * in.w[0] * t6 * t18 + (T(1) / T(9009)) * t0 * in.w[3] * t22;
  const T t23 = T(10) * t0 * ab_ap * t21 + T(11) * t6 * t13 - T(5) * ap_ap * t15 * t6;
  const T g_ab = (T(1) / T(3003)) * t0 * t19 * in.w[0] + (T(1) / T(9009)) * t0 * in.w[1] * t20 + (T(1) / T(9009)) * t0 * t22 * in.w[2] - (T(1) / T(45045)) * t0 * in.w[3] * (T(5) * t0 * ap_ap * t20 - T(13) * t0 * t23 - T(10) * t0 * t22 * ab_ap);
  const T g_factor = -T(13) * length;
  f = (T(1) / T(3465)) * (T(5) * in.w[0] * t15 * t6 + t0 * t23 * in.w[2] + T(5) * t0 * in.w[1] * t21 - t0 * in.w[3] * (T(11) * t0 * (T(35) * t7 * t10 - ab_ap * t6 * t13 - T(35) * t4 * t1) + T(5) * t0 * ap_ap * t21 - T(2) * t0 * t23 * ab_ap)) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 38 +, 80 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = t7 * t3;
  const T t9 = T(1) / bp_bp;
  const T t10 = t9 * t9;
  const T t11 = t10 * t10;
  const T t12 = t10 * t9;
  const T t13 = t11 * t9;
  const T t14 = t12 * t12;
  f = (T(1) / T(15360)) * t2 * (T(1280) * ab_ap * t6 + T(11) * t2 * ab_ab * (T(128) * ab_ap * t8 + T(3) * (T(48) * ab_ap * t7 + T(48) * t11 * a_minus_b + T(7) * t2 * ab_ab * (T(5) * t2 * (T(2) * ab_ap * t4 + T(2) * t10 * a_minus_b + T(3) * t2 * (t9 * a_minus_b + ab_ap * t3 + ab_ab * J2) * ab_ab) * ab_ab + T(8) * t12 * a_minus_b + T(8) * ab_ap * t5)) * t2 * ab_ab + T(128) * t13 * a_minus_b) + T(1280) * t14 * a_minus_b) * in.w[0] * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 45 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t4 * t3;
  const T t11 = t8 * t8;
  const T t12 = t11 * t7;
  const T t13 = t10 * t10;
  const T t14 = t9 * t9;
  const T t15 = t13 * t3;
  const T t16 = t14 * t7;
  const T t17 = T(13) * t2 * ab_ab * (T(11) * (T(128) * t6 * ab_ap + T(3) * (T(48) * t5 * ab_ap + T(7) * t2 * (T(8) * t9 * a_minus_b + T(5) * t2 * (T(2) * t8 * a_minus_b + T(3) * t2 * ab_ab * (t3 * ab_ap + t7 * a_minus_b + J2 * ab_ab) + T(2) * t4 * ab_ap) * ab_ab + T(8) * t10 * ab_ap) * ab_ab + T(48) * t11 * a_minus_b) * t2 * ab_ab + T(128) * t12 * a_minus_b) * t2 * ab_ab + T(1280) * t13 * ab_ap + T(1280) * t14 * a_minus_b) + T(15360) * t15 * ab_ap + T(15360) * t16 * a_minus_b;
  const T g_ap = (T(1) / T(215040)) * t17 * t2 * in.w[0];
  const T g_ab = (T(1) / T(215040)) * (T(15360) * t15 + t17 * ab_ap * t2 - T(15360) * t16) * in.w[0] / ab_ab;
  const T g_factor = -T(14) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−14) dt
/// Operations: 45 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = T(1) / bp_bp;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t9 * t8;
  const T t12 = t7 * t3;
  const T t13 = t10 * t8;
  const T t14 = t11 * t11;
  const T t15 = T(1280) * t6 * ab_ap + T(11) * (T(3) * (T(48) * t7 * ab_ap + T(48) * t10 * a_minus_b + T(7) * (T(5) * (T(3) * (t3 * ab_ap + J2 * ab_ab + t8 * a_minus_b) * t2 * ab_ab + T(2) * t9 * a_minus_b + T(2) * t4 * ab_ap) * t2 * ab_ab + T(8) * t11 * a_minus_b + T(8) * t5 * ab_ap) * t2 * ab_ab) * t2 * ab_ab + T(128) * t12 * ab_ap + T(128) * t13 * a_minus_b) * t2 * ab_ab + T(1280) * t14 * a_minus_b;
  const T t16 = t6 * t3;
  const T t17 = t14 * t8;
  const T t18 = T(13) * t15 * t2 * ab_ab + T(15360) * t16 * ab_ap + T(15360) * t17 * a_minus_b;
  const T g_ap = (T(1) / T(215040)) * t2 * t18 * in.w[0];
  const T g_ab = (T(1) / T(215040)) * (T(15360) * t16 + ab_ap * t2 * t18 - T(15360) * t17) * in.w[0] / ab_ab;
  const T g_factor = -T(14) * length;
  f = (T(1) / T(15360)) * t15 * length * t2 * in.w[0];
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 41 +, 85 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t4 * t3;
  const T t11 = t8 * t7;
  const T t12 = t9 * t7;
  const T t13 = t10 * t10;
  const T t14 = t11 * t11;
  const T t15 = T(11) * t2 * ab_ab * (T(128) * a_minus_b * t6 + T(3) * t2 * ab_ab * (T(48) * a_minus_b * t5 + T(48) * ab_ap * t9 + T(7) * t2 * ab_ab * (T(8) * a_minus_b * t10 + T(5) * t2 * ab_ab * (T(2) * a_minus_b * t4 + T(3) * t2 * (ab_ap * t7 + ab_ab * J2 + a_minus_b * t3) * ab_ab + T(2) * ab_ap * t8) + T(8) * ab_ap * t11)) + T(128) * ab_ap * t12) + T(1280) * a_minus_b * t13 + T(1280) * ab_ap * t14;
  f = (T(1) / T(15360)) * (t15 * t2 * in.w[0] + in.w[1] * (T(1280) * t14 + t15 * ab_ap * t2 - T(1280) * t13) / ab_ab) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 49 +, 118 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / cross_cross;
  const T t8 = t3 * t3;
  const T t9 = T(1) / bp_bp;
  const T t10 = t9 * t9;
  const T t11 = t10 * t10;
  const T t12 = t10 * t9;
  const T t13 = t8 * t2;
  const T t14 = t11 * t9;
  const T t15 = t12 * t12;
  const T t16 = T(1280) * t5 * ab_ap + T(11) * (T(3) * t7 * (T(48) * t8 * ab_ap + T(48) * t11 * a_minus_b + T(7) * (T(5) * (T(2) * t10 * a_minus_b + T(3) * (t2 * ab_ap + J2 * ab_ab + t9 * a_minus_b) * t7 * ab_ab + T(2) * t3 * ab_ap) * t7 * ab_ab + T(8) * t12 * a_minus_b + T(8) * t4 * ab_ap) * t7 * ab_ab) * ab_ab + T(128) * t13 * ab_ap + T(128) * t14 * a_minus_b) * t7 * ab_ab + T(1280) * t15 * a_minus_b;
  const T t17 = t15 * t9;
  const T t18 = T(15360) * t6 * ab_ap + T(13) * t16 * t7 * ab_ab + T(15360) * t17 * a_minus_b;
  const T t19 = T(15360) * t6 + ab_ap * t18 * t7 - T(15360) * t17;
  const T t20 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(215040)) * t19 * t20 * in.w[1] + (T(1) / T(215040)) * in.w[0] * t18 * t7;
  const T g_ab = (T(1) / T(215040)) * (T(14) * t16 * t7 + T(2) * t19 * ab_ap * t20 - ap_ap * t18 * t7) * t20 * in.w[1] + (T(1) / T(215040)) * t19 * in.w[0] * t20;
  const T g_factor = -T(14) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−14) dt
/// Operations: 52 +, 128 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t4 * t4;
  const T t12 = t11 * t3;
  const T t13 = t8 * t7;
  const T t14 = t13 * t13;
  const T t15 = T(1280) * t6 * ab_ap + T(11) * (T(128) * t10 * a_minus_b + T(128) * t12 * ab_ap + T(3) * t2 * (T(7) * (T(8) * t5 * ab_ap + T(5) * (T(2) * t8 * a_minus_b + T(2) * t4 * ab_ap + T(3) * t2 * (J2 * ab_ab + t3 * ab_ap + t7 * a_minus_b) * ab_ab) * t2 * ab_ab + T(8) * t13 * a_minus_b) * t2 * ab_ab + T(48) * t9 * a_minus_b + T(48) * t11 * ab_ap) * ab_ab) * t2 * ab_ab + T(1280) * t14 * a_minus_b;
  const T t16 = t6 * t3;
  const T t17 = t14 * t7;
  const T t18 = T(13) * t15 * t2 * ab_ab + T(15360) * t16 * ab_ap + T(15360) * t17 * a_minus_b;
  const T t19 = ab_ap * t2 * t18 + T(15360) * t16 - T(15360) * t17;
  const T t20 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(215040)) * t2 * t18 * in.w[0] + (T(1) / T(215040)) * in.w[1] * t19 * t20;
  const T g_ab = (T(1) / T(215040)) * t19 * t20 * in.w[0] - (T(1) / T(215040)) * in.w[1] * (ap_ap * t2 * t18 - T(14) * t15 * t2 - T(2) * t19 * ab_ap * t20) * t20;
  const T g_factor = -T(14) * length;
  f = (T(1) / T(15360)) * length * (in.w[1] * (T(1280) * t6 + t15 * ab_ap * t2 - T(1280) * t14) * t20 + t15 * t2 * in.w[0]);
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 44 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = T(1) / cross_cross;
  const T t11 = t8 * t7;
  const T t12 = t6 * t2;
  const T t13 = t9 * t7;
  const T t14 = T(3) * (T(48) * t6 * a_minus_b + T(48) * ab_ap * t9 + T(7) * (T(5) * (T(3) * t10 * ab_ab * (t2 * a_minus_b + ab_ab * J2 + ab_ap * t7) + T(2) * t3 * a_minus_b + T(2) * ab_ap * t8) * t10 * ab_ab + T(8) * t4 * a_minus_b + T(8) * ab_ap * t11) * t10 * ab_ab) * t10 * ab_ab + T(128) * t12 * a_minus_b + T(128) * ab_ap * t13;
  const T t15 = t11 * t11;
  const T t16 = T(1280) * t5 * a_minus_b + T(11) * t14 * t10 * ab_ab + T(1280) * ab_ap * t15;
  const T t17 = ab_ap * t16 * t10 + T(1280) * t15 - T(1280) * t5;
  const T t18 = T(1) / ab_ab;
  f = -(T(1) / T(15360)) * ((t16 * t10 * ap_ap - T(12) * t14 * t10 - T(2) * ab_ap * t17 * t18) * t18 * in.w[2] - in.w[0] * t16 * t10 - t17 * in.w[1] * t18) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 55 +, 135 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t6 * t3;
  const T t8 = t4 * t4;
  const T t9 = t8 * t3;
  const T t10 = T(1) / bp_bp;
  const T t11 = t10 * t10;
  const T t12 = t11 * t10;
  const T t13 = t11 * t11;
  const T t14 = t13 * t10;
  const T t15 = t12 * t12;
  const T t16 = T(1280) * ab_ap * t6 + T(11) * t2 * ab_ab * (T(128) * ab_ap * t9 + T(3) * t2 * (T(48) * ab_ap * t8 + T(7) * t2 * (T(8) * t12 * a_minus_b + T(5) * t2 * ab_ab * (T(2) * ab_ap * t4 + T(2) * t11 * a_minus_b + T(3) * t2 * ab_ab * (t10 * a_minus_b + ab_ap * t3 + ab_ab * J2)) + T(8) * ab_ap * t5) * ab_ab + T(48) * t13 * a_minus_b) * ab_ab + T(128) * t14 * a_minus_b) + T(1280) * t15 * a_minus_b;
  const T t17 = t15 * t10;
  const T t18 = T(15360) * ab_ap * t7 + T(13) * t2 * t16 * ab_ab + T(15360) * t17 * a_minus_b;
  const T t19 = T(1) / ab_ab;
  const T t20 = T(15360) * t17 - ab_ap * t2 * t18 - T(15360) * t7;
  const T t21 = t2 * t18 * ap_ap + T(2) * ab_ap * t19 * t20 - T(14) * t2 * t16;
  const T g_ap = (T(1) / T(215040)) * t2 * t18 * in.w[0] - (T(1) / T(215040)) * t21 * t19 * in.w[2] - (T(1) / T(215040)) * in.w[1] * t19 * t20;
  const T g_ab = -(T(1) / T(215040)) * t21 * in.w[1] * t19 - (T(1) / T(215040)) * t19 * t20 * in.w[0] - (T(1) / T(215040)) * t19 * in.w[2] * (T(14) * t19 * (T(1280) * t15 - ab_ap * t2 * t16 - T(1280) * t6) + T(2) * t21 * ab_ap * t19 - t19 * t20 * ap_ap);
  const T g_factor = -T(14) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−14) dt
/// Operations: 59 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t6 * t3;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(1) / bp_bp;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t11 * t11;
  const T t13 = t12 * t9;
  const T t14 = t4 * t4;
  const T t15 = t10 * t10;
  const T t16 = t14 * t3;
  const T t17 = t15 * t9;
  const T t18 = T(3) * t8 * ab_ab * (T(48) * t14 * ab_ap + T(7) * t8 * ab_ab * (T(8) * a_minus_b * t11 + T(5) * t8 * ab_ab * (T(2) * a_minus_b * t10 + T(2) * t4 * ab_ap + T(3) * t8 * (t3 * ab_ap + a_minus_b * t9 + ab_ab * J2) * ab_ab) + T(8) * t5 * ab_ap) + T(48) * a_minus_b * t15) + T(128) * t16 * ab_ap + T(128) * a_minus_b * t17;
  const T t19 = T(11) * t8 * ab_ab * t18 + T(1280) * t6 * ab_ap + T(1280) * a_minus_b * t12;
  const T t20 = T(15360) * t7 * ab_ap + T(15360) * a_minus_b * t13 + T(13) * t8 * ab_ab * t19;
  const T t21 = T(15360) * t7 + t8 * ab_ap * t20 - T(15360) * t13;
  const T t22 = t8 * ap_ap * t20 - T(14) * t8 * t19 - T(2) * t2 * t21 * ab_ap;
  const T g_ap = (T(1) / T(215040)) * in.w[1] * t2 * t21 + (T(1) / T(215040)) * t8 * in.w[0] * t20 - (T(1) / T(215040)) * t22 * t2 * in.w[2];
  const T t23 = T(1280) * t6 + t8 * t19 * ab_ap - T(1280) * t12;
  const T g_ab = (T(1) / T(215040)) * t2 * t21 * in.w[0] - (T(1) / T(215040)) * in.w[1] * t22 * t2 - (T(1) / T(215040)) * (T(2) * t22 * t2 * ab_ap + t2 * t21 * ap_ap - T(14) * t2 * t23) * t2 * in.w[2];
  const T g_factor = -T(14) * length;
  f = (T(1) / T(15360)) * (in.w[1] * t2 * t23 + t8 * t19 * in.w[0] + t2 * in.w[2] * (T(12) * t8 * t18 + T(2) * t2 * t23 * ab_ap - t8 * ap_ap * t19)) * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 49 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t3;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t4 * t3;
  const T t12 = t8 * t7;
  const T t13 = T(128) * ab_ap * t6 + T(128) * a_minus_b * t10 + T(3) * t2 * ab_ab * (T(7) * t2 * ab_ab * (T(8) * ab_ap * t11 + T(8) * a_minus_b * t12 + T(5) * (T(2) * ab_ap * t4 + T(3) * t2 * ab_ab * (a_minus_b * t7 + ab_ab * J2 + ab_ap * t3) + T(2) * a_minus_b * t8) * t2 * ab_ab) + T(48) * ab_ap * t5 + T(48) * a_minus_b * t9);
  const T t14 = t11 * t11;
  const T t15 = t12 * t12;
  const T t16 = T(11) * t2 * ab_ab * t13 + T(1280) * ab_ap * t14 + T(1280) * a_minus_b * t15;
  const T t17 = T(1) / ab_ab;
  const T t18 = T(1280) * t14 + ab_ap * t2 * t16 - T(1280) * t15;
  const T t19 = t2 * ap_ap * t16 - T(12) * t2 * t13 - T(2) * ab_ap * t17 * t18;
  f = (T(1) / T(15360)) * length * (t2 * in.w[0] * t16 + t17 * in.w[1] * t18 - (T(2) * ab_ap * t19 * t17 + t17 * ap_ap * t18 - T(12) * (T(128) * t6 + ab_ap * t2 * t13 - T(128) * t10) * t17) * t17 * in.w[3] - in.w[2] * t19 * t17);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 61 +, 155 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i14_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / ap_ap;
  const T t5 = t4 * t4;
  const T t6 = t5 * t4;
  const T t7 = t6 * t6;
  const T t8 = t5 * t5;
  const T t9 = t8 * t4;
  const T t10 = T(1) / bp_bp;
  const T t11 = t10 * t10;
  const T t12 = t11 * t10;
  const T t13 = t11 * t11;
  const T t14 = t13 * t10;
  const T t15 = T(128) * ab_ap * t9 + T(3) * t3 * ab_ab * (T(48) * ab_ap * t8 + T(7) * t3 * ab_ab * (T(8) * t12 * a_minus_b + T(8) * ab_ap * t6 + T(5) * t3 * ab_ab * (T(3) * (t10 * a_minus_b + ab_ap * t4 + ab_ab * J2) * t3 * ab_ab + T(2) * ab_ap * t5 + T(2) * t11 * a_minus_b)) + T(48) * t13 * a_minus_b) + T(128) * t14 * a_minus_b;
  const T t16 = t12 * t12;
  const T t17 = T(1280) * ab_ap * t7 + T(11) * t3 * ab_ab * t15 + T(1280) * t16 * a_minus_b;
  const T t18 = t7 * t4;
  const T t19 = t16 * t10;
  const T t20 = T(15360) * ab_ap * t18 + T(15360) * t19 * a_minus_b + T(13) * t3 * t17 * ab_ab;
  const T t21 = T(15360) * t19 - ab_ap * t3 * t20 - T(15360) * t18;
  const T t22 = T(14) * t3 * t17 - t3 * t20 * ap_ap - T(2) * ab_ap * t2 * t21;
  const T t23 = T(1280) * t16 - ab_ap * t3 * t17 - T(1280) * t7;
  const T t24 = T(2) * ab_ap * t2 * t22 + t2 * t21 * ap_ap - T(14) * t2 * t23;
  const T g_ap = (T(1) / T(215040)) * in.w[2] * t2 * t22 + (T(1) / T(215040)) * t24 * t2 * in.w[3] + (T(1) / T(215040)) * t3 * in.w[0] * t20 - (T(1) / T(215040)) * t2 * t21 * in.w[1];
  const T g_ab = (T(1) / T(215040)) * (T(2) * ab_ap * t24 * t2 - T(14) * (t3 * t17 * ap_ap + T(2) * ab_ap * t2 * t23 - T(12) * t3 * t15) * t2 - t2 * ap_ap * t22) * t2 * in.w[3] + (T(1) / T(215040)) * t2 * t22 * in.w[1] + (T(1) / T(215040)) * in.w[2] * t24 * t2 - (T(1) / T(215040)) * t2 * t21 * in.w[0];
  const T g_factor = -T(14) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−14) dt
/// Operations: 68 +, 176 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i14_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / cross_cross;
  const T t4 = T(1) / ap_ap;
  const T t5 = t4 * t4;
  const T t6 = t5 * t4;
  const T t7 = t6 * t6;
  const T t8 = T(1) / bp_bp;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = t10 * t10;
  const T t12 = t5 * t5;
  const T t13 = t9 * t9;
  const T t14 = t13 * t8;
  const T t15 = t12 * t4;
  const T t16 = T(3) * t3 * (T(48) * ab_ap * t12 + T(48) * t13 * a_minus_b + T(7) * t3 * ab_ab * (T(8) * t10 * a_minus_b + T(5) * (T(2) * t9 * a_minus_b + T(3) * (ab_ap * t4 + ab_ab * J2 + t8 * a_minus_b) * t3 * ab_ab + T(2) * ab_ap * t5) * t3 * ab_ab + T(8) * ab_ap * t6)) * ab_ab + T(128) * t14 * a_minus_b + T(128) * ab_ap * t15;
  const T t17 = T(1280) * ab_ap * t7 + T(1280) * t11 * a_minus_b + T(11) * t16 * t3 * ab_ab;
  const T t18 = ab_ap * t3 * t17 + T(1280) * t7 - T(1280) * t11;
  const T t19 = t11 * t8;
  const T t20 = t7 * t4;
  const T t21 = T(13) * t3 * ab_ab * t17 + T(15360) * ab_ap * t20 + T(15360) * t19 * a_minus_b;
  const T t22 = T(15360) * t19 - ab_ap * t3 * t21 - T(15360) * t20;
  const T t23 = T(14) * t3 * t17 - T(2) * t22 * ab_ap * t2 - t3 * t21 * ap_ap;
  const T t24 = T(14) * t2 * t18 + T(2) * ab_ap * t23 * t2 + t22 * t2 * ap_ap;
  const T g_ap = (T(1) / T(215040)) * t24 * t2 * in.w[3] + (T(1) / T(215040)) * t3 * t21 * in.w[0] + (T(1) / T(215040)) * in.w[2] * t23 * t2 - (T(1) / T(215040)) * in.w[1] * t22 * t2;
  const T t25 = T(12) * t16 * t3 + T(2) * ab_ap * t2 * t18 - t3 * t17 * ap_ap;
  const T g_ab = (T(1) / T(215040)) * t24 * in.w[2] * t2 + (T(1) / T(215040)) * (T(2) * t24 * ab_ap * t2 + T(14) * t2 * t25 - t23 * t2 * ap_ap) * t2 * in.w[3] + (T(1) / T(215040)) * in.w[1] * t23 * t2 - (T(1) / T(215040)) * t22 * t2 * in.w[0];
  const T g_factor = -T(14) * length;
  f = (T(1) / T(15360)) * (in.w[1] * t2 * t18 + in.w[2] * t2 * t25 + t3 * t17 * in.w[0] - (t2 * t18 * ap_ap + T(12) * t2 * (T(128) * t14 - ab_ap * t16 * t3 - T(128) * t15) - T(2) * ab_ap * t2 * t25) * t2 * in.w[3]) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (g_ap * ap1 - g_ab * ab1);
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 37 +, 94 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t8 * t7;
  const T t12 = t3 * t3;
  const T t13 = t12 * t2;
  const T t14 = t11 * t11;
  f = (T(1) / T(3003)) * length * t0 * in.w[0] * (T(231) * t5 * t1 * a_minus_b + T(4) * t0 * ab_ab * (T(63) * t10 * t6 * ab_ap + T(2) * (T(8) * t0 * ab_ab * (T(5) * t11 * t6 * ab_ap + T(5) * t4 * t1 * a_minus_b + T(2) * (T(4) * t0 * ab_ab * (t2 * t1 * a_minus_b + T(2) * (t6 * ab_ap + t1 * a_minus_b) * t0 * ab_ab + t7 * t6 * ab_ap) + T(3) * t8 * t6 * ab_ap + T(3) * t3 * t1 * a_minus_b) * t0 * ab_ab) + T(35) * t12 * t1 * a_minus_b + T(35) * t9 * t6 * ab_ap) * t0 * ab_ab + T(63) * t13 * t1 * a_minus_b) + T(231) * t14 * t6 * ab_ap);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 44 +, 122 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t8 * t8;
  const T t12 = t3 * t3;
  const T t13 = t11 * t7;
  const T t14 = t12 * t2;
  const T t15 = t10 * t7;
  const T t16 = t5 * t2;
  const T t17 = T(2) * t0 * (T(231) * t5 * t1 * ab_ap + T(231) * t6 * a_minus_b * t10 + T(4) * t0 * (T(2) * t0 * ab_ab * (T(35) * t6 * a_minus_b * t11 + T(8) * t0 * ab_ab * (T(5) * t4 * t1 * ab_ap + T(5) * t6 * a_minus_b * t9 + T(2) * t0 * (T(3) * t6 * a_minus_b * t8 + T(4) * t0 * ab_ab * (t2 * t1 * ab_ap + t6 * a_minus_b * t7 + T(2) * t0 * ab_ab * (t1 * ab_ap + t6 * a_minus_b)) + T(3) * t3 * t1 * ab_ap) * ab_ab) + T(35) * t12 * t1 * ab_ap) + T(63) * t6 * a_minus_b * t13 + T(63) * t14 * t1 * ab_ap) * ab_ab) * ab_ab + T(429) * t6 * a_minus_b * t15 + T(429) * t16 * t1 * ab_ap;
  const T g_ap = (T(1) / T(6435)) * t0 * t17 * in.w[0];
  const T g_ab = (T(1) / T(6435)) * in.w[0] * (t0 * t17 * ab_ap + T(429) * t16 * t1 - T(429) * t6 * t15) / ab_ab;
  const T g_factor = -T(15) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−15) dt
/// Operations: 44 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t7;
  const T t11 = t3 * t2;
  const T t12 = t8 * t7;
  const T t13 = t12 * t12;
  const T t14 = t11 * t11;
  const T t15 = T(4) * (T(63) * t5 * t1 * a_minus_b + T(63) * t10 * ab_ap * t6 + T(2) * (T(35) * t4 * t1 * a_minus_b + T(35) * t9 * ab_ap * t6 + T(8) * t0 * ab_ab * (T(5) * t11 * t1 * a_minus_b + T(5) * t12 * ab_ap * t6 + T(2) * t0 * ab_ab * (T(3) * t3 * t1 * a_minus_b + T(3) * t8 * ab_ap * t6 + T(4) * (T(2) * (ab_ap * t6 + t1 * a_minus_b) * t0 * ab_ab + t7 * ab_ap * t6 + t2 * t1 * a_minus_b) * t0 * ab_ab))) * t0 * ab_ab) * t0 * ab_ab + T(231) * t13 * ab_ap * t6 + T(231) * t14 * t1 * a_minus_b;
  const T t16 = t14 * t2;
  const T t17 = t13 * t7;
  const T t18 = T(2) * t15 * t0 * ab_ab + T(429) * t16 * t1 * a_minus_b + T(429) * t17 * ab_ap * t6;
  const T g_ap = (T(1) / T(6435)) * t0 * t18 * in.w[0];
  const T g_ab = (T(1) / T(6435)) * (ab_ap * t0 * t18 + T(429) * t17 * t6 - T(429) * t16 * t1) * in.w[0] / ab_ab;
  const T g_factor = -T(15) * length;
  f = (T(1) / T(3003)) * length * t15 * t0 * in.w[0];
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 40 +, 101 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / r0;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t2 * t2;
  const T t11 = t8 * t8;
  const T t12 = t10 * t1;
  const T t13 = t11 * t7;
  const T t14 = t9 * t9;
  const T t15 = T(231) * a_minus_b * t0 * t4 + T(4) * t5 * (T(2) * t5 * (T(8) * (T(5) * a_minus_b * t0 * t3 + T(2) * (T(4) * t5 * (T(2) * t5 * ab_ab * (a_minus_b * t0 + ab_ap * t6) + ab_ap * t6 * t7 + a_minus_b * t0 * t1) * ab_ab + T(3) * a_minus_b * t0 * t2 + T(3) * ab_ap * t6 * t8) * t5 * ab_ab + T(5) * ab_ap * t6 * t9) * t5 * ab_ab + T(35) * a_minus_b * t0 * t10 + T(35) * ab_ap * t6 * t11) * ab_ab + T(63) * a_minus_b * t0 * t12 + T(63) * ab_ap * t6 * t13) * ab_ab + T(231) * ab_ap * t6 * t14;
  f = (T(1) / T(3003)) * (t15 * in.w[0] * t5 - in.w[1] * (T(231) * t0 * t4 - T(231) * t6 * t14 - t15 * ab_ap * t5) / ab_ab) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 48 +, 137 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = t10 * t10;
  const T t12 = t11 * t8;
  const T t13 = t9 * t9;
  const T t14 = t13 * t8;
  const T t15 = t3 * t3;
  const T t16 = t15 * t2;
  const T t17 = T(4) * t0 * ab_ab * (T(63) * t7 * a_minus_b * t14 + T(2) * t0 * ab_ab * (T(35) * t7 * a_minus_b * t13 + T(8) * (T(5) * t7 * a_minus_b * t10 + T(5) * t4 * ab_ap * t1 + T(2) * t0 * ab_ab * (T(3) * t7 * a_minus_b * t9 + T(4) * t0 * (t2 * ab_ap * t1 + T(2) * (t7 * a_minus_b + ab_ap * t1) * t0 * ab_ab + t7 * a_minus_b * t8) * ab_ab + T(3) * t3 * ab_ap * t1)) * t0 * ab_ab + T(35) * t15 * ab_ap * t1) + T(63) * t16 * ab_ap * t1) + T(231) * t5 * ab_ap * t1 + T(231) * t7 * a_minus_b * t11;
  const T t18 = T(429) * t6 * ab_ap * t1 + T(429) * t7 * a_minus_b * t12 + T(2) * t0 * ab_ab * t17;
  const T t19 = T(1) / ab_ab;
  const T t20 = T(429) * t7 * t12 - T(429) * t6 * t1 - t0 * t18 * ab_ap;
  const T g_ap = (T(1) / T(6435)) * in.w[0] * t0 * t18 - (T(1) / T(6435)) * t19 * in.w[1] * t20;
  const T g_ab = -(T(1) / T(6435)) * in.w[0] * t19 * t20 - (T(1) / T(45045)) * t19 * in.w[1] * (T(14) * t19 * t20 * ab_ap + T(7) * t0 * t18 * ap_ap - T(15) * t0 * t17);
  const T g_factor = -T(15) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−15) dt
/// Operations: 51 +, 149 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = t9 * t9;
  const T t12 = t3 * t3;
  const T t13 = t11 * t8;
  const T t14 = t12 * t2;
  const T t15 = t10 * t10;
  const T t16 = T(4) * t0 * ab_ab * (T(2) * t0 * ab_ab * (T(8) * t0 * ab_ab * (T(5) * t4 * ab_ap * t1 + T(2) * t0 * ab_ab * (T(4) * t0 * ab_ab * (a_minus_b * t7 * t8 + t2 * ab_ap * t1 + T(2) * t0 * ab_ab * (ab_ap * t1 + a_minus_b * t7)) + T(3) * t3 * ab_ap * t1 + T(3) * a_minus_b * t7 * t9) + T(5) * a_minus_b * t7 * t10) + T(35) * a_minus_b * t7 * t11 + T(35) * t12 * ab_ap * t1) + T(63) * a_minus_b * t7 * t13 + T(63) * t14 * ab_ap * t1) + T(231) * t5 * ab_ap * t1 + T(231) * a_minus_b * t7 * t15;
  const T t17 = t15 * t8;
  const T t18 = T(429) * t6 * ab_ap * t1 + T(2) * t0 * ab_ab * t16 + T(429) * a_minus_b * t7 * t17;
  const T t19 = T(1) / ab_ab;
  const T t20 = T(429) * t7 * t17 - T(429) * t6 * t1 - t0 * t18 * ab_ap;
  const T g_ap = (T(1) / T(6435)) * t0 * t18 * in.w[0] - (T(1) / T(6435)) * t19 * in.w[1] * t20;
  const T g_ab = -(T(1) / T(45045)) * t19 * in.w[1] * (T(7) * t0 * t18 * ap_ap + T(14) * t19 * t20 * ab_ap - T(15) * t0 * t16) - (T(1) / T(6435)) * t19 * t20 * in.w[0];
  const T g_factor = -T(15) * length;
  f = (T(1) / T(3003)) * (t0 * t16 * in.w[0] - t19 * in.w[1] * (T(231) * t7 * t15 - t0 * t16 * ab_ap - T(231) * t5 * t1)) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 43 +, 114 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / cross_cross;
  const T t6 = T(1) / r1;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t2 * t2;
  const T t12 = t8 * t8;
  const T t13 = t12 * t7;
  const T t14 = t11 * t1;
  const T t15 = T(2) * t5 * ab_ab * (T(35) * t11 * t0 * ab_ap + T(35) * t6 * a_minus_b * t12 + T(8) * t5 * ab_ab * (T(2) * t5 * ab_ab * (T(3) * t6 * a_minus_b * t8 + T(4) * t5 * ab_ab * (T(2) * t5 * ab_ab * (t0 * ab_ap + t6 * a_minus_b) + t1 * t0 * ab_ap + t6 * a_minus_b * t7) + T(3) * t2 * t0 * ab_ap) + T(5) * t6 * a_minus_b * t9 + T(5) * t3 * t0 * ab_ap)) + T(63) * t6 * a_minus_b * t13 + T(63) * t14 * t0 * ab_ap;
  const T t16 = T(231) * t6 * a_minus_b * t10 + T(231) * t4 * t0 * ab_ap + T(4) * t5 * ab_ab * t15;
  const T t17 = T(231) * t4 * t0 + t5 * ab_ap * t16 - T(231) * t6 * t10;
  const T t18 = T(1) / ab_ab;
  f = (T(1) / T(9009)) * length * (T(3) * t17 * t18 * in.w[1] + t18 * in.w[2] * (T(6) * t17 * t18 * ab_ap + T(13) * t5 * t15 - T(3) * t5 * ap_ap * t16) + T(3) * t5 * in.w[0] * t16);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 54 +, 157 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / r1;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t9 * t8;
  const T t11 = t10 * t10;
  const T t12 = t9 * t9;
  const T t13 = t3 * t3;
  const T t14 = t12 * t8;
  const T t15 = t13 * t2;
  const T t16 = T(231) * a_minus_b * t11 * t7 + T(231) * t5 * ab_ap * t1 + T(4) * (T(2) * (T(35) * a_minus_b * t12 * t7 + T(8) * (T(5) * t4 * ab_ap * t1 + T(2) * (T(4) * (a_minus_b * t8 * t7 + t2 * ab_ap * t1 + T(2) * (a_minus_b * t7 + ab_ap * t1) * t0 * ab_ab) * t0 * ab_ab + T(3) * a_minus_b * t9 * t7 + T(3) * t3 * ab_ap * t1) * t0 * ab_ab + T(5) * a_minus_b * t10 * t7) * t0 * ab_ab + T(35) * t13 * ab_ap * t1) * t0 * ab_ab + T(63) * a_minus_b * t14 * t7 + T(63) * t15 * ab_ap * t1) * t0 * ab_ab;
  const T t17 = t11 * t8;
  const T t18 = T(429) * t6 * ab_ap * t1 + T(2) * t16 * t0 * ab_ab + T(429) * a_minus_b * t17 * t7;
  const T t19 = T(429) * t17 * t7 - ab_ap * t0 * t18 - T(429) * t6 * t1;
  const T t20 = T(1) / ab_ab;
  const T t21 = T(14) * ab_ap * t19 * t20 + T(7) * ap_ap * t0 * t18 - T(15) * t16 * t0;
  const T g_ap = (T(1) / T(6435)) * in.w[0] * t0 * t18 - (T(1) / T(45045)) * t21 * in.w[2] * t20 - (T(1) / T(6435)) * in.w[1] * t19 * t20;
  const T g_ab = -(T(1) / T(6435)) * t19 * in.w[0] * t20 - (T(1) / T(45045)) * in.w[1] * t21 * t20 - (T(1) / T(45045)) * (T(2) * t21 * ab_ap * t20 + T(15) * (T(231) * t11 * t7 - t16 * ab_ap * t0 - T(231) * t5 * t1) * t20 - T(7) * ap_ap * t19 * t20) * in.w[2] * t20;
  const T g_factor = -T(15) * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−15) dt
/// Operations: 58 +, 175 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t1;
  const T t5 = T(1) / r1;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t6;
  const T t10 = t2 * t1;
  const T t11 = T(1) / cross_cross;
  const T t12 = t7 * t6;
  const T t13 = T(63) * t4 * t0 * ab_ap + T(63) * t9 * t5 * a_minus_b + T(2) * ab_ab * (T(35) * t8 * t5 * a_minus_b + T(8) * ab_ab * (T(5) * t10 * t0 * ab_ap + T(2) * ab_ab * (T(4) * ab_ab * (t6 * t5 * a_minus_b + T(2) * ab_ab * (t5 * a_minus_b + t0 * ab_ap) * t11 + t1 * t0 * ab_ap) * t11 + T(3) * t2 * t0 * ab_ap + T(3) * t7 * t5 * a_minus_b) * t11 + T(5) * t12 * t5 * a_minus_b) * t11 + T(35) * t3 * t0 * ab_ap) * t11;
  const T t14 = t12 * t12;
  const T t15 = t10 * t10;
  const T t16 = T(4) * ab_ab * t13 * t11 + T(231) * t14 * t5 * a_minus_b + T(231) * t15 * t0 * ab_ap;
  const T t17 = t15 * t1;
  const T t18 = t14 * t6;
  const T t19 = T(2) * ab_ab * t16 * t11 + T(429) * t17 * t0 * ab_ap + T(429) * t18 * t5 * a_minus_b;
  const T t20 = T(1) / ab_ab;
  const T t21 = T(429) * t18 * t5 - ab_ap * t19 * t11 - T(429) * t17 * t0;
  const T t22 = T(15) * t16 * t11 - T(7) * ap_ap * t19 * t11 - T(14) * t20 * ab_ap * t21;
  const T g_ap = (T(1) / T(6435)) * in.w[0] * t19 * t11 + (T(1) / T(45045)) * t20 * in.w[2] * t22 - (T(1) / T(6435)) * t20 * in.w[1] * t21;
  const T t23 = T(231) * t14 * t5 - t16 * ab_ap * t11 - T(231) * t15 * t0;
  const T g_ab = (T(1) / T(45045)) * t20 * in.w[2] * (T(2) * t20 * ab_ap * t22 + T(7) * t20 * ap_ap * t21 - T(15) * t20 * t23) + (T(1) / T(45045)) * t20 * in.w[1] * t22 - (T(1) / T(6435)) * t20 * in.w[0] * t21;
  const T g_factor = -T(15) * length;
  f = (T(1) / T(9009)) * (t20 * in.w[2] * (T(13) * t13 * t11 - T(6) * t20 * t23 * ab_ap - T(3) * t16 * ap_ap * t11) + T(3) * t16 * in.w[0] * t11 - T(3) * t20 * t23 * in.w[1]) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 48 +, 130 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / cross_cross;
  const T t1 = T(1) / r0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = t6 * t2;
  const T t8 = T(1) / r1;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t10 * t10;
  const T t13 = t12 * t9;
  const T t14 = T(63) * t1 * ab_ap * t7 + T(2) * t0 * ab_ab * (T(35) * t1 * ab_ap * t6 + T(8) * t0 * ab_ab * (T(5) * t1 * ab_ap * t4 + T(5) * t8 * a_minus_b * t11 + T(2) * (T(4) * t0 * ab_ab * (T(2) * (t8 * a_minus_b + t1 * ab_ap) * t0 * ab_ab + t8 * a_minus_b * t9 + t1 * ab_ap * t2) + T(3) * t1 * ab_ap * t3 + T(3) * t8 * a_minus_b * t10) * t0 * ab_ab) + T(35) * t8 * a_minus_b * t12) + T(63) * t8 * a_minus_b * t13;
  const T t15 = t11 * t11;
  const T t16 = T(231) * t1 * ab_ap * t5 + T(4) * t0 * ab_ab * t14 + T(231) * t8 * a_minus_b * t15;
  const T t17 = ab_ap * t0 * t16 + T(231) * t1 * t5 - T(231) * t8 * t15;
  const T t18 = T(1) / ab_ab;
  const T t19 = T(3) * t0 * t16 * ap_ap - T(13) * t0 * t14 - T(6) * ab_ap * t17 * t18;
  f = (T(1) / T(9009)) * (T(3) * t17 * t18 * in.w[1] + T(3) * t0 * t16 * in.w[0] - in.w[2] * t18 * t19 - t18 * in.w[3] * (T(2) * ab_ap * t18 * t19 + T(13) * t18 * (T(63) * t8 * t13 - ab_ap * t0 * t14 - T(63) * t1 * t7) + T(3) * t17 * t18 * ap_ap)) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 60 +, 178 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i15_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / r0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t2 * t1;
  const T t4 = t3 * t3;
  const T t5 = t4 * t1;
  const T t6 = T(1) / cross_cross;
  const T t7 = t2 * t2;
  const T t8 = T(1) / r1;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t10 * t10;
  const T t12 = t10 * t9;
  const T t13 = t11 * t9;
  const T t14 = t7 * t1;
  const T t15 = T(2) * t6 * ab_ab * (T(35) * t7 * ab_ap * t0 + T(35) * a_minus_b * t11 * t8 + T(8) * t6 * (T(5) * a_minus_b * t12 * t8 + T(5) * t3 * ab_ap * t0 + T(2) * (T(3) * a_minus_b * t10 * t8 + T(4) * (t1 * ab_ap * t0 + a_minus_b * t9 * t8 + T(2) * t6 * ab_ab * (a_minus_b * t8 + ab_ap * t0)) * t6 * ab_ab + T(3) * t2 * ab_ap * t0) * t6 * ab_ab) * ab_ab) + T(63) * a_minus_b * t13 * t8 + T(63) * t14 * ab_ap * t0;
  const T t16 = t12 * t12;
  const T t17 = T(4) * t6 * t15 * ab_ab + T(231) * t4 * ab_ap * t0 + T(231) * a_minus_b * t16 * t8;
  const T t18 = t16 * t9;
  const T t19 = T(2) * t6 * t17 * ab_ab + T(429) * t5 * ab_ap * t0 + T(429) * a_minus_b * t18 * t8;
  const T t20 = T(429) * t5 * t0 + t19 * ab_ap * t6 - T(429) * t18 * t8;
  const T t21 = T(1) / ab_ab;
  const T t22 = T(14) * t20 * ab_ap * t21 + T(15) * t6 * t17 - T(7) * t19 * ap_ap * t6;
  const T t23 = T(231) * t4 * t0 + ab_ap * t6 * t17 - T(231) * t16 * t8;
  const T t24 = T(7) * ap_ap * t20 * t21 - T(2) * t22 * ab_ap * t21 - T(15) * t23 * t21;
  const T g_ap = (T(1) / T(45045)) * t22 * in.w[2] * t21 + (T(1) / T(6435)) * in.w[1] * t20 * t21 + (T(1) / T(6435)) * t19 * t6 * in.w[0] - (T(1) / T(45045)) * t24 * t21 * in.w[3];
  const T g_ab = (T(1) / T(45045)) * t22 * in.w[1] * t21 + (T(1) / T(6435)) * t20 * t21 * in.w[0] - (T(1) / T(45045)) * (ap_ap * t22 * t21 + T(2) * ab_ap * t24 * t21 - T(5) * (T(6) * t23 * ab_ap * t21 + T(13) * t6 * t15 - T(3) * ap_ap * t6 * t17) * t21) * t21 * in.w[3] - (T(1) / T(45045)) * in.w[2] * t24 * t21;
  const T g_factor = -T(15) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−15) dt
/// Operations: 67 +, 204 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_inverse_i15_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T r0 = sqrt(ap_ap);
  const T r1 = sqrt(bp_bp);
  const T t0 = T(1) / ab_ab;
  const T t1 = T(1) / cross_cross;
  const T t2 = T(1) / r1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t6 * t3;
  const T t8 = T(1) / r0;
  const T t9 = t8 * t8;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t11 * t11;
  const T t13 = t12 * t9;
  const T t14 = t4 * t4;
  const T t15 = t14 * t3;
  const T t16 = t10 * t10;
  const T t17 = t16 * t9;
  const T t18 = T(63) * a_minus_b * t2 * t15 + T(63) * t17 * t8 * ab_ap + T(2) * t1 * ab_ab * (T(35) * a_minus_b * t2 * t14 + T(8) * t1 * ab_ab * (T(5) * a_minus_b * t2 * t5 + T(5) * t11 * t8 * ab_ap + T(2) * t1 * (T(3) * t10 * t8 * ab_ap + T(3) * a_minus_b * t2 * t4 + T(4) * (T(2) * t1 * ab_ab * (t8 * ab_ap + a_minus_b * t2) + a_minus_b * t2 * t3 + t9 * t8 * ab_ap) * t1 * ab_ab) * ab_ab) + T(35) * t16 * t8 * ab_ap);
  const T t19 = T(231) * a_minus_b * t2 * t6 + T(4) * t1 * ab_ab * t18 + T(231) * t12 * t8 * ab_ap;
  const T t20 = T(429) * a_minus_b * t2 * t7 + T(429) * t13 * t8 * ab_ap + T(2) * t19 * t1 * ab_ab;
  const T t21 = t1 * t20 * ab_ap + T(429) * t13 * t8 - T(429) * t2 * t7;
  const T t22 = T(15) * t19 * t1 + T(14) * t0 * t21 * ab_ap - T(7) * t1 * t20 * ap_ap;
  const T t23 = T(231) * t2 * t6 - T(231) * t12 * t8 - t19 * t1 * ab_ap;
  const T t24 = T(15) * t23 * t0 + T(7) * t0 * t21 * ap_ap - T(2) * t0 * t22 * ab_ap;
  const T g_ap = (T(1) / T(6435)) * t0 * t21 * in.w[1] + (T(1) / T(45045)) * in.w[2] * t0 * t22 + (T(1) / T(6435)) * t1 * in.w[0] * t20 - (T(1) / T(45045)) * t24 * t0 * in.w[3];
  const T t25 = T(13) * t1 * t18 - T(6) * t23 * t0 * ab_ap - T(3) * t19 * t1 * ap_ap;
  const T g_ab = (T(1) / T(45045)) * t0 * t22 * in.w[1] + (T(1) / T(6435)) * t0 * t21 * in.w[0] - (T(1) / T(45045)) * t24 * in.w[2] * t0 - (T(1) / T(45045)) * (T(2) * t24 * t0 * ab_ap + t0 * t22 * ap_ap - T(5) * t0 * t25) * t0 * in.w[3];
  const T g_factor = -T(15) * length;
  f = -(T(1) / T(9009)) * (t0 * in.w[3] * (T(13) * t0 * (T(63) * t2 * t15 - t1 * t18 * ab_ap - T(63) * t17 * t8) - T(2) * t0 * t25 * ab_ap - T(3) * t23 * t0 * ap_ap) + T(3) * t23 * t0 * in.w[1] - T(3) * t19 * t1 * in.w[0] - in.w[2] * t0 * t25) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 40 +, 89 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T bp0 = in.p[0] - in.b[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T bp1 = in.p[1] - in.b[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T bp2 = in.p[2] - in.b[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t10 * t7;
  const T t12 = T(1) / cross_cross;
  const T t13 = t3 * t3;
  const T t14 = t13 * t2;
  const T t15 = t8 * t8;
  const T t16 = t15 * t7;
  f = (T(1) / T(215040)) * (T(15360) * t6 * ab_ap + T(15360) * t11 * a_minus_b + T(13) * (T(11) * t12 * (T(128) * t14 * ab_ap + T(128) * t16 * a_minus_b + T(3) * t12 * (T(7) * (T(5) * (T(2) * t8 * a_minus_b + T(3) * (t2 * ab_ap + t7 * a_minus_b + J2 * ab_ab) * t12 * ab_ab + T(2) * t3 * ab_ap) * t12 * ab_ab + T(8) * t9 * a_minus_b + T(8) * t4 * ab_ap) * t12 * ab_ab + T(48) * t13 * ab_ap + T(48) * t15 * a_minus_b) * ab_ab) * ab_ab + T(1280) * t5 * ab_ap + T(1280) * t10 * a_minus_b) * t12 * ab_ab) * length * t12 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 47 +, 112 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / bp_bp;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = T(1) / ap_ap;
  const T t6 = T(1) / cross_cross;
  const T t7 = t5 * t5;
  const T t8 = t7 * t5;
  const T t9 = t7 * t7;
  const T t10 = t3 * t3;
  const T t11 = t9 * t5;
  const T t12 = t10 * t2;
  const T t13 = t4 * t4;
  const T t14 = t8 * t8;
  const T t15 = t13 * t2;
  const T t16 = t14 * t5;
  const T t17 = t10 * t10;
  const T t18 = t9 * t9;
  const T t19 = ab_ab * (T(13) * ab_ab * (T(11) * ab_ab * (T(3) * ab_ab * (T(7) * ab_ab * (T(8) * t4 * a_minus_b + T(5) * ab_ab * (T(3) * ab_ab * (ab_ab * J2 + t2 * a_minus_b + t5 * ab_ap) * t6 + T(2) * t7 * ab_ap + T(2) * t3 * a_minus_b) * t6 + T(8) * t8 * ab_ap) * t6 + T(48) * t9 * ab_ap + T(48) * t10 * a_minus_b) * t6 + T(128) * t11 * ab_ap + T(128) * t12 * a_minus_b) * t6 + T(1280) * t13 * a_minus_b + T(1280) * t14 * ab_ap) * t6 + T(15360) * t15 * a_minus_b + T(15360) * t16 * ab_ap) * t6 + T(14336) * t17 * a_minus_b + T(14336) * t18 * ab_ap;
  const T g_ap = (T(1) / T(229376)) * in.w[0] * t19 * t6;
  const T g_ab = (T(1) / T(229376)) * in.w[0] * (T(14336) * t18 + t19 * ab_ap * t6 - T(14336) * t17) / ab_ab;
  const T g_factor = -T(16) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 |P − Γ(t)|^(−16) dt
/// Operations: 47 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t3;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = t7 * t3;
  const T t9 = T(1) / bp_bp;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t10 * t10;
  const T t13 = t12 * t9;
  const T t14 = t11 * t11;
  const T t15 = t6 * t3;
  const T t16 = t14 * t9;
  const T t17 = T(13) * (T(1280) * ab_ap * t6 + T(11) * (T(128) * ab_ap * t8 + T(3) * t2 * (T(7) * t2 * ab_ab * (T(5) * (T(2) * ab_ap * t4 + T(2) * t10 * a_minus_b + T(3) * t2 * ab_ab * (t9 * a_minus_b + ab_ab * J2 + ab_ap * t3)) * t2 * ab_ab + T(8) * t11 * a_minus_b + T(8) * ab_ap * t5) + T(48) * ab_ap * t7 + T(48) * t12 * a_minus_b) * ab_ab + T(128) * t13 * a_minus_b) * t2 * ab_ab + T(1280) * t14 * a_minus_b) * t2 * ab_ab + T(15360) * ab_ap * t15 + T(15360) * t16 * a_minus_b;
  const T t18 = t12 * t12;
  const T t19 = t7 * t7;
  const T t20 = t17 * t2 * ab_ab + T(14336) * t18 * a_minus_b + T(14336) * ab_ap * t19;
  const T g_ap = (T(1) / T(229376)) * in.w[0] * t2 * t20;
  const T g_ab = (T(1) / T(229376)) * in.w[0] * (ab_ap * t2 * t20 + T(14336) * t19 - T(14336) * t18) / ab_ab;
  const T g_factor = -T(16) * length;
  f = (T(1) / T(215040)) * t17 * in.w[0] * t2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 43 +, 94 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t2;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = T(1) / cross_cross;
  const T t10 = t7 * t6;
  const T t11 = t3 * t2;
  const T t12 = t8 * t6;
  const T t13 = t11 * t11;
  const T t14 = t10 * t10;
  const T t15 = t13 * t2;
  const T t16 = t14 * t6;
  const T t17 = T(13) * (T(11) * (T(128) * t5 * ab_ap + T(3) * (T(48) * t4 * ab_ap + T(48) * t8 * a_minus_b + T(7) * (T(5) * (T(2) * t7 * a_minus_b + T(2) * t3 * ab_ap + T(3) * (t2 * ab_ap + J2 * ab_ab + t6 * a_minus_b) * t9 * ab_ab) * t9 * ab_ab + T(8) * t10 * a_minus_b + T(8) * t11 * ab_ap) * t9 * ab_ab) * t9 * ab_ab + T(128) * t12 * a_minus_b) * t9 * ab_ab + T(1280) * t13 * ab_ap + T(1280) * t14 * a_minus_b) * t9 * ab_ab + T(15360) * t15 * ab_ap + T(15360) * t16 * a_minus_b;
  f = (T(1) / T(215040)) * length * (in.w[1] * (t17 * ab_ap * t9 + T(15360) * t15 - T(15360) * t16) / ab_ab + t17 * in.w[0] * t9);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 51 +, 127 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = T(1) / cross_cross;
  const T t7 = t3 * t2;
  const T t8 = t7 * t7;
  const T t9 = t8 * t2;
  const T t10 = T(1) / bp_bp;
  const T t11 = t10 * t10;
  const T t12 = t11 * t10;
  const T t13 = t12 * t12;
  const T t14 = t13 * t10;
  const T t15 = t11 * t11;
  const T t16 = t4 * t2;
  const T t17 = t15 * t10;
  const T t18 = T(15360) * ab_ap * t9 + T(15360) * t14 * a_minus_b + T(13) * (T(1280) * ab_ap * t8 + T(11) * t6 * (T(3) * t6 * (T(7) * (T(8) * ab_ap * t7 + T(8) * t12 * a_minus_b + T(5) * t6 * ab_ab * (T(2) * ab_ap * t3 + T(2) * t11 * a_minus_b + T(3) * t6 * ab_ab * (t10 * a_minus_b + ab_ab * J2 + ab_ap * t2))) * t6 * ab_ab + T(48) * ab_ap * t4 + T(48) * t15 * a_minus_b) * ab_ab + T(128) * ab_ap * t16 + T(128) * t17 * a_minus_b) * ab_ab + T(1280) * t13 * a_minus_b) * t6 * ab_ab;
  const T t19 = t15 * t15;
  const T t20 = t6 * ab_ab * t18 + T(14336) * t19 * a_minus_b + T(14336) * ab_ap * t5;
  const T t21 = T(14336) * t5 + ab_ap * t6 * t20 - T(14336) * t19;
  const T t22 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(229376)) * t21 * t22 * in.w[1] + (T(1) / T(229376)) * in.w[0] * t6 * t20;
  const T g_ab = (T(1) / T(229376)) * in.w[0] * t21 * t22 - (T(1) / T(3440640)) * (T(15) * t6 * t20 * ap_ap - T(16) * t6 * t18 - T(30) * ab_ap * t21 * t22) * t22 * in.w[1];
  const T g_factor = -T(16) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) |P − Γ(t)|^(−16) dt
/// Operations: 54 +, 137 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t3 * t2;
  const T t7 = t6 * t6;
  const T t8 = t7 * t2;
  const T t9 = T(1) / cross_cross;
  const T t10 = t4 * t2;
  const T t11 = T(1) / bp_bp;
  const T t12 = t11 * t11;
  const T t13 = t12 * t12;
  const T t14 = t12 * t11;
  const T t15 = t13 * t11;
  const T t16 = t14 * t14;
  const T t17 = t16 * t11;
  const T t18 = T(15360) * t8 * ab_ap + T(13) * t9 * (T(11) * (T(128) * t10 * ab_ap + T(3) * (T(48) * t4 * ab_ap + T(48) * t13 * a_minus_b + T(7) * (T(8) * t14 * a_minus_b + T(5) * t9 * (T(2) * t12 * a_minus_b + T(3) * (J2 * ab_ab + t2 * ab_ap + t11 * a_minus_b) * t9 * ab_ab + T(2) * t3 * ab_ap) * ab_ab + T(8) * t6 * ab_ap) * t9 * ab_ab) * t9 * ab_ab + T(128) * t15 * a_minus_b) * t9 * ab_ab + T(1280) * t7 * ab_ap + T(1280) * t16 * a_minus_b) * ab_ab + T(15360) * t17 * a_minus_b;
  const T t19 = t13 * t13;
  const T t20 = T(14336) * t5 * ab_ap + t18 * t9 * ab_ab + T(14336) * t19 * a_minus_b;
  const T t21 = T(14336) * t19 - T(14336) * t5 - t20 * ab_ap * t9;
  const T t22 = T(1) / ab_ab;
  const T g_ap = (T(1) / T(229376)) * t20 * in.w[0] * t9 - (T(1) / T(229376)) * in.w[1] * t21 * t22;
  const T g_ab = -(T(1) / T(3440640)) * in.w[1] * (T(15) * ap_ap * t20 * t9 + T(30) * ab_ap * t21 * t22 - T(16) * t18 * t9) * t22 - (T(1) / T(229376)) * in.w[0] * t21 * t22;
  const T g_factor = -T(16) * length;
  f = (T(1) / T(215040)) * length * (in.w[1] * (T(15360) * t8 + t18 * ab_ap * t9 - T(15360) * t17) * t22 + t18 * in.w[0] * t9);
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 46 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t5 * t2;
  const T t7 = T(1) / bp_bp;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t10 * t7;
  const T t12 = T(1) / cross_cross;
  const T t13 = t8 * t8;
  const T t14 = t13 * t7;
  const T t15 = t3 * t3;
  const T t16 = t15 * t2;
  const T t17 = T(1280) * t5 * ab_ap + T(1280) * t10 * a_minus_b + T(11) * t12 * (T(128) * t14 * a_minus_b + T(128) * t16 * ab_ap + T(3) * (T(48) * t13 * a_minus_b + T(7) * t12 * (T(8) * t4 * ab_ap + T(5) * t12 * (T(3) * (t2 * ab_ap + t7 * a_minus_b + ab_ab * J2) * t12 * ab_ab + T(2) * t8 * a_minus_b + T(2) * t3 * ab_ap) * ab_ab + T(8) * t9 * a_minus_b) * ab_ab + T(48) * t15 * ab_ap) * t12 * ab_ab) * ab_ab;
  const T t18 = T(15360) * t6 * ab_ap + T(15360) * t11 * a_minus_b + T(13) * t12 * t17 * ab_ab;
  const T t19 = T(15360) * t6 + t18 * ab_ap * t12 - T(15360) * t11;
  const T t20 = T(1) / ab_ab;
  f = (T(1) / T(215040)) * (t19 * in.w[1] * t20 + (T(14) * t12 * t17 + T(2) * t19 * ab_ap * t20 - ap_ap * t18 * t12) * in.w[2] * t20 + in.w[0] * t18 * t12) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 57 +, 145 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = T(1) / bp_bp;
  const T t7 = t6 * t6;
  const T t8 = t7 * t7;
  const T t9 = t8 * t8;
  const T t10 = t3 * t2;
  const T t11 = t10 * t10;
  const T t12 = t11 * t2;
  const T t13 = t7 * t6;
  const T t14 = t13 * t13;
  const T t15 = t14 * t6;
  const T t16 = t4 * t2;
  const T t17 = t8 * t6;
  const T t18 = T(1) / cross_cross;
  const T t19 = T(15360) * ab_ap * t12 + T(15360) * t15 * a_minus_b + T(13) * (T(1280) * ab_ap * t11 + T(1280) * t14 * a_minus_b + T(11) * (T(128) * ab_ap * t16 + T(128) * t17 * a_minus_b + T(3) * t18 * ab_ab * (T(48) * ab_ap * t4 + T(48) * t8 * a_minus_b + T(7) * t18 * ab_ab * (T(8) * ab_ap * t10 + T(8) * t13 * a_minus_b + T(5) * t18 * ab_ab * (T(2) * ab_ap * t3 + T(3) * t18 * ab_ab * (t6 * a_minus_b + ab_ap * t2 + ab_ab * J2) + T(2) * t7 * a_minus_b)))) * t18 * ab_ab) * t18 * ab_ab;
  const T t20 = T(14336) * t9 * a_minus_b + t19 * t18 * ab_ab + T(14336) * ab_ap * t5;
  const T t21 = T(14336) * t5 + t20 * ab_ap * t18 - T(14336) * t9;
  const T t22 = T(1) / ab_ab;
  const T t23 = T(30) * t21 * ab_ap * t22 + T(16) * t19 * t18 - T(15) * t20 * t18 * ap_ap;
  const T g_ap = (T(1) / T(3440640)) * t23 * t22 * in.w[2] + (T(1) / T(229376)) * t21 * in.w[1] * t22 + (T(1) / T(229376)) * t20 * t18 * in.w[0];
  const T g_ab = (T(1) / T(229376)) * t21 * t22 * in.w[0] + (T(1) / T(3440640)) * t23 * in.w[1] * t22 - (T(1) / T(3440640)) * (T(15) * t21 * t22 * ap_ap - T(2) * t23 * ab_ap * t22 - T(16) * (ab_ap * t19 * t18 + T(15360) * t12 - T(15360) * t15) * t22) * t22 * in.w[2];
  const T g_factor = -T(16) * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) |P − Γ(t)|^(−16) dt
/// Operations: 61 +, 160 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = T(1) / ap_ap;
  const T t8 = t7 * t7;
  const T t9 = t8 * t7;
  const T t10 = t9 * t9;
  const T t11 = t10 * t7;
  const T t12 = t8 * t8;
  const T t13 = t4 * t3;
  const T t14 = t12 * t7;
  const T t15 = t5 * t3;
  const T t16 = t13 * t13;
  const T t17 = T(11) * t2 * (T(3) * t2 * ab_ab * (T(48) * ab_ap * t12 + T(48) * a_minus_b * t5 + T(7) * t2 * (T(5) * t2 * (T(3) * t2 * ab_ab * (a_minus_b * t3 + ab_ap * t7 + ab_ab * J2) + T(2) * ab_ap * t8 + T(2) * a_minus_b * t4) * ab_ab + T(8) * ab_ap * t9 + T(8) * a_minus_b * t13) * ab_ab) + T(128) * ab_ap * t14 + T(128) * a_minus_b * t15) * ab_ab + T(1280) * ab_ap * t10 + T(1280) * a_minus_b * t16;
  const T t18 = t16 * t3;
  const T t19 = T(15360) * ab_ap * t11 + T(13) * t2 * t17 * ab_ab + T(15360) * a_minus_b * t18;
  const T t20 = t12 * t12;
  const T t21 = T(14336) * a_minus_b * t6 + t2 * ab_ab * t19 + T(14336) * ab_ap * t20;
  const T t22 = T(1) / ab_ab;
  const T t23 = T(14336) * t6 - ab_ap * t2 * t21 - T(14336) * t20;
  const T t24 = T(30) * ab_ap * t22 * t23 + T(15) * t2 * t21 * ap_ap - T(16) * t2 * t19;
  const T g_ap = (T(1) / T(229376)) * t2 * t21 * in.w[0] - (T(1) / T(229376)) * in.w[1] * t22 * t23 - (T(1) / T(3440640)) * t24 * in.w[2] * t22;
  const T t25 = T(15360) * t11 + ab_ap * t2 * t19 - T(15360) * t18;
  const T g_ab = (T(1) / T(3440640)) * (T(15) * t22 * t23 * ap_ap + T(16) * t25 * t22 - T(2) * ab_ap * t24 * t22) * in.w[2] * t22 - (T(1) / T(229376)) * t22 * t23 * in.w[0] - (T(1) / T(3440640)) * in.w[1] * t24 * t22;
  const T g_factor = -T(16) * length;
  f = (T(1) / T(215040)) * (t2 * in.w[0] * t19 + in.w[1] * t25 * t22 - in.w[2] * t22 * (t2 * ap_ap * t19 - T(2) * ab_ap * t25 * t22 - T(14) * t2 * t17)) * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 51 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / ap_ap;
  const T t3 = t2 * t2;
  const T t4 = t3 * t2;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = t6 * t2;
  const T t8 = T(1) / cross_cross;
  const T t9 = T(1) / bp_bp;
  const T t10 = t9 * t9;
  const T t11 = t10 * t9;
  const T t12 = t10 * t10;
  const T t13 = t12 * t9;
  const T t14 = t11 * t11;
  const T t15 = T(1280) * t5 * ab_ap + T(11) * ab_ab * (T(128) * t7 * ab_ap + T(3) * ab_ab * (T(7) * ab_ab * t8 * (T(5) * ab_ab * (T(3) * (a_minus_b * t9 + t2 * ab_ap + ab_ab * J2) * ab_ab * t8 + T(2) * t3 * ab_ap + T(2) * a_minus_b * t10) * t8 + T(8) * a_minus_b * t11 + T(8) * t4 * ab_ap) + T(48) * t6 * ab_ap + T(48) * a_minus_b * t12) * t8 + T(128) * a_minus_b * t13) * t8 + T(1280) * a_minus_b * t14;
  const T t16 = t5 * t2;
  const T t17 = t14 * t9;
  const T t18 = T(13) * ab_ab * t15 * t8 + T(15360) * t16 * ab_ap + T(15360) * a_minus_b * t17;
  const T t19 = T(1) / ab_ab;
  const T t20 = ab_ap * t18 * t8 + T(15360) * t16 - T(15360) * t17;
  const T t21 = T(2) * t19 * t20 * ab_ap + T(14) * t15 * t8 - ap_ap * t18 * t8;
  f = (T(1) / T(215040)) * length * (in.w[0] * t18 * t8 + t19 * (T(2) * t19 * t21 * ab_ap + T(14) * t19 * (t15 * ab_ap * t8 + T(1280) * t5 - T(1280) * t14) - t19 * t20 * ap_ap) * in.w[3] + t19 * in.w[2] * t21 + t19 * t20 * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 63 +, 165 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_inverse_i16_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = atan2(t0, ap_bp) * t1;
  const T t2 = T(1) / ab_ab;
  const T t3 = T(1) / ap_ap;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t4 * t3;
  const T t8 = T(1) / bp_bp;
  const T t9 = t8 * t8;
  const T t10 = T(1) / cross_cross;
  const T t11 = t9 * t8;
  const T t12 = t9 * t9;
  const T t13 = t12 * t8;
  const T t14 = t5 * t3;
  const T t15 = t11 * t11;
  const T t16 = t7 * t7;
  const T t17 = T(11) * ab_ab * (T(3) * (T(7) * ab_ab * (T(8) * t7 * ab_ap + T(5) * (T(2) * t4 * ab_ap + T(2) * a_minus_b * t9 + T(3) * (ab_ab * J2 + a_minus_b * t8 + t3 * ab_ap) * ab_ab * t10) * ab_ab * t10 + T(8) * a_minus_b * t11) * t10 + T(48) * a_minus_b * t12 + T(48) * t5 * ab_ap) * ab_ab * t10 + T(128) * a_minus_b * t13 + T(128) * t14 * ab_ap) * t10 + T(1280) * a_minus_b * t15 + T(1280) * t16 * ab_ap;
  const T t18 = t15 * t8;
  const T t19 = t16 * t3;
  const T t20 = T(13) * t17 * ab_ab * t10 + T(15360) * a_minus_b * t18 + T(15360) * t19 * ab_ap;
  const T t21 = t12 * t12;
  const T t22 = ab_ab * t20 * t10 + T(14336) * a_minus_b * t21 + T(14336) * t6 * ab_ap;
  const T t23 = T(14336) * t6 + t22 * ab_ap * t10 - T(14336) * t21;
  const T t24 = T(16) * t20 * t10 + T(30) * t2 * t23 * ab_ap - T(15) * t22 * ap_ap * t10;
  const T t25 = ab_ap * t20 * t10 + T(15360) * t19 - T(15360) * t18;
  const T t26 = T(2) * t2 * t24 * ab_ap + T(16) * t2 * t25 - T(15) * t2 * t23 * ap_ap;
  const T g_ap = (T(1) / T(229376)) * t2 * t23 * in.w[1] + (T(1) / T(3440640)) * in.w[3] * t2 * t26 + (T(1) / T(3440640)) * t2 * in.w[2] * t24 + (T(1) / T(229376)) * in.w[0] * t22 * t10;
  const T g_ab = (T(1) / T(3440640)) * t2 * in.w[1] * t24 + (T(1) / T(229376)) * in.w[0] * t2 * t23 + (T(1) / T(3440640)) * t2 * t26 * in.w[2] - (T(1) / T(3440640)) * in.w[3] * t2 * (T(16) * (ap_ap * t20 * t10 - T(2) * t2 * t25 * ab_ap - T(14) * t17 * t10) * t2 + t2 * ap_ap * t24 - T(2) * t2 * t26 * ab_ap);
  const T g_factor = -T(16) * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P − Γ(t)|^(−16) dt
/// Operations: 70 +, 186 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
T segment_inverse_i16_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a_minus_b = -ab_bp;
  const T t0 = sqrt(cross_cross);
  const T t1 = T(1) / t0;
  const T J2 = t1 * atan2(t0, ap_bp);
  const T t2 = T(1) / cross_cross;
  const T t3 = T(1) / bp_bp;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t5 * t5;
  const T t7 = t4 * t3;
  const T t8 = t7 * t7;
  const T t9 = t8 * t3;
  const T t10 = T(1) / ap_ap;
  const T t11 = t10 * t10;
  const T t12 = t11 * t10;
  const T t13 = t12 * t12;
  const T t14 = t13 * t10;
  const T t15 = t5 * t3;
  const T t16 = t11 * t11;
  const T t17 = t16 * t10;
  const T t18 = T(11) * t2 * ab_ab * (T(128) * a_minus_b * t15 + T(3) * t2 * ab_ab * (T(48) * a_minus_b * t5 + T(48) * ab_ap * t16 + T(7) * t2 * ab_ab * (T(8) * ab_ap * t12 + T(5) * t2 * ab_ab * (T(2) * ab_ap * t11 + T(2) * a_minus_b * t4 + T(3) * t2 * ab_ab * (ab_ab * J2 + a_minus_b * t3 + ab_ap * t10)) + T(8) * a_minus_b * t7)) + T(128) * ab_ap * t17) + T(1280) * a_minus_b * t8 + T(1280) * ab_ap * t13;
  const T t19 = T(15360) * a_minus_b * t9 + T(15360) * ab_ap * t14 + T(13) * t2 * ab_ab * t18;
  const T t20 = t16 * t16;
  const T t21 = T(14336) * a_minus_b * t6 + t2 * ab_ab * t19 + T(14336) * ab_ap * t20;
  const T t22 = T(1) / ab_ab;
  const T t23 = ab_ap * t2 * t21 + T(14336) * t20 - T(14336) * t6;
  const T t24 = T(30) * ab_ap * t23 * t22 + T(16) * t2 * t19 - T(15) * t2 * t21 * ap_ap;
  const T t25 = T(15360) * t14 + ab_ap * t2 * t19 - T(15360) * t9;
  const T t26 = T(15) * t23 * t22 * ap_ap - T(2) * ab_ap * t22 * t24 - T(16) * t22 * t25;
  const T g_ap = (T(1) / T(229376)) * t2 * t21 * in.w[0] + (T(1) / T(3440640)) * t22 * t24 * in.w[2] + (T(1) / T(229376)) * t23 * t22 * in.w[1] - (T(1) / T(3440640)) * t26 * t22 * in.w[3];
  const T t27 = T(2) * ab_ap * t22 * t25 + T(14) * t2 * t18 - t2 * t19 * ap_ap;
  const T g_ab = (T(1) / T(3440640)) * t22 * in.w[1] * t24 + (T(1) / T(3440640)) * t22 * in.w[3] * (T(16) * t22 * t27 - T(2) * ab_ap * t26 * t22 - t22 * ap_ap * t24) + (T(1) / T(229376)) * t23 * t22 * in.w[0] - (T(1) / T(3440640)) * t26 * t22 * in.w[2];
  const T g_factor = -T(16) * length;
  f = (T(1) / T(215040)) * (t22 * in.w[1] * t25 + t22 * t27 * in.w[2] + t22 * in.w[3] * (T(2) * ab_ap * t22 * t27 + T(14) * t22 * (T(1280) * t13 + ab_ap * t2 * t18 - T(1280) * t8) - t22 * ap_ap * t25) + t2 * in.w[0] * t19) * length;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

}  // namespace skelconv::generated
