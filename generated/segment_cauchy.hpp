// generated/segment_cauchy.hpp — segment kernels of the cauchy family.
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
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 29 +, 39 ×, 2 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 114 +, 204 ×, 25 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
  const T J1 = asinh(X) / t5;
  T F;
  const T t6 = D - T(2) * a * a;
  if (t6 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    F = in.w[0] * J1;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 35 +, 53 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1544 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = b * t3 + t4 * a_minus_b;
    const T t6 = T(1) / D;
    G_ap = t5 * t6 * in.w[0];
    G_ab = in.w[0] * (t3 + t5 * t6 * b - t4) / a;
  }
  const T g_factor = -length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 36 +, 62 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 265 +, 975 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = in.w[0] * J1;
    F = t11;
    const T t12 = -b;
    const T t13 = J_downward<T>(3, a, D, t12, c, a_minus_b, q1);
    G_ap = in.w[0] * t13;
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = T(1) / a;
    G_ab = in.w[0] * (b * t13 + t14 - t15) * t16;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = in.w[0] * J1;
    F = t17;
    const T t18 = T(1) / D;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = b * t19 + a_minus_b * t20;
    G_ap = in.w[0] * t18 * t21;
    const T t22 = T(1) / a;
    G_ab = in.w[0] * (t19 + b * t18 * t21 - t20) * t22;
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Returns false where segment_cauchy_i1_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 36 +, 62 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i1_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
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
    const T t3 = r0 * a_minus_b;
    X = t1 * t2 * (t3 + r1 * b);
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = J1 * in.w[0];
    F = t11;
    const T t12 = T(1) / D;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t13 * a_minus_b + t14 * b;
    G_ap = t12 * in.w[0] * t15;
    const T t16 = T(1) / a;
    G_ab = in.w[0] * t16 * (t12 * t15 * b + t14 - t13);
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 32 +, 43 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 135 +, 226 ×, 25 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = r0 * a_minus_b;
    const T t2 = sqrt(a);
    X = (t1 + b * r1) * t2 / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = r0 * a_minus_b;
    X = -t3 * (b - a_minus_b) / (t4 - b * r1);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = asinh(X) * t6;
  T F;
  const T t7 = D - T(2) * a * a;
  if (t7 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / a;
    F = J1 * in.w[0] - (r0 - r1 - b * J1) * t8 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 40 +, 69 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 269 +, 981 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  T X;
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = b * r1;
    X = t1 * t2 * (t3 + r0 * a_minus_b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = b * r1;
    X = t4 * (b - a_minus_b) / (t5 - r0 * a_minus_b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -b * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = J_downward<T>(3, a, D, -b, c, a_minus_b, q1);
    const T t12 = T(1) / a;
    const T t13 = T(1) / r0;
    const T t14 = T(1) / r1;
    const T t15 = t11 * b + t13 - t14;
    G_ap = t11 * in.w[0] + in.w[1] * t12 * t15;
    G_ab = t12 * t15 * in.w[0] + in.w[1] * t12 * (T(2) * t12 * b * t15 + J1 - t11 * c);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r0;
    const T t18 = T(1) / r1;
    const T t19 = b * t17 + t18 * a_minus_b;
    const T t20 = T(1) / a;
    const T t21 = t18 - t17 - t16 * b * t19;
    G_ap = t16 * t19 * in.w[0] - in.w[1] * t20 * t21;
    G_ab = -t20 * t21 * in.w[0] - in.w[1] * t20 * (T(2) * t20 * b * t21 + t16 * t19 * c - J1);
  }
  const T g_factor = -length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 43 +, 74 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 272 +, 986 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
    const T t2 = r1 * b;
    const T t3 = T(1) / D;
    X = t1 * (t2 + a_minus_b * r0) * t3;
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = T(1) / a;
    const T t12 = in.w[0] * J1 + t11 * in.w[1] * (r1 + b * J1 - r0);
    F = t12;
    const T t13 = -b;
    const T t14 = J_downward<T>(3, a, D, t13, c, a_minus_b, q1);
    const T t15 = T(1) / r1;
    const T t16 = T(1) / r0;
    const T t17 = t15 - b * t14 - t16;
    G_ap = t14 * in.w[0] - t11 * in.w[1] * t17;
    G_ab = -t11 * t17 * in.w[0] - t11 * in.w[1] * (t14 * c + T(2) * t11 * b * t17 - J1);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = in.w[0] * J1 + t18 * in.w[1] * (r1 + b * J1 - r0);
    F = t19;
    const T t20 = T(1) / r1;
    const T t21 = T(1) / r0;
    const T t22 = t20 * a_minus_b + b * t21;
    const T t23 = T(1) / D;
    const T t24 = t20 - b * t22 * t23 - t21;
    G_ap = t22 * in.w[0] * t23 - t18 * in.w[1] * t24;
    G_ab = -t18 * in.w[1] * (t22 * c * t23 + T(2) * t18 * b * t24 - J1) - t18 * t24 * in.w[0];
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Returns false where segment_cauchy_i1_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 74 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i1_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
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
    const T t2 = sqrt(a);
    const T t3 = r0 * a_minus_b;
    X = t1 * t2 * (t3 + r1 * b);
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / a;
    const T t12 = in.w[0] * J1 - (r0 - J1 * b - r1) * t11 * in.w[1];
    F = t12;
    const T t13 = T(1) / r0;
    const T t14 = T(1) / D;
    const T t15 = T(1) / r1;
    const T t16 = a_minus_b * t15 + t13 * b;
    const T t17 = t13 + t14 * b * t16 - t15;
    G_ap = t11 * t17 * in.w[1] + in.w[0] * t14 * t16;
    G_ab = in.w[0] * t11 * t17 + (J1 + T(2) * t11 * t17 * b - c * t14 * t16) * t11 * in.w[1];
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 37 +, 55 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 156 +, 247 ×, 25 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
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
    const T t1 = sqrt(a);
    const T t2 = b * r1;
    X = t1 * (t2 + r0 * a_minus_b) / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = b * r1;
    X = t3 * (b - a_minus_b) / (t4 - r0 * a_minus_b);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = t6 * asinh(X);
  T F;
  const T t7 = D - T(2) * a * a;
  if (t7 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / a;
    const T t9 = r0 - r1 - J1 * b;
    F = J1 * in.w[0] - (T(1) / T(2)) * t8 * in.w[2] * (T(2) * J1 * c + T(4) * t8 * b * t9 - (r0 * b + r1 * a_minus_b + J1 * D) * t8) - t8 * in.w[1] * t9;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 46 +, 80 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 275 +, 992 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
    const T t1 = r0 * a_minus_b;
    const T t2 = sqrt(a);
    const T t3 = T(1) / D;
    X = (t1 + b * r1) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = -t4 * (b - a_minus_b) / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -b * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + in.w[0] * M_flat[1];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = J_downward<T>(3, a, D, -b, c, a_minus_b, q1);
    const T t12 = T(1) / r0;
    const T t13 = T(1) / r1;
    const T t14 = b * t11 + t12 - t13;
    const T t15 = T(1) / a;
    const T t16 = T(2) * b * t14 * t15 + J1 - t11 * c;
    G_ap = t11 * in.w[0] + t16 * t15 * in.w[2] + t14 * in.w[1] * t15;
    const T t17 = r0 - r1 - b * J1;
    G_ab = in.w[1] * t16 * t15 + (T(2) * b * t16 * t15 - t15 * t17 - t14 * c * t15) * t15 * in.w[2] + in.w[0] * t14 * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / a;
    const T t19 = T(1) / r0;
    const T t20 = T(1) / r1;
    const T t21 = b * t19 + t20 * a_minus_b;
    const T t22 = T(1) / D;
    const T t23 = b * t21 * t22 + t19 - t20;
    const T t24 = J1 + T(2) * b * t18 * t23 - t21 * c * t22;
    G_ap = in.w[1] * t18 * t23 + t21 * in.w[0] * t22 + t24 * t18 * in.w[2];
    const T t25 = r0 - r1 - b * J1;
    G_ab = in.w[0] * t18 * t23 + t24 * in.w[1] * t18 - t18 * in.w[2] * (c * t18 * t23 + t18 * t25 - T(2) * b * t24 * t18);
  }
  const T g_factor = -length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 52 +, 96 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 281 +, 1008 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = r0 * a_minus_b;
    X = t1 * t2 * (t3 + r1 * b);
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ap = M_flat[5] * in.w[1] + M_flat[4] * in.w[0] + M_flat[6] * in.w[2];
    G_ab = M_flat[5] * in.w[0] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = T(1) / a;
    const T t12 = r0 - r1 - J1 * b;
    const T t13 = J1 * in.w[0] - (T(1) / T(2)) * (T(4) * t11 * b * t12 + T(2) * c * J1 - (r0 * b + r1 * a_minus_b + J1 * D) * t11) * t11 * in.w[2] - in.w[1] * t11 * t12;
    F = t13;
    const T t14 = T(1) / r0;
    const T t15 = -b;
    const T t16 = J_downward<T>(3, a, D, t15, c, a_minus_b, q1);
    const T t17 = T(1) / r1;
    const T t18 = t14 + t16 * b - t17;
    const T t19 = T(2) * t11 * b * t18 + J1 - c * t16;
    G_ap = t19 * t11 * in.w[2] + in.w[1] * t11 * t18 + t16 * in.w[0];
    G_ab = in.w[1] * t19 * t11 + t11 * t18 * in.w[0] + (T(2) * t19 * t11 * b - c * t11 * t18 - t11 * t12) * t11 * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / a;
    const T t21 = r0 - r1 - J1 * b;
    const T t22 = J1 * in.w[0] - (T(1) / T(2)) * (T(4) * t20 * b * t21 + T(2) * c * J1 - (r0 * b + r1 * a_minus_b + J1 * D) * t20) * t20 * in.w[2] - in.w[1] * t20 * t21;
    F = t22;
    const T t23 = T(1) / D;
    const T t24 = T(1) / r0;
    const T t25 = T(1) / r1;
    const T t26 = t24 * b + t25 * a_minus_b;
    const T t27 = t24 + t23 * t26 * b - t25;
    const T t28 = J1 + T(2) * t27 * t20 * b - c * t23 * t26;
    G_ap = t23 * t26 * in.w[0] + in.w[1] * t27 * t20 + t28 * t20 * in.w[2];
    G_ab = in.w[1] * t28 * t20 + t27 * t20 * in.w[0] - (c * t27 * t20 + t20 * t21 - T(2) * t28 * t20 * b) * t20 * in.w[2];
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Returns false where segment_cauchy_i1_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 96 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i1_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
    const T t3 = r0 * a_minus_b;
    X = t1 * t2 * (t3 + r1 * b);
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = r0 * a_minus_b;
    X = (a_minus_b - b) * t4 / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[0] + M_flat[6] * in.w[2] + in.w[1] * M_flat[5];
    G_ab = in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / a;
    const T t12 = r0 - J1 * b - r1;
    const T t13 = J1 * in.w[0] - in.w[1] * t11 * t12 - (T(1) / T(2)) * t11 * in.w[2] * (T(4) * t11 * t12 * b + T(2) * J1 * c - (J1 * D + r0 * b + r1 * a_minus_b) * t11);
    F = t13;
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = t14 * b + t15 * a_minus_b;
    const T t17 = T(1) / D;
    const T t18 = t16 * t17 * b + t14 - t15;
    const T t19 = J1 + T(2) * t11 * b * t18 - t16 * t17 * c;
    G_ap = t16 * t17 * in.w[0] + in.w[1] * t11 * t18 + t19 * t11 * in.w[2];
    G_ab = in.w[1] * t19 * t11 + t11 * t18 * in.w[0] - t11 * in.w[2] * (t11 * t12 + t11 * t18 * c - T(2) * t19 * t11 * b);
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 42 +, 72 ×, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 177 +, 268 ×, 25 /, 25 sqrt, 0 atan, 1 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
    const T t1 = r0 * a_minus_b;
    const T t2 = sqrt(a);
    X = (t1 + b * r1) * t2 / D;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t3 = sqrt(a);
    const T t4 = r0 * a_minus_b;
    X = -(b - a_minus_b) * t3 / (t4 - b * r1);
  }
  const T t5 = sqrt(a);
  const T t6 = T(1) / t5;
  const T J1 = asinh(X) * t6;
  T F;
  const T t7 = D - T(2) * a * a;
  if (t7 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(1, 1, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / a;
    const T t9 = r0 - r1 - b * J1;
    const T t10 = D * J1 + r0 * b + a_minus_b * r1;
    const T t11 = T(4) * b * t9 * t8 + T(2) * c * J1 - t8 * t10;
    F = in.w[0] * J1 - (T(1) / T(6)) * (T(6) * b * t8 * t11 - T(6) * c * t9 * t8 - (T(3) * b * t8 * t10 + T(2) * r1 * q1 - T(2) * r0 * c) * t8) * t8 * in.w[3] - (T(1) / T(2)) * in.w[2] * t8 * t11 - in.w[1] * t9 * t8;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 54 +, 101 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 283 +, 1013 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
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
    X = -t4 * (a_minus_b - b) / (t5 - a_minus_b * r0);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1];
    G_ab = in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + M_flat[3] * in.w[2];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = -b;
    const T t12 = J_downward<T>(3, a, D, t11, c, a_minus_b, q1);
    const T t13 = T(1) / r0;
    const T t14 = T(1) / r1;
    const T t15 = b * t12 + t13 - t14;
    const T t16 = T(1) / a;
    const T t17 = t12 * c - J1 - T(2) * t15 * t16 * b;
    const T t18 = r1 + b * J1 - r0;
    const T t19 = t15 * t16 * c + T(2) * t16 * t17 * b - t16 * t18;
    G_ap = in.w[0] * t12 + t15 * t16 * in.w[1] - in.w[3] * t19 * t16 - t16 * t17 * in.w[2];
    G_ab = in.w[0] * t15 * t16 - t16 * t17 * in.w[1] - t19 * t16 * in.w[2] - (T(1) / T(2)) * in.w[3] * t16 * (T(4) * t19 * t16 * b - t16 * (t16 * (b * r0 + r1 * a_minus_b + D * J1) + T(4) * t16 * b * t18 - T(2) * J1 * c) - T(2) * t16 * t17 * c);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t20 = T(1) / D;
    const T t21 = T(1) / r1;
    const T t22 = T(1) / r0;
    const T t23 = t21 * a_minus_b + b * t22;
    const T t24 = T(1) / a;
    const T t25 = t21 - t20 * b * t23 - t22;
    const T t26 = t20 * t23 * c + T(2) * t24 * b * t25 - J1;
    const T t27 = r1 + b * J1 - r0;
    const T t28 = T(2) * t24 * t26 * b - t24 * c * t25 - t24 * t27;
    G_ap = t20 * in.w[0] * t23 - t24 * t26 * in.w[2] - t24 * in.w[1] * t25 - in.w[3] * t28 * t24;
    G_ab = -t24 * t26 * in.w[1] - in.w[0] * t24 * t25 - t28 * t24 * in.w[2] - (T(1) / T(2)) * in.w[3] * t24 * (T(4) * t28 * t24 * b - t24 * (t24 * (b * r0 + r1 * a_minus_b + D * J1) + T(4) * t24 * b * t27 - T(2) * J1 * c) - T(2) * t24 * t26 * c);
  }
  const T g_factor = -length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Operations: 61 +, 125 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 290 +, 1037 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
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
    const T t2 = sqrt(a);
    const T t3 = r1 * b;
    X = t1 * t2 * (t3 + r0 * a_minus_b);
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[7] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = r0 - J1 * b - r1;
    const T t12 = T(1) / a;
    const T t13 = J1 * D + r1 * a_minus_b + r0 * b;
    const T t14 = T(2) * c * J1 + T(4) * t11 * t12 * b - t13 * t12;
    const T t15 = J1 * in.w[0] - (T(1) / T(6)) * (T(6) * t14 * t12 * b - t12 * (T(3) * t13 * t12 * b + T(2) * q1 * r1 - T(2) * c * r0) - T(6) * t11 * c * t12) * in.w[3] * t12 - t11 * t12 * in.w[1] - (T(1) / T(2)) * t14 * in.w[2] * t12;
    F = t15;
    const T t16 = T(1) / r0;
    const T t17 = -b;
    const T t18 = J_downward<T>(3, a, D, t17, c, a_minus_b, q1);
    const T t19 = T(1) / r1;
    const T t20 = t16 + t18 * b - t19;
    const T t21 = J1 + T(2) * t12 * b * t20 - t18 * c;
    const T t22 = t11 * t12;
    const T t23 = c * t12 * t20 + t22 - T(2) * t21 * t12 * b;
    G_ap = in.w[2] * t21 * t12 + t12 * in.w[1] * t20 + t18 * in.w[0] - t23 * in.w[3] * t12;
    G_ab = t21 * t12 * in.w[1] + t12 * in.w[0] * t20 - in.w[2] * t23 * t12 - (T(1) / T(2)) * (T(4) * t23 * t12 * b + t14 * t12 + T(2) * c * t21 * t12) * in.w[3] * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = r0 - J1 * b - r1;
    const T t25 = T(1) / a;
    const T t26 = J1 * D + r1 * a_minus_b + r0 * b;
    const T t27 = T(2) * c * J1 + T(4) * t24 * t25 * b - t26 * t25;
    const T t28 = J1 * in.w[0] - (T(1) / T(6)) * (T(6) * t27 * t25 * b - t25 * (T(3) * t26 * t25 * b + T(2) * q1 * r1 - T(2) * c * r0) - T(6) * t24 * c * t25) * in.w[3] * t25 - t24 * t25 * in.w[1] - (T(1) / T(2)) * t27 * in.w[2] * t25;
    F = t28;
    const T t29 = T(1) / r0;
    const T t30 = T(1) / r1;
    const T t31 = t30 * a_minus_b + t29 * b;
    const T t32 = T(1) / D;
    const T t33 = t29 + t31 * t32 * b - t30;
    const T t34 = t24 * t25;
    const T t35 = c * t31 * t32 - J1 - T(2) * t25 * t33 * b;
    const T t36 = c * t25 * t33 + t34 + T(2) * t35 * t25 * b;
    G_ap = t25 * t33 * in.w[1] + t31 * t32 * in.w[0] - t36 * in.w[3] * t25 - t35 * in.w[2] * t25;
    G_ab = t25 * in.w[0] * t33 + (T(1) / T(2)) * in.w[3] * t25 * (T(2) * c * t35 * t25 - t27 * t25 - T(4) * t36 * t25 * b) - t35 * t25 * in.w[1] - t36 * in.w[2] * t25;
  }
  const T g_factor = -in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−1/2) dt
/// Returns false where segment_cauchy_i1_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 125 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i1_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
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
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -b * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(1, 3, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[5] * in.w[0] + M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + M_flat[8] * in.w[3];
    G_ab = in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[3] * M_flat[9] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = r0 - r1 - b * J1;
    const T t12 = T(1) / a;
    const T t13 = r1 * a_minus_b + b * r0 + J1 * D;
    const T t14 = T(4) * b * t11 * t12 + T(2) * c * J1 - t13 * t12;
    const T t15 = J1 * in.w[0] - (T(1) / T(2)) * t14 * in.w[2] * t12 - (T(1) / T(6)) * (T(6) * t14 * b * t12 - (T(3) * b * t13 * t12 + T(2) * q1 * r1 - T(2) * c * r0) * t12 - T(6) * t11 * c * t12) * in.w[3] * t12 - in.w[1] * t11 * t12;
    F = t15;
    const T t16 = T(1) / r0;
    const T t17 = T(1) / r1;
    const T t18 = b * t16 + t17 * a_minus_b;
    const T t19 = T(1) / D;
    const T t20 = b * t18 * t19 + t16 - t17;
    const T t21 = t18 * c * t19 - T(2) * b * t20 * t12 - J1;
    const T t22 = c * t20 * t12 + T(2) * b * t21 * t12 + t11 * t12;
    G_ap = in.w[1] * t20 * t12 + t18 * t19 * in.w[0] - t22 * in.w[3] * t12 - in.w[2] * t21 * t12;
    const T t23 = t14 * t12;
    G_ab = t20 * in.w[0] * t12 - t22 * in.w[2] * t12 - (T(1) / T(2)) * (t23 + T(4) * b * t22 * t12 - T(2) * c * t21 * t12) * in.w[3] * t12 - in.w[1] * t21 * t12;
  }
  const T g_factor = -length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 32 +, 42 ×, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 847 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T J2 = atan2(t3, c_minus_b) / t3;
    F = in.w[0] * J2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 39 +, 62 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1551 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = b * t6 + a_minus_b * t7 + a * J2;
    G_ap = (T(1) / T(2)) * t5 * in.w[0] * t8;
    G_ab = (T(1) / T(2)) * in.w[0] * (t6 + t5 * t8 * b - t7) / a;
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 39 +, 65 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 269 +, 983 ×, 124 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t3 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / c;
    const T t5 = T(1) / q1;
    const T t6 = T(1) / a;
    F = (T(2) * D * t3 - t4 * b - t5 * a_minus_b) * in.w[0] * t6;
    G_ap = t3 * in.w[0];
    G_ab = (T(1) / T(2)) * (T(2) * t3 * b + t4 - t5) * in.w[0] * t6;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t7 = sqrt(D);
    const T t8 = T(1) / t7;
    const T J2 = atan2(t7, c_minus_b) * t8;
    F = J2 * in.w[0];
    const T t9 = T(1) / c;
    const T t10 = T(1) / q1;
    const T t11 = J2 * a + t9 * b + t10 * a_minus_b;
    const T t12 = T(1) / D;
    G_ap = (T(1) / T(2)) * t11 * t12 * in.w[0];
    const T t13 = T(1) / a;
    G_ab = (T(1) / T(2)) * (t11 * t12 * b + t9 - t10) * in.w[0] * t13;
  }
  const T g_factor = -T(2) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Returns false where segment_cauchy_i2_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 39 +, 65 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i2_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    F = in.w[0] * J2;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = b * t5 + a * J2 + a_minus_b * t6;
    const T t8 = T(1) / D;
    G_ap = (T(1) / T(2)) * in.w[0] * t7 * t8;
    const T t9 = T(1) / a;
    G_ab = -(T(1) / T(2)) * t9 * in.w[0] * (t6 - b * t7 * t8 - t5);
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 34 +, 47 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 264 +, 962 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, a, D, -b, c, a_minus_b, q1);
    const T t4 = T(1) / a;
    F = in.w[0] * t3 + (T(1) / T(2)) * (log_ratio + T(2) * b * t3) * t4 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    const T t6 = T(1) / a;
    F = (T(1) / T(2)) * (log_ratio + T(2) * b * J2) * t6 * in.w[1] + in.w[0] * J2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 43 +, 75 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2244 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = b * t6 + a_minus_b * t8 + a * J2;
    const T t10 = t6 + t7 * b * t9 - t8;
    G_ap = (T(1) / T(2)) * in.w[1] * t5 * t10 + (T(1) / T(2)) * t7 * t9 * in.w[0];
    G_ab = (T(1) / T(2)) * in.w[1] * t5 * (T(2) * t5 * b * t10 + T(2) * J2 - t7 * t9 * c) + (T(1) / T(2)) * t5 * in.w[0] * t10;
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 45 +, 83 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 275 +, 999 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
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
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = t5 * a_minus_b;
    const T t7 = t0 * b;
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t6 + t7 - T(2) * D * t8;
    F = (T(1) / T(2)) * (log_ratio - T(2) * t4 * t9 * b) * t4 * in.w[1] - in.w[0] * t4 * t9;
    const T t10 = t5 - t0 - T(2) * t8 * b;
    G_ap = in.w[0] * t8 - (T(1) / T(2)) * t10 * t4 * in.w[1];
    G_ab = -(c * t8 + t4 * t9 + t10 * t4 * b) * t4 * in.w[1] - (T(1) / T(2)) * in.w[0] * t10 * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = sqrt(D);
    const T t12 = T(1) / t11;
    const T J2 = atan2(t11, c_minus_b) * t12;
    const T t13 = T(1) / a;
    F = in.w[0] * J2 + (T(1) / T(2)) * (log_ratio + T(2) * J2 * b) * t13 * in.w[1];
    const T t14 = T(1) / q1;
    const T t15 = t14 * a_minus_b;
    const T t16 = t0 * b;
    const T t17 = t15 + J2 * a + t16;
    const T t18 = T(1) / D;
    const T t19 = t14 - t0 - t17 * t18 * b;
    G_ap = (T(1) / T(2)) * t17 * in.w[0] * t18 - (T(1) / T(2)) * t13 * in.w[1] * t19;
    G_ab = (T(1) / T(2)) * t13 * in.w[1] * (T(2) * J2 - T(2) * t13 * t19 * b - t17 * c * t18) - (T(1) / T(2)) * in.w[0] * t13 * t19;
  }
  const T g_factor = -T(2) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Returns false where segment_cauchy_i2_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 83 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i2_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
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
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(1) / a;
    F = in.w[0] * J2 + (T(1) / T(2)) * t6 * in.w[1] * (log_ratio + T(2) * b * J2);
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = a_minus_b * t8;
    const T t10 = b * t0;
    const T t11 = t9 + t10 + a * J2;
    const T t12 = t0 + t7 * b * t11 - t8;
    G_ap = (T(1) / T(2)) * t6 * in.w[1] * t12 + (T(1) / T(2)) * t7 * t11 * in.w[0];
    G_ab = (T(1) / T(2)) * t6 * in.w[1] * (T(2) * t6 * b * t12 + T(2) * J2 - t7 * t11 * c) + (T(1) / T(2)) * t6 * t12 * in.w[0];
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 37 +, 52 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 267 +, 967 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T log_ratio = log(q1 / c);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(2, a, D, -b, c, a_minus_b, q1);
    const T t5 = T(2) * b * t4 + log_ratio;
    F = t3 * in.w[2] * (t3 * b * t5 + T(1) - c * t4) + in.w[0] * t4 + (T(1) / T(2)) * t3 * t5 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t6 = sqrt(D);
    const T J2 = atan2(t6, c_minus_b) / t6;
    const T t7 = T(1) / a;
    const T t8 = T(2) * J2 * b + log_ratio;
    F = J2 * in.w[0] + (T(1) / T(2)) * t7 * t8 * in.w[1] + t7 * in.w[2] * (t7 * t8 * b + T(1) - J2 * c);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 48 +, 90 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 278 +, 1004 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + in.w[2] * M_flat[3];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / a;
    const T t6 = b * t0;
    const T t7 = T(1) / q1;
    const T t8 = a_minus_b * t7;
    const T t9 = t6 + t8 - T(2) * D * t4;
    const T t10 = t7 - T(2) * t4 * b - t0;
    const T t11 = t5 * t9 + t5 * b * t10 + t4 * c;
    G_ap = t4 * in.w[0] - in.w[2] * t5 * t11 - (T(1) / T(2)) * t5 * t10 * in.w[1];
    G_ab = -(T(1) / T(2)) * t5 * in.w[0] * t10 - (T(1) / T(2)) * (T(4) * t5 * t11 * b - t5 * (log_ratio - T(2) * t5 * b * t9) - t5 * c * t10) * in.w[2] * t5 - t5 * t11 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / D;
    const T t15 = b * t0;
    const T t16 = T(1) / q1;
    const T t17 = a_minus_b * t16;
    const T t18 = t15 + t17 + a * J2;
    const T t19 = t16 - t14 * t18 * b - t0;
    const T t20 = T(1) / a;
    const T t21 = T(2) * t19 * t20 * b + t14 * t18 * c - T(2) * J2;
    G_ap = (T(1) / T(2)) * t14 * t18 * in.w[0] - (T(1) / T(2)) * t19 * t20 * in.w[1] - (T(1) / T(2)) * in.w[2] * t20 * t21;
    G_ab = -(T(1) / T(2)) * t19 * t20 * in.w[0] - (T(1) / T(2)) * t20 * t21 * in.w[1] - (T(1) / T(2)) * in.w[2] * t20 * (T(2) * t20 * b * t21 - (log_ratio + T(2) * b * J2) * t20 - t19 * t20 * c);
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 52 +, 100 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 282 +, 1016 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
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
  T F;
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
    G_ab = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = b * t0;
    const T t6 = T(1) / q1;
    const T t7 = a_minus_b * t6;
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t5 + t7 - T(2) * D * t8;
    const T t10 = log_ratio - T(2) * t9 * t4 * b;
    F = in.w[2] * t4 * (t9 * t4 * c + t4 * b * t10 + T(1)) + (T(1) / T(2)) * t4 * t10 * in.w[1] - t9 * t4 * in.w[0];
    const T t11 = T(2) * t8 * b + t0 - t6;
    const T t12 = t4 * t11 * b - t9 * t4 - t8 * c;
    G_ap = (T(1) / T(2)) * t4 * t11 * in.w[1] + in.w[2] * t4 * t12 + t8 * in.w[0];
    G_ab = (T(1) / T(2)) * (t4 * t10 + T(4) * t4 * b * t12 - t4 * t11 * c) * in.w[2] * t4 + t4 * t12 * in.w[1] + (T(1) / T(2)) * t4 * t11 * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / a;
    const T t16 = log_ratio + T(2) * b * J2;
    F = in.w[0] * J2 + (T(1) / T(2)) * t15 * t16 * in.w[1] - in.w[2] * t15 * (c * J2 - t15 * b * t16 - T(1));
    const T t17 = b * t0;
    const T t18 = T(1) / q1;
    const T t19 = a_minus_b * t18;
    const T t20 = t17 + t19 + a * J2;
    const T t21 = T(1) / D;
    const T t22 = t20 * t21 * b + t0 - t18;
    const T t23 = T(2) * t22 * t15 * b + T(2) * J2 - t20 * t21 * c;
    G_ap = (T(1) / T(2)) * in.w[2] * t15 * t23 + (T(1) / T(2)) * t20 * t21 * in.w[0] + (T(1) / T(2)) * t22 * t15 * in.w[1];
    G_ab = (T(1) / T(2)) * t15 * t23 * in.w[1] + (T(1) / T(2)) * t22 * t15 * in.w[0] + (T(1) / T(2)) * in.w[2] * t15 * (t15 * t16 + T(2) * t15 * b * t23 - t22 * t15 * c);
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Returns false where segment_cauchy_i2_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 100 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i2_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
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
  const T t1 = D - T(2) * a * a;
  const T t2 = -b * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + M_flat[6] * in.w[2];
    G_ab = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    const T t6 = T(2) * b * J2 + log_ratio;
    const T t7 = T(1) / a;
    F = (b * t6 * t7 + T(1) - c * J2) * in.w[2] * t7 + in.w[0] * J2 + (T(1) / T(2)) * t6 * in.w[1] * t7;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * a_minus_b;
    const T t11 = b * t0;
    const T t12 = t10 + J2 * a + t11;
    const T t13 = t9 - t0 - b * t8 * t12;
    const T t14 = T(2) * t13 * b * t7 + c * t8 * t12 - T(2) * J2;
    G_ap = (T(1) / T(2)) * in.w[0] * t8 * t12 - (T(1) / T(2)) * t13 * in.w[1] * t7 - (T(1) / T(2)) * t14 * in.w[2] * t7;
    G_ab = -(T(1) / T(2)) * (T(2) * b * t14 * t7 - t6 * t7 - t13 * c * t7) * in.w[2] * t7 - (T(1) / T(2)) * t13 * in.w[0] * t7 - (T(1) / T(2)) * in.w[1] * t14 * t7;
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 42 +, 62 ×, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 272 +, 977 ×, 123 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_2 = J_downward(…)
    const T t3 = J_downward<T>(2, a, D, -b, c, a_minus_b, q1);
    const T t4 = log_ratio + T(2) * t3 * b;
    const T t5 = T(1) / a;
    const T t6 = t3 * c - t4 * t5 * b - T(1);
    const T t7 = c - q1 - T(2) * b;
    F = (T(1) / T(2)) * in.w[1] * t4 * t5 + t3 * in.w[0] - in.w[2] * t6 * t5 - (T(1) / T(2)) * (T(4) * t6 * t5 * b + c * t4 * t5 + t7 * t5) * in.w[3] * t5;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T J2 = atan2(t8, c_minus_b) / t8;
    const T t9 = log_ratio + T(2) * J2 * b;
    const T t10 = T(1) / a;
    const T t11 = t9 * t10 * b + T(1) - c * J2;
    const T t12 = c - q1 - T(2) * b;
    F = (T(1) / T(2)) * in.w[1] * t9 * t10 + in.w[0] * J2 + (T(1) / T(2)) * (T(4) * t10 * t11 * b - c * t9 * t10 - t12 * t10) * in.w[3] * t10 + in.w[2] * t10 * t11;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 54 +, 106 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 284 +, 1018 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ab = in.w[1] * M_flat[2] + in.w[3] * M_flat[4] + in.w[2] * M_flat[3] + in.w[0] * M_flat[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = a_minus_b * t5;
    const T t7 = b * t0;
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t6 + t7 - T(2) * D * t8;
    const T t10 = log_ratio - T(2) * t4 * t9 * b;
    const T t11 = T(2) * t8 * b + t0 - t5;
    const T t12 = t8 * c + t4 * t9 - t11 * t4 * b;
    const T t13 = t4 * t10 - T(4) * t4 * b * t12 - t11 * t4 * c;
    G_ap = (T(1) / T(2)) * t4 * in.w[3] * t13 + t8 * in.w[0] + (T(1) / T(2)) * t11 * t4 * in.w[1] - in.w[2] * t4 * t12;
    G_ab = (T(1) / T(2)) * t11 * t4 * in.w[0] + ((t4 * t9 * c + t4 * b * t10 + T(1)) * t4 + t4 * t12 * c + t4 * t13 * b) * t4 * in.w[3] + (T(1) / T(2)) * in.w[2] * t4 * t13 - t4 * t12 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = sqrt(D);
    const T t15 = T(1) / t14;
    const T J2 = t15 * atan2(t14, c_minus_b);
    const T t16 = T(1) / D;
    const T t17 = T(1) / q1;
    const T t18 = a_minus_b * t17;
    const T t19 = b * t0;
    const T t20 = t18 + t19 + a * J2;
    const T t21 = T(1) / a;
    const T t22 = t0 + t16 * t20 * b - t17;
    const T t23 = t16 * t20 * c - T(2) * t21 * b * t22 - T(2) * J2;
    const T t24 = log_ratio + T(2) * b * J2;
    const T t25 = t21 * t22 * c + T(2) * t21 * b * t23 - t21 * t24;
    G_ap = (T(1) / T(2)) * t16 * in.w[0] * t20 + (T(1) / T(2)) * t21 * in.w[1] * t22 - (T(1) / T(2)) * in.w[2] * t21 * t23 - (T(1) / T(2)) * t25 * t21 * in.w[3];
    G_ab = (T(1) / T(2)) * t21 * in.w[0] * t22 - (T(1) / T(2)) * t21 * in.w[1] * t23 - (T(1) / T(2)) * t21 * in.w[3] * (T(2) * t25 * t21 * b - T(2) * t21 * (t21 * t24 * b + T(1) - J2 * c) - t21 * t23 * c) - (T(1) / T(2)) * in.w[2] * t25 * t21;
  }
  const T g_factor = -T(2) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Operations: 61 +, 123 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 291 +, 1036 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
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
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1];
    G_ap = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + in.w[3] * M_flat[8] + M_flat[7] * in.w[2];
    G_ab = in.w[2] * M_flat[8] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + in.w[0] * M_flat[6];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = T(1) / q1;
    const T t6 = a_minus_b * t5;
    const T t7 = b * t0;
    const T t8 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t9 = t6 + t7 - T(2) * t8 * D;
    const T t10 = log_ratio - T(2) * t9 * b * t4;
    const T t11 = b * t10 * t4 + t9 * c * t4 + T(1);
    const T t12 = (T(2) * b + q1 - c) * t4;
    F = in.w[2] * t4 * t11 + (T(1) / T(2)) * in.w[3] * (t12 + T(4) * b * t4 * t11 - c * t10 * t4) * t4 + (T(1) / T(2)) * in.w[1] * t10 * t4 - in.w[0] * t9 * t4;
    const T t13 = t0 + T(2) * b * t8 - t5;
    const T t14 = t13 * b * t4 - c * t8 - t9 * t4;
    const T t15 = t10 * t4 + T(4) * b * t14 * t4 - t13 * c * t4;
    G_ap = (T(1) / T(2)) * t13 * in.w[1] * t4 + (T(1) / T(2)) * in.w[3] * t15 * t4 + t14 * in.w[2] * t4 + in.w[0] * t8;
    G_ab = (T(1) / T(2)) * t13 * in.w[0] * t4 + (T(1) / T(2)) * t15 * in.w[2] * t4 + in.w[1] * t14 * t4 - in.w[3] * (c * t14 * t4 - b * t15 * t4 - t4 * t11) * t4;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = atan2(t16, c_minus_b) * t17;
    const T t18 = T(1) / a;
    const T t19 = (T(2) * b + q1 - c) * t18;
    const T t20 = log_ratio + T(2) * b * J2;
    const T t21 = b * t20 * t18 + T(1) - c * J2;
    F = (T(1) / T(2)) * in.w[3] * (t19 + T(4) * t21 * b * t18 - t20 * c * t18) * t18 + (T(1) / T(2)) * in.w[1] * t20 * t18 + t21 * in.w[2] * t18 + in.w[0] * J2;
    const T t22 = T(1) / q1;
    const T t23 = a_minus_b * t22;
    const T t24 = b * t0;
    const T t25 = t23 + J2 * a + t24;
    const T t26 = T(1) / D;
    const T t27 = b * t25 * t26 + t0 - t22;
    const T t28 = t25 * c * t26 - T(2) * J2 - T(2) * t27 * b * t18;
    const T t29 = t20 * t18 - t27 * c * t18 - T(2) * b * t28 * t18;
    G_ap = (T(1) / T(2)) * t27 * in.w[1] * t18 + (T(1) / T(2)) * t29 * in.w[3] * t18 + (T(1) / T(2)) * in.w[0] * t25 * t26 - (T(1) / T(2)) * t28 * in.w[2] * t18;
    G_ab = (T(1) / T(2)) * in.w[0] * t27 * t18 + (T(1) / T(2)) * in.w[3] * (T(2) * t21 * t18 + T(2) * t29 * b * t18 + c * t28 * t18) * t18 + (T(1) / T(2)) * t29 * in.w[2] * t18 - (T(1) / T(2)) * in.w[1] * t28 * t18;
  }
  const T g_factor = -T(2) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−2/2) dt
/// Returns false where segment_cauchy_i2_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 123 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i2_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
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
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[5] * in.w[0] + M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1];
    G_ab = in.w[2] * M_flat[8] + M_flat[7] * in.w[1] + in.w[3] * M_flat[9] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    const T t6 = T(1) / a;
    const T t7 = T(2) * J2 * b + log_ratio;
    const T t8 = t6 * b * t7 + T(1) - c * J2;
    const T t9 = t6 * (c - T(2) * b - q1);
    F = (T(1) / T(2)) * t6 * in.w[1] * t7 + in.w[2] * t6 * t8 + J2 * in.w[0] - (T(1) / T(2)) * in.w[3] * t6 * (c * t6 * t7 + t9 - T(4) * t6 * t8 * b);
    const T t10 = T(1) / q1;
    const T t11 = t0 * b;
    const T t12 = a_minus_b * t10;
    const T t13 = t11 + t12 + J2 * a;
    const T t14 = T(1) / D;
    const T t15 = t10 - t13 * t14 * b - t0;
    const T t16 = T(2) * t15 * t6 * b + c * t13 * t14 - T(2) * J2;
    const T t17 = t6 * t7 + c * t15 * t6 - T(2) * t6 * b * t16;
    G_ap = (T(1) / T(2)) * t17 * in.w[3] * t6 + (T(1) / T(2)) * t13 * t14 * in.w[0] - (T(1) / T(2)) * t15 * t6 * in.w[1] - (T(1) / T(2)) * in.w[2] * t6 * t16;
    G_ab = (T(1) / T(2)) * t17 * in.w[2] * t6 + (T(1) / T(2)) * in.w[3] * t6 * (T(2) * t17 * t6 * b + c * t6 * t16 + T(2) * t6 * t8) - (T(1) / T(2)) * t15 * t6 * in.w[0] - (T(1) / T(2)) * t6 * t16 * in.w[1];
  }
  const T g_factor = -T(2) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 30 +, 38 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 845 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
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
/// Operations: 37 +, 67 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1548 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / D;
    const T t6 = t3 * t3;
    const T t7 = t4 * t4;
    const T t8 = T(2) * (a_minus_b * t3 + b * t4) * t5 * a + t6 * a_minus_b * t3 + b * t4 * t7;
    G_ap = (T(1) / T(3)) * t8 * t5 * in.w[0];
    G_ab = (T(1) / T(3)) * (b * t8 * t5 + t4 * t7 - t6 * t3) * in.w[0] / a;
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 37 +, 70 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1570 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = b * t3 + t4 * a_minus_b;
    const T t6 = T(1) / D;
    F = t5 * in.w[0] * t6;
    const T t7 = t4 * t4;
    const T t8 = t3 * t3;
    const T t9 = T(2) * a * t5 * t6 + t4 * a_minus_b * t7 + b * t8 * t3;
    G_ap = (T(1) / T(3)) * t9 * in.w[0] * t6;
    G_ab = (T(1) / T(3)) * (t8 * t3 + b * t9 * t6 - t4 * t7) * in.w[0] / a;
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Returns false where segment_cauchy_i3_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 37 +, 70 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i3_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * b + t5 * a_minus_b;
    F = t3 * in.w[0] * t6;
    const T t7 = t5 * t5;
    const T t8 = t4 * t4;
    const T t9 = T(2) * a * t3 * t6 + t7 * t5 * a_minus_b + t8 * t4 * b;
    G_ap = (T(1) / T(3)) * t9 * t3 * in.w[0];
    G_ab = (T(1) / T(3)) * (t9 * t3 * b + t8 * t4 - t7 * t5) * in.w[0] / a;
  }
  const T g_factor = -T(3) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 33 +, 44 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1535 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * b;
    F = t3 * in.w[0] * t6 + (t5 + t3 * b * t6 - t4) * in.w[1] / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 41 +, 81 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2241 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t3 * a_minus_b + b * t5;
    const T t7 = T(1) / D;
    const T t8 = t5 * t5;
    const T t9 = t4 * t3 * a_minus_b + T(2) * t6 * t7 * a + b * t5 * t8;
    const T t10 = t4 * t3 - b * t9 * t7 - t5 * t8;
    const T t11 = T(1) / a;
    G_ap = (T(1) / T(3)) * t9 * in.w[0] * t7 - (T(1) / T(3)) * t10 * in.w[1] * t11;
    G_ab = -(T(1) / T(3)) * in.w[0] * t10 * t11 - (T(1) / T(3)) * (c * t9 * t7 + T(2) * b * t10 * t11 - T(3) * t6 * t7) * in.w[1] * t11;
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 44 +, 88 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 273 +, 1007 ×, 124 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = b * t5 * t4;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t7 * a_minus_b * t8;
    const T t10 = J_downward<T>(5, a, D, -b, c, a_minus_b, q1);
    const T t11 = t6 + t9 - T(3) * t10 * D;
    F = -(T(1) / T(2)) * in.w[1] * t3 * (t11 * b * t3 + T(2) * t7 - T(2) * t4) - (T(1) / T(2)) * t11 * in.w[0] * t3;
    const T t12 = t5 * t4;
    const T t13 = t12 + T(3) * t10 * b - t7 * t8;
    G_ap = (T(1) / T(3)) * in.w[1] * t13 * t3 + t10 * in.w[0];
    G_ab = (T(1) / T(3)) * in.w[0] * t13 * t3 - (T(1) / T(6)) * (T(3) * t11 * t3 + T(6) * t10 * c - T(4) * b * t13 * t3) * in.w[1] * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t14 = T(1) / r0;
    const T t15 = T(1) / r1;
    const T t16 = b * t14 + t15 * a_minus_b;
    const T t17 = T(1) / D;
    const T t18 = T(1) / a;
    F = t16 * in.w[0] * t17 + in.w[1] * (t16 * b * t17 + t14 - t15) * t18;
    const T t19 = t14 * t14;
    const T t20 = t19 * t14;
    const T t21 = b * t19 * t14;
    const T t22 = t15 * t15;
    const T t23 = t15 * a_minus_b * t22;
    const T t24 = t21 + t23 + T(2) * t16 * t17 * a;
    const T t25 = t20 + t24 * b * t17 - t15 * t22;
    G_ap = (T(1) / T(3)) * t25 * in.w[1] * t18 + (T(1) / T(3)) * t24 * in.w[0] * t17;
    G_ab = (T(1) / T(3)) * (T(3) * t16 * t17 + T(2) * t25 * b * t18 - t24 * c * t17) * in.w[1] * t18 + (T(1) / T(3)) * t25 * in.w[0] * t18;
  }
  const T g_factor = -T(3) * length * in.s;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Returns false where segment_cauchy_i3_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 44 +, 88 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i3_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = t3 * a_minus_b + t4 * b;
    const T t6 = T(1) / D;
    const T t7 = T(1) / a;
    F = t5 * t6 * in.w[0] - t7 * in.w[1] * (t3 - t5 * t6 * b - t4);
    const T t8 = t3 * t3;
    const T t9 = t4 * t4;
    const T t10 = T(2) * t5 * a * t6 + t3 * a_minus_b * t8 + t4 * b * t9;
    const T t11 = t6 * b * t10 + t4 * t9 - t3 * t8;
    G_ap = (T(1) / T(3)) * t7 * in.w[1] * t11 + (T(1) / T(3)) * t6 * t10 * in.w[0];
    G_ab = (T(1) / T(3)) * t7 * in.w[1] * (T(2) * t7 * b * t11 + T(3) * t5 * t6 - t6 * t10 * c) + (T(1) / T(3)) * t7 * t11 * in.w[0];
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 37 +, 58 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 266 +, 970 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
  const T t0 = b * a_minus_b;
  if (t0 >= T(0)) {
    // P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D
    const T t1 = T(1) / D;
    const T t2 = sqrt(a);
    const T t3 = b * r1;
    X = t1 * t2 * (t3 + r0 * a_minus_b);
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -b * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = J_downward<T>(3, a, D, -b, c, a_minus_b, q1);
    const T t12 = T(1) / a;
    const T t13 = T(1) / r1;
    const T t14 = T(1) / r0;
    const T t15 = t13 - b * t11 - t14;
    F = in.w[0] * t11 + t12 * (J1 - T(2) * b * t15 * t12 - t11 * c) * in.w[2] - in.w[1] * t15 * t12;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = T(1) / D;
    const T t17 = T(1) / r1;
    const T t18 = T(1) / r0;
    const T t19 = t17 * a_minus_b + b * t18;
    const T t20 = T(1) / a;
    const T t21 = t17 - b * t16 * t19 - t18;
    F = in.w[0] * t16 * t19 + t20 * (J1 - T(2) * b * t21 * t20 - c * t16 * t19) * in.w[2] - t21 * in.w[1] * t20;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 47 +, 96 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2936 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t3 * b + t5 * a_minus_b;
    const T t7 = T(1) / D;
    const T t8 = t5 * t5;
    const T t9 = t3 * t4 * b + T(2) * t6 * t7 * a + t5 * a_minus_b * t8;
    const T t10 = t3 * t4 + t9 * t7 * b - t5 * t8;
    const T t11 = T(1) / a;
    const T t12 = c * t9 * t7 - T(3) * t6 * t7 - T(2) * t10 * t11 * b;
    G_ap = (T(1) / T(3)) * t10 * in.w[1] * t11 + (T(1) / T(3)) * t9 * t7 * in.w[0] - (T(1) / T(3)) * t12 * in.w[2] * t11;
    G_ab = (T(1) / T(3)) * in.w[2] * t11 * (T(3) * (t6 * t7 * b + t3 - t5) * t11 - T(2) * t12 * t11 * b - t10 * c * t11) + (T(1) / T(3)) * t10 * t11 * in.w[0] - (T(1) / T(3)) * t12 * in.w[1] * t11;
  }
  const T g_factor = -T(3) * in.s * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 52 +, 114 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 281 +, 1036 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
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
    X = (a_minus_b - b) * t4 / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
    G_ab = M_flat[5] * in.w[0] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t11 = T(1) / a;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12 * b;
    const T t15 = T(1) / r1;
    const T t16 = t15 * t15;
    const T t17 = t16 * t15 * a_minus_b;
    const T t18 = -b;
    const T t19 = J_downward<T>(5, a, D, t18, c, a_minus_b, q1);
    const T t20 = t14 + t17 - T(3) * D * t19;
    const T t21 = T(2) * t12 - t11 * b * t20 - T(2) * t15;
    F = (T(1) / T(2)) * in.w[1] * t11 * t21 + (T(1) / T(2)) * (T(2) * J1 + c * t11 * t20 + T(2) * t11 * t21 * b) * in.w[2] * t11 - (T(1) / T(2)) * t11 * t20 * in.w[0];
    const T t22 = T(3) * t19 * b + t13 * t12 - t16 * t15;
    const T t23 = T(3) * t11 * t20 + T(6) * c * t19 - T(4) * t11 * t22 * b;
    G_ap = t19 * in.w[0] + (T(1) / T(3)) * in.w[1] * t11 * t22 - (T(1) / T(6)) * in.w[2] * t11 * t23;
    G_ab = (T(1) / T(3)) * t11 * t22 * in.w[0] - (T(1) / T(6)) * (T(2) * c * t11 * t22 + T(2) * t11 * t23 * b - T(3) * t11 * t21) * in.w[2] * t11 - (T(1) / T(6)) * in.w[1] * t11 * t23;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t24 = T(1) / a;
    const T t25 = T(1) / r0;
    const T t26 = T(1) / r1;
    const T t27 = t25 * b + t26 * a_minus_b;
    const T t28 = T(1) / D;
    const T t29 = t27 * t28 * b + t25 - t26;
    F = (J1 + T(2) * t24 * t29 * b - c * t27 * t28) * in.w[2] * t24 + t27 * t28 * in.w[0] + in.w[1] * t24 * t29;
    const T t30 = t25 * t25;
    const T t31 = t30 * t25 * b;
    const T t32 = t26 * t26;
    const T t33 = t32 * t26 * a_minus_b;
    const T t34 = t31 + T(2) * t27 * t28 * a + t33;
    const T t35 = t32 * t26 - t30 * t25 - t34 * t28 * b;
    const T t36 = T(2) * t35 * t24 * b + t34 * c * t28 - T(3) * t27 * t28;
    G_ap = (T(1) / T(3)) * t34 * t28 * in.w[0] - (T(1) / T(3)) * t35 * in.w[1] * t24 - (T(1) / T(3)) * in.w[2] * t24 * t36;
    G_ab = (T(1) / T(3)) * (t35 * c * t24 + T(3) * t24 * t29 - T(2) * t24 * t36 * b) * in.w[2] * t24 - (T(1) / T(3)) * t35 * t24 * in.w[0] - (T(1) / T(3)) * in.w[1] * t24 * t36;
  }
  const T g_factor = -T(3) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Returns false where segment_cauchy_i3_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 114 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i3_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + in.s * cross_cross) * in.s;
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
    X = (t1 + b * r1) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = (a_minus_b - b) * t4 / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + in.w[2] * M_flat[6];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / D;
    const T t12 = T(1) / r1;
    const T t13 = T(1) / r0;
    const T t14 = a_minus_b * t12 + b * t13;
    const T t15 = b * t11 * t14 + t13 - t12;
    const T t16 = T(1) / a;
    F = t15 * in.w[1] * t16 + in.w[0] * t11 * t14 + (J1 + T(2) * b * t15 * t16 - c * t11 * t14) * in.w[2] * t16;
    const T t17 = t12 * t12;
    const T t18 = a_minus_b * t17 * t12;
    const T t19 = t13 * t13;
    const T t20 = b * t19 * t13;
    const T t21 = t18 + T(2) * t11 * a * t14 + t20;
    const T t22 = t17 * t12 - t19 * t13 - b * t21 * t11;
    const T t23 = T(3) * t11 * t14 - t21 * c * t11 - T(2) * b * t22 * t16;
    G_ap = (T(1) / T(3)) * in.w[0] * t21 * t11 + (T(1) / T(3)) * t23 * in.w[2] * t16 - (T(1) / T(3)) * t22 * in.w[1] * t16;
    G_ab = (T(1) / T(3)) * in.w[2] * t16 * (T(2) * b * t23 * t16 + T(3) * t15 * t16 + t22 * c * t16) + (T(1) / T(3)) * t23 * in.w[1] * t16 - (T(1) / T(3)) * t22 * in.w[0] * t16;
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 42 +, 67 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 271 +, 979 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  const T J1 = t7 * asinh(X);
  T F;
  const T t8 = D - T(2) * a * a;
  const T t9 = -b * a_minus_b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[3] * M_flat[3];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_3 = J_downward(…)
    const T t11 = T(1) / a;
    const T t12 = T(1) / r1;
    const T t13 = J_downward<T>(3, a, D, -b, c, a_minus_b, q1);
    const T t14 = T(1) / r0;
    const T t15 = t12 - t13 * b - t14;
    const T t16 = c * t13 + T(2) * t15 * t11 * b - J1;
    F = in.w[3] * t11 * (c * t15 * t11 - T(2) * t11 * b * t16 - t11 * (r0 - J1 * b - r1)) + in.w[0] * t13 - in.w[2] * t11 * t16 - t15 * t11 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t17 = T(1) / a;
    const T t18 = T(1) / r1;
    const T t19 = T(1) / D;
    const T t20 = T(1) / r0;
    const T t21 = t18 * a_minus_b + t20 * b;
    const T t22 = t18 - t19 * t21 * b - t20;
    const T t23 = T(2) * t17 * t22 * b + c * t19 * t21 - J1;
    F = in.w[3] * t17 * (c * t17 * t22 - T(2) * t17 * b * t23 - t17 * (r0 - J1 * b - r1)) + t19 * in.w[0] * t21 - in.w[2] * t17 * t23 - t17 * t22 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 54 +, 120 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 283 +, 1039 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + in.w[3] * M_flat[3];
    G_ab = M_flat[3] * in.w[2] + M_flat[4] * in.w[3] + M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t11 = -b;
    const T t12 = J_downward<T>(5, a, D, t11, c, a_minus_b, q1);
    const T t13 = T(1) / a;
    const T t14 = T(1) / r0;
    const T t15 = t14 * t14;
    const T t16 = t14 * t15;
    const T t17 = T(1) / r1;
    const T t18 = t17 * t17;
    const T t19 = T(3) * b * t12 + t16 - t17 * t18;
    const T t20 = t17 * a_minus_b * t18;
    const T t21 = b * t14 * t15;
    const T t22 = t20 + t21 - T(3) * D * t12;
    const T t23 = T(3) * t13 * t22 + T(6) * t12 * c - T(4) * t13 * b * t19;
    const T t24 = T(2) * t14 - T(2) * t17 - t13 * b * t22;
    const T t25 = T(2) * t13 * t19 * c + T(2) * t13 * t23 * b - T(3) * t24 * t13;
    G_ap = in.w[0] * t12 + (T(1) / T(3)) * t13 * t19 * in.w[1] - (T(1) / T(6)) * t13 * t23 * in.w[2] - (T(1) / T(6)) * t13 * in.w[3] * t25;
    G_ab = (T(1) / T(6)) * t13 * in.w[3] * (T(3) * t13 * (T(2) * t24 * t13 * b + T(2) * J1 + t13 * t22 * c) + t13 * t23 * c - T(2) * t13 * b * t25) + (T(1) / T(3)) * t13 * in.w[0] * t19 - (T(1) / T(6)) * t13 * t25 * in.w[2] - (T(1) / T(6)) * t13 * t23 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t26 = T(1) / D;
    const T t27 = T(1) / r0;
    const T t28 = T(1) / r1;
    const T t29 = b * t27 + t28 * a_minus_b;
    const T t30 = t28 * t28;
    const T t31 = t28 * a_minus_b * t30;
    const T t32 = t27 * t27;
    const T t33 = b * t27 * t32;
    const T t34 = T(2) * a * t26 * t29 + t31 + t33;
    const T t35 = T(1) / a;
    const T t36 = t27 * t32;
    const T t37 = t26 * b * t34 + t36 - t28 * t30;
    const T t38 = T(2) * t35 * t37 * b + T(3) * t26 * t29 - t26 * t34 * c;
    const T t39 = t27 + t26 * t29 * b - t28;
    const T t40 = T(2) * t35 * b * t38 + T(3) * t35 * t39 - t35 * t37 * c;
    G_ap = (T(1) / T(3)) * t26 * in.w[0] * t34 + (T(1) / T(3)) * t35 * t37 * in.w[1] + (T(1) / T(3)) * t35 * t38 * in.w[2] + (T(1) / T(3)) * t35 * in.w[3] * t40;
    G_ab = (T(1) / T(3)) * t35 * in.w[1] * t38 + (T(1) / T(3)) * t35 * t40 * in.w[2] + (T(1) / T(3)) * t35 * in.w[0] * t37 + (T(1) / T(3)) * (T(3) * t35 * (T(2) * t35 * b * t39 + J1 - t26 * t29 * c) + T(2) * t35 * b * t40 - t35 * t38 * c) * t35 * in.w[3];
  }
  const T g_factor = -T(3) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Operations: 61 +, 136 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
/// Longest path: 290 +, 1060 ×, 126 /, 7 sqrt, 0 atan, 3 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T X;
  const T t0 = a_minus_b * b;
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
    X = t4 * (a_minus_b - b) / (t5 - r1 * b);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = asinh(X) * t7;
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0];
    G_ab = in.w[3] * M_flat[9] + M_flat[6] * in.w[0] + in.w[2] * M_flat[8] + M_flat[7] * in.w[1];
  } else if (t9 >= T(0) && t10 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_5 = J_downward(…)
    const T t11 = T(1) / a;
    const T t12 = T(1) / r0;
    const T t13 = T(1) / r1;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13 * a_minus_b;
    const T t16 = t12 * t12;
    const T t17 = t16 * t12 * b;
    const T t18 = -b;
    const T t19 = J_downward<T>(5, a, D, t18, c, a_minus_b, q1);
    const T t20 = t15 + t17 - T(3) * D * t19;
    const T t21 = T(2) * t12 - T(2) * t13 - t20 * t11 * b;
    const T t22 = T(2) * J1 + T(2) * t11 * b * t21 + c * t20 * t11;
    const T t23 = r0 - J1 * b - r1;
    F = (T(1) / T(2)) * t11 * in.w[1] * t21 + (T(1) / T(2)) * t22 * in.w[2] * t11 - (T(1) / T(2)) * t11 * in.w[3] * (c * t11 * t21 + T(2) * t11 * t23 - T(2) * t22 * t11 * b) - (T(1) / T(2)) * t20 * t11 * in.w[0];
    const T t24 = T(3) * t19 * b + t16 * t12 - t14 * t13;
    const T t25 = T(6) * c * t19 + T(3) * t20 * t11 - T(4) * t24 * t11 * b;
    const T t26 = T(2) * c * t24 * t11 + T(2) * t11 * t25 * b - T(3) * t11 * t21;
    G_ap = (T(1) / T(3)) * t24 * t11 * in.w[1] + t19 * in.w[0] - (T(1) / T(6)) * t26 * t11 * in.w[3] - (T(1) / T(6)) * in.w[2] * t11 * t25;
    G_ab = (T(1) / T(3)) * t24 * t11 * in.w[0] + (T(1) / T(6)) * (T(3) * t22 * t11 + c * t11 * t25 - T(2) * t26 * t11 * b) * t11 * in.w[3] - (T(1) / T(6)) * in.w[2] * t26 * t11 - (T(1) / T(6)) * t11 * t25 * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t27 = T(1) / a;
    const T t28 = T(1) / D;
    const T t29 = T(1) / r0;
    const T t30 = T(1) / r1;
    const T t31 = t29 * b + t30 * a_minus_b;
    const T t32 = t28 * t31 * b + t29 - t30;
    const T t33 = J1 + T(2) * t27 * t32 * b - c * t28 * t31;
    const T t34 = r0 - J1 * b - r1;
    F = in.w[2] * t27 * t33 + t27 * t32 * in.w[1] + t28 * in.w[0] * t31 - t27 * (c * t27 * t32 + t27 * t34 - T(2) * t27 * t33 * b) * in.w[3];
    const T t35 = t30 * t30;
    const T t36 = t35 * t30 * a_minus_b;
    const T t37 = t29 * t29;
    const T t38 = t37 * t29 * b;
    const T t39 = t36 + t38 + T(2) * t28 * a * t31;
    const T t40 = t35 * t30 - t28 * t39 * b - t37 * t29;
    const T t41 = T(2) * t27 * b * t40 + c * t28 * t39 - T(3) * t28 * t31;
    const T t42 = T(3) * t27 * t32 + c * t27 * t40 - T(2) * t27 * t41 * b;
    G_ap = (T(1) / T(3)) * t28 * t39 * in.w[0] + (T(1) / T(3)) * t42 * t27 * in.w[3] - (T(1) / T(3)) * t27 * t40 * in.w[1] - (T(1) / T(3)) * in.w[2] * t27 * t41;
    G_ab = (T(1) / T(3)) * in.w[2] * t42 * t27 + (T(1) / T(3)) * (T(3) * t27 * t33 + c * t27 * t41 + T(2) * t42 * t27 * b) * t27 * in.w[3] - (T(1) / T(3)) * t27 * t41 * in.w[1] - (T(1) / T(3)) * t27 * in.w[0] * t40;
  }
  const T g_factor = -T(3) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−3/2) dt
/// Returns false where segment_cauchy_i3_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 136 ×, 6 /, 5 sqrt, 0 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i3_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
    const T t2 = sqrt(a);
    const T t3 = T(1) / D;
    X = (t1 + b * r1) * t2 * t3;
  } else {
    // P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)
    const T t4 = sqrt(a);
    const T t5 = a_minus_b * r0;
    X = (a_minus_b - b) * t4 / (t5 - b * r1);
  }
  const T t6 = sqrt(a);
  const T t7 = T(1) / t6;
  const T J1 = t7 * asinh(X);
  T F;
  T G_ap;
  T G_ab;
  const T t8 = D - T(2) * a * a;
  const T t9 = -a_minus_b * b;
  const T t10 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t8 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[8] * in.w[3] + in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
    G_ab = M_flat[9] * in.w[3] + M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t11 = T(1) / a;
    const T t12 = T(1) / r1;
    const T t13 = T(1) / D;
    const T t14 = T(1) / r0;
    const T t15 = a_minus_b * t12 + b * t14;
    const T t16 = t12 - b * t13 * t15 - t14;
    const T t17 = b * J1 + r1 - r0;
    const T t18 = T(2) * b * t16 * t11 + c * t13 * t15 - J1;
    F = t11 * in.w[3] * (t16 * c * t11 + t17 * t11 - T(2) * b * t18 * t11) + t13 * in.w[0] * t15 - t18 * in.w[2] * t11 - t16 * in.w[1] * t11;
    const T t19 = t12 * t12;
    const T t20 = t14 * t14;
    const T t21 = a_minus_b * t19 * t12 + b * t20 * t14 + T(2) * a * t13 * t15;
    const T t22 = t20 * t14;
    const T t23 = b * t21 * t13 + t22 - t19 * t12;
    const T t24 = t21 * c * t13 - T(3) * t13 * t15 - T(2) * b * t11 * t23;
    const T t25 = T(2) * b * t24 * t11 + T(3) * t16 * t11 + c * t11 * t23;
    G_ap = (T(1) / T(3)) * in.w[1] * t11 * t23 + (T(1) / T(3)) * t21 * t13 * in.w[0] - (T(1) / T(3)) * t24 * in.w[2] * t11 - (T(1) / T(3)) * t25 * t11 * in.w[3];
    G_ab = (T(1) / T(3)) * t11 * t23 * in.w[0] + (T(1) / T(3)) * (t24 * c * t11 - T(3) * t18 * t11 - T(2) * b * t25 * t11) * t11 * in.w[3] - (T(1) / T(3)) * t25 * in.w[2] * t11 - (T(1) / T(3)) * t24 * in.w[1] * t11;
  }
  const T g_factor = -T(3) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t9 >= T(0) && t10 >= T(0)) && !(t8 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 34 +, 46 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 851 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    F = (T(1) / T(2)) * t5 * in.w[0] * (J2 * a + b / c + a_minus_b / q1);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 41 +, 73 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1554 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = T(2) * b * t7 + T(3) * t5 * a * (a_minus_b * t8 + b * t6 + a * J2) + T(2) * a_minus_b * t9;
    G_ap = (T(1) / T(8)) * t5 * in.w[0] * t10;
    G_ab = (T(1) / T(8)) * (t5 * t10 * b + T(2) * t7 - T(2) * t9) * in.w[0] / a;
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 41 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1577 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / q1;
    const T t6 = T(1) / c;
    const T t7 = t5 * a_minus_b + J2 * a + t6 * b;
    const T t8 = T(1) / D;
    F = (T(1) / T(2)) * t7 * t8 * in.w[0];
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t9 * a_minus_b + T(2) * t10 * b + T(3) * t7 * a * t8;
    G_ap = (T(1) / T(8)) * t8 * in.w[0] * t11;
    G_ab = (T(1) / T(8)) * (T(2) * t10 + t8 * t11 * b - T(2) * t9) * in.w[0] / a;
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Returns false where segment_cauchy_i4_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 77 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i4_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t6 * b + t7 * a_minus_b + J2 * a;
    F = (T(1) / T(2)) * t5 * in.w[0] * t8;
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t9 * a_minus_b + T(2) * t10 * b + T(3) * a * t5 * t8;
    G_ap = (T(1) / T(8)) * t11 * t5 * in.w[0];
    G_ab = -(T(1) / T(8)) * in.w[0] * (T(2) * t9 - T(2) * t10 - t11 * t5 * b) / a;
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 37 +, 52 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1541 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = a * J2 + b * t5 + a_minus_b * t6;
    const T t8 = T(1) / D;
    F = (T(1) / T(2)) * in.w[0] * t7 * t8 + (T(1) / T(2)) * (t5 + b * t7 * t8 - t6) * in.w[1] / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 45 +, 87 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2247 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[0] * M_flat[1] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / a;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / c;
    const T t10 = a * J2 + t9 * b + a_minus_b * t6;
    const T t11 = t9 * t9;
    const T t12 = T(2) * a_minus_b * t7 + T(3) * t8 * t10 * a + T(2) * t11 * b;
    const T t13 = t12 * t8 * b + T(2) * t11 - T(2) * t7;
    G_ap = (T(1) / T(8)) * t5 * in.w[1] * t13 + (T(1) / T(8)) * t12 * t8 * in.w[0];
    G_ab = (T(1) / T(8)) * in.w[0] * t5 * t13 - (T(1) / T(8)) * (c * t12 * t8 - T(2) * t5 * b * t13 - T(4) * t8 * t10) * t5 * in.w[1];
  }
  const T g_factor = -T(4) * in.s * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 48 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2284 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(4, 6, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = b * t6 + J2 * a + t7 * a_minus_b;
    const T t9 = T(1) / D;
    F = (T(1) / T(2)) * in.w[1] * t5 * (t6 + b * t8 * t9 - t7) + (T(1) / T(2)) * t8 * in.w[0] * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(2) * t10 * a_minus_b + T(2) * b * t11 + T(3) * t8 * t9 * a;
    const T t13 = T(2) * t10 - t12 * b * t9 - T(2) * t11;
    G_ap = (T(1) / T(8)) * t12 * in.w[0] * t9 - (T(1) / T(8)) * t13 * in.w[1] * t5;
    G_ab = -(T(1) / T(8)) * (T(2) * b * t13 * t5 + t12 * c * t9 - T(4) * t8 * t9) * in.w[1] * t5 - (T(1) / T(8)) * in.w[0] * t13 * t5;
  }
  const T g_factor = -T(4) * length * in.s;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Returns false where segment_cauchy_i4_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 48 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i4_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = J2 * a + b * t6 + a_minus_b * t7;
    const T t9 = T(1) / a;
    F = (T(1) / T(2)) * in.w[0] * t5 * t8 - (T(1) / T(2)) * (t7 - t5 * b * t8 - t6) * t9 * in.w[1];
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * t5 * a * t8 + T(2) * a_minus_b * t10 + T(2) * b * t11;
    const T t13 = t5 * b * t12 + T(2) * t11 - T(2) * t10;
    G_ap = (T(1) / T(8)) * t13 * t9 * in.w[1] + (T(1) / T(8)) * in.w[0] * t5 * t12;
    G_ab = (T(1) / T(8)) * t13 * in.w[0] * t9 + (T(1) / T(8)) * (T(2) * t13 * t9 * b + T(4) * t5 * t8 - t5 * t12 * c) * t9 * in.w[1];
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 40 +, 62 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2233 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(4, 4, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = b * t7 + a * J2 + t8 * a_minus_b;
    const T t10 = t6 * t9 * b + t7 - t8;
    F = (T(1) / T(2)) * t5 * (T(2) * J2 + T(2) * t5 * b * t10 - t6 * t9 * c) * in.w[2] + (T(1) / T(2)) * t5 * in.w[1] * t10 + (T(1) / T(2)) * t6 * t9 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 51 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2942 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2];
    G_ab = M_flat[1] * in.w[0] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = a_minus_b * t9 + b * t6 + a * J2;
    const T t11 = t9 * t9;
    const T t12 = T(2) * b * t7 + T(3) * t8 * a * t10 + T(2) * a_minus_b * t11;
    const T t13 = T(2) * t7 + t8 * b * t12 - T(2) * t11;
    const T t14 = t8 * c * t12 - T(4) * t8 * t10 - T(2) * t5 * b * t13;
    G_ap = (T(1) / T(8)) * t5 * t13 * in.w[1] + (T(1) / T(8)) * t8 * in.w[0] * t12 - (T(1) / T(8)) * t5 * in.w[2] * t14;
    G_ab = (T(1) / T(8)) * t5 * t13 * in.w[0] - (T(1) / T(8)) * t5 * in.w[2] * (T(2) * t5 * b * t14 + T(4) * t5 * (t9 - t6 - t8 * t10 * b) + t5 * t13 * c) - (T(1) / T(8)) * t5 * t14 * in.w[1];
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 55 +, 118 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 285 +, 1039 ×, 124 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = M_flat[5] * in.w[0] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = T(4) * t4 * D - t6 * b - a_minus_b * t8;
    const T t10 = T(3) * t7 - T(2) * t3 * b * t9 - T(3) * t5;
    F = (T(1) / T(3)) * t3 * in.w[0] * t9 - (T(1) / T(3)) * (t3 * t10 * b + c * t3 * t9 - (T(2) * D * t3 * t9 - T(3) * a_minus_b * t7 - T(3) * t5 * b) * t3) * t3 * in.w[2] - (T(1) / T(6)) * in.w[1] * t3 * t10;
    const T t11 = t6 + T(4) * t4 * b - t8;
    const T t12 = T(6) * c * t4 - T(3) * t3 * t11 * b - T(2) * t3 * t9;
    G_ap = t4 * in.w[0] + (T(1) / T(4)) * in.w[1] * t3 * t11 - (T(1) / T(6)) * t3 * in.w[2] * t12;
    G_ab = (T(1) / T(4)) * t3 * t11 * in.w[0] - (T(1) / T(6)) * in.w[1] * t3 * t12 - (T(1) / T(12)) * t3 * in.w[2] * (T(3) * c * t3 * t11 + T(4) * t3 * t12 * b + T(2) * t3 * t10);
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t13 = sqrt(D);
    const T t14 = T(1) / t13;
    const T J2 = t14 * atan2(t13, c_minus_b);
    const T t15 = T(1) / D;
    const T t16 = T(1) / q1;
    const T t17 = T(1) / c;
    const T t18 = J2 * a + a_minus_b * t16 + t17 * b;
    const T t19 = t16 - t15 * b * t18 - t17;
    const T t20 = T(1) / a;
    F = (T(1) / T(2)) * t15 * t18 * in.w[0] - (T(1) / T(2)) * in.w[1] * t19 * t20 - (T(1) / T(2)) * (T(2) * t19 * t20 * b + c * t15 * t18 - T(2) * J2) * t20 * in.w[2];
    const T t21 = t17 * t17;
    const T t22 = t16 * t16;
    const T t23 = T(3) * t15 * a * t18 + T(2) * t21 * b + T(2) * a_minus_b * t22;
    const T t24 = T(2) * t21 + t15 * b * t23 - T(2) * t22;
    const T t25 = T(4) * t15 * t18 + T(2) * t20 * t24 * b - c * t15 * t23;
    G_ap = (T(1) / T(8)) * in.w[1] * t20 * t24 + (T(1) / T(8)) * t15 * t23 * in.w[0] + (T(1) / T(8)) * t25 * t20 * in.w[2];
    G_ab = (T(1) / T(8)) * t20 * t24 * in.w[0] + (T(1) / T(8)) * t25 * in.w[1] * t20 - (T(1) / T(8)) * (c * t20 * t24 + T(4) * t19 * t20 - T(2) * t25 * t20 * b) * t20 * in.w[2];
  }
  const T g_factor = -T(4) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Returns false where segment_cauchy_i4_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 55 +, 118 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i4_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
    G_ab = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = a * J2 + b * t5 + a_minus_b * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / a;
    const T t10 = t7 * b * t8 + t5 - t6;
    F = (T(1) / T(2)) * t7 * in.w[0] * t8 + (T(1) / T(2)) * t9 * in.w[1] * t10 - (T(1) / T(2)) * t9 * in.w[2] * (t7 * c * t8 - T(2) * t9 * b * t10 - T(2) * J2);
    const T t11 = t6 * t6;
    const T t12 = t5 * t5;
    const T t13 = T(2) * a_minus_b * t11 + T(3) * a * t7 * t8 + T(2) * b * t12;
    const T t14 = T(2) * t12 + b * t13 * t8 - T(2) * t11;
    const T t15 = T(4) * t7 * t8 + T(2) * t9 * b * t14 - t13 * c * t8;
    G_ap = (T(1) / T(8)) * in.w[0] * t13 * t8 + (T(1) / T(8)) * t9 * t14 * in.w[1] + (T(1) / T(8)) * t9 * in.w[2] * t15;
    G_ab = (T(1) / T(8)) * t9 * in.w[2] * (T(4) * t9 * t10 + T(2) * t9 * b * t15 - t9 * t14 * c) + (T(1) / T(8)) * t9 * t15 * in.w[1] + (T(1) / T(8)) * t9 * t14 * in.w[0];
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 44 +, 74 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 274 +, 989 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T t0 = T(1) / c;
  const T log_ratio = log(t0 * q1);
  T F;
  const T t1 = D - T(2) * a * a;
  const T t2 = -b * a_minus_b;
  const T t3 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(4, 4, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_4 = J_downward(…)
    const T t4 = J_downward<T>(4, a, D, -b, c, a_minus_b, q1);
    const T t5 = T(1) / q1;
    const T t6 = a_minus_b * t5;
    const T t7 = b * t0;
    const T t8 = t6 + t7 - T(2) * t4 * D;
    const T t9 = T(1) / a;
    const T t10 = t5 - T(2) * b * t4 - t0;
    const T t11 = t8 * t9 + c * t4 + b * t10 * t9;
    F = in.w[0] * t4 - (T(1) / T(2)) * ((T(2) * b * t8 * t9 - log_ratio) * t9 + T(4) * b * t11 * t9 - c * t10 * t9) * t9 * in.w[3] - in.w[2] * t11 * t9 - (T(1) / T(2)) * in.w[1] * t10 * t9;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t12 = sqrt(D);
    const T t13 = T(1) / t12;
    const T J2 = atan2(t12, c_minus_b) * t13;
    const T t14 = T(1) / q1;
    const T t15 = a_minus_b * t14;
    const T t16 = b * t0;
    const T t17 = t15 + J2 * a + t16;
    const T t18 = T(1) / D;
    const T t19 = t14 - t0 - t17 * b * t18;
    const T t20 = T(1) / a;
    const T t21 = T(2) * J2 - t17 * c * t18 - T(2) * b * t19 * t20;
    F = (T(1) / T(2)) * t21 * in.w[2] * t20 + (T(1) / T(2)) * in.w[0] * t17 * t18 + (T(1) / T(2)) * (T(2) * b * t21 * t20 + (T(2) * J2 * b + log_ratio) * t20 + t19 * c * t20) * t20 * in.w[3] - (T(1) / T(2)) * in.w[1] * t19 * t20;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 57 +, 121 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3639 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ab = in.w[3] * M_flat[4] + M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[4] * in.w[3] + M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = b * t6 + t9 * a_minus_b + a * J2;
    const T t11 = t9 * t9;
    const T t12 = T(3) * t8 * a * t10 + T(2) * t11 * a_minus_b + T(2) * b * t7;
    const T t13 = T(2) * t7 + t8 * b * t12 - T(2) * t11;
    const T t14 = T(4) * t8 * t10 + T(2) * t5 * b * t13 - t8 * t12 * c;
    const T t15 = t9 - t6 - t8 * b * t10;
    const T t16 = T(4) * t5 * t15 + t5 * c * t13 - T(2) * t5 * b * t14;
    G_ap = (T(1) / T(8)) * t5 * t13 * in.w[1] + (T(1) / T(8)) * t8 * in.w[0] * t12 + (T(1) / T(8)) * t5 * in.w[2] * t14 - (T(1) / T(8)) * t5 * t16 * in.w[3];
    G_ab = (T(1) / T(8)) * t5 * t14 * in.w[1] + (T(1) / T(8)) * t5 * in.w[0] * t13 - (T(1) / T(8)) * t5 * in.w[3] * (T(2) * t5 * t16 * b + t5 * t14 * c + T(4) * t5 * (t8 * t10 * c + T(2) * t5 * b * t15 - T(2) * J2)) - (T(1) / T(8)) * t5 * t16 * in.w[2];
  }
  const T g_factor = -T(4) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Operations: 63 +, 143 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
/// Longest path: 293 +, 1065 ×, 124 /, 3 sqrt, 0 atan, 3 log/asinh.
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  const T t0 = T(1) / c;
  const T log_ratio = log(q1 * t0);
  T F;
  T G_ap;
  T G_ab;
  const T t1 = D - T(2) * a * a;
  const T t2 = -a_minus_b * b;
  const T t3 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0];
    G_ap = M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
    G_ab = in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6];
  } else if (t2 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_6 = J_downward(…)
    const T t4 = T(1) / a;
    const T t5 = J_downward<T>(6, a, D, -b, c, a_minus_b, q1);
    const T t6 = t0 * t0;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = T(4) * D * t5 - b * t6 - a_minus_b * t8;
    const T t10 = T(3) * t0 + T(2) * t4 * b * t9 - T(3) * t7;
    const T t11 = T(3) * a_minus_b * t7 + T(3) * b * t0 - T(2) * D * t4 * t9;
    const T t12 = t4 * b * t10 - t4 * c * t9 - t4 * t11;
    F = (T(1) / T(3)) * in.w[2] * t4 * t12 + (T(1) / T(3)) * t4 * in.w[0] * t9 + (T(1) / T(6)) * t4 * in.w[1] * t10 - (T(1) / T(6)) * t4 * in.w[3] * (t4 * t10 * c + t4 * (T(2) * t4 * t11 * b - T(3) * log_ratio) - T(4) * t4 * t12 * b);
    const T t13 = T(4) * t5 * b + t6 - t8;
    const T t14 = T(6) * t5 * c - T(3) * t4 * t13 * b - T(2) * t4 * t9;
    const T t15 = T(3) * t4 * t13 * c + T(4) * t4 * t14 * b - T(2) * t4 * t10;
    G_ap = in.w[0] * t5 + (T(1) / T(4)) * t4 * t13 * in.w[1] - (T(1) / T(12)) * t4 * in.w[3] * t15 - (T(1) / T(6)) * in.w[2] * t4 * t14;
    G_ab = (T(1) / T(4)) * t4 * in.w[0] * t13 - (T(1) / T(6)) * t4 * t14 * in.w[1] - (T(1) / T(6)) * (t4 * b * t15 - T(2) * t4 * t12 - t4 * t14 * c) * t4 * in.w[3] - (T(1) / T(12)) * in.w[2] * t4 * t15;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t16 = sqrt(D);
    const T t17 = T(1) / t16;
    const T J2 = t17 * atan2(t16, c_minus_b);
    const T t18 = T(1) / a;
    const T t19 = T(1) / D;
    const T t20 = T(1) / q1;
    const T t21 = J2 * a + a_minus_b * t20 + b * t0;
    const T t22 = t0 + t19 * t21 * b - t20;
    const T t23 = T(2) * J2 + T(2) * t18 * b * t22 - t19 * t21 * c;
    F = (T(1) / T(2)) * t18 * t22 * in.w[1] + (T(1) / T(2)) * t19 * t21 * in.w[0] + (T(1) / T(2)) * t18 * in.w[3] * (T(2) * t18 * t23 * b + t18 * (log_ratio + T(2) * J2 * b) - t18 * t22 * c) + (T(1) / T(2)) * in.w[2] * t18 * t23;
    const T t24 = t0 * t0;
    const T t25 = t20 * t20;
    const T t26 = T(3) * t19 * a * t21 + T(2) * b * t24 + T(2) * a_minus_b * t25;
    const T t27 = T(2) * t25 - t19 * b * t26 - T(2) * t24;
    const T t28 = T(2) * t18 * b * t27 + t19 * c * t26 - T(4) * t19 * t21;
    const T t29 = T(4) * t18 * t22 + t18 * c * t27 - T(2) * t28 * t18 * b;
    G_ap = (T(1) / T(8)) * t19 * in.w[0] * t26 + (T(1) / T(8)) * t18 * in.w[3] * t29 - (T(1) / T(8)) * in.w[2] * t28 * t18 - (T(1) / T(8)) * t18 * in.w[1] * t27;
    G_ab = (T(1) / T(8)) * t18 * (t28 * t18 * c + T(4) * t18 * t23 + T(2) * t18 * b * t29) * in.w[3] + (T(1) / T(8)) * in.w[2] * t18 * t29 - (T(1) / T(8)) * t28 * t18 * in.w[1] - (T(1) / T(8)) * t18 * in.w[0] * t27;
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−4/2) dt
/// Returns false where segment_cauchy_i4_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 143 ×, 5 /, 2 sqrt, 1 atan, 1 log/asinh.
template <class T>
bool segment_cauchy_i4_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(4, 6, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ap = M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + M_flat[8] * in.w[3];
    G_ab = M_flat[6] * in.w[0] + in.w[1] * M_flat[7] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    const T t6 = T(1) / q1;
    const T t7 = J2 * a + b * t0 + a_minus_b * t6;
    const T t8 = T(1) / D;
    const T t9 = t0 + b * t7 * t8 - t6;
    const T t10 = T(1) / a;
    const T t11 = c * t7 * t8 - T(2) * J2 - T(2) * b * t9 * t10;
    F = (T(1) / T(2)) * t7 * t8 * in.w[0] + (T(1) / T(2)) * in.w[1] * t9 * t10 + (T(1) / T(2)) * (t10 * (T(2) * b * J2 + log_ratio) - T(2) * b * t10 * t11 - t9 * c * t10) * t10 * in.w[3] - (T(1) / T(2)) * in.w[2] * t10 * t11;
    const T t12 = t6 * t6;
    const T t13 = t0 * t0;
    const T t14 = T(3) * t7 * a * t8 + T(2) * a_minus_b * t12 + T(2) * b * t13;
    const T t15 = T(2) * t12 - T(2) * t13 - b * t14 * t8;
    const T t16 = c * t14 * t8 + T(2) * b * t15 * t10 - T(4) * t7 * t8;
    const T t17 = T(4) * t9 * t10 + t15 * c * t10 - T(2) * b * t16 * t10;
    G_ap = (T(1) / T(8)) * t14 * t8 * in.w[0] + (T(1) / T(8)) * t17 * t10 * in.w[3] - (T(1) / T(8)) * t15 * in.w[1] * t10 - (T(1) / T(8)) * in.w[2] * t16 * t10;
    G_ab = (T(1) / T(8)) * in.w[2] * t17 * t10 - (T(1) / T(8)) * in.w[1] * t16 * t10 - (T(1) / T(8)) * t15 * t10 * in.w[0] - (T(1) / T(8)) * (T(4) * t10 * t11 - c * t16 * t10 - T(2) * b * t17 * t10) * t10 * in.w[3];
  }
  const T g_factor = -T(4) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t2 >= T(0) && t3 >= T(0)) && !(t1 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 32 +, 47 ×, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 848 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    F = (T(1) / T(3)) * t3 * in.w[0] * (T(2) * a * t3 * (a_minus_b * t4 + t5 * b) + t5 * b / c + a_minus_b * t4 / q1);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 39 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1551 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t4 * a_minus_b * t6 + T(3) * b * t7 * t9 + T(4) * t3 * a * (T(2) * t3 * a * (b * t7 + t4 * a_minus_b) + b * t7 * t8 + t4 * a_minus_b * t5);
    G_ap = (T(1) / T(15)) * in.w[0] * t3 * t10;
    G_ab = (T(1) / T(15)) * in.w[0] * (T(3) * t7 * t9 + t3 * b * t10 - T(3) * t4 * t6) / a;
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 39 +, 84 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1574 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * t4;
    const T t7 = t5 * t5;
    const T t8 = T(2) * t3 * a * (t4 * a_minus_b + t5 * b) + t4 * a_minus_b * t6 + t5 * b * t7;
    F = (T(1) / T(3)) * t8 * t3 * in.w[0];
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(3) * t5 * b * t9 + T(4) * t8 * t3 * a + T(3) * t4 * a_minus_b * t10;
    G_ap = (T(1) / T(15)) * t3 * t11 * in.w[0];
    G_ab = (T(1) / T(15)) * (T(3) * t5 * t9 + t3 * t11 * b - T(3) * t4 * t10) * in.w[0] / a;
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Returns false where segment_cauchy_i5_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 39 +, 84 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i5_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = t3 * a_minus_b * t4 + b * t6 * t5 + T(2) * (t3 * a_minus_b + b * t5) * t7 * a;
    F = (T(1) / T(3)) * t8 * t7 * in.w[0];
    const T t9 = t4 * t4;
    const T t10 = t6 * t6;
    const T t11 = T(4) * t8 * t7 * a + T(3) * t3 * a_minus_b * t9 + T(3) * b * t10 * t5;
    G_ap = (T(1) / T(15)) * t11 * t7 * in.w[0];
    G_ab = (T(1) / T(15)) * (T(3) * t10 * t5 + t11 * b * t7 - T(3) * t3 * t9) * in.w[0] / a;
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 35 +, 57 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1538 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / D;
    const T t7 = t5 * t5;
    const T t8 = T(2) * (t3 * b + a_minus_b * t5) * t6 * a + a_minus_b * t5 * t7 + t3 * b * t4;
    F = (T(1) / T(3)) * (t3 * t4 + b * t8 * t6 - t5 * t7) * in.w[1] / a + (T(1) / T(3)) * t8 * in.w[0] * t6;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 43 +, 94 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2244 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t3 * a * (b * t7 + t4 * a_minus_b) + b * t7 * t8 + t4 * a_minus_b * t5;
    const T t11 = T(3) * t4 * a_minus_b * t6 + T(3) * b * t7 * t9 + T(4) * t3 * a * t10;
    const T t12 = t3 * t11 * b + T(3) * t7 * t9 - T(3) * t4 * t6;
    const T t13 = T(1) / a;
    G_ap = (T(1) / T(15)) * t3 * in.w[0] * t11 + (T(1) / T(15)) * t12 * t13 * in.w[1];
    G_ab = (T(1) / T(15)) * t13 * in.w[1] * (T(5) * t3 * t10 + T(2) * t12 * t13 * b - t3 * t11 * c) + (T(1) / T(15)) * t12 * in.w[0] * t13;
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 46 +, 105 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2281 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
    G_ap = in.w[1] * M_beyond[4] + M_beyond[3] * in.w[0];
    G_ab = M_beyond[4] * in.w[0] + in.w[1] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * t5;
    const T t8 = t6 * t6;
    const T t9 = T(2) * a * t4 * (t5 * a_minus_b + t6 * b) + t5 * a_minus_b * t7 + t6 * b * t8;
    F = (T(1) / T(3)) * t3 * in.w[1] * (t4 * b * t9 + t6 * t8 - t5 * t7) + (T(1) / T(3)) * t4 * t9 * in.w[0];
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * t6 * b * t10 + T(4) * a * t4 * t9 + T(3) * t5 * a_minus_b * t11;
    const T t13 = t12 * t4 * b + T(3) * t6 * t10 - T(3) * t5 * t11;
    G_ap = (T(1) / T(15)) * t12 * t4 * in.w[0] + (T(1) / T(15)) * t3 * in.w[1] * t13;
    G_ab = (T(1) / T(15)) * (T(5) * t4 * t9 + T(2) * t3 * b * t13 - t12 * t4 * c) * t3 * in.w[1] + (T(1) / T(15)) * t3 * t13 * in.w[0];
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Returns false where segment_cauchy_i5_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 46 +, 105 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i5_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t4 * t4;
    const T t8 = T(2) * (t4 * b + t5 * a_minus_b) * t3 * a + t5 * a_minus_b * t6 + t7 * t4 * b;
    const T t9 = T(1) / a;
    F = (T(1) / T(3)) * in.w[0] * t3 * t8 + (T(1) / T(3)) * in.w[1] * t9 * (t3 * t8 * b + t7 * t4 - t5 * t6);
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * t10 * t4 * b + T(3) * t5 * a_minus_b * t11 + T(4) * t3 * a * t8;
    const T t13 = T(3) * t5 * t11 - T(3) * t10 * t4 - t3 * t12 * b;
    G_ap = (T(1) / T(15)) * in.w[0] * t3 * t12 - (T(1) / T(15)) * in.w[1] * t9 * t13;
    G_ab = (T(1) / T(15)) * in.w[1] * t9 * (T(5) * t3 * t8 - c * t3 * t12 - T(2) * t9 * b * t13) - (T(1) / T(15)) * in.w[0] * t9 * t13;
  }
  const T g_factor = -T(5) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 38 +, 68 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2230 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + ab1 * bp1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = T(1) / r0;
    const T t5 = t3 * a_minus_b + t4 * b;
    const T t6 = T(1) / D;
    const T t7 = t3 * t3;
    const T t8 = t4 * t4;
    const T t9 = T(2) * t5 * t6 * a + t3 * a_minus_b * t7 + t4 * b * t8;
    const T t10 = t3 * t7 - b * t9 * t6 - t4 * t8;
    const T t11 = T(1) / a;
    F = (T(1) / T(3)) * in.w[0] * t9 * t6 - (T(1) / T(3)) * t10 * in.w[1] * t11 - (T(1) / T(3)) * (T(2) * b * t10 * t11 + c * t9 * t6 - T(3) * t5 * t6) * in.w[2] * t11;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 49 +, 111 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2939 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[0] * M_flat[1] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ab = in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = T(2) * a * t9 * (t6 * a_minus_b + b * t3) + t6 * a_minus_b * t7 + b * t3 * t4;
    const T t11 = T(3) * b * t3 * t5 + T(3) * t6 * a_minus_b * t8 + T(4) * t10 * a * t9;
    const T t12 = b * t11 * t9 + T(3) * t3 * t5 - T(3) * t6 * t8;
    const T t13 = T(1) / a;
    const T t14 = t11 * c * t9 - T(5) * t10 * t9 - T(2) * b * t12 * t13;
    G_ap = (T(1) / T(15)) * in.w[0] * t11 * t9 + (T(1) / T(15)) * in.w[1] * t12 * t13 - (T(1) / T(15)) * t13 * t14 * in.w[2];
    G_ab = (T(1) / T(15)) * t13 * (T(5) * (t3 * t4 + t10 * b * t9 - t6 * t7) * t13 - c * t12 * t13 - T(2) * b * t13 * t14) * in.w[2] + (T(1) / T(15)) * in.w[0] * t12 * t13 - (T(1) / T(15)) * in.w[1] * t13 * t14;
  }
  const T g_factor = -T(5) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 53 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 2992 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(5, 7, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[4] + M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5];
    G_ab = M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t4 * a_minus_b + t6 * b;
    const T t8 = t6 * t6;
    const T t9 = t5 * t4 * a_minus_b + T(2) * a * t3 * t7 + t8 * t6 * b;
    const T t10 = t5 * t4 - t8 * t6 - t3 * t9 * b;
    const T t11 = T(1) / a;
    F = (T(1) / T(3)) * in.w[0] * t3 * t9 - (T(1) / T(3)) * (c * t3 * t9 + T(2) * t10 * t11 * b - T(3) * t3 * t7) * t11 * in.w[2] - (T(1) / T(3)) * t10 * in.w[1] * t11;
    const T t12 = t8 * t8;
    const T t13 = t5 * t5;
    const T t14 = T(3) * t12 * t6 * b + T(4) * a * t3 * t9 + T(3) * t13 * t4 * a_minus_b;
    const T t15 = T(3) * t12 * t6 + t3 * t14 * b - T(3) * t13 * t4;
    const T t16 = T(5) * t3 * t9 + T(2) * t11 * t15 * b - c * t3 * t14;
    G_ap = (T(1) / T(15)) * in.w[1] * t11 * t15 + (T(1) / T(15)) * in.w[0] * t3 * t14 + (T(1) / T(15)) * t11 * in.w[2] * t16;
    G_ab = (T(1) / T(15)) * in.w[0] * t11 * t15 + (T(1) / T(15)) * in.w[1] * t11 * t16 - (T(1) / T(15)) * (T(5) * t10 * t11 + c * t11 * t15 - T(2) * t11 * b * t16) * t11 * in.w[2];
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Returns false where segment_cauchy_i5_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 53 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i5_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = a_minus_b * t5 + t7 * b;
    const T t10 = a_minus_b * t5 * t6 + t8 * t7 * b + T(2) * t4 * a * t9;
    const T t11 = t4 * t10 * b + t8 * t7 - t5 * t6;
    F = (T(1) / T(3)) * (T(2) * t3 * t11 * b + T(3) * t4 * t9 - c * t4 * t10) * in.w[2] * t3 + (T(1) / T(3)) * t4 * t10 * in.w[0] + (T(1) / T(3)) * in.w[1] * t3 * t11;
    const T t12 = t8 * t8;
    const T t13 = t6 * t6;
    const T t14 = T(3) * t12 * t7 * b + T(4) * t4 * a * t10 + T(3) * a_minus_b * t5 * t13;
    const T t15 = t14 * t4 * b + T(3) * t12 * t7 - T(3) * t5 * t13;
    const T t16 = T(2) * t15 * t3 * b + T(5) * t4 * t10 - c * t14 * t4;
    G_ap = (T(1) / T(15)) * in.w[1] * t15 * t3 + (T(1) / T(15)) * t14 * t4 * in.w[0] + (T(1) / T(15)) * t16 * in.w[2] * t3;
    G_ab = (T(1) / T(15)) * in.w[1] * t16 * t3 + (T(1) / T(15)) * in.w[2] * t3 * (T(2) * t16 * t3 * b + T(5) * t3 * t11 - c * t15 * t3) + (T(1) / T(15)) * t15 * t3 * in.w[0];
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 43 +, 80 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2924 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(5, 5, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(5, 5, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = T(1) / r1;
    const T t5 = t3 * b + t4 * a_minus_b;
    const T t6 = T(1) / D;
    const T t7 = t4 * t4;
    const T t8 = t3 * t3;
    const T t9 = T(2) * t5 * a * t6 + t4 * a_minus_b * t7 + t8 * t3 * b;
    const T t10 = t8 * t3 + t9 * t6 * b - t4 * t7;
    const T t11 = T(1) / a;
    const T t12 = c * t9 * t6 - T(2) * t10 * t11 * b - T(3) * t5 * t6;
    F = (T(1) / T(3)) * t9 * t6 * in.w[0] + (T(1) / T(3)) * t10 * t11 * in.w[1] + (T(1) / T(3)) * (T(3) * (t5 * t6 * b + t3 - t4) * t11 - c * t10 * t11 - T(2) * t11 * b * t12) * t11 * in.w[3] - (T(1) / T(3)) * in.w[2] * t11 * t12;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 55 +, 131 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3636 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[3] * M_flat[3] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + in.w[0] * M_flat[1] + in.w[3] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[3] * M_beyond[4] + in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t4 * a_minus_b + t6 * b;
    const T t8 = t6 * t6;
    const T t9 = t4 * a_minus_b * t5 + T(2) * t7 * a * t3 + t6 * t8 * b;
    const T t10 = t5 * t5;
    const T t11 = t8 * t8;
    const T t12 = T(4) * a * t3 * t9 + T(3) * t6 * t11 * b + T(3) * t4 * a_minus_b * t10;
    const T t13 = T(3) * t4 * t10 - t12 * t3 * b - T(3) * t6 * t11;
    const T t14 = T(1) / a;
    const T t15 = T(5) * t3 * t9 - T(2) * t13 * t14 * b - c * t12 * t3;
    const T t16 = t6 * t8 + t3 * t9 * b - t4 * t5;
    const T t17 = T(5) * t16 * t14 + T(2) * t15 * t14 * b + t13 * c * t14;
    G_ap = (T(1) / T(15)) * t15 * t14 * in.w[2] + (T(1) / T(15)) * in.w[3] * t17 * t14 + (T(1) / T(15)) * in.w[0] * t12 * t3 - (T(1) / T(15)) * t13 * in.w[1] * t14;
    G_ab = (T(1) / T(15)) * t17 * t14 * in.w[2] + (T(1) / T(15)) * t15 * in.w[1] * t14 - (T(1) / T(15)) * t13 * in.w[0] * t14 - (T(1) / T(15)) * (T(5) * t14 * (c * t3 * t9 - T(2) * t16 * t14 * b - T(3) * t7 * t3) + t15 * c * t14 - T(2) * t17 * t14 * b) * in.w[3] * t14;
  }
  const T g_factor = -T(5) * length * in.s;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Operations: 62 +, 153 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 291 +, 1078 ×, 124 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + M_flat[8] * in.w[3] + in.w[2] * M_flat[7];
    G_ab = M_flat[9] * in.w[3] + M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_7 = J_downward(…)
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = J_downward<T>(7, a, D, -b, c, a_minus_b, q1);
    const T t11 = t6 * t4 * b + t9 * t7 * a_minus_b - T(5) * D * t10;
    const T t12 = T(3) * t3 * t11 * b + T(4) * t8 * t7 - T(4) * t5 * t4;
    const T t13 = T(3) * t3 * D * t11 + T(4) * t8 * t7 * a_minus_b + T(4) * t5 * t4 * b;
    const T t14 = T(4) * t12 * t3 * b + T(3) * t3 * t13 - T(6) * c * t3 * t11;
    F = (T(1) / T(24)) * (T(2) * c * t12 * t3 + T(3) * t3 * (T(8) * t4 - t3 * t13 * b - T(8) * t7) - T(2) * t3 * t14 * b) * t3 * in.w[3] - (T(1) / T(24)) * in.w[2] * t3 * t14 - (T(1) / T(12)) * t12 * t3 * in.w[1] - (T(1) / T(4)) * t3 * in.w[0] * t11;
    const T t15 = t9 * t7 - T(5) * t10 * b - t6 * t4;
    const T t16 = T(8) * t15 * t3 * b + T(5) * t3 * t11 + T(20) * c * t10;
    const T t17 = T(6) * t16 * t3 * b + T(5) * t12 * t3 - T(12) * t15 * c * t3;
    G_ap = t10 * in.w[0] - (T(1) / T(20)) * t16 * in.w[2] * t3 - (T(1) / T(5)) * t15 * t3 * in.w[1] - (T(1) / T(60)) * t17 * t3 * in.w[3];
    G_ab = -(T(1) / T(5)) * t15 * t3 * in.w[0] - (T(1) / T(120)) * t3 * in.w[3] * (T(5) * t3 * t14 + T(4) * t17 * t3 * b - T(6) * t16 * c * t3) - (T(1) / T(20)) * t16 * t3 * in.w[1] - (T(1) / T(60)) * in.w[2] * t17 * t3;
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t18 = T(1) / r1;
    const T t19 = t18 * t18;
    const T t20 = T(1) / r0;
    const T t21 = t20 * t20;
    const T t22 = T(1) / D;
    const T t23 = t20 * b + t18 * a_minus_b;
    const T t24 = t19 * t18 * a_minus_b + t21 * t20 * b + T(2) * a * t22 * t23;
    const T t25 = t21 * t20 + t24 * t22 * b - t19 * t18;
    const T t26 = T(1) / a;
    const T t27 = T(3) * t22 * t23 + T(2) * t25 * t26 * b - c * t24 * t22;
    F = (T(1) / T(3)) * t24 * t22 * in.w[0] + (T(1) / T(3)) * t27 * in.w[2] * t26 + (T(1) / T(3)) * t26 * in.w[3] * (T(3) * t26 * (t20 + t22 * b * t23 - t18) + T(2) * t27 * t26 * b - t25 * c * t26) + (T(1) / T(3)) * t25 * t26 * in.w[1];
    const T t28 = t21 * t21;
    const T t29 = t19 * t19;
    const T t30 = T(3) * t28 * t20 * b + T(3) * t29 * t18 * a_minus_b + T(4) * t24 * a * t22;
    const T t31 = T(3) * t29 * t18 - t22 * t30 * b - T(3) * t28 * t20;
    const T t32 = c * t22 * t30 + T(2) * t31 * t26 * b - T(5) * t24 * t22;
    const T t33 = T(2) * t32 * t26 * b - t31 * c * t26 - T(5) * t25 * t26;
    G_ap = (T(1) / T(15)) * t22 * t30 * in.w[0] - (T(1) / T(15)) * in.w[2] * t32 * t26 - (T(1) / T(15)) * t26 * t33 * in.w[3] - (T(1) / T(15)) * t31 * t26 * in.w[1];
    G_ab = -(T(1) / T(15)) * t32 * t26 * in.w[1] - (T(1) / T(15)) * in.w[2] * t26 * t33 - (T(1) / T(15)) * t31 * t26 * in.w[0] - (T(1) / T(15)) * (T(2) * t26 * t33 * b - c * t32 * t26 - T(5) * t27 * t26) * t26 * in.w[3];
  }
  const T g_factor = -T(5) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−5/2) dt
/// Returns false where segment_cauchy_i5_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 62 +, 153 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i5_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(5, 7, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
    G_ab = in.w[1] * M_flat[7] + in.w[3] * M_flat[9] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = a_minus_b * t4 + b * t5;
    const T t7 = t4 * t4;
    const T t8 = t5 * t5;
    const T t9 = T(2) * t6 * t3 * a + a_minus_b * t7 * t4 + b * t8 * t5;
    const T t10 = b * t3 * t9 + t8 * t5 - t7 * t4;
    const T t11 = T(1) / a;
    const T t12 = T(2) * b * t10 * t11 + T(3) * t6 * t3 - c * t3 * t9;
    F = (T(1) / T(3)) * in.w[1] * t10 * t11 + (T(1) / T(3)) * t12 * in.w[2] * t11 + (T(1) / T(3)) * t3 * in.w[0] * t9 - (T(1) / T(3)) * (T(3) * (t4 - b * t6 * t3 - t5) * t11 + c * t10 * t11 - T(2) * t12 * b * t11) * in.w[3] * t11;
    const T t13 = t8 * t8;
    const T t14 = t7 * t7;
    const T t15 = T(3) * b * t13 * t5 + T(3) * a_minus_b * t14 * t4 + T(4) * t3 * t9 * a;
    const T t16 = T(3) * t13 * t5 + b * t15 * t3 - T(3) * t14 * t4;
    const T t17 = T(5) * t3 * t9 + T(2) * b * t16 * t11 - c * t15 * t3;
    const T t18 = t16 * c * t11 - T(5) * t10 * t11 - T(2) * b * t17 * t11;
    G_ap = (T(1) / T(15)) * in.w[1] * t16 * t11 + (T(1) / T(15)) * t15 * t3 * in.w[0] + (T(1) / T(15)) * in.w[2] * t17 * t11 - (T(1) / T(15)) * t18 * in.w[3] * t11;
    G_ab = (T(1) / T(15)) * in.w[1] * t17 * t11 + (T(1) / T(15)) * t16 * in.w[0] * t11 - (T(1) / T(15)) * (c * t17 * t11 + T(2) * b * t18 * t11 - T(5) * t12 * t11) * in.w[3] * t11 - (T(1) / T(15)) * t18 * in.w[2] * t11;
  }
  const T g_factor = -T(5) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 36 +, 57 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 854 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    F = (T(1) / T(8)) * in.w[0] * (T(3) * a * (b * t5 + a * J2 + a_minus_b * t6) * t7 + T(2) * a_minus_b * t8 + T(2) * b * t9) * t7;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 43 +, 82 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1557 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = T(5) * t5 * a * (T(3) * t5 * a * (b * t6 + a_minus_b * t7 + a * J2) + T(2) * a_minus_b * t8 + T(2) * b * t9) + T(8) * b * t10 + T(8) * a_minus_b * t11;
    G_ap = (T(1) / T(48)) * t5 * in.w[0] * t12;
    G_ab = (T(1) / T(48)) * in.w[0] * (t5 * t12 * b + T(8) * t10 - T(8) * t11) / a;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 43 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1581 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t7 * a_minus_b + T(2) * t9 * b + T(3) * t5 * (J2 * a + t8 * b + t6 * a_minus_b) * a;
    F = (T(1) / T(8)) * t5 * in.w[0] * t10;
    const T t11 = t9 * t8;
    const T t12 = t7 * t6;
    const T t13 = T(8) * t11 * b + T(5) * t5 * a * t10 + T(8) * t12 * a_minus_b;
    G_ap = (T(1) / T(48)) * t13 * t5 * in.w[0];
    G_ab = (T(1) / T(48)) * (T(8) * t11 + t13 * t5 * b - T(8) * t12) * in.w[0] / a;
  }
  const T g_factor = -T(6) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Returns false where segment_cauchy_i6_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i6_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t7 * b + T(2) * t9 * a_minus_b + T(3) * (J2 * a + t8 * a_minus_b + t6 * b) * t5 * a;
    F = (T(1) / T(8)) * in.w[0] * t5 * t10;
    const T t11 = t7 * t6;
    const T t12 = t9 * t8;
    const T t13 = T(8) * t11 * b + T(5) * t5 * a * t10 + T(8) * t12 * a_minus_b;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t5;
    G_ab = (T(1) / T(48)) * in.w[0] * (T(8) * t11 + t13 * t5 * b - T(8) * t12) / a;
  }
  const T g_factor = -T(6) * in.s * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 39 +, 63 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1544 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = T(2) * a_minus_b * t6 + T(2) * b * t8 + T(3) * (b * t7 + a * J2 + a_minus_b * t5) * t9 * a;
    F = (T(1) / T(8)) * t10 * in.w[0] * t9 - (T(1) / T(8)) * (T(2) * t6 - b * t10 * t9 - T(2) * t8) * in.w[1] / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 47 +, 96 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2250 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(3) * (a_minus_b * t6 + b * t7 + a * J2) * t5 * a + T(2) * b * t8 + T(2) * a_minus_b * t9;
    const T t11 = t8 * t7;
    const T t12 = t9 * t6;
    const T t13 = T(5) * t5 * t10 * a + T(8) * b * t11 + T(8) * a_minus_b * t12;
    const T t14 = T(1) / a;
    const T t15 = T(8) * t12 - b * t13 * t5 - T(8) * t11;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t5 - (T(1) / T(48)) * t14 * t15 * in.w[1];
    G_ab = (T(1) / T(48)) * (T(6) * t5 * t10 - t13 * c * t5 - T(2) * b * t14 * t15) * t14 * in.w[1] - (T(1) / T(48)) * in.w[0] * t14 * t15;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 50 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2288 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / c;
    const T t8 = T(1) / D;
    const T t9 = t7 * t7;
    const T t10 = T(2) * t6 * a_minus_b + T(3) * (b * t7 + J2 * a + t5 * a_minus_b) * t8 * a + T(2) * b * t9;
    const T t11 = T(1) / a;
    F = (T(1) / T(8)) * t10 * in.w[0] * t8 - (T(1) / T(8)) * (T(2) * t6 - b * t10 * t8 - T(2) * t9) * t11 * in.w[1];
    const T t12 = t6 * t5;
    const T t13 = t9 * t7;
    const T t14 = T(8) * t12 * a_minus_b + T(5) * t10 * t8 * a + T(8) * b * t13;
    const T t15 = T(8) * t12 - T(8) * t13 - b * t8 * t14;
    G_ap = (T(1) / T(48)) * in.w[0] * t8 * t14 - (T(1) / T(48)) * t15 * t11 * in.w[1];
    G_ab = -(T(1) / T(48)) * t11 * in.w[1] * (c * t8 * t14 + T(2) * b * t15 * t11 - T(6) * t10 * t8) - (T(1) / T(48)) * t15 * in.w[0] * t11;
  }
  const T g_factor = -T(6) * length * in.s;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Returns false where segment_cauchy_i6_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 50 +, 107 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i6_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = T(2) * a_minus_b * t8 + T(2) * b * t10 + T(3) * t6 * a * (J2 * a + b * t9 + a_minus_b * t7);
    F = (T(1) / T(8)) * t5 * in.w[1] * (t6 * b * t11 + T(2) * t10 - T(2) * t8) + (T(1) / T(8)) * t6 * in.w[0] * t11;
    const T t12 = t8 * t7;
    const T t13 = t10 * t9;
    const T t14 = T(5) * t6 * a * t11 + T(8) * a_minus_b * t12 + T(8) * b * t13;
    const T t15 = t6 * t14 * b + T(8) * t13 - T(8) * t12;
    G_ap = (T(1) / T(48)) * t5 * in.w[1] * t15 + (T(1) / T(48)) * t6 * t14 * in.w[0];
    G_ab = (T(1) / T(48)) * t5 * in.w[1] * (T(6) * t6 * t11 + T(2) * t5 * b * t15 - t6 * t14 * c) + (T(1) / T(48)) * t5 * t15 * in.w[0];
  }
  const T g_factor = -T(6) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 42 +, 74 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2236 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = a * J2 + b * t8 + t6 * a_minus_b;
    const T t11 = T(2) * t7 * a_minus_b + T(2) * b * t9 + T(3) * t5 * a * t10;
    const T t12 = T(1) / a;
    const T t13 = T(2) * t7 - t5 * b * t11 - T(2) * t9;
    F = (T(1) / T(8)) * t5 * in.w[0] * t11 + (T(1) / T(8)) * (T(4) * t5 * t10 - T(2) * t12 * b * t13 - t5 * c * t11) * in.w[2] * t12 - (T(1) / T(8)) * t12 * in.w[1] * t13;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 53 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2945 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[2] * in.w[1] + in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / D;
    const T t12 = T(2) * b * t6 + T(2) * a_minus_b * t9 + T(3) * a * (a * J2 + a_minus_b * t8 + b * t5) * t11;
    const T t13 = T(8) * b * t7 + T(8) * a_minus_b * t10 + T(5) * a * t12 * t11;
    const T t14 = T(1) / a;
    const T t15 = T(8) * t7 + b * t13 * t11 - T(8) * t10;
    const T t16 = T(2) * t14 * b * t15 + T(6) * t12 * t11 - t13 * c * t11;
    G_ap = (T(1) / T(48)) * t13 * in.w[0] * t11 + (T(1) / T(48)) * t14 * in.w[1] * t15 + (T(1) / T(48)) * t16 * t14 * in.w[2];
    G_ab = (T(1) / T(48)) * t14 * in.w[2] * (T(6) * t14 * (T(2) * t6 + b * t12 * t11 - T(2) * t9) + T(2) * t16 * t14 * b - t14 * c * t15) + (T(1) / T(48)) * t16 * t14 * in.w[1] + (T(1) / T(48)) * t14 * in.w[0] * t15;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 57 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 2999 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[4] * in.w[0] + in.w[1] * M_beyond[5] + M_beyond[6] * in.w[2];
    G_ab = in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + in.w[2] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = J2 * a + a_minus_b * t7 + t8 * b;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * t10 * b + T(2) * a_minus_b * t11 + T(3) * t6 * a * t9;
    const T t13 = T(2) * t10 + t12 * t6 * b - T(2) * t11;
    F = (T(1) / T(8)) * t5 * (T(4) * t6 * t9 + T(2) * t5 * b * t13 - c * t12 * t6) * in.w[2] + (T(1) / T(8)) * t12 * t6 * in.w[0] + (T(1) / T(8)) * in.w[1] * t5 * t13;
    const T t14 = t10 * t8;
    const T t15 = t11 * t7;
    const T t16 = T(5) * t12 * t6 * a + T(8) * t14 * b + T(8) * a_minus_b * t15;
    const T t17 = t6 * t16 * b + T(8) * t14 - T(8) * t15;
    const T t18 = c * t6 * t16 - T(6) * t12 * t6 - T(2) * t5 * b * t17;
    G_ap = (T(1) / T(48)) * in.w[1] * t5 * t17 + (T(1) / T(48)) * t6 * t16 * in.w[0] - (T(1) / T(48)) * t5 * in.w[2] * t18;
    G_ab = (T(1) / T(48)) * t5 * t17 * in.w[0] - (T(1) / T(48)) * in.w[1] * t5 * t18 - (T(1) / T(48)) * t5 * in.w[2] * (c * t5 * t17 + T(2) * t5 * t18 * b - T(6) * t5 * t13);
  }
  const T g_factor = -T(6) * in.s * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Returns false where segment_cauchy_i6_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 57 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i6_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = t7 * a_minus_b + t5 * b + J2 * a;
    const T t11 = T(2) * t6 * b + T(2) * t8 * a_minus_b + T(3) * t9 * a * t10;
    const T t12 = T(1) / a;
    const T t13 = T(2) * t6 + t11 * t9 * b - T(2) * t8;
    F = (T(1) / T(8)) * t11 * t9 * in.w[0] + (T(1) / T(8)) * in.w[1] * t12 * t13 + (T(1) / T(8)) * in.w[2] * t12 * (T(4) * t9 * t10 + T(2) * t12 * t13 * b - t11 * c * t9);
    const T t14 = t6 * t5;
    const T t15 = t8 * t7;
    const T t16 = T(8) * t14 * b + T(5) * t11 * t9 * a + T(8) * t15 * a_minus_b;
    const T t17 = T(8) * t14 + t16 * t9 * b - T(8) * t15;
    const T t18 = T(6) * t11 * t9 + T(2) * t17 * t12 * b - c * t16 * t9;
    G_ap = (T(1) / T(48)) * in.w[1] * t17 * t12 + (T(1) / T(48)) * t16 * t9 * in.w[0] + (T(1) / T(48)) * t18 * in.w[2] * t12;
    G_ab = (T(1) / T(48)) * in.w[1] * t18 * t12 + (T(1) / T(48)) * t17 * t12 * in.w[0] + (T(1) / T(48)) * in.w[2] * t12 * (T(6) * t12 * t13 + T(2) * t18 * t12 * b - c * t17 * t12);
  }
  const T g_factor = -T(6) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 47 +, 86 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2930 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(6, 6, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(6, 6, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = a_minus_b * t7 + J2 * a + b * t5;
    const T t10 = T(1) / D;
    const T t11 = T(2) * b * t6 + T(2) * a_minus_b * t8 + T(3) * t9 * a * t10;
    const T t12 = T(2) * t6 + b * t11 * t10 - T(2) * t8;
    const T t13 = T(1) / a;
    const T t14 = T(2) * t12 * b * t13 + T(4) * t9 * t10 - t11 * c * t10;
    F = (T(1) / T(8)) * t12 * in.w[1] * t13 + (T(1) / T(8)) * in.w[3] * (T(4) * (b * t9 * t10 + t5 - t7) * t13 + T(2) * b * t14 * t13 - t12 * c * t13) * t13 + (T(1) / T(8)) * in.w[2] * t14 * t13 + (T(1) / T(8)) * in.w[0] * t11 * t10;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 59 +, 133 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3642 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1] + in.w[2] * M_flat[3] + M_flat[4] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1] + in.w[3] * M_beyond[4] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / c;
    const T t9 = b * t8 + J2 * a + t5 * a_minus_b;
    const T t10 = T(1) / D;
    const T t11 = t8 * t8;
    const T t12 = T(2) * t6 * a_minus_b + T(3) * t9 * a * t10 + T(2) * b * t11;
    const T t13 = t11 * t8;
    const T t14 = T(8) * t7 * a_minus_b + T(5) * t12 * a * t10 + T(8) * b * t13;
    const T t15 = T(1) / a;
    const T t16 = T(8) * t7 - T(8) * t13 - b * t14 * t10;
    const T t17 = T(2) * t11 + b * t12 * t10 - T(2) * t6;
    const T t18 = t14 * c * t10 + T(2) * b * t16 * t15 - T(6) * t12 * t10;
    const T t19 = t16 * c * t15 + T(6) * t17 * t15 - T(2) * b * t18 * t15;
    G_ap = (T(1) / T(48)) * in.w[0] * t14 * t10 + (T(1) / T(48)) * t15 * t19 * in.w[3] - (T(1) / T(48)) * t18 * in.w[2] * t15 - (T(1) / T(48)) * in.w[1] * t16 * t15;
    G_ab = (T(1) / T(48)) * in.w[2] * t15 * t19 + (T(1) / T(48)) * (T(6) * (T(2) * t17 * b * t15 + T(4) * t9 * t10 - c * t12 * t10) * t15 + T(2) * b * t15 * t19 + t18 * c * t15) * t15 * in.w[3] - (T(1) / T(48)) * in.w[1] * t18 * t15 - (T(1) / T(48)) * in.w[0] * t16 * t15;
  }
  const T g_factor = -T(6) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Operations: 66 +, 155 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3714 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1];
    G_ab = in.w[0] * M_flat[6] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(6, 8, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
    G_ap = in.w[1] * M_beyond[6] + in.w[3] * M_beyond[8] + in.w[0] * M_beyond[5] + in.w[2] * M_beyond[7];
    G_ab = in.w[3] * M_beyond[9] + M_beyond[8] * in.w[2] + in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = a * J2 + b * t8 + a_minus_b * t6;
    const T t11 = T(2) * a_minus_b * t7 + T(2) * b * t9 + T(3) * t5 * a * t10;
    const T t12 = T(1) / a;
    const T t13 = T(2) * t7 - t5 * t11 * b - T(2) * t9;
    const T t14 = T(4) * t5 * t10 - T(2) * t12 * b * t13 - t5 * t11 * c;
    F = (T(1) / T(8)) * t5 * t11 * in.w[0] + (T(1) / T(8)) * t12 * t14 * in.w[2] + (T(1) / T(8)) * in.w[3] * t12 * (t12 * t13 * c + T(2) * t12 * b * t14 + T(4) * t12 * (t8 + t5 * t10 * b - t6)) - (T(1) / T(8)) * t12 * in.w[1] * t13;
    const T t15 = t7 * t6;
    const T t16 = t9 * t8;
    const T t17 = T(8) * a_minus_b * t15 + T(8) * b * t16 + T(5) * t5 * a * t11;
    const T t18 = T(8) * t15 - t5 * t17 * b - T(8) * t16;
    const T t19 = T(2) * t12 * b * t18 + t5 * t17 * c - T(6) * t5 * t11;
    const T t20 = t12 * t18 * c - T(2) * t19 * t12 * b - T(6) * t12 * t13;
    G_ap = (T(1) / T(48)) * in.w[3] * t20 * t12 + (T(1) / T(48)) * t5 * in.w[0] * t17 - (T(1) / T(48)) * t19 * t12 * in.w[2] - (T(1) / T(48)) * t12 * in.w[1] * t18;
    G_ab = (T(1) / T(48)) * t20 * t12 * in.w[2] + (T(1) / T(48)) * in.w[3] * t12 * (t19 * t12 * c + T(6) * t12 * t14 + T(2) * t20 * t12 * b) - (T(1) / T(48)) * t12 * in.w[0] * t18 - (T(1) / T(48)) * t19 * t12 * in.w[1];
  }
  const T g_factor = -T(6) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−6/2) dt
/// Returns false where segment_cauchy_i6_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 66 +, 155 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i6_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(6, 8, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3];
    G_ap = M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = in.w[1] * M_flat[7] + M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = T(1) / q1;
    const T t8 = J2 * a + a_minus_b * t7 + b * t5;
    const T t9 = T(1) / D;
    const T t10 = t7 * t7;
    const T t11 = T(2) * b * t6 + T(3) * t8 * a * t9 + T(2) * a_minus_b * t10;
    const T t12 = T(2) * t6 + b * t11 * t9 - T(2) * t10;
    const T t13 = T(1) / a;
    const T t14 = T(2) * t12 * b * t13 + T(4) * t8 * t9 - c * t11 * t9;
    F = (T(1) / T(8)) * t12 * in.w[1] * t13 + (T(1) / T(8)) * t14 * in.w[2] * t13 + (T(1) / T(8)) * t11 * t9 * in.w[0] + (T(1) / T(8)) * (T(2) * t14 * b * t13 - t12 * c * t13 - T(4) * (t7 - t5 - t8 * b * t9) * t13) * t13 * in.w[3];
    const T t15 = t6 * t5;
    const T t16 = t10 * t7;
    const T t17 = T(8) * b * t15 + T(5) * t11 * a * t9 + T(8) * a_minus_b * t16;
    const T t18 = T(8) * t15 + b * t17 * t9 - T(8) * t16;
    const T t19 = T(2) * t18 * b * t13 + T(6) * t11 * t9 - t17 * c * t9;
    const T t20 = t18 * c * t13 - T(6) * t12 * t13 - T(2) * b * t19 * t13;
    G_ap = (T(1) / T(48)) * t18 * in.w[1] * t13 + (T(1) / T(48)) * t19 * in.w[2] * t13 + (T(1) / T(48)) * t17 * t9 * in.w[0] - (T(1) / T(48)) * t20 * t13 * in.w[3];
    G_ab = (T(1) / T(48)) * t18 * t13 * in.w[0] + (T(1) / T(48)) * in.w[1] * t19 * t13 - (T(1) / T(48)) * (T(2) * b * t20 * t13 + t19 * c * t13 - T(6) * t14 * t13) * t13 * in.w[3] - (T(1) / T(48)) * t20 * in.w[2] * t13;
  }
  const T g_factor = -T(6) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 34 +, 62 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 851 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    F = (T(1) / T(15)) * (T(4) * t3 * a * (t5 * t4 * b + T(2) * t3 * a * (t4 * b + a_minus_b * t6) + a_minus_b * t6 * t7) + T(3) * a_minus_b * t6 * t8 + T(3) * t9 * t4 * b) * t3 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 41 +, 91 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1553 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t4 * a_minus_b * t7 + T(2) * a * t3 * (T(3) * t4 * a_minus_b * t6 + T(3) * t10 * b * t8 + T(4) * a * t3 * (T(2) * a * t3 * (t4 * a_minus_b + b * t8) + t4 * a_minus_b * t5 + t9 * b * t8)) + T(5) * t11 * b * t8;
    G_ap = (T(1) / T(35)) * t3 * in.w[0] * t12;
    G_ab = (T(1) / T(35)) * (T(5) * t11 * t8 + t3 * b * t12 - T(5) * t4 * t7) * in.w[0] / a;
  }
  const T g_factor = -T(7) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 41 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1577 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t6 * t4 * b + T(3) * t9 * a_minus_b * t7 + T(4) * (t5 * t4 * b + t8 * a_minus_b * t7 + T(2) * t3 * a * (t4 * b + a_minus_b * t7)) * t3 * a;
    F = (T(1) / T(15)) * t3 * in.w[0] * t10;
    const T t11 = t9 * t8;
    const T t12 = t6 * t5;
    const T t13 = T(2) * t3 * a * t10 + T(5) * t11 * a_minus_b * t7 + T(5) * t12 * t4 * b;
    G_ap = (T(1) / T(35)) * t3 * in.w[0] * t13;
    G_ab = (T(1) / T(35)) * in.w[0] * (T(5) * t12 * t4 + t3 * t13 * b - T(5) * t11 * t7) / a;
  }
  const T g_factor = -T(7) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Returns false where segment_cauchy_i7_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i7_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * a_minus_b * t4 * t6 + T(4) * t3 * a * (b * t8 * t7 + a_minus_b * t4 * t5 + T(2) * (a_minus_b * t4 + b * t7) * t3 * a) + T(3) * b * t9 * t7;
    F = (T(1) / T(15)) * t3 * in.w[0] * t10;
    const T t11 = t6 * t5;
    const T t12 = t9 * t8;
    const T t13 = T(2) * t3 * a * t10 + T(5) * a_minus_b * t4 * t11 + T(5) * b * t12 * t7;
    G_ap = (T(1) / T(35)) * t3 * t13 * in.w[0];
    G_ab = (T(1) / T(35)) * in.w[0] * (T(5) * t12 * t7 + t3 * t13 * b - T(5) * t4 * t11) / a;
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 37 +, 70 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1541 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t4 * b * t6 + T(3) * t7 * a_minus_b * t9 + T(4) * t3 * a * (t7 * a_minus_b * t8 + T(2) * t3 * a * (t4 * b + t7 * a_minus_b) + t4 * b * t5);
    F = (T(1) / T(15)) * t3 * t10 * in.w[0] + (T(1) / T(15)) * in.w[1] * (T(3) * t4 * t6 + t3 * t10 * b - T(3) * t7 * t9) / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 45 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2246 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = T(3) * t3 * a_minus_b * t5 + T(3) * t9 * b * t7 + T(4) * a * t10 * (T(2) * (t3 * a_minus_b + b * t7) * a * t10 + t3 * a_minus_b * t4 + t8 * b * t7);
    const T t12 = t9 * t8;
    const T t13 = T(5) * t3 * a_minus_b * t6 + T(2) * t11 * a * t10 + T(5) * t12 * b * t7;
    const T t14 = T(5) * t12 * t7 + t13 * t10 * b - T(5) * t3 * t6;
    const T t15 = T(1) / a;
    G_ap = (T(1) / T(35)) * t13 * t10 * in.w[0] + (T(1) / T(35)) * t14 * t15 * in.w[1];
    G_ab = (T(1) / T(105)) * (T(7) * t11 * t10 + T(6) * t14 * t15 * b - T(3) * c * t13 * t10) * t15 * in.w[1] + (T(1) / T(35)) * t14 * t15 * in.w[0];
  }
  const T g_factor = -T(7) * in.s * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 48 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2284 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t4 * b * t6 + T(4) * (T(2) * t3 * a * (t7 * a_minus_b + t4 * b) + t7 * a_minus_b * t8 + t4 * b * t5) * t3 * a + T(3) * t7 * a_minus_b * t9;
    const T t11 = T(1) / a;
    F = (T(1) / T(15)) * in.w[0] * t3 * t10 + (T(1) / T(15)) * (t3 * b * t10 + T(3) * t4 * t6 - T(3) * t7 * t9) * t11 * in.w[1];
    const T t12 = t6 * t5;
    const T t13 = t9 * t8;
    const T t14 = T(5) * t4 * b * t12 + T(2) * t3 * a * t10 + T(5) * t7 * a_minus_b * t13;
    const T t15 = T(5) * t7 * t13 - T(5) * t4 * t12 - t3 * b * t14;
    G_ap = (T(1) / T(35)) * in.w[0] * t3 * t14 - (T(1) / T(35)) * t11 * in.w[1] * t15;
    G_ab = (T(1) / T(105)) * (T(7) * t3 * t10 - T(3) * t3 * t14 * c - T(6) * t11 * t15 * b) * t11 * in.w[1] - (T(1) / T(35)) * in.w[0] * t11 * t15;
  }
  const T g_factor = -T(7) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Returns false where segment_cauchy_i7_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 48 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i7_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(4) * t7 * a * (t5 * t4 * b + t9 * t8 * a_minus_b + T(2) * t7 * a * (t8 * a_minus_b + t4 * b)) + T(3) * t10 * t8 * a_minus_b + T(3) * t6 * t4 * b;
    F = (T(1) / T(15)) * in.w[1] * t3 * (T(3) * t6 * t4 + t7 * t11 * b - T(3) * t10 * t8) + (T(1) / T(15)) * in.w[0] * t7 * t11;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    const T t14 = T(2) * t7 * a * t11 + T(5) * t12 * t4 * b + T(5) * t13 * t8 * a_minus_b;
    const T t15 = t14 * t7 * b + T(5) * t12 * t4 - T(5) * t13 * t8;
    G_ap = (T(1) / T(35)) * in.w[0] * t14 * t7 + (T(1) / T(35)) * t15 * in.w[1] * t3;
    G_ab = (T(1) / T(35)) * t15 * in.w[0] * t3 + (T(1) / T(105)) * (T(7) * t7 * t11 + T(6) * t15 * t3 * b - T(3) * c * t14 * t7) * in.w[1] * t3;
  }
  const T g_factor = -T(7) * length * in.s;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 40 +, 81 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2233 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8 * a_minus_b + T(2) * t4 * a * (t8 * a_minus_b + t5 * b) + t5 * b * t6;
    const T t12 = T(3) * t5 * b * t7 + T(3) * t10 * t8 * a_minus_b + T(4) * t4 * a * t11;
    const T t13 = t4 * b * t12 + T(3) * t5 * t7 - T(3) * t10 * t8;
    F = (T(1) / T(15)) * t3 * t13 * in.w[1] + (T(1) / T(15)) * t4 * in.w[0] * t12 - (T(1) / T(15)) * in.w[2] * t3 * (t4 * t12 * c - T(5) * t4 * t11 - T(2) * t3 * b * t13);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 51 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2941 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ab = M_flat[3] * in.w[2] + M_flat[1] * in.w[0] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1];
    G_ab = in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = T(3) * b * t3 * t5 + T(3) * t8 * t6 * a_minus_b + T(4) * (T(2) * (t6 * a_minus_b + b * t3) * t9 * a + t7 * t6 * a_minus_b + b * t3 * t4) * t9 * a;
    const T t11 = t5 * t4;
    const T t12 = t8 * t7;
    const T t13 = T(5) * t12 * t6 * a_minus_b + T(2) * t10 * t9 * a + T(5) * b * t3 * t11;
    const T t14 = T(5) * t3 * t11 + b * t13 * t9 - T(5) * t12 * t6;
    const T t15 = T(1) / a;
    const T t16 = T(7) * t10 * t9 + T(6) * t14 * b * t15 - T(3) * c * t13 * t9;
    G_ap = (T(1) / T(105)) * t16 * in.w[2] * t15 + (T(1) / T(35)) * t14 * in.w[1] * t15 + (T(1) / T(35)) * in.w[0] * t13 * t9;
    G_ab = (T(1) / T(105)) * t16 * in.w[1] * t15 + (T(1) / T(35)) * t14 * in.w[0] * t15 - (T(1) / T(105)) * in.w[2] * (T(3) * t14 * c * t15 - T(7) * (b * t10 * t9 + T(3) * t3 * t5 - T(3) * t8 * t6) * t15 - T(2) * b * t16 * t15) * t15;
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 55 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 2995 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[0] + M_flat[5] * in.w[1] + M_flat[6] * in.w[2];
    G_ab = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4] + M_beyond[6] * in.w[2];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = b * t8 * t7 + T(2) * (a_minus_b * t4 + b * t7) * t3 * a + a_minus_b * t5 * t4;
    const T t10 = t8 * t8;
    const T t11 = T(3) * a_minus_b * t6 * t4 + T(4) * t3 * a * t9 + T(3) * b * t10 * t7;
    const T t12 = b * t3 * t11 + T(3) * t10 * t7 - T(3) * t6 * t4;
    const T t13 = T(1) / a;
    F = (T(1) / T(15)) * t12 * in.w[1] * t13 + (T(1) / T(15)) * (T(2) * b * t12 * t13 + T(5) * t3 * t9 - c * t3 * t11) * t13 * in.w[2] + (T(1) / T(15)) * in.w[0] * t3 * t11;
    const T t14 = t6 * t5;
    const T t15 = t10 * t8;
    const T t16 = T(5) * a_minus_b * t14 * t4 + T(2) * t3 * a * t11 + T(5) * b * t15 * t7;
    const T t17 = T(5) * t15 * t7 + b * t3 * t16 - T(5) * t14 * t4;
    const T t18 = T(3) * c * t3 * t16 - T(6) * b * t13 * t17 - T(7) * t3 * t11;
    G_ap = (T(1) / T(35)) * in.w[0] * t3 * t16 + (T(1) / T(35)) * in.w[1] * t13 * t17 - (T(1) / T(105)) * t18 * t13 * in.w[2];
    G_ab = (T(1) / T(35)) * in.w[0] * t13 * t17 - (T(1) / T(105)) * t18 * in.w[1] * t13 - (T(1) / T(105)) * (T(3) * c * t13 * t17 + T(2) * b * t18 * t13 - T(7) * t12 * t13) * t13 * in.w[2];
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Returns false where segment_cauchy_i7_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 55 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i7_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + in.w[2] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / D;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7 * a_minus_b + T(2) * t6 * a * (b * t3 + t7 * a_minus_b) + b * t4 * t3;
    const T t10 = t8 * t8;
    const T t11 = T(3) * b * t5 * t3 + T(4) * t9 * t6 * a + T(3) * t10 * t7 * a_minus_b;
    const T t12 = T(3) * t5 * t3 + b * t6 * t11 - T(3) * t10 * t7;
    const T t13 = T(1) / a;
    F = (T(1) / T(15)) * in.w[1] * t12 * t13 + (T(1) / T(15)) * in.w[2] * t13 * (T(2) * b * t12 * t13 + T(5) * t9 * t6 - c * t6 * t11) + (T(1) / T(15)) * t6 * in.w[0] * t11;
    const T t14 = t5 * t4;
    const T t15 = t10 * t8;
    const T t16 = T(5) * b * t14 * t3 + T(5) * t15 * t7 * a_minus_b + T(2) * t6 * a * t11;
    const T t17 = T(5) * t14 * t3 + b * t16 * t6 - T(5) * t15 * t7;
    const T t18 = T(6) * b * t17 * t13 + T(7) * t6 * t11 - T(3) * c * t16 * t6;
    G_ap = (T(1) / T(35)) * t17 * in.w[1] * t13 + (T(1) / T(105)) * t18 * in.w[2] * t13 + (T(1) / T(35)) * t16 * t6 * in.w[0];
    G_ab = (T(1) / T(105)) * in.w[1] * t18 * t13 + (T(1) / T(35)) * t17 * t13 * in.w[0] - (T(1) / T(105)) * (T(3) * t17 * c * t13 - T(2) * b * t18 * t13 - T(7) * t12 * t13) * in.w[2] * t13;
  }
  const T g_factor = -T(7) * length * in.s;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 45 +, 95 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2927 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(7, 7, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(7, 7, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = T(2) * t9 * a * (b * t3 + t6 * a_minus_b) + b * t4 * t3 + t6 * a_minus_b * t7;
    const T t11 = T(3) * t6 * a_minus_b * t8 + T(3) * b * t5 * t3 + T(4) * t9 * a * t10;
    const T t12 = T(3) * t5 * t3 + b * t11 * t9 - T(3) * t6 * t8;
    const T t13 = T(1) / a;
    const T t14 = t11 * c * t9 - T(5) * t9 * t10 - T(2) * b * t12 * t13;
    F = (T(1) / T(15)) * in.w[1] * t12 * t13 + (T(1) / T(15)) * t11 * t9 * in.w[0] + (T(1) / T(15)) * (T(5) * (b * t9 * t10 + t4 * t3 - t6 * t7) * t13 - T(2) * b * t13 * t14 - c * t12 * t13) * t13 * in.w[3] - (T(1) / T(15)) * in.w[2] * t13 * t14;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 57 +, 146 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3638 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[3] * in.w[3];
    G_ab = M_flat[3] * in.w[2] + M_flat[4] * in.w[3] + M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[4] * in.w[3] + in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = b * t6 * t7 + T(2) * (a_minus_b * t3 + b * t6) * t9 * a + t4 * a_minus_b * t3;
    const T t11 = T(3) * t5 * a_minus_b * t3 + T(3) * b * t6 * t8 + T(4) * t9 * t10 * a;
    const T t12 = t8 * t7;
    const T t13 = t5 * t4;
    const T t14 = T(2) * t11 * t9 * a + T(5) * b * t6 * t12 + T(5) * t13 * a_minus_b * t3;
    const T t15 = T(1) / a;
    const T t16 = T(5) * t6 * t12 + b * t14 * t9 - T(5) * t13 * t3;
    const T t17 = T(6) * b * t15 * t16 + T(7) * t11 * t9 - T(3) * c * t14 * t9;
    const T t18 = b * t11 * t9 + T(3) * t6 * t8 - T(3) * t5 * t3;
    const T t19 = T(2) * b * t17 * t15 + T(7) * t18 * t15 - T(3) * c * t15 * t16;
    G_ap = (T(1) / T(35)) * in.w[0] * t14 * t9 + (T(1) / T(105)) * t17 * in.w[2] * t15 + (T(1) / T(35)) * in.w[1] * t15 * t16 + (T(1) / T(105)) * t19 * t15 * in.w[3];
    G_ab = (T(1) / T(105)) * t19 * in.w[2] * t15 + (T(1) / T(35)) * in.w[0] * t15 * t16 + (T(1) / T(105)) * in.w[1] * t17 * t15 + (T(1) / T(105)) * (T(2) * b * t19 * t15 + T(7) * (T(5) * t9 * t10 + T(2) * b * t18 * t15 - t11 * c * t9) * t15 - c * t17 * t15) * t15 * in.w[3];
  }
  const T g_factor = -T(7) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Operations: 64 +, 170 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1340 +, 3710 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[8] * in.w[3] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6] + M_flat[5] * in.w[0];
    G_ab = M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + in.w[1] * M_flat[7] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(7, 9, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3];
    G_ap = M_beyond[7] * in.w[2] + in.w[1] * M_beyond[6] + M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0];
    G_ab = in.w[3] * M_beyond[9] + in.w[0] * M_beyond[6] + in.w[2] * M_beyond[8] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = T(2) * (t4 * a_minus_b + b * t7) * t3 * a + b * t8 * t7 + t5 * t4 * a_minus_b;
    const T t10 = t8 * t8;
    const T t11 = T(3) * t6 * t4 * a_minus_b + T(4) * t9 * t3 * a + T(3) * b * t10 * t7;
    const T t12 = T(1) / a;
    const T t13 = T(3) * t6 * t4 - b * t3 * t11 - T(3) * t10 * t7;
    const T t14 = c * t3 * t11 + T(2) * b * t12 * t13 - T(5) * t9 * t3;
    F = (T(1) / T(15)) * t3 * in.w[0] * t11 - (T(1) / T(15)) * (T(2) * b * t14 * t12 - c * t12 * t13 - T(5) * (t8 * t7 + b * t9 * t3 - t5 * t4) * t12) * t12 * in.w[3] - (T(1) / T(15)) * in.w[1] * t12 * t13 - (T(1) / T(15)) * t14 * in.w[2] * t12;
    const T t15 = t6 * t5;
    const T t16 = t10 * t8;
    const T t17 = T(2) * t3 * a * t11 + T(5) * t15 * t4 * a_minus_b + T(5) * b * t16 * t7;
    const T t18 = T(5) * t15 * t4 - b * t17 * t3 - T(5) * t16 * t7;
    const T t19 = T(6) * b * t12 * t18 + T(3) * t17 * c * t3 - T(7) * t3 * t11;
    const T t20 = T(3) * c * t12 * t18 - T(2) * b * t19 * t12 - T(7) * t12 * t13;
    G_ap = (T(1) / T(105)) * t20 * t12 * in.w[3] + (T(1) / T(35)) * t17 * t3 * in.w[0] - (T(1) / T(105)) * t19 * in.w[2] * t12 - (T(1) / T(35)) * in.w[1] * t12 * t18;
    G_ab = (T(1) / T(105)) * t20 * in.w[2] * t12 + (T(1) / T(105)) * (T(2) * b * t20 * t12 + c * t19 * t12 - T(7) * t14 * t12) * t12 * in.w[3] - (T(1) / T(105)) * in.w[1] * t19 * t12 - (T(1) / T(35)) * t12 * t18 * in.w[0];
  }
  const T g_factor = -T(7) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−7/2) dt
/// Returns false where segment_cauchy_i7_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 64 +, 170 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i7_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(7, 9, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[3] * in.w[3];
    G_ap = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + in.w[3] * M_flat[8] + M_flat[6] * in.w[1];
    G_ab = M_flat[9] * in.w[3] + M_flat[7] * in.w[1] + M_flat[6] * in.w[0] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * t5;
    const T t8 = t6 * t6;
    const T t9 = T(2) * t4 * a * (a_minus_b * t5 + t6 * b) + a_minus_b * t5 * t7 + t6 * b * t8;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(4) * t4 * a * t9 + T(3) * t6 * b * t10 + T(3) * a_minus_b * t5 * t11;
    const T t13 = t4 * t12 * b + T(3) * t6 * t10 - T(3) * t5 * t11;
    const T t14 = t4 * t12 * c - T(5) * t4 * t9 - T(2) * t3 * t13 * b;
    F = (T(1) / T(15)) * t3 * t13 * in.w[1] + (T(1) / T(15)) * t4 * in.w[0] * t12 + (T(1) / T(15)) * t3 * in.w[3] * (T(5) * t3 * (t4 * b * t9 + t6 * t8 - t5 * t7) - t3 * t13 * c - T(2) * t14 * t3 * b) - (T(1) / T(15)) * t14 * t3 * in.w[2];
    const T t15 = t11 * t7;
    const T t16 = t10 * t8;
    const T t17 = T(5) * a_minus_b * t5 * t15 + T(5) * t6 * b * t16 + T(2) * t4 * a * t12;
    const T t18 = t4 * b * t17 + T(5) * t6 * t16 - T(5) * t5 * t15;
    const T t19 = T(3) * t4 * t17 * c - T(6) * t18 * t3 * b - T(7) * t4 * t12;
    const T t20 = T(3) * t18 * t3 * c + T(2) * t3 * t19 * b - T(7) * t3 * t13;
    G_ap = (T(1) / T(35)) * t4 * in.w[0] * t17 + (T(1) / T(35)) * t18 * t3 * in.w[1] - (T(1) / T(105)) * t3 * in.w[3] * t20 - (T(1) / T(105)) * t3 * t19 * in.w[2];
    G_ab = (T(1) / T(35)) * t18 * t3 * in.w[0] - (T(1) / T(105)) * t3 * t19 * in.w[1] - (T(1) / T(105)) * t3 * t20 * in.w[2] - (T(1) / T(105)) * t3 * in.w[3] * (T(2) * t3 * b * t20 + T(7) * t14 * t3 - t3 * t19 * c);
  }
  const T g_factor = -T(7) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 38 +, 66 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 857 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = T(1) / D;
    const T t10 = t8 * t8;
    const T t11 = t10 * t8;
    F = (T(1) / T(48)) * (T(8) * t7 * b + T(5) * (T(3) * (a * J2 + a_minus_b * t8 + t5 * b) * t9 * a + T(2) * t6 * b + T(2) * a_minus_b * t10) * t9 * a + T(8) * a_minus_b * t11) * t9 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 45 +, 91 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1559 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(7) * t5 * (T(5) * t5 * a * (T(3) * (b * t6 + a_minus_b * t7 + J2 * a) * t5 * a + T(2) * a_minus_b * t8 + T(2) * b * t9) + T(8) * b * t10 + T(8) * a_minus_b * t11) * a + T(48) * a_minus_b * t12 + T(48) * b * t13;
    G_ap = (T(1) / T(384)) * t14 * t5 * in.w[0];
    G_ab = (T(1) / T(384)) * (b * t14 * t5 + T(48) * t13 - T(48) * t12) * in.w[0] / a;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 45 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1584 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t8 * t7;
    const T t11 = t9 * t6;
    const T t12 = T(5) * t5 * a * (T(3) * t5 * a * (b * t6 + a_minus_b * t7 + a * J2) + T(2) * a_minus_b * t8 + T(2) * b * t9) + T(8) * a_minus_b * t10 + T(8) * b * t11;
    F = (T(1) / T(48)) * t5 * in.w[0] * t12;
    const T t13 = t9 * t9;
    const T t14 = t8 * t8;
    const T t15 = T(7) * t5 * a * t12 + T(48) * b * t13 + T(48) * a_minus_b * t14;
    G_ap = (T(1) / T(384)) * t5 * in.w[0] * t15;
    G_ab = -(T(1) / T(384)) * in.w[0] * (T(48) * t14 - t5 * b * t15 - T(48) * t13) / a;
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Returns false where segment_cauchy_i8_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 95 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i8_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * a_minus_b * t8 + T(5) * t5 * a * (T(2) * a_minus_b * t7 + T(3) * t5 * a * (b * t9 + a_minus_b * t6 + a * J2) + T(2) * b * t10) + T(8) * b * t11;
    F = (T(1) / T(48)) * t5 * in.w[0] * t12;
    const T t13 = t7 * t7;
    const T t14 = t10 * t10;
    const T t15 = T(7) * t5 * a * t12 + T(48) * a_minus_b * t13 + T(48) * b * t14;
    G_ap = (T(1) / T(384)) * t5 * in.w[0] * t15;
    G_ab = (T(1) / T(384)) * in.w[0] * (t5 * b * t15 + T(48) * t14 - T(48) * t13) / a;
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 41 +, 72 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1547 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / D;
    const T t12 = T(8) * t7 * a_minus_b + T(8) * b * t10 + T(5) * t11 * a * (T(2) * t6 * a_minus_b + T(2) * b * t9 + T(3) * t11 * a * (b * t8 + a * J2 + t5 * a_minus_b));
    F = (T(1) / T(48)) * in.w[1] * (t12 * t11 * b + T(8) * t10 - T(8) * t7) / a + (T(1) / T(48)) * t12 * t11 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 49 +, 105 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2252 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t6 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(1) / D;
    const T t13 = T(8) * b * t8 + T(8) * t11 * a_minus_b + T(5) * (T(3) * (J2 * a + t9 * a_minus_b + b * t5) * t12 * a + T(2) * b * t6 + T(2) * t10 * a_minus_b) * t12 * a;
    const T t14 = t10 * t10;
    const T t15 = T(7) * t13 * t12 * a + T(48) * b * t7 + T(48) * t14 * a_minus_b;
    const T t16 = T(48) * t7 + b * t15 * t12 - T(48) * t14;
    const T t17 = T(1) / a;
    G_ap = (T(1) / T(384)) * in.w[1] * t16 * t17 + (T(1) / T(384)) * t15 * in.w[0] * t12;
    G_ab = (T(1) / T(384)) * in.w[0] * t16 * t17 - (T(1) / T(384)) * in.w[1] * (t15 * c * t12 - T(2) * b * t16 * t17 - T(8) * t13 * t12) * t17;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 52 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2291 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t8 * t7;
    const T t11 = t9 * t6;
    const T t12 = T(5) * t5 * a * (T(3) * t5 * a * (J2 * a + a_minus_b * t6 + b * t7) + T(2) * b * t8 + T(2) * a_minus_b * t9) + T(8) * b * t10 + T(8) * a_minus_b * t11;
    const T t13 = T(1) / a;
    F = (T(1) / T(48)) * in.w[0] * t5 * t12 - (T(1) / T(48)) * (T(8) * t11 - T(8) * t10 - t5 * t12 * b) * t13 * in.w[1];
    const T t14 = t9 * t9;
    const T t15 = t8 * t8;
    const T t16 = T(48) * a_minus_b * t14 + T(7) * t5 * t12 * a + T(48) * b * t15;
    const T t17 = t16 * t5 * b + T(48) * t15 - T(48) * t14;
    G_ap = (T(1) / T(384)) * t17 * t13 * in.w[1] + (T(1) / T(384)) * in.w[0] * t16 * t5;
    G_ab = (T(1) / T(384)) * in.w[0] * t17 * t13 + (T(1) / T(384)) * t13 * in.w[1] * (T(8) * t5 * t12 + T(2) * t17 * t13 * b - t16 * t5 * c);
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Returns false where segment_cauchy_i8_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 116 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i8_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t9 * t6;
    const T t11 = t8 * t7;
    const T t12 = T(5) * t5 * a * (T(3) * (J2 * a + b * t6 + a_minus_b * t7) * t5 * a + T(2) * a_minus_b * t8 + T(2) * b * t9) + T(8) * b * t10 + T(8) * a_minus_b * t11;
    const T t13 = T(1) / a;
    F = (T(1) / T(48)) * in.w[0] * t12 * t5 + (T(1) / T(48)) * (b * t12 * t5 + T(8) * t10 - T(8) * t11) * t13 * in.w[1];
    const T t14 = t8 * t8;
    const T t15 = t9 * t9;
    const T t16 = T(7) * t12 * t5 * a + T(48) * a_minus_b * t14 + T(48) * b * t15;
    const T t17 = b * t16 * t5 + T(48) * t15 - T(48) * t14;
    G_ap = (T(1) / T(384)) * t16 * in.w[0] * t5 + (T(1) / T(384)) * t17 * t13 * in.w[1];
    G_ab = (T(1) / T(384)) * in.w[0] * t17 * t13 + (T(1) / T(384)) * (T(2) * b * t17 * t13 + T(8) * t12 * t5 - t16 * c * t5) * t13 * in.w[1];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 44 +, 83 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2239 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / q1;
    const T t9 = T(1) / D;
    const T t10 = t8 * t8;
    const T t11 = T(3) * (a_minus_b * t8 + b * t5 + a * J2) * t9 * a + T(2) * b * t6 + T(2) * a_minus_b * t10;
    const T t12 = t10 * t8;
    const T t13 = T(8) * b * t7 + T(5) * t11 * t9 * a + T(8) * a_minus_b * t12;
    const T t14 = b * t13 * t9 + T(8) * t7 - T(8) * t12;
    const T t15 = T(1) / a;
    F = (T(1) / T(48)) * in.w[1] * t14 * t15 + (T(1) / T(48)) * in.w[0] * t13 * t9 + (T(1) / T(48)) * in.w[2] * t15 * (T(6) * t11 * t9 + T(2) * b * t14 * t15 - t13 * c * t9);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 55 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2947 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t6 * t5;
    const T t14 = T(8) * a_minus_b * t12 + T(5) * t8 * a * (T(2) * a_minus_b * t10 + T(2) * t6 * b + T(3) * (t5 * b + a_minus_b * t9 + J2 * a) * t8 * a) + T(8) * t13 * b;
    const T t15 = T(48) * a_minus_b * t11 + T(48) * t7 * b + T(7) * t8 * a * t14;
    const T t16 = T(48) * t7 + t8 * t15 * b - T(48) * t11;
    const T t17 = T(1) / a;
    const T t18 = c * t8 * t15 - T(8) * t8 * t14 - T(2) * t16 * t17 * b;
    G_ap = (T(1) / T(384)) * t16 * in.w[1] * t17 + (T(1) / T(384)) * in.w[0] * t8 * t15 - (T(1) / T(384)) * t17 * in.w[2] * t18;
    G_ab = (T(1) / T(384)) * t17 * in.w[2] * (T(8) * t17 * (t8 * t14 * b + T(8) * t13 - T(8) * t12) - T(2) * t17 * t18 * b - t16 * c * t17) + (T(1) / T(384)) * in.w[0] * t16 * t17 - (T(1) / T(384)) * in.w[1] * t17 * t18;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 59 +, 139 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 3002 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[0] * M_flat[4] + M_flat[6] * in.w[2];
    G_ab = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ap = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2];
    G_ab = in.w[1] * M_beyond[6] + M_beyond[7] * in.w[2] + in.w[0] * M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / D;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = T(2) * a_minus_b * t6 + T(3) * t8 * (J2 * a + b * t9 + a_minus_b * t5) * a + T(2) * b * t10;
    const T t12 = t10 * t9;
    const T t13 = T(8) * a_minus_b * t7 + T(5) * t11 * t8 * a + T(8) * b * t12;
    const T t14 = b * t13 * t8 + T(8) * t12 - T(8) * t7;
    const T t15 = T(1) / a;
    F = (T(1) / T(48)) * in.w[0] * t13 * t8 + (T(1) / T(48)) * in.w[1] * t14 * t15 - (T(1) / T(48)) * (t13 * c * t8 - T(2) * b * t14 * t15 - T(6) * t11 * t8) * t15 * in.w[2];
    const T t16 = t6 * t6;
    const T t17 = t10 * t10;
    const T t18 = T(48) * a_minus_b * t16 + T(7) * t13 * t8 * a + T(48) * b * t17;
    const T t19 = b * t18 * t8 + T(48) * t17 - T(48) * t16;
    const T t20 = t18 * c * t8 - T(2) * t19 * b * t15 - T(8) * t13 * t8;
    G_ap = (T(1) / T(384)) * in.w[0] * t18 * t8 + (T(1) / T(384)) * t19 * in.w[1] * t15 - (T(1) / T(384)) * t15 * t20 * in.w[2];
    G_ab = (T(1) / T(384)) * t19 * in.w[0] * t15 - (T(1) / T(384)) * (T(2) * b * t15 * t20 + t19 * c * t15 - T(8) * t14 * t15) * t15 * in.w[2] - (T(1) / T(384)) * in.w[1] * t15 * t20;
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Returns false where segment_cauchy_i8_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 139 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i8_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + M_flat[5] * in.w[1];
    G_ab = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(3) * t5 * a * (b * t6 + a * J2 + a_minus_b * t7) + T(2) * a_minus_b * t8 + T(2) * b * t9;
    const T t11 = t8 * t7;
    const T t12 = t9 * t6;
    const T t13 = T(5) * t5 * a * t10 + T(8) * a_minus_b * t11 + T(8) * b * t12;
    const T t14 = T(1) / a;
    const T t15 = t13 * t5 * b + T(8) * t12 - T(8) * t11;
    F = (T(1) / T(48)) * t13 * t5 * in.w[0] + (T(1) / T(48)) * t14 * t15 * in.w[1] + (T(1) / T(48)) * in.w[2] * t14 * (T(2) * t14 * b * t15 + T(6) * t5 * t10 - t13 * t5 * c);
    const T t16 = t8 * t8;
    const T t17 = t9 * t9;
    const T t18 = T(48) * a_minus_b * t16 + T(48) * b * t17 + T(7) * t13 * t5 * a;
    const T t19 = T(48) * t16 - T(48) * t17 - t5 * b * t18;
    const T t20 = t5 * t18 * c + T(2) * t14 * t19 * b - T(8) * t13 * t5;
    G_ap = (T(1) / T(384)) * t5 * in.w[0] * t18 - (T(1) / T(384)) * in.w[2] * t14 * t20 - (T(1) / T(384)) * t14 * t19 * in.w[1];
    G_ab = (T(1) / T(384)) * in.w[2] * t14 * (t14 * t19 * c + T(8) * t14 * t15 - T(2) * t14 * b * t20) - (T(1) / T(384)) * t14 * t20 * in.w[1] - (T(1) / T(384)) * t14 * t19 * in.w[0];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 49 +, 97 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2933 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(8, 8, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(8, 8, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = T(2) * t7 * b + T(3) * a * t5 * (a_minus_b * t8 + t6 * b + a * J2) + T(2) * a_minus_b * t9;
    const T t11 = T(1) / a;
    const T t12 = t7 * t6;
    const T t13 = t9 * t8;
    const T t14 = T(8) * t12 * b + T(8) * a_minus_b * t13 + T(5) * a * t5 * t10;
    const T t15 = T(8) * t12 + t14 * t5 * b - T(8) * t13;
    const T t16 = t14 * c * t5 - T(2) * t15 * t11 * b - T(6) * t5 * t10;
    F = (T(1) / T(48)) * (T(6) * (t5 * b * t10 + T(2) * t7 - T(2) * t9) * t11 - T(2) * t16 * t11 * b - c * t15 * t11) * t11 * in.w[3] + (T(1) / T(48)) * t15 * t11 * in.w[1] + (T(1) / T(48)) * t14 * t5 * in.w[0] - (T(1) / T(48)) * t16 * in.w[2] * t11;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 61 +, 142 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3644 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ab = in.w[1] * M_flat[2] + in.w[2] * M_flat[3] + in.w[0] * M_flat[1] + M_flat[4] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[3] * in.w[2] + M_beyond[4] * in.w[3] + M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = T(1) / D;
    const T t12 = T(2) * t9 * a_minus_b + T(3) * (b * t5 + J2 * a + t8 * a_minus_b) * a * t11 + T(2) * b * t6;
    const T t13 = t6 * t5;
    const T t14 = T(8) * t10 * a_minus_b + T(5) * t12 * a * t11 + T(8) * b * t13;
    const T t15 = t9 * t9;
    const T t16 = T(7) * t14 * a * t11 + T(48) * b * t7 + T(48) * t15 * a_minus_b;
    const T t17 = T(48) * t7 + t16 * b * t11 - T(48) * t15;
    const T t18 = T(1) / a;
    const T t19 = T(8) * t10 - T(8) * t13 - b * t14 * t11;
    const T t20 = t16 * c * t11 - T(8) * t14 * t11 - T(2) * b * t17 * t18;
    const T t21 = t17 * c * t18 + T(8) * t19 * t18 + T(2) * b * t20 * t18;
    G_ap = (T(1) / T(384)) * t17 * in.w[1] * t18 + (T(1) / T(384)) * in.w[0] * t16 * t11 - (T(1) / T(384)) * t18 * t21 * in.w[3] - (T(1) / T(384)) * t20 * in.w[2] * t18;
    G_ab = (T(1) / T(384)) * in.w[0] * t17 * t18 - (T(1) / T(384)) * (T(2) * b * t18 * t21 + T(8) * (T(2) * b * t19 * t18 + c * t14 * t11 - T(6) * t12 * t11) * t18 - t20 * c * t18) * t18 * in.w[3] - (T(1) / T(384)) * t20 * in.w[1] * t18 - (T(1) / T(384)) * in.w[2] * t18 * t21;
  }
  const T g_factor = -T(8) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Operations: 68 +, 166 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3717 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3];
    G_ap = in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + in.w[3] * M_flat[8];
    G_ab = M_flat[8] * in.w[2] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + in.w[0] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(8, 10, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3];
    G_ap = in.w[3] * M_beyond[8] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6] + M_beyond[7] * in.w[2];
    G_ab = M_beyond[7] * in.w[1] + in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9] + M_beyond[8] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / D;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(2) * a_minus_b * t7 + T(2) * b * t11 + T(3) * t9 * (a * J2 + b * t10 + a_minus_b * t6) * a;
    const T t14 = T(8) * a_minus_b * t8 + T(8) * b * t12 + T(5) * t9 * a * t13;
    const T t15 = T(8) * t8 - t9 * b * t14 - T(8) * t12;
    const T t16 = T(2) * t5 * b * t15 + t9 * t14 * c - T(6) * t9 * t13;
    F = (T(1) / T(48)) * in.w[3] * t5 * (t5 * t15 * c - T(2) * t16 * t5 * b - T(6) * (T(2) * t7 - t9 * t13 * b - T(2) * t11) * t5) + (T(1) / T(48)) * t9 * in.w[0] * t14 - (T(1) / T(48)) * t16 * t5 * in.w[2] - (T(1) / T(48)) * t5 * t15 * in.w[1];
    const T t17 = t11 * t11;
    const T t18 = t7 * t7;
    const T t19 = T(48) * b * t17 + T(48) * a_minus_b * t18 + T(7) * t9 * a * t14;
    const T t20 = t9 * t19 * b + T(48) * t17 - T(48) * t18;
    const T t21 = T(8) * t9 * t14 + T(2) * t5 * b * t20 - t9 * t19 * c;
    const T t22 = t5 * c * t20 + T(8) * t5 * t15 - T(2) * t21 * t5 * b;
    G_ap = (T(1) / T(384)) * t5 * in.w[1] * t20 + (T(1) / T(384)) * t9 * in.w[0] * t19 + (T(1) / T(384)) * t21 * t5 * in.w[2] - (T(1) / T(384)) * in.w[3] * t5 * t22;
    G_ab = (T(1) / T(384)) * t5 * in.w[0] * t20 + (T(1) / T(384)) * t21 * t5 * in.w[1] - (T(1) / T(384)) * in.w[3] * t5 * (T(2) * t5 * b * t22 + t21 * t5 * c + T(8) * t16 * t5) - (T(1) / T(384)) * t5 * t22 * in.w[2];
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−8/2) dt
/// Returns false where segment_cauchy_i8_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 68 +, 166 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i8_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(8, 10, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2];
    G_ap = M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + M_flat[6] * in.w[1] + M_flat[8] * in.w[3];
    G_ab = in.w[1] * M_flat[7] + M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = T(3) * a * t5 * (b * t6 + J2 * a + a_minus_b * t7) + T(2) * a_minus_b * t8 + T(2) * b * t9;
    const T t11 = T(1) / a;
    const T t12 = t8 * t7;
    const T t13 = t9 * t6;
    const T t14 = T(5) * t10 * a * t5 + T(8) * a_minus_b * t12 + T(8) * b * t13;
    const T t15 = b * t14 * t5 + T(8) * t13 - T(8) * t12;
    const T t16 = T(2) * b * t15 * t11 + T(6) * t10 * t5 - t14 * c * t5;
    F = (T(1) / T(48)) * (T(6) * (b * t10 * t5 + T(2) * t9 - T(2) * t8) * t11 + T(2) * b * t11 * t16 - t15 * c * t11) * t11 * in.w[3] + (T(1) / T(48)) * t14 * t5 * in.w[0] + (T(1) / T(48)) * t15 * in.w[1] * t11 + (T(1) / T(48)) * in.w[2] * t11 * t16;
    const T t17 = t9 * t9;
    const T t18 = t8 * t8;
    const T t19 = T(48) * b * t17 + T(48) * a_minus_b * t18 + T(7) * t14 * a * t5;
    const T t20 = T(48) * t17 + b * t5 * t19 - T(48) * t18;
    const T t21 = c * t5 * t19 - T(8) * t14 * t5 - T(2) * b * t20 * t11;
    const T t22 = T(2) * t21 * b * t11 + t20 * c * t11 - T(8) * t15 * t11;
    G_ap = (T(1) / T(384)) * in.w[1] * t20 * t11 + (T(1) / T(384)) * t5 * in.w[0] * t19 - (T(1) / T(384)) * t22 * t11 * in.w[3] - (T(1) / T(384)) * t21 * in.w[2] * t11;
    G_ab = (T(1) / T(384)) * (T(8) * t11 * t16 + t21 * c * t11 - T(2) * t22 * b * t11) * t11 * in.w[3] + (T(1) / T(384)) * t20 * t11 * in.w[0] - (T(1) / T(384)) * t21 * in.w[1] * t11 - (T(1) / T(384)) * t22 * in.w[2] * t11;
  }
  const T g_factor = -T(8) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 36 +, 73 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 853 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    F = (T(1) / T(35)) * t3 * in.w[0] * (T(5) * a_minus_b * t4 * t7 + T(2) * t3 * a * (T(3) * t10 * t8 * b + T(3) * a_minus_b * t4 * t6 + T(4) * t3 * (a_minus_b * t4 * t5 + T(2) * (a_minus_b * t4 + t8 * b) * t3 * a + t9 * t8 * b) * a) + T(5) * t11 * t8 * b);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 43 +, 102 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1556 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = t10 * t10;
    const T t14 = T(35) * t6 * b * t3 + T(8) * a * t7 * (T(5) * t8 * a_minus_b * t11 + T(2) * a * t7 * (T(3) * t5 * b * t3 + T(3) * t8 * a_minus_b * t10 + T(4) * a * t7 * (T(2) * a * t7 * (t8 * a_minus_b + b * t3) + t4 * b * t3 + t8 * a_minus_b * t9)) + T(5) * t12 * b * t3) + T(35) * t8 * a_minus_b * t13;
    G_ap = (T(1) / T(315)) * t14 * t7 * in.w[0];
    G_ab = (T(1) / T(315)) * in.w[0] * (t14 * t7 * b + T(35) * t6 * t3 - T(35) * t8 * t13) / a;
  }
  const T g_factor = -T(9) * in.s * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 43 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1580 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t7 * a_minus_b * t4 + T(5) * t11 * t8 * b + T(2) * t3 * (T(4) * t3 * (T(2) * t3 * a * (t8 * b + a_minus_b * t4) + t9 * t8 * b + t5 * a_minus_b * t4) * a + T(3) * t10 * t8 * b + T(3) * t6 * a_minus_b * t4) * a;
    F = (T(1) / T(35)) * t3 * t12 * in.w[0];
    const T t13 = t10 * t10;
    const T t14 = t6 * t6;
    const T t15 = T(8) * t3 * t12 * a + T(35) * t13 * t8 * b + T(35) * t14 * a_minus_b * t4;
    G_ap = (T(1) / T(315)) * t3 * t15 * in.w[0];
    G_ab = (T(1) / T(315)) * (t3 * t15 * b + T(35) * t13 * t8 - T(35) * t14 * t4) * in.w[0] / a;
  }
  const T g_factor = -T(9) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Returns false where segment_cauchy_i9_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 106 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i9_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = t9 * t5;
    const T t11 = t8 * t7;
    const T t12 = T(2) * t3 * a * (T(4) * t3 * a * (a_minus_b * t4 * t5 + b * t7 * t6 + T(2) * t3 * a * (a_minus_b * t4 + b * t6)) + T(3) * b * t8 * t6 + T(3) * a_minus_b * t4 * t9) + T(5) * a_minus_b * t4 * t10 + T(5) * b * t11 * t6;
    F = (T(1) / T(35)) * t3 * in.w[0] * t12;
    const T t13 = t8 * t8;
    const T t14 = t9 * t9;
    const T t15 = T(35) * b * t13 * t6 + T(8) * t3 * a * t12 + T(35) * a_minus_b * t4 * t14;
    G_ap = (T(1) / T(315)) * t3 * in.w[0] * t15;
    G_ab = (T(1) / T(315)) * in.w[0] * (t3 * t15 * b + T(35) * t13 * t6 - T(35) * t4 * t14) / a;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 39 +, 81 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1543 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = t6 * t6;
    const T t9 = t4 * t4;
    const T t10 = t8 * t6;
    const T t11 = t9 * t4;
    const T t12 = T(2) * a * (T(4) * a * (t3 * b * t4 + t5 * a_minus_b * t6 + T(2) * a * (t5 * a_minus_b + t3 * b) * t7) * t7 + T(3) * t5 * a_minus_b * t8 + T(3) * t3 * b * t9) * t7 + T(5) * t5 * a_minus_b * t10 + T(5) * t3 * b * t11;
    F = (T(1) / T(35)) * in.w[0] * t12 * t7 + (T(1) / T(35)) * in.w[1] * (T(5) * t3 * t11 + b * t12 * t7 - T(5) * t5 * t10) / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 47 +, 116 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2249 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(5) * t5 * a_minus_b * t8 + T(5) * b * t9 * t12 + T(2) * a * t4 * (T(3) * t5 * a_minus_b * t7 + T(3) * b * t9 * t11 + T(4) * a * t4 * (b * t9 * t10 + T(2) * a * t4 * (t5 * a_minus_b + b * t9) + t5 * a_minus_b * t6));
    const T t14 = t7 * t7;
    const T t15 = t11 * t11;
    const T t16 = T(8) * a * t4 * t13 + T(35) * t5 * a_minus_b * t14 + T(35) * b * t9 * t15;
    const T t17 = t4 * t16 * b + T(35) * t9 * t15 - T(35) * t5 * t14;
    G_ap = (T(1) / T(315)) * t3 * in.w[1] * t17 + (T(1) / T(315)) * in.w[0] * t4 * t16;
    G_ab = (T(1) / T(315)) * t3 * in.w[1] * (T(2) * t3 * b * t17 + T(9) * t4 * t13 - t4 * t16 * c) + (T(1) / T(315)) * in.w[0] * t3 * t17;
  }
  const T g_factor = -T(9) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 50 +, 129 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2287 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * t4 * a_minus_b * t7 + T(2) * t3 * a * (T(4) * (t8 * b * t9 + T(2) * (t8 * b + t4 * a_minus_b) * t3 * a + t4 * a_minus_b * t5) * t3 * a + T(3) * t4 * a_minus_b * t6 + T(3) * t8 * b * t10) + T(5) * t8 * b * t11;
    const T t13 = T(1) / a;
    F = (T(1) / T(35)) * in.w[0] * t3 * t12 - (T(1) / T(35)) * (T(5) * t4 * t7 - T(5) * t8 * t11 - t3 * t12 * b) * t13 * in.w[1];
    const T t14 = t6 * t6;
    const T t15 = t10 * t10;
    const T t16 = T(35) * t4 * a_minus_b * t14 + T(35) * t8 * b * t15 + T(8) * t3 * a * t12;
    const T t17 = t3 * t16 * b + T(35) * t8 * t15 - T(35) * t4 * t14;
    G_ap = (T(1) / T(315)) * in.w[0] * t3 * t16 + (T(1) / T(315)) * t13 * in.w[1] * t17;
    G_ab = (T(1) / T(315)) * in.w[0] * t13 * t17 + (T(1) / T(315)) * t13 * in.w[1] * (T(9) * t3 * t12 + T(2) * t13 * b * t17 - t3 * t16 * c);
  }
  const T g_factor = -T(9) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Returns false where segment_cauchy_i9_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 50 +, 129 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i9_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(2) * (T(3) * t10 * t8 * a_minus_b + T(3) * t5 * t3 * b + T(4) * (T(2) * t7 * a * (t8 * a_minus_b + t3 * b) + t9 * t8 * a_minus_b + t4 * t3 * b) * t7 * a) * t7 * a + T(5) * t6 * t3 * b + T(5) * t11 * t8 * a_minus_b;
    const T t13 = T(1) / a;
    F = (T(1) / T(35)) * (T(5) * t6 * t3 + t7 * t12 * b - T(5) * t11 * t8) * t13 * in.w[1] + (T(1) / T(35)) * in.w[0] * t7 * t12;
    const T t14 = t10 * t10;
    const T t15 = t5 * t5;
    const T t16 = T(35) * t14 * t8 * a_minus_b + T(35) * t15 * t3 * b + T(8) * t7 * a * t12;
    const T t17 = T(35) * t14 * t8 - T(35) * t15 * t3 - t16 * t7 * b;
    G_ap = (T(1) / T(315)) * t16 * in.w[0] * t7 - (T(1) / T(315)) * t13 * in.w[1] * t17;
    G_ab = (T(1) / T(315)) * (T(9) * t7 * t12 - c * t16 * t7 - T(2) * t13 * t17 * b) * t13 * in.w[1] - (T(1) / T(315)) * in.w[0] * t13 * t17;
  }
  const T g_factor = -T(9) * in.s * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 42 +, 93 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2235 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(3) * t11 * t9 * a_minus_b + T(3) * t4 * b * t6 + T(4) * t8 * a * (t4 * b * t5 + t10 * t9 * a_minus_b + T(2) * t8 * a * (t4 * b + t9 * a_minus_b));
    const T t14 = T(5) * t12 * t9 * a_minus_b + T(5) * t4 * b * t7 + T(2) * t8 * a * t13;
    const T t15 = T(5) * t4 * t7 + t8 * t14 * b - T(5) * t12 * t9;
    F = (T(1) / T(35)) * t3 * t15 * in.w[1] + (T(1) / T(35)) * t8 * t14 * in.w[0] + (T(1) / T(105)) * in.w[2] * t3 * (T(7) * t8 * t13 + T(6) * t3 * b * t15 - T(3) * t8 * t14 * c);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 53 +, 135 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2944 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
    G_ab = M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = T(2) * (T(3) * t5 * t3 * a_minus_b + T(3) * b * t8 * t10 + T(4) * t7 * a * (b * t8 * t9 + t4 * t3 * a_minus_b + T(2) * t7 * a * (b * t8 + t3 * a_minus_b))) * t7 * a + T(5) * b * t8 * t11 + T(5) * t12 * t3 * a_minus_b;
    const T t14 = t10 * t10;
    const T t15 = T(35) * t6 * t3 * a_minus_b + T(8) * t7 * a * t13 + T(35) * b * t8 * t14;
    const T t16 = t15 * b * t7 + T(35) * t8 * t14 - T(35) * t6 * t3;
    const T t17 = T(1) / a;
    const T t18 = T(2) * b * t16 * t17 + T(9) * t7 * t13 - t15 * c * t7;
    G_ap = (T(1) / T(315)) * t18 * t17 * in.w[2] + (T(1) / T(315)) * t15 * in.w[0] * t7 + (T(1) / T(315)) * t16 * in.w[1] * t17;
    G_ab = (T(1) / T(315)) * in.w[1] * t18 * t17 + (T(1) / T(315)) * in.w[0] * t16 * t17 - (T(1) / T(315)) * (T(9) * (T(5) * t12 * t3 - b * t7 * t13 - T(5) * t8 * t11) * t17 + c * t16 * t17 - T(2) * b * t18 * t17) * t17 * in.w[2];
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 57 +, 153 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 2998 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[6] * in.w[2] + M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
    G_ab = in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[6] * in.w[2] + in.w[0] * M_beyond[4] + M_beyond[5] * in.w[1];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
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
    const T t11 = T(1) / D;
    const T t12 = T(4) * (T(2) * (a_minus_b * t7 + b * t3) * t11 * a + b * t4 * t3 + a_minus_b * t8 * t7) * t11 * a + T(3) * a_minus_b * t9 * t7 + T(3) * b * t5 * t3;
    const T t13 = T(5) * a_minus_b * t10 * t7 + T(2) * t12 * t11 * a + T(5) * b * t6 * t3;
    const T t14 = T(5) * t6 * t3 + b * t13 * t11 - T(5) * t10 * t7;
    const T t15 = T(1) / a;
    F = (T(1) / T(35)) * t14 * in.w[1] * t15 + (T(1) / T(35)) * in.w[0] * t13 * t11 - (T(1) / T(105)) * (T(3) * c * t13 * t11 - T(7) * t12 * t11 - T(6) * b * t14 * t15) * t15 * in.w[2];
    const T t16 = t5 * t5;
    const T t17 = t9 * t9;
    const T t18 = T(35) * b * t16 * t3 + T(8) * t13 * t11 * a + T(35) * a_minus_b * t17 * t7;
    const T t19 = t18 * b * t11 + T(35) * t16 * t3 - T(35) * t17 * t7;
    const T t20 = T(2) * b * t19 * t15 + T(9) * t13 * t11 - t18 * c * t11;
    G_ap = (T(1) / T(315)) * t19 * in.w[1] * t15 + (T(1) / T(315)) * t20 * t15 * in.w[2] + (T(1) / T(315)) * t18 * in.w[0] * t11;
    G_ab = (T(1) / T(315)) * (T(9) * t14 * t15 + T(2) * b * t20 * t15 - t19 * c * t15) * t15 * in.w[2] + (T(1) / T(315)) * t19 * in.w[0] * t15 + (T(1) / T(315)) * t20 * in.w[1] * t15;
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Returns false where segment_cauchy_i9_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 57 +, 153 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i9_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(3) * t6 * t4 * b + T(4) * t3 * a * (t8 * t7 * a_minus_b + T(2) * t3 * (t7 * a_minus_b + t4 * b) * a + t5 * t4 * b) + T(3) * t9 * t7 * a_minus_b;
    const T t11 = t9 * t8;
    const T t12 = t6 * t5;
    const T t13 = T(5) * t11 * t7 * a_minus_b + T(2) * t3 * t10 * a + T(5) * t12 * t4 * b;
    const T t14 = t13 * t3 * b + T(5) * t12 * t4 - T(5) * t11 * t7;
    const T t15 = T(1) / a;
    F = (T(1) / T(105)) * (T(7) * t3 * t10 + T(6) * t14 * t15 * b - T(3) * t13 * c * t3) * in.w[2] * t15 + (T(1) / T(35)) * in.w[0] * t13 * t3 + (T(1) / T(35)) * t14 * in.w[1] * t15;
    const T t16 = t9 * t9;
    const T t17 = t6 * t6;
    const T t18 = T(35) * t17 * t4 * b + T(8) * t13 * t3 * a + T(35) * t16 * t7 * a_minus_b;
    const T t19 = T(35) * t16 * t7 - t18 * t3 * b - T(35) * t17 * t4;
    const T t20 = T(9) * t13 * t3 - T(2) * t19 * t15 * b - t18 * c * t3;
    G_ap = (T(1) / T(315)) * t20 * in.w[2] * t15 + (T(1) / T(315)) * t18 * in.w[0] * t3 - (T(1) / T(315)) * in.w[1] * t19 * t15;
    G_ab = (T(1) / T(315)) * in.w[2] * t15 * (c * t19 * t15 + T(9) * t14 * t15 + T(2) * t20 * t15 * b) + (T(1) / T(315)) * t20 * in.w[1] * t15 - (T(1) / T(315)) * in.w[0] * t19 * t15;
  }
  const T g_factor = -T(9) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 47 +, 110 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2929 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(9, 9, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(9, 9, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3];
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
    const T t11 = T(1) / D;
    const T t12 = T(3) * t9 * t7 * a_minus_b + T(3) * t5 * t3 * b + T(4) * t11 * a * (t4 * t3 * b + T(2) * t11 * (t7 * a_minus_b + t3 * b) * a + t8 * t7 * a_minus_b);
    const T t13 = T(5) * t6 * t3 * b + T(5) * t10 * t7 * a_minus_b + T(2) * t11 * a * t12;
    const T t14 = T(5) * t10 * t7 - t13 * t11 * b - T(5) * t6 * t3;
    const T t15 = T(1) / a;
    const T t16 = T(3) * t13 * c * t11 + T(6) * t14 * t15 * b - T(7) * t11 * t12;
    F = (T(1) / T(35)) * t13 * t11 * in.w[0] - (T(1) / T(35)) * t14 * in.w[1] * t15 - (T(1) / T(105)) * (T(2) * t16 * t15 * b - T(7) * (t11 * t12 * b + T(3) * t5 * t3 - T(3) * t9 * t7) * t15 - T(3) * t14 * c * t15) * t15 * in.w[3] - (T(1) / T(105)) * t16 * in.w[2] * t15;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 59 +, 156 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3641 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[3] * in.w[2] + M_flat[4] * in.w[3] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
    G_ab = M_beyond[4] * in.w[3] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t6 * t5;
    const T t13 = T(3) * t6 * a_minus_b * t4 + T(3) * b * t8 * t10 + T(4) * (b * t8 * t9 + t5 * a_minus_b * t4 + T(2) * (a_minus_b * t4 + b * t8) * t3 * a) * t3 * a;
    const T t14 = T(5) * b * t8 * t11 + T(5) * t12 * a_minus_b * t4 + T(2) * t3 * t13 * a;
    const T t15 = t10 * t10;
    const T t16 = T(35) * t7 * a_minus_b * t4 + T(8) * t14 * t3 * a + T(35) * b * t8 * t15;
    const T t17 = b * t3 * t16 + T(35) * t8 * t15 - T(35) * t7 * t4;
    const T t18 = T(1) / a;
    const T t19 = T(9) * t14 * t3 + T(2) * b * t17 * t18 - c * t3 * t16;
    const T t20 = b * t14 * t3 + T(5) * t8 * t11 - T(5) * t12 * t4;
    const T t21 = t17 * c * t18 - T(2) * t19 * b * t18 - T(9) * t20 * t18;
    G_ap = (T(1) / T(315)) * t3 * t16 * in.w[0] + (T(1) / T(315)) * t19 * in.w[2] * t18 + (T(1) / T(315)) * t17 * in.w[1] * t18 - (T(1) / T(315)) * t21 * t18 * in.w[3];
    G_ab = (T(1) / T(315)) * t19 * in.w[1] * t18 + (T(1) / T(315)) * t17 * t18 * in.w[0] - (T(1) / T(315)) * t21 * in.w[2] * t18 - (T(1) / T(315)) * (t19 * c * t18 + T(2) * b * t21 * t18 - T(3) * (T(7) * t3 * t13 + T(6) * b * t20 * t18 - T(3) * t14 * c * t3) * t18) * t18 * in.w[3];
  }
  const T g_factor = -T(9) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Operations: 66 +, 183 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1340 +, 3713 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
    G_ap = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2];
    G_ab = in.w[2] * M_flat[8] + M_flat[7] * in.w[1] + M_flat[6] * in.w[0] + in.w[3] * M_flat[9];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(9, 11, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[5] * in.w[0] + in.w[1] * M_beyond[6] + M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3];
    G_ab = in.w[1] * M_beyond[7] + in.w[0] * M_beyond[6] + in.w[2] * M_beyond[8] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = T(4) * (T(2) * t7 * a * (a_minus_b * t3 + t8 * b) + t9 * t8 * b + a_minus_b * t4 * t3) * t7 * a + T(3) * a_minus_b * t5 * t3 + T(3) * t10 * t8 * b;
    const T t12 = t10 * t9;
    const T t13 = T(5) * a_minus_b * t6 * t3 + T(2) * t11 * t7 * a + T(5) * t12 * t8 * b;
    const T t14 = t13 * t7 * b + T(5) * t12 * t8 - T(5) * t6 * t3;
    const T t15 = T(1) / a;
    const T t16 = T(3) * c * t13 * t7 - T(6) * t14 * t15 * b - T(7) * t11 * t7;
    F = (T(1) / T(35)) * t14 * in.w[1] * t15 + (T(1) / T(35)) * t13 * t7 * in.w[0] - (T(1) / T(105)) * in.w[2] * t16 * t15 - (T(1) / T(105)) * (T(2) * t16 * t15 * b + T(3) * t14 * c * t15 - T(7) * (t11 * t7 * b + T(3) * t10 * t8 - T(3) * t5 * t3) * t15) * t15 * in.w[3];
    const T t17 = t10 * t10;
    const T t18 = t5 * t5;
    const T t19 = T(35) * t17 * t8 * b + T(8) * t13 * t7 * a + T(35) * a_minus_b * t18 * t3;
    const T t20 = T(35) * t17 * t8 + t19 * t7 * b - T(35) * t18 * t3;
    const T t21 = T(2) * t20 * t15 * b + T(9) * t13 * t7 - t19 * c * t7;
    const T t22 = t20 * c * t15 - T(9) * t14 * t15 - T(2) * t21 * t15 * b;
    G_ap = (T(1) / T(315)) * in.w[2] * t21 * t15 + (T(1) / T(315)) * t20 * in.w[1] * t15 + (T(1) / T(315)) * t19 * t7 * in.w[0] - (T(1) / T(315)) * t15 * in.w[3] * t22;
    G_ab = (T(1) / T(315)) * t20 * t15 * in.w[0] + (T(1) / T(315)) * in.w[1] * t21 * t15 - (T(1) / T(315)) * in.w[2] * t15 * t22 - (T(1) / T(315)) * (T(2) * t15 * t22 * b + T(3) * t16 * t15 + c * t21 * t15) * t15 * in.w[3];
  }
  const T g_factor = -T(9) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−9/2) dt
/// Returns false where segment_cauchy_i9_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 66 +, 183 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i9_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(9, 11, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[3] * in.w[3];
    G_ap = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1] + in.w[3] * M_flat[8];
    G_ab = M_flat[8] * in.w[2] + M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(3) * t4 * b * t6 + T(3) * a_minus_b * t8 * t10 + T(4) * t3 * a * (a_minus_b * t8 * t9 + t4 * b * t5 + T(2) * t3 * (t4 * b + a_minus_b * t8) * a);
    const T t13 = T(5) * t4 * b * t7 + T(5) * a_minus_b * t8 * t11 + T(2) * t3 * a * t12;
    const T t14 = T(1) / a;
    const T t15 = T(5) * t4 * t7 + t3 * b * t13 - T(5) * t8 * t11;
    const T t16 = T(3) * t3 * c * t13 - T(7) * t3 * t12 - T(6) * t14 * b * t15;
    F = (T(1) / T(35)) * t3 * in.w[0] * t13 + (T(1) / T(105)) * t14 * in.w[3] * (T(7) * (T(3) * t4 * t6 + t3 * b * t12 - T(3) * t8 * t10) * t14 - T(3) * t14 * c * t15 - T(2) * t14 * b * t16) + (T(1) / T(35)) * t14 * in.w[1] * t15 - (T(1) / T(105)) * t14 * t16 * in.w[2];
    const T t17 = t6 * t6;
    const T t18 = t10 * t10;
    const T t19 = T(35) * t4 * b * t17 + T(8) * t3 * a * t13 + T(35) * a_minus_b * t8 * t18;
    const T t20 = T(35) * t4 * t17 + t3 * b * t19 - T(35) * t8 * t18;
    const T t21 = T(2) * t14 * b * t20 + T(9) * t3 * t13 - t3 * t19 * c;
    const T t22 = T(2) * t14 * b * t21 + T(9) * t14 * t15 - t14 * c * t20;
    G_ap = (T(1) / T(315)) * t22 * t14 * in.w[3] + (T(1) / T(315)) * t3 * in.w[0] * t19 + (T(1) / T(315)) * t14 * t21 * in.w[2] + (T(1) / T(315)) * t14 * in.w[1] * t20;
    G_ab = (T(1) / T(315)) * t14 * in.w[0] * t20 + (T(1) / T(315)) * t14 * t21 * in.w[1] + (T(1) / T(315)) * t22 * t14 * in.w[2] - (T(1) / T(315)) * t14 * in.w[3] * (T(3) * t14 * t16 + t14 * t21 * c - T(2) * t22 * t14 * b);
  }
  const T g_factor = -T(9) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 40 +, 75 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 859 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = t10 * t9;
    const T t13 = t10 * t10;
    F = (T(1) / T(384)) * (T(48) * t7 * b + T(7) * t8 * a * (T(5) * (T(2) * t6 * b + T(2) * a_minus_b * t10 + T(3) * (a * J2 + a_minus_b * t9 + t5 * b) * t8 * a) * t8 * a + T(8) * t11 * b + T(8) * a_minus_b * t12) + T(48) * a_minus_b * t13) * in.w[0] * t8;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 47 +, 100 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1562 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t6 * t6;
    const T t9 = t7 * t7;
    const T t10 = t9 * t7;
    const T t11 = t8 * t6;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = t12 * t6;
    const T t15 = t13 * t7;
    const T t16 = T(3) * (T(7) * t5 * a * (T(5) * (T(3) * (b * t6 + a_minus_b * t7 + J2 * a) * t5 * a + T(2) * b * t8 + T(2) * a_minus_b * t9) * t5 * a + T(8) * a_minus_b * t10 + T(8) * b * t11) + T(48) * b * t12 + T(48) * a_minus_b * t13) * t5 * a + T(128) * b * t14 + T(128) * a_minus_b * t15;
    G_ap = (T(1) / T(1280)) * t16 * t5 * in.w[0];
    G_ab = (T(1) / T(1280)) * (T(128) * t14 + b * t16 * t5 - T(128) * t15) * in.w[0] / a;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 47 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1587 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = T(48) * b * t8 + T(48) * a_minus_b * t11 + T(7) * t5 * a * (T(8) * a_minus_b * t12 + T(8) * b * t13 + T(5) * t5 * a * (T(2) * a_minus_b * t10 + T(2) * b * t7 + T(3) * t5 * a * (a * J2 + b * t6 + a_minus_b * t9)));
    F = (T(1) / T(384)) * in.w[0] * t5 * t14;
    const T t15 = t8 * t6;
    const T t16 = t11 * t9;
    const T t17 = T(128) * b * t15 + T(128) * a_minus_b * t16 + T(3) * t5 * a * t14;
    G_ap = (T(1) / T(1280)) * in.w[0] * t5 * t17;
    G_ab = -(T(1) / T(1280)) * in.w[0] * (T(128) * t16 - T(128) * t15 - t5 * b * t17) / a;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Returns false where segment_cauchy_i10_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 47 +, 104 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i10_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = T(48) * b * t8 + T(48) * a_minus_b * t11 + T(7) * t5 * a * (T(5) * t5 * a * (T(3) * t5 * a * (b * t6 + a_minus_b * t9 + a * J2) + T(2) * a_minus_b * t10 + T(2) * b * t7) + T(8) * a_minus_b * t12 + T(8) * b * t13);
    F = (T(1) / T(384)) * t5 * in.w[0] * t14;
    const T t15 = t11 * t9;
    const T t16 = t8 * t6;
    const T t17 = T(128) * a_minus_b * t15 + T(128) * b * t16 + T(3) * t5 * a * t14;
    G_ap = (T(1) / T(1280)) * t5 * in.w[0] * t17;
    G_ab = -(T(1) / T(1280)) * in.w[0] * (T(128) * t15 - t5 * t17 * b - T(128) * t16) / a;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 43 +, 81 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1549 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t6 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(1) / D;
    const T t13 = t10 * t10;
    const T t14 = T(48) * b * t7 + T(7) * (T(8) * b * t8 + T(8) * a_minus_b * t11 + T(5) * (T(2) * b * t6 + T(3) * (a_minus_b * t9 + J2 * a + b * t5) * t12 * a + T(2) * a_minus_b * t10) * t12 * a) * t12 * a + T(48) * a_minus_b * t13;
    F = (T(1) / T(384)) * t14 * t12 * in.w[0] + (T(1) / T(384)) * (T(48) * t7 + b * t14 * t12 - T(48) * t13) * in.w[1] / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 51 +, 115 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2255 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = T(1) / D;
    const T t14 = t10 * t9;
    const T t15 = t6 * t5;
    const T t16 = T(48) * b * t7 + T(7) * (T(5) * (T(2) * t10 * a_minus_b + T(3) * (b * t5 + J2 * a + t9 * a_minus_b) * t13 * a + T(2) * b * t6) * t13 * a + T(8) * t14 * a_minus_b + T(8) * b * t15) * t13 * a + T(48) * t11 * a_minus_b;
    const T t17 = T(128) * b * t8 + T(128) * t12 * a_minus_b + T(3) * t16 * t13 * a;
    const T t18 = T(128) * t8 + b * t17 * t13 - T(128) * t12;
    const T t19 = T(1) / a;
    G_ap = (T(1) / T(1280)) * in.w[1] * t18 * t19 + (T(1) / T(1280)) * t17 * in.w[0] * t13;
    G_ab = (T(1) / T(3840)) * in.w[1] * (T(10) * t16 * t13 + T(6) * b * t18 * t19 - T(3) * c * t17 * t13) * t19 + (T(1) / T(1280)) * in.w[0] * t18 * t19;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 54 +, 126 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2294 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t6 * t6;
    const T t10 = t8 * t7;
    const T t11 = t9 * t6;
    const T t12 = t9 * t9;
    const T t13 = t8 * t8;
    const T t14 = T(7) * t5 * a * (T(5) * t5 * a * (T(3) * t5 * a * (a_minus_b * t6 + b * t7 + J2 * a) + T(2) * b * t8 + T(2) * a_minus_b * t9) + T(8) * b * t10 + T(8) * a_minus_b * t11) + T(48) * a_minus_b * t12 + T(48) * b * t13;
    const T t15 = T(1) / a;
    F = (T(1) / T(384)) * in.w[0] * t5 * t14 + (T(1) / T(384)) * t15 * in.w[1] * (t5 * b * t14 + T(48) * t13 - T(48) * t12);
    const T t16 = t12 * t6;
    const T t17 = t13 * t7;
    const T t18 = T(128) * a_minus_b * t16 + T(128) * b * t17 + T(3) * t5 * a * t14;
    const T t19 = t5 * b * t18 + T(128) * t17 - T(128) * t16;
    G_ap = (T(1) / T(1280)) * in.w[0] * t5 * t18 + (T(1) / T(1280)) * t15 * in.w[1] * t19;
    G_ab = (T(1) / T(1280)) * in.w[0] * t15 * t19 + (T(1) / T(3840)) * t15 * in.w[1] * (T(6) * t15 * b * t19 + T(10) * t5 * t14 - T(3) * t5 * t18 * c);
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Returns false where segment_cauchy_i10_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 54 +, 126 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i10_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = T(48) * a_minus_b * t8 + T(48) * b * t11 + T(7) * (T(5) * t5 * a * (T(3) * (b * t9 + a_minus_b * t6 + J2 * a) * t5 * a + T(2) * a_minus_b * t7 + T(2) * b * t10) + T(8) * b * t12 + T(8) * a_minus_b * t13) * t5 * a;
    const T t15 = T(1) / a;
    F = (T(1) / T(384)) * (b * t5 * t14 + T(48) * t11 - T(48) * t8) * t15 * in.w[1] + (T(1) / T(384)) * in.w[0] * t5 * t14;
    const T t16 = t8 * t6;
    const T t17 = t11 * t9;
    const T t18 = T(3) * t5 * a * t14 + T(128) * a_minus_b * t16 + T(128) * b * t17;
    const T t19 = b * t18 * t5 + T(128) * t17 - T(128) * t16;
    G_ap = (T(1) / T(1280)) * t19 * t15 * in.w[1] + (T(1) / T(1280)) * t18 * in.w[0] * t5;
    G_ab = (T(1) / T(1280)) * t19 * in.w[0] * t15 - (T(1) / T(3840)) * (T(3) * t18 * c * t5 - T(6) * b * t19 * t15 - T(10) * t5 * t14) * t15 * in.w[1];
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 46 +, 92 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2241 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t7 * t6;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(8) * a_minus_b * t9 + T(5) * (T(2) * a_minus_b * t7 + T(2) * b * t11 + T(3) * (b * t10 + a * J2 + a_minus_b * t6) * t5 * a) * t5 * a + T(8) * b * t12;
    const T t14 = t11 * t11;
    const T t15 = T(48) * a_minus_b * t8 + T(7) * t13 * t5 * a + T(48) * b * t14;
    const T t16 = T(1) / a;
    const T t17 = T(48) * t8 - b * t5 * t15 - T(48) * t14;
    F = (T(1) / T(384)) * in.w[0] * t5 * t15 - (T(1) / T(384)) * (T(2) * b * t16 * t17 + c * t5 * t15 - T(8) * t13 * t5) * in.w[2] * t16 - (T(1) / T(384)) * in.w[1] * t16 * t17;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 57 +, 133 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2950 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t7 * b + T(7) * t9 * a * (T(8) * a_minus_b * t12 + T(5) * t9 * a * (T(2) * t6 * b + T(2) * a_minus_b * t11 + T(3) * (t5 * b + a_minus_b * t10 + J2 * a) * t9 * a) + T(8) * t13 * b) + T(48) * a_minus_b * t14;
    const T t16 = t14 * t10;
    const T t17 = T(128) * t8 * b + T(3) * t15 * t9 * a + T(128) * a_minus_b * t16;
    const T t18 = T(128) * t8 + t9 * t17 * b - T(128) * t16;
    const T t19 = T(1) / a;
    const T t20 = T(3) * c * t9 * t17 - T(6) * t18 * t19 * b - T(10) * t15 * t9;
    G_ap = (T(1) / T(1280)) * in.w[1] * t18 * t19 + (T(1) / T(1280)) * in.w[0] * t9 * t17 - (T(1) / T(3840)) * t20 * t19 * in.w[2];
    G_ab = (T(1) / T(3840)) * (T(10) * (t15 * t9 * b + T(48) * t7 - T(48) * t14) * t19 - T(3) * c * t18 * t19 - T(2) * t20 * t19 * b) * t19 * in.w[2] + (T(1) / T(1280)) * in.w[0] * t18 * t19 - (T(1) / T(3840)) * t20 * in.w[1] * t19;
  }
  const T g_factor = -T(10) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 61 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 3005 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ap = in.w[0] * M_flat[4] + M_flat[6] * in.w[2] + in.w[1] * M_flat[5];
    G_ab = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0] + M_beyond[6] * in.w[2];
    G_ab = in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t9 * t8;
    const T t12 = T(1) / D;
    const T t13 = t6 * t5;
    const T t14 = T(8) * a_minus_b * t11 + T(5) * t12 * a * (T(2) * a_minus_b * t9 + T(2) * b * t6 + T(3) * t12 * (b * t5 + J2 * a + a_minus_b * t8) * a) + T(8) * b * t13;
    const T t15 = T(48) * b * t7 + T(48) * a_minus_b * t10 + T(7) * t14 * t12 * a;
    const T t16 = b * t15 * t12 + T(48) * t7 - T(48) * t10;
    const T t17 = T(1) / a;
    F = (T(1) / T(384)) * in.w[1] * t16 * t17 + (T(1) / T(384)) * t15 * in.w[0] * t12 - (T(1) / T(384)) * (t15 * c * t12 - T(2) * b * t16 * t17 - T(8) * t14 * t12) * t17 * in.w[2];
    const T t18 = t7 * t5;
    const T t19 = t10 * t8;
    const T t20 = T(128) * b * t18 + T(128) * a_minus_b * t19 + T(3) * t15 * t12 * a;
    const T t21 = T(128) * t19 - b * t12 * t20 - T(128) * t18;
    const T t22 = T(10) * t15 * t12 - T(3) * c * t12 * t20 - T(6) * b * t21 * t17;
    G_ap = (T(1) / T(3840)) * t22 * t17 * in.w[2] + (T(1) / T(1280)) * in.w[0] * t12 * t20 - (T(1) / T(1280)) * in.w[1] * t21 * t17;
    G_ab = (T(1) / T(3840)) * (T(10) * t16 * t17 + T(3) * c * t21 * t17 + T(2) * t22 * b * t17) * t17 * in.w[2] + (T(1) / T(3840)) * t22 * in.w[1] * t17 - (T(1) / T(1280)) * in.w[0] * t21 * t17;
  }
  const T g_factor = -T(10) * length * in.s;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Returns false where segment_cauchy_i10_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 150 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i10_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + M_flat[5] * in.w[1];
    G_ab = in.w[2] * M_flat[7] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * a_minus_b * t8 + T(8) * b * t11 + T(5) * t5 * a * (T(2) * a_minus_b * t7 + T(2) * b * t10 + T(3) * t5 * a * (b * t9 + a * J2 + a_minus_b * t6));
    const T t13 = t7 * t7;
    const T t14 = t10 * t10;
    const T t15 = T(7) * t5 * a * t12 + T(48) * a_minus_b * t13 + T(48) * b * t14;
    const T t16 = T(1) / a;
    const T t17 = T(48) * t13 - T(48) * t14 - t5 * b * t15;
    F = (T(1) / T(384)) * t5 * in.w[0] * t15 - (T(1) / T(384)) * in.w[2] * t16 * (t5 * c * t15 + T(2) * t16 * b * t17 - T(8) * t5 * t12) - (T(1) / T(384)) * t16 * t17 * in.w[1];
    const T t18 = t13 * t6;
    const T t19 = t14 * t9;
    const T t20 = T(128) * a_minus_b * t18 + T(128) * b * t19 + T(3) * t5 * a * t15;
    const T t21 = T(128) * t18 - T(128) * t19 - t5 * t20 * b;
    const T t22 = T(10) * t5 * t15 - T(3) * t5 * t20 * c - T(6) * t16 * t21 * b;
    G_ap = (T(1) / T(3840)) * in.w[2] * t16 * t22 + (T(1) / T(1280)) * t5 * t20 * in.w[0] - (T(1) / T(1280)) * t16 * t21 * in.w[1];
    G_ab = (T(1) / T(3840)) * t16 * t22 * in.w[1] - (T(1) / T(1280)) * t16 * t21 * in.w[0] - (T(1) / T(3840)) * in.w[2] * (T(10) * t16 * t17 - T(2) * t16 * b * t22 - T(3) * t16 * t21 * c) * t16;
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 51 +, 106 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2935 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(10, 10, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(10, 10, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * t8 * b + T(5) * a * t5 * (T(2) * t7 * b + T(2) * a_minus_b * t10 + T(3) * (a_minus_b * t9 + t6 * b + a * J2) * a * t5) + T(8) * a_minus_b * t11;
    const T t13 = t10 * t10;
    const T t14 = t7 * t7;
    const T t15 = T(7) * a * t5 * t12 + T(48) * a_minus_b * t13 + T(48) * t14 * b;
    const T t16 = t5 * t15 * b + T(48) * t14 - T(48) * t13;
    const T t17 = T(1) / a;
    const T t18 = c * t5 * t15 - T(2) * t16 * t17 * b - T(8) * t5 * t12;
    F = (T(1) / T(384)) * t16 * t17 * in.w[1] + (T(1) / T(384)) * (T(8) * (T(8) * t8 + t5 * b * t12 - T(8) * t11) * t17 - t16 * c * t17 - T(2) * t17 * t18 * b) * t17 * in.w[3] + (T(1) / T(384)) * t5 * in.w[0] * t15 - (T(1) / T(384)) * in.w[2] * t17 * t18;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 63 +, 153 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3647 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ab = in.w[2] * M_flat[3] + in.w[0] * M_flat[1] + in.w[3] * M_flat[4] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3];
    G_ab = M_beyond[3] * in.w[2] + M_beyond[2] * in.w[1] + M_beyond[1] * in.w[0] + M_beyond[4] * in.w[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = T(8) * t12 * b + T(8) * a_minus_b * t13 + T(5) * a * t9 * (T(2) * a_minus_b * t6 + T(2) * t11 * b + T(3) * a * t9 * (t10 * b + a * J2 + a_minus_b * t5));
    const T t15 = t11 * t11;
    const T t16 = T(48) * a_minus_b * t7 + T(7) * a * t9 * t14 + T(48) * t15 * b;
    const T t17 = t15 * t10;
    const T t18 = T(128) * a_minus_b * t8 + T(3) * a * t16 * t9 + T(128) * t17 * b;
    const T t19 = T(1) / a;
    const T t20 = T(128) * t17 + t18 * t9 * b - T(128) * t8;
    const T t21 = T(10) * t16 * t9 + T(6) * t19 * t20 * b - T(3) * c * t18 * t9;
    const T t22 = T(48) * t7 - T(48) * t15 - t16 * t9 * b;
    const T t23 = T(3) * c * t19 * t20 + T(10) * t19 * t22 - T(2) * t19 * b * t21;
    G_ap = (T(1) / T(1280)) * t18 * t9 * in.w[0] + (T(1) / T(1280)) * t19 * t20 * in.w[1] + (T(1) / T(3840)) * in.w[2] * t19 * t21 - (T(1) / T(3840)) * t19 * in.w[3] * t23;
    G_ab = (T(1) / T(3840)) * t19 * t21 * in.w[1] + (T(1) / T(1280)) * t19 * in.w[0] * t20 - (T(1) / T(3840)) * (T(2) * t19 * t23 * b + c * t19 * t21 + T(10) * (T(2) * t19 * b * t22 + c * t16 * t9 - T(8) * t9 * t14) * t19) * t19 * in.w[3] - (T(1) / T(3840)) * in.w[2] * t19 * t23;
  }
  const T g_factor = -T(10) * in.s * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Operations: 70 +, 177 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3720 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2];
    G_ap = in.w[1] * M_flat[6] + in.w[3] * M_flat[8] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
    G_ab = in.w[2] * M_flat[8] + in.w[0] * M_flat[6] + in.w[3] * M_flat[9] + M_flat[7] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(10, 12, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1];
    G_ap = in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5] + M_beyond[6] * in.w[1] + in.w[3] * M_beyond[8];
    G_ab = M_beyond[6] * in.w[0] + in.w[2] * M_beyond[8] + M_beyond[9] * in.w[3] + M_beyond[7] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(8) * t8 * a_minus_b + T(5) * (T(3) * t5 * a * (b * t9 + t6 * a_minus_b + J2 * a) + T(2) * t7 * a_minus_b + T(2) * b * t10) * t5 * a + T(8) * b * t11;
    const T t13 = t10 * t10;
    const T t14 = t7 * t7;
    const T t15 = T(7) * t5 * a * t12 + T(48) * b * t13 + T(48) * t14 * a_minus_b;
    const T t16 = T(1) / a;
    const T t17 = T(48) * t14 - T(48) * t13 - b * t5 * t15;
    const T t18 = c * t5 * t15 + T(2) * b * t17 * t16 - T(8) * t5 * t12;
    F = (T(1) / T(384)) * t5 * in.w[0] * t15 - (T(1) / T(384)) * (T(8) * (T(8) * t8 - b * t5 * t12 - T(8) * t11) * t16 + T(2) * b * t18 * t16 - c * t17 * t16) * in.w[3] * t16 - (T(1) / T(384)) * t17 * t16 * in.w[1] - (T(1) / T(384)) * in.w[2] * t18 * t16;
    const T t19 = t14 * t6;
    const T t20 = t13 * t9;
    const T t21 = T(3) * t5 * a * t15 + T(128) * t19 * a_minus_b + T(128) * b * t20;
    const T t22 = T(128) * t19 - T(128) * t20 - b * t21 * t5;
    const T t23 = T(3) * c * t21 * t5 + T(6) * b * t22 * t16 - T(10) * t5 * t15;
    const T t24 = T(10) * t17 * t16 + T(2) * b * t23 * t16 - T(3) * c * t22 * t16;
    G_ap = (T(1) / T(1280)) * t21 * t5 * in.w[0] - (T(1) / T(3840)) * in.w[3] * t16 * t24 - (T(1) / T(3840)) * t23 * in.w[2] * t16 - (T(1) / T(1280)) * t22 * t16 * in.w[1];
    G_ab = (T(1) / T(3840)) * (t23 * c * t16 - T(10) * t18 * t16 - T(2) * b * t16 * t24) * in.w[3] * t16 - (T(1) / T(3840)) * t23 * t16 * in.w[1] - (T(1) / T(3840)) * in.w[2] * t16 * t24 - (T(1) / T(1280)) * t22 * in.w[0] * t16;
  }
  const T g_factor = -T(10) * in.s * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−10/2) dt
/// Returns false where segment_cauchy_i10_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 70 +, 177 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i10_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(10, 12, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0];
    G_ap = M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
    G_ab = in.w[1] * M_flat[7] + in.w[3] * M_flat[9] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t7 * t6;
    const T t12 = t10 * t9;
    const T t13 = T(5) * a * t5 * (T(3) * (a_minus_b * t9 + b * t6 + J2 * a) * a * t5 + T(2) * b * t7 + T(2) * a_minus_b * t10) + T(8) * b * t11 + T(8) * a_minus_b * t12;
    const T t14 = t10 * t10;
    const T t15 = T(48) * b * t8 + T(7) * a * t5 * t13 + T(48) * a_minus_b * t14;
    const T t16 = T(1) / a;
    const T t17 = t5 * t15 * b + T(48) * t8 - T(48) * t14;
    const T t18 = t5 * t15 * c - T(8) * t5 * t13 - T(2) * t16 * t17 * b;
    F = (T(1) / T(384)) * t5 * in.w[0] * t15 + (T(1) / T(384)) * (T(8) * t16 * (t5 * t13 * b + T(8) * t11 - T(8) * t12) - T(2) * t16 * b * t18 - t16 * t17 * c) * t16 * in.w[3] + (T(1) / T(384)) * t16 * t17 * in.w[1] - (T(1) / T(384)) * in.w[2] * t16 * t18;
    const T t19 = t8 * t6;
    const T t20 = t14 * t9;
    const T t21 = T(128) * b * t19 + T(3) * a * t5 * t15 + T(128) * a_minus_b * t20;
    const T t22 = T(128) * t20 - t21 * t5 * b - T(128) * t19;
    const T t23 = T(3) * t21 * t5 * c + T(6) * t22 * t16 * b - T(10) * t5 * t15;
    const T t24 = T(2) * t16 * t23 * b - T(10) * t16 * t17 - T(3) * t22 * t16 * c;
    G_ap = (T(1) / T(1280)) * t21 * t5 * in.w[0] - (T(1) / T(3840)) * in.w[2] * t16 * t23 - (T(1) / T(1280)) * t22 * t16 * in.w[1] - (T(1) / T(3840)) * t16 * t24 * in.w[3];
    G_ab = -(T(1) / T(3840)) * t16 * in.w[3] * (T(2) * t16 * t24 * b + T(10) * t16 * t18 - t16 * t23 * c) - (T(1) / T(3840)) * t16 * t23 * in.w[1] - (T(1) / T(3840)) * in.w[2] * t16 * t24 - (T(1) / T(1280)) * t22 * t16 * in.w[0];
  }
  const T g_factor = -T(10) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 38 +, 84 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 856 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    F = (T(1) / T(315)) * t3 * in.w[0] * (T(35) * t4 * b * t7 + T(35) * t11 * a_minus_b * t8 + T(8) * t3 * a * (T(2) * t3 * a * (T(3) * t10 * a_minus_b * t8 + T(3) * t4 * b * t6 + T(4) * t3 * a * (t4 * b * t5 + T(2) * t3 * a * (t4 * b + a_minus_b * t8) + t9 * a_minus_b * t8)) + T(5) * t4 * b * t12 + T(5) * t13 * a_minus_b * t8));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 45 +, 113 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1558 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t5 * t5;
    const T t10 = t9 * t5;
    const T t11 = t8 * t7;
    const T t12 = t9 * t9;
    const T t13 = t8 * t8;
    const T t14 = t12 * t5;
    const T t15 = t13 * t7;
    const T t16 = T(2) * (T(8) * (T(2) * a * t3 * (T(4) * (t5 * t4 * a_minus_b + T(2) * (b * t6 + t4 * a_minus_b) * a * t3 + b * t6 * t7) * a * t3 + T(3) * b * t6 * t8 + T(3) * t9 * t4 * a_minus_b) + T(5) * t10 * t4 * a_minus_b + T(5) * b * t6 * t11) * a * t3 + T(35) * t12 * t4 * a_minus_b + T(35) * b * t6 * t13) * a * t3 + T(63) * t14 * t4 * a_minus_b + T(63) * b * t6 * t15;
    G_ap = (T(1) / T(693)) * t16 * t3 * in.w[0];
    G_ab = -(T(1) / T(693)) * (T(63) * t14 * t4 - T(63) * t6 * t15 - t16 * b * t3) * in.w[0] / a;
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 45 +, 117 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1583 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t4;
    const T t12 = T(1) / D;
    const T t13 = t9 * t9;
    const T t14 = T(35) * a_minus_b * t3 * t6 + T(8) * (T(5) * b * t10 * t7 + T(5) * a_minus_b * t3 * t11 + T(2) * (T(4) * t12 * (b * t8 * t7 + a_minus_b * t3 * t4 + T(2) * (a_minus_b * t3 + b * t7) * t12 * a) * a + T(3) * a_minus_b * t3 * t5 + T(3) * b * t9 * t7) * t12 * a) * t12 * a + T(35) * b * t13 * t7;
    F = (T(1) / T(315)) * in.w[0] * t14 * t12;
    const T t15 = t6 * t4;
    const T t16 = t13 * t8;
    const T t17 = T(63) * a_minus_b * t3 * t15 + T(2) * t14 * t12 * a + T(63) * b * t16 * t7;
    G_ap = (T(1) / T(693)) * in.w[0] * t17 * t12;
    G_ab = -(T(1) / T(693)) * in.w[0] * (T(63) * t3 * t15 - t17 * b * t12 - T(63) * t16 * t7) / a;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Returns false where segment_cauchy_i11_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 117 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i11_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t6 * t5;
    const T t14 = T(35) * t7 * a_minus_b * t4 + T(35) * t11 * t8 * b + T(8) * (T(5) * t12 * t8 * b + T(5) * t13 * a_minus_b * t4 + T(2) * t3 * a * (T(3) * t10 * t8 * b + T(3) * t6 * a_minus_b * t4 + T(4) * t3 * (t5 * a_minus_b * t4 + T(2) * t3 * a * (t8 * b + a_minus_b * t4) + t9 * t8 * b) * a)) * t3 * a;
    F = (T(1) / T(315)) * t3 * in.w[0] * t14;
    const T t15 = t11 * t9;
    const T t16 = t7 * t5;
    const T t17 = T(63) * t15 * t8 * b + T(63) * t16 * a_minus_b * t4 + T(2) * t3 * a * t14;
    G_ap = (T(1) / T(693)) * t17 * t3 * in.w[0];
    G_ab = (T(1) / T(693)) * (T(63) * t15 * t8 + t17 * t3 * b - T(63) * t16 * t4) * in.w[0] / a;
  }
  const T g_factor = -T(11) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 41 +, 92 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1546 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
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
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = t10 * t10;
    const T t14 = T(8) * t7 * a * (T(2) * t7 * a * (T(4) * t7 * a * (t9 * t8 * a_minus_b + t3 * b * t4 + T(2) * t7 * a * (t3 * b + t8 * a_minus_b)) + T(3) * t3 * b * t5 + T(3) * t10 * t8 * a_minus_b) + T(5) * t11 * t8 * a_minus_b + T(5) * t3 * b * t12) + T(35) * t13 * t8 * a_minus_b + T(35) * t3 * b * t6;
    F = (T(1) / T(315)) * in.w[1] * (T(35) * t3 * t6 + t7 * b * t14 - T(35) * t13 * t8) / a + (T(1) / T(315)) * t7 * in.w[0] * t14;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 49 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2251 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  const T D = (ab_ab + in.s * cross_cross) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t6 * t5;
    const T t16 = T(35) * b * t4 * t7 + T(8) * (T(2) * (T(3) * b * t4 * t6 + T(4) * (t10 * t9 * a_minus_b + T(2) * (b * t4 + t9 * a_minus_b) * a * t3 + b * t4 * t5) * a * t3 + T(3) * t11 * t9 * a_minus_b) * a * t3 + T(5) * t14 * t9 * a_minus_b + T(5) * b * t4 * t15) * a * t3 + T(35) * t12 * t9 * a_minus_b;
    const T t17 = T(63) * b * t4 * t8 + T(63) * t13 * t9 * a_minus_b + T(2) * t16 * a * t3;
    const T t18 = T(63) * t13 * t9 - T(63) * t4 * t8 - b * t3 * t17;
    const T t19 = T(1) / a;
    G_ap = (T(1) / T(693)) * in.w[0] * t3 * t17 - (T(1) / T(693)) * t18 * t19 * in.w[1];
    G_ab = -(T(1) / T(3465)) * (T(5) * c * t3 * t17 + T(10) * t18 * b * t19 - T(11) * t16 * t3) * t19 * in.w[1] - (T(1) / T(693)) * t18 * in.w[0] * t19;
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 52 +, 141 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2290 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + M_beyond[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = T(1) / r0;
    const T t6 = T(1) / D;
    const T t7 = t5 * t5;
    const T t8 = t7 * t7;
    const T t9 = t4 * t4;
    const T t10 = t8 * t7;
    const T t11 = t9 * t4;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(8) * (T(2) * (T(4) * (t3 * a_minus_b * t4 + T(2) * (t3 * a_minus_b + b * t5) * t6 * a + b * t7 * t5) * t6 * a + T(3) * b * t8 * t5 + T(3) * t3 * a_minus_b * t9) * t6 * a + T(5) * b * t10 * t5 + T(5) * t3 * a_minus_b * t11) * t6 * a + T(35) * b * t12 * t5 + T(35) * t3 * a_minus_b * t13;
    const T t15 = T(1) / a;
    F = (T(1) / T(315)) * t14 * in.w[0] * t6 - (T(1) / T(315)) * (T(35) * t3 * t13 - b * t14 * t6 - T(35) * t12 * t5) * in.w[1] * t15;
    const T t16 = t12 * t7;
    const T t17 = t13 * t4;
    const T t18 = T(2) * t14 * t6 * a + T(63) * b * t16 * t5 + T(63) * t3 * a_minus_b * t17;
    const T t19 = T(63) * t3 * t17 - T(63) * t16 * t5 - b * t18 * t6;
    G_ap = (T(1) / T(693)) * t18 * in.w[0] * t6 - (T(1) / T(693)) * t19 * in.w[1] * t15;
    G_ab = (T(1) / T(3465)) * (T(11) * t14 * t6 - T(5) * t18 * c * t6 - T(10) * b * t19 * t15) * in.w[1] * t15 - (T(1) / T(693)) * t19 * in.w[0] * t15;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Returns false where segment_cauchy_i11_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 141 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i11_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / r0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * t8;
    const T t11 = t5 * t4;
    const T t12 = T(1) / D;
    const T t13 = t9 * t9;
    const T t14 = T(35) * t3 * a_minus_b * t6 + T(8) * a * (T(5) * b * t10 * t7 + T(5) * t3 * a_minus_b * t11 + T(2) * a * (T(3) * b * t9 * t7 + T(3) * t3 * a_minus_b * t5 + T(4) * a * (t3 * a_minus_b * t4 + b * t8 * t7 + T(2) * a * (t3 * a_minus_b + b * t7) * t12) * t12) * t12) * t12 + T(35) * b * t13 * t7;
    const T t15 = T(1) / a;
    F = (T(1) / T(315)) * t14 * in.w[0] * t12 + (T(1) / T(315)) * (T(35) * t13 * t7 + t14 * b * t12 - T(35) * t3 * t6) * t15 * in.w[1];
    const T t16 = t13 * t8;
    const T t17 = t6 * t4;
    const T t18 = T(63) * t3 * a_minus_b * t17 + T(2) * a * t14 * t12 + T(63) * b * t16 * t7;
    const T t19 = T(63) * t16 * t7 + t18 * b * t12 - T(63) * t3 * t17;
    G_ap = (T(1) / T(693)) * t15 * in.w[1] * t19 + (T(1) / T(693)) * t18 * in.w[0] * t12;
    G_ab = (T(1) / T(693)) * t15 * t19 * in.w[0] + (T(1) / T(3465)) * t15 * in.w[1] * (T(11) * t14 * t12 + T(10) * t15 * b * t19 - T(5) * t18 * c * t12);
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 44 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2238 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * b * t6 * t3 + T(2) * t7 * (T(3) * b * t5 * t3 + T(4) * (t8 * a_minus_b * t9 + T(2) * (b * t3 + t8 * a_minus_b) * t7 * a + b * t4 * t3) * t7 * a + T(3) * t8 * a_minus_b * t10) * a + T(5) * t8 * a_minus_b * t11;
    const T t13 = t10 * t10;
    const T t14 = t5 * t5;
    const T t15 = T(8) * t12 * t7 * a + T(35) * t8 * a_minus_b * t13 + T(35) * b * t14 * t3;
    const T t16 = T(35) * t8 * t13 - T(35) * t14 * t3 - b * t15 * t7;
    const T t17 = T(1) / a;
    F = (T(1) / T(315)) * t15 * t7 * in.w[0] + (T(1) / T(315)) * (T(9) * t12 * t7 - T(2) * b * t16 * t17 - t15 * c * t7) * in.w[2] * t17 - (T(1) / T(315)) * t16 * in.w[1] * t17;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 55 +, 148 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2946 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + in.w[1] * M_beyond[2] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t7;
    const T t14 = t11 * t11;
    const T t15 = T(8) * t4 * a * (T(5) * b * t5 * t8 + T(2) * t4 * a * (T(4) * t4 * a * (t9 * a_minus_b * t10 + b * t5 * t6 + T(2) * (b * t5 + t9 * a_minus_b) * t4 * a) + T(3) * b * t5 * t7 + T(3) * t9 * a_minus_b * t11) + T(5) * t9 * a_minus_b * t12) + T(35) * b * t5 * t13 + T(35) * t9 * a_minus_b * t14;
    const T t16 = t13 * t6;
    const T t17 = t14 * t10;
    const T t18 = T(63) * b * t5 * t16 + T(2) * t4 * a * t15 + T(63) * t9 * a_minus_b * t17;
    const T t19 = T(63) * t9 * t17 - T(63) * t5 * t16 - t4 * b * t18;
    const T t20 = T(11) * t4 * t15 - T(5) * t4 * t18 * c - T(10) * t19 * t3 * b;
    G_ap = (T(1) / T(3465)) * t3 * in.w[2] * t20 + (T(1) / T(693)) * t4 * t18 * in.w[0] - (T(1) / T(693)) * t19 * in.w[1] * t3;
    G_ab = (T(1) / T(3465)) * in.w[1] * t3 * t20 + (T(1) / T(3465)) * t3 * in.w[2] * (T(5) * t19 * t3 * c + T(11) * t3 * (t4 * t15 * b + T(35) * t5 * t13 - T(35) * t9 * t14) + T(2) * t3 * b * t20) - (T(1) / T(693)) * t19 * t3 * in.w[0];
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 59 +, 165 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 3001 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + M_flat[6] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1] + in.w[2] * M_beyond[6];
    G_ab = M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1] + M_beyond[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t5 * t4;
    const T t13 = T(5) * t8 * b * t11 + T(2) * t7 * a * (T(4) * t7 * a * (t3 * a_minus_b * t4 + t8 * b * t9 + T(2) * t7 * a * (t8 * b + t3 * a_minus_b)) + T(3) * t8 * b * t10 + T(3) * t3 * a_minus_b * t5) + T(5) * t3 * a_minus_b * t12;
    const T t14 = t10 * t10;
    const T t15 = T(35) * t3 * a_minus_b * t6 + T(8) * t7 * t13 * a + T(35) * t8 * b * t14;
    const T t16 = T(1) / a;
    const T t17 = t15 * t7 * b + T(35) * t8 * t14 - T(35) * t3 * t6;
    F = (T(1) / T(315)) * t15 * t7 * in.w[0] + (T(1) / T(315)) * (T(2) * t16 * b * t17 + T(9) * t7 * t13 - t15 * t7 * c) * in.w[2] * t16 + (T(1) / T(315)) * t16 * t17 * in.w[1];
    const T t18 = t6 * t4;
    const T t19 = t14 * t9;
    const T t20 = T(63) * t3 * a_minus_b * t18 + T(2) * t15 * t7 * a + T(63) * t8 * b * t19;
    const T t21 = T(63) * t3 * t18 - t7 * b * t20 - T(63) * t8 * t19;
    const T t22 = T(10) * t16 * b * t21 + T(5) * t7 * c * t20 - T(11) * t15 * t7;
    G_ap = (T(1) / T(693)) * t7 * in.w[0] * t20 - (T(1) / T(3465)) * in.w[2] * t16 * t22 - (T(1) / T(693)) * t16 * t21 * in.w[1];
    G_ab = (T(1) / T(3465)) * in.w[2] * t16 * (T(11) * t16 * t17 + T(5) * t16 * t21 * c - T(2) * t16 * b * t22) - (T(1) / T(693)) * t16 * t21 * in.w[0] - (T(1) / T(3465)) * t16 * t22 * in.w[1];
  }
  const T g_factor = -T(11) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Returns false where segment_cauchy_i11_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 165 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i11_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[4] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + M_flat[6] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(5) * b * t7 * t4 + T(5) * t8 * a_minus_b * t11 + T(2) * t3 * a * (T(4) * t3 * a * (t8 * a_minus_b * t9 + b * t5 * t4 + T(2) * t3 * a * (t8 * a_minus_b + b * t4)) + T(3) * b * t6 * t4 + T(3) * t8 * a_minus_b * t10);
    const T t13 = t10 * t10;
    const T t14 = t6 * t6;
    const T t15 = T(8) * t3 * a * t12 + T(35) * t8 * a_minus_b * t13 + T(35) * b * t14 * t4;
    const T t16 = T(1) / a;
    const T t17 = T(35) * t8 * t13 - T(35) * t14 * t4 - t3 * b * t15;
    F = (T(1) / T(315)) * t3 * in.w[0] * t15 - (T(1) / T(315)) * t16 * in.w[1] * t17 - (T(1) / T(315)) * in.w[2] * t16 * (t3 * c * t15 + T(2) * t16 * b * t17 - T(9) * t3 * t12);
    const T t18 = t14 * t5;
    const T t19 = t13 * t9;
    const T t20 = T(2) * t3 * a * t15 + T(63) * b * t18 * t4 + T(63) * t8 * a_minus_b * t19;
    const T t21 = T(63) * t8 * t19 - T(63) * t18 * t4 - t3 * b * t20;
    const T t22 = T(11) * t3 * t15 - T(5) * t3 * c * t20 - T(10) * t16 * b * t21;
    G_ap = (T(1) / T(3465)) * in.w[2] * t16 * t22 + (T(1) / T(693)) * t3 * in.w[0] * t20 - (T(1) / T(693)) * t16 * t21 * in.w[1];
    G_ab = (T(1) / T(3465)) * t16 * in.w[1] * t22 + (T(1) / T(3465)) * in.w[2] * t16 * (T(5) * t16 * t21 * c + T(2) * t16 * b * t22 - T(11) * t16 * t17) - (T(1) / T(693)) * t16 * in.w[0] * t21;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 49 +, 119 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2932 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(11, 11, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[3] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(11, 11, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2];
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
    const T t11 = T(1) / D;
    const T t12 = t9 * t8;
    const T t13 = t5 * t4;
    const T t14 = T(5) * t7 * a_minus_b * t12 + T(5) * t13 * t3 * b + T(2) * (T(3) * t7 * a_minus_b * t9 + T(3) * t5 * t3 * b + T(4) * (T(2) * t11 * (t7 * a_minus_b + t3 * b) * a + t7 * a_minus_b * t8 + t4 * t3 * b) * t11 * a) * t11 * a;
    const T t15 = T(35) * t6 * t3 * b + T(35) * t7 * a_minus_b * t10 + T(8) * t11 * a * t14;
    const T t16 = T(1) / a;
    const T t17 = t15 * t11 * b + T(35) * t6 * t3 - T(35) * t7 * t10;
    const T t18 = T(9) * t11 * t14 + T(2) * t16 * b * t17 - c * t15 * t11;
    F = (T(1) / T(315)) * t15 * t11 * in.w[0] + (T(1) / T(315)) * t18 * in.w[2] * t16 + (T(1) / T(315)) * in.w[1] * t16 * t17 + (T(1) / T(315)) * (T(9) * (T(5) * t13 * t3 + t11 * t14 * b - T(5) * t7 * t12) * t16 + T(2) * t18 * t16 * b - c * t16 * t17) * t16 * in.w[3];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 61 +, 168 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3643 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0];
    G_ab = M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0] + M_flat[4] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + M_beyond[2] * in.w[1];
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
    const T t13 = T(1) / D;
    const T t14 = t5 * t4;
    const T t15 = t10 * t9;
    const T t16 = T(2) * t13 * a * (T(4) * t13 * a * (b * t8 * t9 + T(2) * t13 * a * (b * t8 + a_minus_b * t3) + a_minus_b * t3 * t4) + T(3) * a_minus_b * t3 * t5 + T(3) * b * t8 * t10) + T(5) * a_minus_b * t3 * t14 + T(5) * b * t8 * t15;
    const T t17 = T(35) * a_minus_b * t3 * t6 + T(8) * t16 * t13 * a + T(35) * b * t8 * t11;
    const T t18 = T(63) * a_minus_b * t3 * t7 + T(63) * b * t8 * t12 + T(2) * t13 * a * t17;
    const T t19 = T(1) / a;
    const T t20 = T(63) * t3 * t7 - T(63) * t8 * t12 - t18 * t13 * b;
    const T t21 = T(11) * t13 * t17 - T(5) * t18 * t13 * c - T(10) * t19 * b * t20;
    const T t22 = T(35) * t8 * t11 + t13 * b * t17 - T(35) * t3 * t6;
    const T t23 = T(11) * t22 * t19 + T(2) * t19 * t21 * b + T(5) * t19 * t20 * c;
    G_ap = (T(1) / T(693)) * t18 * t13 * in.w[0] + (T(1) / T(3465)) * in.w[2] * t19 * t21 + (T(1) / T(3465)) * t23 * t19 * in.w[3] - (T(1) / T(693)) * t19 * in.w[1] * t20;
    G_ab = (T(1) / T(3465)) * t19 * t21 * in.w[1] + (T(1) / T(3465)) * in.w[2] * t23 * t19 - (T(1) / T(693)) * t19 * in.w[0] * t20 - (T(1) / T(3465)) * (t19 * t21 * c - T(11) * t19 * (T(2) * t22 * t19 * b + T(9) * t16 * t13 - t13 * t17 * c) - T(2) * t23 * t19 * b) * t19 * in.w[3];
  }
  const T g_factor = -T(11) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Operations: 68 +, 194 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1340 +, 3716 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1] + in.w[3] * M_flat[8];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(11, 13, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + in.w[3] * M_beyond[3] + in.w[0] * M_beyond[0];
    G_ap = in.w[2] * M_beyond[7] + M_beyond[5] * in.w[0] + M_beyond[8] * in.w[3] + M_beyond[6] * in.w[1];
    G_ab = in.w[2] * M_beyond[8] + in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = t10 * t9;
    const T t13 = T(2) * t3 * a * (T(3) * t4 * b * t6 + T(4) * t3 * a * (T(2) * t3 * a * (t8 * a_minus_b + t4 * b) + t8 * a_minus_b * t9 + t4 * b * t5) + T(3) * t8 * a_minus_b * t10) + T(5) * t4 * b * t11 + T(5) * t8 * a_minus_b * t12;
    const T t14 = t10 * t10;
    const T t15 = T(35) * t4 * b * t7 + T(8) * t3 * a * t13 + T(35) * t8 * a_minus_b * t14;
    const T t16 = T(1) / a;
    const T t17 = T(35) * t4 * t7 + t3 * t15 * b - T(35) * t8 * t14;
    const T t18 = t3 * t15 * c - T(2) * t16 * b * t17 - T(9) * t3 * t13;
    F = (T(1) / T(315)) * t3 * t15 * in.w[0] + (T(1) / T(315)) * t16 * in.w[1] * t17 - (T(1) / T(315)) * (t16 * t17 * c + T(2) * t18 * t16 * b - T(9) * (t3 * b * t13 + T(5) * t4 * t11 - T(5) * t8 * t12) * t16) * t16 * in.w[3] - (T(1) / T(315)) * in.w[2] * t18 * t16;
    const T t19 = t7 * t5;
    const T t20 = t14 * t9;
    const T t21 = T(63) * t4 * b * t19 + T(2) * t3 * t15 * a + T(63) * t8 * a_minus_b * t20;
    const T t22 = T(63) * t4 * t19 + t3 * t21 * b - T(63) * t8 * t20;
    const T t23 = T(10) * t16 * t22 * b + T(11) * t3 * t15 - T(5) * t3 * t21 * c;
    const T t24 = T(2) * t16 * t23 * b + T(11) * t16 * t17 - T(5) * t16 * t22 * c;
    G_ap = (T(1) / T(693)) * t16 * t22 * in.w[1] + (T(1) / T(3465)) * t24 * t16 * in.w[3] + (T(1) / T(3465)) * in.w[2] * t16 * t23 + (T(1) / T(693)) * t3 * t21 * in.w[0];
    G_ab = (T(1) / T(3465)) * t16 * t23 * in.w[1] + (T(1) / T(693)) * t16 * t22 * in.w[0] + (T(1) / T(3465)) * (T(2) * t24 * t16 * b - t16 * t23 * c - T(11) * t18 * t16) * t16 * in.w[3] + (T(1) / T(3465)) * t24 * in.w[2] * t16;
  }
  const T g_factor = -T(11) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−11/2) dt
/// Returns false where segment_cauchy_i11_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 68 +, 194 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i11_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(11, 13, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[3] * in.w[3];
    G_ap = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[2] * M_flat[7];
    G_ab = M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + in.w[1] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = T(1) / D;
    const T t13 = t10 * t9;
    const T t14 = t6 * t5;
    const T t15 = T(2) * (T(4) * (T(2) * t12 * a * (t8 * b + a_minus_b * t4) + t9 * t8 * b + t5 * a_minus_b * t4) * t12 * a + T(3) * t6 * a_minus_b * t4 + T(3) * t10 * t8 * b) * t12 * a + T(5) * t13 * t8 * b + T(5) * t14 * a_minus_b * t4;
    const T t16 = T(35) * t7 * a_minus_b * t4 + T(8) * t12 * a * t15 + T(35) * t11 * t8 * b;
    const T t17 = T(35) * t7 * t4 - T(35) * t11 * t8 - t16 * t12 * b;
    const T t18 = T(2) * t17 * t3 * b + t16 * c * t12 - T(9) * t12 * t15;
    F = (T(1) / T(315)) * t3 * in.w[3] * (c * t17 * t3 + T(9) * (t12 * t15 * b + T(5) * t13 * t8 - T(5) * t14 * t4) * t3 - T(2) * t3 * t18 * b) + (T(1) / T(315)) * t16 * t12 * in.w[0] - (T(1) / T(315)) * in.w[2] * t3 * t18 - (T(1) / T(315)) * in.w[1] * t17 * t3;
    const T t19 = t7 * t5;
    const T t20 = t11 * t9;
    const T t21 = T(63) * t19 * a_minus_b * t4 + T(63) * t20 * t8 * b + T(2) * t16 * t12 * a;
    const T t22 = T(63) * t19 * t4 - T(63) * t20 * t8 - t21 * t12 * b;
    const T t23 = T(10) * t22 * t3 * b + T(5) * c * t21 * t12 - T(11) * t16 * t12;
    const T t24 = T(5) * c * t22 * t3 - T(2) * t23 * t3 * b - T(11) * t17 * t3;
    G_ap = (T(1) / T(693)) * t21 * t12 * in.w[0] + (T(1) / T(3465)) * t24 * t3 * in.w[3] - (T(1) / T(3465)) * t23 * in.w[2] * t3 - (T(1) / T(693)) * in.w[1] * t22 * t3;
    G_ab = (T(1) / T(3465)) * t3 * in.w[3] * (T(2) * t24 * t3 * b + t23 * c * t3 - T(11) * t3 * t18) + (T(1) / T(3465)) * t24 * in.w[2] * t3 - (T(1) / T(693)) * t22 * t3 * in.w[0] - (T(1) / T(3465)) * in.w[1] * t23 * t3;
  }
  const T g_factor = -T(11) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 42 +, 84 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 862 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
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
    F = (T(1) / T(1280)) * t5 * in.w[0] * (T(128) * a_minus_b * t9 + T(128) * b * t13 + T(3) * t5 * a * (T(48) * a_minus_b * t8 + T(7) * t5 * a * (T(5) * t5 * a * (T(3) * t5 * a * (a * J2 + b * t10 + a_minus_b * t6) + T(2) * a_minus_b * t7 + T(2) * b * t11) + T(8) * a_minus_b * t14 + T(8) * b * t15) + T(48) * b * t12));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 49 +, 109 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1564 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t7 * t6;
    const T t15 = t11 * t10;
    const T t16 = t14 * t14;
    const T t17 = t15 * t15;
    const T t18 = T(11) * t5 * a * (T(128) * b * t9 + T(128) * t13 * a_minus_b + T(3) * t5 * a * (T(48) * b * t8 + T(48) * t12 * a_minus_b + T(7) * t5 * a * (T(8) * b * t14 + T(5) * t5 * a * (T(2) * b * t7 + T(2) * t11 * a_minus_b + T(3) * t5 * (t10 * a_minus_b + b * t6 + a * J2) * a) + T(8) * t15 * a_minus_b))) + T(1280) * b * t16 + T(1280) * t17 * a_minus_b;
    G_ap = (T(1) / T(15360)) * t5 * in.w[0] * t18;
    G_ab = -(T(1) / T(15360)) * (T(1280) * t17 - T(1280) * t16 - t5 * b * t18) * in.w[0] / a;
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 49 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1590 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t10 * t9;
    const T t14 = T(1) / D;
    const T t15 = t6 * t5;
    const T t16 = T(128) * t8 * a_minus_b + T(128) * t12 * b + T(3) * (T(48) * t7 * a_minus_b + T(7) * (T(8) * t13 * b + T(5) * (T(2) * t10 * b + T(2) * t6 * a_minus_b + T(3) * (J2 * a + t5 * a_minus_b + t9 * b) * t14 * a) * t14 * a + T(8) * t15 * a_minus_b) * t14 * a + T(48) * t11 * b) * t14 * a;
    F = (T(1) / T(1280)) * t16 * t14 * in.w[0];
    const T t17 = t15 * t15;
    const T t18 = t13 * t13;
    const T t19 = T(11) * t16 * t14 * a + T(1280) * t17 * a_minus_b + T(1280) * t18 * b;
    G_ap = (T(1) / T(15360)) * t14 * in.w[0] * t19;
    G_ab = -(T(1) / T(15360)) * in.w[0] * (T(1280) * t17 - T(1280) * t18 - t14 * t19 * b) / a;
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Returns false where segment_cauchy_i12_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 113 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i12_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = t12 * t9;
    const T t15 = t13 * t6;
    const T t16 = T(3) * t5 * a * (T(7) * t5 * a * (T(8) * t8 * b + T(8) * t11 * a_minus_b + T(5) * (T(2) * t10 * a_minus_b + T(2) * t7 * b + T(3) * (t6 * b + J2 * a + t9 * a_minus_b) * t5 * a) * t5 * a) + T(48) * t12 * a_minus_b + T(48) * t13 * b) + T(128) * t14 * a_minus_b + T(128) * t15 * b;
    F = (T(1) / T(1280)) * t16 * t5 * in.w[0];
    const T t17 = t8 * t8;
    const T t18 = t11 * t11;
    const T t19 = T(11) * t16 * t5 * a + T(1280) * t17 * b + T(1280) * t18 * a_minus_b;
    G_ap = (T(1) / T(15360)) * t19 * t5 * in.w[0];
    G_ab = (T(1) / T(15360)) * (t19 * t5 * b + T(1280) * t17 - T(1280) * t18) * in.w[0] / a;
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 45 +, 90 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1552 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t6 * t5;
    const T t15 = t11 * t10;
    const T t16 = T(128) * t13 * a_minus_b + T(3) * t9 * a * (T(48) * t12 * a_minus_b + T(48) * t7 * b + T(7) * (T(5) * t9 * a * (T(2) * t6 * b + T(3) * t9 * a * (t10 * a_minus_b + a * J2 + t5 * b) + T(2) * t11 * a_minus_b) + T(8) * t14 * b + T(8) * t15 * a_minus_b) * t9 * a) + T(128) * t8 * b;
    F = (T(1) / T(1280)) * (T(128) * t8 + t9 * b * t16 - T(128) * t13) * in.w[1] / a + (T(1) / T(1280)) * in.w[0] * t9 * t16;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 53 +, 123 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2257 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1] + M_flat[2] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
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
    const T t17 = T(1) / D;
    const T t18 = T(128) * b * t14 + T(128) * a_minus_b * t16 + T(3) * t17 * a * (T(48) * b * t13 + T(48) * a_minus_b * t15 + T(7) * (T(8) * a_minus_b * t11 + T(8) * b * t7 + T(5) * t17 * a * (T(2) * a_minus_b * t10 + T(2) * b * t6 + T(3) * t17 * a * (a * J2 + b * t5 + a_minus_b * t9))) * t17 * a);
    const T t19 = T(1280) * b * t8 + T(1280) * a_minus_b * t12 + T(11) * t18 * t17 * a;
    const T t20 = T(1280) * t12 - t19 * t17 * b - T(1280) * t8;
    const T t21 = T(1) / a;
    G_ap = (T(1) / T(15360)) * in.w[0] * t19 * t17 - (T(1) / T(15360)) * t20 * t21 * in.w[1];
    G_ab = -(T(1) / T(15360)) * t20 * in.w[0] * t21 - (T(1) / T(15360)) * (t19 * t17 * c + T(2) * t20 * t21 * b - T(12) * t18 * t17) * t21 * in.w[1];
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 56 +, 134 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2297 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = t11 * t11;
    const T t15 = t14 * t10;
    const T t16 = T(128) * t8 * a_minus_b + T(3) * t9 * a * (T(48) * t7 * a_minus_b + T(7) * t9 * a * (T(8) * b * t12 + T(5) * (T(3) * (t5 * a_minus_b + b * t10 + J2 * a) * t9 * a + T(2) * b * t11 + T(2) * t6 * a_minus_b) * t9 * a + T(8) * t13 * a_minus_b) + T(48) * b * t14) + T(128) * b * t15;
    const T t17 = T(1) / a;
    F = (T(1) / T(1280)) * t16 * in.w[0] * t9 - (T(1) / T(1280)) * (T(128) * t8 - t16 * b * t9 - T(128) * t15) * t17 * in.w[1];
    const T t18 = t13 * t13;
    const T t19 = t12 * t12;
    const T t20 = T(1280) * t18 * a_minus_b + T(11) * t16 * t9 * a + T(1280) * b * t19;
    const T t21 = b * t9 * t20 + T(1280) * t19 - T(1280) * t18;
    G_ap = (T(1) / T(15360)) * t21 * t17 * in.w[1] + (T(1) / T(15360)) * in.w[0] * t9 * t20;
    G_ab = (T(1) / T(15360)) * t21 * in.w[0] * t17 + (T(1) / T(15360)) * (T(2) * b * t21 * t17 + T(12) * t16 * t9 - c * t9 * t20) * t17 * in.w[1];
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Returns false where segment_cauchy_i12_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 56 +, 134 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i12_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t7 * t6;
    const T t16 = T(128) * b * t9 + T(128) * a_minus_b * t13 + T(3) * (T(7) * (T(5) * t5 * a * (T(3) * t5 * a * (a_minus_b * t10 + b * t6 + J2 * a) + T(2) * b * t7 + T(2) * a_minus_b * t11) + T(8) * a_minus_b * t14 + T(8) * b * t15) * t5 * a + T(48) * b * t8 + T(48) * a_minus_b * t12) * t5 * a;
    const T t17 = T(1) / a;
    F = (T(1) / T(1280)) * in.w[0] * t5 * t16 - (T(1) / T(1280)) * t17 * in.w[1] * (T(128) * t13 - T(128) * t9 - t5 * b * t16);
    const T t18 = t15 * t15;
    const T t19 = t14 * t14;
    const T t20 = T(11) * t5 * a * t16 + T(1280) * a_minus_b * t19 + T(1280) * b * t18;
    const T t21 = T(1280) * t18 + t5 * b * t20 - T(1280) * t19;
    G_ap = (T(1) / T(15360)) * t21 * t17 * in.w[1] + (T(1) / T(15360)) * in.w[0] * t5 * t20;
    G_ab = (T(1) / T(15360)) * in.w[0] * t21 * t17 - (T(1) / T(15360)) * t17 * in.w[1] * (t5 * t20 * c - T(12) * t5 * t16 - T(2) * t21 * t17 * b);
  }
  const T g_factor = -T(12) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 48 +, 102 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2244 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
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
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t6;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t8 * a_minus_b + T(7) * t5 * a * (T(5) * t5 * a * (T(2) * b * t11 + T(2) * t7 * a_minus_b + T(3) * t5 * a * (t6 * a_minus_b + b * t10 + a * J2)) + T(8) * b * t12 + T(8) * t13 * a_minus_b) + T(48) * b * t14;
    const T t16 = t14 * t10;
    const T t17 = T(128) * t9 * a_minus_b + T(3) * t5 * a * t15 + T(128) * b * t16;
    const T t18 = t5 * b * t17 + T(128) * t16 - T(128) * t9;
    const T t19 = T(1) / a;
    F = (T(1) / T(1280)) * t18 * t19 * in.w[1] + (T(1) / T(1280)) * t5 * in.w[0] * t17 - (T(1) / T(3840)) * (T(3) * t5 * t17 * c - T(10) * t5 * t15 - T(6) * t18 * t19 * b) * in.w[2] * t19;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 59 +, 140 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2952 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t12;
    const T t16 = t13 * t12;
    const T t17 = T(128) * b * t11 + T(128) * a_minus_b * t15 + T(3) * (T(48) * b * t10 + T(7) * t5 * a * (T(5) * t5 * (T(2) * a_minus_b * t13 + T(2) * b * t7 + T(3) * t5 * a * (b * t6 + a * J2 + a_minus_b * t12)) * a + T(8) * a_minus_b * t16 + T(8) * b * t8) + T(48) * a_minus_b * t14) * t5 * a;
    const T t18 = t16 * t16;
    const T t19 = T(1280) * b * t9 + T(11) * t5 * a * t17 + T(1280) * a_minus_b * t18;
    const T t20 = T(1280) * t9 + t5 * b * t19 - T(1280) * t18;
    const T t21 = T(1) / a;
    const T t22 = t5 * t19 * c - T(12) * t5 * t17 - T(2) * t20 * t21 * b;
    G_ap = (T(1) / T(15360)) * t5 * t19 * in.w[0] + (T(1) / T(15360)) * t20 * t21 * in.w[1] - (T(1) / T(15360)) * t21 * in.w[2] * t22;
    G_ab = (T(1) / T(15360)) * t20 * t21 * in.w[0] - (T(1) / T(15360)) * t21 * in.w[2] * (t20 * t21 * c + T(2) * t21 * b * t22 - T(12) * t21 * (t5 * b * t17 + T(128) * t11 - T(128) * t15)) - (T(1) / T(15360)) * t21 * in.w[1] * t22;
  }
  const T g_factor = -T(12) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 63 +, 158 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 3008 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2];
    G_ap = M_beyond[6] * in.w[2] + in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
    G_ab = in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = T(48) * t8 * a_minus_b + T(48) * t11 * b + T(7) * (T(8) * t12 * b + T(8) * t13 * a_minus_b + T(5) * (T(2) * t10 * b + T(3) * (t6 * a_minus_b + J2 * a + t9 * b) * t5 * a + T(2) * t7 * a_minus_b) * t5 * a) * t5 * a;
    const T t15 = t11 * t9;
    const T t16 = t8 * t6;
    const T t17 = T(3) * t5 * a * t14 + T(128) * t15 * b + T(128) * t16 * a_minus_b;
    const T t18 = T(1) / a;
    const T t19 = T(128) * t16 - T(128) * t15 - t5 * b * t17;
    F = (T(1) / T(1280)) * t5 * t17 * in.w[0] - (T(1) / T(1280)) * in.w[1] * t18 * t19 - (T(1) / T(3840)) * (T(3) * c * t5 * t17 + T(6) * t18 * t19 * b - T(10) * t5 * t14) * t18 * in.w[2];
    const T t20 = t12 * t12;
    const T t21 = t13 * t13;
    const T t22 = T(11) * t5 * a * t17 + T(1280) * t21 * a_minus_b + T(1280) * t20 * b;
    const T t23 = T(1280) * t20 + t5 * b * t22 - T(1280) * t21;
    const T t24 = T(2) * t18 * t23 * b + T(12) * t5 * t17 - c * t5 * t22;
    G_ap = (T(1) / T(15360)) * t24 * t18 * in.w[2] + (T(1) / T(15360)) * in.w[1] * t18 * t23 + (T(1) / T(15360)) * t5 * in.w[0] * t22;
    G_ab = (T(1) / T(15360)) * in.w[1] * t24 * t18 + (T(1) / T(15360)) * t18 * t23 * in.w[0] - (T(1) / T(15360)) * t18 * in.w[2] * (c * t18 * t23 + T(12) * t18 * t19 - T(2) * t24 * t18 * b);
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Returns false where segment_cauchy_i12_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 158 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i12_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[4] * in.w[0] + in.w[2] * M_flat[6] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = T(7) * (T(8) * t8 * b + T(8) * t11 * a_minus_b + T(5) * (T(2) * t10 * a_minus_b + T(2) * t7 * b + T(3) * (J2 * a + t6 * b + t9 * a_minus_b) * t5 * a) * t5 * a) * t5 * a + T(48) * t12 * a_minus_b + T(48) * t13 * b;
    const T t15 = t12 * t9;
    const T t16 = t13 * t6;
    const T t17 = T(3) * t14 * t5 * a + T(128) * t15 * a_minus_b + T(128) * t16 * b;
    const T t18 = T(128) * t15 - T(128) * t16 - t5 * t17 * b;
    const T t19 = T(1) / a;
    F = (T(1) / T(1280)) * t5 * t17 * in.w[0] - (T(1) / T(3840)) * (T(6) * t18 * t19 * b + T(3) * c * t5 * t17 - T(10) * t14 * t5) * in.w[2] * t19 - (T(1) / T(1280)) * in.w[1] * t18 * t19;
    const T t20 = t8 * t8;
    const T t21 = t11 * t11;
    const T t22 = T(1280) * t20 * b + T(1280) * t21 * a_minus_b + T(11) * t5 * a * t17;
    const T t23 = T(1280) * t21 - T(1280) * t20 - t22 * t5 * b;
    const T t24 = T(12) * t5 * t17 - c * t22 * t5 - T(2) * t23 * t19 * b;
    G_ap = (T(1) / T(15360)) * in.w[2] * t19 * t24 + (T(1) / T(15360)) * t22 * t5 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t23 * t19;
    G_ab = (T(1) / T(15360)) * in.w[2] * t19 * (c * t23 * t19 + T(2) * t19 * b * t24 - T(12) * t18 * t19) + (T(1) / T(15360)) * in.w[1] * t19 * t24 - (T(1) / T(15360)) * t23 * t19 * in.w[0];
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 53 +, 117 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2938 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(12, 12, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(12, 12, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t7 * t6;
    const T t13 = t10 * t9;
    const T t14 = T(1) / D;
    const T t15 = T(48) * t8 * b + T(48) * a_minus_b * t11 + T(7) * a * (T(8) * t12 * b + T(8) * a_minus_b * t13 + T(5) * a * t14 * (T(2) * t7 * b + T(2) * a_minus_b * t10 + T(3) * (a_minus_b * t9 + a * J2 + t6 * b) * a * t14)) * t14;
    const T t16 = t8 * t6;
    const T t17 = t11 * t9;
    const T t18 = T(3) * t15 * a * t14 + T(128) * a_minus_b * t17 + T(128) * t16 * b;
    const T t19 = T(128) * t16 + t18 * t14 * b - T(128) * t17;
    const T t20 = T(10) * t15 * t14 + T(6) * t5 * b * t19 - T(3) * c * t18 * t14;
    F = (T(1) / T(3840)) * t5 * (T(10) * t5 * (T(48) * t8 + t15 * t14 * b - T(48) * t11) + T(2) * t20 * t5 * b - T(3) * c * t5 * t19) * in.w[3] + (T(1) / T(1280)) * t18 * t14 * in.w[0] + (T(1) / T(3840)) * t20 * in.w[2] * t5 + (T(1) / T(1280)) * t5 * in.w[1] * t19;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 65 +, 161 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3649 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + bp2 * ap2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + in.w[2] * M_flat[3] + M_flat[2] * in.w[1] + in.w[3] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2];
    G_ab = in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = T(1) / D;
    const T t15 = t7 * t7;
    const T t16 = t11 * t11;
    const T t17 = T(48) * a_minus_b * t15 + T(7) * (T(8) * a_minus_b * t8 + T(8) * t12 * b + T(5) * (T(2) * a_minus_b * t7 + T(3) * a * t14 * (t10 * b + a * J2 + a_minus_b * t6) + T(2) * t11 * b) * a * t14) * a * t14 + T(48) * t16 * b;
    const T t18 = t15 * t6;
    const T t19 = t16 * t10;
    const T t20 = T(3) * t17 * a * t14 + T(128) * a_minus_b * t18 + T(128) * t19 * b;
    const T t21 = T(1280) * a_minus_b * t9 + T(1280) * t13 * b + T(11) * a * t14 * t20;
    const T t22 = T(1280) * t9 - T(1280) * t13 - t14 * b * t21;
    const T t23 = T(128) * t19 + t14 * b * t20 - T(128) * t18;
    const T t24 = T(12) * t14 * t20 - c * t14 * t21 - T(2) * t5 * b * t22;
    const T t25 = c * t5 * t22 + T(12) * t5 * t23 + T(2) * t5 * b * t24;
    G_ap = (T(1) / T(15360)) * t5 * in.w[3] * t25 + (T(1) / T(15360)) * in.w[2] * t5 * t24 + (T(1) / T(15360)) * t14 * in.w[0] * t21 - (T(1) / T(15360)) * t5 * in.w[1] * t22;
    G_ab = (T(1) / T(15360)) * in.w[2] * t5 * t25 + (T(1) / T(15360)) * t5 * in.w[1] * t24 - (T(1) / T(15360)) * t5 * in.w[3] * (c * t5 * t24 + T(4) * (T(3) * c * t14 * t20 - T(10) * t17 * t14 - T(6) * t5 * t23 * b) * t5 - T(2) * t5 * b * t25) - (T(1) / T(15360)) * t5 * in.w[0] * t22;
  }
  const T g_factor = -T(12) * in.s * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Operations: 72 +, 186 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3723 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1];
    G_ap = M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + M_flat[5] * in.w[0];
    G_ab = in.w[0] * M_flat[6] + in.w[3] * M_flat[9] + in.w[2] * M_flat[8] + in.w[1] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(12, 14, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[2] * M_beyond[2];
    G_ap = in.w[3] * M_beyond[8] + in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + in.w[2] * M_beyond[7];
    G_ab = M_beyond[6] * in.w[0] + M_beyond[9] * in.w[3] + in.w[2] * M_beyond[8] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t6 * t5;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t7 * b + T(7) * t9 * a * (T(8) * t12 * a_minus_b + T(5) * (T(3) * (t5 * b + t10 * a_minus_b + J2 * a) * t9 * a + T(2) * t11 * a_minus_b + T(2) * t6 * b) * t9 * a + T(8) * t13 * b) + T(48) * t14 * a_minus_b;
    const T t16 = t14 * t10;
    const T t17 = T(128) * t8 * b + T(3) * t15 * t9 * a + T(128) * t16 * a_minus_b;
    const T t18 = T(1) / a;
    const T t19 = T(128) * t16 - t17 * t9 * b - T(128) * t8;
    const T t20 = T(6) * t18 * t19 * b + T(3) * c * t17 * t9 - T(10) * t15 * t9;
    F = (T(1) / T(1280)) * t17 * t9 * in.w[0] - (T(1) / T(3840)) * (T(2) * t20 * t18 * b - T(10) * t18 * (t15 * t9 * b + T(48) * t7 - T(48) * t14) - T(3) * c * t18 * t19) * in.w[3] * t18 - (T(1) / T(1280)) * in.w[1] * t18 * t19 - (T(1) / T(3840)) * t20 * in.w[2] * t18;
    const T t21 = t13 * t13;
    const T t22 = t12 * t12;
    const T t23 = T(11) * t17 * t9 * a + T(1280) * t21 * b + T(1280) * t22 * a_minus_b;
    const T t24 = T(1280) * t22 - t9 * t23 * b - T(1280) * t21;
    const T t25 = c * t9 * t23 + T(2) * t18 * t24 * b - T(12) * t17 * t9;
    const T t26 = T(2) * t25 * t18 * b + T(12) * t18 * t19 - c * t18 * t24;
    G_ap = (T(1) / T(15360)) * t9 * in.w[0] * t23 - (T(1) / T(15360)) * t26 * in.w[3] * t18 - (T(1) / T(15360)) * in.w[1] * t18 * t24 - (T(1) / T(15360)) * in.w[2] * t25 * t18;
    G_ab = (T(1) / T(15360)) * in.w[3] * (c * t25 * t18 - T(4) * t20 * t18 - T(2) * t26 * t18 * b) * t18 - (T(1) / T(15360)) * t18 * in.w[0] * t24 - (T(1) / T(15360)) * in.w[2] * t26 * t18 - (T(1) / T(15360)) * in.w[1] * t25 * t18;
  }
  const T g_factor = -T(12) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−12/2) dt
/// Returns false where segment_cauchy_i12_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 72 +, 186 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i12_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(12, 14, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2];
    G_ap = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + in.w[3] * M_flat[8];
    G_ab = in.w[3] * M_flat[9] + M_flat[7] * in.w[1] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t7 * t6;
    const T t14 = t11 * t11;
    const T t15 = T(48) * t8 * b + T(7) * a * t5 * (T(8) * a_minus_b * t12 + T(8) * t13 * b + T(5) * a * t5 * (T(3) * a * t5 * (a_minus_b * t10 + t6 * b + J2 * a) + T(2) * t7 * b + T(2) * a_minus_b * t11)) + T(48) * a_minus_b * t14;
    const T t16 = t14 * t10;
    const T t17 = T(128) * t9 * b + T(3) * a * t5 * t15 + T(128) * a_minus_b * t16;
    const T t18 = T(1) / a;
    const T t19 = T(128) * t9 + t5 * b * t17 - T(128) * t16;
    const T t20 = T(10) * t5 * t15 + T(6) * t18 * b * t19 - T(3) * c * t5 * t17;
    F = (T(1) / T(1280)) * t5 * in.w[0] * t17 + (T(1) / T(3840)) * in.w[2] * t18 * t20 + (T(1) / T(3840)) * t18 * in.w[3] * (T(2) * t18 * b * t20 + T(10) * (T(48) * t8 + t5 * t15 * b - T(48) * t14) * t18 - T(3) * c * t18 * t19) + (T(1) / T(1280)) * t18 * in.w[1] * t19;
    const T t21 = t13 * t13;
    const T t22 = t12 * t12;
    const T t23 = T(11) * a * t5 * t17 + T(1280) * t21 * b + T(1280) * a_minus_b * t22;
    const T t24 = T(1280) * t21 + t23 * t5 * b - T(1280) * t22;
    const T t25 = T(2) * t18 * b * t24 + T(12) * t5 * t17 - c * t23 * t5;
    const T t26 = c * t18 * t24 - T(2) * t18 * t25 * b - T(12) * t18 * t19;
    G_ap = (T(1) / T(15360)) * t23 * t5 * in.w[0] + (T(1) / T(15360)) * in.w[2] * t18 * t25 + (T(1) / T(15360)) * t18 * in.w[1] * t24 - (T(1) / T(15360)) * t18 * in.w[3] * t26;
    G_ab = (T(1) / T(15360)) * t18 * in.w[1] * t25 + (T(1) / T(15360)) * t18 * in.w[0] * t24 - (T(1) / T(15360)) * t18 * in.w[3] * (T(2) * t18 * t26 * b + c * t18 * t25 - T(4) * t18 * t20) - (T(1) / T(15360)) * in.w[2] * t18 * t26;
  }
  const T g_factor = -T(12) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 40 +, 95 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 858 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t12 * t10;
    const T t14 = t6 * t5;
    const T t15 = t11 * t10;
    F = (T(1) / T(693)) * t3 * in.w[0] * (T(63) * t4 * b * t8 + T(63) * t13 * a_minus_b * t9 + T(2) * t3 * a * (T(35) * t4 * b * t7 + T(8) * t3 * a * (T(5) * t4 * b * t14 + T(2) * t3 * a * (T(3) * t11 * a_minus_b * t9 + T(3) * t4 * b * t6 + T(4) * (T(2) * t3 * a * (t4 * b + a_minus_b * t9) + t4 * b * t5 + t10 * a_minus_b * t9) * t3 * a) + T(5) * t15 * a_minus_b * t9) + T(35) * t12 * a_minus_b * t9));
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 47 +, 124 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1561 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t9 * t9;
    const T t12 = t11 * t9;
    const T t13 = t11 * t11;
    const T t14 = t5 * t5;
    const T t15 = t13 * t9;
    const T t16 = t14 * t4;
    const T t17 = t12 * t12;
    const T t18 = T(231) * t7 * t3 * a_minus_b + T(4) * (T(2) * (T(8) * (T(5) * t6 * t3 * a_minus_b + T(2) * (T(4) * (t4 * t3 * a_minus_b + b * t8 * t9 + T(2) * a * (t3 * a_minus_b + b * t8) * t10) * a * t10 + T(3) * b * t8 * t11 + T(3) * t5 * t3 * a_minus_b) * a * t10 + T(5) * b * t8 * t12) * a * t10 + T(35) * b * t8 * t13 + T(35) * t14 * t3 * a_minus_b) * a * t10 + T(63) * b * t8 * t15 + T(63) * t16 * t3 * a_minus_b) * a * t10 + T(231) * b * t8 * t17;
    G_ap = (T(1) / T(3003)) * t18 * in.w[0] * t10;
    G_ab = (T(1) / T(3003)) * (b * t18 * t10 + T(231) * t8 * t17 - T(231) * t7 * t3) * in.w[0] / a;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 47 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1586 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = T(1) / r1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = t5 * t4;
    const T t11 = t8 * t7;
    const T t12 = t5 * t5;
    const T t13 = t8 * t8;
    const T t14 = t12 * t4;
    const T t15 = t13 * t7;
    const T t16 = T(2) * (T(8) * (T(2) * (T(3) * b * t5 * t3 + T(3) * a_minus_b * t6 * t8 + T(4) * (T(2) * (b * t3 + a_minus_b * t6) * t9 * a + a_minus_b * t6 * t7 + b * t4 * t3) * t9 * a) * t9 * a + T(5) * b * t10 * t3 + T(5) * a_minus_b * t6 * t11) * t9 * a + T(35) * b * t12 * t3 + T(35) * a_minus_b * t6 * t13) * t9 * a + T(63) * b * t14 * t3 + T(63) * a_minus_b * t6 * t15;
    F = (T(1) / T(693)) * in.w[0] * t16 * t9;
    const T t17 = t10 * t10;
    const T t18 = t11 * t11;
    const T t19 = T(4) * t16 * t9 * a + T(231) * b * t17 * t3 + T(231) * a_minus_b * t6 * t18;
    G_ap = (T(1) / T(3003)) * in.w[0] * t19 * t9;
    G_ab = (T(1) / T(3003)) * in.w[0] * (t19 * b * t9 + T(231) * t17 * t3 - T(231) * t6 * t18) / a;
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Returns false where segment_cauchy_i13_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 47 +, 128 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i13_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t6 * t5;
    const T t14 = t11 * t10;
    const T t15 = t12 * t10;
    const T t16 = T(63) * t8 * t4 * b + T(2) * (T(35) * t12 * t9 * a_minus_b + T(35) * t7 * t4 * b + T(8) * (T(5) * t13 * t4 * b + T(5) * t14 * t9 * a_minus_b + T(2) * (T(4) * (t10 * t9 * a_minus_b + T(2) * (t9 * a_minus_b + t4 * b) * t3 * a + t5 * t4 * b) * t3 * a + T(3) * t6 * t4 * b + T(3) * t11 * t9 * a_minus_b) * t3 * a) * t3 * a) * t3 * a + T(63) * t15 * t9 * a_minus_b;
    F = (T(1) / T(693)) * t3 * in.w[0] * t16;
    const T t17 = t14 * t14;
    const T t18 = t13 * t13;
    const T t19 = T(231) * t17 * t9 * a_minus_b + T(4) * t3 * a * t16 + T(231) * t18 * t4 * b;
    G_ap = (T(1) / T(3003)) * t19 * t3 * in.w[0];
    G_ab = (T(1) / T(3003)) * in.w[0] * (T(231) * t18 * t4 + t19 * t3 * b - T(231) * t17 * t9) / a;
  }
  const T g_factor = -T(13) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 43 +, 103 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1548 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t11 * t10;
    const T t14 = t6 * t5;
    const T t15 = t12 * t10;
    const T t16 = T(63) * t8 * t4 * a_minus_b + T(2) * t3 * a * (T(35) * t7 * t4 * a_minus_b + T(35) * t9 * b * t12 + T(8) * t3 * a * (T(5) * t9 * b * t13 + T(5) * t14 * t4 * a_minus_b + T(2) * t3 * a * (T(3) * t6 * t4 * a_minus_b + T(4) * t3 * a * (t9 * b * t10 + t5 * t4 * a_minus_b + T(2) * t3 * a * (t9 * b + t4 * a_minus_b)) + T(3) * t9 * b * t11))) + T(63) * t9 * b * t15;
    F = (T(1) / T(693)) * t3 * in.w[0] * t16 + (T(1) / T(693)) * in.w[1] * (T(63) * t9 * t15 + t3 * b * t16 - T(63) * t8 * t4) / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 51 +, 139 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2254 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r1;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t4;
    const T t7 = t6 * t6;
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t5 * t5;
    const T t15 = t14 * t4;
    const T t16 = t13 * t10;
    const T t17 = T(2) * (T(8) * a * t8 * (T(2) * (T(4) * (t4 * t3 * a_minus_b + b * t9 * t10 + T(2) * (b * t9 + t3 * a_minus_b) * a * t8) * a * t8 + T(3) * b * t9 * t11 + T(3) * t5 * t3 * a_minus_b) * a * t8 + T(5) * t6 * t3 * a_minus_b + T(5) * b * t9 * t12) + T(35) * b * t9 * t13 + T(35) * t14 * t3 * a_minus_b) * a * t8 + T(63) * t15 * t3 * a_minus_b + T(63) * b * t9 * t16;
    const T t18 = t12 * t12;
    const T t19 = T(231) * t7 * t3 * a_minus_b + T(4) * t17 * a * t8 + T(231) * b * t9 * t18;
    const T t20 = b * t19 * t8 + T(231) * t9 * t18 - T(231) * t7 * t3;
    const T t21 = T(1) / a;
    G_ap = (T(1) / T(3003)) * t20 * t21 * in.w[1] + (T(1) / T(3003)) * t19 * in.w[0] * t8;
    G_ab = (T(1) / T(9009)) * (T(13) * t17 * t8 + T(6) * b * t20 * t21 - T(3) * c * t19 * t8) * t21 * in.w[1] + (T(1) / T(3003)) * in.w[0] * t20 * t21;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 54 +, 152 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2293 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + cross_cross * in.s);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = in.w[0] * M_beyond[3] + M_beyond[4] * in.w[1];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / r0;
    const T t4 = t3 * t3;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t4;
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t10;
    const T t14 = t5 * t4;
    const T t15 = t12 * t10;
    const T t16 = T(63) * b * t7 * t3 + T(2) * t8 * a * (T(35) * b * t6 * t3 + T(35) * t9 * a_minus_b * t12 + T(8) * (T(2) * (T(4) * (b * t4 * t3 + t9 * a_minus_b * t10 + T(2) * (t9 * a_minus_b + b * t3) * t8 * a) * t8 * a + T(3) * t9 * a_minus_b * t11 + T(3) * b * t5 * t3) * t8 * a + T(5) * t9 * a_minus_b * t13 + T(5) * b * t14 * t3) * t8 * a) + T(63) * t9 * a_minus_b * t15;
    const T t17 = T(1) / a;
    F = (T(1) / T(693)) * t16 * in.w[0] * t8 - (T(1) / T(693)) * (T(63) * t9 * t15 - T(63) * t7 * t3 - b * t16 * t8) * t17 * in.w[1];
    const T t18 = t14 * t14;
    const T t19 = t13 * t13;
    const T t20 = T(231) * b * t18 * t3 + T(231) * t9 * a_minus_b * t19 + T(4) * t16 * t8 * a;
    const T t21 = T(231) * t9 * t19 - b * t8 * t20 - T(231) * t18 * t3;
    G_ap = (T(1) / T(3003)) * in.w[0] * t8 * t20 - (T(1) / T(3003)) * t21 * t17 * in.w[1];
    G_ab = (T(1) / T(9009)) * (T(13) * t16 * t8 - T(3) * c * t8 * t20 - T(6) * b * t21 * t17) * t17 * in.w[1] - (T(1) / T(3003)) * t21 * in.w[0] * t17;
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Returns false where segment_cauchy_i13_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 54 +, 152 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i13_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    const T t14 = t11 * t9;
    const T t15 = t7 * t5;
    const T t16 = T(2) * a * (T(35) * b * t7 * t4 + T(35) * t8 * a_minus_b * t11 + T(8) * a * (T(5) * b * t12 * t4 + T(5) * t8 * a_minus_b * t13 + T(2) * a * (T(4) * a * (t8 * a_minus_b * t9 + b * t5 * t4 + T(2) * a * (b * t4 + t8 * a_minus_b) * t3) * t3 + T(3) * b * t6 * t4 + T(3) * t8 * a_minus_b * t10) * t3) * t3) * t3 + T(63) * t8 * a_minus_b * t14 + T(63) * b * t15 * t4;
    const T t17 = T(1) / a;
    F = (T(1) / T(693)) * in.w[0] * t3 * t16 - (T(1) / T(693)) * t17 * in.w[1] * (T(63) * t8 * t14 - b * t3 * t16 - T(63) * t15 * t4);
    const T t18 = t12 * t12;
    const T t19 = t13 * t13;
    const T t20 = T(231) * b * t18 * t4 + T(4) * a * t3 * t16 + T(231) * t8 * a_minus_b * t19;
    const T t21 = T(231) * t8 * t19 - T(231) * t18 * t4 - b * t20 * t3;
    G_ap = (T(1) / T(3003)) * t20 * in.w[0] * t3 - (T(1) / T(3003)) * t17 * in.w[1] * t21;
    G_ab = -(T(1) / T(9009)) * t17 * in.w[1] * (T(6) * t17 * b * t21 + T(3) * t20 * c * t3 - T(13) * t3 * t16) - (T(1) / T(3003)) * t17 * t21 * in.w[0];
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 46 +, 115 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2240 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t15 = T(8) * t3 * a * (T(5) * b * t12 * t9 + T(5) * t4 * a_minus_b * t13 + T(2) * (T(3) * t4 * a_minus_b * t6 + T(3) * b * t11 * t9 + T(4) * (T(2) * (b * t9 + t4 * a_minus_b) * t3 * a + b * t10 * t9 + t4 * a_minus_b * t5) * t3 * a) * t3 * a) + T(35) * t4 * a_minus_b * t7 + T(35) * b * t14 * t9;
    const T t16 = t14 * t10;
    const T t17 = T(63) * t4 * a_minus_b * t8 + T(2) * t15 * t3 * a + T(63) * b * t16 * t9;
    const T t18 = T(1) / a;
    const T t19 = T(63) * t4 * t8 - T(63) * t16 * t9 - b * t3 * t17;
    F = (T(1) / T(693)) * in.w[0] * t3 * t17 - (T(1) / T(3465)) * in.w[2] * t18 * (T(5) * c * t3 * t17 + T(10) * b * t19 * t18 - T(11) * t15 * t3) - (T(1) / T(693)) * t19 * in.w[1] * t18;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 57 +, 159 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2949 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
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
    const T t14 = T(1) / D;
    const T t15 = t11 * t10;
    const T t16 = t6 * t5;
    const T t17 = T(63) * t4 * a_minus_b * t8 + T(63) * b * t9 * t13 + T(2) * t14 * a * (T(8) * t14 * a * (T(2) * t14 * a * (T(4) * t14 * a * (t4 * a_minus_b * t5 + b * t9 * t10 + T(2) * t14 * a * (b * t9 + t4 * a_minus_b)) + T(3) * t4 * a_minus_b * t6 + T(3) * b * t9 * t11) + T(5) * b * t9 * t15 + T(5) * t4 * a_minus_b * t16) + T(35) * t4 * a_minus_b * t7 + T(35) * b * t9 * t12);
    const T t18 = t16 * t16;
    const T t19 = t15 * t15;
    const T t20 = T(231) * t4 * a_minus_b * t18 + T(231) * b * t9 * t19 + T(4) * t17 * t14 * a;
    const T t21 = t14 * t20 * b + T(231) * t9 * t19 - T(231) * t4 * t18;
    const T t22 = T(13) * t17 * t14 + T(6) * t3 * t21 * b - T(3) * t14 * t20 * c;
    G_ap = (T(1) / T(9009)) * t3 * in.w[2] * t22 + (T(1) / T(3003)) * in.w[1] * t3 * t21 + (T(1) / T(3003)) * t14 * t20 * in.w[0];
    G_ab = (T(1) / T(3003)) * t3 * t21 * in.w[0] + (T(1) / T(9009)) * (T(2) * t3 * b * t22 + T(13) * (t17 * t14 * b + T(63) * t9 * t13 - T(63) * t4 * t8) * t3 - T(3) * t3 * t21 * c) * t3 * in.w[2] + (T(1) / T(9009)) * in.w[1] * t3 * t22;
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 61 +, 177 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 3004 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ap = M_flat[4] * in.w[0] + in.w[1] * M_flat[5] + M_flat[6] * in.w[2];
    G_ab = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
    G_ap = in.w[2] * M_beyond[6] + in.w[1] * M_beyond[5] + M_beyond[4] * in.w[0];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[5] * in.w[0] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t12 * t10;
    const T t14 = t6 * t5;
    const T t15 = t11 * t10;
    const T t16 = T(35) * t4 * b * t7 + T(8) * t3 * a * (T(2) * t3 * a * (T(4) * (t9 * a_minus_b * t10 + T(2) * t3 * a * (t4 * b + t9 * a_minus_b) + t4 * b * t5) * t3 * a + T(3) * t4 * b * t6 + T(3) * t9 * a_minus_b * t11) + T(5) * t4 * b * t14 + T(5) * t9 * a_minus_b * t15) + T(35) * t9 * a_minus_b * t12;
    const T t17 = T(63) * t4 * b * t8 + T(63) * t9 * a_minus_b * t13 + T(2) * t16 * t3 * a;
    const T t18 = T(1) / a;
    const T t19 = T(63) * t9 * t13 - t3 * b * t17 - T(63) * t4 * t8;
    F = (T(1) / T(693)) * t3 * in.w[0] * t17 + (T(1) / T(3465)) * (T(11) * t16 * t3 - T(10) * t18 * b * t19 - T(5) * t3 * t17 * c) * t18 * in.w[2] - (T(1) / T(693)) * in.w[1] * t18 * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    const T t22 = T(4) * t3 * a * t17 + T(231) * t4 * b * t20 + T(231) * t9 * a_minus_b * t21;
    const T t23 = T(231) * t9 * t21 - T(231) * t4 * t20 - t22 * t3 * b;
    const T t24 = T(3) * t22 * t3 * c + T(6) * t23 * t18 * b - T(13) * t3 * t17;
    G_ap = (T(1) / T(3003)) * t22 * t3 * in.w[0] - (T(1) / T(3003)) * in.w[1] * t23 * t18 - (T(1) / T(9009)) * t24 * t18 * in.w[2];
    G_ab = -(T(1) / T(9009)) * in.w[1] * t24 * t18 - (T(1) / T(9009)) * t18 * in.w[2] * (T(2) * t24 * t18 * b + T(13) * t18 * t19 - T(3) * t23 * t18 * c) - (T(1) / T(3003)) * t23 * t18 * in.w[0];
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Returns false where segment_cauchy_i13_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 177 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i13_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
    G_ab = M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + in.w[2] * M_flat[7];
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
    const T t13 = T(1) / D;
    const T t14 = t5 * t4;
    const T t15 = t10 * t9;
    const T t16 = T(35) * b * t6 * t3 + T(8) * t13 * a * (T(2) * t13 * a * (T(4) * t13 * a * (t8 * a_minus_b * t9 + b * t4 * t3 + T(2) * t13 * a * (b * t3 + t8 * a_minus_b)) + T(3) * b * t5 * t3 + T(3) * t8 * a_minus_b * t10) + T(5) * b * t14 * t3 + T(5) * t8 * a_minus_b * t15) + T(35) * t8 * a_minus_b * t11;
    const T t17 = T(63) * b * t7 * t3 + T(63) * t8 * a_minus_b * t12 + T(2) * t13 * a * t16;
    const T t18 = t17 * t13 * b + T(63) * t7 * t3 - T(63) * t8 * t12;
    const T t19 = T(1) / a;
    F = (T(1) / T(693)) * t17 * t13 * in.w[0] + (T(1) / T(693)) * t18 * t19 * in.w[1] + (T(1) / T(3465)) * in.w[2] * t19 * (T(11) * t13 * t16 + T(10) * t18 * t19 * b - T(5) * t17 * t13 * c);
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    const T t22 = T(231) * b * t20 * t3 + T(231) * t8 * a_minus_b * t21 + T(4) * t17 * t13 * a;
    const T t23 = T(231) * t8 * t21 - T(231) * t20 * t3 - t13 * t22 * b;
    const T t24 = T(6) * t19 * t23 * b + T(3) * t13 * t22 * c - T(13) * t17 * t13;
    G_ap = (T(1) / T(3003)) * t13 * t22 * in.w[0] - (T(1) / T(3003)) * t19 * t23 * in.w[1] - (T(1) / T(9009)) * in.w[2] * t19 * t24;
    G_ab = -(T(1) / T(9009)) * in.w[2] * t19 * (T(2) * t19 * b * t24 - T(13) * t18 * t19 - T(3) * t19 * t23 * c) - (T(1) / T(3003)) * t19 * t23 * in.w[0] - (T(1) / T(9009)) * t19 * t24 * in.w[1];
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 51 +, 132 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2934 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(13, 13, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(13, 13, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = t12 * t10;
    const T t14 = t11 * t10;
    const T t15 = t6 * t5;
    const T t16 = T(8) * t3 * a * (T(5) * t9 * a_minus_b * t14 + T(2) * t3 * a * (T(3) * t6 * t4 * b + T(3) * t9 * a_minus_b * t11 + T(4) * (t9 * a_minus_b * t10 + T(2) * (t9 * a_minus_b + t4 * b) * t3 * a + t5 * t4 * b) * t3 * a) + T(5) * t15 * t4 * b) + T(35) * t7 * t4 * b + T(35) * t9 * a_minus_b * t12;
    const T t17 = T(63) * t8 * t4 * b + T(63) * t9 * a_minus_b * t13 + T(2) * t3 * a * t16;
    const T t18 = T(63) * t9 * t13 - t3 * t17 * b - T(63) * t8 * t4;
    const T t19 = T(1) / a;
    const T t20 = T(5) * c * t3 * t17 + T(10) * t18 * t19 * b - T(11) * t3 * t16;
    F = (T(1) / T(693)) * t3 * t17 * in.w[0] - (T(1) / T(693)) * in.w[1] * t18 * t19 - (T(1) / T(3465)) * t20 * in.w[2] * t19 - (T(1) / T(3465)) * (T(11) * (T(35) * t9 * t12 - t3 * t16 * b - T(35) * t7 * t4) * t19 + T(2) * t20 * t19 * b - T(5) * t18 * c * t19) * t19 * in.w[3];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 63 +, 181 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3646 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1] + M_flat[3] * in.w[3];
    G_ab = in.w[2] * M_flat[3] + in.w[1] * M_flat[2] + in.w[0] * M_flat[1] + in.w[3] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
    G_ab = M_beyond[2] * in.w[1] + in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = t6 * t6;
    const T t11 = t10 * t5;
    const T t12 = T(1) / r0;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = t14 * t14;
    const T t17 = T(35) * a_minus_b * t4 * t10 + T(8) * t9 * a * (T(2) * t9 * a * (T(3) * b * t14 * t12 + T(4) * t9 * a * (a_minus_b * t4 * t5 + T(2) * t9 * a * (a_minus_b * t4 + b * t12) + b * t13 * t12) + T(3) * a_minus_b * t4 * t6) + T(5) * b * t15 * t12 + T(5) * a_minus_b * t4 * t7) + T(35) * b * t16 * t12;
    const T t18 = t16 * t13;
    const T t19 = T(63) * a_minus_b * t4 * t11 + T(2) * t9 * a * t17 + T(63) * b * t18 * t12;
    const T t20 = t15 * t15;
    const T t21 = T(231) * a_minus_b * t4 * t8 + T(4) * t9 * a * t19 + T(231) * b * t20 * t12;
    const T t22 = t21 * t9 * b + T(231) * t20 * t12 - T(231) * t4 * t8;
    const T t23 = T(6) * t3 * b * t22 + T(13) * t9 * t19 - T(3) * t21 * t9 * c;
    const T t24 = T(63) * t18 * t12 + t9 * b * t19 - T(63) * t4 * t11;
    const T t25 = T(2) * t23 * t3 * b + T(13) * t3 * t24 - T(3) * t3 * t22 * c;
    G_ap = (T(1) / T(3003)) * t3 * in.w[1] * t22 + (T(1) / T(9009)) * t3 * t25 * in.w[3] + (T(1) / T(9009)) * in.w[2] * t23 * t3 + (T(1) / T(3003)) * t21 * t9 * in.w[0];
    G_ab = (T(1) / T(9009)) * in.w[2] * t3 * t25 + (T(1) / T(9009)) * t23 * t3 * in.w[1] + (T(1) / T(3003)) * t3 * in.w[0] * t22 + (T(1) / T(45045)) * t3 * in.w[3] * (T(10) * t3 * t25 * b + T(13) * t3 * (T(10) * t3 * b * t24 + T(11) * t9 * t17 - T(5) * t9 * t19 * c) - T(5) * t23 * t3 * c);
  }
  const T g_factor = -T(13) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Operations: 70 +, 208 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1340 +, 3719 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[5] + M_flat[6] * in.w[1] + M_flat[7] * in.w[2] + in.w[3] * M_flat[8];
    G_ab = M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(13, 15, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3];
    G_ap = M_beyond[7] * in.w[2] + M_beyond[8] * in.w[3] + M_beyond[5] * in.w[0] + M_beyond[6] * in.w[1];
    G_ab = in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9] + M_beyond[8] * in.w[2] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / D;
    const T t10 = T(1) / r1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t11;
    const T t15 = t6 * t5;
    const T t16 = t12 * t11;
    const T t17 = T(35) * t10 * a_minus_b * t13 + T(35) * t4 * b * t7 + T(8) * t9 * a * (T(2) * t9 * a * (T(3) * t4 * b * t6 + T(3) * t10 * a_minus_b * t12 + T(4) * t9 * a * (T(2) * t9 * a * (t4 * b + t10 * a_minus_b) + t10 * a_minus_b * t11 + t4 * b * t5)) + T(5) * t4 * b * t15 + T(5) * t10 * a_minus_b * t16);
    const T t18 = T(63) * t10 * a_minus_b * t14 + T(2) * t9 * a * t17 + T(63) * t4 * b * t8;
    const T t19 = T(63) * t4 * t8 + t9 * t18 * b - T(63) * t10 * t14;
    const T t20 = T(10) * t3 * b * t19 + T(11) * t9 * t17 - T(5) * t9 * t18 * c;
    F = (T(1) / T(693)) * t3 * in.w[1] * t19 + (T(1) / T(693)) * t9 * in.w[0] * t18 + (T(1) / T(3465)) * t3 * t20 * in.w[2] - (T(1) / T(3465)) * t3 * (T(5) * t3 * t19 * c - T(11) * (T(35) * t4 * t7 + t9 * b * t17 - T(35) * t10 * t13) * t3 - T(2) * t3 * b * t20) * in.w[3];
    const T t21 = t16 * t16;
    const T t22 = t15 * t15;
    const T t23 = T(231) * t10 * a_minus_b * t21 + T(231) * t4 * b * t22 + T(4) * t9 * a * t18;
    const T t24 = t9 * b * t23 + T(231) * t4 * t22 - T(231) * t10 * t21;
    const T t25 = T(6) * t24 * t3 * b + T(13) * t9 * t18 - T(3) * t9 * t23 * c;
    const T t26 = T(13) * t3 * t19 + T(2) * t25 * t3 * b - T(3) * t24 * t3 * c;
    G_ap = (T(1) / T(9009)) * t26 * t3 * in.w[3] + (T(1) / T(3003)) * t24 * t3 * in.w[1] + (T(1) / T(3003)) * t9 * in.w[0] * t23 + (T(1) / T(9009)) * t25 * t3 * in.w[2];
    G_ab = (T(1) / T(9009)) * t26 * t3 * in.w[2] + (T(1) / T(9009)) * t25 * t3 * in.w[1] + (T(1) / T(3003)) * t24 * t3 * in.w[0] + (T(1) / T(45045)) * t3 * in.w[3] * (T(13) * t3 * t20 + T(10) * t26 * t3 * b - T(5) * t25 * t3 * c);
  }
  const T g_factor = -T(13) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−13/2) dt
/// Returns false where segment_cauchy_i13_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 70 +, 208 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i13_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(13, 15, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ap = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + in.w[2] * M_flat[7];
    G_ab = in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + in.w[1] * M_flat[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t6 * t5;
    const T t14 = T(1) / D;
    const T t15 = T(35) * t7 * t4 * b + T(35) * t11 * a_minus_b * t8 + T(8) * (T(5) * t12 * a_minus_b * t8 + T(5) * t13 * t4 * b + T(2) * t14 * a * (T(4) * (T(2) * (a_minus_b * t8 + t4 * b) * t14 * a + t5 * t4 * b + t9 * a_minus_b * t8) * t14 * a + T(3) * t6 * t4 * b + T(3) * t10 * a_minus_b * t8)) * t14 * a;
    const T t16 = t7 * t5;
    const T t17 = t11 * t9;
    const T t18 = T(63) * t16 * t4 * b + T(63) * t17 * a_minus_b * t8 + T(2) * t15 * t14 * a;
    const T t19 = T(63) * t16 * t4 + t14 * t18 * b - T(63) * t17 * t8;
    const T t20 = T(11) * t15 * t14 + T(10) * t19 * t3 * b - T(5) * c * t14 * t18;
    F = (T(1) / T(3465)) * in.w[3] * t3 * (T(11) * (T(35) * t7 * t4 + t15 * t14 * b - T(35) * t11 * t8) * t3 + T(2) * t20 * t3 * b - T(5) * t19 * c * t3) + (T(1) / T(693)) * in.w[1] * t19 * t3 + (T(1) / T(693)) * t14 * in.w[0] * t18 + (T(1) / T(3465)) * t20 * in.w[2] * t3;
    const T t21 = t13 * t13;
    const T t22 = t12 * t12;
    const T t23 = T(231) * t21 * t4 * b + T(231) * t22 * a_minus_b * t8 + T(4) * t14 * a * t18;
    const T t24 = t23 * t14 * b + T(231) * t21 * t4 - T(231) * t22 * t8;
    const T t25 = T(6) * t24 * t3 * b + T(13) * t14 * t18 - T(3) * c * t23 * t14;
    const T t26 = T(13) * t19 * t3 + T(2) * t25 * t3 * b - T(3) * c * t24 * t3;
    G_ap = (T(1) / T(9009)) * t25 * in.w[2] * t3 + (T(1) / T(9009)) * t26 * in.w[3] * t3 + (T(1) / T(3003)) * t23 * t14 * in.w[0] + (T(1) / T(3003)) * in.w[1] * t24 * t3;
    G_ab = (T(1) / T(3003)) * t24 * in.w[0] * t3 + (T(1) / T(9009)) * in.w[1] * t25 * t3 + (T(1) / T(9009)) * t26 * in.w[2] * t3 + (T(1) / T(45045)) * in.w[3] * t3 * (T(13) * t20 * t3 + T(10) * t26 * t3 * b - T(5) * t25 * c * t3);
  }
  const T g_factor = -T(13) * length * in.s;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 44 +, 93 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 864 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + bp1 * ap1;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 0, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / c;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t13 * t12;
    const T t16 = t14 * t12;
    const T t17 = t15 * t15;
    F = (T(1) / T(15360)) * t5 * in.w[0] * (T(1280) * a_minus_b * t9 + T(11) * t5 * (T(128) * a_minus_b * t11 + T(3) * t5 * a * (T(48) * a_minus_b * t10 + T(48) * b * t14 + T(7) * t5 * a * (T(8) * a_minus_b * t8 + T(5) * t5 * a * (T(3) * t5 * a * (a * J2 + b * t12 + a_minus_b * t6) + T(2) * a_minus_b * t7 + T(2) * b * t13) + T(8) * b * t15)) + T(128) * b * t16) * a + T(1280) * b * t17);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 51 +, 118 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1567 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = t8 * t6;
    const T t15 = t11 * t9;
    const T t16 = t13 * t13;
    const T t17 = t12 * t12;
    const T t18 = t17 * t9;
    const T t19 = t16 * t6;
    const T t20 = T(13) * t5 * a * (T(11) * t5 * a * (T(3) * t5 * a * (T(48) * b * t8 + T(48) * a_minus_b * t11 + T(7) * t5 * a * (T(5) * t5 * a * (T(2) * b * t7 + T(2) * a_minus_b * t10 + T(3) * t5 * a * (b * t6 + a_minus_b * t9 + a * J2)) + T(8) * a_minus_b * t12 + T(8) * b * t13)) + T(128) * b * t14 + T(128) * a_minus_b * t15) + T(1280) * b * t16 + T(1280) * a_minus_b * t17) + T(15360) * a_minus_b * t18 + T(15360) * b * t19;
    G_ap = (T(1) / T(215040)) * t5 * in.w[0] * t20;
    G_ab = (T(1) / T(215040)) * in.w[0] * (T(15360) * t19 + t5 * t20 * b - T(15360) * t18) / a;
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 51 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1593 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = M_beyond[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t7 * t7;
    const T t15 = t14 * t6;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = T(1280) * t9 * a_minus_b + T(1280) * t13 * b + T(11) * t5 * a * (T(128) * t15 * a_minus_b + T(3) * t5 * a * (T(48) * t14 * a_minus_b + T(7) * (T(8) * t12 * b + T(5) * t5 * a * (T(2) * t11 * b + T(3) * (J2 * a + t6 * a_minus_b + t10 * b) * t5 * a + T(2) * t7 * a_minus_b) + T(8) * t8 * a_minus_b) * t5 * a + T(48) * t16 * b) + T(128) * t17 * b);
    F = (T(1) / T(15360)) * t5 * in.w[0] * t18;
    const T t19 = t9 * t6;
    const T t20 = t13 * t10;
    const T t21 = T(15360) * t19 * a_minus_b + T(15360) * t20 * b + T(13) * t5 * a * t18;
    G_ap = (T(1) / T(215040)) * t5 * in.w[0] * t21;
    G_ab = -(T(1) / T(215040)) * (T(15360) * t19 - t5 * b * t21 - T(15360) * t20) * in.w[0] / a;
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Returns false where segment_cauchy_i14_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 51 +, 122 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i14_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t13 * t12;
    const T t16 = t14 * t12;
    const T t17 = t15 * t15;
    const T t18 = T(1280) * b * t9 + T(11) * t5 * a * (T(128) * b * t11 + T(3) * t5 * a * (T(48) * b * t10 + T(48) * a_minus_b * t14 + T(7) * t5 * a * (T(5) * t5 * a * (T(2) * a_minus_b * t13 + T(2) * b * t7 + T(3) * t5 * a * (a * J2 + b * t6 + a_minus_b * t12)) + T(8) * a_minus_b * t15 + T(8) * b * t8)) + T(128) * a_minus_b * t16) + T(1280) * a_minus_b * t17;
    F = (T(1) / T(15360)) * t5 * t18 * in.w[0];
    const T t19 = t9 * t6;
    const T t20 = t17 * t12;
    const T t21 = T(15360) * b * t19 + T(15360) * a_minus_b * t20 + T(13) * t5 * a * t18;
    G_ap = (T(1) / T(215040)) * t5 * in.w[0] * t21;
    G_ab = (T(1) / T(215040)) * (t5 * b * t21 + T(15360) * t19 - T(15360) * t20) * in.w[0] / a;
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 47 +, 99 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1554 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
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
    const T t16 = t14 * t14;
    const T t17 = t13 * t13;
    const T t18 = T(11) * (T(128) * t8 * a_minus_b + T(3) * t9 * a * (T(48) * t7 * a_minus_b + T(48) * t12 * b + T(7) * t9 * a * (T(8) * t13 * b + T(5) * t9 * a * (T(2) * t11 * b + T(3) * t9 * a * (t5 * a_minus_b + a * J2 + t10 * b) + T(2) * t6 * a_minus_b) + T(8) * t14 * a_minus_b)) + T(128) * t15 * b) * t9 * a + T(1280) * t16 * a_minus_b + T(1280) * t17 * b;
    F = (T(1) / T(15360)) * in.w[0] * t18 * t9 + (T(1) / T(15360)) * in.w[1] * (T(1280) * t17 + t18 * t9 * b - T(1280) * t16) / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 55 +, 132 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2260 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
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
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[2] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
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
    const T t15 = T(1) / D;
    const T t16 = t6 * t6;
    const T t17 = t16 * t5;
    const T t18 = t11 * t11;
    const T t19 = t18 * t10;
    const T t20 = T(1280) * b * t8 + T(11) * t15 * a * (T(128) * b * t17 + T(3) * t15 * a * (T(48) * b * t16 + T(48) * a_minus_b * t18 + T(7) * t15 * a * (T(8) * b * t7 + T(5) * t15 * a * (T(2) * b * t6 + T(3) * t15 * a * (a_minus_b * t10 + a * J2 + b * t5) + T(2) * a_minus_b * t11) + T(8) * a_minus_b * t12)) + T(128) * a_minus_b * t19) + T(1280) * a_minus_b * t13;
    const T t21 = T(15360) * b * t9 + T(15360) * a_minus_b * t14 + T(13) * t15 * a * t20;
    const T t22 = T(1) / a;
    const T t23 = T(15360) * t14 - t21 * t15 * b - T(15360) * t9;
    G_ap = (T(1) / T(215040)) * in.w[0] * t21 * t15 - (T(1) / T(215040)) * t22 * in.w[1] * t23;
    G_ab = -(T(1) / T(215040)) * in.w[0] * t22 * t23 - (T(1) / T(215040)) * t22 * in.w[1] * (t21 * t15 * c + T(2) * t22 * b * t23 - T(14) * t15 * t20);
  }
  const T g_factor = -T(14) * in.s * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 58 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2300 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[1] + M_flat[3] * in.w[0];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[1] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[4] * in.w[0] + M_beyond[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t11 * t11;
    const T t13 = T(1) / D;
    const T t14 = t10 * t10;
    const T t15 = t6 * t6;
    const T t16 = t14 * t9;
    const T t17 = t15 * t5;
    const T t18 = T(1280) * t8 * a_minus_b + T(1280) * b * t12 + T(11) * (T(3) * (T(7) * (T(8) * t7 * a_minus_b + T(5) * t13 * (T(2) * t6 * a_minus_b + T(3) * (b * t9 + t5 * a_minus_b + J2 * a) * t13 * a + T(2) * b * t10) * a + T(8) * b * t11) * t13 * a + T(48) * b * t14 + T(48) * t15 * a_minus_b) * t13 * a + T(128) * b * t16 + T(128) * t17 * a_minus_b) * t13 * a;
    const T t19 = T(1) / a;
    F = (T(1) / T(15360)) * in.w[0] * t18 * t13 - (T(1) / T(15360)) * (T(1280) * t8 - b * t18 * t13 - T(1280) * t12) * t19 * in.w[1];
    const T t20 = t12 * t9;
    const T t21 = t8 * t5;
    const T t22 = T(15360) * b * t20 + T(13) * t18 * t13 * a + T(15360) * t21 * a_minus_b;
    const T t23 = T(15360) * t21 - b * t13 * t22 - T(15360) * t20;
    G_ap = (T(1) / T(215040)) * in.w[0] * t13 * t22 - (T(1) / T(215040)) * t19 * in.w[1] * t23;
    G_ab = -(T(1) / T(215040)) * in.w[0] * t19 * t23 - (T(1) / T(215040)) * (c * t13 * t22 + T(2) * b * t19 * t23 - T(14) * t18 * t13) * t19 * in.w[1];
  }
  const T g_factor = -T(14) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Returns false where segment_cauchy_i14_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 58 +, 143 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i14_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = t10 * t10;
    const T t13 = t7 * t7;
    const T t14 = t12 * t9;
    const T t15 = t13 * t6;
    const T t16 = t11 * t11;
    const T t17 = t8 * t8;
    const T t18 = T(11) * t5 * a * (T(3) * t5 * a * (T(7) * t5 * a * (T(8) * b * t8 + T(8) * a_minus_b * t11 + T(5) * (T(3) * t5 * a * (a_minus_b * t9 + b * t6 + J2 * a) + T(2) * a_minus_b * t10 + T(2) * b * t7) * t5 * a) + T(48) * a_minus_b * t12 + T(48) * b * t13) + T(128) * a_minus_b * t14 + T(128) * b * t15) + T(1280) * a_minus_b * t16 + T(1280) * b * t17;
    const T t19 = T(1) / a;
    F = (T(1) / T(15360)) * t18 * t5 * in.w[0] + (T(1) / T(15360)) * (t18 * t5 * b + T(1280) * t17 - T(1280) * t16) * t19 * in.w[1];
    const T t20 = t17 * t6;
    const T t21 = t16 * t9;
    const T t22 = T(13) * t18 * t5 * a + T(15360) * b * t20 + T(15360) * a_minus_b * t21;
    const T t23 = t22 * t5 * b + T(15360) * t20 - T(15360) * t21;
    G_ap = (T(1) / T(215040)) * t19 * in.w[1] * t23 + (T(1) / T(215040)) * t22 * t5 * in.w[0];
    G_ab = (T(1) / T(215040)) * (T(2) * t19 * b * t23 + T(14) * t18 * t5 - t22 * t5 * c) * t19 * in.w[1] + (T(1) / T(215040)) * t19 * t23 * in.w[0];
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 50 +, 110 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2246 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + T(1);
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + in.w[0] * M_flat[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t8 * t8;
    const T t14 = t11 * t11;
    const T t15 = t13 * t7;
    const T t16 = t14 * t10;
    const T t17 = T(3) * t6 * a * (T(7) * t6 * a * (T(8) * t9 * a_minus_b + T(8) * b * t12 + T(5) * (T(2) * t8 * a_minus_b + T(3) * t6 * (b * t10 + a * J2 + t7 * a_minus_b) * a + T(2) * b * t11) * t6 * a) + T(48) * t13 * a_minus_b + T(48) * b * t14) + T(128) * t15 * a_minus_b + T(128) * b * t16;
    const T t18 = t12 * t12;
    const T t19 = t9 * t9;
    const T t20 = T(1280) * b * t18 + T(11) * t6 * a * t17 + T(1280) * t19 * a_minus_b;
    const T t21 = T(1280) * t19 - T(1280) * t18 - t6 * b * t20;
    F = (T(1) / T(15360)) * in.w[2] * t5 * (T(12) * t6 * t17 - t6 * c * t20 - T(2) * t21 * t5 * b) + (T(1) / T(15360)) * t6 * in.w[0] * t20 - (T(1) / T(15360)) * t21 * t5 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 61 +, 149 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2955 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (cross_cross * in.s + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2] + in.w[2] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1];
    G_ab = M_beyond[2] * in.w[1] + in.w[0] * M_beyond[1] + in.w[2] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = t7 * t7;
    const T t17 = t16 * t6;
    const T t18 = t12 * t12;
    const T t19 = t18 * t11;
    const T t20 = T(1280) * a_minus_b * t9 + T(11) * t5 * a * (T(128) * a_minus_b * t17 + T(3) * t5 * (T(48) * a_minus_b * t16 + T(48) * b * t18 + T(7) * t5 * a * (T(8) * a_minus_b * t8 + T(5) * t5 * a * (T(3) * t5 * a * (a * J2 + b * t11 + a_minus_b * t6) + T(2) * a_minus_b * t7 + T(2) * b * t12) + T(8) * b * t13)) * a + T(128) * b * t19) + T(1280) * b * t14;
    const T t21 = T(15360) * a_minus_b * t10 + T(15360) * b * t15 + T(13) * t5 * a * t20;
    const T t22 = T(1) / a;
    const T t23 = T(15360) * t15 + t5 * b * t21 - T(15360) * t10;
    const T t24 = T(2) * t22 * b * t23 + T(14) * t5 * t20 - t5 * t21 * c;
    G_ap = (T(1) / T(215040)) * t5 * in.w[0] * t21 + (T(1) / T(215040)) * t22 * in.w[2] * t24 + (T(1) / T(215040)) * t22 * t23 * in.w[1];
    G_ab = (T(1) / T(215040)) * t22 * t24 * in.w[1] + (T(1) / T(215040)) * t22 * in.w[0] * t23 + (T(1) / T(215040)) * t22 * in.w[2] * (T(2) * t22 * b * t24 + T(14) * t22 * (t5 * b * t20 + T(1280) * t14 - T(1280) * t9) - t22 * t23 * c);
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 65 +, 166 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 3011 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + M_flat[5] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[5] + M_beyond[6] * in.w[2] + M_beyond[4] * in.w[0];
    G_ab = in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / a;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t7 * t7;
    const T t11 = t10 * t6;
    const T t12 = T(1) / D;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t13;
    const T t16 = t14 * t14;
    const T t17 = t16 * t13;
    const T t18 = T(128) * a_minus_b * t11 + T(3) * t12 * (T(48) * a_minus_b * t10 + T(7) * t12 * a * (T(8) * a_minus_b * t8 + T(8) * t15 * b + T(5) * (T(2) * t14 * b + T(2) * a_minus_b * t7 + T(3) * t12 * a * (J2 * a + a_minus_b * t6 + t13 * b)) * t12 * a) + T(48) * t16 * b) * a + T(128) * t17 * b;
    const T t19 = t15 * t15;
    const T t20 = T(1280) * a_minus_b * t9 + T(11) * t18 * t12 * a + T(1280) * t19 * b;
    const T t21 = t20 * t12 * b + T(1280) * t19 - T(1280) * t9;
    F = (T(1) / T(15360)) * in.w[1] * t5 * t21 + (T(1) / T(15360)) * t20 * t12 * in.w[0] + (T(1) / T(15360)) * t5 * in.w[2] * (T(12) * t18 * t12 + T(2) * t5 * b * t21 - c * t20 * t12);
    const T t22 = t19 * t13;
    const T t23 = t9 * t6;
    const T t24 = T(15360) * a_minus_b * t23 + T(13) * t20 * t12 * a + T(15360) * t22 * b;
    const T t25 = T(15360) * t22 + t24 * t12 * b - T(15360) * t23;
    const T t26 = T(2) * t5 * b * t25 + T(14) * t20 * t12 - t24 * c * t12;
    G_ap = (T(1) / T(215040)) * in.w[1] * t5 * t25 + (T(1) / T(215040)) * t24 * t12 * in.w[0] + (T(1) / T(215040)) * t26 * t5 * in.w[2];
    G_ab = (T(1) / T(215040)) * (T(14) * t5 * t21 + T(2) * t26 * t5 * b - c * t5 * t25) * t5 * in.w[2] + (T(1) / T(215040)) * t26 * in.w[1] * t5 + (T(1) / T(215040)) * t5 * in.w[0] * t25;
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Returns false where segment_cauchy_i14_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 65 +, 166 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i14_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[5] + M_flat[4] * in.w[0] + in.w[2] * M_flat[6];
    G_ab = in.w[1] * M_flat[6] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t9;
    const T t12 = T(1) / D;
    const T t13 = t6 * t5;
    const T t14 = t10 * t10;
    const T t15 = t14 * t9;
    const T t16 = T(128) * t8 * a_minus_b + T(3) * (T(48) * t7 * a_minus_b + T(7) * (T(8) * t11 * b + T(5) * t12 * (T(2) * t10 * b + T(2) * t6 * a_minus_b + T(3) * t12 * a * (t5 * a_minus_b + J2 * a + t9 * b)) * a + T(8) * t13 * a_minus_b) * t12 * a + T(48) * t14 * b) * t12 * a + T(128) * t15 * b;
    const T t17 = t13 * t13;
    const T t18 = t11 * t11;
    const T t19 = T(11) * t16 * t12 * a + T(1280) * t17 * a_minus_b + T(1280) * t18 * b;
    const T t20 = T(1) / a;
    const T t21 = T(1280) * t17 - T(1280) * t18 - t19 * t12 * b;
    F = (T(1) / T(15360)) * t19 * t12 * in.w[0] - (T(1) / T(15360)) * in.w[1] * t20 * t21 - (T(1) / T(15360)) * (c * t19 * t12 + T(2) * t20 * t21 * b - T(12) * t16 * t12) * in.w[2] * t20;
    const T t22 = t17 * t5;
    const T t23 = t18 * t9;
    const T t24 = T(13) * t19 * t12 * a + T(15360) * t22 * a_minus_b + T(15360) * t23 * b;
    const T t25 = T(15360) * t22 - T(15360) * t23 - t24 * t12 * b;
    const T t26 = T(2) * t25 * t20 * b + c * t24 * t12 - T(14) * t19 * t12;
    G_ap = (T(1) / T(215040)) * t24 * t12 * in.w[0] - (T(1) / T(215040)) * t25 * in.w[1] * t20 - (T(1) / T(215040)) * in.w[2] * t20 * t26;
    G_ab = (T(1) / T(215040)) * in.w[2] * t20 * (t25 * c * t20 - T(14) * t20 * t21 - T(2) * t20 * t26 * b) - (T(1) / T(215040)) * t25 * t20 * in.w[0] - (T(1) / T(215040)) * in.w[1] * t20 * t26;
  }
  const T g_factor = -T(14) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 55 +, 124 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2940 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(14, 14, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(14, 14, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0] + in.w[2] * M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t5;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = T(1) / D;
    const T t12 = t6 * t5;
    const T t13 = t10 * t9;
    const T t14 = t10 * t10;
    const T t15 = t14 * t9;
    const T t16 = T(128) * b * t8 + T(3) * (T(48) * b * t7 + T(7) * (T(5) * (T(2) * b * t6 + T(2) * a_minus_b * t10 + T(3) * (a_minus_b * t9 + J2 * a + b * t5) * a * t11) * a * t11 + T(8) * b * t12 + T(8) * a_minus_b * t13) * a * t11 + T(48) * a_minus_b * t14) * a * t11 + T(128) * a_minus_b * t15;
    const T t17 = t12 * t12;
    const T t18 = t13 * t13;
    const T t19 = T(11) * t16 * a * t11 + T(1280) * b * t17 + T(1280) * a_minus_b * t18;
    const T t20 = b * t19 * t11 + T(1280) * t17 - T(1280) * t18;
    const T t21 = T(1) / a;
    const T t22 = T(2) * b * t20 * t21 + T(12) * t16 * t11 - c * t19 * t11;
    F = (T(1) / T(15360)) * in.w[3] * (T(2) * t22 * b * t21 + T(12) * (b * t16 * t11 + T(128) * t8 - T(128) * t15) * t21 - c * t20 * t21) * t21 + (T(1) / T(15360)) * in.w[0] * t19 * t11 + (T(1) / T(15360)) * in.w[1] * t20 * t21 + (T(1) / T(15360)) * t22 * in.w[2] * t21;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 67 +, 169 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3652 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + in.w[2] * M_flat[3] + M_flat[1] * in.w[0] + M_flat[4] * in.w[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + M_beyond[2] * in.w[2] + M_beyond[3] * in.w[3] + M_beyond[1] * in.w[1];
    G_ab = in.w[2] * M_beyond[3] + in.w[3] * M_beyond[4] + in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = T(1) / c;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t9 * t8;
    const T t12 = t6 * t6;
    const T t13 = t9 * t9;
    const T t14 = t12 * t5;
    const T t15 = t13 * t8;
    const T t16 = T(3) * (T(7) * (T(8) * t7 * a_minus_b + T(5) * (T(2) * t6 * a_minus_b + T(2) * b * t9 + T(3) * (J2 * a + b * t8 + t5 * a_minus_b) * a * t10) * a * t10 + T(8) * b * t11) * a * t10 + T(48) * t12 * a_minus_b + T(48) * b * t13) * a * t10 + T(128) * t14 * a_minus_b + T(128) * b * t15;
    const T t17 = t7 * t7;
    const T t18 = t11 * t11;
    const T t19 = T(11) * t16 * a * t10 + T(1280) * t17 * a_minus_b + T(1280) * b * t18;
    const T t20 = t17 * t5;
    const T t21 = t18 * t8;
    const T t22 = T(13) * t19 * a * t10 + T(15360) * t20 * a_minus_b + T(15360) * b * t21;
    const T t23 = T(15360) * t20 - b * t22 * t10 - T(15360) * t21;
    const T t24 = T(1) / a;
    const T t25 = T(2) * b * t23 * t24 + c * t22 * t10 - T(14) * t19 * t10;
    const T t26 = T(1280) * t17 - T(1280) * t18 - b * t19 * t10;
    const T t27 = T(2) * b * t25 * t24 + T(14) * t26 * t24 - c * t23 * t24;
    G_ap = (T(1) / T(215040)) * t22 * t10 * in.w[0] - (T(1) / T(215040)) * in.w[2] * t25 * t24 - (T(1) / T(215040)) * in.w[1] * t23 * t24 - (T(1) / T(215040)) * t27 * in.w[3] * t24;
    G_ab = -(T(1) / T(215040)) * t27 * in.w[2] * t24 - (T(1) / T(215040)) * t23 * t24 * in.w[0] - (T(1) / T(215040)) * (T(2) * b * t27 * t24 + T(14) * (t19 * c * t10 + T(2) * b * t26 * t24 - T(12) * t16 * t10) * t24 - t25 * c * t24) * in.w[3] * t24 - (T(1) / T(215040)) * in.w[1] * t25 * t24;
  }
  const T g_factor = -T(14) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Operations: 74 +, 193 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3726 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0];
    G_ab = in.w[0] * M_flat[6] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(14, 16, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + in.w[3] * M_beyond[3] + M_beyond[2] * in.w[2];
    G_ap = in.w[3] * M_beyond[8] + in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + in.w[2] * M_beyond[7];
    G_ab = in.w[3] * M_beyond[9] + M_beyond[8] * in.w[2] + in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = t7 * t6;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t12 * t12;
    const T t15 = t14 * t11;
    const T t16 = T(128) * a_minus_b * t9 + T(3) * t5 * a * (T(7) * t5 * a * (T(8) * a_minus_b * t10 + T(8) * b * t13 + T(5) * t5 * a * (T(2) * a_minus_b * t7 + T(3) * t5 * a * (a * J2 + b * t11 + a_minus_b * t6) + T(2) * b * t12)) + T(48) * a_minus_b * t8 + T(48) * b * t14) + T(128) * b * t15;
    const T t17 = t10 * t10;
    const T t18 = t13 * t13;
    const T t19 = T(11) * t5 * t16 * a + T(1280) * a_minus_b * t17 + T(1280) * b * t18;
    const T t20 = t5 * b * t19 + T(1280) * t18 - T(1280) * t17;
    const T t21 = T(1) / a;
    const T t22 = T(2) * t20 * t21 * b + T(12) * t5 * t16 - t5 * c * t19;
    F = (T(1) / T(15360)) * t20 * t21 * in.w[1] + (T(1) / T(15360)) * t22 * t21 * in.w[2] + (T(1) / T(15360)) * in.w[3] * t21 * (T(2) * t22 * t21 * b - t20 * t21 * c - T(12) * (T(128) * t9 - t5 * t16 * b - T(128) * t15) * t21) + (T(1) / T(15360)) * t5 * in.w[0] * t19;
    const T t23 = t17 * t6;
    const T t24 = t18 * t11;
    const T t25 = T(15360) * a_minus_b * t23 + T(13) * t5 * a * t19 + T(15360) * b * t24;
    const T t26 = T(15360) * t23 - T(15360) * t24 - t5 * t25 * b;
    const T t27 = T(14) * t5 * t19 - T(2) * t21 * b * t26 - t5 * t25 * c;
    const T t28 = T(14) * t20 * t21 + t21 * t26 * c + T(2) * t21 * t27 * b;
    G_ap = (T(1) / T(215040)) * t21 * t27 * in.w[2] + (T(1) / T(215040)) * in.w[3] * t21 * t28 + (T(1) / T(215040)) * t5 * in.w[0] * t25 - (T(1) / T(215040)) * t21 * in.w[1] * t26;
    G_ab = (T(1) / T(215040)) * (T(2) * t21 * t28 * b + T(14) * t22 * t21 - t21 * t27 * c) * in.w[3] * t21 + (T(1) / T(215040)) * t21 * t28 * in.w[2] + (T(1) / T(215040)) * t21 * t27 * in.w[1] - (T(1) / T(215040)) * t21 * in.w[0] * t26;
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−14/2) dt
/// Returns false where segment_cauchy_i14_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 74 +, 193 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i14_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(14, 16, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + in.w[0] * M_flat[0];
    G_ap = M_flat[7] * in.w[2] + M_flat[8] * in.w[3] + M_flat[6] * in.w[1] + in.w[0] * M_flat[5];
    G_ab = in.w[1] * M_flat[7] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
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
    const T t17 = T(1) / D;
    const T t18 = T(128) * a_minus_b * t14 + T(128) * b * t16 + T(3) * (T(48) * a_minus_b * t13 + T(48) * b * t15 + T(7) * (T(8) * b * t11 + T(8) * a_minus_b * t7 + T(5) * (T(2) * b * t10 + T(2) * a_minus_b * t6 + T(3) * (J2 * a + a_minus_b * t5 + b * t9) * a * t17) * a * t17) * a * t17) * a * t17;
    const T t19 = T(1280) * a_minus_b * t8 + T(1280) * b * t12 + T(11) * t18 * a * t17;
    const T t20 = T(1) / a;
    const T t21 = b * t19 * t17 + T(1280) * t12 - T(1280) * t8;
    const T t22 = T(12) * t18 * t17 + T(2) * t21 * b * t20 - c * t19 * t17;
    F = (T(1) / T(15360)) * in.w[0] * t19 * t17 + (T(1) / T(15360)) * (T(12) * (T(128) * t16 + b * t18 * t17 - T(128) * t14) * t20 + T(2) * b * t22 * t20 - t21 * c * t20) * t20 * in.w[3] + (T(1) / T(15360)) * in.w[2] * t22 * t20 + (T(1) / T(15360)) * t21 * in.w[1] * t20;
    const T t23 = t12 * t9;
    const T t24 = t8 * t5;
    const T t25 = T(15360) * a_minus_b * t24 + T(15360) * b * t23 + T(13) * t19 * a * t17;
    const T t26 = T(15360) * t23 + t25 * b * t17 - T(15360) * t24;
    const T t27 = T(2) * b * t26 * t20 + T(14) * t19 * t17 - t25 * c * t17;
    const T t28 = T(14) * t21 * t20 + T(2) * b * t27 * t20 - t26 * c * t20;
    G_ap = (T(1) / T(215040)) * t28 * t20 * in.w[3] + (T(1) / T(215040)) * t27 * in.w[2] * t20 + (T(1) / T(215040)) * in.w[1] * t26 * t20 + (T(1) / T(215040)) * in.w[0] * t25 * t17;
    G_ab = (T(1) / T(215040)) * (T(2) * b * t28 * t20 + T(14) * t22 * t20 - t27 * c * t20) * t20 * in.w[3] + (T(1) / T(215040)) * in.w[0] * t26 * t20 + (T(1) / T(215040)) * in.w[2] * t28 * t20 + (T(1) / T(215040)) * in.w[1] * t27 * t20;
  }
  const T g_factor = -T(14) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 42 +, 106 ×, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 376 +, 861 ×, 122 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 0, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / r0;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * t10;
    const T t14 = t6 * t6;
    const T t15 = t14 * t5;
    const T t16 = t11 * t10;
    const T t17 = t16 * t16;
    F = (T(1) / T(3003)) * t3 * in.w[0] * (T(231) * a_minus_b * t4 * t8 + T(4) * t3 * a * (T(63) * t13 * t9 * b + T(63) * a_minus_b * t4 * t15 + T(2) * t3 * a * (T(35) * a_minus_b * t4 * t14 + T(8) * (T(5) * a_minus_b * t4 * t7 + T(5) * t16 * t9 * b + T(2) * (T(3) * t11 * t9 * b + T(3) * a_minus_b * t4 * t6 + T(4) * t3 * (T(2) * t3 * (t9 * b + a_minus_b * t4) * a + a_minus_b * t4 * t5 + t10 * t9 * b) * a) * t3 * a) * t3 * a + T(35) * t12 * t9 * b)) + T(231) * t17 * t9 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 49 +, 135 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 609 +, 1562 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t15 = T(1) / D;
    const T t16 = t5 * t5;
    const T t17 = t11 * t11;
    const T t18 = t16 * t4;
    const T t19 = t17 * t10;
    const T t20 = T(429) * t3 * a_minus_b * t8 + T(429) * t14 * b * t9 + T(2) * a * t15 * (T(231) * t13 * b * t9 + T(231) * t3 * a_minus_b * t7 + T(4) * a * t15 * (T(2) * (T(35) * t3 * a_minus_b * t16 + T(35) * t17 * b * t9 + T(8) * a * t15 * (T(5) * t3 * a_minus_b * t6 + T(5) * t12 * b * t9 + T(2) * a * t15 * (T(4) * (t10 * b * t9 + T(2) * a * t15 * (t3 * a_minus_b + b * t9) + t3 * a_minus_b * t4) * a * t15 + T(3) * t3 * a_minus_b * t5 + T(3) * t11 * b * t9))) * a * t15 + T(63) * t3 * a_minus_b * t18 + T(63) * t19 * b * t9));
    G_ap = (T(1) / T(6435)) * t20 * t15 * in.w[0];
    G_ab = (T(1) / T(6435)) * (T(429) * t14 * t9 + t20 * t15 * b - T(429) * t3 * t8) * in.w[0] / a;
  }
  const T g_factor = -T(15) * in.s * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 49 +, 139 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 617 +, 1588 ×, 243 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = M_beyond[2] * in.w[0];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t18 = T(231) * t8 * a_minus_b * t4 + T(231) * t13 * t9 * b + T(4) * t3 * a * (T(2) * t3 * (T(35) * t14 * t9 * b + T(35) * t15 * a_minus_b * t4 + T(8) * t3 * a * (T(2) * (T(3) * t11 * t9 * b + T(3) * t6 * a_minus_b * t4 + T(4) * (t5 * a_minus_b * t4 + T(2) * t3 * a * (a_minus_b * t4 + t9 * b) + t10 * t9 * b) * t3 * a) * t3 * a + T(5) * t7 * a_minus_b * t4 + T(5) * t12 * t9 * b)) * a + T(63) * t16 * t9 * b + T(63) * t17 * a_minus_b * t4);
    F = (T(1) / T(3003)) * t3 * in.w[0] * t18;
    const T t19 = t8 * t5;
    const T t20 = t13 * t10;
    const T t21 = T(429) * t19 * a_minus_b * t4 + T(2) * t3 * a * t18 + T(429) * t20 * t9 * b;
    G_ap = (T(1) / T(6435)) * t3 * t21 * in.w[0];
    G_ab = (T(1) / T(6435)) * in.w[0] * (t3 * t21 * b + T(429) * t20 * t9 - T(429) * t19 * t4) / a;
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Returns false where segment_cauchy_i15_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 139 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i15_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t13 = T(1) / D;
    const T t14 = t10 * t10;
    const T t15 = t14 * t9;
    const T t16 = t5 * t5;
    const T t17 = t16 * t4;
    const T t18 = T(231) * t7 * a_minus_b * t3 + T(231) * b * t12 * t8 + T(4) * t13 * a * (T(63) * b * t15 * t8 + T(2) * (T(8) * t13 * a * (T(5) * t6 * a_minus_b * t3 + T(5) * b * t11 * t8 + T(2) * t13 * (T(4) * t13 * a * (t4 * a_minus_b * t3 + b * t9 * t8 + T(2) * t13 * (a_minus_b * t3 + b * t8) * a) + T(3) * t5 * a_minus_b * t3 + T(3) * b * t10 * t8) * a) + T(35) * b * t14 * t8 + T(35) * t16 * a_minus_b * t3) * t13 * a + T(63) * t17 * a_minus_b * t3);
    F = (T(1) / T(3003)) * t18 * t13 * in.w[0];
    const T t19 = t12 * t9;
    const T t20 = t7 * t4;
    const T t21 = T(429) * b * t19 * t8 + T(2) * t18 * t13 * a + T(429) * t20 * a_minus_b * t3;
    G_ap = (T(1) / T(6435)) * t21 * t13 * in.w[0];
    G_ab = (T(1) / T(6435)) * (T(429) * t19 * t8 + b * t21 * t13 - T(429) * t20 * t3) * in.w[0] / a;
  }
  const T g_factor = -T(15) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 45 +, 114 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 607 +, 1551 ×, 238 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0];
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
    const T t15 = T(1) / D;
    const T t16 = t10 * t10;
    const T t17 = t16 * t9;
    const T t18 = T(231) * t7 * t3 * b + T(231) * t8 * a_minus_b * t12 + T(4) * (T(63) * t14 * t3 * b + T(2) * (T(8) * t15 * a * (T(5) * t6 * t3 * b + T(2) * (T(3) * t5 * t3 * b + T(3) * t8 * a_minus_b * t10 + T(4) * t15 * a * (T(2) * (t3 * b + t8 * a_minus_b) * t15 * a + t4 * t3 * b + t8 * a_minus_b * t9)) * t15 * a + T(5) * t8 * a_minus_b * t11) + T(35) * t13 * t3 * b + T(35) * t8 * a_minus_b * t16) * t15 * a + T(63) * t8 * a_minus_b * t17) * t15 * a;
    F = (T(1) / T(3003)) * in.w[0] * t18 * t15 - (T(1) / T(3003)) * in.w[1] * (T(231) * t8 * t12 - T(231) * t7 * t3 - t18 * t15 * b) / a;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 53 +, 150 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2255 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t14 = t6 * t6;
    const T t15 = t14 * t5;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = T(231) * t8 * b * t4 + T(231) * t9 * a_minus_b * t13 + T(4) * a * t3 * (T(63) * t15 * b * t4 + T(63) * t9 * a_minus_b * t17 + T(2) * (T(35) * t14 * b * t4 + T(8) * a * t3 * (T(5) * t7 * b * t4 + T(2) * (T(4) * a * t3 * (T(2) * (t9 * a_minus_b + b * t4) * a * t3 + t9 * a_minus_b * t10 + t5 * b * t4) + T(3) * t6 * b * t4 + T(3) * t9 * a_minus_b * t11) * a * t3 + T(5) * t9 * a_minus_b * t12) + T(35) * t9 * a_minus_b * t16) * a * t3);
    const T t19 = t13 * t10;
    const T t20 = t8 * t5;
    const T t21 = T(2) * a * t3 * t18 + T(429) * t9 * a_minus_b * t19 + T(429) * t20 * b * t4;
    const T t22 = T(429) * t9 * t19 - t3 * b * t21 - T(429) * t20 * t4;
    const T t23 = T(1) / a;
    G_ap = (T(1) / T(6435)) * in.w[0] * t3 * t21 - (T(1) / T(6435)) * t22 * in.w[1] * t23;
    G_ab = -(T(1) / T(6435)) * in.w[0] * t22 * t23 - (T(1) / T(45045)) * (T(14) * t22 * t23 * b + T(7) * c * t3 * t21 - T(15) * t3 * t18) * in.w[1] * t23;
  }
  const T g_factor = -T(15) * in.s * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 56 +, 163 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 856 +, 2295 ×, 364 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (in.s * cross_cross + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[0] * M_beyond[3] + in.w[1] * M_beyond[4];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t18 = T(231) * t4 * a_minus_b * t8 + T(231) * t13 * t9 * b + T(4) * t3 * a * (T(2) * t3 * a * (T(35) * t14 * t9 * b + T(8) * t3 * a * (T(2) * (T(4) * t3 * a * (t4 * a_minus_b * t5 + T(2) * (t4 * a_minus_b + t9 * b) * t3 * a + t10 * t9 * b) + T(3) * t11 * t9 * b + T(3) * t4 * a_minus_b * t6) * t3 * a + T(5) * t4 * a_minus_b * t7 + T(5) * t12 * t9 * b) + T(35) * t4 * a_minus_b * t15) + T(63) * t16 * t9 * b + T(63) * t4 * a_minus_b * t17);
    const T t19 = T(1) / a;
    F = (T(1) / T(3003)) * in.w[0] * t3 * t18 - (T(1) / T(3003)) * t19 * in.w[1] * (T(231) * t4 * t8 - t3 * t18 * b - T(231) * t13 * t9);
    const T t20 = t8 * t5;
    const T t21 = t13 * t10;
    const T t22 = T(2) * t3 * t18 * a + T(429) * t4 * a_minus_b * t20 + T(429) * t21 * t9 * b;
    const T t23 = t22 * t3 * b + T(429) * t21 * t9 - T(429) * t4 * t20;
    G_ap = (T(1) / T(6435)) * t22 * in.w[0] * t3 + (T(1) / T(6435)) * t23 * t19 * in.w[1];
    G_ab = (T(1) / T(6435)) * in.w[0] * t23 * t19 - (T(1) / T(45045)) * t19 * in.w[1] * (T(7) * c * t22 * t3 - T(15) * t3 * t18 - T(14) * t23 * t19 * b);
  }
  const T g_factor = -T(15) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Returns false where segment_cauchy_i15_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 56 +, 163 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i15_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t18 = T(231) * t8 * t4 * b + T(231) * t13 * t9 * a_minus_b + T(4) * (T(63) * t15 * t9 * a_minus_b + T(2) * (T(35) * t14 * t9 * a_minus_b + T(8) * t3 * a * (T(2) * t3 * a * (T(3) * t11 * t9 * a_minus_b + T(4) * t3 * a * (t5 * t4 * b + t10 * t9 * a_minus_b + T(2) * (t9 * a_minus_b + t4 * b) * t3 * a) + T(3) * t6 * t4 * b) + T(5) * t7 * t4 * b + T(5) * t12 * t9 * a_minus_b) + T(35) * t16 * t4 * b) * t3 * a + T(63) * t17 * t4 * b) * t3 * a;
    const T t19 = T(1) / a;
    F = (T(1) / T(3003)) * in.w[0] * t3 * t18 - (T(1) / T(3003)) * in.w[1] * (T(231) * t13 * t9 - T(231) * t8 * t4 - t3 * t18 * b) * t19;
    const T t20 = t8 * t5;
    const T t21 = t13 * t10;
    const T t22 = T(429) * t20 * t4 * b + T(2) * t3 * a * t18 + T(429) * t21 * t9 * a_minus_b;
    const T t23 = T(429) * t21 * t9 - T(429) * t20 * t4 - t3 * t22 * b;
    G_ap = (T(1) / T(6435)) * in.w[0] * t3 * t22 - (T(1) / T(6435)) * t23 * in.w[1] * t19;
    G_ab = -(T(1) / T(6435)) * in.w[0] * t23 * t19 - (T(1) / T(45045)) * (T(14) * t23 * t19 * b + T(7) * c * t3 * t22 - T(15) * t3 * t18) * in.w[1] * t19;
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 48 +, 126 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 839 +, 2243 ×, 355 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[0] * in.w[0] + in.w[2] * M_beyond[2] + M_beyond[1] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t14 = t12 * t9;
    const T t15 = t13 * t5;
    const T t16 = T(2) * t3 * a * (T(8) * t3 * a * (T(5) * t7 * t4 * a_minus_b + T(2) * t3 * a * (T(4) * t3 * a * (t8 * b * t9 + t5 * t4 * a_minus_b + T(2) * t3 * a * (t8 * b + t4 * a_minus_b)) + T(3) * t8 * b * t10 + T(3) * t6 * t4 * a_minus_b) + T(5) * t8 * b * t11) + T(35) * t8 * b * t12 + T(35) * t13 * t4 * a_minus_b) + T(63) * t8 * b * t14 + T(63) * t15 * t4 * a_minus_b;
    const T t17 = t7 * t7;
    const T t18 = t11 * t11;
    const T t19 = T(4) * t3 * a * t16 + T(231) * t17 * t4 * a_minus_b + T(231) * t8 * b * t18;
    const T t20 = T(1) / a;
    const T t21 = t19 * t3 * b + T(231) * t8 * t18 - T(231) * t17 * t4;
    F = (T(1) / T(3003)) * t19 * t3 * in.w[0] + (T(1) / T(9009)) * in.w[2] * (T(13) * t3 * t16 + T(6) * t20 * b * t21 - T(3) * t19 * t3 * c) * t20 + (T(1) / T(3003)) * t20 * t21 * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 59 +, 170 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1076 +, 2950 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[1] * in.w[1] + M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0];
    G_ab = in.w[1] * M_beyond[2] + in.w[2] * M_beyond[3] + in.w[0] * M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
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
    const T t14 = T(1) / D;
    const T t15 = t11 * t11;
    const T t16 = t5 * t5;
    const T t17 = t16 * t4;
    const T t18 = t15 * t10;
    const T t19 = T(231) * t13 * t9 * a_minus_b + T(4) * t14 * a * (T(2) * (T(8) * (T(5) * t12 * t9 * a_minus_b + T(5) * b * t3 * t6 + T(2) * (T(4) * (T(2) * (t9 * a_minus_b + b * t3) * t14 * a + t10 * t9 * a_minus_b + b * t3 * t4) * t14 * a + T(3) * b * t3 * t5 + T(3) * t11 * t9 * a_minus_b) * t14 * a) * t14 * a + T(35) * t15 * t9 * a_minus_b + T(35) * b * t3 * t16) * t14 * a + T(63) * b * t3 * t17 + T(63) * t18 * t9 * a_minus_b) + T(231) * b * t3 * t7;
    const T t20 = t13 * t10;
    const T t21 = T(2) * t19 * t14 * a + T(429) * t20 * t9 * a_minus_b + T(429) * b * t3 * t8;
    const T t22 = T(429) * t3 * t8 + b * t21 * t14 - T(429) * t20 * t9;
    const T t23 = T(1) / a;
    const T t24 = T(14) * t22 * b * t23 + T(15) * t19 * t14 - T(7) * t21 * c * t14;
    G_ap = (T(1) / T(45045)) * t24 * in.w[2] * t23 + (T(1) / T(6435)) * t22 * in.w[1] * t23 + (T(1) / T(6435)) * in.w[0] * t21 * t14;
    G_ab = (T(1) / T(45045)) * (T(15) * (T(231) * t3 * t7 + b * t19 * t14 - T(231) * t13 * t9) * t23 + T(2) * t24 * b * t23 - T(7) * t22 * c * t23) * in.w[2] * t23 + (T(1) / T(45045)) * t24 * in.w[1] * t23 + (T(1) / T(6435)) * t22 * in.w[0] * t23;
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 63 +, 188 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1097 +, 3006 ×, 487 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[0] + M_flat[6] * in.w[2] + M_flat[5] * in.w[1];
    G_ab = M_flat[7] * in.w[2] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 3, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = M_beyond[5] * in.w[1] + M_beyond[6] * in.w[2] + in.w[0] * M_beyond[4];
    G_ab = M_beyond[7] * in.w[2] + M_beyond[6] * in.w[1] + M_beyond[5] * in.w[0];
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
    const T t15 = t10 * t10;
    const T t16 = t15 * t9;
    const T t17 = T(1) / D;
    const T t18 = T(63) * b * t14 * t3 + T(63) * t8 * a_minus_b * t16 + T(2) * (T(35) * b * t13 * t3 + T(8) * (T(5) * b * t6 * t3 + T(5) * t8 * a_minus_b * t11 + T(2) * (T(4) * (t8 * a_minus_b * t9 + b * t4 * t3 + T(2) * (t8 * a_minus_b + b * t3) * t17 * a) * t17 * a + T(3) * b * t5 * t3 + T(3) * t8 * a_minus_b * t10) * t17 * a) * t17 * a + T(35) * t8 * a_minus_b * t15) * t17 * a;
    const T t19 = T(231) * b * t7 * t3 + T(231) * t8 * a_minus_b * t12 + T(4) * t18 * t17 * a;
    const T t20 = T(231) * t8 * t12 - b * t19 * t17 - T(231) * t7 * t3;
    const T t21 = T(1) / a;
    F = (T(1) / T(3003)) * t19 * in.w[0] * t17 - (T(1) / T(3003)) * t20 * in.w[1] * t21 - (T(1) / T(9009)) * t21 * in.w[2] * (T(3) * t19 * c * t17 + T(6) * b * t20 * t21 - T(13) * t18 * t17);
    const T t22 = t7 * t4;
    const T t23 = t12 * t9;
    const T t24 = T(429) * b * t22 * t3 + T(429) * t8 * a_minus_b * t23 + T(2) * t19 * t17 * a;
    const T t25 = T(429) * t8 * t23 - t24 * b * t17 - T(429) * t22 * t3;
    const T t26 = T(15) * t19 * t17 - T(7) * t24 * c * t17 - T(14) * b * t25 * t21;
    G_ap = (T(1) / T(45045)) * t26 * t21 * in.w[2] + (T(1) / T(6435)) * t24 * in.w[0] * t17 - (T(1) / T(6435)) * t25 * in.w[1] * t21;
    G_ab = (T(1) / T(45045)) * (T(2) * b * t26 * t21 + T(7) * t25 * c * t21 - T(15) * t20 * t21) * t21 * in.w[2] + (T(1) / T(45045)) * in.w[1] * t26 * t21 - (T(1) / T(6435)) * in.w[0] * t25 * t21;
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Returns false where segment_cauchy_i15_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 188 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i15_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + in.w[2] * M_flat[2];
    G_ap = M_flat[6] * in.w[2] + in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
    G_ab = M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + M_flat[7] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
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
    const T t18 = T(63) * t4 * a_minus_b * t15 + T(63) * b * t17 * t9 + T(2) * t3 * a * (T(35) * t4 * a_minus_b * t14 + T(35) * b * t16 * t9 + T(8) * t3 * a * (T(5) * t4 * a_minus_b * t7 + T(5) * b * t12 * t9 + T(2) * t3 * a * (T(4) * t3 * a * (b * t10 * t9 + t4 * a_minus_b * t5 + T(2) * t3 * a * (t4 * a_minus_b + b * t9)) + T(3) * t4 * a_minus_b * t6 + T(3) * b * t11 * t9)));
    const T t19 = T(231) * t4 * a_minus_b * t8 + T(231) * b * t13 * t9 + T(4) * t18 * t3 * a;
    const T t20 = T(1) / a;
    const T t21 = T(231) * t13 * t9 + t3 * b * t19 - T(231) * t4 * t8;
    F = (T(1) / T(3003)) * t3 * t19 * in.w[0] + (T(1) / T(9009)) * t20 * in.w[2] * (T(6) * t20 * b * t21 + T(13) * t18 * t3 - T(3) * t3 * t19 * c) + (T(1) / T(3003)) * t20 * in.w[1] * t21;
    const T t22 = t8 * t5;
    const T t23 = t13 * t10;
    const T t24 = T(429) * t4 * a_minus_b * t22 + T(429) * b * t23 * t9 + T(2) * t3 * a * t19;
    const T t25 = t24 * t3 * b + T(429) * t23 * t9 - T(429) * t4 * t22;
    const T t26 = T(14) * t20 * t25 * b + T(15) * t3 * t19 - T(7) * t24 * t3 * c;
    G_ap = (T(1) / T(6435)) * t24 * t3 * in.w[0] + (T(1) / T(45045)) * t20 * t26 * in.w[2] + (T(1) / T(6435)) * t20 * t25 * in.w[1];
    G_ab = (T(1) / T(6435)) * t20 * t25 * in.w[0] + (T(1) / T(45045)) * t20 * in.w[1] * t26 - (T(1) / T(45045)) * t20 * in.w[2] * (T(7) * t20 * t25 * c - T(15) * t20 * t21 - T(2) * t20 * t26 * b);
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 53 +, 143 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1072 +, 2937 ×, 473 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = ap_ap * in.s + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(15, 15, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(15, 15, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1] + in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / D;
    const T t4 = T(1) / r1;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / r0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t6 * t5;
    const T t14 = t7 * t5;
    const T t15 = t11 * t9;
    const T t16 = T(2) * t3 * a * (T(35) * t7 * t4 * a_minus_b + T(35) * t8 * b * t11 + T(8) * t3 * (T(5) * t8 * b * t12 + T(2) * t3 * a * (T(3) * t6 * t4 * a_minus_b + T(3) * t8 * b * t10 + T(4) * (T(2) * t3 * a * (t8 * b + t4 * a_minus_b) + t8 * b * t9 + t5 * t4 * a_minus_b) * t3 * a) + T(5) * t13 * t4 * a_minus_b) * a) + T(63) * t14 * t4 * a_minus_b + T(63) * t8 * b * t15;
    const T t17 = t13 * t13;
    const T t18 = t12 * t12;
    const T t19 = T(4) * t3 * a * t16 + T(231) * t17 * t4 * a_minus_b + T(231) * t8 * b * t18;
    const T t20 = T(1) / a;
    const T t21 = T(231) * t17 * t4 - t3 * b * t19 - T(231) * t8 * t18;
    const T t22 = T(3) * t3 * c * t19 + T(6) * t21 * t20 * b - T(13) * t3 * t16;
    F = (T(1) / T(3003)) * t3 * in.w[0] * t19 + (T(1) / T(9009)) * t20 * in.w[3] * (T(13) * t20 * (t3 * b * t16 + T(63) * t8 * t15 - T(63) * t14 * t4) + T(3) * t21 * t20 * c - T(2) * t22 * t20 * b) - (T(1) / T(3003)) * t21 * t20 * in.w[1] - (T(1) / T(9009)) * t22 * t20 * in.w[2];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 65 +, 191 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1311 +, 3647 ×, 592 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(17, 17, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[4] * in.w[3] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(17, 17, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[2] * M_beyond[2] + in.w[1] * M_beyond[1] + M_beyond[3] * in.w[3] + in.w[0] * M_beyond[0];
    G_ab = in.w[0] * M_beyond[1] + M_beyond[4] * in.w[3] + M_beyond[3] * in.w[2] + in.w[1] * M_beyond[2];
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
    const T t11 = t10 * t10;
    const T t12 = t11 * t9;
    const T t13 = t5 * t5;
    const T t14 = t13 * t4;
    const T t15 = T(1) / D;
    const T t16 = t10 * t9;
    const T t17 = T(63) * t12 * a_minus_b * t8 + T(63) * b * t3 * t14 + T(2) * (T(35) * b * t3 * t13 + T(35) * t11 * a_minus_b * t8 + T(8) * t15 * a * (T(5) * b * t3 * t6 + T(2) * (T(3) * t10 * a_minus_b * t8 + T(3) * b * t3 * t5 + T(4) * t15 * (T(2) * (a_minus_b * t8 + b * t3) * t15 * a + b * t3 * t4 + t9 * a_minus_b * t8) * a) * t15 * a + T(5) * t16 * a_minus_b * t8)) * t15 * a;
    const T t18 = t16 * t16;
    const T t19 = T(231) * b * t3 * t7 + T(4) * t17 * t15 * a + T(231) * t18 * a_minus_b * t8;
    const T t20 = t18 * t9;
    const T t21 = t7 * t4;
    const T t22 = T(429) * b * t3 * t21 + T(2) * t19 * t15 * a + T(429) * t20 * a_minus_b * t8;
    const T t23 = T(429) * t20 * t8 - b * t15 * t22 - T(429) * t3 * t21;
    const T t24 = T(1) / a;
    const T t25 = T(15) * t19 * t15 - T(14) * b * t23 * t24 - T(7) * c * t15 * t22;
    const T t26 = T(231) * t18 * t8 - b * t19 * t15 - T(231) * t3 * t7;
    const T t27 = T(7) * c * t23 * t24 + T(2) * t25 * b * t24 - T(15) * t26 * t24;
    G_ap = (T(1) / T(45045)) * t25 * in.w[2] * t24 + (T(1) / T(45045)) * t27 * t24 * in.w[3] + (T(1) / T(6435)) * in.w[0] * t15 * t22 - (T(1) / T(6435)) * in.w[1] * t23 * t24;
    G_ab = (T(1) / T(45045)) * in.w[2] * t27 * t24 + (T(1) / T(45045)) * t25 * in.w[1] * t24 - (T(1) / T(45045)) * (t25 * c * t24 - T(2) * b * t27 * t24 - T(5) * (T(13) * t17 * t15 - T(6) * b * t26 * t24 - T(3) * c * t19 * t15) * t24) * t24 * in.w[3] - (T(1) / T(6435)) * in.w[0] * t23 * t24;
  }
  const T g_factor = -T(15) * length * in.s;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Operations: 72 +, 218 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
/// Longest path: 1340 +, 3721 ×, 612 /, 5 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(15, 17, 4, a, b, D, c, q1, M_beyond.data());
    F = in.w[1] * M_beyond[1] + in.w[2] * M_beyond[2] + M_beyond[0] * in.w[0] + in.w[3] * M_beyond[3];
    G_ap = in.w[1] * M_beyond[6] + M_beyond[5] * in.w[0] + M_beyond[8] * in.w[3] + M_beyond[7] * in.w[2];
    G_ab = in.w[2] * M_beyond[8] + in.w[0] * M_beyond[6] + in.w[1] * M_beyond[7] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / r0;
    const T t5 = t4 * t4;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = t6 * t6;
    const T t11 = T(1) / r1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t13;
    const T t15 = t13 * t12;
    const T t16 = t10 * t5;
    const T t17 = t14 * t12;
    const T t18 = T(2) * t9 * a * (T(35) * b * t10 * t4 + T(35) * t14 * t11 * a_minus_b + T(8) * (T(2) * (T(3) * t13 * t11 * a_minus_b + T(3) * b * t6 * t4 + T(4) * (T(2) * (b * t4 + t11 * a_minus_b) * t9 * a + b * t5 * t4 + t12 * t11 * a_minus_b) * t9 * a) * t9 * a + T(5) * t15 * t11 * a_minus_b + T(5) * b * t7 * t4) * t9 * a) + T(63) * b * t16 * t4 + T(63) * t17 * t11 * a_minus_b;
    const T t19 = t15 * t15;
    const T t20 = T(4) * t18 * t9 * a + T(231) * b * t8 * t4 + T(231) * t19 * t11 * a_minus_b;
    const T t21 = T(231) * t8 * t4 + b * t20 * t9 - T(231) * t19 * t11;
    const T t22 = T(6) * b * t21 * t3 + T(13) * t18 * t9 - T(3) * c * t20 * t9;
    F = (T(1) / T(9009)) * in.w[2] * t3 * t22 + (T(1) / T(3003)) * t21 * in.w[1] * t3 + (T(1) / T(3003)) * t20 * t9 * in.w[0] - (T(1) / T(9009)) * t3 * in.w[3] * (T(3) * t21 * c * t3 - T(13) * (T(63) * t16 * t4 + b * t18 * t9 - T(63) * t17 * t11) * t3 - T(2) * b * t3 * t22);
    const T t23 = t8 * t5;
    const T t24 = t19 * t12;
    const T t25 = T(2) * t20 * t9 * a + T(429) * b * t23 * t4 + T(429) * t24 * t11 * a_minus_b;
    const T t26 = T(429) * t23 * t4 + b * t25 * t9 - T(429) * t24 * t11;
    const T t27 = T(15) * t20 * t9 + T(14) * b * t26 * t3 - T(7) * c * t25 * t9;
    const T t28 = T(7) * c * t26 * t3 - T(2) * b * t27 * t3 - T(15) * t21 * t3;
    G_ap = (T(1) / T(6435)) * in.w[1] * t26 * t3 + (T(1) / T(45045)) * t27 * in.w[2] * t3 + (T(1) / T(6435)) * t25 * t9 * in.w[0] - (T(1) / T(45045)) * t28 * t3 * in.w[3];
    G_ab = (T(1) / T(6435)) * t26 * t3 * in.w[0] + (T(1) / T(45045)) * (T(5) * t3 * t22 - t27 * c * t3 - T(2) * b * t28 * t3) * t3 * in.w[3] + (T(1) / T(45045)) * t27 * in.w[1] * t3 - (T(1) / T(45045)) * in.w[2] * t28 * t3;
  }
  const T g_factor = -T(15) * length * in.s;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−15/2) dt
/// Returns false where segment_cauchy_i15_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 72 +, 218 ×, 4 /, 3 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i15_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(15, 17, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ap = M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + in.w[3] * M_flat[8] + M_flat[6] * in.w[1];
    G_ab = M_flat[7] * in.w[1] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + M_flat[6] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = T(1) / a;
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t6;
    const T t10 = t7 * t6;
    const T t11 = T(1) / r0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * t12;
    const T t15 = t13 * t13;
    const T t16 = t15 * t12;
    const T t17 = T(63) * a_minus_b * t5 * t9 + T(2) * t4 * a * (T(35) * a_minus_b * t5 * t8 + T(8) * t4 * a * (T(5) * a_minus_b * t5 * t10 + T(2) * t4 * a * (T(3) * a_minus_b * t5 * t7 + T(4) * t4 * (T(2) * t4 * a * (t11 * b + a_minus_b * t5) + t11 * b * t12 + a_minus_b * t5 * t6) * a + T(3) * t11 * b * t13) + T(5) * t11 * b * t14) + T(35) * t11 * b * t15) + T(63) * t11 * b * t16;
    const T t18 = t14 * t14;
    const T t19 = t10 * t10;
    const T t20 = T(231) * a_minus_b * t5 * t19 + T(231) * t11 * b * t18 + T(4) * t4 * a * t17;
    const T t21 = T(231) * t11 * t18 + t4 * b * t20 - T(231) * t5 * t19;
    const T t22 = T(13) * t4 * t17 + T(6) * t21 * t3 * b - T(3) * t4 * t20 * c;
    F = (T(1) / T(9009)) * t3 * t22 * in.w[2] + (T(1) / T(3003)) * t21 * t3 * in.w[1] + (T(1) / T(3003)) * t4 * in.w[0] * t20 - (T(1) / T(9009)) * t3 * in.w[3] * (T(3) * t21 * t3 * c - T(2) * t3 * b * t22 - T(13) * t3 * (T(63) * t11 * t16 + t4 * t17 * b - T(63) * t5 * t9));
    const T t23 = t19 * t6;
    const T t24 = t18 * t12;
    const T t25 = T(429) * a_minus_b * t5 * t23 + T(2) * t4 * a * t20 + T(429) * t11 * b * t24;
    const T t26 = T(429) * t11 * t24 + t25 * t4 * b - T(429) * t5 * t23;
    const T t27 = T(15) * t4 * t20 + T(14) * t3 * b * t26 - T(7) * t25 * t4 * c;
    const T t28 = T(2) * t3 * b * t27 + T(15) * t21 * t3 - T(7) * t3 * t26 * c;
    G_ap = (T(1) / T(6435)) * t25 * t4 * in.w[0] + (T(1) / T(6435)) * t3 * t26 * in.w[1] + (T(1) / T(45045)) * t3 * t28 * in.w[3] + (T(1) / T(45045)) * t3 * t27 * in.w[2];
    G_ab = (T(1) / T(45045)) * t3 * t28 * in.w[2] + (T(1) / T(45045)) * t3 * in.w[1] * t27 + (T(1) / T(6435)) * t3 * in.w[0] * t26 + (T(1) / T(45045)) * t3 * in.w[3] * (T(2) * t3 * t28 * b + T(5) * t3 * t22 - t3 * t27 * c);
  }
  const T g_factor = -T(15) * length * in.s;
  f = F * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 46 +, 102 ×, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 379 +, 867 ×, 122 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T length = sqrt(ab_ab);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 0, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 0, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / c;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t7 * t7;
    const T t16 = t15 * t6;
    const T t17 = t12 * t12;
    const T t18 = t17 * t11;
    const T t19 = t14 * t11;
    F = (T(1) / T(215040)) * t5 * in.w[0] * (T(15360) * a_minus_b * t10 + T(13) * (T(1280) * a_minus_b * t9 + T(1280) * t14 * b + T(11) * t5 * a * (T(128) * a_minus_b * t16 + T(3) * (T(7) * (T(8) * t13 * b + T(8) * a_minus_b * t8 + T(5) * t5 * a * (T(2) * t12 * b + T(2) * a_minus_b * t7 + T(3) * (a * J2 + t11 * b + a_minus_b * t6) * t5 * a)) * t5 * a + T(48) * a_minus_b * t15 + T(48) * t17 * b) * t5 * a + T(128) * t18 * b)) * t5 * a + T(15360) * t19 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 53 +, 126 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 612 +, 1568 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (in.s * cross_cross + ab_ab) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 1, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 1, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0];
    G_ab = M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = T(1) / D;
    const T t14 = t10 * t9;
    const T t15 = t6 * t5;
    const T t16 = t7 * t5;
    const T t17 = t11 * t9;
    const T t18 = t15 * t15;
    const T t19 = t14 * t14;
    const T t20 = t19 * t9;
    const T t21 = t18 * t5;
    const T t22 = T(14336) * b * t8 + T(14336) * a_minus_b * t12 + (T(13) * t13 * (T(11) * (T(3) * (T(7) * t13 * a * (T(5) * t13 * a * (T(2) * b * t6 + T(2) * a_minus_b * t10 + T(3) * (b * t5 + a_minus_b * t9 + J2 * a) * t13 * a) + T(8) * a_minus_b * t14 + T(8) * b * t15) + T(48) * b * t7 + T(48) * a_minus_b * t11) * t13 * a + T(128) * b * t16 + T(128) * a_minus_b * t17) * t13 * a + T(1280) * b * t18 + T(1280) * a_minus_b * t19) * a + T(15360) * a_minus_b * t20 + T(15360) * b * t21) * t13 * a;
    G_ap = (T(1) / T(229376)) * t22 * t13 * in.w[0];
    G_ab = (T(1) / T(229376)) * in.w[0] * (T(14336) * t8 + b * t22 * t13 - T(14336) * t12) / a;
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 53 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 620 +, 1595 ×, 243 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 1, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0];
    G_ap = in.w[0] * M_beyond[2];
    G_ab = in.w[0] * M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = t7 * t7;
    const T t12 = t11 * t6;
    const T t13 = T(1) / c;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * t13;
    const T t17 = t14 * t13;
    const T t18 = t17 * t17;
    const T t19 = t18 * t13;
    const T t20 = T(15360) * a_minus_b * t10 + T(13) * t5 * a * (T(1280) * a_minus_b * t9 + T(11) * t5 * (T(128) * a_minus_b * t12 + T(128) * b * t16 + T(3) * t5 * a * (T(48) * a_minus_b * t11 + T(48) * b * t15 + T(7) * t5 * a * (T(5) * t5 * a * (T(2) * a_minus_b * t7 + T(2) * b * t14 + T(3) * t5 * a * (b * t13 + a_minus_b * t6 + a * J2)) + T(8) * a_minus_b * t8 + T(8) * b * t17))) * a + T(1280) * b * t18) + T(15360) * b * t19;
    F = (T(1) / T(215040)) * t5 * in.w[0] * t20;
    const T t21 = t15 * t15;
    const T t22 = t11 * t11;
    const T t23 = T(14336) * b * t21 + t5 * a * t20 + T(14336) * a_minus_b * t22;
    G_ap = (T(1) / T(229376)) * t5 * in.w[0] * t23;
    G_ab = (T(1) / T(229376)) * in.w[0] * (t5 * b * t23 + T(14336) * t21 - T(14336) * t22) / a;
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 w0 (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Returns false where segment_cauchy_i16_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 53 +, 130 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i16_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 1, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
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
    const T t18 = t16 * t6;
    const T t19 = t17 * t10;
    const T t20 = T(13) * t5 * a * (T(11) * t5 * a * (T(128) * t9 * a_minus_b + T(128) * b * t13 + T(3) * (T(7) * (T(8) * t14 * a_minus_b + T(5) * (T(2) * t7 * a_minus_b + T(2) * b * t11 + T(3) * (b * t10 + t6 * a_minus_b + J2 * a) * t5 * a) * t5 * a + T(8) * b * t15) * t5 * a + T(48) * b * t12 + T(48) * t8 * a_minus_b) * t5 * a) + T(1280) * t16 * a_minus_b + T(1280) * b * t17) + T(15360) * t18 * a_minus_b + T(15360) * b * t19;
    F = (T(1) / T(215040)) * t20 * t5 * in.w[0];
    const T t21 = t12 * t12;
    const T t22 = t8 * t8;
    const T t23 = T(14336) * b * t21 + T(14336) * t22 * a_minus_b + t20 * t5 * a;
    G_ap = (T(1) / T(229376)) * t23 * t5 * in.w[0];
    G_ab = (T(1) / T(229376)) * (T(14336) * t21 + b * t23 * t5 - T(14336) * t22) * in.w[0] / a;
  }
  const T g_factor = -T(16) * in.s * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 49 +, 108 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 610 +, 1557 ×, 238 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (ab_ab + in.s * cross_cross);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 1, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 1, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[1] * in.w[1] + M_beyond[0] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t6 * t6;
    const T t16 = t15 * t5;
    const T t17 = T(1) / D;
    const T t18 = t11 * t11;
    const T t19 = t18 * t10;
    const T t20 = T(15360) * a_minus_b * t9 + T(15360) * b * t14 + T(13) * (T(1280) * a_minus_b * t8 + T(1280) * b * t13 + T(11) * (T(128) * a_minus_b * t16 + T(3) * (T(48) * a_minus_b * t15 + T(7) * (T(5) * t17 * (T(3) * (b * t10 + a_minus_b * t5 + J2 * a) * t17 * a + T(2) * a_minus_b * t6 + T(2) * b * t11) * a + T(8) * a_minus_b * t7 + T(8) * b * t12) * t17 * a + T(48) * b * t18) * t17 * a + T(128) * b * t19) * t17 * a) * t17 * a;
    F = (T(1) / T(215040)) * in.w[0] * t20 * t17 + (T(1) / T(215040)) * (T(15360) * t14 + b * t20 * t17 - T(15360) * t9) * in.w[1] / a;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 57 +, 141 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 2261 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = in.s * (cross_cross * in.s + ab_ab);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 2, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 2, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[0] * in.w[0] + in.w[1] * M_beyond[1];
    G_ab = in.w[1] * M_beyond[2] + M_beyond[1] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = T(1) / D;
    const T t14 = t6 * t6;
    const T t15 = t11 * t11;
    const T t16 = t14 * t5;
    const T t17 = t15 * t10;
    const T t18 = t12 * t12;
    const T t19 = t18 * t10;
    const T t20 = T(15360) * b * t9 + T(13) * (T(1280) * b * t8 + T(11) * (T(3) * (T(7) * (T(8) * b * t7 + T(8) * t12 * a_minus_b + T(5) * (T(2) * b * t6 + T(2) * t11 * a_minus_b + T(3) * (J2 * a + t10 * a_minus_b + b * t5) * t13 * a) * t13 * a) * t13 * a + T(48) * b * t14 + T(48) * t15 * a_minus_b) * t13 * a + T(128) * b * t16 + T(128) * t17 * a_minus_b) * t13 * a + T(1280) * t18 * a_minus_b) * t13 * a + T(15360) * t19 * a_minus_b;
    const T t21 = t15 * t15;
    const T t22 = t14 * t14;
    const T t23 = t20 * t13 * a + T(14336) * t21 * a_minus_b + T(14336) * b * t22;
    const T t24 = b * t23 * t13 + T(14336) * t22 - T(14336) * t21;
    const T t25 = T(1) / a;
    G_ap = (T(1) / T(229376)) * t24 * in.w[1] * t25 + (T(1) / T(229376)) * in.w[0] * t23 * t13;
    G_ab = (T(1) / T(229376)) * t24 * in.w[0] * t25 + (T(1) / T(3440640)) * in.w[1] * t25 * (T(30) * t24 * b * t25 + T(16) * t20 * t13 - T(15) * c * t23 * t13);
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 60 +, 152 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 2302 ×, 364 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = ap_bp * in.s + T(1);
  T F;
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * a * min(T(c), T(q1)) - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 2, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 2, a, b, D, c, q1, M_beyond.data());
    F = in.w[0] * M_beyond[0] + in.w[1] * M_beyond[1];
    G_ap = in.w[1] * M_beyond[4] + in.w[0] * M_beyond[3];
    G_ab = M_beyond[5] * in.w[1] + in.w[0] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / c;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t10 * t9;
    const T t13 = t7 * t6;
    const T t14 = t8 * t6;
    const T t15 = t11 * t9;
    const T t16 = t13 * t13;
    const T t17 = t12 * t12;
    const T t18 = t16 * t6;
    const T t19 = t17 * t9;
    const T t20 = T(13) * t5 * a * (T(11) * t5 * a * (T(3) * t5 * a * (T(48) * a_minus_b * t8 + T(48) * b * t11 + T(7) * t5 * a * (T(5) * t5 * a * (T(3) * t5 * a * (a_minus_b * t6 + b * t9 + J2 * a) + T(2) * b * t10 + T(2) * a_minus_b * t7) + T(8) * b * t12 + T(8) * a_minus_b * t13)) + T(128) * a_minus_b * t14 + T(128) * b * t15) + T(1280) * a_minus_b * t16 + T(1280) * b * t17) + T(15360) * a_minus_b * t18 + T(15360) * b * t19;
    const T t21 = T(1) / a;
    F = (T(1) / T(215040)) * in.w[0] * t5 * t20 - (T(1) / T(215040)) * t21 * in.w[1] * (T(15360) * t18 - t5 * b * t20 - T(15360) * t19);
    const T t22 = t8 * t8;
    const T t23 = t11 * t11;
    const T t24 = T(14336) * a_minus_b * t22 + T(14336) * b * t23 + t5 * a * t20;
    const T t25 = t5 * t24 * b + T(14336) * t23 - T(14336) * t22;
    G_ap = (T(1) / T(229376)) * t21 * in.w[1] * t25 + (T(1) / T(229376)) * in.w[0] * t5 * t24;
    G_ab = (T(1) / T(3440640)) * t21 * in.w[1] * (T(16) * t5 * t20 + T(30) * t21 * t25 * b - T(15) * t5 * t24 * c) + (T(1) / T(229376)) * in.w[0] * t21 * t25;
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Returns false where segment_cauchy_i16_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 60 +, 152 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i16_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[3] * in.w[0] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = t6 * t6;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = T(1) / D;
    const T t15 = t12 * t12;
    const T t16 = t10 * t5;
    const T t17 = t15 * t11;
    const T t18 = t13 * t13;
    const T t19 = t18 * t11;
    const T t20 = T(15360) * b * t9 + T(13) * (T(1280) * b * t8 + T(11) * (T(3) * (T(48) * b * t10 + T(7) * (T(8) * b * t7 + T(8) * a_minus_b * t13 + T(5) * (T(3) * (J2 * a + a_minus_b * t11 + b * t5) * t14 * a + T(2) * b * t6 + T(2) * a_minus_b * t12) * t14 * a) * t14 * a + T(48) * a_minus_b * t15) * t14 * a + T(128) * b * t16 + T(128) * a_minus_b * t17) * t14 * a + T(1280) * a_minus_b * t18) * t14 * a + T(15360) * a_minus_b * t19;
    const T t21 = T(1) / a;
    F = (T(1) / T(215040)) * (t20 * b * t14 + T(15360) * t9 - T(15360) * t19) * t21 * in.w[1] + (T(1) / T(215040)) * t20 * in.w[0] * t14;
    const T t22 = t15 * t15;
    const T t23 = t10 * t10;
    const T t24 = T(14336) * a_minus_b * t22 + t20 * t14 * a + T(14336) * b * t23;
    const T t25 = T(14336) * t23 + b * t24 * t14 - T(14336) * t22;
    G_ap = (T(1) / T(229376)) * in.w[0] * t24 * t14 + (T(1) / T(229376)) * t25 * t21 * in.w[1];
    G_ab = (T(1) / T(229376)) * in.w[0] * t25 * t21 - (T(1) / T(3440640)) * t21 * (T(15) * c * t24 * t14 - T(30) * b * t25 * t21 - T(16) * t20 * t14) * in.w[1];
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 52 +, 119 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 842 +, 2249 ×, 355 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 2, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 2, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t5;
    const T t8 = t7 * t7;
    const T t9 = t8 * t5;
    const T t10 = T(1) / c;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t12 * t12;
    const T t14 = t13 * t10;
    const T t15 = t6 * t6;
    const T t16 = t15 * t5;
    const T t17 = T(1) / D;
    const T t18 = t11 * t11;
    const T t19 = t18 * t10;
    const T t20 = T(11) * (T(128) * a_minus_b * t16 + T(3) * (T(7) * (T(8) * a_minus_b * t7 + T(5) * (T(2) * a_minus_b * t6 + T(2) * b * t11 + T(3) * t17 * a * (b * t10 + a * J2 + a_minus_b * t5)) * t17 * a + T(8) * b * t12) * t17 * a + T(48) * a_minus_b * t15 + T(48) * b * t18) * t17 * a + T(128) * b * t19) * t17 * a + T(1280) * a_minus_b * t8 + T(1280) * b * t13;
    const T t21 = T(15360) * a_minus_b * t9 + T(15360) * b * t14 + T(13) * t20 * t17 * a;
    const T t22 = T(1) / a;
    const T t23 = T(15360) * t9 - b * t21 * t17 - T(15360) * t14;
    F = (T(1) / T(215040)) * in.w[0] * t21 * t17 - (T(1) / T(215040)) * (T(2) * b * t22 * t23 + t21 * c * t17 - T(14) * t20 * t17) * in.w[2] * t22 - (T(1) / T(215040)) * in.w[1] * t22 * t23;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 63 +, 159 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1079 +, 2956 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 3, a, b, c, T(0), T(1), M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + M_flat[1] * in.w[0];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 3, a, b, D, c, q1, M_beyond.data());
    G_ap = M_beyond[2] * in.w[2] + M_beyond[0] * in.w[0] + M_beyond[1] * in.w[1];
    G_ab = in.w[0] * M_beyond[1] + in.w[1] * M_beyond[2] + M_beyond[3] * in.w[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = t7 * t6;
    const T t17 = t16 * t16;
    const T t18 = t17 * t6;
    const T t19 = t12 * t12;
    const T t20 = t19 * t11;
    const T t21 = t8 * t6;
    const T t22 = T(15360) * a_minus_b * t15 + T(15360) * b * t18 + T(13) * t10 * (T(1280) * a_minus_b * t14 + T(11) * (T(3) * t10 * a * (T(48) * a_minus_b * t19 + T(7) * (T(5) * t10 * a * (T(3) * (b * t6 + J2 * a + a_minus_b * t11) * t10 * a + T(2) * a_minus_b * t12 + T(2) * b * t7) + T(8) * a_minus_b * t13 + T(8) * b * t16) * t10 * a + T(48) * b * t8) + T(128) * a_minus_b * t20 + T(128) * b * t21) * t10 * a + T(1280) * b * t17) * a;
    const T t23 = t19 * t19;
    const T t24 = t22 * t10 * a + T(14336) * b * t9 + T(14336) * a_minus_b * t23;
    const T t25 = T(14336) * t9 + b * t10 * t24 - T(14336) * t23;
    const T t26 = T(15) * c * t10 * t24 - T(16) * t22 * t10 - T(30) * b * t5 * t25;
    G_ap = (T(1) / T(229376)) * in.w[1] * t5 * t25 + (T(1) / T(229376)) * in.w[0] * t10 * t24 - (T(1) / T(3440640)) * t5 * in.w[2] * t26;
    G_ab = (T(1) / T(229376)) * in.w[0] * t5 * t25 - (T(1) / T(3440640)) * in.w[1] * t5 * t26 - (T(1) / T(3440640)) * (T(15) * c * t5 * t25 + T(2) * b * t5 * t26 - T(16) * (T(15360) * t18 + b * t22 * t10 - T(15360) * t15) * t5) * t5 * in.w[2];
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 67 +, 176 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1100 +, 3013 ×, 487 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[1] * M_flat[5] + in.w[2] * M_flat[6] + in.w[0] * M_flat[4];
    G_ab = M_flat[6] * in.w[1] + in.w[0] * M_flat[5] + in.w[2] * M_flat[7];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 8> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1];
    G_ap = M_beyond[4] * in.w[0] + in.w[2] * M_beyond[6] + M_beyond[5] * in.w[1];
    G_ab = in.w[2] * M_beyond[7] + in.w[0] * M_beyond[5] + in.w[1] * M_beyond[6];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
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
    const T t15 = T(1) / D;
    const T t16 = t11 * t11;
    const T t17 = t16 * t10;
    const T t18 = t6 * t6;
    const T t19 = t18 * t5;
    const T t20 = T(1280) * b * t8 + T(1280) * a_minus_b * t13 + T(11) * (T(128) * a_minus_b * t17 + T(128) * b * t19 + T(3) * (T(7) * (T(5) * t15 * (T(2) * a_minus_b * t11 + T(3) * (b * t5 + J2 * a + a_minus_b * t10) * t15 * a + T(2) * b * t6) * a + T(8) * b * t7 + T(8) * a_minus_b * t12) * t15 * a + T(48) * a_minus_b * t16 + T(48) * b * t18) * t15 * a) * t15 * a;
    const T t21 = T(15360) * b * t9 + T(15360) * a_minus_b * t14 + T(13) * t15 * t20 * a;
    const T t22 = T(15360) * t14 - T(15360) * t9 - t21 * b * t15;
    const T t23 = T(1) / a;
    F = (T(1) / T(215040)) * t21 * in.w[0] * t15 + (T(1) / T(215040)) * in.w[2] * (T(14) * t15 * t20 - t21 * c * t15 - T(2) * b * t22 * t23) * t23 - (T(1) / T(215040)) * in.w[1] * t22 * t23;
    const T t24 = t18 * t18;
    const T t25 = t16 * t16;
    const T t26 = T(14336) * b * t24 + T(14336) * a_minus_b * t25 + t21 * t15 * a;
    const T t27 = b * t26 * t15 + T(14336) * t24 - T(14336) * t25;
    const T t28 = T(15) * t26 * c * t15 - T(16) * t21 * t15 - T(30) * b * t27 * t23;
    G_ap = (T(1) / T(229376)) * t27 * in.w[1] * t23 + (T(1) / T(229376)) * in.w[0] * t26 * t15 - (T(1) / T(3440640)) * in.w[2] * t28 * t23;
    G_ab = (T(1) / T(229376)) * in.w[0] * t27 * t23 - (T(1) / T(3440640)) * in.w[1] * t28 * t23 - (T(1) / T(3440640)) * in.w[2] * (T(15) * c * t27 * t23 + T(2) * b * t28 * t23 + T(16) * t22 * t23) * t23;
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Returns false where segment_cauchy_i16_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 176 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i16_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 3, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / a;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = t7 * t7;
    const T t9 = t8 * t7;
    const T t10 = T(1) / q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t10;
    const T t13 = t11 * t11;
    const T t14 = t8 * t8;
    const T t15 = t13 * t10;
    const T t16 = t14 * t7;
    const T t17 = t9 * t9;
    const T t18 = t12 * t12;
    const T t19 = T(11) * t6 * (T(3) * t6 * (T(7) * t6 * (T(8) * t9 * b + T(8) * t12 * a_minus_b + T(5) * t6 * a * (T(2) * t11 * a_minus_b + T(3) * t6 * a * (J2 * a + t7 * b + t10 * a_minus_b) + T(2) * t8 * b)) * a + T(48) * t13 * a_minus_b + T(48) * t14 * b) * a + T(128) * t15 * a_minus_b + T(128) * t16 * b) * a + T(1280) * t17 * b + T(1280) * t18 * a_minus_b;
    const T t20 = t17 * t7;
    const T t21 = t18 * t10;
    const T t22 = T(13) * t6 * t19 * a + T(15360) * t20 * b + T(15360) * t21 * a_minus_b;
    const T t23 = t22 * t6 * b + T(15360) * t20 - T(15360) * t21;
    F = (T(1) / T(215040)) * in.w[1] * t5 * t23 + (T(1) / T(215040)) * t22 * t6 * in.w[0] - (T(1) / T(215040)) * (t22 * c * t6 - T(2) * t5 * t23 * b - T(14) * t6 * t19) * in.w[2] * t5;
    const T t24 = t14 * t14;
    const T t25 = t13 * t13;
    const T t26 = T(14336) * t24 * b + T(14336) * t25 * a_minus_b + t22 * t6 * a;
    const T t27 = t6 * b * t26 + T(14336) * t24 - T(14336) * t25;
    const T t28 = T(15) * c * t6 * t26 - T(30) * t27 * t5 * b - T(16) * t22 * t6;
    G_ap = (T(1) / T(229376)) * in.w[1] * t27 * t5 + (T(1) / T(229376)) * t6 * in.w[0] * t26 - (T(1) / T(3440640)) * in.w[2] * t5 * t28;
    G_ab = (T(1) / T(229376)) * t27 * t5 * in.w[0] - (T(1) / T(3440640)) * in.w[1] * t5 * t28 - (T(1) / T(3440640)) * (T(15) * c * t27 * t5 + T(2) * t5 * t28 * b - T(16) * t5 * t23) * in.w[2] * t5;
  }
  const T g_factor = -T(16) * in.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 57 +, 133 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1075 +, 2943 ×, 473 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T length = sqrt(ab_ab);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + T(1);
  const T D = (ab_ab + cross_cross * in.s) * in.s;
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + T(1);
  const T c_minus_b = in.s * ap_bp + T(1);
  T F;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(16, 16, 3, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(16, 16, 3, a, b, D, c, q1, M_beyond.data());
    F = in.w[2] * M_beyond[2] + M_beyond[3] * in.w[3] + in.w[1] * M_beyond[1] + in.w[0] * M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = T(1) / q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    const T t11 = t6 * t5;
    const T t12 = t9 * t8;
    const T t13 = T(1) / D;
    const T t14 = t7 * t5;
    const T t15 = t10 * t8;
    const T t16 = t11 * t11;
    const T t17 = t12 * t12;
    const T t18 = T(11) * (T(3) * (T(48) * b * t7 + T(48) * a_minus_b * t10 + T(7) * (T(8) * b * t11 + T(8) * a_minus_b * t12 + T(5) * (T(3) * (a_minus_b * t8 + J2 * a + b * t5) * a * t13 + T(2) * b * t6 + T(2) * a_minus_b * t9) * a * t13) * a * t13) * a * t13 + T(128) * b * t14 + T(128) * a_minus_b * t15) * a * t13 + T(1280) * b * t16 + T(1280) * a_minus_b * t17;
    const T t19 = t16 * t5;
    const T t20 = t17 * t8;
    const T t21 = T(13) * t18 * a * t13 + T(15360) * b * t19 + T(15360) * a_minus_b * t20;
    const T t22 = T(15360) * t19 + b * t21 * t13 - T(15360) * t20;
    const T t23 = T(1) / a;
    const T t24 = c * t21 * t13 - T(2) * b * t22 * t23 - T(14) * t18 * t13;
    F = (T(1) / T(215040)) * in.w[0] * t21 * t13 + (T(1) / T(215040)) * in.w[1] * t22 * t23 - (T(1) / T(215040)) * (T(2) * t24 * b * t23 + c * t22 * t23 - T(14) * t23 * (T(1280) * t16 + b * t18 * t13 - T(1280) * t17)) * t23 * in.w[3] - (T(1) / T(215040)) * t24 * in.w[2] * t23;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 69 +, 179 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1314 +, 3653 ×, 592 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  T G_ap;
  T G_ab;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(18, 18, 4, a, b, c, T(0), T(1), M_flat.data());
    G_ap = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
    G_ab = in.w[2] * M_flat[3] + in.w[3] * M_flat[4] + in.w[0] * M_flat[1] + in.w[1] * M_flat[2];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(18, 18, 4, a, b, D, c, q1, M_beyond.data());
    G_ap = in.w[0] * M_beyond[0] + M_beyond[2] * in.w[2] + in.w[3] * M_beyond[3] + M_beyond[1] * in.w[1];
    G_ab = M_beyond[1] * in.w[0] + M_beyond[2] * in.w[1] + M_beyond[3] * in.w[2] + in.w[3] * M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / c;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = T(1) / q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t11 * t9;
    const T t14 = t7 * t5;
    const T t15 = t10 * t9;
    const T t16 = t6 * t5;
    const T t17 = T(1) / D;
    const T t18 = t15 * t15;
    const T t19 = t16 * t16;
    const T t20 = T(11) * (T(128) * t13 * a_minus_b + T(128) * b * t14 + T(3) * a * (T(7) * (T(8) * t15 * a_minus_b + T(8) * b * t16 + T(5) * (T(2) * t10 * a_minus_b + T(3) * (b * t5 + J2 * a + t9 * a_minus_b) * a * t17 + T(2) * b * t6) * a * t17) * a * t17 + T(48) * b * t7 + T(48) * t11 * a_minus_b) * t17) * a * t17 + T(1280) * t18 * a_minus_b + T(1280) * b * t19;
    const T t21 = t18 * t9;
    const T t22 = t19 * t5;
    const T t23 = T(13) * t20 * a * t17 + T(15360) * t21 * a_minus_b + T(15360) * b * t22;
    const T t24 = T(14336) * b * t8 + T(14336) * t12 * a_minus_b + t23 * a * t17;
    const T t25 = b * t24 * t17 + T(14336) * t8 - T(14336) * t12;
    const T t26 = T(1) / a;
    const T t27 = T(16) * t23 * t17 + T(30) * t25 * b * t26 - T(15) * t24 * c * t17;
    const T t28 = T(15360) * t21 - T(15360) * t22 - t23 * b * t17;
    const T t29 = T(16) * t28 * t26 + T(15) * t25 * c * t26 - T(2) * b * t27 * t26;
    G_ap = (T(1) / T(229376)) * in.w[0] * t24 * t17 + (T(1) / T(3440640)) * t27 * in.w[2] * t26 + (T(1) / T(229376)) * t25 * in.w[1] * t26 - (T(1) / T(3440640)) * in.w[3] * t29 * t26;
    G_ab = (T(1) / T(3440640)) * t27 * in.w[1] * t26 + (T(1) / T(229376)) * t25 * in.w[0] * t26 - (T(1) / T(3440640)) * t29 * in.w[2] * t26 - (T(1) / T(3440640)) * in.w[3] * (t27 * c * t26 + T(16) * (T(2) * t28 * b * t26 + t23 * c * t17 - T(14) * t20 * t17) * t26 + T(2) * b * t29 * t26) * t26;
  }
  const T g_factor = -T(16) * length * in.s;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Operations: 76 +, 203 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
/// Longest path: 1343 +, 3728 ×, 612 /, 3 sqrt, 0 atan, 2 log/asinh.
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
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 4, a, b, c, T(0), T(1), M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3];
    G_ap = in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + in.w[3] * M_flat[8];
    G_ab = M_flat[8] * in.w[2] + in.w[3] * M_flat[9] + in.w[1] * M_flat[7] + in.w[0] * M_flat[6];
  } else if (t1 >= T(0) && t2 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 10> M_beyond;
    segment_moments_beyond_end<T>(16, 18, 4, a, b, D, c, q1, M_beyond.data());
    F = M_beyond[2] * in.w[2] + in.w[0] * M_beyond[0] + M_beyond[1] * in.w[1] + in.w[3] * M_beyond[3];
    G_ap = in.w[1] * M_beyond[6] + in.w[0] * M_beyond[5] + in.w[3] * M_beyond[8] + M_beyond[7] * in.w[2];
    G_ab = M_beyond[8] * in.w[2] + M_beyond[7] * in.w[1] + in.w[0] * M_beyond[6] + in.w[3] * M_beyond[9];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = t4 * atan2(t3, c_minus_b);
    const T t5 = T(1) / D;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t7 * t7;
    const T t16 = t15 * t6;
    const T t17 = t12 * t12;
    const T t18 = t17 * t11;
    const T t19 = T(1280) * b * t9 + T(1280) * a_minus_b * t14 + T(11) * (T(128) * b * t16 + T(128) * a_minus_b * t18 + T(3) * t5 * a * (T(48) * b * t15 + T(48) * a_minus_b * t17 + T(7) * (T(8) * a_minus_b * t13 + T(8) * b * t8 + T(5) * (T(2) * a_minus_b * t12 + T(2) * b * t7 + T(3) * (a * J2 + b * t6 + a_minus_b * t11) * t5 * a) * t5 * a) * t5 * a)) * t5 * a;
    const T t20 = t14 * t11;
    const T t21 = T(15360) * b * t10 + T(13) * t5 * a * t19 + T(15360) * a_minus_b * t20;
    const T t22 = T(1) / a;
    const T t23 = T(15360) * t20 - t5 * b * t21 - T(15360) * t10;
    const T t24 = T(2) * t23 * t22 * b + t5 * c * t21 - T(14) * t5 * t19;
    F = (T(1) / T(215040)) * t5 * in.w[0] * t21 - (T(1) / T(215040)) * t22 * t24 * in.w[2] - (T(1) / T(215040)) * t23 * t22 * in.w[1] - (T(1) / T(215040)) * in.w[3] * t22 * (T(2) * t22 * b * t24 - t23 * t22 * c - T(14) * t22 * (t5 * b * t19 + T(1280) * t9 - T(1280) * t14));
    const T t25 = t15 * t15;
    const T t26 = t17 * t17;
    const T t27 = T(14336) * b * t25 + T(14336) * a_minus_b * t26 + t5 * a * t21;
    const T t28 = T(14336) * t25 + t27 * t5 * b - T(14336) * t26;
    const T t29 = T(16) * t5 * t21 + T(30) * t22 * b * t28 - T(15) * t27 * t5 * c;
    const T t30 = T(15) * t22 * t28 * c + T(16) * t23 * t22 - T(2) * t22 * t29 * b;
    G_ap = (T(1) / T(229376)) * t27 * t5 * in.w[0] + (T(1) / T(3440640)) * t22 * t29 * in.w[2] + (T(1) / T(229376)) * t22 * in.w[1] * t28 - (T(1) / T(3440640)) * in.w[3] * t22 * t30;
    G_ab = (T(1) / T(3440640)) * t22 * t29 * in.w[1] + (T(1) / T(229376)) * t22 * in.w[0] * t28 - (T(1) / T(3440640)) * t22 * t30 * in.w[2] - (T(1) / T(3440640)) * in.w[3] * t22 * (t22 * t29 * c + T(2) * t22 * t30 * b + T(16) * t22 * t24);
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P − Γ(t)|²)^(−16/2) dt
/// Returns false where segment_cauchy_i16_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 76 +, 203 ×, 5 /, 2 sqrt, 1 atan, 0 log/asinh.
template <class T>
bool segment_cauchy_i16_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
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
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = (T(7) / T(10)) * min(T(c), T(q1)) * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(16, 18, 4, a, b, c, T(0), T(1), M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3];
    G_ap = M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = in.w[1] * M_flat[7] + M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + in.w[2] * M_flat[8];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t3 = sqrt(D);
    const T t4 = T(1) / t3;
    const T J2 = atan2(t3, c_minus_b) * t4;
    const T t5 = T(1) / a;
    const T t6 = T(1) / c;
    const T t7 = t6 * t6;
    const T t8 = t7 * t6;
    const T t9 = t8 * t8;
    const T t10 = t9 * t6;
    const T t11 = T(1) / q1;
    const T t12 = t11 * t11;
    const T t13 = t12 * t11;
    const T t14 = t13 * t13;
    const T t15 = t14 * t11;
    const T t16 = t7 * t7;
    const T t17 = T(1) / D;
    const T t18 = t12 * t12;
    const T t19 = t16 * t6;
    const T t20 = t18 * t11;
    const T t21 = T(1280) * b * t9 + T(1280) * a_minus_b * t14 + T(11) * (T(3) * (T(48) * b * t16 + T(7) * (T(5) * (T(2) * b * t7 + T(3) * (J2 * a + a_minus_b * t11 + b * t6) * a * t17 + T(2) * a_minus_b * t12) * a * t17 + T(8) * b * t8 + T(8) * a_minus_b * t13) * a * t17 + T(48) * a_minus_b * t18) * a * t17 + T(128) * b * t19 + T(128) * a_minus_b * t20) * a * t17;
    const T t22 = T(15360) * b * t10 + T(15360) * a_minus_b * t15 + T(13) * t21 * a * t17;
    const T t23 = T(15360) * t10 + b * t22 * t17 - T(15360) * t15;
    const T t24 = T(2) * b * t5 * t23 + T(14) * t21 * t17 - c * t22 * t17;
    F = (T(1) / T(215040)) * t24 * in.w[2] * t5 + (T(1) / T(215040)) * in.w[1] * t5 * t23 + (T(1) / T(215040)) * t22 * t17 * in.w[0] - (T(1) / T(215040)) * (c * t5 * t23 - T(14) * (T(1280) * t9 + t21 * b * t17 - T(1280) * t14) * t5 - T(2) * t24 * b * t5) * t5 * in.w[3];
    const T t25 = t18 * t18;
    const T t26 = t16 * t16;
    const T t27 = t22 * a * t17 + T(14336) * a_minus_b * t25 + T(14336) * b * t26;
    const T t28 = T(14336) * t25 - b * t27 * t17 - T(14336) * t26;
    const T t29 = T(30) * t28 * b * t5 + T(15) * c * t27 * t17 - T(16) * t22 * t17;
    const T t30 = T(16) * t5 * t23 + T(15) * t28 * c * t5 - T(2) * b * t29 * t5;
    G_ap = (T(1) / T(3440640)) * t30 * t5 * in.w[3] + (T(1) / T(229376)) * t27 * t17 * in.w[0] - (T(1) / T(229376)) * t28 * in.w[1] * t5 - (T(1) / T(3440640)) * t29 * in.w[2] * t5;
    G_ab = (T(1) / T(3440640)) * (T(2) * b * t30 * t5 + T(16) * t24 * t5 + t29 * c * t5) * t5 * in.w[3] + (T(1) / T(3440640)) * t30 * in.w[2] * t5 - (T(1) / T(3440640)) * in.w[1] * t29 * t5 - (T(1) / T(229376)) * t28 * t5 * in.w[0];
  }
  const T g_factor = -T(16) * length * in.s;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t1 >= T(0) && t2 >= T(0)) && !(t0 >= T(0))));
}

}  // namespace skelconv::generated
