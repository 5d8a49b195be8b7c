// generated/segment_compact.hpp — segment kernels of the compact family.
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
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 28 +, 35 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  f = -(T(1) / T(3)) * in.w[0] * length * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) / a;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 25 +, 33 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i2_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T t0 = in.t1 - in.t0;
  const T g_ap = t0 * in.w[0];
  const T g_ab = (T(1) / T(2)) * in.w[0] * (T(2) * t0 * b + q1 - q0) / a;
  const T g_factor = -T(2) * length * inv_R2;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 33 +, 53 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = in.t1 - in.t0;
  const T g_ap = t0 * in.w[0];
  const T t1 = T(1) / a;
  const T g_ab = -(T(1) / T(2)) * in.w[0] * t1 * (q0 - q1 - T(2) * t0 * b);
  const T g_factor = -T(2) * inv_R2 * length;
  f = (T(1) / T(3)) * in.w[0] * length * t1 * (q1 * slope1 + T(2) * t0 * D - q0 * slope0);
  grad[0] = -(ab0 * g_ab - ap0 * g_ap) * g_factor;
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 31 +, 46 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * slope0 + T(2) * (in.t0 - in.t1) * D - slope1 * q1;
  f = -(T(1) / T(12)) * (T(4) * t0 * in.w[0] * t1 + in.w[1] * t0 * (T(4) * b * t0 * t1 + T(3) * q0 * q0 - T(3) * q1 * q1)) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 37 +, 61 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i2_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = in.t1 - in.t0;
  const T t2 = q1 + T(2) * t1 * b - q0;
  const T g_ap = (T(1) / T(2)) * t0 * in.w[1] * t2 + t1 * in.w[0];
  const T g_ab = (T(1) / T(3)) * t0 * in.w[1] * (T(3) * t0 * b * t2 + t0 * (T(2) * t1 * D + q1 * slope1 - q0 * slope0) - T(3) * c * t1) + (T(1) / T(2)) * t0 * in.w[0] * t2;
  const T g_factor = -T(2) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 40 +, 75 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - inv_R2 * cross_cross) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = in.t1 - in.t0;
  const T t1 = q1 + T(2) * b * t0 - q0;
  const T t2 = T(1) / a;
  const T g_ap = t0 * in.w[0] + (T(1) / T(2)) * in.w[1] * t1 * t2;
  const T t3 = q0 * slope0 - q1 * slope1 - T(2) * t0 * D;
  const T g_ab = (T(1) / T(2)) * t1 * t2 * in.w[0] + (T(1) / T(3)) * in.w[1] * (T(3) * b * t1 * t2 - T(3) * t0 * c - t2 * t3) * t2;
  const T g_factor = -T(2) * inv_R2 * length;
  f = -(T(1) / T(12)) * length * (T(4) * t2 * t3 * in.w[0] + in.w[1] * t2 * (T(4) * b * t2 * t3 + T(3) * q0 * q0 - T(3) * q1 * q1));
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 36 +, 65 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1;
  const T t1 = T(1) / a;
  const T t2 = q0 * q0;
  const T t3 = q1 * q1;
  const T t4 = T(4) * b * t0 * t1 + T(3) * t2 - T(3) * t3;
  f = (T(1) / T(60)) * (T(2) * in.w[2] * (T(10) * c * t0 * t1 - T(5) * b * t1 * t4 - T(2) * (T(4) * D * t0 * t1 + T(3) * t2 * slope0 - T(3) * t3 * slope1) * t1) * t1 - T(20) * in.w[0] * t0 * t1 - T(5) * in.w[1] * t1 * t4) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 43 +, 81 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i2_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = in.t1 - in.t0;
  const T t1 = T(1) / a;
  const T t2 = q1 + T(2) * t0 * b - q0;
  const T t3 = T(2) * t0 * D + q1 * slope1 - slope0 * q0;
  const T t4 = T(3) * t2 * t1 * b + t3 * t1 - T(3) * t0 * c;
  const T g_ap = t0 * in.w[0] + (T(1) / T(3)) * t1 * in.w[2] * t4 + (T(1) / T(2)) * t2 * t1 * in.w[1];
  const T g_ab = (T(1) / T(3)) * t1 * in.w[1] * t4 + (T(1) / T(2)) * t2 * t1 * in.w[0] - (T(1) / T(12)) * t1 * in.w[2] * (T(6) * t2 * t1 * c - t1 * (T(3) * q1 * q1 + T(4) * t3 * t1 * b - T(3) * q0 * q0) - T(8) * t1 * b * t4);
  const T g_factor = -T(2) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 49 +, 107 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T t0 = in.t1 - in.t0;
  const T t1 = slope1 * q1 + T(2) * D * t0 - slope0 * q0;
  const T t2 = T(1) / a;
  const T t3 = T(2) * t0 * b + q1 - q0;
  const T t4 = t1 * t2 + T(3) * t3 * t2 * b - T(3) * c * t0;
  const T g_ap = (T(1) / T(3)) * t4 * t2 * in.w[2] + (T(1) / T(2)) * t3 * t2 * in.w[1] + in.w[0] * t0;
  const T t5 = q1 * q1;
  const T t6 = q0 * q0;
  const T t7 = T(4) * t1 * t2 * b + T(3) * t5 - T(3) * t6;
  const T g_ab = (T(1) / T(2)) * in.w[0] * t3 * t2 + (T(1) / T(12)) * (t2 * t7 + T(8) * t4 * t2 * b - T(6) * t3 * t2 * c) * t2 * in.w[2] + (T(1) / T(3)) * t4 * t2 * in.w[1];
  const T g_factor = -T(2) * length * inv_R2;
  f = (T(1) / T(60)) * length * (T(20) * t1 * in.w[0] * t2 + T(2) * (T(2) * t2 * (T(3) * slope1 * t5 + T(4) * t1 * D * t2 - T(3) * slope0 * t6) + T(5) * t2 * t7 * b - T(10) * t1 * t2 * c) * t2 * in.w[2] + T(5) * t2 * t7 * in.w[1]);
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 41 +, 82 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * slope0 - q1 * slope1 - T(2) * D * (in.t1 - in.t0);
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = q0 * q0;
  const T t4 = T(3) * t2 * slope1 - T(4) * t0 * D * t1 - T(3) * t3 * slope0;
  const T t5 = T(3) * t2 - T(3) * t3 - T(4) * t0 * b * t1;
  const T t6 = T(10) * c * t0 * t1 + T(2) * t4 * t1 + T(5) * b * t5 * t1;
  const T t7 = t2 * q1;
  const T t8 = t3 * q0;
  f = -(T(1) / T(60)) * (T(20) * t0 * in.w[0] * t1 - T(2) * t1 * in.w[2] * t6 - T(5) * in.w[1] * t5 * t1 - in.w[3] * (T(4) * b * t1 * t6 + T(2) * t1 * (T(5) * t7 + T(2) * b * t4 * t1 - T(5) * t8) - T(5) * c * t5 * t1) * t1) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 51 +, 109 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i2_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = in.t1 - in.t0;
  const T t1 = q1 + T(2) * b * t0 - q0;
  const T t2 = T(1) / a;
  const T t3 = q0 * slope0 - T(2) * t0 * D - q1 * slope1;
  const T t4 = T(3) * t1 * b * t2 - t3 * t2 - T(3) * c * t0;
  const T t5 = q0 * q0;
  const T t6 = q1 * q1;
  const T t7 = T(4) * t3 * b * t2 + T(3) * t5 - T(3) * t6;
  const T t8 = T(8) * b * t4 * t2 - t2 * t7 - T(6) * t1 * c * t2;
  const T g_ap = (T(1) / T(3)) * in.w[2] * t4 * t2 + (T(1) / T(2)) * t1 * in.w[1] * t2 + (T(1) / T(12)) * in.w[3] * t8 * t2 + in.w[0] * t0;
  const T g_ab = (T(1) / T(12)) * in.w[2] * t8 * t2 + (T(1) / T(3)) * in.w[1] * t4 * t2 + (T(1) / T(2)) * t1 * in.w[0] * t2 + (T(1) / T(30)) * in.w[3] * (T(5) * b * t8 * t2 - T(10) * c * t4 * t2 - (T(2) * (T(4) * t3 * D * t2 + T(3) * t5 * slope0 - T(3) * t6 * slope1) * t2 + T(5) * b * t2 * t7 - T(10) * c * t3 * t2) * t2) * t2;
  const T g_factor = -T(2) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 58 +, 137 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i2_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = in.t1 - in.t0;
  const T t1 = T(1) / a;
  const T t2 = T(2) * b * t0 + q1 - q0;
  const T t3 = T(2) * D * t0 + slope1 * q1 - slope0 * q0;
  const T t4 = T(3) * b * t1 * t2 + t3 * t1 - T(3) * c * t0;
  const T t5 = q1 * q1;
  const T t6 = q0 * q0;
  const T t7 = T(3) * t5 + T(4) * b * t3 * t1 - T(3) * t6;
  const T t8 = T(6) * t1 * t2 * c - t1 * t7 - T(8) * b * t4 * t1;
  const T g_ap = t0 * in.w[0] + (T(1) / T(2)) * in.w[1] * t1 * t2 + (T(1) / T(3)) * t4 * t1 * in.w[2] - (T(1) / T(12)) * t1 * t8 * in.w[3];
  const T t9 = T(4) * t3 * D * t1 + T(3) * slope1 * t5 - T(3) * slope0 * t6;
  const T t10 = T(5) * b * t1 * t7 + T(2) * t9 * t1 - T(10) * t3 * t1 * c;
  const T g_ab = (T(1) / T(30)) * t1 * in.w[3] * (t10 * t1 - T(10) * t4 * t1 * c - T(5) * b * t1 * t8) + (T(1) / T(3)) * in.w[1] * t4 * t1 + (T(1) / T(2)) * t1 * t2 * in.w[0] - (T(1) / T(12)) * t1 * in.w[2] * t8;
  const T g_factor = -T(2) * length * inv_R2;
  const T t11 = t5 * q1;
  const T t12 = t6 * q0;
  f = (T(1) / T(60)) * length * (T(5) * in.w[1] * t1 * t7 + T(20) * t3 * t1 * in.w[0] + t1 * (T(4) * b * t10 * t1 + T(2) * t1 * (T(2) * b * t9 * t1 + T(5) * t11 - T(5) * t12) - T(5) * t1 * c * t7) * in.w[3] + T(2) * t10 * t1 * in.w[2]);
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 30 +, 47 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  f = (T(1) / T(8)) * in.w[0] * length * (T(2) * slope1 * r1 * q1 - T(3) * (r0 * slope0 - J1 * D - slope1 * r1) * D * t1 - T(2) * r0 * q0 * slope0) * t1;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 33 +, 58 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = slope1 * r1 + J1 * D - slope0 * r0;
  const T t3 = T(1) / a;
  const T g_ap = (T(1) / T(2)) * t2 * t3 * in.w[0];
  const T g_ab = (T(1) / T(6)) * t3 * (T(2) * q1 * r1 + T(3) * b * t2 * t3 - T(2) * r0 * q0) * in.w[0];
  const T g_factor = -T(3) * length * inv_R2;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 35 +, 71 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = slope0 * r0 - r1 * slope1 - J1 * D;
  const T t3 = T(1) / a;
  const T g_ap = -(T(1) / T(2)) * t2 * in.w[0] * t3;
  const T g_ab = -(T(1) / T(6)) * in.w[0] * (T(3) * t2 * b * t3 + T(2) * q0 * r0 - T(2) * r1 * q1) * t3;
  const T g_factor = -T(3) * inv_R2 * length;
  f = (T(1) / T(8)) * in.w[0] * length * (T(2) * r1 * q1 * slope1 - T(3) * t2 * D * t3 - T(2) * q0 * slope0 * r0) * t3;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 33 +, 59 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = T(2) * slope1 * r1 * q1 + T(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t1 - T(2) * r0 * q0 * slope0;
  f = -(T(1) / T(40)) * (in.w[1] * (T(8) * r0 * q0 * q0 - T(8) * r1 * q1 * q1 - T(5) * t2 * b * t1) * t1 - T(5) * t2 * in.w[0] * t1) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 39 +, 81 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = slope0 * r0 - J1 * D - r1 * slope1;
  const T t4 = T(3) * b * t2 * t3 + T(2) * q0 * r0 - T(2) * r1 * q1;
  const T g_ap = -(T(1) / T(2)) * t2 * in.w[0] * t3 - (T(1) / T(6)) * t4 * in.w[1] * t2;
  const T g_ab = (T(1) / T(24)) * in.w[1] * (T(12) * c * t2 * t3 - T(3) * (T(2) * q0 * slope0 * r0 + T(3) * D * t2 * t3 - T(2) * r1 * q1 * slope1) * t2 - T(8) * t4 * b * t2) * t2 - (T(1) / T(6)) * t4 * t2 * in.w[0];
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 42 +, 97 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = J1 * D + slope1 * r1 - slope0 * r0;
  const T t4 = T(2) * q0 * r0 - T(2) * q1 * r1 - T(3) * b * t2 * t3;
  const T g_ap = (T(1) / T(2)) * t2 * t3 * in.w[0] - (T(1) / T(6)) * t2 * t4 * in.w[1];
  const T t5 = T(2) * q1 * slope1 * r1 + T(3) * D * t2 * t3 - T(2) * q0 * slope0 * r0;
  const T g_ab = -(T(1) / T(6)) * t2 * t4 * in.w[0] - (T(1) / T(24)) * t2 * (T(12) * t2 * t3 * c + T(8) * b * t2 * t4 - T(3) * t5 * t2) * in.w[1];
  const T g_factor = -T(3) * length * inv_R2;
  f = (T(1) / T(40)) * length * (t2 * (T(5) * t5 * b * t2 + T(8) * q1 * q1 * r1 - T(8) * q0 * q0 * r0) * in.w[1] + T(5) * t5 * t2 * in.w[0]);
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 38 +, 79 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(2) * q0 * slope0 * r0 - T(2) * q1 * slope1 * r1 - T(3) * D * t2 * (slope1 * r1 + J1 * D - slope0 * r0);
  const T t4 = q0 * q0;
  const T t5 = q1 * q1;
  const T t6 = T(5) * b * t2 * t3 + T(8) * t4 * r0 - T(8) * t5 * r1;
  f = -(T(1) / T(240)) * length * (t2 * (T(5) * (T(5) * D * t2 * t3 + T(8) * t4 * slope0 * r0 - T(8) * t5 * slope1 * r1) * t2 + T(12) * b * t6 * t2 - T(30) * t2 * t3 * c) * in.w[2] + T(30) * in.w[0] * t2 * t3 + T(6) * t6 * t2 * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 45 +, 104 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = slope0 * r0 - J1 * D - r1 * slope1;
  const T t3 = T(1) / a;
  const T t4 = T(2) * r1 * q1 - T(3) * b * t2 * t3 - T(2) * q0 * r0;
  const T t5 = T(2) * q0 * slope0 * r0 + T(3) * t2 * D * t3 - T(2) * r1 * q1 * slope1;
  const T t6 = T(8) * t4 * b * t3 + T(12) * c * t2 * t3 - T(3) * t5 * t3;
  const T g_ap = (T(1) / T(24)) * in.w[2] * t6 * t3 + (T(1) / T(6)) * t4 * t3 * in.w[1] - (T(1) / T(2)) * in.w[0] * t2 * t3;
  const T g_ab = (T(1) / T(24)) * t6 * t3 * in.w[1] + (T(1) / T(6)) * t4 * in.w[0] * t3 - (T(1) / T(120)) * in.w[2] * (T(3) * (T(8) * q0 * q0 * r0 + T(5) * t5 * b * t3 - T(8) * r1 * q1 * q1) * t3 + T(20) * c * t4 * t3 - T(10) * b * t6 * t3) * t3;
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 51 +, 131 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = J1 * D + r1 * slope1 - slope0 * r0;
  const T t4 = T(3) * t3 * D * t2 + T(2) * r1 * q1 * slope1 - T(2) * q0 * slope0 * r0;
  const T t5 = T(3) * t3 * b * t2 + T(2) * r1 * q1 - T(2) * q0 * r0;
  const T t6 = T(3) * t2 * t4 + T(8) * b * t2 * t5 - T(12) * t3 * t2 * c;
  const T g_ap = (T(1) / T(24)) * in.w[2] * t6 * t2 + (T(1) / T(2)) * t3 * in.w[0] * t2 + (T(1) / T(6)) * t2 * t5 * in.w[1];
  const T t7 = q0 * q0;
  const T t8 = q1 * q1;
  const T t9 = T(8) * t7 * r0 - T(5) * b * t2 * t4 - T(8) * r1 * t8;
  const T g_ab = (T(1) / T(24)) * t6 * t2 * in.w[1] + (T(1) / T(120)) * (T(10) * t6 * b * t2 - T(3) * t9 * t2 - T(20) * t2 * t5 * c) * in.w[2] * t2 + (T(1) / T(6)) * in.w[0] * t2 * t5;
  const T g_factor = -T(3) * inv_R2 * length;
  f = (T(1) / T(240)) * ((T(5) * t2 * (T(8) * r1 * t8 * slope1 + T(5) * D * t2 * t4 - T(8) * t7 * slope0 * r0) - T(12) * t9 * b * t2 - T(30) * t2 * t4 * c) * in.w[2] * t2 + T(30) * in.w[0] * t2 * t4 - T(6) * t9 * t2 * in.w[1]) * length;
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 43 +, 99 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(2) * q0 * slope0 * r0 - T(2) * r1 * q1 * slope1 - T(3) * D * t2 * (r1 * slope1 + J1 * D - slope0 * r0);
  const T t4 = q0 * q0;
  const T t5 = q1 * q1;
  const T t6 = T(8) * t4 * r0 + T(5) * t3 * b * t2 - T(8) * r1 * t5;
  const T t7 = T(8) * r1 * t5 * slope1 - T(5) * t3 * D * t2 - T(8) * t4 * slope0 * r0;
  const T t8 = T(12) * t6 * b * t2 - T(5) * t7 * t2 - T(30) * c * t3 * t2;
  const T t9 = t5 * q1;
  const T t10 = t4 * q0;
  f = -(T(1) / T(1680)) * length * (T(210) * in.w[0] * t3 * t2 + T(7) * t8 * t2 * in.w[2] + T(42) * t6 * in.w[1] * t2 - in.w[3] * (T(42) * c * t6 * t2 + T(5) * (T(48) * r1 * t9 + T(7) * b * t7 * t2 - T(48) * t10 * r0) * t2 - T(14) * b * t8 * t2) * t2);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 53 +, 134 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = D * J1 + slope1 * r1 - slope0 * r0;
  const T t2 = T(2) * slope1 * r1 * q1 + T(3) * D * t0 * t1 - T(2) * slope0 * r0 * q0;
  const T t3 = T(2) * r1 * q1 + T(3) * t0 * t1 * b - T(2) * r0 * q0;
  const T t4 = T(3) * t2 * t0 + T(8) * t0 * b * t3 - T(12) * t0 * t1 * c;
  const T t5 = q0 * q0;
  const T t6 = q1 * q1;
  const T t7 = T(8) * r0 * t5 - T(8) * r1 * t6 - T(5) * t2 * t0 * b;
  const T t8 = T(3) * t0 * t7 + T(20) * t0 * c * t3 - T(10) * t0 * t4 * b;
  const T g_ap = (T(1) / T(2)) * t0 * t1 * in.w[0] + (T(1) / T(24)) * t0 * in.w[2] * t4 + (T(1) / T(6)) * t0 * in.w[1] * t3 - (T(1) / T(120)) * t8 * t0 * in.w[3];
  const T g_ab = (T(1) / T(6)) * t0 * in.w[0] * t3 + (T(1) / T(24)) * t0 * t4 * in.w[1] - (T(1) / T(240)) * t0 * (T(4) * t8 * t0 * b + T(10) * t0 * c * t4 + t0 * (T(12) * t0 * t7 * b + T(30) * t2 * t0 * c - T(5) * (T(5) * t2 * D * t0 + T(8) * slope1 * r1 * t6 - T(8) * slope0 * r0 * t5) * t0)) * in.w[3] - (T(1) / T(120)) * t8 * t0 * in.w[2];
  const T g_factor = -T(3) * length * inv_R2;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 60 +, 164 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i3_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = slope1 * r1 + J1 * D - slope0 * r0;
  const T t3 = T(1) / a;
  const T t4 = q1 * q1;
  const T t5 = T(2) * q0 * slope0 * r0 - T(3) * t2 * D * t3 - T(2) * q1 * slope1 * r1;
  const T t6 = q0 * q0;
  const T t7 = T(8) * t4 * r1 - T(5) * t5 * b * t3 - T(8) * t6 * r0;
  const T t8 = T(2) * q0 * r0 - T(2) * q1 * r1 - T(3) * b * t2 * t3;
  const T t9 = T(12) * t2 * t3 * c + T(8) * b * t8 * t3 + T(3) * t5 * t3;
  const T t10 = T(3) * t7 * t3 + T(20) * t8 * t3 * c - T(10) * t9 * b * t3;
  const T g_ap = (T(1) / T(2)) * t2 * t3 * in.w[0] + (T(1) / T(120)) * in.w[3] * t10 * t3 - (T(1) / T(24)) * t9 * t3 * in.w[2] - (T(1) / T(6)) * in.w[1] * t8 * t3;
  const T t11 = T(8) * t4 * slope1 * r1 - T(5) * t5 * D * t3 - T(8) * t6 * slope0 * r0;
  const T t12 = T(12) * b * t7 * t3 + T(30) * t5 * t3 * c + T(5) * t11 * t3;
  const T g_ab = (T(1) / T(240)) * in.w[3] * t3 * (t3 * t12 + T(4) * t10 * b * t3 + T(10) * t9 * t3 * c) + (T(1) / T(120)) * t10 * t3 * in.w[2] - (T(1) / T(24)) * t9 * in.w[1] * t3 - (T(1) / T(6)) * t8 * t3 * in.w[0];
  const T g_factor = -T(3) * length * inv_R2;
  const T t13 = t4 * q1;
  const T t14 = t6 * q0;
  f = (T(1) / T(1680)) * length * (T(42) * in.w[1] * t7 * t3 + T(7) * t3 * in.w[2] * t12 + in.w[3] * t3 * (T(5) * t3 * (T(48) * t13 * r1 + T(7) * b * t11 * t3 - T(48) * t14 * r0) + T(14) * b * t3 * t12 - T(42) * t7 * t3 * c) - T(210) * t5 * t3 * in.w[0]);
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 30 +, 45 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  f = -(T(1) / T(15)) * (T(4) * (q0 * slope0 - q1 * slope1 - T(2) * (in.t1 - in.t0) * D) * D * t0 + T(3) * q0 * q0 * slope0 - T(3) * q1 * q1 * slope1) * in.w[0] * length * t0;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 33 +, 56 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i4_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0;
  const T g_ap = (T(1) / T(3)) * in.w[0] * t0 * t1;
  const T g_ab = (T(1) / T(12)) * in.w[0] * t0 * (T(3) * q1 * q1 + T(4) * b * t0 * t1 - T(3) * q0 * q0);
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - ap0 * g_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 35 +, 67 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T t0 = T(1) / a;
  const T t1 = slope0 * q0 - slope1 * q1 - T(2) * D * (in.t1 - in.t0);
  const T g_ap = -(T(1) / T(3)) * t0 * in.w[0] * t1;
  const T t2 = q1 * q1;
  const T t3 = q0 * q0;
  const T g_ab = (T(1) / T(12)) * t0 * (T(3) * t2 - T(3) * t3 - T(4) * t0 * t1 * b) * in.w[0];
  const T g_factor = -T(4) * length * inv_R2;
  f = -(T(1) / T(15)) * (T(4) * D * t0 * t1 + T(3) * slope0 * t3 - T(3) * slope1 * t2) * length * t0 * in.w[0];
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 33 +, 56 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = T(3) * t1 * slope1 - T(4) * t0 * (slope0 * q0 + T(2) * (in.t0 - in.t1) * D - q1 * slope1) * D - T(3) * slope0 * q0 * q0;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  f = (T(1) / T(30)) * (t0 * (T(5) * t2 + T(2) * t0 * b * t3 - T(5) * t5) * in.w[1] + T(2) * t0 * in.w[0] * t3) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 39 +, 77 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i4_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0;
  const T t2 = q0 * q0;
  const T t3 = q1 * q1;
  const T t4 = T(3) * t2 - T(4) * t0 * t1 * b - T(3) * t3;
  const T g_ap = (T(1) / T(3)) * t0 * in.w[0] * t1 - (T(1) / T(12)) * t0 * in.w[1] * t4;
  const T g_ab = -(T(1) / T(12)) * t0 * in.w[0] * t4 - (T(1) / T(30)) * t0 * (T(2) * t0 * (T(3) * t2 * slope0 - T(3) * t3 * slope1 - T(4) * t0 * t1 * D) + T(10) * t0 * c * t1 + T(5) * t0 * t4 * b) * in.w[1];
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 42 +, 91 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = q0 * q0;
  const T t2 = q0 * slope0 - q1 * slope1 - T(2) * D * (in.t1 - in.t0);
  const T t3 = T(1) / a;
  const T t4 = T(3) * t0 - T(3) * t1 - T(4) * t2 * b * t3;
  const T g_ap = (T(1) / T(12)) * in.w[1] * t4 * t3 - (T(1) / T(3)) * t2 * t3 * in.w[0];
  const T t5 = T(3) * t0 * slope1 - T(4) * t2 * D * t3 - T(3) * t1 * slope0;
  const T g_ab = (T(1) / T(12)) * t4 * t3 * in.w[0] + (T(1) / T(30)) * (T(5) * t4 * b * t3 + T(10) * t2 * c * t3 + T(2) * t5 * t3) * in.w[1] * t3;
  const T g_factor = -T(4) * inv_R2 * length;
  const T t6 = t0 * q1;
  const T t7 = t1 * q0;
  f = (T(1) / T(30)) * (in.w[1] * t3 * (T(2) * t5 * b * t3 + T(5) * t6 - T(5) * t7) + T(2) * t5 * t3 * in.w[0]) * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 38 +, 75 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = T(3) * t1 * slope0 - T(3) * q1 * q1 * slope1 - T(4) * t0 * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = T(5) * t2 + T(2) * t0 * t3 * b - T(5) * t5;
  f = -(T(1) / T(210)) * (T(2) * t0 * (T(7) * t6 * t0 * b + T(3) * t0 * (T(5) * t2 * slope0 + T(2) * t0 * t3 * D - T(5) * t5 * slope1) - T(7) * t0 * c * t3) * in.w[2] + T(7) * t6 * t0 * in.w[1] + T(14) * t0 * t3 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 45 +, 98 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i4_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = slope0 * q0 - T(2) * D * (in.t1 - in.t0) - q1 * slope1;
  const T t3 = q0 * q0;
  const T t4 = T(3) * t1 - T(4) * t0 * t2 * b - T(3) * t3;
  const T t5 = T(3) * slope0 * t3 + T(4) * D * t0 * t2 - T(3) * t1 * slope1;
  const T t6 = T(2) * t0 * t5 - T(10) * t0 * t2 * c - T(5) * t0 * t4 * b;
  const T g_ap = (T(1) / T(12)) * t0 * in.w[1] * t4 - (T(1) / T(30)) * t0 * t6 * in.w[2] - (T(1) / T(3)) * in.w[0] * t0 * t2;
  const T t7 = t1 * q1;
  const T t8 = t3 * q0;
  const T g_ab = (T(1) / T(12)) * in.w[0] * t0 * t4 - (T(1) / T(60)) * t0 * (T(5) * t0 * t4 * c + T(4) * t0 * t6 * b - T(2) * t0 * (T(5) * t7 - T(2) * t0 * t5 * b - T(5) * t8)) * in.w[2] - (T(1) / T(30)) * t0 * in.w[1] * t6;
  const T g_factor = -T(4) * length * inv_R2;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 51 +, 124 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0;
  const T t2 = q1 * q1;
  const T t3 = q0 * q0;
  const T t4 = T(4) * t0 * t1 * D + T(3) * t2 * slope1 - T(3) * t3 * slope0;
  const T t5 = T(3) * t3 - T(4) * t0 * b * t1 - T(3) * t2;
  const T t6 = T(2) * t0 * t4 - T(10) * t0 * c * t1 - T(5) * t0 * t5 * b;
  const T g_ap = (T(1) / T(3)) * t0 * t1 * in.w[0] + (T(1) / T(30)) * t0 * in.w[2] * t6 - (T(1) / T(12)) * t0 * in.w[1] * t5;
  const T t7 = t3 * q0;
  const T t8 = t2 * q1;
  const T t9 = T(5) * t7 - T(2) * t0 * t4 * b - T(5) * t8;
  const T g_ab = (T(1) / T(60)) * t0 * in.w[2] * (T(4) * t0 * t6 * b + T(5) * t0 * t5 * c - T(2) * t0 * t9) + (T(1) / T(30)) * t0 * in.w[1] * t6 - (T(1) / T(12)) * t0 * t5 * in.w[0];
  const T g_factor = -T(4) * inv_R2 * length;
  f = -(T(1) / T(210)) * (T(2) * t0 * (T(7) * t0 * c * t4 + T(3) * t0 * (T(5) * t7 * slope0 - T(5) * t8 * slope1 - T(2) * t0 * t4 * D) + T(7) * t0 * t9 * b) * in.w[2] + T(7) * t0 * t9 * in.w[1] - T(14) * t0 * t4 * in.w[0]) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 43 +, 91 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = T(1) / a;
  const T t3 = t0 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = T(3) * slope1 * t4 - T(3) * slope0 * t0 - T(4) * D * t2 * (T(2) * D * (in.t0 - in.t1) + slope0 * q0 - slope1 * q1);
  const T t7 = T(5) * slope0 * t3 - T(5) * slope1 * t5 - T(2) * D * t2 * t6;
  const T t8 = t4 * t4;
  const T t9 = T(5) * t5 + T(2) * b * t2 * t6 - T(5) * t3;
  const T t10 = T(7) * b * t2 * t9 - T(3) * t2 * t7 - T(7) * t2 * t6 * c;
  f = -(T(1) / T(840)) * length * ((T(3) * (T(35) * t1 + T(8) * b * t2 * t7 - T(35) * t8) * t2 + T(28) * t2 * c * t9 - T(16) * b * t2 * t10) * t2 * in.w[3] - T(8) * t2 * in.w[2] * t10 - T(28) * in.w[1] * t2 * t9 - T(56) * t2 * t6 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 53 +, 127 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i4_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = q0 * q0;
  const T t4 = T(4) * t0 * b * t1 + T(3) * t2 - T(3) * t3;
  const T t5 = t2 * q1;
  const T t6 = t3 * q0;
  const T t7 = T(3) * t3 * slope0 - T(4) * t0 * D * t1 - T(3) * t2 * slope1;
  const T t8 = T(5) * t5 - T(5) * t6 - T(2) * b * t7 * t1;
  const T t9 = T(10) * t0 * c * t1 + T(2) * t7 * t1 - T(5) * b * t4 * t1;
  const T t10 = T(2) * t8 * t1 - T(5) * c * t4 * t1 - T(4) * b * t9 * t1;
  const T g_ap = (T(1) / T(3)) * t0 * in.w[0] * t1 + (T(1) / T(12)) * in.w[1] * t4 * t1 + (T(1) / T(60)) * in.w[3] * t1 * t10 - (T(1) / T(30)) * in.w[2] * t9 * t1;
  const T g_ab = (T(1) / T(60)) * in.w[2] * t1 * t10 + (T(1) / T(12)) * in.w[0] * t4 * t1 + (T(1) / T(210)) * (T(7) * b * t1 * t10 + T(2) * (T(7) * t8 * b * t1 + T(7) * c * t7 * t1 - T(3) * (T(2) * t7 * D * t1 + T(5) * t6 * slope0 - T(5) * t5 * slope1) * t1) * t1 + T(7) * c * t9 * t1) * in.w[3] * t1 - (T(1) / T(30)) * in.w[1] * t9 * t1;
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 60 +, 155 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i4_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = slope1 * q1 + T(2) * (in.t1 - in.t0) * D - slope0 * q0;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = q0 * q0;
  const T t4 = T(4) * t0 * b * t1 + T(3) * t2 - T(3) * t3;
  const T t5 = T(3) * slope1 * t2 + T(4) * t0 * D * t1 - T(3) * slope0 * t3;
  const T t6 = T(10) * t0 * t1 * c - T(2) * t1 * t5 - T(5) * b * t1 * t4;
  const T t7 = t2 * q1;
  const T t8 = t3 * q0;
  const T t9 = T(2) * b * t1 * t5 + T(5) * t7 - T(5) * t8;
  const T t10 = T(4) * b * t1 * t6 + T(5) * t1 * t4 * c - T(2) * t1 * t9;
  const T g_ap = (T(1) / T(3)) * in.w[0] * t0 * t1 + (T(1) / T(12)) * in.w[1] * t1 * t4 - (T(1) / T(60)) * t10 * t1 * in.w[3] - (T(1) / T(30)) * t1 * in.w[2] * t6;
  const T t11 = T(5) * slope1 * t7 + T(2) * D * t1 * t5 - T(5) * slope0 * t8;
  const T t12 = T(7) * t1 * c * t5 - T(7) * b * t1 * t9 - T(3) * t1 * t11;
  const T g_ab = (T(1) / T(12)) * in.w[0] * t1 * t4 - (T(1) / T(210)) * (T(2) * t12 * t1 + T(7) * b * t10 * t1 - T(7) * t1 * c * t6) * t1 * in.w[3] - (T(1) / T(30)) * in.w[1] * t1 * t6 - (T(1) / T(60)) * t10 * t1 * in.w[2];
  const T g_factor = -T(4) * length * inv_R2;
  const T t13 = t3 * t3;
  const T t14 = t2 * t2;
  f = (T(1) / T(840)) * length * (T(56) * in.w[0] * t1 * t5 + T(28) * in.w[1] * t1 * t9 - T(8) * t12 * t1 * in.w[2] - (T(3) * (T(35) * t13 - T(8) * b * t1 * t11 - T(35) * t14) * t1 + T(16) * t12 * b * t1 + T(28) * t1 * t9 * c) * t1 * in.w[3]);
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 32 +, 58 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  f = (T(1) / T(48)) * t1 * in.w[0] * (T(8) * slope1 * r1 * q1 * q1 + T(5) * t1 * (T(2) * slope1 * r1 * q1 + T(3) * t1 * D * (slope1 * r1 + J1 * D - r0 * slope0) - T(2) * r0 * q0 * slope0) * D - T(8) * r0 * q0 * q0 * slope0) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 35 +, 69 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = T(2) * slope1 * r1 * q1 + T(3) * t1 * (J1 * D + slope1 * r1 - r0 * slope0) * D - T(2) * r0 * q0 * slope0;
  const T g_ap = (T(1) / T(8)) * t1 * t2 * in.w[0];
  const T g_ab = (T(1) / T(40)) * t1 * (T(8) * r1 * q1 * q1 + T(5) * b * t1 * t2 - T(8) * r0 * q0 * q0) * in.w[0];
  const T g_factor = -T(5) * length * inv_R2;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 37 +, 82 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = T(2) * slope0 * r0 * q0 + T(3) * (slope0 * r0 - slope1 * r1 - D * J1) * D * t0 - T(2) * slope1 * r1 * q1;
  const T g_ap = -(T(1) / T(8)) * t0 * in.w[0] * t1;
  const T t2 = q0 * q0;
  const T t3 = q1 * q1;
  const T g_ab = -(T(1) / T(40)) * (T(8) * r0 * t2 + T(5) * t0 * t1 * b - T(8) * r1 * t3) * t0 * in.w[0];
  const T g_factor = -T(5) * length * inv_R2;
  f = -(T(1) / T(48)) * (T(5) * D * t0 * t1 + T(8) * slope0 * r0 * t2 - T(8) * slope1 * r1 * t3) * length * t0 * in.w[0];
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 35 +, 72 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = T(8) * slope1 * r1 * q1 * q1 + T(5) * D * t1 * (T(2) * slope1 * r1 * q1 + T(3) * D * t1 * (slope1 * r1 + D * J1 - r0 * slope0) - T(2) * r0 * q0 * slope0) - T(8) * r0 * q0 * q0 * slope0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  f = (T(1) / T(336)) * (t1 * (T(7) * t1 * t2 * b + T(48) * r1 * t4 - T(48) * r0 * t6) * in.w[1] + T(7) * t1 * in.w[0] * t2) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 41 +, 92 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = q1 * q1;
  const T t2 = T(1) / a;
  const T t3 = T(2) * slope1 * r1 * q1 + T(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t2 - T(2) * r0 * q0 * slope0;
  const T t4 = q0 * q0;
  const T t5 = T(8) * r1 * t1 + T(5) * t3 * b * t2 - T(8) * r0 * t4;
  const T g_ap = (T(1) / T(40)) * t5 * in.w[1] * t2 + (T(1) / T(8)) * in.w[0] * t3 * t2;
  const T g_ab = (T(1) / T(40)) * in.w[0] * t5 * t2 - (T(1) / T(240)) * in.w[1] * (T(5) * (T(8) * r0 * t4 * slope0 - T(8) * slope1 * r1 * t1 - T(5) * t3 * D * t2) * t2 + T(30) * c * t3 * t2 - T(12) * t5 * b * t2) * t2;
  const T g_factor = -T(5) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 44 +, 108 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(2) * q0 * slope0 * r0 - T(2) * r1 * q1 * slope1 - T(3) * (J1 * D + r1 * slope1 - slope0 * r0) * D * t2;
  const T t4 = q0 * q0;
  const T t5 = q1 * q1;
  const T t6 = T(8) * t4 * r0 + T(5) * b * t2 * t3 - T(8) * r1 * t5;
  const T g_ap = -(T(1) / T(8)) * t2 * in.w[0] * t3 - (T(1) / T(40)) * in.w[1] * t2 * t6;
  const T t7 = T(8) * t4 * slope0 * r0 + T(5) * D * t2 * t3 - T(8) * r1 * t5 * slope1;
  const T g_ab = -(T(1) / T(240)) * in.w[1] * (T(5) * t2 * t7 + T(12) * b * t2 * t6 - T(30) * t2 * c * t3) * t2 - (T(1) / T(40)) * t2 * in.w[0] * t6;
  const T g_factor = -T(5) * length * inv_R2;
  const T t8 = t5 * q1;
  const T t9 = t4 * q0;
  f = (T(1) / T(336)) * (in.w[1] * (T(48) * r1 * t8 - T(7) * b * t2 * t7 - T(48) * t9 * r0) * t2 - T(7) * t2 * in.w[0] * t7) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 40 +, 90 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = T(8) * t5 * slope0 * r0 - T(5) * (T(2) * q1 * slope1 * r1 + T(3) * D * (slope1 * r1 + J1 * D - slope0 * r0) * t2 - T(2) * q0 * slope0 * r0) * D * t2 - T(8) * t3 * slope1 * r1;
  const T t8 = T(48) * t4 * r1 - T(48) * t6 * r0 - T(7) * b * t2 * t7;
  f = (T(1) / T(2688)) * length * (in.w[2] * t2 * (T(16) * b * t8 * t2 + T(56) * t2 * c * t7 - T(7) * t2 * (T(48) * t6 * slope0 * r0 + T(7) * D * t2 * t7 - T(48) * t4 * slope1 * r1)) + T(8) * t8 * t2 * in.w[1] - T(56) * in.w[0] * t2 * t7);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 47 +, 115 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(3) * (slope1 * r1 + D * J1 - slope0 * r0) * D * t2 + T(2) * q1 * slope1 * r1 - T(2) * slope0 * r0 * q0;
  const T t4 = q1 * q1;
  const T t5 = q0 * q0;
  const T t6 = T(5) * t3 * b * t2 + T(8) * t4 * r1 - T(8) * r0 * t5;
  const T t7 = T(8) * t4 * slope1 * r1 + T(5) * t3 * D * t2 - T(8) * slope0 * r0 * t5;
  const T t8 = T(30) * t3 * t2 * c - T(12) * b * t2 * t6 - T(5) * t2 * t7;
  const T g_ap = (T(1) / T(40)) * t2 * in.w[1] * t6 + (T(1) / T(8)) * t3 * in.w[0] * t2 - (T(1) / T(240)) * t8 * t2 * in.w[2];
  const T t9 = t4 * q1;
  const T t10 = t5 * q0;
  const T g_ab = (T(1) / T(40)) * in.w[0] * t2 * t6 - (T(1) / T(240)) * t8 * t2 * in.w[1] - (T(1) / T(1680)) * (T(14) * b * t8 * t2 + T(42) * t2 * c * t6 - T(5) * (T(7) * b * t2 * t7 + T(48) * t9 * r1 - T(48) * r0 * t10) * t2) * t2 * in.w[2];
  const T g_factor = -T(5) * length * inv_R2;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 53 +, 142 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(3) * D * (J1 * D + slope1 * r1 - slope0 * r0) * t2 + T(2) * q1 * slope1 * r1 - T(2) * q0 * slope0 * r0;
  const T t4 = q1 * q1;
  const T t5 = q0 * q0;
  const T t6 = T(5) * b * t2 * t3 + T(8) * t4 * r1 - T(8) * t5 * r0;
  const T t7 = T(8) * t4 * slope1 * r1 + T(5) * D * t2 * t3 - T(8) * t5 * slope0 * r0;
  const T t8 = T(12) * b * t6 * t2 + T(5) * t7 * t2 - T(30) * t2 * t3 * c;
  const T g_ap = (T(1) / T(8)) * in.w[0] * t2 * t3 + (T(1) / T(40)) * t6 * t2 * in.w[1] + (T(1) / T(240)) * t2 * in.w[2] * t8;
  const T t9 = t4 * q1;
  const T t10 = t5 * q0;
  const T t11 = T(7) * b * t7 * t2 + T(48) * t9 * r1 - T(48) * t10 * r0;
  const T g_ab = (T(1) / T(240)) * t2 * in.w[1] * t8 + (T(1) / T(1680)) * t2 * in.w[2] * (T(14) * b * t2 * t8 + T(5) * t2 * t11 - T(42) * t6 * t2 * c) + (T(1) / T(40)) * in.w[0] * t6 * t2;
  const T g_factor = -T(5) * length * inv_R2;
  f = -(T(1) / T(2688)) * ((T(56) * t7 * t2 * c - T(7) * (T(7) * t7 * D * t2 + T(48) * t9 * slope1 * r1 - T(48) * t10 * slope0 * r0) * t2 - T(16) * b * t2 * t11) * t2 * in.w[2] - T(8) * t2 * t11 * in.w[1] - T(56) * t7 * in.w[0] * t2) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 45 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(8) * r1 * q1 * q1 * slope1 - T(8) * r0 * q0 * q0 * slope0 - T(5) * (T(2) * r0 * q0 * slope0 - T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * t2 * D - T(2) * r1 * q1 * slope1) * t2 * D;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = T(7) * t3 * b * t2 + T(48) * r1 * t5 - T(48) * r0 * t7;
  const T t9 = t4 * t4;
  const T t10 = T(48) * r1 * t5 * slope1 + T(7) * t3 * t2 * D - T(48) * r0 * t7 * slope0;
  const T t11 = t6 * t6;
  const T t12 = T(16) * b * t8 * t2 + T(7) * t10 * t2 - T(56) * c * t3 * t2;
  f = -(T(1) / T(8064)) * length * (in.w[3] * (T(24) * c * t8 * t2 - T(7) * (T(128) * r1 * t9 + T(3) * b * t10 * t2 - T(128) * r0 * t11) * t2 - T(6) * b * t12 * t2) * t2 - T(3) * t12 * t2 * in.w[2] - T(168) * t3 * in.w[0] * t2 - T(24) * t8 * in.w[1] * t2);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 55 +, 146 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = T(2) * slope0 * r0 * q0 - T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) - T(2) * slope1 * r1 * q1;
  const T t3 = q0 * q0;
  const T t4 = T(8) * slope1 * r1 * t1 - T(5) * D * t0 * t2 - T(8) * slope0 * r0 * t3;
  const T t5 = t1 * q1;
  const T t6 = t3 * q0;
  const T t7 = T(7) * t0 * t4 * b + T(48) * r1 * t5 - T(48) * r0 * t6;
  const T t8 = T(8) * r0 * t3 + T(5) * t0 * t2 * b - T(8) * r1 * t1;
  const T t9 = T(12) * t0 * b * t8 - T(30) * t0 * t2 * c - T(5) * t0 * t4;
  const T t10 = T(5) * t7 * t0 + T(42) * t0 * c * t8 - T(14) * t0 * t9 * b;
  const T g_ap = (T(1) / T(1680)) * t0 * t10 * in.w[3] - (T(1) / T(240)) * t0 * t9 * in.w[2] - (T(1) / T(40)) * in.w[1] * t0 * t8 - (T(1) / T(8)) * t0 * t2 * in.w[0];
  const T g_ab = (T(1) / T(13440)) * t0 * (T(16) * t0 * t10 * b + T(56) * t0 * t9 * c - T(5) * t0 * (T(56) * t0 * c * t4 - T(16) * t7 * t0 * b - T(7) * (T(48) * slope1 * r1 * t5 + T(7) * D * t0 * t4 - T(48) * slope0 * r0 * t6) * t0)) * in.w[3] + (T(1) / T(1680)) * t0 * in.w[2] * t10 - (T(1) / T(240)) * in.w[1] * t0 * t9 - (T(1) / T(40)) * t0 * in.w[0] * t8;
  const T g_factor = -T(5) * length * inv_R2;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 62 +, 176 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i5_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = T(2) * q0 * slope0 * r0 - T(3) * D * (slope1 * r1 + J1 * D - slope0 * r0) * t2 - T(2) * q1 * slope1 * r1;
  const T t5 = q0 * q0;
  const T t6 = T(8) * t3 * r1 - T(5) * b * t4 * t2 - T(8) * t5 * r0;
  const T t7 = T(5) * t4 * D * t2 + T(8) * t5 * slope0 * r0 - T(8) * t3 * slope1 * r1;
  const T t8 = T(30) * t4 * t2 * c + T(12) * b * t2 * t6 - T(5) * t7 * t2;
  const T t9 = t3 * q1;
  const T t10 = t5 * q0;
  const T t11 = T(48) * t9 * r1 - T(48) * t10 * r0 - T(7) * b * t7 * t2;
  const T t12 = T(14) * b * t8 * t2 + T(5) * t2 * t11 - T(42) * t2 * t6 * c;
  const T g_ap = (T(1) / T(40)) * in.w[1] * t2 * t6 + (T(1) / T(240)) * t8 * t2 * in.w[2] + (T(1) / T(1680)) * in.w[3] * t12 * t2 - (T(1) / T(8)) * in.w[0] * t4 * t2;
  const T t13 = T(48) * t9 * slope1 * r1 - T(48) * t10 * slope0 * r0 - T(7) * t7 * D * t2;
  const T t14 = T(7) * t13 * t2 + T(16) * b * t2 * t11 + T(56) * t7 * t2 * c;
  const T g_ab = (T(1) / T(1680)) * t12 * t2 * in.w[2] + (T(1) / T(40)) * in.w[0] * t2 * t6 + (T(1) / T(240)) * in.w[1] * t8 * t2 + (T(1) / T(13440)) * in.w[3] * t2 * (T(16) * t12 * b * t2 + T(5) * t2 * t14 - T(56) * t8 * t2 * c);
  const T g_factor = -T(5) * inv_R2 * length;
  const T t15 = t5 * t5;
  const T t16 = t3 * t3;
  f = (T(1) / T(8064)) * (T(24) * in.w[1] * t2 * t11 + T(3) * t2 * in.w[2] * t14 - T(168) * in.w[0] * t7 * t2 - in.w[3] * (T(24) * t2 * c * t11 + T(7) * t2 * (T(128) * t15 * r0 - T(3) * t13 * b * t2 - T(128) * t16 * r1) - T(6) * b * t2 * t14) * t2) * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 32 +, 56 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  f = -(T(1) / T(35)) * length * in.w[0] * t0 * (T(2) * D * (T(3) * q0 * q0 * slope0 + T(4) * (q0 * slope0 + T(2) * D * (in.t0 - in.t1) - slope1 * q1) * D * t0 - T(3) * slope1 * q1 * q1) * t0 + T(5) * t2 * slope0 - T(5) * slope1 * t4);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 35 +, 67 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i6_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = T(3) * q0 * q0 * slope0 - T(4) * D * t0 * (q1 * slope1 + T(2) * D * (in.t1 - in.t0) - q0 * slope0) - T(3) * q1 * q1 * slope1;
  const T g_ap = -(T(1) / T(15)) * t0 * t1 * in.w[0];
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T g_ab = -(T(1) / T(30)) * t0 * (T(2) * t0 * t1 * b + T(5) * t3 - T(5) * t5) * in.w[0];
  const T g_factor = -T(6) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 37 +, 78 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = T(4) * (slope1 * q1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D * t0 + T(3) * slope1 * q1 * q1 - T(3) * q0 * q0 * slope0;
  const T g_ap = (T(1) / T(15)) * in.w[0] * t1 * t0;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T g_ab = (T(1) / T(30)) * in.w[0] * t0 * (T(2) * b * t1 * t0 + T(5) * t3 - T(5) * t5);
  const T g_factor = -T(6) * inv_R2 * length;
  f = -(T(1) / T(35)) * in.w[0] * (T(5) * t5 * slope0 - T(5) * slope1 * t3 - T(2) * t1 * D * t0) * length * t0;
  grad[0] = -(ab0 * g_ab - ap0 * g_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 35 +, 64 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t2 * q1;
  const T t5 = T(1) / a;
  const T t6 = t0 * q0;
  const T t7 = T(5) * slope1 * t4 - T(2) * D * t5 * (T(4) * D * t5 * (T(2) * D * (in.t0 - in.t1) + slope0 * q0 - slope1 * q1) + T(3) * slope0 * t0 - T(3) * slope1 * t2) - T(5) * slope0 * t6;
  f = -(T(1) / T(280)) * length * ((T(35) * t1 - T(35) * t3 - T(8) * t7 * b * t5) * t5 * in.w[1] - T(8) * t7 * t5 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 41 +, 87 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i6_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = T(1) / a;
  const T t3 = T(3) * slope1 * t0 - T(4) * D * t2 * (T(2) * D * (in.t0 - in.t1) + slope0 * q0 - slope1 * q1) - T(3) * slope0 * q0 * q0;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = T(5) * t1 + T(2) * t2 * t3 * b - T(5) * t5;
  const T g_ap = (T(1) / T(30)) * t6 * t2 * in.w[1] + (T(1) / T(15)) * t2 * t3 * in.w[0];
  const T g_ab = (T(1) / T(30)) * t6 * t2 * in.w[0] - (T(1) / T(105)) * t2 * (T(7) * t2 * t3 * c - T(3) * t2 * (T(5) * slope1 * t1 + T(2) * D * t2 * t3 - T(5) * slope0 * t5) - T(7) * t6 * t2 * b) * in.w[1];
  const T g_factor = -T(6) * length * inv_R2;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 44 +, 100 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(3) * slope0 * t3 - T(3) * t1 * slope1 - T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0);
  const T t6 = T(5) * t2 - T(5) * t4 - T(2) * t5 * t0 * b;
  const T g_ap = (T(1) / T(30)) * t0 * t6 * in.w[1] - (T(1) / T(15)) * t5 * t0 * in.w[0];
  const T t7 = T(5) * t2 * slope1 - T(2) * D * t5 * t0 - T(5) * slope0 * t4;
  const T g_ab = (T(1) / T(105)) * t0 * (T(3) * t0 * t7 + T(7) * t5 * t0 * c + T(7) * t0 * t6 * b) * in.w[1] + (T(1) / T(30)) * t0 * t6 * in.w[0];
  const T g_factor = -T(6) * inv_R2 * length;
  const T t8 = t3 * t3;
  const T t9 = t1 * t1;
  f = -(T(1) / T(280)) * (t0 * (T(35) * t8 - T(8) * t0 * t7 * b - T(35) * t9) * in.w[1] - T(8) * t0 * t7 * in.w[0]) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 40 +, 84 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(5) * t1 * slope1 + T(2) * (T(3) * t0 * slope1 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t2 - T(3) * q0 * q0 * slope0) * D * t2 - T(5) * t4 * slope0;
  const T t6 = t0 * t0;
  const T t7 = t3 * t3;
  const T t8 = T(35) * t7 - T(35) * t6 - T(8) * b * t5 * t2;
  f = (T(1) / T(2520)) * (T(72) * in.w[0] * t5 * t2 + T(2) * in.w[2] * (T(4) * (T(8) * t5 * D * t2 + T(35) * t6 * slope1 - T(35) * t7 * slope0) * t2 - T(9) * b * t8 * t2 - T(36) * c * t5 * t2) * t2 - T(9) * in.w[1] * t8 * t2) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 47 +, 109 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i6_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T t0 = T(1) / a;
  const T t1 = T(3) * slope1 * q1 * q1 + T(4) * (T(2) * D * (in.t1 - in.t0) + slope1 * q1 - slope0 * q0) * D * t0 - T(3) * slope0 * q0 * q0;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = T(5) * slope1 * t3 + T(2) * D * t0 * t1 - T(5) * slope0 * t5;
  const T t7 = T(5) * t3 + T(2) * t0 * t1 * b - T(5) * t5;
  const T t8 = T(3) * t0 * t6 + T(7) * t0 * t7 * b - T(7) * t0 * c * t1;
  const T g_ap = (T(1) / T(15)) * t0 * t1 * in.w[0] + (T(1) / T(105)) * t8 * t0 * in.w[2] + (T(1) / T(30)) * t0 * t7 * in.w[1];
  const T t9 = t2 * t2;
  const T t10 = t4 * t4;
  const T g_ab = (T(1) / T(840)) * t0 * in.w[2] * (T(16) * t8 * t0 * b + T(3) * (T(8) * t0 * t6 * b + T(35) * t9 - T(35) * t10) * t0 - T(28) * t0 * t7 * c) + (T(1) / T(105)) * t8 * t0 * in.w[1] + (T(1) / T(30)) * t0 * t7 * in.w[0];
  const T g_factor = -T(6) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 53 +, 134 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + slope1 * q1 - slope0 * q0) + T(3) * slope1 * t1 - T(3) * slope0 * q0 * q0;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = T(5) * t2 + T(2) * t0 * t3 * b - T(5) * t5;
  const T t7 = T(5) * slope1 * t2 + T(2) * D * t0 * t3 - T(5) * slope0 * t5;
  const T t8 = T(7) * t0 * c * t3 - T(3) * t0 * t7 - T(7) * t0 * t6 * b;
  const T g_ap = (T(1) / T(30)) * t0 * in.w[1] * t6 + (T(1) / T(15)) * in.w[0] * t0 * t3 - (T(1) / T(105)) * t0 * t8 * in.w[2];
  const T t9 = t4 * t4;
  const T t10 = t1 * t1;
  const T t11 = T(35) * t9 - T(8) * t0 * t7 * b - T(35) * t10;
  const T g_ab = (T(1) / T(30)) * in.w[0] * t0 * t6 - (T(1) / T(105)) * t0 * t8 * in.w[1] - (T(1) / T(840)) * t0 * (T(3) * t0 * t11 + T(16) * t0 * t8 * b + T(28) * t0 * t6 * c) * in.w[2];
  const T g_factor = -T(6) * length * inv_R2;
  f = -(T(1) / T(2520)) * length * (T(2) * (T(4) * (T(35) * slope0 * t9 - T(35) * slope1 * t10 - T(8) * D * t0 * t7) * t0 + T(36) * t0 * c * t7 + T(9) * t0 * t11 * b) * t0 * in.w[2] + T(9) * t0 * in.w[1] * t11 - T(72) * in.w[0] * t0 * t7);
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 45 +, 100 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(5) * t2 * slope1 - T(5) * t4 * slope0 - T(2) * (T(4) * D * (q0 * slope0 - q1 * slope1 - T(2) * (in.t1 - in.t0) * D) * t0 + T(3) * t3 * slope0 - T(3) * t1 * slope1) * D * t0;
  const T t6 = t1 * t1;
  const T t7 = t3 * t3;
  const T t8 = T(8) * t5 * D * t0 + T(35) * t6 * slope1 - T(35) * t7 * slope0;
  const T t9 = T(8) * t5 * b * t0 + T(35) * t6 - T(35) * t7;
  const T t10 = T(4) * t0 * t8 + T(9) * b * t9 * t0 - T(36) * t5 * c * t0;
  const T t11 = t7 * q0;
  const T t12 = t6 * q1;
  f = (T(1) / T(2520)) * length * (T(2) * t10 * t0 * in.w[2] + T(9) * in.w[1] * t9 * t0 + T(72) * t5 * in.w[0] * t0 - in.w[3] * t0 * (T(4) * t0 * (T(63) * t11 - T(63) * t12 - T(2) * b * t0 * t8) + T(9) * c * t9 * t0 - T(4) * t10 * b * t0));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 55 +, 136 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i6_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = T(4) * D * t0 * (slope0 * q0 - slope1 * q1 - T(2) * D * (in.t1 - in.t0)) + T(3) * slope0 * q0 * q0 - T(3) * slope1 * t1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = T(5) * slope1 * t2 - T(2) * D * t0 * t3 - T(5) * slope0 * t5;
  const T t7 = T(2) * b * t0 * t3 + T(5) * t5 - T(5) * t2;
  const T t8 = T(3) * t0 * t6 + T(7) * t0 * c * t3 - T(7) * b * t7 * t0;
  const T t9 = t4 * t4;
  const T t10 = t1 * t1;
  const T t11 = T(35) * t9 - T(35) * t10 - T(8) * b * t0 * t6;
  const T t12 = T(28) * t7 * t0 * c + T(16) * b * t0 * t8 - T(3) * t0 * t11;
  const T g_ap = (T(1) / T(105)) * t0 * in.w[2] * t8 + (T(1) / T(840)) * t12 * t0 * in.w[3] - (T(1) / T(15)) * t0 * t3 * in.w[0] - (T(1) / T(30)) * in.w[1] * t7 * t0;
  const T g_ab = (T(1) / T(1260)) * (T(3) * b * t12 * t0 - T(12) * t0 * c * t8 - (T(36) * t0 * c * t6 + T(4) * t0 * (T(35) * slope0 * t9 - T(35) * slope1 * t10 - T(8) * D * t0 * t6) + T(9) * b * t0 * t11) * t0) * t0 * in.w[3] + (T(1) / T(105)) * in.w[1] * t0 * t8 + (T(1) / T(840)) * t12 * t0 * in.w[2] - (T(1) / T(30)) * t7 * t0 * in.w[0];
  const T g_factor = -T(6) * length * inv_R2;
  grad[0] = (ap0 * g_ap - ab0 * g_ab) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 62 +, 163 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i6_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = T(1) / a;
  const T t5 = T(3) * t2 * slope0 + T(4) * D * t4 * (T(2) * (in.t0 - in.t1) * D + q0 * slope0 - slope1 * q1) - T(3) * slope1 * t0;
  const T t6 = T(5) * t1 - T(5) * t3 - T(2) * b * t4 * t5;
  const T t7 = t2 * t2;
  const T t8 = T(5) * t3 * slope0 + T(2) * D * t4 * t5 - T(5) * slope1 * t1;
  const T t9 = t0 * t0;
  const T t10 = T(35) * t7 + T(8) * b * t8 * t4 - T(35) * t9;
  const T t11 = T(3) * t8 * t4 - T(7) * t6 * b * t4 - T(7) * c * t4 * t5;
  const T t12 = T(28) * c * t6 * t4 + T(3) * t10 * t4 + T(16) * b * t11 * t4;
  const T g_ap = (T(1) / T(30)) * t6 * in.w[1] * t4 - (T(1) / T(840)) * t12 * in.w[3] * t4 - (T(1) / T(15)) * in.w[0] * t4 * t5 - (T(1) / T(105)) * t11 * t4 * in.w[2];
  const T t13 = T(8) * t8 * D * t4 + T(35) * t7 * slope0 - T(35) * slope1 * t9;
  const T t14 = T(4) * t13 * t4 + T(9) * b * t10 * t4 - T(36) * c * t8 * t4;
  const T g_ab = (T(1) / T(30)) * t6 * in.w[0] * t4 - (T(1) / T(1260)) * in.w[3] * t4 * (T(3) * t12 * b * t4 + t14 * t4 - T(12) * c * t11 * t4) - (T(1) / T(105)) * t11 * in.w[1] * t4 - (T(1) / T(840)) * t12 * t4 * in.w[2];
  const T g_factor = -T(6) * inv_R2 * length;
  const T t15 = t7 * q0;
  const T t16 = t9 * q1;
  f = -(T(1) / T(2520)) * (T(2) * t14 * t4 * in.w[2] + T(9) * t10 * in.w[1] * t4 + (T(4) * (T(2) * t13 * b * t4 + T(63) * t15 - T(63) * t16) * t4 + T(4) * t14 * b * t4 - T(9) * c * t10 * t4) * in.w[3] * t4 + T(72) * in.w[0] * t8 * t4) * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 34 +, 71 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  f = (T(1) / T(384)) * in.w[0] * length * t2 * (T(7) * (T(8) * r1 * q1 * q1 * slope1 - T(5) * (T(2) * q0 * slope0 * r0 - T(2) * r1 * q1 * slope1 - T(3) * D * t2 * (r1 * slope1 + J1 * D - slope0 * r0)) * D * t2 - T(8) * q0 * q0 * slope0 * r0) * D * t2 + T(48) * r1 * t4 * slope1 - T(48) * t6 * slope0 * r0);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 37 +, 82 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = T(8) * q1 * q1 * slope1 * r1 + T(5) * D * (T(2) * q1 * slope1 * r1 + T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) - T(2) * slope0 * r0 * q0) * t0 - T(8) * slope0 * r0 * q0 * q0;
  const T g_ap = (T(1) / T(48)) * t0 * t1 * in.w[0];
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T g_ab = -(T(1) / T(336)) * (T(48) * r0 * t3 - T(7) * t0 * t1 * b - T(48) * t5 * r1) * t0 * in.w[0];
  const T g_factor = -T(7) * length * inv_R2;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 39 +, 95 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(8) * q0 * q0 * slope0 * r0 - T(8) * r1 * q1 * q1 * slope1 - T(5) * (T(3) * D * (J1 * D + r1 * slope1 - slope0 * r0) * t2 + T(2) * r1 * q1 * slope1 - T(2) * q0 * slope0 * r0) * D * t2;
  const T g_ap = -(T(1) / T(48)) * in.w[0] * t3 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T g_ab = -(T(1) / T(336)) * in.w[0] * (T(7) * t3 * b * t2 + T(48) * t5 * r0 - T(48) * r1 * t7) * t2;
  const T g_factor = -T(7) * inv_R2 * length;
  f = (T(1) / T(384)) * in.w[0] * (T(48) * r1 * t7 * slope1 - T(7) * t3 * D * t2 - T(48) * t5 * slope0 * r0) * length * t2;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 37 +, 81 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * t4;
  const T t6 = T(1) / a;
  const T t7 = t4 * q0;
  const T t8 = t2 * q1;
  const T t9 = T(7) * D * (T(5) * D * (T(3) * D * t6 * (slope0 * r0 - slope1 * r1 - D * J1) + T(2) * slope0 * r0 * q0 - T(2) * q1 * slope1 * r1) * t6 + T(8) * slope0 * r0 * t4 - T(8) * t2 * slope1 * r1) * t6 + T(48) * slope0 * r0 * t7 - T(48) * t8 * slope1 * r1;
  f = (T(1) / T(1152)) * ((T(128) * t3 * r1 - T(128) * r0 * t5 - T(3) * b * t9 * t6) * t6 * in.w[1] - T(3) * t9 * t6 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 43 +, 105 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = T(8) * slope1 * r1 * q1 * q1 + T(5) * D * t0 * (T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) + T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0) - T(8) * slope0 * r0 * q0 * q0;
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = T(48) * r0 * t3 - T(48) * r1 * t5 - T(7) * t0 * b * t1;
  const T g_ap = (T(1) / T(48)) * t0 * in.w[0] * t1 - (T(1) / T(336)) * t6 * t0 * in.w[1];
  const T g_ab = -(T(1) / T(2688)) * t0 * in.w[1] * (T(56) * t0 * c * t1 + T(16) * t6 * t0 * b - T(7) * (T(7) * D * t0 * t1 + T(48) * slope1 * r1 * t5 - T(48) * slope0 * r0 * t3) * t0) - (T(1) / T(336)) * t6 * t0 * in.w[0];
  const T g_factor = -T(7) * length * inv_R2;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 46 +, 121 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(8) * q1 * q1 * slope1 * r1 - T(5) * D * t2 * (T(2) * q0 * slope0 * r0 + T(3) * D * (slope0 * r0 - slope1 * r1 - J1 * D) * t2 - T(2) * q1 * slope1 * r1) - T(8) * q0 * q0 * slope0 * r0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = T(48) * t5 * r1 + T(7) * b * t2 * t3 - T(48) * t7 * r0;
  const T g_ap = (T(1) / T(48)) * in.w[0] * t2 * t3 + (T(1) / T(336)) * in.w[1] * t2 * t8;
  const T t9 = T(7) * D * t2 * t3 + T(48) * t5 * slope1 * r1 - T(48) * t7 * slope0 * r0;
  const T g_ab = (T(1) / T(336)) * in.w[0] * t2 * t8 - (T(1) / T(2688)) * in.w[1] * t2 * (T(56) * t2 * c * t3 - T(16) * b * t2 * t8 - T(7) * t2 * t9);
  const T g_factor = -T(7) * inv_R2 * length;
  const T t10 = t4 * t4;
  const T t11 = t6 * t6;
  f = (T(1) / T(1152)) * length * (T(3) * in.w[0] * t2 * t9 + in.w[1] * (T(3) * b * t2 * t9 + T(128) * t10 * r1 - T(128) * t11 * r0) * t2);
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 42 +, 102 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q0 * q0;
  const T t3 = t2 * t2;
  const T t4 = T(1) / a;
  const T t5 = t2 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = T(7) * D * (T(8) * t2 * slope0 * r0 - T(8) * q1 * q1 * slope1 * r1 - T(5) * D * (T(2) * q1 * slope1 * r1 - T(2) * q0 * slope0 * r0 - T(3) * D * (slope0 * r0 - slope1 * r1 - J1 * D) * t4) * t4) * t4 + T(48) * t5 * slope0 * r0 - T(48) * t7 * slope1 * r1;
  const T t9 = t6 * t6;
  const T t10 = T(128) * t3 * r0 + T(3) * b * t4 * t8 - T(128) * t9 * r1;
  f = -(T(1) / T(11520)) * length * (in.w[2] * (T(20) * b * t10 * t4 + T(9) * t4 * (T(128) * t3 * slope0 * r0 + T(3) * D * t4 * t8 - T(128) * t9 * slope1 * r1) - T(30) * t4 * t8 * c) * t4 + T(10) * t10 * t4 * in.w[1] + T(30) * in.w[0] * t4 * t8);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 49 +, 128 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(8) * r1 * q1 * q1 * slope1 - T(8) * q0 * q0 * slope0 * r0 - T(5) * (T(2) * q0 * slope0 * r0 - T(3) * (J1 * D + r1 * slope1 - slope0 * r0) * D * t2 - T(2) * r1 * q1 * slope1) * D * t2;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = T(7) * b * t2 * t3 + T(48) * r1 * t5 - T(48) * t7 * r0;
  const T t9 = T(48) * r1 * t5 * slope1 + T(7) * D * t2 * t3 - T(48) * t7 * slope0 * r0;
  const T t10 = T(56) * c * t2 * t3 - T(7) * t9 * t2 - T(16) * b * t8 * t2;
  const T g_ap = (T(1) / T(48)) * in.w[0] * t2 * t3 + (T(1) / T(336)) * t8 * t2 * in.w[1] - (T(1) / T(2688)) * in.w[2] * t10 * t2;
  const T t11 = t6 * t6;
  const T t12 = t4 * t4;
  const T g_ab = (T(1) / T(336)) * t8 * in.w[0] * t2 - (T(1) / T(2688)) * t10 * t2 * in.w[1] - (T(1) / T(8064)) * in.w[2] * (T(7) * t2 * (T(128) * t11 * r0 - T(128) * r1 * t12 - T(3) * b * t9 * t2) + T(6) * b * t10 * t2 + T(24) * c * t8 * t2) * t2;
  const T g_factor = -T(7) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 55 +, 155 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(5) * (T(2) * q0 * slope0 * r0 + T(3) * (slope0 * r0 - r1 * slope1 - J1 * D) * D * t2 - T(2) * r1 * q1 * slope1) * D * t2 + T(8) * q0 * q0 * slope0 * r0 - T(8) * r1 * q1 * q1 * slope1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = T(7) * t3 * b * t2 + T(48) * t5 * r0 - T(48) * r1 * t7;
  const T t9 = T(7) * t3 * D * t2 + T(48) * t5 * slope0 * r0 - T(48) * r1 * t7 * slope1;
  const T t10 = T(56) * c * t3 * t2 - T(16) * b * t8 * t2 - T(7) * t9 * t2;
  const T g_ap = (T(1) / T(2688)) * t10 * in.w[2] * t2 - (T(1) / T(48)) * t3 * in.w[0] * t2 - (T(1) / T(336)) * in.w[1] * t8 * t2;
  const T t11 = t6 * t6;
  const T t12 = t4 * t4;
  const T t13 = T(128) * r1 * t11 - T(3) * t9 * b * t2 - T(128) * t12 * r0;
  const T g_ab = (T(1) / T(8064)) * in.w[2] * t2 * (T(7) * t13 * t2 + T(6) * t10 * b * t2 + T(24) * c * t8 * t2) + (T(1) / T(2688)) * in.w[1] * t10 * t2 - (T(1) / T(336)) * t8 * in.w[0] * t2;
  const T g_factor = -T(7) * inv_R2 * length;
  f = (T(1) / T(11520)) * (in.w[2] * (T(30) * c * t9 * t2 + T(20) * b * t13 * t2 - T(9) * (T(3) * t9 * D * t2 + T(128) * t12 * slope0 * r0 - T(128) * r1 * t11 * slope1) * t2) * t2 + T(10) * in.w[1] * t13 * t2 - T(30) * t9 * in.w[0] * t2) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 47 +, 122 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = T(48) * slope0 * r0 * t2 + T(7) * D * (T(8) * slope0 * r0 * t1 - T(8) * slope1 * r1 * q1 * q1 - T(5) * (T(3) * D * t0 * (slope1 * r1 + D * J1 - slope0 * r0) + T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0) * D * t0) * t0 - T(48) * slope1 * r1 * t4;
  const T t6 = t3 * t3;
  const T t7 = t1 * t1;
  const T t8 = T(128) * slope1 * r1 * t6 - T(128) * slope0 * r0 * t7 - T(3) * D * t0 * t5;
  const T t9 = T(128) * r1 * t6 - T(128) * r0 * t7 - T(3) * t0 * t5 * b;
  const T t10 = T(30) * t0 * c * t5 + T(9) * t0 * t8 + T(20) * t9 * t0 * b;
  const T t11 = t6 * q1;
  const T t12 = t7 * q0;
  f = -(T(1) / T(126720)) * (T(330) * t0 * in.w[0] * t5 - T(11) * t0 * in.w[2] * t10 - T(110) * t9 * t0 * in.w[1] - t0 * (T(22) * t0 * b * t10 + T(9) * t0 * (T(11) * t0 * t8 * b + T(1280) * r1 * t11 - T(1280) * r0 * t12) - T(110) * t9 * t0 * c) * in.w[3]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 57 +, 159 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - inv_R2 * cross_cross) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = T(8) * q0 * q0 * slope0 * r0 - T(5) * (T(2) * r1 * q1 * slope1 - T(3) * (slope0 * r0 - r1 * slope1 - J1 * D) * D * t2 - T(2) * q0 * slope0 * r0) * D * t2 - T(8) * r1 * q1 * q1 * slope1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = T(48) * t5 * r0 + T(7) * t3 * b * t2 - T(48) * r1 * t7;
  const T t9 = T(48) * t5 * slope0 * r0 + T(7) * t3 * D * t2 - T(48) * r1 * t7 * slope1;
  const T t10 = T(56) * t3 * t2 * c - T(16) * t8 * b * t2 - T(7) * t9 * t2;
  const T t11 = t4 * t4;
  const T t12 = t6 * t6;
  const T t13 = T(3) * b * t9 * t2 + T(128) * t11 * r0 - T(128) * r1 * t12;
  const T t14 = T(7) * t13 * t2 - T(24) * t8 * t2 * c - T(6) * b * t10 * t2;
  const T g_ap = (T(1) / T(2688)) * t10 * t2 * in.w[2] - (T(1) / T(48)) * in.w[0] * t3 * t2 - (T(1) / T(336)) * t8 * in.w[1] * t2 - (T(1) / T(8064)) * t14 * in.w[3] * t2;
  const T g_ab = (T(1) / T(2688)) * in.w[1] * t10 * t2 - (T(1) / T(336)) * in.w[0] * t8 * t2 - (T(1) / T(80640)) * in.w[3] * (T(30) * t10 * t2 * c + T(20) * t14 * b * t2 + T(7) * (T(20) * t13 * b * t2 + T(9) * (T(3) * D * t9 * t2 + T(128) * t11 * slope0 * r0 - T(128) * r1 * t12 * slope1) * t2 - T(30) * t9 * t2 * c) * t2) * t2 - (T(1) / T(8064)) * t14 * t2 * in.w[2];
  const T g_factor = -T(7) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 64 +, 188 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i7_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = T(8) * r0 * q0 * q0 * slope0 - T(8) * slope1 * r1 * t2 - T(5) * (T(2) * slope1 * r1 * q1 + T(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t1 - T(2) * r0 * q0 * slope0) * D * t1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = T(48) * r1 * t3 - T(7) * b * t4 * t1 - T(48) * r0 * t6;
  const T t8 = T(48) * r0 * t6 * slope0 + T(7) * D * t4 * t1 - T(48) * slope1 * r1 * t3;
  const T t9 = T(7) * t8 * t1 - T(56) * c * t4 * t1 - T(16) * b * t1 * t7;
  const T t10 = t5 * t5;
  const T t11 = t2 * t2;
  const T t12 = T(128) * r0 * t10 + T(3) * t8 * b * t1 - T(128) * r1 * t11;
  const T t13 = T(7) * t12 * t1 + T(6) * t9 * b * t1 + T(24) * c * t1 * t7;
  const T g_ap = (T(1) / T(336)) * in.w[1] * t1 * t7 - (T(1) / T(48)) * in.w[0] * t4 * t1 - (T(1) / T(2688)) * t9 * in.w[2] * t1 - (T(1) / T(8064)) * in.w[3] * t13 * t1;
  const T t14 = T(128) * slope1 * r1 * t11 - T(128) * r0 * t10 * slope0 - T(3) * t8 * D * t1;
  const T t15 = T(9) * t14 * t1 + T(30) * c * t8 * t1 - T(20) * t12 * b * t1;
  const T g_ab = (T(1) / T(336)) * in.w[0] * t1 * t7 - (T(1) / T(8064)) * in.w[2] * t13 * t1 - (T(1) / T(2688)) * t9 * in.w[1] * t1 - (T(1) / T(80640)) * in.w[3] * (T(20) * b * t13 * t1 - T(7) * t15 * t1 - T(30) * t9 * c * t1) * t1;
  const T g_factor = -T(7) * inv_R2 * length;
  const T t16 = t10 * q0;
  const T t17 = t11 * q1;
  f = -(T(1) / T(126720)) * (T(330) * t8 * in.w[0] * t1 + T(110) * t12 * in.w[1] * t1 - in.w[3] * (T(22) * t15 * b * t1 + T(110) * c * t12 * t1 - T(9) * (T(1280) * r0 * t16 - T(11) * t14 * b * t1 - T(1280) * r1 * t17) * t1) * t1 - T(11) * in.w[2] * t15 * t1) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 34 +, 65 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  f = (T(1) / T(315)) * length * t0 * (T(8) * D * t0 * (T(2) * D * t0 * (T(4) * D * t0 * (slope1 * q1 + T(2) * D * (in.t1 - in.t0) - slope0 * q0) + T(3) * slope1 * q1 * q1 - T(3) * slope0 * q0 * q0) + T(5) * slope1 * t2 - T(5) * slope0 * t4) + T(35) * slope1 * t5 - T(35) * slope0 * t6) * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 37 +, 75 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i8_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = T(5) * t2 * slope0 + T(2) * D * t0 * (T(3) * t1 * slope0 - T(4) * D * t0 * (q1 * slope1 + T(2) * D * (in.t1 - in.t0) - q0 * slope0) - T(3) * q1 * q1 * slope1) - T(5) * t4 * slope1;
  const T g_ap = -(T(1) / T(35)) * t0 * in.w[0] * t5;
  const T t6 = t3 * t3;
  const T t7 = t1 * t1;
  const T g_ab = (T(1) / T(280)) * t0 * (T(35) * t6 - T(8) * t0 * b * t5 - T(35) * t7) * in.w[0];
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = -g_factor * (g_ab * ab0 - ap0 * g_ap);
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 39 +, 87 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(2) * D * t0 * (T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + slope1 * q1 - slope0 * q0) + T(3) * slope1 * q1 * q1 - T(3) * slope0 * q0 * q0) + T(5) * slope1 * t2 - T(5) * slope0 * t4;
  const T g_ap = (T(1) / T(35)) * t0 * t5 * in.w[0];
  const T t6 = t3 * t3;
  const T t7 = t1 * t1;
  const T g_ab = -(T(1) / T(280)) * t0 * (T(35) * t6 - T(35) * t7 - T(8) * b * t0 * t5) * in.w[0];
  const T g_factor = -T(8) * length * inv_R2;
  f = (T(1) / T(315)) * length * (T(35) * slope1 * t7 + T(8) * D * t0 * t5 - T(35) * slope0 * t6) * t0 * in.w[0];
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 37 +, 73 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t0 * q1;
  const T t6 = t3 * t3;
  const T t7 = T(35) * slope1 * t1 - T(8) * D * t2 * (T(5) * slope0 * t4 + T(2) * D * t2 * (T(4) * D * (slope0 * q0 - T(2) * (in.t1 - in.t0) * D - slope1 * q1) * t2 + T(3) * slope0 * t3 - T(3) * slope1 * t0) - T(5) * slope1 * t5) - T(35) * slope0 * t6;
  const T t8 = t1 * q1;
  const T t9 = t6 * q0;
  f = (T(1) / T(630)) * length * (T(2) * t7 * t2 * in.w[0] + t2 * in.w[1] * (T(63) * t8 + T(2) * b * t7 * t2 - T(63) * t9));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 43 +, 95 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i8_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * q0;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = T(1) / a;
  const T t5 = T(5) * t1 * slope0 - T(5) * t3 * slope1 - T(2) * (T(3) * t2 * slope1 - T(4) * D * t4 * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) - T(3) * t0 * slope0) * D * t4;
  const T t6 = t0 * t0;
  const T t7 = t2 * t2;
  const T t8 = T(8) * t5 * b * t4 + T(35) * t6 - T(35) * t7;
  const T g_ap = -(T(1) / T(35)) * t5 * in.w[0] * t4 - (T(1) / T(280)) * t8 * in.w[1] * t4;
  const T g_ab = -(T(1) / T(1260)) * (T(9) * t8 * b * t4 + T(4) * (T(8) * t5 * D * t4 + T(35) * t6 * slope0 - T(35) * t7 * slope1) * t4 - T(36) * c * t5 * t4) * in.w[1] * t4 - (T(1) / T(280)) * t8 * in.w[0] * t4;
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (g_ap * ap1 - g_ab * ab1);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 46 +, 109 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t1 * q1;
  const T t6 = T(5) * t4 * slope0 + T(2) * t0 * D * (T(3) * t3 * slope0 - T(3) * t1 * slope1 - T(4) * (T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0) * t0 * D) - T(5) * t5 * slope1;
  const T t7 = t3 * t3;
  const T t8 = T(35) * t2 - T(8) * t6 * b * t0 - T(35) * t7;
  const T g_ap = (T(1) / T(280)) * in.w[1] * t0 * t8 - (T(1) / T(35)) * t6 * t0 * in.w[0];
  const T t9 = T(35) * t2 * slope1 - T(8) * t6 * t0 * D - T(35) * t7 * slope0;
  const T g_ab = (T(1) / T(1260)) * in.w[1] * t0 * (T(4) * t0 * t9 + T(9) * b * t0 * t8 + T(36) * c * t6 * t0) + (T(1) / T(280)) * t0 * t8 * in.w[0];
  const T g_factor = -T(8) * length * inv_R2;
  const T t10 = t2 * q1;
  const T t11 = t7 * q0;
  f = (T(1) / T(630)) * (T(2) * t0 * in.w[0] * t9 + in.w[1] * (T(2) * b * t0 * t9 + T(63) * t10 - T(63) * t11) * t0) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 42 +, 93 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = t1 * q0;
  const T t3 = T(1) / a;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t0 * q0;
  const T t7 = t4 * t4;
  const T t8 = T(35) * t1 * slope0 - T(8) * (T(2) * (T(4) * D * (T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0) * t3 + T(3) * q1 * q1 * slope1 - T(3) * t0 * slope0) * D * t3 + T(5) * t5 * slope1 - T(5) * t6 * slope0) * D * t3 - T(35) * t7 * slope1;
  const T t9 = t7 * q1;
  const T t10 = T(63) * t2 + T(2) * t8 * b * t3 - T(63) * t9;
  f = -(T(1) / T(6930)) * (T(11) * t10 * t3 * in.w[1] + T(22) * t8 * in.w[0] * t3 - T(2) * in.w[2] * (T(11) * c * t8 * t3 - T(5) * (T(63) * t2 * slope0 + T(2) * t8 * D * t3 - T(63) * t9 * slope1) * t3 - T(11) * t10 * b * t3) * t3) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 49 +, 118 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i8_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(2) * D * t0 * (T(3) * q1 * q1 * slope1 + T(4) * D * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - q0 * slope0) * t0 - T(3) * q0 * q0 * slope0) + T(5) * t2 * slope1 - T(5) * t4 * slope0;
  const T t6 = t3 * t3;
  const T t7 = t1 * t1;
  const T t8 = T(35) * t6 - T(8) * t0 * t5 * b - T(35) * t7;
  const T t9 = T(8) * D * t0 * t5 + T(35) * t7 * slope1 - T(35) * t6 * slope0;
  const T t10 = T(9) * t8 * t0 * b + T(36) * t0 * c * t5 - T(4) * t0 * t9;
  const T g_ap = (T(1) / T(35)) * t0 * t5 * in.w[0] - (T(1) / T(280)) * t8 * t0 * in.w[1] - (T(1) / T(1260)) * t0 * t10 * in.w[2];
  const T t11 = t7 * q1;
  const T t12 = t6 * q0;
  const T g_ab = -(T(1) / T(280)) * t8 * t0 * in.w[0] - (T(1) / T(1260)) * t0 * in.w[1] * t10 - (T(1) / T(2520)) * (T(4) * t0 * t10 * b - T(9) * t8 * t0 * c - T(4) * t0 * (T(2) * t0 * t9 * b + T(63) * t11 - T(63) * t12)) * t0 * in.w[2];
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = -(g_ab * ab0 - g_ap * ap0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 55 +, 143 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(5) * t1 * slope1 - T(2) * D * t2 * (T(3) * slope0 * q0 * q0 + T(4) * D * (slope0 * q0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * t2 - T(3) * t0 * slope1) - T(5) * slope0 * t4;
  const T t6 = t3 * t3;
  const T t7 = t0 * t0;
  const T t8 = T(35) * t6 - T(8) * t5 * t2 * b - T(35) * t7;
  const T t9 = T(8) * t5 * D * t2 + T(35) * t7 * slope1 - T(35) * slope0 * t6;
  const T t10 = T(36) * t5 * t2 * c + T(9) * t2 * t8 * b - T(4) * t2 * t9;
  const T g_ap = (T(1) / T(35)) * t5 * t2 * in.w[0] - (T(1) / T(280)) * t2 * in.w[1] * t8 - (T(1) / T(1260)) * t2 * in.w[2] * t10;
  const T t11 = t6 * q0;
  const T t12 = t7 * q1;
  const T t13 = T(63) * t11 - T(2) * t2 * t9 * b - T(63) * t12;
  const T g_ab = -(T(1) / T(1260)) * t2 * in.w[1] * t10 - (T(1) / T(280)) * t2 * t8 * in.w[0] - (T(1) / T(2520)) * t2 * (T(4) * t2 * b * t10 + T(4) * t2 * t13 - T(9) * t2 * t8 * c) * in.w[2];
  const T g_factor = -T(8) * length * inv_R2;
  f = -(T(1) / T(6930)) * length * (T(11) * t2 * in.w[1] * t13 + T(2) * (T(11) * t2 * t13 * b + T(11) * t2 * t9 * c - T(5) * t2 * (T(2) * D * t2 * t9 + T(63) * t12 * slope1 - T(63) * slope0 * t11)) * t2 * in.w[2] - T(22) * t2 * t9 * in.w[0]);
  grad[0] = -(ab0 * g_ab - ap0 * g_ap) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 47 +, 110 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = t1 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t5 * t5;
  const T t8 = T(8) * D * (T(5) * t4 * slope0 - T(2) * D * t0 * (T(3) * q1 * q1 * slope1 - T(3) * t1 * slope0 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t0) - T(5) * t6 * slope1) * t0 + T(35) * t2 * slope0 - T(35) * t7 * slope1;
  const T t9 = t7 * q1;
  const T t10 = T(63) * t3 + T(2) * b * t8 * t0 - T(63) * t9;
  const T t11 = T(63) * t9 * slope1 - T(2) * t8 * D * t0 - T(63) * t3 * slope0;
  const T t12 = T(11) * b * t0 * t10 - T(11) * t8 * t0 * c - T(5) * t11 * t0;
  const T t13 = t6 * t6;
  const T t14 = t4 * t4;
  f = -(T(1) / T(13860)) * (T(4) * t12 * t0 * in.w[2] + T(22) * in.w[1] * t0 * t10 + (T(8) * t12 * b * t0 - T(22) * t0 * t10 * c - T(5) * (T(4) * b * t11 * t0 + T(231) * t13 - T(231) * t14) * t0) * in.w[3] * t0 + T(44) * in.w[0] * t8 * t0) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 57 +, 145 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i8_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(5) * t2 * slope1 - T(5) * t4 * slope0 - T(2) * (T(4) * (q0 * slope0 - q1 * slope1 - T(2) * (in.t1 - in.t0) * D) * D * t0 + T(3) * t3 * slope0 - T(3) * t1 * slope1) * D * t0;
  const T t6 = t1 * t1;
  const T t7 = t3 * t3;
  const T t8 = T(8) * b * t0 * t5 + T(35) * t6 - T(35) * t7;
  const T t9 = T(8) * D * t0 * t5 + T(35) * t6 * slope1 - T(35) * t7 * slope0;
  const T t10 = T(36) * t0 * t5 * c - T(9) * t8 * b * t0 - T(4) * t0 * t9;
  const T t11 = t6 * q1;
  const T t12 = t7 * q0;
  const T t13 = T(2) * b * t0 * t9 + T(63) * t11 - T(63) * t12;
  const T t14 = T(9) * t8 * t0 * c + T(4) * b * t10 * t0 - T(4) * t0 * t13;
  const T g_ap = (T(1) / T(35)) * in.w[0] * t0 * t5 + (T(1) / T(280)) * t8 * in.w[1] * t0 - (T(1) / T(1260)) * t10 * t0 * in.w[2] - (T(1) / T(2520)) * in.w[3] * t14 * t0;
  const T g_ab = (T(1) / T(280)) * t8 * in.w[0] * t0 + (T(1) / T(13860)) * in.w[3] * (T(11) * t10 * t0 * c - T(4) * t0 * (T(11) * t0 * t9 * c - T(11) * b * t0 * t13 - T(5) * (T(2) * D * t0 * t9 + T(63) * t11 * slope1 - T(63) * t12 * slope0) * t0) - T(11) * b * t14 * t0) * t0 - (T(1) / T(2520)) * t14 * t0 * in.w[2] - (T(1) / T(1260)) * in.w[1] * t10 * t0;
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 64 +, 173 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i8_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = T(5) * slope0 * t2 - T(5) * t4 * slope1 - T(2) * D * t0 * (T(3) * t3 * slope1 + T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0) - T(3) * slope0 * t1);
  const T t6 = t1 * t1;
  const T t7 = t3 * t3;
  const T t8 = T(8) * D * t0 * t5 + T(35) * slope0 * t6 - T(35) * t7 * slope1;
  const T t9 = T(8) * t0 * b * t5 + T(35) * t6 - T(35) * t7;
  const T t10 = T(4) * t0 * t8 + T(9) * t0 * t9 * b - T(36) * t0 * c * t5;
  const T t11 = t6 * q0;
  const T t12 = t7 * q1;
  const T t13 = T(2) * t0 * t8 * b + T(63) * t11 - T(63) * t12;
  const T t14 = T(4) * t0 * t13 + T(4) * t0 * t10 * b - T(9) * t0 * c * t9;
  const T g_ap = -(T(1) / T(1260)) * t0 * in.w[2] * t10 - (T(1) / T(2520)) * t0 * t14 * in.w[3] - (T(1) / T(280)) * t0 * t9 * in.w[1] - (T(1) / T(35)) * t0 * in.w[0] * t5;
  const T t15 = T(63) * t12 * slope1 - T(2) * D * t0 * t8 - T(63) * slope0 * t11;
  const T t16 = T(5) * t0 * t15 + T(11) * t0 * t8 * c - T(11) * t0 * t13 * b;
  const T g_ab = -(T(1) / T(1260)) * t0 * t10 * in.w[1] - (T(1) / T(280)) * t0 * in.w[0] * t9 - (T(1) / T(2520)) * t0 * in.w[2] * t14 - (T(1) / T(13860)) * (T(11) * t0 * t14 * b - T(4) * t0 * t16 - T(11) * t0 * c * t10) * t0 * in.w[3];
  const T g_factor = -T(8) * inv_R2 * length;
  const T t17 = t4 * t4;
  const T t18 = t2 * t2;
  f = (T(1) / T(13860)) * (T(4) * t0 * in.w[2] * t16 + t0 * in.w[3] * (T(22) * t0 * c * t13 + T(5) * (T(4) * t0 * t15 * b + T(231) * t17 - T(231) * t18) * t0 + T(8) * t0 * t16 * b) - T(22) * t0 * t13 * in.w[1] - T(44) * t0 * t8 * in.w[0]) * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 36 +, 80 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t3 * q1;
  const T t8 = t5 * t5;
  f = (T(1) / T(1280)) * in.w[0] * length * t2 * (T(128) * r1 * t4 * slope1 - T(3) * (T(48) * t6 * slope0 * r0 - T(7) * D * (T(5) * D * t2 * (T(2) * r1 * q1 * slope1 - T(3) * D * (slope0 * r0 - J1 * D - r1 * slope1) * t2 - T(2) * q0 * slope0 * r0) + T(8) * r1 * t3 * slope1 - T(8) * t5 * slope0 * r0) * t2 - T(48) * r1 * t7 * slope1) * D * t2 - T(128) * t8 * slope0 * r0);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 39 +, 93 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = T(7) * D * t0 * (T(5) * D * t0 * (T(3) * D * t0 * (slope1 * r1 + D * J1 - slope0 * r0) + T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0) + T(8) * slope1 * r1 * q1 * q1 - T(8) * slope0 * r0 * q0 * q0) + T(48) * slope1 * r1 * t2 - T(48) * slope0 * r0 * t4;
  const T g_ap = (T(1) / T(384)) * t0 * t5 * in.w[0];
  const T t6 = t3 * t3;
  const T t7 = t1 * t1;
  const T g_ab = -(T(1) / T(1152)) * t0 * in.w[0] * (T(128) * r0 * t6 - T(128) * r1 * t7 - T(3) * t0 * t5 * b);
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 41 +, 106 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = T(7) * (T(8) * q1 * q1 * slope1 * r1 - T(5) * (T(2) * q0 * slope0 * r0 - T(3) * D * t2 * (slope1 * r1 + J1 * D - slope0 * r0) - T(2) * q1 * slope1 * r1) * D * t2 - T(8) * q0 * q0 * slope0 * r0) * D * t2 + T(48) * t4 * slope1 * r1 - T(48) * t6 * slope0 * r0;
  const T g_ap = (T(1) / T(384)) * in.w[0] * t2 * t7;
  const T t8 = t5 * t5;
  const T t9 = t3 * t3;
  const T g_ab = -(T(1) / T(1152)) * (T(128) * t8 * r0 - T(3) * b * t2 * t7 - T(128) * t9 * r1) * in.w[0] * t2;
  const T g_factor = -T(9) * inv_R2 * length;
  f = (T(1) / T(1280)) * in.w[0] * (T(128) * t9 * slope1 * r1 + T(3) * D * t2 * t7 - T(128) * t8 * slope0 * r0) * length * t2;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 39 +, 92 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = t1 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = T(1) / a;
  const T t8 = t5 * t5;
  const T t9 = T(3) * (T(48) * r0 * t4 * slope0 - T(48) * slope1 * r1 * t6 - T(7) * (T(8) * slope1 * r1 * t5 + T(5) * (T(2) * slope1 * r1 * q1 + T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t7 - T(2) * r0 * q0 * slope0) * D * t7 - T(8) * r0 * t1 * slope0) * D * t7) * D * t7 + T(128) * r0 * t2 * slope0 - T(128) * slope1 * r1 * t8;
  const T t10 = t8 * q1;
  f = -(T(1) / T(14080)) * length * ((T(1280) * r0 * t3 + T(11) * t9 * b * t7 - T(1280) * r1 * t10) * in.w[1] * t7 + T(11) * t9 * in.w[0] * t7);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 45 +, 114 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * t4;
  const T t6 = T(1) / a;
  const T t7 = t4 * q0;
  const T t8 = t2 * q1;
  const T t9 = T(7) * (T(8) * t4 * slope0 * r0 - T(8) * r1 * t2 * slope1 - T(5) * D * t6 * (T(2) * r1 * q1 * slope1 - T(2) * q0 * slope0 * r0 - T(3) * (slope0 * r0 - J1 * D - r1 * slope1) * D * t6)) * D * t6 + T(48) * t7 * slope0 * r0 - T(48) * r1 * t8 * slope1;
  const T t10 = T(128) * r1 * t3 - T(128) * t5 * r0 - T(3) * t9 * b * t6;
  const T g_ap = (T(1) / T(1152)) * in.w[1] * t10 * t6 - (T(1) / T(384)) * t9 * t6 * in.w[0];
  const T g_ab = (T(1) / T(1152)) * t10 * t6 * in.w[0] + (T(1) / T(11520)) * in.w[1] * (T(30) * c * t9 * t6 + T(20) * b * t10 * t6 - T(9) * (T(128) * t5 * slope0 * r0 + T(3) * t9 * D * t6 - T(128) * r1 * t3 * slope1) * t6) * t6;
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 48 +, 130 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / a;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t2 * q1;
  const T t8 = T(48) * slope0 * r0 * t6 + T(7) * D * t4 * (T(5) * D * t4 * (T(3) * (slope0 * r0 - slope1 * r1 - J1 * D) * D * t4 + T(2) * slope0 * r0 * q0 - T(2) * q1 * slope1 * r1) + T(8) * slope0 * r0 * t5 - T(8) * t2 * slope1 * r1) - T(48) * t7 * slope1 * r1;
  const T t9 = t5 * t5;
  const T t10 = T(128) * t3 * r1 - T(3) * b * t4 * t8 - T(128) * r0 * t9;
  const T g_ap = (T(1) / T(1152)) * t10 * t4 * in.w[1] - (T(1) / T(384)) * t4 * in.w[0] * t8;
  const T t11 = T(128) * t3 * slope1 * r1 - T(3) * D * t4 * t8 - T(128) * slope0 * r0 * t9;
  const T g_ab = (T(1) / T(11520)) * (T(9) * t11 * t4 + T(30) * t4 * t8 * c + T(20) * b * t10 * t4) * t4 * in.w[1] + (T(1) / T(1152)) * t10 * t4 * in.w[0];
  const T g_factor = -T(9) * length * inv_R2;
  const T t12 = t3 * q1;
  const T t13 = t9 * q0;
  f = (T(1) / T(14080)) * length * (t4 * (T(1280) * t12 * r1 + T(11) * b * t11 * t4 - T(1280) * r0 * t13) * in.w[1] + T(11) * t11 * t4 * in.w[0]);
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (g_ap * ap2 - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 44 +, 114 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t3 * t3;
  const T t8 = t5 * t5;
  const T t9 = T(3) * D * (T(7) * (T(8) * slope0 * r0 * q0 * q0 - T(5) * (T(2) * q1 * slope1 * r1 + T(3) * D * t2 * (slope1 * r1 + J1 * D - slope0 * r0) - T(2) * slope0 * r0 * q0) * D * t2 - T(8) * q1 * q1 * slope1 * r1) * D * t2 + T(48) * slope0 * r0 * t4 - T(48) * t6 * slope1 * r1) * t2 + T(128) * slope0 * r0 * t7 - T(128) * t8 * slope1 * r1;
  const T t10 = t7 * q0;
  const T t11 = t8 * q1;
  const T t12 = T(1280) * r0 * t10 + T(11) * b * t2 * t9 - T(1280) * t11 * r1;
  f = -(T(1) / T(168960)) * length * (in.w[2] * (T(11) * (T(11) * D * t2 * t9 + T(1280) * slope0 * r0 * t10 - T(1280) * t11 * slope1 * r1) * t2 + T(24) * b * t2 * t12 - T(132) * t2 * t9 * c) * t2 + T(132) * in.w[0] * t2 * t9 + T(12) * t2 * in.w[1] * t12);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 51 +, 138 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = T(1) / a;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = T(48) * r1 * t3 * slope1 + T(7) * (T(8) * r1 * t2 * slope1 - T(5) * (T(2) * q0 * slope0 * r0 - T(2) * r1 * q1 * slope1 - T(3) * D * t4 * (r1 * slope1 + J1 * D - slope0 * r0)) * D * t4 - T(8) * q0 * q0 * slope0 * r0) * D * t4 - T(48) * t6 * slope0 * r0;
  const T t8 = t2 * t2;
  const T t9 = t5 * t5;
  const T t10 = T(3) * b * t7 * t4 + T(128) * r1 * t8 - T(128) * t9 * r0;
  const T t11 = T(3) * D * t7 * t4 + T(128) * r1 * t8 * slope1 - T(128) * t9 * slope0 * r0;
  const T t12 = T(30) * c * t7 * t4 - T(20) * t10 * b * t4 - T(9) * t11 * t4;
  const T g_ap = (T(1) / T(384)) * in.w[0] * t7 * t4 + (T(1) / T(1152)) * t10 * t4 * in.w[1] - (T(1) / T(11520)) * in.w[2] * t12 * t4;
  const T t13 = t9 * q0;
  const T t14 = t8 * q1;
  const T g_ab = (T(1) / T(1152)) * t10 * in.w[0] * t4 - (T(1) / T(11520)) * t12 * t4 * in.w[1] - (T(1) / T(126720)) * in.w[2] * (T(9) * (T(1280) * t13 * r0 - T(1280) * r1 * t14 - T(11) * b * t11 * t4) * t4 + T(110) * c * t10 * t4 + T(22) * t12 * b * t4) * t4;
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 57 +, 164 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = T(1) / a;
  const T t7 = T(48) * r1 * slope1 * t3 - T(48) * t5 * slope0 * r0 - T(7) * (T(8) * t4 * slope0 * r0 - T(5) * D * t6 * (T(3) * (r1 * slope1 + D * J1 - slope0 * r0) * D * t6 + T(2) * r1 * slope1 * q1 - T(2) * q0 * slope0 * r0) - T(8) * r1 * slope1 * t2) * D * t6;
  const T t8 = t2 * t2;
  const T t9 = t4 * t4;
  const T t10 = T(128) * r1 * t8 + T(3) * t7 * b * t6 - T(128) * t9 * r0;
  const T t11 = T(128) * t9 * slope0 * r0 - T(128) * r1 * slope1 * t8 - T(3) * t7 * D * t6;
  const T t12 = T(20) * t10 * b * t6 - T(9) * t11 * t6 - T(30) * t7 * t6 * c;
  const T g_ap = (T(1) / T(384)) * t7 * in.w[0] * t6 + (T(1) / T(11520)) * in.w[2] * t12 * t6 + (T(1) / T(1152)) * t10 * t6 * in.w[1];
  const T t13 = t8 * q1;
  const T t14 = t9 * q0;
  const T t15 = T(1280) * r1 * t13 - T(1280) * t14 * r0 - T(11) * t11 * b * t6;
  const T g_ab = (T(1) / T(11520)) * t12 * t6 * in.w[1] + (T(1) / T(126720)) * in.w[2] * t6 * (T(9) * t15 * t6 + T(22) * b * t12 * t6 - T(110) * t10 * t6 * c) + (T(1) / T(1152)) * t10 * in.w[0] * t6;
  const T g_factor = -T(9) * inv_R2 * length;
  f = -(T(1) / T(168960)) * length * (T(132) * t11 * in.w[0] * t6 + (T(11) * (T(1280) * t14 * slope0 * r0 + T(11) * t11 * D * t6 - T(1280) * r1 * slope1 * t13) * t6 - T(132) * t11 * t6 * c - T(24) * t15 * b * t6) * in.w[2] * t6 - T(12) * t15 * t6 * in.w[1]);
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = g_factor * (g_ap * ap1 - g_ab * ab1);
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 49 +, 132 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t3 * q1;
  const T t9 = t6 * t6;
  const T t10 = T(128) * t4 * slope1 * r1 - T(3) * (T(48) * slope0 * r0 * t7 + T(7) * (T(8) * slope0 * r0 * t6 - T(8) * t3 * slope1 * r1 - T(5) * D * (T(2) * q1 * slope1 * r1 - T(2) * slope0 * r0 * q0 - T(3) * D * t2 * (slope0 * r0 - J1 * D - slope1 * r1)) * t2) * D * t2 - T(48) * t8 * slope1 * r1) * D * t2 - T(128) * slope0 * r0 * t9;
  const T t11 = t9 * q0;
  const T t12 = T(1280) * t5 * r1 + T(11) * b * t10 * t2 - T(1280) * r0 * t11;
  const T t13 = T(11) * t10 * D * t2 + T(1280) * t5 * slope1 * r1 - T(1280) * slope0 * r0 * t11;
  const T t14 = T(11) * t2 * t13 + T(24) * b * t2 * t12 - T(132) * t10 * t2 * c;
  const T t15 = t7 * t7;
  const T t16 = t8 * t8;
  f = (T(1) / T(2196480)) * length * (T(156) * in.w[1] * t2 * t12 + T(13) * t14 * t2 * in.w[2] + T(1716) * in.w[0] * t10 * t2 + (T(26) * t14 * b * t2 - T(156) * t2 * c * t12 - T(11) * t2 * (T(15360) * r0 * t15 - T(13) * b * t2 * t13 - T(15360) * t16 * r1)) * t2 * in.w[3]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 59 +, 168 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t3 * q1;
  const T t6 = T(1) / a;
  const T t7 = t1 * q0;
  const T t8 = T(48) * slope1 * r1 * t5 + T(7) * (T(8) * slope1 * r1 * t3 + T(5) * (T(2) * slope1 * r1 * q1 + T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t6 - T(2) * r0 * q0 * slope0) * D * t6 - T(8) * r0 * t1 * slope0) * D * t6 - T(48) * r0 * t7 * slope0;
  const T t9 = T(128) * r0 * t2 - T(128) * r1 * t4 - T(3) * t8 * b * t6;
  const T t10 = T(3) * t8 * D * t6 + T(128) * slope1 * r1 * t4 - T(128) * r0 * t2 * slope0;
  const T t11 = T(9) * t10 * t6 - T(30) * c * t8 * t6 - T(20) * t9 * b * t6;
  const T t12 = t2 * q0;
  const T t13 = t4 * q1;
  const T t14 = T(1280) * r0 * t12 - T(1280) * r1 * t13 - T(11) * t10 * b * t6;
  const T t15 = T(110) * c * t9 * t6 + T(22) * t11 * b * t6 - T(9) * t14 * t6;
  const T g_ap = (T(1) / T(126720)) * t15 * in.w[3] * t6 + (T(1) / T(384)) * in.w[0] * t8 * t6 + (T(1) / T(11520)) * t11 * in.w[2] * t6 - (T(1) / T(1152)) * t9 * in.w[1] * t6;
  const T g_ab = (T(1) / T(11520)) * t11 * in.w[1] * t6 + (T(1) / T(126720)) * in.w[2] * t15 * t6 - (T(1) / T(506880)) * (T(44) * t11 * c * t6 + T(3) * (T(24) * t14 * b * t6 + T(132) * t10 * c * t6 - T(11) * (T(1280) * slope1 * r1 * t13 + T(11) * t10 * D * t6 - T(1280) * r0 * t12 * slope0) * t6) * t6 - T(8) * t15 * b * t6) * in.w[3] * t6 - (T(1) / T(1152)) * in.w[0] * t9 * t6;
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 66 +, 200 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i9_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = T(7) * (T(5) * D * (T(2) * q1 * slope1 * r1 - T(2) * slope0 * r0 * q0 - T(3) * D * t2 * (slope0 * r0 - slope1 * r1 - D * J1)) * t2 + T(8) * q1 * q1 * slope1 * r1 - T(8) * slope0 * r0 * q0 * q0) * D * t2 + T(48) * t4 * slope1 * r1 - T(48) * slope0 * r0 * t6;
  const T t8 = t3 * t3;
  const T t9 = t5 * t5;
  const T t10 = T(128) * t8 * r1 + T(3) * b * t2 * t7 - T(128) * r0 * t9;
  const T t11 = T(128) * slope0 * r0 * t9 - T(128) * t8 * slope1 * r1 - T(3) * D * t2 * t7;
  const T t12 = t9 * q0;
  const T t13 = t8 * q1;
  const T t14 = T(11) * b * t11 * t2 + T(1280) * r0 * t12 - T(1280) * t13 * r1;
  const T t15 = T(9) * t11 * t2 + T(30) * t2 * c * t7 - T(20) * b * t2 * t10;
  const T t16 = T(110) * t2 * c * t10 + T(9) * t2 * t14 + T(22) * b * t15 * t2;
  const T g_ap = (T(1) / T(384)) * t2 * in.w[0] * t7 + (T(1) / T(1152)) * in.w[1] * t2 * t10 - (T(1) / T(126720)) * t16 * t2 * in.w[3] - (T(1) / T(11520)) * t15 * t2 * in.w[2];
  const T t17 = T(11) * t11 * D * t2 + T(1280) * slope0 * r0 * t12 - T(1280) * t13 * slope1 * r1;
  const T t18 = T(132) * t11 * t2 * c - T(24) * b * t2 * t14 - T(11) * t17 * t2;
  const T g_ab = (T(1) / T(1152)) * t2 * in.w[0] * t10 + (T(1) / T(506880)) * (T(3) * t18 * t2 + T(44) * t15 * t2 * c - T(8) * b * t16 * t2) * t2 * in.w[3] - (T(1) / T(126720)) * t16 * t2 * in.w[2] - (T(1) / T(11520)) * in.w[1] * t15 * t2;
  const T g_factor = -T(9) * length * inv_R2;
  const T t19 = t4 * t4;
  const T t20 = t6 * t6;
  f = (T(1) / T(2196480)) * ((T(11) * t2 * (T(15360) * t19 * r1 - T(15360) * r0 * t20 - T(13) * b * t17 * t2) + T(26) * b * t18 * t2 + T(156) * t2 * c * t14) * t2 * in.w[3] + T(13) * t18 * t2 * in.w[2] - T(156) * in.w[1] * t2 * t14 - T(1716) * t11 * t2 * in.w[0]) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 36 +, 72 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = t0 * q1;
  const T t5 = T(1) / a;
  const T t6 = t2 * t2;
  const T t7 = t1 * q1;
  const T t8 = t6 * q0;
  f = (T(1) / T(693)) * (T(2) * (T(35) * t1 * slope1 - T(8) * (T(5) * t3 * slope0 - T(5) * t4 * slope1 - T(2) * D * t5 * (T(3) * t0 * slope1 - T(3) * t2 * slope0 - T(4) * (T(2) * (in.t0 - in.t1) * D + q0 * slope0 - q1 * slope1) * D * t5)) * D * t5 - T(35) * t6 * slope0) * D * t5 + T(63) * t7 * slope1 - T(63) * t8 * slope0) * in.w[0] * length * t5;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 39 +, 84 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i10_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = T(8) * D * t0 * (T(5) * slope0 * t2 + T(2) * D * t0 * (T(3) * slope0 * t1 - T(3) * slope1 * q1 * q1 - T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + slope1 * q1 - slope0 * q0)) - T(5) * slope1 * t4) + T(35) * slope0 * t5 - T(35) * slope1 * t6;
  const T g_ap = -(T(1) / T(315)) * t0 * t7 * in.w[0];
  const T t8 = t5 * q0;
  const T t9 = t6 * q1;
  const T g_ab = -(T(1) / T(630)) * t0 * (T(63) * t8 + T(2) * b * t0 * t7 - T(63) * t9) * in.w[0];
  const T g_factor = -T(10) * length * inv_R2;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 41 +, 95 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t0 * t0;
  const T t6 = t3 * t3;
  const T t7 = T(8) * D * (T(5) * slope1 * t1 + T(2) * D * t2 * (T(3) * slope1 * t0 + T(4) * (slope1 * q1 - slope0 * q0 - T(2) * D * (in.t0 - in.t1)) * D * t2 - T(3) * slope0 * q0 * q0) - T(5) * slope0 * t4) * t2 + T(35) * slope1 * t5 - T(35) * slope0 * t6;
  const T g_ap = (T(1) / T(315)) * in.w[0] * t7 * t2;
  const T t8 = t5 * q1;
  const T t9 = t6 * q0;
  const T g_ab = (T(1) / T(630)) * (T(63) * t8 + T(2) * b * t7 * t2 - T(63) * t9) * in.w[0] * t2;
  const T g_factor = -T(10) * length * inv_R2;
  f = -(T(1) / T(693)) * (T(63) * slope0 * t9 - T(2) * D * t7 * t2 - T(63) * slope1 * t8) * length * in.w[0] * t2;
  grad[0] = g_factor * (ap0 * g_ap - g_ab * ab0);
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 39 +, 83 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = t5 * q0;
  const T t8 = t6 * q1;
  const T t9 = T(2) * t0 * D * (T(8) * (T(5) * slope0 * t2 + T(2) * t0 * D * (T(3) * slope0 * t1 - T(4) * t0 * D * (slope1 * q1 + T(2) * D * (in.t1 - in.t0) - slope0 * q0) - T(3) * slope1 * q1 * q1) - T(5) * slope1 * t4) * t0 * D + T(35) * slope0 * t5 - T(35) * slope1 * t6) + T(63) * slope0 * t7 - T(63) * slope1 * t8;
  const T t10 = t2 * t2;
  const T t11 = t4 * t4;
  f = -(T(1) / T(2772)) * length * (T(4) * t0 * t9 * in.w[0] + t0 * (T(4) * t0 * t9 * b + T(231) * t10 - T(231) * t11) * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 45 +, 104 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i10_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t0 * q1;
  const T t6 = t3 * t3;
  const T t7 = T(35) * t1 * slope1 - T(8) * D * t2 * (T(5) * slope0 * t4 + T(2) * D * t2 * (T(3) * slope0 * t3 - T(3) * t0 * slope1 - T(4) * D * t2 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0)) - T(5) * t5 * slope1) - T(35) * slope0 * t6;
  const T t8 = t1 * q1;
  const T t9 = t6 * q0;
  const T t10 = T(2) * t7 * t2 * b + T(63) * t8 - T(63) * t9;
  const T g_ap = (T(1) / T(315)) * t7 * t2 * in.w[0] + (T(1) / T(630)) * t2 * t10 * in.w[1];
  const T g_ab = (T(1) / T(630)) * t2 * t10 * in.w[0] + (T(1) / T(3465)) * t2 * (T(5) * t2 * (T(63) * t8 * slope1 + T(2) * t7 * D * t2 - T(63) * slope0 * t9) + T(11) * t2 * t10 * b - T(11) * t7 * t2 * c) * in.w[1];
  const T g_factor = -T(10) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 48 +, 118 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t1 * q1;
  const T t7 = t4 * t4;
  const T t8 = T(35) * t2 * slope1 - T(8) * D * t0 * (T(5) * t5 * slope0 + T(2) * D * t0 * (T(3) * t4 * slope0 - T(4) * D * t0 * (q1 * slope1 + T(2) * D * (in.t1 - in.t0) - q0 * slope0) - T(3) * t1 * slope1) - T(5) * t6 * slope1) - T(35) * t7 * slope0;
  const T t9 = t7 * q0;
  const T t10 = T(63) * t3 + T(2) * t0 * t8 * b - T(63) * t9;
  const T g_ap = (T(1) / T(630)) * t0 * in.w[1] * t10 + (T(1) / T(315)) * t0 * in.w[0] * t8;
  const T t11 = T(2) * D * t0 * t8 + T(63) * t3 * slope1 - T(63) * t9 * slope0;
  const T g_ab = (T(1) / T(3465)) * t0 * (T(5) * t0 * t11 + T(11) * t0 * t10 * b - T(11) * t0 * c * t8) * in.w[1] + (T(1) / T(630)) * t0 * in.w[0] * t10;
  const T g_factor = -T(10) * inv_R2 * length;
  const T t12 = t6 * t6;
  const T t13 = t5 * t5;
  f = (T(1) / T(2772)) * (t0 * in.w[1] * (T(4) * t0 * t11 * b + T(231) * t12 - T(231) * t13) + T(4) * t0 * in.w[0] * t11) * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 44 +, 101 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t3 * q1;
  const T t6 = t1 * q0;
  const T t7 = t2 * q0;
  const T t8 = t4 * q1;
  const T t9 = T(2) * D * t0 * (T(35) * slope0 * t2 - T(35) * slope1 * t4 - T(8) * (T(2) * D * t0 * (T(4) * D * t0 * (slope1 * q1 + T(2) * D * (in.t1 - in.t0) - slope0 * q0) + T(3) * slope1 * t3 - T(3) * slope0 * t1) + T(5) * slope1 * t5 - T(5) * slope0 * t6) * D * t0) + T(63) * slope0 * t7 - T(63) * slope1 * t8;
  const T t10 = t6 * t6;
  const T t11 = t5 * t5;
  const T t12 = T(231) * t10 + T(4) * t9 * t0 * b - T(231) * t11;
  f = -(T(1) / T(36036)) * length * (T(2) * t0 * (T(6) * t0 * (T(4) * D * t9 * t0 + T(231) * slope0 * t10 - T(231) * slope1 * t11) + T(13) * t0 * t12 * b - T(26) * t9 * t0 * c) * in.w[2] + T(13) * t0 * in.w[1] * t12 + T(52) * t9 * t0 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 51 +, 127 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i10_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = T(8) * D * t0 * (T(2) * D * t0 * (T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + slope1 * q1 - slope0 * q0) + T(3) * slope1 * q1 * q1 - T(3) * slope0 * q0 * q0) + T(5) * slope1 * t2 - T(5) * slope0 * t4) + T(35) * slope1 * t5 - T(35) * slope0 * t6;
  const T t8 = t5 * q1;
  const T t9 = t6 * q0;
  const T t10 = T(2) * b * t7 * t0 + T(63) * t8 - T(63) * t9;
  const T t11 = T(63) * slope0 * t9 - T(63) * slope1 * t8 - T(2) * t7 * D * t0;
  const T t12 = T(11) * b * t10 * t0 - T(5) * t0 * t11 - T(11) * t7 * t0 * c;
  const T g_ap = (T(1) / T(315)) * in.w[0] * t7 * t0 + (T(1) / T(630)) * t10 * t0 * in.w[1] + (T(1) / T(3465)) * t0 * in.w[2] * t12;
  const T t13 = t4 * t4;
  const T t14 = t2 * t2;
  const T g_ab = (T(1) / T(630)) * t10 * in.w[0] * t0 + (T(1) / T(3465)) * t0 * in.w[1] * t12 - (T(1) / T(13860)) * t0 * (T(22) * t10 * t0 * c + T(5) * (T(231) * t13 + T(4) * b * t0 * t11 - T(231) * t14) * t0 - T(8) * b * t0 * t12) * in.w[2];
  const T g_factor = -T(10) * length * inv_R2;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 57 +, 151 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * q1;
  const T t3 = T(1) / a;
  const T t4 = q0 * q0;
  const T t5 = t4 * t4;
  const T t6 = t4 * q0;
  const T t7 = t0 * q1;
  const T t8 = T(35) * t1 * slope1 - T(35) * t5 * slope0 - T(8) * t3 * (T(2) * t3 * (T(3) * t4 * slope0 - T(4) * t3 * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D - T(3) * t0 * slope1) * D + T(5) * t6 * slope0 - T(5) * t7 * slope1) * D;
  const T t9 = t5 * q0;
  const T t10 = T(63) * t2 + T(2) * t3 * t8 * b - T(63) * t9;
  const T t11 = T(63) * t2 * slope1 + T(2) * t3 * t8 * D - T(63) * t9 * slope0;
  const T t12 = T(5) * t3 * t11 + T(11) * t10 * t3 * b - T(11) * t3 * t8 * c;
  const T g_ap = (T(1) / T(630)) * t10 * t3 * in.w[1] + (T(1) / T(3465)) * t3 * in.w[2] * t12 + (T(1) / T(315)) * t3 * t8 * in.w[0];
  const T t13 = t7 * t7;
  const T t14 = t6 * t6;
  const T t15 = T(231) * t13 + T(4) * t3 * t11 * b - T(231) * t14;
  const T g_ab = (T(1) / T(13860)) * t3 * in.w[2] * (T(8) * t3 * t12 * b + T(5) * t3 * t15 - T(22) * t10 * t3 * c) + (T(1) / T(630)) * t10 * t3 * in.w[0] + (T(1) / T(3465)) * t3 * in.w[1] * t12;
  const T g_factor = -T(10) * inv_R2 * length;
  f = (T(1) / T(36036)) * (T(13) * t3 * in.w[1] * t15 + T(52) * t3 * t11 * in.w[0] - T(2) * t3 * (T(26) * t3 * c * t11 - T(13) * t3 * t15 * b - T(6) * t3 * (T(231) * t13 * slope1 + T(4) * t3 * t11 * D - T(231) * t14 * slope0)) * in.w[2]) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 49 +, 118 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t4 * t4;
  const T t6 = T(1) / a;
  const T t7 = t3 * t3;
  const T t8 = t0 * t0;
  const T t9 = t7 * q0;
  const T t10 = t8 * q1;
  const T t11 = T(2) * (T(8) * D * (T(5) * t4 * slope0 + T(2) * D * t6 * (T(3) * t3 * slope0 + T(4) * D * t6 * (T(2) * D * (in.t0 - in.t1) + q0 * slope0 - slope1 * q1) - T(3) * slope1 * t0) - T(5) * slope1 * t1) * t6 + T(35) * t7 * slope0 - T(35) * slope1 * t8) * D * t6 + T(63) * t9 * slope0 - T(63) * slope1 * t10;
  const T t12 = T(231) * t2 - T(231) * t5 - T(4) * b * t6 * t11;
  const T t13 = T(231) * slope1 * t2 - T(4) * D * t6 * t11 - T(231) * t5 * slope0;
  const T t14 = T(26) * t6 * t11 * c + T(13) * b * t12 * t6 + T(6) * t13 * t6;
  const T t15 = t2 * q1;
  const T t16 = t5 * q0;
  f = (T(1) / T(36036)) * (T(13) * in.w[1] * t12 * t6 + t6 * (T(4) * b * t6 * t14 + T(6) * t6 * (T(429) * t15 + T(2) * t13 * b * t6 - T(429) * t16) - T(13) * t12 * t6 * c) * in.w[3] + T(2) * t6 * in.w[2] * t14 - T(52) * t6 * t11 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 59 +, 154 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i10_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * q1;
  const T t3 = q0 * q0;
  const T t4 = t3 * t3;
  const T t5 = t3 * q0;
  const T t6 = T(1) / a;
  const T t7 = t0 * q1;
  const T t8 = T(35) * t1 * slope1 - T(35) * t4 * slope0 - T(8) * (T(5) * t5 * slope0 + T(2) * (T(3) * t3 * slope0 - T(3) * t0 * slope1 - T(4) * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D * t6) * D * t6 - T(5) * t7 * slope1) * D * t6;
  const T t9 = t4 * q0;
  const T t10 = T(63) * t2 * slope1 + T(2) * t8 * D * t6 - T(63) * t9 * slope0;
  const T t11 = T(2) * t8 * b * t6 + T(63) * t2 - T(63) * t9;
  const T t12 = T(5) * t10 * t6 + T(11) * b * t11 * t6 - T(11) * c * t8 * t6;
  const T t13 = t7 * t7;
  const T t14 = t5 * t5;
  const T t15 = T(231) * t13 + T(4) * b * t10 * t6 - T(231) * t14;
  const T t16 = T(22) * c * t11 * t6 - T(5) * t15 * t6 - T(8) * t12 * b * t6;
  const T g_ap = (T(1) / T(3465)) * in.w[2] * t12 * t6 + (T(1) / T(630)) * t11 * in.w[1] * t6 + (T(1) / T(315)) * t8 * in.w[0] * t6 - (T(1) / T(13860)) * in.w[3] * t16 * t6;
  const T g_ab = (T(1) / T(630)) * in.w[0] * t11 * t6 + (T(1) / T(3465)) * t12 * in.w[1] * t6 - (T(1) / T(90090)) * in.w[3] * (T(13) * b * t16 * t6 + T(26) * c * t12 * t6 - T(5) * (T(6) * (T(231) * t13 * slope1 + T(4) * t10 * D * t6 - T(231) * t14 * slope0) * t6 + T(13) * b * t15 * t6 - T(26) * c * t10 * t6) * t6) * t6 - (T(1) / T(13860)) * in.w[2] * t16 * t6;
  const T g_factor = -T(10) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 66 +, 182 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i10_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * t3;
  const T t5 = t3 * q0;
  const T t6 = t1 * q1;
  const T t7 = T(35) * slope1 * t2 - T(35) * t4 * slope0 - T(8) * (T(5) * t5 * slope0 + T(2) * D * (T(3) * t3 * slope0 - T(4) * (slope1 * q1 - T(2) * D * (in.t0 - in.t1) - q0 * slope0) * D * t0 - T(3) * slope1 * t1) * t0 - T(5) * slope1 * t6) * D * t0;
  const T t8 = t2 * q1;
  const T t9 = t4 * q0;
  const T t10 = T(2) * b * t0 * t7 + T(63) * t8 - T(63) * t9;
  const T t11 = T(2) * D * t0 * t7 + T(63) * slope1 * t8 - T(63) * t9 * slope0;
  const T t12 = T(11) * t0 * t7 * c - T(5) * t11 * t0 - T(11) * t10 * b * t0;
  const T t13 = t6 * t6;
  const T t14 = t5 * t5;
  const T t15 = T(231) * t13 + T(4) * b * t11 * t0 - T(231) * t14;
  const T t16 = T(22) * t10 * t0 * c + T(8) * b * t12 * t0 - T(5) * t0 * t15;
  const T g_ap = (T(1) / T(315)) * in.w[0] * t0 * t7 + (T(1) / T(630)) * t10 * in.w[1] * t0 - (T(1) / T(3465)) * t12 * t0 * in.w[2] - (T(1) / T(13860)) * t0 * t16 * in.w[3];
  const T t17 = T(231) * slope1 * t13 + T(4) * t11 * D * t0 - T(231) * t14 * slope0;
  const T t18 = T(13) * b * t0 * t15 + T(6) * t17 * t0 - T(26) * t11 * t0 * c;
  const T g_ab = (T(1) / T(90090)) * t0 * (T(26) * t12 * t0 * c + T(5) * t0 * t18 - T(13) * b * t0 * t16) * in.w[3] + (T(1) / T(630)) * in.w[0] * t10 * t0 - (T(1) / T(3465)) * t12 * in.w[1] * t0 - (T(1) / T(13860)) * t0 * t16 * in.w[2];
  const T g_factor = -T(10) * length * inv_R2;
  const T t19 = t13 * q1;
  const T t20 = t14 * q0;
  f = (T(1) / T(36036)) * (T(2) * t0 * t18 * in.w[2] + T(13) * in.w[1] * t0 * t15 + T(52) * in.w[0] * t11 * t0 + t0 * (T(4) * b * t0 * t18 + T(6) * (T(2) * b * t17 * t0 + T(429) * t19 - T(429) * t20) * t0 - T(13) * t0 * t15 * c) * in.w[3]) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 38 +, 91 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q0 * q0;
  const T t3 = t2 * t2;
  const T t4 = t3 * q0;
  const T t5 = t2 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = t6 * t6;
  const T t9 = t8 * q1;
  f = -(T(1) / T(15360)) * t1 * in.w[0] * length * (T(1280) * r0 * t4 * slope0 + T(11) * t1 * (T(3) * t1 * (T(48) * r0 * t5 * slope0 - T(48) * slope1 * r1 * t7 - T(7) * t1 * (T(8) * slope1 * r1 * t6 - T(8) * r0 * t2 * slope0 - T(5) * t1 * (T(3) * t1 * (r0 * slope0 - slope1 * r1 - J1 * D) * D + T(2) * r0 * q0 * slope0 - T(2) * slope1 * r1 * q1) * D) * D) * D + T(128) * r0 * t3 * slope0 - T(128) * slope1 * r1 * t8) * D - T(1280) * slope1 * r1 * t9);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 41 +, 103 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = T(3) * D * t0 * (T(48) * slope0 * r0 * t2 + T(7) * D * t0 * (T(8) * slope0 * r0 * t1 - T(8) * slope1 * r1 * q1 * q1 - T(5) * D * (T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0 - T(3) * D * (slope0 * r0 - D * J1 - slope1 * r1) * t0) * t0) - T(48) * slope1 * r1 * t4) + T(128) * slope0 * r0 * t5 - T(128) * slope1 * r1 * t6;
  const T g_ap = -(T(1) / T(1280)) * in.w[0] * t0 * t7;
  const T t8 = t6 * q1;
  const T t9 = t5 * q0;
  const T g_ab = (T(1) / T(14080)) * in.w[0] * (T(1280) * r1 * t8 - T(1280) * r0 * t9 - T(11) * t0 * t7 * b) * t0;
  const T g_factor = -T(11) * length * inv_R2;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 43 +, 115 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = T(1) / a;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t2 * q1;
  const T t8 = t5 * t5;
  const T t9 = T(128) * t3 * slope1 * r1 - T(3) * D * t4 * (T(48) * slope0 * r0 * t6 - T(7) * (T(8) * t2 * slope1 * r1 - T(8) * slope0 * r0 * t5 - T(5) * D * t4 * (T(2) * slope0 * r0 * q0 + T(3) * (slope0 * r0 - J1 * D - slope1 * r1) * D * t4 - T(2) * q1 * slope1 * r1)) * D * t4 - T(48) * t7 * slope1 * r1) - T(128) * slope0 * r0 * t8;
  const T g_ap = (T(1) / T(1280)) * in.w[0] * t9 * t4;
  const T t10 = t8 * q0;
  const T t11 = t3 * q1;
  const T g_ab = -(T(1) / T(14080)) * in.w[0] * t4 * (T(1280) * r0 * t10 - T(1280) * t11 * r1 - T(11) * t9 * b * t4);
  const T g_factor = -T(11) * length * inv_R2;
  f = (T(1) / T(15360)) * in.w[0] * length * t4 * (T(1280) * t11 * slope1 * r1 + T(11) * t9 * D * t4 - T(1280) * slope0 * r0 * t10);
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 41 +, 103 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t1 * q0;
  const T t7 = t4 * t4;
  const T t8 = t7 * q1;
  const T t9 = T(1280) * slope0 * r0 * t3 - T(11) * D * t0 * (T(3) * (T(48) * t5 * slope1 * r1 + T(7) * D * t0 * (T(5) * D * t0 * (T(2) * q1 * slope1 * r1 + T(3) * (D * J1 + slope1 * r1 - slope0 * r0) * D * t0 - T(2) * slope0 * r0 * q0) + T(8) * t4 * slope1 * r1 - T(8) * slope0 * r0 * t1) - T(48) * slope0 * r0 * t6) * D * t0 + T(128) * t7 * slope1 * r1 - T(128) * slope0 * r0 * t2) - T(1280) * t8 * slope1 * r1;
  const T t10 = t5 * t5;
  const T t11 = t6 * t6;
  f = -(T(1) / T(199680)) * length * (T(13) * t0 * in.w[0] * t9 - t0 * in.w[1] * (T(15360) * t10 * r1 - T(13) * t0 * t9 * b - T(15360) * r0 * t11));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 47 +, 127 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = T(3) * D * t0 * (T(7) * D * t0 * (T(5) * D * t0 * (T(2) * slope0 * r0 * q0 - T(2) * slope1 * r1 * q1 - T(3) * D * t0 * (slope1 * r1 + D * J1 - slope0 * r0)) + T(8) * slope0 * r0 * q0 * q0 - T(8) * slope1 * r1 * q1 * q1) + T(48) * slope0 * r0 * t2 - T(48) * slope1 * r1 * t4) + T(128) * slope0 * r0 * t5 - T(128) * slope1 * r1 * t6;
  const T t8 = t5 * q0;
  const T t9 = t6 * q1;
  const T t10 = T(11) * t0 * t7 * b + T(1280) * r0 * t8 - T(1280) * r1 * t9;
  const T g_ap = -(T(1) / T(1280)) * t0 * in.w[0] * t7 - (T(1) / T(14080)) * t0 * in.w[1] * t10;
  const T g_ab = (T(1) / T(168960)) * (T(132) * t0 * t7 * c - T(11) * t0 * (T(11) * D * t0 * t7 + T(1280) * slope0 * r0 * t8 - T(1280) * slope1 * r1 * t9) - T(24) * t0 * b * t10) * t0 * in.w[1] - (T(1) / T(14080)) * t0 * in.w[0] * t10;
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - ap1 * g_ap);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 50 +, 141 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * t6;
  const T t8 = t7 * q0;
  const T t9 = t3 * q1;
  const T t10 = t6 * q0;
  const T t11 = T(128) * r0 * t7 * slope0 - T(3) * (T(7) * (T(8) * r1 * t3 * slope1 - T(5) * (T(2) * r0 * q0 * slope0 - T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * t2 * D - T(2) * r1 * q1 * slope1) * t2 * D - T(8) * r0 * t6 * slope0) * t2 * D + T(48) * r1 * t9 * slope1 - T(48) * r0 * t10 * slope0) * t2 * D - T(128) * r1 * t4 * slope1;
  const T t12 = T(1280) * r1 * t5 - T(1280) * r0 * t8 - T(11) * b * t11 * t2;
  const T g_ap = (T(1) / T(14080)) * in.w[1] * t2 * t12 - (T(1) / T(1280)) * t11 * t2 * in.w[0];
  const T t13 = T(1280) * r0 * t8 * slope0 + T(11) * t11 * t2 * D - T(1280) * r1 * t5 * slope1;
  const T g_ab = (T(1) / T(168960)) * in.w[1] * (T(24) * b * t2 * t12 + T(132) * c * t11 * t2 - T(11) * t2 * t13) * t2 + (T(1) / T(14080)) * t2 * t12 * in.w[0];
  const T g_factor = -T(11) * inv_R2 * length;
  const T t14 = t9 * t9;
  const T t15 = t10 * t10;
  f = (T(1) / T(199680)) * length * ((T(15360) * r1 * t14 - T(13) * b * t2 * t13 - T(15360) * r0 * t15) * in.w[1] * t2 - T(13) * t2 * in.w[0] * t13);
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 46 +, 123 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = T(1) / a;
  const T t8 = t5 * q0;
  const T t9 = t2 * q1;
  const T t10 = t6 * q0;
  const T t11 = T(1280) * r1 * t4 * slope1 + T(11) * (T(128) * r1 * t3 * slope1 - T(128) * t6 * slope0 * r0 - T(3) * (T(7) * (T(8) * t5 * slope0 * r0 - T(8) * r1 * t2 * slope1 - T(5) * (T(2) * r1 * q1 * slope1 + T(3) * (r1 * slope1 + J1 * D - slope0 * r0) * D * t7 - T(2) * q0 * slope0 * r0) * D * t7) * D * t7 + T(48) * t8 * slope0 * r0 - T(48) * r1 * t9 * slope1) * D * t7) * D * t7 - T(1280) * t10 * slope0 * r0;
  const T t12 = t9 * t9;
  const T t13 = t8 * t8;
  const T t14 = T(13) * t11 * b * t7 + T(15360) * r1 * t12 - T(15360) * t13 * r0;
  f = -(T(1) / T(2795520)) * length * ((T(182) * c * t11 * t7 - T(28) * t14 * b * t7 - T(13) * (T(15360) * r1 * t12 * slope1 + T(13) * t11 * D * t7 - T(15360) * t13 * slope0 * r0) * t7) * in.w[2] * t7 - T(182) * t11 * in.w[0] * t7 - T(14) * t14 * t7 * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 53 +, 149 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = q0 * q0;
  const T t3 = t2 * t2;
  const T t4 = T(1) / a;
  const T t5 = t2 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = t6 * t6;
  const T t9 = T(128) * r0 * t3 * slope0 + T(3) * (T(7) * (T(8) * r0 * t2 * slope0 - T(8) * r1 * q1 * q1 * slope1 - T(5) * (T(2) * r1 * q1 * slope1 + T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t4 - T(2) * r0 * q0 * slope0) * D * t4) * D * t4 + T(48) * r0 * t5 * slope0 - T(48) * r1 * t7 * slope1) * D * t4 - T(128) * r1 * t8 * slope1;
  const T t10 = t3 * q0;
  const T t11 = t8 * q1;
  const T t12 = T(11) * t9 * b * t4 + T(1280) * r0 * t10 - T(1280) * r1 * t11;
  const T t13 = T(1280) * r0 * t10 * slope0 + T(11) * t9 * D * t4 - T(1280) * r1 * t11 * slope1;
  const T t14 = T(24) * t12 * b * t4 + T(11) * t13 * t4 - T(132) * c * t9 * t4;
  const T g_ap = -(T(1) / T(168960)) * in.w[2] * t14 * t4 - (T(1) / T(14080)) * in.w[1] * t12 * t4 - (T(1) / T(1280)) * t9 * in.w[0] * t4;
  const T t15 = t5 * t5;
  const T t16 = t7 * t7;
  const T g_ab = -(T(1) / T(14080)) * t12 * in.w[0] * t4 - (T(1) / T(168960)) * in.w[1] * t14 * t4 - (T(1) / T(2196480)) * in.w[2] * (T(11) * (T(15360) * r0 * t15 + T(13) * t13 * b * t4 - T(15360) * r1 * t16) * t4 + T(26) * b * t14 * t4 - T(156) * c * t12 * t4) * t4;
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 59 +, 176 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = T(1) / a;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t1 * t1;
  const T t7 = t4 * t4;
  const T t8 = T(3) * (T(48) * slope1 * r1 * t2 + T(7) * (T(8) * slope1 * r1 * t1 + T(5) * (T(2) * slope1 * r1 * q1 + T(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t3 - T(2) * r0 * q0 * slope0) * D * t3 - T(8) * r0 * q0 * q0 * slope0) * D * t3 - T(48) * r0 * t5 * slope0) * D * t3 + T(128) * slope1 * r1 * t6 - T(128) * r0 * t7 * slope0;
  const T t9 = t6 * q1;
  const T t10 = t7 * q0;
  const T t11 = T(11) * b * t8 * t3 + T(1280) * r1 * t9 - T(1280) * r0 * t10;
  const T t12 = T(1280) * r0 * t10 * slope0 - T(11) * D * t8 * t3 - T(1280) * slope1 * r1 * t9;
  const T t13 = T(11) * t12 * t3 + T(132) * c * t8 * t3 - T(24) * b * t11 * t3;
  const T g_ap = (T(1) / T(1280)) * in.w[0] * t8 * t3 + (T(1) / T(14080)) * in.w[1] * t11 * t3 - (T(1) / T(168960)) * in.w[2] * t13 * t3;
  const T t14 = t5 * t5;
  const T t15 = t2 * t2;
  const T t16 = T(13) * t12 * b * t3 + T(15360) * r0 * t14 - T(15360) * r1 * t15;
  const T g_ab = (T(1) / T(14080)) * in.w[0] * t11 * t3 - (T(1) / T(2196480)) * in.w[2] * (T(156) * c * t11 * t3 + T(26) * t13 * b * t3 + T(11) * t16 * t3) * t3 - (T(1) / T(168960)) * in.w[1] * t13 * t3;
  const T g_factor = -T(11) * inv_R2 * length;
  f = -(T(1) / T(2795520)) * (T(182) * t12 * in.w[0] * t3 + T(14) * in.w[1] * t16 * t3 - in.w[2] * (T(182) * t12 * c * t3 - T(28) * b * t16 * t3 - T(13) * (T(13) * t12 * D * t3 + T(15360) * r0 * t14 * slope0 - T(15360) * slope1 * r1 * t15) * t3) * t3) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 51 +, 141 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t3 * t3;
  const T t8 = t5 * t5;
  const T t9 = t7 * q1;
  const T t10 = t8 * q0;
  const T t11 = T(11) * t2 * D * (T(3) * (T(48) * t4 * slope1 * r1 - T(48) * slope0 * r0 * t6 - T(7) * t2 * (T(8) * slope0 * r0 * t5 + T(5) * t2 * D * (T(2) * slope0 * r0 * q0 - T(2) * q1 * slope1 * r1 - T(3) * t2 * (slope1 * r1 + J1 * D - slope0 * r0) * D) - T(8) * t3 * slope1 * r1) * D) * t2 * D + T(128) * t7 * slope1 * r1 - T(128) * slope0 * r0 * t8) + T(1280) * t9 * slope1 * r1 - T(1280) * slope0 * r0 * t10;
  const T t12 = t4 * t4;
  const T t13 = t6 * t6;
  const T t14 = T(13) * t2 * D * t11 + T(15360) * t12 * slope1 * r1 - T(15360) * slope0 * r0 * t13;
  const T t15 = T(15360) * t12 * r1 + T(13) * b * t2 * t11 - T(15360) * r0 * t13;
  const T t16 = T(182) * t2 * t11 * c - T(13) * t2 * t14 - T(28) * b * t2 * t15;
  const T t17 = t12 * q1;
  const T t18 = t13 * q0;
  f = -(T(1) / T(2795520)) * length * (t2 * t16 * in.w[2] + t2 * (T(14) * t2 * t15 * c + T(2) * b * t2 * t16 - T(13) * (T(14336) * t17 * r1 + b * t2 * t14 - T(14336) * r0 * t18) * t2) * in.w[3] - T(14) * in.w[1] * t2 * t15 - T(182) * t2 * t11 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 61 +, 179 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = t6 * q0;
  const T t8 = T(1) / a;
  const T t9 = t5 * q0;
  const T t10 = t2 * t2;
  const T t11 = T(3) * (T(48) * r1 * t3 * slope1 + T(7) * D * (T(8) * r1 * t2 * slope1 - T(8) * t5 * slope0 * r0 - T(5) * D * t8 * (T(3) * (slope0 * r0 - r1 * slope1 - J1 * D) * D * t8 + T(2) * q0 * slope0 * r0 - T(2) * r1 * q1 * slope1)) * t8 - T(48) * t9 * slope0 * r0) * D * t8 + T(128) * r1 * t10 * slope1 - T(128) * t6 * slope0 * r0;
  const T t12 = t10 * q1;
  const T t13 = T(1280) * t7 * slope0 * r0 - T(11) * t11 * D * t8 - T(1280) * r1 * t12 * slope1;
  const T t14 = t9 * t9;
  const T t15 = T(15360) * r1 * t4 - T(13) * b * t13 * t8 - T(15360) * t14 * r0;
  const T t16 = T(1280) * r1 * t12 + T(11) * t11 * b * t8 - T(1280) * t7 * r0;
  const T t17 = T(11) * t13 * t8 + T(132) * c * t11 * t8 - T(24) * b * t16 * t8;
  const T t18 = T(11) * t15 * t8 - T(156) * c * t16 * t8 - T(26) * b * t17 * t8;
  const T g_ap = (T(1) / T(2196480)) * in.w[3] * t18 * t8 + (T(1) / T(14080)) * t16 * in.w[1] * t8 + (T(1) / T(1280)) * t11 * in.w[0] * t8 - (T(1) / T(168960)) * t17 * t8 * in.w[2];
  const T g_ab = (T(1) / T(30750720)) * in.w[3] * (T(11) * (T(28) * b * t15 * t8 + T(182) * c * t13 * t8 - T(13) * (T(13) * t13 * D * t8 + T(15360) * t14 * slope0 * r0 - T(15360) * r1 * t4 * slope1) * t8) * t8 + T(182) * c * t17 * t8 + T(28) * b * t18 * t8) * t8 + (T(1) / T(2196480)) * t18 * t8 * in.w[2] + (T(1) / T(14080)) * in.w[0] * t16 * t8 - (T(1) / T(168960)) * t17 * in.w[1] * t8;
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 68 +, 207 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i11_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t1 * q1;
  const T t7 = t4 * t4;
  const T t8 = T(3) * D * t0 * (T(48) * slope0 * r0 * t5 + T(7) * D * t0 * (T(8) * slope0 * r0 * t4 + T(5) * D * t0 * (T(3) * D * t0 * (slope0 * r0 - D * J1 - slope1 * r1) + T(2) * slope0 * r0 * q0 - T(2) * slope1 * r1 * q1) - T(8) * slope1 * r1 * t1) - T(48) * slope1 * r1 * t6) + T(128) * slope0 * r0 * t7 - T(128) * slope1 * r1 * t2;
  const T t9 = t7 * q0;
  const T t10 = T(1280) * r1 * t3 - T(11) * t0 * t8 * b - T(1280) * r0 * t9;
  const T t11 = T(1280) * slope1 * r1 * t3 - T(11) * D * t0 * t8 - T(1280) * slope0 * r0 * t9;
  const T t12 = T(24) * t0 * t10 * b + T(11) * t11 * t0 + T(132) * t0 * c * t8;
  const T t13 = t6 * t6;
  const T t14 = t5 * t5;
  const T t15 = T(15360) * r1 * t13 + T(13) * t11 * t0 * b - T(15360) * r0 * t14;
  const T t16 = T(26) * t0 * t12 * b + T(11) * t0 * t15 - T(156) * t0 * t10 * c;
  const T g_ap = (T(1) / T(168960)) * t0 * in.w[2] * t12 + (T(1) / T(14080)) * t0 * t10 * in.w[1] + (T(1) / T(2196480)) * t0 * t16 * in.w[3] - (T(1) / T(1280)) * t0 * t8 * in.w[0];
  const T t17 = T(13) * D * t11 * t0 + T(15360) * slope1 * r1 * t13 - T(15360) * slope0 * r0 * t14;
  const T t18 = T(28) * t0 * t15 * b + T(13) * t0 * t17 - T(182) * t11 * t0 * c;
  const T g_ab = (T(1) / T(2196480)) * t0 * in.w[2] * t16 + (T(1) / T(30750720)) * t0 * in.w[3] * (T(28) * t0 * t16 * b + T(11) * t0 * t18 - T(182) * t0 * c * t12) + (T(1) / T(168960)) * t0 * t12 * in.w[1] + (T(1) / T(14080)) * t0 * t10 * in.w[0];
  const T g_factor = -T(11) * inv_R2 * length;
  const T t19 = t13 * q1;
  const T t20 = t14 * q0;
  f = (T(1) / T(2795520)) * (T(182) * t11 * t0 * in.w[0] + T(14) * t0 * t15 * in.w[1] + t0 * in.w[2] * t18 - t0 * in.w[3] * (T(14) * t0 * c * t15 - T(2) * t0 * t18 * b - T(13) * (T(14336) * r1 * t19 + t0 * t17 * b - T(14336) * r0 * t20) * t0)) * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 38 +, 81 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t1 * t1;
  const T t7 = t4 * t4;
  const T t8 = t6 * q0;
  const T t9 = t7 * q1;
  const T t10 = t5 * t5;
  f = -(T(1) / T(3003)) * in.w[0] * t0 * (T(231) * slope0 * t3 + T(4) * (T(2) * D * t0 * (T(8) * D * t0 * (T(5) * slope0 * t2 - T(5) * t5 * slope1 - T(2) * D * t0 * (T(3) * t4 * slope1 + T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0) - T(3) * slope0 * t1)) + T(35) * slope0 * t6 - T(35) * t7 * slope1) + T(63) * slope0 * t8 - T(63) * t9 * slope1) * D * t0 - T(231) * t10 * slope1) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 41 +, 92 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i12_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t3 * t3;
  const T t7 = t5 * q0;
  const T t8 = t6 * q1;
  const T t9 = T(2) * (T(8) * D * t0 * (T(5) * t2 * slope0 - T(5) * t4 * slope1 - T(2) * D * (T(3) * t3 * slope1 - T(3) * t1 * slope0 - T(4) * D * t0 * (T(2) * (in.t0 - in.t1) * D + q0 * slope0 - q1 * slope1)) * t0) + T(35) * t5 * slope0 - T(35) * t6 * slope1) * D * t0 + T(63) * t7 * slope0 - T(63) * t8 * slope1;
  const T g_ap = -(T(1) / T(693)) * in.w[0] * t9 * t0;
  const T t10 = t2 * t2;
  const T t11 = t4 * t4;
  const T g_ab = -(T(1) / T(2772)) * (T(4) * b * t9 * t0 + T(231) * t10 - T(231) * t11) * in.w[0] * t0;
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 43 +, 103 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t3 * q1;
  const T t6 = t1 * q0;
  const T t7 = t2 * q0;
  const T t8 = t4 * q1;
  const T t9 = T(2) * D * t0 * (T(35) * slope0 * t2 - T(35) * slope1 * t4 - T(8) * D * t0 * (T(5) * slope1 * t5 - T(5) * slope0 * t6 - T(2) * D * t0 * (T(3) * slope0 * t1 - T(3) * slope1 * t3 - T(4) * D * t0 * (slope1 * q1 + T(2) * D * (in.t1 - in.t0) - slope0 * q0)))) + T(63) * slope0 * t7 - T(63) * slope1 * t8;
  const T g_ap = -(T(1) / T(693)) * t0 * t9 * in.w[0];
  const T t10 = t6 * t6;
  const T t11 = t5 * t5;
  const T g_ab = -(T(1) / T(2772)) * t0 * in.w[0] * (T(231) * t10 + T(4) * t0 * t9 * b - T(231) * t11);
  const T g_factor = -T(12) * length * inv_R2;
  f = (T(1) / T(3003)) * length * t0 * (T(231) * slope1 * t11 - T(4) * D * t0 * t9 - T(231) * slope0 * t10) * in.w[0];
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 41 +, 91 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = q1 * q1;
  const T t5 = t4 * t4;
  const T t6 = t5 * q1;
  const T t7 = t1 * t1;
  const T t8 = t4 * q1;
  const T t9 = t7 * q0;
  const T t10 = t8 * t8;
  const T t11 = T(231) * slope0 * t3 - T(4) * (T(63) * t6 * slope1 + T(2) * D * t0 * (T(35) * t5 * slope1 - T(35) * slope0 * t7 - T(8) * D * t0 * (T(5) * slope0 * t2 - T(5) * t8 * slope1 - T(2) * D * (T(3) * t4 * slope1 - T(3) * slope0 * t1 - T(4) * D * t0 * (slope0 * q0 - q1 * slope1 - T(2) * D * (in.t1 - in.t0))) * t0)) - T(63) * slope0 * t9) * D * t0 - T(231) * t10 * slope1;
  const T t12 = t3 * q0;
  const T t13 = t10 * q1;
  f = -(T(1) / T(6006)) * (T(2) * t0 * in.w[0] * t11 + t0 * in.w[1] * (T(2) * t0 * b * t11 + T(429) * t12 - T(429) * t13)) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 47 +, 113 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i12_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = t1 * t1;
  const T t3 = T(1) / a;
  const T t4 = t0 * t0;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t6 * t6;
  const T t9 = t8 * q0;
  const T t10 = T(63) * t5 * slope1 + T(2) * D * (T(35) * t4 * slope1 - T(8) * (T(5) * t7 * slope0 - T(2) * D * (T(4) * D * (q1 * slope1 + T(2) * D * (in.t1 - in.t0) - q0 * slope0) * t3 + T(3) * t0 * slope1 - T(3) * t6 * slope0) * t3 - T(5) * t1 * slope1) * D * t3 - T(35) * t8 * slope0) * t3 - T(63) * t9 * slope0;
  const T t11 = t7 * t7;
  const T t12 = T(231) * t2 + T(4) * b * t3 * t10 - T(231) * t11;
  const T g_ap = (T(1) / T(2772)) * t12 * in.w[1] * t3 + (T(1) / T(693)) * in.w[0] * t3 * t10;
  const T g_ab = (T(1) / T(2772)) * in.w[0] * t12 * t3 + (T(1) / T(18018)) * in.w[1] * t3 * (T(6) * (T(231) * t2 * slope1 + T(4) * D * t3 * t10 - T(231) * t11 * slope0) * t3 + T(13) * t12 * b * t3 - T(26) * c * t3 * t10);
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = -g_factor * (g_ab * ab1 - ap1 * g_ap);
  grad[2] = -g_factor * (g_ab * ab2 - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 50 +, 127 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t2 * q1;
  const T t5 = T(1) / a;
  const T t6 = t0 * q0;
  const T t7 = t1 * q0;
  const T t8 = t3 * q1;
  const T t9 = T(2) * (T(35) * t1 * slope0 - T(35) * t3 * slope1 - T(8) * (T(5) * t4 * slope1 + T(2) * D * (T(3) * t2 * slope1 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t5 - T(3) * t0 * slope0) * t5 - T(5) * t6 * slope0) * D * t5) * D * t5 + T(63) * t7 * slope0 - T(63) * t8 * slope1;
  const T t10 = t6 * t6;
  const T t11 = t4 * t4;
  const T t12 = T(231) * t10 + T(4) * b * t9 * t5 - T(231) * t11;
  const T g_ap = -(T(1) / T(693)) * in.w[0] * t9 * t5 - (T(1) / T(2772)) * in.w[1] * t12 * t5;
  const T t13 = T(231) * t10 * slope0 + T(4) * D * t9 * t5 - T(231) * t11 * slope1;
  const T g_ab = -(T(1) / T(2772)) * in.w[0] * t12 * t5 - (T(1) / T(18018)) * in.w[1] * t5 * (T(13) * b * t12 * t5 + T(6) * t13 * t5 - T(26) * c * t9 * t5);
  const T g_factor = -T(12) * inv_R2 * length;
  const T t14 = t10 * q0;
  const T t15 = t11 * q1;
  f = -(T(1) / T(6006)) * (T(2) * in.w[0] * t13 * t5 + in.w[1] * (T(429) * t14 + T(2) * b * t13 * t5 - T(429) * t15) * t5) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 46 +, 110 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t6 * t6;
  const T t8 = t7 * q0;
  const T t9 = t1 * t1;
  const T t10 = t9 * q1;
  const T t11 = t5 * t5;
  const T t12 = t11 * q0;
  const T t13 = T(231) * slope0 * t7 - T(231) * slope1 * t3 - T(4) * (T(63) * slope1 * t10 + T(2) * D * t0 * (T(35) * slope1 * t9 + T(8) * D * t0 * (T(2) * (T(3) * slope1 * t1 + T(4) * (T(2) * (in.t1 - in.t0) * D + slope1 * q1 - slope0 * q0) * D * t0 - T(3) * slope0 * t5) * D * t0 + T(5) * slope1 * t2 - T(5) * slope0 * t6) - T(35) * slope0 * t11) - T(63) * slope0 * t12) * D * t0;
  const T t14 = T(429) * t4 - T(429) * t8 - T(2) * b * t0 * t13;
  f = (T(1) / T(90090)) * (T(2) * t0 * (T(15) * b * t14 * t0 + T(15) * t0 * t13 * c - T(7) * (T(2) * D * t0 * t13 + T(429) * slope0 * t8 - T(429) * slope1 * t4) * t0) * in.w[2] + T(15) * t14 * t0 * in.w[1] - T(30) * in.w[0] * t0 * t13) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 53 +, 134 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i12_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t4 * t4;
  const T t6 = t3 * t3;
  const T t7 = t6 * q0;
  const T t8 = t0 * t0;
  const T t9 = t8 * q1;
  const T t10 = T(1) / a;
  const T t11 = T(63) * t7 * slope0 - T(63) * t9 * slope1 - T(2) * D * t10 * (T(35) * t8 * slope1 - T(35) * t6 * slope0 - T(8) * (T(5) * t4 * slope0 + T(2) * (T(3) * t3 * slope0 - T(3) * t0 * slope1 - T(4) * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D * t10) * D * t10 - T(5) * t1 * slope1) * D * t10);
  const T t12 = T(231) * t2 * slope1 - T(231) * t5 * slope0 - T(4) * t11 * D * t10;
  const T t13 = T(231) * t5 + T(4) * t11 * b * t10 - T(231) * t2;
  const T t14 = T(6) * t12 * t10 + T(26) * t11 * t10 * c - T(13) * t13 * b * t10;
  const T g_ap = (T(1) / T(18018)) * in.w[2] * t14 * t10 - (T(1) / T(693)) * t11 * in.w[0] * t10 - (T(1) / T(2772)) * t13 * t10 * in.w[1];
  const T t15 = t5 * q0;
  const T t16 = t2 * q1;
  const T g_ab = (T(1) / T(18018)) * t14 * t10 * in.w[1] - (T(1) / T(2772)) * t13 * in.w[0] * t10 - (T(1) / T(36036)) * in.w[2] * (T(6) * (T(429) * t15 - T(2) * b * t12 * t10 - T(429) * t16) * t10 - T(4) * b * t14 * t10 - T(13) * t13 * t10 * c) * t10;
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - ab0 * g_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 59 +, 160 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = T(1) / a;
  const T t6 = t3 * q1;
  const T t7 = t0 * q0;
  const T t8 = t4 * q1;
  const T t9 = T(63) * t2 * slope0 + T(2) * (T(35) * t1 * slope0 - T(35) * t4 * slope1 - T(8) * D * t5 * (T(5) * t6 * slope1 + T(2) * D * t5 * (T(3) * t3 * slope1 - T(4) * D * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * t5 - T(3) * t0 * slope0) - T(5) * t7 * slope0)) * D * t5 - T(63) * t8 * slope1;
  const T t10 = t7 * t7;
  const T t11 = t6 * t6;
  const T t12 = T(231) * t10 + T(4) * t9 * b * t5 - T(231) * t11;
  const T t13 = T(231) * t10 * slope0 + T(4) * t9 * D * t5 - T(231) * t11 * slope1;
  const T t14 = T(6) * t13 * t5 + T(13) * t12 * b * t5 - T(26) * c * t9 * t5;
  const T g_ap = -(T(1) / T(693)) * t9 * in.w[0] * t5 - (T(1) / T(2772)) * t12 * t5 * in.w[1] - (T(1) / T(18018)) * t14 * in.w[2] * t5;
  const T t15 = t10 * q0;
  const T t16 = t11 * q1;
  const T t17 = T(429) * t15 + T(2) * t13 * b * t5 - T(429) * t16;
  const T g_ab = -(T(1) / T(36036)) * (T(4) * t14 * b * t5 + T(6) * t17 * t5 - T(13) * c * t12 * t5) * in.w[2] * t5 - (T(1) / T(18018)) * t14 * t5 * in.w[1] - (T(1) / T(2772)) * t12 * in.w[0] * t5;
  const T g_factor = -T(12) * inv_R2 * length;
  f = -(T(1) / T(90090)) * (T(2) * in.w[2] * (T(15) * t17 * b * t5 + T(7) * (T(429) * t15 * slope0 + T(2) * t13 * D * t5 - T(429) * t16 * slope1) * t5 - T(15) * t13 * c * t5) * t5 + T(30) * t13 * in.w[0] * t5 + T(15) * t17 * t5 * in.w[1]) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 51 +, 127 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = q1 * q1;
  const T t5 = t4 * t4;
  const T t6 = t5 * q1;
  const T t7 = t4 * q1;
  const T t8 = t1 * t1;
  const T t9 = t8 * q0;
  const T t10 = t7 * t7;
  const T t11 = T(231) * slope0 * t3 - T(4) * D * t0 * (T(63) * slope1 * t6 + T(2) * (T(8) * D * t0 * (T(5) * slope1 * t7 + T(2) * D * t0 * (T(3) * slope1 * t4 - T(3) * slope0 * t1 - T(4) * D * t0 * (slope0 * q0 - slope1 * q1 - T(2) * D * (in.t1 - in.t0))) - T(5) * slope0 * t2) + T(35) * slope1 * t5 - T(35) * slope0 * t8) * D * t0 - T(63) * slope0 * t9) - T(231) * slope1 * t10;
  const T t12 = t3 * q0;
  const T t13 = t10 * q1;
  const T t14 = T(2) * D * t0 * t11 + T(429) * slope0 * t12 - T(429) * slope1 * t13;
  const T t15 = T(2) * t0 * t11 * b + T(429) * t12 - T(429) * t13;
  const T t16 = T(7) * t14 * t0 + T(15) * t0 * t15 * b - T(15) * t0 * t11 * c;
  const T t17 = t8 * t8;
  const T t18 = t5 * t5;
  f = -(T(1) / T(720720)) * length * (T(16) * t0 * t16 * in.w[2] + T(240) * t0 * t11 * in.w[0] + T(120) * in.w[1] * t0 * t15 - t0 * (T(120) * t0 * c * t15 - T(7) * t0 * (T(16) * t14 * t0 * b + T(6435) * t17 - T(6435) * t18) - T(32) * t0 * t16 * b) * in.w[3]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 61 +, 163 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i12_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * t4;
  const T t6 = t4 * q0;
  const T t7 = t1 * q1;
  const T t8 = t5 * q0;
  const T t9 = T(63) * t3 * slope1 + T(2) * (T(35) * t2 * slope1 - T(35) * t5 * slope0 - T(8) * (T(2) * (T(4) * D * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * t0 + T(3) * t4 * slope0 - T(3) * t1 * slope1) * D * t0 + T(5) * t6 * slope0 - T(5) * t7 * slope1) * D * t0) * D * t0 - T(63) * t8 * slope0;
  const T t10 = t6 * t6;
  const T t11 = t7 * t7;
  const T t12 = T(231) * t10 * slope0 - T(231) * t11 * slope1 - T(4) * D * t0 * t9;
  const T t13 = T(231) * t10 - T(231) * t11 - T(4) * b * t0 * t9;
  const T t14 = T(6) * t12 * t0 + T(13) * t13 * b * t0 + T(26) * c * t0 * t9;
  const T t15 = t10 * q0;
  const T t16 = t11 * q1;
  const T t17 = T(2) * b * t12 * t0 + T(429) * t15 - T(429) * t16;
  const T t18 = T(4) * t14 * b * t0 + T(6) * t17 * t0 - T(13) * c * t13 * t0;
  const T g_ap = (T(1) / T(693)) * in.w[0] * t0 * t9 - (T(1) / T(36036)) * in.w[3] * t0 * t18 - (T(1) / T(18018)) * t14 * t0 * in.w[2] - (T(1) / T(2772)) * t13 * in.w[1] * t0;
  const T g_ab = (T(1) / T(90090)) * in.w[3] * (T(2) * (T(15) * c * t12 * t0 - T(7) * (T(429) * t15 * slope0 + T(2) * D * t12 * t0 - T(429) * t16 * slope1) * t0 - T(15) * t17 * b * t0) * t0 + T(5) * t14 * c * t0 - T(5) * b * t0 * t18) * t0 - (T(1) / T(2772)) * t13 * in.w[0] * t0 - (T(1) / T(36036)) * t0 * in.w[2] * t18 - (T(1) / T(18018)) * t14 * in.w[1] * t0;
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 68 +, 191 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i12_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t1 * q1;
  const T t7 = t4 * t4;
  const T t8 = t7 * q0;
  const T t9 = T(63) * t3 * slope1 + T(2) * D * t0 * (T(35) * t2 * slope1 - T(8) * D * t0 * (T(5) * slope0 * t5 + T(2) * (T(3) * slope0 * t4 - T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0) - T(3) * t1 * slope1) * D * t0 - T(5) * t6 * slope1) - T(35) * slope0 * t7) - T(63) * slope0 * t8;
  const T t10 = t6 * t6;
  const T t11 = t5 * t5;
  const T t12 = T(4) * t9 * t0 * b + T(231) * t10 - T(231) * t11;
  const T t13 = T(231) * t10 * slope1 + T(4) * D * t9 * t0 - T(231) * slope0 * t11;
  const T t14 = T(6) * t0 * t13 + T(13) * t0 * b * t12 - T(26) * t9 * t0 * c;
  const T t15 = t10 * q1;
  const T t16 = t11 * q0;
  const T t17 = T(2) * t0 * t13 * b + T(429) * t15 - T(429) * t16;
  const T t18 = T(13) * t0 * c * t12 - T(4) * t0 * t14 * b - T(6) * t0 * t17;
  const T g_ap = (T(1) / T(2772)) * in.w[1] * t0 * t12 + (T(1) / T(693)) * t9 * t0 * in.w[0] + (T(1) / T(18018)) * t0 * t14 * in.w[2] - (T(1) / T(36036)) * t0 * in.w[3] * t18;
  const T t19 = T(429) * t15 * slope1 + T(2) * D * t0 * t13 - T(429) * slope0 * t16;
  const T t20 = T(15) * t0 * t17 * b + T(7) * t0 * t19 - T(15) * t0 * t13 * c;
  const T g_ab = (T(1) / T(18018)) * in.w[1] * t0 * t14 + (T(1) / T(2772)) * t0 * in.w[0] * t12 - (T(1) / T(90090)) * t0 * (T(5) * t0 * t14 * c + T(5) * t0 * t18 * b - T(2) * t20 * t0) * in.w[3] - (T(1) / T(36036)) * t0 * in.w[2] * t18;
  const T g_factor = -T(12) * length * inv_R2;
  const T t21 = t2 * t2;
  const T t22 = t7 * t7;
  f = (T(1) / T(720720)) * length * (T(240) * t0 * t13 * in.w[0] + T(16) * t20 * t0 * in.w[2] + T(120) * in.w[1] * t0 * t17 + (T(32) * t20 * t0 * b + T(7) * t0 * (T(16) * t0 * t19 * b + T(6435) * t21 - T(6435) * t22) - T(120) * t0 * t17 * c) * t0 * in.w[3]);
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = g_factor * (g_ap * ap1 - g_ab * ab1);
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 40 +, 102 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = T(1) / a;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t2 * q1;
  const T t9 = t6 * t6;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = t7 * t7;
  f = (T(1) / T(215040)) * length * (T(13) * D * (T(1280) * t4 * slope1 * r1 - T(11) * D * t5 * (T(3) * D * t5 * (T(48) * slope0 * r0 * t7 + T(7) * D * (T(8) * slope0 * r0 * t6 - T(8) * t2 * slope1 * r1 - T(5) * D * (T(3) * (slope1 * r1 + J1 * D - slope0 * r0) * D * t5 + T(2) * q1 * slope1 * r1 - T(2) * slope0 * r0 * q0) * t5) * t5 - T(48) * t8 * slope1 * r1) + T(128) * slope0 * r0 * t9 - T(128) * t3 * slope1 * r1) - T(1280) * slope0 * r0 * t10) * t5 + T(15360) * t11 * slope1 * r1 - T(15360) * slope0 * r0 * t12) * t5 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 43 +, 113 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * t4;
  const T t6 = t4 * q0;
  const T t7 = t1 * q1;
  const T t8 = T(1) / a;
  const T t9 = t5 * q0;
  const T t10 = T(1280) * slope1 * r1 * t3 + T(11) * (T(128) * slope1 * r1 * t2 - T(128) * r0 * t5 * slope0 - T(3) * (T(48) * r0 * t6 * slope0 - T(48) * slope1 * r1 * t7 - T(7) * (T(5) * (T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t8 + T(2) * slope1 * r1 * q1 - T(2) * r0 * q0 * slope0) * D * t8 + T(8) * slope1 * r1 * t1 - T(8) * r0 * t4 * slope0) * D * t8) * D * t8) * D * t8 - T(1280) * r0 * t9 * slope0;
  const T g_ap = (T(1) / T(15360)) * in.w[0] * t10 * t8;
  const T t11 = t7 * t7;
  const T t12 = t6 * t6;
  const T g_ab = (T(1) / T(199680)) * in.w[0] * (T(15360) * r1 * t11 + T(13) * b * t10 * t8 - T(15360) * r0 * t12) * t8;
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 45 +, 126 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * t3;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t3 * q0;
  const T t8 = t5 * t5;
  const T t9 = t4 * q0;
  const T t10 = t8 * q1;
  const T t11 = T(11) * D * (T(128) * slope0 * r0 * t4 - T(3) * D * t2 * (T(48) * t6 * slope1 * r1 - T(48) * slope0 * r0 * t7 - T(7) * (T(5) * D * t2 * (T(3) * (slope0 * r0 - slope1 * r1 - J1 * D) * D * t2 + T(2) * slope0 * r0 * q0 - T(2) * q1 * slope1 * r1) + T(8) * slope0 * r0 * t3 - T(8) * t5 * slope1 * r1) * D * t2) - T(128) * t8 * slope1 * r1) * t2 + T(1280) * slope0 * r0 * t9 - T(1280) * t10 * slope1 * r1;
  const T g_ap = -(T(1) / T(15360)) * t2 * t11 * in.w[0];
  const T t12 = t6 * t6;
  const T t13 = t7 * t7;
  const T g_ab = (T(1) / T(199680)) * (T(15360) * t12 * r1 - T(13) * b * t2 * t11 - T(15360) * r0 * t13) * t2 * in.w[0];
  const T g_factor = -T(13) * length * inv_R2;
  f = -(T(1) / T(215040)) * length * t2 * (T(15360) * slope0 * r0 * t13 + T(13) * D * t2 * t11 - T(15360) * t12 * slope1 * r1) * in.w[0];
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 43 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t2 * t2;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * q0;
  const T t9 = t7 * t7;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = T(15360) * slope1 * r1 * t4 + T(13) * D * t1 * (T(1280) * slope1 * r1 * t6 + T(11) * D * t1 * (T(128) * slope1 * r1 * t5 - T(3) * D * t1 * (T(48) * r0 * t8 * slope0 + T(7) * D * t1 * (T(8) * r0 * t7 * slope0 - T(5) * D * t1 * (T(2) * slope1 * r1 * q1 - T(3) * D * t1 * (r0 * slope0 - D * J1 - slope1 * r1) - T(2) * r0 * q0 * slope0) - T(8) * slope1 * r1 * t2) - T(48) * slope1 * r1 * t3) - T(128) * r0 * t9 * slope0) - T(1280) * r0 * t10 * slope0) - T(15360) * r0 * t11 * slope0;
  const T t13 = t11 * q0;
  const T t14 = t4 * q1;
  f = (T(1) / T(215040)) * (t1 * in.w[0] * t12 - t1 * (T(14336) * r0 * t13 - t1 * t12 * b - T(14336) * r1 * t14) * in.w[1]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 49 +, 136 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  const T t2 = q0 * q0;
  const T t3 = t2 * t2;
  const T t4 = t3 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * t5;
  const T t7 = t5 * q1;
  const T t8 = T(1) / a;
  const T t9 = t2 * q0;
  const T t10 = t6 * q1;
  const T t11 = T(1280) * r0 * t4 * slope0 + T(11) * (T(128) * r0 * t3 * slope0 - T(128) * r1 * t6 * slope1 - T(3) * (T(48) * r1 * t7 * slope1 - T(7) * D * t8 * (T(8) * r0 * t2 * slope0 - T(5) * D * (T(2) * r1 * q1 * slope1 - T(2) * r0 * q0 * slope0 - T(3) * (r0 * slope0 - r1 * slope1 - J1 * D) * D * t8) * t8 - T(8) * r1 * t5 * slope1) - T(48) * r0 * t9 * slope0) * D * t8) * D * t8 - T(1280) * r1 * t10 * slope1;
  const T t12 = t9 * t9;
  const T t13 = t7 * t7;
  const T t14 = T(15360) * r0 * t12 + T(13) * t11 * b * t8 - T(15360) * r1 * t13;
  const T g_ap = -(T(1) / T(15360)) * in.w[0] * t11 * t8 - (T(1) / T(199680)) * in.w[1] * t14 * t8;
  const T g_ab = (T(1) / T(2795520)) * in.w[1] * (T(182) * c * t11 * t8 + T(13) * (T(15360) * r1 * t13 * slope1 - T(13) * t11 * D * t8 - T(15360) * r0 * t12 * slope0) * t8 - T(28) * b * t14 * t8) * t8 - (T(1) / T(199680)) * in.w[0] * t14 * t8;
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = -g_factor * (ab2 * g_ab - ap2 * g_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 52 +, 151 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = t1 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t5 * t5;
  const T t8 = t7 * q1;
  const T t9 = T(1280) * slope0 * r0 * t3 + T(11) * t0 * (T(3) * t0 * (T(7) * t0 * (T(8) * slope0 * r0 * t1 - T(5) * t0 * (T(2) * slope1 * r1 * q1 + T(3) * t0 * (slope1 * r1 + J1 * D - slope0 * r0) * D - T(2) * slope0 * r0 * q0) * D - T(8) * slope1 * r1 * q1 * q1) * D + T(48) * slope0 * r0 * t4 - T(48) * slope1 * r1 * t6) * D + T(128) * slope0 * r0 * t2 - T(128) * slope1 * r1 * t7) * D - T(1280) * slope1 * r1 * t8;
  const T t10 = t4 * t4;
  const T t11 = t6 * t6;
  const T t12 = T(13) * t0 * t9 * b + T(15360) * r0 * t10 - T(15360) * r1 * t11;
  const T g_ap = -(T(1) / T(199680)) * in.w[1] * t0 * t12 - (T(1) / T(15360)) * t0 * t9 * in.w[0];
  const T t13 = T(15360) * slope1 * r1 * t11 - T(15360) * slope0 * r0 * t10 - T(13) * t0 * t9 * D;
  const T g_ab = -(T(1) / T(199680)) * t0 * t12 * in.w[0] - (T(1) / T(2795520)) * in.w[1] * t0 * (T(28) * t0 * t12 * b - T(13) * t0 * t13 - T(182) * t0 * t9 * c);
  const T g_factor = -T(13) * inv_R2 * length;
  const T t14 = t11 * q1;
  const T t15 = t10 * q0;
  f = (T(1) / T(215040)) * (in.w[1] * t0 * (T(14336) * r1 * t14 + t0 * t13 * b - T(14336) * r0 * t15) + t0 * in.w[0] * t13) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 48 +, 133 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = t3 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t5 * t5;
  const T t8 = t1 * t1;
  const T t9 = t7 * q1;
  const T t10 = t8 * q0;
  const T t11 = t6 * t6;
  const T t12 = T(13) * D * t0 * (T(11) * D * t0 * (T(3) * D * t0 * (T(7) * D * t0 * (T(8) * slope1 * r1 * q1 * q1 + T(5) * D * (T(3) * D * t0 * (slope1 * r1 + D * J1 - slope0 * r0) + T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0) * t0 - T(8) * slope0 * r0 * t1) + T(48) * slope1 * r1 * t6 - T(48) * slope0 * r0 * t2) + T(128) * slope1 * r1 * t7 - T(128) * slope0 * r0 * t8) + T(1280) * slope1 * r1 * t9 - T(1280) * slope0 * r0 * t10) + T(15360) * slope1 * r1 * t11 - T(15360) * slope0 * r0 * t3;
  const T t13 = t11 * q1;
  const T t14 = T(14336) * r0 * t4 - t0 * t12 * b - T(14336) * r1 * t13;
  f = -(T(1) / T(3440640)) * length * (T(16) * t0 * in.w[1] * t14 + t0 * in.w[2] * (T(32) * t0 * t14 * b + T(16) * t0 * c * t12 - T(15) * t0 * (D * t0 * t12 + T(14336) * slope1 * r1 * t13 - T(14336) * slope0 * r0 * t4)) - T(16) * t0 * t12 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 55 +, 158 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = t7 * q0;
  const T t9 = t1 * t1;
  const T t10 = t9 * q1;
  const T t11 = T(1280) * slope0 * r0 * t8 + T(11) * D * t0 * (T(128) * slope0 * r0 * t7 - T(128) * slope1 * r1 * t9 - T(3) * (T(48) * slope1 * r1 * t2 + T(7) * (T(5) * D * t0 * (T(2) * slope1 * r1 * q1 + T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) - T(2) * slope0 * r0 * q0) + T(8) * slope1 * r1 * t1 - T(8) * slope0 * r0 * t4) * D * t0 - T(48) * slope0 * r0 * t5) * D * t0) - T(1280) * slope1 * r1 * t10;
  const T t12 = T(15360) * r1 * t3 - T(15360) * r0 * t6 - T(13) * t0 * t11 * b;
  const T t13 = T(13) * D * t0 * t11 + T(15360) * slope0 * r0 * t6 - T(15360) * slope1 * r1 * t3;
  const T t14 = T(28) * t0 * t12 * b + T(182) * t0 * t11 * c - T(13) * t0 * t13;
  const T g_ap = (T(1) / T(2795520)) * t0 * t14 * in.w[2] + (T(1) / T(199680)) * t0 * in.w[1] * t12 - (T(1) / T(15360)) * in.w[0] * t0 * t11;
  const T t15 = t3 * q1;
  const T t16 = t6 * q0;
  const T g_ab = (T(1) / T(2795520)) * t0 * t14 * in.w[1] + (T(1) / T(199680)) * in.w[0] * t0 * t12 + (T(1) / T(2795520)) * (T(13) * t0 * (T(14336) * r1 * t15 - t0 * t13 * b - T(14336) * r0 * t16) + T(2) * t0 * t14 * b - T(14) * t0 * c * t12) * t0 * in.w[2];
  const T g_factor = -T(13) * length * inv_R2;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 61 +, 184 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = t1 * t1;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * t6;
  const T t8 = t7 * q1;
  const T t9 = t6 * q1;
  const T t10 = T(1280) * slope0 * r0 * t5 - T(1280) * t8 * slope1 * r1 - T(11) * D * t0 * (T(3) * D * t0 * (T(7) * D * (T(5) * D * t0 * (T(2) * q1 * slope1 * r1 - T(3) * D * t0 * (slope0 * r0 - D * J1 - slope1 * r1) - T(2) * slope0 * r0 * q0) + T(8) * t6 * slope1 * r1 - T(8) * slope0 * r0 * t1) * t0 + T(48) * t9 * slope1 * r1 - T(48) * slope0 * r0 * t2) + T(128) * t7 * slope1 * r1 - T(128) * slope0 * r0 * t4);
  const T t11 = t9 * t9;
  const T t12 = T(15360) * slope0 * r0 * t3 + T(13) * t10 * D * t0 - T(15360) * t11 * slope1 * r1;
  const T t13 = T(13) * t10 * t0 * b + T(15360) * r0 * t3 - T(15360) * t11 * r1;
  const T t14 = T(13) * t0 * t12 + T(28) * t13 * t0 * b - T(182) * t10 * t0 * c;
  const T g_ap = -(T(1) / T(2795520)) * t0 * in.w[2] * t14 - (T(1) / T(199680)) * t13 * t0 * in.w[1] - (T(1) / T(15360)) * t10 * in.w[0] * t0;
  const T t15 = t3 * q0;
  const T t16 = t11 * q1;
  const T t17 = t0 * t12 * b + T(14336) * r0 * t15 - T(14336) * t16 * r1;
  const T g_ab = -(T(1) / T(199680)) * in.w[0] * t13 * t0 - (T(1) / T(2795520)) * t0 * in.w[2] * (T(13) * t17 * t0 + T(2) * t0 * t14 * b - T(14) * t13 * t0 * c) - (T(1) / T(2795520)) * t0 * in.w[1] * t14;
  const T g_factor = -T(13) * length * inv_R2;
  f = -(T(1) / T(3440640)) * length * (T(16) * in.w[0] * t0 * t12 + T(16) * t17 * t0 * in.w[1] + (T(15) * t0 * (T(14336) * slope0 * r0 * t15 + D * t0 * t12 - T(14336) * t16 * slope1 * r1) + T(32) * t17 * t0 * b - T(16) * t0 * t12 * c) * t0 * in.w[2]);
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 53 +, 152 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = t3 * t3;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = t7 * t7;
  const T t9 = t8 * q1;
  const T t10 = T(1) / a;
  const T t11 = t6 * t6;
  const T t12 = t11 * q1;
  const T t13 = t2 * t2;
  const T t14 = t13 * q0;
  const T t15 = T(13) * (T(1280) * r1 * t12 * slope1 + T(11) * D * t10 * (T(128) * r1 * t11 * slope1 - T(3) * (T(48) * t3 * slope0 * r0 + T(7) * D * t10 * (T(8) * t2 * slope0 * r0 - T(8) * r1 * t6 * slope1 - T(5) * D * t10 * (T(2) * r1 * q1 * slope1 + T(3) * (J1 * D + r1 * slope1 - slope0 * r0) * D * t10 - T(2) * q0 * slope0 * r0)) - T(48) * r1 * t7 * slope1) * D * t10 - T(128) * t13 * slope0 * r0) - T(1280) * t14 * slope0 * r0) * D * t10 + T(15360) * r1 * t8 * slope1 - T(15360) * t4 * slope0 * r0;
  const T t16 = T(14336) * t5 * r0 - T(14336) * r1 * t9 - b * t10 * t15;
  const T t17 = T(14336) * t5 * slope0 * r0 - T(14336) * r1 * t9 * slope1 - D * t10 * t15;
  const T t18 = T(15) * t17 * t10 + T(32) * t16 * b * t10 + T(16) * t10 * t15 * c;
  const T t19 = t13 * t13;
  const T t20 = t11 * t11;
  f = -(T(1) / T(58490880)) * (T(272) * t16 * in.w[1] * t10 + in.w[3] * t10 * (T(34) * t18 * b * t10 + T(15) * t10 * (T(229376) * t19 * r0 + T(17) * b * t17 * t10 - T(229376) * r1 * t20) - T(272) * t16 * t10 * c) + T(17) * t18 * t10 * in.w[2] - T(272) * in.w[0] * t10 * t15) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 63 +, 188 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (inv_R2 * cross_cross - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * t6;
  const T t8 = t3 * q1;
  const T t9 = t6 * q0;
  const T t10 = t7 * q0;
  const T t11 = T(1280) * r1 * t5 * slope1 - T(11) * (T(128) * t7 * slope0 * r0 - T(3) * (T(48) * r1 * t8 * slope1 - T(7) * (T(5) * D * t2 * (T(2) * q0 * slope0 * r0 + T(3) * (slope0 * r0 - J1 * D - r1 * slope1) * D * t2 - T(2) * r1 * q1 * slope1) + T(8) * t6 * slope0 * r0 - T(8) * r1 * t3 * slope1) * D * t2 - T(48) * t9 * slope0 * r0) * D * t2 - T(128) * r1 * t4 * slope1) * D * t2 - T(1280) * t10 * slope0 * r0;
  const T t12 = t8 * t8;
  const T t13 = t9 * t9;
  const T t14 = T(15360) * r1 * t12 + T(13) * b * t2 * t11 - T(15360) * t13 * r0;
  const T t15 = T(15360) * t13 * slope0 * r0 - T(13) * D * t2 * t11 - T(15360) * r1 * t12 * slope1;
  const T t16 = T(182) * c * t2 * t11 + T(13) * t15 * t2 - T(28) * b * t14 * t2;
  const T t17 = t12 * q1;
  const T t18 = t13 * q0;
  const T t19 = T(14336) * r1 * t17 - t15 * b * t2 - T(14336) * t18 * r0;
  const T t20 = T(2) * b * t2 * t16 + T(14) * c * t14 * t2 - T(13) * t19 * t2;
  const T g_ap = (T(1) / T(15360)) * in.w[0] * t2 * t11 + (T(1) / T(199680)) * t14 * t2 * in.w[1] - (T(1) / T(2795520)) * in.w[2] * t2 * t16 - (T(1) / T(2795520)) * t20 * in.w[3] * t2;
  const T g_ab = (T(1) / T(44728320)) * (T(16) * c * t2 * t16 + T(13) * (T(32) * b * t19 * t2 + T(16) * c * t15 * t2 - T(15) * (T(14336) * t18 * slope0 * r0 + t15 * D * t2 - T(14336) * r1 * t17 * slope1) * t2) * t2 - T(32) * b * t20 * t2) * in.w[3] * t2 + (T(1) / T(199680)) * in.w[0] * t14 * t2 - (T(1) / T(2795520)) * t2 * t16 * in.w[1] - (T(1) / T(2795520)) * in.w[2] * t20 * t2;
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = g_factor * (g_ap * ap2 - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 70 +, 218 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i13_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = t5 * q0;
  const T t8 = t2 * q1;
  const T t9 = t6 * q0;
  const T t10 = T(1280) * slope1 * r1 * t4 + T(11) * D * t1 * (T(128) * slope1 * r1 * t3 - T(128) * r0 * t6 * slope0 - T(3) * D * (T(7) * D * t1 * (T(5) * D * t1 * (T(2) * r0 * q0 * slope0 + T(3) * D * t1 * (r0 * slope0 - D * J1 - slope1 * r1) - T(2) * slope1 * r1 * q1) + T(8) * r0 * t5 * slope0 - T(8) * slope1 * r1 * t2) + T(48) * r0 * t7 * slope0 - T(48) * slope1 * r1 * t8) * t1) - T(1280) * r0 * t9 * slope0;
  const T t11 = t7 * t7;
  const T t12 = t8 * t8;
  const T t13 = T(15360) * r0 * t11 - T(15360) * r1 * t12 - T(13) * t1 * t10 * b;
  const T t14 = T(15360) * slope1 * r1 * t12 + T(13) * D * t1 * t10 - T(15360) * r0 * t11 * slope0;
  const T t15 = T(182) * t1 * t10 * c + T(28) * t1 * b * t13 - T(13) * t1 * t14;
  const T t16 = t11 * q0;
  const T t17 = t12 * q1;
  const T t18 = T(14336) * r0 * t16 - T(14336) * r1 * t17 - t1 * b * t14;
  const T t19 = T(13) * t1 * t18 + T(2) * t1 * b * t15 - T(14) * t1 * c * t13;
  const T g_ap = (T(1) / T(15360)) * t1 * t10 * in.w[0] - (T(1) / T(199680)) * t1 * in.w[1] * t13 - (T(1) / T(2795520)) * t1 * in.w[2] * t15 - (T(1) / T(2795520)) * t1 * t19 * in.w[3];
  const T t20 = T(14336) * slope1 * r1 * t17 + D * t1 * t14 - T(14336) * r0 * t16 * slope0;
  const T t21 = T(32) * t1 * b * t18 + T(16) * t1 * c * t14 - T(15) * t1 * t20;
  const T g_ab = (T(1) / T(44728320)) * t1 * in.w[3] * (T(16) * t1 * c * t15 - T(32) * t1 * t19 * b - T(13) * t1 * t21) - (T(1) / T(2795520)) * t1 * t15 * in.w[1] - (T(1) / T(2795520)) * t1 * in.w[2] * t19 - (T(1) / T(199680)) * t1 * in.w[0] * t13;
  const T g_factor = -T(13) * inv_R2 * length;
  const T t22 = t3 * t3;
  const T t23 = t6 * t6;
  f = (T(1) / T(58490880)) * (T(272) * t1 * in.w[0] * t14 + t1 * (T(15) * t1 * (T(229376) * r1 * t22 + T(17) * t1 * t20 * b - T(229376) * r0 * t23) + T(272) * t1 * c * t18 - T(34) * t1 * t21 * b) * in.w[3] - T(17) * t1 * t21 * in.w[2] - T(272) * t1 * t18 * in.w[1]) * length;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 40 +, 90 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t1 * q0;
  const T t7 = t4 * t4;
  const T t8 = t7 * q1;
  const T t9 = t6 * t6;
  const T t10 = t5 * t5;
  const T t11 = t9 * q0;
  const T t12 = t10 * q1;
  f = -(T(1) / T(6435)) * length * t0 * (T(2) * D * t0 * (T(4) * D * t0 * (T(63) * t3 * slope0 + T(2) * D * t0 * (T(35) * t2 * slope0 - T(8) * (T(5) * slope1 * t5 + T(2) * D * t0 * (T(3) * slope1 * t4 + T(4) * (slope1 * q1 - T(2) * D * (in.t0 - in.t1) - q0 * slope0) * D * t0 - T(3) * t1 * slope0) - T(5) * t6 * slope0) * D * t0 - T(35) * slope1 * t7) - T(63) * slope1 * t8) + T(231) * t9 * slope0 - T(231) * slope1 * t10) + T(429) * t11 * slope0 - T(429) * slope1 * t12) * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 43 +, 101 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i14_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t1 * q1;
  const T t7 = t4 * t4;
  const T t8 = t7 * q0;
  const T t9 = t6 * t6;
  const T t10 = t5 * t5;
  const T t11 = T(4) * D * t0 * (T(63) * t3 * slope1 + T(2) * D * t0 * (T(35) * t2 * slope1 - T(8) * D * t0 * (T(5) * slope0 * t5 - T(5) * t6 * slope1 - T(2) * D * t0 * (T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0) + T(3) * t1 * slope1 - T(3) * slope0 * t4)) - T(35) * slope0 * t7) - T(63) * slope0 * t8) + T(231) * t9 * slope1 - T(231) * slope0 * t10;
  const T g_ap = (T(1) / T(3003)) * t0 * t11 * in.w[0];
  const T t12 = t9 * q1;
  const T t13 = t10 * q0;
  const T g_ab = (T(1) / T(6006)) * t0 * (T(429) * t12 + T(2) * t0 * t11 * b - T(429) * t13) * in.w[0];
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = (ap0 * g_ap - g_ab * ab0) * g_factor;
  grad[1] = (ap1 * g_ap - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 45 +, 113 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t4 * t4;
  const T t7 = t1 * t1;
  const T t8 = t6 * q0;
  const T t9 = t7 * q1;
  const T t10 = t5 * t5;
  const T t11 = T(231) * t3 * slope1 - T(4) * (T(2) * (T(8) * D * t0 * (T(2) * (T(3) * q0 * q0 * slope0 - T(3) * t1 * slope1 - T(4) * D * t0 * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0)) * D * t0 + T(5) * t5 * slope0 - T(5) * t2 * slope1) + T(35) * t6 * slope0 - T(35) * t7 * slope1) * D * t0 + T(63) * t8 * slope0 - T(63) * t9 * slope1) * D * t0 - T(231) * t10 * slope0;
  const T g_ap = (T(1) / T(3003)) * in.w[0] * t0 * t11;
  const T t12 = t10 * q0;
  const T t13 = t3 * q1;
  const T g_ab = -(T(1) / T(6006)) * in.w[0] * (T(429) * t12 - T(429) * t13 - T(2) * b * t0 * t11) * t0;
  const T g_factor = -T(14) * length * inv_R2;
  f = (T(1) / T(6435)) * in.w[0] * (T(2) * D * t0 * t11 + T(429) * t13 * slope1 - T(429) * t12 * slope0) * length * t0;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (g_ap * ap2 - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 43 +, 100 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t7 * q0;
  const T t10 = t8 * q0;
  const T t11 = t9 * t9;
  const T t12 = t11 * q0;
  const T t13 = T(429) * slope1 * t4 + T(2) * (T(231) * slope1 * t3 + T(4) * (T(63) * slope1 * t6 + T(2) * D * t0 * (T(35) * slope1 * t5 - T(35) * slope0 * t8 - T(8) * D * t0 * (T(5) * slope0 * t9 - T(2) * D * t0 * (T(4) * D * t0 * (T(2) * (in.t1 - in.t0) * D + slope1 * q1 - slope0 * q0) + T(3) * slope1 * t1 - T(3) * slope0 * t7) - T(5) * slope1 * t2)) - T(63) * slope0 * t10) * D * t0 - T(231) * slope0 * t11) * D * t0 - T(429) * slope0 * t12;
  const T t14 = t5 * t5;
  const T t15 = t8 * t8;
  f = (T(1) / T(102960)) * ((T(16) * b * t0 * t13 + T(6435) * t14 - T(6435) * t15) * t0 * in.w[1] + T(16) * t0 * t13 * in.w[0]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 49 +, 123 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i14_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = T(1) / a;
  const T t3 = q0 * q0;
  const T t4 = t3 * q0;
  const T t5 = t0 * t0;
  const T t6 = t3 * t3;
  const T t7 = t5 * q1;
  const T t8 = t6 * q0;
  const T t9 = t1 * t1;
  const T t10 = t4 * t4;
  const T t11 = T(4) * (T(2) * (T(8) * (T(5) * t1 * slope1 + T(2) * D * t2 * (T(3) * t0 * slope1 - T(4) * D * t2 * (q0 * slope0 - T(2) * D * (in.t1 - in.t0) - q1 * slope1) - T(3) * q0 * q0 * slope0) - T(5) * t4 * slope0) * D * t2 + T(35) * t5 * slope1 - T(35) * t6 * slope0) * D * t2 + T(63) * t7 * slope1 - T(63) * t8 * slope0) * D * t2 + T(231) * t9 * slope1 - T(231) * t10 * slope0;
  const T t12 = t10 * q0;
  const T t13 = t9 * q1;
  const T t14 = T(429) * t12 - T(429) * t13 - T(2) * t11 * b * t2;
  const T g_ap = (T(1) / T(3003)) * t11 * in.w[0] * t2 - (T(1) / T(6006)) * in.w[1] * t2 * t14;
  const T g_ab = -(T(1) / T(45045)) * (T(15) * c * t11 * t2 + T(7) * (T(429) * t12 * slope0 - T(429) * t13 * slope1 - T(2) * t11 * D * t2) * t2 + T(15) * b * t2 * t14) * in.w[1] * t2 - (T(1) / T(6006)) * in.w[0] * t2 * t14;
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 52 +, 136 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * q0;
  const T t2 = t1 * t1;
  const T t3 = q1 * q1;
  const T t4 = t3 * q1;
  const T t5 = t4 * t4;
  const T t6 = T(1) / a;
  const T t7 = t3 * t3;
  const T t8 = t0 * t0;
  const T t9 = t7 * q1;
  const T t10 = t8 * q0;
  const T t11 = T(231) * t2 * slope0 - T(231) * t5 * slope1 - T(4) * (T(2) * D * (T(8) * D * (T(5) * t4 * slope1 + T(2) * (T(3) * t3 * slope1 + T(4) * D * t6 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - q0 * slope0) - T(3) * t0 * slope0) * D * t6 - T(5) * t1 * slope0) * t6 + T(35) * t7 * slope1 - T(35) * t8 * slope0) * t6 + T(63) * t9 * slope1 - T(63) * t10 * slope0) * D * t6;
  const T t12 = t2 * q0;
  const T t13 = t5 * q1;
  const T t14 = T(2) * t11 * b * t6 + T(429) * t12 - T(429) * t13;
  const T g_ap = -(T(1) / T(3003)) * t11 * t6 * in.w[0] - (T(1) / T(6006)) * in.w[1] * t14 * t6;
  const T t15 = T(429) * t13 * slope1 - T(429) * t12 * slope0 - T(2) * t11 * D * t6;
  const T g_ab = -(T(1) / T(6006)) * t14 * t6 * in.w[0] - (T(1) / T(45045)) * (T(15) * t14 * b * t6 - T(15) * c * t11 * t6 - T(7) * t15 * t6) * in.w[1] * t6;
  const T g_factor = -T(14) * inv_R2 * length;
  const T t16 = t7 * t7;
  const T t17 = t8 * t8;
  f = (T(1) / T(102960)) * (in.w[1] * (T(6435) * t16 + T(16) * b * t15 * t6 - T(6435) * t17) * t6 + T(16) * t15 * t6 * in.w[0]) * length;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 48 +, 119 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = t1 * q0;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = T(1) / a;
  const T t7 = t3 * q1;
  const T t8 = t0 * q0;
  const T t9 = t8 * t8;
  const T t10 = t7 * t7;
  const T t11 = t9 * q0;
  const T t12 = t10 * q1;
  const T t13 = T(2) * (T(4) * (T(63) * t2 * slope0 - T(63) * t5 * slope1 - T(2) * D * t6 * (T(8) * (T(2) * (T(3) * t3 * slope1 - T(3) * t0 * slope0 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t6) * D * t6 + T(5) * t7 * slope1 - T(5) * t8 * slope0) * D * t6 + T(35) * t4 * slope1 - T(35) * t1 * slope0)) * D * t6 + T(231) * t9 * slope0 - T(231) * t10 * slope1) * D * t6 + T(429) * t11 * slope0 - T(429) * t12 * slope1;
  const T t14 = t1 * t1;
  const T t15 = t4 * t4;
  const T t16 = T(16) * t13 * b * t6 + T(6435) * t14 - T(6435) * t15;
  f = -(T(1) / T(1750320)) * (T(2) * (T(8) * (T(16) * t13 * D * t6 + T(6435) * t14 * slope0 - T(6435) * t15 * slope1) * t6 + T(17) * b * t6 * t16 - T(136) * c * t13 * t6) * in.w[2] * t6 + T(17) * in.w[1] * t6 * t16 + T(272) * t13 * in.w[0] * t6) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 55 +, 143 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i14_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t7 * q0;
  const T t10 = t8 * q0;
  const T t11 = t9 * t9;
  const T t12 = T(231) * t3 * slope1 + T(4) * t0 * (T(63) * t6 * slope1 + T(2) * t0 * (T(35) * t5 * slope1 - T(35) * t8 * slope0 - T(8) * t0 * (T(5) * t9 * slope0 + T(2) * t0 * (T(3) * t7 * slope0 - T(3) * t1 * slope1 - T(4) * t0 * (q1 * slope1 + T(2) * (in.t1 - in.t0) * D - q0 * slope0) * D) * D - T(5) * t2 * slope1) * D) * D - T(63) * t10 * slope0) * D - T(231) * t11 * slope0;
  const T t13 = t11 * q0;
  const T t14 = T(429) * t4 + T(2) * t0 * b * t12 - T(429) * t13;
  const T t15 = T(429) * t4 * slope1 + T(2) * t0 * t12 * D - T(429) * t13 * slope0;
  const T t16 = T(15) * t0 * c * t12 - T(15) * t0 * t14 * b - T(7) * t0 * t15;
  const T g_ap = (T(1) / T(6006)) * t0 * in.w[1] * t14 + (T(1) / T(3003)) * t0 * t12 * in.w[0] - (T(1) / T(45045)) * t0 * t16 * in.w[2];
  const T t17 = t5 * t5;
  const T t18 = t8 * t8;
  const T g_ab = (T(1) / T(6006)) * t0 * t14 * in.w[0] + (T(1) / T(720720)) * t0 * (T(7) * t0 * (T(16) * t0 * b * t15 + T(6435) * t17 - T(6435) * t18) - T(32) * t0 * t16 * b - T(120) * t0 * c * t14) * in.w[2] - (T(1) / T(45045)) * t0 * in.w[1] * t16;
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 61 +, 169 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * q0;
  const T t3 = t2 * t2;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t4 * t4;
  const T t7 = t1 * t1;
  const T t8 = t6 * q1;
  const T t9 = t7 * q0;
  const T t10 = t5 * t5;
  const T t11 = T(231) * slope0 * t3 - T(4) * D * t0 * (T(2) * D * t0 * (T(8) * D * t0 * (T(5) * slope1 * t5 + T(2) * D * t0 * (T(3) * slope1 * t4 + T(4) * D * t0 * (T(2) * (in.t1 - in.t0) * D + slope1 * q1 - slope0 * q0) - T(3) * slope0 * t1) - T(5) * slope0 * t2) + T(35) * slope1 * t6 - T(35) * slope0 * t7) + T(63) * slope1 * t8 - T(63) * slope0 * t9) - T(231) * slope1 * t10;
  const T t12 = t3 * q0;
  const T t13 = t10 * q1;
  const T t14 = T(2) * t11 * t0 * b + T(429) * t12 - T(429) * t13;
  const T t15 = T(2) * D * t11 * t0 + T(429) * slope0 * t12 - T(429) * slope1 * t13;
  const T t16 = T(15) * t14 * t0 * b + T(7) * t0 * t15 - T(15) * t11 * t0 * c;
  const T g_ap = -(T(1) / T(45045)) * t0 * in.w[2] * t16 - (T(1) / T(6006)) * t14 * t0 * in.w[1] - (T(1) / T(3003)) * in.w[0] * t11 * t0;
  const T t17 = t7 * t7;
  const T t18 = t6 * t6;
  const T t19 = T(6435) * t17 + T(16) * t0 * t15 * b - T(6435) * t18;
  const T g_ab = -(T(1) / T(6006)) * t14 * in.w[0] * t0 - (T(1) / T(720720)) * t0 * (T(7) * t0 * t19 + T(32) * t0 * t16 * b - T(120) * t14 * t0 * c) * in.w[2] - (T(1) / T(45045)) * t0 * in.w[1] * t16;
  const T g_factor = -T(14) * length * inv_R2;
  f = -(T(1) / T(1750320)) * length * (T(17) * t0 * in.w[1] * t19 + T(2) * t0 * in.w[2] * (T(17) * t0 * t19 * b + T(8) * (T(6435) * slope0 * t17 + T(16) * D * t0 * t15 - T(6435) * slope1 * t18) * t0 - T(136) * t0 * t15 * c) + T(272) * in.w[0] * t0 * t15);
  grad[0] = -(g_ab * ab0 - ap0 * g_ap) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 53 +, 136 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = T(1) / a;
  const T t5 = t0 * t0;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t8 * q0;
  const T t10 = t7 * q0;
  const T t11 = t10 * t10;
  const T t12 = t11 * q0;
  const T t13 = T(429) * slope1 * t3 + T(2) * D * t4 * (T(231) * slope1 * t2 + T(4) * (T(63) * slope1 * t6 - T(63) * t9 * slope0 - T(2) * D * t4 * (T(35) * t8 * slope0 - T(35) * slope1 * t5 - T(8) * D * t4 * (T(2) * (T(4) * (T(2) * (in.t1 - in.t0) * D + slope1 * q1 - q0 * slope0) * D * t4 + T(3) * slope1 * t0 - T(3) * t7 * slope0) * D * t4 + T(5) * slope1 * t1 - T(5) * t10 * slope0))) * D * t4 - T(231) * t11 * slope0) - T(429) * t12 * slope0;
  const T t14 = t8 * t8;
  const T t15 = t5 * t5;
  const T t16 = T(6435) * t14 - T(6435) * t15 - T(16) * t13 * b * t4;
  const T t17 = t14 * q0;
  const T t18 = T(6435) * t14 * slope0 - T(6435) * slope1 * t15 - T(16) * t13 * D * t4;
  const T t19 = t15 * q1;
  const T t20 = T(17) * b * t16 * t4 + T(136) * t13 * t4 * c + T(8) * t18 * t4;
  f = (T(1) / T(1750320)) * (T(272) * t13 * in.w[0] * t4 + in.w[3] * t4 * (T(17) * t16 * t4 * c - T(8) * t4 * (T(12155) * t17 + T(2) * b * t18 * t4 - T(12155) * t19) - T(4) * t20 * b * t4) - T(17) * in.w[1] * t16 * t4 - T(2) * t20 * t4 * in.w[2]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 63 +, 172 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i14_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = t3 * q0;
  const T t7 = t6 * t6;
  const T t8 = t4 * q0;
  const T t9 = t0 * q1;
  const T t10 = T(1) / a;
  const T t11 = t1 * q1;
  const T t12 = t9 * t9;
  const T t13 = T(231) * t7 * slope0 + T(4) * (T(63) * t8 * slope0 + T(2) * D * (T(35) * t4 * slope0 - T(35) * t1 * slope1 - T(8) * (T(5) * t9 * slope1 + T(2) * (T(3) * t0 * slope1 - T(3) * t3 * slope0 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t10) * D * t10 - T(5) * t6 * slope0) * D * t10) * t10 - T(63) * t11 * slope1) * D * t10 - T(231) * t12 * slope1;
  const T t14 = t7 * q0;
  const T t15 = t12 * q1;
  const T t16 = T(2) * t13 * D * t10 + T(429) * t14 * slope0 - T(429) * t15 * slope1;
  const T t17 = T(6435) * t2 - T(6435) * t5 - T(16) * b * t16 * t10;
  const T t18 = T(2) * t13 * b * t10 + T(429) * t14 - T(429) * t15;
  const T t19 = T(7) * t16 * t10 + T(15) * b * t18 * t10 - T(15) * c * t13 * t10;
  const T t20 = T(7) * t17 * t10 + T(120) * c * t18 * t10 - T(32) * b * t19 * t10;
  const T g_ap = (T(1) / T(720720)) * in.w[3] * t20 * t10 - (T(1) / T(6006)) * in.w[1] * t18 * t10 - (T(1) / T(45045)) * t19 * t10 * in.w[2] - (T(1) / T(3003)) * t13 * in.w[0] * t10;
  const T g_ab = (T(1) / T(720720)) * t20 * t10 * in.w[2] - (T(1) / T(6126120)) * in.w[3] * t10 * (T(7) * (T(8) * (T(6435) * t5 * slope0 + T(16) * t16 * D * t10 - T(6435) * t2 * slope1) * t10 - T(17) * t17 * b * t10 - T(136) * c * t16 * t10) * t10 - T(136) * c * t19 * t10 - T(17) * b * t20 * t10) - (T(1) / T(45045)) * in.w[1] * t19 * t10 - (T(1) / T(6006)) * in.w[0] * t18 * t10;
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 70 +, 201 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i14_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = t1 * q0;
  const T t5 = q1 * q1;
  const T t6 = t5 * q1;
  const T t7 = t5 * t5;
  const T t8 = t7 * q1;
  const T t9 = t4 * t4;
  const T t10 = t6 * t6;
  const T t11 = T(4) * D * (T(63) * slope0 * t3 + T(2) * D * t0 * (T(35) * slope0 * t2 + T(8) * D * t0 * (T(5) * slope0 * t4 + T(2) * D * t0 * (T(3) * slope0 * t1 - T(3) * slope1 * q1 * q1 - T(4) * D * t0 * (slope1 * q1 + T(2) * D * (in.t1 - in.t0) - slope0 * q0)) - T(5) * slope1 * t6) - T(35) * slope1 * t7) - T(63) * slope1 * t8) * t0 + T(231) * slope0 * t9 - T(231) * slope1 * t10;
  const T t12 = t9 * q0;
  const T t13 = t10 * q1;
  const T t14 = T(2) * t0 * t11 * b + T(429) * t12 - T(429) * t13;
  const T t15 = t7 * t7;
  const T t16 = T(2) * D * t0 * t11 + T(429) * slope0 * t12 - T(429) * slope1 * t13;
  const T t17 = t2 * t2;
  const T t18 = T(6435) * t15 - T(16) * t0 * t16 * b - T(6435) * t17;
  const T t19 = T(7) * t0 * t16 + T(15) * t0 * t14 * b - T(15) * t0 * t11 * c;
  const T t20 = T(120) * t0 * c * t14 + T(7) * t18 * t0 - T(32) * t0 * b * t19;
  const T g_ap = (T(1) / T(720720)) * t0 * t20 * in.w[3] - (T(1) / T(3003)) * t0 * t11 * in.w[0] - (T(1) / T(6006)) * in.w[1] * t0 * t14 - (T(1) / T(45045)) * t0 * in.w[2] * t19;
  const T t21 = T(6435) * slope1 * t15 - T(6435) * slope0 * t17 - T(16) * D * t0 * t16;
  const T t22 = T(17) * t18 * t0 * b + T(136) * t0 * t16 * c + T(8) * t0 * t21;
  const T g_ab = (T(1) / T(6126120)) * t0 * in.w[3] * (T(7) * t0 * t22 + T(136) * t0 * c * t19 + T(17) * t0 * t20 * b) + (T(1) / T(720720)) * t0 * in.w[2] * t20 - (T(1) / T(6006)) * t0 * in.w[0] * t14 - (T(1) / T(45045)) * in.w[1] * t0 * t19;
  const T g_factor = -T(14) * length * inv_R2;
  const T t23 = t15 * q1;
  const T t24 = t17 * q0;
  f = (T(1) / T(1750320)) * (T(17) * t18 * in.w[1] * t0 + (T(4) * t0 * t22 * b + T(8) * t0 * (T(2) * t0 * t21 * b + T(12155) * t23 - T(12155) * t24) - T(17) * t18 * t0 * c) * t0 * in.w[3] + T(2) * t0 * in.w[2] * t22 - T(272) * t0 * t16 * in.w[0]) * length;
  grad[0] = (ap0 * g_ap - ab0 * g_ab) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 42 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = t2 * t2;
  const T t7 = t6 * q1;
  const T t8 = T(1) / a;
  const T t9 = q0 * q0;
  const T t10 = t9 * t9;
  const T t11 = t9 * q0;
  const T t12 = t10 * q0;
  const T t13 = t11 * t11;
  const T t14 = t13 * q0;
  f = (T(1) / T(229376)) * (T(14336) * r1 * t5 * slope1 + (T(15360) * r1 * t4 * slope1 + T(13) * (T(1280) * r1 * t7 * slope1 + T(11) * t8 * (T(128) * r1 * t6 * slope1 - T(128) * t10 * slope0 * r0 - T(3) * (T(7) * t8 * (T(8) * t9 * slope0 * r0 - T(5) * t8 * D * (T(2) * r1 * q1 * slope1 + T(3) * t8 * D * (r1 * slope1 + J1 * D - slope0 * r0) - T(2) * q0 * slope0 * r0) - T(8) * r1 * t2 * slope1) * D + T(48) * t11 * slope0 * r0 - T(48) * r1 * t3 * slope1) * t8 * D) * D - T(1280) * t12 * slope0 * r0) * t8 * D - T(15360) * t13 * slope0 * r0) * t8 * D - T(14336) * t14 * slope0 * r0) * in.w[0] * length * t8;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 45 +, 124 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = q0 * q0;
  const T t1 = t0 * q0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / a;
  const T t4 = t0 * t0;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = t6 * t6;
  const T t9 = t8 * q1;
  const T t10 = t7 * t7;
  const T t11 = T(15360) * slope0 * r0 * t2 + T(13) * D * t3 * (T(1280) * slope0 * r0 * t5 + T(11) * D * t3 * (T(128) * slope0 * r0 * t4 - T(3) * D * t3 * (T(7) * D * t3 * (T(8) * slope1 * r1 * q1 * q1 + T(5) * D * (T(3) * (D * J1 + slope1 * r1 - slope0 * r0) * D * t3 + T(2) * slope1 * r1 * q1 - T(2) * slope0 * r0 * q0) * t3 - T(8) * slope0 * r0 * t0) + T(48) * slope1 * r1 * t7 - T(48) * slope0 * r0 * t1) - T(128) * slope1 * r1 * t8) - T(1280) * slope1 * r1 * t9) - T(15360) * slope1 * r1 * t10;
  const T g_ap = -(T(1) / T(215040)) * t11 * t3 * in.w[0];
  const T t12 = t2 * q0;
  const T t13 = t10 * q1;
  const T g_ab = -(T(1) / T(215040)) * t3 * in.w[0] * (t11 * t3 * b + T(14336) * r0 * t12 - T(14336) * r1 * t13);
  const T g_factor = -T(15) * length * inv_R2;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - g_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - g_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 47 +, 135 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t2 * t2;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t8 * q0;
  const T t10 = T(1) / a;
  const T t11 = t7 * q0;
  const T t12 = t11 * t11;
  const T t13 = T(15360) * r1 * t4 * slope1 + T(13) * (T(1280) * r1 * t6 * slope1 - T(1280) * t9 * slope0 * r0 - T(11) * D * t10 * (T(128) * t8 * slope0 * r0 - T(128) * r1 * t5 * slope1 - T(3) * (T(7) * (T(5) * (T(2) * r1 * q1 * slope1 + T(3) * (J1 * D + r1 * slope1 - slope0 * r0) * D * t10 - T(2) * q0 * slope0 * r0) * D * t10 + T(8) * r1 * t2 * slope1 - T(8) * t7 * slope0 * r0) * D * t10 + T(48) * r1 * t3 * slope1 - T(48) * t11 * slope0 * r0) * D * t10)) * D * t10 - T(15360) * t12 * slope0 * r0;
  const T g_ap = (T(1) / T(215040)) * in.w[0] * t13 * t10;
  const T t14 = t4 * q1;
  const T t15 = t12 * q0;
  const T g_ab = (T(1) / T(215040)) * (T(14336) * r1 * t14 + t13 * b * t10 - T(14336) * t15 * r0) * in.w[0] * t10;
  const T g_factor = -T(15) * inv_R2 * length;
  f = (T(1) / T(229376)) * in.w[0] * (T(14336) * r1 * t14 * slope1 + t13 * D * t10 - T(14336) * t15 * slope0 * r0) * length * t10;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 45 +, 124 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t7 * t7;
  const T t9 = t3 * q1;
  const T t10 = t9 * t9;
  const T t11 = t4 * q1;
  const T t12 = t6 * t6;
  const T t13 = t12 * q0;
  const T t14 = t8 * q0;
  const T t15 = t10 * q1;
  const T t16 = D * t2 * (T(15360) * slope0 * r0 * t8 - T(15360) * t10 * slope1 * r1 - T(13) * D * t2 * (T(1280) * t11 * slope1 * r1 - T(11) * D * (T(3) * D * t2 * (T(48) * slope0 * r0 * t7 - T(7) * D * (T(8) * t3 * slope1 * r1 - T(8) * slope0 * r0 * t6 - T(5) * D * t2 * (T(2) * slope0 * r0 * q0 + T(3) * (slope0 * r0 - D * J1 - slope1 * r1) * D * t2 - T(2) * q1 * slope1 * r1)) * t2 - T(48) * t9 * slope1 * r1) + T(128) * slope0 * r0 * t12 - T(128) * t4 * slope1 * r1) * t2 - T(1280) * slope0 * r0 * t13)) + T(14336) * slope0 * r0 * t14 - T(14336) * t15 * slope1 * r1;
  const T t17 = t12 * t12;
  f = (T(1) / T(3899392)) * length * (t2 * in.w[1] * (T(229376) * t5 * r1 - T(17) * b * t2 * t16 - T(229376) * r0 * t17) - T(17) * t2 * in.w[0] * t16);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 51 +, 145 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * q0;
  const T t9 = t7 * t7;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = T(13) * D * t0 * (T(1280) * t6 * slope1 * r1 + T(11) * D * t0 * (T(128) * t5 * slope1 * r1 - T(3) * D * t0 * (T(48) * slope0 * r0 * t8 - T(7) * D * t0 * (T(8) * t1 * slope1 * r1 - T(8) * slope0 * r0 * t7 - T(5) * D * t0 * (T(2) * slope0 * r0 * q0 - T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) - T(2) * q1 * slope1 * r1)) - T(48) * t2 * slope1 * r1) - T(128) * slope0 * r0 * t9) - T(1280) * slope0 * r0 * t10) + T(15360) * t3 * slope1 * r1 - T(15360) * slope0 * r0 * t11;
  const T t13 = t11 * q0;
  const T t14 = T(14336) * t4 * r1 + t0 * t12 * b - T(14336) * r0 * t13;
  const T g_ap = (T(1) / T(215040)) * t0 * t14 * in.w[1] + (T(1) / T(215040)) * t0 * in.w[0] * t12;
  const T g_ab = (T(1) / T(215040)) * t0 * t14 * in.w[0] + (T(1) / T(3440640)) * (T(32) * t0 * t14 * b + T(15) * (D * t0 * t12 + T(14336) * t4 * slope1 * r1 - T(14336) * slope0 * r0 * t13) * t0 - T(16) * t0 * c * t12) * t0 * in.w[1];
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - g_ap * ap0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 54 +, 161 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t2 * t2;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t7 * q0;
  const T t10 = t8 * q0;
  const T t11 = t9 * t9;
  const T t12 = T(15360) * slope1 * r1 * t4 + T(13) * t1 * (T(1280) * slope1 * r1 * t6 + T(11) * (T(128) * slope1 * r1 * t5 - T(128) * r0 * t8 * slope0 - T(3) * t1 * D * (T(7) * t1 * (T(5) * t1 * (T(2) * r0 * q0 * slope0 + T(3) * t1 * (r0 * slope0 - J1 * D - slope1 * r1) * D - T(2) * slope1 * r1 * q1) * D + T(8) * r0 * t7 * slope0 - T(8) * slope1 * r1 * t2) * D + T(48) * r0 * t9 * slope0 - T(48) * slope1 * r1 * t3)) * t1 * D - T(1280) * r0 * t10 * slope0) * D - T(15360) * r0 * t11 * slope0;
  const T t13 = t4 * q1;
  const T t14 = t11 * q0;
  const T t15 = T(14336) * r1 * t13 + t1 * t12 * b - T(14336) * r0 * t14;
  const T g_ap = (T(1) / T(215040)) * t1 * in.w[0] * t12 + (T(1) / T(215040)) * t1 * t15 * in.w[1];
  const T t16 = t1 * t12 * D + T(14336) * slope1 * r1 * t13 - T(14336) * r0 * t14 * slope0;
  const T g_ab = (T(1) / T(215040)) * t1 * in.w[0] * t15 + (T(1) / T(3440640)) * t1 * (T(15) * t1 * t16 + T(32) * t1 * t15 * b - T(16) * t1 * c * t12) * in.w[1];
  const T g_factor = -T(15) * inv_R2 * length;
  const T t17 = t5 * t5;
  const T t18 = t8 * t8;
  f = (T(1) / T(3899392)) * (t1 * in.w[1] * (T(229376) * r1 * t17 + T(17) * t1 * b * t16 - T(229376) * r0 * t18) + T(17) * t1 * in.w[0] * t16) * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 50 +, 144 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q0 * q0;
  const T t3 = t2 * q0;
  const T t4 = t3 * t3;
  const T t5 = t4 * q0;
  const T t6 = q1 * q1;
  const T t7 = t6 * q1;
  const T t8 = t6 * t6;
  const T t9 = t2 * t2;
  const T t10 = t8 * q1;
  const T t11 = t9 * q0;
  const T t12 = t7 * t7;
  const T t13 = t12 * q1;
  const T t14 = T(14336) * r0 * t5 * slope0 + t1 * (T(15360) * r0 * t4 * slope0 - T(13) * t1 * (T(11) * t1 * (T(3) * (T(48) * slope1 * r1 * t7 + T(7) * t1 * (T(8) * slope1 * r1 * t6 - T(5) * t1 * (T(2) * r0 * q0 * slope0 - T(2) * slope1 * r1 * q1 - T(3) * t1 * (slope1 * r1 + J1 * D - r0 * slope0) * D) * D - T(8) * r0 * t2 * slope0) * D - T(48) * r0 * t3 * slope0) * t1 * D + T(128) * slope1 * r1 * t8 - T(128) * r0 * t9 * slope0) * D + T(1280) * slope1 * r1 * t10 - T(1280) * r0 * t11 * slope0) * D - T(15360) * slope1 * r1 * t12) * D - T(14336) * slope1 * r1 * t13;
  const T t15 = t8 * t8;
  const T t16 = t9 * t9;
  const T t17 = T(229376) * r1 * t15 - T(229376) * r0 * t16 - T(17) * t1 * t14 * b;
  f = -(T(1) / T(70189056)) * length * (T(306) * t1 * t14 * in.w[0] - t1 * (T(306) * t1 * c * t14 + T(36) * t1 * t17 * b - T(17) * t1 * (T(229376) * r0 * t16 * slope0 + T(17) * t1 * t14 * D - T(229376) * slope1 * r1 * t15)) * in.w[2] - T(18) * t1 * t17 * in.w[1]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 57 +, 168 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  const T t0 = q1 * q1;
  const T t1 = t0 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * q1;
  const T t4 = T(1) / a;
  const T t5 = t0 * t0;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t8 * q0;
  const T t10 = t7 * q0;
  const T t11 = t10 * t10;
  const T t12 = T(13) * D * t4 * (T(1280) * slope1 * r1 * t6 - T(1280) * slope0 * r0 * t9 - T(11) * (T(3) * (T(48) * slope0 * r0 * t10 - T(7) * D * t4 * (T(8) * slope1 * r1 * t0 + T(5) * D * (T(2) * slope1 * r1 * q1 + T(3) * (D * J1 + slope1 * r1 - slope0 * r0) * D * t4 - T(2) * slope0 * r0 * q0) * t4 - T(8) * slope0 * r0 * t7) - T(48) * slope1 * r1 * t1) * D * t4 + T(128) * slope0 * r0 * t8 - T(128) * slope1 * r1 * t5) * D * t4) + T(15360) * slope1 * r1 * t2 - T(15360) * slope0 * r0 * t11;
  const T t13 = t11 * q0;
  const T t14 = T(14336) * r1 * t3 + t4 * t12 * b - T(14336) * r0 * t13;
  const T t15 = D * t4 * t12 + T(14336) * slope1 * r1 * t3 - T(14336) * slope0 * r0 * t13;
  const T t16 = T(15) * t4 * t15 + T(32) * t14 * t4 * b - T(16) * t4 * c * t12;
  const T g_ap = (T(1) / T(215040)) * t14 * t4 * in.w[1] + (T(1) / T(215040)) * in.w[0] * t4 * t12 + (T(1) / T(3440640)) * t4 * t16 * in.w[2];
  const T t17 = t8 * t8;
  const T t18 = t5 * t5;
  const T g_ab = (T(1) / T(215040)) * in.w[0] * t14 * t4 + (T(1) / T(3440640)) * t4 * in.w[1] * t16 - (T(1) / T(58490880)) * t4 * in.w[2] * (T(15) * t4 * (T(229376) * r0 * t17 - T(229376) * r1 * t18 - T(17) * t4 * t15 * b) + T(272) * t14 * t4 * c - T(34) * t4 * t16 * b);
  const T g_factor = -T(15) * length * inv_R2;
  grad[0] = g_factor * (g_ap * ap0 - g_ab * ab0);
  grad[1] = g_factor * (ap1 * g_ap - g_ab * ab1);
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 63 +, 195 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = t2 * t2;
  const T t7 = t6 * q1;
  const T t8 = q0 * q0;
  const T t9 = t8 * q0;
  const T t10 = t8 * t8;
  const T t11 = t10 * q0;
  const T t12 = t9 * t9;
  const T t13 = T(15360) * r1 * t4 * slope1 + T(13) * D * t1 * (T(1280) * r1 * t7 * slope1 + T(11) * D * t1 * (T(128) * r1 * t6 * slope1 - T(3) * D * t1 * (T(48) * slope0 * r0 * t9 + T(7) * (T(5) * D * t1 * (T(2) * slope0 * r0 * q0 - T(2) * r1 * q1 * slope1 - T(3) * D * (r1 * slope1 + D * J1 - slope0 * r0) * t1) + T(8) * slope0 * r0 * t8 - T(8) * r1 * t2 * slope1) * D * t1 - T(48) * r1 * t3 * slope1) - T(128) * slope0 * r0 * t10) - T(1280) * slope0 * r0 * t11) - T(15360) * slope0 * r0 * t12;
  const T t14 = t12 * q0;
  const T t15 = T(14336) * r1 * t5 + t1 * t13 * b - T(14336) * r0 * t14;
  const T t16 = T(14336) * r1 * t5 * slope1 + D * t1 * t13 - T(14336) * slope0 * r0 * t14;
  const T t17 = T(32) * t1 * b * t15 + T(15) * t16 * t1 - T(16) * t1 * c * t13;
  const T g_ap = (T(1) / T(215040)) * t1 * in.w[1] * t15 + (T(1) / T(3440640)) * t1 * in.w[2] * t17 + (T(1) / T(215040)) * in.w[0] * t1 * t13;
  const T t18 = t10 * t10;
  const T t19 = t6 * t6;
  const T t20 = T(229376) * r0 * t18 - T(229376) * r1 * t19 - T(17) * t16 * t1 * b;
  const T g_ab = (T(1) / T(3440640)) * t1 * in.w[1] * t17 + (T(1) / T(58490880)) * (T(34) * t1 * b * t17 - T(15) * t20 * t1 - T(272) * t1 * c * t15) * t1 * in.w[2] + (T(1) / T(215040)) * in.w[0] * t1 * t15;
  const T g_factor = -T(15) * inv_R2 * length;
  f = -(T(1) / T(70189056)) * ((T(17) * t1 * (T(229376) * slope0 * r0 * t18 - T(229376) * r1 * t19 * slope1 - T(17) * t16 * D * t1) + T(306) * t16 * t1 * c + T(36) * t20 * t1 * b) * t1 * in.w[2] + T(18) * t20 * t1 * in.w[1] - T(306) * t16 * in.w[0] * t1) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (g_ab * ab2 - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 55 +, 164 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * t3;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t6 * q0;
  const T t9 = t2 * q1;
  const T t10 = t5 * q0;
  const T t11 = t3 * q1;
  const T t12 = t10 * t10;
  const T t13 = t9 * t9;
  const T t14 = t12 * q0;
  const T t15 = t13 * q1;
  const T t16 = D * t1 * (T(13) * D * t1 * (T(1280) * r0 * t8 * slope0 + T(11) * D * t1 * (T(128) * r0 * t6 * slope0 - T(128) * slope1 * r1 * t3 - T(3) * D * t1 * (T(48) * slope1 * r1 * t9 + T(7) * D * t1 * (T(8) * slope1 * r1 * t2 - T(8) * r0 * t5 * slope0 - T(5) * (T(2) * r0 * q0 * slope0 - T(3) * D * (slope1 * r1 + D * J1 - r0 * slope0) * t1 - T(2) * slope1 * r1 * q1) * D * t1) - T(48) * r0 * t10 * slope0)) - T(1280) * slope1 * r1 * t11) + T(15360) * r0 * t12 * slope0 - T(15360) * slope1 * r1 * t13) + T(14336) * r0 * t14 * slope0 - T(14336) * slope1 * r1 * t15;
  const T t17 = T(229376) * r1 * t4 - T(229376) * r0 * t7 - T(17) * t1 * t16 * b;
  const T t18 = t7 * q0;
  const T t19 = T(229376) * r0 * t7 * slope0 + T(17) * D * t1 * t16 - T(229376) * slope1 * r1 * t4;
  const T t20 = t4 * q1;
  const T t21 = T(17) * t1 * t19 - T(306) * t1 * c * t16 - T(36) * t1 * t17 * b;
  f = (T(1) / T(1333592064)) * (T(342) * in.w[1] * t1 * t17 - T(5814) * t1 * in.w[0] * t16 - t1 * (T(17) * (T(4128768) * r0 * t18 + T(19) * t1 * t19 * b - T(4128768) * r1 * t20) * t1 + T(342) * t1 * t17 * c + T(38) * t21 * t1 * b) * in.w[3] - T(19) * t21 * t1 * in.w[2]) * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 65 +, 200 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  const T t2 = T(1) / a;
  const T t3 = q1 * q1;
  const T t4 = t3 * t3;
  const T t5 = t3 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t6 * t6;
  const T t9 = t4 * q1;
  const T t10 = t8 * q0;
  const T t11 = t5 * t5;
  const T t12 = t7 * t7;
  const T t13 = T(13) * D * t2 * (T(11) * (T(128) * t4 * slope1 * r1 + T(3) * (T(7) * D * (T(5) * (T(2) * q1 * slope1 * r1 + T(3) * D * t2 * (slope1 * r1 + J1 * D - slope0 * r0) - T(2) * q0 * slope0 * r0) * D * t2 + T(8) * t3 * slope1 * r1 - T(8) * q0 * q0 * slope0 * r0) * t2 + T(48) * t5 * slope1 * r1 - T(48) * t7 * slope0 * r0) * D * t2 - T(128) * t8 * slope0 * r0) * D * t2 + T(1280) * t9 * slope1 * r1 - T(1280) * t10 * slope0 * r0) + T(15360) * t11 * slope1 * r1 - T(15360) * t12 * slope0 * r0;
  const T t14 = t11 * q1;
  const T t15 = t12 * q0;
  const T t16 = t13 * b * t2 + T(14336) * t14 * r1 - T(14336) * t15 * r0;
  const T t17 = t13 * D * t2 + T(14336) * t14 * slope1 * r1 - T(14336) * t15 * slope0 * r0;
  const T t18 = T(15) * t17 * t2 + T(32) * b * t2 * t16 - T(16) * t13 * t2 * c;
  const T t19 = t4 * t4;
  const T t20 = t8 * t8;
  const T t21 = T(17) * b * t17 * t2 + T(229376) * t19 * r1 - T(229376) * t20 * r0;
  const T t22 = T(272) * t2 * c * t16 - T(34) * b * t2 * t18 - T(15) * t21 * t2;
  const T g_ap = (T(1) / T(215040)) * in.w[0] * t13 * t2 + (T(1) / T(215040)) * in.w[1] * t2 * t16 + (T(1) / T(3440640)) * t2 * in.w[2] * t18 - (T(1) / T(58490880)) * in.w[3] * t22 * t2;
  const T g_ab = (T(1) / T(215040)) * in.w[0] * t2 * t16 + (T(1) / T(3440640)) * in.w[1] * t2 * t18 - (T(1) / T(58490880)) * t22 * t2 * in.w[2] - (T(1) / T(350945280)) * in.w[3] * t2 * (T(102) * t2 * t18 * c + T(12) * b * t22 * t2 - T(5) * (T(36) * b * t21 * t2 + T(17) * (T(17) * D * t17 * t2 + T(229376) * t19 * slope1 * r1 - T(229376) * t20 * slope0 * r0) * t2 - T(306) * t17 * t2 * c) * t2);
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = -(ab0 * g_ab - ap0 * g_ap) * g_factor;
  grad[1] = g_factor * (g_ap * ap1 - ab1 * g_ab);
  grad[2] = (g_ap * ap2 - ab2 * g_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 72 +, 229 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
T segment_compact_i15_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  const T t1 = T(1) / a;
  const T t2 = q1 * q1;
  const T t3 = t2 * q1;
  const T t4 = t3 * t3;
  const T t5 = t2 * t2;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * q0;
  const T t9 = t7 * t7;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = T(15360) * slope1 * r1 * t4 + T(13) * t1 * (T(1280) * slope1 * r1 * t6 + T(11) * t1 * (T(128) * slope1 * r1 * t5 - T(3) * t1 * (T(48) * r0 * t8 * slope0 + T(7) * t1 * (T(8) * r0 * t7 * slope0 - T(5) * t1 * (T(2) * slope1 * r1 * q1 - T(2) * r0 * q0 * slope0 - T(3) * t1 * (r0 * slope0 - J1 * D - slope1 * r1) * D) * D - T(8) * slope1 * r1 * t2) * D - T(48) * slope1 * r1 * t3) * D - T(128) * r0 * t9 * slope0) * D - T(1280) * r0 * t10 * slope0) * D - T(15360) * r0 * t11 * slope0;
  const T t13 = t11 * q0;
  const T t14 = t4 * q1;
  const T t15 = T(14336) * r0 * t13 - T(14336) * r1 * t14 - t1 * t12 * b;
  const T t16 = t5 * t5;
  const T t17 = T(14336) * slope1 * r1 * t14 + t1 * t12 * D - T(14336) * r0 * t13 * slope0;
  const T t18 = t9 * t9;
  const T t19 = T(229376) * r1 * t16 + T(17) * t1 * b * t17 - T(229376) * r0 * t18;
  const T t20 = T(16) * t1 * t12 * c + T(32) * t1 * t15 * b - T(15) * t1 * t17;
  const T t21 = T(272) * t1 * t15 * c + T(15) * t1 * t19 - T(34) * t1 * t20 * b;
  const T g_ap = (T(1) / T(215040)) * t1 * t12 * in.w[0] + (T(1) / T(58490880)) * t1 * t21 * in.w[3] - (T(1) / T(215040)) * t1 * t15 * in.w[1] - (T(1) / T(3440640)) * t1 * in.w[2] * t20;
  const T t22 = T(17) * t1 * D * t17 + T(229376) * slope1 * r1 * t16 - T(229376) * r0 * t18 * slope0;
  const T t23 = T(17) * t1 * t22 + T(36) * t1 * t19 * b - T(306) * t1 * c * t17;
  const T g_ab = (T(1) / T(350945280)) * t1 * in.w[3] * (T(12) * t1 * t21 * b + T(102) * t1 * c * t20 + T(5) * t1 * t23) + (T(1) / T(58490880)) * t1 * in.w[2] * t21 - (T(1) / T(3440640)) * t1 * t20 * in.w[1] - (T(1) / T(215040)) * t1 * t15 * in.w[0];
  const T g_factor = -T(15) * inv_R2 * length;
  const T t24 = t16 * q1;
  const T t25 = t18 * q0;
  f = -(T(1) / T(1333592064)) * (t1 * in.w[3] * (T(342) * t1 * c * t19 - T(38) * t1 * t23 * b - T(17) * t1 * (T(19) * t1 * b * t22 + T(4128768) * r1 * t24 - T(4128768) * r0 * t25)) - T(342) * t1 * t19 * in.w[1] - T(5814) * t1 * in.w[0] * t17 - T(19) * t1 * in.w[2] * t23) * length;
  grad[0] = -g_factor * (ab0 * g_ab - g_ap * ap0);
  grad[1] = g_factor * (ap1 * g_ap - ab1 * g_ab);
  grad[2] = (ap2 * g_ap - ab2 * g_ab) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 42 +, 100 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q0 * q0;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = T(1) / a;
  const T t4 = t0 * q0;
  const T t5 = t4 * t4;
  const T t6 = t5 * q0;
  const T t7 = t1 * q0;
  const T t8 = q1 * q1;
  const T t9 = t8 * q1;
  const T t10 = t8 * t8;
  const T t11 = t10 * q1;
  const T t12 = t9 * t9;
  const T t13 = t12 * q1;
  const T t14 = t10 * t10;
  f = -(T(1) / T(109395)) * length * (T(6435) * t2 * slope0 + T(16) * D * t3 * (T(429) * t6 * slope0 + T(2) * D * t3 * (T(231) * t5 * slope0 + T(4) * D * t3 * (T(63) * t7 * slope0 + T(2) * D * t3 * (T(35) * t1 * slope0 - T(8) * (T(2) * D * t3 * (T(3) * slope1 * q1 * q1 - T(4) * D * t3 * (q0 * slope0 + T(2) * D * (in.t0 - in.t1) - slope1 * q1) - T(3) * t0 * slope0) + T(5) * slope1 * t9 - T(5) * t4 * slope0) * D * t3 - T(35) * slope1 * t10) - T(63) * slope1 * t11) - T(231) * slope1 * t12) - T(429) * slope1 * t13) - T(6435) * slope1 * t14) * t3 * in.w[0];
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 45 +, 110 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i16_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t6 * t6;
  const T t8 = t5 * t5;
  const T t9 = t1 * t1;
  const T t10 = t8 * q0;
  const T t11 = t9 * q1;
  const T t12 = t7 * q0;
  const T t13 = T(429) * t4 * slope1 + T(2) * t0 * (T(231) * t3 * slope1 - T(231) * t7 * slope0 - T(4) * t0 * (T(2) * t0 * (T(8) * (T(5) * t6 * slope0 + T(2) * t0 * (T(3) * t5 * slope0 - T(3) * t1 * slope1 - T(4) * t0 * (T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0) * D) * D - T(5) * t2 * slope1) * t0 * D + T(35) * t8 * slope0 - T(35) * t9 * slope1) * D + T(63) * t10 * slope0 - T(63) * t11 * slope1) * D) * D - T(429) * t12 * slope0;
  const T g_ap = (T(1) / T(6435)) * t0 * t13 * in.w[0];
  const T t14 = t8 * t8;
  const T t15 = t9 * t9;
  const T g_ab = -(T(1) / T(102960)) * t0 * (T(6435) * t14 - T(16) * t0 * t13 * b - T(6435) * t15) * in.w[0];
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = -g_factor * (g_ab * ab0 - g_ap * ap0);
  grad[1] = -g_factor * (g_ab * ab1 - g_ap * ap1);
  grad[2] = -(g_ab * ab2 - ap2 * g_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 47 +, 121 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * t7;
  const T t9 = t8 * q0;
  const T t10 = t7 * q0;
  const T t11 = t10 * t10;
  const T t12 = t11 * q0;
  const T t13 = T(429) * t4 * slope1 + T(2) * t0 * (T(4) * t0 * (T(63) * t6 * slope1 - T(63) * t9 * slope0 - T(2) * t0 * (T(35) * t8 * slope0 + T(8) * t0 * (T(5) * t10 * slope0 + T(2) * t0 * (T(4) * t0 * (q0 * slope0 - q1 * slope1 - T(2) * D * (in.t1 - in.t0)) * D + T(3) * t7 * slope0 - T(3) * t1 * slope1) * D - T(5) * t2 * slope1) * D - T(35) * t5 * slope1) * D) * D + T(231) * t3 * slope1 - T(231) * t11 * slope0) * D - T(429) * t12 * slope0;
  const T g_ap = (T(1) / T(6435)) * t0 * in.w[0] * t13;
  const T t14 = t5 * t5;
  const T t15 = t8 * t8;
  const T g_ab = (T(1) / T(102960)) * t0 * in.w[0] * (T(16) * t0 * b * t13 + T(6435) * t14 - T(6435) * t15);
  const T g_factor = -T(16) * inv_R2 * length;
  f = (T(1) / T(109395)) * t0 * (T(6435) * t14 * slope1 + T(16) * t0 * D * t13 - T(6435) * t15 * slope0) * length * in.w[0];
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (g_ap * ap1 - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 45 +, 109 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = t0 * q1;
  const T t4 = t3 * t3;
  const T t5 = t4 * q1;
  const T t6 = q0 * q0;
  const T t7 = t6 * q0;
  const T t8 = t7 * t7;
  const T t9 = t8 * q0;
  const T t10 = T(1) / a;
  const T t11 = t6 * t6;
  const T t12 = t11 * q0;
  const T t13 = t1 * q1;
  const T t14 = t11 * t11;
  const T t15 = T(6435) * t2 * slope1 + T(16) * (T(429) * t5 * slope1 - T(429) * t9 * slope0 - T(2) * t10 * (T(231) * t8 * slope0 + T(4) * (T(2) * t10 * D * (T(35) * t11 * slope0 + T(8) * (T(2) * t10 * D * (T(4) * (q0 * slope0 - q1 * slope1 - T(2) * (in.t1 - in.t0) * D) * t10 * D + T(3) * t6 * slope0 - T(3) * t0 * slope1) + T(5) * t7 * slope0 - T(5) * t3 * slope1) * t10 * D - T(35) * t1 * slope1) + T(63) * t12 * slope0 - T(63) * t13 * slope1) * t10 * D - T(231) * t4 * slope1) * D) * t10 * D - T(6435) * t14 * slope0;
  const T t16 = t2 * q1;
  const T t17 = t14 * q0;
  f = (T(1) / T(218790)) * length * (T(2) * t15 * t10 * in.w[0] + in.w[1] * t10 * (T(2) * t15 * b * t10 + T(12155) * t16 - T(12155) * t17));
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 51 +, 131 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i16_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * q0;
  const T t9 = t7 * t7;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = t11 * q0;
  const T t13 = T(429) * t4 * slope1 + T(2) * D * t0 * (T(231) * t3 * slope1 + T(4) * (T(63) * t6 * slope1 + T(2) * (T(35) * t5 * slope1 - T(8) * (T(5) * t8 * slope0 + T(2) * D * t0 * (T(3) * t7 * slope0 - T(3) * t1 * slope1 - T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - q0 * slope0)) - T(5) * t2 * slope1) * D * t0 - T(35) * t9 * slope0) * D * t0 - T(63) * t10 * slope0) * D * t0 - T(231) * t11 * slope0) - T(429) * t12 * slope0;
  const T t14 = t9 * t9;
  const T t15 = t5 * t5;
  const T t16 = T(6435) * t14 - T(6435) * t15 - T(16) * b * t0 * t13;
  const T g_ap = (T(1) / T(6435)) * t0 * in.w[0] * t13 - (T(1) / T(102960)) * t16 * in.w[1] * t0;
  const T g_ab = -(T(1) / T(102960)) * t16 * t0 * in.w[0] - (T(1) / T(875160)) * in.w[1] * t0 * (T(17) * t16 * b * t0 + T(136) * t0 * t13 * c - T(8) * (T(6435) * t15 * slope1 + T(16) * D * t0 * t13 - T(6435) * t14 * slope0) * t0);
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -(ab2 * g_ab - g_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 54 +, 145 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross2 * cross2 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = q0 * q0;
  const T t5 = t4 * q0;
  const T t6 = t5 * t5;
  const T t7 = t4 * t4;
  const T t8 = t1 * t1;
  const T t9 = t7 * q0;
  const T t10 = t8 * q1;
  const T t11 = t3 * q1;
  const T t12 = t6 * q0;
  const T t13 = T(2) * (T(231) * t3 * slope1 - T(231) * t6 * slope0 - T(4) * (T(2) * (T(35) * t7 * slope0 - T(8) * (T(5) * t2 * slope1 - T(5) * t5 * slope0 - T(2) * D * t0 * (T(4) * (T(2) * D * (in.t0 - in.t1) + q0 * slope0 - q1 * slope1) * D * t0 + T(3) * t4 * slope0 - T(3) * t1 * slope1)) * D * t0 - T(35) * t8 * slope1) * D * t0 + T(63) * t9 * slope0 - T(63) * t10 * slope1) * D * t0) * D * t0 + T(429) * t11 * slope1 - T(429) * t12 * slope0;
  const T t14 = t8 * t8;
  const T t15 = t7 * t7;
  const T t16 = T(16) * b * t0 * t13 + T(6435) * t14 - T(6435) * t15;
  const T g_ap = (T(1) / T(6435)) * t0 * t13 * in.w[0] + (T(1) / T(102960)) * in.w[1] * t16 * t0;
  const T t17 = T(16) * D * t0 * t13 + T(6435) * t14 * slope1 - T(6435) * t15 * slope0;
  const T g_ab = (T(1) / T(102960)) * t16 * t0 * in.w[0] + (T(1) / T(875160)) * in.w[1] * t0 * (T(8) * t0 * t17 + T(17) * t16 * b * t0 - T(136) * t0 * t13 * c);
  const T g_factor = -T(16) * length * inv_R2;
  const T t18 = t15 * q0;
  const T t19 = t14 * q1;
  f = -(T(1) / T(218790)) * (in.w[1] * (T(12155) * t18 - T(12155) * t19 - T(2) * b * t0 * t17) * t0 - T(2) * t0 * in.w[0] * t17) * length;
  grad[0] = -g_factor * (ab0 * g_ab - ap0 * g_ap);
  grad[1] = -(ab1 * g_ab - ap1 * g_ap) * g_factor;
  grad[2] = -(ab2 * g_ab - ap2 * g_ap) * g_factor;
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 50 +, 128 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t5 * q0;
  const T t9 = t8 * t8;
  const T t10 = t9 * q0;
  const T t11 = t6 * q0;
  const T t12 = t1 * q1;
  const T t13 = t2 * q1;
  const T t14 = t12 * t12;
  const T t15 = t14 * q1;
  const T t16 = T(6435) * t7 * slope0 + T(16) * (T(429) * t10 * slope0 + T(2) * D * t0 * (T(4) * D * t0 * (T(63) * t11 * slope0 + T(2) * (T(35) * t6 * slope0 - T(8) * D * t0 * (T(2) * (T(4) * D * t0 * (T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0) + T(3) * t1 * slope1 - T(3) * t5 * slope0) * D * t0 + T(5) * t12 * slope1 - T(5) * t8 * slope0) - T(35) * t2 * slope1) * D * t0 - T(63) * t13 * slope1) + T(231) * t9 * slope0 - T(231) * t14 * slope1) - T(429) * t15 * slope1) * D * t0 - T(6435) * t3 * slope1;
  const T t17 = t7 * q0;
  const T t18 = T(12155) * t4 - T(2) * b * t0 * t16 - T(12155) * t17;
  f = (T(1) / T(4157010)) * length * (T(19) * t0 * t18 * in.w[1] + T(2) * in.w[2] * t0 * (T(19) * b * t0 * t18 + T(19) * t0 * t16 * c - T(9) * (T(2) * D * t0 * t16 + T(12155) * t17 * slope0 - T(12155) * t4 * slope1) * t0) - T(38) * in.w[0] * t0 * t16);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 57 +, 152 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i16_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T t0 = q0 * q0;
  const T t1 = t0 * q0;
  const T t2 = t1 * t1;
  const T t3 = t2 * q0;
  const T t4 = q1 * q1;
  const T t5 = t4 * q1;
  const T t6 = t5 * t5;
  const T t7 = t6 * q1;
  const T t8 = T(1) / a;
  const T t9 = t4 * t4;
  const T t10 = t0 * t0;
  const T t11 = t9 * q1;
  const T t12 = t10 * q0;
  const T t13 = T(429) * t3 * slope0 - T(429) * t7 * slope1 - T(2) * (T(4) * (T(2) * (T(8) * (T(2) * D * (T(4) * (T(2) * (in.t1 - in.t0) * D + q1 * slope1 - q0 * slope0) * D * t8 + T(3) * t4 * slope1 - T(3) * t0 * slope0) * t8 + T(5) * t5 * slope1 - T(5) * t1 * slope0) * D * t8 + T(35) * t9 * slope1 - T(35) * t10 * slope0) * D * t8 + T(63) * t11 * slope1 - T(63) * t12 * slope0) * D * t8 + T(231) * t6 * slope1 - T(231) * t2 * slope0) * D * t8;
  const T t14 = t10 * t10;
  const T t15 = t9 * t9;
  const T t16 = T(6435) * t14 + T(16) * b * t13 * t8 - T(6435) * t15;
  const T t17 = T(6435) * t15 * slope1 - T(16) * t13 * D * t8 - T(6435) * t14 * slope0;
  const T t18 = T(17) * b * t16 * t8 - T(8) * t17 * t8 - T(136) * c * t13 * t8;
  const T g_ap = -(T(1) / T(6435)) * t13 * in.w[0] * t8 - (T(1) / T(875160)) * t18 * in.w[2] * t8 - (T(1) / T(102960)) * in.w[1] * t16 * t8;
  const T t19 = t15 * q1;
  const T t20 = t14 * q0;
  const T g_ab = (T(1) / T(1750320)) * (T(17) * c * t16 * t8 + T(8) * (T(2) * t17 * b * t8 + T(12155) * t19 - T(12155) * t20) * t8 - T(4) * t18 * b * t8) * in.w[2] * t8 - (T(1) / T(102960)) * t16 * in.w[0] * t8 - (T(1) / T(875160)) * in.w[1] * t18 * t8;
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = (g_ap * ap0 - ab0 * g_ab) * g_factor;
  grad[1] = (ap1 * g_ap - ab1 * g_ab) * g_factor;
  grad[2] = g_factor * (ap2 * g_ap - ab2 * g_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 63 +, 179 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * q1;
  const T t3 = T(1) / a;
  const T t4 = t0 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * q0;
  const T t7 = t5 * t5;
  const T t8 = t7 * q0;
  const T t9 = t4 * t4;
  const T t10 = t6 * t6;
  const T t11 = t9 * q1;
  const T t12 = t10 * q0;
  const T t13 = T(2) * (T(4) * (T(63) * t2 * slope1 + T(2) * (T(35) * t1 * slope1 + T(8) * (T(2) * D * t3 * (T(3) * t0 * slope1 - T(3) * q0 * q0 * slope0 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t3) + T(5) * t4 * slope1 - T(5) * t6 * slope0) * D * t3 - T(35) * t7 * slope0) * D * t3 - T(63) * t8 * slope0) * D * t3 + T(231) * t9 * slope1 - T(231) * t10 * slope0) * D * t3 + T(429) * t11 * slope1 - T(429) * t12 * slope0;
  const T t14 = t1 * t1;
  const T t15 = t7 * t7;
  const T t16 = T(16) * t13 * D * t3 + T(6435) * t14 * slope1 - T(6435) * t15 * slope0;
  const T t17 = T(6435) * t15 - T(16) * t13 * b * t3 - T(6435) * t14;
  const T t18 = T(8) * t16 * t3 - T(136) * c * t13 * t3 - T(17) * b * t17 * t3;
  const T g_ap = (T(1) / T(6435)) * t13 * in.w[0] * t3 + (T(1) / T(875160)) * in.w[2] * t3 * t18 - (T(1) / T(102960)) * t17 * t3 * in.w[1];
  const T t19 = t14 * q1;
  const T t20 = t15 * q0;
  const T t21 = T(12155) * t19 + T(2) * b * t16 * t3 - T(12155) * t20;
  const T g_ab = (T(1) / T(875160)) * t3 * t18 * in.w[1] + (T(1) / T(1750320)) * in.w[2] * (T(4) * b * t3 * t18 + T(17) * c * t17 * t3 + T(8) * t3 * t21) * t3 - (T(1) / T(102960)) * in.w[0] * t17 * t3;
  const T g_factor = -T(16) * inv_R2 * length;
  f = (T(1) / T(4157010)) * (T(38) * t16 * in.w[0] * t3 + T(19) * t3 * in.w[1] * t21 + T(2) * in.w[2] * (T(9) * (T(12155) * t19 * slope1 + T(2) * t16 * D * t3 - T(12155) * t20 * slope0) * t3 + T(19) * b * t3 * t21 - T(19) * c * t16 * t3) * t3) * length;
  grad[0] = g_factor * (g_ap * ap0 - ab0 * g_ab);
  grad[1] = -g_factor * (ab1 * g_ab - g_ap * ap1);
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return f;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 55 +, 145 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * t1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = q0 * q0;
  const T t6 = t5 * t5;
  const T t7 = t6 * t6;
  const T t8 = t7 * q0;
  const T t9 = t5 * q0;
  const T t10 = t9 * t9;
  const T t11 = t10 * q0;
  const T t12 = t1 * q1;
  const T t13 = t6 * q0;
  const T t14 = t2 * q1;
  const T t15 = t12 * t12;
  const T t16 = t15 * q1;
  const T t17 = T(6435) * slope0 * t7 + T(16) * (T(429) * slope0 * t11 + T(2) * D * t0 * (T(4) * D * t0 * (T(2) * D * t0 * (T(8) * D * t0 * (T(5) * slope0 * t9 + T(2) * D * t0 * (T(4) * D * t0 * (slope0 * q0 - T(2) * D * (in.t1 - in.t0) - q1 * slope1) + T(3) * slope0 * t5 - T(3) * t1 * slope1) - T(5) * t12 * slope1) + T(35) * slope0 * t6 - T(35) * t2 * slope1) + T(63) * slope0 * t13 - T(63) * t14 * slope1) + T(231) * slope0 * t10 - T(231) * t15 * slope1) - T(429) * t16 * slope1) * D * t0 - T(6435) * t3 * slope1;
  const T t18 = T(12155) * t4 - T(12155) * t8 - T(2) * t0 * t17 * b;
  const T t19 = T(12155) * t4 * slope1 - T(12155) * slope0 * t8 - T(2) * D * t0 * t17;
  const T t20 = T(19) * t0 * t18 * b + T(19) * t0 * c * t17 + T(9) * t0 * t19;
  const T t21 = t14 * t14;
  const T t22 = t13 * t13;
  f = (T(1) / T(8314020)) * length * (T(38) * t0 * t18 * in.w[1] + t0 * (T(8) * t0 * t20 * b + T(9) * t0 * (T(4) * t0 * t19 * b + T(46189) * t21 - T(46189) * t22) - T(38) * t0 * t18 * c) * in.w[3] + T(4) * t0 * in.w[2] * t20 - T(76) * t0 * t17 * in.w[0]);
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 65 +, 181 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i16_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = q1 * q1;
  const T t1 = t0 * t0;
  const T t2 = t1 * t1;
  const T t3 = q0 * q0;
  const T t4 = t3 * t3;
  const T t5 = t4 * t4;
  const T t6 = T(1) / a;
  const T t7 = t4 * q0;
  const T t8 = t0 * q1;
  const T t9 = t3 * q0;
  const T t10 = t1 * q1;
  const T t11 = t9 * t9;
  const T t12 = t8 * t8;
  const T t13 = t11 * q0;
  const T t14 = t12 * q1;
  const T t15 = T(2) * D * t6 * (T(4) * (T(63) * t7 * slope0 + T(2) * (T(35) * t4 * slope0 - T(8) * D * t6 * (T(2) * D * (T(3) * t0 * slope1 - T(3) * t3 * slope0 - T(4) * (q0 * slope0 - T(2) * (in.t1 - in.t0) * D - q1 * slope1) * D * t6) * t6 + T(5) * t8 * slope1 - T(5) * t9 * slope0) - T(35) * t1 * slope1) * D * t6 - T(63) * t10 * slope1) * D * t6 + T(231) * t11 * slope0 - T(231) * t12 * slope1) + T(429) * t13 * slope0 - T(429) * t14 * slope1;
  const T t16 = T(6435) * t2 - T(6435) * t5 - T(16) * t15 * b * t6;
  const T t17 = T(6435) * t5 * slope0 + T(16) * t15 * D * t6 - T(6435) * t2 * slope1;
  const T t18 = T(17) * b * t16 * t6 + T(136) * t15 * t6 * c - T(8) * t6 * t17;
  const T t19 = t5 * q0;
  const T t20 = t2 * q1;
  const T t21 = T(12155) * t19 + T(2) * b * t6 * t17 - T(12155) * t20;
  const T t22 = T(17) * t16 * t6 * c + T(8) * t6 * t21 - T(4) * b * t18 * t6;
  const T g_ap = (T(1) / T(102960)) * t16 * in.w[1] * t6 + (T(1) / T(875160)) * t18 * t6 * in.w[2] - (T(1) / T(6435)) * in.w[0] * t15 * t6 - (T(1) / T(1750320)) * in.w[3] * t22 * t6;
  const T g_ab = (T(1) / T(102960)) * in.w[0] * t16 * t6 + (T(1) / T(875160)) * t18 * in.w[1] * t6 - (T(1) / T(1750320)) * t22 * t6 * in.w[2] - (T(1) / T(16628040)) * in.w[3] * t6 * (T(8) * (T(19) * b * t6 * t21 - T(9) * (T(12155) * t20 * slope1 - T(2) * D * t6 * t17 - T(12155) * t19 * slope0) * t6 - T(19) * t6 * t17 * c) * t6 + T(19) * b * t22 * t6 + T(19) * t18 * t6 * c);
  const T g_factor = -T(16) * length * inv_R2;
  grad[0] = g_factor * (ap0 * g_ap - ab0 * g_ab);
  grad[1] = -(ab1 * g_ab - g_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * g_ab - g_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 72 +, 209 ×, 2 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
T segment_compact_i16_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T t0 = T(1) / a;
  const T t1 = q1 * q1;
  const T t2 = t1 * q1;
  const T t3 = t2 * t2;
  const T t4 = t3 * q1;
  const T t5 = t1 * t1;
  const T t6 = t5 * q1;
  const T t7 = q0 * q0;
  const T t8 = t7 * q0;
  const T t9 = t7 * t7;
  const T t10 = t9 * q0;
  const T t11 = t8 * t8;
  const T t12 = t11 * q0;
  const T t13 = T(429) * t4 * slope1 + T(2) * D * t0 * (T(4) * D * t0 * (T(63) * t6 * slope1 + T(2) * D * t0 * (T(35) * t5 * slope1 - T(8) * D * t0 * (T(5) * slope0 * t8 + T(2) * D * t0 * (T(3) * slope0 * t7 - T(4) * D * t0 * (T(2) * D * (in.t1 - in.t0) + q1 * slope1 - slope0 * q0) - T(3) * t1 * slope1) - T(5) * t2 * slope1) - T(35) * slope0 * t9) - T(63) * slope0 * t10) + T(231) * t3 * slope1 - T(231) * slope0 * t11) - T(429) * slope0 * t12;
  const T t14 = t9 * t9;
  const T t15 = t5 * t5;
  const T t16 = T(6435) * t14 - T(6435) * t15 - T(16) * t0 * t13 * b;
  const T t17 = T(16) * D * t0 * t13 + T(6435) * t15 * slope1 - T(6435) * slope0 * t14;
  const T t18 = T(136) * t0 * c * t13 + T(17) * t0 * b * t16 - T(8) * t17 * t0;
  const T t19 = t14 * q0;
  const T t20 = t15 * q1;
  const T t21 = T(12155) * t19 - T(2) * t17 * t0 * b - T(12155) * t20;
  const T t22 = T(4) * t0 * t18 * b + T(8) * t0 * t21 - T(17) * t0 * c * t16;
  const T g_ap = (T(1) / T(6435)) * t0 * in.w[0] * t13 - (T(1) / T(875160)) * t0 * in.w[2] * t18 - (T(1) / T(102960)) * t0 * t16 * in.w[1] - (T(1) / T(1750320)) * t0 * in.w[3] * t22;
  const T t23 = T(12155) * slope0 * t19 - T(2) * t17 * D * t0 - T(12155) * t20 * slope1;
  const T t24 = T(9) * t0 * t23 + T(19) * t17 * t0 * c + T(19) * t0 * t21 * b;
  const T g_ab = -(T(1) / T(875160)) * t0 * t18 * in.w[1] - (T(1) / T(102960)) * t0 * in.w[0] * t16 - (T(1) / T(1750320)) * t0 * in.w[2] * t22 - (T(1) / T(16628040)) * t0 * in.w[3] * (T(19) * t0 * t22 * b + T(8) * t0 * t24 - T(19) * t0 * c * t18);
  const T g_factor = -T(16) * inv_R2 * length;
  const T t25 = t6 * t6;
  const T t26 = t10 * t10;
  f = (T(1) / T(8314020)) * (t0 * (T(9) * (T(46189) * t25 - T(4) * t0 * t23 * b - T(46189) * t26) * t0 + T(38) * t0 * t21 * c - T(8) * t0 * b * t24) * in.w[3] + T(76) * t17 * t0 * in.w[0] - T(4) * t0 * in.w[2] * t24 - T(38) * t0 * t21 * in.w[1]) * length;
  grad[0] = (g_ap * ap0 - g_ab * ab0) * g_factor;
  grad[1] = -(g_ab * ab1 - ap1 * g_ap) * g_factor;
  grad[2] = (ap2 * g_ap - g_ab * ab2) * g_factor;
  return f;
}

}  // namespace skelconv::generated
