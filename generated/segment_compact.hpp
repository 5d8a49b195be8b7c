// generated/segment_compact.hpp — segment kernels of the compact family.
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
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 43 +, 71 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 2, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 53 +, 82 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i2_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 3, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(0, 0, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 67 +, 105 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 3, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Returns false where segment_compact_i2_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 105 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i2_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 3, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 51 +, 79 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 3, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 62 +, 91 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i2_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(0, 0, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
    G_ab = M_exact[2] * in.w[1] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(2) * length * inv_R2;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 84 +, 122 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ap = M_exact[3] * in.w[0] + M_exact[4] * in.w[1];
    G_ab = in.w[1] * M_exact[5] + in.w[0] * M_exact[4];
  }
  const T g_factor = -T(2) * length * inv_R2;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Returns false where segment_compact_i2_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 84 +, 122 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i2_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
    G_ap = M_exact[4] * in.w[1] + in.w[0] * M_exact[3];
    G_ab = M_exact[5] * in.w[1] + M_exact[4] * in.w[0];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 59 +, 87 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 71 +, 100 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i2_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(0, 0, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + M_exact[0] * in.w[0] + M_exact[2] * in.w[2];
    G_ab = in.w[2] * M_exact[3] + in.w[0] * M_exact[1] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(2) * length * inv_R2;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 101 +, 139 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + M_exact[0] * in.w[0];
    G_ap = M_exact[6] * in.w[2] + in.w[1] * M_exact[5] + M_exact[4] * in.w[0];
    G_ab = in.w[1] * M_exact[6] + in.w[2] * M_exact[7] + in.w[0] * M_exact[5];
  }
  const T g_factor = -T(2) * length * inv_R2;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Returns false where segment_compact_i2_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 101 +, 139 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i2_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + in.w[0] * M_exact[0];
    G_ap = M_exact[4] * in.w[0] + in.w[2] * M_exact[6] + in.w[1] * M_exact[5];
    G_ab = in.w[1] * M_exact[6] + in.w[2] * M_exact[7] + M_exact[5] * in.w[0];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 67 +, 95 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[2] * in.w[2] + M_exact[1] * in.w[1] + in.w[3] * M_exact[3] + M_exact[0] * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 80 +, 109 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i2_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(0, 0, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + in.w[3] * M_exact[3];
    G_ab = in.w[1] * M_exact[2] + in.w[3] * M_exact[4] + in.w[2] * M_exact[3] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Operations: 118 +, 156 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i2_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[3] * M_exact[3] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0];
    G_ap = M_exact[7] * in.w[2] + M_exact[8] * in.w[3] + M_exact[6] * in.w[1] + M_exact[5] * in.w[0];
    G_ab = in.w[3] * M_exact[9] + in.w[0] * M_exact[6] + in.w[2] * M_exact[8] + M_exact[7] * in.w[1];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(2/2) dt
/// Returns false where segment_compact_i2_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 118 +, 156 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i2_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-2, 0, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[2] * in.w[2] + in.w[3] * M_exact[3] + in.w[0] * M_exact[0] + in.w[1] * M_exact[1];
    G_ap = M_exact[7] * in.w[2] + in.w[0] * M_exact[5] + in.w[3] * M_exact[8] + M_exact[6] * in.w[1];
    G_ab = in.w[2] * M_exact[8] + in.w[3] * M_exact[9] + in.w[1] * M_exact[7] + in.w[0] * M_exact[6];
  }
  const T g_factor = -T(2) * inv_R2 * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 36 +, 57 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2071 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-5 = J_upward_compact(…)
    F = (T(1) / T(5)) * (T(6) * a * J_upward_compact<T>(-5, a, D, slope0, q0, slope1, q1) + slope0 * q0 * q0 * r0 - r1 * slope1 * q1 * q1) * in.w[0] / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    F = -(T(1) / T(8)) * t0 * in.w[0] * (T(2) * slope0 * q0 * r0 + T(3) * (slope0 * r0 - r1 * slope1 - D * J1) * D * t0 - T(2) * r1 * slope1 * q1);
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 39 +, 68 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2100 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-1, -1, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-5 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = T(4) * (q0 * q0 * r0 * slope0 + T(6) * a * J_upward_compact<T>(-5, a, D, slope0, q0, slope1, q1) - slope1 * q1 * q1 * r1) * a * t5 + T(5) * q0 * r0 * slope0 - T(5) * slope1 * q1 * r1;
    G_ap = (T(1) / T(15)) * t6 * t5 * in.w[0];
    G_ab = (T(1) / T(15)) * (T(5) * q1 * r1 + t6 * t5 * b - T(5) * q0 * r0) * t0 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = J1 * D + slope1 * r1 - r0 * slope0;
    G_ap = (T(1) / T(2)) * t7 * t0 * in.w[0];
    G_ab = (T(1) / T(6)) * (T(2) * q1 * r1 + T(3) * t7 * t0 * b - T(2) * q0 * r0) * t0 * in.w[0];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 41 +, 81 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2104 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-5 = J_upward_compact(…)
    const T t6 = slope0 * q0 * q0 * r0 + T(6) * a * J_upward_compact<T>(-5, a, D, slope0, q0, slope1, q1) - slope1 * q1 * q1 * r1;
    const T t7 = T(1) / D;
    F = (T(1) / T(5)) * in.w[0] * t6 * t7;
    const T t8 = T(4) * t6 * t7 * a + T(5) * slope0 * q0 * r0 - T(5) * slope1 * q1 * r1;
    G_ap = (T(1) / T(15)) * in.w[0] * t7 * t8;
    G_ab = -(T(1) / T(15)) * (T(5) * q0 * r0 - b * t7 * t8 - T(5) * q1 * r1) * in.w[0] * t1;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t9 = slope0 * r0 - J1 * D - slope1 * r1;
    F = (T(1) / T(8)) * (T(2) * slope1 * q1 * r1 - T(3) * D * t1 * t9 - T(2) * slope0 * q0 * r0) * in.w[0] * t1;
    G_ap = -(T(1) / T(2)) * in.w[0] * t1 * t9;
    G_ab = -(T(1) / T(6)) * in.w[0] * (T(2) * q0 * r0 + T(3) * b * t1 * t9 - T(2) * q1 * r1) * t1;
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Returns false where segment_compact_i3_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 41 +, 81 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i3_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = in.w[0] * M_flat[3];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = D * J1 + r1 * slope1 - slope0 * r0;
    F = (T(1) / T(8)) * (T(3) * D * t2 * t7 + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0) * in.w[0] * t2;
    G_ap = (T(1) / T(2)) * in.w[0] * t2 * t7;
    G_ab = (T(1) / T(6)) * in.w[0] * (T(2) * r1 * q1 + T(3) * b * t2 * t7 - T(2) * q0 * r0) * t2;
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 39 +, 69 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2095 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = T(6) * t6 * a * (slope0 * t8 * r0 + T(8) * a * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) - r1 * slope1 * t10) + T(7) * slope0 * t7 * r0 - T(7) * r1 * slope1 * t9;
    F = (T(1) / T(35)) * t6 * in.w[0] * t11 + (T(1) / T(35)) * t1 * (T(7) * r1 * t9 + t6 * t11 * b - T(7) * t7 * r0) * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t12 = q1 * q1;
    const T t13 = T(3) * D * t1 * (D * J1 + r1 * slope1 - slope0 * r0) + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0;
    const T t14 = q0 * q0;
    F = (T(1) / T(40)) * t1 * (T(8) * r1 * t12 + T(5) * t1 * b * t13 - T(8) * t14 * r0) * in.w[1] + (T(1) / T(8)) * t1 * in.w[0] * t13;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 45 +, 91 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2127 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-1, -1, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = T(6) * (T(8) * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) * a + r0 * slope0 * t8 - t10 * r1 * slope1) * t6 * a + T(7) * r0 * slope0 * t7 - T(7) * t9 * r1 * slope1;
    const T t12 = T(35) * q1 * r1 * slope1 - T(4) * t6 * a * t11 - T(35) * r0 * slope0 * q0;
    const T t13 = T(35) * r0 * q0 + t6 * b * t12 - T(35) * q1 * r1;
    G_ap = -(T(1) / T(105)) * t13 * t1 * in.w[1] - (T(1) / T(105)) * t6 * in.w[0] * t12;
    G_ab = (T(1) / T(105)) * t1 * (t6 * t12 * c + T(3) * t6 * t11 - T(2) * t13 * t1 * b) * in.w[1] - (T(1) / T(105)) * t13 * t1 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = r0 * slope0 - r1 * slope1 - J1 * D;
    const T t15 = T(2) * r0 * q0 + T(3) * t14 * t1 * b - T(2) * q1 * r1;
    G_ap = -(T(1) / T(2)) * t14 * t1 * in.w[0] - (T(1) / T(6)) * t15 * t1 * in.w[1];
    G_ab = (T(1) / T(24)) * t1 * (T(3) * t1 * (T(2) * q1 * r1 * slope1 - T(3) * t14 * D * t1 - T(2) * r0 * slope0 * q0) + T(12) * t14 * t1 * c - T(8) * t15 * t1 * b) * in.w[1] - (T(1) / T(6)) * t15 * t1 * in.w[0];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 48 +, 107 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2140 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
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
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = T(6) * t6 * a * (T(8) * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) * a + t8 * r0 * slope0 - slope1 * t10 * r1) + T(7) * t7 * r0 * slope0 - T(7) * slope1 * t9 * r1;
    F = (T(1) / T(35)) * t1 * in.w[1] * (t11 * t6 * b + T(7) * t9 * r1 - T(7) * t7 * r0) + (T(1) / T(35)) * t11 * t6 * in.w[0];
    const T t12 = T(35) * slope1 * q1 * r1 - T(4) * t11 * t6 * a - T(35) * q0 * r0 * slope0;
    const T t13 = T(35) * q1 * r1 - t6 * b * t12 - T(35) * q0 * r0;
    G_ap = (T(1) / T(105)) * t1 * t13 * in.w[1] - (T(1) / T(105)) * t6 * in.w[0] * t12;
    G_ab = (T(1) / T(105)) * t1 * t13 * in.w[0] + (T(1) / T(105)) * t1 * (t6 * t12 * c + T(3) * t11 * t6 + T(2) * t1 * t13 * b) * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = slope1 * r1 + D * J1 - r0 * slope0;
    const T t15 = T(3) * t14 * D * t1 + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0;
    const T t16 = q0 * q0;
    const T t17 = q1 * q1;
    F = (T(1) / T(8)) * t15 * t1 * in.w[0] - (T(1) / T(40)) * (T(8) * t16 * r0 - T(5) * t15 * t1 * b - T(8) * t17 * r1) * t1 * in.w[1];
    const T t18 = T(2) * q1 * r1 + T(3) * t14 * t1 * b - T(2) * q0 * r0;
    G_ap = (T(1) / T(6)) * t1 * t18 * in.w[1] + (T(1) / T(2)) * t14 * t1 * in.w[0];
    G_ab = (T(1) / T(6)) * t1 * in.w[0] * t18 + (T(1) / T(24)) * t1 * (T(3) * t15 * t1 + T(8) * t1 * t18 * b - T(12) * t14 * t1 * c) * in.w[1];
  }
  const T g_factor = -T(3) * length * inv_R2;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Returns false where segment_compact_i3_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 48 +, 107 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i3_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = in.w[0] * M_flat[3] + M_flat[4] * in.w[1];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = slope0 * r0 - slope1 * r1 - D * J1;
    const T t6 = T(3) * D * t0 * t5 + T(2) * slope0 * q0 * r0 - T(2) * slope1 * q1 * r1;
    const T t7 = q0 * q0;
    const T t8 = q1 * q1;
    F = -(T(1) / T(8)) * t6 * t0 * in.w[0] - (T(1) / T(40)) * t0 * (T(8) * t7 * r0 + T(5) * t6 * t0 * b - T(8) * t8 * r1) * in.w[1];
    const T t9 = T(2) * q1 * r1 - T(3) * t0 * t5 * b - T(2) * q0 * r0;
    G_ap = (T(1) / T(6)) * t0 * t9 * in.w[1] - (T(1) / T(2)) * t0 * in.w[0] * t5;
    G_ab = (T(1) / T(6)) * t0 * t9 * in.w[0] - (T(1) / T(24)) * (T(3) * t6 * t0 - T(12) * c * t0 * t5 - T(8) * t0 * t9 * b) * t0 * in.w[1];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 44 +, 89 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2105 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, root_minus_a * r1)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = slope1 * t8 * r1 - slope0 * t10 * r0 - T(8) * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) * a;
    const T t12 = T(7) * slope1 * t7 * r1 + T(6) * t6 * t11 * a - T(7) * slope0 * t9 * r0;
    const T t13 = t6 * b * t12 + T(7) * t9 * r0 - T(7) * t7 * r1;
    F = (T(1) / T(35)) * in.w[2] * (t6 * t12 * c - T(5) * t6 * t11 - T(2) * b * t13 * t1) * t1 - (T(1) / T(35)) * t6 * t12 * in.w[0] - (T(1) / T(35)) * in.w[1] * t13 * t1;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = q1 * q1;
    const T t15 = T(2) * slope0 * q0 * r0 - T(3) * D * (D * J1 + slope1 * r1 - slope0 * r0) * t1 - T(2) * slope1 * q1 * r1;
    const T t16 = q0 * q0;
    const T t17 = T(8) * t14 * r1 - T(5) * t15 * b * t1 - T(8) * t16 * r0;
    F = (T(1) / T(40)) * in.w[1] * t17 * t1 + (T(1) / T(240)) * in.w[2] * (T(12) * t17 * b * t1 + T(30) * t15 * c * t1 + T(5) * (T(8) * slope1 * t14 * r1 - T(5) * t15 * D * t1 - T(8) * slope0 * t16 * r0) * t1) * t1 - (T(1) / T(8)) * t15 * in.w[0] * t1;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 51 +, 114 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2146 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-1, -1, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[1] * in.w[0] + M_flat[2] * in.w[1] + in.w[2] * M_flat[3];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = T(1) / D;
    const T t10 = T(7) * t5 * r0 * slope0 + T(6) * (T(8) * a * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) + t6 * r0 * slope0 - slope1 * t8 * r1) * t9 * a - T(7) * slope1 * t7 * r1;
    const T t11 = T(35) * slope1 * q1 * r1 - T(4) * t10 * t9 * a - T(35) * q0 * r0 * slope0;
    const T t12 = T(35) * q0 * r0 + t11 * t9 * b - T(35) * q1 * r1;
    const T t13 = t11 * c * t9 + T(3) * t10 * t9 - T(2) * t12 * t0 * b;
    G_ap = (T(1) / T(105)) * in.w[2] * t13 * t0 - (T(1) / T(105)) * t11 * in.w[0] * t9 - (T(1) / T(105)) * t12 * t0 * in.w[1];
    G_ab = (T(1) / T(105)) * in.w[2] * t0 * (T(2) * t13 * t0 * b + c * t12 * t0 + T(3) * (t10 * t9 * b + T(7) * t7 * r1 - T(7) * t5 * r0) * t0) + (T(1) / T(105)) * t13 * t0 * in.w[1] - (T(1) / T(105)) * t12 * in.w[0] * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = slope1 * r1 + J1 * D - r0 * slope0;
    const T t15 = T(2) * q0 * r0 - T(2) * q1 * r1 - T(3) * t0 * t14 * b;
    const T t16 = T(2) * slope1 * q1 * r1 + T(3) * D * t0 * t14 - T(2) * q0 * r0 * slope0;
    const T t17 = T(8) * t15 * t0 * b + T(12) * c * t0 * t14 - T(3) * t0 * t16;
    G_ap = (T(1) / T(2)) * in.w[0] * t0 * t14 - (T(1) / T(24)) * in.w[2] * t17 * t0 - (T(1) / T(6)) * t15 * t0 * in.w[1];
    const T t18 = q1 * q1;
    const T t19 = q0 * q0;
    G_ab = (T(1) / T(120)) * in.w[2] * t0 * (T(3) * t0 * (T(5) * t0 * t16 * b + T(8) * t18 * r1 - T(8) * t19 * r0) + T(20) * t15 * c * t0 - T(10) * t17 * t0 * b) - (T(1) / T(6)) * t15 * in.w[0] * t0 - (T(1) / T(24)) * t17 * t0 * in.w[1];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 57 +, 141 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2163 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = in.w[2] * M_flat[6] + in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
    G_ab = in.w[0] * M_flat[5] + M_flat[7] * in.w[2] + in.w[1] * M_flat[6];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = q0 * q0;
    const T t7 = T(1) / D;
    const T t8 = t6 * q0;
    const T t9 = t5 * q1;
    const T t10 = T(8) * a * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) + slope0 * t8 * r0 - slope1 * t9 * r1;
    const T t11 = T(7) * slope0 * t6 * r0 + T(6) * a * t7 * t10 - T(7) * slope1 * t5 * r1;
    const T t12 = T(7) * t5 * r1 + t11 * b * t7 - T(7) * t6 * r0;
    F = (T(1) / T(35)) * t0 * in.w[1] * t12 + (T(1) / T(35)) * t0 * (T(5) * t7 * t10 + T(2) * t0 * t12 * b - t11 * t7 * c) * in.w[2] + (T(1) / T(35)) * t11 * in.w[0] * t7;
    const T t13 = T(4) * t11 * a * t7 + T(35) * slope0 * q0 * r0 - T(35) * slope1 * q1 * r1;
    const T t14 = T(35) * q0 * r0 - T(35) * q1 * r1 - b * t7 * t13;
    const T t15 = T(2) * t0 * b * t14 + t7 * t13 * c - T(3) * t11 * t7;
    G_ap = (T(1) / T(105)) * in.w[0] * t7 * t13 - (T(1) / T(105)) * t0 * in.w[1] * t14 - (T(1) / T(105)) * t15 * t0 * in.w[2];
    G_ab = (T(1) / T(105)) * t0 * in.w[2] * (t0 * c * t14 + T(3) * t0 * t12 - T(2) * t15 * t0 * b) - (T(1) / T(105)) * t15 * t0 * in.w[1] - (T(1) / T(105)) * in.w[0] * t0 * t14;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t16 = slope0 * r0 - D * J1 - slope1 * r1;
    const T t17 = T(2) * slope1 * q1 * r1 - T(3) * t0 * D * t16 - T(2) * slope0 * q0 * r0;
    const T t18 = q1 * q1;
    const T t19 = q0 * q0;
    const T t20 = T(5) * t0 * b * t17 + T(8) * t18 * r1 - T(8) * t19 * r0;
    F = (T(1) / T(40)) * t0 * in.w[1] * t20 + (T(1) / T(8)) * in.w[0] * t0 * t17 - (T(1) / T(240)) * t0 * (T(5) * (T(8) * slope0 * t19 * r0 - T(5) * t0 * D * t17 - T(8) * slope1 * t18 * r1) * t0 + T(30) * t0 * c * t17 - T(12) * t0 * b * t20) * in.w[2];
    const T t21 = T(2) * q0 * r0 + T(3) * t0 * b * t16 - T(2) * q1 * r1;
    const T t22 = T(12) * t0 * t16 * c + T(3) * t0 * t17 - T(8) * t21 * t0 * b;
    G_ap = (T(1) / T(24)) * t0 * in.w[2] * t22 - (T(1) / T(2)) * in.w[0] * t0 * t16 - (T(1) / T(6)) * t21 * t0 * in.w[1];
    G_ab = (T(1) / T(120)) * t0 * (T(3) * t0 * t20 + T(10) * t0 * b * t22 + T(20) * t21 * t0 * c) * in.w[2] + (T(1) / T(24)) * t0 * in.w[1] * t22 - (T(1) / T(6)) * t21 * in.w[0] * t0;
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Returns false where segment_compact_i3_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 57 +, 141 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i3_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = M_flat[5] * in.w[1] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = D * J1 + r1 * slope1 - slope0 * r0;
    const T t6 = T(2) * slope0 * q0 * r0 - T(3) * t5 * D * t0 - T(2) * r1 * slope1 * q1;
    const T t7 = q0 * q0;
    const T t8 = q1 * q1;
    const T t9 = T(8) * t7 * r0 + T(5) * t6 * t0 * b - T(8) * r1 * t8;
    F = -(T(1) / T(8)) * in.w[0] * t6 * t0 - (T(1) / T(40)) * t9 * t0 * in.w[1] - (T(1) / T(240)) * in.w[2] * (T(12) * t9 * t0 * b + T(5) * (T(5) * t6 * D * t0 + T(8) * slope0 * t7 * r0 - T(8) * r1 * slope1 * t8) * t0 - T(30) * c * t6 * t0) * t0;
    const T t10 = T(3) * t5 * t0 * b + T(2) * r1 * q1 - T(2) * q0 * r0;
    const T t11 = T(3) * t6 * t0 + T(12) * c * t5 * t0 - T(8) * t10 * t0 * b;
    G_ap = (T(1) / T(2)) * in.w[0] * t5 * t0 + (T(1) / T(6)) * t10 * t0 * in.w[1] - (T(1) / T(24)) * in.w[2] * t11 * t0;
    G_ab = (T(1) / T(6)) * in.w[0] * t10 * t0 - (T(1) / T(120)) * in.w[2] * (T(10) * t11 * t0 * b + T(3) * t9 * t0 + T(20) * c * t10 * t0) * t0 - (T(1) / T(24)) * t11 * t0 * in.w[1];
  }
  const T g_factor = -T(3) * length * inv_R2;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 49 +, 109 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2136 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = T(1) / D;
    const T t7 = q1 * q1;
    const T t8 = t5 * q0;
    const T t9 = t5 * t5;
    const T t10 = t7 * t7;
    const T t11 = t7 * q1;
    const T t12 = T(9) * slope0 * t8 * r0 + T(8) * t6 * a * (T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) + slope0 * t9 * r0 - slope1 * t10 * r1) - T(9) * slope1 * t11 * r1;
    const T t13 = T(21) * slope1 * t7 * r1 - T(21) * slope0 * t5 * r0 - T(2) * t6 * a * t12;
    const T t14 = T(21) * t5 * r0 + t6 * b * t13 - T(21) * t7 * r1;
    const T t15 = T(6) * t0 * t14 * b - T(5) * t6 * t12 - T(3) * t6 * t13 * c;
    F = (T(1) / T(315)) * (T(3) * t0 * t14 * c - T(2) * t0 * b * t15 - T(5) * t0 * (T(9) * t8 * r0 - t6 * t12 * b - T(9) * t11 * r1)) * t0 * in.w[3] - (T(1) / T(105)) * t0 * t14 * in.w[1] - (T(1) / T(105)) * t6 * in.w[0] * t13 - (T(1) / T(315)) * t0 * in.w[2] * t15;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t16 = q0 * q0;
    const T t17 = T(2) * slope0 * q0 * r0 - T(3) * D * t0 * (D * J1 + slope1 * r1 - slope0 * r0) - T(2) * slope1 * q1 * r1;
    const T t18 = q1 * q1;
    const T t19 = T(8) * t16 * r0 + T(5) * t0 * t17 * b - T(8) * t18 * r1;
    const T t20 = t16 * q0;
    const T t21 = T(5) * D * t0 * t17 + T(8) * slope0 * t16 * r0 - T(8) * slope1 * t18 * r1;
    const T t22 = t18 * q1;
    const T t23 = T(12) * t19 * t0 * b + T(5) * t0 * t21 - T(30) * t0 * t17 * c;
    F = (T(1) / T(1680)) * t0 * (T(42) * t19 * t0 * c - T(5) * t0 * (T(48) * t20 * r0 + T(7) * t0 * t21 * b - T(48) * t22 * r1) - T(14) * t0 * b * t23) * in.w[3] - (T(1) / T(40)) * t19 * t0 * in.w[1] - (T(1) / T(8)) * t0 * t17 * in.w[0] - (T(1) / T(240)) * t0 * in.w[2] * t23;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 59 +, 144 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2179 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i3_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-1, -1, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3];
    G_ab = M_flat[4] * in.w[3] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t7 * q0;
    const T t11 = t7 * t7;
    const T t12 = t8 * t8;
    const T t13 = T(9) * t9 * r1 * slope1 - T(9) * r0 * slope0 * t10 - T(8) * (T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t11 - t12 * r1 * slope1) * t6 * a;
    const T t14 = T(21) * r0 * slope0 * t7 - T(2) * t13 * t6 * a - T(21) * t8 * r1 * slope1;
    const T t15 = T(105) * q1 * r1 * slope1 - T(105) * r0 * slope0 * q0 - T(4) * t14 * t6 * a;
    const T t16 = t6 * t15 * b + T(105) * r0 * q0 - T(105) * q1 * r1;
    const T t17 = T(2) * t16 * t1 * b - T(3) * t14 * t6 - c * t6 * t15;
    const T t18 = T(21) * t8 * r1 + t14 * t6 * b - T(21) * r0 * t7;
    const T t19 = T(2) * t1 * b * t17 - T(3) * t18 * t1 - c * t16 * t1;
    G_ap = -(T(1) / T(315)) * t19 * t1 * in.w[3] - (T(1) / T(315)) * t6 * t15 * in.w[0] - (T(1) / T(315)) * t1 * in.w[2] * t17 - (T(1) / T(315)) * t16 * in.w[1] * t1;
    G_ab = -(T(1) / T(315)) * t19 * t1 * in.w[2] - (T(1) / T(315)) * in.w[1] * t1 * t17 - (T(1) / T(315)) * t1 * (T(2) * t19 * t1 * b + t1 * (T(5) * t13 * t6 + T(3) * c * t14 * t6 - T(6) * t18 * t1 * b) - c * t1 * t17) * in.w[3] - (T(1) / T(315)) * t16 * t1 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = J1 * D + r1 * slope1 - r0 * slope0;
    const T t21 = T(3) * t20 * t1 * b + T(2) * q1 * r1 - T(2) * r0 * q0;
    const T t22 = T(2) * q1 * r1 * slope1 + T(3) * t20 * D * t1 - T(2) * r0 * slope0 * q0;
    const T t23 = T(8) * t1 * t21 * b + T(3) * t1 * t22 - T(12) * c * t20 * t1;
    const T t24 = q1 * q1;
    const T t25 = q0 * q0;
    const T t26 = T(8) * t24 * r1 + T(5) * t1 * b * t22 - T(8) * r0 * t25;
    const T t27 = T(20) * c * t1 * t21 - T(10) * t1 * b * t23 - T(3) * t1 * t26;
    G_ap = (T(1) / T(24)) * t1 * in.w[2] * t23 + (T(1) / T(6)) * in.w[1] * t1 * t21 + (T(1) / T(2)) * t20 * t1 * in.w[0] - (T(1) / T(120)) * t1 * t27 * in.w[3];
    G_ab = (T(1) / T(24)) * in.w[1] * t1 * t23 + (T(1) / T(6)) * t1 * t21 * in.w[0] - (T(1) / T(120)) * t1 * in.w[2] * t27 - (T(1) / T(240)) * (T(4) * t1 * t27 * b + (T(5) * (T(8) * r0 * slope0 * t25 - T(5) * D * t1 * t22 - T(8) * t24 * r1 * slope1) * t1 + T(30) * c * t1 * t22 - T(12) * t1 * b * t26) * t1 + T(10) * c * t1 * t23) * t1 * in.w[3];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Operations: 66 +, 174 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2206 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i3_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[3] * M_flat[3] + in.w[2] * M_flat[2] + M_flat[1] * in.w[1];
    G_ap = in.w[3] * M_flat[8] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + M_flat[7] * in.w[2];
    G_ab = M_flat[8] * in.w[2] + in.w[0] * M_flat[6] + M_flat[7] * in.w[1] + in.w[3] * M_flat[9];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t6 * q1;
    const T t11 = t8 * q0;
    const T t12 = T(8) * a * t5 * (r1 * slope1 * t7 - T(10) * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) * a - slope0 * t9 * r0) + T(9) * r1 * slope1 * t10 - T(9) * slope0 * t11 * r0;
    const T t13 = T(2) * t12 * a * t5 + T(21) * r1 * slope1 * t6 - T(21) * slope0 * t8 * r0;
    const T t14 = T(21) * t8 * r0 + t5 * t13 * b - T(21) * r1 * t6;
    const T t15 = T(6) * t0 * t14 * b + T(5) * t12 * t5 - T(3) * c * t5 * t13;
    F = -(T(1) / T(105)) * in.w[0] * t5 * t13 - (T(1) / T(105)) * in.w[1] * t0 * t14 - (T(1) / T(315)) * in.w[3] * t0 * (T(2) * t15 * t0 * b + T(5) * t0 * (T(9) * t11 * r0 + t12 * t5 * b - T(9) * r1 * t10) - T(3) * c * t0 * t14) - (T(1) / T(315)) * t15 * t0 * in.w[2];
    const T t16 = T(105) * slope0 * q0 * r0 - T(105) * r1 * slope1 * q1 - T(4) * a * t5 * t13;
    const T t17 = t5 * t16 * b + T(105) * r1 * q1 - T(105) * q0 * r0;
    const T t18 = T(2) * t0 * t17 * b - T(3) * t5 * t13 - c * t5 * t16;
    const T t19 = c * t0 * t17 + T(3) * t0 * t14 - T(2) * t18 * t0 * b;
    G_ap = (T(1) / T(315)) * in.w[0] * t5 * t16 + (T(1) / T(315)) * in.w[1] * t0 * t17 + (T(1) / T(315)) * t18 * t0 * in.w[2] - (T(1) / T(315)) * in.w[3] * t19 * t0;
    G_ab = (T(1) / T(315)) * in.w[0] * t0 * t17 + (T(1) / T(315)) * t18 * in.w[1] * t0 - (T(1) / T(315)) * in.w[3] * (t18 * c * t0 + T(2) * t19 * t0 * b + t15 * t0) * t0 - (T(1) / T(315)) * t19 * t0 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = slope0 * r0 - r1 * slope1 - D * J1;
    const T t21 = T(2) * slope0 * q0 * r0 + T(3) * t20 * t0 * D - T(2) * r1 * slope1 * q1;
    const T t22 = q0 * q0;
    const T t23 = q1 * q1;
    const T t24 = T(5) * t21 * t0 * b + T(8) * t22 * r0 - T(8) * r1 * t23;
    const T t25 = T(5) * t21 * t0 * D + T(8) * slope0 * t22 * r0 - T(8) * r1 * slope1 * t23;
    const T t26 = T(12) * t0 * t24 * b + T(5) * t0 * t25 - T(30) * c * t21 * t0;
    const T t27 = t22 * q0;
    const T t28 = t23 * q1;
    F = -(T(1) / T(8)) * in.w[0] * t21 * t0 - (T(1) / T(240)) * t26 * t0 * in.w[2] - (T(1) / T(40)) * in.w[1] * t0 * t24 - (T(1) / T(1680)) * in.w[3] * (T(5) * (T(48) * t27 * r0 + T(7) * t0 * t25 * b - T(48) * r1 * t28) * t0 + T(14) * t26 * t0 * b - T(42) * c * t0 * t24) * t0;
    const T t29 = T(3) * t20 * t0 * b + T(2) * q0 * r0 - T(2) * r1 * q1;
    const T t30 = T(12) * t20 * c * t0 - T(8) * t0 * t29 * b - T(3) * t21 * t0;
    const T t31 = T(10) * t0 * t30 * b + T(20) * c * t0 * t29 - T(3) * t0 * t24;
    G_ap = (T(1) / T(24)) * t0 * t30 * in.w[2] + (T(1) / T(120)) * in.w[3] * t0 * t31 - (T(1) / T(6)) * in.w[1] * t0 * t29 - (T(1) / T(2)) * in.w[0] * t20 * t0;
    G_ab = (T(1) / T(24)) * in.w[1] * t0 * t30 + (T(1) / T(120)) * t0 * in.w[2] * t31 - (T(1) / T(240)) * in.w[3] * (T(10) * c * t0 * t30 + t26 * t0 - T(4) * t0 * t31 * b) * t0 - (T(1) / T(6)) * in.w[0] * t0 * t29;
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(3/2) dt
/// Returns false where segment_compact_i3_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 66 +, 174 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i3_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-3, -1, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
    G_ap = in.w[3] * M_flat[8] + M_flat[7] * in.w[2] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6];
    G_ab = in.w[0] * M_flat[6] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = D * J1 + r1 * slope1 - slope0 * r0;
    const T t8 = T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1 - T(3) * t7 * D * t2;
    const T t9 = q1 * q1;
    const T t10 = q0 * q0;
    const T t11 = T(8) * r1 * slope1 * t9 - T(5) * t8 * D * t2 - T(8) * slope0 * t10 * r0;
    const T t12 = T(8) * t10 * r0 + T(5) * b * t8 * t2 - T(8) * r1 * t9;
    const T t13 = T(30) * c * t8 * t2 + T(5) * t2 * t11 - T(12) * b * t12 * t2;
    const T t14 = t10 * q0;
    const T t15 = t9 * q1;
    F = (T(1) / T(240)) * t2 * t13 * in.w[2] + (T(1) / T(1680)) * in.w[3] * (T(42) * t12 * c * t2 + T(14) * b * t2 * t13 - T(5) * (T(48) * t14 * r0 - T(48) * r1 * t15 - T(7) * b * t2 * t11) * t2) * t2 - (T(1) / T(8)) * in.w[0] * t8 * t2 - (T(1) / T(40)) * t12 * in.w[1] * t2;
    const T t16 = T(2) * r1 * q1 + T(3) * b * t7 * t2 - T(2) * q0 * r0;
    const T t17 = T(8) * b * t16 * t2 - T(12) * t7 * c * t2 - T(3) * t8 * t2;
    const T t18 = T(3) * t12 * t2 + T(20) * t16 * c * t2 - T(10) * b * t17 * t2;
    G_ap = (T(1) / T(24)) * t17 * t2 * in.w[2] + (T(1) / T(6)) * t16 * in.w[1] * t2 + (T(1) / T(2)) * in.w[0] * t7 * t2 - (T(1) / T(120)) * in.w[3] * t18 * t2;
    G_ab = (T(1) / T(24)) * in.w[1] * t17 * t2 + (T(1) / T(240)) * in.w[3] * (t2 * t13 - T(10) * c * t17 * t2 - T(4) * b * t18 * t2) * t2 + (T(1) / T(6)) * t16 * in.w[0] * t2 - (T(1) / T(120)) * t18 * t2 * in.w[2];
  }
  const T g_factor = -T(3) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 43 +, 78 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 53 +, 89 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i4_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 67 +, 112 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Returns false where segment_compact_i4_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 112 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i4_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 51 +, 86 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 5, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 62 +, 98 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i4_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
    G_ab = M_exact[1] * in.w[0] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 84 +, 129 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ap = M_exact[4] * in.w[1] + M_exact[3] * in.w[0];
    G_ab = in.w[1] * M_exact[5] + in.w[0] * M_exact[4];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Returns false where segment_compact_i4_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 84 +, 129 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i4_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
    G_ap = in.w[1] * M_exact[4] + M_exact[3] * in.w[0];
    G_ab = M_exact[4] * in.w[0] + M_exact[5] * in.w[1];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 59 +, 94 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + M_exact[1] * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 71 +, 107 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i4_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[2] * M_exact[2] + M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ab = in.w[0] * M_exact[1] + in.w[2] * M_exact[3] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(4) * length * inv_R2;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 101 +, 146 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
    G_ap = M_exact[4] * in.w[0] + M_exact[5] * in.w[1] + in.w[2] * M_exact[6];
    G_ab = in.w[2] * M_exact[7] + in.w[1] * M_exact[6] + in.w[0] * M_exact[5];
  }
  const T g_factor = -T(4) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Returns false where segment_compact_i4_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 101 +, 146 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i4_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + in.w[1] * M_exact[1];
    G_ap = in.w[0] * M_exact[4] + M_exact[5] * in.w[1] + in.w[2] * M_exact[6];
    G_ab = in.w[2] * M_exact[7] + M_exact[5] * in.w[0] + M_exact[6] * in.w[1];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 67 +, 102 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[2] * in.w[2] + M_exact[3] * in.w[3] + M_exact[1] * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 80 +, 116 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i4_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-2, -2, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + M_exact[3] * in.w[3] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0];
    G_ab = in.w[2] * M_exact[3] + in.w[3] * M_exact[4] + in.w[0] * M_exact[1] + M_exact[2] * in.w[1];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Operations: 118 +, 163 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i4_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[2] * in.w[2] + in.w[0] * M_exact[0] + in.w[3] * M_exact[3];
    G_ap = M_exact[6] * in.w[1] + M_exact[5] * in.w[0] + M_exact[7] * in.w[2] + M_exact[8] * in.w[3];
    G_ab = in.w[3] * M_exact[9] + in.w[1] * M_exact[7] + M_exact[8] * in.w[2] + in.w[0] * M_exact[6];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(4/2) dt
/// Returns false where segment_compact_i4_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 118 +, 163 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i4_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-4, -2, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[3] * in.w[3] + in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0];
    G_ap = M_exact[7] * in.w[2] + M_exact[5] * in.w[0] + M_exact[8] * in.w[3] + in.w[1] * M_exact[6];
    G_ab = in.w[1] * M_exact[7] + in.w[3] * M_exact[9] + in.w[2] * M_exact[8] + in.w[0] * M_exact[6];
  }
  const T g_factor = -T(4) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 38 +, 68 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2076 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
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
  T F;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    F = -(T(1) / T(7)) * in.w[0] * (t8 * r1 * slope1 - T(8) * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) * a - t10 * r0 * slope0) / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    F = -(T(1) / T(48)) * (T(8) * q0 * q0 * r0 * slope0 - T(5) * (T(2) * q1 * r1 * slope1 + T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t2 - T(2) * q0 * r0 * slope0) * D * t2 - T(8) * q1 * q1 * r1 * slope1) * in.w[0] * t2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 41 +, 79 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2105 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -a * a * t2 * t2 - D;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = T(1) / D;
    const T t8 = t6 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = T(7) * r1 * slope1 * t6 + T(6) * a * t7 * (r1 * slope1 * t8 - r0 * slope0 * t10 - T(8) * a * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1)) - T(7) * r0 * slope0 * t9;
    G_ap = -(T(1) / T(35)) * t11 * t7 * in.w[0];
    G_ab = -(T(1) / T(35)) * t1 * in.w[0] * (T(7) * r0 * t9 + t11 * t7 * b - T(7) * r1 * t6);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t12 = T(2) * r1 * slope1 * q1 + T(3) * t1 * D * (D * J1 + r1 * slope1 - r0 * slope0) - T(2) * r0 * slope0 * q0;
    G_ap = (T(1) / T(8)) * t1 * t12 * in.w[0];
    const T t13 = q0 * q0;
    const T t14 = q1 * q1;
    G_ab = -(T(1) / T(40)) * t1 * (T(8) * r0 * t13 - T(8) * r1 * t14 - T(5) * t1 * t12 * b) * in.w[0];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 43 +, 92 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2109 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-7 = J_upward_compact(…)
    const T t7 = T(1) / D;
    const T t8 = q0 * q0;
    const T t9 = t8 * q0;
    const T t10 = q1 * q1;
    const T t11 = t10 * q1;
    const T t12 = T(8) * a * J_upward_compact<T>(-7, a, D, slope0, q0, slope1, q1) + t9 * r0 * slope0 - t11 * r1 * slope1;
    F = (T(1) / T(7)) * t7 * t12 * in.w[0];
    const T t13 = T(7) * t10 * r1 * slope1 - T(7) * t8 * r0 * slope0 - T(6) * t7 * a * t12;
    G_ap = -(T(1) / T(35)) * t7 * t13 * in.w[0];
    G_ab = -(T(1) / T(35)) * (T(7) * t8 * r0 + t7 * t13 * b - T(7) * t10 * r1) * t2 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = q1 * q1;
    const T t15 = q0 * q0;
    const T t16 = T(2) * q0 * r0 * slope0 + T(3) * D * t2 * (r0 * slope0 - D * J1 - r1 * slope1) - T(2) * q1 * r1 * slope1;
    F = (T(1) / T(48)) * (T(8) * t14 * r1 * slope1 - T(8) * t15 * r0 * slope0 - T(5) * D * t2 * t16) * t2 * in.w[0];
    G_ap = -(T(1) / T(8)) * t2 * t16 * in.w[0];
    G_ab = -(T(1) / T(40)) * t2 * (T(8) * t15 * r0 + T(5) * t2 * t16 * b - T(8) * t14 * r1) * in.w[0];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Returns false where segment_compact_i5_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 43 +, 92 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i5_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -a * a * t2 * t2 - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q0 * q0;
    const T t7 = q1 * q1;
    const T t8 = T(3) * D * t1 * (slope1 * r1 + D * J1 - r0 * slope0) + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0;
    F = -(T(1) / T(48)) * t1 * in.w[0] * (T(8) * t6 * r0 * slope0 - T(8) * slope1 * t7 * r1 - T(5) * D * t1 * t8);
    G_ap = (T(1) / T(8)) * t1 * t8 * in.w[0];
    G_ab = -(T(1) / T(40)) * t1 * (T(8) * t6 * r0 - T(8) * t7 * r1 - T(5) * t1 * t8 * b) * in.w[0];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 41 +, 81 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2099 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = T(1) / D;
    const T t9 = t6 * t6;
    const T t10 = q0 * q0;
    const T t11 = t10 * t10;
    const T t12 = t10 * q0;
    const T t13 = T(8) * t8 * (slope1 * t9 * r1 - t11 * r0 * slope0 - T(10) * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) * a) * a + T(9) * slope1 * t7 * r1 - T(9) * t12 * r0 * slope0;
    F = (T(1) / T(63)) * in.w[1] * (T(9) * t7 * r1 - t13 * b * t8 - T(9) * t12 * r0) * t1 - (T(1) / T(63)) * in.w[0] * t13 * t8;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = q1 * q1;
    const T t15 = t14 * q1;
    const T t16 = T(8) * q0 * q0 * r0 * slope0 - T(5) * (T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t1 + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0) * D * t1 - T(8) * slope1 * t14 * r1;
    const T t17 = q0 * q0;
    const T t18 = t17 * q0;
    F = (T(1) / T(336)) * (T(48) * t15 * r1 - T(7) * b * t16 * t1 - T(48) * t18 * r0) * in.w[1] * t1 - (T(1) / T(48)) * in.w[0] * t16 * t1;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 47 +, 102 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2132 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + in.w[1] * M_flat[2];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = q0 * q0;
    const T t7 = T(1) / D;
    const T t8 = q1 * q1;
    const T t9 = t8 * t8;
    const T t10 = t6 * t6;
    const T t11 = t8 * q1;
    const T t12 = t6 * q0;
    const T t13 = T(8) * (r1 * slope1 * t9 - slope0 * t10 * r0 - T(10) * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) * a) * t7 * a + T(9) * r1 * slope1 * t11 - T(9) * slope0 * t12 * r0;
    const T t14 = T(21) * slope0 * t6 * r0 - T(2) * t7 * t13 * a - T(21) * r1 * slope1 * t8;
    const T t15 = T(21) * t6 * r0 - t14 * b * t7 - T(21) * r1 * t8;
    G_ap = (T(1) / T(105)) * in.w[0] * t14 * t7 - (T(1) / T(105)) * t15 * in.w[1] * t1;
    G_ab = -(T(1) / T(315)) * in.w[1] * (T(3) * t14 * c * t7 + T(6) * b * t15 * t1 + T(5) * t7 * t13) * t1 - (T(1) / T(105)) * in.w[0] * t15 * t1;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t16 = T(3) * (J1 * D + r1 * slope1 - slope0 * r0) * D * t1 + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0;
    const T t17 = q1 * q1;
    const T t18 = q0 * q0;
    const T t19 = T(5) * b * t16 * t1 + T(8) * r1 * t17 - T(8) * t18 * r0;
    G_ap = (T(1) / T(40)) * in.w[1] * t19 * t1 + (T(1) / T(8)) * in.w[0] * t16 * t1;
    G_ab = (T(1) / T(40)) * in.w[0] * t19 * t1 - (T(1) / T(240)) * in.w[1] * (T(30) * c * t16 * t1 + T(5) * (T(8) * slope0 * t18 * r0 - T(8) * r1 * slope1 * t17 - T(5) * t16 * D * t1) * t1 - T(12) * b * t19 * t1) * t1;
  }
  const T g_factor = -T(5) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 50 +, 118 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2145 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -a * a * t3 * t3 - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ap = in.w[1] * M_flat[4] + M_flat[3] * in.w[0];
    G_ab = M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t7 * t7;
    const T t12 = T(1) / D;
    const T t13 = t9 * q0;
    const T t14 = T(9) * t8 * r1 * slope1 - T(8) * a * (T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t10 - t11 * r1 * slope1) * t12 - T(9) * r0 * slope0 * t13;
    F = -(T(1) / T(63)) * t2 * in.w[1] * (b * t14 * t12 + T(9) * r0 * t13 - T(9) * t8 * r1) - (T(1) / T(63)) * t14 * t12 * in.w[0];
    const T t15 = T(21) * r0 * slope0 * t9 - T(2) * a * t14 * t12 - T(21) * t7 * r1 * slope1;
    const T t16 = T(21) * r0 * t9 - T(21) * t7 * r1 - b * t15 * t12;
    G_ap = (T(1) / T(105)) * t15 * t12 * in.w[0] - (T(1) / T(105)) * t2 * in.w[1] * t16;
    G_ab = -(T(1) / T(315)) * t2 * in.w[1] * (T(6) * t2 * b * t16 + T(5) * t14 * t12 + T(3) * t15 * c * t12) - (T(1) / T(105)) * t2 * t16 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = T(3) * t2 * D * (r0 * slope0 - r1 * slope1 - J1 * D) + T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1;
    const T t18 = q0 * q0;
    const T t19 = q1 * q1;
    const T t20 = T(5) * t2 * t17 * D + T(8) * r0 * slope0 * t18 - T(8) * t19 * r1 * slope1;
    const T t21 = t18 * q0;
    const T t22 = t19 * q1;
    F = -(T(1) / T(48)) * t2 * t20 * in.w[0] - (T(1) / T(336)) * t2 * in.w[1] * (T(7) * t2 * b * t20 + T(48) * r0 * t21 - T(48) * t22 * r1);
    const T t23 = T(8) * r0 * t18 + T(5) * t2 * b * t17 - T(8) * t19 * r1;
    G_ap = -(T(1) / T(8)) * t2 * t17 * in.w[0] - (T(1) / T(40)) * t2 * in.w[1] * t23;
    G_ab = (T(1) / T(240)) * t2 * in.w[1] * (T(30) * t2 * t17 * c - T(12) * t2 * b * t23 - T(5) * t2 * t20) - (T(1) / T(40)) * t2 * t23 * in.w[0];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Returns false where segment_compact_i5_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 50 +, 118 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i5_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = T(2) * q0 * r0 * slope0 - T(3) * D * t2 * (D * J1 + r1 * slope1 - r0 * slope0) - T(2) * q1 * r1 * slope1;
    const T t8 = q0 * q0;
    const T t9 = q1 * q1;
    const T t10 = T(5) * D * t2 * t7 + T(8) * t8 * r0 * slope0 - T(8) * t9 * r1 * slope1;
    const T t11 = t8 * q0;
    const T t12 = t9 * q1;
    F = -(T(1) / T(48)) * t2 * in.w[0] * t10 - (T(1) / T(336)) * t2 * in.w[1] * (T(48) * t11 * r0 + T(7) * t2 * b * t10 - T(48) * t12 * r1);
    const T t13 = T(8) * t8 * r0 + T(5) * t2 * b * t7 - T(8) * t9 * r1;
    G_ap = -(T(1) / T(40)) * t2 * t13 * in.w[1] - (T(1) / T(8)) * t2 * in.w[0] * t7;
    G_ab = -(T(1) / T(240)) * t2 * (T(5) * t2 * t10 + T(12) * t2 * b * t13 - T(30) * t2 * c * t7) * in.w[1] - (T(1) / T(40)) * t2 * in.w[0] * t13;
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 46 +, 100 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2109 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
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
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = T(1) / D;
    const T t12 = t9 * t9;
    const T t13 = t7 * t7;
    const T t14 = T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t12 - t13 * r1 * slope1;
    const T t15 = T(9) * t8 * r1 * slope1 - T(9) * r0 * slope0 * t10 - T(8) * a * t11 * t14;
    const T t16 = T(9) * t8 * r1 - T(9) * r0 * t10 - b * t15 * t11;
    F = (T(1) / T(63)) * t16 * t2 * in.w[1] + (T(1) / T(63)) * in.w[2] * t2 * (c * t15 * t11 + T(7) * t11 * t14 + T(2) * b * t16 * t2) - (T(1) / T(63)) * in.w[0] * t15 * t11;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = q1 * q1;
    const T t18 = t17 * q1;
    const T t19 = q0 * q0;
    const T t20 = t19 * q0;
    const T t21 = T(8) * r0 * slope0 * t19 + T(5) * (T(2) * r0 * slope0 * q0 - T(3) * t2 * D * (J1 * D + r1 * slope1 - r0 * slope0) - T(2) * q1 * r1 * slope1) * t2 * D - T(8) * t17 * r1 * slope1;
    const T t22 = T(48) * t18 * r1 - T(48) * r0 * t20 - T(7) * b * t2 * t21;
    F = (T(1) / T(336)) * t22 * t2 * in.w[1] + (T(1) / T(2688)) * in.w[2] * (T(56) * c * t2 * t21 + T(16) * b * t22 * t2 + T(7) * t2 * (T(48) * t18 * r1 * slope1 - T(7) * t2 * D * t21 - T(48) * r0 * slope0 * t20)) * t2 - (T(1) / T(48)) * in.w[0] * t2 * t21;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 53 +, 125 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2152 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ab = M_flat[3] * in.w[2] + M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t7 * t7;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t10 * q1;
    const T t13 = T(9) * r0 * slope0 * t8 + T(8) * (r0 * slope0 * t9 + T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) - t11 * r1 * slope1) * t6 * a - T(9) * t12 * r1 * slope1;
    const T t14 = T(21) * r0 * slope0 * t7 + T(2) * t6 * a * t13 - T(21) * t10 * r1 * slope1;
    const T t15 = t6 * t14 * b + T(21) * t10 * r1 - T(21) * r0 * t7;
    const T t16 = T(5) * t6 * t13 + T(6) * t1 * t15 * b - T(3) * t6 * t14 * c;
    G_ap = (T(1) / T(105)) * in.w[0] * t6 * t14 + (T(1) / T(105)) * t1 * in.w[1] * t15 + (T(1) / T(315)) * t16 * t1 * in.w[2];
    G_ab = (T(1) / T(315)) * (T(2) * t16 * t1 * b + T(5) * t1 * (t6 * b * t13 + T(9) * t12 * r1 - T(9) * r0 * t8) - T(3) * t1 * t15 * c) * t1 * in.w[2] + (T(1) / T(105)) * in.w[0] * t1 * t15 + (T(1) / T(315)) * t16 * t1 * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = T(2) * q1 * r1 * slope1 + T(3) * D * t1 * (r1 * slope1 + J1 * D - r0 * slope0) - T(2) * r0 * slope0 * q0;
    const T t18 = q1 * q1;
    const T t19 = q0 * q0;
    const T t20 = T(5) * t17 * t1 * b + T(8) * t18 * r1 - T(8) * r0 * t19;
    const T t21 = T(8) * r0 * slope0 * t19 - T(5) * t17 * D * t1 - T(8) * t18 * r1 * slope1;
    const T t22 = T(5) * t21 * t1 + T(30) * t17 * t1 * c - T(12) * t20 * t1 * b;
    G_ap = (T(1) / T(8)) * in.w[0] * t17 * t1 + (T(1) / T(40)) * t20 * t1 * in.w[1] - (T(1) / T(240)) * t1 * t22 * in.w[2];
    const T t23 = t19 * q0;
    const T t24 = t18 * q1;
    G_ab = (T(1) / T(40)) * t20 * in.w[0] * t1 - (T(1) / T(240)) * t1 * in.w[1] * t22 - (T(1) / T(1680)) * (T(14) * t1 * t22 * b + T(42) * t20 * t1 * c + T(5) * t1 * (T(48) * r0 * t23 + T(7) * t21 * t1 * b - T(48) * t24 * r1)) * t1 * in.w[2];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 59 +, 152 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2169 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ap = in.w[2] * M_flat[6] + M_flat[4] * in.w[0] + in.w[1] * M_flat[5];
    G_ab = in.w[1] * M_flat[6] + M_flat[7] * in.w[2] + M_flat[5] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = T(1) / D;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t6 * t6;
    const T t12 = t10 * r0 * slope0 + T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) - slope1 * t11 * r1;
    const T t13 = t9 * q0;
    const T t14 = T(8) * a * t8 * t12 + T(9) * t13 * r0 * slope0 - T(9) * slope1 * t7 * r1;
    const T t15 = T(9) * t7 * r1 + t8 * b * t14 - T(9) * t13 * r0;
    F = (T(1) / T(63)) * (T(2) * t1 * b * t15 + T(7) * t8 * t12 - c * t8 * t14) * in.w[2] * t1 + (T(1) / T(63)) * t8 * in.w[0] * t14 + (T(1) / T(63)) * in.w[1] * t1 * t15;
    const T t16 = T(21) * t9 * r0 * slope0 + T(2) * a * t8 * t14 - T(21) * slope1 * t6 * r1;
    const T t17 = T(21) * t6 * r1 + t16 * t8 * b - T(21) * t9 * r0;
    const T t18 = T(3) * c * t16 * t8 - T(6) * t1 * t17 * b - T(5) * t8 * t14;
    G_ap = (T(1) / T(105)) * in.w[1] * t1 * t17 + (T(1) / T(105)) * t16 * t8 * in.w[0] - (T(1) / T(315)) * in.w[2] * t1 * t18;
    G_ab = (T(1) / T(105)) * t1 * t17 * in.w[0] - (T(1) / T(315)) * in.w[2] * t1 * (T(3) * c * t1 * t17 + T(2) * t1 * t18 * b - T(5) * t1 * t15) - (T(1) / T(315)) * in.w[1] * t1 * t18;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t19 = q1 * q1;
    const T t20 = t19 * q1;
    const T t21 = q0 * q0;
    const T t22 = T(3) * t1 * (D * J1 + slope1 * r1 - r0 * slope0) * D + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0;
    const T t23 = T(8) * t21 * r0 * slope0 - T(5) * t1 * D * t22 - T(8) * slope1 * t19 * r1;
    const T t24 = t21 * q0;
    const T t25 = T(48) * t20 * r1 - T(7) * t23 * t1 * b - T(48) * t24 * r0;
    F = (T(1) / T(336)) * in.w[1] * t1 * t25 + (T(1) / T(2688)) * in.w[2] * t1 * (T(56) * c * t23 * t1 + T(7) * (T(48) * slope1 * t20 * r1 - T(7) * t23 * t1 * D - T(48) * t24 * r0 * slope0) * t1 + T(16) * t1 * t25 * b) - (T(1) / T(48)) * t23 * t1 * in.w[0];
    const T t26 = T(5) * t1 * t22 * b + T(8) * t19 * r1 - T(8) * t21 * r0;
    const T t27 = T(5) * t23 * t1 + T(30) * c * t1 * t22 - T(12) * t1 * t26 * b;
    G_ap = (T(1) / T(8)) * t1 * t22 * in.w[0] + (T(1) / T(40)) * in.w[1] * t1 * t26 - (T(1) / T(240)) * t27 * in.w[2] * t1;
    G_ab = (T(1) / T(40)) * t1 * t26 * in.w[0] + (T(1) / T(1680)) * (T(5) * t1 * t25 - T(42) * c * t1 * t26 - T(14) * t27 * t1 * b) * in.w[2] * t1 - (T(1) / T(240)) * in.w[1] * t27 * t1;
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - G_ap * ap0);
  grad[1] = -(G_ab * ab1 - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Returns false where segment_compact_i5_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 59 +, 152 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i5_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - t1 * t1 * a * a;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + M_flat[2] * in.w[2];
    G_ap = M_flat[4] * in.w[0] + M_flat[5] * in.w[1] + M_flat[6] * in.w[2];
    G_ab = in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q1 * q1;
    const T t6 = t5 * q1;
    const T t7 = q0 * q0;
    const T t8 = T(3) * (slope0 * r0 - D * J1 - r1 * slope1) * D * t0 + T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1;
    const T t9 = T(8) * slope0 * t7 * r0 + T(5) * D * t0 * t8 - T(8) * r1 * slope1 * t5;
    const T t10 = t7 * q0;
    const T t11 = T(48) * r1 * t6 - T(7) * t0 * b * t9 - T(48) * t10 * r0;
    F = (T(1) / T(2688)) * (T(16) * t11 * t0 * b + T(56) * c * t0 * t9 - T(7) * (T(48) * slope0 * t10 * r0 + T(7) * D * t0 * t9 - T(48) * r1 * slope1 * t6) * t0) * t0 * in.w[2] + (T(1) / T(336)) * t11 * t0 * in.w[1] - (T(1) / T(48)) * in.w[0] * t0 * t9;
    const T t12 = T(8) * r1 * t5 - T(5) * t0 * b * t8 - T(8) * t7 * r0;
    const T t13 = T(5) * t0 * t9 - T(12) * t0 * t12 * b - T(30) * c * t0 * t8;
    G_ap = (T(1) / T(40)) * t0 * t12 * in.w[1] - (T(1) / T(240)) * t0 * in.w[2] * t13 - (T(1) / T(8)) * in.w[0] * t0 * t8;
    G_ab = (T(1) / T(40)) * in.w[0] * t0 * t12 - (T(1) / T(240)) * t0 * in.w[1] * t13 - (T(1) / T(1680)) * t0 * in.w[2] * (T(42) * c * t0 * t12 + T(14) * t0 * b * t13 - T(5) * t11 * t0);
  }
  const T g_factor = -T(5) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 51 +, 121 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2139 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = T(10) * t5 * a * (slope0 * t8 * r0 + T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) - slope1 * t11 * r1) + T(11) * slope0 * t7 * r0 - T(11) * slope1 * t10 * r1;
    const T t13 = t6 * q0;
    const T t14 = t9 * q1;
    const T t15 = T(8) * t5 * a * t12 + T(99) * slope0 * t13 * r0 - T(99) * slope1 * t14 * r1;
    const T t16 = T(99) * t14 * r1 + t5 * t15 * b - T(99) * t13 * r0;
    const T t17 = T(2) * t0 * b * t16 + T(7) * t5 * t12 - t5 * t15 * c;
    F = (T(1) / T(693)) * t5 * t15 * in.w[0] + (T(1) / T(693)) * t0 * t17 * in.w[2] + (T(1) / T(693)) * t0 * t16 * in.w[1] - (T(1) / T(693)) * t0 * in.w[3] * (t0 * c * t16 + T(7) * t0 * (T(11) * t7 * r0 - t5 * b * t12 - T(11) * t10 * r1) - T(2) * t0 * t17 * b);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t18 = q1 * q1;
    const T t19 = t18 * q1;
    const T t20 = T(8) * slope1 * t18 * r1 - T(5) * D * t0 * (T(2) * slope0 * q0 * r0 - T(2) * slope1 * q1 * r1 - T(3) * (D * J1 + slope1 * r1 - slope0 * r0) * D * t0) - T(8) * slope0 * q0 * q0 * r0;
    const T t21 = q0 * q0;
    const T t22 = t21 * q0;
    const T t23 = T(48) * t19 * r1 + T(7) * t0 * t20 * b - T(48) * t22 * r0;
    const T t24 = T(48) * slope1 * t19 * r1 + T(7) * D * t0 * t20 - T(48) * slope0 * t22 * r0;
    const T t25 = T(56) * t0 * t20 * c - T(16) * t0 * t23 * b - T(7) * t0 * t24;
    const T t26 = t18 * t18;
    const T t27 = t21 * t21;
    F = (T(1) / T(336)) * t0 * t23 * in.w[1] + (T(1) / T(48)) * t0 * t20 * in.w[0] - (T(1) / T(8064)) * t0 * in.w[3] * (T(6) * t0 * b * t25 + T(24) * t0 * t23 * c - T(7) * (T(3) * t0 * b * t24 + T(128) * t26 * r1 - T(128) * t27 * r0) * t0) - (T(1) / T(2688)) * t0 * in.w[2] * t25;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 61 +, 156 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2186 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i5_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-3, -3, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[4] * in.w[3] + M_flat[3] * in.w[2] + M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t9 * t9;
    const T t12 = t11 * q1;
    const T t13 = t7 * t7;
    const T t14 = t13 * q0;
    const T t15 = T(10) * t6 * a * (t12 * r1 * slope1 - T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) - r0 * slope0 * t14) + T(11) * t11 * r1 * slope1 - T(11) * r0 * slope0 * t13;
    const T t16 = T(99) * r0 * slope0 * t8 - T(99) * t10 * r1 * slope1 - T(8) * t15 * t6 * a;
    const T t17 = T(231) * r0 * slope0 * t7 + T(2) * t6 * a * t16 - T(231) * t9 * r1 * slope1;
    const T t18 = t6 * b * t17 + T(231) * t9 * r1 - T(231) * r0 * t7;
    const T t19 = T(6) * t18 * t1 * b + T(5) * t6 * t16 - T(3) * t6 * c * t17;
    const T t20 = T(99) * r0 * t8 - t6 * t16 * b - T(99) * t10 * r1;
    const T t21 = T(2) * t1 * t19 * b - T(5) * t1 * t20 - T(3) * t18 * t1 * c;
    G_ap = (T(1) / T(3465)) * t1 * in.w[3] * t21 + (T(1) / T(1155)) * in.w[1] * t18 * t1 + (T(1) / T(1155)) * t6 * in.w[0] * t17 + (T(1) / T(3465)) * t1 * t19 * in.w[2];
    G_ab = (T(1) / T(3465)) * in.w[1] * t1 * t19 + (T(1) / T(3465)) * t1 * in.w[2] * t21 + (T(1) / T(1155)) * t18 * t1 * in.w[0] - (T(1) / T(3465)) * t1 * (T(5) * t1 * (t6 * t16 * c + T(2) * t1 * t20 * b + T(7) * t15 * t6) + t1 * t19 * c - T(2) * t1 * b * t21) * in.w[3];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = T(2) * q1 * r1 * slope1 + T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t1 - T(2) * r0 * slope0 * q0;
    const T t23 = q0 * q0;
    const T t24 = q1 * q1;
    const T t25 = T(8) * r0 * slope0 * t23 - T(8) * t24 * r1 * slope1 - T(5) * D * t22 * t1;
    const T t26 = T(8) * r0 * t23 - T(8) * t24 * r1 - T(5) * t22 * t1 * b;
    const T t27 = T(30) * t22 * t1 * c + T(5) * t1 * t25 + T(12) * t1 * t26 * b;
    const T t28 = t23 * q0;
    const T t29 = t24 * q1;
    const T t30 = T(48) * r0 * t28 + T(7) * t1 * b * t25 - T(48) * t29 * r1;
    const T t31 = T(5) * t1 * t30 + T(14) * t1 * b * t27 - T(42) * t1 * t26 * c;
    G_ap = (T(1) / T(8)) * t22 * t1 * in.w[0] - (T(1) / T(240)) * t1 * in.w[2] * t27 - (T(1) / T(40)) * in.w[1] * t1 * t26 - (T(1) / T(1680)) * t31 * t1 * in.w[3];
    G_ab = -(T(1) / T(40)) * t1 * t26 * in.w[0] - (T(1) / T(240)) * in.w[1] * t1 * t27 - (T(1) / T(13440)) * t1 * (T(16) * t31 * t1 * b + T(5) * (T(7) * (T(48) * r0 * slope0 * t28 + T(7) * D * t1 * t25 - T(48) * t29 * r1 * slope1) * t1 + T(16) * t1 * t30 * b - T(56) * t1 * t25 * c) * t1 - T(56) * t1 * c * t27) * in.w[3] - (T(1) / T(1680)) * t31 * t1 * in.w[2];
  }
  const T g_factor = -T(5) * length * inv_R2;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Operations: 68 +, 186 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2212 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i5_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2];
    G_ap = in.w[3] * M_flat[8] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
    G_ab = M_flat[7] * in.w[1] + M_flat[8] * in.w[2] + in.w[0] * M_flat[6] + in.w[3] * M_flat[9];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = T(1) / D;
    const T t8 = q1 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = t5 * t5;
    const T t12 = t11 * q0;
    const T t13 = T(11) * r1 * slope1 * t9 + T(10) * a * t7 * (r1 * slope1 * t10 - slope0 * t12 * r0 - T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a) - T(11) * slope0 * t11 * r0;
    const T t14 = t8 * q1;
    const T t15 = T(99) * slope0 * t6 * r0 - T(8) * a * t7 * t13 - T(99) * r1 * slope1 * t14;
    const T t16 = T(99) * r1 * t14 + t15 * t7 * b - T(99) * t6 * r0;
    const T t17 = T(2) * t0 * t16 * b - T(7) * t7 * t13 - t15 * c * t7;
    F = (T(1) / T(693)) * in.w[0] * t15 * t7 + (T(1) / T(693)) * in.w[1] * t0 * t16 + (T(1) / T(693)) * t0 * in.w[2] * t17 - (T(1) / T(693)) * in.w[3] * (T(7) * (t7 * t13 * b + T(11) * t11 * r0 - T(11) * r1 * t9) * t0 + c * t0 * t16 - T(2) * t0 * b * t17) * t0;
    const T t18 = T(2) * t15 * a * t7 + T(231) * slope0 * t5 * r0 - T(231) * r1 * slope1 * t8;
    const T t19 = T(231) * r1 * t8 + t18 * t7 * b - T(231) * t5 * r0;
    const T t20 = T(3) * c * t18 * t7 - T(6) * t0 * t19 * b - T(5) * t15 * t7;
    const T t21 = T(2) * t20 * t0 * b + T(3) * c * t0 * t19 - T(5) * t0 * t16;
    G_ap = (T(1) / T(1155)) * in.w[0] * t18 * t7 + (T(1) / T(1155)) * in.w[1] * t0 * t19 - (T(1) / T(3465)) * t20 * t0 * in.w[2] - (T(1) / T(3465)) * in.w[3] * t0 * t21;
    G_ab = (T(1) / T(1155)) * in.w[0] * t0 * t19 + (T(1) / T(3465)) * (T(5) * t0 * t17 + t20 * c * t0 - T(2) * t0 * t21 * b) * in.w[3] * t0 - (T(1) / T(3465)) * t0 * t21 * in.w[2] - (T(1) / T(3465)) * t20 * in.w[1] * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * q1;
    const T t24 = T(2) * slope0 * q0 * r0 + T(3) * t0 * D * (slope0 * r0 - D * J1 - r1 * slope1) - T(2) * r1 * slope1 * q1;
    const T t25 = q0 * q0;
    const T t26 = T(5) * t0 * D * t24 + T(8) * slope0 * t25 * r0 - T(8) * r1 * slope1 * t22;
    const T t27 = t25 * q0;
    const T t28 = T(48) * r1 * t23 - T(7) * t26 * t0 * b - T(48) * t27 * r0;
    const T t29 = T(7) * t26 * t0 * D + T(48) * slope0 * t27 * r0 - T(48) * r1 * slope1 * t23;
    const T t30 = t25 * t25;
    const T t31 = t22 * t22;
    const T t32 = T(7) * t0 * t29 - T(56) * c * t26 * t0 - T(16) * t28 * t0 * b;
    F = (T(1) / T(336)) * t28 * in.w[1] * t0 - (T(1) / T(8064)) * in.w[3] * (T(24) * c * t28 * t0 + T(7) * t0 * (T(3) * t0 * t29 * b + T(128) * t30 * r0 - T(128) * r1 * t31) + T(6) * t32 * t0 * b) * t0 - (T(1) / T(48)) * in.w[0] * t26 * t0 - (T(1) / T(2688)) * t32 * t0 * in.w[2];
    const T t33 = T(8) * r1 * t22 - T(8) * t25 * r0 - T(5) * t0 * b * t24;
    const T t34 = T(30) * c * t0 * t24 + T(12) * t33 * t0 * b - T(5) * t26 * t0;
    const T t35 = T(5) * t28 * t0 + T(14) * t0 * t34 * b - T(42) * c * t33 * t0;
    G_ap = (T(1) / T(40)) * t33 * in.w[1] * t0 + (T(1) / T(240)) * t0 * in.w[2] * t34 + (T(1) / T(1680)) * in.w[3] * t35 * t0 - (T(1) / T(8)) * in.w[0] * t0 * t24;
    G_ab = (T(1) / T(40)) * in.w[0] * t33 * t0 + (T(1) / T(240)) * in.w[1] * t0 * t34 + (T(1) / T(1680)) * t35 * t0 * in.w[2] - (T(1) / T(13440)) * in.w[3] * (T(56) * c * t0 * t34 + T(5) * t32 * t0 - T(16) * t35 * t0 * b) * t0;
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(5/2) dt
/// Returns false where segment_compact_i5_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 68 +, 186 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i5_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-5, -3, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[3] * M_flat[3];
    G_ap = in.w[3] * M_flat[8] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5] + M_flat[7] * in.w[2];
    G_ab = in.w[3] * M_flat[9] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2] + in.w[0] * M_flat[6];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q1 * q1;
    const T t6 = T(3) * D * t0 * (D * J1 + r1 * slope1 - slope0 * r0) + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0;
    const T t7 = q0 * q0;
    const T t8 = T(8) * r1 * slope1 * t5 + T(5) * D * t6 * t0 - T(8) * slope0 * t7 * r0;
    const T t9 = t5 * q1;
    const T t10 = t7 * q0;
    const T t11 = T(7) * t8 * D * t0 + T(48) * r1 * slope1 * t9 - T(48) * slope0 * t10 * r0;
    const T t12 = T(7) * t8 * t0 * b + T(48) * r1 * t9 - T(48) * t10 * r0;
    const T t13 = T(7) * t11 * t0 + T(16) * t0 * t12 * b - T(56) * t8 * c * t0;
    const T t14 = t7 * t7;
    const T t15 = t5 * t5;
    F = (T(1) / T(2688)) * t0 * in.w[2] * t13 + (T(1) / T(48)) * t8 * in.w[0] * t0 + (T(1) / T(336)) * in.w[1] * t0 * t12 + (T(1) / T(8064)) * in.w[3] * (T(6) * t0 * t13 * b - T(24) * c * t0 * t12 - T(7) * (T(128) * t14 * r0 - T(128) * r1 * t15 - T(3) * t11 * t0 * b) * t0) * t0;
    const T t16 = T(8) * r1 * t5 + T(5) * t6 * t0 * b - T(8) * t7 * r0;
    const T t17 = T(30) * c * t6 * t0 - T(12) * t16 * t0 * b - T(5) * t8 * t0;
    const T t18 = T(14) * t17 * t0 * b + T(42) * c * t16 * t0 - T(5) * t0 * t12;
    G_ap = (T(1) / T(40)) * t16 * in.w[1] * t0 + (T(1) / T(8)) * in.w[0] * t6 * t0 - (T(1) / T(1680)) * in.w[3] * t18 * t0 - (T(1) / T(240)) * t17 * t0 * in.w[2];
    G_ab = (T(1) / T(40)) * in.w[0] * t16 * t0 - (T(1) / T(13440)) * in.w[3] * (T(16) * t18 * t0 * b - T(56) * c * t17 * t0 - T(5) * t0 * t13) * t0 - (T(1) / T(240)) * in.w[1] * t17 * t0 - (T(1) / T(1680)) * t18 * t0 * in.w[2];
  }
  const T g_factor = -T(5) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 43 +, 85 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 53 +, 96 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i6_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0];
    G_ab = M_exact[1] * in.w[0];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 67 +, 119 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Returns false where segment_compact_i6_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 119 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i6_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 51 +, 93 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 7, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 62 +, 105 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i6_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0] + in.w[1] * M_exact[1];
    G_ab = in.w[1] * M_exact[2] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 84 +, 136 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
    G_ap = in.w[0] * M_exact[3] + M_exact[4] * in.w[1];
    G_ab = in.w[1] * M_exact[5] + in.w[0] * M_exact[4];
  }
  const T g_factor = -T(6) * length * inv_R2;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Returns false where segment_compact_i6_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 84 +, 136 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i6_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
    G_ap = in.w[1] * M_exact[4] + M_exact[3] * in.w[0];
    G_ab = M_exact[5] * in.w[1] + M_exact[4] * in.w[0];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 59 +, 101 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[2] * in.w[2] + M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 71 +, 114 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i6_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[1] * in.w[1] + M_exact[0] * in.w[0] + in.w[2] * M_exact[2];
    G_ab = in.w[0] * M_exact[1] + in.w[2] * M_exact[3] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(6) * length * inv_R2;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 101 +, 153 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
    G_ap = M_exact[4] * in.w[0] + in.w[2] * M_exact[6] + M_exact[5] * in.w[1];
    G_ab = in.w[2] * M_exact[7] + in.w[0] * M_exact[5] + in.w[1] * M_exact[6];
  }
  const T g_factor = -T(6) * length * inv_R2;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Returns false where segment_compact_i6_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 101 +, 153 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i6_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[0] * M_exact[0] + in.w[1] * M_exact[1];
    G_ap = in.w[1] * M_exact[5] + in.w[2] * M_exact[6] + in.w[0] * M_exact[4];
    G_ab = in.w[2] * M_exact[7] + in.w[0] * M_exact[5] + M_exact[6] * in.w[1];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 67 +, 109 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[2] * in.w[2] + M_exact[3] * in.w[3] + in.w[1] * M_exact[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 80 +, 123 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i6_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-4, -4, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + M_exact[3] * in.w[3];
    G_ab = M_exact[2] * in.w[1] + in.w[2] * M_exact[3] + in.w[0] * M_exact[1] + in.w[3] * M_exact[4];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Operations: 118 +, 170 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i6_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[3] * M_exact[3] + in.w[0] * M_exact[0] + M_exact[2] * in.w[2];
    G_ap = M_exact[8] * in.w[3] + M_exact[5] * in.w[0] + M_exact[7] * in.w[2] + M_exact[6] * in.w[1];
    G_ab = in.w[3] * M_exact[9] + M_exact[8] * in.w[2] + in.w[0] * M_exact[6] + in.w[1] * M_exact[7];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(6/2) dt
/// Returns false where segment_compact_i6_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 118 +, 170 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i6_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-6, -4, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + in.w[3] * M_exact[3] + in.w[1] * M_exact[1];
    G_ap = M_exact[7] * in.w[2] + M_exact[5] * in.w[0] + in.w[1] * M_exact[6] + M_exact[8] * in.w[3];
    G_ab = in.w[0] * M_exact[6] + in.w[1] * M_exact[7] + in.w[2] * M_exact[8] + in.w[3] * M_exact[9];
  }
  const T g_factor = -T(6) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 40 +, 80 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2078 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
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
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    F = -(T(1) / T(9)) * in.w[0] * (t8 * r1 * slope1 - T(10) * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) * a - r0 * slope0 * t10) / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = q1 * q1;
    const T t14 = t13 * q1;
    F = -(T(1) / T(384)) * in.w[0] * (T(48) * r0 * slope0 * t12 + T(7) * D * t2 * (T(8) * r0 * slope0 * t11 + T(5) * (T(3) * D * t2 * (r0 * slope0 - r1 * slope1 - J1 * D) + T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1) * D * t2 - T(8) * q1 * q1 * r1 * slope1) - T(48) * t14 * r1 * slope1) * t2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 43 +, 92 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2109 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t9 * t9;
    const T t12 = t7 * t7;
    const T t13 = T(9) * r1 * slope1 * t8 - T(9) * slope0 * t10 * r0 - T(8) * a * t6 * (slope0 * t11 * r0 + T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) - r1 * slope1 * t12);
    G_ap = -(T(1) / T(63)) * t6 * t13 * in.w[0];
    G_ab = -(T(1) / T(63)) * t1 * in.w[0] * (t6 * b * t13 + T(9) * t10 * r0 - T(9) * r1 * t8);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = T(8) * slope0 * q0 * q0 * r0 - T(8) * r1 * slope1 * q1 * q1 - T(5) * t1 * D * (T(2) * r1 * slope1 * q1 - T(3) * t1 * D * (slope0 * r0 - r1 * slope1 - D * J1) - T(2) * slope0 * q0 * r0);
    G_ap = -(T(1) / T(48)) * t14 * t1 * in.w[0];
    const T t15 = q1 * q1;
    const T t16 = t15 * q1;
    const T t17 = q0 * q0;
    const T t18 = t17 * q0;
    G_ab = (T(1) / T(336)) * t1 * (T(48) * r1 * t16 - T(48) * t18 * r0 - T(7) * t14 * t1 * b) * in.w[0];
  }
  const T g_factor = -T(7) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 45 +, 105 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2113 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -a * a * t3 * t3 - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-9 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = r0 * slope0 * t8 + T(10) * a * J_upward_compact<T>(-9, a, D, slope0, q0, slope1, q1) - t10 * r1 * slope1;
    const T t12 = T(1) / D;
    F = (T(1) / T(9)) * t11 * in.w[0] * t12;
    const T t13 = t9 * q1;
    const T t14 = t7 * q0;
    const T t15 = T(9) * t13 * r1 * slope1 - T(9) * r0 * slope0 * t14 - T(8) * a * t11 * t12;
    G_ap = -(T(1) / T(63)) * in.w[0] * t12 * t15;
    G_ab = -(T(1) / T(63)) * t2 * in.w[0] * (b * t12 * t15 + T(9) * r0 * t14 - T(9) * t13 * r1);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t16 = T(8) * r0 * slope0 * q0 * q0 - T(5) * t2 * (T(2) * q1 * r1 * slope1 + T(3) * t2 * (r1 * slope1 + J1 * D - r0 * slope0) * D - T(2) * r0 * slope0 * q0) * D - T(8) * q1 * q1 * r1 * slope1;
    const T t17 = q0 * q0;
    const T t18 = t17 * q0;
    const T t19 = q1 * q1;
    const T t20 = t19 * q1;
    F = -(T(1) / T(384)) * t2 * (T(7) * t16 * t2 * D + T(48) * r0 * slope0 * t18 - T(48) * t20 * r1 * slope1) * in.w[0];
    G_ap = -(T(1) / T(48)) * t16 * t2 * in.w[0];
    G_ab = -(T(1) / T(336)) * t2 * in.w[0] * (T(7) * t16 * t2 * b + T(48) * r0 * t18 - T(48) * t20 * r1);
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Returns false where segment_compact_i7_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 45 +, 104 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i7_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -a * a * t2 * t2 - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q0 * q0;
    const T t7 = t6 * q0;
    const T t8 = T(5) * D * t1 * (T(2) * slope1 * q1 * r1 + T(3) * (slope1 * r1 + D * J1 - r0 * slope0) * D * t1 - T(2) * q0 * r0 * slope0) + T(8) * slope1 * q1 * q1 * r1 - T(8) * t6 * r0 * slope0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    F = -(T(1) / T(384)) * (T(48) * t7 * r0 * slope0 - T(7) * D * t1 * t8 - T(48) * slope1 * t10 * r1) * t1 * in.w[0];
    G_ap = (T(1) / T(48)) * t1 * t8 * in.w[0];
    G_ab = (T(1) / T(336)) * t1 * (T(7) * t1 * t8 * b + T(48) * t10 * r1 - T(48) * t7 * r0) * in.w[0];
  }
  const T g_factor = -T(7) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 43 +, 93 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2102 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t10 * q0;
    const T t12 = T(1) / D;
    const T t13 = T(11) * slope1 * t7 * r1 + T(10) * (slope1 * t8 * r1 - T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a - t11 * r0 * slope0) * t12 * a - T(11) * t10 * r0 * slope0;
    F = -(T(1) / T(99)) * in.w[0] * t13 * t12 - (T(1) / T(99)) * in.w[1] * t1 * (b * t13 * t12 + T(11) * t10 * r0 - T(11) * t7 * r1);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = q0 * q0;
    const T t15 = t14 * q0;
    const T t16 = q1 * q1;
    const T t17 = t16 * q1;
    const T t18 = T(7) * D * (T(5) * (T(2) * q0 * r0 * slope0 - T(3) * D * t1 * (slope1 * r1 + J1 * D - r0 * slope0) - T(2) * slope1 * q1 * r1) * D * t1 + T(8) * q0 * q0 * r0 * slope0 - T(8) * slope1 * q1 * q1 * r1) * t1 + T(48) * t15 * r0 * slope0 - T(48) * slope1 * t17 * r1;
    const T t19 = t14 * t14;
    const T t20 = t16 * t16;
    F = -(T(1) / T(1152)) * in.w[1] * (T(3) * b * t18 * t1 + T(128) * t19 * r0 - T(128) * t20 * r1) * t1 - (T(1) / T(384)) * in.w[0] * t18 * t1;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 49 +, 115 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2136 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t6 = q0 * q0;
    const T t7 = t6 * q0;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t8 * t8;
    const T t11 = t10 * q1;
    const T t12 = t6 * t6;
    const T t13 = t12 * q0;
    const T t14 = T(1) / D;
    const T t15 = T(10) * (r1 * slope1 * t11 - slope0 * t13 * r0 - T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a) * t14 * a + T(11) * r1 * slope1 * t10 - T(11) * slope0 * t12 * r0;
    const T t16 = T(99) * slope0 * t7 * r0 - T(99) * r1 * slope1 * t9 - T(8) * t15 * t14 * a;
    const T t17 = b * t16 * t14 + T(99) * r1 * t9 - T(99) * t7 * r0;
    G_ap = (T(1) / T(693)) * t16 * t14 * in.w[0] + (T(1) / T(693)) * t17 * in.w[1] * t1;
    G_ab = (T(1) / T(693)) * t17 * t1 * in.w[0] - (T(1) / T(693)) * (T(7) * t15 * t14 + c * t16 * t14 - T(2) * t17 * b * t1) * in.w[1] * t1;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t18 = T(8) * slope0 * q0 * q0 * r0 - T(8) * r1 * slope1 * q1 * q1 - T(5) * (T(3) * D * t1 * (J1 * D + r1 * slope1 - slope0 * r0) + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0) * D * t1;
    const T t19 = q0 * q0;
    const T t20 = t19 * q0;
    const T t21 = q1 * q1;
    const T t22 = t21 * q1;
    const T t23 = T(7) * t18 * b * t1 + T(48) * t20 * r0 - T(48) * r1 * t22;
    G_ap = -(T(1) / T(48)) * t18 * t1 * in.w[0] - (T(1) / T(336)) * t23 * in.w[1] * t1;
    G_ab = -(T(1) / T(2688)) * in.w[1] * (T(7) * (T(48) * slope0 * t20 * r0 + T(7) * t18 * D * t1 - T(48) * r1 * slope1 * t22) * t1 + T(16) * b * t23 * t1 - T(56) * t18 * c * t1) * t1 - (T(1) / T(336)) * t23 * t1 * in.w[0];
  }
  const T g_factor = -T(7) * inv_R2 * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 52 +, 130 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2149 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = M_flat[3] * in.w[0] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t10 * q0;
    const T t12 = t8 * q1;
    const T t13 = T(1) / D;
    const T t14 = T(11) * t8 * r1 * slope1 - T(11) * r0 * slope0 * t10 - T(10) * (r0 * slope0 * t11 + T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a - t12 * r1 * slope1) * t13 * a;
    F = -(T(1) / T(99)) * in.w[1] * (t14 * b * t13 + T(11) * r0 * t10 - T(11) * t8 * r1) * t2 - (T(1) / T(99)) * t14 * t13 * in.w[0];
    const T t15 = t9 * q0;
    const T t16 = t7 * q1;
    const T t17 = T(99) * r0 * slope0 * t15 - T(99) * t16 * r1 * slope1 - T(8) * t14 * t13 * a;
    const T t18 = T(99) * t16 * r1 + b * t17 * t13 - T(99) * r0 * t15;
    G_ap = (T(1) / T(693)) * t17 * t13 * in.w[0] + (T(1) / T(693)) * in.w[1] * t18 * t2;
    G_ab = (T(1) / T(693)) * t18 * in.w[0] * t2 - (T(1) / T(693)) * in.w[1] * (T(7) * t14 * t13 + c * t17 * t13 - T(2) * b * t18 * t2) * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t19 = q0 * q0;
    const T t20 = t19 * q0;
    const T t21 = T(8) * r0 * slope0 * t19 - T(5) * (T(2) * q1 * r1 * slope1 + T(3) * (r1 * slope1 + D * J1 - r0 * slope0) * D * t2 - T(2) * r0 * slope0 * q0) * D * t2 - T(8) * q1 * q1 * r1 * slope1;
    const T t22 = q1 * q1;
    const T t23 = t22 * q1;
    const T t24 = T(48) * r0 * slope0 * t20 + T(7) * t21 * D * t2 - T(48) * t23 * r1 * slope1;
    const T t25 = t19 * t19;
    const T t26 = t22 * t22;
    F = -(T(1) / T(384)) * t24 * in.w[0] * t2 - (T(1) / T(1152)) * in.w[1] * (T(3) * t24 * b * t2 + T(128) * r0 * t25 - T(128) * t26 * r1) * t2;
    const T t27 = T(48) * t23 * r1 - T(48) * r0 * t20 - T(7) * b * t21 * t2;
    G_ap = (T(1) / T(336)) * in.w[1] * t2 * t27 - (T(1) / T(48)) * t21 * in.w[0] * t2;
    G_ab = (T(1) / T(2688)) * in.w[1] * (T(56) * c * t21 * t2 + T(16) * b * t2 * t27 - T(7) * t24 * t2) * t2 + (T(1) / T(336)) * in.w[0] * t2 * t27;
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Returns false where segment_compact_i7_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 52 +, 131 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i7_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = T(5) * D * t2 * (T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0 - T(3) * D * t2 * (r0 * slope0 - D * J1 - r1 * slope1)) + T(8) * q1 * q1 * r1 * slope1 - T(8) * r0 * slope0 * q0 * q0;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = q0 * q0;
    const T t11 = t10 * q0;
    const T t12 = T(7) * D * t2 * t7 + T(48) * t9 * r1 * slope1 - T(48) * r0 * slope0 * t11;
    const T t13 = t10 * t10;
    const T t14 = t8 * t8;
    F = (T(1) / T(384)) * t2 * in.w[0] * t12 - (T(1) / T(1152)) * t2 * (T(128) * r0 * t13 - T(128) * t14 * r1 - T(3) * t2 * b * t12) * in.w[1];
    const T t15 = T(7) * t2 * t7 * b + T(48) * t9 * r1 - T(48) * r0 * t11;
    G_ap = (T(1) / T(48)) * t2 * in.w[0] * t7 + (T(1) / T(336)) * t15 * t2 * in.w[1];
    G_ab = (T(1) / T(2688)) * t2 * in.w[1] * (T(16) * t15 * t2 * b + T(7) * t2 * t12 - T(56) * t2 * t7 * c) + (T(1) / T(336)) * t15 * t2 * in.w[0];
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 48 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2112 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = t6 * q1;
    const T t11 = T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t9 - t10 * r1 * slope1;
    const T t12 = T(1) / D;
    const T t13 = T(11) * r0 * slope0 * t8 + T(10) * t11 * a * t12 - T(11) * t6 * r1 * slope1;
    const T t14 = T(11) * t6 * r1 + t13 * t12 * b - T(11) * r0 * t8;
    F = (T(1) / T(99)) * in.w[2] * t0 * (T(2) * t14 * t0 * b + T(9) * t11 * t12 - c * t13 * t12) + (T(1) / T(99)) * in.w[0] * t13 * t12 + (T(1) / T(99)) * t14 * t0 * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t15 = q1 * q1;
    const T t16 = t15 * t15;
    const T t17 = t15 * q1;
    const T t18 = q0 * q0;
    const T t19 = t18 * q0;
    const T t20 = T(48) * t17 * r1 * slope1 - T(7) * (T(5) * (T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1 - T(3) * (J1 * D + r1 * slope1 - r0 * slope0) * t0 * D) * t0 * D + T(8) * r0 * slope0 * q0 * q0 - T(8) * t15 * r1 * slope1) * t0 * D - T(48) * r0 * slope0 * t19;
    const T t21 = t18 * t18;
    const T t22 = T(128) * t16 * r1 + T(3) * t0 * t20 * b - T(128) * r0 * t21;
    F = (T(1) / T(1152)) * t0 * in.w[1] * t22 + (T(1) / T(11520)) * in.w[2] * (T(20) * t0 * t22 * b + T(9) * (T(3) * t0 * D * t20 + T(128) * t16 * r1 * slope1 - T(128) * r0 * slope0 * t21) * t0 - T(30) * c * t0 * t20) * t0 + (T(1) / T(384)) * in.w[0] * t0 * t20;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 55 +, 138 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2155 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ab = in.w[1] * M_flat[2] + in.w[0] * M_flat[1] + M_flat[3] * in.w[2];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = T(1) / D;
    const T t9 = t6 * t6;
    const T t10 = t9 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * t11;
    const T t13 = t12 * q0;
    const T t14 = T(11) * t9 * r1 * slope1 + T(10) * t8 * a * (t10 * r1 * slope1 - r0 * slope0 * t13 - T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1)) - T(11) * r0 * slope0 * t12;
    const T t15 = t11 * q0;
    const T t16 = T(8) * t8 * a * t14 + T(99) * t7 * r1 * slope1 - T(99) * r0 * slope0 * t15;
    const T t17 = T(99) * t7 * r1 - t16 * t8 * b - T(99) * r0 * t15;
    const T t18 = T(2) * t1 * t17 * b + t16 * t8 * c - T(7) * t8 * t14;
    G_ap = (T(1) / T(693)) * t1 * t18 * in.w[2] + (T(1) / T(693)) * t1 * in.w[1] * t17 - (T(1) / T(693)) * in.w[0] * t16 * t8;
    G_ab = (T(1) / T(693)) * in.w[0] * t1 * t17 + (T(1) / T(693)) * t1 * in.w[1] * t18 + (T(1) / T(693)) * (T(2) * t1 * b * t18 - T(7) * t1 * (T(11) * r0 * t12 + t8 * b * t14 - T(11) * t9 * r1) - t1 * t17 * c) * t1 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t19 = T(8) * q1 * q1 * r1 * slope1 + T(5) * D * t1 * (T(2) * q1 * r1 * slope1 + T(3) * (r1 * slope1 + D * J1 - r0 * slope0) * D * t1 - T(2) * r0 * slope0 * q0) - T(8) * r0 * slope0 * q0 * q0;
    const T t20 = q1 * q1;
    const T t21 = t20 * q1;
    const T t22 = q0 * q0;
    const T t23 = t22 * q0;
    const T t24 = T(7) * t1 * b * t19 + T(48) * t21 * r1 - T(48) * r0 * t23;
    const T t25 = T(48) * r0 * slope0 * t23 - T(48) * t21 * r1 * slope1 - T(7) * D * t1 * t19;
    const T t26 = T(56) * t1 * t19 * c + T(7) * t1 * t25 - T(16) * t1 * t24 * b;
    G_ap = (T(1) / T(48)) * in.w[0] * t1 * t19 + (T(1) / T(336)) * t1 * t24 * in.w[1] - (T(1) / T(2688)) * t1 * in.w[2] * t26;
    const T t27 = t22 * t22;
    const T t28 = t20 * t20;
    G_ab = (T(1) / T(336)) * in.w[0] * t1 * t24 - (T(1) / T(8064)) * t1 * (T(24) * t1 * t24 * c + T(7) * (T(3) * t1 * b * t25 + T(128) * r0 * t27 - T(128) * t28 * r1) * t1 + T(6) * t1 * b * t26) * in.w[2] - (T(1) / T(2688)) * t1 * in.w[1] * t26;
  }
  const T g_factor = -T(7) * length * inv_R2;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 61 +, 163 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2172 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[0] + M_flat[6] * in.w[2] + in.w[1] * M_flat[5];
    G_ab = in.w[0] * M_flat[5] + in.w[1] * M_flat[6] + in.w[2] * M_flat[7];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a + r0 * slope0 * t9 - r1 * slope1 * t12;
    const T t14 = T(1) / D;
    const T t15 = T(10) * t13 * a * t14 + T(11) * r0 * slope0 * t8 - T(11) * r1 * slope1 * t11;
    const T t16 = T(11) * r0 * t8 - T(11) * r1 * t11 - b * t15 * t14;
    F = (T(1) / T(99)) * in.w[2] * (T(9) * t13 * t14 - T(2) * b * t16 * t2 - t15 * c * t14) * t2 + (T(1) / T(99)) * t15 * in.w[0] * t14 - (T(1) / T(99)) * in.w[1] * t16 * t2;
    const T t17 = t10 * q1;
    const T t18 = t7 * q0;
    const T t19 = T(99) * r1 * slope1 * t17 - T(99) * r0 * slope0 * t18 - T(8) * t15 * a * t14;
    const T t20 = b * t19 * t14 + T(99) * r0 * t18 - T(99) * r1 * t17;
    const T t21 = T(7) * t15 * t14 + c * t19 * t14 - T(2) * t20 * b * t2;
    G_ap = (T(1) / T(693)) * t21 * in.w[2] * t2 - (T(1) / T(693)) * in.w[1] * t20 * t2 - (T(1) / T(693)) * t19 * in.w[0] * t14;
    G_ab = (T(1) / T(693)) * in.w[1] * t21 * t2 - (T(1) / T(693)) * (T(7) * t16 * t2 - T(2) * b * t21 * t2 - t20 * c * t2) * in.w[2] * t2 - (T(1) / T(693)) * t20 * in.w[0] * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * q1;
    const T t24 = q0 * q0;
    const T t25 = t24 * q0;
    const T t26 = T(8) * r0 * slope0 * t24 - T(8) * r1 * slope1 * t22 - T(5) * (T(2) * r1 * slope1 * q1 + T(3) * (r1 * slope1 + D * J1 - r0 * slope0) * t2 * D - T(2) * r0 * slope0 * q0) * t2 * D;
    const T t27 = T(48) * r1 * slope1 * t23 - T(48) * r0 * slope0 * t25 - T(7) * t26 * t2 * D;
    const T t28 = t24 * t24;
    const T t29 = t22 * t22;
    const T t30 = T(128) * r0 * t28 - T(3) * b * t2 * t27 - T(128) * r1 * t29;
    F = (T(1) / T(384)) * in.w[0] * t2 * t27 - (T(1) / T(1152)) * in.w[1] * t30 * t2 - (T(1) / T(11520)) * in.w[2] * (T(20) * b * t30 * t2 + T(9) * (T(128) * r0 * slope0 * t28 - T(3) * t2 * D * t27 - T(128) * r1 * slope1 * t29) * t2 + T(30) * c * t2 * t27) * t2;
    const T t31 = T(7) * b * t26 * t2 + T(48) * r0 * t25 - T(48) * r1 * t23;
    const T t32 = T(7) * t2 * t27 + T(56) * t26 * c * t2 - T(16) * t31 * b * t2;
    G_ap = (T(1) / T(2688)) * in.w[2] * t2 * t32 - (T(1) / T(336)) * in.w[1] * t31 * t2 - (T(1) / T(48)) * t26 * in.w[0] * t2;
    G_ab = (T(1) / T(2688)) * in.w[1] * t2 * t32 - (T(1) / T(336)) * t31 * in.w[0] * t2 - (T(1) / T(8064)) * in.w[2] * t2 * (T(7) * t30 * t2 - T(6) * b * t2 * t32 - T(24) * t31 * c * t2);
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Returns false where segment_compact_i7_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 61 +, 163 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i7_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -a * a * t3 * t3 - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ap = M_flat[4] * in.w[0] + in.w[1] * M_flat[5] + M_flat[6] * in.w[2];
    G_ab = in.w[2] * M_flat[7] + in.w[1] * M_flat[6] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = t7 * q1;
    const T t10 = q0 * q0;
    const T t11 = t10 * q0;
    const T t12 = T(8) * r0 * slope0 * t10 - T(8) * t7 * r1 * slope1 - T(5) * t2 * (T(3) * t2 * (r1 * slope1 + J1 * D - r0 * slope0) * D + T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0) * D;
    const T t13 = T(48) * t9 * r1 * slope1 - T(48) * r0 * slope0 * t11 - T(7) * t2 * t12 * D;
    const T t14 = t10 * t10;
    const T t15 = T(128) * t8 * r1 + T(3) * t2 * b * t13 - T(128) * r0 * t14;
    F = (T(1) / T(1152)) * t2 * in.w[1] * t15 + (T(1) / T(384)) * t2 * in.w[0] * t13 - (T(1) / T(11520)) * t2 * in.w[2] * (T(30) * t2 * c * t13 + T(9) * t2 * (T(128) * r0 * slope0 * t14 - T(3) * t2 * t13 * D - T(128) * t8 * r1 * slope1) - T(20) * t2 * b * t15);
    const T t16 = T(48) * r0 * t11 + T(7) * t2 * b * t12 - T(48) * t9 * r1;
    const T t17 = T(56) * t2 * c * t12 + T(7) * t2 * t13 - T(16) * t2 * t16 * b;
    G_ap = (T(1) / T(2688)) * t2 * in.w[2] * t17 - (T(1) / T(48)) * t2 * in.w[0] * t12 - (T(1) / T(336)) * t2 * in.w[1] * t16;
    G_ab = (T(1) / T(2688)) * t2 * in.w[1] * t17 + (T(1) / T(8064)) * t2 * in.w[2] * (T(24) * t2 * t16 * c + T(6) * t2 * b * t17 + T(7) * t2 * t15) - (T(1) / T(336)) * t2 * t16 * in.w[0];
  }
  const T g_factor = -T(7) * length * inv_R2;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 53 +, 131 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2143 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * t5;
    const T t7 = T(1) / D;
    const T t8 = t6 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t10 * t10;
    const T t12 = t5 * q0;
    const T t13 = t12 * t12;
    const T t14 = t9 * t9;
    const T t15 = t14 * q1;
    const T t16 = T(13) * r0 * slope0 * t8 - T(12) * (t11 * r1 * slope1 - r0 * slope0 * t13 - T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1)) * t7 * a - T(13) * t15 * r1 * slope1;
    const T t17 = T(143) * r0 * slope0 * t6 + T(10) * t7 * t16 * a - T(143) * t14 * r1 * slope1;
    const T t18 = T(143) * r0 * t6 - t7 * t17 * b - T(143) * t14 * r1;
    const T t19 = c * t7 * t17 + T(2) * t18 * t0 * b - T(9) * t7 * t16;
    F = (T(1) / T(1287)) * in.w[3] * (t18 * c * t0 - T(2) * t0 * t19 * b - T(9) * (T(13) * r0 * t8 - t7 * t16 * b - T(13) * t15 * r1) * t0) * t0 + (T(1) / T(1287)) * t7 * t17 * in.w[0] - (T(1) / T(1287)) * t18 * in.w[1] * t0 - (T(1) / T(1287)) * t0 * in.w[2] * t19;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = q1 * q1;
    const T t21 = t20 * q1;
    const T t22 = q0 * q0;
    const T t23 = t22 * q0;
    const T t24 = T(48) * t21 * r1 * slope1 - T(48) * r0 * slope0 * t23 - T(7) * D * t0 * (T(5) * D * t0 * (T(2) * r0 * slope0 * q0 - T(3) * D * t0 * (D * J1 + r1 * slope1 - r0 * slope0) - T(2) * q1 * r1 * slope1) + T(8) * r0 * slope0 * t22 - T(8) * t20 * r1 * slope1);
    const T t25 = t22 * t22;
    const T t26 = t20 * t20;
    const T t27 = T(128) * r0 * t25 - T(3) * t0 * b * t24 - T(128) * t26 * r1;
    const T t28 = T(128) * r0 * slope0 * t25 - T(3) * D * t0 * t24 - T(128) * t26 * r1 * slope1;
    const T t29 = T(9) * t28 * t0 + T(30) * c * t0 * t24 + T(20) * t27 * t0 * b;
    const T t30 = t25 * q0;
    const T t31 = t26 * q1;
    F = (T(1) / T(384)) * t0 * t24 * in.w[0] + (T(1) / T(126720)) * in.w[3] * t0 * (T(110) * c * t27 * t0 - T(22) * t29 * t0 * b - T(9) * (T(1280) * r0 * t30 + T(11) * t28 * t0 * b - T(1280) * t31 * r1) * t0) - (T(1) / T(11520)) * t29 * t0 * in.w[2] - (T(1) / T(1152)) * t27 * in.w[1] * t0;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 63 +, 168 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2188 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i7_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(t0, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-5, -5, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3];
    G_ab = M_flat[3] * in.w[2] + M_flat[4] * in.w[3] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = q0 * q0;
    const T t9 = t8 * q0;
    const T t10 = T(1) / D;
    const T t11 = t8 * t8;
    const T t12 = t11 * q0;
    const T t13 = t9 * t9;
    const T t14 = t7 * t7;
    const T t15 = t6 * t6;
    const T t16 = t15 * q1;
    const T t17 = T(13) * slope0 * t12 * r0 + T(12) * (slope0 * t13 * r0 + T(14) * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) * a - slope1 * t14 * r1) * t10 * a - T(13) * slope1 * t16 * r1;
    const T t18 = T(10) * t10 * a * t17 + T(143) * slope0 * t11 * r0 - T(143) * slope1 * t15 * r1;
    const T t19 = T(1287) * slope1 * t7 * r1 - T(1287) * slope0 * t9 * r0 - T(8) * t18 * t10 * a;
    const T t20 = T(1287) * t7 * r1 - T(1287) * t9 * r0 - b * t10 * t19;
    const T t21 = c * t10 * t19 + T(2) * b * t20 * t1 + T(7) * t18 * t10;
    const T t22 = b * t18 * t10 + T(143) * t15 * r1 - T(143) * t11 * r0;
    const T t23 = c * t20 * t1 - T(2) * b * t21 * t1 - T(7) * t22 * t1;
    G_ap = (T(1) / T(9009)) * t20 * in.w[1] * t1 + (T(1) / T(9009)) * t21 * t1 * in.w[2] - (T(1) / T(9009)) * in.w[0] * t10 * t19 - (T(1) / T(9009)) * in.w[3] * t1 * t23;
    G_ab = (T(1) / T(9009)) * (T(7) * (T(2) * b * t22 * t1 + T(9) * t10 * t17 - c * t18 * t10) * t1 - t21 * c * t1 - T(2) * b * t1 * t23) * in.w[3] * t1 + (T(1) / T(9009)) * in.w[0] * t20 * t1 + (T(1) / T(9009)) * t21 * in.w[1] * t1 - (T(1) / T(9009)) * t1 * t23 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t24 = q1 * q1;
    const T t25 = t24 * q1;
    const T t26 = T(8) * slope1 * t24 * r1 - T(5) * (T(2) * slope0 * q0 * r0 - T(3) * (J1 * D + slope1 * r1 - slope0 * r0) * D * t1 - T(2) * slope1 * q1 * r1) * D * t1 - T(8) * slope0 * q0 * q0 * r0;
    const T t27 = q0 * q0;
    const T t28 = t27 * q0;
    const T t29 = T(48) * t25 * r1 + T(7) * t26 * b * t1 - T(48) * t28 * r0;
    const T t30 = T(48) * slope1 * t25 * r1 + T(7) * t26 * D * t1 - T(48) * slope0 * t28 * r0;
    const T t31 = T(7) * t30 * t1 + T(16) * b * t29 * t1 - T(56) * t26 * c * t1;
    const T t32 = t27 * t27;
    const T t33 = t24 * t24;
    const T t34 = T(128) * t32 * r0 - T(128) * t33 * r1 - T(3) * b * t30 * t1;
    const T t35 = T(24) * c * t29 * t1 + T(7) * t34 * t1 - T(6) * b * t31 * t1;
    G_ap = (T(1) / T(336)) * t29 * in.w[1] * t1 + (T(1) / T(2688)) * t31 * t1 * in.w[2] + (T(1) / T(48)) * t26 * in.w[0] * t1 - (T(1) / T(8064)) * in.w[3] * t35 * t1;
    G_ab = (T(1) / T(336)) * in.w[0] * t29 * t1 + (T(1) / T(2688)) * t31 * in.w[1] * t1 - (T(1) / T(8064)) * t35 * t1 * in.w[2] - (T(1) / T(80640)) * in.w[3] * t1 * (T(20) * b * t35 * t1 + T(30) * c * t31 * t1 + T(7) * (T(30) * t30 * c * t1 + T(20) * b * t34 * t1 - T(9) * (T(3) * t30 * D * t1 + T(128) * slope1 * t33 * r1 - T(128) * slope0 * t32 * r0) * t1) * t1);
  }
  const T g_factor = -T(7) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Operations: 70 +, 199 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2214 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i7_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0];
    G_ap = M_flat[5] * in.w[0] + in.w[3] * M_flat[8] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
    G_ab = M_flat[7] * in.w[1] + in.w[2] * M_flat[8] + M_flat[6] * in.w[0] + M_flat[9] * in.w[3];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t7 = T(1) / D;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t8 * q0;
    const T t15 = t14 * t14;
    const T t16 = t11 * t11;
    const T t17 = t16 * q1;
    const T t18 = T(13) * r0 * slope0 * t10 - T(12) * a * t7 * (t13 * r1 * slope1 - r0 * slope0 * t15 - T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1)) - T(13) * t17 * r1 * slope1;
    const T t19 = T(143) * r0 * slope0 * t9 + T(10) * a * t7 * t18 - T(143) * t16 * r1 * slope1;
    const T t20 = T(143) * t16 * r1 + t7 * b * t19 - T(143) * r0 * t9;
    const T t21 = T(2) * t2 * b * t20 + T(9) * t7 * t18 - t7 * c * t19;
    F = (T(1) / T(1287)) * t7 * in.w[0] * t19 + (T(1) / T(1287)) * t2 * t20 * in.w[1] + (T(1) / T(1287)) * t2 * in.w[2] * t21 + (T(1) / T(1287)) * t2 * (T(2) * t2 * b * t21 + T(9) * t2 * (T(13) * t17 * r1 + t7 * t18 * b - T(13) * r0 * t10) - t2 * c * t20) * in.w[3];
    const T t22 = T(1287) * t12 * r1 * slope1 - T(1287) * r0 * slope0 * t14 - T(8) * a * t7 * t19;
    const T t23 = t7 * b * t22 + T(1287) * r0 * t14 - T(1287) * t12 * r1;
    const T t24 = T(2) * t2 * t23 * b - T(7) * t7 * t19 - t7 * c * t22;
    const T t25 = t2 * t23 * c + T(7) * t2 * t20 - T(2) * t2 * b * t24;
    G_ap = (T(1) / T(9009)) * t2 * in.w[3] * t25 - (T(1) / T(9009)) * t7 * in.w[0] * t22 - (T(1) / T(9009)) * t2 * in.w[2] * t24 - (T(1) / T(9009)) * t2 * t23 * in.w[1];
    G_ab = (T(1) / T(9009)) * t2 * in.w[2] * t25 + (T(1) / T(9009)) * t2 * (T(2) * t2 * b * t25 + t2 * t24 * c + T(7) * t2 * t21) * in.w[3] - (T(1) / T(9009)) * t2 * t24 * in.w[1] - (T(1) / T(9009)) * t2 * t23 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t26 = T(5) * t2 * D * (T(3) * t2 * D * (D * J1 + r1 * slope1 - r0 * slope0) + T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0) + T(8) * q1 * q1 * r1 * slope1 - T(8) * r0 * slope0 * q0 * q0;
    const T t27 = q1 * q1;
    const T t28 = t27 * q1;
    const T t29 = q0 * q0;
    const T t30 = t29 * q0;
    const T t31 = T(7) * t2 * t26 * D + T(48) * t28 * r1 * slope1 - T(48) * r0 * slope0 * t30;
    const T t32 = t27 * t27;
    const T t33 = t29 * t29;
    const T t34 = T(128) * t32 * r1 + T(3) * t2 * b * t31 - T(128) * r0 * t33;
    const T t35 = T(3) * t2 * D * t31 + T(128) * t32 * r1 * slope1 - T(128) * r0 * slope0 * t33;
    const T t36 = T(30) * t2 * t31 * c - T(9) * t2 * t35 - T(20) * t2 * b * t34;
    const T t37 = t32 * q1;
    const T t38 = t33 * q0;
    F = (T(1) / T(384)) * t2 * t31 * in.w[0] + (T(1) / T(1152)) * t2 * t34 * in.w[1] - (T(1) / T(11520)) * t2 * in.w[2] * t36 - (T(1) / T(126720)) * t2 * (T(110) * t2 * c * t34 + T(22) * t2 * b * t36 - T(9) * t2 * (T(1280) * t37 * r1 + T(11) * t2 * t35 * b - T(1280) * r0 * t38)) * in.w[3];
    const T t39 = T(48) * r0 * t30 - T(48) * t28 * r1 - T(7) * t2 * t26 * b;
    const T t40 = T(56) * t2 * t26 * c + T(16) * t2 * b * t39 - T(7) * t2 * t31;
    const T t41 = T(24) * t2 * t39 * c + T(7) * t2 * t34 - T(6) * t2 * b * t40;
    G_ap = (T(1) / T(48)) * t2 * t26 * in.w[0] + (T(1) / T(8064)) * t2 * t41 * in.w[3] - (T(1) / T(2688)) * t2 * in.w[2] * t40 - (T(1) / T(336)) * t2 * t39 * in.w[1];
    G_ab = (T(1) / T(8064)) * t2 * t41 * in.w[2] - (T(1) / T(336)) * t2 * t39 * in.w[0] - (T(1) / T(2688)) * t2 * t40 * in.w[1] - (T(1) / T(80640)) * t2 * in.w[3] * (T(7) * t2 * t36 - T(30) * t2 * c * t40 - T(20) * t2 * t41 * b);
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(7/2) dt
/// Returns false where segment_compact_i7_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 70 +, 197 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i7_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-7, -5, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3];
    G_ap = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = M_flat[8] * in.w[2] + M_flat[6] * in.w[0] + in.w[3] * M_flat[9] + M_flat[7] * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t8 * q0;
    const T t11 = T(8) * r0 * slope0 * t8 - T(8) * slope1 * t6 * r1 - T(5) * D * t1 * (T(3) * D * t1 * (slope1 * r1 + D * J1 - r0 * slope0) + T(2) * slope1 * q1 * r1 - T(2) * r0 * slope0 * q0);
    const T t12 = t6 * q1;
    const T t13 = T(48) * r0 * slope0 * t10 + T(7) * D * t1 * t11 - T(48) * slope1 * t12 * r1;
    const T t14 = T(128) * t7 * r1 - T(128) * r0 * t9 - T(3) * t1 * b * t13;
    const T t15 = T(128) * slope1 * t7 * r1 - T(3) * D * t1 * t13 - T(128) * r0 * slope0 * t9;
    const T t16 = T(30) * t1 * t13 * c + T(20) * t1 * b * t14 + T(9) * t1 * t15;
    const T t17 = t7 * q1;
    const T t18 = t9 * q0;
    F = (T(1) / T(1152)) * t1 * in.w[1] * t14 + (T(1) / T(11520)) * t1 * in.w[2] * t16 - (T(1) / T(126720)) * t1 * (T(110) * t1 * c * t14 - T(9) * t1 * (T(11) * t1 * t15 * b + T(1280) * t17 * r1 - T(1280) * r0 * t18) - T(22) * t1 * t16 * b) * in.w[3] - (T(1) / T(384)) * t1 * in.w[0] * t13;
    const T t19 = T(7) * t1 * b * t11 + T(48) * r0 * t10 - T(48) * t12 * r1;
    const T t20 = T(56) * t1 * t11 * c - T(7) * t1 * t13 - T(16) * t1 * b * t19;
    const T t21 = T(6) * t1 * b * t20 + T(24) * t1 * t19 * c + T(7) * t1 * t14;
    G_ap = (T(1) / T(2688)) * t1 * in.w[2] * t20 + (T(1) / T(8064)) * t1 * in.w[3] * t21 - (T(1) / T(48)) * t1 * t11 * in.w[0] - (T(1) / T(336)) * t1 * t19 * in.w[1];
    G_ab = (T(1) / T(2688)) * t1 * t20 * in.w[1] + (T(1) / T(8064)) * t1 * in.w[2] * t21 + (T(1) / T(80640)) * t1 * (T(7) * t1 * t16 + T(20) * t1 * b * t21 - T(30) * t1 * c * t20) * in.w[3] - (T(1) / T(336)) * t1 * t19 * in.w[0];
  }
  const T g_factor = -T(7) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 43 +, 92 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 53 +, 103 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i8_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 67 +, 126 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Returns false where segment_compact_i8_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 126 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i8_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 51 +, 100 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 9, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 62 +, 112 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i8_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
    G_ab = M_exact[2] * in.w[1] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 84 +, 143 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + in.w[1] * M_exact[1];
    G_ap = in.w[1] * M_exact[4] + M_exact[3] * in.w[0];
    G_ab = M_exact[5] * in.w[1] + M_exact[4] * in.w[0];
  }
  const T g_factor = -T(8) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Returns false where segment_compact_i8_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 84 +, 143 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i8_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[3] + M_exact[4] * in.w[1];
    G_ab = M_exact[5] * in.w[1] + M_exact[4] * in.w[0];
  }
  const T g_factor = -T(8) * length * inv_R2;
  f = length * F;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 59 +, 108 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[0] * in.w[0] + in.w[2] * M_exact[2];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 71 +, 121 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i8_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + M_exact[0] * in.w[0] + M_exact[2] * in.w[2];
    G_ab = in.w[2] * M_exact[3] + in.w[0] * M_exact[1] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(8) * length * inv_R2;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 101 +, 160 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + M_exact[2] * in.w[2];
    G_ap = in.w[1] * M_exact[5] + M_exact[6] * in.w[2] + in.w[0] * M_exact[4];
    G_ab = in.w[0] * M_exact[5] + M_exact[6] * in.w[1] + M_exact[7] * in.w[2];
  }
  const T g_factor = -T(8) * length * inv_R2;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Returns false where segment_compact_i8_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 101 +, 160 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i8_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[0] * M_exact[0] + in.w[1] * M_exact[1];
    G_ap = in.w[1] * M_exact[5] + in.w[2] * M_exact[6] + M_exact[4] * in.w[0];
    G_ab = M_exact[5] * in.w[0] + in.w[1] * M_exact[6] + M_exact[7] * in.w[2];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 67 +, 116 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0] + in.w[2] * M_exact[2] + M_exact[3] * in.w[3];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 80 +, 130 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i8_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-6, -6, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + in.w[3] * M_exact[3] + in.w[2] * M_exact[2];
    G_ab = in.w[1] * M_exact[2] + in.w[2] * M_exact[3] + in.w[3] * M_exact[4] + in.w[0] * M_exact[1];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Operations: 118 +, 177 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i8_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[3] * M_exact[3] + in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + M_exact[1] * in.w[1];
    G_ap = M_exact[8] * in.w[3] + M_exact[5] * in.w[0] + M_exact[7] * in.w[2] + M_exact[6] * in.w[1];
    G_ab = in.w[0] * M_exact[6] + in.w[3] * M_exact[9] + M_exact[7] * in.w[1] + in.w[2] * M_exact[8];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(8/2) dt
/// Returns false where segment_compact_i8_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 118 +, 177 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i8_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 7>(-8, -6, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + M_exact[2] * in.w[2] + in.w[3] * M_exact[3];
    G_ap = M_exact[5] * in.w[0] + M_exact[8] * in.w[3] + M_exact[7] * in.w[2] + M_exact[6] * in.w[1];
    G_ab = in.w[0] * M_exact[6] + in.w[1] * M_exact[7] + M_exact[8] * in.w[2] + in.w[3] * M_exact[9];
  }
  const T g_factor = -T(8) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 42 +, 90 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2083 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * q1;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    F = -(T(1) / T(11)) * in.w[0] * (r1 * slope1 * t7 - slope0 * t10 * r0 - T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1)) / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t11 = q1 * q1;
    const T t12 = t11 * t11;
    const T t13 = q0 * q0;
    const T t14 = t13 * t13;
    const T t15 = t13 * q0;
    const T t16 = t11 * q1;
    F = (T(1) / T(1280)) * t0 * (T(128) * r1 * slope1 * t12 - T(128) * slope0 * t14 * r0 - T(3) * (T(48) * slope0 * t15 * r0 + T(7) * D * t0 * (T(5) * D * t0 * (T(2) * slope0 * q0 * r0 + T(3) * D * t0 * (slope0 * r0 - D * J1 - r1 * slope1) - T(2) * r1 * slope1 * q1) + T(8) * slope0 * t13 * r0 - T(8) * r1 * slope1 * t11) - T(48) * r1 * slope1 * t16) * D * t0) * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 45 +, 103 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2112 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t10 * q0;
    const T t12 = T(10) * (slope1 * t8 * r1 - t11 * r0 * slope0 - T(12) * a * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1)) * a * t5 + T(11) * slope1 * t7 * r1 - T(11) * t10 * r0 * slope0;
    G_ap = -(T(1) / T(99)) * in.w[0] * t5 * t12;
    G_ab = (T(1) / T(99)) * in.w[0] * (T(11) * t7 * r1 - t5 * t12 * b - T(11) * t10 * r0) * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t13 = q0 * q0;
    const T t14 = t13 * q0;
    const T t15 = q1 * q1;
    const T t16 = t15 * q1;
    const T t17 = T(7) * (T(8) * q0 * q0 * r0 * slope0 + T(5) * (T(3) * t0 * D * (r0 * slope0 - J1 * D - slope1 * r1) + T(2) * q0 * r0 * slope0 - T(2) * slope1 * q1 * r1) * t0 * D - T(8) * slope1 * q1 * q1 * r1) * t0 * D + T(48) * t14 * r0 * slope0 - T(48) * slope1 * t16 * r1;
    G_ap = -(T(1) / T(384)) * in.w[0] * t17 * t0;
    const T t18 = t13 * t13;
    const T t19 = t15 * t15;
    G_ab = -(T(1) / T(1152)) * in.w[0] * t0 * (T(3) * t17 * t0 * b + T(128) * t18 * r0 - T(128) * t19 * r1);
  }
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 47 +, 114 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2116 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-11 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = slope0 * t8 * r0 + T(12) * J_upward_compact<T>(-11, a, D, slope0, q0, slope1, q1) * a - slope1 * t11 * r1;
    F = (T(1) / T(11)) * t5 * t12 * in.w[0];
    const T t13 = T(11) * slope0 * t7 * r0 + T(10) * t5 * a * t12 - T(11) * slope1 * t10 * r1;
    G_ap = (T(1) / T(99)) * t5 * t13 * in.w[0];
    G_ab = (T(1) / T(99)) * (T(11) * t10 * r1 + t5 * b * t13 - T(11) * t7 * r0) * t0 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t14 = q0 * q0;
    const T t15 = t14 * t14;
    const T t16 = q1 * q1;
    const T t17 = t16 * q1;
    const T t18 = t14 * q0;
    const T t19 = T(48) * slope1 * t17 * r1 + T(7) * D * t0 * (T(8) * slope1 * t16 * r1 - T(5) * D * t0 * (T(2) * slope0 * q0 * r0 + T(3) * D * t0 * (slope0 * r0 - slope1 * r1 - D * J1) - T(2) * slope1 * q1 * r1) - T(8) * slope0 * t14 * r0) - T(48) * slope0 * t18 * r0;
    const T t20 = t16 * t16;
    F = -(T(1) / T(1280)) * (T(128) * slope0 * t15 * r0 - T(3) * t19 * D * t0 - T(128) * slope1 * t20 * r1) * t0 * in.w[0];
    G_ap = (T(1) / T(384)) * t19 * t0 * in.w[0];
    G_ab = (T(1) / T(1152)) * (T(128) * t20 * r1 + T(3) * t19 * t0 * b - T(128) * t15 * r0) * t0 * in.w[0];
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Returns false where segment_compact_i9_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 47 +, 114 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i9_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
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
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t7 * q1;
    const T t12 = T(48) * slope0 * t10 * r0 - T(7) * D * t2 * (T(5) * D * (T(3) * (D * J1 + r1 * slope1 - slope0 * r0) * D * t2 + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0) * t2 + T(8) * r1 * slope1 * t7 - T(8) * slope0 * t9 * r0) - T(48) * r1 * slope1 * t11;
    const T t13 = t9 * t9;
    F = (T(1) / T(1280)) * in.w[0] * (T(128) * r1 * slope1 * t8 - T(3) * D * t2 * t12 - T(128) * slope0 * t13 * r0) * t2;
    G_ap = -(T(1) / T(384)) * in.w[0] * t2 * t12;
    G_ab = -(T(1) / T(1152)) * in.w[0] * (T(128) * t13 * r0 + T(3) * b * t2 * t12 - T(128) * r1 * t8) * t2;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 45 +, 103 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2108 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t10 * t10;
    const T t12 = t6 * q1;
    const T t13 = t12 * t12;
    const T t14 = t9 * t9;
    const T t15 = t14 * q0;
    const T t16 = T(13) * r1 * slope1 * t8 - T(12) * (T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) + slope0 * t11 * r0 - r1 * slope1 * t13) * t5 * a - T(13) * slope0 * t15 * r0;
    F = -(T(1) / T(143)) * t5 * in.w[0] * t16 - (T(1) / T(143)) * t0 * (t5 * b * t16 + T(13) * t15 * r0 - T(13) * r1 * t8) * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = q1 * q1;
    const T t18 = t17 * q1;
    const T t19 = q0 * q0;
    const T t20 = t19 * q0;
    const T t21 = t17 * t17;
    const T t22 = t19 * t19;
    const T t23 = T(3) * D * t0 * (T(48) * r1 * slope1 * t18 + T(7) * D * t0 * (T(8) * r1 * slope1 * t17 - T(8) * slope0 * q0 * q0 * r0 - T(5) * D * t0 * (T(3) * D * t0 * (slope0 * r0 - D * J1 - r1 * slope1) + T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1)) - T(48) * slope0 * t20 * r0) + T(128) * r1 * slope1 * t21 - T(128) * slope0 * t22 * r0;
    const T t24 = t22 * q0;
    const T t25 = t21 * q1;
    F = (T(1) / T(1280)) * t0 * in.w[0] * t23 - (T(1) / T(14080)) * (T(1280) * t24 * r0 - T(1280) * r1 * t25 - T(11) * t0 * b * t23) * t0 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 51 +, 125 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2140 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[2] * in.w[1] + in.w[0] * M_flat[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * t6;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = t8 * q0;
    const T t12 = t11 * t11;
    const T t13 = t6 * q1;
    const T t14 = t13 * t13;
    const T t15 = t9 * q0;
    const T t16 = t7 * q1;
    const T t17 = T(12) * (T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t12 - t14 * r1 * slope1) * t10 * a + T(13) * r0 * slope0 * t15 - T(13) * t16 * r1 * slope1;
    const T t18 = T(143) * r0 * slope0 * t9 + T(10) * t10 * a * t17 - T(143) * t7 * r1 * slope1;
    const T t19 = T(143) * t7 * r1 + t18 * t10 * b - T(143) * r0 * t9;
    G_ap = (T(1) / T(1287)) * t1 * t19 * in.w[1] + (T(1) / T(1287)) * t18 * t10 * in.w[0];
    G_ab = (T(1) / T(1287)) * t1 * (T(9) * t10 * t17 + T(2) * t1 * b * t19 - t18 * t10 * c) * in.w[1] + (T(1) / T(1287)) * t1 * in.w[0] * t19;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = q1 * q1;
    const T t21 = t20 * t20;
    const T t22 = t20 * q1;
    const T t23 = q0 * q0;
    const T t24 = t23 * q0;
    const T t25 = T(48) * t22 * r1 * slope1 - T(7) * D * t1 * (T(5) * (T(3) * (r0 * slope0 - r1 * slope1 - J1 * D) * D * t1 + T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1) * D * t1 + T(8) * r0 * slope0 * q0 * q0 - T(8) * t20 * r1 * slope1) - T(48) * r0 * slope0 * t24;
    const T t26 = t23 * t23;
    const T t27 = T(128) * t21 * r1 + T(3) * t1 * b * t25 - T(128) * r0 * t26;
    G_ap = (T(1) / T(1152)) * t27 * t1 * in.w[1] + (T(1) / T(384)) * t1 * in.w[0] * t25;
    G_ab = (T(1) / T(1152)) * t27 * t1 * in.w[0] - (T(1) / T(11520)) * t1 * (T(9) * t1 * (T(128) * r0 * slope0 * t26 - T(3) * D * t1 * t25 - T(128) * t21 * r1 * slope1) + T(30) * t1 * t25 * c - T(20) * t27 * t1 * b) * in.w[1];
  }
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 54 +, 141 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2153 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = T(1) / D;
    const T t10 = q1 * q1;
    const T t11 = t10 * q1;
    const T t12 = t11 * t11;
    const T t13 = t6 * q0;
    const T t14 = t13 * t13;
    const T t15 = t10 * t10;
    const T t16 = t15 * q1;
    const T t17 = T(12) * t9 * a * (slope1 * t12 * r1 - t14 * r0 * slope0 - T(14) * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) * a) + T(13) * slope1 * t16 * r1 - T(13) * t8 * r0 * slope0;
    F = -(T(1) / T(143)) * t1 * in.w[1] * (T(13) * t8 * r0 + t9 * t17 * b - T(13) * t16 * r1) - (T(1) / T(143)) * t9 * in.w[0] * t17;
    const T t18 = T(143) * t7 * r0 * slope0 - T(143) * slope1 * t15 * r1 - T(10) * t9 * a * t17;
    const T t19 = T(143) * t7 * r0 - t9 * b * t18 - T(143) * t15 * r1;
    G_ap = (T(1) / T(1287)) * t9 * in.w[0] * t18 - (T(1) / T(1287)) * t1 * in.w[1] * t19;
    G_ab = -(T(1) / T(1287)) * (T(2) * t1 * b * t19 + c * t9 * t18 + T(9) * t9 * t17) * t1 * in.w[1] - (T(1) / T(1287)) * t1 * in.w[0] * t19;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = q0 * q0;
    const T t21 = t20 * t20;
    const T t22 = t20 * q0;
    const T t23 = q1 * q1;
    const T t24 = t23 * q1;
    const T t25 = T(7) * (T(8) * t20 * r0 * slope0 - T(8) * slope1 * q1 * q1 * r1 - T(5) * D * t1 * (T(2) * slope1 * q1 * r1 + T(3) * D * t1 * (slope1 * r1 + D * J1 - r0 * slope0) - T(2) * q0 * r0 * slope0)) * D * t1 + T(48) * t22 * r0 * slope0 - T(48) * slope1 * t24 * r1;
    const T t26 = t23 * t23;
    const T t27 = T(128) * t21 * r0 * slope0 + T(3) * D * t1 * t25 - T(128) * slope1 * t26 * r1;
    const T t28 = t21 * q0;
    const T t29 = t26 * q1;
    F = -(T(1) / T(14080)) * (T(11) * t27 * t1 * b + T(1280) * t28 * r0 - T(1280) * t29 * r1) * t1 * in.w[1] - (T(1) / T(1280)) * t27 * t1 * in.w[0];
    const T t30 = T(128) * t21 * r0 + T(3) * t1 * t25 * b - T(128) * t26 * r1;
    G_ap = -(T(1) / T(1152)) * t1 * t30 * in.w[1] - (T(1) / T(384)) * t1 * in.w[0] * t25;
    G_ab = (T(1) / T(11520)) * t1 * (T(30) * c * t1 * t25 - T(9) * t27 * t1 - T(20) * t1 * t30 * b) * in.w[1] - (T(1) / T(1152)) * t1 * in.w[0] * t30;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Returns false where segment_compact_i9_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 54 +, 140 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i9_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - t1 * t1 * a * a;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * q1;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = t5 * q1;
    const T t12 = t8 * q0;
    const T t13 = T(48) * slope1 * t11 * r1 + T(7) * D * (T(8) * slope1 * t5 * r1 - T(8) * slope0 * t8 * r0 - T(5) * (T(2) * slope0 * q0 * r0 + T(3) * (slope0 * r0 - slope1 * r1 - D * J1) * D * t0 - T(2) * slope1 * q1 * r1) * D * t0) * t0 - T(48) * slope0 * t12 * r0;
    const T t14 = T(128) * slope0 * t9 * r0 - T(3) * t13 * D * t0 - T(128) * slope1 * t6 * r1;
    F = (T(1) / T(14080)) * in.w[1] * (T(1280) * t7 * r1 - T(1280) * t10 * r0 - T(11) * t14 * t0 * b) * t0 - (T(1) / T(1280)) * t14 * t0 * in.w[0];
    const T t15 = T(128) * t6 * r1 + T(3) * t13 * t0 * b - T(128) * t9 * r0;
    G_ap = (T(1) / T(1152)) * in.w[1] * t0 * t15 + (T(1) / T(384)) * t13 * t0 * in.w[0];
    G_ab = (T(1) / T(1152)) * t0 * in.w[0] * t15 - (T(1) / T(11520)) * in.w[1] * (T(30) * c * t13 * t0 + T(9) * t14 * t0 - T(20) * t0 * b * t15) * t0;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 50 +, 122 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2118 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * q0;
    const T t8 = t7 * t7;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t10 * t10;
    const T t12 = slope0 * t8 * r0 + T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) - slope1 * t11 * r1;
    const T t13 = t6 * t6;
    const T t14 = t13 * q0;
    const T t15 = t9 * t9;
    const T t16 = t15 * q1;
    const T t17 = T(12) * a * t5 * t12 + T(13) * slope0 * t14 * r0 - T(13) * slope1 * t16 * r1;
    const T t18 = t5 * t17 * b + T(13) * t16 * r1 - T(13) * t14 * r0;
    F = (T(1) / T(143)) * t5 * t17 * in.w[0] + (T(1) / T(143)) * t18 * t0 * in.w[1] - (T(1) / T(143)) * t0 * in.w[2] * (t5 * t17 * c - T(2) * t18 * t0 * b - T(11) * t5 * t12);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t19 = q0 * q0;
    const T t20 = t19 * t19;
    const T t21 = q1 * q1;
    const T t22 = t21 * q1;
    const T t23 = t19 * q0;
    const T t24 = t21 * t21;
    const T t25 = T(128) * slope0 * t20 * r0 - T(3) * t0 * D * (T(48) * slope1 * t22 * r1 - T(7) * t0 * D * (T(5) * t0 * D * (T(2) * slope0 * q0 * r0 + T(3) * t0 * D * (slope0 * r0 - D * J1 - slope1 * r1) - T(2) * slope1 * q1 * r1) + T(8) * slope0 * t19 * r0 - T(8) * slope1 * t21 * r1) - T(48) * slope0 * t23 * r0) - T(128) * slope1 * t24 * r1;
    const T t26 = t20 * q0;
    const T t27 = t24 * q1;
    const T t28 = T(11) * t0 * t25 * b + T(1280) * t26 * r0 - T(1280) * t27 * r1;
    F = (T(1) / T(168960)) * t0 * in.w[2] * (T(132) * t0 * t25 * c - T(11) * t0 * (T(1280) * slope0 * t26 * r0 + T(11) * t0 * D * t25 - T(1280) * slope1 * t27 * r1) - T(24) * t0 * t28 * b) - (T(1) / T(1280)) * t0 * t25 * in.w[0] - (T(1) / T(14080)) * t0 * in.w[1] * t28;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 57 +, 149 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2159 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, root_minus_a * r1) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope1 * slope0;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ab = M_flat[2] * in.w[1] + M_flat[1] * in.w[0] + in.w[2] * M_flat[3];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t7 = T(1) / D;
    const T t8 = q1 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = t8 * q1;
    const T t12 = t11 * t11;
    const T t13 = q0 * q0;
    const T t14 = t13 * q0;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t16 * q0;
    const T t18 = T(13) * slope1 * t10 * r1 + T(12) * t7 * a * (slope1 * t12 * r1 - T(14) * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) * a - t15 * r0 * slope0) - T(13) * t17 * r0 * slope0;
    const T t19 = T(143) * slope1 * t9 * r1 + T(10) * t18 * t7 * a - T(143) * t16 * r0 * slope0;
    const T t20 = T(143) * t16 * r0 + b * t7 * t19 - T(143) * t9 * r1;
    const T t21 = c * t7 * t19 - T(2) * b * t2 * t20 - T(9) * t18 * t7;
    G_ap = (T(1) / T(1287)) * in.w[2] * t21 * t2 - (T(1) / T(1287)) * t2 * t20 * in.w[1] - (T(1) / T(1287)) * in.w[0] * t7 * t19;
    G_ab = (T(1) / T(1287)) * in.w[2] * (c * t2 * t20 + T(2) * b * t21 * t2 - T(9) * (T(13) * t17 * r0 + b * t18 * t7 - T(13) * t10 * r1) * t2) * t2 + (T(1) / T(1287)) * t21 * t2 * in.w[1] - (T(1) / T(1287)) * in.w[0] * t2 * t20;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q0 * q0;
    const T t23 = t22 * q0;
    const T t24 = q1 * q1;
    const T t25 = t24 * q1;
    const T t26 = T(7) * D * t2 * (T(8) * q0 * q0 * r0 * slope0 - T(8) * slope1 * q1 * q1 * r1 - T(5) * (T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t2 + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0) * D * t2) + T(48) * t23 * r0 * slope0 - T(48) * slope1 * t25 * r1;
    const T t27 = t24 * t24;
    const T t28 = t22 * t22;
    const T t29 = T(128) * slope1 * t27 * r1 - T(128) * t28 * r0 * slope0 - T(3) * t26 * D * t2;
    const T t30 = T(128) * t28 * r0 + T(3) * b * t26 * t2 - T(128) * t27 * r1;
    const T t31 = T(30) * c * t26 * t2 + T(9) * t29 * t2 - T(20) * b * t2 * t30;
    G_ap = (T(1) / T(11520)) * in.w[2] * t2 * t31 - (T(1) / T(1152)) * t2 * t30 * in.w[1] - (T(1) / T(384)) * t26 * in.w[0] * t2;
    const T t32 = t28 * q0;
    const T t33 = t27 * q1;
    G_ab = (T(1) / T(11520)) * t2 * in.w[1] * t31 + (T(1) / T(126720)) * in.w[2] * (T(110) * c * t2 * t30 + T(22) * b * t2 * t31 - T(9) * t2 * (T(1280) * t32 * r0 - T(11) * b * t29 * t2 - T(1280) * t33 * r1)) * t2 - (T(1) / T(1152)) * in.w[0] * t2 * t30;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 63 +, 174 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2176 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ap = M_flat[4] * in.w[0] + M_flat[6] * in.w[2] + M_flat[5] * in.w[1];
    G_ab = in.w[0] * M_flat[5] + M_flat[6] * in.w[1] + in.w[2] * M_flat[7];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * q1;
    const T t12 = t11 * t11;
    const T t13 = T(14) * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) * a + slope0 * t9 * r0 - r1 * slope1 * t12;
    const T t14 = T(1) / D;
    const T t15 = t7 * t7;
    const T t16 = t15 * q0;
    const T t17 = t10 * t10;
    const T t18 = t17 * q1;
    const T t19 = T(13) * slope0 * t16 * r0 + T(12) * t13 * a * t14 - T(13) * r1 * slope1 * t18;
    const T t20 = T(13) * t16 * r0 - b * t19 * t14 - T(13) * r1 * t18;
    F = (T(1) / T(143)) * in.w[2] * (T(11) * t13 * t14 - t19 * c * t14 - T(2) * b * t2 * t20) * t2 + (T(1) / T(143)) * t19 * in.w[0] * t14 - (T(1) / T(143)) * t2 * t20 * in.w[1];
    const T t21 = T(10) * t19 * a * t14 + T(143) * slope0 * t15 * r0 - T(143) * r1 * slope1 * t17;
    const T t22 = T(143) * t15 * r0 - T(143) * r1 * t17 - b * t21 * t14;
    const T t23 = T(2) * b * t22 * t2 + c * t21 * t14 - T(9) * t19 * t14;
    G_ap = (T(1) / T(1287)) * t21 * in.w[0] * t14 - (T(1) / T(1287)) * in.w[2] * t23 * t2 - (T(1) / T(1287)) * t22 * t2 * in.w[1];
    G_ab = -(T(1) / T(1287)) * t23 * t2 * in.w[1] - (T(1) / T(1287)) * (T(9) * t2 * t20 + T(2) * b * t23 * t2 - c * t22 * t2) * in.w[2] * t2 - (T(1) / T(1287)) * in.w[0] * t22 * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t24 = q0 * q0;
    const T t25 = t24 * t24;
    const T t26 = t25 * q0;
    const T t27 = q1 * q1;
    const T t28 = t27 * q1;
    const T t29 = t24 * q0;
    const T t30 = T(48) * r1 * slope1 * t28 - T(48) * slope0 * t29 * r0 - T(7) * (T(8) * slope0 * t24 * r0 - T(8) * r1 * slope1 * t27 - T(5) * (T(2) * r1 * slope1 * q1 - T(3) * t2 * (slope0 * r0 - r1 * slope1 - D * J1) * D - T(2) * slope0 * q0 * r0) * t2 * D) * t2 * D;
    const T t31 = t27 * t27;
    const T t32 = T(128) * slope0 * t25 * r0 - T(3) * t2 * D * t30 - T(128) * r1 * slope1 * t31;
    const T t33 = t31 * q1;
    const T t34 = T(1280) * t26 * r0 + T(11) * b * t2 * t32 - T(1280) * r1 * t33;
    F = -(T(1) / T(14080)) * t34 * t2 * in.w[1] - (T(1) / T(1280)) * in.w[0] * t2 * t32 - (T(1) / T(168960)) * in.w[2] * (T(24) * t34 * b * t2 + T(11) * (T(11) * t2 * D * t32 + T(1280) * slope0 * t26 * r0 - T(1280) * r1 * slope1 * t33) * t2 - T(132) * c * t2 * t32) * t2;
    const T t35 = T(128) * t25 * r0 - T(128) * r1 * t31 - T(3) * b * t2 * t30;
    const T t36 = T(9) * t2 * t32 + T(30) * c * t2 * t30 + T(20) * b * t35 * t2;
    G_ap = (T(1) / T(384)) * in.w[0] * t2 * t30 - (T(1) / T(1152)) * t35 * t2 * in.w[1] - (T(1) / T(11520)) * t36 * in.w[2] * t2;
    G_ab = -(T(1) / T(126720)) * in.w[2] * (T(9) * t34 * t2 + T(22) * b * t36 * t2 - T(110) * c * t35 * t2) * t2 - (T(1) / T(11520)) * t36 * t2 * in.w[1] - (T(1) / T(1152)) * t35 * in.w[0] * t2;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Returns false where segment_compact_i9_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 63 +, 174 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i9_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1] + M_flat[2] * in.w[2];
    G_ap = M_flat[6] * in.w[2] + in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
    G_ab = in.w[0] * M_flat[5] + in.w[2] * M_flat[7] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * t9;
    const T t11 = t9 * q0;
    const T t12 = t7 * q1;
    const T t13 = T(48) * r0 * slope0 * t11 - T(48) * t12 * r1 * slope1 - T(7) * D * (T(8) * t7 * r1 * slope1 + T(5) * (T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t2 + T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0) * D * t2 - T(8) * r0 * slope0 * t9) * t2;
    const T t14 = T(128) * t8 * r1 * slope1 - T(128) * r0 * slope0 * t10 - T(3) * D * t2 * t13;
    const T t15 = t8 * q1;
    const T t16 = t10 * q0;
    const T t17 = T(11) * b * t14 * t2 + T(1280) * t15 * r1 - T(1280) * r0 * t16;
    F = (T(1) / T(14080)) * in.w[1] * t17 * t2 + (T(1) / T(168960)) * in.w[2] * (T(24) * t17 * b * t2 + T(11) * (T(11) * t14 * D * t2 + T(1280) * t15 * r1 * slope1 - T(1280) * r0 * slope0 * t16) * t2 - T(132) * c * t14 * t2) * t2 + (T(1) / T(1280)) * in.w[0] * t14 * t2;
    const T t18 = T(128) * t8 * r1 - T(3) * b * t2 * t13 - T(128) * r0 * t10;
    const T t19 = T(30) * c * t2 * t13 + T(9) * t14 * t2 + T(20) * t18 * b * t2;
    G_ap = (T(1) / T(11520)) * in.w[2] * t19 * t2 + (T(1) / T(1152)) * in.w[1] * t18 * t2 - (T(1) / T(384)) * in.w[0] * t2 * t13;
    G_ab = (T(1) / T(126720)) * (T(9) * t17 * t2 + T(22) * b * t19 * t2 - T(110) * t18 * c * t2) * in.w[2] * t2 + (T(1) / T(1152)) * t18 * in.w[0] * t2 + (T(1) / T(11520)) * in.w[1] * t19 * t2;
  }
  const T g_factor = -T(9) * length * inv_R2;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 55 +, 142 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2150 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[1] * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * t5;
    const T t7 = t6 * q0;
    const T t8 = t5 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * q1;
    const T t15 = T(1) / D;
    const T t16 = T(15) * r0 * slope0 * t9 + T(14) * (r0 * slope0 * t10 + T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) - r1 * slope1 * t14) * t15 * a - T(15) * r1 * slope1 * t13;
    const T t17 = t11 * t11;
    const T t18 = t17 * q1;
    const T t19 = T(65) * r0 * slope0 * t7 + T(4) * t16 * t15 * a - T(65) * r1 * slope1 * t18;
    const T t20 = T(65) * r1 * t18 + t19 * t15 * b - T(65) * r0 * t7;
    const T t21 = T(3) * c * t19 * t15 - T(11) * t16 * t15 - T(6) * t0 * t20 * b;
    F = (T(1) / T(715)) * t19 * t15 * in.w[0] + (T(1) / T(715)) * in.w[1] * t0 * t20 - (T(1) / T(2145)) * (T(2) * t21 * t0 * b + T(3) * c * t0 * t20 - T(11) * (T(15) * r1 * t13 + t16 * t15 * b - T(15) * r0 * t9) * t0) * t0 * in.w[3] - (T(1) / T(2145)) * t21 * t0 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * q1;
    const T t25 = q0 * q0;
    const T t26 = t25 * t25;
    const T t27 = t26 * q0;
    const T t28 = t22 * q1;
    const T t29 = t25 * q0;
    const T t30 = T(128) * r0 * slope0 * t26 - T(3) * D * t0 * (T(48) * r1 * slope1 * t28 + T(7) * D * t0 * (T(8) * r1 * slope1 * t22 + T(5) * D * t0 * (T(2) * r1 * slope1 * q1 + T(3) * D * t0 * (r1 * slope1 + D * J1 - r0 * slope0) - T(2) * r0 * slope0 * q0) - T(8) * r0 * slope0 * t25) - T(48) * r0 * slope0 * t29) - T(128) * r1 * slope1 * t23;
    const T t31 = T(1280) * r1 * t24 - T(1280) * r0 * t27 - T(11) * t0 * t30 * b;
    const T t32 = T(11) * D * t0 * t30 + T(1280) * r0 * slope0 * t27 - T(1280) * r1 * slope1 * t24;
    const T t33 = T(11) * t32 * t0 - T(24) * t0 * t31 * b - T(132) * c * t0 * t30;
    const T t34 = t29 * t29;
    const T t35 = t28 * t28;
    F = (T(1) / T(14080)) * in.w[1] * t0 * t31 - (T(1) / T(168960)) * t0 * in.w[2] * t33 - (T(1) / T(2196480)) * (T(156) * c * t0 * t31 + T(26) * t0 * t33 * b + T(11) * t0 * (T(13) * t32 * t0 * b + T(15360) * r0 * t34 - T(15360) * r1 * t35)) * t0 * in.w[3] - (T(1) / T(1280)) * t0 * t30 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 65 +, 179 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2196 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i9_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-7, -7, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[3] * M_flat[3] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1] + M_flat[4] * in.w[3] + M_flat[3] * in.w[2] + M_flat[2] * in.w[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t6 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * q1;
    const T t15 = T(15) * slope0 * t9 * r0 + T(14) * t5 * a * (T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a + slope0 * t10 * r0 - slope1 * t14 * r1) - T(15) * slope1 * t13 * r1;
    const T t16 = t7 * q0;
    const T t17 = t11 * t11;
    const T t18 = t17 * q1;
    const T t19 = T(4) * t15 * t5 * a + T(65) * slope0 * t16 * r0 - T(65) * slope1 * t18 * r1;
    const T t20 = T(143) * slope0 * t7 * r0 + T(2) * t5 * a * t19 - T(143) * slope1 * t17 * r1;
    const T t21 = T(143) * t7 * r0 - T(143) * t17 * r1 - t5 * t20 * b;
    const T t22 = T(9) * t5 * t19 - T(5) * c * t5 * t20 - T(10) * t21 * t0 * b;
    const T t23 = T(65) * t16 * r0 - t5 * t19 * b - T(65) * t18 * r1;
    const T t24 = T(2) * t22 * t0 * b + T(5) * c * t21 * t0 - T(9) * t0 * t23;
    G_ap = (T(1) / T(1287)) * in.w[0] * t5 * t20 + (T(1) / T(6435)) * t22 * t0 * in.w[2] + (T(1) / T(6435)) * in.w[3] * t0 * t24 - (T(1) / T(1287)) * t21 * in.w[1] * t0;
    G_ab = (T(1) / T(6435)) * t22 * in.w[1] * t0 + (T(1) / T(6435)) * in.w[3] * t0 * (T(2) * t0 * t24 * b - t22 * c * t0 - T(3) * (T(6) * t0 * t23 * b + T(3) * c * t5 * t19 - T(11) * t15 * t5) * t0) + (T(1) / T(6435)) * t0 * in.w[2] * t24 - (T(1) / T(1287)) * in.w[0] * t21 * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t25 = q1 * q1;
    const T t26 = t25 * q1;
    const T t27 = q0 * q0;
    const T t28 = t27 * q0;
    const T t29 = T(48) * slope1 * t26 * r1 + T(7) * D * t0 * (T(8) * slope1 * t25 * r1 - T(5) * (T(2) * slope0 * q0 * r0 + T(3) * D * t0 * (slope0 * r0 - J1 * D - slope1 * r1) - T(2) * slope1 * q1 * r1) * D * t0 - T(8) * slope0 * q0 * q0 * r0) - T(48) * slope0 * t28 * r0;
    const T t30 = t25 * t25;
    const T t31 = t27 * t27;
    const T t32 = T(3) * t29 * t0 * b + T(128) * t30 * r1 - T(128) * t31 * r0;
    const T t33 = T(128) * slope0 * t31 * r0 - T(3) * t29 * D * t0 - T(128) * slope1 * t30 * r1;
    const T t34 = T(9) * t0 * t33 + T(30) * c * t29 * t0 - T(20) * t32 * t0 * b;
    const T t35 = t31 * q0;
    const T t36 = t30 * q1;
    const T t37 = T(1280) * t35 * r0 + T(11) * t0 * t33 * b - T(1280) * t36 * r1;
    const T t38 = T(22) * t34 * t0 * b + T(9) * t0 * t37 + T(110) * t32 * c * t0;
    G_ap = (T(1) / T(384)) * in.w[0] * t29 * t0 + (T(1) / T(1152)) * t32 * in.w[1] * t0 - (T(1) / T(11520)) * t34 * t0 * in.w[2] - (T(1) / T(126720)) * in.w[3] * t0 * t38;
    G_ab = (T(1) / T(1152)) * in.w[0] * t32 * t0 - (T(1) / T(506880)) * in.w[3] * t0 * (T(3) * (T(11) * (T(11) * D * t0 * t33 + T(1280) * slope0 * t35 * r0 - T(1280) * slope1 * t36 * r1) * t0 + T(24) * t0 * t37 * b - T(132) * c * t0 * t33) * t0 + T(8) * t0 * t38 * b - T(44) * t34 * c * t0) - (T(1) / T(11520)) * t34 * in.w[1] * t0 - (T(1) / T(126720)) * t0 * in.w[2] * t38;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Operations: 72 +, 209 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2223 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i9_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
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
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[2] * in.w[2] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[5] + in.w[3] * M_flat[8] + in.w[2] * M_flat[7] + M_flat[6] * in.w[1];
    G_ab = M_flat[9] * in.w[3] + in.w[2] * M_flat[8] + M_flat[6] * in.w[0] + M_flat[7] * in.w[1];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * q1;
    const T t10 = q0 * q0;
    const T t11 = t10 * t10;
    const T t12 = t11 * q0;
    const T t13 = t10 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * q0;
    const T t16 = t7 * q1;
    const T t17 = t16 * t16;
    const T t18 = t17 * q1;
    const T t19 = T(1) / D;
    const T t20 = T(14) * (r0 * slope0 * t15 + T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a - t18 * r1 * slope1) * a * t19 + T(15) * r0 * slope0 * t14 - T(15) * t17 * r1 * slope1;
    const T t21 = T(65) * t9 * r1 * slope1 - T(65) * r0 * slope0 * t12 - T(4) * t20 * a * t19;
    const T t22 = t21 * b * t19 + T(65) * r0 * t12 - T(65) * t9 * r1;
    const T t23 = T(3) * t21 * c * t19 + T(11) * t20 * t19 - T(6) * t22 * b * t2;
    F = (T(1) / T(2145)) * in.w[2] * t23 * t2 - (T(1) / T(2145)) * (T(11) * (T(15) * r0 * t14 - T(15) * t17 * r1 - b * t20 * t19) * t2 - T(3) * t22 * c * t2 - T(2) * b * t23 * t2) * in.w[3] * t2 - (T(1) / T(715)) * t22 * in.w[1] * t2 - (T(1) / T(715)) * t21 * in.w[0] * t19;
    const T t24 = T(143) * t8 * r1 * slope1 + T(2) * t21 * a * t19 - T(143) * r0 * slope0 * t11;
    const T t25 = t24 * b * t19 + T(143) * r0 * t11 - T(143) * t8 * r1;
    const T t26 = T(9) * t21 * t19 + T(10) * b * t25 * t2 - T(5) * t24 * c * t19;
    const T t27 = T(5) * c * t25 * t2 - T(2) * b * t26 * t2 - T(9) * t22 * t2;
    G_ap = (T(1) / T(6435)) * in.w[3] * t2 * t27 - (T(1) / T(1287)) * t25 * in.w[1] * t2 - (T(1) / T(6435)) * in.w[2] * t26 * t2 - (T(1) / T(1287)) * t24 * in.w[0] * t19;
    G_ab = (T(1) / T(6435)) * in.w[2] * t2 * t27 + (T(1) / T(6435)) * in.w[3] * (T(3) * t23 * t2 + T(2) * b * t2 * t27 + t26 * c * t2) * t2 - (T(1) / T(1287)) * in.w[0] * t25 * t2 - (T(1) / T(6435)) * t26 * in.w[1] * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t28 = q0 * q0;
    const T t29 = t28 * q0;
    const T t30 = q1 * q1;
    const T t31 = t30 * q1;
    const T t32 = T(48) * r0 * slope0 * t29 - T(7) * (T(8) * q1 * q1 * r1 * slope1 + T(5) * (T(2) * q1 * r1 * slope1 + T(3) * (D * J1 + r1 * slope1 - r0 * slope0) * t2 * D - T(2) * r0 * slope0 * q0) * t2 * D - T(8) * r0 * slope0 * t28) * t2 * D - T(48) * t31 * r1 * slope1;
    const T t33 = t28 * t28;
    const T t34 = t30 * t30;
    const T t35 = T(3) * t32 * t2 * D + T(128) * r0 * slope0 * t33 - T(128) * t34 * r1 * slope1;
    const T t36 = t34 * q1;
    const T t37 = t33 * q0;
    const T t38 = T(1280) * t36 * r1 * slope1 - T(1280) * r0 * slope0 * t37 - T(11) * t35 * t2 * D;
    const T t39 = T(11) * b * t35 * t2 + T(1280) * r0 * t37 - T(1280) * t36 * r1;
    const T t40 = T(132) * t35 * c * t2 + T(11) * t38 * t2 - T(24) * b * t2 * t39;
    const T t41 = t29 * t29;
    const T t42 = t31 * t31;
    F = (T(1) / T(168960)) * t40 * in.w[2] * t2 - (T(1) / T(14080)) * in.w[1] * t2 * t39 - (T(1) / T(1280)) * in.w[0] * t35 * t2 - (T(1) / T(2196480)) * (T(11) * (T(15360) * r0 * t41 - T(13) * b * t38 * t2 - T(15360) * t42 * r1) * t2 - T(156) * c * t2 * t39 - T(26) * t40 * b * t2) * in.w[3] * t2;
    const T t43 = T(3) * b * t32 * t2 + T(128) * r0 * t33 - T(128) * t34 * r1;
    const T t44 = T(9) * t35 * t2 + T(20) * b * t43 * t2 - T(30) * t32 * c * t2;
    const T t45 = T(22) * b * t44 * t2 + T(9) * t2 * t39 - T(110) * c * t43 * t2;
    G_ap = -(T(1) / T(1152)) * t43 * in.w[1] * t2 - (T(1) / T(126720)) * in.w[3] * t45 * t2 - (T(1) / T(384)) * t32 * in.w[0] * t2 - (T(1) / T(11520)) * in.w[2] * t44 * t2;
    G_ab = (T(1) / T(506880)) * (T(44) * t44 * c * t2 + T(3) * t40 * t2 - T(8) * b * t45 * t2) * in.w[3] * t2 - (T(1) / T(11520)) * t44 * in.w[1] * t2 - (T(1) / T(1152)) * in.w[0] * t43 * t2 - (T(1) / T(126720)) * in.w[2] * t45 * t2;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(9/2) dt
/// Returns false where segment_compact_i9_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 72 +, 209 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i9_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-9, -7, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[6] * in.w[1] + in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + M_flat[8] * in.w[3];
    G_ab = M_flat[8] * in.w[2] + in.w[3] * M_flat[9] + M_flat[6] * in.w[0] + M_flat[7] * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * q1;
    const T t10 = t7 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = T(7) * D * t2 * (T(8) * t7 * r1 * slope1 + T(5) * D * t2 * (T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0 - T(3) * D * t2 * (r0 * slope0 - D * J1 - r1 * slope1)) - T(8) * r0 * slope0 * q0 * q0) + T(48) * t10 * r1 * slope1 - T(48) * r0 * slope0 * t12;
    const T t14 = t11 * t11;
    const T t15 = T(128) * t8 * r1 * slope1 + T(3) * D * t2 * t13 - T(128) * r0 * slope0 * t14;
    const T t16 = t14 * q0;
    const T t17 = T(1280) * t9 * r1 * slope1 + T(11) * D * t2 * t15 - T(1280) * r0 * slope0 * t16;
    const T t18 = T(1280) * r0 * t16 - T(1280) * t9 * r1 - T(11) * t2 * b * t15;
    const T t19 = T(11) * t2 * t17 - T(132) * t2 * t15 * c - T(24) * t2 * b * t18;
    const T t20 = t12 * t12;
    const T t21 = t10 * t10;
    F = (T(1) / T(2196480)) * t2 * in.w[3] * (T(26) * t2 * b * t19 + T(156) * t2 * t18 * c - T(11) * t2 * (T(15360) * r0 * t20 - T(15360) * t21 * r1 - T(13) * t2 * b * t17)) + (T(1) / T(168960)) * in.w[2] * t2 * t19 + (T(1) / T(1280)) * t2 * in.w[0] * t15 - (T(1) / T(14080)) * t2 * t18 * in.w[1];
    const T t22 = T(128) * r0 * t14 - T(3) * t2 * b * t13 - T(128) * t8 * r1;
    const T t23 = T(20) * t2 * b * t22 + T(30) * t2 * c * t13 - T(9) * t2 * t15;
    const T t24 = T(9) * t2 * t18 + T(22) * t2 * t23 * b - T(110) * t2 * c * t22;
    G_ap = (T(1) / T(384)) * t2 * in.w[0] * t13 - (T(1) / T(11520)) * in.w[2] * t2 * t23 - (T(1) / T(126720)) * t2 * in.w[3] * t24 - (T(1) / T(1152)) * t2 * in.w[1] * t22;
    G_ab = (T(1) / T(506880)) * (T(44) * t2 * t23 * c + T(3) * t2 * t19 - T(8) * t2 * b * t24) * t2 * in.w[3] - (T(1) / T(1152)) * t2 * in.w[0] * t22 - (T(1) / T(11520)) * t2 * t23 * in.w[1] - (T(1) / T(126720)) * in.w[2] * t2 * t24;
  }
  const T g_factor = -T(9) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 43 +, 99 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-10, -10, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 53 +, 110 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i10_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 67 +, 133 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(10) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Returns false where segment_compact_i10_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 133 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i10_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 51 +, 107 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 11, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-10, -10, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 62 +, 119 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i10_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
    G_ab = M_exact[2] * in.w[1] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 84 +, 150 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ap = M_exact[3] * in.w[0] + M_exact[4] * in.w[1];
    G_ab = M_exact[4] * in.w[0] + M_exact[5] * in.w[1];
  }
  const T g_factor = -T(10) * length * inv_R2;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Returns false where segment_compact_i10_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 84 +, 150 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i10_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
    G_ap = M_exact[4] * in.w[1] + in.w[0] * M_exact[3];
    G_ab = in.w[1] * M_exact[5] + in.w[0] * M_exact[4];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 59 +, 115 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-10, -10, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + M_exact[0] * in.w[0] + in.w[1] * M_exact[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 71 +, 128 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i10_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-8, -8, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + M_exact[0] * in.w[0];
    G_ab = M_exact[1] * in.w[0] + M_exact[3] * in.w[2] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(10) * length * inv_R2;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 101 +, 167 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[4] + M_exact[6] * in.w[2] + in.w[1] * M_exact[5];
    G_ab = M_exact[7] * in.w[2] + M_exact[6] * in.w[1] + in.w[0] * M_exact[5];
  }
  const T g_factor = -T(10) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Returns false where segment_compact_i10_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 101 +, 167 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i10_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 7>(-10, -8, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0];
    G_ap = in.w[1] * M_exact[5] + M_exact[4] * in.w[0] + in.w[2] * M_exact[6];
    G_ab = in.w[1] * M_exact[6] + M_exact[5] * in.w[0] + M_exact[7] * in.w[2];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 67 +, 123 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-10, -10, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + M_exact[0] * in.w[0] + in.w[3] * M_exact[3] + M_exact[1] * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 104 +, 182 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i10_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 10>(-8, -8, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[3] * M_exact[3] + in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + M_exact[0] * in.w[0];
    G_ab = M_exact[1] * in.w[0] + in.w[1] * M_exact[2] + M_exact[4] * in.w[3] + in.w[2] * M_exact[3];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Operations: 157 +, 247 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i10_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-10, -8, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + M_exact[1] * in.w[1] + in.w[0] * M_exact[0] + in.w[3] * M_exact[3];
    G_ap = M_exact[6] * in.w[1] + M_exact[7] * in.w[2] + M_exact[5] * in.w[0] + M_exact[8] * in.w[3];
    G_ab = in.w[0] * M_exact[6] + in.w[3] * M_exact[9] + M_exact[7] * in.w[1] + in.w[2] * M_exact[8];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(10/2) dt
/// Returns false where segment_compact_i10_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 157 +, 247 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i10_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-10, -8, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[2] * in.w[2] + M_exact[3] * in.w[3] + in.w[0] * M_exact[0];
    G_ap = M_exact[8] * in.w[3] + M_exact[5] * in.w[0] + M_exact[6] * in.w[1] + M_exact[7] * in.w[2];
    G_ab = in.w[2] * M_exact[8] + in.w[0] * M_exact[6] + M_exact[9] * in.w[3] + in.w[1] * M_exact[7];
  }
  const T g_factor = -T(10) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 44 +, 101 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2085 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = t6 * t6;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t9 * t9;
    F = (T(1) / T(13)) * in.w[0] * (slope0 * t7 * r0 + T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) - r1 * slope1 * t10) / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t11 = q0 * q0;
    const T t12 = t11 * t11;
    const T t13 = q1 * q1;
    const T t14 = t13 * q1;
    const T t15 = t11 * q0;
    const T t16 = t13 * t13;
    const T t17 = t12 * q0;
    const T t18 = t16 * q1;
    F = -(T(1) / T(15360)) * t0 * (T(11) * D * t0 * (T(128) * slope0 * t12 * r0 - T(3) * D * t0 * (T(48) * r1 * slope1 * t14 + T(7) * D * (T(8) * r1 * slope1 * t13 - T(5) * D * t0 * (T(2) * slope0 * q0 * r0 + T(3) * D * t0 * (slope0 * r0 - r1 * slope1 - D * J1) - T(2) * r1 * slope1 * q1) - T(8) * slope0 * t11 * r0) * t0 - T(48) * slope0 * t15 * r0) - T(128) * r1 * slope1 * t16) + T(1280) * slope0 * t17 * r0 - T(1280) * r1 * slope1 * t18) * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 47 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2118 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = t6 * q0;
    const T t10 = t9 * t9;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t11 * t11;
    const T t15 = t14 * q1;
    const T t16 = T(13) * r0 * slope0 * t8 + T(12) * t5 * a * (r0 * slope0 * t10 + T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) - r1 * slope1 * t13) - T(13) * r1 * slope1 * t15;
    G_ap = (T(1) / T(143)) * t5 * t16 * in.w[0];
    G_ab = (T(1) / T(143)) * (T(13) * r1 * t15 + t5 * t16 * b - T(13) * r0 * t8) * t0 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = q0 * q0;
    const T t18 = t17 * t17;
    const T t19 = q1 * q1;
    const T t20 = t19 * t19;
    const T t21 = t19 * q1;
    const T t22 = t17 * q0;
    const T t23 = T(128) * r0 * slope0 * t18 - T(128) * r1 * slope1 * t20 - T(3) * D * t0 * (T(48) * r1 * slope1 * t21 + T(7) * D * (T(8) * r1 * slope1 * t19 + T(5) * D * t0 * (T(2) * r1 * slope1 * q1 + T(3) * D * (D * J1 + r1 * slope1 - r0 * slope0) * t0 - T(2) * r0 * slope0 * q0) - T(8) * r0 * slope0 * t17) * t0 - T(48) * r0 * slope0 * t22);
    G_ap = -(T(1) / T(1280)) * t23 * t0 * in.w[0];
    const T t24 = t20 * q1;
    const T t25 = t18 * q0;
    G_ab = (T(1) / T(14080)) * t0 * (T(1280) * r1 * t24 - T(11) * t23 * t0 * b - T(1280) * r0 * t25) * in.w[0];
  }
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 49 +, 125 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2122 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-13 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * q0;
    const T t8 = t7 * t7;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t10 * t10;
    const T t12 = slope0 * t8 * r0 + T(14) * a * J_upward_compact<T>(-13, a, D, slope0, q0, slope1, q1) - slope1 * t11 * r1;
    F = (T(1) / T(13)) * t5 * t12 * in.w[0];
    const T t13 = t6 * t6;
    const T t14 = t13 * q0;
    const T t15 = t9 * t9;
    const T t16 = t15 * q1;
    const T t17 = T(13) * slope0 * t14 * r0 + T(12) * t5 * a * t12 - T(13) * slope1 * t16 * r1;
    G_ap = (T(1) / T(143)) * t5 * t17 * in.w[0];
    G_ab = -(T(1) / T(143)) * (T(13) * t14 * r0 - T(13) * t16 * r1 - t5 * t17 * b) * t0 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t18 = q0 * q0;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = q1 * q1;
    const T t22 = t21 * t21;
    const T t23 = t21 * q1;
    const T t24 = t18 * q0;
    const T t25 = T(128) * slope0 * t19 * r0 - T(128) * slope1 * t22 * r1 - T(3) * (T(48) * slope1 * t23 * r1 + T(7) * D * t0 * (T(8) * slope1 * t21 * r1 - T(8) * slope0 * t18 * r0 - T(5) * (T(3) * D * t0 * (slope0 * r0 - slope1 * r1 - D * J1) + T(2) * slope0 * q0 * r0 - T(2) * slope1 * q1 * r1) * D * t0) - T(48) * slope0 * t24 * r0) * D * t0;
    const T t26 = t22 * q1;
    F = -(T(1) / T(15360)) * t0 * (T(1280) * slope0 * t20 * r0 + T(11) * t25 * D * t0 - T(1280) * slope1 * t26 * r1) * in.w[0];
    G_ap = -(T(1) / T(1280)) * t25 * t0 * in.w[0];
    G_ab = -(T(1) / T(14080)) * t0 * in.w[0] * (T(1280) * t20 * r0 + T(11) * t25 * t0 * b - T(1280) * t26 * r1);
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Returns false where segment_compact_i11_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 49 +, 125 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i11_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q0 * q0;
    const T t6 = t5 * t5;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t5 * q0;
    const T t10 = t7 * t7;
    const T t11 = T(128) * slope0 * t6 * r0 - T(3) * D * t0 * (T(48) * r1 * slope1 * t8 + T(7) * D * t0 * (T(8) * r1 * slope1 * t7 - T(8) * slope0 * t5 * r0 - T(5) * (T(3) * D * t0 * (slope0 * r0 - r1 * slope1 - D * J1) + T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1) * D * t0) - T(48) * slope0 * t9 * r0) - T(128) * r1 * slope1 * t10;
    const T t12 = t6 * q0;
    const T t13 = t10 * q1;
    F = -(T(1) / T(15360)) * in.w[0] * t0 * (T(11) * t11 * D * t0 + T(1280) * slope0 * t12 * r0 - T(1280) * r1 * slope1 * t13);
    G_ap = -(T(1) / T(1280)) * in.w[0] * t11 * t0;
    G_ab = -(T(1) / T(14080)) * in.w[0] * t0 * (T(1280) * t12 * r0 + T(11) * t11 * t0 * b - T(1280) * r1 * t13);
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 47 +, 113 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2109 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * q1;
    const T t7 = t6 * t6;
    const T t8 = q0 * q0;
    const T t9 = t8 * q0;
    const T t10 = t9 * t9;
    const T t11 = T(1) / D;
    const T t12 = t7 * q1;
    const T t13 = t10 * q0;
    const T t14 = T(15) * r1 * slope1 * t7 + T(14) * t11 * (r1 * slope1 * t12 - T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a - slope0 * t13 * r0) * a - T(15) * slope0 * t10 * r0;
    F = (T(1) / T(195)) * t0 * (T(15) * r1 * t7 - T(15) * t10 * r0 - t11 * t14 * b) * in.w[1] - (T(1) / T(195)) * t11 * in.w[0] * t14;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t15 = q1 * q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * q1;
    const T t18 = q0 * q0;
    const T t19 = t18 * t18;
    const T t20 = t18 * q0;
    const T t21 = t15 * q1;
    const T t22 = t19 * q0;
    const T t23 = T(1280) * r1 * slope1 * t17 + T(11) * D * (T(128) * r1 * slope1 * t16 - T(128) * slope0 * t19 * r0 - T(3) * D * t0 * (T(7) * D * t0 * (T(8) * slope0 * t18 * r0 - T(8) * r1 * slope1 * t15 - T(5) * D * t0 * (T(3) * D * t0 * (D * J1 + r1 * slope1 - slope0 * r0) + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0)) + T(48) * slope0 * t20 * r0 - T(48) * r1 * slope1 * t21)) * t0 - T(1280) * slope0 * t22 * r0;
    const T t24 = t21 * t21;
    const T t25 = t20 * t20;
    F = (T(1) / T(15360)) * t0 * in.w[0] * t23 + (T(1) / T(199680)) * t0 * (T(15360) * r1 * t24 + T(13) * t0 * b * t23 - T(15360) * t25 * r0) * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 53 +, 135 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2146 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(t0, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -a * a * t2 * t2 - D;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[0] * M_flat[1] + M_flat[2] * in.w[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = q1 * q1;
    const T t11 = t10 * q1;
    const T t12 = t11 * t11;
    const T t13 = t7 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * q0;
    const T t16 = t12 * q1;
    const T t17 = T(15) * t12 * r1 * slope1 - T(15) * r0 * slope0 * t14 - T(14) * t6 * a * (T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) + r0 * slope0 * t15 - t16 * r1 * slope1);
    const T t18 = t10 * t10;
    const T t19 = t18 * q1;
    const T t20 = T(65) * r0 * slope0 * t9 - T(4) * t6 * a * t17 - T(65) * t19 * r1 * slope1;
    const T t21 = T(65) * r0 * t9 - t6 * b * t20 - T(65) * t19 * r1;
    G_ap = (T(1) / T(715)) * t6 * in.w[0] * t20 - (T(1) / T(715)) * t1 * t21 * in.w[1];
    G_ab = -(T(1) / T(715)) * t1 * in.w[0] * t21 - (T(1) / T(2145)) * t1 * (T(11) * t6 * t17 + T(3) * t6 * t20 * c + T(6) * t1 * t21 * b) * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q0 * q0;
    const T t23 = t22 * t22;
    const T t24 = q1 * q1;
    const T t25 = t24 * q1;
    const T t26 = t22 * q0;
    const T t27 = t24 * t24;
    const T t28 = T(128) * r0 * slope0 * t23 - T(3) * (T(48) * t25 * r1 * slope1 - T(48) * r0 * slope0 * t26 - T(7) * D * t1 * (T(8) * r0 * slope0 * t22 + T(5) * D * (T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1 - T(3) * D * t1 * (J1 * D + r1 * slope1 - r0 * slope0)) * t1 - T(8) * t24 * r1 * slope1)) * D * t1 - T(128) * t27 * r1 * slope1;
    const T t29 = t23 * q0;
    const T t30 = t27 * q1;
    const T t31 = T(11) * t28 * t1 * b + T(1280) * r0 * t29 - T(1280) * t30 * r1;
    G_ap = -(T(1) / T(1280)) * t28 * t1 * in.w[0] - (T(1) / T(14080)) * t1 * in.w[1] * t31;
    G_ab = -(T(1) / T(14080)) * t1 * in.w[0] * t31 - (T(1) / T(168960)) * t1 * in.w[1] * (T(11) * t1 * (T(11) * D * t28 * t1 + T(1280) * r0 * slope0 * t29 - T(1280) * t30 * r1 * slope1) + T(24) * t1 * b * t31 - T(132) * t28 * t1 * c);
  }
  const T g_factor = -T(11) * length * inv_R2;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 56 +, 151 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2159 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
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
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ap = in.w[1] * M_flat[4] + in.w[0] * M_flat[3];
    G_ab = in.w[0] * M_flat[4] + M_flat[5] * in.w[1];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * q1;
    const T t15 = T(15) * t9 * r0 * slope0 + T(14) * t6 * a * (t10 * r0 * slope0 + T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) - slope1 * t14 * r1) - T(15) * slope1 * t13 * r1;
    F = (T(1) / T(195)) * t1 * in.w[1] * (t6 * b * t15 + T(15) * t13 * r1 - T(15) * t9 * r0) + (T(1) / T(195)) * t6 * in.w[0] * t15;
    const T t16 = t7 * t7;
    const T t17 = t16 * q0;
    const T t18 = t11 * t11;
    const T t19 = t18 * q1;
    const T t20 = T(4) * t6 * a * t15 + T(65) * t17 * r0 * slope0 - T(65) * slope1 * t19 * r1;
    const T t21 = t20 * t6 * b + T(65) * t19 * r1 - T(65) * t17 * r0;
    G_ap = (T(1) / T(715)) * t21 * t1 * in.w[1] + (T(1) / T(715)) * t20 * t6 * in.w[0];
    G_ab = (T(1) / T(2145)) * t1 * in.w[1] * (T(6) * t21 * t1 * b + T(11) * t6 * t15 - T(3) * t20 * t6 * c) + (T(1) / T(715)) * t21 * t1 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q0 * q0;
    const T t23 = t22 * t22;
    const T t24 = t23 * q0;
    const T t25 = q1 * q1;
    const T t26 = t25 * q1;
    const T t27 = t22 * q0;
    const T t28 = t25 * t25;
    const T t29 = T(3) * D * t1 * (T(48) * slope1 * t26 * r1 + T(7) * D * t1 * (T(8) * slope1 * t25 * r1 - T(8) * t22 * r0 * slope0 - T(5) * D * (T(2) * q0 * r0 * slope0 - T(2) * slope1 * q1 * r1 - T(3) * (D * J1 + slope1 * r1 - r0 * slope0) * D * t1) * t1) - T(48) * t27 * r0 * slope0) + T(128) * slope1 * t28 * r1 - T(128) * t23 * r0 * slope0;
    const T t30 = t28 * q1;
    const T t31 = T(1280) * t24 * r0 * slope0 - T(11) * D * t1 * t29 - T(1280) * slope1 * t30 * r1;
    const T t32 = t27 * t27;
    const T t33 = t26 * t26;
    F = -(T(1) / T(199680)) * t1 * (T(13) * t1 * t31 * b + T(15360) * t32 * r0 - T(15360) * t33 * r1) * in.w[1] - (T(1) / T(15360)) * t1 * t31 * in.w[0];
    const T t34 = T(1280) * t24 * r0 - T(1280) * t30 * r1 - T(11) * t1 * t29 * b;
    G_ap = (T(1) / T(1280)) * t1 * in.w[0] * t29 - (T(1) / T(14080)) * t1 * in.w[1] * t34;
    G_ab = -(T(1) / T(14080)) * t1 * in.w[0] * t34 - (T(1) / T(168960)) * t1 * (T(24) * t1 * b * t34 + T(11) * t1 * t31 + T(132) * t1 * t29 * c) * in.w[1];
  }
  const T g_factor = -T(11) * length * inv_R2;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Returns false where segment_compact_i11_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 56 +, 151 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i11_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * q1;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t8 * q0;
    const T t11 = t5 * q1;
    const T t12 = T(128) * r1 * slope1 * t6 - T(128) * slope0 * t9 * r0 - T(3) * (T(48) * slope0 * t10 * r0 + T(7) * (T(5) * D * t0 * (T(2) * slope0 * q0 * r0 + T(3) * (slope0 * r0 - D * J1 - r1 * slope1) * D * t0 - T(2) * r1 * slope1 * q1) + T(8) * slope0 * t8 * r0 - T(8) * r1 * slope1 * t5) * D * t0 - T(48) * r1 * slope1 * t11) * D * t0;
    const T t13 = t9 * q0;
    const T t14 = T(1280) * r1 * slope1 * t7 + T(11) * D * t0 * t12 - T(1280) * slope0 * t13 * r0;
    const T t15 = t11 * t11;
    const T t16 = t10 * t10;
    F = (T(1) / T(199680)) * t0 * (T(13) * t0 * t14 * b + T(15360) * r1 * t15 - T(15360) * t16 * r0) * in.w[1] + (T(1) / T(15360)) * t0 * t14 * in.w[0];
    const T t17 = T(1280) * t13 * r0 - T(11) * t0 * t12 * b - T(1280) * r1 * t7;
    G_ap = (T(1) / T(1280)) * t0 * t12 * in.w[0] - (T(1) / T(14080)) * t0 * t17 * in.w[1];
    G_ab = -(T(1) / T(168960)) * (T(132) * c * t0 * t12 + T(24) * t0 * t17 * b - T(11) * t0 * t14) * t0 * in.w[1] - (T(1) / T(14080)) * t0 * in.w[0] * t17;
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 52 +, 134 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2119 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = slope1 * t10 * r1 - T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) - t14 * r0 * slope0;
    const T t16 = T(15) * slope1 * t9 * r1 + T(14) * a * t6 * t15 - T(15) * t13 * r0 * slope0;
    const T t17 = t6 * b * t16 + T(15) * t13 * r0 - T(15) * t9 * r1;
    F = -(T(1) / T(195)) * t6 * t16 * in.w[0] - (T(1) / T(195)) * t1 * in.w[2] * (T(13) * t6 * t15 + T(2) * t1 * b * t17 - t6 * t16 * c) - (T(1) / T(195)) * t1 * in.w[1] * t17;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t18 = q0 * q0;
    const T t19 = t18 * q0;
    const T t20 = t19 * t19;
    const T t21 = t18 * t18;
    const T t22 = t21 * q0;
    const T t23 = q1 * q1;
    const T t24 = t23 * q1;
    const T t25 = t23 * t23;
    const T t26 = t25 * q1;
    const T t27 = T(1280) * t22 * r0 * slope0 + T(11) * t1 * D * (T(128) * t21 * r0 * slope0 + T(3) * t1 * D * (T(7) * t1 * D * (T(8) * t18 * r0 * slope0 - T(5) * t1 * D * (T(2) * slope1 * q1 * r1 + T(3) * t1 * D * (slope1 * r1 + D * J1 - r0 * slope0) - T(2) * q0 * r0 * slope0) - T(8) * slope1 * q1 * q1 * r1) + T(48) * t19 * r0 * slope0 - T(48) * slope1 * t24 * r1) - T(128) * slope1 * t25 * r1) - T(1280) * slope1 * t26 * r1;
    const T t28 = t24 * t24;
    const T t29 = T(15360) * t20 * r0 + T(13) * t1 * t27 * b - T(15360) * t28 * r1;
    F = -(T(1) / T(199680)) * t1 * t29 * in.w[1] - (T(1) / T(2795520)) * t1 * (T(28) * t1 * t29 * b - T(182) * t1 * t27 * c - T(13) * t1 * (T(15360) * slope1 * t28 * r1 - T(13) * t1 * D * t27 - T(15360) * t20 * r0 * slope0)) * in.w[2] - (T(1) / T(15360)) * t1 * t27 * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 59 +, 158 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2166 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2];
    G_ab = in.w[2] * M_flat[3] + M_flat[2] * in.w[1] + M_flat[1] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * q1;
    const T t8 = T(1) / D;
    const T t9 = t5 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = q0 * q0;
    const T t13 = t12 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * q0;
    const T t16 = T(15) * slope1 * t10 * r1 + T(14) * (slope1 * t11 * r1 - t15 * r0 * slope0 - T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a) * t8 * a - T(15) * t14 * r0 * slope0;
    const T t17 = t12 * t12;
    const T t18 = t17 * q0;
    const T t19 = T(4) * t16 * t8 * a + T(65) * slope1 * t7 * r1 - T(65) * t18 * r0 * slope0;
    const T t20 = T(65) * t7 * r1 - t8 * t19 * b - T(65) * t18 * r0;
    const T t21 = T(6) * t20 * t0 * b + T(3) * c * t8 * t19 - T(11) * t16 * t8;
    G_ap = (T(1) / T(2145)) * in.w[2] * t0 * t21 + (T(1) / T(715)) * t20 * t0 * in.w[1] - (T(1) / T(715)) * in.w[0] * t8 * t19;
    G_ab = (T(1) / T(2145)) * in.w[2] * (T(11) * (T(15) * t10 * r1 - t16 * t8 * b - T(15) * t14 * r0) * t0 + T(2) * t0 * t21 * b - T(3) * t20 * c * t0) * t0 + (T(1) / T(715)) * t20 * in.w[0] * t0 + (T(1) / T(2145)) * t0 * in.w[1] * t21;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * t22;
    const T t24 = q0 * q0;
    const T t25 = t24 * q0;
    const T t26 = t22 * q1;
    const T t27 = t24 * t24;
    const T t28 = T(128) * slope1 * t23 * r1 - T(3) * D * t0 * (T(48) * t25 * r0 * slope0 + T(7) * D * t0 * (T(8) * t24 * r0 * slope0 - T(5) * (T(2) * slope1 * q1 * r1 + T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t0 - T(2) * q0 * r0 * slope0) * D * t0 - T(8) * slope1 * t22 * r1) - T(48) * slope1 * t26 * r1) - T(128) * t27 * r0 * slope0;
    const T t29 = t23 * q1;
    const T t30 = t27 * q0;
    const T t31 = T(1280) * slope1 * t29 * r1 + T(11) * t28 * D * t0 - T(1280) * t30 * r0 * slope0;
    const T t32 = T(1280) * t29 * r1 + T(11) * t28 * t0 * b - T(1280) * t30 * r0;
    const T t33 = T(11) * t31 * t0 + T(24) * t0 * t32 * b - T(132) * c * t28 * t0;
    G_ap = (T(1) / T(1280)) * t28 * in.w[0] * t0 + (T(1) / T(168960)) * t33 * in.w[2] * t0 + (T(1) / T(14080)) * t0 * in.w[1] * t32;
    const T t34 = t26 * t26;
    const T t35 = t25 * t25;
    G_ab = (T(1) / T(14080)) * in.w[0] * t0 * t32 + (T(1) / T(2196480)) * in.w[2] * t0 * (T(11) * (T(15360) * t34 * r1 + T(13) * t31 * t0 * b - T(15360) * t35 * r0) * t0 + T(26) * t33 * t0 * b - T(156) * c * t0 * t32) + (T(1) / T(168960)) * t33 * t0 * in.w[1];
  }
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 65 +, 186 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2183 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
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
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ap = M_flat[5] * in.w[1] + M_flat[6] * in.w[2] + in.w[0] * M_flat[4];
    G_ab = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = t9 * q1;
    const T t16 = T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) + t14 * r0 * slope0 - t15 * r1 * slope1;
    const T t17 = T(14) * a * t10 * t16 + T(15) * t13 * r0 * slope0 - T(15) * t9 * r1 * slope1;
    const T t18 = T(15) * t9 * r1 + t10 * b * t17 - T(15) * t13 * r0;
    F = (T(1) / T(195)) * t18 * t2 * in.w[1] + (T(1) / T(195)) * in.w[0] * t10 * t17 + (T(1) / T(195)) * t2 * (T(13) * t10 * t16 + T(2) * t18 * t2 * b - t10 * t17 * c) * in.w[2];
    const T t19 = t7 * t7;
    const T t20 = t19 * q1;
    const T t21 = t11 * t11;
    const T t22 = t21 * q0;
    const T t23 = T(4) * a * t10 * t17 + T(65) * t22 * r0 * slope0 - T(65) * t20 * r1 * slope1;
    const T t24 = T(65) * t20 * r1 + t10 * t23 * b - T(65) * t22 * r0;
    const T t25 = T(11) * t10 * t17 + T(6) * t2 * b * t24 - T(3) * t10 * t23 * c;
    G_ap = (T(1) / T(2145)) * t2 * t25 * in.w[2] + (T(1) / T(715)) * in.w[0] * t10 * t23 + (T(1) / T(715)) * t2 * in.w[1] * t24;
    G_ab = (T(1) / T(2145)) * t2 * (T(2) * t2 * b * t25 + T(11) * t18 * t2 - T(3) * t2 * t24 * c) * in.w[2] + (T(1) / T(2145)) * t2 * in.w[1] * t25 + (T(1) / T(715)) * in.w[0] * t2 * t24;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t26 = q0 * q0;
    const T t27 = t26 * t26;
    const T t28 = t27 * q0;
    const T t29 = t26 * q0;
    const T t30 = q1 * q1;
    const T t31 = t30 * q1;
    const T t32 = t30 * t30;
    const T t33 = T(3) * t2 * D * (T(7) * t2 * D * (T(8) * t26 * r0 * slope0 - T(8) * q1 * q1 * r1 * slope1 - T(5) * t2 * D * (T(3) * t2 * D * (D * J1 + r1 * slope1 - r0 * slope0) + T(2) * q1 * r1 * slope1 - T(2) * q0 * r0 * slope0)) + T(48) * t29 * r0 * slope0 - T(48) * t31 * r1 * slope1) + T(128) * t27 * r0 * slope0 - T(128) * t32 * r1 * slope1;
    const T t34 = t32 * q1;
    const T t35 = T(1280) * t28 * r0 * slope0 + T(11) * t2 * D * t33 - T(1280) * t34 * r1 * slope1;
    const T t36 = t29 * t29;
    const T t37 = t31 * t31;
    const T t38 = T(13) * t2 * b * t35 + T(15360) * t36 * r0 - T(15360) * t37 * r1;
    F = -(T(1) / T(2795520)) * (T(28) * t2 * b * t38 + T(13) * t2 * (T(13) * t2 * D * t35 + T(15360) * t36 * r0 * slope0 - T(15360) * t37 * r1 * slope1) - T(182) * t2 * c * t35) * t2 * in.w[2] - (T(1) / T(15360)) * in.w[0] * t2 * t35 - (T(1) / T(199680)) * t2 * in.w[1] * t38;
    const T t39 = T(11) * t2 * b * t33 + T(1280) * t28 * r0 - T(1280) * t34 * r1;
    const T t40 = T(132) * t2 * c * t33 - T(24) * t2 * t39 * b - T(11) * t2 * t35;
    G_ap = (T(1) / T(168960)) * t2 * t40 * in.w[2] - (T(1) / T(1280)) * in.w[0] * t2 * t33 - (T(1) / T(14080)) * t2 * in.w[1] * t39;
    G_ab = (T(1) / T(168960)) * t2 * in.w[1] * t40 + (T(1) / T(2196480)) * t2 * in.w[2] * (T(26) * t2 * b * t40 + T(156) * t2 * t39 * c - T(11) * t2 * t38) - (T(1) / T(14080)) * in.w[0] * t2 * t39;
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Returns false where segment_compact_i11_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 65 +, 185 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i11_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
    G_ap = M_flat[4] * in.w[0] + M_flat[5] * in.w[1] + M_flat[6] * in.w[2];
    G_ab = in.w[2] * M_flat[7] + in.w[0] * M_flat[5] + in.w[1] * M_flat[6];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t10 * t10;
    const T t12 = t9 * t9;
    const T t13 = t6 * t6;
    const T t14 = T(3) * D * t1 * (T(48) * t10 * r0 * slope0 + T(7) * (T(5) * D * t1 * (T(2) * q0 * r0 * slope0 - T(2) * slope1 * q1 * r1 - T(3) * (slope1 * r1 + D * J1 - r0 * slope0) * D * t1) + T(8) * t9 * r0 * slope0 - T(8) * slope1 * t6 * r1) * D * t1 - T(48) * slope1 * t7 * r1) + T(128) * t12 * r0 * slope0 - T(128) * slope1 * t13 * r1;
    const T t15 = t12 * q0;
    const T t16 = t13 * q1;
    const T t17 = T(11) * D * t1 * t14 + T(1280) * t15 * r0 * slope0 - T(1280) * slope1 * t16 * r1;
    const T t18 = T(15360) * t8 * r1 - T(15360) * t11 * r0 - T(13) * t17 * t1 * b;
    F = (T(1) / T(199680)) * t18 * in.w[1] * t1 + (T(1) / T(2795520)) * (T(182) * c * t17 * t1 + T(28) * t18 * t1 * b - T(13) * (T(15360) * t11 * r0 * slope0 + T(13) * t17 * D * t1 - T(15360) * slope1 * t8 * r1) * t1) * t1 * in.w[2] - (T(1) / T(15360)) * in.w[0] * t17 * t1;
    const T t19 = T(1280) * t15 * r0 + T(11) * t1 * t14 * b - T(1280) * t16 * r1;
    const T t20 = T(24) * t1 * b * t19 + T(11) * t17 * t1 - T(132) * c * t1 * t14;
    G_ap = -(T(1) / T(168960)) * t20 * t1 * in.w[2] - (T(1) / T(14080)) * in.w[1] * t1 * t19 - (T(1) / T(1280)) * in.w[0] * t1 * t14;
    G_ab = (T(1) / T(2196480)) * t1 * in.w[2] * (T(11) * t18 * t1 + T(156) * c * t1 * t19 - T(26) * t20 * t1 * b) - (T(1) / T(14080)) * in.w[0] * t1 * t19 - (T(1) / T(168960)) * t20 * in.w[1] * t1;
  }
  const T g_factor = -T(11) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - G_ap * ap1);
  grad[2] = -g_factor * (G_ab * ab2 - G_ap * ap2);
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 57 +, 152 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2149 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(t0, r0 * root_minus_a)) / root_minus_a;
  T F;
  const T t1 = T(1) / a;
  const T t2 = max(T(b * t1 + (T(1) / T(2))), T((T(3) / T(2)) - b * t1));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + in.w[3] * M_flat[3];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = t7 * t7;
    const T t9 = T(1) / D;
    const T t10 = t8 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = t11 * t11;
    const T t16 = t15 * t15;
    const T t17 = t6 * t6;
    const T t18 = t17 * t17;
    const T t19 = T(17) * slope1 * t10 * r1 - T(17) * t14 * r0 * slope0 - T(16) * (t16 * r0 * slope0 + T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) - slope1 * t18 * r1) * t9 * a;
    const T t20 = T(255) * slope1 * t8 * r1 + T(14) * t9 * a * t19 - T(255) * t13 * r0 * slope0;
    const T t21 = T(255) * t8 * r1 - T(255) * t13 * r0 - b * t20 * t9;
    const T t22 = t20 * c * t9 + T(2) * t21 * b * t1 - T(13) * t9 * t19;
    F = (T(1) / T(3315)) * in.w[2] * t22 * t1 + (T(1) / T(3315)) * (T(2) * b * t22 * t1 + T(13) * (T(17) * t10 * r1 - T(17) * t14 * r0 - b * t9 * t19) * t1 - t21 * c * t1) * in.w[3] * t1 + (T(1) / T(3315)) * t21 * in.w[1] * t1 - (T(1) / T(3315)) * in.w[0] * t20 * t9;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t23 = q1 * q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * q1;
    const T t26 = q0 * q0;
    const T t27 = t26 * q0;
    const T t28 = t23 * q1;
    const T t29 = t26 * t26;
    const T t30 = t29 * q0;
    const T t31 = T(1280) * slope1 * t25 * r1 + T(11) * (T(128) * slope1 * t24 * r1 - T(3) * (T(48) * t27 * r0 * slope0 + T(7) * D * t1 * (T(8) * t26 * r0 * slope0 - T(5) * (T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0 - T(3) * (r0 * slope0 - slope1 * r1 - J1 * D) * D * t1) * D * t1 - T(8) * slope1 * t23 * r1) - T(48) * slope1 * t28 * r1) * D * t1 - T(128) * t29 * r0 * slope0) * D * t1 - T(1280) * t30 * r0 * slope0;
    const T t32 = t28 * t28;
    const T t33 = t27 * t27;
    const T t34 = T(15360) * t32 * r1 + T(13) * t31 * b * t1 - T(15360) * t33 * r0;
    const T t35 = T(13) * t31 * D * t1 + T(15360) * slope1 * t32 * r1 - T(15360) * t33 * r0 * slope0;
    const T t36 = T(28) * t34 * b * t1 + T(13) * t1 * t35 - T(182) * t31 * c * t1;
    const T t37 = t32 * q1;
    const T t38 = t33 * q0;
    F = (T(1) / T(15360)) * t31 * in.w[0] * t1 + (T(1) / T(199680)) * t34 * in.w[1] * t1 + (T(1) / T(2795520)) * in.w[2] * t36 * t1 - (T(1) / T(2795520)) * in.w[3] * t1 * (T(14) * t34 * c * t1 - T(2) * b * t36 * t1 - T(13) * (b * t1 * t35 + T(14336) * t37 * r1 - T(14336) * t38 * r0) * t1);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 67 +, 189 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2198 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i11_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-9, -9, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[2] * M_flat[2] + M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ab = in.w[0] * M_flat[1] + M_flat[2] * in.w[1] + M_flat[4] * in.w[3] + M_flat[3] * in.w[2];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = t7 * q0;
    const T t11 = t10 * t10;
    const T t12 = q1 * q1;
    const T t13 = t12 * q1;
    const T t14 = t13 * t13;
    const T t15 = t14 * q1;
    const T t16 = t12 * t12;
    const T t17 = t16 * t16;
    const T t18 = t8 * t8;
    const T t19 = t11 * q0;
    const T t20 = T(17) * t15 * r1 * slope1 + T(16) * t6 * a * (t17 * r1 * slope1 - T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) - r0 * slope0 * t18) - T(17) * r0 * slope0 * t19;
    const T t21 = T(255) * r0 * slope0 * t11 - T(255) * t14 * r1 * slope1 - T(14) * t20 * t6 * a;
    const T t22 = t16 * q1;
    const T t23 = T(1105) * r0 * slope0 * t9 + T(4) * t6 * a * t21 - T(1105) * t22 * r1 * slope1;
    const T t24 = t6 * b * t23 + T(1105) * t22 * r1 - T(1105) * r0 * t9;
    const T t25 = T(11) * t6 * t21 + T(6) * t1 * t24 * b - T(3) * t6 * t23 * c;
    const T t26 = T(255) * r0 * t11 - t6 * b * t21 - T(255) * t14 * r1;
    const T t27 = T(3) * t1 * t24 * c + T(11) * t1 * t26 - T(2) * t1 * b * t25;
    G_ap = (T(1) / T(12155)) * t1 * t24 * in.w[1] + (T(1) / T(36465)) * t1 * in.w[2] * t25 + (T(1) / T(12155)) * t6 * in.w[0] * t23 - (T(1) / T(36465)) * t1 * in.w[3] * t27;
    G_ab = (T(1) / T(36465)) * t1 * t25 * in.w[1] + (T(1) / T(12155)) * t1 * t24 * in.w[0] - (T(1) / T(36465)) * t1 * in.w[2] * t27 - (T(1) / T(36465)) * t1 * (T(11) * (t6 * c * t21 + T(2) * t1 * b * t26 + T(13) * t20 * t6) * t1 + T(2) * t1 * b * t27 + t1 * t25 * c) * in.w[3];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t28 = q0 * q0;
    const T t29 = t28 * t28;
    const T t30 = q1 * q1;
    const T t31 = t30 * q1;
    const T t32 = t28 * q0;
    const T t33 = t30 * t30;
    const T t34 = T(128) * r0 * slope0 * t29 - T(3) * D * t1 * (T(48) * t31 * r1 * slope1 + T(7) * D * t1 * (T(5) * D * t1 * (T(3) * D * t1 * (r1 * slope1 + D * J1 - r0 * slope0) + T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0) + T(8) * t30 * r1 * slope1 - T(8) * r0 * slope0 * t28) - T(48) * r0 * slope0 * t32) - T(128) * t33 * r1 * slope1;
    const T t35 = t29 * q0;
    const T t36 = t33 * q1;
    const T t37 = T(11) * t1 * t34 * b + T(1280) * r0 * t35 - T(1280) * t36 * r1;
    const T t38 = T(1280) * r0 * slope0 * t35 + T(11) * D * t1 * t34 - T(1280) * t36 * r1 * slope1;
    const T t39 = T(24) * t1 * b * t37 + T(11) * t38 * t1 - T(132) * t1 * t34 * c;
    const T t40 = t32 * t32;
    const T t41 = t31 * t31;
    const T t42 = T(15360) * r0 * t40 + T(13) * t38 * t1 * b - T(15360) * t41 * r1;
    const T t43 = T(26) * t1 * b * t39 + T(11) * t42 * t1 - T(156) * t1 * c * t37;
    G_ap = -(T(1) / T(168960)) * t1 * in.w[2] * t39 - (T(1) / T(14080)) * t1 * t37 * in.w[1] - (T(1) / T(2196480)) * t1 * in.w[3] * t43 - (T(1) / T(1280)) * t1 * t34 * in.w[0];
    G_ab = -(T(1) / T(2196480)) * t1 * in.w[2] * t43 - (T(1) / T(30750720)) * (T(28) * t1 * b * t43 + T(11) * t1 * (T(13) * t1 * (T(15360) * r0 * slope0 * t40 + T(13) * t38 * D * t1 - T(15360) * t41 * r1 * slope1) + T(28) * t42 * t1 * b - T(182) * t38 * t1 * c) - T(182) * t1 * t39 * c) * t1 * in.w[3] - (T(1) / T(168960)) * t1 * t39 * in.w[1] - (T(1) / T(14080)) * t1 * in.w[0] * t37;
  }
  const T g_factor = -T(11) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Operations: 74 +, 218 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2224 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i11_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ap = in.w[2] * M_flat[7] + M_flat[8] * in.w[3] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
    G_ab = in.w[1] * M_flat[7] + M_flat[6] * in.w[0] + M_flat[8] * in.w[2] + M_flat[9] * in.w[3];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * q1;
    const T t10 = T(1) / D;
    const T t11 = t6 * t6;
    const T t12 = t11 * t11;
    const T t13 = q0 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t13 * q0;
    const T t17 = t16 * t16;
    const T t18 = t17 * q0;
    const T t19 = T(17) * slope1 * t9 * r1 + T(16) * (slope1 * t12 * r1 - t15 * r0 * slope0 - T(18) * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) * a) * a * t10 - T(17) * t18 * r0 * slope0;
    const T t20 = T(14) * a * t10 * t19 + T(255) * slope1 * t8 * r1 - T(255) * t17 * r0 * slope0;
    const T t21 = t10 * t20 * b + T(255) * t17 * r0 - T(255) * t8 * r1;
    const T t22 = T(2) * t21 * t1 * b + T(13) * t10 * t19 - t10 * t20 * c;
    F = (T(1) / T(3315)) * t1 * (T(13) * t1 * (T(17) * t9 * r1 - t10 * t19 * b - T(17) * t18 * r0) + t21 * t1 * c - T(2) * t1 * t22 * b) * in.w[3] - (T(1) / T(3315)) * t1 * in.w[2] * t22 - (T(1) / T(3315)) * in.w[1] * t21 * t1 - (T(1) / T(3315)) * t10 * t20 * in.w[0];
    const T t23 = t11 * q1;
    const T t24 = t14 * q0;
    const T t25 = T(1105) * slope1 * t23 * r1 + T(4) * a * t10 * t20 - T(1105) * t24 * r0 * slope0;
    const T t26 = T(1105) * t23 * r1 - t25 * t10 * b - T(1105) * t24 * r0;
    const T t27 = T(11) * t10 * t20 - T(6) * t26 * t1 * b - T(3) * t25 * t10 * c;
    const T t28 = T(11) * t21 * t1 + T(3) * t26 * t1 * c + T(2) * t27 * t1 * b;
    G_ap = (T(1) / T(12155)) * t26 * in.w[1] * t1 - (T(1) / T(36465)) * t27 * t1 * in.w[2] - (T(1) / T(12155)) * t25 * t10 * in.w[0] - (T(1) / T(36465)) * t1 * t28 * in.w[3];
    G_ab = (T(1) / T(12155)) * t26 * t1 * in.w[0] - (T(1) / T(36465)) * t1 * in.w[2] * t28 - (T(1) / T(36465)) * (T(2) * t1 * b * t28 + T(11) * t1 * t22 - t27 * t1 * c) * t1 * in.w[3] - (T(1) / T(36465)) * t27 * in.w[1] * t1;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t29 = q1 * q1;
    const T t30 = t29 * t29;
    const T t31 = t30 * q1;
    const T t32 = q0 * q0;
    const T t33 = t32 * t32;
    const T t34 = t33 * q0;
    const T t35 = t32 * q0;
    const T t36 = t29 * q1;
    const T t37 = T(3) * t1 * D * (T(48) * t35 * r0 * slope0 + T(7) * (T(8) * t32 * r0 * slope0 - T(5) * (T(2) * slope1 * q1 * r1 + T(3) * t1 * D * (slope1 * r1 + D * J1 - r0 * slope0) - T(2) * q0 * r0 * slope0) * t1 * D - T(8) * slope1 * t29 * r1) * t1 * D - T(48) * slope1 * t36 * r1) + T(128) * t33 * r0 * slope0 - T(128) * slope1 * t30 * r1;
    const T t38 = T(1280) * slope1 * t31 * r1 - T(1280) * t34 * r0 * slope0 - T(11) * t1 * D * t37;
    const T t39 = t36 * t36;
    const T t40 = t35 * t35;
    const T t41 = T(15360) * t39 * r1 + T(13) * t1 * b * t38 - T(15360) * t40 * r0;
    const T t42 = t39 * q1;
    const T t43 = T(15360) * slope1 * t39 * r1 + T(13) * t1 * D * t38 - T(15360) * t40 * r0 * slope0;
    const T t44 = t40 * q0;
    const T t45 = T(28) * t1 * t41 * b + T(13) * t1 * t43 - T(182) * t1 * c * t38;
    F = (T(1) / T(15360)) * t1 * in.w[0] * t38 + (T(1) / T(199680)) * in.w[1] * t1 * t41 + (T(1) / T(2795520)) * (T(13) * (T(14336) * t42 * r1 + t1 * b * t43 - T(14336) * t44 * r0) * t1 + T(2) * t1 * t45 * b - T(14) * t1 * t41 * c) * t1 * in.w[3] + (T(1) / T(2795520)) * t1 * t45 * in.w[2];
    const T t46 = T(1280) * t31 * r1 - T(11) * t1 * t37 * b - T(1280) * t34 * r0;
    const T t47 = T(11) * t1 * t38 + T(132) * t1 * t37 * c + T(24) * t1 * b * t46;
    const T t48 = T(11) * t1 * t41 + T(26) * t1 * t47 * b - T(156) * t1 * t46 * c;
    G_ap = (T(1) / T(168960)) * t1 * in.w[2] * t47 + (T(1) / T(2196480)) * t1 * t48 * in.w[3] + (T(1) / T(14080)) * in.w[1] * t1 * t46 - (T(1) / T(1280)) * t1 * t37 * in.w[0];
    G_ab = (T(1) / T(2196480)) * t1 * in.w[2] * t48 + (T(1) / T(168960)) * in.w[1] * t1 * t47 + (T(1) / T(14080)) * t1 * t46 * in.w[0] + (T(1) / T(30750720)) * t1 * (T(11) * t1 * t45 + T(28) * t1 * t48 * b - T(182) * t1 * t47 * c) * in.w[3];
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = length * F;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(11/2) dt
/// Returns false where segment_compact_i11_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 74 +, 218 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i11_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - inv_R2 * cross_cross) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-11, -9, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + in.w[1] * M_flat[1] + in.w[3] * M_flat[3];
    G_ap = M_flat[5] * in.w[0] + M_flat[8] * in.w[3] + M_flat[7] * in.w[2] + in.w[1] * M_flat[6];
    G_ab = M_flat[7] * in.w[1] + in.w[3] * M_flat[9] + M_flat[8] * in.w[2] + M_flat[6] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * q1;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t8 * q0;
    const T t11 = t5 * q1;
    const T t12 = T(128) * slope1 * t6 * r1 - T(128) * slope0 * t9 * r0 - T(3) * (T(48) * slope0 * t10 * r0 + T(7) * (T(8) * slope0 * t8 * r0 - T(5) * (T(2) * slope1 * q1 * r1 + T(3) * D * (slope1 * r1 + D * J1 - slope0 * r0) * t0 - T(2) * slope0 * q0 * r0) * D * t0 - T(8) * slope1 * t5 * r1) * D * t0 - T(48) * slope1 * t11 * r1) * D * t0;
    const T t13 = t9 * q0;
    const T t14 = T(1280) * slope1 * t7 * r1 + T(11) * t12 * D * t0 - T(1280) * slope0 * t13 * r0;
    const T t15 = t11 * t11;
    const T t16 = t10 * t10;
    const T t17 = T(13) * t14 * t0 * b + T(15360) * t15 * r1 - T(15360) * t16 * r0;
    const T t18 = T(15360) * slope1 * t15 * r1 + T(13) * t14 * D * t0 - T(15360) * slope0 * t16 * r0;
    const T t19 = T(28) * t17 * t0 * b + T(13) * t0 * t18 - T(182) * c * t14 * t0;
    const T t20 = t15 * q1;
    const T t21 = t16 * q0;
    F = (T(1) / T(199680)) * t17 * in.w[1] * t0 + (T(1) / T(15360)) * t14 * t0 * in.w[0] + (T(1) / T(2795520)) * t19 * in.w[2] * t0 - (T(1) / T(2795520)) * (T(14) * t17 * c * t0 - T(2) * t19 * t0 * b - T(13) * t0 * (T(14336) * t20 * r1 + t0 * t18 * b - T(14336) * t21 * r0)) * t0 * in.w[3];
    const T t22 = T(1280) * t7 * r1 + T(11) * t12 * t0 * b - T(1280) * t13 * r0;
    const T t23 = T(24) * t0 * t22 * b + T(11) * t14 * t0 - T(132) * c * t12 * t0;
    const T t24 = T(26) * t0 * b * t23 + T(11) * t17 * t0 - T(156) * c * t0 * t22;
    G_ap = (T(1) / T(168960)) * in.w[2] * t0 * t23 + (T(1) / T(14080)) * in.w[1] * t0 * t22 + (T(1) / T(2196480)) * t0 * in.w[3] * t24 + (T(1) / T(1280)) * t12 * t0 * in.w[0];
    G_ab = (T(1) / T(2196480)) * in.w[2] * t0 * t24 + (T(1) / T(14080)) * t0 * t22 * in.w[0] + (T(1) / T(168960)) * in.w[1] * t0 * t23 - (T(1) / T(30750720)) * t0 * (T(182) * c * t0 * t23 - T(28) * t0 * b * t24 - T(11) * t19 * t0) * in.w[3];
  }
  const T g_factor = -T(11) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return !(((t3 >= T(0) && t4 >= T(0)) && !(t2 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 43 +, 106 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 7>(-12, -12, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 53 +, 117 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i12_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-10, -10, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 67 +, 140 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-12, -10, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Returns false where segment_compact_i12_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 140 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i12_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-12, -10, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = M_exact[3] * in.w[0];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 51 +, 114 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 13, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 7>(-12, -12, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 80 +, 168 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i12_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-10, -10, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ab = M_exact[1] * in.w[0] + M_exact[2] * in.w[1];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 111 +, 211 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[3] + M_exact[4] * in.w[1];
    G_ab = M_exact[4] * in.w[0] + M_exact[5] * in.w[1];
  }
  const T g_factor = -T(12) * length * inv_R2;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Returns false where segment_compact_i12_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 111 +, 211 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i12_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ap = M_exact[3] * in.w[0] + M_exact[4] * in.w[1];
    G_ab = in.w[0] * M_exact[4] + in.w[1] * M_exact[5];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 77 +, 167 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + M_exact[2] * in.w[2] + in.w[1] * M_exact[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 92 +, 180 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i12_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-10, -10, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + M_exact[2] * in.w[2];
    G_ab = M_exact[3] * in.w[2] + in.w[0] * M_exact[1] + M_exact[2] * in.w[1];
  }
  const T g_factor = -T(12) * length * inv_R2;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 134 +, 234 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[0] * M_exact[0] + in.w[2] * M_exact[2];
    G_ap = in.w[2] * M_exact[6] + in.w[0] * M_exact[4] + in.w[1] * M_exact[5];
    G_ab = in.w[1] * M_exact[6] + M_exact[5] * in.w[0] + in.w[2] * M_exact[7];
  }
  const T g_factor = -T(12) * length * inv_R2;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Returns false where segment_compact_i12_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 134 +, 234 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i12_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + in.w[2] * M_exact[2];
    G_ap = in.w[1] * M_exact[5] + in.w[0] * M_exact[4] + M_exact[6] * in.w[2];
    G_ab = M_exact[7] * in.w[2] + in.w[0] * M_exact[5] + M_exact[6] * in.w[1];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 88 +, 178 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[0] * in.w[0] + M_exact[3] * in.w[3] + M_exact[2] * in.w[2];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 104 +, 192 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i12_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 10>(-10, -10, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + M_exact[2] * in.w[2] + in.w[3] * M_exact[3];
    G_ab = in.w[0] * M_exact[1] + in.w[3] * M_exact[4] + M_exact[2] * in.w[1] + M_exact[3] * in.w[2];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  grad[0] = (G_ap * ap0 - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Operations: 157 +, 257 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i12_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + in.w[3] * M_exact[3] + M_exact[0] * in.w[0];
    G_ap = M_exact[6] * in.w[1] + in.w[3] * M_exact[8] + M_exact[5] * in.w[0] + M_exact[7] * in.w[2];
    G_ab = in.w[2] * M_exact[8] + M_exact[6] * in.w[0] + in.w[3] * M_exact[9] + in.w[1] * M_exact[7];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(12/2) dt
/// Returns false where segment_compact_i12_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 157 +, 257 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i12_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-12, -10, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[3] * M_exact[3] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
    G_ap = M_exact[7] * in.w[2] + M_exact[6] * in.w[1] + M_exact[5] * in.w[0] + M_exact[8] * in.w[3];
    G_ab = M_exact[7] * in.w[1] + in.w[0] * M_exact[6] + in.w[2] * M_exact[8] + in.w[3] * M_exact[9];
  }
  const T g_factor = -T(12) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 46 +, 112 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2090 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - t1 * t1 * a * a;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    F = (T(1) / T(15)) * in.w[0] * (r0 * slope0 * t8 + T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a - r1 * slope1 * t12) / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t13 = q0 * q0;
    const T t14 = t13 * q0;
    const T t15 = t14 * t14;
    const T t16 = t13 * t13;
    const T t17 = t16 * q0;
    const T t18 = q1 * q1;
    const T t19 = t18 * q1;
    const T t20 = t18 * t18;
    const T t21 = t20 * q1;
    const T t22 = t19 * t19;
    F = -(T(1) / T(215040)) * (T(15360) * r0 * slope0 * t15 + T(13) * (T(1280) * r0 * slope0 * t17 + T(11) * (T(128) * r0 * slope0 * t16 - T(3) * (T(48) * r1 * slope1 * t19 + T(7) * D * t0 * (T(8) * r1 * slope1 * t18 + T(5) * (T(3) * (J1 * D + r1 * slope1 - r0 * slope0) * D * t0 + T(2) * r1 * slope1 * q1 - T(2) * r0 * slope0 * q0) * D * t0 - T(8) * r0 * slope0 * t13) - T(48) * r0 * slope0 * t14) * D * t0 - T(128) * r1 * slope1 * t20) * D * t0 - T(1280) * r1 * slope1 * t21) * D * t0 - T(15360) * r1 * slope1 * t22) * t0 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 49 +, 123 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2119 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0];
    G_ab = in.w[0] * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * q1;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t10 * t10;
    const T t12 = t11 * q0;
    const T t13 = T(1) / D;
    const T t14 = T(15) * slope1 * t7 * r1 + T(14) * (slope1 * t8 * r1 - T(16) * a * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) - t12 * r0 * slope0) * a * t13 - T(15) * t11 * r0 * slope0;
    G_ap = -(T(1) / T(195)) * t14 * in.w[0] * t13;
    G_ab = (T(1) / T(195)) * in.w[0] * (T(15) * t7 * r1 - t14 * t13 * b - T(15) * t11 * r0) * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t15 = q1 * q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * q1;
    const T t18 = q0 * q0;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = t18 * q0;
    const T t22 = t15 * q1;
    const T t23 = T(1280) * slope1 * t17 * r1 - T(1280) * t20 * r0 * slope0 - T(11) * t0 * D * (T(128) * t19 * r0 * slope0 + T(3) * t0 * D * (T(7) * (T(8) * t18 * r0 * slope0 - T(5) * (T(3) * t0 * D * (J1 * D + slope1 * r1 - r0 * slope0) + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0) * t0 * D - T(8) * slope1 * t15 * r1) * t0 * D + T(48) * t21 * r0 * slope0 - T(48) * slope1 * t22 * r1) - T(128) * slope1 * t16 * r1);
    G_ap = (T(1) / T(15360)) * t23 * in.w[0] * t0;
    const T t24 = t22 * t22;
    const T t25 = t21 * t21;
    G_ab = (T(1) / T(199680)) * (T(15360) * t24 * r1 + T(13) * t23 * t0 * b - T(15360) * t25 * r0) * in.w[0] * t0;
  }
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 51 +, 136 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2123 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-15 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * q1;
    const T t15 = r0 * slope0 * t10 + T(16) * J_upward_compact<T>(-15, a, D, slope0, q0, slope1, q1) * a - r1 * slope1 * t14;
    const T t16 = T(1) / D;
    F = (T(1) / T(15)) * in.w[0] * t15 * t16;
    const T t17 = T(15) * r0 * slope0 * t9 + T(14) * t15 * t16 * a - T(15) * r1 * slope1 * t13;
    G_ap = (T(1) / T(195)) * in.w[0] * t17 * t16;
    G_ab = (T(1) / T(195)) * in.w[0] * (T(15) * r1 * t13 + b * t17 * t16 - T(15) * r0 * t9) * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t18 = q0 * q0;
    const T t19 = t18 * q0;
    const T t20 = t19 * t19;
    const T t21 = t18 * t18;
    const T t22 = q1 * q1;
    const T t23 = t22 * q1;
    const T t24 = t22 * t22;
    const T t25 = t21 * q0;
    const T t26 = t24 * q1;
    const T t27 = T(11) * (T(128) * r0 * slope0 * t21 - T(3) * (T(48) * r1 * slope1 * t23 + T(7) * (T(8) * r1 * slope1 * t22 + T(5) * D * t2 * (T(2) * r1 * slope1 * q1 + T(3) * D * t2 * (r1 * slope1 + D * J1 - r0 * slope0) - T(2) * r0 * slope0 * q0) - T(8) * r0 * slope0 * t18) * D * t2 - T(48) * r0 * slope0 * t19) * D * t2 - T(128) * r1 * slope1 * t24) * D * t2 + T(1280) * r0 * slope0 * t25 - T(1280) * r1 * slope1 * t26;
    const T t28 = t23 * t23;
    F = -(T(1) / T(215040)) * in.w[0] * (T(15360) * r0 * slope0 * t20 + T(13) * t27 * D * t2 - T(15360) * r1 * slope1 * t28) * t2;
    G_ap = -(T(1) / T(15360)) * in.w[0] * t27 * t2;
    G_ab = -(T(1) / T(199680)) * in.w[0] * t2 * (T(13) * b * t27 * t2 + T(15360) * r0 * t20 - T(15360) * r1 * t28);
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Returns false where segment_compact_i13_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 51 +, 136 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i13_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = t10 * q1;
    const T t14 = t7 * t7;
    const T t15 = t14 * q0;
    const T t16 = T(1280) * t12 * r1 * slope1 + T(11) * D * t2 * (T(3) * D * t2 * (T(7) * D * t2 * (T(8) * t10 * r1 * slope1 - T(5) * D * t2 * (T(2) * q0 * r0 * slope0 - T(3) * D * t2 * (D * J1 + r1 * slope1 - r0 * slope0) - T(2) * q1 * r1 * slope1) - T(8) * t7 * r0 * slope0) + T(48) * t13 * r1 * slope1 - T(48) * t8 * r0 * slope0) + T(128) * t11 * r1 * slope1 - T(128) * t14 * r0 * slope0) - T(1280) * t15 * r0 * slope0;
    const T t17 = t13 * t13;
    F = -(T(1) / T(215040)) * t2 * in.w[0] * (T(15360) * t9 * r0 * slope0 - T(13) * D * t2 * t16 - T(15360) * t17 * r1 * slope1);
    G_ap = (T(1) / T(15360)) * t2 * t16 * in.w[0];
    G_ab = (T(1) / T(199680)) * t2 * in.w[0] * (T(15360) * t17 * r1 + T(13) * t2 * t16 * b - T(15360) * t9 * r0);
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 49 +, 123 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2114 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = T(1) / D;
    const T t14 = t5 * t5;
    const T t15 = t14 * t14;
    const T t16 = t9 * t9;
    const T t17 = t16 * t16;
    const T t18 = T(17) * t12 * r1 * slope1 - T(16) * t13 * (r0 * slope0 * t15 + T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) - t17 * r1 * slope1) * a - T(17) * r0 * slope0 * t8;
    F = -(T(1) / T(255)) * in.w[1] * (T(17) * r0 * t8 + t18 * t13 * b - T(17) * t12 * r1) * t0 - (T(1) / T(255)) * t18 * t13 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t19 = q1 * q1;
    const T t20 = t19 * q1;
    const T t21 = t20 * t20;
    const T t22 = q0 * q0;
    const T t23 = t22 * q0;
    const T t24 = t23 * t23;
    const T t25 = t22 * t22;
    const T t26 = t19 * t19;
    const T t27 = t25 * q0;
    const T t28 = t26 * q1;
    const T t29 = T(15360) * t21 * r1 * slope1 - T(15360) * r0 * slope0 * t24 - T(13) * D * t0 * (T(11) * (T(3) * D * t0 * (T(48) * r0 * slope0 * t23 + T(7) * (T(8) * r0 * slope0 * t22 - T(5) * D * (T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0 - T(3) * (r0 * slope0 - J1 * D - r1 * slope1) * D * t0) * t0 - T(8) * t19 * r1 * slope1) * D * t0 - T(48) * t20 * r1 * slope1) + T(128) * r0 * slope0 * t25 - T(128) * t26 * r1 * slope1) * D * t0 + T(1280) * r0 * slope0 * t27 - T(1280) * t28 * r1 * slope1);
    const T t30 = t24 * q0;
    const T t31 = t21 * q1;
    F = (T(1) / T(215040)) * t29 * t0 * in.w[0] - (T(1) / T(215040)) * in.w[1] * t0 * (T(14336) * r0 * t30 - T(14336) * t31 * r1 - t29 * t0 * b);
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 55 +, 146 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2146 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope1 * slope0;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[0] * M_flat[0] + in.w[1] * M_flat[1];
    G_ab = in.w[1] * M_flat[2] + M_flat[1] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = T(1) / D;
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = t12 * t12;
    const T t14 = t13 * q1;
    const T t15 = t9 * q0;
    const T t16 = t7 * t7;
    const T t17 = t16 * t16;
    const T t18 = t11 * t11;
    const T t19 = t18 * t18;
    const T t20 = T(17) * slope1 * t14 * r1 - T(17) * t15 * r0 * slope0 - T(16) * (T(18) * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) * a + t17 * r0 * slope0 - slope1 * t19 * r1) * t10 * a;
    const T t21 = T(14) * t10 * a * t20 + T(255) * slope1 * t13 * r1 - T(255) * t9 * r0 * slope0;
    const T t22 = T(255) * t9 * r0 + b * t10 * t21 - T(255) * t13 * r1;
    G_ap = -(T(1) / T(3315)) * in.w[1] * t2 * t22 - (T(1) / T(3315)) * t10 * in.w[0] * t21;
    G_ab = -(T(1) / T(3315)) * in.w[1] * (T(13) * t10 * t20 + T(2) * b * t2 * t22 - c * t10 * t21) * t2 - (T(1) / T(3315)) * in.w[0] * t2 * t22;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t23 = q0 * q0;
    const T t24 = t23 * t23;
    const T t25 = t24 * q0;
    const T t26 = q1 * q1;
    const T t27 = t26 * q1;
    const T t28 = t23 * q0;
    const T t29 = t26 * t26;
    const T t30 = t29 * q1;
    const T t31 = T(1280) * t25 * r0 * slope0 - T(11) * D * t2 * (T(3) * (T(48) * slope1 * t27 * r1 - T(7) * D * t2 * (T(8) * t23 * r0 * slope0 - T(8) * slope1 * t26 * r1 - T(5) * (T(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t2 + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0) * D * t2) - T(48) * t28 * r0 * slope0) * D * t2 + T(128) * slope1 * t29 * r1 - T(128) * t24 * r0 * slope0) - T(1280) * slope1 * t30 * r1;
    const T t32 = t28 * t28;
    const T t33 = t27 * t27;
    const T t34 = T(15360) * t32 * r0 + T(13) * b * t2 * t31 - T(15360) * t33 * r1;
    G_ap = -(T(1) / T(15360)) * in.w[0] * t2 * t31 - (T(1) / T(199680)) * in.w[1] * t34 * t2;
    G_ab = -(T(1) / T(2795520)) * (T(28) * b * t34 * t2 - T(13) * (T(15360) * slope1 * t33 * r1 - T(13) * D * t2 * t31 - T(15360) * t32 * r0 * slope0) * t2 - T(182) * c * t2 * t31) * in.w[1] * t2 - (T(1) / T(199680)) * t34 * in.w[0] * t2;
  }
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 58 +, 161 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2159 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
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
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + in.w[1] * M_flat[1];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + M_flat[4] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t7 = T(1) / D;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = q0 * q0;
    const T t13 = t12 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * q0;
    const T t16 = t12 * t12;
    const T t17 = t16 * t16;
    const T t18 = t8 * t8;
    const T t19 = t18 * t18;
    const T t20 = T(17) * r1 * slope1 * t11 - T(17) * slope0 * t15 * r0 - T(16) * (T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) + slope0 * t17 * r0 - r1 * slope1 * t19) * t7 * a;
    F = -(T(1) / T(255)) * in.w[1] * t2 * (b * t7 * t20 + T(17) * t15 * r0 - T(17) * r1 * t11) - (T(1) / T(255)) * t7 * in.w[0] * t20;
    const T t21 = T(255) * r1 * slope1 * t10 + T(14) * t7 * a * t20 - T(255) * slope0 * t14 * r0;
    const T t22 = T(255) * r1 * t10 - T(255) * t14 * r0 - b * t21 * t7;
    G_ap = (T(1) / T(3315)) * in.w[1] * t22 * t2 - (T(1) / T(3315)) * t21 * t7 * in.w[0];
    G_ab = (T(1) / T(3315)) * in.w[1] * t2 * (t21 * c * t7 + T(2) * b * t22 * t2 - T(13) * t7 * t20) + (T(1) / T(3315)) * t22 * t2 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t23 = q1 * q1;
    const T t24 = t23 * q1;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t26 * q1;
    const T t28 = q0 * q0;
    const T t29 = t28 * q0;
    const T t30 = t28 * t28;
    const T t31 = t30 * q0;
    const T t32 = T(1280) * r1 * slope1 * t27 + T(11) * (T(128) * r1 * slope1 * t26 - T(3) * (T(48) * slope0 * t29 * r0 + T(7) * D * t2 * (T(5) * D * t2 * (T(3) * (slope0 * r0 - r1 * slope1 - D * J1) * D * t2 + T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1) + T(8) * slope0 * t28 * r0 - T(8) * r1 * slope1 * t23) - T(48) * r1 * slope1 * t24) * D * t2 - T(128) * slope0 * t30 * r0) * D * t2 - T(1280) * slope0 * t31 * r0;
    const T t33 = t29 * t29;
    const T t34 = T(15360) * r1 * slope1 * t25 + T(13) * t32 * D * t2 - T(15360) * slope0 * t33 * r0;
    const T t35 = t25 * q1;
    const T t36 = t33 * q0;
    F = (T(1) / T(215040)) * t34 * t2 * in.w[0] + (T(1) / T(215040)) * in.w[1] * t2 * (T(14336) * r1 * t35 + b * t34 * t2 - T(14336) * t36 * r0);
    const T t37 = T(15360) * r1 * t25 + T(13) * t32 * b * t2 - T(15360) * t33 * r0;
    G_ap = (T(1) / T(15360)) * t32 * t2 * in.w[0] + (T(1) / T(199680)) * in.w[1] * t37 * t2;
    G_ab = (T(1) / T(199680)) * t37 * t2 * in.w[0] + (T(1) / T(2795520)) * in.w[1] * t2 * (T(13) * t34 * t2 + T(28) * b * t37 * t2 - T(182) * t32 * c * t2);
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Returns false where segment_compact_i13_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 58 +, 161 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i13_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
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
  const T b = -inv_R2 * ab_ap;
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
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[0] * M_flat[4] + in.w[1] * M_flat[5];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = t7 * t7;
    const T t14 = t13 * q0;
    const T t15 = t10 * q1;
    const T t16 = T(1280) * t12 * r1 * slope1 - T(1280) * r0 * slope0 * t14 - T(11) * (T(128) * r0 * slope0 * t13 - T(128) * t11 * r1 * slope1 - T(3) * (T(7) * (T(8) * t10 * r1 * slope1 - T(5) * D * t2 * (T(2) * r0 * slope0 * q0 - T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t2 - T(2) * q1 * r1 * slope1) - T(8) * r0 * slope0 * t7) * D * t2 + T(48) * t15 * r1 * slope1 - T(48) * r0 * slope0 * t8) * D * t2) * D * t2;
    const T t17 = t15 * t15;
    const T t18 = T(15360) * r0 * slope0 * t9 - T(13) * t16 * D * t2 - T(15360) * t17 * r1 * slope1;
    const T t19 = t9 * q0;
    const T t20 = t17 * q1;
    F = -(T(1) / T(215040)) * in.w[1] * (t18 * b * t2 + T(14336) * r0 * t19 - T(14336) * t20 * r1) * t2 - (T(1) / T(215040)) * in.w[0] * t18 * t2;
    const T t21 = T(15360) * t17 * r1 + T(13) * b * t16 * t2 - T(15360) * r0 * t9;
    G_ap = (T(1) / T(199680)) * t21 * in.w[1] * t2 + (T(1) / T(15360)) * in.w[0] * t16 * t2;
    G_ab = (T(1) / T(2795520)) * in.w[1] * (T(28) * t21 * b * t2 - T(182) * c * t16 * t2 - T(13) * t18 * t2) * t2 + (T(1) / T(199680)) * in.w[0] * t21 * t2;
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 54 +, 143 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2124 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + M_flat[1] * in.w[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t5 * t5;
    const T t13 = t12 * t12;
    const T t14 = r1 * slope1 * t11 - slope0 * t13 * r0 - T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1);
    const T t15 = T(1) / D;
    const T t16 = t9 * q1;
    const T t17 = t16 * t16;
    const T t18 = t17 * q1;
    const T t19 = T(16) * t14 * a * t15 + T(17) * r1 * slope1 * t18 - T(17) * slope0 * t8 * r0;
    const T t20 = T(17) * t8 * r0 + t19 * t15 * b - T(17) * r1 * t18;
    F = -(T(1) / T(255)) * t20 * t0 * in.w[1] - (T(1) / T(255)) * t19 * in.w[0] * t15 - (T(1) / T(255)) * (T(15) * t14 * t15 + T(2) * t20 * t0 * b - c * t19 * t15) * t0 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t21 = q0 * q0;
    const T t22 = t21 * q0;
    const T t23 = t22 * t22;
    const T t24 = t21 * t21;
    const T t25 = t24 * q0;
    const T t26 = q1 * q1;
    const T t27 = t26 * q1;
    const T t28 = t26 * t26;
    const T t29 = t28 * q1;
    const T t30 = t27 * t27;
    const T t31 = T(15360) * slope0 * t23 * r0 + T(13) * t0 * D * (T(1280) * slope0 * t25 * r0 + T(11) * t0 * D * (T(128) * slope0 * t24 * r0 - T(3) * (T(7) * t0 * D * (T(8) * r1 * slope1 * q1 * q1 + T(5) * t0 * D * (T(2) * r1 * slope1 * q1 + T(3) * t0 * D * (D * J1 + r1 * slope1 - slope0 * r0) - T(2) * slope0 * q0 * r0) - T(8) * slope0 * t21 * r0) + T(48) * r1 * slope1 * t27 - T(48) * slope0 * t22 * r0) * t0 * D - T(128) * r1 * slope1 * t28) - T(1280) * r1 * slope1 * t29) - T(15360) * r1 * slope1 * t30;
    const T t32 = t23 * q0;
    const T t33 = t30 * q1;
    const T t34 = T(14336) * t32 * r0 + t0 * t31 * b - T(14336) * r1 * t33;
    F = (T(1) / T(3440640)) * (T(16) * c * t0 * t31 - T(15) * t0 * (T(14336) * slope0 * t32 * r0 + t0 * D * t31 - T(14336) * r1 * slope1 * t33) - T(32) * t34 * t0 * b) * t0 * in.w[2] - (T(1) / T(215040)) * in.w[0] * t0 * t31 - (T(1) / T(215040)) * t34 * t0 * in.w[1];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 61 +, 169 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2165 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
    G_ab = in.w[0] * M_flat[1] + in.w[2] * M_flat[3] + in.w[1] * M_flat[2];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * q0;
    const T t7 = t6 * t6;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = T(1) / D;
    const T t13 = t8 * t8;
    const T t14 = t13 * t13;
    const T t15 = t5 * t5;
    const T t16 = t15 * t15;
    const T t17 = t7 * q0;
    const T t18 = T(17) * slope1 * t11 * r1 + T(16) * t12 * a * (slope1 * t14 * r1 - t16 * r0 * slope0 - T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1)) - T(17) * t17 * r0 * slope0;
    const T t19 = T(255) * t7 * r0 * slope0 - T(255) * slope1 * t10 * r1 - T(14) * t18 * t12 * a;
    const T t20 = T(255) * t7 * r0 - t19 * t12 * b - T(255) * t10 * r1;
    const T t21 = T(13) * t18 * t12 + t19 * c * t12 + T(2) * t0 * b * t20;
    G_ap = (T(1) / T(3315)) * t19 * t12 * in.w[0] - (T(1) / T(3315)) * in.w[1] * t0 * t20 - (T(1) / T(3315)) * t21 * in.w[2] * t0;
    G_ab = (T(1) / T(3315)) * (c * t0 * t20 - T(13) * t0 * (T(17) * t17 * r0 + t18 * t12 * b - T(17) * t11 * r1) - T(2) * t21 * t0 * b) * in.w[2] * t0 - (T(1) / T(3315)) * in.w[1] * t21 * t0 - (T(1) / T(3315)) * t0 * in.w[0] * t20;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * q1;
    const T t25 = t22 * q1;
    const T t26 = q0 * q0;
    const T t27 = t26 * q0;
    const T t28 = t26 * t26;
    const T t29 = t28 * q0;
    const T t30 = T(1280) * slope1 * t24 * r1 + T(11) * (T(128) * slope1 * t23 * r1 + T(3) * (T(7) * D * t0 * (T(8) * slope1 * t22 * r1 - T(8) * q0 * q0 * r0 * slope0 - T(5) * (T(2) * q0 * r0 * slope0 - T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t0 - T(2) * slope1 * q1 * r1) * D * t0) + T(48) * slope1 * t25 * r1 - T(48) * t27 * r0 * slope0) * D * t0 - T(128) * t28 * r0 * slope0) * D * t0 - T(1280) * t29 * r0 * slope0;
    const T t31 = t27 * t27;
    const T t32 = t25 * t25;
    const T t33 = T(15360) * t31 * r0 - T(13) * t0 * t30 * b - T(15360) * t32 * r1;
    const T t34 = T(15360) * t31 * r0 * slope0 - T(15360) * slope1 * t32 * r1 - T(13) * D * t0 * t30;
    const T t35 = T(182) * c * t0 * t30 + T(28) * t33 * t0 * b + T(13) * t34 * t0;
    G_ap = (T(1) / T(15360)) * t0 * t30 * in.w[0] - (T(1) / T(2795520)) * in.w[2] * t0 * t35 - (T(1) / T(199680)) * in.w[1] * t33 * t0;
    const T t36 = t31 * q0;
    const T t37 = t32 * q1;
    G_ab = (T(1) / T(2795520)) * (T(14) * c * t33 * t0 - T(13) * (t34 * t0 * b + T(14336) * t36 * r0 - T(14336) * t37 * r1) * t0 - T(2) * t0 * t35 * b) * in.w[2] * t0 - (T(1) / T(199680)) * t33 * t0 * in.w[0] - (T(1) / T(2795520)) * in.w[1] * t0 * t35;
  }
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 67 +, 194 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2182 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, r0 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[2] * in.w[2] + in.w[1] * M_flat[1];
    G_ap = M_flat[6] * in.w[2] + M_flat[5] * in.w[1] + M_flat[4] * in.w[0];
    G_ab = in.w[2] * M_flat[7] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t7 = T(1) / D;
    const T t8 = q1 * q1;
    const T t9 = t8 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * q1;
    const T t12 = t8 * t8;
    const T t13 = t12 * t12;
    const T t14 = q0 * q0;
    const T t15 = t14 * t14;
    const T t16 = t15 * t15;
    const T t17 = t13 * r1 * slope1 - T(18) * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) * a - r0 * slope0 * t16;
    const T t18 = t14 * q0;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = T(17) * t11 * r1 * slope1 + T(16) * a * t7 * t17 - T(17) * r0 * slope0 * t20;
    const T t22 = T(17) * r0 * t20 + t7 * b * t21 - T(17) * t11 * r1;
    F = (T(1) / T(255)) * t2 * (t7 * t21 * c - T(2) * t2 * b * t22 - T(15) * t7 * t17) * in.w[2] - (T(1) / T(255)) * t7 * t21 * in.w[0] - (T(1) / T(255)) * t2 * in.w[1] * t22;
    const T t23 = T(255) * t10 * r1 * slope1 + T(14) * a * t7 * t21 - T(255) * r0 * slope0 * t19;
    const T t24 = T(255) * r0 * t19 + t23 * t7 * b - T(255) * t10 * r1;
    const T t25 = T(13) * t7 * t21 + T(2) * t2 * b * t24 - t23 * t7 * c;
    G_ap = -(T(1) / T(3315)) * t2 * in.w[1] * t24 - (T(1) / T(3315)) * t2 * in.w[2] * t25 - (T(1) / T(3315)) * t23 * t7 * in.w[0];
    G_ab = -(T(1) / T(3315)) * t2 * in.w[1] * t25 - (T(1) / T(3315)) * t2 * t24 * in.w[0] - (T(1) / T(3315)) * (T(2) * t2 * b * t25 + T(13) * t2 * t22 - t2 * t24 * c) * t2 * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t26 = q1 * q1;
    const T t27 = t26 * q1;
    const T t28 = t27 * t27;
    const T t29 = q0 * q0;
    const T t30 = t29 * q0;
    const T t31 = t29 * t29;
    const T t32 = t26 * t26;
    const T t33 = t31 * q0;
    const T t34 = t32 * q1;
    const T t35 = T(11) * t2 * D * (T(3) * t2 * (T(48) * r0 * slope0 * t30 + T(7) * t2 * D * (T(8) * r0 * slope0 * t29 + T(5) * t2 * D * (T(3) * t2 * D * (r0 * slope0 - D * J1 - r1 * slope1) + T(2) * r0 * slope0 * q0 - T(2) * q1 * r1 * slope1) - T(8) * t26 * r1 * slope1) - T(48) * t27 * r1 * slope1) * D + T(128) * r0 * slope0 * t31 - T(128) * t32 * r1 * slope1) + T(1280) * r0 * slope0 * t33 - T(1280) * t34 * r1 * slope1;
    const T t36 = t30 * t30;
    const T t37 = T(15360) * t28 * r1 * slope1 - T(13) * t2 * D * t35 - T(15360) * r0 * slope0 * t36;
    const T t38 = t28 * q1;
    const T t39 = t36 * q0;
    const T t40 = T(14336) * r0 * t39 - t2 * t37 * b - T(14336) * t38 * r1;
    F = (T(1) / T(3440640)) * t2 * in.w[2] * (T(15) * t2 * (t2 * D * t37 + T(14336) * t38 * r1 * slope1 - T(14336) * r0 * slope0 * t39) - T(16) * t2 * t37 * c - T(32) * t2 * b * t40) + (T(1) / T(215040)) * t2 * t37 * in.w[0] - (T(1) / T(215040)) * t2 * in.w[1] * t40;
    const T t41 = T(15360) * r0 * t36 + T(13) * t2 * t35 * b - T(15360) * t28 * r1;
    const T t42 = T(13) * t2 * t37 + T(182) * t2 * t35 * c - T(28) * t2 * b * t41;
    G_ap = (T(1) / T(2795520)) * t42 * t2 * in.w[2] - (T(1) / T(15360)) * t2 * t35 * in.w[0] - (T(1) / T(199680)) * t2 * in.w[1] * t41;
    G_ab = (T(1) / T(2795520)) * t42 * t2 * in.w[1] - (T(1) / T(199680)) * t2 * t41 * in.w[0] - (T(1) / T(2795520)) * t2 * (T(13) * t2 * t40 - T(2) * t42 * t2 * b - T(14) * t2 * c * t41) * in.w[2];
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (ap2 * G_ap - G_ab * ab2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Returns false where segment_compact_i13_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 67 +, 194 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i13_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = (atan2(-slope1, root_minus_a * r1) - atan2(t0, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -t2 * t2 * a * a - D;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[6] * in.w[2] + M_flat[5] * in.w[1] + in.w[0] * M_flat[4];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = t7 * t7;
    const T t9 = q0 * q0;
    const T t10 = t9 * q0;
    const T t11 = t9 * t9;
    const T t12 = t6 * t6;
    const T t13 = t11 * q0;
    const T t14 = t12 * q1;
    const T t15 = T(11) * (T(3) * D * t1 * (T(48) * t10 * r0 * slope0 + T(7) * (T(8) * t9 * r0 * slope0 - T(5) * (T(2) * slope1 * q1 * r1 - T(3) * (r0 * slope0 - D * J1 - slope1 * r1) * D * t1 - T(2) * q0 * r0 * slope0) * D * t1 - T(8) * slope1 * t6 * r1) * D * t1 - T(48) * slope1 * t7 * r1) + T(128) * t11 * r0 * slope0 - T(128) * slope1 * t12 * r1) * D * t1 + T(1280) * t13 * r0 * slope0 - T(1280) * slope1 * t14 * r1;
    const T t16 = t10 * t10;
    const T t17 = T(15360) * slope1 * t8 * r1 - T(13) * t15 * D * t1 - T(15360) * t16 * r0 * slope0;
    const T t18 = t8 * q1;
    const T t19 = t16 * q0;
    const T t20 = t1 * b * t17 + T(14336) * t18 * r1 - T(14336) * t19 * r0;
    F = (T(1) / T(215040)) * in.w[1] * t1 * t20 + (T(1) / T(215040)) * in.w[0] * t1 * t17 + (T(1) / T(3440640)) * (T(15) * t1 * (D * t1 * t17 + T(14336) * slope1 * t18 * r1 - T(14336) * t19 * r0 * slope0) + T(32) * t1 * b * t20 - T(16) * c * t1 * t17) * t1 * in.w[2];
    const T t21 = T(15360) * t16 * r0 + T(13) * t15 * t1 * b - T(15360) * t8 * r1;
    const T t22 = T(28) * t21 * t1 * b - T(13) * t1 * t17 - T(182) * c * t15 * t1;
    G_ap = -(T(1) / T(199680)) * t21 * in.w[1] * t1 - (T(1) / T(2795520)) * t1 * in.w[2] * t22 - (T(1) / T(15360)) * in.w[0] * t15 * t1;
    G_ab = -(T(1) / T(2795520)) * t1 * in.w[2] * (T(2) * t1 * b * t22 - T(13) * t1 * t20 - T(14) * c * t21 * t1) - (T(1) / T(2795520)) * in.w[1] * t1 * t22 - (T(1) / T(199680)) * in.w[0] * t21 * t1;
  }
  const T g_factor = -T(13) * length * inv_R2;
  f = length * F;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(ab2 * G_ab - ap2 * G_ap) * g_factor;
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 59 +, 162 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2154 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
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
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -D - t3 * t3 * a * a;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[3] * M_flat[3] + M_flat[2] * in.w[2] + in.w[0] * M_flat[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = t11 * t11;
    const T t16 = t15 * t15;
    const T t17 = T(1) / D;
    const T t18 = t7 * t7;
    const T t19 = t18 * t18;
    const T t20 = t19 * q1;
    const T t21 = t16 * q0;
    const T t22 = T(19) * t16 * r0 * slope0 - T(18) * t17 * (t20 * r1 * slope1 - t21 * r0 * slope0 - T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a) * a - T(19) * t19 * r1 * slope1;
    const T t23 = T(323) * t14 * r0 * slope0 + T(16) * t22 * t17 * a - T(323) * t10 * r1 * slope1;
    const T t24 = T(323) * t10 * r1 + b * t23 * t17 - T(323) * t14 * r0;
    const T t25 = c * t23 * t17 - T(2) * t24 * b * t2 - T(15) * t22 * t17;
    F = (T(1) / T(4845)) * t24 * in.w[1] * t2 + (T(1) / T(4845)) * in.w[0] * t23 * t17 - (T(1) / T(4845)) * t25 * t2 * in.w[2] - (T(1) / T(4845)) * in.w[3] * (T(2) * b * t25 * t2 + t24 * c * t2 - T(15) * (T(19) * t19 * r1 + b * t22 * t17 - T(19) * t16 * r0) * t2) * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t26 = q1 * q1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = q0 * q0;
    const T t30 = t29 * q0;
    const T t31 = t30 * t30;
    const T t32 = t29 * t29;
    const T t33 = t26 * q1;
    const T t34 = t27 * q1;
    const T t35 = t32 * q0;
    const T t36 = t33 * t33;
    const T t37 = T(15360) * t31 * r0 * slope0 - T(13) * D * (T(11) * (T(128) * t27 * r1 * slope1 - T(128) * t32 * r0 * slope0 - T(3) * (T(48) * t30 * r0 * slope0 - T(7) * (T(8) * t26 * r1 * slope1 - T(8) * t29 * r0 * slope0 - T(5) * D * t2 * (T(2) * q0 * r0 * slope0 + T(3) * D * t2 * (r0 * slope0 - J1 * D - r1 * slope1) - T(2) * q1 * r1 * slope1)) * D * t2 - T(48) * t33 * r1 * slope1) * D * t2) * D * t2 + T(1280) * t34 * r1 * slope1 - T(1280) * t35 * r0 * slope0) * t2 - T(15360) * t36 * r1 * slope1;
    const T t38 = t31 * q0;
    const T t39 = t36 * q1;
    const T t40 = D * t37 * t2 + T(14336) * t38 * r0 * slope0 - T(14336) * t39 * r1 * slope1;
    const T t41 = t32 * t32;
    const T t42 = T(14336) * t39 * r1 - b * t37 * t2 - T(14336) * t38 * r0;
    const T t43 = T(32) * b * t42 * t2 + T(16) * c * t37 * t2 - T(15) * t40 * t2;
    F = (T(1) / T(58490880)) * in.w[3] * (T(15) * t2 * (T(229376) * t28 * r1 - T(17) * b * t40 * t2 - T(229376) * t41 * r0) + T(34) * b * t43 * t2 - T(272) * t42 * c * t2) * t2 + (T(1) / T(3440640)) * t43 * t2 * in.w[2] + (T(1) / T(215040)) * t42 * in.w[1] * t2 - (T(1) / T(215040)) * in.w[0] * t37 * t2;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 69 +, 198 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2199 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i13_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-11, -11, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[1] * in.w[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3] + in.w[2] * M_flat[2];
    G_ab = in.w[0] * M_flat[1] + M_flat[4] * in.w[3] + M_flat[2] * in.w[1] + M_flat[3] * in.w[2];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * q1;
    const T t12 = t11 * t11;
    const T t13 = t10 * t10;
    const T t14 = t13 * t13;
    const T t15 = t7 * t7;
    const T t16 = t15 * t15;
    const T t17 = t16 * q0;
    const T t18 = t14 * q1;
    const T t19 = T(19) * r1 * slope1 * t14 - T(18) * t6 * a * (T(20) * a * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) + slope0 * t17 * r0 - r1 * slope1 * t18) - T(19) * slope0 * t16 * r0;
    const T t20 = t12 * q1;
    const T t21 = t9 * q0;
    const T t22 = T(16) * t6 * a * t19 + T(323) * r1 * slope1 * t20 - T(323) * slope0 * t21 * r0;
    const T t23 = T(4845) * slope0 * t9 * r0 - T(4845) * r1 * slope1 * t12 - T(14) * t6 * a * t22;
    const T t24 = T(4845) * t9 * r0 - T(4845) * r1 * t12 - t6 * b * t23;
    const T t25 = T(13) * t6 * t22 + t6 * t23 * c + T(2) * t1 * b * t24;
    const T t26 = T(323) * t21 * r0 + t6 * b * t22 - T(323) * r1 * t20;
    const T t27 = T(2) * t25 * t1 * b + T(13) * t1 * t26 - t1 * c * t24;
    G_ap = (T(1) / T(62985)) * t6 * in.w[0] * t23 - (T(1) / T(62985)) * t25 * t1 * in.w[2] - (T(1) / T(62985)) * t1 * t27 * in.w[3] - (T(1) / T(62985)) * t1 * t24 * in.w[1];
    G_ab = -(T(1) / T(62985)) * t1 * in.w[2] * t27 - (T(1) / T(62985)) * t25 * t1 * in.w[1] - (T(1) / T(62985)) * t1 * in.w[3] * (T(2) * t1 * t27 * b - T(13) * t1 * (t6 * c * t22 - T(15) * t6 * t19 - T(2) * t1 * b * t26) - t25 * t1 * c) - (T(1) / T(62985)) * t1 * in.w[0] * t24;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t28 = q0 * q0;
    const T t29 = t28 * t28;
    const T t30 = t29 * q0;
    const T t31 = q1 * q1;
    const T t32 = t31 * t31;
    const T t33 = t31 * q1;
    const T t34 = t28 * q0;
    const T t35 = t32 * q1;
    const T t36 = T(1280) * slope0 * t30 * r0 + T(11) * D * t1 * (T(128) * slope0 * t29 * r0 - T(128) * r1 * slope1 * t32 - T(3) * D * (T(48) * r1 * slope1 * t33 + T(7) * D * t1 * (T(5) * D * t1 * (T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0 - T(3) * D * t1 * (slope0 * r0 - D * J1 - r1 * slope1)) + T(8) * r1 * slope1 * t31 - T(8) * slope0 * t28 * r0) - T(48) * slope0 * t34 * r0) * t1) - T(1280) * r1 * slope1 * t35;
    const T t37 = t34 * t34;
    const T t38 = t33 * t33;
    const T t39 = T(15360) * t37 * r0 + T(13) * t1 * b * t36 - T(15360) * r1 * t38;
    const T t40 = T(15360) * slope0 * t37 * r0 + T(13) * D * t1 * t36 - T(15360) * r1 * slope1 * t38;
    const T t41 = T(182) * t1 * t36 * c - T(28) * t1 * b * t39 - T(13) * t1 * t40;
    const T t42 = t37 * q0;
    const T t43 = t38 * q1;
    const T t44 = T(14336) * t42 * r0 + t1 * b * t40 - T(14336) * r1 * t43;
    const T t45 = T(14) * t1 * c * t39 + T(2) * t41 * t1 * b - T(13) * t44 * t1;
    G_ap = (T(1) / T(2795520)) * t41 * t1 * in.w[2] + (T(1) / T(2795520)) * t1 * t45 * in.w[3] - (T(1) / T(15360)) * t1 * in.w[0] * t36 - (T(1) / T(199680)) * t1 * t39 * in.w[1];
    G_ab = (T(1) / T(44728320)) * t1 * (T(32) * t1 * t45 * b - T(16) * t41 * t1 * c - T(13) * t1 * (T(32) * t44 * t1 * b + T(15) * t1 * (D * t1 * t40 + T(14336) * slope0 * t42 * r0 - T(14336) * r1 * slope1 * t43) - T(16) * t1 * c * t40)) * in.w[3] + (T(1) / T(2795520)) * t1 * in.w[2] * t45 + (T(1) / T(2795520)) * t41 * t1 * in.w[1] - (T(1) / T(199680)) * t1 * in.w[0] * t39;
  }
  const T g_factor = -T(13) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Operations: 76 +, 228 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2225 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i13_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[2] * in.w[2] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[3] * in.w[3];
    G_ap = in.w[2] * M_flat[7] + in.w[1] * M_flat[6] + M_flat[8] * in.w[3] + M_flat[5] * in.w[0];
    G_ab = M_flat[8] * in.w[2] + M_flat[9] * in.w[3] + in.w[1] * M_flat[7] + M_flat[6] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = t7 * t7;
    const T t12 = t11 * t11;
    const T t13 = q0 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * t14;
    const T t16 = t15 * q0;
    const T t17 = t12 * q1;
    const T t18 = T(19) * slope1 * t12 * r1 - T(18) * a * t6 * (T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a + t16 * r0 * slope0 - slope1 * t17 * r1) - T(19) * t15 * r0 * slope0;
    const T t19 = t13 * q0;
    const T t20 = t19 * t19;
    const T t21 = t20 * q0;
    const T t22 = T(323) * slope1 * t10 * r1 + T(16) * t18 * a * t6 - T(323) * t21 * r0 * slope0;
    const T t23 = t6 * t22 * b + T(323) * t21 * r0 - T(323) * t10 * r1;
    const T t24 = T(15) * t18 * t6 + T(2) * t1 * t23 * b - t6 * t22 * c;
    F = -(T(1) / T(4845)) * in.w[1] * t1 * t23 - (T(1) / T(4845)) * t1 * (T(2) * t1 * b * t24 + T(15) * t1 * (t18 * t6 * b + T(19) * t15 * r0 - T(19) * t12 * r1) - t1 * t23 * c) * in.w[3] - (T(1) / T(4845)) * t1 * in.w[2] * t24 - (T(1) / T(4845)) * t6 * t22 * in.w[0];
    const T t25 = T(4845) * t20 * r0 * slope0 - T(4845) * slope1 * t9 * r1 - T(14) * a * t6 * t22;
    const T t26 = T(4845) * t20 * r0 - T(4845) * t9 * r1 - t25 * t6 * b;
    const T t27 = T(13) * t6 * t22 + T(2) * t1 * t26 * b + t25 * t6 * c;
    const T t28 = T(2) * t1 * b * t27 + T(13) * t1 * t23 - t1 * t26 * c;
    G_ap = (T(1) / T(62985)) * t25 * t6 * in.w[0] - (T(1) / T(62985)) * in.w[1] * t1 * t26 - (T(1) / T(62985)) * t1 * in.w[2] * t27 - (T(1) / T(62985)) * t1 * in.w[3] * t28;
    G_ab = (T(1) / T(62985)) * t1 * (t1 * t27 * c - T(2) * t1 * b * t28 - T(13) * t1 * t24) * in.w[3] - (T(1) / T(62985)) * in.w[1] * t1 * t27 - (T(1) / T(62985)) * t1 * t26 * in.w[0] - (T(1) / T(62985)) * t1 * in.w[2] * t28;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t29 = q0 * q0;
    const T t30 = t29 * q0;
    const T t31 = t30 * t30;
    const T t32 = q1 * q1;
    const T t33 = t32 * q1;
    const T t34 = t33 * t33;
    const T t35 = t32 * t32;
    const T t36 = t35 * q1;
    const T t37 = t29 * t29;
    const T t38 = t37 * q0;
    const T t39 = T(1280) * slope1 * t36 * r1 + T(11) * t1 * D * (T(128) * slope1 * t35 * r1 - T(3) * t1 * D * (T(48) * t30 * r0 * slope0 + T(7) * (T(5) * t1 * D * (T(2) * q0 * r0 * slope0 - T(2) * slope1 * q1 * r1 - T(3) * t1 * D * (slope1 * r1 + D * J1 - r0 * slope0)) + T(8) * t29 * r0 * slope0 - T(8) * slope1 * t32 * r1) * t1 * D - T(48) * slope1 * t33 * r1) - T(128) * t37 * r0 * slope0) - T(1280) * t38 * r0 * slope0;
    const T t40 = T(15360) * t31 * r0 * slope0 - T(15360) * slope1 * t34 * r1 - T(13) * t1 * D * t39;
    const T t41 = t31 * q0;
    const T t42 = t34 * q1;
    const T t43 = t1 * b * t40 + T(14336) * t41 * r0 - T(14336) * t42 * r1;
    const T t44 = t1 * D * t40 + T(14336) * t41 * r0 * slope0 - T(14336) * slope1 * t42 * r1;
    const T t45 = T(16) * t1 * t40 * c - T(32) * t1 * b * t43 - T(15) * t1 * t44;
    const T t46 = t37 * t37;
    const T t47 = t35 * t35;
    F = (T(1) / T(3440640)) * t1 * in.w[2] * t45 - (T(1) / T(215040)) * in.w[1] * t1 * t43 - (T(1) / T(215040)) * t1 * t40 * in.w[0] - (T(1) / T(58490880)) * t1 * (T(15) * t1 * (T(229376) * t46 * r0 + T(17) * t1 * t44 * b - T(229376) * t47 * r1) - T(272) * t1 * t43 * c - T(34) * t1 * b * t45) * in.w[3];
    const T t48 = T(15360) * t31 * r0 - T(13) * t1 * b * t39 - T(15360) * t34 * r1;
    const T t49 = T(28) * t1 * t48 * b + T(13) * t1 * t40 + T(182) * t1 * t39 * c;
    const T t50 = T(2) * t49 * t1 * b + T(13) * t1 * t43 - T(14) * t1 * t48 * c;
    G_ap = (T(1) / T(15360)) * t1 * in.w[0] * t39 - (T(1) / T(199680)) * in.w[1] * t1 * t48 - (T(1) / T(2795520)) * t1 * in.w[3] * t50 - (T(1) / T(2795520)) * t49 * t1 * in.w[2];
    G_ab = (T(1) / T(44728320)) * t1 * (T(13) * t1 * t45 + T(16) * t49 * t1 * c - T(32) * t1 * b * t50) * in.w[3] - (T(1) / T(2795520)) * t1 * in.w[2] * t50 - (T(1) / T(2795520)) * t49 * in.w[1] * t1 - (T(1) / T(199680)) * t1 * t48 * in.w[0];
  }
  const T g_factor = -T(13) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(13/2) dt
/// Returns false where segment_compact_i13_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 76 +, 228 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i13_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + (slope1 - b) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope0;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - t2 * t2 * a * a;
  const T t4 = slope1 * slope0;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-13, -11, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[3] * in.w[3] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
    G_ap = M_flat[7] * in.w[2] + M_flat[5] * in.w[0] + in.w[1] * M_flat[6] + M_flat[8] * in.w[3];
    G_ab = M_flat[6] * in.w[0] + M_flat[7] * in.w[1] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * q1;
    const T t11 = t6 * q0;
    const T t12 = t9 * t9;
    const T t13 = t12 * q1;
    const T t14 = T(1280) * t8 * r0 * slope0 + T(11) * (T(128) * t7 * r0 * slope0 - T(3) * D * t1 * (T(48) * slope1 * t10 * r1 - T(48) * t11 * r0 * slope0 - T(7) * D * t1 * (T(5) * (T(2) * q0 * r0 * slope0 + T(3) * (r0 * slope0 - D * J1 - slope1 * r1) * D * t1 - T(2) * slope1 * q1 * r1) * D * t1 + T(8) * t6 * r0 * slope0 - T(8) * slope1 * t9 * r1)) - T(128) * slope1 * t12 * r1) * D * t1 - T(1280) * slope1 * t13 * r1;
    const T t15 = t11 * t11;
    const T t16 = t10 * t10;
    const T t17 = T(13) * D * t1 * t14 + T(15360) * t15 * r0 * slope0 - T(15360) * slope1 * t16 * r1;
    const T t18 = t15 * q0;
    const T t19 = t16 * q1;
    const T t20 = D * t1 * t17 + T(14336) * t18 * r0 * slope0 - T(14336) * slope1 * t19 * r1;
    const T t21 = T(14336) * t18 * r0 + t1 * t17 * b - T(14336) * t19 * r1;
    const T t22 = T(15) * t20 * t1 + T(32) * t1 * t21 * b - T(16) * c * t1 * t17;
    const T t23 = t7 * t7;
    const T t24 = t12 * t12;
    F = -(T(1) / T(3440640)) * t22 * t1 * in.w[2] - (T(1) / T(215040)) * t1 * t17 * in.w[0] - (T(1) / T(58490880)) * t1 * (T(15) * (T(229376) * t23 * r0 + T(17) * t20 * t1 * b - T(229376) * t24 * r1) * t1 + T(34) * t22 * t1 * b - T(272) * c * t1 * t21) * in.w[3] - (T(1) / T(215040)) * in.w[1] * t1 * t21;
    const T t25 = T(15360) * t15 * r0 + T(13) * t1 * t14 * b - T(15360) * t16 * r1;
    const T t26 = T(28) * t1 * t25 * b + T(13) * t1 * t17 - T(182) * c * t1 * t14;
    const T t27 = T(13) * t1 * t21 + T(2) * t26 * t1 * b - T(14) * c * t1 * t25;
    G_ap = -(T(1) / T(2795520)) * t27 * t1 * in.w[3] - (T(1) / T(15360)) * t1 * t14 * in.w[0] - (T(1) / T(2795520)) * t26 * t1 * in.w[2] - (T(1) / T(199680)) * in.w[1] * t1 * t25;
    G_ab = -(T(1) / T(199680)) * t1 * t25 * in.w[0] - (T(1) / T(44728320)) * t1 * (T(32) * t27 * t1 * b + T(13) * t22 * t1 - T(16) * c * t26 * t1) * in.w[3] - (T(1) / T(2795520)) * in.w[1] * t26 * t1 - (T(1) / T(2795520)) * t27 * t1 * in.w[2];
  }
  const T g_factor = -T(13) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return !(((t4 >= T(0) && t5 >= T(0)) && !(t3 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 55 +, 155 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 14, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 68 +, 166 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i14_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0];
    G_ab = in.w[0] * M_exact[1];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = g_factor * (G_ap * ap0 - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (G_ap * ap2 - G_ab * ab2);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 88 +, 198 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Returns false where segment_compact_i14_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 88 +, 198 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i14_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(14) * length * inv_R2;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 66 +, 166 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 15, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 80 +, 178 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i14_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
    G_ab = M_exact[2] * in.w[1] + M_exact[1] * in.w[0];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = g_factor * (ap0 * G_ap - G_ab * ab0);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 111 +, 221 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + M_exact[1] * in.w[1];
    G_ap = in.w[0] * M_exact[3] + in.w[1] * M_exact[4];
    G_ab = M_exact[5] * in.w[1] + in.w[0] * M_exact[4];
  }
  const T g_factor = -T(14) * length * inv_R2;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Returns false where segment_compact_i14_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 111 +, 221 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i14_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
    G_ap = M_exact[3] * in.w[0] + M_exact[4] * in.w[1];
    G_ab = in.w[0] * M_exact[4] + in.w[1] * M_exact[5];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 77 +, 177 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[2] * in.w[2] + in.w[1] * M_exact[1] + in.w[0] * M_exact[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 92 +, 190 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i14_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + M_exact[2] * in.w[2];
    G_ab = M_exact[2] * in.w[1] + in.w[0] * M_exact[1] + M_exact[3] * in.w[2];
  }
  const T g_factor = -T(14) * length * inv_R2;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = -(G_ab * ab2 - G_ap * ap2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 134 +, 244 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[0] * M_exact[0] + in.w[2] * M_exact[2];
    G_ap = in.w[2] * M_exact[6] + M_exact[5] * in.w[1] + in.w[0] * M_exact[4];
    G_ab = M_exact[6] * in.w[1] + in.w[2] * M_exact[7] + M_exact[5] * in.w[0];
  }
  const T g_factor = -T(14) * length * inv_R2;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Returns false where segment_compact_i14_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 134 +, 244 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i14_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + in.w[2] * M_exact[2];
    G_ap = M_exact[6] * in.w[2] + in.w[0] * M_exact[4] + in.w[1] * M_exact[5];
    G_ab = in.w[0] * M_exact[5] + M_exact[7] * in.w[2] + M_exact[6] * in.w[1];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 88 +, 188 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + in.w[1] * M_exact[1] + M_exact[3] * in.w[3] + in.w[2] * M_exact[2];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 104 +, 202 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i14_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 10>(-12, -12, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + in.w[0] * M_exact[0] + in.w[2] * M_exact[2] + M_exact[3] * in.w[3];
    G_ab = in.w[0] * M_exact[1] + in.w[3] * M_exact[4] + M_exact[3] * in.w[2] + in.w[1] * M_exact[2];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = (G_ap * ap1 - G_ab * ab1) * g_factor;
  grad[2] = (G_ap * ap2 - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Operations: 157 +, 267 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i14_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[3] * in.w[3] + in.w[2] * M_exact[2] + in.w[1] * M_exact[1];
    G_ap = M_exact[5] * in.w[0] + M_exact[6] * in.w[1] + M_exact[7] * in.w[2] + M_exact[8] * in.w[3];
    G_ab = in.w[1] * M_exact[7] + M_exact[9] * in.w[3] + M_exact[6] * in.w[0] + in.w[2] * M_exact[8];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(14/2) dt
/// Returns false where segment_compact_i14_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 157 +, 267 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i14_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 10>(-14, -12, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[2] * M_exact[2] + in.w[0] * M_exact[0] + M_exact[1] * in.w[1] + in.w[3] * M_exact[3];
    G_ap = M_exact[6] * in.w[1] + M_exact[5] * in.w[0] + in.w[2] * M_exact[7] + M_exact[8] * in.w[3];
    G_ab = in.w[0] * M_exact[6] + in.w[3] * M_exact[9] + in.w[2] * M_exact[8] + in.w[1] * M_exact[7];
  }
  const T g_factor = -T(14) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (ap2 * G_ap - ab2 * G_ab) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 48 +, 122 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 2089 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -(ab_ab - inv_R2 * cross_cross) * inv_R2;
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(-15, -15, 0, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = q0 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * t9;
    F = -(T(1) / T(17)) * (r1 * slope1 * t7 - T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) - slope0 * t10 * r0) * in.w[0] / D;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t11 = q1 * q1;
    const T t12 = t11 * q1;
    const T t13 = q0 * q0;
    const T t14 = t13 * q0;
    const T t15 = t11 * t11;
    const T t16 = t13 * t13;
    const T t17 = t15 * q1;
    const T t18 = t16 * q0;
    const T t19 = t12 * t12;
    const T t20 = t14 * t14;
    const T t21 = t19 * q1;
    const T t22 = t20 * q0;
    F = (T(1) / T(229376)) * t0 * (D * t0 * (T(13) * D * t0 * (T(11) * D * t0 * (T(3) * D * t0 * (T(48) * r1 * slope1 * t12 - T(48) * slope0 * t14 * r0 - T(7) * D * t0 * (T(8) * slope0 * t13 * r0 - T(8) * r1 * slope1 * t11 - T(5) * D * t0 * (T(3) * D * t0 * (D * J1 + r1 * slope1 - slope0 * r0) + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0))) + T(128) * r1 * slope1 * t15 - T(128) * slope0 * t16 * r0) + T(1280) * r1 * slope1 * t17 - T(1280) * slope0 * t18 * r0) + T(15360) * r1 * slope1 * t19 - T(15360) * slope0 * t20 * r0) + T(14336) * r1 * slope1 * t21 - T(14336) * slope0 * t22 * r0) * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 51 +, 133 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2124 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -D - a * a * t2 * t2;
  const T t4 = slope0 * slope1;
  const T t5 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 1, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t6 = T(1) / D;
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t7 * q0;
    const T t14 = t13 * t13;
    const T t15 = t14 * q0;
    const T t16 = t10 * q1;
    const T t17 = t16 * t16;
    const T t18 = t17 * q1;
    const T t19 = T(16) * a * t6 * (T(18) * a * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) + t9 * r0 * slope0 - t12 * r1 * slope1) + T(17) * t15 * r0 * slope0 - T(17) * t18 * r1 * slope1;
    G_ap = (T(1) / T(255)) * t19 * t6 * in.w[0];
    G_ab = (T(1) / T(255)) * (T(17) * t18 * r1 + t19 * t6 * b - T(17) * t15 * r0) * t1 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t20 = q0 * q0;
    const T t21 = t20 * q0;
    const T t22 = t21 * t21;
    const T t23 = q1 * q1;
    const T t24 = t23 * q1;
    const T t25 = t24 * t24;
    const T t26 = t23 * t23;
    const T t27 = t26 * q1;
    const T t28 = t20 * t20;
    const T t29 = t28 * q0;
    const T t30 = T(15360) * t22 * r0 * slope0 - T(15360) * t25 * r1 * slope1 - T(13) * (T(1280) * t27 * r1 * slope1 + T(11) * t1 * D * (T(128) * t26 * r1 * slope1 - T(3) * (T(48) * t21 * r0 * slope0 - T(48) * t24 * r1 * slope1 - T(7) * t1 * D * (T(8) * t23 * r1 * slope1 - T(5) * t1 * D * (T(2) * q0 * r0 * slope0 - T(3) * (J1 * D + r1 * slope1 - r0 * slope0) * t1 * D - T(2) * q1 * r1 * slope1) - T(8) * t20 * r0 * slope0)) * t1 * D - T(128) * t28 * r0 * slope0) - T(1280) * t29 * r0 * slope0) * t1 * D;
    G_ap = -(T(1) / T(215040)) * t30 * t1 * in.w[0];
    const T t31 = t25 * q1;
    const T t32 = t22 * q0;
    G_ab = (T(1) / T(215040)) * t1 * (T(14336) * t31 * r1 - T(14336) * t32 * r0 - t30 * t1 * b) * in.w[0];
  }
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 53 +, 145 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 2128 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
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
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = in.w[0] * M_flat[2];
    G_ab = M_flat[3] * in.w[0];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-17 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = T(18) * J_upward_compact<T>(-17, a, D, slope0, q0, slope1, q1) * a + slope0 * t9 * r0 - r1 * slope1 * t12;
    const T t14 = T(1) / D;
    F = (T(1) / T(17)) * in.w[0] * t13 * t14;
    const T t15 = t10 * q1;
    const T t16 = t15 * t15;
    const T t17 = t16 * q1;
    const T t18 = t7 * q0;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = T(17) * r1 * slope1 * t17 - T(16) * t13 * t14 * a - T(17) * slope0 * t20 * r0;
    G_ap = -(T(1) / T(255)) * in.w[0] * t14 * t21;
    G_ab = -(T(1) / T(255)) * in.w[0] * (T(17) * t20 * r0 + b * t14 * t21 - T(17) * r1 * t17) * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * q1;
    const T t24 = t23 * t23;
    const T t25 = t24 * q1;
    const T t26 = t22 * t22;
    const T t27 = t26 * q1;
    const T t28 = q0 * q0;
    const T t29 = t28 * q0;
    const T t30 = t28 * t28;
    const T t31 = t30 * q0;
    const T t32 = t29 * t29;
    const T t33 = T(13) * (T(1280) * r1 * slope1 * t27 + T(11) * (T(128) * r1 * slope1 * t26 - T(3) * D * t2 * (T(48) * slope0 * t29 * r0 + T(7) * D * t2 * (T(8) * slope0 * t28 * r0 + T(5) * D * t2 * (T(2) * slope0 * q0 * r0 - T(2) * r1 * slope1 * q1 - T(3) * D * t2 * (D * J1 + r1 * slope1 - slope0 * r0)) - T(8) * r1 * slope1 * t22) - T(48) * r1 * slope1 * t23) - T(128) * slope0 * t30 * r0) * D * t2 - T(1280) * slope0 * t31 * r0) * D * t2 + T(15360) * r1 * slope1 * t24 - T(15360) * slope0 * t32 * r0;
    const T t34 = t32 * q0;
    F = (T(1) / T(229376)) * in.w[0] * (T(14336) * r1 * slope1 * t25 + D * t2 * t33 - T(14336) * slope0 * t34 * r0) * t2;
    G_ap = (T(1) / T(215040)) * in.w[0] * t2 * t33;
    G_ab = -(T(1) / T(215040)) * in.w[0] * (T(14336) * t34 * r0 - b * t2 * t33 - T(14336) * r1 * t25) * t2;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Returns false where segment_compact_i15_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 53 +, 145 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i15_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, r0 * root_minus_a) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(t2 * b + (T(1) / T(2))), T((T(3) / T(2)) - t2 * b));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0];
    G_ap = M_flat[2] * in.w[0];
    G_ab = M_flat[3] * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = q0 * q0;
    const T t11 = t10 * t10;
    const T t12 = t11 * q0;
    const T t13 = t10 * q0;
    const T t14 = t7 * t7;
    const T t15 = t14 * q1;
    const T t16 = t13 * t13;
    const T t17 = T(15360) * t9 * r1 * slope1 - T(13) * D * t2 * (T(1280) * r0 * slope0 * t12 + T(11) * D * t2 * (T(3) * D * t2 * (T(7) * D * t2 * (T(8) * r0 * slope0 * t10 - T(5) * D * t2 * (T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0 - T(3) * D * t2 * (r0 * slope0 - D * J1 - r1 * slope1)) - T(8) * t7 * r1 * slope1) + T(48) * r0 * slope0 * t13 - T(48) * t8 * r1 * slope1) + T(128) * r0 * slope0 * t11 - T(128) * t14 * r1 * slope1) - T(1280) * t15 * r1 * slope1) - T(15360) * r0 * slope0 * t16;
    const T t18 = t9 * q1;
    const T t19 = t16 * q0;
    F = (T(1) / T(229376)) * t2 * (D * t2 * t17 + T(14336) * t18 * r1 * slope1 - T(14336) * r0 * slope0 * t19) * in.w[0];
    G_ap = (T(1) / T(215040)) * t2 * in.w[0] * t17;
    G_ab = -(T(1) / T(215040)) * t2 * (T(14336) * r0 * t19 - T(14336) * t18 * r1 - t2 * b * t17) * in.w[0];
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 51 +, 134 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 541 +, 2113 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, r0 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(-15, -15, 1, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + M_flat[0] * in.w[0];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = t8 * q0;
    const T t14 = T(19) * r0 * slope0 * t8 - T(18) * t5 * a * (t12 * r1 * slope1 - T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a - r0 * slope0 * t13) - T(19) * t11 * r1 * slope1;
    F = (T(1) / T(323)) * t5 * in.w[0] * t14 - (T(1) / T(323)) * in.w[1] * (T(19) * r0 * t8 - T(19) * t11 * r1 - t5 * t14 * b) * t0;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t15 = q0 * q0;
    const T t16 = t15 * t15;
    const T t17 = t16 * t16;
    const T t18 = t15 * q0;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = q1 * q1;
    const T t22 = t21 * q1;
    const T t23 = t22 * t22;
    const T t24 = t21 * t21;
    const T t25 = t24 * q1;
    const T t26 = t16 * q0;
    const T t27 = t23 * q1;
    const T t28 = T(14336) * r0 * slope0 * t20 - (T(15360) * t23 * r1 * slope1 + T(13) * D * t0 * (T(11) * D * t0 * (T(128) * t24 * r1 * slope1 - T(3) * (T(48) * r0 * slope0 * t18 + T(7) * D * t0 * (T(8) * r0 * slope0 * t15 - T(8) * t21 * r1 * slope1 - T(5) * D * t0 * (T(3) * (r1 * slope1 + J1 * D - r0 * slope0) * D * t0 + T(2) * q1 * r1 * slope1 - T(2) * r0 * slope0 * q0)) - T(48) * t22 * r1 * slope1) * D * t0 - T(128) * r0 * slope0 * t16) + T(1280) * t25 * r1 * slope1 - T(1280) * r0 * slope0 * t26) - T(15360) * r0 * slope0 * t19) * D * t0 - T(14336) * t27 * r1 * slope1;
    const T t29 = t24 * t24;
    F = -(T(1) / T(3899392)) * in.w[1] * t0 * (T(229376) * r0 * t17 + T(17) * t0 * t28 * b - T(229376) * t29 * r1) - (T(1) / T(229376)) * t0 * t28 * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 57 +, 155 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 2151 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c - in.t0 * (b - slope0)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope0;
  const T t1 = -slope1;
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, root_minus_a * r1)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope1 * slope0;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 2, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = M_flat[1] * in.w[1] + in.w[0] * M_flat[0];
    G_ab = M_flat[1] * in.w[0] + in.w[1] * M_flat[2];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t7 = q0 * q0;
    const T t8 = t7 * q0;
    const T t9 = t8 * t8;
    const T t10 = t9 * q0;
    const T t11 = T(1) / D;
    const T t12 = q1 * q1;
    const T t13 = t12 * q1;
    const T t14 = t13 * t13;
    const T t15 = t14 * q1;
    const T t16 = t12 * t12;
    const T t17 = t16 * t16;
    const T t18 = t7 * t7;
    const T t19 = t18 * t18;
    const T t20 = t19 * q0;
    const T t21 = t17 * q1;
    const T t22 = T(19) * slope1 * t17 * r1 - T(19) * t19 * r0 * slope0 - T(18) * (t20 * r0 * slope0 + T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a - slope1 * t21 * r1) * t11 * a;
    const T t23 = T(323) * slope1 * t15 * r1 + T(16) * t22 * t11 * a - T(323) * t10 * r0 * slope0;
    const T t24 = T(323) * t10 * r0 + b * t11 * t23 - T(323) * t15 * r1;
    G_ap = -(T(1) / T(4845)) * in.w[1] * t24 * t2 - (T(1) / T(4845)) * t11 * in.w[0] * t23;
    G_ab = -(T(1) / T(4845)) * in.w[1] * (T(15) * t22 * t11 + T(2) * b * t24 * t2 - c * t11 * t23) * t2 - (T(1) / T(4845)) * t24 * in.w[0] * t2;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t25 = q1 * q1;
    const T t26 = t25 * q1;
    const T t27 = t26 * t26;
    const T t28 = q0 * q0;
    const T t29 = t28 * q0;
    const T t30 = t29 * t29;
    const T t31 = t28 * t28;
    const T t32 = t31 * q0;
    const T t33 = t25 * t25;
    const T t34 = t33 * q1;
    const T t35 = T(15360) * slope1 * t27 * r1 - T(15360) * t30 * r0 * slope0 - T(13) * D * t2 * (T(1280) * t32 * r0 * slope0 - T(1280) * slope1 * t34 * r1 - T(11) * D * t2 * (T(128) * slope1 * t33 * r1 - T(128) * t31 * r0 * slope0 - T(3) * (T(7) * (T(8) * t28 * r0 * slope0 - T(5) * (T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t2 + T(2) * slope1 * q1 * r1 - T(2) * q0 * r0 * slope0) * D * t2 - T(8) * slope1 * t25 * r1) * D * t2 + T(48) * t29 * r0 * slope0 - T(48) * slope1 * t26 * r1) * D * t2));
    const T t36 = t30 * q0;
    const T t37 = t27 * q1;
    const T t38 = T(14336) * t36 * r0 - T(14336) * t37 * r1 - b * t35 * t2;
    G_ap = (T(1) / T(215040)) * t35 * in.w[0] * t2 - (T(1) / T(215040)) * in.w[1] * t38 * t2;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t2 * (T(15) * t2 * (t35 * D * t2 + T(14336) * slope1 * t37 * r1 - T(14336) * t36 * r0 * slope0) - T(32) * b * t38 * t2 - T(16) * t35 * c * t2) - (T(1) / T(215040)) * t38 * in.w[0] * t2;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - G_ab * ab1) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 60 +, 171 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 2164 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T((slope1 - b) * in.t1 + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -a * a * t1 * t1 - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[4] * in.w[1] + in.w[0] * M_flat[3];
    G_ab = M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t5 = q0 * q0;
    const T t6 = t5 * t5;
    const T t7 = t6 * t6;
    const T t8 = t7 * q0;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = T(1) / D;
    const T t14 = T(19) * slope0 * t7 * r0 + T(18) * (T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a + slope0 * t8 * r0 - r1 * slope1 * t12) * t13 * a - T(19) * r1 * slope1 * t11;
    F = (T(1) / T(323)) * t14 * t13 * in.w[0] + (T(1) / T(323)) * (T(19) * r1 * t11 + t14 * t13 * b - T(19) * t7 * r0) * t0 * in.w[1];
    const T t15 = t5 * q0;
    const T t16 = t15 * t15;
    const T t17 = t16 * q0;
    const T t18 = t9 * q1;
    const T t19 = t18 * t18;
    const T t20 = t19 * q1;
    const T t21 = T(323) * r1 * slope1 * t20 - T(16) * t14 * t13 * a - T(323) * slope0 * t17 * r0;
    const T t22 = T(323) * t17 * r0 + t13 * t21 * b - T(323) * r1 * t20;
    G_ap = -(T(1) / T(4845)) * t0 * t22 * in.w[1] - (T(1) / T(4845)) * t13 * t21 * in.w[0];
    G_ab = (T(1) / T(4845)) * t0 * in.w[1] * (c * t13 * t21 + T(15) * t14 * t13 - T(2) * t0 * t22 * b) - (T(1) / T(4845)) * t0 * in.w[0] * t22;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t23 = q1 * q1;
    const T t24 = t23 * q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * q1;
    const T t27 = q0 * q0;
    const T t28 = t27 * q0;
    const T t29 = t28 * t28;
    const T t30 = t27 * t27;
    const T t31 = t30 * q0;
    const T t32 = t23 * t23;
    const T t33 = t32 * q1;
    const T t34 = T(15360) * r1 * slope1 * t25 - T(15360) * slope0 * t29 * r0 - T(13) * D * t0 * (T(1280) * slope0 * t31 * r0 + T(11) * (T(128) * slope0 * t30 * r0 - T(128) * r1 * slope1 * t32 - T(3) * D * (T(48) * r1 * slope1 * t24 - T(7) * (T(5) * (T(2) * slope0 * q0 * r0 - T(3) * D * (D * J1 + r1 * slope1 - slope0 * r0) * t0 - T(2) * r1 * slope1 * q1) * D * t0 + T(8) * slope0 * t27 * r0 - T(8) * r1 * slope1 * t23) * D * t0 - T(48) * slope0 * t28 * r0) * t0) * D * t0 - T(1280) * r1 * slope1 * t33);
    const T t35 = t29 * q0;
    const T t36 = T(14336) * r1 * slope1 * t26 + D * t0 * t34 - T(14336) * slope0 * t35 * r0;
    const T t37 = t32 * t32;
    const T t38 = t30 * t30;
    F = (T(1) / T(3899392)) * (T(17) * t36 * t0 * b + T(229376) * r1 * t37 - T(229376) * t38 * r0) * t0 * in.w[1] + (T(1) / T(229376)) * t36 * t0 * in.w[0];
    const T t39 = t0 * t34 * b + T(14336) * r1 * t26 - T(14336) * t35 * r0;
    G_ap = (T(1) / T(215040)) * t39 * t0 * in.w[1] + (T(1) / T(215040)) * t0 * t34 * in.w[0];
    G_ab = (T(1) / T(215040)) * t39 * t0 * in.w[0] - (T(1) / T(3440640)) * t0 * (T(16) * c * t0 * t34 - T(32) * t39 * t0 * b - T(15) * t36 * t0) * in.w[1];
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Returns false where segment_compact_i15_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 60 +, 171 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i15_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -D - a * a * t3 * t3;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[1] * M_flat[1] + in.w[0] * M_flat[0];
    G_ap = in.w[0] * M_flat[3] + in.w[1] * M_flat[4];
    G_ab = in.w[1] * M_flat[5] + in.w[0] * M_flat[4];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * q0;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = t11 * t11;
    const T t16 = t15 * q0;
    const T t17 = t7 * t7;
    const T t18 = t17 * q1;
    const T t19 = T(15360) * r0 * slope0 * t13 + T(13) * D * t2 * (T(1280) * r0 * slope0 * t16 + T(11) * (T(128) * r0 * slope0 * t15 - T(3) * (T(48) * t8 * r1 * slope1 + T(7) * (T(5) * (T(2) * q1 * r1 * slope1 + T(3) * (r1 * slope1 + D * J1 - r0 * slope0) * D * t2 - T(2) * r0 * slope0 * q0) * D * t2 + T(8) * t7 * r1 * slope1 - T(8) * r0 * slope0 * t11) * D * t2 - T(48) * r0 * slope0 * t12) * D * t2 - T(128) * t17 * r1 * slope1) * D * t2 - T(1280) * t18 * r1 * slope1) - T(15360) * t9 * r1 * slope1;
    const T t20 = T(14336) * t10 * r1 * slope1 - T(14336) * r0 * slope0 * t14 - t19 * D * t2;
    const T t21 = t17 * t17;
    const T t22 = t15 * t15;
    F = (T(1) / T(3899392)) * in.w[1] * (T(17) * b * t20 * t2 + T(229376) * t21 * r1 - T(229376) * r0 * t22) * t2 + (T(1) / T(229376)) * in.w[0] * t20 * t2;
    const T t23 = t19 * b * t2 + T(14336) * r0 * t14 - T(14336) * t10 * r1;
    G_ap = -(T(1) / T(215040)) * in.w[0] * t19 * t2 - (T(1) / T(215040)) * in.w[1] * t2 * t23;
    G_ab = (T(1) / T(3440640)) * in.w[1] * (T(16) * t19 * c * t2 + T(15) * t20 * t2 - T(32) * b * t2 * t23) * t2 - (T(1) / T(215040)) * in.w[0] * t2 * t23;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 56 +, 154 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 2123 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T((slope0 - b) * in.t0 + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = (atan2(-slope1, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(-15, -15, 2, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[0] * in.w[0] + M_flat[1] * in.w[1] + M_flat[2] * in.w[2];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * q1;
    const T t14 = T(20) * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) * a + slope0 * t9 * r0 - r1 * slope1 * t13;
    const T t15 = T(18) * t14 * a * t5 + T(19) * slope0 * t8 * r0 - T(19) * r1 * slope1 * t12;
    const T t16 = T(19) * r1 * t12 + t5 * t15 * b - T(19) * t8 * r0;
    F = (T(1) / T(323)) * in.w[0] * t5 * t15 + (T(1) / T(323)) * t16 * t0 * in.w[1] - (T(1) / T(323)) * t0 * (c * t5 * t15 - T(17) * t14 * t5 - T(2) * t16 * t0 * b) * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t17 = q1 * q1;
    const T t18 = t17 * t17;
    const T t19 = t18 * t18;
    const T t20 = t17 * q1;
    const T t21 = t20 * t20;
    const T t22 = t18 * q1;
    const T t23 = q0 * q0;
    const T t24 = t23 * q0;
    const T t25 = t23 * t23;
    const T t26 = t25 * q0;
    const T t27 = t24 * t24;
    const T t28 = t21 * q1;
    const T t29 = t27 * q0;
    const T t30 = (T(15360) * r1 * slope1 * t21 + T(13) * (T(1280) * r1 * slope1 * t22 + T(11) * t0 * D * (T(128) * r1 * slope1 * t18 - T(3) * t0 * D * (T(48) * slope0 * t24 * r0 + T(7) * t0 * D * (T(5) * t0 * D * (T(2) * slope0 * q0 * r0 - T(3) * (r1 * slope1 + D * J1 - slope0 * r0) * t0 * D - T(2) * r1 * slope1 * q1) + T(8) * slope0 * t23 * r0 - T(8) * r1 * slope1 * t17) - T(48) * r1 * slope1 * t20) - T(128) * slope0 * t25 * r0) - T(1280) * slope0 * t26 * r0) * t0 * D - T(15360) * slope0 * t27 * r0) * t0 * D + T(14336) * r1 * slope1 * t28 - T(14336) * slope0 * t29 * r0;
    const T t31 = t25 * t25;
    const T t32 = T(229376) * r1 * t19 + T(17) * t30 * t0 * b - T(229376) * t31 * r0;
    F = (T(1) / T(70189056)) * (T(36) * t0 * t32 * b + T(17) * t0 * (T(17) * t30 * t0 * D + T(229376) * r1 * slope1 * t19 - T(229376) * slope0 * t31 * r0) - T(306) * c * t30 * t0) * t0 * in.w[2] + (T(1) / T(3899392)) * t0 * t32 * in.w[1] + (T(1) / T(229376)) * t30 * in.w[0] * t0;
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 63 +, 178 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 2170 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c - in.t1 * (b - slope1)));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(-slope0, root_minus_a * r0)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t1 = T(1) / a;
  const T t2 = max(T(t1 * b + (T(1) / T(2))), T((T(3) / T(2)) - t1 * b));
  const T t3 = -a * a * t2 * t2 - D;
  const T t4 = slope0 * slope1;
  const T t5 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t3 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 3, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[1] * M_flat[1] + in.w[2] * M_flat[2] + M_flat[0] * in.w[0];
    G_ab = M_flat[1] * in.w[0] + in.w[2] * M_flat[3] + in.w[1] * M_flat[2];
  } else if (t4 >= T(0) && t5 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t6 = q1 * q1;
    const T t7 = t6 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * q1;
    const T t10 = q0 * q0;
    const T t11 = t10 * q0;
    const T t12 = t11 * t11;
    const T t13 = t12 * q0;
    const T t14 = t10 * t10;
    const T t15 = t14 * t14;
    const T t16 = t15 * q0;
    const T t17 = t6 * t6;
    const T t18 = t17 * t17;
    const T t19 = t18 * q1;
    const T t20 = T(1) / D;
    const T t21 = T(19) * slope0 * t15 * r0 + T(18) * a * (T(20) * a * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) + slope0 * t16 * r0 - r1 * slope1 * t19) * t20 - T(19) * r1 * slope1 * t18;
    const T t22 = T(323) * r1 * slope1 * t9 - T(323) * slope0 * t13 * r0 - T(16) * a * t21 * t20;
    const T t23 = t22 * b * t20 + T(323) * t13 * r0 - T(323) * r1 * t9;
    const T t24 = T(2) * t1 * b * t23 - T(15) * t21 * t20 - t22 * c * t20;
    G_ap = -(T(1) / T(4845)) * t22 * in.w[0] * t20 - (T(1) / T(4845)) * t1 * in.w[1] * t23 - (T(1) / T(4845)) * t1 * in.w[2] * t24;
    G_ab = -(T(1) / T(4845)) * t1 * t23 * in.w[0] - (T(1) / T(4845)) * t1 * (T(2) * t1 * b * t24 - t1 * t23 * c - T(15) * t1 * (T(19) * r1 * t18 + b * t21 * t20 - T(19) * t15 * r0)) * in.w[2] - (T(1) / T(4845)) * t1 * in.w[1] * t24;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t25 = q1 * q1;
    const T t26 = t25 * q1;
    const T t27 = t26 * t26;
    const T t28 = t25 * t25;
    const T t29 = t28 * q1;
    const T t30 = q0 * q0;
    const T t31 = t30 * q0;
    const T t32 = t30 * t30;
    const T t33 = t32 * q0;
    const T t34 = t31 * t31;
    const T t35 = T(15360) * r1 * slope1 * t27 + T(13) * t1 * (T(1280) * r1 * slope1 * t29 - T(11) * t1 * (T(3) * t1 * (T(48) * slope0 * t31 * r0 - T(48) * r1 * slope1 * t26 - T(7) * t1 * (T(5) * t1 * (T(3) * t1 * (r1 * slope1 + J1 * D - slope0 * r0) * D + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0) * D + T(8) * r1 * slope1 * t25 - T(8) * slope0 * t30 * r0) * D) * D + T(128) * slope0 * t32 * r0 - T(128) * r1 * slope1 * t28) * D - T(1280) * slope0 * t33 * r0) * D - T(15360) * slope0 * t34 * r0;
    const T t36 = t27 * q1;
    const T t37 = t34 * q0;
    const T t38 = t1 * t35 * b + T(14336) * r1 * t36 - T(14336) * t37 * r0;
    const T t39 = t1 * t35 * D + T(14336) * r1 * slope1 * t36 - T(14336) * slope0 * t37 * r0;
    const T t40 = T(32) * t1 * b * t38 + T(15) * t1 * t39 - T(16) * t1 * t35 * c;
    G_ap = (T(1) / T(215040)) * t1 * t35 * in.w[0] + (T(1) / T(3440640)) * t1 * in.w[2] * t40 + (T(1) / T(215040)) * t1 * in.w[1] * t38;
    const T t41 = t28 * t28;
    const T t42 = t32 * t32;
    G_ab = (T(1) / T(3440640)) * t1 * in.w[1] * t40 + (T(1) / T(215040)) * t1 * t38 * in.w[0] - (T(1) / T(58490880)) * t1 * in.w[2] * (T(272) * t1 * c * t38 - T(34) * t1 * b * t40 - T(15) * t1 * (T(229376) * r1 * t41 + T(17) * t1 * b * t39 - T(229376) * t42 * r0));
  }
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - G_ab * ab1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 69 +, 205 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 2187 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c + (slope0 - b) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, root_minus_a * r1)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope0 * slope1;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + in.w[0] * M_flat[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[5] * in.w[1] + in.w[2] * M_flat[6] + M_flat[4] * in.w[0];
    G_ab = in.w[1] * M_flat[6] + in.w[2] * M_flat[7] + in.w[0] * M_flat[5];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-19 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = t8 * q0;
    const T t10 = q1 * q1;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * q1;
    const T t14 = slope0 * t9 * r0 + T(20) * a * J_upward_compact<T>(-19, a, D, slope0, q0, slope1, q1) - slope1 * t13 * r1;
    const T t15 = T(18) * a * t5 * t14 + T(19) * slope0 * t8 * r0 - T(19) * slope1 * t12 * r1;
    const T t16 = t5 * b * t15 + T(19) * t12 * r1 - T(19) * t8 * r0;
    F = (T(1) / T(323)) * t0 * in.w[1] * t16 + (T(1) / T(323)) * in.w[0] * t5 * t15 - (T(1) / T(323)) * in.w[2] * t0 * (c * t5 * t15 - T(17) * t5 * t14 - T(2) * t0 * b * t16);
    const T t17 = t6 * q0;
    const T t18 = t17 * t17;
    const T t19 = t18 * q0;
    const T t20 = t10 * q1;
    const T t21 = t20 * t20;
    const T t22 = t21 * q1;
    const T t23 = T(16) * a * t5 * t15 + T(323) * slope0 * t19 * r0 - T(323) * slope1 * t22 * r1;
    const T t24 = t23 * t5 * b + T(323) * t22 * r1 - T(323) * t19 * r0;
    const T t25 = T(15) * t5 * t15 + T(2) * t0 * b * t24 - c * t23 * t5;
    G_ap = (T(1) / T(4845)) * t0 * in.w[1] * t24 + (T(1) / T(4845)) * in.w[0] * t23 * t5 + (T(1) / T(4845)) * in.w[2] * t0 * t25;
    G_ab = (T(1) / T(4845)) * in.w[0] * t0 * t24 + (T(1) / T(4845)) * t0 * in.w[1] * t25 - (T(1) / T(4845)) * in.w[2] * t0 * (c * t0 * t24 - T(2) * t0 * t25 * b - T(15) * t0 * t16);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t26 = q1 * q1;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = q0 * q0;
    const T t30 = t29 * t29;
    const T t31 = t30 * t30;
    const T t32 = t29 * q0;
    const T t33 = t26 * q1;
    const T t34 = t30 * q0;
    const T t35 = t27 * q1;
    const T t36 = t32 * t32;
    const T t37 = t33 * t33;
    const T t38 = T(13) * (T(11) * (T(128) * slope0 * t30 * r0 + T(3) * t0 * D * (T(7) * (T(8) * slope0 * t29 * r0 - T(8) * slope1 * t26 * r1 - T(5) * (T(3) * t0 * D * (D * J1 + slope1 * r1 - slope0 * r0) + T(2) * slope1 * q1 * r1 - T(2) * slope0 * q0 * r0) * t0 * D) * t0 * D + T(48) * slope0 * t32 * r0 - T(48) * slope1 * t33 * r1) - T(128) * slope1 * t27 * r1) * t0 * D + T(1280) * slope0 * t34 * r0 - T(1280) * slope1 * t35 * r1) * t0 * D + T(15360) * slope0 * t36 * r0 - T(15360) * slope1 * t37 * r1;
    const T t39 = t36 * q0;
    const T t40 = t37 * q1;
    const T t41 = t38 * t0 * D + T(14336) * slope0 * t39 * r0 - T(14336) * slope1 * t40 * r1;
    const T t42 = T(229376) * t28 * r1 - T(229376) * t31 * r0 - T(17) * t0 * t41 * b;
    F = (T(1) / T(70189056)) * in.w[2] * t0 * (T(17) * (T(229376) * slope1 * t28 * r1 - T(229376) * slope0 * t31 * r0 - T(17) * t0 * D * t41) * t0 + T(306) * c * t0 * t41 + T(36) * t0 * t42 * b) + (T(1) / T(3899392)) * t0 * in.w[1] * t42 - (T(1) / T(229376)) * in.w[0] * t0 * t41;
    const T t43 = T(14336) * t40 * r1 - t38 * t0 * b - T(14336) * t39 * r0;
    const T t44 = T(15) * t0 * t41 - T(32) * t43 * t0 * b - T(16) * c * t38 * t0;
    G_ap = (T(1) / T(215040)) * t43 * t0 * in.w[1] - (T(1) / T(215040)) * t38 * in.w[0] * t0 - (T(1) / T(3440640)) * in.w[2] * t0 * t44;
    G_ab = (T(1) / T(58490880)) * in.w[2] * t0 * (T(15) * t0 * t42 - T(272) * c * t43 * t0 - T(34) * t0 * b * t44) + (T(1) / T(215040)) * t43 * in.w[0] * t0 - (T(1) / T(3440640)) * t0 * in.w[1] * t44;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -(ab1 * G_ab - G_ap * ap1) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Returns false where segment_compact_i15_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 69 +, 205 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i15_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
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
  const T J1 = -(atan2(t0, root_minus_a * r0) - atan2(t1, r1 * root_minus_a)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 8> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[0] * in.w[0] + M_flat[1] * in.w[1];
    G_ap = M_flat[6] * in.w[2] + M_flat[4] * in.w[0] + M_flat[5] * in.w[1];
    G_ab = in.w[2] * M_flat[7] + M_flat[6] * in.w[1] + in.w[0] * M_flat[5];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * q1;
    const T t9 = t8 * t8;
    const T t10 = q0 * q0;
    const T t11 = t10 * q0;
    const T t12 = t11 * t11;
    const T t13 = t10 * t10;
    const T t14 = t7 * t7;
    const T t15 = t13 * q0;
    const T t16 = t14 * q1;
    const T t17 = T(15360) * r1 * slope1 * t9 - T(15360) * slope0 * t12 * r0 - T(13) * (T(11) * D * (T(3) * (T(48) * slope0 * t11 * r0 + T(7) * (T(5) * (T(2) * slope0 * q0 * r0 - T(3) * (r1 * slope1 + D * J1 - slope0 * r0) * D * t2 - T(2) * r1 * slope1 * q1) * D * t2 + T(8) * slope0 * t10 * r0 - T(8) * r1 * slope1 * t7) * D * t2 - T(48) * r1 * slope1 * t8) * D * t2 + T(128) * slope0 * t13 * r0 - T(128) * r1 * slope1 * t14) * t2 + T(1280) * slope0 * t15 * r0 - T(1280) * r1 * slope1 * t16) * D * t2;
    const T t18 = t9 * q1;
    const T t19 = t12 * q0;
    const T t20 = t17 * D * t2 + T(14336) * r1 * slope1 * t18 - T(14336) * slope0 * t19 * r0;
    const T t21 = t13 * t13;
    const T t22 = t14 * t14;
    const T t23 = T(229376) * t21 * r0 - T(17) * b * t20 * t2 - T(229376) * r1 * t22;
    F = (T(1) / T(229376)) * in.w[0] * t20 * t2 - (T(1) / T(70189056)) * in.w[2] * (T(17) * (T(229376) * slope0 * t21 * r0 - T(229376) * r1 * slope1 * t22 - T(17) * t20 * D * t2) * t2 + T(36) * b * t23 * t2 + T(306) * c * t20 * t2) * t2 - (T(1) / T(3899392)) * t23 * t2 * in.w[1];
    const T t24 = T(14336) * t19 * r0 - T(14336) * r1 * t18 - t17 * b * t2;
    const T t25 = T(15) * t20 * t2 - T(32) * b * t2 * t24 - T(16) * t17 * c * t2;
    G_ap = (T(1) / T(215040)) * t17 * in.w[0] * t2 + (T(1) / T(3440640)) * t25 * in.w[2] * t2 - (T(1) / T(215040)) * t2 * in.w[1] * t24;
    G_ab = (T(1) / T(3440640)) * t25 * t2 * in.w[1] - (T(1) / T(58490880)) * in.w[2] * t2 * (T(15) * t23 * t2 - T(34) * t25 * b * t2 - T(272) * c * t2 * t24) - (T(1) / T(215040)) * in.w[0] * t2 * t24;
  }
  const T g_factor = -T(15) * length * inv_R2;
  f = F * length;
  grad[0] = g_factor * (G_ap * ap0 - ab0 * G_ab);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 61 +, 174 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 2156 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(in.t0 * (slope0 - b) + c));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(in.t1 * (slope1 - b) + c));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T J1 = -(atan2(-slope0, root_minus_a * r0) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T F;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -D - a * a * t1 * t1;
  const T t3 = slope0 * slope1;
  const T t4 = a * max(T(q0), T(q1)) - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(-15, -15, 3, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[3] * M_flat[3] + in.w[0] * M_flat[0] + in.w[2] * M_flat[2] + in.w[1] * M_flat[1];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-21 = J_upward_compact(…)
    const T t5 = T(1) / D;
    const T t6 = q0 * q0;
    const T t7 = t6 * t6;
    const T t8 = t7 * t7;
    const T t9 = q1 * q1;
    const T t10 = t9 * t9;
    const T t11 = t10 * t10;
    const T t12 = t11 * q1;
    const T t13 = t10 * q1;
    const T t14 = t13 * t13;
    const T t15 = t7 * q0;
    const T t16 = t15 * t15;
    const T t17 = t8 * q0;
    const T t18 = T(21) * r1 * slope1 * t12 + T(20) * (r1 * slope1 * t14 - slope0 * t16 * r0 - T(22) * a * J_upward_compact<T>(-21, a, D, slope0, q0, slope1, q1)) * t5 * a - T(21) * slope0 * t17 * r0;
    const T t19 = T(133) * slope0 * t8 * r0 - T(6) * t5 * a * t18 - T(133) * r1 * slope1 * t11;
    const T t20 = T(133) * r1 * t11 + t5 * b * t19 - T(133) * t8 * r0;
    const T t21 = T(17) * t5 * t18 + T(3) * t5 * c * t19 - T(6) * t0 * b * t20;
    F = (T(1) / T(2261)) * t5 * in.w[0] * t19 + (T(1) / T(2261)) * in.w[1] * t0 * t20 - (T(1) / T(6783)) * t0 * (T(17) * t0 * (t5 * b * t18 + T(21) * t17 * r0 - T(21) * r1 * t12) + T(3) * t0 * t20 * c + T(2) * t0 * b * t21) * in.w[3] - (T(1) / T(6783)) * t0 * in.w[2] * t21;
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t22 = q1 * q1;
    const T t23 = t22 * t22;
    const T t24 = t23 * t23;
    const T t25 = t24 * q1;
    const T t26 = q0 * q0;
    const T t27 = t26 * t26;
    const T t28 = t27 * t27;
    const T t29 = t28 * q0;
    const T t30 = t26 * q0;
    const T t31 = t30 * t30;
    const T t32 = t31 * q0;
    const T t33 = t27 * q0;
    const T t34 = t22 * q1;
    const T t35 = t23 * q1;
    const T t36 = t34 * t34;
    const T t37 = t36 * q1;
    const T t38 = T(14336) * slope0 * t32 * r0 + D * t0 * (T(13) * D * t0 * (T(1280) * slope0 * t33 * r0 + T(11) * D * t0 * (T(128) * slope0 * t27 * r0 - T(3) * D * t0 * (T(48) * r1 * slope1 * t34 - T(48) * slope0 * t30 * r0 - T(7) * D * t0 * (T(8) * slope0 * t26 * r0 + T(5) * (T(2) * slope0 * q0 * r0 + T(3) * D * t0 * (slope0 * r0 - D * J1 - r1 * slope1) - T(2) * r1 * slope1 * q1) * D * t0 - T(8) * r1 * slope1 * t22)) - T(128) * r1 * slope1 * t23) - T(1280) * r1 * slope1 * t35) + T(15360) * slope0 * t31 * r0 - T(15360) * r1 * slope1 * t36) - T(14336) * r1 * slope1 * t37;
    const T t39 = T(229376) * slope0 * t28 * r0 + T(17) * D * t0 * t38 - T(229376) * r1 * slope1 * t24;
    const T t40 = T(17) * t0 * t38 * b + T(229376) * t28 * r0 - T(229376) * r1 * t24;
    const T t41 = T(36) * t0 * t40 * b + T(17) * t0 * t39 - T(306) * t0 * t38 * c;
    F = (T(1) / T(1333592064)) * t0 * in.w[3] * (T(17) * (T(4128768) * r1 * t25 - T(4128768) * t29 * r0 - T(19) * t0 * t39 * b) * t0 + T(342) * t0 * t40 * c - T(38) * t0 * t41 * b) - (T(1) / T(229376)) * t0 * t38 * in.w[0] - (T(1) / T(70189056)) * t0 * t41 * in.w[2] - (T(1) / T(3899392)) * in.w[1] * t0 * t40;
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 71 +, 209 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 2206 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
std::array<T, 3> segment_compact_i15_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  const T D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  const T slope0 = in.t0 * a - b;
  const T q0 = max(T(0), T(c + in.t0 * (slope0 - b)));
  const T r0 = sqrt(q0);
  const T slope1 = a * in.t1 - b;
  const T q1 = max(T(0), T(c + in.t1 * (slope1 - b)));
  const T r1 = sqrt(q1);
  const T root_minus_a = length * inv_R;
  const T J1 = -(atan2(-slope0, r0 * root_minus_a) - atan2(-slope1, r1 * root_minus_a)) / root_minus_a;
  T G_ap;
  T G_ab;
  const T t0 = T(1) / a;
  const T t1 = max(T(t0 * b + (T(1) / T(2))), T((T(3) / T(2)) - t0 * b));
  const T t2 = -t1 * t1 * a * a - D;
  const T t3 = slope1 * slope0;
  const T t4 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t2 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(-13, -13, 4, a, b, c, in.t0, in.t1, M_flat.data());
    G_ap = in.w[3] * M_flat[3] + in.w[1] * M_flat[1] + M_flat[0] * in.w[0] + M_flat[2] * in.w[2];
    G_ab = M_flat[2] * in.w[1] + M_flat[3] * in.w[2] + M_flat[1] * in.w[0] + in.w[3] * M_flat[4];
  } else if (t3 >= T(0) && t4 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-21 = J_upward_compact(…)
    const T t5 = q1 * q1;
    const T t6 = t5 * q1;
    const T t7 = t6 * t6;
    const T t8 = t7 * q1;
    const T t9 = t5 * t5;
    const T t10 = t9 * t9;
    const T t11 = q0 * q0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t13 * q0;
    const T t15 = t12 * q0;
    const T t16 = t15 * t15;
    const T t17 = t9 * q1;
    const T t18 = t17 * t17;
    const T t19 = T(1) / D;
    const T t20 = t10 * q1;
    const T t21 = T(21) * t14 * r0 * slope0 + T(20) * (T(22) * J_upward_compact<T>(-21, a, D, slope0, q0, slope1, q1) * a + t16 * r0 * slope0 - slope1 * t18 * r1) * t19 * a - T(21) * slope1 * t20 * r1;
    const T t22 = T(133) * slope1 * t10 * r1 - T(133) * t13 * r0 * slope0 - T(6) * t21 * t19 * a;
    const T t23 = t11 * q0;
    const T t24 = t23 * t23;
    const T t25 = t24 * q0;
    const T t26 = T(2261) * slope1 * t8 * r1 + T(16) * t22 * t19 * a - T(2261) * t25 * r0 * slope0;
    const T t27 = t26 * t19 * b + T(2261) * t25 * r0 - T(2261) * t8 * r1;
    const T t28 = t22 * t19 * b + T(133) * t13 * r0 - T(133) * t10 * r1;
    const T t29 = T(2) * t27 * t0 * b + T(15) * t22 * t19 - t26 * c * t19;
    const T t30 = T(15) * t0 * t28 + T(2) * t29 * t0 * b - c * t27 * t0;
    G_ap = -(T(1) / T(33915)) * t26 * t19 * in.w[0] - (T(1) / T(33915)) * t27 * in.w[1] * t0 - (T(1) / T(33915)) * in.w[3] * t0 * t30 - (T(1) / T(33915)) * t29 * t0 * in.w[2];
    G_ab = (T(1) / T(33915)) * in.w[3] * (T(5) * (T(17) * t21 * t19 + T(3) * c * t22 * t19 - T(6) * t0 * b * t28) * t0 + c * t29 * t0 - T(2) * t0 * t30 * b) * t0 - (T(1) / T(33915)) * t29 * in.w[1] * t0 - (T(1) / T(33915)) * t0 * t30 * in.w[2] - (T(1) / T(33915)) * t27 * t0 * in.w[0];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t31 = q1 * q1;
    const T t32 = t31 * q1;
    const T t33 = t32 * t32;
    const T t34 = t33 * q1;
    const T t35 = q0 * q0;
    const T t36 = t35 * q0;
    const T t37 = t36 * t36;
    const T t38 = t35 * t35;
    const T t39 = t31 * t31;
    const T t40 = t38 * q0;
    const T t41 = t39 * q1;
    const T t42 = T(15360) * t37 * r0 * slope0 + T(13) * (T(11) * (T(3) * D * t0 * (T(48) * t36 * r0 * slope0 - T(7) * D * t0 * (T(8) * slope1 * t31 * r1 - T(8) * t35 * r0 * slope0 - T(5) * (T(2) * q0 * r0 * slope0 - T(2) * slope1 * q1 * r1 - T(3) * (slope1 * r1 + J1 * D - r0 * slope0) * D * t0) * D * t0) - T(48) * slope1 * t32 * r1) + T(128) * t38 * r0 * slope0 - T(128) * slope1 * t39 * r1) * D * t0 + T(1280) * t40 * r0 * slope0 - T(1280) * slope1 * t41 * r1) * D * t0 - T(15360) * slope1 * t33 * r1;
    const T t43 = t37 * q0;
    const T t44 = T(14336) * slope1 * t34 * r1 - D * t0 * t42 - T(14336) * t43 * r0 * slope0;
    const T t45 = t0 * t42 * b + T(14336) * t43 * r0 - T(14336) * t34 * r1;
    const T t46 = T(15) * t0 * t44 + T(16) * c * t0 * t42 - T(32) * t0 * t45 * b;
    const T t47 = t38 * t38;
    const T t48 = t39 * t39;
    const T t49 = T(229376) * t47 * r0 - T(17) * t0 * b * t44 - T(229376) * t48 * r1;
    const T t50 = T(15) * t0 * t49 - T(272) * c * t0 * t45 - T(34) * t0 * b * t46;
    G_ap = (T(1) / T(3440640)) * t0 * in.w[2] * t46 - (T(1) / T(215040)) * t0 * t42 * in.w[0] - (T(1) / T(58490880)) * in.w[3] * t0 * t50 - (T(1) / T(215040)) * in.w[1] * t0 * t45;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t0 * t46 - (T(1) / T(350945280)) * in.w[3] * t0 * (T(5) * (T(306) * c * t0 * t44 + T(36) * t0 * t49 * b - T(17) * (T(229376) * slope1 * t48 * r1 + T(17) * D * t0 * t44 - T(229376) * t47 * r0 * slope0) * t0) * t0 + T(102) * c * t0 * t46 + T(12) * t0 * t50 * b) - (T(1) / T(58490880)) * t0 * in.w[2] * t50 - (T(1) / T(215040)) * t0 * t45 * in.w[0];
  }
  const T g_factor = -T(15) * inv_R2 * length;
  grad[0] = (ap0 * G_ap - G_ab * ab0) * g_factor;
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -g_factor * (G_ab * ab2 - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Operations: 78 +, 239 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 570 +, 2233 ×, 259 /, 5 sqrt, 2 atan, 2 log/asinh.
template <class T>
T segment_compact_i15_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  const T slope0 = a * in.t0 - b;
  const T q0 = max(T(0), T(c - (b - slope0) * in.t0));
  const T r0 = sqrt(q0);
  const T slope1 = in.t1 * a - b;
  const T q1 = max(T(0), T(c - (b - slope1) * in.t1));
  const T r1 = sqrt(q1);
  const T root_minus_a = inv_R * length;
  const T t0 = -slope1;
  const T t1 = -slope0;
  const T J1 = (atan2(t0, r1 * root_minus_a) - atan2(t1, root_minus_a * r0)) / root_minus_a;
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -a * a * t3 * t3 - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = in.w[2] * M_flat[2] + M_flat[1] * in.w[1] + in.w[3] * M_flat[3] + M_flat[0] * in.w[0];
    G_ap = in.w[3] * M_flat[8] + M_flat[7] * in.w[2] + M_flat[6] * in.w[1] + in.w[0] * M_flat[5];
    G_ab = M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + M_flat[8] * in.w[2] + M_flat[7] * in.w[1];
  } else if (t5 >= T(0) && t6 >= T(0)) {
    // vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_-21 = J_upward_compact(…)
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = q0 * q0;
    const T t11 = t10 * t10;
    const T t12 = t11 * t11;
    const T t13 = t12 * q0;
    const T t14 = t8 * q1;
    const T t15 = t14 * t14;
    const T t16 = t11 * q0;
    const T t17 = t16 * t16;
    const T t18 = T(1) / D;
    const T t19 = t9 * q1;
    const T t20 = T(21) * slope0 * t13 * r0 - T(20) * (r1 * slope1 * t15 - slope0 * t17 * r0 - T(22) * J_upward_compact<T>(-21, a, D, slope0, q0, slope1, q1) * a) * a * t18 - T(21) * r1 * slope1 * t19;
    const T t21 = T(6) * t20 * a * t18 + T(133) * slope0 * t12 * r0 - T(133) * r1 * slope1 * t9;
    const T t22 = T(133) * r1 * t9 + b * t21 * t18 - T(133) * t12 * r0;
    const T t23 = T(6) * b * t22 * t2 + T(17) * t20 * t18 - T(3) * c * t21 * t18;
    F = (T(1) / T(6783)) * t23 * t2 * in.w[2] + (T(1) / T(2261)) * in.w[0] * t21 * t18 + (T(1) / T(2261)) * in.w[1] * t22 * t2 + (T(1) / T(6783)) * in.w[3] * (T(2) * b * t23 * t2 - T(3) * c * t22 * t2 - T(17) * (T(21) * t13 * r0 - T(21) * r1 * t19 - b * t20 * t18) * t2) * t2;
    const T t24 = t7 * q1;
    const T t25 = t24 * t24;
    const T t26 = t25 * q1;
    const T t27 = t10 * q0;
    const T t28 = t27 * t27;
    const T t29 = t28 * q0;
    const T t30 = T(16) * t21 * a * t18 + T(2261) * slope0 * t29 * r0 - T(2261) * r1 * slope1 * t26;
    const T t31 = T(2261) * r1 * t26 + b * t30 * t18 - T(2261) * t29 * r0;
    const T t32 = T(15) * t21 * t18 + T(2) * t31 * b * t2 - c * t30 * t18;
    const T t33 = T(15) * t22 * t2 + T(2) * t32 * b * t2 - t31 * c * t2;
    G_ap = (T(1) / T(33915)) * t31 * in.w[1] * t2 + (T(1) / T(33915)) * in.w[3] * t33 * t2 + (T(1) / T(33915)) * t32 * t2 * in.w[2] + (T(1) / T(33915)) * in.w[0] * t30 * t18;
    G_ab = (T(1) / T(33915)) * t32 * in.w[1] * t2 + (T(1) / T(33915)) * t33 * t2 * in.w[2] + (T(1) / T(33915)) * t31 * in.w[0] * t2 - (T(1) / T(33915)) * in.w[3] * t2 * (t32 * c * t2 - T(5) * t23 * t2 - T(2) * b * t33 * t2);
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t34 = q1 * q1;
    const T t35 = t34 * q1;
    const T t36 = t35 * t35;
    const T t37 = t36 * q1;
    const T t38 = t34 * t34;
    const T t39 = q0 * q0;
    const T t40 = t39 * q0;
    const T t41 = t39 * t39;
    const T t42 = t38 * q1;
    const T t43 = t41 * q0;
    const T t44 = t40 * t40;
    const T t45 = T(13) * t2 * D * (T(11) * (T(128) * r1 * slope1 * t38 - T(3) * t2 * (T(48) * slope0 * t40 * r0 - T(7) * t2 * D * (T(5) * (T(3) * (r1 * slope1 + D * J1 - slope0 * r0) * t2 * D + T(2) * r1 * slope1 * q1 - T(2) * slope0 * q0 * r0) * t2 * D + T(8) * r1 * slope1 * t34 - T(8) * slope0 * t39 * r0) - T(48) * r1 * slope1 * t35) * D - T(128) * slope0 * t41 * r0) * t2 * D + T(1280) * r1 * slope1 * t42 - T(1280) * slope0 * t43 * r0) + T(15360) * r1 * slope1 * t36 - T(15360) * slope0 * t44 * r0;
    const T t46 = t44 * q0;
    const T t47 = T(14336) * r1 * slope1 * t37 + t45 * t2 * D - T(14336) * slope0 * t46 * r0;
    const T t48 = t38 * t38;
    const T t49 = t41 * t41;
    const T t50 = T(229376) * r1 * t48 + T(17) * b * t47 * t2 - T(229376) * t49 * r0;
    const T t51 = T(229376) * slope0 * t49 * r0 - T(17) * t47 * t2 * D - T(229376) * r1 * slope1 * t48;
    const T t52 = T(36) * b * t2 * t50 - T(17) * t2 * t51 - T(306) * c * t47 * t2;
    const T t53 = t49 * q0;
    const T t54 = t48 * q1;
    F = (T(1) / T(229376)) * in.w[0] * t47 * t2 + (T(1) / T(70189056)) * t2 * t52 * in.w[2] + (T(1) / T(3899392)) * in.w[1] * t2 * t50 - (T(1) / T(1333592064)) * in.w[3] * t2 * (T(17) * (T(4128768) * t53 * r0 + T(19) * b * t2 * t51 - T(4128768) * r1 * t54) * t2 + T(342) * c * t2 * t50 - T(38) * b * t2 * t52);
    const T t55 = T(14336) * r1 * t37 + b * t45 * t2 - T(14336) * t46 * r0;
    const T t56 = T(15) * t47 * t2 + T(32) * b * t2 * t55 - T(16) * c * t45 * t2;
    const T t57 = T(15) * t2 * t50 + T(34) * b * t2 * t56 - T(272) * c * t2 * t55;
    G_ap = (T(1) / T(3440640)) * t2 * t56 * in.w[2] + (T(1) / T(58490880)) * in.w[3] * t57 * t2 + (T(1) / T(215040)) * in.w[1] * t2 * t55 + (T(1) / T(215040)) * in.w[0] * t45 * t2;
    G_ab = (T(1) / T(3440640)) * in.w[1] * t2 * t56 + (T(1) / T(58490880)) * t57 * t2 * in.w[2] + (T(1) / T(215040)) * in.w[0] * t2 * t55 - (T(1) / T(350945280)) * in.w[3] * (T(102) * c * t2 * t56 - T(5) * t2 * t52 - T(12) * b * t57 * t2) * t2;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(15/2) dt
/// Returns false where segment_compact_i15_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 78 +, 239 ×, 3 /, 3 sqrt, 2 atan, 0 log/asinh.
template <class T>
bool segment_compact_i15_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  const T D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
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
  T F;
  T G_ap;
  T G_ab;
  const T t2 = T(1) / a;
  const T t3 = max(T(b * t2 + (T(1) / T(2))), T((T(3) / T(2)) - b * t2));
  const T t4 = -t3 * t3 * a * a - D;
  const T t5 = slope0 * slope1;
  const T t6 = max(T(q0), T(q1)) * a - (T(17) / T(20)) * D;
  if (t4 >= T(0)) {
    // support sphere at least |AB|/2 beyond both ends: every moment by segment_moments_gauss<T, 20>
    std::array<T, 10> M_flat;
    segment_moments_gauss<T, 20>(-15, -13, 4, a, b, c, in.t0, in.t1, M_flat.data());
    F = M_flat[1] * in.w[1] + M_flat[3] * in.w[3] + M_flat[2] * in.w[2] + M_flat[0] * in.w[0];
    G_ap = M_flat[7] * in.w[2] + in.w[3] * M_flat[8] + in.w[0] * M_flat[5] + M_flat[6] * in.w[1];
    G_ab = M_flat[6] * in.w[0] + M_flat[9] * in.w[3] + M_flat[7] * in.w[1] + M_flat[8] * in.w[2];
  } else {
    // recurrence (1) downwards from J_0, J_1
    const T t7 = q1 * q1;
    const T t8 = t7 * t7;
    const T t9 = t8 * t8;
    const T t10 = t9 * q1;
    const T t11 = q0 * q0;
    const T t12 = t11 * t11;
    const T t13 = t12 * t12;
    const T t14 = t11 * q0;
    const T t15 = t14 * t14;
    const T t16 = t15 * q0;
    const T t17 = t7 * q1;
    const T t18 = t8 * q1;
    const T t19 = t12 * q0;
    const T t20 = t17 * t17;
    const T t21 = T(13) * D * (T(11) * D * (T(3) * D * (T(48) * t17 * r1 * slope1 + T(7) * D * (T(5) * D * (T(2) * q1 * r1 * slope1 - T(3) * (r0 * slope0 - D * J1 - r1 * slope1) * D * t2 - T(2) * r0 * slope0 * q0) * t2 + T(8) * t7 * r1 * slope1 - T(8) * r0 * slope0 * t11) * t2 - T(48) * r0 * slope0 * t14) * t2 + T(128) * t8 * r1 * slope1 - T(128) * r0 * slope0 * t12) * t2 + T(1280) * t18 * r1 * slope1 - T(1280) * r0 * slope0 * t19) * t2 + T(15360) * t20 * r1 * slope1 - T(15360) * r0 * slope0 * t15;
    const T t22 = t20 * q1;
    const T t23 = T(14336) * r0 * slope0 * t16 - t21 * D * t2 - T(14336) * t22 * r1 * slope1;
    const T t24 = T(229376) * t9 * r1 * slope1 - T(229376) * r0 * slope0 * t13 - T(17) * t23 * D * t2;
    const T t25 = t13 * q0;
    const T t26 = T(17) * b * t23 * t2 + T(229376) * r0 * t13 - T(229376) * t9 * r1;
    const T t27 = T(17) * t24 * t2 + T(306) * t23 * c * t2 - T(36) * b * t26 * t2;
    F = (T(1) / T(1333592064)) * in.w[3] * (T(17) * (T(4128768) * t10 * r1 + T(19) * b * t24 * t2 - T(4128768) * r0 * t25) * t2 + T(342) * t26 * c * t2 + T(38) * b * t27 * t2) * t2 + (T(1) / T(70189056)) * t27 * t2 * in.w[2] - (T(1) / T(3899392)) * t26 * in.w[1] * t2 - (T(1) / T(229376)) * in.w[0] * t23 * t2;
    const T t28 = T(14336) * r0 * t16 - b * t21 * t2 - T(14336) * t22 * r1;
    const T t29 = T(16) * c * t21 * t2 + T(32) * b * t28 * t2 + T(15) * t23 * t2;
    const T t30 = T(15) * t26 * t2 + T(34) * b * t29 * t2 - T(272) * t28 * c * t2;
    G_ap = (T(1) / T(215040)) * in.w[0] * t21 * t2 - (T(1) / T(3440640)) * t29 * t2 * in.w[2] - (T(1) / T(58490880)) * in.w[3] * t30 * t2 - (T(1) / T(215040)) * t28 * in.w[1] * t2;
    G_ab = (T(1) / T(350945280)) * (T(5) * t27 * t2 + T(102) * t29 * c * t2 - T(12) * b * t30 * t2) * in.w[3] * t2 - (T(1) / T(3440640)) * t29 * in.w[1] * t2 - (T(1) / T(58490880)) * t30 * t2 * in.w[2] - (T(1) / T(215040)) * in.w[0] * t28 * t2;
  }
  const T g_factor = -T(15) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return !(((t5 >= T(0) && t6 >= T(0)) && !(t4 >= T(0))));
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 55 +, 165 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w0_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 16, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 1> M_exact;
    segment_moments_gauss<T, 10>(-16, -16, 0, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 68 +, 176 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i16_w0_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 1, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0];
    G_ab = M_exact[1] * in.w[0];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = -(ab0 * G_ab - ap0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_ab - ap1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 88 +, 208 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w0_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[2];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = -g_factor * (ab1 * G_ab - ap1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_ab - G_ap * ap2);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 w0 (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Returns false where segment_compact_i16_w0_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 88 +, 208 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i16_w0_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0];
    G_ap = M_exact[2] * in.w[0];
    G_ab = in.w[0] * M_exact[3];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 66 +, 176 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w1_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 17, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 2> M_exact;
    segment_moments_gauss<T, 10>(-16, -16, 1, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + M_exact[0] * in.w[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 80 +, 188 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i16_w1_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 2, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[1] * M_exact[1] + in.w[0] * M_exact[0];
    G_ab = in.w[0] * M_exact[1] + M_exact[2] * in.w[1];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = -(G_ab * ab0 - ap0 * G_ap) * g_factor;
  grad[1] = -(G_ab * ab1 - ap1 * G_ap) * g_factor;
  grad[2] = (ap2 * G_ap - G_ab * ab2) * g_factor;
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 111 +, 231 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w1_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + M_exact[1] * in.w[1];
    G_ap = M_exact[4] * in.w[1] + M_exact[3] * in.w[0];
    G_ab = M_exact[4] * in.w[0] + M_exact[5] * in.w[1];
  }
  const T g_factor = -T(16) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (ap0 * G_ap - ab0 * G_ab);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = -g_factor * (ab2 * G_ab - ap2 * G_ap);
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Returns false where segment_compact_i16_w1_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 111 +, 231 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i16_w1_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[1] * in.w[1] + in.w[0] * M_exact[0];
    G_ap = in.w[0] * M_exact[3] + M_exact[4] * in.w[1];
    G_ab = M_exact[4] * in.w[0] + M_exact[5] * in.w[1];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = (ap0 * G_ap - ab0 * G_ab) * g_factor;
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 77 +, 187 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w2_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 18, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 10>(-16, -16, 2, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[0] * in.w[0] + in.w[2] * M_exact[2] + M_exact[1] * in.w[1];
  }
  f = F * length;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 92 +, 200 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i16_w2_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  std::array<T, 3> grad;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 19, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-14, -14, 3, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[0] * M_exact[0] + M_exact[2] * in.w[2] + M_exact[1] * in.w[1];
    G_ab = in.w[1] * M_exact[2] + in.w[2] * M_exact[3] + in.w[0] * M_exact[1];
  }
  const T g_factor = -T(16) * length * inv_R2;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = g_factor * (ap1 * G_ap - ab1 * G_ab);
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 134 +, 254 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w2_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 19, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + in.w[2] * M_exact[2];
    G_ap = in.w[2] * M_exact[6] + in.w[1] * M_exact[5] + in.w[0] * M_exact[4];
    G_ab = in.w[0] * M_exact[5] + in.w[1] * M_exact[6] + M_exact[7] * in.w[2];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_ab * ab0 - ap0 * G_ap);
  grad[1] = -g_factor * (G_ab * ab1 - ap1 * G_ap);
  grad[2] = -(G_ab * ab2 - ap2 * G_ap) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Returns false where segment_compact_i16_w2_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 134 +, 254 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i16_w2_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 19, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 8> M_exact;
    segment_moments_gauss<T, 10>(-16, -14, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + in.w[2] * M_exact[2] + in.w[0] * M_exact[0];
    G_ap = M_exact[5] * in.w[1] + in.w[0] * M_exact[4] + in.w[2] * M_exact[6];
    G_ab = M_exact[6] * in.w[1] + in.w[2] * M_exact[7] + M_exact[5] * in.w[0];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_ab - G_ap * ap0);
  grad[1] = -g_factor * (ab1 * G_ab - G_ap * ap1);
  grad[2] = g_factor * (G_ap * ap2 - ab2 * G_ab);
  return true;
}

/// the field, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 88 +, 198 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w3_f(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  {
    // even degree: the integrand is a polynomial of degree 19, integrated exactly by segment_moments_gauss<T, 10>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 10>(-16, -16, 3, a, b, c, in.t0, in.t1, M_exact.data());
    F = M_exact[2] * in.w[2] + M_exact[1] * in.w[1] + in.w[3] * M_exact[3] + in.w[0] * M_exact[0];
  }
  f = length * F;
  return f;
}

/// its gradient ∇_P f, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 144 +, 302 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
std::array<T, 3> segment_compact_i16_w3_grad(const SegmentInput<T>& in) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
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
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 20, integrated exactly by segment_moments_gauss<T, 15>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 15>(-14, -14, 4, a, b, c, in.t0, in.t1, M_exact.data());
    G_ap = in.w[2] * M_exact[2] + in.w[1] * M_exact[1] + M_exact[3] * in.w[3] + in.w[0] * M_exact[0];
    G_ab = in.w[1] * M_exact[2] + M_exact[4] * in.w[3] + M_exact[1] * in.w[0] + in.w[2] * M_exact[3];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  grad[0] = -g_factor * (ab0 * G_ab - ap0 * G_ap);
  grad[1] = (ap1 * G_ap - ab1 * G_ab) * g_factor;
  grad[2] = g_factor * (ap2 * G_ap - ab2 * G_ab);
  return grad;
}

/// the field and its gradient, where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Operations: 222 +, 397 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh (generic form).
template <class T>
T segment_compact_i16_w3_f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  T f;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - ap_ap * inv_R2;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 20, integrated exactly by segment_moments_gauss<T, 15>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 15>(-16, -14, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[0] * M_exact[0] + in.w[1] * M_exact[1] + in.w[3] * M_exact[3] + in.w[2] * M_exact[2];
    G_ap = M_exact[5] * in.w[0] + M_exact[6] * in.w[1] + M_exact[8] * in.w[3] + in.w[2] * M_exact[7];
    G_ab = in.w[1] * M_exact[7] + in.w[0] * M_exact[6] + in.w[2] * M_exact[8] + in.w[3] * M_exact[9];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = F * length;
  grad[0] = (G_ap * ap0 - ab0 * G_ab) * g_factor;
  grad[1] = (G_ap * ap1 - ab1 * G_ab) * g_factor;
  grad[2] = (G_ap * ap2 - ab2 * G_ab) * g_factor;
  return f;
}

/// The field and its gradient on the generic forms only (no helper loops), where
///     f(P) = |AB| ∫_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 − |P − Γ(t)|²/R²)^(16/2) dt
/// Returns false where segment_compact_i16_w3_f_and_grad takes another form: its values
/// then are not to be used.
/// Operations: 222 +, 397 ×, 3 /, 1 sqrt, 0 atan, 0 log/asinh.
template <class T>
bool segment_compact_i16_w3_f_and_grad_generic(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap0 = in.p[0] - in.a[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap1 = in.p[1] - in.a[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap2 = in.p[2] - in.a[2];
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T length = sqrt(ab_ab);
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = T(1) - inv_R2 * ap_ap;
  T F;
  T G_ap;
  T G_ab;
  {
    // even degree: the integrand is a polynomial of degree 20, integrated exactly by segment_moments_gauss<T, 15>
    std::array<T, 10> M_exact;
    segment_moments_gauss<T, 15>(-16, -14, 4, a, b, c, in.t0, in.t1, M_exact.data());
    F = in.w[1] * M_exact[1] + M_exact[3] * in.w[3] + M_exact[0] * in.w[0] + in.w[2] * M_exact[2];
    G_ap = M_exact[8] * in.w[3] + M_exact[7] * in.w[2] + M_exact[6] * in.w[1] + M_exact[5] * in.w[0];
    G_ab = in.w[2] * M_exact[8] + M_exact[6] * in.w[0] + M_exact[9] * in.w[3] + in.w[1] * M_exact[7];
  }
  const T g_factor = -T(16) * inv_R2 * length;
  f = length * F;
  grad[0] = -(ab0 * G_ab - G_ap * ap0) * g_factor;
  grad[1] = g_factor * (G_ap * ap1 - ab1 * G_ab);
  grad[2] = -(ab2 * G_ab - G_ap * ap2) * g_factor;
  return true;
}

}  // namespace skelconv::generated
