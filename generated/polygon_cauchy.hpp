// generated/polygon_cauchy.hpp — polygon edge kernels of the cauchy family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC §2, Hubert 2012 §3).
// Polygons (SPEC §3, Hubert 2012 §5–8): the terms of one edge of the contour sum
// (codegen/polygon_families.cpp), on the segment forms of the edge;
// skelconv/polygon_field.hpp adds them up.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/gauss_moments.hpp>
#include <skelconv/polygon_angle_integrals.hpp>
#include <skelconv/polygon_edge_input.hpp>
#include <skelconv/segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 37 +, 57 ×, 1 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 97 +, 170 ×, 23 /, 22 sqrt, 3 atan, 0 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  const T alpha_h = h * in.s;
  T H_f;
  const T t0 = min(T(c), T(q1)) - T(2) * zeta2;
  const T t1 = max(T(D - T(2) * zeta2 * a), T(-b * a_minus_b));
  if (t0 >= T(0) && t1 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(1, 1, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r0 * a_minus_b + b * r1), r0 * r1 * alpha_h * alpha_h - b * zeta2 * a_minus_b) / zeta;
    H_f = H1;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 41 +, 61 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 446 +, 1020 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (b / r0 + a_minus_b / r1) / D;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + r1 * b) * zeta * alpha_h, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T H3 = (H1 - alpha_h * J_3) / zeta2;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 41 +, 61 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 466 +, 1021 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (b / r0 + a_minus_b / r1) / D;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(1, 3, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * b + r0 * a_minus_b) * alpha_h * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T H3 = -(alpha_h * J_3 - H1) / zeta2;
    H_f = H1;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 39 +, 53 ×, 2 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 447 +, 979 ×, 145 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross0 * cross0 + cross1 * cross1 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    J_2 = J2;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t5 = t2 - T(2) * zeta2;
  const T t6 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t5 >= T(0) && t6 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(2, 2, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T H2 = (theta - J_2 * alpha_h) / zeta2;
    H_f = H2;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 42 +, 60 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 451 +, 1011 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = in.s * (zeta2 * ab_ab + cross_cross * in.s);
  const T h = in.normal[1] * cross1 + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * t6 * (a_minus_b / q1 + b / c + a * J2);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = -t9 * (J_2 * alpha_h - theta);
    const T H4 = t9 * (H2 - alpha_h * J_4);
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 42 +, 60 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 471 +, 1032 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * (a * J2 + a_minus_b / q1 + b / c) * t6;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(2, 4, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = -t9 * (J_2 * alpha_h - theta);
    const T H4 = -t9 * (alpha_h * J_4 - H2);
    H_f = H2;
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 41 +, 61 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 446 +, 1020 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (b / r0 + a_minus_b / r1) / D;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((b * r1 + r0 * a_minus_b) * zeta * alpha_h, alpha_h * alpha_h * r0 * r1 - b * zeta2 * a_minus_b) / zeta;
    const T H3 = -(alpha_h * J_3 - H1) / zeta2;
    H_f = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 44 +, 74 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 450 +, 1072 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = a_minus_b * t4 + t5 * b;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    J_5 = (T(1) / T(3)) * (t5 * b / c + a_minus_b * t4 / q1 + T(2) * t6 * t7 * a) * t7;
  }
  const T alpha_h = in.s * h;
  T H_g;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (a_minus_b * r0 + r1 * b), r1 * alpha_h * alpha_h * r0 - a_minus_b * zeta2 * b) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = -t10 * (alpha_h * J_3 - H1);
    const T H5 = t10 * (H3 - alpha_h * J_5);
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 44 +, 74 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 470 +, 1073 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + b * t6;
    J_3 = t4 * t7;
    J_5 = (T(1) / T(3)) * t4 * (t5 * a_minus_b / q1 + T(2) * a * t4 * t7 + b * t6 / c);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(3, 5, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (b * r1 + a_minus_b * r0), r1 * alpha_h * alpha_h * r0 - b * a_minus_b * zeta2) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = (H1 - alpha_h * J_3) * t10;
    const T H5 = (H3 - J_5 * alpha_h) * t10;
    H_f = H3;
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 42 +, 60 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 451 +, 1011 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ap0 * ab2 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ap0 * ab1;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + in.s * ap_ap;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * (a * J2 + b / c + a_minus_b / q1) * t6;
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = (theta - J_2 * alpha_h) * t9;
    const T H4 = -(alpha_h * J_4 - H2) * t9;
    H_f = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 45 +, 75 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 455 +, 1044 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a * J2 + a_minus_b * t7 + t8 * b;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t7 * t7;
    const T t11 = t8 * t8;
    J_6 = (T(1) / T(8)) * (T(2) * a_minus_b * t10 + T(2) * t11 * b + T(3) * t6 * a * t9) * t6;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -t14 * (J_2 * alpha_h - theta);
    const T H4 = -t14 * (alpha_h * J_4 - H2);
    const T H6 = -t14 * (J_6 * alpha_h - H4);
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 45 +, 75 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 475 +, 1065 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = J2 * a + a_minus_b * t6 + t7 * b;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    J_6 = (T(1) / T(8)) * (T(2) * t10 * b + T(2) * a_minus_b * t11 + T(3) * t8 * t9 * a) * t9;
  }
  const T alpha_h = in.s * h;
  T H_f;
  T H_g;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(4, 6, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t14;
    const T H4 = t14 * (H2 - alpha_h * J_4);
    const T H6 = t14 * (H4 - J_6 * alpha_h);
    H_f = H4;
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 44 +, 74 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 450 +, 1072 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (cross_cross * in.s + ab_ab * zeta2) * in.s;
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = b * t4 + t5 * a_minus_b;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    J_5 = (T(1) / T(3)) * t7 * (b * t4 / c + T(2) * a * t6 * t7 + t5 * a_minus_b / q1);
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r0 * a_minus_b + b * r1), alpha_h * alpha_h * r0 * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = -(alpha_h * J_3 - H1) * t10;
    const T H5 = (H3 - alpha_h * J_5) * t10;
    H_f = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 47 +, 93 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 454 +, 1125 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + b * t6;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = a_minus_b * t5 * t8 + t9 * b * t6 + T(2) * t4 * a * t7;
    J_5 = (T(1) / T(3)) * t4 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * (T(4) * t4 * a * t10 + T(3) * t11 * b * t6 + T(3) * a_minus_b * t5 * t12) * t4;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r1 * b + a_minus_b * r0) * alpha_h, alpha_h * alpha_h * r1 * r0 - zeta2 * a_minus_b * b) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = -t15 * (alpha_h * J_3 - H1);
    const T H5 = (H3 - alpha_h * J_5) * t15;
    const T H7 = t15 * (H5 - J_7 * alpha_h);
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 47 +, 93 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 474 +, 1126 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross0 * in.normal[0] + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * b + t5 * a_minus_b;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t5 * t5;
    const T t9 = t4 * t4;
    const T t10 = T(2) * t6 * a * t7 + t5 * a_minus_b * t8 + t4 * t9 * b;
    J_5 = (T(1) / T(3)) * t10 * t7;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * t7 * (T(3) * t4 * t11 * b + T(3) * t5 * a_minus_b * t12 + T(4) * a * t10 * t7);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(5, 7, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * zeta * (r1 * b + r0 * a_minus_b), r0 * alpha_h * alpha_h * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - alpha_h * J_3);
    const T H5 = t15 * (H3 - alpha_h * J_5);
    const T H7 = -t15 * (J_7 * alpha_h - H5);
    H_f = H5;
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 45 +, 75 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 455 +, 1044 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + ap0 * bp0;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = J2 * a + t7 * b + a_minus_b * t8;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    J_6 = (T(1) / T(8)) * t6 * (T(2) * a_minus_b * t10 + T(2) * t11 * b + T(3) * t6 * t9 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = t14 * (theta - J_2 * alpha_h);
    const T H4 = -t14 * (alpha_h * J_4 - H2);
    const T H6 = -t14 * (J_6 * alpha_h - H4);
    H_f = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 48 +, 88 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 459 +, 1078 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (zeta2 * ab_ab + in.s * cross_cross) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = t6 * a_minus_b + b * t7 + J2 * a;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * t8 * t9 * a + T(2) * b * t10 + T(2) * t11 * a_minus_b;
    J_6 = (T(1) / T(8)) * t9 * t12;
    const T t13 = t11 * t6;
    const T t14 = t10 * t7;
    J_8 = (T(1) / T(48)) * (T(8) * t13 * a_minus_b + T(8) * b * t14 + T(5) * t9 * a * t12) * t9;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = t17 * (theta - alpha_h * J_2);
    const T H4 = -t17 * (alpha_h * J_4 - H2);
    const T H6 = t17 * (H4 - J_6 * alpha_h);
    const T H8 = -t17 * (J_8 * alpha_h - H6);
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 48 +, 88 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 479 +, 1099 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (in.s * cross_cross + ab_ab * zeta2) * in.s;
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = a * J2 + b * t7 + a_minus_b * t8;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * a_minus_b * t10 + T(2) * b * t11 + T(3) * t6 * a * t9;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    J_8 = (T(1) / T(48)) * t6 * (T(8) * a_minus_b * t13 + T(8) * b * t14 + T(5) * t6 * a * t12);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(6, 8, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t17;
    const T H4 = -(alpha_h * J_4 - H2) * t17;
    const T H6 = -(alpha_h * J_6 - H4) * t17;
    const T H8 = -(alpha_h * J_8 - H6) * t17;
    H_f = H6;
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 47 +, 93 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 454 +, 1125 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (ab_ab * zeta2 + in.s * cross_cross) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + b * t6;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = T(2) * a * t4 * t7 + a_minus_b * t8 * t5 + b * t6 * t9;
    J_5 = (T(1) / T(3)) * t10 * t4;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * t4 * (T(3) * b * t6 * t11 + T(4) * t10 * a * t4 + T(3) * a_minus_b * t12 * t5);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (a_minus_b * r0 + b * r1), r0 * alpha_h * alpha_h * r1 - a_minus_b * b * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * alpha_h) * t15;
    const T H5 = -(J_5 * alpha_h - H3) * t15;
    const T H7 = -t15 * (J_7 * alpha_h - H5);
    H_f = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 50 +, 108 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 458 +, 1178 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = in.normal[1] * cross1 + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + t6 * b;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = T(2) * t4 * t7 * a + t8 * t5 * a_minus_b + t9 * t6 * b;
    J_5 = (T(1) / T(3)) * t10 * t4;
    const T t11 = t8 * t8;
    const T t12 = t9 * t9;
    const T t13 = T(3) * t11 * t5 * a_minus_b + T(3) * t12 * t6 * b + T(4) * t10 * t4 * a;
    J_7 = (T(1) / T(15)) * t13 * t4;
    const T t14 = t12 * t9;
    const T t15 = t11 * t8;
    J_9 = (T(1) / T(35)) * (T(2) * t13 * t4 * a + T(5) * t14 * t6 * b + T(5) * t15 * t5 * a_minus_b) * t4;
  }
  const T alpha_h = in.s * h;
  T H_g;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + r1 * b) * zeta * alpha_h, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = -t18 * (alpha_h * J_3 - H1);
    const T H5 = -t18 * (alpha_h * J_5 - H3);
    const T H7 = t18 * (H5 - J_7 * alpha_h);
    const T H9 = -t18 * (alpha_h * J_9 - H7);
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 50 +, 108 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 478 +, 1179 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * b;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t5 * t5;
    const T t9 = t4 * t4;
    const T t10 = T(2) * t6 * t7 * a + t5 * b * t8 + t4 * a_minus_b * t9;
    J_5 = (T(1) / T(3)) * t7 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * t4 * a_minus_b * t11 + T(3) * t5 * b * t12 + T(4) * t7 * a * t10;
    J_7 = (T(1) / T(15)) * t7 * t13;
    const T t14 = t11 * t9;
    const T t15 = t12 * t8;
    J_9 = (T(1) / T(35)) * t7 * (T(5) * t4 * a_minus_b * t14 + T(2) * t7 * a * t13 + T(5) * t5 * b * t15);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(7, 9, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r0 * a_minus_b + r1 * b) * alpha_h, r0 * r1 * alpha_h * alpha_h - zeta2 * a_minus_b * b) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = -t18 * (J_3 * alpha_h - H1);
    const T H5 = t18 * (H3 - J_5 * alpha_h);
    const T H7 = t18 * (H5 - J_7 * alpha_h);
    const T H9 = -t18 * (J_9 * alpha_h - H7);
    H_f = H7;
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 48 +, 88 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 459 +, 1078 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (ab_ab * zeta2 + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = a * J2 + b * t7 + a_minus_b * t8;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * t6 * a * t9 + T(2) * a_minus_b * t10 + T(2) * b * t11;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    J_8 = (T(1) / T(48)) * t6 * (T(8) * a_minus_b * t13 + T(5) * t6 * a * t12 + T(8) * b * t14);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t17;
    const T H4 = (H2 - alpha_h * J_4) * t17;
    const T H6 = -t17 * (alpha_h * J_6 - H4);
    const T H8 = -(J_8 * alpha_h - H6) * t17;
    H_f = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 51 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 463 +, 1112 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = a * J2 + t7 * b + t8 * a_minus_b;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * t6 * a * t9 + T(2) * t10 * a_minus_b + T(2) * t11 * b;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * t13 * a_minus_b + T(8) * t14 * b + T(5) * t6 * a * t12;
    J_8 = (T(1) / T(48)) * t15 * t6;
    const T t16 = t11 * t11;
    const T t17 = t10 * t10;
    J_10 = (T(1) / T(384)) * (T(7) * t15 * t6 * a + T(48) * t16 * b + T(48) * t17 * a_minus_b) * t6;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = t20 * (theta - J_2 * alpha_h);
    const T H4 = t20 * (H2 - alpha_h * J_4);
    const T H6 = -t20 * (alpha_h * J_6 - H4);
    const T H8 = t20 * (H6 - J_8 * alpha_h);
    const T H10 = t20 * (H8 - alpha_h * J_10);
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 51 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 483 +, 1133 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (ab_ab * zeta2 + in.s * cross_cross) * in.s;
  const T h = cross0 * in.normal[0] + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = b * t7 + a * J2 + t8 * a_minus_b;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * t10 * a_minus_b + T(3) * t6 * a * t9 + T(2) * b * t11;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * t13 * a_minus_b + T(8) * b * t14 + T(5) * t6 * a * t12;
    J_8 = (T(1) / T(48)) * t6 * t15;
    const T t16 = t10 * t10;
    const T t17 = t11 * t11;
    J_10 = (T(1) / T(384)) * t6 * (T(7) * t6 * a * t15 + T(48) * t16 * a_minus_b + T(48) * b * t17);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(8, 10, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t20;
    const T H4 = (H2 - alpha_h * J_4) * t20;
    const T H6 = -(alpha_h * J_6 - H4) * t20;
    const T H8 = (H6 - alpha_h * J_8) * t20;
    const T H10 = (H8 - alpha_h * J_10) * t20;
    H_f = H8;
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 50 +, 108 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 458 +, 1178 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[1] * cross1 + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * a * a;
  const T t1 = -a_minus_b * b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * b + t5 * a_minus_b;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t4 * t4;
    const T t9 = t5 * t5;
    const T t10 = T(2) * t6 * t7 * a + t8 * t4 * b + t9 * t5 * a_minus_b;
    J_5 = (T(1) / T(3)) * t7 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(4) * t7 * a * t10 + T(3) * t11 * t5 * a_minus_b + T(3) * t12 * t4 * b;
    J_7 = (T(1) / T(15)) * t13 * t7;
    const T t14 = t11 * t9;
    const T t15 = t12 * t8;
    J_9 = (T(1) / T(35)) * t7 * (T(5) * t14 * t5 * a_minus_b + T(5) * t15 * t4 * b + T(2) * t13 * t7 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + r0 * a_minus_b), alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = -t18 * (alpha_h * J_3 - H1);
    const T H5 = t18 * (H3 - alpha_h * J_5);
    const T H7 = -(J_7 * alpha_h - H5) * t18;
    const T H9 = -t18 * (alpha_h * J_9 - H7);
    H_f = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 53 +, 123 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 462 +, 1232 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (in.s * cross_cross + ab_ab * zeta2) * in.s;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  T J_11;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
    J_11 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r0;
    const T t6 = T(1) / r1;
    const T t7 = t5 * b + t6 * a_minus_b;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = t5 * b * t8 + t9 * t6 * a_minus_b + T(2) * t4 * a * t7;
    J_5 = (T(1) / T(3)) * t4 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * t11 * t6 * a_minus_b + T(3) * t5 * b * t12 + T(4) * t4 * a * t10;
    J_7 = (T(1) / T(15)) * t4 * t13;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    const T t16 = T(2) * t4 * a * t13 + T(5) * t5 * b * t14 + T(5) * t15 * t6 * a_minus_b;
    J_9 = (T(1) / T(35)) * t4 * t16;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    J_11 = (T(1) / T(315)) * t4 * (T(35) * t5 * b * t17 + T(8) * t4 * a * t16 + T(35) * t18 * t6 * a_minus_b);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t19 = t2 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(11, 11, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + b * r1) * zeta * alpha_h, r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t21 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * alpha_h) * t21;
    const T H5 = (H3 - J_5 * alpha_h) * t21;
    const T H7 = -(J_7 * alpha_h - H5) * t21;
    const T H9 = (H7 - alpha_h * J_9) * t21;
    const T H11 = -(J_11 * alpha_h - H9) * t21;
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 53 +, 123 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 482 +, 1233 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross1 * cross1 + cross0 * cross0;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (cross_cross * in.s + ab_ab * zeta2) * in.s;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  T J_11;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, a, b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
    J_11 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r0;
    const T t6 = T(1) / r1;
    const T t7 = t5 * b + t6 * a_minus_b;
    J_3 = t4 * t7;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    const T t10 = t8 * t6 * a_minus_b + t5 * b * t9 + T(2) * t4 * a * t7;
    J_5 = (T(1) / T(3)) * t4 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(4) * t4 * a * t10 + T(3) * t5 * b * t11 + T(3) * t12 * t6 * a_minus_b;
    J_7 = (T(1) / T(15)) * t4 * t13;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    const T t16 = T(5) * t14 * t6 * a_minus_b + T(2) * t4 * a * t13 + T(5) * t5 * b * t15;
    J_9 = (T(1) / T(35)) * t4 * t16;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    J_11 = (T(1) / T(315)) * t4 * (T(35) * t17 * t6 * a_minus_b + T(35) * t5 * b * t18 + T(8) * t4 * a * t16);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t19 = t2 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(9, 11, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r0 * a_minus_b + b * r1) * alpha_h, r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t21 = T(1) / zeta2;
    const T H3 = -(J_3 * alpha_h - H1) * t21;
    const T H5 = -(J_5 * alpha_h - H3) * t21;
    const T H7 = (H5 - alpha_h * J_7) * t21;
    const T H9 = t21 * (H7 - J_9 * alpha_h);
    const T H11 = -(J_11 * alpha_h - H9) * t21;
    H_f = H9;
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 51 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 463 +, 1112 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + in.s * ap_ap;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross0 * in.normal[0] + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = a * J2 + t6 * a_minus_b + b * t7;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(2) * b * t10 + T(2) * t11 * a_minus_b + T(3) * t8 * t9 * a;
    J_6 = (T(1) / T(8)) * t9 * t12;
    const T t13 = t11 * t6;
    const T t14 = t10 * t7;
    const T t15 = T(8) * t13 * a_minus_b + T(8) * b * t14 + T(5) * t9 * t12 * a;
    J_8 = (T(1) / T(48)) * t9 * t15;
    const T t16 = t10 * t10;
    const T t17 = t11 * t11;
    J_10 = (T(1) / T(384)) * t9 * (T(48) * b * t16 + T(7) * t9 * a * t15 + T(48) * t17 * a_minus_b);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t20;
    const T H4 = t20 * (H2 - alpha_h * J_4);
    const T H6 = t20 * (H4 - alpha_h * J_6);
    const T H8 = -t20 * (alpha_h * J_8 - H6);
    const T H10 = -t20 * (alpha_h * J_10 - H8);
    H_f = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 54 +, 114 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 467 +, 1147 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (zeta2 * ab_ab + in.s * cross_cross) * in.s;
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * a - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
    J_12 = M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = t7 * a_minus_b + J2 * a + b * t8;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * t6 * t9 * a + T(2) * b * t10 + T(2) * t11 * a_minus_b;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * b * t13 + T(5) * t6 * t12 * a + T(8) * t14 * a_minus_b;
    J_8 = (T(1) / T(48)) * t6 * t15;
    const T t16 = t11 * t11;
    const T t17 = t10 * t10;
    const T t18 = T(48) * t16 * a_minus_b + T(48) * b * t17 + T(7) * t6 * t15 * a;
    J_10 = (T(1) / T(384)) * t6 * t18;
    const T t19 = t16 * t7;
    const T t20 = t17 * t8;
    J_12 = (T(1) / T(1280)) * t6 * (T(128) * t19 * a_minus_b + T(128) * b * t20 + T(3) * t6 * t18 * a);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t21 = t2 - T(2) * zeta2;
  const T t22 = max(T(D - T(2) * zeta2 * a), T(t1));
  if (t21 >= T(0) && t22 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(12, 12, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t23 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t23;
    const T H4 = -(J_4 * alpha_h - H2) * t23;
    const T H6 = t23 * (H4 - J_6 * alpha_h);
    const T H8 = (H6 - alpha_h * J_8) * t23;
    const T H10 = -t23 * (J_10 * alpha_h - H8);
    const T H12 = (H10 - J_12 * alpha_h) * t23;
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_12;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 54 +, 114 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 487 +, 1168 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t0 = D - T(2) * a * a;
  const T t1 = -b * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * a * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, a, b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
    J_12 = M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = a * J2 + t6 * a_minus_b + b * t7;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(2) * b * t10 + T(2) * t11 * a_minus_b + T(3) * a * t8 * t9;
    J_6 = (T(1) / T(8)) * t12 * t9;
    const T t13 = t10 * t7;
    const T t14 = t11 * t6;
    const T t15 = T(5) * a * t12 * t9 + T(8) * b * t13 + T(8) * t14 * a_minus_b;
    J_8 = (T(1) / T(48)) * t15 * t9;
    const T t16 = t10 * t10;
    const T t17 = t11 * t11;
    const T t18 = T(48) * b * t16 + T(48) * t17 * a_minus_b + T(7) * a * t15 * t9;
    J_10 = (T(1) / T(384)) * t18 * t9;
    const T t19 = t16 * t7;
    const T t20 = t17 * t6;
    J_12 = (T(1) / T(1280)) * (T(128) * b * t19 + T(128) * t20 * a_minus_b + T(3) * a * t18 * t9) * t9;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t21 = t2 - T(2) * zeta2;
  const T t22 = max(T(D - T(2) * a * zeta2), T(t1));
  if (t21 >= T(0) && t22 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(10, 12, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t23 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t23;
    const T H4 = -(J_4 * alpha_h - H2) * t23;
    const T H6 = -(J_6 * alpha_h - H4) * t23;
    const T H8 = -t23 * (J_8 * alpha_h - H6);
    const T H10 = (H8 - J_10 * alpha_h) * t23;
    const T H12 = -(J_12 * alpha_h - H10) * t23;
    H_f = H10;
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_12;
}

}  // namespace skelconv::generated
